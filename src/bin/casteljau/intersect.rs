//! `casteljau intersect A B` and `casteljau intersect --self A`: exact intersections
//! (`casteljau::intersect`), one answer per pair; batch lines hold `A ; B` (or one curve with
//! `--self`).

use crate::args::{CurveArgs, IntersectArgs};
use crate::batch::{Answer, Json, batch_lines, numbers_in};
use casteljau::error::{Error, Result};
use casteljau::intersect::{Domain, Intersections, intersect, self_intersect};
use casteljau::num::parse::{NumberMode, parse_points_in};
use casteljau::num::scalar::rat;
use casteljau::rational::RationalBezier;
use num_rational::BigRational;
use std::io::Write;

fn curve(
    text: &str,
    line: Option<usize>,
    mode: NumberMode,
    weights: &Option<Vec<BigRational>>,
) -> Result<RationalBezier<BigRational>> {
    let pts = parse_points_in(text, 2, line, mode)?;
    let w = match weights {
        Some(w) if w.len() != pts.len() => {
            return Err(Error::InvalidArgument {
                message: format!("{} weights for {} control points", w.len(), pts.len()),
            });
        }
        Some(w) => w.clone(),
        None => vec![rat(1); pts.len()],
    };
    RationalBezier::new(pts, w)
}

fn text(r: &Intersections) -> String {
    let mut lines: Vec<String> = r
        .intersections
        .iter()
        .map(|i| {
            let point = match &i.point {
                Some(p) => p.to_string(),
                None => format!("(≈ {}, ≈ {})", i.point_float[0], i.point_float[1]),
            };
            format!(
                "s = {} (≈ {}), t = {} (≈ {}) at {point}: {}, contact order {}",
                i.s,
                i.s_float,
                i.t,
                i.t_float,
                i.kind.as_str(),
                i.contact_order
            )
        })
        .collect();
    for o in &r.overlaps {
        lines.push(format!("overlap: s in [{}, {}] with t from {} to {}", o.s[0], o.s[1], o.t[0], o.t[1]));
    }
    if lines.is_empty() { "no intersections".into() } else { lines.join("\n") }
}

/// Runs `intersect`; returns the exit code.
pub fn run(args: &IntersectArgs, out: &mut dyn Write) -> i32 {
    let mode: NumberMode = args.numbers.into();
    let parse_w = |w: &Option<String>, name: &str| w.as_deref().map(|w| numbers_in(name, w, mode)).transpose();
    let (wa, wb) = match (parse_w(&args.weights_a, "--weights-a"), parse_w(&args.weights_b, "--weights-b")) {
        (Ok(a), Ok(b)) => (a, b),
        (Err(e), _) | (_, Err(e)) => {
            eprintln!("casteljau: {e}");
            return 2;
        }
    };
    let single = match (&args.a, &args.b, args.self_intersection) {
        (Some(a), None, true) => Some(a.clone()),
        (Some(a), Some(b), false) => Some(format!("{a} ; {b}")),
        (None, None, _) => None,
        (Some(_), Some(_), true) => {
            eprintln!("casteljau: --self takes one curve");
            return 2;
        }
        _ => {
            eprintln!("casteljau: give two curves A B (or --self A), or --input");
            return 2;
        }
    };
    let domain = if args.all { Domain::All } else { Domain::Unit };
    let curve_args = CurveArgs {
        curve: single,
        input: args.input.clone(),
        dim: 2,
        json: args.json,
        threads: args.threads,
        quiet: args.quiet,
        max_work: casteljau::work::DEFAULT_MAX_WORK,
        numbers: args.numbers,
    };
    let self_mode = args.self_intersection;
    batch_lines(&curve_args, out, |line, text_line| {
        let r = if self_mode {
            self_intersect(&curve(text_line, line, mode, &wa)?, domain)?
        } else {
            let (a, b) = text_line
                .split_once(';')
                .ok_or_else(|| Error::InvalidArgument { message: "a pair of curves is written \"A ; B\"".into() })?;
            intersect(&curve(a, line, mode, &wa)?, &curve(b, line, mode, &wb)?, domain)?
        };
        let json = serde_json::to_string(&r).expect("exact strings and finite floats serialize");
        Ok(Answer { text: text(&r), json: Json::Object(json), failed: false })
    })
}
