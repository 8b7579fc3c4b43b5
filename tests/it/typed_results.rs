//! The library's budgeted operations and their typed results (`curve::exact`, `rational::exact`,
//! `surface::exact`, `classify::report`): each agrees with an independent route, serializes to
//! the JSON the command line prints, and refuses over budget before any work.

use casteljau::classify::{Classified, ClassifyOptions};
use casteljau::curve::{
    DegreeReduction, Derivative, Elevation, Evaluation, PowerForm, RepeatedSubdivision, Scheme, Subdivision,
};
use casteljau::num::parse_points;
use casteljau::rational::{Definedness, ParameterInterval, RationalElevation, RationalEvaluation, RationalSubdivision};
use casteljau::surface::ParameterAxis;
use casteljau::surface::RationalPatch;
use casteljau::work::Budget;
use casteljau::{BezierCurve, Error, RationalBezier, rat, ratio};

fn curve(text: &str) -> BezierCurve<num_rational::BigRational> {
    BezierCurve::new(parse_points(text, 2, None).unwrap()).unwrap()
}

#[test]
fn typed_results_eval_agrees_with_de_casteljau_and_bernstein() {
    let c = curve("-1 -1, -1/3 1, 1/3 -1, 1 1");
    let ts = [rat(0), ratio(1, 3), ratio(-2, 7), ratio(5, 4), rat(1)];
    let e = Evaluation::new(&c, &ts, &Budget::unlimited()).unwrap();
    for (v, t) in e.values.iter().zip(&ts) {
        assert_eq!(v.t, *t);
        assert_eq!(v.point, c.eval(t));
        assert_eq!(v.point, c.eval_bernstein(t));
    }
}

#[test]
fn typed_results_subdivision_agrees_with_generic_de_casteljau() {
    let c = curve("0 1, 1 3, 2 4, 4 2");
    let s = Subdivision::new(&c, &ratio(2, 5), &Budget::unlimited()).unwrap();
    assert_eq!((s.left, s.right), c.subdivide(&ratio(2, 5)));
}

#[test]
fn typed_results_serialize_as_the_command_line_prints() {
    let c = curve("0 0, 2/3 2/3, 4/3 2/3, 2 0");
    let b = Budget::unlimited();
    let json = |v: serde_json::Value| v.to_string();
    assert_eq!(
        json(serde_json::to_value(Evaluation::new(&c, &[ratio(1, 2)], &b).unwrap()).unwrap()),
        r#"{"degree":3,"values":[{"point":["1","1/2"],"t":"1/2"}]}"#
    );
    assert_eq!(
        json(serde_json::to_value(DegreeReduction::new(&c, &b).unwrap()).unwrap()),
        r#"{"degree":3,"points":[["0","0"],["1","1"],["2","0"]],"real_degree":2}"#
    );
    assert_eq!(
        json(serde_json::to_value(Derivative::new(&c, 3, &b).unwrap()).unwrap()),
        r#"{"degree":0,"order":3,"points":[["0","0"]]}"#
    );
    let p = PowerForm::new(&curve("0 0, 1 1"), &b).unwrap();
    assert_eq!(
        serde_json::to_string(&p).unwrap(),
        r#"{"degree":1,"coefficients":[["0","0"],["1","1"]],"matrix":[["1","0"],["-1","1"]]}"#
    );
    let w =
        RationalBezier::new(parse_points("0 0, 1 1, 2 0", 2, None).unwrap(), vec![rat(1), rat(-1), rat(1)]).unwrap();
    let d = Definedness::new(&w, &ParameterInterval::unit(), &b).unwrap();
    assert_eq!(serde_json::to_string(&d).unwrap(), r#"{"interval":["0","1"],"defined":false,"roots":["t = 1/2"]}"#);
    assert_eq!(serde_json::to_string(&w.conic().unwrap()).unwrap(), r#"{"conic":"parabola","shape_factor":"1"}"#);
}

#[test]
fn typed_results_power_form_omits_the_matrix_above_degree_30() {
    let pts: String = (0..=31).map(|k| format!("{k} {}", k * k)).collect::<Vec<_>>().join(", ");
    let p = PowerForm::new(&curve(&pts), &Budget::unlimited()).unwrap();
    assert!(p.matrix.is_none());
    assert!(!serde_json::to_string(&p).unwrap().contains("matrix"));
}

#[test]
fn typed_results_budget_refuses_before_any_work() {
    let pts: String = (0..=400).map(|k| format!("{k} {}", k % 7)).collect::<Vec<_>>().join(", ");
    let c = curve(&pts);
    let tight = Budget::new(10.0, "--max-work");
    let t = ratio(1, 3);
    let refused = |r: Result<(), Error>| matches!(r, Err(Error::WorkLimit { .. }));
    assert!(refused(Evaluation::new(&c, std::slice::from_ref(&t), &tight).map(drop)));
    assert!(refused(Subdivision::new(&c, &t, &tight).map(drop)));
    assert!(refused(RepeatedSubdivision::new(&c, &t, 3, &tight).map(drop)));
    assert!(refused(Elevation::new(&c, 2, &tight).map(drop)));
    assert!(refused(PowerForm::new(&c, &tight).map(drop)));
    assert!(refused(Scheme::new(&c, &t, &tight).map(drop)));
    assert!(refused(Derivative::new(&c, 2, &tight).map(drop)));
    assert!(refused(DegreeReduction::new(&c, &tight).map(drop)));
    let r = RationalBezier::new(c.points().to_vec(), vec![rat(1); c.points().len()]).unwrap();
    assert!(refused(RationalEvaluation::new(&r, std::slice::from_ref(&t), &tight).map(drop)));
    assert!(refused(RationalSubdivision::new(&r, &t, &tight).map(drop)));
    assert!(refused(RationalElevation::new(&r, 1, &tight).map(drop)));
}

#[test]
fn parameter_interval_needs_0_le_from_lt_to_le_1() {
    assert!(ParameterInterval::new(rat(0), rat(1)).is_ok());
    for (a, b) in [(rat(1), rat(1)), (ratio(1, 2), ratio(1, 3)), (rat(-1), rat(1)), (rat(0), ratio(3, 2))] {
        assert!(matches!(ParameterInterval::new(a, b), Err(Error::ParameterInterval { .. })));
    }
}

#[test]
fn classify_routes_write_the_same_json() {
    // the direct integer route, the fixed-width route and the big-number route agree byte for byte
    let mut took_direct = 0;
    let opts = ClassifyOptions::default();
    for text in
        ["0 0, 1 1, 0 1, 1 0", "0 0, 2 2, -1 2, 1 0", "0 0, 0 0, 1 1, 1 0", "0 0, 1 1, 2 2, 3 3", "0 0, 3 3, 0 3, 3 0"]
    {
        // the direct route declines collinear curves; where it answers it must agree
        let mut direct = vec![];
        let took = opts.write_json_direct(text, &mut direct);
        let routed = match opts.classify_text(text, None).unwrap() {
            Classified::Fixed(r) => serde_json::to_string(&r).unwrap(),
            Classified::Exact(r) => serde_json::to_string(&r).unwrap(),
        };
        let c = curve(text);
        let big = casteljau::classify::ClassifyReport {
            classification: casteljau::internal::classify_in(&c).unwrap(),
            evidence: None,
            float: None,
        };
        if took {
            took_direct += 1;
            assert_eq!(String::from_utf8(direct).unwrap(), routed, "{text}");
        }
        assert_eq!(serde_json::to_string(&big).unwrap(), routed, "{text}");
    }
    assert_eq!(took_direct, 4);
}

#[test]
fn patch_split_in_u_and_in_v_of_the_transpose_agree() {
    let net = parse_points("0 0 0, 1 0 1, 2 0 0, 0 1 1, 1 1 2, 2 1 1", 3, None).unwrap();
    let p = RationalPatch::from_net(&net, (1, 2), Some(&[rat(1), rat(2), rat(1), rat(1), rat(3), rat(1)])).unwrap();
    let x = ratio(1, 3);
    let u = p.split(ParameterAxis::U, &x).unwrap();
    let v = p.transpose().split(ParameterAxis::V, &x).unwrap();
    assert_eq!(u.first, v.first.transpose());
    assert_eq!(u.second, v.second.transpose());
}
