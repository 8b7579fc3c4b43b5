//! The checks at the nodes between consecutive segments of a contour: `kink` and
//! `collinear_points`.

use super::exact::{ExactValue, V, cross, dot, sub, v};
use super::{Finding, Kind, LintOptions};
use crate::format::{Contour, PointNumbers, Segment};
use crate::num::scalar::Scalar;
use crate::num::scalar::rat;
use num_rational::BigRational;
use num_traits::Signed;
use std::cmp::Ordering;

/// The tangent directions at the two ends of a segment: `(out of the start, into the end)`,
/// from the nearest control point distinct from each end (`None` for a point).
fn tangents(ps: &[crate::num::point::Point<BigRational>]) -> Option<(V, V)> {
    let (first, last) = (v(&ps[0]), v(&ps[ps.len() - 1]));
    let start = ps[1..].iter().map(v).find(|q| *q != first)?;
    let end = ps[..ps.len() - 1].iter().rev().map(v).find(|q| *q != last)?;
    Some((sub(&start, &first), sub(&last, &end)))
}

/// The cone of directions of the box `d + [−½, ½]²`, as its two extreme corners `(a, b)`
/// (counter-clockwise from `a` to `b`); `None` when the closed box holds the origin.
fn cone(d: &V) -> Option<(V, V)> {
    let h = rat(1) / rat(2);
    if d[0].abs() <= h && d[1].abs() <= h {
        return None;
    }
    let corners: Vec<V> = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
        .iter()
        .map(|&(sx, sy)| [&d[0] + &h * rat(sx), &d[1] + &h * rat(sy)])
        .collect();
    let a = corners.iter().find(|a| corners.iter().all(|c| cross(a, c) >= rat(0)))?.clone();
    let b = corners.iter().find(|b| corners.iter().all(|c| cross(c, b) >= rat(0)))?.clone();
    Some((a, b))
}

/// The ray `r` lies in the cone from `a` to `b` (less than a half-turn wide).
fn in_cone(r: &V, (a, b): &(V, V)) -> bool {
    cross(a, r) >= rat(0) && cross(r, b) >= rat(0) && (dot(r, a) > rat(0) || dot(r, b) > rat(0))
}

/// Moving each handle end by at most ½ unit in x and y can make `u` and `v` point the same way:
/// the cones of the two boxes of directions meet (two angular intervals, each less than a
/// half-turn, meet exactly when one holds an end of the other).
fn explained_by_rounding(u: &V, w: &V) -> bool {
    match (cone(u), cone(w)) {
        (Some(cu), Some(cw)) => {
            in_cone(&cu.0, &cw) || in_cone(&cu.1, &cw) || in_cone(&cw.0, &cu) || in_cone(&cw.1, &cu)
        }
        _ => true,
    }
}

/// The findings at the nodes of contour `ci`.
pub(super) fn check(ci: usize, c: &Contour, numbers: Option<&PointNumbers>, o: &LintOptions) -> Vec<Finding> {
    let mut out = vec![];
    if !(o.wants(Kind::Kink) || o.wants(Kind::CollinearPoints)) {
        return out;
    }
    // the live segments (not a point) with their tangents
    let live: Vec<(usize, &Vec<crate::num::point::Point<BigRational>>, (V, V))> = c
        .segments
        .iter()
        .enumerate()
        .filter_map(|(i, s)| match s {
            Segment::Bezier(ps) => tangents(ps).map(|t| (i, ps, t)),
            Segment::Skipped { .. } => None,
        })
        .collect();
    let pairs = if c.closed { live.len() } else { live.len().saturating_sub(1) };
    if live.len() < 2 {
        return out;
    }
    for k in 0..pairs {
        let (_, a, (_, u)) = &live[k];
        let (j, b, (w, _)) = &live[(k + 1) % live.len()];
        if a[a.len() - 1] != b[0] {
            continue; // not joined (a skipped piece between them)
        }
        // the node's stored number; an implied TrueType midpoint is smooth by construction
        let numbers = numbers.and_then(|n| n.get(*j));
        let point = numbers.and_then(|n| n.first().copied().flatten());
        if numbers.is_some() && point.is_none() {
            continue;
        }
        let (x, d) = (cross(u, w), dot(u, w));
        let node = [ExactValue::from(b[0].coords[0].clone()), ExactValue::from(b[0].coords[1].clone())];
        if x == rat(0) {
            if d.cmp(&rat(0)) == Ordering::Greater && a.len() == 2 && b.len() == 2 && o.wants(Kind::CollinearPoints) {
                let message = format!("the node {} lies between two lines on one line: it is redundant", b[0]);
                let mut f = Finding::new(Kind::CollinearPoints, message).point_at(node);
                (f.contour, f.index, f.point) = (Some(ci), Some(*j), point);
                out.push(f);
            }
            continue;
        }
        if d <= rat(0) || !o.wants(Kind::Kink) {
            continue;
        }
        let r2 = &o.kink_tangent * &o.kink_tangent;
        if &x * &x >= r2 * &d * &d {
            continue;
        }
        let turn = x.to_f64().atan2(d.to_f64()).to_degrees().abs();
        let rounding = explained_by_rounding(u, w);
        let message = format!(
            "the tangents at the node {} turn by {turn:.3}° (below {}°): nearly smooth, but not exactly{}",
            b[0],
            o.kink_degrees,
            if rounding { "; moving the handles by half a unit would make it smooth" } else { "" }
        );
        let mut f = Finding::new(Kind::Kink, message).point_at(node).rounded(rounding);
        (f.contour, f.index, f.point) = (Some(ci), Some(*j), point);
        f.turn_degrees_float = Some(turn);
        out.push(f);
    }
    out
}
