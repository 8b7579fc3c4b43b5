//! The records of a scan of users' files (`casteljau scan`): one per segment of every outline,
//! with where it comes from, its exact control points, classification and
//! [`SegmentFlag`]s; or a piece that was skipped, or a unit that could not be read. Serialized
//! as flat JSON objects (JSON Lines): the [`Source`] fields, `index`, then the variant's fields.
//!
//! # Example
//! ```
//! use casteljau::classify::classify;
//! use casteljau::format::{ScanRecord, Source};
//! use casteljau::{BezierCurve, num::parse_points};
//! let ps = parse_points("0 0, 1 1", 2, None).unwrap();
//! let k = classify(&BezierCurve::new(ps.clone()).unwrap()).unwrap();
//! let at = Source { line: Some(3), ..Source::new("curves.txt") };
//! let r = ScanRecord::Segment { at: &at, index: 0, classification: &k, points: &ps, flags: k.segment_flags(&ps) };
//! let json = serde_json::to_string(&r).unwrap();
//! assert!(json.starts_with(r#"{"file":"curves.txt","line":3,"index":0,"degree":1,"#));
//! assert!(json.ends_with(r#""points":[["0","0"],["1","1"]],"flags":[]}"#));
//! ```

use crate::classify::{Classification, SegmentFlag};
use crate::num::point::Point;
use num_rational::BigRational;
use serde::Serialize;

/// An SVG shape element: its `id`, or its 0-based index among the shape elements.
///
/// # Example
/// ```
/// use casteljau::format::Element;
/// assert_eq!(serde_json::to_string(&Element::Id("logo".into())).unwrap(), r#""logo""#);
/// assert_eq!(serde_json::to_string(&Element::Index(4)).unwrap(), "4");
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
#[serde(untagged)]
pub enum Element {
    /// The element's `id` attribute.
    Id(String),
    /// Its index among the shape elements of the document.
    Index(usize),
}

/// Where a segment comes from: the file, and (by the kind of file) the face, glyph and contour
/// of a font, the element, tag and subpath of an SVG document, or the line of a text batch.
/// Absent fields are not serialized.
///
/// # Example
/// ```
/// use casteljau::format::{Element, Source};
/// let at = Source { element: Some(Element::Index(0)), subpath: Some(1), ..Source::new("<path>") };
/// assert_eq!(serde_json::to_string(&at).unwrap(), r#"{"file":"<path>","element":0,"subpath":1}"#);
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Source<'a> {
    /// The file as named by the user.
    pub file: &'a str,
    /// The face of a font collection.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub face: Option<u32>,
    /// A font glyph's name (`Some(None)`: a glyph without a name, `null`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub glyph: Option<Option<String>>,
    /// A font glyph's id.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub glyph_id: Option<u32>,
    /// The contour of a glyph (0-based).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contour: Option<usize>,
    /// The SVG element.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub element: Option<Element>,
    /// The SVG element's tag.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tag: Option<String>,
    /// The subpath of an SVG element (0-based).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub subpath: Option<usize>,
    /// The line of a text batch (1-based).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub line: Option<usize>,
}

impl<'a> Source<'a> {
    /// A source in `file`, every other field absent.
    ///
    /// # Example
    /// ```
    /// use casteljau::format::Source;
    /// assert_eq!(Source::new("a.ttf").file, "a.ttf");
    /// ```
    pub fn new(file: &'a str) -> Self {
        Source { file, ..Default::default() }
    }
}

/// One record of a scan: a classified segment, a skipped piece, or an error.
///
/// # Example
/// ```
/// use casteljau::format::{ScanRecord, Source};
/// let at = Source::new("a.svg");
/// let r = ScanRecord::Error { at: &at, index: None, error: "line 3: bad path".into() };
/// assert_eq!(serde_json::to_string(&r).unwrap(), r#"{"file":"a.svg","error":"line 3: bad path"}"#);
/// ```
#[derive(Clone, Debug, Serialize)]
#[serde(untagged)]
pub enum ScanRecord<'a> {
    /// A polynomial Bézier segment and what classification found.
    Segment {
        /// Where it comes from.
        #[serde(flatten)]
        at: &'a Source<'a>,
        /// Its place in its contour, subpath or line.
        index: usize,
        /// The fields of `classify --json`.
        #[serde(flatten)]
        classification: &'a Classification,
        /// The exact control points.
        points: &'a [Point<BigRational>],
        /// Its flags.
        flags: Vec<SegmentFlag>,
    },
    /// A piece that is no polynomial Bézier curve (an SVG arc), or an element that is not read.
    Skipped {
        /// Where it comes from.
        #[serde(flatten)]
        at: &'a Source<'a>,
        /// Its place in its subpath (absent for a whole element).
        #[serde(skip_serializing_if = "Option::is_none")]
        index: Option<usize>,
        /// Why it was skipped.
        skipped: &'a str,
        /// Where the piece starts.
        #[serde(skip_serializing_if = "Option::is_none")]
        from: Option<&'a Point<BigRational>>,
        /// Where it ends.
        #[serde(skip_serializing_if = "Option::is_none")]
        to: Option<&'a Point<BigRational>>,
    },
    /// A unit (glyph, element, line) or segment that could not be read or classified.
    Error {
        /// Where it comes from.
        #[serde(flatten)]
        at: &'a Source<'a>,
        /// The segment's place, when one segment failed.
        #[serde(skip_serializing_if = "Option::is_none")]
        index: Option<usize>,
        /// What went wrong.
        error: String,
    },
}
