//! Double-PH (DPH) curves: the DPH test, the Hopf proportionality polynomial, the
//! classification for degrees 3, 5 and 7, and the septic DPH constructor.
//!
//! * (docs/math/ph-curves.md, "DPH test and the rational Frenet frame"; Besednjak §4.1 (4.2)): a PH curve is DPH iff `ρ = |r'×r''|²/σ²`
//!   is the square of a real polynomial `ω`. Over `Q` we test `ρ = c·ω̃²` with `ω̃ ∈ Q[t]`
//!   monic and `c = lc(ρ) > 0` (often not a rational square, e.g. Besednjak Ex 8.1,
//!   `ω = 6√5·t(t³−2t²+2t+2)`), so `ω = √c·ω̃`.
//! * Hopf form (Besednjak §4.3, (4.15); docs/math/ph-curves.md, Errata E15): `αβ' − α'β = g + i f` with
//!   `f = up'−u'p+vq'−v'q`, `g = uq'−u'q−vp'+v'p` (docs/math/ph-curves.md, Errata E12), and the curve is DPH iff
//!   `αβ' − α'β = h·w²` for a real polynomial `h` and a complex polynomial `w`
//!   (up to a complex constant).
//! * Low degrees (Besednjak §5, docs/math/ph-curves.md, "DPH test and the rational Frenet frame"): with `P_ij = α_iβ_j − α_jβ_i` of the
//!   Bernstein coefficients, every PH cubic is DPH; a quintic is DPH iff
//!   `4P_01P_12 = P_02²` (5.3; `st h = 0`, `st w = 1`, "monotone") or `P_01, P_02, P_12` are
//!   real multiples of one complex number (5.4; `st h = 2`, `st w = 0`, "general").
//! * Septics (Besednjak §5.2, docs/math/ph-curves.md, "Septic DPH constructor", docs/math/ph-curves.md, Errata E16): the constructor below.

use super::hodograph::{PhCurve, PhPolyCurve};
use super::util::*;
use super::PhError;
use rcagd_algebra::bernstein;
use rcagd_algebra::complex::Complex;
use rcagd_algebra::quadratic::{sqrt_in_extension, QuadExt};
use rcagd_algebra::{Certificate, Poly, Scalar};

/// `ρ = c·ω̃²`: the polynomial `ω = √c·ω̃` of a DPH curve (`c > 0`; `c = 1` whenever `c`
/// is a square in `F`, always for `f64`).
#[derive(Debug, Clone, PartialEq)]
pub struct DphData<F> {
    /// The radicand `c`.
    pub c: F,
    /// `ω̃` (monic unless `c` was absorbed).
    pub omega_tilde: Poly<F>,
}

impl<F: Scalar> DphData<F> {
    /// `ω(t) = √c·ω̃(t)` in `f64`.
    pub fn omega_f64(&self, t: f64) -> f64 {
        self.c.to_f64().sqrt() * poly_f64(&self.omega_tilde).eval(&t)
    }
    /// `ω = √c·ω̃` exactly, as a polynomial over the real quadratic field `Q(√c)`
    /// ([`QuadExt`]; rational coefficients when `c` is a square).
    ///
    /// # Errors
    /// [`PhError::Irrational`] if a coefficient is not rational (non-finite `f64`).
    pub fn omega_exact(&self) -> Result<Poly<QuadExt>, PhError> {
        let c = self.c.to_rational().ok_or_else(|| PhError::NonFinite {
            what: "the DPH constant c".into(),
        })?;
        let s = sqrt_in_extension(&c)?;
        let coeffs = self
            .omega_tilde
            .coeffs()
            .iter()
            .map(|x| {
                x.to_rational()
                    .map(|q| QuadExt::rational(q) * s.clone())
                    .ok_or_else(|| PhError::NonFinite {
                        what: "a coefficient of ω̃".into(),
                    })
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Poly::new(coeffs))
    }

    /// `ω² = c·ω̃² = ρ`.
    pub fn omega_squared(&self) -> Poly<F> {
        (&self.omega_tilde * &self.omega_tilde).scale(&self.c)
    }
}

/// Outcome of the DPH test.
#[derive(Debug, Clone, PartialEq)]
pub enum DphTest<F> {
    /// DPH with `ρ = c·ω̃²`.
    Dph(DphData<F>),
    /// Not DPH: `ρ` is not a constant times a square.
    NotDph {
        /// `ρ = |r'×r''|²/σ²`.
        rho: Poly<F>,
    },
    /// `ρ ≡ 0`: a straight line (no Frenet frame).
    Line,
}

impl<F: Scalar> PhPolyCurve<F> {
    /// The DPH test `ρ = c·ω̃²` (docs/math/ph-curves.md, "DPH test and the rational Frenet frame", Besednjak (4.2)).
    ///
    /// # Errors
    /// As [`PhPolyCurve::rho`].
    pub fn dph_test(&self) -> Result<DphTest<F>, PhError> {
        let rho = self.rho()?;
        // a line iff ρ = |r''|² − σ'² ≡ 0 (relative to |r''|² for f64)
        let d2 = pderiv(&pderiv(&self.r));
        let line = if F::EXACT {
            rho.is_zero()
        } else {
            // f64: ρ is a difference of terms of size |r''|²; only round-off noise is a line
            poly_scale(&rho) <= 1e-13 * poly_scale(&pdot(&d2, &d2))
        };
        if line {
            return Ok(DphTest::Line);
        }
        // f64 round-off in ρ = |r''|² − σ'² is about ε·|r''|² per coefficient
        let noise = 1e-14 * poly_scale(&pdot(&d2, &d2));
        match scaled_square(&rho, noise) {
            Some((c, omega_tilde)) => Ok(DphTest::Dph(DphData { c, omega_tilde })),
            None => Ok(DphTest::NotDph { rho }),
        }
    }

    /// The DPH data, or an error naming `ρ`.
    ///
    /// # Errors
    /// [`PhError::NotDph`] if the curve is not DPH (or a line); as [`PhPolyCurve::rho`].
    pub fn dph(&self) -> Result<DphData<F>, PhError> {
        match self.dph_test()? {
            DphTest::Dph(d) => Ok(d),
            DphTest::NotDph { rho } => Err(PhError::NotDph(format!(
                "ρ = |r'×r''|²/σ² = {} is not c·(polynomial)²",
                format_poly(&rho, "t")
            ))),
            DphTest::Line => Err(PhError::NotDph(
                "ρ ≡ 0: a straight line has no Frenet frame".into(),
            )),
        }
    }

    /// Certificate `|r'×r''|² − σ²·c·ω̃² ≡ 0` (docs/math/ph-curves.md, "DPH test and the rational Frenet frame").
    ///
    /// For `f64` each residual coefficient is compared with the magnitude of the terms
    /// that make it up, `|r'|²·|r''|² + σ²·σ'²` with every polynomial's coefficients taken
    /// by absolute value: `|r'×r''|²` is a difference of products of that size, and `ω̃` is
    /// the square root of `ρ = |r''|² − σ'²` (the `f64` DPH test), whose rounding
    /// multiplied by `σ²` is of the same size. Nearly straight helices cancel most of it
    /// (a random draw: residual 4·10⁻⁴ against coefficients of `|r'×r''|²` of about 1, and
    /// terms of about 10¹⁰), which the largest coefficient of either side does not see.
    pub fn certify_dph(&self, dph: &DphData<F>) -> Vec<Certificate> {
        let d1 = pderiv(&self.r);
        let d2 = pderiv(&d1);
        let c = pcross(&d1, &d2);
        let s2 = &self.sigma * &self.sigma;
        let lhs = pdot(&c, &c);
        let rhs = &s2 * &dph.omega_squared();
        let norm2 = |v: &PV3<F>| {
            v.iter()
                .map(abs_poly)
                .fold(Poly::zero(), |acc: Poly<f64>, a| &acc + &(&a * &a))
        };
        let sigma = abs_poly(&self.sigma);
        let dsigma = abs_poly(&self.sigma.derivative());
        let magnitude = &(&norm2(&d1) * &norm2(&d2)) + &(&(&sigma * &sigma) * &(&dsigma * &dsigma));
        vec![identity_cert_within(
            "|r'×r''|² − σ²·c·ω̃² ≡ 0 (DPH, ω = √c·ω̃)",
            &lhs,
            &rhs,
            magnitude.coeffs(),
        )]
    }
}

/// The factorization `αβ' − α'β = λ·h·W²` with `h = gcd(Re, Im)` real monic, `W` monic
/// complex and `λ` a complex constant (Besednjak §4.3; docs/math/ph-curves.md, "DPH test and the rational Frenet frame" Hopf form). `h`
/// is the maximal real factor, so in the degenerate overlaps of Besednjak §6.2 (a real
/// square factor of `w²`) it absorbs that factor.
#[derive(Debug, Clone, PartialEq)]
pub struct ProportionalityFactors<F> {
    /// The complex constant `λ`.
    pub lambda: Complex<F>,
    /// The real factor `h` (monic).
    pub h: Poly<F>,
    /// The complex factor `W` (monic); `w = √λ·W`.
    pub w: Poly<Complex<F>>,
}

/// Kind of a DPH quintic by the conditions (5.3)/(5.4) of Besednjak §5.1.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum QuinticDphKind {
    /// `4P_01P_12 = P_02²` (`st h = 0`, `st w = 1`; a monotone helix).
    Monotone,
    /// `P_01, P_02, P_12` real multiples of one complex number (`st h = 2`, `st w = 0`; a
    /// general helix).
    General,
    /// Both conditions (degenerate overlap, Besednjak §6.2.3 end).
    Both,
    /// Neither: not DPH.
    NotDph,
    /// `P_01 = P_02 = P_12 = 0`: a straight line.
    Line,
}

/// Classification of a PH curve.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum DphClass {
    /// Not DPH.
    NotDph,
    /// A straight line (`αβ' − α'β ≡ 0`).
    Line,
    /// DPH with `αβ' − α'β = λ h W²`, `deg h = h_degree`, `deg W = w_degree`, and whether
    /// the curve is a helix (decided by the exact axis test, docs/math/ph-curves.md, "Helix test and axis").
    Dph {
        /// `st(h)`.
        h_degree: usize,
        /// `st(w)`.
        w_degree: usize,
        /// `true` for a (possibly planar) helix.
        helical: bool,
    },
}

impl<F: Scalar> PhCurve<F> {
    /// The proportionality polynomial `αβ' − α'β` (Besednjak (4.15)).
    pub fn proportionality(&self) -> Poly<Complex<F>> {
        let (a, b) = self.hopf_polys();
        &(&a * &b.derivative()) - &(&a.derivative() * &b)
    }

    /// `(g, f)` with `αβ' − α'β = g + i f`, `f = up'−u'p+vq'−v'q`, `g = uq'−u'q−vp'+v'p`
    /// (Besednjak (4.9), corrected: docs/math/ph-curves.md, Errata E12).
    pub fn proportionality_re_im(&self) -> (Poly<F>, Poly<F>) {
        let p = self.proportionality();
        (p.map(|c| c.re.clone()), p.map(|c| c.im.clone()))
    }

    /// The Bernstein products `P_ij = α_iβ_j − α_jβ_i` of the Hopf coefficients
    /// (Besednjak §5), as a full antisymmetric table.
    pub fn plucker(&self) -> Vec<Vec<Complex<F>>> {
        let (a, b) = self.hopf_coefficients();
        let n = a.len();
        (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| csub(&cmul(&a[i], &b[j]), &cmul(&a[j], &b[i])))
                    .collect()
            })
            .collect()
    }

    /// `αβ' − α'β = λ h W²` (see [`ProportionalityFactors`]); `None` if the curve is not
    /// DPH (the quotient by `h` is not a constant times a square).
    ///
    /// # Errors
    /// [`PhError::Degenerate`] for a straight line (`αβ' − α'β ≡ 0`).
    pub fn proportionality_factors(&self) -> Result<Option<ProportionalityFactors<F>>, PhError> {
        let p = self.proportionality();
        if cpoly_negligible(&p, 1.0) && (F::EXACT || p.is_zero()) {
            return Err(PhError::Degenerate(
                "αβ' − α'β ≡ 0: the curve is a straight line".into(),
            ));
        }
        let (re, im) = (p.map(|c| c.re.clone()), p.map(|c| c.im.clone()));
        let h = if re.is_zero() {
            im.monic()
        } else if im.is_zero() {
            re.monic()
        } else {
            gcd_tol(&re, &im)
        };
        let hc = h.map(|c| Complex::new(c.clone(), F::zero()));
        let Ok((q, _)) = p.div_rem(&hc) else {
            return Ok(None);
        };
        let lambda = q.leading();
        let Some(inv) = cdiv(&Complex::new(F::one(), F::zero()), &lambda) else {
            return Ok(None);
        };
        let qm = q.map(|c| cmul(c, &inv));
        Ok(cpoly_monic_sqrt(&qm).map(|w| ProportionalityFactors { lambda, h, w }))
    }

    /// Classification (docs/math/ph-curves.md, "DPH test and the rational Frenet frame" and "Septic DPH constructor"): DPH or not by `αβ' − α'β = λhW²`
    /// (cross-checked with `ρ = c·ω̃²`), `st(h)`, `st(w)`, and helicity by the axis test.
    ///
    /// # Errors
    /// As [`PhPolyCurve::rho`].
    pub fn classify(&self) -> Result<DphClass, PhError> {
        let pc = self.to_poly_curve();
        match pc.dph_test()? {
            DphTest::Line => return Ok(DphClass::Line),
            DphTest::NotDph { .. } => return Ok(DphClass::NotDph),
            DphTest::Dph(_) => {}
        }
        let f = match self.proportionality_factors() {
            Ok(Some(f)) => f,
            Ok(None) => return Ok(DphClass::NotDph),
            Err(_) => return Ok(DphClass::Line),
        };
        let helical = matches!(
            pc.helix_test()?,
            super::HelixTest::Helix(_) | super::HelixTest::Planar { .. } | super::HelixTest::Line
        );
        Ok(DphClass::Dph {
            h_degree: f.h.degree().unwrap_or(0),
            w_degree: f.w.degree().unwrap_or(0),
            helical,
        })
    }

    /// For a quintic (`m = 2`), the conditions (5.3)/(5.4) of Besednjak §5.1 on
    /// `P_01, P_02, P_12`.
    ///
    /// # Errors
    /// [`PhError::DegreeMismatch`] if the curve is not a quintic.
    pub fn quintic_dph_kind(&self) -> Result<QuinticDphKind, PhError> {
        if self.preimage_degree() != 2 {
            return Err(PhError::DegreeMismatch(format!(
                "the quintic DPH conditions need a quadratic preimage, got degree {}",
                self.preimage_degree()
            )));
        }
        let p = self.plucker();
        let (p01, p02, p12) = (p[0][1].clone(), p[0][2].clone(), p[1][2].clone());
        let scale = [&p01, &p02, &p12]
            .iter()
            .map(|c| cnorm_sq(c).to_f64())
            .fold(0.0, f64::max);
        let zero = |c: &Complex<F>| {
            is_negligible(&c.re, scale.sqrt()) && is_negligible(&c.im, scale.sqrt())
        };
        if zero(&p01) && zero(&p02) && zero(&p12) {
            return Ok(QuinticDphKind::Line);
        }
        let mono = csub(
            &cscale(&cmul(&p01, &p12), &F::from_i64(4)),
            &cmul(&p02, &p02),
        );
        let monotone = is_negligible(&mono.re, scale) && is_negligible(&mono.im, scale);
        let im_conj = |a: &Complex<F>, b: &Complex<F>| {
            let v = cmul(&Complex::new(a.re.clone(), -a.im.clone()), b).im;
            is_negligible(&v, scale)
        };
        let general = im_conj(&p01, &p02) && im_conj(&p01, &p12) && im_conj(&p02, &p12);
        Ok(match (monotone, general) {
            (true, true) => QuinticDphKind::Both,
            (true, false) => QuinticDphKind::Monotone,
            (false, true) => QuinticDphKind::General,
            (false, false) => QuinticDphKind::NotDph,
        })
    }

    /// Certificate `αβ' − α'β ≡ λ·h·W²` of a factorization.
    pub fn certify_proportionality(&self, f: &ProportionalityFactors<F>) -> Vec<Certificate> {
        let p = self.proportionality();
        let hc = f.h.map(|c| Complex::new(c.clone(), F::zero()));
        let rhs = (&hc * &(&f.w * &f.w)).map(|c| cmul(c, &f.lambda));
        let d = &p - &rhs;
        let scale = cpoly_scale(&p);
        vec![Certificate::decide(
            "αβ' − α'β ≡ λ·h·W² (Hopf DPH form, Besednjak §4.3)",
            cpoly_negligible(&d, scale),
            F::EXACT,
            || format!("{} non-zero residual coefficients", d.coeffs().len()),
        )]
    }
}

/// Bernstein coefficients (degree 4) `T_k` of `h·w²` for the septic constructor.
fn septic_targets<F: Scalar>(h: &[F], w: &[Complex<F>]) -> Result<Vec<Complex<F>>, PhError> {
    if h.is_empty() || w.is_empty() || (h.len() - 1) + 2 * (w.len() - 1) != 4 {
        return Err(PhError::DegreeMismatch(format!(
            "a septic DPH curve needs st(h) + 2·st(w) = 4 (cases (0,2), (2,1), (4,0)), got st(h) = {}, st(w) = {}",
            h.len() as i64 - 1,
            w.len() as i64 - 1
        )));
    }
    let hc: Vec<Complex<F>> = h
        .iter()
        .map(|x| Complex::new(x.clone(), F::zero()))
        .collect();
    let w2 = bernstein::product(w, w);
    Ok(bernstein::product(&hc, &w2))
}

/// Certificates of a septic built by [`dph_septic`] from `h`, `w` (Besednjak (5.5);
/// docs/math/ph-curves.md, "Septic DPH constructor"): the PH identity of [`PhCurve::certify`], the prescribed Hopf form
/// `αβ' − α'β ≡ h·w²` (real and imaginary parts, power form), and the DPH identity
/// `|r'×r''|² ≡ σ²·4|h w²|²` (so `ω = 2|h||w|²` is a polynomial).
///
/// # Errors
/// [`PhError::DegreeMismatch`] unless `st h + 2 st w = 4`.
pub fn certify_dph_septic<F: Scalar>(
    curve: &PhCurve<F>,
    h: &[F],
    w: &[Complex<F>],
) -> Result<Vec<Certificate>, PhError> {
    let t = septic_targets(h, w)?;
    let hw2 = cpoly_from_bernstein(&t);
    let d = &curve.proportionality() - &hw2;
    let (re, im) = (d.map(|c| c.re.clone()), d.map(|c| c.im.clone()));
    let mut certs = curve.certify();
    certs.push(identity_cert(
        "Re(αβ' − α'β − h w²) ≡ 0 (Besednjak (5.5))",
        &re,
        &Poly::zero(),
    ));
    certs.push(identity_cert(
        "Im(αβ' − α'β − h w²) ≡ 0 (Besednjak (5.5))",
        &im,
        &Poly::zero(),
    ));
    let pc = curve.to_poly_curve();
    let cr = pc.cross_r1_r2();
    let (hr, hi) = (hw2.map(|c| c.re.clone()), hw2.map(|c| c.im.clone()));
    let rho = (&(&hr * &hr) + &(&hi * &hi)).scale(&F::from_i64(4));
    let s2 = pc.speed() * pc.speed();
    certs.push(identity_cert(
        "|r'×r''|² ≡ σ²·4|h w²|² (DPH: ω = 2|h||w|²)",
        &pdot(&cr, &cr),
        &(&s2 * &rho),
    ));
    Ok(certs)
}

/// The two admissible values of `z = α_1β_2 − α_2β_1` for a septic DPH curve with
/// `αβ' − α'β = h w²` (Besednjak (5.8), (5.10) corrected: docs/math/ph-curves.md, Errata E16, (5.12)):
/// `27z² − 18T_2 z − (T_0T_4 − 4T_1T_3) = 0`, i.e. `z = (3T_2 ± √Δ)/9` with
/// `Δ = 9T_2² + 3T_0T_4 − 12T_1T_3` (`T_k` the Bernstein coefficients of `h w²`; for
/// `st h = 4`, `st w = 0` this is `Δ = (9h_2² + 3h_0h_4 − 12h_1h_3)w_0⁴`, docs/math/ph-curves.md, Errata E22).
/// Returned as `[(3T_2 + √Δ)/9, (3T_2 − √Δ)/9]` with the principal square root.
///
/// # Errors
/// [`PhError::DegreeMismatch`] unless `st h + 2 st w = 4`; [`PhError::Irrational`] if
/// `√Δ ∉ F(i)`.
pub fn dph_septic_z_roots<F: Scalar>(
    h: &[F],
    w: &[Complex<F>],
) -> Result<[Complex<F>; 2], PhError> {
    let t = septic_targets(h, w)?;
    let nine = F::from_i64(9);
    let delta = csub(
        &cadd(
            &cscale(&cmul(&t[2], &t[2]), &nine),
            &cscale(&cmul(&t[0], &t[4]), &F::from_i64(3)),
        ),
        &cscale(&cmul(&t[1], &t[3]), &F::from_i64(12)),
    );
    let sq = csqrt(&delta).ok_or_else(|| {
        PhError::Irrational(format!(
            "√Δ with Δ = {} is not in F(i)",
            fmt_complex(&delta)
        ))
    })?;
    let three_t2 = cscale(&t[2], &F::from_i64(3));
    let inv9 = F::one() / nine;
    Ok([
        cscale(&cadd(&three_t2, &sq), &inv9),
        cscale(&csub(&three_t2, &sq), &inv9),
    ])
}

/// The septic DPH curve with `αβ' − α'β = h w²` (Bernstein coefficients `h_i` real,
/// `w_i` complex, `st h + 2 st w = 4`), free coefficients `α_0, α_1, β_0` and
/// `z = α_1β_2 − α_2β_1` (a root from [`dph_septic_z_roots`]) (Besednjak §5.2, (5.5)–(5.12);
/// docs/math/ph-curves.md, "Septic DPH constructor"). Equating the Bernstein coefficients
/// `3P_01, 3/2 P_02, 1/2 P_03 + 3/2 P_12, 3/2 P_13, 3P_23` with those of `h w²` gives
/// `β_1 = (P_01 + α_1β_0)/α_0`, then the linear systems
/// `α_1β_2 − α_2β_1 = z`, `α_0β_2 − α_2β_0 = P_02` and `α_0β_3 − α_3β_0 = P_03`,
/// `α_1β_3 − α_3β_1 = P_13`; the last equation `P_23 = T_4/3` holds iff `z` is a root.
///
/// # Errors
/// [`PhError::DegreeMismatch`] as above; [`PhError::Degenerate`] if `α_0 = 0` or
/// `P_01 = T_0/3 = 0`; [`PhError::NoRealSolution`] if `z` is not a root (the last
/// equation fails).
pub fn dph_septic<F: Scalar>(
    h: &[F],
    w: &[Complex<F>],
    alpha0: &Complex<F>,
    alpha1: &Complex<F>,
    beta0: &Complex<F>,
    z: &Complex<F>,
    start: [F; 3],
) -> Result<PhCurve<F>, PhError> {
    let t = septic_targets(h, w)?;
    let third = F::one() / F::from_i64(3);
    let two_thirds = F::from_i64(2) / F::from_i64(3);
    let p01 = cscale(&t[0], &third);
    let p02 = cscale(&t[1], &two_thirds);
    let p03 = csub(&cscale(&t[2], &F::from_i64(2)), &cscale(z, &F::from_i64(3)));
    let p13 = cscale(&t[3], &two_thirds);
    let p23 = cscale(&t[4], &third);
    if cis_zero(&p01) {
        return Err(PhError::Degenerate(
            "P_01 = h_0 w_0²/3 must be non-zero".into(),
        ));
    }
    let beta1 = cdiv(&cadd(&p01, &cmul(alpha1, beta0)), alpha0)
        .ok_or_else(|| PhError::Degenerate("α_0 must be non-zero".into()))?;
    let neg_p01 = cscale(&p01, &-F::one());
    let err = || PhError::Degenerate("P_01 must be non-zero".into());
    let alpha2 = cdiv(&csub(&cmul(z, alpha0), &cmul(alpha1, &p02)), &neg_p01).ok_or_else(err)?;
    let beta2 = cdiv(&csub(&cmul(beta0, z), &cmul(&beta1, &p02)), &neg_p01).ok_or_else(err)?;
    let alpha3 = cdiv(&csub(&cmul(&p03, alpha1), &cmul(alpha0, &p13)), &p01).ok_or_else(err)?;
    let beta3 = cdiv(&csub(&cmul(&beta1, &p03), &cmul(beta0, &p13)), &p01).ok_or_else(err)?;
    let got = csub(&cmul(&alpha2, &beta3), &cmul(&alpha3, &beta2));
    let d = csub(&got, &p23);
    let scale = cnorm_sq(&p23).to_f64().sqrt();
    if !(is_negligible(&d.re, scale) && is_negligible(&d.im, scale)) {
        return Err(PhError::NoRealSolution(format!(
            "z = {} is not a root of the quadratic (5.12): P_23 − T_4/3 = {}",
            fmt_complex(z),
            fmt_complex(&d)
        )));
    }
    PhCurve::from_hopf(
        &[alpha0.clone(), alpha1.clone(), alpha2, alpha3],
        &[beta0.clone(), beta1, beta2, beta3],
        start,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn r(p: i64, q: i64) -> Rational {
        Rational::from(p) / Rational::from(q)
    }

    /// The septic DPH curve of `w`, `h = 1`, `(α₀, α₁, β₀)` and root `which` of the
    /// z-quadratic (start at the origin): the exact and the `f64` DPH tests both accept it.
    fn assert_septic_dph_agrees(
        w: [Complex<Rational>; 3],
        ab: [Complex<Rational>; 3],
        which: usize,
    ) {
        let h = [r(1, 1)];
        let roots = dph_septic_z_roots(&h, &w).unwrap();
        let [a0, a1, b0] = ab;
        let c = dph_septic(
            &h,
            &w,
            &a0,
            &a1,
            &b0,
            &roots[which],
            [r(0, 1), r(0, 1), r(0, 1)],
        )
        .unwrap();
        let pc = c.to_poly_curve();
        let exact = pc.dph_test().unwrap();
        let approx = pc.to_f64().dph_test().unwrap();
        assert!(matches!(exact, DphTest::Dph(_)));
        assert!(matches!(approx, DphTest::Dph(_)));
    }

    /// Regression: a large septic (cancellation in f64 ρ).
    #[test]
    fn septic_large_f64_agrees() {
        assert_septic_dph_agrees(
            [
                cx(r(-3, 1), r(2, 1)),
                cx(r(-2, 1), r(4, 1)),
                cx(r(0, 1), r(0, 1)),
            ],
            [
                cx(r(-3, 1), r(1, 1)),
                cx(r(0, 1), r(-1, 1)),
                cx(r(0, 1), r(4, 1)),
            ],
            0,
        );
    }

    /// Regression: f64 DPH test on a septic with `α_1 = β_0 = 0`.
    #[test]
    fn septic_sparse_f64_agrees() {
        assert_septic_dph_agrees(
            [
                cx(r(-2, 1), r(-5, 3)),
                cx(r(1, 1), r(0, 1)),
                cx(r(4, 1), r(1, 1)),
            ],
            [
                cx(r(0, 1), r(-1, 1)),
                cx(r(0, 1), r(0, 1)),
                cx(r(0, 1), r(0, 1)),
            ],
            1,
        );
    }

    /// Regression: `w = i·(real)` (degenerate overlap, `αβ' − α'β` real).
    #[test]
    fn septic_imaginary_w_f64_agrees() {
        assert_septic_dph_agrees(
            [
                cx(r(0, 1), r(1, 2)),
                cx(r(0, 1), r(2, 1)),
                cx(r(0, 1), r(2, 1)),
            ],
            [
                cx(r(0, 1), r(-1, 3)),
                cx(r(0, 1), r(2, 1)),
                cx(r(3, 1), r(-1, 1)),
            ],
            0,
        );
    }

    /// Regression: `w` with a real root (degenerate overlap); f64 must agree with exact.
    #[test]
    fn septic_with_real_root_of_w_f64_agrees() {
        assert_septic_dph_agrees(
            [
                cx(r(0, 1), r(1, 3)),
                cx(r(2, 1), r(0, 1)),
                cx(r(0, 1), r(0, 1)),
            ],
            [
                cx(r(0, 1), r(-1, 1)),
                cx(r(5, 1), r(0, 1)),
                cx(r(1, 1), r(0, 1)),
            ],
            1,
        );
    }
}
