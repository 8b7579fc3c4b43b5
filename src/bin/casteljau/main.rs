//! The `casteljau` binary: parses the command line, dispatches each command to its runner and
//! exits with its code. The maths, its work budgets and its typed results live in the library;
//! this binary reads input, renders text or JSON and chooses exit codes.
//!
//! * [`args`]: the clap structs, one per command or shared group; [`options`]: option values
//!   (exact numbers, weights, a patch's degree).
//! * [`batch`]: the drivers reading curves (argument, file, stdin) and answering each, on
//!   [`input`]'s blocks of lines and [`pipeline`]'s ordered workers; [`render`]: answers as text
//!   or JSON Lines, and exit codes.
//! * [`curves`]: the curve commands; [`answers`]: their text, from the library's typed results.
//! * [`commands`]: the commands with their own input and output (`prove`, `plot`, `surface`,
//!   `gallery`); [`splines`]: the `spline` command (knot vectors, JSON Lines splines); [`scan`]:
//!   fonts, SVG and batches, segment by segment; [`intersect`]: `intersect` and `winding`;
//!   [`check`]: a float library's answers against the exact ones; [`shapes`]: `boolean` and
//!   `arrange` on path data and SVG files, [`glyphs`]: `boolean simplify` on every glyph of fonts;
//!   [`remove_overlaps`]: overlap removal that writes the font.
//! * [`finite`]: no `inf` or `NaN` in any output (a refusal instead); [`files`]: output files,
//!   all or nothing.

mod answers;
mod args;
mod batch;
mod check;
mod commands;
mod curves;
mod files;
mod finite;
mod glyphs;
mod input;
mod intersect;
mod lint;
mod lint_draw;
mod lint_html;
mod lint_units;
mod options;
mod pipeline;
mod remove_overlaps;
mod remove_overlaps_html;
mod render;
mod scan;
mod shapes;
mod splines;
mod verdicts;
mod work_option;

use args::{Cli, Command};
use clap::Parser;
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
        Command::Eval { t, rational, curve } => curves::eval(&t, &rational, curve, out),
        Command::Subdivide { t, depth, rational, curve } => curves::subdivide(&t, depth, &rational, curve, out),
        Command::Elevate { by, rational, curve } => curves::elevate(by, &rational, curve, out),
        Command::Power { curve } => curves::power(&curve, out),
        Command::Triangle { t, curve } => curves::triangle(&t, &curve, out),
        Command::Derivative { order, curve } => curves::derivative(order, &curve, out),
        Command::Reduce { curve } => curves::reduce(&curve, out),
        Command::Implicit { poly, rational, curve } => curves::implicit(&poly, &rational, curve, out),
        Command::Defined { from, to, rational, curve } => curves::defined(&from, &to, &rational, curve, out),
        Command::Bbox { rational, curve } => curves::bbox(&rational, curve, out),
        Command::Conic { rational, curve } => curves::conic(&rational, curve, out),
        Command::Classify { float, detail, rational, curve } => curves::classify(float, detail, &rational, curve, out),
        Command::Surface { op } => commands::surface(op, out),
        Command::Plot(args) => commands::plot(args, out),
        Command::Gallery { dir } => commands::gallery(&dir, out),
        Command::Prove(args) => commands::prove(&args, out),
        Command::Check(args) => check::run(&args, out),
        Command::Spline { op } => splines::run(op, out),
        Command::Scan(args) => scan::run(&args, out),
        Command::Lint(args) => lint::run(&args, out),
        Command::Intersect(args) => intersect::run(&args, out),
        Command::Winding(args) => intersect::run_winding(&args, out),
        Command::Boolean(args) => shapes::boolean(&args, out),
        Command::Arrange(args) => shapes::arrange(&args, out),
        Command::RemoveOverlaps(args) => remove_overlaps::run(&args, out),
    }
}
