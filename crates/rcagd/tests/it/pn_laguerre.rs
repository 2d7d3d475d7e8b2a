//! Theorem 4.5 in general (Peternell, "Rational Parametrizations for Envelopes of Quadric
//! Families", §4.5): the envelope of the cones of revolution spanned by two arbitrary
//! rational cycle curves — random exact families, the cone contact certificates
//! `Φ_t(x) ≡ 0`, `∂_tΦ_t(x) ≡ 0`, offsets, `f64` agreement, the named errors for an
//! isotropic cycle curve and for a missing sum-of-two-squares decomposition, and the
//! degrees of Prop. 4.1 as the code finds them.

use proptest::prelude::*;
use rcagd::pn::developable::DevelopablePn;
use rcagd::pn::ruled::{CanalPn, ConeFamilyEnvelope, CycleFamily};
use rcagd::pn::{PnError, RatFn};
use rcagd::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Rational, Scalar};

type Q = Rational;

fn q(p: i64, d: i64) -> Q {
    Q::from_ratio(p, d)
}

/// `Σ c_k t^k` in the two-variable ring (variable 0 is `t`).
fn tpoly(c: &[Q]) -> MPoly<Q> {
    MPoly::from_terms(
        2,
        c.iter()
            .enumerate()
            .filter(|(_, x)| !x.is_zero())
            .map(|(k, x)| (vec![k as u32, 0], x.clone()))
            .collect(),
    )
    .expect("two variables")
}

fn k(c: i64) -> MPoly<Q> {
    MPoly::constant(2, q(c, 1))
}

fn all_exact_hold(certs: &[rcagd_algebra::Certificate]) -> bool {
    certs.iter().all(|c| c.holds && c.exact)
}

fn failing(certs: &[rcagd_algebra::Certificate]) -> Vec<String> {
    certs
        .iter()
        .filter(|c| !c.holds)
        .map(|c| c.property.clone())
        .collect()
}

/// Two cycle families with `|M|² − R² = p₁² + p₂²` by construction: given random
/// `M₁, M₂, p₁, p₂` and a constant `c ≠ 0`, `D = p₁² + p₂² − M₁² − M₂²` is split as
/// `(M₃ − R)(M₃ + R) = c · D/c`. Returns `(c₁, c₂, p)`.
#[allow(clippy::type_complexity)]
fn families(
    m1: &[Q],
    r1: &[Q],
    mm: [&[Q]; 2],
    p: [&[Q]; 2],
    c: Q,
) -> (CycleFamily<Q>, CycleFamily<Q>, [RatFn<Q>; 2]) {
    let big_m1 = tpoly(mm[0]);
    let big_m2 = tpoly(mm[1]);
    let (p1, p2) = (tpoly(p[0]), tpoly(p[1]));
    let d = &(&(&p1 * &p1) + &(&p2 * &p2)) - &(&(&big_m1 * &big_m1) + &(&big_m2 * &big_m2));
    let inv = Q::from(1) / c.clone();
    let half = q(1, 2);
    // M₃ − R = c, M₃ + R = D/c
    let m3 =
        &MPoly::constant(2, c.clone() * half.clone()) + &d.scale(&(inv.clone() * half.clone()));
    let r = &d.scale(&(inv * half.clone())) - &MPoly::constant(2, c * half);
    let center1 = [tpoly(&m1[0..2]), tpoly(&m1[2..4]), tpoly(&m1[4..6])];
    let rad1 = tpoly(r1);
    let c1 = CycleFamily::new(center1.clone(), rad1.clone(), k(1)).expect("family");
    let c2 = CycleFamily::new(
        [
            &center1[0] - &big_m1,
            &center1[1] - &big_m2,
            &center1[2] - &m3,
        ],
        &rad1 - &r,
        k(1),
    )
    .expect("family");
    (c1, c2, [RatFn::poly(p1), RatFn::poly(p2)])
}

fn rational() -> impl Strategy<Value = Q> {
    (-5i64..=5, 1i64..=3).prop_map(|(a, b)| q(a, b))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Random exact cycle curves (linear centres and radii, `|M|² − R²` a sum of two squares
    /// by construction): the envelope is a certified PN surface touching both cycle
    /// families and every cone (`Φ_t(x) ≡ 0`, `∂_tΦ_t(x) ≡ 0`), and its offset is certified.
    /// (`f64` agreement: [`f64_agrees_with_exact_on_the_theorem_4_5_example`]; for random
    /// families the `f64` path is not yet reliable, see [`f64_envelope_of_random_integer_families`].)
    #[test]
    fn random_cycle_curves_envelope_their_cones(
        m1 in prop::collection::vec(rational(), 6),
        r1 in prop::collection::vec(rational(), 2),
        mm in prop::collection::vec(rational(), 4),
        pp in prop::collection::vec(rational(), 4),
        c in (1i64..=3, 1i64..=2),
        d in rational(),
    ) {
        let (c1, c2, p) = families(&m1, &r1, [&mm[0..2], &mm[2..4]], [&pp[0..2], &pp[2..4]], q(c.0, c.1));
        let env = match ConeFamilyEnvelope::new(c1.clone(), c2.clone(), Some(p.clone())) {
            Ok(e) => e,
            // degenerate draws (a developable envelope, cones that degenerate) are named errors
            Err(PnError::Developable(_)) | Err(PnError::IsotropicCycles(_)) => return Ok(()),
            Err(PnError::InvalidInput(m)) if m.contains("degenerate") || m.contains("coincide") => return Ok(()),
            Err(e) => { prop_assert!(false, "unexpected {e}"); unreachable!() }
        };
        let certs = env.certify();
        prop_assert!(all_exact_hold(&certs), "{:?}", failing(&certs));
        prop_assert_eq!(env.cone_certificates().len(), 2);
        let off = env.surface().offset(d.clone());
        prop_assert!(all_exact_hold(&off.certify()));
        prop_assert!(all_exact_hold(&env.offset_tangency_certificates(&d)));
    }
}

/// Two rational (non-polynomial) cycle curves with `p` found by the sum-of-two-squares
/// engine: `c₁ = ((1 − t², 2t, 0)/(1 + t²); 1/(1 + t²))` (centres on the unit circle) and
/// `c₂ = ((0, 0, t); 1/(1 + t²))`: `R ≡ 0`, `|M|² = 1 + t²` is a sum of two squares but
/// not a square.
#[test]
fn rational_cycle_curves_with_p_found_by_the_engine() {
    let t = tpoly(&[q(0, 1), q(1, 1)]);
    let w = tpoly(&[q(1, 1), q(0, 1), q(1, 1)]);
    let c1 = CycleFamily::new(
        [
            tpoly(&[q(1, 1), q(0, 1), q(-1, 1)]),
            t.scale(&q(2, 1)),
            k(0),
        ],
        k(1),
        w.clone(),
    )
    .expect("family");
    let c2 = CycleFamily::new([k(0), k(0), &t * &w], k(1), w).expect("family");
    let env = ConeFamilyEnvelope::new(c1, c2, None).expect("envelope");
    let certs = env.certify();
    assert!(all_exact_hold(&certs), "{:?}", failing(&certs));
    let off = env.surface().offset(q(1, 3));
    assert!(all_exact_hold(&off.certify()));
}

/// `|M|² − R² = t² + 2` is a sum of two squares only over `Q(√2)`: the named error says
/// so; `|M|² − R² ≡ 0` (the cycles touch) and a canal surface whose cycle curve has
/// isotropic tangents (`|ṁ|² ≡ ṙ²`) are named errors too.
#[test]
fn sum_of_squares_obstruction_and_isotropic_cycle_curves() {
    let t = tpoly(&[q(0, 1), q(1, 1)]);
    let c1 = CycleFamily::new([t.clone(), k(1), k(1)], k(0), k(1)).expect("family");
    let c2 = CycleFamily::new([k(0), k(0), k(0)], k(0), k(1)).expect("family");
    match ConeFamilyEnvelope::new(c1, c2, None) {
        Err(PnError::NoRationalPoint(m)) => {
            assert!(m.contains("sum of two squares"), "{m}");
            assert!(
                m.contains("√2") || m.contains("√8") || m.contains("√-2"),
                "{m}"
            );
        }
        other => panic!("expected the sum-of-squares obstruction, got {other:?}"),
    }
    // c₂ = ((t, 0, 0); t) touches c₁ = ((0, 0, 0); 0) for every t
    let c1 = CycleFamily::new([k(0), k(0), k(0)], k(0), k(1)).expect("family");
    let c2 = CycleFamily::new([t.clone(), k(0), k(0)], t.clone(), k(1)).expect("family");
    assert!(matches!(
        ConeFamilyEnvelope::new(c1, c2, None),
        Err(PnError::IsotropicCycles(_))
    ));
    // m = (t, t, 0), r = √2·t is irrational; m = (t, 0, 0), r = t: |ṁ|² = ṙ²
    let fam = CycleFamily::new([t.clone(), k(0), k(0)], t.clone(), k(1)).expect("family");
    match CanalPn::new(fam, None) {
        Err(PnError::IsotropicCycles(m)) => assert!(m.contains("isotropic"), "{m}"),
        other => panic!("expected the isotropic-tangent error, got {other:?}"),
    }
}

/// The same cycle family with `f64` coefficients.
fn family_f64(c: &CycleFamily<Q>) -> CycleFamily<f64> {
    let f = |p: &MPoly<Q>| p.map(Scalar::to_f64);
    let (m, r, w) = c.parts();
    CycleFamily::new([f(m[0]), f(m[1]), f(m[2])], f(r), f(w)).expect("family")
}

/// The exact and the `f64` envelope give the same point at `(a, b)` (relative 1e-9).
fn assert_points_agree(env: &ConeFamilyEnvelope<Q>, envf: &ConeFamilyEnvelope<f64>, a: &Q, b: &Q) {
    let xe = env.surface().eval(a, b).expect("point");
    let xf = envf
        .surface()
        .eval(&Scalar::to_f64(a), &Scalar::to_f64(b))
        .expect("point");
    for i in 0..3 {
        let e = Scalar::to_f64(&xe[i]);
        assert!(
            (e - xf[i]).abs() <= 1e-9 * (1.0 + e.abs()),
            "{e} vs {}",
            xf[i]
        );
    }
}

/// The `f64` construction of the Theorem 4.5 example agrees with the exact one.
#[test]
fn f64_agrees_with_exact_on_the_theorem_4_5_example() {
    let t = tpoly(&[q(0, 1), q(1, 1)]);
    let c1 = CycleFamily::new([t.scale(&q(2, 1)), &t * &t, k(2)], k(3), k(1)).expect("family");
    let c2 = CycleFamily::new([k(0), k(1), k(0)], k(1), k(1)).expect("family");
    let env = ConeFamilyEnvelope::new(c1.clone(), c2.clone(), None).expect("envelope");
    let envf =
        ConeFamilyEnvelope::new(family_f64(&c1), family_f64(&c2), None).expect("f64 envelope");
    assert!(envf.certify().iter().all(|c| c.holds && !c.exact));
    for (a, b) in [(q(5, 4), q(1, 3)), (q(3, 2), q(1, 2)), (q(7, 4), q(-2, 3))] {
        assert_points_agree(&env, &envf, &a, &b);
    }
}

/// Regression of a defect found by the property test above: for `m₁ = 0, r₁ = t,
/// M = (0, −t, ·)`, `p = (1 − 3t, 0)` the exact envelope has point bidegree (8, 4); the
/// `f64` one had (9, 6): the exact path cancelled the common factor `1 − 3t` (the zero of
/// `p₁ = p₂ = 0`, where the cone degenerates and the point map has a base point) by a
/// polynomial gcd, which `f64` lacks, and evaluated to 0/0 rounding noise at `(1/3, 1/2)`.
/// Now the factors of `p` are cancellation candidates in both paths
/// (docs/plans/pn-laguerre.md, item 1).
#[test]
fn f64_envelope_of_random_integer_families() {
    let (env, envf) = base_point_example();
    assert_eq!(envf.surface().degree(), env.surface().degree());
    assert_points_agree(&env, &envf, &q(1, 3), &q(1, 2));
}

/// The example of the known defect above, exact and in `f64`.
fn base_point_example() -> (ConeFamilyEnvelope<Q>, ConeFamilyEnvelope<f64>) {
    let z = || q(0, 1);
    let (c1, c2, p) = families(
        &[z(), z(), z(), z(), z(), z()],
        &[z(), q(1, 1)],
        [&[z(), z()], &[z(), q(-1, 1)]],
        [&[q(1, 1), q(-3, 1)], &[z(), z()]],
        q(1, 1),
    );
    let env = ConeFamilyEnvelope::new(c1.clone(), c2.clone(), Some(p.clone())).expect("e");
    let f = |p: &MPoly<Q>| p.map(Scalar::to_f64);
    let pf = [
        RatFn::new(f(&p[0].num), f(&p[0].den)).expect("den"),
        RatFn::new(f(&p[1].num), f(&p[1].den)).expect("den"),
    ];
    let envf =
        ConeFamilyEnvelope::new(family_f64(&c1), family_f64(&c2), Some(pf)).expect("f64 envelope");
    (env, envf)
}

/// The `f64` envelope of the base-point example agrees with the exact one at parameters
/// away from its uncancelled base point `t = 1/3` (relative 1e-9).
#[test]
fn f64_envelope_agrees_away_from_its_base_point() {
    let (env, envf) = base_point_example();
    for (a, b) in [(q(2, 3), q(-1, 2)), (q(1, 1), q(0, 1)), (q(1, 5), q(3, 2))] {
        assert_points_agree(&env, &envf, &a, &b);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Random quadratic and cubic curves of the isotropic model: the developable PN surface
    /// (Theorem 4.3, developable case) is certified exactly (n·n ≡ 1, n ⟂ x_t, x_v, x on
    /// its plane and on the characteristic line e ∩ ė, ∂_v n ≡ 0), and so is its offset;
    /// constant (y₁, y₂) is the named error.
    #[test]
    fn random_isotropic_curves_give_developable_pn_surfaces(
        c in prop::collection::vec(rational(), 12),
        d in rational(),
    ) {
        let y = [
            RatFn::poly(tpoly(&c[0..4])),
            RatFn::poly(tpoly(&c[4..8])),
            RatFn::poly(tpoly(&c[8..12])),
        ];
        let constant = |p: &MPoly<Q>| p.total_degree().unwrap_or(0) == 0;
        match DevelopablePn::from_isotropic_curve(&y) {
            Ok(dev) => {
                let certs = dev.certify();
                prop_assert!(all_exact_hold(&certs), "{:?}", failing(&certs));
                prop_assert!(all_exact_hold(&dev.surface().offset(d).certify()));
            }
            Err(PnError::Developable(_)) => {
                prop_assert!(constant(&y[0].num) && constant(&y[1].num));
            }
            Err(e) => prop_assert!(false, "unexpected {e}"),
        }
    }
}

/// Proposition 4.1's degrees certified: data `M′ = ((t − i)(e + if), g(t² + 1)/2)` (real
/// and imaginary parts; `R = M′₃`) rotated by `x ↦ (x₁, x₃, −x₂)`, so that
/// `|M|² − R² = (t² + 1)(e² + f²)` and the frame `ζ = ±e₂` reduces the unit normal.
/// General data (`c₁ = c₂ + (M; R)`, `k = 2`): `deg_t n ≤ 2k − 2 = 2` and the dual
/// representation `(E₀ : N)` has `deg_t ≤ 3k − 2 = 4`. A canal surface (`c₁ = ∫(M; R)`,
/// `c₂ = c₁ + ċ₁`, `k = 3`, `M` of degree `k − 1`): `deg_t n ≤ 2`, dual `≤ 3k − 4 = 5`
/// (the general bound would be 7). Every certificate holds exactly.
#[test]
fn prop_4_1_dual_degree_and_canal_bound_are_certified() {
    use rcagd::pn::reducing_frame::ReducedConeEnvelope;
    let t = || MPoly::<Q>::var(2, 0);
    let (e, f, g) = (&k(1) + &t().scale(&q(2, 1)), &k(-1) + &t(), q(2, 1));
    let t2p1 = &(&t() * &t()) + &k(1);
    let mp = [
        &(&t() * &e) + &f,
        &(&t() * &f) - &e,
        t2p1.scale(&(g / q(2, 1))),
    ];
    // rotation x′ = (x₁, −x₃, x₂) of the frame coordinates: M = (M′₁, M′₃, −M′₂)
    let m = [mp[0].clone(), mp[2].clone(), -mp[1].clone()];
    let r = mp[2].clone();
    let base = [k(0), k(1), k(0)];
    let c2 = CycleFamily::new(base.clone(), k(1), k(1)).expect("c2");
    let c1 =
        CycleFamily::new(std::array::from_fn(|i| &base[i] + &m[i]), &k(1) + &r, k(1)).expect("c1");
    let check = |env: &ReducedConeEnvelope<Q>, bound: &str, nb: usize, db: usize| {
        let certs = env.certify();
        assert!(
            all_exact_hold(&certs),
            "{:#?}",
            certs.iter().filter(|c| !c.holds).collect::<Vec<_>>()
        );
        assert!(env.frame().is_some(), "a reducing frame");
        let dual = env.dual_degree_certificates();
        assert_eq!(dual.len(), 2, "{dual:#?}");
        assert!(dual[1].property.contains(bound), "{}", dual[1].property);
        assert!(env.envelope().surface().normal_degree().0 <= nb);
        let deg: usize = dual[1]
            .property
            .split("r₁): ")
            .nth(1)
            .and_then(|s| s.split(' ').next())
            .and_then(|s| s.parse().ok())
            .expect("degree in the text");
        assert!(deg <= db, "{}", dual[1].property);
    };
    let env = ReducedConeEnvelope::new(c1, c2).expect("general envelope");
    assert_eq!(env.data_degree(), 2);
    check(&env, "3k − 2 = 4", 2, 4);
    // the canal surface of c = ∫(M; R) dt
    let integrate = |p: &MPoly<Q>| {
        MPoly::from_terms(
            2,
            p.terms()
                .map(|(ex, c)| {
                    let d = ex.first().copied().unwrap_or(0);
                    (vec![d + 1, 0], c.clone() / Q::from(i64::from(d) + 1))
                })
                .collect(),
        )
        .expect("two variables")
    };
    let cc = CycleFamily::new(
        std::array::from_fn(|i| integrate(&m[i])),
        &integrate(&r) + &k(3),
        k(1),
    )
    .expect("canal family");
    let canal = ReducedConeEnvelope::new(cc.clone(), cc.plus_derivative()).expect("canal");
    assert_eq!(canal.data_degree(), 3);
    check(&canal, "canal bound 3k − 4 = 5", 2, 5);
}
