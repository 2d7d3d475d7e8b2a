//! Cyclide blends between two cones or cylinders of revolution (Peternell, "Rational
//! Parametrizations for Envelopes of Quadric Families", §3.8 and §3.8.1: a cone of
//! revolution is the cyclographic image of a hyperbolic line of `R^{3,1}`, and the image of
//! a pe circle tangent to that line at `P` touches the cone along the characteristic
//! circle of the sphere `P`; docs/math/cyclides.md#blends).
//!
//! Cone `i` is given by one of its inscribed spheres `Pᵢ = (mᵢ; rᵢ)` (it touches the cone
//! along the wanted contact circle) and the direction `dᵢ = (aᵢ; δᵢ)` of its line in
//! `R^{3,1}` (`aᵢ` along the axis, `δᵢ` the change of the radius; `δᵢ = 0`: a cylinder),
//! `⟨dᵢ, dᵢ⟩ > 0`. The blend is the band between the two contact circles of the cyclide of
//! the pe circle tangent to line 1 at `P₁` and to line 2 at `P₂`; it exists iff the lines
//! are coplanar (the cone axes meet or are parallel), their plane is Euclidean and the pe
//! tangent lengths from the intersection point agree.

use super::conic::PeConic;
use super::pe::{negligible, pe, scale, size, sqrt_in_field, sub};
use super::surface::DupinCyclide;
use super::CyclideError;
use crate::canal::bipoly::BiPoly;
use rcagd_algebra::{format_scalar, Certificate, Scalar};
use rcagd_geom::certify::polynomial_is_zero_scaled;
use rcagd_geom::BezierPatch;

/// A cyclide blend: the cyclide and the parameter arc `[0, t₂]` of its first family
/// between the contact spheres `P₁` (`t = 0`) and `P₂` (`t = t₂`, `None` for `t = ∞`).
#[derive(Debug, Clone, PartialEq)]
pub struct CyclideBlend<F> {
    /// The cyclide.
    pub cyclide: DupinCyclide<F>,
    /// The parameter of `P₂` (`None`: `t = ∞`, a half circle).
    pub t2: Option<F>,
    /// The two cones: `(Pᵢ, dᵢ)`.
    pub cones: [([F; 4], [F; 4]); 2],
}

fn minors_vanish<F: Scalar>(vs: &[[F; 4]; 3], sc: f64) -> bool {
    // all 3×3 minors of the 3×4 matrix
    let cols = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]];
    cols.iter().all(|c| {
        let m = |i: usize, j: usize| vs[i][c[j]].clone();
        let d = m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1))
            - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0))
            + m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
        negligible(&d, sc)
    })
}

/// The cyclide blend between the cones (cylinders) of revolution `(P₁, d₁)` and `(P₂, d₂)`.
///
/// # Errors
/// [`CyclideError::IsotropicTangents`] if `⟨dᵢ, dᵢ⟩ ≤ 0` (not a real cone of revolution);
/// [`CyclideError::SkewAxes`] if the lines are not coplanar (no cyclide blend exists);
/// [`CyclideError::NoBlend`] with a message naming the failure: the same line, a non-Euclidean plane,
/// unequal tangent lengths (the contact circles do not fit one pe circle), a contact
/// sphere at the common vertex; [`CyclideError::NotRational`] if the circle needs a square
/// root.
pub fn blend_cones<F: Scalar>(
    p1: [F; 4],
    d1: [F; 4],
    p2: [F; 4],
    d2: [F; 4],
) -> Result<CyclideBlend<F>, CyclideError> {
    let sc = size(&p1)
        .max(size(&p2))
        .max(size(&d1))
        .max(size(&d2))
        .max(1.0);
    for (i, d) in [(1, &d1), (2, &d2)] {
        if pe(d, d) <= F::zero() || negligible(&pe(d, d), sc * sc) {
            return Err(CyclideError::IsotropicTangents(format!(
                "⟨d{i}, d{i}⟩ = {} ≤ 0: |axis|² must exceed (radius change)², else the spheres have no real envelope",
                format_scalar(&pe(d, d))
            )));
        }
    }
    let e = sub(&p2, &p1);
    if !minors_vanish(&[e.clone(), d1.clone(), d2.clone()], sc.powi(3)) {
        return Err(CyclideError::SkewAxes(
            "the lines of the two cones in R^{3,1} are not coplanar (the axes are skew, or the cones' radius functions do not fit): no cyclide blend exists".into(),
        ));
    }
    let (g11, g12, g22) = (pe(&d1, &d1), pe(&d1, &d2), pe(&d2, &d2));
    let parallel = negligible(
        &(g11.clone() * g22.clone() - g12.clone() * g12.clone()),
        sc.powi(4),
    ) && minors_vanish(&[d1.clone(), d2.clone(), d1.clone()], 0.0)
        && (0..4).all(|i| {
            (0..4).all(|j| {
                negligible(
                    &(d1[i].clone() * d2[j].clone() - d1[j].clone() * d2[i].clone()),
                    sc * sc,
                )
            })
        });
    let c0 = if parallel {
        if !negligible(&pe(&e, &d1), sc * sc) {
            return Err(CyclideError::NoBlend(format!(
                "parallel lines: P₂ − P₁ must be pe-orthogonal to the common direction (⟨P₂ − P₁, d⟩ = {}), else no pe circle touches both at P₁, P₂",
                format_scalar(&pe(&e, &d1))
            )));
        }
        let ee = pe(&e, &e);
        if ee <= F::zero() || negligible(&ee, sc * sc) {
            return Err(CyclideError::NoBlend(
                "the two lines coincide or span a non-Euclidean plane".into(),
            ));
        }
        let half = F::one() / F::from_i64(2);
        core::array::from_fn(|i| p1[i].clone() + half.clone() * e[i].clone())
    } else {
        let det = g11.clone() * g22.clone() - g12.clone() * g12.clone();
        if det <= F::zero() {
            return Err(CyclideError::NoBlend(format!(
                "the plane of the two lines is not Euclidean (Gram determinant {}): no pe circle touches both",
                format_scalar(&det)
            )));
        }
        // S = P₁ + λ₁d₁ = P₂ + λ₂d₂: solve in the plane by the Gram system
        let (ed1, ed2) = (pe(&e, &d1), pe(&e, &d2));
        let l1 = (ed1.clone() * g22.clone() - ed2.clone() * g12.clone()) / det.clone();
        let l2 = (ed1 * g12.clone() - ed2 * g11.clone()) / det.clone();
        // tangent lengths λ₁²⟨d₁,d₁⟩ = λ₂²⟨d₂,d₂⟩
        let t1 = l1.clone() * l1.clone() * g11.clone();
        let t2 = l2.clone() * l2.clone() * g22.clone();
        if negligible(&l1, sc) || negligible(&l2, sc) {
            return Err(CyclideError::NoBlend(
                "a contact sphere is the common cycle of both lines (the vertex of the corner)"
                    .into(),
            ));
        }
        if !negligible(&(t1.clone() - t2.clone()), sc.powi(4)) {
            return Err(CyclideError::NoBlend(format!(
                "unequal tangent lengths from the common cycle S of the two lines: λ₁²⟨d₁,d₁⟩ = {} ≠ λ₂²⟨d₂,d₂⟩ = {} (move P₂ along its line)",
                format_scalar(&t1),
                format_scalar(&t2)
            )));
        }
        // centre C₀ = P₁ + μ n₁, n₁ ⟂ d₁ in the plane, ⟨C₀ − P₂, d₂⟩ = 0
        let n1 = sub(&d2, &scale(&(g12.clone() / g11.clone()), &d1));
        let mu = pe(&e, &d2) / pe(&n1, &d2);
        core::array::from_fn(|i| p1[i].clone() + mu.clone() * n1[i].clone())
    };
    let w1 = sub(&p1, &c0);
    let r = pe(&w1, &w1);
    if r <= F::zero() || negligible(&r, sc * sc) {
        return Err(CyclideError::NoBlend(
            "the blend circle has radius 0".into(),
        ));
    }
    let k = sqrt_in_field(&(r.clone() / g11.clone())).ok_or_else(|| {
        CyclideError::NotRational(format!(
            "the blend circle needs √({}) (⟨W₁, W₁⟩/⟨d₁, d₁⟩ is not a rational square)",
            format_scalar(&(r.clone() / g11.clone()))
        ))
    })?;
    let w2 = scale(&k, &d1);
    let cyclide =
        DupinCyclide::from_conic(PeConic::circle_scaled(c0.clone(), w1.clone(), w2.clone())?)?;
    let q = sub(&p2, &c0);
    let (cs, sn) = (pe(&q, &w1) / r.clone(), pe(&q, &w2) / r);
    let one = F::one();
    let t2 = if negligible(&(cs.clone() + one.clone()), 1.0) {
        None
    } else {
        Some(sn / (one + cs))
    };
    Ok(CyclideBlend {
        cyclide,
        t2,
        cones: [(p1, d1), (p2, d2)],
    })
}

/// The contact sphere `P₂` on the line `q₂ + λd₂` of cone 2 that fits the contact sphere
/// `P₁` of cone 1 (equal pe tangent lengths from the common cycle `S` of the two lines, so
/// that one pe circle touches both lines at `P₁` and `P₂`):
///
/// * axes meeting (lines meeting at `S`): `P₂ = S + side·λ₂d₂` with
///   `λ₂² ⟨d₂, d₂⟩ = ⟨P₁ − S, P₁ − S⟩` (`side = ±1` chooses one of the two blends);
/// * parallel axes: `P₂` is the foot of the pe perpendicular from `P₁` to line 2,
///   `P₂ = q₂ + (⟨P₁ − q₂, d⟩/⟨d, d⟩) d` (`side` is ignored).
///
/// # Errors
/// [`CyclideError::IsotropicTangents`] for `⟨dᵢ, dᵢ⟩ ≤ 0`; [`CyclideError::SkewAxes`] if
/// the lines are not coplanar; [`CyclideError::NoBlend`] if they coincide, span a
/// non-Euclidean plane or `P₁` is the common cycle; [`CyclideError::NotRational`] if `λ₂` is
/// irrational (`⟨P₁ − S, P₁ − S⟩/⟨d₂, d₂⟩` not a rational square: choose `P₁` elsewhere on
/// its line).
pub fn fitting_contact_sphere<F: Scalar>(
    p1: &[F; 4],
    d1: &[F; 4],
    q2: &[F; 4],
    d2: &[F; 4],
    side: i8,
) -> Result<[F; 4], CyclideError> {
    let sc = size(p1).max(size(q2)).max(size(d1)).max(size(d2)).max(1.0);
    for (i, d) in [(1, d1), (2, d2)] {
        if pe(d, d) <= F::zero() || negligible(&pe(d, d), sc * sc) {
            return Err(CyclideError::IsotropicTangents(format!(
                "⟨d{i}, d{i}⟩ = {} ≤ 0: |axis|² must exceed (radius change)²",
                format_scalar(&pe(d, d))
            )));
        }
    }
    let e = sub(q2, p1);
    if !minors_vanish(&[e.clone(), d1.clone(), d2.clone()], sc.powi(3)) {
        return Err(CyclideError::SkewAxes(
            "the lines of the two cones in R^{3,1} are not coplanar: no cyclide blend exists"
                .into(),
        ));
    }
    let (g11, g12, g22) = (pe(d1, d1), pe(d1, d2), pe(d2, d2));
    let det = g11.clone() * g22.clone() - g12.clone() * g12.clone();
    if negligible(&det, sc.powi(4)) {
        // parallel lines: the foot of the pe perpendicular from P₁
        let mu = pe(&sub(p1, q2), d2) / g22;
        let p2: [F; 4] = core::array::from_fn(|i| q2[i].clone() + mu.clone() * d2[i].clone());
        let w = sub(&p2, p1);
        if pe(&w, &w) <= F::zero() || negligible(&pe(&w, &w), sc * sc) {
            return Err(CyclideError::NoBlend(
                "the two lines coincide or span a non-Euclidean plane".into(),
            ));
        }
        return Ok(p2);
    }
    if det < F::zero() {
        return Err(CyclideError::NoBlend(format!(
            "the plane of the two lines is not Euclidean (Gram determinant {}): no pe circle touches both",
            format_scalar(&det)
        )));
    }
    // S = P₁ + λ₁d₁ = q₂ + λd₂
    let (ed1, ed2) = (pe(&e, d1), pe(&e, d2));
    let l1 = (ed1.clone() * g22.clone() - ed2.clone() * g12.clone()) / det.clone();
    let s_pt: [F; 4] = core::array::from_fn(|i| p1[i].clone() + l1.clone() * d1[i].clone());
    let t = sub(p1, &s_pt);
    let tt = pe(&t, &t);
    if negligible(&tt, sc * sc) {
        return Err(CyclideError::NoBlend(
            "P₁ is the common cycle of both lines (the vertex of the corner)".into(),
        ));
    }
    let lam = sqrt_in_field(&(tt.clone() / g22.clone())).ok_or_else(|| {
        CyclideError::NotRational(format!(
            "the fitting contact sphere needs √({}) (⟨P₁ − S, P₁ − S⟩/⟨d₂, d₂⟩ is not a rational square): choose P₁ elsewhere on its line",
            format_scalar(&(tt / g22))
        ))
    })?;
    let lam = if side < 0 { -lam } else { lam };
    Ok(core::array::from_fn(|i| {
        s_pt[i].clone() + lam.clone() * d2[i].clone()
    }))
}

impl<F: Scalar> CyclideBlend<F> {
    /// The patches of the band between the contact circles (split at `t = ±1`; `t = 1/τ`
    /// beyond), four pieces in `s` each.
    ///
    /// # Errors
    /// As [`DupinCyclide::band_patches`].
    pub fn patches(&self) -> Result<Vec<BezierPatch<F>>, CyclideError> {
        let (z, one) = (F::zero(), F::one());
        let cy = &self.cyclide;
        match &self.t2 {
            None => {
                let mut v = cy.band_patches(false, &z, &one)?;
                v.extend(cy.band_patches(true, &z, &one)?);
                Ok(v)
            }
            Some(t2) if t2.abs() <= one => {
                if *t2 > z {
                    cy.band_patches(false, &z, t2)
                } else {
                    cy.band_patches(false, t2, &z)
                }
            }
            Some(t2) => {
                let inv = one.clone() / t2.clone();
                if *t2 > z {
                    let mut v = cy.band_patches(false, &z, &one)?;
                    v.extend(cy.band_patches(true, &inv, &one)?);
                    Ok(v)
                } else {
                    let m1 = -one;
                    let mut v = cy.band_patches(false, &m1, &z)?;
                    v.extend(cy.band_patches(true, &m1, &inv)?);
                    Ok(v)
                }
            }
        }
    }

    /// The patches of the complementary band: the rest of the same cyclide between the two
    /// contact circles (the first family's parameter over the complement of the blend's
    /// interval, through `t = ∞`: `t = 1/τ` there), four pieces in `s` per interval. With
    /// [`CyclideBlend::patches`] it covers the whole cyclide; it is tangent to the two
    /// cones along the same circles (from the other side of the contact spheres).
    ///
    /// # Errors
    /// As [`DupinCyclide::band_patches`].
    pub fn complement_patches(&self) -> Result<Vec<BezierPatch<F>>, CyclideError> {
        let (z, one) = (F::zero(), F::one());
        let m1 = -one.clone();
        let cy = &self.cyclide;
        // (reversed, a, b): t ∈ [a, b], or τ ∈ [a, b] with t = 1/τ
        let mut pieces: Vec<(bool, F, F)> = Vec::new();
        match &self.t2 {
            // the blend is t ∈ [0, ∞]
            None => {
                pieces.push((false, m1.clone(), z.clone()));
                pieces.push((true, m1, z));
            }
            Some(t2) if *t2 > z && *t2 <= one => {
                if *t2 < one {
                    pieces.push((false, t2.clone(), one.clone()));
                }
                pieces.push((true, m1.clone(), z.clone()));
                pieces.push((true, z.clone(), one));
                pieces.push((false, m1, z));
            }
            Some(t2) if *t2 > z => {
                pieces.push((true, m1.clone(), one.clone() / t2.clone()));
                pieces.push((false, m1, z));
            }
            Some(t2) if *t2 >= m1 => {
                pieces.push((false, z.clone(), one.clone()));
                pieces.push((true, m1.clone(), z));
                pieces.push((true, F::zero(), one));
                if *t2 > m1 {
                    pieces.push((false, m1, t2.clone()));
                }
            }
            Some(t2) => {
                pieces.push((false, z, one.clone()));
                pieces.push((true, one.clone() / t2.clone(), one));
            }
        }
        let mut out = Vec::new();
        for (rev, a, b) in pieces {
            out.extend(cy.band_patches(rev, &a, &b)?);
        }
        Ok(out)
    }

    /// Certificates of tangency along both contact circles, as identities in `s`: the
    /// circle lies on the contact sphere `Pᵢ` (`|x − mᵢ|² = rᵢ²`), and the tangent planes of
    /// the blend there contain the line of cone `i` (`n·mᵢ − n·x + rᵢ = 0` and
    /// `n·aᵢ + δᵢ = 0`: common tangent planes of blend and cone), plus the cyclide's own
    /// certificates.
    pub fn certify(&self) -> Vec<Certificate> {
        use crate::Certified;
        let mut out = self.cyclide.certify();
        let x = self.cyclide.homogeneous();
        let n = self.cyclide.normal_numerators();
        let ts: [Option<F>; 2] = [Some(F::zero()), self.t2.clone()];
        for (i, ((p, d), t)) in self.cones.iter().zip(ts.iter()).enumerate() {
            // restrict to t (or to t = ∞: leading coefficients in t of degree 2)
            let at = |b: &BiPoly<F>| -> Vec<F> {
                b.coeffs()
                    .iter()
                    .map(|c| match t {
                        Some(t) => c.eval(t),
                        None => c.coeff(2),
                    })
                    .collect()
            };
            let lift = |v: Vec<F>| BiPoly::from_u(&rcagd_algebra::Poly::new(v));
            let xs: [BiPoly<F>; 4] = core::array::from_fn(|k| lift(at(&x[k])));
            let ns: [BiPoly<F>; 3] = core::array::from_fn(|k| lift(at(&n[k])));
            let mut sphere = BiPoly::zero();
            let mut plane = BiPoly::zero();
            let mut axis = xs[0].scale(&d[3]);
            for k in 0..3 {
                let a = xs[k + 1].sub(&xs[0].scale(&p[k]));
                sphere = sphere.add(&a.mul(&a));
                plane = plane.add(&ns[k].mul(&a));
                axis = axis.add(&ns[k].scale(&d[k]));
            }
            let r0 = xs[0].scale(&p[3]);
            sphere = sphere.sub(&r0.mul(&r0));
            // n·(x − m) = r  ⇔  N·(X − X₀m) − X₀² r = 0
            plane = plane.sub(&xs[0].mul(&xs[0]).scale(&p[3]));
            let scl = x
                .iter()
                .flat_map(|b| b.all_coeffs())
                .map(|c| c.to_f64().abs())
                .fold(1.0, f64::max)
                * size(p).max(size(d)).max(1.0);
            let j = i + 1;
            out.push(polynomial_is_zero_scaled(
                &format!("|x − m{j}|² − r{j}² ≡ 0 on the contact circle {j} (it lies on the sphere P{j} of cone {j})"),
                &sphere.all_coeffs(),
                scl * scl,
            ));
            out.push(polynomial_is_zero_scaled(
                &format!("n·(x − m{j}) − r{j} ≡ 0 and n·a{j} + δ{j} ≡ 0 on contact circle {j} (the blend's tangent planes touch cone {j}: common tangent planes)"),
                &plane.all_coeffs().into_iter().chain(axis.all_coeffs()).collect::<Vec<_>>(),
                scl * scl,
            ));
        }
        out
    }
}
