//! Certified binary64 arithmetic for the path oracle: a number `m` with a radius `r`, the exact
//! value lying in `[m − r, m + r]` (midpoint–radius intervals, as in Rump's INTLAB).
//!
//! Every operation rounds to nearest and adds its own rounding to the radius: for `±` and `×`,
//! `|fl(x ∘ y) − x ∘ y| ≤ u·|fl(x ∘ y)|·(1 + 2u) + η` (`u = 2⁻⁵³`, `η` the underflow), and the
//! propagated radii `r_x + r_y` or `|m_x|·r_y + |m_y|·r_x + r_x·r_y`; the radius itself is
//! computed in binary64 and then enlarged by the factor `1 + 4u` and the smallest normal number,
//! which covers the rounding of those few additions. So an upper bound computed from balls (a
//! distance, a control-point pairing) is an upper bound of the exact quantity, never an estimate.

use crate::num::scalar::ratio_to_f64;
use num_rational::BigRational;

/// The unit roundoff `2⁻⁵³`.
const U: f64 = f64::EPSILON / 2.0;

/// `x` enlarged to cover the rounding of the few operations that computed it.
fn up(x: f64) -> f64 {
    x * (1.0 + 4.0 * U) + f64::MIN_POSITIVE
}

/// A certified number: the exact value is within `r` of `m`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Ball {
    pub(super) m: f64,
    pub(super) r: f64,
}

/// A certified point.
pub(super) type BallPoint = [Ball; 2];

impl Ball {
    /// A binary64 number, exactly.
    #[cfg(test)]
    pub(super) fn exact(m: f64) -> Ball {
        Ball { m, r: 0.0 }
    }

    /// A rational, rounded to nearest (error at most `u·|m|`, or infinite past the range).
    pub(super) fn of(q: &BigRational) -> Ball {
        let m = ratio_to_f64(q);
        Ball { m, r: if m.is_finite() { up(U * m.abs()) } else { f64::INFINITY } }
    }

    pub(super) fn add(self, o: Ball) -> Ball {
        let m = self.m + o.m;
        Ball { m, r: up(self.r + o.r + U * m.abs()) }
    }

    pub(super) fn sub(self, o: Ball) -> Ball {
        let m = self.m - o.m;
        Ball { m, r: up(self.r + o.r + U * m.abs()) }
    }

    /// `self · t` for a binary64 `t` taken exactly.
    pub(super) fn scale(self, t: f64) -> Ball {
        let m = self.m * t;
        Ball { m, r: up(self.r * t.abs() + U * m.abs()) }
    }

    /// An upper bound of `|x|`.
    pub(super) fn abs_up(self) -> f64 {
        up(self.m.abs() + self.r)
    }
}

/// `a + t·(b − a)` for a binary64 `t` taken exactly.
pub(super) fn lerp(a: BallPoint, b: BallPoint, t: f64) -> BallPoint {
    [a[0].add(b[0].sub(a[0]).scale(t)), a[1].add(b[1].sub(a[1]).scale(t))]
}

/// `a + t·(b − a)` where `t` is the nearest binary64 of a rational `t* ∈ [0, 1]`: the parameter's
/// own rounding (`|t − t*| ≤ u·t`) is added to the radius.
fn lerp_rounded(a: BallPoint, b: BallPoint, t: f64) -> BallPoint {
    let mut p = lerp(a, b, t);
    for k in 0..2 {
        let extra = U * t * b[k].sub(a[k]).abs_up();
        p[k].r = up(p[k].r + extra);
    }
    p
}

/// An upper bound of the distance between two certified points.
pub(super) fn distance_up(p: BallPoint, q: BallPoint) -> f64 {
    let (dx, dy) = (p[0].sub(q[0]).abs_up(), p[1].sub(q[1]).abs_up());
    // hypot is within one ulp
    up(dx.hypot(dy))
}

/// The blossom of control points at the parameters `ts` (one per degree): with every `t` equal,
/// the point at `t`; with `n − i` copies of `a` and `i` of `b`, the `i`-th control point of the
/// piece on `[a, b]` (de Casteljau's algorithm with a parameter per level).
pub(super) fn blossom(points: &[BallPoint], ts: &[f64]) -> BallPoint {
    let mut q = points.to_vec();
    for (level, &t) in ts.iter().enumerate() {
        for i in 0..q.len() - 1 - level {
            q[i] = lerp(q[i], q[i + 1], t);
        }
    }
    q[0]
}

/// The control points of the piece on `[a, b]` (`a > b`: the piece reversed).
pub(super) fn sub_points(points: &[BallPoint], a: f64, b: f64) -> Vec<BallPoint> {
    let n = points.len() - 1;
    (0..=n)
        .map(|i| {
            let ts: Vec<f64> = (0..n).map(|k| if k < n - i { a } else { b }).collect();
            blossom(points, &ts)
        })
        .collect()
}

/// The point at `t`.
pub(super) fn point_at(points: &[BallPoint], t: f64) -> BallPoint {
    blossom(points, &vec![t; points.len() - 1])
}

/// Degree elevation by one: `Q_i = (i/(n+1))·P_{i−1} + (1 − i/(n+1))·P_i`.
pub(super) fn elevate(points: &[BallPoint]) -> Vec<BallPoint> {
    let n = points.len() - 1;
    let mut out = vec![points[0]];
    for i in 1..=n {
        let t = i as f64 / (n + 1) as f64;
        out.push(lerp_rounded(points[i], points[i - 1], t));
    }
    out.push(points[n]);
    out
}

/// The midpoints, for searches that need no certificate.
pub(super) fn mids(points: &[BallPoint]) -> Vec<[f64; 2]> {
    points.iter().map(|p| [p[0].m, p[1].m]).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::scalar::ratio;

    /// The ball of `1/3 + 1/3·3` holds `4/3`; a control point of a piece holds the exact one.
    #[test]
    fn ball_holds_the_exact_value() {
        let third = Ball::of(&ratio(1, 3));
        let s = third.add(third.scale(3.0));
        assert!((s.m - 4.0 / 3.0).abs() <= s.r && s.r < 1e-15);
        let p = |x: i64, y: i64| [Ball::exact(x as f64), Ball::exact(y as f64)];
        let pts = [p(0, 0), p(1, 2), p(2, 0)];
        let q = point_at(&pts, 0.5);
        assert_eq!((q[0].m, q[1].m), (1.0, 1.0));
        let sub = sub_points(&pts, 0.25, 0.75);
        // the middle control point of the half piece: the blossom (1/4, 3/4) = (1, 5/4)
        assert!((sub[1][0].m - 1.0).abs() <= sub[1][0].r + 1e-300 && (sub[1][1].m - 1.25).abs() <= sub[1][1].r);
        assert!(distance_up(p(0, 0), p(3, 4)) >= 5.0);
    }
}
