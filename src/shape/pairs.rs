//! Which pairs of segments an arrangement must solve, and the ones decided without a resultant
//! (step 1 of [`super::arrangement`]): boxes swept along `x`; two segments sharing one end
//! point `P` meet only there when a line through `P` has their other control points strictly on
//! opposite sides (their convex hulls then meet only at `P`); two segments whose control hulls a
//! line separates meet nowhere; a segment monotone in some direction does not cross itself. On
//! small integer coordinates (doubled, see [`Seg::small`]) every test runs in `i64`/`i128`.

use super::segment::Seg;
use crate::num::point::Point2;
use crate::num::scalar::rat;
use crate::poly::algebraic::RealAlgebraic;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

/// Whether every point of `xs` is strictly on the negative side of the line through `p` with
/// normal `n`, and every point of `ys` strictly on the positive side (points equal to `p` aside).
fn separated_at(
    p: &Point2<BigRational>,
    n: &[BigRational; 2],
    xs: &[Point2<BigRational>],
    ys: &[Point2<BigRational>],
) -> bool {
    let dot = |q: &Point2<BigRational>| (&q.x - &p.x) * &n[0] + (&q.y - &p.y) * &n[1];
    xs.iter().filter(|q| *q != p).all(|q| dot(q).is_negative())
        && ys.iter().filter(|q| *q != p).all(|q| dot(q).is_positive())
}

/// Two segments sharing the end point `p`: a line through `p` with their other control points
/// strictly on opposite sides.
fn split_at_common_point(p: &Point2<BigRational>, a: &[Point2<BigRational>], b: &[Point2<BigRational>]) -> bool {
    let away = |ps: &[Point2<BigRational>]| -> Option<[BigRational; 2]> {
        // the control point nearest to p along the polygon that differs from it
        let first = if ps[0] == *p { ps.iter().find(|q| *q != p) } else { ps.iter().rev().find(|q| *q != p) };
        first.map(|q| [&q.x - &p.x, &q.y - &p.y])
    };
    let (Some(da), Some(db)) = (away(a), away(b)) else { return false };
    let l1 = |v: &[BigRational; 2]| v[0].abs() + v[1].abs();
    let (na, nb) = (l1(&da), l1(&db));
    // db/|db|₁ − da/|da|₁, scaled by |da|₁|db|₁ > 0
    let candidates = [
        [&db[0] * &na - &da[0] * &nb, &db[1] * &na - &da[1] * &nb],
        [db[0].clone(), db[1].clone()],
        [-da[0].clone(), -da[1].clone()],
    ];
    candidates.iter().any(|n| !(n[0].is_zero() && n[1].is_zero()) && separated_at(p, n, a, b))
}

/// [`split_at_common_point`] on small integers (exact in `i128`).
pub(crate) fn split_at_common_point_small(p: [i64; 2], a: &[[i64; 2]], b: &[[i64; 2]]) -> bool {
    let away = |ps: &[[i64; 2]]| -> Option<[i128; 2]> {
        let first = if ps[0] == p { ps.iter().find(|q| **q != p) } else { ps.iter().rev().find(|q| **q != p) };
        first.map(|q| [(q[0] - p[0]) as i128, (q[1] - p[1]) as i128])
    };
    let (Some(da), Some(db)) = (away(a), away(b)) else { return false };
    let (na, nb) = (da[0].abs() + da[1].abs(), db[0].abs() + db[1].abs());
    let candidates = [[db[0] * na - da[0] * nb, db[1] * na - da[1] * nb], db, [-da[0], -da[1]]];
    let dot = |q: &[i64; 2], n: &[i128; 2]| (q[0] - p[0]) as i128 * n[0] + (q[1] - p[1]) as i128 * n[1];
    candidates.iter().any(|n| {
        *n != [0, 0]
            && a.iter().filter(|q| **q != p).all(|q| dot(q, n) < 0)
            && b.iter().filter(|q| **q != p).all(|q| dot(q, n) > 0)
    })
}

/// [`hulls_separated`] on small integers (exact in `i128`).
pub(crate) fn hulls_separated_small(a: &[[i64; 2]], b: &[[i64; 2]]) -> bool {
    let proj = |n: [i128; 2], ps: &[[i64; 2]]| {
        ps.iter()
            .map(|q| q[0] as i128 * n[0] + q[1] as i128 * n[1])
            .fold((i128::MAX, i128::MIN), |(lo, hi), v| (lo.min(v), hi.max(v)))
    };
    for set in [a, b] {
        for i in 0..set.len() {
            for j in i + 1..set.len() {
                let n = [(set[i][1] - set[j][1]) as i128, (set[j][0] - set[i][0]) as i128];
                if n == [0, 0] {
                    continue;
                }
                let ((alo, ahi), (blo, bhi)) = (proj(n, a), proj(n, b));
                if ahi < blo || bhi < alo {
                    return true;
                }
            }
        }
    }
    false
}

/// Whether a line strictly separates the convex hulls of `a` and `b` (tested on the normals of
/// every chord of either point set: a separating axis of two convex polygons is normal to one of
/// their edges).
fn hulls_separated(a: &[Point2<BigRational>], b: &[Point2<BigRational>]) -> bool {
    let proj = |n: &[BigRational; 2], ps: &[Point2<BigRational>]| -> (BigRational, BigRational) {
        let mut it = ps.iter().map(|q| &q.x * &n[0] + &q.y * &n[1]);
        let first = it.next().expect("control points");
        it.fold((first.clone(), first), |(lo, hi), v| {
            (if v < lo { v.clone() } else { lo }, if v > hi { v } else { hi })
        })
    };
    for set in [a, b] {
        for i in 0..set.len() {
            for j in i + 1..set.len() {
                let n = [&set[i].y - &set[j].y, &set[j].x - &set[i].x];
                if n[0].is_zero() && n[1].is_zero() {
                    continue;
                }
                let ((alo, ahi), (blo, bhi)) = (proj(&n, a), proj(&n, b));
                if ahi < blo || bhi < alo {
                    return true;
                }
            }
        }
    }
    false
}

/// What a certified `f64` filter decided.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Filtered {
    Yes,
    No,
    Unsure,
}

/// A bound on the error of every projection `q·n` computed in `f64` from the rounded points,
/// `n` the rounded normal of a chord, against the exact projection on the exact chord's normal:
/// with `M` the largest coordinate, each coordinate is off by at most `uM`, a normal's
/// component by `4uM`, and a projection (two products and a sum of terms below `2M²`) by
/// less than `64uM²`, plus a few subnormal spacings (`u = 2⁻⁵³`).
fn projection_error(a: &[[f64; 2]], b: &[[f64; 2]]) -> f64 {
    let m = a.iter().chain(b).flat_map(|p| p.iter()).fold(0f64, |m, c| m.max(c.abs()));
    64.0 * f64::EPSILON / 2.0 * m * m + 1e-300
}

/// [`hulls_separated`] decided in `f64` when the rounding cannot change the answer: some chord
/// separates the projections by more than twice the error bound (`Yes`: the rounded normal
/// itself separates the exact points), or every chord's projections overlap by more than that
/// (`No`: so do the exact chords' projections). Chords of points equal in `f64` are
/// `Unsure` unless the points are equal exactly (the exact test skips them).
fn hulls_separated_f64(a: (&[[f64; 2]], &[Point2<BigRational>]), b: (&[[f64; 2]], &[Point2<BigRational>])) -> Filtered {
    let err = projection_error(a.0, b.0);
    let proj = |n: [f64; 2], ps: &[[f64; 2]]| {
        ps.iter()
            .map(|q| q[0] * n[0] + q[1] * n[1])
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)))
    };
    let mut all_overlap = true;
    for (set, exact) in [a, b] {
        for i in 0..set.len() {
            for j in i + 1..set.len() {
                let n = [set[i][1] - set[j][1], set[j][0] - set[i][0]];
                if n == [0.0, 0.0] {
                    if exact[i] != exact[j] {
                        all_overlap = false; // a tiny exact chord: left to the exact test
                    }
                    continue;
                }
                let ((alo, ahi), (blo, bhi)) = (proj(n, a.0), proj(n, b.0));
                if ahi + 2.0 * err < blo || bhi + 2.0 * err < alo {
                    return Filtered::Yes;
                }
                if !(ahi - 2.0 * err > blo && bhi - 2.0 * err > alo) {
                    all_overlap = false;
                }
            }
        }
    }
    if all_overlap { Filtered::No } else { Filtered::Unsure }
}

/// [`split_at_common_point`] proved in `f64` (`true`) when a candidate normal `n`, rounded,
/// has the other control points of each segment strictly on its side of the line through `p`,
/// each `(q − p)·n` farther from 0 than its rounding error (`16uM·|n|₁`, `M` the largest
/// coordinate: the rounded normal is a normal like any other, only the points are rounded);
/// `false` when that does not settle (the exact test decides). A point equal to `p` in `f64`
/// must equal it exactly.
fn split_at_common_point_f64(
    (pf, pe): ([f64; 2], &Point2<BigRational>),
    a: (&[[f64; 2]], &[Point2<BigRational>]),
    b: (&[[f64; 2]], &[Point2<BigRational>]),
) -> bool {
    let m = a.0.iter().chain(b.0).flat_map(|q| q.iter()).fold(0f64, |m, c| m.max(c.abs()));
    let away = |ps: &[[f64; 2]]| -> Option<[f64; 2]> {
        let first = if ps[0] == pf { ps.iter().find(|q| **q != pf) } else { ps.iter().rev().find(|q| **q != pf) };
        first.map(|q| [q[0] - pf[0], q[1] - pf[1]])
    };
    let (Some(da), Some(db)) = (away(a.0), away(b.0)) else { return false };
    let (na, nb) = (da[0].abs() + da[1].abs(), db[0].abs() + db[1].abs());
    let candidates = [[db[0] * na - da[0] * nb, db[1] * na - da[1] * nb], db, [-da[0], -da[1]]];
    let side = |(ps, exact): (&[[f64; 2]], &[Point2<BigRational>]), n: &[f64; 2], sign: f64| {
        let margin = 8.0 * f64::EPSILON * m * (n[0].abs() + n[1].abs()) + 1e-300;
        ps.iter().zip(exact).all(|(q, e)| {
            if *q == pf { e == pe } else { sign * ((q[0] - pf[0]) * n[0] + (q[1] - pf[1]) * n[1]) > margin }
        })
    };
    candidates
        .iter()
        .any(|n| n.iter().all(|c| c.is_finite()) && *n != [0.0, 0.0] && side(a, n, -1.0) && side(b, n, 1.0))
}

/// A polynomial segment monotone in some direction (its hodograph in a closed half-plane with a
/// vector strictly inside), hence injective; or a rational quadratic with positive weights
/// whose control points are not collinear (an arc of a proper conic).
pub(crate) fn injective(s: &Seg) -> bool {
    let Some(ps) = &s.hull else { return false };
    if s.degree() <= 1 {
        return true;
    }
    let polynomial = s.curve.weights().windows(2).all(|w| w[0] == w[1]);
    if !polynomial {
        if s.degree() == 2 {
            let d = |i: usize, j: usize, k: usize| (&ps[j].x - &ps[i].x) * (&ps[k].y - &ps[i].y);
            let e = |i: usize, j: usize, k: usize| (&ps[j].y - &ps[i].y) * (&ps[k].x - &ps[i].x);
            return d(0, 1, 2) != e(0, 1, 2);
        }
        return false;
    }
    if let Some(small) = &s.small {
        return injective_small(small);
    }
    let h: Vec<[BigRational; 2]> = ps.windows(2).map(|w| [&w[1].x - &w[0].x, &w[1].y - &w[0].y]).collect();
    let mut candidates: Vec<[BigRational; 2]> = h.clone();
    let sum = h.iter().fold([rat(0), rat(0)], |acc, v| [&acc[0] + &v[0], &acc[1] + &v[1]]);
    candidates.push(sum);
    candidates.push([&h[0][0] + &h[h.len() - 1][0], &h[0][1] + &h[h.len() - 1][1]]);
    candidates.iter().any(|n| {
        let dots: Vec<BigRational> = h.iter().map(|v| &v[0] * &n[0] + &v[1] * &n[1]).collect();
        dots.iter().all(|d| !d.is_negative()) && dots.iter().any(|d| d.is_positive())
    })
}

/// [`injective`]'s hodograph test on small integers (doubled points: the same signs), exact in
/// `i128`.
pub(crate) fn injective_small(ps: &[[i64; 2]]) -> bool {
    let h: Vec<[i128; 2]> = ps.windows(2).map(|w| [(w[1][0] - w[0][0]) as i128, (w[1][1] - w[0][1]) as i128]).collect();
    let mut candidates: Vec<[i128; 2]> = h.clone();
    candidates.push(h.iter().fold([0, 0], |acc, v| [acc[0] + v[0], acc[1] + v[1]]));
    candidates.push([h[0][0] + h[h.len() - 1][0], h[0][1] + h[h.len() - 1][1]]);
    candidates.iter().any(|n| {
        let dots: Vec<i128> = h.iter().map(|v| v[0] * n[0] + v[1] * n[1]).collect();
        dots.iter().all(|d| *d >= 0) && dots.iter().any(|d| *d > 0)
    })
}

/// What [`sweep_pairs`] reports: a pair of segments to decide, or the box comparisons made
/// while the sweep has handled `done` of its `of` steps.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Visit {
    /// Segments `a < b` whose boxes meet (or one of which has no box).
    Pair(usize, usize),
    /// Comparisons of boxes, and the sweep's progress.
    Scanned { comparisons: u64, done: usize, of: usize },
}

/// Visits every pair of non-degenerate segments whose boxes meet (a sweep over `x`), or that
/// have no box, each once, without collecting them; stops (returning `false`) when `visit`
/// returns `false`.
pub(crate) fn sweep_pairs(segs: &[std::sync::Arc<Seg>], visit: &mut dyn FnMut(Visit) -> bool) -> bool {
    let mut boxed: Vec<usize> = vec![];
    let mut unboxed: Vec<usize> = vec![];
    for (k, s) in segs.iter().enumerate() {
        if s.degenerate {
            continue;
        }
        if s.bbox.is_some() { boxed.push(k) } else { unboxed.push(k) }
    }
    let bx = |k: usize| segs[k].bbox.expect("boxed");
    boxed.sort_by(|&a, &b| bx(a)[0].total_cmp(&bx(b)[0]));
    let of = boxed.len() + unboxed.len();
    let mut active: Vec<usize> = vec![];
    for (done, &k) in boxed.iter().enumerate() {
        let b = bx(k);
        if !visit(Visit::Scanned { comparisons: 2 * active.len() as u64 + 1, done, of }) {
            return false;
        }
        active.retain(|&j| bx(j)[2] >= b[0]);
        for &j in &active {
            let c = bx(j);
            if c[1] <= b[3] && b[1] <= c[3] && !visit(Visit::Pair(j.min(k), j.max(k))) {
                return false;
            }
        }
        active.push(k);
    }
    for (i, &u) in unboxed.iter().enumerate() {
        if !visit(Visit::Scanned { comparisons: segs.len() as u64, done: boxed.len() + i, of }) {
            return false;
        }
        for k in 0..segs.len() {
            if k != u
                && !segs[k].degenerate
                && (segs[k].bbox.is_some() || k > u)
                && !visit(Visit::Pair(u.min(k), u.max(k)))
            {
                return false;
            }
        }
    }
    true
}

/// Pairs decided without a resultant: the common points found (possibly none), or `None`.
pub(crate) fn easy_pair(a: &Seg, b: &Seg) -> Option<Vec<(RealAlgebraic, RealAlgebraic)>> {
    let (ha, hb) = (a.hull.as_ref()?, b.hull.as_ref()?);
    if let (Some(sa), Some(sb)) = (&a.small, &b.small) {
        let (a0, a1, b0, b1) = (sa[0], sa[sa.len() - 1], sb[0], sb[sb.len() - 1]);
        let ends = [(a1, b0, 1, 0), (a0, b1, 0, 1), (a0, b0, 0, 0), (a1, b1, 1, 1)];
        let shared: Vec<_> = ends.iter().filter(|(p, q, _, _)| p == q).collect();
        return match shared.len() {
            0 => hulls_separated_small(sa, sb).then(Vec::new),
            1 => {
                let (p, _, s, t) = *shared[0];
                split_at_common_point_small(p, sa, sb).then(|| vec![(rat(s).into(), rat(t).into())])
            }
            _ => None,
        };
    }
    let ends = [(&a.end, &b.start, 1, 0), (&a.start, &b.end, 0, 1), (&a.start, &b.start, 0, 0), (&a.end, &b.end, 1, 1)];
    let shared: Vec<_> = ends.iter().filter(|(p, q, _, _)| p == q).collect();
    // certified f64 first: the exact tests take a few hundred reduced products per pair
    let floats = a.approx.as_deref().zip(b.approx.as_deref());
    let (ha, hb) = (ha.as_slice(), hb.as_slice());
    match shared.len() {
        0 => {
            let decided = floats.map_or(Filtered::Unsure, |(fa, fb)| hulls_separated_f64((fa, ha), (fb, hb)));
            match decided {
                Filtered::Yes => Some(vec![]),
                Filtered::No => None,
                Filtered::Unsure => hulls_separated(ha, hb).then(Vec::new),
            }
        }
        1 => {
            let (p, _, s, t) = shared[0];
            let at = if *s == 1 { a.approx.as_ref().map(|f| f[f.len() - 1]) } else { a.approx.as_ref().map(|f| f[0]) };
            let proved = match (floats, at) {
                (Some((fa, fb)), Some(pf)) => split_at_common_point_f64((pf, *p), (fa, ha), (fb, hb)),
                _ => false,
            };
            (proved || split_at_common_point(p, ha, hb)).then(|| vec![(rat(*s).into(), rat(*t).into())])
        }
        _ => None,
    }
}
