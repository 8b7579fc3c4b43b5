//! The box solver's route: the subdivision filter's candidate boxes solved by Krawczyk's
//! operator ([`super::filter::solve`]), each crossing's parameters then made exact without
//! isolating the resultants' roots.

use super::filter;
use super::pairing::{Side, common_point, square_free_part};
use super::{Contact, Intersection, Intersections};
use crate::poly::algebraic::RealAlgebraic;
use num_bigint::BigInt;

/// The fast route of [`intersect_forms`](super::pairing::intersect_forms) for polynomial curves on the unit square (their system
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
pub(super) fn solved_in_boxes(
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
            kind: Contact::Transversal,
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::intersect::Domain;
    use crate::intersect::elimination::eliminate;
    use crate::intersect::filter::{Regions, candidate_regions};
    use crate::intersect::forms::{cubic, forms_from_homogeneous, homogeneous_rows};
    use crate::intersect::pairing::intersect_forms;
    use crate::num::point::Point;
    use crate::num::scalar::rat;
    use crate::rational::RationalBezier;
    use num_rational::BigRational;

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
}
