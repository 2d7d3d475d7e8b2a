//! Curvature, torsion, the rational Frenet frame of DPH curves, the Euler–Rodrigues
//! frame, and bending energy.
//!
//! NOTES-001 ALG-4 (seed 001 §3.2 (3.17)–(3.18), §4.2; errata 6, 12, 13): for a PH curve
//! `|r'×r''|² = σ²ρ` with a polynomial `ρ` (`= 4|αβ'−α'β|²`, `deg ρ ≤ 2n−6`),
//! `κ² = ρ/σ⁴`, `τ = (r'×r'')·r'''/(σ²ρ)`.
//!
//! NOTES-001 ALG-5 (seed 001 §4.1 (4.3)): for a DPH curve, `ρ = ω²` with a polynomial
//! `ω = √c·ω̃` and the Frenet frame is rational up to the one constant `√c`:
//! `t = r'/σ`, `p = (σr'' − σ'r')/(σω)`, `b = (r'×r'')/(σω)`, `κ = ω/σ²`,
//! `τ = (r'×r'')·r'''/(σ²ω²)`. The sign of `ω` may change at real roots of `ω`
//! (inflections, e.g. seed 001 Ex 8.1 and 8.3 at `t = 0`): there the frame built with
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

    /// `ρ = |r'×r''|²/σ²` (NOTES-001 ALG-4, seed 001 (3.17)): by exact polynomial division
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
                fmt_poly(&rem)
            )));
        }
        Ok(q)
    }

    /// `κ² = ρ/σ⁴ = |r'×r''|²/σ⁶` (NOTES-001 ALG-4).
    ///
    /// # Errors
    /// As [`Self::rho`].
    pub fn curvature_squared(&self) -> Result<RationalFunction<F>, PhError> {
        Ok(RationalFunction {
            num: self.rho()?,
            den: self.sigma.pow(4),
        })
    }

    /// `τ = (r'×r'')·r''' / (σ²ρ)` (NOTES-001 ALG-4; seed 001 (2.14)).
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

    /// Bending energy `E = ∫_a^b κ²σ dt = ∫_a^b ρ/σ³ dt` (seed 001 (9.29); NOTES-001
    /// ALG-10 step 9), by adaptive Gauss–Legendre quadrature in `f64` (relative accuracy
    /// about `1e-12` for regular curves). Exact scalars integrate the exact `ρ/σ³`; `f64`
    /// evaluates `|r'×r''|²/σ⁵` pointwise.
    ///
    /// # Errors
    /// As [`Self::rho`]; [`PhError::Degenerate`] if `σ` vanishes in `[a, b]`.
    pub fn bending_energy_between(&self, a: f64, b: f64) -> Result<f64, PhError> {
        // exact scalars: the exact ρ; f64: |r'×r''|²/σ⁵ pointwise (no coefficient-level
        // cancellation as in ρ = |r''|² − σ'²)
        let rho = if F::EXACT {
            Some(poly_f64(&self.rho()?))
        } else {
            None
        };
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
        let v = adaptive_gauss(&f, a, b, 1e-13, 40);
        if !v.is_finite() {
            return Err(PhError::Degenerate(
                "σ vanishes on the interval: the bending energy diverges".into(),
            ));
        }
        Ok(v)
    }

    /// Bending energy on `[0, 1]`; see [`Self::bending_energy_between`].
    ///
    /// # Errors
    /// As [`Self::bending_energy_between`].
    pub fn bending_energy(&self) -> Result<f64, PhError> {
        self.bending_energy_between(0.0, 1.0)
    }

    /// The rational Frenet frame of a DPH curve with `ρ = c·ω̃²` (NOTES-001 ALG-5).
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
/// `b = (r'×r'')/(σω)` with `ω = √c·ω̃` (NOTES-001 ALG-5; seed 001 §4.1 (4.3)).
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
    #[allow(clippy::type_complexity)]
    pub fn eval_scaled(&self, t: &F) -> Option<([F; 3], [F; 3], [F; 3])> {
        let s = self.sigma.eval(t);
        let w = self.omega_tilde.eval(t);
        if s.is_zero() || w.is_zero() {
            return None;
        }
        let inv_s = F::one() / s.clone();
        let inv_sw = F::one() / (s * w);
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

    /// `κ = ω/σ² = √c·ω̃/σ²` as `(√c-free numerator ω̃, denominator σ²)`: multiply the
    /// value by `√c`.
    pub fn curvature_scaled(&self) -> RationalFunction<F> {
        RationalFunction {
            num: self.omega_tilde.clone(),
            den: &self.sigma * &self.sigma,
        }
    }

    /// Certificates (NOTES-001 §2 "Frenet"), as polynomial identities over `F`:
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
/// (Choi–Han; the quaternion form of seed 001 §3.3).
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

    /// `ρ = 4|αβ' − α'β|²` from the Hopf form (NOTES-001 ALG-4; seed 001 (4.16), erratum 15).
    pub fn rho_hopf(&self) -> Poly<F> {
        let (re, im) = self.proportionality_re_im();
        (&(&re * &re) + &(&im * &im)).scale(&F::from_i64(4))
    }

    /// Certificates of ALG-4: `|r'×r''|² ≡ σ²·4|αβ'−α'β|²` and
    /// `r'×r'' ≡ 2A(f j + g k)A*` with `αβ'−α'β = g + i f`.
    pub fn certify_curvature(&self) -> Vec<Certificate> {
        let pc = self.to_poly_curve();
        let cr = pc.cross_r1_r2();
        let s2 = &pc.sigma * &pc.sigma;
        let mut certs = vec![identity_cert(
            "|r'×r''|² ≡ σ²·4|αβ'−α'β|² (NOTES-001 ALG-4, seed 001 (4.16))",
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
                format!("[r'×r'']_{k} ≡ [2A(f j + g k)A*]_{k} (NOTES-001 ALG-4, erratum 12)"),
                &cr[k],
                &v[k],
            ));
        }
        certs
    }
}

/// Adaptive Gauss–Legendre (7-point) quadrature of `f` on `[a, b]`.
pub(crate) fn adaptive_gauss(f: &dyn Fn(f64) -> f64, a: f64, b: f64, tol: f64, depth: u32) -> f64 {
    const X: [f64; 7] = [
        -0.949_107_912_342_758_5,
        -0.741_531_185_599_394_4,
        -0.405_845_151_377_397_2,
        0.0,
        0.405_845_151_377_397_2,
        0.741_531_185_599_394_4,
        0.949_107_912_342_758_5,
    ];
    const W: [f64; 7] = [
        0.129_484_966_168_869_7,
        0.279_705_391_489_276_7,
        0.381_830_050_505_118_9,
        0.417_959_183_673_469_4,
        0.381_830_050_505_118_9,
        0.279_705_391_489_276_7,
        0.129_484_966_168_869_7,
    ];
    fn gl(f: &dyn Fn(f64) -> f64, a: f64, b: f64) -> f64 {
        let h = 0.5 * (b - a);
        let c = 0.5 * (a + b);
        X.iter()
            .zip(W.iter())
            .map(|(x, w)| w * f(c + h * x))
            .sum::<f64>()
            * h
    }
    /// Recursion with an absolute tolerance halved per level and an evaluation budget
    /// (so that round-off noise cannot force an exponential refinement).
    fn rec(
        f: &dyn Fn(f64) -> f64,
        a: f64,
        b: f64,
        whole: f64,
        eps: f64,
        depth: u32,
        budget: &mut u32,
    ) -> f64 {
        let m = 0.5 * (a + b);
        let l = gl(f, a, m);
        let r = gl(f, m, b);
        if !(l + r).is_finite() {
            return f64::NAN;
        }
        *budget = budget.saturating_sub(1);
        if depth == 0 || *budget == 0 || (l + r - whole).abs() <= eps {
            l + r
        } else {
            rec(f, a, m, l, 0.5 * eps, depth - 1, budget)
                + rec(f, m, b, r, 0.5 * eps, depth - 1, budget)
        }
    }
    let whole = gl(f, a, b);
    if !whole.is_finite() {
        return f64::NAN;
    }
    let eps = tol * whole.abs().max(1e-300);
    let mut budget = 20_000;
    rec(f, a, b, whole, eps, depth, &mut budget)
}
