//! `casteljau boolean OP A [B]` and `casteljau arrange A [B ...]`: exact boolean operations and
//! arrangements (`casteljau::shape`) of shapes given as SVG path data or `.svg` files, one
//! question per argument list or per `--input` line (`A ; B`, `A` alone for `simplify`).
//! Fonts (`boolean simplify FONT...`) are [`crate::glyphs`]'.
//!
//! JSON of `boolean` (one object per question): `op`, `fill`, then the fields of
//! `casteljau::shape::BooleanResult` as it serializes them (`contours`, `path`, `area`,
//! `area_float`, `parents`, `orientation`, `pieces`), and with `--against` a `verdict` object
//! (the fields of `casteljau::oracle::Agreement`).

use crate::args::{ArrangeArgs, BooleanArgs};
use crate::batch::{Answer, Json, batch_lines};
use crate::verdicts::{ResultJson, tolerance, verdict_text};
use casteljau::error::{Error, Result};
use casteljau::format::{fill_path, fill_svg};
use casteljau::num::{NumberMode, Point2, parse_points_in};
use casteljau::oracle::check_against;
use casteljau::shape::{
    Arrangement, BooleanOp, BooleanOptions, BooleanResult, Edge, Face, InputPiece, Location, Orientation, Shape, Vertex,
};
use casteljau::work::Budget;
use num_rational::BigRational;
use serde::Serialize;
use std::collections::HashMap;
use std::io::Write;

/// The file name endings read as fonts.
pub(crate) const FONT_ENDINGS: [&str; 4] = [".ttf", ".otf", ".ttc", ".otc"];

/// Whether an operand names a font file (by its ending).
pub(crate) fn is_font(operand: &str) -> bool {
    let lower = operand.trim().to_ascii_lowercase();
    FONT_ENDINGS.iter().any(|e| lower.ends_with(e))
}

fn invalid(message: String) -> Error {
    Error::InvalidArgument { message }
}

/// An operand as a shape: an `.svg` file (every shape element, [`fill_svg`]), or SVG path data
/// (each subpath closed by a line as SVG fills it; empty text is the empty shape).
pub(crate) fn operand(text: &str, mode: NumberMode, budget: &Budget) -> Result<Shape> {
    let t = text.trim();
    if t.to_ascii_lowercase().ends_with(".svg") {
        let svg = std::fs::read_to_string(t).map_err(|e| invalid(format!("{t}: cannot read: {e}")))?;
        return fill_svg(&svg, mode, budget).map_err(|e| invalid(format!("{t}: {e}")));
    }
    if is_font(t) {
        return Err(invalid(format!("{t}: fonts are read by `boolean simplify FONT...` (fonts only)")));
    }
    Ok(Shape::new(fill_path(t, mode)?))
}

/// The float results of `--against`: one for a single question, or per question line.
enum Against {
    None,
    One(String),
    /// The result's text by the input line of its question.
    Lines(HashMap<usize, String>),
}

impl Against {
    /// The float result of the question on `line`, read as a shape (`None` without `--against`).
    fn shape(&self, line: Option<usize>, mode: NumberMode) -> Result<Option<Shape>> {
        let text = match (self, line) {
            (Against::None, _) => return Ok(None),
            (Against::One(t), _) => t,
            (Against::Lines(m), Some(l)) => {
                m.get(&l).ok_or_else(|| invalid(format!("--against: no result for line {l}")))?
            }
            (Against::Lines(_), None) => return Ok(None),
        };
        let path = fill_path(text, mode).map_err(|e| invalid(format!("--against: {e}")))?;
        Ok(Some(Shape::new(path)))
    }
}

/// The lines of a text as `(number, text)`, numbered as the batch reader numbers them (`\n`,
/// `\r\n` or `\r` ends a line; a byte-order mark opening the text is dropped).
fn numbered_lines(text: &str) -> Vec<(usize, &str)> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let b = text.as_bytes();
    let (mut out, mut start, mut number) = (vec![], 0, 1);
    while start < b.len() {
        let end = b[start..].iter().position(|&c| c == b'\n' || c == b'\r').map_or(b.len(), |i| start + i);
        out.push((number, &text[start..end]));
        start = end + 1;
        if end < b.len() && b[end] == b'\r' && b.get(end + 1) == Some(&b'\n') {
            start += 1;
        }
        number += 1;
    }
    out
}

/// Whether a line is a `#` comment.
fn comment(line: &str) -> bool {
    line.trim_start().starts_with('#')
}

/// `--against` for one question: SVG path data, or a file's first line that is not a comment.
fn against_one(a: &str) -> Result<Against> {
    if !std::path::Path::new(a).is_file() {
        return Ok(Against::One(a.to_string()));
    }
    let text = std::fs::read_to_string(a).map_err(|e| invalid(format!("--against {a}: cannot read: {e}")))?;
    let first = numbered_lines(&text).into_iter().map(|(_, l)| l).find(|l| !comment(l)).unwrap_or("");
    Ok(Against::One(first.to_string()))
}

/// `--against` for a batch: the file's non-comment lines, in order, aligned with the input's
/// question lines (non-blank, non-comment).
fn against_lines(a: &str, input: Option<&str>) -> Result<Against> {
    let input = match input {
        Some(i) if i != "-" => i,
        _ => return Err(invalid("--against with a batch needs --input FILE (not stdin)".into())),
    };
    let read =
        |f: &str, what: &str| std::fs::read_to_string(f).map_err(|e| invalid(format!("{what} {f}: cannot read: {e}")));
    let (questions, answers) = (read(input, "--input")?, read(a, "--against")?);
    let questions: Vec<usize> = numbered_lines(&questions)
        .into_iter()
        .filter(|(_, l)| !l.trim().is_empty() && !comment(l))
        .map(|(n, _)| n)
        .collect();
    let answers: Vec<&str> = numbered_lines(&answers).into_iter().map(|(_, l)| l).filter(|l| !comment(l)).collect();
    if questions.len() != answers.len() {
        return Err(invalid(format!(
            "--against {a} has {} results (lines that are not '#' comments) for {} questions in {input}",
            answers.len(),
            questions.len()
        )));
    }
    Ok(Against::Lines(questions.into_iter().zip(answers.into_iter().map(str::to_string)).collect()))
}

/// Runs `boolean`; returns the exit code.
pub fn boolean(args: &BooleanArgs, out: &mut dyn Write) -> i32 {
    let op: BooleanOp = args.op.into();
    let fonts = args.operands.iter().filter(|o| is_font(o)).count();
    if fonts > 0 {
        if op != BooleanOp::Simplify || fonts != args.operands.len() {
            eprintln!("casteljau: fonts are read by `boolean simplify FONT...` (fonts only, no other operands)");
            return 2;
        }
        return crate::glyphs::run(args, out);
    }
    match run_shapes(args, op, out) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("casteljau: {e}");
            2
        }
    }
}

fn run_shapes(args: &BooleanArgs, op: BooleanOp, out: &mut dyn Write) -> Result<i32> {
    let mode: NumberMode = args.batch.numbers.into();
    if !args.glyphs.is_empty() {
        return Err(invalid("--glyphs selects glyphs of fonts (boolean simplify FONT...)".into()));
    }
    let tol = tolerance(&args.tol)?;
    let options =
        BooleanOptions { fill: args.fill.into(), orientation: args.direction.map_or(Orientation::Ccw, Into::into) };
    let single = match args.operands.len() {
        0 => None,
        n if n == op.inputs() => {
            if args.batch.input.is_some() {
                return Err(invalid("give the operands or --input, not both".into()));
            }
            Some(args.operands.clone())
        }
        n => {
            return Err(invalid(format!(
                "{} takes {} operand{}, not {n}",
                op.as_str(),
                op.inputs(),
                if op.inputs() == 1 { "" } else { "s" }
            )));
        }
    };
    if single.is_none() && args.plot.is_some() {
        return Err(invalid("--plot draws one question (give the operands, not --input)".into()));
    }
    let against = match (&args.against, &single) {
        (None, _) => Against::None,
        (Some(a), Some(_)) => against_one(a)?,
        (Some(a), None) => against_lines(a, args.batch.input.as_deref())?,
    };
    let budget = Budget::new(args.max_work, "--max-work");
    let json = args.batch.json;
    // the single question's operands are taken as given; the text stands for them
    let curve_args = args.batch.curve_args(single.as_ref().map(|_| String::from("<operands>")));
    Ok(batch_lines(&curve_args, out, |line, text| {
        let parts: Vec<&str> = match (&single, line) {
            (Some(ops), None) => ops.iter().map(String::as_str).collect(),
            _ => text.split(';').collect(),
        };
        if parts.len() != op.inputs() {
            return Err(invalid(if op.inputs() == 1 {
                "simplify takes one shape per line (no ';')".into()
            } else {
                "a pair of shapes is written \"A ; B\"".into()
            }));
        }
        let shapes = parts
            .iter()
            .zip(["A", "B"])
            .map(|(p, name)| operand(p, mode, &budget).map_err(|e| invalid(format!("{name}: {e}"))))
            .collect::<Result<Vec<_>>>()?;
        let result = casteljau::shape::boolean(op, &shapes, options, &budget)?;
        let verdict = match against.shape(line, mode)? {
            Some(found) => Some(check_against(op, &shapes, options, &result, &found, &tol, &budget)?),
            None => None,
        };
        if let (None, Some(path)) = (line, &args.plot) {
            plot(&shapes, &result, &budget, path)?;
        }
        let failed = verdict.as_ref().is_some_and(|v| !v.agree);
        // only the output asked for is rendered
        // finite output or a refusal: the rounded path and the float fields
        crate::finite::check_text("the result's path", &result.path)?;
        Ok(if json {
            let j = ResultJson { op, fill: options.fill, result: &result, verdict: verdict.as_ref() };
            crate::finite::check("the result", &j)?;
            let s = serde_json::to_string(&j).expect("exact strings and finite floats serialize");
            Answer { text: String::new(), json: Json::Object(s), failed }
        } else {
            let text = verdict.as_ref().map_or_else(|| result.path.clone(), verdict_text);
            Answer { text, json: Json::Object(String::new()), failed }
        })
    }))
}

/// Samples of a piece of an input segment (its exact curve at rational parameters near the
/// rounded ones: a drawing needs no more).
fn sample_piece(shapes: &[Shape], p: &InputPiece) -> Vec<(f64, f64)> {
    let seg = &shapes[p.input].path().contours()[p.contour][p.segment];
    sample_segment(seg, p.from_float, p.to_float)
}

fn sample_segment(seg: &casteljau::RationalBezier<BigRational>, from: f64, to: f64) -> Vec<(f64, f64)> {
    let n = if seg.degree() <= 1 { 1 } else { 48 };
    (0..=n)
        .filter_map(|k| {
            let t = BigRational::from_float(from + (to - from) * k as f64 / n as f64)?;
            let p = seg.eval(&t).ok()?.to_f64();
            Some((p.coords[0], p.coords[1]))
        })
        .collect()
}

/// `--plot FILE`: the inputs (thin, blue and green), the result filled semi-transparent with its
/// boundary (orange), the arrangement's vertices as black dots; written atomically.
fn plot(shapes: &[Shape], result: &BooleanResult, budget: &Budget, path: &std::path::Path) -> Result<()> {
    use crate::files::write_atomically;
    use casteljau::plot::Figure;
    let mut fig = Figure::new().title(&format!("{} contours, area ≈ {}", result.contours, result.area_float));
    let boundary: Vec<Vec<(f64, f64)>> =
        result.pieces.iter().map(|c| c.iter().flat_map(|p| sample_piece(shapes, p)).collect()).collect();
    fig.region(boundary.clone(), "#e69f00", 0.35);
    for (i, s) in shapes.iter().enumerate() {
        let color = if i == 0 { "#1f5fbf" } else { "#2e8b57" };
        for seg in s.path().contours().iter().flatten() {
            fig.polyline(sample_segment(seg, 0.0, 1.0), color, 1.0, false);
        }
    }
    for mut c in boundary {
        if let Some(&first) = c.first() {
            c.push(first);
        }
        fig.polyline(c, "#d55e00", 2.0, false);
    }
    let arr = Arrangement::new(shapes, budget)?;
    for v in arr.vertices() {
        fig.dot((v.point_float[0], v.point_float[1]), 3.0, "#000000");
    }
    if !fig.is_drawable() {
        return Err(invalid(format!("--plot: {} cannot be drawn (coordinates beyond the f64 range)", path.display())));
    }
    write_atomically(path, fig.to_svg(640).as_bytes())
        .map_err(|e| invalid(format!("--plot: cannot write {}: {e}", path.display())))
}

/// `arrange --json`: the arrangement as the library serializes its parts.
#[derive(Serialize)]
struct ArrangementJson<'a> {
    inputs: usize,
    vertices: Vec<Vertex>,
    edges: Vec<Edge>,
    faces: &'a [Face],
    #[serde(skip_serializing_if = "Vec::is_empty")]
    locations: Vec<Located<'a>>,
}

/// A `--locate` point and where it lies (`vertex`, `edge` with `t`, or `face` with `winding`).
#[derive(Serialize)]
struct Located<'a> {
    point: &'a Point2<BigRational>,
    #[serde(flatten)]
    at: &'a Location,
}

/// Runs `arrange`; returns the exit code.
pub fn arrange(args: &ArrangeArgs, out: &mut dyn Write) -> i32 {
    match run_arrange(args, out) {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("casteljau: {e}");
            2
        }
    }
}

fn run_arrange(args: &ArrangeArgs, out: &mut dyn Write) -> Result<()> {
    let mode: NumberMode = args.numbers.into();
    let points = args
        .locate
        .iter()
        .map(|s| match parse_points_in(s, 2, None, mode) {
            Ok(p) if p.len() == 1 => Ok(Point2::try_from(&p[0]).expect("read with dimension 2")),
            Ok(p) => Err(invalid(format!("--locate takes one point \"x y\", got {} in {s:?}", p.len()))),
            Err(e) => Err(invalid(format!("--locate: {e}"))),
        })
        .collect::<Result<Vec<_>>>()?;
    let budget = Budget::new(args.max_work, "--max-work");
    let shapes = args
        .shapes
        .iter()
        .enumerate()
        .map(|(k, s)| operand(s, mode, &budget).map_err(|e| invalid(format!("shape {}: {e}", k + 1))))
        .collect::<Result<Vec<_>>>()?;
    let arr = Arrangement::new(&shapes, &budget)?;
    let faces = arr.faces()?;
    let locations = points.iter().map(|q| arr.locate(q)).collect::<Result<Vec<_>>>()?;
    let (vertices, edges) = (arr.vertices(), arr.edges());
    let written = if args.json {
        let located = points.iter().zip(&locations).map(|(q, at)| Located { point: q, at }).collect();
        let j = ArrangementJson { inputs: arr.inputs(), vertices, edges, faces: &faces, locations: located };
        crate::finite::check("the arrangement", &j)?;
        writeln!(out, "{}", serde_json::to_string(&j).expect("exact strings and finite floats serialize"))
    } else {
        let mut text = format!(
            "{} input{}: {} vertices, {} edges, {} faces ({} bounded)",
            arr.inputs(),
            if arr.inputs() == 1 { "" } else { "s" },
            vertices.len(),
            edges.len(),
            faces.len(),
            faces.iter().filter(|f| f.bounded).count()
        );
        for (q, at) in points.iter().zip(&locations) {
            let place = match at {
                Location::Vertex { vertex } => {
                    let p = vertices[*vertex].point.iter().map(|x| x.to_string()).collect::<Vec<_>>();
                    format!("vertex {vertex} ({})", p.join(", "))
                }
                Location::Edge { edge, t, .. } => format!("edge {edge} at t = {t}"),
                Location::Face { face, winding } => format!("face {face}, winding numbers {winding:?}"),
            };
            text += &format!("\n{q}: {place}");
        }
        writeln!(out, "{text}")
    };
    written.map_err(|e| invalid(format!("cannot write: {e}")))
}
