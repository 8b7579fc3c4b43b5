//! `casteljau::lint`: exact examples of every kind (constructed, with the exact evidence), and
//! properties that cross-check the findings against exact maps of the outline: reversing a
//! contour flips `direction`; a quarter turn or a mirror moves `missing_extremum` with the
//! outline; a node inserted exactly at an extremum (exact subdivision) removes that finding.

use casteljau::format::{Contour, Segment, parse_path};
use casteljau::lint::{Axis, Evidence, ExactValue, Finding, Glyph, Kind, LintOptions, Severity, lint};
use casteljau::num::NumberMode;
use casteljau::shape::Orientation;
use casteljau::{BezierCurve, Point, RealAlgebraic, rat};
use num_rational::BigRational;
use proptest::prelude::*;

fn findings(d: &str) -> Vec<Finding> {
    lint(&Glyph::new(parse_path(d, NumberMode::Exact).unwrap()), &LintOptions::new(Orientation::Ccw)).unwrap()
}

fn kinds(fs: &[Finding]) -> Vec<Kind> {
    fs.iter().map(|f| f.kind()).collect()
}

fn strings(p: &[ExactValue; 2]) -> [String; 2] {
    [p[0].to_string(), p[1].to_string()]
}

#[test]
fn lint_clean_outlines_give_no_finding() {
    // a square with a hole and an island, a circle of four quadratics with nodes at its extrema
    assert!(findings("M0 0 H10 V10 H0 Z M2 2 V8 H8 V2 Z M3 3 H7 V7 H3 Z").is_empty());
    assert!(findings("M10 0 Q20 0 20 10 Q20 20 10 20 Q0 20 0 10 Q0 0 10 0 Z").is_empty());
}

#[test]
fn lint_missing_extremum_of_a_cubic_is_exact_and_irrational() {
    // x′/3 = 150(1−t)² − 400t(1−t) + 150t² vanishes at t = 1/2 ± √7/14; y′ at t = 1/2
    let fs = findings("M0 0 C150 100 -50 100 100 0 H100 V-50 H0 Z");
    let ext: Vec<&Finding> = fs.iter().filter(|f| f.kind() == Kind::MissingExtremum).collect();
    let params: Vec<String> = ext.iter().map(|f| f.parameters[0].to_string()).collect();
    assert!(params.contains(&"1/2".to_string()), "{params:?}");
    assert_eq!(params.iter().filter(|p| p.contains("sqrt(7)")).count(), 2, "{params:?}");
    let top = ext.iter().find(|f| matches!(f.evidence, Evidence::MissingExtremum { axis: Axis::Y, .. })).unwrap();
    assert_eq!(strings(&top.at[0]), ["50", "75"]);
    let Evidence::MissingExtremum { extent, .. } = &top.evidence else { unreachable!() };
    assert_eq!(extent.to_string(), "75");
}

#[test]
fn lint_missing_extremum_within_half_a_unit_is_rounding() {
    // the node (100, 0) with its handle one unit below: the curve dips 1/52 under y = 0
    let fs = findings("M100 0 Q150 -1 200 50 V100 H100 Z");
    let f = fs.iter().find(|f| f.kind() == Kind::MissingExtremum).unwrap();
    assert_eq!(f.parameters[0].to_string(), "1/52");
    assert_eq!(strings(&f.at[0])[1], "-1/52");
    assert!(f.rounding);
    assert_eq!(f.severity, Severity::Info);
    assert!(!f.fails(&Kind::ALL));
    // --extremum-min: an exact threshold on the extent (1/52 beyond the end points)
    let mut o = LintOptions::new(Orientation::Ccw);
    o.extremum_min = Some(rat(1) / rat(52));
    let g = Glyph::new(parse_path("M100 0 Q150 -1 200 50 V100 H100 Z", NumberMode::Exact).unwrap());
    assert_eq!(lint(&g, &o).unwrap().iter().filter(|f| f.kind() == Kind::MissingExtremum).count(), 1);
    o.extremum_min = Some(rat(1) / rat(51));
    assert_eq!(lint(&g, &o).unwrap().iter().filter(|f| f.kind() == Kind::MissingExtremum).count(), 0);
}

#[test]
fn lint_kink_against_the_angle_and_the_grid() {
    // a turn of atan(7/200) ≈ 2.0° at (400, 400): long handles, not explained by rounding
    let fs = findings("M0 200 Q200 200 400 400 Q607 593 800 593 V0 H0 Z");
    let k = fs.iter().find(|f| f.kind() == Kind::Kink).unwrap();
    assert_eq!(strings(&k.at[0]), ["400", "400"]);
    let Evidence::Kink { turn_degrees_float } = k.evidence else { panic!("{k:?}") };
    assert!(!k.rounding && (turn_degrees_float - 2.0).abs() < 0.1);
    // the same turn direction with a 3-unit handle: half a unit explains it
    let fs = findings("M0 200 Q397 397 400 400 Q607 593 800 593 V0 H0 Z");
    let k = fs.iter().find(|f| f.kind() == Kind::Kink).unwrap();
    assert!(k.rounding);
    // below the angle only: a 1° limit does not flag a 2° turn
    let o = LintOptions::new(Orientation::Ccw).with_kink_angle(1.0).unwrap();
    let g = Glyph::new(parse_path("M0 200 Q200 200 400 400 Q607 593 800 593 V0 H0 Z", NumberMode::Exact).unwrap());
    assert!(lint(&g, &o).unwrap().iter().all(|f| f.kind() != Kind::Kink));
    // exactly collinear, same direction: smooth, no finding
    assert!(findings("M0 200 Q200 200 400 400 Q600 600 800 600 V0 H0 Z").iter().all(|f| f.kind() != Kind::Kink));
}

#[test]
fn lint_collinear_and_zero_length_points() {
    let fs = findings("M0 0 H5 H10 V10 H0 Z");
    assert_eq!(kinds(&fs), [Kind::CollinearPoints]);
    assert_eq!((fs[0].index, fs[0].point), (Some(1), Some(1)));
    let fs = findings("M0 0 H10 H10 V10 H0 Z");
    assert_eq!(kinds(&fs), [Kind::ZeroLengthSegment]);
    assert!(fs[0].fails(&[Kind::ZeroLengthSegment]));
    // a spike back along the same line is no redundant point (it is drawn twice)
    assert!(findings("M0 0 H10 H5 V10 H0 Z").iter().all(|f| f.kind() != Kind::CollinearPoints));
}

#[test]
fn lint_degenerate_handles_cusps_and_loops() {
    // a quadratic with its control point at the midpoint is a line
    let fs = findings("M0 0 Q5 0 10 0 V10 H0 Z");
    assert_eq!(kinds(&fs), [Kind::DegenerateCurve]);
    let fs = findings("M0 0 C0 0 10 10 20 0 Z");
    assert!(kinds(&fs).contains(&Kind::ZeroLengthHandle));
    // an exact cusp at t = 1/2 and an exact loop with its double point
    let fs = findings("M400 100 C100 400 400 400 100 100 Z");
    let c = fs.iter().find(|f| f.kind() == Kind::Cusp).unwrap();
    assert_eq!((c.parameters[0].to_string(), strings(&c.at[0])), ("1/2".into(), ["250".into(), "325".into()]));
    let fs = findings("M400 100 C0 400 500 400 100 100 Z");
    let l = fs.iter().find(|f| f.kind() == Kind::Loop).unwrap();
    assert_eq!(strings(&l.at[0]), ["250", "250"]);
    assert!(fs.iter().any(|f| f.kind() == Kind::SelfIntersection));
}

#[test]
fn lint_a_contour_of_one_closed_cubic_is_no_loop() {
    // a teardrop of one cubic: its ends meet at (0, 0) (t = 0 and 1), where the contour joins
    // the segment to itself; the segment does not cross itself
    for d in ["M0 0 C100 100 -100 100 0 0 Z", "M0 0 C-100 100 100 100 0 0 Z"] {
        let fs = findings(d);
        assert!(!kinds(&fs).contains(&Kind::Loop), "{d}: {:?}", kinds(&fs));
        assert!(!kinds(&fs).contains(&Kind::SelfIntersection), "{d}: {:?}", kinds(&fs));
    }
    // the start point passed again inside the segment (t = 0 and 3/5) is still a loop
    let fs = findings("M10 10 C10 40 30 10 -30 -30 Z");
    let l = fs.iter().find(|f| f.kind() == Kind::Loop).unwrap();
    assert_eq!(l.parameters.iter().map(|t| t.to_string()).collect::<Vec<_>>(), ["0", "3/5"]);
    assert_eq!(strings(&l.at[0]), ["10", "10"]);
}

#[test]
fn lint_a_quartic_segment_is_refused() {
    // the checks are for degrees 1 to 3: a quartic (a made-up contour, no reader gives one) is
    // an error, not wrong findings (its extremum at t = 1/2 was missed) or a panic
    let p = |x: i64, y: i64| Point::new(vec![rat(x), rat(y)]);
    let quartic = vec![p(0, 0), p(10, 10), p(20, 10), p(30, 10), p(40, 0)];
    for pts in [quartic, vec![]] {
        let g = Glyph {
            contours: vec![Contour { segments: vec![Segment::Bezier(pts.clone())], closed: true }],
            ..Default::default()
        };
        let e = lint(&g, &LintOptions::new(Orientation::Ccw)).unwrap_err();
        assert!(e.to_string().contains("degrees 1 to 3"), "{e}");
        // numbered by Glyph::new too: refused the same way, no panic
        let g = Glyph::new(vec![Contour { segments: vec![Segment::Bezier(pts)], closed: true }]);
        assert!(lint(&g, &LintOptions::new(Orientation::Ccw)).is_err());
    }
}

#[test]
fn lint_self_intersection_of_an_open_contour_names_a_stored_segment() {
    // contour 1 is an open subpath, closed for fill by the line (10, 20) → (30, 20) that
    // crosses segment 2 at (25, 20): the finding's segment is one of the contour's four (not
    // the closing line, 4), with its parameter
    let fs = findings("M40 20 L40 20 L20 20 M30 20 L40 20 L40 40 L10 0 L10 20");
    let f = fs.iter().find(|f| f.kind() == Kind::SelfIntersection && f.contour == Some(1)).unwrap();
    assert_eq!(f.index, Some(2));
    assert_eq!(f.parameters[0].to_string(), "1/2");
    assert_eq!(strings(&f.at[0]), ["25", "20"]);
}

#[test]
fn lint_contours_cross_touch_share_and_nest() {
    let fs = findings("M0 0 H10 V10 H0 Z M5 5 H15 V15 H5 Z");
    assert_eq!(kinds(&fs), [Kind::Overlap]);
    assert_eq!(fs[0].contours, Some([0, 1]));
    let at: Vec<[String; 2]> = fs[0].at.iter().map(strings).collect();
    assert_eq!(at, [["10".to_string(), "5".to_string()], ["5".into(), "10".into()]]);
    // sharing one corner only
    let fs = findings("M0 0 H10 V10 H0 Z M10 10 H20 V20 H10 Z");
    assert_eq!(kinds(&fs), [Kind::Touching]);
    // a hole drawn the wrong way round: depth 1 expects clockwise
    let fs = findings("M0 0 H10 V10 H0 Z M2 2 H8 V8 H2 Z");
    assert_eq!(kinds(&fs), [Kind::Direction]);
    assert_eq!(fs[0].contour, Some(1));
    assert_eq!(fs[0].evidence, Evidence::Direction { area: rat(36), depth: 1, expected: Orientation::Cw });
    // a glyph drawn twice (a duplicated component): its hole lies in two copies of one outer
    // contour, depth 1 not 2; the duplicate is what is reported
    let fs = findings("M0 0 H10 V10 H0 Z M2 2 V8 H8 V2 Z M0 0 H10 V10 H0 Z M2 2 V8 H8 V2 Z");
    assert!(fs.iter().all(|f| f.kind() != Kind::Direction), "{:?}", kinds(&fs));
    assert!(fs.iter().any(|f| f.kind() == Kind::OverlappingSegments && f.contours == Some([0, 2])));
    assert!(fs.iter().any(|f| f.kind() == Kind::OverlappingSegments && f.contours == Some([1, 3])));
    // a contour drawing an edge twice (a slit): overlapping_segments of [0, 0]
    let fs = findings("M0 0 H10 V10 H5 V2 V10 H0 Z");
    assert!(fs.iter().any(|f| f.kind() == Kind::OverlappingSegments && f.contours == Some([0, 0])));
    // a bow-tie crosses itself at (5, 5); its signed area is 0, so no direction is decided
    let fs = findings("M0 0 L10 10 L10 0 L0 10 Z");
    assert_eq!(kinds(&fs), [Kind::SelfIntersection]);
    assert_eq!(strings(&fs[0].at[0]), ["5", "5"]);
}

#[test]
fn lint_bbox_against_stored_and_head_boxes() {
    let r4 = |b: [i64; 4]| b.map(rat);
    let mut g = Glyph::new(parse_path("M0 0 Q50 100 100 0 Z", NumberMode::Exact).unwrap());
    g.stored_box = Some(r4([0, 0, 100, 100]));
    assert!(findings_of(&g).is_empty());
    g.stored_box = Some(r4([0, 0, 100, 90]));
    let f = findings_of(&g);
    assert_eq!(kinds(&f), [Kind::Bbox]);
    assert_eq!(f[0].severity, Severity::Warning);
    // the exact outline peaks at y = 50: inside a head box to 50, outside one to 49
    g.stored_box = None;
    g.font_box = Some(r4([0, 0, 100, 50]));
    assert!(findings_of(&g).is_empty());
    g.font_box = Some(r4([0, 0, 100, 49]));
    let f = findings_of(&g);
    assert_eq!((f[0].kind(), f[0].severity, f[0].rounding), (Kind::Bbox, Severity::Error, false));
    let Evidence::Bbox { stored, computed } = &f[0].evidence else { panic!("{:?}", f[0]) };
    assert_eq!((stored[3].to_string(), computed[3].to_string()), ("49".to_string(), "50".to_string()));
}

fn findings_of(g: &Glyph) -> Vec<Finding> {
    let mut o = LintOptions::new(Orientation::Cw);
    o.kinds = vec![Kind::Bbox];
    lint(g, &o).unwrap()
}

// ---- properties ----

/// A random closed contour of small-integer lines, quadratics and cubics.
fn contour() -> impl Strategy<Value = Vec<Vec<[i64; 2]>>> {
    let pt = || (-6i64..=6, -6i64..=6).prop_map(|(x, y)| [x, y]);
    (pt(), prop::collection::vec((1usize..=3, prop::collection::vec(pt(), 3)), 1..4)).prop_map(|(start, segs)| {
        let mut out = vec![];
        let mut cur = start;
        for (deg, pts) in segs {
            let mut ps = vec![cur];
            ps.extend(pts.into_iter().take(deg));
            cur = *ps.last().unwrap();
            out.push(ps);
        }
        out.push(vec![cur, start]);
        out
    })
}

fn to_contour(c: &[Vec<[i64; 2]>], map: impl Fn([i64; 2]) -> [i64; 2]) -> Contour {
    let p = |q: [i64; 2]| {
        let q = map(q);
        Point::new(vec![rat(q[0]), rat(q[1])])
    };
    Contour { segments: c.iter().map(|s| Segment::Bezier(s.iter().map(|&q| p(q)).collect())).collect(), closed: true }
}

fn reversed(c: &[Vec<[i64; 2]>]) -> Vec<Vec<[i64; 2]>> {
    c.iter().rev().map(|s| s.iter().rev().copied().collect()).collect()
}

fn neg(v: &ExactValue) -> ExactValue {
    match v {
        ExactValue::Rational(r) => ExactValue::Rational(-r.clone()),
        ExactValue::Quadratic(q) => ExactValue::from(-q.clone()),
        ExactValue::Algebraic(a) => {
            use casteljau::poly::Poly;
            ExactValue::from(a.map_rational(&Poly::new(vec![rat(0), rat(-1)]), &Poly::constant(rat(1))))
        }
    }
}

fn only(kinds: &[Kind]) -> LintOptions {
    let mut o = LintOptions::new(Orientation::Ccw);
    o.kinds = kinds.to_vec();
    o
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn lint_reversing_a_contour_flips_its_direction(cs in prop::collection::vec(contour(), 1..3), k in 0usize..2) {
        let k = k % cs.len();
        let glyph = |cs: &[Vec<Vec<[i64; 2]>>]| Glyph::new(cs.iter().map(|c| to_contour(c, |q| q)).collect());
        let o = only(&[Kind::Direction]);
        let before = lint(&glyph(&cs), &o).unwrap();
        let mut flipped = cs.clone();
        flipped[k] = reversed(&cs[k]);
        let after = lint(&glyph(&flipped), &o).unwrap();
        let has = |fs: &[Finding], i: usize| fs.iter().any(|f| f.contour == Some(i));
        let area_zero = {
            let g = glyph(&cs[k..=k]);
            // a zero signed area decides no orientation either way round
            lint(&g, &o).unwrap().is_empty() && lint(&glyph(&[reversed(&cs[k])]), &o).unwrap().is_empty()
        };
        if !area_zero {
            prop_assert_ne!(has(&before, k), has(&after, k));
        }
        for i in (0..cs.len()).filter(|&i| i != k) {
            prop_assert_eq!(has(&before, i), has(&after, i));
        }
    }

    #[test]
    fn lint_quarter_turns_and_mirrors_move_missing_extrema(c in contour(), turn in any::<bool>()) {
        let o = only(&[Kind::MissingExtremum]);
        let before = lint(&Glyph::new(vec![to_contour(&c, |q| q)]), &o).unwrap();
        // (x, y) ↦ (−y, x), or (x, y) ↦ (−x, y)
        let map = |q: [i64; 2]| if turn { [-q[1], q[0]] } else { [-q[0], q[1]] };
        let after = lint(&Glyph::new(vec![to_contour(&c, map)]), &o).unwrap();
        prop_assert_eq!(before.len(), after.len());
        for f in &before {
            let Evidence::MissingExtremum { axis, extent } = &f.evidence else { unreachable!() };
            let axis = match (turn, axis) { (true, Axis::X) => Axis::Y, (true, Axis::Y) => Axis::X, (false, a) => *a };
            let image = Evidence::MissingExtremum { axis, extent: extent.clone() };
            let at = if turn { [neg(&f.at[0][1]), f.at[0][0].clone()] } else { [neg(&f.at[0][0]), f.at[0][1].clone()] };
            let moved = after.iter().any(|g| {
                g.index == f.index && g.parameters == f.parameters && g.evidence == image && g.at[0] == at
                    && g.rounding == f.rounding
            });
            prop_assert!(moved, "{:?} has no image in {:?}", f, after);
        }
    }

    #[test]
    fn lint_a_node_at_the_extremum_removes_the_finding(c in contour()) {
        let o = only(&[Kind::MissingExtremum, Kind::Kink, Kind::CollinearPoints]);
        let base = to_contour(&c, |q| q);
        let before = lint(&Glyph::new(vec![base.clone()]), &o).unwrap();
        let count = |fs: &[Finding]| fs.iter().filter(|f| f.kind() == Kind::MissingExtremum).count();
        for f in before.iter().filter(|f| f.kind() == Kind::MissingExtremum) {
            let ExactValue::Rational(t) = &f.parameters[0] else { continue };
            let i = f.index.unwrap();
            let Segment::Bezier(ps) = &base.segments[i] else { unreachable!() };
            let (l, r) = BezierCurve::new(ps.clone()).unwrap().subdivide(t);
            let mut split = base.clone();
            split.segments.splice(i..=i, [Segment::Bezier(l.points().to_vec()), Segment::Bezier(r.points().to_vec())]);
            let after = lint(&Glyph::new(vec![split]), &o).unwrap();
            prop_assert_eq!(count(&after), count(&before) - 1);
            // the new node is smooth: no kink or redundant point there
            prop_assert!(after.iter().all(|g| g.kind() == Kind::MissingExtremum || g.index != Some(i + 1)));
        }
    }
}

#[test]
fn lint_exact_values_compare_numerically() {
    let a = ExactValue::from(RealAlgebraic::from(rat(3) / rat(6)));
    assert_eq!(a, ExactValue::Rational(BigRational::new(1.into(), 2.into())));
    assert_eq!(a.to_string(), "1/2");
}
