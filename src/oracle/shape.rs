//! Deciding a float library's answer to a boolean operation against the exact one: the regions,
//! not their spelling.
//!
//! The float result `F` (closed contours with its numbers read exactly, filled by the same rule
//! as the inputs) is compared with the exact result `E` of `op(A, B)`. Two problems make a
//! disagreement, each proved exactly:
//!
//! - **a witness**: a rational point inside one region and outside the other, farther than `tol`
//!   from `E`'s exact boundary (memberships by exact winding numbers of `A`, `B` and `F`; the
//!   distance by exact root isolation: `(x(t) − q_x)² + (y(t) − q_y)² − tol²` has no root on any
//!   piece of `E`);
//! - **the distance**: a point of one boundary proved farther than `tol` from the other.
//!
//! Otherwise the boundaries are proved within `tol` of each other both ways, and the regions
//! equal at every point farther than `tol` from `∂E` (see the private `distance` module: every
//! float segment is matched with the exact piece it follows by certified control-point bounds,
//! refined until proved, and the matched pieces are joined along `∂E` into a closed path that
//! the float boundary is homotopic to away from those points). Where that matching does not
//! account for the whole region (an exact run the float boundary follows twice or not at all, a
//! rational segment), candidate witness points beside every piece of both boundaries are tried.
//! A decision that needs more refinement than the budget allows is refused with the budget's
//! error, never guessed.
//!
//! Differences of representation are **notes**, not problems: the number of contours, their
//! nesting (a hole touching its outer contour drawn as one contour through the touching point or
//! as two), the direction the float result runs.

use super::distance::{Decider, Outcome, far_from};
use crate::error::{Error, Result};
use crate::num::point::Point2;
use crate::num::scalar::{rat, ratio_to_f64};
use crate::path::{FillRule, PathWinding};
use crate::poly::algebraic::RealAlgebraic;
use crate::shape::segment::Seg;
use crate::shape::{BooleanOp, BooleanOptions, BooleanResult, Shape};
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
/// `depths_found`, `witness` (or null), `distance_bound` (a proved upper bound on the distance
/// between the boundaries, rounded up; null when the distance is proved over the tolerance),
/// `distance_at_least` (a proved lower bound when it is over and finite, else null), `problems` (what
/// disagrees, one sentence each), `notes` (differences of representation that are no
/// disagreement).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Agreement {
    /// No disagreement: no witness, and the boundaries within the tolerance.
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
    /// A proved upper bound on the distance between the two boundaries (`None` when the
    /// distance is over the tolerance).
    pub distance_bound: Option<f64>,
    /// A proved lower bound on that distance when it is over the tolerance (`None` when it is
    /// not, or when one result has a boundary and the other none: no finite bound).
    pub distance_at_least: Option<f64>,
    /// What disagrees, in words.
    pub problems: Vec<String>,
    /// How the float result is spelled differently (contours, nesting, direction), in words.
    pub notes: Vec<String>,
}

/// Decides `found` (a float library's result of `op` on `inputs`) against the exact `result`
/// (see the module documentation).
///
/// # Errors
/// [`Error::InvalidArgument`] for a negative `tol`, or for a distance equal to `tol` to binary64
/// resolution (undecided, never guessed); [`Error::WorkLimit`] when deciding the distance or
/// looking for a witness needs more than `budget`; the errors of exact winding numbers at the
/// witness candidates.
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
    let depths = sorted_depths(&result.parents);
    let found_parents = contour_parents(found)?;
    let depths_found = sorted_depths(&found_parents);
    let contours_found = found.path().contours().len();
    let mut notes = vec![];
    if contours_found != result.contours {
        notes.push(format!("{} contours, not {}", contours_found, result.contours));
    } else if depths != depths_found {
        notes.push(format!("nesting depths {depths_found:?}, not {depths:?}"));
    }
    let (segs, cycles) = result.exact_cycles();
    let decider = Decider::new(segs, cycles, found, tol, options.fill == FillRule::EvenOdd, budget)?;
    let outcome = decider.decide()?;
    let mut problems = vec![];
    let (distance_bound, distance_at_least, regions) = match &outcome {
        Outcome::Under { bound, regions, reversed } => {
            if *reversed {
                notes.push("the float result runs the other way".into());
            }
            (Some(*bound), None, *regions)
        }
        Outcome::Over { point, on_found, at_least } => {
            let (this, other) = if *on_found { ("float", "exact") } else { ("exact", "float") };
            problems.push(if at_least.is_infinite() {
                format!("the {this} result has a boundary and the {other} result none")
            } else {
                format!(
                    "the boundaries are more than {at_least} apart, more than the tolerance: the point ({}, {}) of the \
                     {this} boundary is that far from the {other} one",
                    ratio_to_f64(&point.x),
                    ratio_to_f64(&point.y)
                )
            });
            (None, at_least.is_finite().then_some(*at_least), false)
        }
    };
    // where the matching proved the regions equal away from the boundary, no witness exists
    let witness = if regions { None } else { find_witness(result, inputs, found, tol, op, options, budget)? };
    if let Some(w) = &witness {
        problems.insert(
            0,
            format!(
                "the point ({}, {}) is {} the exact result and {} the float result",
                w.point_float[0],
                w.point_float[1],
                if w.inside_exact { "inside" } else { "outside" },
                if w.inside_found { "inside" } else { "outside" }
            ),
        );
    }
    Ok(Agreement {
        agree: problems.is_empty(),
        contours: result.contours,
        contours_found,
        depths,
        depths_found,
        witness,
        distance_bound,
        distance_at_least,
        problems,
        notes,
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

/// A witness: candidates beside the middle of every piece of both boundaries, stepping away
/// along an axis by `1.5·tol·2^k` while the regions differ there; a candidate counts once both
/// memberships are exact and it is proved farther than `tol` from the exact boundary.
fn find_witness(
    result: &BooleanResult,
    inputs: &[Shape],
    found: &Shape,
    tol: &BigRational,
    op: BooleanOp,
    options: BooleanOptions,
    budget: &Budget,
) -> Result<Option<Witness>> {
    let step0 = if tol.is_positive() {
        tol * BigRational::new(3.into(), 2.into())
    } else {
        BigRational::new(1.into(), 1024.into())
    };
    let (segs, cycles) = result.exact_cycles();
    let exact: Vec<(&Seg, BigRational, BigRational)> =
        cycles.iter().flatten().map(|r| (&*segs[r.seg], r.lo.interval().0, r.hi.interval().1)).collect();
    // candidate origins: rational points inside every exact piece and every float segment
    let mut origins: Vec<(Point2<BigRational>, Point2<BigRational>)> = vec![];
    for r in cycles.iter().flatten() {
        let s = &segs[r.seg];
        let t = RealAlgebraic::rational_between(&r.lo, &r.hi);
        origins.push((s.point_at(&t), s.direction_at(&t)));
    }
    for (c, contour) in found.path().contours().iter().enumerate() {
        for (k, seg) in contour.iter().enumerate() {
            let s = Seg::new(0, c, k, seg.clone())?;
            if !s.degenerate {
                let t = BigRational::new(1.into(), 2.into());
                origins.push((s.point_at(&t), s.direction_at(&t)));
            }
        }
    }
    let scale = {
        let mut m = rat(1);
        for s in segs.iter() {
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
    let mut work = 0.0;
    for (p, d) in origins {
        if d.x == rat(0) && d.y == rat(0) {
            continue;
        }
        // the axis nearest to the normal, both ways
        let axis = if d.y.abs() >= d.x.abs() { [rat(1), rat(0)] } else { [rat(0), rat(1)] };
        for sign in [1, -1] {
            let mut s = step0.clone();
            while s < scale {
                work += 2e4;
                budget.check("looking for a point where the regions differ", work)?;
                let q = Point2::new(&p.x + &s * &axis[0] * rat(sign), &p.y + &s * &axis[1] * rat(sign));
                if let Some((ie, ir)) = memberships(inputs, found, &q, op, options)? {
                    if ie == ir {
                        break; // stepped out of the difference
                    }
                    if far_from(&exact, &q, tol) {
                        let point_float = [ratio_to_f64(&q.x), ratio_to_f64(&q.y)];
                        return Ok(Some(Witness { point: q, point_float, inside_exact: ie, inside_found: ir }));
                    }
                }
                s *= rat(2);
            }
        }
    }
    Ok(None)
}
