//! The foundation constructions: exact circle arcs, full circles and cylinder patches.
//!
//! Exact examples, property tests with random exact inputs (points on a circle from the
//! rational parametrization `t ↦ c + r((1 − t²)/(1 + t²), 2t/(1 + t²))`), agreement of
//! the `f64` construction with the exact one, and typed errors for bad input.

use proptest::prelude::*;
use rcagd::conic::{circle_point, circle_residual, CircleArc, CircleArcs};
use rcagd::cylinder::CylinderPatch;
use rcagd::{circle_arcs, cylinder_patches, full_circle, Certified, ConstructionError};
use rcagd_algebra::{Certificate, Rational, Scalar};
use rcagd_geom::BezierCurve;

fn q(p: i64, d: i64) -> Rational {
    Rational::from_ratio(p, d)
}

fn hom<F: Scalar>(c: &BezierCurve<F>) -> Vec<Vec<F>> {
    c.control_points().map(|p| p.to_vec()).collect()
}

/// Independent evaluation (Bernstein sum) of the Euclidean point at `t`.
fn eval(c: &BezierCurve<Rational>, t: &Rational) -> Vec<Rational> {
    let n = c.degree();
    let mut acc = vec![q(0, 1); c.dim() + 1];
    let s = q(1, 1) - t.clone();
    let mut binom = 1i64;
    for i in 0..=n {
        let mut b = Rational::from(binom);
        for _ in 0..n - i {
            b *= s.clone();
        }
        for _ in 0..i {
            b *= t.clone();
        }
        for (a, x) in acc.iter_mut().zip(c.control_point(i)) {
            *a += b.clone() * x.clone();
        }
        binom = binom * (n - i) as i64 / (i + 1) as i64;
    }
    let w = acc[0].clone();
    acc[1..].iter().map(|x| x.clone() / w.clone()).collect()
}

fn assert_all_hold(certs: &[Certificate]) {
    for c in certs {
        assert!(c.holds, "certificate fails: {c}");
    }
}

// ---------------------------------------------------------------- exact examples

#[test]
fn unit_quarter_is_the_textbook_rational_quarter() {
    let arc = CircleArc::new(
        [q(0, 1), q(0, 1)],
        q(1, 1),
        [q(1, 1), q(0, 1)],
        [q(0, 1), q(1, 1)],
        false,
    )
    .expect("valid");
    assert_eq!(
        hom(arc.curve()),
        vec![
            vec![q(1, 1), q(1, 1), q(0, 1)],
            vec![q(1, 1), q(1, 1), q(1, 1)],
            vec![q(2, 1), q(0, 1), q(2, 1)],
        ]
    );
    // P(1/2) = (3/5, 4/5) — the rational parameter s = 1/2 of the stereographic map.
    assert_eq!(eval(arc.curve(), &q(1, 2)), vec![q(3, 5), q(4, 5)]);
    let certs = arc.certify();
    assert_all_hold(&certs);
    assert!(certs.iter().all(|c| c.exact));
}

#[test]
fn arc_between_pythagorean_points() {
    // (3/5, 4/5) to (−5/13, 12/13) on the unit circle, centre (2, −1), radius 3 (scaled).
    let c = [q(2, 1), q(-1, 1)];
    let r = q(3, 1);
    let p0 = [q(2, 1) + q(9, 5), q(-1, 1) + q(12, 5)];
    let p1 = [q(2, 1) - q(15, 13), q(-1, 1) + q(36, 13)];
    let arc = CircleArc::new(c.clone(), r.clone(), p0.clone(), p1.clone(), false).expect("valid");
    // σ = tan(φ/2) = (d₀ × d₁)/(r² + d₀·d₁).
    assert_eq!(arc.half_angle_tangent(), &q(4, 7));
    assert_all_hold(&arc.certify());
    for k in 0..=8 {
        let p = eval(arc.curve(), &q(k, 8));
        assert_eq!(
            circle_residual(&c, &r, &[p[0].clone(), p[1].clone()]),
            q(0, 1)
        );
    }
    // The other way round is the long arc: split, certified.
    let long = CircleArcs::new(c, r, p0.clone(), p1.clone(), true).expect("valid");
    assert!(long.pieces().len() >= 2);
    assert_all_hold(&long.certify());
    assert_eq!(long.pieces()[0].from(), &p0);
    assert_eq!(long.pieces().last().expect("pieces").to(), &p1);
}

#[test]
fn full_unit_circle_control_points() {
    let circle = full_circle([q(0, 1), q(0, 1)], q(1, 1)).expect("valid");
    let pieces: Vec<Vec<Vec<Rational>>> = circle.curves().iter().map(hom).collect();
    let i = |v: [i64; 3]| v.iter().map(|&k| q(k, 1)).collect::<Vec<_>>();
    assert_eq!(
        pieces,
        vec![
            vec![i([1, 1, 0]), i([1, 1, 1]), i([2, 0, 2])],
            vec![i([1, 0, 1]), i([1, -1, 1]), i([2, -2, 0])],
            vec![i([1, -1, 0]), i([1, -1, -1]), i([2, 0, -2])],
            vec![i([1, 0, -1]), i([1, 1, -1]), i([2, 2, 0])],
        ]
    );
    let certs = circle.certify();
    assert_eq!(certs.len(), 24);
    assert_all_hold(&certs);
    assert_eq!(
        certs
            .iter()
            .filter(|c| c.property.starts_with("G1 join"))
            .count(),
        4
    );
}

#[test]
fn cylinder_quarter_patch() {
    let cyl = CylinderPatch::new(
        q(1, 1),
        [q(1, 1), q(0, 1)],
        [q(0, 1), q(1, 1)],
        q(-1, 2),
        q(2, 1),
    )
    .expect("valid");
    let p = cyl.patch();
    assert_eq!(p.degree(), (2, 2));
    assert_eq!(
        p.control_point(0, 0),
        &[q(1, 1), q(1, 1), q(0, 1), q(-1, 2)]
    );
    assert_eq!(p.control_point(1, 1), &[q(1, 1), q(1, 1), q(1, 1), q(3, 4)]);
    assert_eq!(p.control_point(2, 2), &[q(2, 1), q(0, 1), q(2, 1), q(4, 1)]);
    let certs = cyl.certify();
    assert_all_hold(&certs);
    assert!(certs[0].property.contains("cylinder"));
}

#[test]
fn bad_inputs_give_typed_errors() {
    let c = [q(0, 1), q(0, 1)];
    // Off the circle, with the exact residual |p − c|² − r².
    match CircleArc::new(
        c.clone(),
        q(1, 1),
        [q(1, 1), q(0, 1)],
        [q(1, 2), q(1, 2)],
        false,
    ) {
        Err(ConstructionError::PointNotOnCircle {
            point, residual, ..
        }) => {
            assert_eq!(point, "to");
            assert_eq!(residual, "-1/2");
        }
        other => panic!("expected PointNotOnCircle, got {other:?}"),
    }
    let msg = CircleArcs::new(
        c.clone(),
        q(2, 1),
        [q(1, 1), q(0, 1)],
        [q(0, 1), q(2, 1)],
        false,
    )
    .expect_err("off circle")
    .to_string();
    assert!(
        msg.contains("not on the circle") && msg.contains("-3"),
        "{msg}"
    );
    // Coincident end points.
    for cw in [false, true] {
        assert!(matches!(
            circle_arcs(
                c.clone(),
                q(1, 1),
                [q(0, 1), q(1, 1)],
                [q(0, 1), q(1, 1)],
                cw
            ),
            Err(ConstructionError::CoincidentPoints(_))
        ));
    }
    // Zero and negative radius.
    for r in [q(0, 1), q(-2, 3)] {
        assert!(matches!(
            CircleArc::new(
                c.clone(),
                r.clone(),
                [q(1, 1), q(0, 1)],
                [q(0, 1), q(1, 1)],
                false
            ),
            Err(ConstructionError::NonPositiveRadius { .. })
        ));
        assert!(matches!(
            full_circle(c.clone(), r.clone()),
            Err(ConstructionError::NonPositiveRadius { .. })
        ));
        assert!(matches!(
            CylinderPatch::new(r, [q(1, 1), q(0, 1)], [q(0, 1), q(1, 1)], q(0, 1), q(1, 1)),
            Err(ConstructionError::NonPositiveRadius { .. })
        ));
    }
    // z0 ≥ z1.
    for (z0, z1) in [(q(1, 1), q(1, 1)), (q(2, 1), q(1, 1))] {
        let e = CylinderPatch::new(q(1, 1), [q(1, 1), q(0, 1)], [q(0, 1), q(1, 1)], z0, z1);
        assert!(
            matches!(e, Err(ConstructionError::EmptyInterval { .. })),
            "{e:?}"
        );
    }
    // A single piece of 180° or more.
    assert!(matches!(
        CircleArc::new(
            c.clone(),
            q(1, 1),
            [q(1, 1), q(0, 1)],
            [q(-1, 1), q(0, 1)],
            false
        ),
        Err(ConstructionError::ArcTooLarge(_))
    ));
    // f64: NaN and infinities are typed errors too.
    assert!(matches!(
        CircleArc::new([0.0, 0.0], 1.0, [1.0, 0.0], [f64::NAN, 1.0], false),
        Err(ConstructionError::NotFinite(_))
    ));
    assert!(matches!(
        full_circle([0.0, 0.0], f64::INFINITY),
        Err(ConstructionError::NotFinite(_))
    ));
    assert!(matches!(
        CylinderPatch::new(1.0, [1.0, 0.0], [0.0, 1.0], 0.0, f64::NAN),
        Err(ConstructionError::NotFinite(_))
    ));
}

#[test]
fn f64_certificates_are_tolerance_checks() {
    let arc = CircleArc::new([0.5, -1.0], 2.0, [2.5, -1.0], [0.5, 1.0], false).expect("valid");
    let certs = arc.certify();
    assert_all_hold(&certs);
    assert!(certs.iter().all(|c| !c.exact));
    let circle = full_circle([0.1, 0.2], 0.3).expect("valid");
    assert_all_hold(&circle.certify());
}

// ---------------------------------------------------------------- property tests

fn rational(num: i64, den: i64) -> impl Strategy<Value = Rational> {
    (-num..=num, 1..=den).prop_map(|(p, d)| q(p, d))
}

fn positive(num: i64, den: i64) -> impl Strategy<Value = Rational> {
    (1..=num, 1..=den).prop_map(|(p, d)| q(p, d))
}

fn point(num: i64, den: i64) -> impl Strategy<Value = [Rational; 2]> {
    (rational(num, den), rational(num, den)).prop_map(|(x, y)| [x, y])
}

fn f(x: &Rational) -> f64 {
    Scalar::to_f64(x)
}

fn to_f64(p: &[Rational; 2]) -> [f64; 2] {
    [f(&p[0]), f(&p[1])]
}

/// Relative agreement of homogeneous control points.
fn agree(exact: &BezierCurve<Rational>, float: &BezierCurve<f64>, tol: f64) -> bool {
    exact.degree() == float.degree()
        && exact
            .control_points()
            .zip(float.control_points())
            .all(|(a, b)| {
                let scale = a.iter().map(|x| f(x).abs()).fold(1.0, f64::max);
                a.iter()
                    .zip(b)
                    .all(|(x, y)| (f(x) - y).abs() <= tol * scale)
            })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn random_arcs_certify_and_interpolate(
        c in point(20, 7),
        r in positive(30, 7),
        t0 in rational(40, 17),
        t1 in rational(40, 17),
        clockwise in any::<bool>(),
    ) {
        prop_assume!(t0 != t1);
        let p0 = circle_point(&c, &r, &t0);
        let p1 = circle_point(&c, &r, &t1);
        prop_assert_eq!(circle_residual(&c, &r, &p0), q(0, 1));
        let arcs = CircleArcs::new(c.clone(), r.clone(), p0.clone(), p1.clone(), clockwise).expect("valid arc");
        let pieces = arcs.pieces();
        prop_assert!(!pieces.is_empty() && pieces.len() <= 4);
        let certs = arcs.certify();
        prop_assert!(Certificate::all_hold(&certs), "{:?}", certs.iter().find(|c| !c.holds));
        prop_assert!(certs.iter().all(|c| c.exact));
        prop_assert_eq!(pieces[0].from(), &p0);
        prop_assert_eq!(pieces[pieces.len() - 1].to(), &p1);
        for piece in pieces {
            let s = piece.half_angle_tangent().clone();
            let right_sense = if clockwise { s < q(0, 1) } else { s > q(0, 1) };
            prop_assert!(right_sense);
            // Independent check at a parameter that is not a certificate node.
            let m = eval(piece.curve(), &q(3, 7));
            prop_assert_eq!(circle_residual(&c, &r, &[m[0].clone(), m[1].clone()]), q(0, 1));
            prop_assert_eq!(eval(piece.curve(), &q(0, 1)), piece.from().to_vec());
            prop_assert_eq!(eval(piece.curve(), &q(1, 1)), piece.to().to_vec());
        }
        // A single piece exactly when the arc turns by less than 180°.
        let single = CircleArc::new(c, r, p0, p1, clockwise);
        prop_assert_eq!(single.is_ok(), pieces.len() == 1);
        if let Err(e) = single {
            prop_assert!(matches!(e, ConstructionError::ArcTooLarge(_)), "{}", e);
        }
    }

    #[test]
    fn f64_arcs_agree_with_exact(
        c in point(20, 7),
        r in positive(30, 7),
        t0 in rational(40, 17),
        t1 in rational(40, 17),
        clockwise in any::<bool>(),
    ) {
        prop_assume!(t0 != t1);
        let p0 = circle_point(&c, &r, &t0);
        let p1 = circle_point(&c, &r, &t1);
        // Stay away from the decision boundaries (0°, 180°, 270°, 360°), where the f64 signs
        // of d₀ × d₁ and d₀·d₁ may differ from the exact ones and σ = tan(φ/2) is ill-conditioned.
        let d0 = [p0[0].clone() - c[0].clone(), p0[1].clone() - c[1].clone()];
        let d1 = [p1[0].clone() - c[0].clone(), p1[1].clone() - c[1].clone()];
        let r2 = r.clone() * r.clone();
        let cos = f(&((d0[0].clone() * d1[0].clone() + d0[1].clone() * d1[1].clone()) / r2.clone()));
        let sin = f(&((d0[0].clone() * d1[1].clone() - d0[1].clone() * d1[0].clone()) / r2));
        prop_assume!(1.0 + cos > 1e-2 && sin.abs() > 1e-6 && cos.abs() > 1e-6);
        let exact = circle_arcs(c.clone(), r.clone(), p0.clone(), p1.clone(), clockwise).expect("valid");
        let float = circle_arcs(to_f64(&c), f(&r), to_f64(&p0), to_f64(&p1), clockwise).expect("valid f64");
        prop_assert_eq!(exact.len(), float.len());
        for (a, b) in exact.iter().zip(&float) {
            prop_assert!(agree(a, b, 1e-12), "{:?} vs {:?}", hom(a), hom(b));
        }
        let circle = full_circle(c.clone(), r.clone()).expect("valid");
        let circle_f = full_circle(to_f64(&c), f(&r)).expect("valid");
        for (a, b) in circle.curves().iter().zip(&circle_f.curves()) {
            prop_assert!(agree(a, b, 1e-12));
        }
        prop_assert!(circle_f.all_hold());
    }

    #[test]
    fn random_full_circles_certify(c in point(50, 9), r in positive(50, 9)) {
        let circle = full_circle(c.clone(), r.clone()).expect("valid");
        let certs = circle.certify();
        prop_assert_eq!(certs.len(), 24);
        prop_assert!(Certificate::all_hold(&certs));
        let m = eval(&circle.curves()[2], &q(5, 11));
        prop_assert_eq!(circle_residual(&c, &r, &[m[0].clone(), m[1].clone()]), q(0, 1));
    }

    #[test]
    fn random_cylinder_patches_certify(
        r in positive(30, 7),
        t0 in rational(40, 17),
        t1 in rational(40, 17),
        z0 in rational(20, 5),
        dz in positive(20, 5),
    ) {
        prop_assume!(t0 != t1);
        let o = [q(0, 1), q(0, 1)];
        let p0 = circle_point(&o, &r, &t0);
        let p1 = circle_point(&o, &r, &t1);
        let z1 = z0.clone() + dz;
        let patches = cylinder_patches(r.clone(), p0.clone(), p1.clone(), z0.clone(), z1.clone()).expect("valid");
        prop_assert!(!patches.is_empty() && patches.len() <= 4);
        for p in &patches {
            prop_assert!(p.all_hold(), "{:?}", p.certify().iter().find(|c| !c.holds));
        }
        // Reversed heights are a typed error.
        let e = cylinder_patches(r, p0, p1, z1, z0);
        prop_assert!(matches!(e, Err(ConstructionError::EmptyInterval { .. })), "{:?}", e);
    }

    #[test]
    fn off_circle_points_are_rejected_with_their_residual(
        c in point(20, 7),
        r in positive(30, 7),
        t in rational(40, 17),
        dr in positive(5, 9),
    ) {
        let on = circle_point(&c, &r, &q(1, 3));
        let off = circle_point(&c, &(r.clone() + dr.clone()), &t);
        let want = (r.clone() + dr.clone()) * (r.clone() + dr) - r.clone() * r.clone();
        match CircleArcs::new(c.clone(), r.clone(), on.clone(), off.clone(), false) {
            Err(ConstructionError::PointNotOnCircle { point, residual, .. }) => {
                prop_assert_eq!(point, "to");
                prop_assert_eq!(residual, rcagd_algebra::rational::format_rational(&want));
            }
            other => prop_assert!(false, "expected PointNotOnCircle, got {:?}", other),
        }
        prop_assert!(CircleArc::new(c, r, off, on, true).is_err());
    }

    #[test]
    fn arbitrary_input_never_panics(
        c in point(5, 3),
        r in rational(5, 3),
        a in point(5, 3),
        b in point(5, 3),
        z0 in rational(5, 3),
        z1 in rational(5, 3),
        cw in any::<bool>(),
        fl in proptest::collection::vec(prop_oneof![any::<f64>(), Just(f64::NAN), Just(0.0), Just(1.0)], 7),
    ) {
        let _ = CircleArc::new(c.clone(), r.clone(), a.clone(), b.clone(), cw);
        let _ = circle_arcs(c.clone(), r.clone(), a.clone(), b.clone(), cw);
        let _ = full_circle(c, r.clone());
        let _ = CylinderPatch::new(r.clone(), a.clone(), b.clone(), z0.clone(), z1.clone());
        let _ = cylinder_patches(r, a, b, z0, z1);
        let _ = circle_arcs([fl[0], fl[1]], fl[2], [fl[3], fl[4]], [fl[5], fl[6]], cw).map(|v| v.len());
        let _ = full_circle([fl[0], fl[1]], fl[2]).map(|c| c.certify());
        let _ = cylinder_patches(fl[2], [fl[3], fl[4]], [fl[5], fl[6]], fl[0], fl[1]).map(|v| v.len());
    }
}
