//! A non-negative polynomial as a sum of two squares, `D = g₁² + g₂²` (seed 003 §2.1 before
//! (2.14): "zu jedem Polynom f ≥ 0 existieren f₁, f₂ mit f = f₁² + f₂²"; seed 004 (4.9);
//! NOTES-000-003 item 003-4; NOTES-004 §0 rationality caveat).
//!
//! `D = g₁² + g₂² = |g₁ + i g₂|²` means `D = h·h̄` for `h ∈ K(i)[t]`. The decomposition is
//! computed from the factorization over `Q(i)` ([`super::factor`]):
//!
//! 1. square-free decomposition `D = c · A² · S` (`A = ∏ fₖ^{⌊k/2⌋}`, `S = ∏_{k odd} fₖ`
//!    square-free, monic); `D ≥ 0` on `R` forces `S` to have no real roots and `c > 0`;
//! 2. factor `S` over `Q(i)`: every `Q`-irreducible factor `p` of `S` either splits,
//!    `p = π π̄` (choose `π` or `π̄`: these are the choices of the decomposition, the
//!    `∏ (pᵢ + 1)` factorizations of seed 003 (2.35)), or stays irreducible ("real" factors);
//! 3. the constant `c` is a sum of two rational squares iff every prime `≡ 3 (mod 4)` has
//!    even exponent in its numerator·denominator (Fermat; representations from
//!    Cornacchia/Hermite–Serret for each prime `≡ 1 (mod 4)`).
//!
//! **Exact cases.**
//!
//! * **Over `Q`** ([`SumOfSquares::Rational`]) — exactly when `S` has no real factors and `c`
//!   is a sum of two rational squares: `g₁ + i g₂ = (x + iy)·A·∏π`. This decision is
//!   complete: if no rational decomposition is reported, none exists (a sum of two squares
//!   in `Q(t)` is one in `Q[t]`, and `Q(i)[t]` is a UFD). The only exception is a constant
//!   whose numerator·denominator has a prime cofactor beyond `2⁶⁴` after trial division
//!   (not decided; then the extension below is used).
//! * **Over one real quadratic field `Q(√d)`** ([`SumOfSquares::Extension`]): (a) `S` has no
//!   real factors but `c` is not a sum of two rational squares: `g = √c·A·∏π`,
//!   `d = sqf(c)`; (b) every real factor is a quadratic `t² + bt + e` whose
//!   `δ = 4e − b² > 0` has one common square class `d`: `t² + bt + e = |t + b/2 + i√δ/2|²`,
//!   and `c` (or `c/d`) is a sum of two rational squares.
//! * Otherwise (a real factor of degree ≥ 4, or several square classes) the roots generate a
//!   larger field: [`super::CanalError::NeedsLargerExtension`]; the explicit
//!   [`sum_of_two_squares_f64`] computes an approximate split from the complex roots. Never
//!   silently in `f64`.

use super::factor::{factor_gaussian, GaussPoly};
use super::{negative_interval, CanalError};
use crate::error::format_scalar;
use num_traits::One;
use rcagd_algebra::complex::{conj_poly, re_im_polys, Complex};
use rcagd_algebra::quadratic::{split_square, sqrt_in_extension};
use rcagd_algebra::roots::square_free_decomposition;
use rcagd_algebra::{Poly, QuadExt, Rational, Scalar};

/// A decomposition `D = g₁² + g₂²`.
#[derive(Debug, Clone, PartialEq)]
pub enum SumOfSquares {
    /// Rational `g₁, g₂`.
    Rational {
        /// `g₁`.
        g1: Poly<Rational>,
        /// `g₂`.
        g2: Poly<Rational>,
    },
    /// `g₁, g₂` over `Q(√radicand)`.
    Extension {
        /// The square-free radicand `d` of the field `Q(√d)`.
        radicand: Rational,
        /// `g₁`.
        g1: Poly<QuadExt>,
        /// `g₂`.
        g2: Poly<QuadExt>,
    },
}

impl SumOfSquares {
    /// `None` over `Q`, the radicand `d` over `Q(√d)`.
    pub fn radicand(&self) -> Option<&Rational> {
        match self {
            SumOfSquares::Rational { .. } => None,
            SumOfSquares::Extension { radicand, .. } => Some(radicand),
        }
    }

    /// `(g₁, g₂)` over `QuadExt` (rationals embedded).
    pub fn to_ext(&self) -> (Poly<QuadExt>, Poly<QuadExt>) {
        match self {
            SumOfSquares::Rational { g1, g2 } => (
                g1.map(|x| QuadExt::rational(x.clone())),
                g2.map(|x| QuadExt::rational(x.clone())),
            ),
            SumOfSquares::Extension { g1, g2, .. } => (g1.clone(), g2.clone()),
        }
    }

    /// `true` iff `g₁² + g₂² = d` exactly.
    pub fn verifies(&self, d: &Poly<Rational>) -> bool {
        let (g1, g2) = self.to_ext();
        let s = &(&g1 * &g1) + &(&g2 * &g2);
        s == d.map(|x| QuadExt::rational(x.clone()))
    }
}

/// The factorization data of a non-negative `D` over `Q(i)` (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct GaussianSplit {
    /// The leading coefficient `c > 0`.
    pub lc: Rational,
    /// `A` (monic) with `D = c·A²·S`.
    pub square_part: Poly<Rational>,
    /// One Gaussian factor `π` of every splitting factor `p = π π̄` of `S` (monic).
    pub pairs: Vec<GaussPoly>,
    /// The factors of `S` that stay irreducible over `Q(i)` (monic, rational).
    pub real_factors: Vec<Poly<Rational>>,
}

fn product(ps: &[Poly<Rational>]) -> Poly<Rational> {
    ps.iter().fold(Poly::constant(Rational::ONE), |a, b| &a * b)
}

impl GaussianSplit {
    /// Factors `D` over `Q(i)` (module docs).
    ///
    /// # Errors
    /// [`CanalError::DegenerateSpine`] for `D ≡ 0`, [`CanalError::NoRealEnvelope`] if `D` is
    /// negative somewhere (an interval is named), [`CanalError::Factorization`] if the exact
    /// factorization gives up.
    pub fn new(d: &Poly<Rational>) -> Result<Self, CanalError> {
        if let Some(neg) = negative_interval(d, None)? {
            return Err(neg);
        }
        let lc = d.leading();
        let mut a = Poly::constant(Rational::ONE);
        let mut s_parts = Vec::new();
        for (f, k) in square_free_decomposition(d) {
            a = &a * &f.pow((k / 2) as u32);
            if k % 2 == 1 {
                s_parts.push(f);
            }
        }
        let s = product(&s_parts);
        let mut pairs = Vec::new();
        let mut real_factors = Vec::new();
        if s.degree().is_some_and(|n| n > 0) {
            let facs = factor_gaussian(&s).map_err(|e| CanalError::Factorization(e.to_string()))?;
            let mut used = vec![false; facs.len()];
            for i in 0..facs.len() {
                if used[i] {
                    continue;
                }
                used[i] = true;
                let h = &facs[i];
                let hc = conj_poly(h);
                if hc == *h {
                    real_factors.push(h.map(|c| c.re.clone()));
                    continue;
                }
                if let Some(j) = (i + 1..facs.len()).find(|&j| !used[j] && facs[j] == hc) {
                    used[j] = true;
                }
                pairs.push(h.clone());
            }
        }
        Ok(GaussianSplit {
            lc,
            square_part: a,
            pairs,
            real_factors,
        })
    }

    /// The number of choices `2^(#pairs)` (which of `π`, `π̄` per splitting factor).
    pub fn num_choices(&self) -> usize {
        1usize
            .checked_shl(self.pairs.len() as u32)
            .unwrap_or(usize::MAX)
    }

    /// `true` if a rational decomposition exists (module docs).
    pub fn is_rational(&self) -> bool {
        self.real_factors.is_empty() && matches!(rational_two_squares(&self.lc), Some(Some(_)))
    }

    fn half(&self, choice: usize) -> GaussPoly {
        self.pairs
            .iter()
            .enumerate()
            .fold(GaussPoly::constant(Complex::one()), |acc, (k, h)| {
                let pick = if (choice >> k) & 1 == 1 {
                    conj_poly(h)
                } else {
                    h.clone()
                };
                &acc * &pick
            })
    }

    /// The decomposition for the given choice (bit `k` picks `π̄ₖ` instead of `πₖ`).
    ///
    /// # Errors
    /// [`CanalError::NeedsLargerExtension`] when one quadratic field does not suffice
    /// (module docs).
    pub fn decompose(&self, choice: usize) -> Result<SumOfSquares, CanalError> {
        let h = self.half(choice);
        let a = self.square_part.map(|x| Complex::from_real(x.clone()));
        let ah = &a * &h;
        let lc_rep = rational_two_squares(&self.lc).flatten();
        if self.real_factors.is_empty() {
            if let Some((x, y)) = lc_rep {
                let g = ah.scale(&Complex::new(x, y));
                let (g1, g2) = re_im_polys(&g);
                return Ok(SumOfSquares::Rational { g1, g2 });
            }
            let r = sqrt_in_extension(&self.lc)?;
            let radicand = split_square(&self.lc).1;
            let (re, im) = re_im_polys(&ah);
            let e = |p: &Poly<Rational>| p.map(|x| QuadExt::rational(x.clone())).scale(&r);
            return Ok(SumOfSquares::Extension {
                radicand,
                g1: e(&re),
                g2: e(&im),
            });
        }
        // real factors: all quadratic with one square class of δ
        let mut d: Option<Rational> = None;
        let mut lin: Vec<Poly<Complex<QuadExt>>> = Vec::new();
        for f in &self.real_factors {
            if f.degree() != Some(2) {
                return Err(CanalError::NeedsLargerExtension(format!(
                    "the factor {} of D (odd multiplicity) is irreducible over Q(i) of degree {}: its roots need more than a quadratic extension",
                    fmt_poly(f),
                    f.degree().unwrap_or(0)
                )));
            }
            let (b, e) = (f.coeff(1), f.coeff(0));
            let delta = Rational::from(4) * e - b.clone() * b.clone();
            let (c, sq) = split_square(&delta);
            match &d {
                None => d = Some(sq.clone()),
                Some(d0) if *d0 == sq => {}
                Some(d0) => {
                    return Err(CanalError::NeedsLargerExtension(format!(
                        "the quadratic factors of D need the fields Q(√{}) and Q(√{})",
                        format_scalar(d0),
                        format_scalar(&sq)
                    )))
                }
            }
            let half = Rational::from_ratio(1, 2);
            let im = QuadExt::new(Rational::ZERO, c * half.clone(), sq)?;
            lin.push(Poly::new(vec![
                Complex::new(QuadExt::rational(b * half), im),
                Complex::one(),
            ]));
        }
        let d = d.unwrap_or(Rational::ONE);
        let alpha = if let Some((x, y)) = lc_rep {
            Complex::new(QuadExt::rational(x), QuadExt::rational(y))
        } else if let Some(Some((x, y))) = rational_two_squares(&(self.lc.clone() / d.clone())) {
            let sd = QuadExt::sqrt_d(&d)?;
            Complex::new(sd.clone() * QuadExt::rational(x), sd * QuadExt::rational(y))
        } else {
            return Err(CanalError::NeedsLargerExtension(format!(
                "the leading coefficient {} is not a sum of two squares over Q(√{})",
                format_scalar(&self.lc),
                format_scalar(&d)
            )));
        };
        let to_ext = |p: &GaussPoly| -> Poly<Complex<QuadExt>> {
            p.map(|c| {
                Complex::new(
                    QuadExt::rational(c.re.clone()),
                    QuadExt::rational(c.im.clone()),
                )
            })
        };
        let g = lin
            .iter()
            .fold(to_ext(&ah), |acc, l| &acc * l)
            .scale(&alpha);
        let (g1, g2) = re_im_polys(&g);
        Ok(SumOfSquares::Extension {
            radicand: d,
            g1,
            g2,
        })
    }
}

fn fmt_poly(p: &Poly<Rational>) -> String {
    let terms: Vec<String> = p
        .coeffs()
        .iter()
        .enumerate()
        .filter(|(_, c)| !c.is_zero())
        .map(|(k, c)| match k {
            0 => format_scalar(c),
            1 => format!("{}·t", format_scalar(c)),
            _ => format!("{}·t^{k}", format_scalar(c)),
        })
        .collect();
    if terms.is_empty() {
        "0".into()
    } else {
        terms.join(" + ")
    }
}

/// `D = g₁² + g₂²` (module docs): over `Q` if possible, else over one quadratic field.
///
/// # Errors
/// As [`GaussianSplit::new`] and [`GaussianSplit::decompose`].
pub fn sum_of_two_squares(d: &Poly<Rational>) -> Result<SumOfSquares, CanalError> {
    GaussianSplit::new(d)?.decompose(0)
}

/// `D = g₁² + g₂²` in `f64`. The `f64` coefficients are exact binary rationals, so the
/// square-free decomposition `D = c·A²·S` is computed exactly (multiple roots are the
/// ill-conditioned part of root finding); the simple, non-real roots of `S` are found by
/// Durand–Kerner and the split is `g₁ + ig₂ = √c·A·∏_{Im z > 0}(t − z)`. Approximate; the
/// caller states it.
///
/// # Errors
/// [`CanalError::DegenerateSpine`] for the zero polynomial, [`CanalError::NoRealEnvelope`]
/// if `D` is negative somewhere, [`CanalError::InvalidArgument`] for non-finite
/// coefficients or roots that do not separate.
pub fn sum_of_two_squares_f64(d: &Poly<f64>) -> Result<(Poly<f64>, Poly<f64>), CanalError> {
    let dq: Poly<Rational> = Poly::new(
        d.coeffs()
            .iter()
            .map(|x| {
                Scalar::to_rational(x).ok_or_else(|| {
                    CanalError::InvalidArgument("D has a non-finite coefficient".into())
                })
            })
            .collect::<Result<Vec<_>, _>>()?,
    );
    sum_of_two_squares_approx(&dq)
}

/// `D = g₁² + g₂²` in `f64` for an exact `D`: exact square-free decomposition, numerical
/// roots of the square-free odd part only (see [`sum_of_two_squares_f64`]).
///
/// # Errors
/// As [`sum_of_two_squares_f64`].
pub fn sum_of_two_squares_approx(
    dq: &Poly<Rational>,
) -> Result<(Poly<f64>, Poly<f64>), CanalError> {
    if dq.is_zero() {
        return Err(CanalError::DegenerateSpine("D ≡ 0".into()));
    }
    if let Some(neg) = negative_interval(dq, None)? {
        return Err(neg);
    }
    let lc = Scalar::to_f64(&dq.leading());
    let mut a = Poly::constant(Rational::ONE);
    let mut s = Poly::constant(Rational::ONE);
    for (f, k) in square_free_decomposition(dq) {
        a = &a * &f.pow((k / 2) as u32);
        if k % 2 == 1 {
            s = &s * &f;
        }
    }
    let sf = s.map(Scalar::to_f64);
    let roots = durand_kerner(&sf)?;
    let scale = roots.iter().map(|z| z.norm_sq().sqrt()).fold(1.0, f64::max);
    let upper: Vec<Complex<f64>> = roots
        .iter()
        .filter(|z| z.im > 1e-12 * scale)
        .cloned()
        .collect();
    let n = s.degree().unwrap_or(0);
    if 2 * upper.len() != n {
        return Err(CanalError::InvalidArgument(
            "the roots of the square-free part of D do not separate into conjugate pairs in f64"
                .into(),
        ));
    }
    let h = upper
        .iter()
        .fold(Poly::constant(Complex::new(lc.sqrt(), 0.0)), |acc, z| {
            &acc * &Poly::new(vec![-z.clone(), Complex::new(1.0, 0.0)])
        });
    let af = a.map(|x| Complex::new(Scalar::to_f64(x), 0.0));
    Ok(re_im_polys(&(&h * &af)))
}

/// Durand–Kerner iteration followed by Newton polishing (for simple roots).
fn durand_kerner(p: &Poly<f64>) -> Result<Vec<Complex<f64>>, CanalError> {
    let n = p.degree().unwrap_or(0);
    if n == 0 {
        return Ok(Vec::new());
    }
    let lc = p.leading();
    let c: Vec<Complex<f64>> = p
        .coeffs()
        .iter()
        .map(|x| Complex::new(x / lc, 0.0))
        .collect();
    let eval = |z: &Complex<f64>| {
        c.iter()
            .rev()
            .fold(Complex::new(0.0, 0.0), |acc, a| acc * z.clone() + a.clone())
    };
    let radius = 1.0
        + c.iter()
            .take(n)
            .map(|z| z.norm_sq().sqrt())
            .fold(0.0, f64::max);
    let mut z: Vec<Complex<f64>> = (0..n)
        .map(|k| {
            let a = 2.0 * core::f64::consts::PI * (k as f64 + 0.25) / n as f64;
            Complex::new(radius * 0.9 * a.cos(), radius * 0.9 * a.sin())
        })
        .collect();
    for _ in 0..2000 {
        let mut delta: f64 = 0.0;
        for i in 0..n {
            let mut den = Complex::new(1.0, 0.0);
            for j in 0..n {
                if i != j {
                    den *= z[i].clone() - z[j].clone();
                }
            }
            if den.norm_sq() == 0.0 {
                den = Complex::new(1e-300, 0.0);
            }
            let step = eval(&z[i]) / den;
            delta = delta.max(step.norm_sq().sqrt());
            z[i] = z[i].clone() - step;
        }
        if delta < 1e-15 * radius {
            break;
        }
    }
    let dc: Vec<Complex<f64>> = c
        .iter()
        .enumerate()
        .skip(1)
        .map(|(k, a)| a.clone() * Complex::new(k as f64, 0.0))
        .collect();
    let deval = |z: &Complex<f64>| {
        dc.iter()
            .rev()
            .fold(Complex::new(0.0, 0.0), |acc, a| acc * z.clone() + a.clone())
    };
    for w in z.iter_mut() {
        for _ in 0..8 {
            let dv = deval(w);
            if dv.norm_sq() == 0.0 {
                break;
            }
            let step = eval(w) / dv;
            *w = w.clone() - step;
        }
    }
    if z.iter().any(|w| !w.re.is_finite() || !w.im.is_finite()) {
        return Err(CanalError::InvalidArgument(
            "the root finder did not converge".into(),
        ));
    }
    Ok(z)
}

// ----------------------------------------------------------------------------------------
// sums of two squares of rational numbers
// ----------------------------------------------------------------------------------------

/// `q = x² + y²` with rational `x, y`: `Some(Some((x, y)))`, `Some(None)` if impossible,
/// `None` if undecided (a prime cofactor beyond `2⁶⁴`).
pub fn rational_two_squares(q: &Rational) -> Option<Option<(Rational, Rational)>> {
    if *q < Rational::ZERO {
        return Some(None);
    }
    if q.is_zero() {
        return Some(Some((Rational::ZERO, Rational::ZERO)));
    }
    let num = u128::try_from(q.numerator()).ok()?;
    let den = u128::try_from(q.denominator()).ok()?;
    let n = num.checked_mul(den)?;
    let (x, y) = match int_two_squares(n)? {
        Some(r) => r,
        None => return Some(None),
    };
    let dq = Rational::from(den);
    Some(Some((x / dq.clone(), y / dq)))
}

/// `n = x² + y²` over the integers (as rationals).
fn int_two_squares(n: u128) -> Option<Option<(Rational, Rational)>> {
    let mut m = n;
    let mut factors: Vec<(u128, u32)> = Vec::new();
    let mut p: u128 = 2;
    while p <= 1 << 16 && p * p <= m {
        if m.is_multiple_of(p) {
            let mut e = 0;
            while m.is_multiple_of(p) {
                m /= p;
                e += 1;
            }
            factors.push((p, e));
        }
        p += if p == 2 { 1 } else { 2 };
    }
    if m > 1 {
        let m64 = u64::try_from(m).ok()?;
        let mut big = Vec::new();
        split_u64(m64, &mut big);
        big.sort_unstable();
        for q in big {
            match factors.iter_mut().find(|(f, _)| *f == q as u128) {
                Some((_, e)) => *e += 1,
                None => factors.push((q as u128, 1)),
            }
        }
    }
    let mut acc = (Rational::ONE, Rational::ZERO);
    for (p, e) in factors {
        let mul = |acc: (Rational, Rational), (c, d): (Rational, Rational)| {
            (
                acc.0.clone() * c.clone() - acc.1.clone() * d.clone(),
                acc.0 * d + acc.1 * c,
            )
        };
        if p == 2 {
            for _ in 0..e {
                acc = mul(acc, (Rational::ONE, Rational::ONE));
            }
        } else if p % 4 == 3 {
            if e % 2 == 1 {
                return Some(None);
            }
            let f = Rational::from(p).pow((e / 2) as isize);
            acc = (acc.0 * f.clone(), acc.1 * f);
        } else {
            let p64 = u64::try_from(p).ok()?;
            let (a, b) = prime_two_squares(p64)?;
            for _ in 0..e {
                acc = mul(acc, (Rational::from(a), Rational::from(b)));
            }
        }
    }
    Some(Some(acc))
}

fn mul_mod(a: u64, b: u64, m: u64) -> u64 {
    ((a as u128 * b as u128) % m as u128) as u64
}

fn pow_mod64(mut b: u64, mut e: u64, m: u64) -> u64 {
    let mut r = 1 % m;
    b %= m;
    while e > 0 {
        if e & 1 == 1 {
            r = mul_mod(r, b, m);
        }
        b = mul_mod(b, b, m);
        e >>= 1;
    }
    r
}

fn is_prime_u64(n: u64) -> bool {
    if n < 2 {
        return false;
    }
    for p in [2u64, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37] {
        if n.is_multiple_of(p) {
            return n == p;
        }
    }
    let (mut d, mut s) = (n - 1, 0);
    while d % 2 == 0 {
        d /= 2;
        s += 1;
    }
    'outer: for a in [2u64, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37] {
        let mut x = pow_mod64(a, d, n);
        if x == 1 || x == n - 1 {
            continue;
        }
        for _ in 1..s {
            x = mul_mod(x, x, n);
            if x == n - 1 {
                continue 'outer;
            }
        }
        return false;
    }
    true
}

fn gcd_u64(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        let r = a % b;
        a = b;
        b = r;
    }
    a
}

fn pollard_rho(n: u64) -> u64 {
    if n.is_multiple_of(2) {
        return 2;
    }
    for c in 1..100u64 {
        let f = |x: u64| (mul_mod(x, x, n) + c) % n;
        let (mut x, mut y, mut d) = (2u64, 2u64, 1u64);
        while d == 1 {
            x = f(x);
            y = f(f(y));
            d = gcd_u64(x.abs_diff(y), n);
        }
        if d != n {
            return d;
        }
    }
    n
}

fn split_u64(n: u64, out: &mut Vec<u64>) {
    if n == 1 {
        return;
    }
    if is_prime_u64(n) {
        out.push(n);
        return;
    }
    let d = pollard_rho(n);
    if d == n || d == 1 {
        out.push(n);
        return;
    }
    split_u64(d, out);
    split_u64(n / d, out);
}

fn isqrt_u64(n: u64) -> u64 {
    let mut x = (n as f64).sqrt() as u64;
    while x.checked_mul(x).is_none_or(|v| v > n) {
        x -= 1;
    }
    while (x + 1).checked_mul(x + 1).is_some_and(|v| v <= n) {
        x += 1;
    }
    x
}

/// `p = a² + b²` for a prime `p ≡ 1 (mod 4)` (Hermite–Serret).
fn prime_two_squares(p: u64) -> Option<(u64, u64)> {
    let c = (2..p.min(4096)).find(|&c| pow_mod64(c, (p - 1) / 2, p) == p - 1)?;
    let r = pow_mod64(c, (p - 1) / 4, p);
    let (mut a, mut b) = (p, r);
    let lim = isqrt_u64(p);
    while b > lim {
        let t = a % b;
        a = b;
        b = t;
    }
    let rest = p - b * b;
    let y = isqrt_u64(rest);
    (y * y == rest).then_some((b, y))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(c: &[i64]) -> Poly<Rational> {
        Poly::from_ints(c)
    }
    fn q(n: i64, d: i64) -> Rational {
        Rational::from_ratio(n, d)
    }

    #[test]
    fn rational_numbers() {
        for (n, ok) in [
            (5, true),
            (3, false),
            (9, true),
            (12, false),
            (50, true),
            (21, false),
        ] {
            let r = rational_two_squares(&Rational::from(n)).expect("decided");
            assert_eq!(r.is_some(), ok, "{n}");
            if let Some((x, y)) = r {
                assert_eq!(x.clone() * x + y.clone() * y, Rational::from(n));
            }
        }
        let r = rational_two_squares(&q(5, 9))
            .expect("decided")
            .expect("sos");
        assert_eq!(r.0.clone() * r.0 + r.1.clone() * r.1, q(5, 9));
        // a large prime ≡ 1 mod 4
        let big = Rational::from(1_000_000_009i64 * 13);
        let r = rational_two_squares(&big).expect("decided");
        assert!(r.is_some());
    }

    #[test]
    fn polynomial_decompositions() {
        // 4 + 4t² = 2² + (2t)²
        let d = p(&[4, 0, 4]);
        let s = sum_of_two_squares(&d).expect("sos");
        assert!(matches!(s, SumOfSquares::Rational { .. }));
        assert!(s.verifies(&d));
        // (t² + 1)(t² + 4)·(t − 3)²·5
        let d = &(&(&p(&[1, 0, 1]) * &p(&[4, 0, 1])) * &p(&[9, -6, 1])) * &p(&[5]);
        let s = sum_of_two_squares(&d).expect("sos");
        assert!(matches!(s, SumOfSquares::Rational { .. }));
        assert!(s.verifies(&d));
        // seed 003 §2.3: D = 1 + (15/4)t² needs Q(√15)
        let d = Poly::new(vec![Rational::ONE, Rational::ZERO, q(15, 4)]);
        let s = sum_of_two_squares(&d).expect("sos");
        assert_eq!(s.radicand(), Some(&Rational::from(15)));
        assert!(s.verifies(&d));
        // 3(t² + 1): constant not a sum of two squares → Q(√3)
        let d = p(&[3, 0, 3]);
        let s = sum_of_two_squares(&d).expect("sos");
        assert_eq!(s.radicand(), Some(&Rational::from(3)));
        assert!(s.verifies(&d));
        // (t² + 2)(t² + 3): two square classes → larger extension
        let d = &p(&[2, 0, 1]) * &p(&[3, 0, 1]);
        assert!(matches!(
            sum_of_two_squares(&d),
            Err(CanalError::NeedsLargerExtension(_))
        ));
        // t⁴ + 2: irreducible over Q(i) of degree 4
        assert!(matches!(
            sum_of_two_squares(&p(&[2, 0, 0, 0, 1])),
            Err(CanalError::NeedsLargerExtension(_))
        ));
        // negative somewhere
        assert!(matches!(
            sum_of_two_squares(&p(&[-1, 0, 1])),
            Err(CanalError::NoRealEnvelope { .. })
        ));
        // t⁴ + 1 = |t² + i|²
        let d = p(&[1, 0, 0, 0, 1]);
        let s = sum_of_two_squares(&d).expect("sos");
        assert!(matches!(s, SumOfSquares::Rational { .. }) && s.verifies(&d));
    }

    #[test]
    fn f64_path() {
        let d = Poly::new(vec![2.0, 0.0, 3.0, 0.0, 1.0]); // (t²+1)(t²+2)
        let (g1, g2) = sum_of_two_squares_f64(&d).expect("f64");
        let s = &(&g1 * &g1) + &(&g2 * &g2);
        for (a, b) in s.coeffs().iter().zip(d.coeffs()) {
            assert!((a - b).abs() < 1e-9, "{a} vs {b}");
        }
    }
}
