//! Shared components: what two curves have in common when the resultant vanishes identically
//! (or one curve's self-intersection resultant does), as matching parameter intervals.
//!
//! Every route is exact and decides; a case none of them covers is refused with a message.
//!
//! - **Curves on one line** (collinear control points, any degree, turn-backs allowed, so also
//!   parametrizations that trace the line back and forth): with `u` the coordinate along the
//!   line (`x`, or `y` for a vertical line), `A` is `u = f(s)` and `B` is `u = g(t)`. `[0, 1]` is
//!   cut where `f′` (or `g′`) changes sign; on each pair of monotone pieces the common range of
//!   values `[v₀, v₁]` is one arc `s = f⁻¹(v)`, `t = g⁻¹(v)` (a single point when `v₀ = v₁`). The
//!   ends are exact algebraic numbers: a turning point of `g` is a root of `g′`'s numerator, and
//!   `f⁻¹(g(τ))` for an irrational `τ` is a root of `Res_τ(p(τ), U_A(s)W_B(τ) − W_A(s)U_B(τ))`
//!   picked by exact comparison. Self-overlaps of a line traced back and forth are the pairs of
//!   different pieces.
//! - **Proper parametrizations** (each curve passes once through the shared curve): then
//!   `B(t) = A(φ(t))` for a Möbius map `φ(t) = (αt + β)/(γt + δ)` (affine for two polynomial
//!   curves; sub-segments, reversed, degree-elevated and reweighted copies all are). `φ` is
//!   interpolated through three parameters of `B` whose points have a single rational parameter
//!   on `A` (`gcd` of the two coordinate equations of degree 1), then **proved** by composing:
//!   `(X_A, Y_A, W_A)(αt + β, γt + δ)` (homogeneous) is proportional to `(X_B, Y_B, W_B)`. The
//!   arcs are the pieces of the graph of `φ` in the square (two at most, a hyperbola's branches),
//!   cut at `t ∈ {0, 1, φ⁻¹(0), φ⁻¹(1), −δ/γ}`. The isolated intersections are where the shared
//!   curve crosses itself: each self-intersection `A(s) = A(s′)` of `A` (also with `s′ = ∞`, from
//!   the reversed forms) gives `(s, φ⁻¹(s′))`, an isolated point of `{A(s) = B(t)}` since
//!   `s ≠ φ(t)`.
//! - **Single points**: a curve whose control points all coincide overlaps the other at every
//!   parameter where the other passes through that point.
//!
//! Both forms are first divided by `gcd(X, Y, W)` (base points), so degrees are real degrees.
//! Arcs are always reported inside `[0, 1]²` (a shared component is unbounded over all real
//! parameters); with [`Domain::All`] only the isolated intersections use every real parameter.

use super::forms::{coefficient, to_rational};
use super::roots::finite_roots;
use super::self_intersect::self_intersections_of_forms;
use super::{Domain, Intersection, Intersections, Overlap};
use crate::error::{Error, Result};
use crate::num::scalar::rat;
use crate::poly::Poly;
use crate::poly::algebraic::{RealAlgebraic, resultant_in_v, value_at, zv};
use crate::poly::integer::{derivative_integer, exact_quotient_integer, gcd_integer};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

type Forms = [Vec<BigInt>; 3];

fn refuse<T>(why: &str) -> Result<T> {
    Err(Error::InvalidArgument { message: format!("the curves share a component, but {why}") })
}

/// The forms divided by their common factor (base points removed).
pub(super) fn reduced(f: &Forms) -> Forms {
    let g = gcd_integer(&gcd_integer(&f[0], &f[1]), &f[2]);
    if g.len() <= 1 {
        return f.clone();
    }
    f.clone().map(|p| if p.is_empty() { p } else { exact_quotient_integer(p, &g) })
}

fn degree(f: &Forms) -> usize {
    f.iter().map(Vec::len).max().unwrap_or(1).saturating_sub(1)
}

fn unit(x: &RealAlgebraic) -> bool {
    x.sign() != Ordering::Less && *x <= RealAlgebraic::from(rat(1))
}

/// Refuses when a weight vanishes on `[0, 1]` (arcs are sought there; with the unit domain the
/// caller has checked it already).
fn defined_on_unit(f: &Forms) -> Result<()> {
    if f[2].len() > 1 && !RealAlgebraic::roots_in(&to_rational(&f[2]), &rat(0), &rat(1)).is_empty() {
        return refuse("a weight vanishes on [0, 1], where shared arcs are sought");
    }
    Ok(())
}

/// Everything `A` and `B` share when `A` lies on `B`'s curve identically (forms as in
/// [`super::intersect`]); see the module documentation.
pub(super) fn overlap(fa: &Forms, fb: &Forms, domain: Domain) -> Result<Intersections> {
    let (fa, fb) = (reduced(fa), reduced(fb));
    if domain == Domain::All {
        defined_on_unit(&fa)?;
        defined_on_unit(&fb)?;
    }
    match (degree(&fa), degree(&fb)) {
        (0, 0) => {
            let whole = || [RealAlgebraic::from(rat(0)), RealAlgebraic::from(rat(1))];
            return Ok(Intersections { intersections: vec![], overlaps: vec![overlap_of(whole(), whole())] });
        }
        (0, _) => {
            let overlaps = preimages(&fb, &fa)
                .into_iter()
                .map(|t| overlap_of([rat(0).into(), rat(1).into()], [t.clone(), t]))
                .collect();
            return Ok(Intersections { intersections: vec![], overlaps });
        }
        (_, 0) => {
            let overlaps = preimages(&fa, &fb)
                .into_iter()
                .map(|s| overlap_of([s.clone(), s], [rat(0).into(), rat(1).into()]))
                .collect();
            return Ok(Intersections { intersections: vec![], overlaps });
        }
        _ => {}
    }
    if let Some(line) = line_of(&fa) {
        if !on_line(&line, &fb) {
            return refuse("the second curve is not on the first one's line (internal inconsistency)");
        }
        let u = along(&line);
        let (pa, pb) = (Pieces::new(&fa[u], &fa[2])?, Pieces::new(&fb[u], &fb[2])?);
        let mut out = vec![];
        for i in &pa.pieces {
            for j in &pb.pieces {
                out.extend(shared_range(&pa, i, &pb, j)?);
            }
        }
        return Ok(Intersections { intersections: vec![], overlaps: tidy(out) });
    }
    let Some(phi) = mobius(&fa, &fb) else {
        return refuse(
            "one of them traces it more than once (an improper parametrization): only curves on a line, single \
             points and curves that are Möbius reparametrizations of one another (sub-segments, reversed, \
             degree-elevated or reweighted copies) are supported",
        );
    };
    let overlaps = phi.arcs();
    let intersections = phi.crossings(&fa, &fb, domain)?;
    Ok(Intersections { intersections, overlaps })
}

/// Every self-intersection of the curve with forms `f` in the domain: the isolated ones, or its
/// [`self_overlap`] when the self-intersection resultant vanishes identically.
pub(super) fn self_intersections(f: &Forms, domain: Domain) -> Result<Intersections> {
    match self_intersections_of_forms(f, domain)? {
        Some(found) => Ok(found),
        None => self_overlap(f),
    }
}

/// Self-overlaps of a curve whose self-intersection resultant vanishes identically: pairs of
/// different monotone pieces of a curve on a line; otherwise a refusal.
pub(super) fn self_overlap(f: &Forms) -> Result<Intersections> {
    let f = reduced(f);
    let refused = || {
        Err(Error::InvalidArgument {
            message: "the curve traces a curve more than once (an improper parametrization, not on a line): every \
                      point of an arc is a self-intersection"
                .into(),
        })
    };
    let Some(line) = line_of(&f) else { return refused() };
    defined_on_unit(&f)?;
    let u = along(&line);
    let p = Pieces::new(&f[u], &f[2])?;
    let mut out = vec![];
    for (k, i) in p.pieces.iter().enumerate() {
        for j in &p.pieces[k + 1..] {
            out.extend(shared_range(&p, i, &p, j)?);
        }
    }
    Ok(Intersections { intersections: vec![], overlaps: tidy(out) })
}

fn overlap_of(s: [RealAlgebraic; 2], t: [RealAlgebraic; 2]) -> Overlap {
    Overlap { s_float: s.clone().map(|x| x.to_f64()), t_float: t.clone().map(|x| x.to_f64()), s, t }
}

/// The parameters in `[0, 1]` where the curve `f` passes through the single point `p` (constant
/// forms).
fn preimages(f: &Forms, p: &Forms) -> Vec<RealAlgebraic> {
    let c = |k: usize| p[k].first().cloned().unwrap_or_default();
    // X(t)·w − x·W(t) and Y(t)·w − y·W(t)
    let eq = |k: usize| zv::sub(&zv::mul(&f[k], &vec![c(2)]), &zv::mul(&f[2], &vec![c(k)]));
    let g = gcd_integer(&eq(0), &eq(1));
    if g.len() <= 1 {
        return vec![];
    }
    finite_roots(RealAlgebraic::roots_in(&to_rational(&g), &rat(0), &rat(1)), f)
}

/// `(α, β, γ)` with `αX + βY + γW ≡ 0` when the curve lies on a line (reduced forms, degree ≥ 1).
fn line_of(f: &Forms) -> Option<[BigInt; 3]> {
    let n = f.iter().map(Vec::len).max().unwrap_or(0);
    let col = |k: usize| -> [BigInt; 3] { [0, 1, 2].map(|i| coefficient(&f[i], k)) };
    let cross = |a: &[BigInt; 3], b: &[BigInt; 3]| {
        [&a[1] * &b[2] - &a[2] * &b[1], &a[2] * &b[0] - &a[0] * &b[2], &a[0] * &b[1] - &a[1] * &b[0]]
    };
    let cols: Vec<[BigInt; 3]> = (0..n).map(col).collect();
    let normal = cols
        .iter()
        .enumerate()
        .find_map(|(i, a)| cols[i + 1..].iter().map(|b| cross(a, b)).find(|c| c.iter().any(|x| !x.is_zero())))?;
    on_line(&normal, f).then_some(normal)
}

fn on_line(line: &[BigInt; 3], f: &Forms) -> bool {
    let n = f.iter().map(Vec::len).max().unwrap_or(0);
    (0..n).all(|k| {
        let c = |i: usize| coefficient(&f[i], k);
        (&line[0] * c(0) + &line[1] * c(1) + &line[2] * c(2)).is_zero()
    })
}

/// The coordinate that moves along the line `αx + βy + γ = 0`: `x` (index 0) unless the line is
/// vertical (`β = 0`), then `y`.
fn along(line: &[BigInt; 3]) -> usize {
    if line[1].is_zero() { 1 } else { 0 }
}

/// A piece of `[0, 1]` where `f = U/W` is strictly monotone.
struct Piece {
    /// The ends (`lo < hi`).
    ends: [RealAlgebraic; 2],
    /// `f` at the ends.
    values: [RealAlgebraic; 2],
    rising: bool,
}

impl Piece {
    /// `(value, parameter)` at the low and at the high value.
    fn low(&self) -> (&RealAlgebraic, &RealAlgebraic) {
        let k = if self.rising { 0 } else { 1 };
        (&self.values[k], &self.ends[k])
    }

    fn high(&self) -> (&RealAlgebraic, &RealAlgebraic) {
        let k = if self.rising { 1 } else { 0 };
        (&self.values[k], &self.ends[k])
    }
}

/// `[0, 1]` cut into monotone pieces of `f = U/W` (a curve on a line, `u = f(s)`).
struct Pieces {
    u: Vec<BigInt>,
    w: Vec<BigInt>,
    pieces: Vec<Piece>,
}

impl Pieces {
    fn new(u: &[BigInt], w: &[BigInt]) -> Result<Self> {
        // f′ = (U′W − UW′)/W²
        let n = zv::sub(&zv::mul(&derivative_integer(u), &w.to_vec()), &zv::mul(&u.to_vec(), &derivative_integer(w)));
        if n.is_empty() {
            return refuse("a curve does not move along its line (internal inconsistency)");
        }
        let mut cuts: Vec<RealAlgebraic> = vec![rat(0).into()];
        cuts.extend(
            RealAlgebraic::roots_in(&to_rational(&n), &rat(0), &rat(1))
                .into_iter()
                .filter(|x| x.to_rational().is_none_or(|r| !r.is_zero() && !r.is_one())),
        );
        cuts.push(rat(1).into());
        let (uq, wq) = (to_rational(u), to_rational(w));
        let value = |x: &RealAlgebraic| x.map_rational(&uq, &wq);
        let mut pieces: Vec<Piece> = vec![];
        for pair in cuts.windows(2) {
            let rising = crate::poly::algebraic::sign_at(&n, &RealAlgebraic::rational_between(&pair[0], &pair[1]))
                == Ordering::Greater;
            match pieces.last_mut() {
                // f′ touches zero without changing sign: one piece
                Some(last) if last.rising == rising => {
                    last.ends[1] = pair[1].clone();
                    last.values[1] = value(&pair[1]);
                }
                _ => pieces.push(Piece {
                    ends: [pair[0].clone(), pair[1].clone()],
                    values: [value(&pair[0]), value(&pair[1])],
                    rising,
                }),
            }
        }
        Ok(Pieces { u: u.to_vec(), w: w.to_vec(), pieces })
    }

    /// The parameter in `piece` where `f` takes the value `g(e)` of the other curve `other` at
    /// its parameter `e` (`f` is monotone on the piece, so there is one at most).
    fn inverse(&self, piece: &Piece, v: &RealAlgebraic, other: &Pieces, e: &RealAlgebraic) -> Result<RealAlgebraic> {
        // U(s)·W_other(e) − W(s)·U_other(e) = 0
        let poly: Vec<BigInt> = match e.to_rational() {
            Some(r) => {
                let (ue, we) = (value_at(&other.u, r), value_at(&other.w, r));
                (&to_rational(&self.u).scale(&we) - &to_rational(&self.w).scale(&ue)).to_integer()
            }
            None => {
                let len = other.u.len().max(other.w.len());
                let coeff = |k: usize| -> zv::P {
                    let (uk, wk) = (coefficient(&other.u, k), coefficient(&other.w, k));
                    zv::sub(&zv::mul(&self.u, &vec![wk]), &zv::mul(&self.w, &vec![uk]))
                };
                let mut q: Vec<zv::P> = (0..len).map(coeff).collect();
                while q.last().is_some_and(Vec::is_empty) {
                    q.pop();
                }
                resultant_in_v(&e.polynomial(), &q)
            }
        };
        let poly = zv::trim(poly);
        if !poly.is_empty() {
            let (lo, hi) = (piece.ends[0].interval().0, piece.ends[1].interval().1);
            let (uq, wq) = (to_rational(&self.u), to_rational(&self.w));
            for x in RealAlgebraic::roots_in(&to_rational(&poly), &lo, &hi) {
                if x >= piece.ends[0] && x <= piece.ends[1] && x.map_rational(&uq, &wq) == *v {
                    return Ok(x);
                }
            }
        }
        refuse("an overlap's end was not found (internal inconsistency)")
    }
}

/// The arc (or point) where piece `i` of `a` and piece `j` of `b` take common values.
fn shared_range(a: &Pieces, i: &Piece, b: &Pieces, j: &Piece) -> Result<Option<Overlap>> {
    let (lo_a, lo_b) = (i.low(), j.low());
    let (hi_a, hi_b) = (i.high(), j.high());
    let lo = if lo_a.0 >= lo_b.0 { lo_a.0 } else { lo_b.0 };
    let hi = if hi_a.0 <= hi_b.0 { hi_a.0 } else { hi_b.0 };
    if lo > hi {
        return Ok(None);
    }
    // the parameter on each side where the common range ends at value `v` (its own end, or the
    // inverse of the other side's end)
    let at =
        |v: &RealAlgebraic,
         own: (&RealAlgebraic, &RealAlgebraic),
         theirs: (&RealAlgebraic, &RealAlgebraic),
         me: &Pieces,
         piece: &Piece,
         them: &Pieces| { if v == own.0 { Ok(own.1.clone()) } else { me.inverse(piece, v, them, theirs.1) } };
    let (s_lo, s_hi) = (at(lo, lo_a, lo_b, a, i, b)?, at(hi, hi_a, hi_b, a, i, b)?);
    let (t_lo, t_hi) = (at(lo, lo_b, lo_a, b, j, a)?, at(hi, hi_b, hi_a, b, j, a)?);
    Ok(Some(if i.rising { overlap_of([s_lo, s_hi], [t_lo, t_hi]) } else { overlap_of([s_hi, s_lo], [t_hi, t_lo]) }))
}

/// Sorted, with single-point overlaps dropped when they are the end of another overlap.
fn tidy(mut v: Vec<Overlap>) -> Vec<Overlap> {
    let ends = |o: &Overlap| [(o.s[0].clone(), o.t[0].clone()), (o.s[1].clone(), o.t[1].clone())];
    let point = |o: &Overlap| o.s[0] == o.s[1] && o.t[0] == o.t[1];
    let mut keep = vec![true; v.len()];
    for i in 0..v.len() {
        if point(&v[i]) {
            let p = (v[i].s[0].clone(), v[i].t[0].clone());
            keep[i] = !(0..v.len()).any(|j| j != i && keep[j] && ends(&v[j]).contains(&p));
        }
    }
    let mut k = keep.into_iter();
    v.retain(|_| k.next().unwrap_or(true));
    v.sort_by(|x, y| x.s[0].cmp(&y.s[0]).then_with(|| x.t[0].cmp(&y.t[0])));
    v
}

/// `s = φ(t) = (αt + β)/(γt + δ)` with `B(t) = A(φ(t))`, integers, `αδ − βγ ≠ 0`.
struct Mobius {
    a: BigInt,
    b: BigInt,
    c: BigInt,
    d: BigInt,
}

/// Simple rationals `0, 1, −1, 1/2, −1/2, 2, −2, 1/3, …`: sample parameters.
fn samples() -> impl Iterator<Item = BigRational> {
    (1i64..).flat_map(|k| {
        let mut v = vec![];
        for p in 0..=k {
            for q in 1..=k {
                if p.max(q) == k && num_integer::Integer::gcd(&p, &q) == 1 {
                    v.push(BigRational::new(p.into(), q.into()));
                    if p != 0 {
                        v.push(BigRational::new((-p).into(), q.into()));
                    }
                }
            }
        }
        v
    })
}

/// The Möbius map relating two proper parametrizations of one curve, interpolated and proved
/// (see the module documentation); `None` when there is none.
fn mobius(fa: &Forms, fb: &Forms) -> Option<Mobius> {
    let (m, n) = (degree(fa), degree(fb));
    if m != n {
        return None;
    }
    let mut pairs: Vec<(BigRational, BigRational)> = vec![];
    // a proper A has one parameter over every point but its singular ones and A(∞): at most
    // (m − 1)(m − 2)/2 double points with up to m parameters each, plus B's poles
    for t in samples().take(m * m * m + 2 * n + 8) {
        let [x, y, w] = [0, 1, 2].map(|k| value_at(&fb[k], &t));
        if w.is_zero() {
            continue;
        }
        // X_A(s)·w − x·W_A(s) and Y_A(s)·w − y·W_A(s), times the denominators
        let eq = |c: &BigRational, k: usize| {
            let (cw, wc) = (c.denom() * w.numer(), c.numer() * w.denom());
            zv::sub(&zv::mul(&fa[k], &vec![cw]), &zv::mul(&fa[2], &vec![wc]))
        };
        let (ex, ey) = (eq(&x, 0), eq(&y, 1));
        if ex.len() <= m && ey.len() <= m {
            continue; // B(t) = A(∞): a parameter of A is at infinity, the gcd would not show it
        }
        let g = gcd_integer(&ex, &ey);
        if g.len() == 2 {
            pairs.push((t, BigRational::new(-g[0].clone(), g[1].clone())));
            if pairs.len() == 3 {
                break;
            }
        }
    }
    if pairs.len() < 3 {
        return None;
    }
    // α t_i + β − γ s_i t_i − δ s_i = 0: the null vector of a 3 × 4 matrix by its minors
    let rows: Vec<[BigRational; 4]> =
        pairs.iter().map(|(t, s)| [t.clone(), rat(1), -(s.clone() * t), -s.clone()]).collect();
    let minor = |skip: usize| {
        let c: Vec<usize> = (0..4).filter(|&k| k != skip).collect();
        let e = |i: usize, j: usize| rows[i][c[j]].clone();
        e(0, 0) * (e(1, 1) * e(2, 2) - e(1, 2) * e(2, 1)) - e(0, 1) * (e(1, 0) * e(2, 2) - e(1, 2) * e(2, 0))
            + e(0, 2) * (e(1, 0) * e(2, 1) - e(1, 1) * e(2, 0))
    };
    let v: Vec<BigRational> = (0..4).map(|k| if k % 2 == 0 { minor(k) } else { -minor(k) }).collect();
    let scale = v.iter().fold(BigInt::one(), |acc, x| num_integer::Integer::lcm(&acc, x.denom()));
    let v: Vec<BigInt> = v.iter().map(|x| x.numer() * (&scale / x.denom())).collect();
    let phi = Mobius { a: v[0].clone(), b: v[1].clone(), c: v[2].clone(), d: v[3].clone() };
    if (&phi.a * &phi.d - &phi.b * &phi.c).is_zero() {
        return None;
    }
    // proof: (X_A, Y_A, W_A)(αt + β, γt + δ) ∥ (X_B, Y_B, W_B)
    let composed: Vec<Vec<BigInt>> = fa.iter().map(|f| phi.compose(f, m)).collect();
    let parallel = |i: usize, j: usize| zv::mul(&composed[i], &fb[j]) == zv::mul(&composed[j], &fb[i]);
    (parallel(0, 2) && parallel(1, 2) && parallel(0, 1)).then_some(phi)
}

impl Mobius {
    /// `Σ f_k (αt + β)^k (γt + δ)^(m−k)`.
    fn compose(&self, f: &[BigInt], m: usize) -> Vec<BigInt> {
        let num = vec![self.b.clone(), self.a.clone()];
        let den = vec![self.d.clone(), self.c.clone()];
        let pow = |p: &Vec<BigInt>, k: usize| (0..k).fold(vec![BigInt::one()], |acc, _| zv::mul(&acc, p));
        (0..=m).fold(vec![], |acc, k| {
            let term = zv::mul(&zv::mul(&pow(&num, k), &pow(&den, m - k)), &vec![coefficient(f, k)]);
            zv::sub(&acc, &zv::mul(&term, &vec![BigInt::from(-1)]))
        })
    }

    /// `φ(t)`, `None` at the pole.
    fn at(&self, t: &BigRational) -> Option<BigRational> {
        let den = BigRational::from_integer(self.c.clone()) * t + BigRational::from_integer(self.d.clone());
        (!den.is_zero())
            .then(|| (BigRational::from_integer(self.a.clone()) * t + BigRational::from_integer(self.b.clone())) / den)
    }

    /// `φ⁻¹(s) = (δs − β)/(−γs + α)`, `None` at its pole.
    fn inverse_at(&self, s: &BigRational) -> Option<BigRational> {
        let den = BigRational::from_integer(-self.c.clone()) * s + BigRational::from_integer(self.a.clone());
        (!den.is_zero())
            .then(|| (BigRational::from_integer(self.d.clone()) * s - BigRational::from_integer(self.b.clone())) / den)
    }

    /// The pieces of the graph of `φ` in `[0, 1]²`.
    fn arcs(&self) -> Vec<Overlap> {
        let in_unit = |x: &BigRational| !x.is_negative() && *x <= rat(1);
        let mut cuts: Vec<BigRational> = vec![rat(0), rat(1)];
        cuts.extend([rat(0), rat(1)].iter().filter_map(|s| self.inverse_at(s)).filter(in_unit));
        if !self.c.is_zero() {
            let pole = BigRational::new(-self.d.clone(), self.c.clone());
            if in_unit(&pole) {
                cuts.push(pole);
            }
        }
        cuts.sort();
        cuts.dedup();
        let inside = |t: &BigRational| self.at(t).is_some_and(|s| in_unit(&s));
        // accepted pieces [u, v] (φ is finite and in [0, 1] on them), joined where they meet
        let mut arcs: Vec<(BigRational, BigRational)> = vec![];
        for w in cuts.windows(2) {
            if inside(&((w[0].clone() + &w[1]) / rat(2))) {
                match arcs.last_mut() {
                    Some(last) if last.1 == w[0] => last.1 = w[1].clone(),
                    _ => arcs.push((w[0].clone(), w[1].clone())),
                }
            }
        }
        let mut points: Vec<BigRational> =
            cuts.iter().filter(|t| inside(t) && !arcs.iter().any(|(u, v)| *t == u || *t == v)).cloned().collect();
        points.dedup();
        let mut out: Vec<Overlap> = arcs
            .into_iter()
            .chain(points.into_iter().map(|t| (t.clone(), t)))
            .filter_map(|(u, v)| {
                let (su, sv) = (self.at(&u)?, self.at(&v)?);
                let (s, t) = if su <= sv { ([su, sv], [u, v]) } else { ([sv, su], [v, u]) };
                Some(overlap_of(s.map(RealAlgebraic::from), t.map(RealAlgebraic::from)))
            })
            .collect();
        out.sort_by(|x, y| x.s[0].cmp(&y.s[0]));
        out
    }

    /// The isolated intersections: `A`'s self-intersections `(s, s′)` (`s′` possibly `∞`)
    /// mapped to `(s, φ⁻¹(s′))`.
    fn crossings(&self, fa: &Forms, fb: &Forms, domain: Domain) -> Result<Vec<Intersection>> {
        let in_domain = |x: &RealAlgebraic| domain == Domain::All || unit(x);
        let q = |x: &BigInt| BigRational::from_integer(x.clone());
        let (num, den) = (Poly::new(vec![-q(&self.b), q(&self.d)]), Poly::new(vec![q(&self.a), -q(&self.c)]));
        let mut out = vec![];
        let finite = self_intersections(fa, Domain::All)?;
        for i in &finite.intersections {
            for (s, other, s_float) in [(&i.s, &i.t, i.s_float), (&i.t, &i.s, i.t_float)] {
                if !in_domain(s) || other.sign_of(&den) == Ordering::Equal {
                    continue; // off the domain, or t = ∞
                }
                let t = other.map_rational(&num, &den);
                if in_domain(&t) && finite_roots(vec![t.clone()], fb).len() == 1 {
                    out.push(Intersection { s: s.clone(), s_float, t_float: t.to_f64(), t, ..i.clone() });
                }
            }
        }
        if !self.c.is_zero() {
            // crossings with A(∞) = B(−δ/γ): self-intersections of A(1/u) at u = 0
            let tp = RealAlgebraic::from(BigRational::new(-self.d.clone(), self.c.clone()));
            if in_domain(&tp) && finite_roots(vec![tp.clone()], fb).len() == 1 {
                let m = degree(fa);
                let rev = fa.clone().map(|p| {
                    let mut r: Vec<BigInt> = (0..=m).map(|k| coefficient(&p, m - k)).collect();
                    r = zv::trim(r);
                    r
                });
                let zero = RealAlgebraic::from(rat(0));
                for i in self_intersections(&rev, Domain::All)?.intersections {
                    for (u, other) in [(&i.s, &i.t), (&i.t, &i.s)] {
                        if *other == zero && *u != zero {
                            let s = u.map_rational(&Poly::constant(rat(1)), &Poly::new(vec![rat(0), rat(1)]));
                            if in_domain(&s) {
                                out.push(Intersection {
                                    s_float: s.to_f64(),
                                    s,
                                    t_float: tp.to_f64(),
                                    t: tp.clone(),
                                    ..i.clone()
                                });
                            }
                        }
                    }
                }
            }
        }
        out.sort_by(|x, y| x.s.cmp(&y.s).then_with(|| x.t.cmp(&y.t)));
        out.dedup_by(|x, y| x.s == y.s && x.t == y.t);
        Ok(out)
    }
}
