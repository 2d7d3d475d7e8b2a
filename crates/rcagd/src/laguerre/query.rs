//! Questions about the models of Laguerre and Möbius geometry, answered exactly
//! (M. Peternell, *Rational Parametrizations for Envelopes of Quadric Families*, §2.4,
//! §3.1–§3.5; conventions and corrections in docs/math/laguerre-pn.md#conventions):
//!
//! * [`cycle_models`]: a cycle `(m; r)` in every model — the point `(m, r)` of the
//!   cyclographic model (3.6), the hyperplane `(r, m, 1)` of the Blaschke model, the
//!   isotropic sphere (3.12) and the point `((|m|² − r² + 1)/2, m, (|m|² − r² − 1)/2)` of
//!   the Möbius quadric model (2.13) — and back;
//! * [`plane_models`]: an oriented plane `e0 + n·x = 0` as γ-hyperplane (3.5), Blaschke
//!   point (3.10), isotropic point `Λ(e)` (3.11), dual isotropic plane (3.16) and Möbius
//!   point — and back;
//! * [`isotropic_quadric`]: the isotropic-model function `y₃ = F(y₁, y₂)` of a quadric
//!   `Xᵀ Q X = 0`: `F` solves `A F² + B F + C = 0`, the condition that the plane
//!   `Λ⁻¹(y₁, y₂, F)` of (3.13) touches the quadric (`uᵀ Q* u = 0` for its coordinates
//!   `u = (2F, 2y₁, 2y₂, y₁² + y₂² − 1)` and the dual quadric `Q* = adj Q`); rational,
//!   `F = −C/B`, exactly when `A = 4Q*₀₀ = 0` (the plane at infinity touches: paraboloids;
//!   docs/math/laguerre-pn.md#isotropic-function-of-a-quadric);
//! * [`laguerre_cycles`]: the images of cycles under a Laguerre map `x ↦ a + λAx`
//!   (3.8) and its fixed cycles, the solutions of `(I − λA)x = a`.

#![allow(clippy::needless_range_loop)] // index loops mirror the matrix formulas

use super::models::{Cycle, IsotropicSphere, OrientedPlane};
use super::{LaguerreError, LaguerreMap};
use crate::cyclographic::{
    mobius_bilinear, mobius_image, mobius_plane_point, mobius_point, MobiusImage,
};
use crate::error::{format_point, format_scalar};
use crate::pn::{IsotropicSurface, RatFn};
use crate::quadric::helpers;
use crate::quadric::Mat4;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Scalar};

/// The six normals `Λ⁻¹(u, v)` with `(u, v) ∈ {(0,0), (1,0), (2,0), (0,1), (0,2), (1,1)}`:
/// a unisolvent set for polynomials of degree ≤ 2 in `(u, v)`.
const SAMPLES: [(i64, i64); 6] = [(0, 0), (1, 0), (2, 0), (0, 1), (0, 2), (1, 1)];

/// The unit normal `(2u, 2v, u² + v² − 1)/(u² + v² + 1)` of (3.13).
fn sample_normal<F: Scalar>(u: i64, v: i64) -> [F; 3] {
    let (u, v) = (F::from_i64(u), F::from_i64(v));
    let s = u.clone() * u.clone() + v.clone() * v.clone();
    let d = s.clone() + F::one();
    let two = F::from_i64(2);
    [
        two.clone() * u / d.clone(),
        two * v / d.clone(),
        (s - F::one()) / d,
    ]
}

fn dot3<F: Scalar>(a: &[F; 3], b: &[F; 3]) -> F {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() + a[2].clone() * b[2].clone()
}

/// The tangent plane of the cycle with unit normal `n`: `e0 = −n·m − r` (3.3).
fn tangent_plane<F: Scalar>(c: &Cycle<F>, n: [F; 3]) -> OrientedPlane<F> {
    OrientedPlane {
        e0: -dot3(&n, &c.center) - c.radius.clone(),
        n,
    }
}

fn zero<F: Scalar>(x: &F) -> bool {
    crate::certs::is_negligible(x, 1.0)
}

/// A cycle in every model of Laguerre and Möbius geometry.
#[derive(Debug, Clone, PartialEq)]
pub struct CycleModels<F> {
    /// The cycle `(m; r)`.
    pub cycle: Cycle<F>,
    /// The point `(m₁, m₂, m₃, r)` of the cyclographic model.
    pub cyclographic: [F; 4],
    /// The Blaschke hyperplane `(r, m₁, m₂, m₃, 1)`.
    pub blaschke_hyperplane: [F; 5],
    /// The isotropic sphere `y₃ = α(y₁² + y₂²) + β·y + γ`.
    pub isotropic_sphere: IsotropicSphere<F>,
    /// The point of the Möbius quadric model (of the unoriented sphere, `p₀ − p₄ = 1`).
    pub mobius: [F; 5],
}

/// A cycle in every model.
pub fn cycle_models<F: Scalar>(cycle: &Cycle<F>) -> CycleModels<F> {
    let r2 = cycle.radius.clone() * cycle.radius.clone();
    CycleModels {
        cycle: cycle.clone(),
        cyclographic: cycle.to_cyclographic(),
        blaschke_hyperplane: cycle.blaschke_hyperplane(),
        isotropic_sphere: cycle.isotropic_sphere(),
        mobius: mobius_point(&cycle.center, &r2),
    }
}

/// The cycle of a Blaschke hyperplane `(h₀, …, h₄)` (any non-zero multiple of
/// `(r, m₁, m₂, m₃, 1)`).
///
/// # Errors
/// [`LaguerreError::Degenerate`] if `h₄ = 0` (a hyperplane through the cylinder's vertex
/// direction is no cycle).
pub fn cycle_from_blaschke<F: Scalar>(h: &[F; 5]) -> Result<Cycle<F>, LaguerreError> {
    if h[4].is_zero() {
        return Err(LaguerreError::Degenerate(format!(
            "the Blaschke hyperplane {} has h₄ = 0: it is not the hyperplane of a cycle",
            format_point(h)
        )));
    }
    let k = h[4].clone();
    Cycle::new(
        [
            h[1].clone() / k.clone(),
            h[2].clone() / k.clone(),
            h[3].clone() / k.clone(),
        ],
        h[0].clone() / k,
    )
}

/// The oriented cycles of a point `p` of the Möbius quadric model with `p₀ ≠ p₄`: the
/// sphere `μ(p)` with centre `pᵢ/(p₀ − p₄)` and `r² = Q(p)/(p₀ − p₄)²` (2.13), oriented
/// both ways, when `r²` is the square of a rational; a point of `Q` gives one point cycle.
///
/// # Errors
/// [`LaguerreError::Degenerate`] for `p = 0`, for a plane or the north pole
/// (`p₀ = p₄`), for an imaginary sphere (`r² < 0`) and for an irrational radius (named).
pub fn cycles_from_mobius(
    p: &[rcagd_algebra::Rational; 5],
) -> Result<Vec<Cycle<rcagd_algebra::Rational>>, LaguerreError> {
    let img = mobius_image(p).map_err(|e| LaguerreError::Degenerate(e.to_string()))?;
    match img {
        MobiusImage::Point(m) => Ok(vec![Cycle::point(m)]),
        MobiusImage::Sphere { center, radius_sq } => {
            if radius_sq < rcagd_algebra::Rational::from(0) {
                return Err(LaguerreError::Degenerate(format!(
                    "the point {} lies inside the Möbius quadric: an imaginary sphere, r² = {}",
                    format_point(p),
                    format_scalar(&radius_sq)
                )));
            }
            let r = rcagd_algebra::rational::rational_sqrt(&radius_sq).ok_or_else(|| {
                LaguerreError::Degenerate(format!(
                    "the sphere of {} has r² = {}, not the square of a rational: no rational cycle",
                    format_point(p),
                    format_scalar(&radius_sq)
                ))
            })?;
            Ok(vec![
                Cycle::new(center.clone(), r.clone())?,
                Cycle::new(center, -r)?,
            ])
        }
        MobiusImage::Plane(a) => Err(LaguerreError::Degenerate(format!(
            "the point {} has p₀ = p₄: it is the plane {} + {}·y₁ + {}·y₂ + {}·y₃ = 0, not a sphere",
            format_point(p),
            format_scalar(&a[0]),
            format_scalar(&a[1]),
            format_scalar(&a[2]),
            format_scalar(&a[3])
        ))),
        MobiusImage::Infinity => Err(LaguerreError::Degenerate(
            "the point is the north pole N = (1, 0, 0, 0, 1): the point at infinity".into(),
        )),
    }
}

impl<F: Scalar> crate::Certified for CycleModels<F> {
    /// Round trips of every model; Lemma 3.1 at the six tangent planes with normals
    /// `Λ⁻¹(u, v)`, `(u, v)` unisolvent for degree 2 (so the isotropic images of all
    /// tangent planes lie on the isotropic sphere); the Blaschke points of these planes on
    /// the Blaschke hyperplane; their contact points `m + r n` on the Möbius sphere
    /// (`B(μ⁻¹(x), p) = 0`).
    fn certify(&self) -> Vec<Certificate> {
        let c = &self.cycle;
        let mut out = Vec::new();
        let back = [
            ("cyclographic", Cycle::from_cyclographic(&self.cyclographic)),
            ("isotropic sphere", self.isotropic_sphere.to_cycle()),
        ];
        for (name, b) in back {
            out.push(Certificate::decide(
                format!("the {name} model returns the cycle"),
                &b == c || !F::EXACT && close_cycles(&b, c),
                F::EXACT,
                || format!("{} vs {}", format_cycle(&b), format_cycle(c)),
            ));
        }
        let bl = cycle_from_blaschke(&self.blaschke_hyperplane);
        out.push(Certificate::decide(
            "the Blaschke hyperplane (r, m, 1) returns the cycle",
            bl.as_ref()
                .is_ok_and(|b| b == c || !F::EXACT && close_cycles(b, c)),
            F::EXACT,
            || format!("{bl:?}"),
        ));
        let r2 = c.radius.clone() * c.radius.clone();
        let mob_ok = match mobius_image(&self.mobius) {
            Ok(MobiusImage::Sphere { center, radius_sq }) => {
                center == c.center && radius_sq == r2
                    || !F::EXACT
                        && close_cycles(
                            &Cycle {
                                center,
                                radius: radius_sq,
                            },
                            &Cycle {
                                center: c.center.clone(),
                                radius: r2.clone(),
                            },
                        )
            }
            Ok(MobiusImage::Point(m)) => zero(&r2) && (m == c.center || !F::EXACT),
            _ => false,
        };
        out.push(Certificate::decide(
            "the Möbius point is the sphere |y − m|² = r² (Peternell (2.13))",
            mob_ok,
            F::EXACT,
            || format_point(&self.mobius),
        ));
        let mut iso = true;
        let mut bla = true;
        let mut mob = true;
        for (u, v) in SAMPLES {
            let e = tangent_plane(c, sample_normal(u, v));
            match e.to_isotropic() {
                Ok(y) => iso &= self.isotropic_sphere.contains(&y),
                Err(_) => iso = false,
            }
            let b = e.to_blaschke();
            let h = &self.blaschke_hyperplane;
            bla &= zero(&(0..5).fold(F::zero(), |acc, i| acc + h[i].clone() * b[i].clone()));
            let x: [F; 3] =
                core::array::from_fn(|i| c.center[i].clone() + c.radius.clone() * e.n[i].clone());
            mob &= zero(&mobius_bilinear(
                &mobius_point(&x, &F::zero()),
                &self.mobius,
            ));
        }
        out.push(Certificate::decide(
            "Lemma 3.1 (3.12): Λ of every tangent plane lies on the isotropic sphere (six planes, unisolvent for degree 2)",
            iso,
            F::EXACT,
            || "a tangent plane maps off the isotropic sphere".into(),
        ));
        out.push(Certificate::decide(
            "the Blaschke points of tangent planes lie on the Blaschke hyperplane (six planes)",
            bla,
            F::EXACT,
            || "a Blaschke point is off the hyperplane".into(),
        ));
        out.push(Certificate::decide(
            "the contact points m + r n lie on the Möbius sphere: B(μ⁻¹(x), p) = 0 (six planes)",
            mob,
            F::EXACT,
            || "a contact point is off the sphere".into(),
        ));
        out
    }
}

fn close_cycles<F: Scalar>(a: &Cycle<F>, b: &Cycle<F>) -> bool {
    let d: Vec<F> = a
        .to_cyclographic()
        .iter()
        .zip(b.to_cyclographic().iter())
        .map(|(x, y)| x.clone() - y.clone())
        .collect();
    let scale = a
        .to_cyclographic()
        .iter()
        .map(|x| x.to_f64().abs())
        .fold(1.0, f64::max);
    d.iter().all(|x| crate::certs::is_negligible(x, scale))
}

/// `(m₁, m₂, m₃; r)`.
pub fn format_cycle<F: Scalar>(c: &Cycle<F>) -> String {
    format!(
        "({}, {}, {}; {})",
        format_scalar(&c.center[0]),
        format_scalar(&c.center[1]),
        format_scalar(&c.center[2]),
        format_scalar(&c.radius)
    )
}

/// An oriented plane in every model.
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneModels<F> {
    /// The oriented plane `e0 + n·x = 0`.
    pub plane: OrientedPlane<F>,
    /// The γ-hyperplane `(e0, n, 1)` of the cyclographic model.
    pub gamma_hyperplane: [F; 5],
    /// The point `(1, n, e0)` of the Blaschke cylinder.
    pub blaschke: [F; 5],
    /// `Λ(e) = (e1, e2, e0)/(1 − e3)`, `None` for `n = (0, 0, 1)`.
    pub isotropic: Option<[F; 3]>,
    /// The bisector plane `Λ*(e) = (e0, e1, e2, e3 − 1)` of the dual isotropic model;
    /// `None` for `n = (0, 0, 1)` (the fixed plane's parallels map to the plane at infinity,
    /// Peternell §3.5).
    pub dual_isotropic: Option<[F; 4]>,
    /// The point `(−e0, n, −e0)` of the Möbius quadric model (the unoriented plane).
    pub mobius: [F; 5],
}

/// An oriented plane in every model.
pub fn plane_models<F: Scalar>(plane: &OrientedPlane<F>) -> PlaneModels<F> {
    PlaneModels {
        plane: plane.clone(),
        gamma_hyperplane: plane.to_gamma_hyperplane(),
        blaschke: plane.to_blaschke(),
        isotropic: plane.to_isotropic().ok(),
        dual_isotropic: plane.to_isotropic().ok().map(|_| plane.to_dual_isotropic()),
        mobius: mobius_plane_point(&plane.n, &-plane.e0.clone()),
    }
}

impl<F: Scalar> crate::Certified for PlaneModels<F> {
    /// Round trips through the γ-hyperplane, the Blaschke point, the isotropic point
    /// (3.13) and the dual isotropic plane ((3.17) with the orienting factor); the Möbius
    /// point is the plane; the Blaschke point lies on the cylinder `x₁² + x₂² + x₃² = x₀²`.
    fn certify(&self) -> Vec<Certificate> {
        let e = &self.plane;
        let same = |b: &Result<OrientedPlane<F>, LaguerreError>| {
            b.as_ref().is_ok_and(|b| {
                b == e
                    || !F::EXACT && {
                        let d = [
                            b.e0.clone() - e.e0.clone(),
                            b.n[0].clone() - e.n[0].clone(),
                            b.n[1].clone() - e.n[1].clone(),
                            b.n[2].clone() - e.n[2].clone(),
                        ];
                        d.iter()
                            .all(|x| crate::certs::is_negligible(x, 1.0 + e.e0.to_f64().abs()))
                    }
            })
        };
        let mut out = Vec::new();
        let mut checks: Vec<(&str, Result<OrientedPlane<F>, LaguerreError>)> = vec![
            (
                "the γ-hyperplane (3.5) returns the plane",
                OrientedPlane::from_gamma_hyperplane(&self.gamma_hyperplane),
            ),
            (
                "the Blaschke point (3.10) returns the plane",
                OrientedPlane::from_blaschke(&self.blaschke),
            ),
        ];
        if let Some(d) = &self.dual_isotropic {
            checks.push(("the dual isotropic plane returns the oriented plane ((3.17) with its orienting factor)", OrientedPlane::from_dual_isotropic(d)));
        }
        for (name, b) in checks {
            out.push(Certificate::decide(name, same(&b), F::EXACT, || {
                format!("{b:?}")
            }));
        }
        if let Some(y) = &self.isotropic {
            let b = Ok(OrientedPlane::from_isotropic(y));
            out.push(Certificate::decide(
                "Λ⁻¹(Λ(e)) = e ((3.11), (3.13))",
                same(&b),
                F::EXACT,
                || format!("{b:?}"),
            ));
        }
        let b = &self.blaschke;
        let cyl =
            b[1].clone() * b[1].clone() + b[2].clone() * b[2].clone() + b[3].clone() * b[3].clone()
                - b[0].clone() * b[0].clone();
        out.push(Certificate::decide(
            "the Blaschke point lies on the cylinder x₁² + x₂² + x₃² = x₀²",
            zero(&cyl),
            F::EXACT,
            || format_scalar(&cyl),
        ));
        let mob_ok = match mobius_image(&self.mobius) {
            Ok(MobiusImage::Plane(a)) => {
                let want = [e.e0.clone(), e.n[0].clone(), e.n[1].clone(), e.n[2].clone()];
                a.iter()
                    .zip(&want)
                    .all(|(x, y)| zero(&(x.clone() - y.clone())))
            }
            _ => false,
        };
        out.push(Certificate::decide(
            "the Möbius point (−e0, n, −e0) has p₀ = p₄: the plane e0 + n·y = 0 (Peternell §2.4)",
            mob_ok,
            F::EXACT,
            || format_point(&self.mobius),
        ));
        out
    }
}

/// The isotropic-model function of a quadric `Xᵀ Q X = 0` (`X = (w, x, y, z)`): its
/// tangent planes `Λ⁻¹(y₁, y₂, y₃)` satisfy `A y₃² + B(y₁, y₂) y₃ + C(y₁, y₂) = 0`.
#[derive(Debug, Clone)]
pub struct IsotropicQuadric<F> {
    /// `Q`.
    pub quadric: Mat4<F>,
    /// The dual quadric `Q* = adj Q` (tangent planes `uᵀ Q* u = 0`).
    pub dual: Mat4<F>,
    /// `det Q`.
    pub det: F,
    /// `A = 4 Q*₀₀`.
    pub a: F,
    /// `B = 4(2y₁Q*₀₁ + 2y₂Q*₀₂ + (S − 1)Q*₀₃)`, `S = y₁² + y₂²`.
    pub b: MPoly<F>,
    /// `C = (0, 2y₁, 2y₂, S − 1) Q* (0, 2y₁, 2y₂, S − 1)ᵀ`.
    pub c: MPoly<F>,
    /// `B² − 4AC`.
    pub discriminant: MPoly<F>,
    /// `F = −C/B` when `A = 0` (the quadric touches the plane at infinity).
    pub rational: Option<RatFn<F>>,
    /// `g` with `g² = B² − 4AC` when `A ≠ 0` and the discriminant is a square in
    /// `Q[y₁, y₂]` (exact scalars): the two rational branches `F± = (−B ± g)/(2A)` (the two
    /// orientations of the tangent planes; for a sphere its two isotropic spheres).
    pub discriminant_root: Option<MPoly<F>>,
}

/// The branches `F± = (−B ± g)/(2A)` for a square discriminant `g²`.
impl<F: Scalar> IsotropicQuadric<F> {
    /// `[F+, F−]` when both are rational (`A ≠ 0`, `B² − 4AC = g²`).
    pub fn branches(&self) -> Option<[RatFn<F>; 2]> {
        let g = self.discriminant_root.as_ref()?;
        let den = MPoly::constant(2, F::from_i64(2) * self.a.clone());
        let mk = |num: MPoly<F>| RatFn::new(num, den.clone()).ok();
        Some([
            mk(g.clone() - self.b.clone())?,
            mk(-(g.clone() + self.b.clone()))?,
        ])
    }
}

/// The square root of a polynomial in the lexicographic monomial order (exact scalars):
/// the leading term of `g` is the root of that of `p`, every further term `t` is
/// `LT(p − g²)/(2 LT(g))`; `None` if a step is not exact or the remainder does not vanish.
fn mpoly_sqrt<F: Scalar>(p: &MPoly<F>) -> Option<MPoly<F>> {
    if !F::EXACT || p.is_zero() {
        return None;
    }
    let n = p.nvars();
    let lt = |q: &MPoly<F>| q.terms().last().map(|(e, c)| (e.to_vec(), c.clone()));
    let (e0, c0) = lt(p)?;
    if e0.iter().any(|d| d % 2 != 0) {
        return None;
    }
    let lead_e: Vec<u32> = e0.iter().map(|d| d / 2).collect();
    let lead_c = rcagd_algebra::scalar::sqrt_in_field(&c0)?;
    let mut g = MPoly::monomial(n, &lead_e, lead_c.clone());
    let two_lead = F::from_i64(2) * lead_c;
    let bound = p.num_terms() * 4 + 8;
    for _ in 0..bound {
        let r = p.clone() - g.clone() * g.clone();
        let Some((e, c)) = lt(&r) else {
            return Some(g);
        };
        if e.iter().zip(&lead_e).any(|(a, b)| a < b) || e >= e0 {
            return None;
        }
        let te: Vec<u32> = e.iter().zip(&lead_e).map(|(a, b)| a - b).collect();
        if te >= lead_e {
            return None;
        }
        g += MPoly::monomial(n, &te, c / two_lead.clone());
    }
    None
}

fn adjugate<F: Scalar>(q: &Mat4<F>) -> Mat4<F> {
    core::array::from_fn(|i| {
        core::array::from_fn(|j| {
            // (adj Q)_ij = (−1)^{i+j} det(Q without row j and column i)
            let minor: Vec<Vec<F>> = (0..4)
                .filter(|&r| r != j)
                .map(|r| {
                    (0..4)
                        .filter(|&c| c != i)
                        .map(|c| q[r][c].clone())
                        .collect()
                })
                .collect();
            let d = helpers::det(&minor);
            if (i + j) % 2 == 0 {
                d
            } else {
                -d
            }
        })
    })
}

/// `u(y) = (2y₃, 2y₁, 2y₂, y₁² + y₂² − 1)` in `nvars` variables (`y₃` the third, if any).
fn plane_coords<F: Scalar>(nvars: usize) -> [MPoly<F>; 4] {
    let y1 = MPoly::var(nvars, 0);
    let y2 = MPoly::var(nvars, 1);
    let two = F::from_i64(2);
    let s = y1.clone() * y1.clone() + y2.clone() * y2.clone() - MPoly::constant(nvars, F::one());
    let u0 = if nvars > 2 {
        MPoly::var(nvars, 2).scale(&two)
    } else {
        MPoly::zero(nvars)
    };
    [u0, y1.scale(&two), y2.scale(&two), s]
}

fn form<F: Scalar>(m: &Mat4<F>, u: &[MPoly<F>; 4], nvars: usize) -> MPoly<F> {
    let mut out = MPoly::zero(nvars);
    for i in 0..4 {
        for j in 0..4 {
            if !m[i][j].is_zero() {
                out += (u[i].clone() * u[j].clone()).scale(&m[i][j]);
            }
        }
    }
    out
}

/// The isotropic-model function of the quadric `Q` (symmetric 4×4).
///
/// # Errors
/// [`LaguerreError::Degenerate`] if `Q` is not symmetric, is singular (a cone or
/// cylinder: its tangent planes form a curve of the isotropic model, not a graph), or if
/// `A = B = 0` (no graph: the quadric touches the plane at infinity along a line).
pub fn isotropic_quadric<F: Scalar>(q: &Mat4<F>) -> Result<IsotropicQuadric<F>, LaguerreError> {
    for i in 0..4 {
        for j in i + 1..4 {
            if !zero(&(q[i][j].clone() - q[j][i].clone())) {
                return Err(LaguerreError::Degenerate(format!(
                    "the matrix is not symmetric (entry ({i}, {j}))"
                )));
            }
        }
    }
    let rows: Vec<Vec<F>> = q.iter().map(|r| r.to_vec()).collect();
    let det = helpers::det(&rows);
    if zero(&det) {
        return Err(LaguerreError::Degenerate(
            "det Q = 0: a cone, cylinder or plane pair; its tangent planes are a curve (or less) of the isotropic model, not a graph y₃ = F(y₁, y₂)".into(),
        ));
    }
    let dual = adjugate(q);
    let u = plane_coords::<F>(2);
    let four = F::from_i64(4);
    let a = four.clone() * dual[0][0].clone();
    let mut b = MPoly::zero(2);
    for j in 1..4 {
        b += u[j].scale(&(four.clone() * dual[0][j].clone()));
    }
    let c = form(&dual, &u, 2);
    let discriminant = b.clone() * b.clone() - c.scale(&(four * a.clone()));
    let rational = if zero(&a) {
        if b.is_zero() {
            return Err(LaguerreError::Degenerate(
                "A = B = 0: the tangent planes do not form a graph y₃ = F(y₁, y₂)".into(),
            ));
        }
        Some(
            RatFn::new(c.scale(&-F::one()), b.clone())
                .map_err(|e| LaguerreError::Degenerate(e.to_string()))?,
        )
    } else {
        None
    };
    let discriminant_root = if rational.is_none() {
        mpoly_sqrt(&discriminant)
    } else {
        None
    };
    Ok(IsotropicQuadric {
        quadric: q.clone(),
        dual,
        det,
        a,
        b,
        c,
        discriminant,
        rational,
        discriminant_root,
    })
}

impl<F: Scalar> IsotropicQuadric<F> {
    /// The PN surface `Λ⁻¹` of the graph `y₃ = F` for a rational `F` (the quadric with its
    /// rational unit normals, Peternell Thm 4.3/4.4).
    ///
    /// # Errors
    /// [`LaguerreError::Degenerate`] if `F` is not rational or the surface is degenerate.
    pub fn pn_surface(&self) -> Result<crate::pn::PnSurface<F>, LaguerreError> {
        let f = self.rational.as_ref().ok_or_else(|| {
            LaguerreError::Degenerate(
                "F is not rational (A ≠ 0): F = (−B ± √(B² − 4AC))/(2A)".into(),
            )
        })?;
        IsotropicSurface::graph(f)
            .to_pn_surface()
            .map_err(|e| LaguerreError::Degenerate(e.to_string()))
    }
}

impl<F: Scalar> crate::Certified for IsotropicQuadric<F> {
    /// `Q*·Q = det Q · I`; `u(y)ᵀ Q* u(y) ≡ A y₃² + B y₃ + C` in `(y₁, y₂, y₃)`; for a
    /// rational `F`: the points of its PN surface lie on the quadric, `xᵀ Q x ≡ 0`.
    fn certify(&self) -> Vec<Certificate> {
        let prod = helpers::mat_mul(&self.dual, &self.quadric);
        let ok = (0..4).all(|i| {
            (0..4).all(|j| {
                let want = if i == j { self.det.clone() } else { F::zero() };
                crate::certs::is_negligible(&(prod[i][j].clone() - want), self.det.to_f64().abs())
            })
        });
        let mut out = vec![Certificate::decide(
            "Q*·Q = det Q · I: Q* = adj Q is the dual quadric (tangent planes uᵀ Q* u = 0)",
            ok,
            F::EXACT,
            || "adj Q · Q ≠ det Q · I".into(),
        )];
        let u3 = plane_coords::<F>(3);
        let full = form(&self.dual, &u3, 3);
        let lift = |p: &MPoly<F>| -> MPoly<F> {
            let terms: Vec<(Vec<u32>, F)> = p
                .terms()
                .map(|(e, c)| (vec![e[0], e[1], 0], c.clone()))
                .collect();
            MPoly::from_terms(3, terms).unwrap_or_else(|_| MPoly::zero(3))
        };
        let y3 = MPoly::var(3, 2);
        let quad = (y3.clone() * y3.clone()).scale(&self.a) + lift(&self.b) * y3 + lift(&self.c);
        let diff = full - quad;
        let ok = diff
            .terms()
            .all(|(_, c)| crate::certs::is_negligible(c, 1.0));
        out.push(Certificate::decide(
            "u(y)ᵀ Q* u(y) ≡ A y₃² + B y₃ + C for the plane u(y) = (2y₃, 2y₁, 2y₂, y₁² + y₂² − 1) ∥ Λ⁻¹(y) (3.13)",
            ok,
            F::EXACT,
            || format!("residual {diff:?}"),
        ));
        if let Some(g) = &self.discriminant_root {
            let d = g.clone() * g.clone() - self.discriminant.clone();
            out.push(Certificate::decide(
                "g² ≡ B² − 4AC: both branches F± = (−B ± g)/(2A) are rational",
                d.is_zero(),
                F::EXACT,
                || format!("residual {d:?}"),
            ));
        }
        for (k, f) in self.branches().into_iter().flatten().enumerate() {
            if let Ok(s) = IsotropicSurface::graph(&f).to_pn_surface() {
                let x = s.point_polys();
                let r = form(&self.quadric, x, x[0].nvars());
                let ok = r.terms().all(|(_, c)| crate::certs::is_negligible(c, 1.0));
                out.push(Certificate::decide(
                    format!(
                        "the PN surface Λ⁻¹ of the branch F{} lies on the quadric: xᵀ Q x ≡ 0",
                        if k == 0 { "+" } else { "−" }
                    ),
                    ok,
                    F::EXACT,
                    || format!("residual {r:?}"),
                ));
            }
        }
        if let Ok(s) = self.pn_surface() {
            let x = s.point_polys();
            let r = form(&self.quadric, x, x[0].nvars());
            let ok = r.terms().all(|(_, c)| crate::certs::is_negligible(c, 1.0));
            out.push(Certificate::decide(
                "the PN surface Λ⁻¹ of y₃ = F lies on the quadric: xᵀ Q x ≡ 0",
                ok,
                F::EXACT,
                || format!("residual {r:?}"),
            ));
        }
        out
    }
}

/// The cycles of a Laguerre map `x ↦ a + λAx` of the cyclographic model: images of
/// given cycles and the fixed cycles `(I − λA)x = a`.
#[derive(Debug, Clone, PartialEq)]
pub struct LaguerreCycles<F> {
    /// The map.
    pub map: LaguerreMap<F>,
    /// `(c, map(c))` for the given cycles.
    pub images: Vec<(Cycle<F>, Cycle<F>)>,
    /// A fixed cycle, if any.
    pub fixed: Option<Cycle<F>>,
    /// A basis of the directions `d` with `λAd = d`: the fixed cycles are
    /// `fixed + span(directions)`.
    pub fixed_directions: Vec<[F; 4]>,
}

/// Images and fixed cycles of a Laguerre map.
pub fn laguerre_cycles<F: Scalar>(map: &LaguerreMap<F>, cycles: &[Cycle<F>]) -> LaguerreCycles<F> {
    let images = cycles
        .iter()
        .map(|c| (c.clone(), map.apply_cycle(c)))
        .collect();
    let a = map.matrix();
    let lam = map.scale();
    let shift = map.shift();
    // rows of [I − λA | −a] for the unknowns (x, 1)
    let m: Vec<Vec<F>> = (0..4)
        .map(|i| {
            let mut row: Vec<F> = (0..4)
                .map(|j| {
                    let id = if i == j { F::one() } else { F::zero() };
                    id - lam.clone() * a[i][j].clone()
                })
                .collect();
            row.push(-shift[i].clone());
            row
        })
        .collect();
    let ns = helpers::null_space(&m, 5);
    let fixed = ns.iter().find(|v| !zero(&v[4])).map(|v| {
        let k = v[4].clone();
        Cycle {
            center: [
                v[0].clone() / k.clone(),
                v[1].clone() / k.clone(),
                v[2].clone() / k.clone(),
            ],
            radius: v[3].clone() / k,
        }
    });
    let sq: Vec<Vec<F>> = m.iter().map(|r| r[..4].to_vec()).collect();
    let fixed_directions = helpers::null_space(&sq, 4)
        .into_iter()
        .map(|v| [v[0].clone(), v[1].clone(), v[2].clone(), v[3].clone()])
        .collect();
    LaguerreCycles {
        map: map.clone(),
        images,
        fixed,
        fixed_directions,
    }
}

impl<F: Scalar> crate::Certified for LaguerreCycles<F> {
    /// The map's own certificates; for each image: the six tangent planes of the cycle
    /// (normals `Λ⁻¹(u, v)`) map to tangent planes of the image cycle (oriented contact is
    /// preserved, Peternell §3.2); the fixed cycle and directions are fixed exactly.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = crate::Certified::certify(&self.map);
        for (k, (c, img)) in self.images.iter().enumerate() {
            let mut ok = true;
            for (u, v) in SAMPLES {
                let e = tangent_plane(c, sample_normal(u, v));
                match self.map.apply_plane(&e) {
                    Ok(e2) => ok &= zero(&img.contact_residual(&e2)),
                    Err(_) => ok = false,
                }
            }
            out.push(Certificate::decide(
                format!("cycle {k}: tangent planes of {} map to tangent planes of its image {} (six planes)", format_cycle(c), format_cycle(img)),
                ok,
                F::EXACT,
                || "a mapped tangent plane does not touch the image cycle".into(),
            ));
        }
        if let Some(f) = &self.fixed {
            let x = f.to_cyclographic();
            let y = self.map.apply_point(&x);
            out.push(Certificate::decide(
                format!("the cycle {} is fixed: a + λA x = x", format_cycle(f)),
                x.iter()
                    .zip(&y)
                    .all(|(p, q)| zero(&(p.clone() - q.clone()))),
                F::EXACT,
                || format_point(&y),
            ));
        }
        let a = self.map.matrix();
        let lam = self.map.scale();
        let ok = self.fixed_directions.iter().all(|d| {
            (0..4).all(|i| {
                let ad = (0..4).fold(F::zero(), |acc, j| acc + a[i][j].clone() * d[j].clone());
                zero(&(lam.clone() * ad - d[i].clone()))
            })
        });
        out.push(Certificate::decide(
            format!(
                "the {} fixed directions satisfy λA d = d",
                self.fixed_directions.len()
            ),
            ok,
            F::EXACT,
            || "a direction is not fixed".into(),
        ));
        out
    }
}
