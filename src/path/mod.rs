//! Paths: [`ClosedPath`] (closed contours of polynomial and rational Bézier segments, exact),
//! their winding numbers around a point ([`ClosedPath::winding`]) and the fill rules that make
//! a region of them ([`FillRule`]).
//!
//! The storage layer of planar geometry, as `lyon_path` is lyon's: the arrangements and boolean
//! operations of [`crate::shape`], the formats that read outlines and the float oracles build
//! on it. It depends on [`crate::curve`], [`crate::rational`] and [`crate::poly`] only.
//!
//! # Winding numbers
//! The ray from `q` to the right is followed along each contour: on each segment the roots of
//! `Y(t) − q_y W(t)` on `[0, 1]` cut it into pieces of constant sign; a root whose point lies
//! right of `q` (compared exactly, as real algebraic numbers) counts `+1` when the sign goes
//! from negative to positive across it and `−1` the other way — a touch without crossing counts
//! nothing, a root shared by two segments (a joint) is one event, and a piece lying on the ray
//! counts by the signs before and after it. A root whose point is `q` itself means `q` is on
//! the path. No ray is perturbed and nothing is sampled.
//!
//! # Example
//! ```
//! use casteljau::path::{ClosedPath, FillRule, PathWinding};
//! use casteljau::{BezierCurve, num::{Point2, parse_points}, rat, ratio, work::Budget};
//! let seg = |s: &str| BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap();
//! // the lens between the parabola 0 0, 1 2, 2 0 and the chord back (clockwise)
//! let lens = ClosedPath::from_polynomial(vec![vec![seg("0 0, 1 2, 2 0"), seg("2 0, 0 0")]]).unwrap();
//! let at = |x, y| lens.winding(&Point2::new(x, y), &Budget::unlimited()).unwrap();
//! assert!(matches!(at(rat(1), ratio(1, 2)), PathWinding::Off(w) if w.winding() == -1 && w.inside(FillRule::NonZero)));
//! assert!(matches!(at(rat(1), rat(2)), PathWinding::Off(w) if w.winding() == 0));
//! assert!(matches!(at(rat(1), rat(1)), PathWinding::OnBoundary { on_boundary } if on_boundary.segment == 0));
//! ```

mod closed_path;
pub(crate) mod winding;

pub use closed_path::{BoundaryPoint, ClosedPath, FillRule, PathWinding, WindingNumber};

/// Most segments in one contour of a [`ClosedPath`].
pub(crate) const MAX_PATH_SEGMENTS: usize = 100_000;
