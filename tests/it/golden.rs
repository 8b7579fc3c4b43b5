//! Every command's output, byte for byte, against the answers recorded in
//! `tests/data/golden/expected.jsonl`: a refactoring of the library or the binary must not change
//! one byte of what users read (text and JSON), nor an exit code.
//!
//! The cases are `tests/data/golden/cases.jsonl` (name, arguments, optional standard input; run
//! from the crate's folder). When an output is meant to change, record the new answers with
//! `CASTELJAU_BLESS=1 cargo test --test it golden::` and review the diff of `expected.jsonl`.

use serde::{Deserialize, Serialize};
use std::path::Path;

#[derive(Deserialize)]
struct Case {
    name: String,
    args: Vec<String>,
    stdin: Option<String>,
}

#[derive(Serialize, Deserialize, PartialEq, Debug)]
struct Expected {
    name: String,
    code: Option<i32>,
    stdout: String,
}

/// The output with wall-clock figures masked: `prove` prints each claim's time (`  8.6136s` in
/// text, `"seconds":8.61…` in JSON), the one thing that may differ between two runs.
fn mask_timings(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while !rest.is_empty() {
        if let Some(after) = rest.strip_prefix("\"seconds\":") {
            let n =
                after.find(|c: char| !(c.is_ascii_digit() || c == '.' || c == 'e' || c == '-')).unwrap_or(after.len());
            out.push_str("\"seconds\":0");
            rest = &after[n..];
            continue;
        }
        if rest.starts_with(' ') {
            // spaces, digits, '.', digits, 's', then a space: a time column
            let spaces = rest.len() - rest.trim_start_matches(' ').len();
            let tail = &rest[spaces..];
            let digits = tail.find(|c: char| !(c.is_ascii_digit() || c == '.')).unwrap_or(tail.len());
            if digits > 0 && tail[..digits].contains('.') && tail[digits..].starts_with("s ") {
                out.push_str(" <time> ");
                rest = &tail[digits + 2..];
                continue;
            }
        }
        let c = rest.chars().next().unwrap();
        out.push(c);
        rest = &rest[c.len_utf8()..];
    }
    out
}

fn run_case(case: &Case) -> Expected {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .args(&case.args)
        .current_dir(dir)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("the binary starts");
    let input = case.stdin.clone().unwrap_or_default();
    let mut stdin = child.stdin.take().unwrap();
    let writer = std::thread::spawn(move || {
        use std::io::Write;
        let _ = stdin.write_all(input.as_bytes());
    });
    let out = child.wait_with_output().unwrap();
    writer.join().unwrap();
    let stdout = String::from_utf8(out.stdout).unwrap();
    Expected { name: case.name.clone(), code: out.status.code(), stdout: mask_timings(&stdout) }
}

#[test]
fn golden_every_command_answers_as_recorded() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/golden");
    let cases: Vec<Case> = std::fs::read_to_string(dir.join("cases.jsonl"))
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let got: Vec<Expected> = cases.iter().map(run_case).collect();
    let path = dir.join("expected.jsonl");
    if std::env::var_os("CASTELJAU_BLESS").is_some() {
        let text: String = got.iter().map(|e| serde_json::to_string(e).unwrap() + "\n").collect();
        std::fs::write(&path, text).unwrap();
        return;
    }
    let expected: Vec<Expected> =
        std::fs::read_to_string(&path).unwrap().lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(expected.len(), got.len(), "cases.jsonl and expected.jsonl differ in length: bless again");
    let differ: Vec<&str> = expected.iter().zip(&got).filter(|(e, g)| e != g).map(|(e, _)| e.name.as_str()).collect();
    for (e, g) in expected.iter().zip(&got).filter(|(e, g)| e != g) {
        eprintln!("{}: expected exit {:?}\n{}\ngot exit {:?}\n{}", e.name, e.code, e.stdout, g.code, g.stdout);
    }
    assert!(differ.is_empty(), "outputs changed: {differ:?}");
}
