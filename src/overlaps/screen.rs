//! The cheap exact screen for the common case: a glyph whose contours meet nowhere and run the
//! right way needs no rewriting, and this is decided on small integers without building the
//! glyph's arrangement.
//!
//! On doubled coordinates (font units: integers, and TrueType's implied midpoints at halves),
//! every pair of segments whose boxes meet is separated by a line through their control
//! points' hulls (or, for neighbours in a contour, by a line through their common end — the
//! tests of the arrangement's first step, in `i128`), and every curve is monotone in some
//! direction (so it does not cross itself). Then the contours are disjoint simple closed curves:
//! no `overlap`, `self_intersection` or `overlapping_segments` can be found, and each contour
//! lies inside exactly the contours around one of its points; its orientation (the sign of its
//! exact area) against the parity of that depth is `lint`'s `direction` check. For a composite,
//! only pairs of segments from different components matter, and the components' regions are
//! apart when no contour lies inside another component's region.
//!
//! Anything else — a contact, a coordinate off the half-grid, a contour of fewer than three
//! segments, a nested contour running the wrong way — is left undecided, for the exact route.

use crate::format::{Contour, Segment};
use crate::shape::Orientation;
use crate::shape::pairs::{hulls_separated_small, injective_small, split_at_common_point_small};
use num_rational::BigRational;
use num_traits::ToPrimitive;

/// Largest doubled coordinate taken (products of differences stay far inside `i128`).
const SMALL: i64 = 1 << 40;

/// `2c` when `c` is an integer or a half of small magnitude.
fn doubled(c: &BigRational) -> Option<i64> {
    let n = c.numer().to_i64()?;
    let v = match c.denom().to_i64()? {
        1 => n.checked_mul(2)?,
        2 => n,
        _ => return None,
    };
    (v.abs() < SMALL).then_some(v)
}

/// A contour on the doubled grid: its segments that have length (at least three), closed.
struct Ring {
    component: usize,
    segs: Vec<Vec<[i64; 2]>>,
    boxed: [i64; 4],
}

fn ring(component: usize, c: &Contour) -> Option<Option<Ring>> {
    let mut segs: Vec<Vec<[i64; 2]>> = vec![];
    for s in &c.segments {
        let Segment::Bezier(ps) = s else { return None };
        let d: Vec<[i64; 2]> =
            ps.iter().map(|p| Some([doubled(&p.coords[0])?, doubled(&p.coords[1])?])).collect::<Option<_>>()?;
        if d.iter().all(|q| *q == d[0]) {
            continue; // a point: no length, no region (an anchor when every segment is one)
        }
        segs.push(d);
    }
    let (Some(first), Some(last)) = (segs.first(), segs.last()) else { return Some(None) };
    let (a, b) = (last[last.len() - 1], first[0]);
    if a != b {
        // the closing line, as a fill closes the contour
        segs.push(vec![a, b]);
    }
    if segs.len() < 3 {
        return None;
    }
    let mut boxed = [i64::MAX, i64::MAX, i64::MIN, i64::MIN];
    for q in segs.iter().flatten() {
        boxed = [boxed[0].min(q[0]), boxed[1].min(q[1]), boxed[2].max(q[0]), boxed[3].max(q[1])];
    }
    Some(Some(Ring { component, segs, boxed }))
}

fn box_of(s: &[[i64; 2]]) -> [i64; 4] {
    let mut b = [i64::MAX, i64::MAX, i64::MIN, i64::MIN];
    for q in s {
        b = [b[0].min(q[0]), b[1].min(q[1]), b[2].max(q[0]), b[3].max(q[1])];
    }
    b
}

/// Twice the signed area of a segment times 120 (an integer for degrees up to 3 on the
/// doubled grid, where it is 4·240 times the area).
fn area_units(d: &[[i64; 2]]) -> i128 {
    let c = |i: usize, j: usize| d[i][0] as i128 * d[j][1] as i128 - d[j][0] as i128 * d[i][1] as i128;
    match d.len() {
        2 => 120 * c(0, 1),
        3 => 40 * (c(0, 1) * 2 + c(0, 2) + c(1, 2) * 2),
        4 => 12 * (c(0, 1) * 6 + c(0, 2) * 3 + c(0, 3) + c(1, 2) * 3 + c(1, 3) * 3 + c(2, 3) * 6),
        _ => 0,
    }
}

/// The winding number of a ring around a point off it (doubled coordinates), by a ray to
/// `+x`: the signed crossings, each segment split in halves until its box lies left of the
/// point (no crossing), right of it (the crossings of the whole line, `up(end) − up(start)`
/// with `up(p) = p.y > q.y`), or wholly on one side of the ray's line (none). `None` for a
/// point on the ring (or a split too deep for `i128`).
fn winding(r: &Ring, q: [i64; 2]) -> Option<i64> {
    let q = [q[0] as i128, q[1] as i128];
    let mut total = 0i64;
    for s in &r.segs {
        let pts: Vec<[i128; 2]> = s.iter().map(|p| [p[0] as i128, p[1] as i128]).collect();
        total += crossings(&pts, q, 0)?;
    }
    Some(total)
}

/// [`winding`]'s count for one segment (see there); each split doubles the coordinates (and
/// the point) `n` times so that the halves' control points stay integers.
fn crossings(ps: &[[i128; 2]], q: [i128; 2], depth: u32) -> Option<i64> {
    const DEEPEST: u32 = 40;
    let (mut x0, mut y0, mut x1, mut y1) = (i128::MAX, i128::MAX, i128::MIN, i128::MIN);
    for p in ps {
        (x0, y0, x1, y1) = (x0.min(p[0]), y0.min(p[1]), x1.max(p[0]), y1.max(p[1]));
    }
    if y1 <= q[1] || y0 > q[1] || x1 < q[0] {
        return Some(0);
    }
    let up = |p: &[i128; 2]| i64::from(p[1] > q[1]);
    if x0 > q[0] {
        return Some(up(&ps[ps.len() - 1]) - up(&ps[0]));
    }
    if depth >= DEEPEST {
        return None;
    }
    // de Casteljau at 1/2 on the points scaled by 2^n
    let n = ps.len() - 1;
    let scale = 1i128.checked_shl(n as u32)?;
    let mut level: Vec<[i128; 2]> =
        ps.iter().map(|p| Some([p[0].checked_mul(scale)?, p[1].checked_mul(scale)?])).collect::<Option<_>>()?;
    let (mut left, mut right) = (vec![level[0]], vec![level[n]]);
    for _ in 0..n {
        level = level.windows(2).map(|w| [(w[0][0] + w[1][0]) / 2, (w[0][1] + w[1][1]) / 2]).collect();
        left.push(level[0]);
        right.push(level[level.len() - 1]);
    }
    right.reverse();
    let q2 = [q[0].checked_mul(scale)?, q[1].checked_mul(scale)?];
    Some(crossings(&left, q2, depth + 1)? + crossings(&right, q2, depth + 1)?)
}

/// Whether the glyph certainly needs no rewriting (see the module documentation); `false` when
/// undecided.
pub(super) fn clean(components: &[Vec<Contour>], orientation: Orientation) -> bool {
    let composite = components.len() > 1;
    let mut rings = vec![];
    for (ci, comp) in components.iter().enumerate() {
        for c in comp {
            match ring(ci, c) {
                None => return false,
                Some(None) => {}
                Some(Some(r)) => rings.push(r),
            }
        }
    }
    // every segment: (ring, index, box)
    let mut all: Vec<(usize, usize, [i64; 4])> = vec![];
    for (ri, r) in rings.iter().enumerate() {
        for (si, s) in r.segs.iter().enumerate() {
            if !composite && s.len() > 2 && !injective_small(s) {
                return false;
            }
            all.push((ri, si, box_of(s)));
        }
    }
    all.sort_by_key(|e| e.2[0]);
    let mut active: Vec<usize> = vec![];
    for k in 0..all.len() {
        let (ra, sa, ba) = all[k];
        active.retain(|&j| all[j].2[2] >= ba[0]);
        for &j in &active {
            let (rb, sb, bb) = all[j];
            if bb[1] > ba[3] || ba[1] > bb[3] {
                continue;
            }
            if composite && rings[ra].component == rings[rb].component {
                continue;
            }
            let (a, b) = (&rings[ra].segs[sa], &rings[rb].segs[sb]);
            let n = rings[ra].segs.len();
            let neighbours = ra == rb && (sb == (sa + 1) % n || sa == (sb + 1) % n);
            let separated = if neighbours {
                let (first, second) = if sb == (sa + 1) % n { (a, b) } else { (b, a) };
                let p = first[first.len() - 1];
                // exactly one common end, the joint
                let others = [(first[0], second[0]), (first[0], second[second.len() - 1])];
                others.iter().all(|(x, y)| x != y)
                    && second[second.len() - 1] != p
                    && split_at_common_point_small(p, first, second)
            } else {
                hulls_separated_small(a, b)
            };
            if !separated {
                return false;
            }
        }
        active.push(k);
    }
    // disjoint simple closed curves: nesting by one point of each, direction by exact areas
    for (j, rj) in rings.iter().enumerate() {
        let p = rj.segs[0][0];
        let mut depth: usize = 0;
        // per component, the winding number of its rings around q
        let mut around = vec![0i64; components.len()];
        for (i, ri) in rings.iter().enumerate() {
            let b = ri.boxed;
            if i == j || p[0] < b[0] || p[0] > b[2] || p[1] < b[1] || p[1] > b[3] {
                continue;
            }
            let Some(w) = winding(ri, p) else { return false };
            if w != 0 {
                depth += 1;
            }
            around[ri.component] += w;
        }
        if composite {
            if around.iter().enumerate().any(|(c, w)| c != rj.component && *w != 0) {
                return false; // inside another component's region
            }
            continue;
        }
        let area: i128 = rj.segs.iter().map(|s| area_units(s)).sum();
        let expected = if depth.is_multiple_of(2) { orientation } else { orientation.reversed() };
        let ok = match expected {
            Orientation::Ccw => area >= 0,
            Orientation::Cw => area <= 0,
        };
        if !ok {
            return false;
        }
    }
    true
}
