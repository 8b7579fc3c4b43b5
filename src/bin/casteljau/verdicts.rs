//! What `boolean` and its font route (`glyphs`) share: the `--tol` option, and the text and JSON
//! of an answer with its `--against` verdict.

use crate::batch::option_number;
use casteljau::error::{Error, Result};
use casteljau::oracle::Agreement;
use casteljau::path::FillRule;
use casteljau::shape::{BooleanOp, BooleanResult};
use num_rational::BigRational;
use num_traits::Signed;

/// `--tol`: an exact, non-negative number.
pub(crate) fn tolerance(text: &str) -> Result<BigRational> {
    let tol = option_number("--tol", text)?;
    if tol.is_negative() {
        return Err(Error::InvalidArgument { message: format!("--tol is a distance (≥ 0), not {tol}") });
    }
    Ok(tol)
}

/// `"agree"` or `"disagree: <problems>"`.
pub(crate) fn verdict_text(v: &Agreement) -> String {
    if v.agree { "agree".into() } else { format!("disagree: {}", v.problems.join("; ")) }
}

/// The JSON object of an answer: `head` (already written fields, each followed by a comma, or
/// empty), `op`, `fill`, the result's fields, then `tail` fields (each preceded by a comma).
pub(crate) fn result_json(head: &str, op: BooleanOp, fill: FillRule, r: &BooleanResult, tail: &str) -> String {
    let body = serde_json::to_string(r).expect("exact strings and finite floats serialize");
    let fill = serde_json::to_string(&fill).expect("a name serializes");
    format!("{{{head}\"op\":\"{}\",\"fill\":{fill},{}{tail}}}", op.as_str(), &body[1..body.len() - 1])
}

/// `,"verdict":{…}` (or nothing).
pub(crate) fn verdict_json(v: Option<&Agreement>) -> String {
    v.map(|v| format!(",\"verdict\":{}", serde_json::to_string(v).expect("exact strings and finite floats serialize")))
        .unwrap_or_default()
}
