//! Anticaustics by reflection for light rays parallel to `xₙ` in `Rⁿ`, of mirror
//! hypersurfaces and of `k`-dimensional mirrors (Peternell §3.6, (3.18) corrected, and
//! Theorem 4.1 with its converse; docs/math/n-dimensional.md#anticaustics).
//!
//! A mirror `p(u)` (`k` parameters) with a normal `m` (for `k < n − 1` every normal of the
//! normal space: `m(u, v) = Σ vᵢNᵢ + N_last`, `v` the `n − k − 1` further parameters)
//! reflects the rays `eₙ` into `r = eₙ − 2mₙ m/|m|²`. The anticaustic is
//! `q = (p₁, …, p_{n−1}, c) + 2(pₙ − c) mₙ m/|m|²` — the reflection of the foot point
//! `(p', c)` in the tangent hyperplane; the printed (3.18) has `(p', 0) − 2(pₙ − c)…`, which
//! is not orthogonal to the reflected rays. `q = p + (c − pₙ) r`, so `q` lies on the
//! reflected ray, `∂q/∂c = r`: varying `c` gives the offsets, and `q` is a PN hypersurface
//! with the rational unit normal `r` (Theorem 4.1).
//!
//! **Converse.** A PN hypersurface `x` with unit normal `n` (`nₙ ≢ 1`) is the anticaustic
//! of the mirror `p = x − ((c − xₙ)/(1 − nₙ)) n` (docs/math/n-dimensional.md#anticaustics);
//! [`mirror_of`] builds it, recomputes its anticaustic and certifies that it is `x`.

use super::hypersurface::PnHypersurface;
use super::poly::{clean, cross, dot, dot_scale, mag};
use super::NdimError;
use crate::error::format_scalar;
use crate::pn::poly::{cancel_common, zero_cert};
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Scalar};

/// The anticaustic of a mirror for light parallel to `xₙ` (module docs).
#[derive(Debug, Clone)]
pub struct Anticaustic<F> {
    mirror: Vec<MPoly<F>>,
    normal: Vec<MPoly<F>>,
    c: F,
    surface: PnHypersurface<F>,
}

/// Tangent vectors `P₀∂ⱼP − P∂ⱼP₀` of a homogeneous map in `k` parameters.
fn tangents<F: Scalar>(p: &[MPoly<F>], k: usize) -> Vec<Vec<MPoly<F>>> {
    (0..k)
        .map(|j| {
            (1..p.len())
                .map(|i| clean(&(&(&p[0] * &p[i].partial(j)) - &(&p[i] * &p[0].partial(j)))))
                .collect()
        })
        .collect()
}

/// The normals of the mirror: one vector (`k = n − 1`) or `Σ vᵢNᵢ + N_last` in the extra
/// parameters `v` (variables `k, …, n − 2`).
fn mirror_normal<F: Scalar>(t: &[Vec<MPoly<F>>], n: usize) -> Result<Vec<MPoly<F>>, NdimError> {
    let k = t.len();
    let basis: Vec<Vec<MPoly<F>>> = (0..n)
        .filter_map(|f| {
            // cross product of the tangents and the unit vectors eⱼ, j ∉ {first n−1−k indices ≠ f}
            let others: Vec<usize> = (0..n).filter(|&j| j != f).take(n - 1 - k).collect();
            let mut rows = t.to_vec();
            for &q in &others {
                let mut e = vec![MPoly::zero(1); n];
                e[q] = MPoly::constant(1, F::one());
                rows.push(e);
            }
            let v: Vec<MPoly<F>> = cross(&rows).iter().map(clean).collect();
            (!v.iter().all(MPoly::is_zero)).then_some(v)
        })
        .collect();
    // keep n − k independent ones (a basis of the normal space)
    let mut chosen: Vec<Vec<MPoly<F>>> = Vec::new();
    for b in basis {
        let mut rows = chosen.clone();
        rows.push(b.clone());
        if super::poly::rank(&rows) == rows.len() {
            chosen.push(b);
        }
        if chosen.len() == n - k {
            break;
        }
    }
    if chosen.len() < n - k {
        return Err(NdimError::Degenerate(format!(
            "the mirror's tangent vectors do not span a {k}-dimensional space"
        )));
    }
    let nv = n - 1;
    let last = chosen.len() - 1;
    Ok((0..n)
        .map(|i| {
            chosen
                .iter()
                .enumerate()
                .fold(MPoly::zero(nv), |acc, (j, b)| {
                    let coef = if j == last {
                        MPoly::constant(nv, F::one())
                    } else {
                        MPoly::var(nv, k + j)
                    };
                    &acc + &(&coef * &b[i])
                })
        })
        .collect())
}

impl<F: Scalar> Anticaustic<F> {
    /// The anticaustic of the mirror `p = (P₁, …, Pₙ)/P₀` in `k = params` parameters
    /// (`1 ≤ k ≤ n − 1`) for the light rays `eₙ`, wavefront height `c`.
    ///
    /// # Errors
    /// [`NdimError::InvalidInput`] for `n < 2`, `k` out of range, `P₀ ≡ 0` or more
    /// variables than `k`; [`NdimError::Degenerate`] if the mirror is not `k`-dimensional.
    pub fn new(mirror: Vec<MPoly<F>>, params: usize, c: F) -> Result<Self, NdimError> {
        let n = mirror.len().saturating_sub(1);
        if n < 2 || params == 0 || params > n - 1 {
            return Err(NdimError::InvalidInput(format!(
                "a mirror of Rⁿ needs n ≥ 2 and 1 ≤ k ≤ n − 1 parameters, got n = {n}, k = {params}"
            )));
        }
        if mirror[0].is_zero() {
            return Err(NdimError::InvalidInput(
                "the mirror's weight P₀ is zero".into(),
            ));
        }
        if mirror.iter().any(|p| {
            p.terms()
                .any(|(e, _)| e.iter().skip(params).any(|&x| x > 0))
        }) {
            return Err(NdimError::InvalidInput(format!(
                "the mirror must depend on its {params} parameters only"
            )));
        }
        let t = tangents(&mirror, params);
        if super::poly::rank(&t) < params {
            return Err(NdimError::Degenerate(format!(
                "the mirror's tangent vectors do not span a {params}-dimensional space"
            )));
        }
        let m = mirror_normal(&t, n)?;
        let mm = dot(&m, &m);
        let two = F::from_i64(2);
        let p0 = &mirror[0];
        // lift = 2 (Pₙ − c P₀) mₙ
        let lift = (&(&mirror[n] - &p0.scale(&c)) * &m[n - 1]).scale(&two);
        let mut point = vec![p0 * &mm];
        for i in 0..n {
            let base = if i + 1 < n {
                &mirror[i + 1] * &mm
            } else {
                &p0.scale(&c) * &mm
            };
            point.push(clean(&(&base + &(&lift * &m[i]))));
        }
        // unit normal r = (|m|² eₙ − 2mₙ m)/|m|², plane E₀ = −E·Q/Q₀ scaled by Q₀
        let r: Vec<MPoly<F>> = (0..n)
            .map(|i| {
                let t = (&m[n - 1] * &m[i]).scale(&two);
                if i + 1 == n {
                    clean(&(&mm - &t))
                } else {
                    -t
                }
            })
            .collect();
        let mut plane = vec![-dot(&r, &point[1..])];
        plane.extend(r.iter().map(|x| x * &point[0]));
        let norm = &mm * &point[0];
        let mut all = plane.clone();
        all.push(norm.clone());
        cancel_common(&mut all, &[point[0].clone(), mm.clone()]);
        let norm = all.pop().unwrap_or(norm);
        cancel_common(&mut point, std::slice::from_ref(&mm));
        let surface = PnHypersurface::from_parts(
            format!(
                "anticaustic in R^{n} of a {params}-dimensional mirror ((3.18) corrected), c = {}",
                format_scalar(&c)
            ),
            all,
            norm,
            point,
        )
        .ensure_hypersurface()?;
        Ok(Anticaustic {
            mirror,
            normal: m,
            c,
            surface,
        })
    }

    /// The anticaustic, a PN hypersurface in `(u, v)` with unit normal `r`.
    pub fn surface(&self) -> &PnHypersurface<F> {
        &self.surface
    }

    /// The wavefront height `c`.
    pub fn c(&self) -> &F {
        &self.c
    }

    /// The mirror's homogeneous point `(P₀, …, Pₙ)`.
    pub fn mirror(&self) -> &[MPoly<F>] {
        &self.mirror
    }

    /// `(q − p) ∥ r`: `(q − p)ᵢ rⱼ − (q − p)ⱼ rᵢ ≡ 0` for all `i < j` (the anticaustic point
    /// on the reflected ray through the mirror point).
    pub fn ray_certificates(&self) -> Vec<Certificate> {
        let q = self.surface.point_polys();
        let e = self.surface.plane_polys();
        let p = &self.mirror;
        let n = p.len() - 1;
        let d: Vec<MPoly<F>> = (1..=n)
            .map(|i| &(&q[i] * &p[0]) - &(&p[i] * &q[0]))
            .collect();
        let r = &e[1..];
        let mut out = Vec::new();
        for i in 0..n {
            for j in i + 1..n {
                let c = &(&d[i] * &r[j]) - &(&d[j] * &r[i]);
                out.push(zero_cert(
                    &format!("anticaustic point on the reflected ray through the mirror point ((q − p)×r, {}{})", i + 1, j + 1),
                    &c,
                    dot_scale(&[d[i].clone(), d[j].clone()], &[r[j].clone(), r[i].clone()]),
                ));
            }
        }
        let _ = &self.normal;
        out
    }
}

impl<F: Scalar> Certified for Anticaustic<F> {
    /// The PN identities of the anticaustic (its unit normal is the reflected ray `r`, and
    /// `r ⟂ ∂q`: Theorem 4.1) and the reflected-ray certificates.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.surface.certify();
        out.extend(self.ray_certificates());
        out
    }
}

/// The converse of Theorem 4.1: the mirror `p = x − ((c − xₙ)/(1 − nₙ)) n` of which the PN
/// hypersurface `x` is the anticaustic for light parallel to `xₙ` and wavefront height `c`
/// (module docs), with the anticaustic of that mirror recomputed from the mirror alone and
/// the certificate that it is `x` again.
///
/// # Errors
/// [`NdimError::Degenerate`] if `nₙ ≡ 1` (a horizontal hyperplane) or the mirror degenerates.
pub fn mirror_of<F: Scalar>(
    surface: &PnHypersurface<F>,
    c: &F,
) -> Result<(Anticaustic<F>, Certificate), NdimError> {
    let n = surface.dim();
    let x = surface.point_polys();
    let e = surface.plane_polys();
    let l = surface.norm_poly();
    // p = x − ((c − xₙ)/(1 − nₙ)) n = [X (L − Eₙ) − (cX₀ − Xₙ) E] / (X₀ (L − Eₙ))
    let ld = clean(&(l - &e[n]));
    if ld.is_zero() {
        return Err(NdimError::Degenerate(
            "nₙ ≡ 1: a hyperplane orthogonal to the light is no anticaustic of a mirror".into(),
        ));
    }
    let s = &x[0].scale(c) - &x[n];
    let mut mirror = vec![&x[0] * &ld];
    mirror.extend((1..=n).map(|i| clean(&(&(&x[i] * &ld) - &(&s * &e[i])))));
    cancel_common(&mut mirror, &[ld.clone(), x[0].clone()]);
    let ac = Anticaustic::new(mirror, n - 1, c.clone())?;
    let q = ac.surface().point_polys();
    let mut res = MPoly::zero(0);
    let mut scale = 1.0f64;
    for i in 1..=n {
        let r = &(&q[i] * &x[0]) - &(&x[i] * &q[0]);
        scale = scale.max(mag(&q[i]) * mag(&x[0]) * 16.0);
        res = &res + &(&r * &r);
    }
    let cert = zero_cert(
        "converse of Theorem 4.1: the anticaustic of the constructed mirror is the given hypersurface (q ≡ x)",
        &res,
        scale * scale,
    );
    Ok((ac, cert))
}
