//! The `proofs/` catalogue: claim files, their checking, and the generated `proofs/README.md`.
//!
//! A claim file is TOML: a `seed = "<file name>"` line and `[[claim]]` tables, each with
//!
//! * `id` (unique across the catalogue), `source` (the place in the seed: equation, example,
//!   figure), `statement` (in words), `expect` = `"holds"` or `"fails-as-printed"`;
//! * the checkable content: `kind` and that kind's fields (the kinds and their fields are listed
//!   in `proofs/README.md` and `docs/prove.md`), written **as printed** in the seed, OCR and
//!   typesetting errors included;
//! * for `fails-as-printed`, a `[claim.corrected]` table overriding the fields that change, and
//!   optionally `note`: the corrected statement must hold.
//!
//! A claim passes when its found verdict is its expected one: `holds` when the content holds;
//! `fails-as-printed` when the printed content fails (with its counterexample) and the corrected
//! content holds.

pub(crate) mod claims;
pub(crate) mod common;
mod cost;
pub(crate) mod cubic;
pub(crate) mod polynomial;
pub(crate) mod rational;
pub(crate) mod surface;

use claims::ClaimContent;

use crate::error::{Error, Result};
use crate::work::Budget;
use common::Outcome;
use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// What a claim is expected to do, or was found to do (in JSON: its [`Verdict::as_str`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Verdict {
    /// The statement holds.
    Holds,
    /// The printed statement fails; the corrected one holds.
    FailsAsPrinted,
    /// The statement fails and no corrected statement holds.
    Fails,
}

impl Verdict {
    /// `holds`, `fails-as-printed` or `fails`.
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Holds => "holds",
            Verdict::FailsAsPrinted => "fails-as-printed",
            Verdict::Fails => "fails",
        }
    }
}

/// One claim of the catalogue.
#[derive(Clone, Debug)]
pub struct Claim {
    /// Unique id.
    pub id: String,
    /// Seed file name and place.
    pub source: String,
    /// The statement in words.
    pub statement: String,
    /// The expected verdict.
    pub expect: Verdict,
    /// The content as printed.
    pub(crate) content: ClaimContent,
    /// The corrected content (for `fails-as-printed`).
    pub(crate) corrected: Option<ClaimContent>,
    /// A note on the correction.
    pub note: Option<String>,
    /// The claim file and the line of its `id`.
    pub file: String,
    /// 1-based line of the claim's `id`.
    pub line: usize,
}

/// The result of checking a claim: one line of `prove`, one object of `prove --json` (fields
/// `id`, `source`, `statement`, `expected`, `verdict`, `passed`, `method`, `detail`,
/// `corrected` (or `null`) and `seconds`).
#[derive(Clone, Debug, serde::Serialize)]
pub struct ClaimResult {
    /// The claim's id.
    pub id: String,
    /// Seed file name and place.
    pub source: String,
    /// The statement in words.
    pub statement: String,
    /// The expected verdict.
    pub expected: Verdict,
    /// The verdict found.
    #[serde(rename = "verdict")]
    pub found: Verdict,
    /// The found verdict is the expected one.
    pub passed: bool,
    /// How it was checked.
    pub method: &'static str,
    /// Evidence for the printed content.
    pub detail: String,
    /// Evidence for the corrected content, when there is one.
    #[serde(rename = "corrected")]
    pub corrected_detail: Option<String>,
    /// Seconds taken.
    pub seconds: f64,
}

impl Claim {
    /// The estimated work of checking the claim (its printed and its corrected content), in
    /// work units ([`crate::work`]): what [`check`] compares with its budget.
    ///
    /// # Errors
    /// A malformed claim body, with the file and line.
    pub fn estimate(&self) -> Result<f64> {
        let wrap = |e: Error| Error::ClaimFile {
            file: self.file.clone(),
            line: Some(self.line),
            message: format!("claim {}: {e}", self.id),
        };
        Ok(self.content.estimate().map_err(wrap)?
            + self.corrected.as_ref().map_or(Ok(0.0), |c| c.estimate()).map_err(wrap)?)
    }
}

impl ClaimResult {
    /// The found verdict is the expected one.
    pub fn passed(&self) -> bool {
        self.passed
    }
}

/// The `*.toml` claim files under `paths` (files as given, directories non-recursively), sorted.
///
/// # Errors
/// [`Error::ClaimFile`] for a path that cannot be read.
pub(crate) fn claim_files(paths: &[PathBuf]) -> Result<Vec<PathBuf>> {
    let mut out = Vec::new();
    for p in paths {
        let err =
            |e: std::io::Error| Error::ClaimFile { file: p.display().to_string(), line: None, message: e.to_string() };
        if p.is_dir() {
            let mut files: Vec<PathBuf> = std::fs::read_dir(p)
                .map_err(err)?
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|f| f.extension().is_some_and(|x| x == "toml"))
                .collect();
            files.sort();
            out.extend(files);
        } else if p.exists() {
            out.push(p.clone());
        } else {
            return Err(err(std::io::Error::new(std::io::ErrorKind::NotFound, "no such file or directory")));
        }
    }
    Ok(out)
}

const META_KEYS: [&str; 6] = ["id", "source", "statement", "expect", "note", "corrected"];

fn line_of(text: &str, byte: usize) -> usize {
    text[..byte.min(text.len())].matches('\n').count() + 1
}

/// Parses one claim file's text.
///
/// # Errors
/// [`Error::ClaimFile`] with the file, the line and what is wrong.
pub fn parse_claims(file: &str, text: &str) -> Result<Vec<Claim>> {
    let err = |line: Option<usize>, message: String| Error::ClaimFile { file: file.to_string(), line, message };
    let table: toml::Table = text
        .parse()
        .map_err(|e: toml::de::Error| err(e.span().map(|s| line_of(text, s.start)), e.message().to_string()))?;
    let seed = table
        .get("seed")
        .and_then(|v| v.as_str())
        .ok_or_else(|| err(Some(1), "missing `seed = \"<seed file>\"`".into()))?;
    if let Some(k) = table.keys().find(|k| !["seed", "title", "claim"].contains(&k.as_str())) {
        return Err(err(None, format!("unknown top-level key `{k}`")));
    }
    let claims = match table.get("claim") {
        None => return Ok(vec![]),
        Some(v) => v.as_array().ok_or_else(|| err(None, "`claim` must be an array of tables ([[claim]])".into()))?,
    };
    let mut out = Vec::new();
    // claims appear in file order: each id is searched from the previous one on, and lines are
    // counted incrementally (linear in the file, not quadratic in the number of claims)
    let (mut cursor, mut cursor_line) = (0usize, 1usize);
    for (k, c) in claims.iter().enumerate() {
        let t = c.as_table().ok_or_else(|| err(None, format!("claim {} is not a table", k + 1)))?;
        let s = |key: &str| t.get(key).and_then(|v| v.as_str()).map(str::to_string);
        let id = s("id").ok_or_else(|| err(None, format!("claim {} has no `id`", k + 1)))?;
        let quoted = format!("\"{id}\"");
        let line = match text[cursor..].find(&quoted) {
            Some(b) => {
                cursor_line += text[cursor..cursor + b].matches('\n').count();
                cursor += b;
                Some(cursor_line)
            }
            None => text.find(&quoted).map(|b| line_of(text, b)),
        };
        let cerr = |m: String| err(line, format!("claim {id}: {m}"));
        let source = s("source").ok_or_else(|| cerr("missing `source`".into()))?;
        let statement = s("statement").ok_or_else(|| cerr("missing `statement`".into()))?;
        let expect = match s("expect").as_deref() {
            Some("holds") => Verdict::Holds,
            Some("fails-as-printed") => Verdict::FailsAsPrinted,
            other => return Err(cerr(format!("`expect` must be \"holds\" or \"fails-as-printed\", not {other:?}"))),
        };
        let mut body = t.clone();
        for key in META_KEYS {
            body.remove(key);
        }
        let content: ClaimContent =
            toml::Value::Table(body.clone()).try_into().map_err(|e: toml::de::Error| cerr(e.message().to_string()))?;
        let corrected = match t.get("corrected") {
            None if expect == Verdict::FailsAsPrinted => {
                return Err(cerr("`fails-as-printed` needs a [claim.corrected] table".into()));
            }
            None => None,
            Some(v) => {
                let over = v.as_table().ok_or_else(|| cerr("`corrected` must be a table".into()))?;
                let mut merged = body.clone();
                for (key, value) in over {
                    if key != "note" {
                        merged.insert(key.clone(), value.clone());
                    }
                }
                Some(
                    toml::Value::Table(merged)
                        .try_into()
                        .map_err(|e: toml::de::Error| cerr(format!("corrected: {}", e.message())))?,
                )
            }
        };
        let note = s("note")
            .or_else(|| t.get("corrected").and_then(|c| c.get("note")).and_then(|v| v.as_str()).map(str::to_string));
        out.push(Claim {
            id,
            source: format!("{seed}, {source}"),
            statement,
            expect,
            content,
            corrected,
            note,
            file: file.to_string(),
            line: line.unwrap_or(0),
        });
    }
    Ok(out)
}

/// Loads every claim under `paths`, checking that ids are unique.
///
/// # Errors
/// [`Error::ClaimFile`] for unreadable or malformed files and duplicate ids.
pub fn load(paths: &[PathBuf]) -> Result<Vec<Claim>> {
    let mut claims = Vec::new();
    let mut seen = HashSet::new();
    for f in claim_files(paths)? {
        let name = f.display().to_string();
        let text = std::fs::read_to_string(&f).map_err(|e| Error::ClaimFile {
            file: name.clone(),
            line: None,
            message: e.to_string(),
        })?;
        for c in parse_claims(&name, &text)? {
            if !seen.insert(c.id.clone()) {
                return Err(Error::ClaimFile {
                    file: name,
                    line: Some(c.line),
                    message: format!("duplicate claim id {}", c.id),
                });
            }
            claims.push(c);
        }
    }
    Ok(claims)
}

/// Checks one claim after estimating its work (the printed and the corrected content
/// together): a claim past `budget` is refused before any of it is checked, with
/// [`Error::WorkLimit`] naming the estimate, the limit and the option that raises it; while it
/// runs, the expression language's steps are charged against the same budget
/// ([`crate::proof::expr::with_step_limit`]). [`Budget::unlimited`] for no limit.
///
/// # Errors
/// A malformed claim body (bad expression, missing field, unknown kind), or an estimate past
/// `budget`, with the file and line.
///
/// # Example
/// ```
/// use casteljau::catalogue::{check, parse_claims};
/// use casteljau::work::Budget;
/// let claims = parse_claims("deep.toml", r#"
///     seed = "x"
///     [[claim]]
///     id = "deep"
///     source = "-"
///     statement = "-"
///     expect = "holds"
///     kind = "repeated-subdivision"
///     curve = "0 0, 1 3, 2 -1, 3 4, 4 0, 5 2, 6 -3, 7 1, 8 5, 9 -2, 10 0"
///     t = "1/2"
///     depth = 16
///     pieces = 65536
/// "#).unwrap();
/// let e = check(&claims[0], &Budget::new(1e10, "--max-work")).unwrap_err();
/// assert!(e.to_string().contains("--max-work"));
/// ```
pub fn check(claim: &Claim, budget: &Budget) -> Result<ClaimResult> {
    crate::proof::expr::with_step_limit(budget.expression_steps(), || check_claim(claim, budget))
}

fn check_claim(claim: &Claim, budget: &Budget) -> Result<ClaimResult> {
    let start = Instant::now();
    let wrap = |e: Error| Error::ClaimFile {
        file: claim.file.clone(),
        line: Some(claim.line),
        message: format!("claim {}: {e}", claim.id),
    };
    budget.check("the check", claim.estimate()?).map_err(wrap)?;
    let printed: Outcome = claim.content.check().map_err(wrap)?;
    let (found, corrected_detail) = if printed.holds {
        (Verdict::Holds, None)
    } else {
        match &claim.corrected {
            Some(c) => {
                let fixed = c.check().map_err(wrap)?;
                (if fixed.holds { Verdict::FailsAsPrinted } else { Verdict::Fails }, Some(fixed.detail))
            }
            None => (Verdict::Fails, None),
        }
    };
    Ok(ClaimResult {
        id: claim.id.clone(),
        source: claim.source.clone(),
        statement: claim.statement.clone(),
        expected: claim.expect,
        found,
        passed: found == claim.expect,
        method: printed.method,
        detail: printed.detail,
        corrected_detail,
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// JUnit XML for CI systems: one test case per claim, a failure for each wrong verdict.
pub fn junit(results: &[ClaimResult]) -> String {
    let esc = |s: &str| s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;");
    let failures = results.iter().filter(|r| !r.passed()).count();
    let mut x = format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuite name=\"casteljau prove\" tests=\"{}\" failures=\"{failures}\">\n",
        results.len()
    );
    for r in results {
        x += &format!("  <testcase classname=\"proofs\" name=\"{}\" time=\"{:.4}\"", esc(&r.id), r.seconds);
        if r.passed() {
            x += "/>\n";
        } else {
            x += &format!(
                ">\n    <failure message=\"expected {}, found {}\">{}</failure>\n  </testcase>\n",
                r.expected.as_str(),
                r.found.as_str(),
                esc(&r.detail)
            );
        }
    }
    x + "</testsuite>\n"
}

const README_HEAD: &str = "# proofs/ — the seeds' claims, machine-checked

Generated by `casteljau prove --write-readme` from the claim files in this folder; CI checks that it
is current. Do not edit by hand: edit the `.toml` files and regenerate.

Every checkable statement of the seeds (`../shared/seeds/`) is encoded **as printed** — OCR and
typesetting errors included — and checked exactly. A polynomial identity of degree ≤ d in each
variable that holds on a grid of d + 1 distinct exact values per variable holds everywhere, so the
checks are proofs (for each parameter instance). Where the seed is wrong the claim is expected to
`fail-as-printed`: the checker must find the counterexample, and the corrected statement must hold.

## Claim file format

```toml
seed = \"001_8a5894bbd9ecfc92.txt\"

[[claim]]
id = \"001-identity-8\"
source = \"(8)\"
statement = \"B_j^n(st) = sum_{r=j}^n B_j^r(s) B_r^n(t)\"
expect = \"holds\"                      # or \"fails-as-printed\" with a [claim.corrected] table
kind = \"identity\"
vars = [\"s\", \"t\"]
params = [\"n in 0..=40\", \"j in 0..=n\"]
lhs = \"B(j, n, s*t)\"
rhs = \"sum(r, j, n, B(j, r, s) * B(r, n, t))\"
```

Kinds: `identity` (expressions with `+ - * / ^`, `C(n,k)`, `B(i,n,x)`, `sum(r,a,b,e)`,
`prod(r,a,b,e)`; degree bounds derived, denominators cross-multiplied, poles avoided by switching
grid values), `curve-formula`, `power-form`, `subdivision`, `repeated-subdivision`, `matrix`,
`table`, `basis-table`, `classification`, `moving-lines`, `moving-line-2`, `canonical-map`,
`implicit`, `rational-evaluations`, `rational-elevation`, `rational-subdivision`, `weight-pull`,
`spline-segments`, `patch-evaluations`, `patch-weight-change`, `net` (see `src/catalogue/claims.rs`).

## What is not encoded, and why

- Seed 002 (57)–(59): the appendix's proof of (5) names auxiliary points of Fig. 15 whose labels
  the OCR lost (`OP : OP' = w1 : 1`, `OP : OP = …`); the statements cannot be reconstructed. Their
  conclusion (60) is (5), proved below (`002-eq-5-60`).
- Seed 002 (1)–(3) and (24) are definitions: (1)–(3) are used by the Menelaus claims, and the NURBS
  of (24) is the exact de Boor evaluator every spline claim is compared with.
- Seed 003 §3.1 item 2 prints the matrix form with a stray first row `t^3 t^2 t 1` (a J display
  artefact); the matrix itself is checked (`003-matrix-degree-3`).
- Seeds 002 (30)–(32) are proved for every weight and for scale ratios in 1..2 (each parameter
  instance a proof); with symbolic ratios the grids exceed the prover's size limit.
";

/// The generated `proofs/README.md`: format, errata with counterexamples, every claim's verdict.
pub fn readme(claims: &[Claim], results: &[ClaimResult]) -> String {
    let cell = |s: &str| s.replace('|', "\\|").replace('\n', " ");
    let mut out = README_HEAD.to_string();
    let errata: Vec<_> = claims.iter().zip(results).filter(|(_, r)| r.found == Verdict::FailsAsPrinted).collect();
    let holds = results.iter().filter(|r| r.found == Verdict::Holds).count();
    let wrong = results.iter().filter(|r| !r.passed()).count();
    out += &format!(
        "\n## Summary\n\n{} claims: {holds} hold as printed, {} fail as printed (seed errata, each with a corrected statement that holds){}.\n",
        results.len(),
        errata.len(),
        if wrong > 0 { format!(", **{wrong} with an unexpected verdict**") } else { String::new() }
    );
    out += "\n## Errata\n\n| id | source | printed statement | counterexample | correction (holds) |\n| --- | --- | --- | --- | --- |\n";
    for (c, r) in &errata {
        out += &format!(
            "| `{}` | {} | {} | {} | {} |\n",
            c.id,
            cell(&c.source),
            cell(&c.statement),
            cell(&r.detail),
            cell(c.note.as_deref().unwrap_or(r.corrected_detail.as_deref().unwrap_or("")))
        );
    }
    out += "\n## All claims\n\n| id | source | statement | expected | found | method | evidence |\n| --- | --- | --- | --- | --- | --- | --- |\n";
    for (c, r) in claims.iter().zip(results) {
        out += &format!(
            "| `{}` | {} | {} | {} | {} | {} | {} |\n",
            c.id,
            cell(&c.source),
            cell(&c.statement),
            r.expected.as_str(),
            r.found.as_str(),
            r.method,
            cell(&r.detail)
        );
    }
    out
}

/// The default catalogue folder, `proofs/`.
pub fn default_path() -> PathBuf {
    Path::new("proofs").to_path_buf()
}
