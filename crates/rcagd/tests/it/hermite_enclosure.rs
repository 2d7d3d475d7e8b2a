//! Guaranteed-accuracy Hermite interpolants (`rcagd::ph::hermite_enclosure`): boxes that
//! contain the exact control points and an interval that contains the exact bending energy.

use proptest::prelude::*;
use rcagd::ph::*;
use rcagd_algebra::interval::pow2;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::{QuadExt, Rational};

type Q = Rational;

fn qi(n: i64) -> QuadExt {
    QuadExt::from(n)
}

fn tol() -> (Q, Q) {
    (pow2(-80), pow2(-40))
}

/// Besednjak Example 9.1 (`p_s = 0`, `d_s = (1,0,1)`, `p_f = (1,1,1)`, `d_f = (0,1,1)`):
/// the four interpolants' energies are enclosed, the printed values (322.29811,
/// 1.2735954, 89.576305) lie within their printed precision, and the `f64` pipeline agrees.
#[test]
fn example_9_1_energies_are_enclosed() {
    let data = crate::seed001_examples::example_9_1_data();
    let sol = data.solve_exact().expect("solutions");
    assert_eq!(sol.interpolants.len(), 4);
    let (tp, te) = tol();
    let mut found = [false; 3];
    for (i, it) in sol.interpolants.iter().enumerate() {
        let enc = sol.enclose(i, &tp, &te).expect("enclosure");
        for c in enc.certify() {
            assert!(c.holds && c.exact, "{c}");
        }
        assert!(enc.control_point_width <= tp);
        let e = &enc.bending_energy;
        assert!(e.width() <= te.clone() * e.mag(), "energy width");
        let (lo, hi) = e.to_f64_bounds();
        // the f64 pipeline's energy (adaptive Gauss–Kronrod) agrees to 1e-9
        assert!(
            (it.bending_energy - e.to_f64()).abs() <= 1e-9 * e.to_f64(),
            "f64 E = {} vs [{lo}, {hi}]",
            it.bending_energy
        );
        // the f64 control points agree with the boxes
        for (p, b) in it
            .curve
            .control_points()
            .iter()
            .zip(enc.control_points_f64())
        {
            for k in 0..3 {
                assert!((p[k] - b[k]).abs() <= 1e-12 * b[k].abs().max(1.0));
            }
        }
        for (j, printed) in [322.298_11, 1.273_595_4, 89.576_305].iter().enumerate() {
            if (e.to_f64() - printed).abs() <= 5e-6 * printed {
                found[j] = true;
            }
        }
    }
    assert_eq!(found, [true; 3], "every printed energy is matched");
}

/// A helical quintic whose speed `σ = |A(t)|²` nearly vanishes at `t = 1/2`
/// (`A_1 = c(A_0 + A_2)`, `c = −1/2 + δ`): the energy is about `1/δ³`-large and
/// ill-conditioned. The root is rational, so the exact interpolant is known: its control
/// points lie in the boxes and its energy (from the exact `ρ/σ³`) in the interval.
#[test]
fn nearly_singular_interpolant_is_enclosed() {
    let delta = Q::from(1) / Q::from(200);
    let c = Q::from(-1) / Q::from(2) + delta;
    let a0 = Quaternion::new(Q::from(1), Q::from(1), Q::from(0), Q::from(2));
    let a2 = Quaternion::new(Q::from(0), Q::from(2), Q::from(-1), Q::from(1));
    let a1 = a0.scale(&c) + a2.scale(&c);
    let curve =
        PhCurve::new(vec![a0, a1, a2], [Q::from(0), Q::from(0), Q::from(0)]).expect("curve");
    let pts = curve.control_points();
    let five = Q::from(5);
    let q3 = |v: &[Q; 3]| [0, 1, 2].map(|k| QuadExt::from(v[k].clone()));
    let d_s = [0, 1, 2].map(|k| (pts[1][k].clone() - pts[0][k].clone()) * five.clone());
    let d_f = [0, 1, 2].map(|k| (pts[5][k].clone() - pts[4][k].clone()) * five.clone());
    let data = HermiteData::new(q3(&pts[0]), q3(&d_s), q3(&pts[5]), q3(&d_f));
    let sol = data.solve_exact().expect("solutions");
    let idx = sol
        .interpolants
        .iter()
        .position(|i| i.exact_control_points.as_ref() == Some(&pts))
        .expect("the original curve is an interpolant");
    let (tp, te) = tol();
    let enc = sol.enclose(idx, &tp, &te).expect("enclosure");
    for c in enc.certify() {
        assert!(c.holds, "{c}");
    }
    for (b, p) in enc.control_points.iter().zip(&pts) {
        for k in 0..3 {
            assert!(b[k].contains(&p[k]), "exact control point outside its box");
        }
    }
    let exact_e = curve.to_poly_curve().bending_energy().expect("energy");
    let e = &enc.bending_energy;
    assert!(e.to_f64() > 1e5, "nearly singular: E = {}", e.to_f64());
    assert!(
        (exact_e - e.to_f64()).abs() <= 1e-8 * exact_e,
        "E(exact ρ) = {exact_e} vs enclosure {:?}",
        e.to_f64_bounds()
    );
    // An independent value: mpmath quad at 40 digits of the sympy integrand
    // |r'×r''|²/σ⁵ of this curve (script in docs/math/ph-curves.md, "Guaranteed-accuracy
    // Hermite interpolants") gives 6479945.411018311930…; both f64 quadratures miss it by
    // 1e-11 to 1e-10 relative, the enclosure contains it.
    let reference = Q::from(6_479_945_411_018_311_930i64) / Q::from(1_000_000_000_000i64);
    assert!(e.contains(&reference), "enclosure {:?}", e.to_f64_bounds());
}

fn small() -> impl Strategy<Value = Q> {
    (-4i64..=4).prop_map(Q::from)
}

fn vec3() -> impl Strategy<Value = [Q; 3]> {
    (small(), small(), small()).prop_map(|(a, b, c)| [a, b, c])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(6))]

    /// Random integer Hermite data (irrational roots in general): every enclosure
    /// certifies, is as narrow as asked, and the f64 interpolants agree with it.
    #[test]
    fn random_data_enclosures_agree_with_f64(ps in vec3(), ds in vec3(), pf in vec3(), df in vec3()) {
        let q3 = |v: &[Q; 3]| [0, 1, 2].map(|k| QuadExt::from(v[k].clone()));
        let data = HermiteData::new(q3(&ps), q3(&ds), q3(&pf), q3(&df));
        let Ok(sol) = data.solve_exact() else { return Ok(()) };
        let (tp, te) = tol();
        for (i, it) in sol.interpolants.iter().enumerate() {
            let enc = match sol.enclose(i, &tp, &te) {
                Ok(e) => e,
                // σ with a real root on [0, 1]: the energy diverges, the f64 one too
                Err(PhError::Degenerate(_)) => {
                    prop_assert!(it.bending_energy > 1e6 || !it.bending_energy.is_finite());
                    continue;
                }
                Err(e) => return Err(TestCaseError::fail(format!("{e}"))),
            };
            for c in enc.certify() {
                prop_assert!(c.holds && c.exact, "{}", c);
            }
            prop_assert!(enc.control_point_width <= tp);
            for (p, b) in it.curve.control_points().iter().zip(enc.control_points_f64()) {
                for k in 0..3 {
                    prop_assert!((p[k] - b[k]).abs() <= 1e-7 * b[k].abs().max(1.0), "{} vs {}", p[k], b[k]);
                }
            }
            let e = enc.bending_energy.to_f64();
            prop_assert!((it.bending_energy - e).abs() <= 1e-6 * e, "f64 E = {} vs {}", it.bending_energy, e);
        }
    }
}

/// Example 9.1 with the start derivative stretched to `(s, 0, 1)` for `s` from `10⁻⁶` to
/// `10³`: every interpolant's `f64` quaternion form passes its PH and helix certificates
/// (the Lancret identity with its residual measured against the magnitude of its terms;
/// against the largest coefficient it failed at `s = 1000`, terms near 10²⁴ cancelling to
/// coefficients near 10¹⁶). From `s = 10⁴` on the `f64` helix test takes the nearly
/// planar interpolants (out of plane by `1/s`) for planar ones, and their certificate
/// `n·r' ≡ 0` fails, as it must (docs/plans/reliability.md, item 0).
#[test]
fn f64_helix_certificates_hold_over_twelve_orders_of_magnitude() {
    for k in -6i32..=6 {
        let s = if k >= 0 {
            QuadExt::from(Rational::from(10i64.pow(k.unsigned_abs())))
        } else {
            QuadExt::from(Rational::from(1i64) / Rational::from(10i64.pow(k.unsigned_abs())))
        };
        let data = HermiteData::new(
            [qi(0), qi(0), qi(0)],
            [s, qi(0), qi(1)],
            [qi(1), qi(1), qi(1)],
            [qi(0), qi(1), qi(1)],
        );
        let sol = data.solve_exact().expect("solutions");
        assert!(!sol.interpolants.is_empty(), "s = 10^{k}");
        for it in &sol.interpolants {
            let mut certs = it.curve.certify();
            certs.extend(it.curve.to_poly_curve().certify_helix_test(&it.helix));
            for c in certs {
                assert!(c.holds, "s = 10^{k}: {c}");
            }
        }
    }
}
