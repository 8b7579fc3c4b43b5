//! Exact numbers from text: accepted forms and their exact values, rejected forms with reasons.

use casteljau::num::parse_number;
use casteljau::{Error, Position};

#[test]
fn parse_accepts_exact_forms() {
    for (text, exact) in [
        ("-3", "-3"),
        ("1/3", "1/3"),
        ("-7/12", "-7/12"),
        ("-14/12", "-7/6"),
        ("0.125", "1/8"),
        ("1.5e-3", "3/2000"),
        ("2E3", "2000"),
        ("0.1", "1/10"),
        ("+5", "5"),
        (".5", "1/2"),
        ("5.", "5"),
        ("-0", "0"),
        ("6/3", "2"),
        ("1e+2", "100"),
        ("00012", "12"),
        ("123456789012345678901234567890", "123456789012345678901234567890"),
    ] {
        assert_eq!(parse_number(text, Position::default()).unwrap().to_string(), exact, "{text}");
    }
}

#[test]
fn parse_rejects_non_exact_forms_with_token_and_position() {
    let pos = Position { line: Some(3), column: 7, token: 2 };
    for text in [
        "nan",
        "NaN",
        "inf",
        "-inf",
        "infinity",
        "1/0",
        "0/0",
        "1//2",
        "0x10",
        "",
        "-",
        "+",
        ".",
        "1e",
        "e5",
        "1e1001",
        "1/-2",
        "1.5/2",
        "1/2.5",
        "1_000",
        "١",
        "--1",
        "1e2.5",
        "/2",
        "2/",
        "0x",
        "0xp1",
        "0x1p",
        "0x1.8",
        "0xg1p0",
        "0x1p99999",
        "0x1p-16385",
        "0x1.8p+",
        "0x-1p0",
    ] {
        match parse_number(text, pos) {
            Err(Error::ParseNumber { token, position, reason }) => {
                assert_eq!(position, pos);
                assert!(!reason.is_empty());
                assert_eq!(token, text);
            }
            other => panic!("{text:?} gave {other:?}"),
        }
    }
    let e = parse_number("1/0", pos).unwrap_err().to_string();
    assert_eq!(e, "bad number \"1/0\" at line 3, column 7 (number 2): zero denominator");
}

#[test]
fn parse_limits_token_length_and_exponent() {
    assert!(parse_number(&"9".repeat(1000), Position::default()).is_ok());
    assert!(parse_number(&"9".repeat(1001), Position::default()).is_err());
    assert!(parse_number("1e1000", Position::default()).is_ok());
    assert!(parse_number("1e-1000", Position::default()).is_ok());
    assert!(parse_number("1e99999999999999999999", Position::default()).is_err());
}

/// Hex floats are exact binary values in every mode (C99 `%a`, Rust's hexf).
#[test]
fn parse_hex_floats_exactly() {
    use casteljau::num::{NumberMode, parse_number_in};
    for (text, exact) in
        [("0x1.8p-3", "3/16"), ("0x1p0", "1"), ("-0x1.0p+4", "-16"), ("0X.8P1", "1"), ("0x1p-2", "1/4")]
    {
        for mode in [NumberMode::Exact, NumberMode::Binary64] {
            assert_eq!(parse_number_in(text, Position::default(), mode).unwrap().to_string(), exact, "{text}");
        }
    }
    // the smallest subnormal, exactly 2^-1074, and f64::MAX, exactly
    let tiny = parse_number("-0x1p-1074", Position::default()).unwrap();
    assert_eq!(tiny, -num_rational::BigRational::from_float(f64::from_bits(1)).unwrap());
    let max = parse_number("0x1.fffffffffffffp1023", Position::default()).unwrap();
    assert_eq!(max, num_rational::BigRational::from_float(f64::MAX).unwrap());
}

/// Binary64 mode: every number is the f64 Rust's parser gives, taken exactly; where it matters.
#[test]
fn parse_binary64_mode_rounds_like_the_f64_parser() {
    use casteljau::num::{NumberMode, parse_number_in};
    let b64 = |t: &str| parse_number_in(t, Position::default(), NumberMode::Binary64).unwrap();
    for text in [
        "0.1",
        "-0.3",
        "1e-300",
        "123456789.123456789",
        "2.5e-324",
        "1e-400",
        "0.5",
        "9007199254740993",
        "1/3",
        "-7/12",
    ] {
        let expected = match text.split_once('/') {
            Some((p, q)) => p.parse::<f64>().unwrap() / q.parse::<f64>().unwrap(),
            None => text.parse::<f64>().unwrap(),
        };
        assert_eq!(b64(text), num_rational::BigRational::from_float(expected).unwrap(), "{text}");
    }
    assert_eq!(b64("0.1").to_string(), "3602879701896397/36028797018963968");
    assert_eq!(b64("9007199254740993").to_string(), "9007199254740992"); // 2^53 + 1 rounds to even
    let e = parse_number_in("-1e309", Position::default(), NumberMode::Binary64).unwrap_err().to_string();
    assert!(e.contains("\"-1e309\"") && e.contains("binary64"), "{e}");
}

#[test]
fn integer_cubic_fast_path_declines_19_digit_coordinates_without_overflow() {
    // 19 nines overflow an i64 product: the fast route must decline, not wrap or panic
    assert_eq!(casteljau::internal::integer_cubic("9999999999999999999 0, 1 1, 2 0, 3 1"), None);
    assert_eq!(casteljau::internal::integer_cubic("-9999999999999999999 0, 1 1, 2 0, 3 1"), None);
    let p = casteljau::internal::integer_cubic("999999999999999999 0, 1 1, 2 0, 3 1").unwrap();
    assert_eq!(p[0], [999_999_999_999_999_999, 0]);
}
