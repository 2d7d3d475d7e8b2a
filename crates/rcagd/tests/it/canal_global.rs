//! Certified global regularity of canal surfaces of varying radius (issue 17 item 5): no two
//! closed discs bounded by characteristic circles meet (`rcagd::canal::check_canal_embedded`,
//! docs/math/pipes.md#canal-global).

use proptest::prelude::*;
use rcagd::canal::{
    canal_surface_rational, check_canal_chain_embedded, check_canal_embedded,
    check_canal_embedded_within, check_chain_embedded, check_pipe_embedded, CanalError,
    CanalOptions, CanalSpine, RationalCanal,
};
use rcagd::ph::PhCurve;
use rcagd::Certified;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::Certificate;
use rcagd_algebra::{parse_rational, Poly, Rational, Scalar};
use rcagd_geom::BezierCurve;

fn q(p: i64, d: i64) -> Rational {
    Rational::from_ratio(p, d)
}

fn poly(c: &[Rational]) -> Poly<Rational> {
    Poly::new(c.to_vec())
}

/// The loop `(t² − 1, t³ − t, t/5)`: the points at `t = ±1` are `(0, 0, ±1/5)`, 2/5 apart.
fn lifted_loop(radius: Poly<Rational>) -> CanalSpine<Rational> {
    CanalSpine::polynomial(
        [
            Poly::from_ints(&[-1, 0, 1]),
            Poly::from_ints(&[0, -1, 0, 1]),
            poly(&[q(0, 1), q(1, 5)]),
        ],
        radius,
    )
}

fn dot(a: &[Rational; 3], b: &[Rational; 3]) -> Rational {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() + a[2].clone() * b[2].clone()
}

/// Whether the discs at `t` and `s` meet, decided exactly in another way than the library:
/// the disc at `t` is the ball `|x − m(t)| ≤ |r(t)|` cut by the characteristic plane
/// `(x − m)·ṁ + r ṙ = 0`, so two discs in planes that are not parallel meet iff the two
/// balls' chords on the line of the planes overlap. `None` for parallel planes.
fn discs_meet_independent(
    spine: &CanalSpine<Rational>,
    t: &Rational,
    s: &Rational,
) -> Option<bool> {
    discs_of_two_meet_independent((spine, t), (spine, s))
}

/// [`discs_meet_independent`] for the disc of `first` at `t` and the disc of `second` at `s`
/// (two pieces of a chain).
fn discs_of_two_meet_independent(
    (first, t): (&CanalSpine<Rational>, &Rational),
    (second, s): (&CanalSpine<Rational>, &Rational),
) -> Option<bool> {
    let eval = |spine: &CanalSpine<Rational>, x: &Rational| {
        let w = spine.weight().eval(x);
        let m: [Rational; 3] =
            core::array::from_fn(|i| spine.center_polys()[i].eval(x) / w.clone());
        let r = spine.radius_poly().eval(x) / w.clone();
        // derivatives of m and r by the quotient rule
        let wd = spine.weight().derivative().eval(x);
        let md: [Rational; 3] = core::array::from_fn(|i| {
            (spine.center_polys()[i].derivative().eval(x) - m[i].clone() * wd.clone()) / w.clone()
        });
        let rd = (spine.radius_poly().derivative().eval(x) - r.clone() * wd) / w;
        // plane n·x = k with n = ṁ, k = m·ṁ − r ṙ
        let k = dot(&m, &md) - r.clone() * rd;
        (m, r, md, k)
    };
    let (m1, r1, n1, k1) = eval(first, t);
    let (m2, r2, n2, k2) = eval(second, s);
    let u = [
        n1[1].clone() * n2[2].clone() - n1[2].clone() * n2[1].clone(),
        n1[2].clone() * n2[0].clone() - n1[0].clone() * n2[2].clone(),
        n1[0].clone() * n2[1].clone() - n1[1].clone() * n2[0].clone(),
    ];
    let uu = dot(&u, &u);
    if uu == Rational::ZERO {
        return None;
    }
    // p0 on both planes with u·p0 = 0: p0 = (k1 (n2 × u) + k2 (u × n1)) / |u|²
    let cr = |a: &[Rational; 3], b: &[Rational; 3]| -> [Rational; 3] {
        [
            a[1].clone() * b[2].clone() - a[2].clone() * b[1].clone(),
            a[2].clone() * b[0].clone() - a[0].clone() * b[2].clone(),
            a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone(),
        ]
    };
    let (n2u, un1) = (cr(&n2, &u), cr(&u, &n1));
    let p0: [Rational; 3] = core::array::from_fn(|i| {
        (k1.clone() * n2u[i].clone() + k2.clone() * un1[i].clone()) / uu.clone()
    });
    assert_eq!(dot(&n1, &p0), k1);
    assert_eq!(dot(&n2, &p0), k2);
    // |p0 + λu − m|² ≤ r²: uu λ² + 2 b λ + c ≤ 0, chord centre −b/uu, half width √disc/uu
    let chord = |m: &[Rational; 3], r: &Rational| {
        let d: [Rational; 3] = core::array::from_fn(|i| p0[i].clone() - m[i].clone());
        let b = dot(&u, &d);
        let c = dot(&d, &d) - r.clone() * r.clone();
        (b.clone(), b.clone() * b - uu.clone() * c)
    };
    let (b1, d1) = chord(&m1, &r1);
    let (b2, d2) = chord(&m2, &r2);
    if d1 < Rational::ZERO || d2 < Rational::ZERO {
        return Some(false);
    }
    // overlap iff |b1 − b2| ≤ √d1 + √d2
    let y = (b1.clone() - b2.clone()) * (b1 - b2) - d1.clone() - d2.clone();
    Some(y <= Rational::ZERO || y.clone() * y <= Rational::from(4) * d1 * d2)
}

/// `n + 1` rational sample parameters of `[a, b]`.
fn samples(a: &Rational, b: &Rational, n: i64) -> Vec<Rational> {
    (0..=n)
        .map(|k| a.clone() + (b.clone() - a.clone()) * q(k, n))
        .collect()
}

/// Certified ⇒ no two sampled discs meet (exact, [`discs_meet_independent`]); returns the
/// number of pairs checked.
fn assert_sampled_discs_apart(
    spine: &CanalSpine<Rational>,
    a: &Rational,
    b: &Rational,
    n: i64,
) -> usize {
    let ts = samples(a, b, n);
    let mut checked = 0;
    for (i, t) in ts.iter().enumerate() {
        for s in &ts[i + 1..] {
            if let Some(meet) = discs_meet_independent(spine, t, s) {
                assert!(!meet, "certified, but the discs at {t} and {s} meet");
                checked += 1;
            }
        }
    }
    checked
}

/// The parameters of a refusal, checked exactly: they lie in the named intervals and their
/// discs meet.
fn assert_witness(spine: &CanalSpine<Rational>, e: &CanalError) -> (f64, f64) {
    let CanalError::CanalSelfIntersects {
        first,
        second,
        t,
        s,
    } = e
    else {
        panic!("not a witness: {e}");
    };
    let (t, s) = (parse_rational(t).expect("t"), parse_rational(s).expect("s"));
    let inside = |x: &Rational, iv: &str| {
        let ends: Vec<Rational> = iv
            .trim_matches(|c| c == '[' || c == ']')
            .split(", ")
            .map(|e| parse_rational(e).expect("end"))
            .collect();
        ends[0] <= *x && *x <= ends[1]
    };
    assert!(inside(&t, first) && inside(&s, second), "{e}");
    assert_eq!(discs_meet_independent(spine, &t, &s), Some(true), "{e}");
    (Scalar::to_f64(&t), Scalar::to_f64(&s))
}

#[test]
fn embedded_canal_of_varying_radius_is_certified() {
    // r = (1 + t²/4)/10 around the lifted loop: at t = ±1 the spine points are 2/5 apart,
    // the spheres 1/4
    let r = poly(&[q(1, 10), q(0, 1), q(1, 40)]);
    let s = lifted_loop(r);
    let (a, b) = (q(-3, 2), q(3, 2));
    let t0 = std::time::Instant::now();
    let c = check_canal_embedded(&s, (&a, &b)).expect("embedded");
    eprintln!("{} ({:?})", c.property, t0.elapsed());
    assert!(c.holds && c.exact);
    assert!(assert_sampled_discs_apart(&s, &a, &b, 24) > 250);
    // a growing radius around the parabola (t, t², 0)
    let p = CanalSpine::polynomial(
        [
            Poly::from_ints(&[0, 1]),
            Poly::from_ints(&[0, 0, 1]),
            Poly::zero(),
        ],
        poly(&[q(2, 20), q(1, 20)]),
    );
    let c = check_canal_embedded(&p, (&q(-1, 1), &q(1, 1))).expect("embedded");
    assert!(c.holds && c.exact, "{c:?}");
}

/// The work is bounded: with too few halvings or boxes the answer is "undecided", naming a
/// box, never a hang or a guess.
#[test]
fn limits_give_an_undecided_error_naming_the_box() {
    let r = poly(&[q(1, 10), q(0, 1), q(1, 40)]);
    let s = lifted_loop(r);
    let (a, b) = (q(-3, 2), q(3, 2));
    for limits in [(2, 40_000), (12, 20)] {
        match check_canal_embedded_within(&s, (&a, &b), limits) {
            Err(CanalError::CanalPartsNotApart {
                first,
                second,
                boxes,
            }) => {
                assert!(
                    first.starts_with('[') && second.ends_with(']'),
                    "{first} {second}"
                );
                assert!(boxes <= limits.1, "{boxes}");
            }
            other => panic!("{limits:?}: {other:?}"),
        }
    }
    // the default limits decide it
    assert!(check_canal_embedded(&s, (&a, &b)).is_ok());
}

#[test]
fn canal_whose_far_parts_come_too_close_is_refused_with_the_intervals() {
    // r = (1 + t²/4)/4: at t = ±1 the spheres have radius 5/16, the points are 2/5 apart
    let r = poly(&[q(1, 4), q(0, 1), q(1, 16)]);
    let s = lifted_loop(r);
    let (a, b) = (q(-3, 2), q(3, 2));
    rcagd::canal::check_canal_regularity(&s, (&a, &b)).expect("locally regular");
    let t0 = std::time::Instant::now();
    let e = check_canal_embedded(&s, (&a, &b)).expect_err("self-intersecting");
    eprintln!("{e} ({:?})", t0.elapsed());
    let (t, s_) = assert_witness(&s, &e);
    // the two parts near the spine's near-crossing at t = ±1
    assert!(t < -0.3 && s_ > 0.3, "{t} {s_}");
    // the same radius on a domain with one arm only is embedded
    let c = check_canal_embedded(&s, (&q(-1, 2), &b)).expect("one arm");
    assert!(c.holds);
}

/// The gallery's PH quintic of issue 17 and the loop as pipes: the canal check (any radius)
/// and the pipe check (constant radius, other tests) agree.
#[test]
fn agrees_with_the_pipe_check_on_pipes() {
    let loop_ = CanalSpine::polynomial(
        [
            Poly::from_ints(&[-1, 0, 1]),
            Poly::from_ints(&[0, -1, 0, 1]),
            Poly::zero(),
        ],
        Poly::constant(q(1, 50)),
    );
    let (a, b) = (q(-3, 2), q(3, 2));
    assert!(matches!(
        check_pipe_embedded(&loop_, (&a, &b)),
        Err(CanalError::PipeSelfIntersects { .. })
    ));
    let e = check_canal_embedded(&loop_, (&a, &b)).expect_err("crossing");
    let (t, s) = assert_witness(&loop_, &e);
    assert!((t + 1.0).abs() < 0.1 && (s - 1.0).abs() < 0.1, "{t} {s}");
    let half = q(-1, 2);
    assert!(check_pipe_embedded(&loop_, (&half, &b)).is_ok());
    assert!(check_canal_embedded(&loop_, (&half, &b)).is_ok());
    let quintic = PhCurve::new(
        vec![
            Quaternion::new(q(1, 1), q(0, 1), q(0, 1), q(0, 1)),
            Quaternion::new(q(1, 1), q(1, 1), q(0, 1), q(1, 1)),
            Quaternion::new(q(0, 1), q(0, 1), q(1, 1), q(1, 1)),
        ],
        [q(0, 1), q(0, 1), q(0, 1)],
    )
    .expect("ph");
    let s = CanalSpine::polynomial(quintic.position().clone(), Poly::constant(q(1, 8)));
    let (zero, one) = (q(0, 1), q(1, 1));
    assert!(check_pipe_embedded(&s, (&zero, &one)).is_ok());
    let t0 = std::time::Instant::now();
    let c = check_canal_embedded(&s, (&zero, &one)).expect("embedded");
    eprintln!("{} ({:?})", c.property, t0.elapsed());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Random cubic spines with random linear radii on `[0, 1]`: a certificate means that no
    /// two of 13 sampled discs meet (exact, computed independently of the library); a refusal's
    /// witness discs meet (exact); the constant-radius case agrees with the pipe check when
    /// both decide.
    #[test]
    fn random_canals_certified_or_refused_honestly(
        c in proptest::collection::vec(-3i64..=3, 9),
        r0 in 1i64..=6,
        r1 in -3i64..=3,
    ) {
        let m: [Poly<Rational>; 3] = core::array::from_fn(|i| {
            Poly::from_ints(&[0, c[3 * i], c[3 * i + 1], c[3 * i + 2]])
        });
        let r = poly(&[q(r0, 20), q(r1, 40)]);
        let s = CanalSpine::polynomial(m.clone(), r);
        let (a, b) = (q(0, 1), q(1, 1));
        if s.check_real_envelope(Some((&a, &b))).is_err()
            || rcagd::canal::check_canal_regularity(&s, (&a, &b)).is_err()
        {
            return Ok(());
        }
        let outcome = check_canal_embedded(&s, (&a, &b));
        eprintln!("{:?}", outcome.as_ref().map(|c| &c.property));
        match outcome {
            Ok(cert) => {
                prop_assert!(cert.holds && cert.exact);
                assert_sampled_discs_apart(&s, &a, &b, 12);
            }
            Err(e @ CanalError::CanalSelfIntersects { .. }) => {
                assert_witness(&s, &e);
            }
            Err(CanalError::CanalPartsNotApart { .. }) => {}
            Err(other) => prop_assert!(false, "{other}"),
        }
        // constant radius: the pipe check agrees where both decide
        let pipe = CanalSpine::polynomial(m, Poly::constant(q(r0, 20)));
        if rcagd::canal::check_canal_regularity(&pipe, (&a, &b)).is_ok() {
            let canal = check_canal_embedded(&pipe, (&a, &b));
            let pipe_check = check_pipe_embedded(&pipe, (&a, &b));
            match (&canal, &pipe_check) {
                (Ok(_), Ok(_)) => {}
                (Err(CanalError::CanalSelfIntersects { .. }), Err(CanalError::PipeSelfIntersects { .. })) => {}
                (Err(CanalError::CanalPartsNotApart { .. }), _) | (_, Err(CanalError::TubePartsNotApart { .. })) => {}
                _ => prop_assert!(false, "canal {:?} / pipe {:?}", canal, pipe_check),
            }
        }
    }

    /// Lifted Tschirnhausen cubics `(s(1 − ε²) − s³/3, s², −5εs/2)`, `s ∈ [−2, 2]` (two arms
    /// passing near each other), with random linear radii: many self-intersect. A refusal's
    /// witness discs meet and lie in the named intervals (exact); a certificate means no
    /// two of 17 sampled discs meet (exact, computed independently).
    #[test]
    fn random_lifted_loops(e in 1i64..=6, r0 in 2i64..=8, slope in -2i64..=2) {
        let eps = q(e, 40);
        let s = CanalSpine::polynomial(
            [
                poly(&[q(0, 1), q(1, 1) - eps.clone() * eps.clone(), q(0, 1), q(-1, 3)]),
                Poly::from_ints(&[0, 0, 1]),
                poly(&[q(0, 1), -eps * q(5, 2)]),
            ],
            poly(&[q(r0, 40), q(slope, 80)]),
        );
        let (a, b) = (q(-2, 1), q(2, 1));
        if rcagd::canal::check_canal_regularity(&s, (&a, &b)).is_err() {
            return Ok(());
        }
        let outcome = check_canal_embedded(&s, (&a, &b));
        eprintln!("lifted loop ε = {e}/40, r = {r0}/40 + {slope}/80 s: {:?}", outcome.as_ref().map(|_| "certified"));
        match outcome {
            Ok(cert) => {
                prop_assert!(cert.holds && cert.exact);
                assert_sampled_discs_apart(&s, &a, &b, 16);
            }
            Err(e @ CanalError::CanalSelfIntersects { .. }) => {
                let (t, u) = assert_witness(&s, &e);
                prop_assert!(t < u);
            }
            Err(CanalError::CanalPartsNotApart { .. }) => {}
            Err(other) => prop_assert!(false, "{other}"),
        }
    }
}

/// A lifted Tschirnhausen cubic `(s(1 − ε²) − s³/3, s², −5εs/2)`, `s ∈ [−2, 2]`, `ε = 1/20`,
/// with `r = r₀ + s/80`: its arms pass about 0.43 apart near `s = ±1.72`.
fn lifted_tschirnhausen(r0: Rational) -> CanalSpine<Rational> {
    let eps = q(1, 20);
    CanalSpine::polynomial(
        [
            poly(&[
                q(0, 1),
                q(1, 1) - eps.clone() * eps.clone(),
                q(0, 1),
                q(-1, 3),
            ]),
            Poly::from_ints(&[0, 0, 1]),
            poly(&[q(0, 1), -eps * q(5, 2)]),
        ],
        poly(&[r0, q(1, 80)]),
    )
}

/// Close to where the arms' discs start to meet (between `r₀ = 69/320` and `35/160`, 1.4 %
/// apart) both sides are decided: certified below (no two of 41 sampled discs meet, checked
/// independently), refused above with a witness whose discs meet.
#[test]
fn near_the_threshold_both_sides_are_decided() {
    let (a, b) = (q(-2, 1), q(2, 1));
    let below = lifted_tschirnhausen(q(69, 320));
    let t0 = std::time::Instant::now();
    let c = check_canal_embedded(&below, (&a, &b)).expect("embedded");
    eprintln!("{} ({:?})", c.property, t0.elapsed());
    assert!(c.holds && c.exact);
    assert_sampled_discs_apart(&below, &a, &b, 40);
    let above = lifted_tschirnhausen(q(35, 160));
    let e = check_canal_embedded(&above, (&a, &b)).expect_err("meets");
    let (t, s) = assert_witness(&above, &e);
    assert!(t < -1.5 && s > 1.5, "{t} {s}");
}

type Chain = Vec<(CanalSpine<Rational>, (Rational, Rational))>;

/// The unit circle of the `xy`-plane as four rational quarter arcs
/// `m_k = rot_k((1 − t², 2t, 0)/(1 + t²))`, `t ∈ [0, 1]` (`rot_k` the rotation by `k·90°`),
/// with radius `r = R/(1 + t²)` on every arc.
fn circle_arcs(radius_numerator: &Poly<Rational>, arcs: usize) -> Chain {
    let w = Poly::from_ints(&[1, 0, 1]);
    let (c, s) = (Poly::from_ints(&[1, 0, -1]), Poly::from_ints(&[0, 2]));
    let rot = |k: usize| -> [Poly<Rational>; 3] {
        match k {
            0 => [c.clone(), s.clone(), Poly::zero()],
            1 => [-&s, c.clone(), Poly::zero()],
            2 => [-&c, -&s, Poly::zero()],
            _ => [s.clone(), -&c, Poly::zero()],
        }
    };
    (0..arcs)
        .map(|k| {
            (
                CanalSpine::new(w.clone(), rot(k), radius_numerator.clone()).expect("arc"),
                (q(0, 1), q(1, 1)),
            )
        })
        .collect()
}

/// Certified ⇒ no two sampled discs of the chain meet (exact, independent), pairs at the
/// same point (a joint, the seam) left out; returns the number of pairs checked.
fn assert_chain_discs_apart(chain: &Chain, n: i64) -> usize {
    let mut pts: Vec<(usize, Rational)> = Vec::new();
    for (k, (_, (a, b))) in chain.iter().enumerate() {
        // the end of a piece is the start of the next: sample it once
        let ts = samples(a, b, n);
        pts.extend(ts[..ts.len() - 1].iter().cloned().map(|t| (k, t)));
    }
    let mut checked = 0;
    for (i, (k, t)) in pts.iter().enumerate() {
        for (l, s) in &pts[i + 1..] {
            if let Some(meet) = discs_of_two_meet_independent((&chain[*k].0, t), (&chain[*l].0, s))
            {
                assert!(
                    !meet,
                    "certified, but the discs at {t} (piece {k}) and {s} (piece {l}) meet"
                );
                checked += 1;
            }
        }
    }
    checked
}

/// Closed spines: the adjacency wraps around (the discs at the seam are one disc, Lemma A runs
/// through it); a joint where the radius jumps or `r dr/dσ` changes is not smooth, and the
/// certificate then fails, saying so.
#[test]
fn closed_chains_wrap_around_and_rough_joints_are_named() {
    // r = 1/4 + t²(1 − t)² on every quarter arc: r, dr/dσ (zero) agree at the joints
    let bump =
        &Poly::from_ints(&[1, 0, 0, 0, 0]).scale(&q(1, 4)) + &Poly::from_ints(&[0, 0, 1, -2, 1]);
    let numerator = &bump * &Poly::from_ints(&[1, 0, 1]);
    let torus = circle_arcs(&numerator, 4);
    let t0 = std::time::Instant::now();
    let c = check_canal_chain_embedded(&torus).expect("closed");
    eprintln!("{} ({:?})", c.property, t0.elapsed());
    assert!(
        c.holds && c.exact && c.property.contains("closed"),
        "{}",
        c.property
    );
    assert!(assert_chain_discs_apart(&torus, 6) > 200);
    // three arcs: open, certified
    let c = check_canal_chain_embedded(&torus[..3]).expect("open");
    assert!(c.holds && c.property.contains("open"), "{}", c.property);
    // one closed piece: the quintic loop (0, 0), (1, 0), (2, 2), (−2, 2), (−1, 0), (0, 0) leaves
    // and returns to the origin along +x; as a pipe both checks see the seam
    let loop5 = piece(&[(0, 0), (1, 0), (2, 2), (-2, 2), (-1, 0), (0, 0)], 1, None);
    let pipe = CanalSpine::constant_radius(&loop5, &q(1, 20)).expect("spine");
    let (zero, one) = (q(0, 1), q(1, 1));
    let c = check_canal_embedded(&pipe, (&zero, &one)).expect("closed loop");
    assert!(
        c.holds && c.property.contains("closed spine"),
        "{}",
        c.property
    );
    let p = check_pipe_embedded(&pipe, (&zero, &one)).expect("closed loop as a pipe");
    assert!(p.holds && p.property.contains("closed"), "{}", p.property);
    // r = 1/4 + t/8 jumps from 3/8 back to 1/4 at every joint: not smooth, checked run by run
    let jump = &Poly::from_ints(&[2, 1]).scale(&q(1, 8)) * &Poly::from_ints(&[1, 0, 1]);
    let rough = circle_arcs(&jump, 4);
    let c = check_canal_chain_embedded(&rough).expect("checked per run");
    assert!(!c.holds, "{c:?}");
    let reason = c.residual.clone().unwrap_or_default();
    assert!(
        reason.contains("not smooth") && reason.contains("0/1"),
        "{c:?}"
    );
}

/// The witness of a refusal of a chain: each parameter lies in its named interval of its
/// named piece, and the two discs meet (exact, independent).
fn assert_chain_witness(chain: &Chain, e: &CanalError) {
    let CanalError::CanalSelfIntersects {
        first,
        second,
        t,
        s,
    } = e
    else {
        panic!("not a witness: {e}");
    };
    let parse = |iv: &str, x: &str| -> (usize, Rational) {
        let x = parse_rational(x).expect("parameter");
        let (iv, piece) = iv.split_once(" (spine piece ").expect("piece named");
        let k: usize = piece.trim_end_matches(')').parse().expect("piece");
        let ends: Vec<Rational> = iv
            .trim_matches(|c| c == '[' || c == ']')
            .split(", ")
            .map(|e| parse_rational(e).expect("end"))
            .collect();
        assert!(ends[0] <= x && x <= ends[1], "{e}");
        (k, x)
    };
    let (k, t) = parse(first, t);
    let (l, s) = parse(second, s);
    match discs_of_two_meet_independent((&chain[k].0, &t), (&chain[l].0, &s)) {
        Some(meet) => assert!(meet, "{e}"),
        None => {
            // parallel planes (pipes only here: centre m, radius |r|): the discs meet iff the
            // planes coincide and the centres are at most 2|r| apart
            let (mt, rt) = chain[k].0.eval(&t).expect("point");
            let (ms, rs) = chain[l].0.eval(&s).expect("point");
            assert_eq!(rt.clone() * rt.clone(), rs.clone() * rs, "{e}");
            let d: [Rational; 3] = core::array::from_fn(|i| mt[i].clone() - ms[i].clone());
            let w = chain[k].0.weight();
            let m = chain[k].0.center_polys();
            let tangent: [Rational; 3] = core::array::from_fn(|i| {
                w.eval(&t) * m[i].derivative().eval(&t) - w.derivative().eval(&t) * m[i].eval(&t)
            });
            assert_eq!(dot(&d, &tangent), Rational::ZERO, "{e}");
            assert!(dot(&d, &d) <= q(4, 1) * rt.clone() * rt, "{e}");
        }
    }
}

/// A planar rational Bézier piece (`z = 0`) from integer points `(x/den, y/den)` and weights
/// (as in `pipe_self_intersection.rs`).
fn piece(points: &[(i64, i64)], den: i64, weights: Option<&[i64]>) -> BezierCurve<Rational> {
    let pts: Vec<Vec<Rational>> = points
        .iter()
        .map(|&(x, y)| vec![q(x, den), q(y, den), q(0, 1)])
        .collect();
    match weights {
        None => BezierCurve::from_points(&pts).expect("curve"),
        Some(w) => {
            let w: Vec<Rational> = w.iter().map(|&x| q(x, 1)).collect();
            BezierCurve::from_points_weights(&pts, &w).expect("curve")
        }
    }
}

/// The bulb-shaped bend of `pipe_self_intersection.rs` (least radius of curvature above
/// 1/2, its own double-critical pairs more than 1 apart) from `(0, 0)` up and back down to
/// `(1, 0)`; `flip` mirrors it to `y ↦ −1 − y`.
fn bend(flip: bool) -> Vec<BezierCurve<Rational>> {
    let f = |(x, y): (i64, i64)| if flip { (2 - x, -2 - y) } else { (x, y) };
    let pts = |v: &[(i64, i64)]| v.iter().copied().map(f).collect::<Vec<_>>();
    vec![
        piece(&pts(&[(0, 0), (0, 2), (-1, 2), (-1, 4)]), 2, None),
        piece(&pts(&[(-1, 4), (-1, 6), (1, 6)]), 2, Some(&[1, 1, 2])),
        piece(&pts(&[(1, 6), (3, 6), (3, 4)]), 2, Some(&[2, 1, 1])),
        piece(&pts(&[(3, 4), (3, 2), (2, 2), (2, 0)]), 2, None),
    ]
}

fn pipe_chain(pieces: &[BezierCurve<Rational>], r: &Rational) -> Chain {
    pieces
        .iter()
        .map(|c| {
            (
                CanalSpine::constant_radius(c, r).expect("spine"),
                (q(0, 1), q(1, 1)),
            )
        })
        .collect()
}

/// On pipes (constant radius) around chains, open and closed, the canal check and the pipe
/// check (`check_chain_embedded`, other tests) agree: the unit circle's torus at `r = 1/2`
/// and `3/4` (closed), a U of two parallel arms `1` apart joined by a bend at `r = 0.499` and `0.501`
/// (open; the threshold is `1/2`), and the closed racetrack of two such bends.
#[test]
fn chains_agree_with_the_pipe_check() {
    let w = Poly::from_ints(&[1, 0, 1]);
    for r in [q(1, 2), q(3, 4)] {
        let torus = circle_arcs(&w.scale(&r), 4);
        let pipe = check_chain_embedded(&torus).expect("pipe torus");
        let canal = check_canal_chain_embedded(&torus).expect("canal torus");
        eprintln!("torus r = {r}: {}", canal.property);
        assert!(pipe.holds && canal.holds, "{pipe:?} {canal:?}");
        assert!(pipe.property.contains("closed") && canal.property.contains("closed"));
    }
    // at r = 9/10 (r·κ = 9/10) pairs about 60° apart are settled only because a disc misses
    // the other's plane; the bivariate plane test (divided by (s − t)² on one piece)
    // decides them within the default limits (session 17; undecided after 5540 boxes
    // before), and no two of 24 sampled discs meet (exact, independent)
    let fat = circle_arcs(&w.scale(&q(9, 10)), 4);
    assert!(check_chain_embedded(&fat).expect("pipe torus").holds);
    let t0 = std::time::Instant::now();
    let c = check_canal_chain_embedded(&fat).expect("decided within the default limits");
    eprintln!("torus r = 9/10: {} ({:?})", c.property, t0.elapsed());
    assert!(c.holds && c.property.contains("closed"), "{c:?}");
    assert!(assert_chain_discs_apart(&fat, 6) > 200);
    let mut u = vec![piece(&[(0, -2), (0, 0)], 2, None)];
    u.extend(bend(false));
    u.push(piece(&[(2, 0), (2, -2)], 2, None));
    let mut racetrack = u.clone();
    racetrack.extend(bend(true));
    for spine in [&u, &racetrack] {
        let below = pipe_chain(spine, &q(499, 1000));
        let t0 = std::time::Instant::now();
        let c = check_canal_chain_embedded(&below).expect("embedded");
        eprintln!("{} ({:?})", c.property, t0.elapsed());
        assert!(c.holds, "{c:?}");
        assert!(check_chain_embedded(&below).expect("pipe").holds);
        let above = pipe_chain(spine, &q(501, 1000));
        assert!(matches!(
            check_chain_embedded(&above),
            Err(CanalError::PipeSelfIntersects { .. })
        ));
        let e = check_canal_chain_embedded(&above).expect_err("refused");
        assert_chain_witness(&above, &e);
    }
}

/// `m = (u, 0, u²)`, `r = 1/4 + u²/2`: `|ṁ|² − ṙ² = 1 + 3u²` needs `Q(√3)`, so the canal
/// builder falls back to the cyclographic `Γ(s, t)` with spine parameter
/// `p = −2s/(1 − 3(s² + t²))`. The discs at `±u` are mirror images in the plane `x = 0`.
fn growing_parabola() -> CanalSpine<Rational> {
    CanalSpine::polynomial(
        [
            Poly::from_ints(&[0, 1]),
            Poly::zero(),
            Poly::from_ints(&[0, 0, 1]),
        ],
        poly(&[q(1, 4), q(0, 1), q(1, 2)]),
    )
}

/// Γ(s, t) is checked for global self-intersection on its rectangle (issue 17 item 5): the
/// spine parameters its rectangle reaches are enclosed, and no two characteristic discs over
/// them may meet. Certified: no two discs of a grid of the rectangle meet (exact,
/// independent); refused: the witness parameters are reached by the rectangle (between
/// values of `p` at its corners) and their discs meet.
#[test]
fn gamma_is_checked_for_global_self_intersection_on_its_rectangle() {
    let spine = growing_parabola();
    let opts = CanalOptions {
        domain: Some((q(0, 1), q(1, 1))),
        ..CanalOptions::default()
    };
    let p_at = |s: &Rational, t: &Rational| {
        -(q(2, 1) * s.clone())
            / (q(1, 1) - q(3, 1) * (s.clone() * s.clone() + t.clone() * t.clone()))
    };
    let grid = |rect: &[Rational; 4], n: i64| -> Vec<Rational> {
        let mut ps = Vec::new();
        for i in 0..=n {
            for j in 0..=n {
                let s = rect[0].clone() + (rect[1].clone() - rect[0].clone()) * q(i, n);
                let t = rect[2].clone() + (rect[3].clone() - rect[2].clone()) * q(j, n);
                ps.push(p_at(&s, &t));
            }
        }
        ps
    };
    for (rect, meets) in [
        ([q(-1, 4), q(1, 4), q(-1, 10), q(1, 10)], false),
        ([q(-9, 20), q(9, 20), q(-1, 10), q(1, 10)], true),
    ] {
        let t0 = std::time::Instant::now();
        let built = canal_surface_rational(&spine, &opts, Some(&rect));
        eprintln!("{rect:?}: {:?}", t0.elapsed());
        let ps = grid(&rect, 6);
        match built {
            Ok(RationalCanal::Cyclographic(c)) => {
                assert!(!meets, "expected a refusal on {rect:?}");
                let certs = c.certify();
                assert!(Certificate::all_hold(&certs), "{certs:#?}");
                let global = certs
                    .iter()
                    .find(|x| x.property.starts_with("Γ(s, t) has no self-intersection"))
                    .expect("the global certificate");
                eprintln!("{}", global.property);
                let mut checked = 0;
                for (i, a) in ps.iter().enumerate() {
                    for b in &ps[i + 1..] {
                        if a != b {
                            if let Some(m) = discs_meet_independent(&spine, a, b) {
                                assert!(!m, "certified, but the discs at p = {a}, {b} meet");
                                checked += 1;
                            }
                        }
                    }
                }
                assert!(checked > 300, "{checked}");
            }
            Err(e @ CanalError::CyclographicDiscsMeet { .. }) => {
                assert!(meets, "{e}");
                eprintln!("{e}");
                let CanalError::CyclographicDiscsMeet { t, s, .. } = &e else {
                    unreachable!()
                };
                let (t, s) = (parse_rational(t).expect("t"), parse_rational(s).expect("s"));
                let lo = ps.iter().min().expect("grid").clone();
                let hi = ps.iter().max().expect("grid").clone();
                for x in [&t, &s] {
                    assert!(lo <= *x && *x <= hi, "{x} not reached: {e}");
                }
                assert_eq!(discs_meet_independent(&spine, &t, &s), Some(true), "{e}");
            }
            other => panic!("{rect:?}: {other:?}"),
        }
    }
}
