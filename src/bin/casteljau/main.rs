//! The `casteljau` binary: parses the command line, dispatches each command to its runner and
//! exits with its code.
//!
//! * [`args`]: the clap structs, one per command or shared group.
//! * [`batch`]: reading curves (argument, file, stdin), limits, writing one answer per curve.
//! * [`answers`]: each command's exact answer for one curve, as text and typed JSON.
//! * [`commands`]: the commands with their own input and output (`prove`, `plot`, `surface`,
//!   `gallery`); [`splines`]: the `spline` command (knot vectors, JSON Lines splines); [`scan`]:
//!   fonts, SVG and batches, segment by segment; [`check`]: a float library's answers against
//!   the exact ones.

mod answers;
mod args;
mod batch;
mod check;
mod commands;
mod intersect;
mod scan;
mod splines;

use args::{Cli, Command};
use batch::{
    Answer, MAX_TRIANGLE_DEGREE, Weights, batch, option_number_in, output_limit, rational_batch, rational_curve,
};
use casteljau::error::{Error, Result};
use casteljau::{rat, work};
use clap::Parser;
use num_rational::BigRational;
use std::io::Write;

fn main() {
    let cli = Cli::parse();
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let code = run(cli, &mut out);
    let _ = out.flush();
    std::process::exit(code);
}

/// Runs a parsed command, writing answers to `out` and errors to stderr; returns the exit code.
fn run(cli: Cli, out: &mut dyn Write) -> i32 {
    match cli.command {
        Command::Prove(args) => commands::prove(&args, out),
        Command::Eval { t, rational, curve } => {
            let mode = curve.numbers.into();
            let ts: Result<Vec<BigRational>> = t.iter().map(|s| option_number_in("--t", s, mode)).collect();
            let budget = curve.budget();
            rational_batch(&rational, curve, out, move |c, w| {
                let ts = ts.clone()?;
                let (n, beta) = (c.degree(), work::max_bits(c.points()));
                let estimate: f64 = ts.iter().map(|t| work::evaluation(n, c.dim(), beta, work::bits(t))).sum();
                budget.check(format!("evaluating degree {n} at {} parameters", ts.len()), estimate)?;
                match w {
                    Weights::Polynomial => answers::eval(c, &ts).map(Answer::from),
                    w => answers::eval_rational(&rational_curve(c, w)?, &ts).map(Answer::from),
                }
            })
        }
        Command::Subdivide { t, depth, rational, curve } => {
            let t0 = option_number_in("--t", &t, curve.numbers.into());
            let budget = curve.budget();
            rational_batch(&rational, curve, out, move |c, w| {
                let t0 = t0.clone()?;
                let (n, beta) = (c.degree(), work::max_bits(c.points()));
                let estimate = match depth {
                    None => work::subdivision(n, c.dim(), beta, work::bits(&t0)),
                    Some(k) => work::repeated_subdivision(n, c.dim(), beta, work::bits(&t0), k),
                };
                budget.check(format!("subdividing degree {n}"), estimate)?;
                match w {
                    Weights::Polynomial => answers::subdivide(c, &t0, depth).map(Answer::from),
                    _ if depth.is_some_and(|d| d != 1) => Err(Error::InvalidArgument {
                        message: "--depth is for polynomial curves; rational curves split once".into(),
                    }),
                    w => answers::subdivide_rational(&rational_curve(c, w)?, &t0).map(Answer::from),
                }
            })
        }
        Command::Elevate { by, rational, curve } => {
            let budget = curve.budget();
            rational_batch(&rational, curve, out, move |c, w| {
                let n = c.degree();
                budget.check(
                    format!("elevating degree {n} by {by}"),
                    work::elevation(n, by, c.dim(), work::max_bits(c.points())),
                )?;
                match w {
                    Weights::Polynomial => answers::elevate(c, by).map(Answer::from),
                    w => answers::elevate_rational(&rational_curve(c, w)?, by).map(Answer::from),
                }
            })
        }
        Command::Implicit { poly, rational, curve } => {
            let budget = curve.budget();
            rational_batch(&rational, curve, out, move |c, w| answers::implicit(&rational_curve(c, w)?, &poly, &budget))
        }
        Command::Defined { from, to, rational, curve } => {
            let range = option_number_in("--from", &from, curve.numbers.into())
                .and_then(|a| Ok((a, option_number_in("--to", &to, curve.numbers.into())?)))
                .and_then(|(a, b)| {
                    if a >= b || a < rat(0) || b > rat(1) {
                        Err(Error::InvalidArgument { message: format!("need 0 <= --from < --to <= 1, got [{a}, {b}]") })
                    } else {
                        Ok((a, b))
                    }
                });
            let budget = curve.budget();
            rational_batch(&rational, curve, out, move |c, w| {
                let (a, b) = range.clone()?;
                answers::defined(&rational_curve(c, w)?, &a, &b, &budget)
            })
        }
        Command::Surface { op } => commands::surface(op, out),
        Command::Gallery { dir } => commands::gallery(&dir, out),
        Command::Plot(args) => commands::plot(args, out),
        Command::Spline { op } => splines::run(op, out),
        Command::Scan(args) => scan::run(&args, out),
        Command::Check(args) => check::run(&args, out),
        Command::Intersect(args) => intersect::run(&args, out),
        Command::Winding(args) => intersect::run_winding(&args, out),
        Command::Bbox { rational, curve } => {
            let budget = curve.budget();
            rational_batch(&rational, curve, out, move |c, w| {
                answers::bbox(&rational_curve(c, w)?, &budget).map(Answer::from)
            })
        }
        Command::Conic { rational, curve } => {
            rational_batch(&rational, curve, out, move |c, w| answers::conic(&rational_curve(c, w)?).map(Answer::from))
        }
        Command::Power { curve } => batch(&curve, out, |c| {
            let n = c.degree();
            curve.budget().check(
                format!("the power form of degree {n}"),
                work::power_form(n, c.dim(), work::max_bits(c.points())),
            )?;
            Ok(answers::power(c).into())
        }),
        Command::Triangle { t, curve } => {
            let t = option_number_in("--t", &t, curve.numbers.into());
            batch(&curve, out, |c| {
                output_limit("triangle of degree", c.degree(), MAX_TRIANGLE_DEGREE)?;
                let t = t.clone()?;
                let n = c.degree();
                curve.budget().check(
                    format!("the de Casteljau scheme of degree {n} at a {}-bit t", work::bits(&t)),
                    work::de_casteljau_scheme(n, c.dim(), work::max_bits(c.points()), work::bits(&t)),
                )?;
                answers::triangle(c, &t).map(Answer::from)
            })
        }
        Command::Derivative { order, curve } => batch(&curve, out, |c| {
            let n = c.degree();
            curve.budget().check(
                format!("the derivative of order {order} of degree {n}"),
                work::derivative(n, order.min(n), c.dim(), work::max_bits(c.points())),
            )?;
            Ok(answers::derivative(c, order).into())
        }),
        Command::Reduce { curve } => batch(&curve, out, |c| {
            let n = c.degree();
            curve
                .budget()
                .check(format!("reducing degree {n}"), work::power_form(n, c.dim(), work::max_bits(c.points())))?;
            Ok(answers::reduce(c).into())
        }),
        Command::Classify { float, detail, rational, curve } => {
            if rational.weights.is_none() && !rational.homogeneous {
                let (dim, json, full) = (curve.dim, curve.json, detail == args::Detail::Full);
                let mode = curve.numbers.into();
                let direct = |text: &str, out: &mut Vec<u8>| {
                    dim == 2 && !full && !float && answers::classify_direct_json(text, mode, out)
                };
                return batch::batch_lines_with(&curve, out, &direct, |line, text| {
                    answers::classify(text, dim, mode, line, float, full, json)
                });
            }
            rational_batch(&rational, curve, out, move |c, w| {
                answers::classify_weighted(&rational_curve(c, w)?).map(Answer::from)
            })
        }
    }
}
