//! Rational Bézier curves (seeds 000 and 002 §2): [`RationalBezier`] in homogeneous form,
//! Menelaus configurations, implicit equations proved along a curve, and exact extrema and
//! bounding boxes ([`bounding_box`], polynomial curves included).
//!
//! Depends on [`crate::num`], [`crate::poly`], [`crate::proof`] and [`crate::curve`].

pub(crate) mod exact;
pub(crate) mod extrema;
pub(crate) mod implicit;
pub(crate) mod menelaus;
pub(crate) mod rational_bezier;

pub use exact::{Conic, Definedness, ParameterInterval, RationalElevation, RationalEvaluation, RationalSubdivision};
pub use extrema::{BoundingBox, Stationary, bounding_box};
pub use implicit::ImplicitOutcome;
pub use menelaus::Configuration;
pub use rational_bezier::{ConicType, RationalBezier};
