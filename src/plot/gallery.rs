//! The seed figures that can be reproduced, as deterministic SVG files with an `index.html`.

use crate::curve::bezier::BezierCurve;
use crate::num::parse::parse_points;
use crate::num::point::Point;
use crate::num::scalar::{rat, ratio, ratio_to_f64};
use crate::plot::{CurveOptions, Figure, PALETTE, draw_curve, draw_rational, sample};
use crate::rational::rational_bezier::RationalBezier;
use crate::spline::Conversion;
use crate::spline::RationalSpline;
use crate::spline::net::SplineNet;
use crate::surface::RationalPatch;
use num_rational::BigRational;

/// Width of the gallery images, in pixels.
pub(crate) const WIDTH: u32 = 480;

fn curve(s: &str) -> BezierCurve<BigRational> {
    BezierCurve::new(parse_points(s, 2, None).expect("gallery data parses")).expect("gallery data is a curve")
}
fn weighted(s: &str, w: &[BigRational]) -> RationalBezier<BigRational> {
    RationalBezier::new(parse_points(s, 2, None).expect("gallery data parses"), w.to_vec())
        .expect("gallery data is a rational curve")
}
fn homogeneous(s: &str) -> RationalBezier<BigRational> {
    RationalBezier::from_homogeneous(parse_points(s, 3, None).expect("gallery data parses"))
        .expect("gallery data is a rational curve")
}

/// One gallery figure: file stem, caption, and the figure.
pub(crate) struct Entry {
    /// File name without `.svg`.
    pub name: &'static str,
    /// What the figure shows, with its seed source.
    pub caption: &'static str,
    /// The figure.
    pub figure: Figure,
}

fn cubic_figure(title: &str, pts: &str, opts: CurveOptions) -> Figure {
    let mut f = Figure::new().title(title);
    draw_curve(&mut f, &curve(pts), &opts, PALETTE[0]).expect("planar gallery curve");
    f
}

/// Oblique projection of a 3D point for surface wireframes.
fn project(p: &Point<BigRational>) -> (f64, f64) {
    let (x, y, z) = (ratio_to_f64(&p.coords[0]), ratio_to_f64(&p.coords[1]), ratio_to_f64(&p.coords[2]));
    (x + 0.5 * y, 0.45 * y + 0.8 * z)
}

fn draw_patch(f: &mut Figure, p: &RationalPatch, color: &str, contours: &[BigRational]) {
    let steps = 4;
    for k in 0..=steps {
        let s = BigRational::new(k.into(), steps.into());
        for iso in [
            p.iso_u(&s).expect("the gallery patch has iso-curves"),
            p.iso_v(&s).expect("the gallery patch has iso-curves"),
        ] {
            let eval = |t: &BigRational| iso.eval(t).ok().map(|q| project(&q));
            let width = if k == 0 || k == steps { 1.6 } else { 0.6 };
            for run in sample(&eval, &crate::plot::breaks([]), 1.0) {
                f.polyline(run, color, width, false);
            }
        }
    }
    for (i, c) in contours.iter().enumerate() {
        for seg in p.contour_polyline(2, c, 24) {
            let pts: Vec<(f64, f64)> = seg
                .iter()
                .filter_map(|&(u, v)| {
                    let (u, v) = (BigRational::from_float(u)?, BigRational::from_float(v)?);
                    p.eval(&u, &v).ok().map(|q| project(&q))
                })
                .collect();
            f.polyline(pts, PALETTE[(i + 1) % PALETTE.len()], 1.4, false);
        }
    }
}

fn net_5x5(k22: BigRational) -> SplineNet {
    let pts: Vec<Vec<Point<BigRational>>> = (0..5)
        .map(|i| {
            (0..5).map(|j| Point::new(vec![rat(j), rat(i), if (i, j) == (2, 2) { rat(2) } else { rat(0) }])).collect()
        })
        .collect();
    let mut w: Vec<Vec<BigRational>> = vec![vec![rat(1); 5]; 5];
    w[2][2] = k22;
    SplineNet::new((2, 2), pts, w, vec![rat(1); 6], vec![rat(1); 6]).expect("gallery net")
}

/// Every reproducible figure.
pub(crate) fn entries() -> Vec<Entry> {
    let mut out = Vec::new();
    let ex1 = "-2 0, -1 3, 1 2, 2 0";
    let mut f = Figure::new().title("seed 000 Fig. 17: weights pull the curve (w = 1111, 1311, 1141)");
    for (k, w) in [[1, 1, 1, 1], [1, 3, 1, 1], [1, 1, 4, 1]].iter().enumerate() {
        draw_rational(&mut f, &weighted(ex1, &w.map(rat)), PALETTE[k], k == 0);
    }
    out.push(Entry {
        name: "000-fig17-weights",
        caption: "seed 000, example 1 (Fig. 17): raising w1 or w2 pulls the curve towards b1 or b2",
        figure: f,
    });
    for (name, caption, title, pts, w) in [
        (
            "000-fig18a-folium",
            "seed 000, example 2 (Fig. 18a): the folium x³ − 3xy + y³ = 0",
            "Fig. 18a: folium of Descartes",
            "0 0, 1 0, 2 1, 3/2 3/2",
            vec![rat(1), rat(1), rat(1), rat(2)],
        ),
        (
            "000-fig18b-astroid",
            "seed 000, example 3 (Fig. 18b): the astroid",
            "Fig. 18b: astroid",
            "0 1, 0 1, 0 2/3, 1/4 1/4, 2/3 0, 1 0, 1 0",
            vec![rat(1), rat(1), ratio(6, 5), ratio(8, 5), ratio(12, 5), rat(4), rat(8)],
        ),
        (
            "000-fig18c-semicircle",
            "seed 000, example 4 (Fig. 18c): a semicircle from a cubic",
            "Fig. 18c: semicircle",
            "1 0, 1 2, -1 2, -1 0",
            vec![rat(1), ratio(1, 3), ratio(1, 3), rat(1)],
        ),
        (
            "000-fig20-hyperbola",
            "seed 000, example 6 (Fig. 20): hyperbola arc, cosh(s/2) = 5/4",
            "Fig. 20: hyperbola x² − y² = 1",
            "1 0, 1 3/5, 17/8 15/8",
            vec![rat(1), ratio(5, 4), rat(1)],
        ),
    ] {
        let mut f = Figure::new().title(title);
        draw_rational(&mut f, &weighted(pts, &w), PALETTE[0], true);
        out.push(Entry { name, caption, figure: f });
    }
    let mut f = Figure::new().title("Fig. 19a: circle arc, cos(s/2) = 3/5");
    draw_rational(&mut f, &homogeneous("1 0 1, 3/5 4/5 3/5, -7/25 24/25 1"), PALETTE[0], true);
    out.push(Entry {
        name: "000-fig19a-circle-arc",
        caption: "seed 000, example 5 (Fig. 19a): circle arc with rational half-angle",
        figure: f,
    });
    let mut f = Figure::new().title("Fig. 19b: s = π, b1 at infinity");
    draw_rational(&mut f, &homogeneous("1 0 1, 0 1 0, -1 0 1"), PALETTE[0], true);
    out.push(Entry {
        name: "000-fig19b-point-at-infinity",
        caption: "seed 000, example 5 at s = π (Fig. 19b): w1 = 0, b1 a point at infinity (arrow), still a semicircle",
        figure: f,
    });
    let ex = "-1 -1, -1/3 1, 1/3 -1, 1 1";
    out.push(Entry {
        name: "001-fig8-construction",
        caption: "seed 001 (Fig. 8): the de Casteljau construction at t = 1/3",
        figure: cubic_figure(
            "Fig. 8: de Casteljau at t = 1/3",
            ex,
            CurveOptions { polygon: true, construction: Some(ratio(1, 3)), ..Default::default() },
        ),
    });
    out.push(Entry {
        name: "001-fig9-subdivision",
        caption: "seed 001 (Fig. 9): subdivision of (2t−1, (2t−1)³) at t = 1/3",
        figure: cubic_figure(
            "Fig. 9: subdivision at t = 1/3",
            ex,
            CurveOptions { polygon: true, subdivide: Some((ratio(1, 3), 1)), ..Default::default() },
        ),
    });
    out.push(Entry {
        name: "001-fig10-subdivision-4",
        caption: "seed 001 (Fig. 10): subdivision at t = 1/2 four times; the polygons converge to the curve",
        figure: cubic_figure(
            "Fig. 10: t = 1/2, four times",
            ex,
            CurveOptions { subdivide: Some((ratio(1, 2), 4)), ..Default::default() },
        ),
    });
    let mut f = Figure::new().title("seed 002 Fig. 5: changing w1 (1/2, 1, 2, 5)");
    for (k, w1) in [ratio(1, 2), rat(1), rat(2), rat(5)].into_iter().enumerate() {
        draw_rational(&mut f, &weighted("0 0, 1 3, 3 3, 4 0", &[rat(1), w1, rat(1), rat(1)]), PALETTE[k], k == 1);
    }
    out.push(Entry {
        name: "002-fig5-weight-change",
        caption: "seed 002 (Fig. 5): each point moves along the line to P1 as w1 changes ((23) with the Bernstein γ)",
        figure: f,
    });
    let pts = parse_points("0 0, 1 3, 3 4, 5 1, 7 2, 8 5", 2, None).expect("data");
    let sp = RationalSpline::new(
        3,
        &pts,
        &[rat(1), rat(2), ratio(1, 2), rat(3), rat(1), ratio(2, 3)],
        &[1, 2, 1, 3, 2, 1, 2, 1].map(rat),
    )
    .expect("spline");
    let mut f = Figure::new().title("seed 002 Fig. 6: rational spline polygon and derived Bézier polygons");
    f.polyline(
        pts.iter().map(|p| (ratio_to_f64(&p.coords[0]), ratio_to_f64(&p.coords[1]))).collect(),
        "#888888",
        1.0,
        true,
    );
    for (s, seg) in sp.to_bezier_boehm().expect("the seed spline converts").iter().enumerate() {
        draw_rational(&mut f, seg, PALETTE[s % PALETTE.len()], false);
        let poly: Vec<(f64, f64)> =
            seg.points().iter().flatten().map(|p| (ratio_to_f64(&p.coords[0]), ratio_to_f64(&p.coords[1]))).collect();
        for q in &poly {
            f.dot(*q, 3.0, PALETTE[s % PALETTE.len()]);
        }
        f.polyline(poly, PALETTE[s % PALETTE.len()], 0.8, false);
    }
    out.push(Entry { name: "002-fig6-spline-to-bezier", caption: "seed 002 (Fig. 6): C²-joined rational Bézier segments derived from a cubic rational spline with unequal scale ratios", figure: f });
    for (name, caption, title, k22, contours) in [
        (
            "002-fig11-net",
            "seed 002 (Fig. 11): 9 biquadratic rational patches from a 5×5 rational spline net (oblique projection)",
            "Fig. 11: 5×5 net → 9 patches",
            rat(1),
            vec![],
        ),
        (
            "002-fig13-contours",
            "seed 002 (Fig. 13): the same net with k22 = 3: patch boundaries and contour lines z = 1/4, 1/2, 3/4",
            "Fig. 13: k22 = 3, contours",
            rat(3),
            vec![ratio(1, 4), ratio(1, 2), ratio(3, 4)],
        ),
    ] {
        let net = net_5x5(k22);
        let mut f = Figure::new().title(title);
        for row in net.to_patches(Conversion::Boehm, true).expect("net converts") {
            for p in row {
                draw_patch(&mut f, &p, "#555555", &contours);
            }
        }
        out.push(Entry { name, caption, figure: f });
    }
    for (name, caption, title, pts) in [
        (
            "004-fig1-crunode",
            "seed 004 (Fig. 1): a crunode: loop, double point D, E and the canonical frame",
            "Fig. 1: crunode",
            "0 0, 2 2, -1 2, 1 0",
        ),
        (
            "004-fig2-cusp",
            "seed 004 (Fig. 2): a cusp, drawn as a sharp vertex at its exact parameter",
            "Fig. 2: cusp",
            "0 0, 1 1, 0 1, 1 0",
        ),
        (
            "004-fig3-acnode",
            "seed 004 (Fig. 3): an acnode: isolated double point and two inflections",
            "Fig. 3: acnode",
            "1 -4, -1/3 0, 1/3 -4, 1 4",
        ),
        (
            "004-fig4-explicit",
            "seed 004 (Fig. 4): an explicit cubic (y = x³ up to an affine map): one inflection",
            "Fig. 4: explicit cubic",
            "0 0, 1 2, 2 -1, 3 1",
        ),
    ] {
        out.push(Entry {
            name,
            caption,
            figure: cubic_figure(title, pts, CurveOptions { polygon: true, features: true, ..Default::default() }),
        });
    }
    out
}

/// Every gallery file, `(name, content)`: one SVG per entry and `index.html`, all generated in
/// memory (no file is touched).
pub fn files() -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut html = String::from(
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>casteljau gallery</title></head>\n<body>\n<h1>casteljau: the seeds' figures, computed exactly</h1>\n",
    );
    for e in entries() {
        let file = format!("{}.svg", e.name);
        html += &format!("<figure><img src=\"{file}\" alt=\"{0}\"><figcaption>{0}</figcaption></figure>\n", e.caption);
        out.push((file, e.figure.to_svg(WIDTH)));
    }
    html += "</body></html>\n";
    out.push(("index.html".into(), html));
    out
}
