//! The exact operations on a rational curve over [`BigRational`], each within a work
//! [`Budget`] checked before any work starts ([`crate::work`]), with typed results whose
//! `Serialize` is their JSON (exact numbers as strings). The estimates are those of the
//! polynomial kernels run on the homogeneous curve `(w_i P_i, w_i)`.
//!
//! ```
//! use casteljau::{RationalBezier, num::parse_points, rat, ratio, rational::RationalEvaluation, work::Budget};
//! let pts = parse_points("1 0, 1 1, 0 1", 2, None).unwrap();
//! let arc = RationalBezier::new(pts, vec![rat(1), rat(1), rat(2)]).unwrap();
//! let e = RationalEvaluation::new(&arc, &[ratio(1, 2)], &Budget::unlimited()).unwrap();
//! assert_eq!(e.values[0].point.to_string(), "(3/5, 4/5)");
//! assert!(e.defined_on_0_1);
//! ```

use crate::curve::exact::PointAt;
use crate::error::{Error, Result};
use crate::num::scalar::rat;
use crate::num::serial;
use crate::poly::roots::Root;
use crate::rational::implicit::{ImplicitOutcome, prove_implicit};
use crate::rational::rational_bezier::{ConicType, RationalBezier};
use crate::work::{self, Budget};
use num_rational::BigRational;
use serde::Serialize;
use serde::ser::{SerializeStruct, Serializer};

/// A rational curve in JSON (fields in the order the command line prints them): `degree`, `homogeneous` (the control points `w·P, w`), `points`
/// (affine, `null` at infinity) and `weights`, exact numbers as strings.
///
/// # Example
/// ```
/// use casteljau::{Point, RationalBezier, rat};
/// let c = RationalBezier::new(vec![Point::new(vec![rat(0), rat(0)]), Point::new(vec![rat(1), rat(2)])], vec![rat(1), rat(2)]).unwrap();
/// assert_eq!(
///     serde_json::to_string(&c).unwrap(),
///     r#"{"degree":1,"homogeneous":[["0","0","1"],["2","4","2"]],"points":[["0","0"],["1","2"]],"weights":["1","2"]}"#
/// );
/// ```
impl Serialize for RationalBezier<BigRational> {
    fn serialize<Z: Serializer>(&self, s: Z) -> std::result::Result<Z::Ok, Z::Error> {
        let mut st = s.serialize_struct("RationalBezier", 4)?;
        st.serialize_field("degree", &self.degree())?;
        st.serialize_field("homogeneous", self.homogeneous().points())?;
        st.serialize_field("points", &self.points())?;
        st.serialize_field("weights", &self.weights().iter().map(serial::AsString).collect::<Vec<_>>())?;
        st.end()
    }
}

/// A closed parameter interval `[from, to]` with `0 ≤ from < to ≤ 1`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParameterInterval {
    from: BigRational,
    to: BigRational,
}

impl ParameterInterval {
    /// `[from, to]`, checked.
    ///
    /// # Errors
    /// [`Error::ParameterInterval`] unless `0 ≤ from < to ≤ 1`.
    ///
    /// ```
    /// use casteljau::{rat, ratio, rational::ParameterInterval};
    /// assert!(ParameterInterval::new(ratio(1, 4), rat(1)).is_ok());
    /// assert!(ParameterInterval::new(rat(1), ratio(1, 2)).is_err());
    /// assert_eq!(ParameterInterval::unit().to(), &rat(1));
    /// ```
    pub fn new(from: BigRational, to: BigRational) -> Result<Self> {
        if from >= to || from < rat(0) || to > rat(1) {
            return Err(Error::ParameterInterval { from: from.to_string(), to: to.to_string() });
        }
        Ok(ParameterInterval { from, to })
    }

    /// `[0, 1]`.
    pub fn unit() -> Self {
        ParameterInterval { from: rat(0), to: rat(1) }
    }

    /// The left end.
    pub fn from(&self) -> &BigRational {
        &self.from
    }

    /// The right end.
    pub fn to(&self) -> &BigRational {
        &self.to
    }
}

impl Serialize for ParameterInterval {
    /// `["from", "to"]`, exact strings.
    fn serialize<Z: Serializer>(&self, s: Z) -> std::result::Result<Z::Ok, Z::Error> {
        [serial::AsString(&self.from), serial::AsString(&self.to)].serialize(s)
    }
}

/// The points of a rational curve at given parameters ([`RationalEvaluation::new`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct RationalEvaluation {
    /// The curve's degree.
    pub degree: usize,
    /// Always true: tells these values from a polynomial curve's in JSON.
    pub rational: bool,
    /// One point per parameter, in the order given.
    pub values: Vec<PointAt>,
    /// The denominator has no root on `[0, 1]`.
    pub defined_on_0_1: bool,
}

/// The two halves of a rational curve split at `t` ([`RationalSubdivision::new`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct RationalSubdivision {
    /// Where the curve was split.
    #[serde(serialize_with = "serial::string")]
    pub t: BigRational,
    /// The piece for `[0, t]`.
    pub left: RationalBezier<BigRational>,
    /// The piece for `[t, 1]`.
    pub right: RationalBezier<BigRational>,
}

/// Where the denominator of a rational curve vanishes on an interval
/// ([`Definedness::new`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Definedness {
    /// The interval examined.
    pub interval: ParameterInterval,
    /// The denominator has no root there (and is not identically zero).
    pub defined: bool,
    /// Its roots there, ascending (empty when defined, or when it is identically zero).
    #[serde(serialize_with = "serial::strings")]
    pub roots: Vec<Root>,
}

impl Definedness {
    /// The denominator is identically zero: the curve is defined nowhere.
    pub fn nowhere(&self) -> bool {
        !self.defined && self.roots.is_empty()
    }
}

/// The conic of a rational quadratic ([`RationalBezier::conic`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Conic {
    /// Ellipse, parabola, hyperbola or degenerate.
    #[serde(serialize_with = "conic_name")]
    pub conic: ConicType,
    /// `w1²/(w0·w2)`; `None` when `w0·w2 = 0` (an end point at infinity).
    #[serde(serialize_with = "serial::option_string")]
    pub shape_factor: Option<BigRational>,
}

fn conic_name<Z: Serializer>(k: &ConicType, s: Z) -> std::result::Result<Z::Ok, Z::Error> {
    s.serialize_str(k.as_str())
}

impl RationalBezier<BigRational> {
    /// The conic of a rational quadratic ([`RationalBezier::conic_type`]) with its shape factor.
    ///
    /// # Errors
    /// [`Error::NotApplicable`] unless the degree is 2.
    ///
    /// ```
    /// use casteljau::{RationalBezier, num::parse_points, rat, rational::ConicType};
    /// let c = RationalBezier::new(parse_points("0 0, 1 2, 2 0", 2, None).unwrap(), vec![rat(1), rat(3), rat(1)]).unwrap();
    /// let k = c.conic().unwrap();
    /// assert_eq!((k.conic, k.shape_factor), (ConicType::Hyperbola, Some(rat(9))));
    /// ```
    pub fn conic(&self) -> Result<Conic> {
        let (conic, shape_factor) = self.conic_type()?;
        Ok(Conic { conic, shape_factor })
    }
}

impl ImplicitOutcome {
    /// Proves or refutes `f(x(t)) ≡ 0` along `curve` for the polynomial `f` written in `poly`
    /// (the method: [`crate::rational`]'s implicit module docs, `W^d·f(X/W)` of degree ≤ `n·d`
    /// evaluated at `n·d + 1` parameters), within `budget` (charged per expression step).
    ///
    /// # Errors
    /// A malformed `f`, a curve of dimension > 3, a denominator vanishing everywhere tried;
    /// [`Error::WorkLimit`] when the evaluation exceeds the budget.
    ///
    /// ```
    /// use casteljau::{RationalBezier, rational::ImplicitOutcome, num::parse_points, rat, work::Budget};
    /// let arc = RationalBezier::new(parse_points("1 0, 1 1, 0 1", 2, None).unwrap(), vec![rat(1), rat(1), rat(2)]).unwrap();
    /// assert!(ImplicitOutcome::new(&arc, "x^2 + y^2 - 1", &Budget::unlimited()).unwrap().proved());
    /// ```
    pub fn new(curve: &RationalBezier<BigRational>, poly: &str, budget: &Budget) -> Result<Self> {
        crate::proof::expr::with_step_limit(budget.expression_steps(), || prove_implicit(curve, poly))
    }
}

impl Definedness {
    /// Where the denominator vanishes on `interval`, within `budget` (root isolation charged
    /// step by step: [`crate::poly::isolate_bernstein`]).
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the isolation would exceed `budget`.
    ///
    /// ```
    /// use casteljau::{RationalBezier, rational::Definedness, num::parse_points, rat, ratio, work::Budget};
    /// use casteljau::rational::ParameterInterval;
    /// let c = RationalBezier::new(parse_points("0 0, 1 1, 2 0", 2, None).unwrap(), vec![rat(1), rat(-1), rat(1)]).unwrap();
    /// let d = Definedness::new(&c, &ParameterInterval::unit(), &Budget::unlimited()).unwrap();
    /// assert!(!d.defined);
    /// assert_eq!(d.roots[0].to_string(), "t = 1/2");
    /// let right = ParameterInterval::new(ratio(3, 4), rat(1)).unwrap();
    /// assert!(Definedness::new(&c, &right, &Budget::unlimited()).unwrap().defined);
    /// ```
    pub fn new(curve: &RationalBezier<BigRational>, interval: &ParameterInterval, budget: &Budget) -> Result<Self> {
        let roots = curve.denominator_roots(interval.from(), interval.to(), budget)?;
        let (defined, roots) = match roots {
            None => (false, vec![]),
            Some(r) => (r.is_empty(), r),
        };
        Ok(Definedness { interval: interval.clone(), defined, roots })
    }
}

/// A rational curve written with a higher degree, the same curve ([`RationalElevation::new`]).
#[derive(Clone, Debug, PartialEq)]
pub struct RationalElevation {
    /// The elevated curve.
    pub curve: RationalBezier<BigRational>,
}

impl RationalElevation {
    /// The same curve written with degree `n + by`, within `budget` (its estimate on the
    /// homogeneous curve).
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the estimate exceeds `budget`; as [`RationalBezier::elevate`].
    ///
    /// ```
    /// use casteljau::{RationalBezier, rational::RationalElevation, num::parse_points, rat, ratio, work::Budget};
    /// let c = RationalBezier::new(parse_points("0 0, 1 1, 2 0", 2, None).unwrap(), vec![rat(1), rat(2), rat(1)]).unwrap();
    /// let e = RationalElevation::new(&c, 1, &Budget::unlimited()).unwrap();
    /// assert_eq!(e.curve.weights(), vec![rat(1), ratio(5, 3), ratio(5, 3), rat(1)]);
    /// ```
    pub fn new(curve: &RationalBezier<BigRational>, by: usize, budget: &Budget) -> Result<Self> {
        let h = curve.homogeneous();
        let n = curve.degree();
        budget.check(
            format!("elevating degree {n} by {by}"),
            work::elevation(n, by, h.dim(), work::max_bits(h.points())),
        )?;
        Ok(RationalElevation { curve: curve.elevate(by)? })
    }
}

impl RationalSubdivision {
    /// The two halves at `t`, within `budget` (its estimate on the homogeneous curve).
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the estimate exceeds `budget`; as [`RationalBezier::subdivide`].
    ///
    /// ```
    /// use casteljau::{RationalBezier, rational::RationalSubdivision, num::parse_points, rat, ratio, work::Budget};
    /// let c = RationalBezier::new(parse_points("1 0, 1 1, 0 1", 2, None).unwrap(), vec![rat(1), rat(1), rat(2)]).unwrap();
    /// let s = RationalSubdivision::new(&c, &ratio(1, 2), &Budget::unlimited()).unwrap();
    /// assert_eq!(s.left.points()[2].as_ref().unwrap().to_string(), "(3/5, 4/5)");
    /// ```
    pub fn new(curve: &RationalBezier<BigRational>, t: &BigRational, budget: &Budget) -> Result<Self> {
        let h = curve.homogeneous();
        let (n, beta) = (curve.degree(), work::max_bits(h.points()));
        budget.check(format!("subdividing degree {n}"), work::subdivision(n, h.dim(), beta, work::bits(t)))?;
        let (left, right) = curve.subdivide(t)?;
        Ok(RationalSubdivision { t: t.clone(), left, right })
    }
}

impl RationalEvaluation {
    /// The points at each of `ts`, within `budget` (its estimate on the homogeneous
    /// curve, summed over the parameters), and whether the curve is defined on `[0, 1]`.
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the estimate exceeds `budget`; [`Error::WeightsVanish`] at a
    /// parameter where the denominator is 0.
    ///
    /// ```
    /// use casteljau::{RationalBezier, rational::RationalEvaluation, num::parse_points, rat, ratio, work::Budget};
    /// let c = RationalBezier::new(parse_points("0 0, 1 1, 2 0", 2, None).unwrap(), vec![rat(1), rat(-1), rat(1)]).unwrap();
    /// let e = RationalEvaluation::new(&c, &[rat(0)], &Budget::unlimited()).unwrap();
    /// assert!(!e.defined_on_0_1); // W(t) = (2t − 1)²
    /// assert!(RationalEvaluation::new(&c, &[ratio(1, 2)], &Budget::unlimited()).is_err());
    /// ```
    pub fn new(curve: &RationalBezier<BigRational>, ts: &[BigRational], budget: &Budget) -> Result<Self> {
        let h = curve.homogeneous();
        let (n, beta) = (curve.degree(), work::max_bits(h.points()));
        let estimate: f64 = ts.iter().map(|t| work::evaluation(n, h.dim(), beta, work::bits(t))).sum();
        budget.check(format!("evaluating degree {n} at {} parameters", ts.len()), estimate)?;
        let eval = curve.exact_evaluator();
        let values = ts.iter().map(|t| Ok(PointAt { t: t.clone(), point: eval(t)? })).collect::<Result<_>>()?;
        let defined_on_0_1 = curve.check_defined(&rat(0), &rat(1)).is_ok();
        Ok(RationalEvaluation { degree: n, rational: true, values, defined_on_0_1 })
    }
}
