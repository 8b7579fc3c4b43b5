//! The `casteljau` command line: clap-derived command structs and their execution.
//!
//! Exit codes: `0` success, `1` a check failed (`prove` found a wrong verdict), `2` bad input
//! (malformed number, wrong point count, bad option). In a batch every line is answered; a bad
//! line gets an error (with its line number) and the exit code is 2 at the end.

use crate::bezier::BezierCurve;
use crate::casteljau::subdivision_intervals;
use crate::error::{Error, Position, Result};
use crate::fraction_free;
use crate::parse::{parse_number, parse_points};
use crate::point::Point;
use crate::scalar::Scalar;
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
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Degree elevation: the same curve with `by` more control points.
    Elevate {
        /// How many degrees to add.
        #[arg(long, default_value_t = 1)]
        by: usize,
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
        /// Weights w0..w3 of a rational cubic (exact numbers): classified projectively.
        #[arg(long, allow_hyphen_values = true)]
        weights: Option<String>,
        /// Read control points as homogeneous "X Y W" (W = 0: a point at infinity); implies a
        /// rational cubic.
        #[arg(long)]
        homogeneous: bool,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
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

fn output_limit(what: &'static str, value: usize, limit: usize) -> Result<()> {
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
            prove(&paths, filter.as_deref(), json, junit.as_deref(), write_readme.as_deref(), out)
        }
        Command::Classify { float, weights, homogeneous, mut curve } => {
            if homogeneous {
                curve.dim = 3;
            }
            let weights = match weights.map(|w| parse_points(&w, 1, None)).transpose() {
                Ok(w) => w.map(|w| w.into_iter().map(|p| p.coords[0].clone()).collect::<Vec<_>>()),
                Err(e) => {
                    eprintln!("casteljau: --weights: {e}");
                    return 2;
                }
            };
            if homogeneous || weights.is_some() {
                batch(&curve, out, |c| classify_weighted(c, weights.as_deref(), homogeneous))
            } else {
                batch(&curve, out, |c| classify(c, float))
            }
        }
        Command::Eval { t, curve } => {
            let ts: Result<Vec<BigRational>> = t.iter().map(|s| option_number("--t", s)).collect();
            with_param(ts, &curve, out, |c, ts| eval(c, ts))
        }
        Command::Subdivide { t, depth, curve } => {
            with_param(option_number("--t", &t), &curve, out, |c, t0| subdivide(c, t0, depth))
        }
        Command::Elevate { by, curve } => batch(&curve, out, |c| {
            let e = fraction_free::elevate(c, by)?;
            Ok((e.to_string(), json!({"degree": e.degree(), "points": points_json(e.points())})))
        }),
        Command::Power { curve } => batch(&curve, out, |c| Ok(power(c))),
        Command::Triangle { t, curve } => with_param(option_number("--t", &t), &curve, out, |c, t| {
            output_limit("triangle of degree", c.degree(), MAX_TRIANGLE_DEGREE)?;
            triangle(c, t)
        }),
        Command::Derivative { order, curve } => batch(&curve, out, |c| {
            let d = c.derivative(order);
            Ok((d.to_string(), json!({"order": order, "degree": d.degree(), "points": points_json(d.points())})))
        }),
        Command::Reduce { curve } => batch(&curve, out, |c| {
            let r = fraction_free::reduce_degree(c);
            let text = format!("degree {} (written as {}): {}", r.degree(), c.degree(), r);
            Ok((text, json!({"degree": c.degree(), "real_degree": r.degree(), "points": points_json(r.points())})))
        }),
    }
}

fn option_number(option: &str, s: &str) -> Result<BigRational> {
    parse_number(s.trim(), Position { line: None, column: 1, token: 1 }).map_err(|e| match e {
        Error::ParseNumber { token, reason, .. } => {
            Error::InvalidArgument { message: format!("{option}: bad number {token:?}: {reason}") }
        }
        other => other,
    })
}

fn with_param<P>(
    param: Result<P>,
    args: &CurveArgs,
    out: &mut dyn Write,
    f: impl Fn(&BezierCurve<BigRational>, &P) -> Result<(String, Value)>,
) -> i32 {
    match param {
        Ok(p) => batch(args, out, |c| f(c, &p)),
        Err(e) => {
            eprintln!("casteljau: {e}");
            2
        }
    }
}

/// Reads the curves (argument, file, or stdin) and answers each; exit 2 if any line was bad.
fn batch(
    args: &CurveArgs,
    out: &mut dyn Write,
    f: impl Fn(&BezierCurve<BigRational>) -> Result<(String, Value)>,
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
    for (line, text) in inputs {
        let answer = parse_points(&text, args.dim, line).and_then(BezierCurve::new).and_then(|c| f(&c));
        let written = match answer {
            Ok((text, mut value)) => {
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
    code
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

/// Exact strings of a point's coordinates.
pub fn point_json<S: Scalar>(p: &Point<S>) -> Value {
    Value::Array(p.coords.iter().map(|c| Value::String(c.to_string())).collect())
}

/// Exact strings of a polygon.
pub fn points_json<S: Scalar>(ps: &[Point<S>]) -> Value {
    Value::Array(ps.iter().map(point_json).collect())
}

fn eval(c: &BezierCurve<BigRational>, ts: &[BigRational]) -> Result<(String, Value)> {
    let ic = fraction_free::IntegerCurve::new(c);
    let values: Vec<Point<BigRational>> = ts.iter().map(|t| fraction_free::eval_integer(&ic, t)).collect();
    let text = ts.iter().zip(&values).map(|(t, p)| format!("b({t}) = {p}")).collect::<Vec<_>>().join("\n");
    let js: Vec<Value> =
        ts.iter().zip(&values).map(|(t, p)| json!({"t": t.to_string(), "point": point_json(p)})).collect();
    Ok((text, json!({"degree": c.degree(), "values": js})))
}

fn subdivide(c: &BezierCurve<BigRational>, t0: &BigRational, depth: u32) -> Result<(String, Value)> {
    if depth == 1 {
        let (l, r) = fraction_free::subdivide(c, t0);
        let text = format!("left:  {l}\nright: {r}");
        return Ok((
            text,
            json!({"t": t0.to_string(), "left": points_json(l.points()), "right": points_json(r.points())}),
        ));
    }
    output_limit("subdivision output (pieces × points)", (c.degree() + 1) << depth.min(40), MAX_SUBDIVISION_POINTS)?;
    let pieces = fraction_free::subdivide_repeatedly(c, t0, depth)?;
    let ivs = subdivision_intervals(t0, depth);
    let text = pieces.iter().zip(&ivs).map(|(p, (a, b))| format!("[{a}, {b}]: {p}")).collect::<Vec<_>>().join("\n");
    let js: Vec<Value> = pieces
        .iter()
        .zip(&ivs)
        .map(|(p, (a, b))| json!({"interval": [a.to_string(), b.to_string()], "points": points_json(p.points())}))
        .collect();
    Ok((text, json!({"t": t0.to_string(), "depth": depth, "pieces": js})))
}

fn triangle(c: &BezierCurve<BigRational>, t: &BigRational) -> Result<(String, Value)> {
    let tri = fraction_free::triangle(c, t);
    let text = tri
        .rows
        .iter()
        .enumerate()
        .map(|(r, row)| {
            let pts: Vec<String> = row.iter().map(|p| p.to_string()).collect();
            format!("r={r}: {}", pts.join(" "))
        })
        .collect::<Vec<_>>()
        .join("\n");
    let rows: Vec<Value> = tri.rows.iter().map(|r| points_json(r)).collect();
    Ok((text, json!({"t": t.to_string(), "rows": rows, "point": point_json(tri.point())})))
}

fn power(c: &BezierCurve<BigRational>) -> (String, Value) {
    let coeffs = fraction_free::power_coefficients(c);
    let names = ["x", "y", "z"];
    let lines: Vec<String> = (0..c.dim())
        .map(|k| {
            let name = names.get(k).map(|s| s.to_string()).unwrap_or(format!("x{k}"));
            let poly: Vec<BigRational> = coeffs.iter().map(|p| p.coords[k].clone()).collect();
            format!("{name}(t) = {}", format_polynomial(&poly, "t"))
        })
        .collect();
    let mut value = json!({"degree": c.degree(), "coefficients": points_json(&coeffs)});
    if c.degree() <= MAX_MATRIX_DEGREE {
        let matrix: Vec<Vec<String>> = crate::bernstein::bernstein_to_power_matrix(c.degree())
            .iter()
            .map(|r| r.iter().map(|v| v.to_string()).collect())
            .collect();
        value["matrix"] = json!(matrix);
    }
    (lines.join("\n"), value)
}

/// `c0 + c1 t + c2 t^2 …` with exact coefficients, zero terms omitted (`0` for the zero polynomial).
pub fn format_polynomial(coeffs: &[BigRational], var: &str) -> String {
    let mut s = String::new();
    for (k, c) in coeffs.iter().enumerate() {
        if Scalar::is_zero(c) {
            continue;
        }
        let neg = crate::scalar::Exact::sign(c) == std::cmp::Ordering::Less;
        let mag = if neg { -c.clone() } else { c.clone() };
        if s.is_empty() {
            s.push_str(if neg { "-" } else { "" });
        } else {
            s.push_str(if neg { " - " } else { " + " });
        }
        let one = mag == crate::scalar::rat(1);
        match k {
            0 => s.push_str(&mag.to_string()),
            _ => {
                if !one {
                    s.push_str(&mag.to_string());
                    if !mag.is_integer() {
                        s.push('*');
                    }
                }
                s.push_str(var);
                if k > 1 {
                    s.push_str(&format!("^{k}"));
                }
            }
        }
    }
    if s.is_empty() { "0".into() } else { s }
}

fn classify(c: &BezierCurve<BigRational>, float: bool) -> Result<(String, Value)> {
    use crate::classify::{classify, loop_blinn};
    use crate::moving_line::MovingLines;
    let k = classify(c)?;
    let params = |ps: &[crate::classify::Parameter]| -> Value { ps.iter().map(|p| json!(p.to_string())).collect() };
    let floats = |ps: &[crate::classify::Parameter]| -> Value { ps.iter().map(|p| json!(p.to_f64())).collect() };
    let mut v = json!({
        "degree": k.degree,
        "real_degree": k.real_degree,
        "collinear": k.collinear,
        "class": k.class.as_str(),
        "reason": k.reason,
        "node_type": k.node_type.map(|n| n.as_str()),
        "double_point": k.double_point.as_ref().map(point_json),
        "double_point_parameters": params(&k.double_point_parameters),
        "cusp_parameters": params(&k.cusp_parameters),
        "inflection_parameters": params(&k.inflection_parameters),
        "segment": {
            "loop": k.segment.has_loop,
            "cusp": k.segment.has_cusp,
            "inflections": k.segment.inflections,
            "category": k.segment.category.as_str(),
        },
        "invariants": {"A": k.invariants[0].to_string(), "B": k.invariants[1].to_string(), "C": k.invariants[2].to_string()},
    });
    if let Some((te, d)) = &k.t_e_and_d {
        v["t_E"] = json!(te.to_string());
        v["d"] = json!(d.to_string());
    }
    if c.degree() == 3 {
        let ml = MovingLines::new(c)?;
        let verified = ml.verify().is_ok();
        let (lb, lb_node) = loop_blinn(c);
        v["moving_lines"] = json!({
            "L00": point_json(&ml.l0[0]), "L01": point_json(&ml.l0[1]),
            "L10": point_json(&ml.l1[0]), "L11": point_json(&ml.l1[1]), "L12": point_json(&ml.l1[2]),
            "D": point_json(&ml.double_point),
            "t_E": ml.t_e().map(|t| t.to_string()),
            "verified": verified,
        });
        if let Ok(map) = crate::canonical::canonical_map(c, crate::canonical::Formulas::Corrected) {
            let proved = map.prove(c);
            v["canonical"] = json!({
                "equation": crate::canonical::canonical_equation(map.node),
                "matrix": map.matrix.iter().map(|r| r.iter().map(|x| x.to_string()).collect::<Vec<_>>()).collect::<Vec<_>>(),
                "t_E": map.t_e.to_string(),
                "t_F": map.t_f.to_string(),
                "parameter": "(t - t_E)/(t_F - t_E)",
                "points": map.points.iter().map(|(n, p)| (n.to_string(), json!(p.coords.iter().map(|x| x.to_string()).collect::<Vec<_>>()))).collect::<serde_json::Map<_, _>>(),
                "proved": proved.is_ok(),
                "certificate": match &proved { Ok(c) => c.to_string(), Err(e) => format!("counterexample {e}") },
            });
        }
        v["loop_blinn"] = json!({
            "d1": lb[0].to_string(), "d2": lb[1].to_string(), "d3": lb[2].to_string(),
            "node_type": lb_node.map(|n| n.as_str()),
        });
    }
    if float {
        v["float"] = json!({
            "double_point_parameters": floats(&k.double_point_parameters),
            "cusp_parameters": floats(&k.cusp_parameters),
            "inflection_parameters": floats(&k.inflection_parameters),
            "double_point": k.double_point.as_ref().map(|p| p.to_f64().coords),
        });
    }
    let show = |ps: &[crate::classify::Parameter]| -> String {
        ps.iter()
            .map(|p| if float { format!("{p} (≈{:.6})", p.to_f64()) } else { p.to_string() })
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut text = format!("{}: {}", k.class, k.reason);
    if let Some(dp) = &k.double_point {
        text += &format!("; double point {dp}");
    }
    if !k.double_point_parameters.is_empty() {
        text += &format!(" at t = {}", show(&k.double_point_parameters));
    }
    if !k.inflection_parameters.is_empty() {
        text += &format!("; inflections at t = {}", show(&k.inflection_parameters));
    }
    if k.collinear && !k.cusp_parameters.is_empty() {
        text += &format!("; turns back at t = {}", show(&k.cusp_parameters));
    }
    text += &format!(
        "; on [0,1]: {}{}{} inflection{} ({})",
        if k.segment.has_loop { "loop, " } else { "" },
        if k.segment.has_cusp { "cusp, " } else { "" },
        k.segment.inflections,
        if k.segment.inflections == 1 { "" } else { "s" },
        k.segment.category.as_str()
    );
    Ok((text, v))
}

fn classify_weighted(
    c: &BezierCurve<BigRational>,
    weights: Option<&[BigRational]>,
    homogeneous: bool,
) -> Result<(String, Value)> {
    let h: Vec<Point<BigRational>> = if homogeneous {
        if weights.is_some() {
            return Err(Error::InvalidArgument { message: "give --weights or --homogeneous, not both".into() });
        }
        c.points().to_vec()
    } else {
        let w = weights.expect("weights given");
        if w.len() != c.points().len() {
            return Err(Error::InvalidArgument {
                message: format!("{} weights for {} control points", w.len(), c.points().len()),
            });
        }
        c.points().iter().zip(w).map(|(p, w)| p.to_homogeneous(w)).collect()
    };
    let k = crate::rational_cubic::classify_rational(&h)?;
    let params: Vec<String> = k.double_point_parameters.iter().map(|p| p.to_string()).collect();
    let v = json!({
        "rational": true,
        "class": k.class,
        "reason": k.reason,
        "node_type": k.node_type.map(|n| n.as_str()),
        "double_point": k.double_point.as_ref().map(point_json),
        "double_point_homogeneous": k.double_point_homogeneous.as_ref().map(point_json),
        "double_point_at_infinity": k.at_infinity,
        "double_point_parameters": params,
        "parameter_at_infinity": k.parameter_at_infinity,
        "segment": {"loop": k.has_loop, "cusp": k.has_cusp},
    });
    let mut text = k.class.to_string();
    if let Some(n) = k.node_type {
        text += &format!(" ({})", n.as_str());
    }
    text += &format!(": {}", k.reason);
    if !params.is_empty() {
        text += &format!("; finite double-point parameters t = {}", params.join(", "));
    }
    Ok((text, v))
}

fn prove(
    paths: &[std::path::PathBuf],
    filter: Option<&str>,
    json_out: bool,
    junit: Option<&std::path::Path>,
    write_readme: Option<&std::path::Path>,
    out: &mut dyn Write,
) -> i32 {
    use crate::catalogue;
    use std::io::IsTerminal;
    let paths = if paths.is_empty() { vec![catalogue::default_path()] } else { paths.to_vec() };
    let claims = match catalogue::load(&paths) {
        Ok(c) => c,
        Err(e) => {
            eprintln!("casteljau: {e}");
            return 2;
        }
    };
    let claims: Vec<_> = claims.into_iter().filter(|c| filter.is_none_or(|f| c.id.contains(f))).collect();
    let progress = std::io::stderr().is_terminal() && !json_out;
    let (mut passed, mut failed, mut malformed) = (0, 0, 0);
    let mut results = Vec::new();
    for (k, c) in claims.iter().enumerate() {
        if progress {
            eprint!("\r\x1b[K[{}/{}] {}", k + 1, claims.len(), c.id);
        }
        let r = match catalogue::check(c) {
            Ok(r) => r,
            Err(e) => {
                malformed += 1;
                if progress {
                    eprint!("\r\x1b[K");
                }
                eprintln!("casteljau: {e}");
                continue;
            }
        };
        if r.passed() {
            passed += 1;
        } else {
            failed += 1;
        }
        let line = if json_out {
            json!({
                "id": r.id, "source": c.source, "statement": c.statement, "expected": r.expected.as_str(),
                "verdict": r.found.as_str(), "passed": r.passed(), "method": r.method, "detail": r.detail,
                "corrected": r.corrected_detail, "seconds": r.seconds,
            })
            .to_string()
        } else {
            format!(
                "{} {:<44} {:<17} {:<13} {:>8.4}s  {}",
                if r.passed() { "ok  " } else { "FAIL" },
                r.id,
                r.found.as_str(),
                r.method,
                r.seconds,
                r.detail
            )
        };
        if progress {
            eprint!("\r\x1b[K");
        }
        if writeln!(out, "{line}").is_err() {
            return 2;
        }
        results.push(r);
    }
    if !json_out {
        let _ = writeln!(out, "{passed} passed, {failed} failed");
    }
    if let Some(path) = junit
        && let Err(e) = std::fs::write(path, catalogue::junit(&results))
    {
        eprintln!("casteljau: cannot write {}: {e}", path.display());
        return 2;
    }
    if let Some(path) = write_readme {
        if malformed > 0 || filter.is_some() {
            eprintln!("casteljau: --write-readme needs the whole catalogue, checked without errors");
            return 2;
        }
        if let Err(e) = std::fs::write(path, catalogue::readme(&claims, &results)) {
            eprintln!("casteljau: cannot write {}: {e}", path.display());
            return 2;
        }
    }
    if malformed > 0 {
        2
    } else if failed == 0 {
        0
    } else {
        1
    }
}
