//! What `boolean` and its font route (`glyphs`) share: the `--tol` option, and the text and JSON
//! of an answer with its `--against` verdict.

use crate::batch::option_number;
use casteljau::error::{Error, Result};
use casteljau::oracle::Agreement;
use casteljau::path::FillRule;
use casteljau::shape::{BooleanOp, BooleanResult};
use num_rational::BigRational;
use num_traits::Signed;
use serde::Serialize;

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

/// The JSON object of an answer: `op`, `fill`, the fields of [`BooleanResult`], then `verdict`
/// with `--against` (a [`Agreement`], or what the font route puts in its place).
#[derive(Serialize)]
pub(crate) struct ResultJson<'a, V = &'a Agreement> {
    pub(crate) op: BooleanOp,
    pub(crate) fill: FillRule,
    #[serde(flatten)]
    pub(crate) result: &'a BooleanResult,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) verdict: Option<V>,
}
