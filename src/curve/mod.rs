//! Polynomial Bézier curves: [`BezierCurve`] with derivatives, elevation and exact degree
//! reduction, de Casteljau's scheme and subdivision, and the fraction-free exact kernels.
//!
//! Depends on [`crate::num`] and [`crate::poly`].

pub mod bezier;
pub mod casteljau;
pub mod exact;
pub mod fraction_free;

pub use bezier::BezierCurve;
