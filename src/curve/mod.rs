//! Polynomial Bézier curves: [`BezierCurve`] with derivatives, elevation and exact degree
//! reduction, de Casteljau's scheme and subdivision, and the fraction-free exact kernels.
//!
//! Depends on [`crate::num`] and [`crate::poly`].

pub(crate) mod bezier;
pub(crate) mod casteljau;
pub(crate) mod exact;
pub(crate) mod fraction_free;
mod operations;

pub use bezier::{BezierCurve, parse_curve_in};
pub use casteljau::DeCasteljauTriangle;
pub use exact::{
    DegreeReduction, Derivative, Elevation, Evaluation, Piece, PointAt, PowerForm, RepeatedSubdivision, Scheme,
    Subdivision,
};
