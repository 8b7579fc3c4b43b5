//! The float oracle's shared core: a float library's answer compared with the exact one, within
//! a tolerance on the float side only — the window `[p − tol, p + tol]` around the float `p`,
//! taken exactly, must hold the exact value — and float answers matched to exact ones, every
//! disagreement named by a [`DisagreementKind`] and carrying the float value as a [`FloatValue`].
//!
//! Two oracles use it: [`super::check_classification`] (a float library's answers about one
//! cubic: parameters, counts, the double point) and [`super::check_intersections`] (a float
//! library's intersection parameters of two curves).
//! The matching rule is stated in the [layer's documentation](super#the-shared-matching).

use crate::curve::bezier::BezierCurve;
use crate::error::{Error, Result};
use crate::num::point::Point;
use num_rational::BigRational;
use std::fmt;

/// What kind of disagreement.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DisagreementKind {
    /// A value (class, count, flag, point) differs.
    Mismatch,
    /// An exact answer has no float answer within the tolerance.
    Missed,
    /// A float answer has no exact counterpart.
    Spurious,
    /// A second float answer for an exact answer already matched.
    Duplicate,
}

impl DisagreementKind {
    /// `mismatch`, `missed`, `spurious` or `duplicate`.
    pub fn as_str(self) -> &'static str {
        match self {
            DisagreementKind::Mismatch => "mismatch",
            DisagreementKind::Missed => "missed",
            DisagreementKind::Spurious => "spurious",
            DisagreementKind::Duplicate => "duplicate",
        }
    }
}

impl serde::Serialize for DisagreementKind {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.serialize_str(self.as_str())
    }
}

/// A float library's value in a disagreement, as it is written in JSON (untagged: `null`,
/// `true`, `3`, `0.5`, `"arch"`, `[0.4, 1.2]`). [`Display`](fmt::Display) writes the same JSON
/// text a serializer does: numbers as the shortest text that reads back to the same `f64`
/// (`1.0`, `0.11`, `1e-7`, `1e+16`), non-finite numbers as `null`, text quoted and escaped.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(untagged)]
pub enum FloatValue {
    /// No value: nothing answered (a missed parameter), or "none" (no node type).
    Null,
    /// A flag (`loop`, `cusp`).
    Bool(bool),
    /// A count (`inflections`).
    Count(usize),
    /// A number (a parameter).
    Number(f64),
    /// Text (a class name, or a non-finite parameter written out: `NaN`, `inf`).
    Text(String),
    /// Numbers (a point's coordinates).
    List(Vec<f64>),
}

impl From<bool> for FloatValue {
    fn from(b: bool) -> Self {
        FloatValue::Bool(b)
    }
}

impl From<usize> for FloatValue {
    fn from(n: usize) -> Self {
        FloatValue::Count(n)
    }
}

impl From<f64> for FloatValue {
    fn from(x: f64) -> Self {
        FloatValue::Number(x)
    }
}

impl From<&str> for FloatValue {
    fn from(s: &str) -> Self {
        FloatValue::Text(s.to_owned())
    }
}

impl From<Option<&str>> for FloatValue {
    fn from(s: Option<&str>) -> Self {
        s.map_or(FloatValue::Null, FloatValue::from)
    }
}

impl From<[f64; 2]> for FloatValue {
    fn from(p: [f64; 2]) -> Self {
        FloatValue::List(p.to_vec())
    }
}

impl fmt::Display for FloatValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FloatValue::Null => f.write_str("null"),
            FloatValue::Bool(b) => write!(f, "{b}"),
            FloatValue::Count(n) => write!(f, "{n}"),
            FloatValue::Number(x) => write_json_number(f, *x),
            FloatValue::Text(s) => write_json_string(f, s),
            FloatValue::List(xs) => {
                f.write_str("[")?;
                for (i, x) in xs.iter().enumerate() {
                    if i > 0 {
                        f.write_str(",")?;
                    }
                    write_json_number(f, *x)?;
                }
                f.write_str("]")
            }
        }
    }
}

/// An `f64` as serde_json writes it: `null` unless finite; else the shortest digits that read
/// back to `x` (the nearest such to `x`, a tie to an even last digit), in positional notation
/// with at least one fractional digit (`1.0`, `0.00001`) when the decimal exponent is in
/// `−5..=15`, in scientific notation otherwise (`1e-7`, `1.5e+16`) — the format of serde_json's
/// `zmij` (Schubfach; Ryū's but for the `+`).
fn write_json_number(f: &mut fmt::Formatter<'_>, x: f64) -> fmt::Result {
    if !x.is_finite() {
        return f.write_str("null");
    }
    let (digits, exponent) = shortest_digits(x.abs());
    let sign = if x.is_sign_negative() { "-" } else { "" };
    let n = digits.len() as i32;
    if (-5..=15).contains(&exponent) {
        if exponent < 0 {
            write!(f, "{sign}0.{}{digits}", "0".repeat((-exponent - 1) as usize))
        } else if n <= exponent + 1 {
            write!(f, "{sign}{digits}{}.0", "0".repeat((exponent + 1 - n) as usize))
        } else {
            let (int, frac) = digits.split_at(exponent as usize + 1);
            write!(f, "{sign}{int}.{frac}")
        }
    } else {
        let (first, rest) = digits.split_at(1);
        let dot = if rest.is_empty() { "" } else { "." };
        let plus = if exponent >= 0 { "+" } else { "" };
        write!(f, "{sign}{first}{dot}{rest}e{plus}{exponent}")
    }
}

/// The shortest decimal digits `d₁d₂…dₙ` (no trailing zeros) and exponent `e` with
/// `d₁.d₂…dₙ × 10^e` reading back to `x` (finite, `≥ 0`), the nearest such to `x` and a tie to
/// an even last digit. Rust's `{:e}` writes shortest digits but may break a tie upwards; the
/// neighbours with as many digits are checked exactly.
fn shortest_digits(x: f64) -> (String, i32) {
    let sci = format!("{x:e}");
    let (mantissa, exponent) = sci.split_once('e').expect("`{:e}` writes an exponent");
    let exponent: i32 = exponent.parse().expect("an integer exponent");
    let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    let n = digits.len();
    let Ok(m) = digits.parse::<u64>() else { return (digits, exponent) };
    let exact = BigRational::from_float(x).expect("finite");
    let scale = exponent - (n as i32 - 1);
    let value = |c: u64| {
        let ten = BigRational::from_integer(10.into());
        let p = num_traits::pow(ten, scale.unsigned_abs() as usize);
        let c = BigRational::from_integer(c.into());
        if scale >= 0 { c * p } else { c / p }
    };
    let distance = |c: u64| {
        let d = value(c) - &exact;
        if d < BigRational::from_integer(0.into()) { -d } else { d }
    };
    let best = [m.wrapping_sub(1), m + 1]
        .into_iter()
        .filter(|&c| c.to_string().len() == n && format!("{c}e{scale}").parse::<f64>() == Ok(x))
        .fold(m, |best, c| match distance(c).cmp(&distance(best)) {
            std::cmp::Ordering::Less => c,
            std::cmp::Ordering::Equal if c % 2 == 0 => c,
            _ => best,
        });
    if best == m {
        return (digits, exponent);
    }
    let digits = best.to_string();
    (digits.trim_end_matches('0').to_owned(), exponent)
}

/// A JSON string: quoted, with `"`, `\` and control characters escaped.
fn write_json_string(f: &mut fmt::Formatter<'_>, s: &str) -> fmt::Result {
    f.write_str("\"")?;
    for c in s.chars() {
        match c {
            '"' => f.write_str("\\\"")?,
            '\\' => f.write_str("\\\\")?,
            '\n' => f.write_str("\\n")?,
            '\r' => f.write_str("\\r")?,
            '\t' => f.write_str("\\t")?,
            '\u{8}' => f.write_str("\\b")?,
            '\u{c}' => f.write_str("\\f")?,
            c if (c as u32) < 0x20 => write!(f, "\\u{:04x}", c as u32)?,
            c => write!(f, "{c}")?,
        }
    }
    f.write_str("\"")
}

/// A tolerance is finite and `≥ 0`.
pub(crate) fn check_tolerance(tol: f64) -> Result<()> {
    if tol.is_finite() && tol >= 0.0 {
        Ok(())
    } else {
        Err(Error::InvalidArgument { message: format!("tolerance {tol} must be finite and ≥ 0") })
    }
}

/// A planar curve with `f64` control points, each taken exactly; `not_finite` words the error
/// for a non-finite coordinate.
pub(crate) fn exact_curve(points: &[[f64; 2]], not_finite: impl Fn(f64) -> String) -> Result<BezierCurve<BigRational>> {
    let exact = |x: f64| BigRational::from_float(x).ok_or_else(|| Error::InvalidArgument { message: not_finite(x) });
    let pts = points.iter().map(|p| Ok(Point::new(vec![exact(p[0])?, exact(p[1])?]))).collect::<Result<Vec<_>>>()?;
    BezierCurve::new(pts)
}

/// The exact values a float answer stands for: the closed window `[lo, hi]` around it.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Window {
    /// `p − tol`.
    pub(crate) lo: BigRational,
    /// `p + tol`.
    pub(crate) hi: BigRational,
}

impl Window {
    /// `[p − tol, p + tol]`.
    pub(crate) fn around(p: &BigRational, tol: &BigRational) -> Self {
        Window { lo: p - tol, hi: p + tol }
    }

    /// [`Window::around`] with `tol` never tighter than the spacing of `f64`s at `p` (one ulp),
    /// so the correctly rounded exact answer always agrees: a coordinate near 2·10⁷ cannot be
    /// written within 1e-9 in binary64.
    pub(crate) fn at_least_one_ulp(p: &BigRational, tol: f64) -> Self {
        let f = crate::num::scalar::ratio_to_f64(p).abs();
        let ulp = if f.is_finite() { f.next_up() - f } else { 0.0 };
        Window::around(p, &BigRational::from_float(tol.max(ulp)).expect("finite tolerance"))
    }

    /// The window holds the exact value `e`, given `compare(x)`, the order of `e` against `x`.
    pub(crate) fn holds(&self, compare: impl Fn(&BigRational) -> std::cmp::Ordering) -> bool {
        compare(&self.lo).is_ge() && compare(&self.hi).is_le()
    }
}

/// A float answer that took no exact value (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Unmatched {
    /// Near only exact values already taken: the first of them.
    Duplicate(usize),
    /// Near no exact value.
    Spurious,
}

/// The floats that took no exact value, in order, and the exact values (indices below `exact`)
/// that no float took: the matching of the module documentation, `near(i, x)` saying whether
/// the float `x` is near the exact value `i`.
pub(crate) fn match_floats<F>(
    exact: usize,
    floats: impl IntoIterator<Item = F>,
    mut near: impl FnMut(usize, &F) -> bool,
) -> (Vec<(F, Unmatched)>, Vec<usize>) {
    let mut taken = vec![false; exact];
    let mut unmatched = vec![];
    for x in floats {
        if let Some(i) = (0..exact).filter(|&i| !taken[i]).find(|&i| near(i, &x)) {
            taken[i] = true;
            continue;
        }
        match (0..exact).filter(|&i| taken[i]).find(|&i| near(i, &x)) {
            Some(i) => unmatched.push((x, Unmatched::Duplicate(i))),
            None => unmatched.push((x, Unmatched::Spurious)),
        }
    }
    let missed = (0..exact).filter(|&i| !taken[i]).collect();
    (unmatched, missed)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every value's text is the JSON a serializer writes (the `check` command prints it, and
    /// writes it with `--json`): numbers over the whole binary64 range, at the notation's
    /// boundaries, and text with characters to escape.
    #[test]
    fn float_value_display_is_serialized_json() {
        let mut next = crate::num::symmetric(0x0F10_A7DA_7A5E_ED11);
        let mut values: Vec<FloatValue> = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.5,
            0.11,
            1e-5,
            1e-6,
            1.5e-5,
            9.99e-6,
            1e15,
            1e16,
            9.5e15,
            1.5e16,
            123456789.0,
            0.8872983346207417,
            1085043278225696.2,
            1e-7,
            1e300,
            5e-324,
            f64::MAX,
            f64::MIN_POSITIVE,
            f64::NAN,
            f64::INFINITY,
        ]
        .into_iter()
        .map(FloatValue::Number)
        .collect();
        for _ in 0..8_000 {
            let bits = ((next(1 << 31) as u64) << 33) ^ ((next(1 << 31) as u64) << 2) ^ next(4).unsigned_abs();
            values.push(FloatValue::Number(f64::from_bits(bits)));
            let scale = 10f64.powi(next(20) as i32);
            values.push(FloatValue::Number(next(1 << 30) as f64 / scale));
        }
        values.extend([
            FloatValue::Null,
            FloatValue::Bool(true),
            FloatValue::Count(3),
            FloatValue::List(vec![0.4, 1.2, f64::NAN]),
            FloatValue::List(vec![]),
            FloatValue::Text("arch \"quoted\" \\ \n\t\r\u{8}\u{c}\u{1}\u{1f}\u{7f} é ∞".into()),
        ]);
        for v in &values {
            assert_eq!(v.to_string(), serde_json::to_string(v).unwrap(), "{v:?}");
        }
    }

    /// A value reads back from its JSON as itself (integers as counts, other numbers as numbers).
    #[test]
    fn float_value_reads_back_from_json() {
        for v in [
            FloatValue::Null,
            FloatValue::Bool(false),
            FloatValue::Count(2),
            FloatValue::Number(0.25),
            FloatValue::Text("cusp".into()),
            FloatValue::List(vec![1.5, -2.0]),
        ] {
            assert_eq!(serde_json::from_str::<FloatValue>(&v.to_string()).unwrap(), v);
        }
    }

    /// Floats take exact values in order; a second float near a taken value is its duplicate.
    #[test]
    fn matching_takes_first_free_exact_value() {
        let exact = [0.25, 0.5, 0.75];
        let near = |i: usize, x: &f64| (exact[i] - x).abs() <= 0.1;
        let (unmatched, missed) = match_floats(3, [0.26, 0.24, 0.9, 0.49, 0.51], near);
        let expected =
            vec![(0.24, Unmatched::Duplicate(0)), (0.9, Unmatched::Spurious), (0.51, Unmatched::Duplicate(1))];
        assert_eq!((unmatched, missed), (expected, vec![2]));
        let (unmatched, missed) = match_floats(3, [2.0], near);
        assert_eq!((unmatched, missed), (vec![(2.0, Unmatched::Spurious)], vec![0, 1, 2]));
    }
}
