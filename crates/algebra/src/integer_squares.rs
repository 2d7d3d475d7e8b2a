//! Integers and rationals as sums of two and of four squares, constructively.
//!
//! * **A prime `p ≡ 1 (mod 4)` as `x² + y²`** ([`prime_two_squares`]): Cornacchia's
//!   algorithm (also Hermite–Serret): with `s² ≡ −1 (mod p)` ([`sqrt_mod_prime`]), run
//!   Euclid's algorithm on `(p, s)` until the remainder `x` drops below `√p`; then
//!   `p − x²` is a square `y²` (H. Cohen, *A Course in Computational Algebraic Number
//!   Theory*, 1993, Algorithm 1.5.2).
//! * **Any `n ≥ 0` as `x₁² + x₂² + x₃² + x₄²`** ([`four_squares`]), Lagrange's theorem made
//!   constructive by the randomized algorithm of M. O. Rabin and J. O. Shallit ("Randomized
//!   algorithms in number theory", Comm. Pure Appl. Math. 39, 1986): write `n = 4ᵏn′`
//!   (`n′ ≢ 0 mod 4`); draw `x, y ≤ √n′` with the parities that make `M = n′ − x² − y² ≡ 1
//!   (mod 4)` (`x, y` even for `n′ ≡ 1`, `x` odd and `y` even for `n′ ≡ 2`, both odd for
//!   `n′ ≡ 3`) until `M` is `1` or a prime, then split `M = z² + w²` by Cornacchia; the
//!   answer is `2ᵏ(x, y, z, w)`. By the prime number theorem in progressions about one draw
//!   in `ln n / 2` succeeds. Small `n′` are searched exhaustively.
//!
//! The primality test is probabilistic above `3.3·10²⁴` ([`is_probable_prime`]), but nothing
//! returned depends on it: every representation is checked exactly before it is returned (a
//! composite `M` that passed the test makes Cornacchia's output fail the check, and the
//! draw is discarded). The draws come from a fixed-seed generator, so the answers are
//! reproducible.

use crate::integer::{is_probable_prime, sqrt_mod_prime};
use crate::Rational;
use dashu_base::{BitTest, SquareRoot, UnsignedAbs};
use dashu_int::{IBig, UBig};

/// The draws [`four_squares`] makes at most before it gives up (`None`); with a success
/// rate of about `2 / ln n` per draw this is far beyond what numbers of a few thousand bits
/// need.
pub const FOUR_SQUARES_DRAWS: usize = 200_000;

/// Below this `n′` the four squares are searched exhaustively.
const EXHAUSTIVE_BELOW: u64 = 1 << 16;

/// The odd primes below this bound are used to discard draws before the primality test.
const SIEVE_BOUND: u64 = 2000;

fn small_odd_primes() -> Vec<u64> {
    let mut ps: Vec<u64> = Vec::new();
    let mut k = 3u64;
    while k < SIEVE_BOUND {
        if ps
            .iter()
            .take_while(|p| *p * *p <= k)
            .all(|p| !k.is_multiple_of(*p))
        {
            ps.push(k);
        }
        k += 2;
    }
    ps
}

/// `x` and `y` with `x² + y² = p` for a prime `p = 2` or `p ≡ 1 (mod 4)` (module docs);
/// `None` if `p` is not of that form (or not prime: the result is checked exactly).
pub fn prime_two_squares(p: &UBig) -> Option<(UBig, UBig)> {
    if *p == UBig::from(2u8) {
        return Some((UBig::ONE, UBig::ONE));
    }
    if (p % 4u8) != 1 {
        return None;
    }
    let s = sqrt_mod_prime(&IBig::from(-1), p)?;
    let (mut a, mut b) = (p.clone(), s);
    while &b * &b > *p {
        let r = &a % &b;
        a = b;
        b = r;
    }
    let rest = p - &b * &b;
    let y = rest.sqrt();
    (&y * &y == rest).then_some((b, y))
}

/// A splitmix64 generator: reproducible draws without a dependency.
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A draw in `[0, bound]` (`bound` any size): random bits, reduced.
    fn below_or_equal(&mut self, bound: &UBig) -> UBig {
        let words = bound.bit_len() / 64 + 2;
        let mut x = UBig::ZERO;
        for _ in 0..words {
            x = (x << 64) + UBig::from(self.next());
        }
        x % (bound + UBig::ONE)
    }
}

/// `n′ ≢ 0 (mod 4)` as four squares by exhaustive search (small `n′`).
fn four_squares_small(n: u64) -> Option<[u64; 4]> {
    let isqrt = |m: u64| -> u64 {
        let mut r = (m as f64).sqrt() as u64;
        while r * r > m {
            r -= 1;
        }
        while (r + 1) * (r + 1) <= m {
            r += 1;
        }
        r
    };
    for x in 0..=isqrt(n) {
        let m1 = n - x * x;
        for y in 0..=isqrt(m1) {
            let m2 = m1 - y * y;
            for z in 0..=isqrt(m2) {
                let m3 = m2 - z * z;
                let w = isqrt(m3);
                if w * w == m3 {
                    return Some([x, y, z, w]);
                }
            }
        }
    }
    None
}

/// `[x₁, x₂, x₃, x₄]` with `x₁² + x₂² + x₃² + x₄² = n` (module docs); `None` only if
/// [`FOUR_SQUARES_DRAWS`] draws all fail (not seen). `seed` chooses the draws.
pub fn four_squares(n: &UBig, seed: u64) -> Option<[UBig; 4]> {
    if *n == UBig::ZERO {
        return Some([UBig::ZERO, UBig::ZERO, UBig::ZERO, UBig::ZERO]);
    }
    let mut m = n.clone();
    let mut k = 0usize;
    while (&m % 4u8) == 0 {
        m >>= 2;
        k += 1;
    }
    let scale = |v: [UBig; 4]| v.map(|x| x << k);
    if let Ok(small) = u64::try_from(&m) {
        if small < EXHAUSTIVE_BELOW {
            return four_squares_small(small).map(|v| scale(v.map(UBig::from)));
        }
    }
    let (px, py) = match &m % 4u8 {
        1 => (0u8, 0u8),
        2 => (1, 0),
        _ => (1, 1),
    };
    let root = m.sqrt();
    let primes = small_odd_primes();
    let mut rng = SplitMix(seed ^ 0x5EED_F0E5_4A2B_11C3);
    let fix_parity = |v: UBig, p: u8| -> UBig {
        if u8::from(v.bit(0)) == p {
            v
        } else if v.is_zero() {
            UBig::ONE
        } else {
            v - UBig::ONE
        }
    };
    for _ in 0..FOUR_SQUARES_DRAWS {
        let x = fix_parity(rng.below_or_equal(&root), px);
        let y = fix_parity(rng.below_or_equal(&root), py);
        let used = &x * &x + &y * &y;
        if used > m {
            continue;
        }
        let rest = &m - &used;
        let (z, w) = if rest == UBig::ONE {
            (UBig::ONE, UBig::ZERO)
        } else {
            if primes
                .iter()
                .any(|p| (&rest % *p) == 0 && rest != UBig::from(*p))
            {
                continue;
            }
            if !is_probable_prime(&rest) {
                continue;
            }
            match prime_two_squares(&rest) {
                Some(zw) => zw,
                None => continue,
            }
        };
        let v = [x, y, z, w];
        let sum: UBig = v.iter().map(|a| a * a).sum();
        if sum == m {
            return Some(scale(v));
        }
    }
    None
}

/// A rational `q ≥ 0` as `x₁² + x₂² + x₃² + x₄²` with rational `xᵢ` (`q = a/b`:
/// `ab = Σ yᵢ²` by [`four_squares`], `xᵢ = yᵢ/b`); `None` for `q < 0` (or if the draws
/// fail).
pub fn rational_four_squares(q: &Rational, seed: u64) -> Option<[Rational; 4]> {
    if *q < Rational::ZERO {
        return None;
    }
    let (num, den) = (
        q.numerator().clone().unsigned_abs(),
        q.denominator().clone(),
    );
    let ys = four_squares(&(&num * &den), seed)?;
    Some(ys.map(|y| Rational::from_parts(IBig::from(y), den.clone())))
}

/// `n` as `x² + y²` when trial division decides it (a sum of two squares is a product of
/// sums of two squares: `(a² + b²)(c² + d²) = (ac − bd)² + (ad + bc)²`, the product of the
/// Gaussian integers `a + bi`, `c + di`; Fermat–Euler: `n` is one iff every prime
/// `≡ 3 (mod 4)` divides it to an even power, Cohen 1993, §1.5.2). `n` is divided by `2` and
/// the odd primes below `2000`; each prime `p ≡ 1 (mod 4)` is split by [`prime_two_squares`],
/// each `p ≡ 3 (mod 4)` must come squared, and the cofactor must be `1`, a square or a
/// (probable) prime `≡ 1 (mod 4)`. `None` otherwise — `n` may still be a sum of two squares,
/// but deciding that needs a factorization (callers draw another `n`). The result is checked
/// exactly.
pub fn two_squares_by_trial_division(n: &UBig) -> Option<(UBig, UBig)> {
    if *n == UBig::ZERO {
        return Some((UBig::ZERO, UBig::ZERO));
    }
    type Gauss = (IBig, IBig);
    let mul =
        |a: &Gauss, b: &Gauss| -> Gauss { (&a.0 * &b.0 - &a.1 * &b.1, &a.0 * &b.1 + &a.1 * &b.0) };
    let mut m = n.clone();
    let mut g: Gauss = (IBig::ONE, IBig::ZERO);
    let mut scale = UBig::ONE;
    // 2 = (1 + i)(1 − i)
    let one_plus_i: Gauss = (IBig::ONE, IBig::ONE);
    while (&m % 2u8) == 0 {
        m >>= 1;
        g = mul(&g, &one_plus_i);
    }
    for p in small_odd_primes() {
        if m == UBig::ONE {
            break;
        }
        let mut e = 0u32;
        while (&m % p) == 0 {
            m /= p;
            e += 1;
        }
        if e == 0 {
            continue;
        }
        if p % 4 == 3 {
            if e % 2 == 1 {
                return None;
            }
            scale *= UBig::from(p).pow(e as usize / 2);
        } else {
            let (x, y) = prime_two_squares(&UBig::from(p))?;
            let f: Gauss = (IBig::from(x), IBig::from(y));
            for _ in 0..e {
                g = mul(&g, &f);
            }
        }
    }
    if m != UBig::ONE {
        let root = m.sqrt();
        if &root * &root == m {
            scale *= root;
        } else if (&m % 4u8) == 1 && is_probable_prime(&m) {
            let (x, y) = prime_two_squares(&m)?;
            g = mul(&g, &(IBig::from(x), IBig::from(y)));
        } else {
            return None;
        }
    }
    let (x, y) = (g.0.unsigned_abs() * &scale, g.1.unsigned_abs() * &scale);
    (&x * &x + &y * &y == *n).then_some((x, y))
}

/// A rational `q ≥ 0` as `x² + y²` with rational `x`, `y`, when
/// [`two_squares_by_trial_division`] decides it: `q = a/b` with `b = e²` a square gives
/// `a = u² + v²`, `(x, y) = (u, v)/e`; otherwise `ab = u² + v²`, `(x, y) = (u, v)/b`. `None`
/// for `q < 0` or when that is not decided. The complete decision, which factors as far as
/// needed, is [`crate::sum_of_squares::rational_two_squares`]; this one is for callers that
/// would rather draw another `q` than factor.
pub fn rational_two_squares_by_trial_division(q: &Rational) -> Option<(Rational, Rational)> {
    if *q < Rational::ZERO {
        return None;
    }
    let (num, den) = (
        q.numerator().clone().unsigned_abs(),
        q.denominator().clone(),
    );
    let e = den.sqrt();
    let (n, d) = if &e * &e == den {
        (num, e)
    } else {
        (&num * &den, den)
    };
    let (x, y) = two_squares_by_trial_division(&n)?;
    let f = |v: UBig| Rational::from_parts(IBig::from(v), d.clone());
    Some((f(x), f(y)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Scalar;
    use proptest::prelude::*;

    #[test]
    fn primes_as_two_squares() {
        for p in [2u64, 5, 13, 17, 29, 37, 41, 1_000_000_009, 998_244_353] {
            let pb = UBig::from(p);
            if p % 4 == 3 {
                assert!(prime_two_squares(&pb).is_none());
                continue;
            }
            let (x, y) = prime_two_squares(&pb).expect("p ≡ 1 mod 4");
            assert_eq!(&x * &x + &y * &y, pb, "{p}");
        }
        // p ≡ 3 (mod 4) and a composite ≡ 1 (mod 4) with no such form
        assert!(prime_two_squares(&UBig::from(7u8)).is_none());
        assert!(prime_two_squares(&UBig::from(21u8)).is_none());
        let big = (UBig::ONE << 127) - UBig::ONE; // prime, ≡ 3 mod 4
        assert!(prime_two_squares(&big).is_none());
    }

    #[test]
    fn every_small_number_is_four_squares() {
        for n in 0u64..3000 {
            let v = four_squares(&UBig::from(n), 1).expect("Lagrange");
            let s: UBig = v.iter().map(|a| a * a).sum();
            assert_eq!(s, UBig::from(n));
        }
    }

    #[test]
    fn sums_of_two_squares_by_trial_division() {
        // every n < 5000 that trial division decides is split exactly, and it decides all
        // of them (their prime factors are small or the cofactor is a prime)
        let is_sum = |n: u64| {
            (0..=n).take_while(|x| x * x <= n).any(|x| {
                let r = n - x * x;
                let y = (r as f64).sqrt() as u64;
                (y.saturating_sub(1)..=y + 1).any(|y| y * y == r)
            })
        };
        for n in 0u64..5000 {
            let got = two_squares_by_trial_division(&UBig::from(n));
            assert_eq!(got.is_some(), is_sum(n), "{n}");
            if let Some((x, y)) = got {
                assert_eq!(&x * &x + &y * &y, UBig::from(n));
            }
        }
        // a large prime ≡ 1 (mod 4) times small factors; a large prime ≡ 3 (mod 4) squared
        let p = UBig::from(1_000_000_009u64); // ≡ 1 (mod 4)
        let n = &p * UBig::from(2u8 * 5 * 9);
        let (x, y) = two_squares_by_trial_division(&n).expect("decided");
        assert_eq!(&x * &x + &y * &y, n);
        let big = (UBig::ONE << 127) - UBig::ONE; // prime, ≡ 3 mod 4
        let sq = &big * &big * UBig::from(13u8);
        let (x, y) = two_squares_by_trial_division(&sq).expect("a square times 13");
        assert_eq!(&x * &x + &y * &y, sq);
        assert!(two_squares_by_trial_division(&big).is_none());
        // two large primes ≡ 1 (mod 4): a sum of two squares, not decided without factoring
        let q = UBig::from(1_000_000_021u64); // prime, ≡ 1 (mod 4)
        assert!(two_squares_by_trial_division(&(&p * &q)).is_none());
    }

    #[test]
    fn rationals_as_two_squares() {
        for (n, d) in [
            (5i64, 9i64),
            (5, 2),
            (25, 8),
            (0, 1),
            (1, 2),
            (13, 1_000_000_009),
        ] {
            let q = Rational::from_ratio(n, d);
            let (x, y) = rational_two_squares_by_trial_division(&q).expect("decided");
            assert_eq!(&x * &x + &y * &y, q, "{n}/{d}");
        }
        // 3/4 and 5/3 (15 = 3·5) are not sums of two rational squares
        assert!(rational_two_squares_by_trial_division(&Rational::from_ratio(3, 4)).is_none());
        assert!(rational_two_squares_by_trial_division(&Rational::from_ratio(5, 3)).is_none());
        assert!(rational_two_squares_by_trial_division(&Rational::from(-1)).is_none());
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]
        #[test]
        fn big_numbers_are_four_squares(words in proptest::collection::vec(any::<u64>(), 1..6), seed in any::<u64>()) {
            let n = words.iter().fold(UBig::ZERO, |acc, w| (acc << 64) + UBig::from(*w));
            let v = four_squares(&n, seed).expect("found");
            let s: UBig = v.iter().map(|a| a * a).sum();
            prop_assert_eq!(s, n);
        }

        #[test]
        fn rationals_are_four_squares(n in 0i64..1_000_000_000, d in 1i64..1_000_000_000) {
            let q = Rational::from_ratio(n, d);
            let v = rational_four_squares(&q, 7).expect("found");
            let s = v.iter().fold(Rational::ZERO, |acc, x| acc + x.clone() * x.clone());
            prop_assert_eq!(s, q);
        }
    }
}
