//! Rational spline nets → rational Bézier patches (seed 002 §5, (50)–(54), Figs. 10–11).
//!
//! A net `q_ij` (`i` along `u`, `j` along `v`) with weights `k_ij`, degree `(n_u, n_v)` and scale
//! ratios `λ` (along `u`) and `μ` (along `v`). Each column is a rational spline in `u`: converting
//! every column gives intermediate rational Bézier rows (51)–(52); converting those rows in `v`
//! gives the patches. The seed says the order (columns or rows first) does not matter: both
//! orders are computed and compared exactly. The patches are checked against the tensor-product
//! NURBS on their spans, and their joins for `C^{min(n_u, n_v) − 1}` continuity.

use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::{Scalar, rat};
use crate::rational::rational_bezier::RationalBezier;
use crate::spline::{Conversion, RationalSpline};
use crate::surface::RationalPatch;
use num_rational::BigRational;

/// A rational spline net.
///
/// # Example
/// ```
/// # use casteljau::{Point, rat, spline::{Conversion, SplineNet}};
/// // a 4×4 net of a biquadratic spline surface: 3×3... here 2×2 = 4 patches
/// let pts: Vec<Vec<Point<_>>> = (0..4)
///     .map(|i| (0..4).map(|j| Point::new(vec![rat(j), rat(i), rat((i * j) % 3)])).collect())
///     .collect();
/// let net = SplineNet::new((2, 2), pts, vec![vec![rat(1); 4]; 4], [1, 2, 1, 1, 1].map(rat).to_vec(), [2, 1, 1, 1, 2].map(rat).to_vec()).unwrap();
/// assert_eq!(net.degree, (2, 2));
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SplineNet {
    /// Degrees `(n_u, n_v)`.
    pub degree: (usize, usize),
    /// Homogeneous control points, `rows[i][j]`.
    pub rows: Vec<Vec<Point<BigRational>>>,
    /// Scale ratios along `u`.
    pub lambda: Vec<BigRational>,
    /// Scale ratios along `v`.
    pub mu: Vec<BigRational>,
}

fn convert(sp: &RationalSpline, how: Conversion) -> Result<Vec<RationalBezier<BigRational>>> {
    sp.to_bezier(how)
}

fn transpose<T: Clone>(m: &[Vec<T>]) -> Vec<Vec<T>> {
    (0..m[0].len()).map(|j| m.iter().map(|r| r[j].clone()).collect()).collect()
}

impl SplineNet {
    /// A net from affine points, weights and ratios.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for ragged input (naming the row) or counts that do not fit
    /// the degrees, [`Error::WeightCount`] for a row of weights of another length,
    /// [`Error::ZeroWeight`] naming the first zero weight.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, spline::{Conversion, SplineNet}};
    /// // a 4×4 net of a biquadratic spline surface: 3×3... here 2×2 = 4 patches
    /// let pts: Vec<Vec<Point<_>>> = (0..4)
    ///     .map(|i| (0..4).map(|j| Point::new(vec![rat(j), rat(i), rat((i * j) % 3)])).collect())
    ///     .collect();
    /// let net = SplineNet::new((2, 2), pts, vec![vec![rat(1); 4]; 4], [1, 2, 1, 1, 1].map(rat).to_vec(), [2, 1, 1, 1, 2].map(rat).to_vec()).unwrap();
    /// assert!(SplineNet::new((2, 2), vec![], vec![], vec![], vec![]).is_err());
    /// ```
    pub fn new(
        degree: (usize, usize),
        points: Vec<Vec<Point<BigRational>>>,
        weights: Vec<Vec<BigRational>>,
        lambda: Vec<BigRational>,
        mu: Vec<BigRational>,
    ) -> Result<Self> {
        let cols = points.first().map_or(0, Vec::len);
        let bad = |message: String| Error::InvalidArgument { message };
        if points.is_empty() {
            return Err(bad("a net needs equal-length rows of points and weights; there are none".into()));
        }
        if let Some(r) = points.iter().position(|r| r.len() != cols) {
            return Err(bad(format!("row {} has {} control points, row 1 has {cols}", r + 1, points[r].len())));
        }
        if weights.len() != points.len() {
            return Err(bad(format!("{} rows of weights for {} rows of control points", weights.len(), points.len())));
        }
        if let Some(r) = weights.iter().position(|r| r.len() != cols) {
            return Err(Error::WeightCount { weights: weights[r].len(), points: cols, row: Some(r + 1) });
        }
        for (r, w) in weights.iter().enumerate() {
            if let Some(i) = w.iter().position(Scalar::is_zero) {
                return Err(Error::ZeroWeight { index: i + 1, row: Some(r + 1) });
            }
        }
        let rows = points
            .iter()
            .zip(&weights)
            .map(|(p, w)| p.iter().zip(w).map(|(p, w)| p.to_homogeneous(w)).collect())
            .collect();
        let net = SplineNet { degree, rows, lambda, mu };
        // validate both directions once
        RationalSpline::from_homogeneous(degree.0, net.rows.iter().map(|r| r[0].clone()).collect(), &net.lambda)?;
        RationalSpline::from_homogeneous(degree.1, net.rows[0].clone(), &net.mu)?;
        Ok(net)
    }

    /// The patches `[s][t]` (u-segment `s`, v-segment `t`), converting columns first
    /// (`columns_first = true`, the seed's order (50)–(52)) or rows first.
    ///
    /// # Errors
    /// As the curve conversions.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, spline::{Conversion, SplineNet}};
    /// // a 4×4 net of a biquadratic spline surface: 3×3... here 2×2 = 4 patches
    /// let pts: Vec<Vec<Point<_>>> = (0..4)
    ///     .map(|i| (0..4).map(|j| Point::new(vec![rat(j), rat(i), rat((i * j) % 3)])).collect())
    ///     .collect();
    /// let net = SplineNet::new((2, 2), pts, vec![vec![rat(1); 4]; 4], [1, 2, 1, 1, 1].map(rat).to_vec(), [2, 1, 1, 1, 2].map(rat).to_vec()).unwrap();
    /// let rows = net.to_patches(Conversion::Boehm, false).unwrap();
    /// assert_eq!(rows, net.to_patches(Conversion::Boehm, true).unwrap()); // order independent
    /// ```
    pub fn to_patches(&self, how: Conversion, columns_first: bool) -> Result<Vec<Vec<RationalPatch>>> {
        if columns_first {
            self.convert_dir(&self.rows, (self.degree.0, &self.lambda), (self.degree.1, &self.mu), how, false)
        } else {
            let t = transpose(&self.rows);
            let p = self.convert_dir(&t, (self.degree.1, &self.mu), (self.degree.0, &self.lambda), how, true)?;
            Ok(transpose(&p))
        }
    }

    /// Converts the columns of `grid` (first direction), then the rows of each intermediate
    /// block (second direction); `flip` transposes each patch back.
    fn convert_dir(
        &self,
        grid: &[Vec<Point<BigRational>>],
        first: (usize, &[BigRational]),
        second: (usize, &[BigRational]),
        how: Conversion,
        flip: bool,
    ) -> Result<Vec<Vec<RationalPatch>>> {
        let ncols = grid[0].len();
        // per column: its Bézier segments along the first direction
        let col_segments: Vec<Vec<RationalBezier<BigRational>>> = (0..ncols)
            .map(|j| {
                convert(
                    &RationalSpline::from_homogeneous(first.0, grid.iter().map(|r| r[j].clone()).collect(), first.1)?,
                    how,
                )
            })
            .collect::<Result<_>>()?;
        let nseg = col_segments[0].len();
        let mut out = Vec::with_capacity(nseg);
        for s in 0..nseg {
            // intermediate rows: row i of segment s across all columns
            let inter: Vec<Vec<Point<BigRational>>> = (0..=first.0)
                .map(|i| col_segments.iter().map(|c| c[s].homogeneous().points()[i].clone()).collect())
                .collect();
            let row_segments: Vec<Vec<RationalBezier<BigRational>>> = inter
                .iter()
                .map(|r| convert(&RationalSpline::from_homogeneous(second.0, r.clone(), second.1)?, how))
                .collect::<Result<_>>()?;
            let patches = (0..row_segments[0].len())
                .map(|t| {
                    let rows: Vec<Vec<Point<BigRational>>> =
                        row_segments.iter().map(|r| r[t].homogeneous().points().to_vec()).collect();
                    let p = RationalPatch::from_homogeneous(rows)?;
                    Ok(if flip { p.transpose() } else { p })
                })
                .collect::<Result<Vec<_>>>()?;
            out.push(patches);
        }
        Ok(out)
    }

    /// The tensor-product NURBS at `(u, v)` in the span of patch `(s, t)`: each column's spline at
    /// `u`, then the spline through those points at `v` (homogeneous de Boor twice).
    ///
    /// # Errors
    /// [`Error::WeightsVanish`] where the surface is undefined.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, spline::{Conversion, SplineNet}};
    /// // a 4×4 net of a biquadratic spline surface: 3×3... here 2×2 = 4 patches
    /// let pts: Vec<Vec<Point<_>>> = (0..4)
    ///     .map(|i| (0..4).map(|j| Point::new(vec![rat(j), rat(i), rat((i * j) % 3)])).collect())
    ///     .collect();
    /// let net = SplineNet::new((2, 2), pts, vec![vec![rat(1); 4]; 4], [1, 2, 1, 1, 1].map(rat).to_vec(), [2, 1, 1, 1, 2].map(rat).to_vec()).unwrap();
    /// let ((u0, _), (v0, _)) = net.span(0, 0);
    /// let patch = &net.to_patches(Conversion::Boehm, false).unwrap()[0][0];
    /// assert_eq!(patch.eval(&rat(0), &rat(0)).unwrap(), net.eval(0, 0, &u0, &v0).unwrap());
    /// ```
    pub fn eval(&self, s: usize, t: usize, u: &BigRational, v: &BigRational) -> Result<Point<BigRational>> {
        let ncols = self.rows[0].len();
        let pts: Vec<Point<BigRational>> = (0..ncols)
            .map(|j| {
                let sp = RationalSpline {
                    degree: self.degree.0,
                    homogeneous: self.rows.iter().map(|r| r[j].clone()).collect(),
                    knots: knots(&self.lambda),
                };
                sp.eval_homogeneous(s, u)
            })
            .collect();
        let sp = RationalSpline { degree: self.degree.1, homogeneous: pts, knots: knots(&self.mu) };
        sp.eval_homogeneous(t, v)
            .from_homogeneous()
            .ok_or(Error::WeightsVanish { interval: (u.to_string(), v.to_string()) })
    }

    /// The spans `[u_s, u_{s+1}] × [v_t, v_{t+1}]` of patch `(s, t)`.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, spline::{Conversion, SplineNet}};
    /// // a 4×4 net of a biquadratic spline surface: 3×3... here 2×2 = 4 patches
    /// let pts: Vec<Vec<Point<_>>> = (0..4)
    ///     .map(|i| (0..4).map(|j| Point::new(vec![rat(j), rat(i), rat((i * j) % 3)])).collect())
    ///     .collect();
    /// let net = SplineNet::new((2, 2), pts, vec![vec![rat(1); 4]; 4], [1, 2, 1, 1, 1].map(rat).to_vec(), [2, 1, 1, 1, 2].map(rat).to_vec()).unwrap();
    /// assert_eq!(net.span(0, 0), ((rat(3), rat(4)), (rat(3), rat(4))));
    /// ```
    pub fn span(&self, s: usize, t: usize) -> ((BigRational, BigRational), (BigRational, BigRational)) {
        let (ku, kv) = (knots(&self.lambda), knots(&self.mu));
        let (nu, nv) = self.degree;
        ((ku[nu + s].clone(), ku[nu + s + 1].clone()), (kv[nv + t].clone(), kv[nv + t + 1].clone()))
    }
}

fn knots(ratios: &[BigRational]) -> Vec<BigRational> {
    let mut k = vec![rat(0)];
    for r in ratios {
        let next = k.last().expect("non-empty").clone() + r;
        k.push(next);
    }
    k
}

/// What [`SplineNet::check`] found.
///
/// # Example
/// ```
/// # use casteljau::{Point, rat, spline::{Conversion, SplineNet}};
/// // a 4×4 net of a biquadratic spline surface: 3×3... here 2×2 = 4 patches
/// let pts: Vec<Vec<Point<_>>> = (0..4)
///     .map(|i| (0..4).map(|j| Point::new(vec![rat(j), rat(i), rat((i * j) % 3)])).collect())
///     .collect();
/// let net = SplineNet::new((2, 2), pts, vec![vec![rat(1); 4]; 4], [1, 2, 1, 1, 1].map(rat).to_vec(), [2, 1, 1, 1, 2].map(rat).to_vec()).unwrap();
/// let r = net.check(Conversion::Boehm).unwrap();
/// assert!(r.equals_nurbs && r.smooth_joins && r.order_independent);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NetReport {
    /// Number of patches.
    pub patches: usize,
    /// Rows-first and columns-first give the same patches.
    pub order_independent: bool,
    /// Every patch equals the NURBS on its span (proved on the type-bounded grid).
    pub equals_nurbs: bool,
    /// Every join is `C^{min(n_u, n_v) − 1}` in the spline parameters.
    pub smooth_joins: bool,
    /// The first problem found, in words.
    pub problem: Option<String>,
}

/// `∂^r S/∂u^r (1, v) / λ^r = ∂^r S'/∂u^r (0, v) / λ'^r` for `r ≤ order`, on enough `v`: each side
/// is rational in `v` of type ≤ `((r+1)·n, (r+1)·n)`, so `2(order+1)n + 1` values decide.
fn joins(p: &RationalPatch, q: &RationalPatch, l: &BigRational, l1: &BigRational, order: usize, n: usize) -> bool {
    let count = 2 * (order + 1) * n + 1;
    (0..count).all(|k| {
        let v = BigRational::new((k as i64).into(), ((count.max(2) - 1) as i64).into());
        let dp = p.iso_v(&v).and_then(|c| c.derivatives_at(&rat(1), order));
        let dq = q.iso_v(&v).and_then(|c| c.derivatives_at(&rat(0), order));
        match (dp, dq) {
            (Ok(dp), Ok(dq)) => (0..=order).all(|r| {
                dp[r].scale(&crate::poly::bernstein::pow(l1, r)) == dq[r].scale(&crate::poly::bernstein::pow(l, r))
            }),
            _ => true,
        }
    })
}

impl SplineNet {
    /// Converts the net both ways and proves the patches: equal to the tensor NURBS (rational of type
    /// `(n_u, n_u) × (n_v, n_v)`: a `(2n_u + 1) × (2n_v + 1)` grid decides), and `C^{k}` joins
    /// (`k = min(n_u, n_v) − 1`) checked on the boundary curves (type-bounded grids in the other
    /// parameter).
    ///
    /// # Errors
    /// As the conversions.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{Point, rat, spline::{Conversion, SplineNet}};
    /// // a 4×4 net of a biquadratic spline surface: 3×3... here 2×2 = 4 patches
    /// let pts: Vec<Vec<Point<_>>> = (0..4)
    ///     .map(|i| (0..4).map(|j| Point::new(vec![rat(j), rat(i), rat((i * j) % 3)])).collect())
    ///     .collect();
    /// let net = SplineNet::new((2, 2), pts, vec![vec![rat(1); 4]; 4], [1, 2, 1, 1, 1].map(rat).to_vec(), [2, 1, 1, 1, 2].map(rat).to_vec()).unwrap();
    /// assert_eq!(net.check(Conversion::Boehm).unwrap().patches, 4);
    /// ```
    pub fn check(&self, how: Conversion) -> Result<NetReport> {
        let net = self;
        let a = net.to_patches(how, true)?;
        let b = net.to_patches(how, false)?;
        let order_independent = a == b;
        let (nu, nv) = net.degree;
        let mut problem = None;
        let mut equals_nurbs = true;
        'outer: for (s, row) in a.iter().enumerate() {
            for (t, p) in row.iter().enumerate() {
                let ((u0, u1), (v0, v1)) = net.span(s, t);
                for i in 0..=2 * nu {
                    for j in 0..=2 * nv {
                        let (a_, b_) = (
                            BigRational::new((i as i64).into(), ((2 * nu) as i64).into()),
                            BigRational::new((j as i64).into(), ((2 * nv) as i64).into()),
                        );
                        let (u, v) = (u0.clone() + (u1.clone() - &u0) * &a_, v0.clone() + (v1.clone() - &v0) * &b_);
                        if p.eval(&a_, &b_).ok() != net.eval(s, t, &u, &v).ok() {
                            equals_nurbs = false;
                            problem =
                                Some(format!("patch ({s}, {t}) differs from the NURBS at local (u, v) = ({a_}, {b_})"));
                            break 'outer;
                        }
                    }
                }
            }
        }
        let order = nu.min(nv).saturating_sub(1);
        let mut smooth = true;
        // joins across u (patch (s,t) at u = 1 and (s+1,t) at u = 0), checked along v
        for s in 0..a.len().saturating_sub(1) {
            for t in 0..a[s].len() {
                let (ls, ls1) = (net.lambda[nu + s].clone(), net.lambda[nu + s + 1].clone());
                if !joins(&a[s][t], &a[s + 1][t], &ls, &ls1, order, nv) {
                    smooth = false;
                    problem.get_or_insert(format!(
                        "join between patches ({s}, {t}) and ({}, {t}) is not C^{order}",
                        s + 1
                    ));
                }
            }
        }
        // joins across v: transpose
        for s in 0..a.len() {
            for t in 0..a[s].len().saturating_sub(1) {
                let (mt, mt1) = (net.mu[nv + t].clone(), net.mu[nv + t + 1].clone());
                if !joins(&a[s][t].transpose(), &a[s][t + 1].transpose(), &mt, &mt1, order, nu) {
                    smooth = false;
                    problem.get_or_insert(format!(
                        "join between patches ({s}, {t}) and ({s}, {}) is not C^{order}",
                        t + 1
                    ));
                }
            }
        }
        Ok(NetReport {
            patches: a.iter().map(Vec::len).sum(),
            order_independent,
            equals_nurbs,
            smooth_joins: smooth,
            problem,
        })
    }
}
