//! Classification of a batch of font-like integer cubics (|coordinates| < 2^16): a plain f64
//! classifier, the exact class-and-features path (unchecked i128 under a proved bound → checked
//! i128 → BigInt), the certified f64 filter, the full classification (every exact field) on the fixed-width route, the library's
//! `classify` (fixed-width route, answer converted to `BigRational`) and the full classification in
//! `BigRational` throughout, in one run. `cargo bench -p casteljau-bench --bench classify`.

use casteljau::classify::classify;
use casteljau::internal::classify_in;
use casteljau::internal::{SmallRational, checked};
use casteljau::internal::{decide, summarize_integers};
use casteljau::num::Radical;
use casteljau::{BezierCurve, Point, rat};
use casteljau::{Exact, Scalar};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;

/// Deterministic pseudo-random font-like cubics, with some exact degeneracies mixed in.
fn batch(n: usize) -> Vec<[[i64; 2]; 4]> {
    let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x % (1 << 16)) as i64 - (1 << 15)
    };
    (0..n)
        .map(|i| {
            let mut p = [[0i64; 2]; 4].map(|_| [next(), next()]);
            match i % 10 {
                // cusp at t = 0 (coincident control points)
                0 => p[1] = p[0],
                // a degree-elevated quadratic q0 q1 q2, scaled by 3 to stay integral
                1 => {
                    let (q0, q1, q2) = (p[0], p[1], p[3]);
                    p = [
                        [3 * q0[0], 3 * q0[1]],
                        [q0[0] + 2 * q1[0], q0[1] + 2 * q1[1]],
                        [2 * q1[0] + q2[0], 2 * q1[1] + q2[1]],
                        [3 * q2[0], 3 * q2[1]],
                    ];
                }
                _ => {}
            }
            p
        })
        .collect()
}

fn classify_batch(c: &mut Criterion) {
    let curves = batch(1000);
    let floats: Vec<[[f64; 2]; 4]> = curves.iter().map(|p| p.map(|q| q.map(|v| v as f64))).collect();
    let exact: Vec<BezierCurve<_>> = curves
        .iter()
        .map(|p| BezierCurve::new(p.iter().map(|q| Point::new(vec![rat(q[0]), rat(q[1])])).collect()).unwrap())
        .collect();
    let mut g = c.benchmark_group("classify_1000_cubics");
    g.throughput(Throughput::Elements(curves.len() as u64));
    g.warm_up_time(Duration::from_millis(500));
    g.measurement_time(Duration::from_secs(3));
    g.bench_function("f64_uncertified", |b| {
        b.iter(|| floats.iter().map(|p| decide(black_box(p)).map(|s| s.0)).collect::<Vec<_>>())
    });
    g.bench_function("exact_smallint_i128_bigint", |b| {
        b.iter(|| curves.iter().map(|p| summarize_integers(black_box(p)).0).collect::<Vec<_>>())
    });
    g.bench_function("certified_f64_filter", |b| {
        b.iter(|| floats.iter().map(|p| casteljau::internal::filter_f64(black_box(p)).map(|s| s.0)).collect::<Vec<_>>())
    });
    let small: Vec<BezierCurve<SmallRational>> = curves
        .iter()
        .map(|p| {
            BezierCurve::new(
                p.iter()
                    .map(|q| Point::new(vec![SmallRational::from_i64(q[0]), SmallRational::from_i64(q[1])]))
                    .collect(),
            )
            .unwrap()
        })
        .collect();
    g.bench_function("exact_small_full_classification", |b| {
        b.iter(|| small.iter().map(|c| checked(|| classify_in(black_box(c)).unwrap().class)).collect::<Vec<_>>())
    });
    g.bench_function("exact_small_radical_only", |b| {
        let ds: Vec<SmallRational> = small
            .iter()
            .filter_map(|c| checked(|| classify_in(c).unwrap().t_e_and_d.map(|x| x.1)).flatten())
            .map(|d| if d.sign() == std::cmp::Ordering::Less { -d } else { d })
            .collect();
        b.iter(|| ds.iter().map(|d| checked(|| SmallRational::radical(black_box(d)))).collect::<Vec<_>>())
    });
    g.bench_function("classify_library_call", |b| {
        b.iter(|| exact.iter().map(|c| classify(black_box(c)).unwrap().class).collect::<Vec<_>>())
    });
    g.bench_function("naive_bigrational_classify", |b| {
        b.iter(|| exact.iter().map(|c| classify_in(black_box(c)).unwrap().class).collect::<Vec<_>>())
    });
    g.finish();
}

criterion_group!(benches, classify_batch);
criterion_main!(benches);
