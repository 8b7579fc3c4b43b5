//! The integration tests, one crate of modules so that `cargo test` links the library once.
//!
//! Run one area with a filter: `cargo test --test it intersect::` (module paths prefix the test names).

mod common;

mod algebraic;
mod catalogue;
mod classify;
mod cli;
mod cli_spline;
mod exactness_regressions;
mod formats;
mod fuzz;
mod golden;
mod identity_8;
mod intersect;
mod oracle;
mod parse_fuzz;
mod parse_numbers;
mod plot;
mod properties;
mod rational_bezier;
mod rational_cubic;
mod robustness;
mod seed_examples;
mod spline_knots;
mod strategies;
mod surfaces_splines;
mod typed_results;
