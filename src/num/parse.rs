//! Exact numbers and control polygons from text.
//!
//! Numbers: an optional sign, then an integer (`-3`), a fraction (`-7/12`), a decimal with an
//! optional exponent (`0.125`, `.5`, `1.5e-3`, `2E3`), or a hexadecimal float with a binary
//! exponent (`0x1.8p-3` = 3/16, `-0x1p-1074`, the smallest subnormal, as C's `%a` and Rust's
//! hexf write them). Decimals are exact: `0.1` is `1/10`. Rejected, with the token and its
//! position: `nan`, `inf`, `1/0`, `1//2`, `0x10` (a hex float needs its `p` exponent), `1/-2`,
//! empty tokens, tokens longer than [`MAX_TOKEN_LEN`] characters and exponents beyond
//! ±[`MAX_EXPONENT`] (decimal) or ±[`MAX_BINARY_EXPONENT`] (hex).
//!
//! [`NumberMode::Binary64`] reads every number as the IEEE-754 binary64 value nearest to it
//! (ties to even, as Rust's `f64` parser and C's `strtod` round), taken exactly: the number a float
//! program holds after reading the same text. `0.1` is then
//! `3602879701896397/36028797018963968`, not `1/10`; `0x1.8p-3`, `0.5` and integers up to 2^53
//! are binary64 values already and stay as they are.
//!
//! Curves: numbers separated by whitespace and/or commas. When commas separate groups of
//! several numbers (`"x0 y0, x1 y1"`), each group is one point and must have `dim` numbers;
//! otherwise the numbers are read `dim` at a time.

use crate::error::{Error, Position, Result};
use crate::num::point::Point;
use crate::num::scalar::Scalar;
use crate::num::small::SmallRational;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Pow, Zero};

/// Longest accepted number token, in characters.
pub(crate) const MAX_TOKEN_LEN: usize = 1000;
/// Largest accepted decimal exponent magnitude (`1e1000` is accepted, `1e1001` is not).
pub(crate) const MAX_EXPONENT: u32 = 1000;
/// Largest accepted binary exponent magnitude of a hex float (binary64 needs ±1074).
pub(crate) const MAX_BINARY_EXPONENT: u32 = 16384;

/// How numbers in text are read.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum NumberMode {
    /// Every number is the exact rational it spells (`0.1` = 1/10).
    #[default]
    Exact,
    /// Every number is the binary64 value nearest to it, exactly (`0.1` = 3602879701896397/2^55).
    Binary64,
}

/// [`parse_number`] in a [`NumberMode`].
///
/// # Errors
/// As [`parse_number`]; in binary64 mode also a number beyond the binary64 range (it would round
/// to infinity).
///
/// # Example
/// ```
/// use casteljau::num::{NumberMode, parse_number_in};
/// let p = Default::default();
/// let x = parse_number_in("0.1", p, NumberMode::Binary64).unwrap();
/// assert_eq!(x.to_string(), "3602879701896397/36028797018963968"); // the f64 0.1, exactly
/// assert_eq!(parse_number_in("0.1", p, NumberMode::Exact).unwrap().to_string(), "1/10");
/// assert!(parse_number_in("1e309", p, NumberMode::Binary64).is_err());
/// ```
pub fn parse_number_in(token: &str, position: Position, mode: NumberMode) -> Result<BigRational> {
    let r = parse_number(token, position)?;
    match mode {
        NumberMode::Exact => Ok(r),
        NumberMode::Binary64 => {
            let f = crate::num::scalar::ratio_to_f64(&r);
            if !f.is_finite() {
                return Err(Error::ParseNumber {
                    token: token.chars().take(40).collect(),
                    position,
                    reason: "beyond the binary64 range (it rounds to infinity)".into(),
                });
            }
            Ok(BigRational::from_float(f).expect("finite floats are ratios"))
        }
    }
}

/// Parses one exact number.
///
/// # Errors
/// [`Error::ParseNumber`] naming the token, `position` and the reason.
///
/// # Example
/// ```
/// use casteljau::num::parse_number;
/// let p = Default::default();
/// assert_eq!(parse_number("1.5e-3", p).unwrap().to_string(), "3/2000");
/// assert_eq!(parse_number("-14/12", p).unwrap().to_string(), "-7/6");
/// assert!(parse_number("1/0", p).is_err());
/// ```
pub fn parse_number(token: &str, position: Position) -> Result<BigRational> {
    let fail = |reason: &str| {
        let shown: String = if token.chars().count() > 40 {
            token.chars().take(37).chain("...".chars()).collect()
        } else {
            token.to_string()
        };
        Error::ParseNumber { token: shown, position, reason: reason.to_string() }
    };
    if token.is_empty() {
        return Err(fail("empty number"));
    }
    if token.chars().count() > MAX_TOKEN_LEN {
        return Err(fail(&format!("longer than {MAX_TOKEN_LEN} characters")));
    }
    let (negative, body) = match token.as_bytes()[0] {
        b'-' => (true, &token[1..]),
        b'+' => (false, &token[1..]),
        _ => (false, token),
    };
    let value = if body.starts_with("0x") || body.starts_with("0X") {
        parse_hex_float(&body[2..]).map_err(fail)?
    } else if let Some((num, den)) = body.split_once('/') {
        let n = digits(num).ok_or_else(|| fail("numerator is not a plain integer"))?;
        let d = digits(den).ok_or_else(|| fail("denominator is not a plain positive integer"))?;
        if d.is_zero() {
            return Err(fail("zero denominator"));
        }
        BigRational::new(n, d)
    } else {
        parse_decimal(body).map_err(fail)?
    };
    Ok(if negative { -value } else { value })
}

/// `h[.h]p[±]d` after `0x`: hex digits with an optional point, then a decimal binary exponent.
fn parse_hex_float(s: &str) -> std::result::Result<BigRational, &'static str> {
    let (mantissa, exponent) = s.split_once(['p', 'P']).ok_or("a hex float needs a binary exponent (0x1.8p-3)")?;
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    if int.is_empty() && frac.is_empty() {
        return Err("a hex float needs hex digits");
    }
    if !int.bytes().chain(frac.bytes()).all(|b| b.is_ascii_hexdigit()) {
        return Err("not a hex float (hex digits, then p and the exponent)");
    }
    let exp = match signed_exponent(exponent, MAX_BINARY_EXPONENT) {
        Ok(e) => e,
        Err(Exponent::Malformed) => return Err("malformed binary exponent"),
        Err(Exponent::TooLarge) => return Err("binary exponent too large (limit ±16384)"),
    };
    let digits = format!("{int}{frac}");
    let n = BigInt::parse_bytes(digits.as_bytes(), 16).ok_or("not a hex float")?;
    // each hex digit after the point is 4 bits
    let shift = exp - 4 * frac.len() as i64;
    Ok(if shift >= 0 {
        BigRational::from_integer(n << shift as usize)
    } else {
        BigRational::new(n, BigInt::from(1) << (-shift) as usize)
    })
}

/// Why an exponent was refused.
enum Exponent {
    Malformed,
    TooLarge,
}

/// `[±]digits` with magnitude at most `limit` (the exponent of a decimal or of a hex float).
fn signed_exponent(e: &str, limit: u32) -> std::result::Result<i64, Exponent> {
    let (negative, digits) = match e.as_bytes().first() {
        Some(b'-') => (true, &e[1..]),
        Some(b'+') => (false, &e[1..]),
        _ => (false, e),
    };
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return Err(Exponent::Malformed);
    }
    match digits.parse::<u32>() {
        Ok(m) if m <= limit => Ok(if negative { -(m as i64) } else { m as i64 }),
        _ => Err(Exponent::TooLarge),
    }
}

/// A non-empty run of ASCII digits.
fn digits(s: &str) -> Option<BigInt> {
    if s.is_empty() || !s.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    s.parse().ok()
}

/// `int[.frac][e[±]exp]` with at least one digit in `int` or `frac`.
fn parse_decimal(s: &str) -> std::result::Result<BigRational, &'static str> {
    let (mantissa, exponent) = match s.find(['e', 'E']) {
        Some(i) => (&s[..i], Some(&s[i + 1..])),
        None => (s, None),
    };
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    if int.is_empty() && frac.is_empty() {
        return Err(if s.is_empty() { "sign without digits" } else { "not a number" });
    }
    if !int.bytes().all(|b| b.is_ascii_digit()) || !frac.bytes().all(|b| b.is_ascii_digit()) {
        return Err("not an exact number (use integers, p/q or decimals)");
    }
    let exp = match exponent.map(|e| signed_exponent(e, MAX_EXPONENT)) {
        None => 0,
        Some(Ok(e)) => e,
        Some(Err(Exponent::Malformed)) => return Err("malformed exponent"),
        Some(Err(Exponent::TooLarge)) => return Err("exponent too large (limit ±1000)"),
    };
    let all_digits = format!("{int}{frac}");
    let n: BigInt = all_digits.parse().map_err(|_| "not a number")?;
    let scale = exp - frac.len() as i64;
    let ten = BigInt::from(10u32);
    Ok(if scale >= 0 {
        BigRational::from_integer(n * Pow::pow(&ten, scale as u64))
    } else {
        BigRational::new(n, Pow::pow(&ten, (-scale) as u64))
    })
}

/// A number token with its column and the separator seen before it.
struct Token<'a> {
    text: &'a str,
    column: usize,
    after_comma: bool,
}

/// Splits on whitespace and commas; `Err(column)` at a comma with no number before it.
fn tokens(text: &str) -> std::result::Result<Vec<Token<'_>>, (usize, usize)> {
    let mut out = Vec::new();
    let mut start: Option<(usize, usize)> = None; // byte offset, column
    let mut comma = false;
    let mut column = 0;
    for (i, c) in text.char_indices() {
        column += 1;
        let sep = c.is_whitespace() || c == ',';
        match (sep, start) {
            (true, Some((s, col))) => {
                out.push(Token { text: &text[s..i], column: col, after_comma: comma });
                comma = false;
                start = None;
            }
            (false, None) => start = Some((i, column)),
            _ => {}
        }
        if c == ',' {
            if comma || out.is_empty() {
                return Err((column, out.len() + 1));
            }
            comma = true;
        }
    }
    // one trailing comma ("0 0, 1 1,") is accepted, as spreadsheets and generators write it
    if let Some((s, col)) = start {
        out.push(Token { text: &text[s..], column: col, after_comma: comma });
    }
    Ok(out)
}

/// Parses a control polygon of `dim`-dimensional points.
///
/// `line` is the 1-based line number for batch input (it appears in errors).
///
/// # Errors
/// [`Error::ParseNumber`] for a bad token, [`Error::PointCount`] when the numbers do not form
/// `dim`-dimensional points, [`Error::EmptyCurve`] for no numbers at all.
///
/// # Example
/// ```
/// use casteljau::num::parse_points;
/// let pts = parse_points("-1 -1, -1/3 1, 1/3 -1, 1 1", 2, None).unwrap();
/// assert_eq!(pts.len(), 4);
/// assert_eq!(pts[1].to_string(), "(-1/3, 1)");
/// assert!(parse_points("0 0, 1", 2, None).is_err());
/// ```
pub fn parse_points(text: &str, dim: usize, line: Option<usize>) -> Result<Vec<Point<BigRational>>> {
    parse_points_in(text, dim, line, NumberMode::Exact)
}

/// [`parse_points`] in a [`NumberMode`].
///
/// # Errors
/// As [`parse_points`] and [`parse_number_in`].
pub fn parse_points_in(
    text: &str,
    dim: usize,
    line: Option<usize>,
    mode: NumberMode,
) -> Result<Vec<Point<BigRational>>> {
    let toks = tokens(text).map_err(|(column, token)| Error::ParseNumber {
        token: String::new(),
        position: Position { line, column, token },
        reason: "empty number between commas".to_string(),
    })?;
    if toks.is_empty() {
        return Err(Error::EmptyCurve { line });
    }
    let mut values = Vec::with_capacity(toks.len());
    for (k, t) in toks.iter().enumerate() {
        let position = Position { line, column: t.column, token: k + 1 };
        values.push(parse_number_in(t.text, position, mode)?);
    }
    group_points(&toks, values, dim, line)
}

/// The points of a parsed token list: comma groups of `dim` numbers when commas separate
/// groups of several numbers (`"x0 y0, x1 y1"`), otherwise `dim` numbers at a time.
fn group_points<T: Scalar>(
    toks: &[Token<'_>],
    values: Vec<T>,
    dim: usize,
    line: Option<usize>,
) -> Result<Vec<Point<T>>> {
    let mut groups: Vec<usize> = Vec::new();
    for t in toks {
        if t.after_comma || groups.is_empty() {
            groups.push(0);
        }
        *groups.last_mut().unwrap() += 1;
    }
    let grouped = groups.len() > 1 && groups.iter().any(|&g| g > 1);
    if grouped {
        if let Some((p, &found)) = groups.iter().enumerate().find(|(_, g)| **g != dim) {
            return Err(Error::PointCount { found, dim, point: Some(p + 1), line });
        }
    } else if !values.len().is_multiple_of(dim) {
        return Err(Error::PointCount { found: values.len(), dim, point: None, line });
    }
    let mut it = values.into_iter();
    let n = toks.len() / dim;
    Ok((0..n).map(|_| Point::new(it.by_ref().take(dim).collect())).collect())
}

/// [`parse_points`] on the fast route: the same points as fixed-width [`SmallRational`]s when
/// every token is an integer, a fraction `p/q` or a decimal without exponent of at most 36
/// digits per part; `None` otherwise — for anything else, including every malformed input,
/// which [`parse_points`] then reads or reports. No allocation per number.
///
/// # Example
/// ```
/// use casteljau::{internal::parse_points_small, num::parse_points};
/// let small = parse_points_small("0 0, 1.25 -7/3", 2, None).unwrap();
/// let big = parse_points("0 0, 1.25 -7/3", 2, None).unwrap();
/// assert_eq!(small[1].coords[0].to_big(), big[1].coords[0]);
/// assert!(parse_points_small("1e3 0", 2, None).is_none()); // exponent: the exact route reads it
/// assert!(parse_points_small("0 0, 1", 2, None).is_none()); // malformed: the exact route reports it
/// ```
pub fn parse_points_small(text: &str, dim: usize, line: Option<usize>) -> Option<Vec<Point<SmallRational>>> {
    parse_points_small_in(text, dim, line, NumberMode::Exact)
}

/// [`parse_points_small`] in a [`NumberMode`]: in binary64 mode only numbers that are binary64
/// values already (a power-of-two denominator and a numerator of at most 53 bits) take the fast
/// route; the rest are rounded by [`parse_points_in`].
pub fn parse_points_small_in(
    text: &str,
    dim: usize,
    line: Option<usize>,
    mode: NumberMode,
) -> Option<Vec<Point<SmallRational>>> {
    let toks = tokens(text).ok()?;
    if toks.is_empty() {
        return None;
    }
    let exact_binary64 = |x: &SmallRational| {
        (x.denom() as u128).is_power_of_two() && x.numer().unsigned_abs() <= 1 << 53 && x.denom() <= 1 << 100
    };
    let values = toks
        .iter()
        .map(|t| small_number(t.text).filter(|x| mode == NumberMode::Exact || exact_binary64(x)))
        .collect::<Option<Vec<_>>>()?;
    group_points(&toks, values, dim, line).ok()
}

/// Skips blanks, at most one comma and blanks from `i`; whether there was a comma.
fn skip_separator(b: &[u8], i: &mut usize) -> bool {
    let blank = |c: u8| c == b' ' || c == b'\t';
    while *i < b.len() && blank(b[*i]) {
        *i += 1;
    }
    if *i < b.len() && b[*i] == b',' {
        *i += 1;
        while *i < b.len() && blank(b[*i]) {
            *i += 1;
        }
        return true;
    }
    false
}

/// Eight numbers with `commas[k]` after number `k` form four points as `group_points` reads
/// them: commas after points, none, or after every number.
fn four_points(commas: &[bool; 8]) -> bool {
    let inner = [commas[0], commas[2], commas[4], commas[6]];
    let between = [commas[1], commas[3], commas[5]];
    let grouped = inner.iter().all(|c| !c) && between.iter().all(|&c| c);
    grouped || commas[..7].iter().all(|c| !c) || commas[..7].iter().all(|&c| c)
}

/// The eight number tokens of a planar cubic written `x y, x y, x y, x y` (or separated by
/// spaces only, or by commas only; spaces and tabs, an optional trailing comma): what
/// [`parse_points`] groups into four points, or `None` for any other layout. Allocates nothing.
fn eight_tokens(text: &str) -> Option<[&str; 8]> {
    let b = text.as_bytes();
    let mut tokens = [""; 8];
    // commas[k]: a comma between token k and token k + 1
    let mut commas = [false; 8];
    let blank = |c: u8| c == b' ' || c == b'\t';
    let mut i = 0;
    while i < b.len() && blank(b[i]) {
        i += 1;
    }
    for k in 0..8 {
        let start = i;
        while i < b.len() && !blank(b[i]) && b[i] != b',' {
            i += 1;
        }
        if i == start {
            return None;
        }
        tokens[k] = &text[start..i];
        commas[k] = skip_separator(b, &mut i);
    }
    (i == b.len() && four_points(&commas)).then_some(tokens)
}

/// The planar cubic of a batch line written with plain integers, the common case of font
/// data: `x y, x y, x y, x y` (or the eight numbers separated by spaces only, or by commas
/// only; spaces and tabs, an optional trailing comma), each `[+-]?` and at most 18 digits.
/// The points [`parse_points`] reads from such a line; `None` for anything else (which
/// [`parse_points`] then reads or reports). Allocates nothing.
///
/// # Example
/// ```
/// use casteljau::internal::integer_cubic;
/// assert_eq!(integer_cubic("0 0, 1 -2, +3 4, 5 6"), Some([[0, 0], [1, -2], [3, 4], [5, 6]]));
/// assert_eq!(integer_cubic("0,0,1,2,3,4,5,6,"), Some([[0, 0], [1, 2], [3, 4], [5, 6]]));
/// assert_eq!(integer_cubic("0 0, 1/2 2, 3 4, 5 6"), None); // a fraction: parse_points reads it
/// assert_eq!(integer_cubic("0 0 1, 2 3 4, 5 6"), None); // grouped wrongly: parse_points reports it
/// ```
pub fn integer_cubic(text: &str) -> Option<[[i64; 2]; 4]> {
    let b = text.as_bytes();
    let mut values = [0i64; 8];
    // commas[k]: a comma between value k and value k + 1
    let mut commas = [false; 8];
    let (mut i, mut k) = (0, 0);
    let blank = |c: u8| c == b' ' || c == b'\t';
    while i < b.len() && blank(b[i]) {
        i += 1;
    }
    while k < 8 {
        let negative = match b.get(i)? {
            b'-' => {
                i += 1;
                true
            }
            b'+' => {
                i += 1;
                false
            }
            _ => false,
        };
        let start = i;
        let mut v: i64 = 0;
        while i < b.len() && b[i].is_ascii_digit() {
            // 18 digits always fit an i64; a 19th could overflow the product: not this route
            if i - start == 18 {
                return None;
            }
            v = v * 10 + i64::from(b[i] - b'0');
            i += 1;
        }
        if i == start {
            return None;
        }
        values[k] = if negative { -v } else { v };
        let sep_start = i;
        commas[k] = skip_separator(b, &mut i);
        k += 1;
        if i == sep_start && i < b.len() {
            return None; // a number runs into something else
        }
    }
    if i != b.len() || !four_points(&commas) {
        return None;
    }
    Some([[values[0], values[1]], [values[2], values[3]], [values[4], values[5]], [values[6], values[7]]])
}

/// [`integer_cubic`] for numbers that fit [`SmallRational`]: integers, `p/q` and decimals
/// without exponent as [`parse_points_small_in`] reads them (in binary64 mode only values that
/// are binary64 already). `None` for anything else. Allocates nothing.
///
/// # Example
/// ```
/// use casteljau::{internal::small_cubic, num::NumberMode};
/// let p = small_cubic("0 0, 1/2 -2.5, 3 4, 5 6", NumberMode::Exact).unwrap();
/// assert_eq!(p[1][1].to_string(), "-5/2");
/// assert!(small_cubic("0 0, 0.1 0, 1 1, 2 2", NumberMode::Binary64).is_none()); // 0.1 rounds
/// ```
pub fn small_cubic(text: &str, mode: NumberMode) -> Option<[[SmallRational; 2]; 4]> {
    let t = eight_tokens(text)?;
    let exact_binary64 = |x: &SmallRational| {
        (x.denom() as u128).is_power_of_two() && x.numer().unsigned_abs() <= 1 << 53 && x.denom() <= 1 << 100
    };
    let v = |s: &str| small_number(s).filter(|x| mode == NumberMode::Exact || exact_binary64(x));
    Some([[v(t[0])?, v(t[1])?], [v(t[2])?, v(t[3])?], [v(t[4])?, v(t[5])?], [v(t[6])?, v(t[7])?]])
}

/// Largest digit count per part that [`small_number`] takes (`10^36 < 2^120`).
const SMALL_DIGITS: usize = 36;

/// An integer, `p/q` or decimal without exponent that fits: the value [`parse_number`] gives.
fn small_number(token: &str) -> Option<SmallRational> {
    let b = token.as_bytes();
    let (negative, body) = match b.first()? {
        b'-' => (true, &b[1..]),
        b'+' => (false, &b[1..]),
        _ => (false, b),
    };
    let run = |s: &[u8]| -> Option<i128> {
        if s.len() > SMALL_DIGITS || !s.iter().all(u8::is_ascii_digit) {
            return None;
        }
        Some(s.iter().fold(0i128, |v, &d| v * 10 + (d - b'0') as i128))
    };
    let (num, den) = if let Some(i) = body.iter().position(|&c| c == b'/') {
        let (p, q) = (&body[..i], &body[i + 1..]);
        if p.is_empty() || q.is_empty() {
            return None;
        }
        (run(p)?, run(q)?)
    } else {
        let (int, frac) = match body.iter().position(|&c| c == b'.') {
            Some(i) => (&body[..i], &body[i + 1..]),
            None => (body, &b""[..]),
        };
        if int.is_empty() && frac.is_empty() || int.len() + frac.len() > SMALL_DIGITS {
            return None;
        }
        let n = run(int)?.checked_mul(10i128.checked_pow(frac.len() as u32)?)?.checked_add(run(frac)?)?;
        (n, 10i128.pow(frac.len() as u32))
    };
    SmallRational::new(if negative { -num } else { num }, den)
}

/// A list of exact numbers separated by whitespace or commas (weights, scale ratios, knot
/// intervals): the one number-list reader of the crate.
///
/// # Errors
/// As [`parse_points`] with `dim = 1`: a bad token (named with its position), or no number.
///
/// # Example
/// ```
/// use casteljau::{num::parse_numbers, rat, ratio};
/// assert_eq!(parse_numbers("1, 1/2, 0.25").unwrap(), vec![rat(1), ratio(1, 2), ratio(1, 4)]);
/// assert_eq!(parse_numbers("1 1/2 0.25").unwrap(), parse_numbers("1, 1/2, 0.25").unwrap());
/// assert!(parse_numbers("1 x").is_err());
/// ```
pub fn parse_numbers(text: &str) -> Result<Vec<BigRational>> {
    Ok(parse_points(text, 1, None)?.into_iter().map(|p| p.coords.into_iter().next().expect("dimension 1")).collect())
}
