//! The Dupin cyclide enveloping all spheres tangent to three given oriented spheres
//! (Peternell, "Rational Parametrizations for Envelopes of Quadric Families", §3.8.1:
//! `Γ(A₁) ∩ Γ(A₂) ∩ Γ(A₃)` is a pe circle; docs/math/cyclides.md#three-spheres).
//!
//! The cycles tangent (in oriented contact) to the three cycles `Aᵢ` form the conic
//! `{X : ⟨X − Aᵢ, X − Aᵢ⟩ = 0}`; its conjugate conic — the second family of the same
//! cyclide — is the pe conic through `A₁, A₂, A₃` in their plane. When that plane is
//! Euclidean, the three cycles lie on the pe circle `C₀ + cos θ W₁ + sin θ W₂` with the
//! pe circumcentre `C₀` and `W₁ = A₁ − C₀`, and the cyclide of this circle touches each
//! given sphere along a circle and envelops every sphere tangent to all three.

use super::conic::PeConic;
use super::pe::{negligible, pe, scale, size, sqrt_in_field, sub};
use super::surface::DupinCyclide;
use super::CyclideError;
use crate::cyclographic::OrientedSphere;
use rcagd_algebra::{format_scalar, Certificate, Poly, Scalar};
use rcagd_geom::certify::polynomial_is_zero_scaled;

/// The cyclide enveloping the spheres in oriented contact with the three oriented
/// spheres (signed radii: reversing one sphere gives another of the four cyclides).
///
/// # Errors
/// [`CyclideError::DegenerateSpheres`] if the three cycles are collinear in `R^{3,1}`
/// (e.g. collinear centres with equal radii), coincide, or their plane is not Euclidean
/// (a pe hyperbola or parabola through them: a γ-plane gives the parabolic case, build it
/// with [`DupinCyclide::from_pe_parabola`]); [`CyclideError::NotRational`] if the plane's
/// discriminant is not a rational square (the cyclide then needs a quadratic field).
pub fn from_three_spheres<F: Scalar>(
    spheres: &[OrientedSphere<F>; 3],
) -> Result<DupinCyclide<F>, CyclideError> {
    let a: [[F; 4]; 3] = core::array::from_fn(|i| spheres[i].to_point());
    let b2 = sub(&a[1], &a[0]);
    let b3 = sub(&a[2], &a[0]);
    let sc = size(&b2).max(size(&b3)).max(1.0);
    let (g11, g12, g22) = (pe(&b2, &b2), pe(&b2, &b3), pe(&b3, &b3));
    let det = g11.clone() * g22.clone() - g12.clone() * g12.clone();
    // collinear: B₂ ∥ B₃ (all 2×2 minors vanish)
    let collinear = (0..4).all(|i| {
        (0..4).all(|j| {
            negligible(
                &(b2[i].clone() * b3[j].clone() - b2[j].clone() * b3[i].clone()),
                sc * sc,
            )
        })
    });
    if collinear {
        return Err(CyclideError::DegenerateSpheres(
            "the three cycles (centre, signed radius) are collinear in R^{3,1} (e.g. collinear centres with equal radii, or two equal spheres): the spheres tangent to all three form a one-parameter family whose envelope is not determined by them".into(),
        ));
    }
    if negligible(&det, sc.powi(4)) {
        return Err(CyclideError::DegenerateSpheres(format!(
            "the plane of the three cycles is a γ-plane (Gram determinant 0): the spheres tangent to all three envelop a parabolic cyclide; build it from the pe parabola (DupinCyclide::from_pe_parabola). Gram = [[{}, {}], [{}, {}]]",
            format_scalar(&g11), format_scalar(&g12), format_scalar(&g12), format_scalar(&g22)
        )));
    }
    if det < F::zero() || g11 <= F::zero() {
        return Err(CyclideError::DegenerateSpheres(format!(
            "the plane of the three cycles is pseudo-Euclidean (Gram determinant {} < 0): they lie on a pe hyperbola, not a pe circle; reverse the orientation of one sphere (the sign of its radius) or use spheres whose radii differ less than their centres",
            format_scalar(&det)
        )));
    }
    // circumcentre C₀ = A₁ + αB₂ + βB₃: 2G(α, β)ᵀ = (g11, g22)
    let two = F::from_i64(2);
    let alpha =
        (g11.clone() * g22.clone() - g12.clone() * g22.clone()) / (two.clone() * det.clone());
    let beta = (g22.clone() * g11.clone() - g12.clone() * g11.clone()) / (two * det.clone());
    let y: [F; 4] =
        core::array::from_fn(|i| alpha.clone() * b2[i].clone() + beta.clone() * b3[i].clone());
    let c0: [F; 4] = core::array::from_fn(|i| a[0][i].clone() + y[i].clone());
    let w1 = sub(&a[0], &c0);
    let r = pe(&w1, &w1);
    // Z ⟂ W₁ in the plane, then W₂ = Z √(R/⟨Z, Z⟩)
    let pick = if negligible(
        &(b2[0].clone() * w1[1].clone() - b2[1].clone() * w1[0].clone()),
        sc * sc,
    ) && (0..4).all(|i| {
        (0..4).all(|j| {
            negligible(
                &(b2[i].clone() * w1[j].clone() - b2[j].clone() * w1[i].clone()),
                sc * sc,
            )
        })
    }) {
        &b3
    } else {
        &b2
    };
    let z = sub(pick, &scale(&(pe(pick, &w1) / r.clone()), &w1));
    let zz = pe(&z, &z);
    let ratio = r.clone() / zz.clone();
    let k = sqrt_in_field(&ratio).ok_or_else(|| {
        CyclideError::NotRational(format!(
            "the plane of the three cycles has discriminant {} (not a rational square): the cyclide needs the field Q(√{})",
            format_scalar(&(r.clone() * zz.clone())),
            format_scalar(&(r * zz))
        ))
    })?;
    let w2 = scale(&k, &z);
    DupinCyclide::from_conic(PeConic::circle_scaled(c0, w1, w2)?)
}

/// Certificates that the cyclide envelops the spheres tangent to the three: each given
/// cycle lies on the first conic (`Aᵢ − C₀ = αU + βV`, `α² + β² = 1`) and every sphere of
/// the second family is in oriented contact with it (`⟨D(s) − Aᵢ, D(s) − Aᵢ⟩ ≡ 0`).
pub fn certify_three_spheres<F: Scalar>(
    cyclide: &DupinCyclide<F>,
    spheres: &[OrientedSphere<F>; 3],
) -> Vec<Certificate> {
    let mut out = Vec::new();
    let d = cyclide.second_family();
    for (i, s) in spheres.iter().enumerate() {
        let ai = s.to_point();
        // ⟨W D(s) − W Aᵢ, same⟩ as a polynomial in s
        let diff: [Poly<F>; 4] = core::array::from_fn(|k| &d.p[k] - &d.w.scale(&ai[k]));
        let q = &(&(&(&diff[0] * &diff[0]) + &(&diff[1] * &diff[1])) + &(&diff[2] * &diff[2]))
            - &(&diff[3] * &diff[3]);
        let sc = q
            .coeffs()
            .iter()
            .map(|x| x.to_f64().abs())
            .fold(1.0, f64::max)
            .max(size(&ai).powi(2));
        out.push(polynomial_is_zero_scaled(
            &format!("⟨D(s) − A{}, D(s) − A{}⟩ ≡ 0 (every sphere of the second family touches sphere {} in oriented contact)", i + 1, i + 1, i + 1),
            q.coeffs(),
            sc,
        ));
        if let PeConic::Circle { center, u, v, rho } = cyclide.conic() {
            let w = sub(&ai, center);
            let (al, be) = (
                pe(&w, u) / (pe(u, u) * rho.clone()),
                pe(&w, v) / (pe(v, v) * rho.clone()),
            );
            let rest: Vec<F> = (0..4)
                .map(|k| {
                    w[k].clone()
                        - rho.clone() * (al.clone() * u[k].clone() + be.clone() * v[k].clone())
                })
                .chain(core::iter::once(
                    al.clone() * al.clone() + be.clone() * be.clone() - F::one(),
                ))
                .collect();
            out.push(polynomial_is_zero_scaled(
                &format!("A{} − C₀ = ρ(αU + βV) with α² + β² = 1 (sphere {} belongs to the first family)", i + 1, i + 1),
                &rest,
                size(&ai).max(1.0),
            ));
        }
    }
    out
}
