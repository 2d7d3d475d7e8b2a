//! PN surfaces from their tangent planes: the dual (support function) representation
//! (Peternell §4.1 (4.1)/(4.2), §5.2), anticaustics (§3.6, Theorem 4.1, (3.18) corrected)
//! and Laguerre images (Theorem 4.2).
//!
//! **Envelope of a plane field.** Let `e = (h, n)` be a rational field of oriented planes
//! `h + n·x = 0` with a rational unit normal `n = N/N₀` (`N·N ≡ N₀²`) and support function
//! `h = H/L`. The point `x = e ∩ e_u ∩ e_v` is (using `n·n_u = n·n_v = 0`)
//! ```text
//! x = −h n − [h_u (n_v × n) + h_v (n × n_u)] / det(n_u, n_v, n)
//!   = [−H L Δ N − N₀² (η_u (N_v × N) + η_v (N × N_u))] / (L² N₀ Δ),
//! ```
//! `Δ = det(N_u, N_v, N)`, `η_s = H_s L − H L_s` (derived here; Peternell refers to his reference \[35\]).
//! For the stereographic normal `N = (2ac, 2bc, a² + b² − c²)`, `Δ = −4 N₀ c J`
//! (`J = det((a,b,c), ∂_u, ∂_v)`, checked with sympy), so `N₀` cancels. `Δ ≡ 0` means a
//! developable (one-parameter) family of planes.
//!
//! The forms (4.1) and (4.2) themselves are handled through the isotropic model
//! ([`IsotropicSurface::from_dual`], [`IsotropicSurface::from_support`]; (4.4)), which
//! gives lower degrees; [`from_dual`] and [`from_support_function`] are shortcuts.

use super::isotropic::IsotropicSurface;
use super::poly::{cross3, det3, dot3, RatFn};
use super::surface::{unit_normal_cert, PnSurface};
use super::PnError;
use crate::laguerre::LaguerreMap;
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Scalar};

/// The PN surface of the dual form (4.1) `e = (g, 2acf, 2bcf, (a² + b² − c²) f)`
/// (polynomials `a, b, c, g, f` in `(u, v)`): unit normal `(2ac, 2bc, a² + b² − c²)/(a² + b² + c²)`
/// (for `f > 0`), support `h = g/((a² + b² + c²) f)`.
///
/// # Errors
/// [`PnError::InvalidInput`] for `c ≡ 0` or `f ≡ 0`; [`PnError::Developable`] for a
/// degenerate spherical image.
pub fn from_dual<F: Scalar>(
    a: MPoly<F>,
    b: MPoly<F>,
    c: MPoly<F>,
    g: MPoly<F>,
    f: MPoly<F>,
) -> Result<PnSurface<F>, PnError> {
    let extra = vec![f.clone()];
    IsotropicSurface::from_dual(a, b, c, g, f)?.to_pn_surface_with(&extra)
}

/// The PN surface of the normalized dual form (4.2)
/// `e = (h, 2ac/(a²+b²+c²), 2bc/(a²+b²+c²), (a²+b²−c²)/(a²+b²+c²))` with an arbitrary
/// rational support function `h`.
///
/// # Errors
/// As [`from_dual`].
pub fn from_support_function<F: Scalar>(
    a: MPoly<F>,
    b: MPoly<F>,
    c: MPoly<F>,
    h: &RatFn<F>,
) -> Result<PnSurface<F>, PnError> {
    let extra = vec![h.den.clone()];
    IsotropicSurface::from_support(a, b, c, h)?.to_pn_surface_with(&extra)
}

/// The envelope of the rational plane field `h + n·x = 0`, `n = (N₁, N₂, N₃)/N₀` (module
/// docs): the PN surface with exactly these oriented tangent planes.
///
/// # Errors
/// [`PnError::NotUnitNormal`] unless `N₁² + N₂² + N₃² ≡ N₀²`; [`PnError::Developable`] if
/// `det(N_u, N_v, N) ≡ 0`.
pub fn from_plane_field<F: Scalar>(
    h: &RatFn<F>,
    normal: &[MPoly<F>; 4],
) -> Result<PnSurface<F>, PnError> {
    from_plane_field_with(h, normal, &[])
}

/// [`from_plane_field`] with further known factors of the point representation (divided
/// out exactly, as often as they divide all four coordinates): the `f64` path has no
/// polynomial gcd, so a common factor the construction predicts must be named here to be
/// cancelled there as in the exact path.
///
/// # Errors
/// As [`from_plane_field`].
pub(crate) fn from_plane_field_with<F: Scalar>(
    h: &RatFn<F>,
    normal: &[MPoly<F>; 4],
    factors: &[MPoly<F>],
) -> Result<PnSurface<F>, PnError> {
    let cert = unit_normal_cert(normal);
    if !cert.holds {
        return Err(PnError::NotUnitNormal(
            cert.residual.unwrap_or_else(|| "N·N ≢ N₀²".into()),
        ));
    }
    let n0 = &normal[0];
    let n = [normal[1].clone(), normal[2].clone(), normal[3].clone()];
    let nu: [MPoly<F>; 3] = std::array::from_fn(|i| n[i].partial(0));
    let nv: [MPoly<F>; 3] = std::array::from_fn(|i| n[i].partial(1));
    let delta = det3([&nu, &nv, &n]);
    if delta.is_zero() {
        return Err(PnError::Developable(
            "det(N_u, N_v, N) ≡ 0: the planes form a one-parameter family".into(),
        ));
    }
    let (hn, hd) = (&h.num, &h.den);
    let eta = |k: usize| &(&hn.partial(k) * hd) - &(hn * &hd.partial(k));
    let (eta_u, eta_v) = (eta(0), eta(1));
    let a = cross3(&nv, &n);
    let b = cross3(&n, &nu);
    let hhd = &(hn * hd) * &delta;
    let n02 = n0 * n0;
    let x: [MPoly<F>; 3] = std::array::from_fn(|i| {
        let t = &(&eta_u * &a[i]) + &(&eta_v * &b[i]);
        -(&(&hhd * &n[i]) + &(&n02 * &t))
    });
    let hd2 = hd * hd;
    let k = &hd2 * &delta;
    let w = &k * n0;
    let [x1, x2, x3] = x;
    let mut candidates = vec![n0.clone(), hd.clone()];
    candidates.extend(factors.iter().cloned());
    PnSurface::assemble(
        "envelope of a plane field",
        [w, x1, x2, x3],
        normal.clone(),
        h.clone(),
        Some(k),
        &candidates,
    )
}

/// The anticaustic by reflection of a rational mirror surface for light rays parallel to
/// `x₃` (Peternell §3.6, Theorem 4.1; (3.18) **corrected**, docs/math/laguerre-pn.md):
/// `q = (p₁, p₂, c) + 2(p₃ − c) m₃ m/|m|²`, `m` a normal of the mirror (here
/// `m = (π₁, π₂, π₃)` of the tangent plane `π` through `P̂, P̂_u, P̂_v`). It is a PN surface
/// whose unit normal is the reflected ray direction `r = e₃ − 2m₃m/|m|²`; varying `c`
/// gives its offsets.
///
/// # Errors
/// [`PnError::InvalidInput`] if the mirror is degenerate (`m ≡ 0`) or its weight is zero;
/// [`PnError::Developable`] if the anticaustic's planes form a one-parameter family.
pub fn anticaustic<F: Scalar>(mirror: &[MPoly<F>; 4], c: &F) -> Result<PnSurface<F>, PnError> {
    let pu: [MPoly<F>; 4] = std::array::from_fn(|i| mirror[i].partial(0));
    let pv: [MPoly<F>; 4] = std::array::from_fn(|i| mirror[i].partial(1));
    // π_i = (−1)^i det of the 3×3 minor without column i, of rows (P̂, P̂_u, P̂_v); m = π₁..π₃
    let minor = |skip: usize| {
        let pick = |r: &[MPoly<F>; 4]| {
            let v: Vec<MPoly<F>> = (0..4)
                .filter(|&k| k != skip)
                .map(|k| r[k].clone())
                .collect();
            [v[0].clone(), v[1].clone(), v[2].clone()]
        };
        det3([&pick(mirror), &pick(&pu), &pick(&pv)])
    };
    let m = [-minor(1), minor(2), -minor(3)];
    let mm = dot3(&m, &m);
    if mm.is_zero() || mirror[0].is_zero() {
        return Err(PnError::InvalidInput(
            "the mirror surface is degenerate (zero normal or weight)".into(),
        ));
    }
    let p0 = &mirror[0];
    let two = F::from_i64(2);
    let lift = (&(&mirror[3] - &p0.scale(c)) * &m[2]).scale(&two);
    let w = p0 * &mm;
    let x1 = &(&mirror[1] * &mm) + &(&lift * &m[0]);
    let x2 = &(&mirror[2] * &mm) + &(&lift * &m[1]);
    let x3 = &(&p0.scale(c) * &mm) + &(&lift * &m[2]);
    let m3m = |k: usize| (&m[2] * &m[k]).scale(&two);
    let normal = [mm.clone(), -m3m(0), -m3m(1), &mm - &m3m(2)];
    let point = [w, x1, x2, x3];
    let support = RatFn::new(-dot3(&normal[1..], &point[1..]), &normal[0] * &point[0])?;
    let s = PnSurface::assemble(
        "anticaustic (3.18)",
        point,
        normal,
        support,
        Some(p0.clone()),
        std::slice::from_ref(&mm),
    )?;
    if s.point_map_degenerate() {
        return Err(PnError::Developable(
            "the anticaustic is not a surface (its point map has rank < 2)".into(),
        ));
    }
    Ok(s)
}

impl<F: Scalar> PnSurface<F> {
    /// The image under a Laguerre transformation (Theorem 4.2: Laguerre maps send PN
    /// surfaces, as sets of oriented planes, to PN surfaces). The γ-hyperplane field
    /// `(h, n, 1) ∝ (H N₀, L N, L N₀)` (`h = H/L`) is mapped linearly by
    /// [`LaguerreMap::hyperplane_matrix`]: the new unit normal is `(N, N₀)·B` (the same
    /// degree), the new support function `(H N₀ − L (N, N₀)·Ba)/(L (N, N₀)·B e₄)`, and the
    /// points are recomputed as the envelope ([`from_plane_field`]).
    ///
    /// # Errors
    /// [`PnError::Developable`] if the image planes form a one-parameter family.
    pub fn laguerre_image(&self, map: &LaguerreMap<F>) -> Result<PnSurface<F>, PnError> {
        let h = map.hyperplane_matrix();
        let nv = self.normal_polys();
        // ε_v = (N₁, N₂, N₃, N₀) (the vector part, up to the factor L)
        let ev = [nv[1].clone(), nv[2].clone(), nv[3].clone(), nv[0].clone()];
        let img: [MPoly<F>; 4] = std::array::from_fn(|j| {
            (0..4).fold(MPoly::zero(2), |s, i| &s + &ev[i].scale(&h[i + 1][j + 1]))
        });
        // ε₀' = H N₀ − L Σ ε_v,i (B a)_i, and (B a)_i = −h[i+1][0]
        let lin = (0..4).fold(MPoly::zero(2), |s, i| &s + &ev[i].scale(&h[i + 1][0]));
        let sup = self.support();
        let num = &(&sup.num * &nv[0]) + &(&sup.den * &lin);
        let den = &sup.den * &img[3];
        let support = RatFn::new(num, den)?;
        let normal = [
            img[3].clone(),
            img[0].clone(),
            img[1].clone(),
            img[2].clone(),
        ];
        Ok(
            from_plane_field(&support, &normal)?
                .named(format!("Laguerre image of {}", self.name())),
        )
    }
}

/// The Theorem 4.1 certificate of an anticaustic: the reflected ray through the mirror
/// point passes through the anticaustic point (`(q − p) × r ≡ 0`), in addition to the PN
/// identities (which include `r ⟂ q_u, q_v`).
pub fn anticaustic_certificates<F: Scalar>(
    mirror: &[MPoly<F>; 4],
    surface: &PnSurface<F>,
) -> Vec<Certificate> {
    let mut out = surface.certify();
    let q = surface.point_polys();
    let n = surface.normal_polys();
    // q − p ∝ Q P₀ − P W
    let d: [MPoly<F>; 3] =
        std::array::from_fn(|i| &(&q[i + 1] * &mirror[0]) - &(&mirror[i + 1] * &q[0]));
    let r = [n[1].clone(), n[2].clone(), n[3].clone()];
    let c = cross3(&d, &r);
    for (k, comp) in c.iter().enumerate() {
        out.push(super::poly::zero_cert(
            &format!("anticaustic point on the reflected ray through the mirror point ((q − p) × r, component {k})"),
            comp,
            1e6 * super::poly::mag(comp).max(1.0),
        ));
    }
    out
}
