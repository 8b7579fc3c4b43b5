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
//! use casteljau::internal::{SmallRational, checked};
//! use casteljau::{Scalar, ratio};
//! let x = checked(|| SmallRational::from_i64(1) / SmallRational::from_i64(3) + SmallRational::from_i64(1) / SmallRational::from_i64(6));
//! assert_eq!(x.unwrap().to_string(), "1/2");
//! let big = SmallRational::from_i64(i64::MAX);
//! assert!(checked(|| big * big * big).is_none()); // 2^189 does not fit: refused, not wrapped
//! assert_eq!(SmallRational::from_i64(5).to_big(), ratio(5, 1));
//! ```

use crate::num::quadratic_field::{QuadraticExt, Radical};
use crate::num::scalar::{Exact, Scalar, ratio_to_f64};
use crate::num::word::{extract_small_squares, square_root};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::ToPrimitive;
use std::cell::Cell;
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

// re-exported: code outside `num` (src/classify) uses the path `num::small::gcd_u128`
pub(crate) use crate::num::word::gcd_u128;

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
        let g = gcd_u128(num.unsigned_abs(), den.unsigned_abs()) as i128;
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
        let g = gcd_u128(num.unsigned_abs(), den as u128) as i128;
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
    // a fraction plus an integer stays reduced: gcd(p + kq, q) = gcd_u128(p, q) = 1
    if b.den == 1 {
        return Some(SmallRational { num: a.num.checked_add(b.num.checked_mul(a.den)?)?, den: a.den });
    }
    if a.den == 1 {
        return Some(SmallRational { num: b.num.checked_add(a.num.checked_mul(b.den)?)?, den: b.den });
    }
    let g = gcd_u128(a.den as u128, b.den as u128) as i128;
    let (ad, bd) = (a.den / g, b.den / g);
    let num = a.num.checked_mul(bd)?.checked_add(b.num.checked_mul(ad)?)?;
    // gcd(num, ad·b.den) = gcd_u128(num, g) · (nothing from ad, bd): reduce by the common part with g
    let h = gcd_u128(num.unsigned_abs(), g as u128) as i128;
    let den = (g / h).checked_mul(ad)?.checked_mul(bd)?;
    Some(SmallRational { num: num / h, den })
}

fn mul(a: SmallRational, b: SmallRational) -> Option<SmallRational> {
    if a.den == 1 && b.den == 1 {
        return Some(SmallRational::integer(a.num.checked_mul(b.num)?));
    }
    let g1 = gcd_u128(a.num.unsigned_abs(), b.den as u128) as i128;
    let g2 = gcd_u128(b.num.unsigned_abs(), a.den as u128) as i128;
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

/// The square root of a non-negative `d = p/q` in the spelling of
/// [`QuadraticExt::sqrt`](crate::num::QuadraticExt::sqrt): rational when `d` is a
/// square, else `b·√m` with `m` the integer `p·q` freed of the squares of primes below 1000 and
/// `b = k/q`.
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
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    #[test]
    fn push_to_example() {
        use super::SmallRational;
        let mut out = b"x = ".to_vec();
        SmallRational::new(-6, 4).unwrap().push_to(&mut out);
        assert_eq!(out, b"x = -3/2");
    }
}
