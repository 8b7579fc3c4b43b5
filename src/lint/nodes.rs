//! The checks at the nodes between consecutive segments of a contour: `kink` and
//! `collinear_points`.

use super::exact::{ExactValue, V, cross, dot, sub, v};
use super::{Evidence, Finding, Kind, LintOptions};
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

/// The word-sized decision of a node with doubled tangents `u` (in) and `w` (out): `Some(None)`
/// when it is neither a kink nor a redundant point, `Some(Some(rounding))` for a kink, `None`
/// when the exact route must decide (a redundant point, or a turn too near the limit). For
/// `u · w > 0` the turn is a kink when `|u × w| / (u · w) < r`; both are exact integers below
/// 2^83, so their quotient in `f64` is within a relative 2^-51 of the real one, and only a
/// quotient within a relative 10^-9 of `r` is left to the exact comparison. The rounding test
/// is [`explained_by_rounding`] on the doubled grid (half a unit is 1).
fn screen(u: [i64; 2], w: [i64; 2], r: f64) -> Option<Option<bool>> {
    let (u, w) = (u.map(i128::from), w.map(i128::from));
    let x = u[0] * w[1] - u[1] * w[0];
    let d = u[0] * w[0] + u[1] * w[1];
    if x == 0 {
        return if d > 0 { None } else { Some(None) };
    }
    if d <= 0 {
        return Some(None);
    }
    let q = (x.abs() as f64) / (d as f64);
    if q > r * (1.0 + 1e-9) {
        Some(None)
    } else if q < r * (1.0 - 1e-9) {
        Some(Some(small_rounding(u, w)))
    } else {
        None
    }
}

/// [`explained_by_rounding`] in doubled coordinates (boxes `±1`), in `i128`.
fn small_rounding(u: [i128; 2], w: [i128; 2]) -> bool {
    type W = [i128; 2];
    let cross = |a: &W, b: &W| a[0] * b[1] - a[1] * b[0];
    let dot = |a: &W, b: &W| a[0] * b[0] + a[1] * b[1];
    let cone = |d: W| -> Option<(W, W)> {
        if d[0].abs() <= 1 && d[1].abs() <= 1 {
            return None;
        }
        let corners: Vec<W> = [(-1, -1), (1, -1), (1, 1), (-1, 1)].iter().map(|&(a, b)| [d[0] + a, d[1] + b]).collect();
        let a = *corners.iter().find(|a| corners.iter().all(|c| cross(a, c) >= 0))?;
        let b = *corners.iter().find(|b| corners.iter().all(|c| cross(c, b) >= 0))?;
        Some((a, b))
    };
    let inside = |r: &W, (a, b): &(W, W)| cross(a, r) >= 0 && cross(r, b) >= 0 && (dot(r, a) > 0 || dot(r, b) > 0);
    match (cone(u), cone(w)) {
        (Some(cu), Some(cw)) => inside(&cu.0, &cw) || inside(&cu.1, &cw) || inside(&cw.0, &cu) || inside(&cw.1, &cu),
        _ => true,
    }
}

/// The doubled tangents of a segment `(out of the start, into the end)`, as [`tangents`].
fn small_tangents(ps: &[crate::num::point::Point<BigRational>]) -> Option<([i64; 2], [i64; 2])> {
    let q = super::exact::doubled_all(ps)?;
    let (first, last) = (q[0], q[q.len() - 1]);
    let start = *q[1..].iter().find(|p| **p != first)?;
    let end = *q[..q.len() - 1].iter().rev().find(|p| **p != last)?;
    Some(([start[0] - first[0], start[1] - first[1]], [last[0] - end[0], last[1] - end[1]]))
}

/// The findings at the nodes of contour `ci`.
pub(super) fn check(ci: usize, c: &Contour, numbers: Option<&PointNumbers>, o: &LintOptions) -> Vec<Finding> {
    let mut out = vec![];
    if !(o.wants(Kind::Kink) || o.wants(Kind::CollinearPoints)) {
        return out;
    }
    // the live segments (not a point)
    type Ps = Vec<crate::num::point::Point<BigRational>>;
    let live: Vec<(usize, &Ps)> = c
        .segments
        .iter()
        .enumerate()
        .filter_map(|(i, s)| match s {
            Segment::Bezier(ps) if ps.iter().any(|p| *p != ps[0]) => Some((i, ps)),
            _ => None,
        })
        .collect();
    let pairs = if c.closed { live.len() } else { live.len().saturating_sub(1) };
    if live.len() < 2 {
        return out;
    }
    let r = o.kink_tangent.to_f64();
    let small: Vec<Option<([i64; 2], [i64; 2])>> = live.iter().map(|(_, ps)| small_tangents(ps)).collect();
    for k in 0..pairs {
        let next = (k + 1) % live.len();
        let (_, a) = live[k];
        let (j, b) = live[next];
        if a[a.len() - 1] != b[0] {
            continue; // not joined (a skipped piece between them)
        }
        // the node's stored number; an implied TrueType midpoint is smooth by construction
        let numbers = numbers.and_then(|n| n.get(j));
        let point = numbers.and_then(|n| n.first().copied().flatten());
        if numbers.is_some() && point.is_none() {
            continue;
        }
        let node = || [ExactValue::from(b[0].coords[0].clone()), ExactValue::from(b[0].coords[1].clone())];
        if let (Some((_, su)), Some((sw, _))) = (small[k], small[next]) {
            match screen(su, sw, r) {
                Some(None) => continue,
                Some(Some(rounding)) => {
                    if o.wants(Kind::Kink) {
                        let (su, sw) = (su.map(|c| c as f64), sw.map(|c| c as f64));
                        let turn = (su[0] * sw[1] - su[1] * sw[0]).atan2(su[0] * sw[0] + su[1] * sw[1]).to_degrees();
                        out.push(kink(ci, j, point, &b[0], node(), turn.abs(), rounding, o));
                    }
                    continue;
                }
                None => {}
            }
        }
        let (Some((_, u)), Some((w, _))) = (tangents(a), tangents(b)) else { continue };
        let (x, d) = (cross(&u, &w), dot(&u, &w));
        if x == rat(0) {
            if d.cmp(&rat(0)) == Ordering::Greater && a.len() == 2 && b.len() == 2 && o.wants(Kind::CollinearPoints) {
                let message = format!("the node {} lies between two lines on one line: it is redundant", b[0]);
                let mut f = Finding::new(Evidence::CollinearPoints, message).point_at(node());
                (f.contour, f.index, f.point) = (Some(ci), Some(j), point);
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
        out.push(kink(ci, j, point, &b[0], node(), turn, explained_by_rounding(&u, &w), o));
    }
    out
}

/// The `kink` finding at node `p` of contour `ci`, the start of segment `j`.
#[allow(clippy::too_many_arguments)]
fn kink(
    ci: usize,
    j: usize,
    point: Option<usize>,
    p: &crate::num::point::Point<BigRational>,
    node: [ExactValue; 2],
    turn: f64,
    rounding: bool,
    o: &LintOptions,
) -> Finding {
    let message = format!(
        "the tangents at the node {p} turn by {turn:.3}° (below {}°): nearly smooth, but not exactly{}",
        o.kink_degrees,
        if rounding { "; moving the handles by half a unit would make it smooth" } else { "" }
    );
    let mut f = Finding::new(Evidence::Kink { turn_degrees_float: turn }, message).point_at(node).rounded(rounding);
    (f.contour, f.index, f.point) = (Some(ci), Some(j), point);
    f
}
