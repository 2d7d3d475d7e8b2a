//! Images of rational Bézier curves and tensor-product patches under a generalized
//! stereographic projection, and preimages of half degree.
//!
//! **Polar-form rule** (docs/math/quadrics.md, "Curves and patches under δ"). For a quadratic map `F` with polar form `F̂`
//! and a curve `x(t) = Σ Bᵢⁿ(t) bᵢ`,
//! `F(x(t)) = Σₖ Bₖ²ⁿ(t) dₖ`, `dₖ = Σ_{i+j=k} C(n,i)C(n,j)/C(2n,k) · F̂(bᵢ, bⱼ)`,
//! because `Bᵢⁿ Bⱼⁿ = C(n,i)C(n,j)/C(2n,i+j) · B_{i+j}²ⁿ`. For a patch of bidegree `(m,n)`
//! the rule is applied in each direction:
//! `d_kl = Σ [C(m,i)C(m,i')/C(2m,k)]·[C(n,j)C(n,j')/C(2n,l)] · F̂(c_ij, c_i'j')`.
//! The same rule with the quadric's bilinear form gives the Bernstein coefficients of
//! `Xᵀ Q X` along the image, which all vanish exactly: that is the certificate.
//!
//! **Preimages.** A curve `y` of degree `2n` on the quadric is `F(x)` for some `x` of
//! degree `n` (Jüttler Satz 1, verified for curves; for patches the claim is unverified,
//! docs/math/quadrics.md, Errata J3, so here it is decided case by case). `x` is found by Jüttler's linear
//! problem: at `4n+1` distinct parameters `x(tₛ)` must lie on the fibre over `y(tₛ)`.
//! Then every minor of `[F(x), y]` (degree `4n`) vanishes at `4n+1` points, so
//! `F(x) ∥ y` identically; whether `F(x) = c·y` with a constant `c` is then checked
//! exactly. On a `(4m+1)×(4n+1)` grid the same argument works for patches.

use super::helpers::{self, binom, fmt_scalar, fmt_vec, nodes, to_hom};
use super::{GeneralizedProjection, Hom, Mat4, QuadricError};
use crate::Certified;
use rcagd_algebra::{Certificate, Poly, Scalar};
use rcagd_geom::{BezierCurve, BezierPatch};

/// The control points of a curve in 3-space as homogeneous 4-vectors.
pub(crate) fn curve_points<F: Scalar>(curve: &BezierCurve<F>) -> Result<Vec<Hom<F>>, QuadricError> {
    if curve.dim() != 3 {
        return Err(QuadricError::Dimension(format!(
            "the curve must lie in 3-space (homogeneous points of length 4), it has dimension {}",
            curve.dim()
        )));
    }
    let pts: Vec<Hom<F>> = curve.control_points().map(to_hom).collect();
    if !pts.iter().all(|p| helpers::all_finite(p)) {
        return Err(QuadricError::NotFinite("a control point".into()));
    }
    Ok(pts)
}

/// The control net of a patch in 3-space, `net[i][j]`.
pub(crate) fn patch_net<F: Scalar>(
    patch: &BezierPatch<F>,
) -> Result<Vec<Vec<Hom<F>>>, QuadricError> {
    if patch.dim() != 3 {
        return Err(QuadricError::Dimension(format!(
            "the patch must lie in 3-space (homogeneous points of length 4), it has dimension {}",
            patch.dim()
        )));
    }
    let (m, n) = patch.degree();
    let net: Vec<Vec<Hom<F>>> = (0..=m)
        .map(|i| (0..=n).map(|j| to_hom(patch.control_point(i, j))).collect())
        .collect();
    if !net.iter().flatten().all(|p| helpers::all_finite(p)) {
        return Err(QuadricError::NotFinite("a control point".into()));
    }
    Ok(net)
}

/// The polar-form rule along one direction: `dₖ = Σ_{i+j=k} C(n,i)C(n,j)/C(2n,k)·f(bᵢ, bⱼ)`
/// for a symmetric bilinear `f` with values in `F^len`.
pub(crate) fn polar_rule_curve<F: Scalar, T>(
    b: &[T],
    len: usize,
    f: &dyn Fn(&T, &T) -> Vec<F>,
) -> Vec<Vec<F>> {
    let n = b.len().saturating_sub(1);
    let mut out = vec![vec![F::zero(); len]; 2 * n + 1];
    for i in 0..=n {
        for j in i..=n {
            let k = i + j;
            let mut w = binom::<F>(n, i) * binom::<F>(n, j) / binom::<F>(2 * n, k);
            if i != j {
                w *= F::from_i64(2);
            }
            let v = f(&b[i], &b[j]);
            for (o, x) in out[k].iter_mut().zip(v) {
                *o += w.clone() * x;
            }
        }
    }
    out
}

/// The polar-form rule for a net of bidegree `(m, n)` (docs/math/quadrics.md, "Curves and patches under δ").
pub(crate) fn polar_rule_patch<F: Scalar, T>(
    c: &[Vec<T>],
    len: usize,
    f: &dyn Fn(&T, &T) -> Vec<F>,
) -> Vec<Vec<Vec<F>>> {
    let m = c.len().saturating_sub(1);
    let n = c.first().map_or(0, |r| r.len().saturating_sub(1));
    let mut out = vec![vec![vec![F::zero(); len]; 2 * n + 1]; 2 * m + 1];
    let wu: Vec<Vec<F>> = (0..=m)
        .map(|i| {
            (0..=m)
                .map(|i2| binom::<F>(m, i) * binom::<F>(m, i2) / binom::<F>(2 * m, i + i2))
                .collect()
        })
        .collect();
    let wv: Vec<Vec<F>> = (0..=n)
        .map(|j| {
            (0..=n)
                .map(|j2| binom::<F>(n, j) * binom::<F>(n, j2) / binom::<F>(2 * n, j + j2))
                .collect()
        })
        .collect();
    let idx: Vec<(usize, usize)> = (0..=m).flat_map(|i| (0..=n).map(move |j| (i, j))).collect();
    for (a, &(i, j)) in idx.iter().enumerate() {
        for &(i2, j2) in &idx[a..] {
            let mut w = wu[i][i2].clone() * wv[j][j2].clone();
            if (i, j) != (i2, j2) {
                w *= F::from_i64(2);
            }
            let v = f(&c[i][j], &c[i2][j2]);
            for (o, x) in out[i + i2][j + j2].iter_mut().zip(v) {
                *o += w.clone() * x;
            }
        }
    }
    out
}

/// The rows of a 4×4 matrix, for `rcagd_geom::certify`.
fn rows<F: Scalar>(q: &Mat4<F>) -> Vec<Vec<F>> {
    q.iter().map(|r| r.to_vec()).collect()
}

/// Certifies `Xᵀ Q X ≡ 0` along a curve: every Bernstein coefficient of the form (degree
/// `2·deg`) vanishes exactly (`rcagd_geom::certify::curve_on_quadric`).
pub fn certify_curve_on_quadric<F: Scalar>(
    curve: &BezierCurve<F>,
    q: &Mat4<F>,
    property: &str,
) -> Certificate {
    crate::certs::curve_on_quadric(curve, &rows(q), property)
        .unwrap_or_else(|e| Certificate::fails(property, e.to_string(), F::EXACT))
}

/// Certifies `Xᵀ Q X ≡ 0` on a patch (all Bernstein coefficients of bidegree `(2m, 2n)`,
/// `rcagd_geom::certify::patch_on_quadric`).
pub fn certify_patch_on_quadric<F: Scalar>(
    patch: &BezierPatch<F>,
    q: &Mat4<F>,
    property: &str,
) -> Certificate {
    crate::certs::patch_on_quadric(patch, &rows(q), property)
        .unwrap_or_else(|e| Certificate::fails(property, e.to_string(), F::EXACT))
}

/// The image of a curve: `F(x)` of degree `2n` (docs/math/quadrics.md, "Curves and patches under δ").
#[derive(Debug, Clone, PartialEq)]
pub struct ImageCurve<F> {
    name: String,
    quadric: Mat4<F>,
    preimage: BezierCurve<F>,
    image: BezierCurve<F>,
    evaluator: Vec<Mat4<F>>,
}

impl<F: Scalar> ImageCurve<F> {
    /// The curve `x` in `E³` (degree `n`).
    pub fn preimage(&self) -> &BezierCurve<F> {
        &self.preimage
    }
    /// The curve `F(x)` on the quadric (degree `2n`).
    pub fn image(&self) -> &BezierCurve<F> {
        &self.image
    }
    /// The image, consumed.
    pub fn into_image(self) -> BezierCurve<F> {
        self.image
    }
    /// The matrix of the target quadric.
    pub fn quadric(&self) -> &Mat4<F> {
        &self.quadric
    }
    fn map_point(&self, p: &Hom<F>) -> Hom<F> {
        [0, 1, 2, 3].map(|k| helpers::bilinear(&self.evaluator[k], p, p))
    }
}

impl<F: Scalar> Certified for ImageCurve<F> {
    /// `Xᵀ Q X ≡ 0` (exact Bernstein coefficients) and `y(t) ≡ F(x(t))` (both sides of
    /// degree ≤ `2n`, equal at `2n+1` parameters, hence identical).
    fn certify(&self) -> Vec<Certificate> {
        let on = certify_curve_on_quadric(
            &self.image,
            &self.quadric,
            &format!("the image lies on the quadric of {}: Xᵀ Q X ≡ 0", self.name),
        );
        let n2 = self.image.degree();
        let mut bad = None;
        for t in nodes::<F>(n2) {
            let y = helpers::eval_curve(&self.image, &t);
            let fx = self.map_point(&helpers::eval_curve(&self.preimage, &t));
            let scale = helpers::magnitude(&y).max(helpers::magnitude(&fx));
            if !helpers::all_negligible(&helpers::sub4(&y, &fx), scale) {
                bad = Some((t, y, fx));
                break;
            }
        }
        let prop = format!(
            "Σ dₖ Bₖ^{n2}(t) ≡ F(Σ bᵢ Bᵢ^{}(t)) (polar-form rule)",
            self.preimage.degree()
        );
        let agree = match bad {
            None => Certificate::holds(prop, F::EXACT),
            Some((t, y, fx)) => Certificate::fails(
                prop,
                format!(
                    "at t = {}: {} ≠ {}",
                    fmt_scalar(&t),
                    fmt_vec(&y),
                    fmt_vec(&fx)
                ),
                F::EXACT,
            ),
        };
        vec![on, agree]
    }
}

/// The image of a tensor-product patch: `F(x)` of bidegree `(2m, 2n)` (docs/math/quadrics.md, "Curves and patches under δ").
#[derive(Debug, Clone, PartialEq)]
pub struct ImagePatch<F> {
    name: String,
    quadric: Mat4<F>,
    preimage: BezierPatch<F>,
    image: BezierPatch<F>,
    evaluator: Vec<Mat4<F>>,
}

impl<F: Scalar> ImagePatch<F> {
    /// The patch `x` in `E³` (bidegree `(m, n)`).
    pub fn preimage(&self) -> &BezierPatch<F> {
        &self.preimage
    }
    /// The patch `F(x)` on the quadric (bidegree `(2m, 2n)`).
    pub fn image(&self) -> &BezierPatch<F> {
        &self.image
    }
    /// The image, consumed.
    pub fn into_image(self) -> BezierPatch<F> {
        self.image
    }
    /// The matrix of the target quadric.
    pub fn quadric(&self) -> &Mat4<F> {
        &self.quadric
    }
}

impl<F: Scalar> Certified for ImagePatch<F> {
    /// `Xᵀ Q X ≡ 0` (exact Bernstein coefficients) and `y(u,v) ≡ F(x(u,v))`: the
    /// Bernstein coefficients of bidegree `(2m, 2n)` of each quadratic form
    /// `F_k(x(u, v)) = x(u, v)ᵀ E_k x(u, v)` (products of the preimage's coordinate
    /// polynomials, fraction-free) equal the image's control coordinates — a polynomial
    /// identity, checked coefficient by coefficient (for `f64` relative to their size).
    fn certify(&self) -> Vec<Certificate> {
        let on = certify_patch_on_quadric(
            &self.image,
            &self.quadric,
            &format!(
                "the image patch lies on the quadric of {}: Xᵀ Q X ≡ 0",
                self.name
            ),
        );
        let prop = "Σ d_kl B_k B_l ≡ F(Σ c_ij B_i B_j) (polar-form rule in both directions)";
        let forms: Result<Vec<Vec<F>>, _> = self
            .evaluator
            .iter()
            .map(|e| self.preimage.quadratic_form(&rows(e)))
            .collect();
        let agree = match forms {
            Err(e) => Certificate::fails(prop, e.to_string(), F::EXACT),
            Ok(fx) => {
                let coords = self.image.coords();
                let d = self.image.dim() + 1;
                let scale = helpers::magnitude(coords)
                    .max(fx.iter().map(|f| helpers::magnitude(f)).fold(1.0, f64::max));
                let bad = fx.iter().enumerate().find_map(|(k, f)| {
                    f.iter().enumerate().find_map(|(p, v)| {
                        let y = coords.get(p * d + k)?;
                        let diff = [y.clone() - v.clone()];
                        (!helpers::all_negligible(&diff, scale)).then_some((k, p))
                    })
                });
                let len_ok = fx.iter().all(|f| f.len() * d == coords.len());
                match (bad, len_ok) {
                    (None, true) => Certificate::holds(prop, F::EXACT),
                    (None, false) => Certificate::fails(
                        prop,
                        "the image's bidegree is not twice the preimage's".to_string(),
                        F::EXACT,
                    ),
                    (Some((k, p)), _) => Certificate::fails(
                        prop,
                        format!("coordinate {k} differs at Bernstein coefficient {p}"),
                        F::EXACT,
                    ),
                }
            }
        };
        vec![on, agree]
    }
}

/// The image of a rational Bézier curve of degree `n` in `E³` under `proj`: a curve of
/// degree `2n` on the quadric, by the polar-form rule (docs/math/quadrics.md, "Curves and patches under δ"). For δ a line that is
/// not a projecting line maps to a circle.
///
/// The result may be reducible: if `x` has a factor acting along the fibres the
/// components share a common factor (docs/math/quadrics.md, "Curves and patches under δ"); it is not removed here.
///
/// # Errors
/// [`QuadricError::Dimension`] if the curve is not in 3-space; [`QuadricError::Degenerate`]
/// if the image vanishes identically (the curve lies in the exceptional set).
pub fn curve_image<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    curve: &BezierCurve<F>,
) -> Result<ImageCurve<F>, QuadricError> {
    let b = curve_points(curve)?;
    let d = polar_rule_curve::<F, Hom<F>>(&b, 4, &|x, y| proj.polar(x, y).to_vec());
    let scale = b
        .iter()
        .map(|p| helpers::magnitude(p))
        .fold(1.0, f64::max)
        .powi(2);
    if d.iter().all(|p| helpers::all_negligible(p, scale)) {
        return Err(QuadricError::Degenerate(format!(
            "the image of the curve under {} vanishes identically: the curve lies in the exceptional set",
            proj.name()
        )));
    }
    let image = BezierCurve::from_homogeneous(d)?;
    Ok(ImageCurve {
        name: proj.name(),
        quadric: proj.quadric(),
        preimage: curve.clone(),
        image,
        evaluator: proj.quadratic_map().matrices().to_vec(),
    })
}

/// The image of a tensor-product patch of bidegree `(m, n)` under `proj`: bidegree
/// `(2m, 2n)` (docs/math/quadrics.md, "Curves and patches under δ"). A bilinear patch gives a biquadratic patch whose edges are
/// conics (circles on the sphere).
///
/// # Errors
/// As [`curve_image`].
pub fn patch_image<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    patch: &BezierPatch<F>,
) -> Result<ImagePatch<F>, QuadricError> {
    let c = patch_net(patch)?;
    let d = polar_rule_patch::<F, Hom<F>>(&c, 4, &|x, y| proj.polar(x, y).to_vec());
    let scale = c
        .iter()
        .flatten()
        .map(|p| helpers::magnitude(p))
        .fold(1.0, f64::max)
        .powi(2);
    if d.iter()
        .flatten()
        .all(|p| helpers::all_negligible(p, scale))
    {
        return Err(QuadricError::Degenerate(format!(
            "the image of the patch under {} vanishes identically",
            proj.name()
        )));
    }
    let image = BezierPatch::from_homogeneous(d)?;
    Ok(ImagePatch {
        name: proj.name(),
        quadric: proj.quadric(),
        preimage: patch.clone(),
        image,
        evaluator: proj.quadratic_map().matrices().to_vec(),
    })
}

/// A candidate preimage: coefficients, image net, factor.
type PatchCandidate<F> = (Vec<F>, Vec<Vec<Vec<F>>>, F);

/// A preimage of half degree: `F(x) = c·y` for the given curve or patch `y`.
#[derive(Debug, Clone, PartialEq)]
pub struct Preimage<F, C> {
    /// The given curve or patch on the quadric.
    pub given: C,
    /// The preimage `x` (half degree).
    pub preimage: C,
    /// The constant `c ≠ 0` with `F(x) = c·y`.
    pub factor: F,
    /// `F(x)` by the polar-form rule.
    pub image: C,
}

fn ratio_check<F: Scalar>(image: &[Vec<F>], given: &[Vec<F>]) -> Result<F, String> {
    let scale_i = image
        .iter()
        .map(|p| helpers::magnitude(p))
        .fold(1.0, f64::max);
    let scale_g = given
        .iter()
        .map(|p| helpers::magnitude(p))
        .fold(1.0, f64::max);
    // pivot: largest given entry
    let mut piv: Option<(usize, usize)> = None;
    for (a, p) in given.iter().enumerate() {
        for (b, x) in p.iter().enumerate() {
            if helpers::negligible(x, scale_g) {
                continue;
            }
            match piv {
                Some((pa, pb)) if given[pa][pb].to_f64().abs() >= x.to_f64().abs() => {}
                _ => piv = Some((a, b)),
            }
            if F::EXACT {
                break;
            }
        }
        if F::EXACT && piv.is_some() {
            break;
        }
    }
    let Some((a, b)) = piv else {
        return Err("the given curve is zero".into());
    };
    let c = image[a][b].clone() / given[a][b].clone();
    if helpers::negligible(&c, scale_i / scale_g) {
        return Err("F(x) vanishes".into());
    }
    for (p, g) in image.iter().zip(given) {
        for (x, y) in p.iter().zip(g) {
            let r = x.clone() - c.clone() * y.clone();
            if !helpers::negligible(&r, scale_i) {
                return Err("F(x) is proportional to y only up to a non-constant factor (the given curve is reducible or of lower true degree)".into());
            }
        }
    }
    Ok(c)
}

/// Picks a member `Σ sʲ vⱼ` (moment-curve coefficients, `s = 0, 1, 2, …`) of the solution
/// space for which `accept` holds. If the members failing `accept` form a proper algebraic
/// subset of degree ≤ `deg` in the coefficients, one of the first `deg·(d−1)+1` values
/// of `s` works.
pub(crate) fn pick_member<F: Scalar>(
    basis: &[Vec<F>],
    deg: usize,
    accept: impl FnMut(&[F]) -> bool,
) -> Option<Vec<F>> {
    pick_member_indexed(basis, deg, accept).map(|(_, v)| v)
}

/// [`pick_member`] with the index of the candidate taken ([`member_candidate`]).
pub(crate) fn pick_member_indexed<F: Scalar>(
    basis: &[Vec<F>],
    deg: usize,
    mut accept: impl FnMut(&[F]) -> bool,
) -> Option<(usize, Vec<F>)> {
    let d = basis.len();
    if d == 0 {
        return None;
    }
    let tries = deg.max(1) * d.saturating_sub(1) + 2 + d;
    (0..tries + d)
        .find_map(|k| member_candidate(basis, deg, k).and_then(|v| accept(&v).then_some((k, v))))
}

/// The candidate number `k` of [`pick_member`]: `Σ sʲ basisⱼ` with `s = k` for the first
/// `deg·(d − 1) + 2 + d` candidates (an `f64` one scaled to unit size), then the basis
/// vectors one by one; `None` past the last.
pub(crate) fn member_candidate<F: Scalar>(
    basis: &[Vec<F>],
    deg: usize,
    k: usize,
) -> Option<Vec<F>> {
    let d = basis.len();
    let first = basis.first()?;
    let tries = deg.max(1) * d.saturating_sub(1) + 2 + d;
    if k >= tries {
        return basis.get(k - tries).cloned();
    }
    let s = F::from_i64(k as i64);
    let mut w = F::one();
    let mut v = vec![F::zero(); first.len()];
    for b in basis {
        for (o, x) in v.iter_mut().zip(b) {
            *o += w.clone() * x.clone();
        }
        w *= s.clone();
    }
    if !F::EXACT {
        // keep f64 members of unit size so that the tolerances stay meaningful
        let n = rcagd_algebra::Rational::try_from(helpers::magnitude(&v))
            .unwrap_or_else(|_| rcagd_algebra::Rational::from(1));
        let inv = F::one() / F::from_rational(&n);
        for x in v.iter_mut() {
            *x *= inv.clone();
        }
    }
    Some(v)
}

/// The rows `ν · Σ_j wⱼ x_j = 0` (unknowns `x_j ∈ F⁴` flattened) for covectors `ν`.
pub(crate) fn rows_for<F: Scalar>(weights: &[F], covectors: &[Hom<F>]) -> Vec<Vec<F>> {
    covectors
        .iter()
        .map(|nu| {
            let mut row = vec![F::zero(); 4 * weights.len()];
            for (j, w) in weights.iter().enumerate() {
                for c in 0..4 {
                    row[4 * j + c] = w.clone() * nu[c].clone();
                }
            }
            row
        })
        .collect()
}

/// The two equations "x(t) lies on the fibre over `k`", or `None` if `k = 0` (then the
/// condition is empty). Errors from the fibre are passed on.
fn fibre_rows<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    k: &Hom<F>,
    weights: &[F],
    scale: f64,
) -> Result<Option<Vec<Vec<F>>>, QuadricError> {
    if helpers::all_negligible(k, scale) {
        return Ok(None);
    }
    let [a, b] = proj.fibre(k)?;
    let nu = helpers::annihilator(&[a, b]);
    Ok(Some(rows_for(weights, &nu)))
}

/// A preimage of half degree of a curve on the quadric: `x` of degree `n` with
/// `F(x) = c·y` for the given `y` of degree `2n` (Jüttler Satz 1, linear problem of
/// docs/math/quadrics.md, "Interpolation on the sphere" with `4n+1` samples, see the module docs).
///
/// # Errors
/// [`QuadricError::NotOnQuadric`] (with the failing certificate) if `y` is not on the
/// quadric; [`QuadricError::NoPreimage`] for odd degree or when no `x` of degree `n`
/// exists (e.g. `y` is reducible); [`QuadricError::Dimension`].
pub fn curve_preimage<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    curve: &BezierCurve<F>,
) -> Result<Preimage<F, BezierCurve<F>>, QuadricError> {
    let y = curve_points(curve)?;
    let q = proj.quadric();
    let cert = certify_curve_on_quadric(curve, &q, "on quadric");
    if !cert.holds {
        return Err(QuadricError::NotOnQuadric {
            what: "the curve".into(),
            point: "".into(),
            quadric: proj.name(),
            residual: cert.residual.unwrap_or_default(),
        });
    }
    let deg = curve.degree();
    if deg % 2 == 1 {
        return Err(QuadricError::NoPreimage(format!(
            "the curve has odd degree {deg}; images under {} have even degree",
            proj.name()
        )));
    }
    let n = deg / 2;
    let needed = 4 * n + 1;
    let scale = y.iter().map(|p| helpers::magnitude(p)).fold(1.0, f64::max);
    let mut rows = Vec::new();
    let mut good = 0;
    for t in nodes::<F>(8 * n + 2) {
        if good >= needed {
            break;
        }
        let k = helpers::eval_curve(curve, &t);
        match fibre_rows(proj, &k, &helpers::bernstein(n, &t), scale) {
            Ok(Some(r)) => {
                rows.extend(r);
                good += 1;
            }
            Ok(None) => good += 1,
            Err(QuadricError::Exceptional { .. }) => {}
            Err(e) => return Err(e),
        }
    }
    if good < needed {
        return Err(QuadricError::NoPreimage(
            "too many samples at exceptional points".into(),
        ));
    }
    let basis = helpers::null_space(&rows, 4 * (n + 1));
    let given: Vec<Vec<F>> = y.iter().map(|p| p.to_vec()).collect();
    let mut found: Option<(Vec<F>, Vec<Vec<F>>, F)> = None;
    pick_member(&basis, 2, |v| {
        let x: Vec<Hom<F>> = v.chunks(4).map(to_hom).collect();
        let img = polar_rule_curve::<F, Hom<F>>(&x, 4, &|a, b| proj.polar(a, b).to_vec());
        match ratio_check(&img, &given) {
            Ok(c) => {
                found = Some((v.to_vec(), img, c));
                true
            }
            Err(_) => false,
        }
    });
    let Some((v, img, c)) = found else {
        return reducible_preimage(proj, curve, basis.len());
    };
    let pre = BezierCurve::from_homogeneous(v.chunks(4).map(|c| c.to_vec()).collect())?;
    Ok(Preimage {
        given: curve.clone(),
        preimage: pre,
        factor: c,
        image: BezierCurve::from_homogeneous(img)?,
    })
}

/// A preimage of half bidegree of a patch on the quadric: `x` of bidegree `(m, n)` with
/// `F(x) = c·y` for the given `y` of bidegree `(2m, 2n)`, decided exactly (Jüttler's
/// Satz 1 for surfaces is unverified, docs/math/quadrics.md, Errata J3: this function answers per patch).
///
/// # Errors
/// As [`curve_preimage`].
pub fn patch_preimage<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    patch: &BezierPatch<F>,
) -> Result<Preimage<F, BezierPatch<F>>, QuadricError> {
    let y = patch_net(patch)?;
    let q = proj.quadric();
    let cert = certify_patch_on_quadric(patch, &q, "on quadric");
    if !cert.holds {
        return Err(QuadricError::NotOnQuadric {
            what: "the patch".into(),
            point: "".into(),
            quadric: proj.name(),
            residual: cert.residual.unwrap_or_default(),
        });
    }
    let (dm, dn) = patch.degree();
    if dm % 2 == 1 || dn % 2 == 1 {
        return Err(QuadricError::NoPreimage(format!(
            "the patch has bidegree ({dm}, {dn}); images under {} have even bidegree",
            proj.name()
        )));
    }
    let (m, n) = (dm / 2, dn / 2);
    let scale = y
        .iter()
        .flatten()
        .map(|p| helpers::magnitude(p))
        .fold(1.0, f64::max);
    let unknowns = 4 * (m + 1) * (n + 1);
    // try a few grids; a grid fails only if it hits an exceptional point (cone vertex)
    let mut rows = None;
    'grids: for shift in 0..3i64 {
        let grid = |d: usize| -> Vec<F> {
            (0..=4 * d)
                .map(|i| {
                    F::from_i64(2 * i as i64 + shift) / F::from_i64(2 * (4 * d as i64 + 1) + shift)
                })
                .collect()
        };
        let (us, vs) = (grid(m), grid(n));
        let mut r = Vec::new();
        for u in &us {
            let bu = helpers::bernstein(m, u);
            for v in &vs {
                let bv = helpers::bernstein(n, v);
                let w: Vec<F> = bu
                    .iter()
                    .flat_map(|a| bv.iter().map(move |b| a.clone() * b.clone()))
                    .collect();
                let k = helpers::eval_patch(patch, u, v);
                match fibre_rows(proj, &k, &w, scale) {
                    Ok(Some(rr)) => r.extend(rr),
                    Ok(None) => {}
                    Err(QuadricError::Exceptional { .. }) => continue 'grids,
                    Err(e) => return Err(e),
                }
            }
        }
        rows = Some(r);
        break;
    }
    let Some(rows) = rows else {
        return Err(QuadricError::NoPreimage(
            "the sample grids hit exceptional points".into(),
        ));
    };
    let basis = helpers::null_space(&rows, unknowns);
    let given: Vec<Vec<F>> = y.iter().flatten().map(|p| p.to_vec()).collect();
    let mut found: Option<PatchCandidate<F>> = None;
    pick_member(&basis, 2, |v| {
        let pts: Vec<Hom<F>> = v.chunks(4).map(to_hom).collect();
        let net: Vec<Vec<Hom<F>>> = pts.chunks(n + 1).map(|r| r.to_vec()).collect();
        let img = polar_rule_patch::<F, Hom<F>>(&net, 4, &|a, b| proj.polar(a, b).to_vec());
        let flat: Vec<Vec<F>> = img.iter().flatten().cloned().collect();
        match ratio_check(&flat, &given) {
            Ok(c) => {
                found = Some((v.to_vec(), img, c));
                true
            }
            Err(_) => false,
        }
    });
    let Some((v, img, c)) = found else {
        return Err(QuadricError::NoPreimage(format!(
            "no patch of bidegree ({m}, {n}) maps onto the given patch under {} (solution space of dimension {})",
            proj.name(),
            basis.len()
        )));
    };
    let pts: Vec<Vec<F>> = v.chunks(4).map(|c| c.to_vec()).collect();
    let net: Vec<Vec<Vec<F>>> = pts.chunks(n + 1).map(|r| r.to_vec()).collect();
    Ok(Preimage {
        given: patch.clone(),
        preimage: BezierPatch::from_homogeneous(net)?,
        factor: c,
        image: BezierPatch::from_homogeneous(img)?,
    })
}

impl<F: Scalar> Certified for Preimage<F, BezierCurve<F>> {
    /// `F(x) = c·y` coefficientwise (same degree, so an identity), `c ≠ 0`.
    fn certify(&self) -> Vec<Certificate> {
        let g: Vec<Vec<F>> = self.given.control_points().map(|p| p.to_vec()).collect();
        let i: Vec<Vec<F>> = self.image.control_points().map(|p| p.to_vec()).collect();
        vec![certify_proportional(
            &i,
            &g,
            &self.factor,
            "F(x) ≡ c·y (preimage of half degree)",
        )]
    }
}

impl<F: Scalar> Certified for Preimage<F, BezierPatch<F>> {
    /// `F(x) = c·y` coefficientwise, `c ≠ 0`.
    fn certify(&self) -> Vec<Certificate> {
        let flat = |p: &BezierPatch<F>| -> Vec<Vec<F>> {
            p.coords().chunks(p.dim() + 1).map(|c| c.to_vec()).collect()
        };
        vec![certify_proportional(
            &flat(&self.image),
            &flat(&self.given),
            &self.factor,
            "F(x) ≡ c·y (preimage of half bidegree)",
        )]
    }
}

fn certify_proportional<F: Scalar>(
    image: &[Vec<F>],
    given: &[Vec<F>],
    c: &F,
    property: &str,
) -> Certificate {
    let scale = image
        .iter()
        .map(|p| helpers::magnitude(p))
        .fold(1.0, f64::max);
    let ok = !c.is_zero()
        && image.len() == given.len()
        && image.iter().zip(given).all(|(a, b)| {
            a.iter()
                .zip(b)
                .all(|(x, y)| helpers::negligible(&(x.clone() - c.clone() * y.clone()), scale))
        });
    Certificate::decide(property, ok, F::EXACT, || {
        format!("F(x) − {}·y ≠ 0", fmt_scalar(c))
    })
}

/// The common factor `g` of the homogeneous coordinates of a curve and the reduced curve
/// `y/g` (its components coprime; docs/math/quadrics.md, "Curves and patches under δ": images can be reducible). Exact scalars
/// only: for `f64` the curve is returned unchanged with `g = 1`.
///
/// # Errors
/// [`QuadricError::Dimension`] unless the curve is in 3-space.
pub fn reduce_curve<F: Scalar>(
    curve: &BezierCurve<F>,
) -> Result<(Poly<F>, BezierCurve<F>), QuadricError> {
    curve_points(curve)?;
    let polys = curve.coordinate_polys();
    if !F::EXACT {
        return Ok((Poly::constant(F::one()), curve.clone()));
    }
    let mut g = Poly::zero();
    for p in &polys {
        g = if g.is_zero() { p.monic() } else { g.gcd(p) };
    }
    if g.is_zero() || g.degree().unwrap_or(0) == 0 {
        return Ok((Poly::constant(F::one()), curve.clone()));
    }
    let reduced: Vec<Poly<F>> = polys
        .iter()
        .map(|p| p.div_exact(&g))
        .collect::<Result<_, _>>()?;
    let deg = reduced.iter().filter_map(|p| p.degree()).max().unwrap_or(0);
    Ok((g, BezierCurve::from_coordinate_polys(&reduced, deg)?))
}

/// The monic square root of a monic polynomial, if it is a perfect square.
fn monic_sqrt<F: Scalar>(g: &Poly<F>) -> Option<Poly<F>> {
    let d = g.degree()?;
    if d % 2 == 1 {
        return None;
    }
    let m = d / 2;
    // h = t^m + Σ_{k<m} h_k t^k, determined from the top coefficients of g
    let mut h = vec![F::zero(); m + 1];
    h[m] = F::one();
    let two = F::from_i64(2);
    for k in (0..m).rev() {
        // coefficient of t^{m+k} in h² = g
        let mut s = F::zero();
        for i in k + 1..=m {
            let j = m + k - i;
            if j > k && j <= m {
                s += h[i].clone() * h[j].clone();
            }
        }
        h[k] = (g.coeff(m + k) - s) / two.clone();
    }
    let hp = Poly::new(h);
    (&hp * &hp == *g).then_some(hp)
}

/// Preimages of reducible curves `y = g·ŷ`: if `ŷ` has even degree and `g` is a constant
/// times a square `h²`, then `x = h·x̂` with `F(x̂) = c·ŷ` is a preimage of half degree.
fn reducible_preimage<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    curve: &BezierCurve<F>,
    dim: usize,
) -> Result<Preimage<F, BezierCurve<F>>, QuadricError> {
    let deg = curve.degree();
    let (g, reduced) = reduce_curve(curve)?;
    let gd = g.degree().unwrap_or(0);
    let none = |why: String| {
        Err(QuadricError::NoPreimage(format!(
            "no curve of degree {} maps onto the given curve of degree {deg} under {} (solution space of dimension {dim}){why}",
            deg / 2,
            proj.name()
        )))
    };
    if gd == 0 {
        return none(String::new());
    }
    let why = format!(
        "; the curve is reducible: its coordinates share a factor of degree {gd} (Satz 1 concerns irreducible curves; see reduce_curve)"
    );
    let Some(h) = monic_sqrt(&g) else {
        return none(why);
    };
    if reduced.degree() % 2 == 1 || reduced.degree() + gd != deg {
        return none(why);
    }
    let Ok(inner) = curve_preimage(proj, &reduced) else {
        return none(why);
    };
    let polys: Vec<Poly<F>> = inner
        .preimage
        .coordinate_polys()
        .iter()
        .map(|p| p * &h)
        .collect();
    let x = BezierCurve::from_coordinate_polys(&polys, deg / 2)?;
    let pts = curve_points(&x)?;
    let img = polar_rule_curve::<F, Hom<F>>(&pts, 4, &|a, b| proj.polar(a, b).to_vec());
    let given: Vec<Vec<F>> = curve.control_points().map(|p| p.to_vec()).collect();
    match ratio_check(&img, &given) {
        Ok(c) => Ok(Preimage {
            given: curve.clone(),
            preimage: x,
            factor: c,
            image: BezierCurve::from_homogeneous(img)?,
        }),
        Err(_) => none(why),
    }
}
