//! Certified global regularity of pipes (issue 17 item 5): no two normal discs of radius
//! `|r|` meet (`rcagd::canal::self_intersection`, docs/math/pipes.md, "Global").

use rcagd::canal::{check_chain_embedded, check_pipe_embedded, CanalError, CanalSpine};
use rcagd::ph::PhCurve;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::{Poly, Rational, Scalar};
use rcagd_geom::BezierCurve;

fn q(p: i64, d: i64) -> Rational {
    Rational::from_ratio(p, d)
}

/// A planar rational Bézier piece (`z = 0`) from integer points `(x/den, y/den)` and weights.
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

fn chain(
    pieces: &[BezierCurve<Rational>],
    r: &Rational,
) -> Vec<(CanalSpine<Rational>, (Rational, Rational))> {
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

/// The top bend of a U (coordinates in halves): from `(0, 0)` going up, an S-curve out to
/// `x = −1/2`, a half circle of radius 1 about `(1/2, 2)` (two rational quarter arcs), an
/// S-curve back in to `(1, 0)` going down. Its least radius of curvature is above 1/2 and
/// its own double-critical pairs are more than 1 apart; `flip` mirrors it to `y ↦ −1 − y`
/// (the bottom bend of a closed racetrack, traversed from `(1, −1)` to `(0, −1)`).
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

/// A U: two parallel straight arms 1 apart (`x = 0` and `x = 1`, `y ∈ [−1, 0]`) joined by
/// [`bend`].
fn u_spine() -> Vec<BezierCurve<Rational>> {
    let mut v = vec![piece(&[(0, -2), (0, 0)], 2, None)];
    v.extend(bend(false));
    v.push(piece(&[(2, 0), (2, -2)], 2, None));
    v
}

#[test]
fn loop_crossing_itself_is_refused_with_the_crossing() {
    // m = (t² − 1, t³ − t, 0) passes (0, 0, 0) at t = ±1
    let s = CanalSpine::polynomial(
        [
            Poly::from_ints(&[-1, 0, 1]),
            Poly::from_ints(&[0, -1, 0, 1]),
            Poly::zero(),
        ],
        Poly::constant(q(1, 50)),
    );
    match check_pipe_embedded(&s, (&q(-3, 2), &q(3, 2))) {
        Err(CanalError::PipeSelfIntersects {
            first,
            second,
            distance,
            ..
        }) => {
            let (a, b): (f64, f64) = (first.parse().expect("t"), second.parse().expect("s"));
            assert!((a + 1.0).abs() < 1e-6 && (b - 1.0).abs() < 1e-6, "{a} {b}");
            assert!(distance.parse::<f64>().expect("d") < 1e-6);
        }
        other => panic!("{other:?}"),
    }
    // one crossing parameter only: embedded
    let c = check_pipe_embedded(&s, (&q(-1, 2), &q(3, 2))).expect("embedded");
    assert!(c.holds && c.exact, "{c:?}");
}

#[test]
fn issue_quintic_pipe_is_embedded() {
    let a = vec![
        Quaternion::new(q(1, 1), q(0, 1), q(0, 1), q(0, 1)),
        Quaternion::new(q(1, 1), q(1, 1), q(0, 1), q(1, 1)),
        Quaternion::new(q(0, 1), q(0, 1), q(1, 1), q(1, 1)),
    ];
    let c = PhCurve::new(a, [q(0, 1), q(0, 1), q(0, 1)]).expect("ph");
    let s = CanalSpine::polynomial(c.position().clone(), Poly::constant(q(1, 8)));
    let t = std::time::Instant::now();
    let cert = check_pipe_embedded(&s, (&q(0, 1), &q(1, 1))).expect("embedded");
    eprintln!("{} ({:?})", cert.property, t.elapsed());
    assert!(cert.holds && cert.exact);
}

#[test]
fn u_shaped_spine_arms_two_r_plus_minus_eps() {
    let spine = u_spine();
    // r = 1/2 − 1/1000: the arms are 2r + 1/500 apart
    let t = std::time::Instant::now();
    let below = check_chain_embedded(&chain(&spine, &q(499, 1000))).expect("embedded");
    eprintln!("{} ({:?})", below.property, t.elapsed());
    assert!(below.holds && below.exact);
    for r in [q(501, 1000), q(1, 2)] {
        match check_chain_embedded(&chain(&spine, &r)) {
            Err(CanalError::PipeSelfIntersects {
                first,
                second,
                distance,
                ..
            }) => {
                eprintln!(
                    "r = {}: {first} / {second} at {distance}",
                    Scalar::to_f64(&r)
                );
                assert!((distance.parse::<f64>().expect("d") - 1.0).abs() < 1e-6);
            }
            other => panic!("{other:?}"),
        }
    }
}

/// A closed racetrack: the U's arms and two bends (no ends); embedded iff `2r < 1`.
#[test]
fn closed_racetrack_threshold_and_circle() {
    let mut spine = vec![piece(&[(0, -2), (0, 0)], 2, None)];
    spine.extend(bend(false));
    spine.push(piece(&[(2, 0), (2, -2)], 2, None));
    spine.extend(bend(true));
    let below = check_chain_embedded(&chain(&spine, &q(499, 1000))).expect("embedded");
    assert!(
        below.holds && below.property.contains("closed"),
        "{}",
        below.property
    );
    match check_chain_embedded(&chain(&spine, &q(501, 1000))) {
        Err(CanalError::PipeSelfIntersects { distance, .. }) => {
            assert!((distance.parse::<f64>().expect("d") - 1.0).abs() < 1e-6);
        }
        other => panic!("{other:?}"),
    }
    // the unit circle in four rational quarter arcs (closed): the torus is embedded for
    // every r < 1 (antipodal points are 2 apart, r·κ = r)
    let circle = vec![
        piece(&[(1, 0), (1, 1), (0, 1)], 1, Some(&[1, 1, 2])),
        piece(&[(0, 1), (-1, 1), (-1, 0)], 1, Some(&[2, 1, 1])),
        piece(&[(-1, 0), (-1, -1), (0, -1)], 1, Some(&[1, 1, 2])),
        piece(&[(0, -1), (1, -1), (1, 0)], 1, Some(&[2, 1, 1])),
    ];
    let c = check_chain_embedded(&chain(&circle, &q(9, 10))).expect("torus");
    assert!(c.holds && c.property.contains("closed"), "{}", c.property);
    // the same arcs without the last one: an open spine, whose end discs are apart
    let c = check_chain_embedded(&chain(&circle[..3], &q(9, 10))).expect("open arc");
    assert!(c.holds && c.property.contains("open"), "{}", c.property);
}

/// `f64` reference: the point of the line of the two normal planes nearest the midpoint,
/// and whether it lies in both discs of radius `rho` (scaled by `1 + slack`).
fn discs_meet_f64(
    mt: [f64; 3],
    pt: [f64; 3],
    ms: [f64; 3],
    ps: [f64; 3],
    rho: f64,
    slack: f64,
) -> bool {
    let d = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let c = [
        (mt[0] + ms[0]) / 2.0,
        (mt[1] + ms[1]) / 2.0,
        (mt[2] + ms[2]) / 2.0,
    ];
    let (a11, a12, a22) = (d(pt, pt), d(pt, ps), d(ps, ps));
    let det = a11 * a22 - a12 * a12;
    if det.abs() <= 1e-14 * a11 * a22 {
        return false;
    }
    let (r1, r2) = (d(sub(mt, c), pt), d(sub(ms, c), ps));
    let al = (r1 * a22 - r2 * a12) / det;
    let be = (a11 * r2 - a12 * r1) / det;
    let x = [0, 1, 2].map(|k| c[k] + al * pt[k] + be * ps[k]);
    let lim = (rho * (1.0 + slack)).powi(2);
    d(sub(x, mt), sub(x, mt)) <= lim && d(sub(x, ms), sub(x, ms)) <= lim
}

mod props {
    use super::*;
    use proptest::prelude::*;
    use rcagd::canal::check_pipe_regularity;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]

        /// Random PH quintics with radii around half their sampled double-critical distance:
        /// the exact decision agrees with dense `f64` sampling of the normal discs (an
        /// embedded pipe has no sampled pair of meeting discs with a clear margin; a refusal's
        /// witness discs meet in `f64` too).
        #[test]
        fn random_ph_quintic_pipes_agree_with_sampling(
            a in proptest::collection::vec(proptest::array::uniform4(-3i64..4), 3),
            frac in 1i64..10,
        ) {
            let coeffs: Vec<Quaternion<Rational>> = a
                .iter()
                .map(|c| Quaternion::new(q(c[0], 1), q(c[1], 1), q(c[2], 1), q(c[3], 1)))
                .collect();
            let Ok(curve) = PhCurve::new(coeffs, [q(0, 1), q(0, 1), q(0, 1)]) else { return Ok(()); };
            let pos = curve.position().clone();
            let pf: [Poly<f64>; 3] = core::array::from_fn(|k| pos[k].map(Scalar::to_f64));
            let df: [Poly<f64>; 3] = core::array::from_fn(|k| pf[k].derivative());
            let ddf: [Poly<f64>; 3] = core::array::from_fn(|k| df[k].derivative());
            let at = |p: &[Poly<f64>; 3], t: f64| [p[0].eval(&t), p[1].eval(&t), p[2].eval(&t)];
            // the least sampled radius of curvature
            let n = 200;
            let mut rmin = f64::INFINITY;
            for i in 0..=n {
                let t = i as f64 / n as f64;
                let (d1, d2) = (at(&df, t), at(&ddf, t));
                let c = [d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]];
                let s2 = d1[0] * d1[0] + d1[1] * d1[1] + d1[2] * d1[2];
                let cn = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
                if cn > 0.0 {
                    rmin = rmin.min(s2.powf(1.5) / cn);
                }
            }
            prop_assume!(rmin.is_finite() && rmin > 1e-3);
            // radius: frac/10 ≤ 0.9 of the least radius of curvature (a clear local margin:
            // at r·κ → 1 the close-along-the-spine bound needs ever finer boxes, found with
            // 1.01: undecided at depth 14)
            let rho = Rational::from_ratio(((rmin * frac as f64 / 10.0) * 1000.0).floor().max(1.0) as i64, 1000);
            let rf = Scalar::to_f64(&rho);
            let s = CanalSpine::polynomial(pos.clone(), Poly::constant(rho.clone()));
            let (zero, one) = (q(0, 1), q(1, 1));
            if check_pipe_regularity(&s, (&zero, &one)).is_err() {
                return Ok(());
            }
            match check_pipe_embedded(&s, (&zero, &one)) {
                Ok(c) => {
                    prop_assert!(c.holds && c.exact);
                    // no sampled pair (away from the diagonal) has meeting discs with margin
                    let m = 120;
                    for i in 0..=m {
                        for j in i + 1..=m {
                            let (t, u) = (i as f64 / m as f64, j as f64 / m as f64);
                            let meet = discs_meet_f64(at(&pf, t), at(&df, t), at(&pf, u), at(&df, u), rf, -1e-6);
                            prop_assert!(!meet, "sampled discs at {t}, {u} meet (r = {rf})");
                        }
                    }
                }
                Err(CanalError::PipeSelfIntersects { first, second, .. }) => {
                    let (t, u): (f64, f64) = (first.parse().expect("t"), second.parse().expect("s"));
                    prop_assert!((t - u).abs() > 1e-6);
                    // the rounded parameters: their discs meet within rounding
                    let meet = discs_meet_f64(at(&pf, t), at(&df, t), at(&pf, u), at(&df, u), rf, 1e-3)
                        || {
                            let (x, y) = (at(&pf, t), at(&pf, u));
                            ((x[0] - y[0]).powi(2) + (x[1] - y[1]).powi(2) + (x[2] - y[2]).powi(2)).sqrt() <= 2.0 * rf * (1.0 + 1e-3)
                        };
                    prop_assert!(meet, "witness {t}, {u} (r = {rf})");
                }
                // undecided only where the margin is not clear: the box's spine points
                // within 1 % of 2|r| (found at random: an end disc vs. a disc 0.04 % from
                // touching distance)
                Err(CanalError::TubePartsNotApart { distance, diameter, .. }) => {
                    let (d, dia): (f64, f64) = (distance.parse().expect("d"), diameter.parse().expect("2r"));
                    prop_assert!((d - dia).abs() <= 0.01 * dia, "undecided with a clear margin: {d} vs 2r = {dia}");
                }
                Err(e) => prop_assert!(false, "{e}"),
            }
        }
    }
}
