//! The `--html` report of `casteljau lint`: one self-contained HTML file.
//!
//! No scripts, no network (a Content-Security-Policy says so: inline styles only), system fonts.
//! Per file: a summary table per kind (findings, findings explained by rounding, denied or not),
//! a table per glyph (counts per kind, linking to the drawings), then one card per glyph to
//! look at, drawn as inline SVG at a readable size: the outline filled (nonzero) and stroked,
//! on-curve nodes (squares at corners, circles at smooth nodes, exactly decided; smaller dots
//! for implied on-curve points), off-curve handles with their lines, and every finding not
//! explained by rounding marked in its kind's colour with a numbered badge (a ring at crossings,
//! contacts and nodes, a tangent tick at a missing extremum, an arrow along a contour of the
//! wrong direction from its start, the shared piece of overlapping segments, the stored and
//! computed boxes), listed beside the drawing with its exact evidence.
//!
//! A glyph is drawn when it has a finding rounding does not explain, or could not be checked;
//! glyphs whose findings rounding explains are in the table only. At most [`MAX_DRAWN`]
//! glyphs are drawn per file, so that a large font gives a report of a few megabytes; the rest
//! are counted. The same findings give the same bytes: numbers are formatted with a fixed
//! number of decimals chosen from the drawing's size, and nothing depends on time or hashing.
//!
//! Hooks for tests: every count cell of a kind table has `data-kind` and `data-count` (the
//! rounding column `data-kind` and `data-rounding`), each file section `data-file`, each card
//! `data-glyph-id` (fonts) or `data-element` (SVG), and each drawing is `<svg class="glyph">`
//! with explicit `width` and `height`.

use crate::lint_units::{FileReport, Unit};
use casteljau::format::Element;
use casteljau::lint::{Axis, Evidence, ExactValue, Finding, Kind, Severity};
use casteljau::shape::Orientation;
use std::fmt::Write as _;

use crate::lint_draw::{drawing, esc};

/// Glyphs drawn per file at most (the others are listed in the glyph table and counted).
pub const MAX_DRAWN: usize = 2000;

/// Links to the glyphs with errors listed at most, per file.
const MAX_JUMPS: usize = 300;

/// The colour of each kind's marks.
pub(crate) fn colour(k: Kind) -> &'static str {
    match k {
        Kind::Direction => "#e03131",
        Kind::SelfIntersection => "#a61e4d",
        Kind::Overlap => "#f76707",
        Kind::Touching => "#1c7ed6",
        Kind::OverlappingSegments => "#7048e8",
        Kind::MissingExtremum => "#0ca678",
        Kind::Kink => "#d6336c",
        Kind::CollinearPoints => "#66a80f",
        Kind::ZeroLengthSegment => "#862e9c",
        Kind::ZeroLengthHandle => "#b08800",
        Kind::DegenerateCurve => "#364fc7",
        Kind::Cusp => "#0b7285",
        Kind::Loop => "#8f5a2e",
        Kind::Bbox => "#495057",
    }
}

/// What a kind means, for the kind table.
fn meaning(k: Kind) -> &'static str {
    match k {
        Kind::Direction => "a contour runs the wrong way for its nesting depth",
        Kind::SelfIntersection => "a contour meets itself",
        Kind::Overlap => "two contours cross",
        Kind::Touching => "two contours meet without crossing",
        Kind::OverlappingSegments => "a piece of outline is drawn twice",
        Kind::MissingExtremum => "a horizontal or vertical tangent inside a segment",
        Kind::Kink => "a node almost, but not exactly, smooth",
        Kind::CollinearPoints => "a redundant node between two lines on one line",
        Kind::ZeroLengthSegment => "a segment of length zero",
        Kind::ZeroLengthHandle => "a curve's handle of length zero",
        Kind::DegenerateCurve => "a curve of lower degree than written",
        Kind::Cusp => "a cusp inside a segment",
        Kind::Loop => "a segment crossing itself",
        Kind::Bbox => "a wrong stored bounding box",
    }
}

pub(crate) const STYLE: &str = r#"
:root{--ink:#1d2129;--muted:#6b7280;--line:#e5e7eb;--bg:#f6f7f9;--card:#fff;--accent:#2f5bd3}
*{box-sizing:border-box}
body{margin:0;background:var(--bg);color:var(--ink);font:14px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,"Helvetica Neue",Arial,sans-serif}
main{max-width:1280px;margin:0 auto;padding:28px 32px 48px}
h1{font-size:26px;margin:0 0 4px;letter-spacing:-.01em}
h2{font-size:21px;margin:36px 0 10px;padding-top:8px;border-top:2px solid var(--ink);overflow-wrap:anywhere}
h3{font-size:15px;margin:22px 0 8px;text-transform:uppercase;letter-spacing:.06em;color:var(--muted)}
a{color:var(--accent);text-decoration:none}a:hover{text-decoration:underline}
code,.mono{font-family:ui-monospace,SFMono-Regular,Menlo,Consolas,"Liberation Mono",monospace;font-size:12.5px}
.lede{color:var(--muted);margin:0 0 14px;max-width:900px}
.stats{display:flex;flex-wrap:wrap;gap:10px;margin:10px 0 6px}
.stat{background:var(--card);border:1px solid var(--line);border-radius:10px;padding:8px 14px;min-width:110px}
.stat b{display:block;font-size:22px;font-variant-numeric:tabular-nums}
.stat span{color:var(--muted);font-size:12px}
.stat.bad b{color:#c92a2a}.stat.warn b{color:#b35c00}
.verdict{display:inline-block;border-radius:999px;padding:2px 12px;font-weight:600;font-size:13px}
.verdict.pass{background:#d3f9d8;color:#2b8a3e}.verdict.fail{background:#ffe3e3;color:#c92a2a}
table{border-collapse:collapse;background:var(--card);border:1px solid var(--line);border-radius:10px;overflow:hidden}
th,td{padding:5px 10px;border-bottom:1px solid var(--line);text-align:left;vertical-align:top}
th{background:#f1f3f5;font-size:12px;font-weight:600;color:#495057}
td.n,th.n{text-align:right;font-variant-numeric:tabular-nums}
tr:last-child td{border-bottom:0}
tr.total td{font-weight:600;background:#f8f9fa}
.glyphs th.k{font-size:11px;max-width:84px;white-space:normal;line-height:1.2}
.glyphs td{padding:3px 10px}
.glyphs tr.quiet td{color:var(--muted)}
.r{color:var(--muted);font-size:11.5px}
.sw{display:inline-block;width:10px;height:10px;border-radius:3px;background:var(--k);margin-right:7px;vertical-align:-1px}
.sev{display:inline-block;border-radius:5px;padding:0 6px;font-size:11.5px;font-weight:600}
.sev.error{background:#ffe3e3;color:#c92a2a}.sev.warning{background:#fff3bf;color:#a35200}.sev.info{background:#e9ecef;color:#495057}
.yes{font-weight:600;color:#c92a2a}.no{color:var(--muted)}
details>summary{cursor:pointer;color:var(--accent);margin:4px 0}
.note{color:var(--muted);margin:8px 0}
.jump{margin:12px 0;line-height:2}
.jump a{display:inline-block;background:#fff5f5;border:1px solid #ffc9c9;border-radius:6px;padding:0 8px;margin-right:4px;line-height:1.6;color:#c92a2a}
.legend{display:flex;flex-wrap:wrap;gap:6px 18px;align-items:center;color:var(--muted);font-size:12.5px;margin:6px 0 14px}
.legend span{display:inline-flex;align-items:center;gap:6px}
.cards{display:flex;flex-direction:column;gap:18px}
.card{background:var(--card);border:1px solid var(--line);border-radius:12px;padding:14px 16px;box-shadow:0 1px 2px rgba(0,0,0,.04)}
.card header{display:flex;flex-wrap:wrap;align-items:baseline;gap:4px 12px;margin-bottom:10px}
.card h4{margin:0;font-size:17px;overflow-wrap:anywhere}
.card .meta{color:var(--muted);font-size:12.5px}
.body{display:flex;flex-wrap:wrap;gap:16px;align-items:flex-start}
svg.glyph{flex:none;background:#fff;border:1px solid var(--line);border-radius:8px}
.findings{flex:1 1 360px;min-width:300px;margin:0;padding:0;list-style:none}
.findings>li{padding:8px 0;border-bottom:1px solid var(--line)}
.findings>li:last-child{border-bottom:0}
.num{display:inline-block;min-width:20px;height:20px;border-radius:10px;background:var(--k);color:#fff;font-size:11.5px;font-weight:700;text-align:center;line-height:20px;padding:0 5px;margin-right:6px}
.kind{font-weight:600;color:var(--k)}
.loc{color:var(--muted);font-size:12.5px;margin-left:6px}
.msg{margin:3px 0 4px}
dl.ev{display:grid;grid-template-columns:max-content 1fr;gap:2px 10px;margin:0;font-size:12.5px}
dl.ev dt{color:var(--muted)}
dl.ev dd{margin:0;overflow-wrap:anywhere}
.err{background:#fff5f5;border:1px solid #ffc9c9;color:#c92a2a;border-radius:8px;padding:8px 12px;margin:0 0 10px;overflow-wrap:anywhere}
footer{color:var(--muted);font-size:12px;margin-top:40px}
svg .fill{fill:#e9ecef;fill-rule:nonzero;stroke:none}
svg .ol{fill:none;stroke:#1d2129;stroke-width:1.4px;vector-effect:non-scaling-stroke;stroke-linejoin:round}
svg .skip{fill:none;stroke:#c92a2a;stroke-width:1.4px;stroke-dasharray:4 3;vector-effect:non-scaling-stroke}
svg .base{fill:none;stroke:#ced4da;stroke-width:1px;stroke-dasharray:6 4;vector-effect:non-scaling-stroke}
svg .hd{fill:none;stroke:#adb5bd;stroke-width:1px;vector-effect:non-scaling-stroke}
svg .off{fill:#fff;stroke:#868e96;stroke-width:1px;vector-effect:non-scaling-stroke}
svg .on{fill:#fff;stroke:#1d2129;stroke-width:1.3px;vector-effect:non-scaling-stroke}
svg .imp{fill:#868e96;stroke:none}
svg .m path,svg .m circle,svg .m rect{fill:none;stroke:var(--k);stroke-width:2px;vector-effect:non-scaling-stroke;stroke-linecap:round;stroke-linejoin:round}
svg .m .dot,svg .m .ah{fill:var(--k);stroke:none}
svg .m .hl{stroke-width:8px;stroke-opacity:.4}
svg .m .thin{stroke-width:5px;stroke-opacity:.3}
.findings.rounding>li{padding:3px 0;font-size:12.5px}
svg .m .st{stroke-dasharray:6 4}
svg .m .cp{stroke-width:1.2px}
svg .b circle{fill:var(--k);stroke:#fff;stroke-width:1.5px;vector-effect:non-scaling-stroke}
svg .b text{fill:#fff;font-weight:700;text-anchor:middle;dominant-baseline:central;font-family:system-ui,-apple-system,"Segoe UI",Roboto,Arial,sans-serif}
"#;

/// The report's bytes.
pub fn render(files: &[FileReport], deny: &[Kind]) -> String {
    let mut s = String::with_capacity(1 << 16);
    let names: Vec<&str> = files.iter().map(|f| f.file.as_str()).collect();
    let _ = write!(
        s,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <meta name=\"generator\" content=\"casteljau {}\">\n<title>casteljau lint: {}</title>\n<style>{}",
        env!("CARGO_PKG_VERSION"),
        esc(&names.join(", ")),
        STYLE.trim_start()
    );
    for k in Kind::ALL {
        let _ = write!(s, ".k-{}{{--k:{}}}", k.as_str(), colour(k));
    }
    s.push_str("\n</style>\n</head>\n<body>\n<main>\n<h1>casteljau lint</h1>\n");
    s.push_str(
        "<p class=\"lede\">Outline QA decided in exact arithmetic: every finding is an exact statement about the \
         control points as the file stores them, with its exact evidence. Findings explained by rounding to the \
         font's integer grid are counted apart and never fail a run.</p>\n",
    );
    let denied: Vec<&str> = deny.iter().map(|k| k.as_str()).collect();
    let _ = writeln!(
        s,
        "<p class=\"note\">Denied kinds (fail the run): {}.</p>",
        if denied.is_empty() {
            "none".to_string()
        } else {
            denied.iter().map(|d| format!("<code>{d}</code>")).collect::<Vec<_>>().join(", ")
        }
    );
    if files.len() > 1 {
        s.push_str("<ul>\n");
        for (i, f) in files.iter().enumerate() {
            let _ = writeln!(
                s,
                "<li><a href=\"#f{i}\">{}</a>: {} checked, {} flagged</li>",
                esc(&f.file),
                f.tally.units,
                f.tally.flagged
            );
        }
        s.push_str("</ul>\n");
    }
    for (i, f) in files.iter().enumerate() {
        file_section(&mut s, i, f, deny);
    }
    let _ = write!(
        s,
        "<footer>casteljau {} · lint report · glyphs drawn per file at most {MAX_DRAWN}</footer>\n</main>\n</body>\n</html>\n",
        env!("CARGO_PKG_VERSION")
    );
    s
}

/// Whether a unit gets a drawing: a finding rounding does not explain, or an error.
fn wants_drawing(u: &Unit) -> bool {
    u.error.is_some() || u.findings.iter().any(|f| !f.rounding)
}

fn file_section(s: &mut String, i: usize, f: &FileReport, deny: &[Kind]) {
    let t = &f.tally;
    let _ = writeln!(s, "<section class=\"file\" id=\"f{i}\" data-file=\"{}\">", esc(&f.file));
    let _ = writeln!(s, "<h2>{}</h2>", esc(&f.file));
    let font = f.units.iter().any(Unit::is_font);
    let unit_word = if font { "glyphs" } else { "elements" };
    let sev = |v: Severity| t.by_severity.get(&v).copied().unwrap_or(0);
    let denied_count: usize = t.by_kind.iter().filter(|(k, _)| deny.contains(k)).map(|(_, (n, _))| n).sum();
    let rounding_total: usize = t.by_kind.values().map(|(_, r)| r).sum();
    s.push_str("<div class=\"stats\">\n");
    let stat = |s: &mut String, class: &str, n: usize, what: &str| {
        let _ = writeln!(s, "<div class=\"stat{class}\"><b>{n}</b><span>{what}</span></div>");
    };
    stat(s, "", t.units, &format!("{unit_word} checked"));
    stat(s, if t.flagged > 0 { " warn" } else { "" }, t.flagged, "flagged");
    stat(s, if sev(Severity::Error) > 0 { " bad" } else { "" }, sev(Severity::Error), "errors");
    stat(s, if sev(Severity::Warning) > 0 { " warn" } else { "" }, sev(Severity::Warning), "warnings");
    stat(s, "", sev(Severity::Info), "info");
    stat(s, "", rounding_total, "explained by rounding");
    if t.errors > 0 {
        stat(s, " bad", t.errors, "could not be checked");
    }
    s.push_str("</div>\n");
    let verdict = if t.errors > 0 {
        format!("<span class=\"verdict fail\">{} could not be checked</span>", t.errors)
    } else if denied_count > 0 {
        format!("<span class=\"verdict fail\">fails: {denied_count} denied finding{}</span>", plural(denied_count))
    } else {
        "<span class=\"verdict pass\">passes: no denied finding</span>".to_string()
    };
    let _ = writeln!(s, "<p>{verdict}</p>");

    // the kind table
    let _ = writeln!(s, "<h3 id=\"f{i}-kinds\">Findings by kind</h3>");
    if t.by_kind.is_empty() {
        s.push_str("<p class=\"note\">No findings.</p>\n");
    } else {
        s.push_str(
            "<table class=\"kinds\">\n<tr><th>Kind</th><th>Severity</th><th class=\"n\">Findings</th>\
             <th class=\"n\">Explained by rounding</th><th>Denied</th><th>Meaning</th></tr>\n",
        );
        for (k, (n, r)) in &t.by_kind {
            let name = k.as_str();
            let den = deny.contains(k);
            let _ = writeln!(
                s,
                "<tr class=\"k-{name}\"><td><span class=\"sw\"></span><code>{name}</code></td>\
                 <td><span class=\"sev {sev}\">{sev}</span></td>\
                 <td class=\"n\" data-kind=\"{name}\" data-count=\"{n}\">{n}</td>\
                 <td class=\"n\" data-kind=\"{name}\" data-rounding=\"{r}\">{r}</td>\
                 <td class=\"{yn}\">{yn}</td><td>{}</td></tr>",
                meaning(*k),
                sev = k.severity().as_str(),
                yn = if den { "yes" } else { "no" },
            );
        }
        let total: usize = t.by_kind.values().map(|(n, _)| n).sum();
        let _ = writeln!(
            s,
            "<tr class=\"total\"><td>Total</td><td></td><td class=\"n\">{total}</td><td class=\"n\">{rounding_total}</td>\
             <td></td><td></td></tr>\n</table>"
        );
    }

    // which units are drawn
    let drawable: Vec<bool> = f.units.iter().map(wants_drawing).collect();
    let mut drawn = vec![false; f.units.len()];
    let mut left = MAX_DRAWN;
    for (k, d) in drawable.iter().enumerate() {
        if *d && left > 0 {
            drawn[k] = true;
            left -= 1;
        }
    }
    let wanted = drawable.iter().filter(|d| **d).count();
    let n_drawn = drawn.iter().filter(|d| **d).count();
    let rounding_only = f.units.len() - wanted;

    // the drawn units with an error, first to look at
    let severe: Vec<(usize, &Unit)> = f
        .units
        .iter()
        .enumerate()
        .filter(|(k, u)| {
            drawn[*k] && (u.error.is_some() || u.findings.iter().any(|f| !f.rounding && f.severity == Severity::Error))
        })
        .collect();
    if !severe.is_empty() {
        let _ = write!(s, "<p class=\"jump\"><b>{} with errors:</b> ", capitalised(unit_word));
        let links: Vec<String> = severe
            .iter()
            .take(MAX_JUMPS)
            .map(|(k, u)| format!("<a href=\"#f{i}-u{k}\">{}</a>", esc(&u.label)))
            .collect();
        s.push_str(&links.join(" "));
        if severe.len() > MAX_JUMPS {
            let _ = write!(s, " <span class=\"r\">and {} more</span>", severe.len() - MAX_JUMPS);
        }
        s.push_str("</p>\n");
    }

    // the glyph table
    let _ = writeln!(s, "<h3 id=\"f{i}-glyphs\">{} with findings</h3>", capitalised(unit_word));
    if f.units.is_empty() {
        s.push_str("<p class=\"note\">None.</p>\n");
    } else {
        let kinds: Vec<Kind> = t.by_kind.keys().copied().collect();
        let open = if f.units.len() <= 400 { " open" } else { "" };
        let _ = writeln!(
            s,
            "<details{open}><summary>{} ({} drawn below, {rounding_only} with findings rounding explains only)</summary>",
            counted(f.units.len(), unit_word),
            n_drawn
        );
        s.push_str("<table class=\"glyphs\">\n<tr><th>");
        s.push_str(if font { "Glyph</th><th class=\"n\">ID</th>" } else { "Element</th><th>Tag</th>" });
        for k in &kinds {
            let _ = write!(
                s,
                "<th class=\"k n\"><span class=\"k-{0} sw\"></span>{1}</th>",
                k.as_str(),
                k.as_str().replace('_', " ")
            );
        }
        if t.errors > 0 {
            s.push_str("<th>Error</th>");
        }
        s.push_str("</tr>\n");
        for (k, u) in f.units.iter().enumerate() {
            let quiet = if drawable[k] { "" } else { " class=\"quiet\"" };
            let label = esc(&u.label);
            let name = if drawn[k] {
                format!("<a href=\"#f{i}-u{k}\">{label}</a>")
            } else if drawable[k] {
                format!("{label} <span class=\"r\">(not drawn: over {MAX_DRAWN})</span>")
            } else {
                label
            };
            let id = match (&u.at.glyph_id, &u.at.tag) {
                (Some(g), _) => g.to_string(),
                (None, Some(tag)) => esc(tag),
                _ => String::new(),
            };
            let _ = write!(s, "<tr{quiet}><td>{name}</td><td class=\"{}\">{id}</td>", if font { "n" } else { "" });
            for kind in &kinds {
                let n = u.findings.iter().filter(|f| f.kind() == *kind && !f.rounding).count();
                let r = u.findings.iter().filter(|f| f.kind() == *kind && f.rounding).count();
                s.push_str("<td class=\"n\">");
                if n > 0 {
                    let _ = write!(s, "{n}");
                }
                if r > 0 {
                    let _ = write!(s, " <span class=\"r\">+{r}</span>");
                }
                s.push_str("</td>");
            }
            if t.errors > 0 {
                let _ = write!(s, "<td>{}</td>", if u.error.is_some() { "yes" } else { "" });
            }
            s.push_str("</tr>\n");
        }
        s.push_str("</table>\n<p class=\"note\">Counts of findings not explained by rounding; <span class=\"r\">+n</span>: findings rounding explains.</p>\n</details>\n");
    }

    // the drawings
    let _ = writeln!(s, "<h3>Drawings</h3>");
    let _ = writeln!(
        s,
        "<p class=\"note\">{} drawn: each with a finding not explained by rounding, or an error. \
         {} whose findings rounding explains {} listed above but not drawn; in a drawing, \
         findings rounding explains are listed but not marked.{}</p>",
        counted(n_drawn, unit_word),
        counted(rounding_only, unit_word),
        if rounding_only == 1 { "is" } else { "are" },
        if wanted > n_drawn {
            format!(" {} more not drawn: at most {MAX_DRAWN} drawings per file.", wanted - n_drawn)
        } else {
            String::new()
        }
    );
    if n_drawn > 0 {
        legend(s, font);
    }
    s.push_str("<div class=\"cards\">\n");
    for (k, u) in f.units.iter().enumerate() {
        if drawn[k] {
            card(s, &format!("f{i}-u{k}"), u);
        }
    }
    s.push_str("</div>\n</section>\n");
}

fn plural(n: usize) -> &'static str {
    if n == 1 { "" } else { "s" }
}

/// `n glyphs`, `1 glyph`.
fn counted(n: usize, plural_word: &str) -> String {
    if n == 1 { format!("1 {}", plural_word.trim_end_matches('s')) } else { format!("{n} {plural_word}") }
}

fn capitalised(w: &str) -> String {
    let mut c = w.chars();
    match c.next() {
        Some(f) => f.to_uppercase().chain(c).collect(),
        None => String::new(),
    }
}

/// The key to the drawings.
fn legend(s: &mut String, font: bool) {
    s.push_str("<div class=\"legend\">");
    let item = |s: &mut String, svg: &str, what: &str| {
        let _ = write!(s, "<span><svg width=\"22\" height=\"16\" viewBox=\"0 0 22 16\">{svg}</svg>{what}</span>");
    };
    item(
        s,
        "<path class=\"fill\" d=\"M2 14L11 2L20 14Z\"/><path class=\"ol\" d=\"M2 14L11 2L20 14Z\"/>",
        "outline (nonzero fill)",
    );
    item(s, "<path class=\"on\" d=\"M7.5 4.5h7v7h-7z\"/>", "corner node");
    item(s, "<circle class=\"on\" cx=\"11\" cy=\"8\" r=\"3.6\"/>", "smooth node");
    item(s, "<path class=\"hd\" d=\"M2 12L14 5\"/><circle class=\"off\" cx=\"14\" cy=\"5\" r=\"2.6\"/>", "handle");
    if font {
        item(s, "<circle class=\"imp\" cx=\"11\" cy=\"8\" r=\"2\"/>", "implied on-curve point");
        item(s, "<path class=\"base\" d=\"M0 8H22\"/>", "baseline");
    }
    item(
        s,
        "<g class=\"b k-kink\"><circle cx=\"11\" cy=\"8\" r=\"7\"/><text x=\"11\" y=\"8\" font-size=\"9\">1</text></g>",
        "finding (numbered, coloured by kind)",
    );
    item(
        s,
        "<g class=\"m k-direction\"><path d=\"M2 8H15\"/><path class=\"ah\" d=\"M20 8L13 4.5L13 11.5Z\"/></g>",
        "direction at the contour's start",
    );
    s.push_str("</div>\n");
}

/// Where a finding is, in words.
fn place(f: &Finding) -> String {
    let mut p = vec![];
    if let Some(c) = f.contour {
        p.push(format!("contour {c}"));
    }
    if let Some([a, b]) = f.contours {
        p.push(if a == b { format!("contour {a} (twice)") } else { format!("contours {a} and {b}") });
    }
    if let Some(i) = f.index {
        p.push(format!("segment {i}"));
    }
    if let Some(n) = f.point {
        p.push(format!("point {n}"));
    }
    p.join(" · ")
}

fn code(v: &impl std::fmt::Display) -> String {
    format!("<code>{}</code>", esc(&v.to_string()))
}

/// The exact evidence of a finding as `<dt>`/`<dd>` pairs.
fn evidence(f: &Finding) -> String {
    let mut rows: Vec<(&str, String)> = vec![];
    if !f.at.is_empty() {
        let pts: Vec<String> = f.at.iter().map(|[x, y]| code(&format!("({x}, {y})"))).collect();
        rows.push((if f.at.len() == 1 { "at" } else { "points" }, pts.join("<br>")));
    }
    if !f.parameters.is_empty() {
        let ts: Vec<String> = f.parameters.iter().map(code).collect();
        rows.push(("t", ts.join(", ")));
    }
    let four =
        |v: &[ExactValue]| code(&format!("[{}]", v.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", ")));
    match &f.evidence {
        Evidence::Direction { area, depth, expected } => {
            rows.push(("signed area", code(area)));
            rows.push(("depth", depth.to_string()));
            let expected = if *expected == Orientation::Cw { "clockwise" } else { "counter-clockwise" };
            rows.push(("expected", expected.into()));
        }
        Evidence::MissingExtremum { axis, extent } => {
            let tangent = match axis {
                Axis::X => "vertical (x extreme)",
                Axis::Y => "horizontal (y extreme)",
            };
            rows.push(("tangent", tangent.into()));
            rows.push(("extent", code(extent)));
        }
        Evidence::Kink { turn_degrees_float } => rows.push(("turn", format!("≈ {turn_degrees_float:.3}°"))),
        Evidence::OverlappingSegments { shared } => {
            for sh in shared {
                rows.push((
                    "shared",
                    format!(
                        "contour {} segment {}, t from {} to {}",
                        sh.contour,
                        sh.segment,
                        code(&sh.from),
                        code(&sh.to)
                    ),
                ));
            }
        }
        Evidence::Bbox { stored, computed } => {
            rows.push(("stored box", four(&stored[..])));
            rows.push(("exact box", four(&computed[..])));
        }
        Evidence::SelfIntersection
        | Evidence::Overlap
        | Evidence::Touching
        | Evidence::CollinearPoints
        | Evidence::ZeroLengthSegment
        | Evidence::ZeroLengthHandle
        | Evidence::DegenerateCurve
        | Evidence::Cusp
        | Evidence::Loop => {}
    }
    if rows.is_empty() {
        return String::new();
    }
    let mut s = String::from("<dl class=\"ev\">");
    for (k, v) in rows {
        let _ = write!(s, "<dt>{k}</dt><dd>{v}</dd>");
    }
    s.push_str("</dl>");
    s
}

/// A finding rounding explains, on one line (its message carries the exact values).
fn rounding_item(s: &mut String, f: &Finding) {
    let k = f.kind().as_str();
    let _ = writeln!(
        s,
        "<li class=\"k-{k}\"><span class=\"kind\">{k}</span><span class=\"loc\">{}</span> <span class=\"r\">{}</span></li>",
        place(f),
        esc(&f.message)
    );
}

pub(crate) fn finding_item(s: &mut String, n: usize, f: &Finding) {
    let k = f.kind().as_str();
    let num = format!("<span class=\"num\">{n}</span>");
    let sev = f.severity.as_str();
    let _ = writeln!(
        s,
        "<li class=\"k-{k}\">{num}<span class=\"kind\">{k}</span> <span class=\"sev {sev}\">{sev}</span><span class=\"loc\">{}</span>\
         <div class=\"msg\">{}</div>{}</li>",
        place(f),
        esc(&f.message),
        evidence(f)
    );
}

fn card(s: &mut String, id: &str, u: &Unit) {
    let mut attrs = String::new();
    if let Some(g) = u.at.glyph_id {
        let _ = write!(attrs, " data-glyph-id=\"{g}\"");
    }
    if let Some(face) = u.at.face {
        let _ = write!(attrs, " data-face=\"{face}\"");
    }
    match &u.at.element {
        Some(Element::Id(e)) => {
            let _ = write!(attrs, " data-element=\"{}\"", esc(e));
        }
        Some(Element::Index(i)) => {
            let _ = write!(attrs, " data-element=\"{i}\"");
        }
        None => {}
    }
    let _ = writeln!(s, "<article class=\"card\" id=\"{id}\"{attrs}>");
    let mut meta = vec![];
    if let Some(g) = u.at.glyph_id {
        meta.push(format!("glyph id {g}"));
    }
    if let Some(face) = u.at.face {
        meta.push(format!("face {face}"));
    }
    if let Some(tag) = &u.at.tag {
        meta.push(format!("&lt;{}&gt;", esc(tag)));
    }
    let real: Vec<&Finding> = u.findings.iter().filter(|f| !f.rounding).collect();
    let rounding: Vec<&Finding> = u.findings.iter().filter(|f| f.rounding).collect();
    let mut by_sev = vec![];
    for sev in [Severity::Error, Severity::Warning, Severity::Info] {
        let n = real.iter().filter(|f| f.severity == sev).count();
        if n > 0 {
            by_sev.push(format!("{n} {}{}", sev.as_str(), plural(n)));
        }
    }
    if !rounding.is_empty() {
        by_sev.push(format!("{} explained by rounding", rounding.len()));
    }
    meta.extend(by_sev);
    let _ = writeln!(
        s,
        "<header><h4><a href=\"#{id}\">{}</a></h4><span class=\"meta\">{}</span></header>",
        esc(&u.label),
        meta.join(" · ")
    );
    if let Some(e) = &u.error {
        let _ = writeln!(s, "<p class=\"err\">Could not be checked: {}</p>", esc(e));
    }
    s.push_str("<div class=\"body\">\n");
    let marked: Vec<(usize, &Finding)> = real.iter().enumerate().map(|(k, f)| (k + 1, *f)).collect();
    if let Some(svg) = drawing(u, &marked) {
        s.push_str(&svg);
        s.push('\n');
    }
    s.push_str("<ol class=\"findings\">\n");
    for (n, f) in &marked {
        finding_item(s, *n, f);
    }
    s.push_str("</ol>\n</div>\n");
    if !rounding.is_empty() {
        let _ = writeln!(
            s,
            "<details><summary>{} finding{} explained by rounding (not marked)</summary><ol class=\"findings rounding\">",
            rounding.len(),
            plural(rounding.len())
        );
        for f in rounding {
            rounding_item(s, f);
        }
        s.push_str("</ol></details>\n");
    }
    s.push_str("</article>\n");
}
