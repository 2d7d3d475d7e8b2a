//! The generalized stereographic projection onto the unit sphere (Jüttler §2).
//!
//! * `δ(p) = (p0²+p1²+p2²+p3², 2p0p1−2p2p3, 2p0p2+2p1p3, p1²+p2²−p0²−p3²)` (9): every
//!   real `p ≠ 0` maps to a point of the unit sphere `K: k0² = k1²+k2²+k3²` (5), and
//!   `k0 = |p|² > 0`; δ is defined on all of real `P³` (docs/math/quadrics.md, "The map δ onto the sphere"). It is the Hopf map.
//! * `σ(p0,p1,p2,0) = (p0²+p1²+p2², 2p0p1, 2p0p2, p1²+p2²−p0²)` (10): the stereographic
//!   projection of the equator plane `P: p3 = 0` from `z = (1,0,0,1)` (Satz 2);
//!   `σ⁻¹(k) = (k0−k3, k1, k2, 0)`, with `σ⁻¹(σ(p)) = 2p0·p`.
//! * `ϑ(p) = (p0²+p3², p0p1−p2p3, p0p2+p1p3, 0)` (11), the net projection along the
//!   elliptic congruence (12) (Folgerung 6); `σ(ϑ(p)) = (p0²+p3²)·δ(p)` (Satz 3,
//!   corrected: Jüttler's `δ = σ∘ϑ` holds up to this factor, docs/math/quadrics.md, "The map δ onto the sphere"). ϑ vanishes on
//!   the line `p0 = p3 = 0` (the fibre over `z`), so δ is computed directly, never as σ∘ϑ.
//! * The fibre rotation `J(p) = (−p3, p2, −p1, p0)`, `J² = −I`, `δ((aI+bJ)p) = (a²+b²)δ(p)`.
//! * The fibre over `k ∈ K` (Lemma 4 (12)): `span{a, Ja}` with `a = σ⁻¹(k)`; over `z` it is
//!   `span{(0,1,0,0), (0,0,1,0)}` (docs/math/quadrics.md, "The map δ onto the sphere").

use super::helpers::{self, fmt_vec, mat4_i};
use super::quadratic_map::QuadraticMap;
use super::{check_on_quadric, check_point, GeneralizedProjection, Hom, Mat4, QuadricError};
use rcagd_algebra::{Certificate, Scalar};

/// The unit sphere `K: k0² − k1² − k2² − k3² = 0` as the matrix `diag(1, −1, −1, −1)`.
pub fn sphere_matrix<F: Scalar>() -> Mat4<F> {
    mat4_i([[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, -1, 0], [0, 0, 0, -1]])
}

fn sq<F: Scalar>(x: &F) -> F {
    x.clone() * x.clone()
}

fn two<F: Scalar>() -> F {
    F::from_i64(2)
}

/// `δ(p)`, Jüttler (9).
pub fn delta<F: Scalar>(p: &Hom<F>) -> Hom<F> {
    let [p0, p1, p2, p3] = p;
    [
        sq(p0) + sq(p1) + sq(p2) + sq(p3),
        two::<F>() * (p0.clone() * p1.clone() - p2.clone() * p3.clone()),
        two::<F>() * (p0.clone() * p2.clone() + p1.clone() * p3.clone()),
        sq(p1) + sq(p2) - sq(p0) - sq(p3),
    ]
}

/// The polar form `δ̂(a, b) = (δ(a+b) − δ(a−b))/4`:
/// `(a·b, a0b1+a1b0−a2b3−a3b2, a0b2+a2b0+a1b3+a3b1, a1b1+a2b2−a0b0−a3b3)`.
pub fn delta_polar<F: Scalar>(a: &Hom<F>, b: &Hom<F>) -> Hom<F> {
    let m = |i: usize, j: usize| a[i].clone() * b[j].clone();
    [
        m(0, 0) + m(1, 1) + m(2, 2) + m(3, 3),
        m(0, 1) + m(1, 0) - m(2, 3) - m(3, 2),
        m(0, 2) + m(2, 0) + m(1, 3) + m(3, 1),
        m(1, 1) + m(2, 2) - m(0, 0) - m(3, 3),
    ]
}

/// δ as a [`QuadraticMap`].
pub fn delta_map<F: Scalar>() -> QuadraticMap<F> {
    QuadraticMap::from_fn(delta)
}

/// `σ(p)` for a point of the equator plane `P: p3 = 0`, Jüttler (10) (Satz 2).
///
/// # Errors
/// [`QuadricError::NotInPlane`] if `p3 ≠ 0`, [`QuadricError::ZeroPoint`] for `p = 0`.
pub fn sigma<F: Scalar>(p: &Hom<F>) -> Result<Hom<F>, QuadricError> {
    check_point(p, "the point")?;
    if !helpers::negligible(&p[3], helpers::magnitude(p)) {
        return Err(QuadricError::NotInPlane {
            map: "σ".into(),
            plane: "P: p3 = 0".into(),
            point: fmt_vec(p),
        });
    }
    Ok(sigma_formula(p))
}

fn sigma_formula<F: Scalar>(p: &Hom<F>) -> Hom<F> {
    let [p0, p1, p2, _] = p;
    [
        sq(p0) + sq(p1) + sq(p2),
        two::<F>() * p0.clone() * p1.clone(),
        two::<F>() * p0.clone() * p2.clone(),
        sq(p1) + sq(p2) - sq(p0),
    ]
}

/// σ extended to `P³` by ignoring `p3` (equals δ on `p3 = 0`), as a [`QuadraticMap`].
pub fn sigma_map<F: Scalar>() -> QuadraticMap<F> {
    QuadraticMap::from_fn(sigma_formula)
}

/// The matrix of the linear map `σ⁻¹: k ↦ (k0−k3, k1, k2, 0)`.
pub fn sigma_inverse_matrix<F: Scalar>() -> Mat4<F> {
    mat4_i([[1, 0, 0, -1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0]])
}

/// `σ⁻¹(k) = (k0−k3, k1, k2, 0)` for `k ∈ K` (text after Satz 3).
///
/// # Errors
/// [`QuadricError::NotOnQuadric`] if `k ∉ K`; [`QuadricError::Exceptional`] at the centre
/// `z = (1,0,0,1)`.
pub fn sigma_inverse<F: Scalar>(k: &Hom<F>) -> Result<Hom<F>, QuadricError> {
    check_on_quadric(&sphere_matrix(), k, "the point", "K")?;
    let a = helpers::mat_vec(&sigma_inverse_matrix(), k);
    if helpers::all_negligible(&a, helpers::magnitude(k)) {
        return Err(QuadricError::Exceptional {
            map: "σ⁻¹".into(),
            point: fmt_vec(k),
            reason: "it is the centre z = (1,0,0,1) of the stereographic projection".into(),
        });
    }
    Ok(a)
}

fn theta_formula<F: Scalar>(p: &Hom<F>) -> Hom<F> {
    let [p0, p1, p2, p3] = p;
    [
        sq(p0) + sq(p3),
        p0.clone() * p1.clone() - p2.clone() * p3.clone(),
        p0.clone() * p2.clone() + p1.clone() * p3.clone(),
        F::zero(),
    ]
}

/// `ϑ(p)`, Jüttler (11): the net projection onto `P` along the congruence (12).
///
/// # Errors
/// [`QuadricError::Exceptional`] on the line `p0 = p3 = 0` (the fibre over `z`), where ϑ
/// vanishes identically (docs/math/quadrics.md, "The map δ onto the sphere").
pub fn theta<F: Scalar>(p: &Hom<F>) -> Result<Hom<F>, QuadricError> {
    check_point(p, "the point")?;
    let t = theta_formula(p);
    if helpers::all_negligible(&t, helpers::magnitude(p).powi(2)) {
        return Err(QuadricError::Exceptional {
            map: "ϑ".into(),
            point: fmt_vec(p),
            reason: "it lies on the line p0 = p3 = 0, the projecting line over z".into(),
        });
    }
    Ok(t)
}

/// ϑ as a [`QuadraticMap`].
pub fn theta_map<F: Scalar>() -> QuadraticMap<F> {
    QuadraticMap::from_fn(theta_formula)
}

/// The matrix of the fibre rotation `J(p) = (−p3, p2, −p1, p0)`.
pub fn j_matrix<F: Scalar>() -> Mat4<F> {
    mat4_i([[0, 0, 0, -1], [0, 0, 1, 0], [0, -1, 0, 0], [1, 0, 0, 0]])
}

/// `J(p) = (−p3, p2, −p1, p0)` (docs/math/quadrics.md, "The map δ onto the sphere").
pub fn fibre_rotation<F: Scalar>(p: &Hom<F>) -> Hom<F> {
    [-p[3].clone(), p[2].clone(), -p[1].clone(), p[0].clone()]
}

/// The projecting line of δ over `k ∈ K` (Lemma 4 (12), docs/math/quadrics.md, "The map δ onto the sphere"): `[a, Ja]` with
/// `a = σ⁻¹(k) = (k0−k3, k1, k2, 0)` if `k0 ≠ k3`, and `a = (k1, k0+k3, 0, k2)` otherwise
/// (then `k ∥ z` and the fibre is `span{(0,1,0,0), (0,0,1,0)}`). Then
/// `δ(λa + μJa) = c·(λ²+μ²)·k` with `c = 2(k0−k3)` resp. `c = 2(k0+k3)`. (For `f64` the
/// better conditioned of the two formulas is used.)
///
/// # Errors
/// [`QuadricError::NotOnQuadric`], [`QuadricError::ZeroPoint`], [`QuadricError::NotFinite`].
pub fn delta_fibre<F: Scalar>(k: &Hom<F>) -> Result<[Hom<F>; 2], QuadricError> {
    check_on_quadric(&sphere_matrix(), k, "the point", "K")?;
    let [k0, k1, k2, k3] = k;
    let minus = k0.clone() - k3.clone();
    let plus = k0.clone() + k3.clone();
    let use_seed = if F::EXACT {
        !minus.is_zero()
    } else {
        minus.to_f64().abs() >= plus.to_f64().abs()
    };
    let a = if use_seed {
        [minus, k1.clone(), k2.clone(), F::zero()]
    } else {
        [k1.clone(), plus, F::zero(), k2.clone()]
    };
    let b = fibre_rotation(&a);
    Ok([a, b])
}

/// The generalized stereographic projection δ onto the unit sphere `K` (Jüttler §2).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Delta;

impl<F: Scalar> GeneralizedProjection<F> for Delta {
    fn name(&self) -> String {
        "δ (unit sphere K)".into()
    }
    fn quadric(&self) -> Mat4<F> {
        sphere_matrix()
    }
    fn quadratic_map(&self) -> QuadraticMap<F> {
        delta_map()
    }
    fn apply(&self, p: &Hom<F>) -> Hom<F> {
        delta(p)
    }
    fn polar(&self, a: &Hom<F>, b: &Hom<F>) -> Hom<F> {
        delta_polar(a, b)
    }
    fn fibre(&self, k: &Hom<F>) -> Result<[Hom<F>; 2], QuadricError> {
        delta_fibre(k)
    }
    fn fibre_generator(&self) -> Mat4<F> {
        j_matrix()
    }
}

/// The quadric `α(p1²+p2²) + β(p0p1−p2p3) + γ(p0p2+p1p3) + ε(p0²+p3²) = 0`, the preimage
/// under ϑ of the circle (or line, `α = 0`) `α(X1²+X2²) + βX0X1 + γX0X2 + εX0² = 0` in
/// `P` (docs/math/quadrics.md, "Preimage quadrics"; Jüttler §2 property list). Its determinant is `(4αε−β²−γ²)²/16`: a
/// one-sheet hyperboloid for a real circle, a hyperbolic paraboloid for a line.
pub fn circle_preimage_quadric<F: Scalar>(alpha: &F, beta: &F, gamma: &F, eps: &F) -> Mat4<F> {
    let h = F::one() / two::<F>();
    let z = F::zero();
    let b = beta.clone() * h.clone();
    let g = gamma.clone() * h;
    [
        [eps.clone(), b.clone(), g.clone(), z.clone()],
        [b.clone(), alpha.clone(), z.clone(), g.clone()],
        [g.clone(), z.clone(), alpha.clone(), -b.clone()],
        [z, g, -b, eps.clone()],
    ]
}

/// The matrix of the circle `α(X1²+X2²) + βX0X1 + γX0X2 + εX0² = 0` in the plane `P`
/// (as a quadratic form on `P³` that ignores `X3`).
pub fn plane_circle_matrix<F: Scalar>(alpha: &F, beta: &F, gamma: &F, eps: &F) -> Mat4<F> {
    let h = F::one() / two::<F>();
    let z = F::zero();
    let b = beta.clone() * h.clone();
    let g = gamma.clone() * h;
    [
        [eps.clone(), b.clone(), g.clone(), z.clone()],
        [b, alpha.clone(), z.clone(), z.clone()],
        [g, z.clone(), alpha.clone(), z.clone()],
        [z.clone(), z.clone(), z.clone(), z],
    ]
}

/// The exact identities of Jüttler §2 for δ, σ, ϑ, J as polynomial identities in
/// `p0..p3` (docs/math/quadrics.md, "The map δ onto the sphere", "Preimage quadrics"):
/// (5)/(9) `δ(p) ∈ K`; Satz 2 `δ|_{p3=0} = σ` and `σ(p) = (p1²+p2²−p0²)·z + 2p0·p`
/// (σ(p) lies on the line `zp`); Satz 3 `σ(ϑ(p)) = (p0²+p3²)·δ(p)`; `σ⁻¹(δ(p)) = 2ϑ(p)`;
/// `σ⁻¹(σ(p)) = 2p0·p`; `J² = −I`; `δ∘J = δ`; `δ̂(p, Jp) = 0` (so
/// `δ((aI+bJ)p) = (a²+b²)δ(p)`); Lemma 4: `ϑ∘J = ϑ`, `ϑ̂(p, Jp) = 0`, `ϑ(a) = p0·a` on `P`.
pub fn certify_identities<F: Scalar>() -> Vec<Certificate> {
    let d = delta_map::<F>();
    let s = sigma_map::<F>();
    let t = theta_map::<F>();
    let j = j_matrix::<F>();
    let e_p: Mat4<F> = mat4_i([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0]]);
    let z: Hom<F> = [F::one(), F::zero(), F::zero(), F::one()];
    let mut out = vec![d.certify_on_quadric(
        &sphere_matrix(),
        "(5),(9): δ(p) lies on K: k0²−k1²−k2²−k3² ≡ 0",
    )];
    out.push(
        d.after(&e_p)
            .certify_equals(&s.after(&e_p), "Satz 2: δ(p0,p1,p2,0) ≡ σ(p0,p1,p2,0)"),
    );
    let on_line = QuadraticMap::from_fn(|p: &Hom<F>| {
        let alpha = sq(&p[1]) + sq(&p[2]) - sq(&p[0]);
        let pp = [p[0].clone(), p[1].clone(), p[2].clone(), F::zero()];
        helpers::add4(
            &helpers::scale4(&alpha, &z),
            &helpers::scale4(&(two::<F>() * p[0].clone()), &pp),
        )
    });
    out.push(s.certify_equals(
        &on_line,
        "Satz 2: σ(p) = (p1²+p2²−p0²)·z + 2p0·p lies on the line through z and p",
    ));
    let f03: Mat4<F> = mat4_i([[1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]);
    out.push(QuadraticMap::certify_composition(
        &s,
        &t,
        &f03,
        &d,
        "Satz 3 (corrected): σ(ϑ(p)) ≡ (p0²+p3²)·δ(p)",
    ));
    let two_theta = t.then(&helpers::scale_mat(&two::<F>(), &helpers::identity4()));
    out.push(
        d.then(&sigma_inverse_matrix())
            .certify_equals(&two_theta, "σ⁻¹(δ(p)) ≡ 2ϑ(p)"),
    );
    let two_p0_p = QuadraticMap::from_fn(|p: &Hom<F>| {
        let c = two::<F>() * p[0].clone();
        [
            c.clone() * p[0].clone(),
            c.clone() * p[1].clone(),
            c * p[2].clone(),
            F::zero(),
        ]
    });
    out.push(
        s.then(&sigma_inverse_matrix())
            .after(&e_p)
            .certify_equals(&two_p0_p.after(&e_p), "σ⁻¹(σ(p)) ≡ 2p0·p on P"),
    );
    let jj = helpers::mat_mul(&j, &j);
    let minus_i = helpers::scale_mat(&-F::one(), &helpers::identity4());
    out.push(Certificate::decide(
        "J² = −I",
        jj == minus_i || helpers::mats_close(&jj, &minus_i),
        F::EXACT,
        || format!("J² = {:?}", jj.clone().map(|r| fmt_vec(&r))),
    ));
    out.push(d.certify_invariance(&j, &F::one(), "δ(Jp) ≡ δ(p)"));
    out.push(d.certify_polar_vanishes(&j, "δ̂(p, Jp) ≡ 0, hence δ((aI+bJ)p) ≡ (a²+b²)·δ(p)"));
    out.push(t.certify_invariance(&j, &F::one(), "Lemma 4: ϑ(Jp) ≡ ϑ(p)"));
    out.push(t.certify_polar_vanishes(&j, "Lemma 4: ϑ̂(p, Jp) ≡ 0, hence ϑ(λa+μJa) = (λ²+μ²)ϑ(a)"));
    let p0_p = QuadraticMap::from_fn(|p: &Hom<F>| {
        [
            sq(&p[0]),
            p[0].clone() * p[1].clone(),
            p[0].clone() * p[2].clone(),
            F::zero(),
        ]
    });
    out.push(t.after(&e_p).certify_equals(
        &p0_p.after(&e_p),
        "Lemma 4 (12): ϑ(p0,p1,p2,0) ≡ p0·(p0,p1,p2,0)",
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
            assert!(c.exact);
        }
        for c in certify_identities::<f64>() {
            assert!(c.holds, "{c}");
        }
    }

    #[test]
    fn polar_form_is_the_polarization() {
        let a = [r(1), r(-2), r(3), r(5)];
        let b = [r(-4), r(1), r(2), r(-1)];
        let m = delta_map::<Rational>();
        assert_eq!(delta_polar(&a, &b), m.polar(&a, &b));
        assert_eq!(delta(&a), m.apply(&a));
    }

    #[test]
    fn fibres_map_to_their_point() {
        let k = delta(&[r(1), r(2), r(-1), r(3)]);
        let [a, b] = delta_fibre(&k).unwrap();
        for (l, m) in [(1, 0), (0, 1), (2, -3), (5, 7)] {
            let x = helpers::add4(&helpers::scale4(&r(l), &a), &helpers::scale4(&r(m), &b));
            assert!(helpers::parallel(&delta(&x), &k));
        }
        let z = [r(3), r(0), r(0), r(3)];
        let [a, b] = delta_fibre(&z).unwrap();
        assert!(helpers::parallel(&delta(&a), &z) && helpers::parallel(&delta(&b), &z));
        assert!(matches!(
            delta_fibre(&[r(1), r(1), r(1), r(0)]),
            Err(QuadricError::NotOnQuadric { .. })
        ));
        assert!(matches!(
            sigma_inverse(&z),
            Err(QuadricError::Exceptional { .. })
        ));
        assert!(matches!(
            theta(&[r(0), r(1), r(2), r(0)]),
            Err(QuadricError::Exceptional { .. })
        ));
        assert!(matches!(
            sigma(&[r(0), r(1), r(2), r(1)]),
            Err(QuadricError::NotInPlane { .. })
        ));
    }
}
