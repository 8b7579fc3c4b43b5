//! Exact cubic × cubic intersection against flo_curves' Bézier clipping, in one run: random
//! font-like integer cubic pairs (|coordinates| ≤ 2048) and hard cases (a cubic against its
//! inflection tangent, a line starting on it, a line through its cusp; control points exact
//! `f64`s), per pair. `cargo bench --bench intersect`.

use casteljau::BezierCurve;
use casteljau::intersect::{Domain, intersect_polynomial};
use casteljau::num::point::Point;
use casteljau::strategies::{binary64, intersections as hard};
use criterion::{Criterion, criterion_group, criterion_main};
use num_rational::BigRational;
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::hint::black_box;
use std::time::Duration;

type Curve = BezierCurve<BigRational>;
/// A pair of curves as `f64` control points.
type FloatPair = (Vec<[f64; 2]>, Vec<[f64; 2]>);

fn font_like(n: usize) -> Vec<(Curve, Curve)> {
    let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x % 4097) as i64 - 2048
    };
    let mut cubic = || {
        BezierCurve::new(
            (0..4)
                .map(|_| {
                    Point::new(vec![BigRational::from_integer(next().into()), BigRational::from_integer(next().into())])
                })
                .collect(),
        )
        .unwrap()
    };
    (0..n).map(|_| (cubic(), cubic())).collect()
}

fn flo(a: &[[f64; 2]], b: &[[f64; 2]]) -> usize {
    use flo_curves::BezierCurveFactory;
    use flo_curves::bezier::{Curve, curve_intersects_curve_clip, curve_intersects_line};
    let c = |p: &[f64; 2]| flo_curves::Coord2(p[0], p[1]);
    let cubic = |p: &[[f64; 2]]| Curve::from_points(c(&p[0]), (c(&p[1]), c(&p[2])), c(&p[3]));
    match b.len() {
        2 => curve_intersects_line(&cubic(a), &(c(&b[0]), c(&b[1]))).len(),
        _ => curve_intersects_curve_clip(&cubic(a), &cubic(b), 1e-9).len(),
    }
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("intersect");
    g.sample_size(10).measurement_time(Duration::from_secs(8)).warm_up_time(Duration::from_secs(1));
    let random = font_like(16);
    let random_f: Vec<FloatPair> = random.iter().map(|(a, b)| (binary64::points(a), binary64::points(b))).collect();
    g.bench_function("exact_font_like_cubic_pair_x16", |bn| {
        bn.iter(|| {
            for (a, b) in &random {
                black_box(intersect_polynomial(a, b, Domain::Unit).unwrap());
            }
        })
    });
    g.bench_function("flo_curves_clip_font_like_cubic_pair_x16", |bn| {
        bn.iter(|| {
            for (a, b) in &random_f {
                black_box(flo(a, b));
            }
        })
    });
    let mut runner = TestRunner::new_with_rng(Config::default(), TestRng::from_seed(RngAlgorithm::ChaCha, &[3u8; 32]));
    let mut cases: Vec<(Curve, Curve)> = vec![];
    for _ in 0..6 {
        let (a, b, _) = hard::tangency(3).new_tree(&mut runner).unwrap().current();
        cases.push((a, b));
        let (a, b, _) = hard::endpoint_hit().new_tree(&mut runner).unwrap().current();
        cases.push((a, b));
        let (a, b, _) = hard::through_cusp().new_tree(&mut runner).unwrap().current();
        cases.push((a, b));
    }
    let cases_f: Vec<FloatPair> = cases.iter().map(|(a, b)| (binary64::points(a), binary64::points(b))).collect();
    g.bench_function("exact_hard_cubic_line_pair_x18", |bn| {
        bn.iter(|| {
            for (a, b) in &cases {
                black_box(intersect_polynomial(a, b, Domain::Unit).unwrap());
            }
        })
    });
    g.bench_function("flo_curves_hard_cubic_line_pair_x18", |bn| {
        bn.iter(|| {
            for (a, b) in &cases_f {
                black_box(flo(a, b));
            }
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
