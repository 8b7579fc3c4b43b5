//! # casteljau — Bézier-curve theory in exact arithmetic
//!
//! casteljau is an oracle for floating-point geometry code and a checker for CAGD theory: the
//! same generic algorithms run over `f64` (fast, approximate) and over exact rationals
//! ([`BigRational`](num_rational::BigRational)) or exact quadratic extensions
//! ([`QuadraticExt`]), so answers are exact and identities are *proved* by exact testing.
//!
//! The folders are the layers; each imports only the ones above it in this list:
//!
//! * [`num`]: the [`Scalar`] field trait and the [`Exact`] marker, [`Rational`], exact `K(√d)`
//!   ([`QuadraticExt`]), [`Point`]s, exact numbers from text.
//! * [`poly`]: the Bernstein basis, power ↔ Bernstein conversion, exact polynomial arithmetic
//!   (gcd, square-free part, quadratic roots) and exact real root isolation.
//! * [`proof`]: the grid prover (polynomial identities proved by exact testing) and the exact
//!   expression language of the claim files.
//! * [`curve`]: [`BezierCurve`], de Casteljau's scheme and subdivision, the fraction-free
//!   exact kernels.
//! * [`rational`], [`surface`], [`spline`]: rational curves ([`RationalBezier`]), Menelaus
//!   configurations and implicit equations; rational tensor-product patches; rational splines
//!   and spline nets.
//! * [`classify`](mod@classify): exact cubic classification, the certified fast path, moving lines,
//!   canonical forms, rational cubics.
//! * [`intersect`](mod@intersect), [`path`]: exact intersections; closed paths, their winding
//!   numbers and fill rules.
//! * [`shape`]: arrangements of closed paths and boolean operations.
//! * [`oracle`]: float libraries' answers (classifications, intersections, boolean
//!   operations) decided against the exact ones.
//! * [`format`](mod@format): fonts, SVG and path data read exactly (the edge of the library).
//! * [`lint`]: outline QA findings decided exactly, from the shapes and curves below.
//! * [`overlaps`]: overlap removal that writes the font, its rounding to the grid certified.
//! * [`catalogue`]: the `proofs/` claim files and their exact checks.
//! * [`plot`]: deterministic SVG figures and the seed gallery.
//!
//! [`error`] and [`work`] (cost estimates checked before exact work starts) are shared by all.
//! The command line lives in `src/bin/casteljau/` and is not part of the library.
//!
//! ```
//! use casteljau::{BezierCurve, parse_points, ratio};
//! let c = BezierCurve::new(parse_points("-1 -1, -1/3 1, 1/3 -1, 1 1", 2, None).unwrap()).unwrap();
//! let (left, right) = c.subdivide(&ratio(1, 3)); // fraction-free over BigRational
//! assert_eq!(left.to_string(), "-1 -1, -7/9 -1/3, -5/9 -1/9, -1/3 -1/27");
//! assert_eq!(right.to_string(), "-1/3 -1/27, 1/9 1/9, 5/9 -1/3, 1 1");
//! ```

#[cfg(feature = "catalogue")]
pub mod catalogue;
pub mod classify;
pub mod curve;
pub mod error;
pub mod format;
#[doc(hidden)]
pub mod internal;
pub mod intersect;
pub mod lint;
pub mod num;
pub mod oracle;
#[cfg(feature = "fonts")]
pub mod overlaps;
pub mod path;
pub mod plot;
pub mod poly;
pub mod proof;
pub mod rational;
pub mod shape;
pub mod spline;
#[cfg(feature = "proptest")]
pub mod strategies;
pub mod surface;
pub mod work;

pub use classify::{Classification, NodeType, SegmentFlag, classify};
pub use curve::{BezierCurve, DeCasteljauTriangle};
pub use error::{Error, Position, Result};
pub use intersect::{Domain, Intersection, Intersections, Overlap, intersect, self_intersect};
pub use num::{Exact, Point, QuadraticExt, Rational, Scalar, parse_points, rat, ratio};
pub use path::{ClosedPath, FillRule};
pub use poly::RealAlgebraic;
pub use rational::{BoundingBox, RationalBezier, bounding_box};
pub use spline::RationalSpline;
pub use surface::RationalPatch;
pub use work::Budget;
