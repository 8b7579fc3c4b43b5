//! Outline QA decided exactly: the findings of `casteljau lint` for one glyph (or SVG element).
//!
//! Every finding is a statement about exact numbers: the outline's control points are taken as
//! the exact rationals the file stores (see [`crate::format`]), and each check is an exact sign
//! or an exact equality. A finding carries its exact evidence (points and parameters as
//! [`ExactValue`]s, serialized as strings) and the same numbers as `f64` for display; what only
//! its kind has (a contour's area, an extremum's axis, a box) is its [`Evidence`], one variant
//! per kind.
//!
//! # The kinds
//! | kind | severity | what is decided |
//! |---|---|---|
//! | `direction` | error | a contour's orientation (the sign of its exact signed area, Green's theorem) is wrong for its nesting depth (how many other contours contain it, exactly) |
//! | `self_intersection` | error | a contour meets itself other than where consecutive segments join |
//! | `overlap` | warning | two contours cross: one has parts both inside and outside the other |
//! | `touching` | warning | two contours meet (a shared point, a tangency or a shared piece) without crossing |
//! | `overlapping_segments` | error | a piece of outline is drawn by two contours, or twice by one |
//! | `missing_extremum` | warning | a horizontal or vertical tangent strictly inside a segment |
//! | `kink` | warning | a node whose incoming and outgoing tangents turn by less than the kink angle, but not by zero |
//! | `collinear_points` | info | a node between two lines on one line, going on in the same direction |
//! | `zero_length_segment` | error | a segment whose control points are all one point |
//! | `zero_length_handle` | warning | a curve's first or last control point on its end point |
//! | `degenerate_curve` | warning | a curve whose power form has lower degree than written |
//! | `cusp` | warning | the tangent vanishes and the curve turns back strictly inside a segment |
//! | `loop` | error | a segment crosses itself |
//! | `bbox` | warning / error | the glyph's stored bounding box is not the box of its points (warning), or the exact outline leaves the font's `head` box (error) |
//!
//! The arrangement kinds (`direction` to `overlapping_segments`) come from one exact
//! [`crate::shape::Arrangement`] of the glyph with each contour as its own input, so every
//! edge knows every contour's winding number on its two sides.
//!
//! # Rounding to the grid
//! Font outlines live on an integer grid, so a designer's smooth node or extremum is often
//! stored a fraction of a unit off. A finding that such rounding explains has `rounding: true`
//! and severity `info`, and never fails a run:
//! * `kink`: moving each of the node's two handle points by at most ½ unit in x and in y (the
//!   node kept) can make the two tangents point the same way (an exact test on the cones of
//!   the two boxes of directions);
//! * `missing_extremum`: the extreme coordinate lies within ½ unit of the coordinate of one of
//!   the segment's end points, so rounding puts the true extremum on that node's grid line;
//! * `bbox`: the stored box differs from the exact one by less than one unit on every side.
//!
//! # Example
//! ```
//! use casteljau::lint::{Axis, Evidence, Glyph, Kind, LintOptions, lint};
//! use casteljau::num::NumberMode;
//! use casteljau::shape::Orientation;
//! // a counter-clockwise square, and a curve with its top (t = 1/2) not a node
//! let contours = casteljau::format::parse_path("M0 0 H100 V100 H0 Z M200 0 Q250 100 300 0 Z", NumberMode::Exact).unwrap();
//! let glyph = Glyph::new(contours);
//! let findings = lint(&glyph, &LintOptions::new(Orientation::Ccw)).unwrap();
//! let kinds: Vec<Kind> = findings.iter().map(|f| f.kind()).collect();
//! // the curve contour is clockwise (the area under a cap closed by a line drawn right to left)
//! assert_eq!(kinds, [Kind::Direction, Kind::MissingExtremum]);
//! let top = &findings[1];
//! assert_eq!((top.contour, top.index), (Some(1), Some(0)));
//! assert_eq!(top.parameters[0].to_string(), "1/2");
//! assert_eq!(top.at[0][0].to_string() + ", " + &top.at[0][1].to_string(), "250, 50");
//! // the evidence only a missing extremum has: y is extreme, 50 units above the end points
//! let Evidence::MissingExtremum { axis, extent } = &top.evidence else { unreachable!() };
//! assert_eq!((*axis, extent.to_string()), (Axis::Y, "50".to_string()));
//! ```

mod contours;
mod exact;
mod finding;
mod nodes;
mod segments;

pub use exact::ExactValue;
pub use finding::{Axis, Evidence, Finding, SharedPiece};

use crate::error::{Error, Result};
use crate::format::{Contour, PointNumbers, Segment, point_numbers};
use crate::shape::Orientation;
use crate::work::Budget;
use num_rational::BigRational;
use serde::Serialize;

/// What a finding is about. Serialized as its snake_case name ([`Kind::as_str`]).
///
/// # Example
/// ```
/// use casteljau::lint::Kind;
/// assert_eq!("missing_extremum".parse::<Kind>().unwrap(), Kind::MissingExtremum);
/// assert_eq!(Kind::ALL.len(), 14);
/// assert!(Kind::Direction.denied_by_default() && !Kind::Kink.denied_by_default());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    /// A contour's orientation is wrong for its nesting depth.
    Direction,
    /// A contour meets itself.
    SelfIntersection,
    /// Two contours cross.
    Overlap,
    /// Two contours meet without crossing.
    Touching,
    /// A piece of outline drawn twice.
    OverlappingSegments,
    /// A horizontal or vertical tangent strictly inside a segment.
    MissingExtremum,
    /// A node that is almost, but not exactly, smooth.
    Kink,
    /// A redundant node between two lines on one line.
    CollinearPoints,
    /// A segment of length zero.
    ZeroLengthSegment,
    /// A curve's handle of length zero.
    ZeroLengthHandle,
    /// A curve of lower degree than written.
    DegenerateCurve,
    /// A cusp strictly inside a segment.
    Cusp,
    /// A segment crossing itself.
    Loop,
    /// A wrong stored bounding box.
    Bbox,
}

impl Kind {
    /// Every kind, in the order findings of one place are listed.
    pub const ALL: [Kind; 14] = [
        Kind::Direction,
        Kind::SelfIntersection,
        Kind::Overlap,
        Kind::Touching,
        Kind::OverlappingSegments,
        Kind::MissingExtremum,
        Kind::Kink,
        Kind::CollinearPoints,
        Kind::ZeroLengthSegment,
        Kind::ZeroLengthHandle,
        Kind::DegenerateCurve,
        Kind::Cusp,
        Kind::Loop,
        Kind::Bbox,
    ];

    /// The stable name (`direction`, `self_intersection`, …).
    ///
    /// # Example
    /// ```
    /// assert_eq!(casteljau::lint::Kind::OverlappingSegments.as_str(), "overlapping_segments");
    /// ```
    pub fn as_str(self) -> &'static str {
        match self {
            Kind::Direction => "direction",
            Kind::SelfIntersection => "self_intersection",
            Kind::Overlap => "overlap",
            Kind::Touching => "touching",
            Kind::OverlappingSegments => "overlapping_segments",
            Kind::MissingExtremum => "missing_extremum",
            Kind::Kink => "kink",
            Kind::CollinearPoints => "collinear_points",
            Kind::ZeroLengthSegment => "zero_length_segment",
            Kind::ZeroLengthHandle => "zero_length_handle",
            Kind::DegenerateCurve => "degenerate_curve",
            Kind::Cusp => "cusp",
            Kind::Loop => "loop",
            Kind::Bbox => "bbox",
        }
    }

    /// The severity of a finding of this kind that rounding does not explain.
    ///
    /// # Example
    /// ```
    /// use casteljau::lint::{Kind, Severity};
    /// assert_eq!(Kind::Loop.severity(), Severity::Error);
    /// ```
    pub fn severity(self) -> Severity {
        match self {
            Kind::Direction
            | Kind::SelfIntersection
            | Kind::OverlappingSegments
            | Kind::ZeroLengthSegment
            | Kind::Loop
            | Kind::Bbox => Severity::Error,
            Kind::CollinearPoints => Severity::Info,
            _ => Severity::Warning,
        }
    }

    /// `direction`, `self_intersection`, `overlapping_segments` and `zero_length_segment`: the
    /// kinds that fail a run unless `--deny` says otherwise.
    ///
    /// # Example
    /// ```
    /// assert!(casteljau::lint::Kind::ZeroLengthSegment.denied_by_default());
    /// ```
    pub fn denied_by_default(self) -> bool {
        matches!(self, Kind::Direction | Kind::SelfIntersection | Kind::OverlappingSegments | Kind::ZeroLengthSegment)
    }

    /// Kinds decided from the glyph's arrangement.
    fn needs_arrangement(self) -> bool {
        matches!(
            self,
            Kind::Direction | Kind::SelfIntersection | Kind::Overlap | Kind::Touching | Kind::OverlappingSegments
        )
    }
}

impl std::fmt::Display for Kind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

impl std::str::FromStr for Kind {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        Kind::ALL.into_iter().find(|k| k.as_str() == s).ok_or_else(|| Error::InvalidArgument {
            message: format!("unknown lint kind {s:?} (kinds: {})", Kind::ALL.map(Kind::as_str).join(", ")),
        })
    }
}

/// How much a finding matters. Serialized as `error`, `warning` or `info`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    /// A defect that breaks rendering or the font's contract.
    Error,
    /// Very likely a mistake.
    Warning,
    /// Worth knowing; includes every finding rounding explains.
    Info,
}

impl Severity {
    /// `error`, `warning` or `info`.
    ///
    /// # Example
    /// ```
    /// assert_eq!(casteljau::lint::Severity::Info.as_str(), "info");
    /// ```
    pub fn as_str(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Info => "info",
        }
    }
}

/// One glyph (or SVG element) to check: its contours, each with the numbering of its stored
/// points, and, for `glyf` fonts, the bounding boxes the font stores.
#[derive(Clone, Debug, Default)]
pub struct Glyph {
    /// The contours, as [`crate::format`] reads them.
    pub contours: Vec<Contour>,
    /// Per contour, the stored point numbers of every control point ([`point_numbers`] by
    /// default).
    pub numbers: Vec<PointNumbers>,
    /// Stored points on no segment (contours of one point): they count for the box of the
    /// points.
    pub lone_points: Vec<crate::num::point::Point<BigRational>>,
    /// The box stored in the glyph's header (`glyf`), `[x_min, y_min, x_max, y_max]`.
    pub stored_box: Option<[BigRational; 4]>,
    /// The font's box (`head`): the exact outline must stay inside it.
    pub font_box: Option<[BigRational; 4]>,
}

impl Glyph {
    /// A glyph of these contours, numbered by [`point_numbers`], without stored boxes.
    ///
    /// # Example
    /// ```
    /// let c = casteljau::format::parse_path("M0 0 H1 V1 Z", casteljau::num::NumberMode::Exact).unwrap();
    /// assert_eq!(casteljau::lint::Glyph::new(c).numbers[0].len(), 3);
    /// ```
    pub fn new(contours: Vec<Contour>) -> Self {
        let numbers = contours.iter().map(point_numbers).collect();
        Glyph { contours, numbers, lone_points: vec![], stored_box: None, font_box: None }
    }
}

/// What to check and how.
#[derive(Clone, Debug)]
pub struct LintOptions {
    /// The orientation of outer contours (holes the other way): [`Orientation::Cw`] for TrueType
    /// (`glyf`), [`Orientation::Ccw`] for CFF, CFF2 and SVG.
    pub outer: Orientation,
    /// The kinds to decide (others are not computed).
    pub kinds: Vec<Kind>,
    /// The kink angle in degrees (`0 < α < 90`; default 10).
    pub kink_degrees: f64,
    /// `tan α` as the exact rational value of its binary64 rounding: a turn `θ` is below the
    /// kink angle when `(u × v)² < r²·(u · v)²` with `u · v > 0` (see [`Self::with_kink_angle`]).
    pub kink_tangent: BigRational,
    /// `--extremum-min`: a missing extremum whose extent is below this is not reported.
    pub extremum_min: Option<BigRational>,
    /// The work budget of the glyph's arrangement.
    pub budget: Budget,
}

impl LintOptions {
    /// Every kind, outer contours `outer`, a kink angle of 10°, no extremum threshold, no work
    /// limit.
    ///
    /// # Example
    /// ```
    /// let o = casteljau::lint::LintOptions::new(casteljau::shape::Orientation::Cw);
    /// assert_eq!((o.kinds.len(), o.kink_degrees), (14, 10.0));
    /// ```
    pub fn new(outer: Orientation) -> Self {
        let mut o = LintOptions {
            outer,
            kinds: Kind::ALL.to_vec(),
            kink_degrees: 10.0,
            kink_tangent: BigRational::from_integer(0.into()),
            extremum_min: None,
            budget: Budget::unlimited(),
        };
        o = o.with_kink_angle(10.0).expect("10 degrees is a valid angle");
        o
    }

    /// Sets the kink angle `α` in degrees. The exact comparison uses the rational `r`, the
    /// binary64 value of `tan(α·π/180)` taken exactly (within an ulp or two of the real
    /// tangent): a node with tangents `u` in and `v` out is a kink when `u × v ≠ 0`, `u · v > 0`
    /// and `(u × v)² < r²·(u · v)²`, that is `tan θ < r`.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] unless `0 < α < 90`.
    ///
    /// # Example
    /// ```
    /// let o = casteljau::lint::LintOptions::new(casteljau::shape::Orientation::Cw).with_kink_angle(45.0).unwrap();
    /// let (one, tiny) = (casteljau::rat(1), casteljau::rat(1) / casteljau::rat(1 << 40));
    /// assert!(o.kink_tangent > &one - &tiny && o.kink_tangent < one + tiny); // tan 45° within 2^-40
    /// assert!(casteljau::lint::LintOptions::new(casteljau::shape::Orientation::Cw).with_kink_angle(90.0).is_err());
    /// ```
    pub fn with_kink_angle(mut self, degrees: f64) -> Result<Self> {
        if !(degrees > 0.0 && degrees < 90.0) {
            return Err(Error::InvalidArgument {
                message: format!("the kink angle must be above 0 and below 90 degrees, not {degrees}"),
            });
        }
        let r = degrees.to_radians().tan();
        self.kink_degrees = degrees;
        self.kink_tangent = BigRational::from_float(r).expect("a finite tangent");
        Ok(self)
    }

    fn wants(&self, k: Kind) -> bool {
        self.kinds.contains(&k)
    }
}

/// Every finding of `glyph` of the kinds `options` asks for, ordered by contour, segment,
/// point and kind.
///
/// # Errors
/// [`Error::WorkLimit`] when the glyph's arrangement is estimated above `options.budget`; the
/// errors of [`crate::shape::Arrangement::new`]; [`Error::InvalidArgument`] for a
/// contour with a piece that is no polynomial Bézier curve (an SVG arc) when an arrangement
/// kind is asked for, and for a Bézier segment of degree above 3 (or without control points).
///
/// # Example
/// ```
/// use casteljau::lint::{Evidence, Glyph, Kind, LintOptions, lint};
/// use casteljau::shape::Orientation;
/// // two squares side by side sharing the edge x = 10
/// let c = casteljau::format::parse_path("M0 0 H10 V10 H0 Z M10 0 H20 V10 H10 Z", casteljau::num::NumberMode::Exact).unwrap();
/// let f = lint(&Glyph::new(c), &LintOptions::new(Orientation::Ccw)).unwrap();
/// let kinds: Vec<Kind> = f.iter().map(|f| f.kind()).collect();
/// assert_eq!(kinds, [Kind::Touching, Kind::OverlappingSegments]);
/// assert!(matches!(&f[1].evidence, Evidence::OverlappingSegments { shared } if shared.len() == 2));
/// ```
pub fn lint(glyph: &Glyph, options: &LintOptions) -> Result<Vec<Finding>> {
    // the checks are written for lines, quadratics and cubics (what fonts and SVG hold)
    for (ci, c) in glyph.contours.iter().enumerate() {
        for (si, s) in c.segments.iter().enumerate() {
            if let Segment::Bezier(ps) = s
                && !(1..=4).contains(&ps.len())
            {
                return Err(Error::InvalidArgument {
                    message: format!(
                        "contour {ci}, segment {si}: a Bézier segment of {} control points (lint checks degrees 1 to 3)",
                        ps.len()
                    ),
                });
            }
        }
    }
    let mut out = vec![];
    for (ci, c) in glyph.contours.iter().enumerate() {
        let numbers = glyph.numbers.get(ci);
        for (si, s) in c.segments.iter().enumerate() {
            if let Segment::Bezier(ps) = s {
                let point = numbers.and_then(|n| n.get(si)).and_then(|n| n.first().copied().flatten());
                for mut f in segments::check(ps, options) {
                    f.contour = Some(ci);
                    f.index = Some(si);
                    if f.point.is_none() && matches!(f.evidence, Evidence::ZeroLengthSegment) {
                        f.point = point;
                    }
                    out.push(f);
                }
            }
        }
        out.extend(nodes::check(ci, c, numbers, options));
    }
    if options.kinds.iter().any(|k| k.needs_arrangement()) {
        out.extend(contours::check(glyph, options)?);
    }
    if options.wants(Kind::Bbox) {
        out.extend(segments::boxes(glyph));
    }
    // contour-wide findings (no segment) first within their contour
    let place =
        |f: &Finding| (f.contour.or(f.contours.map(|c| c[0])), f.contours.map(|c| c[1]), f.index, f.point, f.kind());
    out.sort_by_key(place);
    Ok(out)
}
