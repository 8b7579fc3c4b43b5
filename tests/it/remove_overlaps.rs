//! Overlap removal that writes the font: `casteljau::overlaps::write_font` with hand-made
//! decisions (what is written, what stays byte-identical, the tables it recomputes), read back
//! with casteljau's reader, `read-fonts` and `skrifa`; and the `remove-overlaps` command.
//! The last tests run the command end to end with the real per-glyph decision.

use crate::common::{TempDir, run, stderr, stdout};
use crate::font_builder::{self, CffGlyph, Cmd, Line, Move, TtPoint, cff_expected, off, on, tt_expected};
use casteljau::format::Font;
use casteljau::overlaps::{
    FontOutcome, GlyphDecision, GlyphInput, GlyphReport, GridContour, GridPoint, WriteOptions, write_font,
};
use casteljau::{Error, rat};
use read_fonts::{FontRef, TableProvider};
use write_fonts::FontBuilder;
use write_fonts::tables::head::Head;
use write_fonts::tables::hhea::Hhea;
use write_fonts::tables::hmtx::{Hmtx, LongMetric};
use write_fonts::tables::maxp::Maxp;
use write_fonts::tables::post::Post;
use write_fonts::types::{FWord, Tag, UfWord};

// ---------------------------------------------------------------------------------------------
// A TrueType font with instructions, composites and hinting tables, its records written here

/// A glyph record: a simple glyph (contours, instructions) or a composite (components at
/// integer offsets, instructions).
enum Rec {
    Simple(Vec<Vec<TtPoint>>, Vec<u8>),
    Composite(Vec<(u16, i16, i16)>, Vec<u8>),
}

/// The record's bytes: every coordinate as a word, one flag per point (no repeats), so that
/// the writer's own encoding is never the same as the input's by accident.
fn record(r: &Rec, boxes: &[Option<[i16; 4]>]) -> (Vec<u8>, Option<[i16; 4]>) {
    let mut out = vec![];
    match r {
        Rec::Simple(contours, instructions) => {
            let pts: Vec<TtPoint> = contours.iter().flatten().copied().collect();
            if pts.is_empty() {
                return (vec![], None);
            }
            let b = pts.iter().fold([i16::MAX, i16::MAX, i16::MIN, i16::MIN], |[a, b, c, d], &(x, y, _)| {
                [a.min(x), b.min(y), c.max(x), d.max(y)]
            });
            out.extend((contours.len() as i16).to_be_bytes());
            b.iter().for_each(|v| out.extend(v.to_be_bytes()));
            let mut end = 0u16;
            for c in contours {
                end += c.len() as u16;
                out.extend((end - 1).to_be_bytes());
            }
            out.extend((instructions.len() as u16).to_be_bytes());
            out.extend(instructions);
            out.extend(pts.iter().map(|p| p.2 as u8));
            let (mut px, mut py) = (0i16, 0i16);
            let mut ys = vec![];
            for &(x, y, _) in &pts {
                out.extend((x - px).to_be_bytes());
                ys.extend((y - py).to_be_bytes());
                (px, py) = (x, y);
            }
            out.extend(ys);
            if out.len() % 2 == 1 {
                out.push(0);
            }
            (out, Some(b))
        }
        Rec::Composite(components, instructions) => {
            let b = components
                .iter()
                .filter_map(|&(g, dx, dy)| boxes[g as usize].map(|b| [b[0] + dx, b[1] + dy, b[2] + dx, b[3] + dy]))
                .reduce(|[a, b, c, d], [e, f, g, h]| [a.min(e), b.min(f), c.max(g), d.max(h)])
                .unwrap();
            out.extend((-1i16).to_be_bytes());
            b.iter().for_each(|v| out.extend(v.to_be_bytes()));
            for (k, &(g, dx, dy)) in components.iter().enumerate() {
                let mut flags: u16 = 0x0001 | 0x0002; // words, x/y values
                if k + 1 < components.len() {
                    flags |= 0x0020;
                } else if !instructions.is_empty() {
                    flags |= 0x0100;
                }
                out.extend(flags.to_be_bytes());
                out.extend(g.to_be_bytes());
                out.extend(dx.to_be_bytes());
                out.extend(dy.to_be_bytes());
            }
            if !instructions.is_empty() {
                out.extend((instructions.len() as u16).to_be_bytes());
                out.extend(instructions);
            }
            if out.len() % 2 == 1 {
                out.push(0);
            }
            (out, Some(b))
        }
    }
}

/// A TrueType font of these glyphs (glyph 0 first), with `fpgm`, `prep` and `cvt ` and
/// `lsb` as given (`None`: the glyph's `xMin`), and `extra` raw tables.
fn tt_font(glyphs: &[(&str, Rec, Option<i16>)], extra: &[(&[u8; 4], Vec<u8>)]) -> Vec<u8> {
    let mut records: Vec<Vec<u8>> = vec![];
    let mut boxes: Vec<Option<[i16; 4]>> = vec![];
    for (_, r, _) in glyphs {
        let (bytes, b) = record(r, &boxes);
        records.push(bytes);
        boxes.push(b);
    }
    let mut glyf = vec![];
    let mut loca = vec![];
    for r in &records {
        loca.extend(((glyf.len() / 2) as u16).to_be_bytes());
        glyf.extend(r);
    }
    loca.extend(((glyf.len() / 2) as u16).to_be_bytes());
    let all =
        boxes.iter().flatten().copied().reduce(|[a, b, c, d], [e, f, g, h]| [a.min(e), b.min(f), c.max(g), d.max(h)]);
    let all = all.unwrap_or([0; 4]);
    let head = Head {
        font_revision: write_fonts::types::Fixed::ONE,
        units_per_em: 1000,
        x_min: all[0],
        y_min: all[1],
        x_max: all[2],
        y_max: all[3],
        index_to_loc_format: 0,
        ..Default::default()
    };
    let lsb: Vec<i16> =
        glyphs.iter().zip(&boxes).map(|((_, _, l), b)| l.unwrap_or_else(|| b.map_or(0, |b| b[0]))).collect();
    let hhea = Hhea {
        ascender: FWord::new(800),
        descender: FWord::new(-200),
        advance_width_max: UfWord::new(1000),
        caret_slope_rise: 1,
        number_of_h_metrics: lsb.len() as u16,
        ..Default::default()
    };
    let hmtx = Hmtx::new(lsb.iter().map(|&l| LongMetric::new(1000, l)).collect(), vec![]);
    let maxp = Maxp {
        num_glyphs: glyphs.len() as u16,
        max_points: Some(0),
        max_contours: Some(0),
        max_composite_points: Some(0),
        max_composite_contours: Some(0),
        max_zones: Some(2),
        max_twilight_points: Some(0),
        max_storage: Some(0),
        max_function_defs: Some(1),
        max_instruction_defs: Some(0),
        max_stack_elements: Some(8),
        max_size_of_instructions: Some(4),
        max_component_elements: Some(0),
        max_component_depth: Some(0),
    };
    let post = Post::new_v2(glyphs.iter().map(|g| g.0));
    let mut b = FontBuilder::new();
    b.add_table(&head).unwrap();
    b.add_table(&hhea).unwrap();
    b.add_table(&maxp).unwrap();
    b.add_table(&hmtx).unwrap();
    b.add_table(&post).unwrap();
    b.add_raw(Tag::new(b"glyf"), glyf);
    b.add_raw(Tag::new(b"loca"), loca);
    b.add_raw(Tag::new(b"fpgm"), vec![0xb0, 0x00, 0x2c, 0x2d]); // PUSHB 0, FDEF, ENDF
    b.add_raw(Tag::new(b"prep"), vec![0xb0, 0x01, 0x1d]);
    b.add_raw(Tag::new(b"cvt "), vec![0, 50, 0, 80]);
    for (tag, data) in extra {
        b.add_raw(Tag::new(tag), data.clone());
    }
    b.build()
}

/// Clockwise (TrueType outer) polygon.
fn tt_poly(pts: &[(i16, i16)]) -> Vec<TtPoint> {
    pts.iter().map(|&(x, y)| on(x, y)).collect()
}

const OVERLAP_UNION: [(i16, i16); 8] =
    [(0, 0), (0, 300), (200, 300), (200, 500), (500, 500), (500, 200), (300, 200), (300, 0)];

/// `.notdef`, `square` (hinted), `overlap` (two crossing squares), `pair` (two overlapping
/// `square` components, hinted), `shifted` (`overlap` moved by 1000), `curve` (quadratics with
/// an implied on-curve point, hinted).
fn tt_test_font(extra: &[(&[u8; 4], Vec<u8>)]) -> Vec<u8> {
    let sq = |x0, y0, x1, y1| tt_poly(&[(x0, y0), (x0, y1), (x1, y1), (x1, y0)]);
    tt_font(
        &[
            (".notdef", Rec::Simple(vec![], vec![]), None),
            ("square", Rec::Simple(vec![sq(0, 0, 400, 400)], vec![0xb0, 0x05]), None),
            ("overlap", Rec::Simple(vec![sq(0, 0, 300, 300), sq(200, 200, 500, 500)], vec![]), None),
            ("pair", Rec::Composite(vec![(1, 0, 0), (1, 300, 0)], vec![0xb0, 0x01, 0x1d]), None),
            ("shifted", Rec::Composite(vec![(2, 1000, 0)], vec![]), None),
            (
                "curve",
                Rec::Simple(
                    vec![vec![on(0, 0), off(0, 100), off(100, 200), on(200, 200), on(200, 0)]],
                    vec![0xb0, 0x02],
                ),
                None,
            ),
        ],
        extra,
    )
}

fn grid(points: &[TtPoint]) -> GridContour {
    GridContour {
        points: points.iter().map(|&(x, y, on_curve)| GridPoint { x: x as i32, y: y as i32, on_curve }).collect(),
    }
}

fn report(g: &GlyphInput, contours: &[GridContour]) -> GlyphReport {
    GlyphReport {
        glyph: g.name.clone(),
        glyph_id: g.glyph_id,
        contours_before: g.components.iter().map(Vec::len).sum(),
        contours_after: contours.len(),
        points_before: 0,
        points_after: contours.iter().map(|c| c.points.len()).sum(),
        distance_bound: rat(0),
        distance_bound_float: 0.0,
        repairs: vec![],
    }
}

/// Decisions by glyph name: these outlines for the glyphs named, `Unchanged` for the others.
fn decide_by_name(
    table: Vec<(&'static str, Vec<GridContour>)>,
) -> impl Fn(&GlyphInput) -> casteljau::Result<GlyphDecision> + Sync {
    move |g| match table.iter().find(|(n, _)| g.name.as_deref() == Some(*n)) {
        Some((_, contours)) => Ok(GlyphDecision::Rewritten { contours: contours.clone(), report: report(g, contours) }),
        None => Ok(GlyphDecision::Unchanged),
    }
}

fn tt_decisions() -> impl Fn(&GlyphInput) -> casteljau::Result<GlyphDecision> + Sync {
    decide_by_name(vec![
        ("overlap", vec![grid(&tt_poly(&OVERLAP_UNION))]),
        ("pair", vec![grid(&tt_poly(&[(0, 0), (0, 400), (700, 400), (700, 0)]))]),
    ])
}

/// The `glyf` records of a font, by `loca`.
fn records(data: &[u8]) -> Vec<Vec<u8>> {
    let f = FontRef::new(data).unwrap();
    let loca = f.loca(None).unwrap();
    let glyf = f.table_data(Tag::new(b"glyf")).unwrap();
    (0..f.maxp().unwrap().num_glyphs() as usize)
        .map(|g| {
            let (a, b) = (loca.get_raw(g).unwrap() as usize, loca.get_raw(g + 1).unwrap() as usize);
            glyf.as_bytes()[a..b].to_vec()
        })
        .collect()
}

/// Every table's checksum and the whole file's sum (OpenType: 0xB1B0AFBA).
fn assert_checksums(data: &[u8]) {
    let sum = |d: &[u8]| {
        d.chunks(4).fold(0u32, |s, c| {
            let mut w = [0u8; 4];
            w[..c.len()].copy_from_slice(c);
            s.wrapping_add(u32::from_be_bytes(w))
        })
    };
    assert_eq!(sum(data), 0xB1B0_AFBA, "checkSumAdjustment");
    let f = FontRef::new(data).unwrap();
    for r in f.table_directory.table_records() {
        let (at, len) = (r.offset() as usize, r.length() as usize);
        let mut t = data[at..at + len].to_vec();
        if r.tag() == Tag::new(b"head") {
            t[8..12].copy_from_slice(&[0; 4]);
        }
        assert_eq!(sum(&t), r.checksum(), "checksum of {}", r.tag());
        assert_eq!(at % 4, 0, "{} aligned", r.tag());
    }
}

fn names(data: &[u8]) -> Vec<Option<String>> {
    let f = Font::open(data, 0).unwrap();
    (0..f.num_glyphs()).map(|g| f.glyph_name(g)).collect()
}

fn outline(data: &[u8], gid: u32) -> Vec<casteljau::format::Contour> {
    Font::open(data, 0).unwrap().outline(gid).unwrap()
}

fn rewritten(o: &FontOutcome) -> Vec<u32> {
    o.glyphs.iter().filter(|(_, d)| matches!(d, Ok(GlyphDecision::Rewritten { .. }))).map(|(g, _)| *g).collect()
}

// ---------------------------------------------------------------------------------------------
// The TrueType writer

#[test]
fn truetype_rewritten_glyphs_are_their_decisions_and_the_others_keep_their_drawing() {
    let input = tt_test_font(&[]);
    let out = write_font(&input, &WriteOptions::default(), &tt_decisions()).unwrap();
    assert_eq!(rewritten(&out), [2, 3]);
    assert_eq!(names(&out.data), names(&input));
    assert_eq!(outline(&out.data, 2), tt_expected(&[tt_poly(&OVERLAP_UNION)]));
    assert_eq!(outline(&out.data, 3), tt_expected(&[tt_poly(&[(0, 0), (0, 400), (700, 400), (700, 0)])]));
    for gid in [1, 5] {
        assert_eq!(outline(&out.data, gid), outline(&input, gid), "glyph {gid}");
    }
    // the composite using a rewritten glyph draws the rewritten outline, moved
    let moved: Vec<TtPoint> = OVERLAP_UNION.iter().map(|&(x, y)| on(x + 1000, y)).collect();
    assert_eq!(outline(&out.data, 4), tt_expected(&[moved]));
    assert_checksums(&out.data);
}

#[test]
fn truetype_unchanged_glyphs_keep_their_bytes_and_lose_only_their_instructions() {
    let input = tt_test_font(&[]);
    let before = records(&input);
    let kept = write_font(&input, &WriteOptions { keep_hinting: true, glyphs: None }, &tt_decisions()).unwrap();
    let after = records(&kept.data);
    for gid in [0, 1, 4, 5] {
        assert_eq!(after[gid], before[gid], "glyph {gid} with --keep-hinting");
    }
    // a rewritten composite is a simple glyph without instructions
    assert_eq!(i16::from_be_bytes([after[3][0], after[3][1]]), 1);
    let stripped = write_font(&input, &WriteOptions::default(), &tt_decisions()).unwrap();
    let after = records(&stripped.data);
    let f = FontRef::new(&stripped.data).unwrap();
    let glyf = f.glyf().unwrap();
    let loca = f.loca(None).unwrap();
    for gid in [1u32, 2, 3, 5] {
        let g = loca.get_glyf(read_fonts::types::GlyphId::new(gid), &glyf).unwrap().unwrap();
        let read_fonts::tables::glyf::Glyph::Simple(s) = g else { panic!("glyph {gid} is simple") };
        assert!(s.instructions().is_empty(), "glyph {gid} has no instructions");
    }
    // the hinted simple glyph: its bytes with the two instruction bytes spliced out
    let mut expected = before[1].clone();
    expected.drain(14..16);
    expected[12..14].copy_from_slice(&[0, 0]);
    assert_eq!(after[1], expected);
    // fpgm, prep, cvt: copied
    let (a, b) = (FontRef::new(&input).unwrap(), FontRef::new(&stripped.data).unwrap());
    for tag in [b"fpgm", b"prep", b"cvt ", b"post"] {
        assert_eq!(
            a.table_data(Tag::new(tag)).unwrap().as_bytes(),
            b.table_data(Tag::new(tag)).unwrap().as_bytes(),
            "{}",
            String::from_utf8_lossy(tag)
        );
    }
}

#[test]
fn truetype_a_glyph_whose_lsb_is_not_its_xmin_is_written_where_it_draws() {
    // stored lsb 7 for xMin 0: FreeType and fontTools draw the glyph 7 units to the right (the
    // origin at xMin − lsb); the rewrite carries the shift and its lsb becomes its xMin, as
    // fontTools' removeOverlaps writes it
    let sq = |x0, y0, x1, y1| tt_poly(&[(x0, y0), (x0, y1), (x1, y1), (x1, y0)]);
    let input = tt_font(
        &[
            (".notdef", Rec::Simple(vec![], vec![]), None),
            ("overlap", Rec::Simple(vec![sq(0, 0, 300, 300), sq(200, 200, 500, 500)], vec![]), Some(7)),
        ],
        &[],
    );
    let out = write_font(&input, &WriteOptions::default(), &tt_decisions()).unwrap();
    let moved: Vec<(i16, i16)> = OVERLAP_UNION.iter().map(|&(x, y)| (x + 7, y)).collect();
    let expected = tt_expected(&[tt_poly(&moved)]);
    assert_eq!(outline(&out.data, 1), expected);
    let f = FontRef::new(&out.data).unwrap();
    let lsb = f.hmtx().unwrap().side_bearing(read_fonts::types::GlyphId::new(1)).unwrap();
    let glyph = records(&out.data)[1].clone();
    assert_eq!((lsb, i16::from_be_bytes([glyph[2], glyph[3]])), (7, 7));
}

#[test]
fn truetype_metrics_and_maxp_follow_the_written_glyphs() {
    let input = tt_test_font(&[]);
    let out = write_font(&input, &WriteOptions::default(), &tt_decisions()).unwrap();
    let f = FontRef::new(&out.data).unwrap();
    let hmtx = f.hmtx().unwrap();
    let lsb = |g: u32| hmtx.side_bearing(read_fonts::types::GlyphId::new(g)).unwrap();
    // the rewritten glyphs' left side bearings are their xMin; the others' stay
    assert_eq!((lsb(2), lsb(3), lsb(4)), (0, 0, 1000));
    let head = f.head().unwrap();
    assert_eq!([head.x_min(), head.y_min(), head.x_max(), head.y_max()], [0, 0, 1500, 500]);
    assert_eq!(head.index_to_loc_format(), 0);
    assert_eq!(head.flags().bits() & 2, 2, "every left side bearing is the glyph's xMin");
    let maxp = f.maxp().unwrap();
    assert_eq!((maxp.max_points(), maxp.max_contours()), (Some(8), Some(1)));
    assert_eq!((maxp.max_composite_points(), maxp.max_composite_contours()), (Some(8), Some(1)));
    assert_eq!((maxp.max_component_elements(), maxp.max_component_depth()), (Some(1), Some(1)));
    // instruction limits are kept (fontTools does not recompute them)
    assert_eq!(maxp.max_size_of_instructions(), Some(4));
    let hhea = f.hhea().unwrap();
    assert_eq!(hhea.min_left_side_bearing().to_i16(), 0);
    assert_eq!(hhea.x_max_extent().to_i16(), 1500);
    assert_eq!(hhea.min_right_side_bearing().to_i16(), -500);
}

#[test]
fn truetype_composite_box_follows_a_rewritten_component() {
    let input = tt_test_font(&[]);
    // a decision whose box is smaller than the glyph's (as when a sliver is dropped)
    let smaller = vec![grid(&tt_poly(&[(0, 0), (0, 300), (300, 300), (300, 0)]))];
    let out = write_font(&input, &WriteOptions::default(), &decide_by_name(vec![("overlap", smaller)])).unwrap();
    let (before, after) = (records(&input), records(&out.data));
    let bbox = |r: &[u8]| (0..4).map(|k| i16::from_be_bytes([r[2 + 2 * k], r[3 + 2 * k]])).collect::<Vec<_>>();
    assert_eq!(bbox(&before[4]), [1000, 0, 1500, 500]);
    assert_eq!(bbox(&after[4]), [1000, 0, 1300, 300]);
    // only the box changed
    assert_eq!(after[4][10..], before[4][10..]);
}

#[test]
fn truetype_glyph_subset_loses_only_its_own_instructions() {
    let input = tt_test_font(&[]);
    let (before, out) = (
        records(&input),
        write_font(&input, &WriteOptions { keep_hinting: false, glyphs: Some(vec![2]) }, &tt_decisions()).unwrap(),
    );
    assert_eq!(out.glyphs.iter().map(|g| g.0).collect::<Vec<_>>(), [2]);
    let after = records(&out.data);
    for gid in [1, 3, 5] {
        assert_eq!(after[gid], before[gid], "glyph {gid}: not considered, hinting kept");
    }
}

#[test]
fn truetype_output_reads_back_in_skrifa() {
    use skrifa::MetadataProvider;
    #[derive(Default)]
    struct Pen(Vec<(char, Vec<f32>)>);
    impl skrifa::outline::OutlinePen for Pen {
        fn move_to(&mut self, x: f32, y: f32) {
            self.0.push(('M', vec![x, y]));
        }
        fn line_to(&mut self, x: f32, y: f32) {
            self.0.push(('L', vec![x, y]));
        }
        fn quad_to(&mut self, a: f32, b: f32, x: f32, y: f32) {
            self.0.push(('Q', vec![a, b, x, y]));
        }
        fn curve_to(&mut self, a: f32, b: f32, c: f32, d: f32, x: f32, y: f32) {
            self.0.push(('C', vec![a, b, c, d, x, y]));
        }
        fn close(&mut self) {
            self.0.push(('Z', vec![]));
        }
    }
    let draw = |data: &[u8], gid: u32| {
        let f = skrifa::FontRef::new(data).unwrap();
        let mut pen = Pen::default();
        let settings = skrifa::outline::DrawSettings::unhinted(
            skrifa::instance::Size::unscaled(),
            skrifa::instance::LocationRef::default(),
        );
        f.outline_glyphs().get(skrifa::GlyphId::new(gid)).unwrap().draw(settings, &mut pen).unwrap();
        pen.0
    };
    let input = tt_test_font(&[]);
    let out = write_font(&input, &WriteOptions::default(), &tt_decisions()).unwrap();
    let union: Vec<(char, Vec<f32>)> = std::iter::once(('M', vec![0.0, 0.0]))
        .chain(OVERLAP_UNION[1..].iter().map(|&(x, y)| ('L', vec![x as f32, y as f32])))
        .chain([('L', vec![0.0, 0.0]), ('Z', vec![])])
        .collect();
    let d = draw(&out.data, 2);
    // skrifa closes with an explicit line or not; compare without it
    let strip =
        |v: Vec<(char, Vec<f32>)>| v.into_iter().filter(|s| !(s.0 == 'L' && s.1 == [0.0, 0.0])).collect::<Vec<_>>();
    assert_eq!(strip(d), strip(union));
    for gid in [1, 5] {
        assert_eq!(draw(&out.data, gid), draw(&input, gid), "glyph {gid}");
    }
}

#[test]
fn truetype_one_point_contours_are_kept_after_the_decided_contours() {
    let anchor = vec![on(50, 60)];
    let square = tt_poly(&[(0, 0), (0, 100), (100, 100), (100, 0)]);
    let input = tt_font(
        &[
            (".notdef", Rec::Simple(vec![], vec![]), None),
            ("a", Rec::Simple(vec![anchor, square.clone(), square.clone()], vec![]), None),
        ],
        &[],
    );
    let out = write_font(&input, &WriteOptions::default(), &decide_by_name(vec![("a", vec![grid(&square)])])).unwrap();
    let f = Font::open(&out.data, 0).unwrap();
    let o = f.outline_numbered(1).unwrap();
    assert_eq!(
        o.contours,
        tt_expected(&[square])
            .into_iter()
            .chain([casteljau::format::Contour { segments: vec![], closed: true }])
            .collect::<Vec<_>>()
    );
    assert_eq!(o.lone_points, [font_builder::pt(50, 60)]);
}

#[test]
fn decide_errors_leave_the_glyph_unchanged_and_unwritable_decisions_are_errors() {
    let input = tt_test_font(&[]);
    let decide = |g: &GlyphInput| match g.glyph_id {
        2 => Err(Error::WorkLimit { what: "a glyph".into(), estimate: 2.0, limit: 1.0, option: "--max-work" }),
        3 => Ok(GlyphDecision::Rewritten {
            // a contour must start on the curve (two control points in a row are fine in
            // TrueType: they imply the on-curve point between them)
            contours: vec![grid(&[off(1, 1), on(0, 0), on(3, 0)])],
            report: report(g, &[]),
        }),
        5 => Ok(GlyphDecision::Rewritten {
            contours: vec![GridContour {
                points: vec![GridPoint { x: 40000, y: 0, on_curve: true }, GridPoint { x: 0, y: 1, on_curve: true }],
            }],
            report: report(g, &[]),
        }),
        _ => Ok(GlyphDecision::Unchanged),
    };
    let out = write_font(&input, &WriteOptions { keep_hinting: true, glyphs: None }, &decide).unwrap();
    let by = |g: u32| &out.glyphs.iter().find(|x| x.0 == g).unwrap().1;
    let Ok(GlyphDecision::Uncertified { reason }) = by(2) else { panic!("{:?}", by(2)) };
    assert!(reason.contains("--max-work"), "{reason}");
    let e = by(3).as_ref().unwrap_err().to_string();
    assert!(e.contains("glyph 3") && e.contains("starts with a control point"), "{e}");
    let e = by(5).as_ref().unwrap_err().to_string();
    assert!(e.contains("glyph 5"), "{e}");
    assert_eq!(records(&out.data), records(&input), "every glyph left as it was");
}

// ---------------------------------------------------------------------------------------------
// Refusals

#[test]
fn variable_fonts_and_cff2_are_refused_naming_the_table() {
    let data =
        std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/fonts/cantarell_vf_trimmed.ttf")).unwrap();
    let e = write_font(&data, &WriteOptions::default(), &|_| Ok(GlyphDecision::Unchanged)).unwrap_err();
    assert!(e.to_string().contains("fvar") && e.to_string().contains("instantiate"), "{e}");
    let with_cff2 = tt_test_font(&[(b"CFF2", vec![2, 0, 5, 0, 0])]);
    let e = write_font(&with_cff2, &WriteOptions::default(), &|_| Ok(GlyphDecision::Unchanged)).unwrap_err();
    assert!(e.to_string().contains("CFF2"), "{e}");
    let mut ttc = b"ttcf".to_vec();
    ttc.extend([0; 12]);
    let e = write_font(&ttc, &WriteOptions::default(), &|_| Ok(GlyphDecision::Unchanged)).unwrap_err();
    assert!(e.to_string().contains("collection"), "{e}");
    let e = write_font(b"not a font at all", &WriteOptions::default(), &|_| Ok(GlyphDecision::Unchanged)).unwrap_err();
    assert!(e.to_string().contains("not an OpenType font"), "{e}");
    let e = write_font(&tt_test_font(&[]), &WriteOptions { keep_hinting: false, glyphs: Some(vec![99]) }, &|_| {
        Ok(GlyphDecision::Unchanged)
    })
    .unwrap_err();
    assert!(e.to_string().contains("glyph 99"), "{e}");
}

// ---------------------------------------------------------------------------------------------
// The CFF writer

fn cff_poly(pts: &[(i16, i16)]) -> Vec<Cmd> {
    std::iter::once(Move(pts[0].0, pts[0].1)).chain(pts[1..].iter().map(|&(x, y)| Line(x, y))).collect()
}

fn cff_grid(cmds: &[Cmd]) -> GridContour {
    let mut points = vec![];
    for c in cmds {
        match *c {
            Move(x, y) | Line(x, y) => points.push((x, y, true)),
            Cmd::Curve(a, b, c, d, x, y) => points.extend([(a, b, false), (c, d, false), (x, y, true)]),
        }
    }
    grid(&points)
}

#[test]
fn cff_rewritten_charstrings_draw_their_decisions_and_the_others_keep_their_bytes() {
    let union: Vec<(i16, i16)> = OVERLAP_UNION.iter().rev().copied().collect(); // counter-clockwise
    let curve = vec![Move(0, 0), Line(300, 0), Cmd::Curve(400, 100, 400, 200, 300, 300), Line(0, 300)];
    let input = font_builder::cff(&[
        CffGlyph::new(
            "overlap",
            vec![
                cff_poly(&[(0, 0), (300, 0), (300, 300), (0, 300)]),
                cff_poly(&[(200, 200), (500, 200), (500, 500), (200, 500)]),
            ],
        ),
        CffGlyph::new("curvy", vec![curve.clone()]),
    ]);
    // a contour closed by a line, one closed by a curve back to its start
    let closing = vec![Move(600, 0), Line(700, 0), Cmd::Curve(750, 50, 750, 100, 700, 150)];
    let curved = vec![Move(0, 600), Line(100, 600), Cmd::Curve(150, 650, 50, 700, 0, 600)];
    let mut curved_grid = cff_grid(&curved);
    curved_grid.points.pop(); // the curve ends on the start point
    let decided = vec![cff_grid(&cff_poly(&union)), cff_grid(&closing), curved_grid];
    let out = write_font(&input, &WriteOptions::default(), &decide_by_name(vec![("overlap", decided)])).unwrap();
    assert_eq!(rewritten(&out), [1]);
    assert_eq!(outline(&out.data, 1), cff_expected(&[cff_poly(&union), closing, curved]));
    assert_eq!(outline(&out.data, 2), cff_expected(&[curve]));
    let charstrings = |d: &[u8]| -> Vec<Vec<u8>> {
        let f = FontRef::new(d).unwrap();
        let cff =
            read_fonts::ps::cff::CffFontRef::new(f.table_data(Tag::new(b"CFF ")).unwrap().as_bytes(), 0, None).unwrap();
        (0..3).map(|g| cff.charstrings().get(g).unwrap().to_vec()).collect()
    };
    let (a, b) = (charstrings(&input), charstrings(&out.data));
    assert_eq!((&a[0], &a[2]), (&b[0], &b[2]));
    assert_ne!(a[1], b[1]);
    assert_eq!(names(&out.data), names(&input));
    assert_checksums(&out.data);
}

#[test]
fn cff_cid_font_with_hints_keeps_every_drawing() {
    let input =
        std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/fonts/NotoSansJP-Regular.subset.otf")).unwrap();
    let font = Font::open(&input, 0).unwrap();
    // glyph 1 rewritten with its own outline (its points are integers)
    let own: Vec<GridContour> = font
        .outline(1)
        .unwrap()
        .iter()
        .map(|c| {
            let mut points = vec![];
            for s in &c.segments {
                let casteljau::format::Segment::Bezier(ps) = s else { unreachable!() };
                let g = |p: &casteljau::Point<num_rational::BigRational>, on_curve| GridPoint {
                    x: p.coords[0].to_integer().try_into().unwrap(),
                    y: p.coords[1].to_integer().try_into().unwrap(),
                    on_curve,
                };
                if points.is_empty() {
                    points.push(g(&ps[0], true));
                }
                for (k, p) in ps.iter().enumerate().skip(1) {
                    points.push(g(p, k + 1 == ps.len()));
                }
            }
            if points.len() > 1 && points.last().map(|p| (p.x, p.y)) == Some((points[0].x, points[0].y)) {
                points.pop();
            }
            GridContour { points }
        })
        .collect();
    for keep_hinting in [false, true] {
        let name = font.glyph_name(1);
        let decide = |g: &GlyphInput| {
            if g.glyph_id == 1 {
                assert_eq!(g.name, name);
                Ok(GlyphDecision::Rewritten { contours: own.clone(), report: report(g, &own) })
            } else {
                Ok(GlyphDecision::Unchanged)
            }
        };
        let out = write_font(&input, &WriteOptions { keep_hinting, glyphs: None }, &decide).unwrap();
        let written = Font::open(&out.data, 0).unwrap();
        for gid in 0..font.num_glyphs() {
            assert_eq!(written.outline(gid).unwrap(), font.outline(gid).unwrap(), "glyph {gid}, keep {keep_hinting}");
        }
        assert_checksums(&out.data);
        // hints gone: the table shrinks; kept: no charstring grows
        let size = |d: &[u8]| FontRef::new(d).unwrap().table_data(Tag::new(b"CFF ")).unwrap().len();
        if !keep_hinting {
            assert!(size(&out.data) < size(&input), "{} < {}", size(&out.data), size(&input));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The command

fn casteljau_lint_json(path: &std::path::Path) -> String {
    let o = run(&["lint", path.to_str().unwrap(), "--json", "--deny", "none", "-q"], None);
    stdout(&o)
}

#[test]
fn cli_refuses_variable_fonts_with_exit_2_and_leaves_the_output_alone() {
    let dir = TempDir::new("ro-refuse");
    let out = dir.write("out.ttf", "old");
    let vf = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/fonts/cantarell_vf_trimmed.ttf");
    let o = run(&["remove-overlaps", vf, "-o", out.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("fvar"), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "old");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1, "no temporary file left");
}

#[test]
fn cli_bad_input_exits_2_naming_it() {
    let dir = TempDir::new("ro-bad");
    let font = dir.join("in.ttf");
    std::fs::write(&font, tt_test_font(&[])).unwrap();
    let out = dir.join("out.ttf");
    let (f, o) = (font.to_str().unwrap(), out.to_str().unwrap());
    let r = run(&["remove-overlaps", f, "-o", o, "square", "nosuch"], None);
    assert_eq!(r.status.code(), Some(2));
    assert!(stderr(&r).contains("no glyph named nosuch"), "{}", stderr(&r));
    assert!(!out.exists());
    let r = run(&["remove-overlaps", dir.join("missing.ttf").to_str().unwrap(), "-o", o], None);
    assert_eq!(r.status.code(), Some(2));
    assert!(stderr(&r).contains("cannot read"), "{}", stderr(&r));
    let r = run(&["remove-overlaps", f, "-o", dir.join("no/such/dir/out.ttf").to_str().unwrap()], None);
    assert_eq!(r.status.code(), Some(2));
    assert!(stderr(&r).contains("cannot write"), "{}", stderr(&r));
    assert!(!out.exists());
}

/// A font without overlaps: `square`, `curve` and a composite of `square`, all hinted.
fn clean_font() -> Vec<u8> {
    let sq = tt_poly(&[(0, 0), (0, 400), (400, 400), (400, 0)]);
    tt_font(
        &[
            (".notdef", Rec::Simple(vec![], vec![]), None),
            ("square", Rec::Simple(vec![sq], vec![0xb0, 0x05]), None),
            (
                "curve",
                Rec::Simple(
                    vec![vec![on(0, 0), off(0, 100), off(100, 200), on(200, 200), on(200, 0)]],
                    vec![0xb0, 0x02],
                ),
                None,
            ),
            ("moved", Rec::Composite(vec![(1, 500, 0)], vec![0xb0, 0x01]), None),
        ],
        &[],
    )
}

#[test]
fn cli_keep_hinting_on_a_font_without_overlaps_keeps_every_glyph_byte_identical() {
    let dir = TempDir::new("ro-clean");
    let font = dir.join("in.ttf");
    std::fs::write(&font, clean_font()).unwrap();
    let out = dir.join("out.ttf");
    let o = run(
        &[
            "remove-overlaps",
            font.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--keep-hinting",
            "--ignore-errors",
            "-q",
        ],
        None,
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains("4 glyphs considered, 0 rewritten"), "{}", stdout(&o));
    let written = std::fs::read(&out).unwrap();
    assert_eq!(records(&written), records(&clean_font()));
    assert_checksums(&written);
}

#[test]
fn cli_a_glyph_over_the_budget_is_left_unchanged_and_fails_the_run() {
    let dir = TempDir::new("ro-budget");
    let font = dir.join("in.ttf");
    std::fs::write(&font, tt_test_font(&[])).unwrap();
    let (out, html) = (dir.join("out.ttf"), dir.join("report.html"));
    let args = [
        "remove-overlaps",
        font.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "overlap",
        "--max-work",
        "1",
        "--json",
        "--keep-hinting",
        "--html",
        html.to_str().unwrap(),
    ];
    let o = run(&args, None);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let report = std::fs::read_to_string(&html).unwrap();
    assert!(report.contains("<h3>Left unchanged</h3>"), "{report}");
    assert!(report.contains("<td>overlap</td><td class=\"n\">2</td>"), "{report}");
    let line: serde_json::Value = serde_json::from_str(stdout(&o).lines().next().unwrap()).unwrap();
    assert_eq!((line["glyph"].as_str(), line["glyph_id"].as_u64()), (Some("overlap"), Some(2)));
    assert!(line["uncertified"].is_string(), "{line}");
    assert_eq!(records(&std::fs::read(&out).unwrap()), records(&tt_test_font(&[])));
    let mut args = args.to_vec();
    args.push("--ignore-errors");
    assert_eq!(run(&args, None).status.code(), Some(0));
}

#[test]
fn cli_removes_overlaps_from_a_truetype_font_end_to_end() {
    let dir = TempDir::new("ro-e2e-tt");
    let font = dir.join("in.ttf");
    std::fs::write(&font, tt_test_font(&[])).unwrap();
    let (out, html) = (dir.join("out.ttf"), dir.join("report.html"));
    let o = run(
        &[
            "remove-overlaps",
            font.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--json",
            "--html",
            html.to_str().unwrap(),
            "--keep-hinting",
        ],
        None,
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let lines: Vec<serde_json::Value> = stdout(&o).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    let glyphs: Vec<&str> = lines.iter().map(|l| l["glyph"].as_str().unwrap()).collect();
    assert_eq!(glyphs, ["overlap", "pair"]);
    for l in &lines {
        assert_eq!(l["contours_before"], 2);
        assert_eq!(l["contours_after"], 1);
        assert!(l["distance_bound"].is_string() && l["distance_bound_float"].as_f64().unwrap() <= 1.0, "{l}");
    }
    let written = std::fs::read(&out).unwrap();
    assert_eq!(outline(&written, 2), tt_expected(&[tt_poly(&OVERLAP_UNION)]));
    let (before, after) = (records(&tt_test_font(&[])), records(&written));
    for gid in [0, 1, 5] {
        assert_eq!(after[gid], before[gid], "glyph {gid}");
    }
    let lint = casteljau_lint_json(&out);
    for kind in ["\"overlap\"", "self_intersection", "overlapping_segments", "\"direction\""] {
        assert!(!lint.contains(kind), "{kind} in {lint}");
    }
    let report = std::fs::read_to_string(&html).unwrap();
    assert_eq!(report.matches("<figure class=\"before\">").count(), 2);
    assert_eq!(report.matches("<figure class=\"after\">").count(), 2);
}

#[test]
fn cli_removes_overlaps_from_a_cff_font_end_to_end() {
    let dir = TempDir::new("ro-e2e-cff");
    let font = dir.join("in.otf");
    let input = font_builder::cff(&[
        CffGlyph::new(
            "overlap",
            vec![
                cff_poly(&[(0, 0), (300, 0), (300, 300), (0, 300)]),
                cff_poly(&[(200, 200), (500, 200), (500, 500), (200, 500)]),
            ],
        ),
        CffGlyph::new("square", vec![cff_poly(&[(0, 0), (300, 0), (300, 300), (0, 300)])]),
    ]);
    std::fs::write(&font, &input).unwrap();
    let out = dir.join("out.otf");
    let o = run(&["remove-overlaps", font.to_str().unwrap(), "-o", out.to_str().unwrap(), "--json"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(stdout(&o).lines().count(), 1);
    let written = std::fs::read(&out).unwrap();
    let union: Vec<(i16, i16)> = OVERLAP_UNION.iter().rev().copied().collect();
    let mut got = outline(&written, 1);
    assert_eq!(got.len(), 1);
    // the same polygon, whatever its start point
    let expected = cff_expected(&[cff_poly(&union)]).remove(0);
    let k = got[0].segments.iter().position(|s| s == &expected.segments[0]).expect("a shared segment");
    got[0].segments.rotate_left(k);
    assert_eq!(got[0], expected);
    assert_eq!(outline(&written, 2), outline(&input, 2));
}
