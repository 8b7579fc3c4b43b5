//! `casteljau::overlaps::decide_glyph`: planted glyphs where plain rounding breaks the outline
//! (each certified output asserted exactly), the cases that are no reason to rewrite, and
//! properties on random overlapping contours: the written outline is lint-clean and has the
//! exact region's membership at every grid point farther than the proved bound from the exact
//! boundary.

use casteljau::format::{Contour, Segment, parse_path};
use casteljau::lint::{Glyph, Kind, LintOptions, lint};
use casteljau::num::{NumberMode, Point2};
use casteljau::overlaps::{Flavour, GlyphDecision, GlyphInput, GridContour, Repair, decide_glyph};
use casteljau::path::{ClosedPath, PathWinding};
use casteljau::shape::Orientation;
use casteljau::work::Budget;
use casteljau::{BezierCurve, Point, rat};
use num_rational::BigRational;
use proptest::prelude::*;

fn input(components: &[&str], flavour: Flavour, orientation: Orientation) -> GlyphInput {
    GlyphInput {
        glyph_id: 1,
        name: Some("planted".into()),
        components: components.iter().map(|d| parse_path(d, NumberMode::Exact).unwrap()).collect(),
        flavour,
        orientation,
    }
}

fn decide(components: &[&str], flavour: Flavour, orientation: Orientation) -> GlyphDecision {
    decide_glyph(&input(components, flavour, orientation), &Budget::unlimited()).unwrap()
}

/// The contours as text: `x,y` on-curve, `(x,y)` off-curve, contours split by ` | `.
fn text(contours: &[GridContour]) -> String {
    contours
        .iter()
        .map(|c| {
            c.points
                .iter()
                .map(|p| if p.on_curve { format!("{},{}", p.x, p.y) } else { format!("({},{})", p.x, p.y) })
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect::<Vec<_>>()
        .join(" | ")
}

/// The written contours read back as a font reader draws them (TrueType's implied midpoints).
fn read_back(contours: &[GridContour], flavour: Flavour) -> Vec<Contour> {
    let p = |x: i32, y: i32| Point::new(vec![rat(x.into()), rat(y.into())]);
    let half = |a: i32, b: i32| Point::new(vec![rat(a.into()), rat(b.into())]).scale(&(rat(1) / rat(2)));
    contours
        .iter()
        .filter(|c| c.points.len() > 1)
        .map(|c| {
            let n = c.points.len();
            let mut segments = vec![];
            let mut current = vec![p(c.points[0].x, c.points[0].y)];
            for k in 1..=n {
                let g = &c.points[k % n];
                if g.on_curve {
                    current.push(p(g.x, g.y));
                    let end = current.last().unwrap().clone();
                    segments.push(Segment::Bezier(std::mem::replace(&mut current, vec![end])));
                    continue;
                }
                if flavour == Flavour::Quadratic && current.len() == 2 {
                    let prev = &current[1];
                    let mid = half(
                        prev.coords[0].to_integer().try_into().unwrap(),
                        prev.coords[1].to_integer().try_into().unwrap(),
                    )
                    .add(&half(g.x, g.y));
                    current.push(mid.clone());
                    segments.push(Segment::Bezier(std::mem::replace(&mut current, vec![mid])));
                }
                current.push(p(g.x, g.y));
            }
            Contour { segments, closed: true }
        })
        .collect()
}

/// The certified output: its contours, report and a lint of it (no forbidden finding).
fn rewritten(
    components: &[&str],
    flavour: Flavour,
    orientation: Orientation,
) -> (String, casteljau::overlaps::GlyphReport) {
    match decide(components, flavour, orientation) {
        GlyphDecision::Rewritten { contours, report } => {
            let kinds = vec![
                Kind::Overlap,
                Kind::SelfIntersection,
                Kind::OverlappingSegments,
                Kind::ZeroLengthSegment,
                Kind::Direction,
            ];
            let options = LintOptions { kinds, ..LintOptions::new(orientation) };
            let found = lint(&Glyph::new(read_back(&contours, flavour)), &options).unwrap();
            assert!(found.is_empty(), "{:?}", found.iter().map(|f| &f.message).collect::<Vec<_>>());
            assert!(report.distance_bound <= rat(1));
            (text(&contours), report)
        }
        other => panic!("not rewritten: {other:?}"),
    }
}

#[test]
fn overlaps_clean_glyphs_and_touching_contours_stay_unchanged() {
    // a square with a hole, clockwise outer (TrueType)
    let framed = "M0 0 V100 H100 V0 Z M20 20 H80 V80 H20 Z";
    assert_eq!(decide(&[framed], Flavour::Quadratic, Orientation::Cw), GlyphDecision::Unchanged);
    // two squares touching at a corner, and a hole touching its outer contour at a point
    let corner = "M0 0 V10 H10 V0 Z M10 10 V20 H20 V10 Z";
    assert_eq!(decide(&[corner], Flavour::Quadratic, Orientation::Cw), GlyphDecision::Unchanged);
    let touching_hole = "M0 0 V100 H100 V0 Z M0 50 L50 20 L50 80 Z";
    assert_eq!(decide(&[touching_hole], Flavour::Quadratic, Orientation::Cw), GlyphDecision::Unchanged);
    // a composite whose components touch at a point, and one whose components are apart
    let (a, b) = ("M0 0 V10 H10 V0 Z", "M10 10 V20 H20 V10 Z");
    assert_eq!(decide(&[a, b], Flavour::Quadratic, Orientation::Cw), GlyphDecision::Unchanged);
    assert_eq!(decide(&[a, "M30 0 V10 H40 V0 Z"], Flavour::Quadratic, Orientation::Cw), GlyphDecision::Unchanged);
    // anchors (one-point contours) are no reason either
    assert_eq!(
        decide(&[&format!("{framed} M50 200 Z")], Flavour::Quadratic, Orientation::Cw),
        GlyphDecision::Unchanged
    );
    // nothing to draw
    assert_eq!(decide(&[], Flavour::Cubic, Orientation::Ccw), GlyphDecision::Unchanged);
}

#[test]
fn overlaps_reversed_contour_is_turned_and_keeps_its_start() {
    // a counter-clockwise square in a TrueType glyph: written clockwise from the same start
    let (out, report) = rewritten(&["M10 0 H110 V100 H10 Z"], Flavour::Quadratic, Orientation::Cw);
    assert_eq!(out, "10,0 10,100 110,100 110,0");
    assert_eq!((report.contours_before, report.contours_after, report.distance_bound.clone()), (1, 1, rat(0)));
    assert!(report.repairs.is_empty());
}

#[test]
fn overlaps_pinch_is_written_as_contours_meeting_there() {
    // one contour through (10, 10) twice: a bow tie of two squares meeting at a corner
    let (out, report) = rewritten(&["M0 0 L0 10 L20 10 L20 20 L10 20 L10 0 Z"], Flavour::Cubic, Orientation::Ccw);
    assert_eq!(out, "0,0 10,0 10,10 0,10 | 10,10 20,10 20,20 10,20");
    assert_eq!(report.contours_after, 2);
}

#[test]
fn overlaps_overlapping_composites_are_decomposed_and_touching_ones_are_not() {
    let (a, b) = ("M0 0 V10 H10 V0 Z", "M5 5 V15 H15 V5 Z");
    let (out, report) = rewritten(&[a, b], Flavour::Quadratic, Orientation::Cw);
    assert_eq!(out, "0,0 0,10 5,10 5,15 15,15 15,5 10,5 10,0");
    assert_eq!((report.contours_before, report.contours_after), (2, 1));
    // components sharing an edge share a boundary piece: merged
    // (the components' corners on the shared edge stay: no point is dropped or invented)
    let (out, _) = rewritten(&[a, "M10 0 V10 H20 V0 Z"], Flavour::Quadratic, Orientation::Cw);
    assert_eq!(out, "0,0 0,10 10,10 20,10 20,0 10,0");
    // touching at a corner only: unchanged
    assert_eq!(decide(&[a, "M10 10 V20 H20 V10 Z"], Flavour::Quadratic, Orientation::Cw), GlyphDecision::Unchanged);
}

#[test]
fn overlaps_two_meeting_points_rounding_onto_each_other() {
    // a thin spike crossing the square's top at x = 50 + 10/11 and 52 − 10/11: both round to
    // (51, 100), which would fold the spike onto one line; one is written at (52, 100)
    let square = "M0 0 H100 V100 H0 Z";
    let spike = "M50 0 L52 0 L51 110 Z";
    let (out, report) = rewritten(&[&format!("{square} {spike}")], Flavour::Cubic, Orientation::Ccw);
    assert_eq!(
        format!("{out}; {:?}; {}", report.repairs, report.distance_bound),
        "0,0 100,0 100,100 52,100 51,110 51,100 0,100; [MovedVertex { contour: 0, point: 3 }]; 10/11"
    );
}

#[test]
fn overlaps_sliver_thinner_than_a_unit_is_dropped_with_its_area() {
    // two squares a slanted gap apart, joined by a bar: the gap's lower part is a hole 0.4
    // units wide at most, which rounding must collapse
    let a = "M0 0 H100 V100 H0 Z";
    let b = "M100 0 H200 V100 H101 Z";
    let bar = "M50 40 H150 V60 H50 Z";
    let (out, report) = rewritten(&[a, b, bar], Flavour::Cubic, Orientation::Ccw);
    assert_eq!(out, "0,0 100,0 200,0 200,100 101,100 101,60 100,60 100,100 0,100");
    assert_eq!(report.repairs, [Repair::DroppedSliver { area: rat(-8) }]);
}

#[test]
fn overlaps_curves_stay_curves_of_their_degree() {
    // two overlapping quadratic discs (TrueType, implied on-curve points): the union's pieces
    // are sub-segments of the quadratics, their implied points kept where no cut touches them
    let disc = |cx: i64, cy: i64, r: i64| {
        format!(
            "M{} {} Q{} {} {} {} Q{} {} {} {} Q{} {} {} {} Q{} {} {} {} Z",
            cx - r,
            cy,
            cx - r,
            cy + r,
            cx,
            cy + r,
            cx + r,
            cy + r,
            cx + r,
            cy,
            cx + r,
            cy - r,
            cx,
            cy - r,
            cx - r,
            cy - r,
            cx - r,
            cy
        )
    };
    let (out, report) =
        rewritten(&[&format!("{} {}", disc(0, 0, 100), disc(150, 30, 100))], Flavour::Quadratic, Orientation::Cw);
    // the first disc's start (−100, 0) is implied (the midpoint of its neighbours): the contour
    // starts at its next written on-curve point
    assert_eq!(
        format!("{out}; {:?}; {}", report.repairs, report.distance_bound),
        "0,100 (38,100) 61,86 (83,130) 150,130 (250,130) (250,-70) 150,-70 (112,-70) 89,-56 (67,-100) 0,-100 (-100,-100) (-100,100); []; 493183/1000000"
    );
}

/// A random small polygon or quadratic contour on the grid.
fn contour() -> impl Strategy<Value = String> {
    (prop::collection::vec((0i64..40, 0i64..40), 3..6), any::<bool>()).prop_map(|(pts, curved)| {
        let mut d = format!("M{} {}", pts[0].0, pts[0].1);
        for w in pts.windows(2) {
            if curved {
                d += &format!(" Q{} {} {} {}", (w[0].0 + w[1].1) % 40, (w[0].1 + w[1].0) % 40, w[1].0, w[1].1);
            } else {
                d += &format!(" L{} {}", w[1].0, w[1].1);
            }
        }
        d + " Z"
    })
}

/// A lower bound on the squared distance from a point to a segment: exact for a line, the
/// distance to the control points' box otherwise (the curve lies in it).
fn distance2_below(q: &Point2<BigRational>, ps: &[Point<BigRational>]) -> BigRational {
    let (x, y) = (|p: &Point<BigRational>| p.coords[0].clone(), |p: &Point<BigRational>| p.coords[1].clone());
    if ps.len() == 2 {
        let (ax, ay, bx, by) = (x(&ps[0]), y(&ps[0]), x(&ps[1]), y(&ps[1]));
        let (dx, dy) = (&bx - &ax, &by - &ay);
        let len2 = &dx * &dx + &dy * &dy;
        let t = if len2 == rat(0) { rat(0) } else { ((&q.x - &ax) * &dx + (&q.y - &ay) * &dy) / &len2 };
        let t = t.clamp(rat(0), rat(1));
        let (px, py) = (&ax + &dx * &t - &q.x, &ay + &dy * &t - &q.y);
        return &px * &px + &py * &py;
    }
    let (x0, x1) = (ps.iter().map(x).min().unwrap(), ps.iter().map(x).max().unwrap());
    let (y0, y1) = (ps.iter().map(y).min().unwrap(), ps.iter().map(y).max().unwrap());
    let gap = |v: &BigRational, lo: &BigRational, hi: &BigRational| {
        if v < lo {
            lo - v
        } else if v > hi {
            v - hi
        } else {
            rat(0)
        }
    };
    let (dx, dy) = (gap(&q.x, &x0, &x1), gap(&q.y, &y0, &y1));
    &dx * &dx + &dy * &dy
}

fn winding(contours: &[Contour], q: &Point2<BigRational>) -> Option<i64> {
    let segs: Vec<Vec<BezierCurve<BigRational>>> = contours
        .iter()
        .map(|c| {
            c.segments
                .iter()
                .map(|s| match s {
                    Segment::Bezier(ps) => BezierCurve::new(ps.clone()).unwrap(),
                    Segment::Skipped { .. } => unreachable!(),
                })
                .collect()
        })
        .filter(|c: &Vec<_>| !c.is_empty())
        .collect();
    match ClosedPath::from_polynomial(segs).unwrap().winding(q, &Budget::unlimited()).unwrap() {
        PathWinding::Off(w) => Some(w.winding()),
        PathWinding::OnBoundary { .. } => None,
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// Random overlapping contours: the written outline is lint-clean, within the proved bound,
    /// and at grid points farther than the bound from every exact piece (tested against the
    /// boxes of the input segments, which hold the exact pieces) inside exactly when the input's
    /// non-zero fill is.
    #[test]
    fn overlaps_written_outline_keeps_the_region(a in contour(), b in contour(), cubic in any::<bool>()) {
        let (flavour, orientation) = if cubic { (Flavour::Cubic, Orientation::Ccw) } else { (Flavour::Quadratic, Orientation::Cw) };
        let d = format!("{a} {b}");
        let glyph = input(&[&d], flavour, orientation);
        let decision = match decide_glyph(&glyph, &Budget::unlimited()) {
            Ok(dec) => dec,
            Err(e) => return Err(TestCaseError::reject(format!("{e}"))),
        };
        let GlyphDecision::Rewritten { contours, report } = decision else { return Ok(()) };
        prop_assert!(report.distance_bound <= rat(1));
        let written = read_back(&contours, flavour);
        let kinds = vec![Kind::Overlap, Kind::SelfIntersection, Kind::OverlappingSegments, Kind::ZeroLengthSegment, Kind::Direction];
        let options = LintOptions { kinds, ..LintOptions::new(orientation) };
        let found = lint(&Glyph::new(written.clone()), &options).unwrap();
        prop_assert!(found.is_empty(), "{:?}", found.iter().map(|f| &f.message).collect::<Vec<_>>());
        let original = parse_path(&d, NumberMode::Exact).unwrap();
        let bound2 = &report.distance_bound * &report.distance_bound;
        let pieces: Vec<Vec<Point<BigRational>>> = original
            .iter()
            .flat_map(|c| c.segments.iter())
            .filter_map(|s| match s { Segment::Bezier(ps) => Some(ps.clone()), Segment::Skipped { .. } => None })
            .collect();
        for x in (-1..=41).step_by(2) {
            for y in (-1..=41).step_by(2) {
                let q = Point2::new(rat(x) + rat(1) / rat(4), rat(y) + rat(1) / rat(3));
                if pieces.iter().any(|ps| distance2_below(&q, ps) <= bound2) {
                    continue;
                }
                let inside = winding(&original, &q).is_some_and(|w| w != 0);
                let written_inside = winding(&written, &q).is_some_and(|w| w != 0);
                prop_assert_eq!(inside, written_inside, "at ({}, {})", q.x, q.y);
            }
        }
    }
}

/// The glyphs of the test font Tuffy (composites taken whole): every one decided, every
/// rewritten one certified and lint-clean as read back; `uni03E1` needs a moved control point
/// and drops a sliver of irrational area.
#[test]
fn overlaps_tuffy_glyphs_are_all_certified() {
    let data = include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/fonts/Tuffy.ttf"));
    let font = casteljau::format::Font::open(data, 0).unwrap();
    let (mut rewritten, mut sliver) = (0, None);
    for gid in 0..font.num_glyphs() {
        let glyph = GlyphInput {
            glyph_id: gid,
            name: font.glyph_name(gid),
            components: vec![font.outline(gid).unwrap()],
            flavour: Flavour::Quadratic,
            orientation: font.outer_orientation(),
        };
        match decide_glyph(&glyph, &Budget::new(casteljau::work::DEFAULT_MAX_WORK, "--max-work")).unwrap() {
            GlyphDecision::Unchanged => {}
            GlyphDecision::Uncertified { reason } => panic!("{:?}: {reason}", glyph.name),
            GlyphDecision::Rewritten { contours, report } => {
                rewritten += 1;
                let kinds = vec![
                    Kind::Overlap,
                    Kind::SelfIntersection,
                    Kind::OverlappingSegments,
                    Kind::ZeroLengthSegment,
                    Kind::Direction,
                ];
                let options = LintOptions { kinds, ..LintOptions::new(Orientation::Cw) };
                assert!(lint(&Glyph::new(read_back(&contours, Flavour::Quadratic)), &options).unwrap().is_empty());
                assert!(report.distance_bound <= rat(1));
                if glyph.name.as_deref() == Some("uni03E1") {
                    sliver = Some(report.repairs);
                }
            }
        }
    }
    assert!(rewritten >= 19, "{rewritten}");
    let repairs = sliver.expect("uni03E1 rewritten");
    assert!(matches!(repairs[..], [Repair::MovedControl { .. }, Repair::DroppedSliver { .. }]), "{repairs:?}");
    let Repair::DroppedSliver { area } = &repairs[1] else { unreachable!() };
    assert_eq!(area.to_string(), "-551/200000"); // an irrational area: the bound 10⁻⁶ beyond it
}

#[test]
fn overlaps_a_curve_no_grid_point_keeps_curved_is_written_as_a_line() {
    // DejaVu Serif's Ccedilla (a composite: the C and the cedilla, as fontTools draws them):
    // the cedilla's top crosses the C's bottom curve at two points about 5 units apart, and
    // the piece of that curve between them bulges by less than a unit: no grid placement of
    // its control point keeps it curved, so it is written as the line between its ends, not
    // as a curve collapsed onto that line
    let c = "M1444 395Q1378 186 1222.5 78.5Q1067 -29 829 -29Q683 -29 558.0 21.0Q433 71 336 168Q224 280 169.5 \
             422.5Q115 565 115 745Q115 1093 316.0 1306.5Q517 1520 846 1520Q968 1520 1106.0 1488.0Q1244 1456 1403 \
             1391V1047H1290Q1253 1235 1141.5 1324.0Q1030 1413 829 1413Q590 1413 467.0 1243.5Q344 1074 344 745Q344 \
             417 467.0 247.5Q590 78 829 78Q996 78 1104.0 157.5Q1212 237 1260 395Z";
    let cedilla = "M910 0Q974 -64 1005.5 -120.0Q1037 -176 1037 -225Q1037 -306 974.0 -350.5Q911 -395 799 -395Q757 \
                   -395 713.0 -389.0Q669 -383 623 -371V-240Q664 -257 703.5 -265.5Q743 -274 778 -274Q835 -274 868.0 \
                   -247.5Q901 -221 901 -176Q901 -148 879.0 -104.0Q857 -60 813 0Z";
    let (out, report) = rewritten(&[c, cedilla], Flavour::Quadratic, Orientation::Cw);
    assert_eq!(report.repairs, [Repair::Straightened { contour: 0, point: 25 }], "{out}");
    let points: Vec<&str> = out.split(" | ").next().unwrap().split(' ').collect();
    assert_eq!(&points[25..27], ["834,-29", "829,-29"], "{out}");
    assert!(report.distance_bound <= rat(1));
}

#[test]
fn overlaps_a_crossing_rounded_past_an_edge_is_written_beside_it() {
    // a thin wedge over a slanted edge (x = 40 + y/2): it crosses the edge at (320/7, 80/7) ≈
    // (45.71, 11.43) and (591/13, 142/13) ≈ (45.46, 10.92). The first one's nearest grid point
    // (46, 11) lies beyond the wedge's lower edge, from (42, 9) to (69, 24): written there the
    // outline would cross itself, so it is written at (46, 12)
    let slanted = "M0 0 L40 0 L60 40 L0 40 Z";
    let wedge = "M68 26 L42 9 L69 24 Z";
    let (out, report) = rewritten(&[&format!("{slanted} {wedge}")], Flavour::Cubic, Orientation::Ccw);
    assert_eq!(
        format!("{out}; {:?}; {}", report.repairs, report.distance_bound),
        "0,0 40,0 45,11 69,24 68,26 46,12 60,40 0,40; [MovedVertex { contour: 0, point: 5 }]; 638877/1000000"
    );
    // plain rounding: the same outline with the crossing at its nearest grid point
    let plain = parse_path("M0 0 L40 0 L45 11 L69 24 L68 26 L46 11 L60 40 L0 40 Z", NumberMode::Exact).unwrap();
    let found = lint(&Glyph::new(plain), &LintOptions::new(Orientation::Ccw)).unwrap();
    assert!(found.iter().any(|f| f.kind() == Kind::SelfIntersection), "{found:?}");
}
