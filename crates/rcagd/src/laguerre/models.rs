//! The models of Euclidean Laguerre geometry and the maps between them (Peternell §3.1–§3.5,
//! docs/math/laguerre-pn.md#conventions; every formula below was re-derived and is checked by the
//! unit tests and `tests/it/seed004_pn_examples.rs`).
//!
//! | object | standard model | cyclographic `R⁴` (3.5)/(3.6) | Blaschke cylinder (3.10) | isotropic `I³` (3.11)/(3.12) |
//! |---|---|---|---|---|
//! | oriented plane `(e0, n)` | `e0 + n·x = 0` | γ-hyperplane `(e0, n₁, n₂, n₃, 1)` | point `(1, n₁, n₂, n₃, e0)` on `x₁²+x₂²+x₃² = x₀²` | point `(n₁, n₂, e0)/(1 − n₃)` |
//! | cycle `(m; r)` | sphere, signed radius | point `(m, r)` | hyperplane section `(r, m₁, m₂, m₃, 1)` | isotropic sphere `2y₃ + S(r+m₃) + 2y₁m₁ + 2y₂m₂ + r − m₃ = 0` |
//! | oriented contact | `e0 + n·m + r = 0` (3.3) | incidence | incidence | incidence |
//!
//! (`S = y₁² + y₂²`.) The inverse of the isotropic map is (3.13)
//! `Λ⁻¹(y) = (2y₃, 2y₁, 2y₂, S − 1)/(S + 1)`; planes with `n = (0,0,1)` have no image in
//! `I³` (isotropic conformal closure). The dual isotropic model (3.16) is
//! `Λ*(e) = (e0, e1, e2, e3 − 1)` (the bisector plane of `e` and `x₃ = 0`); its inverse
//! (3.17) must carry the factor `ρ = −2Y₃/(Y₁²+Y₂²+Y₃²)` to give the *oriented* plane
//! (docs/math/laguerre-pn.md).
//!
//! The pe (Lorentz) scalar product of the cyclographic model is
//! `⟨a, b⟩ = a₁b₁ + a₂b₂ + a₃b₃ − a₄b₄` ([`lorentz_product`]); for two cycles on a
//! hyperbolic line it is the squared tangential distance
//! ([`Cycle::tangential_distance_squared`]); it vanishes iff the cycles touch.

use super::LaguerreError;
use crate::certs::is_negligible;
use crate::error::{format_point, format_scalar};
use rcagd_algebra::Scalar;

fn dot3<F: Scalar>(a: &[F; 3], b: &[F; 3]) -> F {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() + a[2].clone() * b[2].clone()
}

fn magnitude<F: Scalar>(xs: &[F]) -> f64 {
    xs.iter().map(|x| x.to_f64().abs()).fold(1.0, f64::max)
}

fn check_finite<F: Scalar>(name: &str, xs: &[F]) -> Result<(), LaguerreError> {
    if !F::EXACT && xs.iter().any(|x| !x.to_f64().is_finite()) {
        return Err(LaguerreError::NotFinite(name.to_string()));
    }
    Ok(())
}

/// The pe (Lorentz) scalar product of the cyclographic model,
/// `⟨a, b⟩ = a₁b₁ + a₂b₂ + a₃b₃ − a₄b₄` (Peternell §3.2, `E_pe = diag(1,1,1,−1)`).
pub fn lorentz_product<F: Scalar>(a: &[F; 4], b: &[F; 4]) -> F {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() + a[2].clone() * b[2].clone()
        - a[3].clone() * b[3].clone()
}

/// An oriented plane `e0 + n·x = 0` with unit normal `n` (Peternell (3.1);
/// docs/math/laguerre-pn.md#conventions).
#[derive(Debug, Clone, PartialEq)]
pub struct OrientedPlane<F> {
    /// The coefficient `e0` (minus the signed distance of the origin along `n`).
    pub e0: F,
    /// The unit normal `n = (e1, e2, e3)`.
    pub n: [F; 3],
}

impl<F: Scalar> OrientedPlane<F> {
    /// The oriented plane `e0 + n·x = 0`.
    ///
    /// # Errors
    /// [`LaguerreError::NotUnitNormal`] unless `|n|² = 1` (exactly for exact scalars);
    /// [`LaguerreError::NotFinite`] for a non-finite `f64`.
    pub fn new(e0: F, n: [F; 3]) -> Result<Self, LaguerreError> {
        check_finite(
            "oriented plane",
            &[e0.clone(), n[0].clone(), n[1].clone(), n[2].clone()],
        )?;
        let r = dot3(&n, &n) - F::one();
        if !is_negligible(&r, 1.0) {
            return Err(LaguerreError::NotUnitNormal {
                normal: format_point(&n),
                residual: format_scalar(&r),
            });
        }
        Ok(OrientedPlane { e0, n })
    }

    /// The oriented plane through `p` with unit normal `n`: `e0 = −n·p`.
    ///
    /// # Errors
    /// As [`Self::new`].
    pub fn through_point(n: [F; 3], p: &[F; 3]) -> Result<Self, LaguerreError> {
        let e0 = -dot3(&n, p);
        Self::new(e0, n)
    }

    /// The signed distance `e0 + n·x` of the point `x` (positive on the side `n` points to).
    pub fn signed_distance(&self, x: &[F; 3]) -> F {
        self.e0.clone() + dot3(&self.n, x)
    }

    /// `true` if `x` lies on the plane (exactly for exact scalars).
    pub fn contains(&self, x: &[F; 3]) -> bool {
        is_negligible(&self.signed_distance(x), magnitude(x))
    }

    /// The plane with the opposite orientation `(−e0, −n)`.
    pub fn reversed(&self) -> Self {
        OrientedPlane {
            e0: -self.e0.clone(),
            n: [-self.n[0].clone(), -self.n[1].clone(), -self.n[2].clone()],
        }
    }

    /// The one-sided offset at oriented distance `d`, `x ↦ x + d n`: `e0 ↦ e0 − d`
    /// (docs/math/laguerre-pn.md#conventions; Peternell's printed `e0 ↦ e0 + d` in (3.15)/(4.2) is
    /// the offset by `−d`).
    pub fn offset(&self, d: &F) -> Self {
        OrientedPlane {
            e0: self.e0.clone() - d.clone(),
            n: self.n.clone(),
        }
    }

    /// The γ-hyperplane of the cyclographic model, Peternell (3.5): the coefficients
    /// `(e0, e1, e2, e3, 1)` of `ε₀ + ε₁x₁ + … + ε₄x₄ = 0` in `R⁴`. A cycle `(m; r)` touches
    /// the plane iff its point `(m, r)` lies on it.
    pub fn to_gamma_hyperplane(&self) -> [F; 5] {
        [
            self.e0.clone(),
            self.n[0].clone(),
            self.n[1].clone(),
            self.n[2].clone(),
            F::one(),
        ]
    }

    /// The oriented plane of a γ-hyperplane `(ε₀, …, ε₄)` (any non-zero multiple): divide
    /// by `ε₄` and read `(e0, n)` (Peternell (3.20), `η*`).
    ///
    /// # Errors
    /// [`LaguerreError::Degenerate`] if `ε₄ = 0`; [`LaguerreError::NotLightlike`] unless
    /// `ε₁² + ε₂² + ε₃² = ε₄²`.
    pub fn from_gamma_hyperplane(h: &[F; 5]) -> Result<Self, LaguerreError> {
        check_finite("γ-hyperplane", h)?;
        let inv = h[4].inv().ok_or_else(|| {
            LaguerreError::Degenerate("a γ-hyperplane needs ε₄ ≠ 0 (it is parallel to x₄)".into())
        })?;
        let n = [
            h[1].clone() * inv.clone(),
            h[2].clone() * inv.clone(),
            h[3].clone() * inv.clone(),
        ];
        let r = dot3(&n, &n) - F::one();
        if !is_negligible(&r, 1.0) {
            return Err(LaguerreError::NotLightlike(format!(
                "ε₁² + ε₂² + ε₃² − ε₄² ≠ 0 for {}",
                format_point(h)
            )));
        }
        Ok(OrientedPlane {
            e0: h[0].clone() * inv,
            n,
        })
    }

    /// The point of the Blaschke cylinder, Peternell (3.10), homogeneous `(x₀, …, x₄) =
    /// (1, e1, e2, e3, e0)`; it lies on `x₁² + x₂² + x₃² = x₀²`. Parallel planes lie on one
    /// generator line (fixed `x₁, x₂, x₃`).
    pub fn to_blaschke(&self) -> [F; 5] {
        [
            F::one(),
            self.n[0].clone(),
            self.n[1].clone(),
            self.n[2].clone(),
            self.e0.clone(),
        ]
    }

    /// The oriented plane of a (homogeneous) point of the Blaschke cylinder.
    ///
    /// # Errors
    /// [`LaguerreError::Degenerate`] for `x₀ = 0`; [`LaguerreError::NotLightlike`] if the
    /// point is not on the cylinder.
    pub fn from_blaschke(p: &[F; 5]) -> Result<Self, LaguerreError> {
        check_finite("Blaschke point", p)?;
        let inv = p[0].inv().ok_or_else(|| {
            LaguerreError::Degenerate("Blaschke point at infinity (x₀ = 0)".into())
        })?;
        let n = [
            p[1].clone() * inv.clone(),
            p[2].clone() * inv.clone(),
            p[3].clone() * inv.clone(),
        ];
        let r = dot3(&n, &n) - F::one();
        if !is_negligible(&r, 1.0) {
            return Err(LaguerreError::NotLightlike(format!(
                "{} is not on the Blaschke cylinder x₁²+x₂²+x₃² = x₀²",
                format_point(p)
            )));
        }
        Ok(OrientedPlane {
            e0: p[4].clone() * inv,
            n,
        })
    }

    /// The point of the isotropic model, Peternell (3.11): `Λ(e) = (e1, e2, e0)/(1 − e3)` (the
    /// stereographic projection of the Blaschke cylinder from `W = (0,0,1,0)`).
    ///
    /// # Errors
    /// [`LaguerreError::NoIsotropicImage`] for `n = (0, 0, 1)`.
    pub fn to_isotropic(&self) -> Result<[F; 3], LaguerreError> {
        let den = F::one() - self.n[2].clone();
        let inv = den
            .inv()
            .ok_or_else(|| LaguerreError::NoIsotropicImage(self.describe()))?;
        Ok([
            self.n[0].clone() * inv.clone(),
            self.n[1].clone() * inv.clone(),
            self.e0.clone() * inv,
        ])
    }

    /// The oriented plane of a point of the isotropic model, Peternell (3.13):
    /// `Λ⁻¹(y) = (2y₃, 2y₁, 2y₂, S − 1)/(S + 1)`, `S = y₁² + y₂²` (always a unit normal).
    pub fn from_isotropic(y: &[F; 3]) -> Self {
        let s = y[0].clone() * y[0].clone() + y[1].clone() * y[1].clone();
        let inv = F::one() / (s.clone() + F::one());
        let two = F::from_i64(2);
        OrientedPlane {
            e0: two.clone() * y[2].clone() * inv.clone(),
            n: [
                two.clone() * y[0].clone() * inv.clone(),
                two * y[1].clone() * inv.clone(),
                (s - F::one()) * inv,
            ],
        }
    }

    /// The (non-oriented) bisector plane of the dual isotropic model, Peternell (3.16):
    /// `Λ*(e) = (e0, e1, e2, e3 − 1)`, homogeneous coefficients `(Y₀, …, Y₃)` of
    /// `Y₀ + Y₁x₁ + Y₂x₂ + Y₃x₃ = 0`: the points at equal signed distance from `e` and from
    /// the fixed plane `x₃ = 0`.
    pub fn to_dual_isotropic(&self) -> [F; 4] {
        [
            self.e0.clone(),
            self.n[0].clone(),
            self.n[1].clone(),
            self.n[2].clone() - F::one(),
        ]
    }

    /// The inverse of the dual isotropic map for any non-zero multiple `Y` of a plane,
    /// Peternell (3.17) **corrected** (docs/math/laguerre-pn.md): the oriented plane is
    /// `ρ·(Y₀, Y₁, Y₂, (Y₃² − Y₁² − Y₂²)/(2Y₃))` with `ρ = −2Y₃/(Y₁² + Y₂² + Y₃²)`; the
    /// printed form omits `ρ`, which is negative for `Y₃ > 0` and so reverses the
    /// orientation there.
    ///
    /// # Errors
    /// [`LaguerreError::Degenerate`] for `Y₃ = 0` (the plane is parallel to the light rays
    /// `x₃`: its preimage is the fixed plane `x₃ = 0` itself, or none).
    pub fn from_dual_isotropic(y: &[F; 4]) -> Result<Self, LaguerreError> {
        check_finite("dual isotropic plane", y)?;
        if y[3].is_zero() {
            return Err(LaguerreError::Degenerate(
                "the dual isotropic plane has Y₃ = 0: it has no preimage oriented plane".into(),
            ));
        }
        let q = y[1].clone() * y[1].clone() + y[2].clone() * y[2].clone();
        let rho = -F::from_i64(2) * y[3].clone() / (q.clone() + y[3].clone() * y[3].clone());
        let e3 = (y[3].clone() * y[3].clone() - q) / (F::from_i64(2) * y[3].clone());
        Ok(OrientedPlane {
            e0: rho.clone() * y[0].clone(),
            n: [
                rho.clone() * y[1].clone(),
                rho.clone() * y[2].clone(),
                rho * e3,
            ],
        })
    }

    fn describe(&self) -> String {
        format!(
            "(e0 = {}, n = {})",
            format_scalar(&self.e0),
            format_point(&self.n)
        )
    }
}

/// A cycle `(m; r)`: an oriented sphere with centre `m` and signed radius `r`, a point for
/// `r = 0` (Peternell §3.1). As a set of oriented planes it is every plane with
/// `e0 + n·m + r = 0` (3.2).
#[derive(Debug, Clone, PartialEq)]
pub struct Cycle<F> {
    /// Centre `m`.
    pub center: [F; 3],
    /// Signed radius `r` (`r = 0`: a point).
    pub radius: F,
}

impl<F: Scalar> Cycle<F> {
    /// The cycle `(m; r)`.
    ///
    /// # Errors
    /// [`LaguerreError::NotFinite`] for a non-finite `f64`.
    pub fn new(center: [F; 3], radius: F) -> Result<Self, LaguerreError> {
        check_finite(
            "cycle",
            &[
                center[0].clone(),
                center[1].clone(),
                center[2].clone(),
                radius.clone(),
            ],
        )?;
        Ok(Cycle { center, radius })
    }

    /// The point `p` as a cycle of radius 0.
    pub fn point(p: [F; 3]) -> Self {
        Cycle {
            center: p,
            radius: F::zero(),
        }
    }

    /// `e0 + n·m + r`: zero iff the plane and the cycle are in oriented contact (3.3).
    pub fn contact_residual(&self, plane: &OrientedPlane<F>) -> F {
        plane.e0.clone() + dot3(&plane.n, &self.center) + self.radius.clone()
    }

    /// `true` if the plane touches the cycle with equal orientation (3.3); for a point
    /// cycle: the plane passes through it.
    pub fn in_oriented_contact(&self, plane: &OrientedPlane<F>) -> bool {
        let scale = magnitude(&self.center).max(self.radius.to_f64().abs());
        is_negligible(&self.contact_residual(plane), scale)
    }

    /// The point of contact `m + r n` of a plane in oriented contact
    /// (docs/math/laguerre-pn.md#conventions).
    ///
    /// # Errors
    /// [`LaguerreError::NotInContact`] unless `e0 + n·m + r = 0`.
    pub fn contact_point(&self, plane: &OrientedPlane<F>) -> Result<[F; 3], LaguerreError> {
        if !self.in_oriented_contact(plane) {
            return Err(LaguerreError::NotInContact(format_scalar(
                &self.contact_residual(plane),
            )));
        }
        Ok([0, 1, 2].map(|i| self.center[i].clone() + self.radius.clone() * plane.n[i].clone()))
    }

    /// The dilatation `r ↦ r + d` (3.4): the cycle of the offset surfaces at distance `d`.
    pub fn offset(&self, d: &F) -> Self {
        Cycle {
            center: self.center.clone(),
            radius: self.radius.clone() + d.clone(),
        }
    }

    /// The point `(m₁, m₂, m₃, r)` of the cyclographic model (3.6).
    pub fn to_cyclographic(&self) -> [F; 4] {
        [
            self.center[0].clone(),
            self.center[1].clone(),
            self.center[2].clone(),
            self.radius.clone(),
        ]
    }

    /// The cycle of a point of the cyclographic model (the cyclographic map `η`, (3.19)).
    pub fn from_cyclographic(x: &[F; 4]) -> Self {
        Cycle {
            center: [x[0].clone(), x[1].clone(), x[2].clone()],
            radius: x[3].clone(),
        }
    }

    /// The hyperplane of the Blaschke model whose section with the cylinder is the cycle
    /// (Peternell §3.3): homogeneous coefficients `(r, m₁, m₂, m₃, 1)` of
    /// `r x₀ + m·(x₁, x₂, x₃) + x₄ = 0`; the Blaschke point of a plane lies on it iff the
    /// plane touches the cycle.
    pub fn blaschke_hyperplane(&self) -> [F; 5] {
        [
            self.radius.clone(),
            self.center[0].clone(),
            self.center[1].clone(),
            self.center[2].clone(),
            F::one(),
        ]
    }

    /// The isotropic sphere of the cycle, Lemma 3.1 (3.12).
    pub fn isotropic_sphere(&self) -> IsotropicSphere<F> {
        let half = F::one() / F::from_i64(2);
        let (m, r) = (&self.center, &self.radius);
        IsotropicSphere {
            alpha: -(r.clone() + m[2].clone()) * half.clone(),
            beta: [-m[0].clone(), -m[1].clone()],
            gamma: -(r.clone() - m[2].clone()) * half,
        }
    }

    /// The squared tangential distance `⟨a − b, a − b⟩ = |m_a − m_b|² − (r_a − r_b)²` of the
    /// cyclographic model (Peternell §3.2): the squared distance of the contact points on a
    /// common oriented tangent plane when positive, zero iff the cycles touch (oriented),
    /// negative iff they have no common oriented tangent plane.
    pub fn tangential_distance_squared(&self, other: &Cycle<F>) -> F {
        let a = self.to_cyclographic();
        let b = other.to_cyclographic();
        let d = [0, 1, 2, 3].map(|i| a[i].clone() - b[i].clone());
        lorentz_product(&d, &d)
    }
}

/// An isotropic sphere of the isotropic model `I³`: the graph
/// `y₃ = α(y₁² + y₂²) + β₁y₁ + β₂y₂ + γ` (a paraboloid of revolution with isotropic axis,
/// or a non-isotropic plane for `α = 0`) — by Lemma 3.1 (3.12) exactly the images of
/// cycles: `α = −(r + m₃)/2`, `β = −(m₁, m₂)`, `γ = −(r − m₃)/2`.
#[derive(Debug, Clone, PartialEq)]
pub struct IsotropicSphere<F> {
    /// Coefficient of `y₁² + y₂²`.
    pub alpha: F,
    /// Coefficients of `y₁`, `y₂`.
    pub beta: [F; 2],
    /// Constant term.
    pub gamma: F,
}

impl<F: Scalar> IsotropicSphere<F> {
    /// The height `y₃` over `(y₁, y₂)`.
    pub fn eval(&self, y1: &F, y2: &F) -> F {
        self.alpha.clone() * (y1.clone() * y1.clone() + y2.clone() * y2.clone())
            + self.beta[0].clone() * y1.clone()
            + self.beta[1].clone() * y2.clone()
            + self.gamma.clone()
    }

    /// `true` if `y` lies on the isotropic sphere.
    pub fn contains(&self, y: &[F; 3]) -> bool {
        let r = self.eval(&y[0], &y[1]) - y[2].clone();
        is_negligible(&r, magnitude(y))
    }

    /// The cycle it represents: `r = −(α + γ)`, `m = (−β₁, −β₂, γ − α)` (inverse of (3.12)).
    pub fn to_cycle(&self) -> Cycle<F> {
        Cycle {
            center: [
                -self.beta[0].clone(),
                -self.beta[1].clone(),
                self.gamma.clone() - self.alpha.clone(),
            ],
            radius: -(self.alpha.clone() + self.gamma.clone()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    fn plane() -> OrientedPlane<Rational> {
        // n = (2, 3, 6)/7
        OrientedPlane::new(q(5, 3), [q(2, 7), q(3, 7), q(6, 7)]).expect("unit")
    }

    #[test]
    fn unit_normal_is_checked() {
        assert!(matches!(
            OrientedPlane::new(q(0, 1), [q(1, 1), q(1, 1), q(0, 1)]),
            Err(LaguerreError::NotUnitNormal { .. })
        ));
        assert!(OrientedPlane::new(1.0, [f64::NAN, 0.0, 1.0]).is_err());
    }

    #[test]
    fn model_round_trips() {
        let e = plane();
        assert_eq!(
            OrientedPlane::from_gamma_hyperplane(&e.to_gamma_hyperplane()).expect("γ"),
            e
        );
        assert_eq!(
            OrientedPlane::from_blaschke(&e.to_blaschke()).expect("Δ"),
            e
        );
        let y = e.to_isotropic().expect("n3 ≠ 1");
        assert_eq!(OrientedPlane::from_isotropic(&y), e);
        // a multiple of the γ-hyperplane gives the same plane
        let h = e.to_gamma_hyperplane().map(|x| x * q(-3, 2));
        assert_eq!(OrientedPlane::from_gamma_hyperplane(&h).expect("γ"), e);
        // dual isotropic: the inverse of Λ* for any multiple, orientation kept
        // (docs/math/laguerre-pn.md, Errata E7)
        for k in [q(1, 1), q(-5, 2), q(7, 3)] {
            let yy = e.to_dual_isotropic().map(|x| x * k.clone());
            assert_eq!(OrientedPlane::from_dual_isotropic(&yy).expect("Y3 ≠ 0"), e);
        }
        let top = OrientedPlane::new(q(1, 1), [q(0, 1), q(0, 1), q(1, 1)]).expect("unit");
        assert!(matches!(
            top.to_isotropic(),
            Err(LaguerreError::NoIsotropicImage(_))
        ));
    }

    #[test]
    fn contact_is_incidence_in_every_model() {
        let e = plane();
        // the cycle with centre m touching e: r = −e0 − n·m
        let m = [q(1, 2), q(-3, 1), q(2, 5)];
        let r = -e.e0.clone() - dot3(&e.n, &m);
        let c = Cycle::new(m, r).expect("finite");
        assert!(c.in_oriented_contact(&e));
        let x = c.contact_point(&e).expect("contact");
        assert!(e.contains(&x));
        // cyclographic: the point lies on the γ-hyperplane
        let h = e.to_gamma_hyperplane();
        let p = c.to_cyclographic();
        let inc = h[0].clone() + (0..4).fold(q(0, 1), |s, i| s + h[i + 1].clone() * p[i].clone());
        assert_eq!(inc, q(0, 1));
        // Blaschke: the plane's point lies on the cycle's hyperplane
        let b = e.to_blaschke();
        let bh = c.blaschke_hyperplane();
        assert_eq!(
            (0..5).fold(q(0, 1), |s, i| s + b[i].clone() * bh[i].clone()),
            q(0, 1)
        );
        // isotropic: the plane's point lies on the isotropic sphere, and back
        let sph = c.isotropic_sphere();
        assert!(sph.contains(&e.to_isotropic().expect("image")));
        assert_eq!(sph.to_cycle(), c);
        // a plane not touching the cycle: no incidence anywhere
        let f = e.offset(&q(1, 1));
        assert!(!c.in_oriented_contact(&f));
        assert!(!sph.contains(&f.to_isotropic().expect("image")));
        assert!(matches!(
            c.contact_point(&f),
            Err(LaguerreError::NotInContact(_))
        ));
        // offsets: the dilatation keeps the contact (e0 − d ⇔ r + d,
        // docs/math/laguerre-pn.md, Errata E6)
        assert!(c.offset(&q(1, 1)).in_oriented_contact(&f));
    }

    #[test]
    fn tangential_distance() {
        // two cycles with a common oriented tangent plane z = 0 (n = (0,0,1)):
        // contact points m + r n are (0,0,0) and (3,4,0): tangential distance 5
        let a = Cycle::new([q(0, 1), q(0, 1), q(2, 1)], q(-2, 1)).expect("finite");
        let b = Cycle::new([q(3, 1), q(4, 1), q(7, 1)], q(-7, 1)).expect("finite");
        assert_eq!(a.tangential_distance_squared(&b), q(25, 1));
        // touching cycles (oriented): distance 0
        let c = Cycle::new([q(0, 1), q(0, 1), q(5, 1)], q(-5, 1)).expect("finite");
        assert_eq!(a.tangential_distance_squared(&c), q(0, 1));
    }

    #[test]
    fn dual_isotropic_zero_y3_is_an_error() {
        assert!(OrientedPlane::<Rational>::from_dual_isotropic(&[
            q(1, 1),
            q(1, 1),
            q(0, 1),
            q(0, 1)
        ])
        .is_err());
    }
}
