//! Focal surfaces of a PN surface and the sections of its γ-hypersurface `Γ(φ)`
//! (Peternell §3.9, Lemma 3.5); derivations in docs/math/hypercyclides.md#focal-surfaces
//! and docs/math/hypercyclides.md#gamma-sections.
//!
//! **Focal surfaces.** A cycle `(f; r)` touching the oriented surface `x(u, v)` at `x`
//! has its centre on the normal, `f = x − r n`. It is a *curvature sphere* iff the
//! offset at distance `−r` is singular there, i.e. iff `x_u − r n_u` and `x_v − r n_v`
//! are linearly dependent (Rodrigues). Both vectors are tangent, so the condition is the
//! quadratic `n·((x_u − r n_u) × (x_v − r n_v)) = 0`. With `x = X/W`, `n = N/N₀` and the
//! numerators `ξ = X_u W − X W_u` (= `x_u W²`), `ν = N_u N₀ − N N₀_u` (= `n_u N₀²`), and
//! `r = r′ N₀²/W²` it reads `A − r′B + r′²C = 0`,
//!
//! `A = N·(ξ_u × ξ_v)`, `B = N·(ξ_u × ν_v + ν_u × ξ_v)`, `C = N·(ν_u × ν_v)`,
//!
//! so `r′ = (B ± √D)/(2C)`, `D = B² − 4AC`. The principal radii, the focal points
//! `f = x − r n` and the curvature-sphere cycles `(f; r)` are rational iff `D` is a square
//! in `Q[u, v]` (or `D ≡ 0`: umbilic everywhere, a sphere; `C ≡ 0`: a developable, one
//! focal sheet `r′ = A/B`). The two surfaces of curvature-sphere cycles in `R⁴` are the
//! γ-surfaces of Peternell §3.9 whose top views are the focal surfaces, and whose
//! cyclographic image is the surface again ([`FocalSheet::cycles`] feeds
//! [`super::hypercyclide::CyclographicImage`]).
//!
//! **Sections of `Γ(φ)`.** The cycles in oriented contact with the surface at `x` are
//! `(x − t n; t)`, a γ-line of `R⁴`; their union is the γ-hypersurface `Γ(φ)`. A hyperplane
//! `π: h₀ + h₁y₁ + h₂y₂ + h₃y₃ + h₄y₄ = 0` meets each γ-line once, at
//! `t = (h₀ + h′·x)/(h′·n − h₄)` (`h′ = (h₁, h₂, h₃)`): a rational surface of `R⁴`
//! ([`GammaSection`]). For `π: y₄ = d` (parallel to `R³`) its top view `x − d n` is the
//! offset at distance `−d` (Peternell §3.9: "the top views of all intersections
//! `Γ(φ) ∩ π` are offset surfaces").

use super::hypercyclide::mpoly_sqrt;
use super::poly::{cancel_gcd, cross3, dot3, identity_cert, pad_eval, patch_of, zero_cert};
use super::surface::{check_nonzero, PnSurface};
use super::{Domain, PnError};
use crate::error::format_scalar;
use crate::Certified;
use num_traits::Zero;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Field, Rational};
use rcagd_geom::BezierPatch;

type Q = Rational;
type M = MPoly<Q>;

fn derivative_numerators(p: &[M], w: &M, i: usize) -> [M; 3] {
    std::array::from_fn(|k| &(&p[k].partial(i) * w) - &(&p[k] * &w.partial(i)))
}

fn three(p: &[M]) -> [M; 3] {
    [p[0].clone(), p[1].clone(), p[2].clone()]
}

/// One sheet of the focal surface: the curvature-sphere cycles `(f; r)` of one family,
/// `r = ρN₀²/(σW²)` the principal radius (signed as the cycles: the surface point is
/// `x = f + r n`), `f = x − r n` the principal curvature centre.
#[derive(Debug, Clone)]
pub struct FocalSheet {
    rho: M,
    sigma: M,
    /// `(V, F₁, F₂, F₃, R)`: `f = F/V`, `r = R/V`.
    cycle: [M; 5],
}

impl FocalSheet {
    /// The curvature-sphere cycles as a surface of `R⁴`: `(F₁, F₂, F₃, R)` and the
    /// denominator `V` (the input of [`super::hypercyclide::CyclographicImage::new`]).
    pub fn cycles(&self) -> ([M; 4], M) {
        (
            [
                self.cycle[1].clone(),
                self.cycle[2].clone(),
                self.cycle[3].clone(),
                self.cycle[4].clone(),
            ],
            self.cycle[0].clone(),
        )
    }

    /// The focal point `f(u, v)` (`None` where `V = 0`).
    pub fn point(&self, u: &Q, v: &Q) -> Option<[Q; 3]> {
        let x = [u.clone(), v.clone()];
        let w = pad_eval(&self.cycle[0], &x)?.inv()?;
        Some(std::array::from_fn(|i| {
            pad_eval(&self.cycle[i + 1], &x).unwrap_or_else(Q::zero) * w.clone()
        }))
    }

    /// The principal radius `r(u, v)` of this family (`None` where `V = 0`).
    pub fn radius(&self, u: &Q, v: &Q) -> Option<Q> {
        let x = [u.clone(), v.clone()];
        let w = pad_eval(&self.cycle[0], &x)?.inv()?;
        Some(pad_eval(&self.cycle[4], &x)? * w)
    }

    /// `true` if the focal sheet is a surface (`f_u × f_v ≢ 0`), `false` if it degenerates
    /// to a curve or a point (canal surfaces: the spine; Dupin cyclides: the focal conics).
    pub fn is_surface(&self) -> bool {
        let w = &self.cycle[0];
        let a = derivative_numerators(&self.cycle[1..4], w, 0);
        let b = derivative_numerators(&self.cycle[1..4], w, 1);
        cross3(&a, &b).iter().any(|c| !c.is_zero())
    }

    /// The rational Bézier patch of the focal sheet over `domain`.
    ///
    /// # Errors
    /// [`PnError::Singular`] at a pole of `f` on the domain (`V = 0`: a parabolic point,
    /// where the principal radius is infinite).
    pub fn patch(&self, domain: &Domain<Q>) -> Result<BezierPatch<Q>, PnError> {
        check_nonzero(&self.cycle[0], domain, "focal point at infinity (V = 0)")?;
        patch_of(&self.cycle[..4], domain)
    }
}

/// The focal surfaces of a PN surface (module docs): one sheet per family of principal
/// curvature spheres (one for a sphere or a developable).
#[derive(Debug, Clone)]
pub struct FocalSurfaces {
    surface: PnSurface<Q>,
    xi: [[M; 3]; 2],
    nu: [[M; 3]; 2],
    discriminant: M,
    sheets: Vec<FocalSheet>,
}

impl FocalSurfaces {
    /// The focal sheets of `surface` (exact).
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] for a plane (`B ≡ C ≡ 0`: no focal point);
    /// [`PnError::NoRationalPoint`] if `D = B² − 4AC` is not a square in `Q[u, v]`: the
    /// principal radii and the two focal sheets are conjugate over `Q(u, v)(√D)`.
    pub fn new(surface: &PnSurface<Q>) -> Result<Self, PnError> {
        let x = surface.point_polys();
        let n = surface.normal_polys();
        let xi = [
            derivative_numerators(&x[1..], &x[0], 0),
            derivative_numerators(&x[1..], &x[0], 1),
        ];
        let nu = [
            derivative_numerators(&n[1..], &n[0], 0),
            derivative_numerators(&n[1..], &n[0], 1),
        ];
        let nn = three(&n[1..]);
        let a = dot3(&nn, &cross3(&xi[0], &xi[1]));
        let b = &dot3(&nn, &cross3(&xi[0], &nu[1])) + &dot3(&nn, &cross3(&nu[0], &xi[1]));
        let c = dot3(&nn, &cross3(&nu[0], &nu[1]));
        let disc = &(&b * &b) - &(&a * &c).scale(&Q::from(4));
        // (ρ, σ): r′ = ρ/σ
        let mut roots: Vec<(M, M)> = Vec::new();
        if c.is_zero() {
            if b.is_zero() {
                return Err(PnError::InvalidInput(format!(
                    "{}: the Gauss map is constant (a plane): there is no focal point",
                    surface.name()
                )));
            }
            roots.push((a.clone(), b.clone()));
        } else if disc.is_zero() {
            roots.push((b.clone(), c.scale(&Q::from(2))));
        } else {
            let sq = mpoly_sqrt(&disc).ok_or_else(|| {
                PnError::NoRationalPoint(format!(
                    "{}: the discriminant D = B² − 4AC of the principal radii (total degree {}) is not the square of a polynomial over Q: the principal radii and the two focal sheets are conjugate over Q(u, v)(√D) (docs/math/hypercyclides.md#focal-surfaces)",
                    surface.name(),
                    disc.total_degree().unwrap_or(0)
                ))
            })?;
            let two_c = c.scale(&Q::from(2));
            roots.push((&b + &sq, two_c.clone()));
            roots.push((&b - &sq, two_c));
        }
        let w = &x[0];
        let w2 = w * w;
        let n02 = &n[0] * &n[0];
        let sheets = roots
            .into_iter()
            .map(|(rho, sigma)| {
                let sw = &sigma * w;
                let rn = &rho * &n[0];
                let mut cycle = vec![
                    &sigma * &w2,
                    &(&sw * &x[1]) - &(&rn * &n[1]),
                    &(&sw * &x[2]) - &(&rn * &n[2]),
                    &(&sw * &x[3]) - &(&rn * &n[3]),
                    &rho * &n02,
                ];
                cancel_gcd(&mut cycle);
                let cycle = [
                    cycle[0].clone(),
                    cycle[1].clone(),
                    cycle[2].clone(),
                    cycle[3].clone(),
                    cycle[4].clone(),
                ];
                FocalSheet { rho, sigma, cycle }
            })
            .collect();
        Ok(FocalSurfaces {
            surface: surface.clone(),
            xi,
            nu,
            discriminant: disc,
            sheets,
        })
    }

    /// The sheets (two; one for a sphere or a developable surface).
    pub fn sheets(&self) -> &[FocalSheet] {
        &self.sheets
    }

    /// The discriminant `D = B² − 4AC` (module docs).
    pub fn discriminant(&self) -> &M {
        &self.discriminant
    }

    /// The defining property of a sheet, exactly: `(x_u − r n_u) × (x_v − r n_v) ≡ 0`
    /// (`r` a principal radius: the offset at distance `−r` is singular, all three
    /// components), and the surface point is the contact point of the cycle,
    /// `x ≡ f + r n`.
    pub fn sheet_certificates(&self, sheet: &FocalSheet) -> Vec<Certificate> {
        let (s, r) = (&sheet.sigma, &sheet.rho);
        let dir = |i: usize| -> [M; 3] {
            std::array::from_fn(|k| &(&self.xi[i][k] * s) - &(&self.nu[i][k] * r))
        };
        let cr = cross3(&dir(0), &dir(1));
        let mut out: Vec<Certificate> = cr
            .iter()
            .enumerate()
            .map(|(k, c)| {
                zero_cert(
                    &format!(
                        "{}: r is a principal radius, (x_u − r n_u) × (x_v − r n_v) ≡ 0 (component {k}; Rodrigues, Peternell §3.9)",
                        self.surface.name()
                    ),
                    c,
                    1.0,
                )
            })
            .collect();
        let x = self.surface.point_polys();
        let n = self.surface.normal_polys();
        let cy = &sheet.cycle;
        for i in 0..3 {
            let lhs = &(&x[i + 1] * &cy[0]) * &n[0];
            let rhs = &x[0] * &(&(&cy[i + 1] * &n[0]) + &(&cy[4] * &n[i + 1]));
            out.push(identity_cert(
                &format!("the surface point is the contact point f + r n of the curvature sphere (component {i})"),
                &lhs,
                &rhs,
            ));
        }
        out
    }

    /// The curvature-sphere cycles `(f; r)` of a sheet form a γ-surface of `R⁴`
    /// (Peternell §3.9): the pe Gram determinant `Δ` of its partial derivatives vanishes
    /// identically (docs/math/hypercyclides.md#surfaces).
    pub fn gamma_certificate(&self, sheet: &FocalSheet) -> Certificate {
        let (s, w) = sheet.cycles();
        let a: Vec<M> = (0..4)
            .map(|k| &(&s[k].partial(0) * &w) - &(&s[k] * &w.partial(0)))
            .collect();
        let b: Vec<M> = (0..4)
            .map(|k| &(&s[k].partial(1) * &w) - &(&s[k] * &w.partial(1)))
            .collect();
        let pe = |p: &[M], q: &[M]| &dot3(&p[..3], &q[..3]) - &(&p[3] * &q[3]);
        let (g11, g12, g22) = (pe(&a, &a), pe(&a, &b), pe(&b, &b));
        let delta = &(&g11 * &g22) - &(&g12 * &g12);
        zero_cert(
            "the curvature-sphere cycles form a γ-surface: det of the pe Gram matrix of (f; r)_u, (f; r)_v ≡ 0 (Peternell §3.9)",
            &delta,
            1.0,
        )
    }
}

impl Certified for FocalSurfaces {
    /// The sheet certificates of every sheet (the γ-surface certificate is separate,
    /// [`FocalSurfaces::gamma_certificate`], as its degree is high).
    fn certify(&self) -> Vec<Certificate> {
        self.sheets
            .iter()
            .flat_map(|s| self.sheet_certificates(s))
            .collect()
    }
}

/// The section `Γ(φ) ∩ π` of the γ-hypersurface of a PN surface by a hyperplane
/// `π: h₀ + h₁y₁ + h₂y₂ + h₃y₃ + h₄y₄ = 0` of `R⁴` (module docs): the cycle
/// `(x − t n; t)` on `π` of every surface element, as the homogeneous
/// `Y = (Y₀, Y₁, Y₂, Y₃, Y₄) = (W L, X L − K N, K N₀)` with `L = h′·N − h₄N₀`,
/// `K = h₀W + h′·X`.
#[derive(Debug, Clone)]
pub struct GammaSection {
    surface: PnSurface<Q>,
    hyperplane: [Q; 5],
    point: [M; 5],
}

impl GammaSection {
    /// `Γ(φ) ∩ π` for the oriented PN surface `surface`.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] if `π` contains the γ-line of every surface element
    /// (`h′·n ≡ h₄`: no section point) or `h = 0`.
    pub fn new(surface: &PnSurface<Q>, hyperplane: [Q; 5]) -> Result<Self, PnError> {
        if hyperplane[1..].iter().all(|c| c.is_zero()) {
            return Err(PnError::InvalidInput(
                "the hyperplane needs a non-zero normal (h₁, h₂, h₃, h₄)".into(),
            ));
        }
        let x = surface.point_polys();
        let n = surface.normal_polys();
        let h: [M; 3] = std::array::from_fn(|i| MPoly::constant(2, hyperplane[i + 1].clone()));
        let l = &dot3(&h, &n[1..]) - &n[0].scale(&hyperplane[4]);
        if l.is_zero() {
            return Err(PnError::InvalidInput(format!(
                "the hyperplane ({}) contains the γ-line (x − t n; t) of every surface element of {} (h′·n ≡ h₄): Γ(φ) ∩ π is not a surface",
                hyperplane.iter().map(format_scalar).collect::<Vec<_>>().join(", "),
                surface.name()
            )));
        }
        let k = &x[0].scale(&hyperplane[0]) + &dot3(&h, &x[1..]);
        let mut point = vec![
            &x[0] * &l,
            &(&x[1] * &l) - &(&k * &n[1]),
            &(&x[2] * &l) - &(&k * &n[2]),
            &(&x[3] * &l) - &(&k * &n[3]),
            &k * &n[0],
        ];
        cancel_gcd(&mut point);
        Ok(GammaSection {
            surface: surface.clone(),
            hyperplane,
            point: [
                point[0].clone(),
                point[1].clone(),
                point[2].clone(),
                point[3].clone(),
                point[4].clone(),
            ],
        })
    }

    /// The homogeneous section point `(Y₀, Y₁, Y₂, Y₃, Y₄)` in `R⁴`.
    pub fn point_polys(&self) -> &[M; 5] {
        &self.point
    }

    /// The section point `(y₁, y₂, y₃; y₄)` at `(u, v)` (`None` where `Y₀ = 0`).
    pub fn eval(&self, u: &Q, v: &Q) -> Option<[Q; 4]> {
        let x = [u.clone(), v.clone()];
        let w = pad_eval(&self.point[0], &x)?.inv()?;
        Some(std::array::from_fn(|i| {
            pad_eval(&self.point[i + 1], &x).unwrap_or_else(Q::zero) * w.clone()
        }))
    }

    /// The rational Bézier patch of the top view `(y₁, y₂, y₃)` over `domain`.
    ///
    /// # Errors
    /// [`PnError::Singular`] at a pole of the section on the domain (`Y₀ = 0`).
    pub fn top_view_patch(&self, domain: &Domain<Q>) -> Result<BezierPatch<Q>, PnError> {
        check_nonzero(&self.point[0], domain, "section point at infinity (Y₀ = 0)")?;
        patch_of(&self.point[..4], domain)
    }

    /// If `π` is parallel to `R³` (`h′ = 0`, `π: y₄ = −h₀/h₄`): the offset distance
    /// `d = h₀/h₄` whose offset is the top view.
    pub fn offset_distance(&self) -> Option<Q> {
        let h = &self.hyperplane;
        (h[1].is_zero() && h[2].is_zero() && h[3].is_zero() && !h[4].is_zero())
            .then(|| &h[0] / &h[4])
    }
}

impl Certified for GammaSection {
    /// `Y ∈ π` (`h₀Y₀ + h·Y ≡ 0`); `Y ∈ Γ(φ)`: the cycle `(m; r) = Y/Y₀` touches the
    /// surface's tangent plane at its point, `x ≡ m + r n`; for `π ∥ R³` the top view is
    /// the offset `x + d n`, `d = h₀/h₄` (identically, against [`PnSurface::offset`]).
    fn certify(&self) -> Vec<Certificate> {
        let y = &self.point;
        let h = &self.hyperplane;
        let on_plane = (0..5).fold(MPoly::zero(2), |acc, i| &acc + &y[i].scale(&h[i]));
        let mut out = vec![zero_cert(
            "the section point lies on the hyperplane π",
            &on_plane,
            1.0,
        )];
        let x = self.surface.point_polys();
        let n = self.surface.normal_polys();
        for i in 0..3 {
            let lhs = &(&x[i + 1] * &y[0]) * &n[0];
            let rhs = &x[0] * &(&(&y[i + 1] * &n[0]) + &(&y[4] * &n[i + 1]));
            out.push(identity_cert(
                &format!("the section point is a cycle of Γ(φ): it touches the surface's tangent plane at the surface point, x ≡ m + r n (component {i}; Peternell Lemma 3.5)"),
                &lhs,
                &rhs,
            ));
        }
        if let Some(d) = self.offset_distance() {
            let off = self.surface.offset(d.clone());
            let xo = off.surface().point_polys();
            for i in 0..3 {
                out.push(identity_cert(
                    &format!(
                        "π ∥ R³: the top view of Γ(φ) ∩ π is the offset at distance {} (component {i}; Peternell §3.9)",
                        format_scalar(&d)
                    ),
                    &(&y[i + 1] * &xo[0]),
                    &(&xo[i + 1] * &y[0]),
                ));
            }
        }
        out
    }
}
