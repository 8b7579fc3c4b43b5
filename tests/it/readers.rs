//! The readers through the real binary (issue 34): composite bombs refused before they are
//! composed, glyph names of fonts that store none, path data and SVG documents read in time
//! linear in their size, SVG's rendering tree (`<use>`, `<defs>`, …), and refusals that say
//! where. Bounded by the budget and the readers' limits, not by timed assertions.

use crate::common::{TempDir, run, stderr, stdout};
use crate::font_builder::{TtComposite, TtGlyph, composite_bomb, truetype_composites, tt_square};

fn json_lines(text: &str) -> Vec<serde_json::Value> {
    text.lines().map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{e}: {l}"))).collect()
}

/// The exit code, asserting the process was not killed and printed no panic.
fn code(o: &std::process::Output) -> i32 {
    assert!(!stderr(o).contains("panicked") && !stderr(o).contains("memory allocation"), "{}", stderr(o));
    o.status.code().expect("killed by a signal")
}

#[test]
fn readers_composite_fan_out_is_refused_before_composing_naming_the_glyph() {
    let dir = TempDir::new("readers-bomb");
    let font = dir.join("bomb.ttf");
    std::fs::write(&font, composite_bomb(16)).unwrap();
    let f = font.to_str().unwrap();
    // 65,536 squares: refused at once in lint, scan and boolean, the other glyphs answered
    let o = run(&["lint", "--json", f, "--glyphs", "square,bomb15,bomb16"], None);
    assert_eq!(code(&o), 2, "{}", stderr(&o));
    let lines = json_lines(&stdout(&o));
    let error =
        |name: &str| lines.iter().find(|l| l["glyph"] == name && l.get("error").is_some()).map(|l| l["error"].clone());
    let e = error("bomb16").expect("bomb16 refused").to_string();
    assert!(e.contains("glyph 17 (bomb16)") && e.contains("100000") && e.contains("before composing"), "{e}");
    // 2^15 squares: 131,072 points
    assert!(error("bomb15").is_some());
    assert!(error("square").is_none());
    let o = run(&["scan", "-q", f], None);
    assert_eq!(code(&o), 2);
    let lines = json_lines(&stdout(&o));
    let e = lines.iter().find(|l| l["glyph"] == "bomb15").unwrap();
    assert!(e["error"].as_str().unwrap().contains("more than 100000 points"), "{e}");
    assert!(lines.iter().any(|l| l["glyph"] == "square" && l["index"] == 3));
    // 2^14 squares (65,536 points, 32,766 references) are read
    assert_eq!(lines.iter().filter(|l| l["glyph"] == "bomb14").count(), 65_536);
    let o = run(&["boolean", "simplify", "--json", f, "--glyphs", "bomb16,square"], None);
    assert_eq!(code(&o), 2);
    let lines = json_lines(&stdout(&o));
    assert!(lines[0]["glyph"] == "square" && lines[0]["changed"] == false);
    assert!(lines[1]["error"].as_str().unwrap().contains("more than 100000"), "{}", lines[1]);
}

#[test]
fn readers_composite_of_1024_copies_is_answered() {
    let dir = TempDir::new("readers-bomb10");
    let font = dir.join("bomb.ttf");
    std::fs::write(&font, composite_bomb(10)).unwrap();
    // read, and linted or refused by the arrangement's estimate (naming the budget), never an abort
    let o = run(&["lint", "--json", font.to_str().unwrap(), "--glyphs", "bomb10"], None);
    match code(&o) {
        0 => {}
        2 => assert!(stdout(&o).contains("the arrangement of 4096 segments") && stdout(&o).contains("--max-work")),
        c => panic!("exit {c}: {}{}", stdout(&o), stderr(&o)),
    }
    let o = run(&["scan", "-q", font.to_str().unwrap()], None);
    assert_eq!(code(&o), 0);
    let lines = stdout(&o);
    assert_eq!(lines.lines().filter(|l| l.contains("\"glyph\":\"bomb10\"")).count(), 4096);
}

#[test]
fn readers_composite_cycles_are_refused_naming_the_glyph() {
    let dir = TempDir::new("readers-cycle");
    let font = dir.join("cycle.ttf");
    let square = TtGlyph::new("square", vec![tt_square(0, 0, 10, 10)]);
    // glyph 2 uses glyph 3, which uses glyph 2
    let composites = [
        TtComposite { name: "ping".into(), components: vec![(3, 0, 0)] },
        TtComposite { name: "pong".into(), components: vec![(2, 5, 0), (1, 0, 0)] },
    ];
    std::fs::write(&font, truetype_composites(&[square], &composites, true, &[])).unwrap();
    let o = run(&["scan", "-q", font.to_str().unwrap()], None);
    assert_eq!(code(&o), 2);
    let lines = json_lines(&stdout(&o));
    let e = lines.iter().find(|l| l["glyph"] == "ping").unwrap()["error"].as_str().unwrap().to_string();
    assert!(e.contains("glyph 2 (ping)") && e.contains("cycle"), "{e}");
}

#[test]
fn readers_fonts_without_names_are_named_as_fonttools_derives_them() {
    let dir = TempDir::new("readers-names");
    let font = dir.join("unnamed.ttf");
    let sq = |n: &str| TtGlyph::new(n, vec![tt_square(0, 0, 10, 10)]);
    let glyphs = [sq("a"), sq("b"), sq("c"), sq("d"), sq("e")];
    // glyph 1: U+0041 and U+0391 (the smaller wins); 2: beyond the BMP; 3: not mapped;
    // 4 and 5: the same smallest code point through two subtables is impossible, so 5 is
    // mapped alone to U+0042 and 4 to nothing
    let cmap = [('A', 1), ('Α', 1), ('😀', 2), ('B', 5)];
    std::fs::write(&font, truetype_composites(&glyphs, &[], false, &cmap)).unwrap();
    let f = font.to_str().unwrap();
    let o = run(&["scan", "-q", f], None);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let mut names: Vec<(u64, String)> = json_lines(&stdout(&o))
        .iter()
        .map(|l| (l["glyph_id"].as_u64().unwrap(), l["glyph"].as_str().unwrap().to_string()))
        .collect();
    names.dedup();
    let expected = [(1, "uni0041"), (2, "u1F600"), (3, "glyph00003"), (4, "glyph00004"), (5, "uni0042")];
    assert_eq!(names, expected.map(|(g, n)| (g, n.to_string())));
    // lint, boolean and the reports alike
    let o = run(&["lint", "--json", "--direction", "ccw", f], None);
    let lines = json_lines(&stdout(&o));
    assert!(lines.iter().any(|l| l["glyph"] == "u1F600" && l["kind"] == "direction"), "{}", stdout(&o));
    let o = run(&["boolean", "simplify", "--json", f, "--glyphs", "uni0041,glyph00003"], None);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let lines = json_lines(&stdout(&o));
    assert_eq!(lines[0]["glyph"], "uni0041");
    assert_eq!(lines[1]["glyph"], "glyph00003");
    let html = dir.join("r.html");
    let o = run(&["lint", "-q", "--direction", "ccw", f, "--html", html.to_str().unwrap()], None);
    assert_eq!(code(&o), 1);
    assert!(std::fs::read_to_string(&html).unwrap().contains("uni0041"));
}

/// An SVG document of `body`.
fn svg(body: &str) -> String {
    format!("<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\">{body}</svg>")
}

fn nested(depth: usize, transform: &str) -> String {
    svg(&format!(
        "{}<path d=\"M0 0 H10 V10 H0 Z\"/>{}",
        format!("<g transform=\"{transform}\">").repeat(depth),
        "</g>".repeat(depth)
    ))
}

#[test]
fn readers_deeply_nested_transforms_are_charged_to_the_budget() {
    let dir = TempDir::new("readers-nested");
    for depth in [1000, 3000] {
        let file = dir.write(&format!("n{depth}.svg"), &nested(depth, "scale(1.0001)"));
        let f = file.to_str().unwrap();
        for args in [
            vec!["lint", f, "--max-work", "1"],
            vec!["boolean", "simplify", f, "--max-work", "1"],
            vec!["arrange", f, "--max-work", "1"],
            vec!["scan", "-q", f, "--max-work", "1"],
        ] {
            let o = run(&args, None);
            assert_eq!(code(&o), 2, "{args:?}");
            let e = stderr(&o);
            assert!(e.contains("--max-work") && e.contains("line 1: <g>"), "{args:?}: {e}");
        }
        // within the default budget the reading is cheap: the numbers of 3,000 levels have
        // about 80,000 bits, composed once per level
        let o = run(&["scan", "-q", f], None);
        assert_eq!(code(&o), 0, "{}", stderr(&o));
        assert_eq!(stdout(&o).lines().count(), 4);
    }
    // a chain whose exact products pass the default budget is refused with an estimate that
    // admits it
    let file = dir.write("matrix.svg", &nested(2000, "matrix(1.0001 0.0003 -0.0007 0.9999 1.5 2.25)"));
    let o = run(&["scan", "-q", file.to_str().unwrap(), "--max-work", "1e8"], None);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("raise it with --max-work"), "{}", stderr(&o));
}

#[test]
fn readers_long_path_data_is_read_in_linear_time_and_refused_past_the_limit() {
    let dir = TempDir::new("readers-long");
    let d = |n: usize| format!("M0 0 {}", "L1 1 L2 0 ".repeat(n / 2));
    let over = dir.write("over.svg", &svg(&format!("<path d=\"{} L3 3\"/>", d(100_000))));
    for args in [vec!["lint", over.to_str().unwrap()], vec!["scan", "-q", over.to_str().unwrap()]] {
        let o = run(&args, None);
        assert_eq!(code(&o), 2);
        let out = stdout(&o);
        assert!(out.contains("subpath 0: segments in a subpath 100001 exceeds the limit 100000"), "{out}");
        assert!(out.contains("column"), "{out}");
    }
    // 400,000 segments in 4 subpaths: read (each subpath within the limit)
    let many: String = (0..4).map(|_| d(100_000)).collect::<Vec<_>>().join(" ");
    let file = dir.write("many.svg", &svg(&format!("<path d=\"{many}\"/>")));
    let o = run(&["scan", "-q", "--only", "error", file.to_str().unwrap()], None);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    // 400,000 segments through --against: refused at the limit, as the subpath passes it
    let against = dir.write("against.txt", &format!("{}\n", d(400_000)));
    let o = run(&["boolean", "simplify", "M0 0 H1 V1 Z", "--against", against.to_str().unwrap()], None);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("--against") && stderr(&o).contains("exceeds the limit 100000"), "{}", stderr(&o));
}

#[test]
fn readers_svg_of_20000_squares_is_read_in_linear_time() {
    let dir = TempDir::new("readers-squares");
    let body: String = (0..20_000)
        .map(|i| format!("<rect x=\"{}\" y=\"{}\" width=\"5\" height=\"5\"/>\n", 10 * (i % 150), 10 * (i / 150)))
        .collect();
    let file = dir.write("squares.svg", &svg(&body));
    let o = run(&["scan", file.to_str().unwrap(), "--only", "error"], None);
    assert_eq!(code(&o), 0);
    assert!(stderr(&o).starts_with(&format!("{}: 80000 segments", file.display())), "{}", stderr(&o));
}

#[test]
fn readers_svg_use_draws_copies_and_defs_draw_nothing() {
    let dir = TempDir::new("readers-use");
    let doc = svg(r##"
  <defs><path id="tri" d="M0 0 H4 V4 Z"/><rect id="hidden" width="100" height="100"/></defs>
  <symbol id="sym"><rect width="2" height="2"/></symbol>
  <clipPath id="clip"><rect width="50" height="50"/></clipPath>
  <use xlink:href="#tri" x="10" y="20"/>
  <g transform="scale(2)"><use href="#sym" transform="translate(1 0)"/></g>
  <rect width="1" height="1" display="none"/>
  <rect width="1" height="1" style="fill: red; display : none"/>
"##);
    let file = dir.write("use.svg", &doc);
    let o = run(&["scan", "-q", file.to_str().unwrap()], None);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let lines = json_lines(&stdout(&o));
    // the triangle at (10, 20), the symbol's square scaled by 2 after moving by 1: nothing else
    assert_eq!(lines.len(), 3 + 4);
    assert_eq!(lines[0]["element"], 0);
    assert_eq!(lines[0]["points"], serde_json::json!([["10", "20"], ["14", "20"]]));
    assert_eq!(lines[3]["tag"], "rect");
    assert_eq!(lines[3]["points"][0], serde_json::json!(["2", "0"]));
    assert_eq!(lines[4]["points"][1], serde_json::json!(["6", "4"]));
    // the same as one shape
    let o = run(&["boolean", "--json", "simplify", file.to_str().unwrap()], None);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert_eq!(json_lines(&stdout(&o))[0]["area"], "24"); // 8 + 16
}

#[test]
fn readers_svg_use_that_cannot_be_followed_is_named() {
    let dir = TempDir::new("readers-use-bad");
    for (body, needle) in [
        (r##"<g id="a"><use href="#a"/></g>"##, "a cycle"),
        (r##"<use href="#nosuch"/>"##, "no element has id"),
        (r##"<use href="other.svg#x"/>"##, "outside the document"),
        (r##"<symbol id="s" viewBox="0 0 1 1"><path d="M0 0 H1 V1 Z"/></symbol><use href="#s"/>"##, "viewBox"),
    ] {
        let file = dir.write("bad.svg", &svg(&format!("<path d=\"M0 0 H1 V1 Z\"/>{body}")));
        let o = run(&["scan", "-q", file.to_str().unwrap()], None);
        assert!(stdout(&o).contains(needle), "{body}: {}", stdout(&o));
        let o = run(&["boolean", "simplify", file.to_str().unwrap()], None);
        assert_eq!(code(&o), 2, "{body}: {}", stdout(&o));
        assert!(stderr(&o).contains("line 1: <"), "{body}: {}", stderr(&o));
    }
    // copies of copies: bounded by the budget (each copy charged) and by the segments drawn
    let mut body = String::from("<path id=\"l0\" d=\"M0 0 H1 V1 Z\"/>");
    for k in 1..=12 {
        let uses: String = (0..10).map(|_| format!("<use href=\"#l{}\"/>", k - 1)).collect();
        body.push_str(&format!("<g id=\"l{k}\">{uses}</g>"));
    }
    let file = dir.write("laughs.svg", &svg(&body));
    for args in [vec!["scan", "-q"], vec!["lint", "-q"], vec!["scan", "-q", "--max-work", "1e6"]] {
        let o = run(&[&args[..], &[file.to_str().unwrap()]].concat(), None);
        assert_eq!(code(&o), 2, "{args:?}");
        let e = stderr(&o);
        assert!(e.contains("<use>") || e.contains("--max-work"), "{args:?}: {e}");
    }
}

#[test]
fn readers_lint_with_nothing_checked_is_not_a_pass() {
    let dir = TempDir::new("readers-nothing");
    let file = dir.write("rot.svg", &svg(r#"<circle r="5" transform="rotate(45)"/>"#));
    let o = run(&["lint", file.to_str().unwrap()], None);
    assert_eq!(code(&o), 2);
    assert!(stdout(&o).contains("0 checked") && stdout(&o).contains("1 skipped"), "{}", stdout(&o));
    assert!(stderr(&o).contains("nothing was checked"), "{}", stderr(&o));
    let empty = dir.write("empty.svg", &svg(r##"<defs><path d="M0 0 H1 V1 Z"/></defs>"##));
    let o = run(&["lint", empty.to_str().unwrap()], None);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("nothing was checked"), "{}", stderr(&o));
}

#[test]
fn readers_refusals_name_where() {
    // an arc in path data names its column, and the operand or subpath it is in
    let o = run(&["boolean", "union", "M0 0 H1 V1 Z", "M0 0 A1 1 0 0 1 2 2 Z"], None);
    assert_eq!(code(&o), 2);
    let e = stderr(&o);
    assert!(e.contains("B: subpath 0: elliptical arc at column 6"), "{e}");
    let o = run(&["lint", "--path", "M0 0 L5 5 A1 1 0 0 1 2 2 Z"], None);
    assert!(stdout(&o).contains("column 11"), "{}", stdout(&o));
    // which curve of two, which line of a batch
    let o = run(&["intersect", "0 0, 1 1", ""], None);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("curve B"), "{}", stderr(&o));
    let big: String = (0..10_002).map(|i| format!("{i} 0")).collect::<Vec<_>>().join(", ");
    let o = run(&["intersect", "--input", "-"], Some(&format!("0 0, 1 1 ; {big}\n")));
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("line 1: curve B: degree 10001 exceeds the limit 10000"), "{}", stderr(&o));
    let o = run(&["eval", "--t", "1/2", ""], None);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("the curve argument"), "{}", stderr(&o));
}
