//! The exact arrangement of the segments of several closed paths.
//!
//! 1. **Pairs** (the private `pairs` module). Every pair of segments whose outward-rounded boxes meet is decided: two
//!    segments that share an end point `P` and lie on opposite sides of a line through `P`
//!    (every other control point strictly on its side: their convex hulls meet only at `P`)
//!    meet only there — the common case of neighbours in a contour, decided without a
//!    resultant; two segments whose control hulls are strictly separated by a line meet nowhere;
//!    every other pair goes to [`crate::intersect::intersect_within`] (isolated points, tangencies
//!    and shared arcs, exactly). Each segment is checked for self-intersections unless its
//!    hodograph lies in a closed half-plane with one vector strictly inside (then it is monotone
//!    in that direction and injective).
//! 2. **Split.** Each segment is cut at every parameter where it meets anything (and at 0 and 1):
//!    its edges are the pieces between consecutive cuts. Points are identified by the records
//!    that produced them (a union–find over (segment, parameter)), so a vertex where three or
//!    more curves meet is one vertex, and an irrational vertex is never rounded.
//! 3. **Merge.** Pieces on a shared arc are one edge that records every input piece it carries,
//!    with its direction relative to the edge.
//! 4. **Sides.** For each edge, the winding number of every input on its left and on its right:
//!    the winding number by a ray from a rational point inside the edge toward its left, not
//!    counting the crossings at the origin (see the private `ray` module), and the right one
//!    from `left − right = Σ ±1` over the pieces the edge carries (`+1` forwards). Edges joined
//!    at a vertex of degree 2 bound the same two faces, so one ray serves a whole chain.
//! 5. **Faces** (on demand): the edges around each vertex in counter-clockwise order (see the
//!    private `germ` module), each face boundary traced with the face on its left; a cycle whose
//!    left side has winding number 1 around itself is the outer boundary of a bounded face,
//!    the others are inner boundaries, given to the innermost outer boundary around them.

use super::build::{Link, build, chain_starts, sides};
use super::germ::{Angle, Germ, compare_tangent};
use super::graph::{Arrangement, Edge, Face, HalfEdge, InputPiece, Location, Vertex};
use super::pairs::{Visit, easy_pair, injective, sweep_pairs};
use super::ray::{Axis, Origin, Piece, RayWinding, winding};
use super::segment::Seg;
use crate::error::{Error, Result};
use crate::intersect::Domain;
use crate::num::point::Point2;
use crate::num::scalar::rat;
use crate::path::ClosedPath;
use crate::poly::algebraic::RealAlgebraic;
use crate::work::Budget;
use num_rational::BigRational;
use num_traits::Zero;
use std::cmp::Ordering;

/// Most segments over all inputs of one arrangement.
pub const MAX_ARRANGEMENT_SEGMENTS: usize = 50_000;

/// A rational strictly inside `(lo, hi)` where the segment's tangent does not vanish.
fn inner_parameter(s: &Seg, lo: &RealAlgebraic, hi: &RealAlgebraic) -> BigRational {
    let mut t = RealAlgebraic::rational_between(lo, hi);
    for _ in 0..64 {
        let d = s.direction_at(&t);
        if !(d.x.is_zero() && d.y.is_zero()) {
            return t;
        }
        t = RealAlgebraic::rational_between(lo, &RealAlgebraic::from(t));
    }
    t // a curve whose tangent vanishes on an interval is a point, excluded before
}

impl Arrangement {
    /// The arrangement of the inputs' segments, with the estimated work of every resultant pair,
    /// self-intersection and side winding number checked against `budget` before any of them
    /// starts.
    ///
    /// # Errors
    /// [`Error::TooLarge`] beyond 50,000 (`MAX_ARRANGEMENT_SEGMENTS`); [`Error::WorkLimit`] over the
    /// budget ([`Budget::unlimited`] for no limit); the errors of [`crate::intersect::intersect`]
    /// and [`crate::intersect::self_intersect`] for a pair or a segment (a curve that traces
    /// a curve more than once off a line); [`Error::InvalidArgument`] when two overlapping
    /// segments are split inconsistently (a defect, reported rather than answered wrongly).
    pub fn new(inputs: &[super::Shape], budget: &Budget) -> Result<Self> {
        Self::priced(inputs, budget)
    }

    fn priced(inputs: &[super::Shape], budget: &Budget) -> Result<Self> {
        let paths: Vec<&ClosedPath> = inputs.iter().map(|s| s.path()).collect();
        let total: usize = paths.iter().map(|p| p.segments()).sum();
        if total > MAX_ARRANGEMENT_SEGMENTS {
            return Err(Error::TooLarge {
                what: "segments in an arrangement",
                value: total,
                limit: MAX_ARRANGEMENT_SEGMENTS,
            });
        }
        let mut segs = vec![];
        let mut contours = vec![];
        for (i, p) in paths.iter().enumerate() {
            let mut cs = vec![];
            for (c, contour) in p.contours().iter().enumerate() {
                let mut ids = vec![];
                for (k, curve) in contour.iter().enumerate() {
                    ids.push(segs.len());
                    segs.push(std::sync::Arc::new(Seg::new(i, c, k, curve.clone())?));
                }
                cs.push(ids);
            }
            contours.push(cs);
        }
        // 1. the candidate pairs, counted from the boxes before any is collected
        let screening = super::estimate::survey(&segs, budget)?;
        // the next live segment of each segment in its contour: their joint needs no link
        let mut next_live = vec![usize::MAX; segs.len()];
        for cs in &contours {
            for c in cs {
                let live: Vec<usize> = c.iter().copied().filter(|&k| !segs[k].degenerate).collect();
                for (i, &k) in live.iter().enumerate() {
                    next_live[k] = live[(i + 1) % live.len()];
                }
            }
        }
        // 2. decide the easy pairs, price the rest as they are found
        let mut easy: Vec<((usize, usize), Link)> = vec![];
        let mut general = vec![];
        let mut estimate = screening;
        // pairs that share no end point: each crossing splits chains of edges (rays below)
        let mut crossing = 0usize;
        sweep_pairs(&segs, &mut |v| {
            let Visit::Pair(a, b) = v else { return true };
            match easy_pair(&segs[a], &segs[b]) {
                Some(found) => {
                    let joint = |s: &RealAlgebraic, t: &RealAlgebraic| {
                        let (zero, one) = (rat(0), rat(1));
                        (next_live[a] == b && s.to_rational() == Some(&one) && t.to_rational() == Some(&zero))
                            || (next_live[b] == a && s.to_rational() == Some(&zero) && t.to_rational() == Some(&one))
                    };
                    easy.extend(
                        found.into_iter().filter(|(s, t)| !joint(s, t)).map(|(s, t)| ((a, b), Link::Point(a, s, b, t))),
                    )
                }
                None => {
                    general.push((a, b));
                    estimate += super::estimate::pair(&segs[a], &segs[b]);
                    let (sa, sb) = (&segs[a], &segs[b]);
                    let neighbours =
                        sa.end == sb.start || sa.start == sb.end || sa.start == sb.start || sa.end == sb.end;
                    crossing += usize::from(!neighbours);
                }
            }
            // past the budget, the rest of the pairs need not be looked at
            estimate <= super::estimate::counted_up_to(budget)
        });
        general.sort_unstable();
        easy.sort_by_key(|(key, _)| *key);
        let mut links: Vec<Link> = easy.into_iter().map(|(_, l)| l).collect();
        let selfs: Vec<usize> = (0..segs.len()).filter(|&k| !segs[k].degenerate && !injective(&segs[k])).collect();
        estimate += selfs.iter().map(|&k| super::estimate::own(&segs[k])).sum::<f64>();
        // a ray per chain of edges: one per contour, and about three more per two crossing pairs
        let ray = super::estimate::ray(&segs);
        let contours_live = contours.iter().flatten().filter(|c| c.iter().any(|&k| !segs[k].degenerate)).count();
        let rays = contours_live + crossing * 3 / 2;
        estimate += rays as f64 * ray;
        let count = segs.len();
        let what = |pairs: usize| format!("the arrangement of {count} segments ({pairs} pairs to solve)");
        budget.check(what(general.len()), estimate)?;
        let unlimited = Budget::unlimited();
        for &(a, b) in &general {
            let r = crate::intersect::intersect(&segs[a].curve, &segs[b].curve, Domain::Unit, &unlimited)
                .map_err(|e| located(e, &segs[a], Some(&segs[b])))?;
            for i in r.intersections {
                links.push(Link::Point(a, i.s, b, i.t));
            }
            for o in r.overlaps {
                links.push(Link::Arc(a, o.s, b, o.t));
            }
        }
        for &k in &selfs {
            let r = crate::intersect::self_intersect(&segs[k].curve, Domain::Unit, &unlimited)
                .map_err(|e| located(e, &segs[k], None))?;
            for i in r.intersections {
                links.push(Link::Point(k, i.s, k, i.t));
            }
            for o in r.overlaps {
                links.push(Link::Arc(k, o.s, k, o.t));
            }
        }
        let mut arr = build(segs, inputs.len(), contours, links)?;
        // 3. the sides: one ray per chain of edges, priced now that the chains are known
        let chains = chain_starts(&arr).len();
        budget.check(what(general.len()), estimate + (chains.saturating_sub(rays)) as f64 * ray)?;
        sides(&mut arr)?;
        Ok(arr)
    }

    /// The vertices, in order of first appearance along the inputs' segments. Each point is
    /// exact (rational, or real algebraic where curves cross at an irrational point).
    ///
    /// # Example
    /// ```
    /// use casteljau::shape::{Arrangement, Shape};
    /// // the diagonals of the unit square cross at (1/2, 1/2); the parabola y = 2x(1 − x)·… meets
    /// // the line y = 1/4 at irrational points
    /// let a: Shape = "M0 0 L1 1 L1 0 L0 1 Z".parse().unwrap();
    /// let arr = Arrangement::new(&[a], &casteljau::work::Budget::unlimited()).unwrap();
    /// let centre = arr.vertices().into_iter().find(|v| v.degree == 4).unwrap();
    /// assert_eq!(centre.point.iter().map(|x| x.to_string()).collect::<Vec<_>>(), ["1/2", "1/2"]);
    /// let b: Shape = "M0 0 Q1 2 2 0 Z".parse().unwrap();
    /// let c: Shape = "M0 0.25 H2 V2 H0 Z".parse().unwrap();
    /// let arr = Arrangement::new(&[b, c], &casteljau::work::Budget::unlimited()).unwrap();
    /// let v = arr.vertices().into_iter().find(|v| v.point[0].to_rational().is_none()).unwrap();
    /// assert_eq!(v.point[1].to_string(), "1/4");
    /// ```
    pub fn vertices(&self) -> Vec<Vertex> {
        self.vertex_at
            .iter()
            .enumerate()
            .map(|(v, (k, t))| {
                let s = &self.segs[*k];
                Vertex {
                    point: s.point_at_algebraic(t).to_vec(),
                    point_float: s.point_float(t),
                    degree: self.degree[v],
                }
            })
            .collect()
    }

    /// The edges: each a piece of one segment between two vertices, with every input piece it
    /// carries (overlapping pieces merged) and, per input, the winding numbers on its two sides
    /// (`left − right` is the sum of `±1` over the pieces of that input it carries, `+1` along).
    ///
    /// # Example
    /// ```
    /// use casteljau::shape::{Arrangement, Shape};
    /// let a: Shape = "M0 0 H2 V2 H0 Z".parse().unwrap();
    /// let arr = Arrangement::new(&[a.clone(), a], &casteljau::work::Budget::unlimited()).unwrap();
    /// // every edge carries a piece of both copies
    /// assert!(arr.edges().iter().all(|e| e.pieces.len() == 2 && e.winding_left == [1, 1] && e.winding_right == [0, 0]));
    /// ```
    pub fn edges(&self) -> Vec<Edge> {
        self.edges
            .iter()
            .map(|e| Edge {
                from: e.from,
                to: e.to,
                pieces: e.carriers.iter().map(|(k, lo, hi, fwd)| self.input_piece(*k, lo, hi, *fwd)).collect(),
                winding_left: e.left.clone(),
                winding_right: e.right.clone(),
            })
            .collect()
    }

    pub(crate) fn input_piece(&self, k: usize, lo: &RealAlgebraic, hi: &RealAlgebraic, forward: bool) -> InputPiece {
        let s = &self.segs[k];
        let (from, to) = if forward { (lo.clone(), hi.clone()) } else { (hi.clone(), lo.clone()) };
        let (from_float, to_float) = (from.to_f64(), to.to_f64());
        InputPiece { input: s.input, contour: s.contour, segment: s.index, from, to, from_float, to_float }
    }

    /// The number of inputs.
    ///
    /// # Example
    /// ```
    /// use casteljau::shape::{Arrangement, Shape};
    /// let a: Shape = "M0 0 H1 V1 Z".parse().unwrap();
    /// assert_eq!(Arrangement::new(&[a.clone(), a.clone(), a], &casteljau::work::Budget::unlimited()).unwrap().inputs(), 3);
    /// ```
    pub fn inputs(&self) -> usize {
        self.inputs
    }

    /// The half-edges leaving vertex `v` in counter-clockwise order.
    pub(crate) fn rotation(&self, v: usize, keep: &dyn Fn(HalfEdge) -> bool) -> Result<Vec<HalfEdge>> {
        let mut out: Vec<(HalfEdge, Germ<'_>)> = vec![];
        for (i, e) in self.edges.iter().enumerate() {
            let s = &self.segs[e.seg];
            if e.from == v && keep(HalfEdge { edge: i, forward: true }) {
                out.push((HalfEdge { edge: i, forward: true }, Germ { seg: s, t0: e.lo.clone(), sigma: 1 }));
            }
            if e.to == v && keep(HalfEdge { edge: i, forward: false }) {
                out.push((HalfEdge { edge: i, forward: false }, Germ { seg: s, t0: e.hi.clone(), sigma: -1 }));
            }
        }
        if out.len() <= 2 {
            return Ok(out.into_iter().map(|(h, _)| h).collect());
        }
        let angles: Vec<Angle> = out.iter().map(|(_, g)| g.angle()).collect::<Result<_>>()?;
        let mut order: Vec<usize> = (0..out.len()).collect();
        let mut failure = None;
        order.sort_by(|&i, &j| match angles[i].cmp_direction(&angles[j]) {
            Ordering::Equal => match compare_tangent(&out[i].1, &out[j].1) {
                Ok(o) => o,
                Err(e) => {
                    failure.get_or_insert(e);
                    Ordering::Equal
                }
            },
            o => o,
        });
        if let Some(e) = failure {
            return Err(e);
        }
        Ok(order.into_iter().map(|i| out[i].0).collect())
    }

    /// The winding number of a cycle of half-edges just beside half-edge `h` (on its left), not
    /// counting `h` itself.
    pub(crate) fn beside(&self, cycles: &[Vec<HalfEdge>], h: HalfEdge) -> Result<i64> {
        let (p, axis) = self.beside_point(h);
        let pieces: Vec<Vec<Piece<'_>>> = cycles.iter().map(|c| c.iter().map(|&x| self.piece(x)).collect()).collect();
        match winding(&pieces, &p, axis, Origin::Excluded)? {
            RayWinding::Off(w) => Ok(w),
            RayWinding::On { .. } => unreachable!("an excluded origin is never reported"),
        }
    }

    /// A rational point inside the edge of `h` and an axis direction pointing to `h`'s left.
    pub(crate) fn beside_point(&self, h: HalfEdge) -> (Point2<BigRational>, Axis) {
        let e = &self.edges[h.edge];
        let s = &self.segs[e.seg];
        let t = inner_parameter(s, &e.lo, &e.hi);
        let d = s.direction_at(&t);
        let n = if h.forward { [-d.y.clone(), d.x.clone()] } else { [d.y.clone(), -d.x.clone()] };
        (s.point_at(&t), Axis::toward(&n))
    }

    pub(crate) fn piece(&self, h: HalfEdge) -> Piece<'_> {
        let e = &self.edges[h.edge];
        Piece { seg: &self.segs[e.seg], lo: e.lo.clone(), hi: e.hi.clone(), forward: h.forward }
    }

    /// The winding number of cycles around a rational point not on them.
    pub(crate) fn winding_around(&self, cycles: &[Vec<HalfEdge>], q: &Point2<BigRational>) -> Result<i64> {
        let pieces: Vec<Vec<Piece<'_>>> = cycles.iter().map(|c| c.iter().map(|&x| self.piece(x)).collect()).collect();
        match winding(&pieces, q, Axis::PosX, Origin::Free)? {
            RayWinding::Off(w) => Ok(w),
            RayWinding::On { .. } => Err(Error::InvalidArgument { message: "the point lies on the cycle".into() }),
        }
    }

    /// Cycles of the half-edges selected by `keep` (each vertex having as many selected
    /// half-edges in as out), joined at each vertex with the next selected half-edge clockwise:
    /// the boundaries of the regions on their left, each passing a pinch vertex once per sector.
    pub(crate) fn cycles(&self, keep: &dyn Fn(HalfEdge) -> bool) -> Result<Vec<Vec<HalfEdge>>> {
        let n = self.edges.len();
        let id = |h: HalfEdge| 2 * h.edge + usize::from(!h.forward);
        let head = |h: HalfEdge| if h.forward { self.edges[h.edge].to } else { self.edges[h.edge].from };
        let mut next = vec![usize::MAX; 2 * n];
        // group the selected half-edges by the vertex they leave and the one they enter
        let mut at: Vec<Vec<HalfEdge>> = vec![vec![]; self.vertex_at.len()];
        let mut inn: Vec<Vec<HalfEdge>> = vec![vec![]; self.vertex_at.len()];
        for e in 0..n {
            for forward in [true, false] {
                let h = HalfEdge { edge: e, forward };
                if keep(h) {
                    let tail = if forward { self.edges[e].from } else { self.edges[e].to };
                    at[tail].push(h);
                    inn[head(h)].push(h);
                }
            }
        }
        let twin_of = |h: HalfEdge| HalfEdge { edge: h.edge, forward: !h.forward };
        for (v, outs) in at.iter().enumerate() {
            if outs.len() != inn[v].len() {
                return Err(Error::InvalidArgument {
                    message: format!(
                        "internal: {} boundary edges enter vertex {v} and {} leave",
                        inn[v].len(),
                        outs.len()
                    ),
                });
            }
            match outs.len() {
                0 => continue,
                1 => {
                    next[id(inn[v][0])] = id(outs[0]);
                    continue;
                }
                _ => {}
            }
            // all selected half-edges at v, leaving or (reversed) entering, counter-clockwise
            let rot = self.rotation(v, &|h: HalfEdge| keep(h) || keep(twin_of(h)))?;
            let m = rot.len();
            for (i, &g) in rot.iter().enumerate() {
                let entering = twin_of(g);
                if !keep(entering) {
                    continue;
                }
                // the next selected leaving half-edge clockwise from g
                if let Some(c) = (1..=m).map(|k| rot[(i + m - k) % m]).find(|&c| keep(c)) {
                    next[id(entering)] = id(c);
                }
            }
        }
        let mut seen = vec![false; 2 * n];
        let mut out = vec![];
        for e in 0..n {
            for forward in [true, false] {
                let h = HalfEdge { edge: e, forward };
                if !keep(h) || seen[id(h)] {
                    continue;
                }
                let mut cycle = vec![];
                let mut cur = id(h);
                while !seen[cur] {
                    seen[cur] = true;
                    cycle.push(HalfEdge { edge: cur / 2, forward: cur % 2 == 0 });
                    cur = next[cur];
                    if cur == usize::MAX {
                        return Err(Error::InvalidArgument { message: "internal: an open boundary".into() });
                    }
                }
                if cur != id(h) {
                    return Err(Error::InvalidArgument { message: "internal: boundary cycles cross".into() });
                }
                out.push(cycle);
            }
        }
        Ok(out)
    }

    /// The faces: the bounded ones (each with its outer boundary and the inner boundaries of the
    /// components inside it), then the unbounded face.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] when two edges leaving a vertex agree to every order of their
    /// expansions there (an overlap that was not merged; see the private `germ` module — the
    /// order of tangent edges is otherwise always decided, at cusps and irrational vertices too).
    pub fn faces(&self) -> Result<Vec<Face>> {
        Ok(self.faces_with_depths()?.0.clone())
    }

    /// The faces (computed once) with the depth of each bounded one.
    fn faces_with_depths(&self) -> Result<&(Vec<Face>, Vec<usize>)> {
        if let Some(f) = self.faces.get() {
            return Ok(f);
        }
        let computed = self.compute_faces()?;
        Ok(self.faces.get_or_init(|| computed))
    }

    fn compute_faces(&self) -> Result<(Vec<Face>, Vec<usize>)> {
        let all = |_: HalfEdge| true;
        let cycles = self.cycles(&all)?;
        let mut outer = vec![];
        let mut inner = vec![];
        for c in cycles {
            if self.beside(std::slice::from_ref(&c), c[0])? == 1 {
                outer.push(c);
            } else {
                inner.push(c);
            }
        }
        let boxes: Vec<[f64; 4]> = outer.iter().map(|c| self.cycle_box(c)).collect();
        let depth = self.depths(&outer, &boxes)?;
        let mut faces: Vec<Face> = outer
            .iter()
            .map(|c| Face { bounded: true, outer: c.clone(), inner: vec![], winding: self.side(c[0]).to_vec() })
            .collect();
        let mut unbounded = Face { bounded: false, outer: vec![], inner: vec![], winding: vec![0; self.inputs] };
        for c in inner {
            let mut best: Option<usize> = None;
            let probe = self.probe(c[0]);
            for (i, o) in outer.iter().enumerate() {
                if outside(probe, &boxes[i]) {
                    continue; // a point outside a cycle's box has winding number 0 around it
                }
                if self.beside(std::slice::from_ref(o), c[0])? != 0 && best.is_none_or(|b| depth[i] > depth[b]) {
                    best = Some(i);
                }
            }
            match best {
                Some(i) => faces[i].inner.push(c),
                None => unbounded.inner.push(c),
            }
        }
        faces.push(unbounded);
        Ok((faces, depth))
    }

    /// For each outer cycle, how many other outer cycles enclose its face (`boxes`: the
    /// cycles' boxes, which rule out most pairs without a ray).
    fn depths(&self, outer: &[Vec<HalfEdge>], boxes: &[[f64; 4]]) -> Result<Vec<usize>> {
        let mut depth = vec![0; outer.len()];
        for (i, c) in outer.iter().enumerate() {
            let probe = self.probe(c[0]);
            for (j, o) in outer.iter().enumerate() {
                if i != j && !outside(probe, &boxes[j]) && self.beside(std::slice::from_ref(o), c[0])? != 0 {
                    depth[i] += 1;
                }
            }
        }
        Ok(depth)
    }

    /// The point [`Self::beside`] casts its ray from, rounded to `f64`.
    fn probe(&self, h: HalfEdge) -> [f64; 2] {
        let (p, _) = self.beside_point(h);
        [crate::num::scalar::ratio_to_f64(&p.x), crate::num::scalar::ratio_to_f64(&p.y)]
    }

    /// The union of the outward-rounded boxes of a cycle's segments (unbounded when one has
    /// none).
    fn cycle_box(&self, c: &[HalfEdge]) -> [f64; 4] {
        let mut b = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];
        for h in c {
            match self.segs[self.edges[h.edge].seg].bbox {
                Some(s) => b = [b[0].min(s[0]), b[1].min(s[1]), b[2].max(s[2]), b[3].max(s[3])],
                None => return [f64::NEG_INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::INFINITY],
            }
        }
        b
    }

    /// The per-input winding numbers on the left of a half-edge.
    pub(crate) fn side(&self, h: HalfEdge) -> &[i64] {
        let e = &self.edges[h.edge];
        if h.forward { &e.left } else { &e.right }
    }

    /// Where a rational point lies: on a vertex, inside an edge, or inside a face (with every
    /// input's winding number there). Faces are numbered as [`Self::faces`] lists them.
    ///
    /// # Errors
    /// As [`Self::faces`].
    pub fn locate(&self, q: &Point2<BigRational>) -> Result<Location> {
        let (qx, qy) = (crate::num::scalar::ratio_to_f64(&q.x), crate::num::scalar::ratio_to_f64(&q.y));
        for (v, (k, t)) in self.vertex_at.iter().enumerate() {
            let f = self.segs[*k].point_float(t);
            if (f[0] - qx).abs() <= 1e-300_f64.max(f[0].abs() * 4.0 * f64::EPSILON)
                && (f[1] - qy).abs() <= 1e-300_f64.max(f[1].abs() * 4.0 * f64::EPSILON)
                && self.segs[*k].passes_through(t, q)
            {
                return Ok(Location::Vertex { vertex: v });
            }
        }
        for (i, e) in self.edges.iter().enumerate() {
            let s = &self.segs[e.seg];
            if let Some([x0, y0, x1, y1]) = s.bbox
                && (qx < x0 || qx > x1 || qy < y0 || qy > y1)
            {
                continue;
            }
            let piece = Piece { seg: s, lo: e.lo.clone(), hi: e.hi.clone(), forward: true };
            // a single-piece cycle: only "on it or not" is used
            if let RayWinding::On { t, .. } = winding(&[vec![piece]], q, Axis::PosX, Origin::Free)? {
                let t_float = t.to_f64();
                return Ok(Location::Edge { edge: i, t, t_float });
            }
        }
        let (faces, depths) = self.faces_with_depths()?;
        let mut best: Option<(usize, usize)> = None;
        // the bounded faces come first, in the order of `depths`
        for (i, f) in faces.iter().enumerate().filter(|(_, f)| f.bounded) {
            if best.is_some_and(|(_, d)| depths[i] <= d) {
                continue;
            }
            if self.winding_around(std::slice::from_ref(&f.outer), q)? != 0 {
                best = Some((i, depths[i]));
            }
        }
        Ok(match best {
            Some((i, _)) => Location::Face { face: i, winding: faces[i].winding.clone() },
            None => Location::Face { face: faces.len() - 1, winding: vec![0; self.inputs] },
        })
    }
}

/// Whether a rounded point lies strictly outside an outward-rounded box (then so does the exact
/// point: rounding is monotonic).
fn outside(q: [f64; 2], b: &[f64; 4]) -> bool {
    q[0] < b[0] || q[0] > b[2] || q[1] < b[1] || q[1] > b[3]
}

/// An error from one pair or segment, naming where it is.
fn located(e: Error, a: &Seg, b: Option<&Seg>) -> Error {
    let name = |s: &Seg| format!("input {} contour {} segment {}", s.input, s.contour, s.index);
    match e {
        Error::InvalidArgument { message } => Error::InvalidArgument {
            message: match b {
                Some(b) => format!("{message} ({} against {})", name(a), name(b)),
                None => format!("{message} ({})", name(a)),
            },
        },
        other => other,
    }
}
