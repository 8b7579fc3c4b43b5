//! Runs: a boundary cycle's edges joined into maximal stretches on one input segment, the unit
//! in which boolean results are written (`boolean`) and their areas summed (`area`).

use super::graph::{Arrangement, HalfEdge, InputPiece};
use crate::poly::algebraic::RealAlgebraic;

/// A maximal run of boundary edges on one segment: parameters `from → to`.
#[derive(Clone, Debug)]
pub(super) struct Run {
    pub(super) seg: usize,
    pub(super) from: RealAlgebraic,
    pub(super) to: RealAlgebraic,
    /// The index of its first half-edge in the cycle.
    pub(super) first: usize,
    /// The arrangement's vertex it starts at.
    pub(super) start: usize,
}

impl Run {
    pub(super) fn key(&self) -> (usize, RealAlgebraic) {
        (self.seg, self.from.clone())
    }
    pub(super) fn piece(&self, arr: &Arrangement) -> InputPiece {
        let forward = self.from <= self.to;
        let (lo, hi) = if forward { (&self.from, &self.to) } else { (&self.to, &self.from) };
        arr.input_piece(self.seg, lo, hi, forward)
    }
}

/// The cycle's edges (each by its first carrier) joined into runs on one segment.
pub(super) fn runs(arr: &Arrangement, cycle: &[HalfEdge]) -> Vec<Run> {
    let mut out: Vec<Run> = vec![];
    for (i, h) in cycle.iter().enumerate() {
        let e = &arr.edges[h.edge];
        let (k, lo, hi, fwd) = &e.carriers[0];
        let forward = *fwd == h.forward;
        let (from, to) = if forward { (lo.clone(), hi.clone()) } else { (hi.clone(), lo.clone()) };
        if let Some(last) = out.last_mut()
            && last.seg == *k
            && last.to == from
            && ((last.from < last.to) == forward)
        {
            last.to = to;
            continue;
        }
        let start = if h.forward { e.from } else { e.to };
        out.push(Run { seg: *k, from, to, first: i, start });
    }
    if out.len() > 1 {
        let (first, last) = (&out[0], &out[out.len() - 1]);
        if first.seg == last.seg && last.to == first.from && ((first.from < first.to) == (last.from < last.to)) {
            let last = out.pop().expect("two runs");
            out[0].from = last.from;
            out[0].first = last.first;
            out[0].start = last.start;
        }
    }
    out
}
