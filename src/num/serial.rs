//! Exact numbers in JSON: always strings (`"1/3"`, `"1/2 + 1/6*sqrt(5)"`), never floats, so
//! that a result's `Serialize` derive is its JSON schema. Use the functions with
//! `#[serde(serialize_with = "…")]`; [`Point`] and [`QuadraticExt`] serialize this way on their
//! own (a point as an array of strings).
//!
//! # Example
//! ```
//! use casteljau::{Point, QuadraticExt, rat, ratio};
//! let p = Point::new(vec![ratio(1, 3), rat(2)]);
//! assert_eq!(serde_json::to_string(&p).unwrap(), r#"["1/3","2"]"#);
//! let x = QuadraticExt::new(ratio(1, 2), ratio(1, 6), rat(5));
//! assert_eq!(serde_json::to_string(&x).unwrap(), r#""1/2 + 1/6*sqrt(5)""#);
//! ```

use crate::num::point::{Point, Point2};
use crate::num::quadratic_field::QuadraticExt;
use crate::num::scalar::{Exact, Scalar};
use serde::Serialize;
use serde::ser::{SerializeSeq, Serializer};
use std::fmt::Display;

/// One exact number as a string.
///
/// # Errors
/// Only the serializer's own.
pub fn string<T: Display, S: Serializer>(value: &T, s: S) -> Result<S::Ok, S::Error> {
    s.collect_str(value)
}

/// A list of exact numbers as strings.
///
/// # Errors
/// Only the serializer's own.
pub fn strings<T: Display, S: Serializer>(values: &[T], s: S) -> Result<S::Ok, S::Error> {
    let mut seq = s.serialize_seq(Some(values.len()))?;
    for v in values {
        seq.serialize_element(&AsString(v))?;
    }
    seq.end()
}

/// A value serialized as the string its `Display` writes (no intermediate `String`).
pub(crate) struct AsString<'a, T>(pub &'a T);

impl<T: Display> Serialize for AsString<'_, T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self.0)
    }
}

/// An optional exact number: a string, or `null`.
///
/// # Errors
/// Only the serializer's own.
pub(crate) fn option_string<T: Display, S: Serializer>(value: &Option<T>, s: S) -> Result<S::Ok, S::Error> {
    match value {
        Some(v) => s.collect_str(v),
        None => s.serialize_none(),
    }
}

impl<S: Scalar> Serialize for Point<S> {
    /// An array of exact strings, one per coordinate.
    fn serialize<Z: Serializer>(&self, s: Z) -> Result<Z::Ok, Z::Error> {
        strings(&self.coords, s)
    }
}

impl<S: Scalar> Serialize for Point2<S> {
    /// An array of two exact strings.
    fn serialize<Z: Serializer>(&self, s: Z) -> Result<Z::Ok, Z::Error> {
        strings(&[&self.x, &self.y], s)
    }
}

impl<K: Exact> Serialize for QuadraticExt<K> {
    /// The exact string `a`, `b*sqrt(d)` or `a + b*sqrt(d)`.
    fn serialize<Z: Serializer>(&self, s: Z) -> Result<Z::Ok, Z::Error> {
        s.collect_str(self)
    }
}
