//! `casteljau boolean simplify FONT... [--glyphs a,b]`: every glyph (or the named ones) of
//! fonts simplified exactly (overlaps removed, the filled region's boundary), on all cores, in
//! glyph order; a summary per file on stderr.
//!
//! JSON (one object per glyph): `file`, `face` (collections only), `glyph` (the name or null),
//! `glyph_id`, `contours_before` (the outline's non-empty contours), `changed`, then `op`,
//! `fill` and the fields of `casteljau::shape::BooleanResult`; `verdict` with `--against`. A
//! glyph that cannot be answered has `error` instead (exit 2 at the end). Text: `name: path`
//! per glyph (`#id` for a glyph without a name).
//!
//! The glyph is `casteljau::format::Font::shape`; `changed` is
//! `casteljau::shape::BooleanResult::changes`: false exactly when the result is the outline
//! itself (as many contours, each made of one outline contour's segments as whole `[0, 1]`
//! pieces, forwards, in the same cyclic order; zero-length segments, which bound nothing, left
//! out of the comparison).
//!
//! Contour indices in `pieces` count the outline's non-empty contours; the default
//! `--direction` is the font's own (`casteljau::format::Font::outer_orientation`: clockwise outer
//! contours for TrueType `glyf` outlines, counter-clockwise for CFF), so an outline already in
//! that form comes back unchanged.

use crate::args::BooleanArgs;
use crate::verdicts::{ResultJson, tolerance, verdict_text};
use casteljau::error::{Error, Result};
use casteljau::format::{Font, fill_path};
use casteljau::num::NumberMode;
use casteljau::oracle::Agreement;
use casteljau::oracle::check_against;
use casteljau::path::FillRule;
use casteljau::shape::{BooleanOp, BooleanOptions, BooleanResult, Orientation, Shape, boolean};
use casteljau::work::Budget;
use num_rational::BigRational;
use rayon::prelude::*;
use serde::de::DeserializeOwned;
use serde::{Deserialize, Deserializer, Serialize};
use serde_json::Value;
use std::collections::HashMap;
use std::io::{IsTerminal, Write};
use std::time::Instant;

/// Glyphs answered per parallel chunk.
const GLYPHS_PER_CHUNK: usize = 64;

/// A glyph of a float result file: by id or by name.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
enum Key {
    Id(u32),
    Name(String),
}

/// A float library's answer for one glyph.
#[derive(Clone, Debug)]
enum FloatAnswer {
    Path(String),
    Error(String),
}

/// One line of the `--against` file as it is read: a field of another JSON type than the one
/// expected counts as absent, except `error`, kept whatever it is.
#[derive(Default, Deserialize)]
struct AnswerLine {
    #[serde(default, deserialize_with = "if_typed")]
    file: Option<String>,
    #[serde(default, deserialize_with = "if_typed")]
    glyph: Option<String>,
    #[serde(default, deserialize_with = "if_typed")]
    glyph_id: Option<u32>,
    #[serde(default, deserialize_with = "if_typed")]
    path: Option<String>,
    #[serde(default, deserialize_with = "present")]
    error: Option<Value>,
}

/// A field's value when it has the type `T`, else `None`.
fn if_typed<'de, D: Deserializer<'de>, T: DeserializeOwned>(d: D) -> std::result::Result<Option<T>, D::Error> {
    Ok(T::deserialize(Value::deserialize(d)?).ok())
}

/// A field's value, `null` included.
fn present<'de, D: Deserializer<'de>>(d: D) -> std::result::Result<Option<Value>, D::Error> {
    Value::deserialize(d).map(Some)
}

/// `--against` for fonts: answers by (file or any file, glyph).
#[derive(Default)]
struct FloatAnswers {
    by: HashMap<(Option<String>, Key), FloatAnswer>,
}

impl FloatAnswers {
    /// Reads JSON Lines with `glyph` or `glyph_id`, and `path` or `error` (optional `file`).
    fn read(file: &str) -> Result<Self> {
        let text = std::fs::read_to_string(file)
            .map_err(|e| Error::InvalidArgument { message: format!("--against {file}: cannot read: {e}") })?;
        let mut out = FloatAnswers::default();
        for (i, line) in text.lines().enumerate() {
            let t = line.trim();
            if t.is_empty() || t.starts_with('#') {
                continue;
            }
            let bad = |m: &str| Error::InvalidArgument { message: format!("--against {file}: line {}: {m}", i + 1) };
            // any JSON value is read; only an object has the fields
            let v: Value = serde_json::from_str(t).map_err(|e| bad(&format!("not JSON: {e}")))?;
            let a = match v {
                Value::Object(_) => AnswerLine::deserialize(v).map_err(|e| bad(&e.to_string()))?,
                _ => AnswerLine::default(),
            };
            let answer = match (a.path, a.error) {
                (Some(p), _) => FloatAnswer::Path(p),
                (None, Some(Value::String(e))) => FloatAnswer::Error(e),
                (None, Some(e)) => FloatAnswer::Error(e.to_string()),
                (None, None) => return Err(bad("a line needs \"path\" (a string) or \"error\"")),
            };
            if a.glyph_id.is_none() && a.glyph.is_none() {
                return Err(bad("a line needs \"glyph\" (the name) or \"glyph_id\""));
            }
            if let Some(id) = a.glyph_id {
                out.by.insert((a.file.clone(), Key::Id(id)), answer.clone());
            }
            if let Some(name) = a.glyph {
                out.by.insert((a.file, Key::Name(name)), answer);
            }
        }
        Ok(out)
    }

    /// The answer for a glyph: by id before name, this file's before any file's.
    fn get(&self, file: &str, gid: u32, name: Option<&str>) -> Option<&FloatAnswer> {
        let mut keys = vec![Key::Id(gid)];
        keys.extend(name.map(|n| Key::Name(n.to_string())));
        keys.into_iter()
            .find_map(|k| self.by.get(&(Some(file.to_string()), k.clone())).or_else(|| self.by.get(&(None, k))))
    }
}

/// How a glyph's exact result compares with a float library's. JSON: the [`Agreement`], or
/// `{"agree":false,"problems":[reason]}` without a float result.
#[derive(Serialize)]
#[serde(untagged)]
enum Judged {
    Verdict(Box<Agreement>),
    /// The float library gave no result (its `error`, or no line for the glyph).
    #[serde(serialize_with = "no_result")]
    NoResult(String),
}

impl Judged {
    fn agree(&self) -> bool {
        matches!(self, Judged::Verdict(v) if v.agree)
    }
    fn text(&self) -> String {
        match self {
            Judged::Verdict(v) => verdict_text(v),
            Judged::NoResult(reason) => format!("disagree: {reason}"),
        }
    }
}

/// The verdict of a glyph without a float result: a disagreement, the reason its one problem.
fn no_result<S: serde::Serializer>(reason: &str, s: S) -> std::result::Result<S::Ok, S::Error> {
    #[derive(Serialize)]
    struct Disagree<'a> {
        agree: bool,
        problems: [&'a str; 1],
    }
    Disagree { agree: false, problems: [reason] }.serialize(s)
}

/// A glyph's JSON line: where the glyph is, then its answer or its error.
#[derive(Serialize)]
struct GlyphLine<'a> {
    file: &'a str,
    #[serde(skip_serializing_if = "Option::is_none")]
    face: Option<u32>,
    glyph: Option<&'a str>,
    glyph_id: u32,
    #[serde(flatten)]
    body: GlyphBody<'a>,
}

/// What a glyph's line says after where the glyph is.
#[derive(Serialize)]
#[serde(untagged)]
enum GlyphBody<'a> {
    Answer(GlyphAnswer<'a>),
    /// The glyph could not be answered.
    Error {
        error: String,
    },
}

/// A glyph's answer: its non-empty contours, whether the result changes them, then the result.
#[derive(Serialize)]
struct GlyphAnswer<'a> {
    contours_before: usize,
    changed: bool,
    #[serde(flatten)]
    result: ResultJson<'a, &'a Judged>,
}

/// What the run needs for every glyph.
struct Context<'a> {
    fill: FillRule,
    direction: Option<Orientation>,
    budget: Budget,
    tol: BigRational,
    mode: NumberMode,
    against: Option<&'a FloatAnswers>,
    json: bool,
}

/// One glyph's output.
#[derive(Default)]
struct Done {
    out: Vec<u8>,
    err: Vec<u8>,
    changed: bool,
    error: bool,
    disagree: bool,
}

/// Counts for the summary.
#[derive(Default)]
struct Tally {
    glyphs: usize,
    changed: usize,
    errors: usize,
    disagree: usize,
}

/// Runs `boolean simplify FONT...`; returns the exit code (2 when a file, a glyph name or a
/// glyph failed; else 1 when a float result disagreed; else 0).
pub fn run(args: &BooleanArgs, out: &mut dyn Write) -> i32 {
    if args.batch.input.is_some() {
        eprintln!("casteljau: fonts are given as FONT arguments, not with --input");
        return 2;
    }
    if args.plot.is_some() {
        eprintln!("casteljau: --plot draws one question (path data or an .svg file), not a font");
        return 2;
    }
    let tol = match tolerance(&args.tol) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("casteljau: {e}");
            return 2;
        }
    };
    let against = match args.against.as_deref().map(FloatAnswers::read).transpose() {
        Ok(a) => a,
        Err(e) => {
            eprintln!("casteljau: {e}");
            return 2;
        }
    };
    let Some(pool) = crate::batch::thread_pool(args.batch.threads, None) else { return 2 };
    // every file is read and every --glyphs name checked before any work
    let mut fonts: Vec<(String, Vec<u8>, u32)> = vec![];
    for file in &args.operands {
        let read = std::fs::read(file)
            .map_err(|e| format!("cannot read: {e}"))
            .and_then(|d| Font::count(&d).map(|n| (d, n)).map_err(|e| e.to_string()));
        match read {
            Ok((data, faces)) => fonts.push((file.clone(), data, faces)),
            Err(e) => {
                eprintln!("casteljau: {file}: {e}");
                return 2;
            }
        }
    }
    let mut selections: Vec<Vec<Vec<u32>>> = vec![];
    for (file, data, faces) in &fonts {
        let mut per_face = vec![];
        for face in 0..*faces {
            match Font::open(data, face).map_err(|e| e.to_string()).and_then(|f| select(&f, &args.glyphs)) {
                Ok(gids) => per_face.push(gids),
                Err(e) => {
                    eprintln!("casteljau: {file}: {e}");
                    return 2;
                }
            }
        }
        selections.push(per_face);
    }
    let ctx = Context {
        fill: args.fill.into(),
        direction: args.direction.map(Into::into),
        budget: Budget::new(args.max_work, "--max-work"),
        tol,
        mode: args.batch.numbers.into(),
        against: against.as_ref(),
        json: args.batch.json,
    };
    let progress = !args.batch.quiet && std::io::stderr().is_terminal();
    let (mut errors, mut disagree) = (false, false);
    for ((file, data, faces), per_face) in fonts.iter().zip(selections) {
        let start = Instant::now();
        let mut tally = Tally::default();
        let total: usize = per_face.iter().map(Vec::len).sum();
        for (face, gids) in per_face.into_iter().enumerate() {
            let face = face as u32;
            let font = match Font::open(data, face) {
                Ok(f) => f,
                Err(e) => {
                    eprintln!("casteljau: {file}: {e}");
                    return 2;
                }
            };
            let face_field = (*faces > 1).then_some(face);
            for chunk in gids.chunks(GLYPHS_PER_CHUNK) {
                let done: Vec<Done> =
                    pool.install(|| chunk.par_iter().map(|&gid| glyph(&ctx, &font, file, face_field, gid)).collect());
                for d in done {
                    tally.glyphs += 1;
                    tally.changed += usize::from(d.changed);
                    tally.errors += usize::from(d.error);
                    tally.disagree += usize::from(d.disagree);
                    if !d.err.is_empty() {
                        let _ = out.flush();
                        let _ = std::io::stderr().write_all(&d.err);
                    }
                    if out.write_all(&d.out).is_err() {
                        return 2; // stdout closed
                    }
                }
                if progress {
                    eprint!("\r\x1b[K{file}: {}/{total}", tally.glyphs);
                }
            }
        }
        if progress {
            eprint!("\r\x1b[K");
        }
        errors |= tally.errors > 0;
        disagree |= tally.disagree > 0;
        if !args.batch.quiet {
            eprintln!(
                "{file}: {} glyphs, {} changed, {} errors{}, {:.2} s",
                tally.glyphs,
                tally.changed,
                tally.errors,
                if ctx.against.is_some() { format!(", {} disagree", tally.disagree) } else { String::new() },
                start.elapsed().as_secs_f64()
            );
        }
    }
    if errors {
        2
    } else if disagree {
        1
    } else {
        0
    }
}

/// The glyph ids to answer, in glyph order: all, or those named (every name must exist).
pub(crate) fn select(font: &Font<'_>, names: &[String]) -> std::result::Result<Vec<u32>, String> {
    if names.is_empty() {
        return Ok((0..font.num_glyphs()).collect());
    }
    font.glyphs_named(names).map_err(|e| e.to_string())
}

/// Simplifies one glyph and renders its line.
fn glyph(ctx: &Context<'_>, font: &Font<'_>, file: &str, face: Option<u32>, gid: u32) -> Done {
    let name = font.glyph_name(gid);
    let label = name.clone().unwrap_or_else(|| format!("#{gid}"));
    let line = |body| GlyphLine { file, face, glyph: name.as_deref(), glyph_id: gid, body };
    let orientation = ctx.direction.unwrap_or_else(|| font.outer_orientation());
    let options = BooleanOptions { fill: ctx.fill, orientation };
    let op = BooleanOp::Simplify;
    let answer = || -> Result<(usize, BooleanResult, bool, Option<Judged>)> {
        let shape = font.shape(gid)?;
        let before = shape.path().contours().len();
        let r = boolean(op, std::slice::from_ref(&shape), options, &ctx.budget)?;
        let changed = r.changes(&shape);
        let judged = match ctx.against.map(|a| a.get(file, gid, name.as_deref())) {
            None => None,
            Some(None) => Some(Judged::NoResult("no result for this glyph in --against".into())),
            Some(Some(FloatAnswer::Error(e))) => Some(Judged::NoResult(format!("the float library failed: {e}"))),
            Some(Some(FloatAnswer::Path(p))) => {
                let found = Shape::new(
                    fill_path(p, ctx.mode)
                        .map_err(|e| Error::InvalidArgument { message: format!("--against: {e}") })?,
                );
                let v = check_against(op, std::slice::from_ref(&shape), options, &r, &found, &ctx.tol, &ctx.budget)?;
                Some(Judged::Verdict(Box::new(v)))
            }
        };
        Ok((before, r, changed, judged))
    };
    let mut d = Done::default();
    match answer() {
        Ok((before, r, changed, judged)) => {
            d.changed = changed;
            d.disagree = judged.as_ref().is_some_and(|j| !j.agree());
            if ctx.json {
                let result = ResultJson { op, fill: ctx.fill, result: &r, verdict: judged.as_ref() };
                let answer = GlyphAnswer { contours_before: before, changed, result };
                serde_json::to_writer(&mut d.out, &line(GlyphBody::Answer(answer)))
                    .expect("exact strings and finite floats serialize");
            } else {
                let text = judged.as_ref().map_or_else(|| r.path.clone(), Judged::text);
                d.out.extend_from_slice(format!("{label}: {text}").as_bytes());
            }
            d.out.push(b'\n');
        }
        Err(e) => {
            d.error = true;
            if ctx.json {
                serde_json::to_writer(&mut d.out, &line(GlyphBody::Error { error: e.to_string() }))
                    .expect("strings serialize");
                d.out.push(b'\n');
            } else {
                let _ = writeln!(d.err, "casteljau: {file}: glyph {label} (id {gid}): {e}");
            }
        }
    }
    d
}
