//! The batch drivers: reading curves from the command line, a file or stdin and writing one
//! answer per curve (text, or JSON Lines with the input's `line`), on `--threads` workers.
//!
//! Exit codes: `0` success, `1` a check failed, `2` bad input. In a batch every line is
//! answered; a bad line gets an error (with its line number) and the exit code is 2 at the end.

use crate::args::{CurveArgs, RationalArgs};
use crate::input::{Block, Blocks};
use crate::pipeline::ordered_parallel;
use crate::render::{Rendered, write_rendered};
use casteljau::curve::BezierCurve;
use casteljau::error::{Error, Result};

use num_rational::BigRational;
use std::io::{IsTerminal, Write};
use std::sync::Mutex;

use crate::options::{Weights, parse_weights_in};

// the names the `spline`, `scan`, `intersect` and `winding` runners import from here
pub use crate::options::{numbers, numbers_in, option_number, parse_weights};
pub use crate::pipeline::thread_pool;
pub use crate::render::{Answer, Json};

/// Largest accepted `--dim`.
pub const MAX_DIM: usize = 64;

/// [`batch`] for commands that accept rational curves: parses `--weights` once and reads points
/// with one more coordinate under `--homogeneous`.
pub fn rational_batch(
    rational: &RationalArgs,
    mut curve: CurveArgs,
    out: &mut dyn Write,
    f: impl Fn(&BezierCurve<BigRational>, Weights<'_>) -> Result<Answer> + Sync,
) -> i32 {
    let weights = match parse_weights_in(rational, curve.numbers.into()) {
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

/// Reads the curves (argument, file, or stdin) and answers each; exit 2 if any line was bad.
pub fn batch(
    args: &CurveArgs,
    out: &mut dyn Write,
    f: impl Fn(&BezierCurve<BigRational>) -> Result<Answer> + Sync,
) -> i32 {
    batch_lines(args, out, |line, text| {
        casteljau::curve::parse_curve_in(text, args.dim, line, args.numbers.into()).and_then(|c| f(&c))
    })
}

/// [`batch`] on the raw text of each input line (for inputs that are not a control polygon,
/// such as JSON Lines splines): `f` gets the line number and the text.
///
/// Input is streamed in blocks of whole lines ([`Blocks`], about [`BLOCK_BYTES`](crate::input::BLOCK_BYTES) each): each of
/// `--threads` workers reads the next block, splits it into lines, answers and renders them,
/// and this thread writes the blocks in input order as they are ready ([`ordered_parallel`];
/// with one thread: read, answer, write in turn). Memory is bounded by the blocks in flight,
/// not the input.
pub fn batch_lines(
    args: &CurveArgs,
    out: &mut dyn Write,
    f: impl Fn(Option<usize>, &str) -> Result<Answer> + Sync,
) -> i32 {
    batch_lines_with(args, out, &|_: &str, _: &mut Vec<u8>| false, f)
}

/// [`batch_lines`] with a direct route for JSON output: `direct(text, out)` either appends the
/// line's JSON object (`{…}`) to `out` and returns true, or leaves `out` alone and returns
/// false, and `f` answers the line.
pub fn batch_lines_with(
    args: &CurveArgs,
    out: &mut dyn Write,
    direct: &(dyn Fn(&str, &mut Vec<u8>) -> bool + Sync),
    f: impl Fn(Option<usize>, &str) -> Result<Answer> + Sync,
) -> i32 {
    if args.dim == 0 || args.dim > MAX_DIM {
        eprintln!("casteljau: --dim must be between 1 and {MAX_DIM}");
        return 2;
    }
    let Some(pool) = thread_pool(args.threads, args.curve.as_ref().map(|_| 1)) else { return 2 };
    let json = args.json;
    let mut blocks = match (&args.curve, &args.input) {
        (Some(_), Some(_)) => {
            eprintln!("casteljau: give a curve or --input, not both");
            return 2;
        }
        (Some(c), None) => {
            let mut r = Rendered::default();
            r.add(json, None, f(None, c));
            return match write_rendered(out, &r) {
                true if r.code == 0 && r.failed => 1,
                true => r.code,
                false => 2,
            };
        }
        (None, source) => match Blocks::open(source.as_deref()) {
            Ok(blocks) => {
                if source.as_deref().is_none_or(|s| s == "-") && std::io::stdin().is_terminal() {
                    eprintln!("casteljau: reading curves from stdin, one per line (end with Ctrl-D)");
                }
                blocks
            }
            Err(e) => {
                eprintln!("casteljau: {e}");
                return 2;
            }
        },
    };
    let progress = !args.quiet && std::io::stderr().is_terminal();
    let threads = pool.current_num_threads();
    drop(pool);
    // output buffers go back to a pool once written: reused, they are not faulted in again
    let buffers: Mutex<Vec<Vec<u8>>> = Mutex::new(vec![]);
    let render = |block: &Block| -> Rendered {
        let mut r = Rendered::default();
        if let Some(buffer) = buffers.lock().ok().and_then(|mut p| p.pop()) {
            r.out = buffer;
        }
        block.for_each_line(|line, text| match text {
            Ok(t) if json && r.direct(line, t, direct) => {}
            Ok(t) => r.add(json, Some(line), f(Some(line), t)),
            Err(e) => r.add(json, Some(line), Err(Error::InvalidArgument { message: e })),
        });
        r
    };
    let (mut code, mut failed) = (0, false);
    // writes one block's output; false once stdout is closed
    let mut write_block = |r: Rendered| -> bool {
        code = code.max(r.code);
        failed |= r.failed;
        if !write_rendered(out, &r) {
            return false;
        }
        if progress {
            eprint!("\r\x1b[K{} lines", r.last_line);
        }
        let mut b = r.out;
        b.clear();
        if let Ok(mut p) = buffers.lock() {
            p.push(b);
        }
        true
    };
    let open = if threads == 1 {
        blocks.all(|b| write_block(render(&b)))
    } else {
        ordered_parallel(threads, &mut blocks, &render, &mut write_block)
    };
    if !open {
        return code.max(2);
    }
    if progress {
        eprint!("\r\x1b[K");
    }
    if code == 0 && failed { 1 } else { code }
}
