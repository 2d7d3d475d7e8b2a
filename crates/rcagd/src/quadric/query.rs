//! Questions about the generalized stereographic projections, answered exactly
//! (B. Jüttler, *Zur Konstruktion rationaler Kurven und Flächen auf Quadriken*; our
//! formulations in docs/math/quadrics.md):
//!
//! * [`fibre_query`], [`fibre_through`]: the projecting line (fibre) over a point `k` of
//!   the quadric, or through a point `p` of `P³` with `k = F(p)`; for δ and ψ also the
//!   inverse of the stereographic part, `σ⁻¹(k) = (k0−k3, k1, k2, 0)` in the plane
//!   `P: p3 = 0` (Jüttler, text after Satz 3) and `τ⁻¹(k) = (k0, k1, k2, k0)` in
//!   `R: q3 = q0` (Satz 8). Certified: `F(λa + μb) ∥ k` identically in `λ, μ`.
//! * [`preimage_quadric`]: the preimage `F⁻¹(Φ ∩ π)` of the plane section (circle,
//!   conic) `Φ ∩ π`: the quadric `pᵀ(Σ πᵢ Mᵢ)p = 0` of `πᵀF(p) = 0` (Jüttler §2/§3
//!   property lists; docs/math/quadrics.md, "Preimage quadrics"), with its affine type.
//! * [`collineation_curve`], [`collineation_patch`]: the image of a curve or patch
//!   under a collineation `X ↦ A X` (a regular 4×4 matrix), and of a quadric,
//!   `Q' = A⁻ᵀ Q A⁻¹` (Jüttler, Schlussbemerkung: constructions on one quadric are carried
//!   to projectively equivalent ones by collineations).
//! * [`miquel_points`]: the boundary circles of a biquadratic patch on a quadric, the
//!   second intersections `q1..q4` of adjacent circles and the two Miquel conditions
//!   `det[p1, q2, p3, q4] = det[q1, p2, q3, p4] = 0` (Satz 7).
//! * [`psi_interpolate`]: interpolation on the hyperbolic paraboloid `H: h0h3 = h1h2` by
//!   `ψ` of any degree `n ≥` the lowest one, through the Segre factors `y = u ⊗ v`
//!   (Jüttler (8), (15)): the solution spaces of `u` and `v` and their free parameters.

use super::helpers::{self, fmt_scalar, fmt_vec};
use super::image::{certify_curve_on_quadric, certify_patch_on_quadric, pick_member};
use super::interpolation::{interpolate_lowest_degree, HermiteDatum, Interpolant};
use super::paraboloid::{
    binary_eval, binary_space, checked_segre_factors, segre_product, tau_inverse,
};
use super::sphere_patch::{miquel_residuals, second_intersection};
use super::stereographic::sigma_inverse;
use super::{
    check_on_quadric, check_point, GeneralizedProjection, Hom, Mat4, Quadric, QuadricError,
    QuadricKind,
};
use crate::Certified;
use rcagd_algebra::{bernstein, Certificate, Poly, Scalar};
use rcagd_geom::{BezierCurve, BezierPatch};

/// `v ∥ k` or `v = 0` (exact for exact scalars).
fn parallel_or_zero<F: Scalar>(v: &[F], k: &[F]) -> bool {
    helpers::is_zero_vec(v) || helpers::parallel(v, k)
}

/// Which stereographic inverse a [`FibreQuery`] adds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlaneInverse {
    /// `σ⁻¹(k) = (k0−k3, k1, k2, 0)` in `P: p3 = 0` (δ onto the unit sphere).
    Sigma,
    /// `τ⁻¹(k) = (k0, k1, k2, k0)` in `R: q3 = q0` (ψ onto `H`).
    Tau,
}

/// The projecting line of a generalized stereographic projection over a point of its
/// quadric.
#[derive(Debug, Clone, PartialEq)]
pub struct FibreQuery<F> {
    /// The point `k` of the quadric.
    pub point: Hom<F>,
    /// Two points `a, b` spanning the projecting line over `k`.
    pub fibre: [Hom<F>; 2],
    /// The given point `p` of `P³` (for [`fibre_through`]).
    pub through: Option<Hom<F>>,
    /// The inverse of the stereographic part (`σ⁻¹(k)` or `τ⁻¹(k)`), a point of the fibre.
    pub plane_point: Option<(PlaneInverse, Hom<F>)>,
    images: [Hom<F>; 3],
    quadric: Mat4<F>,
    map: String,
}

/// The fibre (projecting line) of `proj` over the point `k` of its quadric.
///
/// # Errors
/// [`QuadricError::NotOnQuadric`], [`QuadricError::ZeroPoint`], [`QuadricError::NotFinite`],
/// [`QuadricError::Exceptional`] (a cone's vertex).
pub fn fibre_query<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    k: &Hom<F>,
) -> Result<FibreQuery<F>, QuadricError> {
    let q = proj.quadric();
    check_on_quadric(&q, k, "the point", &proj.name())?;
    let [a, b] = proj.fibre(k)?;
    let images = [proj.apply(&a), proj.polar(&a, &b), proj.apply(&b)];
    Ok(FibreQuery {
        point: k.clone(),
        fibre: [a, b],
        through: None,
        plane_point: None,
        images,
        quadric: q,
        map: proj.name(),
    })
}

/// The fibre through a point `p` of `P³`: `k = F(p)` and the projecting line over it.
///
/// # Errors
/// [`QuadricError::ZeroPoint`], [`QuadricError::NotFinite`];
/// [`QuadricError::Exceptional`] if `F(p) = 0` (`p` on an exceptional line of the
/// congruence, where `F` is undefined).
pub fn fibre_through<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    p: &Hom<F>,
) -> Result<FibreQuery<F>, QuadricError> {
    check_point(p, "the point")?;
    let k = proj.apply(p);
    if helpers::all_negligible(&k, helpers::magnitude(p).powi(2)) {
        return Err(QuadricError::Exceptional {
            map: proj.name(),
            point: fmt_vec(p),
            reason: "F(p) = 0: the point lies on an exceptional line of the congruence".into(),
        });
    }
    let mut f = fibre_query(proj, &k)?;
    f.through = Some(p.clone());
    Ok(f)
}

impl<F: Scalar> FibreQuery<F> {
    /// Adds the stereographic inverse (`σ⁻¹` for δ, `τ⁻¹` for ψ); `None` at the centre of
    /// the stereographic projection (`z = (1,0,0,1)` resp. `c = (0,0,0,1)`), whose fibre
    /// does not meet the plane in one point.
    pub fn with_plane_inverse(mut self, which: PlaneInverse) -> Self {
        let x = match which {
            PlaneInverse::Sigma => sigma_inverse(&self.point).ok(),
            PlaneInverse::Tau => tau_inverse(&self.point).ok(),
        };
        self.plane_point = x.map(|x| (which, x));
        self
    }

    /// The values `F(a)`, `F̂(a, b)`, `F(b)`: `F(λa + μb) = λ²F(a) + 2λμF̂(a, b) + μ²F(b)`.
    pub fn images(&self) -> &[Hom<F>; 3] {
        &self.images
    }

    /// The matrix of the target quadric.
    pub fn quadric(&self) -> &Mat4<F> {
        &self.quadric
    }
}

impl<F: Scalar> Certified for FibreQuery<F> {
    /// `k` on the quadric; `a, b` independent; `F(λa + μb) ∥ k` for all `λ, μ` (each of
    /// `F(a)`, `F̂(a, b)`, `F(b)` is a multiple of `k`, not all zero); the given `p` and the
    /// stereographic inverse lie on the line; the inverse lies in its plane and maps to `k`.
    fn certify(&self) -> Vec<Certificate> {
        let k = &self.point;
        let [a, b] = &self.fibre;
        let (r, mag) = helpers::quad_form(&self.quadric, k);
        let mut out = vec![Certificate::decide(
            format!(
                "k = {} lies on the quadric of {}: kᵀ Q k = 0",
                fmt_vec(k),
                self.map
            ),
            helpers::negligible(&r, mag),
            F::EXACT,
            || fmt_scalar(&r),
        )];
        out.push(Certificate::decide(
            "the spanning points a, b of the projecting line are independent",
            helpers::rank(&[a.to_vec(), b.to_vec()]) == 2,
            F::EXACT,
            || format!("a = {}, b = {}", fmt_vec(a), fmt_vec(b)),
        ));
        let ok = self.images.iter().all(|v| parallel_or_zero(v, k))
            && !self.images.iter().all(|v| helpers::is_zero_vec(v));
        out.push(Certificate::decide(
            "F(λa + μb) = λ²F(a) + 2λμF̂(a, b) + μ²F(b) ∥ k identically in λ, μ: the line is the projecting line over k",
            ok,
            F::EXACT,
            || {
                format!(
                    "F(a) = {}, F̂(a, b) = {}, F(b) = {}",
                    fmt_vec(&self.images[0]),
                    fmt_vec(&self.images[1]),
                    fmt_vec(&self.images[2])
                )
            },
        ));
        let on_line = |x: &Hom<F>| helpers::rank(&[a.to_vec(), b.to_vec(), x.to_vec()]) == 2;
        if let Some(p) = &self.through {
            out.push(Certificate::decide(
                format!("the given point {} lies on the projecting line", fmt_vec(p)),
                on_line(p),
                F::EXACT,
                || fmt_vec(p),
            ));
        }
        if let Some((which, x)) = &self.plane_point {
            let (name, in_plane) = match which {
                PlaneInverse::Sigma => (
                    "σ⁻¹(k) = (k0−k3, k1, k2, 0) lies in P: p3 = 0 and on the projecting line",
                    x[3].is_zero()
                        || !F::EXACT && x[3].to_f64().abs() <= 1e-12 * helpers::magnitude(x),
                ),
                PlaneInverse::Tau => (
                    "τ⁻¹(k) = (k0, k1, k2, k0) lies in R: q3 = q0 and on the projecting line",
                    helpers::negligible(&(x[3].clone() - x[0].clone()), helpers::magnitude(x)),
                ),
            };
            out.push(Certificate::decide(
                name,
                in_plane && on_line(x),
                F::EXACT,
                || fmt_vec(x),
            ));
        }
        out
    }
}

/// The preimage quadric of the plane section `Φ ∩ π` (a circle on the sphere, a conic on
/// another quadric): `F⁻¹(Φ ∩ π) = {p : πᵀF(p) = 0} = {p : pᵀ(Σᵢ πᵢ Mᵢ)p = 0}`, the union
/// of the projecting lines over the section (docs/math/quadrics.md, "Preimage quadrics").
#[derive(Debug, Clone, PartialEq)]
pub struct PreimageQuadric<F> {
    /// The plane `π` (covector) of the section.
    pub plane: Hom<F>,
    /// The symmetric matrix `Σᵢ πᵢ Mᵢ`.
    pub matrix: Mat4<F>,
    /// Its affine type (from the signature, exact for exact scalars).
    pub kind: QuadricKind,
    /// For [`preimage_quadric_through`]: the conic through the three points, the image of
    /// a line of the preimage quadric.
    pub section: Option<Interpolant<F>>,
    polar: [[Hom<F>; 4]; 4],
}

/// The preimage quadric of the section of the projection's quadric by the plane `π`.
///
/// # Errors
/// [`QuadricError::ZeroPoint`], [`QuadricError::NotFinite`] for `π`;
/// [`QuadricError::Unsupported`] if `Σ πᵢ Mᵢ = 0`.
pub fn preimage_quadric<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    plane: &Hom<F>,
) -> Result<PreimageQuadric<F>, QuadricError> {
    check_point(plane, "the plane")?;
    let maps = proj.quadratic_map();
    let m = maps.matrices();
    let matrix: Mat4<F> = core::array::from_fn(|i| {
        core::array::from_fn(|j| {
            (0..4).fold(F::zero(), |acc, k| {
                acc + plane[k].clone() * m[k][i][j].clone()
            })
        })
    });
    let quadric = Quadric::from_matrix(matrix.clone())?;
    let e = |i: usize| {
        let mut v = helpers::zero4::<F>();
        v[i] = F::one();
        v
    };
    let polar = core::array::from_fn(|i| core::array::from_fn(|j| proj.polar(&e(i), &e(j))));
    Ok(PreimageQuadric {
        plane: plane.clone(),
        matrix,
        kind: quadric.kind(),
        section: None,
        polar,
    })
}

/// The preimage quadric of the section through three points of the quadric (a circle on
/// the sphere through three points), with the conic itself: the image of the line that
/// meets the three projecting lines (Jüttler's interpolation of lowest degree, `n = 1`).
///
/// # Errors
/// [`QuadricError::NotOnQuadric`]; [`QuadricError::Degenerate`] if the points are
/// collinear (no plane) or coincide; errors of [`preimage_quadric`] and of the
/// interpolation.
pub fn preimage_quadric_through<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    points: &[Hom<F>; 3],
) -> Result<PreimageQuadric<F>, QuadricError> {
    let q = proj.quadric();
    for (i, k) in points.iter().enumerate() {
        check_on_quadric(&q, k, &format!("point {i}"), &proj.name())?;
    }
    let ann = helpers::annihilator(points);
    let [plane] = <[Hom<F>; 1]>::try_from(ann).map_err(|_| {
        QuadricError::Degenerate(
            "the three points do not span a plane (they are collinear or coincide)".into(),
        )
    })?;
    let mut pq = preimage_quadric(proj, &plane)?;
    let params = [F::zero(), F::one() / F::from_i64(2), F::one()];
    let data: Vec<HermiteDatum<F>> = points
        .iter()
        .zip(params)
        .map(|(k, t)| HermiteDatum::point(t, k.clone()))
        .collect();
    pq.section = Some(interpolate_lowest_degree(proj, &data)?);
    Ok(pq)
}

impl<F: Scalar> Certified for PreimageQuadric<F> {
    /// `pᵀ M p ≡ πᵀF(p)` as a polynomial identity (every polar value
    /// `eᵢᵀ M eⱼ = πᵀF̂(eᵢ, eⱼ)`); with a section: the conic lies on the quadric and in the
    /// plane, and its preimage line lies on the preimage quadric.
    fn certify(&self) -> Vec<Certificate> {
        let mut bad = None;
        for i in 0..4 {
            for j in 0..4 {
                let rhs = helpers::dot(&self.plane, &self.polar[i][j]);
                let d = self.matrix[i][j].clone() - rhs;
                if !helpers::negligible(&d, helpers::magnitude(&self.plane)) {
                    bad = Some(format!("entry ({i}, {j}) differs by {}", fmt_scalar(&d)));
                }
            }
        }
        let mut out = vec![Certificate::decide(
            "pᵀ M p ≡ πᵀF(p): M is the preimage of the plane section π ∩ Φ",
            bad.is_none(),
            F::EXACT,
            || bad.clone().unwrap_or_default(),
        )];
        if let Some(s) = &self.section {
            out.extend(s.certify());
            let y = s.curve();
            let in_plane = y
                .control_points()
                .all(|p| helpers::negligible(&helpers::dot(&self.plane, p), helpers::magnitude(p)));
            out.push(Certificate::decide(
                "the conic lies in the plane π",
                in_plane,
                F::EXACT,
                || "a control point is off the plane".into(),
            ));
            out.push(certify_curve_on_quadric(
                s.preimage(),
                &self.matrix,
                "the preimage line of the conic lies on the preimage quadric: pᵀ M p ≡ 0",
            ));
        }
        out
    }
}

/// The image of a curve or patch under the collineation `X ↦ A X`, with the image of a
/// quadric `Q' = A⁻ᵀ Q A⁻¹` (so `Xᵀ Q X = 0 ⇔ (AX)ᵀ Q' (AX) = 0`).
#[derive(Debug, Clone, PartialEq)]
pub struct CollineationImage<F, C> {
    /// The matrix `A`.
    pub matrix: Mat4<F>,
    /// `det A ≠ 0`.
    pub det: F,
    /// The given curve or patch.
    pub original: C,
    /// Its image.
    pub image: C,
    /// The given quadric `Q` and its image `Q'`.
    pub quadrics: Option<(Mat4<F>, Mat4<F>)>,
}

fn rows<F: Scalar>(a: &Mat4<F>) -> Vec<Vec<F>> {
    a.iter().map(|r| r.to_vec()).collect()
}

fn regular<F: Scalar>(a: &Mat4<F>) -> Result<(F, Mat4<F>), QuadricError> {
    if !helpers::all_finite(&a.concat()) {
        return Err(QuadricError::NotFinite("the collineation matrix".into()));
    }
    let det = helpers::det(&rows(a));
    let inv = helpers::inverse4(a).ok_or_else(|| {
        QuadricError::Degenerate(format!(
            "the collineation matrix is singular: det A = {}",
            fmt_scalar(&det)
        ))
    })?;
    Ok((det, inv))
}

fn image_quadric<F: Scalar>(q: &Mat4<F>, inv: &Mat4<F>) -> Mat4<F> {
    helpers::mat_mul(&helpers::transpose(inv), &helpers::mat_mul(q, inv))
}

/// With a quadric `Q` that the object lies on (`on` certifies it), `(Q, Q')` for the
/// image quadric `Q' = A⁻ᵀ Q A⁻¹` (`inv = A⁻¹`); `None` without a quadric.
///
/// # Errors
/// [`QuadricError::NotOnQuadric`] naming `what` and `describe()` if `on` fails.
#[allow(clippy::type_complexity)]
fn quadric_and_image<F: Scalar>(
    quadric: Option<&Mat4<F>>,
    inv: &Mat4<F>,
    on: impl FnOnce(&Mat4<F>) -> Certificate,
    what: &str,
    describe: impl FnOnce() -> String,
) -> Result<Option<(Mat4<F>, Mat4<F>)>, QuadricError> {
    let Some(q) = quadric else {
        return Ok(None);
    };
    let c = on(q);
    if !c.holds {
        return Err(QuadricError::NotOnQuadric {
            what: what.into(),
            point: describe(),
            quadric: "the given quadric".into(),
            residual: c.residual.unwrap_or_default(),
        });
    }
    Ok(Some((q.clone(), image_quadric(q, inv))))
}

/// The image of a space curve (homogeneous `(w, wx, wy, wz)`) under `X ↦ A X`; with a
/// quadric `Q` that the curve lies on, the image quadric `Q'`.
///
/// # Errors
/// [`QuadricError::Dimension`] unless the curve lies in 3-space;
/// [`QuadricError::Degenerate`] if `det A = 0`; [`QuadricError::NotOnQuadric`] if the curve
/// is not on the given quadric.
pub fn collineation_curve<F: Scalar>(
    a: &Mat4<F>,
    curve: &BezierCurve<F>,
    quadric: Option<&Mat4<F>>,
) -> Result<CollineationImage<F, BezierCurve<F>>, QuadricError> {
    if curve.dim() != 3 {
        return Err(QuadricError::Dimension(format!(
            "the curve must lie in 3-space, it has dimension {}",
            curve.dim()
        )));
    }
    let (det, inv) = regular(a)?;
    let quadrics = quadric_and_image(
        quadric,
        &inv,
        |q| certify_curve_on_quadric(curve, q, ""),
        "the curve",
        || format!("of degree {}", curve.degree()),
    )?;
    let image = curve.apply_projective(&rows(a))?;
    Ok(CollineationImage {
        matrix: a.clone(),
        det,
        original: curve.clone(),
        image,
        quadrics,
    })
}

/// As [`collineation_curve`] for a tensor-product patch.
///
/// # Errors
/// As [`collineation_curve`].
pub fn collineation_patch<F: Scalar>(
    a: &Mat4<F>,
    patch: &BezierPatch<F>,
    quadric: Option<&Mat4<F>>,
) -> Result<CollineationImage<F, BezierPatch<F>>, QuadricError> {
    if patch.dim() != 3 {
        return Err(QuadricError::Dimension(format!(
            "the patch must lie in 3-space, it has dimension {}",
            patch.dim()
        )));
    }
    let (det, inv) = regular(a)?;
    let quadrics = quadric_and_image(
        quadric,
        &inv,
        |q| certify_patch_on_quadric(patch, q, ""),
        "the patch",
        || format!("of bidegree {:?}", patch.degree()),
    )?;
    let image = patch.apply_projective(&rows(a))?;
    Ok(CollineationImage {
        matrix: a.clone(),
        det,
        original: patch.clone(),
        image,
        quadrics,
    })
}

fn certify_quadric_transfer<F: Scalar>(
    a: &Mat4<F>,
    quadrics: &Option<(Mat4<F>, Mat4<F>)>,
) -> Option<Certificate> {
    let (q, q2) = quadrics.as_ref()?;
    let back = helpers::mat_mul(&helpers::transpose(a), &helpers::mat_mul(q2, a));
    let ok = if F::EXACT {
        &back == q
    } else {
        helpers::mats_close(&back, q)
    };
    Some(Certificate::decide(
        "Aᵀ Q' A = Q: the image quadric Q' = A⁻ᵀ Q A⁻¹",
        ok,
        F::EXACT,
        || "Aᵀ Q' A differs from Q".into(),
    ))
}

impl<F: Scalar> Certified for CollineationImage<F, BezierCurve<F>> {
    /// `Y(t) ≡ A X(t)` for the coordinate polynomials; `Aᵀ Q' A = Q` and `Yᵀ Q' Y ≡ 0`.
    fn certify(&self) -> Vec<Certificate> {
        let x = self.original.coordinate_polys();
        let y = self.image.coordinate_polys();
        let ok = (0..4).all(|i| {
            let ax = (0..4).fold(Poly::zero(), |acc: Poly<F>, j| {
                acc + x[j].scale(&self.matrix[i][j])
            });
            let d = ax - y[i].clone();
            d.coeffs()
                .iter()
                .all(|c| helpers::negligible(c, helpers::magnitude(&self.matrix.concat())))
        });
        let mut out = vec![Certificate::decide(
            format!(
                "Y(t) ≡ A·X(t) for the homogeneous coordinates, det A = {} ≠ 0",
                fmt_scalar(&self.det)
            ),
            ok,
            F::EXACT,
            || "a coordinate polynomial differs".into(),
        )];
        out.extend(certify_quadric_transfer(&self.matrix, &self.quadrics));
        if let Some((_, q2)) = &self.quadrics {
            out.push(certify_curve_on_quadric(
                &self.image,
                q2,
                "the image curve lies on the image quadric: Yᵀ Q' Y ≡ 0",
            ));
        }
        out
    }
}

impl<F: Scalar> Certified for CollineationImage<F, BezierPatch<F>> {
    /// `Y(u, v) ≡ A X(u, v)` for the coordinate polynomials; `Aᵀ Q' A = Q` and
    /// `Yᵀ Q' Y ≡ 0`.
    fn certify(&self) -> Vec<Certificate> {
        let ok = match (
            self.original.coordinate_polys(),
            self.image.coordinate_polys(),
        ) {
            (Ok(x), Ok(y)) => (0..4).all(|i| {
                let ax = (0..4).fold(
                    rcagd_algebra::mpoly::MPoly::zero(2),
                    |acc: rcagd_algebra::mpoly::MPoly<F>, j| acc + x[j].scale(&self.matrix[i][j]),
                );
                let d = ax - y[i].clone();
                let ok = d.terms().all(|(_, c)| {
                    helpers::negligible(c, helpers::magnitude(&self.matrix.concat()))
                });
                ok
            }),
            _ => false,
        };
        let mut out = vec![Certificate::decide(
            format!(
                "Y(u, v) ≡ A·X(u, v) for the homogeneous coordinates, det A = {} ≠ 0",
                fmt_scalar(&self.det)
            ),
            ok,
            F::EXACT,
            || "a coordinate polynomial differs".into(),
        )];
        out.extend(certify_quadric_transfer(&self.matrix, &self.quadrics));
        if let Some((_, q2)) = &self.quadrics {
            out.push(certify_patch_on_quadric(
                &self.image,
                q2,
                "the image patch lies on the image quadric: Yᵀ Q' Y ≡ 0",
            ));
        }
        out
    }
}

/// The Miquel configuration of a biquadratic patch `y(u, v)` on a quadric (Jüttler
/// Satz 7; docs/math/quadrics.md, "Biquadratic sphere patches and the Miquel
/// configuration"): corners `p1 = y(0,0)`, `p2 = y(1,0)`, `p3 = y(1,1)`, `p4 = y(0,1)`,
/// the planes of the boundary conics `C12 (v = 0)`, `C23 (u = 1)`, `C34 (v = 1)`,
/// `C41 (u = 0)`, and the second intersection `qᵢ` of the two boundary conics at `pᵢ`.
#[derive(Debug, Clone, PartialEq)]
pub struct MiquelPoints<F> {
    /// `p1..p4`.
    pub corners: [Hom<F>; 4],
    /// The planes of `C12, C23, C34, C41`.
    pub planes: [Hom<F>; 4],
    /// `q1..q4` (`qᵢ = pᵢ` where the two conics touch).
    pub second: [Hom<F>; 4],
    /// `det[p1, q2, p3, q4]` and `det[q1, p2, q3, p4]` (points normalized to their first
    /// non-zero coordinate): both zero iff the configuration is Miquel.
    pub residuals: (F, F),
    /// The planes of the Miquel circles `p1 q2 p3 q4` and `q1 p2 q3 p4` where they exist.
    pub miquel_planes: [Option<Hom<F>>; 2],
    patch: BezierPatch<F>,
    quadric: Mat4<F>,
}

impl<F: Scalar> MiquelPoints<F> {
    /// `true` if both Miquel determinants vanish (exactly for exact scalars).
    pub fn is_miquel(&self) -> bool {
        helpers::negligible(&self.residuals.0, 1.0) && helpers::negligible(&self.residuals.1, 1.0)
    }
}

fn plane_of<F: Scalar>(pts: &[Hom<F>]) -> Option<Hom<F>> {
    let ann = helpers::annihilator(pts);
    (ann.len() == 1).then(|| ann.into_iter().next()).flatten()
}

/// The edges of a biquadratic net as control-point indices `(i, j)` (`i` along `u`).
const EDGES: [[(usize, usize); 3]; 4] = [
    [(0, 0), (1, 0), (2, 0)],
    [(2, 0), (2, 1), (2, 2)],
    [(2, 2), (1, 2), (0, 2)],
    [(0, 2), (0, 1), (0, 0)],
];

/// The Miquel points of a biquadratic patch on the quadric `Q`.
///
/// # Errors
/// [`QuadricError::Dimension`] unless the patch is biquadratic in 3-space;
/// [`QuadricError::NotOnQuadric`] if it is not on `Q` (exactly);
/// [`QuadricError::Degenerate`] if a boundary is a line (collinear edge control points) or
/// two boundary conics lie in one plane.
pub fn miquel_points<F: Scalar>(
    quadric: &Mat4<F>,
    patch: &BezierPatch<F>,
) -> Result<MiquelPoints<F>, QuadricError> {
    if patch.dim() != 3 || patch.degree() != (2, 2) {
        return Err(QuadricError::Dimension(format!(
            "a biquadratic patch in 3-space is needed, got bidegree {:?} in dimension {}",
            patch.degree(),
            patch.dim()
        )));
    }
    let c = certify_patch_on_quadric(patch, quadric, "");
    if !c.holds {
        return Err(QuadricError::NotOnQuadric {
            what: "the patch".into(),
            point: "(biquadratic)".into(),
            quadric: "the given quadric".into(),
            residual: c.residual.unwrap_or_default(),
        });
    }
    let cp = |(i, j): (usize, usize)| helpers::to_hom(patch.control_point(i, j));
    let corners: [Hom<F>; 4] = core::array::from_fn(|k| cp(EDGES[k][0]));
    let names = ["C12 (v = 0)", "C23 (u = 1)", "C34 (v = 1)", "C41 (u = 0)"];
    let mut planes = Vec::with_capacity(4);
    for (k, e) in EDGES.iter().enumerate() {
        let pts: Vec<Hom<F>> = e.iter().map(|&ij| cp(ij)).collect();
        planes.push(plane_of(&pts).ok_or_else(|| {
            QuadricError::Degenerate(format!(
                "the boundary {} is a straight line (its control points are collinear)",
                names[k]
            ))
        })?);
    }
    let planes: [Hom<F>; 4] = core::array::from_fn(|k| planes[k].clone());
    let mut second = Vec::with_capacity(4);
    for i in 0..4 {
        second.push(second_intersection(
            quadric,
            &corners[i],
            &planes[(i + 3) % 4],
            &planes[i],
        )?);
    }
    let second: [Hom<F>; 4] = core::array::from_fn(|k| second[k].clone());
    let residuals = miquel_residuals(&corners, &second);
    let miquel_planes = [
        plane_of(&[corners[0].clone(), second[1].clone(), corners[2].clone()]),
        plane_of(&[second[0].clone(), corners[1].clone(), second[2].clone()]),
    ];
    Ok(MiquelPoints {
        corners,
        planes,
        second,
        residuals,
        miquel_planes,
        patch: patch.clone(),
        quadric: quadric.clone(),
    })
}

impl<F: Scalar> Certified for MiquelPoints<F> {
    /// The patch on the quadric; each boundary conic in its plane (all three edge control
    /// points); each `qᵢ` on the quadric and on both planes through `pᵢ`. (Whether the
    /// configuration is Miquel is an answer, [`MiquelPoints::is_miquel`], not a
    /// certificate.)
    fn certify(&self) -> Vec<Certificate> {
        let mut out = vec![certify_patch_on_quadric(
            &self.patch,
            &self.quadric,
            "the patch lies on the quadric: Xᵀ Q X ≡ 0",
        )];
        let names = ["C12", "C23", "C34", "C41"];
        for (k, e) in EDGES.iter().enumerate() {
            let ok = e.iter().all(|&(i, j)| {
                let p = self.patch.control_point(i, j);
                helpers::negligible(&helpers::dot(&self.planes[k], p), helpers::magnitude(p))
            });
            out.push(Certificate::decide(
                format!(
                    "the boundary conic {} lies in the plane {}",
                    names[k],
                    fmt_vec(&self.planes[k])
                ),
                ok,
                F::EXACT,
                || "an edge control point is off the plane".into(),
            ));
        }
        for i in 0..4 {
            let q = &self.second[i];
            let (r, mag) = helpers::quad_form(&self.quadric, q);
            let ok = helpers::negligible(&r, mag)
                && [&self.planes[(i + 3) % 4], &self.planes[i]]
                    .iter()
                    .all(|pl| {
                        helpers::negligible(&helpers::dot(pl.as_slice(), q), helpers::magnitude(q))
                    });
            out.push(Certificate::decide(
                format!(
                    "q{} = {} lies on the quadric and on both boundary planes through p{}",
                    i + 1,
                    fmt_vec(q),
                    i + 1
                ),
                ok,
                F::EXACT,
                || fmt_scalar(&r),
            ));
        }
        out
    }
}

/// A curve on `H: h0h3 = h1h2` of prescribed degree `r + s` through given points at given
/// parameters, `y = u ⊗ v = (u0v0, u1v0, u0v1, u1v1)` with binary forms `u` (degree `r`)
/// and `v` (degree `s`) (Jüttler (8), (15): `ψ(q) = (q0, q1) ⊗ (q3, q2)`).
#[derive(Debug, Clone, PartialEq)]
pub struct PsiInterpolant<F> {
    /// Bernstein coefficients of `u = (q0, q1)`.
    pub u: Vec<[F; 2]>,
    /// Bernstein coefficients of `v = (q3, q2)`.
    pub v: Vec<[F; 2]>,
    /// Dimension of the solution space of `u` (of degree `r`).
    pub u_dimension: usize,
    /// Dimension of the solution space of `v` (of degree `s`).
    pub v_dimension: usize,
    /// The lowest degrees `(r_min, s_min)`.
    pub lowest: (usize, usize),
    /// The curve on `H`, degree `r + s`.
    pub curve: BezierCurve<F>,
    params: Vec<F>,
    points: Vec<Hom<F>>,
}

impl<F: Scalar> PsiInterpolant<F> {
    /// `(r, s)`.
    pub fn degrees(&self) -> (usize, usize) {
        (self.u.len() - 1, self.v.len() - 1)
    }
    /// Free parameters of the family of interpolants of these degrees (projectively):
    /// `(dim U − 1) + (dim V − 1)`.
    pub fn free_parameters(&self) -> usize {
        self.u_dimension + self.v_dimension - 2
    }
}

/// `true` if the binary form has no zero at the parameters and (exact scalars) its two
/// components are coprime of degree `r` (no base point: the degree is really `r`).
fn admissible<F: Scalar>(c: &[F], r: usize, params: &[F]) -> bool {
    let nonzero = params.iter().all(|t| {
        let w = binary_eval(c, r, t);
        !helpers::all_negligible(&w, helpers::magnitude(c))
    });
    if !nonzero || !F::EXACT {
        return nonzero;
    }
    let comp = |k: usize| -> Poly<F> {
        let b: Vec<F> = (0..=r).map(|j| c[2 * j + k].clone()).collect();
        bernstein::from_bernstein(&b)
    };
    let (a, b) = (comp(0), comp(1));
    let full = a.degree() == Some(r) || b.degree() == Some(r);
    let g = a.gcd(&b);
    full && g.degree().unwrap_or(0) == 0 && !(a.is_zero() && b.is_zero())
}

/// All > 0 or all < 0.
fn one_sign<'a, F: Scalar + 'a>(mut xs: impl Iterator<Item = &'a F>) -> bool {
    let z = F::zero();
    let first = xs.next();
    match first {
        Some(f) if *f > z => xs.all(|x| *x > z),
        Some(f) if *f < z => xs.all(|x| *x < z),
        _ => false,
    }
}

fn lowest_degree<F: Scalar>(targets: &[[F; 2]], params: &[F]) -> Option<usize> {
    (0..=targets.len()).find(|&r| {
        let basis = binary_space(targets, params, r);
        pick_member(&basis, 1, |c| admissible(c, r, params)).is_some()
    })
}

/// Interpolation on `H` by `ψ` of total degree `degree = r + s`, through `points` at
/// `params`; `u_degree` fixes `r` (default: the extra degree over the lowest one split as
/// evenly as possible, `u` first, else the nearest split that admits coprime factors:
/// the solutions of degree `r_min + 1` may all be multiples of the lowest one). The member of each solution space is the first one
/// (moment-curve combination) whose components are coprime of full degree and do not
/// vanish at the parameters.
///
/// # Errors
/// [`QuadricError::Dimension`], [`QuadricError::NotOnQuadric`],
/// [`QuadricError::RepeatedParameters`], [`QuadricError::RepeatedPoints`];
/// [`QuadricError::NoInterpolant`] if `degree` is below the lowest degree `r_min + s_min`
/// (named in the message) or `u_degree` is out of range.
pub fn psi_interpolate<F: Scalar>(
    points: &[Hom<F>],
    params: &[F],
    degree: usize,
    u_degree: Option<usize>,
) -> Result<PsiInterpolant<F>, QuadricError> {
    let (us, vs) = checked_segre_factors(points, params)?;
    let none = |what: &str| QuadricError::NoInterpolant {
        degree,
        reason: format!("no admissible {what} factor"),
    };
    let r_min = lowest_degree(&us, params).ok_or_else(|| none("u"))?;
    let s_min = lowest_degree(&vs, params).ok_or_else(|| none("v"))?;
    if degree < r_min + s_min {
        return Err(QuadricError::NoInterpolant {
            degree,
            reason: format!(
                "the lowest degree through these points is {} = {r_min} (u) + {s_min} (v)",
                r_min + s_min
            ),
        });
    }
    let extra = degree - r_min - s_min;
    let candidates: Vec<usize> = match u_degree {
        Some(r) if r < r_min || r > degree - s_min => {
            return Err(QuadricError::NoInterpolant {
                degree,
                reason: format!(
                    "the degree of u must lie in [{r_min}, {}] (lowest u degree {r_min}, lowest v degree {s_min})",
                    degree - s_min
                ),
            })
        }
        Some(r) => vec![r],
        None => {
            // the extra degree split evenly (u first), then the other splits by distance
            let preferred = r_min + extra.div_ceil(2);
            let mut c: Vec<usize> = (r_min..=degree - s_min).collect();
            c.sort_by_key(|&r| (r.abs_diff(preferred), r < preferred));
            c
        }
    };
    // prefer members whose weight component (u0 resp. v0) has Bernstein coefficients of
    // one sign (then the weight u0·v0 of y has no zero on [0, 1]: exportable pieces)
    let choose = |basis: &[Vec<F>], deg: usize| {
        pick_member(basis, deg.max(1) * 2, |c| {
            admissible(c, deg, params) && one_sign(c.iter().step_by(2))
        })
        .or_else(|| pick_member(basis, deg.max(1) * 2, |c| admissible(c, deg, params)))
    };
    let mut found = None;
    for &r in &candidates {
        let s = degree - r;
        let ubasis = binary_space(&us, params, r);
        let vbasis = binary_space(&vs, params, s);
        if let (Some(u), Some(v)) = (choose(&ubasis, r), choose(&vbasis, s)) {
            found = Some((r, s, u, v, ubasis.len(), vbasis.len()));
            break;
        }
    }
    let (_, _, u, v, u_dimension, v_dimension) = found.ok_or_else(|| QuadricError::NoInterpolant {
        degree,
        reason: format!(
            "no split n = r + s with u of degree r ∈ {candidates:?} and v of degree s whose components are coprime (every solution of these degrees is a lower one times a common factor)"
        ),
    })?;
    let u: Vec<[F; 2]> = u.chunks(2).map(|p| [p[0].clone(), p[1].clone()]).collect();
    let v: Vec<[F; 2]> = v.chunks(2).map(|p| [p[0].clone(), p[1].clone()]).collect();
    let pts = segre_product(&u, &v);
    let curve = BezierCurve::from_homogeneous(pts.into_iter().map(|p| p.to_vec()).collect())?;
    Ok(PsiInterpolant {
        u,
        v,
        u_dimension,
        v_dimension,
        lowest: (r_min, s_min),
        curve,
        params: params.to_vec(),
        points: points.to_vec(),
    })
}

impl<F: Scalar> Certified for PsiInterpolant<F> {
    /// The curve lies on `H`; `y(tᵢ) ∥ kᵢ`; `y = u ⊗ v` (its coordinate polynomials are
    /// the products of those of `u` and `v`), and `u`, `v` are coprime of full degree, so
    /// `deg y = r + s`.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = super::paraboloid::certify_interpolant_on_h(
            &self.curve,
            &self.params,
            &self.points,
            "the interpolant lies on H: h0h3 − h1h2 ≡ 0",
        );
        let comp = |w: &[[F; 2]], k: usize| -> Poly<F> {
            bernstein::from_bernstein(&w.iter().map(|p| p[k].clone()).collect::<Vec<_>>())
        };
        let (u0, u1, v0, v1) = (
            comp(&self.u, 0),
            comp(&self.u, 1),
            comp(&self.v, 0),
            comp(&self.v, 1),
        );
        let y = self.curve.coordinate_polys();
        let want = [
            u0.clone() * v0.clone(),
            u1.clone() * v0,
            u0 * v1.clone(),
            u1 * v1,
        ];
        let ok = y.iter().zip(&want).all(|(a, b)| {
            (a.clone() - b.clone())
                .coeffs()
                .iter()
                .all(|c| helpers::negligible(c, helpers::magnitude(self.curve.coords())))
        });
        out.push(Certificate::decide(
            "y ≡ u ⊗ v = (u0v0, u1v0, u0v1, u1v1)",
            ok,
            F::EXACT,
            || "a coordinate differs from the Segre product".into(),
        ));
        let (r, s) = self.degrees();
        let flat = |w: &[[F; 2]]| w.iter().flat_map(|p| p.iter().cloned()).collect::<Vec<F>>();
        out.push(Certificate::decide(
            format!(
                "u and v are coprime of full degrees {r} and {s}: deg y = {}",
                r + s
            ),
            admissible(&flat(&self.u), r, &self.params)
                && admissible(&flat(&self.v), s, &self.params),
            F::EXACT,
            || "a common factor or a zero at a parameter".into(),
        ));
        out
    }
}
