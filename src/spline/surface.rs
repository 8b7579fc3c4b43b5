//! Tensor-product NURBS surfaces from knot vectors in `u` and `v` (any multiplicities, clamped
//! or not) and their exact rational Bézier patches, checked against the surface itself.
//!
//! The net is a grid of homogeneous points `rows[i][j] = (w_ij P_ij, w_ij)`, `i` along `u`
//! (degree `p`), `j` along `v` (degree `q`); the knot vectors follow the curve convention of
//! [`crate::spline::knots`] (`m + p + 2` and `l + q + 2` knots). The patches come from Bézier
//! extraction of every column in `u`, then of every resulting row in `v`; both directions are
//! exact and homogeneous.

use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::spline::RationalSpline;
use crate::spline::knots::joins_with_order;
use crate::surface::RationalPatch;
use num_rational::BigRational;

/// A tensor-product rational B-spline surface.
///
/// # Example
/// ```
/// use casteljau::{Point, rat, ratio, spline::NurbsSurface};
/// // a clamped biquadratic surface, 4×3 net, a double interior knot in u
/// let rows: Vec<Vec<Point<_>>> = (0..4)
///     .map(|i| (0..3).map(|j| Point::new(vec![rat(i), rat(j), rat((i * j) % 3), rat(1)])).collect())
///     .collect();
/// let e = NurbsSurface::from_knots((2, 2), rows.clone(), &[0, 0, 0, 1, 1, 1, 1].map(rat), &[0, 0, 0, 1, 1, 1].map(rat));
/// assert!(e.unwrap_err().to_string().starts_with("knots in u: knot 4 (1) has multiplicity 4"));
/// let s = NurbsSurface::from_knots((2, 2), rows, &[0, 0, 0, 1, 2, 2, 2].map(rat), &[0, 0, 0, 1, 1, 1].map(rat)).unwrap();
/// let report = s.check().unwrap();
/// assert_eq!(report.patches, 2);
/// assert!(report.equals_surface && report.joins_proved);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NurbsSurface {
    /// Degrees `(p, q)` in `u` and `v`.
    pub degree: (usize, usize),
    /// Homogeneous control net, `rows[i][j]`, `i` along `u`.
    pub rows: Vec<Vec<Point<BigRational>>>,
    /// Knots in `u` without the last one (see the curve convention).
    pub knots_u: Vec<BigRational>,
    /// Knots in `v` without the last one.
    pub knots_v: Vec<BigRational>,
}

/// One rational Bézier patch of the surface and its parameter rectangle.
///
/// # Example
/// ```
/// # use casteljau::{Point, rat, ratio, spline::NurbsSurface};
/// let rows: Vec<Vec<Point<_>>> = (0..4)
///     .map(|i| (0..3).map(|j| Point::new(vec![rat(i), rat(j), rat((i * j) % 3), rat(1)])).collect())
///     .collect();
/// let s = NurbsSurface::from_knots((2, 2), rows, &[0, 0, 0, 1, 2, 2, 2].map(rat), &[0, 0, 0, 1, 1, 1].map(rat)).unwrap();
/// let patches = s.bezier_patches().unwrap();
/// assert_eq!((patches[1][0].span_u.clone(), patches[1][0].span_v.clone()), ((rat(1), rat(2)), (rat(0), rat(1))));
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PatchPiece {
    /// `[a, b]` in `u`.
    pub span_u: (BigRational, BigRational),
    /// `[c, d]` in `v`.
    pub span_v: (BigRational, BigRational),
    /// The patch, on `[0, 1]²`.
    pub patch: RationalPatch,
}

/// What [`NurbsSurface::check`] proves.
///
/// # Example
/// ```
/// # use casteljau::{Point, rat, ratio, spline::NurbsSurface};
/// let rows: Vec<Vec<Point<_>>> = (0..4)
///     .map(|i| (0..3).map(|j| Point::new(vec![rat(i), rat(j), rat((i * j) % 3), rat(1)])).collect())
///     .collect();
/// let s = NurbsSurface::from_knots((2, 2), rows, &[0, 0, 0, 1, 2, 2, 2].map(rat), &[0, 0, 0, 1, 1, 1].map(rat)).unwrap();
/// let r = s.check().unwrap();
/// assert_eq!(r.joins_u, vec![("1".to_string(), 1, 1)]); // knot 1 in u, simple: C^1
/// ```
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct NurbsSurfaceReport {
    /// Number of patches.
    pub patches: usize,
    /// Every patch equals the surface homogeneously on a `(p+1)×(q+1)` grid of its rectangle
    /// (both are polynomial of degree `(p, q)` there, so this proves equality).
    pub equals_surface: bool,
    /// Every join between neighbouring patches has the continuity `C^(p−μ)` (in `u`) or
    /// `C^(q−μ)` (in `v`) of its knot's multiplicity, checked on `q + 1` (or `p + 1`) iso-curves
    /// across the join (the derivatives are polynomial of degree `q` (or `p`) along it).
    pub joins_proved: bool,
    /// The continuity claimed at each interior knot in `u` (`(knot, μ, p − μ)`).
    pub joins_u: Vec<(String, usize, i64)>,
    /// The same in `v`.
    pub joins_v: Vec<(String, usize, i64)>,
}

fn transpose<T: Clone>(m: &[Vec<T>]) -> Vec<Vec<T>> {
    (0..m[0].len()).map(|j| m.iter().map(|r| r[j].clone()).collect()).collect()
}

impl NurbsSurface {
    /// A surface from its homogeneous net and full knot vectors in `u` and `v`.
    ///
    /// # Errors
    /// As [`RationalSpline::from_knots`] for either direction (its message prefixed by the
    /// direction), and [`Error::InvalidArgument`] for a ragged net.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, spline::NurbsSurface};
    /// let rows: Vec<Vec<Point<_>>> = (0..4)
    ///     .map(|i| (0..3).map(|j| Point::new(vec![rat(i), rat(j), rat((i * j) % 3), rat(1)])).collect())
    ///     .collect();
    /// let s = NurbsSurface::from_knots((2, 2), rows, &[0, 0, 0, 1, 2, 2, 2].map(rat), &[0, 0, 0, 1, 1, 1].map(rat)).unwrap();
    /// assert_eq!(s.degree, (2, 2));
    /// ```
    pub fn from_knots(
        degree: (usize, usize),
        rows: Vec<Vec<Point<BigRational>>>,
        knots_u: &[BigRational],
        knots_v: &[BigRational],
    ) -> Result<Self> {
        let cols = rows.first().map_or(0, Vec::len);
        if rows.is_empty() || cols == 0 || rows.iter().any(|r| r.len() != cols) {
            return Err(Error::InvalidArgument { message: "a net needs equal-length rows".into() });
        }
        fn prefix(dir: &'static str) -> impl Fn(Error) -> Error {
            move |e: Error| match e {
                Error::InvalidArgument { message } => Error::InvalidArgument { message: format!("{dir}: {message}") },
                other => other,
            }
        }
        let u = RationalSpline::from_knots(degree.0, rows.iter().map(|r| r[0].clone()).collect(), knots_u)
            .map_err(prefix("knots in u"))?;
        let v = RationalSpline::from_knots(degree.1, rows[0].clone(), knots_v).map_err(prefix("knots in v"))?;
        for r in &rows {
            RationalSpline::from_knots(degree.1, r.clone(), knots_v)?;
        }
        Ok(NurbsSurface { degree, rows, knots_u: u.knots, knots_v: v.knots })
    }

    // the knot vectors were validated in `from_knots`; the points may be intermediate ones
    fn spline_u(&self, column: Vec<Point<BigRational>>) -> Result<RationalSpline> {
        Ok(RationalSpline { degree: self.degree.0, homogeneous: column, knots: self.knots_u.clone() })
    }

    fn spline_v(&self, row: Vec<Point<BigRational>>) -> Result<RationalSpline> {
        Ok(RationalSpline { degree: self.degree.1, homogeneous: row, knots: self.knots_v.clone() })
    }

    /// The homogeneous point at `(u, v)` of the domain: de Boor in `u` on every column, then in
    /// `v`.
    ///
    /// # Errors
    /// A parameter outside the domain.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, spline::NurbsSurface};
    /// let rows: Vec<Vec<Point<_>>> = (0..4)
    ///     .map(|i| (0..3).map(|j| Point::new(vec![rat(i), rat(j), rat((i * j) % 3), rat(1)])).collect())
    ///     .collect();
    /// let s = NurbsSurface::from_knots((2, 2), rows, &[0, 0, 0, 1, 2, 2, 2].map(rat), &[0, 0, 0, 1, 1, 1].map(rat)).unwrap();
    /// let patch = &s.bezier_patches().unwrap()[0][0];
    /// let (u, v) = (ratio(1, 2), ratio(1, 3));
    /// assert_eq!(patch.patch.eval_homogeneous(&u, &v), s.eval_homogeneous_at(&u, &v).unwrap());
    /// ```
    pub fn eval_homogeneous_at(&self, u: &BigRational, v: &BigRational) -> Result<Point<BigRational>> {
        let row: Vec<Point<BigRational>> = transpose(&self.rows)
            .into_iter()
            .map(|col| self.spline_u(col)?.eval_homogeneous_at(u))
            .collect::<Result<_>>()?;
        self.spline_v(row)?.eval_homogeneous_at(v)
    }

    /// The domain rectangle `([a, b], [c, d])`.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, spline::NurbsSurface};
    /// let rows: Vec<Vec<Point<_>>> = (0..4)
    ///     .map(|i| (0..3).map(|j| Point::new(vec![rat(i), rat(j), rat((i * j) % 3), rat(1)])).collect())
    ///     .collect();
    /// let s = NurbsSurface::from_knots((2, 2), rows, &[0, 0, 0, 1, 2, 2, 2].map(rat), &[0, 0, 0, 1, 1, 1].map(rat)).unwrap();
    /// assert_eq!(s.domain(), ((rat(0), rat(2)), (rat(0), rat(1))));
    /// ```
    pub fn domain(&self) -> ((BigRational, BigRational), (BigRational, BigRational)) {
        let (p, q) = self.degree;
        let (m, l) = (self.rows.len(), self.rows[0].len());
        ((self.knots_u[p].clone(), self.knots_u[m].clone()), (self.knots_v[q].clone(), self.knots_v[l].clone()))
    }

    /// The rational Bézier patches, `[s][t]` for the `s`-th span in `u` and `t`-th in `v`.
    ///
    /// # Errors
    /// A homogeneous point that becomes zero (weights of opposite signs cancelling).
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, spline::NurbsSurface};
    /// let rows: Vec<Vec<Point<_>>> = (0..4)
    ///     .map(|i| (0..3).map(|j| Point::new(vec![rat(i), rat(j), rat((i * j) % 3), rat(1)])).collect())
    ///     .collect();
    /// let s = NurbsSurface::from_knots((2, 2), rows, &[0, 0, 0, 1, 2, 2, 2].map(rat), &[0, 0, 0, 1, 1, 1].map(rat)).unwrap();
    /// let patches = s.bezier_patches().unwrap();
    /// assert_eq!((patches.len(), patches[0].len()), (2, 1));
    /// ```
    pub fn bezier_patches(&self) -> Result<Vec<Vec<PatchPiece>>> {
        // every column in u: pieces[j][s] = p + 1 points
        let by_column: Vec<Vec<crate::spline::knots::BezierPiece>> =
            transpose(&self.rows).into_iter().map(|col| self.spline_u(col)?.bezier_pieces()).collect::<Result<_>>()?;
        let segments_u = by_column[0].len();
        let mut out = Vec::with_capacity(segments_u);
        for s in 0..segments_u {
            let span_u = by_column[0][s].span.clone();
            // row r of the u-piece s, across the columns, is a spline in v
            let rows_v: Vec<Vec<crate::spline::knots::BezierPiece>> = (0..=self.degree.0)
                .map(|r| {
                    self.spline_v(by_column.iter().map(|c| c[s].homogeneous[r].clone()).collect())?.bezier_pieces()
                })
                .collect::<Result<_>>()?;
            let mut line = Vec::with_capacity(rows_v[0].len());
            for t in 0..rows_v[0].len() {
                let rows: Vec<Vec<Point<BigRational>>> = rows_v.iter().map(|r| r[t].homogeneous.clone()).collect();
                line.push(PatchPiece {
                    span_u: span_u.clone(),
                    span_v: rows_v[0][t].span.clone(),
                    patch: RationalPatch::from_homogeneous(rows)?,
                });
            }
            out.push(line);
        }
        Ok(out)
    }

    /// Proves the patches: equal to the surface on each rectangle and joined with the
    /// continuity of each knot's multiplicity (see [`NurbsSurfaceReport`]).
    ///
    /// # Errors
    /// As [`Self::bezier_patches`].
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, ratio, spline::NurbsSurface};
    /// let rows: Vec<Vec<Point<_>>> = (0..4)
    ///     .map(|i| (0..3).map(|j| Point::new(vec![rat(i), rat(j), rat((i * j) % 3), rat(1)])).collect())
    ///     .collect();
    /// let s = NurbsSurface::from_knots((2, 2), rows, &[0, 0, 0, 1, 2, 2, 2].map(rat), &[0, 0, 0, 1, 1, 1].map(rat)).unwrap();
    /// let r = s.check().unwrap();
    /// assert!(r.equals_surface && r.joins_proved);
    /// ```
    pub fn check(&self) -> Result<NurbsSurfaceReport> {
        let (p, q) = self.degree;
        let patches = self.bezier_patches()?;
        let frac = |k: usize, d: usize| BigRational::new((k as i64).into(), (d.max(1) as i64).into());
        let mut equals_surface = true;
        for piece in patches.iter().flatten() {
            for a in 0..=p {
                for b in 0..=q {
                    let (s, t) = (frac(a, p), frac(b, q));
                    let u = piece.span_u.0.clone() + (piece.span_u.1.clone() - &piece.span_u.0) * &s;
                    let v = piece.span_v.0.clone() + (piece.span_v.1.clone() - &piece.span_v.0) * &t;
                    equals_surface &= piece.patch.eval_homogeneous(&s, &t) == self.eval_homogeneous_at(&u, &v)?;
                }
            }
        }
        let mult = |knots: &[BigRational], x: &BigRational| knots[1..].iter().filter(|k| *k == x).count();
        let len = |(a, b): &(BigRational, BigRational)| b.clone() - a;
        let mut joins_proved = true;
        let mut joins_u = Vec::new();
        for s in 0..patches.len().saturating_sub(1) {
            let knot = patches[s][0].span_u.1.clone();
            let mu = mult(&self.knots_u, &knot).min(p + 1);
            let order = p as i64 - mu as i64;
            joins_u.push((knot.to_string(), mu, order));
            if order < 0 {
                continue;
            }
            for t in 0..patches[s].len() {
                let (left, right) = (&patches[s][t], &patches[s + 1][t]);
                for b in 0..=q {
                    let v = frac(b, q);
                    joins_proved &= joins_with_order(
                        &left.patch.iso_v(&v)?,
                        &right.patch.iso_v(&v)?,
                        &len(&left.span_u),
                        &len(&right.span_u),
                        order as usize,
                    );
                }
            }
        }
        let mut joins_v = Vec::new();
        for t in 0..patches.first().map_or(0, Vec::len).saturating_sub(1) {
            let knot = patches[0][t].span_v.1.clone();
            let mu = mult(&self.knots_v, &knot).min(q + 1);
            let order = q as i64 - mu as i64;
            joins_v.push((knot.to_string(), mu, order));
            if order < 0 {
                continue;
            }
            for line in &patches {
                let (left, right) = (&line[t], &line[t + 1]);
                for a in 0..=p {
                    let u = frac(a, p);
                    joins_proved &= joins_with_order(
                        &left.patch.iso_u(&u)?,
                        &right.patch.iso_u(&u)?,
                        &len(&left.span_v),
                        &len(&right.span_v),
                        order as usize,
                    );
                }
            }
        }
        Ok(NurbsSurfaceReport {
            patches: patches.iter().map(Vec::len).sum(),
            equals_surface,
            joins_proved,
            joins_u,
            joins_v,
        })
    }
}
