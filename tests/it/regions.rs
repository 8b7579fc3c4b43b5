//! Regions decided, not spellings: boolean operations where curves leave a vertex tangentially
//! (at a cusp, at irrational parameters) answered exactly, and the `--against` oracle agreeing
//! with every spelling of the exact region (other contours, nesting, start points, order,
//! direction) while proving a wrong one wrong.

use crate::common::{run, stderr, stdout};
use casteljau::num::Point2;
use casteljau::oracle::check_against;
use casteljau::path::{FillRule, PathWinding};
use casteljau::ratio;
use casteljau::shape::{BooleanOp, BooleanOptions, Shape, boolean};
use casteljau::work::Budget;
use num_rational::BigRational;
use proptest::prelude::*;
use serde_json::Value;

const CUSP: &str = "M0 0 C1 1 0 1 1 0 L0 0 Z";

fn json(args: &[&str]) -> Value {
    let o = run(args, None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    serde_json::from_str(stdout(&o).trim()).unwrap()
}

/// The result's exact membership against the inputs' own winding numbers at rational points of
/// a grid (denominators 17 and 19: off every boundary of these cases, or skipped when on one).
fn assert_memberships(op: BooleanOp, a: &str, b: &str, range: (i64, i64)) {
    let (sa, sb): (Shape, Shape) = (a.parse().unwrap(), b.parse().unwrap());
    let r = boolean(op, &[sa.clone(), sb.clone()], BooleanOptions::default(), &Budget::unlimited()).unwrap();
    let inside = |s: &Shape, q: &Point2<BigRational>| match s.path().winding(q, &Budget::unlimited()).unwrap() {
        PathWinding::Off(w) => Some(FillRule::NonZero.contains(w.winding())),
        PathWinding::OnBoundary { .. } => None,
    };
    let mut checked = 0;
    for i in range.0 * 17..=range.1 * 17 {
        for j in range.0 * 19..=range.1 * 19 {
            let q = Point2::new(ratio(i, 17), ratio(j, 19));
            let (Some(x), Some(y)) = (inside(&sa, &q), inside(&sb, &q)) else { continue };
            let Some(got) = r.contains(&q).unwrap() else { continue };
            assert_eq!(got, op.apply(x, y), "{op:?} at ({i}/17, {j}/19)");
            checked += 1;
        }
    }
    assert!(checked > 100, "{checked}");
}

#[test]
fn boolean_xor_line_through_a_cusp_is_answered_exactly() {
    let b = "M0.5 0 L1 0 L1 1 L0.5 1 L0.5 0 Z";
    let v = json(&["boolean", "xor", CUSP, b, "--json"]);
    // the cusp region has area 3/10, half of it inside the square of area 1/2
    assert_eq!((v["contours"].as_u64(), v["area"].as_str()), (Some(2), Some("1/2")));
    assert_eq!(v["path"], "M0.5 0.75C0.5 0.75 0.5 0.5 0 0L0.5 0ZM0.5 0.75C0.5 0.75 0.5 0.5 1 0L1 1L0.5 1Z");
    assert_memberships(BooleanOp::Xor, CUSP, b, (0, 1));
    for op in ["union", "intersection", "difference"] {
        let o = run(&["boolean", op, CUSP, b], None);
        assert_eq!(o.status.code(), Some(0), "{op}: {}", stderr(&o));
    }
    let v = json(&["boolean", "intersection", CUSP, b, "--json"]);
    assert_eq!(v["area"], "3/20");
}

#[test]
fn boolean_xor_line_touching_a_cusp_is_answered_exactly() {
    let b = "M0 0.75 L1 0.75 L1 1 L0 1 Z";
    let v = json(&["boolean", "xor", CUSP, b, "--json"]);
    // they meet only at the cusp: 3/10 + 1/4
    assert_eq!((v["contours"].as_u64(), v["area"].as_str()), (Some(2), Some("11/20")));
    assert_memberships(BooleanOp::Xor, CUSP, b, (0, 1));
    let v = json(&["boolean", "union", CUSP, b, "--json"]);
    assert_eq!(v["area"], "11/20");
}

/// A cubic crossing `x = 0` with a horizontal tangent at `t = (1 ± √(1/2))/2` (`x = (8t² − 8t +
/// 1)(t + 1)`, `y' = 24(t² − t + 1/8)`), and its mirror image: tangent at two irrational vertices,
/// where the edges leaving in one direction agree to second order and differ at the third.
const LEFT: &str = "M3 0 C-4 3 -11 -6 6 -3 Z";
const RIGHT: &str = "M-3 0 C4 3 11 -6 -6 -3 Z";

#[test]
fn boolean_tangent_at_irrational_parameters_is_answered() {
    let area = |op: &str| json(&["boolean", op, LEFT, RIGHT, "--json"])["area_float"].as_f64().unwrap();
    let (u, i, x, d) = (area("union"), area("intersection"), area("xor"), area("difference"));
    // each shape's area is 162/5
    assert_eq!(json(&["boolean", "simplify", LEFT, "--json"])["area"], "162/5");
    assert!((u + i - 2.0 * 32.4).abs() < 1e-12 && (u - i - x).abs() < 1e-12 && (x - 2.0 * d).abs() < 1e-12);
    assert_eq!(json(&["boolean", "xor", LEFT, RIGHT, "--json"])["contours"], 6);
    for op in [BooleanOp::Union, BooleanOp::Intersection, BooleanOp::Xor, BooleanOp::Difference] {
        assert_memberships(op, LEFT, RIGHT, (-6, 6));
    }
}

#[test]
fn against_the_same_region_with_a_touching_hole_agrees_with_a_note() {
    let a = "m1 1 2 0 0 2 -2 0 z m4 0 l2 0 0 2 -2 0 z";
    let skia = "M1 1 L2 1 L2 0 L5 0 L5 1 L7 1 L7 3 L5 3 L5 4 L2 4 L2 3 L1 3 L1 1 Z M2 3 L3 3 L3 1 L2 1 L2 3 Z";
    let o = run(&["boolean", "xor", a, "M2 0 L5 0 L5 4 L2 4 Z", "--against", skia], None);
    assert_eq!((o.status.code(), stdout(&o).as_str()), (Some(0), "agree\n"), "{}", stderr(&o));
    let o = run(&["boolean", "xor", a, "M2 0 L5 0 L5 4 L2 4 Z", "--against", skia, "--json"], None);
    let v: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["verdict"]["notes"], serde_json::json!(["nesting depths [0, 1], not [0, 0]"]));
    assert_eq!(v["verdict"]["problems"], serde_json::json!([]));
}

#[test]
fn against_its_own_json_path_agrees() {
    let (a, b) = (
        "M3 6 C1 5 0 6 0 6 C2.5 6 0.5 8 1 8 C-1 6 0.5 9 3 6 Z",
        "M10 4 C6.5 2.5 5.5 5 7 2 C5 3 10 6 8 4 C10 2.5 11 5 10 4 Z",
    );
    // the arrangement's estimate (not the oracle) needs the larger budget
    let v = json(&["boolean", "union", a, b, "--json", "--max-work", "1e13"]);
    let path = v["path"].as_str().unwrap();
    let o = run(&["boolean", "union", a, b, "--max-work", "1e13", "--against", path], None);
    assert_eq!((o.status.code(), stdout(&o).as_str()), (Some(0), "agree\n"), "{}", stderr(&o));
}

#[test]
fn against_a_cut_corner_is_proved_wrong_twice() {
    let o = run(
        &[
            "boolean",
            "union",
            "M0 0 H2 V2 H0 Z",
            "M1 1 H3 V3 H1 Z",
            "--against",
            "M0 0 H2 V1 H3 V2.5 L2.5 3 H1 V2 H0 Z",
        ],
        None,
    );
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(
        stdout(&o),
        "disagree: the point (2.7515, 2.75) is inside the exact result and outside the float result; the boundaries \
         are more than 0.247 apart, more than the tolerance: the point (2.75, 2.75) of the float boundary is that far \
         from the exact one\n"
    );
}

/// Small overlapping rectangles with integer corners.
fn rectangle() -> impl Strategy<Value = String> {
    (0i64..6, 0i64..6, 1i64..4, 1i64..4).prop_map(|(x, y, w, h)| format!("M{x} {y} H{} V{} H{x} Z", x + w, y + h))
}

/// The contours of a shape, each a list of segments.
fn contours(s: &Shape) -> Vec<Vec<casteljau::RationalBezier<BigRational>>> {
    s.path().contours().to_vec()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// The exact answer spelled differently — contours in another order, each from another
    /// start point, all reversed, a contour through a pinch split in two — is always agreed with.
    #[test]
    fn oracle_agrees_with_every_spelling_of_the_exact_region(
        a in prop::collection::vec(rectangle(), 1..3),
        b in prop::collection::vec(rectangle(), 1..3),
        op in prop::sample::select(vec![BooleanOp::Union, BooleanOp::Intersection, BooleanOp::Difference, BooleanOp::Xor]),
        shift in 0usize..7,
    ) {
        let (sa, sb): (Shape, Shape) = (a.join(" ").parse().unwrap(), b.join(" ").parse().unwrap());
        let o = BooleanOptions::default();
        let inputs = [sa, sb];
        let r = boolean(op, &inputs, o, &Budget::unlimited()).unwrap();
        let exact: Shape = r.path.parse().unwrap();
        let cs = contours(&exact);
        let mut spellings: Vec<Vec<Vec<casteljau::RationalBezier<BigRational>>>> = vec![cs.clone()];
        spellings.push(cs.iter().rev().cloned().collect());
        spellings.push(cs.iter().map(|c| { let mut c = c.clone(); let k = shift % c.len(); c.rotate_left(k); c }).collect());
        let reversed = |s: &casteljau::RationalBezier<BigRational>| {
            let points = s.points().into_iter().rev().map(|p| p.expect("a finite point")).collect();
            casteljau::RationalBezier::new(points, s.weights().iter().rev().cloned().collect()).unwrap()
        };
        spellings.push(cs.iter().map(|c| c.iter().rev().map(reversed).collect()).collect());
        // a contour passing a vertex twice, split there into two contours
        let mut split = vec![];
        for c in &cs {
            let starts: Vec<_> = c.iter().map(|s| s.points()[0].clone()).collect();
            let twice = (0..c.len()).find_map(|i| (i + 1..c.len()).find(|&j| starts[j] == starts[i]).map(|j| (i, j)));
            match twice {
                Some((i, j)) => {
                    split.push(c[i..j].to_vec());
                    split.push(c[j..].iter().chain(&c[..i]).cloned().collect());
                }
                None => split.push(c.clone()),
            }
        }
        spellings.push(split);
        for s in spellings {
            let found = Shape::from_contours(s).unwrap();
            let v = check_against(op, &inputs, o, &r, &found, &ratio(1, 1000), &Budget::unlimited()).unwrap();
            prop_assert!(v.agree, "{:?} {} / {}: {:?}", op, a.join(" "), b.join(" "), v.problems);
            prop_assert!(v.witness.is_none() && v.distance_bound.is_some_and(|d| d <= 1e-3));
        }
        // and a wrong region is caught: a unit square moved into the answer's complement
        let far: Shape = format!("{} M20 20 H21 V21 H20 Z", r.path).parse().unwrap();
        let v = check_against(op, &inputs, o, &r, &far, &ratio(1, 1000), &Budget::unlimited()).unwrap();
        prop_assert!(!v.agree && v.witness.is_some());
    }
}
