//! Exact cubic classification: the 16 classes, constructed edge cases, and properties that
//! check every exact answer independently (P(t1) = P(t2) in Q(√d), P'(cusp) = 0,
//! P'×P'' = 0 at inflections) and against the seed's moving lines and Loop–Blinn.

use casteljau::classify::MovingLines;
use casteljau::classify::{CurveClass, NodeType, Parameter, SegmentCategory, classify};
use casteljau::internal::loop_blinn;
use casteljau::num::parse_points;
use casteljau::{BezierCurve, Point, QuadraticExt, Scalar, rat, ratio};
use num_rational::BigRational;
use proptest::prelude::*;

fn curve(s: &str) -> BezierCurve<BigRational> {
    BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap()
}

use casteljau::strategies::cubic_from_power as from_power;

/// `(s², s³)` with `s = t − τ`: a cusp exactly at `t = τ`.
fn cusp_at(tau: BigRational) -> BezierCurve<BigRational> {
    let (a, a2) = (-tau.clone(), tau.clone() * &tau);
    // s² = t² − 2τt + τ², s³ = t³ − 3τt² + 3τ²t − τ³
    from_power(
        [a2.clone(), rat(2) * &a, rat(1), rat(0)],
        [-(a2.clone() * &tau), rat(3) * &a2, rat(3) * &a, rat(1)],
        [2, 1, -1, 3],
        [5, -7],
    )
}

/// `(s² − 1, s³ − s)` with `s = 2t/t1 − 1`: double point at `t = 0` and `t = t1`.
fn loop_between_0_and(t1: BigRational) -> BezierCurve<BigRational> {
    let k = rat(2) / &t1; // s = k t − 1
    let (k2, k3) = (k.clone() * &k, k.clone() * &k * &k);
    // s² − 1 = k²t² − 2kt; s³ − s = k³t³ − 3k²t² + 3kt − 1 − kt + 1 = k³t³ − 3k²t² + 2kt
    from_power(
        [rat(0), rat(-2) * &k, k2.clone(), rat(0)],
        [rat(0), rat(2) * &k, rat(-3) * &k2, k3],
        [1, 0, 0, 1],
        [0, 0],
    )
}

fn class_of(s: &str) -> CurveClass {
    classify(&curve(s)).unwrap().class
}

#[test]
fn classify_all_16_classes() {
    use CurveClass::*;
    for (s, class) in [
        ("1 2", Point),
        ("0 0, 1 1", Line),
        ("1 1, 1 1", LineReallyPoint),
        ("0 0, 1 2, 2 0", Quadratic),
        ("0 0, 2 2, 1 1", CollinearQuadratic),
        ("0 0, 1 1, 2 2", QuadraticReallyLine),
        ("3 3, 3 3, 3 3", QuadraticReallyPoint),
        ("0 0, 2 2, -1 2, 1 0", Cubic(NodeType::Crunode)),
        ("0 0, 1 1, 0 1, 1 0", Cubic(NodeType::Cusp)),
        ("0 0, 1 2, 2 -1, 3 1", Cubic(NodeType::Explicit)),
        ("0 0, 1 1, 2 1, 3 0", CubicReallyQuadratic),
        ("0 0, 3 0, -1 0, 2 0", CollinearCubic),
        ("0 0, 2 2, 3 3, 3 3", CubicReallyCollinearQuadratic),
        ("0 0, 1/3 1/3, 2/3 2/3, 1 1", CubicReallyLine),
        ("1/3 1/3, 1/3 1/3, 1/3 1/3, 1/3 1/3", CubicReallyPoint),
    ] {
        assert_eq!(class_of(s), class, "{s}");
    }
    // acnode: (s² + 1, s³ + 3s) on s ∈ [−1, 1]
    let ac = from_power([rat(2), rat(-4), rat(4), rat(0)], [rat(-4), rat(12), rat(-12), rat(8)], [1, 0, 0, 1], [0, 0]);
    assert_eq!(classify(&ac).unwrap().class, Cubic(NodeType::Acnode));
}

#[test]
fn classify_json_fields_for_seed_kinds_figs_1_to_4() {
    let k = classify(&curve("0 0, 2 2, -1 2, 1 0")).unwrap(); // Fig. 1 kind: crunode with a loop
    assert_eq!((k.real_degree, k.collinear, k.node_type), (3, false, Some(NodeType::Crunode)));
    assert_eq!(k.double_point.unwrap().to_string(), "(1/2, 3/5)");
    assert_eq!(
        k.double_point_parameters.iter().map(|p| p.to_string()).collect::<Vec<_>>(),
        ["1/2 - 1/10*sqrt(15)", "1/2 + 1/10*sqrt(15)"]
    );
    assert!(k.segment.has_loop && !k.segment.has_cusp && k.segment.inflections == 0);
    assert_eq!(k.segment.category, SegmentCategory::Loop);
}

#[test]
fn classify_cusp_at_t0_from_coincident_points() {
    let k = classify(&curve("0 0, 0 0, 1 1, 1 0")).unwrap();
    assert_eq!(k.node_type, Some(NodeType::Cusp));
    assert_eq!(k.cusp_parameters, vec![Parameter::from_i64(0)]);
    assert_eq!(k.double_point.unwrap().to_string(), "(0, 0)");
    assert!(k.segment.has_cusp);
    assert_eq!(k.segment.category, SegmentCategory::Cusp);
}

#[test]
fn classify_cusp_at_chosen_parameters_boundaries_included() {
    for (tau, inside) in
        [(ratio(0, 1), true), (ratio(1, 1), true), (ratio(1, 3), true), (ratio(-1, 7), false), (ratio(8, 7), false)]
    {
        let k = classify(&cusp_at(tau.clone())).unwrap();
        assert_eq!(k.node_type, Some(NodeType::Cusp), "τ = {tau}");
        assert_eq!(k.cusp_parameters, vec![Parameter::from_ratio(&tau)]);
        assert_eq!(k.segment.has_cusp, inside, "τ = {tau}");
    }
}

#[test]
fn classify_loop_with_double_point_exactly_at_endpoints() {
    let k = classify(&loop_between_0_and(rat(1))).unwrap();
    assert_eq!(k.node_type, Some(NodeType::Crunode));
    assert_eq!(k.double_point_parameters, vec![Parameter::from_i64(0), Parameter::from_i64(1)]);
    assert!(k.segment.has_loop, "both double-point parameters on the closed interval");
    let k = classify(&loop_between_0_and(ratio(1, 2))).unwrap();
    assert!(k.segment.has_loop);
    let k = classify(&loop_between_0_and(ratio(3, 2))).unwrap();
    assert!(!k.segment.has_loop, "t = 3/2 is outside [0, 1]");
    let k = classify(&loop_between_0_and(ratio(1000001, 1000000))).unwrap();
    assert!(!k.segment.has_loop, "just outside");
}

#[test]
fn classify_inflections_exactly_at_endpoints() {
    // explicit (s, s³) with s = t and s = t − 1
    let at0 = from_power([rat(0), rat(1), rat(0), rat(0)], [rat(0), rat(0), rat(0), rat(1)], [1, 0, 0, 1], [0, 0]);
    let at1 = from_power([rat(-1), rat(1), rat(0), rat(0)], [rat(-1), rat(3), rat(-3), rat(1)], [1, 0, 0, 1], [0, 0]);
    for c in [at0, at1] {
        let k = classify(&c).unwrap();
        assert_eq!(k.node_type, Some(NodeType::Explicit));
        assert_eq!(k.segment.inflections, 1);
        assert_eq!(k.segment.category, SegmentCategory::SingleInflection);
    }
    // acnode (s², s³ + 3s), s = 2t − 1: inflections at s = ±1, i.e. t = 0 and t = 1
    let ac = from_power([rat(1), rat(-4), rat(4), rat(0)], [rat(-4), rat(12), rat(-12), rat(8)], [1, 0, 0, 1], [0, 0]);
    let k = classify(&ac).unwrap();
    assert_eq!(k.node_type, Some(NodeType::Acnode));
    assert_eq!(k.inflection_parameters, vec![Parameter::from_i64(0), Parameter::from_i64(1)]);
    assert_eq!(k.segment.inflections, 2);
    assert_eq!(k.segment.category, SegmentCategory::DoubleInflection);
}

#[test]
fn classify_degree_elevated_quadratic_with_thirds() {
    let q = curve("1/3 2/3, 5/3 -7/3, 10/3 1/3");
    let c = q.elevate(1).unwrap();
    assert!(c.points().iter().any(|p| !p.coords[0].is_integer()));
    let k = classify(&c).unwrap();
    assert_eq!(k.class, CurveClass::CubicReallyQuadratic);
    assert_eq!(k.real_degree, 2);
    assert_eq!(k.node_type, None);
    assert_eq!(k.segment.category, SegmentCategory::Parabola);
}

#[test]
fn classify_near_cusp_is_not_a_cusp() {
    for e in [10, 30, 100] {
        let eps = BigRational::new(1.into(), num_bigint::BigInt::from(10).pow(e));
        for sign in [1, -1] {
            let c = curve(&format!("0 0, 1 {}, 0 1, 1 0", rat(1) + rat(sign) * &eps));
            let k = classify(&c).unwrap();
            assert_ne!(k.node_type, Some(NodeType::Cusp), "10^-{e}");
            assert!(matches!(k.node_type, Some(NodeType::Crunode | NodeType::Acnode)));
        }
    }
}

#[test]
fn classify_rejects_degree_above_3_and_3d() {
    assert!(classify(&curve("0 0, 1 1, 2 0, 3 1, 4 0")).is_err());
    assert!(classify(&BezierCurve::new(parse_points("0 0 0, 1 1 1", 3, None).unwrap()).unwrap()).is_err());
}

fn small() -> impl Strategy<Value = BigRational> {
    prop_oneof![(-8i64..=8).prop_map(rat), (-40i64..=40, 1i64..=6).prop_map(|(p, q)| ratio(p, q))]
}
fn cubic() -> impl Strategy<Value = BezierCurve<BigRational>> {
    prop::collection::vec((small(), small()), 4)
        .prop_map(|v| BezierCurve::new(v.into_iter().map(|(x, y)| Point::new(vec![x, y])).collect()).unwrap())
}

fn lift(c: &BezierCurve<BigRational>) -> BezierCurve<QuadraticExt<BigRational>> {
    c.map(QuadraticExt::from_ratio)
}
fn cross(u: &Point<QuadraticExt<BigRational>>, v: &Point<QuadraticExt<BigRational>>) -> QuadraticExt<BigRational> {
    u.coords[0].clone() * &v.coords[1] - u.coords[1].clone() * &v.coords[0]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn classify_parameters_are_exact(c in cubic()) {
        let k = classify(&c).unwrap();
        let q = lift(&c);
        let (d1, d2) = (q.derivative(1), q.derivative(2));
        match k.node_type {
            Some(NodeType::Crunode) => {
                let p = &k.double_point_parameters;
                let dp = Point::new(k.double_point.clone().unwrap().coords.iter().map(QuadraticExt::from_ratio).collect());
                prop_assert_eq!(q.eval(&p[0]), dp.clone());
                prop_assert_eq!(q.eval(&p[1]), dp);
                prop_assert!(p[0] != p[1]);
            }
            Some(NodeType::Cusp) => {
                let t = &k.cusp_parameters[0];
                prop_assert!(d1.eval(t).coords.iter().all(|x| x.is_zero()));
            }
            _ => {}
        }
        for t in &k.inflection_parameters {
            prop_assert!(cross(&d1.eval(t), &d2.eval(t)).is_zero());
        }
    }

    #[test]
    fn classify_agrees_with_loop_blinn(c in cubic()) {
        let k = classify(&c).unwrap();
        let (_, lb) = loop_blinn(&c);
        if k.real_degree == 3 && !k.collinear {
            prop_assert_eq!(k.node_type, lb);
        } else {
            prop_assert!(k.node_type.is_none());
        }
    }

    /// Seed 004 (3)–(8) as printed, against the power-form route.
    #[test]
    fn moving_lines_follow_the_curve_and_find_the_double_point(c in cubic()) {
        let ml = MovingLines::new(&c).unwrap();
        prop_assert!(ml.verify().is_ok());
        let k = classify(&c).unwrap();
        if let Some(node) = k.node_type {
            let d = &ml.double_point;
            match node {
                NodeType::Explicit => prop_assert!(d.coords[2].is_zero() && !d.coords[..2].iter().all(|x| x.is_zero())),
                _ => {
                    prop_assert_eq!(d.from_homogeneous(), k.double_point.clone());
                    let (te, _) = k.t_e_and_d.clone().unwrap();
                    prop_assert_eq!(ml.t_e(), Some(te.clone()));
                    let e = ml.e_point().unwrap().from_homogeneous().unwrap();
                    prop_assert_eq!(e, c.eval(&te));
                    let (_, disc) = ml.f_and_discriminant();
                    let expected = match node { NodeType::Crunode => std::cmp::Ordering::Greater, NodeType::Cusp => std::cmp::Ordering::Equal, _ => std::cmp::Ordering::Less };
                    prop_assert_eq!(casteljau::Exact::sign(&disc), expected);
                }
            }
        }
    }

    #[test]
    fn classify_is_invariant_under_reversal_and_affine_maps(c in cubic(), m in prop::array::uniform4(-3i64..=3)) {
        prop_assume!(m[0] * m[3] - m[1] * m[2] != 0);
        let k = classify(&c).unwrap();
        let rev = BezierCurve::new(c.points().iter().rev().cloned().collect()).unwrap();
        let kr = classify(&rev).unwrap();
        prop_assert_eq!(kr.class, k.class);
        prop_assert_eq!(&kr.segment, &k.segment);
        let mapped = BezierCurve::new(c.points().iter().map(|p| Point::new(vec![
            rat(m[0]) * &p.coords[0] + rat(m[1]) * &p.coords[1],
            rat(m[2]) * &p.coords[0] + rat(m[3]) * &p.coords[1],
        ])).collect()).unwrap();
        let km = classify(&mapped).unwrap();
        prop_assert_eq!(km.class, k.class);
        prop_assert_eq!(&km.segment, &k.segment);
        prop_assert_eq!(&km.double_point_parameters, &k.double_point_parameters);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(120))]

    /// Seed 004 (9)–(18) and Case 4: the corrected map is proved for every genuine cubic; the
    /// printed (9) and (12) fail on every crunode and cusp (their F, G coincide with D).
    #[test]
    fn canonical_map_corrected_proves_and_printed_9_12_fail(c in cubic()) {
        use casteljau::{classify::canonical_map, proof::Reading};
        let k = classify(&c).unwrap();
        let Some(node) = k.node_type else { return Ok(()) };
        let ml = MovingLines::new(&c).unwrap();
        let fixed = canonical_map(&c, &k, &ml, Reading::Corrected).unwrap();
        prop_assert!(fixed.prove(&c).is_ok(), "{}", c);
        let printed = canonical_map(&c, &k, &ml, Reading::AsPrinted);
        match node {
            NodeType::Crunode | NodeType::Cusp => prop_assert!(printed.map(|m| m.prove(&c).is_err()).unwrap_or(true)),
            _ => prop_assert!(printed.unwrap().prove(&c).is_ok()),
        }
    }
}

#[test]
fn canonical_map_for_constructed_cusps_and_acnodes() {
    use casteljau::{classify::canonical_map, proof::Reading};
    let map = |c: &BezierCurve<BigRational>, reading| {
        canonical_map(c, &classify(c).unwrap(), &MovingLines::new(c).unwrap(), reading).unwrap()
    };
    for tau in [ratio(0, 1), ratio(1, 3), ratio(1, 1)] {
        let c = cusp_at(tau);
        assert!(map(&c, Reading::Corrected).prove(&c).is_ok());
    }
    let ac = from_power([rat(1), rat(-4), rat(4), rat(0)], [rat(-4), rat(12), rat(-12), rat(8)], [1, 0, 0, 1], [0, 0]);
    let m = map(&ac, Reading::AsPrinted);
    assert!(m.prove(&ac).is_ok());
}

fn int_cubic() -> impl Strategy<Value = [[i64; 2]; 4]> {
    prop::array::uniform4(prop::array::uniform2(-(1i64 << 16)..(1i64 << 16)))
}
fn to_curve(p: &[[i64; 2]; 4]) -> BezierCurve<BigRational> {
    BezierCurve::new(p.iter().map(|q| Point::new(vec![rat(q[0]), rat(q[1])])).collect()).unwrap()
}
fn exact_summary(c: &BezierCurve<BigRational>) -> casteljau::internal::Summary {
    let k = classify(c).unwrap();
    (k.class, k.segment)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    #[test]
    fn certified_summary_equals_exact_classification(c in cubic()) {
        prop_assert_eq!(casteljau::internal::summarize(&c), exact_summary(&c));
    }

    #[test]
    fn certified_f64_filter_never_disagrees(p in int_cubic(), small in prop::array::uniform4(prop::array::uniform2(-3i64..=3)), pick in 0u8..3) {
        // mix wide random coordinates with tiny ones (more degenerate cases)
        let p = if pick == 0 { small } else { p };
        let c = to_curve(&p);
        let f = p.map(|q| q.map(|v| v as f64));
        if let Some(s) = casteljau::internal::filter_f64(&f) {
            prop_assert_eq!(s, exact_summary(&c));
        }
        prop_assert_eq!(casteljau::internal::decide(&p.map(|q| q.map(|v| v as i128))).unwrap(), exact_summary(&c));
    }
}

#[test]
fn certified_summary_on_constructed_edge_cases() {
    let mut cases = vec![loop_between_0_and(rat(1)), loop_between_0_and(ratio(3, 2)), curve("0 0, 0 0, 1 1, 1 0")];
    for tau in [ratio(0, 1), ratio(1, 1), ratio(1, 3), ratio(-1, 7)] {
        cases.push(cusp_at(tau));
    }
    cases.push(from_power(
        [rat(1), rat(-4), rat(4), rat(0)],
        [rat(-4), rat(12), rat(-12), rat(8)],
        [1, 0, 0, 1],
        [0, 0],
    ));
    cases.push(curve("0 0, 3 0, -1 0, 2 0"));
    cases.push(curve("0 0, 2 2, 3 3, 3 3"));
    for e in [10u32, 30] {
        let eps = BigRational::new(1.into(), num_bigint::BigInt::from(10).pow(e));
        cases.push(curve(&format!("0 0, 1 {}, 0 1, 1 0", rat(1) + eps)));
    }
    for c in &cases {
        assert_eq!(casteljau::internal::summarize(c), exact_summary(c), "{c}");
    }
    // near a cusp the filter either certifies the true answer for its exact f64 input, or abstains
    let y = 1.0 + 1e-15;
    let near = [[0.0, 0.0], [1.0, y], [0.0, 1.0], [1.0, 0.0]];
    let exact_y = BigRational::from_float(y).unwrap();
    let exact_curve = BezierCurve::new(vec![
        Point::new(vec![rat(0), rat(0)]),
        Point::new(vec![rat(1), exact_y]),
        Point::new(vec![rat(0), rat(1)]),
        Point::new(vec![rat(1), rat(0)]),
    ])
    .unwrap();
    let truth = exact_summary(&exact_curve);
    assert_ne!(truth.0, CurveClass::Cubic(NodeType::Cusp));
    if let Some(s) = casteljau::internal::filter_f64(&near) {
        assert_eq!(s, truth);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// At the edge of the SmallInt bound (|coordinates| just below 2²⁴) nothing overflows.
    #[test]
    fn certified_small_int_limit_is_safe(p in prop::array::uniform4(prop::array::uniform2(prop_oneof![Just((1i64 << 24) - 1), Just(-(1i64 << 24) + 1), -(1i64 << 24) + 1..(1i64 << 24)]))) {
        prop_assert_eq!(casteljau::internal::summarize_integers(&p), exact_summary(&to_curve(&p)));
        prop_assert_eq!(casteljau::internal::decide(&p.map(|q| q.map(num_bigint::BigInt::from))).unwrap(), exact_summary(&to_curve(&p)));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Float inputs (any binary64 values, including near-degenerate ones) are classified exactly.
    #[test]
    fn certified_summarize_f64_equals_exact_on_the_binary_values(p in prop::array::uniform4(prop::array::uniform2(prop_oneof![-1e3f64..1e3, (-4i32..=4).prop_map(|v| v as f64), Just(0.1f64), Just(1.0 + f64::EPSILON)]))) {
        let s = casteljau::internal::summarize_f64(&p).unwrap();
        let c = BezierCurve::new(p.iter().map(|q| Point::new(q.iter().map(|&v| BigRational::from_float(v).unwrap()).collect())).collect()).unwrap();
        prop_assert_eq!(s, exact_summary(&c));
    }
}

/// The fixed-width route (`SmallRational` inside `checked`) and the big-number route give the
/// same classification, spelled alike, whenever the fixed-width route answers.
fn routes_agree(c: &BezierCurve<BigRational>) -> Result<bool, TestCaseError> {
    use casteljau::internal::classify_in;
    use casteljau::internal::{SmallRational, checked};
    let big = classify_in(c).unwrap();
    prop_assert_eq!(&classify(c).unwrap(), &big);
    let Some(small) = checked(|| classify_in(&c.map(SmallRational::from_ratio)).unwrap()) else { return Ok(false) };
    prop_assert_eq!(&small.map(SmallRational::to_big), &big);
    prop_assert_eq!(serde_json::to_string(&small).unwrap(), serde_json::to_string(&big).unwrap());
    Ok(true)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn classify_fixed_width_route_equals_big_route(c in cubic()) {
        routes_agree(&c)?;
    }

    #[test]
    fn classify_fixed_width_route_equals_big_route_on_wide_integers(p in int_cubic(), tiny in prop::array::uniform4(prop::array::uniform2(-3i64..=3)), shift in 0u32..=44, pick in 0u8..3) {
        // font-like, degenerate (tiny) and huge (2^60) coordinates: the last overflow and fall back
        let p = match pick { 0 => tiny, 1 => p, _ => p.map(|q| q.map(|v| v << shift)) };
        routes_agree(&to_curve(&p))?;
    }

    /// The segment features, decided from signs of A, B, C, against the positions of the exact
    /// parameters in [0, 1] (signs in Q(√d)): an independent route.
    #[test]
    fn segment_features_equal_parameter_positions(c in cubic()) {
        let k = classify(&c).unwrap();
        let inside = |t: &Parameter| t.sign() != std::cmp::Ordering::Less && (Parameter::one() - t.clone()).sign() != std::cmp::Ordering::Less;
        use casteljau::Exact;
        prop_assert_eq!(k.segment.has_loop, k.node_type == Some(NodeType::Crunode) && k.double_point_parameters.iter().all(inside));
        prop_assert_eq!(k.segment.has_cusp, k.cusp_parameters.iter().any(inside));
        prop_assert_eq!(k.segment.inflections, k.inflection_parameters.iter().filter(|t| inside(t)).count());
    }
}

#[test]
fn classify_fixed_width_route_on_seed_kinds_and_boundaries() {
    for s in [
        "0 0, 1 1, 0 1, 1 0",
        "0 0, 30 40, -20 40, 10 0",
        "0 0, 1 1, 2 0, 0 1",
        "0 0, 0 0, 1 1, 2 0",
        "0 0, 1 2, 2 2, 3 0",
        "0 0, 1 0, 2 0, 3 0",
        "0 0, 2 0, 1 0, 3 0",
        "1/3 1/7, 2.5 -0.125, 1e3 7, 0 0",
    ] {
        // small inputs: the fixed-width route answers (and agrees)
        assert_eq!(routes_agree(&curve(s)).ok(), Some(true), "{s}");
    }
    // i128::MAX as a coordinate: the fixed-width route reports overflow, the big route answers
    assert_eq!(routes_agree(&curve("170141183460469231731687303715884105727 0, 1 1, 0 1, 1 0")).ok(), Some(false));
}

/// The direct JSON route of integer cubics against serde's JSON of [`classify`]: byte for byte
/// when it answers; `Some(true)` when it did.
fn integer_route_agrees(p: &[[i64; 2]; 4]) -> Result<bool, TestCaseError> {
    let mut out = vec![];
    if !casteljau::internal::classify_json(p, &mut out) {
        prop_assert!(out.is_empty());
        return Ok(false);
    }
    let generic = serde_json::to_string(&classify(&to_curve(p)).unwrap()).unwrap();
    prop_assert_eq!(String::from_utf8(out).unwrap(), generic, "{:?}", p);
    Ok(true)
}

/// A strategy curve with its coordinates scaled to integers (by the lcm of the denominators).
fn scaled_to_integers(c: &BezierCurve<BigRational>) -> Option<[[i64; 2]; 4]> {
    use num_integer::Integer;
    use num_traits::ToPrimitive;
    let l = c.points().iter().flat_map(|q| q.coords.iter()).fold(num_bigint::BigInt::from(1), |l, x| l.lcm(x.denom()));
    let v: Vec<i64> = c
        .points()
        .iter()
        .flat_map(|q| q.coords.iter())
        .map(|x| (x * BigRational::from_integer(l.clone())).to_integer().to_i64())
        .collect::<Option<_>>()?;
    (v.len() == 8).then(|| [[v[0], v[1]], [v[2], v[3]], [v[4], v[5]], [v[6], v[7]]])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn integer_json_route_equals_serde_json_on_random_integers(p in int_cubic(), tiny in prop::array::uniform4(prop::array::uniform2(-3i64..=3)), shift in 0u32..=30, pick in 0u8..3) {
        // font-like (|coordinates| ≤ 2048: no number outgrows 128 bits), tiny (degenerate classes, exact cusps) and wide (up
        // to 2^46: overflow, refusal)
        let p = match pick { 0 => tiny, 1 => p.map(|q| q.map(|v| v >> 5)), _ => p.map(|q| q.map(|v| v << shift)) };
        let taken = integer_route_agrees(&p)?;
        if pick == 1 {
            // a font-like genuine cubic or elevated quadratic is always taken
            let k = classify(&to_curve(&p)).unwrap();
            prop_assert_eq!(taken, k.node_type.is_some() || k.class == CurveClass::CubicReallyQuadratic);
        }
    }

    #[test]
    fn integer_json_route_equals_serde_json_on_edge_case_strategies(
        c in prop_oneof![
            casteljau::strategies::cusp_at(casteljau::strategies::unit_parameter()).prop_map(|(c, _)| c),
            casteljau::strategies::loop_between().prop_map(|(c, _)| c),
            casteljau::strategies::inflection_at_endpoint().prop_map(|(c, _)| c),
            casteljau::strategies::degree_elevated_quadratic(),
            casteljau::strategies::collinear_cubic(),
            casteljau::strategies::coincident_control_points(),
            casteljau::strategies::near_cusp(1..=12).prop_map(|(c, _)| c),
            cubic(),
        ]
    ) {
        if let Some(p) = scaled_to_integers(&c) {
            integer_route_agrees(&p)?;
        }
    }
}

#[test]
fn integer_json_route_on_every_node_type_and_the_refusals() {
    let taken = |s: &str| {
        let c = curve(s);
        let p = scaled_to_integers(&c).unwrap();
        integer_route_agrees(&p).unwrap()
    };
    for s in [
        "0 0, 0 1, 1 1, 1 0",  // crunode, loop outside [0, 1]
        "0 0, 2 2, -1 2, 1 0", // loop
        "0 0, 3 3, 0 3, 3 0",  // cusp at 1/2
        "0 0, 0 0, 1 1, 2 0",  // cusp at 0
        "0 0, 1 1, 2 -1, 3 0", // acnode, one inflection
        "0 0, 1 0, 2 0, 3 3",  // explicit
        "0 0, 1 0, 2 1, 3 3",  // degree-elevated quadratic
        "0 0, 30 40, -20 40, 10 0",
    ] {
        assert!(taken(s), "{s}");
    }
    // collinear, lower degree: the generic route answers
    for s in ["0 0, 1 1, 2 2, 3 3", "0 0, 2 2, 1 1, 3 3", "1 1, 1 1, 1 1, 1 1", "0 0, 1 1, 2 2, 3 3"] {
        assert!(!taken(s), "{s}");
    }
    // beyond 2^40: refused, the generic route answers
    assert!(!casteljau::internal::classify_json(&[[1 << 41, 0], [0, 1], [1, 1], [1, 0]], &mut vec![]));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// The integer line reader reads what the general parser reads, or leaves the line to it.
    #[test]
    fn integer_cubic_reader_agrees_with_parse_points(
        v in prop::array::uniform8(-100_000i64..100_000),
        seps in prop::array::uniform8(prop::sample::select(vec![" ", ", ", ",", "  ", "\t", " ,", ",,", "", " x", "/2 "])),
        trailing in prop::sample::select(vec!["", ",", " ", " , ", ",,"]),
    ) {
        let mut text = String::new();
        for (k, x) in v.iter().enumerate() {
            text += &x.to_string();
            if k < 7 { text += seps[k]; }
        }
        text += trailing;
        if let Some(p) = casteljau::internal::integer_cubic(&text) {
            let parsed = parse_points(&text, 2, None);
            prop_assert!(parsed.is_ok(), "{}", text);
            let (ours, theirs) = (to_curve(&p), parsed.unwrap());
            prop_assert_eq!(ours.points(), theirs.as_slice(), "{}", text);
        }
    }
}

/// `classify_json_scaled` on the curve's integer numerators over their common denominator,
/// against serde's JSON of [`classify`] on the rational curve: byte for byte when it answers.
fn scaled_route_agrees(c: &BezierCurve<BigRational>) -> Result<bool, TestCaseError> {
    use num_integer::Integer;
    let l = c.points().iter().flat_map(|q| q.coords.iter()).fold(num_bigint::BigInt::from(1), |l, x| l.lcm(x.denom()));
    let int = |x: &BigRational| (x * BigRational::from_integer(l.clone())).to_integer();
    let p: [[num_bigint::BigInt; 2]; 4] =
        std::array::from_fn(|i| [int(&c.points()[i].coords[0]), int(&c.points()[i].coords[1])]);
    let mut out = vec![];
    if !casteljau::internal::classify_json_scaled(&p, &l, &mut out) {
        prop_assert!(out.is_empty());
        return Ok(false);
    }
    let generic = serde_json::to_string(&classify(c).unwrap()).unwrap();
    prop_assert_eq!(String::from_utf8(out).unwrap(), generic);
    Ok(true)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn scaled_json_route_equals_serde_json_on_rational_curves(
        c in prop_oneof![
            cubic(),
            casteljau::strategies::cubic(),
            casteljau::strategies::cusp_at(casteljau::strategies::unit_parameter()).prop_map(|(c, _)| c),
            casteljau::strategies::loop_between().prop_map(|(c, _)| c),
            casteljau::strategies::inflection_at_endpoint().prop_map(|(c, _)| c),
            casteljau::strategies::degree_elevated_quadratic(),
            casteljau::strategies::near_cusp(1..=12).prop_map(|(c, _)| c),
        ]
    ) {
        scaled_route_agrees(&c)?;
    }

    /// The fixed-width line reader reads what the general parser reads, or leaves the line to it.
    #[test]
    fn small_cubic_reader_agrees_with_parse_points(
        v in prop::array::uniform8((-100_000i64..100_000, 1i64..60, 0u8..4)),
        seps in prop::array::uniform8(prop::sample::select(vec![" ", ", ", ",", "\t", " ,", ",,", "", " x"])),
    ) {
        let mut text = String::new();
        for (k, &(n, d, form)) in v.iter().enumerate() {
            text += &match form {
                0 => n.to_string(),
                1 => format!("{n}/{d}"),
                2 => format!("{}.{:03}", n / 1000, (n % 1000).abs()),
                _ => format!("{n}/0"),
            };
            if k < 7 { text += seps[k]; }
        }
        if let Some(p) = casteljau::internal::small_cubic(&text, casteljau::num::NumberMode::Exact) {
            let parsed = parse_points(&text, 2, None);
            prop_assert!(parsed.is_ok(), "{}", text);
            let theirs = parsed.unwrap();
            for (i, q) in p.iter().enumerate() {
                prop_assert_eq!(&q.map(|x| x.to_big()).to_vec(), &theirs[i].coords, "{}", text);
            }
        }
    }
}

#[test]
fn scaled_json_route_on_constructed_rational_cubics() {
    let mut taken = 0;
    for s in [
        "0 0, 1/2 1/2, 0 1/2, 1/2 0",
        "1/3 1/7, 5/2 -1/8, 1000 7, 0 0",
        "0 0, 0 1/3, 1/3 1/3, 1/3 0",
        "-1 -1, -1/3 1, 1/3 -1, 1 1",
        "0 0, 1/5 0, 2/5 0, 3/5 1/7",
        "0 0, 1/2 0, 1 1/2, 3/2 3/2",
    ] {
        taken += usize::from(scaled_route_agrees(&curve(s)).unwrap());
    }
    assert_eq!(taken, 6);
}
