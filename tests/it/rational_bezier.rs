//! Rational Bézier curves: seed 000's examples exactly, seed 002's constructions, the three
//! evaluations against each other, operations, denominator safety, implicit equations and the
//! Menelaus configurations.

use casteljau::num::parse_points;
use casteljau::proof::Reading;
use casteljau::rational::Configuration;
use casteljau::rational::ImplicitOutcome;
use casteljau::rational::{ConicType, RationalBezier};
use casteljau::{Error, Point, rat, ratio};
use num_rational::BigRational;
use proptest::prelude::*;

fn rb(points: &str, weights: &[BigRational]) -> RationalBezier<BigRational> {
    RationalBezier::new(parse_points(points, 2, None).unwrap(), weights.to_vec()).unwrap()
}
fn hom(points: &str) -> RationalBezier<BigRational> {
    RationalBezier::from_homogeneous(parse_points(points, 3, None).unwrap()).unwrap()
}
fn pt(x: BigRational, y: BigRational) -> Point<BigRational> {
    Point::new(vec![x, y])
}
fn proved(c: &RationalBezier<BigRational>, f: &str) -> bool {
    matches!(ImplicitOutcome::new(c, f, &casteljau::work::Budget::unlimited()).unwrap(), ImplicitOutcome::Proved { .. })
}
fn params() -> Vec<BigRational> {
    (0..=12).map(|k| ratio(k, 12)).chain([ratio(-3, 2), ratio(7, 5)]).collect()
}

#[test]
fn rational_seed_000_example_1_weights_pull_the_curve() {
    let pts = "-2 0, -1 3, 1 2, 2 0";
    let base = rb(pts, &[rat(1), rat(1), rat(1), rat(1)]);
    // all weights equal: the Bézier curve
    let poly = casteljau::BezierCurve::new(parse_points(pts, 2, None).unwrap()).unwrap();
    for t in params() {
        assert_eq!(base.eval(&t).unwrap(), poly.eval(&t));
    }
    // w1 = 3 (blue) moves every interior point strictly towards b1; w2 = 4 (brown) towards b2
    for (i, w, b) in [(1, rat(3), pt(rat(-1), rat(3))), (2, rat(4), pt(rat(1), rat(2)))] {
        let heavy = base.with_weight(i, w).unwrap();
        for k in 1..12 {
            let t = ratio(k, 12);
            let (p, q) = (base.eval(&t).unwrap(), heavy.eval(&t).unwrap());
            let (dp, dq) = (p.sub(&b), q.sub(&b));
            assert!(dq.dot(&dq) < dp.dot(&dp), "t = {t}");
        }
    }
}

#[test]
fn rational_seed_000_example_2_folium() {
    let c = rb("0 0, 1 0, 2 1, 3/2 3/2", &[rat(1), rat(1), rat(1), rat(2)]);
    for t in params() {
        let d = rat(1) + t.clone() * &t * &t;
        assert_eq!(c.eval(&t).unwrap(), pt(rat(3) * &t / d.clone(), rat(3) * &t * &t / d));
    }
    assert!(proved(&c, "x^3 - 3*x*y + y^3"));
    // x'(t) = (3 − 6t³)/(1 + t³)², y'(t) = (6t − 3t⁴)/(1 + t³)²
    for t in params() {
        let d = rat(1) + t.clone() * &t * &t;
        let t3 = t.clone() * &t * &t;
        let expected =
            pt((rat(3) - rat(6) * &t3) / (d.clone() * &d), (rat(6) * &t - rat(3) * &t3 * &t) / (d.clone() * &d));
        assert_eq!(c.derivative_at(&t).unwrap(), expected);
    }
}

#[test]
fn rational_seed_000_example_3_astroid() {
    let w: Vec<BigRational> = ["1", "1", "6/5", "8/5", "12/5", "4", "8"].iter().map(|s| s.parse().unwrap()).collect();
    let c = rb("0 1, 0 1, 0 2/3, 1/4 1/4, 2/3 0, 1 0, 1 0", &w);
    for t in params() {
        let d = rat(1) + t.clone() * &t;
        let d3 = d.clone() * &d * &d;
        let u = rat(1) - t.clone() * &t;
        assert_eq!(c.eval(&t).unwrap(), pt(rat(8) * &t * &t * &t / d3.clone(), u.clone() * &u * &u / d3));
    }
    assert!(proved(&c, "(x^2 + y^2 - 1)^3 + 27*x^2*y^2"));
}

#[test]
fn rational_seed_000_example_4_semicircle() {
    let c = rb("1 0, 1 2, -1 2, -1 0", &[rat(1), ratio(1, 3), ratio(1, 3), rat(1)]);
    for t in params() {
        let d = rat(1) - rat(2) * &t + rat(2) * &t * &t;
        assert_eq!(c.eval(&t).unwrap(), pt((rat(1) - rat(2) * &t) / d.clone(), rat(2) * &t * (rat(1) - &t) / d));
    }
    assert!(proved(&c, "x^2 + y^2 - 1"));
}

/// Example 5 at every half-angle with rational (cos, sin): Pythagorean triples, both signs.
#[test]
fn rational_seed_000_example_5_circle_arcs_including_s_pi() {
    for (a, b, h) in [(3, 4, 5), (4, 3, 5), (5, 12, 13), (12, 5, 13), (8, 15, 17), (20, 21, 29), (0, 1, 1)] {
        for sign in [1, -1] {
            let (c, s) = (ratio(a, h), ratio(sign * b, h)); // cos(s/2), sin(s/2)
            let (cos_s, sin_s) = (c.clone() * &c - s.clone() * &s, rat(2) * &c * &s);
            // homogeneous b1 = w1·(1, tan(s/2), 1) = (c, s, c): at s = π (c = 0) a point at infinity
            let curve = RationalBezier::from_homogeneous(vec![
                Point::new(vec![rat(1), rat(0), rat(1)]),
                Point::new(vec![c.clone(), s.clone(), c.clone()]),
                Point::new(vec![cos_s.clone(), sin_s.clone(), rat(1)]),
            ])
            .unwrap();
            assert!(proved(&curve, "x^2 + y^2 - 1"), "{a}/{h}");
            for t in params() {
                let u = rat(1) - &t;
                let den = u.clone() * &u + rat(2) * &t * &u * &c + t.clone() * &t;
                let x = (u.clone() * &u + rat(2) * &t * &u * &c + t.clone() * &t * &cos_s) / den.clone();
                let y = (rat(2) * &t * &u * &s + t.clone() * &t * &sin_s) / den;
                assert_eq!(curve.eval(&t).unwrap(), pt(x, y), "example 5 formula");
            }
            assert_eq!(curve.eval(&rat(1)).unwrap(), pt(cos_s, sin_s));
        }
    }
}

#[test]
fn rational_seed_000_example_6_hyperbola() {
    // cosh(s/2) = 5/4, sinh(s/2) = 3/4: p = 17/8, q = 15/8, tanh(s/2) = (p − 1)/q = 3/5
    let (ch, sh) = (ratio(5, 4), ratio(3, 4));
    let (p, q) = (rat(2) * &ch * &ch - rat(1), rat(2) * &sh * &ch);
    assert_eq!((p.clone(), q.clone()), (ratio(17, 8), ratio(15, 8)));
    assert_eq!((p.clone() - rat(1)) / q.clone(), ratio(3, 5));
    assert_eq!(ch.clone() * &ch, (p.clone() + rat(1)) / rat(2)); // cosh(s/2) = √((p+1)/2)
    assert_eq!(sh.clone() * &sh, (p.clone() - rat(1)) / rat(2)); // sinh(s/2) = √((p−1)/2)
    let c = RationalBezier::new(
        vec![pt(rat(1), rat(0)), pt(rat(1), ratio(3, 5)), pt(p.clone(), q.clone())],
        vec![rat(1), ch.clone(), rat(1)],
    )
    .unwrap();
    assert!(proved(&c, "x^2 - y^2 - 1"));
    assert_eq!(c.eval(&rat(1)).unwrap(), pt(p, q));
    assert_eq!(c.conic_type().unwrap().0, ConicType::Hyperbola);
}

#[test]
fn rational_conic_types() {
    let circle = rb("1 0, 1 1, 0 1", &[rat(2), rat(1), rat(1)]); // w1² = 1 < 2: ellipse
    assert_eq!(circle.conic_type().unwrap(), (ConicType::Ellipse, Some(ratio(1, 2))));
    assert_eq!(rb("0 0, 1 1, 2 0", &[rat(1), rat(1), rat(1)]).conic_type().unwrap().0, ConicType::Parabola);
    assert_eq!(rb("0 0, 1 1, 2 0", &[rat(1), rat(2), rat(1)]).conic_type().unwrap().0, ConicType::Hyperbola);
    assert_eq!(rb("0 0, 1 1, 2 2", &[rat(1), rat(2), rat(1)]).conic_type().unwrap().0, ConicType::Degenerate);
    assert!(rb("0 0, 1 1, 2 0, 3 3", &[rat(1), rat(1), rat(1), rat(1)]).conic_type().is_err());
    // the semicircle of example 5 at s = π (w1 = 0): an ellipse (a circle)
    assert_eq!(hom("1 0 1, 0 1 0, -1 0 1").conic_type().unwrap().0, ConicType::Ellipse);
}

#[test]
fn rational_denominator_vanishing_is_an_error_with_an_isolating_interval() {
    let c = rb("0 0, 1 1, 2 0", &[rat(1), rat(-2), rat(1)]); // W = 6t² − 6t + 1: roots 1/2 ± √3/6
    let e = c.check_defined(&rat(0), &rat(1)).unwrap_err();
    let Error::WeightsVanish { interval: (a, b) } = &e else { panic!("{e}") };
    let (a, b): (BigRational, BigRational) = (a.parse().unwrap(), b.parse().unwrap());
    // the root 1/2 − √3/6 ≈ 0.2113 lies in (a, b)
    let r = 0.5 - 3f64.sqrt() / 6.0;
    assert!(casteljau::num::ratio_to_f64(&a) < r && r < casteljau::num::ratio_to_f64(&b));
    assert!(e.to_string().contains("undefined"));
    // on a sub-interval avoiding the roots it is defined
    assert!(c.check_defined(&ratio(1, 4), &ratio(3, 4)).is_ok());
    // a root exactly at t = 1/2
    let d = rb("0 0, 1 1, 2 0", &[rat(1), rat(-1), rat(1)]);
    assert_eq!(
        d.check_defined(&rat(0), &rat(1)).unwrap_err(),
        Error::WeightsVanish { interval: ("1/2".into(), "1/2".into()) }
    );
    assert!(d.eval(&ratio(1, 2)).is_err());
    // positive weights: defined
    assert!(rb("0 0, 1 1, 2 0", &[rat(1), rat(5), rat(1)]).check_defined(&rat(0), &rat(1)).is_ok());
}

#[test]
fn rational_standard_form_when_rational() {
    let c = rb("0 0, 1 2, 3 1", &[rat(4), rat(3), rat(1)]); // w0/w2 = 4 = 2²: ρ = 2
    let (s, rho) = c.standard_form().unwrap();
    assert_eq!(rho, rat(2));
    assert_eq!((s.weights()[0].clone(), s.weights()[2].clone()), (rat(1), rat(1)));
    for k in 0..=8 {
        let sv = ratio(k, 8);
        let t = rho.clone() * &sv / (rat(1) - &sv + rho.clone() * &sv);
        assert_eq!(s.eval(&sv).unwrap(), c.eval(&t).unwrap());
    }
    assert!(rb("0 0, 1 2, 3 1", &[rat(2), rat(3), rat(1)]).standard_form().is_err()); // √2
}

#[test]
fn rational_weight_change_23_as_printed_fails_and_bernstein_form_holds() {
    let c = rb("0 0, 1 3, 3 2, 4 0", &[rat(1), rat(2), ratio(1, 2), rat(1)]);
    let dw = rat(3);
    let t = ratio(1, 3);
    let changed = c.with_weight(1, rat(2) + &dw).unwrap();
    assert_eq!(c.weight_change(1, &dw, &t, Reading::Corrected).unwrap(), changed.eval(&t).unwrap());
    assert_ne!(c.weight_change(1, &dw, &t, Reading::AsPrinted).unwrap(), changed.eval(&t).unwrap());
}

fn rational() -> impl Strategy<Value = BigRational> {
    (-30i64..=30, 1i64..=7).prop_map(|(p, q)| ratio(p, q))
}
fn weight() -> impl Strategy<Value = BigRational> {
    (1i64..=20, 1i64..=7).prop_map(|(p, q)| ratio(p, q))
}
fn curve() -> impl Strategy<Value = RationalBezier<BigRational>> {
    (1usize..=5).prop_flat_map(|n| {
        (prop::collection::vec((rational(), rational()), n + 1), prop::collection::vec(weight(), n + 1)).prop_map(
            |(p, w)| RationalBezier::new(p.into_iter().map(|(x, y)| Point::new(vec![x, y])).collect(), w).unwrap(),
        )
    })
}
fn unit() -> impl Strategy<Value = BigRational> {
    (0i64..=40).prop_map(|k| ratio(k, 40))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]

    #[test]
    fn rational_three_evaluations_agree(c in curve(), t in unit()) {
        let x = c.eval(&t).unwrap();
        prop_assert_eq!(&c.eval_rational_de_casteljau(&t).unwrap(), &x);
        prop_assert_eq!(&c.eval_saito_hosaka(&t).unwrap(), &x);
    }

    #[test]
    fn rational_subdivision_halves_reproduce_the_curve(c in curve(), t0 in unit(), s in unit()) {
        let (l, r) = c.subdivide(&t0).unwrap();
        prop_assert_eq!(l.eval(&s).unwrap(), c.eval(&(t0.clone() * &s)).unwrap());
        prop_assert_eq!(r.eval(&s).unwrap(), c.eval(&(t0.clone() + (rat(1) - &t0) * &s)).unwrap());
    }

    #[test]
    fn rational_elevation_preserves_the_curve_both_routes(c in curve(), t in unit()) {
        let e = c.elevate(1).unwrap();
        let sh = c.elevate_saito_hosaka().unwrap();
        prop_assert_eq!(e.eval(&t).unwrap(), c.eval(&t).unwrap());
        prop_assert_eq!(sh.eval(&t).unwrap(), c.eval(&t).unwrap());
        // (22) gives the same control points as homogeneous elevation
        prop_assert_eq!(sh.points(), e.points());
    }

    #[test]
    fn rational_scaling_all_weights_changes_nothing(c in curve(), k in weight(), t in unit()) {
        let scaled = RationalBezier::from_homogeneous(c.homogeneous().points().iter().map(|p| p.scale(&k)).collect()).unwrap();
        prop_assert_eq!(scaled.eval(&t).unwrap(), c.eval(&t).unwrap());
    }

    #[test]
    fn rational_weight_change_23(c in curve(), i in 0usize..6, dw in weight(), t in unit()) {
        let i = i % (c.degree() + 1);
        let w = c.weights()[i].clone();
        let changed = c.with_weight(i, w + &dw).unwrap();
        prop_assert_eq!(c.weight_change(i, &dw, &t, Reading::Corrected).unwrap(), changed.eval(&t).unwrap());
    }

    #[test]
    fn rational_derivative_equal_weights_is_the_hodograph(c in curve(), k in weight(), t in unit()) {
        let pts: Vec<Point<BigRational>> = c.points().into_iter().map(Option::unwrap).collect();
        let poly = casteljau::BezierCurve::new(pts.clone()).unwrap();
        let equal = RationalBezier::new(pts, vec![k; c.degree() + 1]).unwrap();
        prop_assert_eq!(equal.derivative_at(&t).unwrap(), poly.derivative(1).eval(&t));
    }

    #[test]
    fn menelaus_lemmas_hold_for_random_configurations(
        o in prop::collection::vec(rational(), 3), p0 in prop::collection::vec(rational(), 3), p1 in prop::collection::vec(rational(), 3),
        w0 in weight(), w1 in weight(), t in unit(), three_d in any::<bool>()
    ) {
        let dim = if three_d { 3 } else { 2 };
        let cut = |v: Vec<BigRational>| Point::new(v[..dim].to_vec());
        let Ok(cfg) = Configuration::new(cut(o), cut(p0), cut(p1), w0, w1, t) else { return Ok(()) };
        prop_assert!(cfg.claim_56_holds());
        prop_assert!(cfg.claim_5_holds());
        prop_assert!(cfg.rational_interpolation_holds());
        prop_assert_eq!(cfg.o.add(&cfg.p_e.sub(&cfg.o).scale(&cfg.lambda)), cfg.p_a.clone());
    }
}

#[test]
fn menelaus_4_as_printed_fails_on_an_example() {
    let cfg = Configuration::new(
        pt(rat(0), rat(0)),
        pt(rat(4), rat(1)),
        pt(rat(1), rat(3)),
        rat(2),
        ratio(1, 2),
        ratio(1, 3),
    )
    .unwrap();
    assert!(cfg.claim_56_holds() && cfg.claim_5_holds());
    assert!(!cfg.claim_4_holds(Reading::AsPrinted));
    assert!(
        Configuration::new(pt(rat(0), rat(0)), pt(rat(1), rat(1)), pt(rat(2), rat(2)), rat(1), rat(1), ratio(1, 2))
            .is_err()
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(100))]

    /// The exact report's fraction-free evaluator ([`RationalEvaluation::new`]) equals the closed
    /// form, including where it is undefined.
    #[test]
    fn rational_exact_evaluator_equals_closed_form(c in curve(), t in (-40i64..=80).prop_map(|k| ratio(k, 40))) {
        let fast = casteljau::rational::RationalEvaluation::new(&c, std::slice::from_ref(&t), &casteljau::work::Budget::unlimited());
        prop_assert_eq!(fast.map(|e| e.values[0].point.clone()), c.eval(&t));
    }
}
