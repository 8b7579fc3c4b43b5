//! What checking a claim will cost, estimated from its sizes before any of the work starts
//! (see [`crate::work`] for the units and the cost models).
//!
//! Every kind counts the exact evaluations of its dominant loop — grid points times routes for
//! the grid proofs, table rows for the tables, pieces times grid points for repeated
//! subdivision — and prices each with the cost model of [`crate::work`] at the bit lengths the
//! numbers reach. Parsing and comparing the printed values is linear in the claim file and not
//! counted. The expression language is bounded separately, while it runs, by the step limit
//! of [`crate::proof::expr::with_step_limit`]; an identity's grid is charged there too, per
//! parameter instance, once its degree bounds are known.

use super::claims::ClaimContent;
use super::common::{MAX_TABLE_DEGREE, curve_from, num, parameters_of, rational_curve, scalars};
use super::{cubic, polynomial, rational, surface};
use crate::curve::bezier::BezierCurve;
use crate::error::Result;
use crate::proof::expr::{Env, parse_expr};
use crate::rational::rational_bezier::RationalBezier;
use crate::work::{self, bits, limbs, max_bits, max_bits_of, rational_evaluation};
use num_rational::BigRational;

/// Bits of the grid values of a degree-`d` grid proof (small integers `0..=d` or
/// `0, ±1, ±2, …`): `log₂ d` and a sign.
fn grid_bits(d: usize) -> u64 {
    u64::from(usize::BITS - d.leading_zeros()) + 2
}

/// Bits of the `count` parameters `0, 1, 1/2, 1/3, 2/3, …` of the rational checks (the
/// denominators reach about `√(2·count)`).
fn parameter_bits(count: usize) -> u64 {
    grid_bits(count) + 2
}

fn sizes(c: &BezierCurve<BigRational>) -> (usize, usize, u64) {
    (c.degree(), c.dim(), max_bits(c.points()))
}

fn rational_sizes(r: &RationalBezier<BigRational>) -> (usize, usize, u64) {
    let h = r.homogeneous();
    (h.degree(), h.dim(), max_bits(h.points()))
}

/// `count` evaluations over reduced fractions.
fn evaluations(count: f64, n: usize, dim: usize, beta: u64, tau: u64) -> f64 {
    count * rational_evaluation(n, dim, beta, tau)
}

/// One evaluation of an `(m, n)` patch of dimension `dim` (homogeneous): `n + 1` curves of
/// degree `m`, then one of degree `n`.
fn patch_evaluation(m: usize, n: usize, dim: usize, beta: u64, tau: u64) -> f64 {
    // three times the two curve evaluations: the patch's point is reduced to its dimension and
    // compared (measured: a 7×7 patch's 13×13 grid, 1.9 s; 11×11, 25 s)
    3.0 * ((n as f64 + 1.0) * rational_evaluation(m, dim, beta, tau)
        + rational_evaluation(n, dim, beta.saturating_add((m as u64).saturating_mul(tau)), tau))
}

impl ClaimContent {
    /// The work of [`ClaimContent::check`] in [`crate::work`] units, from the claim's sizes
    /// (degrees, bit lengths, grid sizes, depths), computed before any of it is done.
    ///
    /// # Errors
    /// A malformed claim (its numbers, polygons or expressions do not parse).
    pub fn estimate(&self) -> Result<f64> {
        Ok(match self {
            ClaimContent::Identity(_) => 0.0,
            ClaimContent::CurveFormula(c) => curve_formula(c)?,
            ClaimContent::PowerForm(c) => {
                let (n, dim, beta) = sizes(&curve_from(&c.curve)?);
                work::power_form(n, dim, beta)
            }
            ClaimContent::Subdivision(c) => {
                let curve = curve_from(&c.curve)?;
                let (n, dim, beta) = sizes(&curve);
                let tau = bits(&num(&c.t)?);
                // the halves, then Lemma 2 on n + 1 points: four evaluations each
                work::subdivision(n, dim, beta, tau)
                    + evaluations(
                        4.0 * (n as f64 + 1.0),
                        n,
                        dim,
                        beta.saturating_add(n as u64 * tau),
                        tau + grid_bits(n),
                    )
            }
            ClaimContent::Lemma2(c) => (1..=c.degree.min(8))
                .map(|n| {
                    let points = 2f64.powi(n as i32 + 1) * (n as f64 + 1.0).powi(2);
                    evaluations(4.0 * points, n, 1, grid_bits(n), grid_bits(n))
                })
                .sum(),
            ClaimContent::RepeatedSubdivision(c) => repeated_subdivision(c)?,
            // past the size limit the check itself refuses, naming the limit
            ClaimContent::Matrix(c) => {
                let d = c.degree.min(MAX_TABLE_DEGREE);
                let n = d as f64 + 1.0;
                100.0 * n * n * limbs(d as u64)
            }
            ClaimContent::Table(c) => {
                let (n, dim, beta) = sizes(&curve_from(&c.curve)?);
                let ts = parameters_of(&c.ts, c.steps)?;
                ts.iter().map(|t| work::evaluation(n, dim, beta, bits(t))).sum()
            }
            ClaimContent::BasisTable(c) => {
                let n = c.degree.min(MAX_TABLE_DEGREE);
                let ts = parameters_of(&c.ts, c.steps)?;
                // B_i^n(t): n products of numbers growing to n·τ bits, for every i
                let tau = max_bits_of(&ts);
                let nf = n as f64 + 1.0;
                ts.len() as f64 * nf * nf * 18.0 * limbs((n as u64).saturating_mul(tau).saturating_add(n as u64))
            }
            ClaimContent::Classification(cubic::ClassificationClaim { curve, .. })
            | ClaimContent::MovingLines(cubic::MovingLinesClaim { curve, .. })
            | ClaimContent::MovingLine2(cubic::MovingLine2 { curve, .. })
            | ClaimContent::CanonicalMap(cubic::CanonicalMapClaim { curve, .. }) => {
                // a cubic: power form, discriminants and quadratic roots of its coefficients,
                // a 4×4 grid of cross products
                let (n, dim, beta) = sizes(&curve_from(curve)?);
                let n2 = n.saturating_mul(2);
                200.0 * work::power_form(n, dim, beta)
                    + work::root_isolation(n2, beta.saturating_mul(n2 as u64))
                    + evaluations(64.0, n, 3, beta, 8)
            }
            ClaimContent::Implicit(c) => implicit(c)?,
            ClaimContent::RationalEvaluations(c) => {
                let (n, dim, beta) = rational_sizes(&rational_curve_of(&c.curve, &c.weights, &c.homogeneous)?);
                let (count, tau) = (2 * n + 1, parameter_bits(2 * n + 1));
                // closed form (14), seed 000's recursion, Saito–Hosaka (19)–(20)
                evaluations(2.0 * count as f64, n, dim, beta, tau)
                    + count as f64 * work::saito_hosaka_evaluation(n, dim, beta, tau)
            }
            ClaimContent::RationalElevation(c) => {
                let (n, dim, beta) = rational_sizes(&rational_curve_of(&c.curve, &c.weights, &c.homogeneous)?);
                2.0 * work::elevation(n, 1, dim, beta) + evaluations(n as f64 + 2.0, 1, dim, beta, grid_bits(n))
            }
            ClaimContent::RationalSubdivision(c) => {
                let (n, dim, beta) = rational_sizes(&rational_curve_of(&c.curve, &c.weights, &c.homogeneous)?);
                let tau = bits(&num(&c.t)?);
                let count = 2 * n + 1;
                let grown = beta.saturating_add((n as u64).saturating_mul(tau));
                // the halves, four evaluations per parameter, and (19)–(20)'s interpolation
                // points (a Saito–Hosaka evaluation at t0)
                work::subdivision(n, dim, beta, tau)
                    + evaluations(4.0 * count as f64, n, dim, grown, tau + parameter_bits(count))
                    + work::saito_hosaka_evaluation(n, dim, beta, tau)
            }
            ClaimContent::WeightPull(c) => {
                let r = rational_curve_of(&c.curve, &c.weights, &c.homogeneous)?;
                let (n, dim, beta) = rational_sizes(&r);
                let beta = beta.max(bits(&num(&c.weight)?));
                let count = 2 * n + 1;
                2.0 * work::root_isolation(n, beta)
                    + evaluations(3.0 * count as f64, n, dim, beta, parameter_bits(count))
            }
            ClaimContent::SplineSegments(c) => {
                let curve = curve_from(&c.curve)?;
                let beta = max_bits(curve.points())
                    .max(max_bits_of(&scalars(&c.ratios)?))
                    .max(c.weights.as_deref().map(scalars).transpose()?.as_deref().map_or(0, max_bits_of));
                let (n, dim) = (c.degree, curve.dim() + 1);
                let segments = curve.points().len().saturating_sub(n).max(1) as f64;
                // each segment: de Boor and the Bézier segment on 2n + 1 parameters, the joins
                let grown = beta.saturating_mul(n as u64 + 1);
                segments * evaluations(10.0 * (2 * n + 1) as f64 + 2.0, n, dim, grown, parameter_bits(2 * n + 1))
            }
            ClaimContent::PatchEvaluations(c) => {
                let (rows, beta) = surface::net_sizes(&c.net, c.net_weights.as_deref())?;
                let (m, n) = (rows.0.saturating_sub(1), rows.1.saturating_sub(1));
                let grid = ((2 * m + 1) * (2 * n + 1)) as f64;
                3.0 * grid * patch_evaluation(m, n, 4, beta, grid_bits(2 * m.max(n)))
            }
            ClaimContent::PatchWeightChange(c) => {
                let (rows, beta) = surface::net_sizes(&c.net, c.net_weights.as_deref())?;
                let beta = beta.max(bits(&num(&c.weight)?));
                let (m, n) = (rows.0.saturating_sub(1), rows.1.saturating_sub(1));
                let grid = ((2 * m + 1) * (2 * n + 1)) as f64;
                3.0 * grid * patch_evaluation(m, n, 4, beta, grid_bits(2 * m.max(n)))
            }
            ClaimContent::Net(c) => {
                let (rows, beta) = surface::net_sizes(&c.net, c.net_weights.as_deref())?;
                let beta = beta.max(max_bits_of(&scalars(&c.ratios)?)).max(max_bits_of(&scalars(&c.ratios_v)?));
                let (nu, nv) = c
                    .degrees
                    .as_deref()
                    .and_then(|d| d.split_once(','))
                    .and_then(|(a, b)| Some((a.trim().parse::<usize>().ok()?, b.trim().parse::<usize>().ok()?)))
                    .unwrap_or((2, 2));
                let patches = (rows.0.saturating_sub(nu).max(1) * rows.1.saturating_sub(nv).max(1)) as f64;
                let grid = ((2 * nu + 1) * (2 * nv + 1)) as f64;
                let grown = beta.saturating_mul((nu + nv) as u64 + 1);
                // per patch: both conversions, the tensor NURBS and the patch on the grid, joins
                patches * (4.0 * grid + 8.0) * patch_evaluation(nu, nv, 4, grown, grid_bits(2 * nu.max(nv)))
            }
        })
    }
}

fn rational_curve_of(
    curve: &Option<String>,
    weights: &Option<String>,
    homogeneous: &Option<String>,
) -> Result<RationalBezier<BigRational>> {
    rational_curve(curve.as_deref(), weights.as_deref(), homogeneous.as_deref())
}

fn curve_formula(c: &polynomial::CurveFormula) -> Result<f64> {
    let r = rational_curve_of(&c.curve, &c.weights, &c.homogeneous)?;
    let (n, dim, beta) = rational_sizes(&r);
    let mut degree = n;
    for f in [Some(&c.x), Some(&c.y), c.z.as_ref()].into_iter().flatten() {
        // a malformed formula is reported by the check itself
        if let Ok((a, b)) = parse_expr(f).and_then(|e| {
            e.degree("t", &mut Env::new()).map_err(|e| crate::error::Error::InvalidArgument { message: e.to_string() })
        }) {
            degree = degree.max(n.saturating_add(a.max(b)));
        }
    }
    // fraction-free evaluation at degree + 1 grid values
    Ok((degree as f64 + 1.0) * work::evaluation(n, dim, beta, grid_bits(degree)))
}

fn repeated_subdivision(c: &polynomial::RepeatedSubdivision) -> Result<f64> {
    let (n, dim, beta) = sizes(&curve_from(&c.curve)?);
    let tau = bits(&num(&c.t)?);
    let depth = c.depth.min(crate::curve::casteljau::MAX_SUBDIVISION_DEPTH);
    let pieces = 2f64.powi(depth as i32);
    // every piece (numbers of β + depth·n·τ bits) is proved equal to the curve on its interval
    // (endpoints of depth·τ bits) at n + 1 grid values: two evaluations each
    let piece_bits = beta.saturating_add(u64::from(depth).saturating_mul(n as u64).saturating_mul(tau));
    let interval_bits = u64::from(depth).saturating_mul(tau).saturating_add(grid_bits(n));
    Ok(work::repeated_subdivision(n, dim, beta, tau, depth)
        + evaluations(pieces * (n as f64 + 1.0), n, dim, piece_bits, grid_bits(n))
        + evaluations(pieces * (n as f64 + 1.0), n, dim, beta, interval_bits))
}

fn implicit(c: &rational::Implicit) -> Result<f64> {
    let r = rational_curve_of(&c.curve, &c.weights, &c.homogeneous)?;
    let (n, dim, beta) = rational_sizes(&r);
    let names = ["x", "y", "z"];
    let f = parse_expr(&c.poly)?;
    // a malformed polynomial is reported by the check itself
    let Ok(d) = crate::rational::implicit::total_degree(&f, &names[..(dim - 1).min(3)]) else {
        return Ok(0.0);
    };
    let bound = n.saturating_mul(d);
    let count = bound.saturating_add(1);
    let tau = parameter_bits(count);
    // each parameter: the curve's point, then f at coordinates of n·τ + β bits
    let point_bits = beta.saturating_add((n as u64).saturating_mul(tau));
    let f_cost = f.size() as f64 * 18.0 * limbs(point_bits.saturating_mul(d as u64)).powi(2);
    Ok(count as f64 * (work::evaluation(n, dim, beta, tau) + f_cost))
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    #[test]
    fn claim_content_estimate() {
        use crate::catalogue::ClaimContent;
        let deep: ClaimContent = toml::from_str(
            r#"
            kind = "repeated-subdivision"
            curve = "0 0, 1 3, 2 -1, 3 4, 4 0, 5 2, 6 -3, 7 1, 8 5, 9 -2, 10 0"
            t = "1/2"
            depth = 16
            pieces = 65536
        "#,
        )
        .unwrap();
        assert!(deep.estimate().unwrap() > crate::work::DEFAULT_MAX_WORK);
    }
}
