//! Exact factorization of univariate polynomials over `Q` and over the Gaussian rationals
//! `Q(i)`: the tool behind the sum-of-two-squares and conic-point engines
//! ([`crate::sum_of_squares`], [`crate::conic_point`]) and the canal-surface factorizations
//! (D. Gruber, "Rationale Parametrisierungen von Kugelhüllflächen", 2008, §2.1 before
//! (2.14) and §2.4.2 (2.35)).
//!
//! * **Over `Q`** (Zassenhaus): a square-free primitive `f ∈ Z[x]` is factored modulo a small
//!   prime `p` (not dividing `lc f`, `f mod p` square-free) by Berlekamp's algorithm
//!   (kernel of `Q − I`, `Q` the Frobenius matrix; splitting by `gcd(u, v − s)`,
//!   `s = 0, …, p − 1`), the factorization is lifted by linear Hensel lifting to `pᵏ > 2B`
//!   with the Mignotte-type bound `B = |lc f| · 2ⁿ · (n + 1) · ‖f‖_∞`, and true factors are
//!   recombined from subsets of the lifted factors (`lc f · ∏ gᵢ mod pᵏ`, symmetric residues,
//!   primitive part, exact trial division). The result is complete and exact; the
//!   recombination is exponential in the number of modular factors, which is capped at
//!   [`MAX_MODULAR_FACTORS`] (an error beyond).
//! * **Over `Q(i)`** (Trager's norm method): for square-free `S ∈ Q[t]` choose the smallest
//!   `k = 1, 2, …` with `N(t) = S(t − ki)·S(t + ki)` square-free; factor `N = ∏ Nⱼ` over `Q`;
//!   then `gⱼ = gcd_{Q(i)}(S(t − ki), Nⱼ)` are the irreducible factors of `S(t − ki)` over
//!   `Q(i)`, and `hⱼ(t) = gⱼ(t + ki)` those of `S` ([`factor_gaussian`]). An irreducible
//!   `p ∈ Q[t]` either stays irreducible over `Q(i)` (then `hⱼ = p` is real) or splits as
//!   `p = c·h·h̄` (two conjugate factors of equal degree: never for odd degree; for a
//!   quadratic exactly when its discriminant is minus a rational square), so
//!   [`factor_gaussian_q_first`] factors `S` over `Q` first and applies the norm method only
//!   to its irreducible factors of even degree ≥ 4 (norms of half the degree).

use crate::complex::{norm_sq_poly, Complex};
use crate::roots::square_free_decomposition;
use crate::{Poly, Rational, Scalar};
use num_traits::One;

/// The largest number of modular factors the recombination accepts (`2^(r−1)` subsets).
pub const MAX_MODULAR_FACTORS: usize = 16;

/// The primes tried for the modular factorization.
const PRIMES: [u64; 40] = [
    3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83, 89, 97,
    101, 103, 107, 109, 113, 127, 131, 137, 139, 149, 151, 157, 163, 167, 173, 179,
];

/// A failure of the factorization (never a wrong result).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum FactorError {
    /// The zero polynomial has no factorization.
    Zero,
    /// Too many modular factors for the exhaustive recombination.
    TooManyModularFactors(usize),
    /// No suitable prime / shift was found (not expected for square-free input).
    NoGoodPrime,
}

impl core::fmt::Display for FactorError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            FactorError::Zero => write!(f, "the zero polynomial has no factorization"),
            FactorError::TooManyModularFactors(r) => write!(
                f,
                "{r} modular factors exceed the recombination limit {MAX_MODULAR_FACTORS}"
            ),
            FactorError::NoGoodPrime => write!(
                f,
                "no prime (or Trager shift) keeps the polynomial square-free"
            ),
        }
    }
}

// ----------------------------------------------------------------------------------------
// integers as Rationals with denominator 1
// ----------------------------------------------------------------------------------------

fn int(n: i64) -> Rational {
    Rational::from(n)
}

/// `⌊a/b⌋` for integers `a`, `b > 0`.
fn floor_div(a: &Rational, b: &Rational) -> Rational {
    Rational::from((a / b).floor())
}

/// `a mod m` in `[0, m)`.
fn modulo(a: &Rational, m: &Rational) -> Rational {
    a - m * floor_div(a, m)
}

/// `a mod m` in `(−m/2, m/2]`.
fn sym_mod(a: &Rational, m: &Rational) -> Rational {
    let r = modulo(a, m);
    if r.clone() * int(2) > *m {
        r - m
    } else {
        r
    }
}

fn to_u64_mod(a: &Rational, p: u64) -> u64 {
    let r = modulo(a, &Rational::from(p));
    u64::try_from(r.numerator()).unwrap_or(0)
}

fn abs_r(a: &Rational) -> Rational {
    if *a < Rational::ZERO {
        -a.clone()
    } else {
        a.clone()
    }
}

/// The primitive integer polynomial with positive leading coefficient proportional to `p`.
pub fn primitive_int(p: &Poly<Rational>) -> Poly<Rational> {
    if p.is_zero() {
        return Poly::zero();
    }
    // clear denominators
    let mut l = Rational::ONE;
    for c in p.coeffs() {
        let d = Rational::from(c.denominator().clone());
        l = lcm(&l, &d);
    }
    let q: Vec<Rational> = p.coeffs().iter().map(|c| c * &l).collect();
    let g = q
        .iter()
        .filter(|c| !c.is_zero())
        .fold(Rational::ZERO, |acc, c| gcd_int(&acc, c));
    let mut out: Vec<Rational> = q.iter().map(|c| c / &g).collect();
    if out.last().is_some_and(|c| *c < Rational::ZERO) {
        out = out.into_iter().map(|c| -c).collect();
    }
    Poly::new(out)
}

fn gcd_int(a: &Rational, b: &Rational) -> Rational {
    let mut x = abs_r(a);
    let mut y = abs_r(b);
    while !y.is_zero() {
        let r = modulo(&x, &y);
        x = y;
        y = r;
    }
    x
}

fn lcm(a: &Rational, b: &Rational) -> Rational {
    let g = gcd_int(a, b);
    if g.is_zero() {
        return Rational::ZERO;
    }
    abs_r(&(a * b / g))
}

// ----------------------------------------------------------------------------------------
// polynomials over F_p (coefficients low first, trimmed)
// ----------------------------------------------------------------------------------------

type Mp = Vec<u64>;

fn trim(mut a: Mp) -> Mp {
    while a.last() == Some(&0) {
        a.pop();
    }
    a
}

fn pow_mod(mut b: u64, mut e: u64, p: u64) -> u64 {
    let mut r = 1 % p;
    b %= p;
    while e > 0 {
        if e & 1 == 1 {
            r = r * b % p;
        }
        b = b * b % p;
        e >>= 1;
    }
    r
}

fn inv_mod(a: u64, p: u64) -> u64 {
    pow_mod(a, p - 2, p)
}

fn mp_add(a: &Mp, b: &Mp, p: u64) -> Mp {
    let n = a.len().max(b.len());
    trim(
        (0..n)
            .map(|i| (a.get(i).copied().unwrap_or(0) + b.get(i).copied().unwrap_or(0)) % p)
            .collect(),
    )
}

fn mp_sub(a: &Mp, b: &Mp, p: u64) -> Mp {
    let n = a.len().max(b.len());
    trim(
        (0..n)
            .map(|i| (a.get(i).copied().unwrap_or(0) + p - b.get(i).copied().unwrap_or(0)) % p)
            .collect(),
    )
}

fn mp_mul(a: &Mp, b: &Mp, p: u64) -> Mp {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut out = vec![0u64; a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        if *x == 0 {
            continue;
        }
        for (j, y) in b.iter().enumerate() {
            out[i + j] = (out[i + j] + x * y) % p;
        }
    }
    trim(out)
}

fn mp_scale(a: &Mp, c: u64, p: u64) -> Mp {
    trim(a.iter().map(|x| x * c % p).collect())
}

/// `(q, r)` with `a = q b + r`; `b` non-zero.
fn mp_divrem(a: &Mp, b: &Mp, p: u64) -> (Mp, Mp) {
    let Some(&lb) = b.last() else {
        return (Vec::new(), a.clone());
    };
    let inv = inv_mod(lb, p);
    let mut r = a.clone();
    if r.len() < b.len() {
        return (Vec::new(), trim(r));
    }
    let mut q = vec![0u64; r.len() - b.len() + 1];
    for k in (0..q.len()).rev() {
        let c = r[k + b.len() - 1] * inv % p;
        q[k] = c;
        if c != 0 {
            for (j, bj) in b.iter().enumerate() {
                r[k + j] = (r[k + j] + p - c * bj % p) % p;
            }
        }
    }
    r.truncate(b.len() - 1);
    (trim(q), trim(r))
}

fn mp_monic(a: &Mp, p: u64) -> Mp {
    match a.last() {
        Some(&l) if l != 0 => mp_scale(a, inv_mod(l, p), p),
        _ => a.clone(),
    }
}

fn mp_gcd(a: &Mp, b: &Mp, p: u64) -> Mp {
    let (mut x, mut y) = (a.clone(), b.clone());
    while !y.is_empty() {
        let (_, r) = mp_divrem(&x, &y, p);
        x = y;
        y = r;
    }
    mp_monic(&x, p)
}

// ----------------------------------------------------------------------------------------
// coprimality proved modulo a prime
// ----------------------------------------------------------------------------------------

/// The prime of the coprimality tests: `p = 998244353 = 119·2²³ + 1 ≡ 1 (mod 4)`, so `−1`
/// has the square root `ι = 3^((p−1)/4)` mod `p` (`3` is a primitive root).
const COPRIME_P: u64 = 998_244_353;

/// `x mod p` for a rational whose denominator is prime to `p` (`None` otherwise).
fn rational_mod(x: &Rational, p: u64) -> Option<u64> {
    let d: u64 = x.denominator() % p;
    if d == 0 {
        return None;
    }
    let pi = i64::try_from(p).ok()?;
    let n: i64 = x.numerator() % pi;
    let n = u64::try_from(n.rem_euclid(pi)).ok()?;
    Some(n * inv_mod(d, p) % p)
}

/// The image mod `p` of a polynomial with coefficients `cs` (each mapped by `f`), or `None`
/// if a denominator is divisible by `p`.
fn poly_mod<T>(cs: &[T], f: impl Fn(&T) -> Option<u64>) -> Option<Mp> {
    cs.iter().map(f).collect::<Option<Vec<u64>>>().map(trim)
}

/// Whether the images mod `p` prove `gcd(a, b) = 1`: `a` keeps its degree (`p ∤ lc a`)
/// and the images are coprime over `F_p`.
fn images_coprime(a: &Mp, deg_a: usize, b: &Mp, p: u64) -> bool {
    a.len() == deg_a + 1 && mp_gcd(a, b, p).len() == 1
}

/// `x mod p` for a scalar with a rational value whose denominator is prime to `p`.
fn scalar_mod<F: Scalar>(x: &F, p: u64) -> Option<u64> {
    if x.is_zero() {
        return Some(0);
    }
    rational_mod(&x.to_rational()?, p)
}

/// `true` only if the polynomials `a, b` with rational coefficients are coprime (`false`:
/// not decided here — they may or may not be; also for coefficients that are not rational),
/// proved modulo the prime `p = 998244353`. Let `R = Z_(p)` (the rationals with
/// denominators prime to `p`, a principal ideal domain) and `φ: R[t] → F_p[t]` the
/// reduction. If every coefficient of `a` and `b` lies in `R` and `p ∤ lc(a)`, a common
/// factor `g` of degree `≥ 1` can be taken primitive in `R[t]`, then `a = g·h`, `b = g·k`
/// with `h, k ∈ R[t]` (Gauss' lemma), so `φ(g)` divides `φ(a)` and `φ(b)`, and
/// `deg φ(g) = deg g ≥ 1` because `φ(lc g)·φ(lc h) = φ(lc a) ≠ 0`. Hence
/// `gcd(φ(a), φ(b)) = 1` proves `gcd(a, b) = 1` over `Q` (and over every extension field:
/// the `gcd` does not depend on the field). The argument of the modular `gcd` algorithms,
/// J. von zur Gathen, J. Gerhard, "Modern Computer Algebra", 3rd ed., 2013, chapter 6.
pub fn coprime_mod_p<F: Scalar>(a: &Poly<F>, b: &Poly<F>) -> bool {
    let (Some(da), Some(_)) = (a.degree(), b.degree()) else {
        return false;
    };
    let p = COPRIME_P;
    let (Some(ma), Some(mb)) = (
        poly_mod(a.coeffs(), |c| scalar_mod(c, p)),
        poly_mod(b.coeffs(), |c| scalar_mod(c, p)),
    ) else {
        return false;
    };
    images_coprime(&ma, da, &mb, p)
}

/// The images mod `p` (`i ↦ ι`) of a polynomial over `F(i)` with rational coefficients.
fn gaussian_mod<F: Scalar>(a: &Poly<Complex<F>>, p: u64, iota: u64) -> Option<Mp> {
    poly_mod(a.coeffs(), |c| {
        Some((scalar_mod(&c.re, p)? + iota * scalar_mod(&c.im, p)? % p) % p)
    })
}

/// [`coprime_mod_p`] over `Q(i)`: `true` only if `a, b` with coefficients in `Q(i)` are
/// coprime. The same proof with `R = Z_(p)[i]` (a localization of the principal ideal
/// domain `Z[i]`) and `φ: R[t] → F_p[t]`, `x + iy ↦ x + ιy` with `ι = 3^((p−1)/4)`,
/// `ι² ≡ −1 (mod p)` (a ring homomorphism: the reduction modulo one of the two Gaussian
/// primes over `p ≡ 1 mod 4`).
pub fn gaussian_coprime_mod_p<F: Scalar>(a: &Poly<Complex<F>>, b: &Poly<Complex<F>>) -> bool {
    let (Some(da), Some(_)) = (a.degree(), b.degree()) else {
        return false;
    };
    let p = COPRIME_P;
    let iota = pow_mod(3, (p - 1) / 4, p);
    let (Some(ma), Some(mb)) = (gaussian_mod(a, p, iota), gaussian_mod(b, p, iota)) else {
        return false;
    };
    images_coprime(&ma, da, &mb, p)
}

/// `(g, s, t)` with `s a + t b = g = gcd(a, b)` (monic).
fn mp_xgcd(a: &Mp, b: &Mp, p: u64) -> (Mp, Mp, Mp) {
    let (mut r0, mut r1) = (a.clone(), b.clone());
    let (mut s0, mut s1): (Mp, Mp) = (vec![1], Vec::new());
    let (mut t0, mut t1): (Mp, Mp) = (Vec::new(), vec![1]);
    while !r1.is_empty() {
        let (q, r) = mp_divrem(&r0, &r1, p);
        let s2 = mp_sub(&s0, &mp_mul(&q, &s1, p), p);
        let t2 = mp_sub(&t0, &mp_mul(&q, &t1, p), p);
        r0 = r1;
        r1 = r;
        s0 = s1;
        s1 = s2;
        t0 = t1;
        t1 = t2;
    }
    let l = r0.last().copied().unwrap_or(1);
    let inv = inv_mod(l, p);
    (
        mp_scale(&r0, inv, p),
        mp_scale(&s0, inv, p),
        mp_scale(&t0, inv, p),
    )
}

fn mp_derivative(a: &Mp, p: u64) -> Mp {
    trim(
        a.iter()
            .enumerate()
            .skip(1)
            .map(|(k, c)| (k as u64 % p) * c % p)
            .collect(),
    )
}

/// `x^e mod f`.
fn mp_pow_x(e: u64, f: &Mp, p: u64) -> Mp {
    let mut result: Mp = vec![1];
    let mut base: Mp = mp_divrem(&vec![0, 1], f, p).1;
    let mut k = e;
    while k > 0 {
        if k & 1 == 1 {
            result = mp_divrem(&mp_mul(&result, &base, p), f, p).1;
        }
        base = mp_divrem(&mp_mul(&base, &base, p), f, p).1;
        k >>= 1;
    }
    result
}

/// Kernel of an `n × n` matrix over `F_p` (rows), as row vectors.
fn kernel_mod(mut m: Vec<Vec<u64>>, p: u64) -> Vec<Vec<u64>> {
    let n = m.len();
    let cols = m.first().map_or(0, Vec::len);
    let mut pivots = Vec::new();
    let mut row = 0;
    for col in 0..cols {
        let Some(pr) = (row..n).find(|&r| m[r][col] != 0) else {
            continue;
        };
        m.swap(row, pr);
        let inv = inv_mod(m[row][col], p);
        for x in m[row].iter_mut() {
            *x = *x * inv % p;
        }
        let pivot_row = m[row].clone();
        for (r, mr) in m.iter_mut().enumerate() {
            if r != row && mr[col] != 0 {
                let c = mr[col];
                for (x, y) in mr.iter_mut().zip(&pivot_row) {
                    *x = (*x + p - c * y % p) % p;
                }
            }
        }
        pivots.push(col);
        row += 1;
        if row == n {
            break;
        }
    }
    let free: Vec<usize> = (0..cols).filter(|c| !pivots.contains(c)).collect();
    free.iter()
        .map(|&f| {
            let mut v = vec![0u64; cols];
            v[f] = 1;
            for (r, &pc) in pivots.iter().enumerate() {
                v[pc] = (p - m[r][f]) % p;
            }
            v
        })
        .collect()
}

/// Berlekamp: the monic irreducible factors of a square-free monic `f` over `F_p`.
fn berlekamp(f: &Mp, p: u64) -> Vec<Mp> {
    let n = f.len().saturating_sub(1);
    if n <= 1 {
        return vec![f.clone()];
    }
    // rows: x^{ip} mod f
    let xp = mp_pow_x(p, f, p);
    let mut rows: Vec<Vec<u64>> = Vec::with_capacity(n);
    let mut cur: Mp = vec![1];
    for _ in 0..n {
        let mut r = cur.clone();
        r.resize(n, 0);
        rows.push(r);
        cur = mp_divrem(&mp_mul(&cur, &xp, p), f, p).1;
    }
    // (Q − I)ᵀ
    let m: Vec<Vec<u64>> = (0..n)
        .map(|j| {
            (0..n)
                .map(|i| {
                    let q = rows[i][j];
                    if i == j {
                        (q + p - 1) % p
                    } else {
                        q
                    }
                })
                .collect()
        })
        .collect();
    let basis = kernel_mod(m, p);
    let r = basis.len();
    let mut factors = vec![f.clone()];
    for v in &basis {
        if factors.len() >= r {
            break;
        }
        let v = trim(v.clone());
        if v.len() <= 1 {
            continue;
        }
        let mut next = Vec::new();
        for u in factors {
            if u.len() <= 2 {
                next.push(u);
                continue;
            }
            let mut parts = Vec::new();
            for s in 0..p {
                let vs = mp_sub(&v, &vec![s], p);
                let g = mp_gcd(&u, &vs, p);
                if g.len() > 1 {
                    parts.push(g);
                }
            }
            if parts.is_empty() {
                next.push(u);
            } else {
                next.extend(parts);
            }
        }
        factors = next;
    }
    factors
}

// ----------------------------------------------------------------------------------------
// Hensel lifting (integer polynomials as Rationals)
// ----------------------------------------------------------------------------------------

type Zp = Vec<Rational>;

fn z_from_mp(a: &Mp) -> Zp {
    a.iter().map(|&x| Rational::from(x)).collect()
}

fn z_to_mp(a: &Zp, p: u64) -> Mp {
    trim(a.iter().map(|x| to_u64_mod(x, p)).collect())
}

fn z_mul(a: &Zp, b: &Zp) -> Zp {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut out = vec![Rational::ZERO; a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}

fn z_mod(a: &Zp, m: &Rational) -> Zp {
    a.iter().map(|x| modulo(x, m)).collect()
}

/// Lifts `F ≡ g h (mod p)` (all monic, `F` known mod `pᵏ`) to `F ≡ G H (mod pᵏ)`.
fn hensel_two(f: &Zp, g: &Mp, h: &Mp, p: u64, k: u32) -> (Zp, Zp) {
    let (_, s, t) = mp_xgcd(g, h, p);
    let mut gg = z_from_mp(g);
    let mut hh = z_from_mp(h);
    let pr = Rational::from(p);
    let mut m = pr.clone();
    for _ in 1..k {
        let gh = z_mul(&gg, &hh);
        let n = f.len().max(gh.len());
        let e: Zp = (0..n)
            .map(|i| {
                let a = f.get(i).cloned().unwrap_or(Rational::ZERO);
                let b = gh.get(i).cloned().unwrap_or(Rational::ZERO);
                (a - b) / m.clone()
            })
            .collect();
        let e = z_to_mp(&e, p);
        let (q, r) = mp_divrem(&mp_mul(&t, &e, p), g, p);
        let dh = mp_add(&mp_mul(&e, &s, p), &mp_mul(&q, h, p), p);
        let dh = mp_divrem(&dh, h, p).1; // degree < deg h (exact identity mod p)
        for (i, c) in r.iter().enumerate() {
            if let Some(x) = gg.get_mut(i) {
                *x += m.clone() * Rational::from(*c);
            }
        }
        for (i, c) in dh.iter().enumerate() {
            if let Some(x) = hh.get_mut(i) {
                *x += m.clone() * Rational::from(*c);
            }
        }
        m *= pr.clone();
    }
    (z_mod(&gg, &m), z_mod(&hh, &m))
}

fn mp_product(fs: &[Mp], p: u64) -> Mp {
    fs.iter().fold(vec![1], |acc, f| mp_mul(&acc, f, p))
}

/// Lifts the factorization `f ≡ ∏ gᵢ (mod p)` of a monic `f` (known mod `pᵏ`).
fn hensel_all(f: &Zp, gs: &[Mp], p: u64, k: u32) -> Vec<Zp> {
    if gs.len() <= 1 {
        let m = Rational::from(p).pow(k as isize);
        return vec![z_mod(f, &m)];
    }
    let (a, b) = gs.split_at(gs.len() / 2);
    let (ga, gb) = (mp_product(a, p), mp_product(b, p));
    let (fa, fb) = hensel_two(f, &ga, &gb, p, k);
    let mut out = hensel_all(&fa, a, p, k);
    out.extend(hensel_all(&fb, b, p, k));
    out
}

/// `a⁻¹ mod pᵏ` by Newton iteration.
fn inv_mod_pk(a: &Rational, p: u64, k: u32) -> Rational {
    let pr = Rational::from(p);
    let mut x = Rational::from(inv_mod(to_u64_mod(a, p), p));
    let mut e = 1u32;
    let target = pr.pow(k as isize);
    while e < k {
        e = (2 * e).min(k);
        let m = pr.pow(e as isize);
        x = modulo(&(x.clone() * (int(2) - a * &x)), &m);
    }
    modulo(&x, &target)
}

/// Whether [`factor_squarefree_int`] finds a prime for the square-free `f ∈ Q[x]` and for
/// every factor of it over `Z`: a prime `p` of its list with `p ∤ lc(f)` and `f mod p`
/// square-free (for the primitive part of `f`). A factor `h` of `f` then has `p ∤ lc(h)`
/// (`lc(h) | lc(f)`) and `h mod p` square-free (a divisor of a square-free polynomial), so
/// [`factor_squarefree_int`] of `h` does not end in [`FactorError::NoGoodPrime`]; with
/// `deg h ≤` [`MAX_MODULAR_FACTORS`] it does not end in
/// [`FactorError::TooManyModularFactors`] either (at most `deg h` modular factors).
pub fn has_good_prime(f: &Poly<Rational>) -> bool {
    let f = primitive_int(f);
    let Some(n) = f.degree() else {
        return false;
    };
    if n <= 1 {
        return true;
    }
    let lc = f.leading();
    PRIMES.iter().any(|&p| {
        if to_u64_mod(&lc, p) == 0 {
            return false;
        }
        let fp = z_to_mp(&f.coeffs().to_vec(), p);
        fp.len() == n + 1 && mp_gcd(&fp, &mp_derivative(&fp, p), p).len() == 1
    })
}

/// The irreducible factors over `Z` of a square-free primitive `f ∈ Z[x]` with positive
/// leading coefficient (each primitive with positive leading coefficient).
///
/// # Errors
/// [`FactorError::TooManyModularFactors`], [`FactorError::NoGoodPrime`].
pub fn factor_squarefree_int(f: &Poly<Rational>) -> Result<Vec<Poly<Rational>>, FactorError> {
    let n = f.degree().ok_or(FactorError::Zero)?;
    if n <= 1 {
        return Ok(vec![f.clone()]);
    }
    let lc = f.leading();
    // choose the prime with the fewest modular factors among the first few good ones
    let mut best: Option<(u64, Vec<Mp>)> = None;
    let mut good = 0;
    for &p in &PRIMES {
        if to_u64_mod(&lc, p) == 0 {
            continue;
        }
        let fp = z_to_mp(&f.coeffs().to_vec(), p);
        if fp.len() != n + 1 {
            continue;
        }
        let g = mp_gcd(&fp, &mp_derivative(&fp, p), p);
        if g.len() != 1 {
            continue;
        }
        let facs = berlekamp(&mp_monic(&fp, p), p);
        if facs.len() == 1 {
            return Ok(vec![f.clone()]);
        }
        let better = match &best {
            None => true,
            Some((_, b)) => facs.len() < b.len(),
        };
        if better {
            best = Some((p, facs));
        }
        good += 1;
        if good >= 4 {
            break;
        }
    }
    let (p, facs) = best.ok_or(FactorError::NoGoodPrime)?;
    if facs.len() > MAX_MODULAR_FACTORS {
        return Err(FactorError::TooManyModularFactors(facs.len()));
    }
    // bound
    let maxc = f
        .coeffs()
        .iter()
        .map(abs_r)
        .fold(Rational::ZERO, |a, b| if b > a { b } else { a });
    let bound = abs_r(&lc) * int(2).pow(n as isize) * int(n as i64 + 1) * maxc * int(2);
    let pr = Rational::from(p);
    let mut k = 1u32;
    let mut m = pr.clone();
    while m <= bound {
        m *= pr.clone();
        k += 1;
    }
    // monic f mod p^k
    let linv = inv_mod_pk(&lc, p, k);
    let fm: Zp = f
        .coeffs()
        .iter()
        .map(|c| modulo(&(c * &linv), &m))
        .collect();
    let lifted = hensel_all(&fm, &facs, p, k);
    // recombination
    let mut remaining: Vec<usize> = (0..lifted.len()).collect();
    let mut cur = f.clone();
    let mut out = Vec::new();
    let mut s = 1;
    while 2 * s <= remaining.len() {
        let mut found = None;
        for subset in combinations(&remaining, s) {
            crate::budget::checkpoint();
            let lcc = cur.leading();
            let prod = subset.iter().fold(vec![lcc.clone()], |acc, &i| {
                z_mod(&z_mul(&acc, &lifted[i]), &m)
            });
            let cand: Vec<Rational> = prod.iter().map(|x| sym_mod(x, &m)).collect();
            let cand = primitive_int(&Poly::new(cand));
            if cand.degree().unwrap_or(0) == 0 {
                continue;
            }
            if let Ok((q, r)) = cur.div_rem(&cand) {
                if r.is_zero() {
                    found = Some((subset, cand, q));
                    break;
                }
            }
        }
        match found {
            Some((subset, cand, q)) => {
                remaining.retain(|i| !subset.contains(i));
                out.push(cand);
                cur = primitive_int(&q);
            }
            None => s += 1,
        }
    }
    if cur.degree().is_some_and(|d| d > 0) {
        out.push(cur);
    }
    Ok(out)
}

fn combinations(items: &[usize], k: usize) -> Vec<Vec<usize>> {
    fn rec(
        items: &[usize],
        k: usize,
        start: usize,
        cur: &mut Vec<usize>,
        out: &mut Vec<Vec<usize>>,
    ) {
        if cur.len() == k {
            out.push(cur.clone());
            return;
        }
        for i in start..items.len() {
            cur.push(items[i]);
            rec(items, k, i + 1, cur, out);
            cur.pop();
        }
    }
    let mut out = Vec::new();
    rec(items, k, 0, &mut Vec::new(), &mut out);
    out
}

/// A factorization `c · ∏ fⱼ^{eⱼ}`: the constant and the `(fⱼ, eⱼ)`.
pub type Factorization = (Rational, Vec<(Poly<Rational>, usize)>);

/// The factorization `p = c · ∏ fⱼ^{eⱼ}` over `Q` with monic irreducible `fⱼ`.
///
/// # Errors
/// [`FactorError::Zero`] for `p = 0`; as [`factor_squarefree_int`].
pub fn factor_rational(p: &Poly<Rational>) -> Result<Factorization, FactorError> {
    if p.is_zero() {
        return Err(FactorError::Zero);
    }
    let c = p.leading();
    let mut out = Vec::new();
    for (f, e) in square_free_decomposition(p) {
        for g in factor_squarefree_int(&primitive_int(&f))? {
            out.push((g.monic(), e));
        }
    }
    Ok((c, out))
}

// ----------------------------------------------------------------------------------------
// Q(i)
// ----------------------------------------------------------------------------------------

/// A Gaussian-rational polynomial.
pub type GaussPoly = Poly<Complex<Rational>>;

/// `p` as a polynomial over `Q(i)`.
pub fn to_gauss(p: &Poly<Rational>) -> GaussPoly {
    p.map(|c| Complex::from_real(c.clone()))
}

/// `p(t + c)` for a Gaussian shift `c`.
pub fn shift_gauss(p: &GaussPoly, c: &Complex<Rational>) -> GaussPoly {
    p.compose(&Poly::new(vec![c.clone(), Complex::one()]))
}

/// The monic irreducible factors over `Q(i)` of a square-free `s ∈ Q[t]` (Trager's norm
/// method on all of `s`, module docs; the order is that of the factors of the norm).
/// [`factor_gaussian_q_first`] gives the same factors, faster, in another order.
///
/// # Errors
/// As [`factor_squarefree_int`]; [`FactorError::Zero`] for `s = 0`.
pub fn factor_gaussian(s: &Poly<Rational>) -> Result<Vec<GaussPoly>, FactorError> {
    let n = s.degree().ok_or(FactorError::Zero)?;
    if n == 0 {
        return Ok(Vec::new());
    }
    if n == 1 {
        return Ok(vec![to_gauss(&s.monic())]);
    }
    trager(s)
}

/// The monic irreducible factors over `Q(i)` of a square-free `s ∈ Q[t]`: the irreducible
/// factors of `s` over `Q` ([`factor_squarefree_int`]), each split over `Q(i)` by
/// [`factor_gaussian_irreducible`] (module docs), in that order.
///
/// Factoring over `Q` first keeps Trager's norm, and with it the Zassenhaus factorization
/// that dominates the cost, at twice the degree of one `Q`-irreducible factor instead of
/// twice the degree of `s`; factors of odd degree and quadratics need no norm at all.
///
/// # Errors
/// As [`factor_squarefree_int`]; [`FactorError::Zero`] for `s = 0`.
pub fn factor_gaussian_q_first(s: &Poly<Rational>) -> Result<Vec<GaussPoly>, FactorError> {
    factor_gaussian_with(s, &factor_gaussian_irreducible)
}

/// The split over `Q(i)` of an irreducible polynomial over `Q` ([`factor_gaussian_irreducible`]
/// or a memo of it).
pub type IrreducibleSplit<'a> = dyn Fn(&Poly<Rational>) -> Result<Vec<GaussPoly>, FactorError> + 'a;

/// [`factor_gaussian_q_first`] with the split over `Q(i)` of each irreducible factor over `Q`
/// (primitive, positive leading coefficient) supplied by `irreducible` (a memo of
/// [`factor_gaussian_irreducible`]; the result is the same as long as it returns what that
/// function would).
///
/// # Errors
/// As [`factor_gaussian`], and the errors of `irreducible`.
pub fn factor_gaussian_with(
    s: &Poly<Rational>,
    irreducible: &IrreducibleSplit<'_>,
) -> Result<Vec<GaussPoly>, FactorError> {
    let n = s.degree().ok_or(FactorError::Zero)?;
    if n == 0 {
        return Ok(Vec::new());
    }
    if n == 1 {
        return Ok(vec![to_gauss(&s.monic())]);
    }
    let mut out = Vec::new();
    for f in factor_squarefree_int(&primitive_int(s))? {
        out.extend(irreducible(&f)?);
    }
    Ok(out)
}

/// The monic irreducible factors over `Q(i)` of a polynomial `f` irreducible over `Q`: `f`
/// itself, or the two conjugate factors `h`, `h̄` of `f = c·h·h̄`.
///
/// Since `[Q(i) : Q] = 2`, the irreducible factors of `f` over `Q(i)` are conjugate and of
/// equal degree, so `f` stays irreducible when its degree is odd. A quadratic
/// `t² + bt + c` splits exactly when `4c − b²` is the square of a rational `r ≠ 0`, into
/// `t − (−b ± i r)/2`. Otherwise Trager's norm method (module docs): the smallest
/// `k = 1, 2, …` with `N(t) = f(t − ki)·f(t + ki)` square-free, `N` factored over `Q`, and
/// `gcd_{Q(i)}(f(t − ki), Nⱼ)` shifted back (B. M. Trager, "Algebraic factoring and
/// rational function integration", SYMSAC 1976, §3).
///
/// # Errors
/// As [`factor_squarefree_int`]; [`FactorError::Zero`] for `f = 0`;
/// [`FactorError::NoGoodPrime`] if no shift `k < 64` gives a square-free norm.
pub fn factor_gaussian_irreducible(f: &Poly<Rational>) -> Result<Vec<GaussPoly>, FactorError> {
    let n = f.degree().ok_or(FactorError::Zero)?;
    if n == 0 {
        return Ok(Vec::new());
    }
    if n % 2 == 1 {
        return Ok(vec![to_gauss(&f.monic())]);
    }
    if n == 2 {
        let m = f.monic();
        let (c, b) = (m.coeff(0), m.coeff(1));
        let disc = int(4) * c - &b * &b;
        if disc > Rational::ZERO {
            if let Some(r) = crate::rational::rational_sqrt(&disc) {
                let half = Rational::ONE / int(2);
                // t − z for z = (−b ± i r)/2
                let root = |sign: i64| {
                    Complex::new(
                        -b.clone() * half.clone(),
                        r.clone() * half.clone() * int(sign),
                    )
                };
                let lin = |z: Complex<Rational>| Poly::new(vec![-z, Complex::one()]);
                return Ok(vec![lin(root(1)), lin(root(-1))]);
            }
        }
        return Ok(vec![to_gauss(&m)]);
    }
    if let Some(v) = stays_irreducible(f, n) {
        return Ok(v);
    }
    trager(f)
}

/// The primes `p ≡ 3 (mod 4)` of [`stays_irreducible`] (inert in `Z[i]`).
const INERT_PRIMES: [u64; 12] = [3, 7, 11, 19, 23, 31, 43, 47, 59, 67, 71, 79];

/// `a^e mod m` over `F_p` (`m` non-constant).
fn mp_powmod(a: &Mp, mut e: u64, m: &Mp, p: u64) -> Mp {
    let mut base = mp_divrem(a, m, p).1;
    let mut acc: Mp = vec![1];
    while e > 0 {
        if e & 1 == 1 {
            acc = mp_divrem(&mp_mul(&acc, &base, p), m, p).1;
        }
        base = mp_divrem(&mp_mul(&base, &base, p), m, p).1;
        e >>= 1;
    }
    acc
}

/// Whether the monic square-free `f ∈ F_p[t]` has an irreducible factor of odd degree
/// (distinct-degree factorization: `gcd(f, t^(p^d) − t)` is the product of the
/// irreducible factors whose degree divides `d`).
fn has_odd_degree_factor(f: &Mp, p: u64) -> bool {
    let t: Mp = vec![0, 1];
    let mut rest = f.clone();
    let mut h = t.clone();
    let mut d = 1;
    while rest.len() > 2 * d {
        h = mp_powmod(&h, p, &rest, p);
        let g = mp_gcd(&rest, &mp_sub(&h, &t, p), p);
        if g.len() > 1 {
            if d % 2 == 1 {
                return true;
            }
            rest = mp_divrem(&rest, &g, p).0;
            h = mp_divrem(&h, &rest, p).1;
        }
        d += 1;
    }
    // what is left is irreducible (or 1)
    rest.len() > 1 && (rest.len() - 1) % 2 == 1
}

/// [`trager`]'s answer `[f]` (monic) for a `Q`-irreducible `f` of even degree
/// `4 ≤ n ≤ 8` that stays irreducible over `Q(i)`, found without factoring the norm, when
/// that is proved and Trager's method would give the same answer; `None` otherwise.
///
/// * **Irreducible over `Q(i)`.** Over the quadratic extension a `Q`-irreducible `f` is
///   irreducible or `f = c·h·h̄` with `h` irreducible. Take a prime `p ≡ 3 (mod 4)` that
///   divides no denominator nor `lc f`, with `f mod p` square-free. The monic `h` has
///   coefficients in `Z_(p)[i]` (they are integral over `Z_(p)`: symmetric functions of
///   roots of the monic `f/lc f`), and `Z_(p)[i]/(p) = F_{p²}` with conjugation acting as
///   the Frobenius `σ` (`p` is inert), so `f ≡ lc f · h̃·σ(h̃)`. An irreducible factor `g` of
///   `f mod p` over `F_p` of odd degree stays irreducible over `F_{p²}` and `σ(g) = g`; if
///   `g | h̃` then `g = σ(g) | σ(h̃)` as well, so `g² | f mod p`, which is square-free: a
///   contradiction. So an odd-degree factor modulo such a prime proves `f` irreducible over
///   `Q(i)`.
/// * **Trager's answer.** Trager's method with the first shift `k = 1` whose norm
///   `N = f(t − i)·f(t + i)` is square-free: `N` is then irreducible over `Q` (the norm of the
///   irreducible `f(t − i)`, square-free), its factorization ([`factor_squarefree_int`]) is
///   `[N]` unless it fails — it cannot when a prime of its list is good for `N`
///   ([`has_good_prime`]) and `deg N = 2n ≤` [`MAX_MODULAR_FACTORS`] — and
///   `gcd(f(t − i), N)` shifted back is `f`, monic. `N` square-free is proved by
///   [`coprime_mod_p`] of `N` and `N′`.
fn stays_irreducible(f: &Poly<Rational>, n: usize) -> Option<Vec<GaussPoly>> {
    if n % 2 == 1 || !(4..=MAX_MODULAR_FACTORS / 2).contains(&n) {
        return None;
    }
    let odd = INERT_PRIMES.iter().any(|&p| {
        let Some(fp) = poly_mod(f.coeffs(), |c| rational_mod(c, p)) else {
            return false;
        };
        fp.len() == n + 1
            && mp_gcd(&fp, &mp_derivative(&fp, p), p).len() == 1
            && has_odd_degree_factor(&mp_monic(&fp, p), p)
    });
    if !odd {
        return None;
    }
    let g = shift_gauss(&to_gauss(f), &Complex::new(Rational::ZERO, int(-1)));
    let norm = norm_sq_poly(&g);
    if !coprime_mod_p(&norm, &norm.derivative()) || !has_good_prime(&norm) {
        return None;
    }
    Some(vec![to_gauss(&f.monic())])
}

/// Trager's norm method over `Q(i)` for a square-free `f ∈ Q[t]` (module docs).
fn trager(f: &Poly<Rational>) -> Result<Vec<GaussPoly>, FactorError> {
    let sg = to_gauss(f);
    for k in 1..64i64 {
        let shift = Complex::new(Rational::ZERO, int(-k));
        let g = shift_gauss(&sg, &shift); // f(t − ki)
        let norm = norm_sq_poly(&g); // f(t − ki) f(t + ki)
        if norm.gcd(&norm.derivative()).degree() != Some(0) {
            continue;
        }
        let parts = factor_squarefree_int(&primitive_int(&norm))?;
        let back = Complex::new(Rational::ZERO, int(k));
        let mut out = Vec::new();
        for nj in parts {
            let gj = g.gcd(&to_gauss(&nj));
            if gj.degree().is_some_and(|d| d > 0) {
                out.push(shift_gauss(&gj, &back).monic());
            }
        }
        return Ok(out);
    }
    Err(FactorError::NoGoodPrime)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(c: &[i64]) -> Poly<Rational> {
        Poly::from_ints(c)
    }

    fn product(fs: &[Poly<Rational>]) -> Poly<Rational> {
        fs.iter().fold(Poly::constant(Rational::ONE), |a, b| &a * b)
    }

    #[test]
    fn factors_over_q() {
        // (x² + 1)(x² − 2)(x + 3)(2x − 1)
        let f = product(&[p(&[1, 0, 1]), p(&[-2, 0, 1]), p(&[3, 1]), p(&[-1, 2])]);
        let fs = factor_squarefree_int(&primitive_int(&f)).expect("factor");
        assert_eq!(fs.len(), 4);
        assert_eq!(primitive_int(&product(&fs)), primitive_int(&f));
        // Swinnerton-Dyer-like: x⁴ − 10x² + 1 irreducible but splits mod every prime
        let sd = p(&[1, 0, -10, 0, 1]);
        assert_eq!(factor_squarefree_int(&sd).expect("f").len(), 1);
        // (x⁴+1)(x⁴ − 10x² + 1)
        let g = &p(&[1, 0, 0, 0, 1]) * &sd;
        assert_eq!(factor_squarefree_int(&g).expect("f").len(), 2);
        // with multiplicities
        let h = &(&p(&[1, 1]) * &p(&[1, 1])) * &p(&[5, 0, 3]);
        let (c, fs) = factor_rational(&h).expect("f");
        assert_eq!(c, Rational::from(3));
        assert_eq!(fs.len(), 2);
    }

    #[test]
    fn harder_factorizations() {
        // Swinnerton-Dyer polynomial of √2, √3, √5: irreducible of degree 8
        let sd8 = p(&[576, 0, -960, 0, 352, 0, -40, 0, 1]);
        assert_eq!(factor_squarefree_int(&sd8).expect("f").len(), 1);
        // x¹² − 1 = Φ₁Φ₂Φ₃Φ₄Φ₆Φ₁₂
        let mut c = vec![0i64; 13];
        c[0] = -1;
        c[12] = 1;
        let f = p(&c);
        let fs = factor_squarefree_int(&f).expect("f");
        assert_eq!(fs.len(), 6);
        assert_eq!(product(&fs), f);
        // large coefficients: (1000x² + 999)(x³ − 12345x + 7)
        let g = &p(&[999, 0, 1000]) * &p(&[7, -12345, 0, 1]);
        let fs = factor_squarefree_int(&g).expect("f");
        assert_eq!(fs.len(), 2);
        assert_eq!(product(&fs), g);
    }

    #[test]
    fn gaussian_factors() {
        // t² + 1 = (t + i)(t − i)
        let fs = factor_gaussian(&p(&[1, 0, 1])).expect("f");
        assert_eq!(fs.len(), 2);
        // t² + 2 stays irreducible over Q(i)
        let fs = factor_gaussian(&p(&[2, 0, 1])).expect("f");
        assert_eq!(fs.len(), 1);
        // t⁴ + 4 = (t² + 2t + 2)(t² − 2t + 2) = (t+1+i)(t+1−i)(t−1+i)(t−1−i)
        let fs = factor_gaussian(&p(&[4, 0, 0, 0, 1])).expect("f");
        assert_eq!(fs.len(), 4);
        // t⁴ + 1 splits over Q(i) into t² ± i
        let fs = factor_gaussian(&p(&[1, 0, 0, 0, 1])).expect("f");
        assert_eq!(fs.len(), 2);
        let prod = fs
            .iter()
            .fold(GaussPoly::constant(Complex::one()), |a, b| &a * b);
        assert_eq!(prod, to_gauss(&p(&[1, 0, 0, 0, 1])));
    }

    #[test]
    fn good_primes_of_square_free_polynomials() {
        // square-free: some prime of the list keeps it square-free of full degree
        assert!(has_good_prime(&p(&[5, 2, 1])));
        assert!(has_good_prime(&product(&[
            p(&[1, 0, 1]),
            p(&[-2, 0, 1]),
            p(&[3, 1])
        ])));
        // a square is a square modulo every prime; a zero polynomial has no prime
        assert!(!has_good_prime(&product(&[
            p(&[1, 1]),
            p(&[1, 1]),
            p(&[2, 0, 1])
        ])));
        assert!(!has_good_prime(&Poly::zero()));
        // the leading coefficient 3·5·…·179 (every prime of the list) and a square-free
        // polynomial: no prime keeps the degree
        let lc = PRIMES.iter().fold(Rational::ONE, |a, &q| a * int(q as i64));
        let f = Poly::new(vec![Rational::ONE, Rational::ZERO, lc]);
        assert!(!has_good_prime(&f));
        // and a factorization that finds a prime agrees: the factors multiply back
        let g = product(&[p(&[1, 0, 1]), p(&[-2, 0, 1]), p(&[3, 1])]);
        let fs = factor_squarefree_int(&primitive_int(&g)).expect("good prime");
        assert_eq!(product(&fs).monic(), g.monic());
    }

    #[test]
    fn q_first_splits_quadratics_and_quartics() {
        // t² + 2t + 5 = (t + 1 − 2i)(t + 1 + 2i); t² + 2 stays; t⁴ + 1 = (t² − i)(t² + i)
        for (c, k) in [
            (&[5, 2, 1][..], 2),
            (&[2, 0, 1][..], 1),
            (&[1, 0, 0, 0, 1][..], 2),
        ] {
            let fs = factor_gaussian_irreducible(&p(c)).expect("f");
            assert_eq!(fs.len(), k);
            let prod = fs
                .iter()
                .fold(GaussPoly::constant(Complex::one()), |a, b| &a * b);
            assert_eq!(prod, to_gauss(&p(c)));
        }
    }

    /// The same monic factors as a set (the order differs).
    fn same_factors(s: &Poly<Rational>) {
        let mut a = factor_gaussian(s).expect("trager");
        let b = factor_gaussian_q_first(s).expect("q first");
        assert_eq!(a.len(), b.len(), "{a:?} against {b:?}");
        a.retain(|f| !b.contains(f));
        assert!(a.is_empty(), "{a:?} not found by the Q-first factorization");
    }

    #[test]
    fn q_first_agrees_with_trager_on_examples() {
        // (t² + 1)(t⁴ + 4)(t³ − 2)(t − 3)(t⁴ − 10t² + 1)
        same_factors(&product(&[
            p(&[1, 0, 1]),
            p(&[4, 0, 0, 0, 1]),
            p(&[-2, 0, 0, 1]),
            p(&[-3, 1]),
            p(&[1, 0, -10, 0, 1]),
        ]));
    }

    #[test]
    fn stays_irreducible_is_tragers_answer() {
        // t⁴ − 2 (irreducible over Q(i)): proved, Trager's answer; t⁴ + 1 = (t² − i)(t² + i)
        // and (t² + 1)² + 1 = (t² + 1 − i)(t² + 1 + i): never claimed
        let f = p(&[-2, 0, 0, 0, 1]);
        let fast = stays_irreducible(&f, 4).expect("an odd factor mod an inert prime");
        assert_eq!(Ok(fast), trager(&f));
        for g in [p(&[1, 0, 0, 0, 1]), p(&[2, 0, 2, 0, 1])] {
            assert_eq!(stays_irreducible(&g, 4), None);
            assert_eq!(trager(&g).map(|v| v.len()), Ok(2));
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(32))]

        /// Random quartics, sextics and octics: for every irreducible factor over `Q` of even
        /// degree ≥ 4 (also of `f(t)·f(t)`-like norms, which split over `Q(i)`) the shortcut
        /// answers only with Trager's answer.
        #[test]
        fn stays_irreducible_agrees_with_trager(
            c in proptest::collection::vec(-6i64..7, 5..10),
            d in proptest::collection::vec(-3i64..4, 3),
        ) {
            let f = Poly::from_ints(&c);
            let h = to_gauss(&Poly::from_ints(&d));
            let i = Complex::new(Rational::ZERO, Rational::ONE);
            // a polynomial that splits over Q(i): |h + i·t²|² (degree 4 when deg h ≤ 2)
            let z = Complex::new(Rational::ZERO, Rational::ZERO);
            let w = &h + &Poly::new(vec![z.clone(), z, i]);
            for poly in [f, norm_sq_poly(&w)] {
                if poly.degree().is_none_or(|n| n < 4) {
                    continue;
                }
                let Ok((_, fs)) = factor_rational(&poly) else { continue };
                for (g, _) in fs {
                    let n = g.degree().unwrap_or(0);
                    if let Some(v) = stays_irreducible(&g, n) {
                        proptest::prop_assert_eq!(Ok(v), trager(&g));
                    }
                }
            }
        }
    }

    #[test]
    fn coprime_mod_p_decides_only_coprime_pairs() {
        let (a, b) = (p(&[1, 0, 1]), p(&[-2, 0, 1]));
        assert!(coprime_mod_p(&a, &b));
        let h = p(&[3, 1]);
        assert!(!coprime_mod_p(&(&a * &h), &(&b * &h)));
        // t² + 1 and t − i share the factor t − i over Q(i), not over Q
        let i = Complex::new(Rational::ZERO, Rational::ONE);
        let ga = to_gauss(&a);
        let gl = Poly::new(vec![-i.clone(), Complex::one()]);
        assert!(!gaussian_coprime_mod_p(&ga, &gl));
        assert!(gaussian_coprime_mod_p(&ga, &to_gauss(&b)));
        assert!(gaussian_coprime_mod_p(
            &gl,
            &Poly::new(vec![i, Complex::one()])
        ));
        // a denominator or a leading coefficient divisible by p: not decided here
        let big = Rational::from(COPRIME_P as i64);
        let den = Poly::new(vec![Rational::ONE / big.clone(), Rational::ONE]);
        assert!(!coprime_mod_p(&den, &b));
        let lead = Poly::new(vec![Rational::ONE, big]);
        assert!(!coprime_mod_p(&lead, &b));
        assert!(coprime_mod_p(&b, &lead));
        // zero and constants
        assert!(!coprime_mod_p(&Poly::zero(), &b));
        assert!(coprime_mod_p(&Poly::constant(Rational::from(2)), &b));
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]

        /// Random Gaussian-rational polynomials, with and without a planted common factor:
        /// whenever the modular test says coprime, Euclid's `gcd` is `1`; a planted factor
        /// is never missed; over `Q` likewise for the real parts.
        #[test]
        fn coprime_mod_p_agrees_with_euclid(
            a in proptest::collection::vec((-9i64..10, -9i64..10, 1i64..7), 1..6),
            b in proptest::collection::vec((-9i64..10, -9i64..10, 1i64..7), 1..6),
            h in proptest::collection::vec((-5i64..6, -5i64..6, 1i64..4), 2..4),
            plant in proptest::bool::ANY,
        ) {
            let cp = |v: &[(i64, i64, i64)]| -> GaussPoly {
                Poly::new(v.iter().map(|&(x, y, d)| Complex::new(
                    Rational::from_ratio(x, d), Rational::from_ratio(y, d))).collect())
            };
            let (mut pa, mut pb) = (cp(&a), cp(&b));
            let ph = cp(&h);
            if plant && ph.degree().is_some_and(|d| d > 0) {
                pa = &pa * &ph;
                pb = &pb * &ph;
            }
            proptest::prop_assume!(!pa.is_zero() && !pb.is_zero());
            let one = pa.gcd_euclid(&pb).degree() == Some(0);
            if gaussian_coprime_mod_p(&pa, &pb) {
                proptest::prop_assert!(one);
            }
            let (ra, rb) = (pa.map(|c| c.re.clone()), pb.map(|c| c.re.clone()));
            if !ra.is_zero() && !rb.is_zero() && coprime_mod_p(&ra, &rb) {
                proptest::prop_assert_eq!(ra.gcd_euclid(&rb).degree(), Some(0));
            }
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(32))]

        /// Random products of Gaussian-rational linear and quadratic factors times their
        /// conjugates and of random rational factors: both factorizations over `Q(i)` find
        /// the same factors.
        #[test]
        fn q_first_agrees_with_trager(
            z in proptest::collection::vec((-5i64..6, -5i64..6, 1i64..4), 1..4),
            r in proptest::collection::vec(proptest::collection::vec(-6i64..7, 2..5), 0..3),
        ) {
            // (t − z)(t − z̄) = t² − 2 Re z·t + |z|² for z = (a + bi)/d
            let mut fs: Vec<Poly<Rational>> = z
                .iter()
                .map(|&(a, b, d)| p(&[a * a + b * b, -2 * a * d, d * d]))
                .collect();
            fs.extend(r.iter().filter(|c| c.last().is_some_and(|x| *x != 0)).map(|c| p(c)));
            let f = product(&fs);
            // the square-free part
            let s = crate::roots::square_free_decomposition(&f)
                .into_iter()
                .fold(Poly::constant(Rational::ONE), |acc, (g, _)| &acc * &g);
            same_factors(&s);
        }
    }
}
