//! In-process fuzzing of the text parsers and the expression language with proptest: any
//! string gets a value or an error (never a panic, a stack overflow or a hang), and what parses
//! round-trips through its printed form to the same exact value.

use casteljau::Position;
use casteljau::num::Fraction;
use casteljau::num::{parse_number, parse_points};
use casteljau::proof::expr::{Env, parse_expr, with_step_limit};
use casteljau::rat;
use proptest::prelude::*;

/// Strings built from the characters numbers and curves are made of, plus noise.
fn number_soup() -> impl Strategy<Value = String> {
    prop::collection::vec(
        prop_oneof![
            8 => prop::sample::select(vec!['0', '1', '2', '7', '9', '-', '+', '/', '.', 'e', 'E', ' ', ',', '\t']),
            1 => prop::sample::select(vec!['x', 'n', 'a', 'i', '_', '\u{00A0}', '½', '−', '\u{FEFF}', '\r', '#', ';']),
            1 => any::<char>(),
        ],
        0..40,
    )
    .prop_map(|v| v.into_iter().collect())
}

/// Strings built from the expression language's tokens, with unbalanced parentheses and noise.
fn expression_soup() -> impl Strategy<Value = String> {
    prop::collection::vec(
        prop_oneof![
            6 => prop::sample::select(vec![
                "x", "y", "t", "s", "1", "2", "1/3", "0", "0.5", "+", "-", "*", "/", "^", "(", ")", ",", " ",
                "C(", "B(", "sum(", "prod(", "r", "k", "n", "3", "-1", "1e3",
            ]).prop_map(str::to_string),
            1 => any::<char>().prop_map(|c| c.to_string()),
        ],
        0..40,
    )
    .prop_map(|v| v.concat())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn parse_number_answers_every_string(s in number_soup()) {
        if let Ok(v) = parse_number(&s, Position::default()) {
            // the printed exact form parses back to the same number
            prop_assert_eq!(parse_number(&v.to_string(), Position::default()).unwrap(), v);
        }
    }

    #[test]
    fn parse_points_answers_every_string(s in number_soup(), dim in 1usize..=3) {
        if let Ok(points) = parse_points(&s, dim, Some(7)) {
            let printed: Vec<String> = points
                .iter()
                .map(|p| p.coords.iter().map(|c| c.to_string()).collect::<Vec<_>>().join(" "))
                .collect();
            prop_assert_eq!(parse_points(&printed.join(", "), dim, None).unwrap(), points);
        } else if let Err(e) = parse_points(&s, dim, Some(7)) {
            prop_assert!(!e.to_string().is_empty());
        }
    }

    #[test]
    fn expressions_parse_and_evaluate_without_panic(s in expression_soup(), x in -5i64..=5, y in 1i64..=5) {
        if let Ok(e) = parse_expr(&s) {
            let env = |x: i64, y: i64| -> Env {
                ["x", "t", "n", "r", "k", "s"].iter().map(|n| (n.to_string(), Fraction::from(rat(x)))).chain(std::iter::once(("y".to_string(), Fraction::from(rat(y))))).collect()
            };
            let v = with_step_limit(100_000, || e.eval(&mut env(x, y)));
            // the printed form is the same expression: it evaluates to the same exact value
            let again = parse_expr(&e.to_string()).expect("a printed expression parses");
            let w = with_step_limit(100_000, || again.eval(&mut env(x, y)));
            match (v, w) {
                (Ok(a), Ok(b)) => prop_assert_eq!(a, b),
                (Err(a), Err(b)) => prop_assert_eq!(a.to_string().is_empty(), b.to_string().is_empty()),
                (a, b) => prop_assert!(false, "{:?} vs {:?} for {}", a, b, s),
            }
        }
    }

}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn deep_or_long_expressions_are_refused_not_overflowed(depth in 1usize..3000, wide in 1usize..30_000) {
        let deep = format!("{}x{}", "(".repeat(depth), ")".repeat(depth));
        let r = parse_expr(&deep);
        // shallow nests parse; past the documented depth they are refused with a message
        if depth <= 100 {
            prop_assert!(r.is_ok());
        }
        if depth > casteljau::proof::expr::MAX_EXPR_DEPTH {
            prop_assert!(r.unwrap_err().to_string().contains("deep"));
        }
        let long = vec!["x"; wide].join(" + ");
        let _ = parse_expr(&long).map(|e| with_step_limit(1_000_000, || e.eval(&mut Env::new())));
    }
}

/// Found by `expressions_parse_and_evaluate_without_panic`: `1/30.5` printed as `(1 / 61/2)`,
/// which reads back as `(1/61)/2`.
#[test]
fn expression_fraction_literal_prints_in_parentheses() {
    let e = parse_expr("1/30.5").unwrap();
    let again = parse_expr(&e.to_string()).unwrap();
    let v = |e: &casteljau::proof::expr::Expr| e.eval(&mut Env::new()).unwrap();
    assert_eq!(v(&again), v(&e));
    assert_eq!(v(&e).to_string(), "2/61");
}

proptest! {
    /// Any finite f64, printed as Rust prints it (shortest round-trip decimal, plain or with an
    /// exponent), reads back in binary64 mode as exactly that f64 — and in exact mode as the
    /// decimal, which is the f64 only when the decimal is a binary fraction.
    #[test]
    fn binary64_mode_reads_back_every_printed_f64(bits in any::<u64>()) {
        use casteljau::num::{NumberMode, parse_number_in};
        let x = f64::from_bits(bits);
        prop_assume!(x.is_finite());
        let exact = num_rational::BigRational::from_float(x).unwrap();
        for text in [format!("{x}"), format!("{x:e}"), format!("{x:?}")] {
            let v = parse_number_in(&text, Default::default(), NumberMode::Binary64).unwrap();
            prop_assert_eq!(&v, &exact, "{}", text);
        }
    }
}
