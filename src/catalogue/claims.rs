//! The kinds of claim a `proofs/` file can state: one [`ClaimContent`] variant per kind, each
//! with its own typed fields and its own check, grouped by family in
//! [`polynomial`], [`cubic`], [`rational`] and [`surface`].
//!
//! | kind | fields | check |
//! | --- | --- | --- |
//! | `identity` | `vars`, `params`, `lhs`, `rhs` | grid proof per parameter instance; degree bounds derived from the expressions |
//! | `curve-formula` | `curve`, `weights?`, `x`, `y`, `z?` (expressions in `t`) | grid proof in `t` that the (rational) curve equals the formula |
//! | `power-form` | `curve`, `power` | exact power coefficients (seed 003's matrix product) |
//! | `subdivision` | `curve`, `t`, `left`, `right` | exact halves, and Lemma 2 proved for the curve |
//! | `lemma-2` | `degree` | Lemma 2 for every curve of degree `n ≤ degree`: control points as variables (degree 1 each), `t0`, `s` (degree `n`) |
//! | `repeated-subdivision` | `curve`, `t`, `depth`, `pieces` | every piece proved equal to the curve on its interval |
//! | `matrix` | `degree`, `rows` | the Bernstein → power matrix |
//! | `table` | `curve`, `steps` or `ts`, `values` | exact values at the parameters |
//! | `basis-table` | `degree`, `steps` or `ts`, `rows` | `B_i^n(t_k)` exactly |
//! | `classification` | `curve`, optional `class`, `node_type`, `double_point`, `parameters`, `inflections`, `segment_*` | exact classification |
//! | `moving-lines` | `curve` | seed 004 (3)–(8) proved and compared with the power-form route |
//! | `moving-line-2` | `curve`, `formulas` | seed 004 (2): `P[τ] × P[t] = (t − τ)·r(τ)·M·c(t)`, degree ≤ 3 in `τ` and `t` (4×4 grid); as printed `r(τ)` is the scalar `(1−τ)²(1−t)τ − τ²` applied to the sum of the rows |
//! | `canonical-map` | `curve`, `formulas` | the affine map from the canonical cubic, proved in `Q(√3)(√r)` |
//! | `implicit` | `curve` + `weights`, or `homogeneous`; `poly` | `W^d f(X/W) ≡ 0`, degree ≤ `n·d`: proved at `n·d + 1` parameters (seed 000 examples) |
//! | `rational-evaluations` | rational curve | closed form (14), seed 000's recursion and Saito–Hosaka (19)–(20) are rational functions of type ≤ `(n, n)` in `t`, so agreeing at `2n + 1` parameters proves them equal |
//! | `rational-elevation` | rational curve | (22) gives the homogeneous elevation's points and weights |
//! | `rational-subdivision` | rational curve, `t` | the halves equal the curve on `[0, t]`, `[t, 1]`; the left control points are (19)–(20)'s |
//! | `weight-pull` | rational curve, `index`, `weight` | raising a weight moves every point of `(0, 1)` strictly towards that control point: (23) with `γ_i = B_i^n` proved, `γ_iΔw > 0` and `W > 0` on `(0, 1)` |
//! | `spline-segments` | `curve`, `weights`, `ratios`, `degree`, `method` | the rational Bézier segments equal the NURBS on each span (type-bounded grid) and join `C^{n−1}` |
//! | `patch-evaluations` | `net` (one patch), `net_weights` | closed form (41), de Casteljau `u`-then-`v` and `v`-then-`u` agree on a `(2m+1)×(2n+1)` grid (rational of type `(m,m)×(n,n)`) |
//! | `patch-weight-change` | `net`, `net_weights`, `index`, `index_v`, `weight` (Δw), `formulas` | (48)–(49) with the printed `γ` or the Bernstein one, on the type-bounded grid |
//! | `net` | `net`, `net_weights`, `ratios`, `ratios_v`, `degrees`, `method` | every patch equals the tensor NURBS, joins are `C^{min−1}`, and rows-first = columns-first |
//!
//! `formulas` is a [`Reading`](crate::proof::Reading): `"as-printed"` (the default) or
//! `"corrected"`; `method` a [`Conversion`](crate::spline::Conversion): `"boehm"` (the
//! default), `"seed"` or `"seed-printed"`. Unknown kinds and unknown or missing fields are
//! errors when the file is read, before anything is checked.

use super::common::Outcome;
use super::{cubic, polynomial, rational, surface};
use crate::error::Result;
use serde::Deserialize;

/// A claim's checkable content: its `kind` and that kind's fields.
#[derive(Clone, Debug, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum ClaimContent {
    /// A polynomial identity.
    Identity(polynomial::Identity),
    /// A curve equal to formulas in `t`.
    CurveFormula(polynomial::CurveFormula),
    /// Power coefficients.
    PowerForm(polynomial::PowerForm),
    /// The halves at `t`.
    Subdivision(polynomial::Subdivision),
    /// Lemma 2 in general.
    #[serde(rename = "lemma-2")]
    Lemma2(polynomial::Lemma2),
    /// Repeated subdivision.
    RepeatedSubdivision(polynomial::RepeatedSubdivision),
    /// The Bernstein → power matrix.
    Matrix(polynomial::Matrix),
    /// A table of curve values.
    Table(polynomial::Table),
    /// A table of Bernstein values.
    BasisTable(polynomial::BasisTable),
    /// A cubic's classification.
    Classification(cubic::ClassificationClaim),
    /// Seed 004 (3)–(8).
    MovingLines(cubic::MovingLinesClaim),
    /// Seed 004 (2).
    #[serde(rename = "moving-line-2")]
    MovingLine2(cubic::MovingLine2),
    /// A canonical map.
    CanonicalMap(cubic::CanonicalMapClaim),
    /// An implicit equation of a rational curve.
    Implicit(rational::Implicit),
    /// The three evaluations of a rational curve.
    RationalEvaluations(rational::RationalEvaluations),
    /// Rational degree elevation (22).
    RationalElevation(rational::RationalElevation),
    /// Rational subdivision (19)–(20).
    RationalSubdivision(rational::RationalSubdivision),
    /// Weight pull (23).
    WeightPull(rational::WeightPull),
    /// Spline segments.
    SplineSegments(surface::SplineSegments),
    /// Three evaluations of a patch.
    PatchEvaluations(surface::PatchEvaluations),
    /// Patch weight change (48)–(49).
    PatchWeightChange(surface::PatchWeightChange),
    /// A spline net.
    Net(surface::Net),
}

impl ClaimContent {
    /// Checks the content exactly: one check function per kind.
    ///
    /// # Errors
    /// A malformed claim (bad number, polygon or expression; a size past a limit).
    pub fn check(&self) -> Result<Outcome> {
        match self {
            ClaimContent::Identity(c) => c.check(),
            ClaimContent::CurveFormula(c) => c.check(),
            ClaimContent::PowerForm(c) => c.check(),
            ClaimContent::Subdivision(c) => c.check(),
            ClaimContent::Lemma2(c) => c.check(),
            ClaimContent::RepeatedSubdivision(c) => c.check(),
            ClaimContent::Matrix(c) => c.check(),
            ClaimContent::Table(c) => c.check(),
            ClaimContent::BasisTable(c) => c.check(),
            ClaimContent::Classification(c) => c.check(),
            ClaimContent::MovingLines(c) => c.check(),
            ClaimContent::MovingLine2(c) => c.check(),
            ClaimContent::CanonicalMap(c) => c.check(),
            ClaimContent::Implicit(c) => c.check(),
            ClaimContent::RationalEvaluations(c) => c.check(),
            ClaimContent::RationalElevation(c) => c.check(),
            ClaimContent::RationalSubdivision(c) => c.check(),
            ClaimContent::WeightPull(c) => c.check(),
            ClaimContent::SplineSegments(c) => c.check(),
            ClaimContent::PatchEvaluations(c) => c.check(),
            ClaimContent::PatchWeightChange(c) => c.check(),
            ClaimContent::Net(c) => c.check(),
        }
    }
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    #[test]
    fn claim_content_example() {
        use crate::catalogue::ClaimContent;
        let c: ClaimContent = toml::from_str(
            r#"
            kind = "identity"
            vars = ["t"]
            lhs = "(1 - t)^2 + 2*(1 - t)*t + t^2"
            rhs = "1"
        "#,
        )
        .unwrap();
        let outcome = c.check().unwrap();
        assert!(outcome.holds);
        assert_eq!(outcome.method, "grid");
    }
}
