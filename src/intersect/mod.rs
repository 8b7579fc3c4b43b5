//! Exact intersections of planar polynomial and rational Bézier curves, and self-intersections.
//!
//! Curve–curve: with `A(s) = (X_A, Y_A)/W_A` and `B(t) = (X_B, Y_B)/W_B`, a common point solves
//! `X_A(s)W_B(t) − X_B(t)W_A(s) = 0`, `Y_A(s)W_B(t) − Y_B(t)W_A(s) = 0`. The resultant in `t`
//! is a polynomial `R(s)` whose roots contain every intersection's `s`; the resultant in `s`
//! gives `T(t)` likewise. Each root `σ` of `R` in the domain is paired with each root `τ` of `T`
//! for which `A(σ) = B(τ)` — decided exactly, coordinate by coordinate, as equalities of real
//! algebraic numbers — so every pair reported is an intersection and every intersection is
//! reported, however tangential, at an endpoint, or through a cusp or double point.
//! `R ≡ 0` means the curves share a component: an **overlap** (see [`intersect`]).
//!
//! Self-intersection: `A(s) = A(t)`, `s < t`, from the divided differences
//! `(X(s)W(t) − X(t)W(s))/(s − t)` and the same for `Y`, paired the same way.
//!
//! Contact order: `min(multiplicity of σ in R, multiplicity of τ in T)` — the intersection
//! multiplicity when neither curve passes through the point twice; `1` is transversal, `≥ 2`
//! tangent (a line through a cusp counts 2 as well).
//!
//! # Example
//! ```
//! use casteljau::{BezierCurve, num::parse::parse_points, intersect::{intersect_polynomial, Domain}};
//! let c = |s: &str| BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap();
//! // the parabola y = 4t(1 − t)·… touches the line y = 1 at its apex: one tangency of order 2
//! let r = intersect_polynomial(&c("0 0, 1 2, 2 0"), &c("0 1, 2 1"), Domain::Unit).unwrap();
//! assert_eq!(r.intersections.len(), 1);
//! let i = &r.intersections[0];
//! assert_eq!((i.s.to_string(), i.t.to_string(), i.contact_order), ("1/2".into(), "1/2".into(), 2));
//! assert_eq!(i.kind.as_str(), "tangent");
//! ```

mod filter;
mod overlap;
pub mod winding;

use filter::{Regions, apart, candidate_regions, proved_common};

use crate::curve::bezier::BezierCurve;
use crate::error::{Error, Result};
use crate::num::CheckedRing;
use crate::num::point::Point;
use crate::num::scalar::rat;
use crate::poly::algebraic::{RealAlgebraic, resultant_zv, zv};
use crate::poly::polynomial::{derivative, trim};
use crate::rational::RationalBezier;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::One;
use std::cmp::Ordering;

/// Largest degree of either curve [`intersect`] accepts.
pub const MAX_INTERSECT_DEGREE: usize = 10;

/// Where parameters are sought.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Domain {
    /// The closed square `[0, 1]²` (ends included).
    Unit,
    /// Every real parameter.
    All,
}

/// Transversal or tangent.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// The curves cross with distinct tangents (contact order 1).
    Transversal,
    /// Contact order ≥ 2.
    Tangent,
}

impl Kind {
    /// `transversal` or `tangent`.
    pub fn as_str(self) -> &'static str {
        match self {
            Kind::Transversal => "transversal",
            Kind::Tangent => "tangent",
        }
    }
}

impl serde::Serialize for Kind {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.serialize_str(self.as_str())
    }
}

/// One intersection. JSON: `s`, `t` (exact strings), `s_float`, `t_float`, `point` (exact
/// strings, absent when irrational), `point_float`, `kind`, `contact_order`.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Intersection {
    /// The parameter on the first curve.
    pub s: RealAlgebraic,
    /// The parameter on the second curve (for a self-intersection, the larger parameter).
    pub t: RealAlgebraic,
    /// `s`, correctly rounded.
    pub s_float: f64,
    /// `t`, correctly rounded.
    pub t_float: f64,
    /// The common point, when its coordinates are rational.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub point: Option<Point<BigRational>>,
    /// The common point, each coordinate correctly rounded.
    pub point_float: [f64; 2],
    /// Transversal or tangent.
    pub kind: Kind,
    /// The contact order (see the module documentation).
    pub contact_order: usize,
}

/// A shared arc: matching closed parameter intervals, ends exact (rational, or algebraic where a
/// curve on a line turns back). JSON: `s`, `t` as `[lo, hi]` exact strings (`t` descending when
/// the second curve runs backwards), `s_float`, `t_float` the ends correctly rounded. A single
/// point (`s[0] = s[1]`, `t[0] = t[1]`) is an arc of length zero: the curves share a component
/// and only touch inside the square (collinear segments end to end, say).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Overlap {
    /// The interval on the first curve.
    pub s: [RealAlgebraic; 2],
    /// The matching interval on the second curve, `t(s_lo)` then `t(s_hi)`.
    pub t: [RealAlgebraic; 2],
    /// `s`, correctly rounded.
    pub s_float: [f64; 2],
    /// `t`, correctly rounded.
    pub t_float: [f64; 2],
}

/// Everything two curves share. JSON: `intersections` (sorted by `s`), `overlaps`.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Intersections {
    /// The isolated common points, sorted by `s`, then `t`.
    pub intersections: Vec<Intersection>,
    /// Shared arcs.
    pub overlaps: Vec<Overlap>,
}

/// `(X, Y, W)` of a rational curve as integer power forms (one common positive scale).
fn integer_forms(c: &RationalBezier<BigRational>) -> [Vec<BigInt>; 3] {
    forms_from_homogeneous(&homogeneous_rows(c))
}

/// `(X, Y, W)` as integer power forms from homogeneous control points `(wᵢxᵢ, wᵢyᵢ, wᵢ)`: every
/// number scaled by the lcm of the denominators, then `c_k = C(n,k) Δ^k b_0` (forward
/// differences) in integers.
fn forms_from_homogeneous(rows: &[[BigRational; 3]]) -> [Vec<BigInt>; 3] {
    let scale = rows.iter().flatten().fold(BigInt::one(), |acc, x| {
        if x.denom().is_one() { acc } else { num_integer::Integer::lcm(&acc, x.denom()) }
    });
    let n = rows.len() - 1;
    [0, 1, 2].map(|k| {
        let mut diff: Vec<BigInt> = rows
            .iter()
            .map(|r| if r[k].denom() == &scale { r[k].numer().clone() } else { r[k].numer() * (&scale / r[k].denom()) })
            .collect();
        let mut out = Vec::with_capacity(n + 1);
        for j in 0..=n {
            out.push(&diff[0] * crate::poly::bernstein::binomial(n, j));
            for i in 0..n - j {
                diff[i] = &diff[i + 1] - &diff[i];
            }
        }
        zv::trim(out)
    })
}

fn to_rational(p: &[BigInt]) -> Vec<BigRational> {
    p.iter().map(|c| BigRational::from_integer(c.clone())).collect()
}

/// `F(s) W_B(t) − G(t) W_A(s)` as a polynomial in `t` with coefficients in `Z[s]`.
fn cross_system(fa: &[BigInt], wa: &[BigInt], fb: &[BigInt], wb: &[BigInt]) -> Vec<zv::P> {
    let len = fb.len().max(wb.len());
    let mut out: Vec<zv::P> = (0..len)
        .map(|j| {
            let (w, g) = (coefficient(wb, j), coefficient(fb, j));
            // fa·w_j − g_j·wa
            let a: zv::P = fa.iter().map(|c| c * &w).collect();
            let b: zv::P = wa.iter().map(|c| c * &g).collect();
            zv::sub(&zv::trim(a), &zv::trim(b))
        })
        .collect();
    while out.last().is_some_and(|c| c.is_empty()) {
        out.pop();
    }
    out
}

/// A polynomial in `s` whose roots are the parameters where `A(s)` lies on `B`'s curve:
/// `Res_t(X_A(s)W_B(t) − X_B(t)W_A(s), Y_A(s)W_B(t) − Y_B(t)W_A(s))` up to a constant and the
/// factor `W_A(s)^m`. When both equations have one degree `m` in `t`, it is the determinant of
/// `B`'s implicit (Bézout) matrix at `A(s)`: `f(t)g(u) − f(u)g(t) = w·(t − u)·Σ M_ij t^i u^j`
/// with `M(x, y, w) = −x·Bz(W_B, Y_B) − y·Bz(X_B, W_B) + w·Bz(X_B, Y_B)`, `Bz(p, q)` the
/// Bézoutian `(p(t)q(u) − p(u)q(t))/(t − u)` — an `m × m` determinant (Sederberg's moving-line
/// matrix) instead of the `2m × 2m` Sylvester one, and `det M(x, y, w) = 0` is `B`'s implicit
/// equation. Otherwise (a line parallel to an axis, say) the Sylvester resultant.
fn eliminate(fa: &[Vec<BigInt>; 3], fb: &[Vec<BigInt>; 3]) -> zv::P {
    let (df, dg) = (cross_degree(&fa[0], &fa[2], &fb[0], &fb[2]), cross_degree(&fa[1], &fa[2], &fb[1], &fb[2]));
    if df != dg || df.is_none_or(|d| d < 1) {
        let f = cross_system(&fa[0], &fa[2], &fb[0], &fb[2]);
        let g = cross_system(&fa[1], &fa[2], &fb[1], &fb[2]);
        return resultant_zv(&f, &g);
    }
    let m = df.unwrap_or_default();
    // in checked i128 when the coefficients allow (no allocation), else in BigInt
    let small = |f: &[Vec<BigInt>; 3]| -> Option<[Vec<i128>; 3]> {
        let row = |p: &[BigInt]| p.iter().map(num_traits::ToPrimitive::to_i128).collect::<Option<Vec<i128>>>();
        Some([row(&f[0])?, row(&f[1])?, row(&f[2])?])
    };
    let matrix: Vec<Vec<zv::P>> = match small(fa).zip(small(fb)).and_then(|(a, b)| implicit_matrix(&a, &b, m)) {
        Some(mm) => mm
            .into_iter()
            .map(|row| row.into_iter().map(|e| zv::trim(e.into_iter().map(BigInt::from).collect())).collect())
            .collect(),
        None => implicit_matrix(fa, fb, m)
            .expect("BigInt arithmetic does not overflow")
            .into_iter()
            .map(|row| row.into_iter().map(zv::trim).collect())
            .collect(),
    };
    zv::det(matrix)
}

/// The coefficient of `t^k` (zero past the end).
fn coefficient<T: CheckedRing>(p: &[T], k: usize) -> T {
    p.get(k).cloned().unwrap_or_else(T::zero)
}

/// [`eliminate`]'s implicit matrix `M(A(s))` of order `m`, entries polynomials in `s`:
/// `M_ij = W_A·Bz(X_B, Y_B)_ij − X_A·Bz(W_B, Y_B)_ij − Y_A·Bz(X_B, W_B)_ij`. `None` on an overflow.
fn implicit_matrix<T: CheckedRing>(fa: &[Vec<T>; 3], fb: &[Vec<T>; 3], m: usize) -> Option<Vec<Vec<Vec<T>>>> {
    let (b1, b2, b3) = (bezoutian(&fb[2], &fb[1], m)?, bezoutian(&fb[0], &fb[2], m)?, bezoutian(&fb[0], &fb[1], m)?);
    let len = fa.iter().map(Vec::len).max().unwrap_or(0);
    (0..m)
        .map(|i| {
            (0..m)
                .map(|j| {
                    (0..len)
                        .map(|k| {
                            let w = coefficient(&fa[2], k).mul(&b3[i][j])?;
                            let x = coefficient(&fa[0], k).mul(&b1[i][j])?;
                            let y = coefficient(&fa[1], k).mul(&b2[i][j])?;
                            w.sub(&x)?.sub(&y)
                        })
                        .collect()
                })
                .collect()
        })
        .collect()
}

/// The degree in `t` of [`cross_system`]`(fa, wa, fb, wb)` (`None` when it vanishes), without
/// building it: the largest `j` with `fa·w_j ≠ g_j·wa` (`w_j`, `g_j` the coefficients of `t^j`).
fn cross_degree(fa: &[BigInt], wa: &[BigInt], fb: &[BigInt], wb: &[BigInt]) -> Option<usize> {
    let n = fa.len().max(wa.len());
    (0..fb.len().max(wb.len())).rev().find(|&j| {
        let (w, g) = (coefficient(wb, j), coefficient(fb, j));
        (0..n).any(|k| coefficient(fa, k) * &w != coefficient(wa, k) * &g)
    })
}

/// The Bézoutian of `p` and `q` in formal degree `m`: the `m × m` matrix `Q` with
/// `p(t)q(u) − p(u)q(t) = (t − u)·Σ Q_ij t^i u^j`. From `P_ij = p_i q_j − p_j q_i` and
/// `P_ij = Q_(i−1)j − Q_i(j−1)`: `Q_(i−1)j = P_ij + Q_i(j−1)`. One recurrence for every use:
/// integers (the implicit matrix, in `i128` or `BigInt`; the divided differences) and `f64`
/// enclosures ([`filter::no_common_root`]). `None` on an overflow.
fn bezoutian<T: CheckedRing>(p: &[T], q: &[T], m: usize) -> Option<Vec<Vec<T>>> {
    let n = m + 1;
    let mut out = vec![vec![T::zero(); n]; n];
    for j in 0..n {
        for i in (1..n).rev() {
            let prev = if j > 0 { out[i][j - 1].clone() } else { T::zero() };
            let pij = coefficient(p, i).mul(&coefficient(q, j))?.sub(&coefficient(p, j).mul(&coefficient(q, i))?)?;
            out[i - 1][j] = pij.add(&prev)?;
        }
    }
    out.truncate(m);
    for row in &mut out {
        row.truncate(m);
    }
    Some(out)
}

/// The distinct roots of `r` (integer coefficients, non-zero) in the domain, and whether `r` is
/// square-free (every root simple).
fn roots(r: &[BigInt], domain: Domain) -> (Vec<RealAlgebraic>, bool) {
    let (sf, simple) = square_free_part(r);
    if sf.len() <= 1 {
        return (vec![], simple);
    }
    let roots = match domain {
        Domain::Unit => RealAlgebraic::roots_of_square_free(sf, &rat(0), &rat(1)),
        Domain::All => RealAlgebraic::real_roots(&to_rational(&sf)),
    };
    (roots, simple)
}

/// The primitive square-free part of `r` (integer coefficients, non-zero), and whether `r`
/// was square-free already.
fn square_free_part(r: &[BigInt]) -> (Vec<BigInt>, bool) {
    let p = crate::poly::polynomial::primitive_part(r.to_vec());
    let sf = crate::poly::polynomial::square_free_integer(p.clone());
    let simple = sf.len() == p.len();
    (sf, simple)
}

/// The roots where the curve's weight does not vanish (with every real parameter allowed, a
/// root where it does is a common point at infinity, not an intersection in the plane).
fn finite_roots(roots: Vec<RealAlgebraic>, f: &[Vec<BigInt>; 3]) -> Vec<RealAlgebraic> {
    if f[2].len() == 1 {
        return roots; // a constant weight (non-zero)
    }
    let w = to_rational(&f[2]);
    roots.into_iter().filter(|x| x.sign_of(&w) != Ordering::Equal).collect()
}

/// The multiplicity of `x` as a root of `r`.
fn multiplicity(r: &[BigRational], x: &RealAlgebraic) -> usize {
    let mut p = r.to_vec();
    let mut k = 0;
    while !trim(p.clone()).is_empty() && x.sign_of(&p) == Ordering::Equal {
        k += 1;
        p = derivative(&p);
    }
    k
}

/// The point `(X/W, Y/W)` at `x`.
fn point_at(f: &[Vec<BigInt>; 3], x: &RealAlgebraic) -> [RealAlgebraic; 2] {
    let w = to_rational(&f[2]);
    [x.map_rational(&to_rational(&f[0]), &w), x.map_rational(&to_rational(&f[1]), &w)]
}

fn rational_point(p: &[RealAlgebraic; 2]) -> Option<Point<BigRational>> {
    Some(Point::new(vec![p[0].to_rational()?.clone(), p[1].to_rational()?.clone()]))
}

/// The point `(X/W, Y/W)` at a rational parameter.
fn point_at_rational(f: &[Vec<BigInt>; 3], x: &BigRational) -> Point<BigRational> {
    let eval = |p: &[BigInt]| crate::poly::algebraic::value_at(p, x);
    let w = eval(&f[2]);
    Point::new(vec![eval(&f[0]) / &w, eval(&f[1]) / &w])
}

/// One curve's forms with what the exact-point decision needs about them, computed once.
struct Side<'a> {
    f: &'a [Vec<BigInt>; 3],
    /// The degree of the homogeneous form.
    degree: usize,
    /// `X/W` or `Y/W` is not constant.
    moves: bool,
    /// [`RealAlgebraic::degree_lower_bound`] of the parameters' polynomial (shared by every
    /// irrational root of one resultant), computed on first use.
    bound: std::cell::OnceCell<usize>,
    /// The divided differences `D_X`, `D_Y` of [`Side::irrational_at`] ([`divided_difference`]),
    /// computed on first use.
    partner: std::cell::OnceCell<[Vec<zv::P>; 2]>,
}

impl<'a> Side<'a> {
    fn new(f: &'a [Vec<BigInt>; 3]) -> Self {
        let n = f.iter().map(Vec::len).max().unwrap_or(1);
        Side {
            f,
            degree: n.saturating_sub(1),
            moves: !overlap::is_point(f),
            bound: std::cell::OnceCell::new(),
            partner: std::cell::OnceCell::new(),
        }
    }

    /// The point at the irrational `x` (`narrow`: the same number, a tight interval) is
    /// provably irrational. Were it a rational point `P`, `x` would be a root of `X − P_x W` and
    /// `Y − P_y W`, so every conjugate `u ≠ x` of `x` (there is one: `x` is irrational) would be
    /// one too, and the curve would pass through `P` at `u`: the divided differences
    /// `D_F(x, u) = (F(x)W(u) − F(u)W(x))/(x − u)` (`F = X, Y`) would share the root `u`. So
    /// [`filter::no_common_root`] at `x` proves it (curves of degree ≤ 5; `f64` enclosures).
    /// Else the degree of `x`: `P` rational makes it at most the curve's degree, so a lower bound
    /// above that proves it ([`RealAlgebraic::degree_lower_bound`], a factorization modulo
    /// primes: dearer).
    fn irrational_at(&self, x: &RealAlgebraic, narrow: &RealAlgebraic) -> bool {
        if x.to_rational().is_some() || !self.moves {
            return false;
        }
        if self.degree <= filter::MAX_BEZOUT_ORDER + 1 {
            let [dx, dy] = self.partner.get_or_init(|| {
                [divided_difference(&self.f[0], &self.f[2]), divided_difference(&self.f[1], &self.f[2])]
            });
            if filter::no_common_root(dx, dy, narrow) {
                return true;
            }
        }
        *self.bound.get_or_init(|| x.degree_lower_bound(self.degree + 1)) > self.degree
    }

    /// The point at `x`, correctly rounded.
    fn point_float(&self, x: &RealAlgebraic) -> [f64; 2] {
        let x = x.narrowed(60);
        [x.map_rational_to_f64(&self.f[0], &self.f[2]), x.map_rational_to_f64(&self.f[1], &self.f[2])]
    }
}

/// The common point `A(s) = B(t)` when it is rational, by the cheapest route that decides: a
/// rational parameter, an irrationality proof ([`Side::irrational_at`]), or the exact point
/// (computed once per root, `cached`).
fn common_point(
    (a, s, sn): (&Side, &RealAlgebraic, &RealAlgebraic),
    (b, t, tn): (&Side, &RealAlgebraic, &RealAlgebraic),
    cached: &mut Option<[RealAlgebraic; 2]>,
) -> Option<Point<BigRational>> {
    if let Some(x) = s.to_rational() {
        return Some(point_at_rational(a.f, x));
    }
    if let Some(x) = t.to_rational() {
        return Some(point_at_rational(b.f, x));
    }
    // the curve of lower degree first: its proof asks less (a line's, nothing beyond irrationality)
    let ((c, x, xn), (d, y, yn)) =
        if a.degree <= b.degree { ((a, s, sn), (b, t, tn)) } else { ((b, t, tn), (a, s, sn)) };
    if c.irrational_at(x, xn) || d.irrational_at(y, yn) {
        return None;
    }
    rational_point(cached.get_or_insert_with(|| point_at(a.f, s)))
}

/// [`intersect`] of two polynomial curves.
///
/// # Errors
/// As [`intersect`].
pub fn intersect_polynomial(
    a: &BezierCurve<BigRational>,
    b: &BezierCurve<BigRational>,
    domain: Domain,
) -> Result<Intersections> {
    for c in [a, b] {
        check_shape(c.dim(), c.degree())?;
    }
    let rows = |c: &BezierCurve<BigRational>| -> Vec<[BigRational; 3]> {
        c.points().iter().map(|p| [p.coords[0].clone(), p.coords[1].clone(), rat(1)]).collect()
    };
    intersect_rows(&rows(a), &rows(b), domain)
}

/// The homogeneous control points `(wᵢxᵢ, wᵢyᵢ, wᵢ)`.
fn homogeneous_rows(c: &RationalBezier<BigRational>) -> Vec<[BigRational; 3]> {
    c.homogeneous().points().iter().map(|p| [p.coords[0].clone(), p.coords[1].clone(), p.coords[2].clone()]).collect()
}

/// The intersections of the curves with homogeneous control points `ra` and `rb` (checked by
/// the caller): none at once when the subdivision filter proves the curves apart on `[0, 1]²`,
/// otherwise the exact route, looking for parameters only where the filter left candidates
/// ([`filter::candidate_regions`]).
fn intersect_rows(ra: &[[BigRational; 3]], rb: &[[BigRational; 3]], domain: Domain) -> Result<Intersections> {
    let regions = if domain == Domain::Unit { candidate_regions(ra, rb) } else { Regions::Anywhere };
    if let Regions::Apart = regions {
        return Ok(Intersections { intersections: vec![], overlaps: vec![] });
    }
    intersect_forms(&forms_from_homogeneous(ra), &forms_from_homogeneous(rb), domain, &regions)
}

/// Planar, and of degree at most [`MAX_INTERSECT_DEGREE`].
fn check_shape(dim: usize, degree: usize) -> Result<()> {
    if dim != 2 {
        return Err(Error::DimensionMismatch { expected: 2, found: dim });
    }
    if degree > MAX_INTERSECT_DEGREE {
        return Err(Error::TooLarge { what: "degree to intersect", value: degree, limit: MAX_INTERSECT_DEGREE });
    }
    Ok(())
}

fn check(c: &RationalBezier<BigRational>, domain: Domain) -> Result<()> {
    check_shape(c.dim(), c.degree())?;
    if domain == Domain::Unit {
        c.check_defined(&rat(0), &rat(1))?;
    }
    Ok(())
}

/// Every intersection of two planar curves (polynomial or rational, degree ≤
/// [`MAX_INTERSECT_DEGREE`]) with parameters in the domain, and their shared arcs.
///
/// Overlaps: when the curves share a component, the shared arcs are reported as matching
/// parameter intervals inside `[0, 1]²` (also with [`Domain::All`], where only the isolated
/// intersections use every real parameter): for curves that are Möbius reparametrizations of
/// one another, `B(t) = A((αt + β)/(γt + δ))` (sub-segments, reversed, degree-elevated and
/// reweighted copies, polynomial or rational), with the points where the shared curve crosses
/// itself as isolated intersections; for curves on one line (any parametrization, turn-backs
/// included) arc by monotone piece, ends exact algebraic numbers; for a single point, the
/// parameters where the other curve passes through it (see the private `overlap` module).
///
/// # Errors
/// [`Error::DimensionMismatch`] unless planar; [`Error::TooLarge`] above the degree limit;
/// [`Error::WeightsVanish`] when a weight polynomial vanishes on `[0, 1]` (unit domain);
/// [`Error::InvalidArgument`] for a shared component that one curve traces more than once off a
/// line (an improper parametrization, such as `(s², s⁴)` on `y = x²`), or, with
/// [`Domain::All`], when a weight vanishes on `[0, 1]` where the arcs are sought.
pub fn intersect(
    a: &RationalBezier<BigRational>,
    b: &RationalBezier<BigRational>,
    domain: Domain,
) -> Result<Intersections> {
    intersect_within(a, b, domain, &crate::work::Budget::unlimited())
}

/// The estimated work of intersecting `a` with `b` ([`crate::work::intersection`]).
fn estimate(a: &RationalBezier<BigRational>, b: &RationalBezier<BigRational>) -> f64 {
    let beta = |c: &RationalBezier<BigRational>| crate::work::max_bits(c.homogeneous().points());
    crate::work::intersection(a.degree(), b.degree(), beta(a).max(beta(b)))
}

/// [`intersect`] within a work budget, checked before any work starts.
///
/// # Errors
/// As [`intersect`]; [`Error::WorkLimit`] when the estimate exceeds `budget`.
pub fn intersect_within(
    a: &RationalBezier<BigRational>,
    b: &RationalBezier<BigRational>,
    domain: Domain,
    budget: &crate::work::Budget,
) -> Result<Intersections> {
    check(a, domain)?;
    check(b, domain)?;
    budget.check(format!("intersecting degree {} with degree {}", a.degree(), b.degree()), estimate(a, b))?;
    intersect_rows(&homogeneous_rows(a), &homogeneous_rows(b), domain)
}

/// The intersections of the curves with integer power forms `fa` and `fb` (checked by the
/// caller); [`overlap::overlap`] answers when they share a component.
fn intersect_forms(
    fa: &[Vec<BigInt>; 3],
    fb: &[Vec<BigInt>; 3],
    domain: Domain,
    regions: &Regions,
) -> Result<Intersections> {
    // a single point makes the resultant in the other curve's parameter a constant: decide it
    // as a shared component (the point on the curve, or nothing)
    if overlap::is_point(fa) || overlap::is_point(fb) {
        return overlap::overlap(fa, fb, domain);
    }
    let r = eliminate(fa, fb);
    if r.is_empty() {
        return overlap::overlap(fa, fb, domain);
    }
    let t_poly = eliminate(fb, fa);
    // the system A(σ) − B(τ) in f64 enclosures, for the certified steps (polynomial curves)
    let sys = filter::System::new(fa, fb);
    if let (Regions::Within { boxes }, Some(sys)) = (regions, &sys)
        && let Some(found) = solved_in_boxes(sys, (fa, fb), (&r, &t_poly), boxes)
    {
        return Ok(found);
    }
    // with every real parameter allowed, a root where a weight vanishes is a common point at
    // infinity, not an intersection in the plane
    let ((ss, r_simple), (ts, t_simple)) = (roots(&r, domain), roots(&t_poly, domain));
    let (mut ss, mut ts) = (finite_roots(ss, fa), finite_roots(ts, fb));
    // each root's interval in f64, widened outwards, for the filter's candidate boxes
    let outward = filter::outward;
    let boxes = match regions {
        Regions::Within { boxes } => Some(&boxes[..]),
        _ => None,
    };
    if let Some(boxes) = boxes {
        // a root whose interval misses every box's side is no intersection's parameter
        let meets = |x: &RealAlgebraic, side: usize| {
            let (lo, hi) = outward(x);
            boxes.iter().any(|b| lo <= b[2 * side + 1] && b[2 * side] <= hi)
        };
        ss.retain(|x| meets(x, 0));
        ts.retain(|x| meets(x, 1));
    }
    let (rr, tr) = (to_rational(&r), to_rational(&t_poly));
    // a square-free resultant: every root simple, every contact order 1
    let simple = r_simple || t_simple;
    let (side_a, side_b) = (Side::new(fa), Side::new(fb));
    // exact points only for pairs that neither the enclosures nor the Krawczyk proof decide
    // (most pairs are not intersections, and mapping a root to its point is the costly step)
    let mut pa: Vec<Option<[RealAlgebraic; 2]>> = vec![None; ss.len()];
    let mut pb: Vec<Option<[RealAlgebraic; 2]>> = vec![None; ts.len()];
    // each root narrowed to half an f64 spacing, with its f64, on first need
    let mut na: Vec<Option<(RealAlgebraic, f64)>> = vec![None; ss.len()];
    let mut nb: Vec<Option<(RealAlgebraic, f64)>> = vec![None; ts.len()];
    let mut out = vec![];
    let fs: Vec<(f64, f64)> = ss.iter().map(outward).collect();
    let ft: Vec<(f64, f64)> = ts.iter().map(outward).collect();
    for (i, s) in ss.iter().enumerate() {
        for (j, t) in ts.iter().enumerate() {
            if let Some(boxes) = boxes
                && !boxes.iter().any(|b| fs[i].0 <= b[1] && b[0] <= fs[i].1 && ft[j].0 <= b[3] && b[2] <= ft[j].1)
            {
                continue; // no candidate box holds both parameters
            }
            if apart(fa, s, fb, t) {
                continue;
            }
            let (sn, s_float) = na[i].get_or_insert_with(|| s.narrowed_with_f64());
            let (tn, t_float) = nb[j].get_or_insert_with(|| t.narrowed_with_f64());
            if apart(fa, sn, fb, tn) {
                continue;
            }
            let (s_float, t_float) = (*s_float, *t_float);
            let same = sys.as_ref().is_some_and(|sys| proved_common(sys, s, t, (s_float, t_float))) || {
                let p = pa[i].get_or_insert_with(|| point_at(fa, s)).clone();
                let q = pb[j].get_or_insert_with(|| point_at(fb, t));
                p[0] == q[0] && p[1] == q[1]
            };
            if same {
                let order = if simple { 1 } else { multiplicity(&rr, s).min(multiplicity(&tr, t)).max(1) };
                out.push(Intersection {
                    s_float,
                    t_float,
                    point: common_point(
                        (&side_a, s, na[i].as_ref().map_or(s, |n| &n.0)),
                        (&side_b, t, nb[j].as_ref().map_or(t, |n| &n.0)),
                        &mut pa[i],
                    ),
                    point_float: side_a.point_float(na[i].as_ref().map_or(s, |n| &n.0)),
                    kind: if order == 1 { Kind::Transversal } else { Kind::Tangent },
                    contact_order: order,
                    s: s.clone(),
                    t: t.clone(),
                });
            }
        }
    }
    Ok(Intersections { intersections: out, overlaps: vec![] })
}

/// The fast route of [`intersect_forms`] for polynomial curves on the unit square (their system
/// `sys`, resultants `r` in `s` and `t_poly` in `t`, non-zero): the filter's candidate `boxes` solved by
/// [`filter::solve`] (each proved empty or holding exactly one transversal crossing), then
/// each crossing's parameters made exact without isolating the resultants' roots: the
/// square-free part `p` of a resultant vanishes at the crossing's parameter `σ` (the system has
/// a common root there); when `p′` keeps its sign on the crossing's box and on the rounding cell
/// of an `f64` `u` near `σ` (the numbers nearer to `u` than to its neighbours), and `p` changes
/// sign across that cell, the cell holds exactly one root of `p`, and it is `σ`: so `σ` is that
/// root, `u` is `σ` correctly rounded, and the cell is an isolating interval. `σ` is irrational
/// when `p` provably has no rational root, else checked for one. `None` (the exact route
/// decides) whenever a step is not proved, or the resultants are both not square-free (contact
/// orders then come from multiplicities).
fn solved_in_boxes(
    sys: &filter::System,
    (fa, fb): (&[Vec<BigInt>; 3], &[Vec<BigInt>; 3]),
    (r, t_poly): (&[BigInt], &[BigInt]),
    boxes: &[[f64; 4]],
) -> Option<Intersections> {
    use crate::poly::polynomial::derivative_integer;
    let zeros = filter::solve(sys, boxes)?;
    if zeros.is_empty() {
        return Some(Intersections { intersections: vec![], overlaps: vec![] });
    }
    let ((ps, s_simple), (pt, t_simple)) = (square_free_part(r), square_free_part(t_poly));
    if !(s_simple || t_simple) || ps.len() < 2 || pt.len() < 2 {
        return None;
    }
    // without rational roots the cells' roots are irrational; else each is checked
    let no_rational = crate::poly::algebraic::no_rational_roots;
    let (s_irrational, t_irrational) = (no_rational(&ps), no_rational(&pt));
    let (dps, dpt) = (derivative_integer(&ps), derivative_integer(&pt));
    let (dpsc, dptc) = (filter::Coeffs::new(&dps), filter::Coeffs::new(&dpt));
    let (side_a, side_b) = (Side::new(fa), Side::new(fb));
    let mut out: Vec<Intersection> = vec![];
    for z in zeros {
        let (s, s_float) = root_in_cell(&ps, (&dps, &dpsc), z[0].ends(), s_irrational)?;
        let (t, t_float) = root_in_cell(&pt, (&dpt, &dptc), z[1].ends(), t_irrational)?;
        if out.iter().any(|x| x.s_float == s_float && x.t_float == t_float) {
            continue; // the same crossing, from a box sharing an edge
        }
        let mut cached = None;
        out.push(Intersection {
            s_float,
            t_float,
            point: common_point((&side_a, &s, &s), (&side_b, &t, &t), &mut cached),
            point_float: side_a.point_float(&s),
            kind: Kind::Transversal,
            contact_order: 1,
            s,
            t,
        });
    }
    out.sort_by(|a, b| a.s_float.total_cmp(&b.s_float).then(a.t_float.total_cmp(&b.t_float)));
    Some(Intersections { intersections: out, overlaps: vec![] })
}

/// The root of `p` (square-free, primitive; `dp` its derivative, exact and enclosed) that lies
/// in `[lo, hi]`, where a zero of the system puts one, with its correctly rounded `f64`: the
/// rounding cell of an `f64` `u` (one exact Newton step from the midpoint, then its neighbours)
/// where `p` changes sign, with `p′` of one sign on the cell and on `[lo, hi]` (so one root in
/// both: the one in `[lo, hi]`); `irrational` when `p` has no rational root, else the root is
/// checked for one. `None` when no candidate is proved.
fn root_in_cell(
    p: &[BigInt],
    (dp, dpc): (&[BigInt], &filter::Coeffs),
    (lo, hi): (f64, f64),
    irrational: bool,
) -> Option<(RealAlgebraic, f64)> {
    let mid = lo + (hi - lo) / 2.0;
    // the box is some ulps wide: one exact Newton step from its midpoint finds the f64
    let m = crate::poly::algebraic::newton_step_f64(p, dp, mid).filter(|u| lo <= *u && *u <= hi).unwrap_or(mid);
    for u in [m, m.next_up(), m.next_down()] {
        let (below, above) = (u.next_down(), u.next_up());
        if !(u > 0.0 && above.is_finite() && dpc.nonzero_on(lo.min(below), hi.max(above))) {
            continue;
        }
        let Some(cell) = crate::poly::algebraic::f64_cell(u) else { continue };
        if let Some(x) = RealAlgebraic::certified_root(p.to_vec(), cell.0, cell.1, irrational) {
            return Some((x, u));
        }
    }
    None
}

/// `(F(s)W(t) − F(t)W(s)) / (s − t)` as a polynomial in `t` with coefficients in `Z[s]`.
fn divided_difference(f: &[BigInt], w: &[BigInt]) -> Vec<zv::P> {
    // Q[i][j], the coefficient of s^i t^j: the Bézoutian of f and w in formal degree n
    let n = f.len().max(w.len());
    let q = bezoutian(f, w, n).expect("BigInt arithmetic does not overflow");
    let mut out: Vec<zv::P> = (0..n).map(|j| zv::trim((0..n).map(|i| q[i][j].clone()).collect())).collect();
    while out.last().is_some_and(|c| c.is_empty()) {
        out.pop();
    }
    out
}

/// Every self-intersection `A(s) = A(t)`, `s < t`, with both parameters in the domain (a
/// cubic's double point is the special case: it agrees with [`crate::classify::classify`]).
/// A curve on a line that turns back overlaps itself: its `overlaps` pair different monotone
/// pieces (`s` on the earlier one), inside `[0, 1]²`.
///
/// # Errors
/// As [`intersect`]; [`Error::InvalidArgument`] when the curve traces a curve more than once
/// off a line (every point of an arc would be a self-intersection), or is a single point.
pub fn self_intersect(a: &RationalBezier<BigRational>, domain: Domain) -> Result<Intersections> {
    self_intersect_within(a, domain, &crate::work::Budget::unlimited())
}

/// [`self_intersect`] within a work budget, checked before any work starts.
///
/// # Errors
/// As [`self_intersect`]; [`Error::WorkLimit`] when the estimate exceeds `budget`.
pub fn self_intersect_within(
    a: &RationalBezier<BigRational>,
    domain: Domain,
    budget: &crate::work::Budget,
) -> Result<Intersections> {
    check(a, domain)?;
    budget.check(format!("self-intersecting degree {}", a.degree()), estimate(a, a))?;
    self_intersections_of_forms(&integer_forms(a), domain)
}

/// [`self_intersect`] of the curve with integer power forms `fa` (checked by the caller).
fn self_intersections_of_forms(fa: &[Vec<BigInt>; 3], domain: Domain) -> Result<Intersections> {
    let dx = divided_difference(&fa[0], &fa[2]);
    let dy = divided_difference(&fa[1], &fa[2]);
    if dx.is_empty() || dy.is_empty() {
        // a coordinate is constant: the curve lies on a line; pairs come from the other one
        let d = if dx.is_empty() { &dy } else { &dx };
        if d.is_empty() {
            return Err(Error::InvalidArgument { message: "the curve is a single point".into() });
        }
    }
    let r = resultant_zv(&dx, &dy);
    if r.is_empty() {
        return overlap::self_overlap(fa);
    }
    let (ss, simple) = roots(&r, domain);
    let ss = finite_roots(ss, fa);
    let rr = to_rational(&r);
    let side = Side::new(fa);
    // exact points only for pairs whose enclosures cannot be told apart (see `intersect_within`)
    let mut pts: Vec<Option<[RealAlgebraic; 2]>> = vec![None; ss.len()];
    let mut narrow: Vec<Option<(RealAlgebraic, f64)>> = vec![None; ss.len()];
    let mut out = vec![];
    for i in 0..ss.len() {
        for j in i + 1..ss.len() {
            if apart(fa, &ss[i], fa, &ss[j]) {
                continue;
            }
            for k in [i, j] {
                narrow[k].get_or_insert_with(|| ss[k].narrowed_with_f64());
            }
            let (Some((si, _)), Some((sj, _))) = (&narrow[i], &narrow[j]) else { continue };
            if apart(fa, si, fa, sj) {
                continue;
            }
            let p = pts[i].get_or_insert_with(|| point_at(fa, &ss[i])).clone();
            let q = pts[j].get_or_insert_with(|| point_at(fa, &ss[j]));
            if p[0] == q[0] && p[1] == q[1] {
                let order = if simple { 1 } else { multiplicity(&rr, &ss[i]).min(multiplicity(&rr, &ss[j])).max(1) };
                let (Some((si, s_float)), Some((_, t_float))) = (&narrow[i], &narrow[j]) else { continue };
                out.push(Intersection {
                    s_float: *s_float,
                    t_float: *t_float,
                    point: rational_point(&p),
                    point_float: side.point_float(si),
                    kind: if order == 1 { Kind::Transversal } else { Kind::Tangent },
                    contact_order: order,
                    s: ss[i].clone(),
                    t: ss[j].clone(),
                });
            }
        }
    }
    Ok(Intersections { intersections: out, overlaps: vec![] })
}

/// A float library's intersection parameters checked against the exact answer (the
/// intersection oracle for float code). A float pair `(s, t)` **matches** an exact intersection
/// `(σ, τ)` when `|s − σ| ≤ tol` and `|t − τ| ≤ tol` (decided exactly), or lies on an overlap
/// (its `s` within `tol` of the overlap's `s` interval); exact intersections nobody matched are
/// `missed`, float pairs matching nothing `spurious`, a second pair for one exact intersection a
/// `duplicate`.
///
/// # Example
/// ```
/// use casteljau::intersect::{check_intersections_f64, Domain};
/// let parabola = [[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]];
/// let line = [[0.0, 1.0], [2.0, 1.0]];
/// // a float library that misses the tangency at (1/2, 1/2)
/// let d = check_intersections_f64(&parabola, &line, &[], 1e-9, Domain::Unit).unwrap();
/// assert_eq!((d.len(), d[0].kind.as_str(), d[0].s.as_str()), (1, "missed", "1/2"));
/// assert!(check_intersections_f64(&parabola, &line, &[(0.5, 0.5)], 1e-9, Domain::Unit).unwrap().is_empty());
/// ```
///
/// # Errors
/// As [`intersect`]; [`Error::InvalidArgument`] for non-finite coordinates or tolerance.
pub fn check_intersections_f64(
    a: &[[f64; 2]],
    b: &[[f64; 2]],
    float: &[(f64, f64)],
    tol: f64,
    domain: Domain,
) -> Result<Vec<IntersectionDisagreement>> {
    let bad = |m: String| Error::InvalidArgument { message: m };
    if !(tol.is_finite() && tol >= 0.0) {
        return Err(bad(format!("tolerance {tol} must be finite and ≥ 0")));
    }
    let exact = |x: f64| BigRational::from_float(x).ok_or_else(|| bad(format!("{x} is not finite")));
    let curve = |pts: &[[f64; 2]]| -> Result<BezierCurve<BigRational>> {
        BezierCurve::new(
            pts.iter().map(|p| Ok(Point::new(vec![exact(p[0])?, exact(p[1])?]))).collect::<Result<Vec<_>>>()?,
        )
    };
    let r = intersect_polynomial(&curve(a)?, &curve(b)?, domain)?;
    let tol_q = exact(tol)?;
    let near = |e: &RealAlgebraic, f: &BigRational| {
        *e >= RealAlgebraic::from(f.clone() - &tol_q) && *e <= RealAlgebraic::from(f.clone() + &tol_q)
    };
    let mut matched = vec![false; r.intersections.len()];
    let mut out = vec![];
    for &(s, t) in float {
        let (Some(sq), Some(tq)) = (BigRational::from_float(s), BigRational::from_float(t)) else {
            out.push(IntersectionDisagreement::spurious(s, t));
            continue;
        };
        let on_overlap = r.overlaps.iter().any(|o| {
            o.s[0] <= RealAlgebraic::from(sq.clone() + &tol_q) && o.s[1] >= RealAlgebraic::from(sq.clone() - &tol_q)
        });
        if on_overlap {
            continue;
        }
        let hits: Vec<usize> = (0..r.intersections.len())
            .filter(|&i| near(&r.intersections[i].s, &sq) && near(&r.intersections[i].t, &tq))
            .collect();
        match hits.iter().find(|&&i| !matched[i]) {
            Some(&i) => matched[i] = true,
            None if !hits.is_empty() => {
                let e = &r.intersections[hits[0]];
                out.push(IntersectionDisagreement {
                    kind: crate::classify::oracle::Kind::Duplicate,
                    s: e.s.to_string(),
                    t: e.t.to_string(),
                    float: Some((s, t)),
                    exact_float: Some((e.s_float, e.t_float)),
                });
            }
            None => out.push(IntersectionDisagreement::spurious(s, t)),
        }
    }
    for (e, m) in r.intersections.iter().zip(matched) {
        if !m {
            out.push(IntersectionDisagreement {
                kind: crate::classify::oracle::Kind::Missed,
                s: e.s.to_string(),
                t: e.t.to_string(),
                float: None,
                exact_float: Some((e.s_float, e.t_float)),
            });
        }
    }
    Ok(out)
}

/// One disagreement of [`check_intersections_f64`]. JSON: `kind` (`missed`, `spurious`,
/// `duplicate`), `s`, `t` (exact strings; empty for a spurious pair), `float` (the library's
/// pair), `exact_float`.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct IntersectionDisagreement {
    /// What kind of disagreement.
    pub kind: crate::classify::oracle::Kind,
    /// The exact `s` (empty when spurious).
    pub s: String,
    /// The exact `t` (empty when spurious).
    pub t: String,
    /// The float library's pair.
    pub float: Option<(f64, f64)>,
    /// The exact pair, correctly rounded.
    pub exact_float: Option<(f64, f64)>,
}

impl IntersectionDisagreement {
    fn spurious(s: f64, t: f64) -> Self {
        IntersectionDisagreement {
            kind: crate::classify::oracle::Kind::Spurious,
            s: String::new(),
            t: String::new(),
            float: Some((s, t)),
            exact_float: None,
        }
    }
}

#[cfg(test)]
mod filter_tests {
    use super::*;
    use crate::num::scalar::rat;

    fn cubic(v: [i64; 8]) -> RationalBezier<BigRational> {
        let pts = (0..4).map(|i| Point::new(vec![rat(v[2 * i]), rat(v[2 * i + 1])])).collect();
        RationalBezier::new(pts, vec![rat(1); 4]).unwrap()
    }

    /// Every decision of the enclosure filter and of the Krawczyk proof, checked exactly on every
    /// root pair of random font-like cubic pairs: `apart` only for different points,
    /// `proved_common` only for equal ones, and the proof succeeds on most crossings.
    #[test]
    fn enclosure_filter_and_krawczyk_proof_agree_with_exact_points() {
        let mut next = crate::num::symmetric(0x9E37_79B9_7F4A_7C15);
        let (mut proved, mut crossings) = (0, 0);
        for _ in 0..12 {
            let (a, b) = (cubic(std::array::from_fn(|_| next(2048))), cubic(std::array::from_fn(|_| next(2048))));
            let (fa, fb) = (integer_forms(&a), integer_forms(&b));
            let sys = filter::System::new(&fa, &fb).expect("polynomial curves");
            let r = resultant_zv(
                &cross_system(&fa[0], &fa[2], &fb[0], &fb[2]),
                &cross_system(&fa[1], &fa[2], &fb[1], &fb[2]),
            );
            let t_poly = resultant_zv(
                &cross_system(&fb[0], &fb[2], &fa[0], &fa[2]),
                &cross_system(&fb[1], &fb[2], &fa[1], &fa[2]),
            );
            for s in roots(&r, Domain::Unit).0 {
                for t in roots(&t_poly, Domain::Unit).0 {
                    let (p, q) = (point_at(&fa, &s), point_at(&fb, &t));
                    let equal = p[0] == q[0] && p[1] == q[1];
                    if apart(&fa, &s, &fb, &t) {
                        assert!(!equal, "apart, but A(s) = B(t)");
                    }
                    if proved_common(&sys, &s, &t, (s.to_f64(), t.to_f64())) {
                        assert!(equal, "proved common, but A(s) ≠ B(t)");
                        proved += 1;
                    }
                    crossings += usize::from(equal);
                }
            }
        }
        // the proof may decline a crossing (the exact comparison then decides), but not most
        assert!(crossings > 0 && 4 * proved >= 3 * crossings, "{proved} of {crossings} crossings proved");
    }

    /// The divided-difference proof that a point is irrational ([`Side::irrational_at`]) never
    /// errs, checked against the exact point: on random rational cubics every irrational root of
    /// a resultant with a line (whose intersections are a double point or not); and it declines
    /// at the double point `(0, 0)` of `(s² − 2, s³ − 2s)`, reached at `s = ±√2`.
    #[test]
    fn irrational_point_proof_agrees_with_exact_points() {
        let b = |v: &[i64]| v.iter().map(|&c| BigInt::from(c)).collect::<Vec<_>>();
        let nodal = [b(&[-2, 0, 1]), b(&[0, -2, 0, 1]), b(&[1])];
        let side = Side::new(&nodal);
        let sqrt2 = RealAlgebraic::real_roots(&[rat(-2), rat(0), rat(1)])[1].clone();
        let (narrow, _) = sqrt2.narrowed_with_f64();
        assert!(!filter::no_common_root(
            &divided_difference(&nodal[0], &nodal[2]),
            &divided_difference(&nodal[1], &nodal[2]),
            &narrow
        ));
        assert!(!side.irrational_at(&sqrt2, &narrow));
        let sqrt3 = RealAlgebraic::real_roots(&[rat(-3), rat(0), rat(1)])[1].clone();
        assert!(side.irrational_at(&sqrt3, &sqrt3.narrowed_with_f64().0)); // (1, √3)
        let mut next = crate::num::symmetric(0x2545_F491_4F6C_DD1D);
        let mut proved = 0;
        for _ in 0..40 {
            let f: [Vec<BigInt>; 3] = [
                b(&[next(9), next(9), next(9), next(9)]),
                b(&[next(9), next(9), next(9), next(9)]),
                b(&[next(3).abs() + 1, next(2), next(2)]),
            ];
            let line = [b(&[next(9), next(9)]), b(&[next(9), next(9)]), b(&[1])];
            let r = eliminate(&f, &line);
            if r.is_empty() {
                continue;
            }
            let side = Side::new(&f);
            for x in roots(&r, Domain::All).0.into_iter().filter(|x| x.to_rational().is_none()) {
                if x.sign_of(&to_rational(&f[2])) == Ordering::Equal {
                    continue;
                }
                if side.irrational_at(&x, &x.narrowed_with_f64().0) {
                    assert!(rational_point(&point_at(&f, &x)).is_none(), "proved irrational, but rational at {x}");
                    proved += 1;
                }
            }
        }
        assert!(proved > 20, "{proved} irrational points proved");
    }

    /// The box solver's route ([`solved_in_boxes`]) gives the exact route's answer, strings
    /// included (the displayed interval does not depend on the route), on random font-like
    /// cubic pairs, random quadratic × cubic pairs and cubics against lines; and it answers most
    /// of the pairs that meet.
    #[test]
    fn box_solver_agrees_with_the_exact_route() {
        let mut next = crate::num::symmetric(0x0DDB_1A5E_5BAD_5EED);
        let rows =
            |v: &[i64]| -> Vec<[BigRational; 3]> { v.chunks(2).map(|p| [rat(p[0]), rat(p[1]), rat(1)]).collect() };
        let (mut meeting, mut fast, mut crossings) = (0, 0, 0);
        for k in 0..90 {
            let degree_a = [3, 2, 3][k % 3];
            let degree_b = [3, 3, 1][k % 3];
            let a: Vec<i64> = (0..2 * (degree_a + 1)).map(|_| next(2048)).collect();
            let b: Vec<i64> = (0..2 * (degree_b + 1)).map(|_| next(2048)).collect();
            let (ra, rb) = (rows(&a), rows(&b));
            let (fa, fb) = (forms_from_homogeneous(&ra), forms_from_homogeneous(&rb));
            let exact = intersect_forms(&fa, &fb, Domain::Unit, &Regions::Anywhere).unwrap();
            if exact.intersections.is_empty() {
                continue;
            }
            meeting += 1;
            crossings += exact.intersections.len();
            let Regions::Within { boxes } = candidate_regions(&ra, &rb) else { panic!("they meet") };
            let sys = filter::System::new(&fa, &fb).expect("polynomial curves");
            let Some(found) = solved_in_boxes(&sys, (&fa, &fb), (&eliminate(&fa, &fb), &eliminate(&fb, &fa)), &boxes)
            else {
                continue;
            };
            fast += 1;
            assert_eq!(found, exact, "{a:?} × {b:?}");
            let text = |r: &Intersections| {
                r.intersections.iter().map(|x| format!("{} {} {:?}", x.s, x.t, x.point)).collect::<Vec<_>>()
            };
            assert_eq!(text(&found), text(&exact));
        }
        assert!(meeting > 20 && crossings > meeting && 5 * fast >= 4 * meeting, "{fast} of {meeting} answered");
    }

    /// Rational crossing parameters on the box solver's route: a line through `A(1/3)` with
    /// `B(1/3) = A(1/3)` makes both resultants' square-free parts have a rational root, so the
    /// cells' roots are checked for rationals (`1/3` found, the point exact) and the answer is the
    /// exact route's.
    #[test]
    fn box_solver_finds_rational_parameters() {
        let mut next = crate::num::symmetric(0x7A11_0C0F_FEE5_1DE5);
        let third = BigRational::new(1.into(), 3.into());
        let mut answered = 0;
        for _ in 0..20 {
            let a = cubic(std::array::from_fn(|_| next(2048)));
            let p = a.eval(&third).unwrap();
            let d = [rat(next(1000)), rat(next(1000))];
            let line =
                |k: i64| Point::new(vec![p.coords[0].clone() + &d[0] * rat(k), p.coords[1].clone() + &d[1] * rat(k)]);
            let b = RationalBezier::new(vec![line(-1), line(2)], vec![rat(1); 2]).unwrap();
            let (ra, rb) = (homogeneous_rows(&a), homogeneous_rows(&b));
            let (fa, fb) = (forms_from_homogeneous(&ra), forms_from_homogeneous(&rb));
            let exact = intersect_forms(&fa, &fb, Domain::Unit, &Regions::Anywhere).unwrap();
            let hit = exact.intersections.iter().find(|x| x.s.to_rational() == Some(&third)).expect("A(1/3) is on B");
            assert_eq!((hit.t.to_rational(), hit.point.as_ref()), (Some(&third), Some(&Point::new(p.coords.clone()))));
            let Regions::Within { boxes } = candidate_regions(&ra, &rb) else { panic!("they meet") };
            let sys = filter::System::new(&fa, &fb).expect("polynomial curves");
            if let Some(found) = solved_in_boxes(&sys, (&fa, &fb), (&eliminate(&fa, &fb), &eliminate(&fb, &fa)), &boxes)
            {
                assert_eq!(found, exact);
                answered += 1;
            }
        }
        assert!(answered >= 15, "{answered} of 20 answered by the box solver");
    }

    /// The subdivision filter never changes an answer: random font-like pairs, and pairs that
    /// touch at ends or are tangent, give the same intersections with the filter's regions as
    /// without; and it proves most non-intersecting pairs apart.
    #[test]
    fn subdivision_filter_keeps_every_intersection() {
        let mut next = crate::num::symmetric(0x51_7CC1_B727_220A);
        type Rows = Vec<[BigRational; 3]>;
        let rows = |v: &[i64]| -> Rows { v.chunks(2).map(|p| [rat(p[0]), rat(p[1]), rat(1)]).collect() };
        let mut pairs: Vec<(Rows, Rows)> = (0..40)
            .map(|_| {
                let (a, b): (Vec<i64>, Vec<i64>) =
                    ((0..8).map(|_| next(2048)).collect(), (0..8).map(|_| next(2048)).collect());
                (rows(&a), rows(&b))
            })
            .collect();
        // rational curves with fractional coordinates (inexact in f64: the filter's error radii)
        for _ in 0..12 {
            let weighted = |next: &mut dyn FnMut(i64) -> i64| -> Rows {
                (0..4)
                    .map(|_| {
                        let w = rat(next(4).abs() + 1);
                        let (x, y) = (
                            BigRational::new(next(2048).into(), 7.into()),
                            BigRational::new(next(2048).into(), 7.into()),
                        );
                        [x * &w, y * &w, w]
                    })
                    .collect()
            };
            pairs.push((weighted(&mut next), weighted(&mut next)));
        }
        // a parabola touching a line at its apex, a shared end point, boxes touching at a corner
        pairs.push((rows(&[0, 0, 1, 2, 2, 0]), rows(&[0, 1, 2, 1])));
        pairs.push((rows(&[0, 0, 1, 3, 2, 1, 4, 4]), rows(&[4, 4, 5, 0, 9, 9])));
        pairs.push((rows(&[0, 0, 1, 1]), rows(&[1, 1, 2, 0])));
        let (mut apart, mut empty) = (0, 0);
        for (ra, rb) in &pairs {
            let (fa, fb) = (forms_from_homogeneous(ra), forms_from_homogeneous(rb));
            let exact = intersect_forms(&fa, &fb, Domain::Unit, &Regions::Anywhere).unwrap();
            let regions = candidate_regions(ra, rb);
            if matches!(regions, Regions::Apart) {
                assert!(exact.intersections.is_empty(), "proved apart, but they meet: {exact:?}");
                apart += 1;
            }
            empty += usize::from(exact.intersections.is_empty());
            let filtered = intersect_rows(ra, rb, Domain::Unit).unwrap();
            assert_eq!(filtered, exact);
        }
        assert!(empty > 5 && 4 * apart >= 3 * empty, "{apart} of {empty} empty pairs proved apart");
    }

    /// The implicit-matrix elimination against the Sylvester resultant: equal up to a constant
    /// and the factor `W_A^m`, on random polynomial and rational cubics, quadratics and lines.
    #[test]
    fn bezout_elimination_matches_sylvester() {
        let mut next = crate::num::symmetric(0x1234_5678_9ABC_DEF1);
        for round in 0..40 {
            let degree = |r: usize| [3, 2, 1, 3][r % 4];
            // every seventh round with coordinates near 2^70 (the BigInt route of the matrix)
            let huge = if round % 7 == 0 { BigRational::from_integer(BigInt::from(1) << 70u32) } else { rat(1) };
            let mut curve = |n: usize, rational: bool| {
                let mut c = || rat(next(60)) * &huge + rat(next(60));
                let pts = (0..=n).map(|_| Point::new(vec![c(), c()])).collect();
                let w = (0..=n).map(|_| if rational { rat(next(5).abs() + 1) } else { rat(1) }).collect();
                RationalBezier::new(pts, w).unwrap()
            };
            let (a, b) = (curve(degree(round), round % 3 == 0), curve(degree(round / 4), round % 5 == 0));
            let (fa, fb) = (integer_forms(&a), integer_forms(&b));
            let sylvester = resultant_zv(
                &cross_system(&fa[0], &fa[2], &fb[0], &fb[2]),
                &cross_system(&fa[1], &fa[2], &fb[1], &fb[2]),
            );
            let mut bezout = eliminate(&fa, &fb);
            let m = cross_system(&fa[0], &fa[2], &fb[0], &fb[2]).len() - 1;
            for _ in 0..m {
                bezout = zv::mul(&bezout, &fa[2]);
            }
            let pp = crate::poly::polynomial::primitive_part;
            assert_eq!(pp(sylvester), pp(bezout), "round {round}");
        }
    }

    #[test]
    fn krawczyk_proof_declines_a_tangency() {
        // y = x² at its vertex against the x-axis: a tangency, left to the exact comparison
        let para = RationalBezier::new(
            vec![
                Point::new(vec![rat(-1), rat(1)]),
                Point::new(vec![rat(0), rat(-1)]),
                Point::new(vec![rat(1), rat(1)]),
            ],
            vec![rat(1); 3],
        )
        .unwrap();
        let line = RationalBezier::new(
            vec![Point::new(vec![rat(-2), rat(0)]), Point::new(vec![rat(2), rat(0)])],
            vec![rat(1); 2],
        )
        .unwrap();
        let (fa, fb) = (integer_forms(&para), integer_forms(&line));
        let k = intersect(&para, &line, Domain::Unit).unwrap();
        assert_eq!(k.intersections.len(), 1);
        assert_eq!(k.intersections[0].kind, Kind::Tangent);
        let i = &k.intersections[0];
        let sys = filter::System::new(&fa, &fb).expect("polynomial curves");
        assert!(!proved_common(&sys, &i.s, &i.t, (i.s_float, i.t_float)));
    }
}
