//! Overlap removal ("simplify", non-zero) of every glyph of DejaVu Sans, single-threaded, by the
//! float peers of `casteljau boolean`: linesweeper and flo_curves (the calls of
//! `examples/peers/mod.rs`, as in `examples/path_ops_peers.rs`; a glyph on which a peer panics
//! counts its time up to the panic). The exact `boolean simplify` joins this group when it lands.
//! `cargo bench --bench shapes_peers` (skipped with a message when the font is absent; another
//! font: `CASTELJAU_BENCH_FONT=PATH`).

#[path = "../examples/peers/mod.rs"]
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
