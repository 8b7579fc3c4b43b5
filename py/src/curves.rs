//! `Bezier` and `RationalBezier`: exact curves with the command line's operations, and their
//! intersections.

use crate::numbers::{fraction, rational, real};
use crate::{CasteljauError, budget, guard, run};
use casteljau::classify::{ClassifyReport, FloatApproximations, classify_rational};
use casteljau::curve::{DegreeReduction, Derivative, Elevation, Evaluation, PowerForm, Subdivision};
use casteljau::intersect::Domain;
use casteljau::num::QuadraticExt;
use casteljau::poly::{Poly, RealAlgebraic};
use casteljau::rational::{RationalElevation, RationalEvaluation, RationalSubdivision, bounding_box};
use casteljau::{BezierCurve, Point, RationalBezier as RB};
use num_rational::BigRational;
use num_traits::{One, Signed};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};

type Q = BigRational;

/// Control points from Python: a string of the command line's form (`"0 0, 1 2, 2 0"`, numbers
/// exact) or a sequence of points, each a sequence of numbers.
pub(crate) fn points_of(ob: &Bound<'_, PyAny>, dim: Option<usize>) -> PyResult<Vec<Point<Q>>> {
    if let Ok(s) = ob.downcast::<PyString>() {
        let text = s.to_cow()?;
        return casteljau::num::parse_points(&text, dim.unwrap_or(2), None).map_err(crate::error);
    }
    let mut out = vec![];
    for p in ob.try_iter()? {
        let p = p?;
        let coords = p.try_iter()?.map(|c| rational(&c?)).collect::<PyResult<Vec<Q>>>()?;
        out.push(Point::new(coords));
    }
    Ok(out)
}

/// A point as a tuple of `Fraction`s.
pub(crate) fn point_py<'py>(py: Python<'py>, p: &Point<Q>) -> PyResult<Bound<'py, PyTuple>> {
    let cs = p.coords.iter().map(|c| fraction(py, c)).collect::<PyResult<Vec<_>>>()?;
    PyTuple::new(py, cs)
}

fn points_py<'py>(py: Python<'py>, ps: &[Point<Q>]) -> PyResult<Bound<'py, PyList>> {
    let ps = ps.iter().map(|p| point_py(py, p)).collect::<PyResult<Vec<_>>>()?;
    PyList::new(py, ps)
}

/// `a + b√d` as a real algebraic number.
pub(crate) fn quadratic_real(q: &QuadraticExt<Q>) -> RealAlgebraic {
    if let Some(r) = q.to_base() {
        return r.into();
    }
    let (a, b, d) = (q.rational_part(), q.radical_coefficient(), q.radicand());
    // (t − a)² − b²d
    let p = Poly::new(vec![a * a - b * b * d, -(a + a), Q::one()]);
    let roots = RealAlgebraic::real_roots(&p);
    if b.is_positive() { roots[1].clone() } else { roots[0].clone() }
}

/// The exact point of a curve at an algebraic parameter: `X(t)/W(t)` per coordinate.
pub(crate) fn point_at(curve: &RB<Q>, t: &RealAlgebraic) -> Vec<RealAlgebraic> {
    let forms = curve.homogeneous().coordinate_polynomials();
    let dim = curve.dim();
    (0..dim).map(|k| t.map_rational(&forms[k], &forms[dim])).collect()
}

/// A JSON value as Python: objects as dicts, strings that are exact rationals as `Fraction`s.
pub(crate) fn json_py(py: Python<'_>, v: &serde_json::Value) -> PyResult<PyObject> {
    use serde_json::Value;
    Ok(match v {
        Value::Null => py.None(),
        Value::Bool(b) => b.into_pyobject(py)?.to_owned().into_any().unbind(),
        Value::Number(n) => match n.as_i64() {
            Some(i) => i.into_pyobject(py)?.into_any().unbind(),
            None => n.as_f64().unwrap_or(f64::NAN).into_pyobject(py)?.into_any().unbind(),
        },
        Value::String(s) => {
            let pos = casteljau::error::Position { line: None, column: 1, token: 1 };
            let numeric = s.chars().next().is_some_and(|c| c.is_ascii_digit() || c == '-');
            match casteljau::num::parse_number(s, pos) {
                Ok(r) if numeric => fraction(py, &r)?,
                _ => PyString::new(py, s).into_any().unbind(),
            }
        }
        Value::Array(a) => {
            PyList::new(py, a.iter().map(|x| json_py(py, x)).collect::<PyResult<Vec<_>>>()?)?.into_any().unbind()
        }
        Value::Object(o) => {
            let d = PyDict::new(py);
            for (k, x) in o {
                d.set_item(k, json_py(py, x)?)?;
            }
            d.into_any().unbind()
        }
    })
}

fn domain_of(s: &str) -> PyResult<Domain> {
    match s {
        "unit" => Ok(Domain::Unit),
        "all" => Ok(Domain::All),
        other => Err(CasteljauError::new_err(format!("the domain is \"unit\" or \"all\", not {other:?}"))),
    }
}

/// One isolated common point of two curves (or of a curve with itself).
///
/// `s` and `t` are the exact parameters (`Fraction` or `Algebraic`), `point` the exact common
/// point (a tuple of `Fraction`/`Algebraic`), `contact_order` 1 for a transversal crossing and
/// 2 or more for tangency; `kind` is `"transversal"` or `"tangent"`; `*_float` are the
/// correctly rounded values.
#[pyclass(module = "casteljau", frozen, get_all)]
pub(crate) struct Intersection {
    s: PyObject,
    t: PyObject,
    point: PyObject,
    contact_order: usize,
    kind: &'static str,
    s_float: f64,
    t_float: f64,
    point_float: (f64, f64),
}

#[pymethods]
impl Intersection {
    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        Ok(format!(
            "Intersection(s={}, t={}, point={}, contact_order={})",
            self.s.bind(py).repr()?,
            self.t.bind(py).repr()?,
            self.point.bind(py).repr()?,
            self.contact_order
        ))
    }
}

/// A shared arc: the parameter interval `s = (lo, hi)` on the first curve and the matching
/// `t = (t(lo), t(hi))` on the second (descending when it runs backwards).
#[pyclass(module = "casteljau", frozen, get_all)]
pub(crate) struct Overlap {
    s: (PyObject, PyObject),
    t: (PyObject, PyObject),
    s_float: (f64, f64),
    t_float: (f64, f64),
}

#[pymethods]
impl Overlap {
    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        Ok(format!(
            "Overlap(s=({}, {}), t=({}, {}))",
            self.s.0.bind(py).repr()?,
            self.s.1.bind(py).repr()?,
            self.t.0.bind(py).repr()?,
            self.t.1.bind(py).repr()?
        ))
    }
}

/// Everything two curves share: `points` (isolated intersections sorted by `s`, then `t`) and
/// `overlaps` (shared arcs). Iterating yields the points; `len()` counts them.
#[pyclass(module = "casteljau", frozen, get_all)]
pub(crate) struct Intersections {
    points: Py<PyList>,
    overlaps: Py<PyList>,
}

#[pymethods]
impl Intersections {
    fn __len__(&self, py: Python<'_>) -> usize {
        self.points.bind(py).len()
    }

    fn __iter__(&self, py: Python<'_>) -> PyResult<PyObject> {
        Ok(self.points.bind(py).try_iter()?.into_any().unbind())
    }

    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        Ok(format!(
            "Intersections(points={}, overlaps={})",
            self.points.bind(py).repr()?,
            self.overlaps.bind(py).repr()?
        ))
    }
}

/// The exact answers of `intersect`/`self_intersect` as Python objects (points computed exactly
/// on the first curve).
fn intersections_py(
    py: Python<'_>,
    found: casteljau::Intersections,
    exact_points: Vec<Vec<RealAlgebraic>>,
) -> PyResult<Intersections> {
    let mut points = vec![];
    for (x, p) in found.intersections.into_iter().zip(exact_points) {
        let coords = p.into_iter().map(|c| real(py, c)).collect::<PyResult<Vec<_>>>()?;
        let i = Intersection {
            s: real(py, x.s)?,
            t: real(py, x.t)?,
            point: PyTuple::new(py, coords)?.into_any().unbind(),
            contact_order: x.contact_order,
            kind: x.kind.as_str(),
            s_float: x.s_float,
            t_float: x.t_float,
            point_float: (x.point_float[0], x.point_float[1]),
        };
        points.push(Py::new(py, i)?);
    }
    let mut overlaps = vec![];
    for o in found.overlaps {
        let [s0, s1] = o.s;
        let [t0, t1] = o.t;
        let v = Overlap {
            s: (real(py, s0)?, real(py, s1)?),
            t: (real(py, t0)?, real(py, t1)?),
            s_float: (o.s_float[0], o.s_float[1]),
            t_float: (o.t_float[0], o.t_float[1]),
        };
        overlaps.push(Py::new(py, v)?);
    }
    Ok(Intersections { points: PyList::new(py, points)?.unbind(), overlaps: PyList::new(py, overlaps)?.unbind() })
}

/// Either curve class, as a rational curve.
fn as_rational(ob: &Bound<'_, PyAny>) -> PyResult<RB<Q>> {
    if let Ok(b) = ob.downcast::<Bezier>() {
        return Ok(RB::from(b.get().curve.clone()));
    }
    if let Ok(r) = ob.downcast::<RationalBezier>() {
        return Ok(r.get().curve.clone());
    }
    Err(PyTypeError::new_err(format!("expected a Bezier or RationalBezier, not {}", ob.get_type().name()?)))
}

fn intersect_impl(py: Python<'_>, a: RB<Q>, b: RB<Q>, domain: &str, max_work: Option<f64>) -> PyResult<Intersections> {
    let (domain, budget) = (domain_of(domain)?, budget(max_work)?);
    let (found, pts) = run(py, move || {
        let found = casteljau::intersect(&a, &b, domain, &budget)?;
        let pts = found.intersections.iter().map(|x| point_at(&a, &x.s)).collect();
        Ok((found, pts))
    })?;
    intersections_py(py, found, pts)
}

fn self_intersect_impl(py: Python<'_>, a: RB<Q>, domain: &str, max_work: Option<f64>) -> PyResult<Intersections> {
    let (domain, budget) = (domain_of(domain)?, budget(max_work)?);
    let (found, pts) = run(py, move || {
        let found = casteljau::self_intersect(&a, domain, &budget)?;
        let pts = found.intersections.iter().map(|x| point_at(&a, &x.s)).collect();
        Ok((found, pts))
    })?;
    intersections_py(py, found, pts)
}

/// `(axis, t, value)` per stationary point, and the box `(mins, maxs)`, exactly.
type Extrema = (Vec<(usize, PyObject, PyObject)>, Vec<PyObject>, Vec<PyObject>);

fn extrema_impl(py: Python<'_>, c: RB<Q>, max_work: Option<f64>) -> PyResult<Extrema> {
    let budget = budget(max_work)?;
    let b = run(py, move || bounding_box(&c, &budget))?;
    let st = b
        .stationary
        .into_iter()
        .map(|s| Ok((s.axis, real(py, s.t)?, real(py, s.value)?)))
        .collect::<PyResult<Vec<_>>>()?;
    let mins = b.min.into_iter().map(|x| real(py, x)).collect::<PyResult<Vec<_>>>()?;
    let maxs = b.max.into_iter().map(|x| real(py, x)).collect::<PyResult<Vec<_>>>()?;
    Ok((st, mins, maxs))
}

/// A Bézier curve with exact control points (any dimension).
///
/// `Bezier(points)` takes a sequence of points (each a sequence of numbers: int, Fraction,
/// float taken exactly, or str such as "1/3") or the command line's text `"0 0, 1 2, 2 0"`.
///
/// >>> from casteljau import Bezier
/// >>> c = Bezier([(0, 0), (1, 2), (2, 0)])
/// >>> c(Fraction(1, 3))
/// (Fraction(2, 3), Fraction(8, 9))
/// >>> c.bounds()
/// (Fraction(0, 1), Fraction(0, 1), Fraction(2, 1), Fraction(1, 1))
#[pyclass(module = "casteljau", frozen)]
pub(crate) struct Bezier {
    pub(crate) curve: BezierCurve<Q>,
}

fn new_bezier(py: Python<'_>, curve: BezierCurve<Q>) -> PyResult<Py<Bezier>> {
    Py::new(py, Bezier { curve })
}

#[pymethods]
impl Bezier {
    #[new]
    #[pyo3(signature = (points, *, dim=None))]
    fn new(points: &Bound<'_, PyAny>, dim: Option<usize>) -> PyResult<Self> {
        guard(|| Ok(Bezier { curve: BezierCurve::new(points_of(points, dim)?).map_err(crate::error)? }))
    }

    /// The control points, tuples of `Fraction`s.
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        points_py(py, self.curve.points())
    }

    /// The written degree (control points − 1).
    #[getter]
    fn degree(&self) -> usize {
        self.curve.degree()
    }

    /// Coordinates per point.
    #[getter]
    fn dim(&self) -> usize {
        self.curve.dim()
    }

    /// The degree of the curve itself (the written degree less any exact reduction).
    #[getter]
    fn real_degree(&self) -> usize {
        self.curve.real_degree()
    }

    /// The point at `t`: a tuple of `Fraction`s for a rational `t`, of exact reals
    /// (`Fraction`/`Algebraic`) for an `Algebraic` `t`.
    #[pyo3(signature = (t, *, max_work=None))]
    fn eval<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        max_work: Option<f64>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        if let Ok(a) = t.downcast::<crate::numbers::Algebraic>()
            && a.get().value.to_rational().is_none()
        {
            let (c, t) = (RB::from(self.curve.clone()), a.get().value.clone());
            let p = run(py, move || Ok(point_at(&c, &t)))?;
            return PyTuple::new(py, p.into_iter().map(|x| real(py, x)).collect::<PyResult<Vec<_>>>()?);
        }
        let t = rational(t)?;
        let (c, b) = (self.curve.clone(), budget(max_work)?);
        let e = run(py, move || Evaluation::new(&c, &[t], &b))?;
        point_py(py, &e.values[0].point)
    }

    fn __call__<'py>(&self, py: Python<'py>, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyTuple>> {
        self.eval(py, t, None)
    }

    /// The two halves at `t` (de Casteljau), each reparametrised to `[0, 1]`.
    #[pyo3(signature = (t, *, max_work=None))]
    fn subdivide(
        &self,
        py: Python<'_>,
        t: &Bound<'_, PyAny>,
        max_work: Option<f64>,
    ) -> PyResult<(Py<Bezier>, Py<Bezier>)> {
        let (c, t, b) = (self.curve.clone(), rational(t)?, budget(max_work)?);
        let s = run(py, move || Subdivision::new(&c, &t, &b))?;
        Ok((new_bezier(py, s.left)?, new_bezier(py, s.right)?))
    }

    /// The piece for `[a, b]`, reparametrised to `[0, 1]` (`a > b` runs backwards).
    fn subsegment(&self, py: Python<'_>, a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>) -> PyResult<Py<Bezier>> {
        let (c, a, b) = (self.curve.clone(), rational(a)?, rational(b)?);
        let s = run(py, move || Ok(c.subsegment(&a, &b)))?;
        new_bezier(py, s)
    }

    /// The same curve written with degree `degree + by`.
    #[pyo3(signature = (by=1, *, max_work=None))]
    fn elevate(&self, py: Python<'_>, by: usize, max_work: Option<f64>) -> PyResult<Py<Bezier>> {
        let (c, b) = (self.curve.clone(), budget(max_work)?);
        let e = run(py, move || Elevation::new(&c, by, &b))?;
        new_bezier(py, e.curve)
    }

    /// The same curve written with its real degree (exact degree reduction: the inverse of
    /// `elevate`).
    #[pyo3(signature = (*, max_work=None))]
    fn reduce(&self, py: Python<'_>, max_work: Option<f64>) -> PyResult<Py<Bezier>> {
        let (c, b) = (self.curve.clone(), budget(max_work)?);
        let r = run(py, move || DegreeReduction::new(&c, &b))?;
        new_bezier(py, r.curve)
    }

    /// The power form: coefficient points `a_0, …, a_n` of `Σ a_k t^k`.
    #[pyo3(signature = (*, max_work=None))]
    fn power_form<'py>(&self, py: Python<'py>, max_work: Option<f64>) -> PyResult<Bound<'py, PyList>> {
        let (c, b) = (self.curve.clone(), budget(max_work)?);
        let p = run(py, move || PowerForm::new(&c, &b))?;
        points_py(py, &p.coefficients)
    }

    /// The derivative curve of order `order` (hodograph), degree `n − order`.
    #[pyo3(signature = (order=1, *, max_work=None))]
    fn derivative(&self, py: Python<'_>, order: usize, max_work: Option<f64>) -> PyResult<Py<Bezier>> {
        let (c, b) = (self.curve.clone(), budget(max_work)?);
        let d = run(py, move || Derivative::new(&c, order, &b))?;
        new_bezier(py, d.curve)
    }

    /// The stationary points of each coordinate on `[0, 1]`: `(axis, t, value)`, exact.
    #[pyo3(signature = (*, max_work=None))]
    fn extrema(&self, py: Python<'_>, max_work: Option<f64>) -> PyResult<Vec<(usize, PyObject, PyObject)>> {
        Ok(extrema_impl(py, RB::from(self.curve.clone()), max_work)?.0)
    }

    /// The exact bounding box on `[0, 1]`: `(xmin, ymin, xmax, ymax)` for a planar curve
    /// (fontTools' order), `(*mins, *maxs)` in general; each a `Fraction` or `Algebraic`.
    #[pyo3(signature = (*, max_work=None))]
    fn bounds<'py>(&self, py: Python<'py>, max_work: Option<f64>) -> PyResult<Bound<'py, PyTuple>> {
        let (_, mins, maxs) = extrema_impl(py, RB::from(self.curve.clone()), max_work)?;
        PyTuple::new(py, mins.into_iter().chain(maxs).collect::<Vec<_>>())
    }

    /// The exact classification of a planar curve of degree ≤ 3 (the command line's
    /// `classify --json` report as a dict: exact rationals as `Fraction`, irrational parameters
    /// as `Algebraic`, and the rounded values under `"float"`).
    fn classify(&self, py: Python<'_>) -> PyResult<PyObject> {
        let c = self.curve.clone();
        let k = run(py, move || casteljau::classify(&c))?;
        let params = |ps: &[QuadraticExt<Q>]| -> PyResult<Vec<PyObject>> {
            ps.iter().map(|p| real(py, quadratic_real(p))).collect()
        };
        let (dpp, ip, cp) =
            (params(&k.double_point_parameters)?, params(&k.inflection_parameters)?, params(&k.cusp_parameters)?);
        let float = Some(FloatApproximations::of(&k));
        let report = ClassifyReport { classification: k, evidence: None, float };
        let v = serde_json::to_value(&report).map_err(|e| CasteljauError::new_err(e.to_string()))?;
        let d = json_py(py, &v)?;
        let dict = d.bind(py).downcast::<PyDict>()?;
        dict.set_item("double_point_parameters", dpp)?;
        dict.set_item("inflection_parameters", ip)?;
        dict.set_item("cusp_parameters", cp)?;
        Ok(d)
    }

    /// Every intersection with `other` (a `Bezier` or `RationalBezier`, planar, degree ≤ 10)
    /// with parameters in `[0, 1]²` (`domain="unit"`) or anywhere (`"all"`), and shared arcs.
    #[pyo3(signature = (other, *, domain="unit", max_work=None))]
    fn intersect(
        &self,
        py: Python<'_>,
        other: &Bound<'_, PyAny>,
        domain: &str,
        max_work: Option<f64>,
    ) -> PyResult<Intersections> {
        intersect_impl(py, RB::from(self.curve.clone()), as_rational(other)?, domain, max_work)
    }

    /// Every self-intersection `B(s) = B(t)`, `s < t`.
    #[pyo3(signature = (*, domain="unit", max_work=None))]
    fn self_intersections(&self, py: Python<'_>, domain: &str, max_work: Option<f64>) -> PyResult<Intersections> {
        self_intersect_impl(py, RB::from(self.curve.clone()), domain, max_work)
    }

    /// The same curve as a `RationalBezier` (every weight 1).
    fn to_rational(&self) -> RationalBezier {
        RationalBezier { curve: RB::from(self.curve.clone()) }
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.downcast::<Bezier>().is_ok_and(|o| o.get().curve == self.curve)
    }

    fn __hash__(&self) -> u64 {
        use std::hash::{Hash, Hasher};
        let mut h = std::collections::hash_map::DefaultHasher::new();
        self.curve.to_string().hash(&mut h);
        h.finish()
    }

    fn __repr__(&self) -> String {
        format!("Bezier('{}')", self.curve)
    }

    fn __len__(&self) -> usize {
        self.curve.points().len()
    }
}

/// A rational Bézier curve: exact control points and weights (no weight zero).
///
/// >>> from casteljau import RationalBezier
/// >>> quarter = RationalBezier([(1, 0), (1, 1), (0, 1)], [1, 1, 2])   # x² + y² = 1
/// >>> quarter(Fraction(1, 2))
/// (Fraction(3, 5), Fraction(4, 5))
#[pyclass(module = "casteljau", frozen)]
pub(crate) struct RationalBezier {
    pub(crate) curve: RB<Q>,
}

fn new_rational(py: Python<'_>, curve: RB<Q>) -> PyResult<Py<RationalBezier>> {
    Py::new(py, RationalBezier { curve })
}

#[pymethods]
impl RationalBezier {
    #[new]
    #[pyo3(signature = (points, weights, *, dim=None))]
    fn new(points: &Bound<'_, PyAny>, weights: &Bound<'_, PyAny>, dim: Option<usize>) -> PyResult<Self> {
        guard(|| {
            let ps = points_of(points, dim)?;
            let ws = weights.try_iter()?.map(|w| rational(&w?)).collect::<PyResult<Vec<_>>>()?;
            Ok(RationalBezier { curve: RB::new(ps, ws).map_err(crate::error)? })
        })
    }

    /// From homogeneous control points `(w·x, w·y[, …], w)`, a `Bezier` or points as
    /// `Bezier` takes them; a point whose weight is zero is a point at infinity.
    ///
    /// >>> from casteljau import RationalBezier
    /// >>> RationalBezier.from_homogeneous([(1, 0, 1), (1, 1, 1), (0, 2, 2)])
    /// RationalBezier('1 0, 1 1, 0 1', weights='1 1 2')
    #[staticmethod]
    fn from_homogeneous(points: &Bound<'_, PyAny>) -> PyResult<RationalBezier> {
        guard(|| {
            let h = match points.downcast::<Bezier>() {
                Ok(b) => b.get().curve.points().to_vec(),
                Err(_) => points_of(points, None)?,
            };
            Ok(RationalBezier { curve: RB::from_homogeneous(h).map_err(crate::error)? })
        })
    }

    /// The control points, tuples of `Fraction`s; `None` for a point at infinity (weight zero,
    /// as subdividing or elevating a curve whose weights change sign can give).
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let ps = self
            .curve
            .points()
            .into_iter()
            .map(|p| match p {
                Some(p) => Ok(point_py(py, &p)?.into_any()),
                None => Ok(py.None().into_bound(py)),
            })
            .collect::<PyResult<Vec<_>>>()?;
        PyList::new(py, ps)
    }

    /// The homogeneous control points `(w·x, w·y[, …], w)` as a `Bezier` one dimension up.
    #[getter]
    fn homogeneous(&self, py: Python<'_>) -> PyResult<Py<Bezier>> {
        new_bezier(py, self.curve.homogeneous().clone())
    }

    /// The weights, `Fraction`s.
    #[getter]
    fn weights(&self, py: Python<'_>) -> PyResult<Vec<PyObject>> {
        self.curve.weights().iter().map(|w| fraction(py, w)).collect()
    }

    /// The written degree.
    #[getter]
    fn degree(&self) -> usize {
        self.curve.degree()
    }

    /// Coordinates per point.
    #[getter]
    fn dim(&self) -> usize {
        self.curve.dim()
    }

    /// The point at `t` (`Fraction`s; exact reals for an `Algebraic` `t`).
    #[pyo3(signature = (t, *, max_work=None))]
    fn eval<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        max_work: Option<f64>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        if let Ok(a) = t.downcast::<crate::numbers::Algebraic>()
            && a.get().value.to_rational().is_none()
        {
            let (c, t) = (self.curve.clone(), a.get().value.clone());
            let p = run(py, move || Ok(point_at(&c, &t)))?;
            return PyTuple::new(py, p.into_iter().map(|x| real(py, x)).collect::<PyResult<Vec<_>>>()?);
        }
        let t = rational(t)?;
        let (c, b) = (self.curve.clone(), budget(max_work)?);
        let e = run(py, move || RationalEvaluation::new(&c, &[t], &b))?;
        point_py(py, &e.values[0].point)
    }

    fn __call__<'py>(&self, py: Python<'py>, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyTuple>> {
        self.eval(py, t, None)
    }

    /// The two halves at `t`.
    #[pyo3(signature = (t, *, max_work=None))]
    fn subdivide(
        &self,
        py: Python<'_>,
        t: &Bound<'_, PyAny>,
        max_work: Option<f64>,
    ) -> PyResult<(Py<RationalBezier>, Py<RationalBezier>)> {
        let (c, t, b) = (self.curve.clone(), rational(t)?, budget(max_work)?);
        let s = run(py, move || RationalSubdivision::new(&c, &t, &b))?;
        Ok((new_rational(py, s.left)?, new_rational(py, s.right)?))
    }

    /// The piece for `[a, b]`, reparametrised to `[0, 1]` (`a > b` runs backwards).
    fn subsegment(&self, py: Python<'_>, a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>) -> PyResult<Py<RationalBezier>> {
        let (c, a, b) = (self.curve.clone(), rational(a)?, rational(b)?);
        let s = run(py, move || c.subsegment(&a, &b))?;
        new_rational(py, s)
    }

    /// The same curve written with degree `degree + by`.
    #[pyo3(signature = (by=1, *, max_work=None))]
    fn elevate(&self, py: Python<'_>, by: usize, max_work: Option<f64>) -> PyResult<Py<RationalBezier>> {
        let (c, b) = (self.curve.clone(), budget(max_work)?);
        let e = run(py, move || RationalElevation::new(&c, by, &b))?;
        new_rational(py, e.curve)
    }

    /// The same curve written with the real degree of its homogeneous form (exact degree
    /// reduction, the inverse of `elevate`).
    ///
    /// >>> from casteljau import RationalBezier
    /// >>> RationalBezier([(1, 0), (1, 1), (0, 1)], [1, 1, 2]).elevate(2).reduce()
    /// RationalBezier('1 0, 1 1, 0 1', weights='1 1 2')
    #[pyo3(signature = (*, max_work=None))]
    fn reduce(&self, py: Python<'_>, max_work: Option<f64>) -> PyResult<Py<RationalBezier>> {
        let (c, b) = (self.curve.homogeneous().clone(), budget(max_work)?);
        let r = run(py, move || RB::from_homogeneous(DegreeReduction::new(&c, &b)?.curve.into_points()))?;
        new_rational(py, r)
    }

    /// The power form of the homogeneous curve: coefficient points `a_0, …, a_n` of
    /// `Σ a_k t^k`, each `(numerator coordinates…, denominator)`; the curve is the numerator
    /// over the denominator.
    ///
    /// >>> from casteljau import RationalBezier
    /// >>> RationalBezier([(1, 0), (1, 1), (0, 1)], [1, 1, 2]).power_form()   # ((1 - t²), 2t) / (1 + t²)
    /// [(Fraction(1, 1), Fraction(0, 1), Fraction(1, 1)), (Fraction(0, 1), Fraction(2, 1), Fraction(0, 1)), (Fraction(-1, 1), Fraction(0, 1), Fraction(1, 1))]
    #[pyo3(signature = (*, max_work=None))]
    fn power_form<'py>(&self, py: Python<'py>, max_work: Option<f64>) -> PyResult<Bound<'py, PyList>> {
        let (c, b) = (self.curve.homogeneous().clone(), budget(max_work)?);
        let p = run(py, move || PowerForm::new(&c, &b))?;
        points_py(py, &p.coefficients)
    }

    /// The derivative vectors at `t` up to order `k` (`[C(t), C'(t), …]`), exact.
    #[pyo3(signature = (t, k=1))]
    fn derivatives<'py>(&self, py: Python<'py>, t: &Bound<'py, PyAny>, k: usize) -> PyResult<Bound<'py, PyList>> {
        if k > 20 {
            return Err(CasteljauError::new_err(format!("derivative order {k} exceeds the limit 20")));
        }
        let (c, t) = (self.curve.clone(), rational(t)?);
        let d = run(py, move || c.derivatives_at(&t, k))?;
        points_py(py, &d)
    }

    /// The stationary points of each coordinate on `[0, 1]`: `(axis, t, value)`, exact.
    #[pyo3(signature = (*, max_work=None))]
    fn extrema(&self, py: Python<'_>, max_work: Option<f64>) -> PyResult<Vec<(usize, PyObject, PyObject)>> {
        Ok(extrema_impl(py, self.curve.clone(), max_work)?.0)
    }

    /// The exact bounding box on `[0, 1]` (as `Bezier.bounds`).
    #[pyo3(signature = (*, max_work=None))]
    fn bounds<'py>(&self, py: Python<'py>, max_work: Option<f64>) -> PyResult<Bound<'py, PyTuple>> {
        let (_, mins, maxs) = extrema_impl(py, self.curve.clone(), max_work)?;
        PyTuple::new(py, mins.into_iter().chain(maxs).collect::<Vec<_>>())
    }

    /// The exact classification of a planar rational cubic (the command line's
    /// `classify --weights --json` report as a dict).
    fn classify(&self, py: Python<'_>) -> PyResult<PyObject> {
        let c = self.curve.clone();
        let k = run(py, move || classify_rational(&c))?;
        let dpp =
            k.double_point_parameters.iter().map(|p| real(py, quadratic_real(p))).collect::<PyResult<Vec<_>>>()?;
        let v = serde_json::to_value(&k).map_err(|e| CasteljauError::new_err(e.to_string()))?;
        let d = json_py(py, &v)?;
        d.bind(py).downcast::<PyDict>()?.set_item("double_point_parameters", dpp)?;
        Ok(d)
    }

    /// Every intersection with `other` (as `Bezier.intersect`).
    #[pyo3(signature = (other, *, domain="unit", max_work=None))]
    fn intersect(
        &self,
        py: Python<'_>,
        other: &Bound<'_, PyAny>,
        domain: &str,
        max_work: Option<f64>,
    ) -> PyResult<Intersections> {
        intersect_impl(py, self.curve.clone(), as_rational(other)?, domain, max_work)
    }

    /// Every self-intersection.
    #[pyo3(signature = (*, domain="unit", max_work=None))]
    fn self_intersections(&self, py: Python<'_>, domain: &str, max_work: Option<f64>) -> PyResult<Intersections> {
        self_intersect_impl(py, self.curve.clone(), domain, max_work)
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.downcast::<RationalBezier>().is_ok_and(|o| o.get().curve == self.curve)
    }

    fn __repr__(&self) -> String {
        let w: Vec<String> = self.curve.weights().iter().map(|w| w.to_string()).collect();
        let text = |ps: &[Point<Q>]| {
            ps.iter().map(|p| p.coords.iter().map(|c| c.to_string()).collect::<Vec<_>>().join(" ")).collect::<Vec<_>>()
        };
        match self.curve.points().into_iter().collect::<Option<Vec<_>>>() {
            Some(ps) => format!("RationalBezier('{}', weights='{}')", text(&ps).join(", "), w.join(" ")),
            // a point at infinity (weight zero): the homogeneous points say it all
            None => {
                format!("RationalBezier.from_homogeneous('{}')", text(self.curve.homogeneous().points()).join(", "))
            }
        }
    }
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Bezier>()?;
    m.add_class::<RationalBezier>()?;
    m.add_class::<Intersection>()?;
    m.add_class::<Overlap>()?;
    m.add_class::<Intersections>()?;
    Ok(())
}
