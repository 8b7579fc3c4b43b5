//! Properties of the exact boolean operations and arrangement on curved shapes (issue #27 item 9):
//! random closed contours of lines, quadratics and cubics with small integer or half-integer
//! control points (one or two contours per shape), and circles made of rational quadratics.
//!
//! The independent route for membership is `ClosedPath::winding` (`intersect::winding`) with
//! `FillRule::contains`; the result's membership comes from its exact pieces
//! (`BooleanResult::contains`). Sample points are rational with denominators 14 and 22, so they
//! never lie on the half-integer grid, but they may still lie on a curve: a point on any
//! boundary is skipped, never guessed.
//!
//! A refusal documented by `Arrangement::faces` (two curves leaving a vertex tangentially where
//! their order cannot be decided exactly) skips the case; any other error fails it.

use casteljau::intersect::{ClosedPath, FillRule, PathWinding};
use casteljau::shape::{Arrangement, BooleanOp, BooleanOptions, BooleanResult, Direction, Location, Shape, boolean};
use casteljau::{Point, RationalBezier, rat, ratio};
use num_rational::BigRational;
use proptest::prelude::*;

type Q = BigRational;
/// A polynomial segment: its control points.
type Seg = Vec<(Q, Q)>;
type Contour = Vec<Seg>;
/// A shape: its contours.
type Sh = Vec<Contour>;

const OPS: [BooleanOp; 4] = [BooleanOp::Union, BooleanOp::Intersection, BooleanOp::Difference, BooleanOp::Xor];
const FILLS: [FillRule; 2] = [FillRule::NonZero, FillRule::EvenOdd];

fn pt(x: &Q, y: &Q) -> Point<Q> {
    Point::new(vec![x.clone(), y.clone()])
}

fn bezier(s: &Seg) -> RationalBezier<Q> {
    RationalBezier::new(s.iter().map(|(x, y)| pt(x, y)).collect(), vec![rat(1); s.len()]).unwrap()
}

fn to_shape(sh: &Sh) -> Shape {
    Shape::from_contours(sh.iter().map(|c| c.iter().map(bezier).collect()).collect())
        .unwrap_or_else(|e| panic!("{}: {e}", svg(sh)))
}

/// SVG path data of a shape (for messages and the minimal cases).
fn svg(sh: &Sh) -> String {
    let mut out = String::new();
    for c in sh {
        out.push_str(&format!("M{} {} ", c[0][0].0, c[0][0].1));
        for s in c {
            out.push_str(["", "L", "Q", "C"][s.len() - 1]);
            let rest: Vec<String> = s[1..].iter().map(|(x, y)| format!("{x} {y}")).collect();
            out.push_str(&rest.join(" "));
            out.push(' ');
        }
        out.push_str("Z ");
    }
    out
}

/// One coordinate: an integer in −6..=6 three times in four, else a half-integer.
fn coord() -> impl Strategy<Value = Q> {
    prop_oneof![3 => (-6i64..=6).prop_map(rat), 1 => (-12i64..=12).prop_map(|v| ratio(v, 2))]
}

/// A closed contour of 2–5 segments, each a line, a quadratic or a cubic.
fn contour() -> impl Strategy<Value = Contour> {
    (2usize..=5).prop_flat_map(|n| {
        (
            prop::collection::vec((coord(), coord()), n),
            prop::collection::vec(1usize..=3, n),
            prop::collection::vec((coord(), coord()), 2 * n),
        )
            .prop_map(move |(verts, degs, ctrl)| {
                (0..n)
                    .map(|i| {
                        let mut s = vec![verts[i].clone()];
                        s.extend(ctrl[2 * i..2 * i + degs[i] - 1].iter().cloned());
                        s.push(verts[(i + 1) % n].clone());
                        s
                    })
                    .collect()
            })
    })
}

/// One contour three times in four, else two.
fn shape() -> impl Strategy<Value = Sh> {
    prop_oneof![3 => contour().prop_map(|c| vec![c]), 1 => prop::collection::vec(contour(), 2)]
}

/// Rational sample points off the half-integer grid, in about −7.5..7.5.
fn points(n: usize) -> impl Strategy<Value = Vec<Point<Q>>> {
    prop::collection::vec((-15i64..=14, -15i64..=14), n)
        .prop_map(|v| v.into_iter().map(|(x, y)| pt(&(ratio(x, 2) + ratio(1, 7)), &(ratio(y, 2) + ratio(1, 11)))).collect())
}

fn fill_rule() -> impl Strategy<Value = FillRule> {
    prop_oneof![Just(FillRule::NonZero), Just(FillRule::EvenOdd)]
}

/// The operation, or `None` for a documented refusal (a tangential vertex whose order around
/// it cannot be decided exactly).
fn run(op: BooleanOp, inputs: &[Shape], fill: FillRule) -> Option<BooleanResult> {
    match boolean(op, inputs, BooleanOptions { fill, direction: Direction::Ccw }) {
        Ok(r) => Some(r),
        Err(e) if e.to_string().contains("tangentially") => None,
        Err(e) => {
            let paths: Vec<String> = inputs.iter().map(|s| format!("{:?}", s.path().contours())).collect();
            panic!("{op:?} {fill}: {e}\n{paths:#?}")
        }
    }
}

/// Inside by the fill rule, or `None` on the boundary.
fn inside(path: &ClosedPath, q: &Point<Q>, fill: FillRule) -> Option<bool> {
    match path.winding(q).unwrap() {
        PathWinding::Off(w) => Some(w.inside(fill)),
        PathWinding::OnBoundary { .. } => None,
    }
}

/// `r` holds exactly where `op(inside A, inside B)` does, at the sample points off both
/// boundaries; returns how many points were decided.
fn check_membership(
    r: &BooleanResult,
    op: BooleanOp,
    inputs: &[&ClosedPath],
    fill: FillRule,
    qs: &[Point<Q>],
) -> std::result::Result<usize, TestCaseError> {
    let mut n = 0;
    for q in qs {
        let Some(ia) = inside(inputs[0], q, fill) else { continue };
        let ib = match inputs.get(1) {
            Some(b) => match inside(b, q, fill) {
                Some(v) => v,
                None => continue,
            },
            None => false,
        };
        prop_assert_eq!(r.contains(q).unwrap(), Some(op.apply(ia, ib)), "{:?} {} at {}", op, fill, q);
        n += 1;
    }
    Ok(n)
}

/// Equal areas: exact when both are rational, else within 1e-9 relative of the floats.
fn same_area(a: &BooleanResult, b: &BooleanResult, factor: &Q) -> std::result::Result<(), TestCaseError> {
    match (&a.area, &b.area) {
        (Some(x), Some(y)) => prop_assert_eq!(x * factor, y.clone()),
        _ => {
            let f = num_traits::ToPrimitive::to_f64(factor).unwrap();
            let (x, y) = (a.area_float * f, b.area_float);
            prop_assert!((x - y).abs() <= 1e-9 * x.abs().max(y.abs()).max(1.0), "{} vs {}", x, y);
        }
    }
    Ok(())
}

/// Per contour, its nesting depth from `parents`, sorted.
fn depths(r: &BooleanResult) -> Vec<usize> {
    let depth = |mut i: usize| {
        let mut d = 0;
        while let Some(p) = r.parents[i] {
            d += 1;
            i = p;
            assert!(d <= r.parents.len(), "a cycle in parents");
        }
        d
    };
    let mut v: Vec<usize> = (0..r.contours).map(depth).collect();
    v.sort_unstable();
    v
}

/// Outer contours (even depth) counter-clockwise, holes clockwise.
fn check_orientation(r: &BooleanResult) -> std::result::Result<(), TestCaseError> {
    for i in 0..r.contours {
        let mut d = 0;
        let mut j = i;
        while let Some(p) = r.parents[j] {
            d += 1;
            j = p;
        }
        let want = if d % 2 == 0 { Direction::Ccw } else { Direction::Cw };
        prop_assert_eq!(r.orientation[i], want, "contour {} at depth {}", i, d);
    }
    Ok(())
}

/// Same membership (on the boundary included) at every sample point.
fn same_region(a: &BooleanResult, b: &BooleanResult, qs: &[Point<Q>]) -> std::result::Result<(), TestCaseError> {
    for q in qs {
        prop_assert_eq!(a.contains(q).unwrap(), b.contains(q).unwrap(), "at {}", q);
    }
    Ok(())
}

/// An affine map `x ↦ s·D x + v` with `D` one of the eight symmetries of the square.
#[derive(Clone, Debug)]
struct Affine {
    m: [[Q; 2]; 2],
    v: (Q, Q),
    /// `|det|`.
    scale: Q,
}

impl Affine {
    fn apply(&self, (x, y): &(Q, Q)) -> (Q, Q) {
        (&self.m[0][0] * x + &self.m[0][1] * y + &self.v.0, &self.m[1][0] * x + &self.m[1][1] * y + &self.v.1)
    }
    fn point(&self, q: &Point<Q>) -> Point<Q> {
        let (x, y) = self.apply(&(q.coords[0].clone(), q.coords[1].clone()));
        pt(&x, &y)
    }
    fn shape(&self, sh: &Sh) -> Sh {
        sh.iter().map(|c| c.iter().map(|s| s.iter().map(|p| self.apply(p)).collect()).collect()).collect()
    }
}

fn affine() -> impl Strategy<Value = Affine> {
    let scales = prop_oneof![Just((1, 1)), Just((-1, 1)), Just((2, 1)), Just((-1, 2)), Just((3, 2)), Just((-5, 3))];
    (0usize..8, scales, (-8i64..=8, -8i64..=8)).prop_map(|(k, (sn, sd), (vx, vy))| {
        let s = ratio(sn, sd);
        let z = rat(0);
        // rotations by k·90°, then a mirror in the x-axis for k ≥ 4
        let (c, si) = [(1, 0), (0, 1), (-1, 0), (0, -1)][k % 4];
        let mirror = if k >= 4 { -1 } else { 1 };
        let m = [
            [&s * rat(c), &s * rat(-si * mirror)],
            [&s * rat(si), &s * rat(c * mirror)],
        ];
        let _ = z;
        Affine { m, v: (ratio(vx, 4), ratio(vy, 3)), scale: &s * &s }
    })
}

fn reversed(c: &Contour) -> Contour {
    c.iter().rev().map(|s| s.iter().rev().cloned().collect()).collect()
}

fn bezier_points(b: &RationalBezier<Q>) -> Seg {
    b.points().into_iter().map(|p| {
        let p = p.expect("a finite point");
        (p.coords[0].clone(), p.coords[1].clone())
    }).collect()
}

/// The polynomial segment restricted to `[lo, hi]` (exact de Casteljau).
fn sub_segment(s: &Seg, lo: &Q, hi: &Q) -> Seg {
    let mut c = bezier(s);
    if *hi != rat(1) {
        c = c.subdivide(hi).unwrap().0;
    }
    if *lo != rat(0) {
        c = c.subdivide(&(lo / hi)).unwrap().1;
    }
    bezier_points(&c)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// 1. At rational points off all boundaries, `inside(A op B) = op(inside A, inside B)` for
    /// the four binary operations and simplify of each input, under both fill rules.
    #[test]
    fn membership(a in shape(), b in shape(), qs in points(10)) {
        let (sa, sb) = (to_shape(&a), to_shape(&b));
        for fill in FILLS {
            for op in OPS {
                let Some(r) = run(op, &[sa.clone(), sb.clone()], fill) else { continue };
                check_membership(&r, op, &[sa.path(), sb.path()], fill, &qs)?;
            }
            for s in [&sa, &sb] {
                let Some(r) = run(BooleanOp::Simplify, std::slice::from_ref(s), fill) else { continue };
                check_membership(&r, BooleanOp::Simplify, &[s.path()], fill, &qs)?;
                check_orientation(&r)?;
            }
        }
    }
}
