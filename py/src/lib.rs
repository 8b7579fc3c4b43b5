//! `casteljau._core`: the native half of the `casteljau` Python package.
//!
//! Every entry point runs its exact work through [`run`]: the GIL is released while it runs
//! (`py.allow_threads`), a Rust panic is caught at the boundary and raised as
//! `casteljau.CasteljauError` (never reaching the interpreter as a `PanicException`), and a
//! library [`casteljau::Error`] becomes a `CasteljauError` with the command line's message. Work
//! is bounded by the `max_work=` budget (the command line's `--max-work`, default `1e10`
//! units, about ten seconds); a refusal names `max_work`.
//!
//! The Python side (python/casteljau) holds the protocols (pens, skia-pathops' `Path`,
//! fontTools and ufo2ft glue); this crate holds the exact work and the number conversions.

use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use std::panic::{AssertUnwindSafe, catch_unwind};

mod curves;
mod fonts;
mod numbers;
mod shapes;

create_exception!(
    casteljau,
    CasteljauError,
    PyValueError,
    "An exact operation refused its input or its budget: the command line's message (bad number \
     with its position, a degree limit, a work estimate above `max_work`, …). A `ValueError`."
);

/// The budget of an entry point: `max_work` units (`None`: the command line's default `1e10`;
/// `math.inf`: unlimited), refused naming `max_work`.
pub(crate) fn budget(max_work: Option<f64>) -> PyResult<casteljau::Budget> {
    let limit = max_work.unwrap_or(casteljau::work::DEFAULT_MAX_WORK);
    if limit.is_nan() || limit < 0.0 {
        return Err(CasteljauError::new_err(format!("max_work is a non-negative number of work units, not {limit}")));
    }
    Ok(casteljau::Budget::new(limit, "max_work="))
}

/// A library error as `CasteljauError`, with the command line's message.
pub(crate) fn error(e: casteljau::Error) -> PyErr {
    // the budget is `max_work=` here, where the command line says `--max-work`
    CasteljauError::new_err(e.to_string().replace("max_work= ", "max_work=").replace("--max-work", "max_work="))
}

/// What a caught panic said.
fn panic_text(p: Box<dyn std::any::Any + Send>) -> String {
    if let Some(s) = p.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = p.downcast_ref::<String>() {
        s.clone()
    } else {
        "a panic without a message".to_string()
    }
}

/// Runs exact work with the GIL released and panics caught: `Ok`, a library error as
/// `CasteljauError`, or a panic as `CasteljauError("internal error: …")`.
pub(crate) fn run<T: Send>(py: Python<'_>, f: impl FnOnce() -> casteljau::Result<T> + Send) -> PyResult<T> {
    match py.allow_threads(|| catch_unwind(AssertUnwindSafe(f))) {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(e)) => Err(error(e)),
        Err(p) => Err(CasteljauError::new_err(format!("internal error (please report): {}", panic_text(p)))),
    }
}

/// Runs cheap work holding the GIL, panics caught as in [`run`].
pub(crate) fn guard<T>(f: impl FnOnce() -> PyResult<T>) -> PyResult<T> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(p) => Err(CasteljauError::new_err(format!("internal error (please report): {}", panic_text(p)))),
    }
}

#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("CasteljauError", m.py().get_type::<CasteljauError>())?;
    m.add("DEFAULT_MAX_WORK", casteljau::work::DEFAULT_MAX_WORK)?;
    numbers::register(m)?;
    curves::register(m)?;
    shapes::register(m)?;
    fonts::register(m)?;
    Ok(())
}
