//! Overlap removal ("simplify", non-zero) of every glyph of DejaVu Sans, single-threaded, by the
//! float peers of `casteljau boolean`: linesweeper and flo_curves (the calls of
//! `benches/examples/peers/mod.rs`, as in `benches/examples/path_ops_peers.rs`; a glyph on which a
//! peer panics counts its time up to the panic), and the exact `casteljau::shape::boolean`
//! simplify in the same run: in process on one thread and on two (the glyphs dealt to two scoped
//! threads), and end to end through the command line (`casteljau boolean simplify FONT --json` on
//! all cores, output discarded).
//! `cargo bench -p casteljau-bench --bench shapes_peers` (skipped with a message when the font is
//! absent; another font: `CASTELJAU_BENCH_FONT=PATH`).

#[path = "examples/peers/mod.rs"]
mod peers;

use casteljau::format::Font;
use criterion::{Criterion, SamplingMode, Throughput, criterion_group, criterion_main};
use peers::{Fill, Input, Op, PEERS, catch, glyph_path, run};
use std::hint::black_box;
use std::time::Duration;

const DEFAULT_FONT: &str = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

fn simplify_font(c: &mut Criterion) {
    let path = std::env::var("CASTELJAU_BENCH_FONT").unwrap_or_else(|_| DEFAULT_FONT.into());
    let Ok(data) = std::fs::read(&path) else {
        println!("shapes_peers: {path} not found; skipped");
        return;
    };
    let font = Font::open(&data, 0).expect("a font");
    let glyphs: Vec<Input> = (0..font.num_glyphs()).filter_map(|g| glyph_path(&font, g).ok().map(Input::new)).collect();
    peers::quiet_panics();
    let mut g = c.benchmark_group("simplify_dejavu_sans");
    g.throughput(Throughput::Elements(glyphs.len() as u64));
    // One iteration is the whole font (about a second): flat sampling, 10 samples.
    g.sampling_mode(SamplingMode::Flat);
    g.sample_size(10);
    g.warm_up_time(Duration::from_secs(1));
    g.measurement_time(Duration::from_secs(30));
    let shapes: Vec<casteljau::shape::Shape> = (0..font.num_glyphs()).filter_map(|g| font.shape(g).ok()).collect();
    let exact = |shapes: &[casteljau::shape::Shape]| {
        use casteljau::shape::{BooleanOp, BooleanOptions, boolean};
        for s in shapes {
            let _ = black_box(boolean(
                BooleanOp::Simplify,
                std::slice::from_ref(black_box(s)),
                BooleanOptions::default(),
                &casteljau::work::Budget::unlimited(),
            ));
        }
    };
    g.bench_function("casteljau_exact_1_thread", |b| b.iter(|| exact(&shapes)));
    g.bench_function("casteljau_exact_2_threads", |b| {
        b.iter(|| {
            let (even, odd): (Vec<_>, Vec<_>) = shapes.iter().cloned().enumerate().partition(|(i, _)| i % 2 == 0);
            let (even, odd): (Vec<_>, Vec<_>) =
                (even.into_iter().map(|(_, s)| s).collect(), odd.into_iter().map(|(_, s)| s).collect());
            std::thread::scope(|sc| {
                sc.spawn(|| exact(&even));
                sc.spawn(|| exact(&odd));
            });
        })
    });
    g.bench_function("casteljau_cli_all_cores", |b| {
        b.iter(|| {
            let st = std::process::Command::new(env!("CARGO_BIN_EXE_casteljau-cli"))
                .args(["boolean", "simplify", &path, "--json", "--quiet"])
                .stdout(std::process::Stdio::null())
                .stderr(std::process::Stdio::null())
                .status()
                .expect("the binary runs");
            assert!(st.success(), "casteljau boolean simplify failed");
        })
    });
    for peer in PEERS {
        g.bench_function(peer, |b| {
            b.iter(|| {
                for a in &glyphs {
                    let _ = black_box(catch(|| run(peer, black_box(a), None, Fill::NonZero, Op::Union)));
                }
            })
        });
    }
    g.finish();
}

criterion_group!(benches, simplify_font);
criterion_main!(benches);
