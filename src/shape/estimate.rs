//! What an arrangement will cost, from its segments' counts, degrees, bit lengths and boxes
//! (units and models in [`crate::work`]), checked against the budget before each stage of
//! [`super::Arrangement::new`] starts:
//!
//! 1. **Candidate pairs**, counted by the sweep over the boxes before any is collected or
//!    screened ([`survey`]): every comparison of boxes, the screening of each pair that meets
//!    (shared end points, separating lines), and a resultant for each pair whose boxes are
//!    equal (segments with both ends in common, which the screen cannot decide). The count
//!    stops as soon as the work passes the budget, so a path that goes round a square 12,000
//!    times is refused in milliseconds with a few megabytes, whatever the number of pairs.
//! 2. **Resultant pairs**: the pairs the screen leaves are priced one by one as the screen
//!    finds them ([`pair`], [`crate::work::intersection`]), then with the self-intersection
//!    checks and one ray per contour, before any of them is solved.
//! 3. **Sides**: once the edges are known, one ray per chain of edges joined at vertices of
//!    degree 2 ([`ray`]), before any ray is cast.

use super::pairs::{Visit, sweep_pairs};
use super::segment::Seg;
use crate::error::Result;
use crate::poly::algebraic::RealAlgebraic;
use crate::work::{Budget, intersection, limbs, winding_piece};
use std::sync::Arc;

/// One comparison of two boxes in the sweep, in work units.
const BOX_TEST: f64 = 2.0;

/// One piece's box against a ray's line (the pieces a ray does not meet).
const RAY_BOX: f64 = 250.0;

/// The counting and screening of stages 1 and 2 go on past a small budget up to this much work
/// (0.05 s), so that a refusal names the whole estimate rather than the first pair's.
const COUNTED_ANYWAY: f64 = 5e7;

/// Where the counting and screening of stages 1 and 2 stop: the limit, or a little more for a
/// small one.
pub(super) fn counted_up_to(budget: &Budget) -> f64 {
    budget.limit.max(COUNTED_ANYWAY)
}

/// Screening one candidate pair (shared end points, separating lines): on small integers
/// (fonts) `150` (9,748 pairs of a 2,000-segment glyph in 1.6 ms); decided by the certified
/// `f64` filter (coordinates within `10^±150`) `4·10⁴·L(β)^1.3`; otherwise a few hundred
/// reduced products, `3·(c_a + c_b)·(n + m + 2)` of `2000·L(β)^1.3` each (`c` the chords of
/// a segment's control polygon, `n(n + 1)/2`).
pub(super) fn screen(a: &Seg, b: &Seg) -> f64 {
    if a.small.is_some() && b.small.is_some() {
        return 150.0;
    }
    let l = limbs(a.sizes.bits.max(b.sizes.bits)).powf(1.3);
    if a.approx.is_some() && b.approx.is_some() {
        return 4e4 * l;
    }
    let chords = |s: &Seg| (s.degree() * (s.degree() + 1) / 2) as f64;
    3.0 * (chords(a) + chords(b)) * (a.degree() + b.degree() + 2) as f64 * 2000.0 * l
}

/// The exact intersection of two segments ([`crate::work::intersection`]).
pub(super) fn pair(a: &Seg, b: &Seg) -> f64 {
    intersection(a.degree(), b.degree(), a.sizes.with(b.sizes))
}

/// The self-intersection check of a segment.
pub(super) fn own(a: &Seg) -> f64 {
    intersection(a.degree(), a.degree(), a.sizes)
}

/// Stage 1: the work of the candidate pairs, counted from the boxes without collecting a pair:
/// the comparisons and screenings (returned), plus a resultant for every pair with equal boxes
/// (not returned: stage 2 prices those pairs again). The count stops past
/// [`counted_up_to`], and the refusal extrapolates it to the whole sweep; a count that
/// completes is checked with the rest of the estimate in stage 2.
///
/// # Errors
/// [`crate::Error::WorkLimit`] over the budget.
pub(super) fn survey(segs: &[Arc<Seg>], budget: &Budget) -> Result<f64> {
    let (mut screening, mut equal_boxes) = (0.0, 0.0);
    let mut progress = (0usize, 1usize);
    let mut pairs = 0u64;
    let completed = sweep_pairs(segs, &mut |v| {
        match v {
            Visit::Scanned { comparisons, done, of } => {
                screening += BOX_TEST * comparisons as f64;
                progress = (done, of);
            }
            Visit::Pair(a, b) => {
                let (sa, sb) = (&segs[a], &segs[b]);
                pairs += 1;
                screening += screen(sa, sb);
                if sa.bbox == sb.bbox {
                    equal_boxes += pair(sa, sb);
                }
            }
        }
        screening + equal_boxes <= counted_up_to(budget)
    });
    let what = || format!("the candidate pairs of the arrangement of {} segments ({pairs} so far)", segs.len());
    if !completed {
        // the sweep stopped at step `done` of `of`: the rest, at the rate so far
        let (done, of) = progress;
        let whole = (screening + equal_boxes) * of as f64 / (done.max(1) as f64);
        budget.check(what(), whole)?;
    }
    Ok(screening)
}

/// Stage 3: one ray's work: every segment's box compared against its line, and each segment
/// solved exactly ([`crate::work::winding_piece`]) with the probability that a line through
/// the arrangement's box meets the segment's box (the larger share of the height or the width
/// it spans: the rays run along either axis).
pub(super) fn ray(segs: &[Arc<Seg>]) -> f64 {
    let mut all = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];
    for b in segs.iter().filter_map(|s| s.bbox) {
        all = [all[0].min(b[0]), all[1].min(b[1]), all[2].max(b[2]), all[3].max(b[3])];
    }
    let share = |part: f64, whole: f64| {
        let r = part / whole;
        if r.is_finite() { r.min(1.0) } else { 1.0 }
    };
    segs.iter()
        .filter(|s| !s.degenerate)
        .map(|s| {
            let p = match s.bbox {
                Some(b) => share(b[2] - b[0], all[2] - all[0]).max(share(b[3] - b[1], all[3] - all[1])),
                None => 1.0,
            };
            RAY_BOX + p * winding_piece(s.degree(), s.sizes.bits)
        })
        .sum()
}

/// The result's exact areas and rounded path (stage 4, after the arrangement), per irrational
/// end of a run: `7000·(d·n)²` for a parameter of degree `d` on a segment of degree `n` (the
/// images of the point and of the area's antiderivative there, bisected until their binary64
/// values are decided). Fitted on a union at a cusp (12 irrational ends of degrees 1 to 24: 9.7 ms
/// measured, 9.8 ms estimated) and on two rings of cubics (8 ends of degree 12: 8.3 ms, 8.1 ms).
pub(super) fn run_end(s: &Seg, t: &RealAlgebraic) -> f64 {
    if t.to_rational().is_some() {
        return 0.0;
    }
    let image = (t.polynomial().len().saturating_sub(1) * s.degree()) as f64;
    7000.0 * image * image
}
