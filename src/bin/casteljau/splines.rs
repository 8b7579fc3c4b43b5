//! The `spline` command: reading splines (a control polygon with `--knots`/`--ratios`, or one
//! JSON object per line) and each operation's text and JSON.

use crate::answers::weighted_text;
use crate::args::{KnotArgs, Method, SplineArgs, SplineOp};
use crate::batch::{Answer, Json, batch_lines, numbers, option_number, parse_weights};
use casteljau::error::{Error, Position, Result};
use casteljau::num::Point;
use casteljau::num::{parse_number, parse_points};
use casteljau::spline::{
    BezierConversion, NurbsSurface, RationalSpline, SplineCheck, SplineValues, SurfaceExtraction,
    homogeneous_control_points, joins_text,
};
use casteljau::work::Budget;
use num_rational::BigRational;
use serde::Deserialize;
use serde_json::value::RawValue;
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

/// A spline from the knots or ratios (exactly one of them), homogeneous points, and the degree.
fn build(
    degree: usize,
    hom: Vec<Point<BigRational>>,
    knots: Option<Vec<BigRational>>,
    ratios: Option<Vec<BigRational>>,
) -> Result<RationalSpline> {
    match (knots, ratios) {
        (Some(k), None) => RationalSpline::from_knots(degree, hom, &k),
        (None, Some(r)) => RationalSpline::from_ratios(degree, hom, &r),
        (Some(_), Some(_)) => Err(Error::InvalidArgument { message: "give knots or ratios, not both".into() }),
        (None, None) => Err(Error::InvalidArgument { message: "a spline needs --knots or --ratios".into() }),
    }
}

/// The options of a batch of control polygons, read once (each line reports their errors, in
/// the order a line needs them).
struct Given<'a> {
    args: &'a SplineArgs,
    weights: Result<Option<Vec<BigRational>>>,
    knots: Result<Option<Vec<BigRational>>>,
    ratios: Result<Option<Vec<BigRational>>>,
}

impl<'a> Given<'a> {
    fn new(args: &'a SplineArgs) -> Self {
        Given {
            args,
            weights: parse_weights(&args.rational),
            knots: args.knots.as_deref().map(|k| numbers("--knots", k)).transpose(),
            ratios: args.ratios.as_deref().map(|r| numbers("--ratios", r)).transpose(),
        }
    }
}

/// The spline of one input line: a JSON object, or a control polygon with the options.
fn spline_of(given: &Given<'_>, line: Option<usize>, text: &str) -> Result<RationalSpline> {
    let args = given.args;
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
            homogeneous_control_points(&points, weights.as_deref())?
        };
        return build(s.degree, hom, knots, ratios);
    }
    let dim = args.curve.dim + usize::from(args.rational.homogeneous);
    let points = parse_points(text, dim, line)?;
    let hom = if args.rational.homogeneous {
        points
    } else {
        homogeneous_control_points(&points, given.weights.clone()?.as_deref())?
    };
    build(args.degree, hom, given.knots.clone()?, given.ratios.clone()?)
}

/// The typed result as the answer's JSON (through a `Value`, whose keys print in sorted order,
/// as the fields are declared).
fn json_of(value: &impl serde::Serialize) -> Json {
    Json::Value(serde_json::to_value(value).expect("exact strings serialize"))
}

fn spline_text(sp: &RationalSpline) -> String {
    let knots: Vec<String> = sp.full_knot_vector().iter().map(|k| k.to_string()).collect();
    let pts = casteljau::RationalBezier::from_homogeneous(sp.homogeneous.clone())
        .map(|c| weighted_text(&c))
        .unwrap_or_default();
    format!("degree {}, knots {}: {pts}", sp.degree, knots.join(" "))
}

fn to_bezier(sp: &RationalSpline, method: Method, budget: &Budget) -> Result<Answer> {
    let r = BezierConversion::new(sp, method.into(), budget)?;
    let mut lines: Vec<String> =
        r.segments.iter().map(|s| format!("[{}, {}]: {}", s.span.0, s.span.1, weighted_text(&s.curve))).collect();
    if !r.joins.is_empty() {
        lines.push(format!("joins: {}", joins_text(&r.joins)));
    }
    Ok(Answer { text: lines.join("\n"), json: json_of(&r), failed: !r.proved() })
}

fn check(sp: &RationalSpline, budget: &Budget) -> Result<Answer> {
    let r = SplineCheck::new(sp, budget)?;
    Ok(Answer { text: r.report.join("\n"), json: json_of(&r), failed: !r.passed })
}

fn eval(sp: &RationalSpline, us: &[BigRational], budget: &Budget) -> Result<Answer> {
    let r = SplineValues::new(sp, us, budget)?;
    let text = r.values.iter().map(|v| format!("C({}) = {}", v.u, v.point)).collect::<Vec<_>>().join("\n");
    Ok(Answer { text, json: json_of(&r), failed: false })
}

fn insert(sp: &RationalSpline, u: &BigRational, times: usize) -> Result<Answer> {
    let out = sp.insert_knot(u, times)?;
    Ok(Answer { text: spline_text(&out), json: json_of(&out), failed: false })
}

fn remove(sp: &RationalSpline, u: &BigRational, times: usize) -> Result<Answer> {
    let r = sp.remove_knot(u, times)?;
    let text = if r.removable {
        format!("removed {times}: the curve is unchanged; {}", spline_text(&r.spline))
    } else {
        format!(
            "not removable: removing knot {u} {} would change the curve (removed {} of {times}); {}",
            if r.removed == 0 { "once" } else { "again" },
            r.removed,
            spline_text(&r.spline)
        )
    };
    Ok(Answer { text, json: json_of(&r), failed: !r.removable })
}

fn elevate(sp: &RationalSpline) -> Result<Answer> {
    let up = sp.elevate_degree()?;
    Ok(Answer { text: spline_text(&up), json: json_of(&up), failed: false })
}

/// Runs `spline OP`.
pub(crate) fn run(op: SplineOp, out: &mut dyn Write) -> i32 {
    match op {
        SplineOp::ToBezier { method, spline } => {
            let given = Given::new(&spline);
            let budget = spline.curve.budget();
            batch_lines(&spline.curve, out, |line, text| to_bezier(&spline_of(&given, line, text)?, method, &budget))
        }
        SplineOp::Check { spline } => {
            let given = Given::new(&spline);
            let budget = spline.curve.budget();
            batch_lines(&spline.curve, out, |line, text| check(&spline_of(&given, line, text)?, &budget))
        }
        SplineOp::Eval { u, spline } => {
            let us: Result<Vec<BigRational>> = u.iter().map(|s| option_number("--u", s)).collect();
            let given = Given::new(&spline);
            let budget = spline.curve.budget();
            batch_lines(&spline.curve, out, |line, text| eval(&spline_of(&given, line, text)?, &us.clone()?, &budget))
        }
        SplineOp::Insert { knot: KnotArgs { knot, times }, spline } => {
            let u = option_number("--knot", &knot);
            let given = Given::new(&spline);
            batch_lines(&spline.curve, out, |line, text| insert(&spline_of(&given, line, text)?, &u.clone()?, times))
        }
        SplineOp::Remove { knot: KnotArgs { knot, times }, spline } => {
            let u = option_number("--knot", &knot);
            let given = Given::new(&spline);
            batch_lines(&spline.curve, out, |line, text| remove(&spline_of(&given, line, text)?, &u.clone()?, times))
        }
        SplineOp::Elevate { spline } => {
            let given = Given::new(&spline);
            batch_lines(&spline.curve, out, |line, text| elevate(&spline_of(&given, line, text)?))
        }
        SplineOp::Surface { degree, knots_u, knots_v, rational, mut curve } => {
            let budget = curve.budget();
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
                let hom = if rational.homogeneous {
                    points
                } else {
                    homogeneous_control_points(&points, parse_weights(&rational)?.as_deref())?
                };
                let rows: Vec<Vec<Point<BigRational>>> = hom.chunks(cols).map(<[_]>::to_vec).collect();
                surface(&NurbsSurface::from_knots((p, q), rows, &ku, &kv)?, &budget)
            })
        }
    }
}

fn surface(s: &NurbsSurface, budget: &Budget) -> Result<Answer> {
    let r = SurfaceExtraction::new(s, budget)?;
    let mut lines: Vec<String> = r
        .patches
        .iter()
        .map(|piece| {
            format!(
                "[{}, {}] × [{}, {}]: {}",
                piece.span_u.0,
                piece.span_u.1,
                piece.span_v.0,
                piece.span_v.1,
                piece
                    .patch
                    .homogeneous()
                    .iter()
                    .map(|r| r.iter().map(|p| p.to_string()).collect::<Vec<_>>().join(" "))
                    .collect::<Vec<_>>()
                    .join(" ; ")
            )
        })
        .collect();
    lines.push(format!(
        "{} patches; equal to the surface: {}; joins with each knot's continuity: {}",
        r.check.patches, r.check.equals_surface, r.check.joins_proved
    ));
    let failed = !(r.check.equals_surface && r.check.joins_proved);
    Ok(Answer { text: lines.join("\n"), json: json_of(&r), failed })
}
