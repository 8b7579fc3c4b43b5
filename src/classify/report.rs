//! Classifying a curve written as text, by the fastest exact route that answers what was asked
//! (one place chooses the route): [`ClassifyOptions::write_json_direct`] for planar cubics in
//! fixed-width integers straight to JSON, then [`ClassifyOptions::classify_text`] in fixed-width
//! rationals when every step fits ([`crate::num::checked`]), else in big rationals. The
//! cubic's evidence ([`crate::classify::evidence`]) is always computed in big rationals.
//!
//! ```
//! use casteljau::classify::{Classified, ClassifyOptions};
//! let opts = ClassifyOptions { dim: 2, ..ClassifyOptions::default() };
//! let mut out = vec![];
//! assert!(opts.write_json_direct("0 0, 3 3, 0 3, 3 0", &mut out));
//! assert!(String::from_utf8(out).unwrap().contains(r#""node_type":"cusp""#));
//! match opts.classify_text("0 0, 3 3, 0 3, 3 0", None).unwrap() {
//!     Classified::Fixed(r) => assert_eq!(r.classification.cusp_parameters[0].to_string(), "1/2"),
//!     Classified::Exact(_) => unreachable!("small integers take the fixed-width route"),
//! }
//! ```

use crate::classify::evidence::{CubicEvidence, cubic_evidence};
use crate::classify::{Classification, Parameter, classify_in};
use crate::curve::bezier::BezierCurve;
use crate::error::Result;
use crate::num::parse::{NumberMode, integer_cubic, parse_points_in, parse_points_small_in, small_cubic};
use crate::num::quadratic_field::Radical;
use crate::num::scalar::Scalar;
use crate::num::small::{SmallRational, checked};
use num_rational::BigRational;
use serde::Serialize;

/// What `classify` is asked for, which decides its route.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ClassifyOptions {
    /// Coordinates per control point (classification needs 2; others are an error).
    pub dim: usize,
    /// How numbers in the text are read.
    pub mode: NumberMode,
    /// Also the cubic's evidence (big rationals only).
    pub evidence: bool,
    /// Also the nearest `f64`s of the exact answers.
    pub float: bool,
}

impl Default for ClassifyOptions {
    /// Planar, exact numbers, no evidence, no floats.
    fn default() -> Self {
        ClassifyOptions { dim: 2, mode: NumberMode::Exact, evidence: false, float: false }
    }
}

/// A classification with what else was asked for; serializes flat: the
/// [`Classification`]'s fields, the [`CubicEvidence`]'s and `float`.
#[derive(Clone, Debug, Serialize)]
#[serde(bound(serialize = "K: Radical"))]
pub struct ClassifyReport<K> {
    /// The exact classification.
    #[serde(flatten)]
    pub classification: Classification<K>,
    /// The cubic's evidence, when asked for and the curve is a genuine cubic.
    #[serde(flatten)]
    pub evidence: Option<CubicEvidence>,
    /// Nearest `f64`s, when asked for.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub float: Option<FloatApproximations>,
}

/// The nearest `f64`s of a classification's exact answers.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FloatApproximations {
    /// Of the double-point parameters.
    pub double_point_parameters: Vec<f64>,
    /// Of the cusp parameters.
    pub cusp_parameters: Vec<f64>,
    /// Of the inflection parameters.
    pub inflection_parameters: Vec<f64>,
    /// Of the double point.
    pub double_point: Option<Vec<f64>>,
}

impl FloatApproximations {
    /// The nearest `f64`s of `k`'s parameters and double point.
    pub fn of<K: Radical>(k: &Classification<K>) -> Self {
        let floats = |ps: &[Parameter<K>]| ps.iter().map(|p| p.to_f64()).collect();
        FloatApproximations {
            double_point_parameters: floats(&k.double_point_parameters),
            cusp_parameters: floats(&k.cusp_parameters),
            inflection_parameters: floats(&k.inflection_parameters),
            double_point: k.double_point.as_ref().map(|p| p.to_f64().coords),
        }
    }
}

/// A report in the field its route computed in (both spell every number alike).
#[derive(Clone, Debug)]
pub enum Classified {
    /// Fixed-width rationals: every number and step fitted.
    Fixed(ClassifyReport<SmallRational>),
    /// Big rationals.
    Exact(ClassifyReport<BigRational>),
}

impl ClassifyOptions {
    /// The direct route: a planar cubic whose numbers are integers (or fit a fixed-width
    /// rational over a common denominator), with neither evidence nor floats asked for, is
    /// classified straight to its JSON object (`{…}`, the fields of [`ClassifyReport`]'s JSON),
    /// appended to `out` (the crate's integer route). False, with `out` unchanged, when the
    /// route does not apply: then [`ClassifyOptions::classify_text`] answers.
    pub fn write_json_direct(&self, text: &str, out: &mut Vec<u8>) -> bool {
        use crate::classify::integer::{classify_json, classify_json_small};
        if self.dim != 2 || self.evidence || self.float {
            return false;
        }
        match integer_cubic(text) {
            Some(p) => classify_json(&p, out),
            None => small_cubic(text, self.mode).is_some_and(|p| classify_json_small(&p, out)),
        }
    }

    /// Classifies the control polygon written in `text` (of input line `line`, for errors):
    /// in fixed-width rationals when every number and step fits and no evidence is asked for,
    /// else in big rationals.
    ///
    /// # Errors
    /// As [`crate::num::parse_points_in`], [`BezierCurve::new`] and
    /// [`crate::classify::classify_in`].
    pub fn classify_text(&self, text: &str, line: Option<usize>) -> Result<Classified> {
        // count the numbers before reading them: memory stays a small multiple of the line
        crate::curve::bezier::check_polygon_text(text, self.dim)?;
        let fast = (!self.evidence)
            .then(|| parse_points_small_in(text, self.dim, line, self.mode))
            .flatten()
            .and_then(|pts| checked(|| BezierCurve::new(pts).and_then(|c| classify_in(&c))));
        if let Some(k) = fast {
            let k = k?;
            let float = self.float.then(|| FloatApproximations::of(&k));
            return Ok(Classified::Fixed(ClassifyReport { classification: k, evidence: None, float }));
        }
        let c = parse_points_in(text, self.dim, line, self.mode).and_then(BezierCurve::new)?;
        let k = classify_in(&c)?;
        let evidence = if self.evidence { cubic_evidence(&c, &k)? } else { None };
        let float = self.float.then(|| FloatApproximations::of(&k));
        Ok(Classified::Exact(ClassifyReport { classification: k, evidence, float }))
    }
}
