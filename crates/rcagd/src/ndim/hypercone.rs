//! Envelopes of rational one-parameter families of sphere-hypercones in `Rⁿ` (Peternell
//! §5.3, Theorem 5.1, (5.5)–(5.12); docs/math/n-dimensional.md#sphere-hypercones).
//!
//! Two rational cycle families `cᵢ(t) = (mᵢ; rᵢ)(t)` (centres in `Rⁿ`, signed radii) span
//! the sphere-hypercones `Δ(t)`: their common oriented tangent hyperplanes. In the
//! isotropic model the cycles are the isotropic spheres (5.5); their intersection projects
//! to the `(n−2)`-sphere `d'(t)` (5.6) with centre `p = −(M₁, …, M_{n−1})/β` (5.7) and
//! `ρ² = (|M|² − R²)/β²` (5.8), `M = m₁ − m₂`, `R = r₁ − r₂`, `β = R + Mₙ`. With
//! `P₁² + P₂² = |M|² − R²` (the algebra layer's sum-of-two-squares engine), the point
//! `f = p + (P₁, P₂, 0, …)/β` (5.10) lies on `d'(t)`; reflecting it in the diameter
//! hyperplanes with normals `c(u) = (u₁, …, u_{n−2}, 1)` gives `d'(t)` (5.11), (5.12) lifts
//! it to the isotropic sphere, and `Λ⁻¹` gives the envelope as a PN hypersurface in the
//! parameters `(t, u₁, …, u_{n−2})`.

use super::hypersurface::PnHypersurface;
use super::poly::{clean, dot, dot_scale};
use super::NdimError;
use crate::pn::poly::zero_cert;
use crate::pn::ruled::find_two_squares;
use crate::pn::RatFn;
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Scalar};

/// The envelope of the sphere-hypercones of two cycle families (module docs).
#[derive(Debug, Clone)]
pub struct HyperconeEnvelope<F> {
    centers: [Vec<MPoly<F>>; 2],
    radii: [MPoly<F>; 2],
    p: [RatFn<F>; 2],
    surface: PnHypersurface<F>,
}

impl<F: Scalar> HyperconeEnvelope<F> {
    /// The envelope of the hypercones spanned by the cycles `(m₁; r₁)(t)` and `(m₂; r₂)(t)`
    /// (polynomials in `t`, centres of length `n ≥ 3`). `p = (P₁, P₂)` with
    /// `P₁² + P₂² = |M|² − R²` may be given; otherwise it is found exactly.
    ///
    /// # Errors
    /// [`NdimError::InvalidInput`] for wrong lengths or a dependence on other variables
    /// (`β = R + Mₙ ≡ 0` is the linear case: `d'(t)` is a hyperplane, parametrized
    /// linearly); [`NdimError::Degenerate`] for `|M|² ≡ R²` (isotropic cycle pairs: the
    /// cycles touch, `d'(t)` has radius 0) or a degenerate Gauss image;
    /// [`NdimError::NoRationalPoint`] if `|M|² − R²` is no sum of two squares over `Q(t)`.
    pub fn new(
        m1: Vec<MPoly<F>>,
        r1: MPoly<F>,
        m2: Vec<MPoly<F>>,
        r2: MPoly<F>,
        p: Option<[RatFn<F>; 2]>,
    ) -> Result<Self, NdimError> {
        let n = m1.len();
        if n < 3 || m2.len() != n {
            return Err(NdimError::InvalidInput(format!(
                "two cycle families of Rⁿ need centres of one length n ≥ 3, got {} and {}",
                n,
                m2.len()
            )));
        }
        if !m1
            .iter()
            .chain(&m2)
            .chain([&r1, &r2])
            .all(super::poly::only_var0)
        {
            return Err(NdimError::InvalidInput(
                "the cycle families must depend on t (variable 0) only".into(),
            ));
        }
        let nv = n - 1;
        let lift = |x: &MPoly<F>| &MPoly::zero(nv) + x;
        let mm: Vec<MPoly<F>> = m1.iter().zip(&m2).map(|(a, b)| lift(&(a - b))).collect();
        let rr = lift(&(&r1 - &r2));
        let beta = clean(&(&rr + &mm[n - 1]));
        if beta.is_zero() {
            return Self::linear_case(m1, r1, m2, r2, &mm, &rr);
        }
        let disc = clean(&(&dot(&mm, &mm) - &(&rr * &rr)));
        if disc.is_zero() {
            return Err(NdimError::Degenerate(
                "|m₁ − m₂|² ≡ (r₁ − r₂)²: the two cycles touch for every t and span no real hypercone ((5.8): ρ = 0)".into(),
            ));
        }
        let p = match p {
            Some(p) => {
                let t = p[0].mul(&p[0]).add(&p[1].mul(&p[1]));
                let s = t.sub(&RatFn::poly(disc.clone()));
                // exact: s ≡ 0; f64: every coefficient of the numerator within 10⁻⁹ of the
                // size of the terms that cancel in it (T.num − disc·T.den), not of the
                // residual itself
                let l1 = |q: &MPoly<F>| q.terms().map(|(_, c)| c.to_f64().abs()).sum::<f64>();
                let size = l1(&t.num) + l1(&disc) * l1(&t.den);
                let holds = if F::EXACT {
                    s.num.is_zero()
                } else {
                    s.num.terms().all(|(_, c)| c.to_f64().abs() <= 1e-9 * size)
                };
                if !holds {
                    return Err(NdimError::InvalidInput(
                        "the given (P₁, P₂) do not satisfy P₁² + P₂² ≡ |M|² − R²".into(),
                    ));
                }
                p
            }
            None => find_two_squares(&disc).ok_or_else(|| {
                NdimError::NoRationalPoint(
                    "|m₁ − m₂|² − (r₁ − r₂)² is not a sum of two squares of rational functions of t (the point f(t) of (5.10) needs one)".into(),
                )
            })?,
        };
        // f, p over Q0 = β B, B = b₁ b₂
        let (a1, b1, a2, b2) = (
            lift(&p[0].num),
            lift(&p[0].den),
            lift(&p[1].num),
            lift(&p[1].den),
        );
        let bb = &b1 * &b2;
        let pc: Vec<MPoly<F>> = (0..nv).map(|j| -(&mm[j] * &bb)).collect();
        let mut ff = pc.clone();
        ff[0] = &ff[0] + &(&a1 * &b2);
        ff[1] = &ff[1] + &(&a2 * &b1);
        let q0 = &beta * &bb;
        let c: Vec<MPoly<F>> = (0..nv)
            .map(|j| {
                if j + 1 < nv {
                    MPoly::var(nv, j + 1)
                } else {
                    MPoly::constant(nv, F::one())
                }
            })
            .collect();
        let cc = dot(&c, &c);
        let diff: Vec<MPoly<F>> = pc.iter().zip(&ff).map(|(a, b)| a - b).collect();
        let two = F::from_i64(2);
        let pfc = dot(&diff, &c).scale(&two);
        let z: Vec<MPoly<F>> = (0..nv)
            .map(|j| clean(&(&(&ff[j] * &cc) + &(&pfc * &c[j]))))
            .collect();
        let q = &q0 * &cc;
        let surface = isotropic_envelope(
            &m1,
            &r1,
            z,
            &q,
            format!("envelope of sphere-hypercones in R^{n} (Theorem 5.1)"),
        )?;
        Ok(HyperconeEnvelope {
            centers: [m1, m2],
            radii: [r1, r2],
            p,
            surface,
        })
    }

    /// The linear case `β = R + Mₙ ≡ 0` (Peternell's remark after Theorem 4.5 / 5.1: `d'(t)`
    /// is a hyperplane, parametrized linearly; docs/math/n-dimensional.md#hypercone-linear-case).
    /// Subtracting the isotropic spheres (5.12) of the two cycles,
    /// `2yₙ + rᵢ(S + 1) + mᵢₙ(S − 1) + 2mᵢ′·y′ = 0` (`S = |y′|²`), gives
    /// `βS + (R − Mₙ) + 2M′·y′ = 0`, i.e. `M′·y′ = −R` for `β ≡ 0`: the hyperplane through
    /// `y₀ = −R M′/|M′|²` with the directions `vⱼ = M_k eⱼ − Mⱼ e_k` (`j ≠ k`, `M_k ≢ 0`), so
    /// `y′ = (−R M′ + |M′|² Σ uⱼ vⱼ)/|M′|²` and `yₙ` from (5.12) with `i = 1`. No sum of two
    /// squares is needed (`|M|² − R² = |M′|²`); `p()` is `(0, 0)`.
    fn linear_case(
        m1: Vec<MPoly<F>>,
        r1: MPoly<F>,
        m2: Vec<MPoly<F>>,
        r2: MPoly<F>,
        mm: &[MPoly<F>],
        rr: &MPoly<F>,
    ) -> Result<Self, NdimError> {
        let n = m1.len();
        let nv = n - 1;
        let mp = &mm[..nv];
        let Some(k) = (0..nv).find(|&j| !clean(&mp[j]).is_zero()) else {
            return Err(NdimError::Degenerate(
                "β ≡ 0 and m₁ − m₂ is parallel to the last axis: the cycles touch for every t (|M|² ≡ R²), no real hypercone".into(),
            ));
        };
        let q = dot(mp, mp);
        let others: Vec<usize> = (0..nv).filter(|&j| j != k).collect();
        let z: Vec<MPoly<F>> = (0..nv)
            .map(|i| {
                let mut acc = -(rr * &mp[i]);
                for (idx, &j) in others.iter().enumerate() {
                    let u = MPoly::var(nv, idx + 1);
                    // vⱼ = M_k eⱼ − Mⱼ e_k
                    let vji = if i == j {
                        mp[k].clone()
                    } else if i == k {
                        -mp[j].clone()
                    } else {
                        continue;
                    };
                    acc = &acc + &(&(&q * &vji) * &u);
                }
                clean(&acc)
            })
            .collect();
        let surface = isotropic_envelope(
            &m1,
            &r1,
            z,
            &q,
            format!("envelope of sphere-hypercones in R^{n} (Theorem 5.1, linear case β ≡ 0)"),
        )?;
        let zero = RatFn::poly(MPoly::zero(1));
        Ok(HyperconeEnvelope {
            centers: [m1, m2],
            radii: [r1, r2],
            p: [zero.clone(), zero],
            surface,
        })
    }

    /// The envelope, a PN hypersurface in `(t, u₁, …, u_{n−2})`.
    pub fn surface(&self) -> &PnHypersurface<F> {
        &self.surface
    }

    /// The sum of two squares `(P₁, P₂)` used for `f(t)` (5.10) (`(0, 0)` in the linear
    /// case `β ≡ 0`, which needs none).
    pub fn p(&self) -> &[RatFn<F>; 2] {
        &self.p
    }

    /// The contact certificates: every tangent hyperplane touches both cycles in oriented
    /// contact, `E₀ + E·mᵢ + L rᵢ ≡ 0` (`i = 1, 2`): it belongs to the hypercone `Δ(t)`.
    pub fn contact_certificates(&self) -> Vec<Certificate> {
        let e = self.surface.plane_polys();
        let l = self.surface.norm_poly();
        (0..2)
            .map(|i| {
                let r = &(&e[0] + &dot(&e[1..], &self.centers[i])) + &(l * &self.radii[i]);
                let mut terms = self.centers[i].clone();
                terms.insert(0, MPoly::constant(0, F::one()));
                terms.push(self.radii[i].clone());
                let mut coeffs = e.to_vec();
                coeffs.push(l.clone());
                zero_cert(
                    &format!(
                        "tangent hyperplanes touch cycle {} (E₀ + E·m{} + L r{} ≡ 0)",
                        i + 1,
                        i + 1,
                        i + 1
                    ),
                    &r,
                    dot_scale(&coeffs, &terms),
                )
            })
            .collect()
    }
}

impl<F: Scalar> Certified for HyperconeEnvelope<F> {
    /// The PN identities of the envelope and both contact conditions.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.surface.certify();
        out.extend(self.contact_certificates());
        out
    }
}

/// The isotropic model point `(z/q, yₙ/(2q²))` of the envelope from its first `n − 1`
/// coordinates `z` over `q`: `yₙ` from the isotropic sphere (5.12) of the first cycle,
/// `2yₙ = −r₁(S + 1) − m₁ₙ(S − 1) − 2Σ m₁ⱼ zⱼ` with `S = |z|²` (homogenized by `q`), and the
/// PN hypersurface of that model point.
fn isotropic_envelope<F: Scalar>(
    m1: &[MPoly<F>],
    r1: &MPoly<F>,
    mut z: Vec<MPoly<F>>,
    q: &MPoly<F>,
    name: String,
) -> Result<PnHypersurface<F>, NdimError> {
    let n = m1.len();
    let nv = n - 1;
    let lift = |x: &MPoly<F>| &MPoly::zero(nv) + x;
    let two = F::from_i64(2);
    let s = dot(&z, &z);
    let qq = q * q;
    let m1l: Vec<MPoly<F>> = m1.iter().map(lift).collect();
    let yn = -(&(&(&lift(r1) * &(&s + &qq)) + &(&m1l[n - 1] * &(&s - &qq)))
        + &(q * &dot(&m1l[..nv], &z)).scale(&two));
    let qn = qq.scale(&two);
    z.push(clean(&yn));
    Ok(PnHypersurface::from_isotropic(&z, q, &qn)?.named(name))
}
