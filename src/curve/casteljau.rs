//! De Casteljau's scheme (seed 001, (7)) and subdivision (Lemma 2).
//!
//! The scheme: `b_i^0 = b_i`, `b_i^r(t) = (1−t) b_i^{r−1}(t) + t b_{i+1}^{r−1}(t)` for
//! `r = 1..n`, `i = 0..n−r`; `b(t) = b_0^n(t)`. Lemma 2: splitting at `t0` gives two Bézier
//! curves whose control points are the triangle's boundary,
//! `b_0, b_0^1, …, b_0^n` (for `t ∈ [0, t0]`) and `b_0^n, b_1^{n−1}, …, b_n` (for `[t0, 1]`).

use crate::curve::bezier::BezierCurve;
use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::Scalar;

/// Largest depth for [`subdivide_repeatedly`] (2^depth pieces).
pub const MAX_SUBDIVISION_DEPTH: u32 = 16;

/// The whole de Casteljau triangle at one parameter: `rows[r][i] = b_i^r(t)`.
///
/// # Example
/// ```
/// use casteljau::{BezierCurve, num::parse_points, ratio};
/// let c = BezierCurve::new(parse_points("0 0, 1 2, 2 0", 2, None).unwrap()).unwrap();
/// let tri = c.triangle(&ratio(1, 2));
/// assert_eq!(tri.rows[1][0].to_string(), "(1/2, 1)");
/// assert_eq!(tri.point().to_string(), "(1, 1)");
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DeCasteljauTriangle<S> {
    /// `rows[r]` holds `b_0^r, …, b_{n−r}^r`.
    pub rows: Vec<Vec<Point<S>>>,
}

impl<S: Scalar> DeCasteljauTriangle<S> {
    /// The curve point `b_0^n(t)`.
    pub fn point(&self) -> &Point<S> {
        &self.rows.last().expect("triangle has rows")[0]
    }
    /// Control points of the left piece: `b_0^0, b_0^1, …, b_0^n` (Lemma 2).
    pub fn left_polygon(&self) -> Vec<Point<S>> {
        self.rows.iter().map(|row| row[0].clone()).collect()
    }
    /// Control points of the right piece: `b_0^n, b_1^{n−1}, …, b_n^0` (Lemma 2).
    pub fn right_polygon(&self) -> Vec<Point<S>> {
        self.rows.iter().rev().map(|row| row.last().expect("non-empty row").clone()).collect()
    }
}

/// The de Casteljau triangle of `curve` at `t` (any `t`, not only `[0, 1]`).
pub fn triangle<S: Scalar>(curve: &BezierCurve<S>, t: &S) -> DeCasteljauTriangle<S> {
    let n = curve.degree();
    let mut rows = vec![curve.points().to_vec()];
    for r in 1..=n {
        let prev = &rows[r - 1];
        let row = prev.windows(2).map(|w| w[0].lerp(&w[1], t)).collect();
        rows.push(row);
    }
    DeCasteljauTriangle { rows }
}

/// Splits `curve` at `t0` into the pieces for `[0, t0]` and `[t0, 1]`, each reparametrised
/// to `[0, 1]` (Lemma 2): `left(s) = curve(t0·s)`, `right(s) = curve(t0 + (1−t0)·s)`.
///
/// # Example
/// ```
/// use casteljau::{BezierCurve, num::parse_points, ratio};
/// let c = BezierCurve::new(parse_points("-1 -1, -1/3 1, 1/3 -1, 1 1", 2, None).unwrap()).unwrap();
/// let (l, r) = c.subdivide(&ratio(1, 3));
/// assert_eq!(l.to_string(), "-1 -1, -7/9 -1/3, -5/9 -1/9, -1/3 -1/27");
/// assert_eq!(r.eval(&ratio(0, 1)), l.eval(&ratio(1, 1)));
/// ```
pub fn subdivide<S: Scalar>(curve: &BezierCurve<S>, t0: &S) -> (BezierCurve<S>, BezierCurve<S>) {
    let tri = triangle(curve, t0);
    (BezierCurve::new(tri.left_polygon()).unwrap(), BezierCurve::new(tri.right_polygon()).unwrap())
}

/// Subdivides `depth` times, each piece at its own local parameter `t0`: `2^depth` pieces in
/// order along the curve (seed 001, Fig. 10 uses `t0 = 1/2`, depth 4). The control polygons
/// converge to the curve.
///
/// # Errors
/// [`Error::TooLarge`] for `depth > MAX_SUBDIVISION_DEPTH`.
pub fn subdivide_repeatedly<S: Scalar>(curve: &BezierCurve<S>, t0: &S, depth: u32) -> Result<Vec<BezierCurve<S>>> {
    split_repeatedly(curve, depth, |c| subdivide(c, t0))
}

/// The repetition behind [`subdivide_repeatedly`] and its fraction-free twin
/// ([`fraction_free::subdivide_repeatedly`](crate::curve::fraction_free::subdivide_repeatedly)):
/// every piece is split by `split`, `depth` times.
///
/// # Errors
/// [`Error::TooLarge`] for `depth > MAX_SUBDIVISION_DEPTH`.
pub(crate) fn split_repeatedly<S: Scalar>(
    curve: &BezierCurve<S>,
    depth: u32,
    split: impl Fn(&BezierCurve<S>) -> (BezierCurve<S>, BezierCurve<S>),
) -> Result<Vec<BezierCurve<S>>> {
    if depth > MAX_SUBDIVISION_DEPTH {
        return Err(Error::TooLarge {
            what: "subdivision depth",
            value: depth as usize,
            limit: MAX_SUBDIVISION_DEPTH as usize,
        });
    }
    let mut pieces = vec![curve.clone()];
    for _ in 0..depth {
        pieces = pieces.iter().flat_map(|c| <[_; 2]>::from(split(c))).collect();
    }
    Ok(pieces)
}

/// The parameter intervals of the pieces of [`subdivide_repeatedly`]: piece `k` covers
/// `[a_k, a_{k+1}]` of the original parameter, found by splitting each interval `[a, b]` at
/// `a + t0·(b − a)`.
pub fn subdivision_intervals<S: Scalar>(t0: &S, depth: u32) -> Vec<(S, S)> {
    let mut iv = vec![(S::zero(), S::one())];
    for _ in 0..depth {
        iv = iv
            .into_iter()
            .flat_map(|(a, b)| {
                let m = a.clone() + t0.clone() * &(b.clone() - &a);
                [(a, m.clone()), (m, b)]
            })
            .collect();
    }
    iv
}
