//! Exact winding numbers of closed paths of Bézier segments (polynomial and rational, mixed
//! degrees) around a point, or the exact place where the point lies on the path.
//!
//! The ray from `q` to the right is followed along the whole path: on each segment the roots of
//! `Y(t) − q_y W(t)` on `[0, 1]` cut it into pieces of constant sign; a root whose point lies
//! right of `q` (compared exactly, as real algebraic numbers) counts `+1` when the sign goes
//! from negative to positive across it and `−1` the other way — a touch without crossing counts
//! nothing, a root shared by two segments (a joint) is one event, and a piece lying on the ray
//! counts by the signs before and after it. A root whose point is `q` itself means `q` is on
//! the path. No ray is perturbed and nothing is sampled, so a leading coefficient that vanishes,
//! a tangent ray or a joint on the ray change nothing.
//!
//! # Example
//! ```
//! use casteljau::intersect::{winding_number, Winding};
//! use casteljau::{BezierCurve, num::parse_points, rat, ratio, Point};
//! let seg = |s: &str| BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap();
//! // the lens between the parabola 0 0, 1 2, 2 0 and the chord back
//! let path = vec![seg("0 0, 1 2, 2 0"), seg("2 0, 0 0")];
//! let p = |x, y| Point::new(vec![x, y]);
//! assert_eq!(winding_number(&path, &p(rat(1), ratio(1, 2))).unwrap(), Winding::Inside(-1)); // clockwise
//! assert_eq!(winding_number(&path, &p(rat(1), rat(2))).unwrap(), Winding::Inside(0));
//! assert!(matches!(winding_number(&path, &p(rat(1), rat(1))).unwrap(), Winding::OnBoundary { segment: 0, .. }));
//! ```

use crate::curve::bezier::BezierCurve;
use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::rat;
use crate::poly::Poly;
use crate::poly::algebraic::RealAlgebraic;
use crate::rational::RationalBezier;
use num_rational::BigRational;
use serde::Serialize;
use std::cmp::Ordering;

/// Most segments in one path.
pub const MAX_PATH_SEGMENTS: usize = 100_000;

/// Where the point is relative to the path.
#[derive(Clone, Debug, PartialEq)]
pub enum Winding {
    /// Not on the path: the winding number (counter-clockwise positive; non-zero means inside
    /// by the non-zero rule, odd by the even-odd rule).
    Inside(i64),
    /// On the path: the first segment (0-based) and a parameter where it passes through the
    /// point.
    OnBoundary {
        /// The segment.
        segment: usize,
        /// The parameter on it.
        t: RealAlgebraic,
    },
}

/// What the ray meets along a cycle, in order.
pub(crate) enum Event {
    /// The sign of `y − q_y` on a piece of positive length.
    Sign(Ordering),
    /// A point on the ray's line: is it right of `q`?
    Zero(bool),
}

/// [`winding_number_rational`] within a work budget ([`crate::work::winding_segment`] summed over
/// the segments), checked before any work starts.
///
/// # Errors
/// As [`winding_number_rational`]; [`Error::WorkLimit`] when the estimate exceeds `budget`.
pub fn winding_number_within(
    path: &[RationalBezier<BigRational>],
    q: &Point<BigRational>,
    budget: &crate::work::Budget,
) -> Result<Winding> {
    if path.len() > MAX_PATH_SEGMENTS {
        return Err(Error::TooLarge { what: "segments in a path", value: path.len(), limit: MAX_PATH_SEGMENTS });
    }
    budget.check(format!("the winding number of a path of {} segments", path.len()), winding_estimate(path, q))?;
    winding_number_rational(path, q)
}

/// The estimated work of [`winding_number_rational`]: [`crate::work::winding_segment`] summed
/// over the segments (the query point's bits counted in each).
pub fn winding_estimate(path: &[RationalBezier<BigRational>], q: &Point<BigRational>) -> f64 {
    let qb = q.coords.iter().map(crate::work::bits).sum::<u64>();
    path.iter()
        .map(|s| crate::work::winding_segment(s.degree(), crate::work::max_bits(s.homogeneous().points()) + qb))
        .sum()
}

/// [`winding_number_rational`] of polynomial segments.
///
/// # Errors
/// As [`winding_number_rational`].
pub fn winding_number(path: &[BezierCurve<BigRational>], q: &Point<BigRational>) -> Result<Winding> {
    let segs = path
        .iter()
        .map(|c| RationalBezier::new(c.points().to_vec(), vec![rat(1); c.points().len()]))
        .collect::<Result<Vec<_>>>()?;
    winding_number_rational(&segs, q)
}

/// `Ok` when every segment starts where the previous one ends and the last ends where the
/// first starts.
fn check_closed(path: &[RationalBezier<BigRational>]) -> Result<()> {
    let end = |s: &RationalBezier<BigRational>, t: i64| s.eval(&rat(t));
    // the ends are the first and last homogeneous control points: equal points have
    // proportional coordinates (compared without a division when both weights are 1)
    let same = |a: &Point<BigRational>, b: &Point<BigRational>| -> Option<bool> {
        let one = rat(1);
        (a.coords[2] == one && b.coords[2] == one).then(|| a.coords[0] == b.coords[0] && a.coords[1] == b.coords[1])
    };
    for i in 0..path.len() {
        let j = (i + 1) % path.len();
        let (a, b) = (path[i].homogeneous().points(), path[j].homogeneous().points());
        let equal = match same(&a[a.len() - 1], &b[0]) {
            Some(e) => e,
            None => end(&path[i], 1)? == end(&path[j], 0)?,
        };
        if !equal {
            return Err(Error::InvalidArgument {
                message: format!("the path is not closed: segment {i} ends where segment {j} does not start"),
            });
        }
    }
    Ok(())
}

/// The winding number of a closed path around `q`, or where `q` lies on it.
///
/// # Errors
/// [`Error::InvalidArgument`] when the path is empty, not planar, or not closed (a segment does
/// not start where the previous one ends, or the last does not end at the first's start);
/// [`Error::WeightsVanish`] for a rational segment undefined on `[0, 1]`; [`Error::TooLarge`]
/// beyond [`MAX_PATH_SEGMENTS`].
pub fn winding_number_rational(path: &[RationalBezier<BigRational>], q: &Point<BigRational>) -> Result<Winding> {
    let bad = |m: String| Error::InvalidArgument { message: m };
    if path.is_empty() {
        return Err(bad("an empty path".into()));
    }
    if path.len() > MAX_PATH_SEGMENTS {
        return Err(Error::TooLarge { what: "segments in a path", value: path.len(), limit: MAX_PATH_SEGMENTS });
    }
    if q.dim() != 2 || path.iter().any(|s| s.dim() != 2) {
        return Err(bad("winding numbers are for planar paths and points".into()));
    }
    for s in path {
        s.check_defined(&rat(0), &rat(1))?;
    }
    check_closed(path)?;
    let (qx, qy) = (&q.coords[0], &q.coords[1]);
    let mut events: Vec<Event> = vec![];
    for (i, s) in path.iter().enumerate() {
        let [x, y, w]: [Poly<BigRational>; 3] =
            s.homogeneous().coordinate_polynomials().try_into().expect("planar: X, Y, W");
        let (fx, fy) = (&x - &w.scale(qx), &y - &w.scale(qy));
        if fy.is_zero() {
            // the whole segment lies on the ray's line
            if !fx.is_zero() {
                if let Some(t) = RealAlgebraic::roots_in(&fx, &rat(0), &rat(1)).into_iter().next() {
                    return Ok(Winding::OnBoundary { segment: i, t });
                }
            } else {
                return Ok(Winding::OnBoundary { segment: i, t: RealAlgebraic::from(rat(0)) });
            }
            let right = RealAlgebraic::from(rat(0)).sign_of(&fx) == Ordering::Greater;
            events.push(Event::Zero(right));
            continue;
        }
        let roots = RealAlgebraic::roots_in(&fy, &rat(0), &rat(1));
        let mut breaks: Vec<RealAlgebraic> = vec![RealAlgebraic::from(rat(0))];
        for r in &roots {
            if *r != breaks[breaks.len() - 1] {
                breaks.push(r.clone());
            }
        }
        let one = RealAlgebraic::from(rat(1));
        if breaks[breaks.len() - 1] != one {
            breaks.push(one);
        }
        let is_root = |t: &RealAlgebraic| roots.iter().any(|r| r == t);
        for (k, t) in breaks.iter().enumerate() {
            if is_root(t) {
                let side = t.sign_of(&fx);
                if side == Ordering::Equal {
                    return Ok(Winding::OnBoundary { segment: i, t: t.clone() });
                }
                events.push(Event::Zero(side == Ordering::Greater));
            }
            if let Some(next) = breaks.get(k + 1) {
                let mid = RealAlgebraic::rational_between(t, next);
                let sign = RealAlgebraic::from(mid).sign_of(&fy);
                events.push(Event::Sign(sign));
            }
        }
    }
    Ok(Winding::Inside(count_crossings(&events)))
}

/// The crossings beyond the origin along one closed cycle of events: each run of zeros between
/// two signs is one event, counted `+1` when the sign goes from negative to positive across it
/// and `−1` the other way, when a zero of the run lies beyond the origin (0 without any sign:
/// the whole cycle on the ray's line).
pub(crate) fn count_crossings(events: &[Event]) -> i64 {
    let Some(start) = events.iter().position(|e| matches!(e, Event::Sign(_))) else {
        return 0;
    };
    let n = events.len();
    let mut winding = 0i64;
    let Event::Sign(mut prev) = events[start] else { return 0 };
    let (mut right, mut in_zero) = (false, false);
    for k in 1..=n {
        match &events[(start + k) % n] {
            Event::Zero(r) => {
                in_zero = true;
                right |= *r;
            }
            Event::Sign(s) => {
                if in_zero && right && *s != prev {
                    winding += if *s == Ordering::Greater { 1 } else { -1 };
                }
                in_zero = false;
                right = false;
                prev = *s;
            }
        }
    }
    winding
}

/// How a winding number decides what is inside a path: the `fill-rule` of SVG and CSS (and the
/// two fill operators of PostScript and PDF). Written `nonzero` or `evenodd` as SVG spells them
/// (also `non-zero`, `even-odd`); serialized the SVG way.
///
/// # Example
/// ```
/// use casteljau::intersect::FillRule;
/// let rule: FillRule = "evenodd".parse().unwrap();
/// assert_eq!(rule, FillRule::EvenOdd);
/// assert!(FillRule::NonZero.contains(2) && !FillRule::EvenOdd.contains(2));
/// assert!(FillRule::EvenOdd.contains(-1));
/// assert_eq!(serde_json::to_string(&FillRule::NonZero).unwrap(), r#""nonzero""#);
/// assert!("odd".parse::<FillRule>().is_err());
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum FillRule {
    /// Inside where the winding number is not 0 (SVG's default).
    #[default]
    NonZero,
    /// Inside where the winding number is odd.
    EvenOdd,
}

impl FillRule {
    /// Whether a point of winding number `winding` is inside under this rule.
    ///
    /// # Example
    /// ```
    /// use casteljau::intersect::FillRule;
    /// assert_eq!([0, 1, 2, -3].map(|w| FillRule::EvenOdd.contains(w)), [false, true, false, true]);
    /// ```
    pub fn contains(self, winding: i64) -> bool {
        match self {
            FillRule::NonZero => winding != 0,
            FillRule::EvenOdd => winding % 2 != 0,
        }
    }
}

impl std::fmt::Display for FillRule {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            FillRule::NonZero => "nonzero",
            FillRule::EvenOdd => "evenodd",
        })
    }
}

impl std::str::FromStr for FillRule {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "nonzero" | "non-zero" => Ok(FillRule::NonZero),
            "evenodd" | "even-odd" => Ok(FillRule::EvenOdd),
            other => {
                Err(Error::InvalidArgument { message: format!("the fill rule is nonzero or evenodd, not {other:?}") })
            }
        }
    }
}

/// A path of closed contours, each a chain of planar (rational) Bézier segments that ends
/// where it starts: what a fill rule fills. Open outlines become closed ones by
/// [`crate::format::close_for_fill`] (a closing line, as SVG fills them).
///
/// # Example
/// ```
/// use casteljau::intersect::{ClosedPath, PathWinding};
/// use casteljau::{BezierCurve, Point, num::parse_points, rat};
/// let seg = |s: &str| BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap();
/// let square = |a: i64, b: i64| {
///     let p = |x: i64, y: i64| format!("{x} {y}");
///     vec![seg(&format!("{}, {}", p(a, a), p(b, a))), seg(&format!("{}, {}", p(b, a), p(b, b))),
///          seg(&format!("{}, {}", p(b, b), p(a, b))), seg(&format!("{}, {}", p(a, b), p(a, a)))]
/// };
/// let path = ClosedPath::from_polynomial(vec![square(0, 3), square(1, 2)]).unwrap();
/// assert_eq!(path.segments(), 8);
/// let w = path.winding(&Point::new(vec![rat(3) / rat(2), rat(3) / rat(2)])).unwrap();
/// assert!(matches!(w, PathWinding::Off(n) if n.winding() == 2));
/// assert!(ClosedPath::from_polynomial(vec![vec![seg("0 0, 1 1")]]).is_err()); // not closed
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ClosedPath {
    contours: Vec<Vec<RationalBezier<BigRational>>>,
}

impl ClosedPath {
    /// A path from closed contours.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for an empty contour, a segment that is not planar, or a
    /// contour that is not closed (naming the segments); [`Error::WeightsVanish`] for a
    /// segment undefined at an end; [`Error::TooLarge`] for a contour beyond
    /// [`MAX_PATH_SEGMENTS`].
    ///
    /// # Example
    /// ```
    /// use casteljau::intersect::ClosedPath;
    /// use casteljau::{Point, RationalBezier, rat};
    /// let p = |x: i64, y: i64| Point::new(vec![rat(x), rat(y)]);
    /// // a quarter circle and the two radii closing it
    /// let arc = RationalBezier::new(vec![p(1, 0), p(1, 1), p(0, 1)], vec![rat(1), rat(1), rat(2)]).unwrap();
    /// let line = |a, b| RationalBezier::new(vec![a, b], vec![rat(1), rat(1)]).unwrap();
    /// let path = ClosedPath::new(vec![vec![arc, line(p(0, 1), p(0, 0)), line(p(0, 0), p(1, 0))]]).unwrap();
    /// assert_eq!(path.contours().len(), 1);
    /// ```
    pub fn new(contours: Vec<Vec<RationalBezier<BigRational>>>) -> Result<Self> {
        for c in &contours {
            if c.is_empty() {
                return Err(Error::InvalidArgument { message: "an empty path".into() });
            }
            if c.len() > MAX_PATH_SEGMENTS {
                return Err(Error::TooLarge { what: "segments in a path", value: c.len(), limit: MAX_PATH_SEGMENTS });
            }
            if c.iter().any(|s| s.dim() != 2) {
                return Err(Error::InvalidArgument {
                    message: "winding numbers are for planar paths and points".into(),
                });
            }
            check_closed(c)?;
        }
        Ok(ClosedPath { contours })
    }

    /// [`Self::new`] from polynomial segments.
    ///
    /// # Errors
    /// As [`Self::new`].
    ///
    /// # Example
    /// ```
    /// use casteljau::intersect::ClosedPath;
    /// use casteljau::{BezierCurve, num::parse_points};
    /// let seg = |s: &str| BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap();
    /// assert!(ClosedPath::from_polynomial(vec![vec![seg("0 0, 1 2, 2 0"), seg("2 0, 0 0")]]).is_ok());
    /// ```
    pub fn from_polynomial(contours: Vec<Vec<BezierCurve<BigRational>>>) -> Result<Self> {
        let unit = |c: BezierCurve<BigRational>| {
            let n = c.points().len();
            RationalBezier::new(c.points().to_vec(), vec![rat(1); n])
        };
        Self::new(
            contours.into_iter().map(|c| c.into_iter().map(unit).collect::<Result<Vec<_>>>()).collect::<Result<_>>()?,
        )
    }

    /// The contours.
    ///
    /// # Example
    /// ```
    /// use casteljau::intersect::ClosedPath;
    /// assert!(ClosedPath::new(vec![]).unwrap().contours().is_empty());
    /// ```
    pub fn contours(&self) -> &[Vec<RationalBezier<BigRational>>] {
        &self.contours
    }

    /// The number of segments over all contours.
    ///
    /// # Example
    /// ```
    /// use casteljau::intersect::ClosedPath;
    /// assert_eq!(ClosedPath::new(vec![]).unwrap().segments(), 0);
    /// ```
    pub fn segments(&self) -> usize {
        self.contours.iter().map(Vec::len).sum()
    }

    /// The estimated work of [`Self::winding`]: [`winding_estimate`] summed over the contours.
    ///
    /// # Example
    /// ```
    /// use casteljau::intersect::ClosedPath;
    /// use casteljau::{BezierCurve, Point, num::parse_points, rat};
    /// let seg = |s: &str| BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap();
    /// let path = ClosedPath::from_polynomial(vec![vec![seg("0 0, 1 2, 2 0"), seg("2 0, 0 0")]]).unwrap();
    /// assert!(path.winding_estimate(&Point::new(vec![rat(1), rat(1)])) > 0.0);
    /// ```
    pub fn winding_estimate(&self, q: &Point<BigRational>) -> f64 {
        self.contours.iter().map(|c| winding_estimate(c, q)).sum()
    }

    /// The winding number of the path around `q` (the sum over its contours), or the first
    /// place where `q` lies on the path, within a work budget ([`Self::winding_estimate`]),
    /// checked before any work starts.
    ///
    /// # Errors
    /// As [`winding_number_rational`]; [`Error::WorkLimit`] when the estimate exceeds `budget`.
    ///
    /// # Example
    /// ```
    /// use casteljau::intersect::{ClosedPath, PathWinding};
    /// use casteljau::{BezierCurve, Point, num::parse_points, rat, work::Budget};
    /// let seg = |s: &str| BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap();
    /// let path = ClosedPath::from_polynomial(vec![vec![seg("0 0, 1 2, 2 0"), seg("2 0, 0 0")]]).unwrap();
    /// let on = path.winding_within(&Point::new(vec![rat(1), rat(0)]), &Budget::unlimited()).unwrap();
    /// assert!(matches!(on, PathWinding::OnBoundary { on_boundary } if on_boundary.segment == 1));
    /// assert!(path.winding_within(&Point::new(vec![rat(1), rat(0)]), &Budget::new(10.0, "--max-work")).is_err());
    /// ```
    pub fn winding_within(&self, q: &Point<BigRational>, budget: &crate::work::Budget) -> Result<PathWinding> {
        budget
            .check(format!("the winding number of a path of {} segments", self.segments()), self.winding_estimate(q))?;
        let mut total = 0i64;
        for (subpath, c) in self.contours.iter().enumerate() {
            match winding_number_rational(c, q)? {
                Winding::Inside(w) => total += w,
                Winding::OnBoundary { segment, t } => {
                    let t_float = t.to_f64();
                    return Ok(PathWinding::OnBoundary { on_boundary: BoundaryPoint { segment, subpath, t, t_float } });
                }
            }
        }
        Ok(PathWinding::Off(WindingNumber::new(total)))
    }

    /// [`Self::winding_within`] without a limit.
    ///
    /// # Errors
    /// As [`winding_number_rational`].
    ///
    /// # Example
    /// ```
    /// use casteljau::intersect::{ClosedPath, PathWinding};
    /// use casteljau::{BezierCurve, Point, num::parse_points, rat, ratio};
    /// let seg = |s: &str| BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap();
    /// let path = ClosedPath::from_polynomial(vec![vec![seg("0 0, 1 2, 2 0"), seg("2 0, 0 0")]]).unwrap();
    /// let w = path.winding(&Point::new(vec![rat(1), ratio(1, 2)])).unwrap();
    /// assert_eq!(serde_json::to_string(&w).unwrap(), r#"{"even_odd":true,"inside":true,"winding":-1}"#);
    /// ```
    pub fn winding(&self, q: &Point<BigRational>) -> Result<PathWinding> {
        self.winding_within(q, &crate::work::Budget::unlimited())
    }
}

/// Where a point lies relative to a [`ClosedPath`]: off it with a winding number, or on it.
/// Serialized as the fields of the variant (`even_odd`, `inside`, `winding`, or
/// `on_boundary`).
///
/// # Example
/// ```
/// use casteljau::intersect::{ClosedPath, PathWinding};
/// use casteljau::{BezierCurve, Point, num::parse_points, rat};
/// let seg = |s: &str| BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap();
/// let path = ClosedPath::from_polynomial(vec![vec![seg("0 0, 1 2, 2 0"), seg("2 0, 0 0")]]).unwrap();
/// let on = path.winding(&Point::new(vec![rat(1), rat(1)])).unwrap();
/// assert_eq!(serde_json::to_string(&on).unwrap(), r#"{"on_boundary":{"segment":0,"subpath":0,"t":"1/2","t_float":0.5}}"#);
/// ```
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum PathWinding {
    /// Not on the path.
    Off(WindingNumber),
    /// On the path.
    OnBoundary {
        /// The first place found.
        on_boundary: BoundaryPoint,
    },
}

/// A winding number and what each fill rule makes of it.
///
/// # Example
/// ```
/// use casteljau::intersect::{FillRule, WindingNumber};
/// let w = WindingNumber::new(-2);
/// assert!(w.inside(FillRule::NonZero) && !w.inside(FillRule::EvenOdd));
/// assert_eq!(serde_json::to_string(&w).unwrap(), r#"{"even_odd":false,"inside":true,"winding":-2}"#);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct WindingNumber {
    /// Inside by the even-odd rule.
    even_odd: bool,
    /// Inside by the non-zero rule.
    inside: bool,
    /// The winding number (counter-clockwise positive).
    winding: i64,
}

impl WindingNumber {
    /// The winding number `winding` with its fill-rule answers.
    ///
    /// # Example
    /// ```
    /// use casteljau::intersect::WindingNumber;
    /// assert_eq!(WindingNumber::new(3).winding(), 3);
    /// ```
    pub fn new(winding: i64) -> Self {
        WindingNumber {
            even_odd: FillRule::EvenOdd.contains(winding),
            inside: FillRule::NonZero.contains(winding),
            winding,
        }
    }

    /// The winding number (counter-clockwise positive).
    ///
    /// # Example
    /// ```
    /// use casteljau::intersect::WindingNumber;
    /// assert_eq!(WindingNumber::new(-1).winding(), -1);
    /// ```
    pub fn winding(&self) -> i64 {
        self.winding
    }

    /// Inside under `rule`.
    ///
    /// # Example
    /// ```
    /// use casteljau::intersect::{FillRule, WindingNumber};
    /// assert!(!WindingNumber::new(0).inside(FillRule::NonZero));
    /// ```
    pub fn inside(&self, rule: FillRule) -> bool {
        match rule {
            FillRule::NonZero => self.inside,
            FillRule::EvenOdd => self.even_odd,
        }
    }
}

/// Where a point lies on a [`ClosedPath`]: the contour (`subpath`, 0-based), the segment in it
/// and an exact parameter there, with its correctly rounded `f64`.
///
/// # Example
/// ```
/// use casteljau::intersect::{ClosedPath, PathWinding};
/// use casteljau::{BezierCurve, Point, num::parse_points, rat};
/// let seg = |s: &str| BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap();
/// let path = ClosedPath::from_polynomial(vec![vec![seg("0 0, 2 0"), seg("2 0, 0 2"), seg("0 2, 0 0")]]).unwrap();
/// let PathWinding::OnBoundary { on_boundary: b } = path.winding(&Point::new(vec![rat(1), rat(1)])).unwrap() else { panic!() };
/// assert_eq!((b.subpath, b.segment, b.t.to_string(), b.t_float), (0, 1, "1/2".to_string(), 0.5));
/// ```
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct BoundaryPoint {
    /// The segment within its contour.
    pub segment: usize,
    /// The contour.
    pub subpath: usize,
    /// The exact parameter on the segment.
    #[serde(serialize_with = "crate::num::serial::string")]
    pub t: RealAlgebraic,
    /// `t` rounded to the nearest `f64`.
    pub t_float: f64,
}
