//! The n-dimensional chapter (Peternell ch. 5): PN hypersurfaces of Rⁿ from the dual form
//! with exact offsets, ruled (k+1)-manifolds with their structure and offsets; the §5.5
//! examples of 2-manifolds in R⁴, property tests with random exact input, named errors.

use proptest::prelude::*;
use rcagd::ndim::ruled::RuledKind;
use rcagd::ndim::{NdimError, PnHypersurface, RuledManifold};
use rcagd::pn::{Domain, RatFn};
use rcagd::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Rational, Scalar};

type Q = Rational;

fn q(p: i64, d: i64) -> Q {
    Q::from_ratio(p, d)
}

fn var(n: usize, i: usize) -> MPoly<Q> {
    MPoly::var(n, i)
}

fn cst(n: usize, c: i64) -> MPoly<Q> {
    MPoly::constant(n, q(c, 1))
}

/// A polynomial in `t` from its power coefficients.
fn tp(c: &[i64]) -> MPoly<Q> {
    c.iter().enumerate().fold(MPoly::zero(1), |acc, (i, &x)| {
        &acc + &MPoly::monomial(1, &[i as u32], q(x, 1))
    })
}

fn exact_hold(certs: &[Certificate]) -> bool {
    !certs.is_empty() && certs.iter().all(|c| c.holds && c.exact)
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-7 * (1.0 + a.abs().max(b.abs()))
}

fn to_f64(p: &MPoly<Q>) -> MPoly<f64> {
    p.map(Scalar::to_f64)
}

// ---------------------------------------------------------------------------------
// PN hypersurfaces (§5.2)
// ---------------------------------------------------------------------------------

/// The dual form (5.3) with a = (u₁, u₂, u₃), c = 1, g = −r(|a|² + c²), f = 1 is the
/// hypersphere |x| = r of R⁴ with x = r·n; its offset at d is the sphere of radius r + d.
#[test]
fn hypersphere_of_r4_from_the_dual_form_with_offsets() {
    let a = [var(3, 0), var(3, 1), var(3, 2)];
    let s = &(&(&(&a[0] * &a[0]) + &(&a[1] * &a[1])) + &(&a[2] * &a[2])) + &cst(3, 1);
    let r = q(3, 2);
    let g = s.scale(&-r.clone());
    let h = PnHypersurface::from_dual(&a, &cst(3, 1), &g, &cst(3, 1)).expect("sphere");
    assert_eq!(h.dim(), 4);
    assert!(exact_hold(&h.certify()));
    let u = [q(1, 2), q(-1, 3), q(2, 1)];
    let x = h.eval_point(&u).expect("point");
    let n = h.eval_normal(&u).expect("normal");
    for i in 0..4 {
        assert_eq!(x[i], r.clone() * n[i].clone());
    }
    let d = q(1, 4);
    let off = h.offset(&d).expect("offset");
    assert!(exact_hold(&off.certify()));
    let xd = off.surface().eval_point(&u).expect("offset point");
    let norm2: Q = xd
        .iter()
        .fold(q(0, 1), |acc, v| acc + v.clone() * v.clone());
    assert_eq!(norm2, (r.clone() + d.clone()) * (r + d));
}

/// A general PN hypersurface of R⁴ from the support-function form (5.4): certificates,
/// exact offsets at two distances, and the point solves e, e_u₁, e_u₂, e_u₃ at a sample.
#[test]
fn support_function_form_in_r4() {
    let (u1, u2, u3) = (var(3, 0), var(3, 1), var(3, 2));
    let a = [u1.clone(), u2.clone(), &u3 + &cst(3, 1)];
    let c = &cst(3, 2) + &u1;
    // h = 1 + u₁u₂ − u₃²/2
    let hnum = &(&cst(3, 1) + &(&u1 * &u2)) - &(&u3 * &u3).scale(&q(1, 2));
    let h = RatFn::new(hnum, cst(3, 1)).expect("h");
    let surf = PnHypersurface::from_support(&a, &c, &h).expect("PN hypersurface");
    assert!(exact_hold(&surf.certify()));
    for d in [q(1, 2), q(-3, 7)] {
        assert!(exact_hold(&surf.offset(&d).expect("offset").certify()));
    }
    // the support function is h + n·x = 0 at a sample point
    let u = [q(1, 3), q(2, 5), q(-1, 2)];
    let x = surf.eval_point(&u).expect("point");
    let n = surf.eval_normal(&u).expect("normal");
    let hv = surf.support().eval(&u).expect("h");
    let nx: Q = x
        .iter()
        .zip(&n)
        .fold(q(0, 1), |acc, (a, b)| acc + a.clone() * b.clone());
    assert_eq!(hv + nx, q(0, 1));
}

/// The isotropic model route (3.13) in R⁴ and a slice projected to R³ as a patch.
#[test]
fn isotropic_hypersurface_and_its_projected_slice() {
    let (u1, u2, u3) = (var(3, 0), var(3, 1), var(3, 2));
    // y₄ = u₁² + u₂u₃ − u₃²/3 over the parameter space (y₁, y₂, y₃) = (u₁, u₂, u₃)
    let y4 = &(&(&u1 * &u1) + &(&u2 * &u3)) - &(&u3 * &u3).scale(&q(1, 3));
    let s = PnHypersurface::from_isotropic(&[u1, u2, u3, y4], &cst(3, 1), &cst(3, 1)).expect("iso");
    assert!(exact_hold(&s.certify()));
    let dom = Domain::new(q(0, 1), q(1, 2), q(0, 1), q(1, 2)).expect("domain");
    let patch = s
        .projected_slice([0, 1], &[q(0, 1), q(0, 1), q(1, 3)], [1, 2, 4], &dom)
        .expect("patch");
    // patch(σ, τ) = projection of x(σ/2, τ/2, 1/3)
    let p = patch.eval(&q(1, 2), &q(1, 3)).expect("eval");
    let x = s.eval_point(&[q(1, 4), q(1, 6), q(1, 3)]).expect("x");
    assert_eq!(p, vec![x[0].clone(), x[1].clone(), x[3].clone()]);
    assert!(matches!(
        s.projected_slice([0, 0], &vec![q(0, 1); 3], [1, 2, 3], &dom),
        Err(NdimError::InvalidInput(_))
    ));
    assert!(matches!(
        s.projected_slice([0, 1], &vec![q(0, 1); 3], [1, 2, 5], &dom),
        Err(NdimError::InvalidInput(_))
    ));
}

#[test]
fn hypersurface_errors_are_named() {
    let (u1, u2) = (var(2, 0), var(2, 1));
    // not Pythagorean
    let bad = PnHypersurface::from_plane_field(
        vec![cst(2, 1), u1.clone(), u2.clone(), cst(2, 1)],
        cst(2, 1),
    );
    assert!(matches!(bad, Err(NdimError::NotUnitNormal(_))));
    // a one-parameter family of normals (a = (u₁, u₁)): no envelope point
    let dev = PnHypersurface::from_dual(&[u1.clone(), u1.clone()], &cst(2, 1), &u2, &cst(2, 1));
    assert!(matches!(dev, Err(NdimError::Degenerate(_))));
    // too many variables
    let extra = PnHypersurface::from_dual(&[u1.clone(), var(3, 2)], &cst(2, 1), &u2, &cst(2, 1));
    assert!(matches!(extra, Err(NdimError::InvalidInput(_))));
    assert!(matches!(
        PnHypersurface::from_dual(&[u1, u2.clone()], &MPoly::zero(2), &u2, &cst(2, 1)),
        Err(NdimError::InvalidInput(_))
    ));
}

fn small() -> impl Strategy<Value = i64> {
    -4i64..=4
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    /// Random linear aᵢ, c and quadratic support functions in R⁴: the hypersurface and its
    /// offset at a random distance are certified exactly, and f64 agrees with Q.
    #[test]
    fn random_pn_hypersurfaces_of_r4(
        lin in prop::collection::vec(small(), 16),
        hq in prop::collection::vec(small(), 10),
        (dp, dq) in (-5i64..=5, 1i64..=4),
        su in prop::collection::vec((-3i64..=3, 1i64..=3), 3),
    ) {
        let vars = [var(3, 0), var(3, 1), var(3, 2)];
        let linear = |k: usize| -> MPoly<Q> {
            (0..3).fold(cst(3, lin[4 * k + 3]), |acc, i| &acc + &vars[i].scale(&q(lin[4 * k + i], 1)))
        };
        let a = [linear(0), linear(1), linear(2)];
        let c = &linear(3) + &cst(3, 7);
        let mut hnum = cst(3, hq[9]);
        let mut idx = 0;
        for i in 0..3 {
            hnum = &hnum + &vars[i].scale(&q(hq[idx], 1));
            idx += 1;
            for j in i..3 {
                hnum = &hnum + &(&vars[i] * &vars[j]).scale(&q(hq[idx], 2));
                idx += 1;
            }
        }
        let h = RatFn::new(hnum, cst(3, 1)).expect("h");
        let Ok(s) = PnHypersurface::from_support(&a, &c, &h) else {
            // a degenerate normal map (rank < 3) is the only admissible failure
            let n = [a[0].clone(), a[1].clone(), a[2].clone()];
            prop_assume!(false, "degenerate normal map {:?}", n.len());
            unreachable!()
        };
        prop_assert!(exact_hold(&s.certify()));
        let d = q(dp, dq);
        let off = s.offset(&d).expect("offset of a PN hypersurface");
        prop_assert!(exact_hold(&off.certify()));
        // f64 path
        let af: Vec<MPoly<f64>> = a.iter().map(to_f64).collect();
        let hf = RatFn::new(to_f64(&h.num), to_f64(&h.den)).expect("h");
        let sf = PnHypersurface::from_support(&af, &to_f64(&c), &hf).expect("f64 path");
        let fc = sf.certify();
        prop_assert!(fc.iter().all(|c| c.holds && !c.exact), "{:?}", fc.iter().find(|c| !c.holds));
        let u: Vec<Q> = su.iter().map(|&(p, d)| q(p, d)).collect();
        let uf: Vec<f64> = u.iter().map(Scalar::to_f64).collect();
        if let (Some(x), Some(xf)) = (s.eval_point(&u), sf.eval_point(&uf)) {
            for (a, b) in x.iter().zip(&xf) {
                prop_assert!(close(Scalar::to_f64(a), *b), "{} vs {}", Scalar::to_f64(a), b);
            }
        }
    }
}

// ---------------------------------------------------------------------------------
// Ruled (k+1)-manifolds (§5.4, §5.5)
// ---------------------------------------------------------------------------------

/// §5.5, first example: the developable 2-manifold p = c + u ċ in R⁴ of the inflection-free
/// curve c = (t, t², t³, t⁴): Case 1 with m = 1 (the edge of regression c is the singular
/// set, u* = 0), the normal space N(t) is 2-dimensional and constant along the rulings;
/// the unit normal comes from a conic point of (5.28), the offset from (5.26).
#[test]
fn developable_two_manifold_in_r4() {
    let c = vec![
        tp(&[0, 1]),
        tp(&[0, 0, 1]),
        tp(&[0, 0, 0, 1]),
        tp(&[0, 0, 0, 0, 1]),
    ];
    let cd: Vec<MPoly<Q>> = c.iter().map(|x| x.partial(0)).collect();
    let m = RuledManifold::new(c, tp(&[1]), vec![cd]).expect("manifold");
    let st = m.structure().expect("structure");
    assert_eq!(
        (st.m, st.dim_a, st.dim_t, st.kind),
        (1, 2, 2, RuledKind::Singular)
    );
    assert!(
        st.params[0].num.is_zero(),
        "the singular point is the curve point (u* = 0)"
    );
    assert!(st.directions.is_empty());
    assert!(exact_hold(st.certificates()));
    let off = m.offset(q(1, 2)).expect("offset");
    assert!(exact_hold(&off.certify()));
    // no reparametrization of the rulings was needed (the normal is constant along them)
    assert_eq!(off.reparametrization()[0].num, var(3, 1));
}

/// §5.5, second example: the non-developable 2-manifold p = c + u g in R⁴ (ċ, g, ġ
/// independent): Case 2 with m = 1, the central (striction) curve, and the unit normal on
/// a reparametrized ruling (Step 2, stereographic projection of (5.25)).
#[test]
fn non_developable_two_manifold_in_r4() {
    let c = vec![tp(&[0, 1]), tp(&[0, 0, 1]), tp(&[0]), tp(&[0])];
    let g = vec![tp(&[0]), tp(&[0]), tp(&[1]), tp(&[0, 1])];
    let m = RuledManifold::new(c, tp(&[1]), vec![g]).expect("manifold");
    let st = m.structure().expect("structure");
    assert_eq!(
        (st.m, st.dim_a, st.dim_t, st.kind),
        (1, 2, 3, RuledKind::Central)
    );
    assert!(exact_hold(st.certificates()));
    let off = m.offset(q(1, 3)).expect("offset");
    assert!(exact_hold(&off.certify()));
    // the f64 path: same structure, certificates within tolerance
    let lf: Vec<MPoly<f64>> = [tp(&[0, 1]), tp(&[0, 0, 1]), tp(&[0]), tp(&[0])]
        .iter()
        .map(to_f64)
        .collect();
    let gf: Vec<MPoly<f64>> = [tp(&[0]), tp(&[0]), tp(&[1]), tp(&[0, 1])]
        .iter()
        .map(to_f64)
        .collect();
    let mf = RuledManifold::new(lf, to_f64(&tp(&[1])), vec![gf]).expect("f64 manifold");
    let sf = mf.structure().expect("f64 structure");
    assert_eq!((sf.m, sf.kind), (1, RuledKind::Central));
    assert!(sf.certificates().iter().all(|c| c.holds && !c.exact));
    let x = Scalar::to_f64(&st.params[0].eval(&[q(1, 2)]).expect("u*"));
    let xf = sf.params[0].eval(&[0.5]).expect("u* f64");
    assert!(close(x, xf), "{x} vs {xf}");
}

/// A ruled 3-manifold (k = 2) in R⁵ and one in R⁴: offsets for k = 2 with certificates.
#[test]
fn ruled_three_manifolds_offsets() {
    // R⁴: l = (t, 0, 0, t²), g₁ = (0, 1, 0, t), g₂ = (0, 0, 1, t²)
    let l = vec![tp(&[0, 1]), tp(&[0]), tp(&[0]), tp(&[0, 0, 1])];
    let g1 = vec![tp(&[0]), tp(&[1]), tp(&[0]), tp(&[0, 1])];
    let g2 = vec![tp(&[0]), tp(&[0]), tp(&[1]), tp(&[0, 0, 1])];
    let m = RuledManifold::new(l, tp(&[1]), vec![g1, g2]).expect("manifold");
    let st = m.structure().expect("structure");
    assert!(exact_hold(st.certificates()));
    let off = m.offset(q(1, 2)).expect("offset in R⁴");
    assert!(exact_hold(&off.certify()));
    // R⁵: l = (0, 0, 0, t², t), g₁ = (1, t, 0, 0, 0), g₂ = (0, 0, 1, t, 0): m = 2, Case 2
    let l = vec![tp(&[0]), tp(&[0]), tp(&[0]), tp(&[0, 0, 1]), tp(&[0, 1])];
    let g1 = vec![tp(&[1]), tp(&[0, 1]), tp(&[0]), tp(&[0]), tp(&[0])];
    let g2 = vec![tp(&[0]), tp(&[0]), tp(&[1]), tp(&[0, 1]), tp(&[0])];
    let m = RuledManifold::new(l, tp(&[1]), vec![g1, g2]).expect("manifold");
    let st = m.structure().expect("structure");
    assert_eq!((st.m, st.kind), (2, RuledKind::Central));
    assert!(exact_hold(st.certificates()));
    let off = m.offset(q(1, 2)).expect("offset in R⁵");
    assert!(exact_hold(&off.certify()));
}

#[test]
fn ruled_errors_are_named() {
    // developable surface of R³ (dim N = 1, normal constant along rulings): not rational
    let c = vec![tp(&[0, 1]), tp(&[0, 0, 1]), tp(&[0, 0, 0, 1])];
    let cd: Vec<MPoly<Q>> = c.iter().map(|x| x.partial(0)).collect();
    let m = RuledManifold::new(c, tp(&[1]), vec![cd]).expect("manifold");
    assert!(matches!(m.offset(q(1, 1)), Err(NdimError::NotRational(_))));
    // cylinder over a parabola in R³ (Case 2, m = 0): |N|² = 4t² + 1, not rational
    let l = vec![tp(&[0, 1]), tp(&[0, 0, 1]), tp(&[0])];
    let cyl = RuledManifold::new(l, tp(&[1]), vec![vec![tp(&[0]), tp(&[0]), tp(&[1])]])
        .expect("cylinder");
    let st = cyl.structure().expect("structure");
    assert_eq!((st.m, st.kind), (0, RuledKind::Central));
    assert!(matches!(
        cyl.offset(q(1, 1)),
        Err(NdimError::NotRational(_))
    ));
    // a fixed plane (every point singular)
    let l = vec![tp(&[0]), tp(&[0]), tp(&[0]), tp(&[0])];
    let plane = RuledManifold::new(
        l,
        tp(&[1]),
        vec![vec![tp(&[1]), tp(&[0]), tp(&[0]), tp(&[0])]],
    )
    .expect("line");
    assert!(matches!(plane.structure(), Err(NdimError::Degenerate(_))));
    // k too large, dependent generators
    let l = vec![tp(&[0]); 3];
    assert!(matches!(
        RuledManifold::new(
            l.clone(),
            tp(&[1]),
            vec![vec![tp(&[1]), tp(&[0]), tp(&[0])]; 2]
        ),
        Err(NdimError::InvalidInput(_))
    ));
    let l4 = vec![tp(&[0]); 4];
    assert!(matches!(
        RuledManifold::new(
            l4,
            tp(&[1]),
            vec![vec![tp(&[1]), tp(&[0]), tp(&[0]), tp(&[0])]; 2]
        ),
        Err(NdimError::InvalidInput(_))
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    /// Random ruled 2-manifolds l + u g in R⁴ with quadratic l and linear g: the structure
    /// and, where a rational unit normal exists over Q, the offset are certified exactly.
    #[test]
    fn random_ruled_two_manifolds_of_r4(
        lc in prop::collection::vec(small(), 12),
        gc in prop::collection::vec(small(), 8),
        (dp, dq) in (1i64..=5, 1i64..=4),
    ) {
        let l: Vec<MPoly<Q>> = (0..4).map(|i| tp(&lc[3 * i..3 * i + 3])).collect();
        let g: Vec<MPoly<Q>> = (0..4).map(|i| tp(&gc[2 * i..2 * i + 2])).collect();
        let Ok(m) = RuledManifold::new(l, tp(&[1]), vec![g]) else {
            prop_assume!(false);
            unreachable!()
        };
        match m.structure() {
            Ok(st) => prop_assert!(exact_hold(st.certificates())),
            Err(NdimError::Degenerate(_)) => {}
            Err(e) => prop_assert!(false, "{e}"),
        }
        match m.offset(q(dp, dq)) {
            Ok(off) => prop_assert!(exact_hold(&off.certify())),
            Err(NdimError::NoRationalPoint(_) | NdimError::Degenerate(_) | NdimError::NotRational(_)) => {}
            Err(e) => prop_assert!(false, "{e}"),
        }
    }
}

// ---------------------------------------------------------------------------------
// Sphere-hypercones (§5.3, Theorem 5.1)
// ---------------------------------------------------------------------------------

use rcagd::ndim::HyperconeEnvelope;
use rcagd::pn::ruled::{ConeFamilyEnvelope, CycleFamily};

/// `p` as a polynomial in the two variables of the 3-D module (t = variable 0).
fn two_var(p: &MPoly<Q>) -> MPoly<Q> {
    &MPoly::zero(2) + p
}

/// For n = 3, Theorem 5.1 is Theorem 4.5: the same isotropic construction, so the same
/// points at the same parameters as the library's cone-family envelope.
#[test]
fn hypercones_in_r3_agree_with_theorem_4_5() {
    // m₁ − m₂ = (1, t, t + 1), r₁ − r₂ = t + 1: |M|² − R² = 1 + t²
    let m1 = vec![tp(&[0, 1]), tp(&[1]), tp(&[0, 0, 1])];
    let r1 = tp(&[1]);
    let m2 = vec![tp(&[-1, 1]), tp(&[1, -1]), tp(&[-1, -1, 1])];
    let r2 = tp(&[0, -1]);
    let Ok(env) = HyperconeEnvelope::new(m1.clone(), r1.clone(), m2.clone(), r2.clone(), None)
    else {
        panic!("n = 3 envelope");
    };
    assert!(exact_hold(&env.certify()));
    let fam = |m: &[MPoly<Q>], r: &MPoly<Q>| {
        CycleFamily::new(
            [two_var(&m[0]), two_var(&m[1]), two_var(&m[2])],
            two_var(r),
            MPoly::constant(2, q(1, 1)),
        )
        .expect("family")
    };
    let three = ConeFamilyEnvelope::new(fam(&m1, &r1), fam(&m2, &r2), Some(env.p().clone()))
        .expect("Theorem 4.5");
    let mut compared = 0;
    let params = [(1, 2, 1, 3), (-2, 1, 3, 4), (5, 3, -1, 1), (1, 7, 2, 1)];
    for (tp_, tq, up, uq) in params {
        let (t, u) = (q(tp_, tq), q(up, uq));
        let a = env.surface().eval_point(&[t.clone(), u.clone()]);
        let b = three.surface().eval(&t, &u);
        if let (Some(a), Ok(b)) = (a, b) {
            assert_eq!(a, b.to_vec());
            compared += 1;
        }
    }
    assert!(compared >= 2, "compared {compared} points");
}

/// A family of hypercones of R⁴: point cycles on the line (t, 0, 0, 0) and spheres of
/// radius 1 about (0, t, 1, 0); |M|² − R² = 2t² = t² + t².
#[test]
fn hypercone_envelope_in_r4_with_offsets() {
    let m1 = vec![tp(&[0, 1]), tp(&[0]), tp(&[0]), tp(&[0])];
    let m2 = vec![tp(&[0]), tp(&[0, 1]), tp(&[1]), tp(&[0])];
    let env = HyperconeEnvelope::new(m1, tp(&[0]), m2, tp(&[1]), None).expect("envelope");
    assert!(exact_hold(&env.certify()));
    assert_eq!(env.surface().num_params(), 3);
    let off = env.surface().offset(&q(1, 3)).expect("offset");
    assert!(exact_hold(&off.certify()));
}

/// The linear case `β = R + Mₙ ≡ 0` of Theorem 5.1 (refused before session 12): `d'(t)` is
/// the hyperplane `M′·y′ = −R`, parametrized linearly; no sum of two squares is needed. Two
/// families of R⁴ (`M = (t, −t, 1, t²)`, `R = −t²`; and the former refusal example
/// `M = (−t, 0, 0, −1)`, `R = 1`) give PN hypersurfaces whose tangent hyperplanes touch
/// both cycle families, exactly, with exact offsets; `f64` certifies too.
#[test]
fn hypercone_linear_case_beta_zero() {
    let m1 = vec![tp(&[0, 1]), tp(&[0]), tp(&[1]), tp(&[0, 0, 1])];
    let m2 = vec![tp(&[0]), tp(&[0, 1]), tp(&[0]), tp(&[0])];
    let env = HyperconeEnvelope::new(m1, tp(&[0]), m2, tp(&[0, 0, 1]), None)
        .expect("the linear case is built");
    assert!(
        exact_hold(&env.certify()),
        "{:#?}",
        env.certify()
            .iter()
            .filter(|c| !c.holds)
            .collect::<Vec<_>>()
    );
    assert!(env.p()[0].num.is_zero() && env.p()[1].num.is_zero());
    let off = env.surface().offset(&Q::from_ratio(1, 2)).expect("offset");
    assert!(exact_hold(&off.certify()));
    let z = || vec![tp(&[0]); 4];
    let m2 = vec![tp(&[0, 1]), tp(&[0]), tp(&[0]), tp(&[1])];
    match HyperconeEnvelope::new(z(), tp(&[0]), m2, tp(&[-1]), None) {
        Ok(env) => assert!(exact_hold(&env.certify())),
        // every hypercone has its vertex at the origin: all tangent hyperplanes pass
        // through it and the envelope point collapses there, a named error
        Err(NdimError::Degenerate(m)) => assert!(m.contains("hypersurface"), "{m}"),
        Err(e) => panic!("unexpected {e}"),
    }
    let mf = |v: &[f64]| {
        MPoly::from_terms(
            1,
            v.iter()
                .enumerate()
                .map(|(k, c)| (vec![k as u32], *c))
                .collect(),
        )
        .expect("one variable")
    };
    let envf = HyperconeEnvelope::new(
        vec![
            mf(&[0.0, 1.0]),
            mf(&[0.0]),
            mf(&[1.0]),
            mf(&[0.0, 0.0, 1.0]),
        ],
        mf(&[0.0]),
        vec![mf(&[0.0]), mf(&[0.0, 1.0]), mf(&[0.0]), mf(&[0.0])],
        mf(&[0.0, 0.0, 1.0]),
        None,
    )
    .expect("f64 linear case");
    assert!(envf.certify().iter().all(|c| c.holds));
}

#[test]
fn hypercone_errors_are_named() {
    let z = || vec![tp(&[0]); 4];
    // cycles in oriented contact for every t: |M|² ≡ R²
    let m2 = vec![tp(&[1]), tp(&[0]), tp(&[0]), tp(&[0])];
    assert!(matches!(
        HyperconeEnvelope::new(z(), tp(&[0]), m2, tp(&[1]), None),
        Err(NdimError::Degenerate(_))
    ));
    // β = R + Mₙ ≡ 0 with M parallel to the last axis: the cycles touch (the linear case
    // has no hyperplane)
    let m2 = vec![tp(&[0]), tp(&[0]), tp(&[0]), tp(&[1])];
    assert!(matches!(
        HyperconeEnvelope::new(z(), tp(&[0]), m2, tp(&[-1]), None),
        Err(NdimError::Degenerate(_))
    ));
    // |M|² − R² = 3 is not a sum of two rational squares
    let m2 = vec![tp(&[1]), tp(&[1]), tp(&[1]), tp(&[0, 1])];
    assert!(matches!(
        HyperconeEnvelope::new(z(), tp(&[0]), m2, tp(&[0, 1]), None),
        Err(NdimError::NoRationalPoint(_))
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    /// Random hypercone families of R⁴ with M = (a, b, 0, d), R = d (so |M|² − R² = a² + b²;
    /// a, b linear, d constant):
    /// the envelope is certified exactly (PN identities and both contacts).
    #[test]
    fn random_hypercone_envelopes_of_r4(
        m1c in prop::collection::vec(small(), 4),
        (r0, r1c) in (small(), small()),
        abd in prop::collection::vec(small(), 6),
    ) {
        let a = tp(&abd[0..2]);
        let b = tp(&abd[2..4]);
        let d = tp(&abd[4..5]); // a constant d keeps the degrees (and the test time) small
        prop_assume!(!d.is_zero() && (!a.is_zero() || !b.is_zero()));
        // constant centres m₁, a linear radius r₁
        let m1: Vec<MPoly<Q>> = (0..4).map(|i| tp(&m1c[i..=i])).collect();
        let r1 = tp(&[r0, r1c]);
        let m2 = vec![&m1[0] - &a, &m1[1] - &b, m1[2].clone(), &m1[3] - &d];
        let r2 = &r1 - &d;
        match HyperconeEnvelope::new(m1, r1, m2, r2, None) {
            Ok(env) => prop_assert!(exact_hold(&env.certify())),
            Err(NdimError::Degenerate(_)) => {}
            Err(e) => prop_assert!(false, "{e}"),
        }
    }
}

// ---------------------------------------------------------------------------------
// Anticaustics (§3.6, (3.18) corrected; Theorem 4.1 and its converse)
// ---------------------------------------------------------------------------------

use rcagd::ndim::{mirror_of, Anticaustic};

/// The parabola y = x² reflects the rays e₂ through its focus (0, 1/4): the anticaustics are
/// the circles about the focus of radius c + 1/4 (the printed (3.18) would not give them).
#[test]
fn anticaustics_of_a_parabola_are_circles_about_the_focus() {
    let t = MPoly::<Q>::var(1, 0);
    let mirror = vec![cst(1, 1), t.clone(), &t * &t];
    for c in [q(0, 1), q(3, 4), q(-1, 8)] {
        let ac = Anticaustic::new(mirror.clone(), 1, c.clone()).expect("anticaustic");
        assert!(exact_hold(&ac.certify()));
        let r = c + q(1, 4);
        for s in [q(0, 1), q(1, 2), q(-3, 1), q(7, 5)] {
            let x = ac
                .surface()
                .eval_point(std::slice::from_ref(&s))
                .expect("point");
            let d2 =
                x[0].clone() * x[0].clone() + (x[1].clone() - q(1, 4)) * (x[1].clone() - q(1, 4));
            assert_eq!(d2, r.clone() * r.clone());
        }
    }
}

/// In R³ the construction agrees with the surface anticaustic of the PN module, and the
/// anticaustic at c + d is its offset at d (∂q/∂c = r).
#[test]
fn anticaustic_in_r3_agrees_with_the_pn_module_and_offsets_by_c() {
    let (u, v) = (var(2, 0), var(2, 1));
    // mirror x₃ = u²/2 + u v − v²/3 + u
    let f = &(&(&(&u * &u).scale(&q(1, 2)) + &(&u * &v)) - &(&v * &v).scale(&q(1, 3))) + &u;
    let mirror = vec![cst(2, 1), u.clone(), v.clone(), f];
    let c = q(1, 2);
    let ac = Anticaustic::new(mirror.clone(), 2, c.clone()).expect("anticaustic");
    assert!(exact_hold(&ac.certify()));
    let arr: [MPoly<Q>; 4] = [
        mirror[0].clone(),
        mirror[1].clone(),
        mirror[2].clone(),
        mirror[3].clone(),
    ];
    let three = rcagd::pn::support::anticaustic(&arr, &c).expect("3-D anticaustic");
    let d = q(2, 3);
    let shifted = Anticaustic::new(mirror, 2, c + d.clone()).expect("shifted");
    let off = ac.surface().offset(&d).expect("offset");
    for (a, b) in [(q(1, 3), q(1, 2)), (q(-1, 1), q(2, 1))] {
        let x = ac
            .surface()
            .eval_point(&[a.clone(), b.clone()])
            .expect("point");
        assert_eq!(x, three.eval(&a, &b).expect("point").to_vec());
        assert_eq!(
            shifted.surface().eval_point(&[a.clone(), b.clone()]),
            off.surface().eval_point(&[a, b])
        );
    }
}

/// A curve mirror in R³ (k = 1): the anticaustic is a surface in (t, v) (a canal surface in
/// line contact with the plane x₃ = c, Theorem 4.1); certified, and a mirror curve in R⁴.
#[test]
fn anticaustics_of_k_dimensional_mirrors() {
    let t = MPoly::<Q>::var(1, 0);
    let curve = vec![cst(1, 1), t.clone(), &t * &t, &(&t * &t) * &t];
    let ac = Anticaustic::new(curve, 1, q(1, 1)).expect("curve mirror in R³");
    assert!(exact_hold(&ac.certify()));
    assert_eq!(ac.surface().num_params(), 2);
    // the reflections of the foot point in all planes through a tangent line: a circle in v
    let x = ac.surface().point_polys();
    assert!(
        x.iter().any(|c| c.degree_in(1).unwrap_or(0) > 0),
        "{:?}",
        x.iter()
            .map(|c| (c.degree_in(0), c.degree_in(1), c.nvars()))
            .collect::<Vec<_>>()
    );
    let curve4 = vec![cst(1, 1), t.clone(), &t * &t, cst(1, 1), &t + &cst(1, 2)];
    let ac4 = Anticaustic::new(curve4, 1, q(0, 1)).expect("curve mirror in R⁴");
    assert!(exact_hold(&ac4.certify()));
    assert_eq!(ac4.surface().num_params(), 3);
}

/// The converse of Theorem 4.1: a PN hypersurface of R⁴ is the anticaustic of the mirror
/// built from it (certified by recomputing the anticaustic from the mirror alone).
#[test]
fn pn_hypersurfaces_are_anticaustics_of_mirrors() {
    let (u1, u2, u3) = (var(3, 0), var(3, 1), var(3, 2));
    let a = [u1.clone(), u2.clone(), u3.clone()];
    let h = RatFn::new(&cst(3, 2) + &(&u1 * &u2), cst(3, 1)).expect("h");
    let s = PnHypersurface::from_support(&a, &cst(3, 1), &h).expect("PN");
    let (ac, cert) = mirror_of(&s, &q(1, 3)).expect("mirror");
    assert!(cert.holds && cert.exact, "{cert:?}");
    assert!(exact_hold(&ac.certify()));
}

#[test]
fn anticaustic_errors_are_named() {
    let t = MPoly::<Q>::var(1, 0);
    assert!(matches!(
        Anticaustic::new(vec![cst(1, 1), t.clone(), t.clone()], 2, q(0, 1)),
        Err(NdimError::InvalidInput(_))
    ));
    assert!(matches!(
        Anticaustic::new(vec![cst(1, 1), cst(1, 2), cst(1, 3)], 1, q(0, 1)),
        Err(NdimError::Degenerate(_))
    ));
    assert!(matches!(
        Anticaustic::new(vec![MPoly::zero(1), t.clone(), t], 1, q(0, 1)),
        Err(NdimError::InvalidInput(_))
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    /// Random quadratic graph mirrors in R⁴: the anticaustic is certified exactly (PN
    /// identities, on the reflected rays).
    #[test]
    fn random_mirrors_in_r4(coeffs in prop::collection::vec(small(), 10), (cp, cq) in (-4i64..=4, 1i64..=3)) {
        let vars = [var(3, 0), var(3, 1), var(3, 2)];
        let mut f = cst(3, coeffs[9]);
        let mut k = 0;
        for i in 0..3 {
            f = &f + &vars[i].scale(&q(coeffs[k], 1));
            k += 1;
            for j in i..3 {
                f = &f + &(&vars[i] * &vars[j]).scale(&q(coeffs[k], 2));
                k += 1;
            }
        }
        let mirror = vec![cst(3, 1), vars[0].clone(), vars[1].clone(), vars[2].clone(), f];
        let ac = Anticaustic::new(mirror, 3, q(cp, cq)).expect("graph mirrors are regular");
        prop_assert!(exact_hold(&ac.certify()));
    }
}
