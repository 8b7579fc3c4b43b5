//! The exact arrangement's data: its vertices, edges (each carrying the input pieces on it and
//! the winding numbers on both sides) and faces, as [`super::arrangement`] builds and queries them.
//! Kept apart so the building steps ([`super::build`]) and the queries share the types without
//! importing each other.

use super::segment::Seg;
use crate::poly::algebraic::RealAlgebraic;
use serde::Serialize;

/// Where a piece of an input lies: the input (0-based: `A` is 0, `B` is 1), the contour in it,
/// the segment in the contour, and the exact parameters `from` and `to` on the segment (`from >
/// to` when the piece runs backwards). JSON: `input`, `contour`, `segment`, `from`, `to` (exact
/// strings), `from_float`, `to_float`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct InputPiece {
    /// The input.
    pub input: usize,
    /// The contour within the input.
    pub contour: usize,
    /// The segment within the contour.
    pub segment: usize,
    /// Where the piece starts on the segment.
    #[serde(serialize_with = "crate::num::serial::string")]
    pub from: RealAlgebraic,
    /// Where it ends.
    #[serde(serialize_with = "crate::num::serial::string")]
    pub to: RealAlgebraic,
    /// `from`, correctly rounded.
    pub from_float: f64,
    /// `to`, correctly rounded.
    pub to_float: f64,
}

/// A vertex: an exact point where edges meet. JSON: `point` (exact strings: rationals, or real
/// algebraic numbers), `point_float`, `degree` (edge ends at it).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Vertex {
    /// The exact coordinates.
    #[serde(serialize_with = "crate::num::serial::strings")]
    pub point: Vec<RealAlgebraic>,
    /// The coordinates, correctly rounded.
    pub point_float: [f64; 2],
    /// The number of edge ends at the vertex.
    pub degree: usize,
}

/// An edge: a piece of an input segment between two vertices, with every input piece on it.
/// JSON: `from`, `to` (vertex indices), `pieces` (the first is the edge's own curve, in the
/// edge's direction; the others run along or against it), `winding_left`, `winding_right` (per
/// input, the winding number on each side).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Edge {
    /// The vertex it starts at.
    pub from: usize,
    /// The vertex it ends at.
    pub to: usize,
    /// The input pieces it carries.
    pub pieces: Vec<InputPiece>,
    /// Per input, the winding number just left of the edge.
    pub winding_left: Vec<i64>,
    /// Per input, the winding number just right of it.
    pub winding_right: Vec<i64>,
}

/// A side of an edge: the edge, and whether it is traversed forwards (its left side).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct HalfEdge {
    /// The edge.
    pub edge: usize,
    /// Traversed from `from` to `to` (the face is on its left).
    pub forward: bool,
}

/// A face: a connected component of the plane minus the edges. JSON: `bounded`, `outer` (the
/// outer boundary, half-edges with the face on their left; empty for the unbounded face),
/// `inner` (the boundaries of the components inside it), `winding` (per input).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Face {
    /// Whether the face is bounded.
    pub bounded: bool,
    /// The outer boundary (counter-clockwise).
    pub outer: Vec<HalfEdge>,
    /// The inner boundaries (clockwise).
    pub inner: Vec<Vec<HalfEdge>>,
    /// Per input, the winding number in the face.
    pub winding: Vec<i64>,
}

/// Where a point lies in an [`Arrangement`]. JSON: `{"vertex": i}`, `{"edge": i, "t": …,
/// "t_float": …}` (the parameter on the edge's first piece) or `{"face": i, "winding": […]}`.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Location {
    /// On a vertex.
    Vertex {
        /// The vertex.
        vertex: usize,
    },
    /// Inside an edge.
    Edge {
        /// The edge.
        edge: usize,
        /// The parameter on the edge's first piece's segment.
        #[serde(serialize_with = "crate::num::serial::string")]
        t: RealAlgebraic,
        /// `t`, correctly rounded.
        t_float: f64,
    },
    /// Inside a face.
    Face {
        /// The face (see [`Arrangement::faces`]).
        face: usize,
        /// Per input, the winding number there.
        winding: Vec<i64>,
    },
}

/// An internal edge: a piece of segment `seg` on `[lo, hi]` and what it carries.
#[derive(Clone, Debug)]
pub(crate) struct EdgeData {
    pub seg: usize,
    pub lo: RealAlgebraic,
    pub hi: RealAlgebraic,
    pub from: usize,
    pub to: usize,
    /// `(segment, lo, hi, forward)`.
    pub carriers: Vec<(usize, RealAlgebraic, RealAlgebraic, bool)>,
    pub left: Vec<i64>,
    pub right: Vec<i64>,
}

/// The exact arrangement of closed paths (see the module documentation).
///
/// # Example
/// ```
/// use casteljau::shape::{Arrangement, Location, Shape};
/// use casteljau::{num::Point2, rat};
/// // two unit squares side by side share the edge x = 1
/// let a: Shape = "M0 0 H1 V1 H0 Z".parse().unwrap();
/// let b: Shape = "M1 0 H2 V1 H1 Z".parse().unwrap();
/// let arr = Arrangement::new(&[a, b], &casteljau::work::Budget::unlimited()).unwrap();
/// assert_eq!(arr.vertices().len(), 6);
/// assert_eq!(arr.edges().len(), 7); // the shared edge is one edge carrying two pieces
/// let shared = arr.edges().into_iter().find(|e| e.pieces.len() == 2).unwrap();
/// assert_eq!((shared.winding_left.clone(), shared.winding_right.clone()), (vec![1, 0], vec![0, 1]));
/// let p = Point2::new;
/// let faces = arr.faces().unwrap();
/// assert_eq!(faces.len(), 3); // two squares and the outside
/// let Location::Face { winding, .. } = arr.locate(&p(rat(3) / rat(2), rat(1) / rat(2))).unwrap() else { panic!() };
/// assert_eq!(winding, vec![0, 1]);
/// assert!(matches!(arr.locate(&p(rat(1), rat(0))).unwrap(), Location::Vertex { .. }));
/// ```
#[derive(Clone, Debug)]
pub struct Arrangement {
    pub(crate) segs: Vec<std::sync::Arc<Seg>>,
    pub(crate) inputs: usize,
    /// Per input, per contour, the segment indices.
    pub(crate) contours: Vec<Vec<Vec<usize>>>,
    pub(crate) edges: Vec<EdgeData>,
    /// Per vertex, a representative `(segment, parameter)`.
    pub(crate) vertex_at: Vec<(usize, RealAlgebraic)>,
    pub(crate) degree: Vec<usize>,
    /// The faces and, per bounded face, how many outer boundaries enclose it, once computed.
    pub(super) faces: std::sync::OnceLock<(Vec<Face>, Vec<usize>)>,
}
