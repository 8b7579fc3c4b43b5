//! `casteljau check --against ANSWERS.jsonl [CURVES]`: a float library's answers, one JSON object
//! per curve, checked against the exact classification (`casteljau::oracle::compare_classification`). Every
//! disagreement is reported with the exact value, the float value and the curve; exit 1 when
//! there is any, 2 for bad input.
//!
//! An answer line holds any subset of the oracle's fields plus, optionally, `points` (the control
//! points: JSON numbers are taken as the `f64` they denote, exactly; strings as exact numbers)
//! and `line` (the line of CURVES it answers). Without `line` the k-th answer goes with the k-th
//! curve of CURVES; without CURVES every answer needs `points`.

use crate::args::CheckArgs;
use casteljau::curve::BezierCurve;
use casteljau::error::{Error, Position, Result};
use casteljau::num::Point;
use casteljau::num::{NumberMode, parse_number_in, parse_points_in};
use casteljau::oracle::{ClassificationDisagreement, FloatClassification, Tolerances, compare_classification};
use num_rational::BigRational;
use std::collections::BTreeMap;
use std::io::{BufRead, Write};

/// One answer line as written by the float library.
#[derive(serde::Deserialize)]
struct AnswerLine {
    #[serde(default)]
    points: Option<Vec<Vec<serde_json::Value>>>,
    #[serde(default)]
    line: Option<usize>,
    #[serde(flatten)]
    answers: FloatClassification,
}

/// One answer line, checked.
struct Checked {
    curve_line: Option<usize>,
    points: Vec<Point<BigRational>>,
    disagreements: Vec<ClassificationDisagreement>,
}

/// One reported disagreement, with where it comes from.
#[derive(serde::Serialize)]
struct Report<'a> {
    /// The line of the answers file.
    answer_line: usize,
    /// The line of CURVES, when the curve came from there.
    #[serde(skip_serializing_if = "Option::is_none")]
    curve_line: Option<usize>,
    points: &'a [Point<BigRational>],
    #[serde(flatten)]
    disagreement: &'a ClassificationDisagreement,
}

fn points_from_json(v: &[Vec<serde_json::Value>], line: usize, mode: NumberMode) -> Result<Vec<Point<BigRational>>> {
    let mut out = vec![];
    for (i, p) in v.iter().enumerate() {
        if p.len() != 2 {
            return Err(Error::PointCount { found: p.len(), dim: 2, point: Some(i + 1), line: Some(line) });
        }
        let mut coords = vec![];
        for (j, x) in p.iter().enumerate() {
            let position = Position { line: Some(line), column: 1, token: 2 * i + j + 1 };
            coords.push(match x {
                serde_json::Value::Number(n) => {
                    let f = n.as_f64().filter(|f| f.is_finite()).ok_or_else(|| Error::ParseNumber {
                        token: n.to_string(),
                        position,
                        reason: "not a finite binary64 number".into(),
                    })?;
                    BigRational::from_float(f).expect("finite")
                }
                serde_json::Value::String(s) => parse_number_in(s, position, mode)?,
                other => {
                    return Err(Error::ParseNumber {
                        token: other.to_string(),
                        position,
                        reason: "a coordinate must be a number or an exact string".into(),
                    });
                }
            });
        }
        out.push(Point::new(coords));
    }
    Ok(out)
}

/// The curve lines of CURVES (not blank, not `#` comments), by line number, in order; an error
/// message for a file that cannot be read.
fn read_curves(path: &str) -> std::result::Result<Vec<(usize, String)>, String> {
    let file = std::fs::File::open(path).map_err(|e| format!("cannot open {path}: {e}"))?;
    let mut curves = vec![];
    for (i, l) in std::io::BufReader::new(file).lines().enumerate() {
        match l {
            Ok(l) if l.trim().is_empty() || l.trim_start().starts_with('#') => {}
            Ok(l) => curves.push((i + 1, l)),
            Err(e) => return Err(format!("{path}: line {}: {e}", i + 1)),
        }
    }
    Ok(curves)
}

/// What an answer line is checked against: the curves of CURVES and how numbers are read.
struct Against<'a> {
    curves: &'a [(usize, String)],
    has_curves: bool,
    mode: NumberMode,
    tol: Tolerances,
}

impl Against<'_> {
    /// Checks answer line `answer_line` (the `k`-th answer, counting from 0) against its curve:
    /// its own `points`, the CURVES line it names, or else the `k`-th curve of CURVES.
    fn check(&self, text: &str, answer_line: usize, k: usize) -> Result<Checked> {
        let a: AnswerLine = serde_json::from_str(text)
            .map_err(|e| Error::InvalidArgument { message: format!("not an answer object: {e}") })?;
        let (curve_line, points) = match (&a.points, a.line) {
            (Some(p), _) => (a.line, points_from_json(p, answer_line, self.mode)?),
            (None, Some(l)) => {
                let (_, text) = self.curves.iter().find(|(n, _)| *n == l).ok_or_else(|| Error::InvalidArgument {
                    message: format!("\"line\": {l} is not a curve line of the CURVES file"),
                })?;
                (Some(l), parse_points_in(text, 2, Some(l), self.mode)?)
            }
            (None, None) => {
                let (n, text) = self.curves.get(k).ok_or_else(|| Error::InvalidArgument {
                    message: if !self.has_curves {
                        "no \"points\" and no CURVES file".into()
                    } else {
                        format!("answer {} has no curve: CURVES has {} curves", k + 1, self.curves.len())
                    },
                })?;
                (Some(*n), parse_points_in(text, 2, Some(*n), self.mode)?)
            }
        };
        let d =
            compare_classification(&casteljau::classify(&BezierCurve::new(points.clone())?)?, &a.answers, &self.tol)?;
        Ok(Checked { curve_line, points, disagreements: d })
    }
}

/// Writes one disagreement: a JSON line ([`Report`]) or a text line.
fn write_disagreement(out: &mut dyn Write, json: bool, report: &Report<'_>) -> std::io::Result<()> {
    if json {
        serde_json::to_writer(&mut *out, report).map_err(std::io::Error::other)?;
        return writeln!(out);
    }
    let d = report.disagreement;
    let curve = report.points.iter().map(|p| p.coords.iter().map(|c| c.to_string()).collect::<Vec<_>>().join(" "));
    let exact = match (d.exact.is_empty(), d.exact_float) {
        (true, _) => "none".to_string(),
        (false, Some(f)) => format!("{} (≈ {f})", d.exact),
        (false, None) => d.exact.clone(),
    };
    writeln!(
        out,
        "answer line {}: {} {}: exact {exact}, float {} — curve {}",
        report.answer_line,
        d.field,
        d.kind.as_str(),
        d.float,
        curve.collect::<Vec<_>>().join(", ")
    )
}

/// Runs `check`; returns the exit code.
pub fn run(args: &CheckArgs, out: &mut dyn Write) -> i32 {
    let tol = Tolerances { parameter: args.tol, point: args.point_tol };
    if !(tol.parameter.is_finite() && tol.parameter >= 0.0 && tol.point.is_finite() && tol.point >= 0.0) {
        eprintln!("casteljau: --tol and --point-tol must be finite and ≥ 0");
        return 2;
    }
    let curves = match args.curves.as_deref().map(read_curves).transpose() {
        Ok(c) => c.unwrap_or_default(),
        Err(e) => {
            eprintln!("casteljau: {e}");
            return 2;
        }
    };
    let against = Against { curves: &curves, has_curves: args.curves.is_some(), mode: args.numbers.into(), tol };
    let answers = match std::fs::File::open(&args.against) {
        Ok(f) => std::io::BufReader::new(f),
        Err(e) => {
            eprintln!("casteljau: cannot open {}: {e}", args.against);
            return 2;
        }
    };
    let (mut bad, mut checked, mut total) = (false, 0usize, 0usize);
    let mut tally: BTreeMap<(&'static str, &'static str), usize> = BTreeMap::new();
    let mut k = 0usize;
    for (i, l) in answers.lines().enumerate() {
        let answer_line = i + 1;
        let text = match l {
            Ok(t) if t.trim().is_empty() => continue,
            Ok(t) => t,
            Err(e) => {
                eprintln!("casteljau: {}: line {answer_line}: {e}", args.against);
                bad = true;
                continue;
            }
        };
        let result = against.check(&text, answer_line, k);
        k += 1;
        match result {
            Err(e) => {
                eprintln!("casteljau: {}: line {answer_line}: {e}", args.against);
                bad = true;
            }
            Ok(Checked { curve_line, points, disagreements: ds }) => {
                checked += 1;
                total += ds.len();
                for d in &ds {
                    *tally.entry((d.field, d.kind.as_str())).or_default() += 1;
                    let report = Report { answer_line, curve_line, points: &points, disagreement: d };
                    if write_disagreement(out, args.json, &report).is_err() {
                        return 2;
                    }
                }
            }
        }
    }
    if !args.quiet {
        let kinds: Vec<String> = tally.iter().map(|((f, k), n)| format!("{f} {k} {n}")).collect();
        eprintln!(
            "checked {checked} curves: {total} disagreements{}",
            if kinds.is_empty() { String::new() } else { format!(" ({})", kinds.join(", ")) }
        );
    }
    if bad {
        2
    } else if total > 0 {
        1
    } else {
        0
    }
}
