//! The float-code oracle: the binary64 strategies deliver exact `f64` control points with the
//! promised features, the oracle passes the right answers (rounded to `f64`) and catches every
//! injected wrong one, and `casteljau check` reports them with exit 1.

use crate::common::{TempDir, run, stderr, stdout};
use casteljau::classify::{Classification, NodeType, classify};
use casteljau::oracle::{
    DisagreementKind, FloatClassification, Tolerances, check_classification, compare_classification,
};
use casteljau::strategies::binary64;
use casteljau::{Scalar, rat};
use proptest::prelude::*;

/// What a perfect float library would answer: the exact answers rounded to `f64`, parameters
/// on `[0, 1]` only.
fn perfect(k: &Classification) -> FloatClassification {
    let unit = |ps: &[casteljau::classify::Parameter]| -> Vec<f64> {
        ps.iter().map(|p| p.to_f64()).filter(|t| (0.0..=1.0).contains(t)).collect()
    };
    FloatClassification {
        node_type: Some(k.node_type.map(|n| n.as_str().to_string())),
        category: Some(k.segment.category.as_str().into()),
        has_loop: Some(k.segment.has_loop),
        has_cusp: Some(k.segment.has_cusp),
        inflections: Some(k.segment.inflections),
        inflection_parameters: Some(unit(&k.inflection_parameters)),
        cusp_parameters: Some(unit(&k.cusp_parameters)),
        self_intersection_parameters: Some(if k.segment.has_loop { unit(&k.double_point_parameters) } else { vec![] }),
        double_point: k.double_point.as_ref().map(|p| [p.coords[0].to_f64(), p.coords[1].to_f64()]),
    }
}

fn hard_cases() -> impl Strategy<Value = casteljau::BezierCurve<num_rational::BigRational>> {
    prop_oneof![
        binary64::cusp_at(prop_oneof![binary64::unit_parameter(), binary64::outside_parameter()]).prop_map(|c| c.0),
        binary64::loop_between().prop_map(|c| c.0),
        binary64::inflection_at_endpoint().prop_map(|c| c.0),
        binary64::degree_elevated_quadratic(),
        binary64::collinear_cubic(),
        binary64::coincident_control_points(),
        binary64::near_cusp(1..=60).prop_map(|c| c.0),
        binary64::cubic(),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn binary64_cusp_at_dyadic_parameter(c in binary64::cusp_at(prop_oneof![binary64::unit_parameter(), binary64::outside_parameter()])) {
        let (curve, tau) = c;
        let _ = binary64::points(&curve); // panics unless every coordinate is an f64
        let k = classify(&curve).unwrap();
        prop_assert_eq!(k.node_type, Some(NodeType::Cusp));
        prop_assert_eq!(k.cusp_parameters[0].to_base(), Some(tau.clone()));
        prop_assert_eq!(k.segment.has_cusp, tau >= rat(0) && tau <= rat(1));
    }

    #[test]
    fn binary64_loop_between_dyadic_parameters(c in binary64::loop_between()) {
        let (curve, (t0, t1)) = c;
        let _ = binary64::points(&curve);
        let k = classify(&curve).unwrap();
        prop_assert_eq!(k.node_type, Some(NodeType::Crunode));
        let params: Vec<_> = k.double_point_parameters.iter().map(|p| p.to_base()).collect();
        prop_assert_eq!(params, vec![Some(t0.clone()), Some(t1.clone())]);
        prop_assert_eq!(k.segment.has_loop, t0 >= rat(0) && t1 <= rat(1));
    }

    #[test]
    fn binary64_inflection_at_endpoint(c in binary64::inflection_at_endpoint()) {
        let (curve, at) = c;
        let _ = binary64::points(&curve);
        let k = classify(&curve).unwrap();
        prop_assert_eq!(k.inflection_parameters[0].to_base(), Some(at));
        prop_assert!(k.segment_flags(curve.points()).contains(&casteljau::classify::SegmentFlag::InflectionAtEndpoint));
    }

    #[test]
    fn binary64_near_cusp_is_never_a_cusp(c in binary64::near_cusp(1..=60)) {
        let (curve, _) = c;
        let _ = binary64::points(&curve);
        let k = classify(&curve).unwrap();
        prop_assert!(matches!(k.node_type, Some(NodeType::Crunode | NodeType::Acnode)));
    }

    #[test]
    fn binary64_degenerate_families_are_classified_as_such(
        e in binary64::degree_elevated_quadratic(),
        l in binary64::collinear_cubic(),
        c in binary64::coincident_control_points(),
    ) {
        for curve in [&e, &l, &c] {
            let _ = binary64::points(curve);
        }
        prop_assert!(classify(&e).unwrap().real_degree <= 2);
        prop_assert!(classify(&l).unwrap().collinear);
        let pts = c.points();
        prop_assert!((0..3).any(|i| pts[i] == pts[i + 1]));
    }

    /// The right answers, rounded to f64, pass; each injected wrong answer is caught with the
    /// field it is about.
    #[test]
    fn oracle_passes_right_answers_and_catches_injected_wrong_ones(curve in hard_cases()) {
        let pts = binary64::points(&curve);
        let k = classify(&curve).unwrap();
        let right = perfect(&k);
        let tol = Tolerances::default();
        prop_assert_eq!(check_classification(&pts, &right, &tol).unwrap(), vec![]);
        let caught = |wrong: FloatClassification, field: &str| {
            let d = compare_classification(&k, &wrong, &tol).unwrap();
            d.iter().any(|d| d.field == field)
        };
        let mut w = right.clone();
        w.has_loop = Some(!k.segment.has_loop);
        prop_assert!(caught(w, "loop"));
        let mut w = right.clone();
        w.inflections = Some(k.segment.inflections + 1);
        prop_assert!(caught(w, "inflections"));
        let mut w = right.clone();
        w.category = Some(if k.segment.category.as_str() == "arch" { "loop" } else { "arch" }.into());
        prop_assert!(caught(w, "category"));
        let mut w = right.clone();
        w.node_type = Some(Some("acnode".into()).filter(|_| k.node_type != Some(NodeType::Acnode)));
        prop_assert!(caught(w, "node_type"));
        // a missed parameter, a shifted one, a duplicated one
        let ips = right.inflection_parameters.clone().unwrap();
        if let Some(&first) = ips.first() {
            let mut w = right.clone();
            w.inflection_parameters = Some(ips[1..].to_vec());
            prop_assert!(compare_classification(&k, &w, &tol).unwrap().iter().any(|d| d.kind == DisagreementKind::Missed));
            let mut w = right.clone();
            // one more copy than there are exact parameters: at least one is a duplicate
            w.inflection_parameters = Some(vec![first; ips.len() + 1]);
            prop_assert!(compare_classification(&k, &w, &tol).unwrap().iter().any(|d| d.kind == DisagreementKind::Duplicate));
        }
        let mut w = right.clone();
        w.cusp_parameters = Some(vec![7.5]);
        prop_assert!(compare_classification(&k, &w, &tol).unwrap().iter().any(|d| d.kind == DisagreementKind::Spurious && d.field == "cusp_parameters"));
        if let Some([x, y]) = right.double_point {
            let mut w = right.clone();
            w.double_point = Some([x + 1.0, y]);
            prop_assert!(caught(w, "double_point"));
        }
    }
}

#[test]
fn oracle_decides_the_tolerance_exactly() {
    // loop at t = 1/2 ± √15/10 (irrational). The correctly rounded f64s agree even with tolerance
    // 0 (a tolerance is never tighter than one ulp); the f64 four steps below the nearest one of
    // the first parameter is more than an ulp away: it needs tolerance 1e-16
    let pts = [[0.0, 0.0], [2.0, 2.0], [-1.0, 2.0], [1.0, 0.0]];
    let answers = |s0: f64| FloatClassification {
        self_intersection_parameters: Some(vec![s0, 0.8872983346207417]),
        ..Default::default()
    };
    let tol = |t: f64| Tolerances { parameter: t, point: 0.0 };
    assert!(check_classification(&pts, &answers(0.11270166537925831), &tol(0.0)).unwrap().is_empty());
    let a = answers(f64::from_bits(0.11270166537925831f64.to_bits() - 4));
    assert!(check_classification(&pts, &a, &tol(1e-16)).unwrap().is_empty());
    assert_eq!(check_classification(&pts, &a, &tol(0.0)).unwrap().len(), 2); // one spurious, one missed
    assert!(check_classification(&pts, &a, &tol(-1.0)).is_err());
    assert!(check_classification(&[[f64::NAN, 0.0], [1.0, 1.0]], &a, &tol(0.0)).is_err());
}

/// A file in `dir`, removed with it when the test ends (also when it fails).
fn write(dir: &TempDir, name: &str, text: &str) -> std::path::PathBuf {
    dir.write(name, text)
}

#[test]
fn cli_check_reports_each_disagreement_and_exits_1() {
    let tmp = TempDir::new("oracle");
    let answers = write(
        &tmp,
        "answers.jsonl",
        r#"{"points": [[0,0],[1,1],[0,1],[1,0]], "category": "arch", "cusp_parameters": []}
{"points": [["0","0"],["2","2"],["-1","2"],["1","0"]], "category": "loop", "self_intersection_parameters": [0.1127016653792583, 0.8872983346207417], "double_point": [0.5, 0.6]}
"#,
    );
    let o = run(&["check", "--json", "--against", answers.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let lines: Vec<serde_json::Value> = stdout(&o).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines.len(), 2);
    assert_eq!(lines[0]["field"], "category");
    assert_eq!(lines[0]["kind"], "mismatch");
    assert_eq!(lines[0]["exact"], "cusp");
    assert_eq!(lines[0]["float"], "arch");
    assert_eq!(lines[1]["field"], "cusp_parameters");
    assert_eq!(lines[1]["exact"], "1/2");
    assert_eq!(lines[1]["points"][1], serde_json::json!(["1", "1"]));
    assert!(stderr(&o).contains("checked 2 curves: 2 disagreements"), "{}", stderr(&o));
}

#[test]
fn cli_check_pairs_answers_with_a_curves_file_and_passes_right_answers() {
    let tmp = TempDir::new("oracle");
    let curves = write(&tmp, "curves.txt", "# font cubics\n0 0, 1 1, 0 1, 1 0\n\n0 0, 2 2, -1 2, 1 0\n");
    let answers = write(
        &tmp,
        "right.jsonl",
        r#"{"category": "cusp", "cusp_parameters": [0.5], "node_type": "cusp"}
{"line": 4, "category": "loop", "loop": true, "inflections": 0}
"#,
    );
    let o = run(&["check", "--against", answers.to_str().unwrap(), curves.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    assert!(stdout(&o).is_empty());
    // the same answers against the wrong lines disagree
    let swapped = write(&tmp, "swapped.jsonl", r#"{"line": 2, "category": "loop"}"#);
    let o = run(&["check", "--against", swapped.to_str().unwrap(), curves.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).contains("category mismatch: exact cusp"), "{}", stdout(&o));
}

#[test]
fn cli_check_bad_answers_exit_2_naming_the_line() {
    let tmp = TempDir::new("oracle");
    let answers = write(&tmp, "bad.jsonl", "{\"points\": [[0,0],[1]]}\nnot json\n{\"category\": \"arch\"}\n");
    let o = run(&["check", "--against", answers.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(e.contains("line 1") && e.contains("line 2") && e.contains("line 3"), "{e}");
    assert_eq!(run(&["check", "--against", "/nonexistent.jsonl"], None).status.code(), Some(2));
}
