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

use super::poly::{
    cancel_gcd, cross3, det3, div_exact, dot3, gcd2, identity_cert, int, normalize_content,
    pad_eval, RatFn,
};
use super::poly::{compose, mag, var, Domain};
use super::surface::{check_nonzero, PnSurface};
use super::PnError;
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::Poly;
use rcagd_algebra::{Certificate, Scalar};
use rcagd_geom::BezierCurve;

/// The developable PN surface enveloped by the planes `Λ⁻¹(y(t))` of a rational curve
/// `y(t)` of the isotropic model (Theorem 4.3, developable case), in the parameters
/// `(t, v)` (`v` along the rulings).
///
/// The point form is the **edge form** `x = r(t) + v Q(t)/D(t)` when the developable has
/// an edge of regression `r` (module docs, [`EdgeOfRegression`]): homogeneous
/// `(D, R + v Q)` with `Q = P × Ṗ` divided by its content in `t`. For a cylinder
/// (`D ≡ 0`) it is the foot-point form `x = f + v Q/(Q·Q')` (`Q'` the primitive part of
/// `Q`). The edge form has the lower degree: `(6, 1)` instead of `(11, 1)` for the twisted
/// cubic `y = (t, t², t³/3)` (docs/math/laguerre-pn.md#edge-of-regression).
#[derive(Debug, Clone)]
pub struct DevelopablePn<F> {
    planes: [MPoly<F>; 4],
    norm: MPoly<F>,
    surface: PnSurface<F>,
}

fn only_t<F: Scalar>(p: &MPoly<F>) -> bool {
    p.terms().all(|(e, _)| e.iter().skip(1).all(|&k| k == 0))
}

/// `det(P, Ṗ, P̈)` and the Cramer numerators `R = −(P₀ (Ṗ × P̈) + Ṗ₀ (P̈ × P) + P̈₀ (P × Ṗ))`
/// of the point `r = R/D` on the planes `P₀ + P·x = 0` and their first two derivatives.
fn cramer3<F: Scalar>(planes: &[MPoly<F>; 4]) -> (MPoly<F>, [MPoly<F>; 3]) {
    let p = [planes[1].clone(), planes[2].clone(), planes[3].clone()];
    let pd: [MPoly<F>; 3] = std::array::from_fn(|i| p[i].partial(0));
    let pdd: [MPoly<F>; 3] = std::array::from_fn(|i| pd[i].partial(0));
    let p0d = planes[0].partial(0);
    let p0dd = p0d.partial(0);
    let d = det3([&p, &pd, &pdd]);
    let a = cross3(&pd, &pdd);
    let b = cross3(&pdd, &p);
    let c = cross3(&p, &pd);
    let r =
        std::array::from_fn(|i| -(&(&(&planes[0] * &a[i]) + &(&p0d * &b[i])) + &(&p0dd * &c[i])));
    (d, r)
}

/// `p ≡ 0`, exactly for exact scalars; for `f64` relative to `scale` (the size of the
/// products that formed `p`), so that rounding noise of a cylinder's `D` or a cone's
/// `DṘ − ḊR` is recognised.
fn negligible<F: Scalar>(p: &MPoly<F>, scale: f64) -> bool {
    if F::EXACT {
        p.is_zero()
    } else {
        p.terms().map(|(_, c)| c.to_f64().abs()).fold(0.0, f64::max) <= 1e-10 * scale
    }
}

/// `mag(D)`-style size of the product `P, Ṗ, P̈` (the scale of `det(P, Ṗ, P̈)`).
fn det_scale<F: Scalar>(planes: &[MPoly<F>; 4]) -> f64 {
    let p = [planes[1].clone(), planes[2].clone(), planes[3].clone()];
    let m = |q: &[MPoly<F>; 3]| q.iter().map(mag).fold(0.0, f64::max);
    let pd: [MPoly<F>; 3] = std::array::from_fn(|i| p[i].partial(0));
    let pdd: [MPoly<F>; 3] = std::array::from_fn(|i| pd[i].partial(0));
    (m(&p) * m(&pd) * m(&pdd)).max(f64::MIN_POSITIVE)
}

/// The primitive part in `t` of a vector of polynomials (exact scalars; unchanged for
/// `f64`).
fn primitive3<F: Scalar>(q: &[MPoly<F>; 3]) -> [MPoly<F>; 3] {
    let mut v = q.to_vec();
    cancel_gcd(&mut v);
    normalize_content(&mut v);
    [v[0].clone(), v[1].clone(), v[2].clone()]
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
        // e₀ N₀ = 2 y₃ c² (from (3.13) multiplied by c²): planes P₀ + P·x = 0 times δ;
        // `norm` = δ N₀ is |P| with the sign of the orientation (n = P/norm)
        let mut pl = vec![
            (g * &cc).scale(&two),
            dl * &normal[1],
            dl * &normal[2],
            dl * &normal[3],
        ];
        let mut norm = dl * &normal[0];
        // cancel the common factor of the plane coordinates (it divides |P| too)
        let gp = pl.iter().fold(MPoly::zero(2), |acc, p| gcd2(&acc, p));
        if gp.total_degree().unwrap_or(0) > 0 {
            if let (Some(qs), Some(qn)) = (
                pl.iter()
                    .map(|p| div_exact(p, &gp))
                    .collect::<Option<Vec<_>>>(),
                div_exact(&norm, &gp),
            ) {
                pl = qs;
                norm = qn;
            }
        }
        pl.push(norm);
        normalize_content(&mut pl);
        let norm = pl.pop().unwrap_or_else(|| int(1));
        let planes = [pl[0].clone(), pl[1].clone(), pl[2].clone(), pl[3].clone()];
        let p = [planes[1].clone(), planes[2].clone(), planes[3].clone()];
        let pd: [MPoly<F>; 3] = std::array::from_fn(|i| p[i].partial(0));
        let q = cross3(&p, &pd);
        if q.iter().all(|x| x.is_zero()) {
            return Err(PnError::Developable(
                "the planes Λ⁻¹(y(t)) are parallel or fixed (P × Ṗ ≡ 0): (y₁, y₂) must not be constant".into(),
            ));
        }
        let qp = primitive3(&q);
        let (dd, r) = cramer3(&planes);
        let v = MPoly::var(2, 1);
        let point = if negligible(&dd, det_scale(&planes)) {
            Self::foot_point_form(&planes, &qp)
        } else {
            [
                dd,
                &r[0] + &(&v * &qp[0]),
                &r[1] + &(&v * &qp[1]),
                &r[2] + &(&v * &qp[2]),
            ]
        };
        let surface = PnSurface::from_point_normal(point, normal)?
            .named("developable PN surface (Theorem 4.3, developable case)");
        Ok(DevelopablePn {
            planes,
            norm,
            surface,
        })
    }

    /// The developable PN surface of the normalized plane coordinates (4.20)
    /// `(h, 2ac, 2bc, a² + b² − c²)/(a² + b² + c²)` (polynomials `a, b, c` in `t`, `h`
    /// rational): by (4.4) the isotropic curve `y = (a/c, b/c, h (a² + b² + c²)/(2c²))`.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] for `c ≡ 0`; as [`Self::from_isotropic_curve`].
    pub fn from_support(
        a: MPoly<F>,
        b: MPoly<F>,
        c: MPoly<F>,
        h: &RatFn<F>,
    ) -> Result<Self, PnError> {
        // the same isotropic image as a surface's support function: y = (A/C, B/C, G/D)
        let iso = super::IsotropicSurface::from_support(a, b, c, h)?;
        let [a, b, c, g, d] = iso.parts();
        let y = [
            RatFn::new(a.clone(), c.clone())?,
            RatFn::new(b.clone(), c.clone())?,
            RatFn::new(g.clone(), d.clone())?,
        ];
        Self::from_isotropic_curve(&y)
    }

    /// The foot-point form `x = f + v Q'/(Q·Q')`: `f` the point of the ruling `e ∩ ė` with
    /// `Q'·f = 0` (Cramer's rule, `det(P, Ṗ, Q') = Q·Q'`), `Q'` the primitive part of
    /// `Q = P × Ṗ`; homogeneous `(Q·Q', F + v Q')`.
    fn foot_point_form(planes: &[MPoly<F>; 4], qp: &[MPoly<F>; 3]) -> [MPoly<F>; 4] {
        let p = [planes[1].clone(), planes[2].clone(), planes[3].clone()];
        let pd: [MPoly<F>; 3] = std::array::from_fn(|i| p[i].partial(0));
        let p0d = planes[0].partial(0);
        let q = cross3(&p, &pd);
        let w = dot3(&q, qp);
        let pdq = cross3(&pd, qp);
        let qpp = cross3(qp, &p);
        let v = MPoly::var(2, 1);
        let foot: [MPoly<F>; 3] =
            std::array::from_fn(|i| -(&(&planes[0] * &pdq[i]) + &(&p0d * &qpp[i])));
        [
            w,
            &foot[0] + &(&v * &qp[0]),
            &foot[1] + &(&v * &qp[1]),
            &foot[2] + &(&v * &qp[2]),
        ]
    }

    /// The same surface in the foot-point form `x = f + v Q'/(Q·Q')` (also for developables
    /// with an edge of regression; for comparison of degrees: `(11, 1)` against the edge
    /// form's `(6, 1)` for the twisted cubic).
    ///
    /// # Errors
    /// As [`PnSurface::from_point_normal`] (not expected for a valid developable).
    pub fn foot_point_surface(&self) -> Result<PnSurface<F>, PnError> {
        let p = [
            self.planes[1].clone(),
            self.planes[2].clone(),
            self.planes[3].clone(),
        ];
        let pd: [MPoly<F>; 3] = std::array::from_fn(|i| p[i].partial(0));
        let qp = primitive3(&cross3(&p, &pd));
        let point = Self::foot_point_form(&self.planes, &qp);
        Ok(
            PnSurface::from_point_normal(point, self.surface.normal_polys().clone())?
                .named("developable PN surface, foot-point form"),
        )
    }

    /// The PN surface in `(t, v)`.
    pub fn surface(&self) -> &PnSurface<F> {
        &self.surface
    }

    /// The tangent planes `P₀ + P·x = 0` as polynomials in `t` (`(P₀, P₁, P₂, P₃)`, without
    /// a common polynomial factor).
    pub fn planes(&self) -> &[MPoly<F>; 4] {
        &self.planes
    }

    /// `s` with `|P| = ±s` and the oriented unit normal `n = P/s` (so `e₀ = P₀/s`).
    pub fn plane_norm(&self) -> &MPoly<F> {
        &self.norm
    }

    /// The edge of regression `r = e ∩ ė ∩ ë` ([`EdgeOfRegression`]).
    ///
    /// # Errors
    /// [`PnError::NoEdgeOfRegression`] for a cylinder (`det(P, Ṗ, P̈) ≡ 0`: all rulings
    /// parallel to one plane, the edge is at infinity) and for a cone (`r` constant: the
    /// vertex, named in the message).
    pub fn edge_of_regression(&self) -> Result<EdgeOfRegression<F>, PnError> {
        EdgeOfRegression::of_planes(&self.planes, &self.norm, F::zero())
    }

    /// The edge of regression of the offset at distance `d` (planes `e₀ ↦ e₀ − d`):
    /// `r_d = r + d n + d κ (n × ṅ)` with `κ = |ṅ|²/det(n, ṅ, n̈)`
    /// (docs/math/laguerre-pn.md#edge-of-regression). A cone has offsets with an edge of
    /// regression (on the sphere of radius `|d|` about the vertex).
    ///
    /// # Errors
    /// [`PnError::NoEdgeOfRegression`] for a cylinder, and for `d = 0` as
    /// [`Self::edge_of_regression`].
    pub fn offset_edge(&self, d: F) -> Result<EdgeOfRegression<F>, PnError> {
        EdgeOfRegression::of_planes(&self.planes, &self.norm, d)
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
        // the planes' orientation agrees with the surface normal: P·N₀ ≡ s N
        for k in 0..3 {
            out.push(identity_cert(
                &format!(
                    "developable: the plane normal P/s is the surface normal (P{} N₀ ≡ s N{})",
                    k + 1,
                    k + 1
                ),
                &(&self.planes[k + 1] * &n[0]),
                &(&self.norm * &n[k + 1]),
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

/// The edge of regression `r(t) = e ∩ ė ∩ ë` of a developable with tangent planes
/// `e(t): P₀ + P·x = 0` (or of its offset at distance `d`, planes `P₀ − d s`), as the
/// rational curve `r = R/D`, `D = det(P, Ṗ, P̈)`,
/// `R = −(P₀ (Ṗ × P̈) + Ṗ₀ (P̈ × P) + P̈₀ (P × Ṗ))` (Cramer's rule; Peternell §4.5 remark
/// before Cor. 4.3: a developable is parametrized through its edge of regression, whose
/// offsets are pipe surfaces; derivation of the offset edge in
/// docs/math/laguerre-pn.md#edge-of-regression).
#[derive(Debug, Clone)]
pub struct EdgeOfRegression<F> {
    planes: [MPoly<F>; 4],
    norm: MPoly<F>,
    distance: F,
    point: [MPoly<F>; 4],
}

impl<F: Scalar> EdgeOfRegression<F> {
    fn of_planes(planes: &[MPoly<F>; 4], norm: &MPoly<F>, d: F) -> Result<Self, PnError> {
        let mut pl = planes.clone();
        pl[0] = &pl[0] - &norm.scale(&d);
        let (dd, r) = cramer3(&pl);
        let scale = det_scale(&pl);
        if negligible(&dd, scale) {
            return Err(PnError::NoEdgeOfRegression(
                "a cylinder: det(P, Ṗ, P̈) ≡ 0 (the normals lie on a great circle, all rulings are parallel to one plane; the edge of regression is at infinity)".into(),
            ));
        }
        // r constant ⇔ D Ṙ − Ḋ R ≡ 0
        let ddd = dd.partial(0);
        if r.iter()
            .all(|ri| (&(&dd * &ri.partial(0)) - &(&ddd * ri)).is_zero())
        {
            let at = pad_eval(&dd, &[F::one()])
                .zip(pad_eval(&dd, &[F::zero()]))
                .map(|(a, b)| {
                    if a.is_zero() {
                        (F::zero(), b)
                    } else {
                        (F::one(), a)
                    }
                });
            let vertex = at
                .and_then(|(t0, w)| {
                    let inv = w.inv()?;
                    let c: Option<Vec<F>> = r
                        .iter()
                        .map(|ri| pad_eval(ri, std::slice::from_ref(&t0)).map(|x| x * inv.clone()))
                        .collect();
                    c
                })
                .map(|c| crate::error::format_point(&c))
                .unwrap_or_else(|| "(a fixed point)".into());
            return Err(PnError::NoEdgeOfRegression(format!(
                "a cone: e ∩ ė ∩ ë is the fixed vertex {vertex}, not a curve"
            )));
        }
        let mut point = vec![dd, r[0].clone(), r[1].clone(), r[2].clone()];
        cancel_gcd(&mut point);
        normalize_content(&mut point);
        Ok(EdgeOfRegression {
            planes: planes.clone(),
            norm: norm.clone(),
            distance: d,
            point: [
                point[0].clone(),
                point[1].clone(),
                point[2].clone(),
                point[3].clone(),
            ],
        })
    }

    /// The homogeneous curve `(D, R₁, R₂, R₃)(t)` (polynomials in the variable 0).
    pub fn point_polys(&self) -> &[MPoly<F>; 4] {
        &self.point
    }

    /// The offset distance `d` of the developable whose edge this is (0 for the base).
    pub fn distance(&self) -> &F {
        &self.distance
    }

    /// The degree in `t`.
    pub fn degree(&self) -> usize {
        self.point
            .iter()
            .map(|p| p.total_degree().unwrap_or(0))
            .max()
            .unwrap_or(0)
    }

    /// The point `r(t)` (`None` where `D(t) = 0`).
    pub fn eval(&self, t: &F) -> Option<[F; 3]> {
        let x = [t.clone()];
        let inv = pad_eval(&self.point[0], &x)?.inv()?;
        let e = |p: &MPoly<F>| pad_eval(p, &x).map(|v| v * inv.clone());
        Some([e(&self.point[1])?, e(&self.point[2])?, e(&self.point[3])?])
    }

    /// The rational Bézier curve of `r` on `[a, b]`.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] unless `a < b`; [`PnError::Singular`] if `D` vanishes on
    /// `[a, b]` (a point of `r` at infinity: the normals' curve has a geodesic inflection
    /// there), naming the parameter (as `(t, 0)`).
    pub fn curve(&self, a: &F, b: &F) -> Result<BezierCurve<F>, PnError> {
        if a >= b {
            return Err(PnError::InvalidInput("the interval needs a < b".into()));
        }
        let dom = Domain::new(a.clone(), b.clone(), F::zero(), F::one())?;
        check_nonzero(
            &self.point[0],
            &dom,
            "D = det(P, Ṗ, P̈) = 0: the edge of regression is at infinity",
        )?;
        let map = &MPoly::constant(2, a.clone()) + &var::<F>(0).scale(&(b.clone() - a.clone()));
        let polys: Vec<Poly<F>> = self
            .point
            .iter()
            .map(|p| {
                let q = compose(p, &[map.clone(), var(1)]);
                let n = q.degree_in(0).unwrap_or(0) as usize;
                Poly::new((0..=n).map(|k| q.coeff(&[k as u32, 0])).collect())
            })
            .collect();
        let deg = polys.iter().filter_map(|p| p.degree()).max().unwrap_or(0);
        Ok(BezierCurve::from_coordinate_polys(&polys, deg)?)
    }

    /// `κ = |ṅ|²/det(n, ṅ, n̈) = (|Ṗ|² − ṡ²) s/det(P, Ṗ, P̈)` of the offset rule
    /// `r_d = r + d n + d κ (n × ṅ)` (`n = P/s`; docs/math/laguerre-pn.md#edge-of-regression).
    pub fn kappa(&self) -> RatFn<F> {
        let [p, pd, _] = self.derivs();
        let sd = self.norm.partial(0);
        let num = &(&dot3(&pd, &pd) - &(&sd * &sd)) * &self.norm;
        let pdd: [MPoly<F>; 3] = std::array::from_fn(|i| pd[i].partial(0));
        RatFn {
            num,
            den: det3([&p, &pd, &pdd]),
        }
    }

    fn derivs(&self) -> [[MPoly<F>; 3]; 3] {
        let p = [
            self.planes[1].clone(),
            self.planes[2].clone(),
            self.planes[3].clone(),
        ];
        let pd: [MPoly<F>; 3] = std::array::from_fn(|i| p[i].partial(0));
        let q = cross3(&p, &pd);
        [p, pd, q]
    }

    /// The certificates: `r` lies on `e_d`, `ė_d` and `ë_d` (planes
    /// `(P₀ − d s) + P·x = 0` and their derivatives), identically in `t`; for `d ≠ 0` also
    /// the offset rule `r_d − r ≡ d (n + κ (n × ṅ))` with `r = R/D`, `r_d = X/W`, written
    /// over the denominators as `s (X D − R W) ≡ d W (D P + (|Ṗ|² − ṡ²) Q)`, `Q = P × Ṗ`
    /// (for a cone `R/D` is the vertex).
    pub fn certificates(&self) -> Vec<Certificate> {
        let mut pl = self.planes.clone();
        pl[0] = &pl[0] - &self.norm.scale(&self.distance);
        let x = &self.point;
        let mut out = Vec::new();
        let mut cur = pl;
        for (k, what) in ["e", "ė", "ë"].iter().enumerate() {
            if k > 0 {
                cur = std::array::from_fn(|i| cur[i].partial(0));
            }
            let lhs = &cur[0] * &x[0];
            let rhs = -dot3(&cur[1..], &x[1..]);
            out.push(identity_cert(
                &format!(
                    "edge of regression on {what}_d (d = {}): P₀W + P·X ≡ 0",
                    crate::error::format_scalar(&self.distance)
                ),
                &lhs,
                &rhs,
            ));
        }
        if !self.distance.is_zero() {
            // the base edge (the vertex, for a cone): r = R/D from the planes themselves
            let (w0, b) = cramer3(&self.planes);
            let [p, pd, q] = self.derivs();
            let sd = self.norm.partial(0);
            let coef = &dot3(&pd, &pd) - &(&sd * &sd);
            for i in 0..3 {
                // s (X_d W − X W_d) ≡ d W W_d (D P + coef Q)/D, with W = D (unreduced)
                let lhs = &(&(&x[i + 1] * &w0) - &(&b[i] * &x[0])) * &self.norm;
                let rhs = (&x[0] * &(&(&w0 * &p[i]) + &(&coef * &q[i]))).scale(&self.distance);
                out.push(identity_cert(
                    &format!(
                        "offset edge of regression r_d − r ≡ d (n + κ n × ṅ), component {}",
                        i + 1
                    ),
                    &lhs,
                    &rhs,
                ));
            }
        }
        out
    }
}

impl<F: Scalar> Certified for EdgeOfRegression<F> {
    fn certify(&self) -> Vec<Certificate> {
        self.certificates()
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

    fn curve(y: [MPoly<Q>; 3]) -> [RatFn<Q>; 3] {
        y.map(RatFn::poly)
    }

    fn cubic() -> [RatFn<Q>; 3] {
        let t = var::<Q>(0);
        curve([t.clone(), &t * &t, (&(&t * &t) * &t).scale(&q(1, 3))])
    }

    /// The edge form of the twisted cubic's developable has bidegree (6, 1), the
    /// foot-point form (11, 1); both are certified, with the same normal.
    #[test]
    fn edge_form_reduces_the_degree() {
        let dev = DevelopablePn::from_isotropic_curve(&cubic()).expect("developable");
        assert!(dev.all_hold(), "{:?}", dev.certify());
        assert_eq!(dev.surface().degree(), (6, 1));
        let foot = dev.foot_point_surface().expect("foot form");
        assert!(foot.all_hold());
        assert_eq!(foot.degree(), (11, 1));
        assert_eq!(foot.normal_polys(), dev.surface().normal_polys());
        // v = 0 is the edge of regression
        let edge = dev.edge_of_regression().expect("edge");
        let t0 = q(2, 3);
        let e = edge.eval(&t0).expect("defined");
        assert_eq!(dev.surface().eval(&t0, &q(0, 1)).expect("point"), e);
    }

    /// The edge of regression lies on e, ė, ë; the offset edges at ±d lie on the offset
    /// planes and follow r_d = r + d n + d κ (n × ṅ) (not r + d n).
    #[test]
    fn edge_of_regression_and_its_offsets() {
        let dev = DevelopablePn::from_isotropic_curve(&cubic()).expect("developable");
        let edge = dev.edge_of_regression().expect("edge");
        assert!(edge.all_hold(), "{:?}", edge.certify());
        assert_eq!(edge.degree(), 6);
        for d in [q(1, 2), q(-3, 1)] {
            let off = dev.offset_edge(d.clone()).expect("offset edge");
            assert!(off.all_hold(), "{:?}", off.certify());
            // r_d ≠ r + d n at a sample point: the κ-term is not zero
            let t0 = q(3, 4);
            let (r, rd) = (edge.eval(&t0).expect("r"), off.eval(&t0).expect("r_d"));
            let n = dev.surface().normal_at(&t0, &q(0, 1)).expect("n");
            assert!((0..3).any(|i| rd[i].clone() - r[i].clone() != d.clone() * n[i].clone()));
            // and it is the point of the offset surface on the offset's ruling: the offset
            // edge lies on the offset developable (its planes are e₀ − d)
            let y_off = {
                let t = var::<Q>(0);
                let s = &(&t * &t) + &(&(&t * &t) * &(&t * &t));
                curve([
                    t.clone(),
                    &t * &t,
                    &(&(&t * &t) * &t).scale(&q(1, 3))
                        - &(&s + &int(1)).scale(&(d.clone() / q(2, 1))),
                ])
            };
            let dev_off = DevelopablePn::from_isotropic_curve(&y_off).expect("offset dev");
            let e2 = dev_off.edge_of_regression().expect("edge of the offset");
            assert_eq!(e2.eval(&t0), off.eval(&t0));
        }
    }

    #[test]
    fn cylinders_and_cones_have_no_edge_of_regression() {
        let t = var::<Q>(0);
        // y₂ = 0: the normals (2t, 0, t² − 1)/(t² + 1) run on a great circle: a cylinder
        let cyl = DevelopablePn::from_isotropic_curve(&curve([t.clone(), MPoly::zero(2), &t * &t]))
            .expect("cylinder");
        assert!(cyl.all_hold(), "{:?}", cyl.certify());
        assert!(matches!(
            cyl.edge_of_regression(),
            Err(PnError::NoEdgeOfRegression(m)) if m.contains("cylinder")
        ));
        // y = (t, t², t²): all planes pass through one point: a cone
        let cone = DevelopablePn::from_isotropic_curve(&curve([t.clone(), &t * &t, &t * &t]))
            .expect("cone");
        assert!(cone.all_hold(), "{:?}", cone.certify());
        assert!(matches!(
            cone.edge_of_regression(),
            Err(PnError::NoEdgeOfRegression(m)) if m.contains("cone")
        ));
        // the same in f64 (rounding noise of D and of DṘ − ḊR is recognised)
        let f = |y: [MPoly<Q>; 3]| y.map(|p| RatFn::poly(p.map(Scalar::to_f64)));
        let cyl_f = DevelopablePn::from_isotropic_curve(&f([t.clone(), MPoly::zero(2), &t * &t]))
            .expect("f64 cylinder");
        assert!(cyl_f.all_hold(), "{:?}", cyl_f.certify());
        assert!(matches!(
            cyl_f.edge_of_regression(),
            Err(PnError::NoEdgeOfRegression(m)) if m.contains("cylinder")
        ));
        let cone_f = DevelopablePn::from_isotropic_curve(&f([t.clone(), &t * &t, &t * &t]))
            .expect("f64 cone");
        assert!(matches!(
            cone_f.edge_of_regression(),
            Err(PnError::NoEdgeOfRegression(m)) if m.contains("cone")
        ));
        // the cone's offsets are not cones: their edge lies on the sphere |x − v| = |d|
        let off = cone
            .offset_edge(q(1, 1))
            .expect("offset of a cone has an edge");
        assert!(off.all_hold(), "{:?}", off.certify());
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
