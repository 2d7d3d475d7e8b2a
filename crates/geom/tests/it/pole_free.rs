//! `weight_sign::curve_pole_free`: the one rule for a user's weights, checked against
//! an independent count of sign changes of the weight function on a fine grid.

use proptest::prelude::*;
use rcagd_algebra::Rational;
use rcagd_geom::weight_sign::curve_pole_free;
use rcagd_geom::BezierCurve;

fn curve(weights: &[i64]) -> BezierCurve<Rational> {
    let pts: Vec<Vec<Rational>> = weights
        .iter()
        .enumerate()
        .map(|(i, &w)| {
            vec![
                Rational::from(w),
                Rational::from(w * i as i64),
                Rational::from(w * w),
            ]
        })
        .collect();
    BezierCurve::from_homogeneous(pts).expect("curve")
}

/// `w(t)` in f64 by de Casteljau.
fn w_at(weights: &[i64], t: f64) -> f64 {
    let mut b: Vec<f64> = weights.iter().map(|&w| w as f64).collect();
    for r in 1..b.len() {
        for i in 0..b.len() - r {
            b[i] = (1.0 - t) * b[i] + t * b[i + 1];
        }
    }
    b[0]
}

#[test]
fn examples() {
    // one sign: no pole, also all negative (the same curve)
    assert!(curve_pole_free(&curve(&[1, 1, 2])).expect("no pole").holds);
    assert!(
        curve_pole_free(&curve(&[-1, -1, -2]))
            .expect("no pole")
            .holds
    );
    // mixed signs without a zero: (1−t)² − 2t(1−t) + 2t² = 5t² − 4t + 1 > 0
    assert!(curve_pole_free(&curve(&[1, -1, 2])).expect("no pole").holds);
    // a double zero at t = 1/2: (1−t)² − 2t(1−t) + t² = (2t − 1)²
    let e = curve_pole_free(&curve(&[1, -1, 1])).expect_err("pole");
    assert_eq!(e.zeros.len(), 1);
    assert_eq!(
        e.zeros[0].0,
        <Rational as rcagd_algebra::Scalar>::from_ratio(1, 2)
    );
    // two zeros (2 ± √2)/4
    let e = curve_pole_free(&curve(&[1, -3, 1])).expect_err("poles");
    assert_eq!(e.zeros.len(), 2);
    let r = 2f64.sqrt();
    assert!((e.zeros[0].2 - (2.0 - r) / 4.0).abs() < 1e-12, "{e}");
    assert!((e.zeros[1].2 - (2.0 + r) / 4.0).abs() < 1e-12, "{e}");
    assert!(e.to_string().contains("point at infinity"));
    // a zero at an end point
    assert!(curve_pole_free(&curve(&[0, 1, 1])).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// A sign change of w on a fine grid proves a zero; so the rule must refuse such
    /// weights, and a curve it accepts has w of one sign at every grid point.
    #[test]
    fn agrees_with_sign_changes_on_a_grid(ws in prop::collection::vec(-6i64..=6, 2..6)) {
        prop_assume!(ws.iter().any(|&w| w != 0));
        let vals: Vec<f64> = (0..=2000).map(|k| w_at(&ws, f64::from(k) / 2000.0)).collect();
        let changes = vals.windows(2).any(|p| p[0] * p[1] < 0.0);
        match curve_pole_free(&curve(&ws)) {
            Ok(c) => {
                prop_assert!(c.holds);
                prop_assert!(!changes, "accepted weights {ws:?} whose w changes sign");
                prop_assert!(vals.iter().all(|v| *v != 0.0));
            }
            Err(e) => {
                // every reported zero is a zero: w is small near it
                for (_, _, t) in &e.zeros {
                    if t.is_finite() {
                        prop_assert!(w_at(&ws, *t).abs() < 1e-6, "{ws:?}: {e}");
                    }
                }
            }
        }
    }
}
