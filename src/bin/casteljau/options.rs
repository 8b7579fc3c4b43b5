//! Reading option values: exact numbers (`--t 1/3`, `--ratios "1 2 3"`) in a number mode,
//! `--weights`/`--homogeneous`, and a patch's `--degree m,n`. Errors name the option.

use crate::args::RationalArgs;
use casteljau::curve::BezierCurve;
use casteljau::error::{Error, Position, Result};
use casteljau::num::{NumberMode, parse_number_in, parse_numbers};
use casteljau::rational::RationalBezier;
use casteljau::surface::RationalPatch;
use num_rational::BigRational;

/// The numbers of an option such as `--ratios`, errors prefixed with the option's name.
pub fn numbers(option: &str, text: &str) -> Result<Vec<BigRational>> {
    numbers_in(option, text, NumberMode::Exact)
}

/// [`numbers`] in a number mode.
pub fn numbers_in(option: &str, text: &str, mode: NumberMode) -> Result<Vec<BigRational>> {
    let exact = parse_numbers(text).map_err(|e| Error::InvalidArgument { message: format!("{option}: {e}") })?;
    match mode {
        NumberMode::Exact => Ok(exact),
        // the same tokens again, each read as the f64 it rounds to
        NumberMode::Binary64 => text
            .split(|c: char| c.is_whitespace() || c == ',')
            .filter(|t| !t.is_empty())
            .enumerate()
            .map(|(k, t)| option_number_in(option, t, mode).map_err(|e| position_in(e, k + 1)))
            .collect(),
    }
}

fn position_in(e: Error, k: usize) -> Error {
    match e {
        Error::InvalidArgument { message } => Error::InvalidArgument { message: format!("{message} (number {k})") },
        other => other,
    }
}

/// The exact number of an option such as `--t` (errors name the option).
pub fn option_number(option: &str, s: &str) -> Result<BigRational> {
    option_number_in(option, s, NumberMode::Exact)
}

/// [`option_number`] in a number mode (`--numbers binary64`: the `f64` the token rounds to).
pub fn option_number_in(option: &str, s: &str, mode: NumberMode) -> Result<BigRational> {
    parse_number_in(s.trim(), Position { line: None, column: 1, token: 1 }, mode).map_err(|e| match e {
        Error::ParseNumber { token, reason, .. } => {
            Error::InvalidArgument { message: format!("{option}: bad number {token:?}: {reason}") }
        }
        other => other,
    })
}

/// `--weights`, parsed exactly (`None` without it); an error with `--homogeneous` as well.
pub fn parse_weights(args: &RationalArgs) -> Result<Option<Vec<BigRational>>> {
    parse_weights_in(args, NumberMode::Exact)
}

/// [`parse_weights`] in a number mode.
pub fn parse_weights_in(args: &RationalArgs, mode: NumberMode) -> Result<Option<Vec<BigRational>>> {
    if args.homogeneous && args.weights.is_some() {
        return Err(Error::InvalidArgument { message: "give --weights or --homogeneous, not both".into() });
    }
    let Some(w) = &args.weights else { return Ok(None) };
    numbers_in("--weights", w, mode).map(Some)
}

/// How a command's control points carry weights.
#[derive(Clone, Copy, Debug)]
pub enum Weights<'a> {
    /// A polynomial curve (all weights 1).
    Polynomial,
    /// `--weights`.
    Given(&'a [BigRational]),
    /// `--homogeneous`.
    Homogeneous,
}

/// The rational curve given by a parsed control polygon and its weights.
pub fn rational_curve(c: &BezierCurve<BigRational>, weights: Weights<'_>) -> Result<RationalBezier<BigRational>> {
    match weights {
        Weights::Polynomial => RationalBezier::new(c.points().to_vec(), vec![casteljau::rat(1); c.points().len()]),
        Weights::Given(w) => RationalBezier::new(c.points().to_vec(), w.to_vec()),
        Weights::Homogeneous => RationalBezier::from_homogeneous(c.points().to_vec()),
    }
}

/// `--degree m,n` of a patch.
pub fn patch_degree(degree: &str) -> Result<(usize, usize)> {
    degree
        .split_once(',')
        .and_then(|(a, b)| Some((a.trim().parse::<usize>().ok()?, b.trim().parse::<usize>().ok()?)))
        .ok_or_else(|| Error::InvalidArgument { message: format!("--degree must be \"m,n\", got {degree:?}") })
}

/// The patch of `--degree m,n` from a curve line of `(m+1)(n+1)` points, with `--weights` or
/// `--homogeneous`.
pub fn patch_of(c: &BezierCurve<BigRational>, degree: &str, rational: &RationalArgs) -> Result<RationalPatch> {
    let degree = patch_degree(degree)?;
    if rational.homogeneous {
        return RationalPatch::from_homogeneous_net(c.points(), degree);
    }
    match parse_weights(rational) {
        Ok(w) => RationalPatch::from_net(c.points(), degree, w.as_deref()),
        // a net of the wrong size is reported first
        Err(e) => RationalPatch::from_net(c.points(), degree, None).and(Err(e)),
    }
}

/// `--weights-family wI=a,b,c`: the index `I` of the weight that varies and its values.
pub fn weights_family(f: &str) -> Result<(usize, Vec<BigRational>)> {
    let (name, values) = f
        .split_once('=')
        .ok_or_else(|| Error::InvalidArgument { message: format!("--weights-family {f:?}: write w1=1,3,4") })?;
    let i: usize = name
        .trim()
        .trim_start_matches('w')
        .parse()
        .map_err(|_| Error::InvalidArgument { message: format!("--weights-family: bad index {name:?}") })?;
    Ok((i, numbers("--weights-family", values)?))
}
