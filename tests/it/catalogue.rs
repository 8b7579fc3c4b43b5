//! Meta-tests of the proofs/ catalogue: it parses, ids are unique, every verdict is as expected,
//! the generated README is current, and the checker is not fooled by flipped verdicts or
//! perturbed constants.

use casteljau::catalogue::{self, Verdict, check, load, parse_claims, readme};
use casteljau::work::Budget;
use std::collections::HashSet;
use std::path::PathBuf;

fn proofs() -> Vec<PathBuf> {
    vec![PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("proofs")]
}

#[test]
fn catalogue_parses_with_unique_ids_and_every_verdict_as_expected_and_readme_current() {
    let claims = load(&proofs()).unwrap();
    assert!(claims.len() >= 59, "{} claims", claims.len());
    let ids: HashSet<_> = claims.iter().map(|c| c.id.clone()).collect();
    assert_eq!(ids.len(), claims.len());
    let results: Vec<_> = claims.iter().map(|c| check(c, &Budget::unlimited()).unwrap()).collect();
    for r in &results {
        assert!(r.passed(), "{}: expected {:?}, found {:?}: {}", r.id, r.expected, r.found, r.detail);
    }
    let errata = results.iter().filter(|r| r.found == Verdict::FailsAsPrinted).count();
    assert!(errata >= 10, "{errata} errata");
    let current = std::fs::read_to_string(proofs()[0].join("README.md")).unwrap();
    assert!(
        readme(&claims, &results) == current,
        "proofs/README.md is stale: run `cargo run --release -- prove --write-readme`"
    );
}

const TRUE_IDENTITY: &str = r#"
seed = "001_8a5894bbd9ecfc92.txt"
[[claim]]
id = "t-8"
source = "(8)"
statement = "identity (8), small n"
expect = "holds"
kind = "identity"
vars = ["s", "t"]
params = ["n in 0..=5", "j in 0..=n"]
lhs = "B(j, n, s*t)"
rhs = "sum(r, j, n, B(j, r, s) * B(r, n, t))"
"#;

#[test]
fn catalogue_true_identity_holds_and_perturbed_constant_is_caught() {
    let c = &parse_claims("t.toml", TRUE_IDENTITY).unwrap()[0];
    assert_eq!(check(c, &Budget::unlimited()).unwrap().found, Verdict::Holds);
    for perturbed in [
        TRUE_IDENTITY.replace("B(j, n, s*t)", "B(j, n, s*t) * 1.000000000001"),
        TRUE_IDENTITY.replace("B(r, n, t))", "B(r, n, t) + 10^-30)"),
        TRUE_IDENTITY.replace("sum(r, j, n,", "sum(r, j, n - 1,"),
    ] {
        let c = &parse_claims("t.toml", &perturbed).unwrap()[0];
        let r = check(c, &Budget::unlimited()).unwrap();
        assert_eq!(r.found, Verdict::Fails, "{perturbed}");
        assert!(r.detail.contains("lhs − rhs"), "{}", r.detail);
        assert!(!r.passed());
    }
}

#[test]
fn catalogue_flipped_verdicts_fail() {
    // holds → fails-as-printed (with a "correction" identical to the claim): wrong verdict
    let flipped = TRUE_IDENTITY.replace("expect = \"holds\"", "expect = \"fails-as-printed\"")
        + "[claim.corrected]\nnote = \"none\"\n";
    let c = &parse_claims("t.toml", &flipped).unwrap()[0];
    assert!(!check(c, &Budget::unlimited()).unwrap().passed());
    // a real erratum marked as holding: wrong verdict
    let text = std::fs::read_to_string(proofs()[0].join("003_matrix_form.toml")).unwrap();
    let claims = parse_claims("003", &text).unwrap();
    let mut erratum = claims.into_iter().find(|c| c.id == "003-quartic-expansion-b1").unwrap();
    erratum.expect = Verdict::Holds;
    let r = check(&erratum, &Budget::unlimited()).unwrap();
    assert_eq!(r.found, Verdict::FailsAsPrinted);
    assert!(!r.passed());
}

#[test]
fn catalogue_malformed_files_name_file_and_line() {
    let cases = [
        ("seed = \"x\"\n[[claim]]\nid = \"a\"\nsource = \"s\"\n", "missing `statement`"),
        ("seed = \"x\"\n[[claim\n", "t.toml:2"),
        (&TRUE_IDENTITY.replace("expect = \"holds\"", "expect = \"true\"") as &str, "`expect` must be"),
        (&TRUE_IDENTITY.replace("kind = \"identity\"", "kind = \"identity\"\nfoo = 1") as &str, "unknown field `foo`"),
        (
            &TRUE_IDENTITY.replace("expect = \"holds\"", "expect = \"fails-as-printed\"") as &str,
            "needs a [claim.corrected]",
        ),
        ("[[claim]]\n", "missing `seed"),
    ];
    for (text, message) in cases {
        let e = parse_claims("t.toml", text).unwrap_err().to_string();
        assert!(e.contains(message) && e.starts_with("t.toml"), "{e}");
    }
    // errors found while checking name the claim's line
    let bad = TRUE_IDENTITY.replace("B(j, n, s*t)", "B(j, n, s*t");
    let c = &parse_claims("t.toml", &bad).unwrap()[0];
    let e = check(c, &Budget::unlimited()).unwrap_err().to_string();
    assert!(e.starts_with("t.toml:4: claim t-8") && e.contains("column"), "{e}");
    let dup = format!("{TRUE_IDENTITY}{}", &TRUE_IDENTITY[TRUE_IDENTITY.find("[[claim]]").unwrap()..]);
    let tmp = crate::common::TempDir::new("dup");
    tmp.write("d.toml", &dup);
    assert!(load(&[tmp.path().to_path_buf()]).unwrap_err().to_string().contains("duplicate claim id t-8"));
}

#[test]
fn catalogue_junit_report() {
    let c = &parse_claims("t.toml", TRUE_IDENTITY).unwrap()[0];
    let x = catalogue::junit(&[check(c, &Budget::unlimited()).unwrap()]);
    assert!(x.contains("<testsuite name=\"casteljau prove\" tests=\"1\" failures=\"0\">"));
    assert!(x.contains("<testcase classname=\"proofs\" name=\"t-8\""));
}
