//! Sphere geometry models: the cyclographic (Laguerre) model `R^{3,1}` of oriented spheres
//! (Gruber 2008 §1.2) and the Möbius model `Q ⊂ P⁴` (Peternell §2.4,
//! docs/math/laguerre-pn.md).
//!
//! **Cyclographic model.** An oriented sphere (cycle) with centre `m` and signed radius `r`
//! (points are cycles of radius 0) is the point `(m, r) ∈ R⁴` (Gruber 2008 (1.12)); `R⁴` carries
//! the Lorentz ("pseudo-euclidean") product `⟨a, b⟩_pe = a₁b₁ + a₂b₂ + a₃b₃ − a₄b₄`
//! (1.15). Two cycles are in **oriented contact** iff their difference is isotropic:
//! `⟨k₁ − k₂, k₁ − k₂⟩_pe = 0` (1.13) — the printed (1.16) `⟨k₁, k₂⟩_pe = 0` is wrong
//! (docs/math/lines-and-canal.md, G2). Oriented circles in the plane are the points of `R^{2,1}` in the same way.
//! Orientation convention (docs/math/laguerre-pn.md#conventions): the oriented plane `e₀ + n·x = 0` (`|n| = 1`)
//! touches the cycle `(m; r)` iff `e₀ + n·m + r = 0`, the contact point is `m + r n`; two
//! touching cycles share the contact point `x = m₁ + r₁ν = m₂ + r₂ν` with the common unit
//! normal `ν = (m₁ − m₂)/(r₂ − r₁)`.
//!
//! Vectors of `R^{3,1}` are *spacelike* (flachgängig, `⟨v,v⟩ > 0`), *lightlike* (isotrop) or
//! *timelike* (steilgängig) (Gruber 2008 §1.2.1). The cyclographic image of a point `F` along an
//! isotropic direction `w` is the point `F − (F₄/w₄)(w₁, w₂, w₃)` where the isotropic line
//! meets `x₄ = 0` (003-3); the isotropic directions are `w(s,t) = (2s, 2t, 1 − s² − t²,
//! 1 + s² + t²)` (the absolute quadric `Ω`). Lines of `R^{3,1}` map to cylinders of
//! revolution (parallel to `x₄ = 0`), cones of revolution (spacelike), planes (lightlike) or
//! nothing real (timelike) (Gruber 2008 §1.2.2).
//!
//! **Möbius model.** `Q: −x₀² + x₁² + x₂² + x₃² + x₄² = 0` (Peternell (2.12)), north pole
//! `N = (1, 0, 0, 0, 1)`. A point `p ∉ Q` is the sphere with centre `pᵢ/(p₀ − p₄)` and
//! squared radius `(p₁² + p₂² + p₃² + p₄² − p₀²)/(p₀ − p₄)²` (2.13, verified); for `p₀ = p₄` the
//! plane `−p₀ + p₁y₁ + p₂y₂ + p₃y₃ = 0`; points of `Q` are the points
//! `σ(x) = (x₁, x₂, x₃)/(x₀ − x₄)` of `R³` (inverse: `(|y|² + 1, 2y, |y|² − 1)`). A line of `P⁴`
//! is a pencil of spheres: elliptic (meets `Q` in two conjugate points: the spheres through a
//! real circle), hyperbolic (two real points: two limit points) or parabolic (tangent).
//! A curve `c(t)` has a real envelope (a canal surface) where its tangent lines do not meet
//! `Q` in real points (Peternell §2.4, Thm 2.3).

use crate::error::format_scalar;
use crate::lines::{fmt_vec, is_small, scale_of};
use crate::Certified;
use rcagd_algebra::{Certificate, Scalar};
use thiserror::Error;

/// Errors of the sphere-geometry models. Every variant names the violated precondition.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum CyclographicError {
    /// Two cycles that must be in oriented contact are not.
    #[error(
        "the cycles are not in oriented contact: ⟨k₁ − k₂, k₁ − k₂⟩_pe = {0} ≠ 0 (Gruber (1.13))"
    )]
    NotInContact(String),
    /// Two cycles are identical (their contact is not a point).
    #[error("identical cycles {0}: every point is a contact point")]
    IdenticalCycles(String),
    /// An isotropic direction with `w₄ = 0` has no image in `x₄ = 0`.
    #[error("the direction {0} is parallel to x₄ = 0 (w₄ = 0): no cyclographic image point")]
    HorizontalDirection(String),
    /// A vector that must be isotropic (lightlike) is not.
    #[error("the direction {0} is not isotropic: ⟨w, w⟩_pe = {1}")]
    NotIsotropic(String, String),
    /// A plane normal must be a (rational) unit vector.
    #[error("the plane normal {0} is not a unit vector: |n|² = {1}")]
    NotUnitNormal(String, String),
    /// A vector that must be non-zero is zero.
    #[error("zero vector: {0}")]
    ZeroVector(String),
}

/// The Lorentz product `⟨a, b⟩_pe = a₁b₁ + a₂b₂ + a₃b₃ − a₄b₄` of `R^{3,1}` (Gruber 2008 (1.15)).
pub fn lorentz<F: Scalar>(a: &[F; 4], b: &[F; 4]) -> F {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() + a[2].clone() * b[2].clone()
        - a[3].clone() * b[3].clone()
}

/// The Lorentz product `a₁b₁ + a₂b₂ − a₃b₃` of `R^{2,1}` (oriented circles).
pub fn lorentz3<F: Scalar>(a: &[F; 3], b: &[F; 3]) -> F {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() - a[2].clone() * b[2].clone()
}

/// The causal type of a vector of `R^{3,1}` (Gruber 2008 §1.2.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CausalType {
    /// `⟨v, v⟩_pe > 0` (flachgängig, "raumartig").
    Spacelike,
    /// `⟨v, v⟩_pe = 0` (isotrop, "lichtartig").
    Lightlike,
    /// `⟨v, v⟩_pe < 0` (steilgängig, "zeitartig").
    Timelike,
}

/// The causal type of `v` (exact for exact scalars).
pub fn causal_type<F: Scalar>(v: &[F; 4]) -> CausalType {
    let n = lorentz(v, v);
    let s = scale_of(v);
    if is_small(&n, s * s) {
        CausalType::Lightlike
    } else if n > F::zero() {
        CausalType::Spacelike
    } else {
        CausalType::Timelike
    }
}

/// An oriented sphere (cycle) `(m; r)` with signed radius; `r = 0` is a point.
#[derive(Debug, Clone, PartialEq)]
pub struct OrientedSphere<F> {
    /// Centre `m`.
    pub center: [F; 3],
    /// Signed radius `r` (the orientation).
    pub radius: F,
}

impl<F: Scalar> OrientedSphere<F> {
    /// The cycle `(m; r)`.
    pub fn new(center: [F; 3], radius: F) -> Self {
        OrientedSphere { center, radius }
    }

    /// Its cyclographic preimage `(m₁, m₂, m₃, r) ∈ R^{3,1}` (Gruber 2008 (1.12)).
    pub fn to_point(&self) -> [F; 4] {
        [
            self.center[0].clone(),
            self.center[1].clone(),
            self.center[2].clone(),
            self.radius.clone(),
        ]
    }

    /// The cycle `γ(P)` of a point `P ∈ R^{3,1}`: centre `(p₁, p₂, p₃)`, radius `p₄`.
    pub fn from_point(p: &[F; 4]) -> Self {
        OrientedSphere {
            center: [p[0].clone(), p[1].clone(), p[2].clone()],
            radius: p[3].clone(),
        }
    }

    /// The same sphere with the opposite orientation `(m; −r)`.
    pub fn reversed(&self) -> Self {
        OrientedSphere {
            center: self.center.clone(),
            radius: -self.radius.clone(),
        }
    }

    /// `|x − m|² − r²` (zero on the sphere).
    pub fn power(&self, x: &[F; 3]) -> F {
        let d: [F; 3] = core::array::from_fn(|i| x[i].clone() - self.center[i].clone());
        crate::lines::dot(&d, &d) - self.radius.clone() * self.radius.clone()
    }

    /// `⟨k₁ − k₂, k₁ − k₂⟩_pe` (zero iff in oriented contact; Gruber 2008 (1.13)).
    pub fn contact_residual(&self, other: &OrientedSphere<F>) -> F {
        let a = self.to_point();
        let b = other.to_point();
        let d: [F; 4] = core::array::from_fn(|i| a[i].clone() - b[i].clone());
        lorentz(&d, &d)
    }

    /// `true` if the cycles are in oriented contact (isotropic difference).
    pub fn in_oriented_contact(&self, other: &OrientedSphere<F>) -> bool {
        let s = scale_of(&self.to_point()).max(scale_of(&other.to_point()));
        is_small(&self.contact_residual(other), s * s)
    }

    /// The contact of two touching cycles: the contact point
    /// `x = m₁ + r₁ν`, `ν = (m₁ − m₂)/(r₂ − r₁)` (module docs).
    ///
    /// # Errors
    /// [`CyclographicError::NotInContact`] if the difference is not isotropic,
    /// [`CyclographicError::IdenticalCycles`] for equal cycles.
    pub fn contact(
        &self,
        other: &OrientedSphere<F>,
    ) -> Result<SphereContact<F>, CyclographicError> {
        if !self.in_oriented_contact(other) {
            return Err(CyclographicError::NotInContact(format_scalar(
                &self.contact_residual(other),
            )));
        }
        let dr = other.radius.clone() - self.radius.clone();
        let s = scale_of(&self.to_point()).max(scale_of(&other.to_point()));
        if is_small(&dr, s) {
            return Err(CyclographicError::IdenticalCycles(fmt_vec(
                &self.to_point(),
            )));
        }
        let nu: [F; 3] = core::array::from_fn(|i| {
            (self.center[i].clone() - other.center[i].clone()) / dr.clone()
        });
        let point =
            core::array::from_fn(|i| self.center[i].clone() + self.radius.clone() * nu[i].clone());
        Ok(SphereContact {
            spheres: [self.clone(), other.clone()],
            point,
            normal: nu,
        })
    }

    /// `true` if the cycle touches the oriented plane `e₀ + n·x = 0`: `e₀ + n·m + r = 0`.
    pub fn touches_plane(&self, plane: &OrientedPlane<F>) -> bool {
        let v = plane.offset.clone()
            + crate::lines::dot(&plane.normal, &self.center)
            + self.radius.clone();
        is_small(&v, scale_of(&self.to_point()).max(1.0))
    }
}

/// The contact of two cycles in oriented contact.
#[derive(Debug, Clone, PartialEq)]
pub struct SphereContact<F> {
    /// The two cycles.
    pub spheres: [OrientedSphere<F>; 2],
    /// The contact point.
    pub point: [F; 3],
    /// The common oriented unit normal `ν` at the contact point.
    pub normal: [F; 3],
}

impl<F: Scalar> Certified for SphereContact<F> {
    /// Isotropy of the difference, the contact point on both spheres, `|ν|² = 1`, and
    /// `x = mᵢ + rᵢν` for both cycles.
    fn certify(&self) -> Vec<Certificate> {
        let [a, b] = &self.spheres;
        let s = scale_of(&a.to_point())
            .max(scale_of(&b.to_point()))
            .max(1.0);
        let mut out = Vec::new();
        let r = a.contact_residual(b);
        out.push(Certificate::decide(
            "⟨k₁ − k₂, k₁ − k₂⟩_pe = 0 (oriented contact, Gruber (1.13), sign corrected)",
            is_small(&r, s * s),
            F::EXACT,
            || format_scalar(&r),
        ));
        for (name, c) in [("k₁", a), ("k₂", b)] {
            let p = c.power(&self.point);
            out.push(Certificate::decide(
                format!("the contact point lies on {name}: |x − m|² − r² = 0"),
                is_small(&p, s * s),
                F::EXACT,
                || format_scalar(&p),
            ));
            let dev: Vec<F> = (0..3)
                .map(|i| {
                    self.point[i].clone()
                        - c.center[i].clone()
                        - c.radius.clone() * self.normal[i].clone()
                })
                .collect();
            out.push(Certificate::decide(
                format!("x = m + r·ν for {name} (same oriented normal)"),
                dev.iter().all(|x| is_small(x, s)),
                F::EXACT,
                || fmt_vec(&dev),
            ));
        }
        let nn = crate::lines::dot(&self.normal, &self.normal) - F::one();
        out.push(Certificate::decide(
            "|ν|² = 1",
            is_small(&nn, 1.0),
            F::EXACT,
            || format_scalar(&nn),
        ));
        out
    }
}

/// An oriented circle in the plane, a point of `R^{2,1}`.
#[derive(Debug, Clone, PartialEq)]
pub struct OrientedCircle<F> {
    /// Centre.
    pub center: [F; 2],
    /// Signed radius.
    pub radius: F,
}

impl<F: Scalar> OrientedCircle<F> {
    /// The cycle `(m; r)` of the plane.
    pub fn new(center: [F; 2], radius: F) -> Self {
        OrientedCircle { center, radius }
    }

    /// Its point `(m₁, m₂, r) ∈ R^{2,1}`.
    pub fn to_point(&self) -> [F; 3] {
        [
            self.center[0].clone(),
            self.center[1].clone(),
            self.radius.clone(),
        ]
    }

    /// The circle of a point of `R^{2,1}`.
    pub fn from_point(p: &[F; 3]) -> Self {
        OrientedCircle {
            center: [p[0].clone(), p[1].clone()],
            radius: p[2].clone(),
        }
    }

    /// `⟨k₁ − k₂, k₁ − k₂⟩` in `R^{2,1}`: zero iff the circles are in oriented contact.
    pub fn contact_residual(&self, other: &OrientedCircle<F>) -> F {
        let a = self.to_point();
        let b = other.to_point();
        let d: [F; 3] = core::array::from_fn(|i| a[i].clone() - b[i].clone());
        lorentz3(&d, &d)
    }

    /// `true` if the circles are in oriented contact.
    pub fn in_oriented_contact(&self, other: &OrientedCircle<F>) -> bool {
        let s = scale_of(&self.to_point()).max(scale_of(&other.to_point()));
        is_small(&self.contact_residual(other), s * s)
    }
}

/// An oriented plane `e₀ + n·x = 0` with a (rational) unit normal `n` (docs/math/laguerre-pn.md#conventions).
#[derive(Debug, Clone, PartialEq)]
pub struct OrientedPlane<F> {
    /// The unit normal `n`.
    pub normal: [F; 3],
    /// The offset `e₀`.
    pub offset: F,
}

impl<F: Scalar> OrientedPlane<F> {
    /// The plane `e₀ + n·x = 0`.
    ///
    /// # Errors
    /// [`CyclographicError::NotUnitNormal`] unless `|n|² = 1` exactly (within tolerance for
    /// `f64`).
    pub fn new(normal: [F; 3], offset: F) -> Result<Self, CyclographicError> {
        let nn = crate::lines::dot(&normal, &normal);
        if !is_small(&(nn.clone() - F::one()), 1.0) {
            return Err(CyclographicError::NotUnitNormal(
                fmt_vec(&normal),
                format_scalar(&nn),
            ));
        }
        Ok(OrientedPlane { normal, offset })
    }

    /// The cycle of radius `r` touching the plane at the point `x` of the plane:
    /// `m = x − r n`.
    pub fn touching_cycle(&self, x: &[F; 3], r: &F) -> OrientedSphere<F> {
        OrientedSphere::new(
            core::array::from_fn(|i| x[i].clone() - r.clone() * self.normal[i].clone()),
            r.clone(),
        )
    }
}

/// The isotropic direction `w(s, t) = (2s, 2t, 1 − s² − t², 1 + s² + t²)` (a rational
/// parametrization of the absolute quadric `Ω`, 003-3).
pub fn omega_point<F: Scalar>(s: &F, t: &F) -> [F; 4] {
    let ss = s.clone() * s.clone() + t.clone() * t.clone();
    [
        F::from_i64(2) * s.clone(),
        F::from_i64(2) * t.clone(),
        F::one() - ss.clone(),
        F::one() + ss,
    ]
}

/// The cyclographic image point `F − (F₄/w₄)(w₁, w₂, w₃)` of `F ∈ R^{3,1}` along the
/// isotropic direction `w` (where the isotropic line meets `x₄ = 0`; 003-3). The result lies
/// on the sphere `γ(F)`.
///
/// # Errors
/// [`CyclographicError::NotIsotropic`] unless `⟨w, w⟩_pe = 0`,
/// [`CyclographicError::HorizontalDirection`] for `w₄ = 0`.
pub fn isotropic_image<F: Scalar>(p: &[F; 4], w: &[F; 4]) -> Result<[F; 3], CyclographicError> {
    if causal_type(w) != CausalType::Lightlike {
        return Err(CyclographicError::NotIsotropic(
            fmt_vec(w),
            format_scalar(&lorentz(w, w)),
        ));
    }
    if w[3].is_zero() {
        return Err(CyclographicError::HorizontalDirection(fmt_vec(w)));
    }
    let k = p[3].clone() / w[3].clone();
    Ok(core::array::from_fn(|i| {
        p[i].clone() - k.clone() * w[i].clone()
    }))
}

/// The polar hyperplane `D p`, `D = diag(1, 1, 1, −1)`, of a point `p` of the ideal
/// 3-space `ω` with respect to `Ω` (Gruber 2008 (1.18)).
pub fn polar_plane<F: Scalar>(p: &[F; 4]) -> [F; 4] {
    [p[0].clone(), p[1].clone(), p[2].clone(), -p[3].clone()]
}

/// The cyclographic image of a line `P + λd` of `R^{3,1}` (Gruber 2008 §1.2.2).
#[derive(Debug, Clone, PartialEq)]
pub enum LineImage<F> {
    /// `d₄ = 0`: spheres of constant radius: a cylinder of revolution.
    Cylinder {
        /// A point of the axis.
        axis_point: [F; 3],
        /// The axis direction.
        axis_direction: [F; 3],
        /// The radius (signed).
        radius: F,
    },
    /// `d` spacelike: a cone of revolution with the vertex where the radius vanishes and
    /// `sin²α = d₄²/|d₁₂₃|²` for the half aperture `α`.
    Cone {
        /// The vertex (the point cycle of the line).
        vertex: [F; 3],
        /// The axis direction.
        axis_direction: [F; 3],
        /// `sin²` of the half aperture angle.
        sin2_half_angle: F,
    },
    /// `d` lightlike: all cycles touch one oriented plane at one point.
    Plane {
        /// The common contact point (the line meets `x₄ = 0` there).
        point: [F; 3],
        /// The plane `e₀ + n·x = 0` (unit normal `n = −d₁₂₃/d₄`).
        plane: OrientedPlane<F>,
    },
    /// `d` timelike: no real envelope.
    NotReal,
}

/// The cyclographic image of the line through `p` with direction `d` (Gruber 2008 §1.2.2).
///
/// # Errors
/// [`CyclographicError::ZeroVector`] for `d = 0`.
pub fn line_image<F: Scalar>(p: &[F; 4], d: &[F; 4]) -> Result<LineImage<F>, CyclographicError> {
    if d.iter().all(|x| x.is_zero()) {
        return Err(CyclographicError::ZeroVector(
            "the direction of a line of R^{3,1}".into(),
        ));
    }
    let d3 = [d[0].clone(), d[1].clone(), d[2].clone()];
    if d[3].is_zero() {
        return Ok(LineImage::Cylinder {
            axis_point: [p[0].clone(), p[1].clone(), p[2].clone()],
            axis_direction: d3,
            radius: p[3].clone(),
        });
    }
    let k = p[3].clone() / d[3].clone();
    let vertex: [F; 3] = core::array::from_fn(|i| p[i].clone() - k.clone() * d[i].clone());
    match causal_type(d) {
        CausalType::Timelike => Ok(LineImage::NotReal),
        CausalType::Spacelike => {
            let dd = crate::lines::dot(&d3, &d3);
            Ok(LineImage::Cone {
                vertex,
                axis_direction: d3,
                sin2_half_angle: d[3].clone() * d[3].clone() / dd,
            })
        }
        CausalType::Lightlike => {
            let n: [F; 3] = core::array::from_fn(|i| -d[i].clone() / d[3].clone());
            let e0 = -crate::lines::dot(&n, &vertex);
            Ok(LineImage::Plane {
                point: vertex,
                plane: OrientedPlane {
                    normal: n,
                    offset: e0,
                },
            })
        }
    }
}

/// The type of a 2-plane `ε: a + u g + v h` of `R^{3,1}` and of its cyclographic image
/// (Gruber 2008 §1.2.2), decided by the Gram matrix `G` of `g, h` in the Lorentz product:
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlaneImageKind {
    /// `g₄ = h₄ = 0`: the cycles have the constant radius `a₄`; the image is the pair of
    /// planes parallel to `π(ε)` at distance `|a₄|`.
    Horizontal,
    /// `G` positive definite (every direction spacelike): two planes through the line
    /// `ε ∩ {x₄ = 0}`.
    Spacelike,
    /// `det G = 0` (one isotropic direction): one plane, touched by all cycles at the points
    /// of `ε ∩ {x₄ = 0}`.
    Lightlike,
    /// `det G < 0` (two isotropic directions): two conjugate complex planes, no real image.
    Timelike,
}

/// The cyclographic image of the 2-plane `ε = a + u g + v h` of `R^{3,1}`: the oriented
/// planes `e₀ + n·x = 0`, `|n| = 1`, touching every cycle of `ε` (Gruber 2008 §1.2.2).
///
/// A plane touches the cycle `(m, r)` iff `e₀ + n·m + r = 0` (module docs), so for all of
/// `ε`: `e₀ + n·a' + a₄ = 0`, `n·g' = −g₄`, `n·h' = −h₄` (`x'` = the first three
/// coordinates). With `k = g' × h'` and `n₀ ∈ span(g', h')` solving the two linear
/// conditions, `n = n₀ + λk` and `|n|² = 1` gives `λ² = (1 − |n₀|²)/|k|²`: two real planes
/// for `|n₀|² < 1` (spacelike), one for `|n₀|² = 1` (lightlike), none for `|n₀|² > 1`
/// (timelike) — `1 − |n₀|²` has the sign of `det G`. The square root lives in
/// [`crate::lines::SqrtScalar::Ext`].
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneImage<F: crate::lines::SqrtScalar> {
    /// The point `a`.
    pub point: [F; 4],
    /// The directions `g, h`.
    pub directions: [[F; 4]; 2],
    /// The type.
    pub kind: PlaneImageKind,
    /// The enveloping oriented planes (two, one or none).
    pub planes: Vec<OrientedPlane<F::Ext>>,
}

fn cross3<F: Scalar>(a: &[F; 3], b: &[F; 3]) -> [F; 3] {
    [
        a[1].clone() * b[2].clone() - a[2].clone() * b[1].clone(),
        a[2].clone() * b[0].clone() - a[0].clone() * b[2].clone(),
        a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone(),
    ]
}

/// The cyclographic image of the 2-plane `a + u g + v h` ([`PlaneImage`]).
///
/// # Errors
/// [`CyclographicError::ZeroVector`] if `g' × h' = 0` (the plane is no 2-plane, or contains
/// the radius direction `(0, 0, 0, 1)`: then the cycles fill space and have no envelope).
pub fn plane_image<F: crate::lines::SqrtScalar>(
    a: &[F; 4],
    g: &[F; 4],
    h: &[F; 4],
) -> Result<PlaneImage<F>, CyclographicError> {
    let p3 = |x: &[F; 4]| -> [F; 3] { [x[0].clone(), x[1].clone(), x[2].clone()] };
    let (gp, hp) = (p3(g), p3(h));
    let k = cross3(&gp, &hp);
    if k.iter().all(|x| is_small(x, scale_of(g) * scale_of(h))) {
        return Err(CyclographicError::ZeroVector(format!(
            "g' × h' for the plane spanned by {} and {} (vertical or degenerate plane)",
            fmt_vec(g),
            fmt_vec(h)
        )));
    }
    let dot = |x: &[F; 3], y: &[F; 3]| crate::lines::dot(x, y);
    // n₀ = α g' + β h' with [gg gh; gh hh](α, β) = (−g₄, −h₄)
    let (gg, gh, hh) = (dot(&gp, &gp), dot(&gp, &hp), dot(&hp, &hp));
    let det = gg.clone() * hh.clone() - gh.clone() * gh.clone();
    let (rg, rh) = (-g[3].clone(), -h[3].clone());
    let al = (rg.clone() * hh.clone() - gh.clone() * rh.clone()) / det.clone();
    let be = (gg.clone() * rh - gh.clone() * rg) / det;
    let n0: [F; 3] =
        core::array::from_fn(|i| al.clone() * gp[i].clone() + be.clone() * hp[i].clone());
    let kk = dot(&k, &k);
    let rest = F::one() - dot(&n0, &n0);
    let horizontal = g[3].is_zero() && h[3].is_zero();
    let kind = if horizontal {
        PlaneImageKind::Horizontal
    } else if is_small(&rest, 1.0) {
        PlaneImageKind::Lightlike
    } else if rest > F::zero() {
        PlaneImageKind::Spacelike
    } else {
        PlaneImageKind::Timelike
    };
    let lambdas: Vec<F::Ext> = match kind {
        PlaneImageKind::Timelike => Vec::new(),
        PlaneImageKind::Lightlike => vec![<F::Ext as num_traits::Zero>::zero()],
        _ => {
            let l2 = rest / kk;
            let l = l2
                .sqrt_ext()
                .ok_or_else(|| CyclographicError::NotIsotropic(fmt_vec(g), format_scalar(&l2)))?;
            vec![l.clone(), -l]
        }
    };
    let a3 = p3(a);
    let planes = lambdas
        .into_iter()
        .map(|l| {
            let n: [F::Ext; 3] = core::array::from_fn(|i| n0[i].embed() + l.clone() * k[i].embed());
            let am: [F::Ext; 3] = core::array::from_fn(|i| a3[i].embed());
            let e0 = -(crate::lines::dot(&n, &am) + a[3].embed());
            OrientedPlane {
                normal: n,
                offset: e0,
            }
        })
        .collect();
    Ok(PlaneImage {
        point: a.clone(),
        directions: [g.clone(), h.clone()],
        kind,
        planes,
    })
}

impl<F: crate::lines::SqrtScalar> Certified for PlaneImage<F> {
    /// Every image plane has a unit normal and touches the cycles of `a`, `a + g`, `a + h`
    /// (hence, the contact condition being affine in the cycle, every cycle of `ε`): exact
    /// over the extension field; the number of planes matches the type.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = Vec::new();
        let want = match self.kind {
            PlaneImageKind::Horizontal | PlaneImageKind::Spacelike => 2,
            PlaneImageKind::Lightlike => 1,
            PlaneImageKind::Timelike => 0,
        };
        out.push(Certificate::decide(
            format!("{:?} plane: {want} image planes (Gruber §1.2.2)", self.kind),
            self.planes.len() == want,
            F::EXACT,
            || format!("{} planes", self.planes.len()),
        ));
        let [g, h] = &self.directions;
        let cycles: [[F; 4]; 3] = [
            self.point.clone(),
            core::array::from_fn(|i| self.point[i].clone() + g[i].clone()),
            core::array::from_fn(|i| self.point[i].clone() + h[i].clone()),
        ];
        for (j, pl) in self.planes.iter().enumerate() {
            let nn = crate::lines::dot(&pl.normal, &pl.normal);
            let one = <F::Ext as num_traits::One>::one();
            out.push(Certificate::decide(
                format!("image plane {j} has a unit normal"),
                is_small(&(nn.clone() - one), 1.0),
                F::EXACT,
                || format_scalar(&nn),
            ));
            for c in &cycles {
                let m: [F::Ext; 3] = core::array::from_fn(|i| c[i].embed());
                let r = pl.offset.clone() + crate::lines::dot(&pl.normal, &m) + c[3].embed();
                out.push(Certificate::decide(
                    format!(
                        "image plane {j} touches the cycle {}: e₀ + n·m + r = 0",
                        fmt_vec(c)
                    ),
                    is_small(&r, 1.0 + scale_of(c)),
                    F::EXACT,
                    || format_scalar(&r),
                ));
            }
        }
        out
    }
}

// ---------------------------------------------------------------------------------------
// Möbius model (Peternell §2.4)
// ---------------------------------------------------------------------------------------

/// `Q(x) = −x₀² + x₁² + x₂² + x₃² + x₄²` (Peternell (2.12)).
pub fn mobius_form<F: Scalar>(x: &[F; 5]) -> F {
    mobius_bilinear(x, x)
}

/// The polar form `B(x, y) = −x₀y₀ + x₁y₁ + x₂y₂ + x₃y₃ + x₄y₄` of the Möbius quadric.
pub fn mobius_bilinear<F: Scalar>(x: &[F; 5], y: &[F; 5]) -> F {
    (1..5).fold(-(x[0].clone() * y[0].clone()), |acc, i| {
        acc + x[i].clone() * y[i].clone()
    })
}

/// What a point of `P⁴` represents in the standard model (Peternell §2.4, (2.13)).
#[derive(Debug, Clone, PartialEq)]
pub enum MobiusImage<F> {
    /// A sphere (`p ∉ Q`, `p₀ ≠ p₄`): centre and squared radius (negative: imaginary sphere).
    Sphere {
        /// Centre `pᵢ/(p₀ − p₄)`.
        center: [F; 3],
        /// `(p₁² + p₂² + p₃² + p₄² − p₀²)/(p₀ − p₄)²`.
        radius_sq: F,
    },
    /// A point of `R³` (`p ∈ Q`, `p ≠ N`).
    Point([F; 3]),
    /// A plane `a₀ + a₁y₁ + a₂y₂ + a₃y₃ = 0` (`p₀ = p₄`, `p ≠ N`): `a = (−p₀, p₁, p₂, p₃)`.
    Plane([F; 4]),
    /// The north pole `N` (the point at infinity).
    Infinity,
}

/// The sphere, plane or point `μ(p)` of a point of `P⁴` (Peternell (2.13)).
///
/// # Errors
/// [`CyclographicError::ZeroVector`] for `p = 0`.
pub fn mobius_image<F: Scalar>(p: &[F; 5]) -> Result<MobiusImage<F>, CyclographicError> {
    if p.iter().all(|x| x.is_zero()) {
        return Err(CyclographicError::ZeroVector("a point of P⁴".into()));
    }
    let w = p[0].clone() - p[4].clone();
    if w.is_zero() {
        if p[1].is_zero() && p[2].is_zero() && p[3].is_zero() {
            return Ok(MobiusImage::Infinity);
        }
        return Ok(MobiusImage::Plane([
            -p[0].clone(),
            p[1].clone(),
            p[2].clone(),
            p[3].clone(),
        ]));
    }
    let center: [F; 3] = core::array::from_fn(|i| p[i + 1].clone() / w.clone());
    let q = mobius_form(p);
    if q.is_zero() {
        return Ok(MobiusImage::Point(center));
    }
    Ok(MobiusImage::Sphere {
        center,
        radius_sq: q / (w.clone() * w),
    })
}

/// The point of `P⁴` of the sphere `|y − m|² = r²` (normalised to `p₀ − p₄ = 1`):
/// `p = ((|m|² − r² + 1)/2, m, (|m|² − r² − 1)/2)`; `r² = 0` gives the point `m` on `Q`.
pub fn mobius_point<F: Scalar>(center: &[F; 3], radius_sq: &F) -> [F; 5] {
    let mm = crate::lines::dot(center, center) - radius_sq.clone();
    let half = F::one() / F::from_i64(2);
    [
        (mm.clone() + F::one()) * half.clone(),
        center[0].clone(),
        center[1].clone(),
        center[2].clone(),
        (mm - F::one()) * half,
    ]
}

/// The point of `P⁴` of the plane `n·y = h`: `(h, n₁, n₂, n₃, h)`.
pub fn mobius_plane_point<F: Scalar>(normal: &[F; 3], h: &F) -> [F; 5] {
    [
        h.clone(),
        normal[0].clone(),
        normal[1].clone(),
        normal[2].clone(),
        h.clone(),
    ]
}

/// The type of the pencil of spheres of a line of `P⁴` (Peternell §2.4, cases 1–3).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PencilType {
    /// The line meets `Q` in two conjugate complex points: the spheres through a real
    /// circle (case 1). A canal family with such tangent lines has a real characteristic
    /// circle.
    Elliptic,
    /// Two real points of `Q`: two limit points, no real common circle (case 2).
    Hyperbolic,
    /// Tangent to `Q`: the spheres touching one another at one point (case 3).
    Parabolic,
}

/// The pencil type of the line `p ∨ q`: the sign of `B(p, q)² − Q(p)Q(q)` (negative:
/// elliptic, positive: hyperbolic, zero: parabolic).
pub fn pencil_type<F: Scalar>(p: &[F; 5], q: &[F; 5]) -> PencilType {
    let b = mobius_bilinear(p, q);
    let d = b.clone() * b - mobius_form(p) * mobius_form(q);
    let s = scale_of(p).max(scale_of(q)).powi(4);
    if is_small(&d, s) {
        PencilType::Parabolic
    } else if d > F::zero() {
        PencilType::Hyperbolic
    } else {
        PencilType::Elliptic
    }
}

/// The Möbius reflection with centre `z ∉ Q` (an automorphic collineation of `Q`):
/// `x ↦ x − 2 B(x, z)/Q(z) · z`. For `z` the point of a sphere `S` it is the inversion in `S`
/// (a reflection for a plane), acting on points, spheres and planes alike (Peternell §2.4).
///
/// # Errors
/// [`CyclographicError::ZeroVector`] if `z ∈ Q` (no reflection).
pub fn mobius_reflection<F: Scalar>(z: &[F; 5], x: &[F; 5]) -> Result<[F; 5], CyclographicError> {
    let qz = mobius_form(z);
    if qz.is_zero() {
        return Err(CyclographicError::ZeroVector(format!(
            "the centre {} of a Möbius reflection lies on Q",
            fmt_vec(z)
        )));
    }
    let k = F::from_i64(2) * mobius_bilinear(x, z) / qz;
    Ok(core::array::from_fn(|i| {
        x[i].clone() - k.clone() * z[i].clone()
    }))
}

/// The cyclographic image of a 2-dimensional pe sphere `q = π ∩ Γ(a)` of `R^{3,1}`: the
/// points of the hyperplane `π: ⟨x, ν⟩_pe = c` on the γ-cone of the point `a`
/// (Peternell 1997, §3.9.1).
#[derive(Debug, Clone, PartialEq)]
pub enum PeSphereImage<F> {
    /// `π` is not a γ-hyperplane (`⟨ν, ν⟩_pe ≠ 0`): `q` also lies on the γ-cone of the
    /// pe mirror image `σ(a) = a − 2((⟨a, ν⟩ − c)/⟨ν, ν⟩) ν` of `a` in `π`, and the image is
    /// the two cycles `η(a)`, `η(σ(a))` (every cycle of `q` touches both).
    TwoCycles(OrientedSphere<F>, OrientedSphere<F>),
    /// `π` is a γ-hyperplane: the image is the cycle `η(a)` and the oriented plane
    /// `π ∩ R³`, `e₀ + n·x = 0` with `n = −ν₁₂₃/ν₄`, `e₀ = c/ν₄` (the cycles of `π` touch it).
    CycleAndPlane(OrientedSphere<F>, OrientedPlane<F>),
}

/// The cyclographic image of the pe sphere `π ∩ Γ(a)`, `π: ⟨x, ν⟩_pe = c` (Peternell 1997,
/// §3.9.1).
///
/// # Errors
/// [`CyclographicError::ZeroVector`] for `ν = 0`; [`CyclographicError::IdenticalCycles`]
/// when `a` lies in `π` (then `q` is a cone, not a sphere).
pub fn pe_sphere_image<F: Scalar>(
    a: &[F; 4],
    nu: &[F; 4],
    c: &F,
) -> Result<PeSphereImage<F>, CyclographicError> {
    if nu.iter().all(|x| x.is_zero()) {
        return Err(CyclographicError::ZeroVector(
            "the normal ν of the hyperplane ⟨x, ν⟩ = c".into(),
        ));
    }
    let dist = lorentz(a, nu) - c.clone();
    if dist.is_zero() {
        return Err(CyclographicError::IdenticalCycles(format!(
            "{} (the vertex a lies in the hyperplane: π ∩ Γ(a) is a cone)",
            crate::error::format_point(a)
        )));
    }
    let nn = lorentz(nu, nu);
    if nn.is_zero() {
        // ν₄ ≠ 0 since ν ≠ 0 is isotropic
        let n: [F; 3] = core::array::from_fn(|i| -nu[i].clone() / nu[3].clone());
        let plane = OrientedPlane::new(n, c.clone() / nu[3].clone())?;
        return Ok(PeSphereImage::CycleAndPlane(
            OrientedSphere::from_point(a),
            plane,
        ));
    }
    let t = F::from_i64(2) * dist / nn;
    let b: [F; 4] = core::array::from_fn(|i| a[i].clone() - t.clone() * nu[i].clone());
    Ok(PeSphereImage::TwoCycles(
        OrientedSphere::from_point(a),
        OrientedSphere::from_point(&b),
    ))
}

/// Certificates of [`pe_sphere_image`]: for two cycles `a, b`, `b − a ∥ ν` (all 2×2 minors
/// vanish), the midpoint lies in `π`, so that for every `y ∈ π`
/// `⟨y − b, y − b⟩ − ⟨y − a, y − a⟩ = 0` (the difference is affine in `y` and vanishes on
/// `π`); for a cycle and a plane, `ν₄e₀ = c`, `ν₄n = −ν₁₂₃` and `|n|² = 1`, so every cycle
/// `y ∈ π` touches the plane (`e₀ + n·m_y + r_y = 0`).
pub fn certify_pe_sphere_image<F: Scalar>(
    a: &[F; 4],
    nu: &[F; 4],
    c: &F,
    image: &PeSphereImage<F>,
) -> Vec<Certificate> {
    let ex = F::EXACT;
    let zero = |x: &F| {
        if ex {
            x.is_zero()
        } else {
            x.to_f64().abs() <= 1e-9
        }
    };
    match image {
        PeSphereImage::TwoCycles(k1, k2) => {
            let (p, q) = (k1.to_point(), k2.to_point());
            let d: [F; 4] = core::array::from_fn(|i| q[i].clone() - p[i].clone());
            let parallel = (0..4).all(|i| {
                (0..4).all(|j| zero(&(d[i].clone() * nu[j].clone() - d[j].clone() * nu[i].clone())))
            });
            let two = F::from_i64(2);
            let mid: [F; 4] = core::array::from_fn(|i| (p[i].clone() + q[i].clone()) / two.clone());
            let on = lorentz(&mid, nu) - c.clone();
            let same_a = (0..4).all(|i| zero(&(p[i].clone() - a[i].clone())));
            vec![
                Certificate::decide("η(a) is the cycle a", same_a, ex, || "a differs".into()),
                Certificate::decide(
                    "σ(a) − a ∥ ν (the second cycle is a pe mirror image of a in π)",
                    parallel,
                    ex,
                    || "a 2×2 minor of (σ(a) − a, ν) is not zero".into(),
                ),
                Certificate::decide(
                    "⟨(a + σ(a))/2, ν⟩ = c (π is the mirror: every y ∈ π has ⟨y − a, y − a⟩ = ⟨y − σ(a), y − σ(a)⟩)",
                    zero(&on),
                    ex,
                    || crate::error::format_scalar(&on),
                ),
            ]
        }
        PeSphereImage::CycleAndPlane(k, plane) => {
            let e0 = nu[3].clone() * plane.offset.clone() - c.clone();
            let nn =
                (0..3).all(|i| zero(&(nu[3].clone() * plane.normal[i].clone() + nu[i].clone())));
            let unit = crate::lines::dot(&plane.normal, &plane.normal) - F::one();
            let same_a = (0..4).all(|i| zero(&(k.to_point()[i].clone() - a[i].clone())));
            vec![
                Certificate::decide("η(a) is the cycle a", same_a, ex, || "a differs".into()),
                Certificate::decide(
                    "ν₄e₀ = c and ν₄n = −ν₁₂₃: every cycle (m; r) of π satisfies e₀ + n·m + r = 0 (touches the plane)",
                    zero(&e0) && nn,
                    ex,
                    || "the plane does not match π".into(),
                ),
                Certificate::decide("|n|² = 1", zero(&unit), ex, || {
                    crate::error::format_scalar(&unit)
                }),
            ]
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }
    fn r(n: i64, d: i64) -> Rational {
        Rational::from_ratio(n, d)
    }

    #[test]
    fn contact_of_cycles() {
        // (0,0,0; 1) and (3,4,0; 6): |Δm| = 5 = |Δr|
        let a = OrientedSphere::new([q(0), q(0), q(0)], q(1));
        let b = OrientedSphere::new([q(3), q(4), q(0)], q(6));
        assert!(a.in_oriented_contact(&b));
        let c = a.contact(&b).expect("contact");
        assert!(c.all_hold(), "{:?}", c.certify());
        // the printed (1.16) ⟨k₁, k₂⟩ = 0 is wrong: here it is 3·0 + … − 6 = −6
        assert_ne!(lorentz(&a.to_point(), &b.to_point()), q(0));
        let far = OrientedSphere::new([q(10), q(0), q(0)], q(1));
        assert!(matches!(
            a.contact(&far),
            Err(CyclographicError::NotInContact(_))
        ));
    }

    #[test]
    fn isotropic_images_lie_on_the_sphere() {
        let p = [q(1), q(2), q(3), q(2)];
        let sph = OrientedSphere::from_point(&p);
        for (s, t) in [(0, 0), (1, 2), (-3, 1)] {
            let w = omega_point(&q(s), &q(t));
            assert_eq!(lorentz(&w, &w), q(0));
            let x = isotropic_image(&p, &w).expect("image");
            assert!(sph.power(&x).is_zero());
        }
    }

    #[test]
    fn line_images() {
        let p = [q(0), q(0), q(0), q(1)];
        assert!(matches!(
            line_image(&p, &[q(1), q(0), q(0), q(0)]).expect("l"),
            LineImage::Cylinder { .. }
        ));
        assert!(matches!(
            line_image(&p, &[q(2), q(0), q(0), q(1)]).expect("l"),
            LineImage::Cone { .. }
        ));
        assert!(matches!(
            line_image(&p, &[q(0), q(0), q(1), q(2)]).expect("l"),
            LineImage::NotReal
        ));
        match line_image(&p, &[q(3), q(4), q(0), q(5)]).expect("l") {
            LineImage::Plane { point, plane } => {
                // every cycle of the line touches the plane
                for lam in [0, 1, -2] {
                    let c =
                        OrientedSphere::from_point(&[q(3 * lam), q(4 * lam), q(0), q(1 + 5 * lam)]);
                    assert!(c.touches_plane(&plane));
                }
                assert_eq!(point, [r(-3, 5), r(-4, 5), q(0)]);
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn mobius_sphere_round_trip_and_pencils() {
        let m = [q(1), q(2), q(-1)];
        let p = mobius_point(&m, &q(4));
        match mobius_image(&p).expect("img") {
            MobiusImage::Sphere { center, radius_sq } => {
                assert_eq!(center, m);
                assert_eq!(radius_sq, q(4));
            }
            other => panic!("{other:?}"),
        }
        // two concentric spheres: the pencil contains the centre as a point sphere and ∞
        let p2 = mobius_point(&m, &q(9));
        assert_eq!(pencil_type(&p, &p2), PencilType::Hyperbolic);
        // two intersecting spheres: a real circle
        let p3 = mobius_point(&[q(2), q(2), q(-1)], &q(4));
        assert_eq!(pencil_type(&p, &p3), PencilType::Elliptic);
        // touching spheres
        let p4 = mobius_point(&[q(5), q(2), q(-1)], &q(4));
        assert_eq!(pencil_type(&p, &p4), PencilType::Parabolic);
        // reflection in the unit sphere: inversion y ↦ y/|y|²
        let z = mobius_point(&[q(0), q(0), q(0)], &q(1));
        let y = [q(2), q(0), q(0)];
        let x = mobius_point(&y, &q(0));
        let img = mobius_reflection(&z, &x).expect("refl");
        assert_eq!(
            mobius_image(&img).expect("img"),
            MobiusImage::Point([r(1, 2), q(0), q(0)])
        );
    }

    #[test]
    fn pe_sphere_images() {
        let q = |p: i64, d: i64| Rational::from_ratio(p, d);
        // π: x₄ = 1 (ν = (0, 0, 0, 1), ⟨x, ν⟩ = −x₄ = −1), a = (0, 0, 0, 3): the cycles of
        // radius 1 on the γ-cone of a are spheres of radius 1 centred on |m| = 2, touching
        // η(a) (radius 3) and η(σ(a)) = (0, 0, 0; −1)
        let a = [q(0, 1), q(0, 1), q(0, 1), q(3, 1)];
        let nu = [q(0, 1), q(0, 1), q(0, 1), q(1, 1)];
        let img = pe_sphere_image(&a, &nu, &q(-1, 1)).expect("image");
        match &img {
            PeSphereImage::TwoCycles(k1, k2) => {
                assert_eq!(k1.radius, q(3, 1));
                assert_eq!(k2.radius, q(-1, 1));
                // a cycle of q: m = (2, 0, 0), r = 1 touches both
                let y = OrientedSphere::new([q(2, 1), q(0, 1), q(0, 1)], q(1, 1));
                assert!(y.in_oriented_contact(k1) && y.in_oriented_contact(k2));
            }
            other => panic!("{other:?}"),
        }
        assert!(certify_pe_sphere_image(&a, &nu, &q(-1, 1), &img)
            .iter()
            .all(|c| c.holds));
        // a γ-hyperplane: ν = (1, 0, 0, 1), c = 2: the cycles with m₁ − r = 2 touch the plane
        // x = 2 … oriented: e₀ = 2, n = (−1, 0, 0)
        let nu = [q(1, 1), q(0, 1), q(0, 1), q(1, 1)];
        let img = pe_sphere_image(&a, &nu, &q(2, 1)).expect("image");
        match &img {
            PeSphereImage::CycleAndPlane(_, plane) => {
                assert_eq!(plane.offset, q(2, 1));
                assert_eq!(plane.normal, [q(-1, 1), q(0, 1), q(0, 1)]);
                let y = OrientedSphere::new([q(5, 1), q(1, 1), q(0, 1)], q(3, 1));
                assert!(y.touches_plane(plane));
            }
            other => panic!("{other:?}"),
        }
        assert!(certify_pe_sphere_image(&a, &nu, &q(2, 1), &img)
            .iter()
            .all(|c| c.holds));
        // errors: ν = 0; a in π
        assert!(matches!(
            pe_sphere_image(&a, &[q(0, 1), q(0, 1), q(0, 1), q(0, 1)], &q(0, 1)),
            Err(CyclographicError::ZeroVector(_))
        ));
        assert!(matches!(
            pe_sphere_image(&a, &[q(0, 1), q(0, 1), q(0, 1), q(1, 1)], &q(-3, 1)),
            Err(CyclographicError::IdenticalCycles(_))
        ));
    }

    #[test]
    fn cyclographic_images_of_planes() {
        use rcagd_algebra::{QuadExt, Rational};
        let q = |a: [i64; 4]| a.map(Rational::from);
        let r = |n, d| Rational::from_ratio(n, d);
        // Gruber §1.2.2, the four cases
        let hz = plane_image(&q([0, 0, 0, 2]), &q([1, 0, 0, 0]), &q([0, 1, 0, 0])).expect("h");
        assert_eq!(hz.kind, PlaneImageKind::Horizontal);
        assert!(hz.all_hold(), "{:?}", hz.certify());
        // the planes z = ±2 (oriented: n = (0, 0, ∓1), e₀ = −2)
        for pl in &hz.planes {
            assert_eq!(pl.offset, QuadExt::rational(Rational::from(-2)));
        }
        let a = q([1, 2, 3, 0]);
        let sp =
            plane_image(&a, &[r(1, 1), r(0, 1), r(0, 1), r(1, 2)], &q([0, 1, 0, 0])).expect("s");
        assert_eq!(sp.kind, PlaneImageKind::Spacelike);
        assert!(sp.all_hold(), "{:?}", sp.certify());
        let ll = plane_image(&a, &q([1, 0, 0, 1]), &q([0, 1, 0, 0])).expect("l");
        assert_eq!(ll.kind, PlaneImageKind::Lightlike);
        assert!(ll.all_hold(), "{:?}", ll.certify());
        let tl = plane_image(&a, &q([1, 0, 0, 2]), &q([0, 1, 0, 0])).expect("t");
        assert_eq!(tl.kind, PlaneImageKind::Timelike);
        assert!(tl.planes.is_empty() && tl.all_hold());
        assert!(matches!(
            plane_image(&a, &q([1, 0, 0, 0]), &q([0, 0, 0, 1])),
            Err(CyclographicError::ZeroVector(_))
        ));
        // f64 agrees
        let f = plane_image(
            &[1.0, 2.0, 3.0, 0.0],
            &[1.0, 0.0, 0.0, 0.5],
            &[0.0, 1.0, 0.0, 0.0],
        )
        .expect("f64");
        assert!(f.all_hold());
        assert_eq!(f.kind, PlaneImageKind::Spacelike);
    }
}
