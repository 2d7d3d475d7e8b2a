//! Developable PN surfaces: the developable case of Theorem 4.3 (Peternell, "Rational
//! Parametrizations for Envelopes of Quadric Families", §4.3): a rational **curve**
//! `y(t)` of the isotropic model `I³` is a one-parameter family of oriented planes
//! `e(t) = Λ⁻¹(y(t)) = (2y₃, 2y₁, 2y₂, S − 1)/(S + 1)`, `S = y₁² + y₂²` ((3.13)), with the
//! rational unit normal `n(t) = (2y₁, 2y₂, S − 1)/(S + 1)`. Their envelope is a developable
//! surface, ruled by the lines `e(t) ∩ ė(t)`; it is a PN surface (the normal is constant
//! along each ruling) and its offsets `x + d n` (planes `e₀ ↦ e₀ − d`) are developable PN
//! surfaces again.
//!
//! **Parametrization** (docs/math/laguerre-pn.md#developable). With the planes written as
//! `P₀ + P·x = 0` (polynomials in `t`), `Q = P × Ṗ` is the direction of the ruling, and the
//! foot point `f` of the ruling (the point of `e ∩ ė` with `Q·f = 0`) is, by Cramer's rule,
//! `f = −(P₀ (Ṗ × Q) + Ṗ₀ (Q × P))/|Q|²`. The surface is `x(t, v) = f(t) + v Q(t)/|Q|²`
//! (the ruling parameter scaled by `1/|Q|² > 0`, so that point and foot point share the
//! denominator `|Q|²`).

use super::poly::{cross3, dot3, identity_cert, RatFn};
use super::surface::PnSurface;
use super::PnError;
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Scalar};

/// The developable PN surface enveloped by the planes `Λ⁻¹(y(t))` of a rational curve
/// `y(t)` of the isotropic model (Theorem 4.3, developable case), in the parameters
/// `(t, v)` (`v` along the rulings).
#[derive(Debug, Clone)]
pub struct DevelopablePn<F> {
    planes: [MPoly<F>; 4],
    surface: PnSurface<F>,
}

fn only_t<F: Scalar>(p: &MPoly<F>) -> bool {
    p.terms().all(|(e, _)| e.iter().skip(1).all(|&k| k == 0))
}

impl<F: Scalar> DevelopablePn<F> {
    /// The developable surface of the isotropic curve `y(t) = (y₁, y₂, y₃)(t)` (rational
    /// functions of `t`, the variable 0).
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] if a coordinate involves another variable;
    /// [`PnError::Developable`] if the planes do not form a proper one-parameter family
    /// (`(y₁, y₂)` constant: parallel planes, `P × Ṗ ≡ 0`).
    pub fn from_isotropic_curve(y: &[RatFn<F>; 3]) -> Result<Self, PnError> {
        if !y.iter().all(|f| only_t(&f.num) && only_t(&f.den)) {
            return Err(PnError::InvalidInput(
                "an isotropic curve must depend on the single parameter t (variable 0)".into(),
            ));
        }
        // y₁ = a/c, y₂ = b/c over one denominator; y₃ = g/δ
        let a = &y[0].num * &y[1].den;
        let b = &y[1].num * &y[0].den;
        let c = &y[0].den * &y[1].den;
        let (g, dl) = (&y[2].num, &y[2].den);
        let two = F::from_i64(2);
        let (aa, bb, cc) = (&a * &a, &b * &b, &c * &c);
        let normal = [
            &(&aa + &bb) + &cc,
            (&a * &c).scale(&two),
            (&b * &c).scale(&two),
            &(&aa + &bb) - &cc,
        ];
        // e₀ N₀ = 2 y₃ c² (from (3.13) multiplied by c²): planes P₀ + P·x = 0 times δ
        let planes = [
            (g * &cc).scale(&two),
            dl * &normal[1],
            dl * &normal[2],
            dl * &normal[3],
        ];
        let p = [planes[1].clone(), planes[2].clone(), planes[3].clone()];
        let pd: [MPoly<F>; 3] = std::array::from_fn(|i| p[i].partial(0));
        let p0d = planes[0].partial(0);
        let q = cross3(&p, &pd);
        if q.iter().all(|x| x.is_zero()) {
            return Err(PnError::Developable(
                "the planes Λ⁻¹(y(t)) are parallel or fixed (P × Ṗ ≡ 0): (y₁, y₂) must not be constant".into(),
            ));
        }
        let w = dot3(&q, &q);
        let pdq = cross3(&pd, &q);
        let qp = cross3(&q, &p);
        let v = MPoly::var(2, 1);
        let foot: [MPoly<F>; 3] =
            std::array::from_fn(|i| -(&(&planes[0] * &pdq[i]) + &(&p0d * &qp[i])));
        let point = [
            w.clone(),
            &foot[0] + &(&v * &q[0]),
            &foot[1] + &(&v * &q[1]),
            &foot[2] + &(&v * &q[2]),
        ];
        let surface = PnSurface::from_point_normal(point, normal)?
            .named("developable PN surface (Theorem 4.3, developable case)");
        Ok(DevelopablePn { planes, surface })
    }

    /// The PN surface in `(t, v)`.
    pub fn surface(&self) -> &PnSurface<F> {
        &self.surface
    }

    /// The tangent planes `P₀ + P·x = 0` as polynomials in `t` (`(P₀, P₁, P₂, P₃)`).
    pub fn planes(&self) -> &[MPoly<F>; 4] {
        &self.planes
    }

    /// The certificates that every point lies on the ruling `e(t) ∩ ė(t)`:
    /// `P₀W + P·X ≡ 0` and `Ṗ₀W + Ṗ·X ≡ 0`, and that the normal is constant along the
    /// rulings (`∂_v N ≡ 0`: the Gauss map is degenerate, the surface is developable).
    pub fn ruling_certificates(&self) -> Vec<Certificate> {
        let x = self.surface.point_polys();
        let on = |pl: [MPoly<F>; 4], what: &str| {
            let lhs = &pl[0] * &x[0];
            let rhs = -dot3(&pl[1..], &x[1..]);
            identity_cert(what, &lhs, &rhs)
        };
        let pd: [MPoly<F>; 4] = std::array::from_fn(|i| self.planes[i].partial(0));
        let n = self.surface.normal_polys();
        let mut out = vec![
            on(
                self.planes.clone(),
                "developable: x on its tangent plane e(t): P₀W + P·X ≡ 0",
            ),
            on(
                pd,
                "developable: x on the characteristic line e(t) ∩ ė(t): Ṗ₀W + Ṗ·X ≡ 0",
            ),
        ];
        for (k, ni) in n.iter().enumerate() {
            out.push(identity_cert(
                &format!("developable: the normal is constant along each ruling (∂_v N{k} ≡ 0)"),
                &ni.partial(1),
                &MPoly::zero(2),
            ));
        }
        out
    }
}

impl<F: Scalar> Certified for DevelopablePn<F> {
    /// The PN identities, every point on its ruling `e ∩ ė`, the normal constant along
    /// the rulings.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.surface.certify();
        out.extend(self.ruling_certificates());
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pn::poly::{int, var};
    use rcagd_algebra::Rational;

    type Q = Rational;

    fn q(a: i64, b: i64) -> Q {
        Q::from_ratio(a, b)
    }

    /// The twisted cubic `y = (t, t², t³/3)` of `I³` gives a certified developable PN
    /// surface; its offset at `d` is certified and lies in the planes of the isotropic
    /// offset curve `y₃ − (d/2)(S + 1)` (the offset rule of the isotropic model).
    #[test]
    fn cubic_isotropic_curve_gives_a_developable_pn_surface() {
        let t = var::<Q>(0);
        let y = [
            RatFn::poly(t.clone()),
            RatFn::poly(&t * &t),
            RatFn::poly((&(&t * &t) * &t).scale(&q(1, 3))),
        ];
        let dev = DevelopablePn::from_isotropic_curve(&y).expect("developable");
        assert!(dev.all_hold(), "{:?}", dev.certify());
        let off = dev.surface().offset(q(1, 2));
        assert!(off.all_hold());
        // the offset is developable with the planes e₀ − d: the same construction for
        // y₃ − (d/2)(S + 1) (the isotropic offset rule) gives the same points
        let s = &(&t * &t) + &(&(&t * &t) * &(&t * &t));
        let y_off = [
            y[0].clone(),
            y[1].clone(),
            RatFn::poly(&(&(&t * &t) * &t).scale(&q(1, 3)) - &(&s + &int(1)).scale(&q(1, 4))),
        ];
        let dev_off = DevelopablePn::from_isotropic_curve(&y_off).expect("developable");
        // both rulings lie in the same planes: every offset point is on dev_off's planes
        let x = off.surface().point_polys();
        let pl = dev_off.planes();
        let lhs = &pl[0] * &x[0];
        let rhs = -dot3(&pl[1..], &x[1..]);
        assert_eq!(lhs, rhs);
    }

    #[test]
    fn constant_spherical_image_is_rejected() {
        let t = var::<Q>(0);
        let y = [
            RatFn::constant(q(1, 2)),
            RatFn::constant(q(0, 1)),
            RatFn::poly(t),
        ];
        assert!(matches!(
            DevelopablePn::from_isotropic_curve(&y),
            Err(PnError::Developable(_))
        ));
    }
}
