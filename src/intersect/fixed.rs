//! A transversal crossing refined in 128-bit fixed point, for the box solver's route: from a
//! box that [`filter::solve`](super::filter::solve) proved to hold exactly one zero of
//! `F(σ, τ) = A(σ) − B(τ)`, Newton steps in fixed point (`i128`, 100 fractional bits) propose a
//! point `m` some `2^−95` from the zero, and Krawczyk's operator over the box `m ± r`
//! (`r = 2^−88`, wider if that fails) proves the zero in it: `F(m)` and the Jacobian are
//! evaluated in fixed point with a proved error of a few units of `2^−100`, then enclosed in
//! outward-rounded `f64` intervals. The parameters are then known to about `2^−88`, which
//! almost always decides their correctly rounded `f64`s (both ends of the box round to one
//! `f64`) and the correctly rounded coordinates of the point, with no evaluation of the
//! resultants. Every decision is a proof; whatever is not proved is left to the caller's exact
//! steps.
//!
//! Hand-written because the only wide operation needed is a 128 × 128-bit product shifted back
//! by 100 bits, which four word products give without allocating (a big-integer evaluation of
//! the same point costs some microseconds).

use super::filter::Enclosure;
use num_bigint::BigInt;
use num_traits::ToPrimitive;

/// Fractional bits of the fixed-point numbers.
const FRAC: i32 = 100;

/// `1` in fixed point.
const ONE: i128 = 1 << FRAC;

/// The largest sum of the absolute values of a polynomial's coefficients (and of its
/// derivative's) accepted: values on `[0, 1]` then stay below `2^24` (below `2^124` in fixed
/// point), so that no product overflows.
const MAX_SUM: i128 = 1 << 24;

/// `a·b / 2^100` truncated towards zero (within one unit of the exact quotient), for
/// `|a| < 2^126` and `|b| ≤ 2^100`: the 256-bit product from four word products.
fn mul(a: i128, b: i128) -> i128 {
    const M: u128 = u64::MAX as u128;
    let (x, y) = (a.unsigned_abs(), b.unsigned_abs());
    let (x1, x0, y1, y0) = (x >> 64, x & M, y >> 64, y & M);
    let (p00, p01, p10, p11) = (x0 * y0, x0 * y1, x1 * y0, x1 * y1);
    // x·y = p11·2^128 + p01·2^64 + p10·2^64 + p00 = hi·2^128 + (mid mod 2^64)·2^64 + (p00 mod 2^64)
    let mid = (p00 >> 64) + (p01 & M) + (p10 & M);
    let hi = p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64);
    // ⌊x·y / 2^100⌋ = hi·2^28 + ⌊(mid mod 2^64) / 2^36⌋ (the low word adds less than one unit
    // to a remainder below 2^100 − 2^64)
    let m = ((hi << 28) | ((mid & M) >> 36)) as i128;
    if (a < 0) != (b < 0) { -m } else { m }
}

/// The fixed-point number `v·2^−100` correctly rounded to `f64` (`i128 as f64` rounds to
/// nearest, ties to even; the scaling by a power of two is exact here).
fn to_f64(v: i128) -> f64 {
    v as f64 * f64::powi(2.0, -FRAC)
}

/// An enclosure of the fixed-point number `v ± e` (units of `2^−100`, `e ≥ 0`).
fn enclose(v: i128, e: i128) -> Enclosure {
    Enclosure::new(to_f64(v - e).next_down(), to_f64(v + e).next_up())
}

/// An integer polynomial (lowest degree first) with small coefficients, for fixed-point
/// evaluation on `[0, 1]`.
struct Poly {
    c: Vec<i128>,
    /// `Σ k·|c_k|`: a bound on `|p′|` over `[0, 1]`.
    slope: i128,
}

impl Poly {
    /// `None` when a coefficient sum exceeds [`MAX_SUM`].
    fn new(p: &[BigInt]) -> Option<Self> {
        let c: Vec<i128> = p.iter().map(ToPrimitive::to_i128).collect::<Option<_>>()?;
        let sum = c.iter().try_fold(0i128, |acc, x| acc.checked_add(x.checked_abs()?))?;
        let slope = c
            .iter()
            .enumerate()
            .try_fold(0i128, |acc, (k, x)| acc.checked_add(x.checked_abs()?.checked_mul(k as i128)?))?;
        (sum <= MAX_SUM && slope <= MAX_SUM).then_some(Poly { c, slope })
    }

    /// The derivative (its coefficients are bounded by the slope).
    fn derivative(&self) -> Poly {
        let c: Vec<i128> = self.c.iter().enumerate().skip(1).map(|(k, x)| x * k as i128).collect();
        let slope = c.iter().enumerate().map(|(k, x)| x.abs() * k as i128).sum();
        Poly { c, slope }
    }

    /// The error bound of [`Poly::at`], in units of `2^−100`: one per Horner step.
    fn error(&self) -> i128 {
        self.c.len().saturating_sub(1) as i128
    }

    /// `p(x)` for `0 ≤ x ≤ 1` in fixed point, within [`Poly::error`] units: each Horner step
    /// `acc·x + c` truncates once (under one unit), and `|x| ≤ 1` keeps earlier errors from
    /// growing. `|acc| ≤ Σ|c_k|` keeps every product in [`mul`]'s range.
    fn at(&self, x: i128) -> i128 {
        let Some((last, rest)) = self.c.split_last() else { return 0 };
        rest.iter().rev().fold(last * ONE, |acc, c| mul(acc, x) + c * ONE)
    }
}

/// `F(σ, τ) = (X_A(σ)·w_B − X_B(τ)·w_A, Y_A(σ)·w_B − Y_B(τ)·w_A)` (as
/// [`filter::System`](super::filter::System)) in fixed point, with derivatives.
pub(super) struct FixedSystem {
    /// `X_A·w_B`, `Y_A·w_B` (in σ), `X_B·w_A`, `Y_B·w_A` (in τ).
    p: [Poly; 4],
    /// Their derivatives.
    d: [Poly; 4],
    /// Both weights are 1 (integer control points): `p[0]`, `p[1]` are `A`'s coordinates.
    unit: bool,
}

/// A crossing's parameters to about `2^−88`: `σ ∈ [s.0, s.1]`, `τ ∈ [t.0, t.1]` (fixed point),
/// the one zero of `F` in the box the solver gave.
pub(super) struct Refined {
    s: (i128, i128),
    t: (i128, i128),
    /// The midpoint and radius of the `σ` interval.
    m: i128,
    r: i128,
}

impl FixedSystem {
    /// `None` for curves with a weight that is not constant, or coefficients too large.
    pub(super) fn new(fa: &[Vec<BigInt>; 3], fb: &[Vec<BigInt>; 3]) -> Option<Self> {
        if fa[2].len() != 1 || fb[2].len() != 1 {
            return None;
        }
        let (wa, wb) = (&fa[2][0], &fb[2][0]);
        let scaled = |p: &[BigInt], w: &BigInt| -> Option<Poly> {
            if num_traits::One::is_one(w) {
                Poly::new(p)
            } else {
                Poly::new(&p.iter().map(|c| c * w).collect::<Vec<_>>())
            }
        };
        let p = [scaled(&fa[0], wb)?, scaled(&fa[1], wb)?, scaled(&fb[0], wa)?, scaled(&fb[1], wa)?];
        let d = std::array::from_fn(|k| p[k].derivative());
        let one = |w: &BigInt| w.to_i64() == Some(1);
        Some(FixedSystem { p, d, unit: one(wa) && one(wb) })
    }

    /// `F(m)`, within `error` units.
    fn f(&self, m: [i128; 2]) -> [i128; 2] {
        [self.p[0].at(m[0]) - self.p[2].at(m[1]), self.p[1].at(m[0]) - self.p[3].at(m[1])]
    }

    /// `J(m)` (rows: components of `F`; columns: σ, τ).
    fn jacobian(&self, m: [i128; 2]) -> [[i128; 2]; 2] {
        [[self.d[0].at(m[0]), -self.d[2].at(m[1])], [self.d[1].at(m[0]), -self.d[3].at(m[1])]]
    }

    /// An `f64` inverse of `J(m)` (any matrix keeps Krawczyk's proof valid; a good one makes
    /// it succeed). `None` when it cannot be inverted.
    fn newton_matrix(&self, m: [i128; 2]) -> Option<[[f64; 2]; 2]> {
        let j = self.jacobian(m).map(|row| row.map(to_f64));
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        let y = [[j[1][1] / det, -j[0][1] / det], [-j[1][0] / det, j[0][0] / det]];
        (det != 0.0 && y.iter().flatten().all(|v| v.is_finite())).then_some(y)
    }

    /// The zero of `F` in the box `z` (`[σ_lo, σ_hi]`, `[τ_lo, τ_hi]`, inside `[0, 1]²`, proved
    /// to hold exactly one zero) to about `2^−88`: Newton steps from the box's midpoint, then
    /// Krawczyk's operator proves a box `m ± r` inside `z`, which therefore holds that zero.
    /// `None` when the proof does not succeed (the caller's exact steps decide then).
    pub(super) fn refine(&self, z: [(f64, f64); 2]) -> Option<Refined> {
        let scale = f64::powi(2.0, FRAC);
        // the box's ends in fixed point, rounded inwards
        let inner = |(lo, hi): (f64, f64)| -> Option<(i128, i128)> {
            if !(0.0 <= lo && lo <= hi && hi <= 1.0) {
                return None;
            }
            let (a, b) = (lo * scale, hi * scale);
            Some((a.ceil() as i128, b.floor() as i128))
        };
        let bounds = [inner(z[0])?, inner(z[1])?];
        let mut m = [0, 1].map(|k| ((z[k].0 + z[k].1) / 2.0 * scale) as i128);
        for _ in 0..6 {
            let y = self.newton_matrix(m)?;
            let f = self.f(m).map(to_f64);
            let step: [f64; 2] = std::array::from_fn(|r| y[r][0] * f[0] + y[r][1] * f[1]);
            // a step out of the unit square is no step towards the box's zero
            if !step.iter().all(|s| s.is_finite() && s.abs() < 1.0) {
                return None;
            }
            for k in 0..2 {
                m[k] -= (step[k] * scale) as i128;
                // evaluations need 0 ≤ m ≤ 1 (their error bound, and no overflow)
                if !(0..=ONE).contains(&m[k]) {
                    return None;
                }
            }
            if step.iter().all(|s| s.abs() < f64::powi(2.0, -96)) {
                break;
            }
        }
        // F's components' evaluation errors: X_A and X_B's, Y_A and Y_B's
        let err_f = [self.p[0].error() + self.p[2].error(), self.p[1].error() + self.p[3].error()];
        for bits in [88, 78, 68] {
            let r = 1i128 << (FRAC - bits);
            if (0..2).any(|k| m[k] - r < bounds[k].0 || m[k] + r > bounds[k].1) {
                continue;
            }
            if self.krawczyk_inside(m, r, err_f) {
                return Some(Refined { s: (m[0] - r, m[0] + r), t: (m[1] - r, m[1] + r), m: m[0], r });
            }
        }
        None
    }

    /// Krawczyk's operator on the box `m ± r` (fixed point) lies in the box's interior:
    /// `K − m = −Y·F(m) + (I − Y·J(x))·[−r, r]` inside `(−r, r)` in both coordinates, with
    /// `F(m)` and `J(x)` enclosed from fixed-point values and proved error bounds (`J` over the
    /// box: its value at `m` and the derivative bound times `r`).
    fn krawczyk_inside(&self, m: [i128; 2], r: i128, err_f: [i128; 2]) -> bool {
        let Some(y) = self.newton_matrix(m) else { return false };
        let f = self.f(m);
        let f = [enclose(f[0], err_f[0]), enclose(f[1], err_f[1])];
        let jm = self.jacobian(m);
        // row i, column k: d[i] (σ, k = 0) or −d[2 + i] (τ, k = 1)
        let j: [[Enclosure; 2]; 2] = std::array::from_fn(|i| {
            std::array::from_fn(|k| {
                let d = &self.d[2 * k + i];
                enclose(jm[i][k], d.error() + d.slope * r + 1)
            })
        });
        let rf = to_f64(r);
        let dx = Enclosure::new(-rf, rf);
        let point = |v: f64| Enclosure::new(v, v);
        (0..2).all(|row| {
            let yf = point(y[row][0]).mul(f[0]).add(point(y[row][1]).mul(f[1]));
            let mut k = yf.neg();
            for col in 0..2 {
                let yj = point(y[row][0]).mul(j[0][col]).add(point(y[row][1]).mul(j[1][col]));
                let delta = point(if row == col { 1.0 } else { 0.0 });
                k = k.add(delta.add(yj.neg()).mul(dx));
            }
            let (lo, hi) = k.ends();
            -rf < lo && hi < rf
        })
    }

    /// The point `A(σ)` of a refined crossing, each coordinate correctly rounded, when both
    /// curves have integer control points and the enclosure of each coordinate (its value at
    /// the midpoint within the evaluation error and the slope bound times the radius) rounds to
    /// one `f64`.
    pub(super) fn point_float(&self, x: &Refined) -> Option<[f64; 2]> {
        if !self.unit {
            return None;
        }
        let coordinate = |p: &Poly| {
            let (v, e) = (p.at(x.m), p.error() + p.slope * x.r);
            let (lo, hi) = (to_f64(v - e), to_f64(v + e));
            (lo == hi).then_some(lo)
        };
        Some([coordinate(&self.p[0])?, coordinate(&self.p[1])?])
    }
}

impl Refined {
    /// The interval of `σ` (`0`) or `τ` (`1`), fixed point.
    fn interval(&self, k: usize) -> (i128, i128) {
        if k == 0 { self.s } else { self.t }
    }

    /// An `f64` interval holding `σ` (`k = 0`) or `τ` (`k = 1`).
    pub(super) fn enclosure(&self, k: usize) -> (f64, f64) {
        let (lo, hi) = self.interval(k);
        (to_f64(lo).next_down(), to_f64(hi).next_up())
    }

    /// The parameter `σ` (`k = 0`) or `τ` (`k = 1`) correctly rounded, `u`, when both ends of
    /// its interval round to `u` and lie strictly inside `u`'s rounding cell (the numbers
    /// nearer to `u` than to its neighbours), with `u ≥ 2^−40` (so that the cell's ends are
    /// fixed-point numbers).
    pub(super) fn rounded(&self, k: usize) -> Option<f64> {
        let (lo, hi) = self.interval(k);
        let u = to_f64(lo);
        if u != to_f64(hi) || u < f64::powi(2.0, -40) || u >= 1.0 {
            return None;
        }
        let scale = f64::powi(2.0, FRAC);
        // twice the cell's ends, in fixed point (exact: u and its neighbours are multiples of 2^−92)
        let (below, at, above) = ((u.next_down() * scale) as i128, (u * scale) as i128, (u.next_up() * scale) as i128);
        (2 * lo > below + at && 2 * hi < at + above).then_some(u)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::intersect::filter::Regions;
    use crate::intersect::forms::{cubic, integer_forms};
    use crate::intersect::{Domain, pairing};

    /// On random font-like cubic pairs, every transversal crossing of the exact route refined
    /// from a box around it: the parameters and the point correctly rounded as the exact route
    /// gives them, for all but a rare few.
    #[test]
    fn refined_crossings_round_as_the_exact_route() {
        let mut next = crate::num::symmetric(0x5EED_F1AE_D0C5_0001);
        let (mut crossings, mut refined) = (0, 0);
        for round in 0..90 {
            let (mut va, vb): ([i64; 8], [i64; 8]) =
                (std::array::from_fn(|_| next(2048)), std::array::from_fn(|_| next(2048)));
            if round % 3 == 0 {
                // x linear in the parameter: forms of different lengths for X and Y
                let (x0, dx) = (next(1000), next(300));
                for k in 0..4 {
                    va[2 * k] = x0 + dx * k as i64;
                }
            }
            let (a, b) = (cubic(va), cubic(vb));
            let (fa, fb) = (integer_forms(&a), integer_forms(&b));
            let exact = pairing::intersect_forms(&fa, &fb, Domain::Unit, &Regions::Anywhere).unwrap();
            let sys = FixedSystem::new(&fa, &fb).expect("small integer cubics");
            for x in exact.intersections.iter().filter(|x| x.contact_order == 1) {
                crossings += 1;
                let around = |u: f64| ((u - 1e-12).max(0.0), (u + 1e-12).min(1.0));
                let Some(r) = sys.refine([around(x.s_float), around(x.t_float)]) else { continue };
                let (Some(s), Some(t)) = (r.rounded(0), r.rounded(1)) else { continue };
                assert_eq!((s.to_bits(), t.to_bits()), (x.s_float.to_bits(), x.t_float.to_bits()));
                // the refined interval holds the exact parameters
                let (lo, hi) = r.s;
                let q = |v: i128| num_rational::BigRational::new(v.into(), BigInt::from(1) << 100u32);
                assert!(crate::poly::RealAlgebraic::from(q(lo)) < x.s && x.s < q(hi).into());
                let p = sys.point_float(&r).expect("integer control points");
                assert_eq!(p.map(f64::to_bits), x.point_float.map(f64::to_bits));
                refined += 1;
            }
        }
        assert!(crossings > 30 && 20 * refined >= 19 * crossings, "{refined} of {crossings} refined");
    }

    /// The fixed-point product against exact big-integer arithmetic, signs and extremes
    /// included.
    #[test]
    fn fixed_point_product_is_within_one_unit() {
        let mut next = crate::num::xorshift(0x0123_4567_89AB_CDEF);
        for round in 0..2000 {
            let bits_a = 1 + round % 125;
            let a = (((u128::from(next()) << 64) | u128::from(next())) >> (128 - bits_a)) as i128;
            let b = (((u128::from(next()) << 64) | u128::from(next())) >> 27) as i128;
            let (a, b) = (if round % 3 == 0 { -a } else { a }, if round % 5 == 0 { -b } else { b });
            let exact = (BigInt::from(a) * BigInt::from(b)) >> 100u32; // floor
            let got = BigInt::from(mul(a, b));
            let diff = &exact - &got;
            assert!(diff == BigInt::from(0) || diff == BigInt::from(-1), "{a} × {b}: {got} vs {exact}");
        }
        assert_eq!(mul(ONE, ONE), ONE);
        assert_eq!(mul(-(1 << 125), ONE), -(1 << 125));
    }
}
