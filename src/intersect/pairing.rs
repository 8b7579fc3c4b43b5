//! Root pairing: the resultants' roots in the domain, each root `σ` of `R` paired with each root
//! `τ` of `T` for which `A(σ) = B(τ)` (decided by the certified filters where they can, else
//! exactly), with contact orders and the common point when it is rational.

use super::box_solver::solved_in_boxes;
use super::elimination::{divided_difference, eliminate};
use super::filter::{self, Regions, apart, candidate_regions, proved_common};
use super::forms::{forms_from_homogeneous, point_at, point_at_rational, rational_point, to_rational};
use super::{Contact, Domain, Intersection, Intersections, overlap};
use crate::error::Result;
use crate::num::point::Point;
use crate::num::scalar::rat;
use crate::poly::algebraic::{RealAlgebraic, zv};
use crate::poly::polynomial::{derivative, trim};
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
    let p = crate::poly::polynomial::primitive_part(r.to_vec());
    let sf = crate::poly::polynomial::square_free_integer(p.clone());
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
pub(super) fn multiplicity(r: &[BigRational], x: &RealAlgebraic) -> usize {
    let mut p = r.to_vec();
    let mut k = 0;
    while !trim(p.clone()).is_empty() && x.sign_of(&p) == Ordering::Equal {
        k += 1;
        p = derivative(&p);
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
    partner: std::cell::OnceCell<[Vec<zv::P>; 2]>,
}

impl<'a> Side<'a> {
    pub(super) fn new(f: &'a [Vec<BigInt>; 3]) -> Self {
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
    pub(super) fn point_float(&self, x: &RealAlgebraic) -> [f64; 2] {
        let x = x.narrowed(60);
        [x.map_rational_to_f64(&self.f[0], &self.f[2]), x.map_rational_to_f64(&self.f[1], &self.f[2])]
    }
}

/// The common point `A(s) = B(t)` when it is rational, by the cheapest route that decides: a
/// rational parameter, an irrationality proof ([`Side::irrational_at`]), or the exact point
/// (computed once per root, `cached`).
pub(super) fn common_point(
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

/// The intersections of the curves with homogeneous control points `ra` and `rb` (checked by
/// the caller): none at once when the subdivision filter proves the curves apart on `[0, 1]²`,
/// otherwise the exact route, looking for parameters only where the filter left candidates
/// ([`filter::candidate_regions`]).
pub(super) fn intersect_rows(
    ra: &[[BigRational; 3]],
    rb: &[[BigRational; 3]],
    domain: Domain,
) -> Result<Intersections> {
    let regions = if domain == Domain::Unit { candidate_regions(ra, rb) } else { Regions::Anywhere };
    if let Regions::Apart = regions {
        return Ok(Intersections { intersections: vec![], overlaps: vec![] });
    }
    intersect_forms(&forms_from_homogeneous(ra), &forms_from_homogeneous(rb), domain, &regions)
}

/// The intersections of the curves with integer power forms `fa` and `fb` (checked by the
/// caller); [`overlap::overlap`] answers when they share a component.
pub(super) fn intersect_forms(
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
                    kind: if order == 1 { Contact::Transversal } else { Contact::Tangent },
                    contact_order: order,
                    s: s.clone(),
                    t: t.clone(),
                });
            }
        }
    }
    Ok(Intersections { intersections: out, overlaps: vec![] })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::scalar::rat;
    use num_bigint::BigInt;

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
}
