//! The Dupin cyclide as the cyclographic image of a pe conic, with the rational
//! biquadratic parametrization by the contact points of its two families of enveloped
//! spheres (docs/math/cyclides.md#biquadratic).

use super::conic::{CycleCurve, PeConic};
use super::implicit::implicit_on;
use super::pe::{negligible, pe, size};
use super::CyclideError;
use crate::canal::bipoly::{patch_of, BiPoly};
use crate::Certified;
use rcagd_algebra::{format_scalar, Certificate, Poly, Rational, Scalar};
use rcagd_geom::certify::polynomial_is_zero_scaled;
use rcagd_geom::BezierPatch;

/// The type of a Dupin cyclide (docs/math/cyclides.md#types).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CyclideKind {
    /// No singular point: `ρ²k² < r₀² < ρ²(1 + k²)` with `k² = u₄² + v₄²` (the torus with
    /// `|r₀| < ρ` is the case `k = 0`).
    Ring,
    /// Singular points of horn type: point spheres in the first family
    /// (`r₀² ≤ ρ²k²`) or the double point sphere of the second (`r₀² = ρ²(1 + k²)`, the
    /// horn torus).
    Horn,
    /// Point spheres of the second family, `r₀² > ρ²(1 + k²)` (the spindle torus for
    /// `k = 0`).
    Spindle,
    /// The cubic cyclide of a pe parabola (Prop. 3.2).
    Parabolic,
}

impl CyclideKind {
    /// `"ring"`, `"horn"`, `"spindle"` or `"parabolic"`.
    pub fn name(self) -> &'static str {
        match self {
            CyclideKind::Ring => "ring",
            CyclideKind::Horn => "horn",
            CyclideKind::Spindle => "spindle",
            CyclideKind::Parabolic => "parabolic",
        }
    }
}

/// A Dupin cyclide: the cyclographic image of a pe conic `C` of `R^{3,1}` (Peternell,
/// "Rational Parametrizations for Envelopes of Quadric Families", Lemma 3.4, Prop. 3.1,
/// 3.2), equally the image of the conjugate conic `D` (the second family of enveloped
/// spheres).
///
/// With the cycles `C(t) = (M_C; R_C)/W_C` and `D(s) = (M_D; R_D)/W_D` (both quadratic),
/// each pair is in oriented contact, and the contact point and the common unit normal are
/// (docs/math/cyclides.md#biquadratic)
///
/// ```text
/// x(t, s) = (R_C M_D − R_D M_C) / (R_C W_D − R_D W_C),
/// n(t, s) = (W_C M_D − W_D M_C) / (R_C W_D − R_D W_C),
/// ```
///
/// a rational parametrization of bidegree `(2, 2)` with a rational unit normal, and
/// `x = m_C + r_C n = m_D + r_D n` (Peternell §3.8: contact point `x = m + r n` of a
/// cycle and an oriented plane, (3.3)).
#[derive(Debug, Clone, PartialEq)]
pub struct DupinCyclide<F> {
    conic: PeConic<F>,
    first: CycleCurve<F>,
    second: CycleCurve<F>,
    /// `(X₀, X₁, X₂, X₃)`, `t` inside the coefficients, `s` the outer variable.
    x: [BiPoly<F>; 4],
    /// Numerators of the unit normal over `X₀`.
    normal: [BiPoly<F>; 3],
}

fn bt<F: Scalar>(p: &Poly<F>) -> BiPoly<F> {
    BiPoly::from_t(p.clone())
}
fn bs<F: Scalar>(p: &Poly<F>) -> BiPoly<F> {
    BiPoly::from_u(p)
}

impl<F: Scalar> DupinCyclide<F> {
    /// The cyclographic image of the pe circle `C₀ + ρ(cos θ U + sin θ V)`, `C₀ = (c, r₀)`.
    ///
    /// # Errors
    /// As [`PeConic::circle`] and [`PeConic::conjugate`].
    pub fn from_pe_circle(
        center: [F; 4],
        u: [F; 4],
        v: [F; 4],
        rho: F,
    ) -> Result<Self, CyclideError> {
        Self::from_conic(PeConic::circle(center, u, v, rho)?)
    }

    /// The cyclide of the tilted pe circle with `U = (1, 0, 0, 0)`,
    /// `V = (0, a, 0, b)`, `a = (1 + s²)/(1 − s²)`, `b = 2s/(1 − s²)` (so `a² − b² = 1`),
    /// centre `(c, r₀)`: spine `c + (ρ cos θ, ρ a sin θ, 0)`, radius `r₀ + ρ b sin θ`
    /// (Peternell §3.8.1; `s = 1/3` is the printed example `V = (0, 5/4, 0, 3/4)`, `s = 0`
    /// a torus).
    ///
    /// # Errors
    /// [`CyclideError::IsotropicTangents`] for `|s| ≥ 1`; otherwise as
    /// [`DupinCyclide::from_pe_circle`].
    pub fn tilted(center: [F; 3], rho: F, r0: F, s: F) -> Result<Self, CyclideError> {
        let one = F::one();
        let den = one.clone() - s.clone() * s.clone();
        if den <= F::zero() {
            return Err(CyclideError::IsotropicTangents(format!(
                "the tilt must satisfy |s| < 1, got s = {} (|s| = 1 gives isotropic tangents)",
                format_scalar(&s)
            )));
        }
        let a = (one.clone() + s.clone() * s.clone()) / den.clone();
        let b = F::from_i64(2) * s / den;
        let [c1, c2, c3] = center;
        let z = F::zero();
        Self::from_pe_circle(
            [c1, c2, c3, r0],
            [one, z.clone(), z.clone(), z.clone()],
            [z.clone(), a, z, b],
            rho,
        )
    }

    /// The parabolic cyclide of the pe parabola `C₀ + tU + (t²/2)N`.
    ///
    /// # Errors
    /// As [`PeConic::parabola`] and [`PeConic::conjugate`].
    pub fn from_pe_parabola(vertex: [F; 4], u: [F; 4], n: [F; 4]) -> Result<Self, CyclideError> {
        Self::from_conic(PeConic::parabola(vertex, u, n)?)
    }

    /// The cyclide of a validated pe conic.
    ///
    /// # Errors
    /// As [`PeConic::conjugate`].
    pub fn from_conic(conic: PeConic<F>) -> Result<Self, CyclideError> {
        Self::from_conic_along(conic, &mut super::Route::free())
    }

    /// [`DupinCyclide::from_conic`] with the decisions of `route` for the conjugate conic
    /// ([`PeConic::conjugate_along`]).
    ///
    /// # Errors
    /// As [`PeConic::conjugate_along`].
    pub fn from_conic_along(
        conic: PeConic<F>,
        route: &mut super::Route,
    ) -> Result<Self, CyclideError> {
        let first = conic.curve();
        let second = conic.conjugate_along(route)?;
        Ok(Self::from_families(conic, first, second))
    }

    /// The cyclide of an exact cyclide's pe conic and two families of spheres, each
    /// coefficient rounded once to `F`; the surface `x`, its normal and everything built
    /// on them (patches, certificates) are then computed in `F`.
    ///
    /// Why (for `F = f64`): the conjugate conic's parametrization is ill-conditioned when
    /// the Gram matrix of `span(U, V)^⊥` in its kernel basis nearly cancels
    /// (`g₁₂² − g₁₁g₂₂ ≪ g₁₂²`, docs/math/cyclides.md#two-families): formed in `f64` it
    /// loses the digits of that ratio (measured: `g₁₂²/(g₁₂² − g₁₁g₂₂) = 3158` and a second
    /// family off by 3.0e-13 relative for the integer spheres of centres (2, 3, 2),
    /// (1, −3, 1), (2, 2, −1) and radii −3, −1, 0), and formed exactly from the rounded
    /// input its square roots need not exist (a square over `ℚ` is no square after
    /// rounding). Rounding the exact families once leaves an error of a few units of the
    /// last place in each coefficient.
    pub fn rounded(exact: &DupinCyclide<Rational>) -> Self {
        Self::from_families(
            PeConic::rounded(&exact.conic),
            CycleCurve::rounded(&exact.first),
            CycleCurve::rounded(&exact.second),
        )
    }

    fn from_families(conic: PeConic<F>, first: CycleCurve<F>, second: CycleCurve<F>) -> Self {
        let (wc, rc) = (bt(&first.w), bt(&first.p[3]));
        let (wd, rd) = (bs(&second.w), bs(&second.p[3]));
        let x0 = rc.mul(&wd).sub(&rd.mul(&wc));
        let xi = |i: usize| rc.mul(&bs(&second.p[i])).sub(&rd.mul(&bt(&first.p[i])));
        let ni = |i: usize| wc.mul(&bs(&second.p[i])).sub(&wd.mul(&bt(&first.p[i])));
        let x = [x0, xi(0), xi(1), xi(2)];
        let normal = [ni(0), ni(1), ni(2)];
        DupinCyclide {
            conic,
            first,
            second,
            x,
            normal,
        }
    }

    /// The pe conic `C`.
    pub fn conic(&self) -> &PeConic<F> {
        &self.conic
    }

    /// The first family of enveloped spheres, `C(t)`.
    pub fn first_family(&self) -> &CycleCurve<F> {
        &self.first
    }

    /// The second family, the conjugate conic `D(s)`.
    pub fn second_family(&self) -> &CycleCurve<F> {
        &self.second
    }

    /// Homogeneous coordinates `(X₀, X₁, X₂, X₃)` of `x(t, s)` (bidegree `(2, 2)`).
    pub fn homogeneous(&self) -> &[BiPoly<F>; 4] {
        &self.x
    }

    /// Numerators of the unit normal `n = (N₁, N₂, N₃)/X₀`.
    pub fn normal_numerators(&self) -> &[BiPoly<F>; 3] {
        &self.normal
    }

    /// The type (ring, horn, spindle, parabolic), decided exactly for exact scalars.
    pub fn kind(&self) -> CyclideKind {
        match &self.conic {
            PeConic::Parabola { .. } => CyclideKind::Parabolic,
            PeConic::Circle {
                center,
                u,
                v,
                rho,
                ratio,
            } => {
                let r0 = center[3].clone();
                let r02 = r0.clone() * r0;
                let rr = rho.clone() * rho.clone();
                let k2 = u[3].clone() * u[3].clone() + v[3].clone() * v[3].clone() / ratio.clone();
                let lo = rr.clone() * k2.clone();
                let hi = rr * (pe(u, u) + k2);
                let sc = size(&[r02.clone(), hi.clone()]).max(1.0);
                if negligible(&(r02.clone() - hi.clone()), sc) || r02 <= lo {
                    CyclideKind::Horn
                } else if r02 < hi {
                    CyclideKind::Ring
                } else {
                    CyclideKind::Spindle
                }
            }
        }
    }

    /// The offset at distance `d`: every cycle `(m; r)` of both families becomes
    /// `(m; r + d)`, and `x_d = x + d n` with the same normal (Peternell §3.2; the sign
    /// convention `r → r + d` gives `x + d n`, docs/math/cyclides.md#offsets).
    ///
    /// # Errors
    /// As [`PeConic::circle`] (e.g. the offset of a torus at `d = −r₀` degenerates).
    pub fn offset(&self, d: &F) -> Result<Self, CyclideError> {
        let conic = match &self.conic {
            PeConic::Circle {
                center,
                u,
                v,
                rho,
                ratio,
            } => {
                let mut c = center.clone();
                c[3] = c[3].clone() + d.clone();
                // norms in the ratio k suffice (the pe-unit and the scaled form alike)
                PeConic::circle_full(c, u.clone(), v.clone(), rho.clone(), ratio.clone(), false)?
            }
            PeConic::Parabola { vertex, u, n } => {
                let mut c = vertex.clone();
                c[3] = c[3].clone() + d.clone();
                PeConic::parabola_checked(c, u.clone(), n.clone(), false)?
            }
        };
        Ok(Self::from_families(
            conic,
            self.first.radius_shifted(d),
            self.second.radius_shifted(d),
        ))
    }

    /// The point `x(t, s)`, or `None` at a point at infinity (`X₀ = 0`; only the
    /// parabolic cyclide has real ones).
    pub fn eval(&self, t: &F, s: &F) -> Option<[F; 3]> {
        let w = self.x[0].eval(t, s);
        if w.is_zero() {
            return None;
        }
        Some(core::array::from_fn(|i| {
            self.x[i + 1].eval(t, s) / w.clone()
        }))
    }

    /// The unit normal `n(t, s)`, or `None` where `X₀ = 0`.
    pub fn normal(&self, t: &F, s: &F) -> Option<[F; 3]> {
        let w = self.x[0].eval(t, s);
        if w.is_zero() {
            return None;
        }
        Some(core::array::from_fn(|i| {
            self.normal[i].eval(t, s) / w.clone()
        }))
    }

    /// The value of the implicit equation (quartic, or cubic for the parabolic cyclide;
    /// [`super::implicit`]) at a point.
    pub fn implicit_value(&self, p: &[F; 3]) -> F {
        let h = [F::one(), p[0].clone(), p[1].clone(), p[2].clone()];
        super::implicit::implicit_at(&self.conic, &h)
    }

    /// The biquadratic patch on `[t₀, t₁] × [s₀, s₁]`, its weights made positive at the
    /// centre (the homogeneous coordinates negated if needed).
    ///
    /// # Errors
    /// [`CyclideError::InvalidArgument`] for an empty interval or a geometry failure.
    pub fn patch(&self, t: (&F, &F), s: (&F, &F)) -> Result<BezierPatch<F>, CyclideError> {
        patch_from(&self.x, t, s)
    }

    /// Biquadratic patches over the `t`-interval `[t₀, t₁]` (with `reversed_t`: over
    /// `τ ∈ [t₀, t₁]`, `t = 1/τ`) and every `s` (four pieces in `s`, as in
    /// [`DupinCyclide::covering_patches`]): a band of the cyclide between two of its
    /// circles of the first family.
    ///
    /// # Errors
    /// As [`DupinCyclide::patch`].
    pub fn band_patches(
        &self,
        reversed_t: bool,
        t0: &F,
        t1: &F,
    ) -> Result<Vec<BezierPatch<F>>, CyclideError> {
        let xt: [BiPoly<F>; 4] = if reversed_t {
            core::array::from_fn(|i| reverse_t(&self.x[i]))
        } else {
            self.x.clone()
        };
        let rev_s: [BiPoly<F>; 4] = core::array::from_fn(|i| xt[i].reverse_u(2));
        let (m1, z, one) = (-F::one(), F::zero(), F::one());
        let mut out = Vec::with_capacity(4);
        for xs in [&xt, &rev_s] {
            for (c, d) in [(&m1, &z), (&z, &one)] {
                out.push(patch_from(xs, (t0, t1), (c, d))?);
            }
        }
        Ok(out)
    }

    /// Sixteen biquadratic patches covering the whole real cyclide of a pe circle (ring,
    /// horn, spindle): `t` and `s` each over `[−1, 0]`, `[0, 1]` and, with `t = 1/τ`
    /// (`s = 1/σ`), `τ ∈ [−1, 0]`, `[0, 1]`. The weight `X₀` has no real zero there
    /// (docs/math/cyclides.md#compact), so the patches are free of poles and close up
    /// into a closed surface.
    ///
    /// # Errors
    /// [`CyclideError::InvalidArgument`] for the parabolic cyclide (unbounded: use
    /// [`DupinCyclide::patch`] on a parameter box).
    pub fn covering_patches(&self) -> Result<Vec<BezierPatch<F>>, CyclideError> {
        if self.conic.is_parabola() {
            return Err(CyclideError::InvalidArgument(
                "the parabolic cyclide is unbounded: choose a parameter box (patch)".into(),
            ));
        }
        let rev_t: [BiPoly<F>; 4] = core::array::from_fn(|i| reverse_t(&self.x[i]));
        let (m1, z, one) = (-F::one(), F::zero(), F::one());
        let mut out = Vec::with_capacity(16);
        for xt in [&self.x, &rev_t] {
            let rev_s: [BiPoly<F>; 4] = core::array::from_fn(|i| xt[i].reverse_u(2));
            for xs in [xt, &rev_s] {
                for (a, b) in [(&m1, &z), (&z, &one)] {
                    for (c, d) in [(&m1, &z), (&z, &one)] {
                        out.push(patch_from(xs, (a, b), (c, d))?);
                    }
                }
            }
        }
        Ok(out)
    }
}

fn reverse_t<F: Scalar>(p: &BiPoly<F>) -> BiPoly<F> {
    BiPoly::new(
        p.coeffs()
            .iter()
            .map(|c| {
                let mut v = c.coeffs().to_vec();
                v.resize(3, F::zero());
                v.reverse();
                Poly::new(v)
            })
            .collect(),
    )
}

fn patch_from<F: Scalar>(
    x: &[BiPoly<F>; 4],
    t: (&F, &F),
    s: (&F, &F),
) -> Result<BezierPatch<F>, CyclideError> {
    if t.0 >= t.1 || s.0 >= s.1 {
        return Err(CyclideError::InvalidArgument(format!(
            "empty parameter box [{}, {}] × [{}, {}]",
            format_scalar(t.0),
            format_scalar(t.1),
            format_scalar(s.0),
            format_scalar(s.1)
        )));
    }
    let two = F::from_i64(2);
    let (tm, sm) = (
        (t.0.clone() + t.1.clone()) / two.clone(),
        (s.0.clone() + s.1.clone()) / two,
    );
    let neg = x[0].eval(&tm, &sm) < F::zero();
    let comps: Vec<BiPoly<F>> = x
        .iter()
        .map(|c| if neg { c.neg() } else { c.clone() })
        .collect();
    patch_of(&comps, t, s).map_err(|e| CyclideError::InvalidArgument(e.to_string()))
}

/// `(W X − X₀ M) · (M′W − M W′) + X₀ R (R′W − R W′)` for the cycle curve in one variable
/// (`in_t`: the first family, else the second): the contact condition
/// `(x − m)·ṁ + r ṙ = 0` times `X₀ W³` (Peternell (2.14)).
fn contact<F: Scalar>(x: &[BiPoly<F>; 4], c: &CycleCurve<F>, in_t: bool) -> BiPoly<F> {
    let lift = |p: &Poly<F>| if in_t { bt(p) } else { bs(p) };
    let (w, dw) = (lift(&c.w), lift(&c.w.derivative()));
    let mut acc = BiPoly::zero();
    for i in 0..3 {
        let m = lift(&c.p[i]);
        let dm = lift(&c.p[i].derivative());
        let a = w.mul(&x[i + 1]).sub(&x[0].mul(&m));
        let b = dm.mul(&w).sub(&m.mul(&dw));
        acc = acc.add(&a.mul(&b));
    }
    let r = lift(&c.p[3]);
    let dr = lift(&c.p[3].derivative());
    acc.add(&x[0].mul(&r).mul(&dr.mul(&w).sub(&r.mul(&dw))))
}

/// `|W X − X₀ M|² − X₀² R²`: `x` on the sphere of the cycle.
fn on_sphere<F: Scalar>(x: &[BiPoly<F>; 4], c: &CycleCurve<F>, in_t: bool) -> BiPoly<F> {
    let lift = |p: &Poly<F>| if in_t { bt(p) } else { bs(p) };
    let w = lift(&c.w);
    let mut acc = BiPoly::zero();
    for i in 0..3 {
        let a = w.mul(&x[i + 1]).sub(&x[0].mul(&lift(&c.p[i])));
        acc = acc.add(&a.mul(&a));
    }
    let r = x[0].mul(&lift(&c.p[3]));
    acc.sub(&r.mul(&r))
}

/// `W X − X₀ M − R N`: `x = m + r n`.
fn point_from_normal<F: Scalar>(
    x: &[BiPoly<F>; 4],
    n: &[BiPoly<F>; 3],
    c: &CycleCurve<F>,
    in_t: bool,
) -> Vec<F> {
    let lift = |p: &Poly<F>| if in_t { bt(p) } else { bs(p) };
    let (w, r) = (lift(&c.w), lift(&c.p[3]));
    let mut all = Vec::new();
    for i in 0..3 {
        let e = w
            .mul(&x[i + 1])
            .sub(&x[0].mul(&lift(&c.p[i])))
            .sub(&r.mul(&n[i]));
        all.extend(e.all_coeffs());
    }
    all
}

/// The largest coefficient size of the parametrization (the `f64` tolerance scale).
fn scale_of<F: Scalar>(x: &[BiPoly<F>]) -> f64 {
    let m = x
        .iter()
        .flat_map(|p| p.all_coeffs())
        .map(|c| c.to_f64().abs())
        .fold(0.0, f64::max);
    m.max(1.0)
}

impl<F: Scalar> Certified for DupinCyclide<F> {
    /// Exact identities in `(t, s)`: the canal property for both families (on each
    /// sphere and the contact condition (2.14)), `n·n ≡ 1`, `n ⟂ x_t, x_s`,
    /// `x = m + r n` for both families, the implicit equation, and the pe-circle
    /// conditions of the input.
    fn certify(&self) -> Vec<Certificate> {
        let sc = scale_of(&self.x).max(scale_of(&self.normal));
        let sc4 = sc.powi(4);
        let mut out = Vec::new();
        for (name, fam, in_t) in [("C(t)", &self.first, true), ("D(s)", &self.second, false)] {
            out.push(polynomial_is_zero_scaled(
                &format!(
                    "|x − m|² − r² ≡ 0 for the spheres of {name} (x on every sphere of the family)"
                ),
                &on_sphere(&self.x, fam, in_t).all_coeffs(),
                sc4,
            ));
            out.push(polynomial_is_zero_scaled(
                &format!("(x − m)·ṁ + r ṙ ≡ 0 for {name} (contact condition, Peternell (2.14): the cyclide envelops the family)"),
                &contact(&self.x, fam, in_t).all_coeffs(),
                sc4,
            ));
            out.push(polynomial_is_zero_scaled(
                &format!("x − m − r n ≡ 0 for {name} (contact point x = m + r n, Peternell (3.3))"),
                &point_from_normal(&self.x, &self.normal, fam, in_t),
                sc * sc,
            ));
        }
        let n = &self.normal;
        let nn = n[0]
            .mul(&n[0])
            .add(&n[1].mul(&n[1]))
            .add(&n[2].mul(&n[2]))
            .sub(&self.x[0].mul(&self.x[0]));
        out.push(polynomial_is_zero_scaled(
            "N₁² + N₂² + N₃² − X₀² ≡ 0 (n·n ≡ 1: a rational unit normal)",
            &nn.all_coeffs(),
            sc * sc,
        ));
        for (name, dx) in [
            (
                "x_t",
                self.x.iter().map(BiPoly::partial_t).collect::<Vec<_>>(),
            ),
            (
                "x_s",
                self.x.iter().map(BiPoly::partial_u).collect::<Vec<_>>(),
            ),
        ] {
            // n · (X₀ X_i' − X₀' X_i)
            let mut acc = BiPoly::zero();
            for i in 0..3 {
                let d = self.x[0].mul(&dx[i + 1]).sub(&dx[0].mul(&self.x[i + 1]));
                acc = acc.add(&n[i].mul(&d));
            }
            out.push(polynomial_is_zero_scaled(
                &format!("n · {name} ≡ 0 (n is normal to the surface)"),
                &acc.all_coeffs(),
                sc.powi(3),
            ));
        }
        let (label, deg) = if self.conic.is_parabola() {
            ("cubic", 3)
        } else {
            ("quartic", 4)
        };
        out.push(polynomial_is_zero_scaled(
            &format!("F(x(t, s)) ≡ 0 for the {label} implicit equation F of the cyclide"),
            &implicit_on(&self.conic, &self.x).all_coeffs(),
            sc.powi(deg) * size(&conic_data(&self.conic)).max(1.0).powi(2 * deg),
        ));
        out.extend(self.conic_certificates());
        out
    }
}

fn conic_data<F: Scalar>(c: &PeConic<F>) -> Vec<F> {
    match c {
        PeConic::Circle {
            center,
            u,
            v,
            rho,
            ratio,
        } => center
            .iter()
            .chain(u.iter())
            .chain(v.iter())
            .chain([rho, ratio])
            .cloned()
            .collect(),
        PeConic::Parabola { vertex, u, n } => vertex
            .iter()
            .chain(u.iter())
            .chain(n.iter())
            .cloned()
            .collect(),
    }
}

impl<F: Scalar> DupinCyclide<F> {
    fn conic_certificates(&self) -> Vec<Certificate> {
        let ex = F::EXACT;
        let cert = |prop: &str, x: F, want: F, sc: f64| {
            let r = x - want;
            Certificate::decide(prop, negligible(&r, sc), ex, || format_scalar(&r))
        };
        match &self.conic {
            PeConic::Circle { u, v, ratio, .. } => {
                let sc = size(u).max(size(v)).max(1.0).powi(2);
                let pos_k = *ratio > F::zero() && !negligible(ratio, 1.0);
                let uu = pe(u, u);
                let pos = uu > F::zero();
                vec![
                    Certificate::decide(
                        "⟨U, U⟩ > 0 (a Euclidean plane: hyperbolic tangents)",
                        pos,
                        ex,
                        || format_scalar(&uu),
                    ),
                    Certificate::decide(
                        "k > 0 (the norm ratio ⟨V, V⟩/⟨U, U⟩ of the circle's parametrization)",
                        pos_k,
                        ex,
                        || format_scalar(ratio),
                    ),
                    cert(
                        "⟨V, V⟩ = k⟨U, U⟩ (U, V/√k pe-orthonormal up to the common scale ρ; k = 1 unless the circle's plane has a non-square discriminant)",
                        pe(v, v),
                        uu.clone() * ratio.clone(),
                        sc,
                    ),
                    cert(
                        "⟨U, V⟩ = 0 (a pe circle, Lemma 3.4)",
                        pe(u, v),
                        F::zero(),
                        sc,
                    ),
                ]
            }
            PeConic::Parabola { u, n, .. } => {
                let sc = size(u).max(size(n)).max(1.0).powi(2);
                vec![
                    {
                        let uu = pe(u, u);
                        Certificate::decide(
                            "⟨U, U⟩ > 0 (a spacelike tangent: hyperbolic tangents)",
                            uu > F::zero() && !negligible(&uu, sc),
                            ex,
                            || format_scalar(&uu),
                        )
                    },
                    cert(
                        "⟨N, N⟩ = 0 (N isotropic: a parabola in a γ-plane, Prop. 3.2)",
                        pe(n, n),
                        F::zero(),
                        sc,
                    ),
                    cert("⟨U, N⟩ = 0", pe(u, n), F::zero(), sc),
                ]
            }
        }
    }

    /// Certificates of the offset at distance `d`: `X_d − X − d N ≡ 0`, `X₀ᵈ ≡ X₀`
    /// (`x_d = x + d n`), and every certificate of the offset cyclide itself.
    ///
    /// # Errors
    /// As [`DupinCyclide::offset`].
    pub fn certify_offset(&self, d: &F) -> Result<Vec<Certificate>, CyclideError> {
        let off = self.offset(d)?;
        let sc = scale_of(&self.x).max(scale_of(&self.normal)) * d.to_f64().abs().max(1.0);
        let mut diff = off.x[0].sub(&self.x[0]).all_coeffs();
        for i in 0..3 {
            diff.extend(
                off.x[i + 1]
                    .sub(&self.x[i + 1])
                    .sub(&self.normal[i].scale(d))
                    .all_coeffs(),
            );
        }
        let mut out = vec![polynomial_is_zero_scaled(
            &format!(
                "x_d − x − d n ≡ 0 for d = {} (the offset is the cyclide with r → r + d)",
                format_scalar(d)
            ),
            &diff,
            sc,
        )];
        out.extend(off.certify().into_iter().map(|mut c| {
            c.property = format!("offset d = {}: {}", format_scalar(d), c.property);
            c
        }));
        Ok(out)
    }
}
