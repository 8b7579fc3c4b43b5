//! Rational splines as CAD users give them: a knot vector with multiplicities (clamped or not),
//! knot insertion and exact knot removal, Bézier extraction with the continuity at every join
//! proved, degree elevation, and de Boor evaluation at any parameter of the domain.
//!
//! # Knot convention
//! A degree-`n` spline with control points `P_0 … P_m` has the standard knot vector
//! `t_0 ≤ t_1 ≤ … ≤ t_{m+n+1}` (`m + n + 2` knots, as in IGES/STEP and most NURBS libraries),
//! and its domain is `[t_n, t_{m+1}]`. The first and the last knot never influence the curve on
//! its domain; [`RationalSpline::knots`] keeps `t_0 … t_{m+n}` (the last one dropped), which is
//! exactly the seed's scale-ratio form: ratios `λ_j = t_{j+1} − t_j`, `t_0 = 0`.
//!
//! Interior knots may have any multiplicity `μ ≤ n + 1`; the curve is `C^(n−μ)` there
//! (`C^-1`, a jump, for `μ = n + 1`), and the ends any multiplicity `≤ n + 1` (clamped:
//! `n + 1`). Everything is exact, in homogeneous coordinates, so weights may be zero or negative
//! (points at infinity).
//!
//! # Example
//! ```
//! use casteljau::{Point, rat, spline::RationalSpline};
//! let p: Vec<Point<_>> = [(0, 0), (1, 2), (2, -1), (3, 3), (4, 0), (5, 1)]
//!     .iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
//! // a clamped cubic with one double interior knot: C^1 at u = 1, C^2 at u = 2... here only 1
//! let knots = [0, 0, 0, 0, 1, 1, 2, 2, 2, 2].map(rat);
//! let sp = RationalSpline::from_knots(3, p, &knots).unwrap();
//! let segs = sp.bezier_segments().unwrap();
//! assert_eq!(segs.len(), 2);
//! let joins = sp.joins(&segs);
//! assert_eq!((joins[0].multiplicity, joins[0].continuity, joins[0].proved), (2, 1, true));
//! ```

use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::{Exact, Scalar, rat};
use crate::rational::rational_bezier::RationalBezier;
use crate::spline::{MAX_SPLINE_DEGREE, RationalSpline};
use num_rational::BigRational;
use std::cmp::Ordering;

/// Largest number of control points of a spline read from a knot vector.
pub const MAX_SPLINE_POINTS: usize = 10_000;

/// A join between two adjacent Bézier segments: the knot, its multiplicity `μ`, the continuity
/// `n − μ` it implies (`-1`: a jump), and whether the homogeneous derivatives of orders
/// `0 ..= n − μ` of the two segments were found equal exactly (with respect to the global
/// parameter).
///
/// # Example
/// ```
/// # use casteljau::{Point, rat, ratio, spline::RationalSpline};
/// // a clamped quadratic with an interior knot 1: two Bézier pieces
/// let p: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
/// let sp = RationalSpline::from_knots(2, p, &[0, 0, 0, 1, 2, 2, 2].map(rat)).unwrap();
/// let joins = sp.joins(&sp.bezier_segments().unwrap());
/// assert_eq!((joins[0].knot.clone(), joins[0].multiplicity, joins[0].continuity, joins[0].proved), (rat(1), 1, 1, true));
/// ```
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Join {
    /// The knot value.
    #[serde(serialize_with = "crate::num::serial::string")]
    pub knot: BigRational,
    /// Its multiplicity in the spline's knot vector.
    pub multiplicity: usize,
    /// `n − μ`: the curve is `C^continuity` there (`-1`: no continuity claimed).
    pub continuity: i64,
    /// The derivatives up to that order agree exactly.
    pub proved: bool,
}

/// Homogeneous Bézier control points of one segment and its parameter interval.
///
/// # Example
/// ```
/// # use casteljau::{Point, rat, ratio, spline::RationalSpline};
/// // a clamped quadratic with an interior knot 1: two Bézier pieces
/// let p: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
/// let sp = RationalSpline::from_knots(2, p, &[0, 0, 0, 1, 2, 2, 2].map(rat)).unwrap();
/// let pieces = sp.bezier_pieces().unwrap();
/// assert_eq!(pieces[1].span, (rat(1), rat(2)));
/// assert_eq!(pieces[1].homogeneous.len(), 3);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BezierPiece {
    /// The interval `[a, b]` of the global parameter.
    pub span: (BigRational, BigRational),
    /// `n + 1` homogeneous control points (`w·P, w`).
    pub homogeneous: Vec<Point<BigRational>>,
}

impl BezierPiece {
    /// The piece as a rational Bézier curve on `[0, 1]`.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for a zero homogeneous point.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, spline::RationalSpline};
    /// // a clamped quadratic with an interior knot 1: two Bézier pieces
    /// let p: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
    /// let sp = RationalSpline::from_knots(2, p, &[0, 0, 0, 1, 2, 2, 2].map(rat)).unwrap();
    /// let c = sp.bezier_pieces().unwrap()[0].curve().unwrap();
    /// assert_eq!(c.eval(&rat(1)).unwrap(), sp.eval_at(&rat(1)).unwrap());
    /// ```
    pub fn curve(&self) -> Result<RationalBezier<BigRational>> {
        RationalBezier::from_homogeneous(self.homogeneous.clone())
    }
}

fn bad(message: String) -> Error {
    Error::InvalidArgument { message }
}

/// The multiplicity of `u` in `knots`.
fn multiplicity(knots: &[BigRational], u: &BigRational) -> usize {
    knots.iter().filter(|k| *k == u).count()
}

impl RationalSpline {
    /// A spline from homogeneous control points (`w·P, w`; `w = 0` is a point at infinity) and
    /// a full knot vector of `m + n + 2` non-decreasing exact knots (see the module's knot
    /// convention).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming the offending knot for a decreasing knot vector, a
    /// multiplicity above `n + 1`, a wrong count (`points + degree + 1` knots), an empty domain,
    /// a zero homogeneous point or mixed dimensions; [`Error::TooLarge`] beyond
    /// 12 (`MAX_SPLINE_DEGREE`) or 10,000 (`MAX_SPLINE_POINTS`).
    ///
    /// # Example
    /// ```
    /// use casteljau::{Point, rat, spline::RationalSpline};
    /// let p: Vec<Point<_>> = (0..4).map(|i| Point::new(vec![rat(i), rat(i * i), rat(1)])).collect();
    /// assert!(RationalSpline::from_knots(2, p.clone(), &[0, 0, 0, 1, 2, 2, 2].map(rat)).is_ok());
    /// let e = RationalSpline::from_knots(2, p.clone(), &[0, 0, 0, 2, 1, 2, 2].map(rat)).unwrap_err();
    /// assert!(e.to_string().contains("knot 5 (1) is less than knot 4 (2)"));
    /// assert!(RationalSpline::from_knots(2, p, &[0, 0, 0, 0, 2, 2, 2].map(rat)).is_err()); // μ = 4 > 3
    /// ```
    pub fn from_knots(degree: usize, homogeneous: Vec<Point<BigRational>>, knots: &[BigRational]) -> Result<Self> {
        if degree == 0 || degree > MAX_SPLINE_DEGREE {
            return Err(Error::TooLarge { what: "spline degree", value: degree, limit: MAX_SPLINE_DEGREE });
        }
        if homogeneous.len() > MAX_SPLINE_POINTS {
            return Err(Error::TooLarge {
                what: "spline control points",
                value: homogeneous.len(),
                limit: MAX_SPLINE_POINTS,
            });
        }
        if homogeneous.len() < degree + 1 {
            return Err(bad(format!(
                "a degree-{degree} spline needs at least {} control points, got {}",
                degree + 1,
                homogeneous.len()
            )));
        }
        let dim = homogeneous[0].dim();
        if dim < 2 {
            return Err(bad("homogeneous control points need at least 2 coordinates".into()));
        }
        if let Some(i) = homogeneous.iter().position(|p| p.dim() != dim || p.coords.iter().all(Scalar::is_zero)) {
            return Err(bad(format!("homogeneous control point {} is zero or of another dimension", i + 1)));
        }
        let need = homogeneous.len() + degree + 1;
        if knots.len() != need {
            return Err(bad(format!(
                "{} control points of degree {degree} need {need} knots (points + degree + 1), got {}",
                homogeneous.len(),
                knots.len()
            )));
        }
        if let Some(i) = (1..knots.len()).find(|&i| knots[i] < knots[i - 1]) {
            return Err(bad(format!(
                "knot {} ({}) is less than knot {} ({}): knots must not decrease",
                i + 1,
                knots[i],
                i,
                knots[i - 1]
            )));
        }
        let mut i = 0;
        while i < knots.len() {
            let mu = multiplicity(&knots[i..], &knots[i]);
            if mu > degree + 1 {
                return Err(bad(format!(
                    "knot {} ({}) has multiplicity {mu}, more than degree + 1 = {}",
                    i + 1,
                    knots[i],
                    degree + 1
                )));
            }
            i += mu;
        }
        let m = homogeneous.len() - 1;
        if knots[degree] >= knots[m + 1] {
            return Err(bad(format!(
                "the domain [t_{degree}, t_{}] = [{}, {}] is empty",
                m + 1,
                knots[degree],
                knots[m + 1]
            )));
        }
        Ok(RationalSpline { degree, homogeneous, knots: knots[..knots.len() - 1].to_vec() })
    }

    /// The domain `[t_n, t_{m+1}]`.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, spline::RationalSpline};
    /// // a clamped quadratic with an interior knot 1: two Bézier pieces
    /// let p: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
    /// let sp = RationalSpline::from_knots(2, p, &[0, 0, 0, 1, 2, 2, 2].map(rat)).unwrap();
    /// assert_eq!(sp.domain(), (rat(0), rat(2)));
    /// ```
    pub fn domain(&self) -> (BigRational, BigRational) {
        (self.knots[self.degree].clone(), self.knots[self.homogeneous.len()].clone())
    }

    /// The knot vector as given to [`Self::from_knots`] without its last knot: `t_0 … t_{m+n}`.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, spline::RationalSpline};
    /// // a clamped quadratic with an interior knot 1: two Bézier pieces
    /// let p: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
    /// let sp = RationalSpline::from_knots(2, p, &[0, 0, 0, 1, 2, 2, 2].map(rat)).unwrap();
    /// assert_eq!(sp.knot_vector(), &[0, 0, 0, 1, 2, 2].map(rat)); // the last knot 2 is not kept
    /// ```
    pub fn knot_vector(&self) -> &[BigRational] {
        &self.knots
    }

    /// A full knot vector (`m + n + 2` knots) for output: [`Self::knot_vector`] with its last
    /// knot repeated as the never-used final knot (the input's own last knot is not kept; for
    /// a clamped end it is the same value).
    ///
    /// # Example
    /// ```
    /// use casteljau::{Point, rat, spline::RationalSpline};
    /// let p: Vec<Point<_>> = (0..4).map(|i| Point::new(vec![rat(i), rat(0), rat(1)])).collect();
    /// let knots = [0, 0, 0, 1, 2, 2, 2].map(rat);
    /// assert_eq!(RationalSpline::from_knots(2, p, &knots).unwrap().full_knot_vector(), knots);
    /// ```
    pub fn full_knot_vector(&self) -> Vec<BigRational> {
        let mut k = self.knots.clone();
        k.push(self.knots.last().expect("a spline has knots").clone());
        k
    }

    /// Some knot after the first repeats (a zero scale ratio): the seed's formulas do not apply.
    ///
    /// # Example
    /// ```
    /// use casteljau::{Point, rat, spline::RationalSpline};
    /// let p: Vec<Point<_>> = (0..4).map(|i| Point::new(vec![rat(i), rat(0), rat(1)])).collect();
    /// assert!(RationalSpline::from_knots(2, p.clone(), &[0, 0, 0, 1, 2, 2, 2].map(rat)).unwrap().has_repeated_knots());
    /// assert!(!RationalSpline::from_knots(2, p, &[0, 1, 2, 3, 4, 5, 6].map(rat)).unwrap().has_repeated_knots());
    /// ```
    pub fn has_repeated_knots(&self) -> bool {
        self.knots[1..].windows(2).any(|w| w[0] == w[1])
    }

    /// The homogeneous point at any `u` of the domain by de Boor's recursion (at an interior
    /// knot, from the span on its right; at the right end, from the last span).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for `u` outside the domain.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, spline::RationalSpline};
    /// // a clamped quadratic with an interior knot 1: two Bézier pieces
    /// let p: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
    /// let sp = RationalSpline::from_knots(2, p, &[0, 0, 0, 1, 2, 2, 2].map(rat)).unwrap();
    /// assert_eq!(sp.eval_homogeneous_at(&rat(1)).unwrap().to_string(), "(2, 2, 1)");
    /// ```
    pub fn eval_homogeneous_at(&self, u: &BigRational) -> Result<Point<BigRational>> {
        let (a, b) = self.domain();
        if *u < a || *u > b {
            return Err(bad(format!("u = {u} is outside the domain [{a}, {b}]")));
        }
        let spans = self.span_indices();
        let s = spans.iter().rposition(|&j| self.knots[j] <= *u).unwrap_or(0);
        Ok(self.eval_homogeneous(s, u))
    }

    /// The point at any `u` of the domain (de Boor).
    ///
    /// # Errors
    /// As [`Self::eval_homogeneous_at`], and [`Error::WeightsVanish`] where the weight is 0.
    ///
    /// # Example
    /// ```
    /// use casteljau::{Point, rat, ratio, spline::RationalSpline};
    /// let p: Vec<Point<_>> = [(0, 0), (1, 1), (2, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
    /// let sp = RationalSpline::from_knots(2, p, &[0, 0, 0, 1, 1, 1].map(rat)).unwrap(); // one Bézier piece
    /// assert_eq!(sp.eval_at(&ratio(1, 2)).unwrap().to_string(), "(1, 1/2)");
    /// assert!(sp.eval_at(&rat(2)).is_err());
    /// ```
    pub fn eval_at(&self, u: &BigRational) -> Result<Point<BigRational>> {
        self.eval_homogeneous_at(u)?
            .from_homogeneous()
            .ok_or(Error::WeightsVanish { interval: (u.to_string(), u.to_string()) })
    }

    /// Indices `j` of the knot spans `[t_j, t_{j+1}]` of the domain with `t_j < t_{j+1}`: one
    /// Bézier segment each.
    pub(crate) fn span_indices(&self) -> Vec<usize> {
        (self.degree..self.homogeneous.len()).filter(|&j| self.knots[j] < self.knots[j + 1]).collect()
    }

    /// Boehm's insertion of the knot `u` (strictly inside the domain, or at an end that is not
    /// yet clamped): the same curve with one more control point.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for `u` outside the domain or when `u` already has
    /// multiplicity `n` (an interior knot) and would gain nothing.
    pub(crate) fn insert_knot_once(&self, u: &BigRational) -> Result<Self> {
        let (a, b) = self.domain();
        if *u < a || *u > b {
            return Err(bad(format!("knot {u} is outside the domain [{a}, {b}]")));
        }
        if multiplicity(&self.knots[1..], u) >= self.degree {
            return Err(bad(format!("knot {u} already has multiplicity {}", self.degree)));
        }
        let (knots, homogeneous) = insert(&self.knots, &self.homogeneous, self.degree, u);
        Ok(RationalSpline { degree: self.degree, homogeneous, knots })
    }

    /// Removes one copy of the interior knot `u` **exactly**: `Some` spline when the curve stays
    /// the same (the removal is then unique), `None` when removing `u` would change the curve.
    ///
    /// Inserting `u` into the smaller spline is a linear map `A` of full column rank with
    /// `A·P' = P` to solve; the unique candidate comes from the first equations (forward
    /// substitution) and is accepted only if every equation holds exactly.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] when `u` is not a knot strictly inside the domain.
    pub(crate) fn remove_knot_once(&self, u: &BigRational) -> Result<Option<Self>> {
        let (a, b) = self.domain();
        let n = self.degree;
        if *u <= a || *u >= b || !self.knots.contains(u) {
            return Err(bad(format!("{u} is not a knot strictly inside the domain [{a}, {b}]")));
        }
        let r = self.knots.iter().position(|k| k == u).expect("contains");
        let mut smaller = self.knots.clone();
        smaller.remove(r);
        // In the smaller vector, u is inserted after index k (the last knot ≤ u).
        let k = smaller.iter().rposition(|x| x <= u).expect("domain start is ≤ u");
        let q = &self.homogeneous;
        let m = q.len() - 2; // the smaller spline has m + 1 points
        let mut p: Vec<Point<BigRational>> = Vec::with_capacity(m + 1);
        p.extend_from_slice(&q[..=k - n]);
        // Q_i = (1 − α_i) P_{i−1} + α_i P_i for k − n < i ≤ k; α_i = (u − t_i)/(t_{i+n} − t_i)
        for i in k - n + 1..=k {
            let alpha = (u.clone() - &smaller[i]) / (smaller[i + n].clone() - &smaller[i]);
            if alpha.is_zero() {
                // Q_i = P_{i−1}: the remaining points come from the right
                break;
            }
            let prev = p[i - 1].clone();
            p.push(q[i].sub(&prev.scale(&(rat(1) - &alpha))).scale(&(rat(1) / alpha)));
        }
        // the points after the affected range, from the right: Q_{i+1} = P_i for i ≥ k
        let have = p.len();
        for i in have..=m {
            p.push(q[i + 1].clone());
        }
        if p.len() != m + 1 {
            return Ok(None);
        }
        let (_, back) = insert(&smaller, &p, n, u);
        if back != *q || p.iter().any(|x| x.coords.iter().all(Scalar::is_zero)) {
            return Ok(None);
        }
        Ok(Some(RationalSpline { degree: n, homogeneous: p, knots: smaller }))
    }

    /// The Bézier pieces of the spline, one per non-empty knot span of the domain, by Boehm
    /// insertion of every distinct domain knot (the ends included) up to multiplicity `n`.
    /// Exact and homogeneous: the pieces are the spline, not an approximation.
    ///
    /// # Errors
    /// None for a valid spline; the `Result` guards the homogeneous points' validity.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, spline::RationalSpline};
    /// // a clamped quadratic with an interior knot 1: two Bézier pieces
    /// let p: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
    /// let sp = RationalSpline::from_knots(2, p, &[0, 0, 0, 1, 2, 2, 2].map(rat)).unwrap();
    /// let pieces = sp.bezier_pieces().unwrap();
    /// assert_eq!(pieces.len(), 2);
    /// assert_eq!(pieces[0].homogeneous[2], pieces[1].homogeneous[0]); // C^0 at least: they share a point
    /// ```
    pub fn bezier_pieces(&self) -> Result<Vec<BezierPiece>> {
        // Each piece depends only on its span's n + 1 control points and 2n + 1 knots: insert
        // the span's ends into that window (linear in the spline's size, where inserting into
        // the whole spline copied it for every insertion).
        let n = self.degree;
        let end = self.domain().1;
        let spans = self.span_indices();
        Ok(spans
            .iter()
            .enumerate()
            .map(|(s, &j)| {
                let (a, b) =
                    (self.knots[j].clone(), spans.get(s + 1).map_or(end.clone(), |&next| self.knots[next].clone()));
                let mut u: Vec<BigRational> = self.knots[j - n..].iter().take(2 * n + 1).cloned().collect();
                if u.len() < 2 * n + 1 {
                    // the last knot t_{m+n+1} is not kept: it never influences the curve
                    u.push(u.last().expect("knots").clone());
                }
                let mut p: Vec<Point<BigRational>> = self.homogeneous[j - n..=j].to_vec();
                for knot in [&a, &b] {
                    while multiplicity(&u[1..], knot) < n {
                        (u, p) = insert(&u, &p, n, knot);
                    }
                }
                let k = u.iter().rposition(|x| *x == a).expect("a is a knot");
                BezierPiece { span: (a, b), homogeneous: p[k - n..=k].to_vec() }
            })
            .collect())
    }

    /// [`Self::bezier_pieces`] as rational Bézier curves, each on `[0, 1]`.
    ///
    /// # Errors
    /// As [`Self::bezier_pieces`].
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, spline::RationalSpline};
    /// // a clamped quadratic with an interior knot 1: two Bézier pieces
    /// let p: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
    /// let sp = RationalSpline::from_knots(2, p, &[0, 0, 0, 1, 2, 2, 2].map(rat)).unwrap();
    /// let segs = sp.bezier_segments().unwrap();
    /// assert_eq!(segs[0].eval(&rat(1)).unwrap(), segs[1].eval(&rat(0)).unwrap());
    /// ```
    pub fn bezier_segments(&self) -> Result<Vec<RationalBezier<BigRational>>> {
        self.bezier_pieces()?.iter().map(BezierPiece::curve).collect()
    }

    /// The joins between consecutive `segments` (as returned by [`Self::bezier_segments`] or
    /// any route giving the same pieces): each interior break's multiplicity `μ`, continuity
    /// `n − μ`, and whether the homogeneous derivatives up to that order agree exactly with
    /// respect to the global parameter (`d^r/du^r = (b − a)^{−r} d^r/ds^r` on `[a, b]`).
    /// Where the homogeneous forms differ by a factor (another route's normalisation), the
    /// affine derivatives are compared instead.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, spline::RationalSpline};
    /// // a clamped quadratic with an interior knot 1: two Bézier pieces
    /// let p: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
    /// let sp = RationalSpline::from_knots(2, p, &[0, 0, 0, 1, 2, 2, 2].map(rat)).unwrap();
    /// let j = sp.joins(&sp.bezier_segments().unwrap());
    /// assert_eq!(j.len(), 1);
    /// assert!(j[0].proved && j[0].continuity == 1); // a simple knot of a quadratic: C^1
    /// ```
    pub fn joins(&self, segments: &[RationalBezier<BigRational>]) -> Vec<Join> {
        let n = self.degree;
        let indices = self.span_indices();
        let spans: Vec<(BigRational, BigRational)> =
            indices.iter().map(|&j| (self.knots[j].clone(), self.knots[j + 1].clone())).collect();
        (0..segments.len().saturating_sub(1).min(spans.len().saturating_sub(1)))
            .map(|s| {
                let knot = spans[s].1.clone();
                // the knots do not decrease: the copies of t_{j+1} in t_1 … are its neighbours
                let at = indices[s] + 1;
                let left = self.knots[1..at].iter().rev().take_while(|k| **k == knot).count();
                let right = self.knots[at..].iter().take_while(|k| **k == knot).count();
                let mu = (left + right).min(n + 1);
                let order = n as i64 - mu as i64;
                let (la, lb) = (spans[s].1.clone() - &spans[s].0, spans[s + 1].1.clone() - &spans[s + 1].0);
                let proved = order < 0 || joins_with_order(&segments[s], &segments[s + 1], &la, &lb, order as usize);
                Join { knot, multiplicity: mu, continuity: order, proved }
            })
            .collect()
    }

    /// The same curve one degree higher (clamped at the domain ends), with every interior knot's
    /// multiplicity raised by one: decompose into Bézier pieces, elevate each, and remove knots
    /// exactly back to multiplicity `μ + 1`.
    ///
    /// # Errors
    /// [`Error::TooLarge`] beyond 12 (`MAX_SPLINE_DEGREE`).
    ///
    /// # Example
    /// ```
    /// use casteljau::{Point, rat, ratio, spline::RationalSpline};
    /// let p: Vec<Point<_>> = [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
    /// let sp = RationalSpline::from_knots(2, p, &[0, 0, 0, 1, 2, 2, 2].map(rat)).unwrap();
    /// let up = sp.elevate_degree().unwrap();
    /// assert_eq!(up.degree, 3);
    /// assert_eq!(up.knot_vector(), &[0, 0, 0, 0, 1, 1, 2, 2, 2].map(rat)); // and the last knot 2
    /// assert_eq!(up.eval_at(&ratio(1, 3)).unwrap(), sp.eval_at(&ratio(1, 3)).unwrap());
    /// ```
    pub fn elevate_degree(&self) -> Result<Self> {
        let n = self.degree;
        let p = n + 1;
        if p > MAX_SPLINE_DEGREE {
            return Err(Error::TooLarge { what: "spline degree", value: p, limit: MAX_SPLINE_DEGREE });
        }
        let pieces = self.bezier_pieces()?;
        let (a, b) = self.domain();
        let mut knots = vec![a.clone(); p + 1];
        let mut points: Vec<Point<BigRational>> = Vec::new();
        let mut targets = Vec::new();
        let mut joined = false; // the previous join is continuous: the pieces share a point
        for (s, piece) in pieces.iter().enumerate() {
            let h = elevate_homogeneous(&piece.homogeneous);
            points.extend(if joined { h[1..].to_vec() } else { h });
            if s + 1 < pieces.len() {
                let w = piece.span.1.clone();
                let mu = multiplicity(&self.knots[1..], &w).min(n + 1);
                joined = mu <= n;
                let copies = if joined { p } else { p + 1 };
                knots.extend(std::iter::repeat_n(w.clone(), copies));
                targets.push((w, copies, mu + 1));
            }
        }
        knots.extend(std::iter::repeat_n(b, p + 1));
        let mut out = RationalSpline::from_knots(p, points, &knots)?;
        for (w, copies, target) in targets {
            for _ in target..copies {
                out = out.remove_knot_once(&w)?.ok_or_else(|| {
                    bad(format!("degree elevation: knot {w} could not be removed exactly (internal error)"))
                })?;
            }
        }
        Ok(out)
    }
}

/// Degree elevation of homogeneous Bézier points: `Q_i = (i/(n+1)) P_{i−1} + (1 − i/(n+1)) P_i`.
fn elevate_homogeneous(p: &[Point<BigRational>]) -> Vec<Point<BigRational>> {
    let n = p.len() - 1;
    let d = BigRational::from_integer((n as i64 + 1).into());
    let mut q = vec![p[0].clone()];
    for i in 1..=n {
        let a = BigRational::from_integer((i as i64).into()) / &d;
        q.push(p[i].lerp(&p[i - 1], &a));
    }
    q.push(p[n].clone());
    q
}

/// Homogeneous derivatives of orders `0..=order` agree at the join, scaled to the global
/// parameter; failing that, affine derivatives (other homogeneous normalisations).
pub(crate) fn joins_with_order(
    left: &RationalBezier<BigRational>,
    right: &RationalBezier<BigRational>,
    la: &BigRational,
    lb: &BigRational,
    order: usize,
) -> bool {
    let derivs = |c: &RationalBezier<BigRational>, t: &BigRational| {
        let mut out = Vec::new();
        let mut h = c.homogeneous().clone();
        for _ in 0..=order {
            // at an end the curve is its end control point (no de Casteljau run of n² products)
            out.push(if t.is_zero() {
                h.points()[0].clone()
            } else if *t == rat(1) {
                h.points()[h.points().len() - 1].clone()
            } else {
                h.eval(t)
            });
            if h.degree() == 0 {
                h = crate::curve::bezier::BezierCurve::new(vec![Point::origin(h.dim())]).expect("one point");
            } else {
                h = h.derivative(1);
            }
        }
        out
    };
    let (l, r) = (derivs(left, &rat(1)), derivs(right, &rat(0)));
    let scale = |x: &Point<BigRational>, len: &BigRational, k: usize| x.scale(&crate::poly::bernstein::pow(len, k));
    let homogeneous = (0..=order).all(|k| scale(&l[k], lb, k) == scale(&r[k], la, k));
    if homogeneous {
        return true;
    }
    match (left.derivatives_at(&rat(1), order), right.derivatives_at(&rat(0), order)) {
        (Ok(l), Ok(r)) => (0..=order).all(|k| scale(&l[k], lb, k) == scale(&r[k], la, k)),
        _ => false,
    }
}

/// Boehm's insertion of `u` into `(knots, points)` (internal knot vector `t_0 … t_{m+n}`).
fn insert(
    knots: &[BigRational],
    points: &[Point<BigRational>],
    n: usize,
    u: &BigRational,
) -> (Vec<BigRational>, Vec<Point<BigRational>>) {
    let pm = points.len() - 1;
    // k in [n, pm] with t_k ≤ u, the largest such
    let k = (n..=pm).rev().find(|&k| knots[k] <= *u).unwrap_or(n);
    let mut q = Vec::with_capacity(points.len() + 1);
    q.extend_from_slice(&points[..=k - n]);
    for i in k - n + 1..=k {
        let den = knots[i + n].clone() - &knots[i];
        let a = if den.sign() == Ordering::Greater { (u.clone() - &knots[i]) / den } else { rat(1) };
        q.push(points[i - 1].lerp(&points[i], &a));
    }
    q.extend_from_slice(&points[k..]);
    let mut t = knots.to_vec();
    t.insert(k + 1, u.clone());
    (t, q)
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    #[test]
    fn max_spline_points_example() {
        use crate::{
            Point, rat,
            spline::{RationalSpline, knots::MAX_SPLINE_POINTS},
        };
        let n = MAX_SPLINE_POINTS + 1;
        let p = vec![Point::new(vec![rat(0), rat(0), rat(1)]); n];
        let knots: Vec<_> = (0..n + 2).map(|k| rat(k as i64)).collect();
        assert!(RationalSpline::from_knots(1, p, &knots).is_err());
    }

    #[test]
    fn insert_knot_once_example() {
        use crate::{Point, rat, ratio, spline::RationalSpline};
        let p: Vec<Point<_>> =
            [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
        let sp = RationalSpline::from_knots(2, p, &[0, 0, 0, 1, 2, 2, 2].map(rat)).unwrap();
        let more = sp.insert_knot_once(&ratio(1, 2)).unwrap();
        assert_eq!(more.homogeneous.len(), 5);
        assert_eq!(more.eval_at(&ratio(3, 2)).unwrap(), sp.eval_at(&ratio(3, 2)).unwrap());
        assert_eq!(more.remove_knot_once(&ratio(1, 2)).unwrap(), Some(sp));
    }

    #[test]
    fn remove_knot_once_example() {
        use crate::{Point, rat, ratio, spline::RationalSpline};
        // a clamped quadratic with an interior knot 1: two Bézier pieces
        let p: Vec<Point<_>> =
            [(0, 0), (1, 2), (3, 2), (4, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
        let sp = RationalSpline::from_knots(2, p, &[0, 0, 0, 1, 2, 2, 2].map(rat)).unwrap();
        // this spline is one parabola: its knot 1 comes out, and the curve is unchanged
        let one = sp.remove_knot_once(&rat(1)).unwrap().unwrap();
        assert_eq!(one.homogeneous.len(), 3);
        assert_eq!(one.eval_at(&ratio(1, 2)).unwrap(), sp.eval_at(&ratio(1, 2)).unwrap());
        assert!(sp.remove_knot_once(&ratio(1, 2)).is_err()); // not a knot
    }
}
