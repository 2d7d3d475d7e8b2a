//! Analysis of a given polynomial space curve: the PH test, the parametric speed `σ`,
//! `ρ = |r'×r''|²/σ²` with its degree bound, the DPH test, the helix test with its axis
//! and `κ/τ`, and the Frenet data at a parameter, all exact.
//!
//! For a PH curve of degree `n = 2m + 1` with preimage `A = α + kβ`,
//! `ρ = 4|αβ' − α'β|²` (Besednjak, "DPH-krivulje in polinomske vijačnice", (3.17)); the
//! leading terms of `αβ' − α'β` cancel, so `deg ρ ≤ 4m − 4 = 2n − 6` (ibid. Prop. 3.8).
//!
//! **Frenet data at a rational parameter.** With `|σr'' − σ'r'|² = σ²ρ` and
//! `|r'×r''|² = σ²ρ` (ibid. (3.17)–(3.18)), at a parameter `t₀` with `σ(t₀)ρ(t₀) ≠ 0`
//!
//! `t = r'/σ`, `p = (σr'' − σ'r')/(σ√ρ)`, `b = (r'×r'')/(σ√ρ)`, `κ = √ρ/σ²`,
//! `τ = ((r'×r'')·r''')/(σ²ρ)`,
//!
//! so `t` and `τ` are rational and `p`, `b`, `κ` lie in `Q(√ρ(t₀))` for every PH curve
//! (not only for DPH curves, whose frame is rational in `t` up to one constant).

use super::dph::DphTest;
use super::helix::HelixTest;
use super::hodograph::PhPolyCurve;
use super::util::*;
use super::PhError;
use rcagd_algebra::quadratic::{sqrt_in_extension, QuadExt};
use rcagd_algebra::{Certificate, Poly, Rational, Scalar};

/// The analysis of a PH curve (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct PhAnalysis<F> {
    /// The curve with its parametric speed `σ`.
    pub curve: PhPolyCurve<F>,
    /// `ρ = |r'×r''|²/σ²`.
    pub rho: Poly<F>,
    /// The DPH test `ρ = c·ω̃²`.
    pub dph: DphTest<F>,
    /// The helix test `a·r' ≡ σ`.
    pub helix: HelixTest<F>,
}

/// The Frenet data of a PH curve at one parameter (module docs): `p`, `b` and `κ` as
/// rational vectors and numbers scaled by `√d`, `d = ρ(t₀)`.
#[derive(Debug, Clone, PartialEq)]
pub struct FrenetAt<F> {
    /// The point `r(t₀)`.
    pub point: [F; 3],
    /// The unit tangent `r'/σ`.
    pub tangent: [F; 3],
    /// The radicand `d = ρ(t₀) > 0`.
    pub radicand: F,
    /// `√d·p = (σr'' − σ'r')/σ`.
    pub normal_scaled: [F; 3],
    /// `√d·b = (r'×r'')/σ`.
    pub binormal_scaled: [F; 3],
    /// `κ/√d = 1/σ²`.
    pub curvature_over_root: F,
    /// The torsion `τ = ((r'×r'')·r''')/(σ²ρ)`.
    pub torsion: F,
}

/// The outcome of the PH test of a polynomial curve.
#[derive(Debug, Clone, PartialEq)]
pub enum PhTest<F> {
    /// `|r'|² = σ²` for a polynomial `σ`: the full analysis.
    Ph(Box<PhAnalysis<F>>),
    /// `|r'|²` is not the square of a polynomial.
    NotPh {
        /// `|r'|² = x'² + y'² + z'²`.
        speed_squared: Poly<F>,
    },
}

impl<F: Scalar> PhTest<F> {
    /// The certificates of the answer: [`PhAnalysis::certify`] for a PH curve; for a
    /// curve that is not PH, the exact decision that `|r'|²` has no polynomial square
    /// root (a square root of a polynomial is unique up to sign and is computed exactly
    /// by the coefficient recursion, so its failure is a proof over `Q`).
    pub fn certify(&self) -> Vec<Certificate> {
        match self {
            PhTest::Ph(a) => a.certify(),
            PhTest::NotPh { speed_squared } => {
                let prop = format!(
                    "|r'|² = {} is not the square of a polynomial (not PH)",
                    format_poly(speed_squared, "t")
                );
                vec![match poly_sqrt(speed_squared) {
                    None => Certificate::holds(prop, F::EXACT),
                    Some(s) => {
                        Certificate::fails(prop, format!("σ = {}", format_poly(&s, "t")), F::EXACT)
                    }
                }]
            }
        }
    }
}

/// The PH test of the polynomial curve `r(t)` and, for a PH curve, its analysis.
///
/// # Errors
/// [`PhError::ZeroHodograph`] for a constant curve.
pub fn ph_test<F: Scalar>(r: [Poly<F>; 3]) -> Result<PhTest<F>, PhError> {
    let d = pderiv(&r);
    let speed_squared = pdot(&d, &d);
    match analyze(r) {
        Ok(a) => Ok(PhTest::Ph(Box::new(a))),
        Err(PhError::NotPh(_)) => Ok(PhTest::NotPh { speed_squared }),
        Err(e) => Err(e),
    }
}

/// Analyses the polynomial curve `r(t)`.
///
/// # Errors
/// [`PhError::NotPh`] if `|r'|²` is not the square of a polynomial,
/// [`PhError::ZeroHodograph`] for a constant curve.
pub fn analyze<F: Scalar>(r: [Poly<F>; 3]) -> Result<PhAnalysis<F>, PhError> {
    let curve = PhPolyCurve::from_polynomials(r)?;
    let rho = curve.rho()?;
    let dph = curve.dph_test()?;
    let helix = curve.helix_test()?;
    Ok(PhAnalysis {
        curve,
        rho,
        dph,
        helix,
    })
}

impl<F: Scalar> PhAnalysis<F> {
    /// The degree `n` of the curve.
    pub fn degree(&self) -> usize {
        self.curve.degree()
    }

    /// The bound `2n − 6` on `deg ρ` (0 for `n ≤ 3`).
    pub fn rho_degree_bound(&self) -> usize {
        (2 * self.degree()).saturating_sub(6)
    }

    /// Certificates: the PH identity `|r'|² ≡ σ²`; `|r'×r''|² ≡ σ²ρ`; `deg ρ ≤ 2n − 6`
    /// (every coefficient of `ρ` above `2n − 6` is zero); the DPH identity when the
    /// curve is DPH; the helix identities when it is a helix.
    pub fn certify(&self) -> Vec<Certificate> {
        let mut certs = self.curve.certify();
        let c = self.curve.cross_r1_r2();
        let s2 = self.curve.speed() * self.curve.speed();
        certs.push(identity_cert(
            "|r'×r''|² − σ²ρ ≡ 0",
            &pdot(&c, &c),
            &(&s2 * &self.rho),
        ));
        let bound = self.rho_degree_bound();
        let high: Vec<String> = self
            .rho
            .coeffs()
            .iter()
            .enumerate()
            .skip(bound + 1)
            .filter(|(_, x)| !is_negligible(*x, 1.0))
            .map(|(k, x)| format!("t^{k}: {}", fmt_scalar(x)))
            .collect();
        let prop = format!(
            "deg ρ ≤ 2n − 6 = {bound} (n = {}; Besednjak Prop. 3.8)",
            self.degree()
        );
        certs.push(if high.is_empty() {
            Certificate::holds(prop, F::EXACT)
        } else {
            Certificate::fails(prop, high.join(", "), F::EXACT)
        });
        if let DphTest::Dph(d) = &self.dph {
            certs.extend(self.curve.certify_dph(d));
        }
        match &self.helix {
            HelixTest::Helix(_) | HelixTest::Planar { .. } => {
                certs.extend(self.curve.certify_helix_test(&self.helix));
            }
            // exact linear algebra decided these; there is no identity to check
            HelixTest::NotHelix => certs.push(Certificate::holds(
                "a·r'(t) ≡ σ(t) and n·r'(t) ≡ 0 have no solution (not a helix, not planar)",
                F::EXACT,
            )),
            HelixTest::Line => {}
        }
        certs
    }

    /// The Frenet data at `t0` (module docs).
    ///
    /// # Errors
    /// [`PhError::Degenerate`] where `σ(t₀) = 0` (a singular point) or `ρ(t₀) = 0` (an
    /// inflection, or a straight line: no normal and binormal).
    pub fn frenet_at(&self, t0: &F) -> Result<FrenetAt<F>, PhError> {
        let s = self.curve.speed().eval(t0);
        if s.is_zero() {
            return Err(PhError::Degenerate(format!(
                "σ({}) = 0: the curve is singular there",
                fmt_scalar(t0)
            )));
        }
        let rho = self.rho.eval(t0);
        if rho.partial_cmp(&F::zero()) != Some(std::cmp::Ordering::Greater)
            || is_negligible(&rho, 1.0)
        {
            return Err(PhError::Degenerate(format!(
                "ρ({}) = {}: an inflection or a straight line, the normal and binormal are undefined there",
                fmt_scalar(t0),
                fmt_scalar(&rho)
            )));
        }
        let d1 = pderiv(self.curve.position());
        let d2 = pderiv(&d1);
        let d3 = pderiv(&d2);
        let (r1, r2, r3) = (peval(&d1, t0), peval(&d2, t0), peval(&d3, t0));
        let sd = self.curve.speed().derivative().eval(t0);
        let inv_s = F::one() / s.clone();
        let normal = [0, 1, 2]
            .map(|k| (s.clone() * r2[k].clone() - sd.clone() * r1[k].clone()) * inv_s.clone());
        let cross = cross3(&r1, &r2);
        let torsion = dot3(&cross, &r3) / (s.clone() * s.clone() * rho.clone());
        Ok(FrenetAt {
            point: self.curve.eval(t0),
            tangent: scale3(&r1, &inv_s),
            radicand: rho,
            normal_scaled: normal,
            binormal_scaled: scale3(&cross, &inv_s),
            curvature_over_root: inv_s.clone() * inv_s,
            torsion,
        })
    }
}

impl FrenetAt<Rational> {
    /// `x/√d` exactly, in `Q(√d)`.
    fn over_root(&self, x: &Rational) -> Result<QuadExt, PhError> {
        let root = sqrt_in_extension(&self.radicand)?;
        let inv = root
            .inverse()
            .ok_or_else(|| PhError::Degenerate("ρ(t₀) = 0".into()))?;
        Ok(&QuadExt::rational(x.clone()) * &inv)
    }

    /// The principal normal `p` exactly, in `Q(√ρ(t₀))³`.
    ///
    /// # Errors
    /// Only for an inconsistent radicand (not produced by [`PhAnalysis::frenet_at`]).
    pub fn normal_exact(&self) -> Result<[QuadExt; 3], PhError> {
        let [a, b, c] = &self.normal_scaled;
        Ok([self.over_root(a)?, self.over_root(b)?, self.over_root(c)?])
    }

    /// The binormal `b` exactly, in `Q(√ρ(t₀))³`.
    ///
    /// # Errors
    /// As [`Self::normal_exact`].
    pub fn binormal_exact(&self) -> Result<[QuadExt; 3], PhError> {
        let [a, b, c] = &self.binormal_scaled;
        Ok([self.over_root(a)?, self.over_root(b)?, self.over_root(c)?])
    }

    /// The curvature `κ = √ρ/σ²` exactly, in `Q(√ρ(t₀))`.
    ///
    /// # Errors
    /// As [`Self::normal_exact`].
    pub fn curvature_exact(&self) -> Result<QuadExt, PhError> {
        let root = sqrt_in_extension(&self.radicand)?;
        Ok(&QuadExt::rational(self.curvature_over_root.clone()) * &root)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    /// The twisted cubic-like PH cubic `r' = A i A*` with `A = (1 − t)(1 + j) + t(i + k)`
    /// written in power form, analysed from scratch.
    #[test]
    fn ph_cubic_analysis_and_frenet() {
        let pc = crate::ph::PhCurve::new(
            vec![
                rcagd_algebra::quaternion::Quaternion::new(q(1, 1), q(0, 1), q(1, 1), q(0, 1)),
                rcagd_algebra::quaternion::Quaternion::new(q(0, 1), q(1, 1), q(0, 1), q(1, 1)),
            ],
            [q(0, 1), q(0, 1), q(0, 1)],
        )
        .expect("valid");
        let a = analyze(pc.position()).expect("PH");
        assert!(Certificate::all_hold(&a.certify()), "{:?}", a.certify());
        assert_eq!(a.rho_degree_bound(), 0);
        assert_eq!(a.rho.degree(), Some(0), "a PH cubic has constant ρ");
        let f = a.frenet_at(&q(1, 3)).expect("regular");
        let p = f.normal_exact().expect("exact");
        let b = f.binormal_exact().expect("exact");
        let one = Some(q(1, 1));
        let zero = Some(q(0, 1));
        let dot = |x: &[QuadExt; 3], y: &[QuadExt; 3]| {
            &(&(&x[0] * &y[0]) + &(&x[1] * &y[1])) + &(&x[2] * &y[2])
        };
        assert_eq!(dot(&p, &p).to_rational(), one);
        assert_eq!(dot(&b, &b).to_rational(), one);
        assert_eq!(dot(&p, &b).to_rational(), zero);
        let t = f.tangent.clone().map(QuadExt::rational);
        assert_eq!(dot(&t, &p).to_rational(), zero);
        // f64 agrees with exact
        let af = analyze(pc.to_f64().position()).expect("PH");
        let ff = af.frenet_at(&(1.0 / 3.0)).expect("regular");
        let kf = ff.curvature_over_root * ff.radicand.sqrt();
        let ke = f.curvature_exact().expect("exact");
        let ke = Scalar::to_f64(ke.a()) + Scalar::to_f64(ke.b()) * Scalar::to_f64(ke.d()).sqrt();
        assert!((kf - ke).abs() < 1e-12 * ke.abs());
        assert!((ff.torsion - Scalar::to_f64(&f.torsion)).abs() < 1e-12);
    }

    #[test]
    fn not_ph_is_an_error() {
        let r = [
            Poly::new(vec![q(0, 1), q(1, 1)]),
            Poly::new(vec![q(0, 1), q(0, 1), q(1, 1)]),
            Poly::new(vec![q(0, 1), q(0, 1), q(0, 1), q(1, 1)]),
        ];
        assert!(matches!(analyze(r.clone()), Err(PhError::NotPh(_))));
        match ph_test(r).expect("not constant") {
            // |r'|² = 1 + 4t² + 9t⁴
            PhTest::NotPh { speed_squared } => assert_eq!(
                speed_squared,
                Poly::new(vec![q(1, 1), q(0, 1), q(4, 1), q(0, 1), q(9, 1)])
            ),
            PhTest::Ph(_) => panic!("the twisted cubic is not PH"),
        }
    }
}
