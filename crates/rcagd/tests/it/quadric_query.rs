//! Queries of the quadric module (Jüttler, *Zur Konstruktion rationaler Kurven und
//! Flächen auf Quadriken*): fibres and stereographic inverses at a point, preimage
//! quadrics of plane sections, images under collineations, Miquel points of biquadratic
//! patches, ψ interpolation of any degree. Expected values are computed by hand in the
//! comments; property tests use random exact inputs and compare `f64` with the exact
//! result.

use proptest::prelude::*;
use rcagd::quadric::paraboloid::psi;
use rcagd::quadric::query::*;
use rcagd::quadric::sphere_patch::BiquadraticPatch;
use rcagd::quadric::stereographic::{delta, sphere_matrix};
use rcagd::quadric::{curve_image, Delta, Hom, Psi, QuadricError, QuadricKind};
use rcagd::Certified;
use rcagd_algebra::{Certificate, Rational, Scalar};
use rcagd_geom::BezierCurve;

type Q = Rational;

fn r(n: i64) -> Q {
    Q::from(n)
}
fn q(n: i64, d: i64) -> Q {
    Q::from_ratio(n, d)
}
fn h(v: [i64; 4]) -> Hom<Q> {
    v.map(r)
}
fn parallel(a: &[Q], b: &[Q]) -> bool {
    (0..a.len()).all(|i| {
        (i + 1..a.len()).all(|j| a[i].clone() * b[j].clone() == a[j].clone() * b[i].clone())
    })
}
fn assert_all(certs: &[Certificate]) {
    assert!(!certs.is_empty());
    for c in certs {
        assert!(c.holds, "{c}");
    }
}

#[test]
fn delta_fibre_through_a_point_and_sigma_inverse() {
    // p = (1, 2, −1, 3): δ(p) = (15, 10, 10, −5) (Jüttler (9)); σ⁻¹(k) = (20, 10, 10, 0);
    // by hand the fibre span{p, Jp}, Jp = (−3, −1, −2, 1), meets p3 = 0 in p − 3Jp/(−1)…
    // = (10, 5, 5, 0) ∥ (2, 1, 1, 0).
    let p = h([1, 2, -1, 3]);
    let f = fibre_through(&Delta, &p)
        .unwrap()
        .with_plane_inverse(PlaneInverse::Sigma);
    assert_eq!(f.point, h([15, 10, 10, -5]));
    let (_, x) = f.plane_point.clone().unwrap();
    assert!(parallel(&x, &h([2, 1, 1, 0])));
    assert!(parallel(&f.point, &delta(&x)));
    assert_all(&f.certify());
    // the centre z = (1, 0, 0, 1) has no σ⁻¹; its fibre is the line at infinity x0 = x3 = 0
    let z = fibre_query(&Delta, &h([1, 0, 0, 1]))
        .unwrap()
        .with_plane_inverse(PlaneInverse::Sigma);
    assert!(z.plane_point.is_none());
    assert!(z.fibre.iter().all(|a| a[0] == r(0) && a[3] == r(0)));
    assert_all(&z.certify());
}

#[test]
fn psi_fibre_and_tau_inverse() {
    // q = (1, 2, 3, 4): ψ(q) = (4, 8, 3, 6) on H (4·6 = 8·3); τ⁻¹ = (4, 8, 3, 4) =
    // 4·(1, 2, 0, 0) + (0, 0, 3, 4) lies on the fibre span{(1,2,0,0), (0,0,3,4)} (Segre
    // factors u = (1, 2), v = (4, 3)).
    let f = fibre_through(&Psi, &h([1, 2, 3, 4]))
        .unwrap()
        .with_plane_inverse(PlaneInverse::Tau);
    assert_eq!(f.point, h([4, 8, 3, 6]));
    assert_eq!(f.plane_point.clone().unwrap().1, h([4, 8, 3, 4]));
    assert!(parallel(&f.fibre[0], &h([1, 2, 0, 0])));
    assert!(parallel(&f.fibre[1], &h([0, 0, 3, 4])));
    assert_all(&f.certify());
}

#[test]
fn fibre_errors_are_named() {
    assert!(matches!(
        fibre_query(&Delta, &h([1, 1, 1, 0])),
        Err(QuadricError::NotOnQuadric { .. })
    ));
    // ψ vanishes on the focal line q2 = q3 = 0
    assert!(matches!(
        fibre_through(&Psi, &h([1, 1, 0, 0])),
        Err(QuadricError::Exceptional { .. })
    ));
    assert!(matches!(
        fibre_through(&Delta, &h([0, 0, 0, 0])),
        Err(QuadricError::ZeroPoint(_))
    ));
}

#[test]
fn preimage_quadrics_of_circles() {
    // the equator z = 0, π = (0, 0, 0, 1): πᵀδ(p) = p1² + p2² − p0² − p3², a one-sheet
    // hyperboloid (Jüttler §2: a real circle not through z)
    let eq = preimage_quadric(&Delta, &h([0, 0, 0, 1])).unwrap();
    assert_eq!(
        eq.matrix,
        [[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]].map(|row| row.map(r))
    );
    assert_eq!(eq.kind, QuadricKind::HyperboloidOneSheet);
    assert_all(&eq.certify());
    // π: x + y + z = w, π = (−1, 1, 1, 1), passes through the centre z = (1, 0, 0, 1): the
    // circle is σ of a line of P, its preimage a hyperbolic paraboloid. By hand
    // πᵀδ(p) = −2p0² − 2p3² + 2p0p1 + 2p0p2 + 2p1p3 − 2p2p3.
    let pi = h([-1, 1, 1, 1]);
    let pq = preimage_quadric(&Delta, &pi).unwrap();
    let want = [[-2, 1, 1, 0], [1, 0, 0, 1], [1, 0, 0, -1], [0, 1, -1, -2]].map(|row| row.map(r));
    assert_eq!(pq.matrix, want);
    assert_eq!(pq.kind, QuadricKind::HyperbolicParaboloid);
    assert_all(&pq.certify());
    // through three points of the circle, with the conic
    let pts = [h([1, 1, 0, 0]), h([1, 0, 1, 0]), h([1, 0, 0, 1])];
    let pq = preimage_quadric_through(&Delta, &pts).unwrap();
    assert!(parallel(&pq.plane, &pi));
    assert_eq!(pq.section.as_ref().unwrap().curve().degree(), 2);
    assert_all(&pq.certify());
    assert!(matches!(
        preimage_quadric_through(&Delta, &[h([1, 1, 0, 0]), h([1, 1, 0, 0]), h([1, 0, 0, 1])]),
        Err(QuadricError::Degenerate(_))
    ));
}

#[test]
fn preimage_quadric_of_a_conic_on_h_is_a_hyperbolic_paraboloid() {
    // πᵀψ(q) = (q0, q1)·Π·(q3, q2)ᵀ; on q0 = 0 it is q1·(π1 q3 + π3 q2): the plane at
    // infinity touches, so every non-degenerate preimage is a hyperbolic paraboloid
    // (docs/math/quadrics.md, Errata J2).
    for pi in [h([1, 2, 3, 5]), h([1, 0, 0, -1]), h([2, -1, 3, 1])] {
        let pq = preimage_quadric(&Psi, &pi).unwrap();
        assert_eq!(pq.kind, QuadricKind::HyperbolicParaboloid, "{pi:?}");
        assert_all(&pq.certify());
    }
}

fn sphere_conic() -> BezierCurve<Q> {
    // δ of the line from (1, 0, 0, 0) to (1, 1, 1, 0): a circle arc on the unit sphere
    let line = BezierCurve::from_homogeneous(vec![
        vec![r(1), r(0), r(0), r(0)],
        vec![r(1), r(1), r(1), r(0)],
    ])
    .unwrap();
    curve_image(&Delta, &line).unwrap().into_image()
}

#[test]
fn collineation_maps_the_sphere_to_an_ellipsoid() {
    // A = diag(1, 2, 3, 4): (x, y, z) ↦ (2x, 3y, 4z); the sphere goes to
    // x²/4 + y²/9 + z²/16 = 1, Q' = diag(1, −1/4, −1/9, −1/16).
    let a = [[1, 0, 0, 0], [0, 2, 0, 0], [0, 0, 3, 0], [0, 0, 0, 4]].map(|row| row.map(r));
    let c = sphere_conic();
    let img = collineation_curve(&a, &c, Some(&sphere_matrix())).unwrap();
    let want = [
        [r(1), r(0), r(0), r(0)],
        [r(0), q(-1, 4), r(0), r(0)],
        [r(0), r(0), q(-1, 9), r(0)],
        [r(0), r(0), r(0), q(-1, 16)],
    ];
    assert_eq!(img.quadrics.as_ref().unwrap().1, want);
    assert_eq!(img.det, r(24));
    assert_all(&img.certify());
    let cover = rcagd::quadric::sphere_cover([r(0), r(0), r(0)], [r(1), r(1), r(1)]).unwrap();
    let patch = cover.patches()[0].clone();
    let pimg = collineation_patch(&a, &patch, Some(&sphere_matrix())).unwrap();
    assert_all(&pimg.certify());
}

#[test]
fn collineation_errors_are_named() {
    let sing = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0]].map(|row| row.map(r));
    assert!(matches!(
        collineation_curve(&sing, &sphere_conic(), None),
        Err(QuadricError::Degenerate(_))
    ));
    let id = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]].map(|row| row.map(r));
    let off = BezierCurve::from_homogeneous(vec![
        vec![r(1), r(0), r(0), r(0)],
        vec![r(1), r(1), r(1), r(0)],
    ])
    .unwrap();
    assert!(matches!(
        collineation_curve(&id, &off, Some(&sphere_matrix())),
        Err(QuadricError::NotOnQuadric { .. })
    ));
}

/// The δ-image of the bilinear patch with corners (1,0,0,0), (1,1,0,0), (2,1,1,1),
/// (1,0,1,0) (Satz 7): a biquadratic patch on the sphere.
fn delta_bilinear_patch() -> BiquadraticPatch<Q> {
    BiquadraticPatch::from_bilinear(
        &Delta,
        h([1, 0, 0, 0]),
        h([1, 1, 0, 0]),
        h([2, 1, 1, 1]),
        h([1, 0, 1, 0]),
    )
    .unwrap()
}

#[test]
fn miquel_points_of_a_delta_patch_agree_with_the_construction() {
    // the δ-image of a bilinear patch (Satz 7): the q's computed from the net alone equal
    // those of the construction (images of the projecting lines in the corner planes)
    let bp = delta_bilinear_patch();
    let m = miquel_points(&sphere_matrix(), bp.patch()).unwrap();
    for i in 0..4 {
        assert!(parallel(&m.second[i], &bp.second_points()[i]), "q{}", i + 1);
        assert!(parallel(&m.corners[i], &bp.corners()[i]));
    }
    assert!(m.is_miquel());
    assert!(m.miquel_planes.iter().all(Option::is_some));
    assert_all(&m.certify());
}

#[test]
fn miquel_points_errors_are_named() {
    let bp = delta_bilinear_patch();
    // the same patch is not on the hyperbolic paraboloid
    assert!(matches!(
        miquel_points(&rcagd::quadric::paraboloid::paraboloid_matrix(), bp.patch()),
        Err(QuadricError::NotOnQuadric { .. })
    ));
    let bilinear = rcagd_geom::BezierPatch::from_homogeneous(vec![
        vec![vec![r(1), r(0), r(0), r(0)], vec![r(1), r(0), r(1), r(0)]],
        vec![vec![r(1), r(1), r(0), r(0)], vec![r(1), r(1), r(1), r(0)]],
    ])
    .unwrap();
    assert!(matches!(
        miquel_points(&sphere_matrix(), &bilinear),
        Err(QuadricError::Dimension(_))
    ));
}

#[test]
fn psi_interpolation_of_any_degree() {
    // three points of H: lowest degree 2 (a conic: u, v of degree 1); degree 4 with u, v of
    // degree 2: each solution space has dimension 2·3 − 3 = 3, so 2 + 2 = 4 free parameters.
    let pts: Vec<Hom<Q>> = [[1, 0, 0, 1], [1, 1, 2, 3], [2, 1, -1, 5]]
        .iter()
        .map(|p| psi(&h(*p)))
        .collect();
    let params = [r(0), q(1, 2), r(1)];
    let low = psi_interpolate(&pts, &params, 2, None).unwrap();
    assert_eq!(low.lowest, (1, 1));
    assert_eq!(low.curve.degree(), 2);
    assert_all(&low.certify());
    let quartic = psi_interpolate(&pts, &params, 4, None).unwrap();
    assert_eq!(quartic.degrees(), (2, 2));
    assert_eq!((quartic.u_dimension, quartic.v_dimension), (3, 3));
    assert_eq!(quartic.free_parameters(), 4);
    assert_eq!(quartic.curve.degree(), 4);
    assert_all(&quartic.certify());
    // odd degree, u of degree 3
    let quartic_u3 = psi_interpolate(&pts, &params, 4, Some(3)).unwrap();
    assert_eq!(quartic_u3.degrees(), (3, 1));
    assert_all(&quartic_u3.certify());
    let cubic = psi_interpolate(&pts, &params, 3, None).unwrap();
    assert_eq!(cubic.curve.degree(), 3);
    assert_all(&cubic.certify());
    assert!(matches!(
        psi_interpolate(&pts, &params, 1, None),
        Err(QuadricError::NoInterpolant { .. })
    ));
    assert!(matches!(
        psi_interpolate(&pts, &params, 4, Some(4)),
        Err(QuadricError::NoInterpolant { .. })
    ));
}

fn small() -> impl Strategy<Value = i64> {
    -5i64..=5
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Random points of P³: the fibre through p is certified, contains p, and f64 agrees.
    #[test]
    fn random_fibres(p in proptest::array::uniform4(small())) {
        prop_assume!(p.iter().any(|x| *x != 0));
        let ph = h(p);
        let f = fibre_through(&Delta, &ph).unwrap().with_plane_inverse(PlaneInverse::Sigma);
        for c in f.certify() { prop_assert!(c.holds, "{}", c); }
        let pf = p.map(|x| x as f64);
        let ff = fibre_through(&Delta, &pf).unwrap();
        for c in ff.certify() { prop_assert!(c.holds, "{}", c); }
        for i in 0..4 {
            prop_assert!((ff.point[i] - Scalar::to_f64(&f.point[i])).abs() < 1e-9);
        }
        if ph[0].clone() * ph[3].clone() != r(0) || ph[1].clone() * ph[2].clone() != r(0) {
            if let Ok(g) = fibre_through(&Psi, &ph) {
                for c in g.with_plane_inverse(PlaneInverse::Tau).certify() { prop_assert!(c.holds, "{}", c); }
            }
        }
    }

    /// Random planes: the preimage of the section is certified for δ and ψ.
    #[test]
    fn random_preimage_quadrics(pi in proptest::array::uniform4(small())) {
        prop_assume!(pi.iter().any(|x| *x != 0));
        let pq = preimage_quadric(&Delta, &h(pi)).unwrap();
        for c in pq.certify() { prop_assert!(c.holds, "{}", c); }
        let pq = preimage_quadric(&Psi, &h(pi)).unwrap();
        for c in pq.certify() { prop_assert!(c.holds, "{}", c); }
    }

    /// Random bilinear patches: their δ-images are Miquel (Satz 7).
    #[test]
    fn random_miquel(c in proptest::array::uniform4(proptest::array::uniform4(small()))) {
        let bp = BiquadraticPatch::from_bilinear(&Delta, h(c[0]), h(c[1]), h(c[2]), h(c[3]));
        prop_assume!(bp.is_ok());
        let bp = bp.unwrap();
        if let Ok(m) = miquel_points(&sphere_matrix(), bp.patch()) {
            prop_assert!(m.is_miquel());
            for c in m.certify() { prop_assert!(c.holds, "{}", c); }
        }
    }
}

#[test]
fn psi_interpolation_skips_splits_without_coprime_factors() {
    // u-factors (1, 0), (1, 1), (1, 2), (1, 3) at t = 0, 1/3, 2/3, 1 lie on u = (1, 3t)
    // (degree 1); with 4 points the u-solutions of degree 2 form a 2-dimensional space,
    // (a + bt)·(1, 3t), all with a common factor: degree 4 must take r = 1, s = 3.
    let pts: Vec<Hom<Q>> = [[1, 0, 0, 0], [1, 1, 2, 2], [1, 2, 1, 2], [1, 3, 3, 9]]
        .iter()
        .map(|p| h(*p))
        .collect();
    let params = [r(0), q(1, 3), q(2, 3), r(1)];
    let expected = [(3, (1, 2)), (4, (1, 3)), (5, (3, 2)), (6, (3, 3))];
    for (d, degs) in expected {
        let it = psi_interpolate(&pts, &params, d, None).unwrap();
        assert_eq!(it.lowest, (1, 2));
        assert_eq!(it.degrees(), degs, "degree {d}");
        assert_all(&it.certify());
    }
    assert!(matches!(
        psi_interpolate(&pts, &params, 4, Some(2)),
        Err(QuadricError::NoInterpolant { .. })
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    /// Random regular diagonal-plus-shear collineations of a sphere arc: certified, the
    /// image quadric transfers back, and the f64 image agrees with the exact one.
    #[test]
    fn random_collineations(d in proptest::array::uniform4(1i64..=4), sh in proptest::array::uniform3(small())) {
        let a = [
            [r(d[0]), r(0), r(0), r(0)],
            [r(sh[0]), r(d[1]), r(0), r(0)],
            [r(sh[1]), r(sh[2]), r(d[2]), r(0)],
            [r(0), r(0), r(0), r(d[3])],
        ];
        let c = sphere_conic();
        let img = collineation_curve(&a, &c, Some(&sphere_matrix())).unwrap();
        for x in img.certify() { prop_assert!(x.holds, "{}", x); }
        let af = a.clone().map(|row| row.map(|x| Scalar::to_f64(&x)));
        let cf = c.to_f64();
        let imf = collineation_curve(&af, &cf, Some(&sphere_matrix::<f64>())).unwrap();
        for x in imf.certify() { prop_assert!(x.holds, "{}", x); }
        for (e, f) in img.image.coords().iter().zip(imf.image.coords()) {
            prop_assert!((Scalar::to_f64(e) - f).abs() < 1e-9 * (1.0 + f.abs()));
        }
    }

    /// Random points of H (images of random q): ψ interpolation of degree lowest + 2 is
    /// certified.
    #[test]
    fn random_psi_interpolation(qs in proptest::array::uniform3(proptest::array::uniform4(1i64..=6))) {
        let pts: Vec<Hom<Q>> = qs.iter().map(|p| psi(&h(*p))).collect();
        prop_assume!((0..3).all(|i| (i + 1..3).all(|j| !parallel(&pts[i], &pts[j]))));
        let params = [r(0), q(1, 2), r(1)];
        let low = psi_interpolate(&pts, &params, 0, None).err();
        let refused = matches!(low, Some(QuadricError::NoInterpolant { .. }));
        prop_assert!(refused);
        let it = psi_interpolate(&pts, &params, 4, None).unwrap();
        for x in it.certify() { prop_assert!(x.holds, "{}", x); }
        prop_assert_eq!(it.curve.degree(), 4);
    }
}
