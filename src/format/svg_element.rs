//! One SVG element read exactly ([`super::svg::read_svg`] reads the document): the geometry of
//! `<path>`, `<line>`, `<polyline>`, `<polygon>` and `<rect>` in the element's user space, lengths,
//! and `transform` lists as exact rational matrices; and the records a document's reading gives
//! ([`SvgShape`], [`ShapeProblem`]). Below the walk of the document (`svg_tree`), which places
//! each element under its ancestors' transforms.

use crate::error::{Position, Result};
use crate::format::{Affine, Contour, Segment, svg_path};
use crate::num::parse::{NumberMode, parse_number_in};
use crate::num::point::Point;
use crate::num::scalar::{Exact, Scalar, rat};
use num_rational::BigRational;
use std::cmp::Ordering;

/// One shape element of an SVG document as drawn, in drawing order (document order, with the
/// copies a `<use>` draws where the `<use>` stands), or a `<use>` that draws nothing because
/// of a problem (tag `use`).
#[derive(Clone, Debug)]
pub struct SvgShape {
    /// 0-based index among the document's shapes in drawing order (`path`, `rect`, `line`,
    /// `polyline`, `polygon`, `circle`, `ellipse`, and `use` with a problem).
    pub index: usize,
    /// The element's `id`, when it has one (`None` for a copy drawn by `<use>`: the id names
    /// the original).
    pub id: Option<String>,
    /// The tag name.
    pub tag: String,
    /// 1-based line of the element in the file (of the original, for a copy).
    pub line: usize,
    /// For a copy drawn by `<use>`, the line of that `<use>` (the outermost one, when copies
    /// nest).
    pub use_line: Option<usize>,
    /// The subpaths in user space (all transforms applied), or why the element is not read:
    /// skipped (a circle or ellipse, a non-rational transform) or invalid (bad path data, a unit).
    pub contours: std::result::Result<Vec<Contour>, ShapeProblem>,
}

impl SvgShape {
    /// How records name the element: its `id`, or its index among the shape elements.
    ///
    /// # Example
    /// ```
    /// use casteljau::format::{Element, read_svg};
    /// let svg = r#"<svg xmlns="http://www.w3.org/2000/svg"><path d="M0 0 H1 V1 Z"/><rect id="r" width="1" height="1"/></svg>"#;
    /// let shapes = read_svg(svg, casteljau::num::NumberMode::Exact, &casteljau::work::Budget::unlimited()).unwrap();
    /// assert_eq!(shapes[0].element(), Element::Index(0));
    /// assert_eq!(shapes[1].element(), Element::Id("r".into()));
    /// ```
    pub fn element(&self) -> super::Element {
        match &self.id {
            Some(id) => super::Element::Id(id.clone()),
            None => super::Element::Index(self.index),
        }
    }
}

/// Why a shape element gives no contours.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ShapeProblem {
    /// Not a polynomial Bézier shape, or under a transform that is not rational: left out on
    /// purpose, never approximated (not an error of the file).
    Skipped(String),
    /// Malformed: bad numbers or path data, unsupported units or transforms.
    Invalid(String),
}

impl ShapeProblem {
    /// `true` for [`ShapeProblem::Skipped`].
    pub fn is_skipped(&self) -> bool {
        matches!(self, ShapeProblem::Skipped(_))
    }

    /// The same kind of problem with `prefix` before its text.
    pub(crate) fn within(self, prefix: &str) -> Self {
        match self {
            ShapeProblem::Skipped(m) => ShapeProblem::Skipped(format!("{prefix}{m}")),
            ShapeProblem::Invalid(m) => ShapeProblem::Invalid(format!("{prefix}{m}")),
        }
    }
}

impl From<String> for ShapeProblem {
    fn from(m: String) -> Self {
        ShapeProblem::Invalid(m)
    }
}

impl std::fmt::Display for ShapeProblem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ShapeProblem::Skipped(m) | ShapeProblem::Invalid(m) => f.write_str(m),
        }
    }
}

type ShapeResult<T> = std::result::Result<T, ShapeProblem>;

type P = Point<BigRational>;

fn pt(x: BigRational, y: BigRational) -> P {
    Point::new(vec![x, y])
}

/// The element's own contours in its user space.
pub(crate) fn shape(node: roxmltree::Node<'_, '_>, tag: &str, mode: NumberMode) -> ShapeResult<Vec<Contour>> {
    let len = |name: &str| length(node, name, mode);
    let line = |a: P, b: P| Segment::Bezier(vec![a, b]);
    match tag {
        "path" => match node.attribute("d") {
            None => Ok(vec![]),
            Some(d) => svg_path::parse_path(d, mode).map_err(|e| format!("d: {e}").into()),
        },
        "line" => Ok(vec![Contour {
            segments: vec![line(pt(len("x1")?, len("y1")?), pt(len("x2")?, len("y2")?))],
            closed: false,
        }]),
        "polyline" | "polygon" => {
            let text = node.attribute("points").unwrap_or("");
            // the points attribute is path data without commands
            let numbers = svg_path::parse_path(&format!("M{text}"), mode).map_err(|e| format!("points: {e}"))?;
            let mut vertices: Vec<P> = vec![];
            for c in &numbers {
                for s in &c.segments {
                    if let Segment::Bezier(ps) = s {
                        if vertices.is_empty() {
                            vertices.push(ps[0].clone());
                        }
                        vertices.push(ps[1].clone());
                    }
                }
            }
            let mut segments: Vec<Segment> = vertices.windows(2).map(|w| line(w[0].clone(), w[1].clone())).collect();
            let closed = tag == "polygon";
            if closed && vertices.len() > 1 && vertices[0] != vertices[vertices.len() - 1] {
                segments.push(line(vertices[vertices.len() - 1].clone(), vertices[0].clone()));
            }
            Ok(if segments.is_empty() { vec![] } else { vec![Contour { segments, closed }] })
        }
        "rect" => rect(node, mode),
        _ => {
            Err(ShapeProblem::Skipped(format!("<{tag}> is not a polynomial Bézier curve (a conic); not approximated")))
        }
    }
}

/// `<rect>`: four sides, and with `rx`/`ry` the straight parts plus four skipped corner arcs
/// (SVG 2 §10.2 for the radius rules).
fn rect(node: roxmltree::Node<'_, '_>, mode: NumberMode) -> ShapeResult<Vec<Contour>> {
    let len = |name: &str| length(node, name, mode);
    let (x, y, w, h) = (len("x")?, len("y")?, len("width")?, len("height")?);
    if w.sign() != Ordering::Greater || h.sign() != Ordering::Greater {
        return Ok(vec![]); // not rendered
    }
    let given = |name: &str| node.attribute(name).map(|_| len(name)).transpose();
    let (rx, ry) = match (given("rx")?, given("ry")?) {
        (None, None) => (rat(0), rat(0)),
        (Some(r), None) | (None, Some(r)) => (r.clone(), r),
        (Some(a), Some(b)) => (a, b),
    };
    let half = |v: &BigRational| v / rat(2);
    let rx = if rx > half(&w) { half(&w) } else { rx };
    let ry = if ry > half(&h) { half(&h) } else { ry };
    let (x1, y1) = (x.clone() + &w, y.clone() + &h);
    let corner = |from: P, to: P| Segment::Skipped {
        from,
        to,
        reason: "rounded corner of a <rect> (an elliptical arc): not a polynomial Bézier curve, not approximated"
            .into(),
    };
    if rx.is_zero() || ry.is_zero() {
        let mut segs = vec![];
        let mut side = |a: P, b: P| segs.push(Segment::Bezier(vec![a, b]));
        side(pt(x.clone(), y.clone()), pt(x1.clone(), y.clone()));
        side(pt(x1.clone(), y.clone()), pt(x1.clone(), y1.clone()));
        side(pt(x1.clone(), y1.clone()), pt(x.clone(), y1.clone()));
        side(pt(x.clone(), y1.clone()), pt(x.clone(), y.clone()));
        return Ok(vec![Contour { segments: segs, closed: true }]);
    }
    let (xa, xb, ya, yb) = (x.clone() + &rx, x1.clone() - &rx, y.clone() + &ry, y1.clone() - &ry);
    // top side, corner, right side, corner, … (a side of zero length is left out)
    let corners = [
        (pt(xb.clone(), y.clone()), pt(x1.clone(), ya.clone())),
        (pt(x1.clone(), yb.clone()), pt(xb.clone(), y1.clone())),
        (pt(xa.clone(), y1.clone()), pt(x.clone(), yb.clone())),
        (pt(x.clone(), ya.clone()), pt(xa.clone(), y.clone())),
    ];
    let mut out = vec![];
    for (k, (from, to)) in corners.iter().enumerate() {
        let side_start = &corners[(k + 3) % 4].1;
        if side_start != from {
            out.push(Segment::Bezier(vec![side_start.clone(), from.clone()]));
        }
        out.push(corner(from.clone(), to.clone()));
    }
    Ok(vec![Contour { segments: out, closed: true }])
}

/// A length attribute: a number, optionally with `px`; absent means 0.
pub(crate) fn length(
    node: roxmltree::Node<'_, '_>,
    name: &str,
    mode: NumberMode,
) -> std::result::Result<BigRational, String> {
    let Some(v) = node.attribute(name) else { return Ok(rat(0)) };
    let v = v.trim();
    let v = v.strip_suffix("px").unwrap_or(v);
    if v.ends_with(|c: char| c.is_ascii_alphabetic() || c == '%') {
        return Err(format!("{name}=\"{v}\": only plain numbers and px lengths are read exactly"));
    }
    parse_number_in(v, Position { line: None, column: 1, token: 1 }, mode).map_err(|e| format!("{name}: {e}"))
}

/// An SVG transform list, exactly.
///
/// # Errors
/// [`ShapeProblem::Invalid`] for malformed lists, [`ShapeProblem::Skipped`] for rotations and
/// skews whose sine/cosine/tangent are not rational.
pub fn parse_transform(text: &str, mode: NumberMode) -> ShapeResult<Affine> {
    let mut m = Affine::identity();
    let mut rest = text.trim_start_matches(|c: char| c.is_whitespace() || c == ',');
    while !rest.is_empty() {
        let open = rest.find('(').ok_or_else(|| ShapeProblem::Invalid("expected name(numbers)".into()))?;
        let name = rest[..open].trim();
        let close = rest[open..].find(')').ok_or_else(|| ShapeProblem::Invalid("missing )".into()))? + open;
        let args = &rest[open + 1..close];
        let nums: Vec<BigRational> = args
            .split(|c: char| c.is_whitespace() || c == ',')
            .filter(|s| !s.is_empty())
            .enumerate()
            .map(|(k, s)| parse_number_in(s, Position { line: None, column: 1, token: k + 1 }, mode))
            .collect::<Result<_>>()
            .map_err(|e| e.to_string())?;
        let n = |k: usize| nums.get(k).cloned().unwrap_or_else(|| rat(0));
        let arity = |ok: &[usize]| {
            if ok.contains(&nums.len()) {
                Ok(())
            } else {
                Err(format!("{name} takes {ok:?} numbers, got {}", nums.len()))
            }
        };
        let (o, z) = (rat(1), rat(0));
        let own = match name {
            "matrix" => {
                arity(&[6])?;
                Affine([n(0), n(1), n(2), n(3), n(4), n(5)])
            }
            "translate" => {
                arity(&[1, 2])?;
                Affine([o.clone(), z.clone(), z.clone(), o, n(0), n(1)])
            }
            "scale" => {
                arity(&[1, 2])?;
                let sy = if nums.len() == 2 { n(1) } else { n(0) };
                Affine([n(0), z.clone(), z.clone(), sy, z.clone(), z])
            }
            "rotate" => {
                arity(&[1, 3])?;
                let (c, s) = right_angle(&n(0)).ok_or_else(|| {
                    ShapeProblem::Skipped(format!(
                        "rotate({}) is not a multiple of 90°: its sine and cosine are irrational",
                        n(0)
                    ))
                })?;
                let r = Affine([rat(c), rat(s), rat(-s), rat(c), z.clone(), z.clone()]);
                if nums.len() == 3 {
                    let to = Affine([o.clone(), z.clone(), z.clone(), o.clone(), n(1), n(2)]);
                    let back = Affine([o.clone(), z.clone(), z.clone(), o, -n(1), -n(2)]);
                    to.compose(&r).compose(&back)
                } else {
                    r
                }
            }
            "skewX" | "skewY" => {
                arity(&[1])?;
                let t = tan_exact(&n(0)).ok_or_else(|| {
                    ShapeProblem::Skipped(format!(
                        "{name}({}): the tangent is irrational (only 0° and ±45° are exact)",
                        n(0)
                    ))
                })?;
                if name == "skewX" {
                    Affine([o.clone(), z.clone(), rat(t), o, z.clone(), z])
                } else {
                    Affine([o.clone(), rat(t), z.clone(), o, z.clone(), z])
                }
            }
            _ => return Err(format!("unknown transform {name:?}").into()),
        };
        m = m.compose(&own);
        rest = rest[close + 1..].trim_start_matches(|c: char| c.is_whitespace() || c == ',');
    }
    Ok(m)
}

/// `(cos, sin)` of an angle in degrees that is a multiple of 90.
fn right_angle(deg: &BigRational) -> Option<(i64, i64)> {
    if !deg.is_integer() {
        return None;
    }
    let q = deg.to_integer() % num_bigint::BigInt::from(360);
    let q: i64 = (if q.sign() == num_bigint::Sign::Minus { q + 360 } else { q }).try_into().ok()?;
    match q {
        0 => Some((1, 0)),
        90 => Some((0, 1)),
        180 => Some((-1, 0)),
        270 => Some((0, -1)),
        _ => None,
    }
}

/// `tan` of 0°, ±45° (mod 180°).
fn tan_exact(deg: &BigRational) -> Option<i64> {
    if !deg.is_integer() {
        return None;
    }
    let q = deg.to_integer() % num_bigint::BigInt::from(180);
    let q: i64 = (if q.sign() == num_bigint::Sign::Minus { q + 180 } else { q }).try_into().ok()?;
    match q {
        0 => Some(0),
        45 => Some(1),
        135 => Some(-1),
        _ => None,
    }
}
