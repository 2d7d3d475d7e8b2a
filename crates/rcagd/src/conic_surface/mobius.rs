//! Sphere families from curves of the Möbius model, and canal hypersurfaces of `Rⁿ`
//! (M. Peternell, "Rational Parametrizations for Envelopes of Quadric Families", §2.2:
//! (2.12), (2.13), Thm 2.3 and the remark after it (Cor. 2.3); derivation in
//! `docs/math/conic-surfaces.md`, section "Möbius model and canal hypersurfaces").
//!
//! **Möbius model (2.12)/(2.13).** The quadric `Q: −x₀² + x₁² + … + x_{n+1}² = 0` of
//! `P^{n+1}`; a point `p ∉ Q` with `p₀ ≠ p_{n+1}` is the sphere of `Rⁿ` with centre
//! `pᵢ/(p₀ − p_{n+1})` and squared radius `(p₁² + … + p_{n+1}² − p₀²)/(p₀ − p_{n+1})²`.
//! So a rational curve `c(t)` of `P^{n+1}` is the sphere family `|y − M/w|² = R/w²` with
//! `w = c₀ − c_{n+1}`, `M = (c₁, …, cₙ)`, `R = c₁² + … + c_{n+1}² − c₀²`: only the squared
//! radius is rational (Thm 2.3). For `n = 3` the canal surface is built by
//! [`super::cones::CanalViaCones`].
//!
//! **Canal hypersurfaces (Cor. 2.3).** The envelope of `S(t): |y − M/w|² = R/w²` in `Rⁿ`
//! touches `S(t)` along the `(n−2)`-sphere `S(t) ∩ Ṡ(t)`, `Ṡ` the hyperplane
//! `(wy − M)·(M′w − Mw′) + (R′w − 2Rw′)/2 = 0` (2.14). With a polynomial basis `B(t)` of
//! that hyperplane (`(n+1)×n`, columns `e_k·ε_j − e_j·ε_k`, `e` its coordinates,
//! `e_k ≢ 0`), the characteristic spheres are the quadric family `Bᵀ·A·B` of `P^{n−1}`
//! (`A` the homogeneous sphere matrix), parametrized by §5.1
//! ([`super::quadric_family`]): `y(t, u) = B·g(t, u)`. **Certificates:** every point lies
//! on its sphere, `|w·y − M·y₀|² ≡ R·y₀²`, and on the characteristic hyperplane, and the
//! map has total degree 2 in `u = (u₁, …, u_{n−2})`.

use super::quadric_family::{QuadricFamily, QuadricFamilyError, QuadricFamilyParam};
use super::{P, Q};
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Poly};

/// The sphere family of a curve of the Möbius model (2.13): `(M, R, w)` with
/// `|y − M/w|² = R/w²` (module docs).
///
/// # Errors
/// [`QuadricFamilyError::Shape`] for fewer than 4 coordinates (`n ≥ 2`);
/// [`QuadricFamilyError::Degenerate`] if `c₀ ≡ c_{n+1}` (every point is a hyperplane: the
/// sphere through the north pole).
pub fn mobius_spheres(c: &[P]) -> Result<(Vec<P>, P, P), QuadricFamilyError> {
    if c.len() < 4 {
        return Err(QuadricFamilyError::Shape(format!(
            "a curve of the Möbius model in P^(n+1) needs n + 2 ≥ 4 coordinates, got {}",
            c.len()
        )));
    }
    let n = c.len() - 2;
    let w = &c[0] - &c[n + 1];
    if w.is_zero() {
        return Err(QuadricFamilyError::Degenerate(
            "c₀ ≡ c_(n+1): every point of the curve is a hyperplane (a sphere through the north pole of the Möbius quadric)".into(),
        ));
    }
    let m: Vec<P> = c[1..=n].to_vec();
    let r = c[1..]
        .iter()
        .fold(-&(&c[0] * &c[0]), |acc, x| &acc + &(x * x));
    Ok((m, r, w))
}

/// A canal hypersurface of `Rⁿ` (Cor. 2.3; module docs): variables `t` (index 0) and
/// `u₁ … u_{n−2}`; homogeneous points `(y₀, y₁, …, yₙ)`.
#[derive(Debug, Clone, PartialEq)]
pub struct CanalHypersurface {
    m: Vec<P>,
    rho: P,
    w: P,
    plane: Vec<P>,
    param: QuadricFamilyParam,
    point: Vec<MPoly<Q>>,
}

impl CanalHypersurface {
    /// The envelope of the spheres `|y − M/w|² = R/w²` of `Rⁿ` (`n = M.len() ≥ 3`).
    ///
    /// # Errors
    /// [`QuadricFamilyError::Shape`] (`n < 3`), [`QuadricFamilyError::Degenerate`]
    /// (`w ≡ 0`, or the characteristic hyperplane is undefined: `ṁ ≡ 0` and `ρ̇ ≡ 0`); as
    /// [`QuadricFamily::parametrize`] for the characteristic spheres (no real point: the
    /// spheres do not envelop a real hypersurface there; no rational point: the proof).
    pub fn new(m: Vec<P>, rho: P, w: P) -> Result<Self, QuadricFamilyError> {
        let n = m.len();
        if n < 3 {
            return Err(QuadricFamilyError::Shape(format!(
                "a canal hypersurface lives in Rⁿ, n ≥ 3; the centre has {n} coordinates"
            )));
        }
        if w.is_zero() {
            return Err(QuadricFamilyError::Degenerate(
                "the denominator w(t) is zero".into(),
            ));
        }
        // sphere matrix A on (y₀, y): w²|y|² − 2w M·y y₀ + (|M|² − R) y₀²
        let mm = m.iter().fold(Poly::zero(), |acc, x| &acc + &(x * x));
        let mut a: Vec<Vec<P>> = vec![vec![Poly::zero(); n + 1]; n + 1];
        a[0][0] = &mm - &rho;
        for i in 0..n {
            a[0][i + 1] = -&(&w * &m[i]);
            a[i + 1][0] = a[0][i + 1].clone();
            a[i + 1][i + 1] = &w * &w;
        }
        // the characteristic hyperplane e·(y₀, y) = 0 (module docs)
        let dm: Vec<P> = m
            .iter()
            .map(|x| &(&x.derivative() * &w) - &(x * &w.derivative()))
            .collect();
        let half = Q::from_parts(1u8.into(), 2u8.into());
        let rterm =
            (&(&rho.derivative() * &w) - &(&rho * &w.derivative()).scale(&Q::from(2))).scale(&half);
        let mdm = m
            .iter()
            .zip(&dm)
            .fold(Poly::zero(), |acc, (x, y)| &acc + &(x * y));
        let mut e = vec![&rterm - &mdm];
        e.extend(dm.iter().map(|x| &w * x));
        let Some(k) = (1..=n).find(|&k| !e[k].is_zero()) else {
            return Err(QuadricFamilyError::Degenerate(
                "the characteristic hyperplane is undefined (ṁ ≡ 0: the centres do not move)"
                    .into(),
            ));
        };
        // basis of e·y = 0: columns b_j = e_k ε_j − e_j ε_k, j ≠ k
        let cols: Vec<Vec<P>> = (0..=n)
            .filter(|&j| j != k)
            .map(|j| {
                let mut v = vec![Poly::zero(); n + 1];
                v[j] = e[k].clone();
                v[k] = -&e[j];
                v
            })
            .collect();
        // Bᵀ A B
        let form = |x: &[P], y: &[P]| {
            let mut s = Poly::zero();
            for i in 0..=n {
                for j in 0..=n {
                    if !a[i][j].is_zero() && !x[i].is_zero() && !y[j].is_zero() {
                        s = &s + &(&(&x[i] * &a[i][j]) * &y[j]);
                    }
                }
            }
            s
        };
        let restricted: Vec<Vec<P>> = cols
            .iter()
            .map(|ci| cols.iter().map(|cj| form(ci, cj)).collect())
            .collect();
        let fam = QuadricFamily::new(restricted)?;
        let param = fam.parametrize()?;
        let g = param.map();
        let nv = g[0].nvars();
        let point: Vec<MPoly<Q>> = (0..=n)
            .map(|i| {
                cols.iter().zip(g).fold(MPoly::zero(nv), |acc, (c, gj)| {
                    if c[i].is_zero() {
                        acc
                    } else {
                        &acc + &(&MPoly::from_poly(&c[i], nv, 0) * gj)
                    }
                })
            })
            .collect();
        if point.iter().all(|x| x.is_zero()) {
            return Err(QuadricFamilyError::Degenerate(
                "the characteristic spheres' parametrization vanishes".into(),
            ));
        }
        Ok(CanalHypersurface {
            m,
            rho,
            w,
            plane: e,
            param,
            point,
        })
    }

    /// The homogeneous point map `(y₀, y₁, …, yₙ)(t, u₁, …, u_{n−2})`.
    pub fn point(&self) -> &[MPoly<Q>] {
        &self.point
    }

    /// The parametrization of the characteristic spheres (§5.1) it was built from.
    pub fn spheres(&self) -> &QuadricFamilyParam {
        &self.param
    }

    /// The dimension `n` of the ambient space.
    pub fn dim(&self) -> usize {
        self.m.len()
    }

    /// `(degree in t, total degree in u)`.
    pub fn degree(&self) -> (u32, u32) {
        let dt = self
            .point
            .iter()
            .filter_map(|p| p.degree_in(0))
            .max()
            .unwrap_or(0);
        let du = self
            .point
            .iter()
            .flat_map(|p| p.terms().map(|(e, _)| e.iter().skip(1).sum::<u32>()))
            .max()
            .unwrap_or(0);
        (dt, du)
    }
}

impl Certified for CanalHypersurface {
    /// On its sphere `|w·y − M·y₀|² ≡ R·y₀²`, on the characteristic hyperplane
    /// `e(t)·y ≡ 0` ((2.14)), total degree 2 in `u`, and the §5.1 certificates.
    fn certify(&self) -> Vec<Certificate> {
        let y = &self.point;
        let nv = y[0].nvars();
        let lift = |p: &P| MPoly::from_poly(p, nv, 0);
        let w = lift(&self.w);
        let d = (0..self.m.len()).fold(MPoly::zero(nv), |acc, i| {
            let di = &(&w * &y[i + 1]) - &(&lift(&self.m[i]) * &y[0]);
            &acc + &(&di * &di)
        });
        let on_sphere = &d - &(&lift(&self.rho) * &(&y[0] * &y[0]));
        let on_plane = self
            .plane
            .iter()
            .zip(y)
            .fold(MPoly::zero(nv), |acc, (e, yi)| &acc + &(&lift(e) * yi));
        let (_, du) = self.degree();
        let mut out = vec![
            Certificate::decide(
                "|w·y − M·y₀|² ≡ R·y₀² (every point lies on its sphere |y − m|² = r², Peternell (2.13))",
                on_sphere.is_zero(),
                true,
                || format!("{} terms", on_sphere.num_terms()),
            ),
            Certificate::decide(
                "(y − m)·ṁ + ρ̇/2 ≡ 0 (every point lies on the characteristic sphere, Peternell (2.14))",
                on_plane.is_zero(),
                true,
                || format!("{} terms", on_plane.num_terms()),
            ),
            Certificate::decide(
                "total degree 2 in u (each characteristic sphere parametrized once)",
                du == 2,
                true,
                || format!("degree {du}"),
            ),
        ];
        out.extend(self.param.certify());
        out
    }
}

/// Thm 2.3 from the Möbius model: the canal hypersurface of the sphere family of a curve
/// `c(t)` of `P^{n+1}` ([`mobius_spheres`], [`CanalHypersurface`]).
///
/// # Errors
/// As [`mobius_spheres`] and [`CanalHypersurface::new`].
pub fn canal_from_mobius_curve(c: &[P]) -> Result<CanalHypersurface, QuadricFamilyError> {
    let (m, r, w) = mobius_spheres(c)?;
    CanalHypersurface::new(m, r, w)
}

impl CanalHypersurface {
    /// A picture: for `n = 3` the surface itself on `[t₀, t₁] × [u₀, u₁]`; for `n ≥ 4` the
    /// slice `u₂ = … = 0` projected to `(y₀ : y₁ : y₂ : y₃)`. Positive weights.
    ///
    /// # Errors
    /// [`QuadricFamilyError::Patch`] where the weight `y₀` vanishes on the rectangle.
    pub fn picture(
        &self,
        t: (Q, Q),
        u: (Q, Q),
    ) -> Result<(Vec<rcagd_geom::BezierPatch<Q>>, Certificate), QuadricFamilyError> {
        let pe = |e: super::ConicSurfaceError| QuadricFamilyError::Patch(e.to_string());
        let coords: [MPoly<Q>; 4] =
            core::array::from_fn(|i| super::restrict_to_first_two(&self.point[i]));
        let patch = super::point_patch(&coords, t, u, "y₀").map_err(pe)?;
        super::positive_pieces(patch).map_err(pe)
    }
}
