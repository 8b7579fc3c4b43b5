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

use super::arrangement::{Arrangement, HalfEdge, InputPiece};
use super::segment::Seg;
use crate::error::{Error, Result};
use crate::num::scalar::{rat, ratio_to_f64};
use crate::path::FillRule;
use crate::poly::Poly;
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
pub enum Direction {
    /// Counter-clockwise (SVG, CFF, the mathematical convention).
    #[default]
    Ccw,
    /// Clockwise (TrueType).
    Cw,
}

impl Direction {
    /// The other direction.
    ///
    /// # Example
    /// ```
    /// use casteljau::shape::Direction;
    /// assert_eq!(Direction::Ccw.reversed(), Direction::Cw);
    /// assert_eq!("cw".parse::<Direction>().unwrap().reversed(), Direction::default());
    /// ```
    pub fn reversed(self) -> Direction {
        match self {
            Direction::Ccw => Direction::Cw,
            Direction::Cw => Direction::Ccw,
        }
    }
}

impl std::str::FromStr for Direction {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "ccw" => Ok(Direction::Ccw),
            "cw" => Ok(Direction::Cw),
            other => Err(Error::InvalidArgument { message: format!("the direction is ccw or cw, not {other:?}") }),
        }
    }
}

/// How a boolean operation reads its inputs and writes its result.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BooleanOptions {
    /// The fill rule of every input.
    pub fill: FillRule,
    /// The orientation of the result's outer contours.
    pub direction: Direction,
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
    pub orientation: Vec<Direction>,
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
    /// [`Error::InvalidArgument`] for a point that is not planar.
    ///
    /// # Example
    /// ```
    /// use casteljau::shape::{boolean, BooleanOp, BooleanOptions, Shape};
    /// use casteljau::{Point, rat, ratio};
    /// let a: Shape = "M0 0 H2 V2 H0 Z".parse().unwrap();
    /// let b: Shape = "M1 1 H3 V3 H1 Z".parse().unwrap();
    /// let d = boolean(BooleanOp::Difference, &[a, b], BooleanOptions::default()).unwrap();
    /// let p = |x, y| Point::new(vec![x, y]);
    /// assert_eq!(d.winding(&p(ratio(1, 2), ratio(1, 2))).unwrap(), Some(1));
    /// assert_eq!(d.winding(&p(ratio(3, 2), ratio(3, 2))).unwrap(), Some(0));
    /// assert_eq!(d.winding(&p(rat(1), ratio(3, 2))).unwrap(), None); // on the boundary
    /// ```
    pub fn winding(&self, q: &crate::num::point::Point<BigRational>) -> Result<Option<i64>> {
        use super::ray::{Axis, Origin, Piece, RayWinding, winding};
        if q.dim() != 2 {
            return Err(Error::InvalidArgument { message: "points are planar".into() });
        }
        let (segs, cycles) = &self.exact;
        let pieces: Vec<Vec<Piece<'_>>> = cycles
            .iter()
            .map(|c| {
                c.iter()
                    .map(|(k, lo, hi, forward)| Piece {
                        seg: &segs[*k],
                        lo: lo.clone(),
                        hi: hi.clone(),
                        forward: *forward,
                    })
                    .collect()
            })
            .collect();
        Ok(match winding(&pieces, q, Axis::PosX, Origin::Free)? {
            RayWinding::Off(w) => Some(w),
            RayWinding::On { .. } => None,
        })
    }

    /// The exact boundary pieces: each segment with its parameter interval.
    pub(crate) fn exact_boundary(&self) -> Vec<(std::sync::Arc<Seg>, RealAlgebraic, RealAlgebraic)> {
        let (segs, cycles) = &self.exact;
        cycles.iter().flatten().map(|(k, lo, hi, _)| (segs[*k].clone(), lo.clone(), hi.clone())).collect()
    }

    /// Whether a rational point is inside the result (`None` on its boundary).
    ///
    /// # Errors
    /// As [`Self::winding`].
    ///
    /// # Example
    /// ```
    /// use casteljau::shape::{boolean, BooleanOp, BooleanOptions, Shape};
    /// use casteljau::{Point, ratio};
    /// let a: Shape = "M0 0 H2 V2 H0 Z".parse().unwrap();
    /// let r = boolean(BooleanOp::Simplify, &[a], BooleanOptions::default()).unwrap();
    /// assert_eq!(r.contains(&Point::new(vec![ratio(1, 2), ratio(1, 3)])).unwrap(), Some(true));
    /// ```
    pub fn contains(&self, q: &crate::num::point::Point<BigRational>) -> Result<Option<bool>> {
        Ok(self.winding(q)?.map(|w| w != 0))
    }
}

/// The boundary of `op` applied to the inputs (one for `simplify`, two otherwise), without a
/// work limit.
///
/// # Errors
/// As [`boolean_within`].
///
/// # Example
/// ```
/// use casteljau::shape::{boolean, BooleanOp, BooleanOptions, Shape};
/// use casteljau::rat;
/// let a: Shape = "M0 0 H2 V2 H0 Z".parse().unwrap();
/// let b: Shape = "M1 1 H3 V3 H1 Z".parse().unwrap();
/// let u = boolean(BooleanOp::Union, &[a.clone(), b.clone()], BooleanOptions::default()).unwrap();
/// assert_eq!((u.contours, u.area.clone().unwrap()), (1, rat(7)));
/// assert_eq!(u.path, "M0 0L2 0L2 1L3 1L3 3L1 3L1 2L0 2Z");
/// let i = boolean(BooleanOp::Intersection, &[a.clone(), b.clone()], BooleanOptions::default()).unwrap();
/// assert_eq!(i.area.unwrap(), rat(1));
/// let x = boolean(BooleanOp::Xor, &[a.clone(), a], BooleanOptions::default()).unwrap();
/// assert_eq!(x.contours, 0); // A xor A is empty
/// ```
pub fn boolean(op: BooleanOp, inputs: &[super::Shape], options: BooleanOptions) -> Result<BooleanResult> {
    boolean_within(op, inputs, options, &Budget::unlimited())
}

/// [`boolean`] within a work budget (the arrangement's estimate, checked before it starts).
///
/// # Errors
/// [`Error::InvalidArgument`] for the wrong number of inputs; the errors of
/// [`Arrangement::new_within`] and [`Arrangement::faces`] (pinch points at irrational tangent
/// vertices).
pub fn boolean_within(
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
    let arr = Arrangement::new_within(inputs, budget)?;
    result_of(&arr, op, options)
}

/// The result of `op` on an arrangement of its inputs.
pub(crate) fn result_of(arr: &Arrangement, op: BooleanOp, options: BooleanOptions) -> Result<BooleanResult> {
    let fill = options.fill;
    let inside = |w: &[i64]| op.apply(fill.contains(w[0]), w.len() > 1 && fill.contains(w[1]));
    let keep = |h: HalfEdge| {
        let twin = HalfEdge { edge: h.edge, forward: !h.forward };
        inside(arr.side(h)) && !inside(arr.side(twin))
    };
    let mut cycles = arr.cycles(&keep)?;
    let mut contours: Vec<Vec<Run>> = cycles.iter().map(|c| runs(arr, c)).collect();
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
    let areas: Vec<(Option<BigRational>, f64)> = contours.iter().map(|c| contour_area(arr, c)).collect();
    let mut orientation = vec![];
    for (c, (a, _)) in cycles.iter().zip(&areas) {
        let ccw = match a.as_ref().map(|a| a.cmp(&rat(0))) {
            Some(std::cmp::Ordering::Greater) => true,
            Some(std::cmp::Ordering::Less) => false,
            _ => arr.beside(std::slice::from_ref(c), c[0])? == 1,
        };
        orientation.push(if ccw { Direction::Ccw } else { Direction::Cw });
    }
    // nesting: contours around a point just beside each contour (none when the point is outside
    // the contour's box)
    let n = cycles.len();
    let boxes: Vec<[f64; 4]> = cycles.iter().map(|c| cycle_box(arr, c)).collect();
    let mut encloses = vec![vec![false; n]; n];
    for (j, cj) in cycles.iter().enumerate() {
        let (probe, _) = arr.beside_point(cj[0]);
        let q = [ratio_to_f64(&probe.coords[0]), ratio_to_f64(&probe.coords[1])];
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
    let (area, area_float) = total_area(&areas);
    let flip = options.direction == Direction::Cw;
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

/// The segments a result uses, and per contour its runs as `(segment, lo, hi, forward)`.
type ExactBoundary = (Vec<std::sync::Arc<Seg>>, Vec<Vec<(usize, RealAlgebraic, RealAlgebraic, bool)>>);

fn exact_boundary(arr: &Arrangement, contours: &[Vec<Run>], flip: bool) -> ExactBoundary {
    let mut segs: Vec<std::sync::Arc<Seg>> = vec![];
    let mut index: std::collections::HashMap<usize, usize> = std::collections::HashMap::new();
    let mut cycles = vec![];
    for c in contours {
        let mut cycle = vec![];
        for r in c {
            let k = *index.entry(r.seg).or_insert_with(|| {
                segs.push(arr.segs[r.seg].clone());
                segs.len() - 1
            });
            let forward = r.from <= r.to;
            let (lo, hi) = if forward { (r.from.clone(), r.to.clone()) } else { (r.to.clone(), r.from.clone()) };
            cycle.push((k, lo, hi, forward != flip));
        }
        if flip {
            cycle.reverse();
        }
        cycles.push(cycle);
    }
    (segs, cycles)
}

/// A maximal run of boundary edges on one segment: parameters `from → to`.
#[derive(Clone, Debug)]
struct Run {
    seg: usize,
    from: RealAlgebraic,
    to: RealAlgebraic,
    /// The index of its first half-edge in the cycle.
    first: usize,
}

impl Run {
    fn key(&self) -> (usize, RealAlgebraic) {
        (self.seg, self.from.clone())
    }
    fn piece(&self, arr: &Arrangement) -> InputPiece {
        let forward = self.from <= self.to;
        let (lo, hi) = if forward { (&self.from, &self.to) } else { (&self.to, &self.from) };
        arr.input_piece(self.seg, lo, hi, forward)
    }
}

/// The cycle's edges (each by its first carrier) joined into runs on one segment.
fn runs(arr: &Arrangement, cycle: &[HalfEdge]) -> Vec<Run> {
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
        out.push(Run { seg: *k, from, to, first: i });
    }
    if out.len() > 1 {
        let (first, last) = (&out[0], &out[out.len() - 1]);
        if first.seg == last.seg && last.to == first.from && ((first.from < first.to) == (last.from < last.to)) {
            let last = out.pop().expect("two runs");
            out[0].from = last.from;
            out[0].first = last.first;
        }
    }
    out
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

/// The sum of the contours' areas: exact when every one is, with its correctly rounded value.
fn total_area(areas: &[(Option<BigRational>, f64)]) -> (Option<BigRational>, f64) {
    let mut exact = Some(rat(0));
    let mut float = 0.0;
    for (a, f) in areas {
        match (a, &mut exact) {
            (Some(a), Some(e)) => *e += a,
            _ => exact = None,
        }
        float += f;
    }
    match exact {
        Some(a) => {
            let f = ratio_to_f64(&a);
            (Some(a), f)
        }
        None => (None, float),
    }
}

/// `∮ (x dy − y dx)/2` over one contour: exact when every piece is polynomial with rational
/// ends (or ends where the antiderivative is rational), else the sum of the pieces' values
/// (each exact real algebraic, rounded; or by Gauss–Legendre quadrature for rational segments).
fn contour_area(arr: &Arrangement, runs: &[Run]) -> (Option<BigRational>, f64) {
    let mut exact = Some(rat(0));
    let mut float = 0.0;
    // whole small-integer pieces: numerators over 240 in i128 (60·K, and 4 for the doubled points)
    let mut sixtieths: i128 = 0;
    let (zero, one) = (RealAlgebraic::from(rat(0)), RealAlgebraic::from(rat(1)));
    for r in runs {
        let s = &arr.segs[r.seg];
        let sign = if r.from == zero && r.to == one {
            Some(1)
        } else if r.from == one && r.to == zero {
            Some(-1)
        } else {
            None
        };
        if let (Some(sign), Some(v)) = (sign, whole_area_sixtieths(s))
            && let Some(next) = sixtieths.checked_add(sign * v)
        {
            sixtieths = next;
            continue;
        }
        let (a, f) = piece_area(s, &r.from, &r.to);
        match (a, &mut exact) {
            (Some(a), Some(e)) => *e += a,
            _ => exact = None,
        }
        float += f;
    }
    let small = BigRational::new(sixtieths.into(), 240.into());
    match exact {
        Some(a) => {
            let a = a + small;
            let f = ratio_to_f64(&a);
            (Some(a), f)
        }
        None => (None, float + ratio_to_f64(&small)),
    }
}

/// [`whole_area`] times 240 for a polynomial segment of degree ≤ 3 with small control points:
/// `Σ 60·K[i][j]·(XᵢYⱼ − XⱼYᵢ)` in `i128` with `X = 2x`, `Y = 2y` (`60·K` is integral for these
/// degrees).
fn whole_area_sixtieths(s: &Seg) -> Option<i128> {
    use std::sync::OnceLock;
    static TABLES: OnceLock<Vec<Vec<Vec<i128>>>> = OnceLock::new();
    let tables = TABLES.get_or_init(|| {
        (0..=3)
            .map(|n| {
                if n == 0 {
                    return vec![];
                }
                area_matrix(n)
                    .iter()
                    .map(|row| {
                        row.iter()
                            .map(|k| {
                                let v = k * rat(60);
                                assert!(v.is_integer(), "60·K is integral for degree ≤ 3");
                                num_traits::ToPrimitive::to_i128(&v.to_integer()).expect("small")
                            })
                            .collect()
                    })
                    .collect()
            })
            .collect()
    });
    let (p, n) = (s.small.as_ref()?, s.degree());
    if !s.polynomial || n == 0 || n > 3 {
        return None;
    }
    let k = &tables[n];
    let mut total: i128 = 0;
    for i in 0..=n {
        for j in i + 1..=n {
            let cross = p[i][0] as i128 * p[j][1] as i128 - p[j][0] as i128 * p[i][1] as i128;
            total += k[i][j] * cross;
        }
    }
    Some(total)
}

/// `K[i][j] = (M[i][j] − M[j][i])/2` with `M[i][j] = ∫₀¹ Bᵢⁿ (Bⱼⁿ)′ dt`, so that a whole
/// polynomial segment's `∫ (x dy − y dx)/2 = Σ_{i<j} K[i][j] (xᵢyⱼ − xⱼyᵢ)`; from
/// `(Bⱼⁿ)′ = n(Bⱼ₋₁ⁿ⁻¹ − Bⱼⁿ⁻¹)` and `∫₀¹ Bᵢⁿ Bₖᵐ = C(n,i)C(m,k) / ((n+m+1) C(n+m, i+k))`.
fn area_matrix(n: usize) -> Vec<Vec<BigRational>> {
    let c = |n: usize, k: usize| -> BigRational {
        BigRational::from_integer((0..k).fold(num_bigint::BigInt::from(1), |acc, i| acc * (n - i) / (i + 1)))
    };
    let prod = |i: usize, k: usize| -> BigRational {
        // ∫ B_i^n B_k^{n−1}
        c(n, i) * c(n - 1, k) / (BigRational::from_integer((2 * n).into()) * c(2 * n - 1, i + k))
    };
    let m = |i: usize, j: usize| -> BigRational {
        let mut v = rat(0);
        if j >= 1 {
            v += prod(i, j - 1);
        }
        if j < n {
            v -= prod(i, j);
        }
        v * rat(n as i64)
    };
    (0..=n).map(|i| (0..=n).map(|j| (m(i, j) - m(j, i)) / rat(2)).collect()).collect()
}

/// The area contribution of a whole polynomial segment traversed forwards, from its control
/// points (small integers: the cross products in `i128`).
fn whole_area(s: &Seg) -> Option<BigRational> {
    use std::sync::OnceLock;
    static TABLES: OnceLock<Vec<Vec<Vec<BigRational>>>> = OnceLock::new();
    let tables = TABLES.get_or_init(|| {
        (0..=crate::intersect::MAX_INTERSECT_DEGREE).map(|n| if n == 0 { vec![] } else { area_matrix(n) }).collect()
    });
    let n = s.degree();
    if !s.polynomial || n == 0 || n >= tables.len() {
        return None;
    }
    let k = &tables[n];
    let mut total = rat(0);
    match (&s.small, &s.hull) {
        (Some(p), _) => {
            for i in 0..=n {
                for j in i + 1..=n {
                    // the doubled points: cross products four times too large
                    let cross = p[i][0] as i128 * p[j][1] as i128 - p[j][0] as i128 * p[i][1] as i128;
                    if cross != 0 {
                        total += &k[i][j] * BigRational::new(cross.into(), 4.into());
                    }
                }
            }
        }
        (None, Some(p)) => {
            for i in 0..=n {
                for j in i + 1..=n {
                    let (a, b) = (&p[i].coords, &p[j].coords);
                    total += &k[i][j] * (&a[0] * &b[1] - &b[0] * &a[1]);
                }
            }
        }
        _ => return None,
    }
    Some(total)
}

/// The antiderivative of `(X Y' − Y X')/(2W²)` for a polynomial segment (`W` constant).
fn area_antiderivative(s: &Seg) -> Option<Poly<BigRational>> {
    if !s.polynomial {
        return None;
    }
    let w = s.w().coeff(0);
    let integrand = &(s.x() * &s.y().derivative()) - &(s.y() * &s.x().derivative());
    Some(integrand.scale(&(rat(1) / (&w * &w * rat(2)))).integral())
}

fn piece_area(s: &Seg, from: &RealAlgebraic, to: &RealAlgebraic) -> (Option<BigRational>, f64) {
    let (zero, one) = (RealAlgebraic::from(rat(0)), RealAlgebraic::from(rat(1)));
    let whole = if *from == zero && *to == one {
        Some(false)
    } else if *from == one && *to == zero {
        Some(true)
    } else {
        None
    };
    if let Some(reversed) = whole
        && let Some(a) = whole_area(s)
    {
        let a = if reversed { -a } else { a };
        let f = ratio_to_f64(&a);
        return (Some(a), f);
    }
    if let Some(f) = area_antiderivative(s) {
        if let (Some(a), Some(b)) = (from.to_rational(), to.to_rational()) {
            let v = f.eval(b) - f.eval(a);
            let x = ratio_to_f64(&v);
            return (Some(v), x);
        }
        // F at an algebraic end: a real algebraic number, rational more often than not (a
        // piece on a line through the origin, a symmetric end)
        let at = |t: &RealAlgebraic| match t.to_rational() {
            Some(r) => RealAlgebraic::from(f.eval(r)),
            None => t.map_rational(&f, &Poly::constant(rat(1))),
        };
        let (fa, fb) = (at(from), at(to));
        if let (Some(a), Some(b)) = (fa.to_rational(), fb.to_rational()) {
            let v = b - a;
            let x = ratio_to_f64(&v);
            return (Some(v), x);
        }
        return (None, fb.to_f64() - fa.to_f64());
    }
    // rational segment: Gauss–Legendre on the homogeneous form
    let (a, b) = (from.to_f64(), to.to_f64());
    let (dx, dy, dw) = (s.x().derivative(), s.y().derivative(), s.w().derivative());
    let integrand = |t: f64| {
        let (x, y, w) = (s.x().eval_f64(t), s.y().eval_f64(t), s.w().eval_f64(t));
        let (xp, yp, wp) = (dx.eval_f64(t), dy.eval_f64(t), dw.eval_f64(t));
        // d(x/w) = (x'w − xw')/w², so x dy − y dx = (x(y'w − yw') − y(x'w − xw'))/w³
        (x * (yp * w - y * wp) - y * (xp * w - x * wp)) / (w * w * w) / 2.0
    };
    (None, gauss_legendre(integrand, a, b))
}

fn gauss_legendre(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    // 16 nodes on each half of [a, b]
    const X: [f64; 8] = [
        0.0950125098376374,
        0.2816035507792589,
        0.4580167776572274,
        0.6178762444026438,
        0.755_404_408_355_003,
        0.8656312023878318,
        0.9445750230732326,
        0.9894009349916499,
    ];
    const W: [f64; 8] = [
        0.1894506104550685,
        0.1826034150449236,
        0.1691565193950025,
        0.1495959888165767,
        0.1246289712555339,
        0.0951585116824928,
        0.0622535239386479,
        0.0271524594117541,
    ];
    let half = |a: f64, b: f64| {
        let (c, r) = ((a + b) / 2.0, (b - a) / 2.0);
        r * X.iter().zip(W).map(|(x, w)| w * (f(c - r * x) + f(c + r * x))).sum::<f64>()
    };
    let m = (a + b) / 2.0;
    half(a, m) + half(m, b)
}

/// SVG path data of the pieces: `M`, then `L`, `Q` or `C` per polynomial piece (the sub-curve's
/// control points, exact when both ends are rational, then rounded; the ends always the nearest
/// `f64` of the exact end points), rational pieces as four cubics through their points and
/// tangents (an approximation: `pieces` is the exact answer), `Z`.
fn svg_path(arr: &Arrangement, contours: &[Vec<InputPiece>]) -> String {
    let mut out = String::new();
    let seg_of = |p: &InputPiece| {
        let ids = &arr.contours[p.input][p.contour];
        &arr.segs[ids[p.segment]]
    };
    for c in contours {
        for (i, p) in c.iter().enumerate() {
            let s = seg_of(p);
            let ctrl = sub_curve(s, &p.from, &p.to);
            if i == 0 {
                out.push_str(&format!("M{}", xy(ctrl[0][0])));
            }
            let closing = i + 1 == c.len() && c.len() > 1 && ctrl.len() == 1 && ctrl[0].len() == 2;
            if closing {
                break; // `Z` draws the closing line
            }
            for piece in ctrl {
                let letter = match piece.len() {
                    2 => "L",
                    3 => "Q",
                    _ => "C",
                };
                out.push_str(letter);
                let rest: Vec<String> = piece[1..].iter().map(|q| xy(*q)).collect();
                out.push_str(&rest.join(" "));
            }
        }
        if !c.is_empty() {
            out.push('Z');
        }
    }
    out
}

fn xy(p: [f64; 2]) -> String {
    let f = |v: f64| if v == 0.0 { "0".to_string() } else { format!("{v}") };
    format!("{} {}", f(p[0]), f(p[1]))
}

/// Control points (rounded) of the sub-curve `from → to`, as one or more curves.
fn sub_curve(s: &Seg, from: &RealAlgebraic, to: &RealAlgebraic) -> Vec<Vec<[f64; 2]>> {
    let polynomial = s.polynomial;
    if polynomial && let (Some(a), Some(b), Some(ps)) = (from.to_rational(), to.to_rational(), &s.hull) {
        let (zero, one) = (rat(0), rat(1));
        let f = |p: &crate::num::point::Point<BigRational>| [ratio_to_f64(&p.coords[0]), ratio_to_f64(&p.coords[1])];
        if *a == zero && *b == one {
            return vec![ps.iter().map(f).collect()];
        }
        if *a == one && *b == zero {
            return vec![ps.iter().rev().map(f).collect()];
        }
    }
    let (p0, p1) = (s.point_float(from), s.point_float(to));
    if !polynomial {
        return hermite(s, from.to_f64(), to.to_f64(), p0, p1);
    }
    let near = |t: &RealAlgebraic| -> BigRational {
        match t.to_rational() {
            Some(r) => r.clone(),
            None => {
                let mut t = t.clone();
                t.refine(&BigRational::new(1.into(), num_bigint::BigInt::from(1) << 80));
                let (lo, hi) = t.interval();
                (lo + hi) / rat(2)
            }
        }
    };
    let (a, b) = (near(from), near(to));
    let piece = s.curve.homogeneous().subsegment(&a, &b);
    let pts = piece.points();
    let n = pts.len();
    let mut out: Vec<[f64; 2]> = pts
        .iter()
        .map(|p| [ratio_to_f64(&(&p.coords[0] / &p.coords[2])), ratio_to_f64(&(&p.coords[1] / &p.coords[2]))])
        .collect();
    out[0] = p0;
    out[n - 1] = p1;
    vec![out]
}

/// Four cubics through the points and tangents of a rational piece (rounded).
fn hermite(s: &Seg, a: f64, b: f64, p0: [f64; 2], p1: [f64; 2]) -> Vec<Vec<[f64; 2]>> {
    let (dx, dy, dw) = (s.x().derivative(), s.y().derivative(), s.w().derivative());
    let point = |t: f64| {
        let w = s.w().eval_f64(t);
        [s.x().eval_f64(t) / w, s.y().eval_f64(t) / w]
    };
    let tangent = |t: f64| {
        let (x, y, w) = (s.x().eval_f64(t), s.y().eval_f64(t), s.w().eval_f64(t));
        let (xp, yp, wp) = (dx.eval_f64(t), dy.eval_f64(t), dw.eval_f64(t));
        [(xp * w - x * wp) / (w * w), (yp * w - y * wp) / (w * w)]
    };
    let k = 4;
    (0..k)
        .map(|i| {
            let (t0, t1) = (a + (b - a) * i as f64 / k as f64, a + (b - a) * (i + 1) as f64 / k as f64);
            let (q0, q1) = (if i == 0 { p0 } else { point(t0) }, if i + 1 == k { p1 } else { point(t1) });
            let (d0, d1) = (tangent(t0), tangent(t1));
            let h = (t1 - t0) / 3.0;
            vec![q0, [q0[0] + d0[0] * h, q0[1] + d0[1] * h], [q1[0] - d1[0] * h, q1[1] - d1[1] * h], q1]
        })
        .collect()
}
