//! The `casteljau` binary: answers, exit codes (0 ok, 1 check failed, 2 bad input), errors.

use crate::common::{run, stderr, stdout};

#[test]
fn cli_subdivide_seed_001_example_prints_both_polygons() {
    let o = run(&["subdivide", "--t", "1/3", "-1 -1, -1/3 1, 1/3 -1, 1 1"], None);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(
        stdout(&o),
        "left:  -1 -1, -7/9 -1/3, -5/9 -1/9, -1/3 -1/27\nright: -1/3 -1/27, 1/9 1/9, 5/9 -1/3, 1 1\n"
    );
}

#[test]
fn cli_subdivide_json_uses_exact_strings() {
    let o = run(&["subdivide", "--json", "--t", "1/3", "-1 -1, -1/3 1, 1/3 -1, 1 1"], None);
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["left"][1], serde_json::json!(["-7/9", "-1/3"]));
    assert_eq!(v["right"][0], serde_json::json!(["-1/3", "-1/27"]));
}

#[test]
fn cli_subdivide_depth_gives_pieces_with_intervals() {
    let o = run(&["subdivide", "--t", "1/2", "--depth", "4", "--json", "-1 -1, -1/3 1, 1/3 -1, 1 1"], None);
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["pieces"].as_array().unwrap().len(), 16);
    assert_eq!(v["pieces"][15]["interval"], serde_json::json!(["15/16", "1"]));
    assert_eq!(run(&["subdivide", "--depth", "99", "0 0, 1 1"], None).status.code(), Some(2));
}

#[test]
fn cli_eval_power_elevate_triangle_derivative_reduce() {
    let o = run(&["eval", "--t", "1/10", "--t", "1", "0 1, 1 3, 2 4, 4 2"], None);
    assert_eq!(stdout(&o), "b(1/10) = (301/1000, 196/125)\nb(1) = (4, 2)\n");
    let o = run(&["power", "0 1, 4 2, 2 4, 1 0"], None);
    assert_eq!(stdout(&o), "x(t) = 12t - 18t^2 + 7t^3\ny(t) = 1 + 3t + 3t^2 - 7t^3\n");
    let o = run(&["elevate", "0 0, 1 1, 2 0"], None);
    assert_eq!(stdout(&o), "0 0, 2/3 2/3, 4/3 2/3, 2 0\n");
    let o = run(&["triangle", "--t", "1/2", "0 0, 1 2, 2 0"], None);
    assert_eq!(stdout(&o), "r=0: (0, 0) (1, 2) (2, 0)\nr=1: (1/2, 1) (3/2, 1)\nr=2: (1, 1)\n");
    let o = run(&["derivative", "0 0, 1 2, 2 0"], None);
    assert_eq!(stdout(&o), "2 4, 2 -4\n");
    let o = run(&["reduce", "0 0, 2/3 2/3, 4/3 2/3, 2 0"], None);
    assert_eq!(stdout(&o), "degree 2 (written as 3): 0 0, 1 1, 2 0\n");
    let o = run(&["eval", "--dim", "3", "--t", "1/2", "0 0 0, 2 2 2"], None);
    assert_eq!(stdout(&o), "b(1/2) = (1, 1, 1)\n");
}

#[test]
fn cli_bad_numbers_exit_2_naming_token_and_position() {
    for (curve, token) in [
        ("0 0, 1 nan", "nan"),
        ("0 0, inf 1", "inf"),
        ("0 0, 1/0 1", "1/0"),
        ("0 0, 1//2 1", "1//2"),
        ("0 0, 0x10 1", "0x10"),
        ("0 0, 1e5000 1", "1e5000"),
        ("0 0, 1 1/-2", "1/-2"),
    ] {
        let o = run(&["eval", "--t", "1/2", curve], None);
        assert_eq!(o.status.code(), Some(2), "{curve}");
        let e = stderr(&o);
        assert!(e.contains(&format!("{token:?}")) && e.contains("column"), "{curve}: {e}");
        assert!(!e.contains("panicked"), "{e}");
    }
    let long = format!("0 0, 1 {}", "1".repeat(5000));
    let o = run(&["eval", "--t", "1/2", &long], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("longer than 1000"));
    let o = run(&["eval", "--t", "1/2", "0 0,, 1 1"], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("empty number"));
}

#[test]
fn cli_wrong_point_counts_and_bad_options_exit_2() {
    let o = run(&["eval", "--t", "1/2", "0 0, 1 1 1"], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("point 2 has 3 coordinates, expected 2"), "{}", stderr(&o));
    let o = run(&["eval", "--t", "1/2", "0 0 1"], None);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(run(&["eval", "--t", "one", "0 0, 1 1"], None).status.code(), Some(2));
    assert_eq!(run(&["eval", "--t", "1/2", "--dim", "0", "0 0"], None).status.code(), Some(2));
    assert_eq!(run(&["elevate", "--by", "20000", "0 0, 1 1"], None).status.code(), Some(2));
    assert_eq!(run(&["frobnicate"], None).status.code(), Some(2));
    let big: Vec<String> = (0..=600).map(|i| format!("{i} {}", i % 7)).collect();
    let o = run(&["triangle", "--t", "1/2", &big.join(", ")], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("triangle of degree 600 exceeds the limit 500"));
    assert_eq!(run(&["eval", "--t", "1/2", "--input", "/nonexistent/file"], None).status.code(), Some(2));
    assert_eq!(run(&["eval", "--t", "1/2", ""], None).status.code(), Some(2));
}

#[test]
fn cli_batch_answers_every_line_in_order_and_exits_2_on_a_bad_one() {
    let input = "# curves\n0 0 1 1 2 0\n\n0,0,2,2\n1 2 3\n0 0, 1 x\n4 4 5 5\n";
    let o = run(&["eval", "--t", "1/2", "--json"], Some(input));
    assert_eq!(o.status.code(), Some(2));
    let lines: Vec<serde_json::Value> = stdout(&o).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines.len(), 5);
    assert_eq!(lines[0]["line"], 2);
    assert_eq!(lines[0]["values"][0]["point"], serde_json::json!(["1", "1/2"]));
    assert_eq!(lines[1]["line"], 4);
    assert_eq!(lines[2]["line"], 5);
    assert!(lines[2]["error"].as_str().unwrap().contains("3 numbers"));
    assert!(lines[3]["error"].as_str().unwrap().contains("line 6, column 8 (number 4)"));
    assert_eq!(lines[4]["values"][0]["point"], serde_json::json!(["9/2", "9/2"]));
    // text mode: answers on stdout, errors on stderr
    let o = run(&["eval", "--t", "1/2", "--input", "-"], Some(input));
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(stdout(&o).lines().count(), 3);
    assert!(stdout(&o).lines().all(|l| l.starts_with("line ")), "{}", stdout(&o));
    assert!(stderr(&o).contains("line 5"));
}

#[test]
fn cli_prove_checks_the_catalogue_with_json_junit_and_exit_codes() {
    let o = run(&["prove", "--filter", "003-"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    let out = stdout(&o);
    assert!(out.lines().last().unwrap().ends_with("passed, 0 failed"));
    assert!(out.contains("003-trinomial-5") && out.contains("fails-as-printed"));
    let tmp = crate::common::TempDir::new("prove");
    let junit = tmp.join("junit.xml");
    let o = run(&["prove", "--filter", "trinomial", "--json", "--junit", junit.to_str().unwrap()], None);
    let lines: Vec<serde_json::Value> = stdout(&o).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines.len(), 4);
    assert!(lines.iter().all(|v| v["passed"] == true));
    assert!(std::fs::read_to_string(&junit).unwrap().contains("tests=\"4\" failures=\"0\""));
    // a claim file with a wrong expected verdict: exit 1; a malformed one: exit 2 naming file:line
    let dir = tmp.join("claims");
    std::fs::create_dir_all(&dir).unwrap();
    let wrong = dir.join("wrong.toml");
    std::fs::write(&wrong, "seed = \"x\"\n[[claim]]\nid = \"w\"\nsource = \"s\"\nstatement = \"1 = 2\"\nexpect = \"holds\"\nkind = \"identity\"\nlhs = \"1\"\nrhs = \"2\"\n").unwrap();
    let o = run(&["prove", wrong.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).contains("FAIL w"));
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "seed = \"x\"\n[[claim]]\nid = \"b\"\nsource = \"s\"\nstatement = \"?\"\nexpect = \"holds\"\nkind = \"identity\"\nlhs = \"(1\"\nrhs = \"2\"\n").unwrap();
    let o = run(&["prove", bad.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("bad.toml:3: claim b"), "{}", stderr(&o));
    assert_eq!(run(&["prove", "/nonexistent/proofs"], None).status.code(), Some(2));
}

#[test]
fn cli_help_documents_exit_codes() {
    let o = run(&["--help"], None);
    assert!(stdout(&o).contains("EXIT CODES"));
}

#[test]
fn cli_classify_json_schema_and_batch_order() {
    let input = "0 0 2 2 -1 2 1 0\n0 0 1 1 0 1 1 0\n0 0 1 1 x 1 1 0\n0 0 1 2 2 -1 3 1\n0 0 1 1 2 2 3 3\n0 0 1 2 2 0\n";
    let o = run(&["classify", "--json", "--detail", "full"], Some(input));
    assert_eq!(o.status.code(), Some(2));
    let v: Vec<serde_json::Value> = stdout(&o).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(v.len(), 6);
    assert_eq!(v[0]["node_type"], "crunode");
    assert_eq!(v[0]["real_degree"], 3);
    assert_eq!(v[0]["collinear"], false);
    assert_eq!(v[0]["double_point"], serde_json::json!(["1/2", "3/5"]));
    assert_eq!(v[0]["segment"], serde_json::json!({"loop": true, "cusp": false, "inflections": 0, "category": "loop"}));
    assert_eq!(v[0]["canonical"]["proved"], true);
    assert_eq!(v[0]["moving_lines"]["verified"], true);
    assert_eq!(v[1]["node_type"], "cusp");
    assert_eq!(v[1]["double_point"], serde_json::json!(["1/2", "3/4"]));
    assert_eq!(v[1]["segment"]["cusp"], true);
    assert_eq!(v[2]["line"], 3);
    assert!(v[2]["error"].as_str().unwrap().contains("\"x\""));
    assert_eq!(v[3]["node_type"], "explicit");
    assert_eq!(v[3]["double_point"], serde_json::Value::Null);
    assert_eq!(v[3]["segment"]["inflections"], 1);
    assert_eq!(v[4]["node_type"], serde_json::Value::Null);
    assert_eq!(v[4]["real_degree"], 1);
    assert_eq!(v[4]["collinear"], true);
    assert_eq!(v[5]["class"], "quadratic");
    assert_eq!(v[5]["real_degree"], 2);
}

#[test]
fn cli_classify_text_and_float() {
    let o = run(&["classify", "--float", "0 0, 2 2, -1 2, 1 0"], None);
    assert_eq!(o.status.code(), Some(0));
    let out = stdout(&o);
    assert!(out.starts_with("crunode: "), "{out}");
    assert!(out.contains("1/2 - 1/10*sqrt(15) (≈0.112702)"), "{out}");
    let o = run(&["classify", "0 0, 1 1, 2 0, 3 1, 4 0"], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("degree to classify 4 exceeds the limit 3"));
}

#[test]
fn cli_classify_rational_cubics() {
    // seed 000 example 2: the folium, node at the origin at t = 0 and t = ∞
    let o = run(&["classify", "--json", "--weights", "1 1 1 2", "0 0, 1 0, 2 1, 3/2 3/2"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["node_type"], "crunode");
    assert_eq!(v["double_point"], serde_json::json!(["0", "0"]));
    assert_eq!(v["parameter_at_infinity"], true);
    // homogeneous input with a point at infinity: the explicit cubic is a cusp at infinity
    let o = run(&["classify", "--json", "--homogeneous", "0 0 1, 1 2 1, 2 -1 1, 3 1 1"], None);
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["node_type"], "cusp");
    assert_eq!(v["double_point_at_infinity"], true);
    assert_eq!(v["double_point"], serde_json::Value::Null);
    // wrong weight count, zero weight: exit 2 with a clear message
    let o = run(&["classify", "--weights", "1 1 1", "0 0, 1 0, 2 1, 3/2 3/2"], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("3 weights for 4 control points"));
    let o = run(&["classify", "--weights", "1 0 1 1", "0 0, 1 0, 2 1, 3/2 3/2"], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("weight 2 is 0"), "{}", stderr(&o));
    let o = run(&["classify", "--weights", "1 x 1 1", "0 0, 1 0, 2 1, 3/2 3/2"], None);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn cli_rational_curves_eval_implicit_conic_subdivide_elevate() {
    let folium = "0 0, 1 0, 2 1, 3/2 3/2";
    let o = run(&["eval", "--weights", "1 1 1 2", "--t", "1/3", folium], None);
    assert_eq!(stdout(&o), "x(1/3) = (27/28, 9/28)\n");
    let o = run(&["implicit", "--weights", "1 1 1 2", "--poly", "x^3 - 3*x*y + y^3", folium], None);
    assert_eq!(o.status.code(), Some(0));
    assert!(stdout(&o).starts_with("proved"));
    let o = run(&["implicit", "--json", "--weights", "1 1 1 2", "--poly", "x^3 - 2*x*y + y^3", folium], None);
    assert_eq!(o.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["proved"], false);
    assert_eq!(v["value"], "9/4");
    // seed 000 example 5 at s = π: the semicircle through the point at infinity
    let o = run(&["implicit", "--homogeneous", "--poly", "x^2 + y^2 - 1", "1 0 1, 0 1 0, -1 0 1"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let o = run(&["conic", "--json", "--weights", "1 5/4 1", "1 0, 1 3/5, 17/8 15/8"], None);
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["conic"], "hyperbola");
    assert_eq!(v["shape_factor"], "25/16");
    let o = run(&["subdivide", "--weights", "1 1 1 2", "--t", "1/2", folium], None);
    assert_eq!(
        stdout(&o),
        "left:  0 0 (w 1), 1/2 0 (w 1), 1 1/4 (w 1), 4/3 2/3 (w 9/8)\nright: 4/3 2/3 (w 9/8), 8/5 1 (w 5/4), 5/3 4/3 (w 3/2), 3/2 3/2 (w 2)\n"
    );
    let o = run(&["elevate", "--json", "--homogeneous", "1 0 1, 0 1 0, -1 0 1"], None);
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["weights"], serde_json::json!(["1", "1/3", "1/3", "1"]));
    assert_eq!(v["points"][1], serde_json::json!(["1", "2"])); // seed 000 example 4's control points
    // undefined curves and bad weights: exit 2 with the reason
    let o = run(&["eval", "--weights", "1 -1 1", "--t", "1/2", "0 0, 1 1, 2 0"], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("denominator vanishes at t = 1/2"));
    let o = run(&["eval", "--weights", "1 1/0 1", "--t", "1/2", "0 0, 1 1, 2 0"], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--weights") && stderr(&o).contains("zero denominator"));
    let o = run(&["conic", "--weights", "1 1 1 1", "0 0, 1 1, 2 0, 3 3"], None);
    assert_eq!(o.status.code(), Some(2));
    let o = run(&["subdivide", "--depth", "2", "--weights", "1 1 1", "0 0, 1 1, 2 0"], None);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn cli_defined_isolates_denominator_roots_exactly() {
    let o = run(&["defined", "--weights", "1 -2 1", "0 0, 1 1, 2 0"], None);
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).starts_with("undefined: the denominator vanishes at t in ("), "{}", stdout(&o));
    let o = run(&["defined", "--json", "--weights", "1 -1 1", "0 0, 1 1, 2 0"], None);
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["roots"], serde_json::json!(["t = 1/2"]));
    let o = run(&["defined", "--from", "3/4", "--weights", "1 -2 1", "0 0, 1 1, 2 0"], None);
    assert_eq!(o.status.code(), Some(1)); // 1/2 + √3/6 ≈ 0.789 is in [3/4, 1]
    let o = run(&["defined", "--from", "1/4", "--to", "3/4", "--weights", "1 -2 1", "0 0, 1 1, 2 0"], None);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(
        run(&["defined", "--from", "1", "--to", "0", "--weights", "1 1", "0 0, 1 1"], None).status.code(),
        Some(2)
    );
    let o = run(&["eval", "--json", "--weights", "1 -2 1", "--t", "1/4", "0 0, 1 1, 2 0"], None);
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["defined_on_0_1"], false);
}

#[test]
fn cli_spline_to_bezier_and_check() {
    let pts = "0 0, 1 3, 3 4, 5 1, 7 2, 8 5";
    let args = ["--degree", "3", "--weights", "1 2 1/2 3 1 2/3", "--ratios", "1 2 1 3 2 1 2 1", pts];
    let mut a = vec!["spline", "to-bezier", "--method", "seed", "--json"];
    a.extend(args);
    let o = run(&a, None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["segments"].as_array().unwrap().len(), 3);
    assert_eq!(v["segments"][0]["weights"], serde_json::json!(["25/16", "7/4", "1", "29/20"]));
    assert_eq!(v["segments"][0]["span"], serde_json::json!(["4", "7"]));
    let mut c = vec!["spline", "check"];
    c.extend(args);
    let o = run(&c, None);
    assert_eq!(o.status.code(), Some(0));
    assert!(stdout(&o).contains("seed formulas = Boehm (points and weights): true"));
    let o = run(&["spline", "to-bezier", "--degree", "2", "--ratios", "1 2 1", pts], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("need 7 scale ratios, got 3"));
    let o =
        run(&["spline", "to-bezier", "--method", "seed", "--degree", "4", "--ratios", "1 1 1 1 1 1 1 1 1", pts], None);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn cli_surface_eval_subdivide_elevate_contour() {
    let p = "0 0 0, 1 0 1, 2 0 0, 0 1 1, 1 1 2, 2 1 1";
    let o = run(
        &["surface", "eval", "--degree", "1,2", "--weights", "1 2 1 1 3 1", "--u", "1/2", "--v", "1/3", "--json", p],
        None,
    );
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["point"], serde_json::json!(["4/5", "17/30", "37/30"]));
    assert_eq!(v["de_casteljau_u_then_v_and_v_then_u_agree"], true);
    let o = run(&["surface", "subdivide", "--degree", "1,2", "--v", "1/2", "--json", p], None);
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["first"]["degree"], serde_json::json!([1, 2]));
    let o = run(&["surface", "elevate", "--degree", "1,2", "--u-by", "1", "--v-by", "1", "--json", p], None);
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["degree"], serde_json::json!([2, 3]));
    let o = run(&["surface", "contour", "--degree", "1,2", "--z", "1/2", "--json", p], None);
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["bernstein_coefficients"], serde_json::json!([["-1/2", "1/2", "-1/2"], ["1/2", "3/2", "1/2"]]));
    assert_eq!(
        run(&["surface", "eval", "--degree", "1,2", "--u", "0", "--v", "0", "0 0 0, 1 0 1"], None).status.code(),
        Some(2)
    );
    assert_eq!(run(&["surface", "eval", "--degree", "x", "--u", "0", "--v", "0", p], None).status.code(), Some(2));
    assert_eq!(run(&["surface", "subdivide", "--degree", "1,2", p], None).status.code(), Some(2));
}

#[test]
fn cli_plot_and_gallery() {
    let o = run(&["plot", "--polygon", "--features", "0 0, 1 1, 0 1, 1 0"], None);
    assert_eq!(o.status.code(), Some(0));
    assert!(stdout(&o).starts_with("<svg xmlns="));
    let o = run(&["plot", "--weights", "1 1 1 1", "--weights-family", "w1=1,3,4", "-2 0, -1 3, 1 2, 2 0"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).matches("<polyline").count() >= 3);
    assert_eq!(run(&["plot", "0 0, 1 x"], None).status.code(), Some(2));
    assert_eq!(run(&["plot", "--weights-family", "q", "--weights", "1 1", "0 0, 1 1"], None).status.code(), Some(2));
    let tmp = crate::common::TempDir::new("cli-gallery");
    let dir = tmp.join("gallery");
    let o = run(&["gallery", dir.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(0));
    assert!(dir.join("index.html").exists());
}

/// The fast default and `--detail full` agree on every field they share; only `full` carries
/// the evidence (moving lines, canonical map, Loop–Blinn).
#[test]
fn cli_classify_default_and_full_detail_agree_on_shared_fields() {
    let input = "0 0, 1 1, 0 1, 1 0\n0 0, 2 2, -1 2, 1 0\n0 0, 1 2, 2 -1, 3 1\n0 0, 3 3, 0 3, 3 0\n0 0, 1 1, 2 2, 3 3\n\
                 0 0, 1 0, 1 0, 2 0\n0 0, 1 2, 2 0\n-1 -1, -1/3 1, 1/3 -1, 1 1\n0 0, 0 1, 1 1, 1 0\n5 7, -3 2, 8 -1, 0 4\n\
                 1/3 1/7, 2.5 -0.125, 1e3 7, 0 0\n170141183460469231731687303715884105727 0, 1 1, 0 1, 1 0\n\
                 1200 -700, 1800 2400, -300 1900, 2048 0\n";
    let basic = run(&["classify", "--json", "--float"], Some(input));
    let full = run(&["classify", "--json", "--float", "--detail", "full"], Some(input));
    let parse = |o: &std::process::Output| -> Vec<serde_json::Value> {
        stdout(o).lines().map(|l| serde_json::from_str(l).unwrap()).collect()
    };
    let (b, f) = (parse(&basic), parse(&full));
    assert_eq!(b.len(), 13);
    for (b, f) in b.iter().zip(&f) {
        let (b, f) = (b.as_object().unwrap(), f.as_object().unwrap());
        for (k, v) in b {
            assert_eq!(Some(v), f.get(k), "field {k}");
        }
        for k in ["moving_lines", "canonical", "loop_blinn"] {
            assert!(!b.contains_key(k));
        }
        let extra: Vec<&String> = f.keys().filter(|k| !b.contains_key(*k)).collect();
        assert!(extra.iter().all(|k| ["moving_lines", "canonical", "loop_blinn"].contains(&k.as_str())), "{extra:?}");
    }
    assert!(f[0].get("canonical").is_some());
}

/// Streamed batches: one bad byte spoils only its line; a byte-order mark and CRLF are fine;
/// the answers keep input order on any number of threads; text-mode errors name the line.
#[test]
fn cli_batch_streaming_per_line_errors_and_thread_independent_order() {
    let mut input: Vec<u8> = b"\xEF\xBB\xBF0 0, 1 1\r\n".to_vec();
    input.extend_from_slice(b"0 0, \xFF 1\n");
    for k in 0..5000 {
        input.extend_from_slice(format!("0 {k}, 1 1, 2 {}\n", k % 7).as_bytes());
    }
    let run_bytes = |args: &[&str]| {
        use std::io::Write;
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_casteljau"))
            .args(args)
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        let mut stdin = child.stdin.take().unwrap();
        let data = input.clone();
        let writer = std::thread::spawn(move || stdin.write_all(&data).unwrap());
        let out = child.wait_with_output().unwrap();
        writer.join().unwrap();
        out
    };
    let one = run_bytes(&["eval", "--json", "--t", "1/3", "--threads", "1"]);
    let two = run_bytes(&["eval", "--json", "--t", "1/3", "--threads", "2"]);
    assert_eq!(one.status.code(), Some(2));
    assert_eq!(one.stdout, two.stdout);
    let lines: Vec<serde_json::Value> =
        String::from_utf8(one.stdout).unwrap().lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines.len(), 5002);
    assert_eq!(lines[0]["values"][0]["point"], serde_json::json!(["1/3", "1/3"]));
    assert_eq!(lines[1]["line"], 2);
    assert!(lines[1]["error"].as_str().unwrap().contains("not UTF-8"), "{}", lines[1]);
    assert!(lines.iter().enumerate().skip(2).all(|(i, v)| v["line"] == i + 1));
    let text = run_bytes(&["eval", "--t", "1/3"]);
    assert!(
        String::from_utf8_lossy(&text.stderr).contains("line 2: not UTF-8"),
        "{}",
        String::from_utf8_lossy(&text.stderr)
    );
}

/// `--numbers binary64`: the curve a float program holds after reading "0.1" etc. is not the
/// decimal one. These decimals make an explicit cubic (A = 0) exactly; their binary64 values make
/// an acnode. Hex floats are exact in both modes.
#[test]
fn cli_numbers_binary64_classifies_the_float_curve() {
    let curve = "0 0, 0.1 0.3, 0.2 -0.1, 0.3 0.2";
    let class = |args: &[&str]| -> String {
        let o = run(args, None);
        assert!(o.status.success(), "{}", stderr(&o));
        let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
        v["class"].as_str().unwrap().to_string()
    };
    assert_eq!(class(&["classify", "--json", curve]), "explicit");
    assert_eq!(class(&["classify", "--json", "--numbers", "binary64", curve]), "acnode");
    // the same binary64 values written as hex floats: exact in the default mode
    let hex: Vec<String> = curve
        .split(',')
        .map(|p| {
            p.split_whitespace().map(|t| format!("{:?}", hexf(t.parse::<f64>().unwrap()))).collect::<Vec<_>>().join(" ")
        })
        .collect();
    assert_eq!(class(&["classify", "--json", &hex.join(", ").replace('"', "")]), "acnode");
    // batch lines take the mode too; out-of-range numbers name the token
    let o = run(&["classify", "--numbers", "binary64", "--input", "-"], Some("0 0, 1 1, 2 0, 1e400 1\n"));
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("\"1e400\"") && stderr(&o).contains("line 1"), "{}", stderr(&o));
}

/// `x` as a C99 hex float (`0x1.999999999999ap-4` for 0.1).
fn hexf(x: f64) -> String {
    if x == 0.0 {
        return "0x0p0".into();
    }
    let bits = x.to_bits();
    let sign = if bits >> 63 == 1 { "-" } else { "" };
    let exp = ((bits >> 52) & 0x7ff) as i64;
    let frac = bits & ((1 << 52) - 1);
    assert!(exp != 0, "normal numbers only");
    format!("{sign}0x1.{frac:013x}p{}", exp - 1023)
}

fn font(name: &str) -> String {
    format!("{}/tests/data/fonts/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn json_lines(o: &std::process::Output) -> Vec<serde_json::Value> {
    stdout(o).lines().map(|l| serde_json::from_str(l).unwrap()).collect()
}

#[test]
fn cli_scan_font_lists_every_segment_with_provenance_in_order() {
    let o = run(&["scan", &font("Tuffy.ttf")], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let lines = json_lines(&o);
    assert!(lines.len() > 40_000);
    let a: Vec<&serde_json::Value> = lines.iter().filter(|v| v["glyph"] == "a").collect();
    assert_eq!(a[0]["glyph_id"], 68);
    assert_eq!(a[0]["contour"], 0);
    assert_eq!(a[0]["index"], 0);
    assert_eq!(a[0]["degree"], 2);
    assert_eq!(a[0]["points"], serde_json::json!([["489", "582"], ["378", "582"], ["308", "1025/2"]]));
    assert_eq!(a[0]["class"], "quadratic");
    // glyph ids never go backwards: deterministic file order
    let ids: Vec<u64> = lines.iter().map(|v| v["glyph_id"].as_u64().unwrap()).collect();
    assert!(ids.windows(2).all(|w| w[0] <= w[1]));
    assert!(stderr(&o).contains("segments"), "{}", stderr(&o));
    // the same answer on one thread
    let one = run(&["scan", "--threads", "1", "--quiet", &font("Tuffy.ttf")], None);
    assert_eq!(stdout(&one), stdout(&o));
    assert!(stderr(&one).is_empty());
}

#[test]
fn cli_scan_cff_font_gives_cubics() {
    let o = run(&["scan", "--quiet", &font("cantarell_vf_trimmed.ttf")], None);
    assert_eq!(o.status.code(), Some(0));
    let lines = json_lines(&o);
    assert!(lines.iter().any(|v| v["degree"] == 3 && v["segment"]["category"] == "arch"));
    // a CFF2 font stores no names: they are derived from cmap, as fontTools derives them
    let names: std::collections::BTreeSet<(u64, &str)> =
        lines.iter().map(|v| (v["glyph_id"].as_u64().unwrap(), v["glyph"].as_str().unwrap())).collect();
    let expected = [(1, "uni0069"), (2, "glyph00002"), (3, "uni006A"), (4, "uni006B"), (5, "uni006C")];
    assert_eq!(names.into_iter().collect::<Vec<_>>(), expected);
}

#[test]
fn cli_scan_only_filters_and_flags_endpoint_cusps() {
    let o = run(&["scan", "--only", "endpoint", "--path", "M0 0 C0 0 1 1 2 0 C3 1 4 1 5 0 Z"], None);
    assert_eq!(o.status.code(), Some(0));
    let lines = json_lines(&o);
    assert_eq!(lines.len(), 1);
    assert_eq!(lines[0]["index"], 0);
    assert_eq!(lines[0]["flags"], serde_json::json!(["zero_length_handle", "cusp_at_endpoint"]));
    assert_eq!(lines[0]["cusp_parameters"], serde_json::json!(["0"]));
    assert_eq!(run(&["scan", "--only", "cusps", "--path", "M0 0 L1 1"], None).status.code(), Some(2));
}

#[test]
fn cli_scan_json_is_accepted_and_changes_nothing() {
    // scan always writes JSON Lines; --json (which every other JSON-writing command takes) is a no-op
    let path = "M0 0 C0 0 1 1 2 0 A 1 1 0 0 1 4 4 Z";
    let plain = run(&["scan", "--quiet", "--path", path], None);
    let json = run(&["scan", "--json", "--quiet", "--path", path], None);
    assert_eq!(json.status.code(), Some(0), "{}", stderr(&json));
    assert_eq!(stdout(&json), stdout(&plain));
    assert_eq!(json_lines(&json).len(), 3); // the cubic, the skipped arc, the closing line
}

#[test]
fn cli_scan_svg_reports_skips_and_element_errors_with_exit_2() {
    let dir = crate::common::TempDir::new("scan");
    let svg = dir.join("icon.svg");
    std::fs::write(
        &svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg"><path id="p" d="M0 0 Q1 2 2 0 A1 1 0 0 1 3 3"/>
<circle r="2"/><path d="M0 0 L1"/></svg>"#,
    )
    .unwrap();
    let o = run(&["scan", svg.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(2));
    let lines = json_lines(&o);
    assert_eq!(lines[0]["element"], "p");
    assert_eq!(lines[0]["subpath"], 0);
    assert_eq!(lines[0]["class"], "quadratic");
    assert!(lines[1]["skipped"].as_str().unwrap().contains("arc"));
    assert_eq!(lines[1]["from"], serde_json::json!(["2", "0"]));
    assert_eq!(lines[2]["element"], 1);
    assert!(lines[2]["skipped"].as_str().unwrap().contains("circle"));
    assert!(lines[3]["error"].as_str().unwrap().contains("column"));
    assert!(stderr(&o).contains("errors 1"), "{}", stderr(&o));
    assert_eq!(run(&["scan", dir.join("missing.ttf").to_str().unwrap()], None).status.code(), Some(2));
}

#[test]
fn cli_numbers_binary64_applies_to_parameters_and_weights() {
    let o = run(&["eval", "--json", "--numbers", "binary64", "--t", "0.1", "0 0, 1 0"], None);
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["values"][0]["t"], "3602879701896397/36028797018963968");
    assert_eq!(v["values"][0]["point"][0], "3602879701896397/36028797018963968");
    let exact = run(&["eval", "--json", "--t", "0.1", "0 0, 1 0"], None);
    assert!(stdout(&exact).contains("\"1/10\""));
    // a weight 0.1 read as its double: the curve's midpoint moves accordingly
    let w = |mode: &str| {
        let o =
            run(&["eval", "--json", "--numbers", mode, "--weights", "1 0.1 1", "--t", "1/2", "0 0, 1 1, 2 0"], None);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
        v["values"][0]["point"][1].as_str().unwrap().to_string()
    };
    assert_eq!(w("exact"), "1/11");
    assert_ne!(w("binary64"), "1/11");
    let bad = run(&["eval", "--numbers", "binary64", "--t", "1e400", "0 0, 1 0"], None);
    assert_eq!(bad.status.code(), Some(2));
    assert!(stderr(&bad).contains("--t"), "{}", stderr(&bad));
}

#[test]
fn cli_scan_variation_instances_cff2_and_refuses_glyf() {
    let default = run(&["scan", "--quiet", &font("cantarell_vf_trimmed.ttf")], None);
    let light = run(&["scan", "--quiet", "--variation", "wght=100", &font("cantarell_vf_trimmed.ttf")], None);
    assert_eq!(light.status.code(), Some(0), "{}", stderr(&light));
    let (d, l) = (json_lines(&default), json_lines(&light));
    assert_eq!(d.len(), l.len());
    assert_ne!(d[0]["points"], l[0]["points"]);
    let o = run(&["scan", "--variation", "wght=700", &font("Tuffy.ttf")], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("no variation axes"), "{}", stderr(&o));
    assert_eq!(run(&["scan", "--variation", "wght", &font("cantarell_vf_trimmed.ttf")], None).status.code(), Some(2));
}
