//! Rational Bézier curves (seeds 000 and 002 §2): [`RationalBezier`] in homogeneous form,
//! Menelaus configurations, and implicit equations proved along a curve.
//!
//! Depends on [`crate::num`], [`crate::poly`], [`crate::proof`] and [`crate::curve`].

pub mod implicit;
pub mod menelaus;
pub mod rational_bezier;

pub use rational_bezier::RationalBezier;
