//! The documentation runs: every shell example of `README.md` and `docs/*.md`, and the README's
//! library example, so an example that stops matching the program fails the suite.
//!
//! A ```` ```console ```` block is a sequence of `$ casteljau …` commands, each followed by the
//! output it prints (standard output and standard error together), run from the crate's folder by
//! [`trycmd`] with the binary this `cargo test` built. In the shown output a line `...` stands for
//! any number of lines and `[..]` for any part of a line (timings, long JSON); a line `? N` right
//! after the command is its exit code (0 when absent). Other blocks (```` ```sh ````, ```` ```text ````)
//! are not run. Input files the examples name live in the repository (`docs/examples/`,
//! `tests/data/`).
//!
//! When an output is meant to change, record the new outputs in the Markdown with
//! `TRYCMD=overwrite cargo test --test it docs::` (elisions that still match are kept) and review
//! the diff.

use std::path::{Path, PathBuf};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The Markdown files whose `console` blocks run.
fn documents() -> Vec<PathBuf> {
    let mut docs = vec![root().join("README.md")];
    let mut chapters: Vec<PathBuf> = std::fs::read_dir(root().join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    chapters.sort();
    docs.extend(chapters);
    docs
}

/// A program of the system (`cat`), for examples that show an input file.
fn system_program(name: &str) -> PathBuf {
    let path = std::env::var_os("PATH").unwrap_or_default();
    std::env::split_paths(&path)
        .map(|d| d.join(name))
        .find(|p| p.is_file())
        .unwrap_or_else(|| panic!("`{name}` not found on PATH"))
}

#[test]
fn docs_every_console_example_prints_what_it_shows() {
    // trycmd runs the commands in the test's working folder, which cargo sets to the crate's
    assert_eq!(
        std::env::current_dir().unwrap().canonicalize().unwrap(),
        root().canonicalize().unwrap(),
        "run the docs test from the crate's folder (as cargo test does)"
    );
    let cases = trycmd::TestCases::new();
    cases.register_bin("casteljau", Path::new(env!("CARGO_BIN_EXE_casteljau")));
    cases.register_bin("cat", system_program("cat"));
    for doc in documents() {
        cases.case(doc.strip_prefix(root()).unwrap());
    }
    cases.run();
}

/// The fenced blocks of one language in a Markdown text, each as its lines.
fn blocks<'a>(text: &'a str, language: &str) -> Vec<Vec<&'a str>> {
    let mut out = vec![];
    let mut current: Option<Vec<&str>> = None;
    for line in text.lines() {
        match &mut current {
            None if line.trim_start().strip_prefix("```") == Some(language) => current = Some(vec![]),
            Some(_) if line.trim_start() == "```" => out.push(current.take().unwrap()),
            Some(lines) => lines.push(line),
            None => {}
        }
    }
    out
}

// BEGIN readme_library_example (README.md shows this body verbatim)
fn readme_library_example() -> Result<(), Box<dyn std::error::Error>> {
    use casteljau::{BezierCurve, NodeType, classify, parse_points, ratio};

    let curve = BezierCurve::new(parse_points("0 0, 2 2, -1 2, 1 0", 2, None)?)?;
    let (left, _right) = curve.subdivide(&ratio(1, 2));
    assert_eq!(left.to_string(), "0 0, 1 1, 3/4 3/2, 1/2 3/2");

    let c = classify(&curve)?; // exact: a loop, its double point rational, its parameters in Q(√15)
    assert_eq!(c.node_type, Some(NodeType::Crunode));
    assert_eq!(c.double_point.unwrap().to_string(), "(1/2, 3/5)");
    assert!(c.segment.has_loop);
    Ok(())
}
// END readme_library_example

// BEGIN library_tour (docs/library.md shows this body verbatim)
fn library_tour() -> Result<(), Box<dyn std::error::Error>> {
    use casteljau::curve::Evaluation;
    use casteljau::num::{Rational, Scalar};
    use casteljau::{BezierCurve, Budget, Domain, RationalBezier, intersect, parse_points, proof, rat, ratio};

    let c = BezierCurve::new(parse_points("-1 -1, -1/3 1, 1/3 -1, 1 1", 2, None)?)?;
    let (left, _right) = c.subdivide(&ratio(1, 3)); // over BigRational: the fraction-free kernel
    assert_eq!(left.to_string(), "-1 -1, -7/9 -1/3, -5/9 -1/9, -1/3 -1/27");
    assert_eq!(c.real_degree(), 3);

    // every operation the command line offers, with a work budget checked before it starts
    let _e = Evaluation::new(&c, &[ratio(1, 3)], &Budget::new(1e10, "max_work"))?;

    // exact intersections: parameters and points are exact algebraic numbers
    let a = RationalBezier::new(parse_points("0 0, 1 2, 2 0", 2, None)?, vec![rat(1); 3])?;
    let b = RationalBezier::new(parse_points("0 1, 2 1", 2, None)?, vec![rat(1); 2])?;
    let hits = intersect(&a, &b, Domain::Unit, &Budget::unlimited())?; // the apex touches y = 1: s = t = 1/2, tangent
    assert_eq!(hits.intersections.len(), 1);

    // Prove your own identity: a polynomial of degree ≤ d_j in each variable that vanishes on a
    // (d_j + 1)-point grid per variable is zero. The closure is generic code; run it exactly.
    fn lerp<S: Scalar>(a: &S, b: &S, t: &S) -> S {
        (S::one() - t) * a + t.clone() * b
    }
    let cert = proof::identity::<Rational>(&[1, 1, 1], |v| {
        lerp(&v[0], &v[1], &v[2]) - (v[0].clone() + v[2].clone() * &(v[1].clone() - &v[0]))
    })
    .expect("holds");
    println!("{cert}"); // degree ≤ (1, 1, 1) per variable; vanishes on a 2×2×2 grid …
    Ok(())
}
// END library_tour

/// The body of the function between `// BEGIN name` and `// END name` in this file, without its
/// signature and its last two lines (`Ok(())`, `}`), one indentation less.
fn body_of(name: &str) -> Vec<String> {
    let source = include_str!("docs.rs");
    let begin = source.find(&format!("// BEGIN {name} ")).unwrap();
    let end = source.find(&format!("// END {name}\n")).unwrap();
    let lines: Vec<&str> = source[begin..end].lines().skip(2).collect();
    lines[..lines.len() - 2].iter().map(|l| l.strip_prefix("    ").unwrap_or(l).to_string()).collect()
}

/// `doc` shows one Rust example, and it is the body of the function `name` of this file.
fn assert_shown_verbatim(doc: &str, name: &str) {
    let text = std::fs::read_to_string(root().join(doc)).unwrap();
    let shown = blocks(&text, "rust");
    assert_eq!(shown.len(), 1, "{doc} shows one Rust example");
    assert_eq!(shown[0], body_of(name), "{doc}'s Rust example differs from {name} in tests/it/docs.rs: copy it over");
}

#[test]
fn docs_readme_library_example_runs_and_is_shown_verbatim() {
    readme_library_example().unwrap();
    assert_shown_verbatim("README.md", "readme_library_example");
}

#[test]
fn docs_library_tour_runs_and_is_shown_verbatim() {
    library_tour().unwrap();
    assert_shown_verbatim("docs/library.md", "library_tour");
}

#[test]
fn docs_readme_is_a_front_page() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let lines = readme.lines().count();
    assert!(lines <= 200, "README.md has {lines} lines: the manual belongs in docs/");
    for command in ["cargo run --release -- prove", "cargo test"] {
        assert!(readme.contains(command), "README.md must show `{command}`");
    }
}

/// Every relative link of the documentation names a file or folder of the repository.
#[test]
fn docs_relative_links_resolve() {
    let mut docs = documents();
    docs.extend(["ARCHITECTURE.md", "CONTRIBUTING.md", "CHANGELOG.md", "benches/README.md"].map(|f| root().join(f)));
    let mut broken = vec![];
    for doc in &docs {
        let text = std::fs::read_to_string(doc).unwrap();
        let folder = doc.parent().unwrap();
        // Markdown links `](target)` and HTML `src="target"`
        let targets = text
            .split("](")
            .skip(1)
            .filter_map(|s| s.split(')').next())
            .chain(text.split("src=\"").skip(1).filter_map(|s| s.split('"').next()));
        for target in targets {
            let target = target.split('#').next().unwrap();
            if target.is_empty() || target.contains("://") || target.starts_with("mailto:") {
                continue;
            }
            if !folder.join(target).exists() {
                broken.push(format!("{}: {target}", doc.strip_prefix(root()).unwrap().display()));
            }
        }
    }
    assert!(broken.is_empty(), "links to missing files: {broken:#?}");
}
