//! Property tests for rational Bézier curves and patches with random exact inputs:
//! subdivision, degree elevation, Möbius reparametrization, polynomial maps,
//! derivatives and `f64` evaluation agree with the exact definitions; circle arcs
//! certify on their quadric; bad input gives errors, not panics.

use proptest::prelude::*;
use rcagd_algebra::bernstein;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Poly, Rational, Scalar};
use rcagd_geom::certify;
use rcagd_geom::polymap::PolyMap;
use rcagd_geom::{BezierCurve, BezierPatch, GeomError};

type Q = Rational;

fn q(p: i64, d: i64) -> Q {
    Q::from_ratio(p, d)
}

fn zero() -> Q {
    Q::from(0)
}

fn one() -> Q {
    Q::from(1)
}

// ---------------------------------------------------------------------------------
// Strategies
// ---------------------------------------------------------------------------------

/// A small rational `p/q`, `|p| ≤ 12`, `1 ≤ q ≤ 6`.
fn small_rational() -> impl Strategy<Value = Q> {
    (-12i64..=12, 1i64..=6).prop_map(|(p, d)| q(p, d))
}

/// A positive weight `p/q`, `1 ≤ p ≤ 6`, `1 ≤ q ≤ 4`.
fn weight() -> impl Strategy<Value = Q> {
    (1i64..=6, 1i64..=4).prop_map(|(p, d)| q(p, d))
}

/// A parameter `k/den` in `[0, 1]`.
fn unit_param() -> impl Strategy<Value = Q> {
    (1i64..=9).prop_flat_map(|den| (0..=den).prop_map(move |k| q(k, den)))
}

/// A parameter `k/den` strictly inside `(0, 1)`.
fn inner_param() -> impl Strategy<Value = Q> {
    (2i64..=9).prop_flat_map(|den| (1..den).prop_map(move |k| q(k, den)))
}

/// A curve of degree 1..=5 in dimension 2 or 3 with positive weights.
fn curve() -> impl Strategy<Value = BezierCurve<Q>> {
    (1usize..=5, 2usize..=3).prop_flat_map(|(n, d)| {
        (
            prop::collection::vec(prop::collection::vec(small_rational(), d), n + 1),
            prop::collection::vec(weight(), n + 1),
        )
            .prop_map(|(pts, ws)| BezierCurve::from_points_weights(&pts, &ws).expect("valid"))
    })
}

/// A patch of bidegree up to (3, 3) in dimension 3 with positive weights.
fn patch() -> impl Strategy<Value = BezierPatch<Q>> {
    (1usize..=3, 1usize..=3).prop_flat_map(|(m, n)| {
        (
            prop::collection::vec(
                prop::collection::vec(prop::collection::vec(small_rational(), 3), n + 1),
                m + 1,
            ),
            prop::collection::vec(prop::collection::vec(weight(), n + 1), m + 1),
        )
            .prop_map(|(net, ws)| BezierPatch::from_points_weights(&net, &ws).expect("valid"))
    })
}

/// A homogeneous polynomial map of degree `k ∈ 1..=3` from `nvars` homogeneous
/// coordinates to 3 or 4: each component a sum of up to four random monomials.
fn polymap(nvars: usize) -> impl Strategy<Value = Vec<MPoly<Q>>> {
    (1usize..=3, 3usize..=4).prop_flat_map(move |(k, outputs)| {
        let term = (prop::collection::vec(0..nvars, k), small_rational());
        let component = prop::collection::vec(term, 1..=4).prop_map(move |terms| {
            let terms = terms
                .into_iter()
                .map(|(vars, c)| {
                    let mut e = vec![0u32; nvars];
                    for v in vars {
                        e[v] += 1;
                    }
                    (e, c)
                })
                .collect();
            MPoly::from_terms(nvars, terms).expect("valid terms")
        });
        prop::collection::vec(component, outputs)
    })
}

fn config() -> ProptestConfig {
    ProptestConfig::with_cases(48)
}

/// The nearest `f64` (the trait method, not dashu's inherent one).
fn fl(x: &Q) -> f64 {
    Scalar::to_f64(x)
}

fn max_abs(v: &[Q]) -> f64 {
    v.iter().map(|x| fl(&x.abs())).fold(0.0, f64::max)
}

// ---------------------------------------------------------------------------------
// Curves
// ---------------------------------------------------------------------------------

proptest! {
    #![proptest_config(config())]

    #[test]
    fn subdivision_halves_are_the_curve_reparametrized(c in curve(), t in inner_param(), s in unit_param()) {
        let (left, right) = c.subdivide(&t).expect("finite");
        // Exactly the affine restrictions, as control points and as parametrizations.
        prop_assert_eq!(&left, &c.restrict(&zero(), &t).expect("non-empty"));
        prop_assert_eq!(&right, &c.restrict(&t, &one()).expect("non-empty"));
        prop_assert!(certify::curves_agree(&left, &c.restrict(&zero(), &t).expect("non-empty")).expect("dims").holds);
        prop_assert_eq!(left.eval(&s).expect("w > 0"), c.eval(&(t.clone() * s.clone())).expect("w > 0"));
        let mapped = t.clone() + (one() - t.clone()) * s.clone();
        prop_assert_eq!(right.eval(&s).expect("w > 0"), c.eval(&mapped).expect("w > 0"));
        // The halves meet.
        prop_assert_eq!(left.control_points().last(), right.control_points().next());
    }

    #[test]
    fn degree_elevation_keeps_the_parametrization(c in curve(), r in 1usize..=3, s in unit_param()) {
        let e = c.elevate(r);
        prop_assert_eq!(e.degree(), c.degree() + r);
        prop_assert!(e.same_parametrization(&c));
        prop_assert!(certify::curves_agree(&c, &e).expect("dims").holds);
        prop_assert_eq!(e.eval_homogeneous(&s), c.eval_homogeneous(&s));
        prop_assert_eq!(BezierCurve::from_coordinate_polys(&c.coordinate_polys(), c.degree() + r).expect("fits"), e);
    }

    #[test]
    fn mobius_reparametrization_keeps_the_point_set(
        c in curve(),
        (a, b, cc, d) in (small_rational(), small_rational(), small_rational(), small_rational()),
        s in unit_param(),
    ) {
        let det = a.clone() * d.clone() - b.clone() * cc.clone();
        prop_assume!(!det.is_zero());
        let m = c.reparametrize_mobius(&a, &b, &cc, &d).expect("invertible");
        prop_assert_eq!(m.degree(), c.degree());
        let den = cc.clone() * s.clone() + d.clone();
        prop_assume!(!den.is_zero());
        let phi = (a.clone() * s.clone() + b.clone()) / den.clone();
        // Q(s) = (cs + d)ⁿ P(φ(s)) exactly, hence the same Euclidean point.
        let n = c.degree() as u32;
        let factor = (0..n).fold(one(), |acc, _| acc * den.clone());
        let expected: Vec<Q> = c.eval_homogeneous(&phi).into_iter().map(|x| x * factor.clone()).collect();
        prop_assert_eq!(m.eval_homogeneous(&s), expected);
        if let Ok(p) = c.eval(&phi) {
            prop_assert_eq!(m.eval(&s).expect("same weight up to a non-zero factor"), p);
        }
    }

    #[test]
    fn polymap_image_agrees_pointwise(c in curve(), map in curve_map(), t in small_rational()) {
        let (c, map) = (fit_dim(c, &map), map);
        let image = match c.apply_polymap(&map) {
            Ok(image) => image,
            Err(GeomError::Degree(_)) => return Ok(()), // all components cancelled
            Err(e) => return Err(TestCaseError::fail(e.to_string())),
        };
        let k = map.iter().filter_map(MPoly::total_degree).max().expect("non-zero map");
        prop_assert_eq!(image.degree(), k * c.degree());
        let x = c.eval_homogeneous(&t);
        let fx: Vec<Q> = map.iter().map(|f| f.eval(&x).expect("arity")).collect();
        prop_assert_eq!(image.eval_homogeneous(&t), fx);
    }

    #[test]
    fn derivatives_agree_with_coordinate_polynomials(c in curve(), t in unit_param(), k in 0usize..=3) {
        let polys = c.coordinate_polys();
        let h: Vec<Q> = polys.iter().map(|p| p.derivative_n(k).eval(&t)).collect();
        prop_assert_eq!(c.derivative_homogeneous(&t, k), h);
        prop_assert_eq!(c.derivative(k).degree(), c.degree().saturating_sub(k));
        // First Euclidean derivative: (X'w − Xw')/w².
        let w = polys[0].eval(&t);
        let w1 = polys[0].derivative().eval(&t);
        let expected: Vec<Q> = polys[1..]
            .iter()
            .map(|p| (p.derivative().eval(&t) * w.clone() - p.eval(&t) * w1.clone()) / (w.clone() * w.clone()))
            .collect();
        prop_assert_eq!(c.derivative_euclidean(&t, 1).expect("w > 0"), expected);
    }

    #[test]
    fn f64_evaluation_agrees_with_exact(c in curve(), t in unit_param()) {
        let f = c.to_f64();
        let tf = fl(&t);
        let exact_h = c.eval_homogeneous(&t);
        let scale_h = max_abs(c.coords());
        let mut h = vec![0.0; c.dim() + 1];
        f.eval_homogeneous_into(tf, &mut h).expect("sized");
        for (a, b) in h.iter().zip(&exact_h) {
            prop_assert!((a - fl(b)).abs() <= 1e-12 * scale_h, "{} vs {}", a, fl(b));
        }
        let exact = c.eval(&t).expect("w > 0");
        let scale = c.euclidean_control_points().expect("w > 0").iter().map(|p| max_abs(p)).fold(1.0, f64::max);
        let mut x = vec![0.0; c.dim()];
        f.eval_into(tf, &mut x).expect("w > 0");
        for (a, b) in x.iter().zip(&exact) {
            prop_assert!((a - fl(b)).abs() <= 1e-12 * scale);
        }
        // The generic de Casteljau path on f64 agrees too.
        for (a, b) in f.eval(&tf).expect("w > 0").iter().zip(&exact) {
            prop_assert!((a - fl(b)).abs() <= 1e-12 * scale);
        }
    }

    #[test]
    fn bernstein_power_round_trip(coeffs in prop::collection::vec(small_rational(), 0..=6), extra in 0usize..=3) {
        let p = Poly::new(coeffs);
        let n = p.degree().unwrap_or(0) + extra;
        let b = bernstein::to_bernstein(&p, n).expect("degree fits");
        prop_assert_eq!(b.len(), n + 1);
        prop_assert_eq!(bernstein::from_bernstein(&b), p.clone());
        prop_assert_eq!(bernstein::to_bernstein(&bernstein::from_bernstein(&b), n).expect("fits"), b);
        if let Some(d) = p.degree() {
            if d > 0 {
                prop_assert!(bernstein::to_bernstein(&p, d - 1).is_err());
            }
        }
    }

    #[test]
    fn circle_arcs_certify_exactly((a0, b0, a1, b1) in (small_rational(), small_rational(), small_rational(), small_rational()), delta in weight()) {
        // σ ∘ (line): X = (m₀² + m₁², m₀² − m₁², 2m₀m₁) with m linear in Bernstein form.
        prop_assume!(!(a0.is_zero() && b0.is_zero()));
        let polar = |a: &Q, b: &Q, c: &Q, d: &Q| -> Vec<Q> {
            vec![
                a.clone() * c.clone() + b.clone() * d.clone(),
                a.clone() * c.clone() - b.clone() * d.clone(),
                a.clone() * d.clone() + b.clone() * c.clone(),
            ]
        };
        let arc = BezierCurve::from_homogeneous(vec![
            polar(&a0, &b0, &a0, &b0),
            polar(&a0, &b0, &a1, &b1),
            polar(&a1, &b1, &a1, &b1),
        ]).expect("valid");
        let circle = vec![vec![-one(), zero(), zero()], vec![zero(), one(), zero()], vec![zero(), zero(), one()]];
        let cert = certify::curve_on_quadric(&arc, &circle).expect("3×3");
        prop_assert!(cert.holds && cert.exact, "{}", cert);
        // Perturb the middle weight: c₁ changes by −w₀δ ≠ 0.
        let mut pts: Vec<Vec<Q>> = arc.control_points().map(<[Q]>::to_vec).collect();
        pts[1][0] += delta;
        let bad = BezierCurve::from_homogeneous(pts).expect("valid");
        let cert = certify::curve_on_quadric(&bad, &circle).expect("3×3");
        prop_assert!(!cert.holds);
        prop_assert!(cert.residual.is_some());
    }
}

/// A curve-dimension-agnostic map strategy: maps on 3 or 4 homogeneous coordinates.
fn curve_map() -> impl Strategy<Value = Vec<MPoly<Q>>> {
    (3usize..=4).prop_flat_map(polymap)
}

/// Pads or truncates a curve's points to the map's number of variables.
fn fit_dim(c: BezierCurve<Q>, map: &[MPoly<Q>]) -> BezierCurve<Q> {
    let nvars = map.first().map_or(3, MPoly::nvars);
    let pts: Vec<Vec<Q>> = c
        .control_points()
        .map(|p| {
            let mut v = p.to_vec();
            v.resize(nvars, one());
            v
        })
        .collect();
    BezierCurve::from_homogeneous(pts).expect("valid")
}

// ---------------------------------------------------------------------------------
// Patches
// ---------------------------------------------------------------------------------

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn patch_subdivision_and_restriction(p in patch(), t in inner_param(), (u, v) in (unit_param(), unit_param())) {
        let (a, b) = p.subdivide_u(&t).expect("finite");
        prop_assert_eq!(&a, &p.restrict_u(&zero(), &t).expect("non-empty"));
        prop_assert_eq!(&b, &p.restrict_u(&t, &one()).expect("non-empty"));
        prop_assert_eq!(a.eval(&u, &v).expect("w > 0"), p.eval(&(t.clone() * u.clone()), &v).expect("w > 0"));
        let (c, d) = p.subdivide_v(&t).expect("finite");
        prop_assert_eq!(&c, &p.restrict_v(&zero(), &t).expect("non-empty"));
        let mapped = t.clone() + (one() - t.clone()) * v.clone();
        prop_assert_eq!(d.eval(&u, &v).expect("w > 0"), p.eval(&u, &mapped).expect("w > 0"));
        let r = p.restrict(&t, &one(), &zero(), &t).expect("non-empty");
        let uu = t.clone() + (one() - t.clone()) * u.clone();
        prop_assert_eq!(r.eval(&u, &v).expect("w > 0"), p.eval(&uu, &(t.clone() * v.clone())).expect("w > 0"));
    }

    #[test]
    fn patch_elevation_iso_curves_and_transpose(p in patch(), (ru, rv) in (0usize..=2, 0usize..=2), (u, v) in (unit_param(), unit_param())) {
        let e = p.elevate(ru, rv);
        prop_assert_eq!(e.degree(), (p.degree().0 + ru, p.degree().1 + rv));
        prop_assert!(e.same_parametrization(&p));
        prop_assert_eq!(e.eval_homogeneous(&u, &v), p.eval_homogeneous(&u, &v));
        prop_assert_eq!(p.iso_u(&u).eval_homogeneous(&v), p.eval_homogeneous(&u, &v));
        prop_assert_eq!(p.iso_v(&v).eval_homogeneous(&u), p.eval_homogeneous(&u, &v));
        prop_assert_eq!(p.transpose().eval_homogeneous(&v, &u), p.eval_homogeneous(&u, &v));
        prop_assert_eq!(p.reverse_u().reverse_v().eval_homogeneous(&(one() - u.clone()), &(one() - v.clone())), p.eval_homogeneous(&u, &v));
        let [b0, b1, b2, b3] = p.boundary_curves();
        prop_assert_eq!(b0.eval_homogeneous(&u), p.eval_homogeneous(&u, &zero()));
        prop_assert_eq!(b1.eval_homogeneous(&v), p.eval_homogeneous(&one(), &v));
        prop_assert_eq!(b2.eval_homogeneous(&u), p.eval_homogeneous(&(one() - u.clone()), &one()));
        prop_assert_eq!(b3.eval_homogeneous(&v), p.eval_homogeneous(&zero(), &(one() - v.clone())));
    }

    #[test]
    fn patch_polymap_agrees_pointwise(p in patch(), map in polymap(4), (u, v) in (small_rational(), small_rational())) {
        let image = match p.apply_polymap(&map) {
            Ok(image) => image,
            Err(GeomError::Degree(_)) => return Ok(()),
            Err(e) => return Err(TestCaseError::fail(e.to_string())),
        };
        let k = map.iter().filter_map(MPoly::total_degree).max().expect("non-zero map");
        let (m, n) = p.degree();
        prop_assert_eq!(image.degree(), (k * m, k * n));
        let x = p.eval_homogeneous(&u, &v);
        let fx: Vec<Q> = map.iter().map(|f| f.eval(&x).expect("arity")).collect();
        prop_assert_eq!(image.eval_homogeneous(&u, &v), fx);
    }

    #[test]
    fn patch_partials_agree_with_coordinate_polynomials(p in patch(), (u, v) in (unit_param(), unit_param()), (ku, kv) in (0usize..=2, 0usize..=2)) {
        let polys = p.coordinate_polys().expect("converts");
        let point = [u.clone(), v.clone()];
        let d = |f: &MPoly<Q>, a: usize, b: usize| -> MPoly<Q> {
            let fu = (0..a).fold(f.clone(), |g, _| g.partial(0));
            (0..b).fold(fu, |g, _| g.partial(1))
        };
        let h: Vec<Q> = polys.iter().map(|f| d(f, ku, kv).eval(&point).expect("2 vars")).collect();
        prop_assert_eq!(p.partial_homogeneous(&u, &v, ku, kv), h);
        // x_u = (X_u w − X w_u)/w².
        let w = polys[0].eval(&point).expect("2 vars");
        let wu = d(&polys[0], 1, 0).eval(&point).expect("2 vars");
        let expected: Vec<Q> = polys[1..]
            .iter()
            .map(|f| {
                let x = f.eval(&point).expect("2 vars");
                let xu = d(f, 1, 0).eval(&point).expect("2 vars");
                (xu * w.clone() - x * wu.clone()) / (w.clone() * w.clone())
            })
            .collect();
        prop_assert_eq!(p.partial_euclidean(&u, &v, 1, 0).expect("w > 0"), expected);
        // Mixed second partial against the Leibniz table entry.
        let table = p.partials_euclidean(&u, &v, 1, 1).expect("w > 0");
        prop_assert_eq!(&table[1][1], &p.partial_euclidean(&u, &v, 1, 1).expect("w > 0"));
    }

    #[test]
    fn patch_f64_evaluation_agrees_with_exact(p in patch(), (u, v) in (unit_param(), unit_param())) {
        let f = p.to_f64();
        let exact = p.eval(&u, &v).expect("w > 0");
        let mut x = [0.0; 3];
        f.eval_into(fl(&u), fl(&v), &mut x).expect("w > 0");
        let scale = p
            .coords()
            .chunks(4)
            .flat_map(|h| h[1..].iter().map(|c| fl(&(c.clone() / h[0].clone()).abs())))
            .fold(1.0, f64::max);
        for (a, b) in x.iter().zip(&exact) {
            prop_assert!((a - fl(b)).abs() <= 1e-12 * scale);
        }
    }
}

// ---------------------------------------------------------------------------------
// Deterministic checks
// ---------------------------------------------------------------------------------

fn pts(v: &[&[i64]]) -> Vec<Vec<Q>> {
    v.iter()
        .map(|p| p.iter().map(|&x| Q::from(x)).collect())
        .collect()
}

#[test]
fn quarter_circle_certifies_and_a_perturbed_one_fails() {
    let arc =
        BezierCurve::from_homogeneous(pts(&[&[1, 1, 0], &[1, 1, 1], &[2, 0, 2]])).expect("valid");
    let circle = pts(&[&[-1, 0, 0], &[0, 1, 0], &[0, 0, 1]]);
    let cert = certify::curve_on_quadric(&arc, &circle).expect("3×3");
    assert!(cert.holds && cert.exact, "{cert}");
    let bad =
        BezierCurve::from_homogeneous(pts(&[&[1, 1, 0], &[1, 1, 1], &[2, 0, 3]])).expect("valid");
    let cert = certify::curve_on_quadric(&bad, &circle).expect("3×3");
    assert!(!cert.holds);
    let residual = cert.residual.clone().expect("a residual");
    assert!(residual.contains("coefficient"), "{residual}");
    // A biquadratic patch on the unit sphere: σ applied to a bilinear patch (Jüttler, docs/math/quadrics.md, "Curves and patches under δ").
    let sphere = pts(&[&[-1, 0, 0, 0], &[0, 1, 0, 0], &[0, 0, 1, 0], &[0, 0, 0, 1]]);
    let forms = vec![
        pts(&[&[1, 0, 0], &[0, 1, 0], &[0, 0, 1]]),
        pts(&[&[0, 1, 0], &[1, 0, 0], &[0, 0, 0]]),
        pts(&[&[0, 0, 1], &[0, 0, 0], &[1, 0, 0]]),
        pts(&[&[-1, 0, 0], &[0, 1, 0], &[0, 0, 1]]),
    ];
    let sigma = PolyMap::from_quadratic_forms("σ", &forms).expect("valid");
    let bilinear = BezierPatch::from_homogeneous(vec![
        pts(&[&[1, 0, 0], &[1, 0, 1]]),
        pts(&[&[1, 2, 0], &[2, 1, 3]]),
    ])
    .expect("valid");
    let on_sphere = sigma.apply_patch(&bilinear).expect("dimensions fit");
    assert_eq!(on_sphere.degree(), (2, 2));
    assert!(
        certify::patch_on_quadric(&on_sphere, &sphere)
            .expect("4×4")
            .holds
    );
    assert!(
        !certify::patch_on_quadric(&bilinear.elevate(0, 0), &circle)
            .expect("3×3")
            .holds
    );
}

#[test]
fn bad_input_gives_errors_not_panics() {
    // Empty nets.
    assert!(matches!(
        BezierCurve::<Q>::from_homogeneous(vec![]),
        Err(GeomError::Empty(_))
    ));
    assert!(matches!(
        BezierPatch::<Q>::from_homogeneous(vec![]),
        Err(GeomError::Empty(_))
    ));
    assert!(matches!(
        BezierPatch::<Q>::from_homogeneous(vec![vec![]]),
        Err(GeomError::Empty(_))
    ));
    assert!(BezierCurve::<Q>::from_points(&[]).is_err());
    // Dimension mismatches.
    assert!(matches!(
        BezierCurve::from_homogeneous(pts(&[&[1, 0], &[1, 0, 0]])),
        Err(GeomError::Dimension(_))
    ));
    assert!(
        BezierPatch::from_homogeneous(vec![pts(&[&[1, 0]]), pts(&[&[1, 0], &[1, 1]])]).is_err()
    );
    assert!(BezierPatch::from_flat(2, 1, 1, vec![one(); 5]).is_err());
    let c =
        BezierCurve::from_homogeneous(pts(&[&[1, 0, 0], &[1, 1, 0], &[1, 1, 1]])).expect("valid");
    assert!(c.apply_projective(&pts(&[&[1, 0], &[0, 1]])).is_err());
    assert!(certify::curve_on_quadric(&c, &pts(&[&[1, 0], &[0, 1]])).is_err());
    assert!(certify::interpolates(&c, &one(), &[one()]).is_err());
    let map2 = vec![MPoly::<Q>::var(4, 0), MPoly::var(4, 3)];
    assert!(matches!(
        c.apply_polymap(&map2),
        Err(GeomError::Dimension(_))
    ));
    assert!(c.apply_polymap(&[]).is_err());
    let mut f64_out = [0.0; 1];
    assert!(c.to_f64().eval_into(0.5, &mut f64_out).is_err());
    // Weight-zero evaluation.
    let through_infinity = BezierCurve::from_homogeneous(pts(&[&[1, 0], &[-1, 2]])).expect("valid");
    assert!(matches!(
        through_infinity.eval(&q(1, 2)),
        Err(GeomError::Weight(_))
    ));
    assert!(through_infinity.derivative_euclidean(&q(1, 2), 2).is_err());
    assert!(
        !certify::interpolates(&through_infinity, &q(1, 2), &[one()])
            .expect("1D")
            .holds
    );
    let p =
        BezierPatch::from_homogeneous(vec![pts(&[&[1, 0], &[1, 1]]), pts(&[&[-1, 0], &[-1, 1]])])
            .expect("valid");
    assert!(matches!(
        p.eval(&q(1, 2), &zero()),
        Err(GeomError::Weight(_))
    ));
    assert!(p.partial_euclidean(&q(1, 2), &zero(), 1, 1).is_err());
    assert!(p.to_f64().eval_into(0.5, 0.0, &mut [0.0]).is_err());
    // Degenerate reparametrizations.
    assert!(matches!(
        c.restrict(&q(1, 3), &q(1, 3)),
        Err(GeomError::Parameter(_))
    ));
    assert!(c
        .reparametrize_mobius(&one(), &q(2, 1), &q(3, 1), &q(6, 1))
        .is_err());
    assert!(p.restrict_u(&one(), &one()).is_err());
    assert!(p
        .reparametrize_mobius_v(&zero(), &zero(), &one(), &one())
        .is_err());
    let cf = c.to_f64();
    assert!(cf.subdivide(&f64::NAN).is_err());
    assert!(cf.restrict(&0.0, &f64::INFINITY).is_err());
    assert!(cf.eval(&f64::NAN).is_err());
    // Curves of different dimension never agree.
    assert!(!c.same_parametrization(&through_infinity));
}
