//! The canal surface from an arbitrary rational normal field (Gruber §2.1, (2.10) ff.,
//! with a given rational point on every circle of normals instead of a split of
//! `|ṁ|² − ṙ²`; docs/math/sphere-families.md, "Canal surfaces from a rational normal
//! field").
//!
//! The unit normals of the canal surface along the characteristic circle at `t` are the unit
//! vectors `n` with `⟨n, ṁ⟩ + ṙ = 0` (Gruber (2.9)–(2.11), sign corrected): a circle on the
//! unit sphere. Given one rational point `n₀(t)` of it (a rational unit normal field along
//! the spine), every other point is the second intersection of the line `n₀ + λv` with the
//! unit sphere for a direction `v ⊥ ṁ`: with `v(t, u) = e₁ + u e₂`,
//! `e₁ = ṁ × a`, `e₂ = ṁ × e₁` (`a` a fixed coordinate axis),
//!
//! ```text
//! n(t, u) = n₀ − 2⟨n₀, v⟩/|v|² · v,     x(t, u) = m(t) + r(t) n(t, u),
//! ```
//!
//! rational of degree 2 in `u`. The split `D = g₁² + g₂²` of Peternell–Pottmann is one way to
//! obtain `n₀`; any rational unit field with `⟨n₀, ṁ⟩ + ṙ = 0` serves.

use super::{CanalError, CanalSpine};
use crate::error::format_scalar;
use crate::pn::poly::{identity_cert, mag, patch_of, zero_cert, Domain};
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Poly, Scalar};
use rcagd_geom::BezierPatch;

/// The canal surface `x(t, u)` of a rational normal field (module docs).
#[derive(Debug, Clone)]
pub struct NormalFieldCanal<F> {
    /// Homogeneous `(X₀, X₁, X₂, X₃)` in `(t, u)`.
    x: [MPoly<F>; 4],
    /// `(W, M₁, M₂, M₃, R)` of the spine in `(t, u)`.
    spine: [MPoly<F>; 5],
    /// The derivative numerators `P` in `(t, u)`.
    p: [MPoly<F>; 4],
}

fn lift<F: Scalar>(p: &Poly<F>) -> MPoly<F> {
    MPoly::from_poly(p, 2, 0)
}

fn cross<F: Scalar>(a: &[MPoly<F>; 3], b: &[MPoly<F>; 3]) -> [MPoly<F>; 3] {
    [
        &(&a[1] * &b[2]) - &(&a[2] * &b[1]),
        &(&a[2] * &b[0]) - &(&a[0] * &b[2]),
        &(&a[0] * &b[1]) - &(&a[1] * &b[0]),
    ]
}

fn dot<F: Scalar>(a: &[MPoly<F>], b: &[MPoly<F>]) -> MPoly<F> {
    a.iter()
        .zip(b)
        .fold(MPoly::zero(2), |acc, (x, y)| &acc + &(x * y))
}

fn negligible<F: Scalar>(p: &MPoly<F>) -> bool {
    if F::EXACT {
        return p.is_zero();
    }
    let s = p.terms().map(|(_, c)| c.to_f64().abs()).fold(1.0, f64::max);
    p.terms().all(|(_, c)| c.to_f64().abs() <= 1e-9 * s)
}

/// The canal surface of `spine` with the rational unit normal field `n₀ = N/d` along it
/// (module docs).
///
/// # Errors
/// [`CanalError::InvalidArgument`] unless `|N|² ≡ d²` (a unit field) and
/// `⟨N, ṁ⟩ + d ṙ ≡ 0` (on the circles of normals), or if `ṁ ≡ 0`; the errors of
/// [`CanalSpine::derivative_numerators`].
pub fn canal_surface_from_normal_field<F: Scalar>(
    spine: &CanalSpine<F>,
    normal: &[Poly<F>; 3],
    den: &Poly<F>,
) -> Result<NormalFieldCanal<F>, CanalError> {
    if den.is_zero() {
        return Err(CanalError::InvalidArgument(
            "the normal field's denominator is zero".into(),
        ));
    }
    let pd = spine.derivative_numerators()?;
    let p: [MPoly<F>; 4] = core::array::from_fn(|k| lift(&pd[k]));
    let n0: [MPoly<F>; 3] = core::array::from_fn(|k| lift(&normal[k]));
    let d0 = lift(den);
    let unit = &dot(&n0, &n0) - &(&d0 * &d0);
    if !negligible(&unit) {
        return Err(CanalError::InvalidArgument(
            "the normal field is not a unit field: |N|² ≢ d²".into(),
        ));
    }
    let pm: [MPoly<F>; 3] = [p[0].clone(), p[1].clone(), p[2].clone()];
    let on = &dot(&n0, &pm) + &(&d0 * &p[3]);
    if !negligible(&on) {
        return Err(CanalError::InvalidArgument(
            "the normal field is not on the circles of normals: ⟨N, ṁ⟩ + d·ṙ ≢ 0 (Gruber (2.9), sign corrected)".into(),
        ));
    }
    // e₁ = ṁ × a for the coordinate axis a giving the largest cross product
    let mut best: Option<[MPoly<F>; 3]> = None;
    for k in 0..3 {
        let mut a: [MPoly<F>; 3] = core::array::from_fn(|_| MPoly::zero(2));
        a[k] = MPoly::constant(2, F::one());
        let e = cross(&pm, &a);
        if e.iter().all(negligible) {
            continue;
        }
        if best.is_none() {
            best = Some(e);
        }
    }
    let e1 = best.ok_or_else(|| {
        CanalError::InvalidArgument("ṁ ≡ 0: the spine is a point, no circles of normals".into())
    })?;
    let e2 = cross(&pm, &e1);
    let u = MPoly::var(2, 1);
    let v: [MPoly<F>; 3] = core::array::from_fn(|k| &e1[k] + &(&u * &e2[k]));
    let vv = dot(&v, &v);
    let nv = dot(&n0, &v);
    let two = F::from_i64(2);
    let nn: [MPoly<F>; 3] = core::array::from_fn(|k| &(&vv * &n0[k]) - &(&nv * &v[k]).scale(&two));
    let dn = &d0 * &vv;
    let w = lift(spine.weight());
    let m: [MPoly<F>; 3] = core::array::from_fn(|k| lift(&spine.center_polys()[k]));
    let r = lift(spine.radius_poly());
    let x = [
        &w * &dn,
        &(&m[0] * &dn) + &(&r * &nn[0]),
        &(&m[1] * &dn) + &(&r * &nn[1]),
        &(&m[2] * &dn) + &(&r * &nn[2]),
    ];
    Ok(NormalFieldCanal {
        x,
        spine: [w, m[0].clone(), m[1].clone(), m[2].clone(), r],
        p,
    })
}

impl<F: Scalar> NormalFieldCanal<F> {
    /// Homogeneous `(X₀, X₁, X₂, X₃)` in `(t, u)`.
    pub fn homogeneous(&self) -> &[MPoly<F>; 4] {
        &self.x
    }

    /// `(deg_t, deg_u)`.
    pub fn bidegree(&self) -> (usize, usize) {
        self.x.iter().fold((0, 0), |(a, b), p| {
            (
                a.max(p.degree_in(0).unwrap_or(0) as usize),
                b.max(p.degree_in(1).unwrap_or(0) as usize),
            )
        })
    }

    /// The point `x(t, u)`.
    ///
    /// # Errors
    /// [`CanalError::InvalidArgument`] where `X₀ = 0`.
    pub fn eval(&self, t: &F, u: &F) -> Result<[F; 3], CanalError> {
        let at = [t.clone(), u.clone()];
        let h: Vec<F> = self
            .x
            .iter()
            .map(|p| p.eval(&at).unwrap_or_else(|_| F::zero()))
            .collect();
        let inv = h[0].inv().filter(|_| !h[0].is_zero()).ok_or_else(|| {
            CanalError::InvalidArgument(format!(
                "X₀({}, {}) = 0",
                format_scalar(t),
                format_scalar(u)
            ))
        })?;
        Ok(core::array::from_fn(|k| h[k + 1].clone() * inv.clone()))
    }

    /// The rational Bézier patch on `[t₀, t₁] × [u₀, u₁]`.
    ///
    /// # Errors
    /// [`CanalError::InvalidArgument`] for an empty rectangle.
    pub fn patch(&self, t: (F, F), u: (F, F)) -> Result<BezierPatch<F>, CanalError> {
        let d = Domain::new(t.0, t.1, u.0, u.1)
            .map_err(|e| CanalError::InvalidArgument(e.to_string()))?;
        patch_of(&self.x, &d).map_err(|e| CanalError::InvalidArgument(e.to_string()))
    }
}

impl<F: Scalar> Certified for NormalFieldCanal<F> {
    /// With `x = X/X₀`, `m = M/W`, `r = R/W`, `y = X W − M X₀` (`= (x − m)·X₀W`):
    /// `|y|² ≡ R² X₀²` (on the sphere), `⟨y, P⟩ + R X₀ P₄ ≡ 0` (on the characteristic plane,
    /// Gruber (2.2) sign corrected), and `⟨y, ∂X X₀ − X ∂X₀⟩ ≡ 0` for `∂ = ∂_t, ∂_u` (the
    /// surface normal passes through the spine point).
    fn certify(&self) -> Vec<Certificate> {
        let [w, m1, m2, m3, r] = &self.spine;
        let m = [m1, m2, m3];
        let x0 = &self.x[0];
        let y: [MPoly<F>; 3] = core::array::from_fn(|k| &(&self.x[k + 1] * w) - &(m[k] * x0));
        let rx = r * x0;
        let mut out = vec![identity_cert(
            "|x − m|² ≡ r² (the surface lies on the spheres)",
            &dot(&y, &y),
            &(&rx * &rx),
        )];
        let pm = [self.p[0].clone(), self.p[1].clone(), self.p[2].clone()];
        out.push(identity_cert(
            "⟨x − m, ṁ⟩ + r ṙ ≡ 0 (characteristic circles, Gruber (2.2), sign corrected)",
            &dot(&y, &pm),
            &-(&(&rx * &self.p[3])),
        ));
        for (i, name) in [(0usize, "t"), (1, "u")] {
            let d: [MPoly<F>; 3] = core::array::from_fn(|k| {
                &(&self.x[k + 1].partial(i) * x0) - &(&self.x[k + 1] * &x0.partial(i))
            });
            // the scale of the products (the residual itself is the cancelled sum)
            let terms = y.iter().chain(&d).map(MPoly::num_terms).max().unwrap_or(1);
            let scale = 16.0
                * (0..3).map(|k| mag(&y[k]) * mag(&d[k])).sum::<f64>()
                * (1 + terms * terms) as f64;
            out.push(zero_cert(
                &format!("⟨x − m, ∂{name}x⟩ ≡ 0 (the normal passes through the spine point)"),
                &dot(&y, &d),
                scale,
            ));
        }
        out
    }
}
