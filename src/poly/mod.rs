//! Univariate polynomials: the Bernstein basis and its conversions to and from the power form,
//! exact polynomial arithmetic (trim, division, gcd, square-free part, quadratic roots),
//! exact real root isolation, exact real algebraic numbers ([`algebraic::RealAlgebraic`]),
//! polynomials over `Z[v]` and their resultants (crate-internal `resultant`, shared with the
//! intersection code), and factor-degree bounds from reductions modulo primes (crate-internal
//! `modular`).
//!
//! Depends only on [`crate::num`].

pub(crate) mod algebraic;
pub(crate) mod bernstein;
pub(crate) mod integer;
pub(crate) mod modular;
pub(crate) mod polynomial;
pub(crate) mod resultant;
pub(crate) mod roots;

pub use algebraic::RealAlgebraic;
pub use bernstein::{bernstein, bernstein_all, bernstein_to_power_matrix, binomial, power_to_bernstein_matrix, split};
pub use polynomial::{Poly, quadratic_roots};
pub use roots::{Root, isolate_bernstein};
