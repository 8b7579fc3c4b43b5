//! Regression tests for exactness bugs: each test names the case that once went wrong.

use casteljau::num::ratio_to_f64;
use casteljau::poly::{Root, isolate_bernstein};
use casteljau::rational::RationalBezier;
use casteljau::surface::RationalPatch;
use casteljau::work::Budget;
use casteljau::{Exact, Point, QuadraticExt, Scalar, rat, ratio};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Pow, Signed};
use proptest::prelude::*;
use std::cmp::Ordering;
use std::process::Command;

fn big(s: &str) -> BigRational {
    s.parse().unwrap()
}

/// `10^-k` exactly.
fn ten_to_minus(k: u32) -> BigRational {
    BigRational::new(BigInt::one(), Pow::pow(BigInt::from(10), k))
}

/// `√(2·1009²)` (1009 is a prime above the trial-division bound, so `sqrt` keeps the square
/// factor in the radicand) and `1009·√2` are one number: equal, and their difference is 0.
#[test]
fn quadratic_ext_radicand_with_large_square_factor_equals_reduced_spelling() {
    let unreduced = QuadraticExt::sqrt(rat(2 * 1009 * 1009));
    let reduced = QuadraticExt::new(rat(0), rat(1009), rat(2));
    assert_eq!(unreduced.radicand(), &rat(2 * 1009 * 1009), "the spelling this test is about");
    assert_eq!(unreduced, reduced);
    assert!((unreduced.clone() - reduced.clone()).is_zero());
    assert_eq!((unreduced.clone() - reduced.clone()).sign(), Ordering::Equal);
    assert_eq!(unreduced.clone() * reduced.clone(), QuadraticExt::from_i64(2 * 1009 * 1009));
    assert_eq!(unreduced.clone() / reduced.clone(), QuadraticExt::from_i64(1));
    // a rational plus both spellings: (3 + √(2·1009²)) − (3 + 1009√2) = 0
    let x = QuadraticExt::from_i64(3) + unreduced;
    let y = QuadraticExt::from_i64(3) + reduced;
    assert_eq!(x.clone() - y.clone(), QuadraticExt::from_i64(0));
    // a square factor far beyond any trial division: (10^40 + 7)² · 5
    let p = big("10000000000000000000000000000000000000007");
    let huge = QuadraticExt::new(rat(0), rat(1), p.clone() * &p * rat(5));
    let small = QuadraticExt::new(rat(0), p, rat(5));
    assert_eq!(huge.clone(), small.clone());
    assert!((huge - small).is_zero());
}

/// Numbers of genuinely different fields still compare (unequal) without panicking.
#[test]
fn quadratic_ext_different_fields_compare_unequal() {
    let s2 = QuadraticExt::sqrt(rat(2));
    let s3 = QuadraticExt::sqrt(rat(3));
    assert_ne!(s2, s3);
    assert_ne!(s2, -s2.clone());
    assert_eq!(s2.exact_sqrt(), None, "√√2 is not in Q(√2)");
    // (1 + √2)² = 3 + 2√2: its square root is found in Q(√2)
    let x = QuadraticExt::new(rat(3), rat(2), rat(2));
    assert_eq!(x.exact_sqrt(), Some(QuadraticExt::new(rat(1), rat(1), rat(2))));
}

/// `W(t) = (t − 3/10)² + 10⁻¹²² > 0`: the old isolation stopped at depth 200 and called the
/// interval around 3/10 a root. The curve is defined on [0, 1].
#[test]
fn isolation_positive_denominator_with_near_double_root_has_no_root() {
    let e = ten_to_minus(122);
    let w = vec![ratio(9, 100) + &e, ratio(-21, 100) + &e, ratio(49, 100) + &e];
    assert_eq!(isolate_bernstein(&w, &Budget::unlimited()).unwrap(), Some(vec![]));
    let pts =
        vec![Point::new(vec![rat(0), rat(0)]), Point::new(vec![rat(1), rat(1)]), Point::new(vec![rat(2), rat(0)])];
    let c = RationalBezier::new(pts, w).unwrap();
    assert!(c.check_defined(&rat(0), &rat(1)).is_ok());
}

/// `W(t) = (t − a)(t − b)` with `b − a = 10⁻⁶¹`: two roots, each in its own interval.
#[test]
fn isolation_separates_roots_ten_to_minus_61_apart() {
    let a = ratio(3, 10);
    let b = a.clone() + ten_to_minus(61);
    let w0 = a.clone() * &b;
    let w1 = w0.clone() - (a.clone() + &b) / rat(2);
    let w2 = rat(1) - &w0 + rat(2) * &w1;
    let roots = isolate_bernstein(&[w0, w1, w2], &Budget::unlimited()).unwrap().unwrap();
    assert_eq!(roots.len(), 2, "{roots:?}");
    let w = |t: &BigRational| (t.clone() - &a) * (t.clone() - &b);
    for (r, x) in roots.iter().zip([&a, &b]) {
        let Root::Isolated(lo, hi) = r else { panic!("3/10 is not dyadic: {r:?}") };
        assert!(lo < x && x < hi, "{x} in ({lo}, {hi})");
        assert_ne!(w(lo).sign(), w(hi).sign(), "one simple root: a sign change");
    }
}

/// The same two cases through the command line.
#[test]
fn isolation_cli_defined_answers_both_near_double_root_cases() {
    let run = |weights: String| {
        let out = Command::new(env!("CARGO_BIN_EXE_casteljau"))
            .args(["defined", "--json", "--weights", &weights, "0 0, 1 1, 2 0"])
            .output()
            .unwrap();
        (out.status.code(), String::from_utf8(out.stdout).unwrap())
    };
    let e = ten_to_minus(122);
    let (code, out) = run(format!("{} {} {}", ratio(9, 100) + &e, ratio(-21, 100) + &e, ratio(49, 100) + &e));
    assert_eq!(code, Some(0), "{out}");
    assert!(out.contains("\"defined\":true"), "{out}");
    let a = ratio(3, 10);
    let b = a.clone() + ten_to_minus(61);
    let w0 = a.clone() * &b;
    let w1 = w0.clone() - (a.clone() + &b) / rat(2);
    let w2 = rat(1) - &w0 + rat(2) * &w1;
    let (code, out) = run(format!("{w0} {w1} {w2}"));
    assert_eq!(code, Some(1), "{out}");
    let v: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    assert_eq!(v["roots"].as_array().unwrap().len(), 2, "{out}");
}

/// An intermediate weight 0 stops the affine rational de Casteljau recursion; that is not a
/// disagreement between the two orders.
#[test]
fn surface_eval_orders_agree_homogeneously_with_zero_intermediate_weight() {
    let out = Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .args([
            "surface",
            "eval",
            "--json",
            "--degree",
            "1,1",
            "--u",
            "1/2",
            "--v",
            "1/2",
            "--weights",
            "1 -1 1 1",
            "0 0 0, 1 0 0, 0 1 0, 1 1 1",
        ])
        .output()
        .unwrap();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["de_casteljau_u_then_v_and_v_then_u_agree"], true, "{v}");
    let p = |x: i64, y: i64, z: i64| Point::new(vec![rat(x), rat(y), rat(z)]);
    let s = RationalPatch::new(
        vec![vec![p(0, 0, 0), p(1, 0, 0)], vec![p(0, 1, 0), p(1, 1, 1)]],
        vec![vec![rat(1), rat(-1)], vec![rat(1), rat(1)]],
    )
    .unwrap();
    let point = s.eval(&ratio(1, 2), &ratio(1, 2)).unwrap();
    assert_eq!(v["point"], serde_json::json!(point.coords.iter().map(|c| c.to_string()).collect::<Vec<_>>()));
}

/// The exact value of a finite `f64`.
fn exact(f: f64) -> BigRational {
    BigRational::from_float(f).unwrap()
}

proptest! {
    /// `ratio_to_f64` is correctly rounded: no `f64` is nearer, ties go to the even one; also for
    /// numerators and denominators far beyond `f64` range.
    #[test]
    fn ratio_to_f64_is_correctly_rounded(
        n in prop::collection::vec(any::<u32>(), 1..40),
        d in prop::collection::vec(any::<u32>(), 1..40),
        neg in any::<bool>(),
    ) {
        let to_big = |v: &[u32]| BigInt::from_slice(num_bigint::Sign::Plus, v);
        let den = to_big(&d);
        prop_assume!(den != BigInt::from(0));
        let mut r = BigRational::new(to_big(&n), den);
        if neg { r = -r; }
        let f = ratio_to_f64(&r);
        if f.is_finite() && f != 0.0 {
            let err = (exact(f) - &r).abs();
            for g in [f.next_up(), f.next_down()] {
                if g.is_finite() {
                    let other = (exact(g) - &r).abs();
                    prop_assert!(err < other || (err == other && f.to_bits().is_multiple_of(2)), "{} -> {}", r, f);
                }
            }
        } else if f == 0.0 {
            prop_assert!((r.clone() * rat(2)).abs() <= exact(f64::from_bits(1)), "{} underflowed", r);
        } else {
            prop_assert!(r.clone().abs() >= exact(f64::MAX), "{} overflowed", r);
        }
    }
}

/// Ties round to even with operands beyond `f64` range: `(3^700·(2^53 + 1)) / (3^700·2^53)`
/// reduces, so use an odd denominator instead.
#[test]
fn ratio_to_f64_rounds_huge_operands_correctly() {
    let three = Pow::pow(BigInt::from(3), 700u32);
    // (3^700 + 1)/3^699 = 3 + 3^-699: nearest f64 is 3
    assert_eq!(ratio_to_f64(&BigRational::new(&three + 1, three.clone() / 3)), 3.0);
    // exactly 1 + 2^-53 (a tie) → 1, and a hair above → 1 + 2^-52
    let tie = rat(1) + BigRational::new(BigInt::one(), Pow::pow(BigInt::from(2), 53u32));
    assert_eq!(ratio_to_f64(&tie), 1.0);
    let above = tie + BigRational::new(BigInt::one(), three);
    assert_eq!(ratio_to_f64(&above), 1.0 + f64::EPSILON);
}
