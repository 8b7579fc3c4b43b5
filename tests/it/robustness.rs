//! Inputs that once crashed the binary (panic, stack overflow) or printed nonsense: each is a
//! regression test named after its case. Every one must end with exit 2 and a message.

use crate::common::{TempDir, run, stderr};

fn refused(args: &[&str], needle: &str) {
    let o = run(args, None);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
    assert!(stderr(&o).contains(needle), "{args:?}: {}", stderr(&o));
    assert!(!stderr(&o).contains("panicked"), "{args:?}");
}

#[test]
fn robustness_surface_elevate_zero_points_opposite_weights_is_an_error_not_a_panic() {
    refused(&["surface", "elevate", "--degree", "0,1", "--v-by", "1", "--weights", "1 -1", "0 0 0, 0 0 0"], "zero");
}

#[test]
fn robustness_rational_elevate_never_prints_a_zero_direction() {
    let o = run(&["elevate", "--weights", "1 -1", "0 0, 0 0"], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(!String::from_utf8_lossy(&o.stdout).contains("direction 0 0"));
    assert!(stderr(&o).contains("zero"), "{}", stderr(&o));
}

#[test]
fn robustness_spline_zero_points_opposite_weights_is_an_error_not_a_panic() {
    for op in ["check", "to-bezier"] {
        refused(
            &["spline", op, "--degree", "2", "--weights", "1 -1 1", "--ratios", "1 1 1 1", "0 0, 0 0, 0 0"],
            "zero",
        );
    }
}

#[test]
fn robustness_expression_with_thousands_of_nested_parentheses_is_refused() {
    let deep = format!("{}x{}", "(".repeat(5000), ")".repeat(5000));
    refused(&["implicit", "--poly", &deep, "0 0, 1 1"], "nested more than");
}

#[test]
fn robustness_flat_sum_of_twenty_thousand_terms_is_refused() {
    let flat = vec!["x"; 20000].join("+");
    refused(&["implicit", "--poly", &flat, "0 0, 1 1"], "levels deep");
}

#[test]
fn robustness_division_by_zero_in_a_polynomial_is_named_in_words() {
    let o = run(&["implicit", "--poly", "x/0", "0 0, 1 1"], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("division by zero") && !stderr(&o).contains("DivisionByZero"), "{}", stderr(&o));
}

#[test]
fn robustness_deep_expression_in_a_claim_file_is_a_claim_error() {
    let dir = TempDir::new("deep");
    let file = dir.join("deep.toml");
    let deep = format!("{}t{}", "(".repeat(10000), ")".repeat(10000));
    std::fs::write(
        &file,
        format!(
            "seed = \"x\"\n[[claim]]\nid = \"deep\"\nsource = \"-\"\nstatement = \"-\"\nexpect = \"holds\"\nkind = \"identity\"\nvars = [\"t\"]\nlhs = \"{deep}\"\nrhs = \"t\"\n"
        ),
    )
    .unwrap();
    let o = run(&["prove", file.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("deep.toml") && stderr(&o).contains("nested more than"), "{}", stderr(&o));
}

#[test]
fn robustness_plot_errors_like_every_other_command() {
    let o = run(&["plot"], Some("0 0, 1 x\n"));
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("bad number \"x\""), "{}", stderr(&o));
    assert!(o.stdout.is_empty(), "no half figure");
    refused(&["plot", "--json", "0 0, 1 1"], "--json does not apply");
}

#[test]
fn robustness_plot_never_writes_nan_or_inf() {
    refused(&["plot", "1e308 1e308, -1e308 -1e308"], "exceed the f64 range");
    refused(&["plot", "0 0, 1e400 1, 2 0"], "control point 2 is beyond the f64 range");
}

#[test]
fn robustness_prove_junit_is_all_or_nothing_on_a_malformed_claim() {
    let dir = TempDir::new("junit");
    let claims = dir.join("bad.toml");
    std::fs::write(
        &claims,
        "seed = \"x\"\n[[claim]]\nid = \"bad\"\nsource = \"-\"\nstatement = \"-\"\nexpect = \"holds\"\nkind = \"identity\"\nvars = [\"t\"]\nlhs = \"t +\"\nrhs = \"t\"\n",
    )
    .unwrap();
    let junit = dir.join("report.xml");
    let o = run(&["prove", claims.to_str().unwrap(), "--junit", junit.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(!junit.exists(), "no partial report");
    let leftovers: Vec<_> =
        std::fs::read_dir(dir.path()).unwrap().filter_map(|e| e.ok()).map(|e| e.file_name()).collect();
    assert_eq!(leftovers.len(), 1, "{leftovers:?}");
}

#[test]
fn robustness_implicit_degree_bound_beyond_the_limit_is_refused_before_work() {
    let curve: Vec<String> = (0..=10_000).map(|i| format!("{i} {}", i % 7)).collect();
    refused(&["implicit", "--poly", "y^100000 - x", &curve.join(", ")], "exceeds the limit 20000");
}

#[test]
fn robustness_claim_sizes_beyond_the_limits_are_claim_errors_not_aborts() {
    let dir = TempDir::new("sizes");
    let head = |id: &str| format!("[[claim]]\nid = \"{id}\"\nsource = \"-\"\nstatement = \"-\"\nexpect = \"holds\"\n");
    let text = format!(
        "seed = \"x\"\n{}kind = \"table\"\ncurve = \"0 0, 1 1\"\nsteps = 4000000000\nvalues = [[\"0\", \"0\"]]\n\
         {}kind = \"matrix\"\ndegree = 1000000000\nrows = [[\"1\"]]\n\
         {}kind = \"basis-table\"\ndegree = 1000000000\nsteps = 2\nrows = [[\"1\"]]\n\
         {}kind = \"identity\"\nparams = [\"n in 0..=99999\", \"m in 0..=99999\"]\nlhs = \"n\"\nrhs = \"n\"\n\
         {}kind = \"identity\"\nparams = [\"n in -5000000000000000000..=5000000000000000000\"]\nlhs = \"n\"\nrhs = \"n\"\n",
        head("table"),
        head("matrix"),
        head("basis"),
        head("params"),
        head("overflow")
    );
    let file = dir.join("big.toml");
    std::fs::write(&file, text).unwrap();
    let o = run(&["prove", file.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    for needle in [
        "claim table: steps = 4000000000 is more than the limit",
        "claim matrix: degree = 1000000000 is more than the limit",
        "claim basis: degree = 1000000000 is more than the limit",
        "claim params: more than 100000 parameter instances",
        "claim overflow: parameter n ranges over more than 100000 values",
    ] {
        assert!(stderr(&o).contains(needle), "{needle}: {}", stderr(&o));
    }
}

#[test]
fn robustness_a_trailing_comma_is_accepted_a_double_comma_is_not() {
    let o = run(&["eval", "--t", "1/2", "0 0, 2 2,"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(String::from_utf8_lossy(&o.stdout).trim(), "b(1/2) = (1, 1)");
    refused(&["eval", "--t", "1/2", "0 0,, 2 2"], "empty number between commas");
}

/// A degree-`n` planar control polygon with small integer coordinates.
fn polygon(n: usize) -> String {
    (0..=n).map(|i| format!("{} {}", (i * 7919) % 2001, (i * 104_729) % 1999)).collect::<Vec<_>>().join(", ")
}

/// Refused before any work starts: exit 2, the estimate and the option that raises it, fast.
fn refused_for_work(args: &[&str]) {
    let start = std::time::Instant::now();
    refused(args, "--max-work");
    // a refusal is immediate; the bound only guards against a regression to hours of work
    assert!(start.elapsed().as_secs() < 60, "{:?} took {:?}", &args[..1], start.elapsed());
}

#[test]
fn robustness_documented_degree_commands_on_10001_points_refuse_by_estimate() {
    let big = polygon(10_000);
    for cmd in
        [&["power"][..], &["reduce"], &["subdivide"], &["derivative", "--order", "5000"], &["elevate", "--by", "3"]]
    {
        let mut args = cmd.to_vec();
        args.push(&big);
        refused_for_work(&args);
    }
}

#[test]
fn robustness_eval_at_a_thousand_digit_parameter_refuses_by_estimate() {
    let t = format!("1/{}", "7".repeat(997));
    refused_for_work(&["eval", "--t", &t, &polygon(10_000)]);
}

#[test]
fn robustness_triangle_of_degree_500_at_a_big_parameter_refuses_by_estimate() {
    refused_for_work(&["triangle", "--t", "12345/67891", &polygon(500)]);
}

#[test]
fn robustness_nested_sum_of_ten_to_the_ten_terms_stops_at_the_step_limit() {
    refused_for_work(&["implicit", "--poly", "sum(r, 0, 100000, sum(s, 0, 100000, x))", "0 0, 1 1"]);
}

#[test]
fn robustness_defined_with_positive_weights_at_degree_10000_is_immediate() {
    let o = run(&["defined", &polygon(10_000)], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

#[test]
fn robustness_defined_with_mixed_weights_at_high_degree_refuses_by_estimate() {
    let w: Vec<String> = (0..=3200).map(|i| if i % 3 == 0 { "-1".into() } else { format!("{}", 1 + i % 5) }).collect();
    refused_for_work(&["defined", "--weights", &w.join(" "), &polygon(3200)]);
}

#[test]
fn robustness_max_work_raises_and_lowers_the_budget() {
    let c = polygon(300);
    refused(&["power", "--max-work", "1000", &c], "raise it with --max-work");
    assert_eq!(run(&["power", "--max-work", "1e12", &c], None).status.code(), Some(0));
    refused(&["power", "--max-work", "-3", &c], "positive number of work units");
}

#[test]
fn robustness_prove_with_a_hundred_thousand_instances_stops_at_the_step_limit() {
    let dir = TempDir::new("steps");
    std::fs::write(
        dir.join("c.toml"),
        "seed = \"x\"\ntitle = \"x\"\n\n[[claim]]\nid = \"many\"\nsource = \"x\"\nstatement = \"x\"\nexpect = \"holds\"\n\
         kind = \"identity\"\nvars = [\"t\"]\nparams = [\"n in 0..=99999\"]\nlhs = \"sum(k, 0, n, B(k, n, t))\"\nrhs = \"1\"\n",
    )
    .unwrap();
    let start = std::time::Instant::now();
    let o = run(&["prove", dir.path().to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("--max-work"), "{}", stderr(&o));
    assert!(start.elapsed().as_secs() < 60);
}

#[test]
fn robustness_surface_contour_of_a_64_by_64_patch_on_a_1000_grid_answers() {
    let net: Vec<String> =
        (0..65 * 65).map(|i| format!("{} {} {}", i % 7 - 3, (i * 3) % 11 - 5, (i * 5) % 13 - 6)).collect();
    let o =
        run(&["surface", "contour", "--degree", "64,64", "--z", "1/2", "--polyline", "1000", &net.join(", ")], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

#[test]
fn robustness_cr_only_line_endings_are_lines() {
    let o =
        run(&["eval", "--t", "1/2", "--json"], Some("0 0, 1 1, 2 0\r1 1, 2 2, 3 1\r\r# note\r4 4, 5 5\r\n6 6, 7 7\n"));
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let lines: Vec<serde_json::Value> =
        crate::common::stdout(&o).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    let numbers: Vec<u64> = lines.iter().map(|v| v["line"].as_u64().unwrap()).collect();
    assert_eq!(numbers, [1, 2, 5, 6]);
}

#[test]
fn robustness_plot_title_with_a_control_character_is_valid_xml() {
    let o = run(&["plot", "--title", "a\u{1}b<&\"", "0 0, 1 1, 2 0"], None);
    assert_eq!(o.status.code(), Some(0));
    let svg = crate::common::stdout(&o);
    assert!(!svg.contains('\u{1}'));
    assert!(svg.contains("a\u{FFFD}b&lt;&amp;"));
}

#[test]
fn robustness_plot_features_of_a_glyph_cubic_with_a_far_double_point_keeps_the_curve_large() {
    // the double point lies near (−1.1e10, −2.6e10): drawn as a labelled arrow
    let o = run(&["plot", "--features", "48 43, 22 23, 13 43, 1 56"], None);
    assert_eq!(o.status.code(), Some(0));
    let svg = crate::common::stdout(&o);
    let view = svg.split("viewBox=\"").nth(1).unwrap().split('"').next().unwrap();
    let v: Vec<f64> = view.split(' ').map(|x| x.parse().unwrap()).collect();
    assert!(v[2] < 200.0 && v[3] < 200.0, "view box {view}");
    assert!(svg.contains("far away"));
}

#[test]
fn robustness_ten_thousand_claims_parse_in_one_pass_with_their_lines() {
    let mut text = String::from("seed = \"x\"\ntitle = \"x\"\n\n");
    for i in 0..10_000 {
        text += &format!(
            "[[claim]]\nid = \"c{i}\"\nsource = \"x\"\nstatement = \"x\"\nexpect = \"holds\"\nkind = \"identity\"\n\
             vars = [\"t\"]\nlhs = \"t + {i}\"\nrhs = \"{i} + t\"\n\n"
        );
    }
    let claims = casteljau::catalogue::parse_claims("many.toml", &text).unwrap();
    assert_eq!(claims.len(), 10_000);
    // claim i starts at line 4 + 10 i; its id is on the next line
    assert_eq!(claims[0].line, 5);
    assert_eq!(claims[9_999].line, 5 + 10 * 9_999);
}

#[test]
fn robustness_text_batch_answers_name_their_lines() {
    let o = run(&["subdivide", "--input", "-"], Some("0 0, 1 1\n# skip\n1 1, 3 3\n"));
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(
        crate::common::stdout(&o),
        "line 1:\n  left:  0 0, 1/2 1/2\n  right: 1/2 1/2, 1 1\nline 3:\n  left:  1 1, 2 2\n  right: 2 2, 3 3\n"
    );
}

#[test]
fn robustness_an_over_long_line_is_an_error_for_that_line_only() {
    // 17 MiB of digits on line 2: refused without reading it into a curve; lines 1 and 3 answered
    let input = format!("0 0, 1 1\n{}\n2 2, 3 3\n", "1 ".repeat(17 * 512 * 1024));
    let o = run(&["eval", "--t", "1/2", "--json", "--input", "-"], Some(&input));
    assert_eq!(o.status.code(), Some(2));
    let lines: Vec<serde_json::Value> =
        crate::common::stdout(&o).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines.len(), 3);
    assert!(lines[1]["error"].as_str().unwrap().contains("longer than"));
    assert_eq!(lines[2]["line"], 3);
}

#[test]
fn robustness_plot_of_degree_10000_refuses_by_estimate() {
    refused_for_work(&["plot", &polygon(10_000)]);
}

#[test]
fn robustness_line_numbers_survive_block_boundaries_with_every_line_end() {
    // ~100 KB of lines (several input blocks) ending in \n, \r\n or a lone \r, with blank,
    // comment and bad lines: every answer names its line, on 1 and 2 threads alike
    let ends = ["\n", "\r\n", "\r", "\n", "\r\n"];
    let mut input = String::new();
    let mut expected = vec![];
    for k in 0..4000usize {
        let n = k + 1;
        match k % 13 {
            3 => input += "   ",
            7 => input += "# a comment",
            11 => {
                input += "0 0, 1 x";
                expected.push((n, true));
            }
            _ => {
                input += &format!("{} {}, {} {}, {} {}, {} {}", k, 2 * k, k + 1, 7, 3, k % 5, 9, 1);
                expected.push((n, false));
            }
        }
        if k + 1 < 4000 {
            input += ends[(k * 7 + k / 3) % ends.len()];
        }
    }
    let dir = TempDir::new("blocks");
    let path = dir.write("blocks.txt", &input);
    let outputs: Vec<String> = ["1", "2"]
        .iter()
        .map(|threads| {
            let o = run(&["classify", "--json", "--threads", threads, "--input", path.to_str().unwrap()], None);
            assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
            crate::common::stdout(&o)
        })
        .collect();
    assert_eq!(outputs[0], outputs[1]);
    let lines: Vec<serde_json::Value> = outputs[0].lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    let got: Vec<(usize, bool)> =
        lines.iter().map(|v| (v["line"].as_u64().unwrap() as usize, v.get("error").is_some())).collect();
    assert_eq!(got, expected);
}

/// A claim file with one claim of `kind` and its `fields`.
fn one_claim(id: &str, fields: &str) -> String {
    format!("seed = \"x\"\n[[claim]]\nid = \"{id}\"\nsource = \"-\"\nstatement = \"-\"\nexpect = \"holds\"\n{fields}\n")
}

const DEGREE_10: &str = "0 0, 1 3, 2 -1, 3 4, 4 0, 5 2, 6 -3, 7 1, 8 5, 9 -2, 10 0";

#[test]
fn robustness_claim_repeated_subdivision_depth_16_degree_10_is_refused_before_work() {
    // was: 65,536 pieces each proved on a grid, past 13 minutes under the default budget
    let dir = TempDir::new("deep-subdivision");
    let fields =
        format!("kind = \"repeated-subdivision\"\ncurve = \"{DEGREE_10}\"\nt = \"1/2\"\ndepth = 16\npieces = 65536");
    dir.write("c.toml", &one_claim("deep", &fields));
    // refused with the estimate (exit 2) means no piece was checked: no wall-clock bound needed
    let o = run(&["prove", dir.path().to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(e.contains("claim deep") && e.contains("estimated work") && e.contains("--max-work"), "{e}");
    assert!(!e.contains("panicked"));
}

#[test]
fn robustness_claim_repeated_subdivision_within_the_budget_still_passes() {
    let dir = TempDir::new("shallow-subdivision");
    let fields =
        format!("kind = \"repeated-subdivision\"\ncurve = \"{DEGREE_10}\"\nt = \"1/2\"\ndepth = 4\npieces = 16");
    dir.write("c.toml", &one_claim("shallow", &fields));
    let o = run(&["prove", dir.path().to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(crate::common::stdout(&o).contains("1 passed, 0 failed"));
}

#[test]
fn robustness_every_claim_kind_estimates_its_work_before_starting() {
    // each kind at a size far past the default budget, refused in well under a second each
    let big = |n: usize| (0..=n).map(|i| format!("{i} {}", (i * 7) % 11)).collect::<Vec<_>>().join(", ");
    let ones = |n: usize| vec!["1"; n].join(" ");
    let row = |n: usize, k: usize| (0..n).map(|j| format!("{k} {j} {}", (k * j) % 5)).collect::<Vec<_>>().join(", ");
    let net = |n: usize| (0..n).map(|k| row(n, k)).collect::<Vec<_>>().join("; ");
    let cases = [
        ("rational-evaluations", format!("curve = \"{}\"", big(60))),
        ("rational-subdivision", format!("curve = \"{}\"\nt = \"1/3\"", big(400))),
        ("weight-pull", format!("curve = \"{}\"\nindex = 1\nweight = \"2\"", big(400))),
        ("table", format!("curve = \"{}\"\nsteps = 100000\nvalues = []", big(2000))),
        ("basis-table", "degree = 200\nsteps = 100000\nrows = []".to_string()),
        ("subdivision", format!("curve = \"{}\"\nt = \"1/3\"\nleft = \"0 0\"\nright = \"0 0\"", big(2000))),
        ("patch-evaluations", format!("net = \"{}\"", net(30))),
        ("spline-segments", format!("curve = \"{}\"\nratios = \"{}\"\ndegree = 20", big(300), ones(320))),
        ("implicit", format!("curve = \"{}\"\npoly = \"x^20 - y\"", big(900))),
    ];
    for (kind, fields) in cases {
        let dir = TempDir::new("kinds");
        dir.write("c.toml", &one_claim(kind, &format!("kind = \"{kind}\"\n{fields}")));
        let o = run(&["prove", dir.path().to_str().unwrap()], None);
        assert_eq!(o.status.code(), Some(2), "{kind}: {}", stderr(&o));
        assert!(stderr(&o).contains("--max-work"), "{kind}: {}", stderr(&o));
    }
}

#[test]
fn robustness_every_catalogue_claim_is_estimated_within_the_default_budget() {
    let claims = casteljau::catalogue::load(&[std::path::PathBuf::from("proofs")]).unwrap();
    for c in &claims {
        let e = c.estimate().unwrap();
        assert!(e < casteljau::work::DEFAULT_MAX_WORK / 10.0, "{}: {e:e}", c.id);
    }
}

fn p2(x: i64, y: i64) -> casteljau::Point<num_rational::BigRational> {
    casteljau::Point::new(vec![casteljau::rat(x), casteljau::rat(y)])
}

fn p3(x: i64, y: i64, z: i64) -> casteljau::Point<num_rational::BigRational> {
    casteljau::Point::new(vec![casteljau::rat(x), casteljau::rat(y), casteljau::rat(z)])
}

#[test]
fn robustness_weight_errors_say_which_weight_of_a_curve_and_a_spline() {
    use casteljau::{Error, RationalBezier, rat};
    let pts = vec![p2(0, 0), p2(1, 2), p2(2, 0)];
    let e = RationalBezier::new(pts.clone(), vec![rat(1), rat(1), rat(0)]).unwrap_err();
    assert_eq!(e, Error::ZeroWeight { index: 3, row: None });
    assert!(e.to_string().starts_with("weight 3 is 0: a control point at infinity"), "{e}");
    let e = RationalBezier::new(pts.clone(), vec![rat(1); 2]).unwrap_err();
    assert_eq!(e, Error::WeightCount { weights: 2, points: 3, row: None });
    assert!(e.to_string().contains("2 weights for 3 control points"), "{e}");
    let ratios = vec![rat(1); 4];
    let spline = |w: Vec<num_rational::BigRational>| casteljau::spline::RationalSpline::new(2, &pts, &w, &ratios);
    assert_eq!(spline(vec![rat(1), rat(0), rat(1)]).unwrap_err(), Error::ZeroWeight { index: 2, row: None });
    assert_eq!(spline(vec![rat(1); 4]).unwrap_err(), Error::WeightCount { weights: 4, points: 3, row: None });
}

#[test]
fn robustness_weight_errors_say_which_weight_of_a_patch_and_a_net() {
    use casteljau::surface::RationalPatch;
    use casteljau::{Error, rat};
    let rows = vec![vec![p3(0, 0, 0), p3(1, 0, 1)], vec![p3(0, 1, 0), p3(1, 1, 1)]];
    let e = RationalPatch::new(rows.clone(), vec![vec![rat(1); 2], vec![rat(1), rat(0)]]).unwrap_err();
    assert_eq!(e, Error::ZeroWeight { index: 2, row: Some(2) });
    assert!(e.to_string().starts_with("weight 2 of row 2 is 0"), "{e}");
    let e = RationalPatch::new(rows.clone(), vec![vec![rat(1); 2], vec![rat(1); 3]]).unwrap_err();
    assert_eq!(e, Error::WeightCount { weights: 3, points: 2, row: Some(2) });
    assert!(e.to_string().starts_with("row 2: 3 weights for 2 control points"), "{e}");
    let e = RationalPatch::new(rows.clone(), vec![vec![rat(1); 2]]).unwrap_err();
    assert!(e.to_string().contains("1 rows of weights for 2 rows of control points"), "{e}");
    let s = RationalPatch::new(rows, vec![vec![rat(1); 2]; 2]).unwrap();
    let e = s.with_weight_change(1, 0, &rat(-1)).unwrap_err().to_string();
    assert!(e.contains("new weight 1 of row 2 (w10) is 0: 1 + -1"), "{e}");
    let net = |w: Vec<Vec<num_rational::BigRational>>| {
        let pts: Vec<Vec<_>> = (0..4).map(|i| (0..4).map(|j| p3(j, i, (i * j) % 3)).collect()).collect();
        casteljau::spline::SplineNet::new((2, 2), pts, w, vec![rat(1); 5], vec![rat(1); 5])
    };
    let mut w = vec![vec![rat(1); 4]; 4];
    w[2][3] = rat(0);
    assert_eq!(net(w).unwrap_err(), Error::ZeroWeight { index: 4, row: Some(3) });
    let mut w = vec![vec![rat(1); 4]; 4];
    w[1].pop();
    assert_eq!(net(w).unwrap_err(), Error::WeightCount { weights: 3, points: 4, row: Some(2) });
}

/// Address space allowed to the binary in the long-line test (`ulimit -v`, KiB). Before the fix
/// `eval` read all 1.2 million points of a 10 MB line (about 520 MB resident, 11 s) and only
/// then refused the degree: it dies at this limit. Now the numbers are counted first: 17 MB
/// resident, 0.16 s, and the refusal passes this limit every time (measured 6 of 6 at 200 MB).
const LONG_LINE_ULIMIT_KB: u64 = 300_000;

#[test]
fn robustness_a_10_mb_line_of_small_points_is_refused_in_bounded_memory() {
    let dir = TempDir::new("long-line");
    let line: Vec<String> = (0..1_200_000).map(|i| format!("{} {}", i % 1000, (i * 7) % 1000)).collect();
    let file = dir.write("big.txt", &(line.join(", ") + "\n"));
    assert!(std::fs::metadata(&file).unwrap().len() > 10_000_000);
    for args in
        [&["eval", "--t", "1/2"][..], &["power"], &["subdivide", "--t", "1/3"], &["eval", "--json", "--t", "1/2"]]
    {
        let o = std::process::Command::new("sh")
            .arg("-c")
            .arg(format!("ulimit -v {LONG_LINE_ULIMIT_KB}; exec \"$0\" \"$@\""))
            .arg(env!("CARGO_BIN_EXE_casteljau"))
            .args(args)
            .arg("--input")
            .arg(&file)
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        let all = format!("{}{}", stderr(&o), String::from_utf8_lossy(&o.stdout));
        assert!(all.contains("degree 1199999 exceeds the limit 10000"), "{args:?}: {all}");
        assert!(!all.contains("memory allocation") && !all.contains("panicked"), "{args:?}: {all}");
    }
}
