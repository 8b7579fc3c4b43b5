//! The rounded rendering of a boolean result as SVG path data (`BooleanResult::path`): each
//! piece's sub-curve from the exact segment ([`crate::curve::BezierCurve::subsegment`] when its
//! ends are rational), its control points rounded to the nearest `f64`; rational pieces through
//! [`super::hermite`]. The exact answer is the result's `pieces`; this is its float picture.

use super::graph::{Arrangement, InputPiece};
use super::hermite::hermite;
use super::segment::Seg;
use crate::num::scalar::{rat, ratio_to_f64};
use crate::poly::algebraic::RealAlgebraic;
use num_rational::BigRational;

/// SVG path data of the pieces: `M`, then `L`, `Q` or `C` per polynomial piece (the sub-curve's
/// control points, exact when both ends are rational, then rounded; the ends always the nearest
/// `f64` of the exact end points), rational pieces as four cubics through their points and
/// tangents (an approximation: `pieces` is the exact answer), `Z`.
pub(super) fn svg_path(arr: &Arrangement, contours: &[Vec<InputPiece>]) -> String {
    let mut out = String::new();
    let seg_of = |p: &InputPiece| {
        let ids = &arr.contours[p.input][p.contour];
        &arr.segs[ids[p.segment]]
    };
    for c in contours {
        for (i, p) in c.iter().enumerate() {
            let s = seg_of(p);
            let ctrl = sub_curve(s, &p.from, &p.to);
            if i == 0 {
                out.push_str(&format!("M{}", xy(ctrl[0][0])));
            }
            let closing = i + 1 == c.len() && c.len() > 1 && ctrl.len() == 1 && ctrl[0].len() == 2;
            if closing {
                break; // `Z` draws the closing line
            }
            for piece in ctrl {
                let letter = match piece.len() {
                    2 => "L",
                    3 => "Q",
                    _ => "C",
                };
                out.push_str(letter);
                let rest: Vec<String> = piece[1..].iter().map(|q| xy(*q)).collect();
                out.push_str(&rest.join(" "));
            }
        }
        if !c.is_empty() {
            out.push('Z');
        }
    }
    out
}

fn xy(p: [f64; 2]) -> String {
    let f = |v: f64| if v == 0.0 { "0".to_string() } else { format!("{v}") };
    format!("{} {}", f(p[0]), f(p[1]))
}

/// Control points (rounded) of the sub-curve `from → to`, as one or more curves.
fn sub_curve(s: &Seg, from: &RealAlgebraic, to: &RealAlgebraic) -> Vec<Vec<[f64; 2]>> {
    let polynomial = s.polynomial;
    if polynomial && let (Some(a), Some(b), Some(ps)) = (from.to_rational(), to.to_rational(), &s.hull) {
        let (zero, one) = (rat(0), rat(1));
        let f = |p: &crate::num::point::Point2<BigRational>| [ratio_to_f64(&p.x), ratio_to_f64(&p.y)];
        if *a == zero && *b == one {
            return vec![ps.iter().map(f).collect()];
        }
        if *a == one && *b == zero {
            return vec![ps.iter().rev().map(f).collect()];
        }
    }
    let (p0, p1) = (s.point_float(from), s.point_float(to));
    if !polynomial {
        return hermite(s, from.to_f64(), to.to_f64(), p0, p1);
    }
    let near = |t: &RealAlgebraic| -> BigRational {
        match t.to_rational() {
            Some(r) => r.clone(),
            None => {
                let mut t = t.clone();
                t.refine(&BigRational::new(1.into(), num_bigint::BigInt::from(1) << 80));
                let (lo, hi) = t.interval();
                (lo + hi) / rat(2)
            }
        }
    };
    let (a, b) = (near(from), near(to));
    let piece = s.curve.homogeneous().subsegment(&a, &b);
    let pts = piece.points();
    let n = pts.len();
    let mut out: Vec<[f64; 2]> = pts
        .iter()
        .map(|p| [ratio_to_f64(&(&p.coords[0] / &p.coords[2])), ratio_to_f64(&(&p.coords[1] / &p.coords[2]))])
        .collect();
    out[0] = p0;
    out[n - 1] = p1;
    vec![out]
}
