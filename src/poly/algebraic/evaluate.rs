//! Integer polynomials at rational points and on rational intervals: the exact sign and value
//! at a rational (homogeneous Horner, one division at most), the power form on a subinterval
//! `[lo, hi]`, and the real roots in a closed interval (isolation by the Bernstein route of
//! [`crate::poly::roots`]).

use super::dyadic::{aligned, dyadic_parts, homogeneous_value};
use crate::num::scalar::rat;
use crate::poly::roots::Root;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::cmp::Ordering;

/// The sign of `p(r)` for an integer polynomial (lowest degree first): the sign of
/// `Σ c_i a^i b^(n−i)` for `r = a/b`, `b > 0`.
pub fn sign_at(p: &[BigInt], r: &BigRational) -> Ordering {
    if p.is_empty() {
        return Ordering::Equal;
    }
    let (a, b) = (r.numer(), r.denom());
    let n = p.len() - 1;
    if let Some((m, k)) = dyadic_parts(r) {
        // b = 2^k: the powers of b are shifts
        return homogeneous_value(p, m, k).sign().into_ordering();
    }
    // Horner in homogeneous form: acc = acc·a + c_i·b^(n−i)
    let mut acc = p[n].clone();
    let mut bpow = BigInt::one();
    for i in (0..n).rev() {
        bpow *= b;
        acc = acc * a + &p[i] * &bpow;
    }
    acc.sign().into_ordering()
}

trait IntoOrdering {
    fn into_ordering(self) -> Ordering;
}

impl IntoOrdering for num_bigint::Sign {
    fn into_ordering(self) -> Ordering {
        match self {
            num_bigint::Sign::Minus => Ordering::Less,
            num_bigint::Sign::NoSign => Ordering::Equal,
            num_bigint::Sign::Plus => Ordering::Greater,
        }
    }
}

/// A positive multiple of the power-form coefficients of `c(lo + (hi − lo)·u)` (`c` integer,
/// `lo < hi`), on integers: with `lo = L/D` and `hi − lo = V/D`, `D^n·c(lo + (hi − lo)u)` by
/// homogeneous Horner.
pub(super) fn shifted_integer(c: &[BigInt], lo: &BigRational, hi: &BigRational) -> Vec<BigInt> {
    if num_traits::Zero::is_zero(lo) && num_traits::One::is_one(hi) {
        return c.to_vec();
    }
    let n = c.len() - 1;
    let (d, l, v) = match aligned(lo, hi) {
        // dyadic ends (the usual case): D = 2^k, no gcd
        Some((l, h, k)) => {
            let v = &h - &l;
            (BigInt::one() << k, l, v)
        }
        None => {
            let w = hi.clone() - lo;
            let d = num_integer::Integer::lcm(lo.denom(), w.denom());
            let l = lo.numer() * (&d / lo.denom());
            let v = w.numer() * (&d / w.denom());
            (d, l, v)
        }
    };
    let mut dpow = vec![BigInt::one()];
    for _ in 0..n {
        let last = dpow[dpow.len() - 1].clone();
        dpow.push(last * &d);
    }
    let mut q: Vec<BigInt> = vec![];
    for k in (0..=n).rev() {
        // q ← q·(l + v s) + c_k·D^(n−k)
        let mut next = vec![BigInt::zero(); q.len() + 1];
        for (i, a) in q.iter().enumerate() {
            next[i] += a * &l;
            next[i + 1] += a * &v;
        }
        next[0] += &c[k] * &dpow[n - k];
        q = next;
    }
    q.truncate(n + 1);
    q
}

/// The real roots of the square-free integer polynomial `p` (power form) in the closed interval
/// `[lo, hi]`, ascending, as exact rationals or isolating open intervals.
pub(super) fn isolate_power(p: &[BigInt], lo: &BigRational, hi: &BigRational) -> Vec<Root> {
    let q = shifted_integer(p, lo, hi);
    let b = crate::poly::roots::power_to_bernstein_integer(&q);
    let map = |s: BigRational| lo.clone() + (hi.clone() - lo) * s;
    crate::poly::roots::isolate_square_free(b)
        .into_iter()
        .map(|r| match r {
            Root::Exact(s) => Root::Exact(map(s)),
            Root::Isolated(a, b) => Root::Isolated(map(a), map(b)),
        })
        .collect()
}

/// `p(r)` exactly, for an integer polynomial (homogeneous Horner, one division at the end).
pub(crate) fn value_at(p: &[BigInt], r: &BigRational) -> BigRational {
    let Some(n) = p.len().checked_sub(1) else { return rat(0) };
    let (a, b) = (r.numer(), r.denom());
    let mut acc = p[n].clone();
    let mut bpow = BigInt::one();
    for c in p[..n].iter().rev() {
        bpow *= b;
        acc = acc * a + c * &bpow;
    }
    BigRational::new(acc, bpow)
}
