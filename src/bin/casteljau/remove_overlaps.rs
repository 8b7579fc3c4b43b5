//! `casteljau remove-overlaps IN -o OUT [GLYPHS...]`: overlap removal that writes the font
//! (`casteljau::overlaps`): every glyph (or those named) decided exactly on all cores with its
//! own work budget, the certified outlines written, every other glyph left as it was.
//!
//! Output: per rewritten glyph one line (text) or one JSON object (`--json`: the fields of
//! `casteljau::overlaps::GlyphReport`); per glyph that needed rewriting but could not be
//! certified a line with `uncertified` (the reason); per glyph that could not be read or
//! written a line with `error`; then a summary (stdout in text mode, stderr with `--json`).
//! `--html` also writes before/after drawings (see `remove_overlaps_html`).
//!
//! The font is written (atomically) whenever the input could be read as a whole: glyphs that
//! failed stay as they were. Exit code: 2 for bad input (an unreadable file, not a static
//! TrueType or CFF font, an unknown glyph name, an unwritable output) or a glyph that could
//! not be read; else 1 when a glyph could not be certified; 0 otherwise. `--ignore-errors`
//! makes per-glyph failures exit 0 (as fontTools' option of that name).

use crate::remove_overlaps_html::Summary;
use casteljau::format::Font;
use casteljau::overlaps::{GlyphDecision, GlyphReport, WriteOptions, decide_glyph, write_font};
use casteljau::work::Budget;
use clap::Args;
use serde::Serialize;
use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

/// `casteljau remove-overlaps`.
#[derive(Args, Debug)]
pub struct RemoveOverlapsArgs {
    /// The font to read: a static TrueType (glyf) or CFF-flavoured OpenType font (.ttf .otf).
    pub input: PathBuf,
    /// Only these glyphs (names); all glyphs when none are given.
    pub glyphs: Vec<String>,
    /// The font to write (all or nothing; it may be the input).
    #[arg(long, short)]
    pub output: PathBuf,
    /// Keep the TrueType instructions (CFF hints) of the glyphs not rewritten; by default
    /// every glyph considered loses them, as with fontTools.
    #[arg(long)]
    pub keep_hinting: bool,
    /// Exit 0 although some glyphs could not be certified (or read): they are left unchanged
    /// and reported either way.
    #[arg(long)]
    pub ignore_errors: bool,
    /// One JSON object per rewritten glyph (and per glyph that failed); the summary goes to
    /// stderr.
    #[arg(long)]
    pub json: bool,
    /// Also write a self-contained HTML report: each rewritten glyph before and after.
    #[arg(long)]
    pub html: Option<PathBuf>,
    /// Work budget per glyph, in work units (about 1 ns each): a glyph estimated to cost more
    /// is left unchanged and reported as not certified.
    #[arg(long, default_value_t = casteljau::work::DEFAULT_MAX_WORK, value_parser = crate::work_option::parse_work)]
    pub max_work: f64,
    /// Threads (0: all cores).
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// No summary and no progress on stderr (text mode keeps its summary on stdout).
    #[arg(long, short)]
    pub quiet: bool,
}

/// A glyph that needed rewriting but was left unchanged.
#[derive(Serialize)]
struct Uncertified<'a> {
    glyph: Option<&'a str>,
    glyph_id: u32,
    uncertified: &'a str,
}

/// A glyph that could not be read or written.
#[derive(Serialize)]
struct Failed<'a> {
    glyph: Option<&'a str>,
    glyph_id: u32,
    error: String,
}

/// Runs `remove-overlaps`; returns the exit code.
pub fn run(args: &RemoveOverlapsArgs, out: &mut dyn Write) -> i32 {
    match run_checked(args, out) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("casteljau: {e}");
            2
        }
    }
}

fn text_line(r: &GlyphReport) -> String {
    let name = r.glyph.clone().unwrap_or_else(|| format!("gid {}", r.glyph_id));
    let mut s = format!(
        "{name} (gid {}): rewritten, {} → {} contours, {} → {} points, distance ≤ {} (≈ {})",
        r.glyph_id,
        r.contours_before,
        r.contours_after,
        r.points_before,
        r.points_after,
        r.distance_bound,
        r.distance_bound_float
    );
    if !r.repairs.is_empty() {
        let repairs: Vec<String> = r.repairs.iter().map(ToString::to_string).collect();
        s.push_str(&format!("; repairs: {}", repairs.join(", ")));
    }
    s
}

fn run_checked(args: &RemoveOverlapsArgs, out: &mut dyn Write) -> Result<i32, String> {
    let file = args.input.display().to_string();
    let data = std::fs::read(&args.input).map_err(|e| format!("{file}: cannot read: {e}"))?;
    let font = Font::open(&data, 0).map_err(|e| format!("{file}: {e}"))?;
    let glyphs = if args.glyphs.is_empty() {
        None
    } else {
        Some(font.glyphs_named(&args.glyphs).map_err(|e| format!("{file}: {e}"))?)
    };
    let total = glyphs.as_ref().map_or(font.num_glyphs() as usize, Vec::len);
    let options = WriteOptions { keep_hinting: args.keep_hinting, glyphs };
    let pool = crate::pipeline::thread_pool(args.threads, Some(total)).ok_or("cannot start the threads")?;
    let progress = !args.quiet && std::io::stderr().is_terminal();
    let done = AtomicUsize::new(0);
    let max_work = args.max_work;
    let decide = |g: &casteljau::overlaps::GlyphInput| {
        let d = decide_glyph(g, &Budget::new(max_work, "--max-work"));
        let k = done.fetch_add(1, Ordering::Relaxed) + 1;
        if progress && (k.is_multiple_of(64) || k == total) {
            eprint!("\r\x1b[K{file}: {k}/{total} glyphs");
        }
        d
    };
    let outcome = pool.install(|| write_font(&data, &options, &decide)).map_err(|e| format!("{file}: {e}"));
    if progress {
        eprint!("\r\x1b[K");
    }
    let outcome = outcome?;
    crate::files::write_atomically(&args.output, &outcome.data)
        .map_err(|e| format!("{}: cannot write: {e}", args.output.display()))?;
    let mut summary = Summary { considered: outcome.glyphs.len(), ..Summary::default() };
    let mut buf = vec![];
    for (gid, result) in &outcome.glyphs {
        let name = font.glyph_name(*gid);
        let label = name.clone().unwrap_or_else(|| format!("gid {gid}"));
        match result {
            Ok(GlyphDecision::Unchanged) => {}
            Ok(GlyphDecision::Rewritten { report, .. }) => {
                summary.rewritten += 1;
                if args.json {
                    serde_json::to_writer(&mut buf, report).expect("reports serialize");
                    buf.push(b'\n');
                } else {
                    let _ = writeln!(buf, "{}", text_line(report));
                }
            }
            Ok(GlyphDecision::Uncertified { reason }) => {
                summary.uncertified += 1;
                if args.json {
                    let line = Uncertified { glyph: name.as_deref(), glyph_id: *gid, uncertified: reason };
                    serde_json::to_writer(&mut buf, &line).expect("strings serialize");
                    buf.push(b'\n');
                } else {
                    let _ = writeln!(buf, "{label} (gid {gid}): not certified, left unchanged: {reason}");
                }
            }
            Err(e) => {
                summary.failed += 1;
                if args.json {
                    let line = Failed { glyph: name.as_deref(), glyph_id: *gid, error: e.to_string() };
                    serde_json::to_writer(&mut buf, &line).expect("strings serialize");
                    buf.push(b'\n');
                } else {
                    let _ = writeln!(buf, "{label} (gid {gid}): error, left unchanged: {e}");
                }
            }
        }
    }
    let line = format!(
        "{file} → {}: {} considered, {} rewritten (certified), {} not certified, {} could not be read or written, \
         {} unchanged",
        args.output.display(),
        if summary.considered == 1 { "1 glyph".to_string() } else { format!("{} glyphs", summary.considered) },
        summary.rewritten,
        summary.uncertified,
        summary.failed,
        summary.considered - summary.rewritten - summary.uncertified - summary.failed
    );
    if args.json {
        if !args.quiet {
            eprintln!("{line}");
        }
    } else {
        let _ = writeln!(buf, "{line}");
    }
    if out.write_all(&buf).is_err() {
        return Ok(2);
    }
    if let Some(path) = &args.html {
        let html = crate::remove_overlaps_html::render(&file, &data, &outcome, &summary, args.max_work)?;
        crate::files::write_atomically(path, html.as_bytes())
            .map_err(|e| format!("{}: cannot write: {e}", path.display()))?;
    }
    Ok(if args.ignore_errors {
        0
    } else if summary.failed > 0 {
        2
    } else if summary.uncertified > 0 {
        1
    } else {
        0
    })
}
