//! The generalized stereographic projection onto the hyperbolic paraboloid (Jüttler §3).
//!
//! * `ψ(q) = (q0q3, q1q3, q0q2, q1q2)` (15) maps onto `H: h0h3 = h1h2` (6). It is the
//!   Segre map `(u, v) ↦ u⊗v` of `u = (q0, q1)` and `v = (q3, q2)`, so it vanishes on the
//!   two focal lines `q0 = q1 = 0` and `q2 = q3 = 0` of the hyperbolic congruence
//!   (Satz 11; Jüttler's `(1 λ 0 0)` and `(0 0 1 μ)`).
//! * `τ(q0,q1,q2,q0) = (q0², q0q1, q0q2, q1q2)` (16), the stereographic projection of the
//!   plane `R: q3 = q0` from `c = (0,0,0,1)` (Satz 8); `τ⁻¹(h) = (h0,h1,h2,h0)`.
//! * `α(q) = (q0q3, q1q3, q0q2, q0q3)` (17), with `τ(α(q)) = q0q3·ψ(q)` (Satz 9,
//!   corrected up to this factor, docs/math/quadrics.md, "The map ψ onto the hyperbolic paraboloid").
//! * Fibre over `h` (Lemma 10 (18)): `span{(h0,h1,h2,h0), (h0,h1,0,0)}`; in Segre form
//!   `span{(u0,u1,0,0), (0,0,v1,v0)}` with `h ∥ u⊗v`, which also covers the points with
//!   `h0 = h1 = 0`. `ψ(λa+μb) = λ(λ+μ)h0·h` for Jüttler's basis.
//! * Fibre scaling: `ψ(diag(s,s,1,1)·q) = s·ψ(q)` (the analogue of δ's rotation `J`).

use super::helpers::{self, fmt_vec, mat4_i};
use super::quadratic_map::QuadraticMap;
use super::{check_on_quadric, check_point, GeneralizedProjection, Hom, Mat4, QuadricError};
use rcagd_algebra::{Certificate, Scalar};

/// `H: h0h3 − h1h2 = 0` as a symmetric matrix (the form `2h0h3 − 2h1h2`).
pub fn paraboloid_matrix<F: Scalar>() -> Mat4<F> {
    mat4_i([[0, 0, 0, 1], [0, 0, -1, 0], [0, -1, 0, 0], [1, 0, 0, 0]])
}

/// `ψ(q)`, Jüttler (15).
pub fn psi<F: Scalar>(q: &Hom<F>) -> Hom<F> {
    let [q0, q1, q2, q3] = q;
    [
        q0.clone() * q3.clone(),
        q1.clone() * q3.clone(),
        q0.clone() * q2.clone(),
        q1.clone() * q2.clone(),
    ]
}

/// The polar form `ψ̂(a, b) = ½(a0b3+a3b0, a1b3+a3b1, a0b2+a2b0, a1b2+a2b1)`.
pub fn psi_polar<F: Scalar>(a: &Hom<F>, b: &Hom<F>) -> Hom<F> {
    let h = F::one() / F::from_i64(2);
    let m = |i: usize, j: usize| {
        (a[i].clone() * b[j].clone() + a[j].clone() * b[i].clone()) * h.clone()
    };
    [m(0, 3), m(1, 3), m(0, 2), m(1, 2)]
}

/// ψ as a [`QuadraticMap`].
pub fn psi_map<F: Scalar>() -> QuadraticMap<F> {
    QuadraticMap::from_fn(psi)
}

fn tau_formula<F: Scalar>(q: &Hom<F>) -> Hom<F> {
    let [q0, q1, q2, _] = q;
    [
        q0.clone() * q0.clone(),
        q0.clone() * q1.clone(),
        q0.clone() * q2.clone(),
        q1.clone() * q2.clone(),
    ]
}

/// `τ(q)` for `q ∈ R: q3 = q0`, Jüttler (16) (Satz 8).
///
/// # Errors
/// [`QuadricError::NotInPlane`] if `q3 ≠ q0`; [`QuadricError::ZeroPoint`];
/// [`QuadricError::Exceptional`] at `(0,0,1,0)`... more precisely where τ vanishes
/// (`q0 = 0` and `q1q2 = 0`: the points of `R` on the two generators through `c`).
pub fn tau<F: Scalar>(q: &Hom<F>) -> Result<Hom<F>, QuadricError> {
    check_point(q, "the point")?;
    let d = q[3].clone() - q[0].clone();
    if !helpers::negligible(&d, helpers::magnitude(q)) {
        return Err(QuadricError::NotInPlane {
            map: "τ".into(),
            plane: "R: q3 = q0".into(),
            point: fmt_vec(q),
        });
    }
    let h = tau_formula(q);
    if helpers::all_negligible(&h, helpers::magnitude(q).powi(2)) {
        return Err(QuadricError::Exceptional {
            map: "τ".into(),
            point: fmt_vec(q),
            reason: "it is a fundamental point of the stereographic projection from c (the image of a generator through c)".into(),
        });
    }
    Ok(h)
}

/// τ extended to `P³` by ignoring `q3`, as a [`QuadraticMap`].
pub fn tau_map<F: Scalar>() -> QuadraticMap<F> {
    QuadraticMap::from_fn(tau_formula)
}

/// The matrix of `τ⁻¹: h ↦ (h0, h1, h2, h0)`.
pub fn tau_inverse_matrix<F: Scalar>() -> Mat4<F> {
    mat4_i([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [1, 0, 0, 0]])
}

/// `τ⁻¹(h) = (h0, h1, h2, h0)` for `h ∈ H`.
///
/// # Errors
/// [`QuadricError::NotOnQuadric`]; [`QuadricError::Exceptional`] at the centre
/// `c = (0,0,0,1)`.
pub fn tau_inverse<F: Scalar>(h: &Hom<F>) -> Result<Hom<F>, QuadricError> {
    check_on_quadric(&paraboloid_matrix(), h, "the point", "H")?;
    let q = helpers::mat_vec(&tau_inverse_matrix(), h);
    if helpers::all_negligible(&q, helpers::magnitude(h)) {
        return Err(QuadricError::Exceptional {
            map: "τ⁻¹".into(),
            point: fmt_vec(h),
            reason: "it is the centre c = (0,0,0,1) of the stereographic projection".into(),
        });
    }
    Ok(q)
}

fn alpha_formula<F: Scalar>(q: &Hom<F>) -> Hom<F> {
    let [q0, q1, q2, q3] = q;
    [
        q0.clone() * q3.clone(),
        q1.clone() * q3.clone(),
        q0.clone() * q2.clone(),
        q0.clone() * q3.clone(),
    ]
}

/// `α(q)`, Jüttler (17): the net projection onto `R` along the hyperbolic congruence.
///
/// # Errors
/// [`QuadricError::Exceptional`] where α vanishes: on the focal lines `q0 = q1 = 0`,
/// `q2 = q3 = 0` and on the fibre `q0 = q3 = 0` over `c`.
pub fn alpha<F: Scalar>(q: &Hom<F>) -> Result<Hom<F>, QuadricError> {
    check_point(q, "the point")?;
    let a = alpha_formula(q);
    if helpers::all_negligible(&a, helpers::magnitude(q).powi(2)) {
        return Err(QuadricError::Exceptional {
            map: "α".into(),
            point: fmt_vec(q),
            reason: "it lies on a focal line (q0 = q1 = 0 or q2 = q3 = 0) or on the projecting line q0 = q3 = 0 over c".into(),
        });
    }
    Ok(a)
}

/// α as a [`QuadraticMap`].
pub fn alpha_map<F: Scalar>() -> QuadraticMap<F> {
    QuadraticMap::from_fn(alpha_formula)
}

/// The fibre scaling `diag(s, s, 1, 1)`: `ψ(S q) = s·ψ(q)`, `α(S q) = s·α(q)`.
pub fn fibre_scaling_matrix<F: Scalar>(s: &F) -> Mat4<F> {
    let mut m = helpers::identity4::<F>();
    m[0][0] = s.clone();
    m[1][1] = s.clone();
    m
}

/// The two focal lines of the hyperbolic congruence of ψ, each as two spanning points:
/// `q2 = q3 = 0` (the x-axis `(1 λ 0 0)`) and `q0 = q1 = 0` (the ideal line `(0 0 1 μ)`).
pub fn psi_focal_lines<F: Scalar>() -> [[Hom<F>; 2]; 2] {
    let e = |i: usize| {
        let mut v = helpers::zero4::<F>();
        v[i] = F::one();
        v
    };
    [[e(0), e(1)], [e(2), e(3)]]
}

/// The Segre factors `u = (q0, q1)`, `v = (q3, q2)` of a point `h ∈ H`: `h ∥ u⊗v`, i.e.
/// `h = (u0v0, u1v0, u0v1, u1v1)` up to a factor.
pub(crate) fn segre_factors<F: Scalar>(h: &Hom<F>) -> ([F; 2], [F; 2]) {
    let pick = |a: [F; 2], b: [F; 2]| {
        let na = a[0].to_f64().abs() + a[1].to_f64().abs();
        let nb = b[0].to_f64().abs() + b[1].to_f64().abs();
        let a_zero = a.iter().all(|x| x.is_zero());
        if F::EXACT {
            if a_zero {
                b
            } else {
                a
            }
        } else if na >= nb {
            a
        } else {
            b
        }
    };
    let u = pick([h[0].clone(), h[1].clone()], [h[2].clone(), h[3].clone()]);
    let v = pick([h[0].clone(), h[2].clone()], [h[1].clone(), h[3].clone()]);
    (u, v)
}

/// The projecting line of ψ over `h ∈ H` in Segre form: `[(u0,u1,0,0), (0,0,v1,v0)]`.
/// Each spanning point lies on a focal line (ψ vanishes there); every other point `x` of
/// the line has `ψ(x) ∥ h`.
///
/// # Errors
/// [`QuadricError::NotOnQuadric`], [`QuadricError::ZeroPoint`].
pub fn psi_fibre<F: Scalar>(h: &Hom<F>) -> Result<[Hom<F>; 2], QuadricError> {
    check_on_quadric(&paraboloid_matrix(), h, "the point", "H")?;
    let (u, v) = segre_factors(h);
    let z = F::zero();
    Ok([
        [u[0].clone(), u[1].clone(), z.clone(), z.clone()],
        [z.clone(), z, v[1].clone(), v[0].clone()],
    ])
}

/// Jüttler's basis of the projecting line (Lemma 10 (18)): `[τ⁻¹(h), (h0, h1, 0, 0)]`
/// with `ψ(λa + μb) = λ(λ+μ)h0·h`.
///
/// # Errors
/// As [`tau_inverse`]; [`QuadricError::Exceptional`] if `h0 = h1 = 0` (then `b = 0`; use
/// [`psi_fibre`]).
pub fn psi_fibre_seed<F: Scalar>(h: &Hom<F>) -> Result<[Hom<F>; 2], QuadricError> {
    let a = tau_inverse(h)?;
    let b = [h[0].clone(), h[1].clone(), F::zero(), F::zero()];
    if helpers::all_negligible(&b, helpers::magnitude(h)) {
        return Err(QuadricError::Exceptional {
            map: "Lemma 10".into(),
            point: fmt_vec(h),
            reason: "h0 = h1 = 0: the second spanning point vanishes".into(),
        });
    }
    Ok([a, b])
}

/// The generalized stereographic projection ψ onto the hyperbolic paraboloid `H`
/// (Jüttler §3).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Psi;

impl<F: Scalar> GeneralizedProjection<F> for Psi {
    fn name(&self) -> String {
        "ψ (hyperbolic paraboloid H)".into()
    }
    fn quadric(&self) -> Mat4<F> {
        paraboloid_matrix()
    }
    fn quadratic_map(&self) -> QuadraticMap<F> {
        psi_map()
    }
    fn apply(&self, p: &Hom<F>) -> Hom<F> {
        psi(p)
    }
    fn polar(&self, a: &Hom<F>, b: &Hom<F>) -> Hom<F> {
        psi_polar(a, b)
    }
    fn fibre(&self, k: &Hom<F>) -> Result<[Hom<F>; 2], QuadricError> {
        psi_fibre(k)
    }
    fn fibre_generator(&self) -> Mat4<F> {
        mat4_i([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]])
    }
}

/// The quadric `a q0q3 + b q1q3 + c q0q2 + d q1q2 = 0`, the preimage under α of the conic
/// `aX0² + bX0X1 + cX0X2 + dX1X2 = 0` of `R` (docs/math/quadrics.md, "Preimage quadrics"). It is always a hyperbolic
/// paraboloid (or degenerate), never a one-sheet hyperboloid: docs/math/quadrics.md, Errata J2 (Jüttler §3,
/// first bullet, says "einschaliges Hyperboloid").
pub fn conic_preimage_quadric<F: Scalar>(a: &F, b: &F, c: &F, d: &F) -> Mat4<F> {
    let h = F::one() / F::from_i64(2);
    let z = F::zero();
    let a = a.clone() * h.clone();
    let b = b.clone() * h.clone();
    let c = c.clone() * h.clone();
    let d = d.clone() * h;
    [
        [z.clone(), z.clone(), c.clone(), a.clone()],
        [z.clone(), z.clone(), d.clone(), b.clone()],
        [c, d, z.clone(), z.clone()],
        [a, b, z.clone(), z],
    ]
}

/// The conic `aX0² + bX0X1 + cX0X2 + dX1X2 = 0` in `R` as a quadratic form on `P³`.
pub fn plane_conic_matrix<F: Scalar>(a: &F, b: &F, c: &F, d: &F) -> Mat4<F> {
    let h = F::one() / F::from_i64(2);
    let z = F::zero();
    let b = b.clone() * h.clone();
    let c = c.clone() * h.clone();
    let d = d.clone() * h;
    [
        [a.clone(), b.clone(), c.clone(), z.clone()],
        [b, z.clone(), d.clone(), z.clone()],
        [c, d, z.clone(), z.clone()],
        [z.clone(), z.clone(), z.clone(), z],
    ]
}

/// The exact identities of Jüttler §3 as polynomial identities in `q0..q3`:
/// (6)/(15) `ψ(q) ∈ H`; Satz 8 `ψ|_{q3=q0} = τ`, `τ(q) = q0·(q0,q1,q2,q0) + (q1q2−q0²)·c`
/// (τ(q) lies on the line `cq`); Satz 9 `τ(α(q)) = q0q3·ψ(q)`; `τ⁻¹(ψ(q)) = α(q)`;
/// the fibre scaling `ψ(Sq) = sψ(q)`, `α(Sq) = sα(q)` for `S = diag(s,s,1,1)` (checked
/// at `s = 0, 2`; with `s = 1` trivially, this proves it for all `s`), which with
/// `α(q0,q1,q2,q0) = q0·(q0,q1,q2,q0)` gives Lemma 10.
pub fn certify_identities<F: Scalar>() -> Vec<Certificate> {
    let p = psi_map::<F>();
    let t = tau_map::<F>();
    let a = alpha_map::<F>();
    let e_r: Mat4<F> = mat4_i([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [1, 0, 0, 0]]);
    let mut out = vec![p.certify_on_quadric(
        &paraboloid_matrix(),
        "(6),(15): ψ(q) lies on H: h0h3 − h1h2 ≡ 0",
    )];
    out.push(
        p.after(&e_r)
            .certify_equals(&t.after(&e_r), "Satz 8: ψ(q0,q1,q2,q0) ≡ τ(q0,q1,q2,q0)"),
    );
    let on_line = QuadraticMap::from_fn(|q: &Hom<F>| {
        let c = q[1].clone() * q[2].clone() - q[0].clone() * q[0].clone();
        [
            q[0].clone() * q[0].clone(),
            q[0].clone() * q[1].clone(),
            q[0].clone() * q[2].clone(),
            q[0].clone() * q[0].clone() + c,
        ]
    });
    out.push(t.after(&e_r).certify_equals(
        &on_line.after(&e_r),
        "Satz 8: τ(q) = q0·(q0,q1,q2,q0) + (q1q2−q0²)·c lies on the line through c and q",
    ));
    let f03: Mat4<F> = {
        let h = F::one() / F::from_i64(2);
        let mut m = [
            helpers::zero4::<F>(),
            helpers::zero4(),
            helpers::zero4(),
            helpers::zero4(),
        ];
        m[0][3] = h.clone();
        m[3][0] = h;
        m
    };
    out.push(QuadraticMap::certify_composition(
        &t,
        &a,
        &f03,
        &p,
        "Satz 9 (corrected): τ(α(q)) ≡ q0q3·ψ(q)",
    ));
    out.push(
        p.then(&tau_inverse_matrix())
            .certify_equals(&a, "τ⁻¹(ψ(q)) ≡ α(q)"),
    );
    for s in [0i64, 2] {
        let sm = fibre_scaling_matrix(&F::from_i64(s));
        out.push(p.certify_invariance(
            &sm,
            &F::from_i64(s),
            &format!("ψ(diag({s},{s},1,1)·q) ≡ {s}·ψ(q)"),
        ));
        out.push(a.certify_invariance(
            &sm,
            &F::from_i64(s),
            &format!("α(diag({s},{s},1,1)·q) ≡ {s}·α(q)"),
        ));
    }
    let q0_q = QuadraticMap::from_fn(|q: &Hom<F>| {
        [
            q[0].clone() * q[0].clone(),
            q[0].clone() * q[1].clone(),
            q[0].clone() * q[2].clone(),
            q[0].clone() * q[0].clone(),
        ]
    });
    out.push(a.after(&e_r).certify_equals(
        &q0_q.after(&e_r),
        "Lemma 10 (18): α(q0,q1,q2,q0) ≡ q0·(q0,q1,q2,q0)",
    ));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn r(n: i64) -> Rational {
        Rational::from(n)
    }

    #[test]
    fn identities_hold_exactly() {
        for c in certify_identities::<Rational>() {
            assert!(c.holds, "{c}");
        }
        for c in certify_identities::<f64>() {
            assert!(c.holds, "{c}");
        }
    }

    #[test]
    fn fibres() {
        let h = psi(&[r(2), r(-1), r(3), r(5)]);
        let [a, b] = psi_fibre(&h).unwrap();
        let x = helpers::add4(&helpers::scale4(&r(3), &a), &helpers::scale4(&r(-2), &b));
        assert!(helpers::parallel(&psi(&x), &h));
        let [sa, sb] = psi_fibre_seed(&h).unwrap();
        assert_eq!(
            helpers::rank(&[a.to_vec(), b.to_vec(), sa.to_vec(), sb.to_vec()]),
            2
        );
        // points with h0 = h1 = 0
        let h = [r(0), r(0), r(2), r(3)];
        let [a, b] = psi_fibre(&h).unwrap();
        let x = helpers::add4(&a, &b);
        assert!(helpers::parallel(&psi(&x), &h));
        assert!(psi_fibre_seed(&h).is_err());
        assert!(matches!(
            tau_inverse(&[r(0), r(0), r(0), r(1)]),
            Err(QuadricError::Exceptional { .. })
        ));
        assert!(matches!(
            alpha(&[r(0), r(0), r(1), r(1)]),
            Err(QuadricError::Exceptional { .. })
        ));
    }
}

/// An interpolating curve on `H` built from its Segre factors: `y = u⊗v`, i.e.
/// `y = (u0v0, u1v0, u0v1, u1v1)` with `u = (q0, q1)` of degree `r` and `v = (q3, q2)` of
/// degree `s`, so `deg y = r + s` (Jüttler (8); `ψ(q) = u⊗v`).
#[derive(Debug, Clone, PartialEq)]
pub struct SegreInterpolant<F> {
    u: Vec<[F; 2]>,
    v: Vec<[F; 2]>,
    curve: rcagd_geom::BezierCurve<F>,
    params: Vec<F>,
    points: Vec<Hom<F>>,
}

impl<F: Scalar> SegreInterpolant<F> {
    /// The curve on `H` (degree `r + s`).
    pub fn curve(&self) -> &rcagd_geom::BezierCurve<F> {
        &self.curve
    }
    /// The Bernstein coefficients of `u = (q0, q1)` (degree `r`).
    pub fn u(&self) -> &[[F; 2]] {
        &self.u
    }
    /// The Bernstein coefficients of `v = (q3, q2)` (degree `s`).
    pub fn v(&self) -> &[[F; 2]] {
        &self.v
    }
    /// `(r, s)`.
    pub fn degrees(&self) -> (usize, usize) {
        (self.u.len() - 1, self.v.len() - 1)
    }
}

/// The certificates of an interpolant on `H`: the curve lies on `H` (`on_h` names it) and
/// `y(tᵢ) ∥ kᵢ` for every parameter and point.
pub(crate) fn certify_interpolant_on_h<F: Scalar>(
    curve: &rcagd_geom::BezierCurve<F>,
    params: &[F],
    points: &[Hom<F>],
    on_h: &str,
) -> Vec<Certificate> {
    let mut out = vec![super::image::certify_curve_on_quadric(
        curve,
        &paraboloid_matrix(),
        on_h,
    )];
    for (i, (t, k)) in params.iter().zip(points).enumerate() {
        let y = helpers::eval_curve(curve, t);
        let ok = !helpers::is_zero_vec(&y) && helpers::parallel(&y, k);
        out.push(Certificate::decide(
            format!("y(t{i}) ∥ k{i}"),
            ok,
            F::EXACT,
            || format!("{} vs {}", fmt_vec(&y), fmt_vec(k)),
        ));
    }
    out
}

impl<F: Scalar> crate::Certified for SegreInterpolant<F> {
    /// The curve lies on `H` and passes through every point at its parameter.
    fn certify(&self) -> Vec<Certificate> {
        certify_interpolant_on_h(
            &self.curve,
            &self.params,
            &self.points,
            "the Segre interpolant lies on H: h0h3 − h1h2 ≡ 0",
        )
    }
}

/// The Segre factors `(Uᵢ, Vᵢ)` of points `kᵢ ∥ Uᵢ⊗Vᵢ` on `H`, after checking the
/// interpolation data: as many parameters as points (at least one), every point on `H`,
/// no two parameters and no two points equal.
///
/// # Errors
/// [`QuadricError::Dimension`], [`QuadricError::NotOnQuadric`],
/// [`QuadricError::RepeatedParameters`], [`QuadricError::RepeatedPoints`].
#[allow(clippy::type_complexity)]
pub(crate) fn checked_segre_factors<F: Scalar>(
    points: &[Hom<F>],
    params: &[F],
) -> Result<(Vec<[F; 2]>, Vec<[F; 2]>), QuadricError> {
    if points.len() != params.len() || points.is_empty() {
        return Err(QuadricError::Dimension(format!(
            "{} points but {} parameters",
            points.len(),
            params.len()
        )));
    }
    let q = paraboloid_matrix::<F>();
    let mut us = Vec::new();
    let mut vs = Vec::new();
    for (i, k) in points.iter().enumerate() {
        check_on_quadric(&q, k, &format!("point {i}"), "H")?;
        for j in 0..i {
            if helpers::negligible(
                &(params[i].clone() - params[j].clone()),
                helpers::magnitude(std::slice::from_ref(&params[i])),
            ) {
                return Err(QuadricError::RepeatedParameters(j, i));
            }
            if helpers::parallel(k, &points[j]) {
                return Err(QuadricError::RepeatedPoints(j, i));
            }
        }
        let (u, v) = segre_factors(k);
        us.push(u);
        vs.push(v);
    }
    Ok((us, vs))
}

/// `y = u⊗v = (u0v0, u1v0, u0v1, u1v1)` in Bernstein form of degree `r + s` (product
/// rule `C(r,i)·C(s,j)/C(r+s,i+j)`) for binary forms `u`, `v` of degrees `r`, `s`
/// given by their Bernstein coefficients (both non-empty).
pub(crate) fn segre_product<F: Scalar>(u: &[[F; 2]], v: &[[F; 2]]) -> Vec<[F; 4]> {
    let (r, s) = (u.len().saturating_sub(1), v.len().saturating_sub(1));
    let mut pts = vec![helpers::zero4::<F>(); r + s + 1];
    for (i, ui) in u.iter().enumerate() {
        for (j, vj) in v.iter().enumerate() {
            let w = helpers::binom::<F>(r, i) * helpers::binom::<F>(s, j)
                / helpers::binom::<F>(r + s, i + j);
            let prod = [
                ui[0].clone() * vj[0].clone(),
                ui[1].clone() * vj[0].clone(),
                ui[0].clone() * vj[1].clone(),
                ui[1].clone() * vj[1].clone(),
            ];
            for (o, x) in pts[i + j].iter_mut().zip(prod) {
                *o += w.clone() * x;
            }
        }
    }
    pts
}

/// The lowest-degree binary polynomial `w(t)` (Bernstein coefficients) with
/// `w(tᵢ) ∥ Wᵢ` and `w(tᵢ) ≠ 0` for all `i`.
fn lowest_binary<F: Scalar>(targets: &[[F; 2]], params: &[F]) -> Option<Vec<[F; 2]>> {
    for r in 0..=targets.len() {
        let basis = binary_space(targets, params, r);
        let pick = super::image::pick_member(&basis, 1, |c| {
            params.iter().all(|t| {
                let w = binary_eval(c, r, t);
                !helpers::all_negligible(&w, helpers::magnitude(c))
            })
        });
        if let Some(c) = pick {
            return Some(c.chunks(2).map(|p| [p[0].clone(), p[1].clone()]).collect());
        }
    }
    None
}

/// The binary form with flattened Bernstein coefficients `c` (degree `r`) at `t`.
pub(crate) fn binary_eval<F: Scalar>(c: &[F], r: usize, t: &F) -> [F; 2] {
    let b = helpers::bernstein::<F>(r, t);
    let mut w = [F::zero(), F::zero()];
    for (j, bj) in b.iter().enumerate() {
        w[0] += bj.clone() * c[2 * j].clone();
        w[1] += bj.clone() * c[2 * j + 1].clone();
    }
    w
}

/// The solution space `{w of degree r : w(tᵢ) ∥ Wᵢ}` (flattened Bernstein coefficients).
pub(crate) fn binary_space<F: Scalar>(targets: &[[F; 2]], params: &[F], r: usize) -> Vec<Vec<F>> {
    let rows: Vec<Vec<F>> = targets
        .iter()
        .zip(params)
        .map(|(w, t)| {
            let b = helpers::bernstein::<F>(r, t);
            let mut row = vec![F::zero(); 2 * (r + 1)];
            for (j, bj) in b.iter().enumerate() {
                row[2 * j] = bj.clone() * w[1].clone();
                row[2 * j + 1] = -(bj.clone() * w[0].clone());
            }
            row
        })
        .collect();
    helpers::null_space(&rows, 2 * (r + 1))
}

/// Interpolation on `H` of lowest degree, odd degrees included: the conditions
/// `u(tᵢ) ∥ Uᵢ`, `v(tᵢ) ∥ Vᵢ` for the Segre factors of `kᵢ ∥ Uᵢ⊗Vᵢ` decouple (Jüttler's
/// linear problem for ψ splits into its `u`- and `v`-parts), so the lowest degrees `r`
/// and `s` are found separately and `y = u⊗v` has the lowest degree `r + s` of all
/// rational curves on `H` through the points at these parameters (every coprime curve on
/// `H` is `u⊗v`, Jüttler (8)). Points on one generator give a line (`r = 0` or `s = 0`).
///
/// # Errors
/// [`QuadricError::Dimension`], [`QuadricError::NotOnQuadric`],
/// [`QuadricError::RepeatedParameters`], [`QuadricError::RepeatedPoints`],
/// [`QuadricError::NoInterpolant`].
pub fn interpolate_segre<F: Scalar>(
    points: &[Hom<F>],
    params: &[F],
) -> Result<SegreInterpolant<F>, QuadricError> {
    let (us, vs) = checked_segre_factors(points, params)?;
    let none = |what: &str| QuadricError::NoInterpolant {
        degree: points.len(),
        reason: format!("no admissible {what} factor"),
    };
    let u = lowest_binary(&us, params).ok_or_else(|| none("u"))?;
    let v = lowest_binary(&vs, params).ok_or_else(|| none("v"))?;
    let pts = segre_product(&u, &v);
    let curve =
        rcagd_geom::BezierCurve::from_homogeneous(pts.into_iter().map(|p| p.to_vec()).collect())?;
    Ok(SegreInterpolant {
        u,
        v,
        curve,
        params: params.to_vec(),
        points: points.to_vec(),
    })
}
