//! Rational splines with scale ratios (knot intervals) and their rational Bézier segments
//! (seed 002 §3, (24)–(32), and the quadratic construction (53)–(54) of §5).
//!
//! A degree-`n` rational spline has control points `q_0 … q_m` with weights `k_i` and scale ratios
//! `λ_0 … λ_{m+n−1}` (> 0): the knot intervals, knots `u_0 = 0`, `u_{j+1} = u_j + λ_j`. Its
//! segments `s = 0 … m−n` live on `[u_{n+s}, u_{n+s+1}]`, the interval of ratio `λ_{n+s}`.
//!
//! Three routes to the same rational Bézier segments, checked against each other:
//! * [`RationalSpline::eval`]: the NURBS itself, by de Boor's recursion on homogeneous points
//!   (`(24)`: `Σ w_i P_i N_i(t) / Σ w_i N_i(t)`);
//! * [`RationalSpline::to_bezier_boehm`]: Boehm knot insertion until every segment boundary has
//!   multiplicity `n`;
//! * [`seed_cubic_segment`] and [`seed_quadratic_segment`]: the seed's rational interpolation
//!   formulas (25)–(29) and (53), as printed or corrected.

pub(crate) mod knots;
pub(crate) mod net;
mod report;
pub(crate) mod surface;

pub use knots::{BezierPiece, Join};
pub use net::{NetReport, SplineNet};
pub use surface::{NurbsSurface, NurbsSurfaceReport, PatchPiece};

pub use report::{
    BezierConversion, KnotRemoval, SplineCheck, SplineSegment, SplineValue, SplineValues, SurfaceExtraction, joins_text,
};

use crate::curve::bezier::BezierCurve;
use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::{Exact, Scalar, rat};
use crate::num::small::{SmallRational, checked};
use crate::proof::Reading;
use crate::rational::rational_bezier::{RationalBezier, divide};
use num_rational::BigRational;
use std::cmp::Ordering;

/// Largest spline degree accepted.
pub(crate) const MAX_SPLINE_DEGREE: usize = 12;

/// A rational spline curve.
///
/// # Invariants
/// `homogeneous.len() ≥ degree + 1`; `knots.len() = homogeneous.len() + degree`; knots strictly
/// increase (all scale ratios positive).
///
/// # Example
/// ```
/// # use casteljau::{Point, rat, spline::RationalSpline};
/// // a quadratic spline with 4 control points and scale ratios 1, 2, 1, 1, 1: knots 0 1 3 4 5 6
/// let q: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y)])).collect();
/// let sp = RationalSpline::new(2, &q, &vec![rat(1); 4], &[rat(1), rat(2), rat(1), rat(1), rat(1)]).unwrap();
/// assert_eq!((sp.degree, sp.segments()), (2, 2));
/// assert_eq!(sp.knots, [0, 1, 3, 4, 5, 6].map(rat).to_vec());
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RationalSpline {
    /// The degree `n`.
    pub degree: usize,
    /// Homogeneous control points `(k_i q_i, k_i)`.
    pub homogeneous: Vec<Point<BigRational>>,
    /// Knots `u_0 … u_{m+n}` (partial sums of the scale ratios).
    pub knots: Vec<BigRational>,
}

impl RationalSpline {
    /// A spline from control points, weights and scale ratios (`m + n` of them).
    ///
    /// # Errors
    /// As [`homogeneous_control_points`] (wrong count, a weight of 0) and
    /// [`Self::from_ratios`] (wrong count, a ratio that is not positive, a degree outside
    /// `1..=`12 (`MAX_SPLINE_DEGREE`)).
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, spline::RationalSpline};
    /// // a quadratic spline with 4 control points and scale ratios 1, 2, 1, 1, 1: knots 0 1 3 4 5 6
    /// let q: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y)])).collect();
    /// let sp = RationalSpline::new(2, &q, &vec![rat(1); 4], &[rat(1), rat(2), rat(1), rat(1), rat(1)]).unwrap();
    /// // m + n = 5 ratios for m + 1 = 4 points of degree 2; a ratio 0 is refused
    /// assert!(RationalSpline::new(2, &q, &vec![rat(1); 4], &[rat(1), rat(0), rat(1), rat(1), rat(1)]).is_err());
    /// ```
    pub fn new(
        degree: usize,
        points: &[Point<BigRational>],
        weights: &[BigRational],
        ratios: &[BigRational],
    ) -> Result<Self> {
        Self::from_ratios(degree, homogeneous_control_points(points, Some(weights))?, ratios)
    }

    /// A spline from homogeneous control points (`w·P, w`) and scale ratios `λ_0 … λ_{m+n−1}`
    /// (the knot intervals): the knots are the partial sums `u_0 = 0`, `u_{j+1} = u_j + λ_j`,
    /// then as [`Self::from_knots`] (the final, never used knot repeats the one before).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for a ratio that is not positive (repeated knots need a knot
    /// vector) or a count other than `m + n` ratios for `m + 1` points; then as
    /// [`Self::from_knots`].
    ///
    /// # Example
    /// ```
    /// use casteljau::{Point, rat, spline::RationalSpline};
    /// let h: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
    /// let sp = RationalSpline::from_ratios(2, h.clone(), &[1, 2, 1, 1, 1].map(rat)).unwrap();
    /// assert_eq!(sp.full_knot_vector(), [0, 1, 3, 4, 5, 6, 6].map(rat));
    /// let e = RationalSpline::from_ratios(2, h, &[1, 0, 1, 1, 1].map(rat)).unwrap_err();
    /// assert!(e.to_string().contains("scale ratio 2 (0) must be positive"));
    /// ```
    pub fn from_ratios(degree: usize, homogeneous: Vec<Point<BigRational>>, ratios: &[BigRational]) -> Result<Self> {
        let bad = |m: String| Error::InvalidArgument { message: m };
        if let Some(i) = ratios.iter().position(|r| r.sign() != Ordering::Greater) {
            return Err(bad(format!(
                "scale ratio {} ({}) must be positive; repeated knots go in --knots",
                i + 1,
                ratios[i]
            )));
        }
        let need = (homogeneous.len() + degree).saturating_sub(1);
        if ratios.len() != need {
            return Err(bad(format!(
                "{} control points of degree {degree} need {need} scale ratios, got {}",
                homogeneous.len(),
                ratios.len()
            )));
        }
        let mut knots = Vec::with_capacity(ratios.len() + 2);
        knots.push(rat(0));
        for r in ratios {
            let next = knots.last().expect("non-empty").clone() + r;
            knots.push(next);
        }
        knots.push(knots.last().expect("non-empty").clone());
        Self::from_knots(degree, homogeneous, &knots)
    }

    /// A spline from homogeneous control points (e.g. the intermediate points of a net).
    ///
    /// # Errors
    /// As [`Self::new`].
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, spline::RationalSpline};
    /// // a quadratic spline with 4 control points and scale ratios 1, 2, 1, 1, 1: knots 0 1 3 4 5 6
    /// let q: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y)])).collect();
    /// let sp = RationalSpline::new(2, &q, &vec![rat(1); 4], &[rat(1), rat(2), rat(1), rat(1), rat(1)]).unwrap();
    /// let same = RationalSpline::from_homogeneous(2, sp.homogeneous.clone(), &[rat(1), rat(2), rat(1), rat(1), rat(1)]).unwrap();
    /// assert_eq!(same, sp);
    /// ```
    pub fn from_homogeneous(
        degree: usize,
        homogeneous: Vec<Point<BigRational>>,
        ratios: &[BigRational],
    ) -> Result<Self> {
        let d = homogeneous.first().map_or(1, Point::dim) - 1;
        let pts: Vec<Point<BigRational>> = homogeneous
            .iter()
            .map(|h| {
                h.from_homogeneous()
                    .ok_or_else(|| Error::PointAtInfinity { message: "a spline point at infinity".into() })
            })
            .collect::<Result<_>>()?;
        let ws: Vec<BigRational> = homogeneous.iter().map(|h| h.coords[d].clone()).collect();
        Self::new(degree, &pts, &ws, ratios)
    }

    /// Number of segments: the non-empty knot spans of the domain (`m − n + 1` when every
    /// scale ratio is positive).
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, spline::RationalSpline};
    /// // a quadratic spline with 4 control points and scale ratios 1, 2, 1, 1, 1: knots 0 1 3 4 5 6
    /// let q: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y)])).collect();
    /// let sp = RationalSpline::new(2, &q, &vec![rat(1); 4], &[rat(1), rat(2), rat(1), rat(1), rat(1)]).unwrap();
    /// assert_eq!(sp.segments(), 2);
    /// ```
    pub fn segments(&self) -> usize {
        self.span_indices().len()
    }

    /// The parameter interval of segment `s`: `[u_{n+s}, u_{n+s+1}]` when every scale ratio is
    /// positive, in general the `s`-th non-empty knot span of the domain.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, spline::RationalSpline};
    /// // a quadratic spline with 4 control points and scale ratios 1, 2, 1, 1, 1: knots 0 1 3 4 5 6
    /// let q: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y)])).collect();
    /// let sp = RationalSpline::new(2, &q, &vec![rat(1); 4], &[rat(1), rat(2), rat(1), rat(1), rat(1)]).unwrap();
    /// assert_eq!(sp.span(0), (rat(3), rat(4)));
    /// assert_eq!(sp.span(1), (rat(4), rat(5)));
    /// ```
    pub fn span(&self, s: usize) -> (BigRational, BigRational) {
        let j = self.span_indices()[s];
        (self.knots[j].clone(), self.knots[j + 1].clone())
    }

    /// The homogeneous NURBS point at `u` in segment `s` (de Boor's recursion).
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, spline::RationalSpline};
    /// // a quadratic spline with 4 control points and scale ratios 1, 2, 1, 1, 1: knots 0 1 3 4 5 6
    /// let q: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y)])).collect();
    /// let sp = RationalSpline::new(2, &q, &vec![rat(1); 4], &[rat(1), rat(2), rat(1), rat(1), rat(1)]).unwrap();
    /// assert_eq!(sp.eval_homogeneous(0, &rat(4)).from_homogeneous().unwrap(), sp.eval(0, &rat(4)).unwrap());
    /// ```
    pub fn eval_homogeneous(&self, s: usize, u: &BigRational) -> Point<BigRational> {
        de_boor(&self.knots, &self.homogeneous, self.degree, self.span_indices()[s], u)
    }

    /// The NURBS point at `u` in segment `s`.
    ///
    /// # Errors
    /// [`Error::WeightsVanish`] where the denominator is 0.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, spline::RationalSpline};
    /// // a quadratic spline with 4 control points and scale ratios 1, 2, 1, 1, 1: knots 0 1 3 4 5 6
    /// let q: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y)])).collect();
    /// let sp = RationalSpline::new(2, &q, &vec![rat(1); 4], &[rat(1), rat(2), rat(1), rat(1), rat(1)]).unwrap();
    /// // segment 0 ends where segment 1 starts
    /// assert_eq!(sp.eval(0, &rat(4)).unwrap(), sp.eval(1, &rat(4)).unwrap());
    /// ```
    pub fn eval(&self, s: usize, u: &BigRational) -> Result<Point<BigRational>> {
        self.eval_homogeneous(s, u)
            .from_homogeneous()
            .ok_or(Error::WeightsVanish { interval: (u.to_string(), u.to_string()) })
    }

    /// Rational Bézier segments by Boehm knot insertion (each boundary knot to multiplicity `n`):
    /// [`Self::bezier_segments`], for any knot vector.
    ///
    /// # Errors
    /// [`Error::PointAtInfinity`] when an inserted homogeneous point is zero (weights of
    /// opposite signs cancelling), so a segment has no rational form.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, spline::RationalSpline};
    /// // a quadratic spline with 4 control points and scale ratios 1, 2, 1, 1, 1: knots 0 1 3 4 5 6
    /// let q: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y)])).collect();
    /// let sp = RationalSpline::new(2, &q, &vec![rat(1); 4], &[rat(1), rat(2), rat(1), rat(1), rat(1)]).unwrap();
    /// let segs = sp.to_bezier_boehm().unwrap();
    /// assert_eq!(segs.len(), 2);
    /// assert_eq!(segs[0].eval(&rat(1)).unwrap(), segs[1].eval(&rat(0)).unwrap());
    /// ```
    pub fn to_bezier_boehm(&self) -> Result<Vec<RationalBezier<BigRational>>> {
        self.bezier_segments()
    }

    /// The local scale ratio `λ_i` around segment `s` (`i = 0` is the segment's own interval).
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, spline::RationalSpline};
    /// // a quadratic spline with 4 control points and scale ratios 1, 2, 1, 1, 1: knots 0 1 3 4 5 6
    /// let q: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y)])).collect();
    /// let sp = RationalSpline::new(2, &q, &vec![rat(1); 4], &[rat(1), rat(2), rat(1), rat(1), rat(1)]).unwrap();
    /// assert_eq!(sp.local_ratio(0, 0), rat(1)); // the span's own interval [3, 4]
    /// assert_eq!(sp.local_ratio(0, -1), rat(2)); // [1, 3]
    /// ```
    pub fn local_ratio(&self, s: usize, i: i64) -> BigRational {
        let j = (self.degree + s) as i64 + i;
        self.knots[j as usize + 1].clone() - &self.knots[j as usize]
    }
}

/// Homogeneous control points `(w_i·P_i, w_i)` from affine points and their weights (all 1
/// when `weights` is `None`).
///
/// # Errors
/// [`Error::InvalidArgument`] when the counts differ or a weight is 0 (a control point at
/// infinity is given in homogeneous form, e.g. [`RationalSpline::from_knots`]).
///
/// # Example
/// ```
/// use casteljau::{Point, rat, ratio, spline::homogeneous_control_points};
/// let p = [Point::new(vec![rat(1), rat(2)]), Point::new(vec![rat(3), rat(0)])];
/// let h = homogeneous_control_points(&p, Some(&[ratio(1, 2), rat(1)])).unwrap();
/// assert_eq!(h[0], Point::new(vec![ratio(1, 2), rat(1), ratio(1, 2)]));
/// assert_eq!(homogeneous_control_points(&p, None).unwrap()[1], Point::new(vec![rat(3), rat(0), rat(1)]));
/// assert!(homogeneous_control_points(&p, Some(&[rat(1), rat(0)])).is_err());
/// ```
pub fn homogeneous_control_points(
    points: &[Point<BigRational>],
    weights: Option<&[BigRational]>,
) -> Result<Vec<Point<BigRational>>> {
    let lift = crate::rational::rational_bezier::weighted_homogeneous::<BigRational>;
    let Some(weights) = weights else {
        return Ok(points.iter().map(|p| lift(p, &rat(1))).collect());
    };
    if weights.len() != points.len() {
        return Err(Error::WeightCount { weights: weights.len(), points: points.len(), row: None });
    }
    if let Some(i) = weights.iter().position(Scalar::is_zero) {
        return Err(Error::ZeroWeight { index: i + 1, row: None });
    }
    Ok(points.iter().zip(weights).map(|(p, w)| lift(p, w)).collect())
}

fn w_lin(a: &BigRational, b: &BigRational, x: &BigRational, y: &BigRational) -> BigRational {
    // 𝒲[a:b](x, y) for numbers: (b x + a y)/(a + b)
    (b.clone() * x + a.clone() * y) / (a.clone() + b)
}

/// How a spline is turned into rational Bézier segments: the one switch behind `spline
/// to-bezier --method`, the `method` of the claim files and spline nets.
///
/// Written `boehm`, `seed` or `seed-printed` ([`FromStr`](std::str::FromStr), and so in claim
/// files).
///
/// # Example
/// ```
/// use casteljau::{proof::Reading, spline::Conversion};
/// assert_eq!("boehm".parse::<Conversion>().unwrap(), Conversion::Boehm);
/// assert_eq!("seed-printed".parse::<Conversion>().unwrap(), Conversion::Seed(Reading::AsPrinted));
/// assert!("bohem".parse::<Conversion>().is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Deserialize)]
#[serde(try_from = "String")]
pub enum Conversion {
    /// Boehm knot insertion (any degree).
    Boehm,
    /// The seed's rational interpolation formulas: (25)–(29) for cubics (which hold as
    /// printed, so both readings give them) and (53) for quadratics, as printed or corrected.
    Seed(Reading),
}

impl std::str::FromStr for Conversion {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "boehm" => Ok(Conversion::Boehm),
            "seed" => Ok(Conversion::Seed(Reading::Corrected)),
            "seed-printed" => Ok(Conversion::Seed(Reading::AsPrinted)),
            other => Err(Error::InvalidArgument {
                message: format!("the conversion method is boehm, seed or seed-printed, not {other:?}"),
            }),
        }
    }
}

impl std::fmt::Display for Conversion {
    /// The spelling [`FromStr`](std::str::FromStr) reads: `boehm`, `seed`, `seed-printed`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Conversion::Boehm => "boehm",
            Conversion::Seed(Reading::Corrected) => "seed",
            Conversion::Seed(Reading::AsPrinted) => "seed-printed",
        })
    }
}

impl TryFrom<String> for Conversion {
    type Error = Error;
    fn try_from(s: String) -> Result<Self> {
        s.parse()
    }
}

impl RationalSpline {
    /// The rational Bézier segments, one per span, by the chosen route.
    ///
    /// # Errors
    /// [`Error::NotApplicable`] for the seed's formulas on a degree other than 2 or 3,
    /// [`Error::Degenerate`] when a ratio of their construction vanishes.
    ///
    /// # Example
    /// ```
    /// use casteljau::{Point, rat, proof::Reading, spline::{Conversion, RationalSpline}};
    /// let q: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y)])).collect();
    /// // a quadratic spline with scale ratios 1, 2, 1, 1, 1: two segments
    /// let sp = RationalSpline::new(2, &q, &vec![rat(1); 4], &[rat(1), rat(2), rat(1), rat(1), rat(1)]).unwrap();
    /// let boehm = sp.to_bezier(Conversion::Boehm).unwrap();
    /// assert_eq!(boehm.len(), 2);
    /// assert_eq!(boehm, sp.to_bezier(Conversion::Seed(Reading::Corrected)).unwrap());
    /// ```
    pub fn to_bezier(&self, how: Conversion) -> Result<Vec<RationalBezier<BigRational>>> {
        let segments = 0..self.segments();
        match (how, self.degree) {
            (Conversion::Boehm, _) => self.to_bezier_boehm(),
            (Conversion::Seed(_), _) if self.has_repeated_knots() => Err(Error::NotApplicable {
                message: "the seed's formulas need positive scale ratios (no repeated knots): use the boehm method"
                    .into(),
            }),
            (Conversion::Seed(_), 3) => segments.map(|s| seed_cubic_segment(self, s)).collect(),
            (Conversion::Seed(reading), 2) => segments.map(|s| seed_quadratic_segment(self, s, reading)).collect(),
            (Conversion::Seed(_), n) => Err(Error::NotApplicable {
                message: format!("the seed gives formulas for degrees 2 and 3, not {n}: use the boehm method"),
            }),
        }
    }
}

/// Seed 002 (25)–(29): the rational Bézier segment `s` of a cubic rational spline. `P_{-1}` and
/// `P_4` are the neighbouring junction helpers; `P0 = 𝒲[λ_{−1}w_1 : λ_0 w_{−1}](P_{−1}, P_1)`, etc.
///
/// # Errors
/// [`Error::NotApplicable`] unless the spline is cubic.
///
/// # Example
/// ```
/// use casteljau::{Point, rat, spline::{RationalSpline, seed_cubic_segment}};
/// let q: Vec<Point<_>> = (0..5).map(|i| Point::new(vec![rat(i), rat(i * i % 3)])).collect();
/// let ratios = [1, 2, 1, 3, 1, 2, 1].map(rat);
/// let sp = RationalSpline::new(3, &q, &[1, 2, 1, 3, 1].map(rat), &ratios).unwrap();
/// assert_eq!(seed_cubic_segment(&sp, 1).unwrap(), sp.to_bezier_boehm().unwrap()[1]);
/// ```
#[doc(hidden)]
pub fn seed_cubic_segment(sp: &RationalSpline, s: usize) -> Result<RationalBezier<BigRational>> {
    if sp.degree != 3 {
        return Err(Error::NotApplicable { message: "(25)-(29) are for cubic splines".into() });
    }
    let l = |i: i64| sp.local_ratio(s, i);
    let q: Vec<Point<BigRational>> =
        sp.homogeneous[s..s + 4].iter().map(|h| h.from_homogeneous().expect("finite")).collect();
    let k: Vec<BigRational> = sp.homogeneous[s..s + 4].iter().map(|h| h.coords[h.dim() - 1].clone()).collect();
    // local names: q_{-1} = q[0], q0 = q[1], q1 = q[2], q2 = q[3]
    let fail = || Error::Degenerate { message: "a ratio of the construction vanishes".into() };
    let (lm2, lm1, l0, l1, l2) = (l(-2), l(-1), l(0), l(1), l(2));
    // (29) weights
    let wm1 = w_lin(&(lm2.clone() + &lm1), &l0, &k[0], &k[1]);
    let w1 = w_lin(&lm1, &(l0.clone() + &l1), &k[1], &k[2]);
    let w2 = w_lin(&(lm1.clone() + &l0), &l1, &k[1], &k[2]);
    let w4 = w_lin(&l0, &(l1.clone() + &l2), &k[2], &k[3]);
    let w0 = w_lin(&lm1, &l0, &wm1, &w1);
    let w3 = w_lin(&l0, &l1, &w2, &w4);
    // (28) points
    let pm1 = divide(&((lm2.clone() + &lm1) * &k[1]), &(l0.clone() * &k[0]), &q[0], &q[1]).ok_or_else(fail)?;
    let p1 = divide(&(lm1.clone() * &k[2]), &((l0.clone() + &l1) * &k[1]), &q[1], &q[2]).ok_or_else(fail)?;
    let p2 = divide(&((lm1.clone() + &l0) * &k[2]), &(l1.clone() * &k[1]), &q[1], &q[2]).ok_or_else(fail)?;
    let p4 = divide(&(l0.clone() * &k[3]), &((l1.clone() + &l2) * &k[2]), &q[2], &q[3]).ok_or_else(fail)?;
    let p0 = divide(&(lm1.clone() * &w1), &(l0.clone() * &wm1), &pm1, &p1).ok_or_else(fail)?;
    let p3 = divide(&(l0.clone() * &w4), &(l1.clone() * &w2), &p2, &p4).ok_or_else(fail)?;
    RationalBezier::new(vec![p0, p1, p2, p3], vec![w0, w1, w2, w3])
}

/// Seed 002 (53) for a curve: the rational Bézier segment `s` of a quadratic rational spline,
/// `P'_0 = 𝒲[λ_{−1}k_? : λ_0 k_0](q_0, q_1)`, `P'_1 = q_1`, `P'_2 = 𝒲[λ_0 k_2 : λ_1 k_?](q_1, q_2)`.
/// As printed the `?` are `k_0` and `k_2` (the same weight on both sides); corrected they are
/// `k_1` (the weight of the far point, as in (28)).
///
/// # Errors
/// [`Error::NotApplicable`] unless the spline is quadratic.
///
/// # Example
/// ```
/// # use casteljau::{Point, rat, spline::RationalSpline};
/// // a quadratic spline with 4 control points and scale ratios 1, 2, 1, 1, 1: knots 0 1 3 4 5 6
/// let q: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y)])).collect();
/// let sp = RationalSpline::new(2, &q, &vec![rat(1); 4], &[rat(1), rat(2), rat(1), rat(1), rat(1)]).unwrap();
/// use casteljau::{proof::Reading, spline::seed_quadratic_segment};
/// let boehm = sp.to_bezier_boehm().unwrap();
/// assert_eq!(seed_quadratic_segment(&sp, 0, Reading::Corrected).unwrap(), boehm[0]);
/// ```
#[doc(hidden)]
pub fn seed_quadratic_segment(sp: &RationalSpline, s: usize, version: Reading) -> Result<RationalBezier<BigRational>> {
    if sp.degree != 2 {
        return Err(Error::NotApplicable { message: "(53) is for quadratic splines".into() });
    }
    let (lm1, l0, l1) = (sp.local_ratio(s, -1), sp.local_ratio(s, 0), sp.local_ratio(s, 1));
    let q: Vec<Point<BigRational>> =
        sp.homogeneous[s..s + 3].iter().map(|h| h.from_homogeneous().expect("finite")).collect();
    let k: Vec<BigRational> = sp.homogeneous[s..s + 3].iter().map(|h| h.coords[h.dim() - 1].clone()).collect();
    let fail = || Error::Degenerate { message: "a ratio of the construction vanishes".into() };
    let (left_far, right_near) = match version {
        Reading::AsPrinted => (k[0].clone(), k[2].clone()),
        Reading::Corrected => (k[1].clone(), k[1].clone()),
    };
    let p0 = divide(&(lm1.clone() * &left_far), &(l0.clone() * &k[0]), &q[0], &q[1]).ok_or_else(fail)?;
    let p2 = divide(&(l0.clone() * &k[2]), &(l1.clone() * &right_near), &q[1], &q[2]).ok_or_else(fail)?;
    let w0 = w_lin(&lm1, &l0, &k[0], &k[1]);
    let w2 = w_lin(&l0, &l1, &k[1], &k[2]);
    RationalBezier::new(vec![p0, q[1].clone(), p2], vec![w0, k[1].clone(), w2])
}

/// One failed check of [`check_segments`].
///
/// # Example
/// ```
/// # use casteljau::{Point, rat, spline::RationalSpline};
/// // a quadratic spline with 4 control points and scale ratios 1, 2, 1, 1, 1: knots 0 1 3 4 5 6
/// let q: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y)])).collect();
/// let sp = RationalSpline::new(2, &q, &vec![rat(1); 4], &[rat(1), rat(2), rat(1), rat(1), rat(1)]).unwrap();
/// use casteljau::spline::{SegmentMismatch, check_segments};
/// let mut segs = sp.to_bezier_boehm().unwrap();
/// segs.swap(0, 1);
/// assert!(matches!(check_segments(&sp, &segs), Err(SegmentMismatch::NotTheNurbs { .. })));
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SegmentMismatch {
    /// Segment `s` differs from the NURBS at its local parameter `t`.
    NotTheNurbs {
        /// The segment.
        segment: usize,
        /// The local parameter in `[0, 1]`.
        t: BigRational,
    },
    /// Derivative of order `order` jumps at the joint after segment `segment`.
    Discontinuous {
        /// The left segment.
        segment: usize,
        /// The derivative order.
        order: usize,
    },
}

/// Proves that `segments` are the NURBS `sp` on its spans (rational of type ≤ `(n, n)` in the
/// local parameter: `2n + 1` exact parameters decide each) and that consecutive segments join
/// with the continuity `C^{n−μ}` of each join's knot multiplicity `μ` (`C^{n−1}` for positive
/// scale ratios) in the spline parameter (`d^r/du^r = λ^{−r} d^r/dt^r`), by
/// [`RationalSpline::joins`].
///
/// # Errors
/// The first mismatch found.
///
/// # Example
/// ```
/// # use casteljau::{Point, rat, spline::RationalSpline};
/// // a quadratic spline with 4 control points and scale ratios 1, 2, 1, 1, 1: knots 0 1 3 4 5 6
/// let q: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y)])).collect();
/// let sp = RationalSpline::new(2, &q, &vec![rat(1); 4], &[rat(1), rat(2), rat(1), rat(1), rat(1)]).unwrap();
/// use casteljau::spline::check_segments;
/// assert!(check_segments(&sp, &sp.to_bezier_boehm().unwrap()).is_ok());
/// ```
#[doc(hidden)]
pub fn check_segments(
    sp: &RationalSpline,
    segments: &[RationalBezier<BigRational>],
) -> std::result::Result<usize, SegmentMismatch> {
    // The same comparisons in fixed-width rationals first (about 20 times faster on the small
    // numbers of most splines); exact either way: an overflow anywhere redoes them in BigRational.
    let small = checked(|| {
        let knots: Vec<SmallRational> = sp.knots.iter().map(SmallRational::from_big).collect::<Option<_>>()?;
        let small_points = |ps: &[Point<BigRational>]| -> Option<Vec<Point<SmallRational>>> {
            ps.iter()
                .map(|p| p.coords.iter().map(SmallRational::from_big).collect::<Option<Vec<_>>>().map(Point::new))
                .collect()
        };
        let homogeneous = small_points(&sp.homogeneous)?;
        let segments: Vec<BezierCurve<SmallRational>> = segments
            .iter()
            .map(|c| BezierCurve::new(small_points(c.homogeneous().points())?).ok())
            .collect::<Option<_>>()?;
        Some(nurbs_agreement(sp, &knots, &homogeneous, &segments))
    })
    .flatten();
    let points = match small {
        Some(r) => r?,
        None => {
            let homogeneous: Vec<BezierCurve<BigRational>> = segments.iter().map(|c| c.homogeneous().clone()).collect();
            nurbs_agreement(sp, &sp.knots, &sp.homogeneous, &homogeneous)?
        }
    };
    if let Some((s, j)) = sp.joins(segments).into_iter().enumerate().find(|(_, j)| !j.proved) {
        return Err(SegmentMismatch::Discontinuous { segment: s, order: j.continuity.max(0) as usize });
    }
    Ok(points)
}

/// De Boor's recursion on the homogeneous `points` in the knot span `j` (`t_j ≤ u ≤ t_{j+1}`,
/// internal knot vector, degree `n`).
fn de_boor<S: Scalar>(knots: &[S], points: &[Point<S>], n: usize, j: usize, u: &S) -> Point<S> {
    let mut d: Vec<Point<S>> = points[j - n..=j].to_vec();
    for r in 1..=n {
        for i in (r..=n).rev() {
            let idx = j - n + i; // control point index
            let (lo, hi) = (&knots[idx], &knots[idx + n + 1 - r]);
            let a = (u.clone() - lo) / (hi.clone() - lo);
            d[i] = d[i - 1].lerp(&d[i], &a);
        }
    }
    d.swap_remove(n)
}

/// The first half of [`check_segments`] in any exact scalar: each homogeneous segment (the
/// Bernstein sum) and the NURBS (de Boor) at `2n + 1` parameters of each span give the same
/// affine point, or both none (weight 0). `knots` and `points` are the spline's, converted.
/// Points are compared homogeneously, `x·w' = x'·w` with both weights non-zero, which is
/// equality of the affine points without a division.
fn nurbs_agreement<S: Exact>(
    sp: &RationalSpline,
    knots: &[S],
    points: &[Point<S>],
    segments: &[BezierCurve<S>],
) -> std::result::Result<usize, SegmentMismatch> {
    let n = sp.degree;
    let spans = sp.span_indices();
    let mut count = 0;
    let two_n = S::from_i64(2 * n as i64);
    for (s, seg) in segments.iter().enumerate() {
        let Some(&j) = spans.get(s) else {
            return Err(SegmentMismatch::NotTheNurbs { segment: s, t: rat(0) });
        };
        let (a, b) = (&knots[j], &knots[j + 1]);
        for k in 0..=2 * n {
            let t = S::from_i64(k as i64) / &two_n;
            let u = a.clone() + (b.clone() - a) * &t;
            let (x, y) = (seg.eval_bernstein(&t), de_boor(knots, points, n, j, &u));
            let (wx, wy) = (&x.coords[x.dim() - 1], &y.coords[y.dim() - 1]);
            let agree = match (wx.is_zero(), wy.is_zero()) {
                (true, true) => true, // neither is defined there
                (false, false) => {
                    let same = x.dim() == y.dim()
                        && x.coords.iter().zip(&y.coords).all(|(p, q)| p.clone() * wy == q.clone() * wx);
                    count += usize::from(same);
                    same
                }
                _ => false,
            };
            if !agree {
                return Err(SegmentMismatch::NotTheNurbs {
                    segment: s,
                    t: BigRational::new((k as i64).into(), ((2 * n) as i64).into()),
                });
            }
        }
    }
    Ok(count)
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    #[test]
    fn max_spline_degree_example() {
        use crate::{
            Point, rat,
            spline::{MAX_SPLINE_DEGREE, RationalSpline},
        };
        let n = MAX_SPLINE_DEGREE + 1;
        let q = vec![Point::new(vec![rat(0), rat(0)]); n + 1];
        assert!(RationalSpline::new(n, &q, &vec![rat(1); n + 1], &vec![rat(1); 2 * n]).is_err());
    }
}
