//! The quaternion forms of the DPH condition (Besednjak, "DPH-krivulje in polinomske
//! vijačnice", §4.2–4.3: Prop. 4.6, (4.12), (4.20), (4.21)).
//!
//! For a PH curve `r' = A i A*`, `A = u + vi + pj + qk`, let
//! `f = up' − u'p + vq' − v'q`, `g = uq' − u'q − vp' + v'p` (ibid. (4.9), with the sign of
//! the last term of `g` corrected); then `r'×r'' = 2A(f j + g k)A*` and `ρ = 4(f² + g²)`.
//! The curve is DPH iff `f + i g = h·w²` with a real polynomial `h` and `w = a + i b`,
//! `gcd(a, b) = 1` ((4.12)). Then
//!
//! * Prop. 4.6: `r'×r'' = h·B i B*` with `B = A·C`, `C = −b + a i + a j + b k`;
//! * (4.20): `j(αβ' − α'β) = ½(A*A' − A'*A) × i` (every PH curve; `× i` is the cross
//!   product of the vector part with `i`);
//! * (4.21): `(A*A' − A'*A) × i = h̃·D i D*` with `D = −ã + b̃ i − b̃ j − ã k`, where
//!   `αβ' − α'β = h̃·(ã + i b̃)²` is the Hopf form. The thesis builds `D = jC` from the
//!   `a, b` of (4.12); with those the identity fails (it swaps `f` and `g`, the misprint of
//!   (4.18)): corrected in `docs/math/ph-preimage.md#dph-forms`.
//!
//! In the Hopf form `αβ' − α'β = g + i f` (ibid. (4.15)), so `f + i g = i·conj(αβ' − α'β)`:
//! the `w` of (4.12) is the conjugate of the Hopf factor up to a constant (the printed
//! (4.18) swaps real and imaginary parts; see `docs/math/ph-preimage.md#dph-forms`). From
//! the factorization `αβ' − α'β = λ·h₀·W²` (`W` monic) we get `f + i g = z·h₀·W̄²`,
//! `z = i λ̄`, and `z = κ μ²` with real `κ` and `μ ∈ Q(i)` exactly when `z` is real or
//! `|z|` is rational (`μ = |z| + z`): then `h = κ h₀`, `w = μ W̄` are rational.

use super::hodograph::PhCurve;
use super::util::*;
use super::PhError;
use rcagd_algebra::complex::Complex;
use rcagd_algebra::{Certificate, Poly, Scalar};

/// A quaternion polynomial `[u, v, p, q]` (power form): `u + v i + p j + q k`.
pub type QuatPoly<F> = [Poly<F>; 4];

/// The quaternion DPH forms of a DPH curve (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct DphQuaternionForms<F> {
    /// The curve.
    pub curve: PhCurve<F>,
    /// `f = up' − u'p + vq' − v'q`.
    pub f: Poly<F>,
    /// `g = uq' − u'q − vp' + v'p`.
    pub g: Poly<F>,
    /// The real factor `h` of `f + i g = h·(a + i b)²`.
    pub h: Poly<F>,
    /// `a = Re w`.
    pub a: Poly<F>,
    /// `b = Im w`.
    pub b: Poly<F>,
    /// `C = −b + a i + a j + b k`.
    pub c: QuatPoly<F>,
    /// `B = A·C` with `r'×r'' = h·B i B*` (Prop. 4.6).
    pub b_quat: QuatPoly<F>,
    /// The real factor `h̃` of the Hopf form `αβ' − α'β = h̃·(ã + i b̃)²`.
    pub h_hopf: Poly<F>,
    /// `ã`.
    pub a_hopf: Poly<F>,
    /// `b̃`.
    pub b_hopf: Poly<F>,
    /// `D = −ã + b̃ i − b̃ j − ã k` with `(A*A' − A'*A) × i = h̃·D i D*` ((4.21), corrected).
    pub d: QuatPoly<F>,
}

fn qp_mul<F: Scalar>(a: &QuatPoly<F>, b: &QuatPoly<F>) -> QuatPoly<F> {
    let m = |x: &Poly<F>, y: &Poly<F>| x * y;
    [
        &(&(&m(&a[0], &b[0]) - &m(&a[1], &b[1])) - &m(&a[2], &b[2])) - &m(&a[3], &b[3]),
        &(&(&m(&a[0], &b[1]) + &m(&a[1], &b[0])) + &m(&a[2], &b[3])) - &m(&a[3], &b[2]),
        &(&(&m(&a[0], &b[2]) - &m(&a[1], &b[3])) + &m(&a[2], &b[0])) + &m(&a[3], &b[1]),
        &(&(&m(&a[0], &b[3]) + &m(&a[1], &b[2])) - &m(&a[2], &b[1])) + &m(&a[3], &b[0]),
    ]
}

/// The vector part of `X i X*`: `(x₀² + x₁² − x₂² − x₃², 2(x₀x₃ + x₁x₂), 2(x₁x₃ − x₀x₂))`.
fn qp_sandwich_i<F: Scalar>(x: &QuatPoly<F>) -> [Poly<F>; 3] {
    let two = F::from_i64(2);
    [
        &(&(&x[0] * &x[0]) + &(&x[1] * &x[1])) - &(&(&x[2] * &x[2]) + &(&x[3] * &x[3])),
        (&(&x[0] * &x[3]) + &(&x[1] * &x[2])).scale(&two),
        (&(&x[1] * &x[3]) - &(&x[0] * &x[2])).scale(&two),
    ]
}

/// The vector part `V` of `A*A' − A'*A` (twice the vector part of `A*A'`).
fn a_star_a_prime<F: Scalar>(a: &QuatPoly<F>) -> [Poly<F>; 3] {
    let conj = [a[0].clone(), -a[1].clone(), -a[2].clone(), -a[3].clone()];
    let d = [
        a[0].derivative(),
        a[1].derivative(),
        a[2].derivative(),
        a[3].derivative(),
    ];
    let p = qp_mul(&conj, &d);
    let two = F::from_i64(2);
    [p[1].scale(&two), p[2].scale(&two), p[3].scale(&two)]
}

/// `V × i = (0, V_z, −V_y)`.
fn cross_i<F: Scalar>(v: &[Poly<F>; 3]) -> [Poly<F>; 3] {
    [Poly::zero(), v[2].clone(), -v[1].clone()]
}

/// `z·h₀·W² = h·(a + i b)²` with real `h = κ h₀`, `a + i b = μ W`, `z = κ μ²` (module
/// docs).
#[allow(clippy::type_complexity)]
fn real_times_square<F: Scalar>(
    z: &Complex<F>,
    h0: &Poly<F>,
    w: &Poly<Complex<F>>,
) -> Result<(Poly<F>, Poly<F>, Poly<F>), PhError> {
    let (kappa, mu) = if is_negligible(&z.im, z.re.to_f64().abs()) {
        (z.re.clone(), cx(F::one(), F::zero()))
    } else {
        let n2 = cnorm_sq(z);
        let r = sqrt_scalar(&n2).ok_or_else(|| {
            PhError::Irrational(format!(
                "the constant {} of the DPH form has the irrational modulus √({}), so h and w are not rational",
                fmt_complex(z),
                fmt_scalar(&n2)
            ))
        })?;
        let mu = cx(r + z.re.clone(), z.im.clone());
        let k = cdiv(z, &cmul(&mu, &mu))
            .ok_or_else(|| PhError::Degenerate("the constant of the DPH form is zero".into()))?;
        (k.re, mu)
    };
    let w = w.map(|c| cmul(&mu, c));
    Ok((
        h0.scale(&kappa),
        w.map(|c: &Complex<F>| c.re.clone()),
        w.map(|c: &Complex<F>| c.im.clone()),
    ))
}

/// The quaternion DPH forms of `curve` (module docs).
///
/// # Errors
/// [`PhError::Degenerate`] for a straight line, [`PhError::NotDph`] if the curve is not
/// DPH, [`PhError::Irrational`] if `h` and `w` need a square root (module docs).
pub fn dph_quaternion_forms<F: Scalar>(
    curve: &PhCurve<F>,
) -> Result<DphQuaternionForms<F>, PhError> {
    let factors = curve.proportionality_factors()?.ok_or_else(|| {
        PhError::NotDph("αβ' − α'β is not a real polynomial times a square".into())
    })?;
    let (g, f) = curve.proportionality_re_im();
    // f + i g = i·conj(αβ' − α'β) = z·h₀·W̄², z = i·conj(λ)
    let lam = &factors.lambda;
    let z = cx(lam.im.clone(), lam.re.clone());
    let w_bar = factors.w.map(|c| cx(c.re.clone(), -c.im.clone()));
    let (h, a, b) = real_times_square(&z, &factors.h, &w_bar)?;
    // αβ' − α'β = λ·h₀·W² for (4.21)
    let (h_hopf, a_hopf, b_hopf) = real_times_square(lam, &factors.h, &factors.w)?;
    let c = [-b.clone(), a.clone(), a.clone(), b.clone()];
    let aq = curve.preimage();
    let b_quat = qp_mul(&aq, &c);
    let j = [
        Poly::zero(),
        Poly::zero(),
        Poly::constant(F::one()),
        Poly::zero(),
    ];
    let c_hopf = [
        -b_hopf.clone(),
        a_hopf.clone(),
        a_hopf.clone(),
        b_hopf.clone(),
    ];
    let d = qp_mul(&j, &c_hopf);
    Ok(DphQuaternionForms {
        curve: curve.clone(),
        f,
        g,
        h,
        a,
        b,
        c,
        b_quat,
        h_hopf,
        a_hopf,
        b_hopf,
        d,
    })
}

impl<F: Scalar> DphQuaternionForms<F> {
    /// Certificates: (4.12) `f ≡ h(a² − b²)`, `g ≡ 2hab`; Prop. 4.6 `r'×r'' ≡ h·B i B*`;
    /// (4.20) `j(αβ' − α'β) ≡ ½(A*A' − A'*A) × i`; (4.21) `(A*A' − A'*A) × i ≡ h·D i D*`
    /// (each component, power form).
    pub fn certify(&self) -> Vec<Certificate> {
        let two = F::from_i64(2);
        let (a, b, h) = (&self.a, &self.b, &self.h);
        let mut certs = vec![
            identity_cert(
                "f − h(a² − b²) ≡ 0 (Besednjak (4.12))",
                &self.f,
                &(h * &(&(a * a) - &(b * b))),
            ),
            identity_cert(
                "g − 2hab ≡ 0 (Besednjak (4.12))",
                &self.g,
                &(&(h * a) * b).scale(&two),
            ),
        ];
        let r1 = self.curve.hodograph();
        let r2 = pderiv(&r1);
        let cross = pcross(&r1, &r2);
        let bib = qp_sandwich_i(&self.b_quat);
        let axes = ["x", "y", "z"];
        for k in 0..3 {
            certs.push(identity_cert(
                format!(
                    "(r'×r'')_{} − h·(B i B*)_{} ≡ 0, B = A·C (Besednjak Prop. 4.6)",
                    axes[k], axes[k]
                ),
                &cross[k],
                &(h * &bib[k]),
            ));
        }
        let v = cross_i(&a_star_a_prime(&self.curve.preimage()));
        // j(g + f i) = g j − f k
        let jp = [Poly::zero(), self.g.clone(), -self.f.clone()];
        let half = F::one() / two;
        let did = qp_sandwich_i(&self.d);
        for k in 0..3 {
            certs.push(identity_cert(
                format!(
                    "(j(αβ' − α'β))_{} − ½((A*A' − A'*A) × i)_{} ≡ 0 (Besednjak (4.20))",
                    axes[k], axes[k]
                ),
                &jp[k],
                &v[k].scale(&half),
            ));
            certs.push(identity_cert(
                format!(
                    "((A*A' − A'*A) × i)_{} − h̃·(D i D*)_{} ≡ 0, D = −ã + b̃i − b̃j − ãk with αβ' − α'β = h̃(ã + ib̃)² (Besednjak (4.21), corrected: docs/math/ph-preimage.md#dph-forms)",
                    axes[k], axes[k]
                ),
                &v[k],
                &(&self.h_hopf * &did[k]),
            ));
        }
        certs
    }
}
