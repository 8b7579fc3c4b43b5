//! The exact region's contours put on the integer grid.
//!
//! Every piece of the exact region is a sub-segment of an input segment, so it is written with
//! the input segment's degree (a quadratic piece of a `glyf` glyph stays quadratic; in CFF a
//! quadratic is raised to the cubic it is, exactly) and control points rounded to the grid:
//!
//! * **meeting points** (the arrangement's vertices, exact algebraic points) are rounded
//!   coordinate-wise to the nearest integer, halves up, decided by exact comparisons; a vertex
//!   shared by several contours (a pinch, contours touching) is one point, rounded once, so
//!   what touches before rounding touches after;
//! * **inner control points** of a cut piece are the blossom values of the parameters
//!   ([`super::distance`]), enclosed in rational boxes and rounded to the nearest grid point;
//! * points already on the grid (the input's own points, on whole segments) stay exactly where
//!   they are;
//! * in TrueType, an on-curve point that is the exact midpoint of the control points around it
//!   (an implied point of the input) stays implied: the two control points are written next to
//!   each other and the point is their midpoint again. Where a cut leaves it no midpoint, it
//!   is written, rounded.
//!
//! Each placeable point has a short list of grid candidates (the nearest first, then its
//! neighbours whose displacement bound is at most one unit) from which the repairs choose.
//! A line piece whose two ends round to one grid point is left out (it is that point); the
//! contour it belongs to is the same closed curve without it.

use super::distance::{
    Enclosure, Interval, candidates, collinear, inner_controls, narrowed, nearest_algebraic, nearest_to,
};
use super::region::ExactContour;
use super::{Flavour, GridContour, GridPoint};
use crate::error::{Error, Result};
use crate::num::point::Point2;
use crate::num::scalar::rat;
use crate::shape::graph::Arrangement;
use num_rational::BigRational;
use std::collections::HashMap;

/// A point to place on the grid: where it is exactly and where it may go.
#[derive(Clone, Debug)]
pub(super) struct Placeable {
    /// A rational box around the exact point (the point itself when rational).
    pub enclosure: Enclosure,
    /// Grid points it may be written as, with the square of a bound on its displacement
    /// (the first is the nearest).
    pub candidates: Vec<([i64; 2], BigRational)>,
}

/// A piece to write: its start (a vertex, or an implied midpoint) and inner control points.
#[derive(Clone, Debug)]
pub(super) struct PlanPiece {
    /// The placeable of its start point.
    pub start: usize,
    /// The start is TrueType's implied midpoint of the control points around it.
    pub implied: bool,
    /// The placeables of its inner control points.
    pub controls: Vec<usize>,
    /// The exact piece is a curve off any line (its written copy must be one too).
    pub curved: bool,
}

/// A contour to write, with the nesting of its exact original.
#[derive(Clone, Debug)]
pub(super) struct PlanContour {
    pub pieces: Vec<PlanPiece>,
    pub parent: Option<usize>,
    pub depth: usize,
    /// Its exact original's index in the region.
    pub exact: usize,
}

/// The whole glyph to write.
#[derive(Clone, Debug)]
pub(super) struct Plan {
    pub points: Vec<Placeable>,
    pub contours: Vec<PlanContour>,
}

/// A written contour: its grid points and, per plan piece, where its start lies among them
/// (`None` for a piece left out or an implied start).
#[derive(Clone, Debug)]
pub(super) struct Written {
    pub contour: GridContour,
    /// Per grid point, the placeable it comes from.
    pub source: Vec<usize>,
}

/// The plan of the region's contours: vertices rounded once each, inner control points per piece.
pub(super) fn plan(arr: &Arrangement, region: &[ExactContour], flavour: Flavour) -> Result<Plan> {
    let mut points: Vec<Placeable> = vec![];
    let mut vertex_point: HashMap<usize, usize> = HashMap::new();
    let mut uses: HashMap<usize, usize> = HashMap::new();
    for c in region {
        for v in &c.at {
            *uses.entry(*v).or_default() += 1;
        }
    }
    let mut contours = vec![];
    for c in region {
        let m = c.pieces.len();
        // the control polygons of the pieces, as written (a quadratic raised in CFF)
        let mut polys: Vec<Vec<Point2<BigRational>>> = vec![];
        for p in &c.pieces {
            let seg = &arr.segs[p.seg];
            let hull = seg.hull.as_ref().ok_or_else(|| Error::InvalidArgument {
                message: "a rational segment cannot be written in a font".into(),
            })?;
            let hull = match (flavour, hull.len()) {
                (_, 2) => hull.clone(),
                (Flavour::Quadratic, 3) | (Flavour::Cubic, 4) => hull.clone(),
                (Flavour::Cubic, 3) => elevate(hull),
                (Flavour::Quadratic, n) => {
                    return Err(Error::InvalidArgument {
                        message: format!("a segment of degree {} cannot be written in a TrueType glyph", n - 1),
                    });
                }
                (Flavour::Cubic, n) => {
                    return Err(Error::InvalidArgument {
                        message: format!("a segment of degree {} cannot be written in a CFF glyph", n - 1),
                    });
                }
            };
            polys.push(hull);
        }
        let mut pieces: Vec<PlanPiece> = vec![];
        let mut exact_controls: Vec<Vec<Enclosure>> = vec![];
        for (i, p) in c.pieces.iter().enumerate() {
            let hull = &polys[i];
            let (a, b) = (narrowed(&p.from), narrowed(&p.to));
            let inner = inner_controls(hull, &a, &b);
            let v = c.at[i];
            let start = match vertex_point.get(&v) {
                Some(&k) => k,
                None => {
                    let (k, t) = &arr.vertex_at[v];
                    let [x, y] = arr.segs[*k].point_at_algebraic(t);
                    let enclosure = Enclosure { x: narrowed(&x), y: narrowed(&y) };
                    let first = [nearest_algebraic(&x), nearest_algebraic(&y)];
                    points.push(Placeable { candidates: candidates(&enclosure, first), enclosure });
                    vertex_point.insert(v, points.len() - 1);
                    points.len() - 1
                }
            };
            let mut controls = vec![];
            for e in &inner {
                let first = nearest_to(e);
                points.push(Placeable { candidates: candidates(e, first), enclosure: e.clone() });
                controls.push(points.len() - 1);
            }
            let curved = hull.len() > 2 && !collinear(hull);
            pieces.push(PlanPiece { start, implied: false, controls, curved });
            exact_controls.push(inner);
        }
        // implied TrueType midpoints: a vertex of this contour only, between two quadratic
        // pieces, exactly the midpoint of their exact control points
        if flavour == Flavour::Quadratic {
            for i in 0..m {
                let prev = (i + m - 1) % m;
                if m < 2 || uses[&c.at[i]] != 1 || pieces[i].controls.len() != 1 || pieces[prev].controls.len() != 1 {
                    continue;
                }
                let (Some(c0), Some(c1), Some(v)) = (
                    exact_controls[prev][0].rational(),
                    exact_controls[i][0].rational(),
                    points[pieces[i].start].enclosure.rational(),
                ) else {
                    continue;
                };
                let half = BigRational::new(1.into(), 2.into());
                if (&c0.x + &c1.x) * &half == v.x && (&c0.y + &c1.y) * &half == v.y {
                    pieces[i].implied = true;
                }
            }
            // a contour needs one written on-curve point to start at
            if pieces.iter().all(|p| p.implied)
                && let Some(p) = pieces.first_mut()
            {
                p.implied = false;
            }
        }
        contours.push(PlanContour { pieces, parent: c.parent, depth: c.depth, exact: contours.len() });
    }
    if points
        .iter()
        .flat_map(|p| &p.candidates)
        .any(|(g, _)| g[0].abs() > MOST_COORDINATE || g[1].abs() > MOST_COORDINATE)
    {
        return Err(Error::InvalidArgument {
            message: format!("a coordinate beyond ±{MOST_COORDINATE} cannot be written"),
        });
    }
    Ok(Plan { points, contours })
}

/// The quadratic's control points raised to the cubic's: `P0, (P0 + 2P1)/3, (2P1 + P2)/3, P2`.
fn elevate(q: &[Point2<BigRational>]) -> Vec<Point2<BigRational>> {
    let third = BigRational::new(1.into(), 3.into());
    let mix = |a: &Point2<BigRational>, b: &Point2<BigRational>| {
        Point2::new((&a.x + &b.x * rat(2)) * &third, (&a.y + &b.y * rat(2)) * &third)
    };
    vec![q[0].clone(), mix(&q[0], &q[1]), mix(&q[2], &q[1]), q[2].clone()]
}

/// Largest grid coordinate written (font coordinates are 16-bit; this keeps `i32` safe).
const MOST_COORDINATE: i64 = 1 << 30;

impl Plan {
    /// The plan without contour `k` (which encloses no other contour).
    pub(super) fn drop_contour(&mut self, k: usize) {
        self.contours.remove(k);
        for c in &mut self.contours {
            c.parent = c.parent.map(|p| if p > k { p - 1 } else { p });
        }
    }

    /// An enclosure of the exact signed area of contour `k`: Green's theorem on the exact
    /// control points of its pieces, in interval arithmetic over their enclosures (a point
    /// when every piece has rational ends).
    pub(super) fn area(&self, k: usize) -> Interval {
        let c = &self.contours[k];
        let m = c.pieces.len();
        let mut total = Interval::point(rat(0));
        for (i, p) in c.pieces.iter().enumerate() {
            let mut poly: Vec<&Enclosure> = vec![&self.points[p.start].enclosure];
            poly.extend(p.controls.iter().map(|&k| &self.points[k].enclosure));
            poly.push(&self.points[c.pieces[(i + 1) % m].start].enclosure);
            let cr = |i: usize, j: usize| poly[i].x.times(&poly[j].y).minus(&poly[j].x.times(&poly[i].y));
            let weighted = |terms: &[(usize, usize, i64)], den: i64| {
                let mut sum = Interval::point(rat(0));
                for &(i, j, w) in terms {
                    sum = sum.plus(&cr(i, j).scaled(&rat(w)));
                }
                sum.scaled(&(rat(1) / rat(den)))
            };
            let a = match poly.len() {
                2 => weighted(&[(0, 1, 1)], 2),
                3 => weighted(&[(0, 1, 2), (0, 2, 1), (1, 2, 2)], 6),
                _ => weighted(&[(0, 1, 6), (0, 2, 3), (0, 3, 1), (1, 2, 3), (1, 3, 3), (2, 3, 6)], 20),
            };
            total = total.plus(&a);
        }
        total
    }

    /// The grid point placeable `k` is written as under `choice`.
    pub(super) fn at(&self, choice: &[usize], k: usize) -> [i64; 2] {
        self.points[k].candidates[choice[k]].0
    }

    /// The square of the displacement bound of placeable `k` under `choice`.
    pub(super) fn displacement2(&self, choice: &[usize], k: usize) -> &BigRational {
        &self.points[k].candidates[choice[k]].1
    }

    /// The written position of a piece's start: its grid point, or the midpoint of the written
    /// control points around it when implied.
    pub(super) fn start_position(&self, choice: &[usize], c: &PlanContour, i: usize) -> Point2<BigRational> {
        let p = &c.pieces[i];
        if p.implied {
            let m = c.pieces.len();
            let (a, b) = (self.at(choice, c.pieces[(i + m - 1) % m].controls[0]), self.at(choice, p.controls[0]));
            let half = BigRational::new(1.into(), 2.into());
            return Point2::new(rat(a[0] + b[0]) * &half, rat(a[1] + b[1]) * &half);
        }
        let g = self.at(choice, p.start);
        Point2::new(rat(g[0]), rat(g[1]))
    }

    /// The written control polygon of piece `i` of contour `c` (exact: implied starts and ends
    /// are half-integers).
    pub(super) fn polygon(&self, choice: &[usize], c: &PlanContour, i: usize) -> Vec<Point2<BigRational>> {
        let m = c.pieces.len();
        let mut out = vec![self.start_position(choice, c, i)];
        for &k in &c.pieces[i].controls {
            let g = self.at(choice, k);
            out.push(Point2::new(rat(g[0]), rat(g[1])));
        }
        out.push(self.start_position(choice, c, (i + 1) % m));
        out
    }

    /// Whether piece `i` is left out: every point of its written polygon the same (a line or a
    /// curve whose ends and controls round onto one grid point), its ends written.
    pub(super) fn left_out(&self, choice: &[usize], c: &PlanContour, i: usize) -> bool {
        let m = c.pieces.len();
        if c.pieces[i].implied || c.pieces[(i + 1) % m].implied {
            return false;
        }
        let poly = self.polygon(choice, c, i);
        poly.iter().all(|p| *p == poly[0])
    }

    /// Moves the points of every curve whose rounding under `choice` lies on one line to the
    /// grid candidates (of its own start, control and end points) that keep it curved with the
    /// least displacement, when there are such.
    pub(super) fn keep_curves(&self, choice: &mut [usize]) {
        const MOST: usize = 256;
        for c in &self.contours {
            let m = c.pieces.len();
            for i in 0..m {
                let p = &c.pieces[i];
                if !p.curved || self.left_out(choice, c, i) || !collinear(&self.polygon(choice, c, i)) {
                    continue;
                }
                let next = &c.pieces[(i + 1) % m];
                let mut ks: Vec<usize> = p.controls.clone();
                if !p.implied {
                    ks.push(p.start);
                }
                if !next.implied {
                    ks.push(next.start);
                }
                ks.retain(|&k| self.points[k].candidates.len() > 1);
                let sizes: Vec<usize> = ks.iter().map(|&k| self.points[k].candidates.len()).collect();
                let total: usize = sizes.iter().product();
                if ks.is_empty() || total > MOST {
                    continue;
                }
                let original: Vec<usize> = ks.iter().map(|&k| choice[k]).collect();
                let mut best: Option<(BigRational, Vec<usize>)> = None;
                for code in 0..total {
                    let mut rest = code;
                    let pick: Vec<usize> = sizes
                        .iter()
                        .map(|&n| {
                            let v = rest % n;
                            rest /= n;
                            v
                        })
                        .collect();
                    for (&k, &v) in ks.iter().zip(&pick) {
                        choice[k] = v;
                    }
                    if collinear(&self.polygon(choice, c, i)) {
                        continue;
                    }
                    let worst =
                        ks.iter().map(|&k| self.displacement2(choice, k).clone()).max().unwrap_or_else(|| rat(0));
                    if best.as_ref().is_none_or(|(w, _)| worst < *w) {
                        best = Some((worst, pick));
                    }
                }
                let chosen = best.map_or(original, |(_, pick)| pick);
                for (&k, &v) in ks.iter().zip(&chosen) {
                    choice[k] = v;
                }
            }
        }
    }

    /// The contours written under `choice`.
    pub(super) fn write(&self, choice: &[usize]) -> Vec<Written> {
        let mut out = vec![];
        for c in &self.contours {
            let mut points = vec![];
            let mut source = vec![];
            for (i, p) in c.pieces.iter().enumerate() {
                if self.left_out(choice, c, i) {
                    continue;
                }
                if !p.implied {
                    let g = self.at(choice, p.start);
                    points.push(GridPoint { x: g[0] as i32, y: g[1] as i32, on_curve: true });
                    source.push(p.start);
                }
                for &k in &p.controls {
                    let g = self.at(choice, k);
                    points.push(GridPoint { x: g[0] as i32, y: g[1] as i32, on_curve: false });
                    source.push(k);
                }
            }
            // start on a written on-curve point (the first piece's start unless it was left out)
            if let Some(first_on) = points.iter().position(|p| p.on_curve) {
                points.rotate_left(first_on);
                source.rotate_left(first_on);
            }
            out.push(Written { contour: GridContour { points }, source });
        }
        out
    }

    /// The square of the bound on every written point's displacement from its exact point
    /// under `choice` (implied points are midpoints of bounded ones): see [`super::distance`].
    pub(super) fn bound2(&self, choice: &[usize]) -> BigRational {
        let mut worst = rat(0);
        for c in &self.contours {
            for p in &c.pieces {
                let ks = p.controls.iter().copied().chain((!p.implied).then_some(p.start));
                for k in ks {
                    let d = self.displacement2(choice, k);
                    if *d > worst {
                        worst = d.clone();
                    }
                }
            }
        }
        worst
    }
}

/// The exact segments of written grid contours, as a font reader draws them: TrueType's
/// implied on-curve midpoints between consecutive control points, CFF's cubics; each contour
/// closed back to its first point.
pub(super) fn decode(points: &[GridPoint], flavour: Flavour) -> Vec<Vec<Point2<BigRational>>> {
    let n = points.len();
    let p = |g: &GridPoint| Point2::new(rat(g.x as i64), rat(g.y as i64));
    let mut segs = vec![];
    let Some(start) = points.iter().position(|g| g.on_curve) else { return segs };
    let mut current = vec![p(&points[start])];
    for k in 1..=n {
        let g = &points[(start + k) % n];
        let q = p(g);
        if g.on_curve {
            current.push(q.clone());
            segs.push(std::mem::replace(&mut current, vec![q]));
            continue;
        }
        if flavour == Flavour::Quadratic && current.len() == 2 {
            // two control points in a row: the implied midpoint ends the quadratic
            let half = BigRational::new(1.into(), 2.into());
            let mid = Point2::new((&current[1].x + &q.x) * &half, (&current[1].y + &q.y) * &half);
            current.push(mid.clone());
            segs.push(std::mem::replace(&mut current, vec![mid]));
        }
        current.push(q);
    }
    segs
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decode_reads_implied_midpoints_and_closes() {
        let g = |x: i32, y: i32, on_curve: bool| GridPoint { x, y, on_curve };
        let pts = [g(0, 0, true), g(2, 2, false), g(4, 2, false), g(6, 0, true)];
        let segs = decode(&pts, Flavour::Quadratic);
        let s: Vec<String> =
            segs.iter().map(|s| s.iter().map(|p| format!("{} {}", p.x, p.y)).collect::<Vec<_>>().join(", ")).collect();
        assert_eq!(s, ["0 0, 2 2, 3 2", "3 2, 4 2, 6 0", "6 0, 0 0"]);
        let cubic = decode(&pts, Flavour::Cubic);
        assert_eq!(cubic.len(), 2);
        assert_eq!(cubic[0].len(), 4);
    }
}
