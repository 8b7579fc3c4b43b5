//! The oracles for float code: a float library's answers decided against the exact ones, every
//! disagreement named, with the exact value beside the float one.
//!
//! | what the float library answered | the oracle | the CLI |
//! | --- | --- | --- |
//! | facts about one cubic: category, node type, loop, cusp, inflections and their parameters, the double point | [`check_classification`] (or [`compare_classification`] on a classification at hand) | `casteljau check` |
//! | the intersection parameters of two curves | [`check_intersections`] | — |
//! | the result of a boolean operation on paths | [`check_against`] | `casteljau boolean … --against` |
//!
//! The first two share one rule ([below](self#the-shared-matching)): a float answer stands for
//! the exact values within its tolerance — the window `[p − tol, p + tol]`, both `f64`s taken
//! exactly — and float answers are matched to exact ones in order; what is left over is
//! `missed`, `spurious` or a `duplicate` ([`DisagreementKind`]). The path oracle decides regions:
//! nesting, an exact witness point, and a distance bound between the boundaries.
//!
//! The oracles sit above what they check ([`crate::classify`](mod@crate::classify), [`crate::intersect`](mod@crate::intersect),
//! [`crate::shape`]) and below the formats; nothing but the command line and users' tests
//! imports them.
//!
//! # The shared matching
//! Float answers are taken in the caller's order; each takes the first exact value (in the exact
//! values' order) it is near and that no earlier float took. A float near only exact values
//! already taken is a **duplicate** (of the first of them), a float near none is **spurious**,
//! and an exact value no float took is **missed** (where the caller says it could have been
//! found). Floats in ascending order against exact values in ascending order, with windows of one
//! width, this matches as many as possible.

mod ball;
mod classify;
mod distance;
mod intersect;
mod matching;
mod shape;

pub use classify::{
    ClassificationDisagreement, FloatClassification, Tolerances, check_classification, compare_classification,
};
pub use intersect::{IntersectionDisagreement, check_intersections};
pub use matching::{DisagreementKind, FloatValue};
pub use shape::{Agreement, Witness, check_against};
