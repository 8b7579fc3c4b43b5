//! Proof by testing: polynomial identities proved exactly with casteljau's grid prover.
//!
//! ```sh
//! cargo run --example prove_identity
//! ```
//!
//! A polynomial of degree ≤ d_j in each variable j that vanishes on a grid of d_j + 1 distinct
//! exact values per variable is the zero polynomial. So an identity `lhs = rhs` whose degrees are
//! known is *proved* by evaluating `lhs − rhs` exactly on that grid (`casteljau::proof`); a wrong
//! one is refuted by an exact counterexample. The closures are generic code, run here over the
//! exact `Rational` scalar.

use casteljau::num::{Rational, Scalar};
use casteljau::proof;

/// The Bernstein polynomial `B_i^n(t) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ`.
fn bernstein<S: Scalar>(i: usize, n: usize, t: &S) -> S {
    let binomial = (0..i).fold(1i64, |c, k| c * (n - k) as i64 / (k + 1) as i64);
    let mut b = S::from_i64(binomial);
    for _ in 0..i {
        b = b * t;
    }
    for _ in i..n {
        b = b * &(S::one() - t);
    }
    b
}

fn main() {
    // Bernstein polynomials of degree 7 add up to 1: degree ≤ 7 in t, so 8 points decide
    let n = 7;
    let cert = proof::identity::<Rational>(&[n], |v| {
        (0..=n).fold(Rational::zero(), |sum, i| sum + bernstein(i, n, &v[0])) - Rational::one()
    })
    .expect("the partition of unity holds");
    println!("Σ B_i^7(t) = 1: proved, {cert}");

    // Lagrange's identity (a² + b²)(c² + d²) = (ac − bd)² + (ad + bc)²: degree ≤ 2 in each variable
    let cert = proof::identity::<Rational>(&[2, 2, 2, 2], |v| {
        let (a, b, c, d) = (&v[0], &v[1], &v[2], &v[3]);
        let lhs = (a.clone() * a + b.clone() * b) * &(c.clone() * c + d.clone() * d);
        let u = a.clone() * c - b.clone() * d;
        let w = a.clone() * d + b.clone() * c;
        lhs - (u.clone() * &u + w.clone() * &w)
    })
    .expect("Lagrange's identity holds");
    println!("Lagrange's identity: proved, {cert}");

    // A wrong one, (a + b)³ = a³ + b³ + 3ab: refuted at an exact point
    let wrong = proof::identity::<Rational>(&[3, 3], |v| {
        let (a, b) = (&v[0], &v[1]);
        let s = a.clone() + b;
        let three = Rational::from_i64(3);
        s.clone() * &s * &s - (a.clone() * a * a + b.clone() * b * b + three * a * b)
    });
    match wrong {
        Ok(cert) => println!("(a + b)³ = a³ + b³ + 3ab: proved?! {cert}"),
        Err(counterexample) => println!("(a + b)³ = a³ + b³ + 3ab: refuted {counterexample}"),
    }
}
