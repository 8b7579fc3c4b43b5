//! What a plot costs and whether it can be drawn, decided before drawing; one-weight families.

use super::{CurveOptions, Figure, PALETTE, draw_rational};
use crate::curve::bezier::BezierCurve;
use crate::error::{Error, Result};
use crate::num::scalar::ratio_to_f64;
use crate::rational::rational_bezier::RationalBezier;
use crate::work::{self, Budget};
use num_rational::BigRational;

impl CurveOptions {
    /// Checks that `curve` can be drawn with these options within `budget`: the sampler
    /// evaluates exactly at up to `2^12 + 1` parameters of ≤ 13 bits, plus the construction
    /// and the subdivision asked for (their estimates, [`crate::work`]); and the figure is drawn in `f64`, so every
    /// control point must be within its range (one beyond it would be silently dropped).
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the estimate exceeds `budget`; [`Error::InvalidArgument`]
    /// naming the first control point beyond the `f64` range.
    ///
    /// ```
    /// use casteljau::{BezierCurve, num::parse_points, plot::CurveOptions, work::Budget};
    /// let c = BezierCurve::new(parse_points("0 0, 1 2, 2 0", 2, None).unwrap()).unwrap();
    /// assert!(CurveOptions::default().check_drawable(&c, &Budget::unlimited()).is_ok());
    /// let far = BezierCurve::new(parse_points("0 0, 1e400 0", 2, None).unwrap()).unwrap();
    /// assert!(CurveOptions::default().check_drawable(&far, &Budget::unlimited()).is_err());
    /// ```
    pub fn check_drawable(&self, curve: &BezierCurve<BigRational>, budget: &Budget) -> Result<()> {
        let (n, dim, beta) = (curve.degree(), curve.dim(), work::max_bits(curve.points()));
        let mut estimate = 4097.0 * work::evaluation(n, dim, beta, 13);
        if let Some(t) = &self.construction {
            estimate += work::de_casteljau_scheme(n, dim, beta, work::bits(t));
        }
        if let Some((t, depth)) = &self.subdivide {
            estimate += work::repeated_subdivision(n, dim, beta, work::bits(t), *depth);
        }
        budget.check(format!("plotting a curve of degree {n}"), estimate)?;
        if let Some(i) = curve.points().iter().position(|p| p.coords.iter().any(|x| !ratio_to_f64(x).is_finite())) {
            return Err(Error::InvalidArgument {
                message: format!("control point {} is beyond the f64 range and cannot be drawn", i + 1),
            });
        }
        Ok(())
    }
}

/// Draws a one-weight family of a rational curve: `curve` with weight `index` replaced by each
/// of `values` in turn, member `j` in colour `PALETTE[j mod 6]`, the control polygon with the
/// first member when `polygon`.
///
/// # Errors
/// As [`RationalBezier::with_weight`] (an index out of range, a point at infinity, a weight 0);
/// members before the failing one are already drawn.
///
/// ```
/// use casteljau::{RationalBezier, num::parse_points, rat, plot::{Figure, PALETTE, draw_weight_family}};
/// let c = RationalBezier::new(parse_points("0 0, 1 1, 2 0", 2, None).unwrap(), vec![rat(1); 3]).unwrap();
/// let mut fig = Figure::new();
/// draw_weight_family(&mut fig, &c, 1, &[rat(1), rat(2), rat(3)], true).unwrap();
/// assert!(fig.to_svg(200).contains(PALETTE[2]));
/// assert!(draw_weight_family(&mut fig, &c, 1, &[rat(0)], false).is_err());
/// ```
pub fn draw_weight_family(
    fig: &mut Figure,
    curve: &RationalBezier<BigRational>,
    index: usize,
    values: &[BigRational],
    polygon: bool,
) -> Result<()> {
    for (j, w) in values.iter().enumerate() {
        let member = curve.with_weight(index, w.clone())?;
        draw_rational(fig, &member, PALETTE[j % PALETTE.len()], j == 0 && polygon);
    }
    Ok(())
}
