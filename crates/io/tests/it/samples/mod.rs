//! Exact sample geometry shared by the exchange tests (`tests/exchange.rs`) and the
//! export benchmark (`benches/export.rs`, included with `#[path]`): quarter circles,
//! the sphere as 8 octants, a torus, an open tube, a rational bicubic patch, the unit
//! circle and a spatial cubic.
#![allow(dead_code)]

use rcagd_algebra::{Rational, Scalar};
use rcagd_geom::{BezierCurve, BezierPatch};

pub fn q(p: i64, d: i64) -> Rational {
    Rational::from_ratio(p, d)
}

pub fn int(p: i64) -> Rational {
    Rational::from(p)
}

/// The quarter circle `(1−t², 2t)/(1+t²)` as homogeneous `(w, w·cos, w·sin)` control
/// points, rotated by `k` quarter turns.
pub fn quarter(k: usize) -> [[Rational; 3]; 3] {
    let base = [
        [int(1), int(1), int(0)],
        [int(1), int(1), int(1)],
        [int(2), int(0), int(2)],
    ];
    base.map(|[w, c, s]| {
        let (mut c, mut s) = (c, s);
        for _ in 0..k % 4 {
            (c, s) = (-s, c);
        }
        [w, c, s]
    })
}

/// One octant of the unit sphere (biquadratic, degenerate at the pole `u = 0`),
/// reflected by the signs `(sx, sy, sz)`.
fn sphere_octant(
    sx: i64,
    sy: i64,
    sz: i64,
    center: [i64; 3],
    radius: i64,
) -> BezierPatch<Rational> {
    // meridian (w, w·r, w·z) from the pole to the equator
    let mer = [
        [int(1), int(0), int(1)],
        [int(1), int(1), int(1)],
        [int(2), int(2), int(0)],
    ];
    let eq = quarter(0);
    let net = mer
        .iter()
        .map(|m| {
            eq.iter()
                .map(|e| {
                    let w = m[0].clone() * e[0].clone();
                    let r = int(radius);
                    vec![
                        w.clone(),
                        int(sx) * r.clone() * m[1].clone() * e[1].clone()
                            + w.clone() * int(center[0]),
                        int(sy) * r.clone() * m[1].clone() * e[2].clone()
                            + w.clone() * int(center[1]),
                        int(sz) * r * m[2].clone() * e[0].clone() + w * int(center[2]),
                    ]
                })
                .collect()
        })
        .collect();
    BezierPatch::from_homogeneous(net).expect("valid net")
}

/// The whole sphere as 8 exact biquadratic patches (a closed shell).
pub fn sphere(center: [i64; 3], radius: i64) -> Vec<BezierPatch<Rational>> {
    let mut out = Vec::new();
    for sz in [1, -1] {
        for sy in [1, -1] {
            for sx in [1, -1] {
                out.push(sphere_octant(sx, sy, sz, center, radius));
            }
        }
    }
    out
}

/// A torus with radii `big > small` as 16 exact biquadratic patches:
/// `x = (R + r cos v) cos u`, `y = (R + r cos v) sin u`, `z = r sin v`, each circle
/// as four rational quarter circles; homogeneous `W = wᵤ w_v`,
/// `X = (R w_v + r c_v) cᵤ`, `Y = (R w_v + r c_v) sᵤ`, `Z = r s_v wᵤ`.
pub fn torus(big: Rational, small: Rational) -> Vec<BezierPatch<Rational>> {
    let mut out = Vec::new();
    for a in 0..4 {
        for b in 0..4 {
            let (cu, cv) = (quarter(a), quarter(b));
            let net = cu
                .iter()
                .map(|[wu, c, s]| {
                    cv.iter()
                        .map(|[wv, cc, ss]| {
                            let rad = big.clone() * wv.clone() + small.clone() * cc.clone();
                            vec![
                                wu.clone() * wv.clone(),
                                rad.clone() * c.clone(),
                                rad * s.clone(),
                                small.clone() * ss.clone() * wu.clone(),
                            ]
                        })
                        .collect()
                })
                .collect();
            out.push(BezierPatch::from_homogeneous(net).expect("valid net"));
        }
    }
    out
}

/// An open tube: the cylinder `x² + y² = 1`, `0 ≤ z ≤ 2` as 4 ruled patches.
pub fn tube() -> Vec<BezierPatch<Rational>> {
    (0..4)
        .map(|k| {
            let arc = |z: i64| {
                BezierCurve::from_homogeneous(
                    quarter(k)
                        .iter()
                        .map(|[w, c, s]| vec![w.clone(), c.clone(), s.clone(), w.clone() * int(z)])
                        .collect(),
                )
                .expect("valid")
            };
            BezierPatch::from_curves_ruled(&arc(0), &arc(2)).expect("same dimension")
        })
        .collect()
}

/// A rational bicubic patch with varied weights and non-dyadic coordinates.
pub fn bicubic() -> BezierPatch<Rational> {
    let net = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| {
                    let w = q(1 + ((i * 3 + j * 5) % 4) as i64, 2);
                    let x = q(i as i64, 3);
                    let y = q(j as i64, 3) + q(i as i64, 7);
                    let z = q(((i * j) % 5) as i64 - 2, 9);
                    vec![w.clone(), w.clone() * x, w.clone() * y, w * z]
                })
                .collect()
        })
        .collect();
    BezierPatch::from_homogeneous(net).expect("valid net")
}

/// The unit circle in the plane as 4 rational quadratic pieces.
pub fn circle() -> Vec<BezierCurve<Rational>> {
    (0..4)
        .map(|k| {
            BezierCurve::from_homogeneous(quarter(k).iter().map(|p| p.to_vec()).collect())
                .expect("valid")
        })
        .collect()
}

/// A spatial rational cubic.
pub fn space_cubic() -> BezierCurve<Rational> {
    BezierCurve::from_homogeneous(vec![
        vec![int(1), int(0), int(0), int(0)],
        vec![q(2, 3), q(1, 3), q(2, 3), q(1, 7)],
        vec![q(3, 2), q(3, 2), q(-1, 2), q(3, 5)],
        vec![int(1), int(2), int(1), int(1)],
    ])
    .expect("valid")
}
