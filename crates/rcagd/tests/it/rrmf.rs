//! Rational rotation-minimizing frames and twist-free sweeps (`rcagd::ph::rrmf`,
//! `rcagd::ph::sweep`; docs/math/rrmf.md): the published facts reproduced (Han 2008: a
//! non-planar PH cubic has no rational RMF, a planar PH curve's ERF is its RMF), random
//! RRMF quintics from the quintic condition certify exactly, `f64` agrees with the exact
//! frame, non-RRMF curves are refused with `PhError::NotRrmf`, sweeps certify.

use proptest::prelude::*;
use rcagd::ph::rrmf::{
    erf_twist_numerator, is_rrmf_quintic_class1, quintic_class1_residual, rrmf_quintic_class1,
    RationalRmf,
};
use rcagd::ph::sweep::sweep_profile;
use rcagd::ph::{PhCurve, PhError};
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::{Certificate, Rational, Scalar};

type Q = Rational;

fn q(p: i64, d: i64) -> Q {
    Q::from(p) / Q::from(d)
}
fn qt(a: [i64; 4]) -> Quaternion<Q> {
    Quaternion::new(Q::from(a[0]), Q::from(a[1]), Q::from(a[2]), Q::from(a[3]))
}
fn origin() -> [Q; 3] {
    [Q::from(0), Q::from(0), Q::from(0)]
}
fn holds_exact(certs: &[Certificate]) -> bool {
    certs.iter().all(|c| c.holds && c.exact)
}
fn failing(certs: &[Certificate]) -> Vec<String> {
    certs
        .iter()
        .filter(|c| !c.holds)
        .map(|c| c.to_string())
        .collect()
}

/// A fixed RRMF quintic of the generator: `A_0 = 1 + j`, `A_1 = i + k`, `x = 1`.
fn sample_rrmf() -> PhCurve<Q> {
    rrmf_quintic_class1(qt([1, 0, 1, 0]), qt([0, 1, 0, 1]), Q::from(1), origin()).unwrap()
}

#[test]
fn generated_quintic_satisfies_condition_and_certifies() {
    let c = sample_rrmf();
    assert!(quintic_class1_residual(&c)
        .unwrap()
        .iter()
        .all(|x| *x == Q::from(0)));
    assert!(is_rrmf_quintic_class1(&c).unwrap());
    let rmf = RationalRmf::new(&c).unwrap();
    let certs = rmf.certify();
    assert!(holds_exact(&certs), "{:?}", failing(&certs));
    // class I: |w|² ∝ σ, so w is quadratic
    assert!(
        rmf.rotation
            .0
            .degree()
            .unwrap_or(0)
            .max(rmf.rotation.1.degree().unwrap_or(0))
            <= 2
    );
    // the frame is unit and orthogonal to the tangent at a parameter
    let [t, f1, f2] = rmf.eval(&q(1, 3)).unwrap();
    let dot = |a: &[Q; 3], b: &[Q; 3]| {
        a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() + a[2].clone() * b[2].clone()
    };
    assert_eq!(dot(&t, &f1), Q::from(0));
    assert_eq!(dot(&f1, &f2), Q::from(0));
    assert_eq!(dot(&f2, &f2), Q::from(1));
}

/// Han 2008, "Nonexistence of rational rotation-minimizing frames on cubic curves": a
/// non-planar PH cubic has no rational RMF.
#[test]
fn nonplanar_cubic_is_refused() {
    let c = PhCurve::new(vec![qt([1, 0, 0, 0]), qt([1, 1, 0, 1])], origin()).unwrap();
    assert!(!erf_twist_numerator(&c).is_zero());
    assert!(matches!(RationalRmf::new(&c), Err(PhError::NotRrmf(_))));
}

/// A planar PH curve (`A = u + q k`, `r'` in the `xy`-plane) has `N ≡ 0`: its ERF is
/// rotation-minimizing, `w = 1`.
#[test]
fn planar_curve_erf_is_rmf() {
    let c = PhCurve::new(
        vec![qt([1, 0, 0, 2]), qt([3, 0, 0, -1]), qt([2, 0, 0, 1])],
        origin(),
    )
    .unwrap();
    assert!(erf_twist_numerator(&c).is_zero());
    let rmf = RationalRmf::new(&c).unwrap();
    assert_eq!(rmf.rotation.0.degree(), Some(0));
    assert!(rmf.rotation.1.is_zero());
    assert!(holds_exact(&rmf.certify()));
}

/// The PH quintic (preimage [[1,0,0,0],[1,1,0,1],[0,0,1,1]]) is not RRMF.
#[test]
fn generic_quintic_is_refused_with_named_error() {
    let c = PhCurve::new(
        vec![qt([1, 0, 0, 0]), qt([1, 1, 0, 1]), qt([0, 0, 1, 1])],
        origin(),
    )
    .unwrap();
    assert!(!is_rrmf_quintic_class1(&c).unwrap());
    assert!(matches!(
        RationalRmf::new(&c.to_f64()),
        Err(PhError::NotRrmf(_))
    ));
    match RationalRmf::new(&c) {
        Err(PhError::NotRrmf(msg)) => assert!(msg.contains("residue") || msg.contains("root")),
        other => panic!("expected NotRrmf, got {other:?}"),
    }
    let cubic = PhCurve::new(vec![qt([1, 0, 0, 0]), qt([1, 1, 0, 1])], origin()).unwrap();
    assert!(matches!(
        quintic_class1_residual(&cubic),
        Err(PhError::DegreeMismatch(_))
    ));
}

/// The sweep of a quarter ellipse `(2(1−s²), 2s)/(1+s²)·diag(1, 1/2)` along the sample
/// RRMF quintic: all certificates hold exactly, the weights are positive, and a surface
/// point is `r(t) + x f₁ + y f₂` exactly.
#[test]
fn sweep_of_quarter_ellipse_certifies() {
    let rmf = RationalRmf::new(&sample_rrmf()).unwrap();
    // this curve's least radius of curvature is ≈ 0.0873 (at t = 1/2): the ellipse with
    // semi-axes 2 and 1 is refused (the sweep would intersect itself), the one with
    // semi-axes 1/20 and 1/40 is swept
    let big = [[q(2, 1), q(0, 1)], [q(2, 1), q(1, 1)], [q(0, 1), q(1, 1)]];
    let weights = [Q::from(1), Q::from(1), Q::from(2)];
    match sweep_profile(&rmf, &big, &weights) {
        Err(PhError::Degenerate(m)) => assert!(m.contains("intersect itself"), "{m}"),
        other => panic!("expected the regularity refusal, got {other:?}"),
    }
    let profile = [
        [q(1, 20), q(0, 1)],
        [q(1, 20), q(1, 40)],
        [q(0, 1), q(1, 40)],
    ];
    let s = sweep_profile(&rmf, &profile, &weights).unwrap();
    let certs = s.certify();
    assert!(holds_exact(&certs), "{:?}", failing(&certs));
    // S(u = 0, t) = r(t) + f₁(t)/20
    let t = q(2, 5);
    let p = s.patch.eval(&Q::from(0), &t).unwrap();
    let r = rmf.curve.eval(&t);
    let [_, f1, _] = rmf.eval(&t).unwrap();
    for k in 0..3 {
        assert_eq!(p[k], r[k].clone() + f1[k].clone() * q(1, 20));
    }
    assert!(matches!(
        sweep_profile(&rmf, &profile, &[Q::from(1), Q::from(-1), Q::from(2)]),
        Err(PhError::OutOfRange(_))
    ));
    assert!(matches!(
        sweep_profile(&rmf, &profile[..1], &weights[..1]),
        Err(PhError::DegreeMismatch(_))
    ));
}

/// The condition number of evaluating the frame `F/d` at `t` in `f64`:
/// `max(Σ|c_k||t|^k over the numerators and d) / |d(t)|` (≥ 1); near a zero of `σ` (where
/// `d` is small) the `f64` frame loses that factor.
fn cond(f: &RationalRmf<f64>, t: f64) -> f64 {
    let abs_sum = |p: &rcagd_algebra::Poly<f64>| {
        p.coeffs()
            .iter()
            .enumerate()
            .map(|(k, c)| c.abs() * t.abs().powi(k as i32))
            .sum::<f64>()
    };
    let m =
        f.f1.iter()
            .chain(f.f2.iter())
            .map(abs_sum)
            .fold(abs_sum(&f.den), f64::max);
    (m / f.den.eval(&t).abs()).max(1.0)
}

fn small() -> impl Strategy<Value = Q> {
    (-3i64..=3, 1i64..=2).prop_map(|(p, d)| q(p, d))
}
fn quat() -> impl Strategy<Value = Quaternion<Q>> {
    (small(), small(), small(), small()).prop_map(|(w, x, y, z)| Quaternion::new(w, x, y, z))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Random RRMF quintics from the quintic condition (random exact `A_0`, `A_1`, `x`):
    /// the decision finds `w`, every certificate holds exactly, and the `f64` frame agrees.
    #[test]
    fn random_rrmf_quintics_certify(a0 in quat(), a1 in quat(), x in small()) {
        prop_assume!(a0.norm_sq() != Q::from(0));
        let c = rrmf_quintic_class1(a0, a1, x, origin()).unwrap();
        prop_assert!(is_rrmf_quintic_class1(&c).unwrap());
        let rmf = RationalRmf::new(&c).unwrap();
        let certs = rmf.certify();
        prop_assert!(holds_exact(&certs), "{:?}", failing(&certs));
        let f = rmf.to_f64();
        prop_assert!(f.certify().iter().all(|c| c.holds));
        prop_assert!(is_rrmf_quintic_class1(&c.to_f64()).unwrap());
        // the f64 decision on the rounded curve finds the same frame
        let g = RationalRmf::new(&c.to_f64()).unwrap();
        prop_assert!(g.certify().iter().all(|c| c.holds), "{:?}", failing(&g.certify()));
        for k in 0..=4 {
            let t = k as f64 / 4.0;
            if let (Some(e), Some(h)) = (f.eval(&t), g.eval(&t)) {
                let kappa = cond(&f, t);
                for (ve, vh) in e.iter().zip(&h) {
                    for (a, b) in ve.iter().zip(vh) {
                        prop_assert!((a - b).abs() < 1e-9 * kappa, "{} vs {} (κ = {})", a, b, kappa);
                    }
                }
            }
        }
        for k in 0..=4 {
            let t = q(k, 4);
            if let (Some(e), Some(g)) = (rmf.eval(&t), f.eval(&(k as f64 / 4.0))) {
                let kappa = cond(&f, k as f64 / 4.0);
                for (ve, vg) in e.iter().zip(&g) {
                    for (a, b) in ve.iter().zip(vg) {
                        prop_assert!((Scalar::to_f64(a) - b).abs() < 1e-12 * kappa, "{} vs {} (κ = {})", Scalar::to_f64(a), b, kappa);
                    }
                }
            }
        }
    }
}

/// Hermite data (end points, tangents, RMF vectors) read off an RRMF quintic are
/// reproduced by the interpolant: an exact RRMF quintic whose exact RMF certifies, with the
/// data matched to rounding.
#[test]
fn rrmf_hermite_reproduces_its_data() {
    use rcagd::ph::rrmf_hermite::RrmfHermiteData;
    let c = rrmf_quintic_class1(qt([2, 0, 1, 0]), qt([1, 2, 0, -1]), Q::from(0), origin()).unwrap();
    let f = RationalRmf::new(&c).unwrap().to_f64();
    let [t0, u0, _] = f.eval(&0.0).unwrap();
    let [t1, u1, _] = f.eval(&1.0).unwrap();
    let pts = f.curve.control_points();
    let data = RrmfHermiteData {
        p_i: pts[0],
        t_i: t0,
        u_i: u0,
        p_f: pts[5],
        t_f: t1,
        u_f: u1,
    };
    let h = data.solve().unwrap();
    assert!(
        holds_exact(&h.rmf.certify()),
        "{:?}",
        failing(&h.rmf.certify())
    );
    assert!(is_rrmf_quintic_class1(&h.rmf.curve).unwrap());
    assert!(h.point_residual < 1e-12, "{}", h.point_residual);
    assert!(h.tangent_residual < 1e-12, "{}", h.tangent_residual);
    assert!(h.frame_residual < 1e-9, "{}", h.frame_residual);
    // the end frame turned by 30° about the end tangent: another RRMF quintic
    let rot = |u: [f64; 3], t: [f64; 3]| {
        let b = [
            t[1] * u[2] - t[2] * u[1],
            t[2] * u[0] - t[0] * u[2],
            t[0] * u[1] - t[1] * u[0],
        ];
        let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
        [
            c * u[0] + s * b[0],
            c * u[1] + s * b[1],
            c * u[2] + s * b[2],
        ]
    };
    let turned = RrmfHermiteData {
        u_f: rot(u1, t1),
        ..data.clone()
    };
    let h2 = turned.solve().unwrap();
    assert!(holds_exact(&h2.rmf.certify()));
    assert!(h2.frame_residual < 1e-9, "{}", h2.frame_residual);
    assert!(h2.point_residual < 1e-12 && h2.tangent_residual < 1e-12);
    assert_ne!(h2.rmf.curve, h.rmf.curve);
    // refused data
    let bad = RrmfHermiteData {
        t_i: [0.0; 3],
        ..data.clone()
    };
    assert!(matches!(bad.solve(), Err(PhError::ZeroTangent(_))));
    let bad = RrmfHermiteData { u_i: t0, ..data };
    assert!(matches!(bad.solve(), Err(PhError::Degenerate(_))));
}

fn pos() -> impl Strategy<Value = Q> {
    (1i64..=4, 1i64..=2).prop_map(|(p, d)| q(p, d))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    /// Random rational quadratic profiles (random exact control points, positive weights)
    /// swept along random RRMF quintics: every certificate holds exactly, and the `f64`
    /// sweep of the `f64` frame agrees with the exact surface.
    #[test]
    fn random_sweeps_certify(
        a0 in quat(), a1 in quat(), x in small(),
        pts in proptest::collection::vec((small(), small()), 3),
        ws in proptest::collection::vec(pos(), 3),
    ) {
        prop_assume!(a0.norm_sq() != Q::from(0));
        let c = rrmf_quintic_class1(a0, a1, x, origin()).unwrap();
        let rmf = RationalRmf::new(&c).unwrap();
        let mut profile: Vec<[Q; 2]> = pts.into_iter().map(|(a, b)| [a, b]).collect();
        // a profile reaching the curve's radius of curvature is refused by name: shrink it
        // (by 1/16 at a time) until it fits
        let mut shrinks = 0;
        let s = loop {
            match sweep_profile(&rmf, &profile, &ws) {
                Ok(s) => break s,
                Err(PhError::Degenerate(m)) if m.contains("intersect itself") && shrinks < 6 => {
                    shrinks += 1;
                    let k = q(1, 16);
                    profile = profile.iter().map(|p| [&p[0] * &k, &p[1] * &k]).collect();
                }
                // a singular point of the curve on [0, 1] (σ(t) = 0): refused by name
                Err(PhError::Degenerate(m)) if !m.contains("intersect itself") => return Ok(()),
                Err(e) => panic!("{e}"),
            }
        };
        let certs = s.certify();
        prop_assert!(holds_exact(&certs), "{:?}", failing(&certs));
        let pf: Vec<[f64; 2]> = profile.iter().map(|p| [Scalar::to_f64(&p[0]), Scalar::to_f64(&p[1])]).collect();
        let wf: Vec<f64> = ws.iter().map(Scalar::to_f64).collect();
        let sf = sweep_profile(&rmf.to_f64(), &pf, &wf).unwrap();
        for (u, t) in [(0.0, 0.0), (0.5, 0.25), (1.0, 0.7), (0.3, 1.0)] {
            let e = s.patch.eval(&Q::try_from(u).unwrap(), &Q::try_from(t).unwrap()).unwrap();
            let g = sf.patch.eval(&u, &t).unwrap();
            // 1e-7 relative: the f64 patch goes through power-form polynomials of degree 13
            // (r·d) and their Bernstein conversion, which loses about 8 digits on such
            // inputs (seen: 1.7e-9 relative at t = 1)
            let scale = e.iter().map(|v| Scalar::to_f64(v).abs()).fold(1.0, f64::max);
            for (a, b) in e.iter().zip(&g) {
                prop_assert!((Scalar::to_f64(a) - b).abs() < 1e-7 * scale, "{} vs {} at ({u}, {t})", Scalar::to_f64(a), b);
            }
        }
    }
}
