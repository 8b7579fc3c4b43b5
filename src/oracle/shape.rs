//! Deciding a float library's answer to a boolean operation against the exact one.
//!
//! The float result `R` (closed contours with its numbers read exactly, filled by the same rule
//! as the inputs) is compared with the exact result `E` of `op(A, B)`:
//!
//! - **contours and nesting**: the number of contours, and the sorted list of their nesting
//!   depths (how many other contours enclose each one);
//! - **a witness**: a rational point inside one region and outside the other, farther than `tol`
//!   from `E`'s exact boundary. Candidates are taken beside every edge of the arrangement of
//!   `A`, `B` and `R` where the two regions differ on one side, stepping away from the edge by
//!   `1.5·tol·2^k`; a candidate is accepted only when both memberships are computed exactly (the
//!   winding numbers of `A`, `B` and `R` at it) and `(x(t) − q_x)² + (y(t) − q_y)² − tol²` is
//!   proved positive on every piece of `E` (no root in its parameter interval, exact root
//!   isolation; for a rational piece the same with `W`);
//! - **distance**: an upper bound on the Hausdorff distance between the two boundaries, in
//!   binary64. Each float segment is matched to the exact piece it follows (the piece of an
//!   exact segment between the parameters nearest to its ends): the bound for the pair is the
//!   largest distance between corresponding control points at a common degree (a pairing of
//!   their points, so an upper bound both ways), or for a line the largest distance of the
//!   segment's control points to it and of the ends; the exact pieces must be covered by the
//!   matched parameter intervals. What is left — float segments matching no piece, exact parts
//!   no segment covers — is bounded by adaptive sampling: a part is cut until the distance from
//!   its midpoint to the other boundary plus its speed bound times half its parameter length is
//!   at most `tol` (or the midpoint itself is farther than `tol`, or 14 halvings are reached).
//!   It is an upper bound up to binary64 rounding (relative error about `1e-15` of the
//!   coordinates), which the reported figure does not include.
//!
//! The answers agree when the counts and depths are equal, no witness exists, and the distance
//! bound is at most `tol`.

use crate::curve::BezierCurve;
use crate::error::{Error, Result};
use crate::num::point::{Point, Point2};
use crate::num::scalar::{rat, ratio_to_f64};
use crate::path::PathWinding;
use crate::poly::Poly;
use crate::poly::algebraic::RealAlgebraic;
use crate::shape::segment::Seg;
use crate::shape::{Arrangement, BooleanOp, BooleanOptions, BooleanResult, HalfEdge, Shape};
use crate::work::Budget;
use num_rational::BigRational;
use num_traits::Signed;
use serde::Serialize;

/// A point inside one region and outside the other. JSON: `point` (exact strings),
/// `point_float`, `inside_exact`, `inside_found`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Witness {
    /// The point, exactly.
    pub point: Point2<BigRational>,
    /// The point, rounded.
    pub point_float: [f64; 2],
    /// Whether it is inside the exact result.
    pub inside_exact: bool,
    /// Whether it is inside the float result.
    pub inside_found: bool,
}

/// The verdict on a float result. JSON: `agree`, `contours`, `contours_found`, `depths`,
/// `depths_found`, `witness` (or null), `distance_bound` (binary64 upper bound on the distance
/// between the boundaries), `problems` (one sentence each).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Agreement {
    /// No disagreement found.
    pub agree: bool,
    /// Contours of the exact result.
    pub contours: usize,
    /// Contours of the float result.
    pub contours_found: usize,
    /// Nesting depths of the exact result's contours, sorted.
    pub depths: Vec<usize>,
    /// Nesting depths of the float result's contours, sorted.
    pub depths_found: Vec<usize>,
    /// A point where the regions differ, farther than `tol` from the exact boundary.
    pub witness: Option<Witness>,
    /// An upper bound on the distance between the two boundaries.
    pub distance_bound: f64,
    /// What disagrees, in words.
    pub problems: Vec<String>,
}

/// Decides `found` (a float library's result of `op` on `inputs`) against the exact `result`
/// (see the module documentation).
///
/// # Errors
/// The errors of [`Arrangement::new`] on the inputs with `found`; [`Error::InvalidArgument`]
/// for a negative `tol`.
///
/// # Example
/// ```
/// use casteljau::shape::{boolean, BooleanOp, BooleanOptions, Shape};
/// use casteljau::oracle::check_against;
/// use casteljau::{ratio, work::Budget};
/// let a: Shape = "M0 0 H2 V2 H0 Z".parse().unwrap();
/// let b: Shape = "M1 1 H3 V3 H1 Z".parse().unwrap();
/// let o = BooleanOptions::default();
/// let exact = boolean(BooleanOp::Union, &[a.clone(), b.clone()], o, &casteljau::work::Budget::unlimited()).unwrap();
/// let good: Shape = "M0 0 H2 V1 H3 V3 H1 V2 H0 Z".parse().unwrap();
/// let v = check_against(BooleanOp::Union, &[a.clone(), b.clone()], o, &exact, &good, &ratio(1, 1000), &Budget::unlimited()).unwrap();
/// assert!(v.agree);
/// // a float answer that forgot the corner (1, 2)–(2, 1) overlap: the intersection for the union
/// let bad: Shape = "M1 1 H2 V2 H1 Z".parse().unwrap();
/// let v = check_against(BooleanOp::Union, &[a, b], o, &exact, &bad, &ratio(1, 1000), &Budget::unlimited()).unwrap();
/// assert!(!v.agree);
/// let w = v.witness.unwrap();
/// assert!(w.inside_exact && !w.inside_found);
/// ```
pub fn check_against(
    op: BooleanOp,
    inputs: &[Shape],
    options: BooleanOptions,
    result: &BooleanResult,
    found: &Shape,
    tol: &BigRational,
    budget: &Budget,
) -> Result<Agreement> {
    if tol.is_negative() {
        return Err(Error::InvalidArgument { message: format!("the tolerance is not negative, not {tol}") });
    }
    let fill = options.fill;
    let depths = sorted_depths(&result.parents);
    let found_parents = contour_parents(found)?;
    let depths_found = sorted_depths(&found_parents);
    let contours_found = found.path().contours().len();
    let mut problems = vec![];
    if contours_found != result.contours {
        problems.push(format!("{} contours, not {}", contours_found, result.contours));
    } else if depths != depths_found {
        problems.push(format!("nesting depths {depths_found:?}, not {depths:?}"));
    }
    // the arrangement of the inputs and the float result: edges where the regions differ
    let mut all: Vec<Shape> = inputs.to_vec();
    all.push(found.clone());
    let arr = Arrangement::new_approximating(&all, budget, inputs.len())?;
    let k = inputs.len();
    let in_exact = |w: &[i64]| op.apply(fill.contains(w[0]), k > 1 && fill.contains(w[1]));
    let in_found = |w: &[i64]| fill.contains(w[k]);
    let exact_pieces = result.exact_boundary();
    let witness = find_witness(&arr, inputs, found, &exact_pieces, tol, &|w| in_exact(w) != in_found(w), op, options)?;
    if let Some(w) = &witness {
        problems.push(format!(
            "the point ({}, {}) is {} the exact result and {} the float result",
            w.point_float[0],
            w.point_float[1],
            if w.inside_exact { "inside" } else { "outside" },
            if w.inside_found { "inside" } else { "outside" }
        ));
    }
    let distance_bound = hausdorff_bound(&exact_pieces, found, ratio_to_f64(tol));
    if distance_bound > ratio_to_f64(tol) {
        problems.push(format!("the boundaries are up to {distance_bound} apart (bound), more than the tolerance"));
    }
    Ok(Agreement {
        agree: problems.is_empty(),
        contours: result.contours,
        contours_found,
        depths,
        depths_found,
        witness,
        distance_bound,
        problems,
    })
}

fn sorted_depths(parents: &[Option<usize>]) -> Vec<usize> {
    let depth = |mut i: usize| {
        let mut d = 0;
        while let Some(p) = parents[i] {
            d += 1;
            i = p;
            if d > parents.len() {
                break;
            }
        }
        d
    };
    let mut ds: Vec<usize> = (0..parents.len()).map(depth).collect();
    ds.sort_unstable();
    ds
}

/// The parents of a path's contours: the deepest contour whose winding number around a point
/// of the contour (its start, or another control point when the start lies on it) is non-zero.
fn contour_parents(s: &Shape) -> Result<Vec<Option<usize>>> {
    let cs = s.path().contours();
    let n = cs.len();
    let mut encloses = vec![vec![false; n]; n];
    for (j, cj) in cs.iter().enumerate() {
        let probes: Vec<Point2<BigRational>> = cj
            .iter()
            .filter_map(|seg| seg.eval(&BigRational::new(1.into(), 3.into())).ok())
            .filter_map(|p| Point2::try_from(&p).ok())
            .collect();
        for (i, ci) in cs.iter().enumerate() {
            if i == j {
                continue;
            }
            for q in &probes {
                match crate::path::winding::winding_number_rational(ci, q)? {
                    crate::path::winding::Winding::Inside(w) => {
                        encloses[i][j] = w != 0;
                        break;
                    }
                    crate::path::winding::Winding::OnBoundary { .. } => continue,
                }
            }
        }
    }
    let depth: Vec<usize> = (0..n).map(|j| (0..n).filter(|&i| encloses[i][j]).count()).collect();
    Ok((0..n).map(|j| (0..n).filter(|&i| encloses[i][j]).max_by_key(|&i| depth[i])).collect())
}

/// Inside `op(A, B)` by the inputs' own winding numbers, and inside `R`; `None` on a boundary.
fn memberships(
    inputs: &[Shape],
    found: &Shape,
    q: &Point2<BigRational>,
    op: BooleanOp,
    options: BooleanOptions,
) -> Result<Option<(bool, bool)>> {
    let fill = options.fill;
    let inside = |s: &Shape| -> Result<Option<bool>> {
        Ok(match s.path().winding(q, &Budget::unlimited())? {
            PathWinding::Off(w) => Some(fill.contains(w.winding())),
            PathWinding::OnBoundary { .. } => None,
        })
    };
    let a = inside(&inputs[0])?;
    let b = if inputs.len() > 1 { inside(&inputs[1])? } else { Some(false) };
    let r = inside(found)?;
    Ok(match (a, b, r) {
        (Some(a), Some(b), Some(r)) => Some((op.apply(a, b), r)),
        _ => None,
    })
}

#[allow(clippy::too_many_arguments)]
fn find_witness(
    arr: &Arrangement,
    inputs: &[Shape],
    found: &Shape,
    exact: &[(std::sync::Arc<Seg>, RealAlgebraic, RealAlgebraic)],
    tol: &BigRational,
    differs: &dyn Fn(&[i64]) -> bool,
    op: BooleanOp,
    options: BooleanOptions,
) -> Result<Option<Witness>> {
    let step0 = if tol.is_positive() {
        tol * BigRational::new(3.into(), 2.into())
    } else {
        BigRational::new(1.into(), 1024.into())
    };
    let scale = {
        let mut m = rat(1);
        for s in &arr.segs {
            for p in s.hull.iter().flatten() {
                for c in [&p.x, &p.y] {
                    if c.abs() > m {
                        m = c.abs();
                    }
                }
            }
        }
        m * rat(4)
    };
    for e in 0..arr.edges.len() {
        for forward in [true, false] {
            let h = HalfEdge { edge: e, forward };
            if !differs(arr.side(h)) {
                continue;
            }
            let (p, axis) = arr.beside_point(h);
            let d = axis.unit();
            let mut s = step0.clone();
            while s < scale {
                let q = Point2::new(&p.x + &s * &d[0], &p.y + &s * &d[1]);
                if let Some((ie, ir)) = memberships(inputs, found, &q, op, options)? {
                    if ie != ir && far_from(exact, &q, tol) {
                        let point_float = [ratio_to_f64(&q.x), ratio_to_f64(&q.y)];
                        return Ok(Some(Witness { point: q, point_float, inside_exact: ie, inside_found: ir }));
                    }
                    if ie == ir {
                        break; // stepped out of the difference
                    }
                }
                s *= rat(2);
            }
        }
    }
    Ok(None)
}

/// `|C(t) − q| > tol` for every `t` of every piece, proved exactly.
fn far_from(
    pieces: &[(std::sync::Arc<Seg>, RealAlgebraic, RealAlgebraic)],
    q: &Point2<BigRational>,
    tol: &BigRational,
) -> bool {
    let (qf, tf) = ([ratio_to_f64(&q.x), ratio_to_f64(&q.y)], ratio_to_f64(tol));
    for (s, lo, hi) in pieces {
        if let Some([x0, y0, x1, y1]) = s.bbox
            && (qf[0] < x0 - 2.0 * tf || qf[0] > x1 + 2.0 * tf || qf[1] < y0 - 2.0 * tf || qf[1] > y1 + 2.0 * tf)
        {
            continue; // the box is farther than tol (with room for rounding)
        }
        // |C(t) − q|² − tol² times W²: (X − q_x W)² + (Y − q_y W)² − tol² W²
        let fx = s.x() - &s.w().scale(&q.x);
        let fy = s.y() - &s.w().scale(&q.y);
        let g: Poly<BigRational> = &(&(&fx * &fx) + &(&fy * &fy)) - &(s.w() * s.w()).scale(&(tol * tol));
        let (a, _) = lo.interval();
        let (_, b) = hi.interval();
        if g.is_zero() || !RealAlgebraic::roots_in(&g, &a, &b).is_empty() {
            return false;
        }
        if g.eval(&a).is_negative() {
            return false;
        }
    }
    true
}

/// Binary64 evaluation of a piece.
struct FloatPiece {
    x: Poly<f64>,
    y: Poly<f64>,
    w: Poly<f64>,
    lo: f64,
    hi: f64,
    /// A bound on the speed `|C'(t)|` over `[lo, hi]` (polynomial pieces: degree × the longest
    /// control leg; rational ones: the sampled maximum, doubled).
    speed: f64,
}

impl FloatPiece {
    fn new(s: &Seg, lo: f64, hi: f64) -> Self {
        let f = |p: &Poly<BigRational>| p.map(ratio_to_f64);
        let mut fp = FloatPiece { x: f(s.x()), y: f(s.y()), w: f(s.w()), lo, hi, speed: 0.0 };
        fp.speed = match (&s.hull, s.polynomial) {
            (Some(ps), true) => {
                let legs = ps.windows(2).map(|w| {
                    let dx = ratio_to_f64(&(&w[1].x - &w[0].x));
                    let dy = ratio_to_f64(&(&w[1].y - &w[0].y));
                    dx.hypot(dy)
                });
                s.degree() as f64 * legs.fold(0.0, f64::max) * (1.0 + 1e-12)
            }
            _ => (0..=64).map(|k| fp.speed_at(lo + (hi - lo) * k as f64 / 64.0)).fold(0.0, f64::max) * 2.0,
        };
        fp
    }
    fn at(&self, t: f64) -> [f64; 2] {
        let w = self.w.eval(&t);
        [self.x.eval(&t) / w, self.y.eval(&t) / w]
    }
    fn speed_at(&self, t: f64) -> f64 {
        let h = 1e-6;
        let (a, b) = (self.at(t - h), self.at(t + h));
        (b[0] - a[0]).hypot(b[1] - a[1]) / (2.0 * h)
    }
    /// The nearest point found from `q` by sampling and Newton steps (an upper bound on the
    /// distance: it is a point of the piece).
    fn distance_from(&self, q: [f64; 2]) -> f64 {
        dist(self.at(nearest_on(&|t| self.at(t), q, self.lo, self.hi)), q)
    }
}

/// The directed bound from every piece of `from` to the set `to`.
fn directed(from: &[FloatPiece], to: &[FloatPiece], tol: f64) -> f64 {
    let dist = |q: [f64; 2]| to.iter().map(|p| p.distance_from(q)).fold(f64::INFINITY, f64::min);
    let mut worst: f64 = 0.0;
    for p in from {
        let mut stack = vec![(p.lo, p.hi, 0u32)];
        while let Some((a, b, depth)) = stack.pop() {
            let m = (a + b) / 2.0;
            let d = dist(p.at(m));
            let bound = d + p.speed * (b - a) / 2.0;
            // refine only where the part might still be within tol
            if bound > tol && d <= tol && depth < 14 {
                stack.push((a, m, depth + 1));
                stack.push((m, b, depth + 1));
            } else {
                worst = worst.max(bound);
            }
        }
    }
    worst
}

/// Control points of a segment in binary64 (affine; `None` for a rational segment).
fn float_points(s: &Seg) -> Option<Vec<[f64; 2]>> {
    if !s.polynomial {
        return None;
    }
    s.hull.as_ref().map(|ps| ps.iter().map(|p| [ratio_to_f64(&p.x), ratio_to_f64(&p.y)]).collect())
}

/// The binary64 curve of control points `ps`.
fn curve(ps: &[[f64; 2]]) -> BezierCurve<f64> {
    BezierCurve::new(ps.iter().map(|p| Point::new(p.to_vec())).collect()).expect("a control point")
}

fn points_of(c: &BezierCurve<f64>) -> Vec<[f64; 2]> {
    c.points().iter().map(|p| [p.coords[0], p.coords[1]]).collect()
}

/// De Casteljau in binary64.
fn point_of(ps: &[[f64; 2]], t: f64) -> [f64; 2] {
    let p = curve(ps).eval(&t);
    [p.coords[0], p.coords[1]]
}

/// The control points of `ps` restricted to `[a, b]` ([`BezierCurve::subsegment`], binary64).
fn sub_points(ps: &[[f64; 2]], a: f64, b: f64) -> Vec<[f64; 2]> {
    points_of(&curve(ps).subsegment(&a, &b))
}

/// Degree elevation by one, binary64.
fn elevate(ps: &[[f64; 2]]) -> Vec<[f64; 2]> {
    points_of(&curve(ps).elevate(1).expect("a small degree"))
}

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// The distance from `p` to the segment `[a, b]`.
fn to_segment(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    if len2 == 0.0 {
        return dist(p, a);
    }
    let t = (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0);
    dist(p, [a[0] + t * dx, a[1] + t * dy])
}

/// The parameter of the point of `ps` nearest to `q` (sampling, then Newton), within `[lo, hi]`.
fn nearest(ps: &[[f64; 2]], q: [f64; 2], lo: f64, hi: f64) -> f64 {
    let c = curve(ps);
    nearest_on(
        &|t| {
            let p = c.eval(&t);
            [p.coords[0], p.coords[1]]
        },
        q,
        lo,
        hi,
    )
}

/// The parameter in `[lo, hi]` of the point of the curve `at` nearest to `q` found by 33 samples
/// and Newton steps on the squared distance from the best one (the better of the two).
fn nearest_on(at: &dyn Fn(f64) -> [f64; 2], q: [f64; 2], lo: f64, hi: f64) -> f64 {
    let f = |t: f64| {
        let p = at(t);
        (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)
    };
    let mut best = (f64::INFINITY, lo);
    for k in 0..=32 {
        let t = lo + (hi - lo) * k as f64 / 32.0;
        let d = f(t);
        if d < best.0 {
            best = (d, t);
        }
    }
    let mut t = best.1;
    for _ in 0..20 {
        let h = 1e-6 * (hi - lo).max(1e-12);
        let (f0, fp, fm) = (f(t), f(t + h), f(t - h));
        let (d1, d2) = ((fp - fm) / (2.0 * h), (fp - 2.0 * f0 + fm) / (h * h));
        if d2 <= 0.0 || !d1.is_finite() {
            break;
        }
        let next = (t - d1 / d2).clamp(lo, hi);
        let done = (next - t).abs() < 1e-16;
        t = next;
        if done {
            break;
        }
    }
    if f(t) <= best.0 { t } else { best.1 }
}

/// An upper bound on the distance between a float segment `r` and the piece of `e` between the
/// parameters nearest to `r`'s ends, both ways: for a line, the largest distance of `r`'s
/// control points to it and of the ends (`r` lies in their hull, and its projection covers the
/// line's); otherwise the smaller of the largest distance between corresponding control points
/// of `r` and of the piece at a common degree (a pairing of their points, so an upper bound both
/// ways) and the chord bound (each curve's control points' distance to its chord, plus the
/// chords' ends' distances).
fn matched_bound(r: &[[f64; 2]], e: &[[f64; 2]], a: f64, b: f64) -> f64 {
    let (ea, eb) = (point_of(e, a), point_of(e, b));
    let (ra, rb) = (r[0], r[r.len() - 1]);
    if e.len() == 2 {
        let far = r.iter().map(|p| to_segment(*p, ea, eb)).fold(0.0, f64::max);
        return far.max(dist(ra, ea)).max(dist(rb, eb));
    }
    let mut sub = sub_points(e, a, b);
    // both nearly straight: each curve is within its control points' distance to its chord
    // (and covers it), and the chords are within their ends' distance of each other
    let flat = |ps: &[[f64; 2]]| ps.iter().map(|p| to_segment(*p, ps[0], ps[ps.len() - 1])).fold(0.0, f64::max);
    let chords = flat(r) + flat(&sub) + dist(ra, ea).max(dist(rb, eb));
    let mut rr = r.to_vec();
    while sub.len() < rr.len() {
        sub = elevate(&sub);
    }
    while rr.len() < sub.len() {
        rr = elevate(&rr);
    }
    let paired = rr.iter().zip(&sub).map(|(p, q)| dist(*p, *q)).fold(0.0, f64::max);
    paired.min(chords)
}

/// An upper bound on the Hausdorff distance between the exact boundary and the float result's:
/// each float segment matched to the exact piece it follows ([`matched_bound`]), every exact
/// piece checked to be covered by matched segments, and what is left (unmatched segments,
/// uncovered parts) bounded by sampling (`directed`).
fn hausdorff_bound(exact: &[(std::sync::Arc<Seg>, RealAlgebraic, RealAlgebraic)], found: &Shape, tol: f64) -> f64 {
    struct ExactPiece {
        points: Option<Vec<[f64; 2]>>,
        lo: f64,
        hi: f64,
        bbox: [f64; 4],
        covered: Vec<(f64, f64)>,
    }
    let mut e: Vec<ExactPiece> = exact
        .iter()
        .map(|(s, lo, hi)| ExactPiece {
            points: float_points(s),
            lo: lo.to_f64(),
            hi: hi.to_f64(),
            bbox: s.bbox.unwrap_or([f64::NEG_INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::INFINITY]),
            covered: vec![],
        })
        .collect();
    let mut r_segs = vec![];
    for (c, contour) in found.path().contours().iter().enumerate() {
        for (k, seg) in contour.iter().enumerate() {
            if let Ok(s) = Seg::new(0, c, k, seg.clone())
                && !s.degenerate
            {
                r_segs.push(s);
            }
        }
    }
    if e.is_empty() || r_segs.is_empty() {
        return if e.is_empty() && r_segs.is_empty() { 0.0 } else { f64::INFINITY };
    }
    let mut worst: f64 = 0.0;
    let mut unmatched: Vec<FloatPiece> = vec![];
    // the best exact piece for a float curve `r`: (bound, piece, a, b)
    let best_match = |r: &[[f64; 2]], e: &[ExactPiece]| -> Option<(f64, usize, f64, f64)> {
        let (r0, r1) = (r[0], r[r.len() - 1]);
        let mut best: Option<(f64, usize, f64, f64)> = None;
        for (i, p) in e.iter().enumerate() {
            let Some(ps) = &p.points else { continue };
            let b = p.bbox;
            let slack = tol.max(best.map_or(f64::INFINITY, |x| x.0)).min(1e300);
            let near = |q: [f64; 2]| {
                q[0] >= b[0] - slack && q[0] <= b[2] + slack && q[1] >= b[1] - slack && q[1] <= b[3] + slack
            };
            if !(near(r0) && near(r1)) {
                continue;
            }
            let (lo, hi) = (p.lo.min(p.hi), p.lo.max(p.hi));
            let span = (hi - lo).max(1e-12);
            let (a, bb) = (
                nearest(ps, r0, lo - 1e-9 * span, hi + 1e-9 * span),
                nearest(ps, r1, lo - 1e-9 * span, hi + 1e-9 * span),
            );
            if (a - bb).abs() < 1e-15 {
                continue;
            }
            let d = matched_bound(r, ps, a, bb);
            if best.is_none_or(|x| d < x.0) {
                best = Some((d, i, a, bb));
            }
        }
        best
    };
    // the exact vertices (piece ends), where a float segment may span several exact pieces
    let ends: Vec<[f64; 2]> = e
        .iter()
        .filter_map(|p| p.points.as_ref().map(|ps| [point_of(ps, p.lo), point_of(ps, p.hi)]))
        .flatten()
        .collect();
    for s in &r_segs {
        let Some(r) = float_points(s) else {
            unmatched.push(FloatPiece::new(s, 0.0, 1.0));
            continue;
        };
        let whole = best_match(&r, &e).filter(|m| m.0 <= tol);
        // cut at the exact vertices lying on the segment when no one piece follows it
        let parts: Vec<(f64, f64)> = if whole.is_some() {
            vec![(0.0, 1.0)]
        } else {
            let mut cuts: Vec<f64> = ends
                .iter()
                .filter_map(|q| {
                    let t = nearest(&r, *q, 0.0, 1.0);
                    (dist(point_of(&r, t), *q) <= tol && t > 1e-12 && t < 1.0 - 1e-12).then_some(t)
                })
                .collect();
            cuts.extend([0.0, 1.0]);
            cuts.sort_by(f64::total_cmp);
            cuts.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
            cuts.windows(2).map(|w| (w[0], w[1])).collect()
        };
        for (u0, u1) in parts {
            let sub = if (u0, u1) == (0.0, 1.0) { r.clone() } else { sub_points(&r, u0, u1) };
            match best_match(&sub, &e) {
                Some((d, i, a, b)) if d <= tol.max(1e-300) * 1e6 => {
                    worst = worst.max(d);
                    e[i].covered.push((a.min(b), a.max(b)));
                }
                _ => unmatched.push(FloatPiece::new(s, u0, u1)),
            }
        }
    }
    // the parts of exact pieces no float segment covers
    let mut uncovered: Vec<FloatPiece> = vec![];
    for ((s, _, _), p) in exact.iter().zip(&mut e) {
        let (lo, hi) = (p.lo.min(p.hi), p.lo.max(p.hi));
        let gap = 1e-9 * (hi - lo).max(1e-12);
        p.covered.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mut at = lo;
        for &(a, b) in &p.covered {
            if a > at + gap {
                uncovered.push(FloatPiece::new(s, at, a));
            }
            at = at.max(b);
        }
        if at < hi - gap {
            uncovered.push(FloatPiece::new(s, at, hi));
        }
    }
    if unmatched.is_empty() && uncovered.is_empty() {
        return worst;
    }
    let all_e: Vec<FloatPiece> = exact.iter().map(|(s, lo, hi)| FloatPiece::new(s, lo.to_f64(), hi.to_f64())).collect();
    let all_r: Vec<FloatPiece> = r_segs.iter().map(|s| FloatPiece::new(s, 0.0, 1.0)).collect();
    worst.max(directed(&unmatched, &all_e, tol)).max(directed(&uncovered, &all_r, tol))
}
