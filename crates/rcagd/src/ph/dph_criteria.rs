//! The criteria of Besednjak, "DPH-krivulje in polinomske vijačnice", ch. 7 that decide
//! whether a DPH curve of degree 7 is a helix, as functions of its Hopf preimage
//! `(α, β)` (cubic), with `γ = gcd(α, β)` of degree `r` and the Hopf DPH form
//! `αβ' − α'β = λ·h·W²` (`h` the maximal real factor, `W` monic; see
//! [`super::ProportionalityFactors`]):
//!
//! * Lemma 7.1: a non-helical DPH curve has `r ≤ 1` (so `r ≥ 2` means a helix);
//! * Lemma 7.2: `r = 1` with `h` constant or a square is not DPH ([`lemma_7_2`]: the reduced
//!   Wronskian `α̃β̃' − α̃'β̃` is never `c·(t − τ)²`);
//! * Lemmas 7.3 and 7.5: `z = (a₁(t − τ₁)^m + a₂(t − τ₂)^m)/(b₁(t − τ₁)^m + b₂(t − τ₂)^m)`
//!   is a line or circle iff `τ₁, τ₂` are both real or complex conjugate (as functions in
//!   [`super::generalized_circle`]);
//! * Prop. 7.6 (`st h = 0`, `st w = 2`): non-helical iff the roots of `w` are neither both
//!   real nor conjugate (and `α, β` have the form (7.8), forced for `r = 0`). With `h`
//!   maximal, a monic `W` with real coefficients never occurs here (its square would be
//!   part of `h`), so `r = 0` means non-helical;
//! * Props. 7.7 and 7.8 (`st h = 2`, `st w = 1`): helical iff `r = 1`;
//! * Prop. 7.9 (`st h = 4`, `st w = 0`): helical iff
//!   `Δ = 9h₂² + 3h₀h₄ − 12h₁h₃ ≥ 0` for the Bernstein coefficients `h_k` of `h` ((7.11);
//!   the thesis' Examples 8.8/8.9 misprint `h₁h₄`). `Δ` scales by the square of a constant
//!   factor of `h`, so its sign does not depend on the normalization.
//!
//! The certificate compares the criterion's verdict with the exact axis test `a·r' ≡ σ`.

use super::helix::HelixTest;
use super::hodograph::PhCurve;
use super::PhError;
use num_traits::Zero;
use rcagd_algebra::complex::Complex;
use rcagd_algebra::{bernstein, Certificate, Poly, Rational};

type Q = Rational;

/// Which statement of ch. 7 decides the case.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Chapter7Statement {
    /// Lemma 7.1: `r = deg gcd(α, β) ≥ 2`, a helix.
    Lemma7_1,
    /// Prop. 7.6: `st h = 0`, `st w = 2`.
    Prop7_6,
    /// Prop. 7.7: `st h = 2`, `st w = 1`, `r = 1` (helical).
    Prop7_7,
    /// Prop. 7.8: `st h = 2`, `st w = 1`, `r = 0` (non-helical).
    Prop7_8,
    /// Prop. 7.9: `st h = 4`, `st w = 0`, decided by the sign of `Δ`.
    Prop7_9,
}

impl Chapter7Statement {
    /// The citation, e.g. `"Besednjak Prop. 7.9"`.
    pub fn citation(&self) -> &'static str {
        match self {
            Chapter7Statement::Lemma7_1 => "Besednjak Lemma 7.1",
            Chapter7Statement::Prop7_6 => "Besednjak Prop. 7.6 (with Lemmas 7.2, 7.5)",
            Chapter7Statement::Prop7_7 => "Besednjak Prop. 7.7",
            Chapter7Statement::Prop7_8 => "Besednjak Prop. 7.8",
            Chapter7Statement::Prop7_9 => "Besednjak Prop. 7.9",
        }
    }
}

/// The ch. 7 analysis of a DPH septic (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct SepticDphCriteria {
    /// `r = deg gcd(α, β)`.
    pub gcd_degree: usize,
    /// `st h`.
    pub h_degree: usize,
    /// `st w`.
    pub w_degree: usize,
    /// The deciding statement.
    pub statement: Chapter7Statement,
    /// `Δ` of (7.11) for `st h = 4` (with `h` monic).
    pub delta: Option<Q>,
    /// For `st w = 2`: whether the roots of `w` are both real or conjugate (Lemma 7.5).
    pub w_roots_real_or_conjugate: Option<bool>,
    /// The verdict of the criterion.
    pub helical: bool,
    /// The verdict of the exact axis test `a·r' ≡ σ` (a line or planar curve counts as
    /// a helix, as in Lemma 7.1).
    pub helical_by_axis: bool,
}

/// `Δ = 9h₂² + 3h₀h₄ − 12h₁h₃` of (7.11) from the Bernstein coefficients of a quartic `h`.
///
/// # Errors
/// [`PhError::DegreeMismatch`] unless there are five coefficients.
pub fn prop_7_9_delta(h: &[Q]) -> Result<Q, PhError> {
    let [h0, h1, h2, h3, h4] = <&[Q; 5]>::try_from(h).map_err(|_| {
        PhError::DegreeMismatch(format!(
            "Δ of (7.11) needs the 5 Bernstein coefficients of a quartic h, got {}",
            h.len()
        ))
    })?;
    Ok(
        Q::from(9) * h2.clone() * h2.clone() + Q::from(3) * h0.clone() * h4.clone()
            - Q::from(12) * h1.clone() * h3.clone(),
    )
}

/// Lemma 7.2 on a curve of degree 7 whose Hopf preimage has `r = deg gcd(α, β) = 1`:
/// with `α = γα̃`, `β = γβ̃`, the reduced Wronskian `p = α̃β̃' − α̃'β̃` (degree ≤ 2) is never
/// `c·(t − τ)²`, so the DPH condition cannot hold with `h` constant or a square.
#[derive(Debug, Clone, PartialEq)]
pub struct Lemma72 {
    /// `γ = gcd(α, β)`, monic, linear.
    pub gcd: Poly<Complex<Q>>,
    /// `p = α̃β̃' − α̃'β̃`.
    pub reduced_wronskian: Poly<Complex<Q>>,
    /// The discriminant `p₁² − 4p₀p₂` of `p` (non-zero when `deg p = 2`).
    pub discriminant: Complex<Q>,
}

/// Lemma 7.2 (see [`Lemma72`]).
///
/// # Errors
/// [`PhError::DegreeMismatch`] unless the preimage is cubic with `deg gcd(α, β) = 1`.
pub fn lemma_7_2(curve: &PhCurve<Q>) -> Result<Lemma72, PhError> {
    if curve.preimage_degree() != 3 {
        return Err(PhError::DegreeMismatch(format!(
            "Lemma 7.2 is about curves of degree 7 (a cubic preimage), got degree {}",
            curve.degree()
        )));
    }
    let (alpha, beta) = curve.hopf_polys();
    let gcd = alpha.gcd(&beta).monic();
    if gcd.degree() != Some(1) {
        return Err(PhError::DegreeMismatch(format!(
            "Lemma 7.2 needs r = deg gcd(α, β) = 1, got {}",
            gcd.degree().unwrap_or(0)
        )));
    }
    let inexact = |e| PhError::Degenerate(format!("gcd division: {e}"));
    let a = alpha.div_exact(&gcd).map_err(inexact)?;
    let b = beta.div_exact(&gcd).map_err(inexact)?;
    let p = &(&a * &b.derivative()) - &(&a.derivative() * &b);
    let c = |k: usize| p.coeffs().get(k).cloned().unwrap_or_else(Complex::zero);
    let discriminant = c(1) * c(1) - Complex::from_real(Q::from(4)) * c(0) * c(2);
    Ok(Lemma72 {
        gcd,
        reduced_wronskian: p,
        discriminant,
    })
}

impl Lemma72 {
    /// Certificate: `p` is not a constant times the square of a linear polynomial
    /// (`deg p < 2`, or its discriminant is non-zero), as the lemma states.
    pub fn certify(&self) -> Certificate {
        let deg = self.reduced_wronskian.degree();
        let z = self.discriminant.re == Q::ZERO && self.discriminant.im == Q::ZERO;
        Certificate::decide(
            "Besednjak Lemma 7.2: with r = 1, α̃β̃' − α̃'β̃ is not c·(t − τ)², so h is neither constant nor a square",
            deg.is_some_and(|d| d < 2) || !z,
            true,
            || format!("α̃β̃' − α̃'β̃ = {:?} is a square up to a constant", self.reduced_wronskian),
        )
    }
}

/// The ch. 7 criteria for a DPH curve of degree 7 (module docs).
///
/// # Errors
/// [`PhError::DegreeMismatch`] unless the preimage is cubic and `st h + 2 st w = 4`;
/// [`PhError::NotDph`] for a curve that is not DPH; [`PhError::Degenerate`] for a line.
pub fn septic_dph_criteria(curve: &PhCurve<Q>) -> Result<SepticDphCriteria, PhError> {
    if curve.preimage_degree() != 3 {
        return Err(PhError::DegreeMismatch(format!(
            "the ch. 7 criteria are for curves of degree 7 (a cubic preimage), got degree {}",
            curve.degree()
        )));
    }
    let f = curve.proportionality_factors()?.ok_or_else(|| {
        PhError::NotDph("αβ' − α'β is not a real polynomial times a square".into())
    })?;
    let (alpha, beta) = curve.hopf_polys();
    let gcd_degree = alpha.gcd(&beta).degree().unwrap_or(0);
    let h_degree = f.h.degree().unwrap_or(0);
    let w_degree = f.w.degree().unwrap_or(0);
    let helical_by_axis = !matches!(curve.to_poly_curve().helix_test()?, HelixTest::NotHelix);
    let mut delta = None;
    let mut w_roots = None;
    let (statement, helical) = if gcd_degree >= 2 {
        (Chapter7Statement::Lemma7_1, true)
    } else {
        match (h_degree, w_degree) {
            (0, 2) => {
                let real = f.w.coeffs().iter().all(|c: &Complex<Q>| c.im == Q::ZERO);
                w_roots = Some(real);
                (Chapter7Statement::Prop7_6, real)
            }
            (2, 1) if gcd_degree == 1 => (Chapter7Statement::Prop7_7, true),
            (2, 1) => (Chapter7Statement::Prop7_8, false),
            (4, 0) => {
                let hb = bernstein::to_bernstein(&f.h, 4)?;
                let d = prop_7_9_delta(&hb)?;
                let helical = d >= Q::ZERO;
                delta = Some(d);
                (Chapter7Statement::Prop7_9, helical)
            }
            (h, w) => {
                return Err(PhError::DegreeMismatch(format!(
                    "αβ' − α'β = λhW² with st h = {h}, st w = {w}: the ch. 7 cases need st h + 2 st w = 4"
                )))
            }
        }
    };
    Ok(SepticDphCriteria {
        gcd_degree,
        h_degree,
        w_degree,
        statement,
        delta,
        w_roots_real_or_conjugate: w_roots,
        helical,
        helical_by_axis,
    })
}

impl SepticDphCriteria {
    /// The certificate: the criterion's verdict equals the exact axis test.
    pub fn certify(&self) -> Vec<Certificate> {
        let word = |b: bool| if b { "helical" } else { "not helical" };
        let prop = format!(
            "{} (r = {}, st h = {}, st w = {}) says {}, as the axis test a·r' ≡ σ",
            self.statement.citation(),
            self.gcd_degree,
            self.h_degree,
            self.w_degree,
            word(self.helical)
        );
        vec![Certificate::decide(
            prop,
            self.helical == self.helical_by_axis,
            true,
            || format!("the axis test says {}", word(self.helical_by_axis)),
        )]
    }
}
