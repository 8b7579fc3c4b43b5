//! The capability the curve, rational-curve and patch types share: a point for each parameter,
//! exactly. One trait, so generic code (sampling, oracles in users' tests) takes any of them.

use crate::curve::bezier::BezierCurve;
use crate::error::Result;
use crate::num::point::Point;
use crate::num::scalar::Scalar;

/// A parametric Bézier object: `P(at)` for a parameter `at`.
///
/// Implemented by [`BezierCurve<S>`] (`Parameter = S`, never fails),
/// [`RationalBezier<S>`](crate::RationalBezier) (`Parameter = S`, fails where the weights'
/// denominator `W(t) = Σ wᵢ Bᵢ(t)` vanishes) and [`RationalPatch`](crate::RationalPatch)
/// (`Parameter = [BigRational; 2]` for `(u, v)`).
///
/// # Laws
/// `point_at` agrees with the type's own `eval` exactly, and `point_at(at).dim() == dim()`.
///
/// # Errors
/// [`Error::WeightsVanish`](crate::Error::WeightsVanish) where a rational object's denominator is 0.
///
/// # Example
/// ```
/// use casteljau::{BezierCurve, Parametric, Point, RationalBezier, parse_points, rat, ratio};
/// // generic code: the point at the middle of the parameter range, whatever the curve type
/// fn middle<C: Parametric<Parameter = num_rational::BigRational>>(c: &C) -> Point<C::Scalar> {
///     c.point_at(&ratio(1, 2)).unwrap()
/// }
/// let pts = parse_points("1 0, 1 1, 0 1", 2, None).unwrap();
/// let parabola = BezierCurve::new(pts.clone()).unwrap();
/// let quarter_circle = RationalBezier::new(pts, vec![rat(1), rat(1), rat(2)]).unwrap();
/// assert_eq!(middle(&parabola).to_string(), "(3/4, 3/4)");
/// assert_eq!(middle(&quarter_circle).to_string(), "(3/5, 4/5)");
/// ```
pub trait Parametric {
    /// What a point is found at: the curve parameter `t`, or `[u, v]` for a patch.
    type Parameter;
    /// The coordinates' number type.
    type Scalar: Scalar;
    /// The number of coordinates of each point.
    fn dim(&self) -> usize;
    /// The point at `at`, exact for exact scalars.
    fn point_at(&self, at: &Self::Parameter) -> Result<Point<Self::Scalar>>;
}

impl<S: Scalar> Parametric for BezierCurve<S> {
    type Parameter = S;
    type Scalar = S;
    fn dim(&self) -> usize {
        BezierCurve::dim(self)
    }
    fn point_at(&self, t: &S) -> Result<Point<S>> {
        Ok(self.eval(t))
    }
}
