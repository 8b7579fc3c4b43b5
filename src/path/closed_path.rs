//! [`ClosedPath`] — closed contours of polynomial and rational Bézier segments, the storage
//! every planar algorithm above works on — its winding numbers, and the fill rules that decide
//! from them what is inside.

use super::MAX_PATH_SEGMENTS;
use super::winding::{Winding, check_closed, winding_estimate, winding_number_rational};
use crate::curve::bezier::BezierCurve;
use crate::error::{Error, Result};
use crate::num::point::Point2;
use crate::num::scalar::rat;
use crate::poly::algebraic::RealAlgebraic;
use crate::rational::RationalBezier;
use crate::work::Budget;
use num_rational::BigRational;
use serde::Serialize;

/// How a winding number decides what is inside a path: the `fill-rule` of SVG and CSS (and the
/// two fill operators of PostScript and PDF). Written `nonzero` or `evenodd` as SVG spells them
/// (also `non-zero`, `even-odd`); serialized the SVG way.
///
/// # Example
/// ```
/// use casteljau::path::FillRule;
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
    /// use casteljau::path::FillRule;
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
/// a closing line as SVG fills it (a closing line, as SVG fills them).
///
/// # Example
/// ```
/// use casteljau::path::{ClosedPath, PathWinding};
/// use casteljau::{BezierCurve, num::{Point2, parse_points}, rat};
/// let seg = |s: &str| BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap();
/// let square = |a: i64, b: i64| {
///     let p = |x: i64, y: i64| format!("{x} {y}");
///     vec![seg(&format!("{}, {}", p(a, a), p(b, a))), seg(&format!("{}, {}", p(b, a), p(b, b))),
///          seg(&format!("{}, {}", p(b, b), p(a, b))), seg(&format!("{}, {}", p(a, b), p(a, a)))]
/// };
/// let path = ClosedPath::from_polynomial(vec![square(0, 3), square(1, 2)]).unwrap();
/// assert_eq!(path.segments(), 8);
/// let w = path.winding(&Point2::new(rat(3) / rat(2), rat(3) / rat(2)), &casteljau::work::Budget::unlimited()).unwrap();
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
    /// 100,000 (`MAX_PATH_SEGMENTS`).
    ///
    /// # Example
    /// ```
    /// use casteljau::path::ClosedPath;
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
                return Err(Error::NotApplicable { message: "winding numbers are for planar paths and points".into() });
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
    /// use casteljau::path::ClosedPath;
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
    /// use casteljau::path::ClosedPath;
    /// assert!(ClosedPath::new(vec![]).unwrap().contours().is_empty());
    /// ```
    pub fn contours(&self) -> &[Vec<RationalBezier<BigRational>>] {
        &self.contours
    }

    /// The number of segments over all contours.
    ///
    /// # Example
    /// ```
    /// use casteljau::path::ClosedPath;
    /// assert_eq!(ClosedPath::new(vec![]).unwrap().segments(), 0);
    /// ```
    pub fn segments(&self) -> usize {
        self.contours.iter().map(Vec::len).sum()
    }

    /// The estimated work of [`Self::winding`]: per segment, its degree and the bits of its
    /// numbers and of `q` ([`crate::work`]), summed over the contours.
    ///
    /// # Example
    /// ```
    /// use casteljau::path::ClosedPath;
    /// use casteljau::{BezierCurve, num::{Point2, parse_points}, rat};
    /// let seg = |s: &str| BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap();
    /// let path = ClosedPath::from_polynomial(vec![vec![seg("0 0, 1 2, 2 0"), seg("2 0, 0 0")]]).unwrap();
    /// assert!(path.winding_estimate(&Point2::new(rat(1), rat(1))) > 0.0);
    /// ```
    pub fn winding_estimate(&self, q: &Point2<BigRational>) -> f64 {
        self.contours.iter().map(|c| winding_estimate(c, q)).sum()
    }

    /// The winding number of the path around `q` (the sum over its contours, counter-clockwise
    /// positive), or the first place where `q` lies on the path, within a work budget
    /// ([`Self::winding_estimate`], checked before any work starts; [`Budget::unlimited`] for
    /// none). See the [module documentation](super) for how it is decided.
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the estimate exceeds `budget`.
    ///
    /// # Example
    /// ```
    /// use casteljau::path::{ClosedPath, PathWinding};
    /// use casteljau::{BezierCurve, num::{Point2, parse_points}, rat, work::Budget};
    /// let seg = |s: &str| BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap();
    /// let path = ClosedPath::from_polynomial(vec![vec![seg("0 0, 1 2, 2 0"), seg("2 0, 0 0")]]).unwrap();
    /// let on = path.winding(&Point2::new(rat(1), rat(0)), &Budget::unlimited()).unwrap();
    /// assert!(matches!(on, PathWinding::OnBoundary { on_boundary } if on_boundary.segment == 1));
    /// assert!(path.winding(&Point2::new(rat(1), rat(0)), &Budget::new(10.0, "--max-work")).is_err());
    /// let w = path.winding(&Point2::new(rat(1), rat(1) / rat(2)), &Budget::unlimited()).unwrap();
    /// assert_eq!(serde_json::to_string(&w).unwrap(), r#"{"even_odd":true,"inside":true,"winding":-1}"#);
    /// ```
    pub fn winding(&self, q: &Point2<BigRational>, budget: &Budget) -> Result<PathWinding> {
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
}

/// Where a point lies relative to a [`ClosedPath`]: off it with a winding number, or on it.
/// Serialized as the fields of the variant (`even_odd`, `inside`, `winding`, or
/// `on_boundary`).
///
/// # Example
/// ```
/// use casteljau::path::{ClosedPath, PathWinding};
/// use casteljau::{BezierCurve, num::{Point2, parse_points}, rat};
/// let seg = |s: &str| BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap();
/// let path = ClosedPath::from_polynomial(vec![vec![seg("0 0, 1 2, 2 0"), seg("2 0, 0 0")]]).unwrap();
/// let on = path.winding(&Point2::new(rat(1), rat(1)), &casteljau::work::Budget::unlimited()).unwrap();
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
/// use casteljau::path::{FillRule, WindingNumber};
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
    /// use casteljau::path::WindingNumber;
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
    /// use casteljau::path::WindingNumber;
    /// assert_eq!(WindingNumber::new(-1).winding(), -1);
    /// ```
    pub fn winding(&self) -> i64 {
        self.winding
    }

    /// Inside under `rule`.
    ///
    /// # Example
    /// ```
    /// use casteljau::path::{FillRule, WindingNumber};
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
/// use casteljau::path::{ClosedPath, PathWinding};
/// use casteljau::{BezierCurve, num::{Point2, parse_points}, rat};
/// let seg = |s: &str| BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap();
/// let path = ClosedPath::from_polynomial(vec![vec![seg("0 0, 2 0"), seg("2 0, 0 2"), seg("0 2, 0 0")]]).unwrap();
/// let PathWinding::OnBoundary { on_boundary: b } = path.winding(&Point2::new(rat(1), rat(1)), &casteljau::work::Budget::unlimited()).unwrap() else { panic!() };
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
