//! The answers of the `casteljau` commands: each computes exactly and returns the text line(s)
//! and the JSON object for one curve. Where the library has a result type, the JSON is that
//! type's `Serialize` (the types are the schema); this module adds only the text rendering.

use crate::batch::{Answer, Json};
use casteljau::classify::{Classification, Parameter};
use casteljau::curve::bezier::BezierCurve;
use casteljau::curve::casteljau::subdivision_intervals;
use casteljau::curve::fraction_free;
use casteljau::error::{Error, Result};
use casteljau::num::point::Point;
use casteljau::num::quadratic_field::Radical;
use casteljau::num::scalar::Scalar;
use casteljau::rational::rational_bezier::RationalBezier;
use num_rational::BigRational;
use serde_json::{Value, json};

/// Exact strings of a point's coordinates.
pub fn point_json<S: Scalar>(p: &Point<S>) -> Value {
    Value::Array(p.coords.iter().map(|c| Value::String(c.to_string())).collect())
}

/// Exact strings of a polygon.
pub fn points_json<S: Scalar>(ps: &[Point<S>]) -> Value {
    Value::Array(ps.iter().map(point_json).collect())
}

pub(crate) fn eval(c: &BezierCurve<BigRational>, ts: &[BigRational]) -> Result<(String, Value)> {
    let ic = fraction_free::IntegerCurve::new(c);
    let values: Vec<Point<BigRational>> = ts.iter().map(|t| fraction_free::eval_integer(&ic, t)).collect();
    let text = ts.iter().zip(&values).map(|(t, p)| format!("b({t}) = {p}")).collect::<Vec<_>>().join("\n");
    let js: Vec<Value> =
        ts.iter().zip(&values).map(|(t, p)| json!({"t": t.to_string(), "point": point_json(p)})).collect();
    Ok((text, json!({"degree": c.degree(), "values": js})))
}

/// Without `depth` the two halves (`left`, `right`); with any depth the `pieces` form.
pub(crate) fn subdivide(c: &BezierCurve<BigRational>, t0: &BigRational, depth: Option<u32>) -> Result<(String, Value)> {
    let Some(depth) = depth else {
        let (l, r) = fraction_free::subdivide(c, t0);
        let text = format!("left:  {l}\nright: {r}");
        return Ok((
            text,
            json!({"t": t0.to_string(), "left": points_json(l.points()), "right": points_json(r.points())}),
        ));
    };
    crate::batch::output_limit(
        "subdivision output (pieces × points)",
        (c.degree() + 1) << depth.min(40),
        crate::batch::MAX_SUBDIVISION_POINTS,
    )?;
    let pieces = fraction_free::subdivide_repeatedly(c, t0, depth)?;
    let ivs = subdivision_intervals(t0, depth);
    let text = pieces.iter().zip(&ivs).map(|(p, (a, b))| format!("[{a}, {b}]: {p}")).collect::<Vec<_>>().join("\n");
    let js: Vec<Value> = pieces
        .iter()
        .zip(&ivs)
        .map(|(p, (a, b))| json!({"interval": [a.to_string(), b.to_string()], "points": points_json(p.points())}))
        .collect();
    Ok((text, json!({"t": t0.to_string(), "depth": depth, "pieces": js})))
}

pub(crate) fn elevate(c: &BezierCurve<BigRational>, by: usize) -> Result<(String, Value)> {
    let e = fraction_free::elevate(c, by)?;
    Ok((e.to_string(), json!({"degree": e.degree(), "points": points_json(e.points())})))
}

pub(crate) fn derivative(c: &BezierCurve<BigRational>, order: usize) -> (String, Value) {
    let d = c.derivative(order);
    (d.to_string(), json!({"order": order, "degree": d.degree(), "points": points_json(d.points())}))
}

pub(crate) fn reduce(c: &BezierCurve<BigRational>) -> (String, Value) {
    let r = fraction_free::reduce_degree(c);
    let text = format!("degree {} (written as {}): {}", r.degree(), c.degree(), r);
    (text, json!({"degree": c.degree(), "real_degree": r.degree(), "points": points_json(r.points())}))
}

pub(crate) fn triangle(c: &BezierCurve<BigRational>, t: &BigRational) -> Result<(String, Value)> {
    let tri = fraction_free::triangle(c, t);
    let text = tri
        .rows
        .iter()
        .enumerate()
        .map(|(r, row)| {
            let pts: Vec<String> = row.iter().map(|p| p.to_string()).collect();
            format!("r={r}: {}", pts.join(" "))
        })
        .collect::<Vec<_>>()
        .join("\n");
    let rows: Vec<Value> = tri.rows.iter().map(|r| points_json(r)).collect();
    Ok((text, json!({"t": t.to_string(), "rows": rows, "point": point_json(tri.point())})))
}

pub(crate) fn power(c: &BezierCurve<BigRational>) -> (String, Value) {
    let coeffs = fraction_free::power_coefficients(c);
    let names = ["x", "y", "z"];
    let lines: Vec<String> = (0..c.dim())
        .map(|k| {
            let name = names.get(k).map(|s| s.to_string()).unwrap_or(format!("x{k}"));
            let poly: Vec<BigRational> = coeffs.iter().map(|p| p.coords[k].clone()).collect();
            format!("{name}(t) = {}", format_polynomial(&poly, "t"))
        })
        .collect();
    let mut value = json!({"degree": c.degree(), "coefficients": points_json(&coeffs)});
    if c.degree() <= crate::batch::MAX_MATRIX_DEGREE {
        let matrix: Vec<Vec<String>> = casteljau::poly::bernstein::bernstein_to_power_matrix(c.degree())
            .iter()
            .map(|r| r.iter().map(|v| v.to_string()).collect())
            .collect();
        value["matrix"] = json!(matrix);
    }
    (lines.join("\n"), value)
}

/// `c0 + c1 t + c2 t^2 …` with exact coefficients, zero terms omitted (`0` for the zero polynomial).
pub fn format_polynomial(coeffs: &[BigRational], var: &str) -> String {
    let mut s = String::new();
    for (k, c) in coeffs.iter().enumerate() {
        if Scalar::is_zero(c) {
            continue;
        }
        let neg = casteljau::num::scalar::Exact::sign(c) == std::cmp::Ordering::Less;
        let mag = if neg { -c.clone() } else { c.clone() };
        if s.is_empty() {
            s.push_str(if neg { "-" } else { "" });
        } else {
            s.push_str(if neg { " - " } else { " + " });
        }
        let one = mag == casteljau::num::scalar::rat(1);
        match k {
            0 => s.push_str(&mag.to_string()),
            _ => {
                if !one {
                    s.push_str(&mag.to_string());
                    if !mag.is_integer() {
                        s.push('*');
                    }
                }
                s.push_str(var);
                if k > 1 {
                    s.push_str(&format!("^{k}"));
                }
            }
        }
    }
    if s.is_empty() { "0".into() } else { s }
}

/// The JSON of `classify`: the [`Classification`](casteljau::classify::Classification), the
/// cubic's [`CubicEvidence`](casteljau::classify::evidence::CubicEvidence) and, with `--float`,
/// `f64` approximations.
#[derive(serde::Serialize)]
#[serde(bound(serialize = "K: Radical"))]
struct ClassifyJson<'a, K> {
    #[serde(flatten)]
    classification: &'a Classification<K>,
    #[serde(flatten)]
    evidence: Option<casteljau::classify::evidence::CubicEvidence>,
    #[serde(skip_serializing_if = "Option::is_none")]
    float: Option<FloatApproximations>,
}

/// `--float`: nearest `f64`s of the exact answers.
#[derive(serde::Serialize)]
struct FloatApproximations {
    double_point_parameters: Vec<f64>,
    cusp_parameters: Vec<f64>,
    inflection_parameters: Vec<f64>,
    double_point: Option<Vec<f64>>,
}

/// The direct route of `classify --json` for a planar cubic ([`casteljau::classify::integer`]):
/// plain integers in `i128`; other numbers that fit a fixed-width rational over their common
/// denominator (below 2^64) in big integers; false when it does not take the line.
pub(crate) fn classify_direct_json(text: &str, mode: casteljau::num::parse::NumberMode, out: &mut Vec<u8>) -> bool {
    use casteljau::classify::integer::{classify_json, classify_json_small};
    match casteljau::num::parse::integer_cubic(text) {
        Some(p) => classify_json(&p, out),
        None => casteljau::num::parse::small_cubic(text, mode).is_some_and(|p| classify_json_small(&p, out)),
    }
}

/// `classify` of a polynomial curve: the fast route (fixed-width exact arithmetic, when every
/// number fits) and otherwise the big-number route; with `full` (always big numbers) the cubic's
/// evidence too. Only the output asked for (`json` or text) is rendered.
pub(crate) fn classify(
    text: &str,
    dim: usize,
    mode: casteljau::num::parse::NumberMode,
    line: Option<usize>,
    float: bool,
    full: bool,
    json: bool,
) -> Result<Answer> {
    use casteljau::num::small::checked;
    let fast = (!full)
        .then(|| casteljau::num::parse::parse_points_small_in(text, dim, line, mode))
        .flatten()
        .and_then(|pts| checked(|| BezierCurve::new(pts).and_then(|c| casteljau::classify::classify_in(&c))));
    if let Some(k) = fast {
        return Ok(classification_answer(&k?, None, float, json));
    }
    let c = casteljau::num::parse::parse_points_in(text, dim, line, mode).and_then(BezierCurve::new)?;
    let k = casteljau::classify::classify_in(&c)?;
    let evidence = if full { casteljau::classify::evidence::cubic_evidence(&c, &k)? } else { None };
    Ok(classification_answer(&k, evidence, float, json))
}

/// The text or JSON of a classification (in any exact field: both spell numbers alike).
fn classification_answer<K: Radical>(
    k: &Classification<K>,
    evidence: Option<casteljau::classify::evidence::CubicEvidence>,
    float: bool,
    json: bool,
) -> Answer {
    if json {
        let floats = |ps: &[Parameter<K>]| ps.iter().map(|p| p.to_f64()).collect();
        let float_json = float.then(|| FloatApproximations {
            double_point_parameters: floats(&k.double_point_parameters),
            cusp_parameters: floats(&k.cusp_parameters),
            inflection_parameters: floats(&k.inflection_parameters),
            double_point: k.double_point.as_ref().map(|p| p.to_f64().coords),
        });
        let mut buf = Vec::with_capacity(640);
        serde_json::to_writer(&mut buf, &ClassifyJson { classification: k, evidence, float: float_json })
            .expect("exact strings and finite floats serialize");
        let s = String::from_utf8(buf).expect("serde_json writes UTF-8");
        return Answer { text: String::new(), json: Json::Object(s), failed: false };
    }
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

pub(crate) fn classify_weighted(c: &RationalBezier<BigRational>) -> Result<(String, Value)> {
    if c.degree() != 3 || c.dim() != 2 {
        return Err(Error::InvalidArgument { message: "rational classification takes planar cubics".into() });
    }
    let h = c.homogeneous().points().to_vec();
    let k = casteljau::classify::rational_cubic::classify_rational(&h)?;
    let params: Vec<String> = k.double_point_parameters.iter().map(|p| p.to_string()).collect();
    let v = serde_json::to_value(&k).expect("exact strings serialize");
    let mut text = k.class.to_string();
    if let Some(n) = k.node_type {
        text += &format!(" ({})", n.as_str());
    }
    text += &format!(": {}", k.reason);
    if !params.is_empty() {
        text += &format!("; finite double-point parameters t = {}", params.join(", "));
    }
    Ok((text, v))
}

pub(crate) fn weighted_json(c: &RationalBezier<BigRational>) -> Value {
    json!({
        "degree": c.degree(),
        "points": c.points().iter().map(|p| p.as_ref().map(point_json)).collect::<Vec<_>>(),
        "weights": c.weights().iter().map(|w| w.to_string()).collect::<Vec<_>>(),
        "homogeneous": points_json(c.homogeneous().points()),
    })
}

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

pub(crate) fn eval_rational(c: &RationalBezier<BigRational>, ts: &[BigRational]) -> Result<(String, Value)> {
    let eval = c.exact_evaluator();
    let values: Vec<Point<BigRational>> = ts.iter().map(&eval).collect::<Result<_>>()?;
    let text = ts.iter().zip(&values).map(|(t, p)| format!("x({t}) = {p}")).collect::<Vec<_>>().join("\n");
    let js: Vec<Value> =
        ts.iter().zip(&values).map(|(t, p)| json!({"t": t.to_string(), "point": point_json(p)})).collect();
    let defined = c.check_defined(&casteljau::num::scalar::rat(0), &casteljau::num::scalar::rat(1)).is_ok();
    Ok((text, json!({"degree": c.degree(), "rational": true, "values": js, "defined_on_0_1": defined})))
}

pub(crate) fn defined(
    c: &RationalBezier<BigRational>,
    a: &BigRational,
    b: &BigRational,
    budget: &casteljau::work::Budget,
) -> Result<Answer> {
    let roots = c.denominator_roots_within(a, b, budget)?;
    let (text, failed, list) = match &roots {
        None => ("undefined everywhere: the denominator is identically 0".to_string(), true, vec![]),
        Some(r) if r.is_empty() => (format!("defined on [{a}, {b}]: the denominator has no root there"), false, vec![]),
        Some(r) => {
            let shown: Vec<String> = r.iter().map(|x| x.to_string()).collect();
            (format!("undefined: the denominator vanishes at {}", shown.join("; ")), true, shown)
        }
    };
    Ok(Answer {
        text,
        json: Json::Value(json!({"interval": [a.to_string(), b.to_string()], "defined": !failed, "roots": list})),
        failed,
    })
}

pub(crate) fn subdivide_rational(c: &RationalBezier<BigRational>, t0: &BigRational) -> Result<(String, Value)> {
    let (l, r) = c.subdivide(t0)?;
    let text = format!("left:  {}\nright: {}", weighted_text(&l), weighted_text(&r));
    Ok((text, json!({"t": t0.to_string(), "left": weighted_json(&l), "right": weighted_json(&r)})))
}

pub(crate) fn elevate_rational(c: &RationalBezier<BigRational>, by: usize) -> Result<(String, Value)> {
    let e = c.elevate(by)?;
    Ok((weighted_text(&e), weighted_json(&e)))
}

/// `bbox`: the exact box and stationary points ([`casteljau::rational::extrema::BoundingBox`]).
pub(crate) fn bbox(c: &RationalBezier<BigRational>, budget: &casteljau::work::Budget) -> Result<(String, Value)> {
    let b = casteljau::rational::extrema::bounding_box_within(c, budget)?;
    let names = ["x", "y", "z"];
    let name = |k: usize| names.get(k).map(|s| s.to_string()).unwrap_or(format!("x{k}"));
    let mut lines: Vec<String> = (0..b.min.len())
        .map(|k| {
            format!(
                "{} in [{}, {}] (≈ [{}, {}]), least at t = {}, greatest at t = {}",
                name(k),
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
        lines.push(format!(
            "{}'(t) = 0 at t = {} (≈ {}): {} = {} (≈ {})",
            name(s.axis),
            s.t,
            s.t_float,
            name(s.axis),
            s.value,
            s.value_float
        ));
    }
    let value = serde_json::to_value(&b).expect("exact strings and finite floats serialize");
    Ok((lines.join("\n"), value))
}

pub(crate) fn conic(c: &RationalBezier<BigRational>) -> Result<(String, Value)> {
    let (kind, shape) = c.conic_type()?;
    let text = match &shape {
        Some(k) => format!("{} (shape factor w1²/(w0·w2) = {k})", kind.as_str()),
        None => format!("{} (w0·w2 = 0: an end point at infinity)", kind.as_str()),
    };
    Ok((text, json!({"conic": kind.as_str(), "shape_factor": shape.map(|k| k.to_string())})))
}

pub(crate) fn implicit(
    c: &RationalBezier<BigRational>,
    poly: &str,
    budget: &casteljau::work::Budget,
) -> Result<Answer> {
    use casteljau::rational::implicit::{ImplicitOutcome, prove_implicit};
    let outcome = casteljau::proof::expr::with_step_limit(budget.expression_steps(), || prove_implicit(c, poly))?;
    Ok(match outcome {
        ImplicitOutcome::Proved { degree_bound, parameters } => Answer {
            text: format!(
                "proved: f(x(t)) ≡ 0 — W^d·f(X/W) has degree ≤ {degree_bound} and vanishes at {} parameters with W ≠ 0",
                parameters.len()
            ),
            json: Json::Value(
                json!({"proved": true, "degree_bound": degree_bound, "parameters": parameters.iter().map(|t| t.to_string()).collect::<Vec<_>>()}),
            ),
            failed: false,
        },
        ImplicitOutcome::Counterexample { t, point, value } => Answer {
            text: format!("counterexample: at t = {t} the curve is at {point} where f = {value}"),
            json: Json::Value(
                json!({"proved": false, "t": t.to_string(), "point": point_json(&point), "value": value.to_string()}),
            ),
            failed: true,
        },
    })
}

fn patch_json(p: &casteljau::surface::RationalPatch) -> Value {
    let (m, n) = p.degree();
    json!({
        "degree": [m, n],
        "homogeneous": p.homogeneous().iter().map(|r| points_json(r)).collect::<Vec<_>>(),
        "weights": p.weights().iter().map(|r| r.iter().map(|w| w.to_string()).collect::<Vec<_>>()).collect::<Vec<_>>(),
    })
}

fn patch_text(p: &casteljau::surface::RationalPatch) -> String {
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

pub(crate) fn surface_eval(
    p: &casteljau::surface::RationalPatch,
    u: &BigRational,
    v: &BigRational,
) -> Result<(String, Value)> {
    let s = p.eval(u, v)?;
    // Both orders agree with the closed form homogeneously; where the affine recursion runs
    // (no intermediate weight 0) its point must agree too. A recursion that cannot run is not
    // a disagreement.
    let h = p.eval_homogeneous(u, v);
    let agree = [(p.eval_u_then_v(u, v), true), (p.eval_v_then_u(u, v), false)].into_iter().all(|(affine, u_first)| {
        p.eval_homogeneous_de_casteljau(u, v, u_first) == h && affine.as_ref().ok().is_none_or(|x| *x == s)
    });
    Ok((
        format!("S({u}, {v}) = {s}"),
        json!({"u": u.to_string(), "v": v.to_string(), "point": point_json(&s), "de_casteljau_u_then_v_and_v_then_u_agree": agree}),
    ))
}

pub(crate) fn surface_subdivide(
    p: &casteljau::surface::RationalPatch,
    in_u: bool,
    x: &BigRational,
) -> Result<(String, Value)> {
    let (a, b) = if in_u { p.subdivide_u(x)? } else { p.subdivide_v(x)? };
    let dir = if in_u { "u" } else { "v" };
    Ok((
        format!("{dir} in [0, {x}]: {}\n{dir} in [{x}, 1]: {}", patch_text(&a), patch_text(&b)),
        json!({"direction": dir, "at": x.to_string(), "first": patch_json(&a), "second": patch_json(&b)}),
    ))
}

pub(crate) fn surface_elevate(
    p: &casteljau::surface::RationalPatch,
    u_by: usize,
    v_by: usize,
) -> Result<(String, Value)> {
    let e = p.elevate(u_by, v_by)?;
    Ok((patch_text(&e), patch_json(&e)))
}

pub(crate) fn surface_contour(
    p: &casteljau::surface::RationalPatch,
    z: &BigRational,
    polyline: usize,
) -> Result<(String, Value)> {
    if p.dim() < 3 {
        return Err(Error::InvalidArgument { message: "a contour z = c needs a 3D patch".into() });
    }
    let f = p.contour_polynomial(2, z);
    let rows: Vec<String> = f.iter().map(|r| r.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(" ")).collect();
    let mut text = format!("F(u, v) = Σ B_i(u) B_j(v) c_ij with c = {}", rows.join(" ; "));
    let mut v = json!({"z": z.to_string(), "bernstein_coefficients": f.iter().map(|r| r.iter().map(|x| x.to_string()).collect::<Vec<_>>()).collect::<Vec<_>>()});
    if polyline > 0 {
        let segs = p.contour_polyline(2, z, polyline);
        text += &format!("\n{} sampled segments", segs.len());
        v["polyline"] = json!(segs.iter().map(|s| [[s[0].0, s[0].1], [s[1].0, s[1].1]]).collect::<Vec<_>>());
    }
    Ok((text, v))
}
