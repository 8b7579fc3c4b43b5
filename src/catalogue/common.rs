//! What every claim kind shares: the [`Outcome`] of one check, and reading the claim files'
//! exact numbers, curves and tables.

use crate::curve::bezier::BezierCurve;
use crate::error::{Error, Result};
use crate::num::parse::{parse_number, parse_points};
use crate::num::point::Point;
use crate::num::scalar::rat;
use crate::rational::rational_bezier::RationalBezier;
use num_rational::BigRational;

/// The result of one check: whether the statement holds, how it was checked, and the evidence.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Outcome {
    /// The statement holds.
    pub holds: bool,
    /// `grid`, `exact-compare`, `exact-eval`, …
    pub method: &'static str,
    /// Certificate or counterexample, in words.
    pub detail: String,
}

pub(crate) fn verdict(holds: bool, method: &'static str, detail: String) -> Outcome {
    Outcome { holds, method, detail }
}

pub(crate) fn bad(message: impl Into<String>) -> Error {
    Error::InvalidArgument { message: message.into() }
}

/// One exact number of a claim file.
pub(crate) fn num(s: &str) -> Result<BigRational> {
    parse_number(s.trim(), Default::default())
}

pub(crate) use crate::num::parse::parse_numbers as scalars;

/// `"x0 y0, x1 y1, …"`; the dimension is read from the first point.
pub(crate) fn curve_from(text: &str) -> Result<BezierCurve<BigRational>> {
    let dim = if text.contains(',') { text.split(',').next().map_or(2, |p| p.split_whitespace().count()) } else { 2 };
    BezierCurve::new(parse_points(text, dim, None)?)
}

/// Rows of exact strings as points.
pub(crate) fn points_of(rows: &[Vec<String>]) -> Result<Vec<Point<BigRational>>> {
    rows.iter().map(|r| Ok(Point::new(r.iter().map(|v| num(v)).collect::<Result<_>>()?))).collect()
}

/// Largest `steps` of a table.
pub const MAX_TABLE_STEPS: u32 = 100_000;

/// Largest degree of a `matrix` or `basis-table` claim (the matrix has `(n+1)²` big entries).
pub const MAX_TABLE_DEGREE: usize = 200;

/// Parameters of a table: `ts`, or `k/steps` for `k = 0..=steps`.
pub(crate) fn parameters_of(ts: &Option<Vec<String>>, steps: Option<u32>) -> Result<Vec<BigRational>> {
    match (ts, steps) {
        (Some(ts), _) => ts.iter().map(|t| num(t)).collect(),
        (None, Some(n)) if n > MAX_TABLE_STEPS => {
            Err(bad(format!("steps = {n} is more than the limit {MAX_TABLE_STEPS}")))
        }
        (None, Some(n)) if n > 0 => Ok((0..=n).map(|k| BigRational::new(k.into(), n.into())).collect()),
        _ => Err(bad("a table needs `ts` or `steps`")),
    }
}

/// A rational curve given by `curve` and `weights` (default all 1), or by `homogeneous` points.
pub(crate) fn rational_curve(
    curve: Option<&str>,
    weights: Option<&str>,
    homogeneous: Option<&str>,
) -> Result<RationalBezier<BigRational>> {
    if let Some(h) = homogeneous {
        let dim = h.split(',').next().map_or(3, |p| p.split_whitespace().count());
        return RationalBezier::from_homogeneous(parse_points(h, dim, None)?);
    }
    let curve = curve_from(curve.ok_or_else(|| bad("missing field `curve` (or `homogeneous`)"))?)?;
    let w = match weights {
        Some(w) => scalars(w)?,
        None => vec![rat(1); curve.points().len()],
    };
    RationalBezier::new(curve.points().to_vec(), w)
}

/// Computed and printed points compared exactly, entry by entry.
pub(crate) fn compare(computed: &[Point<BigRational>], expected: &[Point<BigRational>], what: &str) -> Outcome {
    if computed.len() != expected.len() {
        return verdict(
            false,
            "exact-compare",
            format!("{} {what} computed, {} printed", computed.len(), expected.len()),
        );
    }
    match computed.iter().zip(expected).position(|(a, b)| a != b) {
        None => verdict(true, "exact-compare", format!("all {} {what} equal exactly", computed.len())),
        Some(k) => {
            verdict(false, "exact-compare", format!("{what}: entry {k} printed {} but is {}", expected[k], computed[k]))
        }
    }
}

/// Parameters `0, 1, 1/2, 1/3, 2/3, …` where `keep` holds, `count` of them.
pub(crate) fn parameters_where(count: usize, mut keep: impl FnMut(&BigRational) -> bool) -> Vec<BigRational> {
    let mut out = Vec::new();
    let mut q = 1i64;
    while out.len() < count && q < 10_000 {
        for p in 0..=q {
            if num_integer::gcd(p, q) == 1 || (p == 0 && q == 1) {
                let t = BigRational::new(p.into(), q.into());
                if keep(&t) {
                    out.push(t);
                    if out.len() == count {
                        break;
                    }
                }
            }
        }
        q += 1;
    }
    out
}

/// `✓` or `✗`.
pub(crate) fn tick(b: bool) -> &'static str {
    if b { "✓" } else { "✗" }
}
