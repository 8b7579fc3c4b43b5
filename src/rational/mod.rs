//! Rational Bézier curves (seeds 000 and 002 §2): [`RationalBezier`] in homogeneous form,
//! Menelaus configurations, implicit equations proved along a curve, and exact extrema and
//! bounding boxes ([`extrema`], polynomial curves included).
//!
//! Depends on [`crate::num`], [`crate::poly`], [`crate::proof`] and [`crate::curve`].

pub mod exact;
pub mod extrema;
pub mod implicit;
pub mod menelaus;
pub mod rational_bezier;

pub use rational_bezier::RationalBezier;
