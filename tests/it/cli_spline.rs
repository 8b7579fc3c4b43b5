//! The `spline` command with knot vectors: clamped and multiple knots, JSON Lines batches,
//! insertion, exact removal, elevation, evaluation, NURBS surfaces; and `subdivide --depth 1`.

use crate::common::run;
use std::process::Output;

fn json_lines(o: &Output) -> Vec<serde_json::Value> {
    String::from_utf8(o.stdout.clone()).unwrap().lines().map(|l| serde_json::from_str(l).unwrap()).collect()
}

const CIRCLE_POINTS: &str = "1 0, 1 4/3, -7/25 24/25, -1 3/4, -1 0, -1 -4/3, 7/25 -24/25, 1 -3/4, 1 0";
const CIRCLE_WEIGHTS: &str = "1 3/5 1 4/5 1 3/5 1 4/5 1";

#[test]
fn cli_spline_clamped_circle_double_knots_segments_and_c0_joins() {
    let o = run(
        &[
            "spline",
            "to-bezier",
            "--json",
            "--degree",
            "2",
            "--knots",
            "0 0 0 1 1 2 2 3 3 4 4 4",
            "--weights",
            CIRCLE_WEIGHTS,
            CIRCLE_POINTS,
        ],
        None,
    );
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let v = &json_lines(&o)[0];
    let segs = v["segments"].as_array().unwrap();
    assert_eq!(segs.len(), 4);
    assert_eq!(segs[1]["span"], serde_json::json!(["1", "2"]));
    assert_eq!(segs[1]["weights"], serde_json::json!(["1", "4/5", "1"]));
    for j in v["joins"].as_array().unwrap() {
        assert_eq!(
            (j["multiplicity"].as_u64(), j["continuity"].as_i64(), j["proved"].as_bool()),
            (Some(2), Some(0), Some(true))
        );
    }
    // every segment lies on the unit circle, proved by `implicit`
    for s in segs {
        let pts: Vec<String> = s["points"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| format!("{} {}", p[0].as_str().unwrap(), p[1].as_str().unwrap()))
            .collect();
        let w: Vec<&str> = s["weights"].as_array().unwrap().iter().map(|x| x.as_str().unwrap()).collect();
        let o = run(&["implicit", "--weights", &w.join(" "), "--poly", "x^2 + y^2 - 1", &pts.join(", ")], None);
        assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stdout));
    }
}

#[test]
fn cli_spline_check_reports_each_join_continuity() {
    let o = run(
        &["spline", "check", "--degree", "3", "--knots", "0 0 0 0 1 1 2 3 3 3 3", "0 0, 1 2, 2 -1, 3 3, 4 0, 5 1, 6 2"],
        None,
    );
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.contains("u = 1 (multiplicity 2): C^1, proved"), "{text}");
    assert!(text.contains("u = 2 (multiplicity 1): C^2, proved"), "{text}");
}

#[test]
fn cli_spline_json_lines_batch_many_splines_in_one_process() {
    let input = [
        r#"{"degree":2,"knots":[0,0,0,"1/2",1,1,1],"weights":[1,2,1,1],"points":[[0,0],[1,2],[3,2],[4,0.5]]}"#,
        r#"{"degree":1,"ratios":[1,1,1],"points":[[0,0],[1,1],[2,0]]}"#,
        r#"{"degree":2,"knots":[0,0,0,1,1,1],"homogeneous":true,"points":[[1,0,1],[0,1,0],[-1,0,1]]}"#,
        r#"{"degree":2,"knots":[0,0,1,0,1,1],"points":[[0,0],[1,1],[2,0]]}"#,
    ]
    .join("\n");
    let o = run(&["spline", "to-bezier", "--json"], Some(&input));
    assert_eq!(o.status.code(), Some(2), "the fourth line is malformed");
    let v = json_lines(&o);
    assert_eq!(v.len(), 4);
    assert_eq!(v[0]["segments"].as_array().unwrap().len(), 2);
    assert_eq!(v[0]["segments"][1]["points"][2], serde_json::json!(["4", "1/2"]), "0.5 is read exactly");
    assert_eq!(v[1]["segments"].as_array().unwrap().len(), 2);
    // a semicircle through the point at infinity: the middle homogeneous point keeps w = 0
    assert_eq!(v[2]["segments"][0]["homogeneous"][1], serde_json::json!(["0", "1", "0"]));
    assert_eq!(v[3]["line"], 4);
    assert!(v[3]["error"].as_str().unwrap().contains("knot 4 (0) is less than knot 3 (1)"), "{}", v[3]);
}

#[test]
fn cli_spline_knot_errors_name_the_knot_and_exit_2() {
    for (knots, msg) in [
        ("0 0 0 2 1 2 2", "knot 5 (1) is less than knot 4 (2)"),
        ("0 0 0 0 2 2 2", "multiplicity 4, more than degree + 1 = 3"),
        ("0 0 0 1 2 2", "need 7 knots"),
        ("0 0 0 x 2 2 2", "--knots"),
    ] {
        let o = run(&["spline", "to-bezier", "--degree", "2", "--knots", knots, "0 0, 1 2, 3 2, 4 0"], None);
        assert_eq!(o.status.code(), Some(2), "{knots}");
        assert!(String::from_utf8_lossy(&o.stderr).contains(msg), "{knots}: {}", String::from_utf8_lossy(&o.stderr));
    }
    let o = run(&["spline", "to-bezier", "--degree", "2", "--ratios", "1 0 1 1 1", "0 0, 1 2, 3 2, 4 0"], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("scale ratio 2 (0) must be positive"));
}

#[test]
fn cli_spline_insert_remove_elevate_eval() {
    let base = ["--degree", "3", "--knots", "0 0 0 0 1 2 2 2 2"];
    let pts = "0 0, 1 3, 2 -1, 4 2, 5 0";
    let args =
        |op: &[&'static str]| -> Vec<&'static str> { [&["spline"][..], op, &base[..], &["--json", pts][..]].concat() };
    let inserted = json_lines(&run(&args(&["insert", "--knot", "1/2", "--times", "2"]), None));
    assert_eq!(inserted[0]["knots"], serde_json::json!(["0", "0", "0", "0", "1/2", "1/2", "1", "2", "2", "2", "2"]));
    // the inserted knots come out again, exactly
    let knots: Vec<String> =
        inserted[0]["knots"].as_array().unwrap().iter().map(|k| k.as_str().unwrap().to_string()).collect();
    let points: Vec<String> = inserted[0]["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| format!("{} {}", p[0].as_str().unwrap(), p[1].as_str().unwrap()))
        .collect();
    let back = run(
        &[
            "spline",
            "remove",
            "--json",
            "--knot",
            "1/2",
            "--times",
            "2",
            "--degree",
            "3",
            "--knots",
            &knots.join(" "),
            &points.join(", "),
        ],
        None,
    );
    assert_eq!(back.status.code(), Some(0));
    let back = json_lines(&back);
    assert_eq!(back[0]["points"], serde_json::json!([["0", "0"], ["1", "3"], ["2", "-1"], ["4", "2"], ["5", "0"]]));
    // knot 1 of this C^2 cubic is essential: removal refused, exit 1
    let o = run(&args(&["remove", "--knot", "1"]), None);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(json_lines(&o)[0]["removable"], false);
    let up = json_lines(&run(&args(&["elevate"]), None));
    assert_eq!(up[0]["degree"], 4);
    assert_eq!(up[0]["knots"], serde_json::json!(["0", "0", "0", "0", "0", "1", "1", "2", "2", "2", "2", "2"]));
    let e = json_lines(&run(&args(&["eval", "--u", "0", "--u", "1", "--u", "2"]), None));
    assert_eq!(e[0]["values"][0]["point"], serde_json::json!(["0", "0"]));
    assert_eq!(e[0]["values"][2]["point"], serde_json::json!(["5", "0"]));
}

#[test]
fn cli_spline_homogeneous_points_at_infinity() {
    // a semicircle: (1, 0), the direction (0, 1) at infinity, (−1, 0)
    let o = run(
        &[
            "spline",
            "eval",
            "--homogeneous",
            "--degree",
            "2",
            "--knots",
            "0 0 0 1 1 1",
            "--u",
            "1/2",
            "1 0 1, 0 1 0, -1 0 1",
        ],
        None,
    );
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(String::from_utf8(o.stdout).unwrap().trim(), "C(1/2) = (0, 1)");
}

#[test]
fn cli_spline_surface_patches_are_proved() {
    let net: Vec<String> = (0..4).flat_map(|i| (0..3).map(move |j| format!("{i} {j} {}", (i * j) % 3))).collect();
    let o = run(
        &[
            "spline",
            "surface",
            "--json",
            "--degree",
            "2,2",
            "--knots-u",
            "0 0 0 1 2 2 2",
            "--knots-v",
            "0 0 0 1 1 1",
            &net.join(", "),
        ],
        None,
    );
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let v = &json_lines(&o)[0];
    assert_eq!(v["patches"].as_array().unwrap().len(), 2);
    assert_eq!(v["check"]["equals_surface"], true);
    assert_eq!(v["check"]["joins_proved"], true);
}

#[test]
fn cli_subdivide_explicit_depth_1_uses_the_pieces_form() {
    let o = run(&["subdivide", "--json", "--depth", "1", "0 0, 1 1, 2 0"], None);
    let v = &json_lines(&o)[0];
    assert_eq!(v["pieces"].as_array().unwrap().len(), 2);
    assert_eq!(v["pieces"][0]["interval"], serde_json::json!(["0", "1/2"]));
    // without --depth: the two halves, as before
    let v = &json_lines(&run(&["subdivide", "--json", "0 0, 1 1, 2 0"], None))[0];
    assert!(v.get("left").is_some() && v.get("pieces").is_none());
}

#[test]
fn cli_spline_help_states_the_knot_convention() {
    let o = run(&["spline", "--help"], None);
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.contains("m + n + 2") && text.contains("t_(j+1) = t_j + l_j"), "{text}");
}

#[test]
fn cli_spline_method_is_a_closed_set_refused_before_work() {
    let o = run(&["spline", "to-bezier", "--method", "nope", "0 0, 1 1"], None);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8(o.stderr).unwrap();
    assert!(err.contains("boehm, seed, seed-printed"), "{err}");
}

#[test]
fn cli_spline_commands_refuse_past_max_work_before_starting() {
    let knots = "0 0 0 0 1 1 2 3 3 3 3";
    let pts = "0 0, 1 2, 2 -1, 3 3, 4 0, 5 1, 6 2";
    for op in ["check", "to-bezier"] {
        let o = run(&["spline", op, "--max-work", "10", "--degree", "3", "--knots", knots, pts], None);
        assert_eq!(o.status.code(), Some(2), "{op}");
        assert!(String::from_utf8(o.stderr).unwrap().contains("--max-work"), "{op}");
        let o = run(&["spline", op, "--degree", "3", "--knots", knots, pts], None);
        assert_eq!(o.status.code(), Some(0), "{op} within the default budget");
    }
    let o = run(&["spline", "eval", "--max-work", "10", "--u", "1/2", "--degree", "3", "--knots", knots, pts], None);
    assert_eq!(o.status.code(), Some(2));
}
