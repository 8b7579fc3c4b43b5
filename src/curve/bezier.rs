//! Polynomial Bézier curves `b(t) = Σ bᵢ B_i^n(t)` of any degree and dimension.
//!
//! Operations that change the representation but not the curve: degree elevation, exact
//! degree reduction, and the power form. Derivatives give the hodograph. Evaluation and
//! subdivision by de Casteljau's scheme live in [`crate::curve::casteljau`]; their fraction-free exact
//! versions in [`crate::curve::fraction_free`].

use crate::curve::casteljau::{self, DeCasteljauTriangle};
use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::{Exact, Scalar};
use crate::poly::bernstein::{self, binomial_row};
use num_rational::BigRational;
use std::any::Any;
use std::fmt;

/// Largest degree accepted by constructors and degree elevation.
pub const MAX_DEGREE: usize = 10_000;

/// Refuses, before any number of it is read, a control polygon's text whose numbers would make
/// a curve of degree above [`MAX_DEGREE`] in dimension `dim`: [`Error::TooLarge`], the error
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
///
/// # Example
/// ```
/// use casteljau::curve::{MAX_DEGREE, check_polygon_text};
/// assert!(check_polygon_text("0 0, 1 1, 2 0", 2).is_ok());
/// let huge = "1 2, ".repeat(MAX_DEGREE + 2);
/// assert!(check_polygon_text(&huge, 2).unwrap_err().to_string().contains("exceeds the limit 10000"));
/// ```
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

/// [`check_polygon_text`], then the control points read in `mode` and the curve: the route for
/// untrusted text (a line of a batch), whose memory stays proportional to the text.
///
/// # Errors
/// As [`check_polygon_text`], [`crate::num::parse_points_in`] and [`BezierCurve::new`].
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
/// At least one control point; all of the same dimension `≥ 1`; degree ≤ [`MAX_DEGREE`].
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
    points: Vec<Point<S>>,
}

/// The curve and parameter as `BezierCurve<BigRational>` and `&BigRational` when `S` is
/// `BigRational`: the methods below hand exact work to the fraction-free kernels
/// ([`fraction_free`](crate::curve::fraction_free)) and run de Casteljau's scheme generically for
/// every other scalar (`f64`, `Rational`, `Q(√d)`, …). One name per operation, whatever the type.
fn as_exact<'a, S: Scalar>(c: &'a BezierCurve<S>, t: &'a S) -> Option<(&'a BezierCurve<BigRational>, &'a BigRational)> {
    let c = (c as &dyn Any).downcast_ref::<BezierCurve<BigRational>>()?;
    Some((c, (t as &dyn Any).downcast_ref::<BigRational>()?))
}

/// A value computed over `BigRational` returned as the same type spelled generically (`T` is
/// that type whenever [`as_exact`] succeeded).
fn same<T: 'static>(x: impl Any) -> T {
    *(Box::new(x) as Box<dyn Any>).downcast::<T>().expect("S is BigRational")
}

impl<S: Scalar> BezierCurve<S> {
    /// A curve from its control points.
    ///
    /// # Errors
    /// [`Error::EmptyCurve`] for no points, [`Error::DimensionMismatch`] for mixed or zero
    /// dimensions, [`Error::TooLarge`] beyond [`MAX_DEGREE`].
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

    /// `b(t)` by de Casteljau's scheme (7): `b_i^r = (1−t) b_i^{r−1} + t b_{i+1}^{r−1}`,
    /// in place on one flat buffer; `O(n²·dim)` field operations. Over `BigRational` the
    /// fraction-free kernel computes the same point with `O(n)` integer products and one
    /// reduction: `Σ C(n,i) Nᵢ pⁱ(q−p)ⁿ⁻ⁱ / (D qⁿ)` for `t = p/q` and control points `Nᵢ/D`.
    ///
    /// # Example
    /// ```
    /// use casteljau::{BezierCurve, num::parse_points, ratio};
    /// let c = BezierCurve::new(parse_points("0 1, 1 3, 2 4, 4 2", 2, None).unwrap()).unwrap();
    /// assert_eq!(c.eval(&ratio(1, 3)).to_string(), "(28/27, 70/27)");
    /// ```
    pub fn eval(&self, t: &S) -> Point<S> {
        if let Some((c, t)) = as_exact(self, t) {
            return same(crate::curve::fraction_free::eval(c, t));
        }
        self.eval_de_casteljau(t)
    }

    /// [`Self::eval`] by de Casteljau's scheme for every scalar, `BigRational` included (one
    /// reduced fraction per operation there): the generic route the fraction-free kernel is
    /// checked against.
    pub(crate) fn eval_de_casteljau(&self, t: &S) -> Point<S> {
        let dim = self.dim();
        let n = self.degree();
        let mut buf: Vec<S> = self.points.iter().flat_map(|p| p.coords.iter().cloned()).collect();
        let u = S::one() - t;
        for r in 1..=n {
            for i in 0..=(n - r) {
                for c in 0..dim {
                    let k = i * dim + c;
                    buf[k] = u.clone() * &buf[k] + t.clone() * &buf[k + dim];
                }
            }
        }
        buf.truncate(dim);
        Point::new(buf)
    }

    /// `b(t)` as the Bernstein sum `Σ bᵢ B_i^n(t)` (an independent route to [`Self::eval`]).
    pub fn eval_bernstein(&self, t: &S) -> Point<S> {
        bernstein::bernstein_sum(&self.points, t)
    }

    /// `b(t)` by Horner's rule on the power form (a third route).
    pub fn eval_power(&self, t: &S) -> Point<S> {
        bernstein::eval_power(&self.power_coefficients(), t)
    }

    /// Power-form coefficients `c_0, …, c_n` with `b(t) = Σ c_k t^k` (seed 003's matrix form):
    /// `c_k = C(n,k) Σ_{i≤k} (−1)^{k−i} C(k,i) bᵢ` (fraction-free over `BigRational`).
    pub fn power_coefficients(&self) -> Vec<Point<S>> {
        if let Some(c) = (self as &dyn Any).downcast_ref::<BezierCurve<BigRational>>() {
            return same(crate::curve::fraction_free::power_coefficients(c));
        }
        bernstein::to_power(&self.points)
    }

    /// The whole de Casteljau triangle at `t` (any `t`, not only `[0, 1]`): `rows[r][i] = b_i^r(t)`.
    ///
    /// # Example
    /// ```
    /// use casteljau::{BezierCurve, num::parse_points, ratio};
    /// let c = BezierCurve::new(parse_points("0 0, 1 2, 2 0", 2, None).unwrap()).unwrap();
    /// let tri = c.triangle(&ratio(1, 2));
    /// assert_eq!(tri.rows[1][0].to_string(), "(1/2, 1)");
    /// assert_eq!(tri.point().to_string(), "(1, 1)");
    /// ```
    pub fn triangle(&self, t: &S) -> DeCasteljauTriangle<S> {
        if let Some((c, t)) = as_exact(self, t) {
            return same(crate::curve::fraction_free::triangle(c, t));
        }
        casteljau::triangle(self, t)
    }

    /// Splits the curve at `t0` into the pieces for `[0, t0]` and `[t0, 1]`, each
    /// reparametrised to `[0, 1]` (Lemma 2): `left(s) = b(t0·s)`, `right(s) = b(t0 + (1−t0)·s)`;
    /// their control points are the triangle's boundary.
    ///
    /// # Example
    /// ```
    /// use casteljau::{BezierCurve, num::parse_points, ratio};
    /// let c = BezierCurve::new(parse_points("-1 -1, -1/3 1, 1/3 -1, 1 1", 2, None).unwrap()).unwrap();
    /// let (l, r) = c.subdivide(&ratio(1, 3));
    /// assert_eq!(l.to_string(), "-1 -1, -7/9 -1/3, -5/9 -1/9, -1/3 -1/27");
    /// assert_eq!(r.eval(&ratio(0, 1)), l.eval(&ratio(1, 1)));
    /// ```
    pub fn subdivide(&self, t0: &S) -> (Self, Self) {
        if let Some((c, t)) = as_exact(self, t0) {
            return same(crate::curve::fraction_free::subdivide(c, t));
        }
        casteljau::subdivide(self, t0)
    }

    /// Subdivides `depth` times, each piece at its own local parameter `t0`: `2^depth` pieces in
    /// order along the curve (seed 001, Fig. 10: `t0 = 1/2`, depth 4); piece `k` covers
    /// [`subdivision_intervals`](crate::curve::subdivision_intervals)`(t0, depth)[k]`.
    ///
    /// # Errors
    /// [`Error::TooLarge`] for `depth >` [`MAX_SUBDIVISION_DEPTH`](crate::curve::MAX_SUBDIVISION_DEPTH).
    pub fn subdivide_repeatedly(&self, t0: &S, depth: u32) -> Result<Vec<Self>> {
        if let Some((c, t)) = as_exact(self, t0) {
            return crate::curve::fraction_free::subdivide_repeatedly(c, t, depth).map(same);
        }
        casteljau::subdivide_repeatedly(self, t0, depth)
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

    /// Degree elevation by `r`: the same curve with degree `n + r`,
    /// `b'_i = Σ_j C(r, i−j) C(n, j) / C(n+r, i) · b_j`.
    ///
    /// # Errors
    /// [`Error::TooLarge`] when `n + r` exceeds [`MAX_DEGREE`].
    pub fn elevate(&self, r: usize) -> Result<Self> {
        if let Some(c) = (self as &dyn Any).downcast_ref::<BezierCurve<BigRational>>() {
            return crate::curve::fraction_free::elevate(c, r).map(same);
        }
        let n = self.degree();
        let m = n.checked_add(r).filter(|m| *m <= MAX_DEGREE).ok_or(Error::TooLarge {
            what: "elevated degree",
            value: n.saturating_add(r),
            limit: MAX_DEGREE,
        })?;
        let (row_r, row_n, row_m) = (binomial_row::<S>(r), binomial_row::<S>(n), binomial_row::<S>(m));
        let points = (0..=m)
            .map(|i| {
                let mut acc = Point::origin(self.dim());
                for j in i.saturating_sub(r)..=i.min(n) {
                    let w = row_r[i - j].clone() * &row_n[j];
                    acc = acc.add(&self.points[j].scale(&w));
                }
                acc.scale(&(S::one() / row_m[i].clone()))
            })
            .collect();
        Ok(BezierCurve { points })
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

    /// Exact degree reduction: when the curve is really of degree `m < n`, the degree-`m`
    /// control points of the same curve (`self` unchanged when `m = n`).
    ///
    /// Elevation followed by reduction is the identity; reduction followed by elevation to `n`
    /// gives back the original control points.
    pub fn reduce_degree(&self) -> Self {
        if let Some(c) = (self as &dyn Any).downcast_ref::<BezierCurve<BigRational>>() {
            return same(crate::curve::fraction_free::reduce_degree(c));
        }
        let m = self.real_degree();
        if m == self.degree() {
            return self.clone();
        }
        let c = self.power_coefficients();
        BezierCurve { points: bernstein::from_power(&c[..=m]) }
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
