//! The text of each command's answer, rendered from the library's typed result; the JSON is
//! that result's `Serialize` (the types are the schema), so text and JSON cannot drift apart.

use crate::render::{Answer, Json};
use casteljau::classify::Parameter;
use casteljau::classify::RationalClassification;
use casteljau::classify::{Classified, ClassifyReport};
use casteljau::curve::BezierCurve;
use casteljau::curve::{
    DegreeReduction, Derivative, Evaluation, PointAt, PowerForm, RepeatedSubdivision, Scheme, Subdivision,
};
use casteljau::num::Radical;
use casteljau::num::Scalar;
use casteljau::rational::BoundingBox;
use casteljau::rational::ImplicitOutcome;
use casteljau::rational::RationalBezier;
use casteljau::rational::{Conic, Definedness, RationalEvaluation, RationalSubdivision};
use casteljau::surface::PatchValue;
use casteljau::surface::RationalPatch;
use casteljau::surface::{PatchContour, PatchSplit};
use num_rational::BigRational;
use serde_json::Value;

/// `name(t) = point`, one line per parameter.
fn values_text(name: &str, values: &[PointAt]) -> String {
    values.iter().map(|v| format!("{name}({}) = {}", v.t, v.point)).collect::<Vec<_>>().join("\n")
}

/// The name of coordinate `k`: `x`, `y`, `z`, then `x3`, `x4`, ….
fn axis(k: usize) -> String {
    ["x", "y", "z"].get(k).map(|s| s.to_string()).unwrap_or(format!("x{k}"))
}

/// `eval` of a polynomial curve.
pub(crate) fn eval(e: &Evaluation) -> Answer {
    Answer::typed(values_text("b", &e.values), e)
}

/// `eval` of a rational curve.
pub(crate) fn eval_rational(e: &RationalEvaluation) -> Answer {
    Answer::typed(values_text("x", &e.values), e)
}

/// `subdivide`: the two halves.
pub(crate) fn subdivide(s: &Subdivision) -> Answer {
    Answer::typed(format!("left:  {}\nright: {}", s.left, s.right), s)
}

/// `subdivide --depth`: every piece with its interval.
pub(crate) fn subdivide_repeatedly(s: &RepeatedSubdivision) -> Answer {
    let text = s
        .pieces
        .iter()
        .map(|p| format!("[{}, {}]: {}", p.interval.0, p.interval.1, p.points))
        .collect::<Vec<_>>()
        .join("\n");
    Answer::typed(text, s)
}

/// `subdivide` of a rational curve.
pub(crate) fn subdivide_rational(s: &RationalSubdivision) -> Answer {
    Answer::typed(format!("left:  {}\nright: {}", weighted_text(&s.left), weighted_text(&s.right)), s)
}

/// A polynomial curve (`elevate`).
pub(crate) fn curve(c: &BezierCurve<BigRational>) -> Answer {
    Answer::typed(c.to_string(), c)
}

/// A rational curve (`elevate --weights`).
pub(crate) fn rational(c: &RationalBezier<BigRational>) -> Answer {
    Answer::typed(weighted_text(c), c)
}

/// `derivative`.
pub(crate) fn derivative(d: &Derivative) -> Answer {
    Answer::typed(d.curve.to_string(), d)
}

/// `reduce`.
pub(crate) fn reduce(r: &DegreeReduction) -> Answer {
    Answer::typed(format!("degree {} (written as {}): {}", r.real_degree, r.written_degree, r.curve), r)
}

/// `triangle`: one line per row of the scheme.
pub(crate) fn triangle(s: &Scheme) -> Answer {
    let text = s
        .triangle
        .rows
        .iter()
        .enumerate()
        .map(|(r, row)| {
            let pts: Vec<String> = row.iter().map(|p| p.to_string()).collect();
            format!("r={r}: {}", pts.join(" "))
        })
        .collect::<Vec<_>>()
        .join("\n");
    Answer::typed(text, s)
}

/// `power`: one polynomial per coordinate.
pub(crate) fn power(p: &PowerForm) -> Answer {
    let dim = p.coefficients.first().map_or(0, |c| c.dim());
    let lines: Vec<String> = (0..dim).map(|k| format!("{}(t) = {}", axis(k), p.coordinate_text(k, "t"))).collect();
    Answer::typed(lines.join("\n"), p)
}

/// `classify` of a polynomial curve: only the output asked for (JSON or text) is rendered.
pub(crate) fn classified(c: &Classified, float: bool, json: bool) -> Answer {
    match c {
        Classified::Fixed(r) => classification(r, float, json),
        Classified::Exact(r) => classification(r, float, json),
    }
}

/// The text or JSON (written out in the report's field order) of a classification.
fn classification<K: Radical>(r: &ClassifyReport<K>, float: bool, json: bool) -> Answer {
    if json {
        if let Some(field) = crate::finite::first_non_finite(r) {
            return Answer { text: String::new(), json: Json::Overflow(field), failed: false };
        }
        let s = serde_json::to_string(r).expect("exact strings and finite floats serialize");
        return Answer { text: String::new(), json: Json::Object(s), failed: false };
    }
    let k = &r.classification;
    let show = |ps: &[Parameter<K>]| -> String {
        ps.iter()
            .map(|p| if float { format!("{p} (≈{:.6})", p.to_f64()) } else { p.to_string() })
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut text = format!("{}: {}", k.class, k.reason);
    if let Some(dp) = &k.double_point {
        text += &format!("; double point {dp}");
    }
    if !k.double_point_parameters.is_empty() {
        text += &format!(" at t = {}", show(&k.double_point_parameters));
    }
    if !k.inflection_parameters.is_empty() {
        text += &format!("; inflections at t = {}", show(&k.inflection_parameters));
    }
    if k.collinear && !k.cusp_parameters.is_empty() {
        text += &format!("; turns back at t = {}", show(&k.cusp_parameters));
    }
    text += &format!(
        "; on [0,1]: {}{}{} inflection{} ({})",
        if k.segment.has_loop { "loop, " } else { "" },
        if k.segment.has_cusp { "cusp, " } else { "" },
        k.segment.inflections,
        if k.segment.inflections == 1 { "" } else { "s" },
        k.segment.category.as_str()
    );
    Answer { text, json: Json::Value(Value::Null), failed: false }
}

/// `classify --weights`.
pub(crate) fn classified_rational(k: &RationalClassification) -> Answer {
    let mut text = k.class.to_string();
    if let Some(n) = k.node_type {
        text += &format!(" ({})", n.as_str());
    }
    text += &format!(": {}", k.reason);
    if !k.double_point_parameters.is_empty() {
        let params: Vec<String> = k.double_point_parameters.iter().map(|p| p.to_string()).collect();
        text += &format!("; finite double-point parameters t = {}", params.join(", "));
    }
    Answer::typed(text, k)
}

/// `x y (w w_i)` per control point, `direction x y at infinity (w 0)` for weight 0.
pub(crate) fn weighted_text(c: &RationalBezier<BigRational>) -> String {
    c.homogeneous()
        .points()
        .iter()
        .map(|h| match h.from_homogeneous() {
            Some(p) => format!(
                "{} (w {})",
                p.coords.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(" "),
                h.coords[h.dim() - 1]
            ),
            None => format!(
                "direction {} at infinity (w 0)",
                h.coords[..h.dim() - 1].iter().map(|x| x.to_string()).collect::<Vec<_>>().join(" ")
            ),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// `defined`: a failed check where the denominator vanishes.
pub(crate) fn defined(d: &Definedness) -> Answer {
    let text = if d.nowhere() {
        "undefined everywhere: the denominator is identically 0".to_string()
    } else if d.defined {
        format!("defined on [{}, {}]: the denominator has no root there", d.interval.from(), d.interval.to())
    } else {
        let shown: Vec<String> = d.roots.iter().map(|x| x.to_string()).collect();
        format!("undefined: the denominator vanishes at {}", shown.join("; "))
    };
    Answer::typed(text, d).failed_if(!d.defined)
}

/// `bbox`: the box per axis, then the stationary points.
pub(crate) fn bbox(b: &BoundingBox) -> Answer {
    let mut lines: Vec<String> = (0..b.min.len())
        .map(|k| {
            format!(
                "{} in [{}, {}] (≈ [{}, {}]), least at t = {}, greatest at t = {}",
                axis(k),
                b.min[k],
                b.max[k],
                b.min_float[k],
                b.max_float[k],
                b.min_at[k],
                b.max_at[k]
            )
        })
        .collect();
    for s in &b.stationary {
        let name = axis(s.axis);
        lines.push(format!(
            "{name}'(t) = 0 at t = {} (≈ {}): {name} = {} (≈ {})",
            s.t, s.t_float, s.value, s.value_float
        ));
    }
    Answer::typed(lines.join("\n"), b)
}

/// `conic`.
pub(crate) fn conic(k: &Conic) -> Answer {
    let text = match &k.shape_factor {
        Some(s) => format!("{} (shape factor w1²/(w0·w2) = {s})", k.conic.as_str()),
        None => format!("{} (w0·w2 = 0: an end point at infinity)", k.conic.as_str()),
    };
    Answer::typed(text, k)
}

/// `implicit`: a failed check for a counterexample.
pub(crate) fn implicit(outcome: &ImplicitOutcome) -> Answer {
    let text = match outcome {
        ImplicitOutcome::Proved { degree_bound, parameters } => format!(
            "proved: f(x(t)) ≡ 0 — W^d·f(X/W) has degree ≤ {degree_bound} and vanishes at {} parameters with W ≠ 0",
            parameters.len()
        ),
        ImplicitOutcome::Counterexample { t, point, value } => {
            format!("counterexample: at t = {t} the curve is at {point} where f = {value}")
        }
    };
    Answer::typed(text, outcome).failed_if(!outcome.proved())
}

/// A patch's control net: rows separated by ` ; `.
fn patch_text(p: &RationalPatch) -> String {
    p.homogeneous()
        .iter()
        .map(|r| {
            r.iter()
                .map(|h| {
                    let d = h.dim() - 1;
                    match h.from_homogeneous() {
                        Some(q) => format!(
                            "{} (w {})",
                            q.coords.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(" "),
                            h.coords[d]
                        ),
                        None => format!(
                            "direction {} (w 0)",
                            h.coords[..d].iter().map(|x| x.to_string()).collect::<Vec<_>>().join(" ")
                        ),
                    }
                })
                .collect::<Vec<_>>()
                .join(", ")
        })
        .collect::<Vec<_>>()
        .join(" ; ")
}

/// `surface eval`.
pub(crate) fn surface_point(s: &PatchValue) -> Answer {
    Answer::typed(format!("S({}, {}) = {}", s.u, s.v, s.point), s)
}

/// `surface subdivide`.
pub(crate) fn surface_split(s: &PatchSplit) -> Answer {
    let (dir, x) = (s.direction.as_str(), &s.at);
    let text = format!("{dir} in [0, {x}]: {}\n{dir} in [{x}, 1]: {}", patch_text(&s.first), patch_text(&s.second));
    Answer::typed(text, s)
}

/// `surface elevate`.
pub(crate) fn patch(p: &RationalPatch) -> Answer {
    Answer::typed(patch_text(p), p)
}

/// `surface contour`.
pub(crate) fn contour(c: &PatchContour) -> Answer {
    let rows: Vec<String> = c
        .bernstein_coefficients
        .iter()
        .map(|r| r.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(" "))
        .collect();
    let mut text = format!("F(u, v) = Σ B_i(u) B_j(v) c_ij with c = {}", rows.join(" ; "));
    if let Some(segs) = &c.polyline {
        text += &format!("\n{} sampled segments", segs.len());
    }
    Answer::typed(text, c)
}
