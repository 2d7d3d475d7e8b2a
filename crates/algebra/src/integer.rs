//! Integer arithmetic for the rational-point engines: factorization into primes, square
//! roots modulo primes, square-free parts.
//!
//! * **Factorization** ([`factor`]): trial division by the primes below `2¹⁶`, then
//!   Brent's variant of Pollard's ρ on the cofactor, with a fixed work limit
//!   ([`RHO_ITERATIONS`] steps per split); a cofactor that resists is reported as
//!   [`IntegerError::TooHard`], never guessed. Primality is decided by the Miller–Rabin test
//!   with the first twelve prime bases (a proof below `3.3·10²⁴`) plus eight further
//!   bases above that bound.
//! * **Square roots modulo a prime** ([`sqrt_mod_prime`]): Tonelli–Shanks.

use dashu_base::{BitTest, Gcd, SquareRoot, UnsignedAbs};
use dashu_int::{IBig, UBig};
use thiserror::Error;

/// The number of Pollard–Brent steps spent on one split before giving up.
pub const RHO_ITERATIONS: usize = 1 << 20;

/// A failure of the integer arithmetic (never a wrong result).
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum IntegerError {
    /// A composite cofactor could not be split within the work limit.
    #[error(
        "cannot factor the integer {0} within the work limit (Pollard ρ, {RHO_ITERATIONS} steps)"
    )]
    TooHard(String),
}

/// `bᵉ mod m` (`m ≥ 1`).
pub fn pow_mod(b: &UBig, e: &UBig, m: &UBig) -> UBig {
    let mut r = UBig::ONE % m;
    let b = b % m;
    for i in (0..e.bit_len()).rev() {
        r = (&r * &r) % m;
        if e.bit(i) {
            r = (&r * &b) % m;
        }
    }
    r
}

const SMALL_BASES: [u64; 20] = [
    2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71,
];

/// Miller–Rabin (module docs).
pub fn is_probable_prime(n: &UBig) -> bool {
    let two = UBig::from(2u8);
    if *n < two {
        return false;
    }
    for p in SMALL_BASES {
        let pb = UBig::from(p);
        if *n == pb {
            return true;
        }
        if (n % &pb).is_zero() {
            return false;
        }
    }
    let n1 = n - UBig::ONE;
    let mut d = n1.clone();
    let mut s = 0usize;
    while !d.bit(0) {
        d >>= 1;
        s += 1;
    }
    'outer: for a in SMALL_BASES {
        let mut x = pow_mod(&UBig::from(a), &d, n);
        if x == UBig::ONE || x == n1 {
            continue;
        }
        for _ in 1..s {
            x = (&x * &x) % n;
            if x == n1 {
                continue 'outer;
            }
        }
        return false;
    }
    true
}

fn abs_diff(a: &UBig, b: &UBig) -> UBig {
    if a >= b {
        a - b
    } else {
        b - a
    }
}

/// A non-trivial divisor of the odd composite `n` (Pollard–Brent), or `None` within the
/// work limit.
fn rho_split(n: &UBig) -> Option<UBig> {
    for c in 1u64..=16 {
        let c = UBig::from(c);
        let f = |x: &UBig| (x * x + &c) % n;
        let (mut y, mut r, mut q) = (UBig::from(2u8), 1usize, UBig::ONE);
        let (mut x, mut ys) = (y.clone(), y.clone());
        let mut g = UBig::ONE;
        let mut steps = 0usize;
        const M: usize = 128;
        while g == UBig::ONE {
            x = y.clone();
            for _ in 0..r {
                y = f(&y);
            }
            let mut k = 0;
            while k < r && g == UBig::ONE {
                ys = y.clone();
                for _ in 0..M.min(r - k) {
                    y = f(&y);
                    q = (&q * abs_diff(&x, &y)) % n;
                }
                g = (&q).gcd(n);
                k += M;
            }
            r *= 2;
            steps += r;
            if steps > RHO_ITERATIONS {
                break;
            }
        }
        if g == *n {
            loop {
                ys = f(&ys);
                g = (&abs_diff(&x, &ys)).gcd(n);
                if g != UBig::ONE {
                    break;
                }
            }
        }
        if g != UBig::ONE && g != *n {
            return Some(g);
        }
    }
    None
}

fn push(out: &mut Vec<(UBig, u32)>, p: UBig, e: u32) {
    match out.iter_mut().find(|(q, _)| *q == p) {
        Some((_, k)) => *k += e,
        None => out.push((p, e)),
    }
}

/// The prime factorization `n = ∏ pᵢ^{eᵢ}` of `n ≥ 1`, primes ascending (module docs).
///
/// # Errors
/// [`IntegerError::TooHard`] when a composite cofactor resists Pollard's ρ.
pub fn factor(n: &UBig) -> Result<Vec<(UBig, u32)>, IntegerError> {
    let mut out: Vec<(UBig, u32)> = Vec::new();
    if n.is_zero() {
        return Ok(out);
    }
    let mut m = n.clone();
    let mut p: u64 = 2;
    while p < (1 << 16) {
        let pb = UBig::from(p);
        if &pb * &pb > m {
            break;
        }
        let mut e = 0;
        while (&m % &pb).is_zero() {
            m /= &pb;
            e += 1;
        }
        if e > 0 {
            out.push((pb, e));
        }
        p += if p == 2 { 1 } else { 2 };
    }
    let mut stack = vec![m];
    while let Some(m) = stack.pop() {
        if m == UBig::ONE {
            continue;
        }
        if is_probable_prime(&m) {
            push(&mut out, m, 1);
            continue;
        }
        let r = m.sqrt();
        if &r * &r == m {
            stack.push(r.clone());
            stack.push(r);
            continue;
        }
        let d = rho_split(&m).ok_or_else(|| IntegerError::TooHard(m.to_string()))?;
        let q = &m / &d;
        stack.push(d);
        stack.push(q);
    }
    out.sort();
    Ok(out)
}

/// The square-free decomposition `n = s·f²` of a non-zero integer: `(s, f)` with `s`
/// square-free, `sign(s) = sign(n)`, `f > 0`, and the primes of `s`.
///
/// # Errors
/// As [`factor`].
pub fn square_free_part(n: &IBig) -> Result<(IBig, UBig, Vec<UBig>), IntegerError> {
    let fs = factor(&n.clone().unsigned_abs())?;
    let mut s = UBig::ONE;
    let mut f = UBig::ONE;
    let mut primes = Vec::new();
    for (p, e) in fs {
        f *= p.pow((e / 2) as usize);
        if e % 2 == 1 {
            s *= &p;
            primes.push(p);
        }
    }
    let s = if *n < IBig::ZERO {
        -IBig::from(s)
    } else {
        IBig::from(s)
    };
    Ok((s, f, primes))
}

/// `a mod m` in `[0, m)` for an integer `a`.
pub fn rem_euclid(a: &IBig, m: &UBig) -> UBig {
    let mi = IBig::from(m.clone());
    let r = a % &mi;
    let r = if r < IBig::ZERO { r + mi } else { r };
    UBig::try_from(r).unwrap_or(UBig::ZERO)
}

/// The Legendre symbol `(a/p)` for an odd prime `p`: `1`, `−1`, or `0` if `p | a`.
pub fn legendre(a: &IBig, p: &UBig) -> i8 {
    let r = rem_euclid(a, p);
    if r.is_zero() {
        return 0;
    }
    let e = (p - UBig::ONE) >> 1;
    if pow_mod(&r, &e, p) == UBig::ONE {
        1
    } else {
        -1
    }
}

/// A square root of `a` modulo the prime `p` (Tonelli–Shanks), `None` for a non-residue.
pub fn sqrt_mod_prime(a: &IBig, p: &UBig) -> Option<UBig> {
    let a = rem_euclid(a, p);
    if a.is_zero() || *p == UBig::from(2u8) {
        return Some(a);
    }
    if legendre(&IBig::from(a.clone()), p) != 1 {
        return None;
    }
    let one = UBig::ONE;
    let mut q = p - &one;
    let mut s = 0u32;
    while !q.bit(0) {
        q >>= 1;
        s += 1;
    }
    if s == 1 {
        return Some(pow_mod(&a, &((p + &one) >> 2), p));
    }
    let mut z = UBig::from(2u8);
    while legendre(&IBig::from(z.clone()), p) != -1 {
        z += &one;
    }
    let mut m = s;
    let mut c = pow_mod(&z, &q, p);
    let mut t = pow_mod(&a, &q, p);
    let mut r = pow_mod(&a, &((&q + &one) >> 1), p);
    while t != one {
        let mut i = 0u32;
        let mut tt = t.clone();
        while tt != one {
            tt = (&tt * &tt) % p;
            i += 1;
            if i == m {
                return None;
            }
        }
        let mut b = c.clone();
        for _ in 0..(m - i - 1) {
            b = (&b * &b) % p;
        }
        m = i;
        c = (&b * &b) % p;
        t = (&t * &c) % p;
        r = (&r * &b) % p;
    }
    Some(r)
}

/// A square root of `a` modulo the square-free `m` whose primes are given (Chinese
/// remaindering of [`sqrt_mod_prime`]), `None` if `a` is a non-residue modulo one of them.
pub fn sqrt_mod_squarefree(a: &IBig, primes: &[UBig]) -> Option<UBig> {
    let mut r = UBig::ZERO;
    let mut m = UBig::ONE;
    for p in primes {
        let s = sqrt_mod_prime(a, p)?;
        // r' ≡ r (mod m), r' ≡ s (mod p)
        let inv = mod_inverse(&(&m % p), p)?;
        let diff = rem_euclid(&(IBig::from(s) - IBig::from(r.clone())), p);
        let k = (diff * inv) % p;
        r += &m * k;
        m *= p;
    }
    Some(r)
}

/// `a⁻¹ mod m` for `gcd(a, m) = 1` (`None` otherwise).
pub fn mod_inverse(a: &UBig, m: &UBig) -> Option<UBig> {
    if *m == UBig::ONE {
        return Some(UBig::ZERO);
    }
    let (mut r0, mut r1) = (IBig::from(m.clone()), IBig::from(a % m));
    let (mut s0, mut s1) = (IBig::ZERO, IBig::ONE);
    while !r1.is_zero() {
        let q = &r0 / &r1;
        let r2 = &r0 - &q * &r1;
        r0 = r1;
        r1 = r2;
        let s2 = &s0 - &q * &s1;
        s0 = s1;
        s1 = s2;
    }
    (r0 == IBig::ONE).then(|| rem_euclid(&s0, m))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn factors_and_roots() {
        let n = UBig::from(2u64 * 2 * 3 * 1_000_003 * 1_000_033);
        let f = factor(&n).expect("factor");
        let back = f
            .iter()
            .fold(UBig::ONE, |acc, (p, e)| acc * p.pow(*e as usize));
        assert_eq!(back, n);
        assert!(f.iter().all(|(p, _)| is_probable_prime(p)));
        // a product of two primes near 2⁴⁰
        let (p, q) = (
            UBig::from(1_099_511_627_791u64),
            UBig::from(1_099_511_628_401u64),
        );
        assert!(is_probable_prime(&p) && is_probable_prime(&q));
        let f = factor(&(&p * &q)).expect("rho");
        assert_eq!(f, vec![(p, 1), (q, 1)]);
        for (a, p) in [(2i64, 7u64), (5, 41), (10, 13), (3, 97)] {
            let p = UBig::from(p);
            let r = sqrt_mod_prime(&IBig::from(a), &p);
            match r {
                Some(r) => assert_eq!((&r * &r) % &p, rem_euclid(&IBig::from(a), &p)),
                None => assert_eq!(legendre(&IBig::from(a), &p), -1),
            }
        }
        assert_eq!(sqrt_mod_prime(&IBig::from(3), &UBig::from(7u8)), None);
        let (s, f, primes) = square_free_part(&IBig::from(-72)).expect("sf");
        assert_eq!((s, f), (IBig::from(-2), UBig::from(6u8)));
        assert_eq!(primes, vec![UBig::from(2u8)]);
        let r = sqrt_mod_squarefree(&IBig::from(-1), &[UBig::from(5u8), UBig::from(13u8)])
            .expect("-1 mod 65");
        assert_eq!((&r * &r + UBig::ONE) % UBig::from(65u8), UBig::ZERO);
    }
}
