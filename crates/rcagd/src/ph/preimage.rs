//! The quaternion preimage `A(t)` of a given PH hodograph: `r' = A i A*`, recovered exactly.
//!
//! Besednjak, "DPH-krivulje in polinomske vijačnice", Remark 3.15 (from Lemma 2.1) writes
//! the one-parameter family of preimages of a hodograph `r' = (x', y', z')` with speed
//! `σ = |r'|` in Hopf form `A = α + kβ` as
//!
//! `α = √(½(σ + x'))·(−sin φ + i cos φ)`,
//! `β = ((z' cos φ − y' sin φ) + i(y' cos φ + z' sin φ)) / √(2(σ + x'))`,
//!
//! that is `|α|² = (σ + x')/2`, `|β|² = (σ − x')/2` and `αβ̄ = (y' + i z')/2` (the Hopf map
//! `r' = (|α|² − |β|², 2 Re αβ̄, 2 Im αβ̄)`, ibid. §3.4). The square root is a polynomial
//! only after the right choice of complex factors, which the remark leaves open. We make
//! that choice exactly (derivation in `docs/math/ph-preimage.md`):
//!
//! 1. `d = gcd(x', y', z')` (monic); `ř' = r'/d` is a primitive PH hodograph with speed
//!    `σ̌ = σ/d`, its sign chosen with a positive leading coefficient;
//! 2. `Ň = (σ̌ + x̌')/2`, `Y̌ = (y̌' + i ž')/2` and `G = gcd(Ň, Y̌)` over `Q(i)`: for a
//!    primitive hodograph the preimage `(α̌, β̌)` is coprime, so `G = α̌` up to a constant
//!    and `|G|² = c·Ň` for a rational `c > 0`;
//! 3. `d/c = |δ|²` with a complex polynomial `δ` (a sum of two squares over `Q`,
//!    `rcagd_algebra::sum_of_squares`; `d` is `|gcd(α, β)|²` up to a constant, so this is
//!    where non-primitive hodographs have several preimages: one per choice of Gaussian
//!    factors of `d/c`);
//! 4. `α = δ·G`, `β = c·δ·conj(Y̌/G)`, so that `|α|² = d·Ň`, `αβ̄ = d·Y̌`, `|β|² = d·M̌`.
//!
//! Every preimage of the same choice is `A(t)·(cos φ + i sin φ)` with a constant `φ`
//! (Lemma 2.1). The certificate checks `A i A* ≡ r'` coefficientwise.

use super::hodograph::{PhCurve, PhPolyCurve};
use super::util::*;
use super::PhError;
use rcagd_algebra::complex::{conj_poly, norm_sq_poly, Complex};
use rcagd_algebra::sum_of_squares::{GaussianSplit, SumOfSquares, SumOfSquaresError};
use rcagd_algebra::{bernstein, format_poly, Certificate, Poly, Rational, Scalar};

type Q = Rational;
type CPoly = Poly<Complex<Q>>;

/// The preimage of a PH hodograph (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct RecoveredPreimage {
    /// The given hodograph `r' = (x', y', z')`.
    pub hodograph: [Poly<Q>; 3],
    /// Its content `d = gcd(x', y', z')`, monic.
    pub content: Poly<Q>,
    /// The number of choices of Gaussian factors of `d/c` (step 3; 1 for a primitive
    /// hodograph).
    pub choices: usize,
    /// The choice used (`0 ≤ choice < choices`).
    pub choice: usize,
    /// The Hopf polynomials `(α, β)` of the preimage, power form.
    pub hopf: (CPoly, CPoly),
    /// The PH curve `r(0) + ∫ A i A*` with the Bernstein coefficients of `A`.
    pub curve: PhCurve<Q>,
}

fn complex(p: &Poly<Q>) -> CPoly {
    p.map(|x| Complex::new(x.clone(), Q::ZERO))
}

fn sos_error(e: SumOfSquaresError, what: &str) -> PhError {
    match e {
        SumOfSquaresError::Negative(m) => PhError::NotPh(format!(
            "{what} must be a positive constant times |gcd(α, β)|² for a preimage A = α + kβ, but it is negative somewhere ({m}): no quaternion preimage"
        )),
        SumOfSquaresError::Zero => PhError::Degenerate(format!("{what} is zero")),
        other => PhError::Irrational(format!(
            "{what} is not a sum of two squares of rational polynomials: {other}"
        )),
    }
}

/// `|δ|² = q` over `Q` for the given choice of Gaussian factors; the number of choices.
fn gaussian_root(q: &Poly<Q>, choice: usize, what: &str) -> Result<(CPoly, usize), PhError> {
    let split = GaussianSplit::new(q).map_err(|e| sos_error(e, what))?;
    let n = split.num_choices();
    if choice >= n {
        return Err(PhError::OutOfRange(format!(
            "choice {choice}: {what} = {} has {n} choice(s) of complex factors (0 … {})",
            format_poly(q, "t"),
            n - 1
        )));
    }
    match split.decompose(choice).map_err(|e| sos_error(e, what))? {
        SumOfSquares::Rational { g1, g2 } => Ok((
            rcagd_algebra::complex::from_re_im_polys(&g1, &g2),
            n,
        )),
        SumOfSquares::Extension { radicand, .. } => Err(PhError::Irrational(format!(
            "{what} = {} is a sum of two squares only over Q(√{radicand}): the preimage is not rational",
            format_poly(q, "t")
        ))),
    }
}

fn div_exact_c(a: &CPoly, b: &CPoly, what: &str) -> Result<CPoly, PhError> {
    let (q, r) = a.div_rem(b)?;
    if !r.is_zero() {
        return Err(PhError::Degenerate(format!(
            "{what} does not divide exactly"
        )));
    }
    Ok(q)
}

/// The quaternion preimage of the PH curve `r(t)` (module docs), for the given `choice`
/// of Gaussian factors of the hodograph's content (0 for the first).
///
/// # Errors
/// [`PhError::NotPh`] if `|r'|²` is not a square or the content `gcd(x', y', z')` is
/// negative somewhere (then no polynomial preimage exists); [`PhError::Irrational`] if the
/// preimage needs a quadratic irrationality; [`PhError::ZeroHodograph`] for a constant
/// curve; [`PhError::OutOfRange`] for a choice beyond [`RecoveredPreimage::choices`].
pub fn recover_preimage(r: [Poly<Q>; 3], choice: usize) -> Result<RecoveredPreimage, PhError> {
    let start = [r[0].coeff(0), r[1].coeff(0), r[2].coeff(0)];
    let curve = PhPolyCurve::from_polynomials(r)?;
    let h = curve.hodograph();
    let sigma = curve.speed().clone();
    let content = h
        .iter()
        .filter(|p| !p.is_zero())
        .fold(Poly::zero(), |g: Poly<Q>, p| g.gcd(p))
        .monic();
    if content.is_zero() {
        return Err(PhError::ZeroHodograph("r' ≡ 0".into()));
    }
    let div = |p: &Poly<Q>| -> Result<Poly<Q>, PhError> { Ok(p.div_exact(&content)?) };
    let hc = [div(&h[0])?, div(&h[1])?, div(&h[2])?];
    let mut s = div(&sigma)?;
    if s.leading() < Q::ZERO {
        s = -s;
    }
    let half = Q::from_ratio(1, 2);
    let n = (&s + &hc[0]).scale(&half);
    let y = rcagd_algebra::complex::from_re_im_polys(&hc[1], &hc[2])
        .scale(&Complex::new(half.clone(), Q::ZERO));
    let (alpha, beta, choices) = if n.is_zero() {
        // ř' = (−σ̌, 0, 0): α = 0, |β|² = d·σ̌
        let (beta, k) = gaussian_root(&(&content * &s), choice, "d·σ")?;
        (CPoly::zero(), beta, k)
    } else {
        let g = complex(&n).gcd(&y);
        let g2 = norm_sq_poly(&g);
        let c = g2.leading() / n.leading();
        if g2 != n.scale(&c) {
            return Err(PhError::Degenerate(format!(
                "|gcd((σ + x')/2, (y' + iz')/2)|² = {} is not a constant times (σ + x')/2 = {}",
                format_poly(&g2, "t"),
                format_poly(&n, "t")
            )));
        }
        let (delta, k) = gaussian_root(
            &content.scale(&(Q::ONE / c.clone())),
            choice,
            "a constant times the content gcd(x', y', z')",
        )?;
        let alpha = &delta * &g;
        let yg = div_exact_c(&y, &g, "gcd((σ + x')/2, (y' + iz')/2)")?;
        let beta = (&delta * &conj_poly(&yg)).scale(&Complex::new(c, Q::ZERO));
        (alpha, beta, k)
    };
    let m = alpha.degree().unwrap_or(0).max(beta.degree().unwrap_or(0));
    let ab = bernstein::to_bernstein(&alpha, m)?;
    let bb = bernstein::to_bernstein(&beta, m)?;
    let pc = PhCurve::from_hopf(&ab, &bb, start)?;
    Ok(RecoveredPreimage {
        hodograph: h,
        content,
        choices,
        choice,
        hopf: (alpha, beta),
        curve: pc,
    })
}

impl RecoveredPreimage {
    /// The preimage `A·(cos φ + i sin φ)` of the same hodograph (Lemma 2.1); `cos φ`,
    /// `sin φ` rational with `cos²φ + sin²φ = 1`.
    ///
    /// # Errors
    /// [`PhError::OutOfRange`] if `cos²φ + sin²φ ≠ 1`.
    pub fn rotated(&self, cos: &Q, sin: &Q) -> Result<PhCurve<Q>, PhError> {
        let n = cos.clone() * cos.clone() + sin.clone() * sin.clone() - Q::ONE;
        if !n.is_zero() {
            return Err(PhError::OutOfRange(format!("cos²φ + sin²φ − 1 = {n} ≠ 0")));
        }
        let e = quat(cos.clone(), sin.clone(), Q::ZERO, Q::ZERO);
        let coeffs = self
            .curve
            .coefficients()
            .iter()
            .map(|a| qmul(a, &e))
            .collect();
        PhCurve::new(coeffs, self.curve.start().clone())
    }

    /// Certificates: `A i A* ≡ r'` (each component, power form) and the PH identities of
    /// the recovered curve.
    pub fn certify(&self) -> Vec<Certificate> {
        let got = self.curve.hodograph();
        let mut certs: Vec<Certificate> = ["x'", "y'", "z'"]
            .iter()
            .zip(got.iter().zip(self.hodograph.iter()))
            .map(|(name, (a, b))| {
                identity_cert(
                    format!("(A i A*)_{name} − {name} ≡ 0 (the recovered preimage; Besednjak Remark 3.15)"),
                    a,
                    b,
                )
            })
            .collect();
        certs.extend(self.curve.certify());
        certs
    }
}

/// A solution `Q` of `Q i Q* = c` (Besednjak, Lemma 2.1; the exceptional branch for every
/// `c = −|c| i`, not only `c = −i`: see [`super::solve_qiq`]) with the segment
/// `r(t) = t·c` whose constant preimage it is.
#[derive(Debug, Clone, PartialEq)]
pub struct QiqSolution<F> {
    /// The right-hand side `c`.
    pub c: [F; 3],
    /// `(cos φ, sin φ)` of the member `Q(φ)` of the family.
    pub rotation: (F, F),
    /// The solution `Q(φ)`.
    pub q: rcagd_algebra::quaternion::Quaternion<F>,
    /// The PH segment `r(t) = t·c` with `r' = Q i Q*` (degree 1).
    pub segment: PhCurve<F>,
}

/// The solution `Q(φ)` of `Q i Q* = c` (Lemma 2.1) for `rotation = (cos φ, sin φ)`
/// (`φ = 0` when `None`), with its certificate.
///
/// # Errors
/// As [`super::solve_qiq`].
pub fn solve_qiq_certified<F: rcagd_algebra::Scalar>(
    c: &[F; 3],
    rotation: Option<(F, F)>,
) -> Result<QiqSolution<F>, PhError> {
    let rotation = rotation.unwrap_or((F::one(), F::zero()));
    let q = super::solve_qiq(c, Some(rotation.clone()))?;
    let segment = PhCurve::new(vec![q.clone()], [F::zero(), F::zero(), F::zero()])?;
    Ok(QiqSolution {
        c: c.clone(),
        rotation,
        q,
        segment,
    })
}

impl<F: rcagd_algebra::Scalar> QiqSolution<F> {
    /// Certificates: `Q i Q* = c` (each component) and the PH identities of the segment.
    pub fn certify(&self) -> Vec<Certificate> {
        let v = qvec(&sandwich(&self.q, 1, &self.q));
        let mut certs = vec![v3_cert("Q i Q* − c = 0 (Besednjak Lemma 2.1)", &v, &self.c)];
        certs.extend(self.segment.certify());
        certs
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::quaternion::Quaternion;

    fn qi(n: i64) -> Q {
        Q::from(n)
    }

    /// The cubic `A = (1 − t)(1 + j) + t(i + k)`: primitive hodograph, so the recovered
    /// preimage is the given one times a unit complex constant.
    #[test]
    fn cubic_round_trip() {
        let a = vec![
            Quaternion::new(qi(1), qi(0), qi(1), qi(0)),
            Quaternion::new(qi(0), qi(1), qi(0), qi(1)),
        ];
        let pc = PhCurve::new(a, [qi(1), qi(2), qi(3)]).unwrap();
        let rec = recover_preimage(pc.position(), 0).unwrap();
        assert!(Certificate::all_hold(&rec.certify()), "{:?}", rec.certify());
        assert_eq!(rec.content, Poly::constant(qi(1)));
        assert_eq!(rec.choices, 1);
        assert_eq!(rec.curve.control_points(), pc.control_points());
    }

    #[test]
    fn not_ph_and_negative_content_are_errors() {
        let twisted = [
            Poly::from_ints(&[0, 1]),
            Poly::from_ints(&[0, 0, 1]),
            Poly::from_ints(&[0, 0, 0, 1]),
        ];
        assert!(matches!(
            recover_preimage(twisted, 0),
            Err(PhError::NotPh(_))
        ));
        // r' = (t, 0, 0): PH with σ = t, but |A|² = t has no polynomial solution
        let line = [Poly::from_ints(&[0, 0, 1]), Poly::zero(), Poly::zero()];
        assert!(matches!(recover_preimage(line, 0), Err(PhError::NotPh(_))));
    }
}
