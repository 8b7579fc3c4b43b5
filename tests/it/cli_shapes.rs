//! `casteljau boolean` and `casteljau arrange` through the real binary: exact answers (text and
//! JSON), batches, the hard cases of issue #27, fonts glyph by glyph, `--against` verdicts,
//! `--plot`, refusals and errors (exit 2 naming what was wrong).

use crate::common::{TempDir, run, stderr, stdout};
use serde_json::Value;

const A: &str = "M0 0 H2 V2 H0 Z";
const B: &str = "M1 1 H3 V3 H1 Z";

fn data(path: &str) -> String {
    format!("{}/tests/data/{path}", env!("CARGO_MANIFEST_DIR"))
}

fn json_lines(s: &str) -> Vec<Value> {
    s.lines().map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{e}: {l}"))).collect()
}

#[test]
fn boolean_union_text_is_the_path_and_json_has_the_exact_fields() {
    let o = run(&["boolean", "union", A, B], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(stdout(&o), "M0 0L2 0L2 1L3 1L3 3L1 3L1 2L0 2Z\n");

    let o = run(&["boolean", "union", A, B, "--json"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    let keys: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
    let mut want = ["op", "fill", "contours", "path", "area", "area_float", "parents", "orientation", "pieces"];
    let mut got = keys.clone();
    got.sort_unstable();
    want.sort_unstable();
    assert_eq!(got, want);
    assert_eq!(v["op"], "union");
    assert_eq!(v["fill"], "nonzero");
    assert_eq!(v["area"], "7");
    assert_eq!(v["contours"], 1);
    assert_eq!(v["parents"], serde_json::json!([null]));
    assert_eq!(v["orientation"], serde_json::json!(["ccw"]));
    // the union's boundary: the parts of both squares outside the other
    let pieces = v["pieces"][0].as_array().unwrap();
    assert_eq!(pieces.len(), 8);
    assert_eq!(pieces[1]["to"], "1/2");
}

#[test]
fn boolean_each_operation_and_the_empty_result() {
    let area = |op: &str, extra: &[&str]| {
        let mut args = vec!["boolean", op, A, B, "--json"];
        args.extend_from_slice(extra);
        let o = run(&args, None);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let v: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
        (v["area"].as_str().unwrap().to_string(), v["contours"].as_u64().unwrap())
    };
    assert_eq!(area("intersection", &[]), ("1".into(), 1));
    assert_eq!(area("difference", &[]), ("3".into(), 1));
    assert_eq!(area("xor", &[]), ("6".into(), 2));
    // clockwise outer contours: the signed area turns negative
    assert_eq!(area("union", &["--direction", "cw"]), ("-7".into(), 1));
    // A xor A is empty: an empty line
    let o = run(&["boolean", "xor", A, A], None);
    assert_eq!((o.status.code(), stdout(&o).as_str()), (Some(0), "\n"));
    // simplify under even-odd: a square with a square hole inside it
    let o = run(&["boolean", "simplify", "M0 0 H4 V4 H0 Z M1 1 H3 V3 H1 Z", "--fill", "evenodd", "--json"], None);
    let v: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!((v["area"].as_str(), v["fill"].as_str()), (Some("12"), Some("evenodd")));
    assert_eq!(v["parents"], serde_json::json!([null, 0]));
}

#[test]
fn boolean_batch_answers_every_question_line() {
    let dir = TempDir::new("boolean-batch");
    let input = dir.write("q.txt", &format!("# two questions\n{A} ; {B}\n\n{A} ; M0 0 H1 V1 H0 Z\n"));
    let o = run(&["boolean", "intersection", "--input", input.to_str().unwrap(), "--json"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let lines = json_lines(&stdout(&o));
    assert_eq!(lines.len(), 2);
    assert_eq!((lines[0]["line"].as_u64(), lines[0]["area"].as_str()), (Some(2), Some("1")));
    assert_eq!((lines[1]["line"].as_u64(), lines[1]["area"].as_str()), (Some(4), Some("1")));
    // text: one line per answer, naming its input line
    let o = run(&["boolean", "intersection", "--input", input.to_str().unwrap()], None);
    assert_eq!(stdout(&o), "line 2: M2 1L2 2L1 2L1 1Z\nline 4: M0 0L1 0L1 1L0 1Z\n");
}

#[test]
fn boolean_hard_cases_union_answers_every_line() {
    let hard = data("boolean/hard.txt");
    let o = run(&["boolean", "union", "--input", &hard, "--json"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let lines = json_lines(&stdout(&o));
    assert_eq!(lines.len(), 35);
    for l in &lines {
        assert!(l.get("error").is_none(), "{l}");
        assert!(l["path"].is_string() && l["pieces"].is_array(), "{l}");
    }
    // identical squares: their union is the square
    let name_line =
        std::fs::read_to_string(&hard).unwrap().lines().position(|l| l.starts_with("# identical:")).unwrap();
    let identical = lines.iter().find(|l| l["line"].as_u64() == Some(name_line as u64 + 2)).unwrap();
    assert_eq!((identical["area"].as_str(), identical["contours"].as_u64()), (Some("100"), Some(1)));
}

#[test]
fn boolean_bad_path_data_names_the_token_and_exits_2() {
    let o = run(&["boolean", "union", A, "M1 1 H3 V3 H1 x"], None);
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(e.contains("\"x\"") && e.contains("column 15"), "{e}");
    // in a batch the other lines are still answered
    let dir = TempDir::new("boolean-bad");
    let input = dir.write("q.txt", &format!("{A} ; {B}\n{A} ; M0 0 L1 q\n{A} ; {A}\n"));
    let o = run(&["boolean", "union", "--input", input.to_str().unwrap(), "--json"], None);
    assert_eq!(o.status.code(), Some(2));
    let lines = json_lines(&stdout(&o));
    assert_eq!(lines.len(), 3);
    let err = lines[1]["error"].as_str().unwrap();
    assert!(err.contains("\"q\""), "{err}");
    assert_eq!(lines[2]["area"], "4");
    // the wrong number of operands, and a batch line without ';'
    assert_eq!(run(&["boolean", "union", A], None).status.code(), Some(2));
    assert_eq!(run(&["boolean", "simplify", A, B], None).status.code(), Some(2));
}

#[test]
fn boolean_max_work_refusal_exits_2_naming_the_option() {
    let o = run(&["boolean", "union", A, B, "--max-work", "10"], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--max-work"), "{}", stderr(&o));
}

#[test]
fn boolean_svg_files_are_one_shape_and_arcs_are_refused_by_name() {
    let dir = TempDir::new("boolean-svg");
    let svg = dir.write(
        "a.svg",
        r#"<svg xmlns="http://www.w3.org/2000/svg">
  <g transform="translate(1 1)"><rect width="2" height="2"/></g>
  <path d="M0 0 H2 V2 H0"/>
</svg>"#,
    );
    // the open path is closed by a line; the two squares overlap in one unit square
    let o = run(&["boolean", "simplify", svg.to_str().unwrap(), "--json"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["area"], "7");
    let arc = dir.write(
        "arc.svg",
        r#"<svg xmlns="http://www.w3.org/2000/svg"><path id="bump" d="M0 0 A1 1 0 0 1 2 0 Z"/></svg>"#,
    );
    let o = run(&["boolean", "union", svg.to_str().unwrap(), arc.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(e.contains("id=\"bump\"") && e.contains("elliptical arc"), "{e}");
}

#[test]
fn boolean_against_agrees_and_a_wrong_float_result_gets_a_witness() {
    let o = run(&["boolean", "union", A, B, "--against", "M0 0 H2 V1 H3 V3 H1 V2 H0 Z"], None);
    assert_eq!((o.status.code(), stdout(&o).as_str()), (Some(0), "agree\n"), "{}", stderr(&o));
    // a float answer that lost a corner: (2.5, 2.5) to (3, 3) cut off
    let wrong = "M0 0 H2 V1 H3 V2.5 L2.5 3 H1 V2 H0 Z";
    let o = run(&["boolean", "union", A, B, "--against", wrong, "--json"], None);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let v: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    let verdict = &v["verdict"];
    assert_eq!(verdict["agree"], false);
    let w = &verdict["witness"];
    assert_eq!((w["inside_exact"].as_bool(), w["inside_found"].as_bool()), (Some(true), Some(false)), "{verdict}");
    assert!(!verdict["problems"].as_array().unwrap().is_empty());
    // text: the problems on one line
    let o = run(&["boolean", "union", A, B, "--against", wrong], None);
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).starts_with("disagree: the point ("), "{}", stdout(&o));
}

#[test]
fn boolean_against_batches_align_result_lines_with_questions() {
    let dir = TempDir::new("boolean-against");
    let input = dir.write("q.txt", &format!("# union of A and B\n{A} ; {B}\n\n# A xor A\n{A} ; {A}\n"));
    // the second result is empty (A xor A is): an empty line
    let results = dir.write("r.txt", "# float results\nM0 0 H2 V2 H0 Z\n\n");
    let o = run(&["boolean", "xor", "--input", input.to_str().unwrap(), "--against", results.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let out = stdout(&o);
    let lines: Vec<&str> = out.lines().collect();
    assert!(lines[0].starts_with("line 2: disagree: "), "{out}");
    assert_eq!(lines[1], "line 5: agree");
    // a result file with the wrong number of lines is refused before any work
    let short = dir.write("s.txt", "M0 0 H2 V2 H0 Z\n");
    let o = run(&["boolean", "xor", "--input", input.to_str().unwrap(), "--against", short.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("1 results") && stderr(&o).contains("2 questions"), "{}", stderr(&o));
}

#[test]
fn boolean_plot_writes_an_svg_file() {
    let dir = TempDir::new("boolean-plot");
    let path = dir.join("d.svg");
    let o = run(&["boolean", "difference", "M0 0 C0 3 3 3 3 0 Z", B, "--plot", path.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let svg = std::fs::read_to_string(&path).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("fill-opacity") && svg.contains("<circle"), "{svg}");
    // one question only
    let o = run(&["boolean", "union", "--input", "-", "--plot", path.to_str().unwrap()], Some(""));
    assert_eq!(o.status.code(), Some(2));
}

fn tuffy() -> String {
    data("fonts/Tuffy.ttf")
}

#[test]
fn boolean_simplify_fonts_answers_every_glyph_in_order() {
    let d = std::fs::read(tuffy()).unwrap();
    let font = casteljau::format::Font::open(&d, 0).unwrap();
    let o = run(&["boolean", "simplify", &tuffy(), "--json", "--quiet"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let lines = json_lines(&stdout(&o));
    assert_eq!(lines.len(), font.num_glyphs() as usize);
    for (gid, l) in lines.iter().enumerate() {
        assert_eq!(l["glyph_id"].as_u64(), Some(gid as u64));
        assert!(l.get("error").is_none(), "{l}");
    }
    let by_name = |n: &str| lines.iter().find(|l| l["glyph"] == n).unwrap();
    // an overlap-free glyph comes back as itself (TrueType: clockwise outer contours)
    let o_glyph = by_name("o");
    assert_eq!((o_glyph["changed"].as_bool(), o_glyph["contours_before"].as_u64()), (Some(false), Some(2)));
    assert_eq!(o_glyph["orientation"], serde_json::json!(["cw", "ccw"]));
    // the ogonek overlaps the A: the union is one contour fewer
    let a = by_name("Aogonek");
    assert_eq!(a["changed"], true);
    assert!(a["contours"].as_u64() < a["contours_before"].as_u64(), "{a}");
    // --quiet: no summary
    assert!(stderr(&o).is_empty(), "{}", stderr(&o));
}

#[test]
fn boolean_simplify_fonts_glyphs_filter_text_and_unknown_names() {
    let o = run(&["boolean", "simplify", &tuffy(), "--glyphs", "o,A"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    let names: Vec<&str> = out.lines().map(|l| l.split_once(": ").unwrap().0).collect();
    assert_eq!(names, ["A", "o"]); // glyph order
    assert!(stderr(&o).contains("2 glyphs, 0 changed, 0 errors"), "{}", stderr(&o));
    let o = run(&["boolean", "simplify", &tuffy(), "--glyphs", "o,no-such-glyph"], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("no-such-glyph") && stdout(&o).is_empty(), "{}", stderr(&o));
    // fonts only with simplify
    assert_eq!(run(&["boolean", "union", &tuffy(), A], None).status.code(), Some(2));
}

#[test]
fn boolean_simplify_fonts_against_json_lines() {
    let dir = TempDir::new("boolean-font-against");
    let o = run(&["boolean", "simplify", &tuffy(), "--glyphs", "o,A", "--json", "--quiet"], None);
    // the exact answers as a float library's, and one glyph the library failed on
    let mut results = stdout(&o);
    results = results.lines().filter(|l| l.contains("\"glyph\":\"o\"")).collect::<Vec<_>>().join("\n");
    results += "\n{\"glyph\":\"A\",\"error\":\"panicked\"}\n";
    let against = dir.write("r.jsonl", &results);
    let o = run(
        &["boolean", "simplify", &tuffy(), "--glyphs", "o,A", "--against", against.to_str().unwrap(), "--tol", "1"],
        None,
    );
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert_eq!(stdout(&o), "A: disagree: the float library failed: panicked\no: agree\n");
}

#[test]
fn arrange_json_and_locate() {
    let sq = |x: i64| format!("M{x} 0 H{} V1 H{x} Z", x + 1);
    let (a, b) = (sq(0), sq(1));
    let o = run(&["arrange", &a, &b, "--json", "--locate", "3/2 1/2", "--locate", "1 0", "--locate", "1 1/2"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["vertices"].as_array().unwrap().len(), 6);
    assert_eq!(v["edges"].as_array().unwrap().len(), 7);
    assert_eq!(v["faces"].as_array().unwrap().len(), 3);
    let loc = v["locations"].as_array().unwrap();
    assert_eq!(loc[0]["winding"], serde_json::json!([0, 1]));
    assert_eq!(loc[0]["point"], serde_json::json!(["3/2", "1/2"]));
    assert!(loc[1]["vertex"].is_u64());
    assert_eq!(loc[2]["t"], "1/2");
    let o = run(&["arrange", &a, &b], None);
    assert_eq!(stdout(&o), "2 inputs: 6 vertices, 7 edges, 3 faces (2 bounded)\n");
    let o = run(&["arrange", &a, "--locate", "1 x"], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("\"x\""), "{}", stderr(&o));
}
