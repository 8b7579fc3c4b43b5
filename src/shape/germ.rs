//! The cyclic order of the edges leaving a vertex, exactly.
//!
//! An edge leaves its vertex along the segment `C` from parameter `t0` in direction `σ = ±1`.
//! With `D = (X'W − XW', Y'W − YW')` (the tangent times `W² > 0`) and `j` the first order with
//! `D⁽ʲ⁾(t0) ≠ 0`, the edge leaves in direction `σ^(j+1)·D⁽ʲ⁾(t0)` (`j > 0` at a cusp). Directions
//! are ordered counter-clockwise from `+x` by a pseudo-angle: the quadrant and, within it, a
//! rational function of `t0` (`b/(a+b)` in the first quadrant, and so on) that increases with the
//! angle — a real algebraic number when `t0` is, compared exactly.
//!
//! Two edges leaving in the same direction are tangent there; which one lies counter-clockwise
//! of the other is decided by their local expansions (Puiseux series). In a frame along the
//! common direction — `u = s·(x − v_x)`, `w = s·(y − v_y)` with `s` the sign of the direction's
//! `x` component (or `u = s·(y − v_y)`, `w = −s·(x − v_x)` for a vertical direction), so that `u`
//! grows along the direction and `w` to its left — each edge `t = t0 + σ·τ` has
//! `u(τ) = a·τ^m·(1 + r(τ))` with `a > 0` and `m ≥ 1` (`m > 1` at a cusp: the first
//! non-vanishing derivative gives the direction). With `ζ = τ·(1 + r(τ))^(1/m) = (u/a)^(1/m)`
//! (a binomial series; no root of `a` is taken) and its reversion `τ(ζ)`, the edge is the graph
//! `w = Σ_k δ_k ζ^k = Σ_k δ_k a^(−k/m) u^(k/m)`. The coefficients `δ_k` lie in `Q(t0)`: exact
//! polynomials in `t0` ([`NumberField`]), signs decided exactly. The edges are compared term by
//! term in increasing exponent `e`: first the signs of the coefficients, then their sizes
//! `|δ_k|^L / a^(eL)` (`L = lcm(m_g, m_h)`, so no root remains), each a real algebraic number
//! compared exactly. The edge with the larger `w` near the vertex lies counter-clockwise.
//!
//! Two distinct branches of curves of degrees `n_g, n_h` through a point meet there with
//! multiplicity at most `n_g·n_h` (Bézout) or, on one curve, at most `(n − 1)(n − 2)` (twice
//! its genus deficiency); so their expansions differ at an exponent `e ≤ 2·max(n_g, n_h)² + 2`.
//! Expansions agreeing that far are an overlap the arrangement failed to merge: an error, never
//! a guess. The series are computed to a few orders first and deepened only while they agree.

use super::segment::Seg;
use crate::error::{Error, Result};
use crate::num::scalar::rat;
use crate::poly::Poly;
use crate::poly::algebraic::{NumberField, RealAlgebraic};
use num_rational::BigRational;
use std::cmp::Ordering;

/// An edge end leaving a vertex.
#[derive(Clone, Debug)]
pub(crate) struct Germ<'a> {
    pub seg: &'a Seg,
    pub t0: RealAlgebraic,
    /// `+1` when the edge runs towards larger parameters.
    pub sigma: i64,
}

/// The pseudo-angle of a germ's direction: quadrant, then position within it.
#[derive(Clone, Debug)]
pub(crate) struct Angle {
    quadrant: u8,
    within: RealAlgebraic,
}

fn sign_at(p: &Poly<BigRational>, t: &RealAlgebraic) -> Ordering {
    match t.to_rational() {
        Some(r) => p.eval(r).cmp(&rat(0)),
        None => t.sign_of(p),
    }
}

impl Angle {
    /// The order of the directions counter-clockwise from `+x` (equal for tangent germs).
    pub(crate) fn cmp_direction(&self, other: &Angle) -> Ordering {
        (self.quadrant, &self.within).cmp(&(other.quadrant, &other.within))
    }
}

impl Germ<'_> {
    /// The pseudo-angle of the direction in which the edge leaves.
    pub(crate) fn angle(&self) -> Result<Angle> {
        let (mut a, mut b) = (self.seg.dx().clone(), self.seg.dy().clone());
        for j in 0..=2 * self.seg.degree() + 2 {
            let (sa, sb) = (sign_at(&a, &self.t0), sign_at(&b, &self.t0));
            if sa != Ordering::Equal || sb != Ordering::Equal {
                let flip = self.sigma < 0 && j % 2 == 0;
                let (a, b, sa, sb) = if flip { (-&a, -&b, sa.reverse(), sb.reverse()) } else { (a, b, sa, sb) };
                use Ordering::*;
                let (quadrant, num, den) = match (sa, sb) {
                    (Greater, Greater | Equal) => (0u8, b.clone(), &a + &b),
                    (Less | Equal, Greater) => (1, -&a, &b - &a),
                    (Less, Less | Equal) => (2, b.clone(), &a + &b),
                    _ => (3, a.clone(), &a - &b),
                };
                let within = match self.t0.to_rational() {
                    Some(r) => RealAlgebraic::from(num.eval(r) / den.eval(r)),
                    None => self.t0.map_rational(&num, &den),
                };
                return Ok(Angle { quadrant, within });
            }
            a = a.derivative();
            b = b.derivative();
        }
        Err(Error::InvalidArgument { message: "an edge of zero length".into() })
    }
}

/// Compares two germs leaving one vertex in the same direction: `Less` when `g` lies clockwise
/// of `h` (to the right of the common direction).
pub(crate) fn compare_tangent(g: &Germ<'_>, h: &Germ<'_>) -> Result<Ordering> {
    let n = g.seg.degree().max(h.seg.degree()).max(1);
    let limit = 2 * n * n + 2; // the largest exponent at which two distinct branches can agree
    let mut depth = 4;
    loop {
        let depth_now = depth.min(limit);
        let mut bg = Branch::new(g, depth_now)?;
        let mut bh = Branch::new(h, depth_now)?;
        let l = num_integer::Integer::lcm(&bg.m, &bh.m);
        // the exponents e = j/L with both expansions known
        for j in 1..=depth_now * l {
            let (cg, ch) = (bg.coefficient(j, l), bh.coefficient(j, l));
            let (sg, sh) = (
                cg.as_ref().map_or(Ordering::Equal, |k| bg.sign_of(*k)),
                ch.as_ref().map_or(Ordering::Equal, |k| bh.sign_of(*k)),
            );
            if sg != sh {
                return Ok(sg.cmp(&sh));
            }
            if sg == Ordering::Equal {
                continue;
            }
            let (Some(kg), Some(kh)) = (cg, ch) else { unreachable!("non-zero signs") };
            let size = bg.size(kg, j, l).cmp(&bh.size(kh, j, l));
            if size != Ordering::Equal {
                return Ok(if sg == Ordering::Greater { size } else { size.reverse() });
            }
        }
        if depth_now == limit {
            return Err(Error::InvalidArgument {
                message: "two edges agree to every order at a vertex (an overlap that was not merged)".into(),
            });
        }
        depth *= 2;
    }
}

/// A series: coefficients (elements of `Q(t0)`) of `τ^0, τ^1, …`.
type Series = Vec<Poly<BigRational>>;

/// One edge as a graph `w = Σ δ_k (u/a)^(k/m)` near its vertex (see the module documentation).
struct Branch {
    field: NumberField,
    m: usize,
    a: Poly<BigRational>,
    delta: Series,
}

impl Branch {
    /// The expansion of germ `g` up to the exponent `depth` of `u` (`δ_k` for `k ≤ depth·m`).
    fn new(g: &Germ<'_>, depth: usize) -> Result<Branch> {
        let s = g.seg;
        let mut field = NumberField::new(&g.t0);
        // the order of the cusp is at most that of the tangent's first non-vanishing derivative
        let m_max = 2 * s.degree() + 2;
        let order = depth * m_max + m_max;
        let taylor = |p: &Poly<BigRational>| -> Series {
            let mut out = vec![];
            let mut d = p.clone();
            let mut factorial = rat(1);
            for k in 0..=p.degree().unwrap_or(0) {
                let c = field.reduce(&d.scale(&(rat(1) / &factorial)));
                out.push(if g.sigma < 0 && k % 2 == 1 { -&c } else { c });
                d = d.derivative();
                factorial *= rat(k as i64 + 1);
            }
            out
        };
        let (xs, ys, ws) = (taylor(s.x()), taylor(s.y()), taylor(s.w()));
        let winv = field.inverse(&ws[0]);
        let x = series_div(&field, &xs, &ws, &winv, order);
        let y = series_div(&field, &ys, &ws, &winv, order);
        // the first order with a non-zero point coefficient: the direction
        let mut m = 0;
        let mut frame = None;
        for k in 1..=order {
            let (sx, sy) = (field.sign(&x[k]), field.sign(&y[k]));
            if sx != Ordering::Equal {
                frame = Some((true, sx == Ordering::Greater));
            } else if sy != Ordering::Equal {
                frame = Some((false, sy == Ordering::Greater));
            }
            if frame.is_some() {
                m = k;
                break;
            }
        }
        let Some((along_x, positive)) = frame else {
            return Err(Error::InvalidArgument { message: "an edge of zero length".into() });
        };
        let signed = |p: &Poly<BigRational>, plus: bool| if plus { p.clone() } else { -p };
        let (u, w): (Series, Series) = if along_x {
            (x.iter().map(|c| signed(c, positive)).collect(), y.iter().map(|c| signed(c, positive)).collect())
        } else {
            (y.iter().map(|c| signed(c, positive)).collect(), x.iter().map(|c| signed(c, !positive)).collect())
        };
        let a = u[m].clone();
        let ainv = field.inverse(&a);
        let kmax = depth * m;
        // f = u/(a τ^m) = 1 + r, then ζ/τ = f^(1/m)
        let f: Series =
            (0..=kmax).map(|j| field.mul(&u.get(m + j).cloned().unwrap_or_else(Poly::zero), &ainv)).collect();
        let root = series_root(&field, &f, m, kmax);
        let mut zeta: Series = vec![Poly::zero()];
        zeta.extend(root.into_iter().take(kmax));
        let tau = series_reversion(&field, &zeta, kmax);
        let mut w0 = w;
        w0[0] = Poly::zero();
        w0.truncate(kmax + 1);
        let delta = series_compose(&field, &w0, &tau, kmax);
        Ok(Branch { field, m, a, delta })
    }

    /// The index `k` of the coefficient of `u^(j/l)` (`None` when `j/l` is no exponent `k/m`).
    fn coefficient(&self, j: usize, l: usize) -> Option<usize> {
        (j * self.m).is_multiple_of(l).then_some(j * self.m / l)
    }

    fn sign_of(&mut self, k: usize) -> Ordering {
        let c = self.delta.get(k).cloned().unwrap_or_else(Poly::zero);
        self.field.sign(&c)
    }

    /// `|δ_k|^l / a^j`: the size of the coefficient of `u^(j/l)` raised to the power `l`.
    fn size(&mut self, k: usize, j: usize, l: usize) -> RealAlgebraic {
        let d = self.delta[k].clone();
        let d = if self.field.sign(&d) == Ordering::Less { -&d } else { d };
        let num = self.field.pow(&d, l);
        let den = self.field.pow(&self.a, j);
        self.field.value(&num, &den)
    }
}

fn series_mul(f: &NumberField, a: &Series, b: &Series, order: usize) -> Series {
    let mut out: Vec<Poly<BigRational>> = vec![Poly::zero(); order + 1];
    for (i, x) in a.iter().enumerate().take(order + 1) {
        if x.is_zero() {
            continue;
        }
        for (j, y) in b.iter().enumerate().take(order + 1 - i) {
            if !y.is_zero() {
                out[i + j] = &out[i + j] + &(x * y);
            }
        }
    }
    out.iter().map(|c| f.reduce(c)).collect()
}

/// `a/b` to `τ^order`, given `binv = 1/b_0`.
fn series_div(f: &NumberField, a: &Series, b: &Series, binv: &Poly<BigRational>, order: usize) -> Series {
    let mut out: Series = Vec::with_capacity(order + 1);
    for k in 0..=order {
        let mut acc = a.get(k).cloned().unwrap_or_else(Poly::zero);
        for j in 1..=k.min(b.len().saturating_sub(1)) {
            if !b[j].is_zero() {
                acc = &acc - &(&b[j] * &out[k - j]);
            }
        }
        out.push(f.mul(&f.reduce(&acc), binv));
    }
    out
}

/// `p(q(τ))` to `τ^order` (`q_0 = 0`), by Horner's rule.
fn series_compose(f: &NumberField, p: &Series, q: &Series, order: usize) -> Series {
    let mut out: Series = vec![Poly::zero(); order + 1];
    for c in p.iter().take(order + 1).rev() {
        out = series_mul(f, &out, q, order);
        out[0] = &out[0] + c;
    }
    out
}

/// `f^(1/m)` to `τ^order` for `f_0 = 1`: from `m·f·y' = f'·y`,
/// `y_k = Σ_{i=1..k} f_i·y_{k−i}·(i − m(k − i)) / (m·k)`.
fn series_root(f: &NumberField, s: &Series, m: usize, order: usize) -> Series {
    let mut y: Series = vec![Poly::constant(rat(1))];
    for k in 1..=order {
        let mut acc = Poly::zero();
        for i in 1..=k {
            let Some(fi) = s.get(i).filter(|c| !c.is_zero()) else { continue };
            let factor = rat(i as i64 - (m * (k - i)) as i64);
            acc = &acc + &(fi * &y[k - i]).scale(&factor);
        }
        y.push(f.reduce(&acc.scale(&(rat(1) / rat((m * k) as i64)))));
    }
    y
}

/// The reversion `τ(ζ)` of `ζ(τ) = τ + …` to `ζ^order`: Newton's iteration
/// `τ ← τ − (ζ(τ) − ζ)/ζ'(τ)`, which doubles the correct coefficients each step.
fn series_reversion(f: &NumberField, z: &Series, order: usize) -> Series {
    let mut tau: Series = vec![Poly::zero(); order + 1];
    if order >= 1 {
        tau[1] = Poly::constant(rat(1));
    }
    let dz: Series = (1..z.len()).map(|k| z[k].scale(&rat(k as i64))).collect();
    let mut correct = 1;
    while correct <= order {
        let mut residual = series_compose(f, z, &tau, order);
        residual[1] = &residual[1] - &Poly::constant(rat(1));
        let slope = series_compose(f, &dz, &tau, order);
        // slope_0 = 1: the quotient needs no inverse
        let step = series_div(f, &residual, &slope, &Poly::constant(rat(1)), order);
        for k in 0..=order {
            tau[k] = &tau[k] - &step[k];
        }
        correct *= 2;
    }
    tau
}
