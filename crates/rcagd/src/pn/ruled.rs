//! Envelopes of rational families of cones of revolution (Peternell §4.5, Theorem 4.5,
//! (4.5)–(4.19); docs/math/laguerre-pn.md) and what Peternell derives from them: non-developable
//! rational ruled surfaces and their offsets (Cor. 4.2), canal surfaces with rational spine
//! and radius (Cor. 4.3), the ellipsoid and its offsets (Theorem 4.6, §4.7; docs/math/laguerre-pn.md), surfaces of revolution with a PH profile; and the offsets of ruled 2-manifolds
//! in `Rⁿ` (Theorem 5.2, [`RuledManifold`]).
//!
//! **Theorem 4.5.** Two rational cycle families `c_i(t) = (m_i; r_i)(t)` span cones of
//! revolution `Δ(t)` (their common oriented tangent planes). In `I³` the cycles are
//! isotropic spheres (4.5); their intersection projects to the circle `d'(t)` (4.6) with
//! centre `n = −(M₁, M₂)/β` (4.7) and `ρ² = (|M|² − R²)/β²` (4.8), `M = m₁ − m₂`,
//! `R = r₁ − r₂`, `β = R + M₃`. Given `p₁² + p₂² = |M|² − R²`, the point
//! `f = (p₁ − M₁, p₂ − M₂)/β` (4.18) lies on `d'(t)`; reflecting it in the diameters with
//! normals `c(u) = (u, 1)` gives `(y₁, y₂)(t, u) = f + 2((n − f)·c/(c·c)) c` (4.11) and
//! (4.12) gives `y₃`. `Λ⁻¹` of this isotropic surface is the envelope, a PN surface. For
//! `β ≡ 0` the circle is the line `M₁y₁ + M₂y₂ = M₃`, parametrized linearly.
//!
//! **Rationality.** `p₁, p₂` are rational only if `|M|² − R²` is a sum of two squares
//! over `Q(t)`. They can be given; otherwise they are found when `M_k² ≡ R²` for some `k`,
//! or by the complete sum-of-two-squares engine of the algebra layer
//! ([`find_two_squares`]); if that proves that no rational decomposition exists,
//! [`PnError::NoRationalPoint`] names the reason (e.g. the quadratic field it needs).

use super::isotropic::IsotropicSurface;
use super::poly::{
    cancel_common, cross3, dot3, gcd2, identity_cert, int, mag, normalize_content, pad_eval,
    univariate_from_q, univariate_sqrt, univariate_to_q, var, zero_cert, RatFn,
};
use super::surface::PnSurface;
use super::PnError;
use crate::error::format_scalar;
use crate::laguerre::Cycle;
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{format_poly, Certificate, Scalar};

/// `true` if the polynomial involves only the variable `x₀` (`t`).
fn only_t<F: Scalar>(p: &MPoly<F>) -> bool {
    p.terms().all(|(e, _)| e.iter().skip(1).all(|&k| k == 0))
}

/// A rational one-parameter family of cycles `(m(t); r(t)) = (M(t); R(t))/w(t)` (Peternell §4.5:
/// centre and radius rational in the same parameter `t`, the variable `x₀`).
#[derive(Debug, Clone)]
pub struct CycleFamily<F> {
    center: [MPoly<F>; 3],
    radius: MPoly<F>,
    den: MPoly<F>,
}

impl<F: Scalar> CycleFamily<F> {
    /// The family `(M(t); R(t))/w(t)` with polynomials in `t`.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] if `w ≡ 0` or a polynomial involves another variable.
    pub fn new(center: [MPoly<F>; 3], radius: MPoly<F>, den: MPoly<F>) -> Result<Self, PnError> {
        if den.is_zero() {
            return Err(PnError::InvalidInput(
                "a cycle family needs a non-zero denominator w(t)".into(),
            ));
        }
        if !center.iter().chain([&radius, &den]).all(only_t) {
            return Err(PnError::InvalidInput(
                "a cycle family must depend on the single parameter t (variable 0)".into(),
            ));
        }
        Ok(CycleFamily {
            center,
            radius,
            den,
        })
    }

    /// The family with rational centre coordinates and radius (brought to one denominator).
    ///
    /// # Errors
    /// As [`Self::new`].
    pub fn from_rational(center: [RatFn<F>; 3], radius: RatFn<F>) -> Result<Self, PnError> {
        let fns = [
            center[0].clone(),
            center[1].clone(),
            center[2].clone(),
            radius,
        ];
        let den = fns.iter().fold(int::<F>(1), |acc, f| &acc * &f.den);
        let mut polys: Vec<MPoly<F>> = fns
            .iter()
            .map(|f| {
                let mut p = f.num.clone();
                for g in fns.iter() {
                    if !std::ptr::eq(g, f) {
                        p = &p * &g.den;
                    }
                }
                p
            })
            .collect();
        polys.push(den);
        let cands: Vec<MPoly<F>> = fns.iter().map(|f| f.den.clone()).collect();
        cancel_common(&mut polys, &cands);
        normalize_content(&mut polys);
        let w = polys.pop().unwrap_or_else(|| int(1));
        let r = polys.pop().unwrap_or_else(|| MPoly::zero(2));
        Self::new([polys[0].clone(), polys[1].clone(), polys[2].clone()], r, w)
    }

    /// The family of points `(l(t); 0)`.
    ///
    /// # Errors
    /// As [`Self::from_rational`].
    pub fn points(l: [RatFn<F>; 3]) -> Result<Self, PnError> {
        Self::from_rational(l, RatFn::constant(F::zero()))
    }

    /// `c + ċ`: the family `(m + ṁ; r + ṙ)` (Cor. 4.3: the cones `c ∨ (c + ċ)` are tangent
    /// to the canal surface of `c`).
    pub fn plus_derivative(&self) -> Self {
        // (X/w)' = (X'w − Xw')/w², so X/w + (X/w)' = (Xw + X'w − Xw')/w²
        let w = &self.den;
        let dw = w.partial(0);
        let f = |x: &MPoly<F>| &(&(x * w) + &(&x.partial(0) * w)) - &(x * &dw);
        let mut polys = vec![
            f(&self.center[0]),
            f(&self.center[1]),
            f(&self.center[2]),
            f(&self.radius),
            w * w,
        ];
        cancel_common(&mut polys, std::slice::from_ref(w));
        let den = polys.pop().unwrap_or_else(|| int(1));
        let r = polys.pop().unwrap_or_else(|| MPoly::zero(2));
        CycleFamily {
            center: [polys[0].clone(), polys[1].clone(), polys[2].clone()],
            radius: r,
            den,
        }
    }

    /// The numerators `(M₁, M₂, M₃, R)` and the denominator `w`.
    pub fn parts(&self) -> ([&MPoly<F>; 3], &MPoly<F>, &MPoly<F>) {
        (
            [&self.center[0], &self.center[1], &self.center[2]],
            &self.radius,
            &self.den,
        )
    }

    /// The cycle at `t` (`None` where `w(t) = 0`).
    pub fn eval(&self, t: &F) -> Option<Cycle<F>> {
        let x = [t.clone()];
        let inv = pad_eval(&self.den, &x)?.inv()?;
        let e = |p: &MPoly<F>| pad_eval(p, &x).map(|v| v * inv.clone());
        Some(Cycle {
            center: [
                e(&self.center[0])?,
                e(&self.center[1])?,
                e(&self.center[2])?,
            ],
            radius: e(&self.radius)?,
        })
    }
}

/// Rational functions `p₁, p₂` of `t` with `p₁² + p₂² = P` for a polynomial `P(t)`, when
/// `P` is a sum of two squares of rational polynomials: the complete decision of the algebra
/// layer ([`rcagd_algebra::sum_of_squares::sum_of_two_squares`], exact; for `f64` data on the
/// exact binary values of the coefficients). `None` if no such decomposition over `Q` exists.
pub fn find_two_squares<F: Scalar>(p: &MPoly<F>) -> Option<[RatFn<F>; 2]> {
    two_squares_or_reason(p).ok()
}

/// [`find_two_squares`] with the reason of a failure (for the error message).
fn two_squares_or_reason<F: Scalar>(p: &MPoly<F>) -> Result<[RatFn<F>; 2], String> {
    use rcagd_algebra::sum_of_squares::{sum_of_two_squares, SumOfSquares};
    if let Some(s) = univariate_sqrt(p) {
        return Ok([RatFn::poly(s), RatFn::poly(MPoly::zero(2))]);
    }
    if !only_t(p) {
        return Err("it involves a second variable".into());
    }
    let d = univariate_to_q(p).ok_or_else(|| "a coefficient is not finite".to_string())?;
    let shown = format_poly(&d, "t");
    match sum_of_two_squares(&d) {
        Ok(SumOfSquares::Rational { g1, g2 }) => Ok([
            RatFn::poly(univariate_from_q(&g1)),
            RatFn::poly(univariate_from_q(&g2)),
        ]),
        Ok(SumOfSquares::Extension { radicand, .. }) => Err(format!(
            "its numerator {shown} is a sum of two squares only over Q(√{})",
            format_scalar(&radicand)
        )),
        Err(e) => Err(format!("its numerator {shown}: {e}")),
    }
}

/// The envelope of the cones of revolution spanned by two rational cycle families
/// (Theorem 4.5), as a PN surface in the parameters `(t, u)`.
#[derive(Debug, Clone)]
pub struct ConeFamilyEnvelope<F> {
    c1: CycleFamily<F>,
    c2: CycleFamily<F>,
    m: [MPoly<F>; 3],
    r: MPoly<F>,
    md: MPoly<F>,
    p: [RatFn<F>; 2],
    isotropic: IsotropicSurface<F>,
    surface: PnSurface<F>,
}

impl<F: Scalar> ConeFamilyEnvelope<F> {
    /// The envelope of the cones `c₁(t) ∨ c₂(t)`; `p = (p₁, p₂)` with
    /// `p₁² + p₂² = |m₁ − m₂|² − (r₁ − r₂)²` (rational in `t`), or `None` to search for it.
    ///
    /// # Errors
    /// [`PnError::NoRationalPoint`] if `p` is not given and not found;
    /// [`PnError::InvalidInput`] if the given `p` violates the identity or the families
    /// coincide; [`PnError::Developable`] if the envelope is developable (e.g. a
    /// developable ruled surface, whose offsets are pipe surfaces).
    pub fn new(
        c1: CycleFamily<F>,
        c2: CycleFamily<F>,
        p: Option<[RatFn<F>; 2]>,
    ) -> Result<Self, PnError> {
        let (w1, w2) = (&c1.den, &c2.den);
        let m: [MPoly<F>; 3] =
            std::array::from_fn(|i| &(&c1.center[i] * w2) - &(&c2.center[i] * w1));
        let r = &(&c1.radius * w2) - &(&c2.radius * w1);
        let md = w1 * w2;
        let mm = &dot3(&m, &m) - &(&r * &r);
        if m.iter().all(|x| x.is_zero()) && r.is_zero() {
            return Err(PnError::InvalidInput(
                "the two cycle families coincide: they span no cone".into(),
            ));
        }
        if mm.is_zero() {
            return Err(PnError::IsotropicCycles(
                "|m₁ − m₂|² − (r₁ − r₂)² ≡ 0: the cycles c₁(t), c₂(t) are in oriented contact for every t, so their common tangent planes form no cone of revolution".into(),
            ));
        }
        let beta = &r + &m[2];
        let p = match p {
            Some(p) => {
                // (pn₁² + pn₂²)·md² ≡ (|M|² − R²)·pd₁²pd₂²   (p_i = pn_i/pd_i)
                let lhs = &(&(&(&p[0].num * &p[0].num) * &(&p[1].den * &p[1].den))
                    + &(&(&p[1].num * &p[1].num) * &(&p[0].den * &p[0].den)))
                    * &(&md * &md);
                let rhs = &mm * &(&(&p[0].den * &p[0].den) * &(&p[1].den * &p[1].den));
                let c = identity_cert("p₁² + p₂² = |M|² − R²", &lhs, &rhs);
                if !c.holds {
                    return Err(PnError::InvalidInput(format!(
                        "the given (p₁, p₂) do not satisfy p₁² + p₂² = |m₁ − m₂|² − (r₁ − r₂)²: {}",
                        c.residual.unwrap_or_default()
                    )));
                }
                p
            }
            None => {
                // |M|² − R² = M_i² + M_j² when M_k² ≡ R² for the third index k
                let pair = (0..3).rev().find_map(|k| {
                    (&(&m[k] * &m[k]) - &(&r * &r)).is_zero().then(|| {
                        let o: Vec<usize> = (0..3).filter(|&i| i != k).collect();
                        [RatFn::poly(m[o[0]].clone()), RatFn::poly(m[o[1]].clone())]
                    })
                });
                let [a, b] = match pair {
                    Some(pr) => pr,
                    None => two_squares_or_reason(&mm).map_err(|why| {
                        PnError::NoRationalPoint(format!(
                            "|m₁ − m₂|² − (r₁ − r₂)² is not a sum of two squares of rational functions of t: {why}"
                        ))
                    })?,
                };
                // the found values are for the numerators M, R: divide by md
                [
                    RatFn {
                        num: a.num,
                        den: &a.den * &md,
                    },
                    RatFn {
                        num: b.num,
                        den: &b.den * &md,
                    },
                ]
            }
        };
        let u = var::<F>(1);
        let u2p1 = &(&u * &u) + &int(1);
        let (a, b, c) = if beta.is_zero() {
            // the line M₁y₁ + M₂y₂ = M₃
            let c = &(&m[0] * &m[0]) + &(&m[1] * &m[1]);
            if c.is_zero() {
                return Err(PnError::InvalidInput(
                    "M₁ ≡ M₂ ≡ 0 and R + M₃ ≡ 0: the cones degenerate".into(),
                ));
            }
            (
                &(&m[2] * &m[0]) - &(&u * &m[1]),
                &(&m[2] * &m[1]) + &(&u * &m[0]),
                c,
            )
        } else {
            // A = (pn₁·Md − M₁·pd)(u²+1) − 2u·Md(pn₁u + pn₂) etc. with a common pd
            let pd = &p[0].den * &p[1].den;
            let pn1 = &p[0].num * &p[1].den;
            let pn2 = &p[1].num * &p[0].den;
            let lin = &(&(&pn1 * &u) + &pn2) * &md;
            let two = F::from_i64(2);
            (
                &(&(&(&pn1 * &md) - &(&m[0] * &pd)) * &u2p1) - &(&u * &lin).scale(&two),
                &(&(&(&pn2 * &md) - &(&m[1] * &pd)) * &u2p1) - &lin.scale(&two),
                &(&pd * &beta) * &u2p1,
            )
        };
        // (4.12) with the first family: y₃ = G/D
        let (m1, r1, w1) = (&c1.center, &c1.radius, &c1.den);
        let aa = &a * &a;
        let bb = &b * &b;
        let cc = &c * &c;
        let two = F::from_i64(2);
        let g = -(&(&(r1 * &(&(&aa + &bb) + &cc)) + &(&m1[2] * &(&(&aa + &bb) - &cc)))
            + &(&(&(&m1[0] * &a) + &(&m1[1] * &b)) * &c).scale(&two));
        let d = (w1 * &cc).scale(&two);
        let mut parts = vec![a, b, c.clone(), g, d];
        // common factors of (A, B, C) and of (G, D) separately
        let mut abc = parts[..3].to_vec();
        let cands = vec![u2p1.clone(), beta.clone(), md.clone()];
        cancel_common(&mut abc, &cands);
        normalize_content(&mut abc);
        let mut gd = parts[3..].to_vec();
        cancel_common(&mut gd, &[c.clone(), w1.clone()]);
        parts = abc.into_iter().chain(gd).collect();
        let isotropic = IsotropicSurface::new(
            parts[0].clone(),
            parts[1].clone(),
            parts[2].clone(),
            parts[3].clone(),
            parts[4].clone(),
        )?
        .named("cone-family envelope (Theorem 4.5)");
        let mut extra = cands;
        extra.extend([w1.clone(), w2.clone()]);
        // Where p₁ = p₂ = 0 (a real zero of |M|² − R²) the circle d′(t) has radius 0 and
        // every u gives the same point: the point map has a base point along that t, a
        // common factor of the point coordinates. Offering the factors of p as candidates
        // cancels it by exact division in both paths (f64 has no polynomial gcd), so exact
        // and f64 keep the same representation (docs/plans/pn-laguerre.md, item 1).
        extra.extend([p[0].num.clone(), p[1].num.clone()]);
        if F::EXACT {
            extra.push(gcd2(&p[0].num, &p[1].num));
        }
        let surface = isotropic.to_pn_surface_with(&extra)?;
        if surface.point_map_degenerate() {
            return Err(PnError::Developable(
                "the envelope of the cones is a curve or a point (det(x_u, x_v, n) ≡ 0), not a surface".into(),
            ));
        }
        Ok(ConeFamilyEnvelope {
            c1,
            c2,
            m,
            r,
            md,
            p,
            isotropic,
            surface,
        })
    }

    /// The envelope built in the coordinates `x′ = H x` of an orthogonal, symmetric `H`
    /// (a reflection), mapped back: the surface `x = H x′`, `n = H n′`, and the given cycle
    /// families `c₁, c₂` (in the original coordinates, of which `self`'s are the images).
    /// The isotropic surface and `(p₁, p₂)` stay those of the frame.
    pub(crate) fn transformed(
        &self,
        h: &[[F; 3]; 3],
        c1: CycleFamily<F>,
        c2: CycleFamily<F>,
    ) -> Result<Self, PnError> {
        let x = self.surface.point_polys();
        let n = self.surface.normal_polys();
        let map = |v: &[MPoly<F>; 4]| -> [MPoly<F>; 4] {
            let mut out = v.clone();
            for (i, row) in h.iter().enumerate() {
                out[i + 1] = (0..3).fold(MPoly::zero(2), |acc, j| &acc + &v[j + 1].scale(&row[j]));
            }
            out
        };
        let surface = PnSurface::from_point_normal(map(x), map(n))?.named(self.surface.name());
        let (w1, w2) = (&c1.den, &c2.den);
        let m: [MPoly<F>; 3] =
            std::array::from_fn(|i| &(&c1.center[i] * w2) - &(&c2.center[i] * w1));
        let r = &(&c1.radius * w2) - &(&c2.radius * w1);
        let md = w1 * w2;
        Ok(ConeFamilyEnvelope {
            c1,
            c2,
            m,
            r,
            md,
            p: self.p.clone(),
            isotropic: self.isotropic.clone(),
            surface,
        })
    }

    /// The envelope as a PN surface in `(t, u)`.
    pub fn surface(&self) -> &PnSurface<F> {
        &self.surface
    }

    /// The isotropic surface `y(t, u)` (4.11)/(4.12).
    pub fn isotropic(&self) -> &IsotropicSurface<F> {
        &self.isotropic
    }

    /// `(p₁, p₂)` with `p₁² + p₂² = |M|² − R²`.
    pub fn p(&self) -> &[RatFn<F>; 2] {
        &self.p
    }

    /// `M = m₁ − m₂` and `R = r₁ − r₂` as numerators over the common denominator
    /// `w₁w₂`: `(M₁, M₂, M₃, R, w₁w₂)`.
    pub fn m_r(&self) -> [&MPoly<F>; 5] {
        [&self.m[0], &self.m[1], &self.m[2], &self.r, &self.md]
    }

    /// The two cycle families.
    pub fn families(&self) -> (&CycleFamily<F>, &CycleFamily<F>) {
        (&self.c1, &self.c2)
    }

    /// The certificates that the tangent planes touch both cycle families:
    /// `h + n·m_i + r_i ≡ 0`, i.e. `H N₀ w_i + L (N·M_i + N₀ R_i) ≡ 0`.
    pub fn tangency_certificates(&self) -> Vec<Certificate> {
        let h = self.surface.support();
        let n = self.surface.normal_polys();
        [(&self.c1, "c₁"), (&self.c2, "c₂")]
            .into_iter()
            .map(|(c, name)| {
                let lhs = &(&h.num * &n[0]) * &c.den;
                let rhs = -(&h.den * &(&dot3(&n[1..], &c.center) + &(&n[0] * &c.radius)));
                identity_cert(
                    &format!("every tangent plane touches the cycle family {name}: e0 + n·m + r ≡ 0 (Peternell (3.3))"),
                    &lhs,
                    &rhs,
                )
            })
            .collect()
    }
}

impl<F: Scalar> ConeFamilyEnvelope<F> {
    /// The certificates that the envelope touches every cone `Δ(t)` along a curve:
    /// `Φ_t(x(t, u)) ≡ 0` and `(∂_tΦ_t)(x(t, u)) ≡ 0` (`x` held fixed when differentiating),
    /// with the cone of revolution spanned by the two cycles in the vertex-free form
    /// `Φ_t(x) = ((x − m₁)·M + r₁R)² − (|M|² − R²)(|x − m₁|² − r₁²)`
    /// (Peternell §4.5 writes it with the vertex `V = (r₂m₁ − r₁m₂)/(r₂ − r₁)` as
    /// `((x − V)·M)² − (|M|² − R²)|x − V|²`; both are the same polynomial, and the form used
    /// here also covers cylinders, `R ≡ 0`: docs/math/laguerre-pn.md#cone-of-two-cycles).
    ///
    /// With `m₁ = m/w`, `r₁ = ρ/w`, `M = M̃/δ`, `R = R̃/δ`, `x = X/W` and `D = Xw − Wm`:
    /// `Φ = 0 ⇔ S² ≡ Q G` with `S = D·M̃ + Wρ R̃`, `Q = |M̃|² − R̃²`, `G = |D|² − W²ρ²`; and
    /// `∂_tΦ = 0 ⇔ S S′ ≡ w Q′ G − W δ Q G′` with `m′ = ṁw − mẇ`, `M′ = Ṁ̃δ − M̃δ̇` (same for
    /// `ρ`, `R̃`), `S′ = −Wδ(m′·M̃) + w(D·M′) + Wδρ′R̃ + Wwρ R′`, `Q′ = M̃·M′ − R̃R′`,
    /// `G′ = D·m′ + Wρρ′`.
    pub fn cone_certificates(&self) -> Vec<Certificate> {
        let x = self.surface.point_polys();
        let (m, rho, w) = (&self.c1.center, &self.c1.radius, &self.c1.den);
        let (mm, rr, md) = (&self.m, &self.r, &self.md);
        let big_w = &x[0];
        let d: [MPoly<F>; 3] = std::array::from_fn(|k| &(&x[k + 1] * w) - &(big_w * &m[k]));
        let s = &dot3(&d, mm) + &(&(big_w * rho) * rr);
        let q = &dot3(mm, mm) - &(rr * rr);
        let g = &dot3(&d, &d) - &(&(big_w * big_w) * &(rho * rho));
        let phi = identity_cert(
            "the envelope lies on every cone Δ(t): Φ_t(x) = ((x − m₁)·M + r₁R)² − (|M|² − R²)(|x − m₁|² − r₁²) ≡ 0 (Peternell §4.5)",
            &(&s * &s),
            &(&q * &g),
        );
        let dot_t = |p: &MPoly<F>, den: &MPoly<F>| &(&p.partial(0) * den) - &(p * &den.partial(0));
        let m_d: [MPoly<F>; 3] = std::array::from_fn(|k| dot_t(&m[k], w));
        let rho_d = dot_t(rho, w);
        let mm_d: [MPoly<F>; 3] = std::array::from_fn(|k| dot_t(&mm[k], md));
        let rr_d = dot_t(rr, md);
        let wd = big_w * md;
        let s_d = &(&(&(&(-&wd) * &dot3(&m_d, mm)) + &(w * &dot3(&d, &mm_d)))
            + &(&(&wd * &rho_d) * rr))
            + &(&(&(big_w * w) * rho) * &rr_d);
        let q_d = &dot3(mm, &mm_d) - &(rr * &rr_d);
        let g_d = &dot3(&d, &m_d) + &(&(big_w * rho) * &rho_d);
        let dphi = identity_cert(
            "the envelope touches Δ(t) along its characteristic curve: ∂_tΦ_t(x) ≡ 0 (x fixed; Peternell §4.5)",
            &(&s * &s_d),
            &(&(&(w * &q_d) * &g) - &(&(&wd * &q) * &g_d)),
        );
        vec![phi, dphi]
    }
}

impl<F: Scalar> ConeFamilyEnvelope<F> {
    /// The certificates that the offset at distance `d` is the envelope of the offset
    /// cones: its tangent planes touch the cycle families `(m_i; r_i + d)` (offsets of
    /// cycles, docs/math/laguerre-pn.md#conventions): `h_d + n·m_i + r_i + d ≡ 0`.
    pub fn offset_tangency_certificates(&self, d: &F) -> Vec<Certificate> {
        let off = self.surface.offset(d.clone());
        let s = off.surface();
        let h = s.support();
        let n = s.normal_polys();
        [(&self.c1, "c₁"), (&self.c2, "c₂")]
            .into_iter()
            .map(|(c, name)| {
                let lhs = &(&h.num * &n[0]) * &c.den;
                let r = &c.radius + &c.den.scale(d);
                let rhs = -(&h.den * &(&dot3(&n[1..], &c.center) + &(&n[0] * &r)));
                identity_cert(
                    &format!(
                        "the offset at distance {} touches the offset cycle family {name} + d: e0 + n·m + (r + d) ≡ 0",
                        format_scalar(d)
                    ),
                    &lhs,
                    &rhs,
                )
            })
            .collect()
    }
}

impl<F: Scalar> Certified for ConeFamilyEnvelope<F> {
    /// The PN identities, the tangency to both cycle families and the contact with every
    /// cone `Δ(t)` (Theorem 4.5).
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.surface.certify();
        out.extend(self.tangency_certificates());
        out.extend(self.cone_certificates());
        out
    }
}

/// A non-developable rational ruled surface `x = l(t) + v g(t)` with its PN
/// parametrization (Cor. 4.2: Theorem 4.5 with the point families `(l; 0)`, `(l + g; 0)`).
#[derive(Debug, Clone)]
pub struct RuledPn<F> {
    l: [RatFn<F>; 3],
    g: [RatFn<F>; 3],
    envelope: ConeFamilyEnvelope<F>,
}

impl<F: Scalar> RuledPn<F> {
    /// The PN parametrization of the ruled surface `l(t) + v g(t)`; `p` with
    /// `p₁² + p₂² = |g|²` or `None` to search (found at least when some `g_k ≡ 0`, or `|g|²`
    /// is a (rational multiple of a) square).
    ///
    /// # Errors
    /// As [`ConeFamilyEnvelope::new`]; [`PnError::Developable`] for a developable ruled
    /// surface (its offsets are pipe surfaces around the edge of regression, Peternell §4.5).
    pub fn new(
        l: [RatFn<F>; 3],
        g: [RatFn<F>; 3],
        p: Option<[RatFn<F>; 2]>,
    ) -> Result<Self, PnError> {
        let lg: [RatFn<F>; 3] = std::array::from_fn(|i| l[i].add(&g[i]));
        let c1 = CycleFamily::points(l.clone())?;
        let c2 = CycleFamily::points(lg)?;
        let envelope = ConeFamilyEnvelope::new(c1, c2, p).map_err(|e| match e {
            PnError::Developable(s) => PnError::Developable(format!(
                "the ruled surface is developable ({s}); its offsets are pipe surfaces of the edge of regression (Peternell §4.5)"
            )),
            e => e,
        })?;
        Ok(RuledPn { l, g, envelope })
    }

    /// The PN surface (parameters `(t, u)`; the `u`-curves are the rulings).
    pub fn surface(&self) -> &PnSurface<F> {
        self.envelope.surface()
    }

    /// The cone-family envelope behind it.
    pub fn envelope(&self) -> &ConeFamilyEnvelope<F> {
        &self.envelope
    }

    /// The certificate that every point lies on its ruling: `(x − l(t)) × g(t) ≡ 0`.
    pub fn on_ruling_certificates(&self) -> Vec<Certificate> {
        let x = self.surface().point_polys();
        // x − l = (X·ld − ln·W)/(W·ld) per component; g = gn/gd
        let d: [MPoly<F>; 3] = std::array::from_fn(|i| {
            let l = &self.l[i];
            let other: MPoly<F> = (0..3)
                .filter(|&k| k != i)
                .fold(int(1), |acc, k| &acc * &self.l[k].den);
            &(&(&x[i + 1] * &l.den) - &(&l.num * &x[0])) * &other
        });
        let gg: [MPoly<F>; 3] = std::array::from_fn(|i| {
            let other: MPoly<F> = (0..3)
                .filter(|&k| k != i)
                .fold(int(1), |acc, k| &acc * &self.g[k].den);
            &self.g[i].num * &other
        });
        cross3(&d, &gg)
            .iter()
            .enumerate()
            .map(|(k, c)| {
                zero_cert(
                    &format!("point on its ruling: (x − l) × g ≡ 0 (component {k})"),
                    c,
                    1e3 * mag(c),
                )
            })
            .collect()
    }
}

impl<F: Scalar> Certified for RuledPn<F> {
    /// PN identities, tangency, and every point on its ruling.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.envelope.certify();
        out.extend(self.on_ruling_certificates());
        out
    }
}

/// A canal surface with rational spine `m(t)` and rational radius `r(t)` as a PN surface
/// (Cor. 4.3: Theorem 4.5 with `c` and `c + ċ`); real where `|ṁ|² ≥ ṙ²`.
#[derive(Debug, Clone)]
pub struct CanalPn<F> {
    family: CycleFamily<F>,
    envelope: ConeFamilyEnvelope<F>,
}

impl<F: Scalar> CanalPn<F> {
    /// The canal surface of the cycle family `(m; r)(t)`; `p` with
    /// `p₁² + p₂² = |ṁ|² − ṙ²` (or `None` to search).
    ///
    /// # Errors
    /// As [`ConeFamilyEnvelope::new`].
    pub fn new(family: CycleFamily<F>, p: Option<[RatFn<F>; 2]>) -> Result<Self, PnError> {
        let c2 = family.plus_derivative();
        let envelope = ConeFamilyEnvelope::new(family.clone(), c2, p).map_err(|e| match e {
            // the second family is (m + m′; r + r′): name the spine and radius instead
            PnError::NoRationalPoint(m) => {
                PnError::NoRationalPoint(m.replace("|m₁ − m₂|² − (r₁ − r₂)²", "|m′(t)|² − r′(t)²"))
            }
            PnError::IsotropicCycles(_) => PnError::IsotropicCycles(
                "|m′(t)|² − r′(t)² ≡ 0: every tangent of the cycle curve is isotropic (the spheres touch their neighbours), so the canal surface degenerates".into(),
            ),
            e => e,
        })?;
        Ok(CanalPn { family, envelope })
    }

    /// The PN surface.
    pub fn surface(&self) -> &PnSurface<F> {
        self.envelope.surface()
    }

    /// The cone-family envelope behind it.
    pub fn envelope(&self) -> &ConeFamilyEnvelope<F> {
        &self.envelope
    }

    /// The certificate `x ≡ m + r n` (the contact point of the tangent plane with the
    /// sphere `c(t)`; so `|x − m| = |r|`): `X N₀ w − W (M N₀ + R N) ≡ 0`.
    pub fn on_spheres_certificates(&self) -> Vec<Certificate> {
        let x = self.surface().point_polys();
        let n = self.surface().normal_polys();
        let (m, r, w) = (&self.family.center, &self.family.radius, &self.family.den);
        (0..3)
            .map(|i| {
                let lhs = &(&x[i + 1] * &n[0]) * w;
                let rhs = &x[0] * &(&(&m[i] * &n[0]) + &(r * &n[i + 1]));
                identity_cert(
                    &format!("canal surface: x ≡ m + r n (component {i}, so |x − m| = |r|)"),
                    &lhs,
                    &rhs,
                )
            })
            .collect()
    }
}

impl<F: Scalar> Certified for CanalPn<F> {
    /// PN identities, tangency and `x ≡ m + r n`.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.envelope.certify();
        out.extend(self.on_spheres_certificates());
        out
    }
}

/// The ellipsoid `x₁²/a² + x₂²/b² + x₃²/c² = 1` (`a ≥ b ≥ c > 0`, `a > c`) as a PN surface
/// in the frame of Peternell §4.7 (origin at the centre, `x₃` parallel to the normal at an
/// umbilic point, `x₂` kept): the envelope of the cones of revolution with vertices on
/// the focal hyperbola, `c₁ = (m₁; 0)`, `c₂ = (m₂; b)`,
/// `m₁ = (αγ(t⁴+1), 0, ac(t⁴+1) + 2b²t²)/(b(t⁴−1))`,
/// `m₂ = (t²−1)/(b(t²+1))·(αγ, 0, ac − b²)`, and `p = β(ρ₁, ρ₂)`,
/// `(ρ₁, ρ₂) = bt(μ(t²+1), (a−c)t)/(act² + b²)` (docs/math/laguerre-pn.md), with `α = √(b²−c²)`,
/// `γ = √(a²−b²)`, `μ = √(ac)`. The ellipsoid of revolution `a = b` needs only `μ`.
/// In this frame the ellipsoid is, in plane coordinates,
/// `e0² = K₁₁n₁² + b²n₂² + (a²c²/b²)n₃² + 2(αγac/b²)n₁n₃`,
/// `K₁₁ = (b²(a² + c²) − a²c²)/b²` ([`Self::dual_quadric_certificate`]).
#[derive(Debug, Clone)]
pub struct EllipsoidPn<F> {
    abc: [F; 3],
    alpha_gamma: F,
    envelope: ConeFamilyEnvelope<F>,
}

impl<F: Scalar> EllipsoidPn<F> {
    /// The PN ellipsoid in the umbilic frame.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] unless `a ≥ b ≥ c > 0` and `a > c`;
    /// [`PnError::NoRationalPoint`] if `√(b²−c²)·√(a²−b²)` or `√(ac)` is irrational
    /// (e.g. `(a, b, c) = (25/3, 5, 3)` gives `α = 4, γ = 20/3, μ = 5`).
    pub fn new(a: F, b: F, c: F) -> Result<Self, PnError> {
        if !(c > F::zero() && b >= c && a >= b && a > c) {
            return Err(PnError::InvalidInput(format!(
                "the ellipsoid needs a ≥ b ≥ c > 0 and a > c, got ({}, {}, {})",
                format_scalar(&a),
                format_scalar(&b),
                format_scalar(&c)
            )));
        }
        let sq = |x: F, what: &str| {
            super::poly::scalar_sqrt(&x).ok_or_else(|| {
                PnError::NoRationalPoint(format!(
                    "{what} = √{} is irrational: the rotation to the umbilic frame and the cone family need it rational",
                    format_scalar(&x)
                ))
            })
        };
        let ag = sq(
            (b.clone() * b.clone() - c.clone() * c.clone())
                * (a.clone() * a.clone() - b.clone() * b.clone()),
            "αγ",
        )?;
        let mu = sq(a.clone() * c.clone(), "μ")?;
        let t = var::<F>(0);
        let t2 = &t * &t;
        let t4 = &t2 * &t2;
        let k = |x: &F| MPoly::constant(2, x.clone());
        let ac = a.clone() * c.clone();
        let b2 = b.clone() * b.clone();
        let t4p1 = &t4 + &int(1);
        let c1 = CycleFamily::new(
            [
                t4p1.scale(&ag),
                MPoly::zero(2),
                &t4p1.scale(&ac) + &t2.scale(&(F::from_i64(2) * b2.clone())),
            ],
            MPoly::zero(2),
            (&t4 - &int(1)).scale(&b),
        )?;
        let t2m1 = &t2 - &int(1);
        let c2 = CycleFamily::new(
            [
                t2m1.scale(&ag),
                MPoly::zero(2),
                t2m1.scale(&(ac.clone() - b2.clone())),
            ],
            (&t2 + &int(1)).scale(&(b.clone() * b.clone())),
            (&t2 + &int(1)).scale(&b),
        )?;
        // ρ = bt(μ(t²+1), (a−c)t)/(act² + b²); p = β ρ, β = R + M₃ (rational)
        let rden = &t2.scale(&ac) + &k(&b2);
        let rho1 = RatFn {
            num: (&t * &(&t2 + &int(1))).scale(&(b.clone() * mu.clone())),
            den: rden.clone(),
        };
        let rho2 = RatFn {
            num: t2.scale(&(b.clone() * (a.clone() - c.clone()))),
            den: rden,
        };
        // β = (r₁ − r₂) + (m₁₃ − m₂₃)
        let beta = {
            let (cm1, r1, w1) = (&c1.center, &c1.radius, &c1.den);
            let (cm2, r2, w2) = (&c2.center, &c2.radius, &c2.den);
            RatFn {
                num: &(&(r1 + &cm1[2]) * w2) - &(&(r2 + &cm2[2]) * w1),
                den: w1 * w2,
            }
        };
        let p = [beta.mul(&rho1), beta.mul(&rho2)];
        let envelope = ConeFamilyEnvelope::new(c1, c2, Some(p))?;
        Ok(EllipsoidPn {
            abc: [a, b, c],
            alpha_gamma: ag,
            envelope,
        })
    }

    /// The PN surface of the ellipsoid (parameters `(t, u)`).
    pub fn surface(&self) -> &PnSurface<F> {
        self.envelope.surface()
    }

    /// The cone-family envelope behind it.
    pub fn envelope(&self) -> &ConeFamilyEnvelope<F> {
        &self.envelope
    }

    /// `e0² ≡ K₁₁n₁² + b²n₂² + (a²c²/b²)n₃² + 2(αγac/b²)n₁n₃` for the tangent planes of
    /// the surface offset by `d` from the ellipsoid, with `e0 ↦ e0 + d` undone (the offsets
    /// have `e0_d = e0 − d`): the planes of the base are tangent to the ellipsoid.
    pub fn dual_quadric_certificate(&self, surface: &PnSurface<F>) -> Certificate {
        let [a, b, c] = &self.abc;
        let b2 = b.clone() * b.clone();
        let ac = a.clone() * c.clone();
        let k11 = (b2.clone() * (a.clone() * a.clone() + c.clone() * c.clone())
            - ac.clone() * ac.clone())
            / b2.clone();
        let k33 = ac.clone() * ac.clone() / b2.clone();
        let k13 = self.alpha_gamma.clone() * ac / b2.clone();
        let n = surface.normal_polys();
        let h = surface.support();
        // e0 of the ellipsoid's own plane: h + distance
        let e0n = &h.num + &h.den.scale(surface.distance());
        let quad = &(&(&(&n[1] * &n[1]).scale(&k11) + &(&n[2] * &n[2]).scale(&b2))
            + &(&n[3] * &n[3]).scale(&k33))
            + &(&n[1] * &n[3]).scale(&(F::from_i64(2) * k13));
        // e0 = e0n/L, n = N/N₀: e0² = nᵀK*n  ⇔  e0n²·N₀² ≡ (NᵀK*N)·L²
        let lhs = &(&e0n * &e0n) * &(&n[0] * &n[0]);
        let rhs = &quad * &(&h.den * &h.den);
        identity_cert(
            "tangent planes of the ellipsoid (umbilic frame): e0² ≡ nᵀK*n (Peternell §4.7)",
            &lhs,
            &rhs,
        )
    }
}

impl<F: Scalar> Certified for EllipsoidPn<F> {
    /// PN identities, tangency to the cone families, and the dual quadric equation.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.envelope.certify();
        out.push(self.dual_quadric_certificate(self.surface()));
        out
    }
}

// -------------------------------------------------------------------------------------
// Theorem 5.2: offsets of ruled 2-manifolds in Rⁿ
// -------------------------------------------------------------------------------------

/// How to obtain the rational unit normal of a ruled manifold (Theorem 5.2, Steps 1–2;
/// Peternell finds it with Prop. 5.1, a rational point on a conic family, which needs
/// roots of polynomials in general — docs/math/laguerre-pn.md#conventions).
#[derive(Debug, Clone)]
pub enum NormalHint<F> {
    /// Search: a normal `z` linear in `u` (5.23)/(5.24) whose squared length is a square
    /// at a constant ruling parameter `u* ∈ {∞, 0, ±1, ±2, ±1/2, ±3}` (or, where the normal
    /// space is constant along the rulings, a constant combination of two normals).
    Search,
    /// A given rational unit normal field `m(t, u)` (validated exactly).
    UnitNormal(Vec<RatFn<F>>),
    /// A given ruling parameter `u*(t)` at which the chosen normal has rational length.
    RulingPoint(RatFn<F>),
}

/// `(g, p_t, P, w)` polynomial vectors of a ruled manifold (see `RuledManifold::polys`).
type RuledPolys<F> = (Vec<MPoly<F>>, Vec<MPoly<F>>, Vec<MPoly<F>>, MPoly<F>);

/// A rational ruled 2-manifold `p(t, u) = l(t) + u g(t)` in `Rⁿ` (Peternell (5.13), `k = 1`).
#[derive(Debug, Clone)]
pub struct RuledManifold<F> {
    l: Vec<RatFn<F>>,
    g: Vec<RatFn<F>>,
}

/// Substitutes `u = a/b` into a polynomial of degree ≤ `k` in `x₁` (`u`): the numerator
/// `Σ P_j a^j b^{k−j}` over `b^k`.
fn subst_u<F: Scalar>(p: &MPoly<F>, a: &MPoly<F>, b: &MPoly<F>, k: u32) -> MPoly<F> {
    let mut acc = MPoly::zero(2);
    for (e, c) in p.terms() {
        let j = e.get(1).copied().unwrap_or(0);
        let mut rest = e.to_vec();
        if let Some(x) = rest.get_mut(1) {
            *x = 0;
        }
        let mono = MPoly::monomial(2, &rest, c.clone());
        acc = &acc + &(&(&mono * &a.pow(j)) * &b.pow(k.saturating_sub(j)));
    }
    acc
}

impl<F: Scalar> RuledManifold<F> {
    /// The ruled 2-manifold `l(t) + u g(t)` (`t` = variable 0, `u` = variable 1); `l` and
    /// `g` have the same length `n ≥ 3` and depend on `t` only.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] for mismatched lengths, `n < 3`, `g ≡ 0`, or a dependence
    /// on other variables.
    pub fn new(l: Vec<RatFn<F>>, g: Vec<RatFn<F>>) -> Result<Self, PnError> {
        if l.len() != g.len() || l.len() < 3 {
            return Err(PnError::InvalidInput(format!(
                "a ruled manifold in Rⁿ needs l and g of the same length n ≥ 3 (got {} and {})",
                l.len(),
                g.len()
            )));
        }
        if g.iter().all(|x| x.num.is_zero()) {
            return Err(PnError::InvalidInput(
                "the generator g(t) is identically zero".into(),
            ));
        }
        if !l.iter().chain(&g).all(|f| only_t(&f.num) && only_t(&f.den)) {
            return Err(PnError::InvalidInput(
                "l and g must depend on t (variable 0) only".into(),
            ));
        }
        Ok(RuledManifold { l, g })
    }

    /// The ambient dimension `n`.
    pub fn dim(&self) -> usize {
        self.l.len()
    }

    /// Polynomial vectors proportional to `g` and to `p_t = l̇ + u ġ` (common denominators
    /// cleared), and the point numerators `(P, w)` with `p = P/w`.
    fn polys(&self) -> RuledPolys<F> {
        let ld = self.l.iter().fold(int::<F>(1), |a, f| &a * &f.den);
        let gd = self.g.iter().fold(int::<F>(1), |a, f| &a * &f.den);
        let over = |f: &RatFn<F>, all: &[RatFn<F>]| -> MPoly<F> {
            all.iter()
                .filter(|x| !std::ptr::eq(*x, f))
                .fold(f.num.clone(), |a, x| &a * &x.den)
        };
        let ln: Vec<MPoly<F>> = self.l.iter().map(|f| over(f, &self.l)).collect();
        let gn: Vec<MPoly<F>> = self.g.iter().map(|f| over(f, &self.g)).collect();
        let u = var::<F>(1);
        let (ldd, gdd) = (ld.partial(0), gd.partial(0));
        // p_t ∝ (L' ld − L ld')·gd² + u (G' gd − G gd')·ld²
        let gd2 = &gd * &gd;
        let ld2 = &ld * &ld;
        let pt: Vec<MPoly<F>> = ln
            .iter()
            .zip(&gn)
            .map(|(l, g)| {
                let a = &(&(&l.partial(0) * &ld) - &(l * &ldd)) * &gd2;
                let b = &(&(&g.partial(0) * &gd) - &(g * &gdd)) * &ld2;
                &a + &(&u * &b)
            })
            .collect();
        // p = L/ld + u G/gd = (L gd + u G ld)/(ld gd)
        let pn: Vec<MPoly<F>> = ln
            .iter()
            .zip(&gn)
            .map(|(l, g)| &(l * &gd) + &(&u * &(g * &ld)))
            .collect();
        (gn, pt, pn, &ld * &gd)
    }

    /// Normals `z_i` (5.23): `z_i = −(b_i·p_t) b₁ + (b₁·p_t) b_i` from a polynomial basis
    /// `b` of `g^⊥`, linear in `u`; they span the normal space where `b₁·p_t ≠ 0`.
    fn normals(&self, gn: &[MPoly<F>], pt: &[MPoly<F>]) -> Result<Vec<Vec<MPoly<F>>>, PnError> {
        let n = gn.len();
        let j = (0..n).find(|&i| !gn[i].is_zero()).unwrap_or(0);
        let basis: Vec<Vec<MPoly<F>>> = (0..n)
            .filter(|&i| i != j)
            .map(|i| {
                let mut b = vec![MPoly::zero(2); n];
                b[i] = gn[j].clone();
                b[j] = -gn[i].clone();
                b
            })
            .collect();
        let dots: Vec<MPoly<F>> = basis.iter().map(|b| dot3(b, pt)).collect();
        let Some(first) = (0..basis.len()).find(|&i| !dots[i].is_zero()) else {
            return Err(PnError::Developable(
                "p_t ∥ g everywhere: the manifold is a curve (no tangent plane)".into(),
            ));
        };
        let (b1, d1) = (&basis[first], &dots[first]);
        Ok((0..basis.len())
            .filter(|&i| i != first)
            .map(|i| {
                (0..n)
                    .map(|c| &(&(-dots[i].clone()) * &b1[c]) + &(d1 * &basis[i][c]))
                    .collect()
            })
            .collect())
    }

    /// The offset hypersurface at distance `d` (Theorem 5.2): a rational map of the `n − 1`
    /// parameters `(t, s, v₁, …, v_{n−3})` (`s` the new ruling parameter where the unit
    /// normal needed a reparametrization `u = u(t, s)`, else `s = u`).
    ///
    /// # Errors
    /// [`PnError::NoRationalPoint`] if no rational unit normal is found or given (in
    /// particular for `n = 3` and a normal space constant along the rulings — developables
    /// and cylinders, Peternell's excluded cases — unless the normal has rational length);
    /// [`PnError::InvalidInput`] for an invalid hint; [`PnError::Developable`] if the
    /// manifold has no tangent planes.
    pub fn offset(&self, d: F, hint: NormalHint<F>) -> Result<RuledOffset<F>, PnError> {
        let n = self.dim();
        let (gn, pt, pn, pw) = self.polys();
        let zs = self.normals(&gn, &pt)?;
        let depends_on_u = |z: &[MPoly<F>]| z.iter().any(|c| c.degree_in(1).unwrap_or(0) > 0);
        let u_free = zs.iter().all(|z| !depends_on_u(z));
        // (u(t,s) as a/b, unit normal numerators M and its denominator w)
        let (ua, ub, m, mw): (MPoly<F>, MPoly<F>, Vec<MPoly<F>>, MPoly<F>) = match hint {
            NormalHint::UnitNormal(mv) => {
                if mv.len() != n {
                    return Err(PnError::InvalidInput(format!(
                        "the unit normal has {} components, the manifold lives in R^{n}",
                        mv.len()
                    )));
                }
                let den = mv.iter().fold(int::<F>(1), |a, f| &a * &f.den);
                let num: Vec<MPoly<F>> = mv
                    .iter()
                    .map(|f| {
                        mv.iter()
                            .filter(|x| !std::ptr::eq(*x, f))
                            .fold(f.num.clone(), |a, x| &a * &x.den)
                    })
                    .collect();
                let ok = (&dot3(&num, &num) - &(&den * &den)).is_zero()
                    && dot3(&num, &gn).is_zero()
                    && dot3(&num, &pt).is_zero();
                if !ok {
                    return Err(PnError::InvalidInput(
                        "the given vector field is not a unit normal (|m|² ≡ 1, m·g ≡ 0, m·p_t ≡ 0)".into(),
                    ));
                }
                (var(1), int(1), num, den)
            }
            NormalHint::RulingPoint(us) => {
                let z = zs
                    .first()
                    .ok_or_else(|| PnError::InvalidInput("no normal vectors (n < 3)".into()))?;
                self.reparam_from(z, &us.num, &us.den, false)?
                    .ok_or_else(|| {
                        PnError::NoRationalPoint(
                            "|z(t, u*(t))|² is not the square of a rational function for the given u*(t)".into(),
                        )
                    })?
            }
            NormalHint::Search => {
                let consts = [0i64, 1, -1, 2, -2, 3, -3];
                let halves = [(1i64, 2i64), (-1, 2), (1, 3), (-1, 3)];
                let mut cands: Vec<(MPoly<F>, MPoly<F>, bool)> = vec![(int(1), int(0), true)];
                cands.extend(consts.iter().map(|&c| (int(c), int(1), false)));
                cands.extend(halves.iter().map(|&(p, q)| (int(p), int(q), false)));
                let mut found = None;
                if u_free {
                    // constant combinations z_i + s z_j (and single z_i)
                    'outer: for (i, zi) in zs.iter().enumerate() {
                        for (j, zj) in zs.iter().enumerate() {
                            if i == j && i > 0 {
                                continue;
                            }
                            for (a, b, _) in &cands {
                                let comb: Vec<MPoly<F>> = if i == j {
                                    zi.clone()
                                } else {
                                    zi.iter()
                                        .zip(zj)
                                        .map(|(x, y)| &(x * b) + &(y * a))
                                        .collect()
                                };
                                if comb.iter().all(|c| c.is_zero()) {
                                    continue;
                                }
                                if let Some(w) = univariate_sqrt(&dot3(&comb, &comb)) {
                                    found = Some((var(1), int(1), comb, w));
                                    break 'outer;
                                }
                            }
                        }
                    }
                } else {
                    'outer2: for z in zs.iter().filter(|z| depends_on_u(z)) {
                        for (a, b, inf) in &cands {
                            if let Some(r) = self.reparam_from(z, a, b, *inf)? {
                                found = Some(r);
                                break 'outer2;
                            }
                        }
                    }
                }
                found.ok_or_else(|| {
                    PnError::NoRationalPoint(if u_free && n == 3 {
                        "the normal is constant along the rulings (developable or cylinder, Case 1 m = 1 / Case 2 m = 0 with dim N = 1) and has no rational length: the offset is not rational in general (Peternell §5.5)".into()
                    } else {
                        "no rational unit normal found by the search (the conic family (5.25) needs a point over Q(t); pass NormalHint::RulingPoint or NormalHint::UnitNormal)".into()
                    })
                })?
            }
        };
        // substitute u = ua/ub into p, the normals
        let sub_vec = |v: &[MPoly<F>]| -> Vec<MPoly<F>> {
            v.iter().map(|c| subst_u(c, &ua, &ub, 1)).collect()
        };
        let p_num = sub_vec(&pn); // over pw·ub
        let p_den = &pw * &ub;
        let basis: Vec<Vec<MPoly<F>>> = zs.iter().map(|z| sub_vec(z)).collect();
        // normal-space directions c(v) = Σ v_i Z_i + Z_last (variables 2, 3, …)
        let cvec: Vec<MPoly<F>> = if n > 3 {
            let last = basis.len() - 1;
            (0..n)
                .map(|c| {
                    basis
                        .iter()
                        .enumerate()
                        .fold(MPoly::zero(n - 1), |acc, (i, z)| {
                            let coef = if i == last {
                                MPoly::constant(n - 1, F::one())
                            } else {
                                MPoly::var(n - 1, i + 2)
                            };
                            &acc + &(&coef * &z[c])
                        })
                })
                .collect()
        } else {
            Vec::new()
        };
        // y = p + d M − 2d (M·c)/(c·c) c, M = m/mw
        let mut offset: Vec<RatFn<F>> = Vec::with_capacity(n);
        let two_d = F::from_i64(2) * d.clone();
        let (mc, cc) = if n > 3 {
            (dot3(&m, &cvec), dot3(&cvec, &cvec))
        } else {
            (MPoly::zero(2), int(1))
        };
        for c in 0..n {
            let p = RatFn {
                num: p_num[c].clone(),
                den: p_den.clone(),
            };
            let dm = RatFn {
                num: m[c].scale(&d),
                den: mw.clone(),
            };
            let mut y = p.add(&dm);
            if n > 3 {
                let refl = RatFn {
                    num: (&mc * &cvec[c]).scale(&two_d),
                    den: &mw * &cc,
                };
                y = y.sub(&refl);
            }
            offset.push(y);
        }
        let reparam = (ub.total_degree().unwrap_or(0) > 0 || ua != var(1)).then(|| RatFn {
            num: ua.clone(),
            den: ub.clone(),
        });
        Ok(RuledOffset {
            manifold: self.clone(),
            distance: d,
            point: (0..n)
                .map(|c| RatFn {
                    num: p_num[c].clone(),
                    den: p_den.clone(),
                })
                .collect(),
            unit_normal: m
                .iter()
                .map(|c| RatFn {
                    num: c.clone(),
                    den: mw.clone(),
                })
                .collect(),
            offset,
            tangent: [pt.iter().map(|c| subst_u(c, &ua, &ub, 1)).collect(), gn],
            reparam,
        })
    }

    /// For `z = c₀ + u c₁` (polynomial in `t`, linear in `u`) and a candidate ruling point
    /// `u* = a/b` (or `∞` if `inf`): if `|z(u*)|²` is a square, the stereographic
    /// parametrization of the conic `w² = |z(u)|²` from that point:
    /// `u = (2sw* − q₁ − u*q₂ − s²u*)/(q₂ − s²)`, `w = w* + s(u − u*)` (`q_i` the
    /// coefficients of `|z|² = q₀ + q₁u + q₂u²`); at infinity (`q₂ = w₁²`)
    /// `u = (q₀ − s²)/(2(w₁s) − q₁)`, `w = w₁u + s`. The new parameter `s` is variable 1.
    /// Returns `(a(t,s), b(t,s), M numerators, w)`.
    #[allow(clippy::type_complexity)]
    fn reparam_from(
        &self,
        z: &[MPoly<F>],
        a: &MPoly<F>,
        b: &MPoly<F>,
        inf: bool,
    ) -> Result<Option<(MPoly<F>, MPoly<F>, Vec<MPoly<F>>, MPoly<F>)>, PnError> {
        let qq = dot3(z, z);
        let coef = |j: u32| -> MPoly<F> {
            let mut out = MPoly::zero(2);
            for (e, c) in qq.terms() {
                if e.get(1).copied().unwrap_or(0) == j {
                    let mut f = e.to_vec();
                    f[1] = 0;
                    out = &out + &MPoly::monomial(2, &f, c.clone());
                }
            }
            out
        };
        let (q0, q1, q2) = (coef(0), coef(1), coef(2));
        let s = var::<F>(1);
        let two = F::from_i64(2);
        let (ua, ub) = if inf {
            let Some(w1) = univariate_sqrt(&q2) else {
                return Ok(None);
            };
            if w1.is_zero() {
                return Ok(None);
            }
            (
                &q0 - &(&s * &s),
                (&(&w1 * &s) - &q1.scale(&(F::one() / two.clone()))).scale(&two),
            )
        } else {
            // w*² = q₀b² + q₁ab + q₂a² (over b²)
            let val = &(&(&q0 * &(b * b)) + &(&q1 * &(a * b))) + &(&q2 * &(a * a));
            let Some(ws) = univariate_sqrt(&val) else {
                return Ok(None);
            };
            if ws.is_zero() {
                return Ok(None);
            }
            // u = (2s w*/b − q₁ − (a/b)(q₂ + s²))/(q₂ − s²) = (2s w* − q₁b − a(q₂ + s²))/(b(q₂ − s²))
            (
                &(&(&s * &ws).scale(&two) - &(&q1 * b)) - &(a * &(&q2 + &(&s * &s))),
                b * &(&q2 - &(&s * &s)),
            )
        };
        // M = z(u)/|z(u)|: with u = ua/ub, z(u) = (c₀ ub + c₁ ua)/ub and |z(u)|² = Q(ua, ub)/ub²
        let zn: Vec<MPoly<F>> = z.iter().map(|c| subst_u(c, &ua, &ub, 1)).collect();
        let nn = dot3(&zn, &zn);
        // nn is a square in Q[t, s] by construction: w = (ws·… ) — compute it as a bivariate
        // square root through the conic relation: |z(u)|·ub = w·ub with w = w* + s(u − u*)
        let w_num = if inf {
            let w1 = univariate_sqrt(&q2).unwrap_or_else(|| int(1));
            &(&w1 * &ua) + &(&s * &ub)
        } else {
            let val = &(&(&q0 * &(b * b)) + &(&q1 * &(a * b))) + &(&q2 * &(a * a));
            let ws = univariate_sqrt(&val).unwrap_or_else(|| int(1));
            // w = ws/b + s(ua/ub − a/b) = (ws·ub + s(ua·b − a·ub))/(b·ub)
            let num = &(&ws * &ub) + &(&s * &(&(&ua * b) - &(a * &ub)));
            match div_exact_opt(&num, b) {
                Some(q) => q,
                None => return Ok(None),
            }
        };
        // check |z(u)|² ≡ w_num² (both over ub²)
        if !(&nn - &(&w_num * &w_num)).is_zero() && F::EXACT {
            return Ok(None);
        }
        Ok(Some((ua, ub, zn, w_num)))
    }
}

fn div_exact_opt<F: Scalar>(p: &MPoly<F>, d: &MPoly<F>) -> Option<MPoly<F>> {
    super::poly::div_exact(p, d)
}

/// The offset hypersurface of a ruled 2-manifold at distance `d` (Theorem 5.2, (5.26)).
#[derive(Debug, Clone)]
pub struct RuledOffset<F> {
    manifold: RuledManifold<F>,
    distance: F,
    point: Vec<RatFn<F>>,
    unit_normal: Vec<RatFn<F>>,
    offset: Vec<RatFn<F>>,
    tangent: [Vec<MPoly<F>>; 2],
    reparam: Option<RatFn<F>>,
}

impl<F: Scalar> RuledOffset<F> {
    /// The offset hypersurface `y(t, s, v₁, …, v_{n−3})` (5.26).
    pub fn offset_map(&self) -> &[RatFn<F>] {
        &self.offset
    }

    /// The (reparametrized) manifold point `p(t, s)`.
    pub fn point(&self) -> &[RatFn<F>] {
        &self.point
    }

    /// The rational unit normal `M(t, s)`.
    pub fn unit_normal(&self) -> &[RatFn<F>] {
        &self.unit_normal
    }

    /// The reparametrization `u = u(t, s)` of the rulings, if one was needed (Step 2).
    pub fn reparametrization(&self) -> Option<&RatFn<F>> {
        self.reparam.as_ref()
    }

    /// The offset distance.
    pub fn distance(&self) -> &F {
        &self.distance
    }

    /// The manifold.
    pub fn manifold(&self) -> &RuledManifold<F> {
        &self.manifold
    }

    /// The offset point at parameters `(t, s, v…)`; `None` where a denominator vanishes.
    pub fn eval(&self, x: &[F]) -> Option<Vec<F>> {
        self.offset.iter().map(|f| f.eval(x)).collect()
    }
}

impl<F: Scalar> Certified for RuledOffset<F> {
    /// `|M|² ≡ 1`, `M ⟂ τ(p)`, `|y − p|² ≡ d²` and `y − p ⟂ τ(p)` ((5.18), (5.19)) as
    /// identities of rational functions in all parameters.
    fn certify(&self) -> Vec<Certificate> {
        let n = self.point.len();
        let sq = |v: &[RatFn<F>]| {
            v.iter()
                .fold(RatFn::constant(F::zero()), |acc, x| acc.add(&x.mul(x)))
        };
        let dotv = |v: &[RatFn<F>], w: &[MPoly<F>]| {
            v.iter()
                .zip(w)
                .fold(RatFn::constant(F::zero()), |acc, (x, y)| {
                    acc.add(&x.mul(&RatFn::poly(y.clone())))
                })
        };
        let mut out = Vec::new();
        let m2 = sq(&self.unit_normal).sub(&RatFn::constant(F::one()));
        out.push(zero_cert(
            "ruled manifold: |M|² ≡ 1 (rational unit normal, (5.25))",
            &m2.num,
            1e6 * mag(&m2.num),
        ));
        for (name, tv) in [("p_t", &self.tangent[0]), ("g", &self.tangent[1])] {
            let c = dotv(&self.unit_normal, tv);
            out.push(zero_cert(
                &format!("ruled manifold: M·{name} ≡ 0"),
                &c.num,
                1e6 * mag(&c.num),
            ));
        }
        let diff: Vec<RatFn<F>> = (0..n).map(|i| self.offset[i].sub(&self.point[i])).collect();
        let r = sq(&diff).sub(&RatFn::constant(
            self.distance.clone() * self.distance.clone(),
        ));
        out.push(zero_cert(
            &format!(
                "offset hypersurface: |y − p|² ≡ d² = {}",
                format_scalar(&(self.distance.clone() * self.distance.clone()))
            ),
            &r.num,
            1e6 * mag(&r.num),
        ));
        for (name, tv) in [("p_t", &self.tangent[0]), ("g", &self.tangent[1])] {
            let c = dotv(&diff, tv);
            out.push(zero_cert(
                &format!("offset hypersurface: (y − p)·{name} ≡ 0 (y in the normal space, (5.19))"),
                &c.num,
                1e6 * mag(&c.num),
            ));
        }
        out
    }
}
