//! A non-negative polynomial as a sum of two squares, `D = g₁² + g₂²` over `Q[t]` or over
//! one real quadratic field (D. Gruber, "Rationale Parametrisierungen von
//! Kugelhüllflächen", 2008, §2.1 before (2.14): every `f ≥ 0` is `f₁² + f₂²`; M. Peternell,
//! "Rational Parametrizations for Envelopes of Quadric Families", (4.9)). This is the
//! special case `X² + Y² = D·Z²` with `Z = 1` of the conic-point engine
//! ([`crate::conic_point`]); see `docs/math/conic-surfaces.md`.
//!
//! `D = g₁² + g₂² = |g₁ + i g₂|²` means `D = h·h̄` for `h ∈ K(i)[t]`. The decomposition is
//! computed from the factorization over `Q(i)` ([`crate::factor`]):
//!
//! 1. square-free decomposition `D = c · A² · S` (`A = ∏ fₖ^{⌊k/2⌋}`, `S = ∏_{k odd} fₖ`
//!    square-free, monic); `D ≥ 0` on `R` forces `S` to have no real roots and `c > 0`;
//! 2. factor `S` over `Q(i)`: every `Q`-irreducible factor `p` of `S` either splits,
//!    `p = π π̄` (choose `π` or `π̄`: these are the choices of the decomposition, the
//!    `∏ (pᵢ + 1)` factorizations of Gruber (2.35)), or stays irreducible ("real" factors);
//! 3. the constant `c` is a sum of two rational squares iff the conic `X² + Y² = cZ²` has
//!    a rational point ([`crate::conic_point::rational_conic_point`], Legendre's theorem);
//!    any such point has `Z ≠ 0`.
//!
//! **Exact cases.**
//!
//! * **Over `Q`** ([`SumOfSquares::Rational`]) — exactly when `S` has no real factors and `c`
//!   is a sum of two rational squares: `g₁ + i g₂ = (x + iy)·A·∏π`. This decision is
//!   complete: if no rational decomposition is reported, none exists (a sum of two squares
//!   in `Q(t)` is one in `Q[t]`, and `Q(i)[t]` is a UFD). A constant whose integer parts
//!   resist factorization is reported as undecided ([`SumOfSquaresError::Undecided`]).
//! * **Over one real quadratic field `Q(√d)`** ([`SumOfSquares::Extension`]): (a) `S` has no
//!   real factors but `c` is not a sum of two rational squares: `g = √c·A·∏π`,
//!   `d = sqf(c)`; (b) every real factor is a quadratic `t² + bt + e` whose
//!   `δ = 4e − b² > 0` has one common square class `d`: `t² + bt + e = |t + b/2 + i√δ/2|²`,
//!   and `c` (or `c/d`) is a sum of two rational squares.
//! * Otherwise (a real factor of degree ≥ 4, or several square classes) the roots generate a
//!   larger field: [`SumOfSquaresError::NeedsLargerExtension`].

use crate::complex::{conj_poly, re_im_polys, Complex};
use crate::conic_point::{rational_conic_point, ConicPointError, TernaryOutcome};
use crate::factor::{factor_gaussian, GaussPoly};
use crate::quadratic::{split_square, sqrt_in_extension};
use crate::roots::{isolate_real_roots, square_free_decomposition};
use crate::scalar::{format_poly, format_scalar, Scalar};
use crate::{AlgebraError, Poly, QuadExt, Rational};
use num_traits::One;
use thiserror::Error;

/// Why `D` has no decomposition (or none that this module constructs).
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum SumOfSquaresError {
    /// `D ≡ 0`.
    #[error("the zero polynomial")]
    Zero,
    /// `D` is negative somewhere (a real root of odd multiplicity, or a negative leading
    /// coefficient), so it is no sum of real squares.
    #[error("D is negative somewhere: {0}")]
    Negative(String),
    /// `D` is not a sum of two squares over `Q` and no single quadratic extension suffices.
    #[error("needs more than one quadratic extension: {0}")]
    NeedsLargerExtension(String),
    /// The exact factorization gave up.
    #[error("factorization: {0}")]
    Factorization(String),
    /// An integer could not be factored (the rational-squares question is undecided).
    #[error("{0}")]
    Undecided(#[from] ConicPointError),
    /// An algebra failure.
    #[error(transparent)]
    Algebra(#[from] AlgebraError),
}

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
    /// [`SumOfSquaresError::Zero`] for `D ≡ 0`, [`SumOfSquaresError::Negative`] if `D` is
    /// negative somewhere, [`SumOfSquaresError::Factorization`] if the exact factorization
    /// gives up.
    pub fn new(d: &Poly<Rational>) -> Result<Self, SumOfSquaresError> {
        if d.is_zero() {
            return Err(SumOfSquaresError::Zero);
        }
        let lc = d.leading();
        if lc < Rational::ZERO {
            return Err(SumOfSquaresError::Negative(format!(
                "the leading coefficient {} is negative",
                format_scalar(&lc)
            )));
        }
        let mut a = Poly::constant(Rational::ONE);
        let mut s_parts = Vec::new();
        for (f, k) in square_free_decomposition(d) {
            a = &a * &f.pow((k / 2) as u32);
            if k % 2 == 1 {
                s_parts.push(f);
            }
        }
        let s = product(&s_parts);
        let real = isolate_real_roots(&s)?;
        if let Some(iv) = real.first() {
            return Err(SumOfSquaresError::Negative(format!(
                "a real root of odd multiplicity in [{}, {}]",
                format_scalar(&iv.lo),
                format_scalar(&iv.hi)
            )));
        }
        let mut pairs = Vec::new();
        let mut real_factors = Vec::new();
        if s.degree().is_some_and(|n| n > 0) {
            let facs =
                factor_gaussian(&s).map_err(|e| SumOfSquaresError::Factorization(e.to_string()))?;
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
        self.real_factors.is_empty() && matches!(rational_two_squares(&self.lc), Ok(Some(_)))
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
    /// [`SumOfSquaresError::NeedsLargerExtension`] when one quadratic field does not suffice
    /// (module docs).
    pub fn decompose(&self, choice: usize) -> Result<SumOfSquares, SumOfSquaresError> {
        let h = self.half(choice);
        let a = self.square_part.map(|x| Complex::from_real(x.clone()));
        let ah = &a * &h;
        let lc_rep = rational_two_squares(&self.lc)?;
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
                return Err(SumOfSquaresError::NeedsLargerExtension(format!(
                    "the factor {} of D (odd multiplicity) is irreducible over Q(i) of degree {}: its roots need more than a quadratic extension",
                    format_poly(f, "t"),
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
                    return Err(SumOfSquaresError::NeedsLargerExtension(format!(
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
        } else if let Some((x, y)) = rational_two_squares(&(self.lc.clone() / d.clone()))? {
            let sd = QuadExt::sqrt_d(&d)?;
            Complex::new(sd.clone() * QuadExt::rational(x), sd * QuadExt::rational(y))
        } else {
            return Err(SumOfSquaresError::NeedsLargerExtension(format!(
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

/// `D = g₁² + g₂²` (module docs): over `Q` if possible, else over one quadratic field.
///
/// # Errors
/// As [`GaussianSplit::new`] and [`GaussianSplit::decompose`].
pub fn sum_of_two_squares(d: &Poly<Rational>) -> Result<SumOfSquares, SumOfSquaresError> {
    GaussianSplit::new(d)?.decompose(0)
}

/// `q = x² + y²` with rational `x, y`: `Some((x, y))`, or `None` if impossible (the conic
/// `X² + Y² = qZ²` has no rational point; module docs).
///
/// # Errors
/// [`SumOfSquaresError::Undecided`] when an integer resists factorization.
pub fn rational_two_squares(
    q: &Rational,
) -> Result<Option<(Rational, Rational)>, SumOfSquaresError> {
    if *q < Rational::ZERO {
        return Ok(None);
    }
    if q.is_zero() {
        return Ok(Some((Rational::ZERO, Rational::ZERO)));
    }
    match rational_conic_point(&Rational::ONE, &Rational::ONE, &-q.clone())? {
        TernaryOutcome::Point([x, y, z]) if !z.is_zero() => Ok(Some((x / z.clone(), y / z))),
        TernaryOutcome::Point(_) => {
            Err(ConicPointError::Internal("a point of X² + Y² = qZ² with Z = 0".into()).into())
        }
        TernaryOutcome::NoPoint(_) => Ok(None),
    }
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
        let big = Rational::from(1_000_000_009i64 * 13);
        assert!(rational_two_squares(&big).expect("decided").is_some());
    }

    #[test]
    fn polynomial_decompositions() {
        // t² + 9 = t² + 3²
        let d = p(&[9, 0, 1]);
        let s = sum_of_two_squares(&d).expect("sos");
        assert!(matches!(s, SumOfSquares::Rational { .. }) && s.verifies(&d));
        let d = &(&(&p(&[1, 0, 1]) * &p(&[4, 0, 1])) * &p(&[9, -6, 1])) * &p(&[5]);
        let s = sum_of_two_squares(&d).expect("sos");
        assert!(matches!(s, SumOfSquares::Rational { .. }) && s.verifies(&d));
        // 1 + (15/4)t² needs Q(√15)
        let d = Poly::new(vec![Rational::ONE, Rational::ZERO, q(15, 4)]);
        let s = sum_of_two_squares(&d).expect("sos");
        assert_eq!(s.radicand(), Some(&Rational::from(15)));
        assert!(s.verifies(&d));
        let d = &p(&[2, 0, 1]) * &p(&[3, 0, 1]);
        assert!(matches!(
            sum_of_two_squares(&d),
            Err(SumOfSquaresError::NeedsLargerExtension(_))
        ));
        assert!(matches!(
            sum_of_two_squares(&p(&[2, 0, 0, 0, 1])),
            Err(SumOfSquaresError::NeedsLargerExtension(_))
        ));
        assert!(matches!(
            sum_of_two_squares(&p(&[-1, 0, 1])),
            Err(SumOfSquaresError::Negative(_))
        ));
        let d = p(&[1, 0, 0, 0, 1]);
        let s = sum_of_two_squares(&d).expect("sos");
        assert!(matches!(s, SumOfSquares::Rational { .. }) && s.verifies(&d));
    }
}
