//! The block reader of batch input: a file or stdin streamed as [`Block`]s of whole lines
//! (about [`BLOCK_BYTES`] each), with line numbers, for the workers of [`crate::pipeline`].

use std::io::Read;

/// Bytes per block of a streamed batch (whole lines; one worker task each).
pub const BLOCK_BYTES: usize = 16 * 1024;

/// Longest accepted input line, in bytes.
pub const MAX_LINE_BYTES: usize = 16 * 1024 * 1024;

/// The batch input of a file or stdin, streamed as [`Block`]s of whole lines. A line ends at
/// `\n`, `\r\n` or a lone `\r` (classic Mac); a line longer than [`MAX_LINE_BYTES`] becomes an
/// error for that line only (the rest of it is skipped unread into memory).
pub(crate) struct Blocks {
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
pub(crate) struct Block {
    first: usize,
    bytes: Vec<u8>,
    error: Option<String>,
}

impl Block {
    /// Calls `f` with the number and text (without its line end) of every line that is not blank
    /// or a `#` comment; an error for a line that is not UTF-8. A UTF-8 byte-order mark opening
    /// line 1 is dropped.
    pub(crate) fn for_each_line(&self, mut f: impl FnMut(usize, std::result::Result<&str, String>)) {
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
    pub(crate) fn open(source: Option<&str>) -> std::result::Result<Self, String> {
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
