//! Regular quadrics as PN surfaces (Peternell, "Rational Parametrizations for Envelopes of
//! Quadric Families", Theorem 4.6) in the principal frame, through the ruled member ψ of
//! the pencil φ* + μΩ*, and hypercyclides (Prop. 4.3, §4.7): the cyclographic images of
//! quadrics of tilted Euclidean hyperplanes of R⁴.

use proptest::prelude::*;
use rcagd::pn::hypercyclide::{Hypercyclide, PeSimilarity, RegularQuadric};
use rcagd::pn::PnError;
use rcagd::Certified;
use rcagd_algebra::{Certificate, Rational, Scalar};

type Q = Rational;

fn q(p: i64, d: i64) -> Q {
    Q::from_ratio(p, d)
}

fn assert_exact(certs: &[Certificate]) {
    assert!(!certs.is_empty(), "no certificates");
    for c in certs {
        assert!(c.holds && c.exact, "certificate failed: {c}");
    }
}

fn ellipsoid(a: Q, b: Q, c: Q) -> RegularQuadric {
    RegularQuadric::Ellipsoid { a, b, c }
}

/// The point lies on the quadric x²/a² + y²/b² + z²/c² = 1 (value of the left side − 1).
fn ellipsoid_residual(x: &[Q; 3], a: &Q, b: &Q, c: &Q) -> Q {
    &(&(&(&x[0] * &x[0]) / &(a * a)) + &(&(&x[1] * &x[1]) / &(b * b)))
        + &(&(&(&x[2] * &x[2]) / &(c * c)) - &Q::ONE)
}

#[test]
fn seed_ellipsoid_in_the_principal_frame_and_its_offsets() {
    // Peternell §4.7 example (a, b, c) = (25/3, 5, 3), here without the rotation to the
    // umbilic frame: the surface points lie on x²/a² + y²/b² + z²/c² = 1 itself.
    let (a, b, c) = (q(25, 3), q(5, 1), q(3, 1));
    let h = Hypercyclide::<Q>::quadric(ellipsoid(a.clone(), b.clone(), c.clone()), true)
        .expect("rational");
    assert_exact(&h.certify());
    for (s, u) in [(q(1, 3), q(1, 2)), (q(-2, 1), q(3, 1)), (q(5, 7), q(0, 1))] {
        let x = h.surface().eval(&s, &u).expect("defined");
        assert!(
            ellipsoid_residual(&x, &a, &b, &c).is_zero(),
            "on the ellipsoid"
        );
        // the offset at d: x + d n, certified as the image of φ translated along x₄
        let d = q(1, 2);
        let off = h.surface().offset(d.clone());
        let xd = off.surface().eval(&s, &u).expect("defined");
        let n = h.surface().normal_at(&s, &u).expect("normal");
        for i in 0..3 {
            assert_eq!(xd[i], &x[i] + &(&d * &n[i]));
        }
    }
    let off = h.surface().offset(q(-1, 1));
    assert_exact(&h.image_certificates(off.surface()));
    // the other ruling family works too
    let h2 = Hypercyclide::<Q>::quadric(ellipsoid(a, b, c), false).expect("rational");
    assert_exact(&h2.certify());
}

#[test]
fn the_ruled_quadrics_of_the_pencils_are_the_printed_ones() {
    // ellipsoid: x1²/(a²−b²) − x3²/(b²−c²) + x4²/b² = 1, x2 = 0
    let (a, b, c) = (q(25, 3), q(5, 1), q(3, 1));
    let r = ellipsoid(a.clone(), b.clone(), c.clone())
        .rulings(true)
        .expect("rulings");
    assert_exact(&r.certify());
    assert_eq!(r.hyperplane, 2);
    assert_eq!(r.mu0, -(&b * &b));
    let p = &r.psi_point;
    assert_eq!(p[0][0], q(-1, 1));
    assert_eq!(p[1][1], &Q::ONE / &(&(&a * &a) - &(&b * &b)));
    assert_eq!(p[3][3], -(&Q::ONE / &(&(&b * &b) - &(&c * &c))));
    assert_eq!(p[4][4], &Q::ONE / &(&b * &b));
    // two-sheet hyperboloid: x1²/(a²+b²) + x3²/(b²−c²) − x4²/b² = 1, x2 = 0
    let (a, b, c) = (q(12, 1), q(5, 1), q(3, 1));
    let r = RegularQuadric::TwoSheetHyperboloid {
        a: a.clone(),
        b: b.clone(),
        c: c.clone(),
    }
    .rulings(false)
    .expect("rulings");
    assert_exact(&r.certify());
    assert_eq!(r.mu0, &b * &b);
    let p = &r.psi_point;
    assert_eq!(p[1][1], &Q::ONE / &(&(&a * &a) + &(&b * &b)));
    assert_eq!(p[3][3], &Q::ONE / &(&(&b * &b) - &(&c * &c)));
    assert_eq!(p[4][4], -(&Q::ONE / &(&b * &b)));
    // elliptic paraboloid: −x2²/(a²−b²) + x4²/a² = 2x3 − a², x1 = 0. Peternell prints
    // "2x3 − a"; the pencil member (inverse of ψ* restricted to x1 = 0) has a² — the
    // constant term of the point form is a², not a (a = 5: 25, not 5).
    let (a, b) = (q(5, 1), q(4, 1));
    let r = RegularQuadric::EllipticParaboloid {
        a: a.clone(),
        b: b.clone(),
    }
    .rulings(true)
    .expect("rulings");
    assert_exact(&r.certify());
    assert_eq!(r.hyperplane, 1);
    let p = &r.psi_point;
    assert_eq!(p[2][2], -(&Q::ONE / &(&(&a * &a) - &(&b * &b))));
    assert_eq!(p[4][4], &Q::ONE / &(&a * &a));
    assert_eq!(p[0][3], q(-1, 1));
    assert_eq!(p[0][0], &a * &a);
    assert_ne!(p[0][0], a);
}

#[test]
fn elliptic_paraboloid_and_its_offsets() {
    for (a, b, fam) in [(5, 4, true), (5, 3, false), (13, 5, true)] {
        let quad = RegularQuadric::EllipticParaboloid {
            a: q(a, 1),
            b: q(b, 1),
        };
        let h = Hypercyclide::<Q>::quadric(quad, fam).expect("rational");
        assert_exact(&h.certify());
        let off = h.surface().offset(q(2, 1));
        assert_exact(&h.image_certificates(off.surface()));
        // points on x²/a² + y²/b² = 2z
        let x = h.surface().eval(&q(2, 1), &q(1, 3)).expect("defined");
        let lhs = &(&(&x[0] * &x[0]) / &q(a * a, 1)) + &(&(&x[1] * &x[1]) / &q(b * b, 1));
        assert_eq!(lhs, &q(2, 1) * &x[2]);
    }
}

#[test]
fn two_sheet_hyperboloid_with_rational_parabolic_rulings() {
    // (9, 13, 3): (a² + b²)(b² − c²) = 250·160 = 200², and the four parabolic rulings are
    // rational; but a cover branched at two neighbouring ones leaves the quartic
    // (T − r₃)(T − r₄) whose pull-back is a sum of two squares only if the cross ratio
    // (r₁, r₂; r₃, r₄) is a square (here 10/9): a named error, not a wrong surface
    let e = Hypercyclide::<Q>::quadric(
        RegularQuadric::TwoSheetHyperboloid {
            a: q(9, 1),
            b: q(13, 1),
            c: q(3, 1),
        },
        true,
    );
    assert!(
        matches!(e, Err(PnError::NoRationalPoint(ref s)) if s.contains("double covers")),
        "{e:?}"
    );
}

#[test]
fn two_sheet_hyperboloid_whose_parabolic_rulings_interleave() {
    // (12, 5, 3): the rulings of ψ are rational ((a² + b²)(b² − c²) = 52²), but the two
    // rational pairs of parabolic rulings interleave on the focal ellipse, so N(T) changes
    // sign inside and outside each pair: no rational double cover, a named error
    let e = Hypercyclide::<Q>::quadric(
        RegularQuadric::TwoSheetHyperboloid {
            a: q(12, 1),
            b: q(5, 1),
            c: q(3, 1),
        },
        true,
    );
    assert!(
        matches!(e, Err(PnError::NoRationalPoint(ref s)) if s.contains("double covers")),
        "{e:?}"
    );
}

#[test]
fn named_errors() {
    // equal axes: a quadric of revolution (a canal surface)
    let e = Hypercyclide::<Q>::quadric(ellipsoid(q(5, 1), q(5, 1), q(3, 1)), true);
    assert!(matches!(e, Err(PnError::InvalidInput(ref s)) if s.contains("revolution")));
    let e = Hypercyclide::<Q>::quadric(
        RegularQuadric::EllipticParaboloid {
            a: q(1, 1),
            b: q(2, 1),
        },
        true,
    );
    assert!(matches!(e, Err(PnError::InvalidInput(_))));
    // (a² − b²)(b² − c²) = 9·7 is no square: the rulings of ψ are irrational
    let e = Hypercyclide::<Q>::quadric(ellipsoid(q(5, 1), q(4, 1), q(3, 1)), true);
    assert!(
        matches!(e, Err(PnError::NoRationalPoint(ref s)) if s.contains("√")),
        "{e:?}"
    );
    let e = Hypercyclide::<Q>::quadric(
        RegularQuadric::EllipticParaboloid {
            a: q(3, 1),
            b: q(1, 1),
        },
        true,
    );
    assert!(matches!(e, Err(PnError::NoRationalPoint(_))));
    // not a pe similarity
    let mut m = PeSimilarity::identity();
    m.a[0][3] = q(1, 1);
    let e = Hypercyclide::<Q>::new(ellipsoid(q(25, 3), q(5, 1), q(3, 1)), m, true);
    assert!(matches!(e, Err(PnError::InvalidInput(ref s)) if s.contains("pe similarity")));
    assert!(PeSimilarity::boost(0, q(1, 1), [q(0, 1), q(0, 1), q(0, 1), q(0, 1)]).is_err());
}

#[test]
fn hypercyclide_of_an_ellipsoid_in_a_tilted_hyperplane() {
    // the boost in the (x, r) plane with b = 1/2 (cosh 5/3, sinh 4/3) tilts {x₄ = 0}
    let m = PeSimilarity::boost(0, q(1, 2), [q(1, 1), q(0, 1), q(-1, 2), q(1, 3)]).expect("boost");
    let h =
        Hypercyclide::<Q>::new(ellipsoid(q(25, 3), q(5, 1), q(3, 1)), m, true).expect("rational");
    assert_exact(&h.certify());
    // the hyperplane of φ′ is not parallel to R³: the cycles of its points have varying
    // radii, so the hypercyclide is no offset of a quadric
    let phi = h.phi_dual();
    assert!(!phi[4][4].is_zero() || !phi[0][4].is_zero());
}

#[test]
fn translation_along_r_is_the_offset() {
    // φ translated by d along x₄: its cycles are (m; r + d), so η is the offset at d
    let quad = RegularQuadric::EllipticParaboloid {
        a: q(5, 1),
        b: q(4, 1),
    };
    let d = q(3, 4);
    let map = PeSimilarity::boost(0, q(0, 1), [q(0, 1), q(0, 1), q(0, 1), d.clone()])
        .expect("translation");
    let h = Hypercyclide::<Q>::new(quad.clone(), map, true).expect("rational");
    assert_exact(&h.certify());
    let base = Hypercyclide::<Q>::quadric(quad, true).expect("rational");
    let off = base.surface().offset(d);
    for (s, u) in [(q(2, 1), q(1, 3)), (q(-3, 2), q(5, 1))] {
        assert_eq!(
            h.surface().eval(&s, &u).expect("defined"),
            off.surface().eval(&s, &u).expect("defined")
        );
    }
}

fn f64_agrees(h: &Hypercyclide<Q>, hf: &Hypercyclide<f64>) {
    let mut compared = 0;
    for (s, u) in [(q(1, 3), q(1, 2)), (q(3, 2), q(-1, 1)), (q(-4, 5), q(2, 1))] {
        let (Ok(x), Ok(xf)) = (
            h.surface().eval(&s, &u),
            hf.surface().eval(&Scalar::to_f64(&s), &Scalar::to_f64(&u)),
        ) else {
            continue;
        };
        for i in 0..3 {
            let e = Scalar::to_f64(&x[i]);
            assert!(
                (e - xf[i]).abs() <= 1e-6 * (1.0 + e.abs()),
                "f64 {} vs exact {e}",
                xf[i]
            );
        }
        compared += 1;
    }
    assert!(compared > 0, "no sample point was defined");
}

#[test]
fn f64_agrees_with_exact() {
    let quad = RegularQuadric::EllipticParaboloid {
        a: q(5, 1),
        b: q(3, 1),
    };
    let m = PeSimilarity::boost(1, q(1, 3), [q(0, 1), q(1, 1), q(0, 1), q(0, 1)]).expect("boost");
    let h = Hypercyclide::<Q>::new(quad.clone(), m.clone(), true).expect("exact");
    let hf = Hypercyclide::<f64>::new(quad, m, true).expect("f64");
    f64_agrees(&h, &hf);
    let quad = ellipsoid(q(25, 3), q(5, 1), q(3, 1));
    let h = Hypercyclide::<Q>::quadric(quad.clone(), true).expect("exact");
    let hf = Hypercyclide::<f64>::quadric(quad, true).expect("f64");
    f64_agrees(&h, &hf);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(8))]
    /// Random elliptic paraboloids with a² − b² a square (a = m² + n², b = 2mn or m² − n²,
    /// scaled), under random rational boosts and translations: exact certificates and f64
    /// agreement.
    #[test]
    fn random_paraboloid_hypercyclides(
        m in 2i64..6, n in 1i64..4, leg in any::<bool>(), scale in 1i64..4,
        axis in 0usize..3, bn in -3i64..4, t in proptest::array::uniform4(-3i64..4),
        fam in any::<bool>(),
    ) {
        prop_assume!(m > n);
        let a = q((m * m + n * n) * scale, 3);
        let b = if leg { q(2 * m * n * scale, 3) } else { q((m * m - n * n) * scale, 3) };
        let (a, b) = if a > b { (a, b) } else { (b, a) };
        prop_assume!(a != b);
        let quad = RegularQuadric::EllipticParaboloid { a, b };
        let map = PeSimilarity::boost(axis, q(bn, 5), t.map(|x| q(x, 2))).expect("boost");
        let h = Hypercyclide::<Q>::new(quad.clone(), map.clone(), fam).expect("rational");
        for c in h.certify() {
            prop_assert!(c.holds && c.exact, "{}", c);
        }
        let hf = Hypercyclide::<f64>::new(quad, map, fam).expect("f64");
        f64_agrees(&h, &hf);
    }
}

mod surfaces_of_r4 {
    //! Cyclographic images of rational 2-surfaces of R⁴ (Peternell §3.9, Lemma 3.5).
    use super::{assert_exact, q, Q};
    use rcagd::pn::hypercyclide::{mpoly_sqrt, CyclographicImage};
    use rcagd::pn::PnError;
    use rcagd::Certified;
    use rcagd_algebra::mpoly::MPoly;

    fn u() -> MPoly<Q> {
        MPoly::var(2, 0)
    }
    fn v() -> MPoly<Q> {
        MPoly::var(2, 1)
    }
    fn k(c: i64) -> MPoly<Q> {
        MPoly::constant(2, q(c, 1))
    }

    #[test]
    fn square_roots_of_polynomials() {
        let p = &(&(&u() * &u()).scale(&q(3, 2)) - &(&u() * &v())) + &k(7);
        let sq = &p * &p;
        let r = mpoly_sqrt(&sq).expect("a square");
        assert!(r == p || r == -p.clone());
        assert!(mpoly_sqrt(&(&sq + &k(1))).is_none());
        assert!(mpoly_sqrt(&(&u() * &v())).is_none());
        assert!(mpoly_sqrt(&k(2)).is_none());
    }

    #[test]
    fn cycles_touching_a_plane_have_two_rational_sheets() {
        // s = (u, v, −ρ; ρ), ρ = (u² + v²)/4 + 2: every cycle touches z = 0 at (u, v, 0)
        // (one sheet); the other sheet is the second envelope of the spheres (with
        // ρ = (u² + v²)/4 + 1 instead all spheres pass through (0, 0, −2), and the second
        // sheet collapses to that point)
        let rho = &(&(&u() * &u()) + &(&v() * &v())).scale(&q(1, 4)) + &k(2);
        let img = CyclographicImage::new([u(), v(), -rho.clone(), rho], k(1)).expect("rational");
        assert_eq!(img.sheets().len(), 2);
        assert!(!img.is_gamma_surface());
        assert_exact(&img.certify());
        let (s, t) = (q(1, 2), q(-3, 1));
        let pts: Vec<[Q; 3]> = img
            .sheets()
            .iter()
            .map(|sh| sh.eval(&s, &t).expect("defined"))
            .collect();
        assert!(pts.iter().any(|x| x == &[s.clone(), t.clone(), Q::from(0)]));
        assert!(
            pts.iter().any(|x| !x[2].is_zero()),
            "a second, different sheet"
        );
        // offsets: the cycles (m; r + d)
        for sh in img.sheets() {
            let off = sh.offset(q(1, 3));
            assert_exact(&img.image_certificates(off.surface()));
        }
    }

    #[test]
    fn a_pn_surface_in_r3_is_its_own_image() {
        // the unit sphere (2u, 2v, u² + v² − 1)/(u² + v² + 1) with r ≡ 0: both orientations
        let s2 = &(&u() * &u()) + &(&v() * &v());
        let img = CyclographicImage::new(
            [
                u().scale(&q(2, 1)),
                v().scale(&q(2, 1)),
                &s2 - &k(1),
                MPoly::zero(2),
            ],
            &s2 + &k(1),
        )
        .expect("rational");
        assert_eq!(img.sheets().len(), 2);
        assert_exact(&img.certify());
        let x = img.sheets()[0].eval(&q(1, 3), &q(2, 1)).expect("defined");
        let n2: Q = x.iter().fold(Q::from(0), |acc, c| &acc + &(c * c));
        assert_eq!(n2, Q::from(1));
    }

    #[test]
    fn a_gamma_plane_has_one_degenerate_sheet_and_errors_are_named() {
        // s = (u, v, 0; v): tangent planes are γ-planes (the null direction (0, 1, 0, 1));
        // every cycle touches the image along the line f = φ ∩ R³ (Peternell §3.9)
        let img = CyclographicImage::new([u(), v(), MPoly::zero(2), v()], k(1)).expect("γ");
        assert!(img.is_gamma_surface());
        assert_exact(&img.image_certificates(&img.sheets()[0]));
        let x = img.sheets()[0].eval(&q(2, 1), &q(5, 1)).expect("defined");
        assert_eq!(x, [q(2, 1), q(0, 1), q(0, 1)]);
        // a graph in R³ whose parametrization is not PN: Δ is no square
        let e = CyclographicImage::new(
            [
                u(),
                v(),
                &(&u() * &u()) + &(&v() * &v()).scale(&q(2, 1)),
                MPoly::zero(2),
            ],
            k(1),
        );
        assert!(matches!(e, Err(PnError::NoRationalPoint(_))), "{e:?}");
        // centres on a curve
        let e = CyclographicImage::new([u(), u(), u(), v()], k(1));
        assert!(matches!(e, Err(PnError::InvalidInput(_))));
        let e = CyclographicImage::new([u(), v(), u(), v()], MPoly::zero(2));
        assert!(matches!(e, Err(PnError::InvalidInput(_))));
    }

    /// A non-square `Δ` whose odd part `δ` is quadratic is made a square by the
    /// stereographic projection of the quadric `w² = δ(u, v)`
    /// (docs/math/hypercyclides.md#non-square-delta): the spheres `(u, v, 0; ρ)`,
    /// `ρ = (u² + v²)/4 + 1` (`Δ = 1 − (u² + v²)/4`) get two rational sheets, mirror images
    /// in `z = 0` (the centres lie in that plane) and on the spheres of their cycles; the
    /// elliptic paraboloid `z = u² + 2v²` (`Δ = 1 + 4u² + 16v²`) becomes a PN surface on
    /// `z = x² + 2y²`. A constant non-square odd part (`ρ = (u + v)/2`, `Δ = 1/2`) and a
    /// quartic one (`z = u³ + v`, `Δ = 2 + 9u⁴`) are named errors saying why.
    #[test]
    fn non_square_delta_of_degree_two_is_made_a_square_by_reparametrization() {
        let rho = &(&(&u() * &u()) + &(&v() * &v())).scale(&q(1, 4)) + &k(1);
        let s = [u(), v(), MPoly::zero(2), rho.clone()];
        let e = CyclographicImage::new(s.clone(), k(1));
        assert!(matches!(e, Err(PnError::NoRationalPoint(_))), "{e:?}");
        let (img, psi) = CyclographicImage::reparametrized(s, k(1)).expect("quadric δ");
        assert_eq!(img.sheets().len(), 2);
        assert_exact(&img.certify());
        for (a, b) in [(q(1, 3), q(1, 5)), (q(-2, 7), q(3, 4))] {
            let x: Vec<[Q; 3]> = img
                .sheets()
                .iter()
                .map(|sh| sh.eval(&a, &b).expect("defined"))
                .collect();
            assert_eq!(x[0][0], x[1][0]);
            assert_eq!(x[0][1], x[1][1]);
            assert_eq!(x[0][2], -x[1][2].clone());
            assert!(!x[0][2].is_zero());
            let d = psi[2].eval(&[a.clone(), b.clone()]).expect("eval");
            let uu = psi[0].eval(&[a.clone(), b.clone()]).expect("eval") / d.clone();
            let vv = psi[1].eval(&[a.clone(), b.clone()]).expect("eval") / d;
            let r = rho.eval(&[uu.clone(), vv.clone()]).expect("eval");
            for p in &x {
                let dist2 =
                    (&p[0] - &uu) * (&p[0] - &uu) + (&p[1] - &vv) * (&p[1] - &vv) + &p[2] * &p[2];
                assert_eq!(dist2, &r * &r, "on the sphere of the cycle");
            }
        }
        // the elliptic paraboloid z = u² + 2v² as the image of its points (r ≡ 0)
        let z = &(&u() * &u()) + &(&v() * &v()).scale(&q(2, 1));
        let (img, _) = CyclographicImage::reparametrized([u(), v(), z, MPoly::zero(2)], k(1))
            .expect("quadric δ");
        assert_exact(&img.certify());
        for sh in img.sheets() {
            let x = sh.eval(&q(1, 2), &q(-1, 3)).expect("defined");
            assert_eq!(&x[0] * &x[0] + (&x[1] * &x[1]) * q(2, 1), x[2]);
        }
        // named errors: constant and quartic odd parts
        let e = CyclographicImage::reparametrized(
            [u(), v(), MPoly::zero(2), (&u() + &v()).scale(&q(1, 2))],
            k(1),
        );
        assert!(
            matches!(&e, Err(PnError::NoRationalPoint(m)) if m.contains("non-square constant")),
            "{e:?}"
        );
        let e = CyclographicImage::reparametrized(
            [u(), v(), &(&(&u() * &u()) * &u()) + &v(), MPoly::zero(2)],
            k(1),
        );
        assert!(
            matches!(&e, Err(PnError::NoRationalPoint(m)) if m.contains("degree 4")),
            "{e:?}"
        );
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(8))]
        /// Random quadratic radius functions ρ(u, v) of spheres (u, v, −ρ; ρ) touching the
        /// plane z = 0: Δ is a square, both sheets certify exactly, one is the plane.
        #[test]
        fn random_sphere_families_on_a_plane(c in proptest::array::uniform6(-4i64..5)) {
            let rho = &(&(&(&k(c[0]) + &u().scale(&q(c[1], 2))) + &v().scale(&q(c[2], 3)))
                + &(&u() * &u()).scale(&q(c[3], 4)))
                + &(&(&u() * &v()).scale(&q(c[4], 5)) + &(&v() * &v()).scale(&q(c[5], 3)));
            let img = CyclographicImage::new([u(), v(), -rho.clone(), rho], k(1))
                .expect("Δ is a square");
            proptest::prop_assert_eq!(img.sheets().len(), 2);
            for c in img.certify() {
                proptest::prop_assert!(c.holds && c.exact, "{}", c);
            }
            let (s, t) = (q(2, 3), q(-1, 4));
            let on_plane = img
                .sheets()
                .iter()
                .filter_map(|sh| sh.eval(&s, &t).ok())
                .any(|x| x == [s.clone(), t.clone(), Q::from(0)]);
            proptest::prop_assert!(on_plane, "one sheet is the plane z = 0");
        }
    }
}

/// The two-sheet hyperboloid, whose principal-frame construction above ends in
/// `NoRationalPoint`, has a rational PN parametrization over `Q` by the degree-2
/// unirational parametrization of its tangent-plane surface
/// (docs/math/hypercyclides.md#two-sheet-unirational): for `(a, b, c) = (9, 13, 3)` every
/// certificate holds exactly (PN, point on the quadric), the point bidegree is (8, 4) as
/// the sympy derivation predicts, a sample point is a real point of the sheet `x₁ ≥ a`, and
/// the offsets are certified; `f64` certifies too; `b = c` is a named error.
#[test]
fn two_sheet_hyperboloid_by_the_unirational_parametrization() {
    use rcagd::pn::two_sheet::TwoSheetPn;
    let h = TwoSheetPn::new(q(9, 1), q(13, 1), q(3, 1)).expect("two-sheet");
    assert_exact(&h.certify());
    assert_eq!(h.surface().degree(), (8, 4));
    let x = h.surface().eval(&q(1, 2), &q(1, 3)).expect("finite");
    let r = x[0].clone() * x[0].clone() / q(81, 1)
        - x[1].clone() * x[1].clone() / q(169, 1)
        - x[2].clone() * x[2].clone() / q(9, 1);
    assert_eq!(r, q(1, 1));
    assert!(x[0].abs() >= q(9, 1), "{x:?}");
    assert_exact(&h.surface().offset(q(1, 2)).certify());
    let hf = TwoSheetPn::new(9.0f64, 13.0, 3.0).expect("f64");
    assert!(
        hf.certify().iter().all(|c| c.holds),
        "{:?}",
        hf.certify().iter().filter(|c| !c.holds).collect::<Vec<_>>()
    );
    let xf = hf.surface().eval(&0.5, &(1.0 / 3.0)).expect("finite");
    for i in 0..3 {
        let e = Scalar::to_f64(&x[i]);
        assert!(
            (e - xf[i]).abs() <= 1e-9 * (1.0 + e.abs()),
            "{x:?} vs {xf:?}"
        );
    }
    assert!(matches!(
        TwoSheetPn::new(q(9, 1), q(3, 1), q(-3, 1)),
        Err(rcagd::pn::PnError::InvalidInput(_))
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(8))]

    /// Random exact semi-axes (`b² ≠ c²`): the unirational PN parametrization of the
    /// two-sheet hyperboloid is certified exactly (PN and on the quadric).
    #[test]
    fn random_two_sheet_hyperboloids_are_pn(
        a in (1i64..=12, 1i64..=3),
        b in (1i64..=12, 1i64..=3),
        c in (1i64..=12, 1i64..=3),
    ) {
        use rcagd::pn::two_sheet::TwoSheetPn;
        let (a, b, c) = (q(a.0, a.1), q(b.0, b.1), q(c.0, c.1));
        prop_assume!(b != c);
        let h = TwoSheetPn::new(a, b, c).expect("two-sheet");
        for cert in h.certify() {
            prop_assert!(cert.holds && cert.exact, "{}", cert);
        }
    }
}

/// Theorem 4.6 through one entry point: `QuadricPn` uses the ruling construction where it
/// works (the §4.7 ellipsoid) and falls back to the unirational parametrization for the
/// two-sheet hyperboloids whose rulings give no rational family ((9, 13, 3): square cross
/// ratio missing; (12, 5, 3): interleaving parabolic rulings); the fallback is certified
/// exactly on the quadric (foot point on it, normal = the quadric's normal) for the
/// surface and for its offsets; an ellipsoid with irrational rulings stays a named error.
#[test]
fn pn_quadric_falls_back_to_the_unirational_two_sheet_parametrization() {
    use rcagd::pn::hypercyclide::QuadricPn;
    for (a, b, c) in [(9, 13, 3), (12, 5, 3)] {
        let r = RegularQuadric::TwoSheetHyperboloid {
            a: q(a, 1),
            b: q(b, 1),
            c: q(c, 1),
        };
        let h = QuadricPn::<Q>::new(r, true).expect("two-sheet via the fallback");
        assert_eq!(h.construction(), "two_sheet_unirational");
        match &h {
            QuadricPn::TwoSheet { rulings_error, .. } => {
                assert!(rulings_error.contains("double covers"), "{rulings_error}")
            }
            QuadricPn::Rulings(_) => panic!("expected the fallback"),
        }
        assert_exact(&h.certify());
        for d in [q(1, 2), q(-3, 1)] {
            let off = h.surface().offset(d);
            assert_exact(&h.quadric_certificates(off.surface()));
            assert_exact(&off.certify());
        }
        let f = QuadricPn::<f64>::new(
            RegularQuadric::TwoSheetHyperboloid {
                a: q(a, 1),
                b: q(b, 1),
                c: q(c, 1),
            },
            true,
        )
        .expect("f64");
        assert!(f.certify().iter().all(|c| c.holds));
    }
    let e = QuadricPn::<Q>::new(ellipsoid(q(25, 3), q(5, 1), q(3, 1)), true).expect("ellipsoid");
    assert_eq!(e.construction(), "rulings");
    assert_exact(&e.quadric_certificates(e.surface()));
    // (a² − b²)(b² − c²) = 5·3 not a square: the ellipsoid's rulings are irrational
    assert!(matches!(
        QuadricPn::<Q>::new(ellipsoid(q(3, 1), q(2, 1), q(1, 1)), true),
        Err(PnError::NoRationalPoint(_))
    ));
    // validation errors are not masked by the fallback
    assert!(matches!(
        QuadricPn::<Q>::new(
            RegularQuadric::TwoSheetHyperboloid {
                a: q(9, 1),
                b: q(3, 1),
                c: q(13, 1)
            },
            true
        ),
        Err(PnError::InvalidInput(_))
    ));
}

/// Which part of the hyperboloid the real parameters of the unirational parametrization
/// cover (docs/math/hypercyclides.md#two-sheet-region): for `b > c` the wedge
/// `|x₃| ≥ k|x₁ − a|`, `k = c²√(a² + b²)/(ab√(b² − c²))`, of **both** sheets, the normal
/// always with `n₁ ≥ 0`. Exactly on a grid of rational parameters (the squared inequality
/// `c⁴(a² + b²)(x₁ − a)² ≤ a²b²(b² − c²)x₃²`), both sheets reached; and conversely (f64)
/// every sampled point strictly inside the wedge, on either sheet, is the image of the
/// parameters `τ = √(−(c² + aμ)/(b² + aμ))`, `σ = (n₂ − τn₃)/(1 − n₁)`,
/// `μ = (h − an₁)/(1 − n₁)`; outside the wedge `τ²` is negative.
#[test]
fn two_sheet_real_parameters_cover_a_wedge_of_both_sheets() {
    use rcagd::pn::two_sheet::TwoSheetPn;
    let (a, b, c) = (9i64, 13i64, 3i64);
    let h = TwoSheetPn::new(q(a, 1), q(b, 1), q(c, 1)).expect("two-sheet");
    let (aq, a2, b2, c2) = (q(a, 1), q(a * a, 1), q(b * b, 1), q(c * c, 1));
    let (mut plus, mut minus) = (0, 0);
    for i in -6i64..=6 {
        for j in -6i64..=6 {
            let (t, s) = (q(i, 2), q(j, 3));
            let (Ok(x), Ok(n)) = (h.surface().eval(&t, &s), h.surface().normal_at(&t, &s)) else {
                continue;
            };
            assert!(n[0] >= Q::ZERO, "n₁ < 0 at ({t}, {s}): {n:?}");
            let dx = &x[0] - &aq;
            let lhs = &(&(&c2 * &c2) * &(&a2 + &b2)) * &(&dx * &dx);
            let rhs = &(&(&a2 * &b2) * &(&b2 - &c2)) * &(&x[2] * &x[2]);
            assert!(lhs <= rhs, "({t}, {s}) ↦ {x:?} outside the wedge");
            if x[0] >= aq {
                plus += 1;
            } else {
                assert!(x[0] <= -aq.clone(), "{x:?} between the sheets");
                minus += 1;
            }
        }
    }
    assert!(plus > 0 && minus > 0, "sheets reached: {plus} / {minus}");
    // converse in f64
    let hf = TwoSheetPn::new(a as f64, b as f64, c as f64).expect("f64");
    let (af, bf, cf) = (a as f64, b as f64, c as f64);
    let k = cf * cf * (af * af + bf * bf).sqrt() / (af * bf * (bf * bf - cf * cf).sqrt());
    let mut inside = [0, 0];
    for (m, sg) in [(1.0f64, 1.0f64), (1.0, -1.0)] {
        for iu in 1..=8 {
            for ip in 0..24 {
                let u = 1.0 + 0.4 * iu as f64 * m;
                let ph = (ip as f64 + 0.5) * std::f64::consts::PI / 12.0;
                let w = (u * u - 1.0).sqrt();
                let x = [sg * af * u, bf * w * ph.cos(), cf * w * ph.sin()];
                let g = [x[0] / (af * af), -x[1] / (bf * bf), -x[2] / (cf * cf)];
                let l = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt() * sg;
                let n = [g[0] / l, g[1] / l, g[2] / l];
                let hh = n[0] * x[0] + n[1] * x[1] + n[2] * x[2];
                let mu = (hh - af * n[0]) / (1.0 - n[0]);
                let t2 = -(cf * cf + af * mu) / (bf * bf + af * mu);
                let margin = x[2].abs() - k * (x[0] - af).abs();
                if margin < -1e-9 * (1.0 + x[0].abs()) {
                    assert!(t2 < 1e-9, "outside the wedge but τ² = {t2} at {x:?}");
                    continue;
                }
                if margin < 1e-3 * (1.0 + x[0].abs()) {
                    continue;
                }
                let tau = t2.sqrt();
                let sigma = (n[1] - tau * n[2]) / (1.0 - n[0]);
                let y = hf.surface().eval(&tau, &sigma).expect("finite");
                for i in 0..3 {
                    assert!(
                        (y[i] - x[i]).abs() <= 1e-8 * (1.0 + x[i].abs()),
                        "{x:?} ≠ {y:?} at ({tau}, {sigma})"
                    );
                }
                inside[usize::from(sg < 0.0)] += 1;
            }
        }
    }
    assert!(inside[0] > 10 && inside[1] > 10, "{inside:?}");
}

mod focal_surfaces_and_sections {
    //! Focal surfaces of PN surfaces, the γ-surfaces of their curvature spheres and the
    //! sections Γ(φ) ∩ π (Peternell §3.9, Lemma 3.5; docs/math/hypercyclides.md#focal-surfaces).
    use super::{assert_exact, q, Q};
    use rcagd::pn::focal::{FocalSurfaces, GammaSection};
    use rcagd::pn::hypercyclide::CyclographicImage;
    use rcagd::pn::offset::principal_radii_at;
    use rcagd::pn::{IsotropicSurface, PnError, PnSurface};
    use rcagd::Certified;
    use rcagd_algebra::mpoly::MPoly;

    fn u() -> MPoly<Q> {
        MPoly::var(2, 0)
    }
    fn v() -> MPoly<Q> {
        MPoly::var(2, 1)
    }

    /// The independent check of a principal radius `r` at `(a, b)`: the offset at
    /// distance `−r` is singular there (the quadratic `R(δ)` of the offsets' regularity
    /// determinant, computed from the offset surfaces, vanishes at `δ = −r`).
    fn is_principal_radius(s: &PnSurface<Q>, a: &Q, b: &Q, r: &Q) -> bool {
        let c = principal_radii_at(s, a, b);
        let d = -r.clone();
        (&c[0] + &(&c[1] * &d)) + &(&(&c[2] * &d) * &d) == Q::from(0)
    }

    /// The parabolic Dupin cyclide `F = αu² + βv²` of the isotropic model: its focal
    /// sheets degenerate to the two focal parabolas, and the curvature spheres are the
    /// ones the isotropic model predicts independently — the isotropic sphere
    /// `y₃ = αS + 2(β − α)v₀v + (α − β)v₀²` osculating `F` along `v = v₀` is the cycle
    /// `m = (0, 2(α − β)v₀, −α − (β − α)v₀²)`, `r = −α + (β − α)v₀²` (Peternell (3.12)),
    /// and symmetrically for the other family.
    #[test]
    fn focal_sheets_of_a_parabolic_dupin_cyclide_are_its_focal_parabolas() {
        let (al, be) = (q(1, 2), q(-1, 1));
        let s = IsotropicSurface::parabolic_dupin_cyclide(al.clone(), be.clone())
            .to_pn_surface()
            .expect("PN");
        let f = FocalSurfaces::new(&s).expect("rational focal sheets");
        assert_eq!(f.sheets().len(), 2);
        assert_exact(&f.certify());
        for sh in f.sheets() {
            assert!(
                !sh.is_surface(),
                "the focal sets of a Dupin cyclide are curves"
            );
            assert_exact(&[f.gamma_certificate(sh)]);
        }
        for (u0, v0) in [(q(1, 3), q(2, 1)), (q(-3, 2), q(1, 5))] {
            let fam1 = (
                [
                    Q::from(0),
                    q(2, 1) * (&al - &be) * v0.clone(),
                    -al.clone() - (&be - &al) * &v0 * &v0,
                ],
                -al.clone() + (&be - &al) * &v0 * &v0,
            );
            let fam2 = (
                [
                    q(2, 1) * (&be - &al) * u0.clone(),
                    Q::from(0),
                    -be.clone() - (&al - &be) * &u0 * &u0,
                ],
                -be.clone() + (&al - &be) * &u0 * &u0,
            );
            let got: Vec<([Q; 3], Q)> = f
                .sheets()
                .iter()
                .map(|sh| {
                    (
                        sh.point(&u0, &v0).expect("defined"),
                        sh.radius(&u0, &v0).expect("defined"),
                    )
                })
                .collect();
            assert!(got.contains(&fam1), "{got:?} vs {fam1:?}");
            assert!(got.contains(&fam2), "{got:?} vs {fam2:?}");
            for (_, r) in &got {
                assert!(is_principal_radius(&s, &u0, &v0, r));
            }
        }
    }

    /// A rational, non-degenerate γ-surface of `R⁴` with its cyclographic image: the
    /// curvature spheres of one family of the PN surface of `F = u³/6 + v²/2`
    /// (`F_uv ≡ 0`: the eigenvalues `u`, `1` of the Hessian are rational, so are the
    /// principal radii). The cycles form a γ-surface (Δ ≡ 0, exactly) that is a genuine
    /// surface (its top view, a focal sheet, is a surface); `CyclographicImage` of it has
    /// one sheet, which is the PN surface again (points and normals), non-degenerate; and
    /// that sheet's focal surfaces contain the γ-surface's top view (Peternell §3.9).
    #[test]
    fn a_non_degenerate_gamma_surface_and_its_cyclographic_image() {
        let f = &(&(&u() * &u()) * &u()).scale(&q(1, 6)) + &(&v() * &v()).scale(&q(1, 2));
        let s = IsotropicSurface::graph_poly(f).to_pn_surface().expect("PN");
        let foc = FocalSurfaces::new(&s).expect("rational principal radii");
        assert_eq!(foc.sheets().len(), 2);
        assert_exact(&foc.certify());
        let sheet = foc
            .sheets()
            .iter()
            .find(|sh| sh.is_surface())
            .expect("a non-degenerate focal sheet");
        assert_exact(&[foc.gamma_certificate(sheet)]);
        let (cyc, w) = sheet.cycles();
        let img = CyclographicImage::new(cyc, w).expect("γ-surface");
        assert!(img.is_gamma_surface());
        assert_exact(&img.certify());
        let im = &img.sheets()[0];
        assert!(!im.point_map_degenerate(), "a genuine image surface");
        for (a, b) in [(q(1, 2), q(1, 3)), (q(-2, 1), q(3, 4)), (q(5, 7), q(-1, 1))] {
            assert_eq!(
                im.eval(&a, &b).expect("defined"),
                s.eval(&a, &b).expect("defined")
            );
            assert_eq!(
                im.normal_at(&a, &b).expect("defined"),
                s.normal_at(&a, &b).expect("defined")
            );
            let r = sheet.radius(&a, &b).expect("defined");
            assert!(is_principal_radius(&s, &a, &b, &r));
        }
        let back = FocalSurfaces::new(im).expect("rational");
        let (a, b) = (q(1, 2), q(1, 3));
        let p = sheet.point(&a, &b).expect("defined");
        assert!(back
            .sheets()
            .iter()
            .any(|sh| sh.point(&a, &b).as_ref() == Some(&p)));
    }

    /// `Γ(φ) ∩ π`: for `π: y₄ = c` the top view is the offset at `−c` (certified against
    /// `PnSurface::offset`); a tilted hyperplane gives a section on `π` and on `Γ(φ)`; a
    /// hyperplane containing every γ-line is a named error.
    #[test]
    fn sections_of_the_gamma_hypersurface() {
        let f = &(&(&u() * &u()) * &u()).scale(&q(1, 6)) + &(&v() * &v()).scale(&q(1, 2));
        let s = IsotropicSurface::graph_poly(f).to_pn_surface().expect("PN");
        let c = q(1, 2);
        let sec = GammaSection::new(
            &s,
            [-c.clone(), Q::from(0), Q::from(0), Q::from(0), Q::from(1)],
        )
        .expect("section");
        assert_eq!(sec.offset_distance(), Some(-c.clone()));
        assert_exact(&sec.certify());
        let off = s.offset(-c.clone());
        let (a, b) = (q(1, 3), q(-2, 1));
        let y = sec.eval(&a, &b).expect("defined");
        assert_eq!(y[3], c);
        assert_eq!(
            [y[0].clone(), y[1].clone(), y[2].clone()],
            off.surface().eval(&a, &b).expect("defined")
        );
        let tilted = [q(1, 1), q(1, 2), Q::from(0), q(-1, 3), q(2, 1)];
        let sec = GammaSection::new(&s, tilted.clone()).expect("section");
        assert_eq!(sec.offset_distance(), None);
        assert_exact(&sec.certify());
        let y = sec.eval(&a, &b).expect("defined");
        let on = &(&tilted[0] + &(&tilted[1] * &y[0]))
            + &(&(&tilted[3] * &y[2]) + &(&tilted[4] * &y[3]));
        assert_eq!(on, Q::from(0));
        // the plane z = 0 (unit normal (0, 0, 1)) and π: y₃ + y₄ = 0, which contains
        // every γ-line (x − t e₃; t) of the plane
        let plane = PnSurface::from_point_normal(
            [MPoly::constant(2, Q::from(1)), u(), v(), MPoly::zero(2)],
            [
                MPoly::constant(2, Q::from(1)),
                MPoly::zero(2),
                MPoly::zero(2),
                MPoly::constant(2, Q::from(1)),
            ],
        )
        .expect("plane");
        let e = GammaSection::new(
            &plane,
            [Q::from(0), Q::from(0), Q::from(0), Q::from(1), Q::from(1)],
        );
        assert!(matches!(e, Err(PnError::InvalidInput(_))), "{e:?}");
        let e = FocalSurfaces::new(&plane);
        assert!(matches!(e, Err(PnError::InvalidInput(_))), "{e:?}");
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(8))]
        /// Random separable graphs `F = f(u) + g(v)` (`f, g` cubics with random exact
        /// coefficients; rational principal radii): both focal sheets certify exactly, every
        /// radius is a root of the offsets' regularity quadratic at `δ = −r` (independent),
        /// and a random hyperplane section of `Γ(φ)` certifies exactly.
        #[test]
        fn random_separable_graphs_have_certified_focal_sheets_and_sections(
            c in proptest::array::uniform4(-4i64..5),
            h in proptest::array::uniform5(-3i64..4),
        ) {
            let cube = |x: &MPoly<Q>| &(x * x) * x;
            let f = &(&(&cube(&u()).scale(&q(c[0], 6)) + &(&u() * &u()).scale(&q(c[1], 2)))
                + &cube(&v()).scale(&q(c[2], 6)))
                + &(&v() * &v()).scale(&q(c[3], 2));
            let s = IsotropicSurface::graph_poly(f).to_pn_surface().expect("PN");
            match FocalSurfaces::new(&s) {
                Ok(foc) => {
                    for cert in foc.certify() {
                        proptest::prop_assert!(cert.holds && cert.exact, "{}", cert);
                    }
                    let (a, b) = (q(2, 3), q(-3, 5));
                    for sh in foc.sheets() {
                        if let Some(r) = sh.radius(&a, &b) {
                            proptest::prop_assert!(is_principal_radius(&s, &a, &b, &r));
                        }
                    }
                }
                // F quadratic with equal coefficients is a sphere's graph or a plane
                Err(e) => proptest::prop_assert!(
                    c[0] == 0 && c[2] == 0 && c[1] == c[3],
                    "{e:?}"
                ),
            }
            let hq: [Q; 5] = std::array::from_fn(|i| q(h[i], 1));
            if let Ok(sec) = GammaSection::new(&s, hq) {
                for cert in sec.certify() {
                    proptest::prop_assert!(cert.holds && cert.exact, "{}", cert);
                }
            }
        }
    }

    /// A surface whose principal radii are irrational: `D` is not a square, a named error.
    #[test]
    fn irrational_principal_radii_are_a_named_error() {
        // F = u²v/2 + v³/6: Hessian ((v, u), (u, v)) has eigenvalues v ± u — rational;
        // F = u³/6 + u v²/2 + v²: eigenvalues of ((u, v), (v, u + 2)) are irrational
        let f = &(&(&(&u() * &u()) * &u()).scale(&q(1, 6))
            + &(&(&u() * &v()) * &v()).scale(&q(1, 2)))
            + &(&v() * &v());
        let s = IsotropicSurface::graph_poly(f).to_pn_surface().expect("PN");
        let e = FocalSurfaces::new(&s);
        assert!(matches!(e, Err(PnError::NoRationalPoint(_))), "{e:?}");
    }
}
