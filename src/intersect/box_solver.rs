//! The box solver's route: the subdivision filter's candidate boxes solved by Krawczyk's
//! operator ([`super::filter::solve`]), each crossing refined in fixed point
//! ([`super::fixed`]), its parameters then made exact without isolating the resultants' roots.

use super::filter;
use super::fixed::FixedSystem;
use super::roots::{Side, common_point, square_free_part};
use super::{Contact, Intersection, Intersections};
use crate::poly::algebraic::RealAlgebraic;
use num_bigint::BigInt;
use num_rational::BigRational;

/// The fast route of the exact pairing (`pairing::intersect_forms`) for polynomial curves on the
/// unit square (their system `sys`, resultants `r` in `s` and `t_poly` in `t`, non-zero): the
/// filter's candidate `boxes` solved by [`filter::solve`] (each proved empty or holding exactly
/// one transversal crossing), then each crossing's parameters made exact without isolating the
/// resultants' roots: the square-free part `p` of a resultant vanishes at the crossing's
/// parameter `σ` (the system has a common root there). First the crossing is refined in fixed
/// point ([`FixedSystem::refine`]: `σ` within some `2^−88`); when that interval lies strictly
/// inside the rounding cell of an `f64` `u` (the numbers nearer to `u` than to its neighbours)
/// and `p′` keeps its sign on the cell, the cell holds exactly one root of `p`, and it is `σ`:
/// so `u` is `σ` correctly rounded and the cell is an isolating interval, with no evaluation of
/// `p`; the point's coordinates are rounded from the same interval. Otherwise the cell is found
/// from the solver's box: when `p′` keeps its sign on the box and the cell, and `p` changes sign
/// across the cell (exact signs), the same follows. `σ` is irrational when `p` provably has no
/// rational root, else checked for one. `None` (the exact route decides) whenever a step is not
/// proved, or the resultants are both not square-free (contact orders then come from
/// multiplicities).
pub(super) fn solved_in_boxes(
    sys: &filter::System,
    (fa, fb): (&[Vec<BigInt>; 3], &[Vec<BigInt>; 3]),
    (r, t_poly): (&[BigInt], &[BigInt]),
    boxes: &[[f64; 4]],
) -> Option<Intersections> {
    use crate::poly::integer::derivative_integer;
    let zeros = filter::solve(sys, boxes)?;
    if zeros.is_empty() {
        return Some(Intersections { intersections: vec![], overlaps: vec![] });
    }
    let ((mut ps, s_simple), (mut pt, t_simple)) = (square_free_part(r), square_free_part(t_poly));
    if !(s_simple || t_simple) || ps.len() < 2 || pt.len() < 2 {
        return None;
    }
    // without rational roots the cells' roots are irrational; else each is checked
    let no_rational = crate::poly::algebraic::no_rational_roots;
    let (s_irrational, t_irrational) = (no_rational(&ps), no_rational(&pt));
    let derivative = |p: &[BigInt]| filter::Coeffs::derivative_of(p, filter::range_shift(p));
    let (dpsc, dptc) = (derivative(&ps), derivative(&pt));
    // the exact derivatives, for the exact cells (made on first need)
    let (mut dps, mut dpt) = (None, None);
    let (side_a, side_b) = (Side::new(fa), Side::new(fb));
    let mut out: Vec<Intersection> = vec![];
    let fixed = FixedSystem::new(fa, fb);
    let count = zeros.len();
    for (k, z) in zeros.into_iter().enumerate() {
        // refined in fixed point (no evaluation of the resultants), else each parameter's cell
        // found and proved by exact signs
        let refined = fixed.as_ref().and_then(|f| f.refine([z[0].ends(), z[1].ends()]));
        let cells = refined
            .as_ref()
            .and_then(|x| Some((rounded_cell(&dpsc, x.rounded(0)?)?, rounded_cell(&dptc, x.rounded(1)?)?)));
        let proved_fast = cells.is_some();
        let ((s, s_float), (t, t_float)) = match cells {
            Some((cs, ct)) => {
                // the last crossing takes the polynomials, the others copies
                let last = k + 1 == count;
                let take = |p: &mut Vec<BigInt>| if last { std::mem::take(p) } else { p.clone() };
                let root = |p, ((lo, hi), u), irrational| (RealAlgebraic::proved_root(p, lo, hi, irrational), u);
                (root(take(&mut ps), cs, s_irrational), root(take(&mut pt), ct, t_irrational))
            }
            None => {
                let dps = dps.get_or_insert_with(|| derivative_integer(&ps));
                let dpt = dpt.get_or_insert_with(|| derivative_integer(&pt));
                // the exact cells need a box some ulps wide
                let z = filter::shrink(sys, z);
                (
                    root_in_cell(&ps, (dps, &dpsc), z[0].ends(), s_irrational)?,
                    root_in_cell(&pt, (dpt, &dptc), z[1].ends(), t_irrational)?,
                )
            }
        };
        let point_float =
            refined.as_ref().and_then(|x| fixed.as_ref()?.point_float(x)).unwrap_or_else(|| side_a.point_float(&s));
        // tight enclosures of the parameters, for the irrationality proof of the point
        let (s_narrow, t_narrow) = match &refined {
            Some(x) if proved_fast => (x.enclosure(0), x.enclosure(1)),
            _ => (filter::outward(&s), filter::outward(&t)),
        };
        if out.iter().any(|x| x.s_float == s_float && x.t_float == t_float) {
            continue; // the same crossing, from a box sharing an edge
        }
        let mut cached = None;
        out.push(Intersection {
            s_float,
            t_float,
            point: common_point((&side_a, &s, s_narrow), (&side_b, &t, t_narrow), &mut cached),
            point_float,
            kind: Contact::Transversal,
            contact_order: 1,
            s,
            t,
        });
    }
    out.sort_by(|a, b| a.s_float.total_cmp(&b.s_float).then(a.t_float.total_cmp(&b.t_float)));
    Some(Intersections { intersections: out, overlaps: vec![] })
}

/// The rounding cell of the `f64` `u`, where the caller has proved that a root of `p`
/// (square-free, primitive, positive leading coefficient) lies strictly inside (`u` is that root
/// correctly rounded), with `u`, when `p′` (enclosed, `dpc`) keeps one sign on it: then that
/// root is the only one in the cell, which is an isolating interval for
/// [`RealAlgebraic::proved_root`]. `None` when that is not shown.
fn rounded_cell(dpc: &filter::Coeffs, u: f64) -> Option<((BigRational, BigRational), f64)> {
    if !dpc.nonzero_on(u.next_down(), u.next_up()) {
        return None;
    }
    Some((crate::poly::algebraic::f64_cell(u)?, u))
}

/// The root of `p` (square-free, primitive; `dp` its derivative, exact and enclosed) that lies
/// in `[lo, hi]`, where a zero of the system puts one, with its correctly rounded `f64`: the
/// rounding cell of an `f64` `u` (one exact Newton step from the midpoint, then its neighbours)
/// where `p` changes sign, with `p′` of one sign on the cell and on `[lo, hi]` (so one root in
/// both: the one in `[lo, hi]`); `irrational` when `p` has no rational root, else the root is
/// checked for one. `None` when no candidate is proved.
fn root_in_cell(
    p: &[BigInt],
    (dp, dpc): (&[BigInt], &filter::Coeffs),
    (lo, hi): (f64, f64),
    irrational: bool,
) -> Option<(RealAlgebraic, f64)> {
    let mid = lo + (hi - lo) / 2.0;
    // the box is some ulps wide: one exact Newton step from its midpoint finds the f64
    let m = crate::poly::algebraic::newton_step_f64(p, dp, mid).filter(|u| lo <= *u && *u <= hi).unwrap_or(mid);
    for u in [m, m.next_up(), m.next_down()] {
        let (below, above) = (u.next_down(), u.next_up());
        if !(u > 0.0 && above.is_finite() && dpc.nonzero_on(lo.min(below), hi.max(above))) {
            continue;
        }
        let Some(cell) = crate::poly::algebraic::f64_cell(u) else { continue };
        if let Some(x) = RealAlgebraic::certified_root(p.to_vec(), cell.0, cell.1, irrational) {
            return Some((x, u));
        }
    }
    None
}
