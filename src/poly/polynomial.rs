//! [`Poly`]: dense univariate polynomials in power form over any [`Scalar`], the one home of
//! polynomial arithmetic in casteljau — product, Horner evaluation, derivative, composition and
//! Taylor shift, truncated power series, division, gcd and square-free part over `Q`, and the
//! one polynomial printer. Upper layers (curves, intersections, shapes, lint) build their
//! power forms as `Poly` values and call these; they keep no private copy.
//!
//! Hand-written: the polynomial crates on crates.io either fix the coefficient type to
//! floats or need traits our exact fields (`BigRational`, `Q(√d)`) do not implement, and
//! none offers the exact square-free part and gcd over `Q` computed on integers
//! (subresultants, [`super::integer`]) that root isolation needs.
//!
//! # Example
//! ```
//! use casteljau::{rat, ratio, poly::Poly};
//! // (t − 1)²(t + 2) = 2 − 3t + t³ and its derivative
//! let p = Poly::new(vec![rat(2), rat(-3), rat(0), rat(1)]);
//! assert_eq!(p.to_string(), "2 - 3t + t^3");
//! assert_eq!(p.derivative().to_string(), "-3 + 3t^2");
//! assert_eq!(p.gcd(&p.derivative()).to_string(), "-1 + t"); // monic: t − 1
//! assert_eq!(p.square_free().to_string(), "-2 + t + t^2"); // (t − 1)(t + 2)
//! assert_eq!(p.eval(&ratio(1, 2)), ratio(5, 8));
//! assert_eq!((&p * &p).degree(), Some(6));
//! ```

use crate::num::quadratic_field::{QuadraticExt, Radical};
use crate::num::scalar::{Exact, Scalar};
use num_rational::BigRational;
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};

/// A polynomial `p(t) = Σ c_k t^k` with coefficients in `S`, stored lowest degree first with
/// no trailing zeros (the zero polynomial has no coefficients).
///
/// # Invariants
/// The last stored coefficient is not zero, so two polynomials are equal (`==`) exactly when
/// their coefficients are, and [`Poly::degree`] is the true degree.
///
/// # Laws
/// For exact scalars, for all `p, q` and `t`: `(p·q)(t) = p(t)·q(t)`, `(p + q)(t) = p(t) + q(t)`,
/// `p.compose(q)(t) = p(q(t))`, `p.shift(a)(u) = p(a + u)`, and `p = q·(p / q) + p mod q` with
/// `deg(p mod q) < deg q`.
///
/// # Example
/// ```
/// use casteljau::{rat, poly::Poly};
/// let p = Poly::new(vec![rat(1), rat(2), rat(0), rat(0)]); // trailing zeros are dropped
/// assert_eq!(p.coeffs(), &[rat(1), rat(2)]);
/// assert_eq!(p.shift(&rat(1)).to_string(), "3 + 2t"); // p(1 + u) = 3 + 2u
/// assert_eq!(p.compose(&p).to_string(), "3 + 4t"); // 1 + 2(1 + 2t)
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Poly<S> {
    coeffs: Vec<S>,
}

impl<S: Scalar> Default for Poly<S> {
    fn default() -> Self {
        Poly::zero()
    }
}

impl<S: Scalar> Poly<S> {
    /// The polynomial with coefficients `c_0, c_1, …` (lowest degree first); trailing zeros are
    /// dropped.
    pub fn new(mut coeffs: Vec<S>) -> Self {
        while coeffs.last().is_some_and(Scalar::is_zero) {
            coeffs.pop();
        }
        Poly { coeffs }
    }

    /// The zero polynomial.
    pub fn zero() -> Self {
        Poly { coeffs: vec![] }
    }

    /// The constant polynomial `c`.
    pub fn constant(c: S) -> Self {
        Poly::new(vec![c])
    }

    /// The coefficients `c_0, …, c_n`, lowest degree first (empty for the zero polynomial).
    pub fn coeffs(&self) -> &[S] {
        &self.coeffs
    }

    /// The coefficient of `t^k` (zero above the degree).
    pub fn coeff(&self, k: usize) -> S {
        self.coeffs.get(k).cloned().unwrap_or_else(S::zero)
    }

    /// The degree, `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        self.coeffs.len().checked_sub(1)
    }

    /// Whether this is the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }

    /// `p(t)` by Horner's rule (`n` multiplications and additions).
    pub fn eval(&self, t: &S) -> S {
        self.coeffs.iter().rev().fold(S::zero(), |acc, c| acc * t + c)
    }

    /// `p(t)` in binary64 by Horner's rule, each coefficient rounded to `f64` first (for
    /// drawings and float estimates; never for a decision).
    pub(crate) fn eval_f64(&self, t: f64) -> f64 {
        self.coeffs.iter().rev().fold(0.0, |acc, c| acc * t + c.to_f64())
    }

    /// The polynomial with each coefficient mapped by `f` (a change of field: `Q → Q(√d)`,
    /// `Q → f64`). `f` must be a ring homomorphism for the result to mean the same polynomial.
    pub fn map<T: Scalar>(&self, f: impl Fn(&S) -> T) -> Poly<T> {
        Poly::new(self.coeffs.iter().map(f).collect())
    }

    /// `p'(t) = Σ k c_k t^(k−1)`.
    pub fn derivative(&self) -> Self {
        Poly::new(self.coeffs.iter().enumerate().skip(1).map(|(k, c)| c.clone() * S::from_i64(k as i64)).collect())
    }

    /// The antiderivative `∫₀ᵗ p = Σ c_k t^(k+1)/(k + 1)` (zero at `t = 0`).
    pub fn integral(&self) -> Self {
        let mut c = vec![S::zero()];
        c.extend(self.coeffs.iter().enumerate().map(|(k, x)| x.clone() / &S::from_i64(k as i64 + 1)));
        Poly::new(c)
    }

    /// `k·p`.
    pub fn scale(&self, k: &S) -> Self {
        Poly::new(self.coeffs.iter().map(|c| c.clone() * k).collect())
    }

    /// `p(q(t))`, by Horner's rule on polynomials.
    pub fn compose(&self, q: &Self) -> Self {
        let mut out = Poly::zero();
        for c in self.coeffs.iter().rev() {
            out = &(&out * q) + &Poly::constant(c.clone());
        }
        out
    }

    /// The Taylor shift `p(a + u)` as a polynomial in `u` (repeated synthetic division:
    /// `n(n+1)/2` multiply-adds).
    pub fn shift(&self, a: &S) -> Self {
        let mut c = self.coeffs.clone();
        let n = c.len();
        for i in 0..n {
            for j in (i..n.saturating_sub(1)).rev() {
                let next = c[j + 1].clone() * a;
                c[j] = c[j].clone() + &next;
            }
        }
        Poly::new(c)
    }

    /// The power series `p·q` truncated after `t^order` (`order + 1` coefficients, trailing
    /// zeros dropped).
    pub(crate) fn mul_truncated(&self, q: &Self, order: usize) -> Self {
        let mut out = vec![S::zero(); order + 1];
        for (i, x) in self.coeffs.iter().enumerate().take(order + 1) {
            if x.is_zero() {
                continue;
            }
            for (j, y) in q.coeffs.iter().enumerate().take(order + 1 - i) {
                out[i + j] = out[i + j].clone() + &(x.clone() * y);
            }
        }
        Poly::new(out)
    }
}

impl<S: Scalar> Add for &Poly<S> {
    type Output = Poly<S>;
    fn add(self, q: &Poly<S>) -> Poly<S> {
        let n = self.coeffs.len().max(q.coeffs.len());
        Poly::new(
            (0..n)
                .map(|k| match (self.coeffs.get(k), q.coeffs.get(k)) {
                    (Some(a), Some(b)) => a.clone() + b,
                    (Some(a), None) => a.clone(),
                    (None, Some(b)) => b.clone(),
                    (None, None) => unreachable!("k < n"),
                })
                .collect(),
        )
    }
}

impl<S: Scalar> Sub for &Poly<S> {
    type Output = Poly<S>;
    fn sub(self, q: &Poly<S>) -> Poly<S> {
        self + &(-q)
    }
}

impl<S: Scalar> Neg for &Poly<S> {
    type Output = Poly<S>;
    fn neg(self) -> Poly<S> {
        Poly { coeffs: self.coeffs.iter().map(|c| -c.clone()).collect() }
    }
}

impl<S: Scalar> Mul for &Poly<S> {
    type Output = Poly<S>;
    /// The product, `(n + 1)(m + 1)` multiplications (zero coefficients skipped).
    fn mul(self, q: &Poly<S>) -> Poly<S> {
        match (self.is_zero(), q.is_zero()) {
            // the product's degree: every coefficient kept
            (false, false) => self.mul_truncated(q, self.coeffs.len() + q.coeffs.len() - 2),
            _ => Poly::zero(),
        }
    }
}

impl Poly<BigRational> {
    /// Quotient and remainder by `b`: `self = q·b + r` with `deg r < deg b`.
    ///
    /// # Panics
    /// **Panics if `b` is the zero polynomial.**
    pub fn div_rem(&self, b: &Self) -> (Self, Self) {
        let lb = b.coeffs.last().expect("a non-zero divisor").clone();
        let mut a = self.coeffs.clone();
        let mut q = vec![BigRational::from_i64(0); a.len().saturating_sub(b.coeffs.len()) + 1];
        while a.len() >= b.coeffs.len() && !a.is_empty() {
            let f = a.last().expect("non-empty").clone() / &lb;
            let shift = a.len() - b.coeffs.len();
            for (i, c) in b.coeffs.iter().enumerate() {
                a[shift + i] = a[shift + i].clone() - f.clone() * c;
            }
            q[shift] = f;
            a.pop(); // the leading coefficient is now exactly 0
            while a.last().is_some_and(Scalar::is_zero) {
                a.pop();
            }
        }
        (Poly::new(q), Poly::new(a))
    }

    /// The monic greatest common divisor (zero for `gcd(0, 0)`).
    ///
    /// Computed on integers by the subresultant sequence (the internal `poly::integer`): Euclid
    /// over `Q` reduces a fraction at every step and its coefficients swell, which made a
    /// degree-40 gcd take seconds; the primitive sequence keeps every remainder's content
    /// divided out.
    pub fn gcd(&self, b: &Self) -> Self {
        let g = super::integer::gcd_integer(&self.to_integer(), &b.to_integer());
        match g.last().cloned() {
            Some(l) => Poly::new(g.into_iter().map(|c| BigRational::new(c, l.clone())).collect()),
            None => Poly::zero(),
        }
    }

    /// The square-free part `p / gcd(p, p')`: the same roots, each simple, as the primitive
    /// integer polynomial with positive leading coefficient (zero for zero).
    pub fn square_free(&self) -> Self {
        Poly::new(
            super::integer::square_free_integer(self.to_integer()).into_iter().map(BigRational::from_integer).collect(),
        )
    }

    /// A positive multiple of `p` with integer coefficients (the denominators cleared).
    pub(crate) fn to_integer(&self) -> Vec<num_bigint::BigInt> {
        super::integer::to_integer(&self.coeffs)
    }
}

impl<S: Exact> Poly<S> {
    /// The polynomial written in `var`, lowest degree first: `1 - 1/2*t^2 + 3t^3` (the
    /// printer's rules are on [`fmt::Display`]).
    ///
    /// ```
    /// use casteljau::{rat, ratio, poly::Poly};
    /// let p = Poly::new(vec![rat(1), rat(0), ratio(-1, 2), rat(3)]);
    /// assert_eq!(p.text("s").to_string(), "1 - 1/2*s^2 + 3s^3");
    /// assert_eq!(Poly::new(vec![rat(0), rat(-1)]).text("s").to_string(), "-s");
    /// ```
    pub fn text<'a>(&'a self, var: &'a str) -> impl fmt::Display + 'a {
        PolyText { poly: self, var, descending: false }
    }

    /// The polynomial written in `var`, highest degree first, with `*` after every coefficient
    /// that is not 1: `3*t^2 - 2*t + 5` (how the polynomial of an algebraic number is shown).
    ///
    pub(crate) fn text_descending<'a>(&'a self, var: &'a str) -> impl fmt::Display + 'a {
        PolyText { poly: self, var, descending: true }
    }
}

/// The one polynomial printer (see [`Poly::text`] and [`Poly::text_descending`]).
struct PolyText<'a, S> {
    poly: &'a Poly<S>,
    var: &'a str,
    descending: bool,
}

impl<S: Exact> fmt::Display for PolyText<'_, S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let terms: Vec<(usize, &S)> = self.poly.coeffs.iter().enumerate().filter(|(_, c)| !c.is_zero()).collect();
        if terms.is_empty() {
            return write!(f, "0");
        }
        let ordered: Box<dyn Iterator<Item = &(usize, &S)>> =
            if self.descending { Box::new(terms.iter().rev()) } else { Box::new(terms.iter()) };
        for (i, (k, c)) in ordered.enumerate() {
            let negative = c.sign() == Ordering::Less;
            let magnitude = if negative { -(*c).clone() } else { (*c).clone() };
            f.write_str(match (i == 0, negative) {
                (true, true) => "-",
                (true, false) => "",
                (false, true) => " - ",
                (false, false) => " + ",
            })?;
            let text = if S::ATOMIC_DISPLAY { magnitude.to_string() } else { format!("({magnitude})") };
            if *k == 0 {
                write!(f, "{text}")?;
                continue;
            }
            if magnitude != S::one() {
                let integer = magnitude.to_ratio().is_some_and(|r| r.is_integer());
                let star = self.descending || !integer;
                write!(f, "{text}{}", if star { "*" } else { "" })?;
            }
            write!(f, "{}", self.var)?;
            if *k > 1 {
                write!(f, "^{k}")?;
            }
        }
        Ok(())
    }
}

impl<S: Exact> fmt::Display for Poly<S> {
    /// `c0 + c1 t + c2 t^2 …` in ascending powers of `t`: zero terms omitted, a coefficient 1
    /// left out, `*` only after a coefficient that is not an integer (`1/2*t`, `3t`), `0` for
    /// the zero polynomial. Coefficients that are not one token (`Q(√d)`) are parenthesised.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        PolyText { poly: self, var: "t", descending: false }.fmt(f)
    }
}

/// `[c − √r, c + √r]` for `r ≥ 0`, exactly in `K(√r)` (the radical spelled by [`Radical`]).
pub fn center_plus_minus_sqrt<K: Radical>(c: &K, r: &K) -> [QuadraticExt<K>; 2] {
    let s = K::radical(r);
    let c = QuadraticExt::from_base(c.clone());
    [c.clone() - s.clone(), c + s]
}

/// The distinct real roots of `c0 + c1 t + c2 t²`, ascending, each with its multiplicity (a
/// linear polynomial when `c2 = 0`; none for a non-zero constant or the zero polynomial).
///
/// ```
/// use casteljau::{rat, poly::quadratic_roots};
/// // 2 − 4t + t²: roots 2 ∓ √2, simple
/// let r = quadratic_roots(&rat(2), &rat(-4), &rat(1));
/// assert_eq!(r.iter().map(|(x, m)| (x.to_string(), *m)).collect::<Vec<_>>(),
///            vec![("2 - sqrt(2)".to_string(), 1), ("2 + sqrt(2)".to_string(), 1)]);
/// ```
pub fn quadratic_roots<K: Radical>(c0: &K, c1: &K, c2: &K) -> Vec<(QuadraticExt<K>, usize)> {
    if c2.is_zero() {
        if c1.is_zero() {
            return vec![];
        }
        return vec![(QuadraticExt::from_base(-c0.clone() / c1), 1)];
    }
    let disc = c1.clone() * c1 - K::from_i64(4) * c2 * c0;
    let center = -c1.clone() / &(K::from_i64(2) * c2);
    match disc.sign() {
        Ordering::Less => vec![],
        Ordering::Equal => vec![(QuadraticExt::from_base(center), 2)],
        Ordering::Greater => {
            let r = disc / &(K::from_i64(4) * c2 * c2);
            center_plus_minus_sqrt(&center, &r).into_iter().map(|x| (x, 1)).collect()
        }
    }
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    #[test]
    fn text_descending_example() {
        use crate::{poly::Poly, rat};
        let p = Poly::new(vec![rat(-2), rat(0), rat(3)]);
        assert_eq!(p.text_descending("t").to_string(), "3*t^2 - 2");
    }
}
