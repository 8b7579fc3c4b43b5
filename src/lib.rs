//! # casteljau — Bézier-curve theory in exact arithmetic
//!
//! casteljau is an oracle for floating-point geometry code and a checker for CAGD theory: the
//! same generic algorithms run over `f64` (fast, approximate) and over exact rationals
//! ([`BigRational`](num_rational::BigRational)) or exact quadratic extensions
//! ([`QuadraticExt`]), so answers are exact and identities are *proved* by exact testing.
//!
//! * [`scalar`]: the [`Scalar`] field trait and the [`Exact`] marker.
//! * [`quadratic_field`]: exact `K(√d)`.
//! * [`point`], [`bezier`]: points, curves, derivatives, elevation, exact degree reduction.
//! * [`bernstein`]: binomials, Bernstein polynomials, power ↔ Bernstein conversion matrices.
//! * [`casteljau`]: de Casteljau's scheme (the triangle) and subdivision (Lemma 2).
//! * [`fraction_free`]: the exact kernels on integers over one denominator (the fast path).
//! * [`proof`]: the grid prover — proof of polynomial identities by exact testing.
//! * [`expr`], [`catalogue`], [`claim_checks`]: the `proofs/` claim files and their exact checks.
//! * [`classify`], [`certified`], [`moving_line`], [`canonical`], [`rational_cubic`]: exact cubic
//!   classification.
//! * [`parse`]: exact numbers and control polygons from text; [`cli`]: the command line.
//!
//! ```
//! use casteljau::{BezierCurve, fraction_free, parse::parse_points, ratio};
//! let c = BezierCurve::new(parse_points("-1 -1, -1/3 1, 1/3 -1, 1 1", 2, None).unwrap()).unwrap();
//! let (left, right) = fraction_free::subdivide(&c, &ratio(1, 3));
//! assert_eq!(left.to_string(), "-1 -1, -7/9 -1/3, -5/9 -1/9, -1/3 -1/27");
//! assert_eq!(right.to_string(), "-1/3 -1/27, 1/9 1/9, 5/9 -1/3, 1 1");
//! ```

pub mod answers;
pub mod bernstein;
pub mod bezier;
pub mod canonical;
pub mod casteljau;
pub mod catalogue;
pub mod certified;
pub mod claim_checks;
pub mod claim_checks_geometry;
pub mod classify;
pub mod cli;
pub mod commands;
pub mod error;
pub mod expr;
pub mod fraction_free;
pub mod gallery;
pub mod implicit;
pub mod menelaus;
pub mod moving_line;
pub mod parse;
pub mod plot;
pub mod point;
pub mod proof;
pub mod quadratic_field;
pub mod rational_bezier;
pub mod rational_cubic;
pub mod roots;
pub mod scalar;
pub mod spline;
pub mod spline_net;
#[cfg(feature = "proptest")]
pub mod strategies;
pub mod surface;

pub use bezier::BezierCurve;
pub use error::{Error, Position, Result};
pub use point::Point;
pub use quadratic_field::QuadraticExt;
pub use scalar::{Exact, Scalar, rat, ratio};
