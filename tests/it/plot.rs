//! Figures rendered with a real SVG renderer (resvg / tiny-skia), asserting on pixels.

use casteljau::num::parse_points;
use casteljau::num::ratio_to_f64;
use casteljau::plot::{CurveOptions, Figure, draw_curve, draw_rational};
use casteljau::rational::RationalBezier;
use casteljau::{BezierCurve, rat};
use resvg::{tiny_skia, usvg};

const W: u32 = 400;

fn render(svg: &str) -> tiny_skia::Pixmap {
    let tree = usvg::Tree::from_str(svg, &usvg::Options::default()).expect("the SVG parses");
    let size = tree.size().to_int_size();
    let mut pix = tiny_skia::Pixmap::new(size.width(), size.height()).expect("a pixmap");
    resvg::render(&tree, tiny_skia::Transform::default(), &mut pix.as_mut());
    pix
}

fn is_white(p: tiny_skia::PremultipliedColorU8) -> bool {
    p.alpha() == 255 && p.red() > 245 && p.green() > 245 && p.blue() > 245
}

/// Some non-white pixel within `r` pixels of `(x, y)`.
fn inked_near(pix: &tiny_skia::Pixmap, (x, y): (f64, f64), r: i64) -> bool {
    (-r..=r).any(|dx| {
        (-r..=r).any(|dy| {
            let (px, py) = (x.round() as i64 + dx, y.round() as i64 + dy);
            px >= 0
                && py >= 0
                && (px as u32) < pix.width()
                && (py as u32) < pix.height()
                && !is_white(pix.pixel(px as u32, py as u32).unwrap())
        })
    })
}

fn border_is_blank(pix: &tiny_skia::Pixmap) -> bool {
    let (w, h) = (pix.width(), pix.height());
    (0..w).all(|x| is_white(pix.pixel(x, 0).unwrap()) && is_white(pix.pixel(x, h - 1).unwrap()))
        && (0..h).all(|y| is_white(pix.pixel(0, y).unwrap()) && is_white(pix.pixel(w - 1, y).unwrap()))
}

fn curve(s: &str) -> BezierCurve<num_rational::BigRational> {
    BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap()
}

#[test]
fn plot_curve_passes_through_its_exact_endpoints() {
    let c = curve("0 0, 1 3, 3 -1, 4 2");
    let mut fig = Figure::new();
    draw_curve(&mut fig, &c, &CurveOptions::default(), "#000000").unwrap();
    let pix = render(&fig.to_svg(W));
    for p in [&c.points()[0], &c.points()[3]] {
        let at = fig.to_pixel(ratio_to_f64(&p.coords[0]), ratio_to_f64(&p.coords[1]), W);
        assert!(inked_near(&pix, at, 1), "no ink at the endpoint pixel {at:?}");
    }
    // and through an exact interior point
    let m = c.eval(&casteljau::ratio(1, 3));
    assert!(inked_near(&pix, fig.to_pixel(ratio_to_f64(&m.coords[0]), ratio_to_f64(&m.coords[1]), W), 1));
    assert!(border_is_blank(&pix));
}

#[test]
fn plot_cusp_point_is_drawn_as_a_vertex() {
    let c = curve("0 0, 1 1, 0 1, 1 0"); // cusp at t = 1/2, at (1/2, 3/4)
    let mut fig = Figure::new();
    draw_curve(&mut fig, &c, &CurveOptions::default(), "#000000").unwrap();
    let svg = fig.to_svg(W);
    // the cusp (1/2, 3/4) is a vertex of the polyline, exactly
    assert!(svg.contains("0.5000,-0.7500"), "cusp vertex missing");
    let pix = render(&svg);
    assert!(inked_near(&pix, fig.to_pixel(0.5, 0.75, W), 1));
    // nothing is drawn above the cusp: the pixel 12 px above it is blank
    let (x, y) = fig.to_pixel(0.5, 0.75, W);
    assert!(!inked_near(&pix, (x, y - 12.0), 2));
    assert!(border_is_blank(&pix));
}

#[test]
fn plot_overlays_and_rational_curves_stay_inside_the_view_box() {
    let c = curve("-1 -1, -1/3 1, 1/3 -1, 1 1");
    let mut fig = Figure::new().title("construction").grid(true);
    let opts = CurveOptions {
        polygon: true,
        construction: Some(casteljau::ratio(1, 3)),
        subdivide: Some((casteljau::ratio(1, 2), 3)),
        features: true,
    };
    draw_curve(&mut fig, &c, &opts, "#0072b2").unwrap();
    let pix = render(&fig.to_svg(W));
    assert!(border_is_blank(&pix));
    // a rational curve through infinity: split, clipped, still inside
    let r =
        RationalBezier::new(parse_points("0 0, 1 1, 2 0", 2, None).unwrap(), vec![rat(1), rat(-2), rat(1)]).unwrap();
    let mut fig = Figure::new();
    draw_rational(&mut fig, &r, "#000000", true);
    assert!(border_is_blank(&render(&fig.to_svg(W))));
    // a point at infinity drawn as an arrow
    let semi = RationalBezier::from_homogeneous(parse_points("1 0 1, 0 1 0, -1 0 1", 3, None).unwrap()).unwrap();
    let mut fig = Figure::new();
    draw_rational(&mut fig, &semi, "#000000", true);
    let svg = fig.to_svg(W);
    assert!(svg.contains("<polygon"), "arrow head for the point at infinity");
    let pix = render(&svg);
    assert!(inked_near(&pix, fig.to_pixel(0.0, 1.0, W), 1)); // the top of the semicircle
    assert!(border_is_blank(&pix));
}

#[test]
fn plot_svg_is_deterministic() {
    let make = || {
        let mut fig = Figure::new().title("t");
        draw_curve(
            &mut fig,
            &curve("0 0, 2 2, -1 2, 1 0"),
            &CurveOptions { polygon: true, features: true, ..Default::default() },
            "#0072b2",
        )
        .unwrap();
        fig.to_svg(W)
    };
    assert_eq!(make(), make());
}

#[test]
fn gallery_writes_every_figure_parsable_with_index() {
    let tmp = crate::common::TempDir::new("gallery");
    let dir = tmp.join("gallery");
    // the real command writes the files
    let o = crate::common::run(&["gallery", dir.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(0), "{}", crate::common::stderr(&o));
    let files: Vec<String> = casteljau::plot::gallery::files().into_iter().map(|(name, _)| name).collect();
    assert!(files.len() >= 19, "{files:?}");
    let index = std::fs::read_to_string(dir.join("index.html")).unwrap();
    for f in files.iter().filter(|f| f.ends_with(".svg")) {
        assert!(index.contains(&format!("src=\"{f}\"")), "{f} not in index.html");
        let svg = std::fs::read_to_string(dir.join(f)).unwrap();
        let pix = render(&svg);
        assert!(border_is_blank(&pix), "{f} draws outside its view box");
        assert!(
            !is_white(pix.pixel(pix.width() / 2, pix.height() / 2).unwrap())
                || (0..pix.width()).any(|x| !is_white(pix.pixel(x, pix.height() / 2).unwrap())),
            "{f} looks empty"
        );
    }
    for name in ["000-fig17-weights.svg", "001-fig10-subdivision-4.svg", "002-fig11-net.svg", "004-fig2-cusp.svg"] {
        assert!(files.iter().any(|f| f == name), "{name}");
    }
    // deterministic: writing again gives the same bytes
    let again = tmp.join("again");
    assert_eq!(crate::common::run(&["gallery", again.to_str().unwrap()], None).status.code(), Some(0));
    for f in &files {
        assert_eq!(std::fs::read(dir.join(f)).unwrap(), std::fs::read(again.join(f)).unwrap(), "{f}");
    }
}

#[test]
fn gallery_checked_in_docs_are_current() {
    let docs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/gallery");
    for (name, content) in casteljau::plot::gallery::files().into_iter().filter(|(n, _)| n.ends_with(".svg")) {
        let file = docs.join(&name);
        let current = std::fs::read_to_string(&file).unwrap_or_default();
        assert!(current == content, "{} is stale: run `cargo run --release -- gallery docs/gallery`", file.display());
    }
}
