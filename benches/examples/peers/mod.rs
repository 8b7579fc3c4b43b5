//! The float peers of `casteljau boolean`, shared by `benches/examples/path_ops_peers.rs` and
//! `benches/shapes_peers.rs`: linesweeper (`binary_op` on kurbo `BezPath`s, with a fill rule) and
//! flo_curves (`path_remove_overlapped_points`, `path_add`, `path_sub`, `path_intersect` on
//! `SimpleBezierPath`s; even-odd only, see [`flo_simplify_raw`]).
//!
//! Inputs are kurbo `BezPath`s (glyphs read exactly by `casteljau::format::Font`, then rounded to
//! the nearest `f64`: integers for TrueType glyphs; the hard cases are exact `f64`s). flo_curves
//! takes cubics only: a line becomes flo_curves' own `BezierPathBuilder::line_to` cubic (control
//! points at 0.3334 and 0.6667 of the way) and a quadratic is degree-elevated in `f64`
//! (`c1 = p0 + 2/3 (q - p0)`, rounded), so flo_curves sees a curve within rounding of the input.
//!
//! Settings, stated, not tuned: linesweeper's own accuracy (`binary_op`, which picks `eps` from the
//! bounding box, at least `1e-6`); flo_curves' accuracy [`FLO_ACCURACY`] (0.01, as in its own
//! tests and examples).
#![allow(dead_code)] // each of the two users calls part of it

use flo_curves::Coord2;
use flo_curves::bezier::path::{
    BezierPathBuilder, GraphPath, PathLabel, SimpleBezierPath, path_add, path_intersect, path_remove_interior_points,
    path_remove_overlapped_points, path_sub,
};
use kurbo::{BezPath, PathEl, Point};
use std::cell::RefCell;
use std::fmt::Write as _;
use std::panic::{AssertUnwindSafe, catch_unwind};

/// flo_curves' `accuracy` argument (distance under which points are merged).
pub const FLO_ACCURACY: f64 = 0.01;

/// The two peers, in output order.
pub const PEERS: [&str; 2] = ["linesweeper", "flo_curves"];

/// A binary operation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// A ∪ B.
    Union,
    /// A ∩ B.
    Intersection,
    /// A ∖ B.
    Difference,
    /// A △ B.
    Xor,
}

impl Op {
    /// All four, in output order.
    pub const ALL: [Op; 4] = [Op::Union, Op::Intersection, Op::Difference, Op::Xor];

    /// The name used by `casteljau boolean` and in file names.
    pub fn name(self) -> &'static str {
        match self {
            Op::Union => "union",
            Op::Intersection => "intersection",
            Op::Difference => "difference",
            Op::Xor => "xor",
        }
    }
}

/// Fill rule of the inputs (the outputs of both peers are simple contours, valid under both).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fill {
    /// Inside where the winding number is not 0.
    NonZero,
    /// Inside where the winding number is odd.
    EvenOdd,
}

/// One input in each peer's own type (converted once, outside the timed part).
pub struct Input {
    /// For linesweeper.
    pub kurbo: BezPath,
    /// For flo_curves.
    pub flo: Vec<SimpleBezierPath>,
}

impl Input {
    /// Both forms of `p`.
    pub fn new(p: BezPath) -> Input {
        let flo = to_flo(&p);
        Input { kurbo: p, flo }
    }
}

/// A peer's answer in its own type.
pub enum Output {
    /// linesweeper's.
    Kurbo(BezPath),
    /// flo_curves'.
    Flo(Vec<SimpleBezierPath>),
}

impl Output {
    /// SVG path data, numbers in shortest round-trip `f64` form.
    pub fn svg(&self) -> String {
        match self {
            Output::Kurbo(p) => kurbo_svg(p),
            Output::Flo(p) => flo_svg(p),
        }
    }
}

/// glyph `gid` of `font` as a kurbo path (every contour closed), each exact coordinate rounded to
/// the nearest `f64`.
pub fn glyph_path(font: &casteljau::format::Font, gid: u32) -> Result<BezPath, String> {
    use casteljau::format::Segment;
    use num_traits::ToPrimitive;
    let contours = font.outline(gid).map_err(|e| e.to_string())?;
    let mut out = BezPath::new();
    for c in contours {
        let mut first = true;
        for s in &c.segments {
            let Segment::Bezier(ps) = s else { return Err(format!("glyph {gid}: a skipped piece")) };
            let q: Vec<Point> = ps
                .iter()
                .map(|p| Point::new(p.coords[0].to_f64().unwrap_or(f64::NAN), p.coords[1].to_f64().unwrap_or(f64::NAN)))
                .collect();
            if first {
                out.move_to(q[0]);
                first = false;
            }
            match q.len() {
                2 => out.line_to(q[1]),
                3 => out.quad_to(q[1], q[2]),
                _ => out.curve_to(q[1], q[2], q[3]),
            }
        }
        if !first {
            out.close_path();
        }
    }
    Ok(out)
}

/// flo_curves' form of `p`: one closed `SimpleBezierPath` per subpath (a line back to the start
/// is added when the subpath does not end there).
pub fn to_flo(p: &BezPath) -> Vec<SimpleBezierPath> {
    let c = |p: Point| Coord2(p.x, p.y);
    let mut out = vec![];
    let mut cur: Option<(BezierPathBuilder<SimpleBezierPath>, Point, Point)> = None; // builder, start, last
    let finish = |cur: Option<(BezierPathBuilder<SimpleBezierPath>, Point, Point)>, out: &mut Vec<SimpleBezierPath>| {
        if let Some((b, start, last)) = cur {
            let b = if last != start { b.line_to(c(start)) } else { b };
            out.push(b.build());
        }
    };
    for el in p.elements() {
        match *el {
            PathEl::MoveTo(q) => {
                finish(cur.take(), &mut out);
                cur = Some((BezierPathBuilder::start(c(q)), q, q));
            }
            PathEl::LineTo(q) => {
                if let Some((b, s, _)) = cur.take() {
                    cur = Some((b.line_to(c(q)), s, q));
                }
            }
            PathEl::QuadTo(q1, q2) => {
                if let Some((b, s, last)) = cur.take() {
                    let c1 = last + (q1 - last) * (2.0 / 3.0);
                    let c2 = q2 + (q1 - q2) * (2.0 / 3.0);
                    cur = Some((b.curve_to((c(c1), c(c2)), c(q2)), s, q2));
                }
            }
            PathEl::CurveTo(q1, q2, q3) => {
                if let Some((b, s, _)) = cur.take() {
                    cur = Some((b.curve_to((c(q1), c(q2)), c(q3)), s, q3));
                }
            }
            PathEl::ClosePath => finish(cur.take(), &mut out),
        }
    }
    finish(cur, &mut out);
    out
}

fn num(s: &mut String, x: f64) {
    // `{}` of an f64 is the shortest decimal that reads back as the same f64.
    let _ = write!(s, "{x}");
}

fn pt(s: &mut String, p: Point) {
    num(s, p.x);
    s.push(' ');
    num(s, p.y);
}

/// SVG path data of a kurbo path.
pub fn kurbo_svg(p: &BezPath) -> String {
    let mut s = String::new();
    for el in p.elements() {
        if !s.is_empty() {
            s.push(' ');
        }
        match *el {
            PathEl::MoveTo(a) => {
                s.push('M');
                pt(&mut s, a);
            }
            PathEl::LineTo(a) => {
                s.push('L');
                pt(&mut s, a);
            }
            PathEl::QuadTo(a, b) => {
                s.push('Q');
                pt(&mut s, a);
                s.push(' ');
                pt(&mut s, b);
            }
            PathEl::CurveTo(a, b, c) => {
                s.push('C');
                pt(&mut s, a);
                s.push(' ');
                pt(&mut s, b);
                s.push(' ');
                pt(&mut s, c);
            }
            PathEl::ClosePath => s.push('Z'),
        }
    }
    s
}

/// SVG path data of flo_curves paths (each closed with `Z`).
pub fn flo_svg(paths: &[SimpleBezierPath]) -> String {
    let p = |c: &Coord2| Point::new(c.0, c.1);
    let mut out = BezPath::new();
    for (start, curves) in paths {
        out.move_to(p(start));
        for (c1, c2, e) in curves {
            out.curve_to(p(c1), p(c2), p(e));
        }
        out.close_path();
    }
    kurbo_svg(&out)
}

/// linesweeper's `binary_op(a, b, fill, op)`, the output contours concatenated (outer contours
/// and holes wind oppositely, so the result means the same under both fill rules).
pub fn linesweeper_op(a: &BezPath, b: &BezPath, fill: Fill, op: Op) -> Result<Output, String> {
    use linesweeper::{BinaryOp, FillRule, binary_op};
    let fill = match fill {
        Fill::NonZero => FillRule::NonZero,
        Fill::EvenOdd => FillRule::EvenOdd,
    };
    let op = match op {
        Op::Union => BinaryOp::Union,
        Op::Intersection => BinaryOp::Intersection,
        Op::Difference => BinaryOp::Difference,
        Op::Xor => BinaryOp::Xor,
    };
    let contours = binary_op(a, b, fill, op).map_err(|e| e.to_string())?;
    let mut out = BezPath::new();
    for c in contours.contours() {
        out.extend(c.path.iter());
    }
    Ok(Output::Kurbo(out))
}

/// linesweeper's simplify: the union of `a` with the empty path.
pub fn linesweeper_simplify(a: &BezPath, fill: Fill) -> Result<Output, String> {
    linesweeper_op(a, &BezPath::new(), fill, Op::Union)
}

/// flo_curves' overlap removal, `path_remove_overlapped_points`: even-odd whatever the fill rule
/// asked for. flo_curves has no non-zero rule that keeps holes: its graph turns every subpath
/// clockwise before ray casting (`GraphPath::from_path`), so its "non-zero"
/// `path_remove_interior_points` (documented as leaving "no holes") fills every counter of a glyph
/// (o, a, e, A, B, ...). Even-odd keeps them and differs from non-zero only where contours overlap.
pub fn flo_simplify_raw(a: &[SimpleBezierPath]) -> Vec<SimpleBezierPath> {
    path_remove_overlapped_points(&a.to_vec(), FLO_ACCURACY)
}

/// flo_curves' "non-zero" overlap removal, `path_remove_interior_points` (fills holes; see
/// [`flo_simplify_raw`]). Not one of the peers' answers; kept to show the difference.
pub fn flo_remove_interior(a: &[SimpleBezierPath]) -> Vec<SimpleBezierPath> {
    path_remove_interior_points(&a.to_vec(), FLO_ACCURACY)
}

/// [`flo_simplify_raw`] as an [`Output`].
pub fn flo_simplify(a: &[SimpleBezierPath]) -> Result<Output, String> {
    Ok(Output::Flo(flo_simplify_raw(a)))
}

/// flo_curves' binary operations, even-odd (its only rule, see [`flo_simplify_raw`]). Its
/// `path_add`, `path_sub` and `path_intersect` assume operands that do not overlap themselves; as
/// its docs advise, each operand is first cleaned by [`flo_simplify_raw`]. flo_curves has no xor:
/// it is built exactly as `path_add` is (`GraphPath` collide, round, ray-cast edge kinds, heal,
/// exterior paths) with the xor test `odd(A) != odd(B)`.
pub fn flo_op(a: &[SimpleBezierPath], b: &[SimpleBezierPath], op: Op) -> Result<Output, String> {
    let (a, b) = (flo_simplify_raw(a), flo_simplify_raw(b));
    let out = match op {
        Op::Union => path_add(&a, &b, FLO_ACCURACY),
        Op::Intersection => path_intersect(&a, &b, FLO_ACCURACY),
        Op::Difference => path_sub(&a, &b, FLO_ACCURACY),
        Op::Xor => flo_xor(&a, &b),
    };
    Ok(Output::Flo(out))
}

fn flo_xor(a: &[SimpleBezierPath], b: &[SimpleBezierPath]) -> Vec<SimpleBezierPath> {
    // path_add's short cut for an empty operand, which is right for xor too.
    if a.is_empty() {
        return b.to_vec();
    } else if b.is_empty() {
        return a.to_vec();
    }
    let mut g = GraphPath::new();
    g = g.merge(GraphPath::from_merged_paths(a.iter().map(|p| (p, PathLabel(0)))));
    g = g.collide(GraphPath::from_merged_paths(b.iter().map(|p| (p, PathLabel(1)))), FLO_ACCURACY);
    g.round(FLO_ACCURACY);
    g.set_edge_kinds_by_ray_casting(|c| ((c[0] & 1) != 0) != ((c[1] & 1) != 0));
    g.heal_exterior_gaps();
    g.exterior_paths()
}

/// Peer `peer` (one of [`PEERS`]) applied to `a` and `b` (`None`: simplify `a`); `fill` is
/// linesweeper's fill rule (flo_curves reads its inputs even-odd whatever it is).
pub fn run(peer: &str, a: &Input, b: Option<&Input>, fill: Fill, op: Op) -> Result<Output, String> {
    match (peer, b) {
        ("linesweeper", None) => linesweeper_simplify(&a.kurbo, fill),
        ("linesweeper", Some(b)) => linesweeper_op(&a.kurbo, &b.kurbo, fill, op),
        (_, None) => flo_simplify(&a.flo),
        (_, Some(b)) => flo_op(&a.flo, &b.flo, op),
    }
}

thread_local! {
    static LAST_PANIC: RefCell<String> = const { RefCell::new(String::new()) };
}

/// Replaces the panic hook by one that prints nothing and keeps the message and location for
/// [`catch`] (a peer that panics on thousands of glyphs would otherwise flood stderr and the
/// timings).
pub fn quiet_panics() {
    std::panic::set_hook(Box::new(|info| {
        let msg = if let Some(s) = info.payload().downcast_ref::<&str>() {
            (*s).to_string()
        } else if let Some(s) = info.payload().downcast_ref::<String>() {
            s.clone()
        } else {
            "(non-string payload)".to_string()
        };
        let at = info.location().map(|l| format!(" at {}:{}", l.file(), l.line())).unwrap_or_default();
        LAST_PANIC.with(|p| *p.borrow_mut() = format!("{msg}{at}"));
    }));
}

/// `f()`, with a panic turned into `Err("panic: MESSAGE at FILE:LINE")`.
pub fn catch<T>(f: impl FnOnce() -> Result<T, String>) -> Result<T, String> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(_) => Err(format!("panic: {}", LAST_PANIC.with(|p| p.borrow().clone()))),
    }
}
