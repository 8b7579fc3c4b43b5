//! Exact intersections: constructed cases with known answers (tangencies of order 2 and 3,
//! endpoint hits, cusps, overlaps reversed / elevated / sub-segment), public failing cases
//! re-created from their reports, and properties across independent routes (A∩B = B∩A swapped,
//! the common points lie on both curves exactly, a cubic's self-intersection is `classify`'s
//! double point).

use crate::common::{run, stderr, stdout};
use casteljau::classify::{NodeType, classify};
use casteljau::curve::BezierCurve;
use casteljau::intersect::{Domain, self_intersect};
use casteljau::num::Point;
use casteljau::num::{NumberMode, parse_points_in};
use casteljau::poly::RealAlgebraic;
use casteljau::{RationalBezier, rat};
use num_rational::BigRational;
use proptest::prelude::*;

/// Two polynomial curves' intersections (as rational curves of unit weights), no work limit.
fn intersect_polynomial(
    a: &casteljau::BezierCurve<num_rational::BigRational>,
    b: &casteljau::BezierCurve<num_rational::BigRational>,
    domain: Domain,
) -> casteljau::Result<casteljau::intersect::Intersections> {
    casteljau::intersect::intersect(&a.clone().into(), &b.clone().into(), domain, &casteljau::work::Budget::unlimited())
}

fn c(s: &str) -> BezierCurve<BigRational> {
    BezierCurve::new(parse_points_in(s, 2, None, NumberMode::Exact).unwrap()).unwrap()
}

fn c64(s: &str) -> BezierCurve<BigRational> {
    BezierCurve::new(parse_points_in(s, 2, None, NumberMode::Binary64).unwrap()).unwrap()
}

/// `(s, t, contact order)` spelled exactly.
fn hits(a: &BezierCurve<BigRational>, b: &BezierCurve<BigRational>) -> Vec<(String, String, usize)> {
    intersect_polynomial(a, b, Domain::Unit)
        .unwrap()
        .intersections
        .iter()
        .map(|i| (i.s.to_string(), i.t.to_string(), i.contact_order))
        .collect()
}

fn h(s: &str, t: &str, k: usize) -> (String, String, usize) {
    (s.into(), t.into(), k)
}

#[test]
fn intersect_tangencies_of_order_two_and_three() {
    // the parabola's apex touches y = 1
    assert_eq!(hits(&c("0 0, 1 2, 2 0"), &c("0 1, 2 1")), [h("1/2", "1/2", 2)]);
    // y = s³ against its inflection tangent y = 0 at an endpoint: order 3
    assert_eq!(hits(&c("0 0, 1 0, 2 0, 3 1"), &c("0 0, 3 0")), [h("0", "0", 3)]);
    // the seed cubic's inflection tangent, in the middle
    assert_eq!(hits(&c("-1 -1, -1/3 1, 1/3 -1, 1 1"), &c("-1 0, 1 0")), [h("1/2", "1/2", 3)]);
    // two parabolas touching at their apexes
    assert_eq!(hits(&c("0 0, 1 2, 2 0"), &c("0 2, 1 0, 2 2")), [h("1/2", "1/2", 2)]);
}

#[test]
fn intersect_endpoints_irrational_hits_and_cusps() {
    assert_eq!(hits(&c("0 0, 1 0"), &c("1 0, 2 1")), [h("1", "0", 1)]);
    assert_eq!(
        hits(&c("0 0, 1 2, 2 0"), &c("0 1/2, 2 1/2")),
        [h("1/2 - 1/4*sqrt(2)", "1/2 - 1/4*sqrt(2)", 1), h("1/2 + 1/4*sqrt(2)", "1/2 + 1/4*sqrt(2)", 1)]
    );
    // a line through the cusp at t = 0 of a cubic, and through its end point
    assert_eq!(hits(&c("0 0, 0 0, 1 1, 2 0"), &c("0 0, 2 0")), [h("0", "0", 2), h("1", "1", 1)]);
    // touching bounding boxes, no intersection
    assert!(hits(&c("0 0, 1 1, 2 0"), &c("0 1, 1 2, 2 1")).is_empty());
    // the crunode's double point: a line through it meets the cubic twice there
    let r = hits(&c("0 0, 2 2, -1 2, 1 0"), &c("0 3/5, 1 3/5"));
    assert!(r.iter().filter(|x| x.1 == "1/2").count() >= 2, "{r:?}");
}

#[test]
fn intersect_overlaps_reversed_elevated_and_sub_segments() {
    let o = |a: &str, b: &str| {
        let r = intersect_polynomial(&c(a), &c(b), Domain::Unit).unwrap();
        r.overlaps
            .iter()
            .map(|o| (o.s[0].to_string(), o.s[1].to_string(), o.t[0].to_string(), o.t[1].to_string()))
            .collect::<Vec<_>>()
    };
    let q = |a: &str, b: &str, c: &str, d: &str| vec![(a.to_string(), b.to_string(), c.to_string(), d.to_string())];
    // reversed copy
    assert_eq!(o("0 0, 1 2, 2 0", "2 0, 1 2, 0 0"), q("0", "1", "1", "0"));
    // degree-elevated copy
    assert_eq!(o("0 0, 1 2, 2 0", "0 0, 2/3 4/3, 4/3 4/3, 2 0"), q("0", "1", "0", "1"));
    // a sub-segment (the left half, by subdivision)
    assert_eq!(o("0 0, 1 2, 2 0", "0 0, 1/2 1, 1 1"), q("0", "1/2", "0", "1"));
    // collinear segments sharing a piece
    assert_eq!(o("0 0, 1 1, 2 2, 3 3", "1 1, 2 2"), q("1/3", "2/3", "0", "1"));
    // the same line, disjoint pieces: no overlap in the unit square
    assert!(o("0 0, 1 1", "2 2, 3 3").is_empty());
}

#[test]
fn intersect_public_failing_cases_recreated() {
    // Pomax/BezierInfo-2 #329: a degenerate (collinear) quadratic p0 (180, 0), p1 (180, 100),
    // p2 (180, 200) against the line y = 100 — the intersection was not found
    assert_eq!(hits(&c("180 0, 180 100, 180 200"), &c("0 100, 400 100")), [h("1/2", "9/20", 1)]);
    // thelonious/kld-intersections #17: two cubic arcs (SVG path data with binary64 numbers)
    // that visibly cross, reported as not intersecting
    let a = c64("150 150, 183.33333333333331 216.66666666666663, 233.33333333333337 216.66666666666663, 300 150");
    let b = c64("100 200, 166.66666666666663 133.33333333333337, 233.33333333333337 133.33333333333337, 300 200");
    let r = intersect_polynomial(&a, &b, Domain::Unit).unwrap();
    assert_eq!(r.intersections.len(), 2);
    assert!(r.intersections.iter().all(|i| i.kind.as_str() == "transversal"));
    // dhermes/bezier #10 / Paper.js #565 in kind: a tangential touch float code misses — the
    // circle-like arch and its tangent line at an irrational-free apex
    assert_eq!(hits(&c("0 0, 0 4, 4 4, 4 0"), &c("0 3, 4 3")), [h("1/2", "1/2", 2)]);
}

fn cubic() -> impl Strategy<Value = BezierCurve<BigRational>> {
    prop::collection::vec((-12i64..=12, -12i64..=12), 4)
        .prop_map(|v| BezierCurve::new(v.into_iter().map(|(x, y)| Point::new(vec![rat(x), rat(y)])).collect()).unwrap())
}

fn quadratic() -> impl Strategy<Value = BezierCurve<BigRational>> {
    prop::collection::vec((-12i64..=12, -12i64..=12), 3)
        .prop_map(|v| BezierCurve::new(v.into_iter().map(|(x, y)| Point::new(vec![rat(x), rat(y)])).collect()).unwrap())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// A ∩ B is B ∩ A with the parameters swapped, and every rational common point is on both
    /// curves exactly.
    #[test]
    fn intersect_is_symmetric_and_points_lie_on_both(a in quadratic(), b in cubic()) {
        let (ab, ba) = match (intersect_polynomial(&a, &b, Domain::Unit), intersect_polynomial(&b, &a, Domain::Unit)) {
            (Ok(x), Ok(y)) => (x, y),
            (Err(e), _) | (_, Err(e)) => { prop_assert!(e.to_string().contains("share a component")); return Ok(()); }
        };
        let mut left: Vec<(RealAlgebraic, RealAlgebraic)> = ab.intersections.iter().map(|i| (i.s.clone(), i.t.clone())).collect();
        let mut right: Vec<(RealAlgebraic, RealAlgebraic)> = ba.intersections.iter().map(|i| (i.t.clone(), i.s.clone())).collect();
        left.sort();
        right.sort();
        prop_assert_eq!(left, right);
        for i in &ab.intersections {
            if let (Some(s), Some(t), Some(p)) = (i.s.to_rational(), i.t.to_rational(), &i.point) {
                prop_assert_eq!(&a.eval(s), p);
                prop_assert_eq!(&b.eval(t), p);
            }
        }
    }

    /// Scaling the plane changes no common point's parameters: the pair scaled by `2^k` for
    /// `k` = 700, −700, 1500, by `10^400` in x alone, or translated by `2^600` (each beyond the
    /// range where the `f64` filters take the coordinates as they are, so they scale them, and
    /// the translation makes the exact route decide) gives the parameters and contact orders
    /// of the unscaled pair, compared with `==`.
    #[test]
    fn intersect_parameters_do_not_depend_on_the_plane_s_scale(a in quadratic(), b in cubic(), which in 0usize..5) {
        let plain = match intersect_polynomial(&a, &b, Domain::Unit) {
            Ok(x) => x,
            Err(e) => { prop_assert!(e.to_string().contains("share a component")); return Ok(()); }
        };
        let two = |k: i32| if k >= 0 { rat(1) * BigRational::from_integer(num_bigint::BigInt::from(1) << k) }
            else { BigRational::new(1.into(), num_bigint::BigInt::from(1) << -k) };
        let map = |c: &BezierCurve<BigRational>| {
            let pts = c.points().iter().map(|p| {
                let (x, y) = (p.coords[0].clone(), p.coords[1].clone());
                let (x, y) = match which {
                    0 => (x * two(700), y * two(700)),
                    1 => (x * two(-700), y * two(-700)),
                    2 => (x * two(1500), y * two(1500)),
                    3 => (x * BigRational::from_integer(num_bigint::BigInt::from(10).pow(400)), y),
                    _ => (x + two(600), y - two(600)),
                };
                Point::new(vec![x, y])
            }).collect();
            BezierCurve::new(pts).unwrap()
        };
        let scaled = intersect_polynomial(&map(&a), &map(&b), Domain::Unit).unwrap();
        let key = |r: &casteljau::intersect::Intersections| -> Vec<(RealAlgebraic, RealAlgebraic, usize)> {
            r.intersections.iter().map(|i| (i.s.clone(), i.t.clone(), i.contact_order)).collect()
        };
        prop_assert_eq!(key(&plain), key(&scaled));
        prop_assert_eq!(plain.overlaps.len(), scaled.overlaps.len());
    }

    /// The self-intersection of a cubic is classify's double point (a crunode with both
    /// parameters on [0, 1]), and nothing else.
    #[test]
    fn self_intersection_of_a_cubic_is_the_classified_double_point(a in cubic()) {
        let k = classify(&a).unwrap();
        let rb = RationalBezier::new(a.points().to_vec(), vec![rat(1); 4]).unwrap();
        let r = match self_intersect(&rb, Domain::Unit, &casteljau::work::Budget::unlimited()) {
            Ok(r) => r,
            Err(e) => { prop_assert!(k.collinear || k.real_degree < 3, "{}", e); return Ok(()); }
        };
        let expected = k.node_type == Some(NodeType::Crunode) && k.segment.has_loop;
        prop_assert_eq!(r.intersections.len(), usize::from(expected));
        if expected {
            let i = &r.intersections[0];
            prop_assert_eq!(i.s.to_f64(), casteljau::Scalar::to_f64(&k.double_point_parameters[0]));
            prop_assert_eq!(i.t.to_f64(), casteljau::Scalar::to_f64(&k.double_point_parameters[1]));
            prop_assert_eq!(i.point.as_ref(), k.double_point.as_ref());
        }
    }
}

#[test]
fn cli_intersect_text_json_self_and_batch() {
    let o = run(&["intersect", "0 0, 1 2, 2 0", "0 1, 2 1"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(stdout(&o), "s = 1/2 (≈ 0.5), t = 1/2 (≈ 0.5) at (1, 1): tangent, contact order 2\n");
    let o = run(&["intersect", "--json", "0 0, 1 2, 2 0", "0 1/2, 2 1/2"], None);
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["intersections"][0]["s"], "1/2 - 1/4*sqrt(2)");
    assert!(v["intersections"][0].get("point").is_none());
    assert_eq!(v["intersections"][0]["point_float"][1], 0.5);
    assert_eq!(v["intersections"][0]["kind"], "transversal");
    assert_eq!(v["overlaps"], serde_json::json!([]));
    let o = run(&["intersect", "--self", "--json", "0 0, 2 2, -1 2, 1 0"], None);
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["intersections"][0]["point"], serde_json::json!(["1/2", "3/5"]));
    let o = run(&["intersect", "--json", "--input", "-"], Some("0 0, 1 1 ; 0 1, 1 0\n0 0, 1 0 ; 0 1, 1 1\nbad\n"));
    assert_eq!(o.status.code(), Some(2));
    let lines: Vec<serde_json::Value> = stdout(&o).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines[0]["line"], 1);
    assert_eq!(lines[0]["intersections"][0]["point"], serde_json::json!(["1/2", "1/2"]));
    assert_eq!(lines[1]["intersections"], serde_json::json!([]));
    assert!(lines[2]["error"].as_str().unwrap().contains("A ; B"));
    // overlaps are reported, never a hang
    let o = run(&["intersect", "0 0, 1 2, 2 0", "2 0, 1 2, 0 0"], None);
    assert_eq!(stdout(&o), "overlap: s in [0, 1] with t from 1 to 0\n");
}

/// Shared components: rational curves (Möbius reparametrizations, with their crossings), curves
/// on one line (turn-backs included) and single points.
mod overlaps {
    use super::*;
    use casteljau::intersect::{Intersections, intersect};

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    fn rc(points: &str, weights: &[i64]) -> RationalBezier<BigRational> {
        RationalBezier::new(c(points).points().to_vec(), weights.iter().map(|&w| rat(w)).collect()).unwrap()
    }

    fn at(c: &RationalBezier<BigRational>, x: &RealAlgebraic) -> [RealAlgebraic; 2] {
        let h = c.homogeneous().power_coefficients();
        let coord = |k: usize| casteljau::poly::Poly::new(h.iter().map(|p| p.coords[k].clone()).collect());
        [x.map_rational(&coord(0), &coord(2)), x.map_rational(&coord(1), &coord(2))]
    }

    /// Every overlap's ends and every intersection are one point on both curves, exactly.
    pub fn consistent(a: &RationalBezier<BigRational>, b: &RationalBezier<BigRational>, r: &Intersections) -> bool {
        r.overlaps.iter().all(|o| (0..2).all(|k| at(a, &o.s[k]) == at(b, &o.t[k])))
            && r.intersections.iter().all(|i| at(a, &i.s) == at(b, &i.t))
    }

    fn spelled(r: &Intersections) -> Vec<String> {
        r.overlaps.iter().map(|o| format!("s [{}, {}] t {} -> {}", o.s[0], o.s[1], o.t[0], o.t[1])).collect()
    }

    #[test]
    fn rational_overlaps_through_the_pole_of_the_reparametrization() {
        // the unit circle ((1 − s²), 2s)/(1 + s²) on s ∈ [0, 1], and the circle again with
        // s = (4t − 1)/(8t − 4): t ∈ [0, 1/2) runs s from 1/4 down to −∞, t ∈ (1/2, 1] from +∞
        // down to 3/4 — two arcs, one per branch of the hyperbola s(t)
        let a = rc("1 0, 1 1, 0 1", &[1, 1, 2]);
        let b = rc("15/17 8/17, 13/19 16/19, 7/25 24/25", &[17, -19, 25]);
        let r = intersect(&a, &b, Domain::Unit, &casteljau::work::Budget::unlimited()).unwrap();
        assert_eq!(spelled(&r), ["s [0, 1/4] t 1/4 -> 0", "s [3/4, 1] t 1 -> 3/4"]);
        assert!(r.intersections.is_empty() && consistent(&a, &b, &r));
        assert_eq!(r.overlaps[1].t_float, [1.0, 0.75]);
        // B passes through A(∞) = (−1, 0) at t = 1/2; A's own s ∈ [0, 1] is t ∈ [0, 1/3]
        let b = rc("1 0, 1 -1, 0 -1", &[1, -1, 2]);
        assert_eq!(
            spelled(&intersect(&a, &b, Domain::Unit, &casteljau::work::Budget::unlimited()).unwrap()),
            ["s [0, 1] t 0 -> 1/3"]
        );
        assert_eq!(
            spelled(&intersect(&b, &a, Domain::Unit, &casteljau::work::Budget::unlimited()).unwrap()),
            ["s [0, 1/3] t 0 -> 1"]
        );
        // reweighted copies (w_i ρ^i): the same arc, ends fixed
        let r = intersect(
            &rc("1 0, 1 1, 0 1", &[1, 1, 1]),
            &rc("1 0, 1 1, 0 1", &[1, 2, 4]),
            Domain::Unit,
            &casteljau::work::Budget::unlimited(),
        )
        .unwrap();
        assert_eq!(spelled(&r), ["s [0, 1] t 0 -> 1"]);
    }

    #[test]
    fn an_overlap_keeps_the_crossings_of_the_shared_curve() {
        // the crunode cubic and its left half: the loop's second pass (s = 1/2 + √15/10) meets
        // the half at t = 1 − √15/5, off the shared arc
        let a = rc("0 0, 2 2, -1 2, 1 0", &[1, 1, 1, 1]);
        let b = rc("0 0, 1 1, 3/4 3/2, 1/2 3/2", &[1, 1, 1, 1]);
        let r = intersect(&a, &b, Domain::Unit, &casteljau::work::Budget::unlimited()).unwrap();
        assert_eq!(spelled(&r), ["s [0, 1/2] t 0 -> 1"]);
        let i = &r.intersections;
        assert_eq!(i.len(), 1);
        assert_eq!((i[0].s.to_string(), i[0].t.to_string()), ("1/2 + 1/10*sqrt(15)".into(), "1 - 1/5*sqrt(15)".into()));
        assert!(consistent(&a, &b, &r));
        // the nodal cubic (u² − 1, u(u² − 1)) with u = (s − 2)/(s + 1): its double point is
        // A(1/2) = A(∞); B = A((t + 2)/(1 − 3t)) passes it at t = 1/3, where s = ∞ — no shared
        // arc inside the square, one crossing found through A's parameter at infinity
        let a3 = rc("3 -6, 1 -1/2, -1/4 1/2, -3/4 3/8", &[1, 2, 4, 8]);
        let b3 = rc("-1 0, -1 -7/3, 46/3 -14/3, 48 336", &[27, 9, 3, 1]);
        // and B = A((t + 2)/t), which starts at A(∞) = A(1/2): a sample of B at the double point,
        // where A's parameter at infinity must not be mistaken for the other branch's 1/2
        let b4 = rc("0 0, -1/2 -1/2, -13/16 -7/16, -15/16 -15/64", &[8, 16, 32, 64]);
        for (x, y, st) in
            [(&a3, &b3, ("1/2", "1/3")), (&b3, &a3, ("1/3", "1/2")), (&a3, &b4, ("1/2", "0")), (&b4, &a3, ("0", "1/2"))]
        {
            let r = intersect(x, y, Domain::Unit, &casteljau::work::Budget::unlimited()).unwrap();
            assert!(r.overlaps.is_empty() && consistent(x, y, &r));
            let got: Vec<(String, String)> =
                r.intersections.iter().map(|i| (i.s.to_string(), i.t.to_string())).collect();
            assert_eq!(got, [(st.0.to_string(), st.1.to_string())]);
        }
        // a curve with itself: the whole square's diagonal, and the double point both ways
        let r = intersect(&a, &a, Domain::Unit, &casteljau::work::Budget::unlimited()).unwrap();
        assert_eq!(spelled(&r), ["s [0, 1] t 0 -> 1"]);
        assert_eq!(r.intersections.len(), 2);
    }

    #[test]
    fn curves_on_one_line_and_single_points() {
        let o = |a: &str, b: &str| spelled(&intersect_polynomial(&c(a), &c(b), Domain::Unit).unwrap());
        // x = 3s + s³ (collinear control points not evenly spaced: not a line's parametrization
        // of degree 1) against the segment [1, 3]
        assert_eq!(
            o("0 0, 1 0, 2 0, 4 0", "1 0, 3 0"),
            ["s [root 1 of t^3 + 3*t - 1 in [5/16, 3/8], root 1 of t^3 + 3*t - 3 in [13/16, 7/8]] t 0 -> 1"]
        );
        // x = 6s − 15s² + 10s³ turns back at s = 1/2 ∓ √5/10: three arcs against [0, 1]
        let r = o("0 0, 2 0, -1 0, 1 0", "0 0, 1 0");
        assert_eq!(r.len(), 3);
        assert_eq!(r[1], "s [1/2 - 1/10*sqrt(5), 1/2 + 1/10*sqrt(5)] t 1/2 + 1/10*sqrt(5) -> 1/2 - 1/10*sqrt(5)");
        // collinear segments end to end: a shared component that only touches, an arc of length 0
        assert_eq!(o("0 0, 1 0", "1 0, 2 0"), ["s [1, 1] t 0 -> 0"]);
        assert_eq!(o("0 0, 0 1", "0 1, 0 2, 0 3"), ["s [1, 1] t 0 -> 0"]);
        // a single point on a curve: all of it matches the curve's parameter there
        assert_eq!(o("1 1, 1 1", "0 0, 2 2"), ["s [0, 1] t 1/2 -> 1/2"]);
        assert_eq!(o("0 0, 2 2", "1 1, 1 1, 1 1"), ["s [1/2, 1/2] t 0 -> 1"]);
        assert!(o("5 5, 5 5", "0 0, 2 2").is_empty());
        // a line traced back and forth overlaps itself
        let a = rc("0 0, 2 0, -1 0, 1 0", &[1, 1, 1, 1]);
        let r = self_intersect(&a, Domain::Unit, &casteljau::work::Budget::unlimited()).unwrap();
        assert_eq!(r.overlaps.len(), 3);
        assert!(r.overlaps.iter().all(|o| o.s[0] <= o.t[0].clone().min(o.t[1].clone())));
        assert!(consistent(&a, &a, &r));
    }

    #[test]
    fn improper_parametrizations_off_a_line_are_refused() {
        // the parabola y = x² traced as (s², s⁴), against itself (s, s²): a double cover
        let a = c("0 0, 0 0, 1/6 0, 1/2 0, 1 1");
        let b = c("0 0, 1/2 0, 1 1");
        let e = intersect_polynomial(&a, &b, Domain::Unit).unwrap_err().to_string();
        assert!(e.contains("more than once"), "{e}");
    }

    fn rational_cubic() -> impl Strategy<Value = RationalBezier<BigRational>> {
        (prop::collection::vec((-12i64..=12, -12i64..=12), 4), prop::collection::vec(1i64..=4, 4)).prop_map(|(v, w)| {
            let pts = v.into_iter().map(|(x, y)| Point::new(vec![rat(x), rat(y)])).collect();
            RationalBezier::new(pts, w.into_iter().map(rat).collect()).unwrap()
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]

        /// A rational cubic against a reweighted (w_i ρ^i: a Möbius reparametrization), split and
        /// maybe reversed copy of itself: overlaps are found, their ends and the crossings are on
        /// both curves exactly, and swapping the curves swaps the answer.
        #[test]
        fn overlaps_of_reparametrized_copies(
            a in rational_cubic(),
            rho in prop_oneof![Just((1, 2)), Just((2, 1)), Just((3, 1))],
            u in prop_oneof![Just((1, 4)), Just((1, 2)), Just((3, 4))],
            left in any::<bool>(),
            reverse in any::<bool>(),
        ) {
            let rho = q(rho.0, rho.1);
            let w: Vec<BigRational> = a.weights().iter().enumerate().map(|(i, w)| w * num_traits::pow(rho.clone(), i)).collect();
            let pts: Vec<Point<BigRational>> = a.points().into_iter().map(Option::unwrap).collect();
            let re = RationalBezier::new(pts, w).unwrap();
            let (l, r) = re.subdivide(&q(u.0, u.1)).unwrap();
            let mut b = if left { l } else { r };
            if reverse {
                let mut p: Vec<Point<BigRational>> = b.points().into_iter().map(Option::unwrap).collect();
                let mut w = b.weights();
                p.reverse();
                w.reverse();
                b = RationalBezier::new(p, w).unwrap();
            }
            let ab = intersect(&a, &b, Domain::Unit, &casteljau::work::Budget::unlimited()).unwrap();
            let ba = intersect(&b, &a, Domain::Unit, &casteljau::work::Budget::unlimited()).unwrap();
            prop_assert!(!ab.overlaps.is_empty());
            prop_assert!(consistent(&a, &b, &ab));
            let swap = |r: &Intersections| {
                let mut v: Vec<[RealAlgebraic; 4]> = r.overlaps.iter().map(|o| {
                    if o.t[0] <= o.t[1] { [o.t[0].clone(), o.t[1].clone(), o.s[0].clone(), o.s[1].clone()] }
                    else { [o.t[1].clone(), o.t[0].clone(), o.s[1].clone(), o.s[0].clone()] }
                }).collect();
                v.sort();
                v
            };
            let mut direct: Vec<[RealAlgebraic; 4]> = ba.overlaps.iter().map(|o| [o.s[0].clone(), o.s[1].clone(), o.t[0].clone(), o.t[1].clone()]).collect();
            direct.sort();
            prop_assert_eq!(swap(&ab), direct);
            let mut x: Vec<(RealAlgebraic, RealAlgebraic)> = ab.intersections.iter().map(|i| (i.t.clone(), i.s.clone())).collect();
            let mut y: Vec<(RealAlgebraic, RealAlgebraic)> = ba.intersections.iter().map(|i| (i.s.clone(), i.t.clone())).collect();
            x.sort();
            y.sort();
            prop_assert_eq!(x, y);
        }
    }
}

mod winding {
    use super::*;
    use casteljau::path::{ClosedPath, PathWinding};
    use casteljau::work::Budget;

    fn path(s: &str) -> Vec<BezierCurve<BigRational>> {
        s.split(';').map(c).collect()
    }

    /// The winding number of one closed contour around `q` (`Some`), `None` on the contour.
    fn winding_number(contour: &[BezierCurve<BigRational>], q: &Point<BigRational>) -> casteljau::Result<Option<i64>> {
        let p = ClosedPath::from_polynomial(vec![contour.to_vec()])?;
        Ok(match p.winding(&q.try_into()?, &Budget::unlimited())? {
            PathWinding::Off(w) => Some(w.winding()),
            PathWinding::OnBoundary { .. } => None,
        })
    }

    /// The segment of the contour through `q`, when it is on it.
    fn on_segment(contour: &[BezierCurve<BigRational>], q: &Point<BigRational>) -> Option<usize> {
        match ClosedPath::from_polynomial(vec![contour.to_vec()])
            .unwrap()
            .winding(&q.try_into().unwrap(), &Budget::unlimited())
            .unwrap()
        {
            PathWinding::OnBoundary { on_boundary } => Some(on_boundary.segment),
            PathWinding::Off(_) => None,
        }
    }

    fn q(x: BigRational, y: BigRational) -> Point<BigRational> {
        Point::new(vec![x, y])
    }

    #[test]
    fn winding_tangent_rays_joints_and_stretches_on_the_ray() {
        let lens = path("0 0, 1 2, 2 0 ; 2 0, 0 0");
        let w = |x: BigRational, y: BigRational| winding_number(&lens, &q(x, y)).unwrap();
        assert_eq!(w(rat(1), BigRational::new(1.into(), 2.into())), Some(-1));
        // the ray through the apex only touches the parabola
        assert_eq!(w(rat(-1), rat(1)), Some(0));
        // the ray along the chord (a whole segment on it) and through both joints
        assert_eq!(w(rat(-1), rat(0)), Some(0));
        assert_eq!(w(rat(2), rat(0)), None);
        assert!(matches!(on_segment(&lens, &q(rat(2), rat(0))), Some(0 | 1)));
        // a figure eight: +1 in one lobe, −1 in the other (a cubic with its own loop closed by a line)
        let eight = path("0 0, 2 2, -1 2, 1 0 ; 1 0, 0 0");
        let lobes: Vec<Option<i64>> = [
            (BigRational::new(1.into(), 2.into()), BigRational::new(3.into(), 4.into())),
            (BigRational::new(1.into(), 2.into()), BigRational::new(1.into(), 10.into())),
        ]
        .into_iter()
        .map(|(x, y)| winding_number(&eight, &q(x, y)).unwrap())
        .collect();
        assert!(lobes.iter().all(|w| matches!(w, Some(k) if k.abs() == 1)), "{lobes:?}");
        assert!(winding_number(&path("0 0, 1 0 ; 2 0, 0 0"), &q(rat(5), rat(5))).is_err());
    }

    /// The exact crossing-number winding of a polygon (Sunday's rule with rational arithmetic).
    fn polygon_winding(v: &[(i64, i64)], p: (BigRational, BigRational)) -> Option<i64> {
        let mut w = 0;
        for i in 0..v.len() {
            let (a, b) = (v[i], v[(i + 1) % v.len()]);
            let (ax, ay, bx, by) = (rat(a.0), rat(a.1), rat(b.0), rat(b.1));
            let cross = (bx.clone() - &ax) * (p.1.clone() - &ay) - (p.0.clone() - &ax) * (by.clone() - &ay);
            let within = |u: &BigRational, s: &BigRational, t: &BigRational| (u >= s && u <= t) || (u >= t && u <= s);
            if cross == rat(0) && within(&p.0, &ax, &bx) && within(&p.1, &ay, &by) {
                return None; // on the edge
            }
            if ay <= p.1 {
                if by > p.1 && cross > rat(0) {
                    w += 1;
                }
            } else if by <= p.1 && cross < rat(0) {
                w -= 1;
            }
        }
        Some(w)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]

        #[test]
        fn winding_of_polygons_matches_the_crossing_rule(
            v in prop::collection::vec((-4i64..=4, -4i64..=4), 3..7),
            px in -8i64..=8, py in -8i64..=8,
        ) {
            let segs: Vec<BezierCurve<BigRational>> = (0..v.len())
                .map(|i| {
                    let (a, b) = (v[i], v[(i + 1) % v.len()]);
                    BezierCurve::new(vec![Point::new(vec![rat(a.0), rat(a.1)]), Point::new(vec![rat(b.0), rat(b.1)])]).unwrap()
                })
                .collect();
            // half-integer query points hit vertices' rows and columns often, vertices never
            let p = (BigRational::new(px.into(), 2.into()), BigRational::new(py.into(), 2.into()));
            let ours = winding_number(&segs, &q(p.0.clone(), p.1.clone())).unwrap();
            prop_assert_eq!(ours, polygon_winding(&v, p));
        }
    }

    #[test]
    fn cli_winding_text_json_svg() {
        let o = run(&["winding", "--point", "1 1/2", "0 0, 1 2, 2 0 ; 2 0, 0 0"], None);
        assert_eq!(stdout(&o), "winding number -1: inside (non-zero rule), inside (even-odd rule)\n");
        let o = run(&["winding", "--json", "--svg", "--point", "1 0", "M0 0 Q1 2 2 0 Z"], None);
        let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
        assert_eq!(v["on_boundary"]["segment"], 1);
        let o = run(&["winding", "--point", "0 0", "0 0, 1 1 ; 2 2, 0 0"], None);
        assert_eq!(o.status.code(), Some(2));
        assert!(stderr(&o).contains("not closed"), "{}", stderr(&o));
    }
}

mod hard_cases {
    use super::*;
    use casteljau::oracle::check_intersections;
    use casteljau::strategies::{binary64, intersections as hard};

    fn pairs(a: &BezierCurve<BigRational>, b: &BezierCurve<BigRational>) -> Vec<(RealAlgebraic, RealAlgebraic, usize)> {
        intersect_polynomial(a, b, Domain::Unit)
            .unwrap()
            .intersections
            .into_iter()
            .map(|i| (i.s, i.t, i.contact_order))
            .collect()
    }

    fn r(x: &BigRational) -> RealAlgebraic {
        RealAlgebraic::from(x.clone())
    }

    /// The right float answers pass the oracle; answering nothing misses every intersection.
    fn oracle_round_trip(a: &BezierCurve<BigRational>, b: &BezierCurve<BigRational>) -> Result<(), TestCaseError> {
        let (fa, fb) = (binary64::points(a), binary64::points(b));
        let exact = intersect_polynomial(a, b, Domain::Unit).unwrap();
        let right: Vec<(f64, f64)> = exact.intersections.iter().map(|i| (i.s_float, i.t_float)).collect();
        prop_assert_eq!(check_intersections(&fa, &fb, &right, 1e-12, Domain::Unit).unwrap(), vec![]);
        let none = check_intersections(&fa, &fb, &[], 1e-12, Domain::Unit).unwrap();
        prop_assert_eq!(none.len(), exact.intersections.len());
        let mut doubled = right.clone();
        doubled.extend(right.first().copied());
        doubled.push((7.0, 7.0));
        let d = check_intersections(&fa, &fb, &doubled, 1e-12, Domain::Unit).unwrap();
        prop_assert_eq!(d.len(), 1 + usize::from(!right.is_empty()));
        Ok(())
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(16))]

        #[test]
        fn hard_parabola_tangents_have_contact_two(case in hard::tangency(2)) {
            let (a, b, (s, t)) = case;
            prop_assert_eq!(pairs(&a, &b), vec![(r(&s), r(&t), 2)]);
            oracle_round_trip(&a, &b)?;
        }

        #[test]
        fn hard_inflection_tangents_have_contact_three(case in hard::tangency(3)) {
            let (a, b, (s, t)) = case;
            prop_assert_eq!(pairs(&a, &b), vec![(r(&s), r(&t), 3)]);
            oracle_round_trip(&a, &b)?;
        }

        #[test]
        fn hard_endpoint_hits_are_found(case in hard::endpoint_hit()) {
            let (a, b, tau) = case;
            let found = pairs(&a, &b);
            prop_assert!(found.iter().any(|(s, t, _)| *s == r(&tau) && *t == r(&rat(0))), "{:?}", found);
            oracle_round_trip(&a, &b)?;
        }

        #[test]
        fn hard_overlaps_are_reported_as_arcs(case in hard::overlap()) {
            let (a, b, u) = case;
            let x = intersect_polynomial(&a, &b, Domain::Unit).unwrap();
            let unit = |c: &BezierCurve<BigRational>| RationalBezier::new(c.points().to_vec(), vec![rat(1); c.points().len()]).unwrap();
            prop_assert!(super::overlaps::consistent(&unit(&a), &unit(&b), &x));
            let d = |k: usize, q: &Point<BigRational>| q.coords[k].clone() - &a.points()[0].coords[k];
            let line = a.points().iter().all(|p| a.points().iter().all(|q| d(0, p) * d(1, q) == d(1, p) * d(0, q)));
            if line {
                // a cubic on a line may turn back: its arcs are cut at the turning points, but
                // together they hold the whole left piece s ∈ [0, u]
                prop_assert!(x.overlaps.iter().any(|o| o.s[0] == RealAlgebraic::from(rat(0))));
                prop_assert!(x.overlaps.iter().any(|o| o.s[1] == RealAlgebraic::from(u.clone())));
            } else {
                prop_assert_eq!(x.overlaps.len(), 1);
                prop_assert_eq!(&x.overlaps[0].s, &[rat(0), u.clone()].map(RealAlgebraic::from));
                prop_assert_eq!(&x.overlaps[0].t, &[rat(0), rat(1)].map(RealAlgebraic::from));
            }
        }

        #[test]
        fn hard_touching_boxes_do_not_intersect(case in hard::touching_boxes()) {
            let (a, b) = case;
            prop_assert!(pairs(&a, &b).is_empty());
            oracle_round_trip(&a, &b)?;
        }

        #[test]
        fn hard_lines_through_cusps_meet_them_there(case in hard::through_cusp()) {
            let (a, b, tau) = case;
            let found = pairs(&a, &b);
            prop_assert!(found.iter().any(|(s, t, k)| *s == r(&tau) && *t == r(&casteljau::ratio(1, 2)) && *k >= 2), "{:?}", found);
            oracle_round_trip(&a, &b)?;
        }
    }
}

#[test]
fn cli_intersect_plot_marks_tangencies_and_overlaps() {
    let dir = crate::common::TempDir::new("plot");
    let f = dir.join("t.svg");
    let o = run(&["intersect", "--plot", f.to_str().unwrap(), "0 0, 2 4, -1 4, 3 0", "-1 3, 4 3"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let svg = std::fs::read_to_string(&f).unwrap();
    assert!(svg.contains("tangent, order 2"), "{svg}");
    let g = dir.join("o.svg");
    run(&["intersect", "--plot", g.to_str().unwrap(), "0 0, 1 2, 2 0", "0 0, 1/2 1, 1 1"], None);
    assert!(std::fs::read_to_string(&g).unwrap().contains("#ff9900"));
    // one pair only (a file, not stdin: the command refuses before reading)
    let batch = dir.join("pairs.txt");
    std::fs::write(&batch, "0 0, 1 1 ; 0 1, 1 0\n").unwrap();
    assert_eq!(
        run(&["intersect", "--plot", f.to_str().unwrap(), "--input", batch.to_str().unwrap()], None).status.code(),
        Some(2)
    );
}

#[test]
fn cli_intersect_refuses_work_beyond_the_budget_naming_the_option() {
    let pts = |n: i64| (0..n).map(|i| format!("{} {}", i * 37 % 101, i * i % 53)).collect::<Vec<_>>().join(", ");
    let o = run(&["intersect", &pts(11), &pts(11)], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--max-work"), "{}", stderr(&o));
    // huge coordinates: refused before any work
    let big = format!("0 0, 1{} 1, 2 0, 3 1", "0".repeat(990));
    let o = run(&["intersect", &big, "0 1, 1 0, 2 1, 3 0"], None);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("estimated work"), "{}", stderr(&o));
    // and the library without a budget still answers small cases
    assert_eq!(run(&["intersect", "--max-work", "1e9", "0 0, 1 1", "0 1, 1 0"], None).status.code(), Some(0));
}

#[test]
fn intersect_all_parameters_skips_common_points_at_infinity() {
    // both weights (1, −1, 1) vanish at t = 1/2: the curves meet only at infinity there; with
    // every real parameter allowed that is not an intersection in the plane (it used to panic)
    let o = run(
        &["intersect", "--all", "--weights-a", "1 -1 1", "--weights-b", "1 -1 1", "0 0, 1 1, 2 0", "0 1, 1 2, 2 1"],
        None,
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(stdout(&o), "no intersections\n");
    let o = run(&["intersect", "--self", "--all", "--weights-a", "1 -1 1", "0 0, 1 1, 2 0"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

#[test]
fn cli_bbox_and_winding_refuse_work_beyond_the_budget_naming_the_option() {
    // degree 20 with 60-bit coordinates: about 20 s of work, refused up front
    let pts = (0..21i128).map(|i| format!("{} {}", (i * 7919 + 1) << 50, (i * i * 31 + 5) << 48)).collect::<Vec<_>>();
    let o = run(&["bbox", &pts.join(", ")], None);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("bounding box of degree 20") && stderr(&o).contains("--max-work"), "{}", stderr(&o));
    // a small curve is answered, and a raised budget is honoured
    assert_eq!(run(&["bbox", "0 0, 1 2, 2 0"], None).status.code(), Some(0));
    let small = (0..6).map(|i| format!("{} {}", i * 3, (i * i) % 7)).collect::<Vec<_>>().join(", ");
    assert_eq!(run(&["bbox", "--max-work", "1e12", &small], None).status.code(), Some(0));
    // a closed path of four degree-200 segments: refused, naming the option
    let seg = |a: (i64, i64), b: (i64, i64)| {
        let mut p = vec![format!("{} {}", a.0, a.1)];
        p.extend((1..200).map(|i| format!("{} {}", (i * 37) % 101, (i * 53) % 97)));
        p.push(format!("{} {}", b.0, b.1));
        p.join(", ")
    };
    let path = [seg((0, 0), (10, 0)), seg((10, 0), (10, 10)), seg((10, 10), (0, 10)), seg((0, 10), (0, 0))].join(" ; ");
    let o = run(&["winding", "--point", "5 5", &path], None);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("winding number of a path of 4 segments"), "{}", stderr(&o));
    assert!(stderr(&o).contains("--max-work"), "{}", stderr(&o));
    let o = run(&["winding", "--max-work", "1e9", "--point", "1 1", "0 0, 4 0 ; 4 0, 0 4 ; 0 4, 0 0"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

/// SVG fills close an open subpath by a line: `fill_path` of an open outline is the path of
/// the explicitly closed one, and the fill rules read its winding numbers.
#[test]
fn winding_fill_path_closes_open_subpaths_and_fill_rules_decide_inside() {
    use casteljau::format::fill_path;
    use casteljau::path::{FillRule, PathWinding};
    let open = fill_path("M0 0 L4 0 L4 4 L0 4 M1 1 L3 1 L3 3 L1 3", NumberMode::Exact).unwrap();
    let closed = fill_path("M0 0 L4 0 L4 4 L0 4 Z M1 1 L3 1 L3 3 L1 3 Z", NumberMode::Exact).unwrap();
    assert_eq!(open, closed);
    let at = |x: i64, y: i64| casteljau::num::Point2::new(rat(x), rat(y));
    let PathWinding::Off(hole) = open.winding(&at(2, 2), &casteljau::work::Budget::unlimited()).unwrap() else {
        panic!("off the path")
    };
    assert_eq!(hole.winding(), 2);
    assert!(hole.inside(FillRule::NonZero) && !hole.inside(FillRule::EvenOdd));
    let PathWinding::OnBoundary { on_boundary } =
        open.winding(&at(3, 2), &casteljau::work::Budget::unlimited()).unwrap()
    else {
        panic!("on the path")
    };
    assert_eq!((on_boundary.subpath, on_boundary.segment), (1, 1));
    // an arc is no polynomial segment: refused with its reason, not approximated
    assert!(fill_path("M0 0 A1 1 0 0 1 2 0", NumberMode::Exact).is_err());
    assert_eq!("even-odd".parse::<FillRule>().unwrap(), FillRule::EvenOdd);
}
