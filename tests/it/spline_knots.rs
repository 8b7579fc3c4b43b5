//! Splines from knot vectors (clamped, multiple knots): conversion to Bézier with proved joins,
//! knot insertion and exact removal, degree elevation — checked against an independent exact
//! Cox–de Boor evaluation and the seed's scale-ratio route.

use casteljau::num::Point;
use casteljau::rational::ImplicitOutcome;
use casteljau::spline::{Conversion, RationalSpline};
use casteljau::{Scalar, rat, ratio};
use num_rational::BigRational;
use proptest::prelude::*;

/// One knot insertion ([`RationalSpline::insert_knot`] once).
fn insert_once(sp: &RationalSpline, u: &BigRational) -> casteljau::Result<RationalSpline> {
    sp.insert_knot(u, 1)
}

/// One exact knot removal: the spline without the knot, or `None` when removing it would change
/// the curve ([`RationalSpline::remove_knot`] once).
fn remove_once(sp: &RationalSpline, u: &BigRational) -> casteljau::Result<Option<RationalSpline>> {
    let r = sp.remove_knot(u, 1)?;
    Ok(r.removable.then_some(r.spline))
}

fn h(x: BigRational, y: BigRational, w: BigRational) -> Point<BigRational> {
    Point::new(vec![x * &w, y * &w, w])
}

/// Cox–de Boor basis functions `N_{i,p}(u)` on the full knot vector, right-continuous, with
/// the right end of the domain closed — an evaluation independent of de Boor's recursion.
fn basis(knots: &[BigRational], i: usize, p: usize, u: &BigRational, end: &BigRational) -> BigRational {
    if p == 0 {
        let inside = if *u == *end {
            knots[i] < *end && knots[i + 1] == *end // the last span is closed on the right
        } else {
            knots[i] <= *u && *u < knots[i + 1]
        };
        return if inside { rat(1) } else { rat(0) };
    }
    let mut v = rat(0);
    let d1 = knots[i + p].clone() - &knots[i];
    if !Scalar::is_zero(&d1) {
        v += (u.clone() - &knots[i]) / d1 * basis(knots, i, p - 1, u, end);
    }
    let d2 = knots[i + p + 1].clone() - &knots[i + 1];
    if !Scalar::is_zero(&d2) {
        v += (knots[i + p + 1].clone() - u) / d2 * basis(knots, i + 1, p - 1, u, end);
    }
    v
}

fn cox_de_boor(
    full_knots: &[BigRational],
    p: usize,
    pts: &[Point<BigRational>],
    u: &BigRational,
) -> Point<BigRational> {
    let m = pts.len() - 1;
    let end = full_knots[m + 1].clone();
    let mut acc = Point::origin(pts[0].dim());
    for (i, q) in pts.iter().enumerate() {
        acc = acc.add(&q.scale(&basis(full_knots, i, p, u, &end)));
    }
    acc
}

/// A full circle as a clamped rational quadratic NURBS with double interior knots, from four
/// seed-000 arcs with rational weights: half-angle cosines 3/5 and 4/5 (the angles add to π).
fn circle() -> RationalSpline {
    let pts = vec![
        h(rat(1), rat(0), rat(1)),
        h(rat(1), ratio(4, 3), ratio(3, 5)),
        h(ratio(-7, 25), ratio(24, 25), rat(1)),
        h(rat(-1), ratio(3, 4), ratio(4, 5)),
        h(rat(-1), rat(0), rat(1)),
        h(rat(-1), ratio(-4, 3), ratio(3, 5)),
        h(ratio(7, 25), ratio(-24, 25), rat(1)),
        h(rat(1), ratio(-3, 4), ratio(4, 5)),
        h(rat(1), rat(0), rat(1)),
    ];
    RationalSpline::from_knots(2, pts, &[0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4].map(rat)).unwrap()
}

#[test]
fn knots_circle_from_rational_arcs_has_four_segments_on_the_unit_circle() {
    let c = circle();
    let segs = c.bezier_segments().unwrap();
    assert_eq!(segs.len(), 4);
    for s in &segs {
        match ImplicitOutcome::new(s, "x^2 + y^2 - 1", &casteljau::work::Budget::unlimited()).unwrap() {
            ImplicitOutcome::Proved { .. } => {}
            other => panic!("{other:?}"),
        }
    }
    let joins = c.joins(&segs);
    assert_eq!(joins.len(), 3);
    assert!(joins.iter().all(|j| j.multiplicity == 2 && j.continuity == 0 && j.proved), "{joins:?}");
    // the curve is closed and passes (−1, 0) at u = 2
    assert_eq!(c.eval_at(&rat(2)).unwrap().to_string(), "(-1, 0)");
    assert_eq!(c.eval_at(&rat(0)).unwrap(), c.eval_at(&rat(4)).unwrap());
}

/// Knot 1 of this C² cubic is essential (the third derivatives jump there): removal refused.
#[test]
fn knots_removing_an_essential_knot_is_refused() {
    let p: Vec<Point<BigRational>> =
        [(0, 0), (1, 3), (2, -1), (4, 2), (5, 0)].iter().map(|&(x, y)| h(rat(x), rat(y), rat(1))).collect();
    let sp = RationalSpline::from_knots(3, p, &[0, 0, 0, 0, 1, 2, 2, 2, 2].map(rat)).unwrap();
    assert_eq!(remove_once(&sp, &rat(1)).unwrap(), None);
    // inserted once more, it comes out again
    let more = insert_once(&sp, &rat(1)).unwrap();
    assert_eq!(remove_once(&more, &rat(1)).unwrap(), Some(sp));
}

#[test]
fn knots_validation_names_the_offending_knot() {
    let p: Vec<Point<BigRational>> = (0..5).map(|i| h(rat(i), rat(i % 2), rat(1))).collect();
    let err = |k: &[i64]| {
        RationalSpline::from_knots(2, p.clone(), &k.iter().map(|&v| rat(v)).collect::<Vec<_>>())
            .unwrap_err()
            .to_string()
    };
    assert!(err(&[0, 0, 0, 2, 1, 3, 3, 3]).contains("knot 5 (1) is less than knot 4 (2)"));
    assert!(err(&[0, 0, 0, 0, 1, 3, 3, 3]).contains("multiplicity 4"));
    assert!(err(&[0, 0, 0, 1, 3, 3, 3]).contains("need 8 knots"));
    assert!(err(&[0, 1, 1, 1, 1, 1, 1, 2]).contains("multiplicity"));
    assert!(err(&[1, 1, 1, 1, 1, 1, 2, 2]).contains("multiplicity"));
}

#[test]
fn knots_unclamped_uniform_cubic_matches_the_seed_ratio_route() {
    // the seed's scale ratios 1, 2, 1, 3, 1, 2, 1 are the knot vector 0 1 3 4 7 8 10 11 (+ any last knot)
    let q: Vec<Point<BigRational>> = (0..5).map(|i| Point::new(vec![rat(i), rat((i * i) % 3)])).collect();
    let w = [1, 2, 1, 3, 1].map(rat);
    let ratios = [1, 2, 1, 3, 1, 2, 1].map(rat);
    let seed = RationalSpline::new(3, &q, &w, &ratios).unwrap();
    let hom: Vec<_> = q.iter().zip(&w).map(|(p, w)| p.to_homogeneous(w)).collect();
    let knots = RationalSpline::from_knots(3, hom, &[0, 1, 3, 4, 7, 8, 10, 11, 12].map(rat)).unwrap();
    assert_eq!(knots.knot_vector(), seed.knot_vector());
    let by_knots = knots.bezier_segments().unwrap();
    assert_eq!(by_knots, seed.to_bezier_boehm().unwrap());
    assert_eq!(by_knots, seed.to_bezier(Conversion::Seed(casteljau::proof::Reading::Corrected)).unwrap());
    assert!(knots.joins(&by_knots).iter().all(|j| j.continuity == 2 && j.proved));
}

/// Random splines of degree 1..=4 with clamped or unclamped ends and interior multiplicities
/// 1..=degree, homogeneous points with non-zero weights.
fn spline() -> impl Strategy<Value = (RationalSpline, Vec<BigRational>)> {
    (1usize..=4, 0usize..=3, any::<bool>(), any::<bool>()).prop_flat_map(|(n, interior, clamp_l, clamp_r)| {
        (
            Just(n),
            prop::collection::vec(1usize..=n, interior),
            Just((clamp_l, clamp_r)),
            prop::collection::vec((-6i64..=6, -6i64..=6, 1i64..=4), 40),
        )
            .prop_map(|(n, mults, (cl, cr), raw)| {
                let mut knots: Vec<BigRational> = Vec::new();
                // left end: clamped (n + 1 copies of 0) or n + 1 distinct knots −n..=0
                if cl {
                    knots.extend(std::iter::repeat_n(rat(0), n + 1));
                } else {
                    knots.extend((0..=n).map(|k| rat(k as i64 - n as i64)));
                }
                for (k, mu) in mults.iter().enumerate() {
                    knots.extend(std::iter::repeat_n(ratio(2 * k as i64 + 1, 2), *mu));
                }
                let end = rat(mults.len() as i64 + 1);
                if cr {
                    knots.extend(std::iter::repeat_n(end.clone(), n + 1));
                } else {
                    knots.extend((0..=n).map(|k| end.clone() + rat(k as i64)));
                }
                let points = knots.len() - n - 1;
                let pts: Vec<Point<BigRational>> =
                    raw.iter().take(points).map(|&(x, y, w)| h(rat(x), rat(y), ratio(w, 2))).collect();
                (RationalSpline::from_knots(n, pts, &knots).unwrap(), knots)
            })
    })
}

fn params(sp: &RationalSpline) -> Vec<BigRational> {
    let (a, b) = sp.domain();
    (0..=12).map(|k| a.clone() + (b.clone() - &a) * ratio(k, 12)).collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn knots_de_boor_equals_cox_de_boor((sp, full) in spline()) {
        for u in params(&sp) {
            prop_assert_eq!(sp.eval_homogeneous_at(&u).unwrap(), cox_de_boor(&full, sp.degree, &sp.homogeneous, &u));
        }
    }

    #[test]
    fn knots_bezier_pieces_are_the_spline_and_joins_are_proved((sp, _) in spline()) {
        let pieces = sp.bezier_pieces().unwrap();
        for piece in &pieces {
            let (a, b) = &piece.span;
            let c = casteljau::BezierCurve::new(piece.homogeneous.clone()).unwrap();
            for k in 0..=4 {
                let s = ratio(k, 4);
                let u = a.clone() + (b.clone() - a) * &s;
                prop_assert_eq!(c.eval(&s), sp.eval_homogeneous_at(&u).unwrap());
            }
        }
        let segs = sp.bezier_segments().unwrap();
        for j in sp.joins(&segs) {
            prop_assert!(j.proved, "{:?}", j);
            prop_assert_eq!(j.continuity, sp.degree as i64 - j.multiplicity as i64);
        }
    }

    #[test]
    fn knots_insert_then_remove_returns_the_spline((sp, _) in spline(), k in 1i64..=7) {
        let (a, b) = sp.domain();
        let u = a.clone() + (b - &a) * ratio(k, 8);
        if let Ok(more) = insert_once(&sp, &u) {
            for x in params(&sp) {
                prop_assert_eq!(more.eval_homogeneous_at(&x).unwrap(), sp.eval_homogeneous_at(&x).unwrap());
            }
            prop_assert_eq!(remove_once(&more, &u).unwrap(), Some(sp.clone()));
        }
    }

    /// Bézier form and back: insert every interior knot up to multiplicity n, then remove the
    /// inserted copies again: the input spline, exactly.
    #[test]
    fn knots_to_bezier_and_back_by_removal_is_exact((sp, _) in spline()) {
        let n = sp.degree;
        let (a, b) = sp.domain();
        let interior: Vec<BigRational> = {
            let mut v: Vec<_> = sp.knot_vector().iter().filter(|k| **k > a && **k < b).cloned().collect();
            v.dedup();
            v
        };
        let mut bez = sp.clone();
        let mut inserted = Vec::new();
        for u in &interior {
            while bez.knot_vector().iter().filter(|k| *k == u).count() < n {
                bez = insert_once(&bez, u).unwrap();
                inserted.push(u.clone());
            }
        }
        for u in inserted.iter().rev() {
            bez = remove_once(&bez, u).unwrap().expect("an inserted knot is removable");
        }
        prop_assert_eq!(bez, sp);
    }

    /// A removal, when accepted, keeps the curve (the definition of an exact removal).
    #[test]
    fn knots_accepted_removal_keeps_the_curve((sp, _) in spline()) {
        let (a, b) = sp.domain();
        let interior: Vec<BigRational> = sp.knot_vector().iter().filter(|k| **k > a && **k < b).cloned().collect();
        for u in interior {
            if let Some(less) = remove_once(&sp, &u).unwrap() {
                for x in params(&sp) {
                    prop_assert_eq!(less.eval_homogeneous_at(&x).unwrap(), sp.eval_homogeneous_at(&x).unwrap());
                }
            }
        }
    }

    #[test]
    fn knots_degree_elevation_keeps_the_curve((sp, _) in spline()) {
        prop_assume!(sp.degree < 4);
        let up = sp.elevate_degree().unwrap();
        prop_assert_eq!(up.degree, sp.degree + 1);
        for x in params(&sp) {
            let (p, q) = (up.eval_homogeneous_at(&x).unwrap(), sp.eval_homogeneous_at(&x).unwrap());
            prop_assert_eq!(p, q);
        }
        for j in up.joins(&up.bezier_segments().unwrap()) {
            prop_assert!(j.proved);
        }
    }
}

#[test]
fn knots_surface_equals_the_seed_net_route_and_is_proved() {
    use casteljau::spline::NurbsSurface;
    use casteljau::spline::SplineNet;
    let pts: Vec<Vec<Point<BigRational>>> = (0..5)
        .map(|i| (0..5).map(|j| Point::new(vec![rat(j), rat(i), rat((i * j + i + 2 * j) % 5)])).collect())
        .collect();
    let w: Vec<Vec<BigRational>> =
        (0..5).map(|i| (0..5).map(|j| ratio(1 + (i + 2 * j) % 3, 1 + (i * j) % 2)).collect()).collect();
    let (lambda, mu) = ([1, 2, 1, 3, 1, 2].map(rat).to_vec(), [2, 1, 1, 2, 3, 1].map(rat).to_vec());
    let net = SplineNet::new((2, 2), pts.clone(), w.clone(), lambda, mu).unwrap();
    let rows: Vec<Vec<Point<BigRational>>> =
        pts.iter().zip(&w).map(|(r, wr)| r.iter().zip(wr).map(|(p, w)| p.to_homogeneous(w)).collect()).collect();
    let s = NurbsSurface::from_knots(
        (2, 2),
        rows,
        &[0, 1, 3, 4, 7, 8, 10, 11].map(rat),
        &[0, 2, 3, 4, 6, 9, 10, 11].map(rat),
    )
    .unwrap();
    let by_net = net.to_patches(Conversion::Boehm, false).unwrap();
    let by_knots = s.bezier_patches().unwrap();
    assert_eq!(by_knots.len(), 3);
    for (a, b) in by_net.iter().flatten().zip(by_knots.iter().flatten()) {
        assert_eq!(a, &b.patch);
    }
    let r = s.check().unwrap();
    assert_eq!(r.patches, 9);
    assert!(r.equals_surface && r.joins_proved, "{r:?}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Random clamped NURBS surfaces with a repeated interior knot: the patches equal the
    /// surface and every join has the continuity of its multiplicity.
    #[test]
    fn knots_surface_patches_are_proved(p in 1usize..=3, q in 1usize..=2, mu in 1usize..=3, raw in prop::collection::vec((-5i64..=5, 1i64..=3), 64)) {
        use casteljau::spline::NurbsSurface;
        let mu = mu.min(p);
        let mut ku: Vec<BigRational> = vec![rat(0); p + 1];
        ku.extend(std::iter::repeat_n(rat(1), mu));
        ku.extend(std::iter::repeat_n(rat(3), p + 1));
        let kv: Vec<BigRational> = [vec![rat(0); q + 1], vec![ratio(1, 2)], vec![rat(1); q + 1]].concat();
        let (m, l) = (ku.len() - p - 1, kv.len() - q - 1);
        let rows: Vec<Vec<Point<BigRational>>> = (0..m)
            .map(|i| (0..l).map(|j| {
                let (z, w) = raw[(i * l + j) % raw.len()];
                let w = ratio(w, 2);
                Point::new(vec![rat(i as i64) * &w, rat(j as i64) * &w, rat(z) * &w, w])
            }).collect())
            .collect();
        let s = NurbsSurface::from_knots((p, q), rows, &ku, &kv).unwrap();
        let r = s.check().unwrap();
        prop_assert!(r.equals_surface && r.joins_proved, "{:?}", r);
    }
}

/// A spline whose numbers outgrow `i128` products: the fixed-width route of the check
/// overflows and the BigRational route answers, with the same verdict and point count as a
/// small spline of the same shape.
#[test]
fn spline_check_falls_back_to_big_rationals_on_overflow_with_the_same_verdict() {
    let big = BigRational::from_integer(num_bigint::BigInt::from(1u8) << 100u32);
    let pts: Vec<Point<BigRational>> =
        [(0, 0), (1, 3), (2, -1), (4, 2), (5, 0)].iter().map(|&(x, y)| h(rat(x), rat(y), rat(1))).collect();
    let knots = [0, 0, 0, 0, 1, 2, 2, 2, 2].map(rat);
    let scaled: Vec<Point<BigRational>> =
        pts.iter().enumerate().map(|(i, p)| p.scale(&(big.clone() + rat(i as i64)))).collect();
    let budget = casteljau::work::Budget::unlimited();
    let small =
        casteljau::spline::SplineCheck::new(&RationalSpline::from_knots(3, pts, &knots).unwrap(), &budget).unwrap();
    let large =
        casteljau::spline::SplineCheck::new(&RationalSpline::from_knots(3, scaled, &knots).unwrap(), &budget).unwrap();
    assert!(small.passed && large.passed);
    assert_eq!(small.boehm, Ok(14));
    assert_eq!(large.boehm, small.boehm);
    // a wrong segment is still caught by both routes
    let sp =
        RationalSpline::from_knots(3, (0..5).map(|i| h(big.clone() * rat(i), rat(i * i), rat(1))).collect(), &knots)
            .unwrap();
    let mut segs = sp.to_bezier_boehm().unwrap();
    segs.swap(0, 1);
    assert!(matches!(
        casteljau::internal::check_segments(&sp, &segs),
        Err(casteljau::spline::SegmentMismatch::NotTheNurbs { segment: 0, .. })
    ));
}

/// Scale ratios are knot intervals: `from_ratios` is `from_knots` on their partial sums, and
/// `new` (affine points and weights) is `from_ratios` on the weighted points.
#[test]
fn spline_from_ratios_is_from_knots_on_the_partial_sums() {
    let q: Vec<Point<BigRational>> = (0..5).map(|i| Point::new(vec![rat(i), rat(i * i % 3)])).collect();
    let w = [1, 2, 1, 3, 1].map(rat);
    let ratios = [1, 2, 1, 3, 1, 2, 1].map(rat);
    let hom = casteljau::spline::homogeneous_control_points(&q, Some(&w)).unwrap();
    let by_ratios = RationalSpline::from_ratios(3, hom.clone(), &ratios).unwrap();
    let by_knots = RationalSpline::from_knots(3, hom, &[0, 1, 3, 4, 7, 8, 10, 11, 11].map(rat)).unwrap();
    assert_eq!(by_ratios, by_knots);
    assert_eq!(RationalSpline::new(3, &q, &w, &ratios).unwrap(), by_ratios);
    let e = RationalSpline::new(3, &q, &w, &ratios[1..]).unwrap_err().to_string();
    assert!(e.contains("need 7 scale ratios, got 6"), "{e}");
}
