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
//! of the other is decided by their local expansions: with `u = d·(C − v)` the distance along the
//! common direction `d` and `w = n·(C − v)` the distance along its left normal `n`, each edge is
//! locally a graph `w(u) = Σ_k c_k u^k`, and the series are compared coefficient by coefficient
//! (exact power series, reversion of `u(τ)`). Two distinct curves of degrees `m, n` meet with
//! multiplicity at most `m·n`, so the series differ by order `m·n + 1`. This needs the vertex
//! and both parameters rational and both edges regular there; otherwise the order of two tangent
//! edges is refused with [`Error::InvalidArgument`] naming the vertex (never guessed).

use super::segment::Seg;
use crate::error::{Error, Result};
use crate::num::point::Point2;
use crate::num::scalar::rat;
use crate::poly::Poly;
use crate::poly::algebraic::RealAlgebraic;
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
    /// The derivative order of the direction (0 when regular).
    order: usize,
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
                return Ok(Angle { quadrant, within, order: j });
            }
            a = a.derivative();
            b = b.derivative();
        }
        Err(Error::InvalidArgument { message: "an edge of zero length".into() })
    }
}

const SERIES_MARGIN: usize = 2;

/// Compares two germs leaving a rational vertex `v` in the same direction: `Less` when `g`
/// lies clockwise of `h` (to the right of the common direction).
pub(crate) fn compare_tangent(
    g: &Germ<'_>,
    h: &Germ<'_>,
    ga: &Angle,
    ha: &Angle,
    v: &Point2<BigRational>,
) -> Result<Ordering> {
    let refuse = || Error::InvalidArgument {
        message: format!(
            "two curves leave the vertex ({}, {}) tangentially where their order around it cannot be decided \
             exactly (an irrational parameter or a cusp there)",
            crate::num::scalar::ratio_to_f64(&v.x),
            crate::num::scalar::ratio_to_f64(&v.y)
        ),
    };
    let (Some(s), Some(t)) = (g.t0.to_rational(), h.t0.to_rational()) else { return Err(refuse()) };
    if ga.order != 0 || ha.order != 0 {
        return Err(refuse());
    }
    let d = g.seg.direction_at(s);
    let d = if g.sigma < 0 { [-d.x.clone(), -d.y.clone()] } else { [d.x, d.y] };
    let n = [-d[1].clone(), d[0].clone()];
    let order = g.seg.degree() * h.seg.degree() + SERIES_MARGIN;
    let a = graph_series(g, s, v, &d, &n, order);
    let b = graph_series(h, t, v, &d, &n, order);
    for k in 2..=order {
        match a.coeff(k).cmp(&b.coeff(k)) {
            Ordering::Equal => continue,
            o => return Ok(o),
        }
    }
    Err(Error::InvalidArgument {
        message: "two edges agree to every order at a vertex (an overlap that was not merged)".into(),
    })
}

/// The series `w(u) = c_0 + c_1 u + …` to `u^order` for one germ.
fn graph_series(
    g: &Germ<'_>,
    t0: &BigRational,
    v: &Point2<BigRational>,
    d: &[BigRational; 2],
    n: &[BigRational; 2],
    order: usize,
) -> Poly<BigRational> {
    let s = g.seg;
    let px = s.x() - &s.w().scale(&v.x);
    let py = s.y() - &s.w().scale(&v.y);
    let along = |k: &[BigRational; 2]| &px.scale(&k[0]) + &py.scale(&k[1]);
    // the edge's local parameter τ: t = t0 + σ·τ
    let local = |p: &Poly<BigRational>| if g.sigma < 0 { p.shift(t0).reflect() } else { p.shift(t0) };
    let (u, w, den) = (local(&along(d)), local(&along(n)), local(s.w()));
    let u = u.div_truncated(&den, order);
    let w = w.div_truncated(&den, order);
    let tau = u.reversion(order);
    w.compose_truncated(&tau, order)
}
