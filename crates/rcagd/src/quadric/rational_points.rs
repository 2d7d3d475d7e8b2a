//! Rational points on quadrics: an exact decision (Hasse–Minkowski) and a search.
//!
//! A generalized stereographic projection onto a quadric `Xᵀ Q X = 0` with rational
//! coefficients needs one rational point of it (Jüttler Schlussbemerkung: the other
//! quadrics are reached by projective maps; over Q this needs a rational point). Whether
//! one exists is decided exactly:
//!
//! 1. diagonalize `Q` by congruence over Q: `Tᵀ Q T = diag(d₀, …, d₃)`;
//! 2. replace each non-zero `dᵢ` by the square-free integer `aᵢ` of its square class;
//! 3. the form `Σ aᵢ yᵢ²` (n = 3 or 4 non-zero coefficients) has a non-trivial rational
//!    zero iff it has one over R and over every `Q_p` (Hasse–Minkowski); only
//!    `p = 2` and the primes dividing some `aᵢ` need checking. Locally (Serre, *A Course
//!    in Arithmetic*, IV.2.2 Thm. 6), with `d = Π aᵢ` and the Hasse invariant
//!    `ε = Π_{i<j} (aᵢ, aⱼ)_p`: n = 3 is isotropic iff `(−1, −d)_p = ε`; n = 4 iff `d` is
//!    not a square in `Q_p`, or it is and `ε = (−1, −1)_p`.
//!
//! Then a point is searched for among small integer vectors of the diagonal form. The
//! integers involved must fit in `i128` and be factorable by trial division (below
//! `10¹²` after removing factors up to `10⁶`); otherwise the decision is reported as
//! undecided and only the search runs.

// Index loops mirror the matrix formulas (Q_ij, M_k[i][j]) of docs/math/quadrics.md.
#![allow(clippy::needless_range_loop)]

use super::helpers::{self, fmt_scalar};
use super::{Hom, Mat4, QuadricError};
use rcagd_algebra::{Rational, Scalar};

/// The outcome of the local–global decision.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Isotropy {
    /// The form has a non-trivial rational zero.
    Isotropic,
    /// No non-trivial rational zero: the form has none over the named completion
    /// (`"R"` or `"Q_p"`).
    Anisotropic {
        /// `"R"` or `"Q_7"`.
        place: String,
    },
    /// The integers are too large to factor; not decided.
    Undecided(String),
}

/// Congruence diagonalization: `(T, d)` with `Tᵀ Q T = diag(d)` and `T` invertible (its
/// columns are the new basis). Symmetric Gaussian elimination with the usual fix for a
/// zero diagonal (`eₖ ← eₖ + eⱼ` when `Q_kk = Q_jj = 0 ≠ Q_kj`).
pub fn diagonalize<F: Scalar>(q: &Mat4<F>) -> (Mat4<F>, [F; 4]) {
    let mut m = q.clone();
    let mut t = helpers::identity4::<F>();
    let scale = helpers::magnitude(&q.concat());
    let nz = |x: &F| !helpers::negligible(x, scale);
    // apply the column operation col_k += c·col_j to T and the congruence to M
    fn add_col<F: Scalar>(m: &mut Mat4<F>, t: &mut Mat4<F>, k: usize, j: usize, c: &F) {
        for row in t.iter_mut() {
            let v = row[j].clone();
            row[k] += c.clone() * v;
        }
        // M ← Eᵀ M E with E = I + c e_j e_kᵀ: column k += c col j, then row k += c row j
        for row in m.iter_mut() {
            let v = row[j].clone();
            row[k] += c.clone() * v;
        }
        let rj = m[j].clone();
        for (x, y) in m[k].iter_mut().zip(rj) {
            *x += c.clone() * y;
        }
    }
    fn swap<F: Scalar>(m: &mut Mat4<F>, t: &mut Mat4<F>, a: usize, b: usize) {
        for row in t.iter_mut() {
            row.swap(a, b);
        }
        for row in m.iter_mut() {
            row.swap(a, b);
        }
        m.swap(a, b);
    }
    for k in 0..4 {
        if !nz(&m[k][k]) {
            if let Some(j) = (k + 1..4).find(|&j| nz(&m[j][j])) {
                swap(&mut m, &mut t, k, j);
            } else if let Some(j) = (k + 1..4).find(|&j| nz(&m[k][j])) {
                add_col(&mut m, &mut t, k, j, &F::one());
            } else {
                continue;
            }
        }
        let piv = m[k][k].clone();
        for i in k + 1..4 {
            if m[i][k].is_zero() {
                continue;
            }
            let c = -(m[i][k].clone() / piv.clone());
            add_col(&mut m, &mut t, i, k, &c);
            m[i][k] = F::zero();
            m[k][i] = F::zero();
        }
    }
    let d = [0, 1, 2, 3].map(|i| {
        if nz(&m[i][i]) {
            m[i][i].clone()
        } else {
            F::zero()
        }
    });
    (t, d)
}

/// Rank and signature `(positive, negative)` of a symmetric matrix.
pub fn signature<F: Scalar>(q: &Mat4<F>) -> (usize, usize, usize) {
    let (_, d) = diagonalize(q);
    let pos = d.iter().filter(|x| **x > F::zero()).count();
    let neg = d.iter().filter(|x| **x < F::zero()).count();
    (pos + neg, pos, neg)
}

const TRIAL: i128 = 1_000_000;

/// Square-free part and square root of the square part: `n = a·s²`, `a` square-free.
/// `None` if `n` cannot be fully factored by trial division.
fn squarefree(n: i128) -> Option<(i128, i128, Vec<i128>)> {
    let sign = if n < 0 { -1 } else { 1 };
    let mut m = n.checked_abs()?;
    let mut a = 1i128;
    let mut s = 1i128;
    let mut primes = Vec::new();
    let mut p = 2i128;
    while p * p <= m && p <= TRIAL {
        if m % p == 0 {
            let mut e = 0;
            while m % p == 0 {
                m /= p;
                e += 1;
            }
            if e % 2 == 1 {
                a *= p;
                primes.push(p);
            }
            for _ in 0..e / 2 {
                s = s.checked_mul(p)?;
            }
        }
        p += if p == 2 { 1 } else { 2 };
    }
    if m > 1 {
        if m > TRIAL * TRIAL && p > TRIAL {
            return None; // cofactor may be composite
        }
        a = a.checked_mul(m)?;
        primes.push(m);
    }
    Some((sign * a, s, primes))
}

fn mod_pow(mut b: i128, mut e: i128, m: i128) -> i128 {
    let mut r = 1i128;
    b = b.rem_euclid(m);
    while e > 0 {
        if e & 1 == 1 {
            r = r * b % m;
        }
        b = b * b % m;
        e >>= 1;
    }
    r
}

/// Legendre symbol `(u/p)` for an odd prime `p ∤ u`.
fn legendre(u: i128, p: i128) -> i32 {
    if mod_pow(u, (p - 1) / 2, p) == 1 {
        1
    } else {
        -1
    }
}

fn split(a: i128, p: i128) -> (i128, i128) {
    let mut a = a;
    let mut e = 0;
    while a % p == 0 {
        a /= p;
        e += 1;
    }
    (e, a)
}

/// The Hilbert symbol `(a, b)_p` of non-zero integers (Serre III.1.2 Thm. 1).
fn hilbert(a: i128, b: i128, p: i128) -> i32 {
    let (al, u) = split(a, p);
    let (be, v) = split(b, p);
    if p == 2 {
        let eps = |x: i128| if x.rem_euclid(4) == 1 { 0 } else { 1 };
        let omega = |x: i128| {
            if matches!(x.rem_euclid(8), 1 | 7) {
                0
            } else {
                1
            }
        };
        let e = eps(u) * eps(v) + al * omega(v) + be * omega(u);
        if e % 2 == 0 {
            1
        } else {
            -1
        }
    } else {
        let mut s = if (al * be * ((p - 1) / 2)) % 2 == 0 {
            1
        } else {
            -1
        };
        if be % 2 == 1 {
            s *= legendre(u, p);
        }
        if al % 2 == 1 {
            s *= legendre(v, p);
        }
        s
    }
}

/// `d` is a square in `Q_p`.
fn is_padic_square(d: i128, p: i128) -> bool {
    let (e, u) = split(d, p);
    if e % 2 == 1 {
        return false;
    }
    if p == 2 {
        u.rem_euclid(8) == 1
    } else {
        legendre(u, p) == 1
    }
}

/// The square-free integer of the square class of a non-zero rational `n/d` (`= n·d/d²`),
/// with `r` such that `q = a / r²`, and the primes dividing `a`.
fn square_class(q: &Rational) -> Option<(i128, Rational, Vec<i128>)> {
    let n = i128::try_from(q.numerator()).ok()?;
    let d = u128::try_from(q.denominator()).ok()?;
    let d = i128::try_from(d).ok()?;
    let nd = n.checked_mul(d)?;
    let (a, s, primes) = squarefree(nd)?;
    // q = n/d = n d / d² = a s² / d²  ⇒  q = a / (d/s)²
    let r = Rational::from(d) / Rational::from(s);
    Some((a, r, primes))
}

/// Decides whether the diagonal form `Σ aᵢ yᵢ²` (non-zero integer, square-free
/// coefficients, `n = 3` or `4`) has a non-trivial rational zero.
fn decide_diagonal(a: &[i128], primes: &[i128]) -> Isotropy {
    let pos = a.iter().filter(|x| **x > 0).count();
    if pos == 0 || pos == a.len() {
        return Isotropy::Anisotropic { place: "R".into() };
    }
    if a.len() >= 5 {
        return Isotropy::Isotropic;
    }
    let mut ps: Vec<i128> = primes.to_vec();
    ps.push(2);
    ps.sort_unstable();
    ps.dedup();
    let Some(d) = a.iter().try_fold(1i128, |acc, x| acc.checked_mul(*x)) else {
        return Isotropy::Undecided("coefficients too large".into());
    };
    for &p in &ps {
        let mut eps = 1;
        for i in 0..a.len() {
            for j in i + 1..a.len() {
                eps *= hilbert(a[i], a[j], p);
            }
        }
        let ok = match a.len() {
            3 => hilbert(-1, -d, p) == eps,
            4 => !is_padic_square(d, p) || eps == hilbert(-1, -1, p),
            2 => is_padic_square(-d, p),
            _ => true,
        };
        if !ok {
            return Isotropy::Anisotropic {
                place: format!("Q_{p}"),
            };
        }
    }
    Isotropy::Isotropic
}

/// The exact decision for the non-zero diagonal coefficients `coeffs` (rationals).
pub fn decide_isotropy(coeffs: &[Rational]) -> Isotropy {
    let mut a = Vec::new();
    let mut primes = Vec::new();
    for c in coeffs {
        if c.is_zero() {
            continue;
        }
        match square_class(c) {
            Some((ai, _, ps)) => {
                a.push(ai);
                primes.extend(ps);
            }
            None => return Isotropy::Undecided(format!("cannot factor {}", fmt_scalar(c))),
        }
    }
    decide_diagonal(&a, &primes)
}

fn isqrt(n: i128) -> Option<i128> {
    if n < 0 {
        return None;
    }
    let mut x = (n as f64).sqrt() as i128;
    while x > 0 && !matches!(x.checked_mul(x), Some(sq) if sq <= n) {
        x -= 1;
    }
    while (x + 1).checked_mul(x + 1).is_some_and(|sq| sq <= n) {
        x += 1;
    }
    (x.checked_mul(x) == Some(n)).then_some(x)
}

/// Searches `Σ aᵢ yᵢ² = 0` for a non-zero integer solution with `|yᵢ| ≤ h` (the last
/// coordinate solved for).
fn search(a: &[i128], h: i128) -> Option<Vec<i128>> {
    let n = a.len();
    let last = *a.last()?;
    let mut y = vec![-h; n - 1];
    loop {
        if y.iter().any(|v| *v != 0) {
            let s: Option<i128> = y.iter().zip(a).try_fold(0i128, |acc, (v, c)| {
                acc.checked_add(c.checked_mul(v.checked_mul(*v)?)?)
            });
            if let Some(s) = s {
                if s % last == 0 {
                    if let Some(r) = isqrt(-s / last) {
                        let mut out = y.clone();
                        out.push(r);
                        return Some(out);
                    }
                }
            }
        }
        // next vector
        let mut i = 0;
        loop {
            if i == n - 1 {
                return None;
            }
            y[i] += 1;
            if y[i] <= h {
                break;
            }
            y[i] = -h;
            i += 1;
        }
    }
}

/// A rational point of the quadric `Xᵀ Q X = 0` (rank 3 or 4), off the vertex for a cone.
/// Decides existence exactly (module docs), then searches small heights.
///
/// # Errors
/// [`QuadricError::NoRealPoint`] for a definite form (or a cone with a definite base);
/// [`QuadricError::NoRationalPoint`] if Hasse–Minkowski excludes rational points (the
/// message names the place), or if the search fails; [`QuadricError::Unsupported`] for
/// rank ≤ 2.
pub fn find_rational_point(q: &Mat4<Rational>) -> Result<Hom<Rational>, QuadricError> {
    let (t, d) = diagonalize(q);
    let idx: Vec<usize> = (0..4).filter(|&i| !d[i].is_zero()).collect();
    if idx.len() < 3 {
        return Err(QuadricError::Unsupported(format!(
            "rank {} (plane pairs and double planes are not supported)",
            idx.len()
        )));
    }
    let pos = idx.iter().filter(|&&i| d[i] > Rational::from(0)).count();
    if pos == 0 || pos == idx.len() {
        return Err(QuadricError::NoRealPoint(if idx.len() == 4 {
            "the form is definite: the quadric has no real point".into()
        } else {
            "the cone's base conic is imaginary: only the vertex is real".into()
        }));
    }
    let mut a = Vec::new();
    let mut rs = Vec::new();
    let mut primes = Vec::new();
    let mut decidable = true;
    for &i in &idx {
        match square_class(&d[i]) {
            Some((ai, r, ps)) => {
                a.push(ai);
                rs.push(r);
                primes.extend(ps);
            }
            None => {
                decidable = false;
                break;
            }
        }
    }
    if !decidable {
        return Err(QuadricError::NoRationalPoint(
            "the coefficients are too large to decide (factor) exactly; supply a rational point"
                .into(),
        ));
    }
    if let Isotropy::Anisotropic { place } = decide_diagonal(&a, &primes) {
        return Err(QuadricError::NoRationalPoint(format!(
            "the quadric has real points but no rational point: the form {} is anisotropic over {place} (Hasse–Minkowski)",
            a.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", ")
        )));
    }
    for h in [4i128, 12, 40] {
        if let Some(y) = search(&a, h) {
            // x' = r·y in the diagonal basis, X = T x'
            let mut xp = helpers::zero4::<Rational>();
            for (k, &i) in idx.iter().enumerate() {
                xp[i] = rs[k].clone() * Rational::from(y[k]);
            }
            let x = helpers::mat_vec(&t, &xp);
            return Ok(x);
        }
    }
    Err(QuadricError::NoRationalPoint(
        "a rational point exists (Hasse–Minkowski) but none of small height was found; supply one"
            .into(),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(n: i64) -> Rational {
        Rational::from(n)
    }

    #[test]
    fn diagonalization_is_a_congruence() {
        let q: Mat4<Rational> =
            helpers::mat4_i([[0, 1, 2, 0], [1, 0, 0, 3], [2, 0, 0, 1], [0, 3, 1, 0]]);
        let (t, d) = diagonalize(&q);
        let tt = helpers::transpose(&t);
        let m = helpers::mat_mul(&tt, &helpers::mat_mul(&q, &t));
        for i in 0..4 {
            for j in 0..4 {
                let want = if i == j { d[i].clone() } else { r(0) };
                assert_eq!(m[i][j], want);
            }
        }
    }

    #[test]
    fn three_squares() {
        // x² + y² + z² = n w²: rational points iff n is a sum of three rational squares
        for (n, expect) in [
            (1, true),
            (2, true),
            (3, true),
            (7, false),
            (15, false),
            (6, true),
            (28, false),
        ] {
            let q: Mat4<Rational> =
                helpers::mat4_i([[-n, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]);
            let res = find_rational_point(&q);
            assert_eq!(res.is_ok(), expect, "n = {n}: {res:?}");
            if let Ok(p) = res {
                assert!(helpers::quad_form(&q, &p).0.is_zero());
            }
        }
    }

    #[test]
    fn legendre_ternary() {
        // x² + y² = 3 z² has no rational point; x² + y² = 5 z² has.
        let c3: Mat4<Rational> =
            helpers::mat4_i([[0, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -3]]);
        assert!(matches!(
            find_rational_point(&c3),
            Err(QuadricError::NoRationalPoint(_))
        ));
        let c5: Mat4<Rational> =
            helpers::mat4_i([[0, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -5]]);
        let p = find_rational_point(&c5).unwrap();
        assert!(helpers::quad_form(&c5, &p).0.is_zero());
        assert!(!(p[1].is_zero() && p[2].is_zero() && p[3].is_zero()));
        let def: Mat4<Rational> =
            helpers::mat4_i([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]);
        assert!(matches!(
            find_rational_point(&def),
            Err(QuadricError::NoRealPoint(_))
        ));
    }
}
