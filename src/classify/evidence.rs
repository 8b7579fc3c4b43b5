//! The expensive evidence behind a cubic's classification, for `classify --json`: the seed's
//! moving lines with their verification `P·L ≡ 0`, the proved canonical map, and the
//! Loop–Blinn cross-check — computed from an existing [`Classification`], never classifying
//! again.

use crate::classify::canonical::{CanonicalMap, canonical_map};
use crate::classify::moving_line::MovingLines;
use crate::classify::{Classification, NodeType, loop_blinn};
use crate::curve::bezier::BezierCurve;
use crate::error::Result;
use crate::num::point::Point;
use crate::num::serial;
use crate::proof::Reading;
use num_rational::BigRational;
use serde::Serialize;
use std::collections::BTreeMap;

/// Seed 004 (3)–(8): the moving lines `L0 = (L00, L01)`, `L1 = (L10, L11, L12)`, the double
/// point `D` (homogeneous), `t_E`, and whether `P·L0 ≡ P·L1 ≡ 0` was proved.
#[derive(Clone, Debug, Serialize)]
#[allow(non_snake_case)]
pub struct MovingLinesEvidence {
    /// `L0[0]`.
    pub L00: Point<BigRational>,
    /// `L0[1]`.
    pub L01: Point<BigRational>,
    /// `L1[0]`.
    pub L10: Point<BigRational>,
    /// `L1[1]`.
    pub L11: Point<BigRational>,
    /// `L1[2]`.
    pub L12: Point<BigRational>,
    /// `D = L00 × L01`, homogeneous.
    pub D: Point<BigRational>,
    /// `t_E` of (7), when defined.
    #[serde(serialize_with = "serial::option_string")]
    pub t_E: Option<BigRational>,
    /// `P[t]·L0[t] ≡ P[t]·L1[t] ≡ 0` proved on a grid.
    pub verified: bool,
}

/// The canonical map `M` with `P(t) = M·C((t − t_E)/(t_F − t_E))`, proved or refuted.
#[derive(Clone, Debug, Serialize)]
#[allow(non_snake_case)]
pub struct CanonicalEvidence {
    /// The canonical curve's equation.
    pub equation: &'static str,
    /// `M`, 2×3, exact in `Q(√3)(√r)`.
    pub matrix: Vec<Vec<String>>,
    /// `t_E`.
    #[serde(serialize_with = "serial::string")]
    pub t_E: BigRational,
    /// `t_F`.
    #[serde(serialize_with = "serial::string")]
    pub t_F: crate::classify::canonical::Tower,
    /// `"(t - t_E)/(t_F - t_E)"`.
    pub parameter: &'static str,
    /// The reference points used.
    pub points: BTreeMap<String, Point<crate::classify::canonical::Tower>>,
    /// The map was proved.
    pub proved: bool,
    /// The certificate, or `counterexample …`.
    pub certificate: String,
}

/// The Loop–Blinn discriminants and the node type they imply.
#[derive(Clone, Debug, Serialize)]
pub struct LoopBlinnEvidence {
    /// `d1`.
    #[serde(serialize_with = "serial::string")]
    pub d1: BigRational,
    /// `d2`.
    #[serde(serialize_with = "serial::string")]
    pub d2: BigRational,
    /// `d3`.
    #[serde(serialize_with = "serial::string")]
    pub d3: BigRational,
    /// The implied node type (`null` unless a genuine cubic).
    pub node_type: Option<NodeType>,
}

/// All evidence for a cubic (the fields `moving_lines`, `canonical` when the curve has one,
/// and `loop_blinn`).
#[derive(Clone, Debug, Serialize)]
pub struct CubicEvidence {
    /// Seed 004 (3)–(8).
    pub moving_lines: MovingLinesEvidence,
    /// The proved canonical map of a genuine cubic.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub canonical: Option<CanonicalEvidence>,
    /// The Loop–Blinn cross-check.
    pub loop_blinn: LoopBlinnEvidence,
}

impl CanonicalEvidence {
    /// The map in exact strings, with its proof attempted on `curve`.
    pub fn new(map: &CanonicalMap, curve: &BezierCurve<BigRational>) -> Self {
        let proved = map.prove(curve);
        CanonicalEvidence {
            equation: map.node.canonical_equation(),
            matrix: map.matrix.iter().map(|r| r.iter().map(|x| x.to_string()).collect()).collect(),
            t_E: map.t_e.clone(),
            t_F: map.t_f.clone(),
            parameter: "(t - t_E)/(t_F - t_E)",
            points: map.points.iter().map(|(n, p)| (n.to_string(), p.clone())).collect(),
            proved: proved.is_ok(),
            certificate: match &proved {
                Ok(c) => c.to_string(),
                Err(e) => format!("counterexample {e}"),
            },
        }
    }
}

/// The evidence for the cubic `curve` whose classification is `k` (`None` below degree 3).
///
/// # Errors
/// Those of [`MovingLines::new`] (a curve that is not a planar cubic).
pub(crate) fn cubic_evidence(curve: &BezierCurve<BigRational>, k: &Classification) -> Result<Option<CubicEvidence>> {
    if curve.degree() != 3 {
        return Ok(None);
    }
    let ml = MovingLines::new(curve)?;
    let moving_lines = MovingLinesEvidence {
        L00: ml.l0[0].clone(),
        L01: ml.l0[1].clone(),
        L10: ml.l1[0].clone(),
        L11: ml.l1[1].clone(),
        L12: ml.l1[2].clone(),
        D: ml.double_point.clone(),
        t_E: ml.t_e(),
        verified: ml.verify().is_ok(),
    };
    let canonical = if k.node_type.is_some() {
        canonical_map(curve, k, &ml, Reading::Corrected).ok().map(|m| CanonicalEvidence::new(&m, curve))
    } else {
        None
    };
    let (lb, node_type) = loop_blinn(curve);
    let [d1, d2, d3] = lb;
    Ok(Some(CubicEvidence { moving_lines, canonical, loop_blinn: LoopBlinnEvidence { d1, d2, d3, node_type } }))
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    use super::*;
    #[test]
    fn cubic_evidence_example() {
        use crate::classify::classify;
        use crate::{BezierCurve, num::parse_points};
        let c = BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap();
        let k = classify(&c).unwrap();
        let e = cubic_evidence(&c, &k).unwrap().unwrap();
        assert!(e.moving_lines.verified);
        assert!(e.canonical.unwrap().proved);
    }
}
