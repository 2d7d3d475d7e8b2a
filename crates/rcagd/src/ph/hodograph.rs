//! Quaternion and Hopf representations of spatial PH curves, their Bézier control
//! points, the power form with its PH test, and Lemma 2.1 (`Q i Q* = c`).
//!
//! * (docs/math/ph-curves.md, "The hodograph and the speed"; Besednjak §3.3 (3.27), §3.4): `r' = A i A* =
//!   (u²+v²−p²−q², 2(uq+vp), 2(vq−up)) = (|α|²−|β|², 2Re(αβ̄), 2Im(αβ̄))`,
//!   `σ = |A|² = u²+v²+p²+q² = |α|²+|β|²`, with `A = u + vi + pj + qk = α + kβ`,
//!   `α = u + iv`, `β = q + ip`.
//! * (docs/math/ph-curves.md, "Control points from the quaternion coefficients"; Besednjak (8.2), (9.4)): hodograph Bernstein coefficients of
//!   degree `2m`: `H_k = Σ_{i+j=k} C(m,i)C(m,j)/C(2m,k) · A_i i A_j*` and control points
//!   `p_{k+1} = p_k + H_k/n`, `n = 2m + 1`.
//! * (docs/math/ph-curves.md, "Prescribed tangents (Lemma 2.1)"; Besednjak Lemma 2.1, corrected: docs/math/ph-curves.md, Errata E10): the solutions of
//!   `Q i Q* = c`.

use super::util::*;
use super::PhError;
use rcagd_algebra::bernstein;
use rcagd_algebra::complex::Complex;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::{Certificate, Poly, Scalar};
use rcagd_geom::BezierCurve;

/// A spatial PH curve in quaternion form: Bernstein coefficients `A_0, …, A_m` of the
/// preimage `A(t)` and the start point `p_0 = r(0)`; degree `n = 2m + 1`.
///
/// `r(t) = p_0 + ∫₀ᵗ A i A*` (docs/math/ph-curves.md, "The hodograph and the speed" and "Control points from the quaternion coefficients", Besednjak §3.3 (3.27)–(3.29)).
#[derive(Debug, Clone, PartialEq)]
pub struct PhCurve<F> {
    coeffs: Vec<Quaternion<F>>,
    start: [F; 3],
}

impl<F: Scalar> PhCurve<F> {
    /// From the Bernstein coefficients `A_0..A_m` of the quaternion preimage and the
    /// start point `p_0`.
    ///
    /// # Errors
    /// [`PhError::InvalidPreimage`] for no coefficients, [`PhError::ZeroHodograph`] if all
    /// coefficients are zero (then `r' ≡ 0`).
    pub fn new(coeffs: Vec<Quaternion<F>>, start: [F; 3]) -> Result<Self, PhError> {
        if coeffs.is_empty() {
            return Err(PhError::InvalidPreimage(
                "the quaternion preimage A(t) needs at least one Bernstein coefficient".into(),
            ));
        }
        if coeffs.iter().all(qis_zero) {
            return Err(PhError::ZeroHodograph(
                "every Bernstein coefficient A_l is zero, so r' = A i A* ≡ 0".into(),
            ));
        }
        Ok(PhCurve { coeffs, start })
    }

    /// From the Hopf form: Bernstein coefficients `α_l = u_l + i v_l`,
    /// `β_l = q_l + i p_l` and `A_l = α_l + k β_l = u_l + v_l i + p_l j + q_l k`
    /// (Besednjak §3.4; docs/math/ph-curves.md, "Conventions").
    ///
    /// # Errors
    /// [`PhError::InvalidPreimage`] if `α` and `β` differ in length or are empty; as
    /// [`Self::new`].
    pub fn from_hopf(
        alpha: &[Complex<F>],
        beta: &[Complex<F>],
        start: [F; 3],
    ) -> Result<Self, PhError> {
        if alpha.len() != beta.len() {
            return Err(PhError::InvalidPreimage(format!(
                "α has {} Bernstein coefficients but β has {}",
                alpha.len(),
                beta.len()
            )));
        }
        let coeffs = alpha
            .iter()
            .zip(beta)
            .map(|(a, b)| quat(a.re.clone(), a.im.clone(), b.im.clone(), b.re.clone()))
            .collect();
        Self::new(coeffs, start)
    }

    /// The Bernstein coefficients `A_0..A_m`.
    pub fn coefficients(&self) -> &[Quaternion<F>] {
        &self.coeffs
    }

    /// The start point `p_0 = r(0)`.
    pub fn start(&self) -> &[F; 3] {
        &self.start
    }

    /// The Hopf coefficients `(α_l, β_l)`, `α_l = u_l + i v_l`, `β_l = q_l + i p_l`
    /// (inverse of [`Self::from_hopf`]; docs/math/ph-curves.md, "Conventions", docs/math/ph-curves.md, Errata E9).
    pub fn hopf_coefficients(&self) -> (Vec<Complex<F>>, Vec<Complex<F>>) {
        let alpha = self
            .coeffs
            .iter()
            .map(|a| cx(a.w.clone(), a.x.clone()))
            .collect();
        let beta = self
            .coeffs
            .iter()
            .map(|a| cx(a.z.clone(), a.y.clone()))
            .collect();
        (alpha, beta)
    }

    /// Degree `m` of the preimage `A(t)`.
    pub fn preimage_degree(&self) -> usize {
        self.coeffs.len() - 1
    }

    /// Degree `n = 2m + 1` of the curve.
    pub fn degree(&self) -> usize {
        2 * self.preimage_degree() + 1
    }

    /// The power-basis components `[u, v, p, q]` of `A(t) = u + vi + pj + qk`.
    pub fn preimage(&self) -> [Poly<F>; 4] {
        let comp = |f: fn(&Quaternion<F>) -> F| {
            bernstein::from_bernstein(&self.coeffs.iter().map(f).collect::<Vec<_>>())
        };
        [
            comp(|a| a.w.clone()),
            comp(|a| a.x.clone()),
            comp(|a| a.y.clone()),
            comp(|a| a.z.clone()),
        ]
    }

    /// The Hopf polynomials `(α(t), β(t))` in power form.
    pub fn hopf_polys(&self) -> (Poly<Complex<F>>, Poly<Complex<F>>) {
        let (a, b) = self.hopf_coefficients();
        (bernstein::from_bernstein(&a), bernstein::from_bernstein(&b))
    }

    /// The hodograph `r' = A i A* = (u²+v²−p²−q², 2(uq+vp), 2(vq−up))` in power form
    /// (docs/math/ph-curves.md, "The hodograph and the speed"; Besednjak (3.27)).
    pub fn hodograph(&self) -> [Poly<F>; 3] {
        let [u, v, p, q] = self.preimage();
        let two = F::from_i64(2);
        [
            &(&(&u * &u) + &(&v * &v)) - &(&(&p * &p) + &(&q * &q)),
            (&(&u * &q) + &(&v * &p)).scale(&two),
            (&(&v * &q) - &(&u * &p)).scale(&two),
        ]
    }

    /// The parametric speed `σ = |A|² = u²+v²+p²+q²` in power form (docs/math/ph-curves.md, "The hodograph and the speed").
    pub fn speed(&self) -> Poly<F> {
        let [u, v, p, q] = self.preimage();
        &(&(&u * &u) + &(&v * &v)) + &(&(&p * &p) + &(&q * &q))
    }

    /// The Bernstein coefficients (degree `2m`) of the hodograph,
    /// `H_k = Σ_{i+j=k} C(m,i)C(m,j)/C(2m,k) · A_i i A_j*` (docs/math/ph-curves.md, "Control points from the quaternion coefficients").
    pub fn hodograph_bernstein(&self) -> Vec<[F; 3]> {
        let m = self.preimage_degree();
        (0..=2 * m)
            .map(|k| {
                let mut acc = zero3::<F>();
                for i in k.saturating_sub(m)..=k.min(m) {
                    let j = k - i;
                    let w = binom::<F>(m, i) * binom::<F>(m, j) / binom::<F>(2 * m, k);
                    let s = qvec(&sandwich(&self.coeffs[i], 1, &self.coeffs[j]));
                    acc = add3(&acc, &scale3(&s, &w));
                }
                acc
            })
            .collect()
    }

    /// The Bernstein coefficients (degree `2m`) of `σ`,
    /// `σ_k = Σ_{i+j=k} C(m,i)C(m,j)/C(2m,k) · Re(A_i A_j*)` (docs/math/ph-curves.md, "Speed and arc length").
    pub fn speed_bernstein(&self) -> Vec<F> {
        let m = self.preimage_degree();
        (0..=2 * m)
            .map(|k| {
                let mut acc = F::zero();
                for i in k.saturating_sub(m)..=k.min(m) {
                    let j = k - i;
                    let w = binom::<F>(m, i) * binom::<F>(m, j) / binom::<F>(2 * m, k);
                    acc += w * qmul(&self.coeffs[i], &qconj(&self.coeffs[j])).w;
                }
                acc
            })
            .collect()
    }

    /// The Bézier control points `p_0..p_n`, `p_{k+1} = p_k + H_k/n`
    /// (docs/math/ph-curves.md, "Control points from the quaternion coefficients"; Besednjak (8.2) for septics, (9.4) for quintics).
    pub fn control_points(&self) -> Vec<[F; 3]> {
        let n = F::from_i64(self.degree() as i64);
        let mut pts = vec![self.start.clone()];
        for h in self.hodograph_bernstein() {
            let next = add3(
                pts.last().unwrap_or(&self.start),
                &scale3(&h, &(F::one() / n.clone())),
            );
            pts.push(next);
        }
        pts
    }

    /// The curve as a (polynomial, all weights one) Bézier curve of `rcagd-geom`.
    ///
    /// # Errors
    /// [`PhError::Geom`] if the geometry layer rejects the control points.
    pub fn to_bezier(&self) -> Result<BezierCurve<F>, PhError> {
        let pts: Vec<Vec<F>> = self
            .control_points()
            .into_iter()
            .map(|p| p.to_vec())
            .collect();
        Ok(BezierCurve::from_points(&pts)?)
    }

    /// The curve `r(t)` in power form, from the control points.
    pub fn position(&self) -> [Poly<F>; 3] {
        let pts = self.control_points();
        let comp = |c: usize| {
            bernstein::from_bernstein(&pts.iter().map(|p| p[c].clone()).collect::<Vec<_>>())
        };
        [comp(0), comp(1), comp(2)]
    }

    /// `r(t)`.
    pub fn eval(&self, t: &F) -> [F; 3] {
        peval(&self.position(), t)
    }

    /// The power form `(r, σ)` used by the analysis functions (arc length, frames, DPH
    /// and helix tests).
    pub fn to_poly_curve(&self) -> PhPolyCurve<F> {
        PhPolyCurve {
            r: self.position(),
            sigma: self.speed(),
        }
    }

    /// The same curve with `f64` coefficients.
    pub fn to_f64(&self) -> PhCurve<f64> {
        PhCurve {
            coeffs: self
                .coeffs
                .iter()
                .map(|a| qmap(a, |x| x.to_f64()))
                .collect(),
            start: to_f64_3(&self.start),
        }
    }

    /// Certificates (docs/math/ph-curves.md, "The hodograph and the speed"):
    /// * the hodograph of the Bézier control points, `n Σ (p_{k+1}−p_k) b_k^{n−1}`, equals
    ///   `A i A*` computed from the preimage components (docs/math/ph-curves.md, "The hodograph and the speed" and "Control points from the quaternion coefficients");
    /// * `x'² + y'² + z'² − σ² ≡ 0` with `σ = |A|²` and `r'` from the control points.
    pub fn certify(&self) -> Vec<Certificate> {
        let pts = self.control_points();
        let n = F::from_i64(self.degree() as i64);
        let comp = |c: usize| {
            bernstein::from_bernstein(
                &pts.windows(2)
                    .map(|w| (w[1][c].clone() - w[0][c].clone()) * n.clone())
                    .collect::<Vec<_>>(),
            )
        };
        let from_points = [comp(0), comp(1), comp(2)];
        let h = self.hodograph();
        let sigma = self.speed();
        let mut certs = Vec::new();
        for (c, name) in ["x", "y", "z"].iter().enumerate() {
            certs.push(identity_cert(
                format!(
                    "{name}'(t) of the Bézier control points ≡ {name}-component of A(t) i A*(t) (quaternion form, Besednjak, DPH-krivulje in polinomske vijačnice, (3.27)–(3.29))"
                ),
                &from_points[c],
                &h[c],
            ));
        }
        certs.push(identity_cert(
            "x'² + y'² + z'² − σ² ≡ 0 with σ = |A|² (PH, Besednjak, DPH-krivulje in polinomske vijačnice, (3.27))",
            &pdot(&from_points, &from_points),
            &(&sigma * &sigma),
        ));
        certs
    }
}

impl<F: Scalar> crate::Certified for PhCurve<F> {
    fn certify(&self) -> Vec<Certificate> {
        PhCurve::certify(self)
    }
}

/// A polynomial space curve `r(t)` in power form together with a polynomial `σ` with
/// `|r'|² ≡ σ²`: a PH curve given without (or after forgetting) its preimage.
///
/// This is the input of the analysis functions ([`super::speed`], [`super::frame`],
/// [`super::dph`], [`super::helix`]), so that curves printed in power form (Besednjak
/// Examples 3.13, 4.4, 4.5) can be tested directly.
#[derive(Debug, Clone, PartialEq)]
pub struct PhPolyCurve<F> {
    pub(crate) r: [Poly<F>; 3],
    pub(crate) sigma: Poly<F>,
}

impl<F: Scalar> PhPolyCurve<F> {
    /// The PH test of a polynomial curve: `|r'|²` must be the square of a polynomial
    /// `σ` (Besednjak Def. 3.2 / (3.2), docs/math/ph-curves.md, Errata E2: `x'² + y'² + z'² = σ²`). `σ` is
    /// returned with positive leading coefficient.
    ///
    /// # Errors
    /// [`PhError::ZeroHodograph`] for a constant curve, [`PhError::NotPh`] if `|r'|²` is
    /// not a perfect square over `F`.
    pub fn from_polynomials(r: [Poly<F>; 3]) -> Result<Self, PhError> {
        let d = pderiv(&r);
        let s2 = pdot(&d, &d);
        if s2.is_zero() {
            return Err(PhError::ZeroHodograph(
                "r'(t) ≡ 0: the curve is a point".into(),
            ));
        }
        let sigma = poly_sqrt(&s2).ok_or_else(|| {
            PhError::NotPh(format!(
                "|r'|² = {} is not the square of a polynomial",
                format_poly(&s2, "t")
            ))
        })?;
        Ok(PhPolyCurve { r, sigma })
    }

    /// From a curve and a claimed speed `σ` (checked: `|r'|² ≡ σ²`).
    ///
    /// # Errors
    /// [`PhError::NotPh`] if `|r'|² ≢ σ²`.
    pub fn from_parts(r: [Poly<F>; 3], sigma: Poly<F>) -> Result<Self, PhError> {
        let c = PhPolyCurve { r, sigma };
        let cert = c.certify();
        if Certificate::all_hold(&cert) {
            Ok(c)
        } else {
            Err(PhError::NotPh(format!("{}", cert[0])))
        }
    }

    /// `r(t)` in power form.
    pub fn position(&self) -> &[Poly<F>; 3] {
        &self.r
    }

    /// The hodograph `r'(t)`.
    pub fn hodograph(&self) -> [Poly<F>; 3] {
        pderiv(&self.r)
    }

    /// The parametric speed `σ = |r'|`.
    pub fn speed(&self) -> &Poly<F> {
        &self.sigma
    }

    /// Degree of the curve (0 for a constant curve).
    pub fn degree(&self) -> usize {
        self.r.iter().filter_map(|p| p.degree()).max().unwrap_or(0)
    }

    /// `gcd(x', y', z')` (monic), whose non-constant part marks a non-primitive hodograph
    /// (Besednjak §3.1, Examples 8.2–8.4).
    pub fn hodograph_gcd(&self) -> Poly<F> {
        let d = self.hodograph();
        d[0].gcd(&d[1]).gcd(&d[2])
    }

    /// `r(t)`.
    pub fn eval(&self, t: &F) -> [F; 3] {
        peval(&self.r, t)
    }

    /// The same curve with `f64` coefficients.
    pub fn to_f64(&self) -> PhPolyCurve<f64> {
        PhPolyCurve {
            r: [
                poly_f64(&self.r[0]),
                poly_f64(&self.r[1]),
                poly_f64(&self.r[2]),
            ],
            sigma: poly_f64(&self.sigma),
        }
    }

    /// Certificate `x'² + y'² + z'² − σ² ≡ 0` (docs/math/ph-curves.md).
    pub fn certify(&self) -> Vec<Certificate> {
        let d = self.hodograph();
        vec![identity_cert(
            "x'² + y'² + z'² − σ² ≡ 0 (PH)",
            &pdot(&d, &d),
            &(&self.sigma * &self.sigma),
        )]
    }
}

impl<F: Scalar> crate::Certified for PhPolyCurve<F> {
    fn certify(&self) -> Vec<Certificate> {
        PhPolyCurve::certify(self)
    }
}

/// A solution `Q` of `Q i Q* = c` (Besednjak Lemma 2.1, corrected per docs/math/ph-curves.md, "Prescribed tangents (Lemma 2.1)" and
/// docs/math/ph-curves.md, Errata E10), with `(λ, μ, ν) = c/|c|`:
///
/// * if `λ ≠ −1`: `Q(φ) = √(½(1+λ)|c|) (i + μ/(1+λ) j + ν/(1+λ) k)(cos φ + i sin φ)`;
/// * if `λ = −1` (`c = −|c| i`, any magnitude): `Q(φ) = √|c| (cos φ j + sin φ k)`.
///
/// `rotation = Some((cos φ, sin φ))` selects a member of the family (must satisfy
/// `cos²φ + sin²φ = 1`); `None` gives `φ = 0`. In exact arithmetic a rational solution
/// at `φ = 0` exists iff `|c|` is rational and `(|c| + c_x)/2` is a rational square
/// (e.g. `c = (−1, 2, 2)` gives `Q = i + j + k`).
///
/// # Errors
/// [`PhError::ZeroTangent`] for `c = 0`; [`PhError::Irrational`] if the exact solution
/// needs an irrational square root; [`PhError::OutOfRange`] if `cos²φ + sin²φ ≠ 1`.
pub fn solve_qiq<F: Scalar>(
    c: &[F; 3],
    rotation: Option<(F, F)>,
) -> Result<Quaternion<F>, PhError> {
    if is_zero3(c) {
        return Err(PhError::ZeroTangent(
            "Q i Q* = c needs c ≠ 0 (Lemma 2.1)".into(),
        ));
    }
    super::util::check_finite(|| "c of Q i Q* = c in f64".into(), c.iter())?;
    let norm = if F::EXACT {
        None
    } else {
        // |c| without forming |c|² (which overflows from |c| ≈ 1.3e154 on)
        let m = c.iter().map(|x| x.to_f64().abs()).fold(0.0, f64::max);
        let r = c
            .iter()
            .map(|x| (x.to_f64() / m).powi(2))
            .sum::<f64>()
            .sqrt()
            * m;
        rcagd_algebra::Rational::try_from(r)
            .ok()
            .map(|r| F::from_rational(&r))
    };
    let norm = norm.or_else(|| sqrt_scalar(&dot3(c, c))).ok_or_else(|| {
        PhError::Irrational(format!(
            "|c| = √({}) is irrational",
            fmt_scalar(&dot3(c, c))
        ))
    })?;
    let big_n = norm.clone() + c[0].clone();
    let q0 = if big_n.is_zero() || (!F::EXACT && big_n.to_f64() <= 1e-14 * norm.to_f64()) {
        let s = sqrt_scalar(&norm).ok_or_else(|| {
            PhError::Irrational(format!("√|c| = √({}) is irrational", fmt_scalar(&norm)))
        })?;
        quat(F::zero(), F::zero(), s, F::zero())
    } else {
        let half = big_n.clone() / F::from_i64(2);
        let s = sqrt_scalar(&half).ok_or_else(|| {
            PhError::Irrational(format!(
                "√((|c| + c_x)/2) = √({}) is irrational",
                fmt_scalar(&half)
            ))
        })?;
        quat(
            F::zero(),
            s.clone(),
            s.clone() * c[1].clone() / big_n.clone(),
            s * c[2].clone() / big_n,
        )
    };
    match rotation {
        None => Ok(q0),
        Some((co, si)) => {
            let n = co.clone() * co.clone() + si.clone() * si.clone() - F::one();
            if !is_negligible(&n, 1.0) {
                return Err(PhError::OutOfRange(format!(
                    "cos²φ + sin²φ − 1 = {} ≠ 0",
                    fmt_scalar(&n)
                )));
            }
            Ok(qmul(&q0, &quat(co, si, F::zero(), F::zero())))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn r(p: i64) -> Rational {
        Rational::from(p)
    }
    fn q4(w: i64, x: i64, y: i64, z: i64) -> Quaternion<Rational> {
        Quaternion::new(r(w), r(x), r(y), r(z))
    }

    #[test]
    fn cubic_control_points_match_closed_form() {
        // cubic: p1 = p0 + A0iA0*/3, p2 = p1 + (A0iA1* + A1iA0*)/6, p3 = p2 + A1iA1*/3
        let a0 = q4(1, 2, 0, -1);
        let a1 = q4(0, 1, 3, 1);
        let c = PhCurve::new(vec![a0.clone(), a1.clone()], [r(0), r(0), r(0)]).unwrap();
        let pts = c.control_points();
        let third = Rational::from(1) / Rational::from(3);
        let p1 = scale3(&qvec(&sandwich(&a0, 1, &a0)), &third);
        assert_eq!(pts[1], p1);
        let s = qadd(&sandwich(&a0, 1, &a1), &sandwich(&a1, 1, &a0));
        let p2 = add3(
            &p1,
            &scale3(&qvec(&s), &(Rational::from(1) / Rational::from(6))),
        );
        assert_eq!(pts[2], p2);
        assert!(Certificate::all_hold(&c.certify()));
    }

    #[test]
    fn lemma_2_1_rational_particular_solution() {
        let c = [r(-1), r(2), r(2)];
        let q = solve_qiq(&c, None).unwrap();
        assert_eq!(q, q4(0, 1, 1, 1));
        assert_eq!(qvec(&sandwich(&q, 1, &q)), c);
        // exceptional branch c = −|c| i, any magnitude (docs/math/ph-curves.md, Errata E10)
        let c = [r(-4), r(0), r(0)];
        let q = solve_qiq(&c, None).unwrap();
        assert_eq!(qvec(&sandwich(&q, 1, &q)), c);
        assert!(matches!(
            solve_qiq(&[r(0), r(0), r(0)], None),
            Err(PhError::ZeroTangent(_))
        ));
        assert!(matches!(
            solve_qiq(&[r(1), r(0), r(1)], None),
            Err(PhError::Irrational(_))
        ));
        let qf = solve_qiq(&[1.0, 0.0, 1.0], Some((0.6, 0.8))).unwrap();
        let v = qvec(&sandwich(&qf, 1, &qf));
        assert!((v[0] - 1.0).abs() < 1e-12 && v[1].abs() < 1e-12 && (v[2] - 1.0).abs() < 1e-12);
    }

    #[test]
    fn hopf_round_trip_and_power_form_ph_test() {
        let a = vec![q4(1, 1, 1, 0), q4(2, 2, 2, 0), q4(3, 2, 1, 1)];
        let c = PhCurve::new(a.clone(), [r(1), r(2), r(3)]).unwrap();
        let (al, be) = c.hopf_coefficients();
        let c2 = PhCurve::from_hopf(&al, &be, [r(1), r(2), r(3)]).unwrap();
        assert_eq!(c2.coefficients(), &a[..]);
        let pc = PhPolyCurve::from_polynomials(c.position()).unwrap();
        assert_eq!(pc.speed(), &c.speed());
        let not_ph = [
            Poly::from_ints(&[0, 1]),
            Poly::from_ints(&[0, 0, 1]),
            Poly::zero(),
        ];
        assert!(matches!(
            PhPolyCurve::<Rational>::from_polynomials(not_ph),
            Err(PhError::NotPh(_))
        ));
    }
}
