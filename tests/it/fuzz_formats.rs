//! The fuzz harness of `fuzz` extended to the readers: corrupted fonts and composite bombs, and
//! SVG documents of random nesting, transforms and `<use>` references, through `scan`, `lint`,
//! `boolean` and `arrange`, each with the same time cap and promises (exit 0, 1 or 2, no
//! signal, no panic, a message on exit 2, JSON lines that parse).
//!
//! `cargo test --test it fuzz_formats::` runs a bounded, seeded set; more with
//! `CASTELJAU_FUZZ_FORMAT_CASES=2000` (any `CASTELJAU_FUZZ_SEED`).

use crate::common::TempDir;
use crate::font_builder::{TtComposite, TtGlyph, off, on, truetype_composites, tt_square};
use crate::fuzz::{Rng, check};
use std::time::Duration;

/// A small TrueType font: a square, a quadratic glyph, then composites of random fan-out, depth
/// and offsets, sometimes cyclic or naming glyphs the font does not have; names or not.
fn random_font(r: &mut Rng) -> Vec<u8> {
    let glyphs = [
        TtGlyph::new("square", vec![tt_square(0, 0, 100, 100)]),
        TtGlyph::new("bowl", vec![vec![on(0, 0), off(50, 100), on(100, 0), off(50, -20)]]),
    ];
    let depth = r.below(20) + 1;
    let composites: Vec<TtComposite> = (0..depth)
        .map(|k| {
            let gid = 3 + k as u16; // .notdef, square, bowl, then these
            let fan_out = r.below(4) + 1;
            let components = (0..fan_out)
                .map(|_| {
                    let target = match r.below(20) {
                        0 => gid,     // itself
                        1 => gid + 1, // the next one: a cycle when it points back
                        2 => 1000,    // beyond the font
                        _ => gid - 1 - (r.below(2) as u16).min(gid - 1),
                    };
                    let d = |r: &mut Rng| (r.below(400) as i16) - 200;
                    (target, d(r), d(r))
                })
                .collect();
            TtComposite { name: format!("c{k}"), components }
        })
        .collect();
    let cmap = [('A', 1), ('B', 2), ('😀', 3)];
    truetype_composites(&glyphs, &composites, r.chance(50), &cmap)
}

/// A font's bytes with a few bytes changed, or cut short.
fn corrupt(r: &mut Rng, mut bytes: Vec<u8>) -> Vec<u8> {
    if r.chance(20) {
        let keep = r.below(bytes.len());
        bytes.truncate(keep);
        return bytes;
    }
    for _ in 0..r.below(16) + 1 {
        let i = r.below(bytes.len());
        bytes[i] = r.next() as u8;
    }
    bytes
}

const TRANSFORMS: &[&str] = &[
    "scale(1.0001)",
    "scale(3)",
    "translate(1.5 -2)",
    "rotate(90)",
    "rotate(30)",
    "rotate(180, 5 5)",
    "skewX(45)",
    "matrix(1.0001 0.0003 -0.0007 0.9999 1.5 2.25)",
    "scale(1e300)",
    "scale(",
    "scale(0)",
    "",
];

const SHAPES: &[&str] = &[
    r#"<path id="p" d="M0 0 H10 V10 H0 Z"/>"#,
    r#"<path d="M0 0 C10 10 0 10 10 0 Z M2 2 A1 1 0 0 1 3 3 Z"/>"#,
    r#"<rect id="r" width="5" height="5" rx="1"/>"#,
    r#"<rect x="1" y="1" width="5" height="5"/>"#,
    r#"<circle r="3"/>"#,
    r#"<polygon id="q" points="0,0 4,0 2,3"/>"#,
    r#"<line x1="0" y1="0" x2="1em" y2="1"/>"#,
    r#"<path d="M0 0 L"/>"#,
];

/// An SVG document of random nesting, transforms, containers that draw nothing, and `<use>`
/// references (to shapes, to groups, to themselves, to nothing).
fn random_svg(r: &mut Rng) -> String {
    let mut body = String::new();
    let mut open = vec![];
    let depth = if r.chance(10) { r.below(3000) } else { r.below(12) };
    for k in 0..depth {
        let t = r.pick(TRANSFORMS);
        let tag = r.pick(&["g", "g", "g", "defs", "symbol", "clipPath", "a", "svg", "switch"]);
        let extra = if r.chance(10) { r#" display="none""# } else { "" };
        let vb = if r.chance(10) { r#" viewBox="0 0 1 1""# } else { "" };
        body.push_str(&format!(r#"<{tag} id="g{k}" transform="{t}"{extra}{vb}>"#));
        open.push(tag);
        if r.chance(30) {
            body.push_str(r.pick(SHAPES));
        }
        if r.chance(20) {
            let target = r.pick(&["#p", "#r", "#q", "#g0", "#g1", "#nosuch", "other.svg#p", ""]);
            let attr = if r.chance(50) { "href" } else { "xlink:href" };
            body.push_str(&format!(
                r#"<use {attr}="{target}" x="{}" y="1" transform="{}"/>"#,
                r.below(5),
                r.pick(TRANSFORMS)
            ));
        }
    }
    for _ in 0..r.below(4) + 1 {
        body.push_str(r.pick(SHAPES));
    }
    while let Some(tag) = open.pop() {
        body.push_str(&format!("</{tag}>"));
    }
    if r.chance(5) {
        body.truncate(r.below(body.len() + 1)); // not XML any more
    }
    format!(r#"<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink">{body}</svg>"#)
}

fn run_cases(count: usize, seed: u64) {
    let mut r = Rng(seed | 1);
    let dir = TempDir::new("fuzz-formats");
    let tuffy = std::fs::read(format!("{}/tests/data/fonts/Tuffy.ttf", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let cap = Duration::from_secs(10);
    let s = |x: &str| x.to_string();
    let mut failures = vec![];
    for k in 0..count {
        let (file, mut args) = if r.chance(50) {
            let bytes = match r.below(3) {
                0 => corrupt(&mut r, tuffy.clone()),
                1 => {
                    let font = random_font(&mut r);
                    corrupt(&mut r, font)
                }
                _ => random_font(&mut r),
            };
            let file = dir.join(&format!("f{k}.ttf"));
            std::fs::write(&file, bytes).unwrap();
            let f = file.to_string_lossy().into_owned();
            // Tuffy's glyphs are many: the slow commands take a few of them
            let few = [s("--glyphs"), s(r.pick(&["A,B,O", "c0,c1", "square", "nosuch"]))];
            let args = match r.below(4) {
                // (scan's errors are JSON records on stdout: --json says so to the checker)
                0 => vec![s("scan"), s("-q"), s("--json"), f.clone()],
                1 => [vec![s("lint"), s("--json"), f.clone()], few.to_vec()].concat(),
                2 => [vec![s("boolean"), s("simplify"), s("--json"), f.clone()], few.to_vec()].concat(),
                _ => vec![s("lint"), s("-q"), s("--json"), f.clone(), s("--glyphs"), s("square,bowl")],
            };
            (file, args)
        } else {
            let file = dir.join(&format!("s{k}.svg"));
            std::fs::write(&file, random_svg(&mut r)).unwrap();
            let f = file.to_string_lossy().into_owned();
            let args = match r.below(5) {
                0 => vec![s("scan"), s("-q"), s("--json"), f.clone()],
                1 => vec![s("lint"), s("--json"), f.clone()],
                2 => vec![s("boolean"), s("simplify"), f.clone()],
                3 => vec![s("boolean"), s("union"), f.clone(), s("M0 0 H3 V3 H0 Z")],
                _ => vec![s("arrange"), s("--json"), f.clone()],
            };
            (file, args)
        };
        if r.chance(30) {
            args.extend([s("--max-work"), s(r.pick(&["1", "1e6", "1e9"]))]);
        }
        if let Some(why) = check(&args, None, cap) {
            let kept = dir.path().parent().unwrap().join(format!("casteljau-fuzz-case-{seed}-{k}"));
            let _ = std::fs::copy(&file, &kept);
            failures.push(format!("case {k}: {why}\n  args: {args:?}\n  input kept at {}", kept.display()));
        }
        let _ = std::fs::remove_file(&file);
    }
    eprintln!("fuzz_formats: {count} invocations (seed {seed}), {} failures", failures.len());
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn fuzz_formats_fonts_and_svg_are_answered_bounded_run() {
    let count = std::env::var("CASTELJAU_FUZZ_FORMAT_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(60);
    let seed = std::env::var("CASTELJAU_FUZZ_SEED").ok().and_then(|v| v.parse().ok()).unwrap_or(20261122);
    run_cases(count, seed);
}
