//! The big-integer arithmetic under every exact certificate, checked against an independent
//! computation: residues modulo word-size primes computed here from the decimal digits
//! (own `u128` code), compared with the residues of dashu's results. A wrong product is
//! caught unless it agrees modulo all four primes (probability about 2⁻²⁴⁰ for an
//! unstructured error).
//!
//! Regression (third_party/README.md): dashu-int 0.6.2's NTT multiplication squared
//! `6·(R + 1)`, `R` the repunit of 78 000 ones, wrongly; the patched copy uses Toom-3.

use dashu_int::{IBig, UBig};
use std::str::FromStr;

const PRIMES: [u64; 4] = [
    (1 << 61) - 1,
    4_611_686_018_427_387_847,  // 2^62 − 57
    9_223_372_036_854_775_783,  // 2^63 − 25
    18_446_744_073_709_551_557, // 2^64 − 59
];

/// The residues of a decimal numeral modulo [`PRIMES`] (Horner, base 10).
fn residues_of_digits(digits: &str) -> [u64; 4] {
    PRIMES.map(|p| {
        digits.bytes().fold(0u128, |acc, d| {
            (acc * 10 + u128::from(d - b'0')) % u128::from(p)
        }) as u64
    })
}

/// The residues of a non-negative dashu integer modulo [`PRIMES`], from its bytes.
fn residues_of(x: &UBig) -> [u64; 4] {
    let bytes = x.to_le_bytes();
    PRIMES.map(|p| {
        bytes
            .iter()
            .rev()
            .fold(0u128, |acc, &b| (acc * 256 + u128::from(b)) % u128::from(p)) as u64
    })
}

fn mul_mod(a: [u64; 4], b: [u64; 4]) -> [u64; 4] {
    let mut out = [0u64; 4];
    for k in 0..4 {
        out[k] = ((u128::from(a[k]) * u128::from(b[k])) % u128::from(PRIMES[k])) as u64;
    }
    out
}

fn add_mod(a: [u64; 4], b: [u64; 4]) -> [u64; 4] {
    let mut out = [0u64; 4];
    for k in 0..4 {
        out[k] = ((u128::from(a[k]) + u128::from(b[k])) % u128::from(PRIMES[k])) as u64;
    }
    out
}

/// A decimal numeral parsed by dashu, checked against its digits.
fn parsed(digits: &str) -> (UBig, [u64; 4]) {
    let x = UBig::from_str(digits).expect("a decimal numeral");
    let r = residues_of_digits(digits);
    assert_eq!(residues_of(&x), r, "parsing {} digits", digits.len());
    (x, r)
}

/// Numerals with the structures that exposed the fault, and pseudo-random ones
/// (a fixed linear congruential generator: the test is reproducible).
fn numerals() -> Vec<(String, String)> {
    let mut out = Vec::new();
    for n in [10_000usize, 78_000, 200_000] {
        out.push((format!("repunit {n}"), "1".repeat(n)));
        out.push((format!("nines {n}"), "9".repeat(n)));
    }
    // 6·(R + 1) with R the repunit of 78 000 ones: 666…672
    out.push((
        "6(R+1), 78 000 digits".into(),
        format!("{}72", "6".repeat(77_998)),
    ));
    let mut state = 0x2545_f491_4f6c_dd1du64;
    for n in [10_000usize, 100_000, 1_000_000] {
        let digits: String = (0..n)
            .map(|k| {
                state = state
                    .wrapping_mul(6_364_136_223_846_793_005)
                    .wrapping_add(1_442_695_040_888_963_407);
                let d = (state >> 60) % 10;
                char::from(b'0' + if k == 0 { 1 + d % 9 } else { d } as u8)
            })
            .collect();
        out.push((format!("random {n}"), digits));
    }
    out
}

#[test]
fn squares_and_products_of_large_integers_are_right() {
    let nums: Vec<(String, UBig, [u64; 4])> = numerals()
        .into_iter()
        .map(|(name, d)| {
            let (x, r) = parsed(&d);
            (name, x, r)
        })
        .collect();
    for (name, x, r) in &nums {
        // the square, through the product of two equal values and through `sqr`
        let y = x.clone();
        assert_eq!(residues_of(&(x * &y)), mul_mod(*r, *r), "{name}: x·x");
        assert_eq!(residues_of(&x.sqr()), mul_mod(*r, *r), "{name}: x²");
    }
    for w in nums.windows(2) {
        let ((n1, x1, r1), (n2, x2, r2)) = (&w[0], &w[1]);
        assert_eq!(residues_of(&(x1 * x2)), mul_mod(*r1, *r2), "{n1} · {n2}");
        assert_eq!(residues_of(&(x1 + x2)), add_mod(*r1, *r2), "{n1} + {n2}");
    }
}

/// The certificate that exposed the fault: `Xᵀ Q X ≡ 0` for the image on the unit sphere
/// of a cubic whose first control point has the x coordinate `111…1` (78 000 digits),
/// computed as signed rationals (squares of large integers inside Bernstein products).
#[test]
fn a_signed_square_of_78000_digits_is_right() {
    let (x, r) = parsed(&format!("{}72", "6".repeat(77_998)));
    let neg = -IBig::from(x.clone());
    let sq = &neg * &neg;
    let sq = UBig::try_from(sq).expect("a square is not negative");
    assert_eq!(residues_of(&sq), mul_mod(r, r));
}
