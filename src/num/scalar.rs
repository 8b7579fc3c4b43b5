//! Scalars: the numbers every algorithm in casteljau is generic over.
//!
//! [`Scalar`] is a field with by-value and by-reference operations; it is implemented for
//! `f64` (fast, approximate) and [`BigRational`] (exact). [`Exact`] marks the types whose
//! `==` is numeric equality and whose [`Exact::sign`] is decided without rounding: identity
//! checks and classifications require `S: Exact`. The quadratic extension
//! [`QuadraticExt`](crate::num::QuadraticExt) is another `Exact` scalar built on any `Exact` one.
//!
//! # Laws
//! For every implementation (exactly for `Exact` types, up to rounding for `f64`):
//! `a + 0 = a`, `a · 1 = a`, `a + (−a) = 0`, `a · (1/a) = 1` for `a ≠ 0`,
//! `from_i64(m) + from_i64(n) = from_i64(m + n)` and `from_ratio(p/q) · from_i64(q) = from_i64(p)`.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::fmt::{Debug, Display};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A field of numbers on which Bézier algorithms run.
///
/// Kept deliberately small (as `num_traits::Num` is): the field operations by value and by
/// reference, the constants as functions (bignums cannot be `const`), integer and exact-ratio
/// conversions, and a zero test.
///
/// # Example
/// ```
/// use casteljau::Scalar;
/// use num_rational::BigRational;
/// fn lerp<S: Scalar>(a: &S, b: &S, t: &S) -> S {
///     (S::one() - t) * a + t.clone() * b
/// }
/// let r = lerp(&BigRational::from_i64(1), &BigRational::from_i64(4), &"1/3".parse().unwrap());
/// assert_eq!(r, BigRational::from_i64(2));
/// assert_eq!(lerp(&1.0f64, &4.0, &0.5), 2.5);
/// ```
pub trait Scalar:
    'static
    + Clone
    + Debug
    + Display
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + for<'a> Add<&'a Self, Output = Self>
    + for<'a> Sub<&'a Self, Output = Self>
    + for<'a> Mul<&'a Self, Output = Self>
    + for<'a> Div<&'a Self, Output = Self>
{
    /// The additive identity: `a + zero() = a`.
    fn zero() -> Self;
    /// The multiplicative identity: `a · one() = a`.
    fn one() -> Self;
    /// The image of an integer: a ring homomorphism (exact for exact types).
    fn from_i64(n: i64) -> Self;
    /// The image of an exact ratio (rounded to nearest for `f64`).
    fn from_ratio(r: &BigRational) -> Self;
    /// `self == 0` (exact for exact types).
    fn is_zero(&self) -> bool;
    /// An `f64` approximation, for plots and printing with `--float`.
    fn to_f64(&self) -> f64;
}

/// Marker for scalars whose `==` is numeric equality and whose sign is exact.
///
/// # Laws
/// `a == b` exactly when the two numbers are equal, whatever their spelling: [`Rational`] and
/// `BigRational` keep a canonical form (reduced, positive denominator) and compare it;
/// [`QuadraticExt`](crate::num::QuadraticExt) normalises its radicand;
/// [`Fraction`](crate::num::Fraction) keeps unreduced fractions and compares by
/// cross-multiplication (`a/b = c/d ⟺ ad = bc`). The sign is exact in every case.
pub trait Exact: Scalar + Eq {
    /// The exact sign: `Less` for negative, `Equal` for zero, `Greater` for positive.
    fn sign(&self) -> Ordering;
    /// The non-negative square root of `self` when it lies in this field, else `None`.
    ///
    /// # Laws
    /// `x.exact_sqrt() == Some(r)` implies `r ≥ 0` and `r·r == x`; `None` exactly when `x` is
    /// negative or not a square in the field.
    fn exact_sqrt(&self) -> Option<Self>;

    /// Whether `Display` writes one token without spaces (a rational `-7/6`), so that a
    /// compound spelling such as `a + b*sqrt(d)` needs no parentheses around it. `false`
    /// unless an implementation says otherwise.
    const ATOMIC_DISPLAY: bool = false;

    /// The number as a [`BigRational`] when it is one (every rational type); `None` for
    /// extension elements.
    fn to_ratio(&self) -> Option<BigRational> {
        None
    }
}

impl Scalar for f64 {
    fn zero() -> Self {
        0.0
    }
    fn one() -> Self {
        1.0
    }
    fn from_i64(n: i64) -> Self {
        n as f64
    }
    fn from_ratio(r: &BigRational) -> Self {
        ratio_to_f64(r)
    }
    fn is_zero(&self) -> bool {
        *self == 0.0
    }
    fn to_f64(&self) -> f64 {
        *self
    }
}

impl Scalar for BigRational {
    fn zero() -> Self {
        Zero::zero()
    }
    fn one() -> Self {
        One::one()
    }
    fn from_i64(n: i64) -> Self {
        BigRational::from_integer(BigInt::from(n))
    }
    fn from_ratio(r: &BigRational) -> Self {
        r.clone()
    }
    fn is_zero(&self) -> bool {
        Zero::is_zero(self)
    }
    fn to_f64(&self) -> f64 {
        ratio_to_f64(self)
    }
}

impl Exact for BigRational {
    const ATOMIC_DISPLAY: bool = true;
    fn to_ratio(&self) -> Option<BigRational> {
        Some(self.clone())
    }
    fn sign(&self) -> Ordering {
        if Signed::is_negative(self) {
            Ordering::Less
        } else if Zero::is_zero(self) {
            Ordering::Equal
        } else {
            Ordering::Greater
        }
    }
    fn exact_sqrt(&self) -> Option<Self> {
        rational_sqrt(self)
    }
}

/// The exact square root of a non-negative rational, when it is rational.
pub(crate) fn rational_sqrt(d: &BigRational) -> Option<BigRational> {
    if Signed::is_negative(d) {
        return None;
    }
    let n = integer_sqrt(d.numer())?;
    let m = integer_sqrt(d.denom())?;
    Some(BigRational::new(n, m))
}

/// The exact square root of a non-negative integer, when it is an integer.
pub(crate) fn integer_sqrt(n: &BigInt) -> Option<BigInt> {
    if Signed::is_negative(n) {
        return None;
    }
    // squares are 0, 1, 4 or 9 mod 16 and a square mod 63: most non-squares stop here
    let low = n.iter_u64_digits().next().unwrap_or(0);
    if (0x0213u32 >> (low & 15)) & 1 == 0 {
        return None;
    }
    let r63 = (n.magnitude() % 63u32).iter_u32_digits().next().unwrap_or(0);
    if !(0..63u32).any(|x| x * x % 63 == r63) {
        return None;
    }
    let r = n.sqrt();
    (&r * &r == *n).then_some(r)
}

/// The `f64` nearest to an exact ratio (round half to even, as IEEE-754 division): num-rational's
/// correctly rounded conversion, also for numerators and denominators beyond `f64` range
/// (`±inf` past `f64::MAX`, subnormals and `±0` below the smallest normal).
///
/// # Example
/// ```
/// use casteljau::{ratio, num::ratio_to_f64};
/// assert_eq!(ratio_to_f64(&ratio(1, 10)), 0.1);
/// assert_eq!(ratio_to_f64(&ratio(1, 3)), 1.0 / 3.0);
/// ```
pub fn ratio_to_f64(r: &BigRational) -> f64 {
    ToPrimitive::to_f64(r).expect("num-rational converts every ratio to f64")
}

/// The integer `n` as a [`BigRational`].
pub fn rat(n: i64) -> BigRational {
    BigRational::from_i64(n)
}

/// The ratio `p/q` as a reduced [`BigRational`].
///
/// # Panics
/// **Panics if `q == 0`.**
pub fn ratio(p: i64, q: i64) -> BigRational {
    BigRational::new(BigInt::from(p), BigInt::from(q))
}

/// An exact rational with fast paths for integers: a thin wrapper around [`BigRational`].
///
/// `BigRational` reduces after every operation, and its gcd is slow when one side is `1`
/// (Stein's algorithm then takes one step per bit): multiplying two 200-bit integers as ratios
/// costs ~8 µs here against ~50 ns as `BigInt`. `Rational` adds, subtracts and multiplies
/// integers (denominator 1) as integers and otherwise defers to `BigRational`, so the canonical
/// form (reduced, positive denominator) and therefore `==` are the same. Use it for work that
/// stays mostly in the integers, such as grid proofs on integer nodes.
///
/// # Example
/// ```
/// use casteljau::num::{Rational, Scalar};
/// let a = Rational::from_i64(6) * Rational::from_i64(7);
/// assert_eq!(a, Rational::from(casteljau::ratio(84, 2)));
/// assert_eq!((a / Rational::from_i64(4)).to_string(), "21/2");
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Rational(pub BigRational);

impl From<BigRational> for Rational {
    fn from(r: BigRational) -> Self {
        Rational(r)
    }
}

impl From<Rational> for BigRational {
    fn from(r: Rational) -> Self {
        r.0
    }
}

impl Display for Rational {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        Display::fmt(&self.0, f)
    }
}

impl Scalar for Rational {
    fn zero() -> Self {
        Rational(<BigRational as Scalar>::zero())
    }
    fn one() -> Self {
        Rational(<BigRational as Scalar>::one())
    }
    fn from_i64(n: i64) -> Self {
        Rational(<BigRational as Scalar>::from_i64(n))
    }
    fn from_ratio(r: &BigRational) -> Self {
        Rational(r.clone())
    }
    fn is_zero(&self) -> bool {
        Zero::is_zero(&self.0)
    }
    fn to_f64(&self) -> f64 {
        ratio_to_f64(&self.0)
    }
}

impl Exact for Rational {
    const ATOMIC_DISPLAY: bool = true;
    fn to_ratio(&self) -> Option<BigRational> {
        Some(self.0.clone())
    }
    fn sign(&self) -> Ordering {
        self.0.sign()
    }
    fn exact_sqrt(&self) -> Option<Self> {
        rational_sqrt(&self.0).map(Rational)
    }
}

impl Neg for Rational {
    type Output = Self;
    fn neg(self) -> Self {
        Rational(-self.0)
    }
}

macro_rules! integer_fast_path {
    ($tr:ident $m:ident, $int:expr) => {
        impl $tr<&Rational> for Rational {
            type Output = Rational;
            fn $m(self, o: &Rational) -> Rational {
                if self.0.is_integer() && o.0.is_integer() {
                    let f: fn(&BigInt, &BigInt) -> BigInt = $int;
                    Rational(BigRational::from_integer(f(self.0.numer(), o.0.numer())))
                } else {
                    Rational($tr::$m(self.0, &o.0))
                }
            }
        }
        impl $tr for Rational {
            type Output = Rational;
            fn $m(self, o: Rational) -> Rational {
                $tr::$m(self, &o)
            }
        }
    };
}
integer_fast_path!(Add add, |a, b| a + b);
integer_fast_path!(Sub sub, |a, b| a - b);
integer_fast_path!(Mul mul, |a, b| a * b);

impl Div<&Rational> for Rational {
    type Output = Rational;
    fn div(self, o: &Rational) -> Rational {
        Rational(self.0 / &o.0)
    }
}

impl Div for Rational {
    type Output = Rational;
    fn div(self, o: Rational) -> Rational {
        Rational(self.0 / o.0)
    }
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    use super::*;
    #[test]
    fn rational_sqrt_example() {
        use crate::ratio;
        assert_eq!(rational_sqrt(&ratio(9, 4)), Some(ratio(3, 2)));
        assert_eq!(rational_sqrt(&ratio(2, 1)), None);
    }
}
