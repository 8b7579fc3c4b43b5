//! The results of `casteljau lint` per glyph and per file, as the text and JSON output, the
//! summary and the `--html` report read them.

use casteljau::format::Source;
use casteljau::lint::{Finding, Glyph, Kind, Severity};
use std::collections::BTreeMap;

/// The findings of one glyph or element, with what the report draws.
pub struct Unit {
    /// Where it is (file, face, glyph, glyph id, or element and tag).
    pub at: Source<'static>,
    /// A label for people: the glyph name (or `gid N`), or the element.
    pub label: String,
    /// Its outline, as read.
    pub glyph: Glyph,
    /// Its findings (after `--only`/`--ignore`).
    pub findings: Vec<Finding>,
    /// Why it could not be checked.
    pub error: Option<String>,
    /// Why it was not checked: an SVG element that is no Bézier outline (a circle, an
    /// ellipse), as `scan` skips it.
    pub skipped: Option<String>,
}

/// Counts of one file.
#[derive(Default)]
pub struct Tally {
    /// Glyphs (elements) checked.
    pub units: usize,
    /// Glyphs with at least one finding not explained by rounding.
    pub flagged: usize,
    /// Per kind: (findings not explained by rounding, findings rounding explains).
    pub by_kind: BTreeMap<Kind, (usize, usize)>,
    /// Per severity, findings not explained by rounding.
    pub by_severity: BTreeMap<Severity, usize>,
    /// Glyphs that could not be checked.
    pub errors: usize,
    /// SVG elements skipped (no Bézier outline).
    pub skipped: usize,
}

impl Tally {
    pub fn add(&mut self, u: &Unit) {
        if u.skipped.is_some() {
            self.skipped += 1;
            return;
        }
        self.units += 1;
        if u.error.is_some() {
            self.errors += 1;
        }
        if u.findings.iter().any(|f| !f.rounding) {
            self.flagged += 1;
        }
        for f in &u.findings {
            let e = self.by_kind.entry(f.kind()).or_default();
            if f.rounding {
                e.1 += 1;
            } else {
                e.0 += 1;
                *self.by_severity.entry(f.severity).or_default() += 1;
            }
        }
    }
}

/// One file's results, for the report.
pub struct FileReport {
    /// The file as named.
    pub file: String,
    /// Its counts.
    pub tally: Tally,
    /// The glyphs (elements) with a finding or an error, in order.
    pub units: Vec<Unit>,
}

impl Unit {
    /// A font glyph (its drawing has the y axis up), not an SVG element.
    pub fn is_font(&self) -> bool {
        self.at.glyph_id.is_some()
    }
}
