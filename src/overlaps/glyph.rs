//! One glyph decided: whether it needs rewriting, its exact region, and the certified rounding.
//!
//! * **The decision.** A simple glyph (one component) needs rewriting when `lint` finds an
//!   `overlap`, a `self_intersection`, `overlapping_segments` or a `direction` finding; a
//!   composite (several components) when two components' regions overlap (some side of an edge
//!   of their arrangement lies in two of them) or share a boundary piece (an edge on the
//!   boundary of two of them). Contours or components that only touch at points are no reason.
//! * **The region.** The non-zero region of all the glyph's contours together (a rasterizer's
//!   fill of the decomposed outline), in the font's direction ([`super::region`]).
//! * **The rounding.** Plain rounding first ([`super::round`]); if [`super::certify`] rejects it,
//!   the repairs: other grid candidates (each within one unit) for the meeting points and
//!   control points near what failed, one at a time and then on from the best attempt; a
//!   contour whose rounding collapses to nothing (its written copy bounds no area on either
//!   side) is dropped and reported with its area.

use super::certify::{Failure, certify};
use super::distance::{nearest_rational, sqrt_up};
use super::region::region;
use super::round::{Plan, plan};
use super::{Flavour, GlyphDecision, GlyphInput, GlyphReport, GridContour, GridPoint, Repair};
use crate::error::{Error, Result};
use crate::format::{Contour, Segment};
use crate::lint::{Glyph, Kind, LintOptions, lint};
use crate::num::point::Point;
use crate::num::scalar::{rat, ratio_to_f64};
use crate::path::ClosedPath;
use crate::shape::{Arrangement, Shape};
use crate::work::Budget;
use num_rational::BigRational;
use num_traits::Signed;

/// Most certification attempts (each an exact `lint` of the written glyph) per glyph.
const MAX_ATTEMPTS: usize = 32;

/// Placeables tried per round of the repair search.
const SUSPECTS: usize = 6;

/// The point of a contour that draws nothing but a point (an anchor), if it is one.
fn anchor(c: &Contour) -> Option<Point<BigRational>> {
    let mut first: Option<&Point<BigRational>> = None;
    for s in &c.segments {
        let Segment::Bezier(ps) = s else { return None };
        for p in ps {
            match first {
                None => first = Some(p),
                Some(f) if f != p => return None,
                Some(_) => {}
            }
        }
    }
    first.cloned()
}

/// Points as a font stores them: every segment's points after its start, TrueType's implied
/// midpoints (an on-curve point halfway between the control points around it) not counted.
fn stored_points(c: &Contour, flavour: Flavour) -> usize {
    let segs: Vec<&Vec<Point<BigRational>>> = c
        .segments
        .iter()
        .filter_map(|s| match s {
            Segment::Bezier(ps) => Some(ps),
            Segment::Skipped { .. } => None,
        })
        .collect();
    let mut n: usize = segs.iter().map(|s| s.len().saturating_sub(1)).sum();
    if flavour == Flavour::Quadratic {
        let m = segs.len();
        for i in 0..m {
            let (a, b) = (segs[i], segs[(i + 1) % m]);
            if m > 1 && a.len() == 3 && b.len() == 3 && a[2] == a[1].lerp(&b[1], &(rat(1) / rat(2))) {
                n -= 1;
            }
        }
    }
    n
}

/// A component's contours that draw something, as a shape, with their indices in the component.
fn shape_of(contours: &[Contour]) -> Result<Option<(Shape, Vec<usize>)>> {
    let mut segs = vec![];
    let mut index = vec![];
    for (i, c) in contours.iter().enumerate() {
        if anchor(c).is_some() || c.segments.is_empty() {
            continue;
        }
        let closed = crate::format::svg_path::close_for_fill(c)?;
        if !closed.is_empty() {
            segs.push(closed);
            index.push(i);
        }
    }
    if segs.is_empty() {
        return Ok(None);
    }
    Ok(Some((Shape::new(ClosedPath::from_polynomial(segs)?), index)))
}

/// Whether the components' regions overlap or share a boundary piece: some side of an edge in
/// two of them, or an edge on the boundary of two of them.
fn components_meet(arr: &Arrangement) -> bool {
    arr.edges.iter().any(|e| {
        let inside = |w: &[i64]| w.iter().filter(|&&x| x != 0).count();
        let boundary = e.left.iter().zip(&e.right).filter(|(l, r)| (**l != 0) != (**r != 0)).count();
        inside(&e.left) >= 2 || inside(&e.right) >= 2 || boundary >= 2
    })
}

/// An arrangement, or the reason it could not be made (a work limit is passed on).
fn arrangement(inputs: &[Shape], budget: &Budget) -> Result<std::result::Result<Arrangement, String>> {
    match Arrangement::new(inputs, budget) {
        Ok(a) => Ok(Ok(a)),
        Err(e @ Error::WorkLimit { .. }) => Err(e),
        Err(e) => Ok(Err(format!("the exact arrangement: {e}"))),
    }
}

/// [`super::decide_glyph`].
pub(super) fn decide(input: &GlyphInput, budget: &Budget) -> Result<GlyphDecision> {
    if super::screen::clean(&input.components, input.orientation) {
        return Ok(GlyphDecision::Unchanged);
    }
    decide_exactly(input, budget)
}

/// [`decide`] without the screen: the exact route alone.
fn decide_exactly(input: &GlyphInput, budget: &Budget) -> Result<GlyphDecision> {
    if input.components.len() == 1 {
        // a simple glyph: rewritten when lint finds a reason
        let contours: Vec<Contour> = input.components[0].iter().filter(|c| anchor(c).is_none()).cloned().collect();
        let kinds = vec![Kind::Direction, Kind::SelfIntersection, Kind::Overlap, Kind::OverlappingSegments];
        let options = LintOptions { kinds, budget: *budget, ..LintOptions::new(input.orientation) };
        if lint(&Glyph::new(contours), &options)?.is_empty() {
            return Ok(GlyphDecision::Unchanged);
        }
    }
    // the drawing contours as one shape per component: (shape, contour indices, component)
    let mut shapes: Vec<(Shape, Vec<usize>, usize)> = vec![];
    for (ci, comp) in input.components.iter().enumerate() {
        if let Some((s, index)) = shape_of(comp)? {
            shapes.push((s, index, ci));
        }
    }
    if shapes.is_empty() {
        return Ok(GlyphDecision::Unchanged);
    }
    let inputs: Vec<Shape> = shapes.iter().map(|s| s.0.clone()).collect();
    let arr = match arrangement(&inputs, budget)? {
        Ok(a) => a,
        Err(reason) => return Ok(uncertified(reason)),
    };
    // a composite: rewritten only when its components' regions overlap or share pieces
    if input.components.len() > 1 && !components_meet(&arr) {
        return Ok(GlyphDecision::Unchanged);
    }
    rewrite(input, &arr, &shapes, budget)
}

/// The region of a glyph that needs rewriting, rounded and certified.
fn rewrite(
    input: &GlyphInput,
    arr: &Arrangement,
    shapes: &[(Shape, Vec<usize>, usize)],
    budget: &Budget,
) -> Result<GlyphDecision> {
    let exact = match region(arr, input.orientation) {
        Ok(r) => r,
        Err(e @ Error::WorkLimit { .. }) => return Err(e),
        Err(e) => return Ok(uncertified(format!("the exact region: {e}"))),
    };
    let plan = match plan(arr, &exact, input.flavour) {
        Ok(p) => p,
        Err(e) => return Ok(uncertified(e.to_string())),
    };
    let Certified { plan, choice, dropped, straight } = match round_certified(plan, input, budget)? {
        Ok(found) => found,
        Err(failure) => return Ok(uncertified(failure.reason)),
    };
    // the written contours by (component, contour) of their origin, anchors kept at theirs
    let mut keyed: Vec<((usize, usize), GridContour, Vec<usize>)> = vec![];
    for (w, c) in as_lines(&plan, plan.write(&choice), &straight).into_iter().zip(&plan.contours) {
        let (i, contour) = exact[c.exact].origin;
        let (_, index, component) = &shapes[i];
        keyed.push(((*component, index.get(contour).copied().unwrap_or(contour)), w.contour, w.source));
    }
    for (ci, comp) in input.components.iter().enumerate() {
        for (i, c) in comp.iter().enumerate() {
            if let Some(p) = anchor(c) {
                let g = |v: &BigRational| nearest_rational(v) as i32;
                let point = GridPoint { x: g(&p.coords[0]), y: g(&p.coords[1]), on_curve: true };
                keyed.push(((ci, i), GridContour { points: vec![point] }, vec![]));
            }
        }
    }
    keyed.sort_by_key(|e| e.0);
    // repairs in output numbering; a shared vertex is reported where it is first written
    let mut repairs: Vec<Repair> = vec![];
    let mut reported = vec![false; plan.points.len()];
    for (ci, (_, gc, source)) in keyed.iter().enumerate() {
        for (pi, (&k, g)) in source.iter().zip(&gc.points).enumerate() {
            if choice[k] == 0 || reported[k] {
                continue;
            }
            reported[k] = true;
            repairs.push(if g.on_curve {
                Repair::MovedVertex { contour: ci, point: pi }
            } else {
                Repair::MovedControl { contour: ci, point: pi }
            });
        }
    }
    for (k, i) in straight {
        // reported at its start when that is written, else at its first control point
        let piece = &plan.contours[k].pieces[i];
        let at = if piece.implied { piece.controls[0] } else { piece.start };
        if let Some((ci, (_, _, source))) = keyed.iter().enumerate().find(|(_, e)| e.2.contains(&at)) {
            let point = source.iter().position(|&s| s == at).unwrap_or(0);
            repairs.push(Repair::Straightened { contour: ci, point });
        }
    }
    repairs.extend(dropped);
    let contours: Vec<GridContour> = keyed.into_iter().map(|(_, c, _)| c).collect();
    let all_inputs: Vec<&Contour> = input.components.iter().flatten().collect();
    let contours_before = all_inputs.iter().filter(|c| !c.segments.is_empty()).count();
    let points_before =
        all_inputs.iter().map(|c| if anchor(c).is_some() { 1 } else { stored_points(c, input.flavour) }).sum();
    let distance_bound = sqrt_up(&plan.bound2(&choice));
    let report = GlyphReport {
        glyph: input.name.clone(),
        glyph_id: input.glyph_id,
        contours_before,
        contours_after: contours.len(),
        points_before,
        points_after: contours.iter().map(|c| c.points.len()).sum(),
        distance_bound_float: ratio_to_f64(&distance_bound),
        distance_bound,
        repairs,
    };
    Ok(GlyphDecision::Rewritten { contours, report })
}

/// The curves certified straight (their rounded control points in order on the line between
/// their ends) written as lines where both ends are written on-curve points: the same trace,
/// so the same region, boundary and certificate, and no curve collapsed onto a line. A TrueType
/// curve whose end is implied by its neighbour's control point keeps its own, on the line.
fn as_lines(
    plan: &Plan,
    mut written: Vec<super::round::Written>,
    straight: &[(usize, usize)],
) -> Vec<super::round::Written> {
    for &(k, i) in straight {
        let pieces = &plan.contours[k].pieces;
        let end_implied = pieces[(i + 1) % pieces.len()].implied;
        if pieces[i].implied || end_implied {
            continue;
        }
        let w = &mut written[k];
        let keep: Vec<bool> = w.source.iter().map(|s| !pieces[i].controls.contains(s)).collect();
        let mut it = keep.iter();
        w.contour.points.retain(|_| *it.next().expect("one flag per point"));
        let mut it = keep.iter();
        w.source.retain(|_| *it.next().expect("one flag per point"));
    }
    written
}

fn uncertified(reason: String) -> GlyphDecision {
    GlyphDecision::Uncertified { reason }
}

/// A rounding that certifies: the plan (without the dropped contours), the choice of
/// candidates, the dropped contours' repairs and the curves written straight.
struct Certified {
    plan: Plan,
    choice: Vec<usize>,
    dropped: Vec<Repair>,
    straight: Vec<(usize, usize)>,
}

/// Plain rounding (curves kept curved where a candidate allows), then the repair search (see
/// the module documentation); or the last failure.
fn round_certified(
    mut plan: Plan,
    input: &GlyphInput,
    budget: &Budget,
) -> Result<std::result::Result<Certified, Failure>> {
    let (flavour, orientation) = (input.flavour, input.orientation);
    let mut attempts = 0;
    let mut dropped = vec![];
    let mut choice = vec![0; plan.points.len()];
    plan.keep_curves(&mut choice);
    // the attempts' work together within the budget: as many as it holds of the first one's
    // estimate (the written glyph's arrangement), at most MAX_ATTEMPTS
    let each = super::certify::estimate(&plan.write(&choice), flavour, orientation);
    budget.check(format!("certifying the rounded glyph ({} contours)", plan.contours.len()), each)?;
    let most = if each > 0.0 { ((budget.limit / each) as usize).clamp(1, MAX_ATTEMPTS) } else { MAX_ATTEMPTS };
    let check = |plan: &Plan, choice: &[usize], attempts: &mut usize| {
        *attempts += 1;
        certify(plan, choice, &plan.write(choice), flavour, orientation, budget)
    };
    let mut failure = match check(&plan, &choice, &mut attempts)? {
        Ok(straight) => return Ok(Ok(Certified { plan, choice, dropped, straight })),
        Err(f) => f,
    };
    while attempts < most {
        // a contour that collapses to nothing: dropped when its written copy bounds no area
        if let Some(k) = collapsed(&plan, &choice, &failure, flavour, budget)? {
            dropped.push(sliver(&plan, k));
            plan.drop_contour(k);
            match check(&plan, &choice, &mut attempts)? {
                Ok(straight) => return Ok(Ok(Certified { plan, choice, dropped, straight })),
                Err(f) => {
                    failure = f;
                    continue;
                }
            }
        }
        // the placeables nearest to what failed, each moved to its other candidates
        let suspects = suspects(&plan, &failure);
        let mut best: Option<(Vec<usize>, Failure)> = None;
        'search: for s in suspects {
            for alt in 0..plan.points[s].candidates.len() {
                if alt == choice[s] || attempts >= most {
                    continue;
                }
                let mut next = choice.clone();
                next[s] = alt;
                match check(&plan, &next, &mut attempts)? {
                    Ok(straight) => return Ok(Ok(Certified { plan, choice: next, dropped, straight })),
                    Err(f) => {
                        if f.better_than(best.as_ref().map_or(&failure, |b| &b.1)) {
                            best = Some((next, f));
                            break 'search;
                        }
                    }
                }
            }
        }
        match best {
            Some((c, f)) => {
                choice = c;
                failure = f;
            }
            None => break,
        }
    }
    Ok(Err(failure))
}

/// The placeables of the failing contours with more than one candidate, nearest to the failure
/// first.
fn suspects(plan: &Plan, failure: &Failure) -> Vec<usize> {
    let mut ks: Vec<usize> = vec![];
    for (k, c) in plan.contours.iter().enumerate() {
        if !failure.contours.is_empty() && !failure.contours.contains(&k) {
            continue;
        }
        for p in &c.pieces {
            ks.extend(p.controls.iter().copied().chain((!p.implied).then_some(p.start)));
        }
    }
    ks.sort_unstable();
    ks.dedup();
    ks.retain(|&k| plan.points[k].candidates.len() > 1);
    let dist = |k: usize| {
        let e = &plan.points[k].enclosure;
        let (x, y) = (ratio_to_f64(&e.x.lo), ratio_to_f64(&e.y.lo));
        failure.near.iter().map(|q| (q[0] - x).hypot(q[1] - y)).fold(f64::INFINITY, f64::min)
    };
    ks.sort_by(|&a, &b| dist(a).total_cmp(&dist(b)).then(a.cmp(&b)));
    ks.truncate(SUSPECTS);
    ks
}

/// A failing contour whose written copy bounds no area on either side of it and encloses no
/// other contour: the sliver to drop.
fn collapsed(
    plan: &Plan,
    choice: &[usize],
    failure: &Failure,
    flavour: Flavour,
    budget: &Budget,
) -> Result<Option<usize>> {
    let written = plan.write(choice);
    for &k in &failure.contours {
        if k >= plan.contours.len() || plan.contours.iter().any(|c| c.parent == Some(k)) {
            continue;
        }
        let contour = &super::certify::contours_of(&written[k..=k], flavour)[0];
        let segs = crate::format::svg_path::close_for_fill(contour)?;
        if segs.is_empty() {
            return Ok(Some(k));
        }
        let shape = Shape::new(ClosedPath::from_polynomial(vec![segs])?);
        let arr = Arrangement::new(&[shape], budget)?;
        if arr.edges.iter().all(|e| e.left[0] == 0 && e.right[0] == 0) {
            return Ok(Some(k));
        }
    }
    Ok(None)
}

/// The repair that drops contour `k`: its exact area when that is rational, else the
/// multiple of 10⁻⁶ next beyond the enclosure of it (away from zero: a bound on its size).
fn sliver(plan: &Plan, k: usize) -> Repair {
    let a = plan.area(k);
    if a.lo == a.hi {
        return Repair::DroppedSliver { area: a.hi };
    }
    let million = BigRational::from_integer(1_000_000.into());
    let area =
        if a.hi.abs() >= a.lo.abs() { (a.hi * &million).ceil() / million } else { (a.lo * &million).floor() / million };
    Repair::DroppedSliver { area }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::Orientation;

    /// The screen's "unchanged" agrees with the exact route on every glyph of the test font it
    /// decides (composites taken whole), and decides most of them (1,076 of 1,502).
    #[test]
    fn screen_agrees_with_the_exact_decision() {
        let data = include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/fonts/Tuffy.ttf"));
        let font = crate::format::Font::open(data, 0).unwrap();
        let mut screened = 0;
        for gid in 0..font.num_glyphs() {
            let components = vec![font.outline(gid).unwrap()];
            if !super::super::screen::clean(&components, Orientation::Cw) {
                continue;
            }
            screened += 1;
            let input = GlyphInput {
                glyph_id: gid,
                name: font.glyph_name(gid),
                components,
                flavour: Flavour::Quadratic,
                orientation: Orientation::Cw,
            };
            assert_eq!(decide_exactly(&input, &Budget::unlimited()).unwrap(), GlyphDecision::Unchanged, "{gid}");
        }
        assert!(screened > font.num_glyphs() * 2 / 3, "{screened} of {}", font.num_glyphs());
    }

    #[test]
    fn stored_points_leave_implied_midpoints_out() {
        // a TrueType circle of four quadratics whose on-curve points are all midpoints: 4
        // control points stored
        let c = crate::format::parse_path(
            "M0 -100 Q100 -100 100 0 Q100 100 0 100 Q-100 100 -100 0 Q-100 -100 0 -100 Z",
            crate::num::NumberMode::Exact,
        )
        .unwrap();
        assert_eq!(stored_points(&c[0], Flavour::Quadratic), 4);
        assert_eq!(stored_points(&c[0], Flavour::Cubic), 8);
    }
}
