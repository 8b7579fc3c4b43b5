//! Claim kinds about rational curves (seed 000, seed 002 §2): implicit equations, the three
//! evaluations, elevation (22), subdivision (19)–(20) and the weight pull (23).

use crate::catalogue::common::{Outcome, bad, num, parameters_where, rational_curve, verdict};
use crate::error::Result;
use crate::num::point::Point;
use crate::num::scalar::{Exact, rat};
use crate::proof::Reading;
use crate::rational::implicit::{ImplicitOutcome, prove_implicit};
use num_rational::BigRational;
use serde::Deserialize;

macro_rules! rational_claim {
    ($(#[$doc:meta])* $name:ident { $($(#[$fdoc:meta])* $field:ident: $ty:ty),* }) => {
        $(#[$doc])*
        #[derive(Clone, Debug, Deserialize)]
        #[serde(deny_unknown_fields)]
        pub struct $name {
            /// Control points (with `weights`), or use `homogeneous`.
            pub curve: Option<String>,
            /// Weights (default all 1).
            pub weights: Option<String>,
            /// Homogeneous control points `w·x w·y w, …` (`w = 0`: at infinity).
            pub homogeneous: Option<String>,
            $($(#[$fdoc])* pub $field: $ty,)*
        }
    };
}

rational_claim!(
    /// `implicit`: the rational curve lies on `poly = 0`.
    Implicit {
        /// The implicit polynomial in `x, y[, z]`.
        poly: String
    }
);
rational_claim!(
    /// `rational-evaluations`: closed form (14), seed 000's recursion and Saito–Hosaka (19)–(20)
    /// agree.
    RationalEvaluations {}
);
rational_claim!(
    /// `rational-elevation`: (22) gives the homogeneous elevation's points and weights.
    RationalElevation {}
);
rational_claim!(
    /// `rational-subdivision`: the halves at `t`.
    RationalSubdivision {
        /// The split parameter.
        t: String
    }
);
rational_claim!(
    /// `weight-pull`: raising weight `index` to `weight` pulls every point of `(0, 1)` towards
    /// that control point.
    WeightPull {
        /// The control point index.
        index: usize,
        /// The new (larger) weight.
        weight: String
    }
);

impl Implicit {
    /// `W^d f(X/W) ≡ 0` proved (seed 000 examples).
    ///
    /// # Errors
    /// A malformed claim.
    pub fn check(&self) -> Result<Outcome> {
        let c = self;
        let r = rational_curve(c.curve.as_deref(), c.weights.as_deref(), c.homogeneous.as_deref())?;
        Ok(match prove_implicit(&r, &c.poly)? {
            ImplicitOutcome::Proved { degree_bound, parameters } => verdict(
                true,
                "grid",
                format!(
                    "W^d f(X/W) has degree ≤ {degree_bound} in t and vanishes at {} parameters with W ≠ 0",
                    parameters.len()
                ),
            ),
            ImplicitOutcome::Counterexample { t, point, value } => {
                verdict(false, "exact-eval", format!("at t = {t}, x(t) = {point} and f = {value}"))
            }
        })
    }
}

impl RationalEvaluations {
    /// Three routes agree at `2n + 1` parameters.
    ///
    /// # Errors
    /// A malformed claim, or too few parameters where every route is defined.
    pub fn check(&self) -> Result<Outcome> {
        let c = self;
        let r = rational_curve(c.curve.as_deref(), c.weights.as_deref(), c.homogeneous.as_deref())?;
        let r = &r;
        let n = r.degree();
        let ts =
            parameters_where(2 * n + 1, |t| r.eval_rational_de_casteljau(t).is_ok() && r.eval_saito_hosaka(t).is_ok());
        if ts.len() < 2 * n + 1 {
            return Err(bad("too few parameters where every route is defined"));
        }
        for t in &ts {
            let x = r.eval(t)?;
            for (name, y) in [
                ("seed 000 recursion", r.eval_rational_de_casteljau(t)?),
                ("Saito–Hosaka (19)–(20)", r.eval_saito_hosaka(t)?),
            ] {
                if y != x {
                    return Ok(verdict(false, "exact-eval", format!("at t = {t}: (14) gives {x}, {name} gives {y}")));
                }
            }
        }
        Ok(verdict(
            true,
            "grid",
            format!("three routes, rational of type ≤ ({n}, {n}) in t, agree at {} parameters", ts.len()),
        ))
    }
}

impl RationalElevation {
    /// (22) compared with the homogeneous elevation.
    ///
    /// # Errors
    /// A malformed claim.
    pub fn check(&self) -> Result<Outcome> {
        let c = self;
        let r = rational_curve(c.curve.as_deref(), c.weights.as_deref(), c.homogeneous.as_deref())?;
        let (h, sh) = (r.elevate(1)?, r.elevate_saito_hosaka()?);
        let same = h.points() == sh.points() && h.weights().iter().zip(sh.weights()).all(|(a, b)| *a == b);
        Ok(verdict(
            same,
            "exact-compare",
            if same {
                format!("(22) gives the {} control points and weights of the homogeneous elevation", r.degree() + 2)
            } else {
                format!(
                    "(22): {:?} / {:?}; homogeneous: {:?} / {:?}",
                    sh.points(),
                    sh.weights(),
                    h.points(),
                    h.weights()
                )
            },
        ))
    }
}

impl RationalSubdivision {
    /// The halves equal the curve on their intervals; the left control points are those of (19)–(20).
    ///
    /// # Errors
    /// A malformed claim.
    pub fn check(&self) -> Result<Outcome> {
        let c = self;
        let r = rational_curve(c.curve.as_deref(), c.weights.as_deref(), c.homogeneous.as_deref())?;
        let t0 = num(&c.t)?;
        let (l, rt) = r.subdivide(&t0)?;
        let n = r.degree();
        // the halves are rational of type ≤ (n, n) in s: 2n + 1 parameters decide each
        let ts = parameters_where(2 * n + 1, |s| {
            r.eval(&(t0.clone() * s)).is_ok() && r.eval(&(t0.clone() + (rat(1) - &t0) * s)).is_ok()
        });
        for s in &ts {
            let (a, b) = (r.eval(&(t0.clone() * s))?, r.eval(&(t0.clone() + (rat(1) - &t0) * s))?);
            if l.eval(s)? != a || rt.eval(s)? != b {
                return Ok(verdict(false, "exact-eval", format!("a half differs from the curve at s = {s}")));
            }
        }
        // the left half's control points are the rational interpolation points of (19)–(20)
        let mut row: Vec<Point<BigRational>> =
            r.points().into_iter().collect::<Option<_>>().ok_or_else(|| bad("finite points"))?;
        let mut left = vec![row[0].clone()];
        for k in 1..=n {
            let u = rat(1) - &t0;
            row = (0..row.len() - 1)
                .map(|i| {
                    let a = t0.clone() * r.shifted_weight(i + 1, k - 1, &t0);
                    let b = u.clone() * r.shifted_weight(i, k - 1, &t0);
                    crate::rational::rational_bezier::divide(&a, &b, &row[i], &row[i + 1])
                        .ok_or_else(|| bad("vanishing ratio"))
                })
                .collect::<Result<_>>()?;
            left.push(row[0].clone());
        }
        let found: Vec<Point<BigRational>> =
            l.points().into_iter().collect::<Option<_>>().ok_or_else(|| bad("finite points"))?;
        Ok(verdict(
            found == left,
            "grid",
            format!(
                "halves ≡ the curve on [0, t0] and [t0, 1] ({} parameters each); left control points = P0, Pa, Pd, …, P of (19)–(20): {}",
                ts.len(),
                found == left
            ),
        ))
    }
}

impl WeightPull {
    /// (23) with `γ = B_i^n` proved, and the strict pull on `(0, 1)`.
    ///
    /// # Errors
    /// A malformed claim.
    pub fn check(&self) -> Result<Outcome> {
        let c = self;
        let r = rational_curve(c.curve.as_deref(), c.weights.as_deref(), c.homogeneous.as_deref())?;
        let i = c.index;
        let w_new = num(&c.weight)?;
        let dw = w_new.clone() - r.weights().get(i).ok_or_else(|| bad(format!("no control point {i}")))?;
        if dw.sign() != std::cmp::Ordering::Greater {
            return Err(bad("weight-pull needs a larger new weight"));
        }
        let moved = r.with_weight(i, w_new)?;
        let open = (rat(0), rat(1));
        for (name, curve) in [("W", &r), ("W'", &moved)] {
            if let Err(e) = curve.check_defined(&open.0, &open.1) {
                return Ok(verdict(false, "exact-eval", format!("{name}: {e}")));
            }
        }
        let n = r.degree();
        for t in parameters_where(2 * n + 1, |_| true) {
            let (claimed, truth) = (r.weight_change(i, &dw, &t, Reading::Corrected)?, moved.eval(&t)?);
            if claimed != truth {
                return Ok(verdict(false, "exact-eval", format!("(23) at t = {t}: {claimed} ≠ {truth}")));
            }
        }
        Ok(verdict(
            true,
            "grid",
            format!(
                "(23) with γ = B_{i}^{n} proved (type ≤ ({n}, {n}), {} points); W, W' > 0 and γΔw > 0 on (0, 1): every point moves strictly towards b_{i}",
                2 * n + 1
            ),
        ))
    }
}
