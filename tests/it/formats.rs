//! Reading users' files exactly: SVG path data (every command, absolute and relative, smooth
//! reflections, implicit repetition, arcs), SVG documents (shapes, nested transforms), and
//! fonts (TrueType `glyf` cross-checked glyph by glyph against `skrifa`; CFF2 against the
//! outlines FreeType extracted for the fontations test suite; CFF).

use casteljau::format::Font;
use casteljau::format::parse_path;
use casteljau::format::read_svg;
use casteljau::format::{Contour, Segment};
use casteljau::internal::parse_transform;
use casteljau::num::NumberMode;
use casteljau::{Point, ratio};
use num_rational::BigRational;

fn exact(d: &str) -> Vec<Contour> {
    parse_path(d, NumberMode::Exact).unwrap()
}

/// Each segment as its control points' exact spelling, `skipped` for skipped pieces.
fn spelled(cs: &[Contour]) -> Vec<Vec<String>> {
    cs.iter()
        .flat_map(|c| c.segments.iter())
        .map(|s| match s {
            Segment::Bezier(ps) => ps.iter().map(|p| p.to_string()).collect(),
            Segment::Skipped { from, to, .. } => vec!["skipped".into(), from.to_string(), to.to_string()],
        })
        .collect()
}

fn v(items: &[&[&str]]) -> Vec<Vec<String>> {
    items.iter().map(|s| s.iter().map(|x| x.to_string()).collect()).collect()
}

#[test]
fn svg_path_every_command_absolute_and_relative_agree() {
    let abs = "M10 10 L20 10 H30 V20 C30 30 40 30 40 20 S50 10 50 20 Q60 30 70 20 T90 20 Z";
    let rel = "m10 10 l10 0 h10 v10 c0 10 10 10 10 0 s10 -10 10 0 q10 10 20 0 t20 0 z";
    assert_eq!(spelled(&exact(abs)), spelled(&exact(rel)));
    assert_eq!(
        spelled(&exact(abs)),
        v(&[
            &["(10, 10)", "(20, 10)"],
            &["(20, 10)", "(30, 10)"],
            &["(30, 10)", "(30, 20)"],
            &["(30, 20)", "(30, 30)", "(40, 30)", "(40, 20)"],
            // S reflects (40, 30) about (40, 20)
            &["(40, 20)", "(40, 10)", "(50, 10)", "(50, 20)"],
            &["(50, 20)", "(60, 30)", "(70, 20)"],
            // T reflects (60, 30) about (70, 20)
            &["(70, 20)", "(80, 10)", "(90, 20)"],
            // Z: the closing line
            &["(90, 20)", "(10, 10)"],
        ])
    );
    assert!(exact(abs)[0].closed);
}

#[test]
fn svg_path_decimals_are_exact_and_binary64_mode_takes_the_double() {
    let cs = exact("M0.1 0.2 L0.3 1e-1");
    assert_eq!(spelled(&cs), v(&[&["(1/10, 1/5)", "(3/10, 1/10)"]]));
    let b = parse_path("M0.1 0 L1 0", NumberMode::Binary64).unwrap();
    let Segment::Bezier(ps) = &b[0].segments[0] else { panic!() };
    assert_eq!(ps[0].coords[0].to_string(), "3602879701896397/36028797018963968");
}

#[test]
fn svg_path_implicit_repetition_after_move_and_curve() {
    // pairs after M are line-tos (relative after m); a second C triple repeats C
    let s = spelled(&exact("m1 1 2 0 0 2 C0 0 1 1 2 2 3 3 4 4 5 5"));
    assert_eq!(s[0], ["(1, 1)", "(3, 1)"]);
    assert_eq!(s[1], ["(3, 1)", "(3, 3)"]);
    assert_eq!(s[3], ["(2, 2)", "(3, 3)", "(4, 4)", "(5, 5)"]);
    assert_eq!(s.len(), 4);
}

#[test]
fn svg_path_smooth_commands_without_a_predecessor_use_the_current_point() {
    let s = spelled(&exact("M0 0 S1 1 2 0 T4 0"));
    assert_eq!(s[0], ["(0, 0)", "(0, 0)", "(1, 1)", "(2, 0)"]);
    // T after S: nothing to reflect
    assert_eq!(s[1], ["(2, 0)", "(2, 0)", "(4, 0)"]);
}

#[test]
fn svg_path_arcs_are_skipped_with_their_ends_never_approximated() {
    let cs = exact("M0 0 A5 5 0 0 1 10 0 a5 5 0 1 0 -10 0");
    assert_eq!(spelled(&cs), v(&[&["skipped", "(0, 0)", "(10, 0)"], &["skipped", "(10, 0)", "(0, 0)"]]));
    let Segment::Skipped { reason, .. } = &cs[0].segments[0] else { panic!() };
    assert!(reason.contains("elliptical arc"), "{reason}");
    // packed flags
    assert_eq!(spelled(&exact("M0 0a5 5 0 015 5")), v(&[&["skipped", "(0, 0)", "(5, 5)"]]));
    // SVG's exact special cases: zero radius is a line, equal ends draw nothing
    assert_eq!(spelled(&exact("M0 0 A0 5 0 0 1 10 0")), v(&[&["(0, 0)", "(10, 0)"]]));
    assert!(spelled(&exact("M1 1 A5 5 0 0 1 1 1")).is_empty());
}

#[test]
fn svg_path_subpaths_restart_after_close_and_move() {
    let cs = exact("M0 0 L1 0 L1 1 Z L2 2 M5 5 L6 5");
    assert_eq!(cs.len(), 3);
    assert!(cs[0].closed && !cs[1].closed && !cs[2].closed);
    // after Z the next segment starts at the subpath's start
    assert_eq!(spelled(std::slice::from_ref(&cs[1])), v(&[&["(0, 0)", "(2, 2)"]]));
    // a zero-length closing line is not added
    assert_eq!(exact("M0 0 L1 0 L0 0 Z")[0].segments.len(), 2);
}

#[test]
fn svg_path_bad_input_names_token_and_column() {
    for (d, col) in [("M0 0 L1 x", "column 9"), ("M0 0 C1 1 2 2", "column 14"), ("M 0 0 L 1/2 1", "column 10")] {
        let e = parse_path(d, NumberMode::Exact).unwrap_err().to_string();
        assert!(e.contains(col), "{d}: {e}");
    }
    assert!(parse_path("M0 0 A5 5 0 2 1 3 3", NumberMode::Exact).unwrap_err().to_string().contains("arc flag"));
    assert!(parse_path("M1e400 0", NumberMode::Binary64).is_err());
}

#[test]
fn svg_transforms_compose_exactly() {
    let m = |t: &str| parse_transform(t, NumberMode::Exact).unwrap();
    let p = Point::new(vec![ratio(1, 1), ratio(2, 1)]);
    let at = |t: &str| m(t).apply(&p).to_string();
    assert_eq!(at("translate(10 20)"), "(11, 22)");
    assert_eq!(at("scale(0.5)"), "(1/2, 1)");
    assert_eq!(at("rotate(90)"), "(-2, 1)");
    assert_eq!(at("rotate(-90, 1 1)"), "(2, 1)");
    assert_eq!(at("skewX(45)"), "(3, 2)");
    assert_eq!(at("matrix(1 2 3 4 5 6)"), "(12, 16)");
    // the list applies right to left: translate(scale(p))
    assert_eq!(at("translate(1,0) scale(3)"), "(4, 6)");
    for bad in ["rotate(30)", "skewY(10)", "scale()", "shear(1)", "translate(1 2"] {
        assert!(parse_transform(bad, NumberMode::Exact).is_err(), "{bad}");
    }
}

const DOC: &str = r#"<?xml version="1.0"?>
<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd">
<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
  <g transform="translate(100 0)">
    <g transform="scale(2 1)">
      <path id="wave" d="M0 0 C1 1 2 1 3 0"/>
    </g>
  </g>
  <rect x="1" y="2" width="10px" height="4"/>
  <rect id="round" x="0" y="0" width="10" height="4" rx="1"/>
  <line x1="0" y1="0" x2="3" y2="4"/>
  <polyline points="0,0 1,1 2,0"/>
  <polygon points="0 0 4 0 4 3"/>
  <circle cx="1" cy="1" r="1"/>
  <g transform="rotate(45)"><line id="tilted" x1="0" y1="0" x2="1" y2="0"/></g>
  <line id="em" x1="1em" y1="0" x2="2" y2="0"/>
  <path id="broken" d="M0 0 L"/>
</svg>"#;

#[test]
fn svg_document_shapes_in_order_with_transforms_applied() {
    let shapes = read_svg(DOC, NumberMode::Exact, &casteljau::work::Budget::unlimited()).unwrap();
    let tags: Vec<&str> = shapes.iter().map(|s| s.tag.as_str()).collect();
    assert_eq!(tags, ["path", "rect", "rect", "line", "polyline", "polygon", "circle", "line", "line", "path"]);
    let ok = |i: usize| spelled(shapes[i].contours.as_ref().unwrap());
    assert_eq!(ok(0), v(&[&["(100, 0)", "(102, 1)", "(104, 1)", "(106, 0)"]]));
    assert_eq!(shapes[0].id.as_deref(), Some("wave"));
    assert_eq!(
        ok(1),
        v(&[&["(1, 2)", "(11, 2)"], &["(11, 2)", "(11, 6)"], &["(11, 6)", "(1, 6)"], &["(1, 6)", "(1, 2)"]])
    );
    // rounded corners: four straight sides and four skipped arcs, in drawing order
    let round = ok(2);
    assert_eq!(round.len(), 8);
    assert_eq!(round[0], ["(1, 0)", "(9, 0)"]);
    assert_eq!(round[1], ["skipped", "(9, 0)", "(10, 1)"]);
    assert_eq!(round[7], ["skipped", "(0, 1)", "(1, 0)"]);
    assert_eq!(ok(3), v(&[&["(0, 0)", "(3, 4)"]]));
    assert_eq!(ok(4).len(), 2);
    assert_eq!(ok(5), v(&[&["(0, 0)", "(4, 0)"], &["(4, 0)", "(4, 3)"], &["(4, 3)", "(0, 0)"]]));
    let problem = |i: usize| shapes[i].contours.as_ref().unwrap_err();
    assert!(problem(6).is_skipped() && problem(6).to_string().contains("not a polynomial Bézier"));
    assert!(problem(7).is_skipped() && problem(7).to_string().contains("irrational"));
    assert!(!problem(8).is_skipped() && problem(8).to_string().contains("1em"));
    assert!(!problem(9).is_skipped() && problem(9).to_string().contains("column"));
    assert_eq!(shapes[9].line, 17);
}

#[test]
fn svg_document_that_is_not_xml_is_an_error() {
    assert!(read_svg("<svg><path d='M0 0'></svg>", NumberMode::Exact, &casteljau::work::Budget::unlimited()).is_err());
}

fn data(name: &str) -> Vec<u8> {
    std::fs::read(format!("{}/tests/data/fonts/{name}", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

#[test]
fn font_truetype_glyph_a_has_exact_implied_midpoints() {
    let d = data("Tuffy.ttf");
    let f = Font::open(&d, 0).unwrap();
    assert!(!f.is_cff());
    let gid = (0..f.num_glyphs()).find(|&g| f.glyph_name(g).as_deref() == Some("a")).unwrap();
    assert_eq!(gid, 68);
    let cs = f.outline(gid).unwrap();
    assert_eq!(cs.len(), 2);
    let s = spelled(&cs);
    // (378, 582) and (238, 443) are off-curve: the on-curve point between them is implied
    assert_eq!(s[0], ["(489, 582)", "(378, 582)", "(308, 1025/2)"]);
    assert_eq!(s[1], ["(308, 1025/2)", "(238, 443)", "(238, 344)"]);
    assert!(cs.iter().all(|c| c.closed));
}

/// A `skrifa` pen recording segments as `f64` control points (closing lines made explicit when
/// they have non-zero length, as casteljau lists them).
#[derive(Default)]
struct Recorder {
    segments: Vec<Vec<(f64, f64)>>,
    start: (f64, f64),
    cur: (f64, f64),
}

impl skrifa::outline::OutlinePen for Recorder {
    fn move_to(&mut self, x: f32, y: f32) {
        self.start = (x as f64, y as f64);
        self.cur = self.start;
    }
    fn line_to(&mut self, x: f32, y: f32) {
        self.segments.push(vec![self.cur, (x as f64, y as f64)]);
        self.cur = (x as f64, y as f64);
    }
    fn quad_to(&mut self, cx0: f32, cy0: f32, x: f32, y: f32) {
        self.segments.push(vec![self.cur, (cx0 as f64, cy0 as f64), (x as f64, y as f64)]);
        self.cur = (x as f64, y as f64);
    }
    fn curve_to(&mut self, cx0: f32, cy0: f32, cx1: f32, cy1: f32, x: f32, y: f32) {
        self.segments.push(vec![self.cur, (cx0 as f64, cy0 as f64), (cx1 as f64, cy1 as f64), (x as f64, y as f64)]);
        self.cur = (x as f64, y as f64);
    }
    fn close(&mut self) {
        if self.cur != self.start {
            self.segments.push(vec![self.cur, self.start]);
        }
        self.cur = self.start;
    }
}

#[test]
fn font_truetype_every_glyph_matches_skrifa_segment_for_segment() {
    use skrifa::MetadataProvider;
    let d = data("Tuffy.ttf");
    let ours = Font::open(&d, 0).unwrap();
    let theirs = skrifa::FontRef::new(&d).unwrap();
    let outlines = theirs.outline_glyphs();
    let (mut compared, mut scaled_glyphs) = (0, 0);
    for gid in 0..ours.num_glyphs() {
        let mut ours_f: Vec<Vec<(f64, f64)>> = ours
            .outline(gid)
            .unwrap()
            .iter()
            .flat_map(|c| c.segments.iter())
            .map(|s| match s {
                Segment::Bezier(ps) => ps.iter().map(|p| (p.to_f64().coords[0], p.to_f64().coords[1])).collect(),
                Segment::Skipped { .. } => unreachable!("fonts have no arcs"),
            })
            .collect();
        let mut pen = Recorder::default();
        let glyph = outlines.get(skrifa::GlyphId::new(gid)).unwrap();
        let settings = skrifa::outline::DrawSettings::unhinted(
            skrifa::instance::Size::unscaled(),
            skrifa::instance::LocationRef::default(),
        );
        glyph.draw(settings, &mut pen).unwrap();
        // the same segments; a contour may start elsewhere, so compare as sorted lists
        let key = |s: &Vec<(f64, f64)>| s.iter().flat_map(|&(x, y)| [x, y]).map(f64::to_bits).collect::<Vec<_>>();
        ours_f.sort_by_key(key);
        pen.segments.sort_by_key(key);
        // the only coordinates that are not integers or halves come from a component scaled by
        // a 2×2 F2Dot14 matrix: casteljau keeps the exact product, skrifa (like FreeType)
        // rounds each transformed point to an integer — there they agree to within 1 unit
        let scaled = ours_f.iter().flatten().any(|&(x, y)| (2.0 * x).fract() != 0.0 || (2.0 * y).fract() != 0.0);
        if scaled {
            scaled_glyphs += 1;
            assert_eq!(ours_f.len(), pen.segments.len(), "glyph {gid}");
            for (a, b) in ours_f.iter().flatten().zip(pen.segments.iter().flatten()) {
                assert!((a.0 - b.0).abs() <= 1.0 && (a.1 - b.1).abs() <= 1.0, "glyph {gid}: {a:?} {b:?}");
            }
        } else {
            assert_eq!(ours_f, pen.segments, "glyph {gid}");
        }
        compared += ours_f.len();
    }
    assert!(compared > 40_000, "{compared}");
    assert!(scaled_glyphs < 20, "{scaled_glyphs}");
}

/// A glyph's segments as integer control points.
type IntSegments = Vec<Vec<(i64, i64)>>;

/// FreeType's unscaled outlines from the fontations test data: `glyph <id>`, `coords <normalized
/// coordinate>`, then `m x,y`, `l x,y`, `c x,y x,y x,y` lines (integers: FreeType rounds to font
/// units).
fn freetype_outlines(text: &str) -> Vec<(u32, f32, IntSegments)> {
    let mut out = vec![];
    for block in text.split("\n-\n") {
        let mut lines = block.lines();
        let Some(head) = lines.next() else { continue };
        let Some(id) = head.strip_prefix("glyph ") else { continue };
        let gid: u32 = id.split_whitespace().next().unwrap().parse().unwrap();
        let mut coord = 0.0f32;
        let mut segs = vec![];
        let mut cur = (0, 0);
        for l in lines {
            let mut parts = l.split_whitespace();
            let op = parts.next().unwrap();
            if op == "coords" {
                coord = parts.next().unwrap().parse().unwrap();
                continue;
            }
            if !matches!(op, "m" | "l" | "c") {
                continue;
            }
            let pts: Vec<(i64, i64)> = parts
                .map(|p| {
                    let (x, y) = p.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect();
            if op == "m" {
                cur = pts[0];
            } else {
                let mut s = vec![cur];
                s.extend(&pts);
                cur = *pts.last().unwrap();
                segs.push(s);
            }
        }
        out.push((gid, coord, segs));
    }
    out
}

#[test]
fn font_cff2_instances_match_freetype() {
    let d = data("cantarell_vf_trimmed.ttf");
    let mut f = Font::open(&d, 0).unwrap();
    assert!(f.is_cff());
    assert_eq!(f.axes().len(), 1);
    let expected = freetype_outlines(&String::from_utf8(data("cantarell_vf_trimmed-freetype.txt")).unwrap());
    assert_eq!(expected.len(), 30); // 6 glyphs at 5 instances
    let mut fractional = 0;
    for (gid, coord, segs) in expected {
        let raw = (coord as f64 * 16384.0).round() as i16;
        f.set_normalized(vec![read_fonts::types::F2Dot14::from_bits(raw)]).unwrap();
        let ours: Vec<Vec<Point<BigRational>>> = f
            .outline(gid)
            .unwrap()
            .into_iter()
            .flat_map(|c| c.segments)
            .map(|s| match s {
                Segment::Bezier(ps) => ps,
                Segment::Skipped { .. } => unreachable!(),
            })
            .collect();
        // the default instance is integral and equal; at other instances the 16.16 blend gives
        // fractions, which FreeType's unscaled outline turns into integers by its own rounding
        // (neither floor nor nearest throughout): within one unit of the exact value, per
        // coordinate — an instance blended wrongly would be off by tens of units
        let flat: Vec<&Point<BigRational>> = ours.iter().flatten().collect();
        let theirs: Vec<&(i64, i64)> = segs.iter().flatten().collect();
        assert_eq!(ours.iter().map(Vec::len).collect::<Vec<_>>(), segs.iter().map(Vec::len).collect::<Vec<_>>());
        for (p, q) in flat.iter().zip(&theirs) {
            for (x, y) in p.coords.iter().zip([q.0, q.1]) {
                fractional += usize::from(!x.is_integer());
                let diff = x - BigRational::from_integer(y.into());
                assert!(
                    diff < BigRational::from_integer(1.into()) && diff > BigRational::from_integer((-1).into()),
                    "glyph {gid} at {coord}: {x} vs {y}"
                );
            }
        }
        if coord == 0.0 {
            assert!(ours.iter().flatten().all(|p| p.coords.iter().all(|x| x.is_integer())));
        }
    }
    assert!(fractional > 0, "the instances should exercise fractional 16.16 coordinates");
    // user coordinates: the axis range is clamped, unknown axes and glyf fonts refused
    let (tag, min, _, max) = f.axes()[0].clone();
    f.set_variation(&[(tag.clone(), max + 100.0)]).unwrap();
    assert_eq!(f.normalized()[0].to_f32(), 1.0);
    f.set_variation(&[(tag, min)]).unwrap();
    assert_eq!(f.normalized()[0].to_f32(), -1.0);
    assert!(f.set_variation(&[("zzzz".into(), 1.0)]).is_err());
    let tuffy = data("Tuffy.ttf");
    assert!(Font::open(&tuffy, 0).unwrap().set_variation(&[("wght".into(), 700.0)]).is_err());
}

#[test]
fn font_cff_outlines_are_closed_cubics_and_lines_with_exact_fixed_coordinates() {
    let d = data("NotoSansJP-Regular.subset.otf");
    assert_eq!(Font::count(&d).unwrap(), 1);
    let f = Font::open(&d, 0).unwrap();
    assert!(f.is_cff());
    let mut cubics = 0;
    for gid in 0..f.num_glyphs() {
        for c in f.outline(gid).unwrap() {
            assert!(c.closed);
            let ends: Vec<(&Point<BigRational>, &Point<BigRational>)> = c
                .segments
                .iter()
                .map(|s| match s {
                    Segment::Bezier(ps) => {
                        cubics += usize::from(ps.len() == 4);
                        assert!(ps.len() == 2 || ps.len() == 4);
                        (&ps[0], &ps[ps.len() - 1])
                    }
                    Segment::Skipped { .. } => unreachable!(),
                })
                .collect();
            // consecutive segments join and the contour closes on itself
            for w in ends.windows(2) {
                assert_eq!(w[0].1, w[1].0);
            }
            assert_eq!(ends.last().unwrap().1, ends[0].0);
        }
    }
    assert!(cubics > 0);
    assert!(Font::open(&d, 1).is_err());
    assert!(Font::count(b"not a font").is_err());
    assert!(f.outline(f.num_glyphs()).is_err());
}
