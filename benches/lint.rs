//! `casteljau lint` on every glyph of DejaVu Sans (every check): end to end through the command
//! line (`casteljau lint FONT --json`, output discarded) on all cores and on one thread; the
//! library's `casteljau::lint::lint` in process on one thread, with every kind, with the segment
//! and node kinds only, and with the arrangement kinds only; and, in the same run, a float
//! heuristic of the kind font QA tools use (kurbo: the extrema of each segment and the turn at
//! each node in `f64`), for the ratio. `cargo bench -p casteljau-bench --bench lint` (skipped with
//! a message when the font is absent; another font: `CASTELJAU_BENCH_FONT=PATH`).

use casteljau::format::{Font, Segment};
use casteljau::lint::{Glyph, Kind, LintOptions, lint};
use criterion::{Criterion, SamplingMode, Throughput, criterion_group, criterion_main};
use kurbo::{ParamCurve, ParamCurveDeriv, ParamCurveExtrema, Point};
use std::hint::black_box;
use std::time::Duration;

const DEFAULT_FONT: &str = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

fn p(q: &casteljau::Point<num_rational::BigRational>) -> Point {
    use num_traits::ToPrimitive;
    Point::new(q.coords[0].to_f64().unwrap(), q.coords[1].to_f64().unwrap())
}

/// The float heuristic: interior extrema (kurbo) and node turns below 10° in `f64`.
fn float_lint(glyphs: &[Vec<Vec<kurbo::PathSeg>>]) -> usize {
    let mut n = 0;
    for g in glyphs {
        for c in g {
            for (i, s) in c.iter().enumerate() {
                n += s.extrema().len();
                let next = &c[(i + 1) % c.len()];
                let (u, w) = (s.deriv().eval(1.0), next.deriv().eval(0.0));
                let turn = u.to_vec2().cross(w.to_vec2()).atan2(u.to_vec2().dot(w.to_vec2())).abs();
                if turn > 0.0 && turn < 10f64.to_radians() {
                    n += 1;
                }
            }
        }
    }
    n
}

trait Deriv {
    fn deriv(&self) -> kurbo::PathSeg;
}

impl Deriv for kurbo::PathSeg {
    fn deriv(&self) -> kurbo::PathSeg {
        match self {
            kurbo::PathSeg::Line(l) => {
                kurbo::PathSeg::Line(kurbo::Line::new(l.p1 - l.p0.to_vec2(), l.p1 - l.p0.to_vec2()))
            }
            kurbo::PathSeg::Quad(q) => kurbo::PathSeg::Line(q.deriv()),
            kurbo::PathSeg::Cubic(c) => kurbo::PathSeg::Quad(c.deriv()),
        }
    }
}

fn lint_font(c: &mut Criterion) {
    let path = std::env::var("CASTELJAU_BENCH_FONT").unwrap_or_else(|_| DEFAULT_FONT.into());
    let Ok(data) = std::fs::read(&path) else {
        println!("lint: {path} not found; skipped");
        return;
    };
    let font = Font::open(&data, 0).expect("a font");
    let outer = font.outer_orientation();
    // as the command line builds them: with the stored glyph box and the font's head box
    let r4 = |b: [i16; 4]| b.map(|x| num_rational::BigRational::from_integer(x.into()));
    let glyphs: Vec<Glyph> = (0..font.num_glyphs())
        .filter_map(|g| font.outline_numbered(g).ok().map(|o| (g, o)))
        .map(|(g, o)| Glyph {
            stored_box: if o.contours.iter().all(|c| c.segments.is_empty()) {
                None
            } else {
                font.stored_glyph_box(g).map(r4)
            },
            font_box: font.head_box().map(r4),
            contours: o.contours,
            numbers: o.numbers,
            lone_points: o.lone_points,
        })
        .collect();
    let floats: Vec<Vec<Vec<kurbo::PathSeg>>> = glyphs
        .iter()
        .map(|g| {
            g.contours
                .iter()
                .map(|c| {
                    c.segments
                        .iter()
                        .filter_map(|s| match s {
                            Segment::Bezier(ps) => Some(match ps.len() {
                                2 => kurbo::PathSeg::Line(kurbo::Line::new(p(&ps[0]), p(&ps[1]))),
                                3 => kurbo::PathSeg::Quad(kurbo::QuadBez::new(p(&ps[0]), p(&ps[1]), p(&ps[2]))),
                                _ => kurbo::PathSeg::Cubic(kurbo::CubicBez::new(
                                    p(&ps[0]),
                                    p(&ps[1]),
                                    p(&ps[2]),
                                    p(&ps[3]),
                                )),
                            }),
                            Segment::Skipped { .. } => None,
                        })
                        .collect()
                })
                .filter(|c: &Vec<kurbo::PathSeg>| !c.is_empty())
                .collect()
        })
        .collect();
    let mut g = c.benchmark_group("lint_dejavu_sans");
    g.throughput(Throughput::Elements(glyphs.len() as u64));
    g.sampling_mode(SamplingMode::Flat);
    g.sample_size(10);
    g.warm_up_time(Duration::from_secs(1));
    g.measurement_time(Duration::from_secs(30));
    let cli = |threads: &str| {
        let st = std::process::Command::new(env!("CARGO_BIN_EXE_casteljau-cli"))
            .args(["lint", &path, "--json", "--quiet", "--deny", "none", "--threads", threads])
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .status()
            .expect("the binary runs");
        assert!(st.success(), "casteljau lint failed");
    };
    g.bench_function("cli_all_cores", |b| b.iter(|| cli("0")));
    g.bench_function("cli_1_thread", |b| b.iter(|| cli("1")));
    let with = |kinds: Vec<Kind>| {
        let mut o = LintOptions::new(outer);
        o.kinds = kinds;
        o
    };
    let arrangement =
        [Kind::Direction, Kind::SelfIntersection, Kind::Overlap, Kind::Touching, Kind::OverlappingSegments];
    for (name, o) in [
        ("library_1_thread_every_kind", with(Kind::ALL.to_vec())),
        (
            "library_1_thread_segment_and_node_kinds",
            with(Kind::ALL.into_iter().filter(|k| !arrangement.contains(k)).collect()),
        ),
        ("library_1_thread_arrangement_kinds", with(arrangement.to_vec())),
    ] {
        g.bench_function(name, |b| {
            b.iter(|| {
                for gl in &glyphs {
                    let _ = black_box(lint(black_box(gl), &o));
                }
            })
        });
    }
    g.bench_function("f64_heuristic_kurbo_1_thread", |b| b.iter(|| black_box(float_lint(black_box(&floats)))));
    g.finish();
}

criterion_group!(benches, lint_font);
criterion_main!(benches);
