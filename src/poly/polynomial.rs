//! Exact univariate polynomials in power form, `p(t) = Σ c_k t^k` stored lowest degree first
//! with no trailing zeros (the zero polynomial is `[]`): the one home of polynomial
//! arithmetic — trim, remainder, exact division, monic gcd, square-free part — and of the
//! exact real roots of quadratics, `c ± √r` in `Q(√r)`.
//!
//! # Example
//! ```
//! use casteljau::{rat, poly::polynomial::{gcd, square_free, quadratic_roots}};
//! // (t − 1)²(t + 2) = t³ − 3t + 2 and its derivative 3t² − 3
//! let p = vec![rat(2), rat(-3), rat(0), rat(1)];
//! assert_eq!(gcd(p.clone(), vec![rat(-3), rat(0), rat(3)]), vec![rat(-1), rat(1)]); // t − 1
//! assert_eq!(square_free(p), vec![rat(-2), rat(1), rat(1)]); // (t − 1)(t + 2)
//! // 2 − 4t + t²: roots 2 ∓ √2, simple
//! let r = quadratic_roots(&rat(2), &rat(-4), &rat(1));
//! assert_eq!(r.iter().map(|(x, m)| (x.to_string(), *m)).collect::<Vec<_>>(),
//!            vec![("2 - sqrt(2)".to_string(), 1), ("2 + sqrt(2)".to_string(), 1)]);
//! ```

use crate::num::quadratic_field::QuadraticExt;
use crate::num::scalar::{Exact, Scalar, rat};
use num_rational::BigRational;
use std::cmp::Ordering;

/// A power-form polynomial, lowest degree first, no trailing zeros.
pub type Poly = Vec<BigRational>;

/// Drops trailing zero coefficients.
pub fn trim(mut p: Poly) -> Poly {
    while p.last().is_some_and(Scalar::is_zero) {
        p.pop();
    }
    p
}

/// The remainder of `a` divided by `b` (`b` trimmed and non-zero).
///
/// # Panics
/// **Panics if `b` is the zero polynomial.**
pub fn rem(a: Poly, b: &[BigRational]) -> Poly {
    div_rem(a, b).1
}

/// Quotient and remainder of `a` by `b` (`b` trimmed and non-zero): `a = q·b + r`,
/// `deg r < deg b`.
///
/// # Panics
/// **Panics if `b` is the zero polynomial.**
pub fn div_rem(a: Poly, b: &[BigRational]) -> (Poly, Poly) {
    let lb = b.last().expect("non-zero divisor").clone();
    let mut a = trim(a);
    let mut q = vec![rat(0); a.len().saturating_sub(b.len()) + 1];
    while a.len() >= b.len() && !a.is_empty() {
        let f = a.last().expect("non-empty").clone() / &lb;
        let shift = a.len() - b.len();
        for (i, c) in b.iter().enumerate() {
            a[shift + i] = a[shift + i].clone() - f.clone() * c;
        }
        q[shift] = f;
        a.pop(); // the leading coefficient is now exactly 0
        a = trim(a);
    }
    (trim(q), a)
}

/// The monic greatest common divisor (`[]` for `gcd(0, 0)`), by Euclid's algorithm over `Q`.
pub fn gcd(a: Poly, b: Poly) -> Poly {
    let (mut a, mut b) = (trim(a), trim(b));
    while !b.is_empty() {
        let r = rem(a, &b);
        a = b;
        b = r;
    }
    match a.last().cloned() {
        Some(l) => a.into_iter().map(|c| c / &l).collect(),
        None => a,
    }
}

/// `p'`.
pub fn derivative(p: &[BigRational]) -> Poly {
    trim(p.iter().enumerate().skip(1).map(|(k, c)| c.clone() * rat(k as i64)).collect())
}

/// The square-free part `p / gcd(p, p')`: the same roots, each simple (`p` non-zero).
pub fn square_free(p: Poly) -> Poly {
    let p = trim(p);
    let g = gcd(p.clone(), derivative(&p));
    if g.len() <= 1 { p } else { div_rem(p, &g).0 }
}

/// `[c − √r, c + √r]` for `r ≥ 0`, exactly in `Q(√r)`.
pub fn center_plus_minus_sqrt(c: &BigRational, r: &BigRational) -> [QuadraticExt<BigRational>; 2] {
    let s = QuadraticExt::sqrt(r.clone());
    let c = QuadraticExt::from_ratio(c);
    [c.clone() - s.clone(), c + s]
}

/// The distinct real roots of `c0 + c1 t + c2 t²`, ascending, each with its multiplicity (a
/// linear polynomial when `c2 = 0`; none for a non-zero constant or the zero polynomial).
pub fn quadratic_roots(
    c0: &BigRational,
    c1: &BigRational,
    c2: &BigRational,
) -> Vec<(QuadraticExt<BigRational>, usize)> {
    if c2.is_zero() {
        if c1.is_zero() {
            return vec![];
        }
        return vec![(QuadraticExt::from_ratio(&(-c0.clone() / c1)), 1)];
    }
    let disc = c1.clone() * c1 - rat(4) * c2 * c0;
    let center = -c1.clone() / (rat(2) * c2);
    match disc.sign() {
        Ordering::Less => vec![],
        Ordering::Equal => vec![(QuadraticExt::from_ratio(&center), 2)],
        Ordering::Greater => {
            let r = disc / (rat(4) * c2 * c2);
            center_plus_minus_sqrt(&center, &r).into_iter().map(|x| (x, 1)).collect()
        }
    }
}
