//! The constructions moved from the CLI ops into the library (docs/ARCHITECTURE.md,
//! "Library first"): ranked Hermite interpolants, PH combs and feed marks, the charts of a
//! sphere–plane blend.

use proptest::prelude::*;
use rcagd::canal::bipoly::BiPoly;
use rcagd::canal::blend_charts::{chart_patches, charts};
use rcagd::ph::*;
use rcagd_algebra::interval::pow2;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::{Poly, Rational, Scalar};

type Q = Rational;

fn rat() -> impl Strategy<Value = Q> {
    (-6i64..=6, 1i64..=3).prop_map(|(p, q)| Q::from(p) / Q::from(q))
}
fn quat() -> impl Strategy<Value = Quaternion<Q>> {
    (rat(), rat(), rat(), rat()).prop_map(|(w, x, y, z)| Quaternion::new(w, x, y, z))
}
fn point() -> impl Strategy<Value = [Q; 3]> {
    (rat(), rat(), rat()).prop_map(|(a, b, c)| [a, b, c])
}
fn f(x: &Q) -> f64 {
    Scalar::to_f64(x)
}

/// Besednjak Example 9.1: four interpolants ranked by energy, every certificate holds, the
/// first is the least-energy one and its control points meet the Hermite data.
#[test]
fn example_9_1_ranked_interpolants() {
    let data = crate::seed001_examples::example_9_1_data();
    let sol = data.solve_exact().expect("solutions");
    let ranked = sol
        .ranked_interpolants(&data, &pow2(-80), &pow2(-40))
        .expect("ranked");
    assert_eq!(ranked.len(), 4);
    for (k, r) in ranked.iter().enumerate() {
        assert_eq!(r.rank, k + 1);
        assert!(
            r.certificates.iter().all(|c| c.holds),
            "{:?}",
            r.certificates
        );
        assert_eq!(r.control_points.len(), 6);
        assert!(r.enclosure.is_ok());
    }
    assert!(ranked.windows(2).all(|w| w[0].energy <= w[1].energy));
    assert!(sol.interpolants[ranked[0].index].least_energy);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Constant-feed marks of random PH curves: the exact certificate holds, and the f64
    /// marks agree with the exact ones.
    #[test]
    fn feed_marks_certify_and_f64_agrees(coeffs in prop::collection::vec(quat(), 1..4), p0 in point(), n in 2usize..8) {
        prop_assume!(coeffs.iter().all(|a| a.norm_sq() != Q::from(0)));
        let c = PhCurve::new(coeffs.clone(), p0.clone()).unwrap();
        let tol = pow2(-40);
        let m = c.constant_feed_marks(n, &tol).unwrap();
        prop_assert_eq!(m.parameters.len(), n + 1);
        let cert = m.certificate("2⁻⁴⁰");
        prop_assert!(cert.holds && cert.exact, "{}", cert);
        let cf = PhCurve::new(
            coeffs.iter().map(|a| Quaternion::new(f(&a.w), f(&a.x), f(&a.y), f(&a.z))).collect(),
            [f(&p0[0]), f(&p0[1]), f(&p0[2])],
        ).unwrap();
        let mf = cf.constant_feed_marks(n, &1e-12).unwrap();
        prop_assert!((mf.total - f(&m.total)).abs() <= 1e-9 * (1.0 + f(&m.total).abs()));
        for (a, b) in mf.parameters.iter().zip(&m.parameters) {
            prop_assert!((a - f(b)).abs() <= 1e-6, "{} vs {}", a, f(b));
        }
    }

    /// Comb teeth: tip − base is λ times the curvature vector, exactly; f64 agrees.
    #[test]
    fn comb_teeth_are_scaled_curvature_vectors(coeffs in prop::collection::vec(quat(), 2..4), p0 in point(), lambda in rat()) {
        prop_assume!(coeffs.iter().all(|a| a.norm_sq() != Q::from(0)));
        let c = PhCurve::new(coeffs.clone(), p0.clone()).unwrap();
        let pc = c.to_poly_curve();
        let ts: Vec<Q> = (0..5).map(|k| Q::from(k) / Q::from(4)).collect();
        let teeth = pc.curvature_comb(&ts, &lambda);
        let (num, den) = pc.curvature_vector();
        let mut kept = ts.iter().filter(|t| den.eval(t) != Q::from(0));
        for (p, tip) in &teeth {
            let t = kept.next().unwrap();
            prop_assert_eq!(p, &pc.eval(t));
            for i in 0..3 {
                prop_assert_eq!(&tip[i] - &p[i], num[i].eval(t) * lambda.clone() / den.eval(t));
            }
        }
        let cf = PhCurve::new(
            coeffs.iter().map(|a| Quaternion::new(f(&a.w), f(&a.x), f(&a.y), f(&a.z))).collect(),
            [f(&p0[0]), f(&p0[1]), f(&p0[2])],
        ).unwrap();
        let tf: Vec<f64> = ts.iter().map(Scalar::to_f64).collect();
        let teeth_f = cf.to_poly_curve().curvature_comb(&tf, &f(&lambda));
        prop_assert_eq!(teeth_f.len(), teeth.len());
        // the tooth λ·N(t)/D(t) in f64 loses the evaluation condition of N and D: each is
        // compared with the sizes of the terms that make it up (|N|(t), |D|(t): absolute
        // coefficients), found by the CI seed where |D(t)| ≪ |D|(t) (6e-8 relative)
        let abs_eval = |p: &rcagd_algebra::Poly<Q>, t: f64| {
            p.coeffs().iter().rev().fold(0.0, |acc, c| acc * t.abs() + f(c).abs())
        };
        let kept: Vec<&Q> = ts.iter().filter(|t| den.eval(t) != Q::from(0)).collect();
        for (((_, a), (_, b)), t) in teeth_f.iter().zip(&teeth).zip(kept) {
            let tv = f(t);
            let (d, d_abs) = (f(&den.eval(t)), abs_eval(&den, tv));
            for i in 0..3 {
                let e = f(&b[i]);
                let (nv, n_abs) = (f(&num[i].eval(t)), abs_eval(&num[i], tv));
                let cond = f(&lambda).abs() * (n_abs * d.abs() + nv.abs() * d_abs) / (d * d);
                prop_assert!(
                    (a[i] - e).abs() <= 1e-8 * (1.0 + e.abs()) + 1e-9 * cond,
                    "{} vs {}", a[i], e
                );
            }
        }
    }

    /// The second chart is the reparametrization u → 1/u: uⁿ X(t, 1/u) at every (t, u ≠ 0);
    /// the patches of both charts exist.
    #[test]
    fn charts_reverse_u(c in prop::collection::vec(prop::collection::vec(-5i64..=5, 1..3), 1..4), t in rat(), u in rat()) {
        prop_assume!(u != Q::from(0));
        let x: Vec<BiPoly<Q>> = (0..4)
            .map(|k| BiPoly::new(c.iter().map(|row| Poly::from_ints(&row.iter().map(|v| v + k as i64).collect::<Vec<_>>())).collect()))
            .collect();
        let ch = charts(&x, false);
        prop_assert_eq!(ch.len(), 2);
        let n = x.iter().filter_map(BiPoly::degree_u).max().unwrap_or(0);
        let un = (0..n).fold(Q::from(1), |a, _| a * u.clone());
        for k in 0..4 {
            prop_assert_eq!(ch[1][k].eval(&t, &u), un.clone() * x[k].eval(&t, &(Q::from(1) / u.clone())));
        }
        prop_assert_eq!(chart_patches(&x, true).unwrap().len(), 4);
    }
}
