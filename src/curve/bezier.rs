//! Polynomial Bézier curves `b(t) = Σ bᵢ B_i^n(t)` of any degree and dimension.
//!
//! Operations that change the representation but not the curve: degree elevation, exact
//! degree reduction, and the power form. Derivatives give the hodograph. Evaluation and
//! subdivision by de Casteljau's scheme live in [`crate::curve::casteljau`]; their fraction-free exact
//! versions in [`crate::curve::fraction_free`].

use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::{Exact, Scalar};
use crate::poly::bernstein;
use std::fmt;

/// Largest degree accepted by constructors and degree elevation.
pub const MAX_DEGREE: usize = 10_000;

/// Refuses, before any number of it is read, a control polygon's text whose numbers would make
/// a curve of degree above 10,000 (`MAX_DEGREE`) in dimension `dim`: [`Error::TooLarge`], the error
/// [`BezierCurve::new`] gives once the points exist.
///
/// Reading first and checking after costs about 200 bytes per number (each a pair of big
/// integers, each point a vector), forty times the text of short numbers: a 10 MB line of
/// small points needed half a gigabyte before it was refused. Counting the numbers — runs of
/// characters between blanks and commas, as the number reader splits them — takes one pass
/// and no memory.
///
/// # Errors
/// [`Error::TooLarge`] when `numbers / dim − 1 > MAX_DEGREE`.
pub fn check_polygon_text(text: &str, dim: usize) -> Result<()> {
    let mut numbers = 0usize;
    let mut inside = false;
    for c in text.chars() {
        let sep = c.is_whitespace() || c == ',';
        if !sep && !inside {
            numbers += 1;
        }
        inside = !sep;
    }
    let points = numbers / dim.max(1);
    if points > MAX_DEGREE + 1 {
        return Err(Error::TooLarge { what: "degree", value: points - 1, limit: MAX_DEGREE });
    }
    Ok(())
}

/// the polygon-text check, then the control points read in `mode` and the curve: the route for
/// untrusted text (a line of a batch), whose memory stays proportional to the text.
///
/// # Errors
/// As the polygon-text check, [`crate::num::parse_points_in`] and [`BezierCurve::new`].
///
/// # Example
/// ```
/// use casteljau::curve::parse_curve_in;
/// use casteljau::num::NumberMode;
/// let c = parse_curve_in("0 0, 1 2, 2 0", 2, Some(1), NumberMode::Exact).unwrap();
/// assert_eq!(c.degree(), 2);
/// assert!(parse_curve_in(&"1 2 ".repeat(20_000), 2, Some(1), NumberMode::Exact).is_err());
/// ```
pub fn parse_curve_in(
    text: &str,
    dim: usize,
    line: Option<usize>,
    mode: crate::num::parse::NumberMode,
) -> Result<BezierCurve<num_rational::BigRational>> {
    check_polygon_text(text, dim)?;
    BezierCurve::new(crate::num::parse::parse_points_in(text, dim, line, mode)?)
}

/// A Bézier curve: `n + 1 ≥ 1` control points of one dimension `≥ 1`.
///
/// # Invariants
/// At least one control point; all of the same dimension `≥ 1`; degree ≤ 10,000 (`MAX_DEGREE`).
///
/// # Example
/// ```
/// use casteljau::{BezierCurve, num::parse_points, ratio};
/// let c = BezierCurve::new(parse_points("-1 -1, -1/3 1, 1/3 -1, 1 1", 2, None).unwrap()).unwrap();
/// // seed 001: this is (2t − 1, (2t − 1)³)
/// assert_eq!(c.eval(&ratio(1, 3)).to_string(), "(-1/3, -1/27)");
/// assert_eq!(c.real_degree(), 3);
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct BezierCurve<S> {
    pub(in crate::curve) points: Vec<Point<S>>,
}

impl<S: Scalar> BezierCurve<S> {
    /// A curve from its control points.
    ///
    /// # Errors
    /// [`Error::EmptyCurve`] for no points, [`Error::DimensionMismatch`] for mixed or zero
    /// dimensions, [`Error::TooLarge`] beyond 10,000 (`MAX_DEGREE`).
    pub fn new(points: Vec<Point<S>>) -> Result<Self> {
        let first = points.first().ok_or(Error::EmptyCurve { line: None })?;
        let dim = first.dim();
        if dim == 0 {
            return Err(Error::DimensionMismatch { expected: 1, found: 0 });
        }
        if let Some(p) = points.iter().find(|p| p.dim() != dim) {
            return Err(Error::DimensionMismatch { expected: dim, found: p.dim() });
        }
        if points.len() - 1 > MAX_DEGREE {
            return Err(Error::TooLarge { what: "degree", value: points.len() - 1, limit: MAX_DEGREE });
        }
        Ok(BezierCurve { points })
    }

    /// The degree `n` (number of control points minus one).
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }
    /// The dimension of the control points.
    pub fn dim(&self) -> usize {
        self.points[0].dim()
    }
    /// The control points `b_0, …, b_n`.
    pub fn points(&self) -> &[Point<S>] {
        &self.points
    }
    /// Consumes the curve, returning its control points.
    pub fn into_points(self) -> Vec<Point<S>> {
        self.points
    }

    /// `b(t)` as the Bernstein sum `Σ bᵢ B_i^n(t)` (an independent route to [`Self::eval`]).
    pub fn eval_bernstein(&self, t: &S) -> Point<S> {
        bernstein::bernstein_sum(&self.points, t)
    }

    /// `b(t)` by Horner's rule on the power form (a third route).
    pub fn eval_power(&self, t: &S) -> Point<S> {
        bernstein::eval_power(&self.power_coefficients(), t)
    }

    /// The degree-`n` Bézier curve with power form `Σ c_k t^k`, `n = coeffs.len() − 1`.
    ///
    /// # Errors
    /// As [`Self::new`].
    pub fn from_power(coeffs: &[Point<S>]) -> Result<Self> {
        if coeffs.is_empty() {
            return Err(Error::EmptyCurve { line: None });
        }
        Self::new(bernstein::from_power(coeffs))
    }

    /// The `k`-th derivative curve (the hodograph for `k = 1`): degree `n − k` with control
    /// points `n!/(n−k)! · Δ^k bᵢ`, `Δ bᵢ = b_{i+1} − bᵢ`. For `k > n` the zero curve of degree 0.
    ///
    /// # Example
    /// ```
    /// use casteljau::{BezierCurve, Point, rat};
    /// let c = BezierCurve::new(vec![Point::new(vec![rat(0)]), Point::new(vec![rat(1)]), Point::new(vec![rat(4)])]).unwrap();
    /// assert_eq!(c.derivative(1).points()[1].coords[0], rat(6));
    /// ```
    pub fn derivative(&self, k: usize) -> Self {
        let n = self.degree();
        if k > n {
            return BezierCurve { points: vec![Point::origin(self.dim())] };
        }
        let mut pts = self.points.clone();
        for _ in 0..k {
            pts = pts.windows(2).map(|w| w[1].sub(&w[0])).collect();
        }
        let factor = (n - k + 1..=n).fold(S::one(), |acc, m| acc * S::from_i64(m as i64));
        BezierCurve { points: pts.iter().map(|p| p.scale(&factor)).collect() }
    }

    /// The curve with every control point mapped by `f` (e.g. to another scalar type).
    pub fn map<T: Scalar>(&self, f: impl Fn(&S) -> T) -> BezierCurve<T> {
        BezierCurve { points: self.points.iter().map(|p| Point::new(p.coords.iter().map(&f).collect())).collect() }
    }
}

impl<S: Exact> BezierCurve<S> {
    /// The degree of the power-form polynomial: the largest `k` with `c_k ≠ 0`
    /// (0 for a constant curve). Exact: a degree-elevated curve reports its true degree.
    pub fn real_degree(&self) -> usize {
        let c = self.power_coefficients();
        (0..c.len()).rev().find(|&k| c[k].coords.iter().any(|x| !x.is_zero())).unwrap_or(0)
    }
}

impl<S: fmt::Display> fmt::Display for BezierCurve<S> {
    /// `x0 y0, x1 y1, …`: the same syntax the parser reads.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, p) in self.points.iter().enumerate() {
            if i > 0 {
                write!(f, ", ")?;
            }
            for (k, c) in p.coords.iter().enumerate() {
                if k > 0 {
                    write!(f, " ")?;
                }
                write!(f, "{c}")?;
            }
        }
        Ok(())
    }
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    #[test]
    fn check_polygon_text_example() {
        use crate::curve::bezier::{MAX_DEGREE, check_polygon_text};
        assert!(check_polygon_text("0 0, 1 1, 2 0", 2).is_ok());
        let huge = "1 2, ".repeat(MAX_DEGREE + 2);
        assert!(check_polygon_text(&huge, 2).unwrap_err().to_string().contains("exceeds the limit 10000"));
    }
}
