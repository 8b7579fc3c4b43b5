//! Identity (8) of seed 001, B_j^n(st) = Σ_{r=j}^n B_j^r(s) B_r^n(t), proved for every n ≤ 40
//! and every j by the grid prover; a wrong variant is refuted with an exact counterexample.

use casteljau::internal::identity_8;
use casteljau::num::{Rational, Scalar};
use casteljau::poly::bernstein;
use casteljau::proof::{self, GridProver};

#[test]
fn identity_8_proved_for_all_n_up_to_40_and_all_j() {
    for n in 0..=40 {
        let cert = identity_8(n, n).unwrap_or_else(|e| panic!("n = {n}: {e}"));
        assert_eq!(cert.points_checked, (n + 1) * (n + 1));
        assert_eq!(cert.identities, n + 1);
        assert_eq!(cert.degrees, vec![n, n]);
    }
}

#[test]
fn identity_8_wrong_upper_limit_is_refuted_with_exact_counterexample() {
    let n = 5;
    let err = identity_8(n, n - 1).unwrap_err();
    // check the counterexample independently: at (s, t) identity j fails by the missing r = n term
    let (s, t) = (&err.point[0], &err.point[1]);
    let j = err.identity;
    let missing = bernstein(j, n, s) * &bernstein(n, n, t);
    assert!(!missing.is_zero());
    assert_eq!(err.value, missing);
}

#[test]
fn grid_prover_rejects_perturbed_constant() {
    // (1 - s t)^2 = 1 - 2 s t + s^2 t^2, with 2 perturbed to 3
    let res = proof::identity::<Rational>(&[2, 2], |v| {
        let st = v[0].clone() * &v[1];
        let one = Rational::one();
        let lhs = (one.clone() - &st) * &(one.clone() - &st);
        lhs - (one - Rational::from_i64(3) * &st + st.clone() * &st)
    });
    let ce = res.unwrap_err();
    assert!(!ce.value.is_zero());
}

#[test]
fn grid_prover_validates_its_grid() {
    assert!(GridProver::<Rational>::with_nodes(&[1], vec![vec![Rational::one(), Rational::one()]]).is_err());
    assert!(GridProver::<Rational>::with_nodes(&[2], vec![vec![Rational::one(), Rational::zero()]]).is_err());
    assert!(GridProver::<Rational>::new(&[10_000, 10_000]).is_err());
}

#[test]
fn grid_prover_certificate_is_no_proof_of_a_wrong_degree_bound() {
    // t(t-1) vanishes on {0, 1} but has degree 2: with the honest bound 2 it is refuted.
    let f = |v: &[Rational]| v[0].clone() * &(v[0].clone() - &Rational::one());
    assert!(proof::identity::<Rational>(&[1], f).is_ok());
    assert!(proof::identity::<Rational>(&[2], f).is_err());
}
