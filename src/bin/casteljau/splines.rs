//! The `spline` command: reading splines (a control polygon with `--knots`/`--ratios`, or one
//! JSON object per line) and each operation's text and JSON.

use crate::answers::{weighted_json, weighted_text};
use crate::args::{KnotArgs, SplineArgs, SplineOp};
use crate::batch::{Answer, batch_lines, numbers, option_number, parse_weights};
use casteljau::error::{Error, Position, Result};
use casteljau::num::parse::{parse_number, parse_points};
use casteljau::num::point::Point;
use casteljau::rat;
use casteljau::spline::surface::NurbsSurface;
use casteljau::spline::{Conversion, RationalSpline, check_segments};
use num_rational::BigRational;
use serde::Deserialize;
use serde_json::value::RawValue;
use serde_json::{Value, json};
use std::io::Write;

/// One spline of a JSON Lines batch. Numbers are JSON numbers or strings, read exactly.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SplineLine<'a> {
    degree: usize,
    #[serde(borrow, default)]
    knots: Option<Vec<&'a RawValue>>,
    #[serde(borrow, default)]
    ratios: Option<Vec<&'a RawValue>>,
    #[serde(borrow, default)]
    weights: Option<Vec<&'a RawValue>>,
    #[serde(borrow)]
    points: Vec<Vec<&'a RawValue>>,
    #[serde(default)]
    homogeneous: bool,
}

/// The exact number of a JSON number or string.
fn exact(raw: &RawValue, what: &str, index: usize, line: Option<usize>) -> Result<BigRational> {
    let text = raw.get();
    let token = match serde_json::from_str::<String>(text) {
        Ok(s) => s,
        Err(_) => text.to_string(),
    };
    let position = Position { line, column: 1, token: index + 1 };
    parse_number(token.trim(), position).map_err(|e| Error::InvalidArgument { message: format!("{what}: {e}") })
}

fn exact_list(raw: &[&RawValue], what: &str, line: Option<usize>) -> Result<Vec<BigRational>> {
    raw.iter().enumerate().map(|(i, r)| exact(r, what, i, line)).collect()
}

/// A spline from the knots or ratios, homogeneous points, and the degree.
fn build(
    degree: usize,
    hom: Vec<Point<BigRational>>,
    knots: Option<Vec<BigRational>>,
    ratios: Option<Vec<BigRational>>,
) -> Result<RationalSpline> {
    match (knots, ratios) {
        (Some(k), None) => RationalSpline::from_knots(degree, hom, &k),
        (None, Some(r)) => {
            if let Some(i) = r.iter().position(|x| *x <= rat(0)) {
                return Err(Error::InvalidArgument {
                    message: format!("scale ratio {} ({}) must be positive; repeated knots go in --knots", i + 1, r[i]),
                });
            }
            // the knots are the partial sums from 0; the last knot (never used) repeats the one before
            let mut k = vec![rat(0)];
            for x in &r {
                let next = k.last().expect("non-empty").clone() + x;
                k.push(next);
            }
            k.push(k.last().expect("non-empty").clone());
            if k.len() != hom.len() + degree + 1 {
                return Err(Error::InvalidArgument {
                    message: format!(
                        "{} control points of degree {degree} need {} scale ratios, got {}",
                        hom.len(),
                        hom.len() + degree - 1,
                        r.len()
                    ),
                });
            }
            RationalSpline::from_knots(degree, hom, &k)
        }
        (Some(_), Some(_)) => Err(Error::InvalidArgument { message: "give knots or ratios, not both".into() }),
        (None, None) => Err(Error::InvalidArgument { message: "a spline needs --knots or --ratios".into() }),
    }
}

/// Homogeneous points from affine points and weights (a weight 0 needs `--homogeneous`).
fn homogeneous(points: Vec<Point<BigRational>>, weights: Option<Vec<BigRational>>) -> Result<Vec<Point<BigRational>>> {
    let weights = weights.unwrap_or_else(|| vec![rat(1); points.len()]);
    if weights.len() != points.len() {
        return Err(Error::InvalidArgument {
            message: format!("{} weights for {} control points", weights.len(), points.len()),
        });
    }
    if let Some(i) = weights.iter().position(|w| *w == rat(0)) {
        return Err(Error::InvalidArgument {
            message: format!(
                "weight {} is 0: a control point at infinity is given in homogeneous form (--homogeneous)",
                i + 1
            ),
        });
    }
    Ok(points.iter().zip(&weights).map(|(p, w)| p.to_homogeneous(w)).collect())
}

/// The spline of one input line: a JSON object, or a control polygon with the options.
fn spline_of(args: &SplineArgs, line: Option<usize>, text: &str) -> Result<RationalSpline> {
    if text.trim_start().starts_with('{') {
        let s: SplineLine =
            serde_json::from_str(text).map_err(|e| Error::InvalidArgument { message: format!("JSON spline: {e}") })?;
        let points: Vec<Point<BigRational>> = s
            .points
            .iter()
            .enumerate()
            .map(|(i, p)| exact_list(p, &format!("point {}", i + 1), line).map(Point::new))
            .collect::<Result<_>>()?;
        let knots = s.knots.as_deref().map(|k| exact_list(k, "knots", line)).transpose()?;
        let ratios = s.ratios.as_deref().map(|r| exact_list(r, "ratios", line)).transpose()?;
        let weights = s.weights.as_deref().map(|w| exact_list(w, "weights", line)).transpose()?;
        let hom = if s.homogeneous {
            if weights.is_some() {
                return Err(Error::InvalidArgument { message: "give weights or homogeneous points, not both".into() });
            }
            points
        } else {
            homogeneous(points, weights)?
        };
        return build(s.degree, hom, knots, ratios);
    }
    let dim = args.curve.dim + usize::from(args.rational.homogeneous);
    let points = parse_points(text, dim, line)?;
    let hom = if args.rational.homogeneous { points } else { homogeneous(points, parse_weights(&args.rational)?)? };
    let knots = args.knots.as_deref().map(|k| numbers("--knots", k)).transpose()?;
    let ratios = args.ratios.as_deref().map(|r| numbers("--ratios", r)).transpose()?;
    build(args.degree, hom, knots, ratios)
}

/// The spline in JSON: degree, knots (the full vector), homogeneous points, and the affine
/// points and weights where finite.
fn spline_json(sp: &RationalSpline) -> Value {
    let knots: Vec<String> = sp.full_knot_vector().iter().map(|k| k.to_string()).collect();
    let d = sp.homogeneous[0].dim() - 1;
    json!({
        "degree": sp.degree,
        "knots": knots,
        "homogeneous": sp.homogeneous.iter().map(|h| h.coords.iter().map(|x| x.to_string()).collect::<Vec<_>>()).collect::<Vec<_>>(),
        "points": sp.homogeneous.iter().map(|h| h.from_homogeneous().map(|p| p.coords.iter().map(|x| x.to_string()).collect::<Vec<_>>())).collect::<Vec<_>>(),
        "weights": sp.homogeneous.iter().map(|h| h.coords[d].to_string()).collect::<Vec<_>>(),
    })
}

fn spline_text(sp: &RationalSpline) -> String {
    let knots: Vec<String> = sp.full_knot_vector().iter().map(|k| k.to_string()).collect();
    let pts = casteljau::RationalBezier::from_homogeneous(sp.homogeneous.clone())
        .map(|c| weighted_text(&c))
        .unwrap_or_default();
    format!("degree {}, knots {}: {pts}", sp.degree, knots.join(" "))
}

fn joins_text(joins: &[casteljau::spline::knots::Join]) -> String {
    joins
        .iter()
        .map(|j| {
            let c = if j.continuity < 0 { "no continuity (a jump)".to_string() } else { format!("C^{}", j.continuity) };
            format!(
                "u = {} (multiplicity {}): {c}, {}",
                j.knot,
                j.multiplicity,
                if j.proved { "proved" } else { "NOT proved" }
            )
        })
        .collect::<Vec<_>>()
        .join("; ")
}

fn to_bezier(sp: &RationalSpline, method: &str) -> Result<Answer> {
    let how: Conversion = method.parse()?;
    let segs = sp.to_bezier(how)?;
    let joins = sp.joins(&segs);
    let mut lines: Vec<String> = segs
        .iter()
        .enumerate()
        .map(|(s, c)| {
            let (a, b) = sp.span(s);
            format!("[{a}, {b}]: {}", weighted_text(c))
        })
        .collect();
    if !joins.is_empty() {
        lines.push(format!("joins: {}", joins_text(&joins)));
    }
    let js: Vec<Value> = segs
        .iter()
        .enumerate()
        .map(|(s, c)| {
            let (a, b) = sp.span(s);
            let mut v = weighted_json(c);
            v["span"] = json!([a.to_string(), b.to_string()]);
            v
        })
        .collect();
    let failed = joins.iter().any(|j| !j.proved);
    Ok(Answer {
        text: lines.join("\n"),
        json: crate::batch::Json::Value(json!({"degree": sp.degree, "method": method, "segments": js, "joins": joins})),
        failed,
    })
}

fn check(sp: &RationalSpline) -> Result<Answer> {
    use casteljau::proof::Reading;
    let boehm = sp.to_bezier_boehm()?;
    let mut lines = Vec::new();
    let mut failed = false;
    let repeated = sp.has_repeated_knots();
    let mut report = |name: &str, r: std::result::Result<usize, casteljau::spline::SegmentMismatch>| match r {
        Ok(points) => lines.push(format!(
            "{name}: every segment is the NURBS on its span ({points} exact points), joins {}",
            if repeated {
                "C^(n-mu) at each knot of multiplicity mu".to_string()
            } else {
                format!("C^{}", sp.degree - 1)
            }
        )),
        Err(e) => {
            failed = true;
            lines.push(format!("{name}: FAILS: {e:?}"));
        }
    };
    report("Boehm knot insertion", check_segments(sp, &boehm));
    if matches!(sp.degree, 2 | 3) && !repeated {
        let seed = sp.to_bezier(Conversion::Seed(Reading::Corrected))?;
        report("seed formulas", check_segments(sp, &seed));
        let same = seed.iter().zip(&boehm).all(|(a, b)| a.points() == b.points() && a.weights() == b.weights());
        failed |= !same;
        lines.push(format!("seed formulas = Boehm (points and weights): {same}"));
    }
    let joins = sp.joins(&boehm);
    if !joins.is_empty() {
        lines.push(format!("joins: {}", joins_text(&joins)));
    }
    failed |= joins.iter().any(|j| !j.proved);
    Ok(Answer {
        text: lines.join("\n"),
        json: crate::batch::Json::Value(
            json!({"degree": sp.degree, "segments": sp.segments(), "passed": !failed, "report": lines, "joins": joins}),
        ),
        failed,
    })
}

fn eval(sp: &RationalSpline, us: &[BigRational]) -> Result<Answer> {
    let values: Vec<Point<BigRational>> = us.iter().map(|u| sp.eval_at(u)).collect::<Result<_>>()?;
    let text = us.iter().zip(&values).map(|(u, p)| format!("C({u}) = {p}")).collect::<Vec<_>>().join("\n");
    let js: Vec<Value> = us
        .iter()
        .zip(&values)
        .map(|(u, p)| json!({"u": u.to_string(), "point": p.coords.iter().map(|x| x.to_string()).collect::<Vec<_>>()}))
        .collect();
    Ok(Answer { text, json: crate::batch::Json::Value(json!({"degree": sp.degree, "values": js})), failed: false })
}

fn insert(sp: &RationalSpline, u: &BigRational, times: usize) -> Result<Answer> {
    let mut out = sp.clone();
    for _ in 0..times {
        out = out.insert_knot(u)?;
    }
    Ok(Answer { text: spline_text(&out), json: crate::batch::Json::Value(spline_json(&out)), failed: false })
}

fn remove(sp: &RationalSpline, u: &BigRational, times: usize) -> Result<Answer> {
    let mut out = sp.clone();
    for k in 0..times {
        match out.remove_knot(u)? {
            Some(less) => out = less,
            None => {
                let mut v = spline_json(&out);
                v["removed"] = json!(k);
                v["removable"] = json!(false);
                return Ok(Answer {
                    text: format!(
                        "not removable: removing knot {u} {} would change the curve (removed {k} of {times}); {}",
                        if k == 0 { "once" } else { "again" },
                        spline_text(&out)
                    ),
                    json: crate::batch::Json::Value(v),
                    failed: true,
                });
            }
        }
    }
    let mut v = spline_json(&out);
    v["removed"] = json!(times);
    v["removable"] = json!(true);
    Ok(Answer {
        text: format!("removed {times}: the curve is unchanged; {}", spline_text(&out)),
        json: crate::batch::Json::Value(v),
        failed: false,
    })
}

fn elevate(sp: &RationalSpline) -> Result<Answer> {
    let up = sp.elevate_degree()?;
    Ok(Answer { text: spline_text(&up), json: crate::batch::Json::Value(spline_json(&up)), failed: false })
}

/// Runs `spline OP`.
pub(crate) fn run(op: SplineOp, out: &mut dyn Write) -> i32 {
    match op {
        SplineOp::ToBezier { method, spline } => {
            batch_lines(&spline.curve, out, |line, text| to_bezier(&spline_of(&spline, line, text)?, &method))
        }
        SplineOp::Check { spline } => {
            batch_lines(&spline.curve, out, |line, text| check(&spline_of(&spline, line, text)?))
        }
        SplineOp::Eval { u, spline } => {
            let us: Result<Vec<BigRational>> = u.iter().map(|s| option_number("--u", s)).collect();
            batch_lines(&spline.curve, out, |line, text| eval(&spline_of(&spline, line, text)?, &us.clone()?))
        }
        SplineOp::Insert { knot: KnotArgs { knot, times }, spline } => {
            let u = option_number("--knot", &knot);
            batch_lines(&spline.curve, out, |line, text| insert(&spline_of(&spline, line, text)?, &u.clone()?, times))
        }
        SplineOp::Remove { knot: KnotArgs { knot, times }, spline } => {
            let u = option_number("--knot", &knot);
            batch_lines(&spline.curve, out, |line, text| remove(&spline_of(&spline, line, text)?, &u.clone()?, times))
        }
        SplineOp::Elevate { spline } => {
            batch_lines(&spline.curve, out, |line, text| elevate(&spline_of(&spline, line, text)?))
        }
        SplineOp::Surface { degree, knots_u, knots_v, rational, mut curve } => {
            if curve.dim == 2 {
                curve.dim = 3; // surfaces are 3D unless --dim says otherwise
            }
            let dim = curve.dim + usize::from(rational.homogeneous);
            let ku = numbers("--knots-u", &knots_u);
            let kv = numbers("--knots-v", &knots_v);
            batch_lines(&curve, out, |line, text| {
                let (p, q) = degree
                    .split_once(',')
                    .and_then(|(a, b)| Some((a.trim().parse::<usize>().ok()?, b.trim().parse::<usize>().ok()?)))
                    .ok_or_else(|| Error::InvalidArgument {
                        message: format!("--degree must be \"p,q\", got {degree:?}"),
                    })?;
                let (ku, kv) = (ku.clone()?, kv.clone()?);
                let points = parse_points(text, dim, line)?;
                let cols = kv.len().checked_sub(q + 1).filter(|c| *c > 0).ok_or_else(|| Error::InvalidArgument {
                    message: format!("--knots-v: {} knots are too few for degree {q}", kv.len()),
                })?;
                if points.len() % cols != 0 {
                    return Err(Error::InvalidArgument {
                        message: format!(
                            "{} points do not fill rows of {cols} (from --knots-v and degree {q})",
                            points.len()
                        ),
                    });
                }
                let hom = if rational.homogeneous { points } else { homogeneous(points, parse_weights(&rational)?)? };
                let rows: Vec<Vec<Point<BigRational>>> = hom.chunks(cols).map(<[_]>::to_vec).collect();
                surface(&NurbsSurface::from_knots((p, q), rows, &ku, &kv)?)
            })
        }
    }
}

fn surface(s: &NurbsSurface) -> Result<Answer> {
    let patches = s.bezier_patches()?;
    let report = s.check()?;
    let mut lines = Vec::new();
    let mut js = Vec::new();
    for piece in patches.iter().flatten() {
        let h = piece.patch.homogeneous();
        lines.push(format!(
            "[{}, {}] × [{}, {}]: {}",
            piece.span_u.0,
            piece.span_u.1,
            piece.span_v.0,
            piece.span_v.1,
            h.iter()
                .map(|r| r.iter().map(|p| p.to_string()).collect::<Vec<_>>().join(" "))
                .collect::<Vec<_>>()
                .join(" ; ")
        ));
        js.push(json!({
            "span_u": [piece.span_u.0.to_string(), piece.span_u.1.to_string()],
            "span_v": [piece.span_v.0.to_string(), piece.span_v.1.to_string()],
            "homogeneous": h.iter().map(|r| r.iter().map(|p| p.coords.iter().map(|x| x.to_string()).collect::<Vec<_>>()).collect::<Vec<_>>()).collect::<Vec<_>>(),
        }));
    }
    lines.push(format!(
        "{} patches; equal to the surface: {}; joins with each knot's continuity: {}",
        report.patches, report.equals_surface, report.joins_proved
    ));
    let failed = !(report.equals_surface && report.joins_proved);
    Ok(Answer {
        text: lines.join("\n"),
        json: crate::batch::Json::Value(json!({"degree": [s.degree.0, s.degree.1], "patches": js, "check": report})),
        failed,
    })
}
