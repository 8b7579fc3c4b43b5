//! SVG figures of curves, constructions and classifications.
//!
//! Geometry is computed exactly and converted to `f64` only for drawing. Curves are sampled
//! adaptively from exact evaluation, always including the special parameters (cusps, double
//! points, inflections, ends), so a cusp is a sharp vertex of the polyline, not a rounded guess.
//! Output is deterministic: the same input gives the same bytes (fixed number formatting, no
//! randomness, no timestamps), so figures can be checked in and diffed.

mod drawable;
pub mod gallery;

pub use drawable::draw_weight_family;

use crate::classify::{NodeType, classify};
use crate::curve::bezier::BezierCurve;
use crate::curve::fraction_free;
use crate::error::Result;
use crate::num::point::Point;
use crate::num::scalar::{Scalar, ratio_to_f64};
use crate::rational::rational_bezier::RationalBezier;
use num_rational::BigRational;
use std::fmt::Write as _;

/// Colours used by the figures (a colour-blind-safe palette).
pub const PALETTE: [&str; 6] = ["#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9"];

#[derive(Clone, Debug)]
enum Item {
    Polyline { pts: Vec<(f64, f64)>, color: String, width: f64, dashed: bool },
    Dot { at: (f64, f64), radius: f64, color: String },
    Label { at: (f64, f64), text: String, color: String },
    Arrow { from: (f64, f64), to: (f64, f64), color: String },
    Region { contours: Vec<Vec<(f64, f64)>>, color: String, opacity: f64 },
}

/// A figure: items in curve coordinates (y up), fitted into a view box with a margin.
#[derive(Clone, Debug, Default)]
pub struct Figure {
    items: Vec<Item>,
    title: Option<String>,
    grid: bool,
}

/// The fitted view: curve coordinates `[min_x, min_x + w] × [min_y, min_y + h]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct View {
    /// Left edge.
    pub min_x: f64,
    /// Bottom edge.
    pub min_y: f64,
    /// Width.
    pub w: f64,
    /// Height.
    pub h: f64,
}

fn num(v: f64) -> String {
    let s = format!("{v:.4}");
    if s == "-0.0000" { "0.0000".into() } else { s }
}

fn esc(s: &str) -> String {
    // characters XML 1.0 forbids (C0 controls but tab, LF, CR; U+FFFE, U+FFFF) become U+FFFD
    let allowed: String = s
        .chars()
        .map(|c| match c {
            '\t' | '\n' | '\r' => c,
            c if (c as u32) < 0x20 || c == '\u{FFFE}' || c == '\u{FFFF}' => '\u{FFFD}',
            c => c,
        })
        .collect();
    allowed.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

impl Figure {
    /// An empty figure.
    pub fn new() -> Self {
        Self::default()
    }
    /// A title drawn at the top.
    pub fn title(mut self, t: &str) -> Self {
        self.title = Some(t.to_string());
        self
    }
    /// Draw grid lines at integer coordinates (when not too many).
    pub fn grid(mut self, on: bool) -> Self {
        self.grid = on;
        self
    }
    /// A polyline.
    pub fn polyline(&mut self, pts: Vec<(f64, f64)>, color: &str, width: f64, dashed: bool) {
        let pts: Vec<(f64, f64)> = pts.into_iter().filter(|p| p.0.is_finite() && p.1.is_finite()).collect();
        if pts.len() >= 2 {
            self.items.push(Item::Polyline { pts, color: color.into(), width, dashed });
        }
    }
    /// A dot.
    pub fn dot(&mut self, at: (f64, f64), radius: f64, color: &str) {
        if at.0.is_finite() && at.1.is_finite() {
            self.items.push(Item::Dot { at, radius, color: color.into() });
        }
    }
    /// A text label at a point.
    pub fn label(&mut self, at: (f64, f64), text: &str, color: &str) {
        if at.0.is_finite() && at.1.is_finite() {
            self.items.push(Item::Label { at, text: text.into(), color: color.into() });
        }
    }
    /// A filled region: closed polylines filled together under the non-zero rule (a hole runs
    /// against its outer contour), with `opacity` between 0 and 1, no stroke.
    ///
    /// # Example
    /// ```
    /// use casteljau::plot::Figure;
    /// let mut f = Figure::new();
    /// f.region(vec![vec![(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]], "#1f5fbf", 0.3);
    /// assert!(f.to_svg(100).contains(r#"fill-opacity="0.30""#));
    /// ```
    pub fn region(&mut self, contours: Vec<Vec<(f64, f64)>>, color: &str, opacity: f64) {
        let contours: Vec<Vec<(f64, f64)>> = contours
            .into_iter()
            .map(|c| c.into_iter().filter(|p| p.0.is_finite() && p.1.is_finite()).collect::<Vec<_>>())
            .filter(|c| c.len() >= 3)
            .collect();
        if !contours.is_empty() {
            self.items.push(Item::Region { contours, color: color.into(), opacity: opacity.clamp(0.0, 1.0) });
        }
    }
    /// An arrow (a point at infinity drawn as a direction).
    pub fn arrow(&mut self, from: (f64, f64), to: (f64, f64), color: &str) {
        self.items.push(Item::Arrow { from, to, color: color.into() });
    }

    /// Every coordinate of every item, and the view box fitted to them, is a finite `f64` (the
    /// SVG then holds no `NaN` or `inf`); false for input beyond the `f64` range.
    ///
    /// # Example
    /// ```
    /// use casteljau::plot::Figure;
    /// let mut f = Figure::new();
    /// f.dot((0.0, 0.0), 1.0, "black");
    /// assert!(f.is_drawable());
    /// f.dot((1e308, 1e308), 1.0, "black");
    /// f.dot((-1e308, -1e308), 1.0, "black");
    /// assert!(!f.is_drawable()); // the view box would be infinitely wide
    /// ```
    pub fn is_drawable(&self) -> bool {
        let finite = |p: &(f64, f64)| p.0.is_finite() && p.1.is_finite();
        let items = self.items.iter().all(|it| match it {
            Item::Polyline { pts, .. } => pts.iter().all(finite),
            Item::Dot { at, .. } | Item::Label { at, .. } => finite(at),
            Item::Arrow { from, to, .. } => finite(from) && finite(to),
            Item::Region { contours, .. } => contours.iter().flatten().all(finite),
        });
        let v = self.view();
        items && [v.min_x, v.min_y, v.w, v.h].iter().all(|x| x.is_finite())
    }

    /// The view box: the bounding box of every item, with a 6% margin (and a minimum size).
    pub(crate) fn view(&self) -> View {
        let points: Vec<(f64, f64)> = self
            .items
            .iter()
            .flat_map(|it| match it {
                Item::Polyline { pts, .. } => pts.clone(),
                Item::Dot { at, .. } | Item::Label { at, .. } => vec![*at],
                Item::Arrow { from, to, .. } => vec![*from, *to],
                Item::Region { contours, .. } => contours.concat(),
            })
            .collect();
        let ((mut x0, mut y0), (mut x1, mut y1)) = bounds(&points);
        if !x0.is_finite() {
            (x0, y0, x1, y1) = (0.0, 0.0, 1.0, 1.0);
        }
        let (w, h) = ((x1 - x0).max(1e-9), (y1 - y0).max(1e-9));
        let size = w.max(h);
        let (w, h) = (w.max(size * 0.05), h.max(size * 0.05));
        let m = 0.06 * w.max(h);
        let top = if self.title.is_some() { 2.0 * m } else { m };
        View { min_x: x0 - m, min_y: y0 - m, w: w + 2.0 * m, h: h + m + top }
    }

    /// The pixel of curve point `(x, y)` in an image of `width` pixels rendered from
    /// [`Self::to_svg`].
    pub fn to_pixel(&self, x: f64, y: f64, width: u32) -> (f64, f64) {
        let v = self.view();
        let s = width as f64 / v.w;
        ((x - v.min_x) * s, (v.min_y + v.h - y) * s)
    }

    /// Standalone SVG, `width` pixels wide (the height follows the view's aspect).
    pub fn to_svg(&self, width: u32) -> String {
        let v = self.view();
        let height = (width as f64 * v.h / v.w).ceil().max(1.0) as u32;
        let unit = v.w / width as f64; // curve units per pixel
        let mut s = String::new();
        let _ = writeln!(
            s,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="{} {} {} {}">"#,
            num(v.min_x),
            num(-(v.min_y + v.h)),
            num(v.w),
            num(v.h)
        );
        // the background reaches past the view box: the rounded-up height letterboxes it by a
        // fraction of a pixel, which must not stay transparent
        let _ = writeln!(
            s,
            r#"<rect x="{}" y="{}" width="{}" height="{}" fill="white"/>"#,
            num(v.min_x - 0.05 * v.w),
            num(-(v.min_y + v.h) - 0.05 * v.h),
            num(1.1 * v.w),
            num(1.1 * v.h)
        );
        if self.grid {
            let (a, b) = (v.min_x.ceil() as i64, (v.min_x + v.w).floor() as i64);
            let (c, d) = (v.min_y.ceil() as i64, (v.min_y + v.h).floor() as i64);
            if b - a <= 100 && d - c <= 100 {
                // grid lines stop short of the image edge (inside the margin)
                let (ix, iy) = (0.03 * v.w, 0.03 * v.h);
                for x in a..=b {
                    let _ = writeln!(
                        s,
                        r##"<line x1="{0}" y1="{1}" x2="{0}" y2="{2}" stroke="#eeeeee" stroke-width="{3}"/>"##,
                        num(x as f64),
                        num(-(v.min_y + v.h) + iy),
                        num(-v.min_y - iy),
                        num(unit)
                    );
                }
                for y in c..=d {
                    let _ = writeln!(
                        s,
                        r##"<line x1="{1}" y1="{0}" x2="{2}" y2="{0}" stroke="#eeeeee" stroke-width="{3}"/>"##,
                        num(-(y as f64)),
                        num(v.min_x + ix),
                        num(v.min_x + v.w - ix),
                        num(unit)
                    );
                }
            }
        }
        for it in &self.items {
            match it {
                Item::Polyline { pts, color, width: w, dashed } => {
                    let p: Vec<String> = pts.iter().map(|&(x, y)| format!("{},{}", num(x), num(-y))).collect();
                    let dash = if *dashed {
                        format!(r#" stroke-dasharray="{} {}""#, num(4.0 * unit), num(3.0 * unit))
                    } else {
                        String::new()
                    };
                    let _ = writeln!(
                        s,
                        r#"<polyline points="{}" fill="none" stroke="{color}" stroke-width="{}" stroke-linejoin="miter" stroke-miterlimit="20"{dash}/>"#,
                        p.join(" "),
                        num(w * unit)
                    );
                }
                Item::Region { contours, color, opacity } => {
                    let d: Vec<String> = contours
                        .iter()
                        .map(|c| {
                            let p: Vec<String> = c.iter().map(|&(x, y)| format!("{},{}", num(x), num(-y))).collect();
                            format!("M{}Z", p.join(" "))
                        })
                        .collect();
                    let _ = writeln!(
                        s,
                        r#"<path d="{}" fill="{color}" fill-opacity="{opacity:.2}" fill-rule="nonzero" stroke="none"/>"#,
                        d.join(" ")
                    );
                }
                Item::Dot { at, radius, color } => {
                    let _ = writeln!(
                        s,
                        r#"<circle cx="{}" cy="{}" r="{}" fill="{color}"/>"#,
                        num(at.0),
                        num(-at.1),
                        num(radius * unit)
                    );
                }
                Item::Label { at, text, color } => {
                    let _ = writeln!(
                        s,
                        r#"<text x="{}" y="{}" font-family="sans-serif" font-size="{}" fill="{color}">{}</text>"#,
                        num(at.0 + 4.0 * unit),
                        num(-at.1 - 4.0 * unit),
                        num(12.0 * unit),
                        esc(text)
                    );
                }
                Item::Arrow { from, to, color } => {
                    let (dx, dy) = (to.0 - from.0, to.1 - from.1);
                    let len = (dx * dx + dy * dy).sqrt().max(1e-12);
                    let (ux, uy) = (dx / len, dy / len);
                    let hl = 8.0 * unit;
                    let (l, r) = (
                        (to.0 - hl * (ux - 0.5 * uy), to.1 - hl * (uy + 0.5 * ux)),
                        (to.0 - hl * (ux + 0.5 * uy), to.1 - hl * (uy - 0.5 * ux)),
                    );
                    let _ = writeln!(
                        s,
                        r#"<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{color}" stroke-width="{}"/>"#,
                        num(from.0),
                        num(-from.1),
                        num(to.0),
                        num(-to.1),
                        num(1.5 * unit)
                    );
                    let _ = writeln!(
                        s,
                        r#"<polygon points="{},{} {},{} {},{}" fill="{color}"/>"#,
                        num(to.0),
                        num(-to.1),
                        num(l.0),
                        num(-l.1),
                        num(r.0),
                        num(-r.1)
                    );
                }
            }
        }
        if let Some(t) = &self.title {
            let _ = writeln!(
                s,
                r#"<text x="{}" y="{}" font-family="sans-serif" font-size="{}" fill="black">{}</text>"#,
                num(v.min_x + 6.0 * unit),
                num(-(v.min_y + v.h) + 16.0 * unit),
                num(13.0 * unit),
                esc(t)
            );
        }
        s.push_str("</svg>\n");
        s
    }
}

fn f64_point(p: &Point<BigRational>) -> (f64, f64) {
    (ratio_to_f64(&p.coords[0]), p.coords.get(1).map_or(0.0, ratio_to_f64))
}

/// Adaptive samples of a curve given by an exact evaluator: the parameters `breaks` (sorted,
/// within `[0, 1]`, ends included) are always vertices; each interval is halved (exactly, on
/// rationals) until the chord is within 0.2% of the figure size, at least 8 and at most 4096
/// pieces per interval. Evaluations that fail (a pole) split the polyline.
pub(crate) fn sample(
    eval: &dyn Fn(&BigRational) -> Option<(f64, f64)>,
    breaks: &[BigRational],
    size: f64,
) -> Vec<Vec<(f64, f64)>> {
    let tol = 0.002 * size.max(1e-12);
    let mut runs: Vec<Vec<(f64, f64)>> = vec![vec![]];
    let push = |runs: &mut Vec<Vec<(f64, f64)>>, p: Option<(f64, f64)>| match p {
        Some(p) => runs.last_mut().expect("a run").push(p),
        None if runs.last().is_some_and(|r| !r.is_empty()) => runs.push(vec![]),
        None => {}
    };
    let sampler = Sampler { eval, tol };
    for w in breaks.windows(2) {
        let (pa, pb) = (eval(&w[0]), eval(&w[1]));
        if runs.last().is_some_and(|r| r.is_empty()) {
            push(&mut runs, pa);
        }
        let mut mid = Vec::new();
        sampler.refine(&w[0], pa, &w[1], pb, 0, &mut mid);
        for (_, p) in mid {
            push(&mut runs, p);
        }
        push(&mut runs, pb);
    }
    runs.into_iter().filter(|r| r.len() >= 2).collect()
}

/// Recursive halving of a parameter interval until the chord is flat enough.
struct Sampler<'a> {
    eval: &'a dyn Fn(&BigRational) -> Option<(f64, f64)>,
    tol: f64,
}

impl Sampler<'_> {
    fn refine(
        &self,
        a: &BigRational,
        pa: Option<(f64, f64)>,
        b: &BigRational,
        pb: Option<(f64, f64)>,
        depth: u32,
        out: &mut Vec<(BigRational, Option<(f64, f64)>)>,
    ) {
        let m = (a.clone() + b) / crate::num::scalar::rat(2);
        let pm = (self.eval)(&m);
        let flat = match (pa, pm, pb) {
            (Some(p), Some(q), Some(r)) => {
                let (dx, dy) = (r.0 - p.0, r.1 - p.1);
                let len = (dx * dx + dy * dy).sqrt();
                let dev = if len > 0.0 {
                    ((q.0 - p.0) * dy - (q.1 - p.1) * dx).abs() / len
                } else {
                    ((q.0 - p.0).powi(2) + (q.1 - p.1).powi(2)).sqrt()
                };
                dev < self.tol
            }
            _ => false,
        };
        if depth >= 12 || (depth >= 3 && flat) {
            out.push((m, pm));
            return;
        }
        self.refine(a, pa, &m, pm, depth + 1, out);
        out.push((m.clone(), pm));
        self.refine(&m, pm, b, pb, depth + 1, out);
    }
}

/// Sorted, deduplicated break parameters in `[0, 1]`: ends, and `extra` inside.
pub(crate) fn breaks(extra: impl IntoIterator<Item = BigRational>) -> Vec<BigRational> {
    let (z, o) = (crate::num::scalar::rat(0), crate::num::scalar::rat(1));
    let mut v: Vec<BigRational> = extra.into_iter().filter(|t| *t > z && *t < o).collect();
    v.push(z);
    v.push(o);
    v.sort();
    v.dedup();
    v
}

/// A rational close to an exact parameter (for drawing only).
fn approx(p: &crate::classify::Parameter) -> BigRational {
    BigRational::from_float(p.to_f64()).unwrap_or_else(|| crate::num::scalar::rat(0))
}

/// The bounding box `(min, max)` of points (infinite for none): the one box of the plots.
fn bounds(points: &[(f64, f64)]) -> ((f64, f64), (f64, f64)) {
    points.iter().fold(((f64::INFINITY, f64::INFINITY), (f64::NEG_INFINITY, f64::NEG_INFINITY)), |(lo, hi), p| {
        ((lo.0.min(p.0), lo.1.min(p.1)), (hi.0.max(p.0), hi.1.max(p.1)))
    })
}

fn size_of(points: &[(f64, f64)]) -> f64 {
    let ((x0, y0), (x1, y1)) = bounds(points);
    (x1 - x0).max(y1 - y0).max(1e-9)
}

/// What to draw for a polynomial curve.
#[derive(Clone, Debug, Default)]
pub struct CurveOptions {
    /// Draw and label the control polygon.
    pub polygon: bool,
    /// De Casteljau construction at this parameter (seed 001 Fig. 8).
    pub construction: Option<BigRational>,
    /// Repeated subdivision: parameter and depth (seed 001 Fig. 10).
    pub subdivide: Option<(BigRational, u32)>,
    /// Classification features (cubics): double point, cusp, inflections, loop, E and the
    /// canonical frame (seed 004 Figs. 1–4).
    pub features: bool,
}

/// Draws a polynomial planar curve with the chosen overlays.
///
/// # Errors
/// Only for curves that are not planar.
pub fn draw_curve(fig: &mut Figure, curve: &BezierCurve<BigRational>, opts: &CurveOptions, color: &str) -> Result<()> {
    if curve.dim() != 2 {
        return Err(crate::error::Error::DimensionMismatch { expected: 2, found: curve.dim() });
    }
    let poly: Vec<(f64, f64)> = curve.points().iter().map(f64_point).collect();
    let size = size_of(&poly);
    let mut special = Vec::new();
    let klass = (curve.degree() <= 3).then(|| classify(curve).ok()).flatten();
    if let Some(k) = &klass {
        special.extend(
            k.cusp_parameters.iter().chain(&k.double_point_parameters).chain(&k.inflection_parameters).map(approx),
        );
        // the cusp parameter is rational: use it exactly, so the cusp is a vertex
        special.extend(k.cusp_parameters.iter().filter_map(|p| p.to_base()));
    }
    let ic = fraction_free::IntegerCurve::new(curve);
    let eval = |t: &BigRational| Some(f64_point(&fraction_free::eval_integer(&ic, t)));
    for run in sample(&eval, &breaks(special), size) {
        fig.polyline(run, color, 2.0, false);
    }
    if opts.polygon {
        fig.polyline(poly.clone(), "#888888", 1.0, true);
        for (i, p) in poly.iter().enumerate() {
            fig.dot(*p, 3.0, "#444444");
            fig.label(*p, &format!("b{i}"), "#444444");
        }
    }
    if let Some(t) = &opts.construction {
        let tri = fraction_free::triangle(curve, t);
        for (r, row) in tri.rows.iter().enumerate().skip(1) {
            let pts: Vec<(f64, f64)> = row.iter().map(f64_point).collect();
            fig.polyline(pts.clone(), PALETTE[(r + 1) % PALETTE.len()], 1.2, false);
            for p in pts {
                fig.dot(p, 2.5, PALETTE[(r + 1) % PALETTE.len()]);
            }
        }
        let p = f64_point(tri.point());
        fig.dot(p, 4.0, "black");
        fig.label(p, &format!("b(t), t = {t}"), "black");
    }
    if let Some((t, depth)) = &opts.subdivide {
        let pieces = fraction_free::subdivide_repeatedly(curve, t, *depth)?;
        for (k, piece) in pieces.iter().enumerate() {
            fig.polyline(piece.points().iter().map(f64_point).collect(), PALETTE[k % 2 + 1], 1.0, false);
        }
    }
    if opts.features
        && let Some(k) = &klass
    {
        // features far from the control polygon would shrink the curve to a speck: they are
        // drawn as an arrow from the polygon's edge towards them, labelled with the position
        let (lo, hi) = bounds(&poly);
        let within = |q: (f64, f64), margin: f64| {
            q.0 >= lo.0 - margin && q.0 <= hi.0 + margin && q.1 >= lo.1 - margin && q.1 <= hi.1 + margin
        };
        let near = |q: (f64, f64)| within(q, size);
        let centre = ((lo.0 + hi.0) / 2.0, (lo.1 + hi.1) / 2.0);
        if let Some(d) = &k.double_point {
            let p = f64_point(d);
            let name = match k.node_type {
                Some(NodeType::Cusp) => "cusp",
                Some(NodeType::Acnode) => "acnode D",
                _ => "double point D",
            };
            if near(p) {
                fig.dot(p, 5.0, PALETTE[1]);
                fig.label(p, name, PALETTE[1]);
            } else if p.0.is_finite() && p.1.is_finite() {
                let (dx, dy) = (p.0 - centre.0, p.1 - centre.1);
                let len = (dx * dx + dy * dy).sqrt();
                let from = (centre.0 + 0.6 * size * dx / len, centre.1 + 0.6 * size * dy / len);
                let to = (centre.0 + 0.9 * size * dx / len, centre.1 + 0.9 * size * dy / len);
                fig.arrow(from, to, PALETTE[1]);
                fig.label(to, &format!("{name} far away at ({:.4e}, {:.4e})", p.0, p.1), PALETTE[1]);
            }
        }
        for t in &k.inflection_parameters {
            if let Some(p) = eval(&approx(t)).filter(|p| near(*p)) {
                fig.dot(p, 4.0, PALETTE[2]);
                fig.label(p, "inflection", PALETTE[2]);
            }
        }
        if k.segment.has_loop && k.double_point_parameters.len() == 2 {
            let (a, b) = (approx(&k.double_point_parameters[0]), approx(&k.double_point_parameters[1]));
            let mut ts = [a.clone(), b.clone()];
            ts.sort();
            let n = 64;
            let run: Vec<(f64, f64)> = (0..=n)
                .filter_map(|i| {
                    eval(&(ts[0].clone() + (ts[1].clone() - &ts[0]) * BigRational::new(i.into(), n.into())))
                })
                .collect();
            fig.polyline(run, PALETTE[3], 3.5, false);
        }
        let map = crate::classify::moving_line::MovingLines::new(curve)
            .and_then(|ml| crate::classify::canonical::canonical_map(curve, k, &ml, crate::proof::Reading::Corrected));
        if let Ok(map) = map {
            // reference points near the curve (far ones would only shrink the drawing)
            for (name, p) in &map.points {
                let q = (p.coords[0].to_f64(), p.coords[1].to_f64());
                if within(q, 0.25 * size) {
                    fig.dot(q, 3.0, PALETTE[4]);
                    fig.label(q, name, PALETTE[4]);
                }
            }
            // the canonical frame: origin M·(0,0), axis directions M·(1,0), M·(0,1), drawn at a
            // quarter of the curve's size
            let m = |r: usize, c: usize| map.matrix[r][c].to_f64();
            let o = (m(0, 2), m(1, 2));
            let axes = if near(o) { vec![(m(0, 0), m(1, 0)), (m(0, 1), m(1, 1))] } else { vec![] };
            for (dx, dy) in axes {
                let len = (dx * dx + dy * dy).sqrt();
                if len > 0.0 {
                    fig.arrow(o, (o.0 + 0.25 * size * dx / len, o.1 + 0.25 * size * dy / len), PALETTE[4]);
                }
            }
        }
    }
    Ok(())
}

/// Draws a rational planar curve: the curve (split where it passes through infinity), the
/// control polygon with weights, and points at infinity as arrows from their neighbours.
pub fn draw_rational(fig: &mut Figure, curve: &RationalBezier<BigRational>, color: &str, polygon: bool) {
    let finite: Vec<(f64, f64)> = curve.points().iter().flatten().map(f64_point).collect();
    let size = size_of(&finite);
    let (cx, cy) = finite.iter().fold((0.0, 0.0), |a, p| (a.0 + p.0, a.1 + p.1));
    let centre = (cx / finite.len().max(1) as f64, cy / finite.len().max(1) as f64);
    let far = 4.0 * size;
    let exact = curve.exact_evaluator();
    let eval = |t: &BigRational| {
        exact(t).ok().map(|p| f64_point(&p)).filter(|p| (p.0 - centre.0).abs() < far && (p.1 - centre.1).abs() < far)
    };
    let mut special = Vec::new();
    let unlimited = crate::work::Budget::unlimited();
    if let Ok(Some(roots)) =
        curve.denominator_roots(&crate::num::scalar::rat(0), &crate::num::scalar::rat(1), &unlimited)
    {
        for r in roots {
            match r {
                crate::poly::roots::Root::Exact(x) => special.push(x),
                crate::poly::roots::Root::Isolated(a, b) => special.push((a + b) / crate::num::scalar::rat(2)),
            }
        }
    }
    for run in sample(&eval, &breaks(special), size) {
        fig.polyline(run, color, 2.0, false);
    }
    if polygon {
        let pts = curve.points();
        let ws = curve.weights();
        let mut line = Vec::new();
        for (i, (p, w)) in pts.iter().zip(&ws).enumerate() {
            match p {
                Some(p) => {
                    let q = f64_point(p);
                    line.push(q);
                    fig.dot(q, 3.0, "#444444");
                    fig.label(q, &format!("b{i} (w {w})"), "#444444");
                }
                None => {
                    // a direction: draw it from the previous (or next) finite point
                    let h = &curve.homogeneous().points()[i];
                    let d = (ratio_to_f64(&h.coords[0]), ratio_to_f64(&h.coords[1]));
                    let len = (d.0 * d.0 + d.1 * d.1).sqrt().max(1e-12);
                    let from = line
                        .last()
                        .copied()
                        .or_else(|| pts.iter().flatten().next().map(f64_point))
                        .unwrap_or((0.0, 0.0));
                    let to = (from.0 + 0.4 * size * d.0 / len, from.1 + 0.4 * size * d.1 / len);
                    fig.arrow(from, to, "#444444");
                    fig.label(to, &format!("b{i} at infinity"), "#444444");
                }
            }
        }
        fig.polyline(line, "#888888", 1.0, true);
    }
}
