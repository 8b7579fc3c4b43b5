//! Fonts built in the tests: TrueType (`glyf`) and CFF (OpenType `OTTO`) fonts made from integer
//! outlines, read back with the crate's own reader, and the planted-defect glyph set that the
//! tests of `casteljau lint` check against (`lint_fonts`).
//!
//! * [`truetype`]: `glyf`/`loca` written by `write-fonts`, a `post` version 2 table with the
//!   glyph names; each glyph's stored bounding box is that of its points (on- and off-curve)
//!   unless overridden, and `head`'s is the union of the glyphs' (also overridable).
//! * [`cff`]: a minimal CFF 1 table written here by hand (`write-fonts` writes no CFF): header,
//!   Name INDEX, Top DICT INDEX (`charset`, `CharStrings`, `Private`), String INDEX with every
//!   glyph name, an empty Global Subr INDEX, a format 0 charset, the CharStrings INDEX of Type 2
//!   charstrings (`rmoveto`, `rlineto`, `rrcurveto`, `endchar`, integer operands) and a Private
//!   DICT with only `defaultWidthX`; `post` version 3, so the names come from the charset.
//!
//! Glyph 0 is `.notdef`: an empty one is put first unless the first glyph given is named so.
//!
//! Orientation conventions (y up): TrueType outer contours clockwise, holes counter-clockwise;
//! CFF outer contours counter-clockwise, holes clockwise.
//!
//! The planted-defect set that `casteljau lint` is tested on is in `lint_fonts`.

use casteljau::format::{Contour, Segment};
use casteljau::{Point, rat};
use num_rational::BigRational;
use read_fonts::tables::glyf::CurvePoint;
use write_fonts::FontBuilder;
use write_fonts::tables::glyf::{Bbox, Contour as GlyfContour, GlyfLocaBuilder, SimpleGlyph};
use write_fonts::tables::head::Head;
use write_fonts::tables::hhea::Hhea;
use write_fonts::tables::hmtx::{Hmtx, LongMetric};
use write_fonts::tables::maxp::Maxp;
use write_fonts::tables::post::Post;
use write_fonts::types::{FWord, Tag, UfWord, Version16Dot16};

/// Units per em of every built font.
pub const UPEM: u16 = 1000;
/// Advance width of every glyph.
const ADVANCE: u16 = 1000;

// ---------------------------------------------------------------------------------------------
// TrueType

/// A TrueType point: `(x, y, on_curve)`.
pub type TtPoint = (i16, i16, bool);

/// An on-curve point.
pub const fn on(x: i16, y: i16) -> TtPoint {
    (x, y, true)
}

/// An off-curve (quadratic control) point.
pub const fn off(x: i16, y: i16) -> TtPoint {
    (x, y, false)
}

/// A simple TrueType glyph.
#[derive(Clone, Debug)]
pub struct TtGlyph {
    /// The glyph name (`post` version 2).
    pub name: String,
    /// The contours, each a closed ring of points as stored.
    pub contours: Vec<Vec<TtPoint>>,
    /// The stored `glyf` bounding box `[x_min, y_min, x_max, y_max]`; `None`: that of the points.
    pub bbox: Option<[i16; 4]>,
}

impl TtGlyph {
    /// A glyph whose stored bounding box is that of its points.
    pub fn new(name: &str, contours: Vec<Vec<TtPoint>>) -> TtGlyph {
        TtGlyph { name: name.into(), contours, bbox: None }
    }

    /// The same glyph with another stored bounding box.
    pub fn with_bbox(mut self, bbox: [i16; 4]) -> TtGlyph {
        self.bbox = Some(bbox);
        self
    }

    /// The bounding box of the points (on- and off-curve), `None` without points.
    pub fn points_bbox(&self) -> Option<[i16; 4]> {
        let mut it = self.contours.iter().flatten();
        let &(x, y, _) = it.next()?;
        Some(it.fold([x, y, x, y], |[a, b, c, d], &(x, y, _)| [a.min(x), b.min(y), c.max(x), d.max(y)]))
    }

    /// The stored bounding box: the override, or that of the points.
    pub fn stored_bbox(&self) -> Option<[i16; 4]> {
        self.bbox.or_else(|| self.points_bbox())
    }
}

fn with_notdef<G: Clone>(glyphs: &[G], name: impl Fn(&G) -> &str, notdef: G) -> Vec<G> {
    let mut all = vec![];
    if glyphs.first().is_none_or(|g| name(g) != ".notdef") {
        all.push(notdef);
    }
    all.extend_from_slice(glyphs);
    all
}

fn union(boxes: impl Iterator<Item = [i16; 4]>) -> [i16; 4] {
    boxes.reduce(|[a, b, c, d], [e, f, g, h]| [a.min(e), b.min(f), c.max(g), d.max(h)]).unwrap_or([0; 4])
}

/// The common tables: `head`, `hhea`, `maxp`, `hmtx`, `post` (the caller adds the outlines).
fn common_tables(
    builder: &mut FontBuilder<'_>,
    head_bbox: [i16; 4],
    loca_format: i16,
    lsb: &[i16],
    maxp: Maxp,
    post: Post,
) {
    let head = Head {
        font_revision: write_fonts::types::Fixed::ONE,
        units_per_em: UPEM,
        x_min: head_bbox[0],
        y_min: head_bbox[1],
        x_max: head_bbox[2],
        y_max: head_bbox[3],
        index_to_loc_format: loca_format,
        ..Default::default()
    };
    let hhea = Hhea {
        ascender: FWord::new(800),
        descender: FWord::new(-200),
        advance_width_max: UfWord::new(ADVANCE),
        min_left_side_bearing: FWord::new(lsb.iter().copied().min().unwrap_or(0)),
        caret_slope_rise: 1,
        number_of_h_metrics: lsb.len() as u16,
        ..Default::default()
    };
    let hmtx = Hmtx::new(lsb.iter().map(|&l| LongMetric::new(ADVANCE, l)).collect(), vec![]);
    builder.add_table(&head).unwrap();
    builder.add_table(&hhea).unwrap();
    builder.add_table(&maxp).unwrap();
    builder.add_table(&hmtx).unwrap();
    builder.add_table(&post).unwrap();
}

/// A TrueType font of the glyphs (an empty `.notdef` first unless given).
pub fn truetype(glyphs: &[TtGlyph]) -> Vec<u8> {
    truetype_with_head_bbox(glyphs, None)
}

/// [`truetype`] with `head`'s bounding box given (`None`: the union of the glyphs' points).
pub fn truetype_with_head_bbox(glyphs: &[TtGlyph], head_bbox: Option<[i16; 4]>) -> Vec<u8> {
    let glyphs = with_notdef(glyphs, |g| &g.name, TtGlyph::new(".notdef", vec![]));
    let mut glyf = GlyfLocaBuilder::new();
    for g in &glyphs {
        let contours: Vec<GlyfContour> = g
            .contours
            .iter()
            .map(|c| c.iter().map(|&(x, y, on)| CurvePoint::new(x, y, on)).collect::<Vec<_>>().into())
            .collect();
        let [x_min, y_min, x_max, y_max] = g.stored_bbox().unwrap_or([0; 4]);
        let simple = SimpleGlyph { bbox: Bbox { x_min, y_min, x_max, y_max }, contours, instructions: vec![] };
        glyf.add_glyph(&simple).unwrap();
    }
    let (glyf, loca, loca_format) = glyf.build();
    let head_bbox = head_bbox.unwrap_or_else(|| union(glyphs.iter().filter_map(TtGlyph::points_bbox)));
    let lsb: Vec<i16> = glyphs.iter().map(|g| g.stored_bbox().map_or(0, |b| b[0])).collect();
    let maxp = Maxp {
        num_glyphs: glyphs.len() as u16,
        max_points: Some(glyphs.iter().map(|g| g.contours.iter().map(Vec::len).sum::<usize>() as u16).max().unwrap()),
        max_contours: Some(glyphs.iter().map(|g| g.contours.len() as u16).max().unwrap()),
        max_composite_points: Some(0),
        max_composite_contours: Some(0),
        max_zones: Some(1),
        max_twilight_points: Some(0),
        max_storage: Some(0),
        max_function_defs: Some(0),
        max_instruction_defs: Some(0),
        max_stack_elements: Some(0),
        max_size_of_instructions: Some(0),
        max_component_elements: Some(0),
        max_component_depth: Some(0),
    };
    let post = Post::new_v2(glyphs.iter().map(|g| g.name.as_str()));
    let mut builder = FontBuilder::new();
    common_tables(&mut builder, head_bbox, loca_format as i16, &lsb, maxp, post);
    builder.add_table(&glyf).unwrap();
    builder.add_table(&loca).unwrap();
    builder.build()
}

// ---------------------------------------------------------------------------------------------
// CFF

/// A CFF path command, absolute integer coordinates (written as relative operators).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cmd {
    /// Starts the contour (`rmoveto`).
    Move(i16, i16),
    /// A line (`rlineto`).
    Line(i16, i16),
    /// A cubic: two control points and the end (`rrcurveto`).
    Curve(i16, i16, i16, i16, i16, i16),
}
pub use Cmd::{Curve, Line, Move};

/// A CFF glyph.
#[derive(Clone, Debug)]
pub struct CffGlyph {
    /// The glyph name (charset and String INDEX).
    pub name: String,
    /// The contours, each starting with a [`Cmd::Move`]; closed implicitly.
    pub contours: Vec<Vec<Cmd>>,
}

impl CffGlyph {
    /// A glyph.
    pub fn new(name: &str, contours: Vec<Vec<Cmd>>) -> CffGlyph {
        for c in &contours {
            assert!(matches!(c.first(), Some(Move(..))), "{name}: a contour starts with Move");
            assert!(c[1..].iter().all(|m| !matches!(m, Move(..))), "{name}: one Move per contour");
        }
        CffGlyph { name: name.into(), contours }
    }

    /// All points written (start, controls, ends).
    fn points(&self) -> impl Iterator<Item = (i16, i16)> + '_ {
        self.contours.iter().flatten().flat_map(|c| match *c {
            Move(x, y) | Line(x, y) => vec![(x, y)],
            Curve(a, b, c, d, x, y) => vec![(a, b), (c, d), (x, y)],
        })
    }
}

/// A Type 2 charstring / DICT integer operand in its shortest encoding (`28` + `i16` beyond
/// ±1131).
fn push_int(out: &mut Vec<u8>, v: i32) {
    match v {
        -107..=107 => out.push((v + 139) as u8),
        108..=1131 => {
            let w = v - 108;
            out.extend([(247 + (w >> 8)) as u8, (w & 0xff) as u8]);
        }
        -1131..=-108 => {
            let w = -v - 108;
            out.extend([(251 + (w >> 8)) as u8, (w & 0xff) as u8]);
        }
        _ => {
            let w = i16::try_from(v).expect("a charstring operand fits 16 bits");
            out.push(28);
            out.extend(w.to_be_bytes());
        }
    }
}

/// A DICT integer in the fixed 5-byte form (`29` + `i32`), so offsets can be laid out first.
fn push_int5(out: &mut Vec<u8>, v: usize) {
    out.push(29);
    out.extend((v as i32).to_be_bytes());
}

/// A CFF 1 INDEX.
fn index(items: &[Vec<u8>]) -> Vec<u8> {
    let mut out = (items.len() as u16).to_be_bytes().to_vec();
    if items.is_empty() {
        return out;
    }
    let last = 1 + items.iter().map(Vec::len).sum::<usize>();
    let off_size = match last {
        0..=0xff => 1,
        0x100..=0xffff => 2,
        0x1_0000..=0xff_ffff => 3,
        _ => 4,
    };
    out.push(off_size as u8);
    let mut offset = 1usize;
    for k in 0..=items.len() {
        out.extend(&(offset as u32).to_be_bytes()[4 - off_size..]);
        if k < items.len() {
            offset += items[k].len();
        }
    }
    for item in items {
        out.extend(item);
    }
    out
}

/// The Type 2 charstring of a glyph.
fn charstring(g: &CffGlyph) -> Vec<u8> {
    let mut out = vec![];
    // the current point: the last point written (the implicit closing line does not move it)
    let (mut cx, mut cy) = (0i32, 0i32);
    let mut rel = |out: &mut Vec<u8>, x: i16, y: i16| {
        push_int(out, x as i32 - cx);
        push_int(out, y as i32 - cy);
        (cx, cy) = (x as i32, y as i32);
    };
    for c in g.contours.iter().flatten() {
        match *c {
            Move(x, y) => {
                rel(&mut out, x, y);
                out.push(21); // rmoveto
            }
            Line(x, y) => {
                rel(&mut out, x, y);
                out.push(5); // rlineto
            }
            Curve(x1, y1, x2, y2, x, y) => {
                rel(&mut out, x1, y1);
                rel(&mut out, x2, y2);
                rel(&mut out, x, y);
                out.push(8); // rrcurveto
            }
        }
    }
    out.push(14); // endchar
    out
}

/// The `CFF ` table of the glyphs (glyph 0 must be `.notdef`).
fn cff_table(glyphs: &[CffGlyph]) -> Vec<u8> {
    assert_eq!(glyphs[0].name, ".notdef");
    let header = vec![1u8, 0, 4, 4];
    let name_index = index(&[b"CasteljauTest".to_vec()]);
    // every other glyph name is a custom string: SIDs 391, 392, ...
    let strings: Vec<Vec<u8>> = glyphs[1..].iter().map(|g| g.name.as_bytes().to_vec()).collect();
    let string_index = index(&strings);
    let gsubr_index = index(&[]);
    let mut charset = vec![0u8]; // format 0
    for k in 0..glyphs.len() - 1 {
        charset.extend((391 + k as u16).to_be_bytes());
    }
    let charstrings = index(&glyphs.iter().map(charstring).collect::<Vec<_>>());
    let mut private = vec![];
    push_int(&mut private, 0);
    private.push(20); // defaultWidthX
    // Top DICT: charset, CharStrings, Private, all in 5-byte integers so its size is fixed
    let top_dict = |charset_at: usize, charstrings_at: usize, private_at: usize| {
        let mut d = vec![];
        push_int5(&mut d, charset_at);
        d.push(15);
        push_int5(&mut d, charstrings_at);
        d.push(17);
        push_int5(&mut d, private.len());
        push_int5(&mut d, private_at);
        d.push(18);
        d
    };
    let top_len = index(&[top_dict(0, 0, 0)]).len();
    let charset_at = header.len() + name_index.len() + top_len + string_index.len() + gsubr_index.len();
    let charstrings_at = charset_at + charset.len();
    let private_at = charstrings_at + charstrings.len();
    let top_index = index(&[top_dict(charset_at, charstrings_at, private_at)]);
    assert_eq!(top_index.len(), top_len);
    [header, name_index, top_index, string_index, gsubr_index, charset, charstrings, private.clone()].concat()
}

/// A CFF-flavoured OpenType font (`OTTO`) of the glyphs (an empty `.notdef` first unless given).
pub fn cff(glyphs: &[CffGlyph]) -> Vec<u8> {
    let glyphs = with_notdef(glyphs, |g| &g.name, CffGlyph::new(".notdef", vec![]));
    let bbox = |g: &CffGlyph| {
        let mut it = g.points();
        let (x, y) = it.next()?;
        Some(it.fold([x, y, x, y], |[a, b, c, d], (x, y)| [a.min(x), b.min(y), c.max(x), d.max(y)]))
    };
    let head_bbox = union(glyphs.iter().filter_map(bbox));
    let lsb: Vec<i16> = glyphs.iter().map(|g| bbox(g).map_or(0, |b| b[0])).collect();
    let maxp = Maxp { num_glyphs: glyphs.len() as u16, ..Default::default() }; // version 0.5
    let post = Post { version: Version16Dot16::VERSION_3_0, ..Default::default() };
    let mut builder = FontBuilder::new();
    common_tables(&mut builder, head_bbox, 0, &lsb, maxp, post);
    builder.add_raw(Tag::new(b"CFF "), cff_table(&glyphs));
    builder.build()
}

// Squares, in either direction

/// A clockwise (y up) square of on-curve points: a TrueType outer contour.
pub fn tt_square(x0: i16, y0: i16, x1: i16, y1: i16) -> Vec<TtPoint> {
    vec![on(x0, y0), on(x0, y1), on(x1, y1), on(x1, y0)]
}

/// A counter-clockwise (y up) square: a TrueType hole.
pub fn tt_square_ccw(x0: i16, y0: i16, x1: i16, y1: i16) -> Vec<TtPoint> {
    vec![on(x0, y0), on(x1, y0), on(x1, y1), on(x0, y1)]
}

/// A counter-clockwise (y up) square: a CFF outer contour.
pub fn cff_square(x0: i16, y0: i16, x1: i16, y1: i16) -> Vec<Cmd> {
    vec![Move(x0, y0), Line(x1, y0), Line(x1, y1), Line(x0, y1)]
}

/// A clockwise (y up) square: a CFF hole.
pub fn cff_square_cw(x0: i16, y0: i16, x1: i16, y1: i16) -> Vec<Cmd> {
    vec![Move(x0, y0), Line(x0, y1), Line(x1, y1), Line(x1, y0)]
}

// ---------------------------------------------------------------------------------------------
// What the reader should give back, computed independently of it

pub type P = Point<BigRational>;

pub fn pt(x: i64, y: i64) -> P {
    Point::new(vec![rat(x), rat(y)])
}

pub fn seg(points: &[&P]) -> Segment {
    Segment::Bezier(points.iter().map(|&p| p.clone()).collect())
}

/// The segments of TrueType contours: every implied on-curve point (the midpoint of two
/// consecutive off-curve points) made explicit, then the ring walked from its first node.
pub fn tt_expected(contours: &[Vec<TtPoint>]) -> Vec<Contour> {
    contours
        .iter()
        .map(|c| {
            let n = c.len();
            let mut ring: Vec<(P, bool)> = vec![];
            for i in 0..n {
                let (x, y, on_curve) = c[i];
                let (px, py, prev_on) = c[(i + n - 1) % n];
                if !on_curve && !prev_on {
                    ring.push((
                        Point::new(vec![rat(px as i64 + x as i64) / rat(2), rat(py as i64 + y as i64) / rat(2)]),
                        true,
                    ));
                }
                ring.push((pt(x as i64, y as i64), on_curve));
            }
            let first = ring.iter().position(|(_, on)| *on).unwrap();
            ring.rotate_left(first);
            let start = ring[0].0.clone();
            ring.push((start, true));
            let mut segments = vec![];
            let mut i = 0;
            while i + 1 < ring.len() {
                if ring[i + 1].1 {
                    if ring[i + 1].0 != ring[i].0 || i + 2 < ring.len() {
                        segments.push(seg(&[&ring[i].0, &ring[i + 1].0]));
                    }
                    i += 1;
                } else {
                    segments.push(seg(&[&ring[i].0, &ring[i + 1].0, &ring[i + 2].0]));
                    i += 2;
                }
            }
            Contour { segments, closed: true }
        })
        .collect()
}

/// The segments of CFF contours: lines and cubics as written, then the closing line when the
/// contour does not end at its start.
pub fn cff_expected(contours: &[Vec<Cmd>]) -> Vec<Contour> {
    let p = |x: i16, y: i16| pt(x as i64, y as i64);
    contours
        .iter()
        .map(|c| {
            let Move(x0, y0) = c[0] else { unreachable!() };
            let start = p(x0, y0);
            let mut cur = start.clone();
            let mut segments = vec![];
            for m in &c[1..] {
                let (s, to) = match *m {
                    Line(x, y) => (seg(&[&cur, &p(x, y)]), p(x, y)),
                    Curve(a, b, c, d, x, y) => (seg(&[&cur, &p(a, b), &p(c, d), &p(x, y)]), p(x, y)),
                    Move(..) => unreachable!(),
                };
                segments.push(s);
                cur = to;
            }
            if cur != start {
                segments.push(seg(&[&cur, &start]));
            }
            Contour { segments, closed: true }
        })
        .collect()
}

// ---------------------------------------------------------------------------------------------
// TrueType with composites, unnamed glyphs and a cmap

/// A composite TrueType glyph: per component `(glyph id, x offset, y offset)`.
#[derive(Clone, Debug)]
pub struct TtComposite {
    /// The glyph name (when the font stores names).
    pub name: String,
    /// The components.
    pub components: Vec<(u16, i16, i16)>,
}

/// A TrueType font of `glyphs` (an empty `.notdef` first unless given), then `composites` (their
/// ids follow the simple glyphs'), a `cmap` of `mappings`, and a `post` table of version 2 with
/// the names, or of version 3 (no names) when `names` is false.
pub fn truetype_composites(
    glyphs: &[TtGlyph],
    composites: &[TtComposite],
    names: bool,
    mappings: &[(char, u32)],
) -> Vec<u8> {
    use write_fonts::tables::glyf::{Anchor, Component, CompositeGlyph, Transform};
    use write_fonts::types::GlyphId16;
    let glyphs = with_notdef(glyphs, |g| &g.name, TtGlyph::new(".notdef", vec![]));
    let mut glyf = GlyfLocaBuilder::new();
    for g in &glyphs {
        let contours: Vec<GlyfContour> = g
            .contours
            .iter()
            .map(|c| c.iter().map(|&(x, y, on)| CurvePoint::new(x, y, on)).collect::<Vec<_>>().into())
            .collect();
        let [x_min, y_min, x_max, y_max] = g.stored_bbox().unwrap_or([0; 4]);
        let simple = SimpleGlyph { bbox: Bbox { x_min, y_min, x_max, y_max }, contours, instructions: vec![] };
        glyf.add_glyph(&simple).unwrap();
    }
    for c in composites {
        let component = |&(gid, dx, dy): &(u16, i16, i16)| {
            Component::new(
                GlyphId16::new(gid),
                Anchor::Offset { x: dx, y: dy },
                Transform::default(),
                write_fonts::tables::glyf::ComponentFlags::default(),
            )
        };
        let bbox = Bbox { x_min: 0, y_min: 0, x_max: 0, y_max: 0 };
        let mut composite = CompositeGlyph::new(component(&c.components[0]), bbox);
        for k in &c.components[1..] {
            composite.add_component(component(k), bbox);
        }
        glyf.add_glyph(&composite).unwrap();
    }
    let (glyf, loca, loca_format) = glyf.build();
    let head_bbox = union(glyphs.iter().filter_map(TtGlyph::points_bbox));
    let count = glyphs.len() + composites.len();
    let lsb: Vec<i16> = (0..count).map(|k| glyphs.get(k).and_then(TtGlyph::stored_bbox).map_or(0, |b| b[0])).collect();
    let maxp = Maxp {
        num_glyphs: count as u16,
        max_points: Some(glyphs.iter().map(|g| g.contours.iter().map(Vec::len).sum::<usize>() as u16).max().unwrap()),
        max_contours: Some(glyphs.iter().map(|g| g.contours.len() as u16).max().unwrap()),
        max_composite_points: Some(0),
        max_composite_contours: Some(0),
        max_zones: Some(1),
        max_twilight_points: Some(0),
        max_storage: Some(0),
        max_function_defs: Some(0),
        max_instruction_defs: Some(0),
        max_stack_elements: Some(0),
        max_size_of_instructions: Some(0),
        max_component_elements: Some(composites.iter().map(|c| c.components.len() as u16).max().unwrap_or(0)),
        max_component_depth: Some(16),
    };
    let post = if names {
        Post::new_v2(glyphs.iter().map(|g| g.name.as_str()).chain(composites.iter().map(|c| c.name.as_str())))
    } else {
        Post { version: Version16Dot16::VERSION_3_0, ..Default::default() }
    };
    let mut builder = FontBuilder::new();
    common_tables(&mut builder, head_bbox, loca_format as i16, &lsb, maxp, post);
    builder.add_table(&glyf).unwrap();
    builder.add_table(&loca).unwrap();
    if !mappings.is_empty() {
        let cmap = write_fonts::tables::cmap::Cmap::from_mappings(
            mappings.iter().map(|&(c, g)| (c, write_fonts::types::GlyphId::new(g))),
        )
        .unwrap();
        builder.add_table(&cmap).unwrap();
    }
    builder.build()
}

/// A font with a 10×10 square (glyph 1, `square`) and composites `bomb1` … `bomb{depth}`, each
/// using the one before twice (`bomb1` uses the square twice), side by side up to `bomb10`
/// (1,024 squares in a row), on top of each other beyond: `bomb{k}` is `2^k` squares.
pub fn composite_bomb(depth: u16) -> Vec<u8> {
    let square = TtGlyph::new("square", vec![tt_square(0, 0, 10, 10)]);
    let composites: Vec<TtComposite> = (1..=depth)
        .map(|k| {
            let dx = if k <= 10 { 20i16 << (k - 1) } else { 0 };
            TtComposite { name: format!("bomb{k}"), components: vec![(k, 0, 0), (k, dx, 0)] }
        })
        .collect();
    truetype_composites(&[square], &composites, true, &[])
}
