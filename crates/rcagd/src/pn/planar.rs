//! The planar case: rational PH curves (PN curves of the plane) from the isotropic model of
//! the Laguerre plane, their exact offsets, polynomial PH curves from a PH preimage, and
//! surfaces of revolution with a PH profile (Peternell §3.4 for `n = 2`, §4.1–§4.3 in
//! dimension 2; Peternell §4.5 Cor. 4.3 for the surfaces of revolution).
//!
//! In the plane an oriented line is `e0 + n·x = 0`, `|n| = 1`; the isotropic model `I²`
//! is `Λ(e) = (n₁, e0)/(1 − n₂)` with inverse `Λ⁻¹(y) = (2y₂, 2y₁, y₁² − 1)/(y₁² + 1)`
//! ((3.11)/(3.13) with `n = 2`). A rational curve `y(t) = (A/C, G/D)` of `I²` is a
//! rational family of oriented lines with the rational unit normal
//! `n = (2AC, A² − C²)/(A² + C²)`; its envelope `e ∩ e'` is the rational PH curve
//! ```text
//! W = (A² + C²) a' D²,  X₁ = (A² − C²) C² g' − 2ACDG a',  X₂ = 2C² (GD a' − AC g'),
//! ```
//! `a' = A'C − AC'`, `g' = G'D − GD'` (derived here like the surface formula; for a graph
//! `A = t, C = D = 1`: `x = ((t² − 1)F' − 2tF, 2(F − tF'))/(t² + 1)`). Offsets:
//! `x + d n = (X + d K N)/W`, `K = a'D²`, i.e. `G/D ↦ G/D − (d/2)(y₁² + 1)`.
//!
//! A polynomial PH curve with preimage `(u, v)` has `r' = (u² − v², 2uv)`, speed
//! `σ = u² + v²`, unit normal `(−2uv, u² − v²)/σ` (the left normal) — the planar case of
//! [`crate::ph::PhCurve`] (Hopf form `α = u`, `β = v`, both real), with which
//! [`PnCurve::from_ph_preimage`] agrees (tests).

use super::poly::{
    abs_mpoly, cancel_common, identity_cert, identity_cert_within, int, normalize_content,
    pad_eval, var, RatFn,
};
use super::surface::PnSurface;
use super::PnError;
use crate::error::format_scalar;
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{bernstein, Certificate, Poly, Scalar};
use rcagd_geom::BezierCurve;

/// A rational plane curve with a rational unit normal (a rational PH curve): point
/// `(X₁, X₂)/W`, normal `(N₁, N₂)/N₀` with `N₁² + N₂² ≡ N₀²`, support `h` of the line
/// `h + n·x = 0`, cofactor `K = W/N₀`; polynomials in `t` (variable 0).
#[derive(Debug, Clone)]
pub struct PnCurve<F> {
    point: [MPoly<F>; 3],
    normal: [MPoly<F>; 3],
    support: RatFn<F>,
    cofactor: Option<MPoly<F>>,
    distance: F,
}

impl<F: Scalar> PnCurve<F> {
    fn assemble(
        point: [MPoly<F>; 3],
        normal: [MPoly<F>; 3],
        support: RatFn<F>,
        candidates: &[MPoly<F>],
    ) -> Result<Self, PnError> {
        let lhs = &(&normal[1] * &normal[1]) + &(&normal[2] * &normal[2]);
        let c = identity_cert("N₁² + N₂² ≡ N₀²", &lhs, &(&normal[0] * &normal[0]));
        if !c.holds {
            return Err(PnError::NotUnitNormal(c.residual.unwrap_or_default()));
        }
        if point[0].is_zero() || normal[0].is_zero() {
            return Err(PnError::InvalidInput(
                "zero weight or normal denominator".into(),
            ));
        }
        let mut nn = normal.to_vec();
        cancel_common(&mut nn, candidates);
        super::poly::cancel_gcd(&mut nn);
        normalize_content(&mut nn);
        let mut pp = point.to_vec();
        cancel_common(&mut pp, candidates);
        normalize_content(&mut pp);
        let normal = [nn[0].clone(), nn[1].clone(), nn[2].clone()];
        let mut point = [pp[0].clone(), pp[1].clone(), pp[2].clone()];
        let mut g = point
            .iter()
            .fold(MPoly::zero(2), |g, p| super::poly::gcd2(&g, p));
        if let Some(k) = super::poly::div_exact(&point[0], &normal[0]) {
            g = super::poly::gcd2(&g, &k);
        }
        if g.total_degree().unwrap_or(0) > 0 {
            if let Some(qs) = point
                .iter()
                .map(|p| super::poly::div_exact(p, &g))
                .collect::<Option<Vec<_>>>()
            {
                point = [qs[0].clone(), qs[1].clone(), qs[2].clone()];
                normalize_content(&mut point);
            }
        }
        let cofactor = super::poly::div_exact(&point[0], &normal[0]);
        Ok(PnCurve {
            point,
            normal,
            support,
            cofactor,
            distance: F::zero(),
        })
    }

    /// The PH curve of the isotropic curve `y(t) = (A/C, G/D)` (module docs).
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] for `C ≡ 0` or `D ≡ 0`; [`PnError::Developable`] if
    /// `A/C` is constant (all lines parallel: no envelope).
    pub fn from_isotropic(
        a: MPoly<F>,
        c: MPoly<F>,
        g: MPoly<F>,
        d: MPoly<F>,
    ) -> Result<Self, PnError> {
        if c.is_zero() || d.is_zero() {
            return Err(PnError::InvalidInput("C and D must be non-zero".into()));
        }
        let ap = &(&a.partial(0) * &c) - &(&a * &c.partial(0));
        if ap.is_zero() {
            return Err(PnError::Developable(
                "the normal is constant (A/C constant): parallel lines have no envelope".into(),
            ));
        }
        let gp = &(&g.partial(0) * &d) - &(&g * &d.partial(0));
        let (aa, cc) = (&a * &a, &c * &c);
        let n0 = &aa + &cc;
        let two = F::from_i64(2);
        let w = &(&n0 * &ap) * &(&d * &d);
        let x1 = &(&(&(&aa - &cc) * &cc) * &gp) - &(&(&(&a * &c) * &(&d * &g)) * &ap).scale(&two);
        let x2 = (&cc * &(&(&(&g * &d) * &ap) - &(&(&a * &c) * &gp))).scale(&two);
        let normal = [n0.clone(), (&a * &c).scale(&two), &aa - &cc];
        let support = RatFn {
            num: (&g * &cc).scale(&two),
            den: &d * &n0,
        };
        Self::assemble([w, x1, x2], normal, support, &[c, d, ap])
    }

    /// The PH curve of the graph `y₂ = F(t)` of `I²`:
    /// `x = ((t² − 1)F' − 2tF, 2(F − tF'))/(t² + 1)`, `n = (2t, t² − 1)/(t² + 1)`.
    ///
    /// # Errors
    /// As [`Self::from_isotropic`].
    pub fn from_graph(f: &RatFn<F>) -> Result<Self, PnError> {
        Self::from_isotropic(var(0), int(1), f.num.clone(), f.den.clone())
    }

    /// A rational curve with a given rational unit normal (validated: `N₁² + N₂² ≡ N₀²`;
    /// orthogonality is a certificate).
    ///
    /// # Errors
    /// [`PnError::NotUnitNormal`], [`PnError::InvalidInput`] for zero `W` or `N₀`.
    pub fn from_point_normal(point: [MPoly<F>; 3], normal: [MPoly<F>; 3]) -> Result<Self, PnError> {
        let nx = &(&normal[1] * &point[1]) + &(&normal[2] * &point[2]);
        let support = RatFn::new(-nx, &normal[0] * &point[0])?;
        Self::assemble(point, normal, support, &[])
    }

    /// The polynomial PH curve `r(t) = start + ∫₀ᵗ (u² − v², 2uv)` from the Bernstein
    /// coefficients of the preimage `u(t)`, `v(t)` on `[0, 1]`, with its unit normal
    /// `(−2uv, u² − v²)/(u² + v²)`.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] if `u`, `v` are empty, of different lengths, or both zero.
    pub fn from_ph_preimage(u: &[F], v: &[F], start: [F; 2]) -> Result<Self, PnError> {
        if u.is_empty() || u.len() != v.len() {
            return Err(PnError::InvalidInput(
                "the PH preimage needs u and v with the same number (≥ 1) of Bernstein coefficients".into(),
            ));
        }
        let up = bernstein::from_bernstein(u);
        let vp = bernstein::from_bernstein(v);
        if up.is_zero() && vp.is_zero() {
            return Err(PnError::InvalidInput("u ≡ v ≡ 0: zero hodograph".into()));
        }
        let hx = &(&up * &up) - &(&vp * &vp);
        let hy = (&up * &vp).scale(&F::from_i64(2));
        let integ = |p: &Poly<F>, c: &F| -> MPoly<F> {
            let mut coeffs = vec![c.clone()];
            for (k, a) in p.coeffs().iter().enumerate() {
                coeffs.push(a.clone() / F::from_i64(k as i64 + 1));
            }
            MPoly::from_poly(&Poly::new(coeffs), 2, 0)
        };
        let point = [int(1), integ(&hx, &start[0]), integ(&hy, &start[1])];
        let sigma = &(&up * &up) + &(&vp * &vp);
        let normal = [
            MPoly::from_poly(&sigma, 2, 0),
            MPoly::from_poly(&(-hy), 2, 0),
            MPoly::from_poly(&hx, 2, 0),
        ];
        Self::from_point_normal(point, normal)
    }

    /// `(W, X₁, X₂)`.
    pub fn point_polys(&self) -> &[MPoly<F>; 3] {
        &self.point
    }

    /// `(N₀, N₁, N₂)`.
    pub fn normal_polys(&self) -> &[MPoly<F>; 3] {
        &self.normal
    }

    /// The cofactor `K = W/N₀`, when `N₀` divides `W`.
    pub fn cofactor(&self) -> Option<&MPoly<F>> {
        self.cofactor.as_ref()
    }

    /// The support function `h` (line `h + n·x = 0`).
    pub fn support(&self) -> &RatFn<F> {
        &self.support
    }

    /// The degree of the point representation in `t`.
    pub fn degree(&self) -> usize {
        self.point
            .iter()
            .map(|p| p.degree_in(0).unwrap_or(0) as usize)
            .max()
            .unwrap_or(0)
    }

    /// The isotropic image `y(t) = (n₁, e0)/(1 − n₂)` as rational functions.
    pub fn isotropic_image(&self) -> [RatFn<F>; 2] {
        let den = &self.normal[0] - &self.normal[2];
        [
            RatFn {
                num: self.normal[1].clone(),
                den: den.clone(),
            },
            RatFn {
                num: &self.support.num * &self.normal[0],
                den: &self.support.den * &den,
            },
        ]
    }

    /// The point `x(t)`.
    ///
    /// # Errors
    /// [`PnError::Singular`] where `W(t) = 0`.
    pub fn eval(&self, t: &F) -> Result<[F; 2], PnError> {
        let x = [t.clone(), F::zero()];
        let h: Vec<F> = self
            .point
            .iter()
            .map(|p| pad_eval(p, &x).unwrap_or_else(F::zero))
            .collect();
        let inv = h[0].inv().ok_or_else(|| PnError::Singular {
            what: "W = 0 (point at infinity)".into(),
            at: format_scalar(t),
        })?;
        Ok([h[1].clone() * inv.clone(), h[2].clone() * inv])
    }

    /// The unit normal `n(t)`.
    ///
    /// # Errors
    /// [`PnError::Singular`] where `N₀(t) = 0`.
    pub fn normal_at(&self, t: &F) -> Result<[F; 2], PnError> {
        let x = [t.clone(), F::zero()];
        let h: Vec<F> = self
            .normal
            .iter()
            .map(|p| pad_eval(p, &x).unwrap_or_else(F::zero))
            .collect();
        let inv = h[0].inv().ok_or_else(|| PnError::Singular {
            what: "N₀ = 0".into(),
            at: format_scalar(t),
        })?;
        Ok([h[1].clone() * inv.clone(), h[2].clone() * inv])
    }

    /// The offset at distance `d`: `(X + dKN)/W`, support `h − d`.
    pub fn offset(&self, d: F) -> PnCurve<F> {
        let (point, cofactor) = match &self.cofactor {
            Some(k) => (
                [
                    self.point[0].clone(),
                    &self.point[1] + &(k * &self.normal[1]).scale(&d),
                    &self.point[2] + &(k * &self.normal[2]).scale(&d),
                ],
                Some(k.clone()),
            ),
            None => {
                let (w, n0) = (&self.point[0], &self.normal[0]);
                (
                    [
                        w * n0,
                        &(&self.point[1] * n0) + &(w * &self.normal[1]).scale(&d),
                        &(&self.point[2] * n0) + &(w * &self.normal[2]).scale(&d),
                    ],
                    Some(w.clone()),
                )
            }
        };
        PnCurve {
            point,
            normal: self.normal.clone(),
            support: self.support.sub(&RatFn::constant(d.clone())),
            cofactor,
            distance: self.distance.clone() + d,
        }
    }

    /// The same curve with the opposite orientation: normal `−n`, support `−h`; its offset
    /// at `d` is the offset of `self` at `−d` (docs/math/laguerre-pn.md#orientation).
    pub fn opposite(&self) -> PnCurve<F> {
        let n = &self.normal;
        PnCurve {
            point: self.point.clone(),
            normal: [n[0].clone(), -n[1].clone(), -n[2].clone()],
            support: RatFn {
                num: -self.support.num.clone(),
                den: self.support.den.clone(),
            },
            cofactor: self.cofactor.clone(),
            distance: -self.distance.clone(),
        }
    }

    /// The oriented distance to the base curve (0 unless an offset).
    pub fn distance(&self) -> &F {
        &self.distance
    }

    /// The rational Bézier curve on `[a, b]` (local parameter `[0, 1]`).
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] unless `a < b`; geometry-layer failures.
    pub fn curve(&self, a: &F, b: &F) -> Result<BezierCurve<F>, PnError> {
        if a >= b {
            return Err(PnError::InvalidInput("the interval needs a < b".into()));
        }
        let map = &MPoly::constant(2, a.clone()) + &var::<F>(0).scale(&(b.clone() - a.clone()));
        let polys: Vec<Poly<F>> = self
            .point
            .iter()
            .map(|p| {
                let q = super::poly::compose(p, &[map.clone(), var(1)]);
                let n = q.degree_in(0).unwrap_or(0) as usize;
                Poly::new((0..=n).map(|k| q.coeff(&[k as u32, 0])).collect())
            })
            .collect();
        let deg = polys.iter().filter_map(|p| p.degree()).max().unwrap_or(0);
        Ok(BezierCurve::from_coordinate_polys(&polys, deg)?)
    }

    /// Checks that the curve is defined and regular on `[a, b]`: `W ≠ 0` there and the
    /// tangential speed `λ = (X'W − XW')·(−N₂, N₁)` (with `x' = λ (−n₂, n₁)/(W² N₀)`, since
    /// `x' ⟂ n`) has no zero. For an offset at distance `d`, a zero of `λ` is a point where
    /// `d` equals the signed radius of curvature of the base curve (a cusp of the offset).
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] unless `a < b`; [`PnError::CurveSingular`] naming the
    /// parameter `t` where `W` or `λ` vanishes (or changes sign, or may vanish).
    pub fn check_regular(&self, a: &F, b: &F) -> Result<Certificate, PnError> {
        if a >= b {
            return Err(PnError::InvalidInput("the interval needs a < b".into()));
        }
        let dom = super::poly::Domain::new(a.clone(), b.clone(), F::zero(), F::one())?;
        let [w, x1, x2] = &self.point;
        let [_, n1, n2] = &self.normal;
        let check = |p: &MPoly<F>, what: String| -> Result<(), PnError> {
            use super::poly::Sign;
            let at = match super::poly::sign_on_domain(p, &dom, 256) {
                Sign::Positive | Sign::Negative => return Ok(()),
                Sign::ZeroAt(x) => format_scalar(&x[0]),
                Sign::Changes(x, y) => format!(
                    "a point between {} and {} (sign change)",
                    format_scalar(&x[0]),
                    format_scalar(&y[0])
                ),
                Sign::Undecided(x) => {
                    format!(
                        "near {} (possibly; undecided after subdivision)",
                        format_scalar(&x[0])
                    )
                }
            };
            Err(PnError::CurveSingular { what, at })
        };
        check(w, "W = 0 (point at infinity)".into())?;
        let wp = w.partial(0);
        let t1 = &(&x1.partial(0) * w) - &(x1 * &wp);
        let t2 = &(&x2.partial(0) * w) - &(x2 * &wp);
        let speed = &(n1 * &t2) - &(n2 * &t1);
        let what = if self.distance.is_zero() {
            "x' = 0 (singular point of the curve)".to_string()
        } else {
            format!(
                "the offset at distance {} has a cusp (x'_d = 0: the distance equals the radius of curvature of the base curve)",
                format_scalar(&self.distance)
            )
        };
        check(&speed, what)?;
        Ok(Certificate::holds(
            format!(
                "planar PH: W ≠ 0 and x' ≠ 0 on [{}, {}] (Bernstein signs)",
                format_scalar(a),
                format_scalar(b)
            ),
            F::EXACT,
        ))
    }

    /// The certificates of an offset of `base` at distance `d`: `x_d − x ≡ d n`, i.e.
    /// `(X_d W − X W_d)·N₀ ≡ d·W·W_d·N` componentwise (in `f64` each residual coefficient
    /// is compared with the magnitude of the terms that make it up,
    /// `(|X_d||W| + |X||W_d|)|N₀| + |d||W||W_d||N|`, not with the already cancelled
    /// sides).
    pub fn offset_certificates(&self, base: &PnCurve<F>) -> Vec<Certificate> {
        let d = self.distance.clone() - base.distance.clone();
        let (o, b, n) = (&self.point, &base.point, &base.normal);
        (1..3)
            .map(|i| {
                let lhs = &(&(&o[i] * &b[0]) - &(&b[i] * &o[0])) * &n[0];
                let rhs = (&(&b[0] * &o[0]) * &n[i]).scale(&d);
                within(
                    &format!(
                        "planar offset at distance {}: x_d − x ≡ d n (component {i})",
                        format_scalar(&d)
                    ),
                    &lhs,
                    &rhs,
                    || {
                        let a = |p: &MPoly<F>| abs_mpoly(p);
                        &(&(&(&a(&o[i]) * &a(&b[0])) + &(&a(&b[i]) * &a(&o[0]))) * &a(&n[0]))
                            + &(&(&a(&b[0]) * &a(&o[0])) * &a(&n[i])).scale(&d.to_f64().abs())
                    },
                )
            })
            .collect()
    }
}

impl<F: Scalar> Certified for PnCurve<F> {
    /// `N₁² + N₂² ≡ N₀²`, `W ≡ N₀K`, `n ⟂ x'`, `h + n·x ≡ 0`.
    fn certify(&self) -> Vec<Certificate> {
        let [w, x1, x2] = &self.point;
        let [n0, n1, n2] = &self.normal;
        // in f64 the product identities compare each residual coefficient with the
        // magnitude of its terms (`within`), so that cancellation in a side does not
        // shrink the tolerance
        let a = |p: &MPoly<F>| abs_mpoly(p);
        let mut out = vec![within(
            "planar PH: N₁² + N₂² ≡ N₀² (rational unit normal)",
            &(&(n1 * n1) + &(n2 * n2)),
            &(n0 * n0),
            || &(&(&a(n1) * &a(n1)) + &(&a(n2) * &a(n2))) + &(&a(n0) * &a(n0)),
        )];
        // K is a quotient (an f64 division accepts a remainder): the sides' scale
        if let Some(k) = &self.cofactor {
            out.push(identity_cert("planar PH: W ≡ N₀K", w, &(n0 * k)));
        }
        let wp = w.partial(0);
        let (x1p, x2p) = (x1.partial(0), x2.partial(0));
        let t1 = &(&x1p * w) - &(x1 * &wp);
        let t2 = &(&x2p * w) - &(x2 * &wp);
        out.push(within(
            "planar PH: n ⟂ x': N·(X'W − XW') ≡ 0",
            &(n1 * &t1),
            &(-(n2 * &t2)),
            || {
                let t = |xp: &MPoly<F>, x: &MPoly<F>| &(&a(xp) * &a(w)) + &(&a(x) * &a(&wp));
                &(&a(n1) * &t(&x1p, x1)) + &(&a(n2) * &t(&x2p, x2))
            },
        ));
        let lhs = &(&self.support.num * n0) * w;
        let rhs = -(&self.support.den * &(&(n1 * x1) + &(n2 * x2)));
        out.push(identity_cert(
            "planar PH: x on its line: h + n·x ≡ 0",
            &lhs,
            &rhs,
        ));
        out
    }
}

/// `lhs ≡ rhs`: exactly for exact scalars; in `f64` coefficientwise against the magnitude
/// polynomial `magnitude()` of the terms ([`identity_cert_within`]).
fn within<F: Scalar>(
    property: &str,
    lhs: &MPoly<F>,
    rhs: &MPoly<F>,
    magnitude: impl FnOnce() -> MPoly<f64>,
) -> Certificate {
    if F::EXACT {
        identity_cert(property, lhs, rhs)
    } else {
        identity_cert_within(property, lhs, rhs, &magnitude())
    }
}

/// The surface of revolution about the `x₃`-axis of a PH profile `(ρ(t), z(t))` in the
/// `(x₁, x₃)` half-plane: `x(t, s) = (ρ c(s), ρ s̃(s), z)`, `c = (1 − s²)/(1 + s²)`,
/// `s̃ = 2s/(1 + s²)`, with the unit normal `(n_ρ c, n_ρ s̃, n_z)` — a PN surface (a canal
/// surface with rational spine on the axis and rational radius, Cor. 4.3), whose offsets
/// are the surfaces of revolution of the profile's offsets.
///
/// # Errors
/// Only if the profile is degenerate ([`PnError::InvalidInput`]).
pub fn surface_of_revolution<F: Scalar>(profile: &PnCurve<F>) -> Result<PnSurface<F>, PnError> {
    let s = var::<F>(1);
    let s2 = &s * &s;
    let one_p = &int(1) + &s2;
    let one_m = &int(1) - &s2;
    let two_s = s.scale(&F::from_i64(2));
    let [w, r, z] = profile.point_polys().clone();
    let [n0, nr, nz] = profile.normal_polys().clone();
    let point = [&w * &one_p, &r * &one_m, &r * &two_s, &z * &one_p];
    let normal = [&n0 * &one_p, &nr * &one_m, &nr * &two_s, &nz * &one_p];
    let support = RatFn {
        num: profile.support().num.clone(),
        den: profile.support().den.clone(),
    };
    PnSurface::assemble(
        "surface of revolution of a PH profile",
        point,
        normal,
        support,
        None,
        &[one_p],
    )
}
