//! The float peers of `casteljau boolean` (issue #27) run where the exact oracle can judge them:
//! linesweeper and flo_curves (see `peers/mod.rs` for the calls and their settings). `--fill` is
//! linesweeper's fill rule (default non-zero); flo_curves has only even-odd (its non-zero
//! `path_remove_interior_points` fills every hole), so its answers are even-odd ones.
//!
//! 1. Every glyph of a font (default DejaVu Sans) simplified by each peer (overlap removal: the
//!    union of the glyph with the empty path), single-threaded, one panic caught per glyph:
//!    `OUT/linesweeper.jsonl` and `OUT/flo_curves.jsonl`, one line per glyph,
//!    `{"glyph": NAME or null, "glyph_id": N, "path": "SVG path data"}` (or `"error"` instead of
//!    `"path"`), and each peer's wall time.
//! 2. The hard cases (generated here, written to `tests/data/boolean/hard.txt`: a `# name: what it
//!    tests` line, then `A ; B` in SVG path data, every coordinate an exact decimal and an exact
//!    `f64`), and each peer's union, intersection, difference and xor of each:
//!    `OUT/hard-<op>-<peer>.txt`, one line per case in the same order (`# error: ...` for an error
//!    or a panic, so line numbers stay aligned).
//!
//! `cargo run -p casteljau-bench --release --example path_ops_peers -- [FONT] [--out DIR]
//! [--hard FILE] [--fill nonzero|evenodd] [--no-font]`
//!
//! Numbers written by the peers are in shortest round-trip `f64` form (`{}`): the decimal read
//! back is the nearest-`f64` neighbour of the peer's value, not its exact binary value.

mod peers;

use casteljau::format::{Font, parse_path};
use casteljau::num::NumberMode;
use kurbo::BezPath;
use num_rational::BigRational;
use num_traits::{ToPrimitive, Zero};
use peers::{Fill, Input, Op, PEERS, catch, glyph_path, run};
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::{Duration, Instant};

const DEFAULT_FONT: &str = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// One hard case: name, what it tests, A, B (SVG path data).
struct Case {
    name: &'static str,
    what: &'static str,
    a: String,
    b: String,
}

/// The exact decimal expansion of a finite `f64` (every dyadic rational has one).
fn dec(x: f64) -> String {
    let r = BigRational::from_float(x).expect("finite");
    let neg = r < BigRational::zero();
    let r = if neg { -r } else { r };
    let int = r.to_integer();
    let mut frac = r - BigRational::from_integer(int.clone());
    let mut s = format!("{}{int}", if neg { "-" } else { "" });
    if !frac.is_zero() {
        s.push('.');
        let ten = BigRational::from_integer(10.into());
        while !frac.is_zero() {
            frac *= &ten;
            let d = frac.to_integer();
            frac -= BigRational::from_integer(d.clone());
            let _ = write!(s, "{d}");
        }
    }
    s
}

fn pts(ps: &[(f64, f64)]) -> String {
    ps.iter().map(|p| format!("{} {}", dec(p.0), dec(p.1))).collect::<Vec<_>>().join(" ")
}

/// A polygon, closed with `Z`.
fn poly(ps: &[(f64, f64)]) -> String {
    let mut s = format!("M{}", pts(&ps[..1]));
    for p in &ps[1..] {
        let _ = write!(s, " L{}", pts(&[*p]));
    }
    s + " Z"
}

/// The axis-aligned square (rectangle) from `(x0, y0)` to `(x1, y1)`, going along x first
/// (clockwise with y down); `rev`: the other way.
fn rect(x0: f64, y0: f64, x1: f64, y1: f64, rev: bool) -> String {
    let mut ps = vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1)];
    if rev {
        ps[1..].reverse();
    }
    poly(&ps)
}

fn sq(x0: f64, y0: f64, x1: f64, y1: f64) -> String {
    rect(x0, y0, x1, y1, false)
}

/// A circle of four cubics, handle `0.55224609375 r` (a dyadic near the usual 0.5523: the cubics
/// approximate the circle; the case is about their contact, which is exact: both circles of a
/// tangent pair have a vertex with the same tangent at the contact point).
fn circle(cx: f64, cy: f64, r: f64, rev: bool) -> String {
    let h = r * 0.55224609375;
    let ring = [
        (cx + r, cy),
        (cx + r, cy + h),
        (cx + h, cy + r),
        (cx, cy + r),
        (cx - h, cy + r),
        (cx - r, cy + h),
        (cx - r, cy),
        (cx - r, cy - h),
        (cx - h, cy - r),
        (cx, cy - r),
        (cx + h, cy - r),
        (cx + r, cy - h),
        (cx + r, cy),
    ];
    let ps: Vec<(f64, f64)> = if rev { ring.iter().rev().copied().collect() } else { ring.to_vec() };
    let mut s = format!("M{}", pts(&ps[..1]));
    for c in ps[1..].chunks(3) {
        let _ = write!(s, " C{}", pts(c));
    }
    s + " Z"
}

/// The blossom of cubic `p` at `(u, v, w)` (de Casteljau with a different parameter per level;
/// exact here: dyadic points and parameters with few bits).
fn blossom(p: &[(f64, f64); 4], u: f64, v: f64, w: f64) -> (f64, f64) {
    let lerp = |a: (f64, f64), b: (f64, f64), t: f64| (a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t);
    let l1: Vec<_> = (0..3).map(|i| lerp(p[i], p[i + 1], u)).collect();
    let l2: Vec<_> = (0..2).map(|i| lerp(l1[i], l1[i + 1], v)).collect();
    lerp(l2[0], l2[1], w)
}

/// The control points of cubic `p` restricted to `[t0, t1]`.
fn piece(p: &[(f64, f64); 4], t0: f64, t1: f64) -> [(f64, f64); 4] {
    [blossom(p, t0, t0, t0), blossom(p, t0, t0, t1), blossom(p, t0, t1, t1), blossom(p, t1, t1, t1)]
}

fn hard_cases() -> Vec<Case> {
    let case = |name, what, a: String, b: String| Case { name, what, a, b };
    // The arch: a cubic from (0,0) up to height 48 at t = 1/2 and back to (64,0), closed along y = 0.
    let arch_c = [(0.0, 0.0), (0.0, 64.0), (64.0, 64.0), (64.0, 0.0)];
    let arch = format!("M{} C{} Z", pts(&arch_c[..1]), pts(&arch_c[1..]));
    let left = piece(&arch_c, 0.0, 0.5);
    let mid = piece(&arch_c, 0.25, 0.75);
    let right = piece(&arch_c, 0.5, 1.0);
    let on_curve = blossom(&arch_c, 0.25, 0.25, 0.25); // (10, 36)
    let sliver = 10.0 - 2f64.powi(-20);
    vec![
        case("shared-edge", "two squares sharing a whole edge", sq(0., 0., 10., 10.), sq(10., 0., 20., 10.)),
        case(
            "shared-edge-part",
            "squares sharing part of an edge (each has a vertex on the other's edge)",
            sq(0., 0., 10., 10.),
            sq(10., 5., 20., 15.),
        ),
        case("identical", "A op A: the same square twice", sq(0., 0., 10., 10.), sq(0., 0., 10., 10.)),
        case(
            "identical-circle",
            "A op A: the same cubic circle twice",
            circle(0., 0., 64., false),
            circle(0., 0., 64., false),
        ),
        case("reversed", "coincident squares, B is A reversed", sq(0., 0., 10., 10.), rect(0., 0., 10., 10., true)),
        case(
            "reversed-circle",
            "coincident cubic circles, B is A reversed",
            circle(0., 0., 64., false),
            circle(0., 0., 64., true),
        ),
        case("corner-touch", "squares touching at one corner only", sq(0., 0., 10., 10.), sq(10., 10., 20., 20.)),
        case(
            "corner-shared-inside",
            "a square inside another, sharing a corner and parts of two edges",
            sq(0., 0., 10., 10.),
            sq(0., 0., 5., 5.),
        ),
        case(
            "edge-through-vertex",
            "B's edge passes through A's vertex (10,10)",
            sq(0., 0., 10., 10.),
            poly(&[(5., 15.), (15., 5.), (20., 20.)]),
        ),
        case(
            "vertex-on-edge-outside",
            "endpoint hit: B's vertex exactly on A's edge, B outside (a touch)",
            sq(0., 0., 10., 10.),
            poly(&[(10., 5.), (20., 0.), (20., 10.)]),
        ),
        case(
            "vertex-on-edge-crossing",
            "endpoint hit: B's vertex exactly on A's edge, B's edges on both sides of it",
            sq(0., 0., 10., 10.),
            poly(&[(10., 5.), (0., -5.), (20., -5.)]),
        ),
        case(
            "vertex-on-curve",
            "endpoint hit: B's vertex exactly on A's cubic at t = 1/4, B's edges on both sides",
            arch.clone(),
            poly(&[on_curve, (-10., 50.), (30., 20.)]),
        ),
        case(
            "tangent-circles-outside",
            "two cubic circles touching externally at a shared vertex (tangent contact)",
            circle(0., 0., 64., false),
            circle(128., 0., 64., false),
        ),
        case(
            "tangent-circles-inside",
            "a small cubic circle inside a large one, tangent at a shared vertex",
            circle(0., 0., 64., false),
            circle(32., 0., 32., false),
        ),
        case(
            "near-tangent-circles",
            "two cubic circles 2^-20 apart (no contact)",
            circle(0., 0., 64., false),
            circle(128. + 2f64.powi(-20), 0., 64., false),
        ),
        case(
            "circle-tangent-to-edge",
            "a square's edge tangent to a cubic circle at the circle's vertex, inside the square's edge",
            circle(0., 0., 64., false),
            sq(64., -64., 100., 64.),
        ),
        case(
            "arch-tangent-to-edge",
            "a square's edge tangent to a cubic at the cubic's interior point t = 1/2",
            arch.clone(),
            sq(0., 48., 64., 60.),
        ),
        case(
            "overlap-half-inside",
            "a cubic and its exact half (t in [0, 1/2]) overlap; B inside A",
            arch.clone(),
            format!("M{} C{} L32 0 Z", pts(&left[..1]), pts(&left[1..])),
        ),
        case(
            "overlap-half-outside",
            "a cubic and its exact half (t in [0, 1/2]) overlap; B outside A",
            arch.clone(),
            format!("M{} C{} L0 48 Z", pts(&left[..1]), pts(&left[1..])),
        ),
        case(
            "overlap-middle",
            "a cubic and its exact middle piece (t in [1/4, 3/4]) overlap; B outside A",
            arch.clone(),
            format!("M{} C{} L32 80 Z", pts(&mid[..1]), pts(&mid[1..])),
        ),
        case(
            "overlap-reversed",
            "a cubic and its exact half (t in [1/2, 1]) traversed backwards; B outside A",
            arch.clone(),
            format!("M{} C{} {} {} L64 48 Z", pts(&right[3..]), pts(&right[2..3]), pts(&right[1..2]), pts(&right[..1])),
        ),
        case(
            "three-curves",
            "three curves through one point: A's edge, B's line and B's cubic (tangent to A's edge) at (0,0)",
            poly(&[(-10., -10.), (10., 10.), (10., -10.)]),
            "M0 0 L-8 8 L-16 0 C-8 -8 -4 -4 0 0 Z".into(),
        ),
        case(
            "three-contours-one-point",
            "A's two triangles and B's triangle all have a vertex at (0,0)",
            format!("{} {}", poly(&[(0., 0.), (10., 5.), (10., -5.)]), poly(&[(0., 0.), (-10., -5.), (-10., 5.)])),
            poly(&[(0., 0.), (5., 10.), (-5., 10.)]),
        ),
        case(
            "figure-eight",
            "a self-crossing cubic figure-eight (loops of opposite winding); B's edge through the crossing",
            "M0 0 C8 8 16 8 16 0 C16 -8 8 -8 0 0 C-8 8 -16 8 -16 0 C-16 -8 -8 -8 0 0 Z".into(),
            sq(0., -10., 20., 10.),
        ),
        case(
            "bowtie",
            "a self-crossing polygon; B a square around the crossing",
            poly(&[(0., 0.), (20., 20.), (20., 0.), (0., 20.)]),
            sq(5., 5., 15., 15.),
        ),
        case(
            "pentagram",
            "a self-crossing star (winding 2 in the middle: filled non-zero, a hole even-odd); B in the middle, its top corners exactly on two of the star's edges",
            poly(&[(0., -10.), (6., 8.), (-10., -4.), (10., -4.), (-6., 8.)]),
            sq(-2., -2., 2., 2.),
        ),
        case(
            "nested-same",
            "nested squares of the same orientation (winding 2 inside: filled non-zero, a hole even-odd)",
            format!("{} {}", sq(0., 0., 30., 30.), sq(10., 10., 20., 20.)),
            sq(15., -5., 35., 35.),
        ),
        case(
            "nested-opposite",
            "nested squares of opposite orientations (a hole under both rules)",
            format!("{} {}", sq(0., 0., 30., 30.), rect(10., 10., 20., 20., true)),
            sq(15., -5., 35., 35.),
        ),
        case(
            "collinear-cubics-overlap",
            "flat cubics on y = 0 (control points collinear, unevenly spaced, opposite directions) overlapping on x in [10, 30]",
            "M0 0 C2 0 26 0 30 0 L30 10 L0 10 Z".into(),
            "M40 0 C36 0 12 0 10 0 L10 -10 L40 -10 Z".into(),
        ),
        case(
            "collinear-cubic-folding",
            "a flat cubic that runs along y = 0, turns back and goes on again (x: 0, 50/3 at t = 1/3, back to 40/3 at t = 2/3, 30)",
            "M0 0 C40 0 -10 0 30 0 L30 10 L0 10 Z".into(),
            sq(10., -5., 20., 5.),
        ),
        case(
            "zero-length",
            "zero-length segments: repeated line points and a cubic with all four points equal",
            "M0 0 L0 0 L10 0 C10 0 10 0 10 0 L10 10 L0 10 L0 10 Z".into(),
            sq(5., 5., 15., 15.),
        ),
        case(
            "glyph-t",
            "glyph-like overlapping contours (a T of two bars, same orientation); B overlaps the junction",
            format!("{} {}", sq(0., 0., 40., 8.), sq(16., -4., 24., 30.)),
            sq(20., 4., 50., 20.),
        ),
        case(
            "glyph-o",
            "a ring (cubic circle and a smaller reversed one, like an o); B a bar through it",
            format!("{} {}", circle(0., 0., 64., false), circle(0., 0., 32., true)),
            sq(-8., -80., 8., 80.),
        ),
        case("sliver", "squares overlapping by 2^-20 along an edge", sq(0., 0., 10., 10.), sq(sliver, 0., 20., 10.)),
        case("empty-b", "B is empty path data (A op nothing)", sq(0., 0., 10., 10.), String::new()),
    ]
}

/// Every coordinate of `d`, read exactly, is an `f64` (so the peers see exactly what the oracle
/// decides).
fn check_exact_f64(d: &str) {
    use casteljau::format::Segment;
    if d.is_empty() {
        return;
    }
    for c in parse_path(d, NumberMode::Exact).unwrap_or_else(|e| panic!("{d}: {e}")) {
        for s in c.segments {
            let Segment::Bezier(ps) = s else { panic!("{d}: a skipped piece") };
            for v in ps.iter().flat_map(|p| p.coords.iter()) {
                let f = v.to_f64().expect("finite");
                assert_eq!(BigRational::from_float(f).as_ref(), Some(v), "{d}: {v} is not an f64");
            }
        }
    }
}

fn secs(d: Duration) -> String {
    format!("{:.3} s", d.as_secs_f64())
}

fn main() {
    let mut args = std::env::args().skip(1);
    let mut font = PathBuf::from(DEFAULT_FONT);
    let mut out = PathBuf::from("target/path_ops_peers");
    let mut hard_file = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/boolean/hard.txt"));
    let mut fill = Fill::NonZero;
    let mut do_font = true;
    while let Some(a) = args.next() {
        match a.as_str() {
            "--out" => out = args.next().expect("--out DIR").into(),
            "--hard" => hard_file = args.next().expect("--hard FILE").into(),
            "--fill" => {
                fill = match args.next().as_deref() {
                    Some("nonzero") => Fill::NonZero,
                    Some("evenodd") => Fill::EvenOdd,
                    other => panic!("--fill nonzero|evenodd, not {other:?}"),
                }
            }
            "--no-font" => do_font = false,
            _ => font = a.into(),
        }
    }
    std::fs::create_dir_all(&out).expect("--out directory");
    peers::quiet_panics();

    if do_font {
        font_part(&font, &out, fill);
    }

    let cases = hard_cases();
    let mut text = String::from(
        "# Hard cases for boolean operations on paths (issue #27), generated by\n\
         # `cargo run -p casteljau-bench --release --example path_ops_peers` (benches/examples/path_ops_peers.rs); do not edit.\n\
         # Each case: a comment line `# name: what it tests`, then `A ; B` in SVG path data.\n\
         # Every coordinate is an exact decimal and an exact binary64 number.\n\n",
    );
    for c in &cases {
        check_exact_f64(&c.a);
        check_exact_f64(&c.b);
        let _ = writeln!(text, "# {}: {}\n{} ; {}", c.name, c.what, c.a, c.b);
    }
    if let Some(dir) = hard_file.parent() {
        std::fs::create_dir_all(dir).expect("hard-case directory");
    }
    std::fs::write(&hard_file, &text).expect("write the hard cases");
    println!("\n{} hard cases written to {}", cases.len(), hard_file.display());
    hard_part(&cases, &out, fill);
}

fn font_part(font: &PathBuf, out: &std::path::Path, fill: Fill) {
    let data = match std::fs::read(font) {
        Ok(d) => d,
        Err(e) => {
            println!("{}: {e}; the font part is skipped", font.display());
            return;
        }
    };
    let f = Font::open(&data, 0).expect("a font");
    let glyphs: Vec<(u32, Option<String>, Result<Input, String>)> =
        (0..f.num_glyphs()).map(|gid| (gid, f.glyph_name(gid), glyph_path(&f, gid).map(Input::new))).collect();
    println!(
        "{}: {} glyphs, simplify (linesweeper {fill:?}, flo_curves EvenOdd), single-threaded\n",
        font.display(),
        glyphs.len()
    );
    println!("| peer | wall time | glyphs | errors | of which panics |");
    println!("| --- | ---: | ---: | ---: | ---: |");
    for peer in PEERS {
        let t = Instant::now();
        let results: Vec<Result<peers::Output, String>> = glyphs
            .iter()
            .map(|(_, _, g)| match g {
                Ok(g) => catch(|| run(peer, g, None, fill, Op::Union)),
                Err(e) => Err(format!("reading the glyph: {e}")),
            })
            .collect();
        let took = t.elapsed();
        let mut lines = String::new();
        let (mut errors, mut panics) = (0, 0);
        for ((gid, name, _), r) in glyphs.iter().zip(&results) {
            let mut row = serde_json::Map::new();
            row.insert("glyph".into(), name.clone().into());
            row.insert("glyph_id".into(), (*gid).into());
            match r {
                Ok(o) => {
                    row.insert("path".into(), o.svg().into());
                }
                Err(e) => {
                    errors += 1;
                    panics += usize::from(e.starts_with("panic"));
                    row.insert("error".into(), e.clone().into());
                }
            }
            lines.push_str(&serde_json::Value::Object(row).to_string());
            lines.push('\n');
        }
        let file = out.join(format!("{peer}.jsonl"));
        std::fs::write(&file, lines).expect("write JSON Lines");
        println!("| {peer} | {} | {} | {errors} | {panics} |", secs(took), glyphs.len());
    }
    // flo_curves' "non-zero" overlap removal, for the record: glyphs where it has fewer contours
    // than its even-odd one (a filled counter, mostly).
    let fewer = glyphs
        .iter()
        .filter_map(|(_, _, g)| g.as_ref().ok())
        .filter(|g| {
            let n = |r: Result<Vec<_>, String>| r.map_or(usize::MAX, |v| v.len());
            n(catch(|| Ok(peers::flo_remove_interior(&g.flo)))) < n(catch(|| Ok(peers::flo_simplify_raw(&g.flo))))
        })
        .count();
    println!(
        "\nflo_curves' path_remove_interior_points (its non-zero rule, not used) has fewer contours than \
         path_remove_overlapped_points (even-odd, used) on {fewer} glyphs"
    );
}

fn hard_part(cases: &[Case], out: &std::path::Path, fill: Fill) {
    let read = |d: &str| BezPath::from_svg(d).map(Input::new).unwrap_or_else(|e| panic!("{d}: {e}"));
    let inputs: Vec<(Input, Input)> = cases.iter().map(|c| (read(&c.a), read(&c.b))).collect();
    println!(
        "\nhard cases (linesweeper {fill:?}, flo_curves EvenOdd): wall time for all {} cases, and cases with an \
         error (panics)\n",
        cases.len()
    );
    println!("| op | {} |", PEERS.join(" | "));
    println!("| --- |{}", " ---: |".repeat(PEERS.len()));
    for op in Op::ALL {
        let mut row = format!("| {} |", op.name());
        for peer in PEERS {
            let t = Instant::now();
            let results: Vec<_> = inputs.iter().map(|(a, b)| catch(|| run(peer, a, Some(b), fill, op))).collect();
            let took = t.elapsed();
            let mut text = String::new();
            let (mut errors, mut panics) = (0, 0);
            for r in &results {
                match r {
                    Ok(o) => text.push_str(&o.svg()),
                    Err(e) => {
                        errors += 1;
                        panics += usize::from(e.starts_with("panic"));
                        let _ = write!(text, "# error: {}", e.replace('\n', " "));
                    }
                }
                text.push('\n');
            }
            std::fs::write(out.join(format!("hard-{}-{peer}.txt", op.name())), text).expect("write results");
            let _ = write!(row, " {}, {errors} ({panics}) |", secs(took));
        }
        println!("{row}");
    }
    println!("\noutputs in {}", out.display());
}
