//! What the routes share about the resultants' roots: the distinct roots in the domain
//! ([`roots`], [`square_free_part`]), those in the plane ([`finite_roots`]), their multiplicities
//! (contact orders), and the exact common point at a pair of roots ([`Side`], [`common_point`]):
//! rational when it is, proved irrational cheaply when it is not.

use super::Domain;
use super::filter;
use super::filter::divided_difference_enclosed;
use super::forms::{is_point, point_at, point_at_rational, rational_point, to_rational};
use crate::num::point::Point;
use crate::num::scalar::rat;
use crate::poly::Poly;
use crate::poly::algebraic::RealAlgebraic;
use num_bigint::BigInt;
use num_rational::BigRational;
use std::cmp::Ordering;

/// The distinct roots of `r` (integer coefficients, non-zero) in the domain, and whether `r` is
/// square-free (every root simple).
pub(super) fn roots(r: &[BigInt], domain: Domain) -> (Vec<RealAlgebraic>, bool) {
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
pub(super) fn square_free_part(r: &[BigInt]) -> (Vec<BigInt>, bool) {
    // word-sized coefficients proved square-free modulo a prime: no big-integer gcds
    if let Some(p) = crate::poly::integer::square_free_small(r) {
        return (p, true);
    }
    let p = crate::poly::integer::primitive_part(r.to_vec());
    let sf = crate::poly::integer::square_free_integer(p.clone());
    let simple = sf.len() == p.len();
    (sf, simple)
}

/// The roots where the curve's weight does not vanish (with every real parameter allowed, a
/// root where it does is a common point at infinity, not an intersection in the plane).
pub(super) fn finite_roots(roots: Vec<RealAlgebraic>, f: &[Vec<BigInt>; 3]) -> Vec<RealAlgebraic> {
    if f[2].len() == 1 {
        return roots; // a constant weight (non-zero)
    }
    let w = to_rational(&f[2]);
    roots.into_iter().filter(|x| x.sign_of(&w) != Ordering::Equal).collect()
}

/// The multiplicity of `x` as a root of `r`.
pub(super) fn multiplicity(r: &Poly<BigRational>, x: &RealAlgebraic) -> usize {
    let mut p = r.clone();
    let mut k = 0;
    while !p.is_zero() && x.sign_of(&p) == Ordering::Equal {
        k += 1;
        p = p.derivative();
    }
    k
}

/// One curve's forms with what the exact-point decision needs about them, computed once.
pub(super) struct Side<'a> {
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
    partner: std::cell::OnceCell<[Vec<filter::Coeffs>; 2]>,
}

impl<'a> Side<'a> {
    pub(super) fn new(f: &'a [Vec<BigInt>; 3]) -> Self {
        let n = f.iter().map(Vec::len).max().unwrap_or(1);
        Side {
            f,
            degree: n.saturating_sub(1),
            moves: !is_point(f),
            bound: std::cell::OnceCell::new(),
            partner: std::cell::OnceCell::new(),
        }
    }

    /// The point at the irrational `x` (`narrow`: a tight `f64` interval holding it) is
    /// provably irrational. Were it a rational point `P`, `x` would be a root of `X − P_x W` and
    /// `Y − P_y W`, so every conjugate `u ≠ x` of `x` (there is one: `x` is irrational) would be
    /// one too, and the curve would pass through `P` at `u`: the divided differences
    /// `D_F(x, u) = (F(x)W(u) − F(u)W(x))/(x − u)` (`F = X, Y`) would share the root `u`. So
    /// [`filter::no_common_root`] at `x` proves it (curves of degree ≤ 5; `f64` enclosures).
    /// Else the degree of `x`: `P` rational makes it at most the curve's degree, so a lower bound
    /// above that proves it ([`RealAlgebraic::degree_lower_bound`], a factorization modulo
    /// primes: dearer).
    fn irrational_at(&self, x: &RealAlgebraic, narrow: (f64, f64)) -> bool {
        if x.to_rational().is_some() || !self.moves {
            return false;
        }
        if self.degree <= filter::MAX_BEZOUT_ORDER + 1 {
            let [dx, dy] = self.partner.get_or_init(|| {
                let dd = divided_difference_enclosed;
                [dd(&self.f[0], &self.f[2]), dd(&self.f[1], &self.f[2])]
            });
            if filter::no_common_root(dx, dy, narrow) {
                return true;
            }
        }
        *self.bound.get_or_init(|| x.degree_lower_bound(self.degree + 1)) > self.degree
    }

    /// The point at `x`, correctly rounded.
    pub(super) fn point_float(&self, x: &RealAlgebraic) -> [f64; 2] {
        let x = x.narrowed(60);
        [x.map_rational_to_f64(&self.f[0], &self.f[2]), x.map_rational_to_f64(&self.f[1], &self.f[2])]
    }
}

/// The common point `A(s) = B(t)` when it is rational, by the cheapest route that decides: a
/// rational parameter, an irrationality proof ([`Side::irrational_at`], with `sn` and `tn`
/// tight `f64` intervals holding `s` and `t`), or the exact point (computed once per root,
/// `cached`).
pub(super) fn common_point(
    (a, s, sn): (&Side, &RealAlgebraic, (f64, f64)),
    (b, t, tn): (&Side, &RealAlgebraic, (f64, f64)),
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::intersect::elimination::{cross_system, eliminate};
    use crate::intersect::filter::{System, apart, proved_common};
    use crate::intersect::forms::{cubic, integer_forms};
    use crate::poly::algebraic::resultant_zv;

    /// The divided-difference proof that a point is irrational ([`Side::irrational_at`]) never
    /// errs, checked against the exact point: on random rational cubics every irrational root of
    /// a resultant with a line (whose intersections are a double point or not); and it declines
    /// at the double point `(0, 0)` of `(s² − 2, s³ − 2s)`, reached at `s = ±√2`.
    #[test]
    fn irrational_point_proof_agrees_with_exact_points() {
        let b = |v: &[i64]| v.iter().map(|&c| BigInt::from(c)).collect::<Vec<_>>();
        let nodal = [b(&[-2, 0, 1]), b(&[0, -2, 0, 1]), b(&[1])];
        let side = Side::new(&nodal);
        let sqrt2 = RealAlgebraic::real_roots(&crate::poly::Poly::new(vec![rat(-2), rat(0), rat(1)]))[1].clone();
        let narrow = filter::outward(&sqrt2.narrowed_with_f64().0);
        assert!(!filter::no_common_root(
            &divided_difference_enclosed(&nodal[0], &nodal[2]),
            &divided_difference_enclosed(&nodal[1], &nodal[2]),
            narrow
        ));
        assert!(!side.irrational_at(&sqrt2, narrow));
        let sqrt3 = RealAlgebraic::real_roots(&crate::poly::Poly::new(vec![rat(-3), rat(0), rat(1)]))[1].clone();
        assert!(side.irrational_at(&sqrt3, filter::outward(&sqrt3.narrowed_with_f64().0))); // (1, √3)
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
                if side.irrational_at(&x, filter::outward(&x.narrowed_with_f64().0)) {
                    assert!(rational_point(&point_at(&f, &x)).is_none(), "proved irrational, but rational at {x}");
                    proved += 1;
                }
            }
        }
        assert!(proved > 20, "{proved} irrational points proved");
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
            let sys = System::new(&fa, &fb).expect("polynomial curves");
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
}
