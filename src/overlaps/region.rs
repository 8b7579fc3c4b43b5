//! The exact nonzero region of a glyph, read off its arrangement as contours of input pieces.
//!
//! An edge of the arrangement is on the region's boundary when the sum of the inputs' winding
//! numbers is non-zero on exactly one of its sides; the boundary half-edges (region on their
//! left) are joined into cycles at each vertex with the next boundary half-edge clockwise
//! (`Arrangement::cycles`), so a region that touches itself at a vertex is joined sector by
//! sector. A cycle passing a vertex twice (a pinch: a hole touching its outer contour, a
//! contour touching itself) is then split there into loops that each pass it once — the
//! glyph's contours meet at the vertex instead of one contour touching itself.
//!
//! Consecutive edges on one input segment form one piece (a sub-segment of the input segment on
//! an exact parameter interval), so no contour is cut where nothing crosses it. A contour that
//! passes an input contour's start point starts there; contours are ordered by the input
//! contour whose start they keep, the others by their least piece.

use crate::error::Result;
use crate::poly::algebraic::RealAlgebraic;
use crate::shape::Orientation;
use crate::shape::graph::{Arrangement, HalfEdge};
use std::collections::HashMap;

/// A piece of an input segment on an output contour: segment `seg` of the arrangement from
/// parameter `from` to parameter `to` (`from > to` when it runs backwards).
#[derive(Clone, Debug)]
pub(super) struct Piece {
    /// The arrangement's segment.
    pub seg: usize,
    /// Where the piece starts on the segment.
    pub from: RealAlgebraic,
    /// Where it ends.
    pub to: RealAlgebraic,
}

/// A contour of the exact region: its pieces, the arrangement vertex each starts at, and where
/// it lies among the others.
#[derive(Clone, Debug)]
pub(super) struct ExactContour {
    /// The pieces, in drawing order (outer contours in the requested orientation).
    pub pieces: Vec<Piece>,
    /// Per piece, the vertex it starts at (piece `i` ends where piece `i + 1` starts).
    pub at: Vec<usize>,
    /// The contour directly around it.
    pub parent: Option<usize>,
    /// How many contours are around it (even: an outer contour, odd: a hole).
    pub depth: usize,
    /// The input contour it is ordered by, `(input, contour)`: the one whose start it keeps, or
    /// that of its least piece.
    pub origin: (usize, usize),
}

/// The region's contours in drawing order.
pub(super) fn region(arr: &Arrangement, orientation: Orientation) -> Result<Vec<ExactContour>> {
    let inside = |w: &[i64]| w.iter().sum::<i64>() != 0;
    let keep = |h: HalfEdge| inside(arr.side(h)) && !inside(arr.side(HalfEdge { edge: h.edge, forward: !h.forward }));
    let mut cycles = vec![];
    for c in arr.cycles(&keep)? {
        cycles.extend(split_pinches(arr, c));
    }
    // nesting, from the cycles (region on their left): i encloses j when the winding number of
    // i just beside j is non-zero
    let n = cycles.len();
    let boxes: Vec<[f64; 4]> = cycles.iter().map(|c| cycle_box(arr, c)).collect();
    // a point just beside each cycle: outside a cycle's box, that cycle winds 0 around it
    let probes: Vec<[f64; 2]> = cycles
        .iter()
        .map(|c| {
            let (q, _) = arr.beside_point(c[0]);
            [crate::num::scalar::ratio_to_f64(&q.x), crate::num::scalar::ratio_to_f64(&q.y)]
        })
        .collect();
    let mut encloses = vec![vec![false; n]; n];
    for j in 0..n {
        for i in 0..n {
            if i == j || !probe_in(&probes[j], &boxes[i]) {
                continue;
            }
            if arr.beside(std::slice::from_ref(&cycles[i]), cycles[j][0])? != 0 {
                encloses[i][j] = true;
            }
        }
    }
    let depth: Vec<usize> = (0..n).map(|j| (0..n).filter(|&i| encloses[i][j]).count()).collect();
    let parent: Vec<Option<usize>> =
        (0..n).map(|j| (0..n).filter(|&i| encloses[i][j]).max_by_key(|&i| depth[i])).collect();
    let starts = contour_starts(arr);
    let mut contours: Vec<(Key, ExactContour)> = cycles
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let (pieces, at) = pieces_of(arr, c);
            let (pieces, at) = if orientation == Orientation::Cw { reversed(pieces, at) } else { (pieces, at) };
            let mut contour = ExactContour { pieces, at, parent: parent[i], depth: depth[i], origin: (0, 0) };
            let key = rotate_to_start(arr, &starts, &mut contour);
            contour.origin = (key.0, key.1);
            (key, contour)
        })
        .collect();
    // contours in order of their keys, parents renumbered
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| contours[a].0.cmp(&contours[b].0));
    let mut new_index = vec![0; n];
    for (new, &old) in order.iter().enumerate() {
        new_index[old] = new;
    }
    let mut sorted: Vec<Option<ExactContour>> = contours.drain(..).map(|(_, c)| Some(c)).collect();
    let mut out = vec![];
    for &old in &order {
        let mut c = sorted[old].take().expect("each contour once");
        c.parent = c.parent.map(|p| new_index[p]);
        out.push(c);
    }
    Ok(out)
}

/// The order of output contours: the input contour whose start the contour keeps
/// (`(input, contour, 0, 0, 0)`), else its least piece (`(input, contour, 1, segment, parameter)`).
type Key = (usize, usize, u8, usize, RealAlgebraic);

/// Per arrangement segment: the input contour's start point when the segment starts it (its
/// first segment that bounds something, at `t = 0`) or ends it (the last, at `t = 1`).
fn contour_starts(arr: &Arrangement) -> HashMap<usize, RealAlgebraic> {
    let mut out = HashMap::new();
    for cs in &arr.contours {
        for c in cs {
            let live: Vec<usize> = c.iter().copied().filter(|&k| !arr.segs[k].degenerate).collect();
            if let (Some(&first), Some(&last)) = (live.first(), live.last()) {
                out.insert(first, crate::num::scalar::rat(0).into());
                if last != first {
                    out.insert(last, crate::num::scalar::rat(1).into());
                }
            }
        }
    }
    out
}

/// Rotates the contour to start at an input contour's start point (the least such input
/// contour) or, without one, at its least piece; returns its ordering key.
fn rotate_to_start(arr: &Arrangement, starts: &HashMap<usize, RealAlgebraic>, c: &mut ExactContour) -> Key {
    let m = c.pieces.len();
    let at_start = |k: usize, t: &RealAlgebraic| starts.get(&k).is_some_and(|s| s == t);
    let mut best: Option<((usize, usize), usize)> = None;
    for i in 0..m {
        let p = &c.pieces[i];
        let prev = &c.pieces[(i + m - 1) % m];
        // junction i is the start point of the input contour of p or of the piece before it
        let hit = if at_start(p.seg, &p.from) {
            Some(p.seg)
        } else if at_start(prev.seg, &prev.to) {
            Some(prev.seg)
        } else {
            None
        };
        if let Some(k) = hit {
            let s = &arr.segs[k];
            let key = (s.input, s.contour);
            if best.is_none_or(|(b, _)| key < b) {
                best = Some((key, i));
            }
        }
    }
    if let Some(((input, contour), i)) = best {
        c.pieces.rotate_left(i);
        c.at.rotate_left(i);
        return (input, contour, 0, 0, crate::num::scalar::rat(0).into());
    }
    let key_of = |p: &Piece| {
        let s = &arr.segs[p.seg];
        let t = if p.from <= p.to { p.from.clone() } else { p.to.clone() };
        (s.input, s.contour, 1u8, s.index, t)
    };
    let i = (0..m).min_by(|&a, &b| key_of(&c.pieces[a]).cmp(&key_of(&c.pieces[b]))).unwrap_or(0);
    c.pieces.rotate_left(i);
    c.at.rotate_left(i);
    c.pieces.first().map(key_of).unwrap_or((usize::MAX, usize::MAX, 1, 0, crate::num::scalar::rat(0).into()))
}

/// The tail vertex of a half-edge.
fn tail(arr: &Arrangement, h: HalfEdge) -> usize {
    let e = &arr.edges[h.edge];
    if h.forward { e.from } else { e.to }
}

/// Splits a cycle at every vertex it passes more than once into loops passing it once.
fn split_pinches(arr: &Arrangement, cycle: Vec<HalfEdge>) -> Vec<Vec<HalfEdge>> {
    let mut out = vec![];
    let mut stack: Vec<HalfEdge> = vec![];
    let mut pos: HashMap<usize, usize> = HashMap::new();
    for h in cycle {
        let v = tail(arr, h);
        if let Some(&i) = pos.get(&v) {
            let lp: Vec<HalfEdge> = stack.drain(i..).collect();
            for g in &lp {
                pos.remove(&tail(arr, *g));
            }
            out.push(lp);
        }
        pos.insert(v, stack.len());
        stack.push(h);
    }
    if !stack.is_empty() {
        out.push(stack);
    }
    out
}

/// A half-edge's carriers as `(segment, from, to)` in the half-edge's direction.
fn carriers(arr: &Arrangement, h: HalfEdge) -> Vec<(usize, RealAlgebraic, RealAlgebraic)> {
    arr.edges[h.edge]
        .carriers
        .iter()
        .map(
            |(k, lo, hi, fwd)| {
                if *fwd == h.forward { (*k, lo.clone(), hi.clone()) } else { (*k, hi.clone(), lo.clone()) }
            },
        )
        .collect()
}

/// Whether piece `p` goes on as `(k, from, to)`: the same segment, from where it ended, the
/// same way.
fn continues(p: &Piece, k: usize, from: &RealAlgebraic, to: &RealAlgebraic) -> bool {
    p.seg == k && p.to == *from && ((p.from < p.to) == (from < to))
}

/// The cycle's edges joined into pieces on one segment, with the vertex each starts at. Of the
/// pieces an edge carries (a shared arc), the one that continues the previous piece, or else the
/// next edge's, is taken.
fn pieces_of(arr: &Arrangement, cycle: &[HalfEdge]) -> (Vec<Piece>, Vec<usize>) {
    let mut pieces: Vec<Piece> = vec![];
    let mut at = vec![];
    let all: Vec<Vec<(usize, RealAlgebraic, RealAlgebraic)>> = cycle.iter().map(|&h| carriers(arr, h)).collect();
    let m = cycle.len();
    for (i, h) in cycle.iter().enumerate() {
        let cs = &all[i];
        if let Some(last) = pieces.last_mut()
            && let Some((_, _, to)) = cs.iter().find(|(k, from, to)| continues(last, *k, from, to))
        {
            last.to = to.clone();
            continue;
        }
        // a new piece: the carrier the next edge continues, if any
        let next = &all[(i + 1) % m];
        let chosen = cs
            .iter()
            .find(|(k, from, to)| {
                let p = Piece { seg: *k, from: from.clone(), to: to.clone() };
                next.iter().any(|(k2, f2, t2)| continues(&p, *k2, f2, t2))
            })
            .unwrap_or(&cs[0]);
        pieces.push(Piece { seg: chosen.0, from: chosen.1.clone(), to: chosen.2.clone() });
        at.push(tail(arr, *h));
    }
    if pieces.len() > 1 {
        let last = &pieces[pieces.len() - 1];
        let first = &pieces[0];
        if continues(last, first.seg, &first.from, &first.to) {
            // the last piece runs on into the first: one piece, starting where the last did
            let last = pieces.pop().expect("two pieces");
            pieces[0].from = last.from;
            at[0] = at.pop().expect("one vertex per piece");
        }
    }
    (pieces, at)
}

/// The contour run the other way.
fn reversed(mut pieces: Vec<Piece>, at: Vec<usize>) -> (Vec<Piece>, Vec<usize>) {
    let m = pieces.len();
    pieces.reverse();
    for p in &mut pieces {
        std::mem::swap(&mut p.from, &mut p.to);
    }
    // new piece j is old piece m − 1 − j, which started at at[m − 1 − j] and ended at at[m − j]
    let at = (0..m).map(|j| at[(m - j) % m]).collect();
    (pieces, at)
}

/// The union of the boxes of a cycle's segments (unbounded for a segment without one).
fn cycle_box(arr: &Arrangement, c: &[HalfEdge]) -> [f64; 4] {
    let mut b = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];
    for h in c {
        match arr.segs[arr.edges[h.edge].seg].bbox {
            Some(s) => b = [b[0].min(s[0]), b[1].min(s[1]), b[2].max(s[2]), b[3].max(s[3])],
            None => return [f64::NEG_INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::INFINITY],
        }
    }
    b
}

/// Whether a point (its coordinates rounded to nearest, which keeps their order with the box's
/// binary64 ends) lies in a closed box.
fn probe_in(q: &[f64; 2], b: &[f64; 4]) -> bool {
    q[0] >= b[0] && q[1] >= b[1] && q[0] <= b[2] && q[1] <= b[3]
}
