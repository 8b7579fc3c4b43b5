//! Correctly rounded `f64`s of a [`RealAlgebraic`] and Newton narrowing: an `f64` candidate from
//! a safeguarded Newton iteration, proved (or refuted) by exact signs at the ends of its
//! rounding cell; exact Newton steps in dyadic arithmetic whose intervals exact signs prove, so
//! precision roughly doubles per step; and the `f64` rounding cells and Newton steps the
//! intersection oracle's fast route builds certified roots from
//! (`RealAlgebraic::certified_root`). Hand-written because correct rounding needs the exact
//! signs that no floating-point root finder gives, and bisection alone costs one step per bit.

use super::dyadic::{aligned, dyadic, dyadic_parts, exact_f64, homogeneous_value, qmax, qmin};
use super::{RealAlgebraic, Repr};
use crate::num::scalar::ratio_to_f64;
use crate::poly::integer::derivative_integer;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

impl RealAlgebraic {
    /// The nearest `f64` (ties to even), correctly rounded: an `f64` candidate from a
    /// safeguarded Newton iteration, refined by one exact Newton step whose interval the exact
    /// signs prove and which rounds to one `f64`; else the candidate proved by the signs at
    /// the ends of its rounding cell (the midpoints to its neighbours); bisection when both
    /// fail ([`Self::narrowed_with_f64`]).
    pub fn to_f64(&self) -> f64 {
        match &self.0 {
            Repr::Rational(r) => ratio_to_f64(r),
            Repr::Root { .. } => self.narrowed_with_f64().1,
        }
    }

    /// [`Self::to_f64`] by bisection alone: the oracle of the fast route.
    fn to_f64_by_bisection(&self) -> f64 {
        let mut x = self.clone();
        loop {
            match &x.0 {
                Repr::Rational(r) => return ratio_to_f64(r),
                Repr::Root { lo, hi, .. } => {
                    let (a, b) = (ratio_to_f64(lo), ratio_to_f64(hi));
                    if a == b {
                        return a;
                    }
                }
            }
            x.bisect();
        }
    }

    /// For an irrational number: narrows the interval to half an `f64` spacing — between an
    /// `f64` and the midpoint to its neighbour — and returns the nearest `f64`. The candidate
    /// comes from [`f64_root_candidate`]; exact signs at `f64`s around it (galloping outwards,
    /// then bisecting over the `f64`s in order) find the two consecutive `f64`s around the
    /// number, and the sign at their midpoint picks the nearer. `None` (number unchanged) when
    /// it is rational, rounds to zero, or lies outside the finite `f64` range.
    fn narrow_to_f64_cell(&mut self) -> Option<f64> {
        let Repr::Root { poly, lo, hi } = &self.0 else { return None };
        let start = f64_root_candidate(poly, ratio_to_f64(lo), ratio_to_f64(hi))?;
        // f64s in order as integers (negative ones mirrored), and back
        let key = |f: f64| -> i64 {
            if f.is_sign_negative() { -((f.to_bits() & !(1 << 63)) as i64) } else { f.to_bits() as i64 }
        };
        let from_key = |k: i64| -> f64 { if k < 0 { -f64::from_bits((-k) as u64) } else { f64::from_bits(k as u64) } };
        let exact = exact_f64;
        // the number's side of the f64 with key k: Greater when above it
        let sign_lo = self.sign_at_lo();
        let side = |k: i64| -> Option<Ordering> { Some(self.position_given(&exact(from_key(k))?, sign_lo)) };
        let k0 = key(start);
        let first = side(k0)?;
        if first == Ordering::Equal {
            return None;
        }
        let dir: i64 = if first == Ordering::Greater { 1 } else { -1 };
        // gallop: k0 on the number's near side, k1 past it
        let (mut near, mut step) = (k0, 1i64);
        let mut far = loop {
            let k = near.checked_add(dir * step)?;
            match side(k)? {
                Ordering::Equal => return None,
                o if o == first => {
                    near = k;
                    step = step.checked_mul(2)?;
                }
                _ => break k,
            }
        };
        while (far - near).abs() > 1 {
            let mid = near + (far - near) / 2;
            match side(mid)? {
                Ordering::Equal => return None,
                o if o == first => near = mid,
                _ => far = mid,
            }
        }
        let (below, above) = if dir == 1 { (near, far) } else { (far, near) };
        let (fb, fa) = (from_key(below), from_key(above));
        if !fb.is_finite()
            || !fa.is_finite()
            || fb == 0.0
            || fa == 0.0
            || fb.is_sign_negative() != fa.is_sign_negative()
        {
            return None;
        }
        let (eb, ea) = (exact(fb)?, exact(fa)?);
        let mid = {
            let (mb, ma, k) = aligned(&eb, &ea)?;
            dyadic(mb + ma, k + 1)
        };
        let (f, a, b) = match self.position_given(&mid, sign_lo) {
            Ordering::Equal => return None,
            Ordering::Less => (fb, eb, mid),
            Ordering::Greater => (fa, mid, ea),
        };
        let Repr::Root { lo, hi, .. } = &mut self.0 else { return None };
        if a > *lo {
            *lo = a;
        }
        if b < *hi {
            *hi = b;
        }
        Some(f)
    }

    /// A copy narrowed to half an `f64` spacing (when the fast route applies; otherwise
    /// unchanged), with the number correctly rounded to `f64`: both at the cost of one
    /// [`Self::to_f64`]. The copy is the same number; its tight interval makes enclosures of
    /// functions of it tight.
    pub fn narrowed_with_f64(&self) -> (RealAlgebraic, f64) {
        let mut x = self.clone();
        if let Some(f) = x.narrow_by_newton() {
            return (x, f);
        }
        match x.narrow_to_f64_cell() {
            Some(f) => (x, f),
            None => (x, self.to_f64_by_bisection()),
        }
    }

    /// A copy whose interval is narrower than `2^−bits` relative to the number (Newton steps
    /// proved by exact signs; a rational is returned as it is, and a number outside the fast
    /// route's reach as narrow as it got). Functions of the copy enclose tightly: narrow once,
    /// then take several images (as [`Self::map_rational_to_f64`] does) at the price of one.
    pub fn narrowed(&self, bits: u64) -> RealAlgebraic {
        let mut x = self.clone();
        x.refine_newton(bits);
        x
    }
}

/// An `f64` near the root of `p` in `(lo, hi)`, where `p` changes sign: Newton's method kept
/// inside a bracket that `f64` signs shrink (bisection when a step leaves it). Only a
/// candidate: the exact test of [`RealAlgebraic::narrow_to_f64_cell`] decides. `None` when the
/// coefficients do not fit `f64` or the bracket is not finite.
pub(super) fn f64_root_candidate(p: &[BigInt], lo: f64, hi: f64) -> Option<f64> {
    use num_traits::ToPrimitive;
    if !(lo.is_finite() && hi.is_finite() && lo <= hi) {
        return None;
    }
    if lo == hi {
        return Some(lo); // an interval within one f64 spacing
    }
    // scaled so that the largest coefficient is near 1 (signs and roots unchanged)
    let bits = p.iter().map(BigInt::bits).max().unwrap_or(0);
    let shift = bits.saturating_sub(60);
    let c: Vec<f64> = p.iter().map(|x| (x >> shift).to_f64().filter(|v| v.is_finite())).collect::<Option<_>>()?;
    let (c, d) = {
        let c = crate::poly::Poly::new(c);
        let d = c.derivative();
        (c, d)
    };
    let horner = |q: &crate::poly::Poly<f64>, x: f64| q.eval(&x);
    let (mut a, mut b) = (lo, hi);
    let sa = horner(&c, a).signum();
    let mut x = a + (b - a) / 2.0;
    for _ in 0..100 {
        let fx = horner(&c, x);
        if fx == 0.0 {
            return Some(x);
        }
        if fx.signum() == sa {
            a = x;
        } else {
            b = x;
        }
        let dx = horner(&d, x);
        let newton = x - fx / dx;
        let next = if newton > a && newton < b { newton } else { a + (b - a) / 2.0 };
        if next == x || b <= a.next_up() {
            return Some(next);
        }
        x = next;
    }
    Some(x)
}

/// The rounding cell of the finite non-zero `f64` `u`: the numbers nearer to `u` than to its
/// neighbours, `[(u⁻ + u)/2, (u + u⁺)/2]`, exactly (`None` at the ends of the range).
pub(crate) fn f64_cell(u: f64) -> Option<(BigRational, BigRational)> {
    let (below, above) = (u.next_down(), u.next_up());
    if !(below.is_finite() && above.is_finite()) || u == 0.0 {
        return None;
    }
    if u.abs() < 1.0 && u.abs() >= f64::powi(2.0, -1000) {
        // |u| = m·2^e (e < 0, 2^52 ≤ m < 2^53): the neighbours are m ± 1 at the scale 2^e,
        // except below a power of two (m = 2^52), where the spacing halves; every end is an
        // odd multiple of a power of two, so the ratios are reduced
        let (m, e, sign) = num_traits::Float::integer_decode(u);
        let k = u64::from((-e) as u16);
        let end = |num: u64, k: u64| BigRational::new_raw(BigInt::from(num) * i64::from(sign), BigInt::from(1) << k);
        let (near, far) =
            (if m == 1 << 52 { end(4 * m - 1, k + 2) } else { end(2 * m - 1, k + 1) }, end(2 * m + 1, k + 1));
        return Some(if sign > 0 { (near, far) } else { (far, near) });
    }
    f64_cell_by_ratios(u)
}

/// [`f64_cell`] from the exact ratios of `u` and its neighbours.
fn f64_cell_by_ratios(u: f64) -> Option<(BigRational, BigRational)> {
    let (below, above) = (u.next_down(), u.next_up());
    if !(below.is_finite() && above.is_finite()) || u == 0.0 {
        return None;
    }
    let mid = |a: f64, b: f64| -> Option<BigRational> {
        let (ma, mb, k) = aligned(&exact_f64(a)?, &exact_f64(b)?)?;
        Some(dyadic(ma + mb, k + 1))
    };
    Some((mid(below, u)?, mid(u, above)?))
}

/// One Newton step for the integer polynomial `p` (derivative `dp`) from `c = cm/2^ck`: the
/// dyadic interval `x₁ ± ε` around `x₁ = c − p(c)/p′(c)`, with `ε` about `2^16` times the
/// square of the step (quadratic convergence). `None` where `p(c) = 0` or `p′(c) = 0`. Only a
/// proposal — the caller proves it by exact signs at its ends — so the step is divided from
/// the leading bits of `p(c)` and `p′(c)`, with an error far below `ε`.
fn newton_proposal(p: &[BigInt], dp: &[BigInt], cm: &BigInt, ck: u64) -> Option<(BigRational, BigRational)> {
    let pv = homogeneous_value(p, cm, ck); // 2^(ck·n) p(c)
    let dv = homogeneous_value(dp, cm, ck) << ck; // 2^(ck·n) p′(c)
    if dv.is_zero() || pv.is_zero() {
        return None;
    }
    // the step p(c)/p′(c) is about 2^−e; ε = 2^−r, on the grid 2^−kn
    let e = dv.bits() as i64 - pv.bits() as i64;
    let r = (2 * e - 16).max(ck as i64 + 1);
    let kn = (r + 8) as u64;
    let sh = dv.bits().saturating_sub((kn as i64 - e).max(0) as u64 + 64);
    let q = ((pv << kn) >> sh) / (dv >> sh);
    let x = (cm << (kn - ck)) - q;
    let unit = BigInt::from(256);
    Some((dyadic(&x - &unit, kn), dyadic(x + unit, kn)))
}

/// One exact Newton step `u − p(u)/p′(u)` for the integer polynomial `p` (derivative `dp`) from
/// the `f64` `u`, rounded to `f64`: near a simple root, `u` within `ε` of it gives a point within
/// about `ε²` (times `p″/p′`), so this is the root correctly rounded unless the root lies that
/// close to a rounding boundary. Only a proposal (the caller proves what it uses). `None` where
/// `p′(u) = 0` or `u` is not finite.
pub(crate) fn newton_step_f64(p: &[BigInt], dp: &[BigInt], u: f64) -> Option<f64> {
    let c = exact_f64(u)?;
    let (m, k) = dyadic_parts(&c)?;
    // p(u) = P/2^(kn), p′(u) = D/2^(k(n−1)): u − p(u)/p′(u) = (m·D − P)/(D·2^k)
    let n = p.len().checked_sub(1)?;
    let (pv, dv) = (homogeneous_value(p, m, k), homogeneous_value(dp, m, k));
    // dp has formal degree n − 1 when dp.len() = n
    if dv.is_zero() || dp.len() != n {
        return None;
    }
    let (num, den) = (m * &dv - pv, dv << k);
    let (num, den) = if den.is_negative() { (-num, -den) } else { (num, den) };
    Some(ratio_to_f64(&BigRational::new_raw(num, den)))
}

impl RealAlgebraic {
    /// Narrows the interval below `2^−bits` relative to the number's magnitude: Newton steps
    /// in exact dyadic arithmetic from the `f64` cell ([`Self::narrow_to_f64_cell`]), each
    /// proposing an interval about the square of the current width that the exact signs at its
    /// ends prove (or four bisections when they do not), so precision roughly doubles per step.
    /// Returns `false` (the number unchanged or partly narrowed) when the number is rational, its
    /// `f64` cell is unavailable, or an end is not dyadic.
    pub(super) fn refine_newton(&mut self, bits: u64) -> bool {
        let Repr::Root { lo, hi, .. } = &self.0 else { return false };
        let (flo, fhi) = (ratio_to_f64(lo), ratio_to_f64(hi));
        // the magnitude, for the target: the ends' when they are a few f64s apart (an f64
        // rounding cell, say; the smaller end's, so the target is no coarser), else found by
        // narrowing to a cell first (Newton from a wide interval's midpoint may not converge)
        let close = flo != 0.0 && flo.is_sign_negative() == fhi.is_sign_negative() && fhi <= flo.next_up().next_up();
        let f = if close {
            if flo.abs() < fhi.abs() { flo } else { fhi }
        } else {
            self.narrow_to_f64_cell().unwrap_or(0.0)
        };
        if f == 0.0 || !f.is_finite() {
            return false;
        }
        // the target: width below 2^target
        let target = f.abs().log2().floor() as i64 - bits as i64;
        let mut sign_lo = None;
        for _ in 0..64 {
            let Repr::Root { poly, lo, hi } = &self.0 else { return false };
            let Some((ml, mh, k)) = aligned(lo, hi) else { return false };
            // the width m_w / 2^k and its binary order, −log₂ w ≈ k − bits(m_w)
            let wbits = k as i64 - (&mh - &ml).bits() as i64;
            if wbits > -target {
                return true;
            }
            // Newton from the midpoint (ml + mh) / 2^(k+1)
            let dp = derivative_integer(poly);
            let proposed = newton_proposal(poly, &dp, &(&ml + &mh), k + 1).map(|(a, b)| (qmax(a, lo), qmin(b, hi)));
            let sign_lo = *sign_lo.get_or_insert_with(|| self.sign_at_lo());
            let proved = proposed.filter(|(a, b)| {
                self.position_given(a, sign_lo) == Ordering::Greater
                    && self.position_given(b, sign_lo) == Ordering::Less
            });
            match proved {
                Some((a, b)) => {
                    let Repr::Root { lo, hi, .. } = &mut self.0 else { return false };
                    *lo = a;
                    *hi = b;
                }
                None => {
                    for _ in 0..4 {
                        self.bisect();
                    }
                }
            }
        }
        true
    }

    /// For an irrational number: narrows the interval by one Newton step from an `f64`
    /// candidate ([`f64_root_candidate`], [`newton_proposal`]) to about the square of an `f64`
    /// spacing, proved by the exact signs at its ends, and returns the `f64` both ends round
    /// to. `None` (number unchanged) when the step is not proved or its interval straddles a
    /// rounding boundary; [`Self::narrow_to_f64_cell`] then decides.
    fn narrow_by_newton(&mut self) -> Option<f64> {
        let Repr::Root { poly, lo, hi } = &self.0 else { return None };
        let f = f64_root_candidate(poly, ratio_to_f64(lo), ratio_to_f64(hi))?;
        if f == 0.0 {
            return None;
        }
        let c = exact_f64(f)?;
        let (cm, ck) = dyadic_parts(&c)?;
        let dp = derivative_integer(poly);
        let (a, b) = newton_proposal(poly, &dp, cm, ck)?;
        let (a, b) = (qmax(a, lo), qmin(b, hi));
        let rounded = ratio_to_f64(&a);
        if rounded != ratio_to_f64(&b) || rounded == 0.0 || !rounded.is_finite() {
            return None;
        }
        let sign_lo = self.sign_at_lo();
        if self.position_given(&a, sign_lo) != Ordering::Greater || self.position_given(&b, sign_lo) != Ordering::Less {
            return None;
        }
        let Repr::Root { lo, hi, .. } = &mut self.0 else { return None };
        *lo = a;
        *hi = b;
        Some(rounded)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::scalar::rat;

    /// The rounding cells from the float's parts against those from exact ratios: powers of
    /// two (where the spacing below halves), their neighbours, random floats of both signs.
    #[test]
    fn f64_cells_from_parts_match_exact_ratios() {
        let mut word = crate::num::xorshift(0x00CE_11CE_11CE_11CE);
        let mut floats: Vec<f64> = (1..60).map(|k| f64::powi(2.0, -k)).collect();
        floats.extend(floats.clone().iter().flat_map(|&u| [u.next_up(), u.next_down()]));
        floats.extend((0..500).map(|_| f64::from_bits(word() % 0x3FF0_0000_0000_0000)));
        floats.extend([f64::powi(2.0, -1000), f64::powi(2.0, -1000).next_down(), 1e-310, 0.75, 0.999]);
        for u in floats.iter().flat_map(|&u| [u, -u]) {
            assert_eq!(f64_cell(u), f64_cell_by_ratios(u), "{u:e}");
        }
    }

    /// The fast `to_f64` (Newton candidate, exact cell test) against bisection alone, on every
    /// real root of random integer polynomials of degree 2 to 9 (wide and clustered roots).
    #[test]
    fn to_f64_cell_proof_matches_bisection() {
        let mut next = crate::num::symmetric(0x2545_F491_4F6C_DD1D);
        let (mut checked, mut fast, mut newton, mut irrational) = (0, 0, 0, 0);
        for round in 0..120 {
            let n = 2 + round % 8;
            let m = [3, 1000, 1 << 40][round % 3];
            let p: Vec<BigRational> = (0..=n).map(|_| rat(next(m))).collect();
            if p[n] == rat(0) {
                continue;
            }
            for r in RealAlgebraic::real_roots(&crate::poly::Poly::new(p.clone())) {
                assert_eq!(r.to_f64().to_bits(), r.to_f64_by_bisection().to_bits(), "{r}");
                let (narrow, f) = r.narrowed_with_f64();
                assert_eq!((narrow == r, f.to_bits()), (true, r.to_f64().to_bits()), "{r}");
                checked += 1;
                fast += usize::from(r.clone().narrow_to_f64_cell().is_some());
                newton += usize::from(r.clone().narrow_by_newton().is_some());
                irrational += usize::from(r.to_rational().is_none());
            }
        }
        assert!(checked > 100 && fast == irrational, "{checked} roots, {fast} of {irrational} by the cell proof");
        assert!(10 * newton >= 9 * irrational, "{newton} of {irrational} by one Newton step");
    }
}
