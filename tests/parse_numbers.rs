//! Exact numbers from text: accepted forms and their exact values, rejected forms with reasons.

use casteljau::num::parse::parse_number;
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
        "nan", "NaN", "inf", "-inf", "infinity", "1/0", "0/0", "1//2", "0x10", "", "-", "+", ".", "1e", "e5", "1e1001",
        "1/-2", "1.5/2", "1/2.5", "1_000", "١", "--1", "1e2.5", "/2", "2/",
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
