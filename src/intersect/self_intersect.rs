//! Self-intersections `A(s) = A(t)`, `s < t`, from the resultant of the divided differences
//! `(X(s)W(t) − X(t)W(s))/(s − t)` and the same for `Y`, paired like the curve–curve route's
//! (`pairing`). When that resultant vanishes identically the curve shares a component with itself:
//! `None`, and `overlap::self_intersections` (the entry point's route) asks `overlap::self_overlap`.

use super::elimination::divided_difference;
use super::filter::apart;
use super::forms::{point_at, rational_point, to_rational};
use super::roots::{Side, finite_roots, multiplicity, roots};
use super::{Contact, Domain, Intersection, Intersections};
use crate::error::{Error, Result};
use crate::poly::algebraic::{RealAlgebraic, resultant_zv};
use num_bigint::BigInt;

/// [`self_intersect`](super::self_intersect()) of the curve with integer power forms `fa` (checked by the caller);
/// `None` when the resultant vanishes identically (a component shared with itself).
pub(super) fn self_intersections_of_forms(fa: &[Vec<BigInt>; 3], domain: Domain) -> Result<Option<Intersections>> {
    let dx = divided_difference(&fa[0], &fa[2]);
    let dy = divided_difference(&fa[1], &fa[2]);
    if dx.is_empty() || dy.is_empty() {
        // a coordinate is constant: the curve lies on a line; pairs come from the other one
        let d = if dx.is_empty() { &dy } else { &dx };
        if d.is_empty() {
            return Err(Error::Degenerate { message: "the curve is a single point".into() });
        }
    }
    let r = resultant_zv(&dx, &dy);
    if r.is_empty() {
        return Ok(None);
    }
    let (ss, simple) = roots(&r, domain);
    let ss = finite_roots(ss, fa);
    let rr = to_rational(&r);
    let side = Side::new(fa);
    // exact points only for pairs whose enclosures cannot be told apart (see `intersect_within`)
    let mut pts: Vec<Option<[RealAlgebraic; 2]>> = vec![None; ss.len()];
    let mut narrow: Vec<Option<(RealAlgebraic, f64)>> = vec![None; ss.len()];
    let mut out = vec![];
    for i in 0..ss.len() {
        for j in i + 1..ss.len() {
            if apart(fa, &ss[i], fa, &ss[j]) {
                continue;
            }
            for k in [i, j] {
                narrow[k].get_or_insert_with(|| ss[k].narrowed_with_f64());
            }
            let (Some((si, _)), Some((sj, _))) = (&narrow[i], &narrow[j]) else { continue };
            if apart(fa, si, fa, sj) {
                continue;
            }
            for k in [i, j] {
                if pts[k].is_none() {
                    charge_point(fa, &ss[k])?;
                    pts[k] = Some(point_at(fa, &ss[k]));
                }
            }
            let (Some(p), Some(q)) = (&pts[i], &pts[j]) else { continue };
            let p = p.clone();
            if p[0] == q[0] && p[1] == q[1] {
                let order = if simple { 1 } else { multiplicity(&rr, &ss[i]).min(multiplicity(&rr, &ss[j])).max(1) };
                let (Some((si, s_float)), Some((_, t_float))) = (&narrow[i], &narrow[j]) else { continue };
                out.push(Intersection {
                    s_float: *s_float,
                    t_float: *t_float,
                    point: rational_point(&p),
                    point_float: side.point_float(si),
                    kind: if order == 1 { Contact::Transversal } else { Contact::Tangent },
                    contact_order: order,
                    s: ss[i].clone(),
                    t: ss[j].clone(),
                });
            }
        }
    }
    Ok(Some(Intersections { intersections: out, overlaps: vec![] }))
}

/// Charges the exact point of the curve at `s` ([`crate::work::algebraic_image`], once per
/// coordinate) to the budget of the running operation.
fn charge_point(fa: &[Vec<BigInt>; 3], s: &RealAlgebraic) -> Result<()> {
    if s.to_rational().is_some() {
        return Ok(());
    }
    let p = s.polynomial();
    let bits = |c: &[BigInt]| c.iter().map(num_bigint::BigInt::bits).max().unwrap_or(0);
    let bq = fa.iter().map(|f| bits(f)).max().unwrap_or(0);
    let n = fa.iter().map(Vec::len).max().unwrap_or(1).saturating_sub(1);
    let units = 2.0 * crate::work::algebraic_image(p.len().saturating_sub(1), n, bits(&p), bq);
    crate::work::charge(
        || format!("the exact point of a self-intersection of degree {n} (a parameter of degree {})", p.len() - 1),
        units,
    )
}
