//! Two real float libraries checked against casteljau's exact oracle: kurbo's
//! `CubicBez::inflections` and flo_curves' `features_for_cubic_bezier` (category, inflection and
//! loop parameters), on the binary64 hard-case strategies (`casteljau::strategies::binary64`,
//! control points exact `f64`s, so each library sees exactly the curve casteljau decides) and on
//! every cubic of the CFF test fonts. Prints the disagreement table and one minimal example per
//! (library, field, kind).
//!
//! `cargo run -p casteljau-bench --release --example float_libraries -- [cases per family,
//! default 2000]` (the intersection table at the end uses a tenth as many cases per family: exact
//! intersection is slower).
//!
//! Settings, stated, not tuned: oracle tolerance `1e-6` in `t` (`--tol` of `casteljau check`),
//! flo_curves' loop-search accuracy `1e-9`. Cases come from a fixed proptest seed.

use casteljau::format::Font;
use casteljau::format::Segment;
use casteljau::oracle::{ClassificationDisagreement, FloatClassification, Tolerances, check_classification};
use casteljau::strategies::binary64;
use num_rational::BigRational;
use proptest::strategy::{BoxedStrategy, Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::collections::BTreeMap;

type Curve = casteljau::BezierCurve<BigRational>;

fn kurbo_answers(p: &[[f64; 2]]) -> FloatClassification {
    let pt = |i: usize| kurbo::Point::new(p[i][0], p[i][1]);
    let c = kurbo::CubicBez::new(pt(0), pt(1), pt(2), pt(3));
    FloatClassification { inflection_parameters: Some(c.inflections().to_vec()), ..Default::default() }
}

fn flo_answers(p: &[[f64; 2]]) -> FloatClassification {
    use flo_curves::bezier::{CurveFeatures, features_for_cubic_bezier};
    let c = |i: usize| flo_curves::Coord2(p[i][0], p[i][1]);
    let f = features_for_cubic_bezier(&c(0), &c(1), &c(2), &c(3), 1e-9);
    let (category, infl, lp) = match f {
        CurveFeatures::Point => ("point", vec![], vec![]),
        CurveFeatures::Linear => ("line", vec![], vec![]),
        CurveFeatures::Arch => ("arch", vec![], vec![]),
        CurveFeatures::Parabolic => ("parabola", vec![], vec![]),
        CurveFeatures::Cusp => ("cusp", vec![], vec![]),
        CurveFeatures::SingleInflectionPoint(t) => ("single_inflection", vec![t], vec![]),
        CurveFeatures::DoubleInflectionPoint(a, b) => ("double_inflection", vec![a, b], vec![]),
        CurveFeatures::Loop(a, b) => ("loop", vec![], vec![a, b]),
    };
    FloatClassification {
        category: Some(category.into()),
        inflection_parameters: Some(infl),
        self_intersection_parameters: Some(lp),
        ..Default::default()
    }
}

fn families() -> Vec<(&'static str, BoxedStrategy<Curve>)> {
    vec![
        ("cusp at t in [0,1] (dyadic)", binary64::cusp_at(binary64::unit_parameter()).prop_map(|c| c.0).boxed()),
        ("cusp outside [0,1]", binary64::cusp_at(binary64::outside_parameter()).prop_map(|c| c.0).boxed()),
        ("loop, ends at dyadic t (often 0 or 1)", binary64::loop_between().prop_map(|c| c.0).boxed()),
        ("inflection exactly at t = 0 or 1", binary64::inflection_at_endpoint().prop_map(|c| c.0).boxed()),
        ("degree-elevated quadratic", binary64::degree_elevated_quadratic().boxed()),
        ("collinear cubic", binary64::collinear_cubic().boxed()),
        ("coincident control points", binary64::coincident_control_points().boxed()),
        ("near-cusp, P1 moved by 2^-k (k 10..50)", binary64::near_cusp(10..=50).prop_map(|c| c.0).boxed()),
        ("random dyadic cubic", binary64::cubic().boxed()),
    ]
}

/// Every cubic of the CFF test fonts (their coordinates are integers: exact `f64`s).
fn font_cubics() -> Vec<Vec<[f64; 2]>> {
    let mut out = vec![];
    for name in ["cantarell_vf_trimmed.ttf", "NotoSansJP-Regular.subset.otf"] {
        let data = std::fs::read(format!("{}/../tests/data/fonts/{name}", env!("CARGO_MANIFEST_DIR"))).unwrap();
        let f = Font::open(&data, 0).unwrap();
        for gid in 0..f.num_glyphs() {
            for c in f.outline(gid).unwrap() {
                for s in c.segments {
                    if let Segment::Bezier(ps) = s
                        && ps.len() == 4
                    {
                        out.push(binary64::points(&Curve::new(ps).unwrap()));
                    }
                }
            }
        }
    }
    out
}

struct Tally {
    cases: usize,
    by_kind: BTreeMap<(&'static str, &'static str, &'static str), usize>, // (library, field, kind)
    cases_wrong: BTreeMap<&'static str, usize>,
    example: BTreeMap<(&'static str, &'static str, &'static str), (String, ClassificationDisagreement)>,
}

fn run_case(t: &mut Tally, p: &[[f64; 2]], tol: &Tolerances) {
    t.cases += 1;
    for (lib, answers) in [("kurbo", kurbo_answers(p)), ("flo_curves", flo_answers(p))] {
        let ds = check_classification(p, &answers, tol).expect("planar cubic");
        if !ds.is_empty() {
            *t.cases_wrong.entry(lib).or_default() += 1;
        }
        for d in ds {
            let key = (lib, d.field, d.kind.as_str());
            *t.by_kind.entry(key).or_default() += 1;
            let text = p.iter().map(|q| format!("{} {}", q[0], q[1])).collect::<Vec<_>>().join(", ");
            let better = t.example.get(&key).is_none_or(|(old, _)| text.len() < old.len());
            if better {
                t.example.insert(key, (text, d));
            }
        }
    }
}

/// flo_curves' cubic–line and cubic–cubic intersections, as `(s, t)` pairs.
fn flo_intersections(a: &[[f64; 2]], b: &[[f64; 2]]) -> Vec<(f64, f64)> {
    use flo_curves::BezierCurveFactory;
    use flo_curves::bezier::{Curve, curve_intersects_curve_clip, curve_intersects_line};
    let c = |p: &[f64; 2]| flo_curves::Coord2(p[0], p[1]);
    let cubic = |p: &[[f64; 2]]| Curve::from_points(c(&p[0]), (c(&p[1]), c(&p[2])), c(&p[3]));
    match b.len() {
        2 => curve_intersects_line(&cubic(a), &(c(&b[0]), c(&b[1]))).into_iter().map(|(s, t, _)| (s, t)).collect(),
        _ => curve_intersects_curve_clip(&cubic(a), &cubic(b), 1e-9).into_iter().collect(),
    }
}

/// flo_curves' intersections checked by the exact oracle on the hard intersection families
/// (cubic against line or cubic; control points exact `f64`s): cases with a disagreement.
fn intersection_table(n: usize, runner: &mut TestRunner) {
    use casteljau::strategies::intersections as hard;
    use casteljau::{intersect::Domain, oracle::check_intersections};
    let fams: Vec<(&str, BoxedStrategy<(Curve, Curve)>)> = vec![
        ("inflection tangent (contact 3)", hard::tangency(3).prop_map(|(a, b, _)| (a, b)).boxed()),
        ("line starting on the cubic", hard::endpoint_hit().prop_map(|(a, b, _)| (a, b)).boxed()),
        ("line through a cusp", hard::through_cusp().prop_map(|(a, b, _)| (a, b)).boxed()),
        ("cubic and its own left piece (overlap)", hard::overlap().prop_map(|(a, b, _)| (a, b)).boxed()),
        ("random dyadic cubics", (binary64::cubic(), binary64::cubic()).boxed()),
    ];
    println!("\n| intersection cases (flo_curves) | n | cases with a disagreement | missed | spurious | duplicate |");
    println!("| --- | ---: | ---: | ---: | ---: | ---: |");
    for (name, s) in fams {
        let (mut wrong, mut kinds) = (0, BTreeMap::<&str, usize>::new());
        for _ in 0..n {
            let (a, b) = s.new_tree(runner).expect("strategy").current();
            let (pa, pb) = (binary64::points(&a), binary64::points(&b));
            let float = flo_intersections(&pa, &pb);
            let Ok(d) = check_intersections(&pa, &pb, &float, 1e-6, Domain::Unit) else { continue };
            wrong += usize::from(!d.is_empty());
            for x in d {
                *kinds.entry(x.kind.as_str()).or_default() += 1;
            }
        }
        let k = |s: &str| kinds.get(s).copied().unwrap_or(0);
        println!("| {name} | {n} | {wrong} | {} | {} | {} |", k("missed"), k("spurious"), k("duplicate"));
    }
}

fn main() {
    let n: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(2000);
    let tol = Tolerances { parameter: 1e-6, point: 1e-6 };
    let mut all = Tally { cases: 0, by_kind: BTreeMap::new(), cases_wrong: BTreeMap::new(), example: BTreeMap::new() };
    println!("| cases | n | kurbo: cases with a disagreement | flo_curves: cases with a disagreement |");
    println!("| --- | ---: | ---: | ---: |");
    let mut rows: Vec<(String, Vec<Vec<[f64; 2]>>)> = vec![];
    let seed = [7u8; 32];
    let mut runner = TestRunner::new_with_rng(Config::default(), TestRng::from_seed(RngAlgorithm::ChaCha, &seed));
    for (name, s) in families() {
        let cases: Vec<Vec<[f64; 2]>> =
            (0..n).map(|_| binary64::points(&s.new_tree(&mut runner).expect("strategy").current())).collect();
        rows.push((name.to_string(), cases));
    }
    rows.push(("every cubic of the CFF test fonts".into(), font_cubics()));
    for (name, cases) in rows {
        let mut t =
            Tally { cases: 0, by_kind: BTreeMap::new(), cases_wrong: BTreeMap::new(), example: BTreeMap::new() };
        for p in &cases {
            run_case(&mut t, p, &tol);
        }
        println!(
            "| {name} | {} | {} | {} |",
            t.cases,
            t.cases_wrong.get("kurbo").copied().unwrap_or(0),
            t.cases_wrong.get("flo_curves").copied().unwrap_or(0)
        );
        all.cases += t.cases;
        for (k, v) in t.by_kind {
            *all.by_kind.entry(k).or_default() += v;
        }
        for (k, v) in t.cases_wrong {
            *all.cases_wrong.entry(k).or_default() += v;
        }
        for (k, v) in t.example {
            let better = all.example.get(&k).is_none_or(|(old, _)| v.0.len() < old.len());
            if better {
                all.example.insert(k, v);
            }
        }
    }
    println!("\nAll {} cases, disagreements by library, field and kind, with the shortest example:\n", all.cases);
    println!("| library | field | kind | count | example curve | exact | float |");
    println!("| --- | --- | --- | ---: | --- | --- | --- |");
    for (k, count) in &all.by_kind {
        let (curve, d) = &all.example[k];
        println!("| {} | {} | {} | {count} | `{curve}` | `{}` | `{}` |", k.0, k.1, k.2, d.exact, d.float);
    }
    intersection_table(n / 10, &mut runner);
}
