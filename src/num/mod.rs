//! Numbers: the [`Scalar`] field trait with its [`Exact`] marker, the integer-fast exact
//! [`Rational`], exact quadratic extensions [`QuadraticExt`], points (vectors of scalars),
//! fixed-width exact rationals (`SmallRational`, for the internal fast paths), word-sized number
//! theory (gcds, residues, square extraction; crate-internal), and exact numbers and point
//! lists read from text ([`parse_points`], [`parse_number`], [`NumberMode`]).
//!
//! The lowest layer: it imports nothing else of the crate but [`crate::error`].
//!
//! # Which rational type
//!
//! | type | use it for | `==` | overflow |
//! | --- | --- | --- | --- |
//! | `BigRational` (num-rational) | exact answers and inputs: every public result | canonical form | none |
//! | [`Rational`] | a [`Scalar`] for generic code run exactly (integer values add and multiply as integers) | canonical form | none |
//! | [`Fraction`] | long evaluations (claim expressions): no gcd per operation | cross-multiplication | none; reduced past 2048 bits |
//! | `SmallRational` (internal) | fixed-width fast paths, run inside `checked` | canonical form | reported: `checked` returns `None`, the caller redoes the work in `BigRational` |
//!
//! All four are exact ([`Exact`]): equal numbers compare equal whatever their spelling.

pub(crate) mod fraction;
pub(crate) mod parse;
pub(crate) mod point;
pub(crate) mod quadratic_field;
pub(crate) mod scalar;
pub(crate) mod serial;
pub(crate) mod small;
pub(crate) mod word;

pub use fraction::Fraction;
pub use parse::{NumberMode, parse_number, parse_number_in, parse_numbers, parse_points, parse_points_in};
pub use point::{Point, Point2};
pub use quadratic_field::{QuadraticExt, Radical};
pub use scalar::{Exact, Rational, Scalar, rat, ratio, ratio_to_f64};

/// Ring arithmetic that may fail: checked fixed-width integers give `None` on overflow, exact
/// and interval types never do. Internal (reached through `casteljau::internal`). One home for
/// the code written once over several number types: the certified cubic classification
/// (`SignRing` adds signs) and the intersection oracle's Bézoutians (checked `i128`, `BigInt`,
/// `f64` enclosures).
///
/// # Example
/// ```
/// use casteljau::internal::CheckedRing;
/// assert_eq!(i128::MAX.add(&1), None);
/// assert_eq!(<i128 as CheckedRing>::zero().mul(&5), Some(0));
/// ```
#[doc(hidden)]
pub trait CheckedRing: Clone + Sized {
    /// `0`.
    fn zero() -> Self;
    /// `a + b`, `None` on overflow.
    fn add(&self, o: &Self) -> Option<Self>;
    /// `a − b`, `None` on overflow.
    fn sub(&self, o: &Self) -> Option<Self>;
    /// `a · b`, `None` on overflow.
    fn mul(&self, o: &Self) -> Option<Self>;
}

impl CheckedRing for i128 {
    fn zero() -> Self {
        0
    }
    fn add(&self, o: &Self) -> Option<Self> {
        self.checked_add(*o)
    }
    fn sub(&self, o: &Self) -> Option<Self> {
        self.checked_sub(*o)
    }
    fn mul(&self, o: &Self) -> Option<Self> {
        self.checked_mul(*o)
    }
}

impl CheckedRing for num_bigint::BigInt {
    fn zero() -> Self {
        num_bigint::BigInt::default()
    }
    fn add(&self, o: &Self) -> Option<Self> {
        Some(self + o)
    }
    fn sub(&self, o: &Self) -> Option<Self> {
        Some(self - o)
    }
    fn mul(&self, o: &Self) -> Option<Self> {
        Some(self * o)
    }
}

/// Deterministic pseudo-random integers in `[−m, m]` for tests, from [`xorshift`] words.
#[cfg(test)]
pub(crate) fn symmetric(seed: u64) -> impl FnMut(i64) -> i64 {
    let mut word = xorshift(seed);
    move |m| (word() % (2 * m as u64 + 1)) as i64 - m
}

/// Deterministic pseudo-random words for tests (xorshift64; `seed` non-zero).
#[cfg(test)]
pub(crate) fn xorshift(seed: u64) -> impl FnMut() -> u64 {
    let mut x = seed;
    move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        x
    }
}
