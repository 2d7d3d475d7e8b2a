//! Canal-surface blends with prescribed contact (Gruber ch. 2; Peternell §2.4–2.5, §3.8).
//!
//! A canal surface touches each of its spheres along the characteristic circle
//! `K(t) ∩ K̇(t)`, `K̇: (y − m)·ṁ + r ṙ = 0`. A family with `k(0) = (c₀; r₀)`,
//! `k(1) = (c₁; r₁)` therefore blends the two spheres **G¹ along the circles**
//! `Cᵢ = Sᵢ ∩ {(y − cᵢ)·ṁ(i) = −rᵢ ṙ(i)}`. A contact circle prescribed as the plane section
//! `(y − c)·n = h` of the sphere (`h² < r²|n|²` for a real circle) fixes the tangent
//! direction of `k` at the end: `ṁ = λn`, `ṙ = −λh/r` (`λ ≠ 0`), i.e.
//! `k̇ = λ(n, −h/r)` — a spacelike vector of `R^{3,1}` exactly when the circle is real.
//!
//! * **Spine/radius.** The default is the cubic Hermite interpolant in `R^{3,1}` of the end
//!   points and tangents (`λᵢ` default: the chord length over `|nᵢ|`, rounded to two decimals,
//!   or given); a user family is accepted after checking its ends (sphere and contact plane)
//!   exactly.
//! * **Construction.** [`super::canal_surface_pole_free`] on the domain `[0, 1]` (in a frame
//!   without base points there, [`super::frame`]; reparametrized by
//!   `t = s²/(1 + s²)` when `|ṁ| < |ṙ|` outside `[0, 1]`): exact over `Q` or over the quadratic
//!   field it needs; an interval of `[0, 1]` with `|ṁ| < |ṙ|` is named in the error (choose
//!   other `λ`).
//! * **Sphere and plane.** A plane is a sphere through the centre `O` of an inversion
//!   `ι(y) = O + (y − O)/|y − O|²` (a Möbius transformation, Peternell §2.4: it maps spheres to
//!   spheres, planes through `O`… and canal surfaces to canal surfaces, conformally). The
//!   blend between `S` and the plane `ε` with contact circle `C ⊂ ε` is `ι` of the sphere
//!   blend between `ι(S)` and the sphere `ι(ε)` with contact circles `ι(C_S)`, `ι(C)`; `O` is
//!   chosen on the normal of `ε` through the centre of `C`. The family of the result is
//!   `ι(c; r) = (O + (c − O)/(|c − O|² − r²); r/(|c − O|² − r²))`; its last sphere is the plane
//!   (weight zero) and the surface touches `ε` along `C`. The plane's normal must have a
//!   rational length (`ι(ε)` has radius `1/(2·dist(O, ε))`).
//!
//! **Certificates.** The canal identities of [`super::envelope`] for the family actually
//! enveloped, and for each end: the end circle `x(end, u)` lies on the sphere (or in the
//! plane and on the prescribed circle) and in the prescribed contact plane, as polynomial
//! identities in `u`; for the plane end also the tangency `n·x_t ≡ 0` along `C`.

use super::bipoly::{bidegree, BiPoly};
use super::envelope::{canal_certificates, CanalBuild, CanalOptions};
use super::{CanalError, CanalSpine};
use crate::error::format_scalar;
use crate::lines::{dot, fmt_vec};
use crate::Certified;
use rcagd_algebra::rational::rational_sqrt;
use rcagd_algebra::{Certificate, Poly, QuadExt, Rational, Scalar};
use rcagd_geom::certify::polynomial_is_zero_scaled;

/// One end of a blend: the sphere `(c; r)` and the contact circle `S ∩ {(y − c)·n = h}`; `n`
/// is also the direction of the spine there (leaving at the start, arriving at the end).
#[derive(Debug, Clone, PartialEq)]
pub struct BlendEnd<F> {
    /// Centre `c`.
    pub center: [F; 3],
    /// Signed radius `r ≠ 0`.
    pub radius: F,
    /// Plane normal `n ≠ 0` of the contact circle (spine direction).
    pub normal: [F; 3],
    /// Offset `h`: the circle's plane is `(y − c)·n = h`.
    pub offset: F,
}

impl<F: Scalar> BlendEnd<F> {
    /// The end `(c; r)` with contact plane `(y − c)·n = h`.
    ///
    /// # Errors
    /// [`CanalError::InvalidArgument`] for `r = 0`, `n = 0` or `h² ≥ r²|n|²` (no real
    /// contact circle).
    pub fn new(center: [F; 3], radius: F, normal: [F; 3], offset: F) -> Result<Self, CanalError> {
        if radius.is_zero() {
            return Err(CanalError::InvalidArgument(
                "a blend end needs a sphere of non-zero radius".into(),
            ));
        }
        let nn = dot(&normal, &normal);
        if nn.is_zero() {
            return Err(CanalError::InvalidArgument(
                "the contact plane normal must be non-zero".into(),
            ));
        }
        let lhs = offset.clone() * offset.clone();
        let rhs = radius.clone() * radius.clone() * nn;
        if lhs >= rhs {
            return Err(CanalError::InvalidArgument(format!(
                "the plane (y − c)·n = {} does not cut the sphere of radius {} in a real circle (h² = {} ≥ r²|n|² = {})",
                format_scalar(&offset),
                format_scalar(&radius),
                format_scalar(&lhs),
                format_scalar(&rhs)
            )));
        }
        Ok(BlendEnd {
            center,
            radius,
            normal,
            offset,
        })
    }

    /// The point `(c, r)` of `R^{3,1}`.
    pub fn point(&self) -> [F; 4] {
        [
            self.center[0].clone(),
            self.center[1].clone(),
            self.center[2].clone(),
            self.radius.clone(),
        ]
    }

    /// The tangent `k̇ = λ(n, −h/r)` of the family at this end (module docs).
    pub fn tangent(&self, lambda: &F) -> [F; 4] {
        [
            lambda.clone() * self.normal[0].clone(),
            lambda.clone() * self.normal[1].clone(),
            lambda.clone() * self.normal[2].clone(),
            -(lambda.clone() * self.offset.clone() / self.radius.clone()),
        ]
    }
}

/// The spine/radius pair of a blend.
#[derive(Debug, Clone, PartialEq)]
pub enum BlendSpine<F> {
    /// Cubic Hermite with the default tangent magnitudes.
    Default,
    /// Cubic Hermite with the tangents `λ₀(n₀, −h₀/r₀)`, `λ₁(n₁, −h₁/r₁)`.
    Hermite {
        /// `λ₀ ≠ 0`.
        lambda0: F,
        /// `λ₁ ≠ 0`.
        lambda1: F,
    },
    /// A user family on `t ∈ [0, 1]` (checked at both ends).
    Custom(CanalSpine<F>),
}

/// The cubic Hermite family `k(t)` with `k(0) = K₀`, `k(1) = K₁`, `k̇(0) = T₀`, `k̇(1) = T₁`:
/// `k = K₀ + T₀t + (3(K₁ − K₀) − 2T₀ − T₁)t² + (2(K₀ − K₁) + T₀ + T₁)t³`.
pub fn hermite_spine<F: Scalar>(
    a: &BlendEnd<F>,
    b: &BlendEnd<F>,
    lambda0: &F,
    lambda1: &F,
) -> CanalSpine<F> {
    let (k0, k1) = (a.point(), b.point());
    let (t0, t1) = (a.tangent(lambda0), b.tangent(lambda1));
    let three = F::from_i64(3);
    let two = F::from_i64(2);
    let comp = |i: usize| {
        Poly::new(vec![
            k0[i].clone(),
            t0[i].clone(),
            three.clone() * (k1[i].clone() - k0[i].clone())
                - two.clone() * t0[i].clone()
                - t1[i].clone(),
            two.clone() * (k0[i].clone() - k1[i].clone()) + t0[i].clone() + t1[i].clone(),
        ])
    };
    CanalSpine::polynomial([comp(0), comp(1), comp(2)], comp(3))
}

fn approx(x: f64) -> Rational {
    let k = (x * 100.0).round();
    let k = if k.abs() < 1.0 { 1.0 } else { k };
    Rational::from_ratio(k as i64, 100)
}

/// The default tangent magnitudes: `λᵢ ≈ |c₁ − c₀|/|nᵢ|` (two decimals, at least 1/100).
pub fn default_lambdas(a: &BlendEnd<Rational>, b: &BlendEnd<Rational>) -> (Rational, Rational) {
    let d: Vec<Rational> = (0..3)
        .map(|i| b.center[i].clone() - a.center[i].clone())
        .collect();
    let chord = Scalar::to_f64(&dot(&d, &d)).sqrt().max(1e-2);
    let l0 = chord / Scalar::to_f64(&dot(&a.normal, &a.normal)).sqrt();
    let l1 = chord / Scalar::to_f64(&dot(&b.normal, &b.normal)).sqrt();
    (approx(l0), approx(l1))
}

/// Checks that a user family starts at `a` and ends at `b` with the prescribed contact
/// planes: `k(i) = (cᵢ; rᵢ)` and `(ṁ, −r ṙ) ∥ (n, h)` at both ends.
fn check_custom(
    spine: &CanalSpine<Rational>,
    ends: [&BlendEnd<Rational>; 2],
) -> Result<(), CanalError> {
    let p = spine.derivative_numerators()?;
    for (i, e) in ends.iter().enumerate() {
        let t = Rational::from(i as i64);
        let (m, r) = spine.eval(&t)?;
        if m != e.center || r != e.radius {
            return Err(CanalError::InvalidArgument(format!(
                "the family at t = {i} is the sphere ({}; {}), not ({}; {})",
                fmt_vec(&m),
                format_scalar(&r),
                fmt_vec(&e.center),
                format_scalar(&e.radius)
            )));
        }
        let v = [
            p[0].eval(&t),
            p[1].eval(&t),
            p[2].eval(&t),
            -(r.clone() * p[3].eval(&t)),
        ];
        let w = [
            e.normal[0].clone(),
            e.normal[1].clone(),
            e.normal[2].clone(),
            e.offset.clone(),
        ];
        if !crate::lines::proportional(&v, &w) || v.iter().all(Rational::is_zero) {
            return Err(CanalError::InvalidArgument(format!(
                "the characteristic circle at t = {i} lies in the plane (y − c)·{} = {}, not in the prescribed one",
                fmt_vec(&[v[0].clone(), v[1].clone(), v[2].clone()]),
                format_scalar(&v[3])
            )));
        }
    }
    Ok(())
}

/// A blend between two spheres.
#[derive(Debug, Clone, PartialEq)]
pub struct SphereBlend {
    /// The two ends.
    pub ends: [BlendEnd<Rational>; 2],
    /// The family enveloped (before any reparametrization).
    pub spine: CanalSpine<Rational>,
    /// The canal surface (over `Q` or `Q(√d)`), domain `[0, 1]`.
    pub build: CanalBuild,
}

/// The canal-surface blend between two spheres with prescribed contact circles (module
/// docs).
///
/// # Errors
/// [`CanalError::InvalidArgument`] for `λ = 0` or a custom family that misses an end;
/// [`CanalError::NoRealEnvelope`] naming the interval of `[0, 1]` with `|ṁ| < |ṙ|`; as
/// [`super::canal_surface`] ([`CanalError::NeedsLargerExtension`]: use [`blend_spheres_f64`]).
pub fn blend_spheres(
    a: &BlendEnd<Rational>,
    b: &BlendEnd<Rational>,
    spine: &BlendSpine<Rational>,
) -> Result<SphereBlend, CanalError> {
    // one sphere twice: a blend from a sphere to itself is no surface between two spheres
    if a.center == b.center && a.radius == b.radius {
        return Err(CanalError::InvalidArgument(format!(
            "coincident spheres: both ends are the sphere ({}; {}); a blend needs two different spheres",
            fmt_vec(&a.center),
            format_scalar(&a.radius)
        )));
    }
    let family = match spine {
        BlendSpine::Default => {
            let (l0, l1) = default_lambdas(a, b);
            hermite_spine(a, b, &l0, &l1)
        }
        BlendSpine::Hermite { lambda0, lambda1 } => {
            if lambda0.is_zero() || lambda1.is_zero() {
                return Err(CanalError::InvalidArgument(
                    "the tangent magnitudes λ₀, λ₁ must be non-zero".into(),
                ));
            }
            hermite_spine(a, b, lambda0, lambda1)
        }
        BlendSpine::Custom(s) => {
            check_custom(s, [a, b])?;
            s.clone()
        }
    };
    let options = CanalOptions {
        domain: Some((Rational::ZERO, Rational::ONE)),
        ..CanalOptions::default()
    };
    let build = super::frame::canal_surface_pole_free(&family, &options)?;
    Ok(SphereBlend {
        ends: [a.clone(), b.clone()],
        spine: family,
        build,
    })
}

/// The blend in `f64` (the split of `D` from its complex roots): for data whose exact split
/// needs more than one quadratic field.
///
/// # Errors
/// As [`blend_spheres`].
pub fn blend_spheres_f64(
    a: &BlendEnd<Rational>,
    b: &BlendEnd<Rational>,
    spine: &BlendSpine<Rational>,
) -> Result<super::CanalSurface<f64>, CanalError> {
    let family = match spine {
        BlendSpine::Default => {
            let (l0, l1) = default_lambdas(a, b);
            hermite_spine(a, b, &l0, &l1)
        }
        BlendSpine::Hermite { lambda0, lambda1 } => hermite_spine(a, b, lambda0, lambda1),
        BlendSpine::Custom(s) => {
            check_custom(s, [a, b])?;
            s.clone()
        }
    };
    let options = CanalOptions {
        domain: Some((Rational::ZERO, Rational::ONE)),
        ..CanalOptions::default()
    };
    super::envelope::canal_surface_approx(&family, &options)
}

fn ext(x: &Rational) -> QuadExt {
    QuadExt::rational(x.clone())
}

/// `|X₁₂₃ − c X₀|² − r² X₀²` and `n·(X₁₂₃ − c X₀) − h X₀` of an end circle.
fn end_identities<F: Scalar>(
    circle: &[Poly<F>; 4],
    center: &[F; 3],
    radius_sq: &F,
    normal: &[F; 3],
    offset: &F,
) -> (Poly<F>, Poly<F>) {
    let d: Vec<Poly<F>> = (0..3)
        .map(|i| &circle[i + 1] - &circle[0].scale(&center[i]))
        .collect();
    let sphere = d.iter().fold(Poly::zero(), |acc, x| &acc + &(x * x))
        - (&circle[0] * &circle[0]).scale(radius_sq);
    let plane = (0..3).fold(Poly::zero(), |acc, i| &acc + &d[i].scale(&normal[i]))
        - circle[0].scale(offset);
    (sphere, plane)
}

fn pscale<F: Scalar>(p: &[Poly<F>]) -> f64 {
    p.iter()
        .flat_map(|q| q.coeffs().iter())
        .map(|x| x.to_f64().abs())
        .fold(1.0, f64::max)
}

impl Certified for SphereBlend {
    /// The canal identities and, for both ends, the end circle on the sphere and in the
    /// prescribed contact plane (polynomial identities in `u`).
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.build.certify();
        let s = self.build.to_ext();
        for (i, e) in self.ends.iter().enumerate() {
            match s.end_circle(i) {
                Ok(c) => {
                    let center = e.center.clone().map(|x| ext(&x));
                    let normal = e.normal.clone().map(|x| ext(&x));
                    let (sp, pl) = end_identities(
                        &c,
                        &center,
                        &ext(&(e.radius.clone() * e.radius.clone())),
                        &normal,
                        &ext(&e.offset),
                    );
                    let sc = pscale(&c);
                    out.push(polynomial_is_zero_scaled(
                        &format!(
                            "end {i}: the contact circle lies on the sphere ({}; {})",
                            fmt_vec(&e.center),
                            format_scalar(&e.radius)
                        ),
                        sp.coeffs(),
                        sc * sc,
                    ));
                    out.push(polynomial_is_zero_scaled(
                        &format!("end {i}: the contact circle lies in the plane (y − c)·n = h"),
                        pl.coeffs(),
                        sc,
                    ));
                    let nondeg = c[1..].iter().any(|p| p.degree().is_some_and(|d| d > 0));
                    out.push(Certificate::decide(
                        format!("end {i}: the contact circle is not a point"),
                        nondeg,
                        true,
                        || "constant end curve".into(),
                    ));
                }
                Err(err) => out.push(Certificate::fails(
                    format!("end {i} circle"),
                    err.to_string(),
                    true,
                )),
            }
        }
        out
    }
}

// ----------------------------------------------------------------------------------------
// sphere and plane: inversion
// ----------------------------------------------------------------------------------------

/// The plane end of a blend: the plane `n·y = e` and the contact circle in it with centre
/// `p` (a point of the plane) and radius `ρ > 0`. `|n|` must be rational.
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneEnd {
    /// Normal `n` (with rational length).
    pub normal: [Rational; 3],
    /// Offset `e` of the plane `n·y = e`.
    pub offset: Rational,
    /// Centre of the contact circle (on the plane).
    pub center: [Rational; 3],
    /// Radius of the contact circle.
    pub radius: Rational,
}

/// A canal surface obtained by a Möbius inversion of another one: its family and its
/// homogeneous parametrization.
#[derive(Debug, Clone, PartialEq)]
pub struct InvertedCanal<F> {
    /// The family enveloped (the inverted spheres; the plane is the member of weight 0).
    pub spine: CanalSpine<F>,
    /// Homogeneous coordinates `(X₀, X₁, X₂, X₃)` in `(t, u)`.
    pub x: [BiPoly<F>; 4],
    /// `Some((a, b))` if the parameter is `s` with `t = (a + b s²)/(1 + s²)`.
    pub reparametrized: Option<(Rational, Rational)>,
}

/// A blend between a sphere and a plane (module docs), over `QuadExt` (exact) or `f64`.
#[derive(Debug, Clone, PartialEq)]
pub struct SpherePlaneBlend<F> {
    /// The sphere end.
    pub sphere: BlendEnd<Rational>,
    /// The plane end.
    pub plane: PlaneEnd,
    /// The inversion centre `O` (power 1).
    pub inversion_center: [Rational; 3],
    /// The sphere blend in the inverted space.
    pub inner: super::CanalSurface<F>,
    /// The result.
    pub surface: InvertedCanal<F>,
    /// `None` over `Q` (or for `f64`), `Some(d)` over `Q(√d)`.
    pub radicand: Option<Rational>,
}

/// `ι(c; r) = (O + (c − O)/(|c − O|² − r²); r/(|c − O|² − r²))`.
fn invert_sphere(
    o: &[Rational; 3],
    c: &[Rational; 3],
    r: &Rational,
) -> Option<([Rational; 3], Rational)> {
    let d: Vec<Rational> = (0..3).map(|i| c[i].clone() - o[i].clone()).collect();
    let den = dot(&d, &d) - r.clone() * r.clone();
    if den.is_zero() {
        return None;
    }
    Some((
        core::array::from_fn(|i| o[i].clone() + d[i].clone() / den.clone()),
        r.clone() / den,
    ))
}

/// `ι` of the plane `n·y = e` (`O ∉` plane): the sphere through `O` with centre
/// `O − n/(2δ)`, `δ = n·O − e`, and squared radius `|n|²/(4δ²)`.
fn invert_plane_sq(
    o: &[Rational; 3],
    n: &[Rational; 3],
    e: &Rational,
) -> Option<([Rational; 3], Rational)> {
    let delta = dot(n, o) - e.clone();
    if delta.is_zero() {
        return None;
    }
    let two_d = Rational::from(2) * delta.clone();
    Some((
        core::array::from_fn(|i| o[i].clone() - n[i].clone() / two_d.clone()),
        dot(n, n) / (two_d.clone() * two_d),
    ))
}

/// The radical plane `N·y = E` of two spheres given with squared radii:
/// `N = 2(b − a)`, `E = |b|² − |a|² − r_b² + r_a²`.
fn radical_plane(
    a: &([Rational; 3], Rational),
    b: &([Rational; 3], Rational),
) -> ([Rational; 3], Rational) {
    let n = core::array::from_fn(|i| Rational::from(2) * (b.0[i].clone() - a.0[i].clone()));
    let e = dot(&b.0, &b.0) - dot(&a.0, &a.0) - b.1.clone() + a.1.clone();
    (n, e)
}

/// The blend end in the inverted space: the image sphere and the plane of the image circle,
/// the normal oriented along `dir`.
fn inverted_end(
    sphere: &([Rational; 3], Rational),
    plane: ([Rational; 3], Rational),
    dir: &[Rational; 3],
) -> Result<BlendEnd<Rational>, CanalError> {
    let (mut n, mut e) = plane;
    if dot(&n, dir) < Rational::ZERO {
        n = n.map(|x| -x);
        e = -e;
    }
    let h = e - dot(&n, &sphere.0);
    BlendEnd::new(sphere.0.clone(), sphere.1.clone(), n, h)
}

/// The homogeneous inversion `X ↦ (|V|², O|V|² + X₀V)`, `V = X₁₂₃ − X₀O`.
fn invert_bipoly<F: Scalar>(x: &[BiPoly<F>; 4], o: &[F; 3]) -> [BiPoly<F>; 4] {
    let v: Vec<BiPoly<F>> = (0..3).map(|i| x[i + 1].sub(&x[0].scale(&o[i]))).collect();
    let vv = v.iter().fold(BiPoly::zero(), |acc, a| acc.add(&a.mul(a)));
    [
        vv.clone(),
        vv.scale(&o[0]).add(&x[0].mul(&v[0])),
        vv.scale(&o[1]).add(&x[0].mul(&v[1])),
        vv.scale(&o[2]).add(&x[0].mul(&v[2])),
    ]
}

/// The inverted family: `W'' = |M − WO|² − R²`, `M'' = OW'' + W(M − WO)`, `R'' = WR`.
fn invert_spine<F: Scalar>(s: &CanalSpine<F>, o: &[F; 3]) -> Result<CanalSpine<F>, CanalError> {
    let w = s.weight();
    let m = s.center_polys();
    let r = s.radius_poly();
    let v: Vec<Poly<F>> = (0..3).map(|i| &m[i] - &w.scale(&o[i])).collect();
    let w2 = &v.iter().fold(Poly::zero(), |acc, a| &acc + &(a * a)) - &(r * r);
    let m2: [Poly<F>; 3] = core::array::from_fn(|i| &w2.scale(&o[i]) + &(w * &v[i]));
    CanalSpine::new(w2, m2, w * r)
}

/// The admissible inversion set-ups: `(O, end in the inverted space for the sphere, end for
/// the image of the plane)`, `O = p + κ n/|n|` on the normal through the circle centre.
#[allow(clippy::type_complexity)]
fn inversion_setups(
    a: &BlendEnd<Rational>,
    plane: &PlaneEnd,
) -> Result<Vec<([Rational; 3], BlendEnd<Rational>, BlendEnd<Rational>)>, CanalError> {
    let nn = dot(&plane.normal, &plane.normal);
    let nlen = rational_sqrt(&nn).ok_or_else(|| {
        CanalError::InvalidArgument(format!(
            "the plane normal {} must have rational length (|n|² = {} is not a square)",
            fmt_vec(&plane.normal),
            format_scalar(&nn)
        ))
    })?;
    if nlen.is_zero() {
        return Err(CanalError::InvalidArgument(
            "the plane needs a non-zero normal".into(),
        ));
    }
    if plane.radius <= Rational::ZERO {
        return Err(CanalError::InvalidArgument(format!(
            "the contact circle radius must be positive, got {}",
            format_scalar(&plane.radius)
        )));
    }
    if dot(&plane.normal, &plane.center) != plane.offset {
        return Err(CanalError::InvalidArgument(format!(
            "the contact circle centre {} is not on the plane",
            fmt_vec(&plane.center)
        )));
    }
    let mut out = Vec::new();
    for kappa in [1i64, 2, -1, 3, -2, 5] {
        let o: [Rational; 3] = core::array::from_fn(|i| {
            plane.center[i].clone() + Rational::from(kappa) * plane.normal[i].clone() / nlen.clone()
        });
        let Some(s1) = invert_sphere(&o, &a.center, &a.radius) else {
            continue;
        };
        // the contact plane of the sphere end: (y − c)·n = h ⇔ n·y = h + n·c
        let p1e = a.offset.clone() + dot(&a.normal, &a.center);
        let Some(p1) = invert_plane_sq(&o, &a.normal, &p1e) else {
            continue;
        };
        let Some(sig_sq) = invert_plane_sq(&o, &plane.normal, &plane.offset) else {
            continue;
        };
        // ι(ε) with its radius |n|/(2|δ|) (rational because |n| is)
        let delta = dot(&plane.normal, &o) - plane.offset.clone();
        let sr = nlen.clone() / (Rational::from(2) * delta);
        let sigma = (sig_sq.0.clone(), if sr < Rational::ZERO { -sr } else { sr });
        let Some(z2) = invert_sphere(&o, &plane.center, &plane.radius) else {
            continue;
        };
        let sq = |s: &([Rational; 3], Rational)| (s.0.clone(), s.1.clone() * s.1.clone());
        let rad1 = radical_plane(&sq(&s1), &p1);
        let rad2 = radical_plane(&sig_sq, &sq(&z2));
        let dir: [Rational; 3] = core::array::from_fn(|i| sigma.0[i].clone() - s1.0[i].clone());
        if let (Ok(e0), Ok(e1)) = (
            inverted_end(&s1, rad1, &dir),
            inverted_end(&sigma, rad2, &dir),
        ) {
            out.push((o, e0, e1));
        }
    }
    if out.is_empty() {
        return Err(CanalError::InvalidArgument(
            "no admissible inversion centre on the normal of the plane circle".into(),
        ));
    }
    Ok(out)
}

fn finish<F: Scalar>(
    a: &BlendEnd<Rational>,
    plane: &PlaneEnd,
    o: [Rational; 3],
    inner: super::CanalSurface<F>,
    radicand: Option<Rational>,
) -> Result<SpherePlaneBlend<F>, CanalError> {
    let of = o.clone().map(|x| F::from_rational(&x));
    let x = invert_bipoly(inner.homogeneous(), &of);
    let fam = invert_spine(inner.spine(), &of)?;
    Ok(SpherePlaneBlend {
        sphere: a.clone(),
        plane: plane.clone(),
        inversion_center: o,
        surface: InvertedCanal {
            spine: fam,
            x,
            reparametrized: inner.reparametrization().cloned(),
        },
        inner,
        radicand,
    })
}

/// The canal-surface blend between a sphere (contact circle prescribed as for
/// [`blend_spheres`]) and a plane (contact circle in the plane), by inversion (module docs);
/// exact over `Q` or `Q(√d)`.
///
/// # Errors
/// [`CanalError::InvalidArgument`] if `|n|` is irrational, `ρ ≤ 0`, the circle centre is not
/// on the plane, or no admissible inversion centre is found; as [`blend_spheres`]
/// ([`CanalError::NeedsLargerExtension`]: use [`blend_sphere_plane_f64`]).
pub fn blend_sphere_plane(
    a: &BlendEnd<Rational>,
    plane: &PlaneEnd,
    spine: &BlendSpine<Rational>,
) -> Result<SpherePlaneBlend<QuadExt>, CanalError> {
    let mut last_err = None;
    for (o, e0, e1) in inversion_setups(a, plane)? {
        match blend_spheres(&e0, &e1, spine) {
            Ok(b) => {
                let radicand = b.build.radicand().cloned();
                return finish(a, plane, o, b.build.to_ext(), radicand);
            }
            Err(e) => last_err = Some(e),
        }
    }
    Err(last_err.unwrap_or_else(|| CanalError::InvalidArgument("no inversion".into())))
}

/// [`blend_sphere_plane`] in `f64` (the inner sphere blend by [`blend_spheres_f64`]).
///
/// # Errors
/// As [`blend_sphere_plane`].
pub fn blend_sphere_plane_f64(
    a: &BlendEnd<Rational>,
    plane: &PlaneEnd,
    spine: &BlendSpine<Rational>,
) -> Result<SpherePlaneBlend<f64>, CanalError> {
    let mut last_err = None;
    for (o, e0, e1) in inversion_setups(a, plane)? {
        match blend_spheres_f64(&e0, &e1, spine) {
            Ok(s) => return finish(a, plane, o, s, None),
            Err(e) => last_err = Some(e),
        }
    }
    Err(last_err.unwrap_or_else(|| CanalError::InvalidArgument("no inversion".into())))
}

impl<F: Scalar> InvertedCanal<F> {
    fn deg_t(&self) -> usize {
        bidegree(&self.x).0
    }

    /// The end circle (`0`: `t = 0`, `1`: `t = 1`) as homogeneous polynomials in `u`.
    pub fn end_circle(&self, end: usize) -> [Poly<F>; 4] {
        if self.reparametrized.is_some() && end == 1 {
            let n = self.deg_t();
            return core::array::from_fn(|k| {
                Poly::new(self.x[k].coeffs().iter().map(|p| p.coeff(n)).collect())
            });
        }
        let t = F::from_i64(end as i64);
        let t = if self.reparametrized.is_some() {
            F::zero()
        } else {
            t
        };
        core::array::from_fn(|k| self.x[k].at_t(&t))
    }

    /// `∂X/∂t` along the end circle (in the chart `σ = 1/s` at a reparametrized `t = 1`).
    fn end_derivative(&self, end: usize) -> [Poly<F>; 4] {
        if self.reparametrized.is_some() && end == 1 {
            let n = self.deg_t();
            return core::array::from_fn(|k| {
                let rev = self.x[k].transpose().reverse_u(n).transpose();
                rev.partial_t().at_t(&F::zero())
            });
        }
        let t = F::from_i64(end as i64);
        let t = if self.reparametrized.is_some() {
            F::zero()
        } else {
            t
        };
        core::array::from_fn(|k| self.x[k].partial_t().at_t(&t))
    }

    /// The point `x(t, u)`.
    ///
    /// # Errors
    /// [`CanalError::InvalidArgument`] where `X₀ = 0`.
    pub fn eval(&self, t: &F, u: &F) -> Result<[F; 3], CanalError> {
        let h: [F; 4] = core::array::from_fn(|k| self.x[k].eval(t, u));
        let inv = h[0]
            .inv()
            .ok_or_else(|| CanalError::InvalidArgument("X₀ = 0".into()))?;
        Ok(core::array::from_fn(|i| h[i + 1].clone() * inv.clone()))
    }

    /// The bidegree.
    pub fn degree(&self) -> (usize, usize) {
        bidegree(&self.x)
    }
}

impl<F: Scalar> Certified for SpherePlaneBlend<F> {
    /// The canal identities of the inverted family, the sphere-end circle on the sphere and
    /// in its contact plane, the plane-end circle in the plane and on the prescribed circle,
    /// and the tangency `n·x_t ≡ 0` along it.
    fn certify(&self) -> Vec<Certificate> {
        let s = &self.surface;
        let fr = |x: &Rational| F::from_rational(x);
        let mut out = match s.spine.derivative_numerators() {
            Ok(p) => canal_certificates(&s.spine, &p, &s.x),
            Err(e) => vec![Certificate::fails(
                "inverted family",
                e.to_string(),
                F::EXACT,
            )],
        };
        let c0 = s.end_circle(0);
        let e = &self.sphere;
        let (sp, pl) = end_identities(
            &c0,
            &e.center.clone().map(|x| fr(&x)),
            &fr(&(e.radius.clone() * e.radius.clone())),
            &e.normal.clone().map(|x| fr(&x)),
            &fr(&e.offset),
        );
        let sc = pscale(&c0);
        out.push(polynomial_is_zero_scaled(
            "sphere end: the contact circle lies on the sphere",
            sp.coeffs(),
            sc * sc,
        ));
        out.push(polynomial_is_zero_scaled(
            "sphere end: the contact circle lies in the prescribed plane",
            pl.coeffs(),
            sc,
        ));
        let c1 = s.end_circle(1);
        let pe = &self.plane;
        let inplane = (0..3).fold(Poly::zero(), |acc, i| {
            &acc + &c1[i + 1].scale(&fr(&pe.normal[i]))
        }) - c1[0].scale(&fr(&pe.offset));
        let d: Vec<Poly<F>> = (0..3)
            .map(|i| &c1[i + 1] - &c1[0].scale(&fr(&pe.center[i])))
            .collect();
        let oncircle = d.iter().fold(Poly::zero(), |acc, x| &acc + &(x * x))
            - (&c1[0] * &c1[0]).scale(&fr(&(pe.radius.clone() * pe.radius.clone())));
        let sc1 = pscale(&c1);
        out.push(polynomial_is_zero_scaled(
            "plane end: the contact curve lies in the plane n·y = e",
            inplane.coeffs(),
            sc1,
        ));
        out.push(polynomial_is_zero_scaled(
            "plane end: the contact curve is the prescribed circle",
            oncircle.coeffs(),
            sc1 * sc1,
        ));
        let dt = s.end_derivative(1);
        let tangency = (0..3).fold(Poly::zero(), |acc, i| {
            &acc + &(&(&dt[i + 1] * &c1[0]) - &(&c1[i + 1] * &dt[0])).scale(&fr(&pe.normal[i]))
        });
        out.push(polynomial_is_zero_scaled(
            "plane end: the surface is tangent to the plane along the circle (n·x_t ≡ 0)",
            tangency.coeffs(),
            sc1 * pscale(&dt),
        ));
        let nondeg = c1[1..].iter().any(|p| p.degree().is_some_and(|d| d > 0));
        out.push(Certificate::decide(
            "plane end: the contact curve is not a point",
            nondeg,
            F::EXACT,
            || "constant".into(),
        ));
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    fn r(n: i64, d: i64) -> Rational {
        Rational::from_ratio(n, d)
    }

    #[test]
    fn coaxial_sphere_blend() {
        let a = BlendEnd::new([q(0), q(0), q(0)], q(1), [q(0), q(0), q(1)], r(1, 2)).expect("a");
        let b = BlendEnd::new([q(0), q(0), q(4)], q(2), [q(0), q(0), q(1)], q(-1)).expect("b");
        match blend_spheres(&a, &b, &BlendSpine::Default) {
            Ok(bl) => assert!(bl.all_hold(), "{:?}", bl.certify()),
            Err(CanalError::NeedsLargerExtension(_)) => {
                let f = blend_spheres_f64(&a, &b, &BlendSpine::Default).expect("f64");
                assert!(f.all_hold());
            }
            Err(e) => panic!("{e}"),
        }
    }

    #[test]
    fn sphere_plane_blend() {
        let a = BlendEnd::new([q(0), q(0), q(3)], q(1), [q(0), q(0), q(-1)], r(1, 2)).expect("a");
        let p = PlaneEnd {
            normal: [q(0), q(0), q(1)],
            offset: q(0),
            center: [q(0), q(0), q(0)],
            radius: q(2),
        };
        match blend_sphere_plane(&a, &p, &BlendSpine::Default) {
            Ok(bl) => assert!(bl.all_hold(), "{:?}", bl.certify()),
            Err(CanalError::NeedsLargerExtension(_)) => {
                let f = blend_sphere_plane_f64(&a, &p, &BlendSpine::Default).expect("f64");
                assert!(f.all_hold(), "{:?}", f.certify());
            }
            Err(e) => panic!("{e}"),
        }
    }

    #[test]
    fn end_checks() {
        assert!(BlendEnd::new([q(0), q(0), q(0)], q(1), [q(0), q(0), q(1)], q(2)).is_err());
        assert!(BlendEnd::new([q(0), q(0), q(0)], q(0), [q(0), q(0), q(1)], q(0)).is_err());
        assert!(BlendEnd::new([q(0), q(0), q(0)], q(2), [q(0), q(0), q(1)], q(1)).is_ok());
    }
}
