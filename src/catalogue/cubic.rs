//! Claim kinds about cubic curves (seed 004): classification, moving lines (3)–(8) and (2),
//! and the canonical maps (9)–(18).

use crate::catalogue::common::{Outcome, curve_from, tick, verdict};
use crate::classify::canonical::canonical_map;
use crate::classify::moving_line::MovingLines;
use crate::classify::{NodeType, classify};
use crate::error::Result;
use crate::num::point::Point;
use crate::num::scalar::{Exact, Scalar, rat};
use crate::proof::{self, Reading};
use num_rational::BigRational;
use serde::Deserialize;

/// `classification`: the exact classification against the given expectations (each optional).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClassificationClaim {
    /// Control points.
    pub curve: String,
    /// Expected class name.
    pub class: Option<String>,
    /// Expected node type.
    pub node_type: Option<String>,
    /// Expected double point.
    pub double_point: Option<Vec<String>>,
    /// Expected double-point (or cusp) parameters.
    pub parameters: Option<Vec<String>>,
    /// Expected inflection parameters.
    pub inflections: Option<Vec<String>>,
    /// Expected: loop on [0, 1].
    pub segment_loop: Option<bool>,
    /// Expected: cusp on [0, 1].
    pub segment_cusp: Option<bool>,
    /// Expected: inflections on [0, 1].
    pub segment_inflections: Option<usize>,
}

/// `moving-lines`: seed 004 (3)–(8) proved and compared with the power-form route.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MovingLinesClaim {
    /// Control points of a planar cubic.
    pub curve: String,
}

/// `moving-line-2`: seed 004 (2), `P[τ] × P[t] = (t − τ)·r(τ)·M·c(t)`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MovingLine2 {
    /// Control points of a planar cubic.
    pub curve: String,
    /// `r(τ)` as printed (a scalar applied to the sum of the rows) or corrected.
    #[serde(default = "as_printed")]
    pub formulas: Reading,
}

/// `canonical-map`: the affine map from the canonical cubic, proved in `Q(√3)(√r)`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CanonicalMapClaim {
    /// Control points of a genuine planar cubic.
    pub curve: String,
    /// The reference-point formulas (9), (12), (15)–(16) as printed or corrected.
    #[serde(default = "as_printed")]
    pub formulas: Reading,
}

fn as_printed() -> Reading {
    Reading::AsPrinted
}

impl CanonicalMapClaim {
    /// Builds the map (classifying the curve once) and proves `M·C(t̃) ≡ P(t)`.
    ///
    /// # Errors
    /// A malformed curve.
    pub fn check(&self) -> Result<Outcome> {
        let curve = curve_from(&self.curve)?;
        let map = classify(&curve).and_then(|k| {
            if k.node_type.is_none() || curve.degree() != 3 {
                return Err(crate::error::Error::Degenerate {
                    message: format!("canonical forms need a genuine cubic; this curve is {}", k.class),
                });
            }
            canonical_map(&curve, &k, &MovingLines::new(&curve)?, self.formulas)
        });
        Ok(match map {
            Ok(m) => match m.prove(&curve) {
                Ok(cert) => verdict(true, "grid", format!("M·C(t̃) ≡ P(t) in Q(√3)(√r): {cert}")),
                Err(e) => {
                    let pts: Vec<String> = m.points.iter().map(|(n, p)| format!("{n} = {p}")).collect();
                    verdict(false, "grid", format!("{}; {e}", pts.join(", ")))
                }
            },
            Err(e) => verdict(false, "exact-compare", e.to_string()),
        })
    }
}

impl ClassificationClaim {
    /// Each given expectation compared with the exact classification.
    ///
    /// # Errors
    /// A malformed or non-planar curve of degree above 3.
    pub fn check(&self) -> Result<Outcome> {
        let c = self;
        let curve = curve_from(&c.curve)?;
        let k = classify(&curve)?;
        let mut wrong = Vec::new();
        let mut check = |what: &str, found: String, expected: Option<String>| {
            if let Some(e) = expected
                && e != found
            {
                wrong.push(format!("{what} expected {e}, found {found}"));
            }
        };
        check("class", k.class.as_str().into(), c.class.clone());
        check("node_type", k.node_type.map_or("none".into(), |n| n.as_str().into()), c.node_type.clone());
        check(
            "double_point",
            k.double_point.as_ref().map_or("none".into(), |p| p.to_string()),
            c.double_point.as_ref().map(|p| format!("({})", p.join(", "))),
        );
        let params = if k.node_type == Some(NodeType::Cusp) { &k.cusp_parameters } else { &k.double_point_parameters };
        check(
            "parameters",
            format!("{:?}", params.iter().map(|p| p.to_string()).collect::<Vec<_>>()),
            c.parameters.as_ref().map(|p| format!("{p:?}")),
        );
        check(
            "inflections",
            format!("{:?}", k.inflection_parameters.iter().map(|p| p.to_string()).collect::<Vec<_>>()),
            c.inflections.as_ref().map(|p| format!("{p:?}")),
        );
        check("segment loop", k.segment.has_loop.to_string(), c.segment_loop.map(|b| b.to_string()));
        check("segment cusp", k.segment.has_cusp.to_string(), c.segment_cusp.map(|b| b.to_string()));
        check("segment inflections", k.segment.inflections.to_string(), c.segment_inflections.map(|b| b.to_string()));
        Ok(if wrong.is_empty() {
            verdict(true, "exact-compare", format!("{}: {}", k.class, k.reason))
        } else {
            verdict(false, "exact-compare", wrong.join("; "))
        })
    }
}

impl MovingLinesClaim {
    /// `P·L ≡ 0` proved, then (4), (7), (8) and the discriminant's sign compared with the power-form route.
    ///
    /// # Errors
    /// A malformed curve or one that is not a planar cubic.
    pub fn check(&self) -> Result<Outcome> {
        let curve = curve_from(&self.curve)?;
        let ml = MovingLines::new(&curve)?;
        if let Err(e) = ml.verify() {
            return Ok(verdict(false, "grid", format!("P[t]·L[t] ≢ 0: {e}")));
        }
        let k = classify(&curve)?;
        let Some((te, _)) = k.t_e_and_d.clone() else {
            let at_inf = ml.double_point.coords[2].is_zero();
            return Ok(verdict(
                at_inf,
                "grid",
                format!("P·L0 ≡ P·L1 ≡ 0 proved; D = L00 × L01 = {} (at infinity: {at_inf})", ml.double_point),
            ));
        };
        let node = k.node_type.expect("genuine cubic");
        let d_ok = ml.double_point.from_homogeneous() == k.double_point;
        let te_ok = ml.t_e() == Some(te.clone());
        let e_ok = ml.e_point().and_then(|e| e.from_homogeneous()) == Some(curve.eval(&te));
        let (_, disc) = ml.f_and_discriminant();
        let expected_sign = match node {
            NodeType::Crunode => std::cmp::Ordering::Greater,
            NodeType::Cusp => std::cmp::Ordering::Equal,
            _ => std::cmp::Ordering::Less,
        };
        let sign_ok = disc.sign() == expected_sign;
        Ok(verdict(
            d_ok && te_ok && e_ok && sign_ok,
            "grid",
            format!(
                "P·L0 ≡ P·L1 ≡ 0 proved; (4) D = {} {}; (7) t_E = {te} {}; (8) E = P(t_E) {}; sign of disc(L1[t]·D) gives {} {}",
                k.double_point.as_ref().expect("D"),
                tick(d_ok),
                tick(te_ok),
                tick(e_ok),
                node.as_str(),
                tick(sign_ok)
            ),
        ))
    }
}

/// Seed 004 (2): `L[t] = P[τ] × P[t] = (t − τ)·r(τ)·M·c(t)` with `c(t) = ((1−t)², (1−t)t, t²)` and
/// `M` the matrix of cross products `Q_i × Q_j`.
impl MovingLine2 {
    /// The cross-product identity proved on a 4×4 grid in `(τ, t)`.
    ///
    /// # Errors
    /// A malformed curve or one that is not a planar cubic.
    pub fn check(&self) -> Result<Outcome> {
        let curve = curve_from(&self.curve)?;
        let ml = MovingLines::new(&curve)?;
        let q = &ml.q;
        let x = |a: &Point<BigRational>, b: &Point<BigRational>| a.cross(b).expect("3-vectors");
        let m = [
            [x(&q[0], &q[1]), x(&q[0], &q[2]), x(&q[0], &q[3])],
            [x(&q[0], &q[2]), x(&q[0], &q[3]).add(&x(&q[1], &q[2])), x(&q[1], &q[3])],
            [x(&q[0], &q[3]), x(&q[1], &q[3]), x(&q[2], &q[3])],
        ];
        let printed = self.formulas == Reading::AsPrinted;
        let res = proof::identities::<BigRational>(&[3, 3], |v| {
            let (tau, t) = (&v[0], &v[1]);
            let (u, ut) = (rat(1) - tau, rat(1) - t);
            let col = [ut.clone() * &ut, ut.clone() * t, t.clone() * t];
            let row: [BigRational; 3] = if printed {
                let s = u.clone() * &u * &ut * tau - tau.clone() * tau;
                [s.clone(), s.clone(), s]
            } else {
                [u.clone() * &u, u.clone() * tau, tau.clone() * tau]
            };
            let mut rhs = Point::origin(3);
            for a in 0..3 {
                for b in 0..3 {
                    rhs = rhs.add(&m[a][b].scale(&(row[a].clone() * &col[b])));
                }
            }
            let rhs = rhs.scale(&(t.clone() - tau));
            x(&ml.point(tau), &ml.point(t)).sub(&rhs).coords
        });
        Ok(match res {
            Ok(cert) => verdict(true, "grid", format!("P[τ] × P[t] ≡ (t − τ) r(τ) M c(t): {cert}")),
            Err(e) => verdict(
                false,
                "grid",
                format!(
                    "at (τ, t) = ({}, {}) coordinate {} differs by {}",
                    e.point[0], e.point[1], e.identity, e.value
                ),
            ),
        })
    }
}
