//! Unit tests of `rcagd_cli::value` (moved out of the library so that `cargo test`
//! does not compile the library a second time as a test harness; docs/ARCHITECTURE.md, "Tests").

use rcagd_algebra::Rational;
use rcagd_cli::recipe::toml::parse;
use rcagd_cli::recipe::RecipeValue;
use rcagd_cli::value::*;

fn val(src: &str) -> RecipeValue {
    let doc = parse(&format!("v = {src}")).unwrap();
    doc.get("v").unwrap().value.clone()
}

fn q(p: i64, d: i64) -> Rational {
    Rational::from(p) / Rational::from(d)
}

#[test]
fn exact_numbers() {
    assert_eq!(number(&val("0.1")).unwrap(), q(1, 10));
    assert_eq!(number(&val("-2e-3")).unwrap(), q(-1, 500));
    assert_eq!(number(&val("1_000")).unwrap(), q(1000, 1));
    assert_eq!(number(&val("0x1F")).unwrap(), q(31, 1));
    assert_eq!(number(&val("0b101")).unwrap(), q(5, 1));
    assert_eq!(number(&val("\"3/7\"")).unwrap(), q(3, 7));
    assert_eq!(number(&val("\" -0.125 \"")).unwrap(), q(-1, 8));
    assert_eq!(
        number(&val("1e1000")).unwrap(),
        Rational::from(10).pow(1000)
    );
    let e = number(&val("1e1001")).unwrap_err();
    assert!(e.message.contains("out of range"), "{}", e.message);
    assert!(number(&val("\"1/1e-99999999\"")).is_err());
    let e = number(&val("\"abc\"")).unwrap_err();
    assert!(e.message.contains("not a number: \"abc\""), "{}", e.message);
    let e = number(&val("inf")).unwrap_err();
    assert!(e.message.contains("not a number: `inf`"), "{}", e.message);
    let e = number(&val("[1]")).unwrap_err();
    assert!(
        e.message.contains("expected a number, found an array"),
        "{}",
        e.message
    );
}

#[test]
fn points_and_nets() {
    assert_eq!(
        convert(ParamKind::Point2, &val("[1, \"1/2\"]")).unwrap(),
        Value::Point(vec![q(1, 1), q(1, 2)])
    );
    let e = convert(ParamKind::Point3, &val("[1, 2]")).unwrap_err();
    assert!(
        e.message.contains("found an array of 2 elements"),
        "{}",
        e.message
    );
    let e = convert(ParamKind::Points, &val("[[1, 2], [1, 2, 3]]")).unwrap_err();
    assert!(e.message.starts_with("point 1:"), "{}", e.message);
    assert_eq!(e.span.start, 4 + 9);
    let e = convert(ParamKind::Net, &val("[[[0,0],[1,0]],[[0,1]]]")).unwrap_err();
    assert!(e.message.contains("rectangular"), "{}", e.message);
    assert!(matches!(
        convert(ParamKind::Net, &val("[[[0,0],[1,0]],[[0,1],[1,1]]]")),
        Ok(Value::Net(_))
    ));
    let e = convert(ParamKind::Points, &val("[]")).unwrap_err();
    assert!(e.message.contains("empty"), "{}", e.message);
}

#[test]
fn ints_bools_choices() {
    assert_eq!(convert(ParamKind::Int, &val("3")).unwrap(), Value::Int(3));
    assert_eq!(
        convert(ParamKind::Int, &val("\"6/2\"")).unwrap(),
        Value::Int(3)
    );
    let e = convert(ParamKind::Int, &val("1.5")).unwrap_err();
    assert!(
        e.message.contains("expected an integer, found 3/2"),
        "{}",
        e.message
    );
    assert!(convert(ParamKind::Int, &val("1e30")).is_err());
    assert_eq!(
        convert(ParamKind::Bool, &val("true")).unwrap(),
        Value::Bool(true)
    );
    assert!(convert(ParamKind::Bool, &val("1")).is_err());
    let k = ParamKind::Choice(&["xy", "xz"]);
    assert!(convert(k, &val("\"xy\"")).is_ok());
    let e = convert(k, &val("\"yz\"")).unwrap_err();
    assert!(e.message.contains("one of \"xy\", \"xz\""), "{}", e.message);
}

#[test]
fn json_echo_is_exact() {
    let v = Value::Points(vec![vec![q(1, 10), q(2, 1)]]);
    assert_eq!(v.to_json().to_string(), r#"[["1/10","2"]]"#);
}
