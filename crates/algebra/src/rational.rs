//! Exact rationals ([`Rational`] = `dashu_ratio::RBig`) and exact parsing of user numbers.
//!
//! Numbers written by a user are exact: `"3/7"`, `"-0.125"` (= −1/8), `"12"`,
//! `"1e-3"` (= 1/1000), `"2.5E+2"`. A decimal is its exact decimal value, never a
//! binary float.

use crate::error::AlgebraError;
use dashu_base::{SquareRoot, UnsignedAbs};
use dashu_int::{IBig, UBig};

/// The exact rational number type of rcagd.
pub type Rational = dashu_ratio::RBig;

fn parse_err(input: &str, reason: &str) -> AlgebraError {
    AlgebraError::ParseNumber {
        input: input.to_string(),
        reason: reason.to_string(),
    }
}

fn parse_int(s: &str, input: &str) -> Result<IBig, AlgebraError> {
    let digits = s.strip_prefix(['+', '-']).unwrap_or(s);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return Err(parse_err(input, "expected digits"));
    }
    let v: IBig = digits
        .parse()
        .map_err(|_| parse_err(input, "expected digits"))?;
    Ok(if s.starts_with('-') { -v } else { v })
}

/// Parses a decimal number `[+-]digits[.digits][(e|E)[+-]digits]` exactly.
fn parse_decimal(s: &str, input: &str) -> Result<Rational, AlgebraError> {
    let (mantissa, exp) = match s.find(['e', 'E']) {
        Some(i) => {
            let e = &s[i + 1..];
            let e_digits = e.strip_prefix(['+', '-']).unwrap_or(e);
            if e_digits.is_empty() || !e_digits.bytes().all(|b| b.is_ascii_digit()) {
                return Err(parse_err(input, "malformed exponent"));
            }
            if e_digits.len() > 6 {
                return Err(parse_err(input, "exponent too large"));
            }
            let e: i64 = e
                .parse()
                .map_err(|_| parse_err(input, "malformed exponent"))?;
            (&s[..i], e)
        }
        None => (s, 0),
    };
    let negative = mantissa.starts_with('-');
    let body = mantissa.strip_prefix(['+', '-']).unwrap_or(mantissa);
    let (int_part, frac_part) = match body.split_once('.') {
        Some((a, b)) => (a, b),
        None => (body, ""),
    };
    if int_part.is_empty() && frac_part.is_empty() {
        return Err(parse_err(input, "expected digits"));
    }
    if !int_part.bytes().all(|b| b.is_ascii_digit())
        || !frac_part.bytes().all(|b| b.is_ascii_digit())
    {
        return Err(parse_err(
            input,
            "expected an integer, a fraction p/q or a decimal",
        ));
    }
    let digits = format!("{int_part}{frac_part}");
    let mut num: IBig = if digits.is_empty() {
        IBig::ZERO
    } else {
        digits
            .parse()
            .map_err(|_| parse_err(input, "expected digits"))?
    };
    if negative {
        num = -num;
    }
    let scale = exp - frac_part.len() as i64;
    let ten = UBig::from(10u8);
    Ok(if scale >= 0 {
        Rational::from(num * IBig::from(ten.pow(scale as usize)))
    } else {
        Rational::from_parts(num, ten.pow((-scale) as usize))
    })
}

/// Parses an exact number: an integer `"12"`, a fraction `"3/7"` (numerator and
/// denominator may be decimals, `"1.5/2"`), or a decimal with optional exponent
/// (`"-0.125"`, `"1e-3"`). Surrounding whitespace is ignored.
///
/// # Errors
/// [`AlgebraError::ParseNumber`] naming the input when it is not a number or the
/// denominator is zero.
pub fn parse_rational(input: &str) -> Result<Rational, AlgebraError> {
    let s = input.trim();
    if s.is_empty() {
        return Err(parse_err(input, "empty"));
    }
    if let Some((p, q)) = s.split_once('/') {
        let p = parse_decimal(p.trim(), input)?;
        let q = parse_decimal(q.trim(), input)?;
        if q.is_zero() {
            return Err(parse_err(input, "zero denominator"));
        }
        return Ok(p / q);
    }
    if s.contains(['.', 'e', 'E']) {
        parse_decimal(s, input)
    } else {
        Ok(Rational::from(parse_int(s, input)?))
    }
}

/// The exact square root of a non-negative rational, if it is a rational square.
pub fn rational_sqrt(q: &Rational) -> Option<Rational> {
    if q.numerator() < &IBig::ZERO {
        return None;
    }
    let num = q.numerator().clone().unsigned_abs();
    let den = q.denominator();
    let sn = num.sqrt();
    let sd = den.sqrt();
    if &sn * &sn == num && &sd * &sd == *den {
        Some(Rational::from_parts(IBig::from(sn), sd))
    } else {
        None
    }
}

/// `true` if `q` is the square of a rational.
pub fn is_rational_square(q: &Rational) -> bool {
    rational_sqrt(q).is_some()
}

/// `q` rounded down (or up) to `digits` significant decimal digits.
pub fn round_decimal(q: &Rational, digits: u32, up: bool) -> Rational {
    if *q == Rational::ZERO {
        return q.clone();
    }
    // e = ⌊log10 |q|⌋ (approximately; any e gives a valid outward rounding)
    let e = q.to_f64().value().abs().log10().floor();
    let e = if e.is_finite() { e as i64 } else { 0 };
    let k = i64::from(digits) - 1 - e; // scale 10^k
    let ten = UBig::from(10u8);
    let scale = if k >= 0 {
        Rational::from(ten.pow(k as usize))
    } else {
        Rational::from_parts(IBig::ONE, ten.pow((-k) as usize))
    };
    let x = q * &scale;
    let n = if up { x.ceil() } else { x.floor() };
    Rational::from(n) / scale
}

/// A rational whose denominator divides a power of ten, as a decimal (`-12.0625`); any other
/// rational as `p/q`.
pub fn format_decimal(q: &Rational) -> String {
    // q = n/(2^a 5^b): k = max(a, b) decimals
    let mut den = q.denominator().clone();
    let (two, five) = (UBig::from(2u8), UBig::from(5u8));
    let (mut a, mut b) = (0usize, 0usize);
    while &den % &two == UBig::ZERO {
        den /= &two;
        a += 1;
    }
    while &den % &five == UBig::ZERO {
        den /= &five;
        b += 1;
    }
    let k = a.max(b);
    let ten = UBig::from(10u8);
    if den != UBig::ONE {
        return format_rational(q);
    }
    let n = q * Rational::from(ten.pow(k));
    let n = n.numerator().clone();
    let neg = n < IBig::ZERO;
    let digits = if neg { (-n).to_string() } else { n.to_string() };
    let body = if k == 0 {
        digits
    } else if digits.len() > k {
        format!(
            "{}.{}",
            &digits[..digits.len() - k],
            &digits[digits.len() - k..]
        )
    } else {
        format!("0.{}{}", "0".repeat(k - digits.len()), digits)
    };
    if neg {
        format!("-{body}")
    } else {
        body
    }
}

/// Formats a rational as `"p/q"` (or `"p"` when integral), the exchange form of rcagd.
pub fn format_rational(q: &Rational) -> String {
    if q.denominator() == &UBig::ONE {
        format!("{}", q.numerator())
    } else {
        format!("{}/{}", q.numerator(), q.denominator())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_parts_signed(IBig::from(p), IBig::from(d))
    }

    #[test]
    fn decimals_round_outward_and_print_exactly() {
        assert_eq!(format_decimal(&q(-1, 8)), "-0.125");
        assert_eq!(format_decimal(&q(12, 1)), "12");
        assert_eq!(format_decimal(&q(1, 3)), "1/3");
        assert_eq!(format_decimal(&q(3, 400)), "0.0075");
        let third = q(1, 3);
        let (lo, hi) = (
            round_decimal(&third, 4, false),
            round_decimal(&third, 4, true),
        );
        assert_eq!(
            (format_decimal(&lo), format_decimal(&hi)),
            ("0.3333".into(), "0.3334".into())
        );
        let big = q(-200_000_001, 3);
        assert!(round_decimal(&big, 5, false) <= big && big <= round_decimal(&big, 5, true));
        assert_eq!(format_decimal(&round_decimal(&big, 5, true)), "-66666000");
    }

    #[test]
    fn parses_exact_numbers() {
        assert_eq!(parse_rational("3/7").ok(), Some(q(3, 7)));
        assert_eq!(parse_rational("-0.125").ok(), Some(q(-1, 8)));
        assert_eq!(parse_rational("12").ok(), Some(q(12, 1)));
        assert_eq!(parse_rational("1e-3").ok(), Some(q(1, 1000)));
        assert_eq!(parse_rational("2.5E+2").ok(), Some(q(250, 1)));
        assert_eq!(parse_rational("0.1").ok(), Some(q(1, 10)));
        assert_eq!(parse_rational(" -6/4 ").ok(), Some(q(-3, 2)));
        assert_eq!(parse_rational(".5").ok(), Some(q(1, 2)));
        assert_eq!(parse_rational("+7").ok(), Some(q(7, 1)));
    }

    #[test]
    fn rejects_non_numbers() {
        for bad in [
            "",
            "abc",
            "1/0",
            "1.2.3",
            "e5",
            "1e",
            "--1",
            "1/",
            "0x10",
            "nan",
            "1e9999999",
        ] {
            assert!(parse_rational(bad).is_err(), "{bad:?} should not parse");
        }
    }

    #[test]
    fn squares() {
        assert_eq!(rational_sqrt(&q(9, 4)), Some(q(3, 2)));
        assert_eq!(rational_sqrt(&q(2, 1)), None);
        assert_eq!(rational_sqrt(&q(-4, 1)), None);
        assert_eq!(rational_sqrt(&q(0, 1)), Some(q(0, 1)));
        assert!(is_rational_square(&q(25, 49)));
        assert!(!is_rational_square(&q(3, 4)));
    }

    #[test]
    fn formats() {
        assert_eq!(format_rational(&q(-3, 7)), "-3/7");
        assert_eq!(format_rational(&q(4, 2)), "2");
    }
}
