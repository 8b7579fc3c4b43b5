//! Extrema and the exact bounding box of a polynomial or rational Bézier curve on `[0, 1]`.
//!
//! For a coordinate `x(t) = X(t)/W(t)` (`W = 1` for a polynomial curve) the stationary
//! parameters are the roots on `[0, 1]` of `X′W − XW′` (of `X′` when `W = 1`), exact real
//! algebraic numbers; the value there is the algebraic number `X(t)/W(t)`
//! ([`RealAlgebraic::map_rational`]); the box is the least and greatest of those values and of
//! the end values, compared exactly. Nothing is sampled and nothing is rounded: a vanishing
//! leading coefficient, a stationary point exactly at an end, or a weight that makes the
//! denominator small changes nothing.
//!
//! # Example
//! ```
//! use casteljau::{BezierCurve, RationalBezier, num::parse_points, rational::bounding_box, work::Budget};
//! let bounding_box_polynomial = |c: &BezierCurve<_>| bounding_box(&RationalBezier::from(c.clone()), &Budget::unlimited());
//! // the arch 0 0, 1 2, 2 0: y = 4t(1 − t) peaks at t = 1/2 with y = 1
//! let c = BezierCurve::new(parse_points("0 0, 1 2, 2 0", 2, None).unwrap()).unwrap();
//! let b = bounding_box_polynomial(&c).unwrap();
//! assert_eq!((b.min[1].to_string(), b.max[1].to_string()), ("0".into(), "1".into()));
//! assert_eq!(b.max_at[1].to_string(), "1/2");
//! // a cubic whose x-extremes are irrational: exact, with correctly rounded floats beside
//! let c = BezierCurve::new(parse_points("0 0, 3 1, -1 2, 1 3", 2, None).unwrap()).unwrap();
//! let b = bounding_box_polynomial(&c).unwrap();
//! assert_eq!(b.max_at[0].to_string(), "7/13 - 1/13*sqrt(10)");
//! assert_eq!(b.max[0].to_string(), "133/169 + 20/169*sqrt(10)"); // x(t) = 9t − 21t² + 13t³ there
//! assert_eq!(b.max_float[0], 1.161216291144187);
//! ```

use crate::error::{Error, Result};
use crate::num::scalar::rat;
use crate::poly::algebraic::RealAlgebraic;
use crate::rational::RationalBezier;
use num_rational::BigRational;

/// Largest degree [`bounding_box`] accepts (the value of a stationary point comes from a
/// resultant of size up to `3n − 2`).
pub const MAX_EXTREMA_DEGREE: usize = 20;

/// A stationary point of one coordinate on `[0, 1]`.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Stationary {
    /// The coordinate: 0 for `x`, 1 for `y`, 2 for `z` (JSON: `"x"`, `"y"`, `"z"`, `"x3"`, …).
    #[serde(serialize_with = "axis_name")]
    pub axis: usize,
    /// The parameter, exact.
    pub t: RealAlgebraic,
    /// The coordinate's value there, exact.
    pub value: RealAlgebraic,
    /// `t`, correctly rounded.
    pub t_float: f64,
    /// `value`, correctly rounded.
    pub value_float: f64,
}

fn axis_name<S: serde::Serializer>(k: &usize, s: S) -> std::result::Result<S::Ok, S::Error> {
    match ["x", "y", "z"].get(*k) {
        Some(n) => s.serialize_str(n),
        None => s.collect_str(&format_args!("x{k}")),
    }
}

/// The exact bounding box of a curve on `[0, 1]`, per coordinate. JSON: `min`, `max` (exact
/// strings per coordinate), `min_at`, `max_at` (the smallest parameter where each is reached),
/// `min_float`, `max_float`, and `stationary` (every root of a coordinate's derivative on
/// `[0, 1]`: `axis`, `t`, `value`, `t_float`, `value_float`).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct BoundingBox {
    /// Least value of each coordinate.
    pub min: Vec<RealAlgebraic>,
    /// Greatest value of each coordinate.
    pub max: Vec<RealAlgebraic>,
    /// Where each least value is reached first.
    pub min_at: Vec<RealAlgebraic>,
    /// Where each greatest value is reached first.
    pub max_at: Vec<RealAlgebraic>,
    /// `min`, correctly rounded.
    pub min_float: Vec<f64>,
    /// `max`, correctly rounded.
    pub max_float: Vec<f64>,
    /// The stationary points of every coordinate on `[0, 1]`, by axis then parameter.
    pub stationary: Vec<Stationary>,
}

/// The exact bounding box and stationary points of a rational curve on `[0, 1]` (a polynomial
/// curve: `RationalBezier::from(curve)`), within a work budget checked before any work starts
/// ([`Budget::unlimited`](crate::work::Budget::unlimited) for no limit).
///
/// # Errors
/// [`Error::WeightsVanish`] when the denominator vanishes on `[0, 1]`; [`Error::TooLarge`] above
/// 20 (`MAX_EXTREMA_DEGREE`); [`Error::WorkLimit`] when the estimate exceeds `budget`.
pub fn bounding_box(curve: &RationalBezier<BigRational>, budget: &crate::work::Budget) -> Result<BoundingBox> {
    let n = curve.degree();
    if n > MAX_EXTREMA_DEGREE {
        return Err(Error::TooLarge { what: "degree for extrema", value: n, limit: MAX_EXTREMA_DEGREE });
    }
    let beta = crate::work::max_bits(curve.homogeneous().points());
    budget.check(format!("the bounding box of degree {n}"), crate::work::extrema(n, beta))?;
    curve.check_defined(&rat(0), &rat(1))?;
    let forms = curve.homogeneous().coordinate_polynomials();
    let dim = curve.dim();
    let w = &forms[dim];
    let w_prime = w.derivative();
    let mut out = BoundingBox {
        min: vec![],
        max: vec![],
        min_at: vec![],
        max_at: vec![],
        min_float: vec![],
        max_float: vec![],
        stationary: vec![],
    };
    for k in 0..dim {
        let x = &forms[k];
        let value_at = |t: &RealAlgebraic| t.map_rational(x, w);
        let crit = &(&x.derivative() * w) - &(x * &w_prime);
        let mut candidates: Vec<(RealAlgebraic, RealAlgebraic)> = vec![];
        let zero = RealAlgebraic::from(rat(0));
        candidates.push((zero.clone(), value_at(&zero)));
        if !crit.is_zero() {
            for t in RealAlgebraic::roots_in(&crit, &rat(0), &rat(1)) {
                let v = value_at(&t);
                out.stationary.push(Stationary {
                    axis: k,
                    t_float: t.to_f64(),
                    value_float: v.to_f64(),
                    t: t.clone(),
                    value: v.clone(),
                });
                candidates.push((t, v));
            }
        }
        let one = RealAlgebraic::from(rat(1));
        candidates.push((one.clone(), value_at(&one)));
        // the first (smallest t) of the least and of the greatest values
        let mut lo = 0;
        let mut hi = 0;
        for i in 1..candidates.len() {
            if candidates[i].1 < candidates[lo].1 {
                lo = i;
            }
            if candidates[i].1 > candidates[hi].1 {
                hi = i;
            }
        }
        out.min_float.push(candidates[lo].1.to_f64());
        out.max_float.push(candidates[hi].1.to_f64());
        out.min.push(candidates[lo].1.clone());
        out.max.push(candidates[hi].1.clone());
        out.min_at.push(candidates[lo].0.clone());
        out.max_at.push(candidates[hi].0.clone());
    }
    Ok(out)
}
