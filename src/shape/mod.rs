//! Shapes: closed paths under a fill rule, their exact arrangement, and boolean operations.
//!
//! A [`Shape`] is a set of closed contours of planar polynomial or rational Bézier segments (a
//! [`ClosedPath`]); SVG path data parses into one (`"M0 0 H1 V1 Z".parse::<Shape>()`, open
//! subpaths closed by a line as SVG fills them). The [`Arrangement`] of several shapes cuts every
//! segment at every point where it meets any segment (its own contour included), merges shared
//! arcs into one edge that records each input piece on it, and knows, for every edge, each
//! input's winding number on both sides: from it come the faces with their winding numbers,
//! exact point location, and the [`boolean`] operations. Nothing is rounded: vertices are exact
//! algebraic points, edges are segments on exact parameter intervals, and every decision —
//! which side, which order around a vertex, inside or out — is an exact sign.
//!
//! Zero-length segments (every control point the same) are kept in the numbering and ignored
//! for the region.
//!
//! # Example
//! ```
//! use casteljau::shape::{boolean, BooleanOp, BooleanOptions, Shape};
//! // a figure-eight: under non-zero both lobes are filled, under even-odd too; simplify gives two contours
//! let eight: Shape = "M0 0 L2 2 L2 0 L0 2 Z".parse().unwrap();
//! let r = boolean(BooleanOp::Simplify, &[eight], BooleanOptions::default(), &casteljau::work::Budget::unlimited()).unwrap();
//! assert_eq!(r.contours, 2);
//! assert_eq!(r.area.unwrap().to_string(), "2");
//! ```

mod area;
pub(crate) mod arrangement;
mod boolean;
mod build;
mod changed;
mod estimate;
mod germ;
pub(crate) mod graph;
mod hermite;
pub(crate) mod pairs;
mod ray;
mod render;
mod runs;
pub(crate) mod segment;

pub(crate) use boolean::ExactRun;
pub use boolean::{BooleanOp, BooleanOptions, BooleanResult, Orientation, boolean};
pub use graph::{Arrangement, Edge, Face, HalfEdge, InputPiece, Location, Vertex};

use crate::error::Result;
use crate::num::point::Point2;
use crate::path::ClosedPath;
use crate::rational::RationalBezier;
use num_rational::BigRational;

/// A filled shape: closed contours of planar Bézier segments (see [`ClosedPath`]).
///
/// # Example
/// ```
/// use casteljau::shape::Shape;
/// let s: Shape = "M0 0 Q1 2 2 0 Z".parse().unwrap();
/// assert_eq!(s.path().contours().len(), 1);
/// assert_eq!(s.path().segments(), 2); // the quadratic and the closing line
/// assert!("M0 0 L1 x".parse::<Shape>().is_err());
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Shape {
    path: ClosedPath,
}

impl Shape {
    /// The shape filled by a closed path.
    ///
    /// # Example
    /// ```
    /// use casteljau::format::fill_path;
    /// use casteljau::num::NumberMode;
    /// use casteljau::shape::Shape;
    /// let s = Shape::new(fill_path("M0 0 L1 0 L0 1", NumberMode::Exact).unwrap()); // closed for fill
    /// assert_eq!(s, "M0 0 L1 0 L0 1 Z".parse().unwrap());
    /// ```
    pub fn new(path: ClosedPath) -> Self {
        Shape { path }
    }

    /// The shape of closed contours of (rational) segments.
    ///
    /// # Errors
    /// As [`ClosedPath::new`].
    ///
    /// # Example
    /// ```
    /// use casteljau::shape::Shape;
    /// use casteljau::{Point, RationalBezier, rat};
    /// let p = |x: i64, y: i64| Point::new(vec![rat(x), rat(y)]);
    /// let line = |a, b| RationalBezier::new(vec![a, b], vec![rat(1), rat(1)]).unwrap();
    /// // a quarter disc: the arc x² + y² = 1 and two radii
    /// let arc = RationalBezier::new(vec![p(1, 0), p(1, 1), p(0, 1)], vec![rat(1), rat(1), rat(2)]).unwrap();
    /// let s = Shape::from_contours(vec![vec![arc, line(p(0, 1), p(0, 0)), line(p(0, 0), p(1, 0))]]).unwrap();
    /// assert_eq!(s.path().segments(), 3);
    /// ```
    pub fn from_contours(contours: Vec<Vec<RationalBezier<BigRational>>>) -> Result<Self> {
        Ok(Shape { path: ClosedPath::new(contours)? })
    }

    /// The shape of closed polygons (each a list of vertices; the closing side is implied).
    ///
    /// # Errors
    /// [`crate::Error::InvalidArgument`] for a polygon of fewer than two vertices.
    ///
    /// # Example
    /// ```
    /// use casteljau::shape::Shape;
    /// use casteljau::{num::Point2, rat};
    /// let p = |x: i64, y: i64| Point2::new(rat(x), rat(y));
    /// let s = Shape::polygons(vec![vec![p(0, 0), p(1, 0), p(0, 1)]]).unwrap();
    /// assert_eq!(s.path().segments(), 3);
    /// ```
    pub fn polygons(polygons: Vec<Vec<Point2<BigRational>>>) -> Result<Self> {
        let one = || crate::num::scalar::rat(1);
        let mut contours = vec![];
        for poly in polygons {
            if poly.len() < 2 {
                return Err(crate::Error::InvalidArgument {
                    message: format!("a polygon needs at least two vertices, not {}", poly.len()),
                });
            }
            let n = poly.len();
            contours.push(
                (0..n)
                    .map(|i| {
                        let (a, b) = (poly[i].clone().into(), poly[(i + 1) % n].clone().into());
                        RationalBezier::new(vec![a, b], vec![one(), one()])
                    })
                    .collect::<Result<Vec<_>>>()?,
            );
        }
        Self::from_contours(contours)
    }

    /// The closed path.
    ///
    /// # Example
    /// ```
    /// use casteljau::shape::Shape;
    /// let s: Shape = "M0 0 H2 V2 H0 Z M5 5 H6 V6 Z".parse().unwrap();
    /// assert_eq!(s.path().contours().len(), 2);
    /// ```
    pub fn path(&self) -> &ClosedPath {
        &self.path
    }
}
