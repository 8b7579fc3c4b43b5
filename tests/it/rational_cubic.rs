//! Rational cubics, projectively: unit weights reproduce the polynomial classification, and
//! projective maps (which can send the double point to infinity) preserve node type and
//! parameters.

use casteljau::classify::RationalClassification;

/// The rational classification of four homogeneous control points.
fn classify_rational(h: &[casteljau::Point<num_rational::BigRational>]) -> casteljau::Result<RationalClassification> {
    casteljau::classify::classify_rational(&casteljau::RationalBezier::from_homogeneous(h.to_vec())?)
}
use casteljau::classify::{NodeType, classify};
use casteljau::strategies::{cubic, loop_between};
use casteljau::{BezierCurve, Point, Scalar, rat};
use num_rational::BigRational;
use proptest::prelude::*;

fn homogeneous(c: &BezierCurve<BigRational>) -> Vec<Point<BigRational>> {
    c.points().iter().map(|p| p.to_homogeneous(&rat(1))).collect()
}

fn apply(m: &[i64; 9], p: &Point<BigRational>) -> Point<BigRational> {
    Point::new((0..3).map(|r| (0..3).fold(rat(0), |acc, c| acc + rat(m[3 * r + c]) * &p.coords[c])).collect())
}

fn det3(m: &[i64; 9]) -> i64 {
    m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6])
}

#[test]
fn rational_cubic_folium_seed_000_example_2() {
    let h: Vec<Point<BigRational>> = [(0, 0, 1), (1, 0, 1), (2, 1, 1), (3, 3, 2)]
        .iter()
        .map(|&(x, y, w)| Point::new(vec![rat(x), rat(y), rat(w)]))
        .collect();
    let k = classify_rational(&h).unwrap();
    assert_eq!(k.node_type, Some(NodeType::Crunode));
    assert_eq!(k.double_point.unwrap().to_string(), "(0, 0)");
    assert!(k.parameter_at_infinity);
    assert_eq!(k.double_point_parameters.iter().map(|p| p.to_string()).collect::<Vec<_>>(), ["0"]);
    assert!(!k.has_loop);
}

#[test]
fn rational_cubic_degenerate_inputs_are_named() {
    let pts =
        |v: &[(i64, i64, i64)]| v.iter().map(|&(x, y, w)| Point::new(vec![rat(x), rat(y), rat(w)])).collect::<Vec<_>>();
    assert_eq!(classify_rational(&pts(&[(0, 0, 1), (1, 1, 1), (2, 2, 1), (5, 5, 1)])).unwrap().class, "line");
    // a conic written as a cubic: the rational quadratic H = (1,0,1), (1,1,1), (0,2,2), elevated
    let conic = [
        Point::new(vec![rat(1), rat(0), rat(1)]),
        Point::new(vec![rat(1), rat(1), rat(1)]),
        Point::new(vec![rat(0), rat(2), rat(2)]),
    ];
    let elevated = BezierCurve::new(conic.to_vec()).unwrap().elevate(1).unwrap();
    assert_eq!(classify_rational(elevated.points()).unwrap().class, "reduces_to_conic");
    assert!(classify_rational(&pts(&[(0, 0, 0), (1, 1, 1), (2, 0, 1), (3, 1, 1)])).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn rational_cubic_unit_weights_match_polynomial_classification(c in cubic()) {
        let k = classify(&c).unwrap();
        let r = classify_rational(&homogeneous(&c)).unwrap();
        match k.node_type {
            None => prop_assert!(r.node_type.is_none()),
            Some(NodeType::Explicit) => {
                prop_assert_eq!(r.node_type, Some(NodeType::Cusp));
                prop_assert!(r.at_infinity && r.parameter_at_infinity);
            }
            Some(node) => {
                prop_assert_eq!(r.node_type, Some(node));
                prop_assert_eq!(&r.double_point, &k.double_point);
                let finite: Vec<_> = if node == NodeType::Cusp { k.cusp_parameters.clone() } else { k.double_point_parameters.clone() };
                prop_assert_eq!(&r.double_point_parameters, &finite);
                prop_assert_eq!(r.has_loop, k.segment.has_loop);
                if node == NodeType::Cusp { prop_assert_eq!(r.has_cusp, k.segment.has_cusp); }
            }
        }
    }

    #[test]
    fn rational_cubic_projective_maps_preserve_node_and_parameters(c in loop_between(), m in prop::array::uniform9(-3i64..=3), scale in prop::array::uniform4(1i64..=5)) {
        prop_assume!(det3(&m) != 0);
        let (curve, _) = c;
        let base = classify_rational(&homogeneous(&curve)).unwrap();
        // projective image, with each control point's weight scaled differently is NOT the same
        // curve; scaling all by one constant is.
        let mapped: Vec<Point<BigRational>> = homogeneous(&curve).iter().map(|p| apply(&m, p).scale(&rat(scale[0]))).collect();
        let r = classify_rational(&mapped).unwrap();
        prop_assert_eq!(r.node_type, base.node_type);
        prop_assert_eq!(&r.double_point_parameters, &base.double_point_parameters);
        let d = apply(&m, base.double_point_homogeneous.as_ref().unwrap());
        let rd = r.double_point_homogeneous.unwrap();
        // proportional homogeneous vectors
        let cross = d.cross(&rd).unwrap();
        prop_assert!(cross.coords.iter().all(|x| x.is_zero()));
        prop_assert_eq!(r.at_infinity, d.coords[2].is_zero());
    }
}

#[test]
fn rational_cubic_double_point_sent_to_infinity() {
    // the crunode (s² − 1, s³ − s) has its node at the origin; the projective map
    // (X, Y, W) ↦ (X, Y, X + W) … sends points with X = −W to infinity: move the node first.
    let c = BezierCurve::new(casteljau::num::parse_points("0 0, 2 2, -1 2, 1 0", 2, None).unwrap()).unwrap();
    let k = classify(&c).unwrap();
    let d = k.double_point.unwrap(); // (1/2, 3/5)
    // W' = W − 2X: vanishes at x = 1/2
    let m = [1, 0, 0, 0, 1, 0, -2, 0, 1];
    let mapped: Vec<Point<BigRational>> = homogeneous(&c).iter().map(|p| apply(&m, p)).collect();
    let r = classify_rational(&mapped).unwrap();
    assert_eq!(r.node_type, Some(NodeType::Crunode));
    assert!(r.at_infinity);
    assert_eq!(r.double_point, None);
    assert_eq!(r.double_point_parameters, k.double_point_parameters);
    assert_eq!(d.coords[0], BigRational::new(1.into(), 2.into()));
}
