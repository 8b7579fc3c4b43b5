//! A fuzz harness through the real binary: structured and random invocations of every
//! subcommand, each run with a time cap, asserting the promise "every input answered":
//! exit code 0, 1 or 2, no signal, no panic text, a message on exit 2, JSON lines that parse,
//! no half-written file.
//!
//! `cargo test --test it fuzz::` runs a bounded, seeded set (a few hundred cases). For releases:
//! `CASTELJAU_FUZZ_CASES=100000 cargo test --release --test it fuzz:: -- --nocapture` (any
//! `CASTELJAU_FUZZ_SEED`); failures print the exact invocation to reproduce.
//!
//! Written by hand rather than with a fuzzing crate: the cases are whole command lines for a
//! process with a time cap, which coverage-guided in-process fuzzers do not drive.

use std::io::Write;
use std::time::{Duration, Instant};

/// xorshift64*: deterministic, seedable, no dependency.
pub(crate) struct Rng(pub(crate) u64);

impl Rng {
    pub(crate) fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    pub(crate) fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    pub(crate) fn pick<'a>(&mut self, xs: &[&'a str]) -> &'a str {
        xs[self.below(xs.len())]
    }
    pub(crate) fn chance(&mut self, percent: usize) -> bool {
        self.below(100) < percent
    }
}

const GOOD_NUMBERS: &[&str] =
    &["0", "1", "-1", "2", "1/2", "-1/3", "0.25", "1e-3", "7/5", "3", "-2", "12345/67891", "0x10p-4"];
const BAD_NUMBERS: &[&str] = &["x", "1/0", "", "nan", "inf", "1//2", "--1", "1e", "0x", "½", "1e400000000"];

fn number(r: &mut Rng) -> String {
    if r.chance(6) { r.pick(BAD_NUMBERS).to_string() } else { r.pick(GOOD_NUMBERS).to_string() }
}

fn numbers(r: &mut Rng, n: usize) -> String {
    (0..n).map(|_| number(r)).collect::<Vec<_>>().join(" ")
}

fn curve(r: &mut Rng, points: usize, dim: usize) -> String {
    let sep = if r.chance(5) { ";" } else { ", " };
    let mut s = (0..points).map(|_| numbers(r, dim)).collect::<Vec<_>>().join(sep);
    if r.chance(3) {
        s.push(',');
    }
    if r.chance(2) {
        s = format!("{s} {}", number(r)); // a dangling coordinate
    }
    s
}

/// One invocation: the arguments and, sometimes, a batch on stdin.
fn case(r: &mut Rng) -> (Vec<String>, Option<String>) {
    let pts = r.below(6) + 1;
    let c = |r: &mut Rng| curve(r, pts, 2);
    let mut a: Vec<String> = Vec::new();
    let s = |x: &str| x.to_string();
    match r.below(22) {
        18..=21 => return shapes(r),
        0 => a.extend([s("eval"), s("--t"), number(r), c(r)]),
        1 => {
            a.extend([s("subdivide"), s("--t"), number(r)]);
            if r.chance(50) {
                a.extend([s("--depth"), (r.below(6)).to_string()]);
            }
            a.push(c(r));
        }
        2 => a.extend([s("elevate"), s("--by"), r.below(4).to_string(), c(r)]),
        3 => a.extend([s("power"), c(r)]),
        4 => a.extend([s("triangle"), s("--t"), number(r), c(r)]),
        5 => a.extend([s("derivative"), s("--order"), r.below(5).to_string(), c(r)]),
        6 => a.extend([s("reduce"), c(r)]),
        7 => {
            let k = r.below(3) + 2;
            a.extend([s("classify"), curve(r, k + 1, 2)]);
            if r.chance(30) {
                a.extend([s("--weights"), numbers(r, k + 1)]);
            }
        }
        8 => a.extend([
            s("implicit"),
            s("--poly"),
            s(r.pick(&["x^2 + y^2 - 1", "x - y", "x/0", "(x", "x^-1", "y^3 - x*y + 2"])),
            c(r),
        ]),
        9 => a.extend([s("defined"), s("--weights"), numbers(r, pts), c(r)]),
        10 => a.extend([s("conic"), s("--weights"), numbers(r, 3), curve(r, 3, 2)]),
        11 => a.extend([s("eval"), s("--weights"), numbers(r, pts), s("--t"), number(r), c(r)]),
        12 => {
            let (m, n) = (r.below(3), r.below(3));
            a.extend([
                s("surface"),
                s(r.pick(&["eval", "elevate", "subdivide", "contour"])),
                s("--degree"),
                format!("{m},{n}"),
            ]);
            a.extend([s("--u"), number(r)]);
            if r.chance(50) {
                a.extend([s("--weights"), numbers(r, (m + 1) * (n + 1))]);
            }
            a.push(curve(r, (m + 1) * (n + 1), 3));
        }
        13 => {
            let n = r.below(3) + 1;
            let count = pts.max(n + 1);
            a.extend([s("spline"), s(r.pick(&["to-bezier", "check", "elevate"])), s("--degree"), n.to_string()]);
            if r.chance(50) {
                a.extend([s("--knots"), numbers(r, count + n + 1)]);
            } else {
                a.extend([s("--ratios"), numbers(r, count + n - 1)]);
            }
            if r.chance(40) {
                a.extend([s("--weights"), numbers(r, count)]);
            }
            a.push(curve(r, count, 2));
        }
        14 => a.extend([s("plot"), s(r.pick(&["--polygon", "--features", "--grid"])), c(r)]),
        15 => {
            // a batch on stdin, JSON Lines out
            let cmd = r.pick(&["eval", "classify", "power", "reduce", "subdivide"]);
            a.extend([s(cmd), s("--json")]);
            if cmd == "eval" {
                a.extend([s("--t"), s("1/3")]);
            }
            let lines: Vec<String> = (0..r.below(8) + 1)
                .map(|_| {
                    if r.chance(10) {
                        s(r.pick(&["", "# comment", "\u{feff}0 0, 1 1", "0 0,, 1 1", "{}"]))
                    } else {
                        let k = if cmd == "classify" { r.below(3) + 2 } else { r.below(5) + 1 };
                        curve(r, k, 2)
                    }
                })
                .collect();
            return (a, Some(lines.join("\n")));
        }
        16 if r.chance(25) => return huge(r),
        16 if r.chance(30) => {
            // one long line of many small points (once half a gigabyte per 10 MB line):
            // refused by its degree before its numbers are read
            let cmd = r.pick(&["eval", "classify", "power", "subdivide"]);
            a.extend([s(cmd), s("--t"), s("1/3")]);
            if cmd == "classify" || cmd == "power" {
                a.truncate(1);
            }
            let points = *[10_001usize, 10_002, 200_000].get(r.below(3)).unwrap();
            let line: Vec<String> = (0..points).map(|i| format!("{} {}", i % 97, i % 89)).collect();
            return (a, Some(line.join(r.pick(&[", ", " ", ","]))));
        }
        17 if r.chance(50) => return claim_file(r),
        _ => {
            // random tokens: options and values in any order
            let words = [
                "eval",
                "classify",
                "--t",
                "--json",
                "--weights",
                "--homogeneous",
                "--dim",
                "3",
                "0",
                "-",
                "--depth",
                "1 2, 3 4",
            ];
            a.extend((0..r.below(6) + 1).map(|_| s(r.pick(&words))));
        }
    }
    (a, None)
}

/// Numbers of shapes: small, fractional, and of very different magnitudes (past the `f64`
/// range too).
const SHAPE_NUMBERS: &[&str] = &[
    "0",
    "1",
    "2",
    "3",
    "-1",
    "0.5",
    "7",
    "10",
    "1e300",
    "-1e300",
    "1e-300",
    "1e400",
    "12345678901234567890",
    "1e-20",
];

/// SVG path data: a few closed contours of lines, quadratics and cubics.
fn path_data(r: &mut Rng) -> String {
    let mut d = String::new();
    for _ in 0..r.below(2) + 1 {
        let n = |r: &mut Rng| -> String {
            if r.chance(80) {
                r.pick(&["0", "1", "2", "3", "5", "0.5"]).to_string()
            } else {
                r.pick(SHAPE_NUMBERS).to_string()
            }
        };
        let ns = |r: &mut Rng, k: usize| (0..k).map(|_| n(r)).collect::<Vec<_>>().join(" ");
        d += &format!("M{}", ns(r, 2));
        for _ in 0..r.below(4) + 1 {
            let seg = match r.below(5) {
                0 => format!(" L{}", ns(r, 2)),
                1 => format!(" Q{}", ns(r, 4)),
                2 => format!(" C{}", ns(r, 6)),
                3 => format!(" H{}", n(r)),
                _ => format!(" V{}", n(r)),
            };
            d += &seg;
        }
        d += " Z ";
    }
    d
}

/// `boolean`, `arrange`, `lint` and `scan` on path data and SVG documents: magnitudes past the
/// `f64` range, nested and huge transforms, tight budgets, absurd thread counts.
fn shapes(r: &mut Rng) -> (Vec<String>, Option<String>) {
    let s = |x: &str| x.to_string();
    let mut a: Vec<String> = match r.below(6) {
        0 => {
            let op = r.pick(&["union", "intersection", "difference", "xor"]);
            vec![s("boolean"), s(op), path_data(r), path_data(r)]
        }
        1 => vec![s("boolean"), s("simplify"), path_data(r)],
        2 => vec![s("arrange"), path_data(r), path_data(r)],
        3 => vec![s("lint"), s("--path"), path_data(r)],
        _ => {
            // an SVG document on disk: nested or huge transforms around a path
            static COUNTER: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
            let k = COUNTER.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            let dir = std::env::temp_dir().join(format!("casteljau-fuzz-svg-{}-{k}", std::process::id()));
            std::fs::create_dir_all(&dir).unwrap();
            // (deep nests of transforms whose numbers grow fast are the readers' own cases)
            let (depth, t) = match r.below(3) {
                0 => (1000, "scale(3)"),
                1 => (
                    *[1usize, 2, 10].get(r.below(3)).unwrap(),
                    r.pick(&["scale(1e300)", "translate(1e300 0)", "scale(1e-300)"]),
                ),
                _ => (
                    *[1usize, 10].get(r.below(2)).unwrap(),
                    r.pick(&["scale(1.0001)", "rotate(45)", "matrix(0 1 1 0 0 0)"]),
                ),
            };
            let svg = format!(
                "<svg xmlns=\"http://www.w3.org/2000/svg\">{}<path d=\"{}\"/>{}</svg>",
                format!("<g transform=\"{t}\">").repeat(depth),
                path_data(r),
                "</g>".repeat(depth)
            );
            let file = dir.join("s.svg");
            std::fs::write(&file, svg).unwrap();
            let f = file.to_string_lossy().into_owned();
            match r.below(4) {
                0 => vec![s("boolean"), s("simplify"), f],
                1 => vec![s("arrange"), f],
                2 => vec![s("lint"), f],
                _ => vec![s("scan"), f],
            }
        }
    };
    if r.chance(40) {
        a.push(s("--json"));
    }
    // within the 10 s cap whatever the machine's load: a budget of about a second at most
    if a[0] != "scan" {
        a.extend([s("--max-work"), s(r.pick(&["1", "1e6", "1e8", "1e9", "1e9"]))]);
    }
    if a[0] == "lint" && r.chance(20) {
        a.extend([s("--threads"), s("100000")]);
    }
    (a, None)
}

/// Whether the output has a float that is not finite as Rust writes it (`inf`, `NaN`), in
/// words or path data (`Linf`), not inside a word (`inflection`).
pub(crate) fn has_non_finite(text: &str) -> bool {
    // error lines quote the input's token (`bad number "inf"`): only answers count
    text.lines().filter(|l| !l.contains("\"error\"") && !l.contains("error:")).any(non_finite_in_line)
}

fn non_finite_in_line(text: &str) -> bool {
    let b = text.as_bytes();
    ["inf", "NaN"].iter().any(|w| {
        text.match_indices(w).any(|(i, _)| {
            let before = i.checked_sub(1).map(|j| b[j]);
            let after = b.get(i + w.len()).copied();
            !before.is_some_and(|c| c.is_ascii_lowercase()) && !after.is_some_and(|c| c.is_ascii_alphanumeric())
        })
    })
}

/// Inputs at and past the documented sizes (degree 10,000, 1000-character parameters, nested
/// folds, big grids): each must be refused by its work estimate or answered within the cap.
fn huge(r: &mut Rng) -> (Vec<String>, Option<String>) {
    let s = |x: &str| x.to_string();
    let points = *[2000usize, 5000, 10_001, 10_002].get(r.below(4)).unwrap();
    let poly: String =
        (0..points).map(|i| format!("{} {}", (i * 7919) % 2001, (i * 104_729) % 1999)).collect::<Vec<_>>().join(", ");
    let digits = format!("1/{}", "7".repeat(r.below(998) + 1));
    let mut a: Vec<String> = match r.below(9) {
        0 => vec![s("power")],
        1 => vec![s("reduce")],
        2 => vec![s("subdivide"), s("--t"), digits],
        3 => vec![s("eval"), s("--t"), digits],
        4 => vec![s("derivative"), s("--order"), r.below(points).to_string()],
        5 => vec![s("elevate"), s("--by"), r.below(50).to_string()],
        6 => {
            let w: Vec<String> = (0..points).map(|i| if (i * 31) % 7 == 0 { s("-1") } else { s("2") }).collect();
            vec![s("defined"), s("--weights"), w.join(" ")]
        }
        7 if r.chance(50) => vec![s("plot"), s(r.pick(&["--features", "--polygon", "--grid"]))],
        7 => vec![s("triangle"), s("--t"), s(r.pick(&["1/2", "12345/67891"]))],
        _ => {
            let inner = r.pick(&["x", "x*y", "x^100000", "B(3, 100000, x)", "C(100000, 50000)"]);
            return (
                vec![
                    s("implicit"),
                    s("--poly"),
                    format!("sum(r, 0, 100000, sum(s, 0, 100000, {inner}))"),
                    s("--max-work"),
                    s("1e9"),
                    s("0 0, 1 1"),
                ],
                None,
            );
        }
    };
    a.extend([s("--max-work"), s(r.pick(&["1e9", "1e8", "3e9"]))]);
    // the polygon on stdin: argv strings are capped at 128 KiB
    (a, Some(poly))
}

/// A claim file of random fragments (sizes at and past the limits, bad expressions), checked
/// by `prove`.
fn claim_file(r: &mut Rng) -> (Vec<String>, Option<String>) {
    static COUNTER: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let k = COUNTER.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("casteljau-fuzz-claims-{}-{k}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let lhs = r.pick(&["B(j, n, t)", "sum(k, 0, n, B(k, n, t))", "t^n", "(t", "1/0", "prod(k, 1, n, t)", "C(n, j)"]);
    let rhs = r.pick(&["1", "t", "sum(r, j, n, B(j, r, t) * B(r, n, t))", "x", "t^(n+1)/t"]);
    let range = r.pick(&["0..=3", "0..=99999", "0..=100001", "-5000000000000000000..=5000000000000000000", "3..=1"]);
    let extra = r.pick(&["", "steps = 4000000000\n", "degree = 1000000000\n", "unknown = 1\n"]);
    let head =
        "seed = \"x\"\ntitle = \"x\"\n\n[[claim]]\nid = \"f\"\nsource = \"x\"\nstatement = \"x\"\nexpect = \"holds\"\n";
    let text = if r.chance(40) {
        // kinds whose work grows with depth, degree or grid: estimated and refused up front
        // (a depth-16 subdivision of a degree-10 curve once ran past 13 minutes)
        let n = *[3usize, 10, 40, 200].get(r.below(4)).unwrap();
        let curve: Vec<String> = (0..=n).map(|i| format!("{i} {}", (i * 7) % 11)).collect();
        let curve = curve.join(", ");
        let net: Vec<String> = (0..n.min(40))
            .map(|i| (0..n.min(40)).map(|j| format!("{i} {j} 1")).collect::<Vec<_>>().join(", "))
            .collect();
        let body = match r.below(6) {
            0 => format!(
                "kind = \"repeated-subdivision\"\ncurve = \"{curve}\"\nt = \"{}\"\ndepth = {}\npieces = 4",
                r.pick(&["1/2", "12345/67891"]),
                r.below(18)
            ),
            1 => format!("kind = \"rational-evaluations\"\ncurve = \"{curve}\""),
            2 => format!("kind = \"weight-pull\"\ncurve = \"{curve}\"\nindex = 1\nweight = \"9\""),
            3 => format!("kind = \"patch-evaluations\"\nnet = \"{}\"", net.join("; ")),
            4 => format!("kind = \"implicit\"\ncurve = \"{curve}\"\npoly = \"x^{} - y\"", r.below(60)),
            _ => format!("kind = \"table\"\ncurve = \"{curve}\"\nsteps = {}\nvalues = []", r.below(100_000) + 1),
        };
        format!("{head}{body}\n")
    } else {
        format!(
            "{head}kind = \"{}\"\nvars = [\"t\"]\nparams = [\"n in {range}\", \"j in 0..=n\"]\nlhs = \"{lhs}\"\nrhs = \"{rhs}\"\n{extra}",
            r.pick(&["identity", "table", "matrix", "nonsense"])
        )
    };
    std::fs::write(dir.join("c.toml"), text).unwrap();
    let s = |x: &str| x.to_string();
    let mut a = vec![s("prove"), dir.to_string_lossy().into_owned(), s("--max-work"), s("1e8")];
    if r.chance(30) {
        a.push(s("--json"));
    }
    (a, None)
}

/// Runs one case with a time cap; returns a description of what broke the promise, if anything.
pub(crate) fn check(args: &[String], stdin: Option<&str>, cap: Duration) -> Option<String> {
    let mut child = crate::common::spawn(args);
    let mut pipe = child.stdin.take().expect("stdin");
    let input = stdin.unwrap_or("").to_string();
    let writer = std::thread::spawn(move || {
        let _ = pipe.write_all(input.as_bytes());
    });
    // read both pipes while the child runs: a full pipe would otherwise stall it
    let drain = |mut r: Box<dyn std::io::Read + Send>| {
        std::thread::spawn(move || {
            let mut v = Vec::new();
            let _ = r.read_to_end(&mut v);
            v
        })
    };
    let out_reader = drain(Box::new(child.stdout.take().expect("stdout")));
    let err_reader = drain(Box::new(child.stderr.take().expect("stderr")));
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().ok().flatten() {
            break status;
        }
        if start.elapsed() > cap {
            let _ = child.kill();
            let _ = child.wait();
            return Some(format!("no answer within {cap:?}"));
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    let _ = writer.join();
    let (out_bytes, err_bytes) = (out_reader.join().expect("stdout"), err_reader.join().expect("stderr"));
    let (stdout, stderr) = (String::from_utf8_lossy(&out_bytes), String::from_utf8_lossy(&err_bytes));
    let code = match status.code() {
        Some(c) => c,
        None => return Some("killed by a signal".into()),
    };
    if ![0, 1, 2].contains(&code) {
        return Some(format!("exit code {code}: {stderr}"));
    }
    if stderr.contains("panicked") || stderr.contains("RUST_BACKTRACE") {
        return Some(format!("panic: {stderr}"));
    }
    // a weight message says which weight: never the bare "a weight is 0" / "one weight per
    // control point" of old
    for vague in ["a weight is 0", "one weight per control point"] {
        if stderr.contains(vague) {
            return Some(format!("a weight message that does not say which: {stderr}"));
        }
    }
    // finite output or a refusal (a number that is not finite never printed)
    if has_non_finite(&stdout) {
        return Some(format!(
            "a number that is not finite in the output: {}",
            &stdout[..stdout.floor_char_boundary(300)]
        ));
    }
    let json = args.iter().any(|a| a == "--json");
    // lint reports a glyph it could not check on its own line of the report
    let lint_error = args.first().is_some_and(|a| a == "lint") && stdout.contains(": error: ");
    if code == 2 && stderr.trim().is_empty() && !(json && stdout.contains("\"error\"")) && !lint_error {
        return Some("exit 2 without a message".into());
    }
    if json && !args.iter().any(|a| a == "plot") {
        for line in stdout.lines() {
            if serde_json::from_str::<serde_json::Value>(line).is_err() {
                return Some(format!("not JSON: {line}"));
            }
        }
    }
    None
}

fn run_cases(count: usize, seed: u64) {
    let mut r = Rng(seed | 1);
    let cap = Duration::from_secs(10);
    let mut failures = Vec::new();
    for k in 0..count {
        let (args, stdin) = case(&mut r);
        let why = check(&args, stdin.as_deref(), cap);
        if args.first().is_some_and(|a| a == "prove")
            && args.get(1).is_some_and(|p| p.contains("casteljau-fuzz-claims"))
        {
            let _ = std::fs::remove_dir_all(&args[1]);
        }
        if let Some(svg) = args.iter().find(|a| a.contains("casteljau-fuzz-svg-"))
            && let Some(dir) = std::path::Path::new(svg).parent()
        {
            let _ = std::fs::remove_dir_all(dir);
        }
        if let Some(why) = why {
            let shown = |x: &str| {
                if x.len() > 300 {
                    format!("{}… ({} bytes)", &x[..x.floor_char_boundary(300)], x.len())
                } else {
                    x.to_string()
                }
            };
            let args: Vec<String> = args.iter().map(|a| shown(a)).collect();
            failures.push(format!("case {k}: {why}\n  args: {args:?}\n  stdin: {:?}", stdin.as_deref().map(shown)));
        }
    }
    eprintln!("fuzz: {count} invocations (seed {seed}), {} failures", failures.len());
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn fuzz_every_invocation_is_answered_bounded_run() {
    let count = std::env::var("CASTELJAU_FUZZ_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(300);
    let seed = std::env::var("CASTELJAU_FUZZ_SEED").ok().and_then(|v| v.parse().ok()).unwrap_or(20261122);
    run_cases(count, seed);
}

/// No file is left behind when `plot -o` or `prove --junit` fails.
#[test]
fn fuzz_failed_outputs_leave_no_file() {
    let dir = crate::common::TempDir::new("fuzz-out");
    let svg = dir.join("x.svg");
    let o = crate::common::run(&["plot", "-o", svg.to_str().unwrap(), "0 0, 1 x"], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(std::fs::read_dir(dir.path()).unwrap().next().is_none(), "a file was left behind");
}
