//! Queries of the Laguerre/Möbius models (Peternell, *Rational Parametrizations for
//! Envelopes of Quadric Families*, §2.4, §3.1–§3.5): a cycle or plane in every model and
//! back, the isotropic-model function of a quadric, the cycles of a Laguerre map.
//! Expected values are computed by hand in the comments.

use proptest::prelude::*;
use rcagd::laguerre::query::*;
use rcagd::laguerre::{Cycle, LaguerreError, LaguerreMap, OrientedPlane};
use rcagd::Certified;
use rcagd_algebra::{Certificate, Rational, Scalar};

type Q = Rational;

fn r(n: i64) -> Q {
    Q::from(n)
}
fn q(n: i64, d: i64) -> Q {
    Q::from_ratio(n, d)
}
fn assert_all(certs: &[Certificate]) {
    assert!(!certs.is_empty());
    for c in certs {
        assert!(c.holds, "{c}");
    }
}

#[test]
fn a_cycle_in_every_model() {
    // (m; r) = ((1, 2, 3); 4): α = −(r + m3)/2 = −7/2, β = (−1, −2), γ = −(r − m3)/2 = −1/2
    // (3.12); Möbius: |m|² − r² = −2, p = (−1/2, 1, 2, 3, −3/2) (p₀ − p₄ = 1).
    let c = Cycle::new([r(1), r(2), r(3)], r(4)).unwrap();
    let m = cycle_models(&c);
    assert_eq!(m.cyclographic, [r(1), r(2), r(3), r(4)]);
    assert_eq!(m.blaschke_hyperplane, [r(4), r(1), r(2), r(3), r(1)]);
    assert_eq!(m.isotropic_sphere.alpha, q(-7, 2));
    assert_eq!(m.isotropic_sphere.beta, [r(-1), r(-2)]);
    assert_eq!(m.isotropic_sphere.gamma, q(-1, 2));
    assert_eq!(m.mobius, [q(-1, 2), r(1), r(2), r(3), q(-3, 2)]);
    assert_all(&m.certify());
    // back from the Möbius point: both orientations
    let back = cycles_from_mobius(&m.mobius).unwrap();
    assert_eq!(
        back,
        vec![c.clone(), Cycle::new([r(1), r(2), r(3)], r(-4)).unwrap()]
    );
    assert_eq!(
        cycle_from_blaschke(&m.blaschke_hyperplane.clone().map(|x| x * r(3))).unwrap(),
        c
    );
    // a point cycle
    let p = cycle_models(&Cycle::point([r(1), r(0), r(-2)]));
    assert_all(&p.certify());
    assert_eq!(
        cycles_from_mobius(&p.mobius).unwrap(),
        vec![Cycle::point([r(1), r(0), r(-2)])]
    );
}

#[test]
fn mobius_errors_are_named() {
    // r² = 2: (|m|² − 2 ± 1)/2 with m = 0
    let p = [q(-1, 2), r(0), r(0), r(0), q(-3, 2)];
    assert!(
        matches!(cycles_from_mobius(&p), Err(LaguerreError::Degenerate(m)) if m.contains("r² = 2"))
    );
    // p₀ = p₄: a plane
    assert!(
        matches!(cycles_from_mobius(&[r(1), r(1), r(0), r(0), r(1)]), Err(LaguerreError::Degenerate(m)) if m.contains("plane"))
    );
    // inside Q: imaginary sphere
    assert!(
        matches!(cycles_from_mobius(&[r(1), r(0), r(0), r(0), r(0)]), Err(LaguerreError::Degenerate(m)) if m.contains("imaginary"))
    );
    assert!(cycle_from_blaschke(&[r(1), r(0), r(0), r(0), r(0)]).is_err());
}

#[test]
fn a_plane_in_every_model() {
    // n = (2, 3, 6)/7, e0 = 5/3: Λ(e) = (2/7, 3/7, 5/3)/(1/7) = (2, 3, 35/3) (3.11);
    // Λ*(e) = (5/3, 2/7, 3/7, −1/7) (3.16); Möbius (−5/3, 2/7, 3/7, 6/7, −5/3).
    let e = OrientedPlane::new(q(5, 3), [q(2, 7), q(3, 7), q(6, 7)]).unwrap();
    let m = plane_models(&e);
    assert_eq!(m.isotropic, Some([r(2), r(3), q(35, 3)]));
    assert_eq!(
        m.dual_isotropic,
        Some([q(5, 3), q(2, 7), q(3, 7), q(-1, 7)])
    );
    assert_eq!(m.mobius, [q(-5, 3), q(2, 7), q(3, 7), q(6, 7), q(-5, 3)]);
    assert_eq!(m.blaschke, [r(1), q(2, 7), q(3, 7), q(6, 7), q(5, 3)]);
    assert_all(&m.certify());
    let up = plane_models(&OrientedPlane::new(r(1), [r(0), r(0), r(1)]).unwrap());
    assert!(up.isotropic.is_none() && up.dual_isotropic.is_none());
    assert_all(&up.certify());
}

fn sphere_matrix(m: [Q; 3], rad: Q) -> [[Q; 4]; 4] {
    let mm = m.iter().fold(r(0), |s, x| s + x.clone() * x.clone()) - rad.clone() * rad;
    [
        [mm, -m[0].clone(), -m[1].clone(), -m[2].clone()],
        [-m[0].clone(), r(1), r(0), r(0)],
        [-m[1].clone(), r(0), r(1), r(0)],
        [-m[2].clone(), r(0), r(0), r(1)],
    ]
}

#[test]
fn isotropic_function_of_a_sphere_has_the_two_isotropic_spheres_as_branches() {
    // |x − m|² = r²: A ≠ 0 (not rational as one function), but both oriented cycles
    // (m; ±r) give isotropic spheres F± with A F² + B F + C ≡ 0 (Lemma 3.1).
    let m = [r(1), r(-2), q(1, 2)];
    let iq = isotropic_quadric(&sphere_matrix(m.clone(), r(3))).unwrap();
    assert!(iq.rational.is_none());
    assert_ne!(iq.a, r(0));
    assert_all(&iq.certify());
    // B² − 4AC is a square: the branches are the isotropic spheres of (m; ±3)
    let [fp, fm] = iq.branches().expect("rational branches");
    let sp = Cycle::new(m.clone(), r(3)).unwrap().isotropic_sphere();
    let sm = Cycle::new(m.clone(), r(-3)).unwrap().isotropic_sphere();
    for (y1, y2) in [(0, 0), (1, 2), (-3, 1), (2, -5)] {
        let (y1, y2) = (q(y1, 3), q(y2, 2));
        let got = [
            fp.eval(&[y1.clone(), y2.clone()]).unwrap(),
            fm.eval(&[y1.clone(), y2.clone()]).unwrap(),
        ];
        let want = [sp.eval(&y1, &y2), sm.eval(&y1, &y2)];
        assert!(
            got == want || got == [want[1].clone(), want[0].clone()],
            "{got:?} vs {want:?}"
        );
    }
    // a triaxial ellipsoid x² + y²/4 + z²/9 = 1: B² − 4AC is no square
    let e = [
        [r(-1), r(0), r(0), r(0)],
        [r(0), r(1), r(0), r(0)],
        [r(0), r(0), q(1, 4), r(0)],
        [r(0), r(0), r(0), q(1, 9)],
    ];
    let ie = isotropic_quadric(&e).unwrap();
    assert!(ie.branches().is_none() && ie.rational.is_none());
    assert_all(&ie.certify());
    for sign in [1, -1] {
        let s = Cycle::new(m.clone(), r(3 * sign))
            .unwrap()
            .isotropic_sphere();
        for (y1, y2) in [(0, 0), (1, 2), (-3, 1), (2, -5)] {
            let (y1, y2) = (q(y1, 3), q(y2, 2));
            let f = s.eval(&y1, &y2);
            let b = iq.b.eval(&[y1.clone(), y2.clone()]).unwrap();
            let c = iq.c.eval(&[y1, y2]).unwrap();
            assert_eq!(iq.a.clone() * f.clone() * f.clone() + b * f + c, r(0));
        }
    }
}

#[test]
fn isotropic_function_of_a_paraboloid_is_rational() {
    // z = x² + y²: x² + y² − wz = 0. Tangent plane at (2/3, 0, 4/9) with normal
    // (4/5, 0, −3/5) = Λ⁻¹-normal of (y1, y2) = (1/2, 0): e0 = −4/15, y3 = e0(S+1)/2 = −1/6.
    // At (0, 0) the plane z = 0 with normal (0, 0, −1): F(0, 0) = 0.
    let qm = [
        [r(0), r(0), r(0), q(-1, 2)],
        [r(0), r(1), r(0), r(0)],
        [r(0), r(0), r(1), r(0)],
        [q(-1, 2), r(0), r(0), r(0)],
    ];
    let iq = isotropic_quadric(&qm).unwrap();
    assert_eq!(iq.a, r(0));
    let f = iq.rational.clone().unwrap();
    assert_eq!(f.eval(&[q(1, 2), r(0)]), Some(q(-1, 6)));
    assert_eq!(f.eval(&[r(0), r(0)]), Some(r(0)));
    assert_all(&iq.certify());
    // a cone is refused
    let cone = [
        [r(0), r(0), r(0), r(0)],
        [r(0), r(1), r(0), r(0)],
        [r(0), r(0), r(1), r(0)],
        [r(0), r(0), r(0), r(-1)],
    ];
    assert!(matches!(
        isotropic_quadric(&cone),
        Err(LaguerreError::Degenerate(_))
    ));
}

#[test]
fn cycles_of_laguerre_maps() {
    // x ↦ 2x: (1, 2, 3; 4) ↦ (2, 4, 6; 8), the only fixed cycle is (0, 0, 0; 0)
    let c = Cycle::new([r(1), r(2), r(3)], r(4)).unwrap();
    let sim = LaguerreMap::similarity(r(2)).unwrap();
    let lc = laguerre_cycles(&sim, std::slice::from_ref(&c));
    assert_eq!(
        lc.images[0].1,
        Cycle::new([r(2), r(4), r(6)], r(8)).unwrap()
    );
    assert_eq!(lc.fixed, Some(Cycle::point([r(0), r(0), r(0)])));
    assert!(lc.fixed_directions.is_empty());
    assert_all(&lc.certify());
    // the dilatation by 1/2 (offset): r ↦ r + 1/2, no fixed cycle, λA = I fixes every direction
    let dil = LaguerreMap::dilatation(q(1, 2));
    let lc = laguerre_cycles(&dil, std::slice::from_ref(&c));
    assert_eq!(
        lc.images[0].1,
        Cycle::new([r(1), r(2), r(3)], q(9, 2)).unwrap()
    );
    assert!(lc.fixed.is_none());
    assert_eq!(lc.fixed_directions.len(), 4);
    assert_all(&lc.certify());
    // a boost along x: fixes the cycles with m₁ = r = 0 (a plane of fixed points)
    let b = LaguerreMap::boost(0, q(1, 3)).unwrap();
    let lc = laguerre_cycles(&b, &[c]);
    assert_eq!(lc.fixed_directions.len(), 2);
    assert!(lc.fixed.is_some());
    assert_all(&lc.certify());
}

fn small() -> impl Strategy<Value = i64> {
    -6i64..=6
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Random cycles and planes: every model certified, f64 agrees with exact.
    #[test]
    fn random_models(m in proptest::array::uniform3(small()), rad in small(), a in small(), b in small(), e0 in small()) {
        let c = Cycle::new(m.map(r), r(rad)).unwrap();
        let cm = cycle_models(&c);
        for x in cm.certify() { prop_assert!(x.holds, "{}", x); }
        let cf = Cycle::new(m.map(|x| x as f64), rad as f64).unwrap();
        let cmf = cycle_models(&cf);
        for x in cmf.certify() { prop_assert!(x.holds, "{}", x); }
        for i in 0..5 { prop_assert!((cmf.mobius[i] - Scalar::to_f64(&cm.mobius[i])).abs() < 1e-9); }
        let e = OrientedPlane::from_isotropic(&[q(a, 2), q(b, 3), r(e0)]);
        let pm = plane_models(&e);
        for x in pm.certify() { prop_assert!(x.holds, "{}", x); }
        let y = pm.isotropic.clone().unwrap();
        prop_assert_eq!(y, [q(a, 2), q(b, 3), r(e0)]);
    }

    /// Random spheres: both isotropic spheres solve the quadratic of the isotropic model.
    #[test]
    fn random_sphere_isotropic_function(m in proptest::array::uniform3(small()), rad in 1i64..=5, y1 in small(), y2 in small()) {
        let iq = isotropic_quadric(&sphere_matrix(m.map(r), r(rad))).unwrap();
        for x in iq.certify() { prop_assert!(x.holds, "{}", x); }
        let s = Cycle::new(m.map(r), r(rad)).unwrap().isotropic_sphere();
        let (y1, y2) = (r(y1), r(y2));
        let f = s.eval(&y1, &y2);
        let b = iq.b.eval(&[y1.clone(), y2.clone()]).unwrap();
        let c = iq.c.eval(&[y1, y2]).unwrap();
        prop_assert_eq!(iq.a.clone() * f.clone() * f.clone() + b * f + c, r(0));
    }

    /// Random similarities with translation and dilatation: images certified (contact
    /// preserved), the fixed cycle fixed, f64 images agree with exact ones.
    #[test]
    fn random_laguerre_cycles(lam in 2i64..=4, t in proptest::array::uniform3(small()), d in small(), c in proptest::array::uniform4(small())) {
        let map = LaguerreMap::similarity(r(lam)).unwrap()
            .compose(&LaguerreMap::translation(t.map(r)))
            .compose(&LaguerreMap::dilatation(r(d)));
        let cyc = Cycle::new([r(c[0]), r(c[1]), r(c[2])], r(c[3])).unwrap();
        let lc = laguerre_cycles(&map, std::slice::from_ref(&cyc));
        for x in lc.certify() { prop_assert!(x.holds, "{}", x); }
        prop_assert!(lc.fixed.is_some());
        let mapf = LaguerreMap::similarity(lam as f64).unwrap()
            .compose(&LaguerreMap::translation(t.map(|x| x as f64)))
            .compose(&LaguerreMap::dilatation(d as f64));
        let cf = Cycle::new([c[0] as f64, c[1] as f64, c[2] as f64], c[3] as f64).unwrap();
        let lf = laguerre_cycles(&mapf, std::slice::from_ref(&cf));
        for x in lf.certify() { prop_assert!(x.holds, "{}", x); }
        let (e, f) = (lc.images[0].1.to_cyclographic(), lf.images[0].1.to_cyclographic());
        for i in 0..4 { prop_assert!((Scalar::to_f64(&e[i]) - f[i]).abs() < 1e-9); }
    }
}
