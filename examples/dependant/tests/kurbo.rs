//! kurbo's answers about cubics, checked by casteljau's exact oracle: inflection parameters through
//! `oracle::check_classification` (the engine of `casteljau check`), bounding boxes through the exact extrema.
//! Control points are small dyadic numbers, so kurbo's `f64` inputs are exactly the curves
//! casteljau decides.

use casteljau::oracle::{FloatClassification, Tolerances, check_classification};
use casteljau::rational::{BoundingBox, bounding_box};

/// The exact box of a polynomial curve (as a rational one of unit weights), no work limit.
fn bounding_box_polynomial(c: &casteljau::BezierCurve<num_rational::BigRational>) -> casteljau::Result<BoundingBox> {
    bounding_box(&c.clone().into(), &casteljau::work::Budget::unlimited())
}
use casteljau::{BezierCurve, Point};
use casteljau_dependant::within;
use kurbo::{CubicBez, ParamCurveExtrema};
use num_rational::BigRational;

/// Font-like cubics: S-curves, arches, a loop, a curve with an inflection at an end point.
const CUBICS: [[[f64; 2]; 4]; 6] = [
    [[0.0, 0.0], [1.0, 2.0], [2.0, -2.0], [3.0, 0.0]],
    [[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]],
    [[10.0, 0.0], [40.0, 90.0], [70.0, -30.0], [100.0, 45.5]],
    [[0.0, 0.0], [2.0, 2.0], [-1.0, 2.0], [1.0, 0.0]],
    [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 1.0]],
    [[0.5, 0.25], [3.75, 8.0], [-2.5, 6.125], [4.0, -1.0]],
];

fn kurbo_cubic(c: &[[f64; 2]; 4]) -> CubicBez {
    let p = |q: [f64; 2]| (q[0], q[1]);
    CubicBez::new(p(c[0]), p(c[1]), p(c[2]), p(c[3]))
}

fn exact_cubic(c: &[[f64; 2]; 4]) -> BezierCurve<BigRational> {
    let q = |x: f64| BigRational::from_float(x).unwrap();
    BezierCurve::new(c.iter().map(|p| Point::new(vec![q(p[0]), q(p[1])])).collect()).unwrap()
}

#[test]
fn kurbo_inflections_agree_with_the_exact_ones_within_1e_9() {
    for c in &CUBICS {
        let inflections: Vec<f64> = kurbo_cubic(c).inflections().into_iter().filter(|t| (0.0..=1.0).contains(t)).collect();
        let answers = FloatClassification { inflection_parameters: Some(inflections), ..Default::default() };
        let d = check_classification(c, &answers, &Tolerances::default()).unwrap();
        assert!(d.is_empty(), "{c:?}: {d:?}");
    }
}

#[test]
fn oracle_reports_a_wrong_inflection_list() {
    // an S-curve's inflection at t = 1/2, reported 1e-6 off: spurious, and the exact one missed
    let c = &CUBICS[0];
    let mut t = kurbo_cubic(c).inflections().to_vec();
    assert_eq!(t, [0.5]);
    t[0] += 1e-6;
    let answers = FloatClassification { inflection_parameters: Some(t), ..Default::default() };
    let d = check_classification(c, &answers, &Tolerances::default()).unwrap();
    let kinds: Vec<&str> = d.iter().map(|x| x.kind.as_str()).collect();
    assert_eq!(kinds, ["spurious", "missed"], "{d:?}");
}

#[test]
fn kurbo_bounding_boxes_contain_the_exact_ones_within_1e_12() {
    for c in &CUBICS {
        let r = kurbo_cubic(c).bounding_box();
        let exact = bounding_box_polynomial(&exact_cubic(c)).unwrap();
        let scale = r.width().max(r.height()).max(1.0);
        let tol = 1e-12 * scale;
        assert!(within(&exact.min[0], r.x0, tol) && within(&exact.max[0], r.x1, tol), "{c:?}: x {r:?}");
        assert!(within(&exact.min[1], r.y0, tol) && within(&exact.max[1], r.y1, tol), "{c:?}: y {r:?}");
    }
}
