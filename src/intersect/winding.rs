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
//! # Example
//! ```
//! use casteljau::intersect::winding::{winding_number, Winding};
//! use casteljau::{BezierCurve, num::parse::parse_points, rat, ratio, Point};
//! let seg = |s: &str| BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap();
//! // the lens between the parabola 0 0, 1 2, 2 0 and the chord back
//! let path = vec![seg("0 0, 1 2, 2 0"), seg("2 0, 0 0")];
//! let p = |x, y| Point::new(vec![x, y]);
//! assert_eq!(winding_number(&path, &p(rat(1), ratio(1, 2))).unwrap(), Winding::Inside(-1)); // clockwise
//! assert_eq!(winding_number(&path, &p(rat(1), rat(2))).unwrap(), Winding::Inside(0));
//! assert!(matches!(winding_number(&path, &p(rat(1), rat(1))).unwrap(), Winding::OnBoundary { segment: 0, .. }));
//! ```

use crate::curve::bezier::BezierCurve;
use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::rat;
use crate::poly::algebraic::RealAlgebraic;
use crate::poly::polynomial::trim;
use crate::rational::RationalBezier;
use num_rational::BigRational;
use std::cmp::Ordering;

/// Most segments in one path.
pub const MAX_PATH_SEGMENTS: usize = 100_000;

/// Where the point is relative to the path.
#[derive(Clone, Debug, PartialEq)]
pub enum Winding {
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

enum Event {
    /// The sign of `y − q_y` on a piece of positive length.
    Sign(Ordering),
    /// A point on the ray's line: is it right of `q`?
    Zero(bool),
}

/// A rational strictly between `a < b`: the intervals are refined until the upper end of `a`'s
/// lies below the lower end of `b`'s (or equals it with both irrational: open intervals).
fn rational_between(a: &RealAlgebraic, b: &RealAlgebraic) -> BigRational {
    let (mut a, mut b) = (a.clone(), b.clone());
    loop {
        let ((_, ah), (bl, _)) = (a.interval(), b.interval());
        if ah < bl {
            return (ah + bl) / rat(2);
        }
        if ah == bl && a.interval().0 != ah && b.interval().1 != bl {
            return ah; // a < ah = bl < b
        }
        a.bisect();
        b.bisect();
    }
}

/// [`winding_number_rational`] within a work budget ([`crate::work::winding_segment`] summed over
/// the segments), checked before any work starts.
///
/// # Errors
/// As [`winding_number_rational`]; [`Error::WorkLimit`] when the estimate exceeds `budget`.
pub fn winding_number_within(
    path: &[RationalBezier<BigRational>],
    q: &Point<BigRational>,
    budget: &crate::work::Budget,
) -> Result<Winding> {
    if path.len() > MAX_PATH_SEGMENTS {
        return Err(Error::TooLarge { what: "segments in a path", value: path.len(), limit: MAX_PATH_SEGMENTS });
    }
    budget.check(format!("the winding number of a path of {} segments", path.len()), winding_estimate(path, q))?;
    winding_number_rational(path, q)
}

/// The estimated work of [`winding_number_rational`]: [`crate::work::winding_segment`] summed
/// over the segments (the query point's bits counted in each).
pub fn winding_estimate(path: &[RationalBezier<BigRational>], q: &Point<BigRational>) -> f64 {
    let qb = q.coords.iter().map(crate::work::bits).sum::<u64>();
    path.iter()
        .map(|s| crate::work::winding_segment(s.degree(), crate::work::max_bits(s.homogeneous().points()) + qb))
        .sum()
}

/// [`winding_number_rational`] of polynomial segments.
///
/// # Errors
/// As [`winding_number_rational`].
pub fn winding_number(path: &[BezierCurve<BigRational>], q: &Point<BigRational>) -> Result<Winding> {
    let segs = path
        .iter()
        .map(|c| RationalBezier::new(c.points().to_vec(), vec![rat(1); c.points().len()]))
        .collect::<Result<Vec<_>>>()?;
    winding_number_rational(&segs, q)
}

/// The winding number of a closed path around `q`, or where `q` lies on it.
///
/// # Errors
/// [`Error::InvalidArgument`] when the path is empty, not planar, or not closed (a segment does
/// not start where the previous one ends, or the last does not end at the first's start);
/// [`Error::WeightsVanish`] for a rational segment undefined on `[0, 1]`; [`Error::TooLarge`]
/// beyond [`MAX_PATH_SEGMENTS`].
pub fn winding_number_rational(path: &[RationalBezier<BigRational>], q: &Point<BigRational>) -> Result<Winding> {
    let bad = |m: String| Error::InvalidArgument { message: m };
    if path.is_empty() {
        return Err(bad("an empty path".into()));
    }
    if path.len() > MAX_PATH_SEGMENTS {
        return Err(Error::TooLarge { what: "segments in a path", value: path.len(), limit: MAX_PATH_SEGMENTS });
    }
    if q.dim() != 2 || path.iter().any(|s| s.dim() != 2) {
        return Err(bad("winding numbers are for planar paths and points".into()));
    }
    for s in path {
        s.check_defined(&rat(0), &rat(1))?;
    }
    let end = |s: &RationalBezier<BigRational>, t: i64| s.eval(&rat(t));
    for i in 0..path.len() {
        let j = (i + 1) % path.len();
        if end(&path[i], 1)? != end(&path[j], 0)? {
            return Err(bad(format!("the path is not closed: segment {i} ends where segment {j} does not start")));
        }
    }
    let (qx, qy) = (&q.coords[0], &q.coords[1]);
    let mut events: Vec<Event> = vec![];
    for (i, s) in path.iter().enumerate() {
        let h = s.homogeneous().power_coefficients();
        let coord = |k: usize| -> Vec<BigRational> { h.iter().map(|p| p.coords[k].clone()).collect() };
        let (x, y, w) = (coord(0), coord(1), coord(2));
        let minus = |a: &[BigRational], c: &BigRational| -> Vec<BigRational> {
            trim(a.iter().zip(&w).map(|(ai, wi)| ai.clone() - c.clone() * wi).collect())
        };
        let (fx, fy) = (minus(&x, qx), minus(&y, qy));
        if fy.is_empty() {
            // the whole segment lies on the ray's line
            if !fx.is_empty() {
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
                let mid = rational_between(t, next);
                let sign = RealAlgebraic::from(mid).sign_of(&fy);
                events.push(Event::Sign(sign));
            }
        }
    }
    // follow the cycle: each run of zeros between two signs is one event
    let Some(start) = events.iter().position(|e| matches!(e, Event::Sign(_))) else {
        return Ok(Winding::Inside(0)); // the whole path lies on the ray's line
    };
    let n = events.len();
    let mut winding = 0i64;
    let mut prev = match events[start] {
        Event::Sign(s) => s,
        Event::Zero(_) => unreachable!("start is a sign"),
    };
    let mut right = false;
    let mut in_zero = false;
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
    Ok(Winding::Inside(winding))
}
