//! An exact cover of the whole sphere — and of every axis-parallel ellipsoid — by sixteen
//! rational biquadratic patches with positive weights (Jüttler §2: δ restricted to the
//! plane `P: p3 = 0` is the stereographic projection σ, Satz 2 / docs/math/quadrics.md, "The map δ onto the sphere").
//!
//! **Construction.** The plane `P: p3 = 0` is covered by the four closed projective
//! triangles `T(s₁, s₂) = {p0 ≥ 0, s₁p1 ≥ 0, s₂p2 ≥ 0}` (`s₁, s₂ = ±1`; every point of
//! `P` has a representative with `p0 ≥ 0`). Each is the bilinear patch
//! `x(u,v) = ((1−u)(1−v), s₁u, s₂v, 0)` over `[0,1]²`: for `(p0, |p1|, |p2|)` the equation
//! `(1−λ|p1|)(1−λ|p2|) = λp0` has a root `λ ∈ (0, 1/max(|p1|,|p2|)]` (intermediate value
//! theorem), so `(u, v) = λ(|p1|, |p2|) ∈ [0,1]²` reaches it. δ maps `P` onto `K`: every
//! `k ≠ z` is `δ(σ⁻¹(k))` with `σ⁻¹(k) = (k0−k3, k1, k2, 0)` (docs/math/quadrics.md, "The map δ onto the sphere"), and the line at
//! infinity `p0 = p3 = 0` of `P` (the fibre over the north pole `z = (1,0,0,1)`) maps to
//! `z`. Hence the δ-images (docs/math/quadrics.md, "Curves and patches under δ") cover `K` exactly. Each triangle is split into
//! the four bilinear sub-patches over `[a/2, (a+1)/2] × [b/2, (b+1)/2]` (exact restriction:
//! the corners are `x(u, v)` at the sub-square's corners), so that every boundary arc spans
//! at most 90° and every weight `k0 = |x|²`-coefficient is positive (a half meridian in one
//! piece would need a zero weight, which CAD exchange formats reject). The edges on the
//! line at infinity collapse to `z`.
//!
//! **Ellipsoids.** `A = [[1,0,0,0],[c_x,a,0,0],[c_y,0,b,0],[c_z,0,0,c]]` maps `K` onto the
//! ellipsoid `((x−c_x)/a)² + ((y−c_y)/b)² + ((z−c_z)/c)² = 1` (docs/math/quadrics.md, "Other quadrics", with a
//! translation); it is applied to the control points (exact, degree kept).

use super::general::{certify_transfer, transfer_patch, Quadric};
use super::helpers::{self, fmt_vec};
use super::image::{certify_patch_on_quadric, patch_image, ImagePatch};
use super::{Delta, Hom, Mat4, QuadricError};
use crate::Certified;
use rcagd_algebra::{Certificate, Scalar};
use rcagd_geom::BezierPatch;

/// The sign pairs `(s₁, s₂)` of the four triangles.
const SIGNS: [(i64, i64); 4] = [(1, 1), (-1, 1), (-1, -1), (1, -1)];

/// The sub-squares `(a, b)`: `[a/2, (a+1)/2] × [b/2, (b+1)/2]`.
const SUBS: [(i64, i64); 4] = [(0, 0), (1, 0), (0, 1), (1, 1)];

/// Sixteen biquadratic patches covering the ellipsoid with centre `c` and semi-axes
/// `a, b, c` (the unit sphere for `c = 0`, `a = b = c = 1`) exactly (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct SphereCover<F> {
    sphere_patches: Vec<ImagePatch<F>>,
    patches: Vec<BezierPatch<F>>,
    map: Mat4<F>,
    target: Quadric<F>,
}

/// `4·x(u, v)` of the triangle `T(s₁, s₂)` at `u = i/2`, `v = j/2` (integers).
fn corner4(s1: i64, s2: i64, i: i64, j: i64) -> [i64; 4] {
    [(2 - i) * (2 - j), 4 * s1 * i / 2, 4 * s2 * j / 2, 0]
}

/// The bilinear preimage of the sub-square `(a, b)` of the triangle `T(s₁, s₂)`.
fn piece<F: Scalar>(s1: i64, s2: i64, a: i64, b: i64) -> Result<BezierPatch<F>, QuadricError> {
    let h = |i: i64, j: i64| corner4(s1, s2, i, j).map(F::from_i64).to_vec();
    Ok(BezierPatch::from_homogeneous(vec![
        vec![h(a, b), h(a, b + 1)],
        vec![h(a + 1, b), h(a + 1, b + 1)],
    ])?)
}

/// The `(s₁, s₂, a, b)` of every patch, in output order.
fn layout() -> impl Iterator<Item = (i64, i64, i64, i64)> {
    SIGNS
        .into_iter()
        .flat_map(|(s1, s2)| SUBS.into_iter().map(move |(a, b)| (s1, s2, a, b)))
}

/// The exact cover of the ellipsoid `((x−c_x)/a)² + ((y−c_y)/b)² + ((z−c_z)/c)² = 1` by
/// sixteen biquadratic patches (module docs); `center = [0,0,0]`, `radii = [1,1,1]` gives
/// the unit sphere `K` itself.
///
/// # Errors
/// [`QuadricError::InvalidArgument`] if a semi-axis is zero; [`QuadricError::NotFinite`].
pub fn sphere_cover<F: Scalar>(
    center: [F; 3],
    radii: [F; 3],
) -> Result<SphereCover<F>, QuadricError> {
    if !helpers::all_finite(&center) {
        return Err(QuadricError::NotFinite("the centre".into()));
    }
    for (r, axis) in radii.iter().zip(["a", "b", "c"]) {
        if r.is_zero() || !helpers::all_finite(std::slice::from_ref(r)) {
            return Err(QuadricError::InvalidArgument(format!(
                "the semi-axis {axis} must be finite and non-zero"
            )));
        }
    }
    let z = F::zero;
    let [cx, cy, cz] = center;
    let [a, b, c] = radii;
    let map: Mat4<F> = [
        [F::one(), z(), z(), z()],
        [cx.clone(), a.clone(), z(), z()],
        [cy.clone(), z(), b.clone(), z()],
        [cz.clone(), z(), z(), c.clone()],
    ];
    // Q = −e0e0ᵀ + Σᵢ (eᵢ − cᵢe0)(eᵢ − cᵢe0)ᵀ / rᵢ²
    let mut q: Mat4<F> = [
        helpers::zero4(),
        helpers::zero4(),
        helpers::zero4(),
        helpers::zero4(),
    ];
    q[0][0] = -F::one();
    for (i, (ci, ri)) in [(cx, a), (cy, b), (cz, c)].into_iter().enumerate() {
        let mut e = helpers::zero4::<F>();
        e[0] = -ci;
        e[i + 1] = F::one();
        let w = F::one() / (ri.clone() * ri);
        for r in 0..4 {
            for s in 0..4 {
                q[r][s] += w.clone() * e[r].clone() * e[s].clone();
            }
        }
    }
    let target = Quadric::from_matrix(q)?.named("the ellipsoid of the cover");
    let mut sphere_patches = Vec::with_capacity(16);
    let mut patches = Vec::with_capacity(16);
    for (s1, s2, a, b) in layout() {
        let img = patch_image(&Delta, &piece::<F>(s1, s2, a, b)?)?;
        patches.push(transfer_patch(&map, img.image())?);
        sphere_patches.push(img);
    }
    Ok(SphereCover {
        sphere_patches,
        patches,
        map,
        target,
    })
}

impl<F: Scalar> SphereCover<F> {
    /// The sixteen patches on the ellipsoid: for `(s₁, s₂) = (+,+), (−,+), (−,−), (+,−)` the
    /// sub-squares `(0,0), (1,0), (0,1), (1,1)`.
    pub fn patches(&self) -> &[BezierPatch<F>] {
        &self.patches
    }
    /// The patches, consumed.
    pub fn into_patches(self) -> Vec<BezierPatch<F>> {
        self.patches
    }
    /// The patches on the unit sphere before the map `A`, with their preimages.
    pub fn sphere_patches(&self) -> &[ImagePatch<F>] {
        &self.sphere_patches
    }
    /// The ellipsoid.
    pub fn quadric(&self) -> &Quadric<F> {
        &self.target
    }
}

/// The four boundary curves of a patch as homogeneous control points:
/// `u = 0`, `v = 0`, `u = 1`, `v = 1`.
fn edges<F: Scalar>(p: &BezierPatch<F>) -> [Vec<Hom<F>>; 4] {
    let (m, n) = p.degree();
    let row = |i: usize| {
        (0..=n)
            .map(|j| helpers::to_hom(p.control_point(i, j)))
            .collect()
    };
    let col = |j: usize| {
        (0..=m)
            .map(|i| helpers::to_hom(p.control_point(i, j)))
            .collect()
    };
    [row(0), col(0), row(m), col(n)]
}

/// One certificate for a property checked on every patch: holds iff it holds for all;
/// the residual names the first patch where it fails.
fn for_all<F: Scalar>(property: &str, results: impl Iterator<Item = Certificate>) -> Certificate {
    let failed: Vec<String> = results
        .enumerate()
        .filter(|(_, c)| !c.holds)
        .map(|(k, c)| format!("patch {k}: {}", c.residual.unwrap_or_default()))
        .collect();
    Certificate::decide(property, failed.is_empty(), F::EXACT, || failed.join("; "))
}

impl<F: Scalar> Certified for SphereCover<F> {
    /// `A` maps `K` onto the ellipsoid; for every patch: on `K` before `A` with the
    /// polar-form rule, on the ellipsoid (`Xᵀ Q X ≡ 0`, exact Bernstein coefficients),
    /// every weight positive (no pole, exportable), preimage = the sub-square of its
    /// triangle; watertight: every edge is an edge of exactly one other patch or collapses
    /// to the pole `A·z`; the triangles cover every sign quadrant of `p3 = 0`.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = vec![certify_transfer(
            &self.map,
            &Quadric::unit_sphere(),
            &self.target,
        )];
        let n = self.patches.len();
        out.push(for_all::<F>(
            "every patch on K: Xᵀ Q X ≡ 0 and Σ d_kl B_k B_l ≡ δ(Σ c_ij B_i B_j) (polar-form rule)",
            self.sphere_patches.iter().map(|img| {
                let certs = img.certify();
                let bad: Vec<String> = certs
                    .iter()
                    .filter(|c| !c.holds)
                    .map(ToString::to_string)
                    .collect();
                Certificate::decide("", bad.is_empty(), F::EXACT, || bad.join("; "))
            }),
        ));
        out.push(for_all::<F>(
            &format!("all {n} patches lie on the ellipsoid: Xᵀ Q X ≡ 0"),
            self.patches
                .iter()
                .map(|p| certify_patch_on_quadric(p, self.target.matrix(), "")),
        ));
        out.push(for_all::<F>(
            "every weight > 0 (no pole on [0,1]², exportable)",
            self.patches.iter().map(|p| {
                let s = p.dim() + 1;
                let bad = p
                    .coords()
                    .iter()
                    .step_by(s)
                    .find(|w| **w <= F::zero())
                    .cloned();
                Certificate::decide("", bad.is_none(), F::EXACT, || {
                    format!(
                        "weight {}",
                        bad.as_ref().map(helpers::fmt_scalar).unwrap_or_default()
                    )
                })
            }),
        ));
        out.push(for_all::<F>(
            "every preimage is the exact restriction of its triangle x(u,v) = ((1−u)(1−v), s₁u, s₂v, 0) to its sub-square",
            self.sphere_patches.iter().zip(layout()).map(|(img, (s1, s2, a, b))| {
                let ok = piece::<F>(s1, s2, a, b).is_ok_and(|w| &w == img.preimage());
                Certificate::decide("", ok, F::EXACT, || "the preimage differs".into())
            }),
        ));
        // watertight: every edge is shared with exactly one other patch or collapsed
        let pole = helpers::mat_vec(&self.map, &[F::one(), F::zero(), F::zero(), F::one()]);
        let all: Vec<[Vec<Hom<F>>; 4]> = self.patches.iter().map(edges).collect();
        let mut problems = Vec::new();
        for (k, ek) in all.iter().enumerate() {
            for (e, edge) in ek.iter().enumerate() {
                if edge.iter().all(|x| helpers::parallel(x, &pole)) {
                    continue;
                }
                let rev: Vec<Hom<F>> = edge.iter().rev().cloned().collect();
                let partners = all
                    .iter()
                    .enumerate()
                    .filter(|(l, _)| *l != k)
                    .flat_map(|(_, el)| el.iter())
                    .filter(|o| **o == *edge || **o == rev)
                    .count();
                if partners != 1 {
                    problems.push(format!(
                        "patch {k} edge {e}: shared with {partners} patches"
                    ));
                }
            }
        }
        out.push(Certificate::decide(
            "watertight: every edge is the edge of exactly one other patch (same control points) or collapses to the pole A·z",
            problems.is_empty(),
            F::EXACT,
            || format!("{} (pole {})", problems.join("; "), fmt_vec(&pole)),
        ));
        let all_quadrants = [(1, 1), (1, -1), (-1, 1), (-1, -1)]
            .iter()
            .all(|s| SIGNS.contains(s));
        let all_subs = (0..2).all(|a| (0..2).all(|b| SUBS.contains(&(a, b))));
        out.push(Certificate::decide(
            "the triangles cover every sign quadrant of p3 = 0 and their sub-squares tile [0,1]², so the patches cover the whole quadric",
            all_quadrants && all_subs,
            F::EXACT,
            || "a quadrant or sub-square is missing".to_string(),
        ));
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn r(n: i64) -> Rational {
        Rational::from(n)
    }

    #[test]
    fn unit_sphere_cover_certifies() {
        let c = sphere_cover([r(0), r(0), r(0)], [r(1), r(1), r(1)]).unwrap();
        assert_eq!(c.patches().len(), 16);
        assert!(c.patches().iter().all(|p| p.degree() == (2, 2)));
        for cert in c.certify() {
            assert!(cert.holds && cert.exact, "{cert}");
        }
    }

    #[test]
    fn ellipsoid_cover_certifies_and_f64_agrees() {
        let c = sphere_cover([r(1), r(-2), r(3)], [r(2), r(3), r(1) / r(2)]).unwrap();
        assert!(c.all_hold());
        let f = sphere_cover([1.0, -2.0, 3.0], [2.0, 3.0, 0.5]).unwrap();
        assert!(f.all_hold());
        for (pe, pf) in c.patches().iter().zip(f.patches()) {
            for (x, y) in pe.coords().iter().zip(pf.coords()) {
                assert!((Scalar::to_f64(x) - y).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn a_wrong_patch_fails_its_certificate() {
        let mut c = sphere_cover([r(0), r(0), r(0)], [r(1), r(1), r(1)]).unwrap();
        let full = c.clone();
        // a missing patch leaves a hole: the watertight certificate fails
        c.patches.pop();
        let failing: Vec<_> = c.certify().into_iter().filter(|x| !x.holds).collect();
        assert_eq!(failing.len(), 1, "{failing:?}");
        assert!(failing[0].property.starts_with("watertight"));
        // a patch moved off the ellipsoid
        let mut d = full;
        let moved = transfer_patch(
            &helpers::mat4_i([[1, 0, 0, 0], [1, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]),
            &d.patches[5],
        )
        .unwrap();
        d.patches[5] = moved;
        assert!(d
            .certify()
            .iter()
            .any(|x| !x.holds && x.property.contains("lie on the ellipsoid")));
    }

    #[test]
    fn zero_semi_axis_is_an_error() {
        let e = sphere_cover([r(0), r(0), r(0)], [r(1), r(0), r(1)]).unwrap_err();
        assert!(e.to_string().contains("semi-axis b"), "{e}");
    }
}
