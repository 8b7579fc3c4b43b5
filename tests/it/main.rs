//! The integration tests, one crate of modules so that `cargo test` links the library once.
//!
//! Run one area with a filter: `cargo test --test it intersect::` (module paths prefix the test names).
//! Modules that run the binary need the `cli` feature; with `--no-default-features` the
//! library's own tests still run.

mod common;

#[cfg(feature = "cli")]
mod algebraic;
#[cfg(feature = "cli")]
mod budgets;
#[cfg(feature = "catalogue")]
mod catalogue;
mod classify;
#[cfg(feature = "cli")]
mod cli;
#[cfg(feature = "cli")]
mod cli_lint;
#[cfg(feature = "cli")]
mod cli_shapes;
#[cfg(feature = "cli")]
mod cli_spline;
#[cfg(feature = "cli")]
mod docs;
#[cfg(feature = "cli")]
mod exactness_regressions;
#[cfg(feature = "fonts")]
mod font_builder;
#[cfg(all(feature = "fonts", feature = "svg"))]
mod formats;
#[cfg(feature = "cli")]
mod fuzz;
#[cfg(feature = "cli")]
mod fuzz_formats;
#[cfg(feature = "cli")]
mod golden;
mod identity_8;
#[cfg(feature = "cli")]
mod intersect;
mod lint;
#[cfg(feature = "fonts")]
mod lint_fonts;
#[cfg(feature = "cli")]
mod lint_report;
#[cfg(feature = "cli")]
mod oracle;
#[cfg(feature = "fonts")]
mod overlaps;
mod parse_fuzz;
mod parse_numbers;
mod plot;
mod properties;
mod rational_bezier;
mod rational_cubic;
#[cfg(feature = "cli")]
mod readers;
#[cfg(feature = "cli")]
mod regions;
#[cfg(feature = "cli")]
mod remove_overlaps;
#[cfg(feature = "cli")]
mod robustness;
mod seed_examples;
mod shape_properties;
mod shapes;
mod spline_knots;
mod strategies;
mod surfaces_splines;
mod typed_results;
