//! [`Fraction`]: an exact rational kept **unreduced** (`num/den` with no gcd after each
//! operation), for evaluating long expressions at many points.
//!
//! [`BigRational`] reduces after every operation, and num-bigint's gcd is the bit-by-bit Stein
//! algorithm: evaluating a rational-function identity of seed 002 at one grid point cost
//! ~170 µs, almost all of it in gcds. A fraction that is only multiplied out (`a/b + c/d =
//! (ad + bc)/bd`, one product when the denominators agree) costs a few big-integer products
//! instead; it is reduced only when its denominator outgrows [`REDUCE_BITS`] (so sums of many
//! fractions cannot grow without bound) and when it is shown or converted. Equality is
//! numeric (`a/b = c/d ⟺ ad = bc`), so the type is [`Exact`] like [`BigRational`].
//! num-rational offers no unreduced mode, hence this small type.
//!
//! # Example
//! ```
//! use casteljau::num::Fraction;
//! use casteljau::{Scalar, ratio};
//! let x = Fraction::from(ratio(1, 6)) + Fraction::from(ratio(1, 3));
//! assert_eq!(x, Fraction::from(ratio(1, 2))); // numeric equality, whatever the spelling
//! assert_eq!(x.to_string(), "1/2");          // shown reduced
//! assert_eq!(x.to_big(), ratio(1, 2));
//! ```

use crate::num::scalar::{Exact, Scalar, ratio_to_f64, rational_sqrt};
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Denominators longer than this many bits are reduced after an operation.
pub(crate) const REDUCE_BITS: u64 = 2048;

/// An exact rational `num/den` (`den > 0`), not necessarily reduced. An integer carries no
/// denominator at all (`den = None`), so integer arithmetic allocates only its results.
#[derive(Clone, Debug)]
pub struct Fraction {
    num: BigInt,
    den: Option<BigInt>,
}

impl Fraction {
    /// `num/den` for `den ≠ 0`, sign moved to the numerator.
    fn new_raw(num: BigInt, den: BigInt) -> Self {
        let (num, den) = if den.is_negative() { (-num, -den) } else { (num, den) };
        let f = if den.is_one() { Fraction { num, den: None } } else { Fraction { num, den: Some(den) } };
        if f.den.as_ref().is_some_and(|d| d.bits() > REDUCE_BITS) { f.reduced() } else { f }
    }

    fn integer(num: BigInt) -> Self {
        Fraction { num, den: None }
    }

    /// Bits of the numerator plus the denominator (as stored, unreduced): the size the cost
    /// of an operation on it grows with.
    pub(crate) fn bits(&self) -> u64 {
        self.num.bits() + self.den.as_ref().map_or(0, BigInt::bits)
    }

    /// The same number with `gcd(num, den) = 1`.
    pub fn reduced(&self) -> Self {
        let Some(d) = &self.den else { return self.clone() };
        let g = self.num.gcd(d);
        let (n, d) = (&self.num / &g, d / &g);
        if d.is_one() { Fraction::integer(n) } else { Fraction { num: n, den: Some(d) } }
    }

    /// The number as a reduced [`BigRational`].
    pub fn to_big(&self) -> BigRational {
        let r = self.reduced();
        BigRational::new_raw(r.num, r.den.unwrap_or_else(BigInt::one))
    }

    /// The number when it is an integer that fits `i64` (without reducing: `4/2` gives `None`
    /// unless its denominator is 1).
    pub fn to_i64(&self) -> Option<i64> {
        if self.den.is_none() { num_traits::ToPrimitive::to_i64(&self.num) } else { None }
    }

    /// `a · b` from references (no copy of either operand).
    pub fn product(a: &Fraction, b: &Fraction) -> Fraction {
        let num = &a.num * &b.num;
        match (&a.den, &b.den) {
            (None, None) => Fraction::integer(num),
            (Some(d), None) | (None, Some(d)) => Fraction { num, den: Some(d.clone()) },
            (Some(x), Some(y)) => Fraction::new_raw(num, x * y),
        }
    }

    /// Whether the number is an integer.
    pub fn is_integer(&self) -> bool {
        self.den.as_ref().is_none_or(|d| (&self.num % d).is_zero())
    }
}

impl From<BigRational> for Fraction {
    fn from(r: BigRational) -> Self {
        let (num, den) = r.into_raw();
        if den.is_one() { Fraction::integer(num) } else { Fraction { num, den: Some(den) } }
    }
}

impl PartialEq for Fraction {
    /// Numeric: `a/b = c/d ⟺ ad = bc`.
    fn eq(&self, o: &Self) -> bool {
        match (&self.den, &o.den) {
            (None, None) => self.num == o.num,
            (Some(a), Some(b)) if a == b => self.num == o.num,
            (None, Some(b)) => &self.num * b == o.num,
            (Some(a), None) => self.num == &o.num * a,
            (Some(a), Some(b)) => &self.num * b == &o.num * a,
        }
    }
}

impl Eq for Fraction {}

impl fmt::Display for Fraction {
    /// Reduced, as [`BigRational`] shows it.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.to_big(), f)
    }
}

impl Scalar for Fraction {
    fn zero() -> Self {
        Fraction::integer(BigInt::zero())
    }
    fn one() -> Self {
        Fraction::integer(BigInt::one())
    }
    fn from_i64(n: i64) -> Self {
        Fraction::integer(BigInt::from(n))
    }
    fn from_ratio(r: &BigRational) -> Self {
        Fraction::from(r.clone())
    }
    fn is_zero(&self) -> bool {
        self.num.is_zero()
    }
    fn to_f64(&self) -> f64 {
        ratio_to_f64(&self.to_big())
    }
}

impl Exact for Fraction {
    const ATOMIC_DISPLAY: bool = true;
    fn to_ratio(&self) -> Option<BigRational> {
        Some(self.to_big())
    }
    fn sign(&self) -> Ordering {
        self.num.sign().cmp(&num_bigint::Sign::NoSign)
    }
    fn exact_sqrt(&self) -> Option<Self> {
        rational_sqrt(&self.to_big()).map(Fraction::from)
    }
}

impl Neg for Fraction {
    type Output = Self;
    fn neg(self) -> Self {
        Fraction { num: -self.num, den: self.den }
    }
}

/// `a/b ± c/d` with one product when the denominators agree or one is absent.
fn add_sub(x: Fraction, o: &Fraction, minus: bool) -> Fraction {
    let join = |a: BigInt, b: BigInt| if minus { a - b } else { a + b };
    match (x.den, &o.den) {
        (None, None) => Fraction::integer(join(x.num, o.num.clone())),
        (Some(a), None) => {
            let n = join(x.num, &o.num * &a);
            Fraction { num: n, den: Some(a) }
        }
        (None, Some(b)) => Fraction { num: join(x.num * b, o.num.clone()), den: Some(b.clone()) },
        (Some(a), Some(b)) if a == *b => Fraction { num: join(x.num, o.num.clone()), den: Some(a) },
        (Some(a), Some(b)) => {
            let n = join(x.num * b, &o.num * &a);
            Fraction::new_raw(n, a * b)
        }
    }
}

impl Add<&Fraction> for Fraction {
    type Output = Self;
    fn add(self, o: &Self) -> Self {
        add_sub(self, o, false)
    }
}

impl Sub<&Fraction> for Fraction {
    type Output = Self;
    fn sub(self, o: &Self) -> Self {
        add_sub(self, o, true)
    }
}

impl Mul<&Fraction> for Fraction {
    type Output = Self;
    fn mul(self, o: &Self) -> Self {
        match (self.den, &o.den) {
            (None, None) => Fraction::integer(self.num * &o.num),
            (Some(a), None) => Fraction { num: self.num * &o.num, den: Some(a) },
            (None, Some(b)) => Fraction { num: self.num * &o.num, den: Some(b.clone()) },
            (Some(a), Some(b)) => Fraction::new_raw(self.num * &o.num, a * b),
        }
    }
}

impl Div<&Fraction> for Fraction {
    type Output = Self;
    /// # Panics
    /// **Panics on division by zero.**
    fn div(self, o: &Self) -> Self {
        assert!(!o.num.is_zero(), "Fraction: division by zero");
        let num = match &o.den {
            None => self.num,
            Some(b) => self.num * b,
        };
        let den = match self.den {
            None => o.num.clone(),
            Some(a) => a * &o.num,
        };
        Fraction::new_raw(num, den)
    }
}

macro_rules! by_value {
    ($($tr:ident $m:ident),*) => {$(
        impl $tr for Fraction {
            type Output = Self;
            fn $m(self, o: Self) -> Self {
                <Self as $tr<&Self>>::$m(self, &o)
            }
        }
    )*};
}
by_value!(Add add, Sub sub, Mul mul, Div div);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::scalar::ratio;

    #[test]
    fn fraction_agrees_with_big_rational() {
        let xs = [ratio(1, 3), ratio(-7, 12), ratio(5, 1), ratio(0, 1), ratio(-1, 1), ratio(9, 6)];
        for a in &xs {
            for b in &xs {
                let (fa, fb) = (Fraction::from(a.clone()), Fraction::from(b.clone()));
                assert_eq!((fa.clone() + fb.clone()).to_big(), a + b);
                assert_eq!((fa.clone() - fb.clone()).to_big(), a - b);
                assert_eq!((fa.clone() * fb.clone()).to_big(), a * b);
                if !Scalar::is_zero(b) {
                    assert_eq!((fa.clone() / fb.clone()).to_big(), a / b);
                }
                assert_eq!(fa == fb, a == b);
                assert_eq!(fa.sign(), a.sign());
            }
        }
        // a negative divisor keeps the denominator positive
        let q = Fraction::from(ratio(1, 2)) / Fraction::from(ratio(-3, 1));
        assert_eq!(q.sign(), Ordering::Less);
        assert_eq!(q.to_string(), "-1/6");
    }

    #[test]
    fn fraction_sums_stay_bounded() {
        // Σ 1/k for k ≤ 2000 multiplies denominators; reduction keeps them near lcm(1..2000)
        let mut s = Fraction::zero();
        for k in 1..=2000 {
            s = s + Fraction::from(ratio(1, k));
        }
        assert!(s.den.as_ref().unwrap().bits() <= 2 * REDUCE_BITS + 64);
    }
}
