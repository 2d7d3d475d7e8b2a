//! Curvature, torsion, the rational Frenet frame of DPH curves, the Euler–Rodrigues
//! frame, and bending energy.
//!
//! docs/math/ph-curves.md, "Curvature and torsion" (Besednjak §3.2 (3.17)–(3.18), §4.2; errata E6, E12, E13 of docs/math/ph-curves.md): for a PH curve
//! `|r'×r''|² = σ²ρ` with a polynomial `ρ` (`= 4|αβ'−α'β|²`, `deg ρ ≤ 2n−6`),
//! `κ² = ρ/σ⁴`, `τ = (r'×r'')·r'''/(σ²ρ)`.
//!
//! docs/math/ph-curves.md, "DPH test and the rational Frenet frame" (Besednjak §4.1 (4.3)): for a DPH curve, `ρ = ω²` with a polynomial
//! `ω = √c·ω̃` and the Frenet frame is rational up to the one constant `√c`:
//! `t = r'/σ`, `p = (σr'' − σ'r')/(σω)`, `b = (r'×r'')/(σω)`, `κ = ω/σ²`,
//! `τ = (r'×r'')·r'''/(σ²ω²)`. The sign of `ω` may change at real roots of `ω`
//! (inflections, e.g. Besednjak Ex 8.1 and 8.3 at `t = 0`): there the frame built with
//! the polynomial `ω` flips `p` and `b`, and the true Frenet frame (with `|ω|`) is
//! undefined at the root itself.

use super::dph::DphData;
use super::hodograph::{PhCurve, PhPolyCurve};
use super::util::*;
use super::PhError;
use rcagd_algebra::bernstein;
use rcagd_algebra::quaternion::{self, Quaternion};
use rcagd_algebra::{Certificate, Poly, Scalar};

/// A rational function `num(t)/den(t)`.
#[derive(Debug, Clone, PartialEq)]
pub struct RationalFunction<F> {
    /// Numerator.
    pub num: Poly<F>,
    /// Denominator.
    pub den: Poly<F>,
}

impl<F: Scalar> RationalFunction<F> {
    /// Value at `t`, `None` where the denominator vanishes.
    pub fn eval(&self, t: &F) -> Option<F> {
        let d = self.den.eval(t);
        if d.is_zero() {
            None
        } else {
            Some(self.num.eval(t) / d)
        }
    }

    /// Value at an `f64` parameter.
    pub fn eval_f64(&self, t: f64) -> Option<f64> {
        let d = poly_f64(&self.den).eval(&t);
        if d == 0.0 {
            None
        } else {
            Some(poly_f64(&self.num).eval(&t) / d)
        }
    }

    /// `true` if the function is constant (`num·den' − num'·den ≡ 0`).
    pub fn is_constant(&self) -> bool {
        let w = &(&self.num * &self.den.derivative()) - &(&self.num.derivative() * &self.den);
        poly_negligible(&w, poly_scale(&self.num).max(poly_scale(&self.den)))
    }
}

impl<F: Scalar> PhPolyCurve<F> {
    /// `r' × r''` in power form.
    pub fn cross_r1_r2(&self) -> [Poly<F>; 3] {
        let d1 = pderiv(&self.r);
        let d2 = pderiv(&d1);
        pcross(&d1, &d2)
    }

    /// The triple product `(r' × r'') · r'''`.
    pub fn triple_product(&self) -> Poly<F> {
        let d1 = pderiv(&self.r);
        let d2 = pderiv(&d1);
        let d3 = pderiv(&d2);
        pdot(&pcross(&d1, &d2), &d3)
    }

    /// `ρ = |r'×r''|²/σ²` (docs/math/ph-curves.md, "Curvature and torsion", Besednjak (3.17)): by exact polynomial division
    /// for exact scalars; for `f64` by the division-free identity `ρ = |r''|² − σ'²`
    /// (from `|r'×r''|² = |r'|²|r''|² − (r'·r'')²`, `|r'|² = σ²`, `r'·r'' = σσ'`), since
    /// long division in floating point amplifies round-off in the low coefficients.
    ///
    /// # Errors
    /// [`PhError::Degenerate`] if `σ ≡ 0`; [`PhError::NotPh`] if (exactly) the division
    /// leaves a remainder (then `σ` is not the speed of `r`).
    pub fn rho(&self) -> Result<Poly<F>, PhError> {
        if self.sigma.is_zero() {
            return Err(PhError::Degenerate("σ ≡ 0".into()));
        }
        if !F::EXACT {
            let d2 = pderiv(&pderiv(&self.r));
            let sd = self.sigma.derivative();
            return Ok(trim_noise(&pdot(&d2, &d2) - &(&sd * &sd)));
        }
        let c = self.cross_r1_r2();
        let c2 = pdot(&c, &c);
        let s2 = &self.sigma * &self.sigma;
        let (q, rem) = c2.div_rem(&s2)?;
        if !rem.is_zero() {
            return Err(PhError::NotPh(format!(
                "|r'×r''|² is not divisible by σ²: remainder {}",
                format_poly(&rem, "t")
            )));
        }
        Ok(q)
    }

    /// The curvature vector `κ·n = (σr'' − σ'r')/σ³` of a PH curve, as the numerator
    /// `σr'' − σ'r'` and the denominator `σ³`: rational for every PH curve (no `√ρ`),
    /// since `d t/ds = (r'/σ)'/σ` (docs/math/ph-curves.md, "Curvature and torsion" and "DPH test and the rational Frenet frame"; Besednjak (4.3) with `κ = ω/σ²`,
    /// `p = (σr'' − σ'r')/(σω)`). Used for curvature combs.
    pub fn curvature_vector(&self) -> ([Poly<F>; 3], Poly<F>) {
        let d1 = pderiv(&self.r);
        let d2 = pderiv(&d1);
        let sd = self.sigma.derivative();
        (
            psub(&pscale_poly(&d2, &self.sigma), &pscale_poly(&d1, &sd)),
            self.sigma.pow(3),
        )
    }

    /// Certificates of [`Self::curvature_vector`]: `|σr''−σ'r'|² ≡ σ²ρ` (so
    /// `|κn|² = ρ/σ⁴ = κ²`) and `(σr''−σ'r')·r' ≡ 0` (normal to the tangent).
    ///
    /// # Errors
    /// As [`Self::rho`].
    pub fn certify_curvature_vector(&self) -> Result<Vec<Certificate>, PhError> {
        let (num, _) = self.curvature_vector();
        let rho = self.rho()?;
        Ok(vec![
            identity_cert(
                "|σr''−σ'r'|² ≡ σ²ρ (|κn| = κ)",
                &pdot(&num, &num),
                &(&(&self.sigma * &self.sigma) * &rho),
            ),
            identity_cert(
                "(σr''−σ'r')·r' ≡ 0 (κn ⊥ t)",
                &pdot(&num, &pderiv(&self.r)),
                &Poly::zero(),
            ),
        ])
    }

    /// `κ² = ρ/σ⁴ = |r'×r''|²/σ⁶` (docs/math/ph-curves.md, "Curvature and torsion").
    ///
    /// # Errors
    /// As [`Self::rho`].
    pub fn curvature_squared(&self) -> Result<RationalFunction<F>, PhError> {
        Ok(RationalFunction {
            num: self.rho()?,
            den: self.sigma.pow(4),
        })
    }

    /// `τ = (r'×r'')·r''' / (σ²ρ)` (docs/math/ph-curves.md, "Curvature and torsion"; Besednjak (2.14)).
    ///
    /// # Errors
    /// As [`Self::rho`]; [`PhError::Degenerate`] for a straight line (`ρ ≡ 0`).
    pub fn torsion(&self) -> Result<RationalFunction<F>, PhError> {
        let rho = self.rho()?;
        if rho.is_zero() {
            return Err(PhError::Degenerate(
                "ρ ≡ 0: a straight line has no torsion".into(),
            ));
        }
        Ok(RationalFunction {
            num: self.triple_product(),
            den: &(&self.sigma * &self.sigma) * &rho,
        })
    }

    /// Bending energy `E = ∫_a^b κ²σ dt = ∫_a^b ρ/σ³ dt` (Besednjak (9.29);
    /// docs/math/ph-curves.md, "Hermite interpolation by helical PH quintics") with an error estimate; see [`BendingEnergy`].
    ///
    /// The integrand is rational with poles at the (complex) roots of `σ`. A PH curve with
    /// a root pair of `σ` close to the real axis has a sharp peak of `1/σ³` at the nearby
    /// local minimum of `σ` (width ≈ `√(σ/σ'')` there), which a fixed or depth-first
    /// adaptive rule can miss or under-resolve (the defect that made the `f64` and the
    /// exact path disagree by 5e-6 and both be wrong by a factor 2 on a septic with roots
    /// of `σ` at `0.14 ± 0.087i`, `0.81 ± 0.083i`: true `E = 86.33508777895…`).
    /// Therefore the interval is first split at the real roots of `σ'` (every peak of
    /// `1/σ³` lies at such a critical point, computed by exact real-root isolation of
    /// Bernstein subdivision of `σ'` in `f64`, variation diminishing), and then integrated by
    /// *globally* adaptive
    /// Gauss–Kronrod (7, 15) quadrature: the interval with the largest error estimate
    /// `|K15 − G7|` is bisected until the summed estimate is below `1e-13·E` (or the
    /// interval budget of 4000 is spent). The two integrand paths are
    /// exact scalars: the exact `ρ` (converted to `f64` coefficients), `ρ(t)/σ(t)³`;
    /// `f64`: `|r'(t)×r''(t)|²/σ(t)⁵` pointwise (no coefficient-level cancellation as in
    /// `ρ = |r''|² − σ'²`).
    ///
    /// # Errors
    /// As [`Self::rho`]; [`PhError::OutOfRange`] unless `a ≤ b` are finite;
    /// [`PhError::Degenerate`] if `σ` vanishes in `[a, b]` (decided exactly for exact
    /// scalars; for `f64` when the quadrature does not stay finite).
    pub fn bending_energy_with_error(&self, a: f64, b: f64) -> Result<BendingEnergy, PhError> {
        if !(a.is_finite() && b.is_finite() && a <= b) {
            return Err(PhError::OutOfRange(format!(
                "bending energy needs finite a ≤ b, got [{a}, {b}]"
            )));
        }
        if F::EXACT {
            if let (Some(s), Some(lo), Some(hi)) = (
                poly_rational(&self.sigma),
                rcagd_algebra::Rational::try_from(a).ok(),
                rcagd_algebra::Rational::try_from(b).ok(),
            ) {
                if !s.is_zero() && rcagd_algebra::roots::count_real_roots_in(&s, &lo, &hi)? > 0 {
                    return Err(PhError::Degenerate(format!(
                        "σ vanishes in [{a}, {b}]: the bending energy diverges"
                    )));
                }
            }
        }
        let rho = if F::EXACT {
            Some(poly_f64(&self.rho()?))
        } else {
            None
        };
        if self.sigma.is_zero() {
            return Err(PhError::Degenerate("σ ≡ 0".into()));
        }
        let sigma = poly_f64(&self.sigma);
        let d1 = pderiv(&[
            poly_f64(&self.r[0]),
            poly_f64(&self.r[1]),
            poly_f64(&self.r[2]),
        ]);
        let d2 = pderiv(&d1);
        let f = |t: f64| {
            let s = sigma.eval(&t);
            match &rho {
                Some(rho) => rho.eval(&t) / (s * s * s),
                None => {
                    let c = cross3(&peval(&d1, &t), &peval(&d2, &t));
                    dot3(&c, &c) / (s * s * s * s * s)
                }
            }
        };
        // break points: the critical points of σ inside (a, b)
        let mut cuts = vec![a];
        sign_changes_f64(&sigma.derivative(), a, b, &mut cuts);
        cuts.retain(|&t| t >= a && t < b);
        cuts.push(b);
        let (value, error) = gauss_kronrod(&f, &cuts, 1e-13, 4000);
        if !(value.is_finite() && error.is_finite()) {
            return Err(PhError::Degenerate(format!(
                "σ vanishes (numerically) in [{a}, {b}]: the bending energy diverges"
            )));
        }
        Ok(BendingEnergy { value, error })
    }

    /// Bending energy on `[a, b]`, the value of [`Self::bending_energy_with_error`].
    ///
    /// # Errors
    /// As [`Self::bending_energy_with_error`].
    pub fn bending_energy_between(&self, a: f64, b: f64) -> Result<f64, PhError> {
        self.bending_energy_with_error(a, b).map(|e| e.value)
    }

    /// Bending energy on `[0, 1]`; see [`Self::bending_energy_between`].
    ///
    /// # Errors
    /// As [`Self::bending_energy_between`].
    pub fn bending_energy(&self) -> Result<f64, PhError> {
        self.bending_energy_between(0.0, 1.0)
    }

    /// The rational Frenet frame of a DPH curve with `ρ = c·ω̃²` (docs/math/ph-curves.md, "DPH test and the rational Frenet frame").
    pub fn frenet_frame(&self, dph: &DphData<F>) -> FrenetFrame<F> {
        let d1 = pderiv(&self.r);
        let d2 = pderiv(&d1);
        let d3 = pderiv(&d2);
        FrenetFrame {
            sigma: self.sigma.clone(),
            d1,
            d2,
            d3,
            c: dph.c.clone(),
            omega_tilde: dph.omega_tilde.clone(),
        }
    }
}

/// The Frenet frame of a DPH curve, `t = r'/σ`, `p = (σr''−σ'r')/(σω)`,
/// `b = (r'×r'')/(σω)` with `ω = √c·ω̃` (docs/math/ph-curves.md, "DPH test and the rational Frenet frame"; Besednjak §4.1 (4.3)).
///
/// The exact evaluations return `t` and the *scaled* vectors `p̃ = √c·p`, `b̃ = √c·b`,
/// which are rational at rational `t`.
#[derive(Debug, Clone, PartialEq)]
pub struct FrenetFrame<F> {
    sigma: Poly<F>,
    d1: [Poly<F>; 3],
    d2: [Poly<F>; 3],
    d3: [Poly<F>; 3],
    c: F,
    omega_tilde: Poly<F>,
}

impl<F: Scalar> FrenetFrame<F> {
    /// The radicand `c` (`ω = √c·ω̃`).
    pub fn radicand(&self) -> &F {
        &self.c
    }

    /// Numerator of `p̃ = √c·p`: `σr'' − σ'r'` (denominator `σω̃`).
    pub fn normal_numerator(&self) -> [Poly<F>; 3] {
        let sd = self.sigma.derivative();
        psub(
            &pscale_poly(&self.d2, &self.sigma),
            &pscale_poly(&self.d1, &sd),
        )
    }

    /// Numerator of `b̃ = √c·b`: `r'×r''` (denominator `σω̃`).
    pub fn binormal_numerator(&self) -> [Poly<F>; 3] {
        pcross(&self.d1, &self.d2)
    }

    /// `(t, p̃, b̃)` at the parameter `t` with `p = p̃/√c`, `b = b̃/√c` (exact), or
    /// `None` where `σ(t)ω̃(t) = 0` (inflection or singular point).
    ///
    /// This is the classical Frenet frame: `p̃ = (σr''−σ'r')/(σ|ω̃|)` and
    /// `b̃ = (r'×r'')/(σ|ω̃|)`, so `b` points along `r'×r''` and `p = b × t` on both
    /// sides of a sign change of the polynomial `ω̃` (dividing by the signed `ω̃`
    /// would flip `p` and `b` wherever `ω̃ < 0`).
    #[allow(clippy::type_complexity)]
    pub fn eval_scaled(&self, t: &F) -> Option<([F; 3], [F; 3], [F; 3])> {
        let s = self.sigma.eval(t);
        let w = self.omega_tilde.eval(t);
        if s.is_zero() || w.is_zero() {
            return None;
        }
        let inv_s = F::one() / s.clone();
        let inv_sw = F::one() / (s * w.abs());
        Some((
            scale3(&peval(&self.d1, t), &inv_s),
            scale3(&peval(&self.normal_numerator(), t), &inv_sw),
            scale3(&peval(&self.binormal_numerator(), t), &inv_sw),
        ))
    }

    /// `(t, p, b)` at `t` in `f64` (with `√c` applied), `None` at zeros of `σω̃`.
    pub fn eval_f64(&self, t: f64) -> Option<[[f64; 3]; 3]> {
        let tf = F::from_rational(&rcagd_algebra::Rational::try_from(t).ok()?);
        let (a, b, c) = self.eval_scaled(&tf)?;
        let k = 1.0 / self.c.to_f64().sqrt();
        let s = |v: [F; 3]| -> [f64; 3] {
            let f = to_f64_3(&v);
            [f[0] * k, f[1] * k, f[2] * k]
        };
        Some([to_f64_3(&a), s(b), s(c)])
    }

    /// `κ = |ω|/σ² = √c·|ω̃|/σ²` as `(√c-free numerator ω̃, denominator σ²)`: multiply
    /// the absolute value by `√c` (the numerator `ω̃` is signed; its sign changes are
    /// the inflections).
    pub fn curvature_scaled(&self) -> RationalFunction<F> {
        RationalFunction {
            num: self.omega_tilde.clone(),
            den: &self.sigma * &self.sigma,
        }
    }

    /// Certificates (docs/math/ph-curves.md, "DPH test and the rational Frenet frame"), as polynomial identities over `F`:
    /// * `|r'×r''|² ≡ σ²·c·ω̃²` (`b·b = 1`);
    /// * `|σr''−σ'r'|² ≡ σ²·c·ω̃²` (`p·p = 1`);
    /// * `(σr''−σ'r')·r' ≡ 0` (`p ⊥ t`);
    /// * `r' × (σr''−σ'r') ≡ σ (r'×r'')` (`t × p = b`);
    /// * `c·Ñ·ω̃ ≡ −[(r'×r'')·r'''] (σr''−σ'r')` with
    ///   `Ñ = σω̃ (r'×r''') − (σ'ω̃ + σω̃')(r'×r'')` (Frenet–Serret `b' = −στp`).
    pub fn certify(&self) -> Vec<Certificate> {
        let pn = self.normal_numerator();
        let bn = self.binormal_numerator();
        let s2cw2 = (&(&self.sigma * &self.sigma) * &(&self.omega_tilde * &self.omega_tilde))
            .scale(&self.c);
        let mut certs = vec![
            identity_cert("|r'×r''|² ≡ σ²·c·ω̃² (b·b = 1)", &pdot(&bn, &bn), &s2cw2),
            identity_cert("|σr''−σ'r'|² ≡ σ²·c·ω̃² (p·p = 1)", &pdot(&pn, &pn), &s2cw2),
            identity_cert(
                "(σr''−σ'r')·r' ≡ 0 (p ⊥ t)",
                &pdot(&pn, &self.d1),
                &Poly::zero(),
            ),
        ];
        let tp = pcross(&self.d1, &pn);
        let sb = pscale_poly(&bn, &self.sigma);
        for k in 0..3 {
            certs.push(identity_cert(
                format!("[r' × (σr''−σ'r')]_{k} ≡ σ[r'×r'']_{k} (t × p = b)"),
                &tp[k],
                &sb[k],
            ));
        }
        let trip = pdot(&bn, &self.d3);
        let r1r3 = pcross(&self.d1, &self.d3);
        let sw = &self.sigma * &self.omega_tilde;
        let dsw = &(&self.sigma.derivative() * &self.omega_tilde)
            + &(&self.sigma * &self.omega_tilde.derivative());
        let nt = psub(&pscale_poly(&r1r3, &sw), &pscale_poly(&bn, &dsw));
        for k in 0..3 {
            let lhs = (&nt[k] * &self.omega_tilde).scale(&self.c);
            let rhs = -(&trip * &pn[k]);
            certs.push(identity_cert(
                format!("c·Ñ_{k}·ω̃ ≡ −[(r'×r'')·r'''](σr''−σ'r')_{k} (b' = −στp)"),
                &lhs,
                &rhs,
            ));
        }
        certs
    }
}

impl<F: Scalar> crate::Certified for FrenetFrame<F> {
    fn certify(&self) -> Vec<Certificate> {
        FrenetFrame::certify(self)
    }
}

/// The Euler–Rodrigues frame of a PH curve: `e_1 = A i A*/σ`, `e_2 = A j A*/σ`,
/// `e_3 = A k A*/σ` — a rational orthonormal frame with `e_1` the unit tangent
/// (Choi–Han; the quaternion form of Besednjak §3.3).
#[derive(Debug, Clone, PartialEq)]
pub struct EulerRodriguesFrame<F> {
    /// Numerators `A i A*`, `A j A*`, `A k A*`.
    pub numerators: [[Poly<F>; 3]; 3],
    /// The common denominator `σ = |A|²`.
    pub sigma: Poly<F>,
}

impl<F: Scalar> EulerRodriguesFrame<F> {
    /// `(e_1, e_2, e_3)` at `t`, `None` where `σ(t) = 0`.
    pub fn eval(&self, t: &F) -> Option<[[F; 3]; 3]> {
        let s = self.sigma.eval(t);
        if s.is_zero() {
            return None;
        }
        let inv = F::one() / s;
        Some([
            scale3(&peval(&self.numerators[0], t), &inv),
            scale3(&peval(&self.numerators[1], t), &inv),
            scale3(&peval(&self.numerators[2], t), &inv),
        ])
    }

    /// Certificates: `|e_k|²σ² ≡ σ²`, `e_k·e_l ≡ 0` (`k ≠ l`), `e_1 × e_2 ≡ e_3` (times `σ²`).
    pub fn certify(&self) -> Vec<Certificate> {
        let s2 = &self.sigma * &self.sigma;
        let n = &self.numerators;
        let mut certs = Vec::new();
        for (k, name) in ["AiA*", "AjA*", "AkA*"].iter().enumerate() {
            certs.push(identity_cert(
                format!("|{name}|² ≡ σ² (ERF)"),
                &pdot(&n[k], &n[k]),
                &s2,
            ));
        }
        for (k, l) in [(0, 1), (0, 2), (1, 2)] {
            certs.push(identity_cert(
                format!("e_{}·e_{} ≡ 0 (ERF)", k + 1, l + 1),
                &pdot(&n[k], &n[l]),
                &Poly::zero(),
            ));
        }
        let c = pcross(&n[0], &n[1]);
        let s3 = pscale_poly(&n[2], &self.sigma);
        for k in 0..3 {
            certs.push(identity_cert(
                format!("[AiA* × AjA*]_{k} ≡ σ [AkA*]_{k} (ERF right-handed)"),
                &c[k],
                &s3[k],
            ));
        }
        certs
    }
}

impl<F: Scalar> crate::Certified for EulerRodriguesFrame<F> {
    fn certify(&self) -> Vec<Certificate> {
        EulerRodriguesFrame::certify(self)
    }
}

impl<F: Scalar> PhCurve<F> {
    /// The quaternion polynomial `A(t)` in power form.
    pub fn preimage_poly(&self) -> Poly<Quaternion<F>> {
        bernstein::from_bernstein(self.coefficients())
    }

    /// The Euler–Rodrigues frame `(A i A*, A j A*, A k A*)/σ`.
    pub fn euler_rodrigues_frame(&self) -> EulerRodriguesFrame<F> {
        let a = self.preimage_poly();
        let e = |u: Quaternion<F>| quaternion::vector_polys(&quaternion::sandwich(&a, &u));
        EulerRodriguesFrame {
            numerators: [e(Quaternion::i()), e(Quaternion::j()), e(Quaternion::k())],
            sigma: self.speed(),
        }
    }

    /// `ρ = 4|αβ' − α'β|²` from the Hopf form (docs/math/ph-curves.md, "Curvature and torsion"; Besednjak (4.16), docs/math/ph-curves.md, Errata E15).
    pub fn rho_hopf(&self) -> Poly<F> {
        let (re, im) = self.proportionality_re_im();
        (&(&re * &re) + &(&im * &im)).scale(&F::from_i64(4))
    }

    /// Certificates of docs/math/ph-curves.md, "Curvature and torsion": `|r'×r''|² ≡ σ²·4|αβ'−α'β|²` and
    /// `r'×r'' ≡ 2A(f j + g k)A*` with `αβ'−α'β = g + i f`.
    pub fn certify_curvature(&self) -> Vec<Certificate> {
        let pc = self.to_poly_curve();
        let cr = pc.cross_r1_r2();
        let s2 = &pc.sigma * &pc.sigma;
        let mut certs = vec![identity_cert(
            "|r'×r''|² ≡ σ²·4|αβ'−α'β|² (Besednjak (4.16))",
            &pdot(&cr, &cr),
            &(&s2 * &self.rho_hopf()),
        )];
        // r'×r'' = 2 A (f j + g k) A*
        let (g, f) = self.proportionality_re_im();
        let a = self.preimage_poly();
        let two = F::from_i64(2);
        let fj =
            f.map(|c| Quaternion::new(F::zero(), F::zero(), c.clone() * two.clone(), F::zero()));
        let gk =
            g.map(|c| Quaternion::new(F::zero(), F::zero(), F::zero(), c.clone() * two.clone()));
        let mid = &fj + &gk;
        let prod = &(&a * &mid) * &quaternion::conj_poly(&a);
        let v = quaternion::vector_polys(&prod);
        for k in 0..3 {
            certs.push(identity_cert(
                format!("[r'×r'']_{k} ≡ [2A(f j + g k)A*]_{k}"),
                &cr[k],
                &v[k],
            ));
        }
        certs
    }
}

/// A bending energy with the quadrature's error estimate (the sum over the final
/// intervals of `|K15 − G7|`, a conservative bound for smooth integrands).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BendingEnergy {
    /// The value `∫ ρ/σ³ dt`.
    pub value: f64,
    /// The estimated absolute error.
    pub error: f64,
}

/// Appends to `out` the parameters in `(a, b)` where the `f64` polynomial `p` changes sign
/// (to about `1e-12·(b − a)`), by Bernstein subdivision: the Bernstein coefficients of `p`
/// on `[a, b]` bound its sign changes (variation diminishing), a piece without a sign
/// change in its coefficients has no root, a piece with one sign change and opposite end
/// values is bisected, anything else is split by de Casteljau at the midpoint.
pub(crate) fn sign_changes_f64(p: &Poly<f64>, a: f64, b: f64, out: &mut Vec<f64>) {
    let c = p.coeffs();
    let n = c.len();
    if n < 2 || a.is_nan() || b.is_nan() || b <= a {
        return;
    }
    // q(u) = p(a + (b − a)u): Taylor shift by a, then scale
    let mut q: Vec<f64> = c.to_vec();
    for i in 0..n {
        for j in (i..n - 1).rev() {
            q[j] += a * q[j + 1];
        }
    }
    let mut hk = 1.0;
    for x in q.iter_mut() {
        *x *= hk;
        hk *= b - a;
    }
    // power → Bernstein: b_k = Σ_{j ≤ k} C(k, j)/C(n−1, j) q_j
    let deg = n - 1;
    let binom = |n: usize, k: usize| -> f64 {
        (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
    };
    let bern: Vec<f64> = (0..n)
        .map(|k| {
            (0..=k)
                .map(|j| binom(k, j) / binom(deg, j) * q[j])
                .sum::<f64>()
        })
        .collect();
    let eval = |t: f64| p.eval(&t);
    fn rec(
        bern: &[f64],
        a: f64,
        b: f64,
        min_w: f64,
        depth: u32,
        eval: &dyn Fn(f64) -> f64,
        out: &mut Vec<f64>,
    ) {
        let changes = bern
            .windows(2)
            .filter(|w| (w[0] < 0.0 && w[1] > 0.0) || (w[0] > 0.0 && w[1] < 0.0))
            .count();
        if changes == 0 {
            return;
        }
        let (Some(&first), Some(&last)) = (bern.first(), bern.last()) else {
            return;
        };
        if changes == 1 && first * last < 0.0 {
            // exactly one simple root: bisection
            let (mut lo, mut hi) = (a, b);
            let slo = first < 0.0;
            while hi - lo > min_w {
                let m = 0.5 * (lo + hi);
                if (eval(m) < 0.0) == slo {
                    lo = m;
                } else {
                    hi = m;
                }
            }
            out.push(0.5 * (lo + hi));
            return;
        }
        if depth == 0 || b - a <= min_w {
            out.push(0.5 * (a + b));
            return;
        }
        // de Casteljau at 1/2
        let n = bern.len();
        let mut left = Vec::with_capacity(n);
        let mut right = vec![0.0; n];
        let mut w = bern.to_vec();
        left.push(w[0]);
        right[n - 1] = w[n - 1];
        for r in 1..n {
            for i in 0..n - r {
                w[i] = 0.5 * (w[i] + w[i + 1]);
            }
            left.push(w[0]);
            right[n - 1 - r] = w[n - 1 - r];
        }
        let m = 0.5 * (a + b);
        rec(&left, a, m, min_w, depth - 1, eval, out);
        rec(&right, m, b, min_w, depth - 1, eval, out);
    }
    rec(&bern, a, b, 1e-12 * (b - a), 60, &eval, out);
}

/// Gauss–Kronrod (7, 15) on `[a, b]`: `(K15, |K15 − G7|)` (QUADPACK `qk15` nodes).
fn gk15(f: &dyn Fn(f64) -> f64, a: f64, b: f64) -> (f64, f64) {
    const XGK: [f64; 8] = [
        0.991_455_371_120_812_6,
        0.949_107_912_342_758_5,
        0.864_864_423_359_769_1,
        0.741_531_185_599_394_4,
        0.586_087_235_467_691_1,
        0.405_845_151_377_397_2,
        0.207_784_955_007_898_5,
        0.0,
    ];
    const WGK: [f64; 8] = [
        0.022_935_322_010_529_22,
        0.063_092_092_629_978_55,
        0.104_790_010_322_250_2,
        0.140_653_259_715_525_9,
        0.169_004_726_639_267_9,
        0.190_350_578_064_785_4,
        0.204_432_940_075_298_9,
        0.209_482_141_084_727_8,
    ];
    const WG: [f64; 4] = [
        0.129_484_966_168_869_7,
        0.279_705_391_489_276_7,
        0.381_830_050_505_118_9,
        0.417_959_183_673_469_4,
    ];
    let h = 0.5 * (b - a);
    let c = 0.5 * (a + b);
    let fc = f(c);
    let mut k = WGK[7] * fc;
    let mut g = WG[3] * fc;
    for j in 0..7 {
        let x = h * XGK[j];
        let s = f(c - x) + f(c + x);
        k += WGK[j] * s;
        if j % 2 == 1 {
            g += WG[j / 2] * s;
        }
    }
    (k * h, ((k - g) * h).abs())
}

/// Globally adaptive Gauss–Kronrod (7, 15) quadrature of `f` over the consecutive
/// intervals of `cuts` (sorted): the interval with the largest error estimate is bisected
/// until the summed estimate is at most `rel_tol·|I|` or `max_intervals` is reached
/// (intervals shorter than `1e-14` of the whole are not split further, so round-off
/// cannot force an endless refinement). Returns `(I, error estimate)`; NaN on a
/// non-finite integrand value.
pub(crate) fn gauss_kronrod(
    f: &dyn Fn(f64) -> f64,
    cuts: &[f64],
    rel_tol: f64,
    max_intervals: usize,
) -> (f64, f64) {
    let (Some(&first), Some(&last)) = (cuts.first(), cuts.last()) else {
        return (0.0, 0.0);
    };
    let min_width = 1e-14 * (last - first).abs().max(f64::MIN_POSITIVE);
    // (a, b, value, error)
    let mut parts: Vec<(f64, f64, f64, f64)> = Vec::new();
    for w in cuts.windows(2) {
        if w[1] > w[0] {
            let (v, e) = gk15(f, w[0], w[1]);
            if !(v.is_finite() && e.is_finite()) {
                return (f64::NAN, f64::NAN);
            }
            parts.push((w[0], w[1], v, e));
        }
    }
    loop {
        let total: f64 = parts.iter().map(|p| p.2).sum();
        let err: f64 = parts.iter().map(|p| p.3).sum();
        if err <= rel_tol * total.abs() || parts.len() >= max_intervals {
            return (total, err);
        }
        // the splittable interval with the largest error
        let worst = parts
            .iter()
            .enumerate()
            .filter(|(_, p)| p.1 - p.0 > min_width)
            .max_by(|x, y| x.1 .3.total_cmp(&y.1 .3))
            .map(|(i, _)| i);
        let Some(i) = worst else {
            return (total, err);
        };
        let (a, b, _, _) = parts.swap_remove(i);
        let m = 0.5 * (a + b);
        for (x, y) in [(a, m), (m, b)] {
            let (v, e) = gk15(f, x, y);
            if !(v.is_finite() && e.is_finite()) {
                return (f64::NAN, f64::NAN);
            }
            parts.push((x, y, v, e));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sign_changes_of_a_cubic() {
        // (t − 0.2)(t − 0.25)(t − 0.9) on [0, 1]; two of the roots are close
        let p = &(&Poly::new(vec![-0.2, 1.0]) * &Poly::new(vec![-0.25, 1.0]))
            * &Poly::new(vec![-0.9, 1.0]);
        let mut out = Vec::new();
        sign_changes_f64(&p, 0.0, 1.0, &mut out);
        assert_eq!(out.len(), 3, "{out:?}");
        for (x, r) in out.iter().zip([0.2, 0.25, 0.9]) {
            assert!((x - r).abs() < 1e-10, "{out:?}");
        }
        // on a sub-interval, and a polynomial without real roots
        let mut out = Vec::new();
        sign_changes_f64(&p, 0.22, 2.0, &mut out);
        assert_eq!(out.len(), 2, "{out:?}");
        let mut out = Vec::new();
        sign_changes_f64(&Poly::new(vec![1.0, 0.0, 1.0]), -3.0, 3.0, &mut out);
        assert!(out.is_empty());
    }

    #[test]
    fn gauss_kronrod_peak() {
        // ∫_0^1 ε/((t − 1/2)² + ε²) dt = 2 atan(1/(2ε)), sharp peak at 1/2
        let eps = 1e-4;
        let f = |t: f64| eps / ((t - 0.5) * (t - 0.5) + eps * eps);
        let exact = 2.0 * (0.5 / eps).atan();
        let (v, e) = gauss_kronrod(&f, &[0.0, 0.5, 1.0], 1e-13, 4000);
        assert!(
            (v - exact).abs() <= 1e-11 * exact,
            "{v} vs {exact}, est {e}"
        );
        assert!(e <= 1e-12 * exact);
    }
}
