//! A finding and its evidence: what is common to every finding (severity, place, exact points
//! and parameters, message) in [`Finding`], what only one kind has in [`Evidence`].

use super::exact::ExactValue;
use super::{Kind, Severity};
use crate::shape::Orientation;
use num_rational::BigRational;
use serde::Serialize;
use serde::ser::{Impossible, SerializeStruct, Serializer};

/// A piece of a segment, `[from, to]` in its parameter, shared with another contour or drawn
/// twice (the evidence of `overlapping_segments`). JSON: `contour`, `segment`, `from`, `to`.
///
/// # Example
/// ```
/// use casteljau::lint::{Evidence, Glyph, LintOptions, lint};
/// // the right square's left edge covers the middle of the left square's right edge
/// let c = casteljau::format::parse_path("M0 0 H4 V4 H0 Z M4 1 H8 V3 H4 Z", casteljau::num::NumberMode::Exact).unwrap();
/// let f = lint(&Glyph::new(c), &LintOptions::new(casteljau::shape::Orientation::Ccw)).unwrap();
/// let shared = f.iter().find_map(|f| match &f.evidence {
///     Evidence::OverlappingSegments { shared } => Some(shared),
///     _ => None,
/// });
/// let spans: Vec<String> = shared.unwrap().iter().map(|p| format!("{} {} {}..{}", p.contour, p.segment, p.from, p.to)).collect();
/// assert_eq!(spans, ["0 1 1/4..3/4", "1 3 1..0"]);
/// ```
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SharedPiece {
    /// The contour.
    pub contour: usize,
    /// The segment in the contour.
    pub segment: usize,
    /// Where the piece starts on the segment.
    pub from: ExactValue,
    /// Where it ends (`from > to`: the piece runs against the edge it shares).
    pub to: ExactValue,
}

/// The coordinate that is extreme at a missing extremum. Serialized (and displayed) as `x` or
/// `y`.
///
/// # Example
/// ```
/// use casteljau::lint::Axis;
/// assert_eq!((Axis::X.as_str(), Axis::Y.to_string().as_str()), ("x", "y"));
/// assert_eq!(serde_json::to_string(&Axis::Y).unwrap(), r#""y""#);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Axis {
    /// x is extreme: a vertical tangent.
    X,
    /// y is extreme: a horizontal tangent.
    Y,
}

impl Axis {
    /// `x` or `y`.
    pub fn as_str(self) -> &'static str {
        match self {
            Axis::X => "x",
            Axis::Y => "y",
        }
    }
}

impl std::fmt::Display for Axis {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// What a finding is, with the evidence of its kind: one variant per [`Kind`] (same name), each
/// carrying exactly the fields of that kind. The evidence every kind has (points, parameters,
/// place) is in [`Finding`].
///
/// Serialized with its kind as the tag: `{"kind": "direction", "area": …, "depth": …,
/// "expected": …}`, `{"kind": "cusp"}`. In a [`Finding`]'s JSON the same fields follow
/// `parameters` (and `kind` comes first).
///
/// # Example
/// ```
/// use casteljau::lint::{Evidence, Glyph, Kind, LintOptions, lint};
/// use casteljau::shape::Orientation;
/// // a 6 × 6 hole drawn counter-clockwise, like its outer contour
/// let c = casteljau::format::parse_path("M0 0 H10 V10 H0 Z M2 2 H8 V8 H2 Z", casteljau::num::NumberMode::Exact).unwrap();
/// let f = &lint(&Glyph::new(c), &LintOptions::new(Orientation::Ccw)).unwrap()[0];
/// let Evidence::Direction { area, depth, expected } = &f.evidence else { panic!("{f:?}") };
/// assert_eq!((area.to_string(), *depth, *expected), ("36".to_string(), 1, Orientation::Cw));
/// assert_eq!(f.evidence.kind(), Kind::Direction);
/// assert_eq!(
///     serde_json::to_string(&f.evidence).unwrap(),
///     r#"{"kind":"direction","area":"36","depth":1,"expected":"cw"}"#
/// );
/// assert_eq!(serde_json::to_string(&Evidence::Cusp).unwrap(), r#"{"kind":"cusp"}"#);
/// ```
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Evidence {
    /// A contour's orientation is wrong for its nesting depth.
    Direction {
        /// The contour's exact signed area (positive counter-clockwise, y up).
        #[serde(serialize_with = "crate::num::serial::string")]
        area: BigRational,
        /// How many other contours contain this one.
        depth: usize,
        /// The orientation expected at that depth.
        expected: Orientation,
    },
    /// A contour meets itself (the point in [`Finding::at`], the parameter on the segment
    /// [`Finding::index`] in [`Finding::parameters`]).
    SelfIntersection,
    /// Two contours cross ([`Finding::contours`]; where they meet in [`Finding::at`]).
    Overlap,
    /// Two contours meet without crossing ([`Finding::contours`]; where in [`Finding::at`]).
    Touching,
    /// A piece of outline drawn by two contours, or twice by one (its ends in [`Finding::at`]).
    OverlappingSegments {
        /// The shared pieces, one per contour (or per pass).
        shared: Vec<SharedPiece>,
    },
    /// A horizontal or vertical tangent strictly inside a segment (the point in
    /// [`Finding::at`], the parameter in [`Finding::parameters`]).
    MissingExtremum {
        /// The extreme coordinate: [`Axis::X`] at a vertical tangent, [`Axis::Y`] at a
        /// horizontal one.
        axis: Axis,
        /// How far the extreme coordinate lies beyond the range of the segment's end points
        /// (negative: inside it).
        extent: ExactValue,
    },
    /// A node that is almost, but not exactly, smooth (the node in [`Finding::at`]).
    Kink {
        /// The turn at the node in degrees (`f64`, for display; the decision is exact).
        turn_degrees_float: f64,
    },
    /// A redundant node between two lines on one line (the node in [`Finding::at`]).
    CollinearPoints,
    /// A segment of length zero (its point in [`Finding::at`]).
    ZeroLengthSegment,
    /// A curve's handle of length zero (the end point it lies on in [`Finding::at`]).
    ZeroLengthHandle,
    /// A curve of lower degree than written.
    DegenerateCurve,
    /// A cusp strictly inside a segment (the point in [`Finding::at`], the parameter in
    /// [`Finding::parameters`]).
    Cusp,
    /// A segment crossing itself (the double point in [`Finding::at`], its two parameters in
    /// [`Finding::parameters`]).
    Loop,
    /// A wrong stored bounding box: the glyph header's box against the box of the points, or
    /// the font's `head` box against the exact outline.
    Bbox {
        /// The stored box `[x_min, y_min, x_max, y_max]`.
        stored: Box<[ExactValue; 4]>,
        /// The box it should be (of the points, or of the exact outline).
        computed: Box<[ExactValue; 4]>,
    },
}

impl Evidence {
    /// The kind this evidence is of.
    ///
    /// # Example
    /// ```
    /// use casteljau::lint::{Evidence, Kind};
    /// assert_eq!(Evidence::Kink { turn_degrees_float: 2.0 }.kind(), Kind::Kink);
    /// ```
    pub fn kind(&self) -> Kind {
        match self {
            Evidence::Direction { .. } => Kind::Direction,
            Evidence::SelfIntersection => Kind::SelfIntersection,
            Evidence::Overlap => Kind::Overlap,
            Evidence::Touching => Kind::Touching,
            Evidence::OverlappingSegments { .. } => Kind::OverlappingSegments,
            Evidence::MissingExtremum { .. } => Kind::MissingExtremum,
            Evidence::Kink { .. } => Kind::Kink,
            Evidence::CollinearPoints => Kind::CollinearPoints,
            Evidence::ZeroLengthSegment => Kind::ZeroLengthSegment,
            Evidence::ZeroLengthHandle => Kind::ZeroLengthHandle,
            Evidence::DegenerateCurve => Kind::DegenerateCurve,
            Evidence::Cusp => Kind::Cusp,
            Evidence::Loop => Kind::Loop,
            Evidence::Bbox { .. } => Kind::Bbox,
        }
    }
}

/// One finding, located in its glyph: `contour` (or `contours` for a pair), `index` (the
/// segment in the contour) and `point` (the node's index among the contour's stored points,
/// see [`crate::format::PointNumbers`]), with its exact evidence: the points and parameters
/// any kind may have here, what only its kind has in [`Finding::evidence`].
///
/// JSON: `kind`, `severity`, `rounding`, `contour`, `contours`, `index`, `point`, `at`,
/// `at_float`, `parameters`, the fields of the kind's [`Evidence`], `message`; absent
/// locations are not serialized.
///
/// # Example
/// ```
/// use casteljau::lint::{Evidence, Glyph, Kind, LintOptions, lint};
/// let c = casteljau::format::parse_path("M0 0 H5 H10 V10 H0 Z", casteljau::num::NumberMode::Exact).unwrap();
/// let f = &lint(&Glyph::new(c), &LintOptions::new(casteljau::shape::Orientation::Ccw)).unwrap()[0];
/// assert_eq!((f.kind(), &f.evidence), (Kind::CollinearPoints, &Evidence::CollinearPoints));
/// assert_eq!(
///     serde_json::to_string(f).unwrap(),
///     r#"{"kind":"collinear_points","severity":"info","rounding":false,"contour":0,"index":1,"point":1,"at":[["5","0"]],"at_float":[[5.0,0.0]],"parameters":[],"message":"the node (5, 0) lies between two lines on one line: it is redundant"}"#
/// );
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Finding {
    /// What was found, with the evidence only its kind has ([`Finding::kind`] names the kind).
    pub evidence: Evidence,
    /// The severity ([`Kind::severity`], or `info` when rounding explains it).
    pub severity: Severity,
    /// Explained by rounding to the grid (see the module documentation).
    pub rounding: bool,
    /// The contour.
    pub contour: Option<usize>,
    /// The two contours of `overlap`, `touching` and `overlapping_segments` (`[i, i]` for one
    /// contour drawing a piece twice).
    pub contours: Option<[usize; 2]>,
    /// The segment in the contour (for a node: the segment that starts there).
    pub index: Option<usize>,
    /// The node's index among the contour's stored points.
    pub point: Option<usize>,
    /// Exact points: the crossing or contact points, the extremum, the node, the cusp, the
    /// loop's double point.
    pub at: Vec<[ExactValue; 2]>,
    /// `at` as `f64`s.
    pub at_float: Vec<[f64; 2]>,
    /// Exact parameters on the segment `index`.
    pub parameters: Vec<ExactValue>,
    /// One line saying what is wrong, with the figures.
    pub message: String,
}

impl Finding {
    /// A finding of the kind of `evidence`, with its default severity and no place or points
    /// yet.
    pub(crate) fn new(evidence: Evidence, message: String) -> Self {
        Finding {
            severity: evidence.kind().severity(),
            evidence,
            rounding: false,
            contour: None,
            contours: None,
            index: None,
            point: None,
            at: vec![],
            at_float: vec![],
            parameters: vec![],
            message,
        }
    }

    pub(crate) fn rounded(mut self, rounding: bool) -> Self {
        self.rounding = rounding;
        if rounding {
            self.severity = Severity::Info;
        }
        self
    }

    pub(crate) fn point_at(mut self, p: [ExactValue; 2]) -> Self {
        self.at_float.push([p[0].to_f64(), p[1].to_f64()]);
        self.at.push(p);
        self
    }

    /// The kind of the finding (of its [`Evidence`]), as `--only`, `--ignore` and `--deny`
    /// name it.
    ///
    /// # Example
    /// ```
    /// use casteljau::lint::{Glyph, Kind, LintOptions, lint};
    /// let c = casteljau::format::parse_path("M0 0 Q5 0 10 0 V10 H0 Z", casteljau::num::NumberMode::Exact).unwrap();
    /// let f = lint(&Glyph::new(c), &LintOptions::new(casteljau::shape::Orientation::Ccw)).unwrap();
    /// assert_eq!(f[0].kind(), Kind::DegenerateCurve);
    /// ```
    pub fn kind(&self) -> Kind {
        self.evidence.kind()
    }

    /// Whether this finding fails a run that denies `denied` (findings rounding explains never
    /// do).
    ///
    /// # Example
    /// ```
    /// use casteljau::lint::{Glyph, Kind, LintOptions, lint};
    /// let c = casteljau::format::parse_path("M0 0 H10 H10 V10 Z", casteljau::num::NumberMode::Exact).unwrap();
    /// let f = lint(&Glyph::new(c), &LintOptions::new(casteljau::shape::Orientation::Ccw)).unwrap();
    /// assert_eq!(f[0].kind(), Kind::ZeroLengthSegment);
    /// assert!(f[0].fails(&[Kind::ZeroLengthSegment]) && !f[0].fails(&[Kind::Kink]));
    /// ```
    pub fn fails(&self, denied: &[Kind]) -> bool {
        !self.rounding && denied.contains(&self.kind())
    }
}

/// The tag of [`Evidence`]'s JSON (its `#[serde(tag = "kind")]`), written first by a
/// [`Finding`].
const TAG: &str = "kind";

/// `kind` first, the common fields in their order, then the fields of the [`Evidence`], then
/// `message` (see [`Finding`]).
///
/// Written by hand because serde's derive cannot give this order: a flattened internally
/// tagged enum writes its tag where the enum field stands, so `kind` would follow
/// `parameters`. Only the layout is hand-written, and each field once: the common fields
/// here, the evidence's fields by [`Evidence`]'s derived `Serialize` (so its attributes stay
/// the schema of each kind), forwarded into this object, its tag left out, by a small private
/// serializer (`#[serde(flatten)]` at a chosen place).
impl Serialize for Finding {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        fn optional<M: SerializeStruct, T: Serialize>(
            m: &mut M,
            key: &'static str,
            value: &Option<T>,
        ) -> Result<(), M::Error> {
            match value {
                Some(v) => m.serialize_field(key, v),
                None => m.skip_field(key),
            }
        }
        let mut m = s.serialize_struct("Finding", 12)?;
        m.serialize_field(TAG, &self.kind())?;
        m.serialize_field("severity", &self.severity)?;
        m.serialize_field("rounding", &self.rounding)?;
        optional(&mut m, "contour", &self.contour)?;
        optional(&mut m, "contours", &self.contours)?;
        optional(&mut m, "index", &self.index)?;
        optional(&mut m, "point", &self.point)?;
        m.serialize_field("at", &self.at)?;
        m.serialize_field("at_float", &self.at_float)?;
        m.serialize_field("parameters", &self.parameters)?;
        self.evidence.serialize(Inline(&mut m))?;
        m.serialize_field("message", &self.message)?;
        m.end()
    }
}

/// A serializer that takes a struct (or an internally tagged enum's variant) and writes its
/// fields, but for the tag [`TAG`], into the struct `M` is writing.
struct Inline<'a, M>(&'a mut M);

impl<M: SerializeStruct> SerializeStruct for Inline<'_, M> {
    type Ok = ();
    type Error = M::Error;

    fn serialize_field<T: ?Sized + Serialize>(&mut self, key: &'static str, value: &T) -> Result<(), M::Error> {
        if key == TAG { Ok(()) } else { self.0.serialize_field(key, value) }
    }

    fn skip_field(&mut self, key: &'static str) -> Result<(), M::Error> {
        self.0.skip_field(key)
    }

    fn end(self) -> Result<(), M::Error> {
        Ok(())
    }
}

/// What [`Inline`] answers a value that is no struct.
fn not_a_struct<E: serde::ser::Error>() -> E {
    E::custom("only a struct's fields can be written into a struct")
}

/// The serializer methods of values that are no struct: refused.
macro_rules! no_struct {
    ($($method:ident($($arg:ty),*) -> $ok:ty;)*) => {$(
        fn $method(self, $(_: $arg),*) -> Result<$ok, M::Error> {
            Err(not_a_struct())
        }
    )*};
}

impl<'a, M: SerializeStruct> Serializer for Inline<'a, M> {
    type Ok = ();
    type Error = M::Error;
    type SerializeSeq = Impossible<(), M::Error>;
    type SerializeTuple = Impossible<(), M::Error>;
    type SerializeTupleStruct = Impossible<(), M::Error>;
    type SerializeTupleVariant = Impossible<(), M::Error>;
    type SerializeMap = Impossible<(), M::Error>;
    type SerializeStruct = Self;
    type SerializeStructVariant = Impossible<(), M::Error>;

    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Self, M::Error> {
        Ok(self)
    }

    no_struct! {
        serialize_bool(bool) -> ();
        serialize_i8(i8) -> ();
        serialize_i16(i16) -> ();
        serialize_i32(i32) -> ();
        serialize_i64(i64) -> ();
        serialize_u8(u8) -> ();
        serialize_u16(u16) -> ();
        serialize_u32(u32) -> ();
        serialize_u64(u64) -> ();
        serialize_f32(f32) -> ();
        serialize_f64(f64) -> ();
        serialize_char(char) -> ();
        serialize_str(&str) -> ();
        serialize_bytes(&[u8]) -> ();
        serialize_none() -> ();
        serialize_unit() -> ();
        serialize_unit_struct(&'static str) -> ();
        serialize_unit_variant(&'static str, u32, &'static str) -> ();
        serialize_seq(Option<usize>) -> Self::SerializeSeq;
        serialize_tuple(usize) -> Self::SerializeTuple;
        serialize_tuple_struct(&'static str, usize) -> Self::SerializeTupleStruct;
        serialize_tuple_variant(&'static str, u32, &'static str, usize) -> Self::SerializeTupleVariant;
        serialize_map(Option<usize>) -> Self::SerializeMap;
        serialize_struct_variant(&'static str, u32, &'static str, usize) -> Self::SerializeStructVariant;
    }

    fn serialize_some<T: ?Sized + Serialize>(self, _: &T) -> Result<(), M::Error> {
        Err(not_a_struct())
    }

    fn serialize_newtype_struct<T: ?Sized + Serialize>(self, _: &'static str, _: &T) -> Result<(), M::Error> {
        Err(not_a_struct())
    }

    fn serialize_newtype_variant<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: &T,
    ) -> Result<(), M::Error> {
        Err(not_a_struct())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::scalar::rat;

    /// Each variant's JSON tag is its kind's name, the name `kind` a finding writes.
    #[test]
    fn evidence_tag_is_the_kind_name() {
        let x = || ExactValue::from(rat(1));
        let four = || Box::new([x(), x(), x(), x()]);
        let all = [
            Evidence::Direction { area: rat(1), depth: 0, expected: Orientation::Ccw },
            Evidence::SelfIntersection,
            Evidence::Overlap,
            Evidence::Touching,
            Evidence::OverlappingSegments { shared: vec![] },
            Evidence::MissingExtremum { axis: Axis::X, extent: x() },
            Evidence::Kink { turn_degrees_float: 1.0 },
            Evidence::CollinearPoints,
            Evidence::ZeroLengthSegment,
            Evidence::ZeroLengthHandle,
            Evidence::DegenerateCurve,
            Evidence::Cusp,
            Evidence::Loop,
            Evidence::Bbox { stored: four(), computed: four() },
        ];
        assert_eq!(all.iter().map(Evidence::kind).collect::<Vec<_>>(), Kind::ALL);
        for e in &all {
            let json = serde_json::to_value(e).unwrap();
            assert_eq!(json["kind"], e.kind().as_str());
            let f = serde_json::to_value(Finding::new(e.clone(), String::new())).unwrap();
            for (key, value) in json.as_object().unwrap() {
                assert_eq!(&f[key], value, "{key}");
            }
        }
    }
}
