//! Proof by exact testing: the grid prover.
//!
//! A polynomial `f(x_1, …, x_k)` of degree at most `d_j` in each variable `x_j` that vanishes on
//! a grid `G_1 × … × G_k` of distinct values, `|G_j| = d_j + 1`, is the zero polynomial
//! (induction on `k`: for each fixed grid value of `x_1..x_{k−1}` a univariate polynomial of
//! degree ≤ `d_k` with `d_k + 1` roots is zero). So an identity `lhs = rhs` whose difference
//! obeys the degree bounds is **proved** by checking it exactly on the grid — and refuted, with
//! an exact counterexample, when one grid point fails.
//!
//! The closure is generic code run over an [`Exact`] scalar; the caller vouches for the degree
//! bounds (they are part of the statement being proved, and appear in the certificate).
//!
//! # Example
//! ```
//! use casteljau::{proof, Scalar};
//! use num_rational::BigRational;
//! // (s + t)² = s² + 2st + t²: degree ≤ 2 in s and in t.
//! let cert = proof::identity::<BigRational>(&[2, 2], |v| {
//!     let (s, t) = (&v[0], &v[1]);
//!     let l = (s.clone() + t) * (s.clone() + t);
//!     l - (s.clone() * s + BigRational::from_i64(2) * s * t + t.clone() * t)
//! }).unwrap();
//! assert_eq!(cert.points_checked, 9);
//! // A wrong identity yields an exact counterexample.
//! let err = proof::identity::<BigRational>(&[2, 2], |v| {
//!     let (s, t) = (&v[0], &v[1]);
//!     (s.clone() + t) * (s.clone() + t) - (s.clone() * s + t.clone() * t)
//! }).unwrap_err();
//! assert!(!err.value.is_zero());
//! ```

pub mod expr;

/// Which statement of a seed's claim is meant: the one **as printed** (which may be wrong: the
/// seeds are OCR'd and contain errors) or the **corrected** one that holds. One enum for every
/// claim with two readings (canonical maps, spline formulas, weight changes, Menelaus ratios).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Reading {
    /// The formula exactly as printed in the seed.
    AsPrinted,
    /// The statement that holds (identical to the printed one where the seed is right).
    Corrected,
}

use crate::error::{Error, Result};
use crate::num::scalar::Exact;
use std::fmt;

/// Largest number of grid points one check may visit.
pub(crate) const MAX_GRID_POINTS: usize = 50_000_000;

/// Evidence that an identity holds: the degree bounds and the grid it vanished on. Its JSON:
/// `degrees`, `nodes` (exact strings), `points_checked`, `identities`.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Certificate {
    /// Per-variable degree bounds `d_j`.
    pub degrees: Vec<usize>,
    /// Grid values per variable (`d_j + 1` distinct exact values each), as exact strings.
    pub nodes: Vec<Vec<String>>,
    /// Number of grid points evaluated.
    pub points_checked: usize,
    /// Number of identities checked on each point (for batched checks).
    pub identities: usize,
}

impl fmt::Display for Certificate {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let sizes: Vec<String> = self.nodes.iter().map(|n| n.len().to_string()).collect();
        let degs: Vec<String> = self.degrees.iter().map(|d| d.to_string()).collect();
        write!(
            f,
            "degree ≤ ({}) per variable; vanishes on a {} grid of distinct exact points ({} points",
            degs.join(", "),
            sizes.join("×"),
            self.points_checked
        )?;
        if self.identities > 1 {
            write!(f, ", {} identities each", self.identities)?;
        }
        write!(f, ")")
    }
}

/// An exact point where an identity fails. Its JSON: `point`, `value` (exact strings),
/// `identity`.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Counterexample<S: fmt::Display> {
    /// The variables' values.
    #[serde(serialize_with = "crate::num::serial::strings")]
    pub point: Vec<S>,
    /// The (non-zero) value of `lhs − rhs` there.
    #[serde(serialize_with = "crate::num::serial::string")]
    pub value: S,
    /// Which identity of a batch failed (0 for a single identity).
    pub identity: usize,
}

impl<S: fmt::Display> fmt::Display for Counterexample<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let pt: Vec<String> = self.point.iter().map(|v| v.to_string()).collect();
        write!(f, "at ({}) lhs − rhs = {}", pt.join(", "), self.value)
    }
}

/// A grid of distinct exact values per variable.
#[derive(Clone, Debug)]
pub struct GridProver<S> {
    degrees: Vec<usize>,
    nodes: Vec<Vec<S>>,
}

/// A value that occurs twice in `vals`, if any: the values are sorted by the exact sign of
/// their differences and neighbours compared with `==`, `O(d log d)` exact operations instead
/// of the `O(d²)` pairs.
fn repeated_value<S: Exact>(vals: &[S]) -> Option<&S> {
    let mut sorted: Vec<&S> = vals.iter().collect();
    sorted.sort_by(|a, b| ((*a).clone() - (*b).clone()).sign());
    sorted.windows(2).find(|w| w[0] == w[1]).map(|w| w[0])
}

impl<S: Exact> GridProver<S> {
    /// The default grid: the integers `0, 1, …, d_j` for variable `j`.
    ///
    /// # Errors
    /// [`Error::TooLarge`] when the grid has more than 5·10⁷ (`MAX_GRID_POINTS`) points.
    pub fn new(degrees: &[usize]) -> Result<Self> {
        let nodes = degrees.iter().map(|&d| (0..=d as i64).map(S::from_i64).collect()).collect();
        Self::with_nodes(degrees, nodes)
    }

    /// A grid with given values; variable `j` needs at least `d_j + 1` pairwise distinct values
    /// (only the first `d_j + 1` are used).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for too few or repeated values, [`Error::TooLarge`] as in
    /// [`Self::new`].
    pub fn with_nodes(degrees: &[usize], nodes: Vec<Vec<S>>) -> Result<Self> {
        if nodes.len() != degrees.len() {
            return Err(Error::InvalidArgument {
                message: format!("{} degree bounds but {} node lists", degrees.len(), nodes.len()),
            });
        }
        let mut total: usize = 1;
        let mut kept = Vec::with_capacity(nodes.len());
        for (j, (d, mut vals)) in degrees.iter().zip(nodes).enumerate() {
            if vals.len() <= *d {
                return Err(Error::InvalidArgument {
                    message: format!("variable {j} needs {} grid values, got {}", d + 1, vals.len()),
                });
            }
            vals.truncate(d + 1);
            if let Some(v) = repeated_value(&vals) {
                return Err(Error::InvalidArgument { message: format!("variable {j}: grid value {v} repeats") });
            }
            total = total.saturating_mul(d + 1);
            kept.push(vals);
        }
        if total > MAX_GRID_POINTS {
            return Err(Error::TooLarge { what: "grid points", value: total, limit: MAX_GRID_POINTS });
        }
        Ok(GridProver { degrees: degrees.to_vec(), nodes: kept })
    }

    /// Checks a batch of identities `f(x) = 0` (each entry of the returned vector one identity,
    /// all obeying the same degree bounds) on every grid point, in lexicographic order.
    ///
    /// # Errors
    /// The first failing point as a [`Counterexample`].
    pub fn check_all(&self, mut f: impl FnMut(&[S]) -> Vec<S>) -> std::result::Result<Certificate, Counterexample<S>> {
        match self.try_check_all(|x| Ok::<_, std::convert::Infallible>(f(x))) {
            Ok(r) => r,
            Err(never) => match never {},
        }
    }

    /// [`Self::check_all`] for a closure that may fail at a point (e.g. a vanishing
    /// denominator): the closure's error stops the check and is returned as the outer `Err`,
    /// so the caller can choose other grid values.
    ///
    /// # Errors
    /// The closure's error.
    pub fn try_check_all<E>(
        &self,
        mut f: impl FnMut(&[S]) -> std::result::Result<Vec<S>, E>,
    ) -> std::result::Result<std::result::Result<Certificate, Counterexample<S>>, E> {
        let k = self.nodes.len();
        let mut index = vec![0usize; k];
        let mut point: Vec<S> = self.nodes.iter().map(|n| n[0].clone()).collect();
        let mut checked = 0;
        let mut identities = 0;
        loop {
            let values = f(&point)?;
            identities = identities.max(values.len());
            if let Some((i, v)) = values.into_iter().enumerate().find(|(_, v)| !v.is_zero()) {
                return Ok(Err(Counterexample { point, value: v, identity: i }));
            }
            checked += 1;
            // advance the odometer, last variable fastest
            let mut j = k;
            loop {
                if j == 0 {
                    return Ok(Ok(self.certificate(checked, identities)));
                }
                j -= 1;
                index[j] += 1;
                if index[j] < self.nodes[j].len() {
                    point[j] = self.nodes[j][index[j]].clone();
                    break;
                }
                index[j] = 0;
                point[j] = self.nodes[j][0].clone();
            }
        }
    }

    /// Checks one identity `f(x) = 0` on the grid.
    ///
    /// # Errors
    /// The first failing point as a [`Counterexample`].
    pub fn check(&self, mut f: impl FnMut(&[S]) -> S) -> std::result::Result<Certificate, Counterexample<S>> {
        self.check_all(|x| vec![f(x)])
    }

    fn certificate(&self, points_checked: usize, identities: usize) -> Certificate {
        Certificate {
            degrees: self.degrees.clone(),
            nodes: self.nodes.iter().map(|n| n.iter().map(|v| v.to_string()).collect()).collect(),
            points_checked,
            identities,
        }
    }
}

/// Proves `f ≡ 0` for a polynomial `f` of degree ≤ `degrees[j]` in variable `j`, on the default
/// grid `{0, …, d_j}`; see the module docs.
///
/// # Errors
/// A [`Counterexample`] where `f ≠ 0`.
///
/// # Panics
/// **Panics** when the grid exceeds 5·10⁷ (`MAX_GRID_POINTS`) (use [`GridProver::new`] to get an error).
pub fn identity<S: Exact>(
    degrees: &[usize],
    f: impl FnMut(&[S]) -> S,
) -> std::result::Result<Certificate, Counterexample<S>> {
    GridProver::new(degrees).expect("grid within limits").check(f)
}

/// [`identity`] for a batch of identities sharing one grid (each closure result entry is one
/// identity, e.g. one per index `j`).
///
/// # Errors
/// A [`Counterexample`] naming the failing identity's index.
///
/// # Panics
/// **Panics** when the grid exceeds 5·10⁷ (`MAX_GRID_POINTS`).
pub fn identities<S: Exact>(
    degrees: &[usize],
    f: impl FnMut(&[S]) -> Vec<S>,
) -> std::result::Result<Certificate, Counterexample<S>> {
    GridProver::new(degrees).expect("grid within limits").check_all(f)
}

/// Identity (8) of seed 001 for one `n`, all `j` at once:
/// `B_j^n(st) − Σ_{r=j}^{n} B_j^r(s) B_r^n(t) = 0`, degree ≤ n in `s` and in `t`.
///
/// `upper` replaces the sum's upper limit `n` (pass `n`; a smaller value is a wrong variant
/// used to show the prover refutes it).
///
/// # Errors
/// A counterexample `(s, t)` with the failing `j` as its `identity`.
#[doc(hidden)]
pub fn identity_8(
    n: usize,
    upper: usize,
) -> std::result::Result<Certificate, Counterexample<crate::num::scalar::Rational>> {
    use crate::num::scalar::{Rational, Scalar};
    // The grid varies t fastest: the B_j^r(s) table is rebuilt only when s changes.
    let mut cache: Option<(Rational, Vec<Vec<Rational>>)> = None;
    identities::<Rational>(&[n, n], |v| {
        let (s, t) = (&v[0], &v[1]);
        if cache.as_ref().is_none_or(|(cs, _)| cs != s) {
            cache = Some((s.clone(), (0..=n).map(|r| crate::poly::bernstein::bernstein_all(r, s)).collect()));
        }
        let b_s = &cache.as_ref().expect("just filled").1;
        let lhs = crate::poly::bernstein::bernstein_all(n, &(s.clone() * t));
        let b_t = crate::poly::bernstein::bernstein_all(n, t);
        (0..=n)
            .map(|j| {
                let rhs = (j..=upper.min(n)).fold(Rational::zero(), |acc, r| acc + b_s[r][j].clone() * &b_t[r]);
                lhs[j].clone() - rhs
            })
            .collect()
    })
}
