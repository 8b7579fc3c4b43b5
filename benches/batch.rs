//! End-to-end batch classification, in one run: the `casteljau classify --json --input FILE`
//! command line on 1 and 2 threads, the same exact pipeline in process (parse → classify →
//! JSON Lines), and a plain `f64` pipeline that parses the same text and writes the same JSON
//! fields (floats instead of exact strings) for the ratio, and the generic exact route (fixed-width
//! rationals, serde) for the gain of the integer route. Inputs: 32,768 font-like integer
//! cubics (|coordinates| ≤ 2048, a tenth with a cusp at t = 0), 4,096 cubics with small
//! rational coordinates, and 31 copies of the first (1,015,808 lines, command line only).
//! Also `spline check` on 20,000 degree-1 lines (in process and the command line).
//! `cargo bench -p casteljau-bench --bench batch` (`-- spline_check` for that group only).

use casteljau::BezierCurve;
use casteljau::classify::classify;
use casteljau::internal::checked;
use casteljau::internal::classify_in;
use casteljau::internal::{classify_json, classify_json_small};
use casteljau::internal::{integer_cubic, parse_points_small, small_cubic};
use casteljau::num::{NumberMode, parse_points};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::Duration;

fn xorshift(seed: u64) -> impl FnMut() -> u64 {
    let mut x = seed;
    move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        x
    }
}

/// Font-like integer cubics, one per line.
fn font_like(n: usize) -> String {
    let mut next = xorshift(0x9E37_79B9_7F4A_7C15);
    let mut out = String::new();
    for i in 0..n {
        let mut p: Vec<[i64; 2]> =
            (0..4).map(|_| [(next() % 4097) as i64 - 2048, (next() % 4097) as i64 - 2048]).collect();
        if i % 10 == 0 {
            p[1] = p[0];
        }
        let line: Vec<String> = p.iter().map(|q| format!("{} {}", q[0], q[1])).collect();
        out += &line.join(", ");
        out.push('\n');
    }
    out
}

/// Cubics with small rational coordinates (`p/q`, |p| < 1000, 0 < q < 50).
fn small_rationals(n: usize) -> String {
    let mut next = xorshift(0x2545_F491_4F6C_DD1D);
    let mut out = String::new();
    for _ in 0..n {
        let line: Vec<String> = (0..4)
            .map(|_| {
                let mut c = || format!("{}/{}", (next() % 1999) as i64 - 999, next() % 49 + 1);
                format!("{} {}", c(), c())
            })
            .collect();
        out += &line.join(", ");
        out.push('\n');
    }
    out
}

fn write_input(name: &str, text: &str) -> PathBuf {
    let path = std::env::temp_dir().join(format!("casteljau-bench-{}-{name}", std::process::id()));
    std::fs::write(&path, text).unwrap();
    path
}

/// The command line, output discarded.
fn cli(path: &PathBuf, threads: usize) {
    let status = Command::new(env!("CARGO_BIN_EXE_casteljau-cli"))
        .args(["classify", "--json", "--input"])
        .arg(path)
        .args(["--threads", &threads.to_string()])
        .stdout(Stdio::null())
        .status()
        .unwrap();
    assert!(status.success());
}

/// The exact pipeline in process, as the command runs it on one thread: integer cubics straight
/// to JSON (`classify::integer`), anything else by the generic route.
fn exact_pipeline(text: &str, out: &mut Vec<u8>) {
    for line in text.lines() {
        if let Some(p) = integer_cubic(line)
            && classify_json(&p, out)
        {
            out.push(b'\n');
            continue;
        }
        // other numbers that fit: integers over their common denominator, in big integers
        if let Some(p) = small_cubic(line, NumberMode::Exact)
            && classify_json_small(&p, out)
        {
            out.push(b'\n');
            continue;
        }
        generic_line(line, out);
    }
}

/// The generic route in process (the same answers): fixed-width rationals, then serde.
fn generic_pipeline(text: &str, out: &mut Vec<u8>) {
    for line in text.lines() {
        generic_line(line, out);
    }
}

/// One line by the generic route: fixed-width rationals, or big ones when a number outgrows them.
fn generic_line(line: &str, out: &mut Vec<u8>) {
    let pts = parse_points_small(line, 2, None).expect("small numbers");
    match checked(|| classify_in(&BezierCurve::new(pts).unwrap()).unwrap()) {
        Some(k) => serde_json::to_writer(&mut *out, &k).unwrap(),
        None => {
            let c = BezierCurve::new(parse_points(line, 2, None).unwrap()).unwrap();
            serde_json::to_writer(&mut *out, &classify(&c).unwrap()).unwrap()
        }
    }
    out.push(b'\n');
}

/// The f64 fields of `classify --json`, computed in floating point.
#[derive(serde::Serialize)]
struct FloatClassification {
    degree: usize,
    real_degree: usize,
    collinear: bool,
    class: &'static str,
    node_type: Option<&'static str>,
    double_point: Option<[f64; 2]>,
    double_point_parameters: Vec<f64>,
    inflection_parameters: Vec<f64>,
    cusp_parameters: Vec<f64>,
    invariants: [f64; 3],
    #[serde(rename = "t_E")]
    t_e: Option<f64>,
    d: Option<f64>,
    segment: FloatSegment,
}

#[derive(serde::Serialize)]
struct FloatSegment {
    #[serde(rename = "loop")]
    has_loop: bool,
    cusp: bool,
    inflections: usize,
    category: &'static str,
}

/// A plain f64 classifier (the formulas of `casteljau::classify`, rounded): what a float
/// library computes for the same fields.
fn classify_f64(p: &[[f64; 2]; 4]) -> FloatClassification {
    let sub = |a: [f64; 2], b: [f64; 2]| [a[0] - b[0], a[1] - b[1]];
    let cross = |a: [f64; 2], b: [f64; 2]| a[0] * b[1] - a[1] * b[0];
    let (d1, d2, d3) = (sub(p[1], p[0]), sub(p[2], p[1]), sub(p[3], p[2]));
    let a1 = [3.0 * d1[0], 3.0 * d1[1]];
    let dd = sub(d2, d1);
    let a2 = [3.0 * dd[0], 3.0 * dd[1]];
    let a3 = sub(sub(d3, d2), dd);
    let (a, b, c) = (cross(a2, a3), cross(a1, a3), cross(a1, a2));
    let nz = |v: [f64; 2]| v[0] != 0.0 || v[1] != 0.0;
    let real_degree = if nz(a3) {
        3
    } else if nz(a2) {
        2
    } else if nz(a1) {
        1
    } else {
        0
    };
    let collinear = a == 0.0 && b == 0.0 && c == 0.0;
    let unit = |t: f64| (0.0..=1.0).contains(&t);
    let mut k = FloatClassification {
        degree: 3,
        real_degree,
        collinear,
        class: "cubic_really_quadratic",
        node_type: None,
        double_point: None,
        double_point_parameters: vec![],
        inflection_parameters: vec![],
        cusp_parameters: vec![],
        invariants: [a, b, c],
        t_e: None,
        d: None,
        segment: FloatSegment { has_loop: false, cusp: false, inflections: 0, category: "parabola" },
    };
    if real_degree < 3 || collinear {
        k.class = if collinear { "collinear_cubic" } else { k.class };
        k.segment.category = if collinear { "line" } else { "parabola" };
        return k;
    }
    if a == 0.0 {
        k.class = "explicit";
        k.node_type = Some("explicit");
        k.inflection_parameters = vec![-c / (3.0 * b)];
    } else {
        let te = -b / (2.0 * a);
        let d = (4.0 * a * c - 3.0 * b * b) / (4.0 * a * a);
        let s = (a * c - b * b) / (a * a * a);
        let v = [a * a2[0] - b * a3[0], a * a2[1] - b * a3[1]];
        k.double_point = Some([p[0][0] + s * v[0], p[0][1] + s * v[1]]);
        k.t_e = Some(te);
        k.d = Some(d);
        if d > 0.0 {
            k.class = "crunode";
            k.double_point_parameters = vec![te - d.sqrt(), te + d.sqrt()];
        } else if d == 0.0 {
            k.class = "cusp";
            k.double_point_parameters = vec![te];
            k.cusp_parameters = vec![te];
        } else {
            k.class = "acnode";
            let r = (-d / 3.0).sqrt();
            k.inflection_parameters = vec![te - r, te + r];
        }
        k.node_type = Some(k.class);
    }
    k.segment.has_loop = k.class == "crunode" && k.double_point_parameters.iter().all(|&t| unit(t));
    k.segment.cusp = k.cusp_parameters.iter().any(|&t| unit(t));
    k.segment.inflections = k.inflection_parameters.iter().filter(|&&t| unit(t)).count();
    k.segment.category = match (k.segment.has_loop, k.segment.cusp, k.segment.inflections) {
        (true, _, _) => "loop",
        (_, true, _) => "cusp",
        (_, _, 0) => "arch",
        (_, _, 1) => "single_inflection",
        _ => "double_inflection",
    };
    k
}

/// The f64 pipeline: parse the same text as `f64`s, classify, write JSON Lines.
fn f64_pipeline(text: &str, out: &mut Vec<u8>) {
    for line in text.lines() {
        let mut v = [0f64; 8];
        for (slot, tok) in
            v.iter_mut().zip(line.split(|c: char| c == ',' || c.is_whitespace()).filter(|t| !t.is_empty()))
        {
            // a fraction `p/q` as a float library would read it: p / q rounded
            *slot = match tok.split_once('/') {
                Some((p, q)) => p.parse::<f64>().unwrap() / q.parse::<f64>().unwrap(),
                None => tok.parse().unwrap(),
            };
        }
        let p = [[v[0], v[1]], [v[2], v[3]], [v[4], v[5]], [v[6], v[7]]];
        serde_json::to_writer(&mut *out, &classify_f64(&p)).unwrap();
        out.push(b'\n');
    }
}

fn batch(c: &mut Criterion) {
    let fonts = font_like(32_768);
    let rationals = small_rationals(4_096);
    let font_file = write_input("fonts.txt", &fonts);
    let rational_file = write_input("rationals.txt", &rationals);
    let mut sink = Vec::with_capacity(64 << 20);
    // sanity: both exact pipelines answer every line, alike
    exact_pipeline(&fonts, &mut sink);
    assert_eq!(sink.iter().filter(|&&b| b == b'\n').count(), 32_768);
    let mut generic = Vec::new();
    generic_pipeline(&fonts, &mut generic);
    assert!(sink == generic, "the integer route and the generic route differ");
    let (mut exact, mut generic) = (Vec::new(), Vec::new());
    exact_pipeline(&rationals, &mut exact);
    generic_pipeline(&rationals, &mut generic);
    assert!(exact == generic, "the scaled route and the generic route differ");

    for (name, text, path, n) in [
        ("font_like_32768", &fonts, &font_file, 32_768u64),
        ("small_rationals_4096", &rationals, &rational_file, 4_096),
    ] {
        let mut g = c.benchmark_group(format!("batch_{name}"));
        g.throughput(Throughput::Elements(n));
        g.sample_size(10);
        g.warm_up_time(Duration::from_millis(500));
        g.measurement_time(Duration::from_secs(4));
        g.bench_function("f64_pipeline_in_process", |b| {
            b.iter(|| {
                sink.clear();
                f64_pipeline(black_box(text), &mut sink);
            })
        });
        g.bench_function("exact_pipeline_in_process", |b| {
            b.iter(|| {
                sink.clear();
                exact_pipeline(black_box(text), &mut sink);
            })
        });
        g.bench_function("generic_pipeline_in_process", |b| {
            b.iter(|| {
                sink.clear();
                generic_pipeline(black_box(text), &mut sink);
            })
        });
        g.bench_function("cli_1_thread", |b| b.iter(|| cli(path, 1)));
        g.bench_function("cli_2_threads", |b| b.iter(|| cli(path, 2)));
        g.finish();
    }
    // a font library's worth: 31 copies of the font-like file, 1,015,808 lines, end to end
    let million = write_input("fonts_1m.txt", &fonts.repeat(31));
    let mut g = c.benchmark_group("batch_font_like_1015808");
    g.throughput(Throughput::Elements(32_768 * 31));
    g.sample_size(10);
    g.warm_up_time(Duration::from_millis(500));
    g.measurement_time(Duration::from_secs(15));
    g.bench_function("cli_1_thread", |b| b.iter(|| cli(&million, 1)));
    g.bench_function("cli_2_threads", |b| b.iter(|| cli(&million, 2)));
    g.finish();
    let _ = std::fs::remove_file(million);
    let _ = std::fs::remove_file(font_file);
    let _ = std::fs::remove_file(rational_file);
}

/// Font-like line segments (degree-1 splines of one span), one per line.
fn font_lines(n: usize) -> String {
    let mut next = xorshift(0x0123_4567_89AB_CDEF);
    let mut out = String::new();
    for _ in 0..n {
        let mut c = || (next() % 4097) as i64 - 2048;
        out += &format!("{} {}, {} {}\n", c(), c(), c(), c());
    }
    out
}

/// `spline check` on degree-1 lines, in process (parse → spline → check → JSON) and by the
/// command line on one thread: the lines/s of the spline batch route. Bounded: 20,000 lines,
/// ten samples. `cargo bench -p casteljau-bench --bench batch -- spline_check`.
fn spline_check(c: &mut Criterion) {
    use casteljau::spline::{RationalSpline, homogeneous_control_points};
    use casteljau::work::Budget;
    const LINES: usize = 20_000;
    let text = font_lines(LINES);
    let path = write_input("spline_lines.txt", &text);
    let knots = [0, 0, 1, 1].map(casteljau::rat);
    let in_process = |text: &str, out: &mut Vec<u8>| {
        for line in text.lines() {
            let h = homogeneous_control_points(&parse_points(line, 2, None).unwrap(), None).unwrap();
            let check = casteljau::spline::SplineCheck::new(
                &RationalSpline::from_knots(1, h, &knots).unwrap(),
                &Budget::unlimited(),
            )
            .unwrap();
            assert!(check.passed);
            serde_json::to_writer(&mut *out, &check).unwrap();
            out.push(b'\n');
        }
    };
    let mut sink = Vec::with_capacity(8 << 20);
    let mut g = c.benchmark_group(format!("batch_spline_check_{LINES}"));
    g.throughput(Throughput::Elements(LINES as u64));
    g.sample_size(10);
    g.warm_up_time(Duration::from_millis(500));
    g.measurement_time(Duration::from_secs(3));
    g.bench_function("in_process", |b| {
        b.iter(|| {
            sink.clear();
            in_process(black_box(&text), &mut sink);
        })
    });
    g.bench_function("cli_1_thread", |b| {
        b.iter(|| {
            let status = Command::new(env!("CARGO_BIN_EXE_casteljau-cli"))
                .args(["spline", "check", "--degree", "1", "--knots", "0 0 1 1", "--json", "--threads", "1", "--input"])
                .arg(&path)
                .stdout(Stdio::null())
                .status()
                .unwrap();
            assert!(status.success());
        })
    });
    g.finish();
    let _ = std::fs::remove_file(path);
}

criterion_group!(benches, spline_check, batch);
criterion_main!(benches);
