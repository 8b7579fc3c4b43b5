//! Steps 2–4 of [`super::arrangement`]: the segments split at every contact, points identified
//! by the records that produced them (a union–find with parity), overlapping pieces merged into
//! one edge, and the winding numbers on both sides of every edge, one ray per chain of edges.

use super::graph::{Arrangement, EdgeData, HalfEdge};
use super::ray::{Origin, Piece, RayWinding, whole, winding};
use super::segment::Seg;
use crate::error::{Error, Result};
use crate::num::scalar::rat;
use crate::poly::algebraic::RealAlgebraic;

/// What two segments share, as found.
#[allow(clippy::large_enum_variant)] // short-lived, one per contact
pub(super) enum Link {
    Point(usize, RealAlgebraic, usize, RealAlgebraic),
    Arc(usize, [RealAlgebraic; 2], usize, [RealAlgebraic; 2]),
}

/// Union–find with parity.
struct Union {
    parent: Vec<usize>,
    parity: Vec<bool>,
}

impl Union {
    fn new(n: usize) -> Self {
        Union { parent: (0..n).collect(), parity: vec![false; n] }
    }
    fn find(&mut self, x: usize) -> (usize, bool) {
        let mut path = vec![];
        let mut r = x;
        while self.parent[r] != r {
            path.push(r);
            r = self.parent[r];
        }
        // compress, accumulating parity from the top
        let mut acc = false;
        for &n in path.iter().rev() {
            acc ^= self.parity[n];
            self.parity[n] = acc;
            self.parent[n] = r;
        }
        (r, if path.is_empty() { false } else { self.parity[x] })
    }
    /// Joins `a` and `b` with `parity(a) ^ parity(b) = p`; false on a contradiction.
    fn union(&mut self, a: usize, b: usize, p: bool) -> bool {
        let (ra, pa) = self.find(a);
        let (rb, pb) = self.find(b);
        if ra == rb {
            return pa ^ pb == p;
        }
        let (lo, hi) = if ra < rb { (ra, rb) } else { (rb, ra) };
        self.parent[hi] = lo;
        self.parity[hi] = pa ^ pb ^ p;
        true
    }
}

/// Splits, identifies, merges and sides (steps 2–4 of the module documentation).
pub(super) fn build(
    segs: Vec<std::sync::Arc<Seg>>,
    inputs: usize,
    contours: Vec<Vec<Vec<usize>>>,
    links: Vec<Link>,
) -> Result<Arrangement> {
    let n = segs.len();
    let mut params: Vec<Vec<RealAlgebraic>> = vec![vec![rat(0).into(), rat(1).into()]; n];
    for l in &links {
        match l {
            Link::Point(a, s, b, t) => {
                params[*a].push(s.clone());
                params[*b].push(t.clone());
            }
            Link::Arc(a, s, b, t) => {
                params[*a].extend(s.iter().cloned());
                params[*b].extend(t.iter().cloned());
            }
        }
    }
    for p in &mut params {
        p.sort();
        p.dedup();
    }
    let mut base = vec![0usize; n + 1];
    for k in 0..n {
        base[k + 1] = base[k] + params[k].len();
    }
    let node = |k: usize, t: &RealAlgebraic, params: &Vec<Vec<RealAlgebraic>>| -> usize {
        base[k] + params[k].binary_search(t).expect("every linked parameter is a cut")
    };
    let mut nodes = Union::new(base[n]);
    for input in &contours {
        for c in input {
            let live: Vec<usize> = c.iter().copied().filter(|&k| !segs[k].degenerate).collect();
            for (i, &k) in live.iter().enumerate() {
                let next = live[(i + 1) % live.len()];
                let last = params[k].len() - 1;
                nodes.union(base[k] + last, base[next], false);
            }
        }
    }
    for l in &links {
        match l {
            Link::Point(a, s, b, t) => {
                nodes.union(node(*a, s, &params), node(*b, t, &params), false);
            }
            Link::Arc(a, s, b, t) => {
                nodes.union(node(*a, &s[0], &params), node(*b, &t[0], &params), false);
                nodes.union(node(*a, &s[1], &params), node(*b, &t[1], &params), false);
            }
        }
    }
    // raw edges, numbered by segment then parameter
    let mut edge_base = vec![0usize; n + 1];
    for k in 0..n {
        edge_base[k + 1] = edge_base[k] + if segs[k].degenerate { 0 } else { params[k].len() - 1 };
    }
    let mut merge = Union::new(edge_base[n]);
    let bad = |m: &str| Error::InvalidArgument { message: format!("internal: {m}") };
    for l in &links {
        let Link::Arc(a, s, b, t) = l else { continue };
        if s[0] == s[1] {
            continue;
        }
        let idx = |k: usize, x: &RealAlgebraic| params[k].binary_search(x).expect("a cut");
        let (a0, a1) = (idx(*a, &s[0]), idx(*a, &s[1]));
        let (ta, tb) = (idx(*b, &t[0]), idx(*b, &t[1]));
        let (b0, b1, reversed) = if ta < tb { (ta, tb, false) } else { (tb, ta, true) };
        if a1 - a0 != b1 - b0 {
            return Err(bad("the pieces of an overlap do not match"));
        }
        for i in 0..a1 - a0 {
            let ea = edge_base[*a] + a0 + i;
            let eb = if reversed { edge_base[*b] + b1 - 1 - i } else { edge_base[*b] + b0 + i };
            if !merge.union(ea, eb, reversed) {
                return Err(bad("an overlap runs both ways"));
            }
        }
    }
    // vertices in order of first appearance
    let mut vertex_of_root: std::collections::HashMap<usize, usize> = std::collections::HashMap::new();
    let mut vertex_at = vec![];
    let mut vertex = |nodes: &mut Union, k: usize, i: usize, params: &Vec<Vec<RealAlgebraic>>| -> usize {
        let (r, _) = nodes.find(base[k] + i);
        *vertex_of_root.entry(r).or_insert_with(|| {
            vertex_at.push((k, params[k][i].clone()));
            vertex_at.len() - 1
        })
    };
    let mut edges: Vec<EdgeData> = vec![];
    let mut edge_of_root: std::collections::HashMap<usize, usize> = std::collections::HashMap::new();
    for k in 0..n {
        if segs[k].degenerate {
            continue;
        }
        for i in 0..params[k].len() - 1 {
            let raw = edge_base[k] + i;
            let (root, flip) = merge.find(raw);
            let (lo, hi) = (params[k][i].clone(), params[k][i + 1].clone());
            let (from, to) = (vertex(&mut nodes, k, i, &params), vertex(&mut nodes, k, i + 1, &params));
            match edge_of_root.get(&root) {
                None => {
                    edge_of_root.insert(root, edges.len());
                    // the first raw edge of a class is its root (unions keep the smaller index)
                    debug_assert!(!flip);
                    edges.push(EdgeData {
                        seg: k,
                        lo: lo.clone(),
                        hi: hi.clone(),
                        from,
                        to,
                        carriers: vec![(k, lo, hi, true)],
                        left: vec![],
                        right: vec![],
                    });
                }
                Some(&e) => {
                    let ed = &mut edges[e];
                    let ok = if flip { ed.from == to && ed.to == from } else { ed.from == from && ed.to == to };
                    if !ok {
                        return Err(bad("an overlap joins pieces with different ends"));
                    }
                    ed.carriers.push((k, lo, hi, !flip));
                }
            }
        }
    }
    let mut degree = vec![0usize; vertex_at.len()];
    for e in &edges {
        degree[e.from] += 1;
        degree[e.to] += 1;
    }
    Ok(Arrangement { segs, inputs, contours, edges, vertex_at, degree, faces: std::sync::OnceLock::new() })
}

/// The edges at each vertex.
fn edges_at(arr: &Arrangement) -> Vec<Vec<usize>> {
    let mut at: Vec<Vec<usize>> = vec![vec![]; arr.vertex_at.len()];
    for (i, e) in arr.edges.iter().enumerate() {
        at[e.from].push(i);
        at[e.to].push(i);
    }
    at
}

/// The first edge of each chain of edges joined at vertices of degree 2, in edge order: where
/// [`sides`] casts its rays.
pub(super) fn chain_starts(arr: &Arrangement) -> Vec<usize> {
    let at = edges_at(arr);
    let mut seen = vec![false; arr.edges.len()];
    let mut starts = vec![];
    for start in 0..arr.edges.len() {
        if seen[start] {
            continue;
        }
        starts.push(start);
        let mut stack = vec![start];
        while let Some(i) = stack.pop() {
            if std::mem::replace(&mut seen[i], true) {
                continue;
            }
            for v in [arr.edges[i].from, arr.edges[i].to] {
                if at[v].len() == 2 {
                    stack.extend(at[v].iter().copied().filter(|&j| !seen[j]));
                }
            }
        }
    }
    starts
}

/// Step 4: the winding numbers on both sides of every edge, one ray per chain of edges joined
/// at vertices of degree 2.
pub(super) fn sides(arr: &mut Arrangement) -> Result<()> {
    let m = arr.edges.len();
    let at = edges_at(arr);
    let input_cycles: Vec<Vec<Vec<Piece<'_>>>> = arr
        .contours
        .iter()
        .map(|cs| {
            cs.iter()
                .map(|c| {
                    c.iter().filter(|&&k| !arr.segs[k].degenerate).map(|&k| whole(&arr.segs[k])).collect::<Vec<_>>()
                })
                .filter(|c: &Vec<Piece<'_>>| !c.is_empty())
                .collect()
        })
        .collect();
    let mut done: Vec<Option<(Vec<i64>, Vec<i64>)>> = vec![None; m];
    for start in 0..m {
        if done[start].is_some() {
            continue;
        }
        let e = &arr.edges[start];
        let (p, axis) = arr.beside_point(HalfEdge { edge: start, forward: true });
        let mut left = vec![0i64; arr.inputs];
        for (i, cycles) in input_cycles.iter().enumerate() {
            left[i] = match winding(cycles, &p, axis, Origin::Excluded)? {
                RayWinding::Off(w) => w,
                RayWinding::On { .. } => unreachable!("an excluded origin is never reported"),
            };
        }
        let mut right = left.clone();
        for (k, _, _, fwd) in &e.carriers {
            right[arr.segs[*k].input] -= if *fwd { 1 } else { -1 };
        }
        // propagate along the chain through vertices of degree 2
        let mut stack = vec![(start, left, right)];
        while let Some((i, l, r)) = stack.pop() {
            if done[i].is_some() {
                continue;
            }
            let (from, to) = (arr.edges[i].from, arr.edges[i].to);
            for (v, leaving) in [(to, true), (from, false)] {
                if at[v].len() != 2 {
                    continue;
                }
                let j = if at[v][0] == i { at[v][1] } else { at[v][0] };
                if j == i || done[j].is_some() {
                    continue;
                }
                // the chain continues through v: j keeps the sides when it runs on from v
                let ej = &arr.edges[j];
                let same = if leaving { ej.from == v } else { ej.to == v };
                if same { stack.push((j, l.clone(), r.clone())) } else { stack.push((j, r.clone(), l.clone())) }
            }
            done[i] = Some((l, r));
        }
    }
    for (e, d) in arr.edges.iter_mut().zip(done) {
        let (l, r) = d.expect("every edge is sided");
        e.left = l;
        e.right = r;
    }
    Ok(())
}
