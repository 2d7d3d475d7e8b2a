//! The pe conics of `R^{3,1}` whose cyclographic images are Dupin cyclides (Peternell,
//! "Rational Parametrizations for Envelopes of Quadric Families", §3.8.1, Lemma 3.4,
//! Prop. 3.1 and 3.2), and the conjugate conic of the second family of enveloped spheres
//! (our derivation: docs/math/cyclides.md#two-families).

use super::pe::{add, negligible, pe, pe_row, power_of_two_near_sqrt, scale, size, sub};
use super::route::Route;
use super::CyclideError;
use rcagd_algebra::conic_point::{rational_conic_point, TernaryOutcome};
use rcagd_algebra::{format_scalar, format_vector, Matrix, Poly, Rational, Scalar};

/// A pe conic whose cyclographic image is a Dupin cyclide.
#[derive(Debug, Clone, PartialEq)]
pub enum PeConic<F> {
    /// The pe circle `C(θ) = C₀ + ρ (cos θ U + sin θ V/√k)` in a Euclidean plane of
    /// `R^{3,1}`: `⟨U, U⟩ = ⟨V, V⟩ = 1`, `k = 1` (or, from [`PeConic::circle_scaled`], equal
    /// positive norms `R` with `ρ = 1`, `k = 1`; or, from [`PeConic::circle_ratio`],
    /// `⟨V, V⟩ = k⟨U, U⟩` with `k > 0` not necessarily a square and `ρ = 1`),
    /// `⟨U, V⟩ = 0`, `ρ ≠ 0` (Lemma 3.4, Prop. 3.1). Its rational parametrization is
    /// `C₀ + ρ((1 − k s²)U + 2s V)/(1 + k s²)` (`s = tan(θ/2)/√k`;
    /// docs/math/cyclides.md#three-spheres).
    Circle {
        /// Centre `C₀ = (c, r₀)`: the middle sphere.
        center: [F; 4],
        /// First pe-unit vector `U`.
        u: [F; 4],
        /// Second pe-unit vector `V`, pe-orthogonal to `U`.
        v: [F; 4],
        /// The pe radius `ρ ≠ 0`.
        rho: F,
        /// The norm ratio `k = ⟨V, V⟩/⟨U, U⟩ > 0` (`1` for the pe-orthonormal and the
        /// equal-norm forms).
        ratio: F,
    },
    /// The pe parabola `C(t) = C₀ + t U + (t²/2) N` in a γ-plane (Prop. 3.2):
    /// `⟨U, U⟩ = 1` (or, from [`PeConic::parabola_scaled`], any `⟨U, U⟩ = g > 0`: the
    /// parameter is then `√g` times the pe arc length), `N ≠ 0` isotropic
    /// (`⟨N, N⟩ = 0`), `⟨U, N⟩ = 0`; its image is a parabolic Dupin cyclide (a cubic).
    Parabola {
        /// The vertex `C₀`.
        vertex: [F; 4],
        /// The pe-unit tangent `U` at the vertex.
        u: [F; 4],
        /// The isotropic direction `N` (the point at infinity of the parabola).
        n: [F; 4],
    },
}

/// A rational curve of `R^{3,1}` of degree ≤ 2 in homogeneous form: the cycle
/// `(P₁, P₂, P₃; P₄) / W` (centre and signed radius).
#[derive(Debug, Clone, PartialEq)]
pub struct CycleCurve<F> {
    /// The weight `W`.
    pub w: Poly<F>,
    /// The numerators `(M₁, M₂, M₃, R)`.
    pub p: [Poly<F>; 4],
}

impl<F: Scalar> CycleCurve<F> {
    /// The exact curve with every coefficient rounded once to `F` (the nearest `f64`).
    pub fn rounded(exact: &CycleCurve<Rational>) -> Self {
        let r = |p: &Poly<Rational>| p.map(F::from_rational);
        CycleCurve {
            w: r(&exact.w),
            p: core::array::from_fn(|i| r(&exact.p[i])),
        }
    }

    /// The cycle at the parameter `t` as a point of `R^{3,1}`, or `None` where `W(t) = 0`
    /// (a point at infinity of the conic).
    pub fn eval(&self, t: &F) -> Option<[F; 4]> {
        let w = self.w.eval(t);
        if w.is_zero() {
            return None;
        }
        Some(core::array::from_fn(|i| self.p[i].eval(t) / w.clone()))
    }

    /// The curve with `t = 1/τ` (coefficients reversed at degree 2): covers the
    /// neighbourhood of `t = ∞`.
    pub fn reversed(&self) -> CycleCurve<F> {
        let rev = |p: &Poly<F>| {
            let mut c = p.coeffs().to_vec();
            c.resize(3, F::zero());
            c.reverse();
            Poly::new(c)
        };
        CycleCurve {
            w: rev(&self.w),
            p: core::array::from_fn(|i| rev(&self.p[i])),
        }
    }

    /// The curve shifted by `d` in the radius: every cycle `(m; r)` becomes `(m; r + d)`
    /// (the offset of the cyclographic image by `d`).
    pub fn radius_shifted(&self, d: &F) -> CycleCurve<F> {
        let mut p = self.p.clone();
        p[3] = &p[3] + &self.w.scale(d);
        CycleCurve {
            w: self.w.clone(),
            p,
        }
    }
}

fn quad<F: Scalar>(c0: F, c1: F, c2: F) -> Poly<F> {
    Poly::new(vec![c0, c1, c2])
}

impl<F: Scalar> PeConic<F> {
    /// The exact conic with every entry rounded once to `F` (no validation: the exact
    /// conic was validated).
    pub fn rounded(exact: &PeConic<Rational>) -> Self {
        let v = |a: &[Rational; 4]| -> [F; 4] { core::array::from_fn(|i| F::from_rational(&a[i])) };
        match exact {
            PeConic::Circle {
                center,
                u,
                v: w,
                rho,
                ratio,
            } => PeConic::Circle {
                center: v(center),
                u: v(u),
                v: v(w),
                rho: F::from_rational(rho),
                ratio: F::from_rational(ratio),
            },
            PeConic::Parabola { vertex, u, n } => PeConic::Parabola {
                vertex: v(vertex),
                u: v(u),
                n: v(n),
            },
        }
    }

    /// The pe circle `C₀ + ρ (cos θ U + sin θ V)`, validated.
    ///
    /// # Errors
    /// [`CyclideError::ZeroRadius`] for `ρ = 0`; [`CyclideError::IsotropicTangents`] if
    /// `⟨U, U⟩ ≤ 0` or `⟨V, V⟩ ≤ 0` (the conic would have isotropic or timelike tangents);
    /// [`CyclideError::NotOrthonormal`] unless `⟨U, U⟩ = ⟨V, V⟩ = 1`, `⟨U, V⟩ = 0`;
    /// [`CyclideError::Degenerate`] if every cycle is a point (`r ≡ 0`: the circle lies
    /// in `R³`, Lemma 3.4 excludes it).
    pub fn circle(center: [F; 4], u: [F; 4], v: [F; 4], rho: F) -> Result<Self, CyclideError> {
        Self::circle_checked(center, u, v, rho, true)
    }

    /// The pe circle `C₀ + cos θ W₁ + sin θ W₂` with `⟨W₁, W₁⟩ = ⟨W₂, W₂⟩ > 0`,
    /// `⟨W₁, W₂⟩ = 0` (stored with `ρ = 1`; the norm need not be a rational square).
    ///
    /// # Errors
    /// As [`PeConic::circle`], with "equal norms" in place of "pe-unit".
    pub fn circle_scaled(center: [F; 4], w1: [F; 4], w2: [F; 4]) -> Result<Self, CyclideError> {
        Self::circle_checked(center, w1, w2, F::one(), false)
    }

    /// The pe circle `C₀ + ((1 − k s²)W₁ + 2s W₂)/(1 + k s²)` for spacelike, pe-orthogonal
    /// `W₁, W₂` with `k = ⟨W₂, W₂⟩/⟨W₁, W₁⟩` (stored with `ρ = 1`). `k` need not be a
    /// square: this is the circle `C₀ + cos θ W₁ + sin θ W₂/√k` with `tan(θ/2) = √k s`,
    /// rational although its `(cos θ, sin θ)` form is not (docs/math/cyclides.md#three-spheres).
    ///
    /// # Errors
    /// As [`PeConic::circle`], with "`⟨W₁, W₂⟩ = 0`, both norms positive" in place of
    /// "pe-unit".
    pub fn circle_ratio(center: [F; 4], w1: [F; 4], w2: [F; 4]) -> Result<Self, CyclideError> {
        let (n1, n2) = (pe(&w1, &w1), pe(&w2, &w2));
        let ratio = if n1 <= F::zero() || n1.is_zero() {
            F::one() // rejected below as isotropic / timelike
        } else {
            n2 / n1
        };
        Self::circle_full(center, w1, w2, F::one(), ratio, false)
    }

    pub(crate) fn circle_checked(
        center: [F; 4],
        u: [F; 4],
        v: [F; 4],
        rho: F,
        unit: bool,
    ) -> Result<Self, CyclideError> {
        Self::circle_full(center, u, v, rho, F::one(), unit)
    }

    /// [`PeConic::circle_checked`] with the norm ratio `k = ⟨V, V⟩/⟨U, U⟩`.
    pub(crate) fn circle_full(
        center: [F; 4],
        u: [F; 4],
        v: [F; 4],
        rho: F,
        ratio: F,
        unit: bool,
    ) -> Result<Self, CyclideError> {
        let s = size(&u).max(size(&v)).max(1.0);
        if negligible(&rho, 1.0) {
            return Err(CyclideError::ZeroRadius(format!(
                "ρ = {}: a pe circle of radius 0 is a point, its image a single sphere",
                format_scalar(&rho)
            )));
        }
        let (uu, vv, uv) = (pe(&u, &u), pe(&v, &v), pe(&u, &v));
        for (name, x) in [("⟨U, U⟩", &uu), ("⟨V, V⟩", &vv)] {
            if *x <= F::zero() || negligible(x, s * s) {
                return Err(CyclideError::IsotropicTangents(format!(
                    "{name} = {} ≤ 0: the conic C₀ + ρ(cos θ U + sin θ V) has isotropic or timelike tangents (no real envelope there)",
                    format_scalar(x)
                )));
            }
        }
        let one = if unit { F::one() } else { uu.clone() };
        if !(negligible(&(uu.clone() - one.clone()), s * s)
            && negligible(&(vv.clone() - one * ratio.clone()), s * s)
            && negligible(&uv, s * s))
        {
            return Err(CyclideError::NotOrthonormal(format!(
                "⟨U, U⟩ = {}, ⟨V, V⟩ = {}, ⟨U, V⟩ = {} (need {}) for U = {}, V = {}",
                format_scalar(&uu),
                format_scalar(&vv),
                format_scalar(&uv),
                if unit {
                    "1, 1, 0".to_string()
                } else {
                    format!("⟨V, V⟩ = {}·⟨U, U⟩, 0", format_scalar(&ratio))
                },
                format_vector(&u),
                format_vector(&v)
            )));
        }
        let r0 = center[3].clone();
        if negligible(&r0, 1.0) && negligible(&u[3], s) && negligible(&v[3], s) {
            return Err(CyclideError::Degenerate(
                "r ≡ 0: every cycle of the pe circle is a point (the circle lies in R³); its cyclographic image is the circle itself, not a surface".into(),
            ));
        }
        Ok(PeConic::Circle {
            center,
            u,
            v,
            rho,
            ratio,
        })
    }

    /// The pe parabola `C₀ + t U + (t²/2) N`, validated.
    ///
    /// # Errors
    /// [`CyclideError::ZeroRadius`] for `N = 0` (a line, not a conic);
    /// [`CyclideError::IsotropicTangents`] if `⟨U, U⟩ ≤ 0`;
    /// [`CyclideError::NotOrthonormal`] unless `⟨U, U⟩ = 1`, `⟨N, N⟩ = 0`, `⟨U, N⟩ = 0`.
    pub fn parabola(vertex: [F; 4], u: [F; 4], n: [F; 4]) -> Result<Self, CyclideError> {
        Self::parabola_checked(vertex, u, n, true)
    }

    /// The pe parabola `C₀ + t U + (t²/2) N` with `⟨U, U⟩ = g > 0` not necessarily 1 (the
    /// pe-unit tangent `U/√g` need not be rational; docs/math/cyclides.md#three-spheres).
    ///
    /// # Errors
    /// As [`PeConic::parabola`], with "`⟨U, U⟩ > 0`" in place of "`⟨U, U⟩ = 1`".
    pub fn parabola_scaled(vertex: [F; 4], u: [F; 4], n: [F; 4]) -> Result<Self, CyclideError> {
        Self::parabola_checked(vertex, u, n, false)
    }

    pub(crate) fn parabola_checked(
        vertex: [F; 4],
        u: [F; 4],
        n: [F; 4],
        unit: bool,
    ) -> Result<Self, CyclideError> {
        let s = size(&u).max(size(&n)).max(1.0);
        if n.iter().all(|x| negligible(x, s)) {
            return Err(CyclideError::ZeroRadius(
                "N = 0: the parabola C₀ + tU + (t²/2)N degenerates to a line".into(),
            ));
        }
        let (uu, nn, un) = (pe(&u, &u), pe(&n, &n), pe(&u, &n));
        if uu <= F::zero() || negligible(&uu, s * s) {
            return Err(CyclideError::IsotropicTangents(format!(
                "⟨U, U⟩ = {} ≤ 0: the parabola has isotropic or timelike tangents at its vertex",
                format_scalar(&uu)
            )));
        }
        let one = if unit { F::one() } else { uu.clone() };
        if !(negligible(&(uu.clone() - one), s * s)
            && negligible(&nn, s * s)
            && negligible(&un, s * s))
        {
            return Err(CyclideError::NotOrthonormal(format!(
                "⟨U, U⟩ = {}, ⟨N, N⟩ = {}, ⟨U, N⟩ = {} (need {}, 0, 0: a pe parabola in a γ-plane) for U = {}, N = {}",
                format_scalar(&uu),
                format_scalar(&nn),
                format_scalar(&un),
                if unit { "1" } else { "> 0" },
                format_vector(&u),
                format_vector(&n)
            )));
        }
        Ok(PeConic::Parabola { vertex, u, n })
    }

    /// `true` for the parabola (parabolic cyclide).
    pub fn is_parabola(&self) -> bool {
        matches!(self, PeConic::Parabola { .. })
    }

    /// The rational parametrization: `((1+kt²)C₀ + ρ((1−kt²)U + 2tV)) / (1+kt²)` for the
    /// circle (`k` its norm ratio, `1` unless built by [`PeConic::circle_ratio`]),
    /// `C₀ + tU + (t²/2)N` for the parabola.
    pub fn curve(&self) -> CycleCurve<F> {
        let (z, one, two) = (F::zero(), F::one(), F::from_i64(2));
        match self {
            PeConic::Circle {
                center,
                u,
                v,
                rho,
                ratio,
            } => CycleCurve {
                w: quad(one, z, ratio.clone()),
                p: core::array::from_fn(|i| {
                    quad(
                        center[i].clone() + rho.clone() * u[i].clone(),
                        two.clone() * rho.clone() * v[i].clone(),
                        ratio.clone() * (center[i].clone() - rho.clone() * u[i].clone()),
                    )
                }),
            },
            PeConic::Parabola { vertex, u, n } => CycleCurve {
                w: Poly::constant(one),
                p: core::array::from_fn(|i| {
                    quad(vertex[i].clone(), u[i].clone(), n[i].clone() / two.clone())
                }),
            },
        }
    }

    /// The conjugate conic: the cycles in oriented contact with every cycle of `self`
    /// (docs/math/cyclides.md#two-families). For the circle: the pe hyperbola
    /// `{C₀ + Z : Z ⟂ U, V, ⟨Z, Z⟩ = −ρ²R}` of Prop. 3.1 (both branches, `R = ⟨U, U⟩`),
    /// `D(s) = (k s² N₊ + s C₀ + (a/k) N₋) / s` in the isotropic basis `N±` of
    /// `span(U, V)^⊥`, `a = −ρ²R / (2⟨N₊, N₋⟩)`, `k` a power of two near `√|a|`; for the
    /// parabola with `g = ⟨U, U⟩`: `C₀ + M + sP − (s²q/(2g))N` with `P ⟂ U, N`,
    /// `q = ⟨P, P⟩` (`P` pe-unit, `q = 1`, when its norm is a square), `M` isotropic,
    /// `⟨M, N⟩ = g`, `M ⟂ U, P` (Prop. 3.2; docs/math/cyclides.md#two-families).
    ///
    /// # Errors
    /// [`CyclideError::NotRational`] if a square root the construction needs is not in
    /// the scalar field (cannot happen for exact input that passed validation: the
    /// discriminants are squares, docs/math/cyclides.md#rationality).
    pub fn conjugate(&self) -> Result<CycleCurve<F>, CyclideError> {
        self.conjugate_along(&mut Route::free())
    }

    /// [`PeConic::conjugate`] taking the decisions of `route` (whether the isotropic
    /// directions are rational, the rational point, the pivots; see [`Route`]).
    ///
    /// # Errors
    /// As [`PeConic::conjugate`]; [`CyclideError::InvalidArgument`] if `route` was
    /// recorded on another construction.
    pub fn conjugate_along(&self, route: &mut Route) -> Result<CycleCurve<F>, CyclideError> {
        match self {
            PeConic::Circle {
                center, u, v, rho, ..
            } => {
                let (na, nb) = match null_pair(&[u.clone(), v.clone()], route) {
                    Ok(pair) => pair,
                    // the isotropic directions need √k: parametrize through a rational point
                    Err(CyclideError::NotRational(why)) => {
                        return hyperbola_through_point(center, u, v, rho, &why, route)
                    }
                    Err(e) => return Err(e),
                };
                let h = pe(&na, &nb);
                // Z = α N₊ + β N₋ with 2αβh = −ρ²: α = s k, β = a/(s k)
                let a = -(rho.clone() * rho.clone() * pe(u, u)) / (F::from_i64(2) * h);
                let k = power_of_two_near_sqrt(&a);
                // homogeneous: (s² k N₊ + s C₀ + (a/k) N₋) / s
                let nk = scale(&k, &na);
                let nm = scale(&(a / k.clone()), &nb);
                Ok(CycleCurve {
                    w: Poly::new(vec![F::zero(), F::one()]),
                    p: core::array::from_fn(|i| {
                        quad(nm[i].clone(), center[i].clone(), nk[i].clone())
                    }),
                })
            }
            PeConic::Parabola { vertex, u, n } => {
                let (m, p, q) = parabola_frame_along(u, n, route)?;
                let c = add(vertex, &m);
                let k = q / (F::from_i64(2) * pe(u, u));
                Ok(CycleCurve {
                    w: Poly::constant(F::one()),
                    p: core::array::from_fn(|i| {
                        quad(c[i].clone(), p[i].clone(), -(n[i].clone() * k.clone()))
                    }),
                })
            }
        }
    }
}

/// The pe hyperbola `{C₀ + Z : Z ⟂ U, V, ⟨Z, Z⟩ = m}`, `m = −ρ²⟨U, U⟩`, when its isotropic
/// directions are irrational (the norm ratio `k` of the circle is not a square): with a
/// pe-orthogonal basis `z₁, z₂` of `span(U, V)^⊥` (`α = ⟨z₁, z₁⟩`, `β = ⟨z₂, z₂⟩`, `αβ < 0`)
/// and a rational point `P₀ = x z₁ + y z₂` of `αx² + βy² = m` (Legendre's theorem, the
/// algebra's conic engine), the lines through `P₀` with direction `d(s) = z₁ + sλz₂` meet
/// the hyperbola again in `Z(s) = (⟨d, d⟩P₀ − 2⟨P₀, d⟩d)/⟨d, d⟩`, so
/// `D(s) = (⟨d, d⟩C₀ + ⟨d, d⟩P₀ − 2⟨P₀, d⟩d)/⟨d, d⟩` (degree 2; `λ` a power of two near
/// `√(α/|β|)` balances it; docs/math/cyclides.md#three-spheres).
fn hyperbola_through_point<F: Scalar>(
    center: &[F; 4],
    u: &[F; 4],
    v: &[F; 4],
    rho: &F,
    why: &str,
    route: &mut Route,
) -> Result<CycleCurve<F>, CyclideError> {
    let basis = pe_complement_along(&[u.clone(), v.clone()], route)?;
    let [a0, b0] = <[[F; 4]; 2]>::try_from(basis)
        .map_err(|_| CyclideError::InvalidArgument("U and V are linearly dependent".into()))?;
    let sc = size(&a0).max(size(&b0)).max(1.0);
    let (z1, z2) = if route.flag(|| negligible(&pe(&a0, &a0), sc * sc))? {
        let c = add(&a0, &b0);
        let cc = pe(&c, &c);
        (c.clone(), sub(&a0, &scale(&(pe(&a0, &c) / cc), &c)))
    } else {
        let aa = pe(&a0, &a0);
        (a0.clone(), sub(&b0, &scale(&(pe(&b0, &a0) / aa), &a0)))
    };
    let (al, be) = (pe(&z1, &z1), pe(&z2, &z2));
    let m = -(rho.clone() * rho.clone() * pe(u, u));
    let not_rational = |more: String| {
        CyclideError::NotRational(format!(
            "{why}; the conjugate pe hyperbola {}·x² + {}·y² = {} has {more}",
            format_scalar(&al),
            format_scalar(&be),
            format_scalar(&m)
        ))
    };
    let q = |x: &F| {
        x.to_rational()
            .ok_or_else(|| not_rational("coefficients outside Q".into()))
    };
    let (x, y) = route.point(|| {
        let (qa, qb, qm) = (q(&al)?, q(&be)?, q(&m)?);
        match rational_conic_point(&qa, &qb, &(-qm)) {
            Ok(TernaryOutcome::Point([x, y, w])) if !w.is_zero() => Ok((
                F::from_rational(&(x / w.clone())),
                F::from_rational(&(y / w)),
            )),
            Ok(TernaryOutcome::Point(_)) => Err(not_rational("only a point at infinity".into())),
            Ok(TernaryOutcome::NoPoint(place)) => Err(not_rational(format!(
                "no rational point (none over {place})"
            ))),
            Err(e) => Err(not_rational(format!("no rational point found ({e})"))),
        }
    })?;
    let p0: [F; 4] =
        core::array::from_fn(|i| x.clone() * z1[i].clone() + y.clone() * z2[i].clone());
    let lam = if be.is_zero() {
        F::one()
    } else {
        power_of_two_near_sqrt(&(al.clone() / be.clone()))
    };
    // d(s) = z₁ + s λ z₂: ⟨d, d⟩ = α + λ²β s², ⟨P₀, d⟩ = αx + λβy s
    let l2b = lam.clone() * lam.clone() * be.clone();
    let w = quad(al.clone(), F::zero(), l2b.clone());
    let pd = [al.clone() * x, lam.clone() * be * y];
    let two = F::from_i64(2);
    let p = core::array::from_fn(|i| {
        let c = center[i].clone() + p0[i].clone();
        // ⟨d,d⟩(C₀ + P₀) − 2⟨P₀, d⟩ d
        let d0 = z1[i].clone();
        let d1 = lam.clone() * z2[i].clone();
        quad(
            al.clone() * c.clone() - two.clone() * pd[0].clone() * d0.clone(),
            -(two.clone() * (pd[0].clone() * d1.clone() + pd[1].clone() * d0)),
            l2b.clone() * c - two.clone() * pd[1].clone() * d1,
        )
    });
    Ok(CycleCurve { w, p })
}

/// A basis of `{X : ⟨X, Aᵢ⟩ = 0 ∀i}` (the pivot columns of `route`).
pub(crate) fn pe_complement_along<F: Scalar>(
    a: &[[F; 4]],
    route: &mut Route,
) -> Result<Vec<[F; 4]>, CyclideError> {
    let rows: Vec<Vec<F>> = a.iter().map(pe_row).collect();
    route
        .null_space(&rows)?
        .into_iter()
        .map(|v| {
            <[F; 4]>::try_from(v)
                .map_err(|_| CyclideError::InvalidArgument("kernel vector of wrong length".into()))
        })
        .collect()
}

/// The two isotropic directions `N₊, N₋` of the Lorentzian plane `span(U, V)^⊥`; they are
/// rational because its discriminant is `−1` times a square
/// (docs/math/cyclides.md#rationality).
pub(crate) fn null_pair<F: Scalar>(
    uv: &[[F; 4]; 2],
    route: &mut Route,
) -> Result<([F; 4], [F; 4]), CyclideError> {
    let basis = pe_complement_along(uv, route)?;
    let [a, b] = <[[F; 4]; 2]>::try_from(basis)
        .map_err(|_| CyclideError::InvalidArgument("U and V are linearly dependent".into()))?;
    let (g11, g12, g22) = (pe(&a, &a), pe(&a, &b), pe(&b, &b));
    let disc = g12.clone() * g12.clone() - g11.clone() * g22.clone();
    let sc = size(&a).max(size(&b)).max(1.0);
    if route.flag(|| disc <= F::zero() || negligible(&disc, sc.powi(4)))? {
        return Err(CyclideError::InvalidArgument(format!(
            "span(U, V)^⊥ is not a Lorentzian plane (discriminant {})",
            format_scalar(&disc)
        )));
    }
    if route.flag(|| negligible(&g11, sc * sc))? {
        let nb = sub(&scale(&g22, &a), &scale(&(F::from_i64(2) * g12), &b));
        return Ok((a, nb));
    }
    let root = route.sqrt(&disc)?.ok_or_else(|| {
        CyclideError::NotRational(format!(
            "the isotropic directions of span(U, V)^⊥ need √{}",
            format_scalar(&disc)
        ))
    })?;
    let np = add(&scale(&(root.clone() - g12.clone()), &a), &scale(&g11, &b));
    let nm = add(&scale(&(-root - g12), &a), &scale(&g11, &b));
    Ok((np, nm))
}

/// For the pe parabola `C₀ + tU + (t²/2)N`: `(M, P, q)` with `M` isotropic, `⟨M, N⟩ = ⟨U, U⟩`,
/// `M ⟂ U, P`, and `P ⟂ U, N` spacelike with `q = ⟨P, P⟩` (`P` pe-unit and `q = 1` when the
/// norm of the first candidate is a square in the field) (docs/math/cyclides.md#two-families).
pub(crate) fn parabola_frame<F: Scalar>(
    u: &[F; 4],
    n: &[F; 4],
) -> Result<([F; 4], [F; 4], F), CyclideError> {
    parabola_frame_along(u, n, &mut Route::free())
}

/// [`parabola_frame`] taking the decisions of `route`.
pub(crate) fn parabola_frame_along<F: Scalar>(
    u: &[F; 4],
    n: &[F; 4],
    route: &mut Route,
) -> Result<([F; 4], [F; 4], F), CyclideError> {
    let basis = pe_complement_along(&[u.clone(), n.clone()], route)?;
    let s = size(n).max(1.0);
    let mut cands = basis.clone();
    if let [a, b] = basis.as_slice() {
        cands.push(add(a, b));
    }
    let first = route.index(|| cands.iter().position(|c| !negligible(&pe(c, c), s * s)))?;
    let p0 = first.and_then(|i| cands.get(i).cloned()).ok_or_else(|| {
        CyclideError::InvalidArgument("span(U, N)^⊥ has no spacelike vector".into())
    })?;
    let pp = pe(&p0, &p0);
    let (p, q) = match route.sqrt(&pp)? {
        Some(root) if !root.is_zero() => (scale(&(F::one() / root), &p0), F::one()),
        _ => (p0, pp),
    };
    let g = pe(u, u);
    let m = Matrix::from_rows(vec![pe_row(u), pe_row(&p), pe_row(n)])
        .map_err(|e| CyclideError::InvalidArgument(e.to_string()))?;
    let sol = m
        .solve(&[F::zero(), F::zero(), g.clone()])
        .map_err(|e| CyclideError::InvalidArgument(e.to_string()))?;
    let m0 = sol
        .particular()
        .and_then(|x| <[F; 4]>::try_from(x.to_vec()).ok())
        .ok_or_else(|| {
            CyclideError::InvalidArgument("no vector M with ⟨M, N⟩ = ⟨U, U⟩, M ⟂ U, P".into())
        })?;
    // M = M₀ − c N is isotropic: ⟨M₀, M₀⟩ − 2c⟨M₀, N⟩ = 0
    let c = pe(&m0, &m0) / (F::from_i64(2) * g);
    Ok((sub(&m0, &scale(&c, n)), p, q))
}
