//! `casteljau intersect A B` and `casteljau intersect --self A`: exact intersections
//! (`casteljau::intersect`), one answer per pair; batch lines hold `A ; B` (or one curve with
//! `--self`).

use crate::args::IntersectArgs;
use crate::batch::{Answer, Json, batch_lines, numbers_in};
use casteljau::error::{Error, Result};
use casteljau::format::fill_path;
use casteljau::intersect::{Domain, Intersections, intersect, self_intersect};
use casteljau::num::rat;
use casteljau::num::{NumberMode, parse_points_in};
use casteljau::path::{ClosedPath, FillRule, PathWinding};
use casteljau::rational::RationalBezier;
use num_rational::BigRational;
use std::io::Write;

fn curve(
    text: &str,
    line: Option<usize>,
    mode: NumberMode,
    weights: &Option<Vec<BigRational>>,
) -> Result<RationalBezier<BigRational>> {
    let pts = parse_points_in(text, 2, line, mode)?;
    let n = pts.len();
    RationalBezier::new(pts, weights.clone().unwrap_or_else(|| vec![rat(1); n]))
}

fn text(r: &Intersections) -> String {
    let mut lines: Vec<String> = r
        .intersections
        .iter()
        .map(|i| {
            let point = match &i.point {
                Some(p) => p.to_string(),
                None => format!("(≈ {}, ≈ {})", i.point_float[0], i.point_float[1]),
            };
            format!(
                "s = {} (≈ {}), t = {} (≈ {}) at {point}: {}, contact order {}",
                i.s,
                i.s_float,
                i.t,
                i.t_float,
                i.kind.as_str(),
                i.contact_order
            )
        })
        .collect();
    for o in &r.overlaps {
        lines.push(format!("overlap: s in [{}, {}] with t from {} to {}", o.s[0], o.s[1], o.t[0], o.t[1]));
    }
    if lines.is_empty() { "no intersections".into() } else { lines.join("\n") }
}

/// Runs `intersect`; returns the exit code.
pub fn run(args: &IntersectArgs, out: &mut dyn Write) -> i32 {
    let mode: NumberMode = args.batch.numbers.into();
    let parse_w = |w: &Option<String>, name: &str| w.as_deref().map(|w| numbers_in(name, w, mode)).transpose();
    let (wa, wb) = match (parse_w(&args.weights_a, "--weights-a"), parse_w(&args.weights_b, "--weights-b")) {
        (Ok(a), Ok(b)) => (a, b),
        (Err(e), _) | (_, Err(e)) => {
            eprintln!("casteljau: {e}");
            return 2;
        }
    };
    let single = match (&args.a, &args.b, args.self_intersection) {
        (Some(a), None, true) => Some(a.clone()),
        (Some(a), Some(b), false) => Some(format!("{a} ; {b}")),
        (None, None, _) => None,
        (Some(_), Some(_), true) => {
            eprintln!("casteljau: --self takes one curve");
            return 2;
        }
        _ => {
            eprintln!("casteljau: give two curves A B (or --self A), or --input");
            return 2;
        }
    };
    let domain = if args.all { Domain::All } else { Domain::Unit };
    if let Some(path) = &args.plot {
        let Some(pair) = single.as_deref() else {
            eprintln!("casteljau: --plot draws one pair (give A B, not --input)");
            return 2;
        };
        if let Err(e) = plot(pair, args.self_intersection, mode, &wa, &wb, domain, path) {
            eprintln!("casteljau: --plot: {e}");
            return 2;
        }
    }
    let curve_args = args.batch.curve_args(single);
    let self_mode = args.self_intersection;
    let budget = casteljau::work::Budget::new(args.max_work, "--max-work");
    let json_out = args.batch.json;
    batch_lines(&curve_args, out, |line, text_line| {
        let r = if self_mode {
            self_intersect(&curve(text_line, line, mode, &wa)?, domain, &budget)?
        } else {
            let (a, b) = text_line
                .split_once(';')
                .ok_or_else(|| Error::InvalidArgument { message: "a pair of curves is written \"A ; B\"".into() })?;
            // which curve of the pair (its columns count from the start of its own text)
            let named = |which: &str, text: &str, w: &Option<Vec<BigRational>>| {
                curve(text, None, mode, w)
                    .map_err(|e| Error::InvalidArgument { message: format!("curve {which}: {e}") })
            };
            intersect(&named("A", a, &wa)?, &named("B", b, &wb)?, domain, &budget)?
        };
        // only the output asked for is rendered (an algebraic number's spelling has a cost)
        Ok(if json_out {
            crate::finite::check("the intersections", &r)?;
            let json = serde_json::to_string(&r).expect("exact strings and finite floats serialize");
            Answer { text: String::new(), json: Json::Object(json), failed: false }
        } else {
            Answer { text: text(&r), json: Json::Object(String::new()), failed: false }
        })
    })
}

/// `casteljau winding --point "x y" PATH`: the winding number of a closed path (segments
/// separated by `;`, or SVG path data with `--svg`, every subpath closed as SVG fills it,
/// [`fill_path`]) around the point, or where the point lies on the path. JSON: the
/// fields of [`PathWinding`]: `winding` (absent on the boundary), `inside` (non-zero rule),
/// `even_odd`, `on_boundary` (`{"subpath", "segment", "t", "t_float"}` or absent).
pub fn run_winding(args: &crate::args::WindingArgs, out: &mut dyn Write) -> i32 {
    let mode: NumberMode = args.batch.numbers.into();
    let q = match parse_points_in(&args.point, 2, None, mode) {
        Ok(p) if p.len() == 1 => casteljau::num::Point2::try_from(&p[0]).expect("read with dimension 2"),
        Ok(p) => {
            eprintln!("casteljau: --point takes one point \"x y\", got {}", p.len());
            return 2;
        }
        Err(e) => {
            eprintln!("casteljau: --point: {e}");
            return 2;
        }
    };
    let svg = args.svg;
    let budget = casteljau::work::Budget::new(args.max_work, "--max-work");
    let curve_args = args.batch.curve_args(args.path.clone());
    batch_lines(&curve_args, out, |line, text_line| {
        let path = if svg {
            fill_path(text_line, mode)?
        } else {
            let contour = text_line
                .split(';')
                .map(|s| parse_points_in(s, 2, line, mode).and_then(casteljau::BezierCurve::new))
                .collect::<Result<_>>()?;
            ClosedPath::from_polynomial(vec![contour])?
        };
        let r = path.winding(&q, &budget)?;
        let text = match &r {
            PathWinding::OnBoundary { on_boundary: b } => {
                format!("on the path: subpath {}, segment {}, t = {}", b.subpath, b.segment, b.t)
            }
            PathWinding::Off(w) => {
                let word = |rule| if w.inside(rule) { "inside" } else { "outside" };
                format!(
                    "winding number {}: {} (non-zero rule), {} (even-odd rule)",
                    w.winding(),
                    word(FillRule::NonZero),
                    word(FillRule::EvenOdd)
                )
            }
        };
        let json = Json::Value(serde_json::to_value(&r).expect("exact strings and finite floats serialize"));
        Ok(Answer { text, json, failed: false })
    })
}

/// `--plot FILE`: both curves (blue and green), transversal hits as black dots, tangencies as red
/// dots labelled with their contact order, overlaps as a thick orange band; written atomically.
fn plot(
    pair: &str,
    self_mode: bool,
    mode: NumberMode,
    wa: &Option<Vec<BigRational>>,
    wb: &Option<Vec<BigRational>>,
    domain: Domain,
    path: &std::path::Path,
) -> Result<()> {
    use crate::files::write_atomically;
    use casteljau::plot::{Figure, draw_rational};
    let (a, b) = if self_mode {
        let a = curve(pair, None, mode, wa)?;
        (a, None)
    } else {
        let (x, y) = pair.split_once(';').expect("a pair");
        (curve(x, None, mode, wa)?, Some(curve(y, None, mode, wb)?))
    };
    let r = match &b {
        Some(b) => intersect(&a, b, domain, &casteljau::work::Budget::unlimited())?,
        None => self_intersect(&a, domain, &casteljau::work::Budget::unlimited())?,
    };
    let mut fig = Figure::new().title(if self_mode { "self-intersections" } else { "intersections" });
    draw_rational(&mut fig, &a, "#1f5fbf", false);
    if let Some(b) = &b {
        draw_rational(&mut fig, b, "#2e8b57", false);
    }
    for o in &r.overlaps {
        let n = 64;
        let pts: Vec<(f64, f64)> = (0..=n)
            .filter_map(|k| {
                // the drawing needs no exact ends: the correctly rounded ones, taken exactly
                let [lo, hi] = o.s_float.map(BigRational::from_float);
                let (lo, hi) = (lo?, hi?);
                let s = lo.clone() + (hi - &lo) * BigRational::new(k.into(), n.into());
                let p = a.eval(&s).ok()?.to_f64();
                Some((p.coords[0], p.coords[1]))
            })
            .collect();
        fig.polyline(pts, "#ff9900", 7.0, false);
    }
    for i in &r.intersections {
        let at = (i.point_float[0], i.point_float[1]);
        if i.contact_order > 1 {
            fig.dot(at, 5.0, "#d62728");
            fig.label(at, &format!("tangent, order {}", i.contact_order), "#d62728");
        } else {
            fig.dot(at, 4.0, "#000000");
        }
    }
    write_atomically(path, fig.to_svg(640).as_bytes())
        .map_err(|e| Error::InvalidArgument { message: format!("cannot write {}: {e}", path.display()) })
}
