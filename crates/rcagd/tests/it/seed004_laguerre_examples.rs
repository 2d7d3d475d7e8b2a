//! M. Peternell, *Rational Parametrizations for Envelopes of Quadric Families*, chapter 3 —
//! the examples and statements of the Laguerre-geometry chapter that are not already in
//! `seed004_pn_examples.rs` (which holds (3.11)–(3.13), Lemma 3.1, (3.14)/(3.15) with
//! docs/math/laguerre-pn.md, Errata E6, (3.17) with E7, (3.18) with E8 and the cyclide
//! pencils of §3.8.1 with E9/E10). Everything here is exact over Q.

use rcagd::laguerre::*;
use rcagd::Certified;
use rcagd_algebra::{Rational, Scalar};

type Q = Rational;

fn q(p: i64, d: i64) -> Q {
    Q::from_ratio(p, d)
}
fn qi(n: i64) -> Q {
    Q::from(n)
}
fn dot(a: &[Q], b: &[Q]) -> Q {
    a.iter()
        .zip(b)
        .fold(qi(0), |s, (x, y)| s + x.clone() * y.clone())
}
fn sub3(a: &[Q; 3], b: &[Q; 3]) -> [Q; 3] {
    std::array::from_fn(|i| a[i].clone() - b[i].clone())
}

/// §3.1 (3.4): the dilatation adds d to every signed radius and "does not preserve
/// points": a point cycle becomes a sphere of radius d, and the planes through the point
/// become the planes touching that sphere, each moved by +d along its normal (E6).
#[test]
fn s3_1_dilatation_does_not_preserve_points() {
    let p = [qi(1), qi(-2), q(1, 2)];
    let d = q(3, 2);
    let dil = LaguerreMap::dilatation(d.clone());
    let sphere = dil.apply_cycle(&Cycle::point(p.clone()));
    assert_eq!(sphere.center, p);
    assert_eq!(sphere.radius, d, "(3.4) r ↦ r + d");
    for n in [
        [q(3, 5), q(4, 5), qi(0)],
        [q(2, 7), q(-3, 7), q(6, 7)],
        [qi(0), qi(0), qi(-1)],
    ] {
        let e = OrientedPlane::through_point(n.clone(), &p).expect("unit");
        let e2 = dil.apply_plane(&e).expect("plane");
        assert!(sphere.in_oriented_contact(&e2));
        let touch = sphere.contact_point(&e2).expect("contact");
        let want: [Q; 3] = std::array::from_fn(|i| p[i].clone() + d.clone() * n[i].clone());
        assert_eq!(touch, want, "contact point p + d n");
        // the reversed plane through p is a tangent plane of the point cycle too: its image
        // touches the same sphere, at p − d n
        let r2 = dil.apply_plane(&e.reversed()).expect("plane");
        let back: [Q; 3] = std::array::from_fn(|i| p[i].clone() - d.clone() * n[i].clone());
        assert_eq!(sphere.contact_point(&r2).expect("contact"), back);
    }
}

/// §3.1: two oriented planes are in oriented contact iff their unit normals coincide; the
/// Blaschke points of parallel planes lie on one generator of the cylinder (§3.3) and their
/// isotropic images on one isotropic line (§3.4).
#[test]
fn s3_3_parallel_planes_on_one_generator() {
    let n = [q(2, 3), q(-2, 3), q(1, 3)];
    let planes: Vec<OrientedPlane<Q>> = [qi(0), qi(2), q(-7, 3)]
        .into_iter()
        .map(|e0| OrientedPlane::new(e0, n.clone()).expect("unit"))
        .collect();
    let gen: Vec<Vec<Q>> = planes
        .iter()
        .map(|e| e.to_blaschke()[..4].to_vec())
        .collect();
    assert!(gen.iter().all(|g| *g == gen[0]), "same (x₀, x₁, x₂, x₃)");
    let iso: Vec<[Q; 3]> = planes
        .iter()
        .map(|e| e.to_isotropic().expect("image"))
        .collect();
    assert!(
        iso.iter().all(|y| y[..2] == iso[0][..2]),
        "one isotropic line"
    );
    assert_ne!(iso[0][2], iso[1][2]);
}

/// §3.2: the pe distance of two points of the cyclographic model on a hyperbolic line is
/// the tangential distance of the cycles (the distance of the contact points on a common
/// oriented tangent plane); on a parabolic line it is 0 (touching cycles, common surface
/// element); on an elliptic line ⟨a − b, a − b⟩ < 0 and there is no common tangent plane.
#[test]
fn s3_2_tangential_distance_and_line_types() {
    let e = OrientedPlane::new(q(1, 2), [q(2, 7), q(3, 7), q(6, 7)]).expect("unit");
    // two contact points on e and two radii ⇒ two cycles touching e there
    let foot = |s: Q, t: Q| -> [Q; 3] {
        let base: [Q; 3] = std::array::from_fn(|i| -e.e0.clone() * e.n[i].clone());
        let u1 = [q(3, 7), q(-2, 7), qi(0)];
        let u2 = [q(6, 7), qi(0), q(-2, 7)];
        std::array::from_fn(|i| {
            base[i].clone() + s.clone() * u1[i].clone() + t.clone() * u2[i].clone()
        })
    };
    let (ya, yb) = (foot(qi(1), qi(2)), foot(q(-3, 2), q(1, 3)));
    assert!(e.contains(&ya) && e.contains(&yb));
    let mk = |y: &[Q; 3], r: Q| {
        let m: [Q; 3] = std::array::from_fn(|i| y[i].clone() - r.clone() * e.n[i].clone());
        Cycle::new(m, r).expect("finite")
    };
    let (ca, cb) = (mk(&ya, qi(2)), mk(&yb, q(-5, 4)));
    assert!(ca.in_oriented_contact(&e) && cb.in_oriented_contact(&e));
    let dy = sub3(&ya, &yb);
    assert_eq!(ca.tangential_distance_squared(&cb), dot(&dy, &dy));
    // parabolic line: same contact point ⇒ d_pe = 0
    let cc = mk(&ya, q(7, 3));
    assert_eq!(ca.tangential_distance_squared(&cc), qi(0));
    // elliptic line: concentric spheres of radii 1 and 2 have no common oriented tangent
    // plane (e0 + n·m + 1 = 0 = e0 + n·m + 2 is impossible)
    let c1 = Cycle::new([qi(0), qi(0), qi(0)], qi(1)).expect("finite");
    let c2 = Cycle::new([qi(0), qi(0), qi(0)], qi(2)).expect("finite");
    assert_eq!(c1.tangential_distance_squared(&c2), qi(-1));
    assert!(c1.tangential_distance_squared(&c2) < qi(0));
}

/// §3.2 (3.8)/(3.9): a pe congruence (|λ| = 1) preserves the squared pe distance, a pe
/// similarity scales it by λ²; the rational boost with s = 1/3 has cosh = 5/4,
/// sinh = 3/4 and is pe-orthogonal.
#[test]
fn s3_2_pe_congruences_and_similarities() {
    let boost = LaguerreMap::boost(0, q(1, 3)).expect("s² ≠ 1");
    assert_eq!(boost.matrix()[0][0], q(5, 4));
    assert_eq!(boost.matrix()[0][3], q(3, 4));
    assert_eq!(boost.matrix()[3][3], q(5, 4));
    assert!(boost.certify().iter().all(|c| c.holds && c.exact));
    let a = Cycle::new([qi(1), qi(2), qi(0)], qi(1)).expect("finite");
    let b = Cycle::new([qi(-3), q(1, 2), qi(4)], qi(-2)).expect("finite");
    let d2 = a.tangential_distance_squared(&b);
    let cong = boost.compose(&LaguerreMap::translation([qi(1), qi(0), qi(-1)]));
    assert_eq!(
        cong.apply_cycle(&a)
            .tangential_distance_squared(&cong.apply_cycle(&b)),
        d2
    );
    let sim = LaguerreMap::similarity(qi(-3))
        .expect("λ ≠ 0")
        .compose(&cong);
    assert_eq!(
        sim.apply_cycle(&a)
            .tangential_distance_squared(&sim.apply_cycle(&b)),
        qi(9) * d2
    );
}

/// §3.2, the example after (3.9): a Euclidean hyperplane π of the cyclographic model is
/// mapped onto R³ = {x₄ = 0} by a Laguerre transformation — a translation if π ∥ R³, else
/// a boost. Here π: x₄ = (3/5)x₁ + 2 (its ideal points (x₁, x₂, x₃, 3x₁/5) are spacelike,
/// so π is Euclidean); the boost with s = −1/3 (tanh = −3/5) after the dilatation by −2
/// maps it onto x₄ = 0: all cycles of π become points.
#[test]
fn s3_2_euclidean_hyperplane_to_r3() {
    let map = LaguerreMap::boost(0, q(-1, 3))
        .expect("s² ≠ 1")
        .compose(&LaguerreMap::dilatation(qi(-2)));
    assert!(map.all_hold());
    for (x1, x2, x3) in [
        (qi(0), qi(0), qi(0)),
        (qi(5), qi(-1), qi(2)),
        (q(-7, 3), q(1, 2), qi(9)),
    ] {
        let x4 = q(3, 5) * x1.clone() + qi(2);
        let img = map.apply_point(&[x1, x2, x3, x4]);
        assert_eq!(img[3], qi(0), "the cycle on π becomes a point");
    }
    // parallel case: x₄ = 2 is mapped by the dilatation (translation in R⁴) by −2
    let par = LaguerreMap::dilatation(qi(-2));
    assert_eq!(par.apply_point(&[qi(1), qi(2), qi(3), qi(2)])[3], qi(0));
    // a hyperplane x₄ = x₁ (a γ-hyperplane, not Euclidean) cannot be mapped to R³: every
    // boost keeps it lightlike — its normal (1, 0, 0, −1) stays pe-null
    let h = map.hyperplane_matrix();
    let eps = [qi(0), qi(1), qi(0), qi(0), qi(-1)];
    let img: Vec<Q> = (0..5)
        .map(|c| (0..5).fold(qi(0), |s, r| s + eps[r].clone() * h[r][c].clone()))
        .collect();
    let lorentz = img[1].clone() * img[1].clone()
        + img[2].clone() * img[2].clone()
        + img[3].clone() * img[3].clone()
        - img[4].clone() * img[4].clone();
    assert_eq!(lorentz, qi(0));
}

/// §3.4, Lemma 3.1 and the isotropic conformal closure: a cycle whose isotropic sphere is
/// a plane has r + m₃ = 0 (it touches the plane z = 0 oriented by (0, 0, 1), which has no
/// image in I³); that plane itself is reported.
#[test]
fn s3_4_isotropic_closure() {
    let c = Cycle::new([qi(1), qi(2), qi(3)], qi(-3)).expect("finite");
    let sph = c.isotropic_sphere();
    assert_eq!(sph.alpha, qi(0), "r + m₃ = 0 ⇒ an isotropic plane");
    let z0 = OrientedPlane::new(qi(0), [qi(0), qi(0), qi(1)]).expect("unit");
    assert!(c.in_oriented_contact(&z0));
    assert!(matches!(
        z0.to_isotropic(),
        Err(LaguerreError::NoIsotropicImage(_))
    ));
    // the dual isotropic model has no image for it either (Y₃ = 0)
    assert!(OrientedPlane::from_dual_isotropic(&z0.to_dual_isotropic()).is_err());
}

/// §3.4: isotropic Möbius circles — the common oriented tangent planes of two cycles (the
/// tangent planes of a cone of revolution) are the intersection of two isotropic spheres,
/// whose top view is the circle (α₁ − α₂)S + (β₁ − β₂)·y + γ₁ − γ₂ = 0.
#[test]
fn s3_4_isotropic_mobius_circles() {
    let c1 = Cycle::new([qi(1), qi(2), qi(0)], qi(1)).expect("finite");
    let c2 = Cycle::new([qi(1), qi(2), qi(5)], qi(4)).expect("finite");
    let (s1, s2) = (c1.isotropic_sphere(), c2.isotropic_sphere());
    let a = s1.alpha.clone() - s2.alpha.clone();
    let b = [
        s1.beta[0].clone() - s2.beta[0].clone(),
        s1.beta[1].clone() - s2.beta[1].clone(),
    ];
    let g = s1.gamma.clone() - s2.gamma.clone();
    // a common tangent plane: n = (4/5, 0, −3/5) (n·(m₁ − m₂) + r₁ − r₂ = 3 − 3 = 0)
    let n0 = [q(4, 5), qi(0), q(-3, 5)];
    let e0 = -dot(&n0, &c1.center) - c1.radius.clone();
    let p = OrientedPlane::new(e0, n0)
        .expect("unit")
        .to_isotropic()
        .expect("image");
    let circ = |y: &[Q]| {
        a.clone() * (y[0].clone() * y[0].clone() + y[1].clone() * y[1].clone())
            + b[0].clone() * y[0].clone()
            + b[1].clone() * y[1].clone()
            + g.clone()
    };
    assert_eq!(circ(&p), qi(0));
    // every other point of the top-view circle: second intersection with lines through p
    for t in [qi(0), q(1, 2), qi(-3), q(7, 4)] {
        let w = [qi(1), t];
        let ww = dot(&w, &w);
        let lam = -(qi(2) * a.clone() * dot(&p[..2], &w) + dot(&b, &w)) / (a.clone() * ww);
        let y1 = p[0].clone() + lam.clone() * w[0].clone();
        let y2 = p[1].clone() + lam * w[1].clone();
        let y = [y1.clone(), y2.clone(), s1.eval(&y1, &y2)];
        assert_eq!(circ(&y), qi(0));
        assert!(s2.contains(&y), "on both isotropic spheres");
        let e = OrientedPlane::from_isotropic(&y);
        assert!(c1.in_oriented_contact(&e) && c2.in_oriented_contact(&e));
    }
}

/// §3.5: the dual isotropic image Λ*(e) (3.16) is the bisector of e and x₃ = 0 (points at
/// equal signed distance), and the polarity with respect to the isotropic sphere
/// x₁² + x₂² − 2x₃ = 0 maps it to (e₁, e₂, −e₀)/(1 − e₃): Λ(e) reflected in y₃ = 0.
#[test]
fn s3_5_dual_isotropic_model_and_polarity() {
    for e in [
        OrientedPlane::new(q(-7, 5), [q(2, 7), q(6, 7), q(-3, 7)]).expect("unit"),
        OrientedPlane::new(qi(3), [q(-2, 3), q(1, 3), q(2, 3)]).expect("unit"),
    ] {
        let y = e.to_dual_isotropic();
        // bisector: points x with Y·(1, x) = 0 satisfy e0 + n·x = x₃
        for (x1, x2) in [(qi(0), qi(0)), (qi(2), q(-1, 3)), (q(5, 2), qi(4))] {
            let x3 = -(y[0].clone() + y[1].clone() * x1.clone() + y[2].clone() * x2.clone())
                / y[3].clone();
            let x = [x1, x2, x3.clone()];
            assert_eq!(e.signed_distance(&x), x3, "equal signed distances");
        }
        // pole of the plane Y w.r.t. x₁² + x₂² − 2x₀x₃ = 0 (matrix M = M⁻¹):
        // (x₀, x₁, x₂, x₃) = (−Y₃, Y₁, Y₂, −Y₀)
        let pole = [-y[3].clone(), y[1].clone(), y[2].clone(), -y[0].clone()];
        let aff = [
            pole[1].clone() / pole[0].clone(),
            pole[2].clone() / pole[0].clone(),
            pole[3].clone() / pole[0].clone(),
        ];
        let lam = e.to_isotropic().expect("image");
        assert_eq!(
            aff,
            [lam[0].clone(), lam[1].clone(), -lam[2].clone()],
            "π∘Λ*(e) = Λ(e) reflected in y₃ = 0"
        );
    }
}
