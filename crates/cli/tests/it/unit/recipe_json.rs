//! Unit tests of `rcagd_cli::recipe::json` (moved out of the library so that `cargo test`
//! does not compile the library a second time as a test harness; docs/ARCHITECTURE.md, "Tests").

use rcagd_cli::recipe::json::*;
use rcagd_cli::recipe::{NumberText, ValueKind};
use rcagd_cli::source::Span;

fn num(raw: &str) -> ValueKind {
    ValueKind::Number(NumberText {
        raw: raw.into(),
        radix: 10,
    })
}

#[test]
fn parses_values_with_spans() {
    let v = parse(r#" {"a": [1, -0.1e+2, "x\u00e9\n"], "b": true, "c": null} "#).unwrap();
    assert_eq!(v.span, Span::new(1, 55));
    let a = v.get("a").unwrap();
    assert_eq!(a.key_span, Span::new(2, 5));
    let items = a.value.as_array().unwrap();
    assert_eq!(items[0].kind, num("1"));
    assert_eq!(items[1].kind, num("-0.1e+2"));
    assert_eq!(items[1].span, Span::new(11, 18));
    assert_eq!(items[2].kind, ValueKind::String("xé\n".into()));
    assert_eq!(v.get("b").unwrap().value.kind, ValueKind::Bool(true));
    assert_eq!(v.get("c").unwrap().value.kind, ValueKind::Null);
}

#[test]
fn surrogate_pairs() {
    let v = parse(r#""\ud83d\ude00""#).unwrap();
    assert_eq!(v.kind, ValueKind::String("😀".into()));
    assert!(parse(r#""\ud83d""#).is_err());
    assert!(parse(r#""\ude00""#).is_err());
}

#[test]
fn rejects_non_json_with_positions() {
    let cases: &[(&str, usize, &str)] = &[
        ("", 0, "empty"),
        ("[1, 2", 0, "unclosed array"),
        ("[1, 2,]", 6, "trailing comma"),
        ("{\"a\": 1,}", 8, "trailing comma"),
        ("{\"a\" 1}", 5, "expected ':'"),
        ("{a: 1}", 1, "expected a key"),
        ("[01]", 1, "leading zeros"),
        ("[1.]", 3, "after the decimal point"),
        ("[1e]", 3, "exponent"),
        ("[+1]", 1, "starts with a digit"),
        ("[.5]", 1, "starts with a digit"),
        ("['a']", 1, "double quotes"),
        ("[tru]", 1, "unknown literal"),
        ("[nulll]", 1, "unknown literal"),
        ("\"abc", 0, "unterminated string"),
        ("\"a\nb\"", 2, "line break"),
        ("\"\\x\"", 1, "invalid escape"),
        ("\"\\u12\"", 1, "four hex digits"),
        ("{\"a\": 1, \"a\": 2}", 9, "duplicate key"),
        ("[1] [2]", 4, "after the end"),
        ("[1 2]", 3, "expected ',' or ']'"),
        ("{\"a\": 1 \"b\": 2}", 8, "expected ',' or '}'"),
    ];
    for &(src, at, msg) in cases {
        let e = parse(src).expect_err(src);
        assert_eq!(e.span.start, at, "{src:?}: {e:?}");
        assert!(e.message.contains(msg), "{src:?}: {}", e.message);
    }
}

#[test]
fn bounded_depth() {
    let deep = "[".repeat(100_000);
    let e = parse(&deep).unwrap_err();
    assert!(e.message.contains("nesting"), "{}", e.message);
    let ok = format!("{}{}", "[".repeat(MAX_DEPTH), "]".repeat(MAX_DEPTH));
    assert!(parse(&ok).is_ok());
    let too = format!("{}{}", "[".repeat(MAX_DEPTH + 1), "]".repeat(MAX_DEPTH + 1));
    assert!(parse(&too).is_err());
}
