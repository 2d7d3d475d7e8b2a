//! B. Jüttler, *Zur Konstruktion rationaler Kurven und Flächen auf Quadriken*:
//! every formula, statement and construction the paper prints, reproduced exactly, with
//! the corrections of docs/math/quadrics.md (errata J1–J3).
//! The seed prints no numerical examples; its "examples" are the formulas (5)–(18),
//! Satz 1–11, Lemma 4/10 and the property lists, each checked here as an exact identity
//! or on exact instances.

use rcagd::quadric::general::{certify_transfer, seed_transfer, transfer_curve};
use rcagd::quadric::image::{
    certify_curve_on_quadric, certify_patch_on_quadric, curve_image, curve_preimage, patch_image,
    patch_preimage,
};
use rcagd::quadric::interpolation::{interpolate, interpolate_in_plane};
use rcagd::quadric::paraboloid::{
    self, alpha, conic_preimage_quadric, paraboloid_matrix, plane_conic_matrix, psi, psi_fibre,
    psi_fibre_seed, tau, tau_inverse,
};
use rcagd::quadric::sphere_patch::{miquel_residuals, BiquadraticPatch};
use rcagd::quadric::stereographic::{
    self, circle_preimage_quadric, delta, delta_fibre, fibre_rotation, plane_circle_matrix, sigma,
    sigma_inverse, sphere_matrix, theta,
};
use rcagd::quadric::{
    Delta, GeneralizedProjection, Hom, Mat4, Psi, Quadric, QuadricError, QuadricKind,
};
use rcagd::Certified;
use rcagd_algebra::Rational;
use rcagd_geom::{BezierCurve, BezierPatch};

fn r(n: i64) -> Rational {
    Rational::from(n)
}
fn q(n: i64, d: i64) -> Rational {
    Rational::from(n) / Rational::from(d)
}
fn h(v: [i64; 4]) -> Hom<Rational> {
    v.map(r)
}
fn curve(pts: &[[i64; 4]]) -> BezierCurve<Rational> {
    BezierCurve::from_homogeneous(pts.iter().map(|p| p.map(r).to_vec()).collect()).unwrap()
}
fn add(a: &Hom<Rational>, b: &Hom<Rational>) -> Hom<Rational> {
    [0, 1, 2, 3].map(|i| a[i].clone() + b[i].clone())
}
fn scale(c: &Rational, a: &Hom<Rational>) -> Hom<Rational> {
    a.clone().map(|x| c.clone() * x)
}
fn rank(rows: &[Hom<Rational>]) -> usize {
    // exact rank by elimination
    let mut m: Vec<Vec<Rational>> = rows.iter().map(|r| r.to_vec()).collect();
    let mut rk = 0;
    for col in 0..4 {
        let Some(p) = (rk..m.len()).find(|&i| !m[i][col].is_zero()) else {
            continue;
        };
        m.swap(rk, p);
        for i in 0..m.len() {
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
    rank(&[a.clone(), b.clone()]) == 1
}
fn quad(m: &Mat4<Rational>, x: &Hom<Rational>) -> Rational {
    let mut s = r(0);
    for i in 0..4 {
        for j in 0..4 {
            s += m[i][j].clone() * x[i].clone() * x[j].clone();
        }
    }
    s
}
fn det4(rows: [&Hom<Rational>; 4]) -> Rational {
    // Leibniz over permutations
    let perms = permutations();
    let mut s = r(0);
    for (p, sign) in perms {
        let mut t = r(sign);
        for i in 0..4 {
            t *= rows[i][p[i]].clone();
        }
        s += t;
    }
    s
}
fn permutations() -> Vec<([usize; 4], i64)> {
    let mut out = Vec::new();
    for a in 0..4 {
        for b in 0..4 {
            for c in 0..4 {
                for d in 0..4 {
                    let p = [a, b, c, d];
                    let mut seen = [false; 4];
                    if p.iter().any(|&x| std::mem::replace(&mut seen[x], true)) {
                        continue;
                    }
                    let mut inv = 0;
                    for i in 0..4 {
                        for j in i + 1..4 {
                            if p[i] > p[j] {
                                inv += 1;
                            }
                        }
                    }
                    out.push((p, if inv % 2 == 0 { 1 } else { -1 }));
                }
            }
        }
    }
    out
}
/// A small deterministic generator of exact test data.
struct Lcg(u64);
impl Lcg {
    fn int(&mut self, lo: i64, hi: i64) -> i64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        lo + ((self.0 >> 33) % ((hi - lo + 1) as u64)) as i64
    }
    fn rat(&mut self) -> Rational {
        q(self.int(-5, 5), self.int(1, 3))
    }
    fn hom(&mut self) -> Hom<Rational> {
        loop {
            let p = [self.rat(), self.rat(), self.rat(), self.rat()];
            if p.iter().any(|x| !x.is_zero()) {
                return p;
            }
        }
    }
}
fn assert_all(certs: &[rcagd_algebra::Certificate]) {
    for c in certs {
        assert!(c.holds, "{c}");
        assert!(c.exact, "{c} should be exact");
    }
}

// ---------------------------------------------------------------------------------------
// §1–§2: δ, σ, ϑ and the projecting lines

/// (5), (7), (9): δ(p) lies on the unit sphere K, as a polynomial identity, and
/// k0 = |p|² > 0.
#[test]
fn formula_9_delta_lands_on_the_sphere_5() {
    let certs = stereographic::certify_identities::<Rational>();
    assert!(certs[0].property.contains("(5),(9)"));
    assert_all(&certs);
    let mut g = Lcg(1);
    for _ in 0..20 {
        let p = g.hom();
        let k = delta(&p);
        assert!(quad(&sphere_matrix(), &k).is_zero());
        assert!(k[0] > r(0));
    }
}

/// Satz 2 (10): δ restricted to the equator plane P is the stereographic projection σ
/// from z = (1,0,0,1): σ(p) lies on K and on the line z p.
#[test]
fn satz_2_sigma_is_the_stereographic_projection_from_z() {
    let z = h([1, 0, 0, 1]);
    let mut g = Lcg(2);
    for _ in 0..20 {
        let mut p = g.hom();
        p[3] = r(0);
        if p[0].is_zero() && p[1].is_zero() && p[2].is_zero() {
            continue;
        }
        let s = sigma(&p).unwrap();
        assert_eq!(s, delta(&p));
        assert!(quad(&sphere_matrix(), &s).is_zero());
        assert!(
            rank(&[z.clone(), p.clone(), s.clone()]) <= 2,
            "σ(p) on the line zp"
        );
        // σ⁻¹(σ(p)) = 2p0·p (docs/math/quadrics.md, "The map δ onto the sphere")
        if !p[0].is_zero() {
            assert_eq!(
                sigma_inverse(&s).unwrap(),
                scale(&(r(2) * p[0].clone()), &p)
            );
        }
    }
    assert!(matches!(
        sigma(&h([1, 2, 3, 4])),
        Err(QuadricError::NotInPlane { .. })
    ));
}

/// Satz 3 (11), corrected (docs/math/quadrics.md, "The map δ onto the sphere"): δ = σ∘ϑ holds only up to the factor p0²+p3²,
/// σ(ϑ(p)) = (p0²+p3²)·δ(p); the paper's proof ϑ = σ⁻¹∘δ holds up to the factor 2.
#[test]
fn satz_3_delta_is_sigma_after_theta_up_to_a_factor() {
    let certs = stereographic::certify_identities::<Rational>();
    let s3 = certs
        .iter()
        .find(|c| c.property.starts_with("Satz 3"))
        .unwrap();
    assert!(s3.holds, "{s3}");
    let inv = certs
        .iter()
        .find(|c| c.property.starts_with("σ⁻¹(δ(p))"))
        .unwrap();
    assert!(inv.holds, "{inv}");
    // the factor matters: δ(p) and σ(ϑ(p)) differ by p0²+p3² ≠ 1 in general
    let p = h([1, 2, 3, 1]);
    let st = sigma(&theta(&p).unwrap()).unwrap();
    assert_eq!(st, scale(&r(2), &delta(&p)));
    // ϑ vanishes on the fibre over z (p0 = p3 = 0), δ does not
    assert!(matches!(
        theta(&h([0, 1, 2, 0])),
        Err(QuadricError::Exceptional { .. })
    ));
    assert!(parallel(&delta(&h([0, 1, 2, 0])), &h([1, 0, 0, 1])));
}

/// Lemma 4 (12): the preimage of p ∈ P under ϑ (and of k = σ(p) under δ) is the line
/// λ(p0,p1,p2,0) + μ(0,p2,−p1,p0), and δ(λa+μJa) = 2(k0−k3)(λ²+μ²)·k (docs/math/quadrics.md, "The map δ onto the sphere").
#[test]
fn lemma_4_projecting_lines_12() {
    let mut g = Lcg(3);
    for _ in 0..20 {
        let k = delta(&g.hom());
        let [a, b] = delta_fibre(&k).unwrap();
        if k[0] != k[3] {
            assert_eq!(a, sigma_inverse(&k).unwrap());
            assert_eq!(
                b,
                [
                    r(0),
                    k[2].clone(),
                    -k[1].clone(),
                    k[0].clone() - k[3].clone()
                ]
            );
            assert_eq!(b, fibre_rotation(&a));
            let c = r(2) * (k[0].clone() - k[3].clone());
            for (l, m) in [(1, 0), (0, 1), (2, -3), (-1, 5)] {
                let x = add(&scale(&r(l), &a), &scale(&r(m), &b));
                assert_eq!(delta(&x), scale(&(c.clone() * r(l * l + m * m)), &k));
                assert_eq!(
                    theta(&x).unwrap(),
                    scale(&(a[0].clone() * r(l * l + m * m)), &a)
                );
            }
        }
    }
    // the fibre over z (docs/math/quadrics.md, "The map δ onto the sphere")
    let [a, b] = delta_fibre(&h([1, 0, 0, 1])).unwrap();
    assert_eq!(rank(&[a, b, h([0, 1, 0, 0]), h([0, 0, 1, 0])]), 2);
    let certs = stereographic::certify_identities::<Rational>();
    for name in [
        "Lemma 4: ϑ(Jp)",
        "Lemma 4: ϑ̂",
        "Lemma 4 (12)",
        "J² = −I",
        "δ(Jp)",
        "δ̂(p, Jp)",
    ] {
        let c = certs.iter().find(|c| c.property.starts_with(name)).unwrap();
        assert!(c.holds, "{c}");
    }
}

/// A complex number as a pair, for (13)/(14).
type C = (Rational, Rational);
fn cmul(a: &C, b: &C) -> C {
    (
        a.0.clone() * b.0.clone() - a.1.clone() * b.1.clone(),
        a.0.clone() * b.1.clone() + a.1.clone() * b.0.clone(),
    )
}
fn cadd(a: &C, b: &C) -> C {
    (a.0.clone() + b.0.clone(), a.1.clone() + b.1.clone())
}

/// Satz 5 (13), (14): every projecting line meets both conjugate-imaginary focal lines
/// ξ(1,0,0,±i) + ζ(0,1,∓i,0) (at λ = 1, μ = ±i), which lie on the absolute quadric
/// Σxᵢ² = 0: the congruence is elliptic and the lines are Clifford parallels.
#[test]
fn satz_5_focal_lines_13_on_the_absolute_quadric_14() {
    let mut g = Lcg(5);
    let i: C = (r(0), r(1));
    let re = |x: &Rational| -> C { (x.clone(), r(0)) };
    for _ in 0..10 {
        let p = g.hom();
        let a = [p[0].clone(), p[1].clone(), p[2].clone(), r(0)];
        let ja = fibre_rotation(&a);
        for sgn in [1i64, -1] {
            let mu: C = (r(0), r(sgn));
            // X = a + μ Ja
            let x: Vec<C> = (0..4)
                .map(|k| cadd(&re(&a[k]), &cmul(&mu, &re(&ja[k]))))
                .collect();
            // ξ = p0, ζ = p1 ± i p2; focal line ξ(1,0,0,±i) + ζ(0,1,∓i,0)
            let xi = re(&p[0]);
            let zeta = cadd(&re(&p[1]), &cmul(&(r(0), r(sgn)), &re(&p[2])));
            let e1: [C; 4] = [(r(1), r(0)), (r(0), r(0)), (r(0), r(0)), (r(0), r(sgn))];
            let e2: [C; 4] = [(r(0), r(0)), (r(1), r(0)), (r(0), r(-sgn)), (r(0), r(0))];
            for k in 0..4 {
                assert_eq!(x[k], cadd(&cmul(&xi, &e1[k]), &cmul(&zeta, &e2[k])), "(13)");
            }
            // (14): Σ x_k² = 0 on the focal line
            let s = (0..4).fold((r(0), r(0)), |s, k| cadd(&s, &cmul(&x[k], &x[k])));
            assert_eq!(s, (r(0), r(0)), "(14)");
        }
        let _ = &i;
    }
}

/// Folgerung 6: ϑ maps every point to the intersection of its projecting line with P:
/// ϑ(p) = p0·p − p3·Jp.
#[test]
fn folgerung_6_theta_is_a_net_projection() {
    let mut g = Lcg(6);
    for _ in 0..20 {
        let p = g.hom();
        if p[0].is_zero() && p[3].is_zero() {
            continue;
        }
        let t = theta(&p).unwrap();
        let jp = fibre_rotation(&p);
        assert_eq!(t, add(&scale(&p[0], &p), &scale(&(-p[3].clone()), &jp)));
        assert!(t[3].is_zero());
    }
}

/// §2 property list, 1st bullet, and docs/math/quadrics.md, "Preimage quadrics": the ϑ-preimage of a circle
/// α(X1²+X2²)+βX0X1+γX0X2+εX0² = 0 is the quadric
/// α(p1²+p2²)+β(p0p1−p2p3)+γ(p0p2+p1p3)+ε(p0²+p3²) = 0 (times p0²+p3²), of determinant
/// (4αε−β²−γ²)²/16: a one-sheet hyperboloid for a real circle, a hyperbolic paraboloid
/// for a line (α = 0, a circle through z on K).
#[test]
fn circle_preimages_are_hyperboloids_and_line_preimages_paraboloids() {
    let theta_map = stereographic::theta_map::<Rational>();
    let f03: Mat4<Rational> = [h([1, 0, 0, 0]), h([0; 4]), h([0; 4]), h([0, 0, 0, 1])];
    for (al, be, ga, ep, kind) in [
        (1, 0, 0, -4, QuadricKind::HyperboloidOneSheet),
        (2, 3, -1, -5, QuadricKind::HyperboloidOneSheet),
        (1, -2, 4, 1, QuadricKind::HyperboloidOneSheet),
        (0, 1, 2, 3, QuadricKind::HyperbolicParaboloid),
        (0, 0, 1, -7, QuadricKind::HyperbolicParaboloid),
    ] {
        let (al, be, ga, ep) = (r(al), r(be), r(ga), r(ep));
        let m = circle_preimage_quadric(&al, &be, &ga, &ep);
        let c = plane_circle_matrix(&al, &be, &ga, &ep);
        let cert = theta_map.certify_pullback(&c, &f03, &m, "circle(ϑ(p)) ≡ (p0²+p3²)·quadric(p)");
        assert!(cert.holds, "{cert}");
        let quadric = Quadric::from_matrix(m.clone()).unwrap();
        assert_eq!(quadric.kind(), kind);
        let rows: Vec<Vec<Rational>> = m.iter().map(|r| r.to_vec()).collect();
        let d = det_rows(&rows);
        let w = r(4) * al.clone() * ep.clone() - be.clone() * be.clone() - ga.clone() * ga.clone();
        assert_eq!(d, w.clone() * w / r(16));
    }
}
fn det_rows(m: &[Vec<Rational>]) -> Rational {
    let rows: Vec<Hom<Rational>> = m
        .iter()
        .map(|r| [r[0].clone(), r[1].clone(), r[2].clone(), r[3].clone()])
        .collect();
    det4([&rows[0], &rows[1], &rows[2], &rows[3]])
}

/// §2 property list, 2nd bullet: a non-projecting line maps to a circle on K (a conic of
/// degree 2 whose control points span a plane; docs/math/quadrics.md, "Curves and patches under δ", special case n = 1).
#[test]
fn lines_map_to_circles() {
    let mut g = Lcg(8);
    for _ in 0..10 {
        let (a, b) = (g.hom(), g.hom());
        if rank(&[a.clone(), b.clone()]) < 2 {
            continue;
        }
        let line = BezierCurve::from_homogeneous(vec![a.to_vec(), b.to_vec()]).unwrap();
        let img = curve_image(&Delta, &line).unwrap();
        assert_all(&img.certify());
        let pts: Vec<Hom<Rational>> = img
            .image()
            .control_points()
            .map(|p| [p[0].clone(), p[1].clone(), p[2].clone(), p[3].clone()])
            .collect();
        assert!(rank(&pts) <= 3, "the image circle is planar");
    }
    // a projecting line maps to a single point
    let [a, b] = delta_fibre(&delta(&h([1, 2, 3, 4]))).unwrap();
    let fib = BezierCurve::from_homogeneous(vec![a.to_vec(), b.to_vec()]).unwrap();
    let img = curve_image(&Delta, &fib).unwrap();
    let pts: Vec<Hom<Rational>> = img
        .image()
        .control_points()
        .map(|p| [p[0].clone(), p[1].clone(), p[2].clone(), p[3].clone()])
        .collect();
    assert_eq!(rank(&pts), 1);
}

/// §2 property list, 3rd bullet: every plane contains exactly one projecting line, and the
/// lines of the plane map to the circles through one point (the image of that line).
#[test]
fn every_plane_contains_one_projecting_line_and_its_lines_map_to_a_circle_bundle() {
    let mut g = Lcg(9);
    for _ in 0..8 {
        let plane = g.hom();
        let [fa, fb] = Delta.fibre_in_plane(&plane).unwrap();
        let k = delta(&add(&fa, &fb));
        assert!(
            parallel(&delta(&fa), &k) && parallel(&delta(&fb), &k),
            "a projecting line"
        );
        // three lines of the plane; their image circles pass through k
        let basis = plane_basis(&plane);
        for (s, t) in [(1, 2), (0, 1), (2, 0)] {
            let (p1, p2) = (&basis[s], &basis[t]);
            let line =
                BezierCurve::from_homogeneous(vec![p1.to_vec(), add(p2, p1).to_vec()]).unwrap();
            let img = curve_image(&Delta, &line).unwrap();
            let pts: Vec<Hom<Rational>> = img
                .image()
                .control_points()
                .map(|p| [p[0].clone(), p[1].clone(), p[2].clone(), p[3].clone()])
                .collect();
            let mut all = pts.clone();
            all.push(k.clone());
            assert!(rank(&all) <= 3, "k lies in the plane of the image circle");
        }
    }
}
fn plane_basis(plane: &Hom<Rational>) -> Vec<Hom<Rational>> {
    // three independent solutions of planeᵀx = 0
    let piv = (0..4).find(|&i| !plane[i].is_zero()).unwrap();
    (0..4)
        .filter(|&j| j != piv)
        .map(|j| {
            let mut v = [r(0), r(0), r(0), r(0)];
            v[j] = plane[piv].clone();
            v[piv] = -plane[j].clone();
            v
        })
        .collect()
}

/// §2 (interpolation is a linear problem; lower degree than with σ), docs/math/quadrics.md, "Interpolation on the sphere": five
/// points on K are interpolated by a unique δ-quartic (solution space of dimension 2,
/// {(aI+bJ)x}); a σ-preimage (planar, p3 = 0) of degree 2 cannot meet them, it needs
/// degree 3 (a sextic on K).
#[test]
fn interpolation_is_linear_and_needs_lower_degree_than_sigma() {
    let pts = [
        h([1, 0, 0, 1]),
        h([1, 1, 0, 0]),
        h([1, 0, 1, 0]),
        h([3, 2, 2, 1]),
        h([9, 4, -4, 7]),
    ];
    for p in &pts {
        assert!(quad(&sphere_matrix(), p).is_zero());
    }
    let params: Vec<Rational> = (0..5).map(|i| q(i, 4)).collect();
    let it = interpolate(&Delta, &pts, &params, 2).unwrap();
    assert_eq!(it.degree(), 4);
    assert_eq!(it.dimension(), 2);
    assert_eq!(it.free_parameters(), 0);
    assert_all(&it.certify());
    // the two basis solutions give the same sphere curve (J-orbit)
    let m1 = it.member(&Delta, &[r(1), r(0)]).unwrap();
    let m2 = it.member(&Delta, &[r(2), r(-3)]).unwrap();
    let ok = rcagd_geom::certify::curves_agree(m1.image(), m2.image()).unwrap();
    assert!(ok.holds, "{ok}");
    // σ: preimage in the plane p3 = 0
    let plane = h([0, 0, 0, 1]);
    assert!(matches!(
        interpolate_in_plane(&Delta, &pts, &params, 2, &plane),
        Err(QuadricError::NoInterpolant { .. })
    ));
    let s = interpolate_in_plane(&Delta, &pts, &params, 3, &plane).unwrap();
    assert_eq!(s.degree(), 6);
    assert_all(&s.certify());
}

/// Satz 1 (curves): every irreducible curve of degree 2n on K is δ of a curve of degree
/// n. Checked on σ-images (circles and quartics built independently of δ's interpolation)
/// and on δ-images; the preimage is recovered up to the fibre rotation.
#[test]
fn satz_1_curves_have_preimages_of_half_degree() {
    // σ-image of a planar conic: a quartic on K
    let planar = curve(&[[1, 0, 1, 0], [2, 1, -1, 0], [1, 3, 2, 0]]);
    let y = curve_image(&Delta, &planar).unwrap().into_image();
    let pre = curve_preimage(&Delta, &y).unwrap();
    assert_eq!(pre.preimage.degree(), 2);
    assert_all(&pre.certify());
    // a rational circle of K (the equator) from its conic parametrization
    let equator = BezierCurve::from_homogeneous(vec![
        vec![r(1), r(1), r(0), r(0)],
        vec![r(1), r(1), r(1), r(0)],
        vec![r(2), r(0), r(2), r(0)],
    ])
    .unwrap();
    assert!(certify_curve_on_quadric(&equator, &sphere_matrix(), "equator").holds);
    let pre = curve_preimage(&Delta, &equator).unwrap();
    assert_eq!(pre.preimage.degree(), 1);
    assert_all(&pre.certify());
}

/// docs/math/quadrics.md, Errata J3 (Satz 1, surface half, unverified): `patch_preimage` decides per patch.
/// A δ-image of a bilinear patch has a bilinear preimage; the biquadratic patch of
/// revolution on K (meridian arc × parallel arc) has one too, consistent with Satz 1.
#[test]
fn satz_1_surfaces_is_decided_per_patch() {
    let bil = BezierPatch::from_homogeneous(vec![
        vec![h([1, 2, 0, 1]).to_vec(), h([3, 0, -1, 1]).to_vec()],
        vec![h([2, -1, 1, 0]).to_vec(), h([1, 1, 3, -2]).to_vec()],
    ])
    .unwrap();
    let y = patch_image(&Delta, &bil).unwrap().into_image();
    let pre = patch_preimage(&Delta, &y).unwrap();
    assert_eq!(pre.preimage.degree(), (1, 1));
    assert_all(&pre.certify());
    // surface of revolution: meridian (w, r, z) on r² + z² = w², parallel (w', c, s)
    let meridian = [[r(1), r(0), r(-1)], [r(1), r(1), r(-1)], [r(2), r(2), r(0)]];
    let parallel_arc = [
        [r(1), r(1), r(0)],
        [q(3, 5), q(3, 5), q(4, 5)],
        [r(1), q(-7, 25), q(24, 25)],
    ];
    let net: Vec<Vec<Vec<Rational>>> = meridian
        .iter()
        .map(|m| {
            parallel_arc
                .iter()
                .map(|p| {
                    vec![
                        m[0].clone() * p[0].clone(),
                        m[1].clone() * p[1].clone(),
                        m[1].clone() * p[2].clone(),
                        m[2].clone() * p[0].clone(),
                    ]
                })
                .collect()
        })
        .collect();
    let rev = BezierPatch::from_homogeneous(net).unwrap();
    assert!(certify_patch_on_quadric(&rev, &sphere_matrix(), "revolution patch on K").holds);
    let pre = patch_preimage(&Delta, &rev).unwrap();
    assert_eq!(pre.preimage.degree(), (1, 1));
    assert_all(&pre.certify());
}

/// Satz 7 (docs/math/quadrics.md, "Biquadratic sphere patches and the Miquel configuration"): the δ-image of a bilinear patch is a biquadratic patch on K
/// whose corners p_i and second circle intersections q_i satisfy det[p1,q2,p3,q4] = 0 and
/// det[q1,p2,q3,p4] = 0 (Miquel), verified on random bilinear patches, including the
/// degenerate small-integer cases (tangent circles, q_i = p_j).
#[test]
fn satz_7_miquel_on_random_bilinear_patches() {
    let mut g = Lcg(7);
    let mut done = 0;
    let mut nontrivial = 0;
    while done < 12 {
        let c = [g.hom(), g.hom(), g.hom(), g.hom()];
        let Ok(bp) = BiquadraticPatch::from_bilinear(
            &Delta,
            c[0].clone(),
            c[1].clone(),
            c[2].clone(),
            c[3].clone(),
        ) else {
            continue;
        };
        assert_all(&bp.certify());
        let (r1, r2) = bp.miquel_residuals();
        assert!(r1.is_zero() && r2.is_zero());
        let p = bp.corners();
        if !det4([&p[0], &p[1], &p[2], &p[3]]).is_zero() {
            nontrivial += 1; // the corners themselves are not concyclic
        }
        done += 1;
    }
    assert!(nontrivial > 0);
    // tangent circles: q_i = p_i
    let bp = BiquadraticPatch::from_bilinear(
        &Delta,
        h([1, 0, 0, 0]),
        h([0, 1, 0, 0]),
        h([0, 0, 1, 0]),
        h([0, 0, 0, 1]),
    );
    if let Ok(bp) = bp {
        assert_all(&bp.certify());
    }
}

/// Converse of Satz 7 (docs/math/quadrics.md, "Biquadratic sphere patches and the Miquel configuration"): from corners and boundary circles in Miquel position
/// the chain construction gives a bilinear preimage and closes (c00' ∥ c00); the weight
/// of c11 is a free parameter; non-Miquel data are refused with the residual.
#[test]
fn converse_of_satz_7_from_a_miquel_configuration() {
    let mut g = Lcg(17);
    let mut tested = 0;
    while tested < 5 {
        let c = [g.hom(), g.hom(), g.hom(), g.hom()];
        let Ok(bp) = BiquadraticPatch::from_bilinear(
            &Delta,
            c[0].clone(),
            c[1].clone(),
            c[2].clone(),
            c[3].clone(),
        ) else {
            continue;
        };
        let p = bp.corners().clone();
        let qs = bp.second_points().clone();
        if (0..4).any(|i| {
            parallel(&p[i], &qs[i])
                || parallel(&p[(i + 1) % 4], &qs[i])
                || parallel(&p[i], &qs[(i + 3) % 4])
        }) {
            continue; // tangent circles: no third point from the q's
        }
        for w in [r(1), q(3, 2)] {
            let back =
                BiquadraticPatch::from_miquel_points(&Delta, p.clone(), qs.clone(), w).unwrap();
            assert_all(&back.certify());
            for i in 0..4 {
                assert!(parallel(&back.corners()[i], &p[i]));
                assert!(parallel(&back.second_points()[i], &qs[i]));
            }
        }
        // move p3 along its circle C23 … no: replace it by another sphere point
        let mut bad = p.clone();
        bad[2] = delta(&g.hom());
        let (r1, _) = miquel_residuals(&bad, &qs);
        if !r1.is_zero() {
            let e = [qs[0].clone(), qs[1].clone(), qs[2].clone(), qs[3].clone()];
            match BiquadraticPatch::from_corners(&Delta, bad, e, r(1)) {
                Err(QuadricError::MiquelFails { residual, .. }) => assert_ne!(residual, "0"),
                Err(QuadricError::Degenerate(_)) => {}
                other => panic!("expected MiquelFails, got {other:?}"),
            }
        }
        tested += 1;
    }
}

// ---------------------------------------------------------------------------------------
// §3: ψ, τ, α

/// (6), (8), (15): ψ(q) lies on H: h0h3 = h1h2; Satz 8 (16): ψ on R (q3 = q0) is the
/// stereographic projection τ from c = (0,0,0,1); Satz 9 (17), corrected:
/// τ(α(q)) = q0q3·ψ(q); τ⁻¹(ψ(q)) = α(q).
#[test]
fn formulas_15_to_17_and_satz_8_9() {
    assert_all(&paraboloid::certify_identities::<Rational>());
    let c = h([0, 0, 0, 1]);
    let mut g = Lcg(11);
    for _ in 0..20 {
        let qq = g.hom();
        let hh = psi(&qq);
        assert!(quad(&paraboloid_matrix(), &hh).is_zero());
        let mut rq = qq.clone();
        rq[3] = rq[0].clone();
        if let Ok(t) = tau(&rq) {
            assert_eq!(t, psi(&rq));
            assert!(
                rank(&[c.clone(), rq.clone(), t.clone()]) <= 2,
                "τ(q) on the line cq"
            );
        }
        if let Ok(a) = alpha(&qq) {
            match tau(&a) {
                Ok(t) => assert_eq!(t, scale(&(qq[0].clone() * qq[3].clone()), &hh)),
                // τ vanishes at α(q) exactly when the factor q0q3 does
                Err(_) => assert!((qq[0].clone() * qq[3].clone()).is_zero()),
            }
            assert_eq!(tau_inverse(&hh).unwrap(), a);
        }
    }
}

/// Lemma 10 (18), Satz 11: the ψ-preimage of h is the line λ(h0,h1,h2,h0) + μ(h0,h1,0,0),
/// with α(λa+μb) = λ(λ+μ)q0·(q0,q1,q2,q0) and ψ(λa+μb) = λ(λ+μ)h0·h (docs/math/quadrics.md, "The map ψ onto the hyperbolic paraboloid"); every
/// such line meets the focal lines (1 λ 0 0) and (0 0 1 μ) (a hyperbolic congruence).
#[test]
fn lemma_10_and_satz_11_hyperbolic_congruence() {
    let mut g = Lcg(12);
    for _ in 0..20 {
        let hh = psi(&g.hom());
        let Ok([a, b]) = psi_fibre_seed(&hh) else {
            continue;
        };
        for (l, m) in [(1, 0), (2, 1), (-1, 3), (3, -5)] {
            let x = add(&scale(&r(l), &a), &scale(&r(m), &b));
            let f = r(l * (l + m)) * hh[0].clone();
            assert_eq!(psi(&x), scale(&f, &hh));
            let qv = a.clone();
            let expect = scale(&(r(l * (l + m)) * qv[0].clone()), &qv);
            let al = alpha(&x);
            if f.is_zero() {
                continue;
            }
            assert_eq!(al.unwrap(), expect);
        }
        // Satz 11: the line meets both focal lines
        let [u, v] = psi_fibre(&hh).unwrap();
        assert!(
            u[2].is_zero() && u[3].is_zero(),
            "(u0,u1,0,0) on the x-axis (1 λ 0 0)"
        );
        assert!(
            v[0].is_zero() && v[1].is_zero(),
            "(0,0,v1,v0) on the ideal line (0 0 1 μ)"
        );
        assert_eq!(
            rank(&[a.clone(), b.clone(), u, v]),
            2,
            "same line as Lemma 10"
        );
    }
    assert!(matches!(
        tau_inverse(&h([0, 0, 0, 1])),
        Err(QuadricError::Exceptional { .. })
    ));
}

/// docs/math/quadrics.md, Errata J1 (§3 property list, 2nd bullet): the image of a non-projecting line is a
/// conic on H under **ψ** (printed: δ). The ψ-image lies on H, is planar, and is not on K.
#[test]
fn erratum_e1_line_images_are_conics_on_h_under_psi() {
    let line = curve(&[[1, 2, 0, 1], [2, -1, 3, 1]]);
    let img = curve_image(&Psi, &line).unwrap();
    assert_all(&img.certify());
    let pts: Vec<Hom<Rational>> = img
        .image()
        .control_points()
        .map(|p| [p[0].clone(), p[1].clone(), p[2].clone(), p[3].clone()])
        .collect();
    assert!(rank(&pts) <= 3);
    assert!(!certify_curve_on_quadric(img.image(), &sphere_matrix(), "on K").holds);
    // α maps the line to a hyperbola with axis-parallel asymptotes in R: through (0,1,0,0)
    // and (0,0,1,0) in the plane q3 = q0
    let a0 = alpha(&h([1, 2, 0, 1])).unwrap();
    assert_eq!(a0[0], a0[3]);
}

/// docs/math/quadrics.md, Errata J2 (§3 property list, 1st bullet): the α-preimage of a hyperbola with
/// axis-parallel asymptotes is a **hyperbolic paraboloid** (printed: one-sheet
/// hyperboloid): a q0q3 + b q1q3 + c q0q2 + d q1q2 = 0 always contains the focal line
/// q0 = q1 = 0 and is touched by the plane at infinity. The line case (2nd half of the
/// bullet) is a hyperbolic paraboloid too, as printed.
#[test]
fn erratum_e2_conic_preimages_are_hyperbolic_paraboloids() {
    let alpha_map = paraboloid::alpha_map::<Rational>();
    let f03: Mat4<Rational> = {
        let mut m = [h([0; 4]), h([0; 4]), h([0; 4]), h([0; 4])];
        m[0][3] = q(1, 2);
        m[3][0] = q(1, 2);
        m
    };
    for (a, b, c, d) in [
        (-1, 0, 0, 1),
        (2, 1, -3, 1),
        (-4, 2, 1, -1),
        (1, 1, 1, 0),
        (0, 2, 3, 0),
    ] {
        let (a, b, c, d) = (r(a), r(b), r(c), r(d));
        let m = conic_preimage_quadric(&a, &b, &c, &d);
        let conic = plane_conic_matrix(&a, &b, &c, &d);
        let cert = alpha_map.certify_pullback(&conic, &f03, &m, "conic(α(q)) ≡ q0q3·quadric(q)");
        assert!(cert.holds, "{cert}");
        let quadric = Quadric::from_matrix(m).unwrap();
        let kind = quadric.kind();
        assert_ne!(kind, QuadricKind::HyperboloidOneSheet);
        if !(d.is_zero() && (b.is_zero() || c.is_zero())) && quadric.signature().0 == 4 {
            assert_eq!(kind, QuadricKind::HyperbolicParaboloid);
        }
        // contains the focal line q0 = q1 = 0
        for x in [h([0, 0, 1, 0]), h([0, 0, 0, 1]), h([0, 0, 2, -3])] {
            assert!(quadric.residual(&x).is_zero());
        }
    }
}

// ---------------------------------------------------------------------------------------
// Schlussbemerkung / docs/math/quadrics.md, "Other quadrics": other quadrics

/// docs/math/quadrics.md, "Other quadrics": the projective maps K → ellipsoid diag(1,a,b,c), K → two-sheet
/// hyperboloid (k0 ↔ k3), K → elliptic paraboloid ((x0,x3) = (k0−k3, k0+k3)), and
/// H → one-sheet hyperboloid map the quadrics onto each other exactly, and carry curves
/// (degree unchanged) onto the target.
#[test]
fn notes_000_11_transfers() {
    let x = curve(&[[1, 0, 1, 2], [2, 1, -1, 0], [1, 3, 0, 1]]);
    for (name, params, psi_source) in [
        ("ellipsoid", vec![r(2), q(1, 3), r(5)], false),
        ("hyperboloid_two_sheets", vec![], false),
        ("elliptic_paraboloid", vec![], false),
        ("hyperboloid_one_sheet", vec![], true),
    ] {
        let (a, src, dst) = seed_transfer(name, &params).unwrap();
        assert!(certify_transfer(&a, &src, &dst).holds, "{name}");
        let img = if psi_source {
            curve_image(&Psi, &x)
        } else {
            curve_image(&Delta, &x)
        }
        .unwrap();
        let moved = transfer_curve(&a, img.image()).unwrap();
        assert_eq!(moved.degree(), 4);
        assert!(
            certify_curve_on_quadric(&moved, dst.matrix(), name).holds,
            "{name}"
        );
    }
}

/// Schlussbemerkung: the construction carries over to every quadric with a rational
/// point through a rational normal form; for the unit sphere it is δ/2, and degenerate
/// quadrics use a parabolic congruence with an exceptional line.
#[test]
fn schlussbemerkung_all_quadrics() {
    let half = |x: Rational| x / r(2);
    let proj = Quadric::<Rational>::unit_sphere().projection().unwrap();
    let p = h([1, -2, 3, 5]);
    assert_eq!(proj.apply(&p), delta(&p).map(half));
    let cone = Quadric::cone(r(1), r(2), r(1))
        .unwrap()
        .projection()
        .unwrap();
    assert_all(&cone.certify());
    // the exceptional line p1 = p2 = 0 maps to zero
    assert!(cone.apply(&h([1, 0, 0, 1])).iter().all(|x| x.is_zero()));
}

/// §3 ("Interpolation auf H … analog"): interpolation on H by the decoupled linear problem
/// of ψ. Three points on one generator need only a line (degree 1), which the even-degree
/// ψ-images (degree 2n) cannot show; five general points need degree 4 = 2 + 2.
#[test]
fn interpolation_on_h_of_lowest_degree() {
    use rcagd::quadric::paraboloid::interpolate_segre;
    // the generator u = (1, 2) fixed: points (v0, 2v0, v1, 2v1)
    let pts = [h([1, 2, 0, 0]), h([1, 2, 1, 2]), h([1, 2, 3, 6])];
    let params = [r(0), q(1, 2), r(1)];
    let it = interpolate_segre(&pts, &params).unwrap();
    assert_eq!(it.degrees(), (0, 1));
    assert_eq!(it.curve().degree(), 1);
    assert_all(&it.certify());
    // general points: ψ-images of random points
    let mut g = Lcg(21);
    let pts: Vec<Hom<Rational>> = (0..5).map(|_| psi(&g.hom())).collect();
    let params: Vec<Rational> = (0..5).map(|i| q(i, 4)).collect();
    let it = interpolate_segre(&pts, &params).unwrap();
    assert_eq!(it.degrees(), (2, 2));
    assert_all(&it.certify());
    let via_psi = interpolate(&Psi, &pts, &params, 2).unwrap();
    assert_all(&via_psi.certify());
}
