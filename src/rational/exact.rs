//! The exact operations on a rational curve over [`BigRational`], each within a work
//! [`Budget`] checked before any work starts ([`crate::work`]), with typed results whose
//! `Serialize` is their JSON (exact numbers as strings). The estimates are those of the
//! polynomial kernels run on the homogeneous curve `(w_i P_i, w_i)`.
//!
//! ```
//! use casteljau::{RationalBezier, num::parse_points, rat, ratio, work::Budget};
//! let pts = parse_points("1 0, 1 1, 0 1", 2, None).unwrap();
//! let arc = RationalBezier::new(pts, vec![rat(1), rat(1), rat(2)]).unwrap();
//! let e = arc.eval_within(&[ratio(1, 2)], &Budget::unlimited()).unwrap();
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
    /// [`Error::InvalidArgument`] unless `0 ≤ from < to ≤ 1`.
    ///
    /// ```
    /// use casteljau::{rat, ratio, rational::ParameterInterval};
    /// assert!(ParameterInterval::new(ratio(1, 4), rat(1)).is_ok());
    /// assert!(ParameterInterval::new(rat(1), ratio(1, 2)).is_err());
    /// assert_eq!(ParameterInterval::unit().to(), &rat(1));
    /// ```
    pub fn new(from: BigRational, to: BigRational) -> Result<Self> {
        if from >= to || from < rat(0) || to > rat(1) {
            return Err(Error::InvalidArgument { message: format!("need 0 <= from < to <= 1, got [{from}, {to}]") });
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

/// The points of a rational curve at given parameters ([`RationalBezier::eval_within`]).
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

/// The two halves of a rational curve split at `t` ([`RationalBezier::subdivide_within`]).
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
/// ([`RationalBezier::defined_within`]).
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
    /// The points at each of `ts`, within `budget` ([`work::evaluation`] on the homogeneous
    /// curve, summed over the parameters), and whether the curve is defined on `[0, 1]`.
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the estimate exceeds `budget`; [`Error::WeightsVanish`] at a
    /// parameter where the denominator is 0.
    ///
    /// ```
    /// use casteljau::{RationalBezier, num::parse_points, rat, ratio, work::Budget};
    /// let c = RationalBezier::new(parse_points("0 0, 1 1, 2 0", 2, None).unwrap(), vec![rat(1), rat(-1), rat(1)]).unwrap();
    /// let e = c.eval_within(&[rat(0)], &Budget::unlimited()).unwrap();
    /// assert!(!e.defined_on_0_1); // W(t) = (2t − 1)²
    /// assert!(c.eval_within(&[ratio(1, 2)], &Budget::unlimited()).is_err());
    /// ```
    pub fn eval_within(&self, ts: &[BigRational], budget: &Budget) -> Result<RationalEvaluation> {
        let h = self.homogeneous();
        let (n, beta) = (self.degree(), work::max_bits(h.points()));
        let estimate: f64 = ts.iter().map(|t| work::evaluation(n, h.dim(), beta, work::bits(t))).sum();
        budget.check(format!("evaluating degree {n} at {} parameters", ts.len()), estimate)?;
        let eval = self.exact_evaluator();
        let values = ts.iter().map(|t| Ok(PointAt { t: t.clone(), point: eval(t)? })).collect::<Result<_>>()?;
        let defined_on_0_1 = self.check_defined(&rat(0), &rat(1)).is_ok();
        Ok(RationalEvaluation { degree: n, rational: true, values, defined_on_0_1 })
    }

    /// The two halves at `t`, within `budget` ([`work::subdivision`] on the homogeneous curve).
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the estimate exceeds `budget`; as [`RationalBezier::subdivide`].
    ///
    /// ```
    /// use casteljau::{RationalBezier, num::parse_points, rat, ratio, work::Budget};
    /// let c = RationalBezier::new(parse_points("1 0, 1 1, 0 1", 2, None).unwrap(), vec![rat(1), rat(1), rat(2)]).unwrap();
    /// let s = c.subdivide_within(&ratio(1, 2), &Budget::unlimited()).unwrap();
    /// assert_eq!(s.left.points()[2].as_ref().unwrap().to_string(), "(3/5, 4/5)");
    /// ```
    pub fn subdivide_within(&self, t: &BigRational, budget: &Budget) -> Result<RationalSubdivision> {
        let h = self.homogeneous();
        let (n, beta) = (self.degree(), work::max_bits(h.points()));
        budget.check(format!("subdividing degree {n}"), work::subdivision(n, h.dim(), beta, work::bits(t)))?;
        let (left, right) = self.subdivide(t)?;
        Ok(RationalSubdivision { t: t.clone(), left, right })
    }

    /// The same curve written with degree `n + by`, within `budget` ([`work::elevation`] on the
    /// homogeneous curve).
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the estimate exceeds `budget`; as [`RationalBezier::elevate`].
    ///
    /// ```
    /// use casteljau::{RationalBezier, num::parse_points, rat, ratio, work::Budget};
    /// let c = RationalBezier::new(parse_points("0 0, 1 1, 2 0", 2, None).unwrap(), vec![rat(1), rat(2), rat(1)]).unwrap();
    /// let e = c.elevate_within(1, &Budget::unlimited()).unwrap();
    /// assert_eq!(e.weights(), vec![rat(1), ratio(5, 3), ratio(5, 3), rat(1)]);
    /// ```
    pub fn elevate_within(&self, by: usize, budget: &Budget) -> Result<RationalBezier<BigRational>> {
        let h = self.homogeneous();
        let n = self.degree();
        budget.check(
            format!("elevating degree {n} by {by}"),
            work::elevation(n, by, h.dim(), work::max_bits(h.points())),
        )?;
        self.elevate(by)
    }

    /// Where the denominator vanishes on `interval`, within `budget` (root isolation charged
    /// step by step: [`crate::poly::isolate_in_within`]).
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the isolation would exceed `budget`.
    ///
    /// ```
    /// use casteljau::{RationalBezier, num::parse_points, rat, ratio, work::Budget};
    /// use casteljau::rational::ParameterInterval;
    /// let c = RationalBezier::new(parse_points("0 0, 1 1, 2 0", 2, None).unwrap(), vec![rat(1), rat(-1), rat(1)]).unwrap();
    /// let d = c.defined_within(&ParameterInterval::unit(), &Budget::unlimited()).unwrap();
    /// assert!(!d.defined);
    /// assert_eq!(d.roots[0].to_string(), "t = 1/2");
    /// let right = ParameterInterval::new(ratio(3, 4), rat(1)).unwrap();
    /// assert!(c.defined_within(&right, &Budget::unlimited()).unwrap().defined);
    /// ```
    pub fn defined_within(&self, interval: &ParameterInterval, budget: &Budget) -> Result<Definedness> {
        let roots = self.denominator_roots_within(interval.from(), interval.to(), budget)?;
        let (defined, roots) = match roots {
            None => (false, vec![]),
            Some(r) => (r.is_empty(), r),
        };
        Ok(Definedness { interval: interval.clone(), defined, roots })
    }

    /// Proves `f(x(t)) ≡ 0` for the polynomial `f` written in `poly` ([`prove_implicit`]),
    /// within `budget` (its expression steps: [`Budget::expression_steps`]).
    ///
    /// # Errors
    /// As [`prove_implicit`]; [`Error::WorkLimit`] when the evaluation exceeds the steps.
    ///
    /// ```
    /// use casteljau::{RationalBezier, num::parse_points, rat, work::Budget};
    /// let arc = RationalBezier::new(parse_points("1 0, 1 1, 0 1", 2, None).unwrap(), vec![rat(1), rat(1), rat(2)]).unwrap();
    /// assert!(arc.implicit_within("x^2 + y^2 - 1", &Budget::unlimited()).unwrap().proved());
    /// ```
    pub fn implicit_within(&self, poly: &str, budget: &Budget) -> Result<ImplicitOutcome> {
        crate::proof::expr::with_step_limit(budget.expression_steps(), || prove_implicit(self, poly))
    }

    /// The conic of a rational quadratic ([`RationalBezier::conic_type`]) with its shape factor.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] unless the degree is 2.
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
