//! The `casteljau` command line: clap-derived command structs and their execution.
//!
//! Exit codes: `0` success, `1` a check failed (`prove` found a wrong verdict), `2` bad input
//! (malformed number, wrong point count, bad option). In a batch every line is answered; a bad
//! line gets an error (with its line number) and the exit code is 2 at the end.

use crate::answers::{self, points_json};
use casteljau::curve::bezier::BezierCurve;
use casteljau::curve::fraction_free;
use casteljau::error::{Error, Position, Result};
use casteljau::num::parse::{parse_number, parse_points};
use casteljau::num::point::Point;
use casteljau::rational::rational_bezier::RationalBezier;
use clap::{Args, Parser, Subcommand};
use num_rational::BigRational;
use serde_json::{Value, json};
use std::io::{BufRead, Read, Write};

const AFTER_HELP: &str = "\
CURVES: control points as exact numbers (integers, p/q, decimals such as 0.125 or 1.5e-3),
commas between points: \"x0 y0, x1 y1, x2 y2\". With --input FILE (or '-' / no curve: stdin)
each line is one curve; numbers may be separated by whitespace or commas, read --dim at a time.
Blank lines and lines starting with '#' are skipped.

EXIT CODES: 0 ok; 1 a check failed; 2 bad input (the message names the token and position).";

/// casteljau: Bézier curves in exact arithmetic.
#[derive(Parser, Debug)]
#[command(name = "casteljau", version, about, after_help = AFTER_HELP)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Evaluate b(t) exactly (fraction-free de Casteljau).
    Eval {
        /// Parameter values (repeatable): exact numbers.
        #[arg(long = "t", required = true, allow_hyphen_values = true)]
        t: Vec<String>,
        /// Rational curves.
        #[command(flatten)]
        rational: RationalArgs,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Split at t (Lemma 2) into the control polygons of [0,t] and [t,1]; with --depth, repeat.
    Subdivide {
        /// The split parameter.
        #[arg(long = "t", default_value = "1/2", allow_hyphen_values = true)]
        t: String,
        /// Split every piece again, depth times (2^depth pieces, as in seed 001 Fig. 10).
        #[arg(long, default_value_t = 1)]
        depth: u32,
        /// Rational curves (depth 1).
        #[command(flatten)]
        rational: RationalArgs,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Degree elevation: the same curve with `by` more control points.
    Elevate {
        /// How many degrees to add.
        #[arg(long, default_value_t = 1)]
        by: usize,
        /// Rational curves.
        #[command(flatten)]
        rational: RationalArgs,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Power form: coefficients c_k with b(t) = Σ c_k t^k, and the conversion matrix.
    Power {
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// The de Casteljau scheme: every b_i^r(t).
    Triangle {
        /// The parameter.
        #[arg(long = "t", allow_hyphen_values = true)]
        t: String,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// The k-th derivative curve (hodograph for k = 1).
    Derivative {
        /// The order k.
        #[arg(long, default_value_t = 1)]
        order: usize,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Exact degree reduction: the true degree and the control points of that degree.
    Reduce {
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Classify planar curves of degree ≤ 3 exactly: node type, double point, parameters,
    /// segment features on [0,1].
    Classify {
        /// Also print f64 approximations of the exact parameters.
        #[arg(long)]
        float: bool,
        /// A rational cubic (classified projectively).
        #[command(flatten)]
        rational: RationalArgs,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Prove or refute that a (rational) curve lies on f = 0: exit 0 proved, 1 counterexample.
    Implicit {
        /// The polynomial f in x, y (and z), e.g. "x^3 - 3*x*y + y^3".
        #[arg(long, allow_hyphen_values = true)]
        poly: String,
        /// Rational curves.
        #[command(flatten)]
        rational: RationalArgs,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Is the rational curve defined on [a, b] (default [0, 1])? Exact root isolation of the
    /// denominator Σ w_i B_i(t): exit 0 defined, 1 with isolating intervals of its roots.
    Defined {
        /// Start of the interval.
        #[arg(long, default_value = "0", allow_hyphen_values = true)]
        from: String,
        /// End of the interval.
        #[arg(long, default_value = "1", allow_hyphen_values = true)]
        to: String,
        /// Rational curves.
        #[command(flatten)]
        rational: RationalArgs,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// The conic of a rational quadratic: ellipse, parabola, hyperbola (from w1² − w0·w2).
    Conic {
        /// Rational curves.
        #[command(flatten)]
        rational: RationalArgs,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Rational tensor-product Bézier patches: points row-major, (m+1)(n+1) of them.
    Surface {
        /// What to do with the patch.
        #[command(subcommand)]
        op: SurfaceOp,
    },
    /// Rational splines with scale ratios → C^(n-1)-joined rational Bézier segments.
    Spline {
        /// What to do with the spline.
        #[command(subcommand)]
        op: SplineOp,
    },
    /// Draw curves as standalone SVG (to stdout or -o FILE); every curve of a batch in one figure.
    Plot {
        /// Draw and label the control polygon.
        #[arg(long)]
        polygon: bool,
        /// Overlay the de Casteljau construction at this parameter.
        #[arg(long, allow_hyphen_values = true)]
        construction: Option<String>,
        /// Overlay repeated subdivision at this parameter (with --depth).
        #[arg(long = "subdivide", allow_hyphen_values = true)]
        subdivide_at: Option<String>,
        /// Depth of --subdivide.
        #[arg(long, default_value_t = 1)]
        depth: u32,
        /// Mark classification features (double point, cusp, inflections, loop, E, canonical frame).
        #[arg(long)]
        features: bool,
        /// A family of curves varying one weight, e.g. "w1=1,3,4" (needs --weights for the rest).
        #[arg(long)]
        weights_family: Option<String>,
        /// Grid lines at integer coordinates.
        #[arg(long)]
        grid: bool,
        /// A title.
        #[arg(long)]
        title: Option<String>,
        /// Image width in pixels.
        #[arg(long, default_value_t = 480)]
        width: u32,
        /// Write the SVG here instead of stdout.
        #[arg(long, short)]
        output: Option<std::path::PathBuf>,
        /// Rational curves.
        #[command(flatten)]
        rational: RationalArgs,
        /// The curve(s).
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Write the seed figures that can be reproduced (SVG) and an index.html into DIR.
    Gallery {
        /// The folder.
        dir: std::path::PathBuf,
    },
    /// Check the claim catalogue (default proofs/): one line per claim, exit 0 iff every
    /// verdict is as expected, 1 otherwise, 2 on malformed claim files.
    Prove {
        /// Claim files or folders (default: proofs/).
        paths: Vec<std::path::PathBuf>,
        /// Only claims whose id contains this text.
        #[arg(long)]
        filter: Option<String>,
        /// One JSON object per claim.
        #[arg(long)]
        json: bool,
        /// Also write a JUnit XML report to this file.
        #[arg(long)]
        junit: Option<std::path::PathBuf>,
        /// Regenerate the catalogue's README (default proofs/README.md) from this run.
        #[arg(long, num_args = 0..=1, default_missing_value = "proofs/README.md")]
        write_readme: Option<std::path::PathBuf>,
    },
}

/// Patch operations.
#[derive(Subcommand, Debug)]
pub enum SurfaceOp {
    /// S(u, v): the closed form (41), checked against de Casteljau u-then-v and v-then-u.
    Eval {
        /// Parameter u.
        #[arg(long, allow_hyphen_values = true)]
        u: String,
        /// Parameter v.
        #[arg(long, allow_hyphen_values = true)]
        v: String,
        /// The patch.
        #[command(flatten)]
        patch: PatchArgs,
    },
    /// Split at u = U (or v = V).
    Subdivide {
        /// Split in u here.
        #[arg(long, allow_hyphen_values = true)]
        u: Option<String>,
        /// Split in v here.
        #[arg(long, allow_hyphen_values = true)]
        v: Option<String>,
        /// The patch.
        #[command(flatten)]
        patch: PatchArgs,
    },
    /// Degree elevation in u and v.
    Elevate {
        /// Degrees added in u.
        #[arg(long, default_value_t = 0)]
        u_by: usize,
        /// Degrees added in v.
        #[arg(long, default_value_t = 0)]
        v_by: usize,
        /// The patch.
        #[command(flatten)]
        patch: PatchArgs,
    },
    /// The contour z = C as an exact implicit polynomial in (u, v), and a sampled polyline.
    Contour {
        /// The height C.
        #[arg(long, allow_hyphen_values = true)]
        z: String,
        /// Sample the contour on an N×N grid (f64 segments, for plots).
        #[arg(long, default_value_t = 0)]
        polyline: usize,
        /// The patch.
        #[command(flatten)]
        patch: PatchArgs,
    },
}

/// A patch given as a curve line of (m+1)(n+1) points.
#[derive(Args, Debug)]
pub struct PatchArgs {
    /// Degrees "m,n" (rows along u, columns along v).
    #[arg(long)]
    pub degree: String,
    /// Weights, row-major (default all 1).
    #[command(flatten)]
    pub rational: RationalArgs,
    /// The control net, row-major, and output form (3D by default).
    #[command(flatten)]
    pub curve: CurveArgs,
}

/// Spline operations.
#[derive(Subcommand, Debug)]
pub enum SplineOp {
    /// The rational Bézier segments of the spline, with their weights.
    ToBezier {
        /// `seed` (the seed's rational interpolation formulas: cubic (25)-(29), quadratic (53)
        /// corrected) or `boehm` (knot insertion, any degree).
        #[arg(long, default_value = "boehm")]
        method: String,
        /// The spline.
        #[command(flatten)]
        spline: SplineArgs,
    },
    /// Prove the segments: equal to the NURBS on each span, C^(n-1) joins, seed = Boehm.
    Check {
        /// The spline.
        #[command(flatten)]
        spline: SplineArgs,
    },
}

/// A rational spline.
#[derive(Args, Debug)]
pub struct SplineArgs {
    /// The degree n.
    #[arg(long, default_value_t = 3)]
    pub degree: usize,
    /// Scale ratios (knot intervals), m + n of them for m + 1 control points.
    #[arg(long, allow_hyphen_values = true)]
    pub ratios: String,
    /// Weights k_i (default all 1).
    #[arg(long, allow_hyphen_values = true)]
    pub weights: Option<String>,
    /// The control polygon, and output form.
    #[command(flatten)]
    pub curve: CurveArgs,
}

pub(crate) fn numbers(option: &str, text: &str) -> Result<Vec<BigRational>> {
    let pts = parse_points(text, 1, None).map_err(|e| Error::InvalidArgument { message: format!("{option}: {e}") })?;
    Ok(pts.into_iter().map(|p| p.coords[0].clone()).collect())
}

pub(crate) fn patch_of(
    c: &BezierCurve<BigRational>,
    degree: &str,
    rational: &RationalArgs,
) -> Result<casteljau::surface::RationalPatch> {
    let bad = |m: String| Error::InvalidArgument { message: m };
    let (m, n) = degree
        .split_once(',')
        .and_then(|(a, b)| Some((a.trim().parse::<usize>().ok()?, b.trim().parse::<usize>().ok()?)))
        .ok_or_else(|| bad(format!("--degree must be \"m,n\", got {degree:?}")))?;
    if m > casteljau::surface::MAX_PATCH_DEGREE || n > casteljau::surface::MAX_PATCH_DEGREE {
        return Err(Error::TooLarge {
            what: "patch degree",
            value: m.max(n),
            limit: casteljau::surface::MAX_PATCH_DEGREE,
        });
    }
    let pts = c.points();
    if pts.len() != (m + 1) * (n + 1) {
        return Err(bad(format!("a degree ({m}, {n}) patch needs {} points, got {}", (m + 1) * (n + 1), pts.len())));
    }
    let rows: Vec<Vec<Point<BigRational>>> = pts.chunks(n + 1).map(|r| r.to_vec()).collect();
    if rational.homogeneous {
        return casteljau::surface::RationalPatch::from_homogeneous(rows);
    }
    let w = match rational.parse_weights()? {
        Some(w) if w.len() != pts.len() => {
            return Err(bad(format!("{} weights for {} control points", w.len(), pts.len())));
        }
        Some(w) => w,
        None => vec![casteljau::num::scalar::rat(1); pts.len()],
    };
    casteljau::surface::RationalPatch::new(rows, w.chunks(n + 1).map(|r| r.to_vec()).collect())
}

/// Weights of a rational curve (for eval, subdivide, elevate, implicit, conic, classify).
#[derive(Args, Debug, Clone)]
pub struct RationalArgs {
    /// Weights w0..wn (exact numbers, one per control point): a rational curve.
    #[arg(long, allow_hyphen_values = true)]
    pub weights: Option<String>,
    /// Read control points as homogeneous "w·x w·y w" (w = 0: a point at infinity, a direction).
    #[arg(long)]
    pub homogeneous: bool,
}

impl RationalArgs {
    fn parse_weights(&self) -> Result<Option<Vec<BigRational>>> {
        if self.homogeneous && self.weights.is_some() {
            return Err(Error::InvalidArgument { message: "give --weights or --homogeneous, not both".into() });
        }
        let Some(w) = &self.weights else { return Ok(None) };
        let pts =
            parse_points(w, 1, None).map_err(|e| Error::InvalidArgument { message: format!("--weights: {e}") })?;
        Ok(Some(pts.into_iter().map(|p| p.coords[0].clone()).collect()))
    }
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
pub(crate) fn rational_curve(
    c: &BezierCurve<BigRational>,
    weights: Weights<'_>,
) -> Result<RationalBezier<BigRational>> {
    match weights {
        Weights::Polynomial => {
            RationalBezier::new(c.points().to_vec(), vec![casteljau::num::scalar::rat(1); c.points().len()])
        }
        Weights::Given(w) => RationalBezier::new(c.points().to_vec(), w.to_vec()),
        Weights::Homogeneous => RationalBezier::from_homogeneous(c.points().to_vec()),
    }
}

/// One command's answer for one curve.
pub struct Answer {
    /// Text output.
    pub text: String,
    /// JSON output.
    pub json: Value,
    /// A check failed (exit code 1).
    pub failed: bool,
}

impl From<(String, Value)> for Answer {
    fn from((text, json): (String, Value)) -> Self {
        Answer { text, json, failed: false }
    }
}

/// Where the curves come from, and the output form.
#[derive(Args, Debug)]
pub struct CurveArgs {
    /// One curve, e.g. "0 0, 1 2, 2 0". Omit to read --input or stdin.
    #[arg(allow_hyphen_values = true)]
    pub curve: Option<String>,
    /// A batch file, one curve per line ('-' for stdin).
    #[arg(long, short)]
    pub input: Option<String>,
    /// Dimension of the control points (2 or 3; any ≥ 1 works).
    #[arg(long, default_value_t = 2)]
    pub dim: usize,
    /// JSON Lines output with exact strings.
    #[arg(long)]
    pub json: bool,
}

/// Largest accepted `--dim`.
pub const MAX_DIM: usize = 64;
/// Largest degree whose conversion matrix `power --json` includes.
pub const MAX_MATRIX_DEGREE: usize = 30;
/// Largest degree `triangle` prints (its output has (n+1)(n+2)/2 points).
pub const MAX_TRIANGLE_DEGREE: usize = 500;
/// Largest number of control points `subdivide --depth` prints.
pub const MAX_SUBDIVISION_POINTS: usize = 1 << 20;

pub(crate) fn output_limit(what: &'static str, value: usize, limit: usize) -> Result<()> {
    if value > limit { Err(Error::TooLarge { what, value, limit }) } else { Ok(()) }
}

/// Largest batch input, in bytes.
pub const MAX_INPUT_BYTES: u64 = 256 * 1024 * 1024;

/// Parses the command line and runs it; returns the process exit code.
pub fn main() -> i32 {
    let cli = Cli::parse();
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let code = run(cli, &mut out);
    let _ = out.flush();
    code
}

/// Runs a parsed command, writing answers to `out` and errors to stderr; returns the exit code.
pub fn run(cli: Cli, out: &mut dyn Write) -> i32 {
    match cli.command {
        Command::Prove { paths, filter, json, junit, write_readme } => {
            crate::commands::prove(&paths, filter.as_deref(), json, junit.as_deref(), write_readme.as_deref(), out)
        }
        Command::Eval { t, rational, curve } => {
            let ts: Result<Vec<BigRational>> = t.iter().map(|s| option_number("--t", s)).collect();
            rational_batch(&rational, curve, out, move |c, w| {
                let ts = ts.clone()?;
                match w {
                    Weights::Polynomial => answers::eval(c, &ts).map(Answer::from),
                    w => answers::eval_rational(&rational_curve(c, w)?, &ts).map(Answer::from),
                }
            })
        }
        Command::Subdivide { t, depth, rational, curve } => {
            let t0 = option_number("--t", &t);
            rational_batch(&rational, curve, out, move |c, w| {
                let t0 = t0.clone()?;
                match w {
                    Weights::Polynomial => answers::subdivide(c, &t0, depth).map(Answer::from),
                    _ if depth != 1 => Err(Error::InvalidArgument {
                        message: "--depth is for polynomial curves; rational curves split once".into(),
                    }),
                    w => answers::subdivide_rational(&rational_curve(c, w)?, &t0).map(Answer::from),
                }
            })
        }
        Command::Elevate { by, rational, curve } => rational_batch(&rational, curve, out, move |c, w| match w {
            Weights::Polynomial => {
                let e = fraction_free::elevate(c, by)?;
                Ok(Answer::from((e.to_string(), json!({"degree": e.degree(), "points": points_json(e.points())}))))
            }
            w => answers::elevate_rational(&rational_curve(c, w)?, by).map(Answer::from),
        }),
        Command::Implicit { poly, rational, curve } => {
            rational_batch(&rational, curve, out, move |c, w| answers::implicit(&rational_curve(c, w)?, &poly))
        }
        Command::Defined { from, to, rational, curve } => {
            let range =
                option_number("--from", &from).and_then(|a| Ok((a, option_number("--to", &to)?))).and_then(|(a, b)| {
                    if a >= b || a < casteljau::num::scalar::rat(0) || b > casteljau::num::scalar::rat(1) {
                        Err(Error::InvalidArgument { message: format!("need 0 <= --from < --to <= 1, got [{a}, {b}]") })
                    } else {
                        Ok((a, b))
                    }
                });
            rational_batch(&rational, curve, out, move |c, w| {
                let (a, b) = range.clone()?;
                answers::defined(&rational_curve(c, w)?, &a, &b)
            })
        }
        Command::Surface { op } => crate::commands::surface(op, out),
        Command::Gallery { dir } => match casteljau::plot::gallery::write(&dir) {
            Ok(files) => {
                let _ = writeln!(out, "wrote {} files to {}", files.len(), dir.display());
                0
            }
            Err(e) => {
                eprintln!("casteljau: {e}");
                2
            }
        },
        Command::Plot {
            polygon,
            construction,
            subdivide_at,
            depth,
            features,
            weights_family,
            grid,
            title,
            width,
            output,
            rational,
            curve,
        } => {
            let opts = (|| -> Result<casteljau::plot::CurveOptions> {
                Ok(casteljau::plot::CurveOptions {
                    polygon,
                    construction: construction.as_deref().map(|t| option_number("--construction", t)).transpose()?,
                    subdivide: subdivide_at
                        .as_deref()
                        .map(|t| option_number("--subdivide", t).map(|t| (t, depth)))
                        .transpose()?,
                    features,
                })
            })();
            crate::commands::plot(
                opts,
                weights_family,
                grid,
                title,
                width.clamp(16, 8192),
                output,
                rational,
                curve,
                out,
            )
        }
        Command::Spline { op } => crate::commands::spline(op, out),
        Command::Conic { rational, curve } => {
            rational_batch(&rational, curve, out, move |c, w| answers::conic(&rational_curve(c, w)?).map(Answer::from))
        }
        Command::Power { curve } => batch(&curve, out, |c| Ok(answers::power(c).into())),
        Command::Triangle { t, curve } => {
            let t = option_number("--t", &t);
            batch(&curve, out, move |c| {
                output_limit("triangle of degree", c.degree(), MAX_TRIANGLE_DEGREE)?;
                answers::triangle(c, &t.clone()?).map(Answer::from)
            })
        }
        Command::Derivative { order, curve } => batch(&curve, out, |c| {
            let d = c.derivative(order);
            Ok(Answer::from((
                d.to_string(),
                json!({"order": order, "degree": d.degree(), "points": points_json(d.points())}),
            )))
        }),
        Command::Reduce { curve } => batch(&curve, out, |c| {
            let r = fraction_free::reduce_degree(c);
            let text = format!("degree {} (written as {}): {}", r.degree(), c.degree(), r);
            Ok(Answer::from((
                text,
                json!({"degree": c.degree(), "real_degree": r.degree(), "points": points_json(r.points())}),
            )))
        }),
        Command::Classify { float, rational, curve } => rational_batch(&rational, curve, out, move |c, w| match w {
            Weights::Polynomial => answers::classify(c, float).map(Answer::from),
            w => answers::classify_weighted(&rational_curve(c, w)?).map(Answer::from),
        }),
    }
}

/// [`batch`] for commands that accept rational curves: parses `--weights` once and reads points
/// with one more coordinate under `--homogeneous`.
pub(crate) fn rational_batch(
    rational: &RationalArgs,
    mut curve: CurveArgs,
    out: &mut dyn Write,
    f: impl Fn(&BezierCurve<BigRational>, Weights<'_>) -> Result<Answer>,
) -> i32 {
    let weights = match rational.parse_weights() {
        Ok(w) => w,
        Err(e) => {
            eprintln!("casteljau: {e}");
            return 2;
        }
    };
    if rational.homogeneous {
        curve.dim += 1;
    }
    let w = match (&weights, rational.homogeneous) {
        (Some(w), _) => Weights::Given(w),
        (None, true) => Weights::Homogeneous,
        (None, false) => Weights::Polynomial,
    };
    batch(&curve, out, |c| f(c, w))
}

pub(crate) fn option_number(option: &str, s: &str) -> Result<BigRational> {
    parse_number(s.trim(), Position { line: None, column: 1, token: 1 }).map_err(|e| match e {
        Error::ParseNumber { token, reason, .. } => {
            Error::InvalidArgument { message: format!("{option}: bad number {token:?}: {reason}") }
        }
        other => other,
    })
}

/// Reads the curves (argument, file, or stdin) and answers each; exit 2 if any line was bad.
pub(crate) fn batch(
    args: &CurveArgs,
    out: &mut dyn Write,
    f: impl Fn(&BezierCurve<BigRational>) -> Result<Answer>,
) -> i32 {
    if args.dim == 0 || args.dim > MAX_DIM {
        eprintln!("casteljau: --dim must be between 1 and {MAX_DIM}");
        return 2;
    }
    let inputs: Vec<(Option<usize>, String)> = match (&args.curve, &args.input) {
        (Some(_), Some(_)) => {
            eprintln!("casteljau: give a curve or --input, not both");
            return 2;
        }
        (Some(c), None) => vec![(None, c.clone())],
        (None, source) => match read_lines(source.as_deref()) {
            Ok(lines) => lines,
            Err(e) => {
                eprintln!("casteljau: {e}");
                return 2;
            }
        },
    };
    let mut code = 0;
    let mut failed = false;
    for (line, text) in inputs {
        let answer = parse_points(&text, args.dim, line).and_then(BezierCurve::new).and_then(|c| f(&c));
        let written = match answer {
            Ok(Answer { text, json: mut value, failed: f }) => {
                failed |= f;
                if args.json {
                    if let (Some(l), Some(obj)) = (line, value.as_object_mut()) {
                        obj.insert("line".into(), json!(l));
                    }
                    writeln!(out, "{value}")
                } else {
                    writeln!(out, "{text}")
                }
            }
            Err(e) => {
                code = 2;
                let e = match (e, line) {
                    (Error::EmptyCurve { .. }, l) => Error::EmptyCurve { line: l },
                    (e, _) => e,
                };
                if args.json {
                    writeln!(out, "{}", json!({"line": line, "error": e.to_string()}))
                } else {
                    eprintln!("casteljau: {e}");
                    Ok(())
                }
            }
        };
        if written.is_err() {
            return code.max(2); // stdout closed (e.g. a pipe): stop quietly
        }
    }
    if code == 0 && failed { 1 } else { code }
}

fn read_lines(source: Option<&str>) -> std::result::Result<Vec<(Option<usize>, String)>, String> {
    let mut text = String::new();
    let read = match source {
        None | Some("-") => std::io::stdin().lock().take(MAX_INPUT_BYTES + 1).read_to_string(&mut text),
        Some(path) => std::fs::File::open(path)
            .map_err(|e| format!("cannot open {path}: {e}"))?
            .take(MAX_INPUT_BYTES + 1)
            .read_to_string(&mut text),
    };
    read.map_err(|e| format!("cannot read input: {e}"))?;
    if text.len() as u64 > MAX_INPUT_BYTES {
        return Err(format!("input larger than {MAX_INPUT_BYTES} bytes"));
    }
    Ok(text
        .as_bytes()
        .lines()
        .enumerate()
        .filter_map(|(i, l)| {
            let l = l.ok()?;
            let trimmed = l.trim();
            (!trimmed.is_empty() && !trimmed.starts_with('#')).then(|| (Some(i + 1), l))
        })
        .collect())
}
