//! The walk of an SVG document that decides what is drawn, and under which transform
//! ([`super::svg::read_svg`]): the rules of SVG's rendering tree that change the geometry.
//!
//! * Only containers (`<svg>`, `<g>`, `<a>`, `<switch>`) have their children walked; shapes
//!   inside anything else (a shape, `<text>`, an unknown element) are not drawn.
//! * The content of `<defs>`, `<symbol>`, `<clipPath>`, `<mask>`, `<marker>` and `<pattern>`
//!   is never drawn where it stands; an element with `display="none"` (the attribute or an
//!   inline `style`) is not drawn, nor is anything inside it. Stylesheets are not read.
//! * Of a `<switch>`, the first child element without conditional attributes
//!   (`requiredFeatures`, `requiredExtensions`, `systemLanguage`) is drawn: conditions are not
//!   evaluated.
//! * `<use href="#id">` (or `xlink:href`) draws a copy of the element with that `id` where the
//!   `<use>` stands: under the `<use>`'s ancestors, its `transform` and then `translate(x, y)`,
//!   not under the ancestors of the original. A `<symbol>` is drawn as a group; one with a
//!   `viewBox` is skipped (its viewport scaling is not read). Copies nest up to 16 deep
//!   (`MAX_USE_DEPTH`); a `<use>` that refers to itself or to an element containing it, a
//!   missing `id` or a reference to another file is listed as a problem of the `<use>`
//!   (tag `use`); a reference to a `<defs>`, `<clipPath>`, … draws nothing, as it is not drawn.
//! * A nested `<svg>` is placed by `translate(x, y)`; one with a `viewBox` has its shapes skipped.
//!
//! Work: the transforms are composed once per element (not once per shape and ancestor), with
//! products that cancel common factors by one big remainder; every composition and every
//! transformed point is charged before it is computed, and so is every element of a copy, against
//! the budget of the whole document (the numbers of a deep chain of `scale(1.0001)` grow with its
//! depth). At most 200,000 segments are drawn through `<use>` in one document
//! (`MAX_USE_SEGMENTS`): copies of copies would otherwise grow exponentially.

use super::svg_element::{ShapeProblem, SvgShape, length, parse_transform, shape};
use crate::error::{Error, Result};
use crate::format::{Affine, Contour, Segment};
use crate::num::parse::NumberMode;
use crate::num::scalar::rat;
use crate::work::Budget;
use std::collections::HashMap;
use std::rc::Rc;

/// Elements whose content is never drawn where it stands.
pub(crate) const NOT_DRAWN: [&str; 6] = ["defs", "symbol", "clipPath", "mask", "marker", "pattern"];

/// Deepest nesting of `<use>` copies followed.
pub(crate) const MAX_USE_DEPTH: usize = 16;

/// Most segments drawn through `<use>` in one document.
pub(crate) const MAX_USE_SEGMENTS: usize = 200_000;

/// Elements visited to estimate the rest of the work once the budget is passed (the estimate of
/// a larger document is what these cost, a lower bound).
const ESTIMATE_VISITS: usize = 1_000_000;

/// Work units of one element visited in a copy drawn by `<use>` (about 60 ns measured here on
/// copies of copies of empty groups).
const COPY_WORK: f64 = 100.0;

/// Work units per point of a copied shape drawn without a transform (the copy).
const COPY_POINT_WORK: f64 = 200.0;

const XLINK: &str = "http://www.w3.org/1999/xlink";

type Node<'a, 'i> = roxmltree::Node<'a, 'i>;

/// Where an element is drawn: the product of the transforms above it (or why its shapes are not
/// read), and the `<use>` copies it is part of.
struct Context {
    transform: std::result::Result<Rc<Affine>, ShapeProblem>,
    /// The sizes of its entries (estimated, once the budget is spent: the walk then only
    /// estimates what the rest would cost, for the message).
    sizes: AffineSizes,
    identity: bool,
    uses: Option<Rc<UseLink>>,
}

/// A `<use>` being followed: its target, its line, how deep, and the `<use>` around it.
struct UseLink {
    target: roxmltree::NodeId,
    line: usize,
    depth: usize,
    outer: Option<Rc<UseLink>>,
}

impl UseLink {
    fn outermost_line(&self) -> usize {
        let mut l = self;
        while let Some(o) = &l.outer {
            l = o;
        }
        l.line
    }

    fn follows(&self, target: roxmltree::NodeId) -> bool {
        let mut l = Some(self);
        while let Some(link) = l {
            if link.target == target {
                return true;
            }
            l = link.outer.as_deref();
        }
        false
    }
}

/// The walk's state: the shapes drawn so far and the work charged.
pub(crate) struct Walker<'a, 'i> {
    doc: &'a roxmltree::Document<'i>,
    mode: NumberMode,
    budget: &'a Budget,
    /// Byte offsets of the text's line feeds (lines by binary search: roxmltree's positions
    /// count from the start of the text every time).
    line_feeds: Vec<usize>,
    ids: Option<HashMap<&'a str, Node<'a, 'i>>>,
    spent: f64,
    /// Where the budget was passed: from there on nothing is computed, the rest is estimated.
    over: Option<String>,
    /// Elements visited since (the estimate stops after [`ESTIMATE_VISITS`]).
    visits_over: usize,
    copied_segments: usize,
    /// The contours of shapes drawn by `<use>`, read once per element.
    parsed: HashMap<roxmltree::NodeId, std::result::Result<Rc<Vec<Contour>>, ShapeProblem>>,
    pub(crate) shapes: Vec<SvgShape>,
}

impl<'a, 'i> Walker<'a, 'i> {
    pub(crate) fn new(doc: &'a roxmltree::Document<'i>, text: &str, mode: NumberMode, budget: &'a Budget) -> Self {
        let line_feeds = text.bytes().enumerate().filter(|&(_, b)| b == b'\n').map(|(i, _)| i).collect();
        Walker {
            doc,
            mode,
            budget,
            line_feeds,
            ids: None,
            spent: 0.0,
            over: None,
            visits_over: 0,
            copied_segments: 0,
            parsed: HashMap::new(),
            shapes: vec![],
        }
    }

    /// The 1-based line of an element's start.
    fn line(&self, node: Node<'_, '_>) -> usize {
        let at = node.range().start;
        self.line_feeds.partition_point(|&f| f < at) + 1
    }

    /// Charges `units` of work about to be done at `node` against the document's budget; past
    /// it, the walk only estimates.
    fn charge(&mut self, node: Node<'_, '_>, units: f64) {
        self.spent += units;
        if self.spent > self.budget.limit && self.over.is_none() {
            self.over = Some(format!(
                "line {}: <{}>: reading the document (the exact products of its transforms and the copies of \
                 its <use> elements; this element passes the limit)",
                self.line(node),
                node.tag_name().name()
            ));
        }
    }

    /// Walks the document from its root element.
    pub(crate) fn walk(&mut self) -> Result<()> {
        let root = self.doc.root_element();
        let identity = Affine::identity();
        let sizes = identity.sizes();
        let top = Rc::new(Context { transform: Ok(Rc::new(identity)), sizes, identity: true, uses: None });
        // (element, its context, drawn as the target of a <use>)
        let mut stack: Vec<(Node<'a, 'i>, Rc<Context>, bool)> = vec![(root, top, false)];
        while let Some((node, ctx, used)) = stack.pop() {
            let tag = node.tag_name().name();
            if hidden(node) || (NOT_DRAWN.contains(&tag) && !(used && tag == "symbol")) {
                continue;
            }
            if self.over.is_some() {
                self.visits_over += 1;
                if self.visits_over > ESTIMATE_VISITS {
                    break;
                }
            }
            if ctx.uses.is_some() {
                self.charge(node, COPY_WORK);
            }
            let ctx = self.enter(node, tag, &ctx, node == root)?;
            let children: Vec<Node<'a, 'i>> = match tag {
                "path" | "rect" | "line" | "polyline" | "polygon" | "circle" | "ellipse" => {
                    self.draw(node, tag, &ctx)?;
                    vec![]
                }
                "use" => {
                    if let Some(next) = self.follow(node, &ctx)? {
                        stack.push(next);
                    }
                    vec![]
                }
                "switch" => node
                    .children()
                    .filter(|c| c.is_element())
                    .find(|c| {
                        ["requiredFeatures", "requiredExtensions", "systemLanguage"]
                            .iter()
                            .all(|a| c.attribute(*a).is_none())
                    })
                    .into_iter()
                    .collect(),
                "svg" | "g" | "a" | "symbol" => node.children().filter(|c| c.is_element()).collect(),
                _ if node == root => node.children().filter(|c| c.is_element()).collect(),
                _ => vec![],
            };
            stack.extend(children.into_iter().rev().map(|c| (c, ctx.clone(), false)));
        }
        match self.over.take() {
            // the estimate: all that was charged, and what the rest of the walk would cost
            Some(what) => self.budget.check(what, self.spent),
            None => Ok(()),
        }
    }

    /// The context inside an element: its `transform`, then for `<use>` and a nested `<svg>`
    /// `translate(x, y)`; a nested `<svg>` or a used `<symbol>` with a `viewBox` skips its shapes.
    fn enter(&mut self, node: Node<'_, '_>, tag: &str, ctx: &Rc<Context>, root: bool) -> Result<Rc<Context>> {
        let mut ctx = ctx.clone();
        if let Some(t) = node.attribute("transform") {
            ctx = match parse_transform(t, self.mode) {
                Ok(own) => self.compose(node, &ctx, own)?,
                Err(e) => problem(&ctx, e.within(&format!("transform=\"{t}\": "))),
            };
        }
        if tag == "use" || (tag == "svg" && !root) {
            let offset = length(node, "x", self.mode).and_then(|x| Ok((x, length(node, "y", self.mode)?)));
            ctx = match offset {
                Ok((x, y)) if x == rat(0) && y == rat(0) => ctx,
                Ok((x, y)) => self.compose(node, &ctx, Affine([rat(1), rat(0), rat(0), rat(1), x, y]))?,
                Err(e) => problem(&ctx, ShapeProblem::Invalid(format!("<{tag}>: {e}"))),
            };
        }
        if matches!(tag, "svg" | "symbol") && !root && node.attribute("viewBox").is_some() {
            let reason = format!("inside a <{tag}> with a viewBox (its viewport scaling is not read)");
            ctx = problem(&ctx, ShapeProblem::Skipped(reason));
        }
        Ok(ctx)
    }

    /// `ctx`'s transform followed by `own`, charged before it is computed.
    fn compose(&mut self, node: Node<'_, '_>, ctx: &Rc<Context>, own: Affine) -> Result<Rc<Context>> {
        let Ok(outer) = &ctx.transform else { return Ok(ctx.clone()) };
        let uses = ctx.uses.clone();
        if ctx.identity {
            let (sizes, identity) = (own.sizes(), own == Affine::identity());
            return Ok(Rc::new(Context { transform: Ok(Rc::new(own)), sizes, identity, uses }));
        }
        let (work, sizes) = compose_work(&ctx.sizes, &own.sizes());
        self.charge(node, work);
        if self.over.is_some() {
            // estimated only: the map itself is not needed any more
            return Ok(Rc::new(Context { transform: Ok(outer.clone()), sizes, identity: false, uses }));
        }
        let transform = outer.compose(&own);
        let (sizes, identity) = (transform.sizes(), transform == Affine::identity());
        Ok(Rc::new(Context { transform: Ok(Rc::new(transform)), sizes, identity, uses }))
    }

    /// Lists a shape element with its contours in user space.
    fn draw(&mut self, node: Node<'a, 'i>, tag: &str, ctx: &Context) -> Result<()> {
        let m = match &ctx.transform {
            Err(p) => {
                self.list(node, tag, ctx, Err(p.clone()));
                return Ok(());
            }
            Ok(m) => m.clone(),
        };
        let own = match self.own_contours(node, tag, ctx.uses.is_some()) {
            Err(p) => {
                self.list(node, tag, ctx, Err(p));
                return Ok(());
            }
            Ok(own) => own,
        };
        let pieces = || own.iter().flat_map(|c| &c.segments);
        let points: usize = pieces().map(points_of).sum();
        if ctx.uses.is_some() {
            self.copied_segments += pieces().count();
            if self.copied_segments > MAX_USE_SEGMENTS {
                return Err(Error::InvalidArgument {
                    message: format!(
                        "line {}: <{tag}>: segments drawn through <use> {} exceeds the limit {MAX_USE_SEGMENTS}",
                        self.line(node),
                        self.copied_segments
                    ),
                });
            }
        }
        let contours = if ctx.identity {
            if ctx.uses.is_some() {
                self.charge(node, points as f64 * COPY_POINT_WORK);
            }
            if self.over.is_some() {
                return Ok(());
            }
            Rc::unwrap_or_clone(own)
        } else {
            let bits = pieces().map(bits_of).max().unwrap_or(0);
            self.charge(node, points as f64 * apply_work(&ctx.sizes, bits));
            if self.over.is_some() {
                return Ok(());
            }
            let image = |c: &Contour| Contour {
                segments: c.segments.iter().map(|s| m.apply_segment(s)).collect(),
                closed: c.closed,
            };
            own.iter().map(image).collect()
        };
        self.list(node, tag, ctx, Ok(contours));
        Ok(())
    }

    fn list(
        &mut self,
        node: Node<'_, '_>,
        tag: &str,
        ctx: &Context,
        contours: std::result::Result<Vec<Contour>, ShapeProblem>,
    ) {
        let copy = ctx.uses.as_deref();
        self.shapes.push(SvgShape {
            index: self.shapes.len(),
            // a copy is named by its index: the id belongs to the original
            id: if copy.is_some() { None } else { node.attribute("id").map(str::to_string) },
            tag: tag.to_string(),
            line: self.line(node),
            use_line: copy.map(UseLink::outermost_line),
            contours,
        });
    }

    /// The element's own contours (read once per element for copies).
    fn own_contours(
        &mut self,
        node: Node<'_, '_>,
        tag: &str,
        copy: bool,
    ) -> std::result::Result<Rc<Vec<Contour>>, ShapeProblem> {
        if !copy {
            return shape(node, tag, self.mode).map(Rc::new);
        }
        let mode = self.mode;
        self.parsed.entry(node.id()).or_insert_with(|| shape(node, tag, mode).map(Rc::new)).clone()
    }

    /// The element a `<use>` draws, in its context; a problem of the `<use>` is listed.
    fn follow(&mut self, node: Node<'a, 'i>, ctx: &Rc<Context>) -> Result<Option<(Node<'a, 'i>, Rc<Context>, bool)>> {
        let href = node.attribute("href").or_else(|| node.attribute((XLINK, "href")));
        let fail = |w: &mut Self, p: ShapeProblem| {
            w.list(node, "use", ctx, Err(p));
            Ok(None)
        };
        let Some(href) = href else {
            return fail(self, ShapeProblem::Invalid("<use> without href: nothing to draw".into()));
        };
        let Some(id) = href.trim().strip_prefix('#') else {
            let why = format!("<use href=\"{href}\">: references outside the document are not read");
            return fail(self, ShapeProblem::Skipped(why));
        };
        let doc = self.doc;
        let ids = self.ids.get_or_insert_with(|| {
            let mut ids = HashMap::new();
            for n in doc.descendants().filter(|n| n.is_element()) {
                if let Some(i) = n.attribute("id") {
                    ids.entry(i).or_insert(n);
                }
            }
            ids
        });
        let Some(&target) = ids.get(id) else {
            return fail(self, ShapeProblem::Invalid(format!("<use href=\"{href}\">: no element has id \"{id}\"")));
        };
        let depth = ctx.uses.as_ref().map_or(0, |u| u.depth) + 1;
        let cycle = target == node
            || node.ancestors().any(|a| a == target)
            || ctx.uses.as_ref().is_some_and(|u| u.follows(target.id()));
        if cycle {
            let why = format!("<use href=\"{href}\">: it draws itself (a cycle of references)");
            return fail(self, ShapeProblem::Invalid(why));
        }
        if depth > MAX_USE_DEPTH {
            let why = format!("<use href=\"{href}\">: copies nested deeper than {MAX_USE_DEPTH}");
            return fail(self, ShapeProblem::Invalid(why));
        }
        let link = UseLink { target: target.id(), line: self.line(node), depth, outer: ctx.uses.clone() };
        let inner = Rc::new(Context {
            transform: ctx.transform.clone(),
            sizes: ctx.sizes,
            identity: ctx.identity,
            uses: Some(Rc::new(link)),
        });
        Ok(Some((target, inner, true)))
    }
}

/// The context with its shapes not read for `p` (a problem above keeps its own reason).
fn problem(ctx: &Rc<Context>, p: ShapeProblem) -> Rc<Context> {
    if ctx.transform.is_err() {
        return ctx.clone();
    }
    Rc::new(Context { transform: Err(p), sizes: ctx.sizes, identity: false, uses: ctx.uses.clone() })
}

/// The largest bit length of a piece's coordinates.
fn bits_of(s: &Segment) -> u64 {
    match s {
        Segment::Bezier(ps) => crate::work::max_bits(ps),
        Segment::Skipped { from, to, .. } => crate::work::max_bits(&[from.clone(), to.clone()]),
    }
}

/// Control points and ends of a piece.
fn points_of(s: &Segment) -> usize {
    match s {
        Segment::Bezier(ps) => ps.len(),
        Segment::Skipped { .. } => 2,
    }
}

/// `display="none"`, as an attribute or in the inline `style`.
fn hidden(node: Node<'_, '_>) -> bool {
    if node.attribute("display").is_some_and(|d| d.trim() == "none") {
        return true;
    }
    node.attribute("style").is_some_and(|s| {
        s.split(';').any(|d| d.split_once(':').is_some_and(|(k, v)| k.trim() == "display" && v.trim() == "none"))
    })
}

// ---------------------------------------------------------------------------------------------
// The work of exact affine maps

/// Work units of one product or sum of exact rationals of `b1` and `b2` bits (`mul_ratio`,
/// `add_ratio`), with `L(b)` limbs: `300 + 60·(L(b1) + L(b2))` for the allocations and the
/// remainders that bring a gcd down to the smaller size (a remainder by a word costs a 128-bit
/// division per limb), `2·L(b1)·L(b2)` for the products and `26·L(min)²` for Stein's gcd on the
/// smaller size (fitted on this machine: 0.45 to 2.4 times the measured time on 1,000 to 6,000 nested
/// SVG `scale(1.0001)` (a big entry times a small one), 300 and 1,000 nested
/// `matrix(1.0001 0.0003 -0.0007 0.9999 1.5 2.25)` (balanced gcds), their products applied
/// to 2,000 paths).
fn rational_op_work(b1: u64, b2: u64) -> f64 {
    let (l1, l2, small) = (crate::work::limbs(b1), crate::work::limbs(b2), crate::work::limbs(b1.min(b2)));
    300.0 + 60.0 * (l1 + l2) + 2.0 * l1 * l2 + 26.0 * small * small
}

/// The sizes of an affine map's entries, `[a b c d e f]`: 0 for a zero entry, else its bit
/// length (numerator plus denominator). Known exactly for a computed map, or estimated for one
/// that is not computed (each product's bits the sum of its factors', each sum's one more than
/// the sum of its terms').
type AffineSizes = [u64; 6];

impl Affine {
    /// The sizes of the entries.
    pub(crate) fn sizes(&self) -> AffineSizes {
        self.0.each_ref().map(|x| if x.numer().bits() == 0 { 0 } else { crate::work::bits(x) })
    }
}

/// The work and the bits of `x y + u v` of entries of the given sizes (a zero product costs
/// nothing).
fn dot_work(x: u64, y: u64, u: u64, v: u64) -> (f64, u64) {
    let term = |p: u64, q: u64| (p != 0 && q != 0).then(|| (rational_op_work(p, q), p.saturating_add(q)));
    sum_work(term(x, y), term(u, v))
}

/// The work and bits of the sum of two terms given as `(work, bits)` (`None`: a zero term).
fn sum_work(s: Option<(f64, u64)>, t: Option<(f64, u64)>) -> (f64, u64) {
    match (s, t) {
        (Some((w1, b1)), Some((w2, b2))) => {
            (w1 + w2 + rational_op_work(b1, b2), b1.saturating_add(b2).saturating_add(1))
        }
        (Some(x), None) | (None, Some(x)) => x,
        (None, None) => (0.0, 0),
    }
}

/// `(work, bits)` of a term, `None` for size 0.
fn nonzero(work: f64, bits: u64) -> Option<(f64, u64)> {
    (bits != 0).then_some((work, bits))
}

/// The work units of [`Affine::compose`] of maps of the given sizes, and the sizes of the
/// result (estimated).
fn compose_work(outer: &AffineSizes, inner: &AffineSizes) -> (f64, AffineSizes) {
    let [a, b, c, d, e, f] = *outer;
    let [a2, b2, c2, d2, e2, f2] = *inner;
    let shifted = |t: u64, (w, bits): (f64, u64)| sum_work(nonzero(w, bits), nonzero(0.0, t));
    let entries = [
        dot_work(a, a2, c, b2),
        dot_work(b, a2, d, b2),
        dot_work(a, c2, c, d2),
        dot_work(b, c2, d, d2),
        shifted(e, dot_work(a, e2, c, f2)),
        shifted(f, dot_work(b, e2, d, f2)),
    ];
    (entries.iter().map(|x| x.0).sum(), entries.map(|x| x.1))
}

/// The work units of [`Affine::apply`], for a map of the given sizes, to a point whose
/// coordinates have at most `point_bits` bits (neither of them zero).
fn apply_work(m: &AffineSizes, point_bits: u64) -> f64 {
    let [a, b, c, d, e, f] = *m;
    let coordinate = |p: u64, q: u64, t: u64| {
        let (w, bits) = dot_work(p, point_bits, q, point_bits);
        sum_work(nonzero(w, bits), nonzero(0.0, t)).0
    };
    coordinate(a, c, e) + coordinate(b, d, f)
}

#[cfg(test)]
mod calibration {
    use super::*;

    fn nested(depth: usize, transform: &str, shape: &str) -> String {
        format!("<svg>{}{shape}{}</svg>", format!("<g transform=\"{transform}\">").repeat(depth), "</g>".repeat(depth))
    }

    #[test]
    #[ignore]
    fn svg_transform_charges_against_time() {
        let square = "<path d=\"M0 0 H1 V1 Z\"/>";
        let many: String = (0..2000).map(|i| format!("<path d=\"M{i} 0 h1.37 v1.5 h-1.37 Z\"/>")).collect();
        let cases = [
            ("scale 1000", nested(1000, "scale(1.0001)", square)),
            ("scale 3000", nested(3000, "scale(1.0001)", square)),
            ("scale 6000", nested(6000, "scale(1.0001)", square)),
            ("matrix 300", nested(300, "matrix(1.0001 0.0003 -0.0007 0.9999 1.5 2.25)", square)),
            ("matrix 1000", nested(1000, "matrix(1.0001 0.0003 -0.0007 0.9999 1.5 2.25)", square)),
            ("translate 3000", nested(3000, "translate(1.37 2.5)", square)),
            ("scale 1000, 2000 paths", nested(1000, "scale(1.0001)", &many)),
            ("matrix 100, 2000 paths", nested(100, "matrix(1.0001 0.0003 -0.0007 0.9999 1.5 2.25)", &many)),
        ];
        for (name, text) in cases {
            let doc = roxmltree::Document::parse(&text).unwrap();
            let budget = Budget::unlimited();
            let t = std::time::Instant::now();
            let mut w = Walker::new(&doc, &text, NumberMode::Exact, &budget);
            w.walk().unwrap();
            let ns = t.elapsed().as_nanos() as f64;
            eprintln!("{name}: charged {:.2e}, took {:.2e} ns, ratio {:.2}", w.spent, ns, w.spent / ns);
        }
    }
}
