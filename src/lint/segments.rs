//! The checks of one segment (`zero_length_segment`, `zero_length_handle`, `degenerate_curve`,
//! `missing_extremum`, `cusp`, `loop`) and of the glyph's boxes (`bbox`).

use super::exact::{ExactValue, strictly_inside};
use super::{Axis, Evidence, Finding, Glyph, Kind, LintOptions};
use crate::classify::classify;
use crate::curve::BezierCurve;
use crate::format::Segment;
use crate::num::point::Point;
use crate::num::quadratic_field::QuadraticExt;
use crate::num::scalar::rat;
use crate::poly::Poly;
use crate::poly::algebraic::RealAlgebraic;
use num_rational::BigRational;
use num_traits::Signed;
use std::cmp::Ordering;

type P = Point<BigRational>;

/// The power form of coordinate `axis` of the segment with control points `ps`.
pub(super) fn power(ps: &[P], axis: usize) -> Poly<BigRational> {
    Poly::new(crate::poly::bernstein::to_power(ps).into_iter().map(|c| c.coords[axis].clone()).collect())
}

/// `p(t)` for a polynomial `p` and an algebraic `t`, exactly.
fn value(p: &Poly<BigRational>, t: &RealAlgebraic) -> RealAlgebraic {
    t.map_rational(p, &Poly::constant(rat(1)))
}

fn exact_point(ps: &[P], t: &RealAlgebraic) -> [ExactValue; 2] {
    [0, 1].map(|a| ExactValue::from(value(&power(ps, a), t)))
}

fn quadratic_point(ps: &[P], t: &QuadraticExt<BigRational>) -> [ExactValue; 2] {
    [0, 1].map(|a| ExactValue::from(power(ps, a).map(|c| QuadraticExt::from_base(c.clone())).eval(t)))
}

/// The simple real roots of `p` (degree ≤ 2, power form) strictly inside `(0, 1)`: where the
/// polynomial changes sign. A double root (zero discriminant) is no sign change.
fn sign_changes(p: &Poly<BigRational>) -> Vec<RealAlgebraic> {
    let c = |k: usize| p.coeff(k);
    match p.degree() {
        None | Some(0) => vec![],
        Some(1) => {
            let t = -c(0) / c(1);
            if strictly_inside(&t) { vec![t.into()] } else { vec![] }
        }
        _ => {
            let disc = c(1) * c(1) - rat(4) * c(2) * c(0);
            if disc <= rat(0) {
                return vec![];
            }
            RealAlgebraic::roots_in(p, &rat(0), &rat(1))
                .into_iter()
                .filter(|t| t.sign() == Ordering::Greater && t.to_rational() != Some(&rat(1)))
                .collect()
        }
    }
}

/// A word-sized screen (doubled coordinates, exact): `true` when the segment surely has no
/// finding of the kinds asked for — it is not a point, has no zero-length handle, has its
/// written degree, and its control polygon is monotone in x and in y. Then `x′` (or `y′`) keeps
/// one strict sign inside `(0, 1)` (a Bernstein sum of same-signed differences vanishes inside
/// only when they are all zero), so there is no interior extremum, cusp or loop.
fn clean(q: &[[i64; 2]], o: &LintOptions) -> bool {
    let n = q.len() - 1;
    if q.iter().all(|p| *p == q[0]) {
        return false;
    }
    if n == 1 {
        return true;
    }
    if o.wants(Kind::ZeroLengthHandle) && (q[1] == q[0] || q[n - 1] == q[n]) {
        return false;
    }
    if o.wants(Kind::DegenerateCurve) {
        // the leading power coefficient Δ^n P0 (times C(n, n) = 1)
        let lead = |a: usize| -> i128 {
            let v: Vec<i128> = q.iter().map(|p| p[a] as i128).collect();
            if n == 2 { v[0] - 2 * v[1] + v[2] } else { v[3] - 3 * v[2] + 3 * v[1] - v[0] }
        };
        if lead(0) == 0 && lead(1) == 0 {
            return false;
        }
    }
    let monotone = |a: usize| {
        let d: Vec<i64> = q.windows(2).map(|w| w[1][a] - w[0][a]).collect();
        d.iter().all(|&x| x >= 0) || d.iter().all(|&x| x <= 0)
    };
    !(o.wants(Kind::MissingExtremum) || o.wants(Kind::Cusp) || o.wants(Kind::Loop)) || (monotone(0) && monotone(1))
}

/// The findings of one segment with control points `ps`.
pub(super) fn check(ps: &[P], o: &LintOptions) -> Vec<Finding> {
    let mut out = vec![];
    let n = ps.len() - 1;
    if let Some(q) = super::exact::doubled_all(ps)
        && clean(&q, o)
    {
        return out;
    }
    if ps.iter().all(|p| *p == ps[0]) {
        if o.wants(Kind::ZeroLengthSegment) {
            let what = if n == 1 { "line" } else { "curve" };
            out.push(
                Finding::new(Evidence::ZeroLengthSegment, format!("a {what} of length zero at {}", ps[0]))
                    .point_at(point(&ps[0])),
            );
        }
        return out;
    }
    if n >= 2 && o.wants(Kind::ZeroLengthHandle) {
        for (h, end, name) in [(1, 0, "first"), (n - 1, n, "last")] {
            if ps[h] == ps[end] {
                out.push(
                    Finding::new(
                        Evidence::ZeroLengthHandle,
                        format!("the {name} handle has length zero (on {})", ps[end]),
                    )
                    .point_at(point(&ps[end])),
                );
            }
        }
    }
    let powers = [power(ps, 0), power(ps, 1)];
    if n >= 2 && o.wants(Kind::DegenerateCurve) {
        let real = powers.iter().filter_map(Poly::degree).max().unwrap_or(0);
        if real < n {
            let what = ["a point", "a line", "a quadratic"][real];
            out.push(Finding::new(
                Evidence::DegenerateCurve,
                format!("written with degree {n}, the curve is {what} (its power form has degree {real})"),
            ));
        }
    }
    if n >= 2 && o.wants(Kind::MissingExtremum) {
        out.extend(extrema(ps, &powers, o));
    }
    let collinear = {
        let d = |i: usize| [&ps[i].coords[0] - &ps[0].coords[0], &ps[i].coords[1] - &ps[0].coords[1]];
        (1..=n).all(|i| (1..=n).all(|j| super::exact::cross(&d(i), &d(j)) == rat(0)))
    };
    if (n == 3 || (n == 2 && collinear)) && (o.wants(Kind::Cusp) || o.wants(Kind::Loop)) {
        out.extend(cusps_and_loops(ps, o));
    }
    out
}

fn point(p: &P) -> [ExactValue; 2] {
    [ExactValue::from(p.coords[0].clone()), ExactValue::from(p.coords[1].clone())]
}

/// `missing_extremum`: where a coordinate's derivative changes sign strictly inside the segment
/// (and the other does not vanish there: that is a cusp).
fn extrema(ps: &[P], powers: &[Poly<BigRational>; 2], o: &LintOptions) -> Vec<Finding> {
    let mut out = vec![];
    let n = ps.len() - 1;
    for axis in 0..2 {
        let d = powers[axis].derivative();
        let other = powers[1 - axis].derivative();
        for t in sign_changes(&d) {
            if t.sign_of(&other) == Ordering::Equal {
                continue;
            }
            let (e0, e1) = (&ps[0].coords[axis], &ps[n].coords[axis]);
            let (lo, hi) = if e0 <= e1 { (e0, e1) } else { (e1, e0) };
            // ±(x(t) − c)
            let shifted = |c: &BigRational, sign: i64| (&powers[axis] - &Poly::constant(c.clone())).scale(&rat(sign));
            let above = value(&shifted(hi, 1), &t);
            let below = value(&shifted(lo, -1), &t);
            let extent = if above >= below { above } else { below };
            if let Some(m) = &o.extremum_min
                && extent < RealAlgebraic::from(m.clone())
            {
                continue;
            }
            let half = rat(1) / rat(2);
            // |x(t) − e| < 1/2
            let near = |e: &BigRational| {
                let p = shifted(e, 1);
                t.sign_of(&(&p - &Poly::constant(half.clone()))) == Ordering::Less
                    && t.sign_of(&(&p + &Poly::constant(half.clone()))) == Ordering::Greater
            };
            let rounding = near(e0) || near(e1);
            let at = exact_point(ps, &t);
            let (extreme, tangent) = if axis == 0 { (Axis::X, "vertical") } else { (Axis::Y, "horizontal") };
            let extent = ExactValue::from(extent);
            let message = format!(
                "{tangent} tangent at t = {t}: {extreme} = {} is an extremum inside the segment, not a node ({} beyond its end points{})",
                at[axis],
                extent,
                if rounding { "; within half a unit of an end point's coordinate" } else { "" }
            );
            let evidence = Evidence::MissingExtremum { axis: extreme, extent };
            let mut f = Finding::new(evidence, message).point_at(at).rounded(rounding);
            f.parameters.push(ExactValue::from(t));
            out.push(f);
        }
    }
    out
}

/// `cusp` (strictly inside) and `loop` from the exact classification.
fn cusps_and_loops(ps: &[P], o: &LintOptions) -> Vec<Finding> {
    let mut out = vec![];
    let Ok(k) = BezierCurve::new(ps.to_vec()).and_then(|c| classify(&c)) else { return out };
    if o.wants(Kind::Cusp) {
        for t in k.cusp_parameters.iter().filter(|t| strictly_inside(*t)) {
            let at = quadratic_point(ps, t);
            let message = format!("the tangent vanishes and the curve turns back at t = {t}, ({}, {})", at[0], at[1]);
            let mut f = Finding::new(Evidence::Cusp, message).point_at(at);
            f.parameters.push(ExactValue::from(t.clone()));
            out.push(f);
        }
    }
    // a double point at t = 0 and 1 only is the segment's two ends meeting (a closed segment,
    // such as a contour of one cubic): the segment does not cross itself there
    let crossing = k.double_point_parameters.iter().any(strictly_inside);
    if o.wants(Kind::Loop) && k.segment.has_loop && crossing {
        let ts: Vec<ExactValue> = k.double_point_parameters.iter().map(|t| ExactValue::from(t.clone())).collect();
        let at = match &k.double_point {
            Some(p) => point(p),
            None => quadratic_point(ps, &k.double_point_parameters[0]),
        };
        let message = format!(
            "the segment crosses itself at ({}, {}), t = {}",
            at[0],
            at[1],
            ts.iter().map(|t| t.to_string()).collect::<Vec<_>>().join(" and ")
        );
        let mut f = Finding::new(Evidence::Loop, message).point_at(at);
        f.parameters = ts;
        out.push(f);
    }
    out
}

/// `bbox`: the stored `glyf` box against the box of the points, and the exact outline against
/// the font's `head` box.
pub(super) fn boxes(g: &Glyph) -> Vec<Finding> {
    let mut out = vec![];
    let segments: Vec<&Vec<P>> = g
        .contours
        .iter()
        .flat_map(|c| &c.segments)
        .filter_map(|s| match s {
            Segment::Bezier(ps) => Some(ps),
            Segment::Skipped { .. } => None,
        })
        .collect();
    if segments.is_empty() {
        return out;
    }
    let side = |b: &[BigRational; 4]| Box::new(b.clone().map(ExactValue::from));
    if let Some(stored) = &g.stored_box {
        let mut b = [0, 1, 0, 1].map(|a| segments[0][0].coords[a].clone());
        for p in segments.iter().flat_map(|s| s.iter()).chain(&g.lone_points) {
            for a in 0..2 {
                if p.coords[a] < b[a] {
                    b[a] = p.coords[a].clone();
                }
                if p.coords[a] > b[a + 2] {
                    b[a + 2] = p.coords[a].clone();
                }
            }
        }
        if b != *stored {
            let rounding = (0..4).all(|i| (&b[i] - &stored[i]).abs() < rat(1));
            let message = format!(
                "the glyph header stores the box [{}] but its points span [{}]",
                stored.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", "),
                b.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", ")
            );
            // a stale header box misleads clipping and layout a little: a warning
            let mut f = Finding::new(Evidence::Bbox { stored: side(stored), computed: side(&b) }, message);
            f.severity = super::Severity::Warning;
            out.push(f.rounded(rounding));
        }
    }
    // a segment lies in the hull of its control points: only a control point outside the
    // font's box can take the outline out of it
    let outside_hull = |font: &[BigRational; 4]| {
        segments
            .iter()
            .flat_map(|s| s.iter())
            .any(|p| (0..2).any(|a| p.coords[a] < font[a] || p.coords[a] > font[a + 2]))
    };
    if let Some(font) = g.font_box.as_ref().filter(|f| outside_hull(f)) {
        // the exact outline's extreme coordinates: end points and interior extrema
        let mut worst: [Option<RealAlgebraic>; 4] = [None, None, None, None];
        for ps in &segments {
            for axis in 0..2 {
                let c = power(ps, axis);
                let mut values: Vec<RealAlgebraic> =
                    [&ps[0], &ps[ps.len() - 1]].iter().map(|p| RealAlgebraic::from(p.coords[axis].clone())).collect();
                if ps.len() > 2 {
                    values.extend(sign_changes(&c.derivative()).iter().map(|t| value(&c, t)));
                }
                for v in values {
                    if worst[axis].as_ref().is_none_or(|w| v < *w) {
                        worst[axis] = Some(v.clone());
                    }
                    if worst[axis + 2].as_ref().is_none_or(|w| v > *w) {
                        worst[axis + 2] = Some(v);
                    }
                }
            }
        }
        let worst = worst.map(|w| w.expect("a segment"));
        let outside = (0..2).any(|a| worst[a] < RealAlgebraic::from(font[a].clone()))
            || (2..4).any(|a| worst[a] > RealAlgebraic::from(font[a].clone()));
        if outside {
            let beyond_one = (0..2).any(|a| worst[a] <= RealAlgebraic::from(&font[a] - rat(1)))
                || (2..4).any(|a| worst[a] >= RealAlgebraic::from(&font[a] + rat(1)));
            let computed = Box::new(worst.map(ExactValue::from));
            let message = format!(
                "the exact outline spans [{}], outside the font's head box [{}]",
                computed.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", "),
                font.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", ")
            );
            out.push(Finding::new(Evidence::Bbox { stored: side(font), computed }, message).rounded(!beyond_one));
        }
    }
    out
}
