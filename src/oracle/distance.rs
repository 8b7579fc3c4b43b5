//! The distance between the exact boundary `∂E` of a boolean result and a float result's boundary
//! `∂F`, decided: proved at most `tol`, or proved more than `tol` at an exact point — by
//! refinement, never by a cap that could answer wrongly; only the work budget ends it undecided.
//!
//! **Matching.** Each float segment (or a part of it, cut at the exact vertices near it or
//! halved) is matched with a piece `Q = E[a, b]` of an exact run, `a` and `b` the parameters
//! nearest to its ends: at a common degree, `|P(s) − Q(s)| ≤ max_i |P_i − Q_i| = δ` for every `s`
//! (the difference is a convex combination of the control points' differences), computed in
//! certified binary64 (`ball`). `δ ≤ tol` proves the part within `tol` of `∂E` and `Q` within
//! `tol` of `∂F`. A part that matches nothing is halved, unless its middle point is proved
//! farther than `tol` from `∂E` (exact root isolation: `|C(t) − q|² − tol²` has no root on any
//! run): then the distance is over `tol`.
//!
//! **Connectors and the map φ.** Consecutive parts meet at a point `p` of `∂F`; their matched
//! pieces end and start at points of `∂E` that are joined along `∂E` (the rest of a run, whole
//! short runs, through the exact vertices) by a path whose control hulls lie within `tol` of `p`.
//! This defines a continuous map `φ` from `∂F` onto a closed path on `∂E` with `|x − φ(x)| ≤ tol`,
//! so the straight homotopy from `∂F` to `φ(∂F)` stays within `tol` of `∂E`: at every point `q`
//! farther than `tol` from `∂E`, `winding(∂F, q) = winding(φ(∂F), q)`. And `φ(∂F)` runs along
//! each exact run a net number of times `c` (constant along the run); when every run has `c = 1`
//! (or every one `−1`: the float result drawn the other way; under even–odd, every `c` odd), the
//! regions agree at every point farther than `tol` from `∂E`, and every run is covered: the
//! boundaries are within `tol` both ways.
//!
//! **What is left** — runs with another count, rational segments — is bounded by refinement: a
//! part of a curve whose control hull lies within `r` of a point `m` of it, `m` within `d` of the
//! other boundary (a certified point of it), is within `d + r`; otherwise it is halved, unless
//! `m` is proved farther than `tol` from the other boundary.

use super::ball::{Ball, BallPoint, distance_up, elevate, mids, point_at, sub_points};
use crate::curve::BezierCurve;
use crate::error::{Error, Result};
use crate::num::point::{Point, Point2};
use crate::num::scalar::{rat, ratio_to_f64};
use crate::poly::Poly;
use crate::poly::algebraic::RealAlgebraic;
use crate::shape::ExactRun;
use crate::shape::segment::Seg;
use crate::work::Budget;
use num_rational::BigRational;
use num_traits::Signed;
use std::collections::{HashMap, VecDeque};
use std::sync::Arc;

/// Work units charged per candidate examined (about a microsecond each).
const UNITS: f64 = 1000.0;

/// The nearest binary64 at most `q`.
fn below(q: &BigRational) -> f64 {
    let f = ratio_to_f64(q);
    match BigRational::from_float(f) {
        Some(x) if x > *q => f.next_down(),
        _ => f,
    }
}

/// The nearest binary64 at least `q`.
fn above(q: &BigRational) -> f64 {
    let f = ratio_to_f64(q);
    match BigRational::from_float(f) {
        Some(x) if x < *q => f.next_up(),
        _ => f,
    }
}

fn exact(f: f64) -> BigRational {
    BigRational::from_float(f).expect("a finite parameter")
}

/// `[a, b]` with `a ≤ t ≤ b`, binary64.
fn enclose(t: &RealAlgebraic) -> (f64, f64) {
    match t.to_rational() {
        Some(r) => (below(r), above(r)),
        None => {
            let mut t = t.clone();
            t.refine(&BigRational::new(1.into(), num_bigint::BigInt::from(1) << 62u32));
            let (a, b) = t.interval();
            (below(&a), above(&b))
        }
    }
}

/// A curve with certified evaluation: a segment, its control points as balls when polynomial
/// (and their midpoints, for searches).
#[derive(Clone)]
struct Curve {
    seg: Arc<Seg>,
    pts: Option<Vec<BallPoint>>,
    mids: Vec<[f64; 2]>,
}

impl Curve {
    fn new(seg: Arc<Seg>) -> Self {
        let pts: Option<Vec<BallPoint>> = if seg.polynomial {
            seg.hull.as_ref().map(|ps| ps.iter().map(|p| [Ball::of(&p.x), Ball::of(&p.y)]).collect())
        } else {
            None
        };
        let mids = pts.as_ref().map(|p| mids(p)).unwrap_or_default();
        Curve { seg, pts, mids }
    }

    /// A certified point at `t`.
    fn point(&self, t: f64) -> BallPoint {
        match &self.pts {
            Some(p) => point_at(p, t),
            None => {
                let q = self.seg.point_at(&exact(t));
                [Ball::of(&q.x), Ball::of(&q.y)]
            }
        }
    }

    /// The point at `t`, binary64 (for searches).
    fn eval(&self, t: f64) -> [f64; 2] {
        if self.pts.is_some() {
            if let Some([point, ..]) = self.eval_derivatives(t) {
                return point;
            }
            if let [only] = self.mids[..] {
                return only;
            }
            let c =
                BezierCurve::new(self.mids.iter().map(|q| Point::new(q.to_vec())).collect()).expect("a control point");
            let q = c.eval(&t);
            return [q.coords[0], q.coords[1]];
        }
        let w = self.seg.w().eval_f64(t);
        [self.seg.x().eval_f64(t) / w, self.seg.y().eval_f64(t) / w]
    }

    /// The point at `t` and the first two derivatives there, binary64, by de Casteljau's
    /// levels: with `m` points left at a level of a curve of `n` control points, the second
    /// derivative is `(n−1)(n−2)·(q2 − 2q1 + q0)` when `m = 3`, the first `(n−1)·(q1 − q0)` when
    /// `m = 2` (polynomial curves of 2 to 8 control points; `None` otherwise).
    fn eval_derivatives(&self, t: f64) -> Option<[[f64; 2]; 3]> {
        let n = self.mids.len();
        if self.pts.is_none() || !(2..=8).contains(&n) {
            return None;
        }
        let mut q = [[0.0; 2]; 8];
        q[..n].copy_from_slice(&self.mids);
        let mut second = [0.0; 2];
        for m in (3..=n).rev() {
            if m == 3 {
                let k = ((n - 1) * (n - 2)) as f64;
                second = [k * (q[2][0] - 2.0 * q[1][0] + q[0][0]), k * (q[2][1] - 2.0 * q[1][1] + q[0][1])];
            }
            for i in 0..m - 1 {
                q[i] = [q[i][0] + t * (q[i + 1][0] - q[i][0]), q[i][1] + t * (q[i + 1][1] - q[i][1])];
            }
        }
        let k = (n - 1) as f64;
        let first = [k * (q[1][0] - q[0][0]), k * (q[1][1] - q[0][1])];
        let point = [q[0][0] + t * (q[1][0] - q[0][0]), q[0][1] + t * (q[1][1] - q[0][1])];
        Some([point, first, second])
    }

    /// The parameter in `[lo, hi]` of the point nearest to `q` found by 17 samples and, around
    /// the best, Newton's method on `(C(t) − q)·C'(t) = 0` while each step brings the point
    /// nearer, else a golden section search (a search: nothing is certified by it; robust where
    /// the curve is stationary, as at a control point doubling an end).
    fn nearest(&self, q: [f64; 2], lo: f64, hi: f64) -> f64 {
        let f = |t: f64| {
            let p = self.eval(t);
            (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)
        };
        let mut best = (f64::INFINITY, lo);
        for k in 0..=16 {
            let t = lo + (hi - lo) * k as f64 / 16.0;
            let d = f(t);
            if d < best.0 {
                best = (d, t);
            }
        }
        let step = (hi - lo) / 16.0;
        let (mut a, mut b) = ((best.1 - step).max(lo), (best.1 + step).min(hi));
        if let Some(t) = self.newton(q, best, a, b) {
            return t;
        }
        const G: f64 = 0.618_033_988_749_894_8;
        let (mut c, mut d) = (b - G * (b - a), a + G * (b - a));
        let (mut fc, mut fd) = (f(c), f(d));
        for _ in 0..60 {
            if fc < fd {
                b = d;
                d = c;
                fd = fc;
                c = b - G * (b - a);
                fc = f(c);
            } else {
                a = c;
                c = d;
                fc = fd;
                d = a + G * (b - a);
                fd = f(d);
            }
            if b - a <= 4.0 * f64::EPSILON * b.abs().max(1e-300) {
                break;
            }
        }
        let t = if fc < fd { c } else { d };
        if f(t) <= best.0 { t } else { best.1 }
    }

    /// Newton's method for [`Curve::nearest`] from `start = (squared distance, t)` inside
    /// `[a, b]`: the parameter where the steps stop moving, or `None` when a step leaves the
    /// bracket, does not bring the point nearer, or the curvature term makes it no descent.
    fn newton(&self, q: [f64; 2], start: (f64, f64), a: f64, b: f64) -> Option<f64> {
        let (mut d, mut t) = start;
        // near a stationary point of the curve the distance is flat in `t` to fourth order and
        // the steps stall: left to the golden section search
        let diameter =
            self.mids.iter().map(|m| (m[0] - self.mids[0][0]).hypot(m[1] - self.mids[0][1])).fold(0.0, f64::max);
        let slow = 1e-3 * diameter;
        for _ in 0..12 {
            let [p, d1, d2] = self.eval_derivatives(t)?;
            if d1[0].hypot(d1[1]) <= slow {
                return None;
            }
            let r = [p[0] - q[0], p[1] - q[1]];
            let g = r[0] * d1[0] + r[1] * d1[1];
            let h = d1[0] * d1[0] + d1[1] * d1[1] + r[0] * d2[0] + r[1] * d2[1];
            if g == 0.0 {
                return Some(t);
            }
            if h.is_nan() || h <= 0.0 {
                return None;
            }
            let next = t - g / h;
            if !(next >= a && next <= b) {
                return None;
            }
            let p = self.eval(next);
            let dn = (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2);
            if dn > d {
                return None;
            }
            if (next - t).abs() <= 4.0 * f64::EPSILON * t.abs().max(f64::MIN_POSITIVE) {
                return Some(next);
            }
            (d, t) = (dn, next);
        }
        None
    }

    /// Control points whose hull holds the curve on `[a, b]` (`None`: a rational piece whose
    /// weights change sign there, to be cut).
    fn hull(&self, a: f64, b: f64) -> Option<Vec<BallPoint>> {
        if let Some(p) = &self.pts {
            return Some(sub_points(p, a, b));
        }
        let h = self.seg.curve.homogeneous().subsegment(&exact(a), &exact(b));
        let ws: Vec<&BigRational> = h.points().iter().map(|p| &p.coords[2]).collect();
        if !(ws.iter().all(|w| w.is_positive()) || ws.iter().all(|w| w.is_negative())) {
            return None;
        }
        Some(
            h.points()
                .iter()
                .map(|p| [Ball::of(&(&p.coords[0] / &p.coords[2])), Ball::of(&(&p.coords[1] / &p.coords[2]))])
                .collect(),
        )
    }
}

fn box_of(ps: &[BallPoint]) -> [f64; 4] {
    let mut b = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];
    for p in ps {
        b[0] = b[0].min(p[0].m - p[0].r);
        b[1] = b[1].min(p[1].m - p[1].r);
        b[2] = b[2].max(p[0].m + p[0].r);
        b[3] = b[3].max(p[1].m + p[1].r);
    }
    b
}

/// A lower bound of the distance from `q` to the box `b` (the larger of the axis gaps: a search
/// filter).
fn box_distance(b: &[f64; 4], q: [f64; 2]) -> f64 {
    let dx = (b[0] - q[0]).max(q[0] - b[2]).max(0.0);
    let dy = (b[1] - q[1]).max(q[1] - b[3]).max(0.0);
    dx.max(dy) * (1.0 - 1e-12)
}

/// One run of the exact boundary, with binary64 parameters just outside (`lo_out ≤ lo`,
/// `hi_out ≥ hi`) and strictly inside (`lo < lo_in`, `hi_in < hi`) its ends.
struct Run {
    curve: Curve,
    lo: RealAlgebraic,
    hi: RealAlgebraic,
    lo_out: f64,
    hi_out: f64,
    lo_in: f64,
    hi_in: f64,
    /// The contour runs from `lo` to `hi`.
    forward: bool,
    /// The exact vertices at `lo` and at `hi`.
    lo_vertex: usize,
    hi_vertex: usize,
    bbox: [f64; 4],
}

/// A float segment.
struct FloatSeg {
    curve: Curve,
    bbox: [f64; 4],
}

/// A place on a run: one of its ends, or a binary64 parameter inside it.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Pos {
    Lo,
    Hi,
    At(f64),
}

impl Pos {
    fn key(self) -> f64 {
        match self {
            Pos::Lo => f64::NEG_INFINITY,
            Pos::Hi => f64::INFINITY,
            Pos::At(t) => t,
        }
    }
}

/// A stretch of a run that `φ(∂F)` runs along: the run, from, to.
type Trav = (usize, Pos, Pos);

/// A part of a float segment matched with a piece of a run.
#[derive(Clone, Debug)]
struct Part {
    seg: usize,
    u1: f64,
    run: usize,
    a: f64,
    b: f64,
}

/// How the distance was decided.
#[derive(Clone, Debug)]
pub(super) enum Outcome {
    /// Within `bound ≤ tol` both ways; `regions`: the regions agree at every point farther than
    /// `tol` from `∂E` (proved by the counts), `reversed`: the float result runs the other way.
    Under { bound: f64, regions: bool, reversed: bool },
    /// `point`, on the float boundary (`on_found`) or the exact one, is farther than `at_least`
    /// (`≥ tol`) from the other boundary.
    Over { point: Point2<BigRational>, on_found: bool, at_least: f64 },
}

/// The decision's state.
pub(super) struct Decider<'a> {
    runs: Vec<Run>,
    floats: Vec<FloatSeg>,
    contours: Vec<Vec<usize>>,
    tol: BigRational,
    tol_f: f64,
    evenodd: bool,
    work: f64,
    budget: &'a Budget,
    /// Per run, the places `φ(∂F)` runs along it.
    travs: Vec<Vec<(Pos, Pos)>>,
    bound: f64,
    /// The run the last matched part followed.
    hint: Option<usize>,
    /// The exact vertices (the runs' ends, just inside), binary64.
    vertices: Vec<[f64; 2]>,
}

impl<'a> Decider<'a> {
    pub(super) fn new(
        segs: &[Arc<Seg>],
        cycles: &[Vec<ExactRun>],
        found: &crate::shape::Shape,
        tol: &BigRational,
        evenodd: bool,
        budget: &'a Budget,
    ) -> Result<Self> {
        let mut runs = vec![];
        for r in cycles.iter().flatten() {
            let curve = Curve::new(segs[r.seg].clone());
            let ((lo_out, lo_up), (hi_down, hi_out)) = (enclose(&r.lo), enclose(&r.hi));
            let (lo_in, hi_in) = (lo_up.next_up(), hi_down.next_down());
            let bbox = match curve.hull(lo_out, hi_out) {
                Some(h) => box_of(&h),
                None => [f64::NEG_INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::INFINITY],
            };
            let (lo_vertex, hi_vertex) = if r.forward { (r.start, r.end) } else { (r.end, r.start) };
            runs.push(Run {
                curve,
                lo: r.lo.clone(),
                hi: r.hi.clone(),
                lo_out,
                hi_out,
                lo_in,
                hi_in,
                forward: r.forward,
                lo_vertex,
                hi_vertex,
                bbox,
            });
        }
        let mut floats = vec![];
        let mut contours = vec![];
        for (c, contour) in found.path().contours().iter().enumerate() {
            let mut ids = vec![];
            for (k, seg) in contour.iter().enumerate() {
                let s = Seg::new(0, c, k, seg.clone())?;
                if s.degenerate {
                    continue;
                }
                let curve = Curve::new(Arc::new(s));
                let bbox = match curve.hull(0.0, 1.0) {
                    Some(h) => box_of(&h),
                    None => [f64::NEG_INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::INFINITY],
                };
                ids.push(floats.len());
                floats.push(FloatSeg { curve, bbox });
            }
            if !ids.is_empty() {
                contours.push(ids);
            }
        }
        let travs = vec![vec![]; runs.len()];
        let vertices = runs
            .iter()
            .flat_map(|e: &Run| [e.lo_in, e.hi_in].map(|t| e.curve.eval(t.clamp(0.0, 1.0))))
            .filter(|v| v[0].is_finite() && v[1].is_finite())
            .collect();
        Ok(Decider {
            runs,
            floats,
            contours,
            tol: tol.clone(),
            tol_f: below(tol),
            evenodd,
            work: 0.0,
            budget,
            travs,
            bound: 0.0,
            hint: None,
            vertices,
        })
    }

    fn charge(&mut self, units: f64) -> Result<()> {
        self.work += units;
        self.budget.check("deciding the distance between the exact and the float boundary", self.work)
    }

    /// Decides the distance (see the module documentation).
    pub(super) fn decide(mut self) -> Result<Outcome> {
        let mut continuous = true;
        for c in 0..self.contours.len() {
            let mut parts: Vec<Part> = vec![];
            let mut broken = false;
            for k in 0..self.contours[c].len() {
                let j = self.contours[c][k];
                if self.floats[j].curve.pts.is_none() {
                    // a rational float segment: bounded by refinement, no part of φ
                    if let Some(o) = self.directed_float(j)? {
                        return Ok(o);
                    }
                    broken = true;
                    continue;
                }
                if let Some(o) = self.match_range(j, 0.0, 1.0, &mut parts)? {
                    return Ok(o);
                }
            }
            continuous &= !broken;
            for p in &parts {
                self.travs[p.run].push((Pos::At(p.a), Pos::At(p.b)));
            }
            if broken {
                continue;
            }
            for i in 0..parts.len() {
                let (x, y) = (&parts[i], &parts[(i + 1) % parts.len()]);
                let p = self.floats[x.seg].curve.point(x.u1);
                match self.connector(p, (x.run, x.b), (y.run, y.a)) {
                    Some(ts) => {
                        for (r, from, to) in ts {
                            self.travs[r].push((from, to));
                        }
                    }
                    None => continuous = false,
                }
            }
        }
        // the net counts, and the runs they leave uncovered
        let counts: Vec<Option<i64>> = (0..self.runs.len()).map(|i| self.count(i)).collect();
        for (i, c) in counts.iter().enumerate() {
            if c.is_none_or(|c| c == 0)
                && let Some(o) = self.directed_exact(i)?
            {
                return Ok(o);
            }
        }
        let sign = counts.first().copied().flatten().unwrap_or(1);
        let regions = continuous
            && counts.iter().all(|c| match c {
                Some(c) if self.evenodd => c % 2 != 0,
                Some(c) => *c == sign && sign.abs() == 1,
                None => false,
            });
        Ok(Outcome::Under { bound: self.bound, regions, reversed: regions && !self.evenodd && sign == -1 })
    }

    /// Matches `[u0, u1]` of float segment `j`, cutting it until every part matches, or finds
    /// a point of it farther than `tol` from `∂E`.
    fn match_range(&mut self, j: usize, u0: f64, u1: f64, out: &mut Vec<Part>) -> Result<Option<Outcome>> {
        self.match_at(j, u0, u1, out, 0)
    }

    fn match_at(&mut self, j: usize, u0: f64, u1: f64, out: &mut Vec<Part>, depth: usize) -> Result<Option<Outcome>> {
        self.charge(UNITS * (1 + self.runs.len() / 8) as f64)?;
        if let Some(p) = self.try_match(j, u0, u1) {
            out.push(p);
            return Ok(None);
        }
        let um = u0 + (u1 - u0) / 2.0;
        // a point far from ∂E ends the matching; looked for at every third level (a search)
        if depth.is_multiple_of(3)
            && let Some(o) = self.float_point_far(j, um)?
        {
            return Ok(Some(o));
        }
        let cut = self.vertex_cut(j, u0, u1).unwrap_or(um);
        if !(cut > u0 && cut < u1) {
            if let Some(o) = self.float_point_far(j, um)? {
                return Ok(Some(o));
            }
            let p = self.floats[j].curve.eval(u0);
            return Err(Error::InvalidArgument {
                message: format!(
                    "the float boundary near ({}, {}) is as far from the exact one as the tolerance, to binary64 \
                     resolution: the distance is not decided",
                    p[0], p[1]
                ),
            });
        }
        if let Some(o) = self.match_at(j, u0, cut, out, depth + 1)? {
            return Ok(Some(o));
        }
        self.match_at(j, cut, u1, out, depth + 1)
    }

    /// The run piece nearest to part `[u0, u1]` of float segment `j` when their control points
    /// pair within `tol`.
    fn try_match(&mut self, j: usize, u0: f64, u1: f64) -> Option<Part> {
        let p = sub_points(self.floats[j].curve.pts.as_ref()?, u0, u1);
        let (p0, p1) = ([p[0][0].m, p[0][1].m], [p[p.len() - 1][0].m, p[p.len() - 1][1].m]);
        let mut best: Option<(f64, usize, f64, f64)> = None;
        // the run the last part matched first; the first piece within tol is a proof
        let order = self.hint.into_iter().chain((0..self.runs.len()).filter(|&i| Some(i) != self.hint));
        for i in order {
            if best.is_some_and(|b| b.0 <= self.tol_f) {
                break;
            }
            let e = &self.runs[i];
            let Some(q) = &e.curve.pts else { continue };
            let slack = best.map_or(self.tol_f, |b| b.0.min(self.tol_f));
            if box_distance(&e.bbox, p0) > slack || box_distance(&e.bbox, p1) > slack || e.lo_in >= e.hi_in {
                continue;
            }
            // the nearest parameters, and the run's ends where they are near too (a run whose
            // ends are one vertex: the nearest parameter alone cannot tell which end)
            let candidates = |q: [f64; 2]| {
                let mut ts = vec![e.curve.nearest(q, e.lo_in, e.hi_in)];
                for t in [e.lo_in, e.hi_in] {
                    let v = e.curve.eval(t);
                    if (v[0] - q[0]).hypot(v[1] - q[1]) <= 2.0 * self.tol_f && !ts.contains(&t) {
                        ts.push(t);
                    }
                }
                ts
            };
            for a in candidates(p0) {
                for b in candidates(p1) {
                    if a == b {
                        continue;
                    }
                    let mut sub = sub_points(q, a, b);
                    let mut pp = p.clone();
                    while sub.len() < pp.len() {
                        sub = elevate(&sub);
                    }
                    while pp.len() < sub.len() {
                        pp = elevate(&pp);
                    }
                    let d = pp.iter().zip(&sub).map(|(x, y)| distance_up(*x, *y)).fold(0.0, f64::max);
                    if best.is_none_or(|b| d < b.0) {
                        best = Some((d, i, a, b));
                    }
                }
            }
        }
        let (d, run, a, b) = best.filter(|b| b.0 <= self.tol_f)?;
        self.bound = self.bound.max(d);
        self.hint = Some(run);
        Some(Part { seg: j, u1, run, a, b })
    }

    /// A parameter inside `(u0, u1)` where float segment `j` passes an exact vertex within
    /// `2·tol`, the one nearest to the middle.
    fn vertex_cut(&self, j: usize, u0: f64, u1: f64) -> Option<f64> {
        let f = &self.floats[j].curve;
        let part = box_of(&sub_points(f.pts.as_ref()?, u0, u1));
        let margin = (u1 - u0) * 1e-6;
        let mid = u0 + (u1 - u0) / 2.0;
        let mut best: Option<f64> = None;
        for &v in &self.vertices {
            if box_distance(&part, v) > 2.0 * self.tol_f {
                continue;
            }
            let u = f.nearest(v, u0, u1);
            let q = f.eval(u);
            if (q[0] - v[0]).hypot(q[1] - v[1]) <= 2.0 * self.tol_f + 1e-300
                && u > u0 + margin
                && u < u1 - margin
                && best.is_none_or(|b| (u - mid).abs() < (b - mid).abs())
            {
                best = Some(u);
            }
        }
        best
    }

    /// The place on `∂E` nearest to `q` found by search: its distance estimate, and a certified
    /// upper bound of the distance (to the certified point there).
    fn nearest_exact(&self, q: BallPoint) -> (f64, f64) {
        let qm = [q[0].m, q[1].m];
        let (mut est, mut up) = (f64::INFINITY, f64::INFINITY);
        let order = self.hint.into_iter().chain((0..self.runs.len()).filter(|&i| Some(i) != self.hint));
        for e in order.map(|i| &self.runs[i]) {
            if e.lo_in >= e.hi_in || box_distance(&e.bbox, qm) > est {
                continue;
            }
            let t = e.curve.nearest(qm, e.lo_in, e.hi_in);
            let p = e.curve.eval(t);
            let d = (p[0] - qm[0]).hypot(p[1] - qm[1]);
            if d < est {
                est = d;
                up = up.min(distance_up(e.curve.point(t), q));
            }
        }
        (est, up)
    }

    /// The same for `∂F`.
    fn nearest_float(&self, q: BallPoint) -> (f64, f64) {
        let qm = [q[0].m, q[1].m];
        let (mut est, mut up) = (f64::INFINITY, f64::INFINITY);
        for f in &self.floats {
            if box_distance(&f.bbox, qm) > est {
                continue;
            }
            let t = f.curve.nearest(qm, 0.0, 1.0);
            let p = f.curve.eval(t);
            let d = (p[0] - qm[0]).hypot(p[1] - qm[1]);
            if d < est {
                est = d;
                up = up.min(distance_up(f.curve.point(t), q));
            }
        }
        (est, up)
    }

    /// The exact pieces of `∂E` (or of `∂F`), for proofs: segments with rational parameter
    /// ranges holding them.
    fn pieces(&self, exact_side: bool) -> Vec<(&Seg, BigRational, BigRational)> {
        if exact_side {
            self.runs.iter().map(|e| (&*e.curve.seg, e.lo.interval().0, e.hi.interval().1)).collect()
        } else {
            self.floats.iter().map(|f| (&*f.curve.seg, rat(0), rat(1))).collect()
        }
    }

    /// The point of float segment `j` at `u` when it is proved farther than `tol` from `∂E`.
    fn float_point_far(&mut self, j: usize, u: f64) -> Result<Option<Outcome>> {
        let (est, _) = self.nearest_exact(self.floats[j].curve.point(u));
        if est <= self.tol_f * (1.0 + 1e-9) {
            return Ok(None);
        }
        self.charge(UNITS * 50.0)?;
        let q = self.floats[j].curve.seg.point_at(&exact(u));
        Ok(self.proved_far(q, est, true))
    }

    /// `Over` at `q` (on the float boundary when `on_found`) when `q` is proved farther than
    /// `tol` from the other boundary: the distance bound reported is a round number below the
    /// estimate `est` when that is proved too, else `tol`.
    fn proved_far(&self, q: Point2<BigRational>, est: f64, on_found: bool) -> Option<Outcome> {
        let pieces = self.pieces(on_found);
        if !far_from(&pieces, &q, &self.tol) {
            return None;
        }
        let mut at_least = ratio_to_f64(&self.tol);
        if est.is_finite() {
            let round: f64 = format!("{:.2e}", est * 0.99).parse().unwrap_or(0.0);
            if let Some(r) = BigRational::from_float(round)
                && r > self.tol
                && far_from(&pieces, &q, &r)
            {
                at_least = round;
            }
        } else {
            at_least = f64::INFINITY;
        }
        Some(Outcome::Over { point: q, on_found, at_least })
    }

    /// A path along `∂E` from `from` to `to` whose control hulls lie within `tol` of `p`.
    fn connector(&mut self, p: BallPoint, from: (usize, f64), to: (usize, f64)) -> Option<Vec<(usize, Pos, Pos)>> {
        let reach = |s: &Self, i: usize, x0: f64, x1: f64| -> Option<f64> {
            let h = s.runs[i].curve.hull(x0.min(x1), x0.max(x1))?;
            let d = h.iter().map(|c| distance_up(*c, p)).fold(0.0, f64::max);
            (d <= s.tol_f).then_some(d)
        };
        let mut worst = 0.0f64;
        if from.0 == to.0
            && let Some(d) = reach(self, from.0, from.1, to.1)
        {
            self.bound = self.bound.max(d);
            return Some(vec![(from.0, Pos::At(from.1), Pos::At(to.1))]);
        }
        // breadth-first over the exact vertices
        let (e1, e2) = (&self.runs[from.0], &self.runs[to.0]);
        let mut starts = vec![];
        if let Some(d) = reach(self, from.0, e1.lo_out, from.1) {
            starts.push((e1.lo_vertex, (from.0, Pos::At(from.1), Pos::Lo), d));
        }
        if let Some(d) = reach(self, from.0, from.1, e1.hi_out) {
            starts.push((e1.hi_vertex, (from.0, Pos::At(from.1), Pos::Hi), d));
        }
        let mut goals: HashMap<usize, ((usize, Pos, Pos), f64)> = HashMap::new();
        if let Some(d) = reach(self, to.0, e2.lo_out, to.1) {
            goals.insert(e2.lo_vertex, ((to.0, Pos::Lo, Pos::At(to.1)), d));
        }
        if let Some(d) = reach(self, to.0, to.1, e2.hi_out) {
            goals.entry(e2.hi_vertex).or_insert(((to.0, Pos::Hi, Pos::At(to.1)), d));
        }
        if starts.is_empty() || goals.is_empty() {
            return None;
        }
        let pm = [p[0].m, p[1].m];
        let mut edges: HashMap<usize, Vec<(usize, Trav, f64)>> = HashMap::new();
        for i in 0..self.runs.len() {
            let e = &self.runs[i];
            if box_distance(&e.bbox, pm) > self.tol_f {
                continue;
            }
            if let Some(d) = reach(self, i, e.lo_out, e.hi_out) {
                edges.entry(e.lo_vertex).or_default().push((e.hi_vertex, (i, Pos::Lo, Pos::Hi), d));
                edges.entry(e.hi_vertex).or_default().push((e.lo_vertex, (i, Pos::Hi, Pos::Lo), d));
            }
        }
        let mut parent: HashMap<usize, Option<(usize, Trav, f64)>> = HashMap::new();
        let mut queue = VecDeque::new();
        let mut first: HashMap<usize, ((usize, Pos, Pos), f64)> = HashMap::new();
        for (v, t, d) in starts {
            if let std::collections::hash_map::Entry::Vacant(slot) = parent.entry(v) {
                slot.insert(None);
                first.insert(v, (t, d));
                queue.push_back(v);
            }
        }
        while let Some(v) = queue.pop_front() {
            if let Some((last, dl)) = goals.get(&v).cloned() {
                let mut path = vec![last];
                worst = worst.max(dl);
                let mut at = v;
                while let Some(Some((prev, t, d))) = parent.get(&at).cloned() {
                    path.push(t);
                    worst = worst.max(d);
                    at = prev;
                }
                let (t, d) = first[&at];
                path.push(t);
                worst = worst.max(d);
                path.reverse();
                self.bound = self.bound.max(worst);
                return Some(path);
            }
            for (w, t, d) in edges.get(&v).cloned().unwrap_or_default() {
                if let std::collections::hash_map::Entry::Vacant(slot) = parent.entry(w) {
                    slot.insert(Some((v, t, d)));
                    queue.push_back(w);
                }
            }
        }
        None
    }

    /// The net number of times `φ(∂F)` runs along run `i` in the contour's direction, when it
    /// is the same along the whole run.
    fn count(&self, i: usize) -> Option<i64> {
        let travs = &self.travs[i];
        if travs.is_empty() {
            return Some(0);
        }
        let mut keys: Vec<f64> = travs.iter().flat_map(|(a, b)| [a.key(), b.key()]).collect();
        keys.extend([f64::NEG_INFINITY, f64::INFINITY]);
        keys.sort_by(f64::total_cmp);
        keys.dedup();
        let forward = self.runs[i].forward;
        // a stretch `lo → hi` covers the windows between consecutive keys from `lo` to `hi`:
        // ±1 added at `lo`'s index and taken off at `hi`'s, summed along the keys
        let index = |k: f64| keys.binary_search_by(|x| x.total_cmp(&k)).expect("a key");
        let mut step = vec![0i64; keys.len()];
        for (a, b) in travs {
            let (lo, hi) = if a.key() <= b.key() { (a.key(), b.key()) } else { (b.key(), a.key()) };
            let sign = if (b.key() > a.key()) == forward { 1 } else { -1 };
            step[index(lo)] += sign;
            step[index(hi)] -= sign;
        }
        let mut count = None;
        let mut net = 0i64;
        for s in &step[..keys.len() - 1] {
            net += s;
            if count.is_some_and(|c| c != net) {
                return None;
            }
            count = Some(net);
        }
        count
    }

    /// Bounds run `i` against `∂F` by refinement.
    fn directed_exact(&mut self, i: usize) -> Result<Option<Outcome>> {
        let (lo, hi) = (self.runs[i].lo_out, self.runs[i].hi_out);
        self.directed(true, i, lo, hi)
    }

    /// Bounds the rational float segment `j` against `∂E` by refinement.
    fn directed_float(&mut self, j: usize) -> Result<Option<Outcome>> {
        self.directed(false, j, 0.0, 1.0)
    }

    /// Every point of the curve (run `k` when `exact_side`, else float segment `k`) on
    /// `[lo, hi]` within `tol` of the other boundary, or a point of it proved farther.
    fn directed(&mut self, exact_side: bool, k: usize, lo: f64, hi: f64) -> Result<Option<Outcome>> {
        let (curve, lo_in, hi_in) = if exact_side {
            let e = &self.runs[k];
            (e.curve.clone(), e.lo_in, e.hi_in)
        } else {
            (self.floats[k].curve.clone(), 0.0, 1.0)
        };
        let mut stack = vec![(lo, hi)];
        while let Some((a, b)) = stack.pop() {
            self.charge(UNITS * (1 + (self.floats.len() + self.runs.len()) / 8) as f64)?;
            let m = a + (b - a) / 2.0;
            let inside = m >= lo_in && m <= hi_in;
            if exact_side && let Some(d) = self.try_cover(&curve, a, b) {
                self.bound = self.bound.max(d);
                continue;
            }
            let hull = curve.hull(a, b);
            let c = curve.point(m);
            let (est, up) = if exact_side { self.nearest_float(c) } else { self.nearest_exact(c) };
            if let Some(h) = &hull {
                let r = h.iter().map(|p| distance_up(*p, c)).fold(0.0, f64::max);
                let total = up + r;
                if total <= self.tol_f {
                    self.bound = self.bound.max(total);
                    continue;
                }
            }
            if inside && est > self.tol_f * (1.0 + 1e-9) {
                self.charge(UNITS * 50.0)?;
                let q = curve.seg.point_at(&exact(m));
                if let Some(o) = self.proved_far(q, est, !exact_side) {
                    return Ok(Some(o));
                }
            }
            if !(m > a && m < b) {
                let p = curve.eval(a);
                return Err(Error::InvalidArgument {
                    message: format!(
                        "the boundary near ({}, {}) is as far from the other as the tolerance, to binary64 \
                         resolution: the distance is not decided",
                        p[0], p[1]
                    ),
                });
            }
            stack.push((m, b));
            stack.push((a, m));
        }
        Ok(None)
    }
}

impl Decider<'_> {
    /// The piece of a float segment nearest to `[a, b]` of the exact curve when their control
    /// points pair within `tol`: its bound.
    fn try_cover(&self, curve: &Curve, a: f64, b: f64) -> Option<f64> {
        let q = sub_points(curve.pts.as_ref()?, a, b);
        let (q0, q1) = ([q[0][0].m, q[0][1].m], [q[q.len() - 1][0].m, q[q.len() - 1][1].m]);
        let mut best: Option<f64> = None;
        for f in &self.floats {
            let Some(p) = &f.curve.pts else { continue };
            let slack = best.unwrap_or(self.tol_f).min(self.tol_f);
            if box_distance(&f.bbox, q0) > slack || box_distance(&f.bbox, q1) > slack {
                continue;
            }
            let (ta, tb) = (f.curve.nearest(q0, 0.0, 1.0), f.curve.nearest(q1, 0.0, 1.0));
            if ta == tb {
                continue;
            }
            let mut sub = sub_points(p, ta, tb);
            let mut qq = q.clone();
            while sub.len() < qq.len() {
                sub = elevate(&sub);
            }
            while qq.len() < sub.len() {
                qq = elevate(&qq);
            }
            let d = qq.iter().zip(&sub).map(|(x, y)| distance_up(*x, *y)).fold(0.0, f64::max);
            if best.is_none_or(|b| d < b) {
                best = Some(d);
            }
        }
        best.filter(|d| *d <= self.tol_f)
    }
}

/// `|C(t) − q| > r` for every `t` of every piece, proved exactly: `(X − q_x W)² + (Y − q_y W)²
/// − r² W²` has no root in the piece's parameter range and is positive there.
pub(super) fn far_from(pieces: &[(&Seg, BigRational, BigRational)], q: &Point2<BigRational>, r: &BigRational) -> bool {
    let (qf, rf) = ([ratio_to_f64(&q.x), ratio_to_f64(&q.y)], ratio_to_f64(r));
    for (s, a, b) in pieces {
        if let Some([x0, y0, x1, y1]) = s.bbox
            && (qf[0] < x0 - 2.0 * rf - 1e-300
                || qf[0] > x1 + 2.0 * rf + 1e-300
                || qf[1] < y0 - 2.0 * rf - 1e-300
                || qf[1] > y1 + 2.0 * rf + 1e-300)
        {
            continue; // the box is farther than r (with room for rounding)
        }
        let fx = s.x() - &s.w().scale(&q.x);
        let fy = s.y() - &s.w().scale(&q.y);
        let g: Poly<BigRational> = &(&(&fx * &fx) + &(&fy * &fy)) - &(s.w() * s.w()).scale(&(r * r));
        if g.is_zero() || !RealAlgebraic::roots_in(&g, a, b).is_empty() {
            return false;
        }
        if g.eval(a).is_negative() {
            return false;
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rational::RationalBezier;

    fn curve(points: &[(i64, i64)]) -> Curve {
        let ps = points.iter().map(|&(x, y)| Point::new(vec![rat(x), rat(y)])).collect();
        let c = RationalBezier::new(ps, vec![rat(1); points.len()]).unwrap();
        Curve::new(Arc::new(Seg::new(0, 0, 0, c).unwrap()))
    }

    #[test]
    fn derivatives_of_a_quadratic_and_a_cubic_are_exact_at_dyadic_parameters() {
        // (0,0) (0,1) (2,2): C(t) = (2t², 2t), C' = (4t, 2), C'' = (4, 0)
        let q = curve(&[(0, 0), (0, 1), (2, 2)]);
        assert_eq!(q.eval_derivatives(0.5), Some([[0.5, 1.0], [2.0, 2.0], [4.0, 0.0]]));
        // (0,0) (1,0) (2,0) (3,6): x = 3t, y = 6t³: C' = (3, 18t²), C'' = (0, 36t)
        let c = curve(&[(0, 0), (1, 0), (2, 0), (3, 6)]);
        assert_eq!(c.eval_derivatives(0.5), Some([[1.5, 0.75], [3.0, 4.5], [0.0, 18.0]]));
        assert_eq!(c.eval(0.25), [0.75, 6.0 / 64.0]);
    }

    #[test]
    fn nearest_finds_the_foot_of_the_perpendicular() {
        // the parabola (2t², 2t) and the point (0, 1): the squared distance 4t⁴ + (2t − 1)² is
        // least where its derivative 16t³ + 8t − 4 vanishes
        let q = curve(&[(0, 0), (0, 1), (2, 2)]);
        let t = q.nearest([0.0, 1.0], 0.0, 1.0);
        assert!((16.0 * t * t * t + 8.0 * t - 4.0).abs() < 1e-12, "{t}");
    }
}
