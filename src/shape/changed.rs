//! Whether a boolean result is its input unchanged: the question a font tool asks of every
//! simplified glyph (`casteljau boolean simplify FONT` reports it as `changed`).

use super::{BooleanResult, Shape};
use crate::poly::RealAlgebraic;
use crate::rational::RationalBezier;
use num_rational::BigRational;
use num_traits::{One, Zero};

impl BooleanResult {
    /// Whether this result differs from `shape`, the input it was computed from (input 0, as in
    /// [`super::BooleanOp::Simplify`]): `false` exactly when the result is `shape`'s outline
    /// itself — as many contours as `shape`, each made of the segments of one of `shape`'s
    /// contours (each contour used once), every segment as a whole `[0, 1]` piece run forwards,
    /// in the contour's cyclic order from any start. Zero-length segments (every control point
    /// the same), which bound nothing, are left out of the comparison.
    ///
    /// So an outline that is already the boundary of its fill, with its outer contours in the
    /// requested [`super::Orientation`], is unchanged; an overlap removed, a contour reversed, a
    /// segment cut at a crossing, or a piece of another input are changes. The decision is
    /// exact: it compares the result's [`super::InputPiece`]s, whose ends are exact.
    ///
    /// # Example
    /// ```
    /// use casteljau::shape::{BooleanOp, BooleanOptions, Orientation, Shape, boolean};
    /// let simplify = |s: &Shape, orientation| {
    ///     let options = BooleanOptions { orientation, ..BooleanOptions::default() };
    ///     boolean(BooleanOp::Simplify, std::slice::from_ref(s), options, &casteljau::work::Budget::unlimited()).unwrap()
    /// };
    /// // a counter-clockwise square with a clockwise hole, a zero-length segment (H4) included
    /// let framed: Shape = "M0 0 H4 H4 V4 H0 Z M1 1 V3 H3 V1 Z".parse().unwrap();
    /// assert!(!simplify(&framed, Orientation::Ccw).changes(&framed));
    /// // asked for clockwise outer contours, every contour is reversed
    /// assert!(simplify(&framed, Orientation::Cw).changes(&framed));
    /// // two overlapping squares become one contour
    /// let overlap: Shape = "M0 0 H2 V2 H0 Z M1 1 H3 V3 H1 Z".parse().unwrap();
    /// assert!(simplify(&overlap, Orientation::Ccw).changes(&overlap));
    /// ```
    pub fn changes(&self, shape: &Shape) -> bool {
        let contours = shape.path().contours();
        if self.contours != contours.len() || self.pieces.len() != contours.len() {
            return true;
        }
        let (zero, one) = (RealAlgebraic::from(BigRational::zero()), RealAlgebraic::from(BigRational::one()));
        let mut used = vec![false; contours.len()];
        for pieces in &self.pieces {
            let Some(k) = pieces.first().map(|p| p.contour) else { return true };
            if k >= contours.len() || used[k] {
                return true;
            }
            used[k] = true;
            if pieces.iter().any(|p| p.input != 0 || p.contour != k || p.from != zero || p.to != one) {
                return true;
            }
            // the contour's segments that bound something, in order
            let own: Vec<usize> = (0..contours[k].len()).filter(|&i| !is_point(&contours[k][i])).collect();
            let got: Vec<usize> = pieces.iter().map(|p| p.segment).collect();
            if own.len() != got.len() {
                return true;
            }
            let Some(shift) = own.iter().position(|&s| s == got[0]) else { return true };
            if (0..own.len()).any(|i| own[(i + shift) % own.len()] != got[i]) {
                return true;
            }
        }
        false
    }
}

/// Whether every control point of a segment is the same point (a segment of zero length).
fn is_point(segment: &RationalBezier<BigRational>) -> bool {
    let ps = segment.points();
    ps.iter().all(|p| p == &ps[0])
}
