//! Points and vectors of any dimension over a [`Scalar`], and homogeneous coordinates.

use crate::error::{Error, Result};
use crate::num::scalar::Scalar;
use std::fmt;

/// A point (or vector) with coordinates in `S`.
///
/// Homogeneous form: the point `p` with weight `w` is `(w·p, w)`; a homogeneous point with
/// last coordinate `0` is a point at infinity (a direction).
///
/// # Example
/// ```
/// use casteljau::{Point, ratio};
/// let p = Point::new(vec![ratio(1, 2), ratio(3, 1)]);
/// let h = p.to_homogeneous(&ratio(2, 1));
/// assert_eq!(h.to_string(), "(1, 6, 2)");
/// assert_eq!(h.from_homogeneous(), Some(p));
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Point<S> {
    /// The coordinates, `x, y[, z, …]`.
    pub coords: Vec<S>,
}

impl<S: Scalar> Point<S> {
    /// A point from its coordinates.
    pub fn new(coords: Vec<S>) -> Self {
        Point { coords }
    }
    /// The origin of dimension `dim`.
    pub fn origin(dim: usize) -> Self {
        Point { coords: vec![S::zero(); dim] }
    }
    /// The number of coordinates.
    pub fn dim(&self) -> usize {
        self.coords.len()
    }
    /// `self + other`, coordinate-wise. **Panics** if dimensions differ.
    pub fn add(&self, other: &Self) -> Self {
        self.zip(other, |a, b| a.clone() + b)
    }
    /// `self − other`, coordinate-wise. **Panics** if dimensions differ.
    pub fn sub(&self, other: &Self) -> Self {
        self.zip(other, |a, b| a.clone() - b)
    }
    /// `s · self`.
    pub fn scale(&self, s: &S) -> Self {
        Point { coords: self.coords.iter().map(|c| c.clone() * s).collect() }
    }
    /// The affine combination `(1 − t)·self + t·other`. **Panics** if dimensions differ.
    pub fn lerp(&self, other: &Self, t: &S) -> Self {
        let u = S::one() - t;
        self.zip(other, |a, b| u.clone() * a + t.clone() * b)
    }
    /// The dot product `Σ aᵢbᵢ`. **Panics** if dimensions differ.
    pub fn dot(&self, other: &Self) -> S {
        self.coords.iter().zip(&other.coords).fold(S::zero(), |acc, (a, b)| acc + a.clone() * b)
    }
    /// The cross product of two 3-vectors (for homogeneous 2D points: the line through them,
    /// or the meet of two lines).
    ///
    /// # Errors
    /// [`Error::DimensionMismatch`] unless both are 3-dimensional.
    pub fn cross(&self, other: &Self) -> Result<Self> {
        if self.dim() != 3 || other.dim() != 3 {
            return Err(Error::DimensionMismatch { expected: 3, found: self.dim().max(other.dim()) });
        }
        let (a, b) = (&self.coords, &other.coords);
        Ok(Point::new(vec![
            a[1].clone() * &b[2] - a[2].clone() * &b[1],
            a[2].clone() * &b[0] - a[0].clone() * &b[2],
            a[0].clone() * &b[1] - a[1].clone() * &b[0],
        ]))
    }
    /// Homogeneous coordinates `(w·x, w·y, …, w)`.
    pub fn to_homogeneous(&self, w: &S) -> Self {
        let mut coords: Vec<S> = self.coords.iter().map(|c| c.clone() * w).collect();
        coords.push(w.clone());
        Point { coords }
    }
    /// The affine point of homogeneous coordinates, or `None` for a point at infinity (`w = 0`).
    pub fn from_homogeneous(&self) -> Option<Self> {
        let (w, rest) = self.coords.split_last()?;
        if w.is_zero() {
            return None;
        }
        Some(Point { coords: rest.iter().map(|c| c.clone() / w).collect() })
    }
    /// The point with coordinates converted to `f64`.
    pub fn to_f64(&self) -> Point<f64> {
        Point { coords: self.coords.iter().map(S::to_f64).collect() }
    }

    fn zip(&self, other: &Self, f: impl Fn(&S, &S) -> S) -> Self {
        assert_eq!(self.dim(), other.dim(), "point dimensions differ");
        Point { coords: self.coords.iter().zip(&other.coords).map(|(a, b)| f(a, b)).collect() }
    }
}

impl<S: fmt::Display> fmt::Display for Point<S> {
    /// `(x, y)` with each coordinate in its exact form.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "(")?;
        for (i, c) in self.coords.iter().enumerate() {
            if i > 0 {
                write!(f, ", ")?;
            }
            write!(f, "{c}")?;
        }
        write!(f, ")")
    }
}

/// A point (or vector) of the plane, `(x, y)`, with coordinates in `S`.
///
/// Planar code takes and returns `Point2`: the query points of winding numbers
/// ([`crate::path::ClosedPath::winding`]), of arrangements and of boolean results, and the
/// points of the float oracles. Unlike [`Point`] it cannot have the wrong dimension, so those
/// APIs have no dimension error. Curves keep [`Point`], as they have any dimension;
/// `Point2::try_from` converts (refusing a point that is not planar) and `Point::from` back.
///
/// `Copy` when `S` is (`Point2<f64>`). Serializes as [`Point`] does: an array of two exact
/// strings.
///
/// # Example
/// ```
/// use casteljau::{Point, num::Point2, rat, ratio};
/// let p = Point2::new(ratio(1, 2), rat(3));
/// assert_eq!(p.to_string(), "(1/2, 3)");
/// assert_eq!(Point::from(p.clone()), Point::new(vec![ratio(1, 2), rat(3)]));
/// assert_eq!(Point2::try_from(&Point::new(vec![ratio(1, 2), rat(3)])).unwrap(), p);
/// assert!(Point2::try_from(&Point::new(vec![rat(1), rat(2), rat(3)])).is_err());
/// assert_eq!(p.to_f64(), Point2::new(0.5, 3.0));
/// assert_eq!(serde_json::to_string(&p).unwrap(), r#"["1/2","3"]"#);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Point2<S> {
    /// The first coordinate.
    pub x: S,
    /// The second coordinate.
    pub y: S,
}

impl<S> Point2<S> {
    /// The point `(x, y)`.
    pub fn new(x: S, y: S) -> Self {
        Point2 { x, y }
    }
}

impl<S: Scalar> Point2<S> {
    /// The point with coordinates converted to `f64`.
    pub fn to_f64(&self) -> Point2<f64> {
        Point2 { x: self.x.to_f64(), y: self.y.to_f64() }
    }

    /// `self − other`.
    pub fn sub(&self, other: &Self) -> Self {
        Point2 { x: self.x.clone() - &other.x, y: self.y.clone() - &other.y }
    }

    /// The cross product `self.x·other.y − self.y·other.x` (twice the signed area of the
    /// triangle `0, self, other`).
    pub fn cross(&self, other: &Self) -> S {
        self.x.clone() * &other.y - self.y.clone() * &other.x
    }
}

impl<S> From<[S; 2]> for Point2<S> {
    fn from([x, y]: [S; 2]) -> Self {
        Point2 { x, y }
    }
}

impl<S> From<Point2<S>> for [S; 2] {
    fn from(p: Point2<S>) -> Self {
        [p.x, p.y]
    }
}

impl<S: Scalar> From<Point2<S>> for Point<S> {
    fn from(p: Point2<S>) -> Self {
        Point::new(vec![p.x, p.y])
    }
}

impl<S: Scalar> TryFrom<&Point<S>> for Point2<S> {
    type Error = Error;
    /// The planar point of a [`Point`] of dimension 2.
    ///
    /// # Errors
    /// [`Error::DimensionMismatch`] for any other dimension.
    fn try_from(p: &Point<S>) -> Result<Self> {
        match p.coords.as_slice() {
            [x, y] => Ok(Point2 { x: x.clone(), y: y.clone() }),
            c => Err(Error::DimensionMismatch { expected: 2, found: c.len() }),
        }
    }
}

impl<S: fmt::Display> fmt::Display for Point2<S> {
    /// `(x, y)` with each coordinate in its exact form.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {})", self.x, self.y)
    }
}
