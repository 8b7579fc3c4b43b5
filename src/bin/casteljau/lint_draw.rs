//! The drawings of the `--html` report of `casteljau lint` (see `lint_html`): a glyph's outline
//! as inline SVG in screen coordinates (y flipped for fonts), its nodes and handles, and the
//! marks of its findings.

use crate::lint_units::Unit;
use casteljau::curve::BezierCurve;
use casteljau::format::Segment;
use casteljau::lint::{Axis, Evidence, ExactValue, Finding, Kind};
use casteljau::num::{Point, Point2};
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use std::fmt::Write as _;

/// The height of a drawing in CSS pixels (its width follows the outline's aspect, padded to
/// between [`MIN_ASPECT`] and [`MAX_ASPECT`]).
const HEIGHT: f64 = 440.0;
const MIN_ASPECT: f64 = 0.45;
const MAX_ASPECT: f64 = 1.9;

type P = Point2<f64>;

/// One segment for drawing, in screen coordinates (y flipped for fonts).
struct Seg {
    pts: Vec<P>,
    numbers: Vec<Option<usize>>,
    skipped: bool,
    /// Exact tangent directions at the start and at the end (`None`: the segment has none).
    out: Option<[BigRational; 2]>,
    into: Option<[BigRational; 2]>,
}

struct Outline {
    contours: Vec<(Vec<Seg>, bool)>,
    /// Stored points on no segment (contours of one point).
    lone: Vec<P>,
    flip: bool,
}

fn xy(p: &Point<BigRational>) -> [&BigRational; 2] {
    [&p.coords[0], &p.coords[1]]
}

fn diff(a: &Point<BigRational>, b: &Point<BigRational>) -> [BigRational; 2] {
    [&a.coords[0] - &b.coords[0], &a.coords[1] - &b.coords[1]]
}

impl Outline {
    fn new(u: &Unit) -> Outline {
        let flip = u.is_font();
        let f = |p: &Point<BigRational>| {
            let [x, y] = xy(p).map(casteljau::num::ratio_to_f64);
            Point2::new(x, if flip { -y } else { y })
        };
        let contours = u
            .glyph
            .contours
            .iter()
            .enumerate()
            .map(|(ci, c)| {
                let segs = c
                    .segments
                    .iter()
                    .enumerate()
                    .map(|(si, seg)| {
                        let numbers = u.glyph.numbers.get(ci).and_then(|n| n.get(si)).cloned().unwrap_or_default();
                        match seg {
                            Segment::Bezier(ps) => {
                                let out = ps.iter().skip(1).find(|p| *p != &ps[0]).map(|p| diff(p, &ps[0]));
                                let last = &ps[ps.len() - 1];
                                let into = ps.iter().rev().skip(1).find(|p| *p != last).map(|p| diff(last, p));
                                Seg { pts: ps.iter().map(f).collect(), numbers, skipped: false, out, into }
                            }
                            Segment::Skipped { from, to, .. } => {
                                Seg { pts: vec![f(from), f(to)], numbers, skipped: true, out: None, into: None }
                            }
                        }
                    })
                    .collect();
                (segs, c.closed)
            })
            .collect();
        let lone = u.glyph.lone_points.iter().map(f).collect();
        Outline { contours, lone, flip }
    }

    fn point(&self, p: [f64; 2]) -> P {
        Point2::new(p[0], if self.flip { -p[1] } else { p[1] })
    }

    fn segment(&self, contour: Option<usize>, index: Option<usize>) -> Option<&Seg> {
        self.contours.get(contour?)?.0.get(index?)
    }
}

/// `v` with at most `dec` decimals, trailing zeros dropped, no `-0`.
fn fmt(v: f64, dec: usize) -> String {
    let mut s = format!("{v:.dec$}");
    if s.contains('.') {
        while s.ends_with('0') {
            s.pop();
        }
        if s.ends_with('.') {
            s.pop();
        }
    }
    if s == "-0" { "0".into() } else { s }
}

/// The binary64 curve of control points `pts`.
fn curve(pts: &[P]) -> BezierCurve<f64> {
    BezierCurve::new(pts.iter().map(|p| Point::from(*p)).collect()).expect("a control point")
}

fn eval(pts: &[P], t: f64) -> P {
    Point2::try_from(&curve(pts).eval(&t)).expect("planar")
}

/// The control points of the piece `[a, b]` of a Bézier curve, running from the smaller
/// parameter to the larger.
fn piece(pts: &[P], a: f64, b: f64) -> Vec<P> {
    let (a, b) = if a <= b { (a, b) } else { (b, a) };
    curve(pts).subsegment(&a, &b).points().iter().map(|p| Point2::try_from(p).expect("planar")).collect()
}

/// A drawing's scale: user units per CSS pixel and the decimals of its numbers.
struct Pen {
    u: f64,
    dec: usize,
}

impl Pen {
    fn n(&self, v: f64) -> String {
        fmt(v, self.dec)
    }
    fn p(&self, p: P) -> String {
        format!("{} {}", self.n(p.x), self.n(p.y))
    }
    /// Path data of a Bézier segment continuing from its first point.
    fn seg(&self, pts: &[P], d: &mut String) {
        let cmd = match pts.len() {
            3 => 'Q',
            4 => 'C',
            _ => 'L',
        };
        d.push(cmd);
        let rest: Vec<String> = pts[1..].iter().map(|p| self.p(*p)).collect();
        d.push_str(&rest.join(" "));
    }
    fn circle(&self, class: &str, c: P, r_px: f64) -> String {
        let cls = if class.is_empty() { String::new() } else { format!(" class=\"{class}\"") };
        format!("<circle{cls} cx=\"{}\" cy=\"{}\" r=\"{}\"/>", self.n(c.x), self.n(c.y), self.n(r_px * self.u))
    }
}

fn finite(p: P) -> bool {
    p.x.is_finite() && p.y.is_finite()
}

/// The stored and computed boxes of a `bbox` finding, in screen coordinates (none for other
/// kinds).
fn boxes(f: &Finding, o: &Outline) -> Vec<(P, P)> {
    let Evidence::Bbox { stored, computed } = &f.evidence else { return vec![] };
    [stored, computed]
        .into_iter()
        .map(|b| {
            let v: Vec<f64> = b.iter().map(ExactValue::to_f64).collect();
            let (p, q) = (o.point([v[0], v[1]]), o.point([v[2], v[3]]));
            (Point2::new(p.x.min(q.x), p.y.min(q.y)), Point2::new(p.x.max(q.x), p.y.max(q.y)))
        })
        .collect()
}

/// The view box `(x, y, w, h)` and the size in pixels, or `None` when nothing finite is drawn.
fn view(o: &Outline, marked: &[&Finding]) -> Option<([f64; 4], [f64; 2])> {
    let mut pts: Vec<P> = o.contours.iter().flat_map(|(c, _)| c.iter().flat_map(|s| s.pts.iter().copied())).collect();
    pts.extend(&o.lone);
    for f in marked {
        pts.extend(f.at_float.iter().map(|p| o.point(*p)));
        for (a, b) in boxes(f, o) {
            pts.extend([a, b]);
        }
    }
    let pts: Vec<P> = pts.into_iter().filter(|p| finite(*p)).collect();
    if pts.is_empty() {
        return None;
    }
    let (mut x0, mut y0, mut x1, mut y1) = (f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY);
    for Point2 { x, y } in pts {
        (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x), y1.max(y));
    }
    let size = (x1 - x0).max(y1 - y0).max(1e-9);
    let (mut w, mut h) = ((x1 - x0).max(size * 0.02), (y1 - y0).max(size * 0.02));
    let m = 0.08 * size;
    (w, h) = (w + 2.0 * m, h + 2.0 * m);
    let (cx, cy) = ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
    if w / h < MIN_ASPECT {
        w = h * MIN_ASPECT;
    } else if w / h > MAX_ASPECT {
        h = w / MAX_ASPECT;
    }
    let v = [cx - w / 2.0, cy - h / 2.0, w, h];
    if !v.iter().all(|x| x.is_finite()) || w <= 0.0 || h <= 0.0 {
        return None;
    }
    let px = [(HEIGHT * w / h).round(), HEIGHT];
    Some((v, px))
}

/// Whether the node between tangents `into` and `out` is smooth: the tangents point the same way
/// (decided exactly).
fn smooth(into: &Option<[BigRational; 2]>, out: &Option<[BigRational; 2]>) -> bool {
    match (into, out) {
        (Some([a, b]), Some([c, d])) => (a * d - b * c).is_zero() && (a * c + b * d).is_positive(),
        _ => false,
    }
}

/// The SVG drawing of a unit, with its marks.
pub(crate) fn drawing(u: &Unit, marked: &[(usize, &Finding)]) -> Option<String> {
    let o = Outline::new(u);
    let fs: Vec<&Finding> = marked.iter().map(|(_, f)| *f).collect();
    let (v, px) = view(&o, &fs)?;
    let upx = v[3] / px[1];
    // enough decimals for a tenth of a pixel
    let dec = (-(upx / 10.0).log10()).ceil().clamp(0.0, 9.0) as usize;
    let pen = Pen { u: upx, dec };
    let mut s = String::new();
    let _ = write!(
        s,
        "<svg class=\"glyph\" width=\"{}\" height=\"{}\" viewBox=\"{} {} {} {}\" role=\"img\" aria-label=\"{}\">",
        px[0],
        px[1],
        pen.n(v[0]),
        pen.n(v[1]),
        pen.n(v[2]),
        pen.n(v[3]),
        esc(&u.label)
    );
    if o.flip && v[1] < 0.0 && v[1] + v[3] > 0.0 {
        let _ = write!(s, "<path class=\"base\" d=\"M{} 0H{}\"/>", pen.n(v[0]), pen.n(v[0] + v[2]));
    }
    // the outline
    let mut d = String::new();
    let mut skipped = String::new();
    for (segs, closed) in &o.contours {
        let Some(first) = segs.first() else { continue };
        if !finite(first.pts[0]) {
            continue;
        }
        let _ = write!(d, "M{}", pen.p(first.pts[0]));
        for sg in segs {
            if sg.pts.iter().all(|p| finite(*p)) {
                pen.seg(&sg.pts, &mut d);
                if sg.skipped {
                    let _ = write!(skipped, "M{}L{}", pen.p(sg.pts[0]), pen.p(sg.pts[1]));
                }
            }
        }
        if *closed {
            d.push('Z');
        }
    }
    if !d.is_empty() {
        let _ = write!(s, "<path class=\"fill\" d=\"{d}\"/><path class=\"ol\" d=\"{d}\"/>");
    }
    if !skipped.is_empty() {
        let _ = write!(s, "<path class=\"skip\" d=\"{skipped}\"/>");
    }
    // handles, off-curve points, nodes
    let (mut handles, mut offs, mut corners, mut rounds, mut implied) =
        (String::new(), String::new(), String::new(), String::new(), String::new());
    let r_off = 2.6 * pen.u;
    let r_on = 3.6 * pen.u;
    let a = 3.5 * pen.u;
    let r_imp = 2.0 * pen.u;
    let ring = |d: &mut String, c: P, r: f64| {
        let _ = write!(
            d,
            "M{} {}a{r} {r} 0 1 0 {} 0a{r} {r} 0 1 0 {} 0",
            pen.n(c.x - r),
            pen.n(c.y),
            pen.n(2.0 * r),
            pen.n(-2.0 * r),
            r = pen.n(r)
        );
    };
    let square = |d: &mut String, c: P| {
        let _ = write!(
            d,
            "M{} {}h{}v{}h{}z",
            pen.n(c.x - a),
            pen.n(c.y - a),
            pen.n(2.0 * a),
            pen.n(2.0 * a),
            pen.n(-2.0 * a)
        );
    };
    for (segs, closed) in &o.contours {
        let count = segs.len();
        for (si, sg) in segs.iter().enumerate() {
            if !sg.pts.iter().all(|p| finite(*p)) {
                continue;
            }
            if sg.pts.len() > 2 && !sg.skipped {
                let last = sg.pts.len() - 1;
                let _ = write!(handles, "M{}L{}", pen.p(sg.pts[0]), pen.p(sg.pts[1]));
                let _ = write!(handles, "M{}L{}", pen.p(sg.pts[last]), pen.p(sg.pts[last - 1]));
                for p in &sg.pts[1..last] {
                    ring(&mut offs, *p, r_off);
                }
            }
            // the node at the segment's start; an open contour's last end too
            let prev = if si > 0 {
                Some(&segs[si - 1])
            } else if *closed {
                segs.last()
            } else {
                None
            };
            let mut nodes = vec![(sg.pts[0], sg.numbers.first().copied().flatten(), prev.map(|p| &p.into), &sg.out)];
            if !closed && si + 1 == count {
                nodes.push((sg.pts[sg.pts.len() - 1], sg.numbers.last().copied().flatten(), Some(&sg.into), &None));
            }
            for (at, number, into, out) in nodes {
                let stored = sg.numbers.is_empty() || number.is_some();
                if !stored {
                    ring(&mut implied, at, r_imp);
                } else if into.is_some_and(|i| smooth(i, out)) {
                    ring(&mut rounds, at, r_on);
                } else {
                    square(&mut corners, at);
                }
            }
        }
    }
    for at in o.lone.iter().filter(|p| finite(**p)) {
        square(&mut corners, *at);
    }
    for (class, d) in [("hd", &handles), ("off", &offs), ("imp", &implied), ("on", &corners), ("on", &rounds)] {
        if !d.is_empty() {
            let _ = write!(s, "<path class=\"{class}\" d=\"{d}\"/>");
        }
    }
    // the marks, then their badges on top
    let mut badges: Vec<(P, usize, Kind)> = vec![];
    for (n, f) in marked {
        if let Some(at) = mark(&mut s, &pen, &o, f) {
            let mut b = Point2::new(at.x + 11.0 * pen.u, at.y - 11.0 * pen.u);
            for _ in 0..8 {
                let near = badges.iter().any(|(q, _, _)| (q.x - b.x).hypot(q.y - b.y) < 15.0 * pen.u);
                if !near {
                    break;
                }
                b.x += 16.0 * pen.u;
            }
            badges.push((b, *n, f.kind()));
        }
    }
    if !badges.is_empty() {
        let _ = write!(s, "<g font-size=\"{}\">", pen.n(10.0 * pen.u));
        for (b, n, k) in badges {
            let r = if n >= 10 { 8.5 } else { 7.5 };
            let _ = write!(
                s,
                "<g class=\"b k-{}\">{}<text x=\"{}\" y=\"{}\">{n}</text></g>",
                k.as_str(),
                pen.circle("", b, r),
                pen.n(b.x),
                pen.n(b.y)
            );
        }
        s.push_str("</g>");
    }
    s.push_str("</svg>");
    // finite output: a drawing with a number beyond the f64 range is left out (the glyph's
    // error says why)
    if crate::finite::non_finite_token(&s.replace(&esc(&u.label), "")).is_some() {
        return None;
    }
    Some(s)
}

/// Draws the mark of one finding; returns where its badge goes.
fn mark(s: &mut String, pen: &Pen, o: &Outline, f: &Finding) -> Option<P> {
    let pts: Vec<P> = f.at_float.iter().map(|p| o.point(*p)).filter(|p| finite(*p)).collect();
    let mut m = String::new();
    let mut badge = pts.first().copied();
    match &f.evidence {
        Evidence::Direction { .. } => {
            let segs = &o.contours.get(f.contour?)?.0;
            let start = segs.first()?.pts[0];
            // the first point away from the start gives the contour's direction there
            let next = segs.iter().flat_map(|sg| sg.pts.iter()).find(|p| **p != start && finite(**p));
            // the contour itself, then a ring at its start
            let mut d = format!("M{}", pen.p(start));
            for sg in segs.iter().filter(|sg| sg.pts.iter().all(|p| finite(*p))) {
                pen.seg(&sg.pts, &mut d);
            }
            let _ = write!(m, "<path class=\"hl thin\" d=\"{d}\"/>");
            m.push_str(&pen.circle("", start, 5.0));
            if let Some(next) = next {
                let (dx, dy) = (next.x - start.x, next.y - start.y);
                let len = dx.hypot(dy);
                let (ux, uy) = (dx / len, dy / len);
                let l = 34.0 * pen.u;
                let tip = Point2::new(start.x + ux * l, start.y + uy * l);
                let (hx, hy) = (tip.x - ux * 10.0 * pen.u, tip.y - uy * 10.0 * pen.u);
                let (nx, ny) = (-uy * 5.0 * pen.u, ux * 5.0 * pen.u);
                let _ = write!(m, "<path d=\"M{}L{}\"/>", pen.p(start), pen.p(Point2::new(hx, hy)));
                let _ = write!(
                    m,
                    "<path class=\"ah\" d=\"M{}L{}L{}Z\"/>",
                    pen.p(tip),
                    pen.p(Point2::new(hx + nx, hy + ny)),
                    pen.p(Point2::new(hx - nx, hy - ny))
                );
            }
            badge = Some(start);
        }
        Evidence::MissingExtremum { axis, .. } => {
            let p = *pts.first()?;
            let l = 14.0 * pen.u;
            if *axis == Axis::X {
                let _ = write!(m, "<path d=\"M{}V{}\"/>", pen.p(Point2::new(p.x, p.y - l)), pen.n(p.y + l));
            } else {
                let _ = write!(m, "<path d=\"M{}H{}\"/>", pen.p(Point2::new(p.x - l, p.y)), pen.n(p.x + l));
            }
            m.push_str(&pen.circle("dot", p, 3.2));
        }
        Evidence::OverlappingSegments { shared } => {
            let mut d = String::new();
            for sh in shared {
                if let Some(sg) = o.segment(Some(sh.contour), Some(sh.segment)) {
                    let pc = piece(&sg.pts, sh.from.to_f64(), sh.to.to_f64());
                    if pc.iter().all(|p| finite(*p)) {
                        let _ = write!(d, "M{}", pen.p(pc[0]));
                        pen.seg(&pc, &mut d);
                    }
                }
            }
            if !d.is_empty() {
                let _ = write!(m, "<path class=\"hl\" d=\"{d}\"/>");
            }
            for p in &pts {
                m.push_str(&pen.circle("dot", *p, 3.0));
            }
        }
        Evidence::DegenerateCurve => {
            let sg = o.segment(f.contour, f.index)?;
            if !sg.pts.iter().all(|p| finite(*p)) {
                return None;
            }
            let mut d = format!("M{}", pen.p(sg.pts[0]));
            pen.seg(&sg.pts, &mut d);
            let _ = write!(m, "<path class=\"hl\" d=\"{d}\"/>");
            badge = Some(eval(&sg.pts, 0.5));
        }
        Evidence::Bbox { .. } => {
            let bx = boxes(f, o);
            for (k, (a, b)) in bx.iter().enumerate() {
                let _ = write!(
                    m,
                    "<rect class=\"{}\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/>",
                    if k == 0 { "st" } else { "cp" },
                    pen.n(a.x),
                    pen.n(a.y),
                    pen.n(b.x - a.x),
                    pen.n(b.y - a.y)
                );
            }
            badge = bx.first().map(|(a, _)| *a);
        }
        _ => {
            for p in &pts {
                m.push_str(&pen.circle("", *p, 7.0));
            }
            if pts.is_empty() {
                // no point: the segment's middle
                let sg = o.segment(f.contour, f.index)?;
                badge = Some(eval(&sg.pts, 0.5)).filter(|p| finite(*p));
            }
        }
    }
    if !m.is_empty() {
        let _ = write!(s, "<g class=\"m k-{}\">{m}</g>", f.kind().as_str());
    }
    badge
}

/// `&`, `<`, `>`, `"` and `'` as references; controls HTML forbids as U+FFFD.
pub(crate) fn esc(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            '\t' | '\n' => out.push(c),
            c if c.is_control() || c == '\u{FFFE}' || c == '\u{FFFF}' => out.push('\u{FFFD}'),
            c => out.push(c),
        }
    }
    out
}
