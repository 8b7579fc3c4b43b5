//! Typed results of the spline operations, one per operation of the `spline` command: each
//! derives `Serialize` (exact numbers as strings), so its JSON is its schema, and text is
//! rendered from the same value.

use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::serial::AsString;
use crate::proof::Reading;
use crate::rational::RationalBezier;
use crate::spline::knots::Join;
use crate::spline::surface::{NurbsSurface, NurbsSurfaceReport, PatchPiece};
use crate::spline::{Conversion, RationalSpline, SegmentMismatch, check_segments};
use crate::work::Budget;
use num_rational::BigRational;
use serde::Serialize;
use serde::ser::{SerializeStruct, Serializer};

/// An interval `(a, b)` as `["a", "b"]`.
fn pair<S: Serializer>(p: &(BigRational, BigRational), s: S) -> std::result::Result<S::Ok, S::Error> {
    [AsString(&p.0), AsString(&p.1)].serialize(s)
}

/// A spline as JSON: `degree`, `homogeneous` (the control points `w·P, w`), `knots` (the full
/// vector, [`RationalSpline::full_knot_vector`]), `points` (affine, `null` at infinity) and
/// `weights`.
///
/// # Example
/// ```
/// use casteljau::{Point, rat, spline::RationalSpline};
/// let h: Vec<Point<_>> = [(0, 0, 1), (2, 2, 2), (2, 0, 1)].iter().map(|&(x, y, w)| Point::new(vec![rat(x), rat(y), rat(w)])).collect();
/// let sp = RationalSpline::from_knots(2, h, &[0, 0, 0, 1, 1, 1].map(rat)).unwrap();
/// assert_eq!(
///     serde_json::to_string(&sp).unwrap(),
///     r#"{"degree":2,"homogeneous":[["0","0","1"],["2","2","2"],["2","0","1"]],"knots":["0","0","0","1","1","1"],"points":[["0","0"],["1","1"],["2","0"]],"weights":["1","2","1"]}"#
/// );
/// ```
impl Serialize for RationalSpline {
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        let d = self.homogeneous[0].dim() - 1;
        let points: Vec<Option<Point<BigRational>>> = self.homogeneous.iter().map(Point::from_homogeneous).collect();
        let weights: Vec<&BigRational> = self.homogeneous.iter().map(|h| &h.coords[d]).collect();
        let mut st = s.serialize_struct("RationalSpline", 5)?;
        st.serialize_field("degree", &self.degree)?;
        st.serialize_field("homogeneous", &self.homogeneous)?;
        st.serialize_field("knots", &self.full_knot_vector().iter().map(AsString).collect::<Vec<_>>())?;
        st.serialize_field("points", &points)?;
        st.serialize_field("weights", &weights.into_iter().map(AsString).collect::<Vec<_>>())?;
        st.end()
    }
}

/// One rational Bézier segment of a spline and its parameter interval: the curve's fields
/// (`degree`, `homogeneous`, `points`, `weights`) and `span`.
///
/// # Example
/// ```
/// use casteljau::{Point, rat, spline::{BezierConversion, Conversion, RationalSpline}};
/// let h: Vec<Point<_>> = [(0, 0), (1, 2), (2, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
/// let sp = RationalSpline::from_knots(1, h, &[0, 0, 1, 2, 2].map(rat)).unwrap();
/// let c = BezierConversion::new(&sp, Conversion::Boehm, &casteljau::work::Budget::unlimited()).unwrap();
/// assert_eq!(c.segments[1].span, (rat(1), rat(2)));
/// let json = serde_json::to_string(&c.segments[1]).unwrap();
/// assert!(json.ends_with(r#""span":["1","2"]}"#));
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct SplineSegment {
    /// The segment on `[0, 1]`.
    #[serde(flatten)]
    pub curve: RationalBezier<BigRational>,
    /// Its interval `[a, b]` of the spline parameter.
    #[serde(serialize_with = "pair")]
    pub span: (BigRational, BigRational),
}

/// A spline's rational Bézier segments by one [`Conversion`] and the continuity proved at each
/// join ([`BezierConversion::new`]).
///
/// # Example
/// ```
/// use casteljau::{Point, rat, spline::{BezierConversion, Conversion, RationalSpline}};
/// let h: Vec<Point<_>> = [(0, 0), (1, 2), (2, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
/// let sp = RationalSpline::from_knots(1, h, &[0, 0, 1, 2, 2].map(rat)).unwrap();
/// let c = BezierConversion::new(&sp, Conversion::Boehm, &casteljau::work::Budget::unlimited()).unwrap();
/// assert_eq!((c.segments.len(), c.joins.len(), c.joins[0].continuity), (2, 1, 0));
/// assert!(c.proved());
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct BezierConversion {
    /// The spline's degree.
    pub degree: usize,
    /// The joins between consecutive segments ([`RationalSpline::joins`]).
    pub joins: Vec<Join>,
    /// The route taken (written `boehm`, `seed`, `seed-printed`).
    #[serde(serialize_with = "crate::num::serial::string")]
    pub method: Conversion,
    /// The segments, in parameter order.
    pub segments: Vec<SplineSegment>,
}

impl BezierConversion {
    /// Every join's continuity was proved.
    ///
    /// # Example
    /// ```
    /// use casteljau::{Point, rat, spline::{BezierConversion, Conversion, RationalSpline}};
    /// let h: Vec<Point<_>> = (0..4).map(|i| Point::new(vec![rat(i), rat(i * i), rat(1)])).collect();
    /// let sp = RationalSpline::from_knots(2, h, &[0, 0, 0, 1, 2, 2, 2].map(rat)).unwrap();
    /// assert!(BezierConversion::new(&sp, Conversion::Boehm, &casteljau::work::Budget::unlimited()).unwrap().proved());
    /// ```
    pub fn proved(&self) -> bool {
        self.joins.iter().all(|j| j.proved)
    }
}

/// The proof that a spline's Bézier segments are the spline: Boehm's segments checked against
/// the NURBS ([`check_segments`]), for degrees 2 and 3 with positive scale ratios also the
/// seed's formulas and their equality with Boehm's, and the continuity at every join.
/// Serialized as `degree`, `joins`, `passed`, `report` (the lines of the text) and `segments`
/// (their count).
///
/// # Example
/// ```
/// use casteljau::{Point, rat, spline::{RationalSpline, SplineCheck}, work::Budget};
/// let h: Vec<Point<_>> = [(0, 0), (1, 2), (2, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
/// let sp = RationalSpline::from_knots(1, h, &[0, 0, 1, 2, 2].map(rat)).unwrap();
/// let c = SplineCheck::new(&sp, &Budget::unlimited()).unwrap();
/// assert!(c.passed);
/// assert_eq!(c.boehm, Ok(6)); // 3 exact points on each of the 2 segments
/// assert_eq!(c.report[0], "Boehm knot insertion: every segment is the NURBS on its span (6 exact points), joins C^0");
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct SplineCheck {
    /// The spline's degree.
    pub degree: usize,
    /// The joins between Boehm's segments.
    pub joins: Vec<Join>,
    /// Everything was proved.
    pub passed: bool,
    /// One line per finding, as the text output prints them.
    pub report: Vec<String>,
    /// The number of segments.
    pub segments: usize,
    /// Boehm's segments against the NURBS: the exact points compared, or the first mismatch.
    #[serde(skip)]
    pub boehm: std::result::Result<usize, SegmentMismatch>,
    /// For degrees 2 and 3 with positive scale ratios: the seed's formulas (corrected reading)
    /// against the NURBS, and whether their points and weights equal Boehm's.
    #[serde(skip)]
    pub seed: Option<(std::result::Result<usize, SegmentMismatch>, bool)>,
}

/// A spline's values at some parameters ([`SplineValues::new`]).
///
/// # Example
/// ```
/// use casteljau::{Point, rat, ratio, spline::{RationalSpline, SplineValues}, work::Budget};
/// let h: Vec<Point<_>> = [(0, 0), (1, 2), (2, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
/// let sp = RationalSpline::from_knots(1, h, &[0, 0, 1, 2, 2].map(rat)).unwrap();
/// let v = SplineValues::new(&sp, &[ratio(1, 2)], &Budget::unlimited()).unwrap();
/// assert_eq!(serde_json::to_string(&v).unwrap(), r#"{"degree":1,"values":[{"point":["1/2","1"],"u":"1/2"}]}"#);
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct SplineValues {
    /// The spline's degree.
    pub degree: usize,
    /// One value per parameter, in the order given.
    pub values: Vec<SplineValue>,
}

/// The point of a spline at one parameter.
///
/// # Example
/// ```
/// use casteljau::{Point, rat, spline::{RationalSpline, SplineValues}, work::Budget};
/// let h: Vec<Point<_>> = [(0, 0), (2, 2)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
/// let sp = RationalSpline::from_knots(1, h, &[0, 0, 1, 1].map(rat)).unwrap();
/// let v = &SplineValues::new(&sp, &[rat(1)], &Budget::unlimited()).unwrap().values[0];
/// assert_eq!((v.u.clone(), v.point.clone()), (rat(1), Point::new(vec![rat(2), rat(2)])));
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct SplineValue {
    /// The affine point.
    pub point: Point<BigRational>,
    /// The parameter.
    #[serde(serialize_with = "crate::num::serial::string")]
    pub u: BigRational,
}

/// The result of removing a knot several times ([`RationalSpline::remove_knot`]): the
/// spline after the removals that kept the curve, how many there were, and whether all the
/// requested ones did. Serialized as the spline's fields plus `removable` and `removed`.
///
/// # Example
/// ```
/// use casteljau::{Point, rat, spline::RationalSpline};
/// let h: Vec<Point<_>> = (0..5).map(|i| Point::new(vec![rat(i), rat(i), rat(1)])).collect();
/// let sp = RationalSpline::from_knots(2, h, &[0, 0, 0, 1, 1, 2, 2, 2].map(rat)).unwrap();
/// let r = sp.remove_knot(&rat(1), 2).unwrap(); // a straight line: both copies come out
/// assert_eq!((r.removed, r.removable, r.spline.homogeneous.len()), (2, true, 3));
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct KnotRemoval {
    /// The spline after the exact removals.
    #[serde(flatten)]
    pub spline: RationalSpline,
    /// Every requested removal kept the curve.
    pub removable: bool,
    /// The number of removals made.
    pub removed: usize,
}

/// The exact rational Bézier patches of a NURBS surface and their check
/// ([`SurfaceExtraction::new`]). Serialized as `check`, `degree` (`[p, q]`) and
/// `patches` (each with `homogeneous` rows, `span_u` and `span_v`).
///
/// # Example
/// ```
/// use casteljau::{Point, rat, spline::{NurbsSurface, SurfaceExtraction}, work::Budget};
/// let row = |y: i64| (0..2).map(|x| Point::new(vec![rat(x), rat(y), rat(x * y), rat(1)])).collect::<Vec<_>>();
/// let s = NurbsSurface::from_knots((1, 1), vec![row(0), row(1)], &[0, 0, 1, 1].map(rat), &[0, 0, 1, 1].map(rat)).unwrap();
/// let e = SurfaceExtraction::new(&s, &Budget::unlimited()).unwrap();
/// assert_eq!(e.patches.len(), 1);
/// assert!(e.check.equals_surface && e.check.joins_proved);
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct SurfaceExtraction {
    /// The patches against the surface, and the continuity at the joins.
    pub check: NurbsSurfaceReport,
    /// The degrees `(p, q)`.
    pub degree: (usize, usize),
    /// The patches, row by row (along `u`, then `v`).
    pub patches: Vec<PatchPiece>,
}

impl Serialize for PatchPiece {
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        struct Span<'a>(&'a (BigRational, BigRational));
        impl Serialize for Span<'_> {
            fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
                pair(self.0, s)
            }
        }
        let mut st = s.serialize_struct("PatchPiece", 3)?;
        st.serialize_field("homogeneous", self.patch.homogeneous())?;
        st.serialize_field("span_u", &Span(&self.span_u))?;
        st.serialize_field("span_v", &Span(&self.span_v))?;
        st.end()
    }
}

impl RationalSpline {
    /// The spline with the knot `u` inserted `times` times ([`Self::insert_knot`] repeated).
    ///
    /// # Errors
    /// As [`Self::insert_knot`]; [`Error::TooLarge`] when the result would exceed
    /// 10,000 (`MAX_SPLINE_POINTS`).
    ///
    /// # Example
    /// ```
    /// use casteljau::{Point, rat, ratio, spline::RationalSpline};
    /// let h: Vec<Point<_>> = (0..4).map(|i| Point::new(vec![rat(i), rat(i * i), rat(1)])).collect();
    /// let sp = RationalSpline::from_knots(3, h, &[0, 0, 0, 0, 1, 1, 1, 1].map(rat)).unwrap();
    /// let more = sp.insert_knot(&ratio(1, 2), 2).unwrap();
    /// assert_eq!(more.homogeneous.len(), 6);
    /// assert_eq!(more.eval_at(&ratio(1, 3)).unwrap(), sp.eval_at(&ratio(1, 3)).unwrap());
    /// ```
    pub fn insert_knot(&self, u: &BigRational, times: usize) -> Result<Self> {
        let limit = crate::spline::knots::MAX_SPLINE_POINTS;
        if self.homogeneous.len().saturating_add(times) > limit {
            return Err(Error::TooLarge {
                what: "spline control points",
                value: self.homogeneous.len().saturating_add(times),
                limit,
            });
        }
        let mut out = self.clone();
        for _ in 0..times {
            out = out.insert_knot_once(u)?;
        }
        Ok(out)
    }

    /// Removes the knot `u` up to `times` times, each removal exact ([`Self::remove_knot`]):
    /// stops at the first removal that would change the curve.
    ///
    /// # Errors
    /// As [`Self::remove_knot`].
    ///
    /// # Example
    /// ```
    /// use casteljau::{Point, rat, spline::RationalSpline};
    /// let h: Vec<Point<_>> = [(0, 0), (1, 3), (2, -1), (4, 2), (5, 0)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
    /// let sp = RationalSpline::from_knots(3, h, &[0, 0, 0, 0, 1, 2, 2, 2, 2].map(rat)).unwrap();
    /// let r = sp.remove_knot(&rat(1), 1).unwrap();
    /// assert_eq!((r.removed, r.removable), (0, false)); // knot 1 carries a real join
    /// assert_eq!(r.spline, sp);
    /// ```
    pub fn remove_knot(&self, u: &BigRational, times: usize) -> Result<KnotRemoval> {
        let mut spline = self.clone();
        for removed in 0..times {
            match spline.remove_knot_once(u)? {
                Some(less) => spline = less,
                None => return Ok(KnotRemoval { spline, removable: false, removed }),
            }
        }
        Ok(KnotRemoval { spline, removable: true, removed: times })
    }

    /// "a degree-n spline of m control points" for work-limit messages.
    fn work_what(&self, doing: &str) -> String {
        let sep = if doing.is_empty() { "" } else { " " };
        format!("{doing}{sep}a degree-{} spline of {} control points", self.degree, self.homogeneous.len())
    }

    /// `(degree, control points, homogeneous dimension, bits)` for the cost models.
    fn work_shape(&self) -> crate::work::SplineShape {
        crate::work::SplineShape {
            degree: self.degree,
            points: self.homogeneous.len(),
            dim: self.homogeneous[0].dim(),
            bits: crate::work::max_bits(&self.homogeneous).max(crate::work::max_bits_of(&self.knots)),
        }
    }
}

impl NurbsSurface {}

/// The joins in words: `u = 1 (multiplicity 1): C^1, proved; …`.
///
/// # Example
/// ```
/// use casteljau::{Point, rat, spline::{RationalSpline, joins_text}};
/// let h: Vec<Point<_>> = (0..4).map(|i| Point::new(vec![rat(i), rat(i * i), rat(1)])).collect();
/// let sp = RationalSpline::from_knots(2, h, &[0, 0, 0, 1, 2, 2, 2].map(rat)).unwrap();
/// assert_eq!(joins_text(&sp.joins(&sp.bezier_segments().unwrap())), "u = 1 (multiplicity 1): C^1, proved");
/// ```
pub fn joins_text(joins: &[Join]) -> String {
    joins
        .iter()
        .map(|j| {
            let c = if j.continuity < 0 { "no continuity (a jump)".to_string() } else { format!("C^{}", j.continuity) };
            format!(
                "u = {} (multiplicity {}): {c}, {}",
                j.knot,
                j.multiplicity,
                if j.proved { "proved" } else { "NOT proved" }
            )
        })
        .collect::<Vec<_>>()
        .join("; ")
}

impl SplineValues {
    /// The points at each of `us` (de Boor, [`RationalSpline::eval_at`]), within a work budget
    /// (its estimate each).
    ///
    /// # Errors
    /// As [`RationalSpline::eval_at`]; [`Error::WorkLimit`] when the estimate exceeds `budget`.
    ///
    /// # Example
    /// ```
    /// use casteljau::{Point, rat, ratio, spline::{RationalSpline, SplineValues}, work::Budget};
    /// let h: Vec<Point<_>> = [(0, 0), (2, 2)].iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y), rat(1)])).collect();
    /// let sp = RationalSpline::from_knots(1, h, &[0, 0, 1, 1].map(rat)).unwrap();
    /// let v = SplineValues::new(&sp, &[ratio(1, 4), rat(1)], &Budget::unlimited()).unwrap();
    /// assert_eq!(v.values[0].point, Point::new(vec![ratio(1, 2), ratio(1, 2)]));
    /// assert!(SplineValues::new(&sp, &[rat(2)], &Budget::unlimited()).is_err()); // outside [0, 1]
    /// ```
    pub fn new(spline: &RationalSpline, us: &[BigRational], budget: &Budget) -> Result<Self> {
        let tau = crate::work::max_bits_of(us);
        budget.check(
            format!("{} evaluations of {}", us.len(), spline.work_what("")),
            us.len() as f64 * crate::work::spline_evaluation(spline.work_shape(), tau),
        )?;
        let values =
            us.iter().map(|u| Ok(SplineValue { point: spline.eval_at(u)?, u: u.clone() })).collect::<Result<_>>()?;
        Ok(SplineValues { degree: spline.degree, values })
    }
}

impl SplineCheck {
    /// The proof that the spline's Bézier segments are the spline ([`SplineCheck`]), within a
    /// work budget (its estimate).
    ///
    /// # Errors
    /// As [`RationalSpline::to_bezier`]; [`Error::WorkLimit`] when the estimate exceeds `budget`. A
    /// failed proof is not an error: `passed` is false.
    ///
    /// # Example
    /// ```
    /// use casteljau::{Point, rat, spline::{RationalSpline, SplineCheck}, work::Budget};
    /// let q: Vec<Point<_>> = (0..6).map(|i| Point::new(vec![rat(i), rat(i * i % 5)])).collect();
    /// let sp = RationalSpline::new(3, &q, &[1, 2, 1, 3, 1, 2].map(rat), &[1, 2, 1, 3, 2, 1, 2, 1].map(rat)).unwrap();
    /// let c = SplineCheck::new(&sp, &Budget::unlimited()).unwrap();
    /// assert!(c.passed);
    /// assert_eq!(c.seed.as_ref().map(|s| s.1), Some(true)); // the seed's formulas give Boehm's segments
    /// ```
    pub fn new(spline: &RationalSpline, budget: &Budget) -> Result<Self> {
        budget.check(
            spline.work_what("checking the Bézier segments of"),
            crate::work::spline_check(spline.work_shape()),
        )?;
        let boehm_segments = spline.to_bezier_boehm()?;
        let repeated = spline.has_repeated_knots();
        let mut report = Vec::new();
        let mut passed = true;
        let mut line = |name: &str, r: &std::result::Result<usize, SegmentMismatch>| match r {
            Ok(points) => report.push(format!(
                "{name}: every segment is the NURBS on its span ({points} exact points), joins {}",
                if repeated {
                    "C^(n-mu) at each knot of multiplicity mu".to_string()
                } else {
                    format!("C^{}", spline.degree - 1)
                }
            )),
            Err(e) => {
                passed = false;
                report.push(format!("{name}: FAILS: {e:?}"));
            }
        };
        let boehm = check_segments(spline, &boehm_segments);
        line("Boehm knot insertion", &boehm);
        let seed = if matches!(spline.degree, 2 | 3) && !repeated {
            let seed = spline.to_bezier(Conversion::Seed(Reading::Corrected))?;
            let checked = check_segments(spline, &seed);
            line("seed formulas", &checked);
            let same =
                seed.iter().zip(&boehm_segments).all(|(a, b)| a.points() == b.points() && a.weights() == b.weights());
            passed &= same;
            report.push(format!("seed formulas = Boehm (points and weights): {same}"));
            Some((checked, same))
        } else {
            None
        };
        let joins = spline.joins(&boehm_segments);
        if !joins.is_empty() {
            report.push(format!("joins: {}", joins_text(&joins)));
        }
        passed &= joins.iter().all(|j| j.proved);
        Ok(SplineCheck { degree: spline.degree, joins, passed, report, segments: spline.segments(), boehm, seed })
    }
}

impl BezierConversion {
    /// The rational Bézier segments by `how` with their spans and the joins between them,
    /// within a work budget (its estimate).
    ///
    /// # Errors
    /// As [`RationalSpline::to_bezier`]; [`Error::WorkLimit`] when the estimate exceeds `budget`.
    ///
    /// # Example
    /// ```
    /// use casteljau::{Point, rat, spline::{BezierConversion, Conversion, RationalSpline}, work::Budget};
    /// let h: Vec<Point<_>> = (0..4).map(|i| Point::new(vec![rat(i), rat(i * i), rat(1)])).collect();
    /// let sp = RationalSpline::from_knots(2, h, &[0, 0, 0, 1, 2, 2, 2].map(rat)).unwrap();
    /// let c = BezierConversion::new(&sp, Conversion::Boehm, &Budget::unlimited()).unwrap();
    /// assert_eq!(c.segments[0].span, (rat(0), rat(1)));
    /// assert!(BezierConversion::new(&sp, Conversion::Boehm, &Budget::new(1.0, "--max-work")).is_err());
    /// ```
    pub fn new(spline: &RationalSpline, how: Conversion, budget: &Budget) -> Result<Self> {
        budget.check(spline.work_what("Bézier segments of"), crate::work::spline_conversion(spline.work_shape()))?;
        let segs = spline.to_bezier(how)?;
        let joins = spline.joins(&segs);
        let spans = spline.span_indices();
        let segments = segs
            .into_iter()
            .zip(spans)
            .map(|(curve, j)| SplineSegment { curve, span: (spline.knots[j].clone(), spline.knots[j + 1].clone()) })
            .collect();
        Ok(BezierConversion { degree: spline.degree, joins, method: how, segments })
    }
}

impl SurfaceExtraction {
    /// The exact Bézier patches ([`NurbsSurface::bezier_patches`]) and their check ([`NurbsSurface::check`]),
    /// within a work budget (its estimate).
    ///
    /// # Errors
    /// As [`NurbsSurface::bezier_patches`] and [`NurbsSurface::check`]; [`Error::WorkLimit`] when the estimate
    /// exceeds `budget`.
    ///
    /// # Example
    /// ```
    /// use casteljau::{Point, rat, spline::{NurbsSurface, SurfaceExtraction}, work::Budget};
    /// let row = |y: i64| (0..3).map(|x| Point::new(vec![rat(x), rat(y), rat(x * y), rat(1)])).collect::<Vec<_>>();
    /// let s = NurbsSurface::from_knots((1, 1), vec![row(0), row(1)], &[0, 0, 1, 1].map(rat), &[0, 0, 1, 2, 2].map(rat)).unwrap();
    /// let e = SurfaceExtraction::new(&s, &Budget::unlimited()).unwrap();
    /// assert_eq!((e.degree, e.patches.len(), e.check.patches), ((1, 1), 2, 2));
    /// ```
    pub fn new(surface: &NurbsSurface, budget: &Budget) -> Result<Self> {
        let points: usize = surface.rows.iter().map(Vec::len).sum();
        let dim = surface.rows.first().and_then(|r| r.first()).map_or(1, Point::dim);
        let bits = surface.rows.iter().map(|r| crate::work::max_bits(r)).max().unwrap_or(0);
        budget.check(
            format!(
                "the Bézier patches of a degree-({}, {}) surface of {points} control points",
                surface.degree.0, surface.degree.1
            ),
            crate::work::surface_extraction(surface.degree, points, dim, bits),
        )?;
        let patches = surface.bezier_patches()?.into_iter().flatten().collect();
        let check = surface.check()?;
        Ok(SurfaceExtraction { check, degree: surface.degree, patches })
    }
}
