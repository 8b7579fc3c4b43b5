//! The exact operations on a polynomial curve over [`BigRational`], each within a work
//! [`Budget`]: the cost is estimated from the input ([`crate::work`]) and checked before any
//! work starts, so an accepted input gets its answer in bounded time. Each returns a typed
//! result whose `Serialize` is its JSON (exact numbers as strings, [`crate::num::serial`]).
//!
//! The kernels are the fraction-free ones of [`crate::curve::fraction_free`].
//!
//! ```
//! use casteljau::{BezierCurve, curve::Evaluation, num::parse_points, ratio, work::Budget};
//! let c = BezierCurve::new(parse_points("0 0, 1 2, 2 0", 2, None).unwrap()).unwrap();
//! let e = Evaluation::new(&c, &[ratio(1, 2)], &Budget::unlimited()).unwrap();
//! assert_eq!(e.values[0].point.to_string(), "(1, 1)");
//! let tight = Budget::new(1.0, "--max-work");
//! assert!(Evaluation::new(&c, &[ratio(1, 2)], &tight).is_err()); // refused before any work
//! ```

use crate::curve::bezier::BezierCurve;
use crate::curve::casteljau::{DeCasteljauTriangle, subdivision_intervals};
use crate::curve::fraction_free;
use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::Scalar;
use crate::num::serial;
use crate::poly::Poly;
use crate::work::{self, Budget};
use num_bigint::BigInt;
use num_rational::BigRational;
use serde::Serialize;
use serde::ser::{SerializeStruct, Serializer};

/// Largest degree whose Bernstein-to-power matrix [`PowerForm::new`] includes.
pub const MAX_MATRIX_DEGREE: usize = 30;
/// Largest degree whose whole de Casteljau scheme [`Scheme::new`] computes (its
/// output has `(n+1)(n+2)/2` points).
pub const MAX_TRIANGLE_DEGREE: usize = 500;
/// Largest number of control points [`RepeatedSubdivision::new`] returns.
pub const MAX_SUBDIVISION_POINTS: usize = 1 << 20;

impl<S: Scalar> Serialize for BezierCurve<S> {
    /// `{"degree": n, "points": [[x, y], …]}` with exact strings.
    fn serialize<Z: Serializer>(&self, s: Z) -> std::result::Result<Z::Ok, Z::Error> {
        let mut st = s.serialize_struct("BezierCurve", 2)?;
        st.serialize_field("degree", &self.degree())?;
        st.serialize_field("points", self.points())?;
        st.end()
    }
}

/// A curve point at a parameter.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct PointAt {
    /// The parameter.
    #[serde(serialize_with = "serial::string")]
    pub t: BigRational,
    /// The point there.
    pub point: Point<BigRational>,
}

/// The points of a curve at given parameters ([`Evaluation::new`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Evaluation {
    /// The curve's degree.
    pub degree: usize,
    /// One point per parameter, in the order given.
    pub values: Vec<PointAt>,
}

/// The two halves of a curve split at `t` ([`Subdivision::new`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Subdivision {
    /// Where the curve was split.
    #[serde(serialize_with = "serial::string")]
    pub t: BigRational,
    /// The piece for `[0, t]`, reparametrised to `[0, 1]`.
    #[serde(serialize_with = "points_of")]
    pub left: BezierCurve<BigRational>,
    /// The piece for `[t, 1]`, reparametrised to `[0, 1]`.
    #[serde(serialize_with = "points_of")]
    pub right: BezierCurve<BigRational>,
}

/// One piece of a repeated subdivision: the parameter interval it covers and its polygon.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Piece {
    /// `[a, b]` of the original parameter.
    #[serde(serialize_with = "interval")]
    pub interval: (BigRational, BigRational),
    /// The piece, reparametrised to `[0, 1]`.
    #[serde(serialize_with = "points_of")]
    pub points: BezierCurve<BigRational>,
}

/// `2^depth` pieces, each interval split at its own local `t` ([`RepeatedSubdivision::new`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct RepeatedSubdivision {
    /// The local split parameter.
    #[serde(serialize_with = "serial::string")]
    pub t: BigRational,
    /// Rounds of splitting.
    pub depth: u32,
    /// The pieces, left to right.
    pub pieces: Vec<Piece>,
}

/// The whole de Casteljau scheme at `t` ([`Scheme::new`]); serializes as
/// `{"t", "rows", "point"}`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Scheme {
    /// The parameter.
    pub t: BigRational,
    /// The scheme's rows `b_i^r`.
    pub triangle: DeCasteljauTriangle<BigRational>,
}

impl Serialize for Scheme {
    fn serialize<Z: Serializer>(&self, s: Z) -> std::result::Result<Z::Ok, Z::Error> {
        let mut st = s.serialize_struct("Scheme", 3)?;
        st.serialize_field("t", &serial::AsString(&self.t))?;
        st.serialize_field("rows", &self.triangle.rows)?;
        st.serialize_field("point", self.triangle.point())?;
        st.end()
    }
}

/// The power form `Σ a_k t^k` of a curve ([`PowerForm::new`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct PowerForm {
    /// The curve's degree.
    pub degree: usize,
    /// `a_0, …, a_n`, one point each.
    pub coefficients: Vec<Point<BigRational>>,
    /// The Bernstein-to-power matrix (`M[k][i]`: the coefficient of `t^k` in `B_i^n`), up to
    /// degree 30 (`MAX_MATRIX_DEGREE`).
    #[serde(skip_serializing_if = "Option::is_none", serialize_with = "matrix")]
    pub matrix: Option<Vec<Vec<BigInt>>>,
}

impl PowerForm {
    /// Coordinate `k` as a polynomial in `var` (ascending powers, [`Poly::text`]).
    ///
    /// ```
    /// use casteljau::{BezierCurve, curve::PowerForm, num::parse_points, work::Budget};
    /// let c = BezierCurve::new(parse_points("0 0, 1 2, 2 0", 2, None).unwrap()).unwrap();
    /// let p = PowerForm::new(&c, &Budget::unlimited()).unwrap();
    /// assert_eq!(p.coordinate_text(1, "t"), "4t - 4t^2");
    /// ```
    pub fn coordinate_text(&self, k: usize, var: &str) -> String {
        Poly::new(self.coefficients.iter().map(|p| p.coords[k].clone()).collect()).text(var).to_string()
    }
}

/// The derivative curve of some order ([`Derivative::new`]); serializes as
/// `{"order", "degree", "points"}`.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Derivative {
    /// The order of the derivative.
    pub order: usize,
    /// The derivative, a curve of degree `n − order` (a point, of degree 0, past `n`).
    #[serde(flatten)]
    pub curve: BezierCurve<BigRational>,
}

/// A curve written with its real degree ([`DegreeReduction::new`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct DegreeReduction {
    /// The degree the curve was written with.
    #[serde(rename = "degree")]
    pub written_degree: usize,
    /// Its real degree (the reduced curve's degree).
    pub real_degree: usize,
    /// The same curve with `real_degree + 1` control points.
    #[serde(rename = "points", serialize_with = "points_of")]
    pub curve: BezierCurve<BigRational>,
}

fn points_of<Z: Serializer>(c: &BezierCurve<BigRational>, s: Z) -> std::result::Result<Z::Ok, Z::Error> {
    c.points().serialize(s)
}

fn interval<Z: Serializer>(iv: &(BigRational, BigRational), s: Z) -> std::result::Result<Z::Ok, Z::Error> {
    [serial::AsString(&iv.0), serial::AsString(&iv.1)].serialize(s)
}

fn matrix<Z: Serializer>(m: &Option<Vec<Vec<BigInt>>>, s: Z) -> std::result::Result<Z::Ok, Z::Error> {
    let rows: Option<Vec<Vec<serial::AsString<'_, BigInt>>>> =
        m.as_ref().map(|m| m.iter().map(|r| r.iter().map(serial::AsString).collect()).collect());
    rows.serialize(s)
}

/// An error when `value` exceeds `limit`.
fn output_limit(what: &'static str, value: usize, limit: usize) -> Result<()> {
    if value > limit { Err(Error::TooLarge { what, value, limit }) } else { Ok(()) }
}

impl DegreeReduction {
    /// The curve written with its real degree, within `budget` (its estimate).
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the estimate exceeds `budget`.
    ///
    /// ```
    /// use casteljau::{BezierCurve, curve::DegreeReduction, num::parse_points, work::Budget};
    /// let c = BezierCurve::new(parse_points("0 0, 2/3 2/3, 4/3 2/3, 2 0", 2, None).unwrap()).unwrap();
    /// let r = DegreeReduction::new(&c, &Budget::unlimited()).unwrap();
    /// assert_eq!((r.written_degree, r.real_degree), (3, 2));
    /// assert_eq!(r.curve.to_string(), "0 0, 1 1, 2 0");
    /// ```
    pub fn new(curve: &BezierCurve<BigRational>, budget: &Budget) -> Result<Self> {
        let n = curve.degree();
        budget
            .check(format!("reducing degree {n}"), work::power_form(n, curve.dim(), work::max_bits(curve.points())))?;
        let curve = fraction_free::reduce_degree(curve);
        Ok(DegreeReduction { written_degree: n, real_degree: curve.degree(), curve })
    }
}

impl Derivative {
    /// The derivative of order `order` as a curve, within `budget` (its estimate).
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the estimate exceeds `budget`.
    ///
    /// ```
    /// use casteljau::{BezierCurve, curve::Derivative, num::parse_points, work::Budget};
    /// let c = BezierCurve::new(parse_points("0 0, 1 2, 2 0", 2, None).unwrap()).unwrap();
    /// let d = Derivative::new(&c, 1, &Budget::unlimited()).unwrap();
    /// assert_eq!((d.order, d.curve.to_string()), (1, "2 4, 2 -4".to_string()));
    /// ```
    pub fn new(curve: &BezierCurve<BigRational>, order: usize, budget: &Budget) -> Result<Self> {
        let n = curve.degree();
        budget.check(
            format!("the derivative of order {order} of degree {n}"),
            work::derivative(n, order.min(n), curve.dim(), work::max_bits(curve.points())),
        )?;
        Ok(Derivative { order, curve: curve.derivative(order) })
    }
}

impl Scheme {
    /// The whole de Casteljau scheme at `t`, within `budget` (its estimate).
    ///
    /// # Errors
    /// [`Error::TooLarge`] above degree 500 (`MAX_TRIANGLE_DEGREE`); [`Error::WorkLimit`] when the
    /// estimate exceeds `budget`.
    ///
    /// ```
    /// use casteljau::{BezierCurve, curve::Scheme, num::parse_points, ratio, work::Budget};
    /// let c = BezierCurve::new(parse_points("0 0, 1 2, 2 0", 2, None).unwrap()).unwrap();
    /// let s = Scheme::new(&c, &ratio(1, 2), &Budget::unlimited()).unwrap();
    /// assert_eq!(s.triangle.rows[1][0].to_string(), "(1/2, 1)");
    /// assert_eq!(s.triangle.point().to_string(), "(1, 1)");
    /// ```
    pub fn new(curve: &BezierCurve<BigRational>, t: &BigRational, budget: &Budget) -> Result<Self> {
        let n = curve.degree();
        output_limit("triangle of degree", n, MAX_TRIANGLE_DEGREE)?;
        budget.check(
            format!("the de Casteljau scheme of degree {n} at a {}-bit t", work::bits(t)),
            work::de_casteljau_scheme(n, curve.dim(), work::max_bits(curve.points()), work::bits(t)),
        )?;
        Ok(Scheme { t: t.clone(), triangle: fraction_free::triangle(curve, t) })
    }
}

impl PowerForm {
    /// The power form, with the conversion matrix up to degree 30 (`MAX_MATRIX_DEGREE`), within
    /// `budget` (its estimate).
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the estimate exceeds `budget`.
    ///
    /// ```
    /// use casteljau::{BezierCurve, curve::PowerForm, num::parse_points, work::Budget};
    /// let c = BezierCurve::new(parse_points("0 0, 1 2, 2 0", 2, None).unwrap()).unwrap();
    /// let p = PowerForm::new(&c, &Budget::unlimited()).unwrap();
    /// assert_eq!(p.coefficients[1].to_string(), "(2, 4)");
    /// assert_eq!(p.matrix.unwrap()[1], vec![(-2).into(), 2.into(), 0.into()]);
    /// ```
    pub fn new(curve: &BezierCurve<BigRational>, budget: &Budget) -> Result<Self> {
        let n = curve.degree();
        budget.check(
            format!("the power form of degree {n}"),
            work::power_form(n, curve.dim(), work::max_bits(curve.points())),
        )?;
        let matrix = (n <= MAX_MATRIX_DEGREE).then(|| crate::poly::bernstein::bernstein_to_power_matrix(n));
        Ok(PowerForm { degree: n, coefficients: fraction_free::power_coefficients(curve), matrix })
    }
}

/// A curve written with a higher degree, the same curve ([`Elevation::new`]); serializes as
/// the curve does (`{"degree", "points"}`).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
#[serde(transparent)]
pub struct Elevation {
    /// The elevated curve.
    pub curve: BezierCurve<BigRational>,
}

impl Elevation {
    /// The same curve written with degree `n + by`, within `budget` (its estimate).
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the estimate exceeds `budget`; as
    /// [`BezierCurve::elevate`] (fraction-free).
    ///
    /// ```
    /// use casteljau::{BezierCurve, curve::Elevation, num::parse_points, work::Budget};
    /// let c = BezierCurve::new(parse_points("0 0, 1 1, 2 0", 2, None).unwrap()).unwrap();
    /// let e = Elevation::new(&c, 1, &Budget::unlimited()).unwrap();
    /// assert_eq!(e.curve.to_string(), "0 0, 2/3 2/3, 4/3 2/3, 2 0");
    /// ```
    pub fn new(curve: &BezierCurve<BigRational>, by: usize, budget: &Budget) -> Result<Self> {
        let n = curve.degree();
        budget.check(
            format!("elevating degree {n} by {by}"),
            work::elevation(n, by, curve.dim(), work::max_bits(curve.points())),
        )?;
        Ok(Elevation { curve: fraction_free::elevate(curve, by)? })
    }
}

impl RepeatedSubdivision {
    /// `depth` rounds of subdivision, each piece split at its own local `t`, within `budget`
    /// (its estimate).
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the estimate exceeds `budget`; [`Error::TooLarge`] when the
    /// pieces would hold more than 2²⁰ (`MAX_SUBDIVISION_POINTS`) points or `depth` exceeds
    /// 16 (`MAX_SUBDIVISION_DEPTH`).
    ///
    /// ```
    /// use casteljau::{BezierCurve, curve::RepeatedSubdivision, num::parse_points, ratio, work::Budget};
    /// let c = BezierCurve::new(parse_points("0 0, 1 1", 2, None).unwrap()).unwrap();
    /// let s = RepeatedSubdivision::new(&c, &ratio(1, 2), 2, &Budget::unlimited()).unwrap();
    /// assert_eq!(s.pieces.len(), 4);
    /// assert_eq!(s.pieces[1].interval, (ratio(1, 4), ratio(1, 2)));
    /// assert_eq!(s.pieces[1].points.to_string(), "1/4 1/4, 1/2 1/2");
    /// ```
    pub fn new(curve: &BezierCurve<BigRational>, t: &BigRational, depth: u32, budget: &Budget) -> Result<Self> {
        let (n, beta) = (curve.degree(), work::max_bits(curve.points()));
        budget.check(
            format!("subdividing degree {n}"),
            work::repeated_subdivision(n, curve.dim(), beta, work::bits(t), depth),
        )?;
        output_limit("subdivision output (pieces × points)", (n + 1) << depth.min(40), MAX_SUBDIVISION_POINTS)?;
        let pieces = fraction_free::subdivide_repeatedly(curve, t, depth)?;
        let pieces = pieces
            .into_iter()
            .zip(subdivision_intervals(t, depth))
            .map(|(points, interval)| Piece { interval, points })
            .collect();
        Ok(RepeatedSubdivision { t: t.clone(), depth, pieces })
    }
}

impl Subdivision {
    /// The two halves at `t` (Lemma 2, fraction-free), within `budget` (its estimate).
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the estimate exceeds `budget`.
    ///
    /// ```
    /// use casteljau::{BezierCurve, curve::Subdivision, num::parse_points, ratio, work::Budget};
    /// let c = BezierCurve::new(parse_points("-1 -1, -1/3 1, 1/3 -1, 1 1", 2, None).unwrap()).unwrap();
    /// let s = Subdivision::new(&c, &ratio(1, 3), &Budget::unlimited()).unwrap();
    /// assert_eq!(s.left.to_string(), "-1 -1, -7/9 -1/3, -5/9 -1/9, -1/3 -1/27");
    /// assert_eq!(s.right.to_string(), "-1/3 -1/27, 1/9 1/9, 5/9 -1/3, 1 1");
    /// ```
    pub fn new(curve: &BezierCurve<BigRational>, t: &BigRational, budget: &Budget) -> Result<Self> {
        let (n, beta) = (curve.degree(), work::max_bits(curve.points()));
        budget.check(format!("subdividing degree {n}"), work::subdivision(n, curve.dim(), beta, work::bits(t)))?;
        let (left, right) = fraction_free::subdivide(curve, t);
        Ok(Subdivision { t: t.clone(), left, right })
    }
}

impl Evaluation {
    /// The points at each of `ts` (fraction-free Horner), within `budget`
    /// (the `evaluation` estimate summed over the parameters).
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the estimate exceeds `budget`.
    ///
    /// ```
    /// use casteljau::{BezierCurve, curve::Evaluation, num::parse_points, ratio, work::Budget};
    /// let c = BezierCurve::new(parse_points("0 1, 1 3, 2 4, 4 2", 2, None).unwrap()).unwrap();
    /// let e = Evaluation::new(&c, &[ratio(1, 3)], &Budget::unlimited()).unwrap();
    /// assert_eq!((e.degree, e.values[0].point.to_string()), (3, "(28/27, 70/27)".to_string()));
    /// ```
    pub fn new(curve: &BezierCurve<BigRational>, ts: &[BigRational], budget: &Budget) -> Result<Self> {
        let (n, beta) = (curve.degree(), work::max_bits(curve.points()));
        let estimate: f64 = ts.iter().map(|t| work::evaluation(n, curve.dim(), beta, work::bits(t))).sum();
        budget.check(format!("evaluating degree {n} at {} parameters", ts.len()), estimate)?;
        let ic = fraction_free::IntegerCurve::new(curve);
        let values = ts.iter().map(|t| PointAt { t: t.clone(), point: fraction_free::eval_integer(&ic, t) }).collect();
        Ok(Evaluation { degree: n, values })
    }
}
