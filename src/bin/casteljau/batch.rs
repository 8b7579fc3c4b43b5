//! Reading curves from the command line, a file or stdin, the limits on input and output, and
//! writing one answer per curve (text, or JSON Lines with the input's `line`).
//!
//! Exit codes: `0` success, `1` a check failed, `2` bad input. In a batch every line is
//! answered; a bad line gets an error (with its line number) and the exit code is 2 at the end.

use crate::args::{CurveArgs, RationalArgs};
use casteljau::curve::bezier::BezierCurve;
use casteljau::error::{Error, Position, Result};
use casteljau::num::parse::{NumberMode, parse_number_in, parse_numbers};
use casteljau::num::point::Point;
use casteljau::rational::rational_bezier::RationalBezier;
use num_rational::BigRational;
use serde_json::{Value, json};
use std::io::{IsTerminal, Read, Write};
use std::sync::{Condvar, Mutex};

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
        casteljau::curve::bezier::parse_curve_in(text, args.dim, line, args.numbers.into()).and_then(|c| f(&c))
    })
}

/// [`batch`] on the raw text of each input line (for inputs that are not a control polygon,
/// such as JSON Lines splines): `f` gets the line number and the text.
///
/// Input is streamed in blocks of whole lines ([`Blocks`], about [`BLOCK_BYTES`] each): each of
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
    let Some(pool) = thread_pool(args.threads) else { return 2 };
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

/// Renders `blocks` on `threads` workers and writes them in input order as they are ready: each
/// worker takes the next block from the reader (under a lock), renders it and sends it to this
/// thread, which writes the blocks in order. At most `4 × threads` blocks are taken and not yet
/// written, so memory stays bounded however far one slow block holds the order back. Returns
/// false when `write` reports stdout closed (the workers then stop).
fn ordered_parallel(
    threads: usize,
    blocks: &mut Blocks,
    render: &(dyn Fn(&Block) -> Rendered + Sync),
    write: &mut dyn FnMut(Rendered) -> bool,
) -> bool {
    let limit = 4 * threads;
    // (reader, next sequence number, blocks in flight, stop)
    let state = Mutex::new((blocks, 0usize, 0usize, false));
    let room = Condvar::new();
    let (tx, rx) = std::sync::mpsc::channel::<(usize, Rendered)>();
    std::thread::scope(|scope| {
        for _ in 0..threads {
            let tx = tx.clone();
            let (state, room) = (&state, &room);
            scope.spawn(move || {
                loop {
                    let (seq, block) = {
                        let mut s = state.lock().unwrap_or_else(|p| p.into_inner());
                        while s.2 >= limit && !s.3 {
                            s = room.wait(s).unwrap_or_else(|p| p.into_inner());
                        }
                        if s.3 {
                            return;
                        }
                        let Some(block) = s.0.next() else { return };
                        s.1 += 1;
                        s.2 += 1;
                        (s.1 - 1, block)
                    };
                    if tx.send((seq, render(&block))).is_err() {
                        return;
                    }
                }
            });
        }
        drop(tx);
        let mut waiting: std::collections::BTreeMap<usize, Rendered> = std::collections::BTreeMap::new();
        let mut next = 0;
        let mut open = true;
        for (seq, r) in rx {
            waiting.insert(seq, r);
            while let Some(r) = waiting.remove(&next) {
                next += 1;
                open = open && write(r);
                let mut s = state.lock().unwrap_or_else(|p| p.into_inner());
                s.2 -= 1;
                s.3 |= !open;
                room.notify_all();
            }
            if !open {
                break;
            }
        }
        open
    })
}

/// The output of one block: stdout bytes (answers, and errors in JSON mode), stderr bytes
/// (errors in text mode), the exit code so far (0 or 2) and whether a check failed.
#[derive(Default)]
struct Rendered {
    out: Vec<u8>,
    err: Vec<u8>,
    code: i32,
    failed: bool,
    last_line: usize,
}

impl Rendered {
    /// The JSON line of `direct`, when it answers: `{"line":N,` and the object's fields.
    fn direct(&mut self, line: usize, text: &str, direct: &(dyn Fn(&str, &mut Vec<u8>) -> bool + Sync)) -> bool {
        let start = self.out.len();
        self.out.extend_from_slice(b"{\"line\":");
        self.out.extend_from_slice(itoa::Buffer::new().format(line).as_bytes());
        let body = self.out.len();
        if !direct(text, &mut self.out) {
            self.out.truncate(start);
            return false;
        }
        if self.out.len() == body + 2 {
            self.out.truncate(body); // `{}`
            self.out.push(b'}');
        } else {
            self.out[body] = b',';
        }
        self.out.push(b'\n');
        self.last_line = line;
        true
    }

    /// Renders the answer of `line` (`None`: a single curve from the command line).
    fn add(&mut self, json: bool, line: Option<usize>, result: Result<Answer>) {
        self.last_line = line.unwrap_or(0);
        let out = &mut self.out;
        // writing to a Vec cannot fail
        let _ = match result {
            Ok(Answer { text, json: answer, failed }) => {
                self.failed |= failed;
                if json {
                    match (answer, line) {
                        (Json::Value(mut value), line) => {
                            if let (Some(l), Some(obj)) = (line, value.as_object_mut()) {
                                obj.insert("line".into(), json!(l));
                            }
                            writeln!(out, "{value}")
                        }
                        (Json::Object(s), Some(l)) => {
                            out.extend_from_slice(b"{\"line\":");
                            out.extend_from_slice(itoa::Buffer::new().format(l).as_bytes());
                            if s.len() > 2 {
                                out.push(b',');
                                out.extend_from_slice(&s.as_bytes()[1..]);
                            } else {
                                out.push(b'}');
                            }
                            out.push(b'\n');
                            Ok(())
                        }
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
                self.code = 2;
                let e = match (e, line) {
                    (Error::EmptyCurve { .. }, l) => Error::EmptyCurve { line: l },
                    (e, _) => e,
                };
                if json {
                    writeln!(out, "{}", json!({"line": line, "error": e.to_string()}))
                } else {
                    match line {
                        Some(l) if e.line().is_none() => writeln!(self.err, "casteljau: line {l}: {e}"),
                        _ => writeln!(self.err, "casteljau: {e}"),
                    }
                }
            }
        };
    }
}

/// Writes a block's output (stderr first: its lines come before later answers on a terminal);
/// false once stdout is closed (e.g. a pipe).
fn write_rendered(out: &mut dyn Write, r: &Rendered) -> bool {
    if !r.err.is_empty() {
        let _ = out.flush();
        let _ = std::io::stderr().write_all(&r.err);
    }
    out.write_all(&r.out).is_ok()
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

/// Bytes per block of a streamed batch (whole lines; one worker task each).
pub const BLOCK_BYTES: usize = 16 * 1024;

/// Longest accepted input line, in bytes.
pub const MAX_LINE_BYTES: usize = 16 * 1024 * 1024;

/// The batch input of a file or stdin, streamed as [`Block`]s of whole lines. A line ends at
/// `\n`, `\r\n` or a lone `\r` (classic Mac); a line longer than [`MAX_LINE_BYTES`] becomes an
/// error for that line only (the rest of it is skipped unread into memory).
struct Blocks {
    reader: Box<dyn Read + Send>,
    /// Bytes read and not yet handed out.
    pending: Vec<u8>,
    /// How far `pending` has been searched for line ends, and the end of its last complete line.
    scanned: usize,
    complete: usize,
    /// Lines handed out so far.
    number: usize,
    eof: bool,
    /// Skipping the rest of an over-long line; `after_cr`: a `\n` right after is part of its end.
    skipping: bool,
    after_cr: bool,
}

/// Whole lines from the input, numbered from `first`; or an error for the line `first`.
struct Block {
    first: usize,
    bytes: Vec<u8>,
    error: Option<String>,
}

impl Block {
    /// Calls `f` with the number and text (without its line end) of every line that is not blank
    /// or a `#` comment; an error for a line that is not UTF-8. A UTF-8 byte-order mark opening
    /// line 1 is dropped.
    fn for_each_line(&self, mut f: impl FnMut(usize, std::result::Result<&str, String>)) {
        if let Some(e) = &self.error {
            return f(self.first, Err(e.clone()));
        }
        let b = &self.bytes;
        let (mut start, mut number) = (0, self.first);
        while start < b.len() {
            let end = b[start..].iter().position(|&c| c == b'\n' || c == b'\r').map_or(b.len(), |i| start + i);
            let mut line = &b[start..end];
            start = end + 1;
            if end < b.len() && b[end] == b'\r' && b.get(end + 1) == Some(&b'\n') {
                start += 1;
            }
            if number == 1 && line.starts_with(&[0xEF, 0xBB, 0xBF]) {
                line = &line[3..];
            }
            match std::str::from_utf8(line) {
                Ok(text) => {
                    let trimmed = text.trim();
                    if !trimmed.is_empty() && !trimmed.starts_with('#') {
                        f(number, Ok(text));
                    }
                }
                Err(e) => f(number, Err(format!("not UTF-8 (byte {} of the line)", e.valid_up_to() + 1))),
            }
            number += 1;
        }
    }
}

impl Blocks {
    fn open(source: Option<&str>) -> std::result::Result<Self, String> {
        let reader: Box<dyn Read + Send> = match source {
            None | Some("-") => Box::new(std::io::stdin()),
            Some(path) => Box::new(std::fs::File::open(path).map_err(|e| format!("cannot open {path}: {e}"))?),
        };
        Ok(Blocks {
            reader,
            pending: Vec::new(),
            scanned: 0,
            complete: 0,
            number: 0,
            eof: false,
            skipping: false,
            after_cr: false,
        })
    }

    /// Reads more input into `pending` (at most [`BLOCK_BYTES`] at a time); records the end.
    fn fill(&mut self) -> std::io::Result<()> {
        let len = self.pending.len();
        self.pending.resize(len + BLOCK_BYTES, 0);
        let read = loop {
            match self.reader.read(&mut self.pending[len..]) {
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
                other => break other,
            }
        };
        self.pending.truncate(len + *read.as_ref().unwrap_or(&0));
        if read.as_ref().is_ok_and(|&n| n == 0) {
            self.eof = true;
        }
        read.map(|_| ())
    }

    /// Searches the new bytes of `pending` for line ends. A `\r` as the very last byte (before
    /// the end of the input) may be the first half of a `\r\n`: it is left for the next read.
    fn scan(&mut self) {
        let b = &self.pending;
        let mut i = self.scanned;
        while i < b.len() {
            match b[i] {
                b'\n' => self.complete = i + 1,
                b'\r' if i + 1 < b.len() => self.complete = if b[i + 1] == b'\n' { i + 2 } else { i + 1 },
                b'\r' if self.eof => self.complete = i + 1,
                b'\r' => break,
                _ => {}
            }
            i += if b[i] == b'\r' && b.get(i + 1) == Some(&b'\n') { 2 } else { 1 };
        }
        self.scanned = i;
    }

    /// Drops the rest of an over-long line, through its line end.
    fn skip(&mut self) -> std::io::Result<()> {
        while self.skipping {
            if self.pending.is_empty() {
                if self.eof {
                    self.skipping = false;
                    break;
                }
                self.fill()?;
                continue;
            }
            if self.after_cr {
                if self.pending[0] == b'\n' {
                    self.pending.remove(0);
                }
                self.skipping = false;
                self.after_cr = false;
                break;
            }
            match self.pending.iter().position(|&c| c == b'\n' || c == b'\r') {
                Some(i) => {
                    let cr = self.pending[i] == b'\r';
                    self.pending.drain(..=i);
                    if cr {
                        self.after_cr = true; // a following \n is part of this line end
                    } else {
                        self.skipping = false;
                    }
                }
                None => self.pending.clear(),
            }
        }
        Ok(())
    }

    /// Hands out `pending[..end]` as a block.
    fn hand_out(&mut self, end: usize) -> Block {
        let rest = self.pending.split_off(end);
        let bytes = std::mem::replace(&mut self.pending, rest);
        let first = self.number + 1;
        let b = &bytes;
        let mut lines = 0;
        let mut i = 0;
        while i < b.len() {
            match b[i] {
                b'\n' => lines += 1,
                b'\r' => {
                    lines += 1;
                    if b.get(i + 1) == Some(&b'\n') {
                        i += 1;
                    }
                }
                _ => {}
            }
            i += 1;
        }
        if b.last().is_some_and(|&c| c != b'\n' && c != b'\r') {
            lines += 1; // the last line of the input, without a line end
        }
        self.number += lines;
        self.scanned -= end.min(self.scanned);
        self.complete -= end.min(self.complete);
        Block { first, bytes, error: None }
    }

    fn error(&mut self, message: String) -> Block {
        self.number += 1;
        Block { first: self.number, bytes: vec![], error: Some(message) }
    }
}

impl Iterator for Blocks {
    type Item = Block;
    fn next(&mut self) -> Option<Block> {
        loop {
            if let Err(e) = self.skip() {
                self.eof = true;
                self.pending.clear();
                return Some(self.error(format!("cannot read input: {e}")));
            }
            self.scan();
            let partial = self.pending.len() - self.complete;
            if partial > MAX_LINE_BYTES {
                if self.complete > 0 {
                    let end = self.complete;
                    return Some(self.hand_out(end));
                }
                // an over-long line: an error for it, the rest of it skipped
                self.pending.clear();
                (self.scanned, self.complete, self.skipping) = (0, 0, true);
                return Some(self.error(format!("line longer than {MAX_LINE_BYTES} bytes")));
            }
            if self.complete >= BLOCK_BYTES || (self.eof && self.complete > 0) {
                let end = self.complete;
                return Some(self.hand_out(end));
            }
            if self.eof {
                if self.pending.is_empty() {
                    return None;
                }
                let end = self.pending.len();
                return Some(self.hand_out(end));
            }
            if let Err(e) = self.fill() {
                self.eof = true;
                self.pending.clear();
                return Some(self.error(format!("cannot read input: {e}")));
            }
        }
    }
}
