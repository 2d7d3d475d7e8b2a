//! The developable of tangent planes of a conic surface (M. Peternell, "Rational
//! Parametrizations for Envelopes of Quadric Families", Thm 1.3) as a point surface, so
//! that the dual construction can be exported (a patch of planes has no exchange format).
//!
//! The planes `F(t)` of Thm 1.3 touch the conic surface `Φ` at the contact point `k(t)` of
//! the tangent line `y(t)` with its conic (the curve of Thm 1.2): `F ⊃ y` and
//! `F ∩ c(t) = y ∩ c(t) = {k}`. Since `k(t)` is a curve on `Φ`, `k̇` lies in the tangent
//! plane `F`, so `Ḟ·k = −F·k̇ = 0`: `k(t)` lies on the ruling `F(t) ∩ Ḟ(t)` of the
//! developable enveloped by the planes `F(t)`. With a second point `w(t)` of the ruling
//! (its meet with a coordinate plane, the plane at infinity first: then `w` is the
//! ruling's direction), `x(t, v) = k(t) + v·w(t)` parametrizes the developable, which
//! touches `Φ` along `k(t)` (docs/math/conic-surfaces.md, "The developable of tangent
//! planes").

use super::{
    deriv, det3, dot4, form4, point_bidegree, point_patch, positive_pieces, primitive, pz,
    ConicFamily, ConicSurfaceError, P, Q,
};
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Poly};
use rcagd_geom::BezierPatch;

/// The point common to the planes `a`, `b`, `e`: `w_i = (−1)^i·det` of `[a; b; e]` without
/// column `i` (so `w·a = w·b = w·e = 0`).
fn meet3(a: &[P; 4], b: &[P; 4], e: &[P; 4]) -> [P; 4] {
    core::array::from_fn(|i| {
        let cols: Vec<usize> = (0..4).filter(|&j| j != i).collect();
        let m: [[P; 3]; 3] = [a, b, e].map(|r| core::array::from_fn(|k| r[cols[k]].clone()));
        let d = det3(&m);
        if i % 2 == 0 {
            d
        } else {
            -&d
        }
    })
}

/// `a ∥ b` (all `2×2` minors vanish).
fn parallel(a: &[P; 4], b: &[P; 4]) -> bool {
    (0..4).all(|i| (0..4).all(|j| (&(&a[i] * &b[j]) - &(&a[j] * &b[i])).is_zero()))
}

/// The developable of tangent planes `F(t)` of a conic surface as the point surface
/// `x(t, v) = k(t) + v·w(t)` (module docs); variables `t` (index 0) and `v` (index 1).
#[derive(Debug, Clone, PartialEq)]
pub struct TangentDevelopable {
    family: ConicFamily,
    planes: [P; 4],
    contact: [P; 4],
    ruling: [P; 4],
    point: [MPoly<Q>; 4],
}

impl ConicFamily {
    /// The developable of the tangent planes of Thm 1.3 as a point surface (module docs).
    ///
    /// # Errors
    /// As [`Self::tangent_developable`] and [`Self::rational_curve`];
    /// [`ConicSurfaceError::Degenerate`] if the planes `F(t)` are one fixed plane (a plane
    /// touching the surface along a curve, as for the §1.5 example) or form a pencil (the
    /// curve `k(t)` is a line of a ruled surface).
    pub fn tangent_developable_surface(&self) -> Result<TangentDevelopable, ConicSurfaceError> {
        let planes = self.tangent_developable()?;
        let contact = self.rational_curve()?;
        let dplanes: [P; 4] = core::array::from_fn(|i| planes[i].derivative());
        if parallel(&planes, &dplanes) {
            return Err(ConicSurfaceError::Degenerate(
                "the tangent planes F(t) are one fixed plane (it touches the surface along the curve k(t)): the developable degenerates to that plane".into(),
            ));
        }
        // F, Ḟ, F̈ dependent: the planes lie in a pencil (all rulings one line, e.g. the
        // tangent planes along a line of a ruled surface)
        let ddplanes: [P; 4] = core::array::from_fn(|i| dplanes[i].derivative());
        if meet3(&planes, &dplanes, &ddplanes)
            .iter()
            .all(|x| x.is_zero())
        {
            return Err(ConicSurfaceError::Degenerate(
                "the tangent planes F(t) form a pencil (they touch the surface along one line): every ruling F ∩ Ḟ is that line".into(),
            ));
        }
        let ruling = (0..4)
            .map(|j| {
                let e: [P; 4] =
                    core::array::from_fn(|i| if i == j { Poly::constant(Q::ONE) } else { pz() });
                meet3(&planes, &dplanes, &e)
            })
            .find(|w| w.iter().any(|x| !x.is_zero()) && !parallel(w, &contact))
            .ok_or_else(|| {
                ConicSurfaceError::Degenerate(
                    "the tangent planes F(t) form a pencil: every ruling F ∩ Ḟ is one line".into(),
                )
            })?;
        let ruling = primitive(ruling);
        let v = MPoly::var(2, 1);
        let point: [MPoly<Q>; 4] = core::array::from_fn(|i| {
            &MPoly::from_poly(&contact[i], 2, 0) + &(&v * &MPoly::from_poly(&ruling[i], 2, 0))
        });
        Ok(TangentDevelopable {
            family: self.clone(),
            planes,
            contact,
            ruling,
            point,
        })
    }
}

impl TangentDevelopable {
    /// The planes `F(t)`.
    pub fn planes(&self) -> &[P; 4] {
        &self.planes
    }

    /// The contact curve `k(t)` (on the conic surface and on every ruling).
    pub fn contact(&self) -> &[P; 4] {
        &self.contact
    }

    /// The second point `w(t)` of each ruling.
    pub fn ruling(&self) -> &[P; 4] {
        &self.ruling
    }

    /// The homogeneous point `x(t, v)`.
    pub fn point(&self) -> &[MPoly<Q>; 4] {
        &self.point
    }

    /// `(deg_t, deg_v)`.
    pub fn degree(&self) -> (u32, u32) {
        point_bidegree(&self.point)
    }

    /// The rational Bézier patch on `[t₀, t₁] × [v₀, v₁]`.
    ///
    /// # Errors
    /// [`ConicSurfaceError::Patch`] for an empty rectangle or a vanishing weight `x₀`.
    pub fn patch(&self, t: (Q, Q), v: (Q, Q)) -> Result<BezierPatch<Q>, ConicSurfaceError> {
        point_patch(&self.point, t, v, "x₀")
    }
}

impl Certified for TangentDevelopable {
    /// Every point lies on the ruling `F(t) ∩ Ḟ(t)` (`F·x ≡ Ḟ·x ≡ 0`: the developable
    /// enveloped by `F`), every plane touches the conic surface (`FCFᵀ ≡ FĊFᵀ ≡ 0`), and the
    /// contact curve lies on the surface (`γ·k ≡ 0`, `kᵀadj(C + γγᵀ)k ≡ 0`) and in its plane
    /// (`F·k ≡ 0`); the surface is ruled (degree 1 in `v`).
    fn certify(&self) -> Vec<Certificate> {
        let fam = &self.family;
        let lift = |p: &[P; 4]| -> [MPoly<Q>; 4] {
            core::array::from_fn(|i| MPoly::from_poly(&p[i], 2, 0))
        };
        let f = lift(&self.planes);
        let df = lift(&core::array::from_fn(|i| self.planes[i].derivative()));
        let x = &self.point;
        let dotm = |a: &[MPoly<Q>; 4], b: &[MPoly<Q>; 4]| {
            (0..4).fold(MPoly::zero(2), |acc, i| &acc + &(&a[i] * &b[i]))
        };
        let fx = dotm(&f, x);
        let dfx = dotm(&df, x);
        let fcf = form4(&fam.c, &f, &f);
        let fdf = form4(&deriv(&fam.c), &f, &f);
        let k = lift(&self.contact);
        let gk = dot4(&fam.gamma, &self.contact);
        let cg: super::Mat4 = core::array::from_fn(|i| {
            core::array::from_fn(|j| &fam.c[i][j] + &(&fam.gamma[i] * &fam.gamma[j]))
        });
        let kck = form4(&super::adjugate(&cg), &k, &k);
        let fk = dot4(&self.planes, &self.contact);
        let (_, dv) = self.degree();
        let terms = |p: &MPoly<Q>| format!("{} terms", p.num_terms());
        vec![
            Certificate::decide(
                "F(t)·x(t, v) ≡ 0 and Ḟ(t)·x(t, v) ≡ 0 (x lies on the ruling F ∩ Ḟ of the developable)",
                fx.is_zero() && dfx.is_zero(),
                true,
                || format!("F·x: {}, Ḟ·x: {}", terms(&fx), terms(&dfx)),
            ),
            Certificate::decide(
                "F·C(t)·Fᵀ ≡ 0 and F·Ċ(t)·Fᵀ ≡ 0 (every plane F(t) touches the conic surface)",
                fcf.is_zero() && fdf.is_zero(),
                true,
                || format!("FCFᵀ: {}, FĊFᵀ: {}", terms(&fcf), terms(&fdf)),
            ),
            Certificate::decide(
                "γ·k ≡ 0, kᵀ·adj(C + γγᵀ)·k ≡ 0, F·k ≡ 0 (the developable touches the surface along k(t))",
                gk.is_zero() && kck.is_zero() && fk.is_zero(),
                true,
                || format!("γ·k ≢ 0: {}, F·k ≢ 0: {}, conic: {}", !gk.is_zero(), !fk.is_zero(), terms(&kck)),
            ),
            Certificate::decide(
                "degree 1 in v (a ruled surface)",
                dv == 1,
                true,
                || format!("degree {dv} in v"),
            ),
        ]
    }
}

/// The developable of tangent planes as positive-weight patches, with certificates.
#[derive(Debug, Clone)]
pub struct DevelopablePatch {
    /// The point surface.
    pub surface: TangentDevelopable,
    /// The patch on the rectangle, split into pieces with positive weights.
    pub patches: Vec<BezierPatch<Q>>,
    /// The surface's certificates and the weight certificate.
    pub certificates: Vec<Certificate>,
}

/// The developable of tangent planes of a conic surface as positive-weight patches on
/// `[t₀, t₁] × [v₀, v₁]`, with its certificates.
///
/// # Errors
/// As [`ConicFamily::tangent_developable_surface`] and [`TangentDevelopable::patch`].
pub fn tangent_developable_patches(
    family: &ConicFamily,
    t: (Q, Q),
    v: (Q, Q),
) -> Result<DevelopablePatch, ConicSurfaceError> {
    let surface = family.tangent_developable_surface()?;
    let (patches, weights) = positive_pieces(surface.patch(t, v)?)?;
    let mut certificates = surface.certify();
    certificates.push(weights);
    Ok(DevelopablePatch {
        surface,
        patches,
        certificates,
    })
}
