//! SVG documents read exactly: every `<path>` and the Bézier-exact basic shapes (`<line>`,
//! `<polyline>`, `<polygon>`, `<rect>`) that the document draws, with the `transform`s of the
//! element and its ancestors applied as exact rational matrices. XML is parsed by `roxmltree`;
//! path data by [`crate::format::svg_path`].
//!
//! What is drawn follows SVG's rendering tree: the content of `<defs>`, `<symbol>`,
//! `<clipPath>`, `<mask>`, `<marker>` and `<pattern>` is not drawn where it stands, nor an
//! element with `display="none"`; `<use>` draws a copy of the element it refers to under its own
//! transform and `translate(x, y)`; see `format::svg_tree` for every rule (nested `<svg>`,
//! `<switch>`, references that cannot be followed).
//!
//! What is not a polynomial Bézier curve is never approximated: `<circle>` and `<ellipse>` are
//! listed with a note, the rounded corners of a `<rect>` and arcs inside paths are
//! [`Segment::Skipped`] pieces, and a transform that is not rational (`rotate(30)`) skips its
//! elements with a note. Transforms: `matrix`, `translate`, `scale`, `rotate` by a multiple of
//! 90° (with or without a centre) and `skewX`/`skewY` by 0° or ±45°. Lengths are plain numbers
//! or `px`; other units make a per-element error.
//!
//! Reading takes time linear in the text, plus the exact products of the transforms, which are
//! charged against a [`Budget`] for the whole document before they are computed.
//!
//! # Example
//! ```
//! use casteljau::format::read_svg;
//! use casteljau::{num::NumberMode, work::Budget};
//! let svg = r#"<svg xmlns="http://www.w3.org/2000/svg">
//!   <g transform="translate(10 0) scale(2)"><path id="p" d="M0 0 Q1 1 2 0"/></g>
//! </svg>"#;
//! let shapes = read_svg(svg, NumberMode::Exact, &Budget::unlimited()).unwrap();
//! assert_eq!(shapes[0].id.as_deref(), Some("p"));
//! let casteljau::format::Segment::Bezier(q) = &shapes[0].contours.as_ref().unwrap()[0].segments[0] else { panic!() };
//! assert_eq!(q[1].to_string(), "(12, 2)");
//! ```

use crate::error::{Error, Position, Result};
use crate::format::{Affine, Contour, Segment, svg_path};
use crate::num::parse::{NumberMode, parse_number_in};
use crate::num::point::Point;
use crate::num::scalar::{Exact, Scalar, rat};
use crate::work::Budget;
use num_rational::BigRational;
use std::cmp::Ordering;

/// Most XML nodes accepted in one document.
pub const MAX_SVG_NODES: u32 = 10_000_000;

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

/// The shapes an SVG document draws (see the module documentation), in drawing order.
///
/// # Errors
/// [`Error::InvalidArgument`] when the text is not well-formed XML (with the parser's line and
/// column), or naming the element where more than 200,000 segments (`MAX_USE_SEGMENTS`) are
/// drawn through `<use>`; [`Error::WorkLimit`] naming the element where the exact products of
/// the transforms and the copies drawn by `<use>` pass `budget` (charged before they are
/// computed). Problems of single elements are reported in [`SvgShape::contours`], not here.
///
/// # Example
/// ```
/// use casteljau::format::read_svg;
/// use casteljau::{num::NumberMode, work::Budget};
/// let svg = r##"<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink">
///   <defs><path id="tri" d="M0 0 H2 V2 Z"/></defs>
///   <use xlink:href="#tri" x="10"/>
///   <use href="#tri" transform="scale(2)"/>
/// </svg>"##;
/// let shapes = read_svg(svg, NumberMode::Exact, &Budget::unlimited()).unwrap();
/// assert_eq!(shapes.len(), 2); // the two copies; the definition is not drawn
/// assert_eq!((shapes[0].line, shapes[0].use_line), (2, Some(3)));
/// let c = shapes[1].contours.as_ref().unwrap();
/// assert_eq!(format!("{:?}", c[0].segments[0]), format!("{:?}", casteljau::format::parse_path("M0 0 H4", NumberMode::Exact).unwrap()[0].segments[0]));
/// // deeply nested transforms are charged before their numbers are multiplied out
/// let deep = format!("<svg>{}<path d=\"M0 0 H1 V1 Z\"/>{}</svg>", "<g transform=\"scale(1.0001)\">".repeat(300), "</g>".repeat(300));
/// let e = read_svg(&deep, NumberMode::Exact, &Budget::new(1e3, "--max-work")).unwrap_err();
/// assert!(e.to_string().contains("--max-work"), "{e}");
/// ```
pub fn read_svg(text: &str, mode: NumberMode, budget: &Budget) -> Result<Vec<SvgShape>> {
    let options = roxmltree::ParsingOptions { allow_dtd: true, nodes_limit: MAX_SVG_NODES, ..Default::default() };
    let doc = roxmltree::Document::parse_with_options(text, options)
        .map_err(|e| Error::InvalidArgument { message: format!("not an SVG (XML) document: {e}") })?;
    let mut walker = super::svg_tree::Walker::new(&doc, text, mode, budget);
    walker.walk()?;
    Ok(walker.shapes)
}

/// An SVG document as the one shape its elements fill: every shape of [`read_svg`]
/// (transforms applied), in drawing order, each subpath closed for fill as SVG fills it
/// (a closing line as SVG fills it) and empty ones left out, all in one
/// [`Shape`](crate::shape::Shape), so where elements overlap their windings add up (the fill
/// rule is the operation's, e.g. [`crate::shape::BooleanOptions::fill`]). Nothing is
/// approximated: an element that is not made of polynomial Bézier pieces is refused.
///
/// # Errors
/// As [`read_svg`] for the document; [`Error::InvalidArgument`] naming the element
/// (`line 3: <circle id="c">: …`, or `line 3: <circle> (shape 2): …` by its index among the
/// shapes when it has no `id`, `line 3: <path> (shape 2, drawn by the <use> on line 9): …` for
/// a copy) for an element that is skipped (a circle, an ellipse, a transform that is not
/// rational), malformed (bad path data, a unit, a `<use>` that cannot be followed), or holds a
/// piece that is no polynomial Bézier curve (an arc, a rounded corner), or for a subpath of
/// more than 100,000 (`MAX_PATH_SEGMENTS`) segments.
///
/// # Example
/// ```
/// use casteljau::format::fill_svg;
/// use casteljau::{num::NumberMode, work::Budget};
/// let svg = r#"<svg xmlns="http://www.w3.org/2000/svg">
///   <rect width="4" height="4"/>
///   <g transform="translate(10 0)"><path d="M0 0 L2 0 L1 2"/></g>
/// </svg>"#;
/// let shape = fill_svg(svg, NumberMode::Exact, &Budget::unlimited()).unwrap();
/// assert_eq!(shape.path().contours().len(), 2); // the rectangle and the closed triangle
/// let arc = r#"<svg xmlns="http://www.w3.org/2000/svg"><path d="M0 0 H2 V2 H0 Z"/><circle id="c" r="1"/></svg>"#;
/// let e = fill_svg(arc, NumberMode::Exact, &Budget::unlimited()).unwrap_err();
/// assert!(e.to_string().starts_with(r#"line 1: <circle id="c">: "#), "{e}");
/// ```
pub fn fill_svg(text: &str, mode: NumberMode, budget: &Budget) -> Result<crate::shape::Shape> {
    let mut contours = vec![];
    for s in read_svg(text, mode, budget)? {
        let at = || match (&s.id, s.use_line) {
            (Some(id), _) => format!("line {}: <{} id=\"{id}\">", s.line, s.tag),
            (None, None) => format!("line {}: <{}> (shape {})", s.line, s.tag, s.index),
            (None, Some(u)) => {
                format!("line {}: <{}> (shape {}, drawn by the <use> on line {u})", s.line, s.tag, s.index)
            }
        };
        let within =
            |problem: &dyn std::fmt::Display| Error::InvalidArgument { message: format!("{}: {problem}", at()) };
        for (k, c) in s.contours.as_ref().map_err(|problem| within(problem))?.iter().enumerate() {
            let segs = svg_path::close_for_fill(c).map_err(|e| within(&format!("subpath {k}: {e}")))?;
            if !segs.is_empty() {
                contours.push(segs);
            }
        }
    }
    Ok(crate::shape::Shape::new(crate::path::ClosedPath::from_polynomial(contours)?))
}

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
