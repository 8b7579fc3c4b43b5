//! The `--html` report of `casteljau remove-overlaps`: one self-contained HTML file in the
//! style of lint's report (`lint_html`, whose styles and drawings it reuses).
//!
//! A summary, a table of the glyphs left unchanged because they could not be certified (or
//! read), then one card per rewritten glyph (at most [`crate::lint_html::MAX_DRAWN`]): the glyph
//! as the input draws it, with its overlaps, self-intersections, shared pieces and reversed
//! contours marked as lint finds them, beside the glyph as written, with its certificate
//! (contours and points before and after, the proved distance bound, the repairs).
//!
//! Hooks for tests: each card has `data-glyph-id`, each drawing is `<svg class="glyph">`, the
//! before and after figures are `<figure class="before">` and `<figure class="after">`.

use crate::lint_draw::{drawing, esc};
use crate::lint_html::{MAX_DRAWN, STYLE, finding_item};
use crate::lint_units::Unit;
use casteljau::format::{Font, Source};
use casteljau::lint::{Finding, Glyph, Kind, LintOptions, lint};
use casteljau::overlaps::{FontOutcome, GlyphDecision, GlyphReport, Repair};
use casteljau::work::Budget;
use std::fmt::Write as _;

/// Counts of the run (the summary line, and the head of the report).
#[derive(Default)]
pub struct Summary {
    pub considered: usize,
    pub rewritten: usize,
    pub uncertified: usize,
    pub failed: usize,
}

/// The kinds marked on the input's drawing: what overlap removal removes.
const MARKED: [Kind; 4] = [Kind::Overlap, Kind::SelfIntersection, Kind::OverlappingSegments, Kind::Direction];

const EXTRA_STYLE: &str = "figure{margin:0;display:flex;flex-direction:column;gap:4px}\
figcaption{color:var(--muted);font-size:12.5px}\
.pair{display:flex;flex-wrap:wrap;gap:16px;align-items:flex-start}";

/// A glyph of a font as the report draws it, `None` when it cannot be read.
fn unit(font: &Font<'_>, file: &'static str, gid: u32, findings: bool, max_work: f64) -> Option<Unit> {
    let outline = font.outline_numbered(gid).ok()?;
    let glyph = Glyph {
        contours: outline.contours,
        numbers: outline.numbers,
        lone_points: outline.lone_points,
        stored_box: None,
        font_box: None,
    };
    let findings = if findings {
        let mut o = LintOptions::new(font.outer_orientation());
        o.kinds = MARKED.to_vec();
        o.budget = Budget::new(max_work, "--max-work");
        lint(&glyph, &o).unwrap_or_default()
    } else {
        vec![]
    };
    let name = font.glyph_name(gid);
    let label = name.clone().unwrap_or_else(|| format!("gid {gid}"));
    let at = Source { file, glyph: Some(name), glyph_id: Some(gid), ..Default::default() };
    Some(Unit { at, label, glyph, findings, error: None, skipped: None })
}

fn repair(r: &Repair) -> String {
    esc(&r.to_string())
}

fn card(s: &mut String, before: &Unit, after: Option<&Unit>, r: &GlyphReport) {
    let _ = writeln!(s, "<article class=\"card\" id=\"g{}\" data-glyph-id=\"{}\">", r.glyph_id, r.glyph_id);
    let _ = writeln!(
        s,
        "<header><h4><a href=\"#g{}\">{}</a></h4><span class=\"meta\">glyph id {} · contours {} → {} · points {} → \
         {} · distance ≤ <code>{}</code> (≈ {})</span></header>",
        r.glyph_id,
        esc(&before.label),
        r.glyph_id,
        r.contours_before,
        r.contours_after,
        r.points_before,
        r.points_after,
        esc(&r.distance_bound.to_string()),
        r.distance_bound_float
    );
    s.push_str("<div class=\"body\">\n<div class=\"pair\">\n");
    let real: Vec<&Finding> = before.findings.iter().filter(|f| !f.rounding).collect();
    let marked: Vec<(usize, &Finding)> = real.iter().enumerate().map(|(k, f)| (k + 1, *f)).collect();
    if let Some(svg) = drawing(before, &marked) {
        let _ = writeln!(s, "<figure class=\"before\">{svg}<figcaption>before</figcaption></figure>");
    }
    if let Some(svg) = after.and_then(|a| drawing(a, &[])) {
        let _ = writeln!(s, "<figure class=\"after\">{svg}<figcaption>after (as written)</figcaption></figure>");
    }
    s.push_str("</div>\n<ol class=\"findings\">\n");
    for (n, f) in &marked {
        finding_item(s, *n, f);
    }
    for rp in &r.repairs {
        let _ = writeln!(s, "<li>repair: {}</li>", repair(rp));
    }
    s.push_str("</ol>\n</div>\n</article>\n");
}

/// The report's bytes.
pub fn render(
    file: &str,
    input: &[u8],
    outcome: &FontOutcome,
    summary: &Summary,
    max_work: f64,
) -> Result<String, String> {
    let before = Font::open(input, 0).map_err(|e| format!("{file}: {e}"))?;
    let after = Font::open(&outcome.data, 0).map_err(|e| format!("the written font: {e}"))?;
    let name: &'static str = Box::leak(file.to_string().into_boxed_str());
    let mut s = String::with_capacity(1 << 16);
    let _ = write!(
        s,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <meta name=\"generator\" content=\"casteljau {}\">\n<title>casteljau remove-overlaps: {}</title>\n<style>{}{EXTRA_STYLE}",
        env!("CARGO_PKG_VERSION"),
        esc(file),
        STYLE.trim_start()
    );
    for k in MARKED {
        let _ = write!(s, ".k-{}{{--k:{}}}", k.as_str(), crate::lint_html::colour(k));
    }
    s.push_str("\n</style>\n</head>\n<body>\n<main>\n<h1>casteljau remove-overlaps</h1>\n");
    let _ = writeln!(
        s,
        "<p class=\"lede\">{}: each glyph's nonzero region decided exactly, written back on the integer grid, and \
         the rounded outline decided again exactly (certified). Every glyph not listed here is unchanged.</p>",
        esc(file)
    );
    s.push_str("<div class=\"stats\">\n");
    for (class, n, what) in [
        ("", summary.considered, "glyphs considered"),
        ("", summary.rewritten, "rewritten (certified)"),
        (if summary.uncertified > 0 { " bad" } else { "" }, summary.uncertified, "not certified"),
        (if summary.failed > 0 { " bad" } else { "" }, summary.failed, "could not be read or written"),
    ] {
        let _ = writeln!(s, "<div class=\"stat{class}\"><b>{n}</b><span>{what}</span></div>");
    }
    s.push_str("</div>\n");
    let failed: Vec<(u32, String)> = outcome
        .glyphs
        .iter()
        .filter_map(|(g, r)| match r {
            Ok(GlyphDecision::Uncertified { reason }) => Some((*g, format!("not certified: {reason}"))),
            Err(e) => Some((*g, format!("error: {e}"))),
            _ => None,
        })
        .collect();
    if !failed.is_empty() {
        s.push_str("<h3>Left unchanged</h3>\n<table>\n<tr><th>glyph</th><th class=\"n\">id</th><th>why</th></tr>\n");
        for (g, why) in &failed {
            let label = before.glyph_name(*g).unwrap_or_else(|| format!("gid {g}"));
            let _ = writeln!(s, "<tr><td>{}</td><td class=\"n\">{g}</td><td>{}</td></tr>", esc(&label), esc(why));
        }
        s.push_str("</table>\n");
    }
    s.push_str("<h3>Rewritten glyphs</h3>\n<div class=\"cards\">\n");
    let mut drawn = 0;
    for (gid, r) in &outcome.glyphs {
        let Ok(GlyphDecision::Rewritten { report, .. }) = r else { continue };
        if drawn == MAX_DRAWN {
            let _ = writeln!(s, "<p class=\"note\">Only the first {MAX_DRAWN} rewritten glyphs are drawn.</p>");
            break;
        }
        let Some(b) = unit(&before, name, *gid, true, max_work) else { continue };
        let a = unit(&after, name, *gid, false, max_work);
        card(&mut s, &b, a.as_ref(), report);
        drawn += 1;
    }
    s.push_str("</div>\n");
    let _ = write!(
        s,
        "<footer>casteljau {} · remove-overlaps report</footer>\n</main>\n</body>\n</html>\n",
        env!("CARGO_PKG_VERSION")
    );
    Ok(s)
}
