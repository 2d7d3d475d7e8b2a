//! PN surfaces from the isotropic model `I³` (Peternell §4.3, Theorems 4.3/4.4, (4.4), §4.4;
//! docs/math/laguerre-pn.md).
//!
//! A point `y` of `I³` is the oriented plane `Λ⁻¹(y) = (2y₃, 2y₁, 2y₂, S − 1)/(S + 1)`
//! (3.13), `S = y₁² + y₂²`. A rational surface `y(u, v)` of `I³` is therefore a rational
//! two-parameter family of oriented planes with the rational unit normal
//! `n = (2y₁, 2y₂, S − 1)/(S + 1)`; its envelope is a PN surface (Theorem 4.3), and every
//! PN surface arises this way.
//!
//! **Closed formula.** For a graph `y₃ = F(u, v)` (docs/math/laguerre-pn.md):
//! ```text
//! x₁ = ((u² − v² − 1) F_u + 2uv F_v − 2u F)/(S + 1)
//! x₂ = ((v² − u² − 1) F_v + 2uv F_u − 2v F)/(S + 1)
//! x₃ = 2 (F − u F_u − v F_v)/(S + 1),        n = (2u, 2v, S − 1)/(S + 1).
//! ```
//! The point depends only on the tangent plane of the isotropic surface (first-order
//! contact), so for a parametrized surface `y = (A/C, B/C, G/D)` it is the same formula
//! with the slopes `−m₁/m₃`, `−m₂/m₃` of its normal `m = y_u × y_v`. With
//! `a_s = A_sC − AC_s`, `b_s = B_sC − BC_s`, `g_s = G_sD − GD_s` (`s = u, v`),
//! `J = det(P, P_u, P_v)` for `P = (A, B, C)`, `N₀ = A² + B² + C²`:
//! ```text
//! μ₁ = C (b_u g_v − b_v g_u),  μ₂ = C (g_u a_v − g_v a_u),  μ₃ = D² J,
//! τ  = A (b_u g_v − b_v g_u) + B (g_u a_v − g_v a_u) + D G J,
//! x  = [N₀ (μ₁, μ₂, 0) − 2Cτ (A, B, −C)] / (N₀ μ₃),   n = (2AC, 2BC, A² + B² − C²)/N₀
//! ```
//! (derived here and checked with sympy; the graph case `A = u, B = v, C = D = 1` is
//! the closed formula of Theorem 4.3/4.4, docs/math/laguerre-pn.md#closed-formula). The weight is
//! `W = N₀ μ₃`, so the cofactor of the offsets is `K = μ₃ = D²J`. `J ≡ 0` means the spherical image
//! `(A/C, B/C)` is a curve: the planes envelope a developable surface and have no point
//! representation of this kind.
//!
//! The offset at distance `d` is `y₃ ↦ y₃ − (d/2)(S + 1)` (Peternell (3.15) corrected,
//! docs/math/laguerre-pn.md#conventions) — for a graph `F ↦ F − (d/2)(u² + v² + 1)`
//! ([`IsotropicSurface::offset`]).

use super::poly::{cancel_common, det3, int, normalize_content, var, RatFn};
use super::surface::PnSurface;
use super::PnError;
use crate::laguerre::Cycle;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::Scalar;

/// A rational surface `y(u, v) = (A/C, B/C, G/D)` of the isotropic model `I³`
/// (polynomials `A, B, C, G, D` in `(u, v)`, `C, D ≢ 0`).
#[derive(Debug, Clone)]
pub struct IsotropicSurface<F> {
    a: MPoly<F>,
    b: MPoly<F>,
    c: MPoly<F>,
    g: MPoly<F>,
    d: MPoly<F>,
    name: String,
}

impl<F: Scalar> IsotropicSurface<F> {
    /// The isotropic surface `y = (A/C, B/C, G/D)`.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] if `C` or `D` is the zero polynomial.
    pub fn new(
        a: MPoly<F>,
        b: MPoly<F>,
        c: MPoly<F>,
        g: MPoly<F>,
        d: MPoly<F>,
    ) -> Result<Self, PnError> {
        if c.is_zero() || d.is_zero() {
            return Err(PnError::InvalidInput(
                "the denominators C and D of an isotropic surface must be non-zero polynomials"
                    .into(),
            ));
        }
        Ok(IsotropicSurface {
            a,
            b,
            c,
            g,
            d,
            name: "isotropic surface".into(),
        })
    }

    /// The graph `y₃ = F(u, v)` (Theorem 4.4: the PN surfaces with a quadratic spherical
    /// representation).
    pub fn graph(f: &RatFn<F>) -> Self {
        IsotropicSurface {
            a: var(0),
            b: var(1),
            c: int(1),
            g: f.num.clone(),
            d: f.den.clone(),
            name: "graph".into(),
        }
    }

    /// The graph of a polynomial `F(u, v)`.
    pub fn graph_poly(f: MPoly<F>) -> Self {
        Self::graph(&RatFn::poly(f))
    }

    /// The dual PN form (4.1) `e = (g, 2acf, 2bcf, (a² + b² − c²) f)` in the isotropic model,
    /// (4.4): `y = (a/c, b/c, g/(2c²f))`.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] if `c` or `f` is zero.
    pub fn from_dual(
        a: MPoly<F>,
        b: MPoly<F>,
        c: MPoly<F>,
        g: MPoly<F>,
        f: MPoly<F>,
    ) -> Result<Self, PnError> {
        let d = &(&c * &c) * &f.scale(&F::from_i64(2));
        let mut s = Self::new(a, b, c, g, d)?;
        s.name = "dual PN form (4.1)".into();
        Ok(s)
    }

    /// The normalized dual form (4.2) `e = (h, 2ac, 2bc, a² + b² − c²)/(a² + b² + c²)` with
    /// support function `h` (plane `h + n·x = 0`): `y = (a/c, b/c, h(a² + b² + c²)/(2c²))`.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] if `c` is zero.
    pub fn from_support(
        a: MPoly<F>,
        b: MPoly<F>,
        c: MPoly<F>,
        h: &RatFn<F>,
    ) -> Result<Self, PnError> {
        let n0 = &(&(&a * &a) + &(&b * &b)) + &(&c * &c);
        let g = &h.num * &n0;
        let d = &(&c * &c) * &h.den.scale(&F::from_i64(2));
        let mut s = Self::new(a, b, c, g, d)?;
        s.name = "support function (4.2)".into();
        Ok(s)
    }

    /// The graph of the isotropic sphere of a cycle (Lemma 3.1 (3.12)):
    /// `F = −[(r + m₃)S + 2m₁u + 2m₂v + r − m₃]/2`; its PN surface is the sphere itself,
    /// `x = m + r n` (docs/math/laguerre-pn.md).
    pub fn from_cycle(cycle: &Cycle<F>) -> Self {
        let sph = cycle.isotropic_sphere();
        let (u, v) = (var::<F>(0), var::<F>(1));
        let s = &(&u * &u) + &(&v * &v);
        let f = &(&(&s.scale(&sph.alpha) + &u.scale(&sph.beta[0])) + &v.scale(&sph.beta[1]))
            + &MPoly::constant(2, sph.gamma.clone());
        let mut g = Self::graph_poly(f);
        g.name = "isotropic sphere of a cycle".into();
        g
    }

    /// The parabolic Dupin cyclide `F = αu² + βv²` (Peternell §4.4; `α ≠ β`; for `α = β` it is an
    /// isotropic sphere, i.e. a sphere). Its dual form is
    /// `(2(αu² + βv²), 2u, 2v, S − 1)/(S + 1)` (the factor 2 is missing in print;
    /// docs/math/laguerre-pn.md).
    pub fn parabolic_dupin_cyclide(alpha: F, beta: F) -> Self {
        let (u, v) = (var::<F>(0), var::<F>(1));
        let f = &(&u * &u).scale(&alpha) + &(&v * &v).scale(&beta);
        let mut g = Self::graph_poly(f);
        g.name = "parabolic Dupin cyclide".into();
        g
    }

    /// The graph `F = p·S/(S − 1)` (docs/math/laguerre-pn.md): its PN surface is the paraboloid of
    /// revolution `x₃ = (x₁² + x₂²)/(2p)` (checked in the tests), with rational offsets.
    pub fn paraboloid(p: F) -> Self {
        let (u, v) = (var::<F>(0), var::<F>(1));
        let s = &(&u * &u) + &(&v * &v);
        let f = RatFn {
            num: s.scale(&p),
            den: &s - &int(1),
        };
        let mut g = Self::graph(&f);
        g.name = "paraboloid".into();
        g
    }

    /// A copy with another name.
    pub fn named(mut self, name: impl Into<String>) -> Self {
        self.name = name.into();
        self
    }

    /// The polynomials `(A, B, C, G, D)`.
    pub fn parts(&self) -> [&MPoly<F>; 5] {
        [&self.a, &self.b, &self.c, &self.g, &self.d]
    }

    /// The isotropic point `y(u, v)` (`None` where `C` or `D` vanishes).
    pub fn eval(&self, u: &F, v: &F) -> Option<[F; 3]> {
        let x = [u.clone(), v.clone()];
        let e = |p: &MPoly<F>| super::poly::pad_eval(p, &x);
        let ci = e(&self.c)?.inv()?;
        let di = e(&self.d)?.inv()?;
        Some([e(&self.a)? * ci.clone(), e(&self.b)? * ci, e(&self.g)? * di])
    }

    /// The offset in the isotropic model: `y₃ ↦ y₃ − (d/2)(S + 1)` (Peternell (3.15) corrected,
    /// docs/math/laguerre-pn.md#conventions), i.e. `G/D ↦ (2C²G − d·D·N₀)/(2C²D)`; for a graph
    /// `F ↦ F − (d/2)(u² + v² + 1)`.
    pub fn offset(&self, dist: &F) -> Self {
        let n0 = &(&(&self.a * &self.a) + &(&self.b * &self.b)) + &(&self.c * &self.c);
        let c2 = &self.c * &self.c;
        let mut g = &(&c2 * &self.g).scale(&F::from_i64(2)) - &(&self.d * &n0).scale(dist);
        let mut d = (&c2 * &self.d).scale(&F::from_i64(2));
        let mut pair = vec![g, d];
        cancel_common(&mut pair, &[self.c.clone(), self.d.clone()]);
        normalize_content(&mut pair);
        d = pair.pop().unwrap_or_else(|| int(1));
        g = pair.pop().unwrap_or_else(|| MPoly::zero(2));
        IsotropicSurface {
            a: self.a.clone(),
            b: self.b.clone(),
            c: self.c.clone(),
            g,
            d,
            name: format!("{} (isotropic offset)", self.name),
        }
    }

    /// The PN surface `Λ⁻¹(y)` by the closed formula (module docs).
    ///
    /// A curve `y(t)` of `I³` (all of `A, B, C, G, D` in the variable 0 only) gives its
    /// developable PN surface in `(t, v)` instead ([`super::developable::DevelopablePn`]).
    ///
    /// # Errors
    /// [`PnError::Developable`] if `J ≡ 0` (degenerate spherical image) and `y` is not a
    /// curve in `t` with a proper one-parameter family of planes.
    pub fn to_pn_surface(&self) -> Result<PnSurface<F>, PnError> {
        self.to_pn_surface_with(&[])
    }

    /// As [`Self::to_pn_surface`], trying the extra candidate common factors too.
    pub(crate) fn to_pn_surface_with(&self, extra: &[MPoly<F>]) -> Result<PnSurface<F>, PnError> {
        let (a, b, c, g, d) = (&self.a, &self.b, &self.c, &self.g, &self.d);
        let p = |x: &MPoly<F>| [x.partial(0), x.partial(1)];
        let [au, av] = p(a);
        let [bu, bv] = p(b);
        let [cu, cv] = p(c);
        let [gu, gv] = p(g);
        let [du, dv] = p(d);
        let jac = det3([
            &[a.clone(), b.clone(), c.clone()],
            &[au.clone(), bu.clone(), cu.clone()],
            &[av.clone(), bv.clone(), cv.clone()],
        ]);
        if jac.is_zero() {
            let only_t = |p: &MPoly<F>| p.terms().all(|(e, _)| e.iter().skip(1).all(|&k| k == 0));
            if [a, b, c, g, d].into_iter().all(only_t) {
                // a curve y(t) of I³: the developable PN surface (Theorem 4.3, developable
                // case), parametrized by t and the ruling parameter v
                let y = [
                    RatFn::new(a.clone(), c.clone())?,
                    RatFn::new(b.clone(), c.clone())?,
                    RatFn::new(g.clone(), d.clone())?,
                ];
                return Ok(super::developable::DevelopablePn::from_isotropic_curve(&y)?
                    .surface()
                    .clone());
            }
            return Err(PnError::Developable(format!(
                "{}: the spherical image (A/C, B/C) has Jacobian J = det(P, P_u, P_v) ≡ 0",
                self.name
            )));
        }
        let hom = |xs: &MPoly<F>, x: &MPoly<F>, den_s: &MPoly<F>, den: &MPoly<F>| {
            &(xs * den) - &(x * den_s)
        };
        let a_u = hom(&au, a, &cu, c);
        let a_v = hom(&av, a, &cv, c);
        let b_u = hom(&bu, b, &cu, c);
        let b_v = hom(&bv, b, &cv, c);
        let g_u = hom(&gu, g, &du, d);
        let g_v = hom(&gv, g, &dv, d);
        let bg = &(&b_u * &g_v) - &(&b_v * &g_u);
        let ga = &(&g_u * &a_v) - &(&g_v * &a_u);
        let mu1 = c * &bg;
        let mu2 = c * &ga;
        let mu3 = &(d * d) * &jac;
        let tau = &(&(a * &bg) + &(b * &ga)) + &(&(d * g) * &jac);
        let aa = a * a;
        let bb = b * b;
        let cc = c * c;
        let n0 = &(&aa + &bb) + &cc;
        let two = F::from_i64(2);
        let ctau2 = (c * &tau).scale(&two);
        let w = &n0 * &mu3;
        let x1 = &(&n0 * &mu1) - &(&ctau2 * a);
        let x2 = &(&n0 * &mu2) - &(&ctau2 * b);
        let x3 = &ctau2 * c;
        let normal = [
            n0.clone(),
            (a * c).scale(&two),
            (b * c).scale(&two),
            &(&aa + &bb) - &cc,
        ];
        let support = RatFn {
            num: (g * &cc).scale(&two),
            den: d * &n0,
        };
        let mut candidates = vec![jac.clone(), c.clone(), d.clone()];
        candidates.extend(extra.iter().cloned());
        PnSurface::assemble(
            format!("Λ⁻¹({})", self.name),
            [w, x1, x2, x3],
            normal,
            support,
            Some(mu3),
            &candidates,
        )
    }
}

impl<F: Scalar> PartialEq for IsotropicSurface<F> {
    fn eq(&self, other: &Self) -> bool {
        self.a == other.a
            && self.b == other.b
            && self.c == other.c
            && self.g == other.g
            && self.d == other.d
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Certified;
    use rcagd_algebra::Rational;

    type Q = Rational;
    fn q(p: i64, d: i64) -> Q {
        Q::from_ratio(p, d)
    }

    #[test]
    fn graph_closed_formula_matches_a42() {
        // F = u³/3 − u v + v²/2 + 1
        let (u, v) = (var::<Q>(0), var::<Q>(1));
        let f = &(&(&(&(&u * &u) * &u).scale(&q(1, 3)) - &(&u * &v)) + &(&v * &v).scale(&q(1, 2)))
            + &int(1);
        let s = IsotropicSurface::graph_poly(f.clone())
            .to_pn_surface()
            .expect("pn");
        assert!(s.all_hold(), "{:?}", s.certify());
        // compare with the closed formula of Theorem 4.3/4.4 at a point
        let (uu, vv) = (q(1, 2), q(-2, 3));
        let x = s.eval(&uu, &vv).expect("point");
        let fe = |p: &MPoly<Q>| p.eval(&[uu.clone(), vv.clone()]).expect("2 vars");
        let (ff, fu, fv) = (fe(&f), fe(&f.partial(0)), fe(&f.partial(1)));
        let ss = uu.clone() * uu.clone() + vv.clone() * vv.clone() + q(1, 1);
        let x1 = ((uu.clone() * uu.clone() - vv.clone() * vv.clone() - q(1, 1)) * fu.clone()
            + q(2, 1) * uu.clone() * vv.clone() * fv.clone()
            - q(2, 1) * uu.clone() * ff.clone())
            / ss.clone();
        let x3 = q(2, 1) * (ff - uu.clone() * fu - vv.clone() * fv) / ss;
        assert_eq!(x[0], x1);
        assert_eq!(x[2], x3);
    }

    #[test]
    fn developable_is_an_error() {
        // spherical image a curve: A = u, B = u, C = 1
        let u = var::<Q>(0);
        let iso =
            IsotropicSurface::new(u.clone(), u.clone(), int(1), var(1), int(1)).expect("valid");
        assert!(matches!(iso.to_pn_surface(), Err(PnError::Developable(_))));
        // a curve y(u) = (u, u², u³) of I³: the developable PN surface
        let curve = IsotropicSurface::new(u.clone(), &u * &u, int(1), &(&u * &u) * &u, int(1))
            .expect("valid");
        let dev = curve.to_pn_surface().expect("developable PN surface");
        assert!(dev.all_hold(), "{:?}", dev.certify());
        assert!(dev.normal_polys().iter().all(|n| n.partial(1).is_zero()));
        // a constant spherical image stays an error
        let flat = IsotropicSurface::new(int(1), int(0), int(1), u.clone(), int(1)).expect("valid");
        assert!(matches!(flat.to_pn_surface(), Err(PnError::Developable(_))));
        assert!(IsotropicSurface::new(u.clone(), u, MPoly::zero(2), int(1), int(1)).is_err());
    }
}
