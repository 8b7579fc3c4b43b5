//! Exact-kernel benchmarks: f64, naive BigRational and fraction-free de Casteljau in one run.
//!
//! `cargo bench -p casteljau-bench --bench kernels`; README's table is read from this run's output.

use casteljau::internal::{eval_de_casteljau, subdivide_de_casteljau};
use casteljau::{BezierCurve, Point, Scalar, ratio};
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use num_rational::BigRational;
use std::hint::black_box;
use std::time::Duration;

/// A deterministic degree-`n` planar curve with small rational coordinates.
fn curve(n: usize) -> BezierCurve<BigRational> {
    let pts = (0..=n as i64)
        .map(|i| Point::new(vec![ratio((i * 7) % 13 - 6, 1 + i % 5), ratio((i * 11) % 17 - 8, 1 + i % 3)]))
        .collect();
    BezierCurve::new(pts).unwrap()
}

fn eval(c: &mut Criterion) {
    let mut g = c.benchmark_group("eval");
    g.warm_up_time(Duration::from_millis(500));
    g.measurement_time(Duration::from_secs(2));
    for &n in &[3usize, 10, 30, 100] {
        for (tn, td) in [(1i64, 3i64), (12345, 67891)] {
            let exact = curve(n);
            let float = exact.map(|v| v.to_f64());
            let t = ratio(tn, td);
            let tf = tn as f64 / td as f64;
            let label = format!("n={n},t={tn}/{td}");
            g.bench_with_input(BenchmarkId::new("f64", &label), &(), |b, _| b.iter(|| float.eval(black_box(&tf))));
            g.bench_with_input(BenchmarkId::new("fraction_free", &label), &(), |b, _| {
                b.iter(|| black_box(&exact).eval(black_box(&t)))
            });
            if n == 100 && tn != 1 {
                g.sample_size(10);
            }
            g.bench_with_input(BenchmarkId::new("naive_bigrational", &label), &(), |b, _| {
                b.iter(|| eval_de_casteljau(black_box(&exact), black_box(&t)))
            });
            g.sample_size(100);
        }
    }
    g.finish();
}

fn subdivide(c: &mut Criterion) {
    let mut g = c.benchmark_group("subdivide");
    g.warm_up_time(Duration::from_millis(500));
    g.measurement_time(Duration::from_secs(2));
    for &n in &[3usize, 30] {
        let exact = curve(n);
        let t = ratio(12345, 67891);
        g.bench_with_input(BenchmarkId::new("fraction_free", n), &(), |b, _| {
            b.iter(|| black_box(&exact).subdivide(black_box(&t)))
        });
        g.bench_with_input(BenchmarkId::new("naive_bigrational", n), &(), |b, _| {
            b.iter(|| subdivide_de_casteljau(black_box(&exact), black_box(&t)))
        });
    }
    g.finish();
}

fn identity_8(c: &mut Criterion) {
    let mut g = c.benchmark_group("identity_8");
    g.sample_size(10);
    g.bench_function("n=20,all j", |b| b.iter(|| casteljau::proof::identity_8(black_box(20), 20).unwrap()));
    g.finish();
}

criterion_group!(benches, eval, subdivide, identity_8);
criterion_main!(benches);
