//! The oracle for float curve code: a float library's answers about one curve, checked against
//! the exact classification — every disagreement, per field, with the exact value and the float
//! one (the engine of `casteljau check`).
//!
//! The answers ([`FloatClassification`], JSON with any subset of the fields, unknown fields ignored):
//!
//! | field | meaning | compared |
//! | --- | --- | --- |
//! | `node_type` | `"crunode"`, `"cusp"`, `"acnode"`, `"explicit"` or `null` (not a genuine cubic) | exactly |
//! | `category` | the segment's Stone–DeRose category: `point`, `line`, `parabola`, `arch`, `single_inflection`, `double_inflection`, `loop`, `cusp` | exactly |
//! | `loop`, `cusp` | a loop / a cusp on `[0, 1]` | exactly |
//! | `inflections` | the number of inflections on `[0, 1]` | exactly |
//! | `inflection_parameters` | the inflection parameters the library found on `[0, 1]` | within `tol` |
//! | `cusp_parameters` | the cusp parameters on `[0, 1]` | within `tol` |
//! | `self_intersection_parameters` | the two parameters of a loop on `[0, 1]` (`[]` when none) | within `tol` |
//! | `double_point` | `[x, y]` of the double point (crunode, acnode) or cusp point | within `point_tol` |
//!
//! Parameter lists: a float parameter **matches** an exact one `e` when `|p − e| ≤ tol`, decided
//! exactly (`p` and `tol` are taken as the exact values of their `f64`s, `e` is exact in `Q(√d)`).
//! An exact parameter on `[0, 1]` matched by no float parameter is **missed**; a float parameter
//! matching no exact parameter of the curve (on `[0, 1]` or not) is **spurious**; a second float
//! parameter matching an exact parameter already matched is a **duplicate**. Points: the distance
//! in each coordinate is at most `point_tol`, exactly. A tolerance is never tighter than the
//! spacing of `f64`s at the float value (one ulp), so the correctly rounded exact answer always
//! agrees — a coordinate near 2·10⁷ cannot be written within 1e-9 in binary64.
//!
//! The window around a float answer, the matching and the disagreement kinds are
//! [`crate::oracle`]'s, shared with the intersection oracle; a float value is a [`FloatValue`].
//!
//! # Example
//! ```
//! use casteljau::oracle::{FloatClassification, Tolerances, check_classification};
//! // a cusp exactly at t = 1/2; a float library that says "arch" and misses it
//! let answers: FloatClassification = serde_json::from_str(r#"{"category": "arch", "cusp_parameters": []}"#).unwrap();
//! let d = check_classification(&[[0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]], &answers, &Tolerances::default()).unwrap();
//! assert_eq!(d.len(), 2);
//! assert_eq!((d[0].field, d[0].kind.as_str(), d[0].exact.as_str()), ("category", "mismatch", "cusp"));
//! assert_eq!((d[1].field, d[1].kind.as_str(), d[1].exact.as_str()), ("cusp_parameters", "missed", "1/2"));
//! ```

use super::matching::{Unmatched, Window, check_tolerance, exact_curve, match_floats};
use crate::classify::{Classification, NodeType, Parameter, classify};
use crate::error::Result;
use crate::num::quadratic_field::QuadraticExt;
use crate::num::scalar::{Exact, Scalar};
use num_rational::BigRational;

use super::matching::{DisagreementKind, FloatValue};

/// A float library's answers about one curve (see the module table); absent fields are not
/// checked.
#[derive(Clone, Debug, Default, PartialEq, serde::Deserialize, serde::Serialize)]
pub struct FloatClassification {
    /// The node type, or `None` inside `Some` for "not a genuine cubic" (JSON `null`).
    #[serde(default, deserialize_with = "explicit_null", skip_serializing_if = "Option::is_none")]
    pub node_type: Option<Option<String>>,
    /// The segment's category.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub category: Option<String>,
    /// A loop on `[0, 1]`.
    #[serde(default, rename = "loop", skip_serializing_if = "Option::is_none")]
    pub has_loop: Option<bool>,
    /// A cusp on `[0, 1]`.
    #[serde(default, rename = "cusp", skip_serializing_if = "Option::is_none")]
    pub has_cusp: Option<bool>,
    /// The number of inflections on `[0, 1]`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub inflections: Option<usize>,
    /// Inflection parameters found on `[0, 1]`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub inflection_parameters: Option<Vec<f64>>,
    /// Cusp parameters found on `[0, 1]`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cusp_parameters: Option<Vec<f64>>,
    /// The two parameters of a loop on `[0, 1]` (empty when there is none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub self_intersection_parameters: Option<Vec<f64>>,
    /// The double point or cusp point.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub double_point: Option<[f64; 2]>,
}

fn explicit_null<'de, D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Option<Option<String>>, D::Error> {
    use serde::Deserialize;
    Ok(Some(Option::<String>::deserialize(d)?))
}

/// How far a float answer may be from the exact one and still agree.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerances {
    /// Absolute tolerance on parameters `t` (default `1e-9`).
    pub parameter: f64,
    /// Absolute tolerance on each coordinate of the double point (default `1e-9`).
    pub point: f64,
}

impl Default for Tolerances {
    fn default() -> Self {
        Tolerances { parameter: 1e-9, point: 1e-9 }
    }
}

/// One disagreement between a float answer and the exact one. JSON fields: `field`, `kind`,
/// `exact` (the exact value as a string, `""` when there is none, e.g. for a spurious parameter),
/// `exact_float` (its nearest `f64`, when it is a number), `float` (the library's value).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct ClassificationDisagreement {
    /// The answer field (`category`, `inflection_parameters`, …).
    pub field: &'static str,
    /// What kind of disagreement.
    pub kind: DisagreementKind,
    /// The exact value.
    pub exact: String,
    /// The exact value's nearest `f64`, for numbers.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exact_float: Option<f64>,
    /// The float library's value.
    pub float: FloatValue,
}

/// Every disagreement between `answers` and the exact classification of the planar curve of
/// degree ≤ 3 with control points `points` (each `f64` taken exactly), in the order of the
/// module table.
///
/// # Errors
/// [`Error::InvalidArgument`](crate::Error::InvalidArgument) for a non-finite coordinate or a
/// negative or non-finite tolerance; otherwise as [`classify`].
pub fn check_classification(
    points: &[[f64; 2]],
    answers: &FloatClassification,
    tol: &Tolerances,
) -> Result<Vec<ClassificationDisagreement>> {
    let curve = exact_curve(points, |x| format!("control point coordinate {x} is not finite"))?;
    compare_classification(&classify(&curve)?, answers, tol)
}

/// [`check_classification`] on a classification already computed (of an exact curve, say, or
/// to compare several libraries' answers with one exact classification).
///
/// # Errors
/// [`Error::InvalidArgument`](crate::Error::InvalidArgument) for a negative or non-finite
/// tolerance.
///
/// ```
/// use casteljau::{BezierCurve, classify, num::parse_points};
/// use casteljau::oracle::{FloatClassification, Tolerances, compare_classification};
/// let exact = classify(&BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap()).unwrap();
/// let says_arch = FloatClassification { category: Some("arch".into()), ..Default::default() };
/// assert_eq!(compare_classification(&exact, &says_arch, &Tolerances::default()).unwrap().len(), 1);
/// ```
pub fn compare_classification(
    k: &Classification,
    answers: &FloatClassification,
    tol: &Tolerances,
) -> Result<Vec<ClassificationDisagreement>> {
    for t in [tol.parameter, tol.point] {
        check_tolerance(t)?;
    }
    Ok(compare(k, answers, tol))
}

/// The comparison itself (tolerances checked by the caller).
fn compare(k: &Classification, answers: &FloatClassification, tol: &Tolerances) -> Vec<ClassificationDisagreement> {
    let mut out = vec![];
    let mut differ = |field, exact: String, float: FloatValue| {
        out.push(ClassificationDisagreement {
            field,
            kind: DisagreementKind::Mismatch,
            exact,
            exact_float: None,
            float,
        })
    };
    if let Some(n) = &answers.node_type {
        let exact = k.node_type.map(NodeType::as_str);
        if exact != n.as_deref() {
            differ("node_type", exact.unwrap_or("null").into(), FloatValue::from(n.as_deref()));
        }
    }
    if let Some(c) = &answers.category
        && c != k.segment.category.as_str()
    {
        differ("category", k.segment.category.as_str().into(), c.as_str().into());
    }
    if let Some(b) = answers.has_loop
        && b != k.segment.has_loop
    {
        differ("loop", k.segment.has_loop.to_string(), b.into());
    }
    if let Some(b) = answers.has_cusp
        && b != k.segment.has_cusp
    {
        differ("cusp", k.segment.has_cusp.to_string(), b.into());
    }
    if let Some(n) = answers.inflections
        && n != k.segment.inflections
    {
        differ("inflections", k.segment.inflections.to_string(), n.into());
    }
    if let Some(ps) = &answers.inflection_parameters {
        match_parameters(&mut out, "inflection_parameters", &k.inflection_parameters, ps, tol.parameter);
    }
    if let Some(ps) = &answers.cusp_parameters {
        match_parameters(&mut out, "cusp_parameters", &k.cusp_parameters, ps, tol.parameter);
    }
    if let Some(ps) = &answers.self_intersection_parameters {
        // only a loop on [0, 1] has self-intersection parameters to report
        let exact: &[Parameter] = if k.segment.has_loop { &k.double_point_parameters } else { &[] };
        match_parameters(&mut out, "self_intersection_parameters", exact, ps, tol.parameter);
    }
    if let Some(p) = answers.double_point {
        match &k.double_point {
            None => out.push(ClassificationDisagreement {
                field: "double_point",
                kind: DisagreementKind::Spurious,
                exact: String::new(),
                exact_float: None,
                float: p.into(),
            }),
            Some(d) => {
                let near = d.coords.iter().zip(p).all(|(e, f)| match BigRational::from_float(f) {
                    Some(f) => within(&QuadraticExt::from_base(e.clone()), &f, tol.point),
                    None => false,
                });
                if !near {
                    out.push(ClassificationDisagreement {
                        field: "double_point",
                        kind: DisagreementKind::Mismatch,
                        exact: d.to_string(),
                        exact_float: None,
                        float: p.into(),
                    });
                }
            }
        }
    }
    out
}

/// `|e − p| ≤ tol` exactly, `tol` widened to one ulp at `p` ([`Window::at_least_one_ulp`]).
fn within(e: &Parameter, p: &BigRational, tol: f64) -> bool {
    Window::at_least_one_ulp(p, tol).holds(|x| (e.clone() - QuadraticExt::from_base(x.clone())).sign())
}

/// Matches float parameters to the exact ones (ascending) so that as many as possible agree:
/// in ascending order each float takes the smallest unmatched exact parameter within `tol`
/// ([`crate::oracle`]'s matching); what is left over is spurious, duplicate or missed (an exact
/// parameter on `[0, 1]`).
fn match_parameters(
    out: &mut Vec<ClassificationDisagreement>,
    field: &'static str,
    exact: &[Parameter],
    float: &[f64],
    tol: f64,
) {
    let mut sorted: Vec<f64> = float.to_vec();
    sorted.sort_by(f64::total_cmp);
    let floats = sorted.into_iter().map(|p| (p, BigRational::from_float(p)));
    let (unmatched, missed) =
        match_floats(exact.len(), floats, |i, (_, q)| q.as_ref().is_some_and(|q| within(&exact[i], q, tol)));
    for ((p, q), why) in unmatched {
        out.push(match why {
            Unmatched::Duplicate(i) => ClassificationDisagreement {
                field,
                kind: DisagreementKind::Duplicate,
                exact: exact[i].to_string(),
                exact_float: Some(exact[i].to_f64()),
                float: p.into(),
            },
            Unmatched::Spurious => ClassificationDisagreement {
                field,
                kind: DisagreementKind::Spurious,
                exact: String::new(),
                exact_float: None,
                // a non-finite float is written out as text
                float: if q.is_some() { p.into() } else { FloatValue::Text(p.to_string()) },
            },
        });
    }
    for e in missed.into_iter().map(|i| &exact[i]).filter(|e| crate::classify::in_unit_interval(e)) {
        out.push(ClassificationDisagreement {
            field,
            kind: DisagreementKind::Missed,
            exact: e.to_string(),
            exact_float: Some(e.to_f64()),
            float: FloatValue::Null,
        });
    }
}
