//! Property tests of the PH module: random small rational quaternion / complex inputs,
//! every certificate must hold exactly, and the `f64` path must agree with the exact one.

use proptest::prelude::*;
use rcagd::ph::dph::{certify_dph_septic, dph_septic, dph_septic_z_roots};
use rcagd::ph::*;
use rcagd_algebra::complex::Complex;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::{Certificate, Poly, Rational, Scalar};

type Q = Rational;

fn rat() -> impl Strategy<Value = Q> {
    (-6i64..=6, 1i64..=3).prop_map(|(p, q)| Q::from(p) / Q::from(q))
}
fn quat() -> impl Strategy<Value = Quaternion<Q>> {
    (rat(), rat(), rat(), rat()).prop_map(|(w, x, y, z)| Quaternion::new(w, x, y, z))
}
fn cplx() -> impl Strategy<Value = Complex<Q>> {
    (rat(), rat()).prop_map(|(a, b)| Complex::new(a, b))
}
fn point() -> impl Strategy<Value = [Q; 3]> {
    (rat(), rat(), rat()).prop_map(|(a, b, c)| [a, b, c])
}
fn nonzero_c(c: &Complex<Q>) -> bool {
    !(c.re == Q::from(0) && c.im == Q::from(0))
}
fn holds_exact(certs: &[Certificate]) -> bool {
    certs.iter().all(|c| c.holds && c.exact)
}
fn holds(certs: &[Certificate]) -> bool {
    certs.iter().all(|c| c.holds)
}
trait ToF {
    fn to_f64_(&self) -> f64;
}
impl ToF for Q {
    fn to_f64_(&self) -> f64 {
        Scalar::to_f64(self)
    }
}
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(b.abs()).max(1.0)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// docs/math/ph-curves.md, "The hodograph and the speed" and "Control points from the quaternion coefficients", "Speed and arc length": control points, σ, arc length certify exactly; f64 agrees.
    #[test]
    fn ph_curve_certifies(coeffs in prop::collection::vec(quat(), 1..5), p0 in point()) {
        prop_assume!(coeffs.iter().any(|a| a.norm_sq() != Q::from(0)));
        let c = PhCurve::new(coeffs, p0).unwrap();
        prop_assert!(holds_exact(&c.certify()));
        prop_assert!(holds_exact(&c.certify_arc_length()));
        prop_assert!(holds_exact(&c.certify_curvature()));
        prop_assert!(holds_exact(&c.euler_rodrigues_frame().certify()));
        let pc = c.to_poly_curve();
        prop_assert!(holds_exact(&pc.certify()));
        // PH test of the power form recovers σ
        let pc2 = PhPolyCurve::from_polynomials(c.position()).unwrap();
        prop_assert_eq!(pc2.speed(), &c.speed());
        // f64 agrees with exact
        let cf = c.to_f64();
        prop_assert!(holds(&cf.certify()));
        for (pe, pf) in c.control_points().iter().zip(cf.control_points()) {
            for k in 0..3 {
                prop_assert!(close(pe[k].to_f64_(), pf[k]));
            }
        }
        prop_assert!(close(c.arc_length().to_f64_(), cf.arc_length()));
        let e = pc.bending_energy();
        let ef = pc.to_f64().bending_energy();
        if let (Ok(e), Ok(ef)) = (e, ef) {
            // f64 pointwise vs exact ρ: agree to 1e-7
            prop_assert!((e - ef).abs() <= 1e-7 * e.abs().max(1.0), "E = {} vs {}", e, ef);
        }
    }

    /// docs/math/ph-curves.md, "Speed and arc length": parameter at arc length (exact bracket) and the constant-feed sampler.
    #[test]
    fn parameter_at_arc_length(coeffs in prop::collection::vec(quat(), 2..4), frac in 0u32..=16) {
        prop_assume!(coeffs.iter().all(|a| a.norm_sq() != Q::from(0)));
        let c = PhCurve::new(coeffs, [Q::from(0), Q::from(0), Q::from(0)]).unwrap();
        let pc = c.to_poly_curve();
        let total = pc.arc_length();
        let target = total.clone() * Q::from(frac as i64) / Q::from(16);
        let tol = Q::from(1) / Q::from(1i64 << 40);
        let p = pc.parameter_at_arc_length(&target, &tol).unwrap();
        let s = pc.arc_length_poly();
        prop_assert!(s.eval(&p.lo) <= target && target <= s.eval(&p.hi));
        prop_assert!(p.hi.clone() - p.lo.clone() <= tol);
        prop_assert!(p.lo <= p.t && p.t <= p.hi);
        let pf = pc.to_f64().parameter_at_arc_length(&target.to_f64_(), &1e-13).unwrap();
        prop_assert!((pf.t - p.t.to_f64_()).abs() < 1e-9);
        let ts = pc.constant_feed_parameters(8, &tol).unwrap();
        prop_assert_eq!(ts.len(), 9);
        for w in ts.windows(2) {
            prop_assert!(w[0] < w[1]);
        }
        prop_assert!(pc.parameter_at_arc_length(&(total + Q::from(1)), &tol).is_err());
    }

    /// Every PH cubic is DPH and a helix (Besednjak §4.1); Frenet certificates hold.
    #[test]
    fn cubics_are_dph_helices(a0 in quat(), a1 in quat()) {
        let c = PhCurve::new(vec![a0, a1], [Q::from(0), Q::from(0), Q::from(0)]).unwrap();
        let pc = c.to_poly_curve();
        match pc.dph_test().unwrap() {
            DphTest::Dph(d) => {
                prop_assert!(holds_exact(&pc.certify_dph(&d)));
                prop_assert!(holds_exact(&pc.frenet_frame(&d).certify()));
                match pc.helix_test().unwrap() {
                    HelixTest::Helix(h) => prop_assert!(holds_exact(&pc.certify_helix(&h))),
                    HelixTest::Planar { .. } | HelixTest::Line => {}
                    HelixTest::NotHelix => prop_assert!(false, "a PH cubic is a helix"),
                }
                // f64 agrees
                prop_assert!(matches!(pc.to_f64().dph_test().unwrap(), DphTest::Dph(_)));
            }
            DphTest::Line => {}
            DphTest::NotDph { .. } => prop_assert!(false, "every PH cubic is DPH"),
        }
    }

    /// docs/math/ph-curves.md, "Helix constructions": helices by reparametrization and/or multiplication certify as helices with
    /// the predicted proportionality polynomial.
    #[test]
    fn helix_constructions(a0 in cplx(), a1 in cplx(), b0 in cplx(), b1 in cplx(),
                           k in 1usize..=3, fg in prop::collection::vec((rat(), rat()), 4),
                           w in prop::collection::vec(cplx(), 1..=3)) {
        let Ok(seed) = LineCircle::new(a0, a1, b0, b1) else { return Ok(()) };
        let f: Vec<Q> = fg.iter().take(k + 1).map(|x| x.0.clone()).collect();
        let g: Vec<Q> = fg.iter().take(k + 1).map(|x| x.1.clone()).collect();
        prop_assume!(w.iter().any(nonzero_c));
        let Ok(curve) = seed.helix(&f, &g, &w, [Q::from(0), Q::from(0), Q::from(0)]) else { return Ok(()) };
        prop_assert!(holds_exact(&curve.certify()));
        prop_assert!(holds_exact(&seed.certify_helix_construction(&curve, &f, &g, &w).unwrap()));
        prop_assert_eq!(curve.proportionality(), seed.predicted_proportionality(&f, &g, &w));
        let pc = curve.to_poly_curve();
        match pc.helix_test().unwrap() {
            HelixTest::Helix(h) => {
                prop_assert!(holds_exact(&pc.certify_helix(&h)));
                let d = pc.dph().unwrap();
                prop_assert!(holds_exact(&pc.certify_dph(&d)));
                // f64 agrees
                if let Ok(HelixTest::Helix(hf)) = pc.to_f64().helix_test() {
                    prop_assert!(close(hf.tan2_psi(), h.tan2_psi().to_f64_()) || h.tan2_psi().to_f64_().abs() > 1e6);
                }
            }
            HelixTest::Planar { .. } | HelixTest::Line => {}
            HelixTest::NotHelix => prop_assert!(false, "constructed helix fails the axis test"),
        }
        if w.len() == 1 && k == 1 {
            // cubic helix (up to the constant w)
            prop_assert!(curve.preimage_degree() == 1);
        }
    }

    /// Quintic helix recognition (Besednjak §6.2): reparametrization → general,
    /// multiplication → monotone with 4c_0c_2 = 1.
    #[test]
    fn quintic_helix_recognition(a0 in cplx(), a1 in cplx(), b0 in cplx(), b1 in cplx(),
                                 f in prop::collection::vec(rat(), 3), g in prop::collection::vec(rat(), 3),
                                 w in prop::collection::vec(cplx(), 2)) {
        let Ok(seed) = LineCircle::new(a0, a1, b0, b1) else { return Ok(()) };
        if let Ok(c) = seed.reparametrized_helix(&f, &g, [Q::from(0), Q::from(0), Q::from(0)]) {
            prop_assert!(c.coefficients_in_real_plane());
            match c.quintic_helix_kind().unwrap() {
                QuinticHelixKind::General { .. } | QuinticHelixKind::Both { .. } => {}
                QuinticHelixKind::Monotone { .. } => {}
                QuinticHelixKind::NotHelical => {
                    // only when A_0, A_2 are dependent
                    let a = c.coefficients();
                    let ratio_dependent = (0..4).all(|_| true) && (a[0].norm_sq() == Q::from(0) || a[2].norm_sq() == Q::from(0) || {
                        let x = a[0].dot(&a[2]);
                        x.clone() * x == a[0].norm_sq() * a[2].norm_sq()
                    });
                    prop_assert!(ratio_dependent);
                }
            }
            prop_assert!(!matches!(c.quintic_dph_kind().unwrap(), QuinticDphKind::NotDph));
        }
        prop_assume!(w.iter().all(nonzero_c));
        if let Ok(c) = seed.multiplied_helix(&w, [Q::from(0), Q::from(0), Q::from(0)]) {
            match c.quintic_helix_kind().unwrap() {
                QuinticHelixKind::Monotone { c0, c2 } | QuinticHelixKind::Both { monotone: (c0, c2), .. } => {
                    let p = c0 * c2;
                    prop_assert_eq!(p, Complex::new(Q::from(1) / Q::from(4), Q::from(0)));
                }
                k => prop_assert!(false, "multiplication helix not recognised: {:?}", k),
            }
            prop_assert!(matches!(c.quintic_dph_kind().unwrap(), QuinticDphKind::Monotone | QuinticDphKind::Both));
        }
    }
}

proptest! {
    // septic constructions with exact certificates of degree-12 identities: fewer cases
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// docs/math/ph-curves.md, "Septic DPH constructor": septic DPH curves (st h = 0, st w = 2 and st h = 2, st w = 1, whose roots are
    /// always rational) certify; the classification finds the degrees of h and w.
    #[test]
    fn septic_dph_constructor(w2 in prop::collection::vec(cplx(), 3), h2 in prop::collection::vec(rat(), 3),
                              w1 in prop::collection::vec(cplx(), 2),
                              al0 in cplx(), al1 in cplx(), be0 in cplx(), which in 0usize..2) {
        prop_assume!(nonzero_c(&al0));
        for (h, w) in [(vec![Q::from(1)], w2.clone()), (h2.clone(), w1.clone())] {
            let Ok(roots) = dph_septic_z_roots(&h, &w) else { continue };
            let z = &roots[which];
            let Ok(c) = dph_septic(&h, &w, &al0, &al1, &be0, z, [Q::from(0), Q::from(0), Q::from(0)]) else { continue };
            prop_assert!(holds_exact(&c.certify()));
            prop_assert!(holds_exact(&certify_dph_septic(&c, &h, &w).unwrap()));
            let pc = c.to_poly_curve();
            match pc.dph_test().unwrap() {
                DphTest::Dph(d) => {
                    prop_assert!(holds_exact(&pc.certify_dph(&d)));
                    prop_assert!(holds_exact(&pc.frenet_frame(&d).certify()));
                    // f64 agrees unless the problem is ill-conditioned: ρ = |r''|² − σ'²
                    // cancels to ~1e-12 of |r''|² for some septics with large coefficients
                    // (found by proptest), below what f64 power-basis arithmetic resolves;
                    // there the f64 test answers `Line` or `NotDph`
                    if !matches!(pc.to_f64().dph_test().unwrap(), DphTest::Dph(_)) {
                        let r2 = pc.position().clone().map(|x| x.derivative().derivative());
                        let s2 = r2.iter().fold(Poly::zero(), |a, x| &a + &(x * x));
                        let scale = |p: &Poly<Q>| p.coeffs().iter().map(|c| Scalar::to_f64(c).abs()).fold(0.0, f64::max);
                        let rel = scale(&pc.rho().unwrap()) / scale(&s2);
                        prop_assert!(rel <= 1e-9, "f64 DPH test disagrees on a well-conditioned curve: ρ/|r''|² = {:e}", rel);
                    }
                }
                DphTest::Line => {}
                DphTest::NotDph { .. } => prop_assert!(false, "septic constructor gave a non-DPH curve"),
            }
            if let Ok(Some(fac)) = c.proportionality_factors() {
                prop_assert!(holds_exact(&c.certify_proportionality(&fac)));
            }
        }
    }
}

proptest! {
    // each exact Hermite solve isolates the roots of a quartic over Q(√m) by Sturm
    // sequences (≈ 0.2 s per case in the test profile): fewer cases
    #![proptest_config(ProptestConfig::with_cases(16))]

    /// docs/math/ph-curves.md, "Hermite interpolation by helical PH quintics": Hermite data sampled from a random rational general helical quintic are
    /// interpolated; the original curve is among the (exact) interpolants, every
    /// certificate holds, and the f64 path finds the same energies.
    #[test]
    fn hermite_recovers_helical_quintic(a0 in quat(), a2 in quat(), c0 in rat(), c2 in rat(), p0 in point()) {
        prop_assume!(a0.norm_sq() != Q::from(0) && a2.norm_sq() != Q::from(0));
        let a1 = a0.scale(&c0) + a2.scale(&c2);
        let curve = PhCurve::new(vec![a0, a1, a2], p0).unwrap();
        let pts = curve.control_points();
        let five = Q::from(5);
        let d_s = [0, 1, 2].map(|k| (pts[1][k].clone() - pts[0][k].clone()) * five.clone());
        let d_f = [0, 1, 2].map(|k| (pts[5][k].clone() - pts[4][k].clone()) * five.clone());
        let data = HermiteData::new(pts[0].clone(), d_s, pts[5].clone(), d_f);
        let k0 = c0.clone() + Q::from(3) / Q::from(4);
        let k2 = c2.clone() + Q::from(3) / Q::from(4);
        let continuum = k0 * k2 * Q::from(16) == Q::from(5);
        let sol = match data.solve_exact() {
            // k_0k_2 = 5/16 (r_3 = 0): X is undetermined, a one-parameter family
            Err(PhError::Degenerate(_)) if continuum => return Ok(()),
            Ok(s) if continuum => {
                prop_assert!(s.continuum.is_some());
                return Ok(());
            }
            Ok(s) => s,
            Err(PhError::ParallelEndTangents(_)) | Err(PhError::CoincidentEndPoints(_)) => return Ok(()),
            Err(e) => return Err(TestCaseError::fail(format!("{e}"))),
        };
        let found = sol.interpolants.iter().any(|i| i.exact_control_points.as_ref() == Some(&pts));
        prop_assert!(found, "the original quintic is not among the interpolants");
        for c in sol.certify() {
            prop_assert!(c.holds || !c.exact, "{}", c);
        }
        prop_assert!(sol.interpolants.len() % 2 == 0 && sol.interpolants.len() <= 8);
        prop_assert!(!sol.best().is_empty());
        // the f64 path finds the original curve too
        let sf = data.solve_f64().unwrap();
        let near = |i: &HermiteInterpolant| {
            i.curve.control_points().iter().zip(&pts).all(|(a, b)| {
                (0..3).all(|k| (a[k] - b[k].to_f64_()).abs() <= 1e-6 * b[k].to_f64_().abs().max(1.0))
            })
        };
        prop_assert!(sf.interpolants.iter().any(near), "f64 path misses the original quintic");
    }
}

/// Regression (proptest case `00a2ee4…`): a septic whose speed has roots close to the real
/// axis (`σ` roots `0.1404 ± 0.0866i`, `0.8089 ± 0.0827i`), so `ρ/σ³` has two sharp
/// peaks. The reference `E = 86.335087778953805012…` was computed independently with
/// mpmath (`quad` at 30 digits on the exact `ρ/σ³`, identical with 50 sub-intervals).
#[test]
fn bending_energy_near_singular_speed() {
    let q = |w: Q, x: Q, y: Q, z: Q| Quaternion::new(w, x, y, z);
    let r = |p: i64, d: i64| Q::from(p) / Q::from(d);
    let c = PhCurve::new(
        vec![
            q(r(2, 3), r(0, 1), r(1, 3), r(4, 1)),
            q(r(2, 1), r(-3, 1), r(0, 1), r(-6, 1)),
            q(r(0, 1), r(-1, 1), r(-1, 1), r(0, 1)),
            q(r(0, 1), r(2, 1), r(0, 1), r(0, 1)),
        ],
        [Q::from(0), Q::from(0), Q::from(0)],
    )
    .unwrap();
    let pc = c.to_poly_curve();
    let exact = pc.bending_energy_with_error(0.0, 1.0).unwrap();
    let float = pc.to_f64().bending_energy_with_error(0.0, 1.0).unwrap();
    let truth = 86.335_087_778_953_8;
    for e in [exact, float] {
        assert!((e.value - truth).abs() <= 1e-11 * truth, "E = {e:?}");
        assert!(e.error <= 1e-12 * truth, "error estimate {e:?}");
    }
    // a curve through a cusp (σ(1/2) = 0): the energy diverges, reported as an error
    let cusp = PhCurve::new(
        vec![
            q(r(1, 1), r(0, 1), r(0, 1), r(0, 1)),
            q(r(-1, 1), r(0, 1), r(0, 1), r(0, 1)),
        ],
        [Q::from(0), Q::from(0), Q::from(0)],
    )
    .unwrap();
    assert!(matches!(
        cusp.to_poly_curve().bending_energy(),
        Err(PhError::Degenerate(_))
    ));
}

/// Known defect (found by `helix_constructions` with a random seed): the f64 helix test
/// loses seven digits on this septic helix (tan²ψ = 37 exactly, 36.99999988 in f64): the
/// axis comes from an elimination on power-basis coefficients. Run with `--ignored`;
/// remove the `ignore` when the f64 axis solve is made stable (least squares / refinement).
#[test]
#[ignore = "known f64 accuracy defect of the helix axis solve"]
fn f64_helix_axis_of_a_septic_helix() {
    let q = |n: i64, d: i64| Q::from_parts_signed(n.into(), d.into());
    let c = |a: Q, b: Q| Complex::new(a, b);
    let seed = LineCircle::new(
        c(q(2, 1), q(0, 1)),
        c(q(-6, 1), q(0, 1)),
        c(q(0, 1), q(-2, 1)),
        c(q(1, 1), q(0, 1)),
    )
    .expect("a line/circle seed");
    let f = vec![q(-6, 1), q(-1, 2)];
    let g = vec![q(-1, 2), q(0, 1)];
    let w = vec![
        c(q(-2, 3), q(0, 1)),
        c(q(2, 3), q(-2, 1)),
        c(q(0, 1), q(2, 1)),
    ];
    let curve = seed
        .helix(&f, &g, &w, [Q::from(0), Q::from(0), Q::from(0)])
        .expect("a helix");
    let pc = curve.to_poly_curve();
    let HelixTest::Helix(h) = pc.helix_test().expect("test") else {
        panic!("the exact curve is a helix")
    };
    assert_eq!(h.tan2_psi(), Q::from(37));
    let Ok(HelixTest::Helix(hf)) = pc.to_f64().helix_test() else {
        panic!("the f64 curve is a helix")
    };
    assert!(close(hf.tan2_psi(), 37.0), "{}", hf.tan2_psi());
}

fn cpoly(cs: Vec<Complex<Q>>) -> Poly<Complex<Q>> {
    Poly::new(cs)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Besednjak Lemma 7.2 on random cubic preimages α = γα̃, β = γβ̃ with a common
    /// linear factor: the reduced Wronskian is never a constant times a square, and a DPH
    /// curve among them never has h constant (st h = 0).
    #[test]
    fn lemma_7_2_on_random_preimages(g0 in cplx(), a in (cplx(), cplx(), cplx()), b in (cplx(), cplx(), cplx())) {
        let gamma = cpoly(vec![g0, Complex::from_real(Q::from(1))]);
        let at = cpoly(vec![a.0, a.1, a.2]);
        let bt = cpoly(vec![b.0, b.1, b.2]);
        prop_assume!(at.degree() == Some(2) || bt.degree() == Some(2));
        let alpha = &gamma * &at;
        let beta = &gamma * &bt;
        let ab = rcagd_algebra::bernstein::to_bernstein(&alpha, 3).unwrap();
        let bb = rcagd_algebra::bernstein::to_bernstein(&beta, 3).unwrap();
        let curve = PhCurve::from_hopf(&ab, &bb, [Q::from(0), Q::from(0), Q::from(0)]).unwrap();
        match rcagd::ph::dph_criteria::lemma_7_2(&curve) {
            Ok(l) => {
                prop_assert!(l.certify().holds, "{}", l.certify());
                if let Ok(Some(f)) = curve.proportionality_factors() {
                    prop_assert!(f.h.degree().unwrap_or(0) > 0, "DPH with r = 1 and h constant");
                }
            }
            // α̃, β̃ share a factor too (r ≥ 2)
            Err(PhError::DegreeMismatch(_)) => prop_assert!(at.gcd(&bt).degree().unwrap_or(0) > 0 || at.is_zero() || bt.is_zero()),
            Err(e) => return Err(TestCaseError::fail(format!("{e}"))),
        }
    }

    /// Besednjak Lemma 7.5 with random Gaussian-rational data: the linear-system decision
    /// agrees with the lemma's prediction (and the circle found is certified).
    #[test]
    fn lemma_7_5_on_random_data(a1 in cplx(), a2 in cplx(), b1 in cplx(), b2 in cplx(), t1 in cplx(), t2 in cplx(), m in 1u32..=3, kind in 0usize..3) {
        use rcagd::ph::generalized_circle::lemma_7_5;
        let t2 = match kind {
            0 => Complex::from_real(t2.re),          // with t1 real below: both real
            1 => t1.conj(),                           // conjugate pair
            _ => t2,                                  // general
        };
        let t1 = if kind == 0 { Complex::from_real(t1.re) } else { t1 };
        match lemma_7_5([&a1, &a2], [&b1, &b2], [&t1, &t2], m) {
            Ok(l) => {
                for c in l.certify() {
                    prop_assert!(c.holds && c.exact, "{}", c);
                }
            }
            Err(PhError::Degenerate(_)) => {}
            Err(e) => return Err(TestCaseError::fail(format!("{e}"))),
        }
    }
}
