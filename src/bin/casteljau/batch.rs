//! Reading curves from the command line, a file or stdin, the limits on input and output, and
//! writing one answer per curve (text, or JSON Lines with the input's `line`).
//!
//! Exit codes: `0` success, `1` a check failed, `2` bad input. In a batch every line is
//! answered; a bad line gets an error (with its line number) and the exit code is 2 at the end.

use crate::args::{CurveArgs, RationalArgs};
use casteljau::curve::bezier::BezierCurve;
use casteljau::error::{Error, Position, Result};
use casteljau::num::parse::{NumberMode, parse_number_in, parse_numbers, parse_points_in};
use casteljau::num::point::Point;
use casteljau::rational::rational_bezier::RationalBezier;
use num_rational::BigRational;
use rayon::prelude::*;
use serde_json::{Value, json};
use std::io::{BufRead, IsTerminal, Write};

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

/// The patch of `--degree m,n` from a curve line of `(m+1)(n+1)` points.
pub fn patch_of(
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
    let w = match parse_weights(rational)? {
        Some(w) if w.len() != pts.len() => {
            return Err(bad(format!("{} weights for {} control points", w.len(), pts.len())));
        }
        Some(w) => w,
        None => vec![casteljau::num::scalar::rat(1); pts.len()],
    };
    casteljau::surface::RationalPatch::new(rows, w.chunks(n + 1).map(|r| r.to_vec()).collect())
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
    pub json: Json,
    /// A check failed (exit code 1).
    pub failed: bool,
}

/// An answer's JSON object: a value, or already written out (from a result type's `Serialize`,
/// without the detour through a map); batch input adds `"line"` to either.
pub enum Json {
    /// A value (its keys print in sorted order).
    Value(Value),
    /// A serialized object (`{…}`); `"line"` is written first.
    Object(String),
}

impl From<(String, Value)> for Answer {
    fn from((text, json): (String, Value)) -> Self {
        Answer { text, json: Json::Value(json), failed: false }
    }
}

/// Largest accepted `--dim`.
pub const MAX_DIM: usize = 64;
/// Largest degree whose conversion matrix `power --json` includes.
pub const MAX_MATRIX_DEGREE: usize = 30;
/// Largest degree `triangle` prints (its output has (n+1)(n+2)/2 points).
pub const MAX_TRIANGLE_DEGREE: usize = 500;
/// Largest number of control points `subdivide --depth` prints.
pub const MAX_SUBDIVISION_POINTS: usize = 1 << 20;

/// An error when `value` exceeds `limit`.
pub fn output_limit(what: &'static str, value: usize, limit: usize) -> Result<()> {
    if value > limit { Err(Error::TooLarge { what, value, limit }) } else { Ok(()) }
}

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

/// Reads the curves (argument, file, or stdin) and answers each; exit 2 if any line was bad.
pub fn batch(
    args: &CurveArgs,
    out: &mut dyn Write,
    f: impl Fn(&BezierCurve<BigRational>) -> Result<Answer> + Sync,
) -> i32 {
    batch_lines(args, out, |line, text| {
        parse_points_in(text, args.dim, line, args.numbers.into()).and_then(BezierCurve::new).and_then(|c| f(&c))
    })
}

/// [`batch`] on the raw text of each input line (for inputs that are not a control polygon,
/// such as JSON Lines splines): `f` gets the line number and the text.
///
/// Input is streamed: lines are read in chunks of [`CHUNK_LINES`]; chunk k is answered on
/// `--threads` cores (rayon) while this thread writes chunk k − 1's answers in input order and
/// reads chunk k + 1 (with one thread: write, answer, read in turn), so memory is bounded by two
/// chunks, not the input.
pub fn batch_lines(
    args: &CurveArgs,
    out: &mut dyn Write,
    f: impl Fn(Option<usize>, &str) -> Result<Answer> + Sync,
) -> i32 {
    if args.dim == 0 || args.dim > MAX_DIM {
        eprintln!("casteljau: --dim must be between 1 and {MAX_DIM}");
        return 2;
    }
    let Some(pool) = thread_pool(args.threads) else { return 2 };
    let sequential = pool.current_num_threads() == 1;
    let answer = |(line, text): &(Option<usize>, std::result::Result<String, String>)| -> Result<Answer> {
        match text {
            Ok(t) => f(*line, t),
            Err(e) => Err(Error::InvalidArgument { message: e.clone() }),
        }
    };
    let mut source: Box<dyn Iterator<Item = (Option<usize>, std::result::Result<String, String>)>> =
        match (&args.curve, &args.input) {
            (Some(_), Some(_)) => {
                eprintln!("casteljau: give a curve or --input, not both");
                return 2;
            }
            (Some(c), None) => Box::new(std::iter::once((None, Ok(c.clone())))),
            (None, source) => match Lines::open(source.as_deref()) {
                Ok(lines) if source.as_deref().is_none_or(|s| s == "-") && std::io::stdin().is_terminal() => {
                    eprintln!("casteljau: reading curves from stdin, one per line (end with Ctrl-D)");
                    Box::new(lines)
                }
                Ok(lines) => Box::new(lines),
                Err(e) => {
                    eprintln!("casteljau: {e}");
                    return 2;
                }
            },
        };
    let progress = args.input.is_some() && !args.quiet && std::io::stderr().is_terminal();
    let mut code = 0;
    let mut failed = false;
    let mut done = 0usize;
    type Item = (Option<usize>, std::result::Result<String, String>);
    // writes one chunk's answers in order; false once stdout is closed
    let mut write_chunk = |chunk: &[Item], answers: Vec<Result<Answer>>| -> bool {
        for ((line, _), result) in chunk.iter().zip(answers) {
            let line = *line;
            let written = match result {
                Ok(Answer { text, json, failed: f }) => {
                    failed |= f;
                    if args.json {
                        match (json, line) {
                            (Json::Value(mut value), line) => {
                                if let (Some(l), Some(obj)) = (line, value.as_object_mut()) {
                                    obj.insert("line".into(), json!(l));
                                }
                                writeln!(out, "{value}")
                            }
                            (Json::Object(s), Some(l)) if s.len() > 2 => writeln!(out, "{{\"line\":{l},{}", &s[1..]),
                            (Json::Object(_), Some(l)) => writeln!(out, "{{\"line\":{l}}}"),
                            (Json::Object(s), None) => writeln!(out, "{s}"),
                        }
                    } else if let Some(l) = line {
                        // batch input: every answer names its line, like every error
                        if text.contains('\n') {
                            writeln!(out, "line {l}:\n  {}", text.replace('\n', "\n  "))
                        } else {
                            writeln!(out, "line {l}: {text}")
                        }
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
                        match line {
                            Some(l) if e.line().is_none() => eprintln!("casteljau: line {l}: {e}"),
                            _ => eprintln!("casteljau: {e}"),
                        }
                        Ok(())
                    }
                }
            };
            if written.is_err() {
                return false; // stdout closed (e.g. a pipe): stop quietly
            }
        }
        done += chunk.len();
        if progress {
            eprint!("\r\x1b[K{done} lines");
        }
        true
    };
    // Chunk k is answered on the pool while this thread writes chunk k − 1 and reads chunk k + 1.
    let mut pending: Option<(Vec<Item>, Vec<Result<Answer>>)> = None;
    let mut chunk: Vec<Item> = source.by_ref().take(CHUNK_LINES).collect();
    while !chunk.is_empty() {
        let (answers, next, open) = if sequential {
            // answer before freeing the previous chunk's answers: their memory is then reused
            // for the next chunk instead of going back to the system and faulting in again
            let answers: Vec<Result<Answer>> = chunk.iter().map(answer).collect();
            let open = pending.take().is_none_or(|(c, a)| write_chunk(&c, a));
            (answers, source.by_ref().take(CHUNK_LINES).collect(), open)
        } else {
            std::thread::scope(|scope| {
                let worker = scope.spawn(|| pool.install(|| chunk.par_iter().map(answer).collect::<Vec<_>>()));
                let open = pending.take().is_none_or(|(c, a)| write_chunk(&c, a));
                let next: Vec<Item> = if open { source.by_ref().take(CHUNK_LINES).collect() } else { vec![] };
                let answers = worker.join().unwrap_or_else(|p| std::panic::resume_unwind(p));
                (answers, next, open)
            })
        };
        if !open {
            return code.max(2);
        }
        pending = Some((std::mem::replace(&mut chunk, next), answers));
    }
    if let Some((c, a)) = pending.take()
        && !write_chunk(&c, a)
    {
        return code.max(2);
    }
    if progress {
        eprint!("\r\x1b[K");
    }
    if code == 0 && failed { 1 } else { code }
}

/// The worker pool of `--threads N` (0: all cores); `None` after saying why on stderr.
pub fn thread_pool(threads: usize) -> Option<rayon::ThreadPool> {
    match rayon::ThreadPoolBuilder::new().num_threads(threads).build() {
        Ok(p) => Some(p),
        Err(e) => {
            eprintln!("casteljau: cannot start {threads} threads: {e}");
            None
        }
    }
}

/// Lines per chunk of a streamed batch.
pub const CHUNK_LINES: usize = 4096;

/// Longest accepted input line, in bytes.
pub const MAX_LINE_BYTES: usize = 16 * 1024 * 1024;

/// The batch lines of a file or stdin, streamed: `(line number, text)` for every line that is
/// not blank or a `#` comment; a line that is not UTF-8 or longer than [`MAX_LINE_BYTES`] is an
/// error for that line only. A UTF-8 byte-order mark and LF, CRLF and CR-only (classic Mac)
/// line endings are accepted.
struct Lines {
    reader: Box<dyn BufRead>,
    number: usize,
}

impl Lines {
    fn open(source: Option<&str>) -> std::result::Result<Self, String> {
        let reader: Box<dyn BufRead> = match source {
            None | Some("-") => Box::new(std::io::BufReader::new(std::io::stdin())),
            Some(path) => Box::new(std::io::BufReader::new(
                std::fs::File::open(path).map_err(|e| format!("cannot open {path}: {e}"))?,
            )),
        };
        Ok(Lines { reader, number: 0 })
    }
}

/// Reads one line into `buf` (at most `limit` bytes): up to and including the first `\n`, or
/// the first `\r` (with a `\n` right after it, as in CRLF), which is stored as `\n`. Returns
/// the bytes consumed (0 at the end of the input).
fn read_line_any(reader: &mut dyn BufRead, buf: &mut Vec<u8>, limit: usize) -> std::io::Result<usize> {
    let mut consumed = 0;
    let mut after_cr = false;
    loop {
        let chunk = match reader.fill_buf() {
            Ok(c) => c,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if after_cr {
            // a CR ended the line; swallow the LF of a CRLF
            if chunk.first() == Some(&b'\n') {
                reader.consume(1);
                consumed += 1;
            }
            return Ok(consumed);
        }
        if chunk.is_empty() {
            return Ok(consumed);
        }
        let room = limit.saturating_sub(buf.len());
        let end = chunk.iter().take(room).position(|&b| b == b'\n' || b == b'\r');
        match end {
            Some(i) => {
                let cr = chunk[i] == b'\r';
                buf.extend_from_slice(&chunk[..i]);
                buf.push(b'\n');
                reader.consume(i + 1);
                consumed += i + 1;
                if !cr {
                    return Ok(consumed);
                }
                after_cr = true;
            }
            None => {
                let n = chunk.len().min(room);
                buf.extend_from_slice(&chunk[..n]);
                reader.consume(n);
                consumed += n;
                if buf.len() >= limit {
                    return Ok(consumed);
                }
            }
        }
    }
}

impl Iterator for Lines {
    type Item = (Option<usize>, std::result::Result<String, String>);
    fn next(&mut self) -> Option<Self::Item> {
        loop {
            let mut buf = Vec::new();
            let read = read_line_any(&mut self.reader, &mut buf, MAX_LINE_BYTES + 1);
            match read {
                Ok(0) => return None,
                Ok(_) => {}
                Err(e) => {
                    self.number += 1;
                    return Some((Some(self.number), Err(format!("cannot read input: {e}"))));
                }
            }
            self.number += 1;
            if buf.len() > MAX_LINE_BYTES && buf.last() != Some(&b'\n') {
                // skip the rest of the over-long line
                let mut rest = Vec::new();
                while read_line_any(&mut self.reader, &mut rest, MAX_LINE_BYTES).is_ok_and(|n| n > 0) {
                    if rest.last() == Some(&b'\n') {
                        break;
                    }
                    rest.clear();
                }
                return Some((Some(self.number), Err(format!("line longer than {MAX_LINE_BYTES} bytes"))));
            }
            if self.number == 1 && buf.starts_with(&[0xEF, 0xBB, 0xBF]) {
                buf.drain(..3);
            }
            let text = match String::from_utf8(buf) {
                Ok(t) => t,
                Err(e) => {
                    return Some((
                        Some(self.number),
                        Err(format!("not UTF-8 (byte {} of the line)", e.utf8_error().valid_up_to() + 1)),
                    ));
                }
            };
            let trimmed = text.trim();
            if trimmed.is_empty() || trimmed.starts_with('#') {
                continue;
            }
            return Some((Some(self.number), Ok(text.trim_end_matches(['\n', '\r']).to_string())));
        }
    }
}
