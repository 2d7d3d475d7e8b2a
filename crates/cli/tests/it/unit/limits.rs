//! Unit tests of `rcagd_cli::limits` (moved out of the library so that `cargo test`
//! does not compile the library a second time as a test harness; docs/ARCHITECTURE.md, "Tests").

use rcagd_cli::limits::*;

#[test]
fn digits_are_counted_without_exponent_sign_or_separators() {
    assert_eq!(digit_count("123"), 3);
    assert_eq!(digit_count("-1_000"), 4);
    assert_eq!(digit_count("3/7"), 2);
    assert_eq!(digit_count("-2.5e-300"), 2);
    assert_eq!(digit_count("0x1F"), 3);
    assert_eq!(digit_count("1.5/20"), 4);
}

#[test]
fn non_finite_numbers_are_recognised_as_words_and_said_as_too_large() {
    assert!(shows_non_finite("|c| = √(inf) is irrational"));
    assert!(shows_non_finite("residual NaN·t^16 + 1"));
    assert!(shows_non_finite("the number -inf cannot be written"));
    assert!(!shows_non_finite("a point at infinity (weight 0)"));
    assert!(!shows_non_finite("information: 1e300"));
    let e = export_error("a.step: the number inf cannot be written");
    assert!(e.starts_with("input too large for f64: a.step"), "{e}");
    assert_eq!(export_error(&e), e);
    assert_eq!(export_error("a plain error"), "a plain error");
    let m = too_large_for_f64(("d_s", "≈ 1e300".into()), "√(inf)");
    assert!(
        m.starts_with("input too large for f64: `d_s` (its largest number is ≈ 1e300)"),
        "{m}"
    );
    let w = work_limit_message(
        "a",
        rcagd_algebra::budget::WorkLimitExceeded {
            limit: std::time::Duration::from_secs(2),
        },
    );
    assert_eq!(
        w,
        "work limit exceeded: building \"a\" took more than 2 s (raise with --max-seconds)"
    );
    assert_eq!(
        Limits::default().work_limit(),
        Some(std::time::Duration::from_secs(600))
    );
    let none = Limits {
        seconds: 0,
        ..Limits::default()
    };
    assert_eq!(none.work_limit(), None);
}

#[test]
fn magnitudes_are_decimal_orders() {
    let q = |s: &str| rcagd_algebra::parse_rational(s).unwrap();
    assert_eq!(decimal_order(&q("0")), None);
    assert_eq!(decimal_order(&q("1")), Some(0));
    assert_eq!(decimal_order(&q("1e300")), Some(300));
    assert_eq!(decimal_order(&q("-1e-300")), Some(-300));
    assert_eq!(decimal_order(&q("999/1000")), Some(-1));
    assert_eq!(decimal_order(&q("1e1000")), Some(1000));
    let xs = [q("0"), q("1/2"), q("1e300"), q("3")];
    let (s, lo, hi) = magnitude_spread(&xs).unwrap();
    assert!((s - 300.301_029_995_66).abs() < 1e-6, "{s}");
    assert_eq!((lo, hi), (&xs[1], &xs[2]));
    assert_eq!(magnitude_spread(&[q("0")]), None);
}
