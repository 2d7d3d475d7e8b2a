//! Canal surfaces by the cyclographic parametrization Γ(s, t) of D. Gruber, "Rationale
//! Parametrisierungen von Kugelhüllflächen" (2008), §2.3, as the rational fallback of the
//! canal builder (`rcagd::canal::canal_surface_rational`): families whose discriminant
//! |ṁ|² − ṙ² splits only over Q(√d) are built over Q when they are quadratic; the named
//! errors otherwise; random quadratic families certified, f64 agreeing with exact.

use proptest::prelude::*;
use rcagd::canal::{
    canal_surface_from_normal_field, canal_surface_rational, CanalError, CanalOptions, CanalSpine,
    QuadraticCanal, RationalCanal,
};
use rcagd::Certified;
use rcagd_algebra::{Certificate, Poly, Rational, Scalar};

fn r(n: i64, d: i64) -> Rational {
    Rational::from_ratio(n, d)
}

fn opts() -> CanalOptions {
    CanalOptions {
        domain: Some((r(0, 1), r(1, 1))),
        ..CanalOptions::default()
    }
}

/// Gruber (2.19): m(u) = (u, 0, u²), r(u) = u²/4; D = 1 + (15/4)u².
fn example_2_3() -> CanalSpine<Rational> {
    CanalSpine::polynomial(
        [
            Poly::from_ints(&[0, 1]),
            Poly::zero(),
            Poly::from_ints(&[0, 0, 1]),
        ],
        Poly::new(vec![r(0, 1), r(0, 1), r(1, 4)]),
    )
}

#[test]
fn the_example_of_2_3_is_built_over_q_by_gamma() {
    let spine = example_2_3();
    // inside the circle 5(s² + t²) = 3 (where p = 4s/(5s² + 5t² − 3) has its pole), s < 0:
    // spine parameters p ∈ (0.18, 4)
    let dom = [r(-1, 2), r(-1, 8), r(1, 8), r(1, 2)];
    let built = canal_surface_rational(&spine, &opts(), Some(&dom)).expect("built");
    let RationalCanal::Cyclographic(c) = built else {
        panic!("the spine-parameter constructions need Q(√15): expected the fallback");
    };
    assert_eq!(c.radicand(), &r(15, 1));
    let certs = c.certify();
    assert!(Certificate::all_hold(&certs), "{certs:#?}");
    assert!(certs.iter().all(|x| x.exact));
    // a point of a piece lies on the sphere of its spine parameter
    let g = c.surface();
    let (s, t) = (r(-1, 3), r(1, 4));
    let x = g.eval(&s, &t).expect("point");
    let (n, d) = g.parameter();
    let p = n.eval(&s, &t) / d.eval(&s, &t);
    let (m, rad) = spine.eval(&p).expect("sphere");
    let dist: Rational = (0..3).fold(r(0, 1), |a, k| {
        a + (x[k].clone() - m[k].clone()) * (x[k].clone() - m[k].clone())
    });
    assert_eq!(dist, rad.clone() * rad);
    assert!(!c.patches().is_empty());
}

/// The family of (2.19) in the parameter p = 1/u: weight p² (a rational double root), the
/// same spheres. The Möbius change p = 0 + 1/p' makes it polynomial again, so Γ applies,
/// certified (the Möbius identity included), and Γ(s, t) is the same map as for (2.19).
#[test]
fn a_family_with_a_square_weight_is_built_by_a_mobius_change() {
    // m = (1/p, 0, 1/p²), r = 1/(4p²): W = p², M = (p, 0, 1), R = 1/4
    let spine = CanalSpine::new(
        Poly::from_ints(&[0, 0, 1]),
        [
            Poly::from_ints(&[0, 1]),
            Poly::zero(),
            Poly::from_ints(&[1]),
        ],
        Poly::new(vec![r(1, 4)]),
    )
    .expect("spine");
    let (poly, rho) = rcagd::canal::cyclographic_param::polynomial_form(&spine).expect("form");
    assert_eq!(rho, r(0, 1));
    assert_eq!(poly.weight().degree(), Some(0));
    let dom = [r(-1, 2), r(-1, 8), r(1, 8), r(1, 2)];
    let built = canal_surface_rational(&spine, &opts(), Some(&dom)).expect("built");
    let RationalCanal::Cyclographic(c) = built else {
        panic!("expected the cyclographic fallback");
    };
    let certs = c.certify();
    assert!(Certificate::all_hold(&certs), "{certs:#?}");
    assert!(certs
        .iter()
        .any(|x| x.property.contains("Möbius") || x.property.contains("p' = 1/(p")));
    let RationalCanal::Cyclographic(c0) =
        canal_surface_rational(&example_2_3(), &opts(), Some(&dom)).expect("2.19")
    else {
        panic!("expected the cyclographic fallback");
    };
    for (s, t) in [(r(-1, 3), r(1, 4)), (r(-1, 5), r(1, 3))] {
        assert_eq!(
            c.surface().eval(&s, &t).expect("Γ"),
            c0.surface().eval(&s, &t).expect("Γ of 2.19")
        );
    }
    // a weight with two distinct roots is refused by name
    let two_roots = CanalSpine::new(
        Poly::from_ints(&[-1, 0, 1]),
        [
            Poly::from_ints(&[0, 1]),
            Poly::zero(),
            Poly::from_ints(&[1]),
        ],
        Poly::new(vec![r(1, 4)]),
    )
    .expect("spine");
    assert!(rcagd::canal::cyclographic_param::polynomial_form(&two_roots).is_none());
}

/// `F(p(s, t))` of the canal regularity condition at a point of Ω(s, t) (exact).
fn regularity_at(
    spine: &CanalSpine<Rational>,
    g: &QuadraticCanal<Rational>,
    s: &Rational,
    t: &Rational,
) -> (Rational, Rational) {
    let (n, d) = g.parameter();
    let p = n.eval(s, t) / d.eval(s, t);
    (
        rcagd::canal::canal_regularity_polynomial(spine).eval(&p),
        spine.radius_poly().eval(&p),
    )
}

/// Γ is checked for local self-intersections on its rectangle: the gallery's rectangle of
/// (2.19) is certified (F(p(s, t)) > 0 checked independently on a grid), a rectangle reaching
/// the vertex p = 0 (radius 0) and one where the radius 1 + p²/4 exceeds the parabola's
/// radius of curvature 1/2 are refused at a point where the condition fails.
#[test]
fn gamma_is_checked_for_local_self_intersection_on_its_rectangle() {
    let spine = example_2_3();
    let dom = [r(1, 1), r(2, 1), r(-1, 1), r(1, 1)];
    let RationalCanal::Cyclographic(c) =
        canal_surface_rational(&spine, &opts(), Some(&dom)).expect("built")
    else {
        panic!("expected the fallback");
    };
    let certs = c.certify();
    assert!(Certificate::all_hold(&certs), "{certs:#?}");
    assert!(certs
        .iter()
        .any(|x| x.property.starts_with("no local self-intersection of Γ")));
    for i in 0..=4 {
        for j in 0..=4 {
            let (s, t) = (r(4 + i, 4), r(j - 2, 2));
            let (f, rad) = regularity_at(&spine, c.surface(), &s, &t);
            assert!(f > r(0, 1) && rad != r(0, 1), "F ≤ 0 at ({s}, {t})");
        }
    }
    let witness = |e: CanalError| match e {
        CanalError::SingularCyclographic { s, t, reason, .. } => (
            rcagd_algebra::parse_rational(&s).expect("s"),
            rcagd_algebra::parse_rational(&t).expect("t"),
            reason,
        ),
        e => panic!("expected SingularCyclographic, got {e}"),
    };
    // p = 4s/(5s² + 5t² − 3) = 0 on s = 0: the sphere of radius 0
    let through_vertex = [r(-1, 10), r(1, 10), r(1, 1), r(2, 1)];
    let (s, t, reason) = witness(
        canal_surface_rational(&spine, &opts(), Some(&through_vertex)).expect_err("vertex"),
    );
    assert!(reason.contains("radius"), "{reason}");
    let g = QuadraticCanal::from_spine(&spine).expect("Γ");
    assert!(
        regularity_at(&spine, &g, &s, &t).1 <= r(0, 1) || s < r(0, 1),
        "R(p) > 0 at the witness ({s}, {t})"
    );
    // m = (u, 0, u²), r = 1 + u²/4: at u = 0 the radius 1 exceeds the radius of curvature 1/2
    let fat = CanalSpine::polynomial(
        [
            Poly::from_ints(&[0, 1]),
            Poly::zero(),
            Poly::from_ints(&[0, 0, 1]),
        ],
        Poly::new(vec![r(1, 1), r(0, 1), r(1, 4)]),
    );
    let err = canal_surface_rational(&fat, &opts(), Some(&through_vertex)).expect_err("singular");
    assert!(err.to_string().contains("singular at (s, t)"), "{err}");
    let (s, t, reason) = witness(err);
    assert!(reason.contains("F = "), "{reason}");
    let g = QuadraticCanal::from_spine(&fat).expect("Γ");
    assert!(
        regularity_at(&fat, &g, &s, &t).0 <= r(0, 1),
        "F > 0 at the witness ({s}, {t})"
    );
    // F = 15(4u² + 1)(240u⁶ + 183u⁴ + 24u² − 16)/64 > 0 exactly for |u| > 0.4636 (sympy):
    // the gallery's rectangle reaches u ≈ 0.36 and is refused, [1, 3/2] × [−1/2, 1/2]
    // (u from about 0.63 to 2) is regular
    assert!(canal_surface_rational(&fat, &opts(), Some(&dom)).is_err());
    let off = [r(1, 1), r(3, 2), r(-1, 2), r(1, 2)];
    let RationalCanal::Cyclographic(c) =
        canal_surface_rational(&fat, &opts(), Some(&off)).expect("regular")
    else {
        panic!("expected the fallback");
    };
    assert!(c.all_hold());
}

#[test]
fn fallback_errors_are_named() {
    let spine = example_2_3();
    // Γ applies but no rectangle is given
    match canal_surface_rational(&spine, &opts(), None) {
        Err(CanalError::CyclographicDomainNeeded { radicand }) => assert_eq!(radicand, "15"),
        other => panic!("{other:?}"),
    }
    // a rectangle across the pole circle 5(s² + t²) = 3
    let dom = [r(-1, 1), r(-1, 4), r(1, 8), r(1, 2)];
    match canal_surface_rational(&spine, &opts(), Some(&dom)) {
        Err(CanalError::InvalidArgument(m)) => assert!(m.contains("pole"), "{m}"),
        other => panic!("{other:?}"),
    }
    // an empty rectangle
    let dom = [r(1, 2), r(-1, 8), r(1, 8), r(1, 2)];
    assert!(matches!(
        canal_surface_rational(&spine, &opts(), Some(&dom)),
        Err(CanalError::InvalidArgument(_))
    ));
    // a cone m = (0, 0, t), r = t/2: D = 3/4 needs Q(√3), and k̇ is constant, so
    // ⟨w, k̇⟩ = 0 does not involve the spine parameter: Γ does not apply
    let cone = CanalSpine::polynomial(
        [Poly::zero(), Poly::zero(), Poly::from_ints(&[0, 1])],
        Poly::new(vec![r(0, 1), r(1, 2)]),
    );
    let dom = [r(1, 4), r(1, 2), r(1, 4), r(1, 2)];
    match canal_surface_rational(&cone, &opts(), Some(&dom)) {
        Err(CanalError::IrrationalSplit { radicand }) => assert_eq!(radicand, "3"),
        other => panic!("{other:?}"),
    }
    // a family that splits over Q keeps its spine-parameter construction
    let pipe = CanalSpine::polynomial(
        [Poly::from_ints(&[0, 1]), Poly::zero(), Poly::zero()],
        Poly::new(vec![r(1, 4)]),
    );
    assert!(matches!(
        canal_surface_rational(&pipe, &opts(), Some(&dom)),
        Ok(RationalCanal::Spine(..))
    ));
}

fn small() -> impl Strategy<Value = i64> {
    -3i64..=3
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    /// Random quadratic families: whenever the spine-parameter constructions need a
    /// quadratic field, Γ is built over Q on some small rectangle, certified, and the f64
    /// construction agrees with the exact one.
    #[test]
    fn random_quadratic_families(c in proptest::array::uniform8(small())) {
        let spine = CanalSpine::polynomial(
            [
                Poly::from_ints(&[0, 2 + c[0].abs(), c[1]]),
                Poly::from_ints(&[0, c[2], c[3]]),
                Poly::from_ints(&[0, c[4], c[5]]),
            ],
            Poly::new(vec![r(1, 1), r(c[6], 4), r(c[7], 8)]),
        );
        let mut built = None;
        'outer: for i in 0..4 {
            for j in 0..4 {
                let dom = [r(i, 4), r(2 * i + 1, 8), r(j, 4), r(2 * j + 1, 8)];
                match canal_surface_rational(&spine, &opts(), Some(&dom)) {
                    Ok(b) => { built = Some((b, dom)); break 'outer; }
                    Err(CanalError::InvalidArgument(_) | CanalError::SingularCyclographic { .. }) => continue,
                    Err(_) => return Ok(()),
                }
            }
        }
        let Some((built, dom)) = built else { return Ok(()) };
        match built {
            RationalCanal::Spine(s, _) => prop_assert!(s.all_hold()),
            RationalCanal::Cyclographic(g) => {
                prop_assert!(g.all_hold());
                // the regularity certificate, checked independently at points of the rectangle
                let [s0, s1, t0, t1] = dom;
                for (i, j) in [(0, 0), (1, 2), (2, 1), (3, 3), (4, 4)] {
                    let s = s0.clone() + (s1.clone() - s0.clone()) * r(i, 4);
                    let t = t0.clone() + (t1.clone() - t0.clone()) * r(j, 4);
                    let (fv, rad) = regularity_at(&spine, g.surface(), &s, &t);
                    prop_assert!(fv > r(0, 1) && rad != r(0, 1));
                }
                let f = QuadraticCanal::from_spine(&spine.map_scalar(Scalar::to_f64)).expect("f64");
                let (s, t) = (r(1, 3), r(2, 7));
                if let (Ok(x), Ok(y)) = (g.surface().eval(&s, &t), f.eval(&Scalar::to_f64(&s), &Scalar::to_f64(&t))) {
                    for k in 0..3 {
                        let v = Scalar::to_f64(&x[k]);
                        prop_assert!((v - y[k]).abs() <= 1e-9 * (1.0 + v.abs()), "{} vs {}", v, y[k]);
                    }
                }
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// (2.10) with an arbitrary rational normal field: a rational point n₀(t) on every circle of
// normals instead of a split of |ṁ|² − ṙ².

#[test]
fn canal_surface_from_a_rational_normal_field() {
    // m = (t, t²/2, 0), r = t: ṁ = (1, t, 0), ṙ = 1, and n₀ = (−1, 0, 0) is a unit normal
    // with ⟨n₀, ṁ⟩ + ṙ = 0 (docs/math/lines-and-canal.md, Errata G9 family)
    let spine = CanalSpine::polynomial(
        [
            Poly::from_ints(&[0, 1]),
            Poly::new(vec![r(0, 1), r(0, 1), r(1, 2)]),
            Poly::zero(),
        ],
        Poly::from_ints(&[0, 1]),
    );
    let n0 = [Poly::from_ints(&[-1]), Poly::zero(), Poly::zero()];
    let c = canal_surface_from_normal_field(&spine, &n0, &Poly::from_ints(&[1])).expect("built");
    let certs = c.certify();
    assert!(Certificate::all_hold(&certs), "{certs:#?}");
    assert_eq!(certs.len(), 4);
    assert_eq!(c.bidegree().1, 2, "circles of degree 2 in u");
    // a point is at distance r(t) from m(t)
    let (t, u) = (r(1, 2), r(3, 1));
    let x = c.eval(&t, &u).expect("point");
    let (m, rad) = spine.eval(&t).expect("sphere");
    let dist = (0..3).fold(r(0, 1), |a, k| a + (x[k].clone() - m[k].clone()).pow(2));
    assert_eq!(dist, rad.clone() * rad);
    assert!(c.patch((r(1, 4), r(1, 1)), (r(0, 1), r(1, 1))).is_ok());
    // not a unit field / not on the circles of normals: named errors
    let bad = [Poly::from_ints(&[0, 1]), Poly::zero(), Poly::zero()];
    match canal_surface_from_normal_field(&spine, &bad, &Poly::from_ints(&[1])) {
        Err(CanalError::InvalidArgument(m)) => assert!(m.contains("unit"), "{m}"),
        other => panic!("{other:?}"),
    }
    let off = [Poly::from_ints(&[1]), Poly::zero(), Poly::zero()];
    match canal_surface_from_normal_field(&spine, &off, &Poly::from_ints(&[1])) {
        Err(CanalError::InvalidArgument(m)) => assert!(m.contains("circles of normals"), "{m}"),
        other => panic!("{other:?}"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    /// Random families built around a random rational unit vector n₀ = σ(a, b) (inverse
    /// stereographic projection): m random, r = c − ⟨n₀, m⟩ so that ⟨n₀, ṁ⟩ + ṙ = 0; the
    /// surface is certified and f64 agrees with exact (on the exact spheres where the exact
    /// path cancelled a common factor of ṁ and ṙ).
    #[test]
    fn random_normal_fields(
        a in small(), b in small(), c in proptest::array::uniform6(small()), k in 1i64..=3,
    ) {
        let den = 1 + a * a + b * b;
        let n0 = [r(2 * a, den), r(2 * b, den), r(1 - a * a - b * b, den)];
        let m = [
            Poly::from_ints(&[0, 1, c[0]]),
            Poly::from_ints(&[0, c[1], c[2]]),
            Poly::from_ints(&[0, c[3], c[4]]),
        ];
        let mut rad = Poly::new(vec![r(k, 1)]);
        for (i, mi) in m.iter().enumerate() {
            rad = &rad - &mi.scale(&n0[i]);
        }
        let spine = CanalSpine::polynomial(m, rad);
        let nf = n0.clone().map(|x| Poly::new(vec![x]));
        let built = match canal_surface_from_normal_field(&spine, &nf, &Poly::from_ints(&[1])) {
            Ok(b) => b,
            Err(CanalError::InvalidArgument(m)) if m.contains("ṁ ≡ 0") => return Ok(()),
            Err(e) => return Err(TestCaseError::fail(format!("{e}"))),
        };
        prop_assert!(built.all_hold());
        let nf64 = nf.clone().map(|p| p.map(Scalar::to_f64));
        let f = canal_surface_from_normal_field(&spine.map_scalar(Scalar::to_f64), &nf64, &Poly::new(vec![1.0]))
            .map_err(|e| TestCaseError::fail(format!("{e}")))?;
        prop_assert!(f.all_hold());
        let (t, u) = (r(2, 5), r(-3, 7));
        // The exact path divides (ṁ, ṙ) by their gcd, the f64 path cannot: when the gcd g(t)
        // is not constant (e.g. a spine on a line) the circles are parametrized by u·g(t)
        // instead of u — the same surface, another parametrization. Then the f64 point is
        // checked on the exact sphere instead of against the exact point.
        let raw_degree = spine.center_polys().iter().chain([spine.radius_poly()]).filter_map(|p| p.degree()).max().unwrap_or(0);
        let cancelled = spine.derivative_numerators().map(|p| p.iter().filter_map(|q| q.degree()).max().unwrap_or(0) + 1 < raw_degree).unwrap_or(false);
        if let (Ok(x), Ok(y)) = (built.eval(&t, &u), f.eval(&Scalar::to_f64(&t), &Scalar::to_f64(&u))) {
            if cancelled {
                let c = spine.center_polys().clone().map(|p| Scalar::to_f64(&p.eval(&t)));
                let rad = Scalar::to_f64(&spine.radius_poly().eval(&t));
                let d2: f64 = (0..3).map(|i| (y[i] - c[i]) * (y[i] - c[i])).sum();
                prop_assert!((d2 - rad * rad).abs() <= 1e-9 * (1.0 + rad * rad), "f64 point off the sphere: {} vs {}", d2, rad * rad);
            } else {
                for i in 0..3 {
                    let v = Scalar::to_f64(&x[i]);
                    prop_assert!((v - y[i]).abs() <= 1e-9 * (1.0 + v.abs()), "{} vs {}", v, y[i]);
                }
            }
        }
    }
}

/// Regression: a spine on a line, m = (t − t²)(1, −2, −1), r = 1 + t − t², normal field
/// (0, 0, 1). ṁ and ṙ share the factor 1 − 2t, which the exact path cancels: its circles
/// are parametrized differently from the f64 ones, and both lie on the exact spheres.
#[test]
fn normal_field_on_a_line_spine_f64_points_lie_on_the_spheres() {
    let m = [
        Poly::from_ints(&[0, 1, -1]),
        Poly::from_ints(&[0, -2, 2]),
        Poly::from_ints(&[0, -1, 1]),
    ];
    let rad = Poly::from_ints(&[1, 1, -1]);
    let spine = CanalSpine::polynomial(m, rad);
    let nf = [r(0, 1), r(0, 1), r(1, 1)].map(|x| Poly::new(vec![x]));
    let built =
        canal_surface_from_normal_field(&spine, &nf, &Poly::from_ints(&[1])).expect("exact");
    assert!(built.all_hold());
    let nf64 = nf.clone().map(|p| p.map(Scalar::to_f64));
    let f = canal_surface_from_normal_field(
        &spine.map_scalar(Scalar::to_f64),
        &nf64,
        &Poly::new(vec![1.0]),
    )
    .expect("f64");
    assert!(f.all_hold());
    for (t, u) in [(0.4, -3.0 / 7.0), (0.2, 1.0 / 7.0), (0.6, 2.0 / 7.0)] {
        let y = f.eval(&t, &u).expect("f64 point");
        let c = [t - t * t, -2.0 * (t - t * t), -(t - t * t)];
        let rad = 1.0 + t - t * t;
        let d2: f64 = (0..3).map(|i| (y[i] - c[i]) * (y[i] - c[i])).sum();
        assert!((d2 - rad * rad).abs() < 1e-12, "{d2} vs {}", rad * rad);
    }
}
