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
