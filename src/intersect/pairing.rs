//! Root pairing: the resultants' roots in the domain, each root `σ` of `R` paired with each root
//! `τ` of `T` for which `A(σ) = B(τ)` (decided by the certified filters where they can, else
//! exactly), with contact orders and the common point when it is rational.

use super::box_solver::solved_in_boxes;
use super::elimination::eliminate;
use super::filter::{self, Regions, apart, candidate_regions, proved_common};
use super::forms::{forms_from_homogeneous, is_point, point_at, to_rational};
use super::roots::{Side, common_point, finite_roots, multiplicity, roots};
use super::{Contact, Domain, Intersection, Intersections, overlap};
use crate::error::Result;
use crate::poly::algebraic::RealAlgebraic;
use num_bigint::BigInt;
use num_rational::BigRational;

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

/// [`intersect_rows`] for polynomial curves with integer control points below `2^53` in
/// magnitude (checked by the caller): the same regions and forms, made from words (`None` on an
/// overflow, for [`intersect_rows`] to answer).
pub(super) fn intersect_integer_points(
    pa: &[[i64; 2]],
    pb: &[[i64; 2]],
    domain: Domain,
) -> Option<Result<Intersections>> {
    use super::forms::forms_from_integer_points;
    let regions = if domain == Domain::Unit { filter::candidate_regions_integer(pa, pb) } else { Regions::Anywhere };
    if let Regions::Apart = regions {
        return Some(Ok(Intersections { intersections: vec![], overlaps: vec![] }));
    }
    let (fa, fb) = (forms_from_integer_points(pa)?, forms_from_integer_points(pb)?);
    Some(intersect_forms(&fa, &fb, domain, &regions))
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
    if is_point(fa) || is_point(fb) {
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
                        (&side_a, s, outward(na[i].as_ref().map_or(s, |n| &n.0))),
                        (&side_b, t, outward(nb[j].as_ref().map_or(t, |n| &n.0))),
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
    use crate::intersect::filter::System;
    use crate::intersect::forms::{cubic, homogeneous_rows, integer_forms};
    use crate::num::point::Point;
    use crate::num::scalar::rat;
    use crate::rational::RationalBezier;
    use num_rational::BigRational;

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

    /// The word route for integer control points ([`intersect_integer_points`]) answers as the
    /// rows do, on random pairs of lines, quadratics and cubics (both domains), pairs sharing an
    /// end, and a cubic against its own left half (an overlap).
    #[test]
    fn integer_points_route_agrees_with_rows() {
        let mut next = crate::num::symmetric(0x1D7E_6E25_0F0F_1A7E);
        let rows =
            |v: &[[i64; 2]]| -> Vec<[BigRational; 3]> { v.iter().map(|p| [rat(p[0]), rat(p[1]), rat(1)]).collect() };
        type Points = Vec<[i64; 2]>;
        let mut pairs: Vec<(Points, Points)> = (0..60)
            .map(|k| {
                let mut curve = |n: usize| (0..=n).map(|_| [next(2048), next(2048)]).collect::<Vec<_>>();
                (curve([3, 2, 1][k % 3]), curve([3, 3, 2, 1][k % 4]))
            })
            .collect();
        pairs.push((vec![[0, 0], [1, 3], [2, 1], [4, 4]], vec![[4, 4], [5, 0], [9, 9]]));
        pairs.push((vec![[0, 0], [8, 16], [16, 0], [24, 8]], vec![[0, 0], [4, 8], [8, 8], [12, 7]]));
        for (a, b) in &pairs {
            for domain in [Domain::Unit, Domain::All] {
                let by_rows = intersect_rows(&rows(a), &rows(b), domain).unwrap();
                let by_words = intersect_integer_points(a, b, domain).expect("small").unwrap();
                assert_eq!(by_words, by_rows, "{a:?} × {b:?}");
            }
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
        let k = intersect_rows(&homogeneous_rows(&para), &homogeneous_rows(&line), Domain::Unit).unwrap();
        assert_eq!(k.intersections.len(), 1);
        assert_eq!(k.intersections[0].kind, Contact::Tangent);
        let i = &k.intersections[0];
        let sys = System::new(&fa, &fb).expect("polynomial curves");
        assert!(!proved_common(&sys, &i.s, &i.t, (i.s_float, i.t_float)));
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
}
