//! D. Gruber, *Rationale Parametrisierungen von Kugelhüllflächen* (2008), chapters 1–2, and
//! the Möbius-geometry / canal-surface parts of M. Peternell, *Rational Parametrizations
//! for Envelopes of Quadric Families* (ch. 2 and §3.8/§4.5): every formula and printed
//! example reproduced exactly, with the errata of docs/math/lines-and-canal.md
//! confirmed by a counter-check where the printed form differs.

use rcagd::canal::{
    canal_surface, krasauskas_bound, sum_of_two_squares, CanalBuild, CanalError, CanalOptions,
    CanalSpine, GaussianSplit, QuadraticCanal, SumOfSquares,
};
use rcagd::cyclographic::{
    causal_type, isotropic_image, line_image, lorentz, mobius_bilinear, mobius_form, mobius_image,
    mobius_point, mobius_reflection, omega_point, pencil_type, polar_plane, CausalType, LineImage,
    MobiusImage, OrientedSphere, PencilType,
};
use rcagd::lines::plucker::{incidence_matrix, klein_form, wedge};
use rcagd::lines::{reciprocal_product, CongruenceKind, Line, LinearComplex, LinearCongruence};
use rcagd::Certified;
use rcagd_algebra::complex::{conj_poly, Complex};
use rcagd_algebra::{Poly, Rational, Scalar};

fn q(n: i64) -> Rational {
    Rational::from(n)
}
fn r(n: i64, d: i64) -> Rational {
    Rational::from_ratio(n, d)
}
fn v4(a: [i64; 4]) -> [Rational; 4] {
    a.map(q)
}
fn p(c: &[i64]) -> Poly<Rational> {
    Poly::from_ints(c)
}
fn pr(c: &[(i64, i64)]) -> Poly<Rational> {
    Poly::new(c.iter().map(|&(n, d)| r(n, d)).collect())
}
fn scale6(k: &Rational, l: &[Rational; 6]) -> [Rational; 6] {
    core::array::from_fn(|i| k.clone() * l[i].clone())
}
fn mat_vec(m: &[[Rational; 4]; 4], v: &[Rational; 4]) -> [Rational; 4] {
    core::array::from_fn(|i| (0..4).fold(q(0), |acc, j| acc + m[i][j].clone() * v[j].clone()))
}

// ------------------------------------------------------------------------------------
// §1.1.1 Plücker coordinates
// ------------------------------------------------------------------------------------

#[test]
fn s003_1_1_wedge_homogeneity_and_identity() {
    // (1.1)/(1.2): (λp + μq) ∧ (ρp + σq) = (λσ − μρ)(p ∧ q); (1.3) Plücker identity
    let (pp, qq) = (v4([1, 2, -1, 3]), v4([2, 0, 5, -1]));
    let l = wedge(&pp, &qq);
    assert_eq!(klein_form(&l), q(0));
    let (la, mu, rho, sg) = (q(3), q(-2), r(1, 2), q(5));
    let a: [Rational; 4] =
        core::array::from_fn(|i| la.clone() * pp[i].clone() + mu.clone() * qq[i].clone());
    let b: [Rational; 4] =
        core::array::from_fn(|i| rho.clone() * pp[i].clone() + sg.clone() * qq[i].clone());
    let k = la * sg - mu * rho;
    assert_eq!(wedge(&a, &b), scale6(&k, &l));
    // (1.6): for affine points the moment is p × direction
    let line = Line::from_affine_points(&[q(1), q(2), q(3)], &[q(4), q(0), q(-1)]).expect("l");
    let d = line.direction();
    let m = line.moment();
    let pxd = [
        q(2) * d[2].clone() - q(3) * d[1].clone(),
        q(3) * d[0].clone() - q(1) * d[2].clone(),
        q(1) * d[1].clone() - q(2) * d[0].clone(),
    ];
    assert_eq!(m, pxd);
    assert_eq!(
        d[0].clone() * m[0].clone() + d[1].clone() * m[1].clone() + d[2].clone() * m[2].clone(),
        q(0)
    );
}

#[test]
fn s003_1_1_points_s_i_and_erratum_e23() {
    // docs/math/lines-and-canal.md, "Plücker coordinates": s_i ∧ s_j = (l1, l2, l3, l6, −l5, l4)·l for the pairs 12, 13, 14, 23, 24, 34
    let line = Line::from_points(&v4([1, 2, -1, 3]), &v4([2, 0, 5, -1])).expect("l");
    let l = line.coords().clone();
    let s = line.coordinate_plane_points();
    let factors = [
        (0, 1, l[0].clone()),
        (0, 2, l[1].clone()),
        (0, 3, l[2].clone()),
        (1, 2, l[5].clone()),
        (1, 3, -l[4].clone()),
        (2, 3, l[3].clone()),
    ];
    for (i, j, f) in &factors {
        assert_eq!(wedge(&s[*i], &s[*j]), scale6(f, &l), "pair {i}{j}");
    }
    // docs/math/lines-and-canal.md, Errata G23: the factor can vanish, then s_i ∧ s_j = 0 is not the line
    let lx = Line::from_affine_points(&[q(0), q(0), q(0)], &[q(1), q(0), q(0)]).expect("x-axis");
    let sx = lx.coordinate_plane_points();
    assert!(
        wedge(&sx[0], &sx[2]).iter().all(|c| *c == q(0)),
        "s1 ∧ s3 = l2·l = 0"
    );
    let (a, b) = lx.points();
    assert!(Line::from_points(&a, &b).expect("pts").same_line(&lx));
}

#[test]
fn s003_1_5_axis_coordinates() {
    // (1.5): the wedge of two planes is (l4, l5, l6; l1, l2, l3)
    let line = Line::from_points(&v4([1, 2, -1, 3]), &v4([2, 0, 5, -1])).expect("l");
    let (u, w) = line.planes();
    let a = wedge(&u, &w);
    let l = line.coords();
    let swapped = [
        l[3].clone(),
        l[4].clone(),
        l[5].clone(),
        l[0].clone(),
        l[1].clone(),
        l[2].clone(),
    ];
    let k = a
        .iter()
        .zip(&swapped)
        .find(|(_, s)| **s != q(0))
        .map(|(x, s)| x.clone() / s.clone())
        .expect("k");
    assert_eq!(a, scale6(&k, &swapped));
    let from_planes = Line::from_planes(&u, &w).expect("planes");
    assert!(from_planes.same_line(&line));
    assert!(from_planes.all_hold());
}

// ------------------------------------------------------------------------------------
// §1.1.2 incidence and intersection
// ------------------------------------------------------------------------------------

#[test]
fn s003_1_7_incidence_matrix() {
    let (pp, qq) = (v4([1, 2, -1, 3]), v4([2, 0, 5, -1]));
    let l = wedge(&pp, &qq);
    let m = incidence_matrix(&l);
    assert!(mat_vec(&m, &pp).iter().all(|x| *x == q(0)));
    assert!(mat_vec(&m, &qq).iter().all(|x| *x == q(0)));
    assert!(!mat_vec(&m, &v4([1, 0, 0, 0])).iter().all(|x| *x == q(0)));
    let line = Line::from_points(&pp, &qq).expect("l");
    assert!(line.all_hold());
}

#[test]
fn s003_1_10_intersection_condition_and_erratum_e1() {
    // (1.8)–(1.10): g, h meet iff ⟨ḡ, h⟩ + ⟨g, h̄⟩ = 0
    let pp = [q(1), q(0), q(0)];
    let qq = [q(0), q(3), q(2)];
    let g = Line::from_point_direction(&pp, &[q(1), q(1), q(0)]).expect("g");
    let x = [q(3), q(2), q(0)]; // a point of g: p + 2(1,1,0)
    let h = Line::from_affine_points(&x, &qq).expect("h through a point of g");
    assert_eq!(g.reciprocal_product(&h), q(0));
    assert!(g.meets(&h));
    let meet = g.intersection(&h).expect("meet");
    assert_eq!(
        [
            meet[1].clone() / meet[0].clone(),
            meet[2].clone() / meet[0].clone(),
            meet[3].clone() / meet[0].clone()
        ],
        x
    );
    // docs/math/lines-and-canal.md, Errata G1: coplanarity is q − p ⊥ g × h, NOT q − p ⊥ g, h
    let (gd, hd) = (g.direction(), h.direction());
    let qp: Vec<Rational> = (0..3).map(|i| qq[i].clone() - pp[i].clone()).collect();
    let dot = |a: &[Rational], b: &[Rational]| {
        a.iter()
            .zip(b)
            .fold(q(0), |s, (x, y)| s + x.clone() * y.clone())
    };
    let cross = [
        gd[1].clone() * hd[2].clone() - gd[2].clone() * hd[1].clone(),
        gd[2].clone() * hd[0].clone() - gd[0].clone() * hd[2].clone(),
        gd[0].clone() * hd[1].clone() - gd[1].clone() * hd[0].clone(),
    ];
    assert_eq!(dot(&qp, &cross), q(0));
    assert_ne!(dot(&qp, &gd), q(0), "the printed 'q − p ⊥ g' is false here");
    // (1.10) holds for parallel lines too
    let g2 = Line::from_point_direction(&[q(0), q(5), q(1)], &[q(1), q(1), q(0)]).expect("g2");
    assert_eq!(g.reciprocal_product(&g2), q(0));
    // skew lines
    let k = Line::from_point_direction(&[q(0), q(0), q(1)], &[q(0), q(1), q(0)]).expect("k");
    assert_ne!(reciprocal_product(g.coords(), k.coords()), q(0));
}

// ------------------------------------------------------------------------------------
// §1.1.3–1.1.8 complexes, congruences, nets
// ------------------------------------------------------------------------------------

#[test]
fn s003_1_11_linear_complexes() {
    // (1.11): c₄x₁ + c₅x₂ + c₆x₃ + c₁x₄ + c₂x₅ + c₃x₆ = 0; singular ⇔ lines meeting the axis
    let axis = Line::from_affine_points(&[q(1), q(1), q(0)], &[q(1), q(1), q(1)]).expect("a");
    let c = LinearComplex::singular(&axis);
    assert!(c.is_singular());
    for (a, b, meets) in [
        ([1, 1, 5], [3, 2, 1], true),
        ([0, 0, 0], [1, 0, 0], false),
        ([0, 0, 0], [2, 2, 7], true),
    ] {
        let x = Line::from_affine_points(&a.map(q), &b.map(q)).expect("x");
        assert_eq!(c.contains(&x), meets);
        assert_eq!(x.meets(&axis), meets);
    }
    let reg = LinearComplex::new([1, 0, 0, 2, 0, 0].map(q)).expect("regular");
    assert!(!reg.is_singular());
    assert!(reg.all_hold());
    let (ax, pitch) = reg.axis_and_parameter().expect("axis");
    assert_eq!(pitch, q(2));
    assert_eq!(ax.coords().clone(), [1, 0, 0, 0, 0, 0].map(q));
}

#[test]
fn s003_1_1_6_line_nets() {
    // hyperbolic: lines meeting two skew real focal lines
    let a1 = Line::from_affine_points(&[q(0), q(0), q(0)], &[q(1), q(0), q(0)]).expect("a1");
    let a2 = Line::from_affine_points(&[q(0), q(0), q(1)], &[q(0), q(1), q(1)]).expect("a2");
    let h = LinearCongruence::from_focal_lines(&a1, &a2).expect("h");
    assert_eq!(h.kind(), CongruenceKind::Hyperbolic);
    assert!(h.all_hold());
    // fibration: a unique line through each regular point (§1.1.5)
    let x = h.line_through(&v4([1, 3, 2, 5])).expect("fibre");
    assert!(x.meets(&a1) && x.meets(&a2) && x.contains_point(&v4([1, 3, 2, 5])));
    // hyperbolic net from two regular complexes with a non-square discriminant: focal lines
    // over Q(√d)
    let c1 = LinearComplex::new([1, 0, 0, 1, 0, 0].map(q)).expect("c1");
    let c2 = LinearComplex::new([0, 1, 0, 0, -2, 1].map(q)).expect("c2");
    let n = LinearCongruence::new(c1.clone(), c2).expect("n");
    assert_eq!(n.kind(), CongruenceKind::Hyperbolic);
    assert!(n.all_hold(), "{:?}", n.certify());
    // elliptic: conjugate complex focal lines
    let e = LinearCongruence::new(
        c1.clone(),
        LinearComplex::new([0, 1, 0, 0, 1, 0].map(q)).expect("c"),
    )
    .expect("e");
    assert_eq!(e.kind(), CongruenceKind::Elliptic);
    assert!(e.all_hold());
    let fibre = e
        .line_through(&v4([1, 0, 0, 0]))
        .expect("real line of an elliptic net");
    assert!(e.contains(&fibre));
    // parabolic: regular complex ∩ singular complex whose axis lies in it (§1.1.6)
    let axis = Line::from_coords([0, 1, 0, 0, 0, 0].map(q)).expect("axis");
    assert!(c1.contains(&axis));
    let pnet = LinearCongruence::new(c1, LinearComplex::singular(&axis)).expect("p");
    assert_eq!(pnet.kind(), CongruenceKind::Parabolic);
    assert!(pnet.all_hold());
    // singular net (bundle and field) of two meeting lines
    let b = Line::from_affine_points(&[q(0), q(0), q(0)], &[q(0), q(1), q(0)]).expect("b");
    let s = LinearCongruence::from_focal_lines(&a1, &b).expect("s");
    assert_eq!(s.kind(), CongruenceKind::Degenerate);
    assert!(s.all_hold());
}

#[test]
fn s003_1_1_8_one_four_congruence_example() {
    // β(t) = (3t + t⁴, t²(4 − t²), t(4 − t²)) has order 4 and meets the x-axis in the three
    // real points t = 0, ±2; the congruence line through P joins P to the residual
    // intersection of the plane P ∨ (x-axis) with β.
    let beta = |t: i64| [3 * t + t.pow(4), t * t * (4 - t * t), t * (4 - t * t)];
    for t in [0, 2, -2] {
        let b = beta(t);
        assert_eq!((b[1], b[2]), (0, 0), "β({t}) on the x-axis");
    }
    let xaxis = Line::from_affine_points(&[q(0), q(0), q(0)], &[q(1), q(0), q(0)]).expect("g");
    let pp = v4([1, 7, 1, 1]);
    let plane = xaxis.join_point(&pp).expect("plane"); // y = z
                                                       // β ∩ plane: t(4 − t²)(t − 1) = 0 → residual t = 1
    let b1 = beta(1);
    let qq = v4([1, b1[0], b1[1], b1[2]]);
    assert_eq!(
        (0..4).fold(q(0), |s, i| s + plane[i].clone() * qq[i].clone()),
        q(0)
    );
    let line = Line::from_points(&pp, &qq).expect("congruence line");
    assert!(line.meets(&xaxis) && line.all_hold());
}

// ------------------------------------------------------------------------------------
// §1.2 the cyclographic map
// ------------------------------------------------------------------------------------

#[test]
fn s003_1_13_oriented_contact_and_erratum_e2() {
    let k1 = OrientedSphere::new([q(0), q(0), q(0)], q(2));
    let k2 = OrientedSphere::new([q(0), q(3), q(4)], q(7));
    // (1.13): |M − N|² = (m₄ − n₄)²
    assert_eq!(k1.contact_residual(&k2), q(0));
    let c = k1.contact(&k2).expect("contact");
    assert!(c.all_hold());
    // docs/math/lines-and-canal.md, Errata G2: the printed (1.16) ⟨k₁, k₂⟩_pe = 0 does not express contact
    assert_ne!(lorentz(&k1.to_point(), &k2.to_point()), q(0));
    // (1.14): a point (radius 0) on a sphere
    let pt = OrientedSphere::new([q(2), q(0), q(0)], q(0));
    assert!(pt.in_oriented_contact(&k1));
    assert_eq!(k1.power(&[q(2), q(0), q(0)]), q(0));
    // causal types (§1.2.1)
    assert_eq!(causal_type(&v4([1, 0, 0, 0])), CausalType::Spacelike);
    assert_eq!(causal_type(&v4([3, 4, 0, 5])), CausalType::Lightlike);
    assert_eq!(causal_type(&v4([0, 0, 1, 2])), CausalType::Timelike);
}

#[test]
fn s003_1_19_polarity_and_light_cone() {
    // (1.18) points → planes D p; (1.19) the polar line E g is the intersection of the polar
    // planes of two points of g
    let (a, b) = (v4([1, 2, 0, 1]), v4([0, 1, 1, 3]));
    let g = Line::from_points(&a, &b).expect("g");
    let h = g.polar_omega();
    let via_planes = Line::from_planes(&polar_plane(&a), &polar_plane(&b)).expect("polar");
    assert!(h.same_line(&via_planes));
    // light cone: the isotropic lines through P meet x₄ = 0 in the sphere γ(P)
    let pnt = v4([1, -2, 3, 4]);
    let sphere = OrientedSphere::from_point(&pnt);
    for (s, t) in [(0, 0), (1, 0), (2, -3), (-1, 5)] {
        let w = omega_point(&q(s), &q(t));
        let x = isotropic_image(&pnt, &w).expect("img");
        assert_eq!(sphere.power(&x), q(0));
    }
}

#[test]
fn s003_1_2_2_images_of_lines() {
    let pnt = v4([0, 0, 0, 2]);
    assert!(matches!(
        line_image(&pnt, &v4([0, 0, 1, 0])).expect("i"),
        LineImage::Cylinder { .. }
    ));
    match line_image(&pnt, &v4([2, 0, 0, 1])).expect("i") {
        LineImage::Cone {
            vertex,
            sin2_half_angle,
            ..
        } => {
            assert_eq!(vertex, [q(-4), q(0), q(0)]);
            assert_eq!(sin2_half_angle, r(1, 4));
        }
        other => panic!("{other:?}"),
    }
    assert!(matches!(
        line_image(&pnt, &v4([0, 1, 0, 1])).expect("i"),
        LineImage::Plane { .. }
    ));
    assert!(matches!(
        line_image(&pnt, &v4([0, 1, 0, 2])).expect("i"),
        LineImage::NotReal
    ));
}

// ------------------------------------------------------------------------------------
// chapter 2: canal surfaces
// ------------------------------------------------------------------------------------

fn example_2_3() -> CanalSpine<Rational> {
    // m(u) = (u, 0, u²), r(u) = u²/4 (2.19)
    CanalSpine::polynomial(
        [p(&[0, 1]), p(&[]), p(&[0, 0, 1])],
        pr(&[(0, 1), (0, 1), (1, 4)]),
    )
}

#[test]
fn s003_2_3_example_cyclographic_reparametrization_and_gamma() {
    let spine = example_2_3();
    let canal = QuadraticCanal::from_spine(&spine).expect("quadratic");
    // (2.21) u = 4s/(−3 + 5s² + 5t²) (docs/math/lines-and-canal.md, Errata G5: k̇(u), not k̇(t))
    let (num, den) = canal.parameter();
    for (s, t) in [(r(1, 3), r(2, 7)), (q(2), r(-1, 2)), (r(-5, 3), q(1))] {
        let u = num.eval(&s, &t) / den.eval(&s, &t);
        let printed = q(4) * s.clone()
            / (q(-3) + q(5) * s.clone() * s.clone() + q(5) * t.clone() * t.clone());
        assert_eq!(u, printed);
        // the printed Γ
        let ss = s.clone() * s.clone() + t.clone() * t.clone();
        let pre = q(4) * s.clone() / ((q(-3) + q(5) * ss.clone()).pow(2) * (q(1) + ss.clone()));
        let gamma = [
            pre.clone()
                * (q(-3)
                    + q(2) * t.clone() * t.clone()
                    + q(5) * s.clone().pow(4)
                    + q(10) * s.clone() * s.clone() * t.clone() * t.clone()
                    + q(5) * t.clone().pow(4)),
            pre.clone() * (q(-2) * s.clone() * t.clone()),
            pre * s.clone() * (q(3) + q(5) * ss),
        ];
        assert_eq!(canal.eval(&s, &t).expect("point"), gamma);
    }
    assert!(canal.all_hold(), "{:?}", canal.certify());
    // the same surface by the Peternell–Pottmann recipe (docs/math/lines-and-canal.md, "Canal surfaces") needs Q(√15):
    // D = 1 + 4u² − u²/4 = 1 + (15/4)u²
    assert_eq!(
        spine.discriminant().expect("D"),
        pr(&[(1, 1), (0, 1), (15, 4)])
    );
    let b = canal_surface(&spine, &CanalOptions::default()).expect("build");
    assert_eq!(b.radicand(), Some(&q(15)));
    assert!(b.all_hold(), "{:?}", b.certify());
    // both parametrize the same surface: a point of the cyclographic Γ lies on the sphere
    // K(u) and on the plane K̇(u) — i.e. on the PP characteristic circle at that u
    let s = r(1, 3);
    let t = r(2, 7);
    let u = num.eval(&s, &t) / den.eval(&s, &t);
    let x = canal.eval(&s, &t).expect("pt");
    let (m, rad) = spine.eval(&u).expect("sphere");
    let d: Vec<Rational> = (0..3).map(|i| x[i].clone() - m[i].clone()).collect();
    let dot = |a: &[Rational], b: &[Rational]| {
        a.iter()
            .zip(b)
            .fold(q(0), |s, (x, y)| s + x.clone() * y.clone())
    };
    assert_eq!(dot(&d, &d), rad.clone() * rad.clone());
    let md = [q(1), q(0), q(2) * u.clone()];
    let rd = u.clone() / q(2);
    assert_eq!(dot(&d, &md) + rad * rd, q(0));
}

#[test]
fn s003_2_2_contact_sign_erratum_e3() {
    // the printed (2.2) ⟨x − m, ṁ⟩ − r ṙ = 0 fails on the envelope; + r ṙ holds (E3)
    let spine = example_2_3();
    let canal = QuadraticCanal::from_spine(&spine).expect("q");
    let (num, den) = canal.parameter();
    let (s, t) = (q(2), r(1, 3));
    let u = num.eval(&s, &t) / den.eval(&s, &t);
    let x = canal.eval(&s, &t).expect("pt");
    let (m, rad) = spine.eval(&u).expect("sphere");
    let md = [q(1), q(0), q(2) * u.clone()];
    let rd = u / q(2);
    let xm: Rational = (0..3).fold(q(0), |acc, i| {
        acc + (x[i].clone() - m[i].clone()) * md[i].clone()
    });
    assert_eq!(xm.clone() + rad.clone() * rd.clone(), q(0));
    assert_ne!(xm - rad * rd, q(0));
}

#[test]
fn s003_2_11_pole_and_cone_vertex() {
    // (2.11): s = m − (r/ṙ)ṁ is the pole of K̇ w.r.t. K; (2.12) z = s − e = −ṁ/ṙ
    let (m, rr, md, rd) = ([q(1), q(2), q(0)], q(3), [q(2), q(-1), q(2)], q(2));
    let s: Vec<Rational> = (0..3)
        .map(|i| m[i].clone() - rr.clone() / rd.clone() * md[i].clone())
        .collect();
    // polar plane of s: (s − m)·(x − m) = r² ⇔ ṁ·(x − m) = −r ṙ (corrected sign)
    let sm: Vec<Rational> = (0..3).map(|i| s[i].clone() - m[i].clone()).collect();
    for i in 0..3 {
        assert_eq!(sm[i].clone() * (-rd.clone() / rr.clone()), md[i].clone());
    }
    let e: Vec<Rational> = (0..3)
        .map(|i| m[i].clone() + (q(1) - rr.clone()) / rd.clone() * md[i].clone())
        .collect();
    for i in 0..3 {
        assert_eq!(s[i].clone() - e[i].clone(), -md[i].clone() / rd.clone());
    }
}

#[test]
fn s003_2_13_stereographic_circle_erratum_e4() {
    // the unit normals q of the envelope project to the circle with centre μ = −(ṁ₁, ṁ₂)/c
    // and radius² ρ² = D/c² (c = ṙ + ṁ₃); the printed ρ² = D/c is wrong (E4)
    let spine = CanalSpine::polynomial(
        [p(&[0, 1]), pr(&[(0, 1), (0, 1), (1, 2)]), p(&[0, 0, 0, 1])],
        p(&[1, 1]),
    );
    let b = canal_surface(
        &spine,
        &CanalOptions {
            axis: Some(rcagd::canal::AxisChoice {
                axis: 2,
                positive: true,
            }),
            ..CanalOptions::default()
        },
    )
    .expect("build");
    let s = b.to_ext();
    let t = rcagd_algebra::QuadExt::rational(r(1, 2));
    let u = rcagd_algebra::QuadExt::rational(r(3, 5));
    let x = s.eval(&t, &u).expect("pt");
    let (m, rad) = s.spine().eval(&t).expect("sphere");
    let qv: Vec<_> = (0..3)
        .map(|i| (x[i].clone() - m[i].clone()) / rad.clone())
        .collect();
    // stereographic projection from (0, 0, 1): k = (q₁, q₂)/(1 − q₃)
    let one = rcagd_algebra::QuadExt::rational(q(1));
    let k1 = qv[0].clone() / (one.clone() - qv[2].clone());
    let k2 = qv[1].clone() / (one - qv[2].clone());
    // ṁ = (1, t, 3t²), ṙ = 1 at t = 1/2
    let (md, rd) = ([r(1, 1), r(1, 2), r(3, 4)], q(1));
    let c = rd.clone() + md[2].clone();
    let d = md.iter().fold(q(0), |s, x| s + x.clone() * x.clone()) - rd.clone() * rd;
    let e = |x: Rational| rcagd_algebra::QuadExt::rational(x);
    let mu = [e(-md[0].clone() / c.clone()), e(-md[1].clone() / c.clone())];
    let rho2 = (k1 - mu[0].clone()).pow2() + (k2 - mu[1].clone()).pow2();
    assert_eq!(rho2, e(d.clone() / (c.clone() * c.clone())));
    assert_ne!(rho2, e(d / c));
}

trait Pow2 {
    fn pow2(self) -> Self;
}
impl Pow2 for rcagd_algebra::QuadExt {
    fn pow2(self) -> Self {
        self.clone() * self
    }
}

#[test]
fn s003_satz1_rational_parametrizations() {
    // Satz 1: rational spine and radius give a rational parametrization; exact over Q when D
    // is a sum of two rational squares.
    // m = (t², t, 0), r = t: D = 4t² + 1 − 1 = 4t² = (2t)² + 0²
    let spine = CanalSpine::polynomial([p(&[0, 0, 1]), p(&[0, 1]), p(&[])], p(&[0, 1]));
    let b = canal_surface(&spine, &CanalOptions::default()).expect("b");
    assert!(matches!(b, CanalBuild::Rational(_)));
    assert!(b.all_hold());
    // a rational family with rational weight: m = (2t, 1 − t², 0)/(1 + t²) (unit circle),
    // r = 1/2: a torus; D = 4/(1+t²)²·W⁴/d² is a square
    let w = p(&[1, 0, 1]);
    let spine = CanalSpine::new(
        w.clone(),
        [p(&[0, 2]), p(&[1, 0, -1]), p(&[])],
        w.scale(&r(1, 2)),
    )
    .expect("torus family");
    let b = canal_surface(&spine, &CanalOptions::default()).expect("torus");
    let s = b.as_rational().expect("rational torus");
    assert!(b.all_hold(), "{:?}", b.certify());
    // the torus (x² + y² + z² + R² − ρ²)² = 4R²(x² + y²), R = 1, ρ = 1/2
    let x = s.eval(&r(1, 3), &r(-2, 5)).expect("pt");
    let s2 = x.iter().fold(q(0), |a, c| a + c.clone() * c.clone());
    let lhs = (s2 + q(1) - r(1, 4)).pow(2);
    let rhs = q(4) * (x[0].clone() * x[0].clone() + x[1].clone() * x[1].clone());
    assert_eq!(lhs, rhs);
}

#[test]
fn s003_2_4_krasauskas_pieces() {
    // (2.22) Q = x₀x₃ − x₁x₂; (2.23) f(U) = (U₀U₂, U₀U₃, U₁U₂, U₁U₃) ∈ Q
    let f = |u: &[Rational; 4]| {
        [
            u[0].clone() * u[2].clone(),
            u[0].clone() * u[3].clone(),
            u[1].clone() * u[2].clone(),
            u[1].clone() * u[3].clone(),
        ]
    };
    let qf = |x: &[Rational; 4]| x[0].clone() * x[3].clone() - x[1].clone() * x[2].clone();
    let a = v4([1, 2, -1, 3]);
    let b = v4([2, -3, 1, 1]);
    assert_eq!(qf(&f(&a)), q(0));
    // (2.24) corrected (docs/math/lines-and-canal.md, Errata G6): f((λ, μ)·U) = λμ f(U)
    let (la, mu) = (q(3), r(-1, 2));
    let scaled = [
        la.clone() * a[0].clone(),
        la.clone() * a[1].clone(),
        mu.clone() * a[2].clone(),
        mu.clone() * a[3].clone(),
    ];
    let fa = f(&a);
    let fs = f(&scaled);
    for i in 0..4 {
        assert_eq!(fs[i], la.clone() * mu.clone() * fa[i].clone());
    }
    // (2.25) the plane e(a, b) = (l₁₃, −l₁₂, −l₀₃, l₀₂) contains f(a), f(b), f(a + b)
    let l = |i: usize, j: usize| a[i].clone() * b[j].clone() - a[j].clone() * b[i].clone();
    let e = [l(1, 3), -l(1, 2), -l(0, 3), l(0, 2)];
    let ab: [Rational; 4] = core::array::from_fn(|i| a[i].clone() + b[i].clone());
    for x in [f(&a), f(&b), f(&ab)] {
        assert_eq!(
            (0..4).fold(q(0), |s, i| s + e[i].clone() * x[i].clone()),
            q(0)
        );
    }
    // (2.26)/(2.27): e((λ, μ)·a, b) = λL + μM
    let l2 =
        |i: usize, j: usize| scaled[i].clone() * b[j].clone() - scaled[j].clone() * b[i].clone();
    let e2 = [l2(1, 3), -l2(1, 2), -l2(0, 3), l2(0, 2)];
    let ll = [
        a[1].clone() * b[3].clone(),
        -a[1].clone() * b[2].clone(),
        -a[0].clone() * b[3].clone(),
        a[0].clone() * b[2].clone(),
    ];
    let mm = [
        -a[3].clone() * b[1].clone(),
        a[2].clone() * b[1].clone(),
        a[3].clone() * b[0].clone(),
        -a[2].clone() * b[0].clone(),
    ];
    for i in 0..4 {
        assert_eq!(
            e2[i],
            la.clone() * ll[i].clone() + mu.clone() * mm[i].clone()
        );
    }
}

type C = Complex<Rational>;
fn c(a: i64, b: i64) -> C {
    Complex::new(q(a), q(b))
}

#[test]
fn s003_2_29_phi_and_gcd_recovery() {
    // (2.28) Φ(x) = ½(x₀ + x₃, x₁ + ix₂, x₁ − ix₂, x₀ − x₃); (2.29) Φ(f_s(U)) = f(U₊)
    let phi = |x: &[C; 4]| {
        let h = C::new(r(1, 2), q(0));
        let i = C::i();
        [
            h.clone() * (x[0].clone() + x[3].clone()),
            h.clone() * (x[1].clone() + i.clone() * x[2].clone()),
            h.clone() * (x[1].clone() - i * x[2].clone()),
            h * (x[0].clone() - x[3].clone()),
        ]
    };
    let fs = |u0: &C, u1: &C| {
        let a = u0.clone() * u1.conj();
        [
            C::from_real(u0.norm_sq() + u1.norm_sq()),
            C::from_real(q(2) * a.re.clone()),
            C::from_real(q(2) * a.im.clone()),
            C::from_real(u0.norm_sq() - u1.norm_sq()),
        ]
    };
    let (u0, u1) = (c(1, 2), c(-3, 1));
    let x = fs(&u0, &u1);
    // on S²
    assert_eq!(
        x[0].clone() * x[0].clone()
            - x[1].clone() * x[1].clone()
            - x[2].clone() * x[2].clone()
            - x[3].clone() * x[3].clone(),
        C::from_real(q(0))
    );
    let y = phi(&x);
    let fu = [
        u0.clone() * u0.conj(),
        u0.clone() * u1.conj(),
        u1.clone() * u0.conj(),
        u1.clone() * u1.conj(),
    ];
    assert_eq!(y, fu);
    // (2.32) gcd recovery for polynomial U: U₀ = gcd(y₀, y₁), U₁ = gcd(y₀, y₁)·y₃/y₁
    let pu0 = Poly::new(vec![c(1, 1), c(0, 1), c(2, 0)]);
    let pu1 = Poly::new(vec![c(3, 0), c(-1, 2)]);
    let y0 = &pu0 * &conj_poly(&pu0);
    let y1 = &pu0 * &conj_poly(&pu1);
    let y3 = &pu1 * &conj_poly(&pu1);
    let g = y0.gcd(&y1);
    assert_eq!(g, pu0.monic());
    let u1_rec = (&g * &y3).div_exact(&y1).expect("exact");
    assert_eq!(u1_rec.monic(), pu1.monic());
}

#[test]
fn s003_2_33_discriminant_identity_erratum_e7() {
    // B* = iBΦ⁻¹: B*₀B*₃ − B*₁B*₂ = B₁² + B₂² + B₃² − B₀² (printed B₁² + B₂² + B₄² + B₀²)
    // Φ⁻¹(y) = (y₀ + y₃, y₁ + y₂, −i(y₁ − y₂), y₀ − y₃); B*ⱼ = i Σₖ Bₖ (Φ⁻¹)ₖⱼ
    let bv = [q(2), q(-1), q(3), q(5)];
    let inv = [
        [c(1, 0), c(0, 0), c(0, 0), c(1, 0)],
        [c(0, 0), c(1, 0), c(1, 0), c(0, 0)],
        [c(0, 0), c(0, -1), c(0, 1), c(0, 0)],
        [c(1, 0), c(0, 0), c(0, 0), c(-1, 0)],
    ];
    let bs: Vec<C> = (0..4)
        .map(|j| {
            C::i()
                * (0..4).fold(C::from_real(q(0)), |s, k| {
                    s + C::from_real(bv[k].clone()) * inv[k][j].clone()
                })
        })
        .collect();
    let lhs = bs[0].clone() * bs[3].clone() - bs[1].clone() * bs[2].clone();
    let corrected =
        bv[1].clone().pow(2) + bv[2].clone().pow(2) + bv[3].clone().pow(2) - bv[0].clone().pow(2);
    assert_eq!(lhs, C::from_real(corrected.clone()));
    let printed = bv[1].clone().pow(2) + bv[2].clone().pow(2) + bv[0].clone().pow(2);
    assert_ne!(C::from_real(printed), lhs);
    // for a canal surface B = (ṙ, ṁ): the discriminant is |ṁ|² − ṙ² = D (2.34)
}

#[test]
fn s003_2_35_factorizations_and_satz2_erratum_e9() {
    // (2.35): D = ∏ (λλ̄)^{pᵢ} ρ²; ∏(pᵢ + 1) factorizations D = l₀₁ l̄₀₁
    // (t² + 1)(t² + 4) has two simple pairs: 4 choices of π (2² with p = 1)
    let d = &p(&[1, 0, 1]) * &p(&[4, 0, 1]);
    let split = GaussianSplit::new(&d).expect("split");
    assert_eq!(split.pairs.len(), 2);
    assert_eq!(split.num_choices(), 4);
    for choice in 0..4 {
        let s = split.decompose(choice).expect("sos");
        assert!(matches!(s, SumOfSquares::Rational { .. }) && s.verifies(&d));
    }
    // Satz 2 (2.37) as printed overestimates for polynomial data (docs/math/lines-and-canal.md, Errata G9):
    // m = (t, t²/2, 0), r = t, D = t²: n = 2·max(1, 2) = 4, bound (6, 2); construction (4, 2)
    let spine = CanalSpine::polynomial(
        [p(&[0, 1]), pr(&[(0, 1), (0, 1), (1, 2)]), p(&[])],
        p(&[0, 1]),
    );
    assert_eq!(spine.discriminant().expect("D"), p(&[0, 0, 1]));
    let bound = krasauskas_bound(&spine).expect("bound");
    assert_eq!((bound.n, bound.bidegree), (4, (6, 2)));
    let b = canal_surface(&spine, &CanalOptions::default()).expect("build");
    assert_eq!(b.degree(), (4, 2));
    assert!(b.all_hold());
}

#[test]
fn s003_sum_of_two_squares_cases() {
    // exact over Q iff D splits over Q(i) with a sum-of-two-squares constant
    let d = p(&[4, 0, 4]); // 4 + 4t² (docs/math/lines-and-canal.md, "Canal surfaces")
    assert!(matches!(
        sum_of_two_squares(&d).expect("s"),
        SumOfSquares::Rational { .. }
    ));
    // D = 1 + (15/4)t² (example 2.3) needs Q(√15)
    let d = pr(&[(1, 1), (0, 1), (15, 4)]);
    assert_eq!(sum_of_two_squares(&d).expect("s").radicand(), Some(&q(15)));
}

// ------------------------------------------------------------------------------------
// Peternell: Möbius geometry and canal surfaces (ch. 2), cyclides (§3.8.1), §4.5
// ------------------------------------------------------------------------------------

#[test]
fn s004_2_13_mobius_spheres() {
    // inverse stereographic points lie on Q; (2.13) centre and radius
    let y = [q(1), q(-2), r(1, 2)];
    let yy = y.iter().fold(q(0), |s, c| s + c.clone() * c.clone());
    let x = [
        yy.clone() + q(1),
        q(2) * y[0].clone(),
        q(2) * y[1].clone(),
        q(2) * y[2].clone(),
        yy - q(1),
    ];
    assert_eq!(mobius_form(&x), q(0));
    assert_eq!(mobius_image(&x).expect("pt"), MobiusImage::Point(y.clone()));
    let pp = [q(3), q(1), q(2), q(-1), q(1)];
    match mobius_image(&pp).expect("sphere") {
        MobiusImage::Sphere { center, radius_sq } => {
            assert_eq!(center, [r(1, 2), q(1), r(-1, 2)]);
            assert_eq!(radius_sq, r(1 + 4 + 1 + 1 - 9, 4));
        }
        other => panic!("{other:?}"),
    }
    // the polar hyperplane of p cuts Q in the sphere μ(p): B(p, x) = 0 ⇔ x on the sphere
    let sph = mobius_point(&[q(1), q(0), q(2)], &q(9));
    let on = mobius_point(&[q(4), q(0), q(2)], &q(0)); // a point at distance 3
    let off = mobius_point(&[q(5), q(0), q(2)], &q(0));
    assert_eq!(mobius_bilinear(&sph, &on), q(0));
    assert_ne!(mobius_bilinear(&sph, &off), q(0));
    // planes: p₀ = p₄
    assert_eq!(
        mobius_image(&[q(2), q(1), q(0), q(0), q(2)]).expect("plane"),
        MobiusImage::Plane([q(-2), q(1), q(0), q(0)])
    );
    // an automorphic collineation (inversion) maps Q to Q
    let z = mobius_point(&[q(0), q(0), q(0)], &q(4));
    let img = mobius_reflection(&z, &on).expect("inv");
    assert_eq!(mobius_form(&img), q(0));
}

#[test]
fn s004_2_4_pencils_and_reality_of_canal_families() {
    // Thm 2.3: a curve c(t) of P⁴ envelops a real canal surface where its tangent lines miss Q;
    // with c(t) = μ⁻¹(m(t), r(t)²) this is D = |ṁ|² − ṙ² > 0 (elliptic pencil)
    let spine = CanalSpine::polynomial([p(&[0, 1]), p(&[]), p(&[])], p(&[0, 0, 1]));
    // D = 1 − 4t²: real for |t| < 1/2
    for (t, real) in [
        (r(1, 4), true),
        (q(1), false),
        (r(-1, 3), true),
        (q(-2), false),
    ] {
        let (m, rad) = spine.eval(&t).expect("sph");
        let c0 = mobius_point(&m, &(rad.clone() * rad.clone()));
        // the exact tangent: ċ = (m·ṁ − rṙ, ṁ, m·ṁ − rṙ) with m = (t, 0, 0), r = t²
        let k = t.clone() - q(2) * t.clone().pow(3);
        let c1 = [k.clone(), q(1), q(0), q(0), k];
        let ty = pencil_type(&c0, &c1);
        assert_eq!(ty == PencilType::Elliptic, real, "t = {t}");
    }
    assert!(matches!(
        spine.check_real_envelope(None),
        Err(CanalError::NoRealEnvelope { .. })
    ));
    assert!(spine
        .check_real_envelope(Some((&r(-1, 2), &r(1, 2))))
        .is_ok());
}

#[test]
fn s004_a3_4_dupin_cyclide_family() {
    // Peternell §3.8.1 (docs/math/lines-and-canal.md, "Canal surfaces"): C(θ) = C₀ + ρ(cos θ U + sin θ V), U = (1,0,0,0), V = (0, 5/4, 0, 3/4):
    // spine (ρ cos θ, 5ρ/4 sin θ, 0), r = r₀ + 3ρ/4 sin θ, |ṁ|² − ṙ² = ρ²·θ̇²
    let (rho, r0) = (q(2), q(3));
    let w = p(&[1, 0, 1]); // cos θ = (1 − t²)/(1 + t²), sin θ = 2t/(1 + t²)
    let cos = p(&[1, 0, -1]);
    let sin = p(&[0, 2]);
    let spine = CanalSpine::new(
        w.clone(),
        [
            cos.scale(&rho),
            sin.scale(&(r(5, 4) * rho.clone())),
            Poly::zero(),
        ],
        &w.scale(&r0) + &sin.scale(&(r(3, 4) * rho.clone())),
    )
    .expect("cyclide family");
    let d = spine.discriminant().expect("D");
    let s = sum_of_two_squares(&d).expect("sos");
    assert!(matches!(s, SumOfSquares::Rational { .. }));
    let b = canal_surface(&spine, &CanalOptions::default()).expect("cyclide");
    assert!(b.as_rational().is_some());
    assert!(b.all_hold(), "{:?}", b.certify());
    // the Dupin quartic (Peternell §3.8.1; docs/math/cyclides.md, "Implicit"), (X² + Y² + Z² − μ² + b²)² = 4(aX − cμ)² + 4b²Y², with the axes
    // relabelled (X = y, Y = x; semi-axes a = 5ρ/4, b = ρ, c = −3ρ/4, μ = r₀):
    // (|x|² − 5)² − 4((5/2)y + 9/2)² − 16x² ≡ 0 as a polynomial identity in (t, u)
    let x = b.as_rational().expect("rational").homogeneous();
    let x00 = x[0].mul(&x[0]);
    let sum = x[1]
        .mul(&x[1])
        .add(&x[2].mul(&x[2]))
        .add(&x[3].mul(&x[3]))
        .sub(&x00.scale(&q(5)));
    let l = x[2].mul(&x[0]).scale(&r(5, 2)).add(&x00.scale(&r(9, 2)));
    let quartic = sum
        .mul(&sum)
        .sub(&l.mul(&l).scale(&q(4)))
        .sub(&x[1].mul(&x[1]).mul(&x00).scale(&q(16)));
    assert!(
        quartic.is_zero(),
        "the Dupin cyclide quartic of Peternell §3.8.1"
    );
    // with the sign of c flipped (the other relabelling) it fails: the check is not vacuous
    let l2 = x[2].mul(&x[0]).scale(&r(5, 2)).sub(&x00.scale(&r(9, 2)));
    let wrong = sum
        .mul(&sum)
        .sub(&l2.mul(&l2).scale(&q(4)))
        .sub(&x[1].mul(&x[1]).mul(&x00).scale(&q(16)));
    assert!(!wrong.is_zero());
}

#[test]
fn s004_4_5_canal_with_cubic_spine_and_radius() {
    // Fig. 4.3: a canal surface with cubic spine and cubic radius; the construction is
    // rational when D splits suitably over Q(i). m = (3t, 3t², 2t³) is PH (|ṁ| = 3 + 6t²);
    // with r = t:
    let spine = CanalSpine::polynomial([p(&[0, 3]), p(&[0, 0, 3]), p(&[0, 0, 0, 2])], p(&[0, 1]));
    // D = (3 + 6t²)² − 1 = 4(3t² + 1)(3t² + 2): the two quadratic factors need Q(√3) and
    // Q(√6) — no single quadratic field: an error, and the explicit f64 path instead
    assert!(matches!(
        canal_surface(&spine, &CanalOptions::default()),
        Err(CanalError::NeedsLargerExtension(_))
    ));
    let sf = rcagd::canal::canal_surface_approx(&spine, &CanalOptions::default()).expect("f64");
    assert!(sf.all_hold(), "{:?}", sf.certify());
    // a PH cubic with constant radius: always rational (pipe), degree ≤ 3k − 2 = 7
    let pipe = CanalSpine::polynomial([p(&[0, 3]), p(&[0, 0, 3]), p(&[0, 0, 0, 2])], p(&[1]));
    let b = canal_surface(&pipe, &CanalOptions::default()).expect("pipe");
    assert!(b.as_rational().is_some());
    assert!(b.degree().0 <= 7);
    assert!(b.all_hold());
}

#[test]
fn s004_thm_2_3_canal_from_a_mobius_curve() {
    // c(t) = μ⁻¹(m(t), r(t)²) for m = (t, t², 0), r = t/2 + 1: the family of the Möbius
    // model gives back the spine and radius, and its envelope is certified
    let m = [p(&[0, 1]), p(&[0, 0, 1]), p(&[])];
    let rr = pr(&[(1, 1), (1, 2)]);
    let mm = &(&(&m[0] * &m[0]) + &(&m[1] * &m[1])) + &(&m[2] * &m[2]);
    let k = &mm - &(&rr * &rr);
    let half = r(1, 2);
    let c = [
        (&k + &p(&[1])).scale(&half),
        m[0].clone(),
        m[1].clone(),
        m[2].clone(),
        (&k - &p(&[1])).scale(&half),
    ];
    let spine = CanalSpine::from_mobius_curve(&c).expect("rational radius");
    let (centre, radius) = spine.eval(&r(3, 2)).expect("sphere");
    assert_eq!(centre, [r(3, 2), r(9, 4), q(0)]);
    assert_eq!(radius.clone() * radius, r(49, 16));
    let b = canal_surface(&spine, &CanalOptions::default()).expect("canal");
    assert!(b.all_hold(), "{:?}", b.certify());
    // only r² rational: refused with a reason
    let c2 = [p(&[2, 0, 1]), p(&[0, 1]), p(&[]), p(&[]), p(&[0, 0, 1])];
    assert!(matches!(
        CanalSpine::from_mobius_curve(&c2),
        Err(CanalError::InvalidArgument(_))
    ));
}

/// Gruber §2.4.2 (2.36)/(2.37): Krasauskas' reduced pencil against Peternell–Pottmann and
/// the bound of Satz 2, on rational circle spines (ring torus, Dupin cyclide) and a rational
/// quadratic family whose `D` splits over `Q(i)` into two irreducible quadratics.
#[test]
fn s003_2_4_krasauskas_reduction() {
    use rcagd::canal::{Construction, Method};
    let w = p(&[1, 0, 1]);
    let cases: Vec<(&str, CanalSpine<Rational>)> = vec![
        (
            "torus",
            CanalSpine::new(
                w.clone(),
                [p(&[1, 0, -1]), p(&[0, 2]), p(&[])],
                w.scale(&r(1, 2)),
            )
            .expect("spine"),
        ),
        (
            "dupin",
            CanalSpine::new(
                w.clone(),
                [p(&[5, 0, -5]), p(&[0, 8]), p(&[])],
                &w.scale(&q(2)) - &p(&[3, 0, -3]),
            )
            .expect("spine"),
        ),
        (
            // a polynomial quintic family tangent to the plane z = −1 (r = m₃ + 1, so
            // D = ṁ₁² + ṁ₂²): the pencil goes below the construction's (3k − 2, 2) and the
            // bound (2.37) (docs/math/lines-and-canal.md, Errata G9)
            "plane-tangent quintic",
            CanalSpine::polynomial(
                [p(&[0, 1, 0, 1]), p(&[0, 0, 2, 0, 0, 1]), p(&[0, 1, 1])],
                p(&[1, 1, 1]),
            ),
        ),
        (
            "quadratic",
            CanalSpine::new(
                w.clone(),
                [p(&[3, 1, 3]), p(&[-1, 1, -1]), p(&[2, 0, -1])],
                p(&[-1, -1, 1]),
            )
            .expect("spine"),
        ),
    ];
    // (Peternell–Pottmann, Krasauskas, lowest, bound (2.37)). The bound of Satz 2 is over C:
    // for "quadratic" D = (t² − (4 + 2i)t − 1)(t² − (4 − 2i)t − 1) its factors are
    // irreducible over Q(i), the reduction over Q(i) stops at pencil degree 2.
    let expected = [
        ((4, 2), (2, 2), (2, 2), (4, 2)),
        ((4, 2), (2, 2), (2, 2), (4, 2)),
        ((13, 2), (9, 2), (9, 2), (13, 2)),
        ((6, 2), (6, 2), (6, 2), (4, 2)),
    ];
    for ((name, spine), want) in cases.into_iter().zip(expected) {
        let bound = krasauskas_bound(&spine).expect("bound");
        let mut degs = Vec::new();
        for method in [
            Method::PeternellPottmann,
            Method::Krasauskas,
            Method::Lowest,
        ] {
            let options = CanalOptions {
                method,
                ..CanalOptions::default()
            };
            let b = match canal_surface(&spine, &options) {
                Ok(b) => b,
                Err(e) => panic!("{name} {method:?}: {e}"),
            };
            assert!(b.all_hold(), "{name} {method:?}: {:?}", b.certify());
            let s = b.as_rational().expect("rational");
            degs.push(b.degree());
            if method == Method::Krasauskas {
                let Construction::Krasauskas {
                    initial_degree,
                    reduced_degree,
                    ..
                } = s.construction()
                else {
                    panic!("{name}: not a Krasauskas build");
                };
                // the first pencil has the degree of P (module docs)
                let dp = spine
                    .derivative_numerators()
                    .expect("P")
                    .iter()
                    .filter_map(Poly::degree)
                    .max()
                    .unwrap_or(0);
                assert_eq!(initial_degree, dp, "{name}");
                assert!(reduced_degree <= initial_degree, "{name}");
                // (k + 2·deg(a, b), 2) before common factors in t cancel
                assert!(
                    b.degree().0 <= 2 * reduced_degree + spine.degree(),
                    "{name}"
                );
            }
        }
        assert_eq!((degs[0], degs[1], degs[2], bound.bidegree), want, "{name}");
    }
}
