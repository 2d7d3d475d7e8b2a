//! Alternative generations of line nets and congruences of order one (Gruber 2008
//! §1.1.6–1.1.8): random exact inputs, every certificate exact, `f64` agreement, named
//! errors for degenerate input.

use proptest::prelude::*;
use rcagd::lines::{
    regulus_meeting, CongruenceKind, CubicChordCongruence, GeneratedNet, GenerationError, Line,
    LinearComplex, LinearCongruence, OneNCongruence, OrderOneError,
};
use rcagd::Certified;
use rcagd_algebra::{Poly, Rational};

fn q(n: i64) -> Rational {
    Rational::from(n)
}

fn v4(a: [i64; 4]) -> [Rational; 4] {
    a.map(q)
}

fn to_f64<const N: usize>(a: &[Rational; N]) -> [f64; N] {
    core::array::from_fn(|k| a[k].to_f64().value())
}

fn small() -> impl Strategy<Value = i64> {
    -5i64..6
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// α: x₃ = 0 and β: x₂ = 0 with κ(s) ⊂ s (b₀, b₁ have x₃ = 0): a net whenever the data
    /// are non-degenerate; the f64 construction agrees.
    #[test]
    fn collineation_nets(b in proptest::array::uniform8(small()), w in 1i64..4) {
        let a = [v4([1, 0, 0, 0]), v4([0, 1, 0, 0]), v4([0, 0, 1, 0])];
        let bb = [
            v4([w, b[0], 0, 0]),
            v4([b[1], b[2], 0, 0]),
            v4([b[3], b[4], 0, b[5]]),
        ];
        match GeneratedNet::from_plane_collineation(&a, &bb) {
            Ok(g) => {
                prop_assert!(g.all_hold(), "{:?}", g.certify());
                let af = a.clone().map(|p| to_f64(&p));
                let bf = bb.clone().map(|p| to_f64(&p));
                let gf = GeneratedNet::from_plane_collineation(&af, &bf).expect("f64");
                prop_assert!(gf.all_hold(), "{:?}", gf.certify());
                prop_assert_eq!(gf.congruence().kind(), g.congruence().kind());
            }
            Err(GenerationError::NotAPlane(_)) | Err(GenerationError::SamePlane)
            | Err(GenerationError::NotANet { .. }) => {}
            Err(e) => prop_assert!(false, "unexpected {e}"),
        }
    }

    /// Two reguli of a random net (the net lines meeting two random lines) give the net back.
    #[test]
    fn reguli_span_their_net(c in proptest::array::uniform6(small()), d in proptest::array::uniform6(small()),
                             p in proptest::array::uniform6(small())) {
        let (Ok(k1), Ok(k2)) = (LinearComplex::new(c.map(q)), LinearComplex::new(d.map(q))) else {
            return Ok(());
        };
        let Ok(net) = LinearCongruence::new(k1, k2) else { return Ok(()) };
        if net.kind() == CongruenceKind::Degenerate {
            return Ok(());
        }
        let l = |a: [i64; 3], b: [i64; 3]| Line::from_affine_points(&a.map(q), &b.map(q));
        let (Ok(g1), Ok(g2)) = (l([p[0], p[1], 1], [p[2], 0, p[3]]), l([0, p[4], p[5]], [1, 2, 3])) else {
            return Ok(());
        };
        let (Ok(r1), Ok(r2)) = (regulus_meeting(&net, &g1), regulus_meeting(&net, &g2)) else {
            return Ok(());
        };
        match GeneratedNet::from_reguli(&r1, &r2) {
            Ok(g) => {
                prop_assert!(g.all_hold(), "{:?}", g.certify());
                prop_assert_eq!(g.congruence().kind(), net.kind());
                for x in g.congruence().sample_lines() {
                    prop_assert!(net.contains(&x));
                }
            }
            // the two reguli coincide (g₁, g₂ in a common complex with the net)
            Err(GenerationError::NotANet { complexes, .. }) => prop_assert!(complexes > 2),
            Err(e) => prop_assert!(false, "unexpected {e}"),
        }
    }

    /// Tangents of the ruled surface X(u, v) = p(u) + v q(u) with random quadratic p, q.
    #[test]
    fn ruled_surface_tangent_nets(c in proptest::array::uniform12(small()), u0 in -3i64..4) {
        let p = [Poly::from_ints(&[1]), Poly::from_ints(&[c[0], c[1]]), Poly::from_ints(&[c[2], 0, c[3]]), Poly::from_ints(&[0, c[4]])];
        let qq = [Poly::from_ints(&[0, c[5]]), Poly::from_ints(&[c[6]]), Poly::from_ints(&[c[7], c[8]]), Poly::from_ints(&[c[9], c[10], c[11]])];
        match GeneratedNet::from_ruled_surface_tangents(&p, &qq, &q(u0)) {
            Ok(g) => {
                prop_assert!(g.all_hold(), "{:?}", g.certify());
                let pf = p.clone().map(|x| x.map(|c| c.to_f64().value()));
                let qf = qq.clone().map(|x| x.map(|c| c.to_f64().value()));
                let gf = GeneratedNet::from_ruled_surface_tangents(&pf, &qf, &(u0 as f64)).expect("f64");
                prop_assert!(gf.all_hold(), "{:?}", gf.certify());
            }
            Err(GenerationError::TorsalGenerator(_)) | Err(GenerationError::Net(_)) => {}
            Err(e) => prop_assert!(false, "unexpected {e}"),
        }
    }

    /// Chord congruences of random twisted cubics: certificates, and the chord through a
    /// random point contains it (f64 agrees).
    #[test]
    fn cubic_chords(a in proptest::array::uniform16(small()), p in proptest::array::uniform4(small())) {
        let m: [[Rational; 4]; 4] = core::array::from_fn(|i| core::array::from_fn(|k| q(a[4 * i + k])));
        match CubicChordCongruence::new(m.clone()) {
            Ok(c) => {
                prop_assert!(c.all_hold(), "{:?}", c.certify());
                let pt = p.map(q);
                match c.chord_through(&pt) {
                    Ok(e) => {
                        let l = c.chord(&e).expect("chord");
                        prop_assert!(l.contains_point(&pt));
                        let cf = CubicChordCongruence::new(m.map(|r| to_f64(&r))).expect("f64");
                        let ef = cf.chord_through(&to_f64(&pt)).expect("f64 chord");
                        let lf = cf.chord(&ef).expect("f64 line");
                        prop_assert!(lf.contains_point(&to_f64(&pt)));
                    }
                    Err(OrderOneError::SingularPoint(_)) => {}
                    Err(e) => prop_assert!(false, "unexpected {e}"),
                }
            }
            Err(OrderOneError::NotATwistedCubic) => {}
            Err(e) => prop_assert!(false, "unexpected {e}"),
        }
    }

    /// (1, 2)-congruences: a conic meeting the x-axis once, k(t) = (1 + a t², t, b t², c t)
    /// ⇒ k meets {x₂ = x₃ = 0} at t = 0.
    #[test]
    fn one_two_congruences(a in small(), b in small(), c in small(), p in proptest::array::uniform4(small())) {
        let k = [Poly::from_ints(&[1, 0, a]), Poly::from_ints(&[0, 1]), Poly::from_ints(&[0, 0, b]), Poly::from_ints(&[0, c])];
        match OneNCongruence::new(v4([1, 0, 0, 0]), v4([0, 1, 0, 0]), k) {
            Ok(cg) => {
                prop_assert_eq!(cg.order_class(), (1, 2));
                prop_assert!(cg.all_hold(), "{:?}", cg.certify());
                if let Ok(l) = cg.line_through(&p.map(q)) {
                    prop_assert!(l.contains_point(&p.map(q)));
                    let g = Line::from_points(&v4([1, 0, 0, 0]), &v4([0, 1, 0, 0])).expect("g");
                    prop_assert!(l.meets(&g));
                }
            }
            Err(OrderOneError::NotOrderOne { .. }) | Err(OrderOneError::CurveInPlane) => {}
            Err(e) => prop_assert!(false, "unexpected {e}"),
        }
    }
}

#[test]
fn one_n_congruence_errors() {
    // a twisted cubic meeting the line x₁ = x₃ = 0 once is no (1, 3)-congruence (needs 2
    // points; its tangent x₂ = x₃ = 0 would do: it meets the cubic twice at t = 0)
    let k = [
        Poly::from_ints(&[1]),
        Poly::from_ints(&[0, 1]),
        Poly::from_ints(&[0, 0, 1]),
        Poly::from_ints(&[0, 0, 0, 1]),
    ];
    assert!(matches!(
        OneNCongruence::new(v4([1, 0, 0, 0]), v4([0, 0, 1, 0]), k.clone()),
        Err(OrderOneError::NotOrderOne {
            order: 3,
            meets: 1,
            needed: 2
        })
    ));
    let tangent = OneNCongruence::new(v4([1, 0, 0, 0]), v4([0, 1, 0, 0]), k).expect("tangent");
    assert!(tangent.all_hold(), "{:?}", tangent.certify());
    // a conic in a plane through the line
    let k = [
        Poly::from_ints(&[1, 0, 1]),
        Poly::from_ints(&[0, 1]),
        Poly::from_ints(&[0]),
        Poly::from_ints(&[0, 1]),
    ];
    assert!(matches!(
        OneNCongruence::new(v4([1, 0, 0, 0]), v4([0, 1, 0, 0]), k),
        Err(OrderOneError::CurveInPlane)
    ));
    // a planar cubic is no twisted cubic
    assert!(matches!(
        CubicChordCongruence::new([
            v4([1, 0, 0, 0]),
            v4([0, 1, 0, 0]),
            v4([0, 0, 1, 0]),
            v4([0, 1, 1, 0])
        ]),
        Err(OrderOneError::NotATwistedCubic)
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// Cyclographic images of random 2-planes of R^{3,1} (Gruber §1.2.2): the planes touch
    /// every cycle of the 2-plane exactly (over Q(√d)); f64 gives the same type and the
    /// same number of planes.
    #[test]
    fn plane_images(a in proptest::array::uniform4(small()), g in proptest::array::uniform4(small()),
                    h in proptest::array::uniform4(small())) {
        use rcagd::cyclographic::{plane_image, CyclographicError};
        let (a, g, h) = (a.map(q), g.map(q), h.map(q));
        match plane_image(&a, &g, &h) {
            Ok(img) => {
                prop_assert!(img.all_hold(), "{:?}", img.certify());
                let f = plane_image(&to_f64(&a), &to_f64(&g), &to_f64(&h)).expect("f64");
                prop_assert!(f.all_hold(), "{:?}", f.certify());
                prop_assert_eq!(f.kind, img.kind);
                prop_assert_eq!(f.planes.len(), img.planes.len());
            }
            Err(CyclographicError::ZeroVector(_)) => {}
            Err(e) => prop_assert!(false, "unexpected {e}"),
        }
    }
}

// ---------------------------------------------------------------------------------------
// Congruences of order m > 1: parametrized line families, normal congruences.

/// `det`-type cross product: the plane through three points (or the point on three planes).
fn cross4(a: &[Rational; 4], b: &[Rational; 4], c: &[Rational; 4]) -> [Rational; 4] {
    let m3 = |i: usize, j: usize, k: usize| -> Rational {
        a[i].clone() * (b[j].clone() * c[k].clone() - b[k].clone() * c[j].clone())
            - a[j].clone() * (b[i].clone() * c[k].clone() - b[k].clone() * c[i].clone())
            + a[k].clone() * (b[i].clone() * c[j].clone() - b[j].clone() * c[i].clone())
    };
    [m3(1, 2, 3), -m3(0, 2, 3), m3(0, 1, 3), -m3(0, 1, 2)]
}

/// The pencil ∩ bundle generation of the parabolic net (Gruber §1.1.6): the pencil
/// x + u z = 0 about the y-axis and the bundle through P = (1, 0, 0) with φ₂ = [a, P]
/// (z = 0) give the net of the vertices c(u) = (0, 1/u, 0) on the y-axis.
#[test]
fn pencil_and_bundle_generation() {
    let e0 = v4([0, 1, 0, 0]);
    let e1 = v4([0, 0, 0, 1]);
    let f = [v4([-1, 1, 0, 0]), v4([0, 0, 1, 0]), v4([0, 0, 0, 1])];
    let g = GeneratedNet::from_pencil_and_bundle(&e0, &e1, &f).expect("parabolic net");
    assert!(g.all_hold(), "{:#?}", g.certify());
    assert_eq!(g.congruence().kind(), CongruenceKind::Parabolic);
    assert!(g.line_net().is_some());
    assert!(g
        .certify()
        .iter()
        .any(|c| c.property.contains("passes through the vertex c(u)")));
    // f64 agrees: the same construction succeeds and certifies
    let gf = GeneratedNet::from_pencil_and_bundle(
        &to_f64(&e0),
        &to_f64(&e1),
        &f.clone().map(|x| to_f64(&x)),
    )
    .expect("f64");
    assert!(gf.all_hold());
    // φ₂ not through the axis: the lines through one point a ∩ φ₂ (a bundle), not a net
    let bad = [v4([-1, 1, 0, 0]), v4([0, 0, 1, 0]), v4([-1, 1, 0, 1])];
    assert!(matches!(
        GeneratedNet::from_pencil_and_bundle(&e0, &e1, &bad),
        Err(GenerationError::NotANet { .. })
    ));
    // the carrier point on the axis, dependent bundle planes, a degenerate pencil
    assert!(matches!(
        GeneratedNet::from_pencil_and_bundle(
            &e0,
            &e1,
            &[v4([0, 1, 0, 0]), v4([-1, 0, 1, 0]), v4([0, 0, 0, 1])]
        ),
        Err(GenerationError::DegenerateBundle(_))
    ));
    assert!(matches!(
        GeneratedNet::from_pencil_and_bundle(&e0, &e1, &[f[0].clone(), f[0].clone(), f[2].clone()]),
        Err(GenerationError::DegenerateBundle(_))
    ));
    assert!(matches!(
        GeneratedNet::from_pencil_and_bundle(&e0, &e0, &f),
        Err(GenerationError::DegeneratePencil)
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    /// Random axis a = A ∨ B, carrier point P, pencil planes [A, B, Xᵢ], bundle planes
    /// [P, Yᵢ, Zᵢ] and φ₂ = [A, B, P]: a certified parabolic net whenever the data are
    /// non-degenerate.
    #[test]
    fn random_pencil_and_bundle(a in proptest::array::uniform4(small()), b in proptest::array::uniform4(small()),
                                p in proptest::array::uniform4(small()), x in proptest::array::uniform8(small()),
                                y in proptest::array::uniform16(small())) {
        let (a, b, p) = (v4(a), v4(b), v4(p));
        let pt = |s: &[i64], k: usize| v4([s[4 * k], s[4 * k + 1], s[4 * k + 2], s[4 * k + 3]]);
        let e0 = cross4(&a, &b, &pt(&x, 0));
        let e1 = cross4(&a, &b, &pt(&x, 1));
        let f = [
            cross4(&p, &pt(&y, 0), &pt(&y, 1)),
            cross4(&p, &pt(&y, 2), &pt(&y, 3)),
            cross4(&a, &b, &p),
        ];
        match GeneratedNet::from_pencil_and_bundle(&e0, &e1, &f) {
            Ok(g) => {
                prop_assert!(g.all_hold(), "{:?}", g.certify());
                prop_assert_eq!(g.congruence().kind(), CongruenceKind::Parabolic);
            }
            Err(GenerationError::DegeneratePencil)
            | Err(GenerationError::DegenerateBundle(_))
            | Err(GenerationError::NotANet { .. })
            | Err(GenerationError::Net(_)) => {}
            Err(e) => prop_assert!(false, "unexpected {e}"),
        }
    }
}

mod order_greater_one {
    use rcagd::lines::ParametrizedCongruence;
    use rcagd::Certified;
    use rcagd_algebra::mpoly::MPoly;
    use rcagd_algebra::{Certificate, Rational, Scalar};

    fn p(s: &[(i64, u32, u32)]) -> MPoly<Rational> {
        s.iter().fold(MPoly::zero(2), |a, &(c, i, j)| {
            &a + &MPoly::monomial(2, &[i, j], Rational::from(c))
        })
    }

    /// A surface with its expected `(order, class, μ)`.
    type Case = (&'static str, [MPoly<Rational>; 4], (usize, usize, usize));

    fn w() -> MPoly<Rational> {
        p(&[(1, 0, 0), (1, 2, 0), (1, 0, 2)])
    }

    /// The normal congruences of quadrics, against the classical counts: a sphere's normals
    /// form the bundle through its centre (order 1, class 0, every line met twice: μ = 2);
    /// the paraboloid of revolution (3, 2), the elliptic paraboloid (5, 2) and the triaxial
    /// ellipsoid (6, 2) (normals through a generic point; G. Salmon, "A Treatise on the
    /// Analytic Geometry of Three Dimensions", 1882, §§ 199–200).
    #[test]
    fn normal_congruences_of_quadrics() {
        let cases: Vec<Case> = vec![
            (
                "sphere",
                [
                    w(),
                    p(&[(2, 1, 0)]),
                    p(&[(2, 0, 1)]),
                    p(&[(1, 0, 0), (-1, 2, 0), (-1, 0, 2)]),
                ],
                (1, 0, 2),
            ),
            (
                "paraboloid of revolution",
                [
                    p(&[(1, 0, 0)]),
                    p(&[(1, 1, 0)]),
                    p(&[(1, 0, 1)]),
                    p(&[(1, 2, 0), (1, 0, 2)]),
                ],
                (3, 2, 1),
            ),
            (
                "elliptic paraboloid",
                [
                    p(&[(1, 0, 0)]),
                    p(&[(1, 1, 0)]),
                    p(&[(1, 0, 1)]),
                    p(&[(1, 2, 0), (2, 0, 2)]),
                ],
                (5, 2, 1),
            ),
            (
                "ellipsoid with semi-axes 1, 2, 3",
                [
                    w(),
                    p(&[(2, 1, 0)]),
                    p(&[(4, 0, 1)]),
                    p(&[(3, 0, 0), (-3, 2, 0), (-3, 0, 2)]),
                ],
                (6, 2, 1),
            ),
        ];
        for (name, x, want) in cases {
            let c = ParametrizedCongruence::normals(x).expect("normals");
            let certs = c.certify();
            assert!(Certificate::all_hold(&certs), "{name}: {certs:#?}");
            assert!(certs
                .iter()
                .any(|c| c.property.contains("orthogonal to the surface")));
            assert_eq!(c.order_and_class().expect("count"), want, "{name}");
            let oc = c.order_class(3).expect("decided");
            assert_eq!((oc.order, oc.class, oc.mu), want, "{name}: {oc:?}");
            assert!(oc.certificate().holds, "{name}: {oc:?}");
        }
        // a family that is not built as normals carries no normality claim
        let x = [
            w(),
            p(&[(2, 1, 0)]),
            p(&[(2, 0, 1)]),
            p(&[(1, 0, 0), (-1, 2, 0), (-1, 0, 2)]),
        ];
        let bad = ParametrizedCongruence::new(
            x.clone(),
            [MPoly::zero(2), x[1].clone(), x[2].clone(), x[1].clone()],
        )
        .expect("lines");
        assert!(ParametrizedCongruence::normals(x).is_ok());
        assert!(
            !bad.certify()
                .iter()
                .any(|c| c.property.contains("orthogonal to the surface")),
            "a general family has no normality certificate"
        );
        // a curve has no normal congruence: a named error
        let curve = [
            p(&[(1, 0, 0)]),
            p(&[(1, 1, 0)]),
            p(&[(1, 2, 0)]),
            p(&[(1, 3, 0)]),
        ];
        assert!(ParametrizedCongruence::normals(curve).is_err());
    }

    /// The lines meeting a line g and a conic disjoint from it: order 2 (the plane P ∨ g meets
    /// the conic twice), class 2 (a plane meets g once and the conic twice); the focal sheets
    /// are the conic and the line themselves (`A₀ ≡ A₂ ≡ 0`). The secants of a twisted cubic:
    /// (1, 3), every chord counted from both ends (μ = 2).
    #[test]
    fn a_two_two_congruence_and_the_cubic_secants() {
        // conic (1 + u², 2u, 0, 1 − u²)… in the plane x₂ = 0; g: (1, 0, 0, 0) + v (0, 0, 1, 0)
        // shifted off the conic: g(v) = (1, 5, v, 0)
        let conic = [
            p(&[(1, 0, 0), (1, 2, 0)]),
            p(&[(2, 1, 0)]),
            MPoly::zero(2),
            p(&[(1, 0, 0), (-1, 2, 0)]),
        ];
        let g = [
            p(&[(1, 0, 0)]),
            p(&[(5, 0, 0)]),
            p(&[(1, 0, 1)]),
            MPoly::zero(2),
        ];
        let c = ParametrizedCongruence::new(conic.clone(), g.clone()).expect("(2, 2)");
        assert_eq!(c.order_and_class().expect("count"), (2, 2, 1));
        let sheets = c.rational_focal_sheets().expect("focal curves");
        assert_eq!(sheets, [conic, g]);
        let certs = c.certify();
        assert!(Certificate::all_hold(&certs), "{certs:#?}");
        assert_eq!(
            certs
                .iter()
                .filter(|c| c.property.contains("focal sheet"))
                .count(),
            4
        );
        // the twisted cubic (1, t, t², t³): chords k(u) ∨ k(v)
        let k = |var: u32| -> [MPoly<Rational>; 4] {
            core::array::from_fn(|e| {
                let ex = e as u32;
                if var == 0 {
                    p(&[(1, ex, 0)])
                } else {
                    p(&[(1, 0, ex)])
                }
            })
        };
        let chords = ParametrizedCongruence::new(k(0), k(1)).expect("chords");
        assert_eq!(chords.order_and_class().expect("count"), (1, 3, 2));
        // not two-parametric: a regulus as p(u) ∨ q(u) (no v) is refused
        let ruled = ParametrizedCongruence::new(
            [
                p(&[(1, 0, 0)]),
                p(&[(1, 1, 0)]),
                MPoly::zero(2),
                MPoly::zero(2),
            ],
            [
                MPoly::zero(2),
                MPoly::zero(2),
                p(&[(1, 0, 0)]),
                p(&[(1, 1, 0)]),
            ],
        );
        assert!(ruled.is_err());
    }

    /// Order and class decided over independent choices: the maximum is reached by at least
    /// two of them (a non-generic choice only lowers a count), certified.
    #[test]
    fn order_class_decided_over_choices() {
        let par = [
            p(&[(1, 0, 0)]),
            p(&[(1, 1, 0)]),
            p(&[(1, 0, 1)]),
            p(&[(1, 2, 0), (1, 0, 2)]),
        ];
        let c = ParametrizedCongruence::normals(par).expect("normals");
        let oc = c.order_class(3).expect("decided");
        assert_eq!((oc.order, oc.class, oc.mu), (3, 2, 1));
        assert!(oc.certificate().holds, "{oc:?}");
        assert!(oc.agreeing() >= 2);
        // the (2, 2)-congruence of a conic and a line
        let conic = [
            p(&[(1, 0, 0), (1, 2, 0)]),
            p(&[(2, 1, 0)]),
            MPoly::zero(2),
            p(&[(1, 0, 0), (-1, 2, 0)]),
        ];
        let g = [
            p(&[(1, 0, 0)]),
            p(&[(5, 0, 0)]),
            p(&[(1, 0, 1)]),
            MPoly::zero(2),
        ];
        let c = ParametrizedCongruence::new(conic, g).expect("(2, 2)");
        let oc = c.order_class(3).expect("decided");
        assert_eq!((oc.order, oc.class, oc.mu), (2, 2, 1));
        assert!(oc.certificate().holds);
    }

    /// The normal congruence of the paraboloid of revolution z = u² + v² has rational focal
    /// sheets (its principal curvatures are rational in u, v: the discriminant of the focal
    /// polynomial is a square): the axis (a curve) and the evolute surface, certified on the
    /// lines and focal. The elliptic paraboloid's sheets are irrational (no square).
    #[test]
    fn focal_sheets_of_a_square_discriminant() {
        let par = [
            p(&[(1, 0, 0)]),
            p(&[(1, 1, 0)]),
            p(&[(1, 0, 1)]),
            p(&[(1, 2, 0), (1, 0, 2)]),
        ];
        let c = ParametrizedCongruence::normals(par).expect("normals");
        let sheets = c.rational_focal_sheets().expect("rational sheets");
        let kinds: Vec<bool> = sheets
            .iter()
            .map(ParametrizedCongruence::is_surface)
            .collect();
        assert_eq!(kinds.iter().filter(|k| **k).count(), 1, "one surface");
        // the curve sheet is the axis x = y = 0
        let axis = sheets
            .iter()
            .find(|s| !ParametrizedCongruence::is_surface(s))
            .expect("axis");
        assert!(axis[1].is_zero() && axis[2].is_zero());
        let certs = c.certify();
        assert!(Certificate::all_hold(&certs), "{certs:#?}");
        assert_eq!(
            certs
                .iter()
                .filter(|c| c.property.contains("focal sheet"))
                .count(),
            4
        );
        // the evolute at (u, v) = (1, 0): the centre of curvature of the meridian parabola
        // z = x² at x = 1 is (−4, 0, 7/2)
        let ev = sheets
            .iter()
            .find(|s| ParametrizedCongruence::is_surface(s))
            .expect("evolute");
        let at: Vec<Rational> = ev
            .iter()
            .map(|x| {
                x.eval(&[Rational::from(1), Rational::from(0)])
                    .expect("eval")
            })
            .collect();
        let aff: Vec<Rational> = at[1..].iter().map(|x| x.clone() / at[0].clone()).collect();
        assert_eq!(
            aff,
            vec![
                Rational::from(-4),
                Rational::from(0),
                Rational::from_ratio(7, 2)
            ]
        );
        let ell = ParametrizedCongruence::normals([
            p(&[(1, 0, 0)]),
            p(&[(1, 1, 0)]),
            p(&[(1, 0, 1)]),
            p(&[(1, 2, 0), (2, 0, 2)]),
        ])
        .expect("normals");
        assert!(ell.rational_focal_sheets().is_none());
    }
}
