//! Finite output or a refusal: an exact answer whose float picture overflows `f64` (a coordinate
//! of `1e400`, an SVG `scale(1e300) scale(1e300)`, an area of `10⁶⁰⁰`) is refused (exit 2) with
//! the field or the number that overflowed, rather than printed with `inf`, `NaN` or a JSON
//! `null` in a float field. The exact numbers are never the problem: only their rounded copies
//! (`*_float` fields, SVG path data, drawings).

use casteljau::error::{Error, Result};
use serde::ser::{self, Serialize};
use std::fmt;

/// The first float of `value` (as its `Serialize` writes it) that is not finite, named by its
/// path (`vertices[4].point_float[0]`); `None` when every float is finite.
pub(crate) fn first_non_finite(value: &impl Serialize) -> Option<String> {
    let mut finder = Finder { path: vec![] };
    match value.serialize(&mut finder) {
        Err(Found(Some(path))) => Some(path),
        _ => None,
    }
}

/// `Ok` when every float of `value` is finite; else the refusal naming `what` and the field.
pub(crate) fn check(what: &str, value: &impl Serialize) -> Result<()> {
    match first_non_finite(value) {
        None => Ok(()),
        Some(field) => Err(overflow(what, &format!("the float field {field}"))),
    }
}

/// `Ok` when `text` (a rendered answer, path data, a drawing) has no `inf` or `NaN` token;
/// else the refusal naming `what`.
pub(crate) fn check_text(what: &str, text: &str) -> Result<()> {
    match non_finite_token(text) {
        None => Ok(()),
        // (the message itself never spells the token: it is output too)
        Some(_) => Err(overflow(what, "a rounded number")),
    }
}

/// The first `inf` (or `-inf`) or `NaN` as Rust writes a float that is not finite, in text or
/// in SVG path data (`M0 0Linf 0`): the letters not followed by a letter or digit, nor preceded
/// by a lower-case letter (so `inflection` and `Delinf` do not count, `Linf` does).
pub(crate) fn non_finite_token(text: &str) -> Option<&'static str> {
    let bytes = text.as_bytes();
    for (word, name) in [("inf", "inf"), ("NaN", "NaN")] {
        for (i, _) in text.match_indices(word) {
            let before = i.checked_sub(1).map(|j| bytes[j]);
            let after = bytes.get(i + word.len()).copied();
            if !before.is_some_and(|b| b.is_ascii_lowercase())
                && !after.is_some_and(|b| b.is_ascii_alphanumeric() || b == b'_')
            {
                return Some(name);
            }
        }
    }
    None
}

/// `Ok` when every coordinate of the contours rounds to a finite `f64` (so that their drawing
/// and the float fields of what is found on them can be written); else the refusal naming the
/// first coordinate that does not, by contour and segment.
pub(crate) fn check_contours(contours: &[casteljau::format::Contour]) -> Result<()> {
    use casteljau::format::Segment;
    for (c, contour) in contours.iter().enumerate() {
        for (k, s) in contour.segments.iter().enumerate() {
            let points: Vec<&casteljau::Point<num_rational::BigRational>> = match s {
                Segment::Bezier(ps) => ps.iter().collect(),
                Segment::Skipped { from, to, .. } => vec![from, to],
            };
            for p in points {
                if let Some(x) = p.coords.iter().find(|x| !casteljau::num::ratio_to_f64(x).is_finite()) {
                    let digits = x.to_integer().to_string().len();
                    return Err(overflow(
                        &format!("contour {c}, segment {k}"),
                        &format!("a coordinate of about {digits} digits"),
                    ));
                }
            }
        }
    }
    Ok(())
}

/// The refusal: what could not be written, and why.
pub(crate) fn overflow(what: &str, detail: &str) -> Error {
    Error::InvalidArgument {
        message: format!(
            "{what}: {detail} is beyond the f64 range (the exact answer has no finite float picture; scale the input down)"
        ),
    }
}

/// What stops the walk: the path of a non-finite float, or a serializer's own message.
#[derive(Debug)]
struct Found(Option<String>);

impl fmt::Display for Found {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?}", self.0)
    }
}

impl std::error::Error for Found {}

impl ser::Error for Found {
    fn custom<T: fmt::Display>(_: T) -> Self {
        Found(None)
    }
}

/// A serializer that writes nothing and stops at the first non-finite float.
struct Finder {
    path: Vec<String>,
}

impl Finder {
    fn float(&self, v: f64) -> std::result::Result<(), Found> {
        if v.is_finite() { Ok(()) } else { Err(Found(Some(self.here()))) }
    }

    fn here(&self) -> String {
        let mut s = String::new();
        for p in &self.path {
            if !p.starts_with('[') && !s.is_empty() {
                s.push('.');
            }
            s.push_str(p);
        }
        if s.is_empty() { "the value".into() } else { format!("`{s}`") }
    }

    fn nested<T: ?Sized + Serialize>(&mut self, key: String, value: &T) -> std::result::Result<(), Found> {
        self.path.push(key);
        value.serialize(&mut *self)?;
        self.path.pop();
        Ok(())
    }
}

/// Counts the elements of a sequence for their `[i]` in the path (a map's values go by their
/// key when it is a string).
struct Seq<'a> {
    finder: &'a mut Finder,
    index: usize,
    key: Option<String>,
}

impl Seq<'_> {
    fn element<T: ?Sized + Serialize>(&mut self, value: &T) -> std::result::Result<(), Found> {
        let key = format!("[{}]", self.index);
        self.index += 1;
        self.finder.nested(key, value)
    }
}

type Res = std::result::Result<(), Found>;

impl<'a> ser::Serializer for &'a mut Finder {
    type Ok = ();
    type Error = Found;
    type SerializeSeq = Seq<'a>;
    type SerializeTuple = Seq<'a>;
    type SerializeTupleStruct = Seq<'a>;
    type SerializeTupleVariant = Seq<'a>;
    type SerializeMap = Seq<'a>;
    type SerializeStruct = Seq<'a>;
    type SerializeStructVariant = Seq<'a>;

    fn serialize_bool(self, _: bool) -> Res {
        Ok(())
    }
    fn serialize_i8(self, _: i8) -> Res {
        Ok(())
    }
    fn serialize_i16(self, _: i16) -> Res {
        Ok(())
    }
    fn serialize_i32(self, _: i32) -> Res {
        Ok(())
    }
    fn serialize_i64(self, _: i64) -> Res {
        Ok(())
    }
    fn serialize_u8(self, _: u8) -> Res {
        Ok(())
    }
    fn serialize_u16(self, _: u16) -> Res {
        Ok(())
    }
    fn serialize_u32(self, _: u32) -> Res {
        Ok(())
    }
    fn serialize_u64(self, _: u64) -> Res {
        Ok(())
    }
    fn serialize_f32(self, v: f32) -> Res {
        self.float(f64::from(v))
    }
    fn serialize_f64(self, v: f64) -> Res {
        self.float(v)
    }
    fn serialize_char(self, _: char) -> Res {
        Ok(())
    }
    fn serialize_str(self, _: &str) -> Res {
        Ok(())
    }
    fn serialize_bytes(self, _: &[u8]) -> Res {
        Ok(())
    }
    fn serialize_none(self) -> Res {
        Ok(())
    }
    fn serialize_some<T: ?Sized + Serialize>(self, value: &T) -> Res {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Res {
        Ok(())
    }
    fn serialize_unit_struct(self, _: &'static str) -> Res {
        Ok(())
    }
    fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> Res {
        Ok(())
    }
    fn serialize_newtype_struct<T: ?Sized + Serialize>(self, _: &'static str, value: &T) -> Res {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        value: &T,
    ) -> Res {
        self.nested(variant.to_string(), value)
    }
    fn serialize_seq(self, _: Option<usize>) -> std::result::Result<Seq<'a>, Found> {
        Ok(Seq { finder: self, index: 0, key: None })
    }
    fn serialize_tuple(self, _: usize) -> std::result::Result<Seq<'a>, Found> {
        Ok(Seq { finder: self, index: 0, key: None })
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> std::result::Result<Seq<'a>, Found> {
        Ok(Seq { finder: self, index: 0, key: None })
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> std::result::Result<Seq<'a>, Found> {
        Ok(Seq { finder: self, index: 0, key: None })
    }
    fn serialize_map(self, _: Option<usize>) -> std::result::Result<Seq<'a>, Found> {
        Ok(Seq { finder: self, index: 0, key: None })
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> std::result::Result<Seq<'a>, Found> {
        Ok(Seq { finder: self, index: 0, key: None })
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> std::result::Result<Seq<'a>, Found> {
        Ok(Seq { finder: self, index: 0, key: None })
    }
    fn collect_str<T: ?Sized + fmt::Display>(self, _: &T) -> Res {
        // exact numbers are written through Display: nothing to check, nothing to format
        Ok(())
    }
}

impl ser::SerializeSeq for Seq<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_element<T: ?Sized + Serialize>(&mut self, value: &T) -> Res {
        self.element(value)
    }
    fn end(self) -> Res {
        Ok(())
    }
}

impl ser::SerializeTuple for Seq<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_element<T: ?Sized + Serialize>(&mut self, value: &T) -> Res {
        self.element(value)
    }
    fn end(self) -> Res {
        Ok(())
    }
}

impl ser::SerializeTupleStruct for Seq<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, value: &T) -> Res {
        self.element(value)
    }
    fn end(self) -> Res {
        Ok(())
    }
}

impl ser::SerializeTupleVariant for Seq<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, value: &T) -> Res {
        self.element(value)
    }
    fn end(self) -> Res {
        Ok(())
    }
}

impl ser::SerializeMap for Seq<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_key<T: ?Sized + Serialize>(&mut self, key: &T) -> Res {
        self.key = serde_json::to_value(key).ok().and_then(|k| k.as_str().map(String::from));
        Ok(())
    }
    fn serialize_value<T: ?Sized + Serialize>(&mut self, value: &T) -> Res {
        match self.key.take() {
            Some(key) => self.finder.nested(key, value),
            None => self.element(value),
        }
    }
    fn end(self) -> Res {
        Ok(())
    }
}

impl ser::SerializeStruct for Seq<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, key: &'static str, value: &T) -> Res {
        self.finder.nested(key.to_string(), value)
    }
    fn end(self) -> Res {
        Ok(())
    }
}

impl ser::SerializeStructVariant for Seq<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, key: &'static str, value: &T) -> Res {
        self.finder.nested(key.to_string(), value)
    }
    fn end(self) -> Res {
        Ok(())
    }
}
