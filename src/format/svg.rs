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

use super::svg_element::SvgShape;
use crate::error::{Error, Result};
use crate::format::svg_path;
use crate::num::parse::NumberMode;
use crate::work::Budget;

/// Most XML nodes accepted in one document.
pub const MAX_SVG_NODES: u32 = 10_000_000;

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
