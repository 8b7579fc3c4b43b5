//! Exact dyadic rationals `m/2^k`, the form of every interval end that bisection and `f64`s
//! produce: their parts, two of them over one power of two, comparison by a shift, `f64`s as
//! exact ratios, and integer polynomials evaluated at a dyadic without a division. Hand-written
//! because `Ratio`'s own comparison and construction divide and take gcds, which cost more than
//! shifts on these sizes.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;
use std::cmp::Ordering;

/// `(m, k)` with `r = m / 2^k`, when the denominator of `r` is a power of two.
pub(super) fn dyadic_parts(r: &BigRational) -> Option<(&BigInt, u64)> {
    let d = r.denom();
    let k = d.bits() - 1;
    (d.trailing_zeros() == Some(k)).then_some((r.numer(), k))
}

/// Two dyadic numbers over one power of two: `(m_a, m_b, k)` with `a = m_a/2^k`,
/// `b = m_b/2^k`; `None` unless both are dyadic.
pub(super) fn aligned(a: &BigRational, b: &BigRational) -> Option<(BigInt, BigInt, u64)> {
    let ((ma, ka), (mb, kb)) = (dyadic_parts(a)?, dyadic_parts(b)?);
    let k = ka.max(kb);
    Some((ma << (k - ka), mb << (k - kb), k))
}

/// `a` against `b`, exactly: by a shift when both are dyadic (the usual case here), else by
/// cross-multiplication — `Ratio`'s own comparison divides, which costs more on these sizes.
pub(super) fn qcmp(a: &BigRational, b: &BigRational) -> Ordering {
    if let Some((ma, mb, _)) = aligned(a, b) {
        return ma.cmp(&mb);
    }
    (a.numer() * b.denom()).cmp(&(b.numer() * a.denom()))
}

/// The larger of `a` and `b` ([`qcmp`]).
pub(super) fn qmax(a: BigRational, b: &BigRational) -> BigRational {
    if qcmp(&a, b) == Ordering::Less { b.clone() } else { a }
}

/// The smaller of `a` and `b` ([`qcmp`]).
pub(super) fn qmin(a: BigRational, b: &BigRational) -> BigRational {
    if qcmp(&a, b) == Ordering::Greater { b.clone() } else { a }
}

/// A finite positive `f64` as `m·2^e` (`m` an integer).
pub(super) fn dyadic_parts_f64(x: f64) -> (u64, i64) {
    let (m, e, _) = num_traits::Float::integer_decode(x);
    (m, i64::from(e))
}

/// `m / 2^k` as a reduced ratio, by trailing zeros (no gcd): the one root isolation uses.
pub(super) use crate::poly::roots::dyadic;

/// A finite `f64` as an exact reduced ratio, without a gcd (its denominator is a power of two).
pub(super) fn exact_f64(f: f64) -> Option<BigRational> {
    if !f.is_finite() {
        return None;
    }
    let (mantissa, exponent, sign) = num_traits::Float::integer_decode(f);
    let m = BigInt::from(mantissa) * i64::from(sign);
    Some(if exponent >= 0 {
        BigRational::from_integer(m << exponent as u64)
    } else {
        dyadic(m, u64::from(exponent.unsigned_abs()))
    })
}

/// `2^(k·n)·p(m/2^k)` for an integer polynomial of formal degree `n = p.len() − 1`.
pub(super) fn homogeneous_value(p: &[BigInt], m: &BigInt, k: u64) -> BigInt {
    let Some(n) = p.len().checked_sub(1) else { return BigInt::zero() };
    let mut acc = p[n].clone();
    for i in (0..n).rev() {
        acc = acc * m + (&p[i] << (k * (n - i) as u64));
    }
    acc
}
