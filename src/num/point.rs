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
