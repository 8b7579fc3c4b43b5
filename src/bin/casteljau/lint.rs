//! `casteljau lint FILE... [--path DATA]`: outline QA decided exactly (see `casteljau::lint`).
//!
//! Every glyph of every font (or the `--glyphs` named), every shape element of an SVG file and
//! the `--path` data is checked on all cores; the findings are written in glyph order, as text
//! (one line per finding, then a summary per file) or `--json` (one JSON object per finding:
//! the location fields `file`, `face` (collections), `glyph`, `glyph_id` or `element`, `tag`,
//! then the fields of `casteljau::lint::Finding`; a glyph that could not be checked is a line
//! with `error`; an SVG element that is no Bézier outline (a circle, an ellipse) a line with
//! `skipped`, counted apart). `--html` also writes the report of `lint_html`.
//!
//! Exit code: 2 when a file, a glyph or an element could not be read or checked, or when
//! nothing in a file was checked (every element skipped, or none drawn: nothing checked is not
//! a pass); else 1 when a finding of a denied kind is not explained by rounding; else 0.

use crate::args::LintArgs;
use crate::lint_units::{FileReport, Tally, Unit};
use casteljau::format::{Element, Font, Source, parse_path, read_svg};
use casteljau::lint::{Finding, Glyph, Kind, LintOptions, Severity, lint};
use casteljau::num::NumberMode;
use casteljau::shape::Orientation;
use casteljau::work::Budget;
use num_rational::BigRational;
use rayon::prelude::*;
use serde::Serialize;
use std::io::{IsTerminal, Write};

struct Linter {
    kinds: Vec<Kind>,
    deny: Vec<Kind>,
    direction: Option<Orientation>,
    kink_angle: f64,
    extremum_min: Option<BigRational>,
    max_work: f64,
    mode: NumberMode,
    json: bool,
}

impl Linter {
    fn options(&self, outer: Orientation) -> LintOptions {
        let mut o = LintOptions::new(self.direction.unwrap_or(outer))
            .with_kink_angle(self.kink_angle)
            .expect("checked before the run");
        o.kinds = self.kinds.clone();
        o.extremum_min = self.extremum_min.clone();
        o.budget = Budget::new(self.max_work, "--max-work");
        o
    }

    fn check(&self, at: Source<'static>, label: String, glyph: Glyph, outer: Orientation) -> Unit {
        // finite output or a refusal: an outline beyond the f64 range has no drawing, and its
        // findings' float fields would overflow
        let finite = |findings: &[casteljau::lint::Finding]| -> casteljau::error::Result<()> {
            for f in findings {
                crate::finite::check(&format!("the {} finding", f.kind()), f)?;
                crate::finite::check_text(&format!("the {} finding", f.kind()), &f.message)?;
            }
            Ok(())
        };
        let checked = crate::finite::check_contours(&glyph.contours)
            .and_then(|()| lint(&glyph, &self.options(outer)))
            .and_then(|findings| finite(&findings).map(|()| findings));
        match checked {
            Ok(findings) => Unit { at, label, glyph, findings, error: None, skipped: None },
            Err(e) => Unit { at, label, glyph, findings: vec![], error: Some(e.to_string()), skipped: None },
        }
    }

    fn write(&self, u: &Unit, out: &mut Vec<u8>) {
        #[derive(Serialize)]
        struct Line<'a> {
            #[serde(flatten)]
            at: &'a Source<'a>,
            #[serde(flatten)]
            finding: &'a Finding,
        }
        #[derive(Serialize)]
        struct SkippedLine<'a> {
            #[serde(flatten)]
            at: &'a Source<'a>,
            skipped: &'a str,
        }
        #[derive(Serialize)]
        struct ErrorLine<'a> {
            #[serde(flatten)]
            at: &'a Source<'a>,
            error: &'a str,
        }
        if self.json {
            if let Some(e) = &u.error {
                serde_json::to_writer(&mut *out, &ErrorLine { at: &u.at, error: e }).expect("strings serialize");
                out.push(b'\n');
            }
            if let Some(why) = &u.skipped {
                serde_json::to_writer(&mut *out, &SkippedLine { at: &u.at, skipped: why }).expect("strings serialize");
                out.push(b'\n');
            }
            for f in &u.findings {
                serde_json::to_writer(&mut *out, &Line { at: &u.at, finding: f }).expect("strings serialize");
                out.push(b'\n');
            }
            return;
        }
        let file = u.at.file;
        if let Some(e) = &u.error {
            let _ = writeln!(out, "{file}: {}: error: {e}", u.label);
        }
        if let Some(why) = &u.skipped {
            let _ = writeln!(out, "{file}: {}: skipped: {why}", u.label);
        }
        for f in &u.findings {
            let mut place = vec![];
            if let Some(c) = f.contour {
                place.push(format!("contour {c}"));
            }
            if let Some([a, b]) = f.contours {
                place.push(format!("contours {a} and {b}"));
            }
            if let Some(i) = f.index {
                place.push(format!("segment {i}"));
            }
            if let Some(p) = f.point {
                place.push(format!("point {p}"));
            }
            let place = if place.is_empty() { String::new() } else { format!(" {}", place.join(", ")) };
            let rounding = if f.rounding { " (rounding)" } else { "" };
            let _ = writeln!(
                out,
                "{file}: {}{place}: {} {}{rounding}: {}",
                u.label,
                f.severity.as_str(),
                f.kind(),
                f.message
            );
        }
    }
}

/// Glyphs answered per parallel chunk.
const UNITS_PER_CHUNK: usize = 256;

/// The kinds of `--deny`, `none` for none.
fn denied(list: &Option<Vec<String>>) -> Result<Vec<Kind>, String> {
    match list {
        None => Ok(Kind::ALL.into_iter().filter(|k| k.denied_by_default()).collect()),
        Some(names) => {
            let mut kinds = vec![];
            for n in names.iter().map(|n| n.trim()).filter(|n| !n.is_empty()) {
                match n {
                    "none" => {}
                    "all" => kinds.extend(Kind::ALL),
                    _ => kinds.push(n.parse::<Kind>().map_err(|e| format!("--deny: {e}"))?),
                }
            }
            Ok(kinds)
        }
    }
}

/// Runs `lint`; returns the exit code.
pub fn run(args: &LintArgs, out: &mut dyn Write) -> i32 {
    match run_checked(args, out) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("casteljau: {e}");
            2
        }
    }
}

fn run_checked(args: &LintArgs, out: &mut dyn Write) -> Result<i32, String> {
    if args.files.is_empty() && args.path.is_none() {
        return Err("lint needs FILE arguments or --path".into());
    }
    LintOptions::new(Orientation::Ccw).with_kink_angle(args.kink_angle).map_err(|e| format!("--kink-angle: {e}"))?;
    let extremum_min = args
        .extremum_min
        .as_deref()
        .map(|s| casteljau::num::parse_number(s.trim(), Default::default()))
        .transpose()
        .map_err(|e| format!("--extremum-min: {e}"))?;
    let variation = args.variation.as_deref().map(crate::scan::parse_variation).transpose()?;
    let kinds: Vec<Kind> = Kind::ALL
        .into_iter()
        .filter(|k| args.only.is_empty() || args.only.contains(k))
        .filter(|k| !args.ignore.contains(k))
        .collect();
    let linter = Linter {
        kinds,
        deny: denied(&args.deny)?,
        direction: args.direction.map(Into::into),
        kink_angle: args.kink_angle,
        extremum_min,
        max_work: args.max_work,
        mode: args.numbers.into(),
        json: args.json,
    };
    let Some(pool) = crate::batch::thread_pool(args.threads, args.path.as_ref().map(|_| 1)) else { return Ok(2) };
    // every file is read before any work
    let mut sources: Vec<(String, Vec<u8>)> = vec![];
    for file in &args.files {
        let data = std::fs::read(file).map_err(|e| format!("{file}: cannot read: {e}"))?;
        sources.push((file.clone(), data));
    }
    let progress = !args.quiet && std::io::stderr().is_terminal();
    let mut reports: Vec<FileReport> = vec![];
    let mut code = 0;
    let keep_units = args.html.is_some();
    let mut finish = |file: &str, units: Vec<Unit>, tally: &mut Tally, kept: &mut Vec<Unit>, out: &mut dyn Write| {
        let mut buf = vec![];
        for u in units {
            linter.write(&u, &mut buf);
            tally.add(&u);
            if u.findings.iter().any(|f| f.fails(&linter.deny)) {
                code = code.max(1);
            }
            if u.error.is_some() {
                code = 2;
            }
            if keep_units && (u.error.is_some() || !u.findings.is_empty()) {
                kept.push(u);
            }
        }
        if progress {
            eprint!("\r\x1b[K{file}: {}", tally.units);
        }
        out.write_all(&buf).is_ok()
    };
    if let Some(d) = &args.path {
        let mut tally = Tally::default();
        let mut kept = vec![];
        let at = Source { element: Some(Element::Index(0)), ..Source::new("<path>") };
        let unit = match parse_path(d, linter.mode) {
            Ok(contours) => linter.check(at, "path".into(), Glyph::new(contours), Orientation::Ccw),
            Err(e) => Unit {
                at,
                label: "path".into(),
                glyph: Glyph::default(),
                findings: vec![],
                error: Some(e.to_string()),
                skipped: None,
            },
        };
        if !finish("<path>", vec![unit], &mut tally, &mut kept, out) {
            return Ok(2);
        }
        reports.push(FileReport { file: "<path>".into(), tally, units: kept });
    }
    for (file, data) in &sources {
        let name: &'static str = Box::leak(file.clone().into_boxed_str());
        let lower = file.to_ascii_lowercase();
        let mut tally = Tally::default();
        let mut kept = vec![];
        let mut each = |units: Vec<Unit>| finish(name, units, &mut tally, &mut kept, out);
        let ok = if [".ttf", ".otf", ".ttc", ".otc"].iter().any(|e| lower.ends_with(e)) {
            lint_font(&linter, &pool, name, data, &args.glyphs, variation.as_deref(), &mut each)?
        } else if lower.ends_with(".svg") {
            lint_svg(&linter, &pool, name, data, &mut each)?
        } else {
            return Err(format!("{file}: lint reads fonts (.ttf .otf .ttc .otc) and SVG files (.svg)"));
        };
        if progress {
            eprint!("\r\x1b[K");
        }
        if !ok {
            return Ok(2);
        }
        reports.push(FileReport { file: file.clone(), tally, units: kept });
    }
    for r in &reports {
        if r.tally.units == 0 {
            // nothing checked is not a pass
            let skipped = match r.tally.skipped {
                0 => "it has no outline".to_string(),
                1 => "its one element was skipped: no Bézier outline".to_string(),
                n => format!("all {n} elements were skipped: no Bézier outline"),
            };
            eprintln!("casteljau: {}: nothing was checked ({skipped})", r.file);
            code = 2;
        }
        let line = summary(&r.file, &r.tally);
        if args.json {
            if !args.quiet {
                eprintln!("{line}");
            }
        } else if writeln!(out, "{line}").is_err() {
            return Ok(2);
        }
    }
    if let Some(path) = &args.html {
        let html = crate::lint_html::render(&reports, &linter.deny);
        crate::files::write_atomically(path, html.as_bytes())
            .map_err(|e| format!("{}: cannot write: {e}", path.display()))?;
    }
    Ok(code)
}

fn summary(file: &str, t: &Tally) -> String {
    let kinds: Vec<String> = t
        .by_kind
        .iter()
        .map(|(k, (n, r))| if *r > 0 { format!("{k} {n} (+{r} rounding)") } else { format!("{k} {n}") })
        .collect();
    let sev = |s: Severity| t.by_severity.get(&s).copied().unwrap_or(0);
    format!(
        "{file}: {} checked, {} flagged; {} errors, {} warnings, {} info; {}{}{}",
        t.units,
        t.flagged,
        sev(Severity::Error),
        sev(Severity::Warning),
        sev(Severity::Info),
        if kinds.is_empty() { "no findings".into() } else { kinds.join(", ") },
        if t.errors > 0 { format!("; {} could not be checked", t.errors) } else { String::new() },
        if t.skipped > 0 { format!("; {} skipped (no Bézier outline)", t.skipped) } else { String::new() }
    )
}

type Each<'e> = dyn FnMut(Vec<Unit>) -> bool + 'e;

fn lint_font(
    linter: &Linter,
    pool: &rayon::ThreadPool,
    file: &'static str,
    data: &[u8],
    names: &[String],
    variation: Option<&[(String, f64)]>,
    each: &mut Each<'_>,
) -> Result<bool, String> {
    let faces = Font::count(data).map_err(|e| format!("{file}: {e}"))?;
    for face in 0..faces {
        let mut f = Font::open(data, face).map_err(|e| format!("{file}: {e}"))?;
        if let Some(v) = variation {
            f.set_variation(v).map_err(|e| format!("{file}: --variation: {e}"))?;
        }
        let gids = crate::glyphs::select(&f, names).map_err(|e| format!("{file}: {e}"))?;
        let outer = f.outer_orientation();
        let rat4 = |b: [i16; 4]| b.map(|x| BigRational::from_integer(x.into()));
        // an instance moves the outline away from the default instance's head box
        let font_box = if variation.is_none() { f.head_box().map(rat4) } else { None };
        for chunk in gids.chunks(UNITS_PER_CHUNK) {
            let units: Vec<Unit> = pool.install(|| {
                chunk
                    .par_iter()
                    .map(|&gid| {
                        let name = f.glyph_name(gid);
                        let label = name.clone().unwrap_or_else(|| format!("gid {gid}"));
                        let at = Source {
                            file,
                            face: (faces > 1).then_some(face),
                            glyph: Some(name),
                            glyph_id: Some(gid),
                            ..Default::default()
                        };
                        match f.outline_numbered(gid) {
                            Ok(outline) => {
                                let empty = outline.contours.iter().all(|c| c.segments.is_empty());
                                let glyph = Glyph {
                                    contours: outline.contours,
                                    numbers: outline.numbers,
                                    lone_points: outline.lone_points,
                                    stored_box: if empty { None } else { f.stored_glyph_box(gid).map(rat4) },
                                    font_box: font_box.clone(),
                                };
                                linter.check(at, label, glyph, outer)
                            }
                            Err(e) => Unit {
                                at,
                                label,
                                glyph: Glyph::default(),
                                findings: vec![],
                                error: Some(e.to_string()),
                                skipped: None,
                            },
                        }
                    })
                    .collect()
            });
            if !each(units) {
                return Ok(false);
            }
        }
    }
    Ok(true)
}

fn lint_svg(
    linter: &Linter,
    pool: &rayon::ThreadPool,
    file: &'static str,
    data: &[u8],
    each: &mut Each<'_>,
) -> Result<bool, String> {
    let text = std::str::from_utf8(data).map_err(|e| format!("{file}: not UTF-8: {e}"))?;
    let budget = Budget::new(linter.max_work, "--max-work");
    let shapes = read_svg(text, linter.mode, &budget).map_err(|e| format!("{file}: {e}"))?;
    for chunk in shapes.chunks(UNITS_PER_CHUNK) {
        let units: Vec<Unit> = pool.install(|| {
            chunk
                .par_iter()
                .map(|s| {
                    let element = s.element();
                    let label = match &s.id {
                        Some(id) => format!("{} #{id}", s.tag),
                        None => format!("{} [{}]", s.tag, s.index),
                    };
                    let at = Source { file, element: Some(element), tag: Some(s.tag.clone()), ..Default::default() };
                    match &s.contours {
                        Ok(contours) => linter.check(at, label, Glyph::new(contours.clone()), Orientation::Ccw),
                        // not an error of the file: listed as skipped, as scan lists it
                        Err(e) if e.is_skipped() => Unit {
                            at,
                            label,
                            glyph: Glyph::default(),
                            findings: vec![],
                            error: None,
                            skipped: Some(e.to_string()),
                        },
                        Err(e) => Unit {
                            at,
                            label,
                            glyph: Glyph::default(),
                            findings: vec![],
                            error: Some(format!("line {}: {e}", s.line)),
                            skipped: None,
                        },
                    }
                })
                .collect()
        });
        if !each(units) {
            return Ok(false);
        }
    }
    Ok(true)
}
