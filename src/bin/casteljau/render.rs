//! Rendering answers: one [`Answer`] per curve (text, JSON, whether a check failed), rendered
//! per block of input into [`Rendered`] bytes (stdout, stderr, exit code) and written in order.
//! In JSON mode every answer and every error is one line (JSON Lines) naming its input `line`.

use casteljau::error::{Error, Result};
use serde_json::Value;
use std::io::Write;

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
    /// A result whose float field (named) is not finite: refused in JSON mode
    /// ([`crate::finite`]).
    Overflow(String),
}

impl From<(String, Value)> for Answer {
    fn from((text, json): (String, Value)) -> Self {
        Answer { text, json: Json::Value(json), failed: false }
    }
}

impl Answer {
    /// An answer whose JSON is `value`'s `Serialize` (as a [`Json::Value`]: keys in sorted order).
    pub fn typed(text: String, value: &impl serde::Serialize) -> Self {
        let json = match crate::finite::first_non_finite(value) {
            Some(field) => Json::Overflow(field),
            None => Json::Value(typed_json(value)),
        };
        Answer { text, json, failed: false }
    }

    /// A failed check (exit code 1) when `failed`.
    pub fn failed_if(mut self, failed: bool) -> Self {
        self.failed = failed;
        self
    }
}

/// The JSON value of a result type.
pub fn typed_json(value: &impl serde::Serialize) -> Value {
    serde_json::to_value(value).expect("exact strings and finite floats serialize")
}

/// The JSON line of an input line that could not be answered.
#[derive(serde::Serialize)]
struct ErrorLine {
    error: String,
    line: Option<usize>,
}

/// The output of one block: stdout bytes (answers, and errors in JSON mode), stderr bytes
/// (errors in text mode), the exit code so far (0 or 2) and whether a check failed.
#[derive(Default)]
pub(crate) struct Rendered {
    pub(crate) out: Vec<u8>,
    pub(crate) err: Vec<u8>,
    pub(crate) code: i32,
    pub(crate) failed: bool,
    pub(crate) last_line: usize,
}

impl Rendered {
    /// The JSON line of `direct`, when it answers: `{"line":N,` and the object's fields.
    pub(crate) fn direct(
        &mut self,
        line: usize,
        text: &str,
        direct: &(dyn Fn(&str, &mut Vec<u8>) -> bool + Sync),
    ) -> bool {
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
    pub(crate) fn add(&mut self, json: bool, line: Option<usize>, result: Result<Answer>) {
        self.last_line = line.unwrap_or(0);
        // finite output or a refusal: the float fields in JSON, the numbers of the text
        let result = result.and_then(|a| {
            match &a.json {
                Json::Overflow(field) if json => {
                    return Err(crate::finite::overflow("the answer", &format!("the float field {field}")));
                }
                _ if !json => crate::finite::check_text("the answer", &a.text)?,
                _ => {}
            }
            Ok(a)
        });
        let out = &mut self.out;
        // writing to a Vec cannot fail
        let _ = match result {
            Ok(Answer { text, json: answer, failed }) => {
                self.failed |= failed;
                if json {
                    match (answer, line) {
                        (Json::Value(mut value), line) => {
                            if let (Some(l), Some(obj)) = (line, value.as_object_mut()) {
                                obj.insert("line".into(), Value::from(l));
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
                        (Json::Overflow(_), _) => Ok(()), // refused above
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
                    // a curve given as the argument: say so, as a batch says its line
                    (Error::EmptyCurve { .. }, None) => Error::InvalidArgument {
                        message: "the curve argument is empty: a curve needs at least one control point".into(),
                    },
                    (e @ Error::TooLarge { what: "degree", .. }, None) => {
                        Error::InvalidArgument { message: format!("the curve argument: {e}") }
                    }
                    (Error::EmptyCurve { .. }, l) => Error::EmptyCurve { line: l },
                    (e, _) => e,
                };
                if json {
                    writeln!(out, "{}", typed_json(&ErrorLine { error: e.to_string(), line }))
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
pub(crate) fn write_rendered(out: &mut dyn Write, r: &Rendered) -> bool {
    if !r.err.is_empty() {
        let _ = out.flush();
        let _ = std::io::stderr().write_all(&r.err);
    }
    out.write_all(&r.out).is_ok()
}
