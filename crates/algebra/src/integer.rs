//! Integer arithmetic for the rational-point engines: factorization into primes, square
//! roots modulo primes, square-free parts.
//!
//! * **Factorization** ([`factor`]): trial division by the primes below `2¹⁶`, then
//!   Brent's variant of Pollard's ρ on the cofactor, with a fixed work limit
//!   ([`RHO_ITERATIONS`] steps per split), then Lenstra's elliptic curve method
//!   ([`ecm_split`]: Montgomery curves with Suyama's parametrization, stage 1 by the
//!   Montgomery ladder, a prime-by-prime stage 2; the schedule [`ECM_SCHEDULE`] is the work
//!   limit). A cofactor that resists both is reported as [`IntegerError::TooHard`], never
//!   guessed. Every factor found is a divisor by construction (a gcd with `n`); primality is
//!   decided by the Miller–Rabin test with the first twenty prime bases (a proof below
//!   `3.3·10²⁴`, the first thirteen bases suffice there: Sorenson and Webster, "Strong
//!   pseudoprimes to twelve prime bases", Math. Comp. 86, 2017) and, above that bound, also
//!   by the strong Lucas test with Selfridge's parameters (together the Baillie–PSW test:
//!   R. Baillie and S. Wagstaff, "Lucas pseudoprimes", Math. Comp. 35, 1980; no composite
//!   passing it is known).
//! * **Square roots modulo a prime** ([`sqrt_mod_prime`]): Tonelli–Shanks.

use dashu_base::{BitTest, Gcd, SquareRoot, UnsignedAbs};
use dashu_int::{IBig, UBig};
use thiserror::Error;

/// The number of Pollard–Brent steps spent on one split before giving up.
pub const RHO_ITERATIONS: usize = 1 << 20;

std::thread_local! {
    /// The quick mode of [`with_quick_factoring`] on this thread.
    static QUICK: core::cell::Cell<bool> = const { core::cell::Cell::new(false) };
}

/// Pollard–Brent steps per split in the quick mode.
pub const QUICK_RHO_ITERATIONS: usize = 1 << 14;

/// Runs `f` with a small factorization work limit on this thread: [`QUICK_RHO_ITERATIONS`]
/// ρ steps and no elliptic curves. For optional work (the conic-point engine's search for
/// a point of lower degree), where giving up ([`IntegerError::TooHard`]) is cheap and a
/// full attempt is not worth minutes.
pub fn with_quick_factoring<T>(f: impl FnOnce() -> T) -> T {
    let old = QUICK.with(|q| q.replace(true));
    let out = f();
    QUICK.with(|q| q.set(old));
    out
}

fn quick() -> bool {
    QUICK.with(core::cell::Cell::get)
}

/// A failure of the integer arithmetic (never a wrong result).
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum IntegerError {
    /// A composite cofactor could not be split within the work limit.
    #[error(
        "cannot factor the integer {0} within the work limit (Pollard ρ, {RHO_ITERATIONS} steps; elliptic curve method up to B1 = 50000)"
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
    // Miller–Rabin with the first 13 prime bases is a proof below 3.3·10²⁴ (module docs)
    if n.bit_len() <= 81 {
        return true;
    }
    strong_lucas(n)
}

/// The Jacobi symbol `(a/n)` for odd `n > 0`.
fn jacobi(a: &IBig, n: &UBig) -> i8 {
    let mut a = rem_euclid(a, n);
    let mut n = n.clone();
    let mut r = 1i8;
    let (three, five, eight) = (UBig::from(3u8), UBig::from(5u8), UBig::from(8u8));
    while !a.is_zero() {
        while !a.bit(0) {
            a >>= 1;
            let m = &n % &eight;
            if m == three || m == five {
                r = -r;
            }
        }
        core::mem::swap(&mut a, &mut n);
        let four = UBig::from(4u8);
        if &a % &four == three && &n % &four == three {
            r = -r;
        }
        a = &a % &n;
    }
    if n == UBig::ONE {
        r
    } else {
        0
    }
}

/// The strong Lucas probable-prime test with Selfridge's parameters (`D` the first of
/// `5, −7, 9, −11, …` with `(D/n) = −1`, `P = 1`, `Q = (1 − D)/4`) for odd `n` that is not
/// a square (Baillie and Wagstaff, "Lucas pseudoprimes", Math. Comp. 35, 1980, §3).
fn strong_lucas(n: &UBig) -> bool {
    let r = n.sqrt();
    if &r * &r == *n {
        return false;
    }
    let mut d = IBig::from(5);
    loop {
        match jacobi(&d, n) {
            -1 => break,
            0 => {
                // d shares a factor with n (|d| < n for n > 2⁸¹)
                return false;
            }
            _ => {}
        }
        d = if d > IBig::ZERO {
            -(d + IBig::from(2))
        } else {
            -d + IBig::from(2)
        };
    }
    let q = (IBig::ONE - &d) / IBig::from(4);
    let m = |x: IBig| rem_euclid(&x, n);
    let dm = m(d.clone());
    let qm = m(q);
    // n + 1 = d·2^s, d odd
    let np1 = n + UBig::ONE;
    let mut k = np1.clone();
    let mut s = 0usize;
    while !k.bit(0) {
        k >>= 1;
        s += 1;
    }
    // U_k, V_k, Q^k by the binary method (P = 1)
    let inv2 = (n + UBig::ONE) >> 1;
    let (mut u, mut v, mut qk) = (UBig::ONE, UBig::ONE, qm.clone());
    for i in (0..k.bit_len().saturating_sub(1)).rev() {
        // doubling
        u = (&u * &v) % n;
        v = m(IBig::from(&v * &v) - IBig::from(&qk * UBig::from(2u8)));
        qk = (&qk * &qk) % n;
        if k.bit(i) {
            // (U, V) → (U_{j+1}, V_{j+1}) = ((U + V)/2, (D·U + V)/2)
            let u1 = ((&u + &v) * &inv2) % n;
            let v1 = ((&dm * &u + &v) * &inv2) % n;
            u = u1;
            v = v1;
            qk = (&qk * &qm) % n;
        }
    }
    if u.is_zero() || v.is_zero() {
        return true;
    }
    for _ in 1..s {
        v = m(IBig::from(&v * &v) - IBig::from(&qk * UBig::from(2u8)));
        qk = (&qk * &qk) % n;
        if v.is_zero() {
            return true;
        }
    }
    false
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
            if steps
                > if quick() {
                    QUICK_RHO_ITERATIONS
                } else {
                    RHO_ITERATIONS
                }
            {
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

/// The elliptic-curve work limit: `(B1, curves)` stages, tried in order; stage 2 runs to
/// `B2 = 50·B1`. With these, factors up to about 25 decimal digits are found with good
/// probability (the classical table of optimal B1: 2 000 for 15 digits, 11 000 for 20,
/// 50 000 for 25; P. Zimmermann and B. Dodson, "20 years of ECM", ANTS VII, 2006).
pub const ECM_SCHEDULE: [(u64, usize); 3] = [(2_000, 25), (11_000, 90), (50_000, 120)];

/// `(a − b) mod n` for reduced `a, b`.
fn sub_mod(a: &UBig, b: &UBig, n: &UBig) -> UBig {
    if a >= b {
        a - b
    } else {
        n - (b - a)
    }
}

/// A point `(X : Z)` of a Montgomery curve `By² = x³ + Ax² + x` in x-only coordinates.
#[derive(Clone)]
struct XZ {
    x: UBig,
    z: UBig,
}

/// Montgomery's x-only arithmetic modulo `n` with `a24 = (A + 2)/4` (P. L. Montgomery,
/// "Speeding the Pollard and elliptic curve methods of factorization", Math. Comp. 48,
/// 1987, §10.3.1).
struct Curve<'a> {
    n: &'a UBig,
    a24: UBig,
}

impl Curve<'_> {
    fn mul(&self, a: &UBig, b: &UBig) -> UBig {
        (a * b) % self.n
    }
    fn add_m(&self, a: &UBig, b: &UBig) -> UBig {
        let s = a + b;
        if s >= *self.n {
            s - self.n
        } else {
            s
        }
    }
    /// `2P`: `X₂ = (X+Z)²(X−Z)²`, `Z₂ = 4XZ·((X−Z)² + a24·4XZ)`.
    fn dbl(&self, p: &XZ) -> XZ {
        let s = self.add_m(&p.x, &p.z);
        let d = sub_mod(&p.x, &p.z, self.n);
        let t1 = self.mul(&s, &s);
        let t2 = self.mul(&d, &d);
        let t3 = sub_mod(&t1, &t2, self.n);
        XZ {
            x: self.mul(&t1, &t2),
            z: self.mul(&t3, &self.add_m(&t2, &self.mul(&self.a24, &t3))),
        }
    }
    /// `P + Q` from `P − Q`: `X = Z₋·(u + v)²`, `Z = X₋·(u − v)²` with
    /// `u = (X_P − Z_P)(X_Q + Z_Q)`, `v = (X_P + Z_P)(X_Q − Z_Q)`.
    fn add(&self, p: &XZ, q: &XZ, diff: &XZ) -> XZ {
        let u = self.mul(&sub_mod(&p.x, &p.z, self.n), &self.add_m(&q.x, &q.z));
        let v = self.mul(&self.add_m(&p.x, &p.z), &sub_mod(&q.x, &q.z, self.n));
        let s = self.add_m(&u, &v);
        let d = sub_mod(&u, &v, self.n);
        XZ {
            x: self.mul(&diff.z, &self.mul(&s, &s)),
            z: self.mul(&diff.x, &self.mul(&d, &d)),
        }
    }
    /// `k·P` by the Montgomery ladder (`k ≥ 1`).
    fn ladder(&self, p: &XZ, k: u64) -> XZ {
        let mut r0 = p.clone();
        let mut r1 = self.dbl(p);
        for i in (0..63 - k.leading_zeros()).rev() {
            if k >> i & 1 == 1 {
                r0 = self.add(&r1, &r0, p);
                r1 = self.dbl(&r1);
            } else {
                r1 = self.add(&r1, &r0, p);
                r0 = self.dbl(&r0);
            }
        }
        r0
    }
}

/// The primes up to `b` (sieve of Eratosthenes).
fn primes_up_to(b: u64) -> Vec<u64> {
    let b = b as usize;
    let mut comp = vec![false; b + 1];
    let mut out = Vec::new();
    for i in 2..=b {
        if !comp[i] {
            out.push(i as u64);
            let mut j = i * i;
            while j <= b {
                comp[j] = true;
                j += i;
            }
        }
    }
    out
}

/// A non-trivial divisor `g` of `n` (`1 < g < n`) from `gcd(x, n)`, if there is one.
fn proper_gcd(x: &UBig, n: &UBig) -> Option<UBig> {
    let g = x.gcd(n);
    (g != UBig::ONE && g != *n).then_some(g)
}

/// Lenstra's elliptic curve method on the odd composite `n` (not a prime power) with the
/// work limit `schedule` (module docs): a non-trivial divisor, or `None`. Curve `σ`:
/// `u = σ² − 5`, `v = 4σ`, `P = (u³ : v³)`, `a24 = (v − u)³(3u + v)/(16u³v)` (Suyama's
/// parametrization: the group order is divisible by 12). Stage 1 multiplies `P` by every
/// prime power up to `B1`; stage 2 accumulates `X_{mD}·Z_j − X_j·Z_{mD}` over the primes
/// `q = mD ± j ≤ B2` (`jP` for `j < D` coprime to `D`, `mD·P` by differential additions),
/// which vanishes modulo `p` when `q·P` is the neutral element modulo `p`.
pub fn ecm_split(n: &UBig, schedule: &[(u64, usize)]) -> Option<UBig> {
    const D: u64 = 210;
    let mut sigma = 6u64;
    for &(b1, curves) in schedule {
        let b2 = b1 * 50;
        let primes = primes_up_to(b2);
        let mut is_prime = vec![false; (b2 + D + 1) as usize];
        for &p in &primes {
            is_prime[p as usize] = true;
        }
        for _ in 0..curves {
            sigma += 1;
            let s = UBig::from(sigma);
            let u = (&s * &s - UBig::from(5u8)) % n;
            let v = (UBig::from(4u8) * &s) % n;
            let u3 = (&u * &u % n) * &u % n;
            let v3 = (&v * &v % n) * &v % n;
            let vmu = sub_mod(&v, &u, n);
            let num = (&vmu * &vmu % n) * &vmu % n * ((UBig::from(3u8) * &u + &v) % n) % n;
            let den = (UBig::from(16u8) * &u3 % n) * &v % n;
            if let Some(g) = proper_gcd(&den, n) {
                return Some(g);
            }
            let Some(inv) = mod_inverse(&den, n) else {
                continue;
            };
            let curve = Curve {
                n,
                a24: num * inv % n,
            };
            let mut p = XZ { x: u3, z: v3 };
            // stage 1
            for &q in primes.iter().take_while(|&&q| q <= b1) {
                let mut qk = q;
                while qk <= b1 / q {
                    qk *= q;
                }
                p = curve.ladder(&p, qk);
            }
            if let Some(g) = proper_gcd(&p.z, n) {
                return Some(g);
            }
            if (&p.z).gcd(n) == *n {
                continue;
            }
            // stage 2: baby steps jP (odd j < D), giant steps mD·P
            let p2 = curve.dbl(&p);
            let mut baby: Vec<Option<XZ>> = vec![None; D as usize];
            baby[1] = Some(p.clone());
            let mut prev = p.clone();
            let mut cur = curve.add(&p2, &p, &p); // 3P
            let mut j = 3u64;
            while j < D {
                baby[j as usize] = Some(cur.clone());
                let next = curve.add(&cur, &p2, &prev);
                prev = cur;
                cur = next;
                j += 2;
            }
            let dp = curve.ladder(&p, D);
            let m0 = (b1 / D).max(1);
            // giant steps from m = max(m0, 2) (the difference (m − 1)·D·P must not be O)
            let mut m = m0.max(2);
            let mut gm_prev = curve.ladder(&p, (m - 1) * D);
            let mut gm = curve.ladder(&p, m * D);
            let mut acc = UBig::ONE;
            let mut count = 0usize;
            while m * D <= b2 + D {
                for jj in (1..D).step_by(2) {
                    let hi = m * D + jj;
                    let lo = m * D - jj;
                    let hit = (lo > b1 && is_prime[lo as usize])
                        || (hi > b1 && hi <= b2 && is_prime[hi as usize]);
                    if !hit {
                        continue;
                    }
                    if let Some(bj) = &baby[jj as usize] {
                        let t = sub_mod(&curve.mul(&gm.x, &bj.z), &curve.mul(&bj.x, &gm.z), n);
                        acc = curve.mul(&acc, &t);
                        count += 1;
                    }
                }
                if count >= 2_000 {
                    if let Some(g) = proper_gcd(&acc, n) {
                        return Some(g);
                    }
                    count = 0;
                }
                let next = curve.add(&gm, &dp, &gm_prev);
                gm_prev = gm;
                gm = next;
                m += 1;
            }
            if let Some(g) = proper_gcd(&acc, n) {
                return Some(g);
            }
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
/// [`IntegerError::TooHard`] when a composite cofactor resists Pollard's ρ and the elliptic
/// curve method within their work limits.
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
        let d = rho_split(&m)
            .or_else(|| {
                if quick() {
                    None
                } else {
                    ecm_split(&m, &ECM_SCHEDULE)
                }
            })
            .ok_or_else(|| IntegerError::TooHard(m.to_string()))?;
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
    let abs = n.clone().unsigned_abs();
    // a perfect square (up to sign) needs no factorization: s = ±1, f = √|n|, the same
    // answer as below (every exponent even); its factorization can be far out of reach
    let root = abs.sqrt();
    if &root * &root == abs && abs != UBig::ZERO {
        let s = if *n < IBig::ZERO {
            -IBig::ONE
        } else {
            IBig::ONE
        };
        return Ok((s, root, Vec::new()));
    }
    let fs = factor(&abs)?;
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

    fn mersenne(p: usize) -> UBig {
        (UBig::ONE << p) - UBig::ONE
    }

    /// A perfect square whose root is a product of two large primes (out of reach of ρ and
    /// the ECM schedule) is answered without factoring, as the factorization would.
    #[test]
    fn square_free_part_of_a_hard_square() {
        let root = mersenne(127) * mersenne(89);
        let n = IBig::from(&root * &root);
        let (s, f, primes) = square_free_part(&n).expect("a square");
        assert_eq!((s, &f), (IBig::ONE, &root));
        assert!(primes.is_empty());
        let (s, f, _) = square_free_part(&-n).expect("minus a square");
        assert_eq!((s, f), (-IBig::ONE, root));
        // the general path agrees on a square it can factor
        let (s, f, _) = square_free_part(&IBig::from(4 * 9 * 49)).expect("small");
        assert_eq!((s, f), (IBig::ONE, UBig::from(42u8)));
    }

    fn check_factorization(n: &UBig, f: &[(UBig, u32)]) {
        let back = f
            .iter()
            .fold(UBig::ONE, |acc, (p, e)| acc * p.pow(*e as usize));
        assert_eq!(&back, n);
        assert!(f.iter().all(|(p, _)| is_probable_prime(p)), "{f:?}");
    }

    /// Primality against known primes and composites: the Mersenne primes `2^p − 1` for
    /// p = 61, 89, 107, 127 and the composites `2^p − 1` for p = 67, 101 (Cole 1903;
    /// factor 7432339208719 of `2^101 − 1`), the smallest strong pseudoprime to the first
    /// thirteen prime bases, 3317044064679887385961981, and products of two Mersenne primes.
    #[test]
    fn primality_known_values() {
        for p in [61, 89, 107, 127] {
            assert!(is_probable_prime(&mersenne(p)), "M{p}");
        }
        for p in [67, 101] {
            assert!(!is_probable_prime(&mersenne(p)), "M{p}");
        }
        let psp: UBig = "3317044064679887385961981".parse().expect("literal");
        assert!(!is_probable_prime(&psp));
        assert!(!is_probable_prime(&(mersenne(89) * mersenne(107))));
        assert!(!is_probable_prime(&(mersenne(127) * mersenne(127))));
        // the strong Lucas test alone: passes primes, rejects these composites
        assert!(strong_lucas(&mersenne(127)));
        assert!(!strong_lucas(&(mersenne(61) * mersenne(89))));
        // 5777 = 53·109 is the smallest strong Lucas pseudoprime (Baillie–Wagstaff, Table 2)
        assert!(strong_lucas(&UBig::from(5777u32)));
        assert_eq!(jacobi(&IBig::from(1001), &UBig::from(9907u32)), -1);
        assert_eq!(jacobi(&IBig::from(19), &UBig::from(45u32)), 1);
        assert_eq!(jacobi(&IBig::from(3), &UBig::from(9u32)), 0);
    }

    /// The elliptic curve method splits products that Pollard's ρ cannot (a 61-bit factor
    /// needs about 2³⁰ ρ steps); the factors multiply back and are prime.
    #[test]
    fn ecm_splits_products_of_known_primes() {
        let (m61, m89, m31) = (mersenne(61), mersenne(89), mersenne(31));
        let n = &m61 * &m89;
        assert_eq!(rho_split(&n), None, "ρ within its limit");
        let g = ecm_split(&n, &ECM_SCHEDULE).expect("ECM finds the 61-bit factor");
        assert!(g == m61 || g == m89, "{g}");
        // trial division, ρ (the 31-bit factor) and the primality test in one run
        let n3 = &m31 * &m61 * UBig::from(9u8);
        let f = factor(&n3).expect("factor");
        check_factorization(&n3, &f);
        assert_eq!(f, vec![(UBig::from(3u8), 2), (m31, 1), (m61, 1)]);
        // 2^67 − 1 = 193707721 · 761838257287 (Cole 1903)
        let f = factor(&mersenne(67)).expect("factor");
        assert_eq!(
            f,
            vec![
                (UBig::from(193_707_721u64), 1),
                (UBig::from(761_838_257_287u64), 1)
            ]
        );
    }

    /// A tiny work limit may fail, but never returns a wrong divisor; `factor` reports
    /// `TooHard` only for a composite it could not split.
    #[test]
    fn ecm_never_wrong() {
        // the quick mode gives up on a 61-bit factor (no elliptic curves), and is restored
        let m = mersenne(61) * mersenne(89);
        assert!(matches!(
            with_quick_factoring(|| factor(&m)),
            Err(IntegerError::TooHard(_))
        ));
        assert!(!quick());
        let n = mersenne(89) * mersenne(107);
        for limit in [[(50u64, 1usize)], [(200, 2)]] {
            if let Some(g) = ecm_split(&n, &limit) {
                assert!(g > UBig::ONE && g < n && (&n % &g).is_zero());
            }
        }
    }

    /// The integers that left four conic-point benchmark families undecided under Pollard ρ
    /// alone (docs/BENCHMARKS.md) are factored now: the two with 17- and 15-digit factors
    /// here, the two with 20- and 21-digit factors (about 40 s each in the test profile)
    /// in [`benchmark_integers_with_20_digit_factors`].
    #[test]
    fn benchmark_integers() {
        factor_all(&[
            "7137525858178123098574649693617337",
            "165007955199822014276293129864111",
        ]);
    }

    /// Slow in the test profile (ECM with 20- and 21-digit factors): run by
    /// `cargo test --release -p rcagd-algebra --lib -- --ignored benchmark_integers`.
    #[test]
    #[ignore = "slow: ECM on 20- and 21-digit factors (about 80 s in the test profile)"]
    fn benchmark_integers_with_20_digit_factors() {
        factor_all(&[
            "1112697600727565733339128465758264846982101581422315967301372853",
            "27366208895456260263398415383589608518923884862147430339",
        ]);
    }

    fn factor_all(integers: &[&str]) {
        for s in integers {
            let n: UBig = s.parse().expect("literal");
            let f = factor(&n).expect("decided");
            eprintln!("{s} = {f:?}");
            check_factorization(&n, &f);
        }
    }

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
