//! Univariate polynomials: the Bernstein basis and its conversions to and from the power form,
//! exact polynomial arithmetic (trim, division, gcd, square-free part, quadratic roots),
//! exact real root isolation, exact real algebraic numbers ([`algebraic::RealAlgebraic`]),
//! polynomials over `Z[v]` and their resultants (crate-internal `resultant`, shared with the
//! intersection code), and factor-degree bounds from reductions modulo primes ([`modular`]).
//!
//! Depends only on [`crate::num`].

pub mod algebraic;
pub mod bernstein;
pub mod modular;
pub mod polynomial;
pub(crate) mod resultant;
pub mod roots;

pub use roots::{Root, isolate_bernstein, isolate_bernstein_within, isolate_in, isolate_in_within};
