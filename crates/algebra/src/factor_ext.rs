//! Exact factorization over the biquadratic field `K = Q(√d, i) = Q(√d)(i)` (`d > 0` not a
//! square) and the real roots of polynomials over `Q(√d)`: the tools of Krasauskas'
//! reduction over `Q(√d)` (D. Gruber, "Rationale Parametrisierungen von
//! Kugelhüllflächen", 2008, §2.4.2, step (2.36) needs the irreducible factors of
//! `det(a, b)` over the coefficient field).
//!
//! **Norms.** `K` has the four automorphisms `id`, `z ↦ z̄` (complex conjugation),
//! `σ: √d ↦ −√d`, and both; the norm `N(l) = l · l̄ · σ(l) · σ(l̄)` of `l ∈ K[t]` lies in `Q[t]`.
//!
//! **Factorization** (Trager, "Algebraic factoring and rational function integration",
//! SYMSAC 1976, with the primitive element `θ = √d + i` of degree 4). For `l ∈ K[t]`:
//! 1. the square-free part `l*` of `l`; its norm `N(l*)` is factored over `Q`
//!    ([`crate::factor::factor_rational`]): every `K`-irreducible factor of `l` divides
//!    exactly one `Q`-irreducible factor `p` of the norm;
//! 2. each such `p` is factored over `K` by Trager's method: the smallest `k = 1, 2, …`
//!    with `N(p(t − kθ))` square-free, `N(p(t − kθ)) = ∏ Nⱼ` over `Q`,
//!    `gⱼ = gcd_K(p(t − kθ), Nⱼ)` are the `K`-irreducible factors of `p(t − kθ)`, and
//!    `gⱼ(t + kθ)` those of `p`;
//! 3. the factors of `l` are those `K`-factors of the `p` that divide `l`.
//!
//! The result is complete when every Zassenhaus factorization over `Q` succeeds. When one
//! gives up (more than [`crate::factor::MAX_MODULAR_FACTORS`] modular factors), step 2 is
//! replaced for that `p` by the factors over `Q(i)` ([`crate::factor::factor_gaussian`])
//! and by `gcd_K(l, p)`: these divide `l` but may be reducible over `K` — the factors *not
//! found* are then exactly the `K`-irreducible pieces of such a gcd.

use crate::complex::{conj_poly, Complex};
use crate::factor::{factor_gaussian, factor_rational, primitive_int, FactorError};
use crate::roots::isolate_real_roots;
use crate::{AlgebraError, Poly, QuadExt, Rational};
use core::cmp::Ordering;
use num_traits::{One, Zero};

/// A polynomial over `K = Q(√d)(i)`.
pub type BiquadPoly = Poly<Complex<QuadExt>>;

/// The result of [`factor_biquadratic`]: the irreducible factors found, and whether the
/// list is complete (every factor irreducible over `K`).
#[derive(Debug, Clone, PartialEq)]
pub struct BiquadFactors {
    /// Monic factors of `l` over `K`, pairwise distinct; with `complete`, irreducible.
    pub factors: Vec<BiquadPoly>,
    /// `true` if every `Q`-factorization succeeded (then `factors` are the `K`-irreducible
    /// factors of `l`, without multiplicity).
    pub complete: bool,
}

fn q(x: Rational) -> QuadExt {
    QuadExt::rational(x)
}

/// `x` as an element of `K` (`x ∈ Q`).
fn kq(x: Rational) -> Complex<QuadExt> {
    Complex::from_real(q(x))
}

/// `σ`: `√d ↦ −√d` on the coefficients.
fn sigma(p: &BiquadPoly) -> BiquadPoly {
    p.map(|c| Complex::new(c.re.conj(), c.im.conj()))
}

/// `p ∈ Q[t]` as a polynomial over `K`.
pub fn to_biquad(p: &Poly<Rational>) -> BiquadPoly {
    p.map(|c| kq(c.clone()))
}

/// `p ∈ Q(i)[t]` as a polynomial over `K`.
pub fn gauss_to_biquad(p: &Poly<Complex<Rational>>) -> BiquadPoly {
    p.map(|c| Complex::new(q(c.re.clone()), q(c.im.clone())))
}

/// The norm `l · l̄ · σ(l) · σ(l̄) ∈ Q[t]` (module docs).
///
/// # Errors
/// [`AlgebraError::InvalidArgument`] if a coefficient of the product is not rational
/// (coefficients from different quadratic fields).
pub fn biquad_norm(l: &BiquadPoly) -> Result<Poly<Rational>, AlgebraError> {
    let n1 = l * &conj_poly(l);
    let n2 = &n1 * &sigma(&n1);
    let coeffs = n2
        .coeffs()
        .iter()
        .map(|c| {
            if !c.im.is_zero() {
                return None;
            }
            c.re.to_rational()
        })
        .collect::<Option<Vec<_>>>()
        .ok_or_else(|| {
            AlgebraError::InvalidArgument(
                "the norm over Q(√d, i) has an irrational coefficient: the coefficients lie in different quadratic fields".into(),
            )
        })?;
    Ok(Poly::new(coeffs))
}

fn shift(p: &BiquadPoly, c: &Complex<QuadExt>) -> BiquadPoly {
    p.compose(&Poly::new(vec![c.clone(), Complex::one()]))
}

fn is_square_free(p: &Poly<Rational>) -> bool {
    p.gcd(&p.derivative()).degree() == Some(0)
}

/// The `K`-irreducible factors of an irreducible `p ∈ Q[t]` (module docs, step 2).
///
/// # Errors
/// From the factorization over `Q` ([`FactorError`]).
pub fn factor_irreducible_over_biquad(
    p: &Poly<Rational>,
    d: &Rational,
) -> Result<Vec<BiquadPoly>, FactorError> {
    let n = p.degree().ok_or(FactorError::Zero)?;
    let pk = to_biquad(p);
    if n <= 1 {
        return Ok(vec![pk.monic()]);
    }
    let Ok(sd) = QuadExt::sqrt_d(d) else {
        return Err(FactorError::NoGoodPrime);
    };
    let theta = Complex::new(sd, QuadExt::one());
    for k in 1..32i64 {
        let c = theta.scale(&QuadExt::from(k));
        let g = shift(&pk, &-c.clone()); // p(t − kθ)
        let Ok(norm) = biquad_norm(&g) else {
            return Err(FactorError::NoGoodPrime);
        };
        if !is_square_free(&norm) {
            continue;
        }
        let (_, parts) = factor_rational(&norm)?;
        let mut out = Vec::new();
        for (nj, _) in parts {
            let gj = g.gcd(&to_biquad(&nj));
            if gj.degree().is_some_and(|e| e > 0) {
                out.push(shift(&gj, &c).monic());
            }
        }
        return Ok(out);
    }
    Err(FactorError::NoGoodPrime)
}

fn divides(f: &BiquadPoly, l: &BiquadPoly) -> bool {
    l.div_rem(f).is_ok_and(|(_, r)| r.is_zero())
}

/// The monic irreducible factors of `l ≠ 0` over `K = Q(√d)(i)` (module docs), with a flag
/// saying whether the list is complete. A constant `l` has no factors.
///
/// # Errors
/// [`AlgebraError::InvalidArgument`] for `l = 0`, a radicand that is not a positive
/// non-square, or coefficients outside `Q(√d)(i)`.
pub fn factor_biquadratic(l: &BiquadPoly, d: &Rational) -> Result<BiquadFactors, AlgebraError> {
    if l.is_zero() {
        return Err(AlgebraError::InvalidArgument(
            "the zero polynomial has no factorization".into(),
        ));
    }
    QuadExt::sqrt_d(d)?;
    let mut out = BiquadFactors {
        factors: Vec::new(),
        complete: true,
    };
    if l.degree().is_none_or(|e| e == 0) {
        return Ok(out);
    }
    let sf = match l.div_exact(&l.gcd(&l.derivative())) {
        Ok(s) => s,
        Err(_) => l.clone(),
    };
    let norm = biquad_norm(&sf)?;
    let push = |f: BiquadPoly, out: &mut BiquadFactors| {
        if f.degree().is_some_and(|e| e > 0) && divides(&f, l) && !out.factors.contains(&f) {
            out.factors.push(f);
        }
    };
    let primes: Vec<Poly<Rational>> = match factor_rational(&norm) {
        Ok((_, ps)) => ps.into_iter().map(|(p, _)| p).collect(),
        Err(_) => {
            // the norm itself resists: its square-free parts are the only Q-factors known
            out.complete = false;
            crate::roots::square_free_decomposition(&norm)
                .into_iter()
                .map(|(p, _)| p.monic())
                .collect()
        }
    };
    for p in primes {
        match factor_irreducible_over_biquad(&p, d) {
            Ok(fs) if out.complete || fs.len() > 1 => {
                for f in fs {
                    push(f, &mut out);
                }
            }
            _ => {
                out.complete = false;
                if let Ok(gs) = factor_gaussian(&primitive_int(&p)) {
                    for g in gs {
                        let gk = gauss_to_biquad(&g);
                        push(sf.gcd(&gk).monic(), &mut out);
                    }
                }
                push(sf.gcd(&to_biquad(&p)).monic(), &mut out);
            }
        }
    }
    Ok(out)
}

/// `g(x)` for `g ∈ Q(√d)[t]` at a rational `x`, exactly.
fn eval_quad(g: &Poly<QuadExt>, x: &Rational) -> QuadExt {
    g.eval(&q(x.clone()))
}

/// Whether `g ∈ Q(√d)[t]` (real coefficients) has a real root, decided exactly: the real
/// roots of `g` are among those of `g · σ(g) ∈ Q[t]`; on every isolating interval of that
/// norm the square-free part of `g` changes sign iff the root there is one of `g`.
///
/// # Errors
/// [`AlgebraError::InvalidArgument`] for `g = 0` or coefficients from different fields.
pub fn has_real_root_quad(g: &Poly<QuadExt>) -> Result<bool, AlgebraError> {
    if g.is_zero() {
        return Err(AlgebraError::InvalidArgument(
            "the zero polynomial vanishes everywhere".into(),
        ));
    }
    if g.degree().is_none_or(|e| e == 0) {
        return Ok(false);
    }
    let sf = match g.div_exact(&g.gcd(&g.derivative())) {
        Ok(s) => s,
        Err(_) => g.clone(),
    };
    let sg = sf.map(QuadExt::conj);
    let n = &sf * &sg;
    let nq = n
        .coeffs()
        .iter()
        .map(|c| c.to_rational())
        .collect::<Option<Vec<_>>>()
        .ok_or_else(|| {
            AlgebraError::InvalidArgument(
                "g · σ(g) has an irrational coefficient: coefficients from different quadratic fields".into(),
            )
        })?;
    for iv in isolate_real_roots(&Poly::new(nq))? {
        if iv.is_exact() {
            if eval_quad(&sf, &iv.lo).is_zero() {
                return Ok(true);
            }
            continue;
        }
        let (a, b) = (eval_quad(&sf, &iv.lo), eval_quad(&sf, &iv.hi));
        // no root of the norm at the endpoints, so a and b are non-zero
        if a.sign() != Ordering::Equal && b.sign() != Ordering::Equal && a.sign() != b.sign() {
            return Ok(true);
        }
    }
    Ok(false)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(c: &[i64]) -> Poly<Rational> {
        Poly::from_ints(c)
    }

    fn r(n: i64) -> Rational {
        Rational::from(n)
    }

    fn product(fs: &[BiquadPoly]) -> BiquadPoly {
        fs.iter()
            .fold(Poly::constant(Complex::one()), |a, b| &a * b)
    }

    #[test]
    fn splits_quadratics_of_the_field_into_linear_factors() {
        // (t² + 2t + 16)(t² + 1)(t² + 3): t² + 2t + 16 = (t + 1)² + 15 has roots −1 ± i√15,
        // t² + 1 = (t − i)(t + i); t² + 3 stays irreducible over Q(√15, i)
        let l = to_biquad(&(&(&p(&[16, 2, 1]) * &p(&[1, 0, 1])) * &p(&[3, 0, 1])));
        let f = factor_biquadratic(&l, &r(15)).expect("factor");
        assert!(f.complete);
        let degs: Vec<usize> = f.factors.iter().map(|x| x.degree().unwrap_or(0)).collect();
        assert_eq!(degs.iter().filter(|&&e| e == 1).count(), 4, "{degs:?}");
        assert_eq!(degs.iter().filter(|&&e| e == 2).count(), 1, "{degs:?}");
        assert_eq!(product(&f.factors), l.monic());
    }

    #[test]
    fn the_third_subfield_splits_too() {
        // t² + 5 = (t − i√5)(t + i√5) over Q(√5, i), irreducible over Q(√5) and Q(i)
        let l = to_biquad(&p(&[5, 0, 1]));
        let f = factor_biquadratic(&l, &r(5)).expect("factor");
        assert!(f.complete);
        assert_eq!(f.factors.len(), 2);
        // a non-rational Gaussian polynomial: (t − √5 − i)²(t + 2)
        let sd = QuadExt::sqrt_d(&r(5)).expect("√5");
        let lin = Poly::new(vec![Complex::new(-sd, -QuadExt::one()), Complex::one()]);
        let l = &(&lin * &lin) * &to_biquad(&p(&[2, 1]));
        let f = factor_biquadratic(&l, &r(5)).expect("factor");
        assert!(f.complete);
        assert_eq!(f.factors.len(), 2);
        assert!(f.factors.contains(&lin));
    }

    #[test]
    fn real_roots_over_a_quadratic_field() {
        let sd = QuadExt::sqrt_d(&r(2)).expect("√2");
        // t − √2: a real root; t² + √2: none; (t² − 2)(t + √2): yes
        let lin = Poly::new(vec![-sd.clone(), QuadExt::one()]);
        assert!(has_real_root_quad(&lin).expect("roots"));
        let pos = Poly::new(vec![sd.clone(), QuadExt::zero(), QuadExt::one()]);
        assert!(!has_real_root_quad(&pos).expect("roots"));
        // t² − √2 t + 1 (discriminant 2 − 4 < 0) times t² + 1: none
        let neg = Poly::new(vec![QuadExt::one(), -sd, QuadExt::one()]);
        let t21 = p(&[1, 0, 1]).map(|c| QuadExt::rational(c.clone()));
        assert!(!has_real_root_quad(&(&neg * &t21)).expect("roots"));
        assert!(has_real_root_quad(
            &(&neg * &p(&[-2, 0, 1]).map(|c| QuadExt::rational(c.clone())))
        )
        .expect("roots"));
    }
}
