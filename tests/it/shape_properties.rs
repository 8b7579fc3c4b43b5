//! Properties of the exact boolean operations and arrangement on curved shapes (issue #27 item 9):
//! random closed contours of lines, quadratics and cubics with small integer or half-integer
//! control points (one or two contours per shape), and circles made of rational quadratics.
//!
//! The independent route for membership is `ClosedPath::winding` (`path::winding`) with
//! `FillRule::contains`; the result's membership comes from its exact pieces
//! (`BooleanResult::contains`). Sample points are rational with denominators 14 and 22, so they
//! never lie on the half-integer grid, but they may still lie on a curve: a point on any
//! boundary is skipped, never guessed.
//!
//! Every case must be answered: the order of curves leaving a vertex tangentially is decided at
//! cusps and irrational vertices too, so any error fails the case.

use casteljau::num::Point2;
use casteljau::path::{ClosedPath, FillRule, PathWinding};
use casteljau::shape::{Arrangement, BooleanOp, BooleanOptions, BooleanResult, Location, Orientation, Shape, boolean};
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

/// The number of cases: `n`, or `SHAPE_PROPERTY_CASES` from the environment (for longer runs).
fn cases(n: u32) -> u32 {
    std::env::var("SHAPE_PROPERTY_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(n)
}

fn pt(x: &Q, y: &Q) -> Point<Q> {
    Point::new(vec![x.clone(), y.clone()])
}

/// A query point.
fn qpt(x: &Q, y: &Q) -> Point2<Q> {
    Point2::new(x.clone(), y.clone())
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

/// SVG path data of a shape of polynomial segments.
fn shape_svg(s: &Shape) -> String {
    let sh: Sh = s.path().contours().iter().map(|c| c.iter().map(bezier_points).collect()).collect();
    svg(&sh)
}

/// One coordinate: an integer in −m..=m three times in four, else a half-integer (none when
/// `halves` is false).
fn coord(m: i64, halves: bool) -> impl Strategy<Value = Q> {
    let h = if halves { 1 } else { 0 };
    prop_oneof![3 => (-m..=m).prop_map(rat), h => (-2 * m..=2 * m).prop_map(|v| ratio(v, 2))]
}

/// A closed contour of 2–5 segments, each a line, a quadratic or a cubic (2 : 2 : 1: cubic
/// against cubic is the slow case).
fn contour(m: i64, halves: bool) -> impl Strategy<Value = Contour> {
    (2usize..=5).prop_flat_map(move |n| {
        (
            prop::collection::vec((coord(m, halves), coord(m, halves)), n),
            prop::collection::vec(prop_oneof![2 => Just(1usize), 2 => Just(2), 1 => Just(3)], n),
            prop::collection::vec((coord(m, halves), coord(m, halves)), 2 * n),
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

/// One contour three times in four, else two; coordinates in −6..=6 and halves.
fn shape() -> impl Strategy<Value = Sh> {
    shape_on(6, true)
}

fn shape_on(m: i64, halves: bool) -> impl Strategy<Value = Sh> {
    prop_oneof![3 => contour(m, halves).prop_map(|c| vec![c]), 1 => prop::collection::vec(contour(m, halves), 2)]
}

/// Integer coordinates in −2..=2: shared vertices, overlapping and tangent segments are common.
fn coarse_shape() -> impl Strategy<Value = Sh> {
    shape_on(2, false)
}

/// Rational sample points off the half-integer grid, in about −7.5..7.5.
fn points(n: usize) -> impl Strategy<Value = Vec<Point2<Q>>> {
    prop::collection::vec((-15i64..=14, -15i64..=14), n).prop_map(|v| {
        v.into_iter().map(|(x, y)| qpt(&(ratio(x, 2) + ratio(1, 7)), &(ratio(y, 2) + ratio(1, 11)))).collect()
    })
}

fn fill_rule() -> impl Strategy<Value = FillRule> {
    prop_oneof![Just(FillRule::NonZero), Just(FillRule::EvenOdd)]
}

/// The operation (always answered: `Some`; the cases keep their `let Some(..) else` shape).
fn run(op: BooleanOp, inputs: &[Shape], fill: FillRule) -> Option<BooleanResult> {
    match boolean(
        op,
        inputs,
        BooleanOptions { fill, orientation: Orientation::Ccw },
        &casteljau::work::Budget::unlimited(),
    ) {
        Ok(r) => Some(r),
        Err(e) => {
            let paths: Vec<String> = inputs.iter().map(shape_svg).collect();
            panic!("{op:?} {fill}: {e}\n{paths:#?}")
        }
    }
}

/// Inside by the fill rule, or `None` on the boundary.
fn inside(path: &ClosedPath, q: &Point2<Q>, fill: FillRule) -> Option<bool> {
    match path.winding(q, &casteljau::work::Budget::unlimited()).unwrap() {
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
    qs: &[Point2<Q>],
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
        let want = if d % 2 == 0 { Orientation::Ccw } else { Orientation::Cw };
        prop_assert_eq!(r.orientation[i], want, "contour {} at depth {}", i, d);
    }
    Ok(())
}

/// Same membership (on the boundary included) at every sample point.
fn same_region(a: &BooleanResult, b: &BooleanResult, qs: &[Point2<Q>]) -> std::result::Result<(), TestCaseError> {
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
    fn point(&self, q: &Point2<Q>) -> Point2<Q> {
        let (x, y) = self.apply(&(q.x.clone(), q.y.clone()));
        qpt(&x, &y)
    }
    fn shape(&self, sh: &Sh) -> Sh {
        sh.iter().map(|c| c.iter().map(|s| s.iter().map(|p| self.apply(p)).collect()).collect()).collect()
    }
}

fn affine() -> impl Strategy<Value = Affine> {
    let scales = prop_oneof![Just((1, 1)), Just((-1, 1)), Just((2, 1)), Just((-1, 2)), Just((3, 2)), Just((-5, 3))];
    (0usize..8, scales, (-8i64..=8, -8i64..=8)).prop_map(|(k, (sn, sd), (vx, vy))| {
        let s = ratio(sn, sd);
        // rotations by k·90°, then a mirror in the x-axis for k ≥ 4
        let (c, si) = [(1, 0), (0, 1), (-1, 0), (0, -1)][k % 4];
        let mirror = if k >= 4 { -1 } else { 1 };
        let m = [[&s * rat(c), &s * rat(-si * mirror)], [&s * rat(si), &s * rat(c * mirror)]];
        Affine { m, v: (ratio(vx, 4), ratio(vy, 3)), scale: &s * &s }
    })
}

fn reversed(c: &Contour) -> Contour {
    c.iter().rev().map(|s| s.iter().rev().cloned().collect()).collect()
}

fn bezier_points(b: &RationalBezier<Q>) -> Seg {
    b.points()
        .into_iter()
        .map(|p| {
            let p = p.expect("a finite point");
            (p.coords[0].clone(), p.coords[1].clone())
        })
        .collect()
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
    #![proptest_config(ProptestConfig { cases: cases(24), ..ProptestConfig::default() })]

    /// 1. At rational points off all boundaries, `inside(A op B) = op(inside A, inside B)` for
    /// the four binary operations and simplify, under either fill rule; outer contours ccw,
    /// holes cw. And 5. (below): the area identities, on the same operations of the same pair
    /// (`membership_and_area_identities_of`: each operation is computed once for both).
    #[test]
    fn membership_and_area_identities(a in shape(), b in shape(), fill in fill_rule(), qs in points(10)) {
        membership_and_area_identities_of(&a, &b, fill, &qs).map_err(|e| named(e, &a, &b))?;
    }

    /// 1′ and 5′. The same on a coarse integer grid (−2..=2): degenerate cases are the rule, and
    /// most areas are rational. The membership property failed in nearly every run of 24 cases
    /// on the bug of `a_line_and_a_degenerate_quadratic_on_one_segment_bound_nothing` (a
    /// quadratic or cubic with a control point on an end, overlapping a line toward negative x);
    /// with such segments filtered out it passed 300 cases. Run it with `--ignored`.
    #[test]
    fn membership_and_area_identities_on_a_coarse_grid(
        a in coarse_shape(), b in coarse_shape(), fill in fill_rule(), qs in coarse_points(10),
    ) {
        membership_and_area_identities_of(&a, &b, fill, &qs).map_err(|e| named(e, &a, &b))?;
    }
}

/// The failure with both inputs as SVG path data.
fn named(e: TestCaseError, a: &Sh, b: &Sh) -> TestCaseError {
    TestCaseError::fail(format!("{e}\nA: {}\nB: {}", svg(a), svg(b)))
}

/// Rational sample points off the integer grid in about −2.5..2.5.
fn coarse_points(n: usize) -> impl Strategy<Value = Vec<Point2<Q>>> {
    prop::collection::vec((-10i64..=9, -10i64..=9), n).prop_map(|v| {
        v.into_iter().map(|(x, y)| qpt(&(ratio(x, 4) + ratio(1, 7)), &(ratio(y, 4) + ratio(1, 11)))).collect()
    })
}

/// Properties 1 (membership and orientation of each of the four operations and of simplify of
/// A, each skipped alone when refused) and 5 (the area identities, when neither simplify nor any
/// operation is refused) on one pair, every operation computed once for both. They were two
/// properties drawing pairs of their own, each run computing the same operations again.
fn membership_and_area_identities_of(
    a: &Sh,
    b: &Sh,
    fill: FillRule,
    qs: &[Point2<Q>],
) -> std::result::Result<(), TestCaseError> {
    let (sa, sb) = (to_shape(a), to_shape(b));
    let both = [sa.clone(), sb.clone()];
    let mut results = Vec::with_capacity(OPS.len());
    for op in OPS {
        let r = run(op, &both, fill);
        if let Some(r) = &r {
            check_membership(r, op, &[sa.path(), sb.path()], fill, qs)?;
            check_orientation(r)?;
        }
        results.push(r);
    }
    let Some(aa) = run(BooleanOp::Simplify, &both[..1], fill) else { return Ok(()) };
    check_membership(&aa, BooleanOp::Simplify, &[sa.path()], fill, qs)?;
    check_orientation(&aa)?;
    let Some(bb) = run(BooleanOp::Simplify, &both[1..], fill) else { return Ok(()) };
    let [Some(u), Some(i), Some(d), Some(x)] = &results[..] else { return Ok(()) };
    area_identities_of(u, i, d, x, &aa, &bb)
}

fn any_op() -> impl Strategy<Value = BooleanOp> {
    prop::sample::select(vec![
        BooleanOp::Union,
        BooleanOp::Intersection,
        BooleanOp::Difference,
        BooleanOp::Xor,
        BooleanOp::Simplify,
    ])
}

fn inputs_of(op: BooleanOp, a: &Shape, b: &Shape) -> Vec<Shape> {
    if op == BooleanOp::Simplify { vec![a.clone()] } else { vec![a.clone(), b.clone()] }
}

/// The same region: contour count, nesting depths, area and membership at the sample points.
fn same_result(r: &BooleanResult, s: &BooleanResult, qs: &[Point2<Q>]) -> std::result::Result<(), TestCaseError> {
    prop_assert_eq!(r.contours, s.contours, "{} vs {}", r.path, s.path);
    prop_assert_eq!(depths(r), depths(s));
    same_area(r, s, &rat(1))?;
    same_region(r, s, qs)
}

/// `Σ lhs = Σ rhs − Σ minus` for areas: exactly when every area is rational, else in floats.
fn area_sum(plus: &[&BooleanResult], minus: &[&BooleanResult], what: &str) -> std::result::Result<bool, TestCaseError> {
    let all: Vec<&&BooleanResult> = plus.iter().chain(minus).collect();
    if all.iter().all(|r| r.area.is_some()) {
        let p: Q = plus.iter().map(|r| r.area.clone().unwrap()).sum();
        let m: Q = minus.iter().map(|r| r.area.clone().unwrap()).sum();
        prop_assert_eq!(p, m, "{}", what);
        Ok(true)
    } else {
        let p: f64 = plus.iter().map(|r| r.area_float).sum();
        let m: f64 = minus.iter().map(|r| r.area_float).sum();
        let scale: f64 = all.iter().map(|r| r.area_float.abs()).sum::<f64>().max(1.0);
        prop_assert!((p - m).abs() <= 1e-9 * scale, "{}: {} vs {}", what, p, m);
        Ok(false)
    }
}

fn split_t() -> impl Strategy<Value = Q> {
    prop::sample::select(vec![(1, 2), (1, 3), (2, 3), (1, 4), (3, 5)]).prop_map(|(p, q)| ratio(p, q))
}

/// A circle of four quarter arcs (weights 1, 1, 2), counter-clockwise from `(cx + r, cy)`.
fn circle(cx: &Q, cy: &Q, r: &Q) -> Vec<RationalBezier<Q>> {
    let p = |x: i64, y: i64| pt(&(cx + r * rat(x)), &(cy + r * rat(y)));
    let arc = |a, b, c| RationalBezier::new(vec![a, b, c], vec![rat(1), rat(1), rat(2)]).unwrap();
    vec![
        arc(p(1, 0), p(1, 1), p(0, 1)),
        arc(p(0, 1), p(-1, 1), p(-1, 0)),
        arc(p(-1, 0), p(-1, -1), p(0, -1)),
        arc(p(0, -1), p(1, -1), p(1, 0)),
    ]
}

/// An axis-parallel square, counter-clockwise.
fn square(x0: &Q, y0: &Q, side: &Q) -> Vec<RationalBezier<Q>> {
    let c = [(0, 0), (1, 0), (1, 1), (0, 1)].map(|(i, j)| pt(&(x0 + side * rat(i)), &(y0 + side * rat(j))));
    (0..4)
        .map(|i| RationalBezier::new(vec![c[i].clone(), c[(i + 1) % 4].clone()], vec![rat(1), rat(1)]).unwrap())
        .collect()
}

/// Unit vectors with rational coordinates.
fn direction() -> impl Strategy<Value = (Q, Q)> {
    prop::sample::select(vec![(5, 0), (0, 5), (-5, 0), (0, -5), (3, 4), (-4, 3), (-3, -4), (4, -3)])
        .prop_map(|(x, y)| (ratio(x, 5), ratio(y, 5)))
}

/// Two disc-or-square shapes: a circle A and, by mode, a random circle, an externally or
/// internally tangent circle, a random square, a square tangent from outside at A's rightmost
/// point, or A's circumscribed square (tangent at four points). With its description.
fn disc_pair() -> impl Strategy<Value = (Shape, Shape, String)> {
    (0usize..6, (-3i64..=3, -3i64..=3), 1i64..=3, (-3i64..=3, -3i64..=3), 1i64..=3, direction()).prop_map(
        |(mode, (ax, ay), ra, (bx, by), rb, (ux, uy))| {
            let (ax, ay, ra) = (rat(ax), rat(ay), rat(ra));
            let a = circle(&ax, &ay, &ra);
            let rb_q = rat(rb);
            let (b, what) = match mode {
                0 => (circle(&rat(bx), &rat(by), &rb_q), format!("circle ({bx}, {by}) r {rb}")),
                1 | 2 => {
                    let d = if mode == 1 { &ra + &rb_q } else { &ra - &rb_q };
                    let (cx, cy) = (&ax + &d * &ux, &ay + &d * &uy);
                    let w = format!("circle ({cx}, {cy}) r {rb}");
                    (circle(&cx, &cy, &rb_q), w)
                }
                3 => (square(&rat(bx), &rat(by), &rb_q), format!("square ({bx}, {by}) side {rb}")),
                4 => {
                    let (x0, y0) = (&ax + &ra, &ay - rat(1));
                    let w = format!("square ({x0}, {y0}) side 2");
                    (square(&x0, &y0, &rat(2)), w)
                }
                _ => {
                    let (x0, y0) = (&ax - &ra, &ay - &ra);
                    let side = &ra * rat(2);
                    let w = format!("square ({x0}, {y0}) side {side}");
                    (square(&x0, &y0, &side), w)
                }
            };
            let what = format!("A: circle ({ax}, {ay}) r {ra}; B: {what}");
            (Shape::from_contours(vec![a]).unwrap(), Shape::from_contours(vec![b]).unwrap(), what)
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(24), ..ProptestConfig::default() })]

    /// 2. Translations by rational vectors, rational scalings (either sign), quarter turns and
    /// mirrors of both inputs keep the contour count, the sorted nesting depths and the
    /// orientation convention (outer contours ccw: a mirror reverses the inputs but the result
    /// is re-oriented, so its area stays positive), scale the exact area by `|det|`, and keep
    /// the membership of correspondingly mapped points.
    #[test]
    fn invariance_under_similarities(a in shape(), b in shape(), t in affine(), op in any_op(), fill in fill_rule(), qs in points(8)) {
        let (sa, sb) = (to_shape(&a), to_shape(&b));
        let (ta, tb) = (to_shape(&t.shape(&a)), to_shape(&t.shape(&b)));
        let Some(r) = run(op, &inputs_of(op, &sa, &sb), fill) else { return Ok(()) };
        let Some(s) = run(op, &inputs_of(op, &ta, &tb), fill) else { return Ok(()) };
        prop_assert_eq!(r.contours, s.contours, "{} vs {}", r.path, s.path);
        prop_assert_eq!(depths(&r), depths(&s));
        check_orientation(&r)?;
        check_orientation(&s)?;
        prop_assert!(s.area_float >= -1e-12 && r.area_float >= -1e-12, "{} {}", r.area_float, s.area_float);
        same_area(&r, &s, &t.scale)?;
        for q in &qs {
            prop_assert_eq!(r.contains(q).unwrap(), s.contains(&t.point(q)).unwrap(), "at {}", q);
        }
    }

    /// 3. Other descriptions of the same inputs give the same region and area: a segment of A
    /// split at a rational t (exact de Casteljau), every contour of A reversed (the winding
    /// numbers negate: both rules keep the region), A and B swapped for the symmetric
    /// operations, and A's contours reordered with each contour started at another segment
    /// (one of the four per case, each for simplify of A and a binary operation).
    #[test]
    fn same_region_from_another_description(
        a in shape(), b in shape(), ci in any::<prop::sample::Index>(), si in any::<prop::sample::Index>(),
        t in split_t(), op in prop::sample::select(OPS.to_vec()), fill in fill_rule(), qs in points(8), kind in 0usize..4,
    ) {
        let (sa, sb) = (to_shape(&a), to_shape(&b));
        let Some(simple) = run(BooleanOp::Simplify, std::slice::from_ref(&sa), fill) else { return Ok(()) };
        let Some(base) = run(op, &[sa.clone(), sb.clone()], fill) else { return Ok(()) };
        if kind == 0 {
        let mut split = a.clone();
        let c = ci.index(split.len());
        let k = si.index(split[c].len());
        let (l, r) = bezier(&split[c][k]).subdivide(&t).unwrap();
        split[c].splice(k..=k, [bezier_points(&l), bezier_points(&r)]);
        let s_split = to_shape(&split);
        if let Some(x) = run(BooleanOp::Simplify, std::slice::from_ref(&s_split), fill) {
            same_result(&simple, &x, &qs)?;
        }
        if let Some(x) = run(op, &[s_split, sb.clone()], fill) {
            same_result(&base, &x, &qs)?;
        }
        } else if kind == 1 {
        let rev: Sh = a.iter().map(reversed).collect();
        let s_rev = to_shape(&rev);
        if let Some(x) = run(BooleanOp::Simplify, std::slice::from_ref(&s_rev), fill) {
            same_result(&simple, &x, &qs)?;
        }
        if let Some(x) = run(op, &[s_rev, sb.clone()], fill) {
            same_result(&base, &x, &qs)?;
        }
        } else if kind == 2 {
        if op != BooleanOp::Difference
            && let Some(x) = run(op, &[sb.clone(), sa.clone()], fill)
        {
            same_result(&base, &x, &qs)?;
        }
        } else {
        let mut re: Sh = a.iter().rev().cloned().collect();
        for c in &mut re {
            c.rotate_left(1);
        }
        if let Some(x) = run(BooleanOp::Simplify, std::slice::from_ref(&to_shape(&re)), fill) {
            same_result(&simple, &x, &qs)?;
        }
        if let Some(x) = run(op, &[to_shape(&re), sb.clone()], fill) {
            same_result(&base, &x, &qs)?;
        }
        }
    }

    /// 4. `simplify(simplify(A))` is `simplify(A)`. The second input is built from the exact
    /// pieces (each piece the exact sub-curve of its input segment, by de Casteljau) when every
    /// piece has rational ends: then the contour count, depths, exact area and membership agree.
    /// When a piece has an irrational end, the second input is the SVG `path` (rounded to `f64`):
    /// then only `area_float` (within 1e-9 relative) and membership at points whose membership
    /// in the first result is the same at eight neighbours 1/1000 away (so not near its
    /// boundary) are compared.
    #[test]
    fn simplify_is_idempotent(a in shape(), fill in fill_rule(), qs in points(10)) {
        let sa = to_shape(&a);
        let Some(r) = run(BooleanOp::Simplify, std::slice::from_ref(&sa), fill) else { return Ok(()) };
        let exact = r.pieces.iter().flatten().all(|p| p.from.to_rational().is_some() && p.to.to_rational().is_some());
        if exact {
            let contours: Sh = r.pieces.iter().map(|c| c.iter().map(|p| {
                let (f, t) = (p.from.to_rational().unwrap(), p.to.to_rational().unwrap());
                let seg = &a[p.contour][p.segment];
                if f < t {
                    sub_segment(seg, f, t)
                } else {
                    sub_segment(seg, t, f).into_iter().rev().collect()
                }
            }).collect()).collect();
            let s2 = to_shape(&contours);
            let Some(r2) = run(BooleanOp::Simplify, std::slice::from_ref(&s2), fill) else {
                return Err(TestCaseError::fail(format!("the second pass refused: {}", svg(&contours))));
            };
            same_result(&r, &r2, &qs)?;
        } else {
            let s2: Shape = r.path.parse().unwrap();
            let Some(r2) = run(BooleanOp::Simplify, std::slice::from_ref(&s2), fill) else { return Ok(()) };
            let (x, y) = (r.area_float, r2.area_float);
            prop_assert!((x - y).abs() <= 1e-9 * x.abs().max(1.0), "{} vs {}", x, y);
            let d = ratio(1, 1000);
            for q in &qs {
                let Some(w) = r.contains(q).unwrap() else { continue };
                let near = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1)]
                    .iter()
                    .all(|&(i, j)| {
                        let n = qpt(&(&q.x + &d * rat(i)), &(&q.y + &d * rat(j)));
                        r.contains(&n).unwrap() == Some(w)
                    });
                if near {
                    prop_assert_eq!(r2.contains(q).unwrap(), Some(w), "at {}", q);
                }
            }
        }
    }

    // 5. and 5′. (the area identities) are checked by `membership_and_area_identities` and
    // `membership_and_area_identities_on_a_coarse_grid` above, on their pairs.

    /// 6. Every face's winding numbers are the inputs' `winding` at a rational point in it
    /// (`locate` finds the face), and Euler's formula `V − E + F = 1 + C` holds with `C` the
    /// connected components of the edge graph.
    #[test]
    fn arrangement_faces_and_euler(a in shape(), b in shape(), qs in points(5)) {
        let (sa, sb) = (to_shape(&a), to_shape(&b));
        let arr = Arrangement::new(&[sa.clone(), sb.clone()], &casteljau::work::Budget::unlimited()).unwrap();
        let faces = match arr.faces() {
            Ok(f) => f,
            Err(e) => panic!("{e}: {} / {}", svg(&a), svg(&b)),
        };
        let (vs, es) = (arr.vertices(), arr.edges());
        let mut up: Vec<usize> = (0..vs.len()).collect();
        fn find(up: &mut [usize], mut i: usize) -> usize {
            while up[i] != i {
                up[i] = up[up[i]];
                i = up[i];
            }
            i
        }
        for e in &es {
            let (x, y) = (find(&mut up, e.from), find(&mut up, e.to));
            up[x] = y;
        }
        let components = (0..vs.len()).filter(|&i| find(&mut up, i) == i).count();
        prop_assert_eq!(vs.len() as i64 - es.len() as i64 + faces.len() as i64, 1 + components as i64,
            "V {} E {} F {} C {}", vs.len(), es.len(), faces.len(), components);
        for q in &qs {
            let on: Vec<bool> = [&sa, &sb].iter().map(|s| matches!(s.path().winding(q, &casteljau::work::Budget::unlimited()).unwrap(), PathWinding::OnBoundary { .. })).collect();
            match arr.locate(q).unwrap() {
                Location::Face { face, winding } => {
                    prop_assert_eq!(&faces[face].winding, &winding, "face {} at {}", face, q);
                    for (i, s) in [&sa, &sb].iter().enumerate() {
                        let PathWinding::Off(w) = s.path().winding(q, &casteljau::work::Budget::unlimited()).unwrap() else {
                            return Err(TestCaseError::fail(format!("{q} is in face {face} but on input {i}")));
                        };
                        prop_assert_eq!(winding[i], w.winding(), "input {} at {}", i, q);
                    }
                }
                other => prop_assert!(on.contains(&true), "{:?} at {}, which is on no input", other, q),
            }
        }
    }

    /// 7. Circles of rational quadratics (random, externally and internally tangent) with each
    /// other and with squares (random, tangent, circumscribed): the membership property.
    #[test]
    fn circles_and_squares_membership((a, b, _what) in disc_pair(), fill in fill_rule(), qs in points(10)) {
        for op in OPS {
            let Some(r) = run(op, &[a.clone(), b.clone()], fill) else { continue };
            check_membership(&r, op, &[a.path(), b.path()], fill, &qs)?;
            check_orientation(&r)?;
        }
    }
}

/// Property 5: `area(A ∪ B) + area(A ∩ B) = area(A) + area(B)`,
/// `area(A − B) + area(A ∩ B) = area(A)` and `area(A △ B) = area(A ∪ B) − area(A ∩ B)`, from the
/// union `u`, intersection `i`, difference `d`, xor `x` and simplified inputs `aa`, `bb`: exactly
/// when all the areas involved are rational, else in floats (1e-9 relative).
fn area_identities_of(
    u: &BooleanResult,
    i: &BooleanResult,
    d: &BooleanResult,
    x: &BooleanResult,
    aa: &BooleanResult,
    bb: &BooleanResult,
) -> std::result::Result<(), TestCaseError> {
    area_sum(&[u, i], &[aa, bb], "union + intersection = A + B")?;
    area_sum(&[d, i], &[aa], "difference + intersection = A")?;
    area_sum(&[x, i], &[u], "xor + intersection = union")?;
    Ok(())
}

/// Simplify of `A op B` for the minimal cases below.
fn simplify_of(op: BooleanOp, ds: &[&str]) -> casteljau::Result<BooleanResult> {
    let shapes: Vec<Shape> = ds.iter().map(|d| d.parse().unwrap()).collect();
    boolean(op, &shapes, BooleanOptions::default(), &casteljau::work::Budget::unlimited())
}

/// Found by `membership_on_a_coarse_grid` (now `membership_and_area_identities_on_a_coarse_grid`;
/// shrunk twice, to the first two inputs). A line from (0, 0) to (−1, 1) and back along a quadratic
/// whose control point is its own start (the same segment, traced at another speed) bound no
/// region: every point off them has winding number 0. The arrangement does not merge the two arcs
/// (both edges get windings 0 | −1), and simplify returns one clockwise contour of area 0
/// (`M-1 1L0 0Q-1 1 -1 1Z`). It happens when the segment runs toward negative x — (−1, 1),
/// (−2, 2), (−2, 0), and with the cubic `C-1 1 -1 1 0 0` too — and not toward (2, 0), (1, 1),
/// (2, 1), (0, 2), nor with the control point at the middle (`Q-0.5 0.5 0 0`); the last two
/// inputs here are such controls.
#[test]
fn a_line_and_a_degenerate_quadratic_on_one_segment_bound_nothing() {
    let mut wrong = vec![];
    for d in [
        "M0 0 L-1 1 Q-1 1 0 0 Z",
        "M0 0 L-2 0 Q-2 0 0 0 Z",
        "M0 0 L0 0 L-2 0 Q-2 0 0 0 Z",
        "M0 0 L2 0 Q2 0 0 0 Z",
        "M0 0 L1 1 Q1 1 0 0 Z",
    ] {
        let r = simplify_of(BooleanOp::Simplify, &[d]).unwrap();
        eprintln!("{d}: {} contours, area {:?}, {:?}, {}", r.contours, r.area, r.orientation, r.path);
        if r.contours != 0 || r.area != Some(rat(0)) {
            wrong.push(d);
        }
    }
    assert!(wrong.is_empty(), "{wrong:?}");
}

/// The same unmerged overlap next to a triangle: the union is refused instead of being the
/// triangle (area 1).
#[test]
fn a_triangle_with_the_unmerged_sliver() {
    let r = simplify_of(BooleanOp::Union, &["M0 0 L0 -1 L-2 0 Z", "M0 0 L-1 1 Q-1 1 0 0 Z"]).unwrap();
    assert_eq!((r.contours, r.area), (1, Some(rat(1))));
}
