//! Property tests of the Laguerre-geometry module (Peternell ch. 3, §3.1–§3.2) with random exact
//! inputs: the model maps round-trip, Laguerre maps preserve oriented contact (and the incidence
//! form of every hyperplane), the dilatation is the offset with the sign of
//! docs/math/laguerre-pn.md, Errata E6, every map is pe-orthogonal, and `f64` agrees with the exact
//! result.

use proptest::prelude::*;
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
fn rat((p, d): (i64, i64)) -> Q {
    q(p, d)
}
fn rational() -> impl Strategy<Value = (i64, i64)> {
    (-6i64..=6, 1i64..=4)
}
fn dot(a: &[Q], b: &[Q]) -> Q {
    a.iter()
        .zip(b)
        .fold(qi(0), |s, (x, y)| s + x.clone() * y.clone())
}

/// The unit normal `(2a, 2b, a² + b² − 1)/(a² + b² + 1)` (inverse stereographic
/// projection, Peternell (3.13)), optionally reversed.
fn unit_normal(a: &Q, b: &Q, flip: bool) -> [Q; 3] {
    let s = a.clone() * a.clone() + b.clone() * b.clone();
    let den = s.clone() + qi(1);
    let n = [
        qi(2) * a.clone() / den.clone(),
        qi(2) * b.clone() / den.clone(),
        (s - qi(1)) / den,
    ];
    if flip {
        n.map(|x| -x)
    } else {
        n
    }
}

/// The rotation matrix of the rational quaternion `(w, x, y, z) ≠ 0`.
fn rotation(w: &Q, x: &Q, y: &Q, z: &Q) -> [[Q; 3]; 3] {
    let nn = w.clone() * w.clone()
        + x.clone() * x.clone()
        + y.clone() * y.clone()
        + z.clone() * z.clone();
    let t = |v: Q| v / nn.clone();
    let (w, x, y, z) = (w.clone(), x.clone(), y.clone(), z.clone());
    let two = qi(2);
    [
        [
            t(w.clone() * w.clone() + x.clone() * x.clone()
                - y.clone() * y.clone()
                - z.clone() * z.clone()),
            t(two.clone() * (x.clone() * y.clone() - w.clone() * z.clone())),
            t(two.clone() * (x.clone() * z.clone() + w.clone() * y.clone())),
        ],
        [
            t(two.clone() * (x.clone() * y.clone() + w.clone() * z.clone())),
            t(
                w.clone() * w.clone() - x.clone() * x.clone() + y.clone() * y.clone()
                    - z.clone() * z.clone(),
            ),
            t(two.clone() * (y.clone() * z.clone() - w.clone() * x.clone())),
        ],
        [
            t(two.clone() * (x.clone() * z.clone() - w.clone() * y.clone())),
            t(two.clone() * (y.clone() * z.clone() + w.clone() * x.clone())),
            t(
                w.clone() * w.clone() - x.clone() * x.clone() - y.clone() * y.clone()
                    + z.clone() * z.clone(),
            ),
        ],
    ]
}

/// Random ingredients of a Laguerre map: similarity λ, boost (axis, s), rotation
/// quaternion, translation, dilatation.
#[derive(Debug, Clone)]
struct MapSpec {
    lambda: (i64, i64),
    axis: usize,
    s: (i64, i64),
    quat: Vec<i64>,
    shift: Vec<(i64, i64)>,
    dil: (i64, i64),
}

fn map_spec() -> impl Strategy<Value = MapSpec> {
    (
        (prop_oneof![-4i64..=-1, 1i64..=4], 1i64..=3),
        0usize..3,
        (-3i64..=3, 4i64..=9),
        prop::collection::vec(-3i64..=3, 4),
        prop::collection::vec(rational(), 3),
        rational(),
    )
        .prop_map(|(lambda, axis, s, quat, shift, dil)| MapSpec {
            lambda,
            axis,
            s,
            quat,
            shift,
            dil,
        })
}

fn build_map(m: &MapSpec) -> LaguerreMap<Q> {
    let mut quat: Vec<Q> = m.quat.iter().map(|&k| qi(k)).collect();
    if quat.iter().all(|x| *x == qi(0)) {
        quat[0] = qi(1);
    }
    let rot = LaguerreMap::rotation(rotation(&quat[0], &quat[1], &quat[2], &quat[3]))
        .expect("a quaternion rotation is orthogonal");
    LaguerreMap::similarity(rat(m.lambda))
        .expect("λ ≠ 0")
        .compose(&LaguerreMap::boost(m.axis, rat(m.s)).expect("|s| < 1"))
        .compose(&rot)
        .compose(&LaguerreMap::translation([
            rat(m.shift[0]),
            rat(m.shift[1]),
            rat(m.shift[2]),
        ]))
        .compose(&LaguerreMap::dilatation(rat(m.dil)))
}

/// `AᵀEA − E`, computed here independently of the library.
fn pe_residual_is_zero(a: &[[Q; 4]; 4]) -> bool {
    let eta = |k: usize| if k == 3 { qi(-1) } else { qi(1) };
    (0..4).all(|i| {
        (0..4).all(|j| {
            let s = (0..4).fold(qi(0), |s, k| s + a[k][i].clone() * eta(k) * a[k][j].clone());
            s == if i == j { eta(i) } else { qi(0) }
        })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Every model map of Peternell §3.2–§3.5 round-trips exactly: γ-hyperplanes (3.5) (any
    /// multiple), Blaschke points (3.10), the isotropic model (3.11)/(3.13) in both
    /// directions, the dual isotropic model (3.16)/(3.17) with the factor ρ of
    /// docs/math/laguerre-pn.md, Errata E7 (any multiple), cycles ↔ cyclographic points (3.6) ↔ isotropic spheres (3.12).
    #[test]
    fn model_maps_round_trip(
        a in rational(), b in rational(), flip in any::<bool>(),
        e0 in rational(), k in (prop_oneof![-5i64..=-1, 1i64..=5], 1i64..=3),
        m in prop::collection::vec(rational(), 3), r in rational(),
        y in prop::collection::vec(rational(), 3),
    ) {
        let n = unit_normal(&rat(a), &rat(b), flip);
        let e = OrientedPlane::new(rat(e0), n.clone()).expect("unit normal");
        let kk = rat(k);
        let g = e.to_gamma_hyperplane().map(|x| x * kk.clone());
        prop_assert_eq!(OrientedPlane::from_gamma_hyperplane(&g).expect("γ"), e.clone());
        let bl = e.to_blaschke();
        prop_assert_eq!(dot(&bl[1..4], &bl[1..4]), bl[0].clone() * bl[0].clone());
        prop_assert_eq!(OrientedPlane::from_blaschke(&bl.map(|x| x * kk.clone())).expect("Δ"), e.clone());
        if n[2] != qi(1) {
            let yy = e.to_isotropic().expect("n₃ ≠ 1");
            prop_assert_eq!(OrientedPlane::from_isotropic(&yy), e.clone());
        } else {
            prop_assert!(matches!(e.to_isotropic(), Err(LaguerreError::NoIsotropicImage(_))));
        }
        if n[2] != qi(1) {
            let dy = e.to_dual_isotropic().map(|x| x * kk.clone());
            prop_assert_eq!(OrientedPlane::from_dual_isotropic(&dy).expect("Y₃ ≠ 0"), e.clone());
        }
        let y = [rat(y[0]), rat(y[1]), rat(y[2])];
        let plane = OrientedPlane::from_isotropic(&y);
        prop_assert_eq!(dot(&plane.n, &plane.n), qi(1));
        prop_assert_eq!(plane.to_isotropic().expect("image"), y);
        let c = Cycle::new([rat(m[0]), rat(m[1]), rat(m[2])], rat(r)).expect("finite");
        prop_assert_eq!(Cycle::from_cyclographic(&c.to_cyclographic()), c.clone());
        prop_assert_eq!(c.isotropic_sphere().to_cycle(), c.clone());
        // contact ⇔ incidence in the isotropic model (Lemma 3.1)
        let touching = plane.offset(&c.contact_residual(&plane));
        prop_assert!(c.in_oriented_contact(&touching));
        prop_assert!(c.isotropic_sphere().contains(&touching.to_isotropic().expect("image")));
        prop_assert_eq!(
            c.in_oriented_contact(&plane),
            c.isotropic_sphere().contains(&plane.to_isotropic().expect("image"))
        );
    }

    /// Laguerre maps (3.8) preserve oriented contact and non-contact (3.3), keep the
    /// incidence value ε₀ + ε·x of every hyperplane and point of R⁴, compose as maps,
    /// invert exactly and agree with their action on the isotropic model.
    #[test]
    fn laguerre_maps_preserve_oriented_contact(
        spec in map_spec(), spec2 in map_spec(),
        a in rational(), b in rational(), e0 in rational(),
        m in prop::collection::vec(rational(), 3),
        eps in prop::collection::vec(rational(), 5),
        x in prop::collection::vec(rational(), 4),
    ) {
        let map = build_map(&spec);
        let e = OrientedPlane::new(rat(e0), unit_normal(&rat(a), &rat(b), false)).expect("unit");
        let m = [rat(m[0]), rat(m[1]), rat(m[2])];
        let r = -e.e0.clone() - dot(&e.n, &m);
        let c = Cycle::new(m, r).expect("finite");
        prop_assert!(c.in_oriented_contact(&e));
        let (e2, c2) = (map.apply_plane(&e).expect("plane"), map.apply_cycle(&c));
        prop_assert!(c2.in_oriented_contact(&e2), "contact preserved by {}", map);
        let far = c.offset(&qi(1));
        prop_assert!(!map.apply_cycle(&far).in_oriented_contact(&e2), "non-contact preserved");
        // the contact point moves to the contact point
        let x0 = c.contact_point(&e).expect("contact");
        let x2 = c2.contact_point(&e2).expect("contact");
        if *map.scale() == qi(1) && map.matrix()[3][3] == qi(1) && map.shift()[3] == qi(0) {
            // a Euclidean motion: contact points are mapped as points
            let img = map.apply_point(&[x0[0].clone(), x0[1].clone(), x0[2].clone(), qi(0)]);
            prop_assert_eq!(img[..3].to_vec(), x2.to_vec());
        }
        // ε' · (1, x') = ε · (1, x) for any hyperplane ε and point x of R⁴
        let eps: Vec<Q> = eps.into_iter().map(rat).collect();
        let x: [Q; 4] = [rat(x[0]), rat(x[1]), rat(x[2]), rat(x[3])];
        let h = map.hyperplane_matrix();
        let eps2: Vec<Q> = (0..5).map(|col| (0..5).fold(qi(0), |s, row| s + eps[row].clone() * h[row][col].clone())).collect();
        let x2p = map.apply_point(&x);
        prop_assert_eq!(
            eps2[0].clone() + dot(&eps2[1..], &x2p),
            eps[0].clone() + dot(&eps[1..], &x)
        );
        // composition and inverse
        let other = build_map(&spec2);
        let comp = map.compose(&other);
        prop_assert_eq!(comp.apply_cycle(&c), map.apply_cycle(&other.apply_cycle(&c)));
        prop_assert_eq!(
            comp.apply_plane(&e).expect("plane"),
            map.apply_plane(&other.apply_plane(&e).expect("plane")).expect("plane")
        );
        prop_assert_eq!(map.inverse().apply_cycle(&c2), c.clone());
        prop_assert_eq!(map.inverse().apply_plane(&e2).expect("plane"), e.clone());
        // the isotropic model: Λ ∘ α ∘ Λ⁻¹, and the image sphere contains the image point
        let y = e.to_isotropic().expect("image");
        if let Ok(y2) = map.apply_isotropic(&y) {
            prop_assert_eq!(OrientedPlane::from_isotropic(&y2), e2.clone());
            prop_assert!(c2.isotropic_sphere().contains(&y2));
        } else {
            prop_assert_eq!(e2.n[2].clone(), qi(1));
        }
    }

    /// The dilatation (3.4) is the offset x ↦ x + d n: on planes e0 ↦ e0 − d and on cycles
    /// r ↦ r + d (docs/math/laguerre-pn.md, Errata E6 — the printed e0 ↦ e0 + d is the offset by
    /// −d); in the isotropic model y₃ ↦ y₃ − (d/2)(S + 1) (corrected (3.15)). It commutes with
    /// Euclidean motions and dilatations add.
    #[test]
    fn dilatation_is_the_offset_e6(
        a in rational(), b in rational(), e0 in rational(),
        d in (prop_oneof![-9i64..=-1, 1i64..=9], 1i64..=4), d2 in rational(),
        s in rational(), t in rational(),
        spec in map_spec(),
    ) {
        let d = rat(d);
        let e = OrientedPlane::new(rat(e0), unit_normal(&rat(a), &rat(b), false)).expect("unit");
        let dil = LaguerreMap::dilatation(d.clone());
        let img = dil.apply_plane(&e).expect("plane");
        prop_assert_eq!(img.clone(), e.offset(&d));
        prop_assert_eq!(img.e0.clone(), e.e0.clone() - d.clone());
        // a point of e: the foot of the origin plus a tangent combination
        let (u1, u2) = ([e.n[1].clone(), -e.n[0].clone(), qi(0)], [e.n[2].clone(), qi(0), -e.n[0].clone()]);
        let x: [Q; 3] = std::array::from_fn(|i| -e.e0.clone() * e.n[i].clone() + rat(s) * u1[i].clone() + rat(t) * u2[i].clone());
        prop_assert!(e.contains(&x));
        let xd: [Q; 3] = std::array::from_fn(|i| x[i].clone() + d.clone() * e.n[i].clone());
        let xm: [Q; 3] = std::array::from_fn(|i| x[i].clone() - d.clone() * e.n[i].clone());
        prop_assert!(img.contains(&xd), "x + d n on the dilated plane");
        prop_assert!(!img.contains(&xm), "E6: not x − d n");
        // the printed rule e0 + d is the offset by −d
        let printed = OrientedPlane::new(e.e0.clone() + d.clone(), e.n.clone()).expect("unit");
        prop_assert!(printed.contains(&xm));
        // cycles: r ↦ r + d; the point cycle of x becomes the sphere touching img at x + d n
        let pc = Cycle::point(x.clone());
        let dc = dil.apply_cycle(&pc);
        prop_assert_eq!(dc.clone(), pc.offset(&d));
        prop_assert_eq!(dc.contact_point(&img).expect("contact").to_vec(), xd.to_vec());
        // isotropic model
        let y = e.to_isotropic().expect("image");
        prop_assert_eq!(dil.apply_isotropic(&y).expect("image"), isotropic_dilatation(&y, &d));
        prop_assert_eq!(OrientedPlane::from_isotropic(&isotropic_dilatation(&y, &d)), img);
        // group laws
        let sum = LaguerreMap::dilatation(d.clone()).compose(&LaguerreMap::dilatation(rat(d2)));
        prop_assert_eq!(sum.apply_plane(&e).expect("plane"), e.offset(&(d.clone() + rat(d2))));
        let mut quat: Vec<Q> = spec.quat.iter().map(|&k| qi(k)).collect();
        if quat.iter().all(|x| *x == qi(0)) { quat[0] = qi(1); }
        let motion = LaguerreMap::rotation(rotation(&quat[0], &quat[1], &quat[2], &quat[3])).expect("rot")
            .compose(&LaguerreMap::translation([rat(spec.shift[0]), rat(spec.shift[1]), rat(spec.shift[2])]));
        prop_assert_eq!(
            motion.compose(&dil).apply_plane(&e).expect("plane"),
            dil.compose(&motion).apply_plane(&e).expect("plane")
        );
    }

    /// Every composed map is pe-orthogonal (3.9), checked independently of the library and
    /// by its certificate; pe congruences (|λ| = 1) keep the squared tangential distance of
    /// two cycles, pe similarities scale it by λ²; a perturbed matrix is rejected.
    #[test]
    fn pe_orthogonality(
        spec in map_spec(),
        m1 in prop::collection::vec(rational(), 4),
        m2 in prop::collection::vec(rational(), 4),
        (i, j) in (0usize..4, 0usize..4),
    ) {
        let map = build_map(&spec);
        prop_assert!(pe_residual_is_zero(map.matrix()));
        let certs = map.certify();
        prop_assert!(certs.iter().all(|c| c.holds && c.exact));
        let c1 = Cycle::new([rat(m1[0]), rat(m1[1]), rat(m1[2])], rat(m1[3])).expect("finite");
        let c2 = Cycle::new([rat(m2[0]), rat(m2[1]), rat(m2[2])], rat(m2[3])).expect("finite");
        let l = map.scale().clone();
        prop_assert_eq!(
            map.apply_cycle(&c1).tangential_distance_squared(&map.apply_cycle(&c2)),
            l.clone() * l * c1.tangential_distance_squared(&c2)
        );
        let mut bad = map.matrix().clone();
        bad[i][j] = bad[i][j].clone() + q(1, 7);
        let rejected = matches!(
            LaguerreMap::new(map.shift().clone(), map.scale().clone(), bad),
            Err(LaguerreError::NotOrthogonal { .. })
        );
        prop_assert!(rejected, "a perturbed matrix must be rejected");
    }

    /// The f64 path agrees with the exact one (maps of planes and cycles, model maps).
    #[test]
    fn f64_agrees_with_exact(
        a in rational(), b in rational(), e0 in rational(),
        lambda in (1i64..=4, 1i64..=3), s in (-3i64..=3, 4i64..=9), axis in 0usize..3,
        sh in prop::collection::vec(rational(), 3), d in rational(),
    ) {
        let e = OrientedPlane::new(rat(e0), unit_normal(&rat(a), &rat(b), false)).expect("unit");
        let map = LaguerreMap::similarity(rat(lambda)).expect("λ")
            .compose(&LaguerreMap::boost(axis, rat(s)).expect("boost"))
            .compose(&LaguerreMap::translation([rat(sh[0]), rat(sh[1]), rat(sh[2])]))
            .compose(&LaguerreMap::dilatation(rat(d)));
        let f = |x: (i64, i64)| x.0 as f64 / x.1 as f64;
        let nf = e.n.clone().map(|x| Scalar::to_f64(&x));
        let ef = OrientedPlane::new(f(e0), nf).expect("unit within tolerance");
        let mapf = LaguerreMap::similarity(f(lambda)).expect("λ")
            .compose(&LaguerreMap::boost(axis, f(s)).expect("boost"))
            .compose(&LaguerreMap::translation([f(sh[0]), f(sh[1]), f(sh[2])]))
            .compose(&LaguerreMap::dilatation(f(d)));
        prop_assert!(mapf.all_hold());
        let img = map.apply_plane(&e).expect("plane");
        let imgf = mapf.apply_plane(&ef).expect("plane");
        let close = |x: f64, y: f64| (x - y).abs() <= 1e-9 * (1.0 + x.abs().max(y.abs()));
        prop_assert!(close(imgf.e0, Scalar::to_f64(&img.e0)));
        for k in 0..3 {
            prop_assert!(close(imgf.n[k], Scalar::to_f64(&img.n[k])));
        }
        let c = Cycle::new([rat(sh[0]), rat(sh[1]), rat(d)], rat(a)).expect("finite");
        let cf = Cycle::new(c.center.clone().map(|x| Scalar::to_f64(&x)), Scalar::to_f64(&c.radius)).expect("finite");
        let (ci, cfi) = (map.apply_cycle(&c), mapf.apply_cycle(&cf));
        prop_assert!(close(cfi.radius, Scalar::to_f64(&ci.radius)));
        if let (Ok(y), Ok(yf)) = (img.to_isotropic(), imgf.to_isotropic()) {
            for k in 0..3 {
                prop_assert!((yf[k] - Scalar::to_f64(&y[k])).abs() <= 1e-6 * (1.0 + Scalar::to_f64(&y[k]).abs()));
            }
        }
    }
}

/// Non-finite `f64` input and a γ-hyperplane that is not lightlike are errors, not panics.
#[test]
fn invalid_inputs_are_errors() {
    assert!(matches!(
        OrientedPlane::new(f64::INFINITY, [0.0, 0.0, 1.0]),
        Err(LaguerreError::NotFinite(_))
    ));
    assert!(matches!(
        Cycle::new([0.0, f64::NAN, 0.0], 1.0),
        Err(LaguerreError::NotFinite(_))
    ));
    assert!(matches!(
        OrientedPlane::from_gamma_hyperplane(&[qi(1), qi(1), qi(1), qi(0), qi(1)]),
        Err(LaguerreError::NotLightlike(_))
    ));
    assert!(matches!(
        OrientedPlane::from_gamma_hyperplane(&[qi(1), qi(1), qi(0), qi(0), qi(0)]),
        Err(LaguerreError::Degenerate(_))
    ));
    assert!(matches!(
        OrientedPlane::from_blaschke(&[qi(0), qi(1), qi(0), qi(0), qi(0)]),
        Err(LaguerreError::Degenerate(_))
    ));
    let e = OrientedPlane::new(qi(1), [q(3, 5), q(4, 5), qi(0)]).expect("unit");
    let c = Cycle::new([qi(0), qi(0), qi(0)], qi(0)).expect("finite");
    assert!(matches!(
        c.contact_point(&e),
        Err(LaguerreError::NotInContact(_))
    ));
}
