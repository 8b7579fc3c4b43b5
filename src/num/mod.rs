//! Numbers: the [`Scalar`] field trait with its [`Exact`] marker, the integer-fast exact
//! [`Rational`], exact quadratic extensions [`QuadraticExt`], points (vectors of scalars), and
//! fixed-width exact rationals ([`small::SmallRational`], checked), and exact numbers and point
//! lists read from text.
//!
//! The lowest layer: it imports nothing else of the crate but [`crate::error`].

pub mod fraction;
pub mod parse;
pub mod point;
pub mod quadratic_field;
pub mod scalar;
pub mod serial;
pub mod small;

pub use point::Point;
pub use quadratic_field::{QuadraticExt, Radical};
pub use scalar::{Exact, Rational, Scalar, rat, ratio, ratio_to_f64};

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
