//! The one error type of casteljau: every variant says what went wrong and where.

use std::fmt;

/// Where a token stands in the input: 1-based line (for batch input), 1-based character
/// column, and 1-based index of the number among the line's numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Position {
    /// 1-based line number, when the input has lines (batch files, stdin).
    pub line: Option<usize>,
    /// 1-based character column of the token's first character.
    pub column: usize,
    /// 1-based index of the token among the numbers of its line.
    pub token: usize,
}

impl fmt::Display for Position {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(line) = self.line {
            write!(f, "line {line}, ")?;
        }
        write!(f, "column {} (number {})", self.column, self.token)
    }
}

/// Everything that can go wrong in casteljau's library and CLI.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// A token is not an exact number (`1/3`, `-0.25`, `2E3` are; `nan`, `1/0`, `0x10` are not).
    ParseNumber {
        /// The offending token as written (shortened when very long).
        token: String,
        /// Where it stands.
        position: Position,
        /// Why it was rejected.
        reason: String,
    },
    /// A curve's numbers do not group into points of the expected dimension.
    PointCount {
        /// How many numbers (or coordinates of the offending point) were found.
        found: usize,
        /// The dimension expected (2 or 3, or as given by `--dim`).
        dim: usize,
        /// Which point is malformed (1-based), when the input groups points with commas.
        point: Option<usize>,
        /// The line, for batch input.
        line: Option<usize>,
    },
    /// A curve needs at least one control point.
    EmptyCurve {
        /// The line, for batch input.
        line: Option<usize>,
    },
    /// Control points of one curve (or curves combined) differ in dimension.
    DimensionMismatch {
        /// The dimension of the first point.
        expected: usize,
        /// The dimension found.
        found: usize,
    },
    /// A size beyond a documented limit (degree, depth, token length, exponent).
    TooLarge {
        /// What is too large.
        what: &'static str,
        /// The requested size.
        value: usize,
        /// The largest size allowed.
        limit: usize,
    },
    /// The denominator `Σ w_i B_i^n(t)` of a rational curve vanishes: at `t` when both ends are
    /// equal, otherwise somewhere in the isolating interval `(a, b)`.
    WeightsVanish {
        /// The exact ends `a`, `b` of the interval.
        interval: (String, String),
    },
    /// A malformed expression (proofs/ identities, `--poly`).
    Expression {
        /// The expression text.
        text: String,
        /// 1-based character column of the problem.
        column: usize,
        /// What is wrong.
        message: String,
    },
    /// A malformed claim file in `proofs/`.
    ClaimFile {
        /// The file.
        file: String,
        /// 1-based line, when known.
        line: Option<usize>,
        /// What is wrong.
        message: String,
    },
    /// The estimated work of an answer exceeds the budget (see [`crate::work`]).
    WorkLimit {
        /// What would be computed, with the sizes that drive the cost.
        what: String,
        /// The estimate, in work units (about 1 ns each on the reference machine).
        estimate: f64,
        /// The budget.
        limit: f64,
        /// The option that raises the budget.
        option: &'static str,
    },
    /// The weights do not match the control points one to one (a rational curve, spline,
    /// patch or net).
    ///
    /// ```
    /// use casteljau::{Error, Point, rat, RationalBezier};
    /// let pts = vec![Point::new(vec![rat(0), rat(0)]), Point::new(vec![rat(1), rat(1)])];
    /// let e = RationalBezier::new(pts, vec![rat(1)]).unwrap_err();
    /// assert_eq!(e, Error::WeightCount { weights: 1, points: 2, row: None });
    /// assert_eq!(e.to_string(), "1 weights for 2 control points");
    /// ```
    WeightCount {
        /// How many weights were given (in the row, for a patch or net).
        weights: usize,
        /// How many control points there are (in the row).
        points: usize,
        /// The row of a patch or net where the counts differ, 1-based; `None` for a curve or
        /// spline.
        row: Option<usize>,
    },
    /// A weight is 0 where finite control points are needed (a control point at infinity is
    /// given in homogeneous form instead).
    ///
    /// Positions are 1-based, like every position in this enum ([`Error::PointCount`]'s
    /// `point`, [`Position`]) and every "weight i" and "control point i" message of the
    /// command line: `index = 1` is the first weight, the seeds' `w0`.
    ///
    /// ```
    /// use casteljau::{Error, Point, rat, RationalBezier};
    /// let pts = vec![Point::new(vec![rat(0), rat(0)]), Point::new(vec![rat(1), rat(1)])];
    /// let e = RationalBezier::new(pts, vec![rat(1), rat(0)]).unwrap_err();
    /// assert_eq!(e, Error::ZeroWeight { index: 2, row: None });
    /// assert!(e.to_string().starts_with("weight 2 is 0: a control point at infinity"));
    /// ```
    ZeroWeight {
        /// Which weight (of its row, for a patch or net), 1-based.
        index: usize,
        /// The row of a patch or net, 1-based; `None` for a curve or spline.
        row: Option<usize>,
    },
    /// The input is degenerate for the operation: a curve that is a single point, coincident
    /// points where distinct ones are needed, a cubic of lower class than the operation needs,
    /// a construction whose ratio vanishes.
    ///
    /// ```
    /// use casteljau::{Budget, BezierCurve, Domain, Error, RationalBezier, parse_points, self_intersect};
    /// let c = RationalBezier::from(BezierCurve::new(parse_points("1 1, 1 1, 1 1", 2, None).unwrap()).unwrap());
    /// let e = self_intersect(&c, Domain::Unit, &Budget::unlimited()).unwrap_err();
    /// assert!(matches!(e, Error::Degenerate { .. }));
    /// assert_eq!(e.to_string(), "the curve is a single point");
    /// ```
    Degenerate {
        /// What is degenerate, in words.
        message: String,
    },
    /// A point at infinity where a finite one is needed (a zero weight reached through a
    /// construction, a homogeneous zero vector, a reference point at infinity).
    PointAtInfinity {
        /// Which point, in words.
        message: String,
    },
    /// The operation is defined for another kind of input: another dimension, degree or curve
    /// type (e.g. moving lines need a planar cubic; the seed's formula (53) is for quadratic
    /// splines).
    NotApplicable {
        /// What the operation takes, in words.
        message: String,
    },
    /// A parameter interval `[from, to]` outside `0 ≤ from < to ≤ 1`.
    ParameterInterval {
        /// The interval's start, exactly.
        from: String,
        /// Its end, exactly.
        to: String,
    },
    /// An argument outside the operation's domain (e.g. a derivative order above the degree),
    /// or a malformed option, where no variant above applies.
    InvalidArgument {
        /// What is wrong, in words.
        message: String,
    },
}

impl Error {
    /// The input line the error already names (batch input), if any.
    pub fn line(&self) -> Option<usize> {
        match self {
            Error::ParseNumber { position, .. } => position.line,
            Error::PointCount { line, .. } | Error::EmptyCurve { line } => *line,
            _ => None,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let at_line = |line: &Option<usize>| line.map(|l| format!("line {l}: ")).unwrap_or_default();
        match self {
            Error::ParseNumber { token, position, reason } => {
                write!(f, "bad number {token:?} at {position}: {reason}")
            }
            Error::PointCount { found, dim, point: Some(p), line } => write!(
                f,
                "{}point {p} has {found} coordinate{}, expected {dim}",
                at_line(line),
                if *found == 1 { "" } else { "s" }
            ),
            Error::PointCount { found, dim, point: None, line } => write!(
                f,
                "{}{found} number{} cannot be split into {dim}D points",
                at_line(line),
                if *found == 1 { "" } else { "s" }
            ),
            Error::EmptyCurve { line } => write!(f, "{}a curve needs at least one control point", at_line(line)),
            Error::DimensionMismatch { expected, found } => {
                write!(f, "points of dimension {expected} and {found} cannot be combined")
            }
            Error::TooLarge { what, value, limit } => write!(f, "{what} {value} exceeds the limit {limit}"),
            Error::InvalidArgument { message }
            | Error::Degenerate { message }
            | Error::PointAtInfinity { message }
            | Error::NotApplicable { message } => write!(f, "{message}"),
            Error::ParameterInterval { from, to } => write!(f, "need 0 <= from < to <= 1, got [{from}, {to}]"),
            Error::WorkLimit { what, estimate, limit, option } => {
                write!(f, "{what}: estimated work {estimate:.1e} exceeds the limit {limit:.1e}")?;
                if !option.is_empty() {
                    // a budget that admits this input: the estimate rounded up to one digit
                    let exp = estimate.log10().floor() as i32;
                    let mantissa = (estimate / 10f64.powi(exp)).ceil();
                    write!(f, " (about {:.0} s here; raise it with {option} {mantissa}e{exp})", estimate / 1e9)?;
                }
                Ok(())
            }
            // the texts without a row are those the command line has always printed (JSON
            // error lines are recorded byte for byte)
            Error::WeightCount { weights, points, row } => {
                if let Some(r) = row {
                    write!(f, "row {r}: ")?;
                }
                write!(f, "{weights} weights for {points} control points")
            }
            Error::ZeroWeight { index, row } => {
                write!(f, "weight {index} ")?;
                if let Some(r) = row {
                    write!(f, "of row {r} ")?;
                }
                write!(
                    f,
                    "is 0: a control point at infinity is given in homogeneous form (--homogeneous \"x y {}0\")",
                    if row.is_some() { "z " } else { "" }
                )
            }
            Error::WeightsVanish { interval: (a, b) } if a == b => {
                write!(f, "the weights make the curve undefined: the denominator vanishes at t = {a}")
            }
            Error::WeightsVanish { interval: (a, b) } => write!(
                f,
                "the weights make the curve undefined: the denominator vanishes at a t in the interval ({a}, {b})"
            ),
            Error::Expression { text, column, message } => {
                // a long expression is shortened around the column
                let chars: Vec<char> = text.chars().collect();
                if chars.len() <= 80 {
                    write!(f, "in expression {text:?}, column {column}: {message}")
                } else {
                    let at = column.saturating_sub(1).min(chars.len());
                    let (a, b) = (at.saturating_sub(30), (at + 30).min(chars.len()));
                    let part: String = chars[a..b].iter().collect();
                    write!(
                        f,
                        "in expression of {} characters, near {}{part:?}{}, column {column}: {message}",
                        chars.len(),
                        if a > 0 { "…" } else { "" },
                        if b < chars.len() { "…" } else { "" }
                    )
                }
            }
            Error::ClaimFile { file, line: Some(l), message } => write!(f, "{file}:{l}: {message}"),
            Error::ClaimFile { file, line: None, message } => write!(f, "{file}: {message}"),
        }
    }
}

impl std::error::Error for Error {}

/// `Result` with casteljau's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;
