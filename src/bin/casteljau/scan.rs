//! `casteljau scan FILE...`: every segment of every outline in fonts (`.ttf`, `.otf`, `.ttc`,
//! `.otc`), SVG files (`.svg`), bare SVG path data (`--path`) and text batches (any other file:
//! one curve per line), one JSON line per segment (always JSON Lines: `--json` is accepted and
//! changes nothing) with its provenance, exact control points,
//! classification and flags, in file order; a summary per file on stderr.
//!
//! JSON fields (stable; more may be added): `file`; fonts: `face` (collections only), `glyph`
//! (the glyph's name or `null`), `glyph_id`, `contour`; SVG: `element` (the id, or the 0-based
//! index among shape elements), `tag`, `subpath`; text batches: `line`; then `index` (the
//! segment's place in its contour/subpath/line), the fields of `classify --json` (`degree`,
//! `class`, `segment`, exact parameters, …), `points` (exact strings) and `flags` (see
//! `casteljau::classify::SegmentFlag`); the records are `casteljau::format::ScanRecord`s. A piece that is no polynomial Bézier curve (an SVG
//! arc) has `skipped` (the reason), `from` and `to` instead; an element or glyph that cannot be
//! read has `error`.

use crate::args::{OnlyKind, ScanArgs};
use casteljau::classify::{Classification, SegmentFlag, classify};
use casteljau::curve::BezierCurve;
use casteljau::format::{Contour, Font, Segment, parse_path, read_svg};
use casteljau::format::{Element, ScanRecord, Source as Provenance};
use casteljau::num::{NumberMode, parse_points_in};
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::io::{IsTerminal, Write};

/// Counts for the summary.
#[derive(Default)]
struct Tally {
    segments: usize,
    by_category: BTreeMap<&'static str, usize>,
    by_flag: BTreeMap<&'static str, usize>,
    skipped: usize,
    errors: usize,
    units_with_loop_or_cusp: usize,
}

impl Tally {
    fn add(&mut self, o: Tally) {
        self.segments += o.segments;
        for (k, v) in o.by_category {
            *self.by_category.entry(k).or_default() += v;
        }
        for (k, v) in o.by_flag {
            *self.by_flag.entry(k).or_default() += v;
        }
        self.skipped += o.skipped;
        self.errors += o.errors;
        self.units_with_loop_or_cusp += o.units_with_loop_or_cusp;
    }
}

/// The rendered lines of one unit (glyph, element, batch line) and its tally.
struct Rendered {
    lines: Vec<u8>,
    tally: Tally,
}

/// What a rendered unit is: its contours are a glyph's `contour`s, an SVG element's
/// `subpath`s, or one batch line's curve.
#[derive(Clone, Copy)]
enum Unit {
    Glyph,
    Element,
    Line,
}

struct Scanner {
    only: Vec<OnlyKind>,
    mode: NumberMode,
    variation: Option<Vec<(String, f64)>>,
    budget: casteljau::work::Budget,
}

impl Scanner {
    fn keep(&self, k: Option<&Classification>, flags: &[SegmentFlag], skipped: bool, error: bool) -> bool {
        if self.only.is_empty() {
            return true;
        }
        self.only.iter().any(|o| match o {
            OnlyKind::Cusp => k.is_some_and(|k| k.segment.has_cusp),
            OnlyKind::Loop => k.is_some_and(|k| k.segment.has_loop),
            OnlyKind::Inflection => k.is_some_and(|k| k.segment.inflections > 0),
            OnlyKind::Degenerate => flags.contains(&SegmentFlag::Degenerate),
            OnlyKind::ZeroLengthHandle => flags.contains(&SegmentFlag::ZeroLengthHandle),
            OnlyKind::Endpoint => flags.iter().any(|f| f.at_endpoint()),
            OnlyKind::Skipped => skipped,
            OnlyKind::Error => error,
        })
    }

    /// The JSON lines of one unit's contours.
    fn render(&self, at: &Provenance<'_>, contours: &[Contour], unit: Unit) -> Rendered {
        let mut out = Rendered { lines: vec![], tally: Tally::default() };
        let mut loop_or_cusp = false;
        for (ci, c) in contours.iter().enumerate() {
            let mut at = at.clone();
            match unit {
                Unit::Glyph => at.contour = Some(ci),
                Unit::Element => at.subpath = Some(ci),
                Unit::Line => {}
            }
            for (index, s) in c.segments.iter().enumerate() {
                out.tally.segments += 1;
                match s {
                    Segment::Bezier(ps) => {
                        let k = BezierCurve::new(ps.clone()).and_then(|c| classify(&c));
                        let k = match k {
                            Ok(k) => k,
                            Err(e) => {
                                self.error_line(&mut out, &at, Some(index), e.to_string());
                                continue;
                            }
                        };
                        let flags = k.segment_flags(ps);
                        *out.tally.by_category.entry(k.segment.category.as_str()).or_default() += 1;
                        for f in &flags {
                            *out.tally.by_flag.entry(f.as_str()).or_default() += 1;
                        }
                        loop_or_cusp |= k.segment.has_loop || k.segment.has_cusp;
                        if !self.keep(Some(&k), &flags, false, false) {
                            continue;
                        }
                        let r = ScanRecord::Segment { at: &at, index, classification: &k, points: ps, flags };
                        // finite output or a refusal (the float fields of a huge segment)
                        if let Some(field) = crate::finite::first_non_finite(&r) {
                            let e = crate::finite::overflow("the segment", &format!("the float field {field}"));
                            self.error_line(&mut out, &at, Some(index), e.to_string());
                            continue;
                        }
                        write_record(&mut out.lines, &r);
                    }
                    Segment::Skipped { from, to, reason } => {
                        out.tally.skipped += 1;
                        if !self.keep(None, &[], true, false) {
                            continue;
                        }
                        let r = ScanRecord::Skipped {
                            at: &at,
                            index: Some(index),
                            skipped: reason,
                            from: Some(from),
                            to: Some(to),
                        };
                        write_record(&mut out.lines, &r);
                    }
                }
            }
        }
        out.tally.units_with_loop_or_cusp = usize::from(loop_or_cusp);
        out
    }

    fn error_line(&self, out: &mut Rendered, at: &Provenance<'_>, index: Option<usize>, error: String) {
        out.tally.errors += 1;
        if self.keep(None, &[], false, true) {
            let r = ScanRecord::Error { at, index, error };
            write_record(&mut out.lines, &r);
        }
    }

    fn rendered_error(&self, at: &Provenance<'_>, error: String) -> Rendered {
        let mut out = Rendered { lines: vec![], tally: Tally::default() };
        self.error_line(&mut out, at, None, error);
        out
    }
}

fn write_record(buf: &mut Vec<u8>, r: &ScanRecord<'_>) {
    serde_json::to_writer(&mut *buf, r).expect("exact strings serialize");
    buf.push(b'\n');
}

/// Glyphs (or elements, or lines) answered per parallel chunk.
const UNITS_PER_CHUNK: usize = 256;

/// Runs `scan`; returns the exit code (2 when any file, glyph, element or line could not be
/// read; 0 otherwise).
pub fn run(args: &ScanArgs, out: &mut dyn Write) -> i32 {
    let only = args.only.clone();
    if args.files.is_empty() && args.path.is_none() {
        eprintln!("casteljau: scan needs FILE arguments or --path");
        return 2;
    }
    let Some(pool) = crate::batch::thread_pool(args.threads, None) else { return 2 };
    let variation = match args.variation.as_deref().map(parse_variation).transpose() {
        Ok(v) => v,
        Err(e) => {
            eprintln!("casteljau: --variation: {e}");
            return 2;
        }
    };
    let budget = casteljau::work::Budget::new(args.max_work, "--max-work");
    let sc = Scanner { only, mode: args.numbers.into(), variation, budget };
    let progress = !args.quiet && std::io::stderr().is_terminal();
    let mut code = 0;
    let mut write = |r: &Rendered| -> bool { out.write_all(&r.lines).is_ok() };
    if let Some(d) = &args.path {
        let at = Provenance { element: Some(Element::Index(0)), ..Provenance::new("<path>") };
        let r = match parse_path(d, sc.mode) {
            Ok(contours) => sc.render(&at, &contours, Unit::Element),
            Err(e) => sc.rendered_error(&at, e.to_string()),
        };
        if r.tally.errors > 0 {
            code = 2;
        }
        if !write(&r) {
            return 2;
        }
        summary(args, "<path>", &r.tally);
    }
    for file in &args.files {
        let lower = file.to_ascii_lowercase();
        let mut tally = Tally::default();
        let mut units = 0usize;
        let mut each = |chunk: Vec<Rendered>, total: Option<usize>| -> bool {
            for r in chunk {
                units += 1;
                if !write(&r) {
                    return false;
                }
                tally.add(r.tally);
            }
            if progress {
                match total {
                    Some(t) => eprint!("\r\x1b[K{file}: {units}/{t}"),
                    None => eprint!("\r\x1b[K{file}: {units}"),
                }
            }
            true
        };
        let ok = if [".ttf", ".otf", ".ttc", ".otc"].iter().any(|e| lower.ends_with(e)) {
            scan_font(&sc, &pool, file, &mut each)
        } else if lower.ends_with(".svg") {
            scan_svg(&sc, &pool, file, &mut each)
        } else {
            scan_text(&sc, &pool, file, &mut each)
        };
        if progress {
            eprint!("\r\x1b[K");
        }
        match ok {
            Ok(true) => {}
            Ok(false) => return code.max(2), // stdout closed
            Err(e) => {
                eprintln!("casteljau: {file}: {e}");
                code = 2;
                continue;
            }
        }
        if tally.errors > 0 {
            code = 2;
        }
        summary(args, file, &tally);
    }
    code
}

type Each<'e> = dyn FnMut(Vec<Rendered>, Option<usize>) -> bool + 'e;

fn scan_font(sc: &Scanner, pool: &rayon::ThreadPool, file: &str, each: &mut Each<'_>) -> Result<bool, String> {
    let data = std::fs::read(file).map_err(|e| format!("cannot read: {e}"))?;
    let faces = Font::count(&data).map_err(|e| e.to_string())?;
    for face in 0..faces {
        let mut f = Font::open(&data, face).map_err(|e| e.to_string())?;
        if let Some(v) = &sc.variation {
            f.set_variation(v).map_err(|e| format!("--variation: {e}"))?;
        }
        let n = f.num_glyphs() as usize;
        let gids: Vec<u32> = (0..f.num_glyphs()).collect();
        for chunk in gids.chunks(UNITS_PER_CHUNK) {
            let rendered: Vec<Rendered> = pool.install(|| {
                chunk
                    .par_iter()
                    .map(|&gid| {
                        let at = Provenance {
                            file,
                            face: (faces > 1).then_some(face),
                            glyph: Some(f.glyph_name(gid)),
                            glyph_id: Some(gid),
                            ..Default::default()
                        };
                        match f.outline(gid) {
                            Ok(contours) => sc.render(&at, &contours, Unit::Glyph),
                            Err(e) => sc.rendered_error(&at, e.to_string()),
                        }
                    })
                    .collect()
            });
            if !each(rendered, Some(n)) {
                return Ok(false);
            }
        }
    }
    Ok(true)
}

fn scan_svg(sc: &Scanner, pool: &rayon::ThreadPool, file: &str, each: &mut Each<'_>) -> Result<bool, String> {
    let text = std::fs::read_to_string(file).map_err(|e| format!("cannot read: {e}"))?;
    let shapes = read_svg(&text, sc.mode, &sc.budget).map_err(|e| e.to_string())?;
    let n = shapes.len();
    for chunk in shapes.chunks(UNITS_PER_CHUNK) {
        let rendered: Vec<Rendered> = pool.install(|| {
            chunk
                .par_iter()
                .map(|s| {
                    let element = s.element();
                    let at =
                        Provenance { file, element: Some(element), tag: Some(s.tag.clone()), ..Default::default() };
                    match &s.contours {
                        Ok(contours) => sc.render(&at, contours, Unit::Element),
                        Err(e) if e.is_skipped() => {
                            // not an error of the file: listed as skipped
                            let reason = e.to_string();
                            let mut r = Rendered { lines: vec![], tally: Tally::default() };
                            r.tally.skipped += 1;
                            if sc.keep(None, &[], true, false) {
                                let rec = ScanRecord::Skipped {
                                    at: &at,
                                    index: None,
                                    skipped: &reason,
                                    from: None,
                                    to: None,
                                };
                                write_record(&mut r.lines, &rec);
                            }
                            r
                        }
                        Err(e) => sc.rendered_error(&at, format!("line {}: {e}", s.line)),
                    }
                })
                .collect()
        });
        if !each(rendered, Some(n)) {
            return Ok(false);
        }
    }
    Ok(true)
}

fn scan_text(sc: &Scanner, pool: &rayon::ThreadPool, file: &str, each: &mut Each<'_>) -> Result<bool, String> {
    let text = std::fs::File::open(file).map_err(|e| format!("cannot read: {e}"))?;
    let reader = std::io::BufReader::new(text);
    let mut lines = std::io::BufRead::lines(reader).enumerate().peekable();
    while lines.peek().is_some() {
        let chunk: Vec<(usize, std::io::Result<String>)> = lines.by_ref().take(UNITS_PER_CHUNK * 16).collect();
        let rendered: Vec<Rendered> = pool.install(|| {
            chunk
                .par_iter()
                .filter(|(_, l)| l.as_ref().map_or(true, |l| !l.trim().is_empty() && !l.trim_start().starts_with('#')))
                .map(|(i, l)| {
                    let at = Provenance { file, line: Some(i + 1), ..Default::default() };
                    let l = match l {
                        Ok(l) => l,
                        Err(e) => return sc.rendered_error(&at, e.to_string()),
                    };
                    match parse_points_in(l, 2, Some(i + 1), sc.mode) {
                        Ok(ps) => sc.render(
                            &at,
                            &[Contour { segments: vec![Segment::Bezier(ps)], closed: false }],
                            Unit::Line,
                        ),
                        Err(e) => sc.rendered_error(&at, e.to_string()),
                    }
                })
                .collect()
        });
        if !each(rendered, None) {
            return Ok(false);
        }
    }
    Ok(true)
}

/// The per-file summary on stderr (none with `--quiet`).
fn summary(args: &ScanArgs, file: &str, t: &Tally) {
    if args.quiet {
        return;
    }
    let list = |m: &BTreeMap<&str, usize>| m.iter().map(|(k, v)| format!("{k} {v}")).collect::<Vec<_>>().join(", ");
    eprintln!(
        "{file}: {} segments; categories: {}; flags: {}; units with a loop or cusp: {}; skipped {}, errors {}",
        t.segments,
        if t.by_category.is_empty() { "none".into() } else { list(&t.by_category) },
        if t.by_flag.is_empty() { "none".into() } else { list(&t.by_flag) },
        t.units_with_loop_or_cusp,
        t.skipped,
        t.errors
    );
}

/// `wght=700,wdth=80` as `(tag, value)` pairs.
pub(crate) fn parse_variation(text: &str) -> Result<Vec<(String, f64)>, String> {
    text.split(',')
        .filter(|s| !s.trim().is_empty())
        .map(|s| {
            let (tag, value) = s.split_once('=').ok_or_else(|| format!("{s:?} is not tag=value"))?;
            let tag = tag.trim();
            if tag.is_empty() || tag.len() > 4 || !tag.is_ascii() {
                return Err(format!("{tag:?} is not an axis tag (1 to 4 ASCII characters)"));
            }
            let v: f64 = value.trim().parse().map_err(|_| format!("{value:?} is not a number"))?;
            if !v.is_finite() {
                return Err(format!("{value:?} is not finite"));
            }
            Ok((tag.to_string(), v))
        })
        .collect()
}
