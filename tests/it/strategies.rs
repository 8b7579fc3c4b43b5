//! The exported edge-case strategies deliver what they promise, checked by the exact classifier
//! and the certified fast path.

use casteljau::classify::{CurveClass, NodeType, classify};
use casteljau::internal::summarize;
use casteljau::strategies::*;
use casteljau::{Scalar, rat};
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn strategies_cusp_at_chosen_parameter(c in cusp_at(prop_oneof![unit_parameter(), small_rational()])) {
        let (curve, tau) = c;
        let k = classify(&curve).unwrap();
        prop_assert_eq!(k.node_type, Some(NodeType::Cusp));
        prop_assert_eq!(k.cusp_parameters[0].to_base(), Some(tau.clone()));
        prop_assert_eq!(k.segment.has_cusp, tau >= rat(0) && tau <= rat(1));
        prop_assert_eq!(summarize(&curve), (k.class, k.segment));
    }

    #[test]
    fn strategies_loop_between_parameters(c in loop_between()) {
        let (curve, (t0, t1)) = c;
        let k = classify(&curve).unwrap();
        prop_assert_eq!(k.node_type, Some(NodeType::Crunode));
        let params: Vec<_> = k.double_point_parameters.iter().map(|p| p.to_base()).collect();
        prop_assert_eq!(params, vec![Some(t0.clone()), Some(t1.clone())]);
        prop_assert_eq!(k.segment.has_loop, t0 >= rat(0) && t1 <= rat(1));
        prop_assert_eq!(summarize(&curve), (k.class, k.segment));
    }

    #[test]
    fn strategies_inflection_at_endpoint(c in inflection_at_endpoint()) {
        let (curve, at) = c;
        let k = classify(&curve).unwrap();
        prop_assert_eq!(k.node_type, Some(NodeType::Explicit));
        prop_assert_eq!(k.inflection_parameters[0].to_base(), Some(at));
        prop_assert_eq!(k.segment.inflections, 1);
        prop_assert_eq!(summarize(&curve), (k.class, k.segment));
    }

    #[test]
    fn strategies_degree_elevated_quadratic(c in degree_elevated_quadratic()) {
        let k = classify(&c).unwrap();
        prop_assert!(k.real_degree <= 2);
        prop_assert!(k.node_type.is_none());
        if !k.collinear && k.real_degree == 2 { prop_assert_eq!(k.class, CurveClass::CubicReallyQuadratic); }
        prop_assert_eq!(summarize(&c), (k.class, k.segment));
    }

    #[test]
    fn strategies_collinear_and_coincident(c in collinear_cubic(), d in coincident_control_points()) {
        let k = classify(&c).unwrap();
        prop_assert!(k.collinear && k.node_type.is_none());
        prop_assert_eq!(summarize(&c), (k.class, k.segment));
        let kd = classify(&d).unwrap();
        prop_assert_eq!(summarize(&d), (kd.class, kd.segment.clone()));
        // a genuine cubic with P0 = P1 (or P2 = P3) has its cusp exactly at the endpoint
        if kd.node_type == Some(NodeType::Cusp) {
            prop_assert!(kd.segment.has_cusp);
        }
    }

    #[test]
    fn strategies_near_cusp_is_never_a_cusp(c in near_cusp(1..=60)) {
        let (curve, k) = c;
        let cls = classify(&curve).unwrap();
        prop_assert!(matches!(cls.node_type, Some(NodeType::Crunode | NodeType::Acnode)), "10^-{}", k);
        let d = cls.t_e_and_d.unwrap().1;
        prop_assert!(!d.is_zero());
    }
}
