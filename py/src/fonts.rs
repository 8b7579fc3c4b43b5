//! Fonts, outline QA, overlap removal, the claim catalogue and the float oracles.

use crate::curves::json_py;
use crate::{CasteljauError, budget, run};
use casteljau::format::{Contour, Font, Segment};
use casteljau::intersect::Domain;
use casteljau::lint::{Glyph, Kind, LintOptions};
use casteljau::overlaps::{Flavour, GlyphDecision, GlyphInput, WriteOptions, decide_glyph, write_font};
use casteljau::shape::Orientation;
use casteljau::{Budget, Point};
use num_rational::BigRational;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList};
use std::path::PathBuf;

fn to_json<T: serde::Serialize>(v: &T) -> PyResult<serde_json::Value> {
    serde_json::to_value(v).map_err(|e| CasteljauError::new_err(e.to_string()))
}

/// Font contours from the exchange form (polynomial segments only).
fn font_contours(ob: &Bound<'_, PyAny>) -> PyResult<Vec<Contour>> {
    let contours = crate::shapes::contours_of(ob)?;
    contours
        .into_iter()
        .map(|c| {
            let segments = c
                .into_iter()
                .map(|s| {
                    let ps: Vec<Point<BigRational>> =
                        s.points().into_iter().map(|p| p.expect("no weight zero")).collect();
                    Segment::Bezier(ps)
                })
                .collect();
            Ok(Contour { segments, closed: true })
        })
        .collect()
}

fn kinds_of(kinds: Option<Vec<String>>) -> PyResult<Vec<Kind>> {
    match kinds {
        None => Ok(Kind::ALL.to_vec()),
        Some(ks) => ks.iter().map(|k| k.parse().map_err(crate::error)).collect(),
    }
}

fn orientation_of(s: &str) -> PyResult<Orientation> {
    s.parse().map_err(crate::error)
}

fn lint_options(
    kinds: Option<Vec<String>>,
    outer: Orientation,
    budget: Budget,
    kink: Option<f64>,
) -> PyResult<LintOptions> {
    let mut o = LintOptions::new(outer);
    o.kinds = kinds_of(kinds)?;
    o.budget = budget;
    if let Some(k) = kink {
        o = o.with_kink_angle(k).map_err(crate::error)?;
    }
    Ok(o)
}

/// `lint_font(data, glyphs=None, kinds=None, max_work=None, face=0, kink_angle=None)`: every
/// finding of every glyph (or of the named glyphs) of a font file, as the command line's
/// `lint --json`: a list of `(glyph_name, glyph_id, findings, error)`, findings as dicts.
#[pyfunction]
#[pyo3(signature = (data, glyphs=None, kinds=None, max_work=None, face=0, kink_angle=None))]
#[allow(clippy::type_complexity)]
fn lint_font(
    py: Python<'_>,
    data: Vec<u8>,
    glyphs: Option<Vec<String>>,
    kinds: Option<Vec<String>>,
    max_work: Option<f64>,
    face: u32,
    kink_angle: Option<f64>,
) -> PyResult<Vec<(String, u32, PyObject, Option<String>)>> {
    let budget = budget(max_work)?;
    let (kinds, kink) = (kinds, kink_angle);
    // validate the options before the work
    lint_options(kinds.clone(), Orientation::Ccw, budget, kink)?;
    let rows = run(py, move || {
        let f = Font::open(&data, face)?;
        let options = {
            let mut o = LintOptions::new(f.outer_orientation());
            o.kinds = match &kinds {
                None => Kind::ALL.to_vec(),
                Some(ks) => ks.iter().map(|k| k.parse()).collect::<casteljau::Result<Vec<_>>>()?,
            };
            o.budget = budget;
            if let Some(k) = kink {
                o = o.with_kink_angle(k)?;
            }
            o
        };
        let gids: Vec<u32> = match &glyphs {
            None => (0..f.num_glyphs()).collect(),
            Some(names) => f.glyphs_named(names)?,
        };
        let rat4 = |b: [i16; 4]| b.map(|x| BigRational::from_integer(x.into()));
        let font_box = f.head_box().map(rat4);
        let mut rows = vec![];
        for gid in gids {
            let name = f.glyph_name(gid).unwrap_or_else(|| format!("gid{gid}"));
            let row = match f.outline_numbered(gid) {
                Ok(outline) => {
                    let empty = outline.contours.iter().all(|c| c.segments.is_empty());
                    let glyph = Glyph {
                        contours: outline.contours,
                        numbers: outline.numbers,
                        lone_points: outline.lone_points,
                        stored_box: if empty { None } else { f.stored_glyph_box(gid).map(rat4) },
                        font_box: font_box.clone(),
                    };
                    match casteljau::lint::lint(&glyph, &options) {
                        Ok(findings) => {
                            let json = serde_json::to_value(&findings)
                                .map_err(|e| casteljau::Error::InvalidArgument { message: e.to_string() })?;
                            (name, gid, json, None)
                        }
                        Err(e) => (name, gid, serde_json::Value::Array(vec![]), Some(e.to_string())),
                    }
                }
                Err(e) => (name, gid, serde_json::Value::Array(vec![]), Some(e.to_string())),
            };
            rows.push(row);
        }
        Ok(rows)
    })?;
    rows.into_iter().map(|(n, g, j, e)| Ok((n, g, json_py(py, &j)?, e))).collect()
}

/// `lint_contours(contours, orientation="ccw", kinds=None, max_work=None, kink_angle=None)`: the
/// findings of one outline in exchange form (polynomial segments of degree ≤ 3).
#[pyfunction]
#[pyo3(signature = (contours, orientation="ccw", kinds=None, max_work=None, kink_angle=None))]
fn lint_contours(
    py: Python<'_>,
    contours: &Bound<'_, PyAny>,
    orientation: &str,
    kinds: Option<Vec<String>>,
    max_work: Option<f64>,
    kink_angle: Option<f64>,
) -> PyResult<PyObject> {
    let options = lint_options(kinds, orientation_of(orientation)?, budget(max_work)?, kink_angle)?;
    let glyph = Glyph::new(font_contours(contours)?);
    let findings = run(py, move || casteljau::lint::lint(&glyph, &options))?;
    json_py(py, &to_json(&findings)?)
}

fn flavour_of(s: &str) -> PyResult<Flavour> {
    match s {
        "quadratic" => Ok(Flavour::Quadratic),
        "cubic" => Ok(Flavour::Cubic),
        other => Err(CasteljauError::new_err(format!("the flavour is \"quadratic\" or \"cubic\", not {other:?}"))),
    }
}

/// A decision as Python: `("unchanged", None, None)`, `("rewritten", contours, report)` with
/// contours lists of `(x, y, on_curve)`, or `("uncertified", reason, None)`.
fn decision_py(py: Python<'_>, d: GlyphDecision) -> PyResult<(String, PyObject, PyObject)> {
    Ok(match d {
        GlyphDecision::Unchanged => ("unchanged".into(), py.None(), py.None()),
        GlyphDecision::Rewritten { contours, report } => {
            let cs = PyList::empty(py);
            for c in contours {
                let pts: Vec<(i32, i32, bool)> = c.points.iter().map(|p| (p.x, p.y, p.on_curve)).collect();
                cs.append(pts)?;
            }
            ("rewritten".into(), cs.into_any().unbind(), json_py(py, &to_json(&report)?)?)
        }
        GlyphDecision::Uncertified { reason } => {
            ("uncertified".into(), reason.into_pyobject(py)?.into_any().unbind(), py.None())
        }
    })
}

/// `decide_glyph(components, flavour, orientation, name=None, glyph_id=0, max_work=None)`: the
/// overlap-removal decision for one glyph (the `remove-overlaps` command's library route):
/// `components` one exchange-form outline per component, already in glyph space.
#[pyfunction]
#[pyo3(signature = (components, flavour, orientation, name=None, glyph_id=0, max_work=None))]
fn decide(
    py: Python<'_>,
    components: Vec<Bound<'_, PyAny>>,
    flavour: &str,
    orientation: &str,
    name: Option<String>,
    glyph_id: u32,
    max_work: Option<f64>,
) -> PyResult<(String, PyObject, PyObject)> {
    let input = GlyphInput {
        glyph_id,
        name,
        components: components.iter().map(font_contours).collect::<PyResult<Vec<_>>>()?,
        flavour: flavour_of(flavour)?,
        orientation: orientation_of(orientation)?,
    };
    let budget = budget(max_work)?;
    let d = run(py, move || decide_glyph(&input, &budget))?;
    decision_py(py, d)
}

/// `remove_overlaps(data, glyph_ids=None, keep_hinting=False, max_work=None)`: the font file
/// rewritten with each glyph's certified overlap removal (`casteljau::overlaps::write_font`
/// with `decide_glyph`, `max_work` per glyph). Returns `(data, glyphs)`, `glyphs` a list of
/// `(glyph_id, status, detail, report)` with status `unchanged`, `rewritten`, `uncertified`
/// or `error`.
#[pyfunction]
#[pyo3(signature = (data, glyph_ids=None, keep_hinting=false, max_work=None))]
#[allow(clippy::type_complexity)]
fn remove_overlaps<'py>(
    py: Python<'py>,
    data: Vec<u8>,
    glyph_ids: Option<Vec<u32>>,
    keep_hinting: bool,
    max_work: Option<f64>,
) -> PyResult<(Bound<'py, PyBytes>, Vec<(u32, String, PyObject, PyObject)>)> {
    let budget = budget(max_work)?;
    let options = WriteOptions { keep_hinting, glyphs: glyph_ids };
    let out = run(py, move || write_font(&data, &options, &|g| decide_glyph(g, &budget)))?;
    let mut glyphs = vec![];
    for (gid, d) in out.glyphs {
        glyphs.push(match d {
            Ok(d) => {
                let (status, detail, report) = decision_py(py, d)?;
                (gid, status, detail, report)
            }
            Err(e) => (gid, "error".into(), e.to_string().into_pyobject(py)?.into_any().unbind(), py.None()),
        });
    }
    Ok((PyBytes::new(py, &out.data), glyphs))
}

/// `prove(paths=None, text=None, name="<text>", max_work=None)`: the verdicts of the claims in
/// claim files (files or directories of `*.toml`) or in claim-file text, as dicts (the command
/// line's `prove --json` objects).
#[pyfunction]
#[pyo3(signature = (paths=None, text=None, name="<text>", max_work=None))]
fn prove(
    py: Python<'_>,
    paths: Option<Vec<PathBuf>>,
    text: Option<String>,
    name: &str,
    max_work: Option<f64>,
) -> PyResult<PyObject> {
    let budget = budget(max_work)?;
    let name = name.to_string();
    let results = run(py, move || {
        let claims = match (paths, text) {
            (Some(p), None) => casteljau::catalogue::load(&p)?,
            (None, Some(t)) => casteljau::catalogue::parse_claims(&name, &t)?,
            _ => {
                return Err(casteljau::Error::InvalidArgument { message: "give claim files or claim text".into() });
            }
        };
        claims.iter().map(|c| casteljau::catalogue::check(c, &budget)).collect::<casteljau::Result<Vec<_>>>()
    })?;
    json_py(py, &to_json(&results)?)
}

/// `check_intersections(a, b, found, tol, domain="unit")`: a float library's intersection
/// parameters `found` (pairs `(s, t)`) of two binary64 curves checked against the exact answer:
/// a list of disagreements (`kind` missed/spurious/duplicate, exact `s`, `t`, the library's
/// `float` pair, `exact_float`).
#[pyfunction]
#[pyo3(signature = (a, b, found, tol, domain="unit"))]
fn check_intersections(
    py: Python<'_>,
    a: Vec<[f64; 2]>,
    b: Vec<[f64; 2]>,
    found: Vec<(f64, f64)>,
    tol: f64,
    domain: &str,
) -> PyResult<PyObject> {
    let domain = match domain {
        "unit" => Domain::Unit,
        "all" => Domain::All,
        other => return Err(CasteljauError::new_err(format!("the domain is \"unit\" or \"all\", not {other:?}"))),
    };
    let d = run(py, move || casteljau::oracle::check_intersections(&a, &b, &found, tol, domain))?;
    json_py(py, &to_json(&d)?)
}

/// `glyph_outline(data, glyph, face=0)`: one glyph of a font file read exactly, in exchange
/// form (the font's own reading: TrueType implied points exact, components decomposed).
#[pyfunction]
#[pyo3(signature = (data, glyph, face=0))]
fn font_glyph(py: Python<'_>, data: Vec<u8>, glyph: &Bound<'_, PyAny>, face: u32) -> PyResult<Py<PyList>> {
    let by_name: Option<String> = glyph.extract().ok();
    let by_id: Option<u32> = if by_name.is_none() { Some(glyph.extract()?) } else { None };
    let contours = run(py, move || {
        let f = Font::open(&data, face)?;
        let gid = match (by_name, by_id) {
            (Some(n), _) => f.glyphs_named(&[n])?[0],
            (None, Some(g)) => g,
            _ => unreachable!("a name or an id"),
        };
        f.outline(gid)
    })?;
    let out = PyList::empty(py);
    for c in contours {
        let segs = PyList::empty(py);
        let mut closing: Option<Point<BigRational>> = None;
        let mut last: Option<Point<BigRational>> = None;
        for s in &c.segments {
            if let Segment::Bezier(ps) = s {
                closing.get_or_insert_with(|| ps[0].clone());
                last = ps.last().cloned();
                let pts = ps.iter().map(|p| crate::curves::point_py(py, p)).collect::<PyResult<Vec<_>>>()?;
                segs.append((pts, py.None()))?;
            }
        }
        if let (Some(a), Some(b)) = (closing, last)
            && a != b
        {
            segs.append((vec![crate::curves::point_py(py, &b)?, crate::curves::point_py(py, &a)?], py.None()))?;
        }
        if !segs.is_empty() {
            out.append(segs)?;
        }
    }
    Ok(out.unbind())
}

/// `lint_kinds()`: every lint kind with its severity and whether it fails a run by default.
#[pyfunction]
fn lint_kinds(py: Python<'_>) -> PyResult<Vec<PyObject>> {
    Kind::ALL
        .iter()
        .map(|k| {
            let d = PyDict::new(py);
            d.set_item("kind", k.as_str())?;
            d.set_item("severity", k.severity().as_str())?;
            d.set_item("denied_by_default", k.denied_by_default())?;
            Ok(d.into_any().unbind())
        })
        .collect()
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(lint_font, m)?)?;
    m.add_function(wrap_pyfunction!(lint_contours, m)?)?;
    m.add_function(wrap_pyfunction!(lint_kinds, m)?)?;
    m.add_function(wrap_pyfunction!(decide, m)?)?;
    m.add_function(wrap_pyfunction!(remove_overlaps, m)?)?;
    m.add_function(wrap_pyfunction!(prove, m)?)?;
    m.add_function(wrap_pyfunction!(check_intersections, m)?)?;
    m.add_function(wrap_pyfunction!(font_glyph, m)?)?;
    Ok(())
}
