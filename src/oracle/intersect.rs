//! The intersection oracle for float code: a float library's intersection parameters checked
//! against the exact answer, on the shared matching of [`crate::oracle`].

use super::matching::{DisagreementKind, Unmatched, Window, check_tolerance, exact_curve, match_floats};
use crate::error::Result;
use crate::intersect::{Domain, intersect};
use crate::poly::algebraic::RealAlgebraic;
use crate::rational::RationalBezier;
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
/// use casteljau::{intersect::Domain, oracle::check_intersections};
/// let parabola = [[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]];
/// let line = [[0.0, 1.0], [2.0, 1.0]];
/// // a float library that misses the tangency at (1/2, 1/2)
/// let d = check_intersections(&parabola, &line, &[], 1e-9, Domain::Unit).unwrap();
/// assert_eq!((d.len(), d[0].kind.as_str(), d[0].s.as_str()), (1, "missed", "1/2"));
/// assert!(check_intersections(&parabola, &line, &[(0.5, 0.5)], 1e-9, Domain::Unit).unwrap().is_empty());
/// ```
///
/// # Errors
/// As [`intersect`](crate::intersect::intersect); [`Error::InvalidArgument`](crate::Error::InvalidArgument) for non-finite coordinates or tolerance.
pub fn check_intersections(
    a: &[[f64; 2]],
    b: &[[f64; 2]],
    float: &[(f64, f64)],
    tol: f64,
    domain: Domain,
) -> Result<Vec<IntersectionDisagreement>> {
    check_tolerance(tol)?;
    let curve = |pts: &[[f64; 2]]| exact_curve(pts, |x| format!("{x} is not finite"));
    let r = intersect(
        &RationalBezier::from(curve(a)?),
        &RationalBezier::from(curve(b)?),
        domain,
        &crate::work::Budget::unlimited(),
    )?;
    let tol = BigRational::from_float(tol).expect("finite tolerance");
    // each pair's windows in s and t (none when not finite); a pair on an overlap is neither
    // matched nor reported
    let floats = float
        .iter()
        .map(|&(s, t)| {
            let window = |x: f64| BigRational::from_float(x).map(|q| Window::around(&q, &tol));
            ((s, t), window(s).zip(window(t)))
        })
        .filter(|(_, w)| {
            !w.as_ref().is_some_and(|(ws, _)| {
                r.overlaps.iter().any(|o| {
                    o.s[0] <= RealAlgebraic::from(ws.hi.clone()) && o.s[1] >= RealAlgebraic::from(ws.lo.clone())
                })
            })
        });
    let holds = |w: &Window, e: &RealAlgebraic| w.holds(|x| e.cmp(&RealAlgebraic::from(x.clone())));
    let (unmatched, missed) = match_floats(r.intersections.len(), floats, |i, (_, w)| {
        let e = &r.intersections[i];
        w.as_ref().is_some_and(|(ws, wt)| holds(ws, &e.s) && holds(wt, &e.t))
    });
    let mut out = vec![];
    for (((s, t), _), why) in unmatched {
        out.push(match why {
            Unmatched::Duplicate(i) => {
                let e = &r.intersections[i];
                IntersectionDisagreement {
                    kind: DisagreementKind::Duplicate,
                    s: e.s.to_string(),
                    t: e.t.to_string(),
                    float: Some((s, t)),
                    exact_float: Some((e.s_float, e.t_float)),
                }
            }
            Unmatched::Spurious => IntersectionDisagreement::spurious(s, t),
        });
    }
    for e in missed.into_iter().map(|i| &r.intersections[i]) {
        out.push(IntersectionDisagreement {
            kind: DisagreementKind::Missed,
            s: e.s.to_string(),
            t: e.t.to_string(),
            float: None,
            exact_float: Some((e.s_float, e.t_float)),
        });
    }
    Ok(out)
}

/// One disagreement of [`check_intersections`]. JSON: `kind` (`missed`, `spurious`,
/// `duplicate`), `s`, `t` (exact strings; empty for a spurious pair), `float` (the library's
/// pair), `exact_float`.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct IntersectionDisagreement {
    /// What kind of disagreement.
    pub kind: DisagreementKind,
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
            kind: DisagreementKind::Spurious,
            s: String::new(),
            t: String::new(),
            float: Some((s, t)),
            exact_float: None,
        }
    }
}
