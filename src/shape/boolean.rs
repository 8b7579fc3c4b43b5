//! Boolean operations on shapes, read off the arrangement.
//!
//! With `inside_i = fill.contains(w_i)` for the winding number `w_i` of input `i`, a point is in
//! the result when `op(inside_0, inside_1)` holds (`union`: or, `intersection`: and,
//! `difference`: `A` and not `B`, `xor`, `simplify`: `A` alone). An edge of the arrangement is
//! on the result's boundary exactly when the operation differs on its two sides; it is
//! oriented with the result on its left (outer contours counter-clockwise, holes clockwise), and
//! the boundary edges are joined at each vertex with the next boundary edge clockwise
//! (`Arrangement::cycles`).
//!
//! **Pinch points.** Where the result touches itself at a vertex (two squares meeting at a
//! corner, a hole touching its outer contour), the boundary is joined sector by sector: each
//! contour turns at the vertex into the boundary of the same sector of the region it arrived
//! along. Two regions that meet only at a point are two contours sharing that vertex; a hole
//! that touches its outer contour at one point makes, with it, one contour that passes through
//! the vertex twice (the region's boundary is one closed curve there).
//!
//! Consecutive edges on one input segment are reported as one piece, and each contour starts at
//! its least piece (by input, contour, segment and parameter), contours in that order too.

use super::area::{contour_area, total_area};
use super::graph::{Arrangement, HalfEdge, InputPiece};
use super::render::svg_path;
use super::runs::{Run, runs};
use super::segment::Seg;
use crate::error::{Error, Result};
use crate::num::point::Point2;
use crate::num::scalar::{rat, ratio_to_f64};
use crate::path::FillRule;
use crate::poly::algebraic::RealAlgebraic;
use crate::work::Budget;
use num_rational::BigRational;
use serde::Serialize;

/// A boolean operation.
///
/// # Example
/// ```
/// use casteljau::shape::BooleanOp;
/// let op: BooleanOp = "difference".parse().unwrap();
/// assert_eq!(op, BooleanOp::Difference);
/// assert!(op.apply(true, false) && !op.apply(true, true));
/// assert_eq!(op.inputs(), 2);
/// assert_eq!(BooleanOp::Simplify.inputs(), 1);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum BooleanOp {
    /// `A ∪ B`.
    Union,
    /// `A ∩ B`.
    Intersection,
    /// `A − B`.
    Difference,
    /// `A △ B`.
    Xor,
    /// The filled region of `A` alone, overlaps removed.
    Simplify,
}

impl BooleanOp {
    /// Whether a point inside `a` (by `A`'s fill) and `b` is inside the result.
    pub fn apply(self, a: bool, b: bool) -> bool {
        match self {
            BooleanOp::Union => a || b,
            BooleanOp::Intersection => a && b,
            BooleanOp::Difference => a && !b,
            BooleanOp::Xor => a ^ b,
            BooleanOp::Simplify => a,
        }
    }

    /// How many inputs it takes.
    pub fn inputs(self) -> usize {
        if self == BooleanOp::Simplify { 1 } else { 2 }
    }

    /// Its name.
    pub fn as_str(self) -> &'static str {
        match self {
            BooleanOp::Union => "union",
            BooleanOp::Intersection => "intersection",
            BooleanOp::Difference => "difference",
            BooleanOp::Xor => "xor",
            BooleanOp::Simplify => "simplify",
        }
    }
}

impl std::str::FromStr for BooleanOp {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        Ok(match s {
            "union" => BooleanOp::Union,
            "intersection" => BooleanOp::Intersection,
            "difference" => BooleanOp::Difference,
            "xor" => BooleanOp::Xor,
            "simplify" => BooleanOp::Simplify,
            other => {
                return Err(Error::InvalidArgument {
                    message: format!(
                        "the operation is union, intersection, difference, xor or simplify, not {other:?}"
                    ),
                });
            }
        })
    }
}

/// The orientation of outer contours (holes the other way).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Orientation {
    /// Counter-clockwise (SVG, CFF, the mathematical convention).
    #[default]
    Ccw,
    /// Clockwise (TrueType).
    Cw,
}

impl Orientation {
    /// The other orientation.
    ///
    /// # Example
    /// ```
    /// use casteljau::shape::Orientation;
    /// assert_eq!(Orientation::Ccw.reversed(), Orientation::Cw);
    /// assert_eq!("cw".parse::<Orientation>().unwrap().reversed(), Orientation::default());
    /// ```
    pub fn reversed(self) -> Orientation {
        match self {
            Orientation::Ccw => Orientation::Cw,
            Orientation::Cw => Orientation::Ccw,
        }
    }
}

impl std::str::FromStr for Orientation {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "ccw" => Ok(Orientation::Ccw),
            "cw" => Ok(Orientation::Cw),
            other => Err(Error::InvalidArgument { message: format!("the orientation is ccw or cw, not {other:?}") }),
        }
    }
}

/// How a boolean operation reads its inputs and writes its result.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BooleanOptions {
    /// The fill rule of every input.
    pub fill: FillRule,
    /// The orientation of the result's outer contours.
    pub orientation: Orientation,
}

/// The result of a boolean operation: oriented boundary contours, each a list of input pieces.
/// JSON (fields are added, never renamed): `contours` (count), `path` (SVG path data, numbers
/// the nearest `f64` in shortest round-trip form), `area` (exact string when rational, else
/// null), `area_float`, `parents` (per contour, the contour directly enclosing it, or null),
/// `orientation` (per contour, `ccw` or `cw`), `pieces` (per contour, [`InputPiece`]s).
#[derive(Clone, Debug, Serialize)]
pub struct BooleanResult {
    /// The number of contours.
    pub contours: usize,
    /// SVG path data.
    pub path: String,
    /// The exact area, when every piece is polynomial with rational ends.
    #[serde(serialize_with = "crate::num::serial::option_string")]
    pub area: Option<BigRational>,
    /// The area, rounded.
    pub area_float: f64,
    /// Per contour, the contour that directly encloses it.
    pub parents: Vec<Option<usize>>,
    /// Per contour, its orientation.
    pub orientation: Vec<Orientation>,
    /// Per contour, its pieces in order.
    pub pieces: Vec<Vec<InputPiece>>,
    /// The exact boundary: the segments used and, per contour, `(segment, lo, hi, forward)`.
    #[serde(skip)]
    exact: ExactBoundary,
}

impl BooleanResult {
    /// The winding number of the result's boundary around a rational point (`1` inside the
    /// result with counter-clockwise outer contours, `-1` with clockwise ones, `0` outside), or
    /// `None` when the point lies on the boundary. Computed from the exact pieces alone.
    ///
    /// # Errors
    /// As the arrangement's ray casting (none for a point off the boundary).
    ///
    /// # Example
    /// ```
    /// use casteljau::shape::{boolean, BooleanOp, BooleanOptions, Shape};
    /// use casteljau::{num::Point2, rat, ratio};
    /// let a: Shape = "M0 0 H2 V2 H0 Z".parse().unwrap();
    /// let b: Shape = "M1 1 H3 V3 H1 Z".parse().unwrap();
    /// let d = boolean(BooleanOp::Difference, &[a, b], BooleanOptions::default(), &casteljau::work::Budget::unlimited()).unwrap();
    /// let p = Point2::new;
    /// assert_eq!(d.winding(&p(ratio(1, 2), ratio(1, 2))).unwrap(), Some(1));
    /// assert_eq!(d.winding(&p(ratio(3, 2), ratio(3, 2))).unwrap(), Some(0));
    /// assert_eq!(d.winding(&p(rat(1), ratio(3, 2))).unwrap(), None); // on the boundary
    /// ```
    pub fn winding(&self, q: &Point2<BigRational>) -> Result<Option<i64>> {
        use super::ray::{Axis, Origin, Piece, RayWinding, winding};
        let (segs, cycles) = &self.exact;
        let pieces: Vec<Vec<Piece<'_>>> = cycles
            .iter()
            .map(|c| {
                c.iter()
                    .map(|r| Piece { seg: &segs[r.seg], lo: r.lo.clone(), hi: r.hi.clone(), forward: r.forward })
                    .collect()
            })
            .collect();
        Ok(match winding(&pieces, q, Axis::PosX, Origin::Free)? {
            RayWinding::Off(w) => Some(w),
            RayWinding::On { .. } => None,
        })
    }

    /// The exact boundary: the segments used and, per contour, its runs.
    pub(crate) fn exact_cycles(&self) -> (&[std::sync::Arc<Seg>], &[Vec<ExactRun>]) {
        (&self.exact.0, &self.exact.1)
    }

    /// Whether a rational point is inside the result (`None` on its boundary).
    ///
    /// # Errors
    /// As [`Self::winding`].
    ///
    /// # Example
    /// ```
    /// use casteljau::shape::{boolean, BooleanOp, BooleanOptions, Shape};
    /// use casteljau::{num::Point2, ratio};
    /// let a: Shape = "M0 0 H2 V2 H0 Z".parse().unwrap();
    /// let r = boolean(BooleanOp::Simplify, &[a], BooleanOptions::default(), &casteljau::work::Budget::unlimited()).unwrap();
    /// assert_eq!(r.contains(&Point2::new(ratio(1, 2), ratio(1, 3))).unwrap(), Some(true));
    /// ```
    pub fn contains(&self, q: &Point2<BigRational>) -> Result<Option<bool>> {
        Ok(self.winding(q)?.map(|w| w != 0))
    }
}

/// The boundary of `op` applied to the inputs (one for `simplify`, two otherwise), within a work
/// budget (the arrangement's estimate, checked before it starts; [`Budget::unlimited`] for no
/// limit).
///
/// # Errors
/// [`Error::InvalidArgument`] for the wrong number of inputs; the errors of
/// [`Arrangement::new`] and [`Arrangement::faces`].
///
/// # Example
/// ```
/// use casteljau::shape::{boolean, BooleanOp, BooleanOptions, Shape};
/// use casteljau::{rat, work::Budget};
/// let any = Budget::unlimited();
/// let a: Shape = "M0 0 H2 V2 H0 Z".parse().unwrap();
/// let b: Shape = "M1 1 H3 V3 H1 Z".parse().unwrap();
/// let u = boolean(BooleanOp::Union, &[a.clone(), b.clone()], BooleanOptions::default(), &any).unwrap();
/// assert_eq!((u.contours, u.area.clone().unwrap()), (1, rat(7)));
/// assert_eq!(u.path, "M0 0L2 0L2 1L3 1L3 3L1 3L1 2L0 2Z");
/// let i = boolean(BooleanOp::Intersection, &[a.clone(), b.clone()], BooleanOptions::default(), &any).unwrap();
/// assert_eq!(i.area.unwrap(), rat(1));
/// let x = boolean(BooleanOp::Xor, &[a.clone(), a], BooleanOptions::default(), &any).unwrap();
/// assert_eq!(x.contours, 0); // A xor A is empty
/// ```
pub fn boolean(
    op: BooleanOp,
    inputs: &[super::Shape],
    options: BooleanOptions,
    budget: &Budget,
) -> Result<BooleanResult> {
    if inputs.len() != op.inputs() {
        return Err(Error::InvalidArgument {
            message: format!("{} takes {} input(s), not {}", op.as_str(), op.inputs(), inputs.len()),
        });
    }
    let arr = Arrangement::new(inputs, budget)?;
    result_of(&arr, op, options, budget)
}

/// The result of `op` on an arrangement of its inputs.
pub(crate) fn result_of(
    arr: &Arrangement,
    op: BooleanOp,
    options: BooleanOptions,
    budget: &Budget,
) -> Result<BooleanResult> {
    let fill = options.fill;
    let inside = |w: &[i64]| op.apply(fill.contains(w[0]), w.len() > 1 && fill.contains(w[1]));
    let keep = |h: HalfEdge| {
        let twin = HalfEdge { edge: h.edge, forward: !h.forward };
        inside(arr.side(h)) && !inside(arr.side(twin))
    };
    let mut cycles = arr.cycles(&keep)?;
    let mut contours: Vec<Vec<Run>> = cycles.iter().map(|c| runs(arr, c)).collect();
    // 4. the exact areas and the rounded path, priced by the runs' irrational ends
    let runs_count: usize = contours.iter().map(Vec::len).sum();
    let ends: f64 = contours
        .iter()
        .flatten()
        .map(|r| {
            super::estimate::run_end(&arr.segs[r.seg], &r.from) + super::estimate::run_end(&arr.segs[r.seg], &r.to)
        })
        .sum();
    budget.check(format!("the exact areas and path of the result ({runs_count} runs)"), ends)?;
    // canonical order: each contour from its least run, contours by their first run
    for (c, cyc) in contours.iter_mut().zip(cycles.iter_mut()) {
        let start = (0..c.len()).min_by(|&i, &j| c[i].key().cmp(&c[j].key())).unwrap_or(0);
        c.rotate_left(start);
        let first = c.first().map_or(0, |r| r.first);
        cyc.rotate_left(first);
    }
    let mut order: Vec<usize> = (0..contours.len()).collect();
    order.sort_by(|&i, &j| contours[i][0].key().cmp(&contours[j][0].key()));
    let contours: Vec<Vec<Run>> = order.iter().map(|&i| contours[i].clone()).collect();
    let cycles: Vec<Vec<HalfEdge>> = order.iter().map(|&i| cycles[i].clone()).collect();
    // orientation: the sign of the contour's exact area, or else its winding number just left
    // of itself: 1 (ccw) or 0 (cw)
    let areas: Vec<_> = contours.iter().map(|c| contour_area(arr, c)).collect();
    let mut orientation = vec![];
    for (c, a) in cycles.iter().zip(&areas) {
        let ccw = match a.exact().map(|a| a.cmp(&rat(0))) {
            Some(std::cmp::Ordering::Greater) => true,
            Some(std::cmp::Ordering::Less) => false,
            _ => arr.beside(std::slice::from_ref(c), c[0])? == 1,
        };
        orientation.push(if ccw { Orientation::Ccw } else { Orientation::Cw });
    }
    // nesting: contours around a point just beside each contour (none when the point is outside
    // the contour's box)
    let n = cycles.len();
    let boxes: Vec<[f64; 4]> = cycles.iter().map(|c| cycle_box(arr, c)).collect();
    let mut encloses = vec![vec![false; n]; n];
    for (j, cj) in cycles.iter().enumerate() {
        let (probe, _) = arr.beside_point(cj[0]);
        let q = [ratio_to_f64(&probe.x), ratio_to_f64(&probe.y)];
        for (i, ci) in cycles.iter().enumerate() {
            let b = boxes[i];
            if i == j || q[0] < b[0] || q[0] > b[2] || q[1] < b[1] || q[1] > b[3] {
                continue;
            }
            if arr.beside(std::slice::from_ref(ci), cj[0])? != 0 {
                encloses[i][j] = true;
            }
        }
    }
    let depth: Vec<usize> = (0..n).map(|j| (0..n).filter(|&i| encloses[i][j]).count()).collect();
    let parents: Vec<Option<usize>> =
        (0..n).map(|j| (0..n).filter(|&i| encloses[i][j]).max_by_key(|&i| depth[i])).collect();
    let (area, area_float) = total_area(&areas)?;
    let flip = options.orientation == Orientation::Cw;
    let orientation = orientation.into_iter().map(|o| if flip { o.reversed() } else { o }).collect();
    let (area, area_float) = if flip { (area.map(|a| -a), -area_float) } else { (area, area_float) };
    let pieces: Vec<Vec<InputPiece>> = contours
        .iter()
        .map(|c| {
            let mut ps: Vec<InputPiece> = c.iter().map(|r| r.piece(arr)).collect();
            if flip {
                ps.reverse();
                for p in &mut ps {
                    std::mem::swap(&mut p.from, &mut p.to);
                    std::mem::swap(&mut p.from_float, &mut p.to_float);
                }
            }
            ps
        })
        .collect();
    let path = svg_path(arr, &pieces);
    let exact = exact_boundary(arr, &contours, flip);
    Ok(BooleanResult { contours: pieces.len(), path, area, area_float, parents, orientation, pieces, exact })
}

/// One run of a result's exact boundary: the segment (an index into the result's segments), its
/// parameter interval `lo < hi`, whether the contour runs along it from `lo` to `hi`, and the
/// arrangement's vertices it starts and ends at (in the contour's direction).
#[derive(Clone, Debug)]
pub(crate) struct ExactRun {
    pub(crate) seg: usize,
    pub(crate) lo: RealAlgebraic,
    pub(crate) hi: RealAlgebraic,
    pub(crate) forward: bool,
    pub(crate) start: usize,
    pub(crate) end: usize,
}

/// The segments a result uses, and per contour its runs.
type ExactBoundary = (Vec<std::sync::Arc<Seg>>, Vec<Vec<ExactRun>>);

fn exact_boundary(arr: &Arrangement, contours: &[Vec<Run>], flip: bool) -> ExactBoundary {
    let mut segs: Vec<std::sync::Arc<Seg>> = vec![];
    let mut index: std::collections::HashMap<usize, usize> = std::collections::HashMap::new();
    let mut cycles = vec![];
    for c in contours {
        let mut cycle = vec![];
        for (i, r) in c.iter().enumerate() {
            let k = *index.entry(r.seg).or_insert_with(|| {
                segs.push(arr.segs[r.seg].clone());
                segs.len() - 1
            });
            let forward = r.from <= r.to;
            let (lo, hi) = if forward { (r.from.clone(), r.to.clone()) } else { (r.to.clone(), r.from.clone()) };
            let (start, end) = (r.start, c[(i + 1) % c.len()].start);
            let (start, end) = if flip { (end, start) } else { (start, end) };
            cycle.push(ExactRun { seg: k, lo, hi, forward: forward != flip, start, end });
        }
        if flip {
            cycle.reverse();
        }
        cycles.push(cycle);
    }
    (segs, cycles)
}

/// The union of the boxes of a cycle's segments.
fn cycle_box(arr: &Arrangement, c: &[HalfEdge]) -> [f64; 4] {
    let mut b = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];
    for h in c {
        match arr.segs[arr.edges[h.edge].seg].bbox {
            Some(s) => {
                b = [b[0].min(s[0]), b[1].min(s[1]), b[2].max(s[2]), b[3].max(s[3])];
            }
            None => return [f64::NEG_INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::INFINITY],
        }
    }
    b
}
