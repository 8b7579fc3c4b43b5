//! Glyph outlines of TrueType (`glyf`) and CFF/CFF2 fonts (`.ttf`, `.otf`, `.ttc`, `.otc`),
//! read from the font's raw tables with `read-fonts`, with the font's exact values:
//!
//! * `glyf`: the `i16` point coordinates; an implied on-curve point between two off-curve
//!   points is their exact midpoint; composite glyphs apply their component transforms exactly
//!   (`F2Dot14` entries are `k/16384`), with point-matching anchors and the scaled/unscaled
//!   offset flags of the OpenType specification. Quadratic segments and lines. Where a
//!   component is scaled by a 2×2 matrix the exact products are usually not integers:
//!   FreeType and `skrifa` round each transformed point to an integer font unit, `ttf-parser`
//!   keeps an `f32`; casteljau keeps the exact rational (the tests compare with `skrifa`:
//!   equal on every other glyph of the test font, within one unit on the scaled ones).
//! * CFF and CFF2: the Type 2 charstring is evaluated by `read-fonts` in the format's own
//!   16.16 fixed-point arithmetic, and each coordinate it emits is taken as the exact rational
//!   `bits/65536`. Cubic segments and lines.
//!
//! Variable fonts: the default instance, or an instance of a **CFF2** font
//! ([`Font::set_variation`], `--variation wght=700`): user coordinates are normalized by the
//! OpenType rules (`fvar`, `avar`) into `F2Dot14` and the charstring's `blend` operators are
//! evaluated in 16.16 by `read-fonts`, so the instance's coordinates are exactly the 16.16 values
//! of the format's own arithmetic, not the real-number interpolation, whose scalars the format
//! rounds (the tests compare with FreeType's unscaled instances, which FreeType rounds to integer
//! font units: within one unit everywhere, equal at the default instance). Instances of `glyf` fonts
//! (`gvar` deltas with their interpolation of untouched points) are refused: no crate applies them
//! without `f32`. Font pens that hand out `f32` are not used at all.
//!
//! Every contour is closed: its closing line is listed when it has non-zero length.
//!
//! # Example
//! ```no_run
//! use casteljau::format::Font;
//! let data = std::fs::read("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf").unwrap();
//! let font = Font::open(&data, 0).unwrap();
//! let gid = (0..font.num_glyphs()).find(|&g| font.glyph_name(g).as_deref() == Some("a")).unwrap();
//! let contours = font.outline(gid).unwrap();
//! assert_eq!(contours.len(), 2);
//! ```

use crate::error::{Error, Result};
use crate::format::{Affine, Contour, Segment};
use crate::num::point::Point;
use crate::num::scalar::rat;
use num_rational::BigRational;
use read_fonts::tables::glyf::{Anchor, CompositeGlyphFlags, Glyf, Glyph};
use read_fonts::tables::loca::Loca;
use read_fonts::tables::post::Post;
use read_fonts::types::{F2Dot14, Fixed, GlyphId, GlyphId16, Tag};
use read_fonts::{FileRef, FontRef, TableProvider};

/// Deepest nesting of composite glyphs followed (the OpenType `maxp.maxComponentDepth` is
/// usually ≤ 3).
pub const MAX_COMPONENT_DEPTH: usize = 16;

/// Most points and component references of one glyph after composition (a composite that
/// uses a glyph twice counts that glyph's points twice): counted from the glyph headers, with
/// memoisation per glyph id, before any point is composed.
pub const MAX_GLYPH_POINTS: usize = 100_000;

/// Most `(code point, glyph)` pairs read from one `cmap` subtable for glyph names (a valid
/// subtable has at most one per code point, 0x110000).
const MAX_CMAP_PAIRS: usize = 0x11_0000;

type P = Point<BigRational>;

fn fail(message: String) -> Error {
    Error::InvalidArgument { message }
}

enum Outlines<'a> {
    Glyf { glyf: Glyf<'a>, loca: Loca<'a> },
    Cff(read_fonts::ps::cff::CffFontRef<'a>),
}

/// One font of a font file, ready to give exact glyph outlines.
pub struct Font<'a> {
    font: FontRef<'a>,
    outlines: Outlines<'a>,
    num_glyphs: u32,
    post: Option<Post<'a>>,
    /// Normalized variation coordinates (empty: the default instance).
    coords: Vec<F2Dot14>,
    /// The names derived from `cmap` for a font that stores none, made on first use.
    derived_names: std::sync::OnceLock<Vec<String>>,
}

impl<'a> Font<'a> {
    /// The number of fonts in a font file (1 for `.ttf`/`.otf`, the count of a collection): the
    /// faces [`Font::open`] takes.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] when the data is not an OpenType font or collection.
    pub fn count(data: &[u8]) -> Result<u32> {
        match FileRef::new(data).map_err(|e| fail(format!("not a font file: {e}")))? {
            FileRef::Font(_) => Ok(1),
            FileRef::Collection(c) => Ok(c.len()),
        }
    }

    /// The font at `index` of a font file (0 for a single font).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] when the data is not a font, the index is out of range, or the
    /// font has neither `glyf` nor `CFF `/`CFF2` outlines.
    pub fn open(data: &'a [u8], index: u32) -> Result<Self> {
        let font = FontRef::from_index(data, index).map_err(|e| fail(format!("font {index}: {e}")))?;
        let num_glyphs = font.maxp().map_err(|e| fail(format!("font {index}: maxp: {e}")))?.num_glyphs() as u32;
        let upem = font.head().ok().map(|h| h.units_per_em() as i32);
        let outlines = if let (Ok(glyf), Ok(loca)) = (font.glyf(), font.loca(None)) {
            Outlines::Glyf { glyf, loca }
        } else {
            let table = font
                .table_data(Tag::new(b"CFF "))
                .or_else(|| font.table_data(Tag::new(b"CFF2")))
                .ok_or_else(|| fail(format!("font {index}: no glyf or CFF outlines")))?;
            let cff = read_fonts::ps::cff::CffFontRef::new(table.as_bytes(), 0, upem)
                .map_err(|e| fail(format!("font {index}: CFF: {e}")))?;
            Outlines::Cff(cff)
        };
        let post = font.post().ok();
        Ok(Font { font, outlines, num_glyphs, post, coords: vec![], derived_names: std::sync::OnceLock::new() })
    }

    /// The variation axes: `(tag, min, default, max)` in user units (`fvar`); empty for a font
    /// that is not variable.
    pub fn axes(&self) -> Vec<(String, f64, f64, f64)> {
        let Ok(fvar) = self.font.fvar() else { return vec![] };
        fvar.axes()
            .unwrap_or_default()
            .iter()
            .map(|a| {
                (a.axis_tag().to_string(), a.min_value().to_f64(), a.default_value().to_f64(), a.max_value().to_f64())
            })
            .collect()
    }

    /// Selects an instance by user coordinates (`[("wght", 700.0)]`; axes not named stay at their
    /// default; values are clamped to the axis range and taken in 16.16, as the format does).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for an unknown axis, a font without variations, or a `glyf`
    /// font (see the module documentation).
    pub fn set_variation(&mut self, settings: &[(String, f64)]) -> Result<()> {
        let axes = self.axes();
        if axes.is_empty() {
            return Err(fail("the font has no variation axes (no fvar table)".into()));
        }
        for (tag, _) in settings {
            if !axes.iter().any(|a| &a.0 == tag) {
                let names: Vec<&str> = axes.iter().map(|a| a.0.as_str()).collect();
                return Err(fail(format!("no axis {tag:?} (axes: {})", names.join(", "))));
            }
        }
        if !self.is_cff() {
            return Err(fail(
                "instances of glyf fonts are not offered: applying gvar deltas (with the interpolation of \
                 untouched points) is done in f32 by every font crate, so the coordinates would not be exact"
                    .into(),
            ));
        }
        let fvar = self.font.fvar().map_err(|e| fail(format!("fvar: {e}")))?;
        let avar = self.font.avar().ok();
        let mut coords = vec![F2Dot14::ZERO; axes.len()];
        let user =
            settings.iter().map(|(t, v)| (Tag::new_checked(t.as_bytes()).unwrap_or_default(), Fixed::from_f64(*v)));
        fvar.user_to_normalized(avar.as_ref(), user, &mut coords);
        self.coords = coords;
        Ok(())
    }

    /// Selects an instance by normalized coordinates (one `F2Dot14` per axis, in `fvar` order).
    ///
    /// # Errors
    /// As [`Self::set_variation`].
    pub fn set_normalized(&mut self, coords: Vec<F2Dot14>) -> Result<()> {
        if !self.is_cff() && coords.iter().any(|c| *c != F2Dot14::ZERO) {
            return Err(fail("instances of glyf fonts are not offered (see Font::set_variation)".into()));
        }
        self.coords = coords;
        Ok(())
    }

    /// The normalized coordinates of the selected instance (empty for the default one).
    pub fn normalized(&self) -> &[F2Dot14] {
        &self.coords
    }

    /// The number of glyphs (`maxp`).
    pub fn num_glyphs(&self) -> u32 {
        self.num_glyphs
    }

    /// `true` for CFF/CFF2 outlines (cubics), `false` for `glyf` (quadratics).
    pub fn is_cff(&self) -> bool {
        matches!(self.outlines, Outlines::Cff(_))
    }

    /// The glyph's name: its PostScript name from the `post` table (versions 1 and 2) or the CFF
    /// charset, and for a font that stores none (`post` version 3, as CFF2 and many web fonts
    /// have) the name fontTools derives: `cid01234` for the glyphs of a CID-keyed CFF font (the
    /// CID, at least five digits); else from the Unicode subtables of `cmap` (platform 0, or
    /// platform 3 with encoding 0, 1 or 10), the smallest code point mapped to the glyph as
    /// `uniXXXX` (`uXXXXX` beyond the BMP), `.alt1`, `.alt2`, … added for the second, third, …
    /// glyph of that name in glyph order; else `glyph01234` (the glyph id, at least five
    /// digits); `.notdef` for glyph 0. (fontTools first looks the code point up in the Adobe
    /// Glyph List For New Fonts, naming U+0041 `A` where casteljau writes `uni0041`; casteljau
    /// does not carry that list.) `None` only for an id beyond the font's glyphs.
    ///
    /// # Example
    /// ```
    /// use casteljau::format::Font;
    /// let data = include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/fonts/NotoSansJP-Regular.subset.otf"));
    /// let font = Font::open(data, 0).unwrap(); // CID-keyed CFF: no names stored
    /// assert_eq!(font.glyph_name(0).as_deref(), Some(".notdef"));
    /// assert!(font.glyph_name(1).unwrap().starts_with("cid"));
    /// assert_eq!(font.glyph_name(font.num_glyphs()), None);
    /// ```
    pub fn glyph_name(&self, gid: u32) -> Option<String> {
        if gid >= self.num_glyphs {
            return None;
        }
        if let Some(name) = u16::try_from(gid).ok().and_then(|g| self.post.as_ref()?.glyph_name(GlyphId16::new(g))) {
            return Some(name.to_string());
        }
        if let Outlines::Cff(cff) = &self.outlines
            && let Some(charset) = cff.charset()
        {
            if gid == 0 {
                return Some(".notdef".into());
            }
            if let Ok(sid) = charset.string_id(GlyphId::new(gid)) {
                if cff.is_cid() {
                    return Some(format!("cid{:05}", sid.to_u16()));
                }
                if let Some(s) = cff.string(sid) {
                    return Some(String::from_utf8_lossy(s).into_owned());
                }
            }
        }
        self.derived_names.get_or_init(|| self.names_from_cmap()).get(gid as usize).cloned()
    }

    /// Every glyph's name as fontTools derives it from `cmap` (see [`Self::glyph_name`]).
    fn names_from_cmap(&self) -> Vec<String> {
        let n = self.num_glyphs as usize;
        let mut smallest: Vec<Option<u32>> = vec![None; n];
        if let Ok(cmap) = self.font.cmap() {
            let limits =
                read_fonts::tables::cmap::CmapIterLimits { max_char: char::MAX as u32, glyph_count: self.num_glyphs };
            for record in cmap.encoding_records() {
                let (platform, encoding) = (record.platform_id(), record.encoding_id());
                let unicode = platform == read_fonts::tables::cmap::PlatformId::Unicode
                    || (platform == read_fonts::tables::cmap::PlatformId::Windows && matches!(encoding, 0 | 1 | 10));
                let Ok(subtable) = record.subtable(cmap.offset_data()) else { continue };
                if !unicode {
                    continue;
                }
                for (code, gid) in subtable.iter_with_limits(limits).take(MAX_CMAP_PAIRS) {
                    if let Some(s) = smallest.get_mut(gid.to_u32() as usize) {
                        *s = Some(s.map_or(code, |c| c.min(code)));
                    }
                }
            }
        }
        let mut uses: std::collections::HashMap<String, usize> = std::collections::HashMap::new();
        (0..n)
            .map(|gid| match smallest[gid] {
                _ if gid == 0 => ".notdef".to_string(),
                None => format!("glyph{gid:05}"),
                Some(code) => {
                    let base = if code <= 0xFFFF { format!("uni{code:04X}") } else { format!("u{code:X}") };
                    let count = uses.entry(base.clone()).or_insert(0);
                    *count += 1;
                    if *count > 1 { format!("{base}.alt{}", *count - 1) } else { base }
                }
            })
            .collect()
    }

    /// `glyph 12 (name)`, how messages name a glyph.
    fn label(&self, gid: u32) -> String {
        match self.glyph_name(gid) {
            Some(name) => format!("glyph {gid} ({name})"),
            None => format!("glyph {gid}"),
        }
    }

    /// The glyph's contours in font units, exactly (see the module documentation).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming the glyph for malformed glyph data, a composite nested
    /// deeper than 16 (`MAX_COMPONENT_DEPTH`) or cyclic, or one that decomposes into more than
    /// 100,000 (`MAX_GLYPH_POINTS`) points and component references (counted from the glyph
    /// headers before anything is composed: a glyph that uses the previous one twice, 16 levels
    /// deep, is refused at once).
    pub fn outline(&self, gid: u32) -> Result<Vec<Contour>> {
        if gid >= self.num_glyphs {
            return Err(fail(format!("glyph {gid}: the font has {} glyphs", self.num_glyphs)));
        }
        match &self.outlines {
            Outlines::Glyf { .. } => Ok(self.outline_numbered(gid)?.contours),
            Outlines::Cff(cff) => {
                let fd = cff.subfont_index(GlyphId::new(gid)).unwrap_or(0);
                let sub = cff.subfont(fd, &self.coords).map_err(|e| fail(format!("glyph {gid}: CFF: {e}")))?;
                let mut sink = CffSink::default();
                cff.evaluate_charstring(&sub, GlyphId::new(gid), &self.coords, &mut sink)
                    .map_err(|e| fail(format!("glyph {gid}: charstring: {e}")))?;
                sink.finish_contour();
                Ok(sink.contours)
            }
        }
    }

    /// The glyph's contours ([`Self::outline`]) with, per contour, per segment, per control
    /// point, the index of that point among the contour's stored points: for `glyf`, the
    /// contour's own points, off-curve points counted, `None` for an implied on-curve midpoint;
    /// for CFF, the start point is 0 and every later control and end point takes the next
    /// number (the closing line, and a last segment ending on the start point, end at 0), as
    /// [`super::point_numbers`] gives. Contours of one point (anchors some `glyf` fonts keep
    /// in their outlines) have no segment; their points are listed apart.
    ///
    /// # Errors
    /// As [`Self::outline`].
    pub fn outline_numbered(&self, gid: u32) -> Result<super::NumberedOutline> {
        if gid >= self.num_glyphs {
            return Err(fail(format!("glyph {gid}: the font has {} glyphs", self.num_glyphs)));
        }
        match &self.outlines {
            Outlines::Glyf { glyf, loca } => {
                let raw = self.glyf_raw(glyf, loca, gid, None)?;
                let lone_points = raw.iter().filter(|c| c.len() == 1).map(|c| c[0].0.clone()).collect();
                let (contours, numbers) = raw.iter().map(quadratic_contour).unzip();
                Ok(super::NumberedOutline { contours, numbers, lone_points })
            }
            Outlines::Cff(_) => {
                let contours = self.outline(gid)?;
                let numbers = contours.iter().map(super::point_numbers).collect();
                Ok(super::NumberedOutline { contours, numbers, lone_points: vec![] })
            }
        }
    }

    /// A `glyf` glyph's raw contours, its decomposed size counted first (refused before
    /// composing when over the limit); `parts` receives where each top-level component ends.
    fn glyf_raw(
        &self,
        glyf: &Glyf<'_>,
        loca: &Loca<'_>,
        gid: u32,
        parts: Option<&mut Vec<usize>>,
    ) -> Result<std::rc::Rc<Vec<RawContour>>> {
        let label = |g: u32| self.label(g);
        let mut sizes = std::collections::HashMap::new();
        let size = decomposed_size(glyf, loca, gid, 0, &mut sizes, &mut vec![], &label)?;
        if size > MAX_GLYPH_POINTS {
            return Err(fail(format!(
                "{}: its composite decomposes into more than {MAX_GLYPH_POINTS} points and component \
                 references, the limit (refused before composing)",
                self.label(gid)
            )));
        }
        glyf_points(glyf, loca, gid, &mut std::collections::HashMap::new(), &label, parts)
    }

    /// Whether glyph `gid` is a `glyf` composite (false for CFF and unreadable glyphs).
    pub(crate) fn is_composite(&self, gid: u32) -> bool {
        match &self.outlines {
            Outlines::Glyf { glyf, loca } => {
                matches!(loca.get_glyf(GlyphId::new(gid), glyf), Ok(Some(Glyph::Composite(_))))
            }
            Outlines::Cff(_) => false,
        }
    }

    /// The glyph's outline split by component, for overlap removal: a simple glyph (or a CFF
    /// glyph) is one part; a composite `glyf` glyph one part per component, each already placed
    /// in the glyph's space exactly (as [`Self::outline`] places it). Contours of one point
    /// are empty contours in their part; their points are listed apart, placed, in order.
    ///
    /// # Errors
    /// As [`Self::outline`].
    pub(crate) fn outline_parts(&self, gid: u32) -> Result<(Vec<Vec<Contour>>, Vec<P>)> {
        if gid >= self.num_glyphs {
            return Err(fail(format!("glyph {gid}: the font has {} glyphs", self.num_glyphs)));
        }
        match &self.outlines {
            Outlines::Glyf { glyf, loca } => {
                let mut ends = vec![];
                let raw = self.glyf_raw(glyf, loca, gid, Some(&mut ends))?;
                let lone = raw.iter().filter(|c| c.len() == 1).map(|c| c[0].0.clone()).collect();
                if ends.is_empty() {
                    ends.push(raw.len()); // a simple glyph: one part
                }
                let mut start = 0;
                let parts = ends
                    .iter()
                    .map(|&end| {
                        let part = raw[start..end].iter().map(|c| quadratic_contour(c).0).collect();
                        start = end;
                        part
                    })
                    .collect();
                Ok((parts, lone))
            }
            Outlines::Cff(_) => Ok((vec![self.outline(gid)?], vec![])),
        }
    }

    /// The bounding box stored in the glyph's `glyf` header, `[x_min, y_min, x_max, y_max]`
    /// (`None` for CFF fonts, an empty glyph, or an unreadable one).
    pub fn stored_glyph_box(&self, gid: u32) -> Option<[i16; 4]> {
        let Outlines::Glyf { glyf, loca } = &self.outlines else { return None };
        let g = loca.get_glyf(GlyphId::new(gid), glyf).ok()??;
        Some([g.x_min(), g.y_min(), g.x_max(), g.y_max()])
    }

    /// The font's bounding box from its `head` table, `[x_min, y_min, x_max, y_max]`.
    pub fn head_box(&self) -> Option<[i16; 4]> {
        let h = self.font.head().ok()?;
        Some([h.x_min(), h.y_min(), h.x_max(), h.y_max()])
    }

    /// The glyph as a filled [`crate::shape::Shape`], the input of [`crate::shape::boolean`]: its
    /// contours ([`Self::outline`]), every contour closed for fill (a closing line where it does
    /// not end where it starts, as SVG fills an open subpath), empty contours left out. Contour
    /// `k` of the shape is the glyph's `k`-th non-empty contour, its segments those of
    /// [`Self::outline`] in order (with the closing line, if any, last).
    ///
    /// # Errors
    /// As [`Self::outline`]; [`Error::InvalidArgument`] with the reason for a piece that is not a
    /// polynomial Bézier curve ([`Segment::Skipped`]: the `glyf` and CFF readers make none, so
    /// this is a safeguard); [`Error::TooLarge`] for a contour of more than
    /// 100,000 (`MAX_PATH_SEGMENTS`) segments.
    ///
    /// # Example
    /// ```
    /// use casteljau::format::Font;
    /// use casteljau::shape::{BooleanOp, BooleanOptions, boolean};
    /// let data = include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/fonts/Tuffy.ttf"));
    /// let font = Font::open(data, 0).unwrap();
    /// let o = font.glyphs_named(&["O"]).unwrap()[0];
    /// let shape = font.shape(o).unwrap();
    /// assert_eq!(shape.path().contours().len(), 2); // the outer contour and the counter
    /// // the glyph simplified in the font's own direction is its outline unchanged
    /// let options = BooleanOptions { orientation: font.outer_orientation(), ..BooleanOptions::default() };
    /// let r = boolean(BooleanOp::Simplify, std::slice::from_ref(&shape), options, &casteljau::work::Budget::unlimited()).unwrap();
    /// assert!(!r.changes(&shape));
    /// // a glyph without contours is the empty shape
    /// let space = font.glyphs_named(&["space"]).unwrap()[0];
    /// assert!(font.shape(space).unwrap().path().contours().is_empty());
    /// ```
    pub fn shape(&self, gid: u32) -> Result<crate::shape::Shape> {
        let mut contours = vec![];
        for c in self.outline(gid)? {
            let segs = super::svg_path::close_for_fill(&c)?;
            if !segs.is_empty() {
                contours.push(segs);
            }
        }
        Ok(crate::shape::Shape::new(crate::path::ClosedPath::from_polynomial(contours)?))
    }

    /// The direction of the font's outer contours by its format's convention: clockwise for
    /// TrueType `glyf` outlines, counter-clockwise for CFF and CFF2 (the y axis up, in font
    /// units). Counters run the other way. It is the direction a well-formed outline already
    /// has, so `boolean` simplification in it leaves such an outline unchanged, and the one
    /// `lint` checks contours against.
    ///
    /// # Example
    /// ```
    /// use casteljau::format::Font;
    /// use casteljau::shape::Orientation;
    /// let data = include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/fonts/Tuffy.ttf"));
    /// assert_eq!(Font::open(data, 0).unwrap().outer_orientation(), Orientation::Cw); // glyf
    /// let data = include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/fonts/NotoSansJP-Regular.subset.otf"));
    /// assert_eq!(Font::open(data, 0).unwrap().outer_orientation(), Orientation::Ccw); // CFF
    /// ```
    pub fn outer_orientation(&self) -> crate::shape::Orientation {
        if self.is_cff() { crate::shape::Orientation::Ccw } else { crate::shape::Orientation::Cw }
    }

    /// The ids of the glyphs with the given names ([`Self::glyph_name`]), in glyph order, each
    /// once: a name given twice counts once, and a name several glyphs carry stands for the
    /// first of them. No names give no ids.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] listing every name no glyph has (`no glyph named x, y`).
    ///
    /// # Example
    /// ```
    /// use casteljau::format::Font;
    /// let data = include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/fonts/Tuffy.ttf"));
    /// let font = Font::open(data, 0).unwrap();
    /// assert_eq!(font.glyphs_named(&["o", "A", "o"]).unwrap(), [36, 82]);
    /// let e = font.glyphs_named(&["A", "nosuch", "nor_this"]).unwrap_err();
    /// assert_eq!(e.to_string(), "no glyph named nosuch, nor_this");
    /// ```
    pub fn glyphs_named<S: AsRef<str>>(&self, names: &[S]) -> Result<Vec<u32>> {
        if names.is_empty() {
            return Ok(vec![]);
        }
        let mut ids: std::collections::HashMap<String, u32> = std::collections::HashMap::new();
        for gid in 0..self.num_glyphs {
            if let Some(n) = self.glyph_name(gid) {
                ids.entry(n).or_insert(gid);
            }
        }
        let unknown: Vec<&str> = names.iter().map(AsRef::as_ref).filter(|n| !ids.contains_key(*n)).collect();
        if !unknown.is_empty() {
            return Err(fail(format!("no glyph named {}", unknown.join(", "))));
        }
        let set: std::collections::BTreeSet<u32> = names.iter().map(|n| ids[n.as_ref()]).collect();
        Ok(set.into_iter().collect())
    }
}

/// A TrueType contour: points with their on-curve flags.
type RawContour = Vec<(P, bool)>;

fn f2dot14(v: read_fonts::types::F2Dot14) -> BigRational {
    BigRational::new(v.to_bits().into(), 16384.into())
}

fn int(v: i16) -> BigRational {
    rat(v as i64)
}

/// The points and component references of a glyph after composition, counted from the glyph
/// headers (memoised per glyph id in `sizes`; `path`: the composites being counted, for
/// cycles), saturating just past [`MAX_GLYPH_POINTS`].
fn decomposed_size(
    glyf: &Glyf<'_>,
    loca: &Loca<'_>,
    gid: u32,
    depth: usize,
    sizes: &mut std::collections::HashMap<u32, usize>,
    path: &mut Vec<u32>,
    label: &dyn Fn(u32) -> String,
) -> Result<usize> {
    if let Some(&n) = sizes.get(&gid) {
        return Ok(n);
    }
    if path.contains(&gid) {
        return Err(fail(format!("{}: its composite uses itself (a cycle of components)", label(path[0]))));
    }
    if depth > MAX_COMPONENT_DEPTH {
        return Err(fail(format!(
            "{}: composite nesting deeper than {MAX_COMPONENT_DEPTH} (at {})",
            label(path[0]),
            label(gid)
        )));
    }
    let glyph = loca.get_glyf(GlyphId::new(gid), glyf).map_err(|e| fail(format!("{}: {e}", label(gid))))?;
    let n = match glyph {
        None => 0,
        Some(Glyph::Simple(g)) => g.num_points(),
        Some(Glyph::Composite(g)) => {
            path.push(gid);
            let mut n = 0usize;
            for comp in g.components() {
                let own = decomposed_size(glyf, loca, comp.glyph.to_u32(), depth + 1, sizes, path, label)?;
                n = n.saturating_add(own).saturating_add(1).min(MAX_GLYPH_POINTS + 1);
            }
            path.pop();
            n
        }
    };
    sizes.insert(gid, n);
    Ok(n)
}

/// The glyph's contours in its own units, composites composed exactly, each glyph composed once
/// (memoised per glyph id in `done`: a glyph used twice is copied, not composed again). The
/// size is checked by [`decomposed_size`] first.
fn glyf_points(
    glyf: &Glyf<'_>,
    loca: &Loca<'_>,
    gid: u32,
    done: &mut std::collections::HashMap<u32, std::rc::Rc<Vec<RawContour>>>,
    label: &dyn Fn(u32) -> String,
    mut parts: Option<&mut Vec<usize>>,
) -> Result<std::rc::Rc<Vec<RawContour>>> {
    if let Some(points) = done.get(&gid) {
        return Ok(points.clone());
    }
    let glyph = loca.get_glyf(GlyphId::new(gid), glyf).map_err(|e| fail(format!("{}: {e}", label(gid))))?;
    let mut out: Vec<RawContour> = vec![];
    match glyph {
        None => {}
        Some(Glyph::Simple(g)) => {
            let mut points = g.points();
            let mut start = 0usize;
            for end in g.end_pts_of_contours() {
                let end = end.get() as usize;
                if end < start || end >= g.num_points() {
                    return Err(fail(format!("{}: contour end {end} out of order", label(gid))));
                }
                let mut c = Vec::with_capacity(end + 1 - start);
                for _ in start..=end {
                    let p = points.next().ok_or_else(|| fail(format!("{}: too few points", label(gid))))?;
                    c.push((Point::new(vec![int(p.x), int(p.y)]), p.on_curve));
                }
                out.push(c);
                start = end + 1;
            }
        }
        Some(Glyph::Composite(g)) => {
            // the points composed so far, by number: where each contour starts
            let mut starts: Vec<usize> = vec![];
            let mut count = 0usize;
            for comp in g.components() {
                let t = &comp.transform;
                let linear = Affine([f2dot14(t.xx), f2dot14(t.yx), f2dot14(t.xy), f2dot14(t.yy), rat(0), rat(0)]);
                let own = glyf_points(glyf, loca, comp.glyph.to_u32(), done, label, None)?;
                // the component in the composite's units: its 2×2 part, then the offset
                let scaled: Vec<RawContour> = if linear == Affine::identity() {
                    own.as_ref().clone()
                } else {
                    own.iter().map(|c| c.iter().map(|(p, on)| (linear.apply(p), *on)).collect()).collect()
                };
                let offset = match comp.anchor {
                    Anchor::Offset { x, y } => {
                        let o = Point::new(vec![int(x), int(y)]);
                        if comp.flags.contains(CompositeGlyphFlags::SCALED_COMPONENT_OFFSET)
                            && !comp.flags.contains(CompositeGlyphFlags::UNSCALED_COMPONENT_OFFSET)
                        {
                            linear.apply(&o)
                        } else {
                            o
                        }
                    }
                    Anchor::Point { base, component } => {
                        // point matching: the component's point lands on the base's point
                        let b = nth_point(&out, &starts, base as usize).ok_or_else(|| {
                            fail(format!("{}: anchor point {base} beyond the composed points", label(gid)))
                        })?;
                        let c = scaled.iter().flatten().nth(component as usize).map(|(p, _)| p).ok_or_else(|| {
                            fail(format!("{}: component point {component} beyond its points", label(gid)))
                        })?;
                        b.sub(c)
                    }
                };
                let moved = offset.coords.iter().any(|x| *x != rat(0));
                for c in scaled {
                    starts.push(count);
                    count += c.len();
                    out.push(if moved { c.into_iter().map(|(p, on)| (p.add(&offset), on)).collect() } else { c });
                }
                if let Some(parts) = parts.as_deref_mut() {
                    parts.push(out.len());
                }
            }
        }
    }
    let total: usize = out.iter().map(Vec::len).sum();
    if total > MAX_GLYPH_POINTS {
        return Err(Error::TooLarge { what: "points in one glyph", value: total, limit: MAX_GLYPH_POINTS });
    }
    let out = std::rc::Rc::new(out);
    done.insert(gid, out.clone());
    Ok(out)
}

/// Point `k` of `contours`, numbered in order (`starts`: where each contour's points start).
fn nth_point<'c>(contours: &'c [RawContour], starts: &[usize], k: usize) -> Option<&'c P> {
    let c = starts.partition_point(|&s| s <= k).checked_sub(1)?;
    contours.get(c)?.get(k - starts[c]).map(|(p, _)| p)
}

fn midpoint(a: &P, b: &P) -> P {
    a.add(b).scale(&BigRational::new(1.into(), 2.into()))
}

/// The segments of a closed TrueType contour: lines between on-curve points, quadratics through
/// off-curve points, and the implied on-curve midpoint between two off-curve points.
/// Each segment's control points are numbered by their index in `points` (`None`: implied).
fn quadratic_contour(points: &RawContour) -> (Contour, super::PointNumbers) {
    let mut segments = vec![];
    let mut numbers = vec![];
    let n = points.len();
    // a contour of one point (on- or off-curve) draws nothing: its point is listed apart
    if n <= 1 {
        return (Contour { segments, closed: true }, numbers);
    }
    let first_on = points.iter().position(|(_, on)| *on);
    let (start, start_index, order): (P, Option<usize>, Vec<usize>) = match first_on {
        Some(f) => (points[f].0.clone(), Some(f), (f + 1..n).chain(0..f).collect()),
        None => (midpoint(&points[n - 1].0, &points[0].0), None, (0..n).collect()),
    };
    let (mut cur, mut cur_index) = (start.clone(), start_index);
    let mut pending: Option<usize> = None;
    for i in order {
        let (q, on) = &points[i];
        match (pending.take(), on) {
            (None, true) => {
                segments.push(Segment::Bezier(vec![cur.clone(), q.clone()]));
                numbers.push(vec![cur_index, Some(i)]);
                (cur, cur_index) = (q.clone(), Some(i));
            }
            (None, false) => pending = Some(i),
            (Some(c), true) => {
                segments.push(Segment::Bezier(vec![cur.clone(), points[c].0.clone(), q.clone()]));
                numbers.push(vec![cur_index, Some(c), Some(i)]);
                (cur, cur_index) = (q.clone(), Some(i));
            }
            (Some(c), false) => {
                let m = midpoint(&points[c].0, q);
                segments.push(Segment::Bezier(vec![cur.clone(), points[c].0.clone(), m.clone()]));
                numbers.push(vec![cur_index, Some(c), None]);
                (cur, cur_index) = (m, None);
                pending = Some(i);
            }
        }
    }
    match pending {
        Some(c) => {
            segments.push(Segment::Bezier(vec![cur, points[c].0.clone(), start]));
            numbers.push(vec![cur_index, Some(c), start_index]);
        }
        None if cur != start => {
            segments.push(Segment::Bezier(vec![cur, start]));
            numbers.push(vec![cur_index, start_index]);
        }
        None => {}
    }
    (Contour { segments, closed: true }, numbers)
}

/// Collects the charstring's path commands as exact segments.
#[derive(Default)]
struct CffSink {
    contours: Vec<Contour>,
    current: Option<(P, P, Vec<Segment>)>, // (start, current point, segments)
}

fn fixed(v: read_fonts::types::Fixed) -> BigRational {
    BigRational::new(v.to_bits().into(), 65536.into())
}

impl CffSink {
    fn finish_contour(&mut self) {
        if let Some((start, cur, mut segs)) = self.current.take() {
            if cur != start {
                segs.push(Segment::Bezier(vec![cur, start]));
            }
            self.contours.push(Contour { segments: segs, closed: true });
        }
    }

    fn point(x: read_fonts::types::Fixed, y: read_fonts::types::Fixed) -> P {
        Point::new(vec![fixed(x), fixed(y)])
    }

    fn push(&mut self, to: P, segment: impl FnOnce(P) -> Segment) {
        let (_, cur, segs) = self.current.get_or_insert_with(|| {
            let o = Point::new(vec![rat(0), rat(0)]);
            (o.clone(), o, vec![])
        });
        let s = segment(std::mem::replace(cur, to));
        segs.push(s);
    }
}

impl read_fonts::ps::cs::CommandSink for CffSink {
    fn move_to(&mut self, x: read_fonts::types::Fixed, y: read_fonts::types::Fixed) {
        self.finish_contour();
        let p = Self::point(x, y);
        self.current = Some((p.clone(), p, vec![]));
    }

    fn line_to(&mut self, x: read_fonts::types::Fixed, y: read_fonts::types::Fixed) {
        let p = Self::point(x, y);
        self.push(p.clone(), |from| Segment::Bezier(vec![from, p]));
    }

    fn curve_to(
        &mut self,
        cx0: read_fonts::types::Fixed,
        cy0: read_fonts::types::Fixed,
        cx1: read_fonts::types::Fixed,
        cy1: read_fonts::types::Fixed,
        x: read_fonts::types::Fixed,
        y: read_fonts::types::Fixed,
    ) {
        let (c0, c1, p) = (Self::point(cx0, cy0), Self::point(cx1, cy1), Self::point(x, y));
        self.push(p.clone(), |from| Segment::Bezier(vec![from, c0, c1, p]));
    }

    fn close(&mut self) {
        self.finish_contour();
    }
}
