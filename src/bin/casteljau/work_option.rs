//! The `--max-work` option's value, shared by every command that takes a work budget.

/// A positive work budget (`1e12`, `5000000000`).
pub fn parse_work(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(x) if x > 0.0 => Ok(x),
        _ => Err(format!("{s:?} is not a positive number of work units (e.g. 1e12)")),
    }
}
