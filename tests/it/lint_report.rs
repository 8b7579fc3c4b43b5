//! `casteljau lint --html`: the report in a real browser (headless Chromium), its counts against
//! the `--json` findings of the same run, its bytes run to run, and its writing all or nothing.
//!
//! The browser test needs `chromium` (`/usr/bin/chromium` or on `PATH`; Debian's package, which
//! `.ci/run` installs). Without it the test says SKIPPED on stderr and passes, except under CI
//! (the `CI` variable set), where it fails.

use crate::common::{TempDir, run, stdout};
use serde_json::Value;
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Flagged glyphs of Tuffy (a wrong direction, overlaps, a self-intersection, overlapping
/// segments, a wrong stored box, missing extrema, kinks...) and `O`, whose findings rounding
/// explains all: it is in the glyph table but not drawn.
const GLYPHS: &str = "uni1EFA,ghestrokecyrillic,ae,obarredcyrillic,uni03E1,Aogonek,O";

/// The Content-Security-Policy every report carries (no scripts, no network).
const CSP: &str =
    "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'\">\n";

/// Appended by the test (never in the report): writes what the browser laid out into
/// `<pre id="measure">` as JSON.
const MEASURE: &str = r##"<script>
addEventListener('load', () => {
  const svgs = [...document.querySelectorAll('svg.glyph')];
  const drawings = svgs.map(s => {
    const r = s.getBoundingClientRect();
    return {width: r.width, height: r.height, width_attr: s.getAttribute('width'), height_attr: s.getAttribute('height')};
  });
  const fileOf = e => { const f = e.closest('[data-file]'); return f ? f.dataset.file : null; };
  const cells = [...document.querySelectorAll('[data-kind]')].map(e => ({
    file: fileOf(e), kind: e.dataset.kind, count: e.dataset.count ?? null,
    rounding: e.dataset.rounding ?? null, text: e.textContent.trim()}));
  const cards = [...document.querySelectorAll('.card')].map(c => ({
    file: fileOf(c), glyph_id: c.dataset.glyphId ?? null, element: c.dataset.element ?? null,
    drawings: c.querySelectorAll('svg.glyph').length}));
  const links = [...document.querySelectorAll('a[href^="#"]')];
  const broken = links.filter(a => !document.getElementById(a.getAttribute('href').slice(1))).length;
  const pre = document.createElement('pre');
  pre.id = 'measure';
  pre.textContent = JSON.stringify({svgs: svgs.length, drawings, cells, cards, links: links.length, broken});
  document.body.appendChild(pre);
});
</script>
"##;

fn tuffy() -> String {
    format!("{}/tests/data/fonts/Tuffy.ttf", env!("CARGO_MANIFEST_DIR"))
}

/// An SVG file with a self-intersecting bow tie (its id needs escaping), an open S curve, a
/// clean square and a cusp.
const SHAPES: &str = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 100">
  <path id="bow&amp;tie&lt;b&gt;" d="M10 10 L90 90 L90 10 L10 90 Z"/>
  <path d="M110 10 C190 10 110 90 190 90"/>
  <rect id="ok" x="0" y="0" width="5" height="5"/>
  <path id="cusp" d="M100 50 C150 0 100 0 150 50 Z"/>
</svg>
"#;

/// Runs `casteljau lint ARGS --json --html REPORT`; returns the report, the JSON findings and
/// the exit code.
fn lint(args: &[&str], report: &Path) -> (String, Vec<Value>, i32) {
    let mut full = vec!["lint"];
    full.extend(args);
    full.extend(["--json", "-q", "--html", report.to_str().unwrap()]);
    let o = run(&full, None);
    let lines = stdout(&o).lines().map(|l| serde_json::from_str(l).expect("a JSON line")).collect();
    let html = std::fs::read_to_string(report).expect("the report is written");
    (html, lines, o.status.code().unwrap())
}

/// Per file, per kind: (findings not explained by rounding, findings rounding explains).
fn counts(lines: &[Value]) -> BTreeMap<(String, String), (u64, u64)> {
    let mut m = BTreeMap::new();
    for l in lines.iter().filter(|l| l.get("kind").is_some()) {
        let key = (l["file"].as_str().unwrap().to_string(), l["kind"].as_str().unwrap().to_string());
        let e: &mut (u64, u64) = m.entry(key).or_default();
        if l["rounding"].as_bool().unwrap() {
            e.1 += 1;
        } else {
            e.0 += 1;
        }
    }
    m
}

/// Per file, the glyph ids or elements with a finding rounding does not explain, or an error:
/// the units the report draws.
fn flagged(lines: &[Value]) -> BTreeSet<(String, String)> {
    lines
        .iter()
        .filter(|l| l.get("error").is_some() || l["rounding"] == Value::Bool(false))
        .map(|l| {
            let unit = match (&l["glyph_id"], &l["element"]) {
                (Value::Number(g), _) => g.to_string(),
                (_, Value::String(e)) => e.clone(),
                (_, Value::Number(e)) => e.to_string(),
                _ => panic!("a finding without glyph or element: {l}"),
            };
            (l["file"].as_str().unwrap().to_string(), unit)
        })
        .collect()
}

fn chromium() -> Option<PathBuf> {
    let fixed = PathBuf::from("/usr/bin/chromium");
    if fixed.is_file() {
        return Some(fixed);
    }
    std::env::var_os("PATH")?.to_str()?.split(':').map(|d| Path::new(d).join("chromium")).find(|p| p.is_file())
}

/// Loads `page` in headless Chromium and returns (the DOM after load, Chromium's stderr). The
/// run is killed (its whole process group) after 60 s.
fn load(chromium: &Path, page: &Path, dir: &TempDir, name: &str) -> (String, String) {
    use std::os::unix::process::CommandExt;
    let profile = dir.join(&format!("profile-{name}"));
    std::fs::create_dir_all(&profile).unwrap();
    let out_path = dir.join(&format!("{name}.dom"));
    let err_path = dir.join(&format!("{name}.err"));
    let mut child = Command::new(chromium)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            &format!("--user-data-dir={}", profile.display()),
            "--enable-logging=stderr",
            "--v=0",
            "--virtual-time-budget=5000",
            "--dump-dom",
            &format!("file://{}", page.display()),
        ])
        .stdin(Stdio::null())
        .stdout(std::fs::File::create(&out_path).unwrap())
        .stderr(std::fs::File::create(&err_path).unwrap())
        .process_group(0)
        .spawn()
        .expect("chromium starts");
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break s;
        }
        if start.elapsed() > Duration::from_secs(60) {
            let _ = Command::new("kill").args(["-KILL", "--", &format!("-{}", child.id())]).status();
            let _ = child.wait();
            panic!("chromium did not finish loading {} within 60 s", page.display());
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    let dom = std::fs::read_to_string(&out_path).unwrap();
    let err = std::fs::read_to_string(&err_path).unwrap();
    assert!(status.success(), "chromium failed ({status}) on {}:\n{err}", page.display());
    (dom, err)
}

/// Console output and refused loads in Chromium's log: the report has no script and loads
/// nothing, and the measuring script logs nothing, so any console line is a failure (Chromium
/// logs every console message, errors and CSP violations included, as `CONSOLE`).
fn console_problems(stderr: &str) -> Vec<&str> {
    stderr
        .lines()
        .filter(|l| {
            l.contains("CONSOLE")
                || l.contains("Uncaught")
                || l.contains("Refused to")
                || l.contains("Content Security Policy")
                || l.contains("Failed to load resource")
        })
        .collect()
}

fn unescape(s: &str) -> String {
    s.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&nbsp;", "\u{a0}")
        .replace("&quot;", "\"")
        .replace("&amp;", "&")
}

/// The `#measure` JSON of a dumped DOM.
fn measure(dom: &str) -> Value {
    let start = dom.find("<pre id=\"measure\">").expect("the measuring script ran") + "<pre id=\"measure\">".len();
    let end = start + dom[start..].find("</pre>").unwrap();
    serde_json::from_str(&unescape(&dom[start..end])).expect("measure is JSON")
}

/// What the report must satisfy whatever the input: self-contained, then in the browser every
/// drawing laid out at its size, every count cell showing its count and equal to the JSON's,
/// one card with one drawing per flagged unit, no broken link, no console message.
fn check_in_browser(chromium: &Path, dir: &TempDir, name: &str, html: &str, lines: &[Value]) {
    for banned in ["<script", "http://", "https://", " src="] {
        assert!(!html.contains(banned), "{name}: the report contains {banned:?}");
    }
    assert!(html.contains(CSP), "{name}: the report carries its Content-Security-Policy");
    // the unmodified report: no console message, no refused load
    let plain = dir.join(&format!("{name}.html"));
    std::fs::write(&plain, html).unwrap();
    let (_, err) = load(chromium, &plain, dir, &format!("{name}-plain"));
    assert!(console_problems(&err).is_empty(), "{name}: console messages:\n{}", console_problems(&err).join("\n"));

    // the copy with the measuring script (the policy, which forbids scripts, taken out)
    let copy = dir.join(&format!("{name}-measured.html"));
    let measured = html.replacen(CSP, "", 1).replacen("</body>", &format!("{MEASURE}</body>"), 1);
    std::fs::write(&copy, measured).unwrap();
    let (dom, err) = load(chromium, &copy, dir, &format!("{name}-measured"));
    assert!(console_problems(&err).is_empty(), "{name}: console messages:\n{}", console_problems(&err).join("\n"));
    let m = measure(&dom);

    let expected_units = flagged(lines);
    let drawings = m["drawings"].as_array().unwrap();
    assert_eq!(m["svgs"].as_u64().unwrap() as usize, expected_units.len(), "{name}: one drawing per flagged unit");
    for d in drawings {
        let (w, h) = (d["width"].as_f64().unwrap(), d["height"].as_f64().unwrap());
        let wa: f64 = d["width_attr"].as_str().expect("an explicit width").parse().unwrap();
        let ha: f64 = d["height_attr"].as_str().expect("an explicit height").parse().unwrap();
        assert!(w > 0.0 && h > 0.0 && wa > 0.0 && ha > 0.0, "{name}: a drawing of no size: {d}");
        assert!(w + 0.5 >= wa && h + 0.5 >= ha, "{name}: a drawing laid out below its size: {d}");
    }
    let cards: BTreeSet<(String, String)> = m["cards"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            assert_eq!(c["drawings"], 1, "{name}: one drawing per card: {c}");
            let unit = c["glyph_id"].as_str().or(c["element"].as_str()).expect("a card names its glyph or element");
            (c["file"].as_str().unwrap().to_string(), unit.to_string())
        })
        .collect();
    assert_eq!(cards, expected_units, "{name}: the cards are the flagged glyphs/elements");
    assert!(m["links"].as_u64().unwrap() > 0);
    assert_eq!(m["broken"], 0, "{name}: every in-page link has its target");

    // the kind tables: each cell's text is its attribute, and the counts are the JSON's
    let mut shown: BTreeMap<(String, String), (u64, u64)> = BTreeMap::new();
    for c in m["cells"].as_array().unwrap() {
        let key = (c["file"].as_str().unwrap().to_string(), c["kind"].as_str().unwrap().to_string());
        let text = c["text"].as_str().unwrap();
        let e = shown.entry(key).or_default();
        if let Some(n) = c["count"].as_str() {
            assert_eq!(text, n, "{name}: a count cell shows its data-count: {c}");
            e.0 = n.parse().unwrap();
        } else {
            let r = c["rounding"].as_str().expect("a cell has data-count or data-rounding");
            assert_eq!(text, r, "{name}: a rounding cell shows its data-rounding: {c}");
            e.1 = r.parse().unwrap();
        }
    }
    assert_eq!(shown, counts(lines), "{name}: the kind tables count the JSON findings");
}

#[test]
fn lint_report_in_chromium() {
    let Some(chromium) = chromium() else {
        assert!(
            std::env::var_os("CI").is_none(),
            "lint report browser test: chromium not found, and CI must run it (install Debian's chromium)"
        );
        eprintln!("SKIPPED: lint report browser test: chromium not found (install Debian's chromium; .ci/run does)");
        return;
    };
    let dir = TempDir::new("lint-report");
    let font = tuffy();

    // fonts: a few flagged glyphs and one whose findings rounding explains
    let (html, lines, code) = lint(&[&font, "--glyphs", GLYPHS], &dir.join("font.html"));
    assert_eq!(code, 1, "uni1EFA's wrong direction is denied");
    let c = counts(&lines);
    for kind in
        ["direction", "overlap", "self_intersection", "overlapping_segments", "bbox", "missing_extremum", "kink"]
    {
        assert!(c.contains_key(&(font.clone(), kind.to_string())), "Tuffy's glyphs have {kind}");
    }
    let o = lines.iter().filter(|l| l["glyph"] == "O").collect::<Vec<_>>();
    assert!(!o.is_empty() && o.iter().all(|l| l["rounding"] == true), "O's findings are all explained by rounding");
    let o_id = &o[0]["glyph_id"];
    assert!(
        html.contains("<td>O</td>") && !html.contains(&format!("data-glyph-id=\"{o_id}\"")),
        "O is listed, not drawn"
    );
    check_in_browser(&chromium, &dir, "font", &html, &lines);

    // an SVG file and --path data (y down), ids that need escaping
    let svg = dir.write("shapes.svg", SHAPES);
    let (html, lines, code) =
        lint(&[svg.to_str().unwrap(), "--path", "M0 0 H10 H10 V10 Z M2 2 V8 H8 V2 Z"], &dir.join("svg.html"));
    assert_eq!(code, 1);
    assert!(html.contains("data-element=\"bow&amp;tie&lt;b&gt;\""), "the id is escaped");
    assert!(!html.contains("bow&tie<b>"));
    check_in_browser(&chromium, &dir, "svg", &html, &lines);
}

#[test]
fn lint_report_deterministic_and_all_or_nothing() {
    let dir = TempDir::new("lint-report-bytes");
    let font = tuffy();
    let args = ["lint", &font, "--glyphs", GLYPHS, "-q", "--html"];
    let (a, b) = (dir.join("a.html"), dir.join("b.html"));
    for p in [&a, &b] {
        let mut full = args.to_vec();
        full.push(p.to_str().unwrap());
        assert_eq!(run(&full, None).status.code(), Some(1));
    }
    let bytes = std::fs::read(&a).unwrap();
    assert!(bytes.len() > 10_000);
    assert_eq!(bytes, std::fs::read(&b).unwrap(), "two runs give the same bytes");

    // a report that cannot be written: exit 2, nothing written, no temporary file left
    let listing = |d: &Path| {
        let mut v: Vec<String> =
            std::fs::read_dir(d).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        v.sort();
        v
    };
    let before = listing(dir.path());
    let missing = dir.join("no/such/dir/r.html");
    let o = run(&["lint", &font, "--glyphs", GLYPHS, "-q", "--html", missing.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("cannot write"));
    assert!(!dir.join("no").exists());
    // the target is a directory: the rename fails after the temporary file was written
    let taken = dir.join("taken.html");
    std::fs::create_dir(&taken).unwrap();
    let o = run(&["lint", &font, "--glyphs", GLYPHS, "-q", "--html", taken.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(taken.is_dir() && listing(&taken).is_empty());
    let mut after = listing(dir.path());
    after.retain(|n| n != "taken.html");
    assert_eq!(after, before, "no temporary file is left behind");
}
