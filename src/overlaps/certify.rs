//! The written outline re-decided exactly: what makes a rounded glyph certified.
//!
//! The written contours are read back as a font reader draws them ([`super::round::decode`])
//! and checked, every test exact:
//!
//! 1. the same number of contours as the exact region, none collapsed: every written contour
//!    has an on-curve point and a non-zero area of the exact region's sign for it (outer
//!    contours in the font's direction, holes the other way);
//! 2. no piece that is a curve in the exact region collapsed: a curve whose written control
//!    points lie on one line must run along it once, from its start to its end (then it is a
//!    curve of the exact region within the bound of that straight piece — reported as
//!    straightened, tried only when no grid candidate within one unit keeps it curved — and
//!    never a point or a spike that doubles back);
//! 3. `lint` finds no `overlap`, `self_intersection`, `overlapping_segments`,
//!    `zero_length_segment` or `direction` (contours touching at points are allowed, as in
//!    the input);
//! 4. every written contour lies inside the same contour as its exact original (the nesting is
//!    the exact region's).
//!
//! Together with the distance bound of [`super::distance`] (every written piece within the
//! bound of its exact piece, parameter by parameter, so each written contour is homotopic to
//! its exact original through curves that stay within the bound), a point farther than the
//! bound from the exact boundary has the same winding number around the written contours as
//! around the exact ones: inside the written glyph exactly when inside the exact region.

use super::round::{Plan, Written, decode};
use super::{Flavour, GridPoint};
use crate::error::Result;
use crate::format::{Contour, Segment};
use crate::lint::{Glyph, Kind, LintOptions, lint};
use crate::num::point::{Point, Point2};
use crate::num::scalar::rat;
use crate::path::{ClosedPath, PathWinding};
use crate::shape::Orientation;
use crate::work::Budget;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

/// Why a written outline is not certified: in words, where (points in font units), and which
/// written contours are involved.
#[derive(Clone, Debug)]
pub(super) struct Failure {
    pub reason: String,
    pub near: Vec<[f64; 2]>,
    pub contours: Vec<usize>,
    /// The check that failed (1 to 4, in the order of the module documentation) and how many
    /// findings it made: an attempt that fails a later check, or the same check with fewer
    /// findings, is nearer to certified.
    pub score: (usize, usize),
}

impl Failure {
    /// The failure of check `stage` with these findings (reason, points, contour), if any.
    fn of(stage: usize, found: Vec<(String, Vec<[f64; 2]>, usize)>) -> Option<Failure> {
        let reason = found.first()?.0.clone();
        let mut contours: Vec<usize> = found.iter().map(|f| f.2).collect();
        contours.sort_unstable();
        contours.dedup();
        Some(Failure {
            reason,
            near: found.iter().flat_map(|f| f.1.iter().copied()).collect(),
            contours,
            score: (stage, found.len()),
        })
    }

    /// Whether this failure is nearer to certified than `other`.
    pub(super) fn better_than(&self, other: &Failure) -> bool {
        self.score.0 > other.score.0 || (self.score.0 == other.score.0 && self.score.1 < other.score.1)
    }
}

/// The kinds a certified outline must not have.
const FORBIDDEN: [Kind; 5] =
    [Kind::Overlap, Kind::SelfIntersection, Kind::OverlappingSegments, Kind::ZeroLengthSegment, Kind::Direction];

/// The written contours as exact font contours.
pub(super) fn contours_of(written: &[Written], flavour: Flavour) -> Vec<Contour> {
    written
        .iter()
        .map(|w| Contour {
            segments: decode(&w.contour.points, flavour)
                .into_iter()
                .map(|s| Segment::Bezier(s.into_iter().map(|p| Point::new(vec![p.x, p.y])).collect()))
                .collect(),
            closed: true,
        })
        .collect()
}

/// The signed area of a closed contour of Bézier segments (Green's theorem, exact).
fn area(c: &Contour) -> BigRational {
    let mut total = rat(0);
    for s in &c.segments {
        let Segment::Bezier(ps) = s else { continue };
        let cr = |i: usize, j: usize| &ps[i].coords[0] * &ps[j].coords[1] - &ps[j].coords[0] * &ps[i].coords[1];
        total += match ps.len() {
            2 => cr(0, 1) / rat(2),
            3 => (cr(0, 1) * rat(2) + cr(0, 2) + cr(1, 2) * rat(2)) / rat(6),
            4 => {
                (cr(0, 1) * rat(6)
                    + cr(0, 2) * rat(3)
                    + cr(0, 3)
                    + cr(1, 2) * rat(3)
                    + cr(1, 3) * rat(3)
                    + cr(2, 3) * rat(6))
                    / rat(20)
            }
            _ => rat(0),
        };
    }
    total
}

fn grid_f64(g: &GridPoint) -> [f64; 2] {
    [f64::from(g.x), f64::from(g.y)]
}

fn first_point(w: &Written) -> Vec<[f64; 2]> {
    w.contour.points.first().map(grid_f64).into_iter().collect()
}

/// Checks the written outline (see the module documentation): when certified, the curves
/// written straight (contour, piece); else why not.
///
/// # Errors
/// [`crate::Error::WorkLimit`] when the written glyph's arrangement or a winding number is
/// estimated above `budget`.
pub(super) fn certify(
    plan: &Plan,
    choice: &[usize],
    written: &[Written],
    flavour: Flavour,
    orientation: Orientation,
    budget: &Budget,
) -> Result<std::result::Result<Vec<(usize, usize)>, Failure>> {
    let contours = contours_of(written, flavour);
    // 1. every contour written, with the right sign of area
    let mut failures: Vec<(String, Vec<[f64; 2]>, usize)> = vec![];
    for (k, (c, w)) in contours.iter().zip(written).enumerate() {
        let expected = if plan.contours[k].depth.is_multiple_of(2) { orientation } else { orientation.reversed() };
        let a = area(c);
        let ok = match expected {
            Orientation::Ccw => a.is_positive(),
            Orientation::Cw => a.is_negative(),
        };
        if !ok {
            let what = if a.is_zero() { "collapses (zero area)" } else { "turns the wrong way" };
            let near = w.contour.points.iter().map(grid_f64).collect();
            failures.push((format!("rounding: contour {k} {what}"), near, k));
        }
    }
    if let Some(f) = Failure::of(1, failures) {
        return Ok(Err(f));
    }
    // 2. no curve collapsed: a curve written on a line must run along it once, from its start
    // to its end (then it is straightened, within the bound; see `straightened`)
    let mut failures = vec![];
    let mut straight = vec![];
    for (k, c) in plan.contours.iter().enumerate() {
        for (i, p) in c.pieces.iter().enumerate() {
            if !p.curved || plan.left_out(choice, c, i) {
                continue;
            }
            let poly = plan.polygon(choice, c, i);
            if !super::distance::collinear(&poly) {
                continue;
            }
            if runs_along(&poly) {
                straight.push((k, i));
                continue;
            }
            let start = plan.start_position(choice, c, i);
            let near = vec![[crate::num::scalar::ratio_to_f64(&start.x), crate::num::scalar::ratio_to_f64(&start.y)]];
            failures.push((format!("rounding: a curve of contour {k} collapses onto a line"), near, k));
        }
    }
    if let Some(f) = Failure::of(2, failures) {
        return Ok(Err(f));
    }
    // 3. lint
    let options = LintOptions { kinds: FORBIDDEN.to_vec(), budget: *budget, ..LintOptions::new(orientation) };
    let findings = lint(&Glyph::new(contours.clone()), &options)?;
    if let Some(f) = findings.first() {
        let near: Vec<[f64; 2]> =
            findings.iter().flat_map(|f| f.at.iter().map(|p| [p[0].to_f64(), p[1].to_f64()])).collect();
        let mut involved: Vec<usize> =
            findings.iter().flat_map(|f| f.contour.into_iter().chain(f.contours.into_iter().flatten())).collect();
        involved.sort_unstable();
        involved.dedup();
        let near =
            if near.is_empty() { involved.iter().flat_map(|&k| first_point(&written[k])).collect() } else { near };
        return Ok(Err(Failure {
            reason: format!("rounding: {} ({})", f.message, f.kind()),
            near,
            contours: involved,
            score: (3, findings.len()),
        }));
    }
    // 4. nesting
    let parents = parents(&contours, budget)?;
    let mut failures = vec![];
    for (k, (got, c)) in parents.iter().zip(&plan.contours).enumerate() {
        if *got != c.parent {
            let reason = format!("rounding: contour {k} lies in {got:?}, not in {:?} as exactly", c.parent);
            failures.push((reason, first_point(&written[k]), k));
        }
    }
    Ok(match Failure::of(4, failures) {
        Some(f) => Err(f),
        None => Ok(straight),
    })
}

/// Whether a control polygon on one line runs along it once, from its first point to its last:
/// every control point's position along the chord in `[0, 1]` and non-decreasing (then the
/// curve's coordinate along the line has a non-negative derivative: it traces the chord once).
fn runs_along(poly: &[Point2<BigRational>]) -> bool {
    let (a, b) = (&poly[0], &poly[poly.len() - 1]);
    let d = b.sub(a);
    let len2 = &d.x * &d.x + &d.y * &d.y;
    if len2.is_zero() {
        return false;
    }
    let mut last = rat(0);
    for p in &poly[1..poly.len() - 1] {
        let q = p.sub(a);
        let t = (&q.x * &d.x + &q.y * &d.y) / &len2;
        if t < last || t > rat(1) {
            return false;
        }
        last = t;
    }
    true
}

/// The estimated work of one [`certify`] of these written contours: that of `lint`'s
/// arrangement, which refuses a zero budget naming its estimate before any work starts.
pub(super) fn estimate(written: &[Written], flavour: Flavour, orientation: Orientation) -> f64 {
    let options =
        LintOptions { kinds: FORBIDDEN.to_vec(), budget: Budget::new(0.0, ""), ..LintOptions::new(orientation) };
    match lint(&Glyph::new(contours_of(written, flavour)), &options) {
        Err(crate::Error::WorkLimit { estimate, .. }) => estimate,
        _ => 0.0,
    }
}

/// The control points' box of a contour.
fn box_of(c: &Contour) -> Option<[BigRational; 4]> {
    let mut b: Option<[BigRational; 4]> = None;
    for s in &c.segments {
        let Segment::Bezier(ps) = s else { continue };
        for p in ps {
            let (x, y) = (&p.coords[0], &p.coords[1]);
            b = Some(match b {
                None => [x.clone(), y.clone(), x.clone(), y.clone()],
                Some([x0, y0, x1, y1]) => [
                    if *x < x0 { x.clone() } else { x0 },
                    if *y < y0 { y.clone() } else { y0 },
                    if *x > x1 { x.clone() } else { x1 },
                    if *y > y1 { y.clone() } else { y1 },
                ],
            });
        }
    }
    b
}

/// Points on a contour to test its nesting with: the segments' points at `t = 1/2`, `1/3`,
/// `2/3`, then their ends.
fn probes(c: &Contour) -> Vec<Point2<BigRational>> {
    let mut out = vec![];
    for t in [rat(1) / rat(2), rat(1) / rat(3), rat(2) / rat(3)] {
        for s in &c.segments {
            let Segment::Bezier(ps) = s else { continue };
            let Ok(curve) = crate::curve::BezierCurve::new(ps.clone()) else { continue };
            let p = curve.eval(&t);
            out.push(Point2::new(p.coords[0].clone(), p.coords[1].clone()));
        }
    }
    out
}

/// Per contour, the contour directly around it (written contours cross nowhere, so a point of
/// a contour off another tells whether it lies inside it).
fn parents(contours: &[Contour], budget: &Budget) -> Result<Vec<Option<usize>>> {
    let n = contours.len();
    let paths: Vec<Option<ClosedPath>> = contours
        .iter()
        .map(|c| {
            let segs = crate::format::svg_path::close_for_fill(c).ok()?;
            ClosedPath::from_polynomial(vec![segs]).ok()
        })
        .collect();
    let boxes: Vec<Option<[BigRational; 4]>> = contours.iter().map(box_of).collect();
    let mut encloses = vec![vec![false; n]; n];
    for j in 0..n {
        let tests = probes(&contours[j]);
        for i in 0..n {
            let (Some(path), Some(b)) = (&paths[i], &boxes[i]) else { continue };
            if i == j {
                continue;
            }
            for q in &tests {
                // a contour lies in its control points' box: outside it, it winds 0
                if q.x < b[0] || q.y < b[1] || q.x > b[2] || q.y > b[3] {
                    break;
                }
                match path.winding(q, budget)? {
                    PathWinding::Off(w) => {
                        encloses[i][j] = w.winding() != 0;
                        break;
                    }
                    PathWinding::OnBoundary { .. } => continue,
                }
            }
        }
    }
    let depth: Vec<usize> = (0..n).map(|j| (0..n).filter(|&i| encloses[i][j]).count()).collect();
    Ok((0..n).map(|j| (0..n).filter(|&i| encloses[i][j]).max_by_key(|&i| depth[i])).collect())
}
