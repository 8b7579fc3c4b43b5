//! The intersection oracle for float code: a float library's intersection parameters checked
//! against the exact answer, on the shared matching of [`crate::oracle`].

use super::{Domain, intersect_polynomial};
use crate::curve::bezier::BezierCurve;
use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::poly::algebraic::RealAlgebraic;
use num_rational::BigRational;

/// A float library's intersection parameters checked against the exact answer (the
/// intersection oracle for float code). A float pair `(s, t)` **matches** an exact intersection
/// `(σ, τ)` when `|s − σ| ≤ tol` and `|t − τ| ≤ tol` (decided exactly), or lies on an overlap
/// (its `s` within `tol` of the overlap's `s` interval); exact intersections nobody matched are
/// `missed`, float pairs matching nothing `spurious`, a second pair for one exact intersection a
/// `duplicate`.
///
/// # Example
/// ```
/// use casteljau::intersect::{check_intersections_f64, Domain};
/// let parabola = [[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]];
/// let line = [[0.0, 1.0], [2.0, 1.0]];
/// // a float library that misses the tangency at (1/2, 1/2)
/// let d = check_intersections_f64(&parabola, &line, &[], 1e-9, Domain::Unit).unwrap();
/// assert_eq!((d.len(), d[0].kind.as_str(), d[0].s.as_str()), (1, "missed", "1/2"));
/// assert!(check_intersections_f64(&parabola, &line, &[(0.5, 0.5)], 1e-9, Domain::Unit).unwrap().is_empty());
/// ```
///
/// # Errors
/// As [`intersect`]; [`Error::InvalidArgument`] for non-finite coordinates or tolerance.
pub fn check_intersections_f64(
    a: &[[f64; 2]],
    b: &[[f64; 2]],
    float: &[(f64, f64)],
    tol: f64,
    domain: Domain,
) -> Result<Vec<IntersectionDisagreement>> {
    let bad = |m: String| Error::InvalidArgument { message: m };
    if !(tol.is_finite() && tol >= 0.0) {
        return Err(bad(format!("tolerance {tol} must be finite and ≥ 0")));
    }
    let exact = |x: f64| BigRational::from_float(x).ok_or_else(|| bad(format!("{x} is not finite")));
    let curve = |pts: &[[f64; 2]]| -> Result<BezierCurve<BigRational>> {
        BezierCurve::new(
            pts.iter().map(|p| Ok(Point::new(vec![exact(p[0])?, exact(p[1])?]))).collect::<Result<Vec<_>>>()?,
        )
    };
    let r = intersect_polynomial(&curve(a)?, &curve(b)?, domain)?;
    let tol_q = exact(tol)?;
    let near = |e: &RealAlgebraic, f: &BigRational| {
        *e >= RealAlgebraic::from(f.clone() - &tol_q) && *e <= RealAlgebraic::from(f.clone() + &tol_q)
    };
    let mut matched = vec![false; r.intersections.len()];
    let mut out = vec![];
    for &(s, t) in float {
        let (Some(sq), Some(tq)) = (BigRational::from_float(s), BigRational::from_float(t)) else {
            out.push(IntersectionDisagreement::spurious(s, t));
            continue;
        };
        let on_overlap = r.overlaps.iter().any(|o| {
            o.s[0] <= RealAlgebraic::from(sq.clone() + &tol_q) && o.s[1] >= RealAlgebraic::from(sq.clone() - &tol_q)
        });
        if on_overlap {
            continue;
        }
        let hits: Vec<usize> = (0..r.intersections.len())
            .filter(|&i| near(&r.intersections[i].s, &sq) && near(&r.intersections[i].t, &tq))
            .collect();
        match hits.iter().find(|&&i| !matched[i]) {
            Some(&i) => matched[i] = true,
            None if !hits.is_empty() => {
                let e = &r.intersections[hits[0]];
                out.push(IntersectionDisagreement {
                    kind: crate::classify::oracle::Kind::Duplicate,
                    s: e.s.to_string(),
                    t: e.t.to_string(),
                    float: Some((s, t)),
                    exact_float: Some((e.s_float, e.t_float)),
                });
            }
            None => out.push(IntersectionDisagreement::spurious(s, t)),
        }
    }
    for (e, m) in r.intersections.iter().zip(matched) {
        if !m {
            out.push(IntersectionDisagreement {
                kind: crate::classify::oracle::Kind::Missed,
                s: e.s.to_string(),
                t: e.t.to_string(),
                float: None,
                exact_float: Some((e.s_float, e.t_float)),
            });
        }
    }
    Ok(out)
}

/// One disagreement of [`check_intersections_f64`]. JSON: `kind` (`missed`, `spurious`,
/// `duplicate`), `s`, `t` (exact strings; empty for a spurious pair), `float` (the library's
/// pair), `exact_float`.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct IntersectionDisagreement {
    /// What kind of disagreement.
    pub kind: crate::classify::oracle::Kind,
    /// The exact `s` (empty when spurious).
    pub s: String,
    /// The exact `t` (empty when spurious).
    pub t: String,
    /// The float library's pair.
    pub float: Option<(f64, f64)>,
    /// The exact pair, correctly rounded.
    pub exact_float: Option<(f64, f64)>,
}

impl IntersectionDisagreement {
    fn spurious(s: f64, t: f64) -> Self {
        IntersectionDisagreement {
            kind: crate::classify::oracle::Kind::Spurious,
            s: String::new(),
            t: String::new(),
            float: Some((s, t)),
            exact_float: None,
        }
    }
}
