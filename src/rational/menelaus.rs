//! Saito–Hosaka's Menelaus lemmas (seed 002, (2)–(6) and appendix (55)–(60)), as exact
//! configurations.
//!
//! Given rational control points `P0, P1` with weights `w0, w1`, any origin `O` (2D or 3D, not
//! on the line `P0P1`) and `t`: the non-rational points `P̂_i = O + w_i (P_i − O)` ((2)–(3)), their
//! linear interpolation `P_e = (1−t) P̂0 + t P̂1`, and `P_a`, where the line `O P_e` meets `P0P1`.
//! The seed claims
//!
//! * (56) (its (4) is garbled by OCR): `P0 P_a : P_a P1 = t·w1 : (1−t)·w0` — `P_a` is the
//!   rational interpolation point `𝒱[t·w1 : (1−t)·w0](P0, P1)` of (16)–(17);
//! * (5)/(60): `O P_a : O P_e = 1 : w_a`, with (6) `w_a = w0(1−t) + w1 t`.
//!
//! [`Configuration::new`] builds the configuration exactly; the `*_ratio` methods return the
//! exact ratios found, to compare with the claims.

use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::{Exact, Scalar};

/// An exact Menelaus configuration.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Configuration<S> {
    /// The origin `O`.
    pub o: Point<S>,
    /// `P0`, `P1`.
    pub p: [Point<S>; 2],
    /// `w0`, `w1`.
    pub w: [S; 2],
    /// The parameter.
    pub t: S,
    /// `P̂0`, `P̂1` (non-rational control points).
    pub p_hat: [Point<S>; 2],
    /// `P_e`.
    pub p_e: Point<S>,
    /// `P_a = O + λ (P_e − O) = P0 + μ (P1 − P0)`.
    pub p_a: Point<S>,
    /// `λ`: `O P_a : O P_e = λ : 1`.
    pub lambda: S,
    /// `μ`: `P0 P_a : P_a P1 = μ : (1 − μ)`.
    pub mu: S,
}

impl<S: Exact> Configuration<S> {
    /// Builds the configuration.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for mixed dimensions, [`Error::Degenerate`] for `O` on the line
    /// `P0P1` or `P0 = P1`, [`Error::PointAtInfinity`] when the line `O P_e` is parallel to `P0P1`
    /// (then `P_a` is at infinity: `w_a = 0`).
    pub fn new(o: Point<S>, p0: Point<S>, p1: Point<S>, w0: S, w1: S, t: S) -> Result<Self> {
        let dim = o.dim();
        if p0.dim() != dim || p1.dim() != dim || !(2..=3).contains(&dim) {
            return Err(Error::InvalidArgument { message: "O, P0, P1 must all be 2D or all 3D".into() });
        }
        let hat = |p: &Point<S>, w: &S| o.add(&p.sub(&o).scale(w));
        let p_hat = [hat(&p0, &w0), hat(&p1, &w1)];
        let p_e = p_hat[0].lerp(&p_hat[1], &t);
        // Solve λ d − μ e = f with d = P_e − O, e = P1 − P0, f = P0 − O, in the coordinate plane
        // (pair of axes) where d × e does not vanish.
        let (d, e, f) = (p_e.sub(&o), p1.sub(&p0), p0.sub(&o));
        if e.coords.iter().all(Scalar::is_zero) {
            return Err(Error::Degenerate { message: "P0 = P1".into() });
        }
        let cross = |a: &Point<S>, b: &Point<S>, i: usize, j: usize| {
            a.coords[i].clone() * &b.coords[j] - a.coords[j].clone() * &b.coords[i]
        };
        let planes: &[(usize, usize)] = if dim == 2 { &[(0, 1)] } else { &[(0, 1), (0, 2), (1, 2)] };
        // O on the line P0P1 ⟺ f × e = 0 in every plane
        if planes.iter().all(|&(i, j)| cross(&f, &e, i, j).is_zero()) {
            return Err(Error::Degenerate { message: "O lies on the line P0P1".into() });
        }
        let &(i, j) = planes.iter().find(|&&(i, j)| !cross(&d, &e, i, j).is_zero()).ok_or_else(|| {
            Error::PointAtInfinity { message: "the line O P_e is parallel to P0P1 (w_a = 0: P_a at infinity)".into() }
        })?;
        let det = cross(&d, &e, i, j);
        // λ d − μ e = f: Cramer with columns (d, −e)
        let lambda = cross(&f, &e, i, j) / det.clone();
        let mu = -cross(&d, &f, i, j) / det;
        let p_a = p0.add(&e.scale(&mu));
        Ok(Configuration { o, p: [p0, p1], w: [w0, w1], t, p_hat, p_e, p_a, lambda, mu })
    }

    /// `(μ, 1 − μ)`: the ratio `P0 P_a : P_a P1` found.
    pub fn division_ratio(&self) -> (S, S) {
        (self.mu.clone(), S::one() - &self.mu)
    }

    /// (56): `P0 P_a : P_a P1 = t w1 : (1−t) w0` (compared cross-multiplied).
    pub fn claim_56_holds(&self) -> bool {
        let (m, n) = self.division_ratio();
        let (a, b) = (self.t.clone() * &self.w[1], (S::one() - &self.t) * &self.w[0]);
        m * &b == n * &a
    }

    /// (4): as printed, `P0 P_a : P1 P_e = w0 t : w0 (1−t)` — signed lengths along the two
    /// lines compared as `|P0 P_a|² (1−t)² = |P1 P_e|² t²`; corrected, the appendix's (56)
    /// ([`Self::claim_56_holds`]).
    pub fn claim_4_holds(&self, reading: crate::proof::Reading) -> bool {
        if reading == crate::proof::Reading::Corrected {
            return self.claim_56_holds();
        }
        let l1 = self.p_a.sub(&self.p[0]);
        let l2 = self.p_e.sub(&self.p[1]);
        let u = S::one() - &self.t;
        l1.dot(&l1) * &(u.clone() * &u) == l2.dot(&l2) * &(self.t.clone() * &self.t)
    }

    /// (5)/(60) with (6): `O P_a : O P_e = 1 : w_a`, `w_a = w0(1−t) + w1 t`, i.e. `λ·w_a = 1`.
    pub fn claim_5_holds(&self) -> bool {
        let wa = self.w[0].clone() * &(S::one() - &self.t) + self.w[1].clone() * &self.t;
        self.lambda.clone() * &wa == S::one()
    }

    /// `P_a` equals the rational interpolation point (16): `((1−t)w0 P0 + t w1 P1)/((1−t)w0 + t w1)`.
    pub fn rational_interpolation_holds(&self) -> bool {
        let a = self.t.clone() * &self.w[1];
        let b = (S::one() - &self.t) * &self.w[0];
        crate::rational::rational_bezier::divide(&a, &b, &self.p[0], &self.p[1]).is_some_and(|q| q == self.p_a)
    }
}
