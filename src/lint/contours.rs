//! The checks between contours, from one exact arrangement of the glyph with each contour as
//! its own input: `direction`, `self_intersection`, `overlap`, `touching` and
//! `overlapping_segments`.
//!
//! * Each vertex lists the (contour, segment, parameter) records of the pieces that meet there.
//!   A contour *passes* a vertex once per run of its records joined end-to-start (the end of a
//!   segment and the start of the next non-degenerate one are one pass); two passes are a
//!   `self_intersection`.
//! * Contour `i` *crosses* contour `j` when the edges drawn by `i` and not by `j` lie both
//!   where `j`'s winding number is zero and where it is not (or the same with `i` and `j`
//!   swapped): `overlap`. Contours that meet without crossing are `touching`; an edge that
//!   carries pieces of both is `overlapping_segments` (of one contour twice: `[i, i]`).
//! * Contour `i` lies *inside* `j` when they do not cross and an edge drawn by `i` and not by
//!   `j` has a non-zero winding number of `j`; the depth of `i` is the number of contours it
//!   lies inside, a contour drawn twice (every edge of each an edge of the other) counted once.
//!   Outer contours (even depth) run in the outer direction, holes (odd) the other way; the
//!   orientation is the sign of the contour's exact signed area.
//!
//! An open subpath takes part closed by a line, as its fill is (its closing line is segment
//! number `n` of a subpath of `n` segments in `shared`), unless it lies on one line: then it
//! encloses nothing (a stroke, an SVG `<line>`) and is left out.

use super::exact::{ExactValue, segment_area};
use super::{Evidence, Finding, Glyph, Kind, LintOptions, SharedPiece};
use crate::error::Result;
use crate::format::svg_path::close_for_fill;
use crate::num::scalar::rat;
use crate::path::ClosedPath;
use crate::poly::algebraic::RealAlgebraic;
use crate::shape::{Arrangement, Orientation, Shape};
use std::cmp::Ordering;

/// A piece's parameter at a vertex: (input, segment index in its contour, parameter).
type Record = (usize, usize, RealAlgebraic);

pub(super) fn check(g: &Glyph, o: &LintOptions) -> Result<Vec<Finding>> {
    let mut out = vec![];
    let mut inputs = vec![];
    let mut contour_of = vec![];
    let mut areas = vec![];
    for (ci, c) in g.contours.iter().enumerate() {
        let segs = close_for_fill(c)?;
        if segs.iter().all(|s| s.points().iter().all(|p| *p == s.points()[0])) {
            continue;
        }
        // an open subpath on one line (an SVG <line>, a stroke) encloses nothing: its fill
        // outline would retrace it, which is no defect of an open path
        if !c.closed && on_one_line(&segs) {
            continue;
        }
        if o.wants(Kind::Direction) {
            areas.push(segs.iter().map(|s| segment_area(s.points())).fold(rat(0), |a, b| a + b));
        }
        inputs.push(Shape::new(ClosedPath::from_polynomial(vec![segs])?));
        contour_of.push(ci);
    }
    let n = inputs.len();
    if n == 0 {
        return Ok(out);
    }
    let arr = Arrangement::new(&inputs, &o.budget)?;
    let seg_of = |k: usize| &arr.segs[k];

    // per vertex, the records of the pieces meeting there
    let mut records: Vec<Vec<Record>> = vec![vec![]; arr.vertex_at.len()];
    let mut add = |v: usize, r: Record| {
        if !records[v].iter().any(|q| q.0 == r.0 && q.1 == r.1 && q.2 == r.2) {
            records[v].push(r);
        }
    };
    for e in &arr.edges {
        for (k, lo, hi, fwd) in &e.carriers {
            let s = seg_of(*k);
            let (at_from, at_to) = if *fwd { (lo, hi) } else { (hi, lo) };
            add(e.from, (s.input, s.index, at_from.clone()));
            add(e.to, (s.input, s.index, at_to.clone()));
        }
    }
    // the next non-degenerate segment of each segment of each input's one contour
    let mut next_live: Vec<std::collections::HashMap<usize, usize>> = vec![Default::default(); n];
    for (i, cs) in arr.contours.iter().enumerate() {
        for c in cs {
            let live: Vec<usize> = c.iter().copied().filter(|&k| !arr.segs[k].degenerate).collect();
            for (p, &k) in live.iter().enumerate() {
                next_live[i].insert(arr.segs[k].index, arr.segs[live[(p + 1) % live.len()]].index);
            }
        }
    }
    let (zero, one) = (RealAlgebraic::from(rat(0)), RealAlgebraic::from(rat(1)));
    let passes = |rs: &[&Record], i: usize| -> usize {
        let joints = rs
            .iter()
            .filter(|(_, s, t)| {
                *t == one && next_live[i].get(s).is_some_and(|nx| rs.iter().any(|(_, s2, t2)| s2 == nx && *t2 == zero))
            })
            .count();
        rs.len() - joints
    };
    let vertex_point = |v: usize| -> [ExactValue; 2] {
        let (k, t) = &arr.vertex_at[v];
        arr.segs[*k].point_at_algebraic(t).map(ExactValue::from)
    };

    // self-intersections
    if o.wants(Kind::SelfIntersection) {
        for (v, rs) in records.iter().enumerate() {
            for i in 0..n {
                let mine: Vec<&Record> = rs.iter().filter(|r| r.0 == i).collect();
                if mine.len() < 2 || passes(&mine, i) < 2 {
                    continue;
                }
                let at = vertex_point(v);
                let list: Vec<String> = mine.iter().map(|(_, s, t)| format!("segment {s} at t = {t}")).collect();
                let message =
                    format!("contour {} meets itself at ({}, {}): {}", contour_of[i], at[0], at[1], list.join(", "));
                let mut f = Finding::new(Evidence::SelfIntersection, message).point_at(at);
                f.contour = Some(contour_of[i]);
                // a segment of the contour, not the line that closes an open one for fill
                let stored = g.contours[contour_of[i]].segments.len();
                let first = mine.iter().find(|r| r.1 < stored).unwrap_or(&mine[0]);
                f.index = Some(first.1);
                f.parameters = vec![ExactValue::from(first.2.clone())];
                out.push(f);
            }
        }
    }

    // per pair (and per contour with itself): shared edges; per ordered pair: what each sees
    let inputs_on = |e: &crate::shape::graph::EdgeData| -> Vec<usize> {
        let mut v: Vec<usize> = e.carriers.iter().map(|c| arr.segs[c.0].input).collect();
        v.sort_unstable();
        v
    };
    // sees[i][j] = (some edge of i off j outside j, some inside j)
    let mut sees = vec![vec![(false, false); n]; n];
    for e in &arr.edges {
        let on = inputs_on(e);
        for &i in &on {
            for j in 0..n {
                if j == i || on.contains(&j) {
                    continue;
                }
                if e.left[j] == 0 {
                    sees[i][j].0 = true;
                } else {
                    sees[i][j].1 = true;
                }
            }
        }
    }
    let crosses = |i: usize, j: usize| (sees[i][j].0 && sees[i][j].1) || (sees[j][i].0 && sees[j][i].1);
    let inside = |i: usize, j: usize| !crosses(i, j) && sees[i][j].1;
    // every edge of each is an edge of the other: a contour drawn twice
    let coincident = |i: usize, j: usize| i != j && sees[i][j] == (false, false) && sees[j][i] == (false, false);

    // shared edges: every pair of inputs (or an input twice) an edge carries
    if o.wants(Kind::OverlappingSegments) {
        for e in arr.edges.iter().filter(|e| e.carriers.len() >= 2) {
            let on = inputs_on(e);
            let mut pairs: Vec<(usize, usize)> = vec![];
            for (x, &i) in on.iter().enumerate() {
                for &j in &on[x + 1..] {
                    if !pairs.contains(&(i, j)) {
                        pairs.push((i, j));
                    }
                }
            }
            for (i, j) in pairs {
                let pieces: Vec<&(usize, RealAlgebraic, RealAlgebraic, bool)> =
                    e.carriers.iter().filter(|c| arr.segs[c.0].input == i || arr.segs[c.0].input == j).collect();
                let (a, b) = (vertex_point(e.from), vertex_point(e.to));
                let whom = if i == j {
                    format!("contour {} draws", contour_of[i])
                } else {
                    format!("contours {} and {} both draw", contour_of[i], contour_of[j])
                };
                let twice = if i == j { " twice" } else { "" };
                let message = format!("{whom} the piece from ({}, {}) to ({}, {}){twice}", a[0], a[1], b[0], b[1]);
                let shared = pieces
                    .iter()
                    .map(|(k, lo, hi, fwd)| {
                        let s = &arr.segs[*k];
                        let (from, to) = if *fwd { (lo, hi) } else { (hi, lo) };
                        SharedPiece {
                            contour: contour_of[s.input],
                            segment: s.index,
                            from: ExactValue::from(from.clone()),
                            to: ExactValue::from(to.clone()),
                        }
                    })
                    .collect();
                let mut f = Finding::new(Evidence::OverlappingSegments { shared }, message).point_at(a).point_at(b);
                f.contours = Some([contour_of[i], contour_of[j]]);
                out.push(f);
            }
        }
    }
    // contacts between two contours: the vertices where both have a record
    if o.wants(Kind::Overlap) || o.wants(Kind::Touching) {
        let mut contacts: std::collections::BTreeMap<(usize, usize), Vec<usize>> = Default::default();
        for (v, rs) in records.iter().enumerate() {
            let mut here: Vec<usize> = rs.iter().map(|r| r.0).collect();
            here.sort_unstable();
            here.dedup();
            for (x, &i) in here.iter().enumerate() {
                for &j in &here[x + 1..] {
                    contacts.entry((i, j)).or_default().push(v);
                }
            }
        }
        for ((i, j), vs) in contacts {
            let evidence = if crosses(i, j) { Evidence::Overlap } else { Evidence::Touching };
            if !o.wants(evidence.kind()) {
                continue;
            }
            let points: Vec<[ExactValue; 2]> = vs.iter().map(|&v| vertex_point(v)).collect();
            let list: Vec<String> = points.iter().take(4).map(|p| format!("({}, {})", p[0], p[1])).collect();
            let more = if points.len() > 4 { format!(" and {} more", points.len() - 4) } else { String::new() };
            let verb = if evidence == Evidence::Overlap { "cross; they meet" } else { "touch without crossing" };
            let message =
                format!("contours {} and {} {verb} at {}{more}", contour_of[i], contour_of[j], list.join(", "));
            let mut f = Finding::new(evidence, message);
            for p in points {
                f = f.point_at(p);
            }
            f.contours = Some([contour_of[i], contour_of[j]]);
            out.push(f);
        }
    }

    if o.wants(Kind::Direction) {
        for i in 0..n {
            let area = &areas[i];
            let found = match area.cmp(&rat(0)) {
                Ordering::Greater => Orientation::Ccw,
                Ordering::Less => Orientation::Cw,
                Ordering::Equal => continue,
            };
            // contours drawn twice count once (their duplicate is overlapping_segments)
            let containers: Vec<usize> = (0..n).filter(|&j| j != i && inside(i, j)).collect();
            let depth = containers
                .iter()
                .enumerate()
                .filter(|&(x, &j)| !containers[..x].iter().any(|&k| coincident(k, j)))
                .count();
            let expected = if depth % 2 == 0 { o.outer } else { o.outer.reversed() };
            if found == expected {
                continue;
            }
            let name = |d: Orientation| if d == Orientation::Ccw { "counter-clockwise" } else { "clockwise" };
            let role = if depth % 2 == 0 { "an outer contour" } else { "a hole" };
            let start = start_point(g, contour_of[i]);
            let message = format!(
                "contour {} runs {} (signed area {}) but is {role} (inside {depth} other contour{}), which should run {}",
                contour_of[i],
                name(found),
                area,
                if depth == 1 { "" } else { "s" },
                name(expected)
            );
            let evidence = Evidence::Direction { area: area.clone(), depth, expected };
            let mut f = Finding::new(evidence, message);
            if let Some(p) = start {
                f = f.point_at(p);
            }
            f.contour = Some(contour_of[i]);
            out.push(f);
        }
    }
    Ok(out)
}

/// Every control point of every segment on one line.
fn on_one_line(segs: &[crate::curve::BezierCurve<num_rational::BigRational>]) -> bool {
    use super::exact::{cross, sub, v};
    let ps: Vec<_> = segs.iter().flat_map(|s| s.points().iter().map(v)).collect();
    let Some(a) = ps.first() else { return true };
    let Some(b) = ps.iter().find(|p| *p != a) else { return true };
    let d = sub(b, a);
    ps.iter().all(|p| cross(&d, &sub(p, a)) == rat(0))
}

fn start_point(g: &Glyph, ci: usize) -> Option<[ExactValue; 2]> {
    g.contours[ci].segments.iter().find_map(|s| match s {
        crate::format::Segment::Bezier(ps) => {
            Some([ExactValue::from(ps[0].coords[0].clone()), ExactValue::from(ps[0].coords[1].clone())])
        }
        crate::format::Segment::Skipped { .. } => None,
    })
}
