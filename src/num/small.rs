//! Fixed-width exact rationals: [`SmallRational`], an `i128` ratio whose arithmetic either is
//! exact or reports that it overflowed — never a wrong number.
//!
//! The classification of a font's cubic needs a few dozen rational operations on numbers of
//! 40–110 bits. As [`BigRational`] each costs an allocation and a gcd (num-bigint's gcd is the
//! bit-by-bit Stein algorithm): ~250 µs per curve. In `i128`, with integers kept unreduced
//! (denominator 1 needs no gcd) and a word-sized binary gcd otherwise, the same work takes
//! about a microsecond. No crate offers a checked fixed-width rational with these semantics
//! (`num_rational::Ratio<i128>` panics on overflow), hence this module.
//!
//! # Exactness contract
//! Every operation is exact or *poisons the thread*: an operation whose result does not fit
//! `i128` sets a thread-local overflow flag and returns an arbitrary value. Run a computation
//! inside [`checked`]: it returns `None` when anything overflowed (then redo it with
//! [`BigRational`]), and otherwise the computation's exact result. Values are reduced with a
//! positive denominator, so `==` is numeric equality and `Display` spells a number exactly as
//! [`BigRational`] does (`-7/6`, `3`).
//!
//! # Example
//! ```
//! use casteljau::num::small::{SmallRational, checked};
//! use casteljau::{Scalar, ratio};
//! let x = checked(|| SmallRational::from_i64(1) / SmallRational::from_i64(3) + SmallRational::from_i64(1) / SmallRational::from_i64(6));
//! assert_eq!(x.unwrap().to_string(), "1/2");
//! let big = SmallRational::from_i64(i64::MAX);
//! assert!(checked(|| big * big * big).is_none()); // 2^189 does not fit: refused, not wrapped
//! assert_eq!(SmallRational::from_i64(5).to_big(), ratio(5, 1));
//! ```

use crate::num::quadratic_field::{QuadraticExt, Radical};
use crate::num::scalar::{Exact, Scalar, ratio_to_f64};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::ToPrimitive;
use std::cell::Cell;
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

thread_local! {
    static OVERFLOW: Cell<bool> = const { Cell::new(false) };
}

fn poison() -> SmallRational {
    OVERFLOW.with(|f| f.set(true));
    SmallRational::ZERO
}

fn poisoned() -> bool {
    OVERFLOW.with(Cell::get)
}

/// Runs `f` and returns its result, or `None` if any [`SmallRational`] operation in it overflowed.
///
/// Nested calls are independent: an overflow inside an inner call does not fail the outer one.
pub fn checked<T>(f: impl FnOnce() -> T) -> Option<T> {
    let outer = OVERFLOW.with(|c| c.replace(false));
    let value = f();
    let failed = OVERFLOW.with(|c| c.replace(outer));
    (!failed).then_some(value)
}

/// An exact rational `num/den` in `i128` (reduced, `den > 0`); see the module's exactness
/// contract.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SmallRational {
    num: i128,
    den: i128,
}

/// `gcd(a, b)` of non-negative numbers (binary; word-sized when both fit 64 bits).
pub(crate) fn gcd_u128(a: u128, b: u128) -> u128 {
    gcd(a, b)
}

/// `gcd(|a|, |b|)`: one big remainder and word gcds when either fits 128 bits (the common case
/// for contents of polynomials), num-bigint's binary gcd otherwise.
pub(crate) fn gcd_big(a: &num_bigint::BigInt, b: &num_bigint::BigInt) -> num_bigint::BigInt {
    use num_bigint::{BigInt, BigUint};
    use num_traits::ToPrimitive;
    let rem = |x: &BigUint, w: u128| -> u128 {
        if w >> 64 == 0 { u128::from(rem_u64(x, w as u64)) } else { (x % w).to_u128().expect("below a u128") }
    };
    let (ma, mb) = (a.magnitude(), b.magnitude());
    let small = |w: u128, other: &BigUint| -> BigInt {
        if w == 0 { BigInt::from(other.clone()) } else { BigInt::from(gcd(w, rem(other, w))) }
    };
    match (ma.to_u128(), mb.to_u128()) {
        (Some(w), _) => small(w, mb),
        (None, Some(w)) => small(w, ma),
        (None, None) => num_integer::Integer::gcd(a, b),
    }
}

/// `gcd(a, b)` of non-negative numbers (binary; word-sized when both fit 64 bits).
fn gcd(a: u128, b: u128) -> u128 {
    if a == 0 || b == 0 {
        return a | b;
    }
    if a == 1 || b == 1 {
        return 1;
    }
    if a >> 64 == 0 && b >> 64 == 0 {
        return gcd64(a as u64, b as u64) as u128;
    }
    // one word-sized argument: one remainder brings the other down to a word
    if a >> 64 == 0 || b >> 64 == 0 {
        let (big, word) = if a >> 64 == 0 { (b, a as u64) } else { (a, b as u64) };
        return gcd64(word, (big % word as u128) as u64) as u128;
    }
    let shift = (a | b).trailing_zeros();
    let (mut a, mut b) = (a >> a.trailing_zeros(), b);
    loop {
        b >>= b.trailing_zeros();
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        b -= a;
        if b == 0 {
            return a << shift;
        }
        if b >> 64 == 0 && a >> 64 == 0 {
            return (gcd64(a as u64, b as u64) as u128) << shift;
        }
    }
}

fn gcd64(a: u64, b: u64) -> u64 {
    if a == 0 || b == 0 {
        return a | b;
    }
    let shift = (a | b).trailing_zeros();
    let (mut a, mut b) = (a >> a.trailing_zeros(), b >> b.trailing_zeros());
    // both odd; min/max instead of a branch on the comparison (which mispredicts half the time)
    while a != b {
        let (lo, hi) = (a.min(b), a.max(b));
        let diff = hi - lo;
        a = lo;
        b = diff >> diff.trailing_zeros();
    }
    a << shift
}

impl SmallRational {
    const ZERO: SmallRational = SmallRational { num: 0, den: 1 };

    /// The integer `n`.
    pub const fn integer(n: i128) -> Self {
        SmallRational { num: n, den: 1 }
    }

    /// `num/den` reduced, or `None` when `den == 0` or the reduced form does not fit
    /// (`den = i128::MIN`).
    pub fn new(num: i128, den: i128) -> Option<Self> {
        if den == 0 {
            return None;
        }
        let g = gcd(num.unsigned_abs(), den.unsigned_abs()) as i128;
        let (mut n, mut d) = (num / g, den / g);
        if d < 0 {
            n = n.checked_neg()?;
            d = d.checked_neg()?;
        }
        Some(SmallRational { num: n, den: d })
    }

    /// Reduces `num/den` (`den > 0`), poisoning on nothing: both already fit.
    fn reduced(num: i128, den: i128) -> Self {
        if den == 1 {
            return SmallRational { num, den };
        }
        let g = gcd(num.unsigned_abs(), den as u128) as i128;
        SmallRational { num: num / g, den: den / g }
    }

    /// The numerator (sign of the number).
    pub fn numer(&self) -> i128 {
        self.num
    }
    /// The denominator (positive).
    pub fn denom(&self) -> i128 {
        self.den
    }

    /// The same number as a [`BigRational`] (no gcd: already reduced).
    pub fn to_big(&self) -> BigRational {
        BigRational::new_raw(BigInt::from(self.num), BigInt::from(self.den))
    }

    /// The number, when a [`BigRational`] fits; `None` otherwise (no poisoning).
    pub fn from_big(r: &BigRational) -> Option<Self> {
        Some(SmallRational { num: r.numer().to_i128()?, den: r.denom().to_i128()? })
    }
}

impl SmallRational {
    /// Appends the number as [`Display`](fmt::Display) spells it (`n` or `n/d`), without the
    /// formatting machinery: the hot path of batch output.
    ///
    /// # Example
    /// ```
    /// use casteljau::num::small::SmallRational;
    /// let mut out = b"x = ".to_vec();
    /// SmallRational::new(-6, 4).unwrap().push_to(&mut out);
    /// assert_eq!(out, b"x = -3/2");
    /// ```
    pub fn push_to(&self, out: &mut Vec<u8>) {
        let mut buf = itoa::Buffer::new();
        out.extend_from_slice(
            match i64::try_from(self.num) {
                Ok(n) => buf.format(n),
                Err(_) => buf.format(self.num),
            }
            .as_bytes(),
        );
        if self.den != 1 {
            out.push(b'/');
            out.extend_from_slice(
                match u64::try_from(self.den) {
                    Ok(d) => buf.format(d),
                    Err(_) => buf.format(self.den),
                }
                .as_bytes(),
            );
        }
    }
}

impl fmt::Display for SmallRational {
    /// As [`BigRational`]: `n` or `n/d`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // word-sized numbers format without 128-bit divisions
        let mut buf = itoa::Buffer::new();
        f.write_str(match i64::try_from(self.num) {
            Ok(n) => buf.format(n),
            Err(_) => buf.format(self.num),
        })?;
        if self.den != 1 {
            f.write_str("/")?;
            f.write_str(match u64::try_from(self.den) {
                Ok(d) => buf.format(d),
                Err(_) => buf.format(self.den),
            })?;
        }
        Ok(())
    }
}

/// `√n` when `n` is a perfect square: residues mod 64 and 63 reject most non-squares at once,
/// then a float estimate with one Newton step and an exact ±1 correction.
fn square_root(n: u128) -> Option<u128> {
    const SQ64: u64 = {
        let mut m = 0u64;
        let mut i = 0;
        while i < 64 {
            m |= 1 << ((i * i) % 64);
            i += 1;
        }
        m
    };
    const SQ63: u64 = {
        let mut m = 0u64;
        let mut i = 0;
        while i < 63 {
            m |= 1 << ((i * i) % 63);
            i += 1;
        }
        m
    };
    if SQ64 >> (n % 64) & 1 == 0 || SQ63 >> (n % 63) & 1 == 0 {
        return None;
    }
    let r = isqrt(n);
    (r * r == n).then_some(r)
}

/// `⌊√n⌋`.
fn isqrt(n: u128) -> u128 {
    if n < 2 {
        return n;
    }
    let mut r = (n as f64).sqrt() as u128;
    if n >> 100 != 0 {
        r = (r + n / r) / 2; // the float estimate is off by up to ~2^12 here
    }
    while r.checked_mul(r).is_none_or(|s| s > n) {
        r -= 1;
    }
    while (r + 1).checked_mul(r + 1).is_some_and(|s| s <= n) {
        r += 1;
    }
    r
}

impl Scalar for SmallRational {
    fn zero() -> Self {
        SmallRational::ZERO
    }
    fn one() -> Self {
        SmallRational::integer(1)
    }
    fn from_i64(n: i64) -> Self {
        SmallRational::integer(n as i128)
    }
    /// The ratio, or a poisoned value when it does not fit.
    fn from_ratio(r: &BigRational) -> Self {
        SmallRational::from_big(r).unwrap_or_else(poison)
    }
    fn is_zero(&self) -> bool {
        self.num == 0
    }
    /// Correctly rounded, as [`ratio_to_f64`].
    fn to_f64(&self) -> f64 {
        const EXACT: u128 = 1 << 53;
        if self.num.unsigned_abs() <= EXACT && (self.den as u128) <= EXACT {
            // both operands exact: one IEEE division, correctly rounded
            self.num as f64 / self.den as f64
        } else {
            ratio_to_f64(&self.to_big())
        }
    }
}

impl Exact for SmallRational {
    const ATOMIC_DISPLAY: bool = true;
    fn to_ratio(&self) -> Option<BigRational> {
        Some(self.to_big())
    }
    fn sign(&self) -> Ordering {
        self.num.cmp(&0)
    }
    fn exact_sqrt(&self) -> Option<Self> {
        if self.num < 0 {
            return None;
        }
        let rn = square_root(self.num as u128)?;
        let rd = square_root(self.den as u128)?;
        Some(SmallRational { num: rn as i128, den: rd as i128 })
    }
}

impl Neg for SmallRational {
    type Output = Self;
    fn neg(self) -> Self {
        match self.num.checked_neg() {
            Some(num) => SmallRational { num, den: self.den },
            None => poison(),
        }
    }
}

impl Add<&SmallRational> for SmallRational {
    type Output = Self;
    fn add(self, o: &Self) -> Self {
        add(self, *o).unwrap_or_else(poison)
    }
}

impl Sub<&SmallRational> for SmallRational {
    type Output = Self;
    fn sub(self, o: &Self) -> Self {
        match o.num.checked_neg() {
            Some(num) => add(self, SmallRational { num, den: o.den }).unwrap_or_else(poison),
            None => poison(),
        }
    }
}

impl Mul<&SmallRational> for SmallRational {
    type Output = Self;
    fn mul(self, o: &Self) -> Self {
        mul(self, *o).unwrap_or_else(poison)
    }
}

impl Div<&SmallRational> for SmallRational {
    type Output = Self;
    /// # Panics
    /// **Panics on division by zero**, unless the thread is already poisoned (the divisor is then
    /// an arbitrary value and the result is discarded by [`checked`]).
    fn div(self, o: &Self) -> Self {
        if o.num == 0 {
            assert!(poisoned(), "SmallRational: division by zero");
            return SmallRational::ZERO;
        }
        let (num, den) =
            if o.num < 0 { (o.den.checked_neg(), o.num.checked_neg()) } else { (Some(o.den), Some(o.num)) };
        match (num, den) {
            (Some(num), Some(den)) => mul(self, SmallRational { num, den }).unwrap_or_else(poison),
            _ => poison(),
        }
    }
}

fn add(a: SmallRational, b: SmallRational) -> Option<SmallRational> {
    if a.den == b.den {
        return Some(SmallRational::reduced(a.num.checked_add(b.num)?, a.den));
    }
    // a fraction plus an integer stays reduced: gcd(p + kq, q) = gcd(p, q) = 1
    if b.den == 1 {
        return Some(SmallRational { num: a.num.checked_add(b.num.checked_mul(a.den)?)?, den: a.den });
    }
    if a.den == 1 {
        return Some(SmallRational { num: b.num.checked_add(a.num.checked_mul(b.den)?)?, den: b.den });
    }
    let g = gcd(a.den as u128, b.den as u128) as i128;
    let (ad, bd) = (a.den / g, b.den / g);
    let num = a.num.checked_mul(bd)?.checked_add(b.num.checked_mul(ad)?)?;
    // gcd(num, ad·b.den) = gcd(num, g) · (nothing from ad, bd): reduce by the common part with g
    let h = gcd(num.unsigned_abs(), g as u128) as i128;
    let den = (g / h).checked_mul(ad)?.checked_mul(bd)?;
    Some(SmallRational { num: num / h, den })
}

fn mul(a: SmallRational, b: SmallRational) -> Option<SmallRational> {
    if a.den == 1 && b.den == 1 {
        return Some(SmallRational::integer(a.num.checked_mul(b.num)?));
    }
    let g1 = gcd(a.num.unsigned_abs(), b.den as u128) as i128;
    let g2 = gcd(b.num.unsigned_abs(), a.den as u128) as i128;
    if g1 == 0 || g2 == 0 {
        return Some(SmallRational::ZERO);
    }
    let num = (a.num / g1).checked_mul(b.num / g2)?;
    let den = (a.den / g2).checked_mul(b.den / g1)?;
    Some(SmallRational { num, den })
}

macro_rules! by_value {
    ($($tr:ident $m:ident),*) => {$(
        impl $tr for SmallRational {
            type Output = Self;
            fn $m(self, o: Self) -> Self {
                <Self as $tr<&Self>>::$m(self, &o)
            }
        }
    )*};
}
by_value!(Add add, Sub sub, Mul mul, Div div);

/// Odd primes `p` below 1000 with `p²`, their inverses mod 2^128 and mod 2^64, and
/// `u128::MAX / p`, `u64::MAX / p`: `p | m` iff `m · p⁻¹ mod 2^w ≤ (2^w − 1) / p` (one
/// multiplication per prime, no division).
struct OddPrime {
    p: u128,
    inv: u128,
    limit: u128,
    inv64: u64,
    limit64: u64,
}

const ODD_PRIMES: [OddPrime; 167] = {
    let mut out = [const { OddPrime { p: 0, inv: 0, limit: 0, inv64: 0, limit64: 0 } }; 167];
    let mut n = 3u128;
    let mut k = 0;
    while k < 167 {
        let mut prime = true;
        let mut q = 3;
        while q * q <= n {
            if n.is_multiple_of(q) {
                prime = false;
                break;
            }
            q += 2;
        }
        if prime {
            // Newton's iteration doubles the correct low bits: 3 → 6 → … → 192 ≥ 128
            let mut inv = n;
            let mut i = 0;
            while i < 6 {
                inv = inv.wrapping_mul(2u128.wrapping_sub(n.wrapping_mul(inv)));
                i += 1;
            }
            out[k] = OddPrime { p: n, inv, limit: u128::MAX / n, inv64: inv as u64, limit64: u64::MAX / n as u64 };
            k += 1;
        }
        n += 2;
    }
    out
};

/// The odd primes below 1000 (as [`ODD_PRIMES`]) with their inverses mod 2^64 and
/// `u64::MAX / p`, packed for the word-sized loop of [`extract_small_squares`].
const ODD_PRIMES64: [(u64, u64, u64); 167] = {
    let mut out = [(0u64, 0u64, 0u64); 167];
    let mut k = 0;
    while k < 167 {
        out[k] = (ODD_PRIMES[k].p as u64, ODD_PRIMES[k].inv64, ODD_PRIMES[k].limit64);
        k += 1;
    }
    out
};

/// `(k, m)` with `n = k²·m` and `m` free of the squares of primes below 1000 — the
/// square extraction of [`QuadraticExt::sqrt`](crate::QuadraticExt) for `BigRational`, on words
/// (64-bit words once `n` fits one).
fn extract_small_squares(mut n: u128) -> (u128, u128) {
    let mut k = 1u128;
    if n == 0 {
        return (1, 0);
    }
    let twos = n.trailing_zeros();
    k <<= twos / 2;
    n >>= twos - twos % 2;
    let (k2, m) = extract_small_squares_from(n, 0);
    (k * k2, m)
}

/// The odd part of [`extract_small_squares`], from the `from`-th odd prime on.
fn extract_small_squares_from(mut n: u128, from: usize) -> (u128, u128) {
    let mut k = 1u128;
    for (j, op) in ODD_PRIMES.iter().enumerate().skip(from) {
        if n >> 64 == 0 {
            let (k64, m) = extract_small_squares64(n as u64, j);
            return (k * k64, m as u128);
        }
        loop {
            let q = n.wrapping_mul(op.inv);
            if q > op.limit {
                break;
            }
            // p | n; p² | n?
            let q2 = q.wrapping_mul(op.inv);
            if q2 > op.limit {
                break;
            }
            n = q2;
            k *= op.p;
        }
    }
    (k, n)
}

/// Products of consecutive odd primes below 1000, each below 2^63, with the index range of its
/// primes in [`ODD_PRIMES`]: one remainder of a big number per group, then word arithmetic.
const PRIME_GROUPS: ([(u64, usize, usize); 167], usize) = {
    let mut out = [(0u64, 0usize, 0usize); 167];
    let (mut g, mut k) = (0, 0);
    while k < 167 {
        let (mut prod, start) = (1u64, k);
        while k < 167 && (prod as u128) * ODD_PRIMES[k].p < 1 << 63 {
            prod *= ODD_PRIMES[k].p as u64;
            k += 1;
        }
        out[g] = (prod, start, k);
        g += 1;
    }
    (out, g)
};

/// `n mod m` for `m < 2^64`, from the 64-bit digits (most significant first), without allocating.
pub(crate) fn rem_u64(n: &num_bigint::BigUint, m: u64) -> u64 {
    n.iter_u64_digits().rev().fold(0u64, |r, d| ((u128::from(r) << 64 | u128::from(d)) % u128::from(m)) as u64)
}

/// `n mod m` in `[0, m)` for a signed `n` and `m < 2^64` ([`rem_u64`] of the magnitude, negated
/// modulo `m` for a negative `n`).
pub(crate) fn residue(n: &num_bigint::BigInt, m: u64) -> u64 {
    let r = rem_u64(n.magnitude(), m);
    if n.sign() == num_bigint::Sign::Minus && r != 0 { m - r } else { r }
}

/// [`extract_small_squares`] of a big number: `(k, m)` with `n = k²·m` and `m` free of the
/// squares of primes below 1000 (the rule of [`QuadraticExt::sqrt`](crate::QuadraticExt)).
/// Divisibility is read from one remainder per group of primes ([`PRIME_GROUPS`]), not one big
/// division per prime.
pub(crate) fn extract_small_squares_big(n: &num_bigint::BigUint) -> (num_bigint::BigUint, num_bigint::BigUint) {
    use num_bigint::BigUint;
    use num_traits::{ToPrimitive, Zero};
    if let Some(w) = n.to_u128() {
        let (k, m) = extract_small_squares(w);
        return (BigUint::from(k), BigUint::from(m));
    }
    let mut m = n.clone();
    let mut k = BigUint::from(1u32);
    if m.is_zero() {
        return (k, m);
    }
    let twos = m.trailing_zeros().unwrap_or(0);
    k <<= twos / 2;
    m >>= twos - twos % 2;
    let (groups, count) = PRIME_GROUPS;
    for &(prod, start, end) in &groups[..count] {
        let r = rem_u64(&m, prod);
        for op in &ODD_PRIMES[start..end] {
            let p = op.p as u64;
            if !r.is_multiple_of(p) {
                continue;
            }
            // p | m: divide out p² while it divides (m changes, so test on m itself)
            let square = BigUint::from(p * p);
            while rem_u64(&m, p * p) == 0 {
                m /= &square;
                k *= p;
            }
            if let Some(w) = m.to_u128() {
                // the rest fits a word: finish there, from the next prime on
                let next = ODD_PRIMES.iter().position(|o| o.p as u64 > p).unwrap_or(167);
                let (k2, m2) = extract_small_squares_from(w, next);
                return (k * BigUint::from(k2), BigUint::from(m2));
            }
        }
    }
    (k, m)
}

/// [`extract_small_squares`] of a word from the `from`-th odd prime on: one multiplication and
/// one comparison per prime while no prime divides `n` (the common case).
fn extract_small_squares64(mut n: u64, from: usize) -> (u128, u64) {
    let mut k = 1u128;
    for &(p, inv, limit) in &ODD_PRIMES64[from..] {
        let q = n.wrapping_mul(inv);
        if q <= limit {
            // p | n: divide out p² while it divides
            let mut q = q;
            loop {
                let q2 = q.wrapping_mul(inv);
                if q2 > limit {
                    break;
                }
                n = q2;
                k *= p as u128;
                q = n.wrapping_mul(inv);
                if q > limit {
                    break;
                }
            }
        }
    }
    (k, n)
}

/// The square root of a non-negative `d = p/q` in the spelling of
/// [`QuadraticExt::sqrt`](crate::QuadraticExt): rational when `d` is a square, else
/// `b·√m` with `m` the integer `p·q` freed of the squares of primes below 1000 and `b = k/q`.
/// Poisons when `m` does not fit.
fn sqrt_parts(d: SmallRational) -> (SmallRational, SmallRational) {
    assert!(d.num >= 0, "sqrt of a negative rational");
    if let Some(r) = d.exact_sqrt() {
        return (r, SmallRational::ZERO);
    }
    // p and q are coprime, so the squares of p·q are those of p times those of q.
    let (kp, mp) = extract_small_squares(d.num as u128);
    let (kq, mq) = extract_small_squares(d.den as u128);
    let Some(m) = mp.checked_mul(mq).filter(|&m| m <= i128::MAX as u128) else { return (poison(), poison()) };
    let Some(k) = kp.checked_mul(kq).filter(|&k| k <= i128::MAX as u128) else { return (poison(), poison()) };
    let b = SmallRational::integer(k as i128) / SmallRational::integer(d.den);
    if let Some(r) = square_root(m) {
        return (b * SmallRational::integer(r as i128), SmallRational::ZERO);
    }
    (b, SmallRational::integer(m as i128))
}

impl Radical for SmallRational {
    fn radical(d: &Self) -> QuadraticExt<Self> {
        let (b, m) = sqrt_parts(*d);
        if m.is_zero() { QuadraticExt::from_base(b) } else { QuadraticExt::new(SmallRational::ZERO, b, m) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::scalar::ratio;

    #[test]
    fn small_rational_matches_big_rational_on_mixed_operations() {
        let xs = [ratio(1, 3), ratio(-7, 12), ratio(5, 1), ratio(0, 1), ratio(-1, 1), ratio(1_000_003, 999_983)];
        for a in &xs {
            for b in &xs {
                let (sa, sb) = (SmallRational::from_big(a).unwrap(), SmallRational::from_big(b).unwrap());
                assert_eq!((sa + sb).to_big(), a + b);
                assert_eq!((sa - sb).to_big(), a - b);
                assert_eq!((sa * sb).to_big(), a * b);
                if !Scalar::is_zero(b) {
                    assert_eq!((sa / sb).to_big(), a / b);
                }
                assert_eq!((sa + sb).to_string(), (a + b).to_string());
            }
        }
    }

    #[test]
    fn small_rational_overflow_is_reported_not_wrapped() {
        let big = SmallRational::integer(i128::MAX);
        assert!(checked(|| big + SmallRational::integer(1)).is_none());
        assert!(checked(|| -SmallRational::integer(i128::MIN)).is_none());
        assert_eq!(checked(|| big - big), Some(SmallRational::ZERO));
        // an inner overflow does not leak into an outer computation
        assert!(checked(|| checked(|| big * big).is_none()).unwrap());
    }

    #[test]
    fn square_roots_of_words_are_exact() {
        for r in [0u128, 1, 2, 3, 1 << 20, (1 << 63) - 25, u64::MAX as u128] {
            assert_eq!(square_root(r * r), Some(r), "{r}");
            if r > 1 {
                assert_eq!(square_root(r * r - 1), None);
                assert_eq!(isqrt(r * r - 1), r - 1);
                assert_eq!(square_root(r * r + 1), None);
            }
        }
        assert_eq!(isqrt(u128::MAX), u64::MAX as u128);
    }

    #[test]
    fn small_squares_are_extracted_like_the_big_route() {
        for (n, k, m) in
            [(12u128, 2u128, 3u128), (2 * 997 * 997, 997, 2), (1009 * 1009 * 3, 1, 1009 * 1009 * 3), (1, 1, 1)]
        {
            assert_eq!(extract_small_squares(n), (k, m), "{n}");
        }
    }
}

#[cfg(test)]
mod big_square_tests {
    use super::*;
    use num_bigint::BigUint;
    use num_traits::{One, Zero};

    /// The rule as first written: divide out k² for every k from 2 to 999.
    fn naive(n: &BigUint) -> (BigUint, BigUint) {
        let (mut k, mut m) = (BigUint::one(), n.clone());
        if m.is_zero() {
            return (k, m);
        }
        for j in 2u32..1000 {
            let jj = BigUint::from(j * j);
            while (&m % &jj).is_zero() {
                m /= &jj;
                k *= j;
            }
        }
        (k, m)
    }

    #[test]
    fn big_square_extraction_equals_the_naive_rule() {
        let mut next = crate::num::xorshift(0x2545_F491_4F6C_DD1D);
        for _ in 0..300 {
            // products of small primes (some squared), a large prime-ish part, powers of two
            let mut n = BigUint::from(next() | 1) * BigUint::from(next());
            for _ in 0..(next() % 6) {
                let p = [3u64, 5, 7, 11, 997, 991, 2, 9, 25][(next() % 9) as usize];
                n *= p * p;
            }
            if next().is_multiple_of(3) {
                n *= BigUint::from(next()) * BigUint::from(next());
            }
            assert_eq!(extract_small_squares_big(&n), naive(&n), "{n}");
        }
        assert_eq!(extract_small_squares_big(&BigUint::zero()), (BigUint::one(), BigUint::zero()));
    }
}
