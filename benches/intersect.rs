//! Exact cubic × cubic intersection against flo_curves' Bézier clipping, in one run: random
//! font-like integer cubic pairs (|coordinates| ≤ 2048) and hard cases (a cubic against its
//! inflection tangent, a line starting on it, a line through its cusp; control points exact
//! `f64`s). Criterion times each batch (the mean per pair); `per_pair_medians` then times every
//! pair on its own and prints the median per pair of both routes and their ratio (the issue's
//! target is stated for the median); `command_line` times `casteljau intersect --json -i FILE`
//! end to end on 1,024 such pairs (eight times the 128), on 1 and 2 threads.
//! `cargo bench -p casteljau-bench --bench intersect`.

use casteljau::BezierCurve;
use casteljau::intersect::{Domain, Intersections};
use casteljau::work::Budget;

/// Two polynomial curves' exact intersections (the library's route for them).
fn intersect_polynomial(
    a: &BezierCurve<BigRational>,
    b: &BezierCurve<BigRational>,
    domain: Domain,
) -> casteljau::Result<Intersections> {
    casteljau::intersect::intersect(&a.clone().into(), &b.clone().into(), domain, &Budget::unlimited())
}
use casteljau::num::Point;
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
    let random = font_like(RANDOM_PAIRS);
    let random_f: Vec<FloatPair> = random.iter().map(|(a, b)| (binary64::points(a), binary64::points(b))).collect();
    g.bench_function("exact_font_like_cubic_pair_x128", |bn| {
        bn.iter(|| {
            for (a, b) in &random {
                black_box(intersect_polynomial(a, b, Domain::Unit).unwrap());
            }
        })
    });
    g.bench_function("flo_curves_clip_font_like_cubic_pair_x128", |bn| {
        bn.iter(|| {
            for (a, b) in &random_f {
                black_box(flo(a, b));
            }
        })
    });
    let cases = hard_cases();
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

/// How many random font-like pairs are timed.
const RANDOM_PAIRS: usize = 128;

/// Six of each hard family, from a fixed seed.
fn hard_cases() -> Vec<(Curve, Curve)> {
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
    cases
}

/// The fastest of `reps` runs of `f`, in µs.
fn fastest(reps: usize, mut f: impl FnMut()) -> f64 {
    (0..reps)
        .map(|_| {
            let t = std::time::Instant::now();
            f();
            t.elapsed().as_secs_f64() * 1e6
        })
        .fold(f64::INFINITY, f64::min)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 { v[n / 2] } else { (v[n / 2 - 1] + v[n / 2]) / 2.0 }
}

/// Every pair timed on its own (exact: fastest of 5 runs; flo_curves: fastest of 200), then the
/// median per pair of each route and their ratio, printed.
fn per_pair_medians(_: &mut Criterion) {
    for (name, pairs) in
        [("random font-like cubic pairs", font_like(RANDOM_PAIRS)), ("hard cubic × line pairs", hard_cases())]
    {
        let floats: Vec<FloatPair> = pairs.iter().map(|(a, b)| (binary64::points(a), binary64::points(b))).collect();
        let exact: Vec<f64> = pairs
            .iter()
            .map(|(a, b)| fastest(5, || drop(black_box(intersect_polynomial(a, b, Domain::Unit).unwrap()))))
            .collect();
        let flo_times: Vec<f64> = floats
            .iter()
            .map(|(a, b)| {
                fastest(200, || {
                    black_box(flo(a, b));
                })
            })
            .collect();
        let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
        let (me, mf) = (median(exact.clone()), median(flo_times.clone()));
        println!(
            "per pair, {} {name}: exact median {me:.1} µs (mean {:.1}), flo_curves median {mf:.2} µs (mean {:.2}), ratio of medians {:.0}×",
            pairs.len(),
            mean(&exact),
            mean(&flo_times),
            me / mf
        );
    }
}

/// The random pairs as batch lines, `A ; B`.
fn batch_text(pairs: &[(Curve, Curve)]) -> String {
    let curve = |c: &Curve| {
        c.points().iter().map(|p| format!("{} {}", p.coords[0], p.coords[1])).collect::<Vec<_>>().join(", ")
    };
    pairs.iter().map(|(a, b)| format!("{} ; {}\n", curve(a), curve(b))).collect()
}

/// `casteljau intersect --json -i FILE` end to end on 1,024 random font-like pairs (the 128 eight
/// times), output discarded, on 1 and 2 threads.
fn command_line(c: &mut Criterion) {
    let text = batch_text(&font_like(RANDOM_PAIRS)).repeat(8);
    let path = std::env::temp_dir().join(format!("casteljau-bench-{}-intersect", std::process::id()));
    std::fs::write(&path, text).unwrap();
    let mut g = c.benchmark_group("intersect_cli");
    g.sample_size(10).measurement_time(Duration::from_secs(8)).warm_up_time(Duration::from_secs(1));
    for threads in [1, 2] {
        g.bench_function(format!("cli_1024_pairs_{threads}_thread"), |bn| {
            bn.iter(|| {
                let status = std::process::Command::new(env!("CARGO_BIN_EXE_casteljau-cli"))
                    .args(["intersect", "--json", "-i"])
                    .arg(&path)
                    .args(["--threads", &threads.to_string()])
                    .stdout(std::process::Stdio::null())
                    .status()
                    .unwrap();
                assert!(status.success());
            })
        });
    }
    g.finish();
    let _ = std::fs::remove_file(&path);
}

criterion_group!(benches, bench, per_pair_medians, command_line);
criterion_main!(benches);
