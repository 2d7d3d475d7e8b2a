//! Circles and lines of the complex plane traced by rational functions — the tools behind
//! the helix criteria of Besednjak, "DPH-krivulje in polinomske vijačnice", ch. 7 (the
//! tangent indicatrix of a DPH curve is a circle on S² iff `z = α/β` traces a circle or a
//! line, via the Hopf map).
//!
//! * Lemma 7.3: for `a₁b₂ − a₂b₁ ≠ 0`, `z(φ) = (a₁e^{iφ} + a₂)/(b₁e^{iφ} + b₂)` traces the
//!   circle with centre `z_c = (a₁b̄₁ − a₂b̄₂)/(|b₁|² − |b₂|²)` and radius
//!   `R = |a₂b₁ − a₁b₂|/||b₁|² − |b₂|²|`, a line when `|b₁| = |b₂|` (Remark 7.4: constant
//!   when `a₁b₂ = a₂b₁`). [`mobius_unit_circle_image`].
//! * A rational curve `z(t) = A(t)/B(t)` (`A, B ∈ Q(i)[t]`) lies on a circle or line iff
//!   some real `(c, e)` and complex `d`, not all zero, satisfy
//!   `c|A|² + 2Re(d̄AB̄) + e|B|² ≡ 0` — a linear system over `Q` in four unknowns
//!   ([`generalized_circle_through`]); its solution is the circle, full rank is the proof
//!   that there is none.
//! * Lemma 7.5: `z(t) = (a₁(t − τ₁)^m + a₂(t − τ₂)^m)/(b₁(t − τ₁)^m + b₂(t − τ₂)^m)` traces a
//!   circle or line iff `τ₁, τ₂` are both real or complex conjugate ([`lemma_7_5`], which
//!   decides it with the linear system above and certifies that the lemma's prediction
//!   agrees). The "only if" needs `m ≥ 2`: for `m = 1`, `z` is a Möbius image of the real
//!   line and always a circle or line (the thesis uses the lemma with `m = 3` only); the
//!   prediction here includes that case.

use super::PhError;
use num_traits::{One, Zero};
use rcagd_algebra::complex::{conj_poly, re_im_polys, Complex};
use rcagd_algebra::{Certificate, Matrix, Poly, Rational};

type Q = Rational;
type C = Complex<Q>;

/// A circle or a line of the complex plane, exactly.
#[derive(Debug, Clone, PartialEq)]
pub enum GeneralizedCircle {
    /// `|z − centre|² = radius_sq`.
    Circle {
        /// The centre.
        centre: C,
        /// `R²`.
        radius_sq: Q,
    },
    /// `{point + λ·direction : λ ∈ R}`.
    Line {
        /// A point of the line.
        point: C,
        /// A direction (non-zero).
        direction: C,
    },
}

impl GeneralizedCircle {
    /// The implicit form `c|z|² + 2Re(d̄z) + e = 0` as `(c, d, e)` (`c = 0` for a line).
    pub fn implicit(&self) -> (Q, C, Q) {
        match self {
            GeneralizedCircle::Circle { centre, radius_sq } => (
                Q::ONE,
                -centre.clone(),
                centre.norm_sq() - radius_sq.clone(),
            ),
            GeneralizedCircle::Line { point, direction } => {
                // normal n = i·direction: Re(n̄(z − p)) = 0
                let n = C::i() * direction.clone();
                let e = -(n.re.clone() * point.re.clone() + n.im.clone() * point.im.clone());
                (Q::ZERO, n.scale(&(Q::ONE / Q::from(2))), e)
            }
        }
    }

    fn from_implicit(c: &Q, d: &C, e: &Q) -> Option<Self> {
        if *c != Q::ZERO {
            let centre = -d.scale(&(Q::ONE / c.clone()));
            let radius_sq = centre.norm_sq() - e.clone() / c.clone();
            return Some(GeneralizedCircle::Circle { centre, radius_sq });
        }
        if d.re == Q::ZERO && d.im == Q::ZERO {
            return None;
        }
        // 2Re(d̄z) + e = 0: point −e d/(2|d|²), direction i·d
        let point = d.scale(&(-e.clone() / (Q::from(2) * d.norm_sq())));
        Some(GeneralizedCircle::Line {
            point,
            direction: C::i() * d.clone(),
        })
    }

    /// `c|A|² + 2Re(d̄AB̄) + e|B|²`: identically zero iff `A/B` lies on the circle or line.
    fn residual(&self, a: &Poly<C>, b: &Poly<C>) -> Poly<Q> {
        let (c, d, e) = self.implicit();
        residual(&c, &d, &e, a, b)
    }

    /// Certificate: `A(t)/B(t)` lies on it, as the polynomial identity
    /// `c|A|² + 2Re(d̄AB̄) + e|B|² ≡ 0`.
    pub fn certify_on(&self, a: &Poly<C>, b: &Poly<C>, what: &str) -> Certificate {
        let r = self.residual(a, b);
        Certificate::decide(
            format!("{what} lies on {self}: c|A|² + 2Re(d̄AB̄) + e|B|² ≡ 0"),
            r.is_zero(),
            true,
            || format!("residual of degree {:?}", r.degree()),
        )
    }
}

impl std::fmt::Display for GeneralizedCircle {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            GeneralizedCircle::Circle { centre, radius_sq } => {
                write!(f, "the circle |z − ({centre})|² = {radius_sq}")
            }
            GeneralizedCircle::Line { point, direction } => {
                write!(f, "the line ({point}) + λ({direction})")
            }
        }
    }
}

fn abs2(p: &Poly<C>) -> Poly<Q> {
    let (re, im) = re_im_polys(p);
    &(&re * &re) + &(&im * &im)
}

fn residual(c: &Q, d: &C, e: &Q, a: &Poly<C>, b: &Poly<C>) -> Poly<Q> {
    // 2Re(d̄ A B̄)
    let ab = &a.scale(&d.conj()) * &conj_poly(b);
    let (re, _) = re_im_polys(&ab);
    &(&abs2(a).scale(c) + &re.scale(&Q::from(2))) + &abs2(b).scale(e)
}

/// Lemma 7.3 / Remark 7.4: the image of the unit circle under
/// `w ↦ (a₁w + a₂)/(b₁w + b₂)`, with its certificate (the rational unit circle
/// `w = (1 + is)/(1 − is)` mapped into the circle or line, identically in `s`).
///
/// # Errors
/// [`PhError::Degenerate`] if `a₁b₂ − a₂b₁ = 0` (a constant map, Remark 7.4) or
/// `b₁ = b₂ = 0`.
pub fn mobius_unit_circle_image(
    a1: &C,
    a2: &C,
    b1: &C,
    b2: &C,
) -> Result<(GeneralizedCircle, Certificate), PhError> {
    let det = a1.clone() * b2.clone() - a2.clone() * b1.clone();
    if det.re == Q::ZERO && det.im == Q::ZERO {
        return Err(PhError::Degenerate(
            "a₁b₂ − a₂b₁ = 0: the map is constant (Besednjak Remark 7.4)".into(),
        ));
    }
    let nb = b1.norm_sq() - b2.norm_sq();
    let image = if nb != Q::ZERO {
        // (7.6)
        let centre =
            (a1.clone() * b1.conj() - a2.clone() * b2.conj()).scale(&(Q::ONE / nb.clone()));
        let radius_sq = det.norm_sq() / (nb.clone() * nb);
        GeneralizedCircle::Circle { centre, radius_sq }
    } else {
        // two finite image points among w = 1, −1, i, −i
        let ws = [C::one(), -C::one(), C::i(), -C::i()];
        let pts: Vec<C> = ws
            .iter()
            .filter_map(|w| {
                let den = b1.clone() * w.clone() + b2.clone();
                let num = a1.clone() * w.clone() + a2.clone();
                (den.norm_sq() != Q::ZERO).then(|| num / den)
            })
            .collect();
        let (p, q) = match pts.as_slice() {
            [p, q, ..] => (p.clone(), q.clone()),
            _ => {
                return Err(PhError::Degenerate(
                    "b₁ = b₂ = 0: the map is undefined".into(),
                ))
            }
        };
        GeneralizedCircle::Line {
            direction: q - p.clone(),
            point: p,
        }
    };
    // w = (1 + is)/(1 − is): A = a₁(1 + is) + a₂(1 − is), B likewise
    let lin = |x: &C, y: &C| {
        Poly::new(vec![
            x.clone() + y.clone(),
            (x.clone() - y.clone()) * C::i(),
        ])
    };
    let cert = image.certify_on(
        &lin(a1, a2),
        &lin(b1, b2),
        "Besednjak Lemma 7.3: z(φ) = (a₁e^{iφ} + a₂)/(b₁e^{iφ} + b₂)",
    );
    Ok((image, cert))
}

/// The circle or line through the rational curve `A(t)/B(t)`, if there is one (module
/// docs): `Ok(Some(_))` with the identity certified, `Ok(None)` when the linear system has
/// full rank (a proof that there is none).
///
/// # Errors
/// [`PhError::Degenerate`] if `B ≡ 0` or `A/B` is constant (every circle through the point
/// qualifies).
pub fn generalized_circle_through(
    a: &Poly<C>,
    b: &Poly<C>,
) -> Result<Option<GeneralizedCircle>, PhError> {
    if b.is_zero() {
        return Err(PhError::Degenerate("the denominator B is zero".into()));
    }
    // A/B constant ⇔ A·B' − A'·B ≡ 0 … more simply A × B proportional: A·B(0)… use the
    // Wronskian
    let w = &(a * &b.derivative()) - &(&a.derivative() * b);
    if w.is_zero() {
        return Err(PhError::Degenerate(
            "A/B is constant: every circle through the point contains it".into(),
        ));
    }
    // unknowns (c, Re d, Im d, e); each contributes a real polynomial
    let cols = [
        residual(&Q::ONE, &C::zero(), &Q::ZERO, a, b),
        residual(&Q::ZERO, &C::one(), &Q::ZERO, a, b),
        residual(&Q::ZERO, &C::i(), &Q::ZERO, a, b),
        residual(&Q::ZERO, &C::zero(), &Q::ONE, a, b),
    ];
    let rows = cols.iter().map(|p| p.coeffs().len()).max().unwrap_or(0);
    let m = Matrix::from_fn(rows, 4, |i, j| {
        cols[j].coeffs().get(i).cloned().unwrap_or(Q::ZERO)
    });
    let kernel = m.null_space();
    let Some(v) = kernel.first() else {
        return Ok(None);
    };
    let d = C::new(v[1].clone(), v[2].clone());
    Ok(GeneralizedCircle::from_implicit(&v[0], &d, &v[3]))
}

/// The result of Lemma 7.5 for given `a₁, a₂, b₁, b₂, τ₁, τ₂, m`.
#[derive(Debug, Clone, PartialEq)]
pub struct Lemma75 {
    /// `A(t) = a₁(t − τ₁)^m + a₂(t − τ₂)^m`.
    pub numerator: Poly<C>,
    /// `B(t) = b₁(t − τ₁)^m + b₂(t − τ₂)^m`.
    pub denominator: Poly<C>,
    /// The lemma's prediction: `τ₁, τ₂` both real or complex conjugate, or `m = 1`.
    pub predicted: bool,
    /// The circle or line through `z(t)`, decided by the linear system.
    pub circle: Option<GeneralizedCircle>,
}

/// Lemma 7.5 for Gaussian-rational data (module docs).
///
/// # Errors
/// [`PhError::OutOfRange`] for `m = 0`; [`PhError::Degenerate`] when `z` is constant
/// (`a₁b₂ = a₂b₁` or `τ₁ = τ₂`) or `B ≡ 0`.
pub fn lemma_7_5(a: [&C; 2], b: [&C; 2], tau: [&C; 2], m: u32) -> Result<Lemma75, PhError> {
    if m == 0 {
        return Err(PhError::OutOfRange("Lemma 7.5 needs m ≥ 1".into()));
    }
    let pw = |t: &C| {
        let lin = Poly::new(vec![-t.clone(), C::one()]);
        (0..m).fold(Poly::constant(C::one()), |acc, _| &acc * &lin)
    };
    let (p1, p2) = (pw(tau[0]), pw(tau[1]));
    let numerator = &p1.scale(a[0]) + &p2.scale(a[1]);
    let denominator = &p1.scale(b[0]) + &p2.scale(b[1]);
    let real = |t: &C| t.im == Q::ZERO;
    let predicted = m == 1 || (real(tau[0]) && real(tau[1])) || *tau[0] == tau[1].conj();
    let circle = generalized_circle_through(&numerator, &denominator)?;
    Ok(Lemma75 {
        numerator,
        denominator,
        predicted,
        circle,
    })
}

impl Lemma75 {
    /// Certificates: the curve lies on the circle found (polynomial identity), and the
    /// lemma's prediction agrees with the decision (a circle exists iff predicted; no
    /// circle is proven by the full rank of the linear system).
    pub fn certify(&self) -> Vec<Certificate> {
        let mut v = Vec::new();
        if let Some(c) = &self.circle {
            v.push(c.certify_on(&self.numerator, &self.denominator, "z(t) of Lemma 7.5"));
        }
        let word = |b: bool| {
            if b {
                "a circle or line"
            } else {
                "no circle or line"
            }
        };
        v.push(Certificate::decide(
            format!(
                "Besednjak Lemma 7.5: τ₁, τ₂ {} both real or conjugate (or m = 1), so z(t) traces {}",
                if self.predicted { "are" } else { "are not" },
                word(self.predicted)
            ),
            self.predicted == self.circle.is_some(),
            true,
            || format!("the linear system finds {}", word(self.circle.is_some())),
        ));
        v
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(re: i64, im: i64) -> C {
        C::new(Q::from(re), Q::from(im))
    }

    #[test]
    fn lemma_7_3_circle_and_line() {
        // z = (e^{iφ} + 0)/(2e^{iφ} + 1): centre 2/3, R = 1/3
        let (img, cert) = mobius_unit_circle_image(&c(1, 0), &c(0, 0), &c(2, 0), &c(1, 0)).unwrap();
        assert!(cert.holds && cert.exact, "{cert}");
        assert_eq!(
            img,
            GeneralizedCircle::Circle {
                centre: C::new(Q::from(2) / Q::from(3), Q::ZERO),
                radius_sq: Q::ONE / Q::from(9)
            }
        );
        // |b₁| = |b₂|: z = 1/(w + 1) traces the line Re z = 1/2
        let (img, cert) = mobius_unit_circle_image(&c(0, 0), &c(1, 0), &c(1, 0), &c(1, 0)).unwrap();
        assert!(cert.holds, "{cert}");
        assert!(matches!(img, GeneralizedCircle::Line { .. }));
        assert!(matches!(
            mobius_unit_circle_image(&c(1, 1), &c(2, 2), &c(1, 0), &c(2, 0)),
            Err(PhError::Degenerate(_))
        ));
    }

    #[test]
    fn lemma_7_5_all_cases() {
        let (a1, a2, b1, b2) = (c(1, 2), c(-1, 0), c(0, 1), c(3, -1));
        // real roots, conjugate roots: circles
        for (t1, t2) in [(c(0, 0), c(1, 0)), (c(1, 2), c(1, -2))] {
            for m in 1..=3 {
                let l = lemma_7_5([&a1, &a2], [&b1, &b2], [&t1, &t2], m).unwrap();
                assert!(l.predicted && l.circle.is_some());
                assert!(l.certify().iter().all(|c| c.holds && c.exact));
            }
        }
        // neither: no circle, proven by full rank
        let l = lemma_7_5([&a1, &a2], [&b1, &b2], [&c(0, 1), &c(2, 3)], 2).unwrap();
        assert!(!l.predicted && l.circle.is_none());
        assert!(l.certify().iter().all(|c| c.holds));
        // m = 1: a Möbius image of the real line, always a circle
        let l = lemma_7_5([&a1, &a2], [&b1, &b2], [&c(0, 1), &c(2, 3)], 1).unwrap();
        assert!(l.predicted && l.circle.is_some());
        assert!(l.certify().iter().all(|c| c.holds));
        assert!(lemma_7_5([&a1, &a2], [&b1, &b2], [&c(0, 1), &c(0, 1)], 2).is_err());
    }
}
