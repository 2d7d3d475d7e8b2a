//! Polynomial helices: the exact helix test (axis), Lancret's certificate, line/circle
//! seeds and the constructions by reparametrization, multiplication and both, and the
//! recognition of helical quintics.
//!
//! * (docs/math/ph-curves.md, "Helix test and axis"; Besednjak Def. 3.10, (3.23), Lancret (3.24)/(4.7), docs/math/ph-curves.md, Errata E7): a PH
//!   curve is a helix with axis `â` and angle `ψ` iff `â·r' ≡ cos ψ·σ`. Exact test: solve
//!   the linear system `a·r'(t) ≡ σ(t)` (one equation per power of `t`) for `a ∈ F³`;
//!   then `cos ψ = 1/|a|`, `â = a/|a|`, `tan²ψ = |a|² − 1 = (κ/τ)²`. If only `a·r' ≡ 0` is
//!   solvable the curve is planar (ψ = π/2). `(â, ψ) ~ (−â, π − ψ)`.
//! * (docs/math/ph-curves.md, "Helix constructions"; Besednjak §6.1–6.3, Lemma 6.4, (6.5)–(6.24)): helices from a line
//!   or circle `z(t) = (a_0(1−t)+a_1t)/(b_0(1−t)+b_1t)` in the complex plane: the cubic
//!   helix `α = a_0(1−t)+a_1t`, `β = b_0(1−t)+b_1t`; the reparametrization with real
//!   Bernstein `f, g`: `α̂_i = f_i(a_1−a_0) + g_i a_0`, `β̂_i = f_i(b_1−b_0) + g_i b_0`
//!   (proportionality `(f'g − fg')(a_0b_1 − a_1b_0)`); the multiplication by a complex
//!   `w`: `α = α̂·w`, `β = β̂·w` (Bernstein products; proportionality times `w²`).
//!   Reparametrize first, then multiply (Besednjak §6.3.3).

use super::hodograph::{PhCurve, PhPolyCurve};
use super::util::*;
use super::PhError;
use rcagd_algebra::bernstein;
use rcagd_algebra::complex::Complex;
use rcagd_algebra::{Certificate, Poly, Scalar};

/// A non-planar (or planar-with-axis) helix: `a·r' ≡ σ`, `|a| = 1/cos ψ`.
#[derive(Debug, Clone, PartialEq)]
pub struct HelixData<F> {
    /// The axis vector `a` with `a·r' ≡ σ` (so `|a| = 1/cos ψ`, `0 ≤ ψ < π/2`).
    pub a: [F; 3],
}

impl<F: Scalar> HelixData<F> {
    /// `|a|²`.
    pub fn a_norm_sq(&self) -> F {
        dot3(&self.a, &self.a)
    }
    /// `cos²ψ = 1/|a|²` (exact).
    pub fn cos2_psi(&self) -> F {
        F::one() / self.a_norm_sq()
    }
    /// `tan²ψ = |a|² − 1 = (κ/τ)²` (exact).
    pub fn tan2_psi(&self) -> F {
        self.a_norm_sq() - F::one()
    }
    /// The unit axis `a/|a|` in `f64`.
    pub fn axis_f64(&self) -> [f64; 3] {
        let a = to_f64_3(&self.a);
        let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
        [a[0] / n, a[1] / n, a[2] / n]
    }
    /// The angle `ψ ∈ [0, π/2)` between axis and tangent, radians.
    pub fn psi_f64(&self) -> f64 {
        (1.0 / self.a_norm_sq().to_f64().sqrt()).acos()
    }
    /// `|κ/τ| = tan ψ` in `f64`.
    pub fn kappa_over_tau_abs_f64(&self) -> f64 {
        self.tan2_psi().to_f64().max(0.0).sqrt()
    }
}

/// Outcome of the helix test.
#[derive(Debug, Clone, PartialEq)]
pub enum HelixTest<F> {
    /// `a·r' ≡ σ` has the unique solution `a`.
    Helix(HelixData<F>),
    /// Planar, `n·r' ≡ 0` (ψ = π/2, a trivial helix).
    Planar {
        /// The plane normal.
        normal: [F; 3],
    },
    /// A straight line (every direction orthogonal or the tangent direction works).
    Line,
    /// Not a helix.
    NotHelix,
}

impl<F: Scalar> PhPolyCurve<F> {
    /// The exact helix test: solve `a·r'(t) ≡ σ(t)` (docs/math/ph-curves.md, "Helix test and axis"; Besednjak (3.23)).
    ///
    /// # Errors
    /// [`PhError::NonFinite`] when an `f64` hodograph coefficient overflowed.
    pub fn helix_test(&self) -> Result<HelixTest<F>, PhError> {
        let d = self.hodograph();
        super::util::check_finite(
            || "the hodograph and parametric speed in f64 (from the curve's data)".into(),
            d.iter()
                .flat_map(|p| p.coeffs().iter())
                .chain(self.sigma.coeffs()),
        )?;
        let rows = d
            .iter()
            .map(|p| p.degree().map_or(0, |x| x + 1))
            .chain(std::iter::once(self.sigma.degree().map_or(0, |x| x + 1)))
            .max()
            .unwrap_or(0);
        let m: Vec<Vec<F>> = (0..rows)
            .map(|k| vec![d[0].coeff(k), d[1].coeff(k), d[2].coeff(k)])
            .collect();
        let b: Vec<F> = (0..rows).map(|k| self.sigma.coeff(k)).collect();
        if let Some((a, null)) = solve_linear(&m, &b, 3) {
            return Ok(if null.is_empty() {
                HelixTest::Helix(HelixData {
                    a: [a[0].clone(), a[1].clone(), a[2].clone()],
                })
            } else {
                HelixTest::Line
            });
        }
        // a nearly planar helix whose f64 solve over all coefficients failed (its rows
        // differ in size by orders of magnitude): the better conditioned axis from the ends
        if let Some(a) = self.axis_from_ends() {
            return Ok(HelixTest::Helix(HelixData { a }));
        }
        let zeros = vec![F::zero(); rows];
        match solve_linear(&m, &zeros, 3) {
            Some((_, null)) if null.len() == 1 => {
                let n = &null[0];
                Ok(HelixTest::Planar {
                    normal: [n[0].clone(), n[1].clone(), n[2].clone()],
                })
            }
            Some((_, null)) if null.len() >= 2 => Ok(HelixTest::Line),
            _ => Ok(HelixTest::NotHelix),
        }
    }

    /// The axis of a helix from its ends: `a·r'(0) = σ(0)`, `a·r'(1) = σ(1)` and
    /// `a·(r(1) − r(0)) = ∫₀¹σ` (the identity `a·r' ≡ σ` at both ends and integrated), by
    /// Cramer's rule when the three vectors are independent, accepted when `a·r' ≡ σ`
    /// holds: exactly, or for `f64` coefficientwise within [`F64_TOL`] of the sum of the
    /// absolute values of the terms. A solution of `a·r' ≡ σ` satisfies the three
    /// equations, so when they determine `a` this is the helix test. Used after the solve
    /// over all coefficients finds no axis: in `f64` that solve fails when the end tangents
    /// differ in size by orders of magnitude (a nearly planar helix, `|a| = 1/cos ψ` large,
    /// was taken for a planar curve), while its axis is the more accurate one otherwise.
    fn axis_from_ends(&self) -> Option<[F; 3]> {
        let d = self.hodograph();
        let (zero, one) = (F::zero(), F::one());
        let (p0, p1) = (peval(&self.r, &zero), peval(&self.r, &one));
        let chord: V3<F> = std::array::from_fn(|i| p1[i].clone() - p0[i].clone());
        let rows = [peval(&d, &zero), peval(&d, &one), chord];
        let rhs = [
            self.sigma.eval(&zero),
            self.sigma.eval(&one),
            self.arc_length(),
        ];
        let det = det3(&rows[0], &rows[1], &rows[2]);
        // Hadamard's bound: |det| ≤ the product of the row lengths
        let hadamard: f64 = rows
            .iter()
            .map(|r| r.iter().map(|x| x.to_f64().powi(2)).sum::<f64>().sqrt())
            .product();
        if det.is_zero() || (!F::EXACT && det.to_f64().abs() <= F64_TOL * hadamard) {
            return None;
        }
        let a: V3<F> = std::array::from_fn(|j| {
            let mut m = rows.clone();
            for (row, b) in m.iter_mut().zip(&rhs) {
                row[j] = b.clone();
            }
            det3(&m[0], &m[1], &m[2]) / det.clone()
        });
        let m = axis_magnitude(&a, &d, &self.sigma);
        identity_cert_within("", &pdot_const(&a, &d), &self.sigma, &m)
            .holds
            .then_some(a)
    }

    /// The helix data, or an error.
    ///
    /// # Errors
    /// [`PhError::NotHelix`] unless the curve is a non-planar helix.
    pub fn helix(&self) -> Result<HelixData<F>, PhError> {
        match self.helix_test()? {
            HelixTest::Helix(h) => Ok(h),
            HelixTest::Planar { .. } => Err(PhError::NotHelix(
                "the curve is planar (ψ = π/2): a·r' ≡ σ has no solution".into(),
            )),
            HelixTest::Line => Err(PhError::NotHelix("the curve is a straight line".into())),
            HelixTest::NotHelix => Err(PhError::NotHelix(
                "a·r'(t) ≡ σ(t) has no solution a ∈ F³ (no axis)".into(),
            )),
        }
    }

    /// Certificates of a helix (docs/math/ph-curves.md, "Helix test and axis"): `a·r' − σ ≡ 0` (so
    /// `â·t = cos ψ` with `|a| = 1/cos ψ`), and Lancret's constant ratio
    /// `ρ³ − (|a|² − 1)·((r'×r'')·r''')² ≡ 0` (`(κ/τ)² = tan²ψ`).
    pub fn certify_helix(&self, h: &HelixData<F>) -> Vec<Certificate> {
        let d = self.hodograph();
        let mut certs = vec![identity_cert_within(
            format!(
                "a·r' − σ ≡ 0 with a = {} (helix axis, |a| = 1/cos ψ)",
                fmt_v3(&h.a)
            ),
            &pdot_const(&h.a, &d),
            &self.sigma,
            &axis_magnitude(&h.a, &d, &self.sigma),
        )];
        match self.rho() {
            Ok(rho) => {
                let trip = self.triple_product();
                let property = "ρ³ − (|a|²−1)·((r'×r'')·r''')² ≡ 0 (Lancret: (κ/τ)² = tan²ψ)";
                let (lhs, rhs) = (rho.pow(3), (&trip * &trip).scale(&h.tan2_psi()));
                certs.push(if F::EXACT {
                    identity_cert(property, &lhs, &rhs)
                } else {
                    identity_cert_within(property, &lhs, &rhs, &self.lancret_magnitude(h))
                });
            }
            Err(e) => certs.push(Certificate::fails(
                "ρ = |r'×r''|²/σ² is a polynomial",
                e.to_string(),
                F::EXACT,
            )),
        }
        certs
    }

    /// For `f64`: coefficientwise bounds of the sums of the absolute values of the terms
    /// of Lancret's identity, `(|r''|² + σ'²)³ + |tan²ψ|·(Σᵢ|r'×r''|ᵢ·|r'''ᵢ|)²` evaluated on
    /// the absolute values of the coefficients (`ρ = |r''|² − σ'²` as [`Self::rho`]
    /// computes it in `f64`; the cross product with its differences turned into sums).
    /// The residual is compared with these, not with the largest coefficient: the
    /// identity cancels terms far larger than its coefficients when the end tangents
    /// differ in size by orders of magnitude (start derivative `(1000, 0, 1)`, end
    /// derivative `(0, 1, 1)`: terms near 10²⁴, residual 10¹⁶ from rounding alone).
    fn lancret_magnitude(&self, h: &HelixData<F>) -> Vec<f64> {
        let abs = |p: &Poly<F>| Poly::new(p.coeffs().iter().map(|c| c.to_f64().abs()).collect());
        let r = [abs(&self.r[0]), abs(&self.r[1]), abs(&self.r[2])];
        let d1 = pderiv(&r);
        let d2 = pderiv(&d1);
        let d3 = pderiv(&d2);
        let ds = abs(&self.sigma).derivative();
        let rho = &pdot(&d2, &d2) + &(&ds * &ds);
        let cross = [
            &(&d1[1] * &d2[2]) + &(&d1[2] * &d2[1]),
            &(&d1[2] * &d2[0]) + &(&d1[0] * &d2[2]),
            &(&d1[0] * &d2[1]) + &(&d1[1] * &d2[0]),
        ];
        let trip = pdot(&cross, &d3);
        let m = &rho.pow(3) + &(&trip * &trip).scale(&h.tan2_psi().to_f64().abs());
        m.coeffs().to_vec()
    }

    /// Certificates of an outcome of [`Self::helix_test`]: [`Self::certify_helix`] for an
    /// axis; `n·r' ≡ 0` for a planar curve (a trivial helix, ψ = π/2); `r' × r'' ≡ 0` for a
    /// line; a failing certificate for [`HelixTest::NotHelix`].
    pub fn certify_helix_test(&self, t: &HelixTest<F>) -> Vec<Certificate> {
        let d = self.hodograph();
        match t {
            HelixTest::Helix(h) => self.certify_helix(h),
            HelixTest::Planar { normal } => vec![identity_cert(
                format!(
                    "n·r' ≡ 0 with n = {} (planar: a helix with ψ = π/2)",
                    fmt_v3(normal)
                ),
                &pdot_const(normal, &d),
                &Poly::zero(),
            )],
            HelixTest::Line => {
                let c = pcross(&d, &pderiv(&d));
                vec![identity_cert(
                    "|r'×r''|² ≡ 0 (straight line)",
                    &pdot(&c, &c),
                    &Poly::zero(),
                )]
            }
            HelixTest::NotHelix => vec![Certificate::fails(
                "a·r' ≡ σ (helix axis)",
                "the linear system a·r'(t) ≡ σ(t) has no solution",
                F::EXACT,
            )],
        }
    }

    /// `κ/τ = ω³/((r'×r'')·r''')` squared, as the rational function `ρ³/trip²`
    /// (Besednjak (4.7); constant iff the curve is a helix, Lancret).
    ///
    /// # Errors
    /// As [`PhPolyCurve::rho`].
    pub fn kappa_over_tau_squared(&self) -> Result<super::RationalFunction<F>, PhError> {
        let trip = self.triple_product();
        Ok(super::RationalFunction {
            num: self.rho()?.pow(3),
            den: &trip * &trip,
        })
    }
}

impl<F: Scalar> PhCurve<F> {
    /// The helix test of [`PhPolyCurve::helix_test`].
    ///
    /// # Errors
    /// As [`PhPolyCurve::helix_test`].
    pub fn helix_test(&self) -> Result<HelixTest<F>, PhError> {
        self.to_poly_curve().helix_test()
    }

    /// `true` if all Bernstein coefficients `A_l` lie in one real 2-plane of `H`
    /// (rank ≤ 2): the recognition test of general helices built by reparametrization
    /// (`A_i = f_i V_0 + g_i V_1`, docs/math/ph-curves.md, "Helix constructions").
    pub fn coefficients_in_real_plane(&self) -> bool {
        let rows: Vec<Vec<F>> = (0..4)
            .map(|c| {
                self.coefficients()
                    .iter()
                    .map(|a| qcomponents(a)[c].clone())
                    .collect()
            })
            .collect();
        let n = self.coefficients().len();
        match solve_linear(&rows, &vec![F::zero(); 4], n) {
            Some((_, null)) => n - null.len() <= 2,
            None => false,
        }
    }

    /// Recognition of a helical quintic (Besednjak §6.2.2–6.2.3, (6.11), (6.13)):
    /// general `A_1 = c_0A_0 + c_2A_2` with real `c`'s, or monotone `A_1 = A_0c_0 + A_2c_2`
    /// with complex `c`'s (multiplying on the right) and `4c_0c_2 = 1`.
    ///
    /// # Errors
    /// [`PhError::DegreeMismatch`] if the curve is not a quintic.
    pub fn quintic_helix_kind(&self) -> Result<QuinticHelixKind<F>, PhError> {
        if self.preimage_degree() != 2 {
            return Err(PhError::DegreeMismatch(format!(
                "a quintic needs a quadratic preimage, got degree {}",
                self.preimage_degree()
            )));
        }
        let a = self.coefficients();
        let (a0, a1, a2) = (&a[0], &a[1], &a[2]);
        let c0v = qcomponents(a0);
        let c2v = qcomponents(a2);
        let t = qcomponents(a1);
        let m: Vec<Vec<F>> = (0..4)
            .map(|k| vec![c0v[k].clone(), c2v[k].clone()])
            .collect();
        let general = match solve_linear(&m, &t, 2) {
            Some((x, null)) if null.is_empty() => Some((x[0].clone(), x[1].clone())),
            _ => None,
        };
        let a0i = qcomponents(&sandwich_right_i(a0));
        let a2i = qcomponents(&sandwich_right_i(a2));
        let m4: Vec<Vec<F>> = (0..4)
            .map(|k| {
                vec![
                    c0v[k].clone(),
                    a0i[k].clone(),
                    c2v[k].clone(),
                    a2i[k].clone(),
                ]
            })
            .collect();
        let monotone = match solve_linear(&m4, &t, 4) {
            Some((x, null)) if null.is_empty() => {
                let c0 = cx(x[0].clone(), x[1].clone());
                let c2 = cx(x[2].clone(), x[3].clone());
                let p = cscale(&cmul(&c0, &c2), &F::from_i64(4));
                if is_negligible(&(p.re.clone() - F::one()), 1.0) && is_negligible(&p.im, 1.0) {
                    Some((c0, c2))
                } else {
                    None
                }
            }
            _ => None,
        };
        Ok(match (general, monotone) {
            (Some((c0, c2)), None) => QuinticHelixKind::General { c0, c2 },
            (None, Some((c0, c2))) => QuinticHelixKind::Monotone { c0, c2 },
            (Some(g), Some(m)) => QuinticHelixKind::Both {
                general: g,
                monotone: m,
            },
            (None, None) => QuinticHelixKind::NotHelical,
        })
    }
}

/// `A·i`.
fn sandwich_right_i<F: Scalar>(
    a: &rcagd_algebra::quaternion::Quaternion<F>,
) -> rcagd_algebra::quaternion::Quaternion<F> {
    qmul(a, &qunit(1))
}

/// Helical quintic recognition result (Besednjak §6.2).
#[derive(Debug, Clone, PartialEq)]
pub enum QuinticHelixKind<F> {
    /// `A_1 = c_0A_0 + c_2A_2`, real `c`'s (quadratic reparametrization, `st h = 2`).
    General {
        /// `c_0`.
        c0: F,
        /// `c_2`.
        c2: F,
    },
    /// `A_1 = A_0c_0 + A_2c_2`, complex `c`'s with `4c_0c_2 = 1` (multiplication, `st h = 0`).
    Monotone {
        /// `c_0`.
        c0: Complex<F>,
        /// `c_2`.
        c2: Complex<F>,
    },
    /// Both forms (degenerate overlap).
    Both {
        /// The real pair.
        general: (F, F),
        /// The complex pair.
        monotone: (Complex<F>, Complex<F>),
    },
    /// Neither form.
    NotHelical,
}

/// The image of a line/circle seed in the complex plane (Besednjak Lemma 6.4).
#[derive(Debug, Clone, PartialEq)]
pub enum LineOrCircle<F> {
    /// A line (`Im(b_1 b̄_0) = 0`).
    Line,
    /// A circle with centre `(a_1b̄_0 − a_0b̄_1)/(b_1b̄_0 − b̄_1b_0)` and squared radius
    /// `|a_0b_1 − a_1b_0|²/|b_1b̄_0 − b̄_1b_0|²`.
    Circle {
        /// Centre.
        center: Complex<F>,
        /// Squared radius.
        radius_sq: F,
    },
}

/// A line/circle seed `z(t) = (a_0(1−t) + a_1t)/(b_0(1−t) + b_1t)` (Besednjak (6.5)).
#[derive(Debug, Clone, PartialEq)]
pub struct LineCircle<F> {
    /// `a_0`.
    pub a0: Complex<F>,
    /// `a_1`.
    pub a1: Complex<F>,
    /// `b_0`.
    pub b0: Complex<F>,
    /// `b_1`.
    pub b1: Complex<F>,
}

impl<F: Scalar> LineCircle<F> {
    /// A seed; requires `a_0b_1 − a_1b_0 ≠ 0` (else `z` is constant).
    ///
    /// # Errors
    /// [`PhError::Degenerate`] if `a_0b_1 − a_1b_0 = 0`.
    pub fn new(
        a0: Complex<F>,
        a1: Complex<F>,
        b0: Complex<F>,
        b1: Complex<F>,
    ) -> Result<Self, PhError> {
        let s = LineCircle { a0, a1, b0, b1 };
        let d = s.determinant();
        if cis_zero(&d) {
            return Err(PhError::Degenerate(
                "a_0b_1 − a_1b_0 = 0: z(t) is constant, no helix".into(),
            ));
        }
        Ok(s)
    }

    /// `a_0b_1 − a_1b_0` (the proportionality polynomial of the cubic helix).
    pub fn determinant(&self) -> Complex<F> {
        csub(&cmul(&self.a0, &self.b1), &cmul(&self.a1, &self.b0))
    }

    /// The image of `z` (Besednjak Lemma 6.4).
    pub fn image(&self) -> LineOrCircle<F> {
        let conj = |c: &Complex<F>| cx(c.re.clone(), -c.im.clone());
        let den = csub(
            &cmul(&self.b1, &conj(&self.b0)),
            &cmul(&conj(&self.b1), &self.b0),
        );
        if cis_zero(&den) {
            return LineOrCircle::Line;
        }
        let num = csub(
            &cmul(&self.a1, &conj(&self.b0)),
            &cmul(&self.a0, &conj(&self.b1)),
        );
        let center = cdiv(&num, &den).unwrap_or_else(|| cx(F::zero(), F::zero()));
        let radius_sq = cnorm_sq(&self.determinant()) / cnorm_sq(&den);
        LineOrCircle::Circle { center, radius_sq }
    }

    /// `z(t)` (`None` at a pole).
    pub fn eval(&self, t: &F) -> Option<Complex<F>> {
        let s = F::one() - t.clone();
        let n = cadd(&cscale(&self.a0, &s), &cscale(&self.a1, t));
        let d = cadd(&cscale(&self.b0, &s), &cscale(&self.b1, t));
        cdiv(&n, &d)
    }

    /// The cubic helix `α = a_0(1−t)+a_1t`, `β = b_0(1−t)+b_1t` (Besednjak §6.2.1).
    ///
    /// # Errors
    /// As [`PhCurve::from_hopf`].
    pub fn cubic_helix(&self, start: [F; 3]) -> Result<PhCurve<F>, PhError> {
        PhCurve::from_hopf(
            &[self.a0.clone(), self.a1.clone()],
            &[self.b0.clone(), self.b1.clone()],
            start,
        )
    }

    /// The helix by reparametrization `f/g` (real Bernstein coefficients of equal
    /// degree `k ≥ 1`) followed by multiplication by `w` (complex Bernstein, degree ≥ 0;
    /// `w = [1]` for none): `α = α̂·w`, `β = β̂·w`, `α̂_i = f_i(a_1−a_0) + g_i a_0`,
    /// `β̂_i = f_i(b_1−b_0) + g_i b_0` (docs/math/ph-curves.md, "Helix constructions"; Besednjak (6.9), (6.15), (6.22),
    /// (6.24)). The proportionality polynomial is `(f'g − fg')(a_0b_1 − a_1b_0)w²`.
    ///
    /// # Errors
    /// [`PhError::DegreeMismatch`] if `f`, `g` differ in length or are shorter than 2, or
    /// `w` is empty; [`PhError::Degenerate`] if `f'g − fg' ≡ 0` or `w ≡ 0`.
    pub fn helix(
        &self,
        f: &[F],
        g: &[F],
        w: &[Complex<F>],
        start: [F; 3],
    ) -> Result<PhCurve<F>, PhError> {
        if f.len() != g.len() || f.len() < 2 {
            return Err(PhError::DegreeMismatch(format!(
                "f and g need the same number (≥ 2) of Bernstein coefficients, got {} and {}",
                f.len(),
                g.len()
            )));
        }
        if w.is_empty() || w.iter().all(cis_zero) {
            return Err(PhError::Degenerate(
                "the multiplier w must be non-zero".into(),
            ));
        }
        let fp = bernstein::from_bernstein(f);
        let gp = bernstein::from_bernstein(g);
        let h = &(&fp.derivative() * &gp) - &(&fp * &gp.derivative());
        if h.is_zero() {
            return Err(PhError::Degenerate(
                "f'g − fg' ≡ 0: f/g is constant, the reparametrization collapses".into(),
            ));
        }
        let da = csub(&self.a1, &self.a0);
        let db = csub(&self.b1, &self.b0);
        let ah: Vec<Complex<F>> = f
            .iter()
            .zip(g)
            .map(|(fi, gi)| cadd(&cscale(&da, fi), &cscale(&self.a0, gi)))
            .collect();
        let bh: Vec<Complex<F>> = f
            .iter()
            .zip(g)
            .map(|(fi, gi)| cadd(&cscale(&db, fi), &cscale(&self.b0, gi)))
            .collect();
        let alpha = bernstein::product(&ah, w);
        let beta = bernstein::product(&bh, w);
        PhCurve::from_hopf(&alpha, &beta, start)
    }

    /// Reparametrization only (Besednjak §6.2.2, §6.3.1).
    ///
    /// # Errors
    /// As [`Self::helix`].
    pub fn reparametrized_helix(
        &self,
        f: &[F],
        g: &[F],
        start: [F; 3],
    ) -> Result<PhCurve<F>, PhError> {
        self.helix(f, g, &[cx(F::one(), F::zero())], start)
    }

    /// Multiplication only (`f = t`, `g = 1`; Besednjak §6.2.3, §6.3.2).
    ///
    /// # Errors
    /// As [`Self::helix`].
    pub fn multiplied_helix(&self, w: &[Complex<F>], start: [F; 3]) -> Result<PhCurve<F>, PhError> {
        self.helix(&[F::zero(), F::one()], &[F::one(), F::one()], w, start)
    }

    /// Certificates of a curve built by [`Self::helix`] from `f`, `g`, `w`: the PH
    /// identity, the predicted proportionality polynomial
    /// `αβ' − α'β ≡ (f'g − fg')(a_0b_1 − a_1b_0)w²` (Besednjak §6.2), and the certificates
    /// of the axis test ([`PhPolyCurve::certify_helix_test`]: `a·r' ≡ σ` and Lancret's
    /// constant `κ/τ`, or the plane of a planar curve); a curve without an axis gets a
    /// failing certificate.
    ///
    /// # Errors
    /// As [`PhPolyCurve::rho`].
    pub fn certify_helix_construction(
        &self,
        curve: &PhCurve<F>,
        f: &[F],
        g: &[F],
        w: &[Complex<F>],
    ) -> Result<Vec<Certificate>, PhError> {
        let mut certs = curve.certify();
        let d = &curve.proportionality() - &self.predicted_proportionality(f, g, w);
        let (re, im) = (d.map(|c| c.re.clone()), d.map(|c| c.im.clone()));
        // f64: each residual coefficient against the sizes of the terms that cancel in it
        // (not the residual's own size: it is the cancelled difference)
        let scale = self.helix_magnitude(curve, f, g, w);
        certs.push(identity_cert_within(
            "Re(αβ' − α'β − (f'g − fg')(a0b1 − a1b0)w²) ≡ 0 (Besednjak §6.2)",
            &re,
            &Poly::zero(),
            &scale,
        ));
        certs.push(identity_cert_within(
            "Im(αβ' − α'β − (f'g − fg')(a0b1 − a1b0)w²) ≡ 0 (Besednjak §6.2)",
            &im,
            &Poly::zero(),
            &scale,
        ));
        let pc = curve.to_poly_curve();
        let t = pc.helix_test()?;
        certs.extend(pc.certify_helix_test(&t));
        Ok(certs)
    }

    /// Coefficientwise bounds of the terms of `αβ' − α'β − (f'g − fg')(a_0b_1 − a_1b_0)w²`
    /// in power form, `|α||β'| + |α'||β| + (|f'||g| + |f||g'|)·|a_0b_1 − a_1b_0|·|w|²`
    /// (each factor by [`abs_power_from_bernstein`], complex parts by `|re| + |im|`): the
    /// scale of the `f64` residual of [`Self::certify_helix_construction`].
    fn helix_magnitude(&self, curve: &PhCurve<F>, f: &[F], g: &[F], w: &[Complex<F>]) -> Vec<f64> {
        let cabs = |c: &Complex<F>| c.re.to_f64().abs() + c.im.to_f64().abs();
        let (a, b) = curve.hopf_coefficients();
        let a = abs_power_from_bernstein(&a.iter().map(cabs).collect::<Vec<_>>());
        let b = abs_power_from_bernstein(&b.iter().map(cabs).collect::<Vec<_>>());
        let lhs = &(&a * &b.derivative()) + &(&a.derivative() * &b);
        let fm = abs_power_from_bernstein(&f.iter().map(|x| x.to_f64().abs()).collect::<Vec<_>>());
        let gm = abs_power_from_bernstein(&g.iter().map(|x| x.to_f64().abs()).collect::<Vec<_>>());
        let wm = abs_power_from_bernstein(&w.iter().map(cabs).collect::<Vec<_>>());
        let h = &(&fm.derivative() * &gm) + &(&fm * &gm.derivative());
        let rhs = &(&h * &(&wm * &wm)) * &Poly::constant(cabs(&self.determinant()));
        (&lhs + &rhs).coeffs().to_vec()
    }

    /// The predicted proportionality polynomial `(f'g − fg')(a_0b_1 − a_1b_0)w²`.
    pub fn predicted_proportionality(
        &self,
        f: &[F],
        g: &[F],
        w: &[Complex<F>],
    ) -> Poly<Complex<F>> {
        let fp = bernstein::from_bernstein(f);
        let gp = bernstein::from_bernstein(g);
        let h = &(&fp.derivative() * &gp) - &(&fp * &gp.derivative());
        let d = self.determinant();
        let wp = cpoly_from_bernstein(w);
        let hc = h.map(|c| cmul(&cx(c.clone(), F::zero()), &d));
        &hc * &(&wp * &wp)
    }
}

/// Coefficientwise `Σᵢ|aᵢ|·|r'ᵢ| + |σ|`: the sums of the absolute values of the terms of
/// `a·r' − σ`, the scale of its `f64` residual (large `|a| = 1/cos ψ` cancels).
fn axis_magnitude<F: Scalar>(a: &[F; 3], d: &[Poly<F>; 3], sigma: &Poly<F>) -> Vec<f64> {
    let n = d
        .iter()
        .chain([sigma])
        .map(|p| p.coeffs().len())
        .max()
        .unwrap_or(0);
    (0..n)
        .map(|k| {
            (0..3)
                .map(|i| a[i].to_f64().abs() * d[i].coeff(k).to_f64().abs())
                .sum::<f64>()
                + sigma.coeff(k).to_f64().abs()
        })
        .collect()
}

/// Coefficientwise bounds of the power form of `Σᵢ bᵢ Bᵢⁿ(t)` from `|bᵢ|`: coefficient `k`
/// is `Σ_{i ≤ k} |bᵢ| C(n, i) C(n − i, k − i)` (the power coefficients of `Bᵢⁿ` are
/// `(−1)^{k−i} C(n, i) C(n − i, k − i)`), so every term of a product of such polynomials
/// is bounded by the product of these (non-negative) bounds.
fn abs_power_from_bernstein(b: &[f64]) -> Poly<f64> {
    let n = b.len().saturating_sub(1);
    let binom = |n: usize, k: usize| -> f64 {
        (0..k).fold(1.0, |acc, j| acc * (n - j) as f64 / (j + 1) as f64)
    };
    let coeffs = (0..=n)
        .map(|k| {
            (0..=k)
                .map(|i| b[i] * binom(n, i) * binom(n - i, k - i))
                .sum::<f64>()
        })
        .collect::<Vec<_>>();
    Poly::new(if b.is_empty() { Vec::new() } else { coeffs })
}
