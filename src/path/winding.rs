//! Exact winding numbers of closed paths of Bézier segments (polynomial and rational, mixed
//! degrees) around a point, or the exact place where the point lies on the path.
//!
//! The ray from `q` to the right is followed along the whole path: on each segment the roots of
//! `Y(t) − q_y W(t)` on `[0, 1]` cut it into pieces of constant sign; a root whose point lies
//! right of `q` (compared exactly, as real algebraic numbers) counts `+1` when the sign goes
//! from negative to positive across it and `−1` the other way — a touch without crossing counts
//! nothing, a root shared by two segments (a joint) is one event, and a piece lying on the ray
//! counts by the signs before and after it. A root whose point is `q` itself means `q` is on
//! the path. No ray is perturbed and nothing is sampled, so a leading coefficient that vanishes,
//! a tangent ray or a joint on the ray change nothing.
//!
//! The public face of this algorithm is [`super::ClosedPath::winding`].

use crate::error::{Error, Result};
use crate::num::point::{Point, Point2};
use crate::num::scalar::rat;
use crate::poly::Poly;
use crate::poly::algebraic::RealAlgebraic;
use crate::rational::RationalBezier;
use num_rational::BigRational;
use std::cmp::Ordering;

use super::MAX_PATH_SEGMENTS;

/// Where the point is relative to the path.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Winding {
    /// Not on the path: the winding number (counter-clockwise positive; non-zero means inside
    /// by the non-zero rule, odd by the even-odd rule).
    Inside(i64),
    /// On the path: the first segment (0-based) and a parameter where it passes through the
    /// point.
    OnBoundary {
        /// The segment.
        segment: usize,
        /// The parameter on it.
        t: RealAlgebraic,
    },
}

/// What the ray meets along a cycle, in order.
pub(crate) enum Event {
    /// The sign of `y − q_y` on a piece of positive length.
    Sign(Ordering),
    /// A point on the ray's line: is it right of `q`?
    Zero(bool),
}

/// The estimated work of [`winding_number_rational`]: [`crate::work::winding_segment`] summed
/// over the segments (the query point's bits counted in each).
pub(crate) fn winding_estimate(path: &[RationalBezier<BigRational>], q: &Point2<BigRational>) -> f64 {
    let qb = crate::work::bits(&q.x) + crate::work::bits(&q.y);
    path.iter()
        .map(|s| crate::work::winding_segment(s.degree(), crate::work::max_bits(s.homogeneous().points()) + qb))
        .sum()
}

/// `Ok` when every segment starts where the previous one ends and the last ends where the
/// first starts.
pub(super) fn check_closed(path: &[RationalBezier<BigRational>]) -> Result<()> {
    let end = |s: &RationalBezier<BigRational>, t: i64| s.eval(&rat(t));
    // the ends are the first and last homogeneous control points: equal points have
    // proportional coordinates (compared without a division when both weights are 1)
    let same = |a: &Point<BigRational>, b: &Point<BigRational>| -> Option<bool> {
        let one = rat(1);
        (a.coords[2] == one && b.coords[2] == one).then(|| a.coords[0] == b.coords[0] && a.coords[1] == b.coords[1])
    };
    for i in 0..path.len() {
        let j = (i + 1) % path.len();
        let (a, b) = (path[i].homogeneous().points(), path[j].homogeneous().points());
        let equal = match same(&a[a.len() - 1], &b[0]) {
            Some(e) => e,
            None => end(&path[i], 1)? == end(&path[j], 0)?,
        };
        if !equal {
            return Err(Error::InvalidArgument {
                message: format!("the path is not closed: segment {i} ends where segment {j} does not start"),
            });
        }
    }
    Ok(())
}

/// The winding number of a closed path around `q`, or where `q` lies on it.
///
/// # Errors
/// [`Error::InvalidArgument`] when the path is empty, not planar, or not closed (a segment does
/// not start where the previous one ends, or the last does not end at the first's start);
/// [`Error::WeightsVanish`] for a rational segment undefined on `[0, 1]`; [`Error::TooLarge`]
/// beyond 100,000 (`MAX_PATH_SEGMENTS`).
pub(crate) fn winding_number_rational(
    path: &[RationalBezier<BigRational>],
    q: &Point2<BigRational>,
) -> Result<Winding> {
    let bad = |m: String| Error::InvalidArgument { message: m };
    if path.is_empty() {
        return Err(bad("an empty path".into()));
    }
    if path.len() > MAX_PATH_SEGMENTS {
        return Err(Error::TooLarge { what: "segments in a path", value: path.len(), limit: MAX_PATH_SEGMENTS });
    }
    if path.iter().any(|s| s.dim() != 2) {
        return Err(bad("winding numbers are for planar paths and points".into()));
    }
    for s in path {
        s.check_defined(&rat(0), &rat(1))?;
    }
    check_closed(path)?;
    let (qx, qy) = (&q.x, &q.y);
    let mut events: Vec<Event> = vec![];
    for (i, s) in path.iter().enumerate() {
        // Y(t) − q_y W(t) = Σ B_i(t) (Y_i − q_y W_i): when every control point's term has one
        // strict sign, so has the polynomial on [0, 1] — the segment does not meet the ray's
        // line, and its only event is that sign (what the general route below finds, without
        // its power form and root isolation).
        if let Some(sign) = one_side(s, qy) {
            events.push(Event::Sign(sign));
            continue;
        }
        let [x, y, w]: [Poly<BigRational>; 3] =
            s.homogeneous().coordinate_polynomials().try_into().expect("planar: X, Y, W");
        let (fx, fy) = (&x - &w.scale(qx), &y - &w.scale(qy));
        if fy.is_zero() {
            // the whole segment lies on the ray's line
            if !fx.is_zero() {
                if let Some(t) = RealAlgebraic::roots_in(&fx, &rat(0), &rat(1)).into_iter().next() {
                    return Ok(Winding::OnBoundary { segment: i, t });
                }
            } else {
                return Ok(Winding::OnBoundary { segment: i, t: RealAlgebraic::from(rat(0)) });
            }
            let right = RealAlgebraic::from(rat(0)).sign_of(&fx) == Ordering::Greater;
            events.push(Event::Zero(right));
            continue;
        }
        let roots = RealAlgebraic::roots_in(&fy, &rat(0), &rat(1));
        let mut breaks: Vec<RealAlgebraic> = vec![RealAlgebraic::from(rat(0))];
        for r in &roots {
            if *r != breaks[breaks.len() - 1] {
                breaks.push(r.clone());
            }
        }
        let one = RealAlgebraic::from(rat(1));
        if breaks[breaks.len() - 1] != one {
            breaks.push(one);
        }
        let is_root = |t: &RealAlgebraic| roots.iter().any(|r| r == t);
        for (k, t) in breaks.iter().enumerate() {
            if is_root(t) {
                let side = t.sign_of(&fx);
                if side == Ordering::Equal {
                    return Ok(Winding::OnBoundary { segment: i, t: t.clone() });
                }
                events.push(Event::Zero(side == Ordering::Greater));
            }
            if let Some(next) = breaks.get(k + 1) {
                let mid = RealAlgebraic::rational_between(t, next);
                let sign = RealAlgebraic::from(mid).sign_of(&fy);
                events.push(Event::Sign(sign));
            }
        }
    }
    Ok(Winding::Inside(count_crossings(&events)))
}

/// The common strict sign of `Y_i − q_y W_i` over the homogeneous control points of `s`, if
/// they have one (each compared exactly; `Y_i` against `q_y` directly where `W_i = 1`).
fn one_side(s: &RationalBezier<BigRational>, qy: &BigRational) -> Option<Ordering> {
    let one = rat(1);
    let mut common = None;
    for p in s.homogeneous().points() {
        let (y, w) = (&p.coords[1], &p.coords[2]);
        let side = if *w == one { y.cmp(qy) } else { y.cmp(&(qy * w)) };
        if side == Ordering::Equal || common.is_some_and(|c| c != side) {
            return None;
        }
        common = Some(side);
    }
    common
}

/// The crossings beyond the origin along one closed cycle of events: each run of zeros between
/// two signs is one event, counted `+1` when the sign goes from negative to positive across it
/// and `−1` the other way, when a zero of the run lies beyond the origin (0 without any sign:
/// the whole cycle on the ray's line).
pub(crate) fn count_crossings(events: &[Event]) -> i64 {
    let Some(start) = events.iter().position(|e| matches!(e, Event::Sign(_))) else {
        return 0;
    };
    let n = events.len();
    let mut winding = 0i64;
    let Event::Sign(mut prev) = events[start] else { return 0 };
    let (mut right, mut in_zero) = (false, false);
    for k in 1..=n {
        match &events[(start + k) % n] {
            Event::Zero(r) => {
                in_zero = true;
                right |= *r;
            }
            Event::Sign(s) => {
                if in_zero && right && *s != prev {
                    winding += if *s == Ordering::Greater { 1 } else { -1 };
                }
                in_zero = false;
                right = false;
                prev = *s;
            }
        }
    }
    winding
}
