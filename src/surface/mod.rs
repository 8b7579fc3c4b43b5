//! Rational tensor-product Bézier patches (seed 002 §4, (33)–(49)), exact.
//!
//! `S(u, v) = Σ_i Σ_j B_i^m(u) B_j^n(v) w_ij P_ij / Σ_i Σ_j B_i^m(u) B_j^n(v) w_ij` ((41)–(42)),
//! stored as a grid of homogeneous points `(w_ij P_ij, w_ij)`, row `i` (the `u` index), column
//! `j` (the `v` index). Three evaluations agree exactly: the closed form, rational de Casteljau
//! in `u` then `v`, and in `v` then `u` — the tensor-product statement (44)–(47).

pub(crate) mod exact;

pub use exact::{ParameterAxis, PatchContour, PatchSplit};

use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::Scalar;
use crate::proof::Reading;
use crate::rational::rational_bezier::{RationalBezier, divide};
use num_rational::BigRational;

/// A rational Bézier patch of degree `(m, n)`.
///
/// # Invariants
/// `m + 1` rows of `n + 1` homogeneous points each, all of one dimension ≥ 2, none zero.
///
/// # Example
/// ```
/// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
/// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
/// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
/// let s = RationalPatch::new(
///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
///     vec![vec![rat(1); 3], vec![rat(1); 3]],
/// ).unwrap();
/// let (u, v) = (ratio(1, 3), ratio(1, 2));
/// assert_eq!(s.degree(), (1, 2));
/// assert_eq!(s.eval(&u, &v).unwrap().to_string(), "(1, 1/3, 1/2)");
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RationalPatch {
    rows: Vec<Vec<Point<BigRational>>>,
}

/// Largest patch degree in either direction.
pub(crate) const MAX_PATCH_DEGREE: usize = 64;

impl RationalPatch {
    /// A patch from `(m+1)×(n+1)` points (row-major) and weights.
    ///
    /// # Errors
    /// [`Error::WeightCount`] for a row whose weights and points differ in number (naming the
    /// row), [`Error::ZeroWeight`] for a zero weight (naming its row and place),
    /// [`Error::InvalidArgument`] for ragged rows or unequal numbers of rows, [`Error::TooLarge`]
    /// for degrees above 64 (`MAX_PATCH_DEGREE`).
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
    /// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
    /// let s = RationalPatch::new(
    ///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
    ///     vec![vec![rat(1); 3], vec![rat(1); 3]],
    /// ).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(1, 2));
    /// assert!(RationalPatch::new(vec![vec![p(0, 0, 0)]], vec![vec![rat(0)]]).is_err()); // a weight 0
    /// ```
    pub fn new(points: Vec<Vec<Point<BigRational>>>, weights: Vec<Vec<BigRational>>) -> Result<Self> {
        let bad = |m: String| Error::InvalidArgument { message: m };
        if points.len() != weights.len() {
            return Err(bad(format!("{} rows of weights for {} rows of control points", weights.len(), points.len())));
        }
        if let Some((r, (p, w))) = points.iter().zip(&weights).enumerate().find(|(_, (p, w))| p.len() != w.len()) {
            return Err(Error::WeightCount { weights: w.len(), points: p.len(), row: Some(r + 1) });
        }
        for (r, w) in weights.iter().enumerate() {
            if let Some(i) = w.iter().position(Scalar::is_zero) {
                return Err(Error::ZeroWeight { index: i + 1, row: Some(r + 1) });
            }
        }
        Self::from_homogeneous(
            points
                .iter()
                .zip(&weights)
                .map(|(p, w)| {
                    p.iter().zip(w).map(|(p, w)| crate::rational::rational_bezier::weighted_homogeneous(p, w)).collect()
                })
                .collect(),
        )
    }

    /// A patch from homogeneous points.
    ///
    /// # Errors
    /// As [`Self::new`].
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
    /// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
    /// let s = RationalPatch::new(
    ///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
    ///     vec![vec![rat(1); 3], vec![rat(1); 3]],
    /// ).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(1, 2));
    /// assert_eq!(RationalPatch::from_homogeneous(s.homogeneous().to_vec()).unwrap(), s);
    /// ```
    pub fn from_homogeneous(rows: Vec<Vec<Point<BigRational>>>) -> Result<Self> {
        let bad = |m: String| Error::InvalidArgument { message: m };
        let cols = rows.first().map_or(0, Vec::len);
        if rows.is_empty() || cols == 0 || rows.iter().any(|r| r.len() != cols) {
            return Err(bad("a patch needs (m+1) rows of (n+1) points".into()));
        }
        if rows.len() - 1 > MAX_PATCH_DEGREE || cols - 1 > MAX_PATCH_DEGREE {
            return Err(Error::TooLarge {
                what: "patch degree",
                value: (rows.len() - 1).max(cols - 1),
                limit: MAX_PATCH_DEGREE,
            });
        }
        let dim = rows[0][0].dim();
        if dim < 2 || rows.iter().flatten().any(|p| p.dim() != dim || p.coords.iter().all(Scalar::is_zero)) {
            return Err(bad("homogeneous points of one dimension, none zero".into()));
        }
        Ok(RationalPatch { rows })
    }

    /// The degrees `(m, n)`.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
    /// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
    /// let s = RationalPatch::new(
    ///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
    ///     vec![vec![rat(1); 3], vec![rat(1); 3]],
    /// ).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(1, 2));
    /// assert_eq!(s.degree(), (1, 2));
    /// ```
    pub fn degree(&self) -> (usize, usize) {
        (self.rows.len() - 1, self.rows[0].len() - 1)
    }
    /// The dimension of the patch's points.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
    /// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
    /// let s = RationalPatch::new(
    ///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
    ///     vec![vec![rat(1); 3], vec![rat(1); 3]],
    /// ).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(1, 2));
    /// assert_eq!(s.dim(), 3);
    /// ```
    pub fn dim(&self) -> usize {
        self.rows[0][0].dim() - 1
    }
    /// The homogeneous control net, row `i` = `u` index.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
    /// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
    /// let s = RationalPatch::new(
    ///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
    ///     vec![vec![rat(1); 3], vec![rat(1); 3]],
    /// ).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(1, 2));
    /// assert_eq!(s.homogeneous()[0][1].to_string(), "(1, 0, 1, 1)"); // (w·P, w)
    /// ```
    pub fn homogeneous(&self) -> &[Vec<Point<BigRational>>] {
        &self.rows
    }
    /// The weights `w_ij`.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
    /// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
    /// let s = RationalPatch::new(
    ///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
    ///     vec![vec![rat(1); 3], vec![rat(1); 3]],
    /// ).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(1, 2));
    /// assert_eq!(s.weights(), vec![vec![rat(1); 3]; 2]);
    /// ```
    pub fn weights(&self) -> Vec<Vec<BigRational>> {
        self.rows.iter().map(|r| r.iter().map(|p| p.coords[self.dim()].clone()).collect()).collect()
    }
    fn column(&self, j: usize) -> Vec<Point<BigRational>> {
        self.rows.iter().map(|r| r[j].clone()).collect()
    }
    fn curve(points: Vec<Point<BigRational>>) -> RationalBezier<BigRational> {
        RationalBezier::from_homogeneous(points).expect("patch points are valid homogeneous points")
    }

    /// The homogeneous point `Σ Σ B_i(u) B_j(v) (w_ij P_ij, w_ij)`.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
    /// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
    /// let s = RationalPatch::new(
    ///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
    ///     vec![vec![rat(1); 3], vec![rat(1); 3]],
    /// ).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(1, 2));
    /// assert_eq!(s.eval_homogeneous(&u, &v).to_string(), "(1, 1/3, 1/2, 1)");
    /// ```
    pub fn eval_homogeneous(&self, u: &BigRational, v: &BigRational) -> Point<BigRational> {
        let (m, n) = self.degree();
        let (bu, bv) = (crate::poly::bernstein::bernstein_all(m, u), crate::poly::bernstein::bernstein_all(n, v));
        let mut acc = Point::origin(self.dim() + 1);
        for (i, row) in self.rows.iter().enumerate() {
            for (j, p) in row.iter().enumerate() {
                acc = acc.add(&p.scale(&(bu[i].clone() * &bv[j])));
            }
        }
        acc
    }

    /// `S(u, v)` by the closed form (41).
    ///
    /// # Errors
    /// [`Error::WeightsVanish`] where `W_00(u, v; m, n) = 0`.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
    /// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
    /// let s = RationalPatch::new(
    ///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
    ///     vec![vec![rat(1); 3], vec![rat(1); 3]],
    /// ).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(1, 2));
    /// assert_eq!(s.eval(&u, &v).unwrap().to_string(), "(1, 1/3, 1/2)"); // (2v, u, 2v(1 − v))
    /// ```
    pub fn eval(&self, u: &BigRational, v: &BigRational) -> Result<Point<BigRational>> {
        self.eval_homogeneous(u, v).from_homogeneous().ok_or_else(|| Error::WeightsVanish {
            interval: (format!("(u, v) = ({u}, {v})"), format!("(u, v) = ({u}, {v})")),
        })
    }

    /// `S(u, v)` by rational de Casteljau on each column in `u` (the curves `r_j(u)` of (45),
    /// with weights `(1−u+uE)^m w_0j`), then on the resulting points in `v` (47).
    ///
    /// # Errors
    /// [`Error::WeightsVanish`] when an intermediate weight vanishes.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
    /// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
    /// let s = RationalPatch::new(
    ///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
    ///     vec![vec![rat(1); 3], vec![rat(1); 3]],
    /// ).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(1, 2));
    /// assert_eq!(s.eval_u_then_v(&u, &v).unwrap(), s.eval(&u, &v).unwrap());
    /// ```
    pub fn eval_u_then_v(&self, u: &BigRational, v: &BigRational) -> Result<Point<BigRational>> {
        let (m, n) = self.degree();
        let (pts, ws): (Vec<_>, Vec<_>) = (0..=n)
            .map(|j| {
                let c = Self::curve(self.column(j));
                Ok((c.eval_rational_de_casteljau(u)?, c.shifted_weight(0, m, u)))
            })
            .collect::<Result<Vec<_>>>()?
            .into_iter()
            .unzip();
        RationalBezier::new(pts, ws)?.eval_rational_de_casteljau(v)
    }

    /// `S(u, v)` by rational de Casteljau on each row in `v`, then in `u`.
    ///
    /// # Errors
    /// As [`Self::eval_u_then_v`].
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
    /// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
    /// let s = RationalPatch::new(
    ///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
    ///     vec![vec![rat(1); 3], vec![rat(1); 3]],
    /// ).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(1, 2));
    /// assert_eq!(s.eval_v_then_u(&u, &v).unwrap(), s.eval(&u, &v).unwrap());
    /// ```
    pub fn eval_v_then_u(&self, u: &BigRational, v: &BigRational) -> Result<Point<BigRational>> {
        let (m, n) = self.degree();
        let (pts, ws): (Vec<_>, Vec<_>) = (0..=m)
            .map(|i| {
                let c = Self::curve(self.rows[i].clone());
                Ok((c.eval_rational_de_casteljau(v)?, c.shifted_weight(0, n, v)))
            })
            .collect::<Result<Vec<_>>>()?
            .into_iter()
            .unzip();
        RationalBezier::new(pts, ws)?.eval_rational_de_casteljau(u)
    }

    /// The iso-parameter curve `v ↦ S(u0, v)` as a rational Bézier curve of degree `n`.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
    /// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
    /// let s = RationalPatch::new(
    ///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
    ///     vec![vec![rat(1); 3], vec![rat(1); 3]],
    /// ).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(1, 2));
    /// assert_eq!(s.iso_u(&u).unwrap().eval(&v).unwrap(), s.eval(&u, &v).unwrap());
    /// ```
    pub fn iso_u(&self, u0: &BigRational) -> Result<RationalBezier<BigRational>> {
        let n = self.degree().1;
        RationalBezier::from_homogeneous((0..=n).map(|j| Self::curve(self.column(j)).eval_homogeneous(u0)).collect())
    }

    /// The iso-parameter curve `u ↦ S(u, v0)` as a rational Bézier curve of degree `m`.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
    /// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
    /// let s = RationalPatch::new(
    ///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
    ///     vec![vec![rat(1); 3], vec![rat(1); 3]],
    /// ).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(1, 2));
    /// assert_eq!(s.iso_v(&v).unwrap().eval(&u).unwrap(), s.eval(&u, &v).unwrap());
    /// ```
    pub fn iso_v(&self, v0: &BigRational) -> Result<RationalBezier<BigRational>> {
        RationalBezier::from_homogeneous(
            self.rows.iter().map(|r| Self::curve(r.clone()).eval_homogeneous(v0)).collect(),
        )
    }

    /// Splits at `u0`: the patches for `u ∈ [0, u0]` and `[u0, 1]` (every column subdivided).
    pub(crate) fn subdivide_u(&self, u0: &BigRational) -> Result<(Self, Self)> {
        let (a, b) = self.transpose().subdivide_v(u0)?;
        Ok((a.transpose(), b.transpose()))
    }

    /// Splits at `v0` (every row subdivided).
    pub(crate) fn subdivide_v(&self, v0: &BigRational) -> Result<(Self, Self)> {
        let halves: Vec<_> = self
            .rows
            .iter()
            .map(|r| crate::curve::casteljau::subdivide(Self::curve(r.clone()).homogeneous(), v0))
            .collect();
        Ok((
            RationalPatch::from_homogeneous(halves.iter().map(|h| h.0.points().to_vec()).collect())?,
            RationalPatch::from_homogeneous(halves.iter().map(|h| h.1.points().to_vec()).collect())?,
        ))
    }

    /// The transposed patch (`u` and `v` exchanged).
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
    /// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
    /// let s = RationalPatch::new(
    ///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
    ///     vec![vec![rat(1); 3], vec![rat(1); 3]],
    /// ).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(1, 2));
    /// assert_eq!(s.transpose().eval(&v, &u).unwrap(), s.eval(&u, &v).unwrap());
    /// ```
    pub fn transpose(&self) -> Self {
        let n = self.degree().1;
        RationalPatch { rows: (0..=n).map(|j| self.column(j)).collect() }
    }

    /// Degree elevation by `ru` in `u` and `rv` in `v`.
    ///
    /// # Errors
    /// [`Error::TooLarge`] beyond 64 (`MAX_PATCH_DEGREE`).
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
    /// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
    /// let s = RationalPatch::new(
    ///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
    ///     vec![vec![rat(1); 3], vec![rat(1); 3]],
    /// ).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(1, 2));
    /// let e = s.elevate(1, 1).unwrap();
    /// assert_eq!(e.degree(), (2, 3));
    /// assert_eq!(e.eval(&u, &v).unwrap(), s.eval(&u, &v).unwrap());
    /// ```
    pub fn elevate(&self, ru: usize, rv: usize) -> Result<Self> {
        let (m, n) = self.degree();
        if m + ru > MAX_PATCH_DEGREE || n + rv > MAX_PATCH_DEGREE {
            return Err(Error::TooLarge { what: "patch degree", value: (m + ru).max(n + rv), limit: MAX_PATCH_DEGREE });
        }
        // homogeneous elevation of every row, then every column; an intermediate point may be
        // zero (weights of opposite signs cancelling), the result is validated once at the end
        let elevate = |pts: Vec<Point<BigRational>>, r: usize| -> Result<Vec<Point<BigRational>>> {
            Ok(crate::curve::bezier::BezierCurve::new(pts)?.elevate(r)?.points().to_vec())
        };
        let rows: Vec<Vec<Point<BigRational>>> =
            self.rows.iter().map(|r| elevate(r.clone(), rv)).collect::<Result<_>>()?;
        let cols: Vec<Vec<Point<BigRational>>> = (0..rows[0].len())
            .map(|j| elevate(rows.iter().map(|r| r[j].clone()).collect(), ru))
            .collect::<Result<_>>()?;
        Ok(RationalPatch::from_homogeneous(cols)?.transpose())
    }

    /// Weight change (48)–(49): `S'(u, v) = 𝒲[γ_i(u) γ_j(v) Δw : W_00(u, v)](S(u, v), P_ij)` with
    /// `γ` the Bernstein polynomial `B_i^m(u)` ([`Reading::Corrected`]) or the seed's
    /// `C(m,i)(1−u)^i u^{m−i}` ([`Reading::AsPrinted`]).
    ///
    /// # Errors
    /// [`Error::WeightsVanish`] where the patch is undefined; a point at infinity.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
    /// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
    /// let s = RationalPatch::new(
    ///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
    ///     vec![vec![rat(1); 3], vec![rat(1); 3]],
    /// ).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(1, 2));
    /// use casteljau::proof::Reading;
    /// let changed = s.with_weight_change(1, 1, &rat(2)).unwrap().eval(&u, &v).unwrap();
    /// assert_eq!(s.weight_change(1, 1, &rat(2), &u, &v, Reading::Corrected).unwrap(), changed);
    /// assert_ne!(s.weight_change(1, 1, &rat(2), &u, &v, Reading::AsPrinted).unwrap(), changed);
    /// ```
    pub fn weight_change(
        &self,
        i: usize,
        j: usize,
        dw: &BigRational,
        u: &BigRational,
        v: &BigRational,
        reading: Reading,
    ) -> Result<Point<BigRational>> {
        let (m, n) = self.degree();
        let gamma = |k: usize, d: usize, x: &BigRational| {
            if reading == Reading::AsPrinted {
                crate::poly::bernstein::binomial_scalar::<BigRational>(d, k)
                    * crate::poly::bernstein::pow(&(crate::num::scalar::rat(1) - x), k)
                    * crate::poly::bernstein::pow(x, d - k)
            } else {
                crate::poly::bernstein::bernstein(k, d, x)
            }
        };
        let s = self.eval(u, v)?;
        let w00 = self.eval_homogeneous(u, v).coords[self.dim()].clone();
        let p = self.rows[i][j]
            .from_homogeneous()
            .ok_or_else(|| Error::PointAtInfinity { message: "point at infinity".into() })?;
        divide(&(gamma(i, m, u) * gamma(j, n, v) * dw), &w00, &s, &p)
            .ok_or_else(|| Error::WeightsVanish { interval: (u.to_string(), v.to_string()) })
    }

    /// The patch with `w_ij` increased by `dw` (the point `P_ij` kept).
    ///
    /// # Errors
    /// For a point at infinity or a resulting zero weight.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, surface::RationalPatch};
    /// # let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
    /// let s = RationalPatch::new(
    ///     vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
    ///     vec![vec![rat(1); 3], vec![rat(1); 3]],
    /// ).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(1, 2));
    /// assert_eq!(s.with_weight_change(0, 1, &rat(2)).unwrap().weights()[0], vec![rat(1), rat(3), rat(1)]);
    /// ```
    pub fn with_weight_change(&self, i: usize, j: usize, dw: &BigRational) -> Result<Self> {
        let mut rows = self.rows.clone();
        let d = self.dim();
        let p = rows[i][j]
            .from_homogeneous()
            .ok_or_else(|| Error::PointAtInfinity { message: "point at infinity".into() })?;
        let w = rows[i][j].coords[d].clone() + dw;
        if w.is_zero() {
            return Err(Error::InvalidArgument {
                message: format!(
                    "the new weight {} of row {} (w{i}{j}) is 0: {} + {dw}",
                    j + 1,
                    i + 1,
                    rows[i][j].coords[d]
                ),
            });
        }
        rows[i][j] = p.to_homogeneous(&w);
        Ok(RationalPatch { rows })
    }

    /// The contour `z = c` (seed 002 Figs. 9, 13) as an implicit curve in `(u, v)`: the Bernstein
    /// coefficients `w_ij (z_ij − c)` of the polynomial `F(u, v) = Σ Σ B_i(u) B_j(v) w_ij (z_ij − c)`
    /// of degree `(m, n)`, whose zero set in `[0,1]²` (where `W ≠ 0`) is the contour. `axis` picks
    /// the coordinate (`2` = z).
    pub(crate) fn contour_polynomial(&self, axis: usize, c: &BigRational) -> Vec<Vec<BigRational>> {
        let d = self.dim();
        self.rows
            .iter()
            .map(|r| r.iter().map(|h| h.coords[axis].clone() - c.clone() * &h.coords[d]).collect())
            .collect()
    }

    /// Sampled contour of [`Self::contour_polynomial`] for plots: segments in `(u, v)` from a
    /// marching-squares pass over a `res × res` grid, in `f64` (for drawing only).
    pub(crate) fn contour_polyline(&self, axis: usize, c: &BigRational, res: usize) -> Vec<[(f64, f64); 2]> {
        let coeffs: Vec<Vec<f64>> =
            self.contour_polynomial(axis, c).iter().map(|r| r.iter().map(|a| a.to_f64()).collect()).collect();
        let (m, n) = self.degree();
        let res = res.max(1);
        let h = 1.0 / res as f64;
        // F on the (res+1)² grid nodes, each once: G[b][i] = Σ_j c_ij B_j(v_b), then
        // F(u_a, v_b) = Σ_i B_i(u_a) G[b][i] — O((m+1)(n+1)·res + (m+1)·res²) products
        let bu: Vec<Vec<f64>> = (0..=res).map(|a| crate::poly::bernstein::bernstein_all(m, &(a as f64 * h))).collect();
        let g: Vec<Vec<f64>> = (0..=res)
            .map(|b| {
                let bv = crate::poly::bernstein::bernstein_all(n, &(b as f64 * h));
                coeffs.iter().map(|r| r.iter().zip(&bv).map(|(x, y)| x * y).sum::<f64>()).collect()
            })
            .collect();
        let node = |a: usize, b: usize| bu[a].iter().zip(&g[b]).map(|(x, y)| x * y).sum::<f64>();
        let values: Vec<Vec<f64>> = (0..=res).map(|a| (0..=res).map(|b| node(a, b)).collect()).collect();
        let mut out = Vec::new();
        for a in 0..res {
            for b in 0..res {
                let (u0, v0) = (a as f64 * h, b as f64 * h);
                let corners = [(u0, v0), (u0 + h, v0), (u0 + h, v0 + h), (u0, v0 + h)];
                let vals = [values[a][b], values[a + 1][b], values[a + 1][b + 1], values[a][b + 1]];
                let mut cuts = Vec::new();
                for e in 0..4 {
                    let (p, q) = (corners[e], corners[(e + 1) % 4]);
                    let (fp, fq) = (vals[e], vals[(e + 1) % 4]);
                    if (fp < 0.0) != (fq < 0.0) {
                        let s = fp / (fp - fq);
                        cuts.push((p.0 + s * (q.0 - p.0), p.1 + s * (q.1 - p.1)));
                    }
                }
                for pair in cuts.chunks(2) {
                    if let [x, y] = pair {
                        out.push([*x, *y]);
                    }
                }
            }
        }
        out
    }
}

/// A patch's point at `(u, v)` with the agreement of every evaluation route
/// ([`RationalPatch::eval_checked`]); serialized as `de_casteljau_u_then_v_and_v_then_u_agree`,
/// `point`, `u`, `v` (exact numbers as strings).
///
/// # Example
/// ```
/// use casteljau::{Point, rat, ratio, surface::RationalPatch};
/// let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
/// let patch = RationalPatch::new(vec![vec![p(0, 0, 0), p(0, 1, 1)], vec![p(1, 0, 1), p(1, 1, 2)]], vec![vec![rat(1); 2]; 2]).unwrap();
/// let v = patch.eval_checked(&ratio(1, 2), &ratio(1, 2), &casteljau::work::Budget::unlimited()).unwrap();
/// assert_eq!(
///     serde_json::to_string(&v).unwrap(),
///     r#"{"de_casteljau_u_then_v_and_v_then_u_agree":true,"point":["1/2","1/2","1"],"u":"1/2","v":"1/2"}"#
/// );
/// ```
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct PatchValue {
    /// Both orders of de Casteljau's recursion agree with the closed form homogeneously, and
    /// the affine recursions give the same point wherever they run (no intermediate weight 0).
    pub de_casteljau_u_then_v_and_v_then_u_agree: bool,
    /// The point (the closed form `Σ Σ B_i(u) B_j(v) w_ij P_ij / Σ Σ B_i(u) B_j(v) w_ij`).
    pub point: Point<BigRational>,
    /// The parameter `u`.
    #[serde(serialize_with = "crate::num::serial::string")]
    pub u: BigRational,
    /// The parameter `v`.
    #[serde(serialize_with = "crate::num::serial::string")]
    pub v: BigRational,
}

impl RationalPatch {
    /// The point at `(u, v)` by the closed form, checked against the four recursions (de
    /// Casteljau homogeneous and affine, `u` then `v` and `v` then `u`): the same answers as
    /// [`Self::eval`], the u-then-v and v-then-u routes, [`Self::eval_u_then_v`] and
    /// [`Self::eval_v_then_u`], computed in fixed-width rationals first (exact: an overflow
    /// anywhere redoes them in `BigRational`), about ten times faster on small numbers.
    ///
    /// # Errors
    /// [`Error::WeightsVanish`] where the closed form's weight is 0 (as [`Self::eval`]). A
    /// recursion that cannot run (an intermediate weight 0) is not a disagreement.
    /// [`Error::WorkLimit`] when the estimate (six evaluations, each of `m + n + 2` curves of
    /// the larger degree) exceeds `budget`, checked before any work starts.
    ///
    /// # Example
    /// ```
    /// use casteljau::{Point, rat, ratio, surface::RationalPatch, work::Budget};
    /// let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    /// let rows = vec![vec![p(0, 0, 0), p(0, 1, 1)], vec![p(1, 0, 1), p(1, 1, 2)]];
    /// let patch = RationalPatch::new(rows, vec![vec![rat(1), rat(2)], vec![rat(3), rat(1)]]).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(2, 5));
    /// let checked = patch.eval_checked(&u, &v, &Budget::unlimited()).unwrap();
    /// assert_eq!(checked.point, patch.eval(&u, &v).unwrap());
    /// assert!(checked.de_casteljau_u_then_v_and_v_then_u_agree);
    /// assert!(patch.eval_checked(&u, &v, &Budget::new(1.0, "--max-work")).is_err());
    /// ```
    pub fn eval_checked(&self, u: &BigRational, v: &BigRational, budget: &crate::work::Budget) -> Result<PatchValue> {
        use crate::num::small::{SmallRational, checked};
        let (m, n) = self.degree();
        let beta = self.rows.iter().map(|r| crate::work::max_bits(r)).max().unwrap_or(0);
        let tau = crate::work::bits(u).max(crate::work::bits(v));
        budget.check(
            format!("checked evaluation of a degree-({m}, {n}) patch"),
            6.0 * (m + n + 2) as f64 * crate::work::evaluation(m.max(n), self.dim() + 1, beta, tau),
        )?;
        let small = checked(|| {
            let to_small = |p: &Point<BigRational>| {
                p.coords.iter().map(SmallRational::from_big).collect::<Option<Vec<_>>>().map(Point::new)
            };
            let rows: Vec<Vec<Point<SmallRational>>> =
                self.rows.iter().map(|r| r.iter().map(to_small).collect::<Option<_>>()).collect::<Option<_>>()?;
            let (h, agree) = evaluation_routes(&rows, &SmallRational::from_big(u)?, &SmallRational::from_big(v)?);
            Some((Point::new(h.coords.iter().map(SmallRational::to_big).collect()), agree))
        })
        .flatten();
        let (h, agree) = small.unwrap_or_else(|| evaluation_routes(&self.rows, u, v));
        let point = h.from_homogeneous().ok_or_else(|| Error::WeightsVanish {
            interval: (format!("(u, v) = ({u}, {v})"), format!("(u, v) = ({u}, {v})")),
        })?;
        Ok(PatchValue { de_casteljau_u_then_v_and_v_then_u_agree: agree, point, u: u.clone(), v: v.clone() })
    }
}

/// The closed form's homogeneous point of the patch `rows` at `(u, v)`, and whether both
/// homogeneous de Casteljau orders equal it and both affine recursions, where they run, give
/// its affine point: the routes of [`RationalPatch::eval_checked`] in any exact scalar.
fn evaluation_routes<S: crate::num::scalar::Exact>(rows: &[Vec<Point<S>>], u: &S, v: &S) -> (Point<S>, bool) {
    let (m, n) = (rows.len() - 1, rows[0].len() - 1);
    let column = |j: usize| rows.iter().map(|r| r[j].clone()).collect::<Vec<_>>();
    let (bu, bv) = (crate::poly::bernstein::bernstein_all(m, u), crate::poly::bernstein::bernstein_all(n, v));
    let mut h = Point::origin(rows[0][0].dim());
    for (i, row) in rows.iter().enumerate() {
        for (j, p) in row.iter().enumerate() {
            h = h.add(&p.scale(&(bu[i].clone() * &bv[j])));
        }
    }
    let line = |pts: Vec<Point<S>>, t: &S| {
        crate::curve::bezier::BezierCurve::new(pts).expect("patch rows and columns are valid curves").eval(t)
    };
    let u_first = line((0..=n).map(|j| line(column(j), u)).collect(), v);
    let v_first = line((0..=m).map(|i| line(rows[i].clone(), v)).collect(), u);
    let affine = |lines: Vec<Vec<Point<S>>>, first: &S, then: &S, k: usize| -> Result<Point<S>> {
        let (pts, ws): (Vec<_>, Vec<_>) = lines
            .into_iter()
            .map(|l| {
                let c = RationalBezier::from_homogeneous(l).expect("patch points are valid homogeneous points");
                Ok((c.eval_rational_de_casteljau(first)?, c.shifted_weight(0, k, first)))
            })
            .collect::<Result<Vec<_>>>()?
            .into_iter()
            .unzip();
        RationalBezier::new(pts, ws)?.eval_rational_de_casteljau(then)
    };
    let s = h.from_homogeneous();
    let agrees = |r: Result<Point<S>>| r.ok().is_none_or(|x| Some(x) == s);
    let agree = u_first == h
        && v_first == h
        && agrees(affine((0..=n).map(column).collect(), u, v, m))
        && agrees(affine(rows.to_vec(), v, u, n));
    (h, agree)
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    #[test]
    fn max_patch_degree_example() {
        use crate::{
            Point, rat,
            surface::{MAX_PATCH_DEGREE, RationalPatch},
        };
        let row = vec![Point::new(vec![rat(0), rat(0), rat(0), rat(1)]); MAX_PATCH_DEGREE + 2];
        assert!(RationalPatch::from_homogeneous(vec![row.clone(), row]).is_err());
    }

    #[test]
    fn subdivide_u_example() {
        use crate::{Point, rat, ratio, surface::RationalPatch};
        let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
        // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
        let s = RationalPatch::new(
            vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
            vec![vec![rat(1); 3], vec![rat(1); 3]],
        )
        .unwrap();
        let v = ratio(1, 2);
        let (a, b) = s.subdivide_u(&ratio(1, 4)).unwrap();
        assert_eq!(a.eval(&rat(1), &v).unwrap(), s.eval(&ratio(1, 4), &v).unwrap());
        assert_eq!(b.eval(&rat(0), &v).unwrap(), s.eval(&ratio(1, 4), &v).unwrap());
    }

    #[test]
    fn subdivide_v_example() {
        use crate::{Point, rat, ratio, surface::RationalPatch};
        let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
        // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
        let s = RationalPatch::new(
            vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
            vec![vec![rat(1); 3], vec![rat(1); 3]],
        )
        .unwrap();
        let u = ratio(1, 3);
        let (a, b) = s.subdivide_v(&ratio(1, 4)).unwrap();
        assert_eq!(a.eval(&u, &rat(1)).unwrap(), s.eval(&u, &ratio(1, 4)).unwrap());
        assert_eq!(b.eval(&u, &rat(0)).unwrap(), s.eval(&u, &ratio(1, 4)).unwrap());
    }

    #[test]
    fn contour_polynomial_example() {
        use crate::{Point, rat, ratio, surface::RationalPatch};
        let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
        // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
        let s = RationalPatch::new(
            vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
            vec![vec![rat(1); 3], vec![rat(1); 3]],
        )
        .unwrap();
        // z = 3/8 where 2v(1 − v) = 3/8: v = 1/4 and v = 3/4
        let f = s.contour_polynomial(2, &ratio(3, 8));
        assert_eq!(f, vec![vec![ratio(-3, 8), ratio(5, 8), ratio(-3, 8)]; 2]);
    }

    #[test]
    fn contour_polyline_example() {
        use crate::{Point, rat, ratio, surface::RationalPatch};
        let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
        // z = 2v(1 − v) over the unit square, degree (1, 2), all weights 1
        let s = RationalPatch::new(
            vec![vec![p(0, 0, 0), p(1, 0, 1), p(2, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1), p(2, 1, 0)]],
            vec![vec![rat(1); 3], vec![rat(1); 3]],
        )
        .unwrap();
        let segs = s.contour_polyline(2, &ratio(3, 8), 16);
        assert!(!segs.is_empty());
        assert!(segs.iter().flatten().all(|&(a, b)| (0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b)));
    }
}
