//! Users' files read into exact Bézier segments: SVG path data ([`parse_path`]) and SVG documents
//! (`read_svg`, feature `svg`), TrueType and CFF fonts (`Font`, feature `fonts`). The edge layer: it depends on the numbers and
//! curves below it and nothing depends on it; readers never round — a number that cannot be
//! taken exactly is an error or a skipped piece with its reason, never an approximation.
//!
//! Every reader produces [`Contour`]s of [`Segment`]s: polynomial Bézier pieces of degree 1–3 with
//! exact control points, or pieces that are not polynomial Bézier curves (elliptical arcs) kept
//! in place as [`Segment::Skipped`] with their endpoints and the reason, so that every piece of
//! every outline is listed.

#[cfg(feature = "fonts")]
pub(crate) mod font;
pub(crate) mod scan;
#[cfg(feature = "svg")]
pub(crate) mod svg;
#[cfg(feature = "svg")]
pub(crate) mod svg_element;
pub(crate) mod svg_path;
#[cfg(feature = "svg")]
pub(crate) mod svg_tree;

#[cfg(feature = "fonts")]
pub use font::Font;
pub use scan::{Element, ScanRecord, Source};
#[cfg(feature = "svg")]
pub use svg::{fill_svg, read_svg};
#[cfg(feature = "svg")]
pub use svg_element::{ShapeProblem, SvgShape};
pub use svg_path::{fill_path, parse_path};

/// Per segment of a contour, per control point, the index of that point among the contour's
/// stored points (`None`: a point the format implies, such as TrueType's on-curve midpoint
/// between two off-curve points).
pub type PointNumbers = Vec<Vec<Option<usize>>>;

/// A glyph's contours with the numbering of their stored points ([`PointNumbers`], one per
/// contour) and the points of its one-point contours, which draw nothing (`Font::outline_numbered`,
/// feature `fonts`).
///
/// # Example
/// ```
/// use casteljau::format::{NumberedOutline, parse_path, point_numbers};
/// let contours = parse_path("M0 0 H2 V2 Z", casteljau::num::NumberMode::Exact).unwrap();
/// let numbers = contours.iter().map(point_numbers).collect();
/// let o = NumberedOutline { contours, numbers, lone_points: vec![] };
/// assert_eq!(o.numbers[0][2], [Some(2), Some(0)]); // the closing line ends on point 0
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct NumberedOutline {
    /// The contours.
    pub contours: Vec<Contour>,
    /// Per contour, the stored point numbers of every control point.
    pub numbers: Vec<PointNumbers>,
    /// The points of contours of one point.
    pub lone_points: Vec<Point<BigRational>>,
}

/// The numbering of a contour whose points are all stored, in drawing order: the first
/// segment's start is 0, every later control and end point takes the next number, and a closed
/// contour's last segment ends at 0 when it ends on the start point (CFF charstrings, SVG path
/// data).
///
/// # Example
/// ```
/// use casteljau::format::{parse_path, point_numbers};
/// let c = &parse_path("M0 0 L10 0 C10 5 5 10 0 10 Z", casteljau::num::NumberMode::Exact).unwrap()[0];
/// // the line, the cubic and the closing line back to the start
/// assert_eq!(point_numbers(c), [vec![Some(0), Some(1)], vec![Some(1), Some(2), Some(3), Some(4)], vec![Some(4), Some(0)]]);
/// ```
pub fn point_numbers(c: &Contour) -> PointNumbers {
    let mut next = 0usize;
    // (a segment without points, which no reader makes, numbers as none)
    let start = c.segments.first().and_then(|s| match s {
        Segment::Bezier(ps) => ps.first().cloned(),
        Segment::Skipped { from, .. } => Some(from.clone()),
    });
    let last = c.segments.len().saturating_sub(1);
    c.segments
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let count = match s {
                Segment::Bezier(ps) => ps.len(),
                Segment::Skipped { .. } => 2,
            };
            let end = match s {
                Segment::Bezier(ps) => ps.last().cloned(),
                Segment::Skipped { to, .. } => Some(to.clone()),
            };
            let mut numbers = vec![Some(next)];
            for k in 1..count {
                if k + 1 == count && i == last && c.closed && end == start {
                    numbers.push(Some(0));
                } else {
                    next += 1;
                    numbers.push(Some(next));
                }
            }
            numbers
        })
        .collect()
}

use crate::num::point::Point;
use num_rational::BigRational;

/// One piece of an outline.
#[derive(Clone, Debug, PartialEq)]
pub enum Segment {
    /// A polynomial Bézier segment: 2, 3 or 4 exact control points (a line, a quadratic or a
    /// cubic).
    Bezier(Vec<Point<BigRational>>),
    /// A piece that is not a polynomial Bézier curve and is not approximated: its exact ends and
    /// why it was skipped.
    Skipped {
        /// Where the piece starts.
        from: Point<BigRational>,
        /// Where it ends.
        to: Point<BigRational>,
        /// What it is and why it is not converted (e.g. an elliptical arc).
        reason: String,
    },
}

/// A contour (font) or subpath (SVG): its pieces in drawing order, including the closing line
/// when the outline is closed and the closing line has non-zero length.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Contour {
    /// The pieces, in order.
    pub segments: Vec<Segment>,
    /// Closed (`Z`, or every font contour).
    pub closed: bool,
}

/// An exact planar affine map `(x, y) ↦ (a x + c y + e, b x + d y + f)`, the SVG matrix
/// `[a b c d e f]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Affine(pub [BigRational; 6]);

impl Affine {
    /// The identity map.
    pub fn identity() -> Self {
        let (o, z) = (crate::num::scalar::rat(1), crate::num::scalar::rat(0));
        Affine([o.clone(), z.clone(), z.clone(), o, z.clone(), z])
    }

    /// `self ∘ inner`: first `inner`, then `self` (an SVG parent's transform composed with its
    /// child's: `parent.compose(child)`). Zero entries cost nothing, and the products cancel
    /// common factors through one big remainder where the sizes differ (a deep chain of small
    /// scales composes in time linear in the size of its numbers).
    pub fn compose(&self, inner: &Affine) -> Affine {
        let [a, b, c, d, e, f] = &self.0;
        let [a2, b2, c2, d2, e2, f2] = &inner.0;
        Affine([
            dot(a, a2, c, b2),
            dot(b, a2, d, b2),
            dot(a, c2, c, d2),
            dot(b, c2, d, d2),
            add_ratio(&dot(a, e2, c, f2), e),
            add_ratio(&dot(b, e2, d, f2), f),
        ])
    }

    /// The image of a point.
    pub fn apply(&self, p: &Point<BigRational>) -> Point<BigRational> {
        let [a, b, c, d, e, f] = &self.0;
        let (x, y) = (&p.coords[0], &p.coords[1]);
        Point::new(vec![add_ratio(&dot(a, x, c, y), e), add_ratio(&dot(b, x, d, y), f)])
    }

    /// The image of a segment (affine maps take Bézier control points to control points, so
    /// the image is exact).
    pub fn apply_segment(&self, s: &Segment) -> Segment {
        match s {
            Segment::Bezier(ps) => Segment::Bezier(ps.iter().map(|p| self.apply(p)).collect()),
            Segment::Skipped { from, to, reason } => {
                Segment::Skipped { from: self.apply(from), to: self.apply(to), reason: reason.clone() }
            }
        }
    }
}

/// `p q + r s`, exactly.
fn dot(p: &BigRational, q: &BigRational, r: &BigRational, s: &BigRational) -> BigRational {
    add_ratio(&mul_ratio(p, q), &mul_ratio(r, s))
}

use crate::num::word::{add_ratio, mul_ratio};
