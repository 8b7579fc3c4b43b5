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

/// The pairs of non-degenerate segments whose boxes meet (a sweep over `x`), or that have no box.
pub(crate) fn candidate_pairs(segs: &[std::sync::Arc<Seg>]) -> Vec<(usize, usize)> {
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
    let mut pairs = vec![];
    let mut active: Vec<usize> = vec![];
    for &k in &boxed {
        let b = bx(k);
        active.retain(|&j| bx(j)[2] >= b[0]);
        for &j in &active {
            let c = bx(j);
            if c[1] <= b[3] && b[1] <= c[3] {
                pairs.push((j.min(k), j.max(k)));
            }
        }
        active.push(k);
    }
    for &u in &unboxed {
        for k in 0..segs.len() {
            if k != u && !segs[k].degenerate && (segs[k].bbox.is_some() || k > u) {
                pairs.push((u.min(k), u.max(k)));
            }
        }
    }
    pairs.sort_unstable();
    pairs.dedup();
    pairs
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
    match shared.len() {
        0 => hulls_separated(ha, hb).then(Vec::new),
        1 => {
            let (p, _, s, t) = shared[0];
            split_at_common_point(p, ha, hb).then(|| vec![(rat(*s).into(), rat(*t).into())])
        }
        _ => None,
    }
}
