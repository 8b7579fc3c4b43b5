//! Claim kinds about splines, patches and nets (seed 002 §3–§5).

use crate::catalogue::common::{Outcome, bad, curve_from, num, scalars, verdict};
use crate::error::Result;
use crate::num::parse::parse_points;
use crate::num::point::Point;
use crate::num::scalar::rat;
use crate::proof::Reading;
use crate::spline::net::SplineNet;
use crate::spline::{Conversion, RationalSpline, check_segments};
use crate::surface::RationalPatch;
use num_rational::BigRational;
use serde::Deserialize;

fn boehm() -> Conversion {
    Conversion::Boehm
}

fn as_printed() -> Reading {
    Reading::AsPrinted
}

/// `spline-segments`: a rational spline's Bézier segments by the chosen route.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SplineSegments {
    /// Control points.
    pub curve: String,
    /// Weights (default all 1).
    pub weights: Option<String>,
    /// Scale ratios, `m + n` of them.
    pub ratios: String,
    /// The degree `n`.
    pub degree: usize,
    /// `boehm` (default), `seed` or `seed-printed`.
    #[serde(default = "boehm")]
    pub method: Conversion,
}

/// `patch-evaluations`: the three evaluations of one patch agree.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PatchEvaluations {
    /// The net: rows separated by `;`, points by `,`.
    pub net: String,
    /// Its weights, rows separated by `;`.
    pub net_weights: Option<String>,
}

/// `patch-weight-change`: (48)–(49) for control point `(index, index_v)`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PatchWeightChange {
    /// The net: rows separated by `;`, points by `,`.
    pub net: String,
    /// Its weights, rows separated by `;`.
    pub net_weights: Option<String>,
    /// The `u` index.
    pub index: usize,
    /// The `v` index.
    pub index_v: usize,
    /// The weight change `Δw`.
    pub weight: String,
    /// `γ` as printed or the Bernstein polynomial.
    #[serde(default = "as_printed")]
    pub formulas: Reading,
}

/// `net`: a rational spline net turned into patches.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Net {
    /// The net: rows separated by `;`, points by `,`.
    pub net: String,
    /// Its weights, rows separated by `;`.
    pub net_weights: Option<String>,
    /// Scale ratios along `u`.
    pub ratios: String,
    /// Scale ratios along `v`.
    pub ratios_v: String,
    /// Degrees `"nu,nv"` (default `2,2`).
    pub degrees: Option<String>,
    /// `boehm` (default), `seed` or `seed-printed`.
    #[serde(default = "boehm")]
    pub method: Conversion,
}
impl SplineSegments {
    /// The segments equal the NURBS on each span and join `C^(n−1)`.
    ///
    /// # Errors
    /// A malformed claim.
    pub fn check(&self) -> Result<Outcome> {
        let c = self;

        let curve = curve_from(&c.curve)?;
        let n = c.degree;
        let ratios = scalars(&c.ratios)?;
        let weights = match &c.weights {
            Some(w) => scalars(w)?,
            None => vec![rat(1); curve.points().len()],
        };
        let sp = RationalSpline::new(n, curve.points(), &weights, &ratios)?;
        let segs = sp.to_bezier(c.method)?;
        Ok(match check_segments(&sp, &segs) {
            Ok(points) => verdict(
                true,
                "grid",
                format!(
                    "{} segments, each the NURBS on its span ({points} exact points, type ≤ ({n}, {n})), joins C^{}",
                    segs.len(),
                    n - 1
                ),
            ),
            Err(e) => verdict(false, "grid", format!("{e:?}")),
        })
    }
}

impl PatchEvaluations {
    /// Closed form (41), `u`-then-`v` and `v`-then-`u` agree on the type-bounded grid.
    ///
    /// # Errors
    /// A malformed claim.
    pub fn check(&self) -> Result<Outcome> {
        let c = self;
        let p = patch_of(&c.net, c.net_weights.as_deref())?;
        let (m, n) = p.degree();
        for i in 0..=2 * m {
            for j in 0..=2 * n {
                let (u, v) = (
                    BigRational::new((i as i64).into(), ((2 * m).max(1) as i64).into()),
                    BigRational::new((j as i64).into(), ((2 * n).max(1) as i64).into()),
                );
                let s = p.eval(&u, &v)?;
                if p.eval_u_then_v(&u, &v)? != s || p.eval_v_then_u(&u, &v)? != s {
                    return Ok(verdict(false, "exact-eval", format!("routes differ at (u, v) = ({u}, {v})")));
                }
            }
        }
        Ok(verdict(
            true,
            "grid",
            format!(
                "closed form (41) = u-then-v = v-then-u on a {}×{} grid (rational of type ({m},{m})×({n},{n}))",
                2 * m + 1,
                2 * n + 1
            ),
        ))
    }
}

impl PatchWeightChange {
    /// (48)–(49) against the patch with the changed weight, on the type-bounded grid.
    ///
    /// # Errors
    /// A malformed claim.
    pub fn check(&self) -> Result<Outcome> {
        let c = self;
        let p = patch_of(&c.net, c.net_weights.as_deref())?;
        let (i, j) = (c.index, c.index_v);
        let dw = num(&c.weight)?;
        let changed = p.with_weight_change(i, j, &dw)?;
        let (m, n) = p.degree();
        for a in 0..=2 * m {
            for b in 0..=2 * n {
                let (u, v) = (
                    BigRational::new((a as i64).into(), ((2 * m) as i64 + 1).into()),
                    BigRational::new((b as i64).into(), ((2 * n) as i64 + 1).into()),
                );
                let (claimed, truth) = (p.weight_change(i, j, &dw, &u, &v, c.formulas)?, changed.eval(&u, &v)?);
                if claimed != truth {
                    return Ok(verdict(
                        false,
                        "exact-eval",
                        format!("at (u, v) = ({u}, {v}): (49) gives {claimed}, the changed patch is at {truth}"),
                    ));
                }
            }
        }
        Ok(verdict(
            true,
            "grid",
            format!(
                "(49) ≡ the patch with w_{i}{j} + Δw on a {}×{} grid (type ({m},{m})×({n},{n}))",
                2 * m + 1,
                2 * n + 1
            ),
        ))
    }
}

impl Net {
    /// Every patch equals the tensor NURBS, joins are `C^(min−1)`, rows-first = columns-first.
    ///
    /// # Errors
    /// A malformed claim.
    pub fn check(&self) -> Result<Outcome> {
        let c = self;

        let (rows, weights) = net_rows(&c.net, c.net_weights.as_deref())?;
        let (nu, nv) = match &c.degrees {
            None => (2, 2),
            Some(d) => d
                .split_once(',')
                .and_then(|(a, b)| Some((a.trim().parse().ok()?, b.trim().parse().ok()?)))
                .ok_or_else(|| bad(format!("degrees must be \"nu,nv\", not {d:?}")))?,
        };
        let net = SplineNet::new((nu, nv), rows, weights, scalars(&c.ratios)?, scalars(&c.ratios_v)?)?;
        let r = net.check(c.method)?;
        let ok = r.order_independent && r.equals_nurbs && r.smooth_joins;
        Ok(verdict(
            ok,
            "grid",
            format!(
                "{} patches; equal to the tensor NURBS: {}; C^{} joins: {}; rows-first = columns-first: {}{}",
                r.patches,
                r.equals_nurbs,
                nu.min(nv) - 1,
                r.smooth_joins,
                r.order_independent,
                r.problem.map(|p| format!(" ({p})")).unwrap_or_default()
            ),
        ))
    }
}

type Grid = (Vec<Vec<Point<BigRational>>>, Vec<Vec<BigRational>>);

/// A patch or net: rows separated by `;`, points by `,`; weights likewise (default all 1).
fn net_rows(net: &str, net_weights: Option<&str>) -> Result<Grid> {
    let rows: Vec<Vec<Point<BigRational>>> =
        net.split(';').map(|r| parse_points(r.trim(), 3, None)).collect::<Result<_>>()?;
    let weights: Vec<Vec<BigRational>> = match net_weights {
        Some(w) => w.split(';').map(|r| scalars(r.trim())).collect::<Result<_>>()?,
        None => rows.iter().map(|r| vec![rat(1); r.len()]).collect(),
    };
    Ok((rows, weights))
}

/// The shape (rows, points in the longest row) of a patch or net and the largest bit length of
/// its coordinates and weights, for [`ClaimContent::estimate`](super::claims::ClaimContent::estimate).
pub(super) fn net_sizes(net: &str, net_weights: Option<&str>) -> Result<((usize, usize), u64)> {
    let (rows, weights) = net_rows(net, net_weights)?;
    let beta = rows
        .iter()
        .map(|r| crate::work::max_bits(r))
        .chain(weights.iter().map(|w| crate::work::max_bits_of(w)))
        .max()
        .unwrap_or(0);
    Ok(((rows.len(), rows.iter().map(Vec::len).max().unwrap_or(0)), beta))
}

fn patch_of(net: &str, net_weights: Option<&str>) -> Result<RationalPatch> {
    let (rows, weights) = net_rows(net, net_weights)?;
    RationalPatch::new(rows, weights)
}
