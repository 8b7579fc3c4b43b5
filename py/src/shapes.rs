//! Shapes across the boundary, boolean operations, winding numbers and the `--against` oracle.
//!
//! A shape travels as a list of closed contours, each a list of segments `(points, weights)`:
//! `points` the control points `(x, y)` with the segment's start included (each segment starts
//! where the previous one ends, the last ends where the first starts), `weights` `None` for a
//! polynomial segment. A boolean result comes back in the same form, each output segment the
//! exact piece of an input segment: control points `Fraction`s when the piece's ends are
//! rational parameters, else the ends correctly rounded (`Fraction` when the end point is
//! rational) and the inner control points rounded from parameters within `2^-80`.

use crate::numbers::{fraction, rational, real};
use crate::{CasteljauError, budget, run};
use casteljau::num::Point2;
use casteljau::num::ratio_to_f64;
use casteljau::oracle::check_against as oracle_check;
use casteljau::path::{FillRule, PathWinding};
use casteljau::poly::RealAlgebraic;
use casteljau::shape::{BooleanOp, BooleanOptions, BooleanResult, Orientation, Shape, boolean as exact_boolean};
use casteljau::{BezierCurve, Point, RationalBezier};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};
use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};

type Q = BigRational;
type Contours = Vec<Vec<RationalBezier<Q>>>;

/// A shape from its exchange form (see the module documentation).
pub(crate) fn contours_of(ob: &Bound<'_, PyAny>) -> PyResult<Contours> {
    let mut out = vec![];
    for (ci, c) in ob.try_iter()?.enumerate() {
        let mut segs = vec![];
        for (si, s) in c?.try_iter()?.enumerate() {
            let s = s?;
            let (pts, weights): (Bound<'_, PyAny>, Bound<'_, PyAny>) = s.extract()?;
            let mut ps = vec![];
            for p in pts.try_iter()? {
                let (x, y): (Bound<'_, PyAny>, Bound<'_, PyAny>) = p?.extract()?;
                ps.push(Point::new(vec![rational(&x)?, rational(&y)?]));
            }
            let seg = if weights.is_none() {
                BezierCurve::new(ps).map(RationalBezier::from)
            } else {
                let ws = weights.try_iter()?.map(|w| rational(&w?)).collect::<PyResult<Vec<_>>>()?;
                RationalBezier::new(ps, ws)
            };
            let seg = seg.map_err(|e| CasteljauError::new_err(format!("contour {ci}, segment {si}: {e}")))?;
            segs.push(seg);
        }
        out.push(segs);
    }
    Ok(out)
}

fn shape_of(ob: &Bound<'_, PyAny>) -> PyResult<Shape> {
    Shape::from_contours(contours_of(ob)?).map_err(crate::error)
}

fn fill_of(s: &str) -> PyResult<FillRule> {
    match s {
        "nonzero" => Ok(FillRule::NonZero),
        "evenodd" => Ok(FillRule::EvenOdd),
        other => Err(CasteljauError::new_err(format!("the fill rule is \"nonzero\" or \"evenodd\", not {other:?}"))),
    }
}

fn orientation_of(s: &str) -> PyResult<Orientation> {
    s.parse().map_err(crate::error)
}

fn op_of(s: &str) -> PyResult<BooleanOp> {
    s.parse().map_err(crate::error)
}

/// A coordinate of an output point: exact when rational, else correctly rounded.
enum Coord {
    Exact(Q),
    Float(f64),
}

/// An output segment: control points and weights (`None`: polynomial).
struct OutSegment {
    points: Vec<[Coord; 2]>,
    weights: Option<Vec<Coord>>,
}

fn exact_point(p: &Point<Q>) -> [Coord; 2] {
    [Coord::Exact(p.coords[0].clone()), Coord::Exact(p.coords[1].clone())]
}

fn real_coord(x: RealAlgebraic) -> Coord {
    match x.to_rational() {
        Some(r) => Coord::Exact(r.clone()),
        None => Coord::Float(x.to_f64()),
    }
}

/// A rational within `2^-80` of an algebraic parameter (the parameter itself when rational).
fn near(t: &RealAlgebraic) -> Q {
    match t.to_rational() {
        Some(r) => r.clone(),
        None => {
            let mut t = t.clone();
            t.refine(&Q::new(BigInt::one(), BigInt::one() << 80));
            let (lo, hi) = t.interval();
            (lo + hi) / Q::from_integer(2.into())
        }
    }
}

/// The piece `from → to` of a segment (see the module documentation).
fn piece(seg: &RationalBezier<Q>, from: &RealAlgebraic, to: &RealAlgebraic) -> casteljau::Result<OutSegment> {
    let polynomial = seg.weights().iter().all(One::is_one);
    if let (Some(a), Some(b)) = (from.to_rational(), to.to_rational()) {
        // the whole segment, forwards or backwards (most pieces): its own numbers
        let whole = |x: &Q, y: &Q| x.is_zero() && y.is_one();
        if whole(a, b) || whole(b, a) {
            let mut points: Vec<[Coord; 2]> = seg
                .points()
                .into_iter()
                .map(|p| exact_point(&p.expect("a defined piece has no weight zero")))
                .collect();
            let mut weights = seg.weights();
            if whole(b, a) {
                points.reverse();
                weights.reverse();
            }
            let weights = if polynomial { None } else { Some(weights.into_iter().map(Coord::Exact).collect()) };
            return Ok(OutSegment { points, weights });
        }
        let sub = seg.subsegment(a, b)?;
        let points: Vec<[Coord; 2]> =
            sub.points().into_iter().map(|p| exact_point(&p.expect("a defined piece has no weight zero"))).collect();
        let weights = if polynomial { None } else { Some(sub.weights().into_iter().map(Coord::Exact).collect()) };
        return Ok(OutSegment { points, weights });
    }
    let sub = seg.subsegment(&near(from), &near(to))?;
    let mut points: Vec<[Coord; 2]> = sub
        .points()
        .into_iter()
        .map(|p| {
            let p = p.expect("a defined piece has no weight zero");
            [Coord::Float(ratio_to_f64(&p.coords[0])), Coord::Float(ratio_to_f64(&p.coords[1]))]
        })
        .collect();
    let n = points.len();
    let ends = |t: &RealAlgebraic| {
        let p = crate::curves::point_at(seg, t);
        let mut it = p.into_iter().map(real_coord);
        [it.next().expect("planar"), it.next().expect("planar")]
    };
    points[0] = ends(from);
    points[n - 1] = ends(to);
    let weights =
        if polynomial { None } else { Some(sub.weights().iter().map(|w| Coord::Float(ratio_to_f64(w))).collect()) };
    Ok(OutSegment { points, weights })
}

fn coord_py(py: Python<'_>, c: &Coord) -> PyResult<PyObject> {
    match c {
        Coord::Exact(r) => fraction(py, r),
        Coord::Float(f) => Ok(f.into_pyobject(py)?.into_any().unbind()),
    }
}

fn coord_q(c: &Coord) -> Q {
    match c {
        Coord::Exact(r) => r.clone(),
        Coord::Float(f) => Q::from_float(*f).expect("a finite coordinate"),
    }
}

/// `60 · ∫₀¹ (x y′ − y x′) dt` over a polynomial segment of degree ≤ 3, from its control points:
/// `P₀×P₁` (line), `⅓(2P₀×P₁ + P₀×P₂ + 2P₁×P₂)` (quadratic), `1/20(12P₀×P₁ + 6P₀×P₂ + 2P₀×P₃ +
/// 6P₁×P₂ + 6P₁×P₃ + 12P₂×P₃)` (cubic), scaled by 60 to stay free of fractions. `None` above
/// degree 3.
fn sixty_green(p: &[[Q; 2]]) -> Option<Q> {
    let cross = |i: usize, j: usize| &p[i][0] * &p[j][1] - &p[i][1] * &p[j][0];
    let k = |c: i64| Q::from_integer(c.into());
    Some(match p.len() {
        1 => Q::zero(),
        2 => cross(0, 1) * k(60),
        3 => (cross(0, 1) * k(2) + cross(0, 2) + cross(1, 2) * k(2)) * k(20),
        4 => {
            (cross(0, 1) * k(12)
                + cross(0, 2) * k(6)
                + cross(0, 3) * k(2)
                + cross(1, 2) * k(6)
                + cross(1, 3) * k(6)
                + cross(2, 3) * k(12))
                * k(3)
        }
        _ => return None,
    })
}

/// The signed area (counter-clockwise positive) enclosed by a closed contour of polynomial
/// segments of degree ≤ 3, exactly: `½ Σ ∫₀¹ (x y′ − y x′) dt`. `None` above degree 3.
fn contour_area(segments: &[Vec<[Q; 2]>]) -> Option<Q> {
    if let Some(a) = contour_area_halves(segments) {
        return Some(a);
    }
    let mut total = Q::zero();
    for s in segments {
        total += sixty_green(s)?;
    }
    Some(total / Q::from_integer(120.into()))
}

/// [`contour_area`] in `i128` when every coordinate is an integer or a half-integer that fits
/// `i64` (font outlines with TrueType's implied points): the same formula on the doubled
/// coordinates, every step checked. `None` otherwise, or on overflow.
fn contour_area_halves(segments: &[Vec<[Q; 2]>]) -> Option<Q> {
    use num_traits::ToPrimitive;
    let two = BigInt::from(2);
    let doubled = |q: &Q| -> Option<i128> {
        let n = q.numer().to_i64()? as i128;
        if q.denom().is_one() {
            n.checked_mul(2)
        } else if *q.denom() == two {
            Some(n)
        } else {
            None
        }
    };
    let mut total: i128 = 0;
    for s in segments {
        let p: Vec<[i128; 2]> = s.iter().map(|[x, y]| Some([doubled(x)?, doubled(y)?])).collect::<Option<_>>()?;
        let cross = |i: usize, j: usize| p[i][0].checked_mul(p[j][1])?.checked_sub(p[i][1].checked_mul(p[j][0])?);
        let terms: &[(usize, usize, i128)] = match p.len() {
            1 => &[],
            2 => &[(0, 1, 60)],
            3 => &[(0, 1, 40), (0, 2, 20), (1, 2, 40)],
            4 => &[(0, 1, 36), (0, 2, 18), (0, 3, 6), (1, 2, 18), (1, 3, 18), (2, 3, 36)],
            _ => return None,
        };
        for &(i, j, k) in terms {
            total = total.checked_add(cross(i, j)?.checked_mul(k)?)?;
        }
    }
    // the coordinates were doubled: areas scale by 4
    Some(Q::new(BigInt::from(total), BigInt::from(480)))
}

/// An output piece: a whole input segment (forwards or backwards), which Python takes from its
/// own input, or the control points of a part of one.
enum Item {
    Whole { input: usize, contour: usize, segment: usize, reversed: bool },
    Part(OutSegment),
}

/// Per contour its items, and per contour its area (see [`result_items`]).
type ResultItems = (Vec<Vec<Item>>, Vec<Option<Q>>);

/// The result's contours as items and, when there are several, their exact signed areas (for
/// skia-pathops' contour order; `None` for a contour with a rational piece).
fn result_items(inputs: &[&[Vec<RationalBezier<Q>>]], r: &BooleanResult) -> casteljau::Result<ResultItems> {
    let (zero, one) = (RealAlgebraic::from(Q::zero()), RealAlgebraic::from(Q::one()));
    let several = r.pieces.len() > 1;
    let mut out = vec![];
    let mut areas = vec![];
    for c in &r.pieces {
        let mut items = vec![];
        let mut polygon: Option<Vec<Vec<[Q; 2]>>> = several.then(Vec::new);
        for p in c {
            let seg = &inputs[p.input][p.contour][p.segment];
            let forward = p.from == zero && p.to == one;
            let item = if forward || (p.from == one && p.to == zero) {
                Item::Whole { input: p.input, contour: p.contour, segment: p.segment, reversed: !forward }
            } else {
                Item::Part(piece(seg, &p.from, &p.to)?)
            };
            if let Some(poly) = polygon.as_mut() {
                match &item {
                    Item::Whole { reversed, .. } if seg.weights().iter().all(One::is_one) => {
                        let h = seg.homogeneous().points();
                        let mut pts: Vec<[Q; 2]> =
                            h.iter().map(|h| [h.coords[0].clone(), h.coords[1].clone()]).collect();
                        if *reversed {
                            pts.reverse();
                        }
                        poly.push(pts);
                    }
                    Item::Part(o) if o.weights.is_none() => {
                        poly.push(o.points.iter().map(|[x, y]| [coord_q(x), coord_q(y)]).collect());
                    }
                    _ => polygon = None,
                }
            }
            items.push(item);
        }
        areas.push(polygon.and_then(|p| contour_area(&p)));
        out.push(items);
    }
    Ok((out, areas))
}

/// One output segment as `(points, weights)`.
fn segment_py<'py>(py: Python<'py>, s: &OutSegment) -> PyResult<Bound<'py, PyTuple>> {
    let pts = s
        .points
        .iter()
        .map(|[x, y]| PyTuple::new(py, [coord_py(py, x)?, coord_py(py, y)?]))
        .collect::<PyResult<Vec<_>>>()?;
    let w: PyObject = match &s.weights {
        None => py.None(),
        Some(ws) => {
            PyList::new(py, ws.iter().map(|w| coord_py(py, w)).collect::<PyResult<Vec<_>>>()?)?.into_any().unbind()
        }
    };
    PyTuple::new(py, [PyList::new(py, pts)?.into_any().unbind(), w])
}

fn segments_py(py: Python<'_>, contours: &[Vec<OutSegment>]) -> PyResult<Py<PyList>> {
    let out = PyList::empty(py);
    for c in contours {
        let segs = PyList::empty(py);
        for s in c {
            segs.append(segment_py(py, s)?)?;
        }
        out.append(segs)?;
    }
    Ok(out.unbind())
}

/// Items as Python: a whole piece as `(input, contour, segment, reversed)`, a part as
/// `(points, weights)`.
fn items_py(py: Python<'_>, contours: &[Vec<Item>]) -> PyResult<Py<PyList>> {
    let out = PyList::empty(py);
    for c in contours {
        let segs = PyList::empty(py);
        for item in c {
            match item {
                Item::Whole { input, contour, segment, reversed } => {
                    segs.append((*input, *contour, *segment, *reversed))?
                }
                Item::Part(s) => segs.append(segment_py(py, s)?)?,
            }
        }
        out.append(segs)?;
    }
    Ok(out.unbind())
}

/// `boolean(op, inputs, fill, orientation, max_work)`: the exact boolean operation `op`
/// (`union`, `intersection`, `difference`, `xor`, `simplify`) on shapes in exchange form.
/// Returns `(contours, area, parents, orientations, areas)`: the result's contours, each a list
/// of pieces — a whole input segment as `(input, contour, segment, reversed)`, a part of one in
/// exchange form `(points, weights)` —, its exact area (`Fraction`, or `None` when a piece is
/// rational or has irrational ends), each contour's directly enclosing contour (or `None`), each
/// contour's orientation (`"ccw"`/`"cw"`), and, when there are several contours, each one's exact
/// signed area as drawn (`None` otherwise, and for a contour with a rational piece).
#[pyfunction]
#[pyo3(signature = (op, inputs, fill="nonzero", orientation="ccw", max_work=None))]
#[allow(clippy::type_complexity)]
fn boolean(
    py: Python<'_>,
    op: &str,
    inputs: Vec<Bound<'_, PyAny>>,
    fill: &str,
    orientation: &str,
    max_work: Option<f64>,
) -> PyResult<(Py<PyList>, PyObject, Vec<Option<usize>>, Vec<&'static str>, Vec<PyObject>)> {
    let op = op_of(op)?;
    let options = BooleanOptions { fill: fill_of(fill)?, orientation: orientation_of(orientation)? };
    let inputs = inputs.iter().map(contours_of).collect::<PyResult<Vec<_>>>()?;
    let budget = budget(max_work)?;
    let (r, items, areas) = run(py, move || {
        let shapes = inputs.into_iter().map(Shape::from_contours).collect::<casteljau::Result<Vec<_>>>()?;
        let r = exact_boolean(op, &shapes, options, &budget)?;
        let contours: Vec<&[Vec<RationalBezier<Q>>]> = shapes.iter().map(|s| s.path().contours()).collect();
        let (items, areas) = result_items(&contours, &r)?;
        Ok((r, items, areas))
    })?;
    let areas = areas
        .iter()
        .map(|a| match a {
            Some(a) => fraction(py, a),
            None => Ok(py.None()),
        })
        .collect::<PyResult<Vec<_>>>()?;
    let area = match &r.area {
        Some(a) => fraction(py, a)?,
        None => py.None(),
    };
    let orient = r
        .orientation
        .iter()
        .map(|o| match o {
            Orientation::Ccw => "ccw",
            Orientation::Cw => "cw",
        })
        .collect();
    Ok((items_py(py, &items)?, area, r.parents.clone(), orient, areas))
}

/// Whether `r` (the simplified `shape`) is `shape`'s outline with some contours reversed: as
/// many contours, each made of the non-degenerate segments of one input contour (each used
/// once), whole `[0, 1]` pieces all forwards or all backwards, in the contour's cyclic order.
fn same_up_to_direction(r: &BooleanResult, shape: &Shape) -> bool {
    let (zero, one) = (RealAlgebraic::from(Q::from_integer(0.into())), RealAlgebraic::from(Q::one()));
    let contours = shape.path().contours();
    let degenerate = |s: &RationalBezier<Q>| {
        let ps = s.points();
        ps.iter().all(|p| *p == ps[0])
    };
    let live: Vec<Vec<usize>> =
        contours.iter().map(|c| (0..c.len()).filter(|&i| !degenerate(&c[i])).collect()).collect();
    let expected = live.iter().filter(|l| !l.is_empty()).count();
    if r.pieces.len() != expected {
        return false;
    }
    let mut used = vec![false; contours.len()];
    for c in &r.pieces {
        let Some(first) = c.first() else { return false };
        let k = first.contour;
        if first.input != 0 || used[k] {
            return false;
        }
        used[k] = true;
        let forward = first.from == zero;
        let whole = |p: &casteljau::shape::InputPiece| {
            p.input == 0
                && p.contour == k
                && if forward { p.from == zero && p.to == one } else { p.from == one && p.to == zero }
        };
        if !c.iter().all(whole) {
            return false;
        }
        let mut order: Vec<usize> = c.iter().map(|p| p.segment).collect();
        if !forward {
            order.reverse();
        }
        let want = &live[k];
        if order.len() != want.len() {
            return false;
        }
        let Some(at) = want.iter().position(|&s| s == order[0]) else { return false };
        if !(0..want.len()).all(|i| order[i] == want[(at + i) % want.len()]) {
            return false;
        }
    }
    true
}

/// `changes(shape, fill, orientation, max_work, ignore_direction=False)`: whether removing
/// overlaps (the exact `simplify` with outer contours `orientation`) changes the outline; with
/// `ignore_direction`, reversed contours do not count as a change.
#[pyfunction]
#[pyo3(signature = (shape, fill="nonzero", orientation="ccw", max_work=None, *, ignore_direction=false))]
fn changes(
    py: Python<'_>,
    shape: &Bound<'_, PyAny>,
    fill: &str,
    orientation: &str,
    max_work: Option<f64>,
    ignore_direction: bool,
) -> PyResult<bool> {
    let options = BooleanOptions { fill: fill_of(fill)?, orientation: orientation_of(orientation)? };
    let s = shape_of(shape)?;
    let budget = budget(max_work)?;
    run(py, move || {
        let r = exact_boolean(BooleanOp::Simplify, std::slice::from_ref(&s), options, &budget)?;
        Ok(if ignore_direction { !same_up_to_direction(&r, &s) } else { r.changes(&s) })
    })
}

/// `winding(shape, point, max_work)`: the exact winding number of the shape's contours around
/// a rational point (counter-clockwise positive), or `None` when the point is on a contour.
#[pyfunction]
#[pyo3(signature = (shape, point, max_work=None))]
fn winding(
    py: Python<'_>,
    shape: &Bound<'_, PyAny>,
    point: &Bound<'_, PyAny>,
    max_work: Option<f64>,
) -> PyResult<Option<i64>> {
    let s = shape_of(shape)?;
    let (x, y): (Bound<'_, PyAny>, Bound<'_, PyAny>) = point.extract()?;
    let q = Point2::new(rational(&x)?, rational(&y)?);
    let budget = budget(max_work)?;
    run(py, move || {
        Ok(match s.path().winding(&q, &budget)? {
            PathWinding::Off(w) => Some(w.winding()),
            PathWinding::OnBoundary { .. } => None,
        })
    })
}

/// `check_against(op, inputs, found, tol, fill, max_work)`: a float library's result `found`
/// of `op` on `inputs` decided against the exact one (the command line's `--against`): the
/// `Agreement` as a dict (`agree`, `contours`, `contours_found`, `depths`, `depths_found`,
/// `witness` with an exact `point`, `distance_bound`, `problems`).
#[pyfunction]
#[pyo3(signature = (op, inputs, found, tol, fill="nonzero", max_work=None))]
fn check_against(
    py: Python<'_>,
    op: &str,
    inputs: Vec<Bound<'_, PyAny>>,
    found: &Bound<'_, PyAny>,
    tol: &Bound<'_, PyAny>,
    fill: &str,
    max_work: Option<f64>,
) -> PyResult<PyObject> {
    let op = op_of(op)?;
    let options = BooleanOptions { fill: fill_of(fill)?, orientation: Orientation::Ccw };
    let shapes = inputs.iter().map(shape_of).collect::<PyResult<Vec<_>>>()?;
    let found = shape_of(found)?;
    let tol = rational(tol)?;
    let budget = budget(max_work)?;
    let a = run(py, move || {
        let exact = exact_boolean(op, &shapes, options, &budget)?;
        oracle_check(op, &shapes, options, &exact, &found, &tol, &budget)
    })?;
    let v = serde_json::to_value(&a).map_err(|e| CasteljauError::new_err(e.to_string()))?;
    crate::curves::json_py(py, &v)
}

/// `svg_path(d)`: SVG path data read exactly as the shape its fill covers (open subpaths
/// closed by a line), in exchange form.
#[pyfunction]
fn svg_path(py: Python<'_>, d: &str) -> PyResult<Py<PyList>> {
    let d = d.to_string();
    let path = run(py, move || casteljau::format::fill_path(&d, casteljau::num::NumberMode::Exact))?;
    let contours: Vec<Vec<OutSegment>> = path
        .contours()
        .iter()
        .map(|c| {
            c.iter()
                .map(|s| {
                    let points = s.points().into_iter().map(|p| exact_point(&p.expect("no weight zero"))).collect();
                    OutSegment { points, weights: None }
                })
                .collect()
        })
        .collect();
    segments_py(py, &contours)
}

/// `point_at(segment, t)`: the exact point of an exchange-form segment at an exact parameter.
#[pyfunction]
fn segment_point(py: Python<'_>, points: &Bound<'_, PyAny>, t: &Bound<'_, PyAny>) -> PyResult<(PyObject, PyObject)> {
    let ps = crate::curves::points_of(points, None)?;
    let c = RationalBezier::from(BezierCurve::new(ps).map_err(crate::error)?);
    let t = crate::numbers::real_of(t)?;
    let p = run(py, move || Ok(crate::curves::point_at(&c, &t)))?;
    let mut it = p.into_iter();
    Ok((real(py, it.next().expect("planar"))?, real(py, it.next().expect("planar"))?))
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(boolean, m)?)?;
    m.add_function(wrap_pyfunction!(changes, m)?)?;
    m.add_function(wrap_pyfunction!(winding, m)?)?;
    m.add_function(wrap_pyfunction!(check_against, m)?)?;
    m.add_function(wrap_pyfunction!(svg_path, m)?)?;
    m.add_function(wrap_pyfunction!(segment_point, m)?)?;
    Ok(())
}
