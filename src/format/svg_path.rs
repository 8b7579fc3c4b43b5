//! SVG path data (the `d` attribute) read exactly: every number token is the exact decimal it
//! spells (or, in [`NumberMode::Binary64`], the `f64` it rounds to, taken exactly), so the
//! segments are the curves the path denotes, not their floating-point images.
//!
//! Commands (SVG 1.1 §8.3 / SVG 2 §9.3): `M L H V C S Q T A Z`, absolute (upper case) and
//! relative (lower case), implicit repetition (extra coordinate pairs after `M` are line-tos),
//! smooth reflections (`S` reflects the previous `C`/`S` control point, `T` the previous
//! `Q`/`T` one, else the current point), compact numbers (`1.5.5` is `1.5 .5`, `1-2` is
//! `1 -2`) and packed arc flags (`a1 1 0 01 5 5`). `Z` adds the closing line when it has
//! non-zero length and returns to the subpath's start. Reading takes time linear in the length
//! of the text; a subpath of more than 100,000 segments is refused as it passes the limit.
//!
//! Elliptical arcs are not polynomial Bézier curves: an arc becomes a
//! [`Segment::Skipped`] with its exact ends (its reason names the column where its command starts), except where the SVG rules make it exact — an arc
//! whose ends coincide is omitted and one with `rx = 0` or `ry = 0` is a straight line
//! (SVG 1.1 §F.6.2).
//!
//! Written by hand: the SVG path crates (`svgtypes`, `kurbo`) parse numbers into `f64`, which
//! would round `0.1` before casteljau could see it.
//!
//! # Example
//! ```
//! use casteljau::format::{Segment, parse_path};
//! use casteljau::num::NumberMode;
//! let subpaths = parse_path("M0 0 c1 1 2 1 3 0 s1-1 2 0z", NumberMode::Exact).unwrap();
//! assert_eq!(subpaths.len(), 1);
//! let segs = &subpaths[0].segments;
//! assert_eq!(segs.len(), 3); // two cubics and the closing line
//! let Segment::Bezier(s) = &segs[1] else { panic!() };
//! // S reflects the previous control point (2, 1) about (3, 0)
//! assert_eq!(s[1].to_string(), "(4, -1)");
//! assert!(subpaths[0].closed);
//! ```

use crate::curve::bezier::BezierCurve;
use crate::error::{Error, Position, Result};
use crate::format::{Contour, Segment};
use crate::num::parse::{NumberMode, parse_number_in};
use crate::num::point::Point;
use crate::num::scalar::{Scalar, rat};
use crate::path::{ClosedPath, MAX_PATH_SEGMENTS};
use num_rational::BigRational;

/// Longest accepted path data, in bytes.
pub const MAX_PATH_BYTES: usize = 64 * 1024 * 1024;

type P = Point<BigRational>;

fn pt(x: BigRational, y: BigRational) -> P {
    Point::new(vec![x, y])
}

/// The byte scanner: numbers, flags and commands with their 1-based column.
struct Scanner<'a> {
    s: &'a [u8],
    text: &'a str,
    i: usize,
    numbers: usize,
    mode: NumberMode,
    /// The last column counted: `(byte, column)`, so that columns asked in increasing order
    /// cost the text between them only.
    counted: std::cell::Cell<(usize, usize)>,
}

impl Scanner<'_> {
    fn skip_separators(&mut self) {
        while self.i < self.s.len() && matches!(self.s[self.i], b' ' | b'\t' | b'\n' | b'\r' | b'\x0c' | b',') {
            self.i += 1;
        }
    }

    fn skip_space(&mut self) {
        while self.i < self.s.len() && matches!(self.s[self.i], b' ' | b'\t' | b'\n' | b'\r' | b'\x0c') {
            self.i += 1;
        }
    }

    /// The 1-based character column of byte `i`, counted from the last column asked for (only
    /// for messages and arcs: counting from the start for every number made reading quadratic in
    /// the length of the path data).
    fn column(&self, i: usize) -> usize {
        let (byte, column) = self.counted.get();
        let column =
            if i >= byte { column + self.text[byte..i].chars().count() } else { self.text[..i].chars().count() + 1 };
        self.counted.set((i, column));
        column
    }

    fn position(&self, i: usize) -> Position {
        Position { line: None, column: self.column(i), token: self.numbers + 1 }
    }

    fn error(&self, i: usize, reason: &str) -> Error {
        let token: String = self.text[i..].chars().take_while(|c| !c.is_whitespace()).take(20).collect();
        Error::ParseNumber { token, position: self.position(i), reason: reason.into() }
    }

    fn number(&mut self) -> Result<BigRational> {
        self.skip_separators();
        let start = self.i;
        let s = self.s;
        let mut j = self.i;
        if j < s.len() && matches!(s[j], b'+' | b'-') {
            j += 1;
        }
        let int_start = j;
        while j < s.len() && s[j].is_ascii_digit() {
            j += 1;
        }
        let mut digits = j - int_start;
        if j < s.len() && s[j] == b'.' {
            j += 1;
            let f = j;
            while j < s.len() && s[j].is_ascii_digit() {
                j += 1;
            }
            digits += j - f;
        }
        if digits == 0 {
            return Err(if start >= s.len() {
                self.error(start.min(s.len()), "a number is missing here (path data ended)")
            } else {
                self.error(start, "a number is expected here")
            });
        }
        if j < s.len() && matches!(s[j], b'e' | b'E') {
            let mut k = j + 1;
            if k < s.len() && matches!(s[k], b'+' | b'-') {
                k += 1;
            }
            if k < s.len() && s[k].is_ascii_digit() {
                while k < s.len() && s[k].is_ascii_digit() {
                    k += 1;
                }
                j = k;
            }
        }
        self.i = j;
        self.numbers += 1;
        // the position goes into the error only: the column is counted when there is one
        parse_number_in(&self.text[start..j], Position::default(), self.mode).map_err(|mut e| {
            if let Error::ParseNumber { position, .. } = &mut e {
                *position = Position { line: None, column: self.column(start), token: self.numbers };
            }
            e
        })
    }

    fn pair(&mut self) -> Result<P> {
        let x = self.number()?;
        let y = self.number()?;
        Ok(pt(x, y))
    }

    /// An arc flag: the single character `0` or `1` (it may be followed by a number at once).
    fn flag(&mut self) -> Result<bool> {
        self.skip_separators();
        match self.s.get(self.i) {
            Some(b'0') => {
                self.i += 1;
                self.numbers += 1;
                Ok(false)
            }
            Some(b'1') => {
                self.i += 1;
                self.numbers += 1;
                Ok(true)
            }
            _ => Err(self.error(self.i.min(self.s.len()), "an arc flag (0 or 1) is expected here")),
        }
    }
}

/// The subpaths of SVG path data, exactly (see the module documentation for the grammar).
///
/// # Errors
/// [`Error::ParseNumber`] naming the token and its column for a malformed number, a missing
/// coordinate, an unknown command or path data that does not start with a move-to;
/// [`Error::TooLarge`] beyond 64 MiB (`MAX_PATH_BYTES`); [`Error::InvalidArgument`] naming the
/// subpath and column where a subpath grows past 100,000 segments (`MAX_PATH_SEGMENTS`, the limit
/// of a path's contour), before the rest is read.
pub fn parse_path(d: &str, mode: NumberMode) -> Result<Vec<Contour>> {
    if d.len() > MAX_PATH_BYTES {
        return Err(Error::TooLarge { what: "path data bytes", value: d.len(), limit: MAX_PATH_BYTES });
    }
    let mut sc = Scanner { s: d.as_bytes(), text: d, i: 0, numbers: 0, mode, counted: std::cell::Cell::new((0, 1)) };
    let mut out: Vec<Contour> = vec![];
    let mut current: Option<Contour> = None;
    let zero = || rat(0);
    let mut cur = pt(zero(), zero());
    let mut start = cur.clone();
    // the reflected control point of S (after C/S) or T (after Q/T)
    let mut last_cubic: Option<P> = None;
    let mut last_quad: Option<P> = None;
    let mut command: Option<u8> = None;
    let mut first = true;
    loop {
        sc.skip_space();
        if sc.i >= sc.s.len() {
            break;
        }
        // where the command starts: its letter, or its first number when it is repeated
        let command_at = sc.i;
        let c = sc.s[sc.i];
        let cmd = if c.is_ascii_alphabetic() {
            let at = sc.i;
            sc.i += 1;
            if !b"MmLlHhVvCcSsQqTtAaZz".contains(&c) {
                return Err(sc.error(at, "unknown path command"));
            }
            if first && !matches!(c, b'M' | b'm') {
                return Err(sc.error(at, "path data must start with a move-to (M or m)"));
            }
            c
        } else {
            match command {
                // implicit repetition: after M the pairs are line-tos
                Some(b'M') => b'L',
                Some(b'm') => b'l',
                Some(b'Z' | b'z') | None => {
                    let at = sc.i;
                    sc.skip_separators();
                    return Err(sc.error(
                        sc.i.min(sc.s.len()).max(at),
                        if command.is_none() {
                            "path data must start with a move-to (M or m)"
                        } else {
                            "a command is expected after Z"
                        },
                    ));
                }
                Some(c) => c,
            }
        };
        first = false;
        let relative = cmd.is_ascii_lowercase();
        let base = cur.clone();
        let abs = |p: P| if relative { p.add(&base) } else { p };
        // a new subpath after Z starts at the subpath's start
        if !matches!(cmd, b'M' | b'm' | b'Z' | b'z') && current.is_none() {
            current = Some(Contour::default());
            start = cur.clone();
        }
        let mut next_cubic = None;
        let mut next_quad = None;
        match cmd.to_ascii_uppercase() {
            b'M' => {
                let p = abs(sc.pair()?);
                if let Some(c) = current.take() {
                    out.push(c);
                }
                current = Some(Contour::default());
                cur = p.clone();
                start = p;
            }
            b'L' | b'H' | b'V' => {
                let p = match cmd.to_ascii_uppercase() {
                    b'L' => abs(sc.pair()?),
                    b'H' => {
                        let x = sc.number()?;
                        pt(if relative { x + &cur.coords[0] } else { x }, cur.coords[1].clone())
                    }
                    _ => {
                        let y = sc.number()?;
                        pt(cur.coords[0].clone(), if relative { y + &cur.coords[1] } else { y })
                    }
                };
                push(&mut current, Segment::Bezier(vec![cur.clone(), p.clone()]));
                cur = p;
            }
            b'C' => {
                let (p1, p2, p3) = (abs(sc.pair()?), abs(sc.pair()?), abs(sc.pair()?));
                push(&mut current, Segment::Bezier(vec![cur.clone(), p1, p2.clone(), p3.clone()]));
                next_cubic = Some(p2);
                cur = p3;
            }
            b'S' => {
                let p1 = reflect(last_cubic.as_ref(), &cur);
                let (p2, p3) = (abs(sc.pair()?), abs(sc.pair()?));
                push(&mut current, Segment::Bezier(vec![cur.clone(), p1, p2.clone(), p3.clone()]));
                next_cubic = Some(p2);
                cur = p3;
            }
            b'Q' => {
                let (p1, p2) = (abs(sc.pair()?), abs(sc.pair()?));
                push(&mut current, Segment::Bezier(vec![cur.clone(), p1.clone(), p2.clone()]));
                next_quad = Some(p1);
                cur = p2;
            }
            b'T' => {
                let p1 = reflect(last_quad.as_ref(), &cur);
                let p2 = abs(sc.pair()?);
                push(&mut current, Segment::Bezier(vec![cur.clone(), p1.clone(), p2.clone()]));
                next_quad = Some(p1);
                cur = p2;
            }
            b'A' => {
                let (rx, ry) = (sc.number()?, sc.number()?);
                let _rotation = sc.number()?;
                let (large, sweep) = (sc.flag()?, sc.flag()?);
                let p = abs(sc.pair()?);
                if p != cur {
                    let seg = if rx.is_zero() || ry.is_zero() {
                        // SVG: a zero radius makes the arc a straight line
                        Segment::Bezier(vec![cur.clone(), p.clone()])
                    } else {
                        Segment::Skipped {
                            from: cur.clone(),
                            to: p.clone(),
                            reason: format!(
                                "elliptical arc at column {} (rx {rx}, ry {ry}, large-arc {}, sweep {}): not a \
                                 polynomial Bézier curve, not approximated",
                                sc.column(command_at),
                                u8::from(large),
                                u8::from(sweep)
                            ),
                        }
                    };
                    push(&mut current, seg);
                }
                cur = p;
            }
            _ => {
                // Z
                if let Some(mut c) = current.take() {
                    if cur != start {
                        c.segments.push(Segment::Bezier(vec![cur.clone(), start.clone()]));
                    }
                    c.closed = true;
                    out.push(c);
                }
                cur = start.clone();
            }
        }
        if let Some(c) = current.as_ref().or(out.last()).filter(|c| c.segments.len() > MAX_PATH_SEGMENTS) {
            // refused as the subpath grows past the limit, before the rest is read
            let subpath = out.len() - usize::from(current.is_none());
            return Err(Error::InvalidArgument {
                message: format!(
                    "subpath {subpath}: segments in a subpath {} exceeds the limit {MAX_PATH_SEGMENTS} (at column {})",
                    c.segments.len(),
                    sc.column(sc.i)
                ),
            });
        }
        last_cubic = next_cubic;
        last_quad = next_quad;
        command = Some(cmd);
        // a command letter followed by nothing where numbers are due is caught by `number`;
        // after Z and before the next letter only separators may follow
        if matches!(cmd, b'Z' | b'z') {
            sc.skip_space();
        }
    }
    if let Some(c) = current.take() {
        out.push(c);
    }
    Ok(out)
}

fn push(current: &mut Option<Contour>, s: Segment) {
    current.get_or_insert_with(Contour::default).segments.push(s);
}

/// The reflection `2·cur − c` of the previous control point, or `cur` when there is none.
fn reflect(c: Option<&P>, cur: &P) -> P {
    match c {
        Some(c) => cur.scale(&rat(2)).sub(c),
        None => cur.clone(),
    }
}

/// The segments of a subpath as a closed contour for filling: every piece as a polynomial
/// Bézier curve and, when the subpath does not end where it starts, the closing line (SVG fills
/// an open subpath as if closed by a line, SVG 1.1 §11.3). An empty subpath gives no segments.
///
/// # Errors
/// [`Error::InvalidArgument`] with the reason for a piece that is no polynomial Bézier curve
/// (an elliptical arc, [`Segment::Skipped`]); [`Error::TooLarge`] when the closed contour has
/// more than 100,000 (`MAX_PATH_SEGMENTS`) segments (the callers name the subpath).
pub fn close_for_fill(contour: &Contour) -> Result<Vec<BezierCurve<BigRational>>> {
    if contour.segments.len() >= MAX_PATH_SEGMENTS {
        let closing = usize::from(contour.segments.first().zip(contour.segments.last()).is_some_and(|(a, b)| {
            let start = match a {
                Segment::Bezier(ps) => ps.first(),
                Segment::Skipped { from, .. } => Some(from),
            };
            let end = match b {
                Segment::Bezier(ps) => ps.last(),
                Segment::Skipped { to, .. } => Some(to),
            };
            start != end
        }));
        let n = contour.segments.len() + closing;
        if n > MAX_PATH_SEGMENTS {
            return Err(Error::TooLarge { what: "segments in a closed subpath", value: n, limit: MAX_PATH_SEGMENTS });
        }
    }
    let mut segs = Vec::with_capacity(contour.segments.len() + 1);
    for s in &contour.segments {
        match s {
            Segment::Bezier(ps) => segs.push(BezierCurve::new(ps.clone())?),
            Segment::Skipped { reason, .. } => return Err(Error::InvalidArgument { message: reason.clone() }),
        }
    }
    if let (Some(first), Some(last)) = (segs.first(), segs.last()) {
        let (a, b) = (last.points()[last.points().len() - 1].clone(), first.points()[0].clone());
        if a != b {
            segs.push(BezierCurve::new(vec![a, b])?);
        }
    }
    Ok(segs)
}

/// SVG path data as the closed path its fill covers: [`parse_path`], each subpath closed by
/// a closing line as SVG fills it, empty subpaths (a lone move-to) left out.
///
/// # Errors
/// As [`parse_path`] and a closing line as SVG fills it.
///
/// # Example
/// ```
/// use casteljau::format::fill_path;
/// use casteljau::path::{FillRule, PathWinding};
/// use casteljau::num::NumberMode;
/// use casteljau::{Point, rat};
/// let path = fill_path("M0 0 L4 0 L4 4 L0 4 Z M1 1 L3 1 L3 3 L1 3", NumberMode::Exact).unwrap();
/// assert_eq!(path.contours().len(), 2);
/// let PathWinding::Off(w) = path.winding(&casteljau::num::Point2::new(rat(2), rat(2)), &casteljau::work::Budget::unlimited()).unwrap() else { panic!() };
/// assert_eq!(w.winding(), 2);
/// assert!(!w.inside(FillRule::EvenOdd));
/// ```
pub fn fill_path(d: &str, mode: NumberMode) -> Result<ClosedPath> {
    let mut contours = vec![];
    for (k, c) in parse_path(d, mode)?.iter().enumerate() {
        let segs = close_for_fill(c).map_err(|e| Error::InvalidArgument { message: format!("subpath {k}: {e}") })?;
        if !segs.is_empty() {
            contours.push(segs);
        }
    }
    ClosedPath::from_polynomial(contours)
}

/// SVG path data as the shape its fill covers ([`fill_path`], numbers read exactly).
impl std::str::FromStr for crate::shape::Shape {
    type Err = Error;
    fn from_str(d: &str) -> Result<Self> {
        Ok(crate::shape::Shape::new(fill_path(d, NumberMode::Exact)?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn beziers(d: &str) -> Vec<Vec<String>> {
        parse_path(d, NumberMode::Exact)
            .unwrap()
            .iter()
            .flat_map(|c| c.segments.iter())
            .map(|s| match s {
                Segment::Bezier(ps) => ps.iter().map(|p| p.to_string()).collect(),
                Segment::Skipped { .. } => vec!["skipped".into()],
            })
            .collect()
    }

    #[test]
    fn svg_path_compact_numbers_split_like_browsers() {
        assert_eq!(beziers("M1.5.5L-1-2"), vec![vec!["(3/2, 1/2)", "(-1, -2)"]]);
        assert_eq!(beziers("M0,0 1e1,2E-1"), vec![vec!["(0, 0)", "(10, 1/5)"]]);
    }

    #[test]
    fn svg_path_t_reflects_through_chain_and_resets_after_other_commands() {
        let s = beziers("M0 0 Q1 1 2 0 T4 0 L5 0 T6 0");
        assert_eq!(s[1], vec!["(2, 0)", "(3, -1)", "(4, 0)"]);
        // after L there is nothing to reflect: the control point is the current point
        assert_eq!(s[3], vec!["(5, 0)", "(5, 0)", "(6, 0)"]);
    }

    #[test]
    fn svg_path_errors_name_the_column() {
        let e = parse_path("M0 0 L1", NumberMode::Exact).unwrap_err();
        assert!(e.to_string().contains("column 8"), "{e}");
        let e = parse_path("L0 0", NumberMode::Exact).unwrap_err();
        assert!(e.to_string().contains("move-to"), "{e}");
        let e = parse_path("M0 0 X1 1", NumberMode::Exact).unwrap_err();
        assert!(e.to_string().contains("column 6"), "{e}");
    }
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    #[test]
    fn close_for_fill_example() {
        use crate::format::parse_path;
        use crate::format::svg_path::close_for_fill;
        use crate::num::NumberMode;
        let subpaths = parse_path("M0 0 Q1 2 2 0", NumberMode::Exact).unwrap();
        let closed = close_for_fill(&subpaths[0]).unwrap();
        assert_eq!(closed.len(), 2); // the quadratic and the line back to (0, 0)
        assert_eq!(closed[1].points()[1].to_string(), "(0, 0)");
    }
}
