//! Rational splines → rational Bézier segments (three routes), rational patches (three
//! evaluations and operations), and spline nets → patches in both orders.

use casteljau::internal::{check_segments, seed_cubic_segment, seed_quadratic_segment};
use casteljau::proof::Reading;
use casteljau::rational::RationalBezier;
use casteljau::spline::Conversion;
use casteljau::spline::SplineNet;
use casteljau::spline::{RationalSpline, SegmentMismatch};
use casteljau::surface::RationalPatch;
use casteljau::{Point, rat, ratio};
use num_rational::BigRational;
use proptest::prelude::*;

fn p2(x: i64, y: i64) -> Point<BigRational> {
    Point::new(vec![rat(x), rat(y)])
}
fn same(a: &RationalBezier<BigRational>, b: &RationalBezier<BigRational>) -> bool {
    a.points() == b.points() && a.weights() == b.weights()
}

#[test]
fn spline_cubic_unequal_ratios_seed_25_29_equals_boehm_and_nurbs() {
    let pts: Vec<_> = [(0, 0), (1, 3), (3, 4), (5, 1), (7, 2), (8, 5)].iter().map(|&(x, y)| p2(x, y)).collect();
    let w = vec![rat(1), rat(2), ratio(1, 2), rat(3), rat(1), ratio(2, 3)];
    let lam: Vec<_> = [1, 2, 1, 3, 2, 1, 2, 1].iter().map(|&v| rat(v)).collect();
    let sp = RationalSpline::new(3, &pts, &w, &lam).unwrap();
    assert_eq!(sp.segments(), 3);
    let boehm = sp.to_bezier_boehm().unwrap();
    let seed: Vec<_> = (0..3).map(|s| seed_cubic_segment(&sp, s).unwrap()).collect();
    for (a, b) in seed.iter().zip(&boehm) {
        assert!(same(a, b));
    }
    assert_eq!(check_segments(&sp, &seed), Ok(21));
    // the first segment's weights by (29), worked by hand: λ_-2..λ_2 = 2 1 3 2 1, k_-1..k_2 = 1 2 1/2 3:
    // w_-1 = (3·1 + 3·2)/6 = 3/2, w1 = (5·2 + 1/2)/6 = 7/4, w2 = (2·2 + 4·1/2)/6 = 1, w4 = 7/4,
    // w0 = (3·3/2 + 7/4)/4 = 25/16, w3 = (2·1 + 3·7/4)/5 = 29/20
    assert_eq!(seed[0].weights(), vec![ratio(25, 16), ratio(7, 4), rat(1), ratio(29, 20)]);
}

#[test]
fn spline_uniform_nonrational_cubic_is_the_classic_b_spline() {
    // all ratios and weights 1: the uniform cubic B-spline; Bézier points (1/6)(q0 + 4q1 + q2) etc.
    let pts: Vec<_> = [(0, 0), (6, 6), (12, 0), (18, 6)].iter().map(|&(x, y)| p2(x, y)).collect();
    let sp = RationalSpline::new(3, &pts, &vec![rat(1); 4], &vec![rat(1); 6]).unwrap();
    let seg = seed_cubic_segment(&sp, 0).unwrap();
    // (q0 + 4q1 + q2)/6, (2q1 + q2)/3, (q1 + 2q2)/3, (q1 + 4q2 + q3)/6
    let expect: Vec<Option<Point<BigRational>>> =
        [(6, 4), (8, 4), (10, 2), (12, 2)].iter().map(|&(x, y)| Some(p2(x, y))).collect();
    assert_eq!(seg.points(), expect);
}

#[test]
fn spline_quadratic_53_as_printed_fails_corrected_holds() {
    let pts: Vec<_> = [(0, 0), (2, 3), (4, 1), (6, 4), (8, 0)].iter().map(|&(x, y)| p2(x, y)).collect();
    let w = vec![rat(1), rat(3), ratio(1, 2), rat(2), rat(1)];
    let lam: Vec<_> = [1, 2, 1, 3, 2, 1].iter().map(|&v| rat(v)).collect();
    let sp = RationalSpline::new(2, &pts, &w, &lam).unwrap();
    let fixed: Vec<_> =
        (0..sp.segments()).map(|s| seed_quadratic_segment(&sp, s, Reading::Corrected).unwrap()).collect();
    assert!(check_segments(&sp, &fixed).is_ok());
    let printed: Vec<_> =
        (0..sp.segments()).map(|s| seed_quadratic_segment(&sp, s, Reading::AsPrinted).unwrap()).collect();
    assert!(matches!(check_segments(&sp, &printed), Err(SegmentMismatch::NotTheNurbs { .. })));
    // with equal weights the printed formula is right (k0 = k1 makes the misprint harmless)
    let sp1 = RationalSpline::new(2, &pts, &vec![rat(1); 5], &lam).unwrap();
    let printed1: Vec<_> =
        (0..sp1.segments()).map(|s| seed_quadratic_segment(&sp1, s, Reading::AsPrinted).unwrap()).collect();
    assert!(check_segments(&sp1, &printed1).is_ok());
}

#[test]
fn spline_rejects_bad_input() {
    let pts: Vec<_> = (0..4).map(|i| p2(i, i * i)).collect();
    assert!(RationalSpline::new(3, &pts, &vec![rat(1); 4], &vec![rat(1); 5]).is_err()); // needs 6 ratios
    assert!(RationalSpline::new(3, &pts, &vec![rat(1); 4], &[rat(1), rat(0), rat(1), rat(1), rat(1), rat(1)]).is_err());
    assert!(RationalSpline::new(3, &pts, &vec![rat(1); 3], &vec![rat(1); 6]).is_err());
    assert!(RationalSpline::new(4, &pts, &vec![rat(1); 4], &vec![rat(1); 7]).is_err());
}

fn patch() -> RationalPatch {
    let pts: Vec<Vec<Point<BigRational>>> =
        (0..3).map(|i| (0..4).map(|j| Point::new(vec![rat(j), rat(i), rat((i * 3 + j * 5) % 4)])).collect()).collect();
    let w: Vec<Vec<BigRational>> =
        (0..3).map(|i| (0..4).map(|j| ratio(1 + (i + j) % 3, 1 + (i * j) % 2)).collect()).collect();
    RationalPatch::new(pts, w).unwrap()
}

#[test]
fn surface_three_evaluations_subdivision_elevation_iso_curves() {
    let p = patch();
    assert_eq!(p.degree(), (2, 3));
    let grid: Vec<BigRational> = (0..=6).map(|k| ratio(k, 6)).collect();
    let su = p.split(casteljau::surface::ParameterAxis::U, &ratio(1, 3)).unwrap();
    let sv = p.split(casteljau::surface::ParameterAxis::V, &ratio(2, 5)).unwrap();
    let (lu, ru) = (su.first, su.second);
    let (lv, rv) = (sv.first, sv.second);
    let e = p.elevate(1, 2).unwrap();
    assert_eq!(e.degree(), (3, 5));
    for u in &grid {
        for v in &grid {
            let s = p.eval(u, v).unwrap();
            assert_eq!(p.eval_u_then_v(u, v).unwrap(), s);
            assert_eq!(p.eval_v_then_u(u, v).unwrap(), s);
            assert_eq!(e.eval(u, v).unwrap(), s);
            assert_eq!(p.iso_u(u).unwrap().eval(v).unwrap(), s);
            assert_eq!(p.iso_v(v).unwrap().eval(u).unwrap(), s);
            assert_eq!(lu.eval(u, v).unwrap(), p.eval(&(ratio(1, 3) * u), v).unwrap());
            assert_eq!(ru.eval(u, v).unwrap(), p.eval(&(ratio(1, 3) + ratio(2, 3) * u), v).unwrap());
            assert_eq!(lv.eval(u, v).unwrap(), p.eval(u, &(ratio(2, 5) * v)).unwrap());
            assert_eq!(rv.eval(u, v).unwrap(), p.eval(u, &(ratio(2, 5) + ratio(3, 5) * v)).unwrap());
        }
    }
}

#[test]
fn surface_weight_change_48_49_printed_gamma_fails_bernstein_holds() {
    let p = patch();
    let dw = rat(2);
    let changed = p.with_weight_change(1, 1, &dw).unwrap();
    let (u, v) = (ratio(1, 3), ratio(1, 4));
    assert_eq!(p.weight_change(1, 1, &dw, &u, &v, Reading::Corrected).unwrap(), changed.eval(&u, &v).unwrap());
    assert_ne!(p.weight_change(1, 1, &dw, &u, &v, Reading::AsPrinted).unwrap(), changed.eval(&u, &v).unwrap());
}

#[test]
fn surface_contour_polynomial_vanishes_exactly_on_the_contour() {
    let p = patch();
    let c = ratio(3, 2);
    let contour = p.contour(&c, 16).unwrap();
    let f = &contour.bernstein_coefficients;
    // along the iso-curve v = 1/2, F(u, 1/2) = W(u, 1/2)·(z(u, 1/2) − c)
    for k in 0..=8 {
        let (u, v) = (ratio(k, 8), ratio(1, 2));
        let h = p.eval_homogeneous(&u, &v);
        let (bu, bv) = (casteljau::poly::bernstein_all(2, &u), casteljau::poly::bernstein_all(3, &v));
        let fv = f
            .iter()
            .enumerate()
            .fold(rat(0), |acc, (i, r)| r.iter().enumerate().fold(acc, |a, (j, x)| a + x.clone() * &bu[i] * &bv[j]));
        assert_eq!(fv, h.coords[2].clone() - c.clone() * &h.coords[3]);
    }
    assert!(!contour.polyline.unwrap().is_empty());
}

fn net(weights_vary: bool) -> SplineNet {
    let pts: Vec<Vec<Point<BigRational>>> = (0..5)
        .map(|i| (0..5).map(|j| Point::new(vec![rat(j), rat(i), rat((i * j + i + 2 * j) % 5)])).collect())
        .collect();
    let mut w: Vec<Vec<BigRational>> = (0..5)
        .map(|i| {
            (0..5).map(|j| if weights_vary { ratio(1 + (i + 2 * j) % 3, 1 + (i * j) % 2) } else { rat(1) }).collect()
        })
        .collect();
    if weights_vary {
        w[2][2] = rat(3);
    }
    let lambda: Vec<_> = [1, 2, 1, 3, 1, 2].iter().map(|&v| rat(v)).collect();
    let mu: Vec<_> = [2, 1, 1, 2, 3, 1].iter().map(|&v| rat(v)).collect();
    SplineNet::new((2, 2), pts, w, lambda, mu).unwrap()
}

#[test]
fn net_5x5_gives_9_biquadratic_patches_c1_order_independent() {
    let n = net(true);
    for how in [Conversion::Boehm, Conversion::Seed(Reading::Corrected)] {
        let r = n.check(how).unwrap();
        assert_eq!(r.patches, 9);
        assert!(r.order_independent && r.equals_nurbs && r.smooth_joins, "{how:?}: {:?}", r.problem);
    }
    assert_eq!(
        n.to_patches(Conversion::Boehm, true).unwrap(),
        n.to_patches(Conversion::Seed(Reading::Corrected), false).unwrap()
    );
    let printed = n.check(Conversion::Seed(Reading::AsPrinted)).unwrap();
    assert!(!printed.equals_nurbs);
    // with unit weights the misprint is harmless
    let r = net(false).check(Conversion::Seed(Reading::AsPrinted)).unwrap();
    assert!(r.equals_nurbs && r.smooth_joins);
}

fn ratio_s() -> impl Strategy<Value = BigRational> {
    (1i64..=5, 1i64..=3).prop_map(|(p, q)| ratio(p, q))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    #[test]
    fn spline_random_segments_equal_nurbs_with_smooth_joins(
        degree in 1usize..=4, extra in 0usize..=3,
        coords in prop::collection::vec((-9i64..=9, -9i64..=9), 9), weights in prop::collection::vec(ratio_s(), 9), ratios in prop::collection::vec(ratio_s(), 16)
    ) {
        let m = degree + extra;
        let pts: Vec<_> = coords[..=m].iter().map(|&(x, y)| p2(x, y)).collect();
        let sp = RationalSpline::new(degree, &pts, &weights[..=m], &ratios[..m + degree]).unwrap();
        let boehm = sp.to_bezier_boehm().unwrap();
        prop_assert_eq!(boehm.len(), sp.segments());
        prop_assert!(check_segments(&sp, &boehm).is_ok());
        if degree == 3 {
            for (s, b) in boehm.iter().enumerate() {
                prop_assert!(same(&seed_cubic_segment(&sp, s).unwrap(), b));
            }
        }
        if degree == 2 {
            for (s, b) in boehm.iter().enumerate() {
                prop_assert!(same(&seed_quadratic_segment(&sp, s, Reading::Corrected).unwrap(), b));
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    /// Random exact 4×4 biquadratic and bicubic nets with random weights and ratios: patches equal
    /// the tensor NURBS, join C^(min−1), and both conversion orders agree; the seed's corrected
    /// quadratic formulas give the same patches as Boehm.
    #[test]
    fn net_random_exact_nets(
        z in prop::collection::vec(-5i64..=5, 25), w in prop::collection::vec(ratio_s(), 25),
        lam in prop::collection::vec(ratio_s(), 7), mu in prop::collection::vec(ratio_s(), 7), cubic in any::<bool>()
    ) {
        let size = if cubic { 5 } else { 4 };
        let d = if cubic { 3 } else { 2 };
        let pts: Vec<Vec<Point<BigRational>>> = (0..size).map(|i| (0..size).map(|j| Point::new(vec![rat(j as i64), rat(i as i64), rat(z[i * 5 + j])])).collect()).collect();
        let ws: Vec<Vec<BigRational>> = (0..size).map(|i| (0..size).map(|j| w[i * 5 + j].clone()).collect()).collect();
        let n = SplineNet::new((d, d), pts, ws, lam[..size - 1 + d].to_vec(), mu[..size - 1 + d].to_vec()).unwrap();
        let r = n.check(Conversion::Boehm).unwrap();
        prop_assert!(r.order_independent && r.equals_nurbs && r.smooth_joins, "{:?}", r.problem);
        if !cubic {
            prop_assert_eq!(n.to_patches(Conversion::Boehm, true).unwrap(), n.to_patches(Conversion::Seed(Reading::Corrected), true).unwrap());
        }
    }
}

/// `eval_checked` answers as the BigRational routes, on small numbers (fixed-width route) and
/// on numbers whose products overflow `i128` (BigRational fallback).
#[test]
fn surface_eval_checked_agrees_with_every_route_small_and_large() {
    use casteljau::surface::RationalPatch;
    let big = num_rational::BigRational::from_integer(num_bigint::BigInt::from(3u8).pow(90));
    for scale in [casteljau::rat(1), big] {
        let p = |x: i64, y: i64, z: i64| {
            casteljau::Point::new(vec![casteljau::rat(x) * &scale, casteljau::rat(y), casteljau::rat(z)])
        };
        let rows = vec![vec![p(0, 0, 1), p(1, 2, 0), p(2, 0, 3)], vec![p(0, 3, 2), p(2, 2, 2), p(3, 3, 1)]];
        let w = vec![
            vec![casteljau::rat(1), casteljau::rat(2), casteljau::rat(1)],
            vec![casteljau::rat(3), casteljau::rat(1), casteljau::rat(2)],
        ];
        let patch = RationalPatch::new(rows, w).unwrap();
        let (u, v) = (casteljau::ratio(2, 7), casteljau::ratio(5, 9));
        let c = patch.eval_checked(&u, &v, &casteljau::work::Budget::unlimited()).unwrap();
        assert_eq!(c.point, patch.eval(&u, &v).unwrap());
        assert_eq!(c.point, patch.eval_u_then_v(&u, &v).unwrap());
        assert!(c.de_casteljau_u_then_v_and_v_then_u_agree);
    }
}
