//! Overlap removal that writes the font: each glyph's nonzero region, decided exactly, written
//! back on the font's integer grid with the rounding re-decided exactly (certified), and the
//! font file rewritten with every other glyph byte-identical.
//!
//! Two halves meet at [`GlyphInput`] / [`GlyphDecision`]:
//!
//! * [`decide_glyph`] (`glyph.rs`, `round.rs`): per glyph, whether it needs rewriting (overlap,
//!   self-intersection, shared boundary piece, wrong direction; composite components whose
//!   regions overlap or share pieces) and, if so, the certified integer outline and its report.
//! * [`write_font`] (`glyf.rs`, `cff.rs`): the font file rewritten from the decisions
//!   (TrueType `glyf`/`loca`/`hmtx`/`head`/`maxp`; CFF charstrings), everything else copied.
//!
//! The per-glyph half, file by file: `screen` (the cheap exact decision for glyphs whose
//! contours meet nowhere), `glyph` (the decision, the rewrite and the repair search), `region`
//! (the exact non-zero region as contours of input pieces), `round` (the rounding plan and the
//! written contours), `distance` (enclosures, grid candidates and the bound), `certify` (the
//! exact re-decision of the written outline).

mod certify;
mod distance;
mod glyph;
mod region;
mod round;
mod screen;

mod cff;
mod glyf;
mod sfnt;

use crate::error::{Error, Result};
use crate::format::{Contour, Font};
use crate::shape::Orientation;
use crate::work::Budget;
use num_rational::BigRational;
use serde::Serialize;
use std::collections::BTreeMap;

/// The curves a font stores: TrueType quadratics or CFF cubics.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Flavour {
    /// `glyf`: lines and quadratic segments (one off-curve point between on-curve points).
    Quadratic,
    /// CFF: lines and cubic segments (two off-curve points between on-curve points).
    Cubic,
}

/// A point of an output contour, on the integer grid.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct GridPoint {
    /// x, in font units.
    pub x: i32,
    /// y, in font units.
    pub y: i32,
    /// On-curve (`true`) or a control point.
    pub on_curve: bool,
}

/// An output contour: its points in drawing order, closed, as a font stores them (TrueType:
/// two consecutive control points imply the on-curve point at their exact midpoint, kept only
/// where the certified outline has it there; CFF: two control points per cubic). The first
/// point is on-curve.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct GridContour {
    /// The points.
    pub points: Vec<GridPoint>,
}

/// What one glyph looks like to [`decide_glyph`].
#[derive(Clone, Debug)]
pub struct GlyphInput {
    /// The glyph id.
    pub glyph_id: u32,
    /// The glyph name (or fontTools' derived name).
    pub name: Option<String>,
    /// The outline, one entry per component (a simple glyph has one entry), each component's
    /// contours already transformed into glyph space, exactly.
    pub components: Vec<Vec<Contour>>,
    /// The font's curves.
    pub flavour: Flavour,
    /// The font's direction of outer contours (glyf: clockwise, CFF: counter-clockwise).
    pub orientation: Orientation,
}

/// A repair the rounding needed, reported per glyph.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Repair {
    /// An off-curve point moved to a neighbouring grid point.
    MovedControl {
        /// The contour (output numbering).
        contour: usize,
        /// The point within it.
        point: usize,
    },
    /// A meeting point (on-curve) written at a neighbouring grid point of its nearest one.
    MovedVertex {
        /// The contour (output numbering) where it is first written.
        contour: usize,
        /// The point within it.
        point: usize,
    },
    /// A curve of the exact region that no grid candidate within one unit keeps curved,
    /// written as the line between its rounded ends (it lies within `distance_bound` of that
    /// line). A TrueType curve whose end is an implied point keeps its control points, in order
    /// on that line. `point` is the line's start.
    Straightened {
        /// The contour (output numbering).
        contour: usize,
        /// Its first control point within it.
        point: usize,
    },
    /// A contour whose exact area rounding must collapse was dropped.
    DroppedSliver {
        /// Its exact signed area (string when serialized); where that is irrational, the
        /// multiple of 10⁻⁶ next beyond it, away from zero.
        #[serde(serialize_with = "crate::num::serial::string")]
        area: BigRational,
    },
}

impl std::fmt::Display for Repair {
    /// One line per repair, as the command line's text output and HTML report print it.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Repair::MovedControl { contour, point } => write!(f, "control point {point} of contour {contour} moved"),
            Repair::MovedVertex { contour, point } => write!(f, "on-curve point {point} of contour {contour} moved"),
            Repair::Straightened { contour, point } => {
                write!(f, "curve at point {point} of contour {contour} straightened")
            }
            Repair::DroppedSliver { area } => write!(f, "sliver of exact area {area} dropped"),
        }
    }
}

/// The certificate of a rewritten glyph. JSON fields: `glyph`, `glyph_id`, `contours_before`,
/// `contours_after`, `points_before`, `points_after`, `distance_bound` (exact string),
/// `distance_bound_float`, `repairs`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct GlyphReport {
    /// The glyph name.
    pub glyph: Option<String>,
    /// The glyph id.
    pub glyph_id: u32,
    /// Contours before.
    pub contours_before: usize,
    /// Contours after.
    pub contours_after: usize,
    /// Points before (on- and off-curve, as stored).
    pub points_before: usize,
    /// Points after.
    pub points_after: usize,
    /// A proved upper bound on the distance between the written outline and the exact boundary.
    #[serde(serialize_with = "crate::num::serial::string")]
    pub distance_bound: BigRational,
    /// `distance_bound`, rounded.
    pub distance_bound_float: f64,
    /// What the rounding needed.
    pub repairs: Vec<Repair>,
}

/// What [`decide_glyph`] decided.
#[derive(Clone, Debug, PartialEq)]
pub enum GlyphDecision {
    /// Nothing to remove: the glyph stays byte-identical.
    Unchanged,
    /// The certified outline to write.
    Rewritten {
        /// The contours, on the grid.
        contours: Vec<GridContour>,
        /// Its certificate.
        report: GlyphReport,
    },
    /// It needs rewriting but could not be certified: left unchanged and reported.
    Uncertified {
        /// Why, in words.
        reason: String,
    },
}

/// Decides one glyph: whether it needs rewriting and, if so, its certified grid outline.
///
/// * **Whether.** A simple glyph (one component) is rewritten when [`crate::lint`] finds an
///   `overlap`, a `self_intersection`, `overlapping_segments` or a `direction` finding; a
///   composite (several components) only when two components' regions overlap or share a
///   boundary piece (decided on their exact arrangement). Contours or components that only
///   touch at points are no reason, and one-point contours (anchors) are kept as they are.
///   Glyphs whose contours meet nowhere are decided without an arrangement (an exact screen on
///   small integers), so most glyphs of a font cost little.
/// * **What.** The non-zero region of all the glyph's contours, exactly, in
///   `input.orientation`: every piece of its boundary is an input segment or an exact
///   sub-segment of one, of the same degree (a quadratic raised exactly to a cubic for
///   [`Flavour::Cubic`]); a contour that touches itself (a pinch) is split there into contours
///   meeting at the point; a contour that passes an input contour's start point starts there,
///   and contours keep the input's order.
/// * **The rounding, certified.** Meeting points are rounded to the nearest grid point (exact
///   comparisons of the algebraic coordinates with the half-integers), control points of cut
///   pieces from rational enclosures of their blossom values; TrueType's implied on-curve
///   points stay implied where they are still midpoints. The written outline is then decided
///   again, exactly: the same contours with the same nesting and orientations, no curve
///   collapsed, no `overlap`, `self_intersection`, `overlapping_segments`,
///   `zero_length_segment` or `direction` finding. Where that fails, the repairs (reported in
///   [`GlyphReport::repairs`]) choose other grid points within one unit for the meeting and
///   control points near the failure, or drop a contour whose rounding bounds no area.
/// * **The bound.** `distance_bound` is a rational `≥ max |Q_i − P_i|` over every written
///   control point `Q_i` and its exact counterpart `P_i` (an upper bound of the Euclidean
///   distance, through a rational square root taken upwards): each written piece is the same
///   degree as its exact piece, so `|Q(s) − P(s)| ≤ max |Q_i − P_i|` at every parameter `s`,
///   and every point farther than the bound from the exact boundary is inside the written
///   glyph exactly when it is inside the exact region. It is at most 1.
///
/// A glyph that needs rewriting but whose rounding cannot be certified is
/// [`GlyphDecision::Uncertified`] with the reason (so is one whose exact arrangement is refused,
/// e.g. two curves leaving a cusp tangentially); it is never [`GlyphDecision::Rewritten`].
///
/// # Errors
/// [`Error::WorkLimit`] when the glyph's work exceeds `budget` (the caller reports it as an
/// uncertified glyph left unchanged): the glyph's arrangement, its certification (as many
/// repair attempts as the budget holds, at most 32); the errors of [`crate::lint::lint`] for a
/// segment of degree above 3.
///
/// # Example
/// ```
/// use casteljau::format::parse_path;
/// use casteljau::num::NumberMode;
/// use casteljau::overlaps::{decide_glyph, Flavour, GlyphDecision, GlyphInput};
/// use casteljau::shape::Orientation;
/// use casteljau::work::Budget;
/// // two overlapping squares of a TrueType glyph (outer contours clockwise)
/// let contours = parse_path("M0 0 V10 H10 V0 Z M5 5 V15 H15 V5 Z", NumberMode::Exact).unwrap();
/// let input = GlyphInput {
///     glyph_id: 7,
///     name: Some("overlap".into()),
///     components: vec![contours],
///     flavour: Flavour::Quadratic,
///     orientation: Orientation::Cw,
/// };
/// let GlyphDecision::Rewritten { contours, report } = decide_glyph(&input, &Budget::unlimited()).unwrap() else {
///     panic!("an overlap is rewritten")
/// };
/// let points: Vec<(i32, i32)> = contours[0].points.iter().map(|p| (p.x, p.y)).collect();
/// assert_eq!(points, [(0, 0), (0, 10), (5, 10), (5, 15), (15, 15), (15, 5), (10, 5), (10, 0)]);
/// assert_eq!((report.contours_before, report.contours_after), (2, 1));
/// assert_eq!(report.distance_bound.to_string(), "0"); // every meeting point is on the grid
/// // a square with its hole is already right: unchanged
/// let framed = parse_path("M0 0 V10 H10 V0 Z M2 2 H8 V8 H2 Z", NumberMode::Exact).unwrap();
/// let input = GlyphInput { components: vec![framed], ..input };
/// assert_eq!(decide_glyph(&input, &Budget::unlimited()).unwrap(), GlyphDecision::Unchanged);
/// ```
pub fn decide_glyph(input: &GlyphInput, budget: &Budget) -> Result<GlyphDecision> {
    glyph::decide(input, budget)
}

/// The font writer's options (fontTools' `removeOverlaps` options where they make sense).
#[derive(Clone, Debug, Default)]
pub struct WriteOptions {
    /// Keep TrueType instructions of unchanged glyphs (`--keep-hinting`).
    pub keep_hinting: bool,
    /// Only these glyphs (all when `None`).
    pub glyphs: Option<Vec<u32>>,
}

/// The written font and what happened to each glyph considered.
#[derive(Clone, Debug)]
pub struct FontOutcome {
    /// The new font file.
    pub data: Vec<u8>,
    /// Per glyph considered, in glyph order: its id and decision. An `Err` is a glyph whose
    /// outline could not be read, or whose decided outline could not be written (a coordinate
    /// beyond the format's range, points in an order the format cannot store); an error of
    /// `decide` (such as [`Error::WorkLimit`]) is an [`GlyphDecision::Uncertified`] glyph
    /// with the error's message. Either way the glyph is left unchanged.
    pub glyphs: Vec<(u32, Result<GlyphDecision>)>,
}

/// What the table writers need: the outlines to write and whose instructions or hints go.
pub(crate) struct Written {
    /// The glyphs rewritten: their contours (one-point contours of the original appended).
    changed: BTreeMap<u32, Vec<GridContour>>,
    /// The glyphs considered (`None`: all).
    considered: Option<std::collections::BTreeSet<u32>>,
    /// Keep the instructions (hints) of the glyphs not rewritten.
    keep_hinting: bool,
}

impl Written {
    /// Whether a glyph that is not rewritten loses its TrueType instructions.
    fn strip_instructions(&self, gid: u32) -> bool {
        !self.keep_hinting && self.considered.as_ref().is_none_or(|c| c.contains(&gid))
    }
}

/// Whether the points of a decided contour can be stored in the font's format: the first
/// point on-curve; TrueType: any run of control points (implied on-curve midpoints); CFF:
/// exactly two. A contour of one point is an anchor.
fn storable(c: &GridContour, flavour: Flavour) -> std::result::Result<(), String> {
    let Some(first) = c.points.first() else { return Ok(()) };
    if !first.on_curve {
        return Err("a contour starts with a control point".into());
    }
    let mut run = 0;
    for p in c.points.iter().skip(1).chain(std::iter::once(first)) {
        if p.on_curve {
            let ok = match flavour {
                // consecutive control points imply the on-curve point between them (TrueType)
                Flavour::Quadratic => true,
                Flavour::Cubic => run == 0 || run == 2,
            };
            if !ok {
                return Err(format!("{run} control points between two on-curve points"));
            }
            run = 0;
        } else {
            run += 1;
        }
    }
    Ok(())
}

/// Rewrites a font from per-glyph decisions (`decide`, normally [`decide_glyph`] with a
/// budget per glyph), on all cores (rayon's current pool): changed glyphs get their certified
/// outlines, every other glyph stays byte-identical, its instructions aside.
///
/// * TrueType (`glyf`): see the `glyf` writer — glyph records copied from their `loca` ranges,
///   rewritten glyphs encoded as simple glyphs without instructions (a composite that is
///   rewritten becomes a simple glyph), the instructions of the other glyphs considered
///   removed unless [`WriteOptions::keep_hinting`] (fontTools' `removeHinting`), `loca`,
///   `head` (box, `indexToLocFormat`, flags bit 1), `hmtx` (a rewritten glyph's left side
///   bearing is its `xMin`), `hhea` and `maxp` recomputed as fontTools does on saving.
/// * CFF (`CFF `): see the CFF writer — when a glyph is rewritten, its charstring is
///   replaced (same width), every charstring is desubroutinized (no subroutine is left) and,
///   unless `keep_hinting`, loses its hints.
/// * Every other table is copied; the table directory, table checksums and
///   `head.checkSumAdjustment` are computed anew. `head.modified` is kept, so the same input
///   and decisions give the same bytes.
///
/// One-point contours of a rewritten glyph (anchors) are kept: appended after its decided
/// contours unless the decision already has contours of one point.
///
/// # Errors
/// [`Error::InvalidArgument`] for data that is not a single OpenType font (collections, WOFF),
/// variable fonts (`fvar`) and CFF2 (refused naming the table: instantiate first, then remove
/// overlaps), a glyph id beyond the font, or tables too malformed to rewrite (naming the
/// table or glyph).
///
/// # Example
/// ```
/// use casteljau::overlaps::{GlyphDecision, WriteOptions, write_font};
/// let data = include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/fonts/Tuffy.ttf"));
/// let options = WriteOptions { keep_hinting: true, glyphs: Some(vec![36]) };
/// let out = write_font(data, &options, &|_| Ok(GlyphDecision::Unchanged)).unwrap();
/// assert_eq!(out.glyphs.len(), 1);
/// // nothing rewritten: the same outlines, every table but head, hhea, maxp, loca, glyf the same
/// let font = casteljau::format::Font::open(&out.data, 0).unwrap();
/// assert_eq!(font.num_glyphs(), 1502);
/// ```
pub fn write_font(
    data: &[u8],
    options: &WriteOptions,
    decide: &(dyn Fn(&GlyphInput) -> Result<GlyphDecision> + Sync),
) -> Result<FontOutcome> {
    use rayon::prelude::*;
    let tables = sfnt::Tables::read(data)?;
    if tables.get(b"fvar").is_some() {
        return Err(Error::InvalidArgument {
            message: "a variable font (fvar table): instantiate it first (a static instance, e.g. with \
                      fontTools' instancer), then remove overlaps"
                .into(),
        });
    }
    if tables.get(b"CFF2").is_some() {
        return Err(Error::InvalidArgument {
            message: "a CFF2 table: only static TrueType (glyf) and CFF fonts are written".into(),
        });
    }
    let cff = tables.get(b"glyf").is_none();
    if cff && tables.get(b"CFF ").is_none() {
        return Err(Error::InvalidArgument { message: "no glyf or CFF table: no outlines to rewrite".into() });
    }
    let font = Font::open(data, 0)?;
    let n = font.num_glyphs();
    let gids: Vec<u32> = match &options.glyphs {
        None => (0..n).collect(),
        Some(g) => {
            if let Some(bad) = g.iter().find(|&&g| g >= n) {
                return Err(Error::InvalidArgument { message: format!("glyph {bad}: the font has {n} glyphs") });
            }
            let set: std::collections::BTreeSet<u32> = g.iter().copied().collect();
            set.into_iter().collect()
        }
    };
    let flavour = if font.is_cff() { Flavour::Cubic } else { Flavour::Quadratic };
    let orientation = font.outer_orientation();
    type Decided = (u32, Result<GlyphDecision>, Vec<crate::num::Point<BigRational>>);
    let decided: Vec<Decided> = gids
        .par_iter()
        .map(|&gid| {
            let (components, lone) = match font.outline_parts(gid) {
                Ok(parts) => parts,
                Err(e) => return (gid, Err(e), vec![]),
            };
            if components.len() == 1 && font.is_composite(gid) {
                // one component: nothing of its own overlaps; its glyph's own rewrite reaches it
                // through the reference (fontTools decomposes only composites whose components
                // overlap)
                return (gid, Ok(GlyphDecision::Unchanged), lone);
            }
            let input = GlyphInput { glyph_id: gid, name: font.glyph_name(gid), components, flavour, orientation };
            let decision = decide(&input).unwrap_or_else(|e| GlyphDecision::Uncertified { reason: e.to_string() });
            if let GlyphDecision::Rewritten { contours, .. } = &decision {
                // the outline must fit the format: checked by encoding it once
                let fits = match contours.iter().find_map(|c| storable(c, flavour).err()) {
                    Some(e) => Err(e),
                    None if flavour == Flavour::Quadratic => {
                        glyf::encode_simple(contours, gid).map(|_| ()).map_err(|e| e.to_string())
                    }
                    None => cff::encode_charstring(None, contours, gid).map(|_| ()).map_err(|e| e.to_string()),
                };
                if let Err(e) = fits {
                    let message = format!("glyph {gid}: the decided outline cannot be written: {e}");
                    return (gid, Err(Error::InvalidArgument { message }), vec![]);
                }
            }
            (gid, Ok(decision), lone)
        })
        .collect();
    let mut changed = BTreeMap::new();
    for (gid, d, lone) in &decided {
        if let Ok(GlyphDecision::Rewritten { contours, .. }) = d {
            let mut all = contours.clone();
            if !contours.iter().any(|c| c.points.len() == 1) {
                all.extend(lone.iter().map(|p| GridContour { points: vec![grid_point(p)] }));
            }
            changed.insert(*gid, all);
        }
    }
    let written = Written {
        changed,
        considered: options.glyphs.as_ref().map(|_| gids.iter().copied().collect()),
        keep_hinting: options.keep_hinting,
    };
    let data =
        if cff { cff::write(&tables, n as usize, &written)? } else { glyf::write(&tables, n as usize, &written)? };
    Ok(FontOutcome { data, glyphs: decided.into_iter().map(|(g, d, _)| (g, d)).collect() })
}

/// A one-point contour's point on the grid: its coordinates rounded half up (they are integers
/// except in a scaled component).
fn grid_point(p: &crate::num::Point<BigRational>) -> GridPoint {
    let half = BigRational::new(1.into(), 2.into());
    let round = |v: &BigRational| {
        let r = (v + &half).floor().to_integer();
        i32::try_from(r).unwrap_or(0)
    };
    GridPoint { x: round(&p.coords[0]), y: round(&p.coords[1]), on_curve: true }
}
