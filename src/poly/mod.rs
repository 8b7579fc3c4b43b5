//! Univariate polynomials: the Bernstein basis and its conversions to and from the power form,
//! exact polynomial arithmetic (trim, division, gcd, square-free part, quadratic roots),
//! exact real root isolation, exact real algebraic numbers ([`algebraic::RealAlgebraic`]),
//! polynomials over `Z[v]` and their resultants (crate-internal `resultant`, shared with the
//! intersection code), and factor-degree bounds from reductions modulo primes ([`min_factor_degree`]).
//!
//! Depends only on [`crate::num`].

pub(crate) mod algebraic;
pub(crate) mod bernstein;
pub(crate) mod integer;
pub(crate) mod modular;
pub(crate) mod polynomial;
pub(crate) mod resultant;
pub(crate) mod roots;

pub use algebraic::{RealAlgebraic, sign_at, simplest_rational};
pub use bernstein::{
    bernstein, bernstein_all, bernstein_sum, bernstein_to_power_matrix, binomial, binomial_row, binomial_scalar,
    eval_power, from_power, power_to_bernstein_matrix, split, split_integer, to_power,
};
pub use modular::min_factor_degree;
pub use polynomial::{Poly, center_plus_minus_sqrt, quadratic_roots};
pub use roots::{Root, isolate_bernstein, isolate_bernstein_within, isolate_in, isolate_in_within, restrict};
