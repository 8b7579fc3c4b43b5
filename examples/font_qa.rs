//! Font QA: lint every glyph of a font exactly and print the findings grouped by kind.
//!
//! ```sh
//! cargo run --example font_qa -- tests/data/fonts/Tuffy.ttf
//! ```
//!
//! Any TrueType, CFF or CFF2 font (Tuffy when no path is given). Every finding is decided exactly
//! on the coordinates the font stores; those that rounding to the font's integer grid explains
//! are counted apart, as `casteljau lint` does. The command line has more (choosing kinds, JSON,
//! an HTML report): see `docs/lint.md`.

use casteljau::format::Font;
use casteljau::lint::{Glyph, LintOptions, lint};
use casteljau::rat;
use std::collections::BTreeMap;

/// Findings of one kind: a line per finding not explained by rounding, and how many are.
#[derive(Default)]
struct Group {
    severity: &'static str,
    lines: Vec<String>,
    explained_by_rounding: usize,
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = std::env::args().nth(1).unwrap_or_else(|| "tests/data/fonts/Tuffy.ttf".into());
    let data = std::fs::read(&path)?;
    let font = Font::open(&data, 0)?;
    // outer contours run clockwise in TrueType outlines, counter-clockwise in CFF
    let options = LintOptions::new(font.outer_orientation());
    let exact_box = |b: [i16; 4]| b.map(|x| rat(x.into()));

    let mut groups: BTreeMap<&str, Group> = BTreeMap::new();
    for gid in 0..font.num_glyphs() {
        let outline = font.outline_numbered(gid)?;
        let empty = outline.contours.iter().all(|c| c.segments.is_empty());
        let glyph = Glyph {
            // the boxes the font stores, checked against the exact outline
            stored_box: if empty { None } else { font.stored_glyph_box(gid).map(exact_box) },
            font_box: font.head_box().map(exact_box),
            contours: outline.contours,
            numbers: outline.numbers,
            lone_points: outline.lone_points,
        };
        let name = font.glyph_name(gid).unwrap_or_else(|| format!("#{gid}"));
        for finding in lint(&glyph, &options)? {
            let group = groups.entry(finding.kind().as_str()).or_default();
            group.severity = finding.severity.as_str();
            if finding.rounding {
                group.explained_by_rounding += 1;
            } else {
                group.lines.push(format!("{name}: {}", finding.message));
            }
        }
    }

    println!("{path}: {} glyphs", font.num_glyphs());
    for (kind, group) in &groups {
        println!(
            "\n{kind} ({}): {} findings, {} more explained by rounding",
            group.severity,
            group.lines.len(),
            group.explained_by_rounding
        );
        for line in group.lines.iter().take(3) {
            println!("  {line}");
        }
        if group.lines.len() > 3 {
            println!("  … and {} more", group.lines.len() - 3);
        }
    }
    Ok(())
}
