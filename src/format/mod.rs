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
pub(crate) mod svg_path;
#[cfg(feature = "svg")]
pub(crate) mod svg_tree;

#[cfg(feature = "fonts")]
pub use font::Font;
pub use scan::{Element, ScanRecord, Source};
#[cfg(feature = "svg")]
pub use svg::{ShapeProblem, SvgShape, fill_svg, read_svg};
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

#[cfg_attr(not(feature = "svg"), allow(dead_code))] // the SVG reader's charges
/// Work units of one product or sum of exact rationals of `b1` and `b2` bits ([`mul_ratio`],
/// [`add_ratio`]), with `L(b)` limbs: `300 + 60·(L(b1) + L(b2))` for the allocations and the
/// remainders that bring a gcd down to the smaller size (a remainder by a word costs a 128-bit
/// division per limb), `2·L(b1)·L(b2)` for the products and `26·L(min)²` for Stein's gcd on the
/// smaller size (fitted on this machine: 0.45 to 2.4 times the measured time on 1,000 to 6,000 nested
/// SVG `scale(1.0001)` (a big entry times a small one), 300 and 1,000 nested
/// `matrix(1.0001 0.0003 -0.0007 0.9999 1.5 2.25)` (balanced gcds), their products applied
/// to 2,000 paths).
pub(crate) fn rational_op_work(b1: u64, b2: u64) -> f64 {
    let (l1, l2, small) = (crate::work::limbs(b1), crate::work::limbs(b2), crate::work::limbs(b1.min(b2)));
    300.0 + 60.0 * (l1 + l2) + 2.0 * l1 * l2 + 26.0 * small * small
}

#[cfg_attr(not(feature = "svg"), allow(dead_code))] // the SVG reader's charges
/// The sizes of an affine map's entries, `[a b c d e f]`: 0 for a zero entry, else its bit
/// length (numerator plus denominator). Known exactly for a computed map, or estimated for one
/// that is not computed (each product's bits the sum of its factors', each sum's one more than
/// the sum of its terms').
pub(crate) type AffineSizes = [u64; 6];

impl Affine {
    #[cfg_attr(not(feature = "svg"), allow(dead_code))] // the SVG reader's charges
    /// The sizes of the entries.
    pub(crate) fn sizes(&self) -> AffineSizes {
        self.0.each_ref().map(|x| if x.numer().bits() == 0 { 0 } else { crate::work::bits(x) })
    }
}

#[cfg_attr(not(feature = "svg"), allow(dead_code))] // the SVG reader's charges
/// The work and the bits of `x y + u v` of entries of the given sizes (a zero product costs
/// nothing).
fn dot_work(x: u64, y: u64, u: u64, v: u64) -> (f64, u64) {
    let term = |p: u64, q: u64| (p != 0 && q != 0).then(|| (rational_op_work(p, q), p.saturating_add(q)));
    sum_work(term(x, y), term(u, v))
}

#[cfg_attr(not(feature = "svg"), allow(dead_code))] // the SVG reader's charges
/// The work and bits of the sum of two terms given as `(work, bits)` (`None`: a zero term).
fn sum_work(s: Option<(f64, u64)>, t: Option<(f64, u64)>) -> (f64, u64) {
    match (s, t) {
        (Some((w1, b1)), Some((w2, b2))) => {
            (w1 + w2 + rational_op_work(b1, b2), b1.saturating_add(b2).saturating_add(1))
        }
        (Some(x), None) | (None, Some(x)) => x,
        (None, None) => (0.0, 0),
    }
}

#[cfg_attr(not(feature = "svg"), allow(dead_code))] // the SVG reader's charges
/// `(work, bits)` of a term, `None` for size 0.
fn nonzero(work: f64, bits: u64) -> Option<(f64, u64)> {
    (bits != 0).then_some((work, bits))
}

#[cfg_attr(not(feature = "svg"), allow(dead_code))] // the SVG reader's charges
/// The work units of [`Affine::compose`] of maps of the given sizes, and the sizes of the
/// result (estimated).
pub(crate) fn compose_work(outer: &AffineSizes, inner: &AffineSizes) -> (f64, AffineSizes) {
    let [a, b, c, d, e, f] = *outer;
    let [a2, b2, c2, d2, e2, f2] = *inner;
    let shifted = |t: u64, (w, bits): (f64, u64)| sum_work(nonzero(w, bits), nonzero(0.0, t));
    let entries = [
        dot_work(a, a2, c, b2),
        dot_work(b, a2, d, b2),
        dot_work(a, c2, c, d2),
        dot_work(b, c2, d, d2),
        shifted(e, dot_work(a, e2, c, f2)),
        shifted(f, dot_work(b, e2, d, f2)),
    ];
    (entries.iter().map(|x| x.0).sum(), entries.map(|x| x.1))
}

#[cfg_attr(not(feature = "svg"), allow(dead_code))] // the SVG reader's charges
/// The work units of [`Affine::apply`], for a map of the given sizes, to a point whose
/// coordinates have at most `point_bits` bits (neither of them zero).
pub(crate) fn apply_work(m: &AffineSizes, point_bits: u64) -> f64 {
    let [a, b, c, d, e, f] = *m;
    let coordinate = |p: u64, q: u64, t: u64| {
        let (w, bits) = dot_work(p, point_bits, q, point_bits);
        sum_work(nonzero(w, bits), nonzero(0.0, t)).0
    };
    coordinate(a, c, e) + coordinate(b, d, f)
}
