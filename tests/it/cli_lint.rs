//! `casteljau lint` through the real binary: text and JSON output, `--only`/`--ignore`/`--deny`
//! and the exit codes, SVG files and path data, a CFF2 instance, glyph order on all cores,
//! and the errors (exit 2 naming what was wrong).

use crate::common::{TempDir, run, stderr, stdout};
use serde_json::Value;

fn font(name: &str) -> String {
    format!("{}/tests/data/fonts/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn json_lines(s: &str) -> Vec<Value> {
    s.lines().map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{e}: {l}"))).collect()
}

const HOLE_WRONG: &str = "M0 0 H10 V10 H0 Z M2 2 H8 V8 H2 Z";

#[test]
fn lint_text_names_the_place_and_ends_with_a_summary() {
    let o = run(&["lint", "--path", HOLE_WRONG], None);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let text = stdout(&o);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 2, "{text}");
    assert!(
        lines[0].starts_with("<path>: path contour 1: error direction: contour 1 runs counter-clockwise"),
        "{text}"
    );
    assert_eq!(lines[1], "<path>: 1 checked, 1 flagged; 1 errors, 0 warnings, 0 info; direction 1");
}

#[test]
fn lint_json_has_the_location_and_exact_evidence() {
    let o = run(&["lint", "--json", "--path", HOLE_WRONG], None);
    assert_eq!(o.status.code(), Some(1));
    let v = json_lines(&stdout(&o));
    assert_eq!(v.len(), 1);
    let f = &v[0];
    assert_eq!(f["file"], "<path>");
    assert_eq!(f["element"], 0);
    assert_eq!(
        (f["kind"].as_str(), f["severity"].as_str(), f["rounding"].as_bool()),
        (Some("direction"), Some("error"), Some(false))
    );
    assert_eq!((f["contour"].as_u64(), f["depth"].as_u64()), (Some(1), Some(1)));
    assert_eq!(f["area"], "36");
    assert_eq!(f["expected"], "cw");
    assert_eq!(f["at"], serde_json::json!([["2", "2"]]));
    // the summary goes to stderr in JSON mode
    assert!(stderr(&o).contains("1 checked, 1 flagged"));
}

#[test]
fn lint_only_ignore_and_deny_choose_kinds_and_the_exit_code() {
    let code = |args: &[&str]| run(&[&["lint", "--path", HOLE_WRONG][..], args].concat(), None).status.code();
    assert_eq!(code(&[]), Some(1));
    assert_eq!(code(&["--ignore", "direction"]), Some(0));
    assert_eq!(code(&["--only", "kink,missing_extremum"]), Some(0));
    assert_eq!(code(&["--deny", "none"]), Some(0));
    assert_eq!(code(&["--deny", "kink"]), Some(0));
    assert_eq!(code(&["--deny", "direction"]), Some(1));
    // outer contours clockwise: now the outer square is the wrong one
    let o = run(&["lint", "--json", "--path", HOLE_WRONG, "--direction", "cw"], None);
    let v = json_lines(&stdout(&o));
    assert_eq!(v.len(), 1);
    assert_eq!(v[0]["contour"], 0);
    // rounding-explained findings never fail: a kink a half-unit handle explains
    let d = "M0 200 Q397 397 400 400 Q607 593 800 593 V0 H0 Z";
    let o = run(&["lint", "--json", "--path", d, "--deny", "kink", "--only", "kink"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    assert_eq!(json_lines(&stdout(&o))[0]["rounding"], true);
}

#[test]
fn lint_reads_svg_files_and_fonts_in_glyph_order() {
    let dir = TempDir::new("cli-lint");
    let svg = dir.write(
        "a.svg",
        r#"<svg xmlns="http://www.w3.org/2000/svg"><path id="ok" d="M0 0 H10 V10 H0 Z"/><rect id="r" x="0" y="0" width="5" height="5"/><path d="M0 0 L10 10 L10 0 L0 10 Z"/></svg>"#,
    );
    let o = run(&["lint", "--json", svg.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let v = json_lines(&stdout(&o));
    assert_eq!(v.len(), 1);
    assert_eq!((v[0]["element"].as_u64(), v[0]["kind"].as_str()), (Some(2), Some("self_intersection")));
    // a whole font: the same lines on one thread and on all cores
    let tuffy = font("Tuffy.ttf");
    let one = run(&["lint", "--json", "--threads", "1", &tuffy], None);
    let all = run(&["lint", "--json", &tuffy], None);
    assert_eq!(one.stdout, all.stdout);
    let v = json_lines(&stdout(&all));
    let ids: Vec<u64> = v.iter().map(|f| f["glyph_id"].as_u64().unwrap()).collect();
    assert!(ids.windows(2).all(|w| w[0] <= w[1]));
    assert!(v.iter().all(|f| f["file"] == tuffy.as_str() && f.get("glyph").is_some()));
    // --glyphs picks glyphs by name
    let o = run(&["lint", "--json", "--glyphs", "u1091C", &tuffy], None);
    assert!(json_lines(&stdout(&o)).iter().all(|f| f["glyph"] == "u1091C"));
}

#[test]
fn lint_cff2_instances_and_cff_fonts() {
    let vf = font("cantarell_vf_trimmed.ttf");
    for extra in [&[][..], &["--variation", "wght=700"][..]] {
        let o = run(&[&["lint", "--json", &vf][..], extra].concat(), None);
        assert_ne!(o.status.code(), Some(2), "{}", stderr(&o));
        let v = json_lines(&stdout(&o));
        assert!(v.iter().any(|f| f["kind"] == "self_intersection"));
    }
    let o = run(&["lint", "--json", &font("NotoSansJP-Regular.subset.otf")], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

#[test]
fn lint_refuses_bad_input_with_exit_2() {
    let dir = TempDir::new("cli-lint-bad");
    let junk = dir.write("junk.ttf", "not a font");
    for (args, needle) in [
        (vec!["lint"], "FILE arguments or --path"),
        (vec!["lint", junk.to_str().unwrap()], "junk.ttf"),
        (vec!["lint", "--path", "M0 0 L1 x Z"], "x"),
        (vec!["lint", "--path", "M0 0 H1 V1 Z", "--only", "kinky"], "unknown lint kind \"kinky\""),
        (vec!["lint", "--path", "M0 0 H1 V1 Z", "--deny", "kinky"], "unknown lint kind \"kinky\""),
        (vec!["lint", "--path", "M0 0 H1 V1 Z", "--kink-angle", "90"], "kink angle"),
        (vec!["lint", "--path", "M0 0 H1 V1 Z", "--extremum-min", "1/0"], "--extremum-min"),
        (vec!["lint", &font("Tuffy.ttf"), "--glyphs", "nosuchglyph"], "nosuchglyph"),
        (vec!["lint", &font("Tuffy.ttf"), "--variation", "wght=700"], "variation"),
        (vec!["lint", "/nonexistent/a.ttf"], "cannot read"),
    ] {
        let o = run(&args, None);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        let said = format!("{}{}", stderr(&o), stdout(&o));
        assert!(said.contains(needle), "{args:?}: {said}");
    }
    // a glyph whose arrangement is over the budget is an error line, the others still answered
    let o = run(&["lint", "--json", "--path", "M0 0 C10 20 -10 20 0 5 L3 -4 Z", "--max-work", "1"], None);
    assert_eq!(o.status.code(), Some(2));
    let v = json_lines(&stdout(&o));
    assert!(v[0]["error"].as_str().unwrap().contains("--max-work"), "{v:?}");
}

fn lint_font_json(data: &[u8], extra: &[&str]) -> (Option<i32>, Vec<Value>) {
    let dir = TempDir::new("cli-lint-font");
    let path = dir.join("f.ttf");
    std::fs::write(&path, data).unwrap();
    let o = run(&[&["lint", "--json", path.to_str().unwrap()][..], extra].concat(), None);
    (o.status.code(), json_lines(&stdout(&o)))
}

#[test]
fn lint_one_point_off_curve_contour_draws_nothing() {
    // a contour of one point draws nothing, whether the point is on or off the curve: no
    // zero-length segment, and the point stays out of the head box check of the outline
    use crate::font_builder::{TtGlyph, off, on, truetype_with_head_bbox};
    let square = vec![on(100, 100), on(100, 500), on(500, 500), on(500, 100)];
    let glyphs = [
        TtGlyph::new("anchor_on", vec![vec![on(50, 50)], square.clone()]),
        TtGlyph::new("anchor_off", vec![vec![off(50, 50)], square.clone()]),
        TtGlyph::new("anchor_off_only", vec![vec![off(50, 50)]]),
    ];
    let (code, v) = lint_font_json(&truetype_with_head_bbox(&glyphs, Some([50, 50, 500, 500])), &[]);
    assert_eq!(code, Some(0), "{v:?}");
    assert!(v.is_empty(), "{v:?}");
    let (_, v) = lint_font_json(&truetype_with_head_bbox(&glyphs, Some([100, 100, 500, 500])), &["--only", "bbox"]);
    assert!(v.is_empty(), "{v:?}");
}

#[test]
fn lint_svg_strokes_enclose_nothing_and_conics_are_listed_as_skipped() {
    let dir = TempDir::new("cli-lint-svg-skip");
    let svg = dir.write(
        "s.svg",
        r#"<svg xmlns="http://www.w3.org/2000/svg"><circle cx="5" cy="5" r="3"/><line x1="0" y1="0" x2="10" y2="0"/><path d="M0 0 L100 0 L50 0"/><polyline points="0 0 10 0 10 10"/></svg>"#,
    );
    let o = run(&["lint", "--json", svg.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    let v = json_lines(&stdout(&o));
    // the circle is listed as skipped; the line and the open path on one line draw no fill, so
    // their retraced fill outline is no overlapping_segments; the polyline's fill is a triangle
    assert_eq!(v.len(), 1, "{v:?}");
    assert_eq!((v[0]["tag"].as_str(), v[0]["skipped"].is_string()), (Some("circle"), true));
    assert!(stderr(&o).contains("3 checked") && stderr(&o).contains("1 skipped"), "{}", stderr(&o));
    // closed, the same path is a contour drawn twice over its piece from (50, 0) to (100, 0)
    let o = run(&["lint", "--json", "--path", "M0 0 L100 0 L50 0 Z"], None);
    assert!(json_lines(&stdout(&o)).iter().any(|f| f["kind"] == "overlapping_segments"));
}
