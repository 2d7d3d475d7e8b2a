//! Property tests for the quadric module: random exact inputs for every map and
//! construction; certificates hold exactly; f64 agrees with the exact results; invalid
//! inputs give typed errors, never panics.

use proptest::prelude::*;
use rcagd::quadric::general::AnyProjection;
use rcagd::quadric::image::{
    curve_image, curve_preimage, patch_image, patch_preimage, reduce_curve,
};
use rcagd::quadric::interpolation::{
    interpolate, interpolate_hermite, interpolate_lowest_degree, sample_points, HermiteDatum,
};
use rcagd::quadric::paraboloid::{psi, psi_polar};
use rcagd::quadric::rational_points::find_rational_point;
use rcagd::quadric::sphere_patch::BiquadraticPatch;
use rcagd::quadric::stereographic::{delta, delta_polar, fibre_rotation};
use rcagd::quadric::{Delta, GeneralizedProjection, Hom, Mat4, Psi, Quadric, QuadricError};
use rcagd::Certified;
use rcagd_algebra::{Rational, Scalar};
use rcagd_geom::polymap::PolyMap;
use rcagd_geom::{BezierCurve, BezierPatch};

fn q(n: i64, d: i64) -> Rational {
    Rational::from(n) / Rational::from(d)
}
fn rat() -> impl Strategy<Value = Rational> {
    (-6i64..=6, 1i64..=4).prop_map(|(n, d)| q(n, d))
}
fn hom() -> impl Strategy<Value = Hom<Rational>> {
    [rat(), rat(), rat(), rat()].prop_filter("non-zero", |p| p.iter().any(|x| !x.is_zero()))
}
fn curve(max_deg: usize) -> impl Strategy<Value = BezierCurve<Rational>> {
    prop::collection::vec(hom(), 2..=max_deg + 1).prop_map(|pts| {
        BezierCurve::from_homogeneous(pts.into_iter().map(|p| p.to_vec()).collect()).unwrap()
    })
}
fn patch() -> impl Strategy<Value = BezierPatch<Rational>> {
    (1usize..=2, 1usize..=2).prop_flat_map(|(m, n)| {
        prop::collection::vec(prop::collection::vec(hom(), n + 1), m + 1).prop_map(|net| {
            BezierPatch::from_homogeneous(
                net.into_iter()
                    .map(|r| r.into_iter().map(|p| p.to_vec()).collect())
                    .collect(),
            )
            .unwrap()
        })
    })
}
fn add(a: &Hom<Rational>, b: &Hom<Rational>) -> Hom<Rational> {
    [0, 1, 2, 3].map(|i| a[i].clone() + b[i].clone())
}
fn sc(c: &Rational, a: &Hom<Rational>) -> Hom<Rational> {
    a.clone().map(|x| c.clone() * x)
}
fn quad<F: Scalar>(m: &Mat4<F>, x: &Hom<F>) -> F {
    let mut s = F::zero();
    for i in 0..4 {
        for j in 0..4 {
            s += m[i][j].clone() * x[i].clone() * x[j].clone();
        }
    }
    s
}
fn rank3(a: &Hom<Rational>, b: &Hom<Rational>, c: &Hom<Rational>) -> usize {
    let mut m = [a.to_vec(), b.to_vec(), c.to_vec()];
    let mut rk = 0;
    for col in 0..4 {
        let Some(p) = (rk..3).find(|&i| !m[i][col].is_zero()) else {
            continue;
        };
        m.swap(rk, p);
        for i in 0..3 {
            if i != rk && !m[i][col].is_zero() {
                let f = m[i][col].clone() / m[rk][col].clone();
                let pivot_row = m[rk].clone();
                for (x, v) in m[i].iter_mut().zip(pivot_row) {
                    *x -= f.clone() * v;
                }
            }
        }
        rk += 1;
    }
    rk
}
fn parallel(a: &Hom<Rational>, b: &Hom<Rational>) -> bool {
    (0..4).all(|i| {
        (0..4).all(|j| (a[i].clone() * b[j].clone() - a[j].clone() * b[i].clone()).is_zero())
    })
}
fn fl(x: &Rational) -> f64 {
    Scalar::to_f64(x)
}
fn to_f64(p: &Hom<Rational>) -> Hom<f64> {
    p.clone().map(|x| fl(&x))
}
fn close(a: &[f64], b: &[Rational]) -> bool {
    let m = b.iter().map(|x| fl(x).abs()).fold(1.0, f64::max);
    a.iter().zip(b).all(|(x, y)| (x - fl(y)).abs() <= 1e-9 * m)
}
fn curve_f64(c: &BezierCurve<Rational>) -> BezierCurve<f64> {
    BezierCurve::from_homogeneous(
        c.control_points()
            .map(|p| p.iter().map(fl).collect())
            .collect(),
    )
    .unwrap()
}
fn assert_certs(certs: &[rcagd_algebra::Certificate]) -> Result<(), TestCaseError> {
    for c in certs {
        prop_assert!(c.holds, "{}", c);
    }
    Ok(())
}
fn named_quadric(kind: usize, a: Rational, b: Rational, c: Rational) -> Quadric<Rational> {
    match kind {
        0 => Quadric::ellipsoid(a, b, c),
        1 => Quadric::hyperboloid_one_sheet(a, b, c),
        2 => Quadric::hyperboloid_two_sheets(a, b, c),
        3 => Quadric::elliptic_paraboloid(a, b),
        4 => Quadric::hyperbolic_paraboloid(a, b),
        5 => Quadric::cone(a, b, c),
        6 => Quadric::elliptic_cylinder(a, b),
        7 => Quadric::hyperbolic_cylinder(a, b),
        8 => Quadric::parabolic_cylinder(a),
        9 => Quadric::sphere([b, c, a.clone()], a),
        _ => Ok(Quadric::seed_paraboloid()),
    }
    .unwrap()
}
fn pos() -> impl Strategy<Value = Rational> {
    (1i64..=7, 1i64..=3).prop_map(|(n, d)| q(n, d))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// δ: on K, polar form, fibre rotation, fibres contain their preimages; f64 agrees.
    #[test]
    fn delta_map_properties(p in hom(), a in hom(), b in hom(), s in rat(), t in rat()) {
        let k = delta(&p);
        prop_assert!(quad(&rcagd::quadric::stereographic::sphere_matrix(), &k).is_zero());
        prop_assert!(k[0] > Rational::from(0));
        let plus = delta(&add(&a, &b));
        let minus = delta(&add(&a, &sc(&Rational::from(-1), &b)));
        let pol = delta_polar(&a, &b);
        for i in 0..4 {
            prop_assert_eq!(pol[i].clone(), (plus[i].clone() - minus[i].clone()) / Rational::from(4));
        }
        let x = add(&sc(&s, &p), &sc(&t, &fibre_rotation(&p)));
        let n2 = s.clone() * s.clone() + t.clone() * t.clone();
        prop_assert_eq!(delta(&x), sc(&n2, &k));
        let [fa, fb] = Delta.fibre(&k).unwrap();
        prop_assert_eq!(rank3(&fa, &fb, &p), 2, "p lies on the fibre over δ(p)");
        prop_assert!(close(&delta(&to_f64(&p)), &k));
    }

    /// ψ: on H, polar form, fibres; f64 agrees.
    #[test]
    fn psi_map_properties(p in hom(), a in hom(), b in hom()) {
        let h = psi(&p);
        prop_assert!(quad(&rcagd::quadric::paraboloid::paraboloid_matrix(), &h).is_zero());
        let plus = psi(&add(&a, &b));
        let minus = psi(&add(&a, &sc(&Rational::from(-1), &b)));
        let pol = psi_polar(&a, &b);
        for i in 0..4 {
            prop_assert_eq!(pol[i].clone(), (plus[i].clone() - minus[i].clone()) / Rational::from(4));
        }
        if h.iter().any(|x| !x.is_zero()) {
            let [fa, fb] = Psi.fibre(&h).unwrap();
            prop_assert_eq!(rank3(&fa, &fb, &p), 2);
            prop_assert!(parallel(&psi(&add(&fa, &fb)), &h));
        } else {
            prop_assert!((p[0].is_zero() && p[1].is_zero()) || (p[2].is_zero() && p[3].is_zero()), "ψ = 0 only on the focal lines");
        }
        prop_assert!(close(&psi(&to_f64(&p)), &h));
    }

    /// Curve images (n → 2n): certificates hold; the polar-form rule agrees with the geometry
    /// layer's exact polynomial-map image and quadric certificate; f64 agrees.
    #[test]
    fn curve_images(x in curve(3), use_psi in any::<bool>()) {
        let proj: &dyn GeneralizedProjection<Rational> = if use_psi { &Psi } else { &Delta };
        let Ok(img) = curve_image(proj, &x) else { return Ok(()) };
        prop_assert_eq!(img.image().degree(), 2 * x.degree());
        assert_certs(&img.certify())?;
        let forms: Vec<Vec<Vec<Rational>>> = proj.quadratic_map().matrices().iter().map(|m| m.iter().map(|r| r.to_vec()).collect()).collect();
        let pm = PolyMap::from_quadratic_forms("F", &forms).unwrap();
        let other = pm.apply_curve(&x).unwrap();
        prop_assert_eq!(other.coords(), img.image().coords());
        let qm: Vec<Vec<Rational>> = proj.quadric().iter().map(|r| r.to_vec()).collect();
        prop_assert!(rcagd_geom::certify::curve_on_quadric(img.image(), &qm).unwrap().holds);
        let fimg = if use_psi { curve_image(&Psi, &curve_f64(&x)) } else { curve_image(&Delta, &curve_f64(&x)) }.unwrap();
        prop_assert!(close(fimg.image().coords(), img.image().coords()));
        for c in fimg.certify() {
            prop_assert!(c.holds && !c.exact, "{}", c);
        }
    }

    /// Patch images ((m,n) → (2m,2n)): certificates, cross-check with the geometry layer.
    #[test]
    fn patch_images(x in patch()) {
        let Ok(img) = patch_image(&Delta, &x) else { return Ok(()) };
        let (m, n) = x.degree();
        prop_assert_eq!(img.image().degree(), (2 * m, 2 * n));
        assert_certs(&img.certify())?;
        let forms: Vec<Vec<Vec<Rational>>> = Delta.quadratic_map().matrices().iter().map(|m| m.iter().map(|r| r.to_vec()).collect()).collect();
        let other = PolyMap::from_quadratic_forms("δ", &forms).unwrap().apply_patch(&x).unwrap();
        prop_assert_eq!(other.coords(), img.image().coords());
    }

    /// Preimages of half degree: δ(x) and ψ(x) give back an x' with F(x') = c·F(x).
    #[test]
    fn curve_preimages(x in curve(2), use_psi in any::<bool>()) {
        let proj: &dyn GeneralizedProjection<Rational> = if use_psi { &Psi } else { &Delta };
        let Ok(img) = curve_image(proj, &x) else { return Ok(()) };
        match curve_preimage(proj, img.image()) {
            Ok(pre) => {
                prop_assert_eq!(pre.preimage.degree(), x.degree());
                assert_certs(&pre.certify())?;
            }
            // only reducible images (coordinates with a common factor) may lack a preimage
            // found by the linear problem (Satz 1 concerns irreducible curves)
            Err(QuadricError::NoPreimage(_)) => {
                let (g, _) = reduce_curve(img.image()).unwrap();
                prop_assert!(g.degree().unwrap_or(0) > 0);
            }
            Err(e) => prop_assert!(false, "{e}"),
        }
    }

    /// Patch preimages of bilinear images.
    #[test]
    fn patch_preimages(c in [hom(), hom(), hom(), hom()]) {
        let x = BezierPatch::from_homogeneous(vec![vec![c[0].to_vec(), c[1].to_vec()], vec![c[2].to_vec(), c[3].to_vec()]]).unwrap();
        let Ok(img) = patch_image(&Delta, &x) else { return Ok(()) };
        let pre = patch_preimage(&Delta, img.image()).unwrap();
        assert_certs(&pre.certify())?;
    }

    /// Interpolation of 2n+1 points of a random δ-curve of degree 2n at random distinct
    /// parameters: the interpolant passes through the points exactly, has degree 2n and is
    /// unique (solution space {(aI+bJ)x}, dimension 2 in general position).
    #[test]
    fn interpolation_of_points(x in curve(2), params in prop::collection::btree_set(-8i64..=8, 5)) {
        let n = x.degree();
        let params: Vec<Rational> = params.into_iter().take(2 * n + 1).map(|t| q(t, 4)).collect();
        let img = curve_image(&Delta, &x).unwrap();
        let pts = sample_points(img.image(), &params);
        match interpolate(&Delta, &pts, &params, n) {
            Ok(it) => {
                assert_certs(&it.certify())?;
                prop_assert!(it.dimension() >= 2 && it.dimension() % 2 == 0);
                if it.dimension() == 2 {
                    let same = rcagd_geom::certify::curves_agree(it.curve(), img.image()).unwrap();
                    prop_assert!(same.holds, "{}", same);
                }
                let low = interpolate_lowest_degree(&Delta, it.data()).unwrap();
                prop_assert!(low.preimage_degree() <= n);
                assert_certs(&low.certify())?;
            }
            Err(QuadricError::RepeatedPoints(..)) => {}
            Err(e) => prop_assert!(false, "{e}"),
        }
    }

    /// Hermite data from a random δ-quartic: points and tangents at t = 0 and t = 1 with
    /// the fibre positions of the generating curve are met by a quartic; with default
    /// fibre positions the lowest-degree interpolant exists and certifies.
    #[test]
    fn hermite_interpolation(x in curve(2).prop_filter("degree 2", |c| c.degree() == 2)) {
        let img = curve_image(&Delta, &x).unwrap();
        let y = img.image();
        let mut data = Vec::new();
        for t in [Rational::from(0), Rational::from(1)] {
            let k = sample_points(y, std::slice::from_ref(&t)).remove(0);
            let d = y.derivative_homogeneous(&t, 1);
            let tan: Hom<Rational> = [d[0].clone(), d[1].clone(), d[2].clone(), d[3].clone()];
            if parallel(&tan, &k) { return Ok(()); }
            let xt = sample_points(&x, std::slice::from_ref(&t)).remove(0);
            let [a, b] = Delta.fibre(&k).unwrap();
            // coordinates of x(t) in the basis [a, b] (a ⊥ b, |a| = |b| for δ)
            let dot = |u: &Hom<Rational>, v: &Hom<Rational>| (0..4).fold(Rational::from(0), |s, i| s + u[i].clone() * v[i].clone());
            let pos = [dot(&xt, &a), dot(&xt, &b)];
            data.push(HermiteDatum { t, point: k, tangent: Some(tan), fibre_position: pos });
        }
        let it = interpolate_hermite(&Delta, &data, 2).unwrap();
        assert_certs(&it.certify())?;
        for d in data.iter_mut() {
            d.fibre_position = [Rational::from(1), Rational::from(1)];
        }
        let low = interpolate_lowest_degree(&Delta, &data).unwrap();
        assert_certs(&low.certify())?;
    }

    /// Satz 7 on random bilinear patches, and the converse construction from the corners and
    /// the boundary circles (third points at the edge midpoints).
    #[test]
    fn miquel_patches(c in [hom(), hom(), hom(), hom()], w in pos()) {
        let Ok(bp) = BiquadraticPatch::from_bilinear(&Delta, c[0].clone(), c[1].clone(), c[2].clone(), c[3].clone()) else { return Ok(()) };
        assert_certs(&bp.certify())?;
        let y = bp.patch();
        let half = q(1, 2);
        let ev = |u: &Rational, v: &Rational| -> Hom<Rational> {
            let e = rcagd_geom::BezierPatch::eval_homogeneous(y, u, v);
            [e[0].clone(), e[1].clone(), e[2].clone(), e[3].clone()]
        };
        let (o, z) = (Rational::from(1), Rational::from(0));
        let edges = [ev(&half, &z), ev(&o, &half), ev(&half, &o), ev(&z, &half)];
        match BiquadraticPatch::from_corners(&Delta, bp.corners().clone(), edges, w) {
            Ok(back) => {
                assert_certs(&back.certify())?;
                for i in 0..4 {
                    prop_assert!(parallel(&back.corners()[i], &bp.corners()[i]));
                }
            }
            Err(QuadricError::Degenerate(_)) => {}
            Err(e) => prop_assert!(false, "{e}"),
        }
    }

    /// Every named quadric: the projection certifies, fibres contain their preimages, curve
    /// images lie on the quadric, interpolation works, and f64 agrees with exact.
    #[test]
    fn general_quadrics(kind in 0usize..11, a in pos(), b in pos(), c in pos(), p in hom(), x in curve(2)) {
        let quadric = named_quadric(kind, a.clone(), b.clone(), c.clone());
        let proj = quadric.projection().unwrap();
        assert_certs(&proj.certify())?;
        let k = proj.apply(&p);
        if k.iter().any(|v| !v.is_zero()) {
            prop_assert!(quadric.residual(&k).is_zero());
            let [fa, fb] = proj.fibre(&k).unwrap();
            prop_assert_eq!(rank3(&fa, &fb, &p), 2, "p on the fibre over F(p)");
        }
        let Ok(img) = curve_image(&proj, &x) else { return Ok(()) };
        assert_certs(&img.certify())?;
        // f64: the same quadric built from f64 parameters
        let qf = match kind {
            0 => Quadric::ellipsoid(fl(&a), fl(&b), fl(&c)),
            1 => Quadric::hyperboloid_one_sheet(fl(&a), fl(&b), fl(&c)),
            _ => Quadric::from_matrix(quadric.matrix().clone().map(|r| r.map(|v| fl(&v)))).and_then(|qq| qq.with_point(to_f64(quadric.point().unwrap()))),
        }.unwrap();
        if kind <= 1 || quadric.point().is_some() {
            let pf = match (&proj, qf.projection().unwrap()) {
                (AnyProjection::General(_), pf @ AnyProjection::General(_)) => pf,
                (AnyProjection::Cone(_), pf @ AnyProjection::Cone(_)) => pf,
                _ => { prop_assert!(false, "f64 and exact classify differently"); unreachable!() }
            };
            prop_assert!(close(&pf.apply(&to_f64(&p)), &k));
        }
        let params: Vec<Rational> = (0..3).map(|i| q(i, 2)).collect();
        let pts = sample_points(img.image(), &params);
        if let Ok(it) = interpolate(&proj, &pts, &params, x.degree()) {
            assert_certs(&it.certify())?;
        }
    }

    /// Random matrices and points never panic; every failure is a typed error.
    #[test]
    fn random_inputs_give_errors_not_panics(m in prop::collection::vec(-3i64..=3, 10), p in hom(), pts in prop::collection::vec(hom(), 1..5)) {
        let e = |i: usize| Rational::from(m[i]);
        let mat: Mat4<Rational> = [
            [e(0), e(1), e(2), e(3)],
            [e(1), e(4), e(5), e(6)],
            [e(2), e(5), e(7), e(8)],
            [e(3), e(6), e(8), e(9)],
        ];
        if let Ok(quadric) = Quadric::from_matrix(mat.clone()) {
            let _ = quadric.kind();
            if let Ok(proj) = quadric.projection() {
                assert_certs(&proj.certify())?;
                let k = proj.apply(&p);
                if k.iter().any(|v| !v.is_zero()) {
                    prop_assert!(quadric.residual(&k).is_zero());
                    let _ = proj.fibre(&k);
                }
                let _ = proj.fibre(&p);
            }
            match find_rational_point(&mat) {
                Ok(x) => prop_assert!(quad(&mat, &x).is_zero()),
                Err(QuadricError::NoRationalPoint(_) | QuadricError::NoRealPoint(_) | QuadricError::Unsupported(_)) => {}
                Err(other) => prop_assert!(false, "{other}"),
            }
        }
        let params: Vec<Rational> = (0..pts.len()).map(|i| Rational::from(i as i64)).collect();
        let res = interpolate(&Delta, &pts, &params, 2);
        let on_sphere = pts.iter().all(|k| quad(&rcagd::quadric::stereographic::sphere_matrix(), k).is_zero());
        if !on_sphere {
            let is_not_on_quadric = matches!(res, Err(QuadricError::NotOnQuadric { .. }));
            prop_assert!(is_not_on_quadric);
        }
        let _ = Delta.fibre(&p);
        let _ = Psi.fibre(&p);
    }
}

#[test]
fn typed_errors() {
    let r = Rational::from;
    let k = |v: [i64; 4]| v.map(Rational::from);
    // not on the quadric
    assert!(matches!(
        Delta.fibre(&k([1, 1, 1, 0])),
        Err(QuadricError::NotOnQuadric { .. })
    ));
    assert!(matches!(
        Delta.fibre(&k([0, 0, 0, 0])),
        Err(QuadricError::ZeroPoint(_))
    ));
    // repeated points and parameters
    let pts = [k([1, 1, 0, 0]), k([2, 2, 0, 0]), k([1, 0, 1, 0])];
    assert!(matches!(
        interpolate(&Delta, &pts, &[r(0), r(1), r(2)], 1),
        Err(QuadricError::RepeatedPoints(0, 1))
    ));
    let pts = [k([1, 1, 0, 0]), k([1, 0, 1, 0])];
    assert!(matches!(
        interpolate(&Delta, &pts, &[r(1), r(1)], 1),
        Err(QuadricError::RepeatedParameters(0, 1))
    ));
    assert!(matches!(
        interpolate(&Delta, &pts, &[r(1)], 1),
        Err(QuadricError::Dimension(_))
    ));
    // the exceptional line of the parabolic congruence (cone), and its vertex
    let cone = Quadric::cone(r(1), r(1), r(1))
        .unwrap()
        .projection()
        .unwrap();
    let axis_line = BezierCurve::from_homogeneous(vec![
        vec![r(1), r(0), r(0), r(0)],
        vec![r(0), r(0), r(0), r(1)],
    ])
    .unwrap();
    assert!(matches!(
        curve_image(&cone, &axis_line),
        Err(QuadricError::Degenerate(_))
    ));
    assert!(matches!(
        cone.fibre(&k([1, 0, 0, 0])),
        Err(QuadricError::Exceptional { .. })
    ));
    // ψ's focal lines
    let focal = BezierCurve::from_homogeneous(vec![
        vec![r(1), r(0), r(0), r(0)],
        vec![r(0), r(1), r(0), r(0)],
    ])
    .unwrap();
    assert!(matches!(
        curve_image(&Psi, &focal),
        Err(QuadricError::Degenerate(_))
    ));
    // no real / no rational point
    let imag = Quadric::from_matrix([
        k([1, 0, 0, 0]),
        k([0, 1, 0, 0]),
        k([0, 0, 1, 0]),
        k([0, 0, 0, 1]),
    ])
    .unwrap();
    assert!(matches!(
        imag.projection(),
        Err(QuadricError::NoRealPoint(_))
    ));
    let seven = Quadric::from_matrix([
        k([-7, 0, 0, 0]),
        k([0, 1, 0, 0]),
        k([0, 0, 1, 0]),
        k([0, 0, 0, 1]),
    ])
    .unwrap();
    match seven.projection() {
        Err(QuadricError::NoRationalPoint(msg)) => assert!(msg.contains("Q_2"), "{msg}"),
        other => panic!("{other:?}"),
    }
    // Miquel failing, degenerate: p1, p2, p3 on the equator C12, so q2 = p3 and
    // det[p1,q2,p3,q4] = 0 trivially; the chain does not close
    let corners = [
        k([1, 1, 0, 0]),
        k([1, 0, 1, 0]),
        k([1, -1, 0, 0]),
        k([1, 0, 0, 1]),
    ];
    let edges = [
        k([5, 3, 4, 0]),
        k([3, -2, 2, 1]),
        k([3, -2, -2, 1]),
        k([3, 2, 1, 2]),
    ];
    match BiquadraticPatch::from_corners(&Delta, corners.clone(), edges, r(1)) {
        Err(QuadricError::MiquelFails { residual, detail }) => {
            assert_eq!(residual, "0");
            assert!(detail.contains("q2 = p3"), "{detail}");
        }
        other => panic!("expected MiquelFails: {other:?}"),
    }
    // Miquel failing with a non-zero residual
    let edges = [
        k([3, 2, 2, 1]),
        k([3, -2, 2, 1]),
        k([3, -2, -2, 1]),
        k([3, 2, 1, 2]),
    ];
    match BiquadraticPatch::from_corners(&Delta, corners, edges, r(1)) {
        Err(QuadricError::MiquelFails { residual, .. }) => assert_ne!(residual, "0"),
        other => panic!("expected MiquelFails: {other:?}"),
    }
    // f64: not finite
    let nan = [f64::NAN, 0.0, 0.0, 1.0];
    assert!(matches!(Delta.fibre(&nan), Err(QuadricError::NotFinite(_))));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// f64 interpolation agrees with the exact interpolant (same data, same parameters).
    #[test]
    fn f64_interpolation_agrees(x in curve(2).prop_filter("degree 2", |c| c.degree() == 2)) {
        let params: Vec<Rational> = (0..5).map(|i| q(i, 4)).collect();
        let img = curve_image(&Delta, &x).unwrap();
        let pts = sample_points(img.image(), &params);
        let Ok(exact) = interpolate(&Delta, &pts, &params, 2) else { return Ok(()) };
        if exact.dimension() != 2 { return Ok(()); }
        let pf: Vec<Hom<f64>> = pts.iter().map(to_f64).collect();
        let tf: Vec<f64> = params.iter().map(fl).collect();
        let approx = interpolate(&Delta, &pf, &tf, 2).unwrap();
        for c in approx.certify() {
            prop_assert!(c.holds && !c.exact, "{}", c);
        }
        // same curve up to a constant factor: compare normalized control points
        let e = exact.curve().coords();
        let a = approx.curve().coords();
        let (ie, _) = e.iter().enumerate().max_by(|u, v| fl(u.1).abs().total_cmp(&fl(v.1).abs())).unwrap();
        let ratio = a[ie] / fl(&e[ie]);
        let scaled: Vec<f64> = a.iter().map(|v| v / ratio).collect();
        prop_assert!(close(&scaled, e));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// Interpolation on H through ψ-images of random points at distinct parameters: the
    /// Segre interpolant passes through them, has degree ≤ the ψ-interpolant's.
    #[test]
    fn segre_interpolation(ps in prop::collection::vec(hom(), 2..6)) {
        use rcagd::quadric::paraboloid::interpolate_segre;
        let pts: Vec<Hom<Rational>> = ps.iter().map(psi).collect();
        if pts.iter().any(|p| p.iter().all(|x| x.is_zero())) { return Ok(()); }
        let params: Vec<Rational> = (0..pts.len()).map(|i| q(i as i64, 3)).collect();
        match interpolate_segre(&pts, &params) {
            Ok(it) => {
                assert_certs(&it.certify())?;
                let (r, s) = it.degrees();
                prop_assert!(r + s <= 2 * (pts.len() / 2) + 1);
            }
            Err(QuadricError::RepeatedPoints(..)) => {}
            Err(e) => prop_assert!(false, "{e}"),
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Satz 7 transferred: bilinear patches map to biquadratic patches on an ellipsoid and a
    /// two-sheet hyperboloid through their rational normal forms, with the Miquel
    /// certificates (concyclic = coplanar on every quadric).
    #[test]
    fn miquel_on_other_oval_quadrics(c in [hom(), hom(), hom(), hom()], a in pos(), b in pos(), cc in pos(), two_sheet in any::<bool>()) {
        let quadric = if two_sheet { Quadric::hyperboloid_two_sheets(a, b, cc) } else { Quadric::ellipsoid(a, b, cc) }.unwrap();
        let proj = quadric.projection().unwrap();
        let Ok(bp) = BiquadraticPatch::from_bilinear(&proj, c[0].clone(), c[1].clone(), c[2].clone(), c[3].clone()) else { return Ok(()) };
        assert_certs(&bp.certify())?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    /// The whole-sphere cover mapped onto a random ellipsoid: every certificate holds
    /// exactly (on the ellipsoid, positive weights, watertight), the patches' points
    /// satisfy the ellipsoid's equation, and the f64 construction agrees.
    #[test]
    fn sphere_cover_on_random_ellipsoids(c in [rat(), rat(), rat()], r in [pos(), pos(), pos()], u in 0i64..=4, v in 0i64..=4) {
        let cover = rcagd::quadric::sphere_cover(c.clone(), r.clone()).unwrap();
        assert_certs(&cover.certify())?;
        prop_assert_eq!(cover.patches().len(), 16);
        let (u, v) = (q(u, 4), q(v, 4));
        for p in cover.patches() {
            let x = p.eval(&u, &v).unwrap();
            let s: Rational = (0..3)
                .map(|i| {
                    let d = (x[i].clone() - c[i].clone()) / r[i].clone();
                    d.clone() * d
                })
                .fold(Rational::from(0), |a, b| a + b);
            prop_assert_eq!(s, Rational::from(1));
        }
        let f = rcagd::quadric::sphere_cover(c.clone().map(|x| fl(&x)), r.clone().map(|x| fl(&x))).unwrap();
        prop_assert!(f.all_hold());
        for (pe, pf) in cover.patches().iter().zip(f.patches()) {
            prop_assert!(close(pf.coords(), pe.coords()));
        }
    }
}
