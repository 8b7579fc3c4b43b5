//! Shapes: the exact arrangement and boolean operations on the degenerate cases of issue #27,
//! each with its exact answer, and properties that cross-check the boolean result against the
//! inputs' winding numbers (an independent route: `path::winding`).

use casteljau::num::Point2;
use casteljau::path::{ClosedPath, FillRule, PathWinding};
use casteljau::shape::{Arrangement, BooleanOp, BooleanOptions, BooleanResult, Location, Orientation, Shape, boolean};
use casteljau::{Point, RationalBezier, rat, ratio};
use num_rational::BigRational;
use proptest::prelude::*;

fn shape(d: &str) -> Shape {
    d.parse().unwrap_or_else(|e| panic!("{d}: {e}"))
}

fn run(op: BooleanOp, inputs: &[&str], fill: FillRule) -> BooleanResult {
    let shapes: Vec<Shape> = inputs.iter().map(|d| shape(d)).collect();
    boolean(op, &shapes, BooleanOptions { fill, orientation: Orientation::Ccw }, &casteljau::work::Budget::unlimited())
        .unwrap_or_else(|e| panic!("{inputs:?}: {e}"))
}

fn nz(op: BooleanOp, inputs: &[&str]) -> BooleanResult {
    run(op, inputs, FillRule::NonZero)
}

fn area(r: &BooleanResult) -> BigRational {
    r.area.clone().expect("a rational area")
}

fn p(x: BigRational, y: BigRational) -> Point2<BigRational> {
    Point2::new(x, y)
}

const SQUARE: &str = "M0 0 L2 0 L2 2 L0 2 Z";

#[test]
fn squares_sharing_an_edge_unite_into_one_contour() {
    let r = nz(BooleanOp::Union, &["M0 0 H1 V1 H0 Z", "M1 0 H2 V1 H1 Z"]);
    assert_eq!(r.contours, 1);
    assert_eq!(area(&r), rat(2));
    assert_eq!(r.path, "M0 0L1 0L2 0L2 1L1 1L0 1Z"); // pieces of both squares
    assert_eq!(r.orientation, vec![Orientation::Ccw]);
    // the intersection is the shared edge only: empty
    assert_eq!(nz(BooleanOp::Intersection, &["M0 0 H1 V1 H0 Z", "M1 0 H2 V1 H1 Z"]).contours, 0);
}

#[test]
fn a_shape_with_itself() {
    let u = nz(BooleanOp::Union, &[SQUARE, SQUARE]);
    assert_eq!((u.contours, area(&u)), (1, rat(4)));
    assert!(u.pieces[0].iter().all(|p| p.input == 0), "A ∪ A is A, by A's own pieces");
    let i = nz(BooleanOp::Intersection, &[SQUARE, SQUARE]);
    assert_eq!((i.contours, area(&i)), (1, rat(4)));
    for op in [BooleanOp::Difference, BooleanOp::Xor] {
        let r = nz(op, &[SQUARE, SQUARE]);
        assert_eq!((r.contours, area(&r), r.path.as_str()), (0, rat(0), ""), "{op:?}");
    }
    // reversed copy: the same region
    let rev = "M0 0 L0 2 L2 2 L2 0 Z";
    assert_eq!(nz(BooleanOp::Xor, &[SQUARE, rev]).contours, 0);
    assert_eq!(area(&nz(BooleanOp::Union, &[SQUARE, rev])), rat(4));
}

#[test]
fn contours_touching_at_one_point_stay_two() {
    let r = nz(BooleanOp::Union, &["M0 0 H1 V1 H0 Z", "M1 1 H2 V2 H1 Z"]);
    assert_eq!(r.contours, 2);
    assert_eq!(r.parents, vec![None, None]);
    assert_eq!(area(&r), rat(2));
    assert_eq!(nz(BooleanOp::Intersection, &["M0 0 H1 V1 H0 Z", "M1 1 H2 V2 H1 Z"]).contours, 0);
}

#[test]
fn a_hole_touching_its_outer_contour_is_one_contour_through_the_pinch() {
    // a triangle hole (clockwise) whose apex touches the outer square's bottom side at (2, 0)
    let r = nz(BooleanOp::Simplify, &["M0 0 L4 0 L4 4 L0 4 Z M2 0 L1 2 L3 2 Z"]);
    assert_eq!(area(&r), rat(16) - rat(2));
    assert_eq!(r.contours, 1, "{}", r.path);
    // the same by difference
    let d = nz(BooleanOp::Difference, &["M0 0 L4 0 L4 4 L0 4 Z", "M2 0 L3 2 L1 2 Z"]);
    assert_eq!((d.contours, area(&d)), (1, rat(14)));
}

fn circle(cx: i64, cy: i64, r: i64) -> Shape {
    // four quarter arcs, weights 1, 1, 2 at the corners (x² + y² = r² exactly)
    let pt = |x: i64, y: i64| Point::new(vec![rat(cx + x), rat(cy + y)]);
    let w = vec![rat(1), rat(1), rat(2)];
    let arc = |a, b, c| RationalBezier::new(vec![a, b, c], w.clone()).unwrap();
    Shape::from_contours(vec![vec![
        arc(pt(r, 0), pt(r, r), pt(0, r)),
        arc(pt(0, r), pt(-r, r), pt(-r, 0)),
        arc(pt(-r, 0), pt(-r, -r), pt(0, -r)),
        arc(pt(0, -r), pt(r, -r), pt(r, 0)),
    ]])
    .unwrap()
}

#[test]
fn tangent_circles_touch_at_one_point() {
    let (a, b) = (circle(0, 0, 1), circle(2, 0, 1));
    let o = BooleanOptions::default();
    let u = boolean(BooleanOp::Union, &[a.clone(), b.clone()], o, &casteljau::work::Budget::unlimited()).unwrap();
    assert_eq!(u.contours, 2);
    assert!(u.area.is_none(), "a disc's area is not rational");
    assert!((u.area_float - 2.0 * std::f64::consts::PI).abs() < 1e-9, "{}", u.area_float);
    assert_eq!(
        boolean(BooleanOp::Intersection, &[a.clone(), b.clone()], o, &casteljau::work::Budget::unlimited())
            .unwrap()
            .contours,
        0
    );
    // internally tangent: a circle of radius 2 around (1, 0) touches the unit circle at (-1, 0)
    let big = circle(1, 0, 2);
    let d =
        boolean(BooleanOp::Difference, &[big.clone(), a.clone()], o, &casteljau::work::Budget::unlimited()).unwrap();
    assert_eq!(d.contours, 1, "the crescent is one contour through the tangency");
    assert!((d.area_float - 3.0 * std::f64::consts::PI).abs() < 1e-9);
    let arr = Arrangement::new(&[big, a], &casteljau::work::Budget::unlimited()).unwrap();
    let v = arr.vertices().iter().position(|v| v.point_float == [-1.0, 0.0]).expect("a vertex at (-1, 0)");
    assert_eq!(arr.locate(&p(rat(-1), rat(0))).unwrap(), Location::Vertex { vertex: v });
}

#[test]
fn a_curve_overlapping_part_of_another() {
    // A: the lens under the cubic 0 0, 1 3, 3 3, 4 0 and its chord; B: its left half (the cubic
    // split at 1/2: 0 0, 1/2 3/2, 5/4 9/4, 2 9/4) closed by the line back to the origin
    let a = "M0 0 C1 3 3 3 4 0 Z";
    let b = "M0 0 C0.5 1.5 1.25 2.25 2 2.25 Z";
    let u = nz(BooleanOp::Union, &[a, b]);
    let (ua, ia) = (area(&u), area(&nz(BooleanOp::Intersection, &[a, b])));
    let (aa, ba) = (area(&nz(BooleanOp::Simplify, &[a])), area(&nz(BooleanOp::Simplify, &[b])));
    assert_eq!(ua.clone() + ia.clone(), aa.clone() + ba.clone());
    assert_eq!(u.contours, 1);
    assert_eq!(ua, aa, "B lies inside A");
    assert_eq!(ia, ba);
    // the arrangement merges the shared arc: one edge carrying a piece of each input
    let arr = Arrangement::new(&[shape(a), shape(b)], &casteljau::work::Budget::unlimited()).unwrap();
    let shared: Vec<_> = arr.edges().into_iter().filter(|e| e.pieces.len() == 2).collect();
    assert_eq!(shared.len(), 1);
    assert_eq!((shared[0].pieces[0].to.to_string(), shared[0].pieces[1].to.to_string()), ("1/2".into(), "1".into()));
}

#[test]
fn a_contour_through_another_vertex() {
    // the diamond's left corner is the square's right side midpoint (2, 1)
    let r = nz(BooleanOp::Union, &[SQUARE, "M2 1 L3 0 L4 1 L3 2 Z"]);
    assert_eq!((r.contours, area(&r)), (2, rat(6)));
    // a triangle whose side passes through the square's corner (2, 2), overlapping it
    let t = nz(BooleanOp::Union, &[SQUARE, "M3 1 L1 3 L1 1 Z"]);
    assert_eq!((t.contours, area(&t)), (1, rat(5)));
}

#[test]
fn three_curves_through_one_point() {
    // three lines through (1, 1) in three triangles
    let tris = ["M0 0 L2 2 L2 0 Z", "M0 2 L2 0 L0 0 Z", "M1 0 L1 2 L0 2 Z"];
    let shapes: Vec<Shape> = tris.iter().map(|d| shape(d)).collect();
    let arr = Arrangement::new(&shapes, &casteljau::work::Budget::unlimited()).unwrap();
    let center = arr.vertices().into_iter().find(|v| v.point_float == [1.0, 1.0]).expect("a vertex at (1, 1)");
    assert_eq!(center.degree, 6);
    let faces = arr.faces().unwrap();
    // Euler: V − E + F = 2 for a connected arrangement
    assert_eq!(arr.vertices().len() as i64 - arr.edges().len() as i64 + faces.len() as i64, 2);
    let u = nz(BooleanOp::Union, &[tris[0], tris[1]]);
    assert_eq!((u.contours, area(&u)), (1, rat(3)));
}

#[test]
fn figure_eight_under_both_rules() {
    let eight = "M0 0 L2 2 L2 0 L0 2 Z";
    for fill in [FillRule::NonZero, FillRule::EvenOdd] {
        let r = run(BooleanOp::Simplify, &[eight], fill);
        assert_eq!((r.contours, area(&r)), (2, rat(2)), "{fill}");
        assert_eq!(r.orientation, vec![Orientation::Ccw, Orientation::Ccw]);
    }
}

#[test]
fn nested_holes_by_orientation_and_rule() {
    let outer = "M0 0 L4 0 L4 4 L0 4 Z";
    let (cw, ccw) = ("M1 1 L1 3 L3 3 L3 1 Z", "M1 1 L3 1 L3 3 L1 3 Z");
    let hole = nz(BooleanOp::Simplify, &[&format!("{outer} {cw}")]);
    assert_eq!((hole.contours, area(&hole)), (2, rat(12)));
    assert_eq!(hole.parents, vec![None, Some(0)]);
    assert_eq!(hole.orientation, vec![Orientation::Ccw, Orientation::Cw]);
    let filled = nz(BooleanOp::Simplify, &[&format!("{outer} {ccw}")]);
    assert_eq!((filled.contours, area(&filled)), (1, rat(16)));
    let eo = run(BooleanOp::Simplify, &[&format!("{outer} {ccw}")], FillRule::EvenOdd);
    assert_eq!((eo.contours, area(&eo)), (2, rat(12)));
    // an island in the hole
    let island = "M1.5 1.5 L2.5 1.5 L2.5 2.5 L1.5 2.5 Z";
    let r = nz(BooleanOp::Simplify, &[&format!("{outer} {cw} {island}")]);
    assert_eq!(r.parents, vec![None, Some(0), Some(1)]);
    assert_eq!(area(&r), rat(13));
    // clockwise output
    let o = BooleanOptions { fill: FillRule::NonZero, orientation: Orientation::Cw };
    let c = boolean(BooleanOp::Simplify, &[shape(&format!("{outer} {cw}"))], o, &casteljau::work::Budget::unlimited())
        .unwrap();
    assert_eq!(c.orientation, vec![Orientation::Cw, Orientation::Ccw]);
    assert_eq!(area(&c), rat(-12));
}

#[test]
fn cusps_collinear_cubics_and_zero_length_segments() {
    // a cubic with a cusp at t = 1/2 (control polygon crossed), closed by its chord
    let cusp = "M0 0 C4 4 0 4 4 0 Z";
    let r = nz(BooleanOp::Simplify, &[cusp]);
    assert_eq!(r.contours, 1);
    assert_eq!(area(&r), ratio(24, 5));
    // a cubic on the x-axis that runs past its end and back, and the segment back
    let collinear = "M0 0 C3 0 -1 0 2 0 L2 1 L0 1 Z";
    let c = nz(BooleanOp::Simplify, &[collinear]);
    assert_eq!((c.contours, area(&c)), (1, rat(2)));
    // zero-length segments are ignored for the region
    let z = nz(BooleanOp::Simplify, &["M0 0 L0 0 L2 0 L2 2 L2 2 L0 2 Z"]);
    assert_eq!((z.contours, area(&z)), (1, rat(4)));
}

fn inside(path: &ClosedPath, q: &Point2<BigRational>, fill: FillRule) -> Option<bool> {
    match path.winding(q, &casteljau::work::Budget::unlimited()).unwrap() {
        PathWinding::Off(w) => Some(w.inside(fill)),
        PathWinding::OnBoundary { .. } => None,
    }
}

/// A closed polygon with small integer vertices, possibly self-intersecting.
fn polygon() -> impl Strategy<Value = Vec<(i64, i64)>> {
    prop::collection::vec((-4i64..=4, -4i64..=4), 3..=6)
}

fn to_shape(poly: &[(i64, i64)]) -> Option<Shape> {
    let pts: Vec<Point2<BigRational>> = poly.iter().map(|&(x, y)| p(rat(x), rat(y))).collect();
    Shape::polygons(vec![pts]).ok()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// inside(A op B) = op(inside(A), inside(B)) at rational points off both boundaries, with
    /// the inputs' winding numbers from `path::winding` and the result's from its pieces.
    #[test]
    fn membership_matches_the_operation(a in polygon(), b in polygon(), qs in prop::collection::vec((-9i64..=9, -9i64..=9), 12), even in any::<bool>()) {
        let (Some(sa), Some(sb)) = (to_shape(&a), to_shape(&b)) else { return Ok(()) };
        let fill = if even { FillRule::EvenOdd } else { FillRule::NonZero };
        for op in [BooleanOp::Union, BooleanOp::Intersection, BooleanOp::Difference, BooleanOp::Xor] {
            let r = boolean(op, &[sa.clone(), sb.clone()], BooleanOptions { fill, orientation: Orientation::Ccw }, &casteljau::work::Budget::unlimited()).unwrap();
            for &(x, y) in &qs {
                let q = p(ratio(x, 2) + ratio(1, 7), ratio(y, 2) + ratio(1, 11));
                let (Some(ia), Some(ib)) = (inside(sa.path(), &q, fill), inside(sb.path(), &q, fill)) else { continue };
                let got = r.contains(&q).unwrap();
                prop_assert_eq!(got, Some(op.apply(ia, ib)), "{:?} at {}", op, q);
            }
        }
        // area(A ∪ B) + area(A ∩ B) = area(A) + area(B), exactly
        let o = BooleanOptions { fill, orientation: Orientation::Ccw };
        let ar = |op, s: &[Shape]| boolean(op, s, o, &casteljau::work::Budget::unlimited()).unwrap().area.unwrap();
        let both = [sa.clone(), sb.clone()];
        prop_assert_eq!(ar(BooleanOp::Union, &both) + ar(BooleanOp::Intersection, &both),
            ar(BooleanOp::Simplify, std::slice::from_ref(&sa)) + ar(BooleanOp::Simplify, std::slice::from_ref(&sb)));
    }

    /// Every face's winding numbers equal `winding` at a rational point inside it.
    #[test]
    fn face_windings_match_winding_at_a_point(a in polygon(), b in polygon(), qs in prop::collection::vec((-9i64..=9, -9i64..=9), 12)) {
        let (Some(sa), Some(sb)) = (to_shape(&a), to_shape(&b)) else { return Ok(()) };
        let arr = Arrangement::new(&[sa.clone(), sb.clone()], &casteljau::work::Budget::unlimited()).unwrap();
        for &(x, y) in &qs {
            let q = p(ratio(x, 2) + ratio(1, 7), ratio(y, 2) + ratio(1, 11));
            if let Location::Face { winding, .. } = arr.locate(&q).unwrap() {
                for (i, s) in [&sa, &sb].iter().enumerate() {
                    let PathWinding::Off(w) = s.path().winding(&q, &casteljau::work::Budget::unlimited()).unwrap() else { panic!("off the edges") };
                    prop_assert_eq!(winding[i], w.winding());
                }
            }
        }
    }
}

#[test]
fn the_oracle_accepts_a_right_float_answer_and_catches_wrong_ones() {
    use casteljau::oracle::check_against;
    use casteljau::work::Budget;
    let (a, b) = (shape("M0 0 H2 V2 H0 Z"), shape("M1 1 H3 V3 H1 Z"));
    let o = BooleanOptions::default();
    let exact = boolean(BooleanOp::Union, &[a.clone(), b.clone()], o, &casteljau::work::Budget::unlimited()).unwrap();
    let tol = ratio(1, 1000);
    let check = |d: &str| {
        check_against(BooleanOp::Union, &[a.clone(), b.clone()], o, &exact, &shape(d), &tol, &Budget::unlimited())
            .unwrap()
    };
    assert!(check("M0 0 H2 V1 H3 V3 H1 V2 H0 Z").agree);
    // off by 1e-4 at one corner: within the tolerance
    assert!(check("M0 0 H2 V1 H3 V3.0001 H1 V2 H0 Z").agree);
    // off by 0.01: a witness farther than tol from the exact boundary, and the distance bound
    let v = check("M0 0 H2 V1 H3 V3.01 H1 V2 H0 Z");
    assert!(!v.agree);
    let w = v.witness.expect("a witness");
    assert!(!w.inside_exact && w.inside_found);
    assert!(v.distance_bound.is_none() && v.distance_at_least.is_some_and(|d| d > 1e-3), "{:?}", v.distance_at_least);
    // a dropped contour: the count and a witness
    let v = check("M0 0 H2 V2 H0 Z");
    assert_eq!((v.contours, v.contours_found), (1, 1));
    assert!(!v.agree && v.witness.is_some());
    // an extra contour far away
    let v = check("M0 0 H2 V1 H3 V3 H1 V2 H0 Z M10 10 H11 V11 H10 Z");
    assert_eq!(v.contours_found, 2);
    assert!(!v.agree);
}
