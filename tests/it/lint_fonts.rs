//! The planted-defect fonts of `casteljau lint`, built with `font_builder`: one glyph per defect
//! kind, named after its kind, each with exactly one planted defect and otherwise clean, plus
//! `clean_*` glyphs with no defect at all ([`planted_truetype`], [`planted_cff`], [`PLANTED_TT`],
//! [`PLANTED_CFF`]). [`census`] is an independent exact check of the local and pairwise
//! properties each kind names (built on the crate's classification, extrema and intersections),
//! used to verify the planted geometry; then the real command must find each planted defect and
//! nothing else.

use crate::font_builder::*;
use casteljau::format::{Contour, Font, Segment};
use casteljau::intersect::{Contact, Domain};
use casteljau::num::ratio_to_f64;
use casteljau::rational::{BoundingBox, bounding_box};

/// The exact box of a polynomial curve (as a rational one of unit weights), no work limit.
fn bounding_box_polynomial(c: &casteljau::BezierCurve<num_rational::BigRational>) -> casteljau::Result<BoundingBox> {
    bounding_box(&c.clone().into(), &casteljau::work::Budget::unlimited())
}
use casteljau::{BezierCurve, Scalar, classify, rat};
use num_rational::BigRational;
use num_traits::Signed;
use std::collections::BTreeSet;

/// Two polynomial curves' intersections (as rational curves of unit weights), no work limit.
fn intersect_polynomial(
    a: &casteljau::BezierCurve<num_rational::BigRational>,
    b: &casteljau::BezierCurve<num_rational::BigRational>,
    domain: Domain,
) -> casteljau::Result<casteljau::intersect::Intersections> {
    casteljau::intersect::intersect(&a.clone().into(), &b.clone().into(), domain, &casteljau::work::Budget::unlimited())
}

// ---------------------------------------------------------------------------------------------
// The planted-defect set

/// `(glyph name, primary kind, other kinds a lint may also report for that glyph)`.
pub type Planted = (&'static str, &'static str, &'static [&'static str]);

/// The planted TrueType glyphs. The extra kinds allowed:
/// * `self_intersection` (bow-tie): its two lobes turn opposite ways (total area 0), so its
///   `direction` is undecidable and may be reported;
/// * `overlapping_segments`: the two squares also touch at the ends of the shared piece;
/// * `missing_extremum`: the outline's top (y = 300) is below the off-curve point (y = 500),
///   so a `bbox` check against the exact outline (not the points) differs by 200;
/// * `zero_length_segment`: the doubled point lies on the edge's line (`collinear_points`).
pub const PLANTED_TT: &[Planted] = &[
    ("direction", "direction", &[]),
    ("self_intersection", "self_intersection", &["direction"]),
    ("overlap", "overlap", &[]),
    ("touching", "touching", &[]),
    ("overlapping_segments", "overlapping_segments", &["touching"]),
    ("missing_extremum", "missing_extremum", &["bbox"]),
    ("kink", "kink", &[]),
    ("collinear_points", "collinear_points", &[]),
    ("zero_length_segment", "zero_length_segment", &["collinear_points"]),
    ("degenerate_curve", "degenerate_curve", &[]),
    ("bbox", "bbox", &[]),
    ("zero_length_handle", "zero_length_handle", &[]),
    ("cusp", "cusp", &["overlapping_segments", "self_intersection", "missing_extremum"]),
];

/// The planted CFF glyphs. The extra kinds allowed, besides those of [`PLANTED_TT`]:
/// * `cusp`: the cusp is the curve's top (a horizontal and vertical tangent inside:
///   `missing_extremum`) and a singular point (may be taken as a `self_intersection`);
/// * `loop`: the loop crosses itself (`self_intersection`), has vertical tangents inside
///   (`missing_extremum`), and its small lobe turns against the contour (`direction`);
/// * `zero_length_handle`: the tangent vanishes at the curve's start, which `classify` counts
///   as a cusp at `t = 0` (`cusp`).
pub const PLANTED_CFF: &[Planted] = &[
    ("direction", "direction", &[]),
    ("self_intersection", "self_intersection", &["direction"]),
    ("overlap", "overlap", &[]),
    ("touching", "touching", &[]),
    ("overlapping_segments", "overlapping_segments", &["touching"]),
    ("missing_extremum", "missing_extremum", &[]),
    ("kink", "kink", &[]),
    ("collinear_points", "collinear_points", &[]),
    ("zero_length_segment", "zero_length_segment", &["collinear_points"]),
    ("zero_length_handle", "zero_length_handle", &["cusp"]),
    ("degenerate_curve", "degenerate_curve", &[]),
    ("cusp", "cusp", &["missing_extremum", "self_intersection"]),
    ("loop", "loop", &["self_intersection", "missing_extremum", "direction"]),
];

/// The clean glyphs of both sets: no finding at all.
pub const CLEAN: &[&str] = &["clean_square", "clean_square_hole", "clean_circle", "clean_o"];

/// The clean TrueType glyphs ([`CLEAN`]).
pub fn clean_tt_glyphs() -> Vec<TtGlyph> {
    vec![
        TtGlyph::new("clean_square", vec![tt_square(100, 100, 500, 500)]),
        TtGlyph::new("clean_square_hole", vec![tt_square(100, 100, 600, 600), tt_square_ccw(250, 250, 450, 450)]),
        // a circle of radius 200 about (300, 300): nodes at the extrema, control points at the
        // corners of the square around it (handles axis-aligned), clockwise
        TtGlyph::new(
            "clean_circle",
            vec![vec![
                on(300, 100),
                off(100, 100),
                on(100, 300),
                off(100, 500),
                on(300, 500),
                off(500, 500),
                on(500, 300),
                off(500, 100),
            ]],
        ),
        // a ring: the outer circle of off-curve points only (its nodes are the implied midpoints
        // (300,100), (100,300), (300,500), (500,300)), clockwise; the inner of radius 100,
        // explicit nodes, counter-clockwise
        TtGlyph::new(
            "clean_o",
            vec![
                vec![off(100, 100), off(100, 500), off(500, 500), off(500, 100)],
                vec![
                    on(300, 200),
                    off(400, 200),
                    on(400, 300),
                    off(400, 400),
                    on(300, 400),
                    off(200, 400),
                    on(200, 300),
                    off(200, 200),
                ],
            ],
        ),
    ]
}

/// The planted TrueType glyphs ([`PLANTED_TT`]), in that order.
pub fn planted_tt_glyphs() -> Vec<TtGlyph> {
    vec![
        // a square drawn counter-clockwise
        TtGlyph::new("direction", vec![tt_square_ccw(100, 100, 500, 500)]),
        // a bow-tie: the diagonals cross at (300, 300)
        TtGlyph::new("self_intersection", vec![vec![on(100, 100), on(500, 500), on(500, 100), on(100, 500)]]),
        // two clockwise squares crossing at (400, 250) and (250, 400)
        TtGlyph::new("overlap", vec![tt_square(100, 100, 400, 400), tt_square(250, 250, 550, 550)]),
        // two clockwise squares sharing the corner (300, 300)
        TtGlyph::new("touching", vec![tt_square(100, 100, 300, 300), tt_square(300, 300, 500, 500)]),
        // two clockwise squares side by side sharing x = 300, 200 ≤ y ≤ 300
        TtGlyph::new("overlapping_segments", vec![tt_square(100, 100, 300, 300), tt_square(300, 200, 500, 400)]),
        // an arch (100,100) (300,500) (500,100): its top (300, 300) at t = 1/2 is not a node
        TtGlyph::new("missing_extremum", vec![vec![on(100, 100), off(300, 500), on(500, 100)]]),
        // two quadratics meeting at (400, 400): in (200, 200), out (207, 193), a turn of 2.0°
        TtGlyph::new(
            "kink",
            vec![vec![on(0, 200), off(200, 200), on(400, 400), off(607, 593), on(800, 593), on(800, 0), on(0, 0)]],
        ),
        // a square whose left edge is split at its midpoint (100, 300)
        TtGlyph::new(
            "collinear_points",
            vec![vec![on(100, 100), on(100, 300), on(100, 500), on(500, 500), on(500, 100)]],
        ),
        // a square with its corner (100, 500) written twice
        TtGlyph::new(
            "zero_length_segment",
            vec![vec![on(100, 100), on(100, 500), on(100, 500), on(500, 500), on(500, 100)]],
        ),
        // a square whose left edge is a quadratic with its control point at the edge's midpoint
        TtGlyph::new(
            "degenerate_curve",
            vec![vec![on(100, 100), off(100, 300), on(100, 500), on(500, 500), on(500, 100)]],
        ),
        // a square whose stored x_max is 510, not 500
        TtGlyph::new("bbox", vec![tt_square(100, 100, 500, 500)]).with_bbox([100, 100, 510, 500]),
        // a square whose right edge is a quadratic with its off-curve point on its start (500, 500),
        // as DejaVu Sans has 2,771 of them
        TtGlyph::new(
            "zero_length_handle",
            vec![vec![on(100, 100), on(100, 500), on(500, 500), off(500, 500), on(500, 100)]],
        ),
        // a square whose right edge is a quadratic with its control point above its start: it
        // runs up to y = 1550/3 at t = 1/6, turns back (a cusp of a collinear curve) and down
        TtGlyph::new("cusp", vec![vec![on(100, 100), on(100, 500), on(500, 500), off(500, 600), on(500, 100)]]),
    ]
}

/// The font of the planted and the clean TrueType glyphs, and `(glyph name, primary kind)` of
/// each planted one ([`PLANTED_TT`] has the kinds also allowed).
pub fn planted_truetype() -> (Vec<u8>, Vec<(&'static str, &'static str)>) {
    let glyphs: Vec<TtGlyph> = planted_tt_glyphs().into_iter().chain(clean_tt_glyphs()).collect();
    (truetype(&glyphs), PLANTED_TT.iter().map(|&(n, k, _)| (n, k)).collect())
}

/// The font of the clean TrueType glyphs only.
pub fn clean_truetype() -> Vec<u8> {
    truetype(&clean_tt_glyphs())
}

/// The clean CFF glyphs ([`CLEAN`]).
pub fn clean_cff_glyphs() -> Vec<CffGlyph> {
    // a circle of radius 200 about (300, 300), counter-clockwise, handles 110 long
    let circle = vec![
        Move(300, 100),
        Curve(410, 100, 500, 190, 500, 300),
        Curve(500, 410, 410, 500, 300, 500),
        Curve(190, 500, 100, 410, 100, 300),
        Curve(100, 190, 190, 100, 300, 100),
    ];
    // radius 100, clockwise, handles 55 long
    let inner = vec![
        Move(300, 200),
        Curve(245, 200, 200, 245, 200, 300),
        Curve(200, 355, 245, 400, 300, 400),
        Curve(355, 400, 400, 355, 400, 300),
        Curve(400, 245, 355, 200, 300, 200),
    ];
    vec![
        CffGlyph::new("clean_square", vec![cff_square(100, 100, 500, 500)]),
        CffGlyph::new("clean_square_hole", vec![cff_square(100, 100, 600, 600), cff_square_cw(250, 250, 450, 450)]),
        CffGlyph::new("clean_circle", vec![circle.clone()]),
        CffGlyph::new("clean_o", vec![circle, inner]),
    ]
}

/// The planted CFF glyphs ([`PLANTED_CFF`]), in that order.
pub fn planted_cff_glyphs() -> Vec<CffGlyph> {
    vec![
        // a square drawn clockwise
        CffGlyph::new("direction", vec![cff_square_cw(100, 100, 500, 500)]),
        // a bow-tie: the diagonals cross at (300, 300)
        CffGlyph::new("self_intersection", vec![vec![Move(100, 100), Line(500, 500), Line(500, 100), Line(100, 500)]]),
        // two counter-clockwise squares crossing at (400, 250) and (250, 400)
        CffGlyph::new("overlap", vec![cff_square(100, 100, 400, 400), cff_square(250, 250, 550, 550)]),
        // two counter-clockwise squares sharing the corner (300, 300)
        CffGlyph::new("touching", vec![cff_square(100, 100, 300, 300), cff_square(300, 300, 500, 500)]),
        // two counter-clockwise squares side by side sharing x = 300, 200 ≤ y ≤ 300
        CffGlyph::new("overlapping_segments", vec![cff_square(100, 100, 300, 300), cff_square(300, 200, 500, 400)]),
        // an arch (500,100) (400,400) (200,400) (100,100): its top (300, 325) at t = 1/2 is not a node
        CffGlyph::new("missing_extremum", vec![vec![Move(500, 100), Curve(400, 400, 200, 400, 100, 100)]]),
        // two cubics meeting at (400, 400): in (-207, -193), out (-200, -200), a turn of 2.0°
        CffGlyph::new(
            "kink",
            vec![vec![
                Move(0, 200),
                Line(0, 0),
                Line(800, 0),
                Line(800, 593),
                Curve(700, 593, 607, 593, 400, 400),
                Curve(200, 200, 150, 200, 0, 200),
            ]],
        ),
        // a square whose bottom edge is split at its midpoint (300, 100)
        CffGlyph::new(
            "collinear_points",
            vec![vec![Move(100, 100), Line(300, 100), Line(500, 100), Line(500, 500), Line(100, 500)]],
        ),
        // a square with its corner (500, 100) written twice (`0 0 rlineto`)
        CffGlyph::new(
            "zero_length_segment",
            vec![vec![Move(100, 100), Line(500, 100), Line(500, 100), Line(500, 500), Line(100, 500)]],
        ),
        // a quarter disc whose cubic's first control point is its start (500, 100)
        CffGlyph::new(
            "zero_length_handle",
            vec![vec![Move(100, 100), Line(500, 100), Curve(500, 100, 500, 500, 100, 500)]],
        ),
        // a square whose left edge is a cubic with control points at 1/3 and 2/3 of it
        CffGlyph::new(
            "degenerate_curve",
            vec![vec![
                Move(100, 100),
                Line(700, 100),
                Line(700, 700),
                Line(100, 700),
                Curve(100, 500, 100, 300, 100, 100),
            ]],
        ),
        // the cusp cubic (400,100) (100,400) (400,400) (100,100): cusp at t = 1/2, (250, 325)
        CffGlyph::new("cusp", vec![vec![Move(400, 100), Curve(100, 400, 400, 400, 100, 100)]]),
        // a cubic with a loop: (400,100) (0,400) (500,400) (100,100), crossing itself at (250, 250)
        // (t = 1/2 ∓ √3/6)
        CffGlyph::new("loop", vec![vec![Move(400, 100), Curve(0, 400, 500, 400, 100, 100)]]),
    ]
}

/// The font of the planted and the clean CFF glyphs, and `(glyph name, primary kind)` of each
/// planted one ([`PLANTED_CFF`] has the kinds also allowed).
pub fn planted_cff() -> (Vec<u8>, Vec<(&'static str, &'static str)>) {
    let glyphs: Vec<CffGlyph> = planted_cff_glyphs().into_iter().chain(clean_cff_glyphs()).collect();
    (cff(&glyphs), PLANTED_CFF.iter().map(|&(n, k, _)| (n, k)).collect())
}

/// The font of the clean CFF glyphs only.
pub fn clean_cff() -> Vec<u8> {
    cff(&clean_cff_glyphs())
}

/// The glyph id of `name`.
pub fn gid(font: &Font<'_>, name: &str) -> u32 {
    (0..font.num_glyphs()).find(|&g| font.glyph_name(g).as_deref() == Some(name)).expect(name)
}

// ---------------------------------------------------------------------------------------------
// Tests

fn p(x: i64, y: i64) -> P {
    pt(x, y)
}

#[test]
fn font_builder_truetype_round_trip() {
    let glyphs: Vec<TtGlyph> = planted_tt_glyphs().into_iter().chain(clean_tt_glyphs()).collect();
    let data = truetype(&glyphs);
    let font = Font::open(&data, 0).unwrap();
    assert!(!font.is_cff());
    assert_eq!(font.num_glyphs() as usize, glyphs.len() + 1);
    assert_eq!(font.glyph_name(0).as_deref(), Some(".notdef"));
    assert!(font.outline(0).unwrap().is_empty());
    for (k, g) in glyphs.iter().enumerate() {
        let gid = k as u32 + 1;
        assert_eq!(font.glyph_name(gid).as_deref(), Some(g.name.as_str()));
        assert_eq!(font.outline(gid).unwrap(), tt_expected(&g.contours), "{}", g.name);
        let off = stored_bbox_off(&data, gid);
        assert_eq!(off, if g.name == "bbox" { 10 } else { 0 }, "{}", g.name);
    }
    // written out by hand: the ring's outer contour of off-curve points only starts at the
    // implied midpoint of its last and first points
    let o = font.outline(gid(&font, "clean_o")).unwrap();
    assert_eq!(
        o[0].segments,
        vec![
            seg(&[&p(300, 100), &p(100, 100), &p(100, 300)]),
            seg(&[&p(100, 300), &p(100, 500), &p(300, 500)]),
            seg(&[&p(300, 500), &p(500, 500), &p(500, 300)]),
            seg(&[&p(500, 300), &p(500, 100), &p(300, 100)]),
        ]
    );
    let arch = font.outline(gid(&font, "missing_extremum")).unwrap();
    assert_eq!(
        arch[0].segments,
        vec![seg(&[&p(100, 100), &p(300, 500), &p(500, 100)]), seg(&[&p(500, 100), &p(100, 100)])]
    );
    let z = font.outline(gid(&font, "zero_length_segment")).unwrap();
    assert_eq!(z[0].segments[1], seg(&[&p(100, 500), &p(100, 500)]));
    // head's bounding box: the union of the points, or as given
    let head = |data: &[u8]| {
        use read_fonts::TableProvider;
        let h = read_fonts::FontRef::new(data).unwrap().head().unwrap();
        [h.x_min(), h.y_min(), h.x_max(), h.y_max()]
    };
    assert_eq!(head(&data), [0, 0, 800, 600]);
    let other = truetype_with_head_bbox(&glyphs, Some([-5, -6, 700, 800]));
    assert_eq!(head(&other), [-5, -6, 700, 800]);
}

#[test]
fn font_builder_cff_round_trip() {
    let glyphs: Vec<CffGlyph> = planted_cff_glyphs().into_iter().chain(clean_cff_glyphs()).collect();
    let data = cff(&glyphs);
    assert_eq!(&data[..4], b"OTTO");
    let font = Font::open(&data, 0).unwrap();
    assert!(font.is_cff());
    assert_eq!(font.num_glyphs() as usize, glyphs.len() + 1);
    assert_eq!(font.glyph_name(0).as_deref(), Some(".notdef"));
    assert!(font.outline(0).unwrap().is_empty());
    for (k, g) in glyphs.iter().enumerate() {
        let gid = k as u32 + 1;
        assert_eq!(font.glyph_name(gid).as_deref(), Some(g.name.as_str()));
        assert_eq!(font.outline(gid).unwrap(), cff_expected(&g.contours), "{}", g.name);
    }
    // written out by hand: the closing line is listed only when non-zero
    let cusp = font.outline(gid(&font, "cusp")).unwrap();
    assert_eq!(
        cusp[0].segments,
        vec![seg(&[&p(400, 100), &p(100, 400), &p(400, 400), &p(100, 100)]), seg(&[&p(100, 100), &p(400, 100)])]
    );
    let kink = font.outline(gid(&font, "kink")).unwrap();
    assert_eq!(kink[0].segments.len(), 5);
    let z = font.outline(gid(&font, "zero_length_segment")).unwrap();
    assert_eq!(z[0].segments[1], seg(&[&p(500, 100), &p(500, 100)]));
    // a second contour's moveto is relative to the last point written
    let o = font.outline(gid(&font, "clean_o")).unwrap();
    assert_eq!(o[1].segments[0], seg(&[&p(300, 200), &p(245, 200), &p(200, 245), &p(200, 300)]));
}

#[test]
fn font_builder_large_operands_and_names() {
    // operands in all four encodings, and names in the String INDEX that are also standard
    // strings ("A", "space")
    let g = CffGlyph::new(
        "A",
        vec![vec![
            Move(-20000, -2000),
            Line(-1000, -2000),
            Line(-1000, 20000),
            Curve(-800, 20100, 100, 21000, -20000, 107),
        ]],
    );
    let h = CffGlyph::new("space", vec![]);
    let data = cff(&[g.clone(), h]);
    let font = Font::open(&data, 0).unwrap();
    assert_eq!(font.glyph_name(1).as_deref(), Some("A"));
    assert_eq!(font.glyph_name(2).as_deref(), Some("space"));
    assert_eq!(font.outline(1).unwrap(), cff_expected(&g.contours));
    assert!(font.outline(2).unwrap().is_empty());
    // a given .notdef stays glyph 0
    let t = TtGlyph::new(".notdef", vec![tt_square(0, 0, 10, 10)]);
    let data = truetype(std::slice::from_ref(&t));
    let font = Font::open(&data, 0).unwrap();
    assert_eq!(font.num_glyphs(), 1);
    assert_eq!(font.outline(0).unwrap(), tt_expected(&t.contours));
}

// ---------------------------------------------------------------------------------------------
// An independent exact census of the properties the lint kinds name

fn curves(contour: &Contour) -> Vec<BezierCurve<BigRational>> {
    contour
        .segments
        .iter()
        .map(|s| match s {
            Segment::Bezier(ps) => BezierCurve::new(ps.clone()).unwrap(),
            Segment::Skipped { .. } => panic!("a font segment is never skipped"),
        })
        .collect()
}

/// `∮ x dy` of a Bézier curve (Green: the contour's signed area is the sum over its segments;
/// positive counter-clockwise, y up).
fn x_dy(c: &BezierCurve<BigRational>) -> BigRational {
    let power = c.power_coefficients();
    let (x, y): (Vec<_>, Vec<_>) = power.iter().map(|p| (p.coords[0].clone(), p.coords[1].clone())).unzip();
    // ∫₀¹ x(t) y'(t) dt = Σ_{i, j≥1} x_i j y_j / (i + j)
    let mut sum = rat(0);
    for (i, xi) in x.iter().enumerate() {
        for (j, yj) in y.iter().enumerate().skip(1) {
            sum += xi * yj * rat(j as i64) / rat((i + j) as i64);
        }
    }
    sum
}

/// The signed area of a closed contour (positive: counter-clockwise with y up).
pub fn signed_area(contour: &Contour) -> BigRational {
    curves(contour).iter().map(x_dy).sum()
}

fn is_point(c: &BezierCurve<BigRational>) -> bool {
    c.points().iter().all(|p| p == &c.points()[0])
}

fn sub(a: &P, b: &P) -> [BigRational; 2] {
    [&a.coords[0] - &b.coords[0], &a.coords[1] - &b.coords[1]]
}

/// The tangent direction leaving the start (`end = false`) or reaching the end of a curve: to
/// or from the nearest control point distinct from that end.
fn tangent(c: &BezierCurve<BigRational>, end: bool) -> Option<[BigRational; 2]> {
    let ps = c.points();
    if end {
        let last = ps.last().unwrap();
        ps.iter().rev().find(|p| *p != last).map(|p| sub(last, p))
    } else {
        ps.iter().find(|p| *p != &ps[0]).map(|p| sub(p, &ps[0]))
    }
}

fn bbox_of(cs: &[BezierCurve<BigRational>]) -> [f64; 4] {
    let mut b = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];
    for p in cs.iter().flat_map(|c| c.points()) {
        let (x, y) = (ratio_to_f64(&p.coords[0]), ratio_to_f64(&p.coords[1]));
        b = [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)];
    }
    b
}

/// The lint kinds a glyph's outline exhibits, by exact reference definitions (a small
/// independent lint for the planted set; `kink` below 10°, `missing_extremum` beyond one unit):
/// * `direction`: a contour of zero area, or whose area sign is not that of its nesting depth
///   (depth by bounding-box containment; outer: clockwise for TrueType, counter-clockwise for CFF);
/// * `self_intersection`: two segments of one contour meeting anywhere but at their shared node;
/// * `overlap` / `touching` / `overlapping_segments`: two contours crossing inside both segments /
///   meeting only at an end or tangentially / sharing an arc of positive length;
/// * `missing_extremum`: a stationary point of x or y strictly inside a segment, beyond both
///   ends' values by more than one unit;
/// * `kink`: distinct tangents at a node, turning by less than 10°;
/// * `collinear_points`: a node between two lines going on in the same direction;
/// * `zero_length_segment`: a segment that is a single point;
/// * `zero_length_handle`: a curve with a control point on its adjacent end (not all equal);
/// * `degenerate_curve`: a curve of real degree below its written degree;
/// * `cusp` / `loop`: `classify` finds a cusp strictly inside (a quadratic's too: the turning
///   point of a collinear one) / a cubic's loop on `[0, 1]`.
/// * `bbox` is not a property of the outline: see [`stored_bbox_off`].
pub fn census(contours: &[Contour], truetype: bool) -> BTreeSet<&'static str> {
    let mut kinds = BTreeSet::new();
    let cs: Vec<Vec<BezierCurve<BigRational>>> = contours.iter().map(curves).collect();
    // direction
    let boxes: Vec<[f64; 4]> = cs.iter().map(|c| bbox_of(c)).collect();
    for (i, c) in contours.iter().enumerate() {
        let inside =
            |o: &[f64; 4], b: &[f64; 4]| o[0] <= b[0] && o[1] <= b[1] && o[2] >= b[2] && o[3] >= b[3] && o != b;
        let depth = (0..contours.len()).filter(|&j| j != i && inside(&boxes[j], &boxes[i])).count();
        let area = signed_area(c);
        let ccw_wanted = (depth % 2 == 0) != truetype;
        if area.is_zero() || area.is_positive() != ccw_wanted {
            kinds.insert("direction");
        }
    }
    for c in &cs {
        let n = c.len();
        // self_intersection (between the segments that are not points; neighbours meet at a node)
        let real: Vec<_> = c.iter().filter(|s| !is_point(s)).collect();
        let m = real.len();
        for a in 0..m {
            for b in a + 1..m {
                let found = intersect_polynomial(real[a], real[b], Domain::Unit).unwrap();
                let next = b == a + 1;
                let wrap = a == 0 && b == m - 1;
                let at_node = |s: f64, t: f64| (next && s == 1.0 && t == 0.0) || (wrap && s == 0.0 && t == 1.0);
                if found.intersections.iter().any(|x| !at_node(x.s_float, x.t_float))
                    || found
                        .overlaps
                        .iter()
                        .any(|o| !at_node(o.s_float[0], o.t_float[0]) || o.s_float[0] != o.s_float[1])
                {
                    kinds.insert("self_intersection");
                }
            }
        }
        for (k, curve) in c.iter().enumerate() {
            let d = curve.degree();
            if is_point(curve) {
                kinds.insert("zero_length_segment");
                continue;
            }
            if d >= 2 && curve.real_degree() < d {
                kinds.insert("degenerate_curve");
            }
            let ps = curve.points();
            if d >= 2 && (ps[1] == ps[0] || ps[d - 1] == ps[d]) {
                kinds.insert("zero_length_handle");
            }
            if d >= 2 {
                let class = classify(curve).unwrap();
                if d == 3 && class.segment.has_loop {
                    kinds.insert("loop");
                }
                if class.cusp_parameters.iter().any(|t| {
                    let t = t.to_f64();
                    t > 0.0 && t < 1.0
                }) && class.segment.has_cusp
                {
                    kinds.insert("cusp");
                }
            }
            if d >= 2 {
                let bb = bounding_box_polynomial(curve).unwrap();
                for s in &bb.stationary {
                    let ends = [&ps[0].coords[s.axis], &ps[d].coords[s.axis]].map(ratio_to_f64);
                    let beyond = (s.value_float - ends[0].max(ends[1])).max(ends[0].min(ends[1]) - s.value_float);
                    if s.t_float > 0.0 && s.t_float < 1.0 && beyond > 1.0 {
                        kinds.insert("missing_extremum");
                    }
                }
            }
            // the node at the end of this segment
            let next = &c[(k + 1) % n];
            if let (Some(a), Some(b)) = (tangent(curve, true), tangent(next, false)) {
                let cross = &a[0] * &b[1] - &a[1] * &b[0];
                let dot = &a[0] * &b[0] + &a[1] * &b[1];
                if cross.is_zero() && dot.is_positive() && d == 1 && next.degree() == 1 {
                    kinds.insert("collinear_points");
                }
                let fl = ratio_to_f64;
                let angle = fl(&cross).atan2(fl(&dot)).abs();
                if !cross.is_zero() && angle < 10f64.to_radians() {
                    kinds.insert("kink");
                }
            }
        }
    }
    // between contours
    for i in 0..cs.len() {
        for j in i + 1..cs.len() {
            for a in cs[i].iter().filter(|c| !is_point(c)) {
                for b in cs[j].iter().filter(|c| !is_point(c)) {
                    let found = intersect_polynomial(a, b, Domain::Unit).unwrap();
                    for x in &found.intersections {
                        let inner = |v: f64| v > 0.0 && v < 1.0;
                        if inner(x.s_float) && inner(x.t_float) && x.kind == Contact::Transversal {
                            kinds.insert("overlap");
                        } else {
                            kinds.insert("touching");
                        }
                    }
                    for o in &found.overlaps {
                        kinds.insert(if o.s_float[0] != o.s_float[1] { "overlapping_segments" } else { "touching" });
                    }
                }
            }
        }
    }
    kinds
}

/// How far a TrueType glyph's stored bounding box is from that of its points (the largest
/// difference of the four sides), read from the font's `glyf` table.
pub fn stored_bbox_off(data: &[u8], gid: u32) -> i32 {
    use read_fonts::TableProvider;
    use read_fonts::tables::glyf::Glyph;
    let font = read_fonts::FontRef::new(data).unwrap();
    let (glyf, loca) = (font.glyf().unwrap(), font.loca(None).unwrap());
    let Some(Glyph::Simple(g)) = loca.get_glyf(read_fonts::types::GlyphId::new(gid), &glyf).unwrap() else {
        return 0;
    };
    let mut it = g.points();
    let Some(p) = it.next() else { return 0 };
    let b = it.fold([p.x, p.y, p.x, p.y], |[a, b, c, d], p| [a.min(p.x), b.min(p.y), c.max(p.x), d.max(p.y)]);
    let stored = [g.x_min(), g.y_min(), g.x_max(), g.y_max()];
    (0..4).map(|k| (stored[k] as i32 - b[k] as i32).abs()).max().unwrap()
}

/// Checks every planted glyph exhibits its primary kind and no kind beyond those allowed, and
/// every clean glyph none.
fn check_census(data: &[u8], planted: &[Planted], truetype: bool) {
    let font = Font::open(data, 0).unwrap();
    for &(name, kind, also) in planted {
        let g = gid(&font, name);
        let mut kinds = census(&font.outline(g).unwrap(), truetype);
        if truetype && stored_bbox_off(data, g) >= 2 {
            kinds.insert("bbox");
        }
        assert!(kinds.contains(kind), "{name}: {kinds:?}");
        let extra: Vec<_> = kinds.iter().filter(|k| **k != kind && !also.contains(k)).collect();
        assert!(extra.is_empty(), "{name}: also {extra:?}");
    }
    for name in CLEAN {
        let g = gid(&font, name);
        let kinds = census(&font.outline(g).unwrap(), truetype);
        assert!(kinds.is_empty(), "{name}: {kinds:?}");
        assert!(!truetype || stored_bbox_off(data, g) == 0);
    }
}

#[test]
fn font_builder_planted_truetype_geometry() {
    let (data, list) = planted_truetype();
    assert_eq!(list.len(), PLANTED_TT.len());
    check_census(&data, PLANTED_TT, true);
}

#[test]
fn font_builder_planted_cff_geometry() {
    let (data, list) = planted_cff();
    assert_eq!(list.len(), PLANTED_CFF.len());
    check_census(&data, PLANTED_CFF, false);
}

#[test]
fn font_builder_planted_specifics() {
    // the cusp and the loop, as classify sees them
    let cubic = |s: &[(i64, i64)]| BezierCurve::new(s.iter().map(|&(x, y)| p(x, y)).collect()).unwrap();
    let k = classify(&cubic(&[(400, 100), (100, 400), (400, 400), (100, 100)])).unwrap();
    assert!(k.segment.has_cusp && !k.segment.has_loop);
    assert_eq!(k.cusp_parameters.iter().map(|t| t.to_string()).collect::<Vec<_>>(), ["1/2"]);
    assert_eq!(k.double_point, Some(p(250, 325)));
    let k = classify(&cubic(&[(400, 100), (0, 400), (500, 400), (100, 100)])).unwrap();
    assert!(k.segment.has_loop && !k.segment.has_cusp);
    assert_eq!(k.double_point, Some(p(250, 250)));
    let ts: Vec<String> = k.double_point_parameters.iter().map(|t| t.to_string()).collect();
    assert_eq!(ts, ["1/2 - 1/6*sqrt(3)", "1/2 + 1/6*sqrt(3)"]);
    // the kink turns by 2.0°
    let ((ax, ay), (bx, by)) = ((200.0f64, 200.0f64), (207.0f64, 193.0f64));
    let angle = (ax * by - ay * bx).atan2(ax * bx + ay * by).abs().to_degrees();
    assert!((1.9..2.1).contains(&angle), "{angle}");
    // the clean fonts: .notdef and the clean glyphs
    for data in [clean_truetype(), clean_cff()] {
        let font = Font::open(&data, 0).unwrap();
        let names: Vec<_> = (1..font.num_glyphs()).map(|g| font.glyph_name(g).unwrap()).collect();
        assert_eq!(names, CLEAN);
    }
    // the clean glyphs' directions: TrueType outer clockwise (negative area), CFF counter-clockwise
    let tt = clean_truetype();
    let font = Font::open(&tt, 0).unwrap();
    let o = font.outline(gid(&font, "clean_o")).unwrap();
    assert!(signed_area(&o[0]).is_negative() && signed_area(&o[1]).is_positive());
    let sq = font.outline(gid(&font, "clean_square")).unwrap();
    assert_eq!(signed_area(&sq[0]), rat(-160000));
    let data = clean_cff();
    let font = Font::open(&data, 0).unwrap();
    let o = font.outline(gid(&font, "clean_o")).unwrap();
    assert!(signed_area(&o[0]).is_positive() && signed_area(&o[1]).is_negative());
}

// ---------------------------------------------------------------------------------------------
// The lint command on the planted fonts

#[cfg(feature = "cli")]
fn lint_json(data: &[u8], file: &str) -> (Option<i32>, Vec<serde_json::Value>, String) {
    let dir = crate::common::TempDir::new("font-builder");
    let path = dir.join(file);
    std::fs::write(&path, data).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .args(["lint", "--json"])
        .arg(&path)
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    let lines = text
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{e}: {l}")))
        .collect();
    (out.status.code(), lines, String::from_utf8_lossy(&out.stderr).into_owned())
}

#[cfg(feature = "cli")]
fn check_lint(data: &[u8], clean: &[u8], planted: &[Planted], file: &str) {
    let (code, findings, stderr) = lint_json(data, file);
    assert_ne!(code, Some(2), "the font is unreadable or the command unknown: {stderr}");
    let kinds_of = |name: &str| -> BTreeSet<String> {
        findings
            .iter()
            .filter(|f| f["glyph"].as_str() == Some(name))
            .map(|f| f["kind"].as_str().unwrap().to_string())
            .collect()
    };
    for f in &findings {
        let glyph = f["glyph"].as_str().unwrap_or("");
        assert!(planted.iter().any(|p| p.0 == glyph), "a finding on a glyph without a planted defect: {f}");
    }
    for &(name, kind, also) in planted {
        let kinds = kinds_of(name);
        assert!(kinds.contains(kind), "{name}: no {kind} finding; found {kinds:?}");
        let extra: Vec<_> = kinds.iter().filter(|k| *k != kind && !also.contains(&k.as_str())).collect();
        assert!(extra.is_empty(), "{name}: unexpected {extra:?}");
    }
    for name in CLEAN {
        assert!(kinds_of(name).is_empty(), "{name}: {:?}", kinds_of(name));
    }
    assert_eq!(code, Some(1), "the planted font has denied findings");
    let (code, findings, stderr) = lint_json(clean, file);
    assert!(findings.is_empty(), "{findings:?}");
    assert_eq!(code, Some(0), "{stderr}");
}

#[cfg(feature = "cli")]
#[test]
fn lint_planted_truetype_finds_each_defect() {
    check_lint(&planted_truetype().0, &clean_truetype(), PLANTED_TT, "planted.ttf");
}

#[cfg(feature = "cli")]
#[test]
fn lint_planted_cff_finds_each_defect() {
    check_lint(&planted_cff().0, &clean_cff(), PLANTED_CFF, "planted.otf");
}
