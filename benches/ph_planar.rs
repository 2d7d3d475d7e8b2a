//! Planar PH benchmarks (issue 5 part B; results in docs/BENCHMARKS.md, "Planar PH").
//!
//! * `hermite/*`: planar PH quintic C1 Hermite interpolation in `f64` — the four
//!   preimages plus the exact (polynomial) arc length of each, and the full solve with
//!   the shape measures (absolute rotation index, bending energy by quadrature); peer:
//!   the cubic Hermite polynomial of the same data plus its arc length by composite
//!   7-point Gauss–Legendre quadrature on 16 sub-intervals (what a kernel does without
//!   PH curves).
//! * `spline/*`: C2 PH quintic spline through N points in `f64` (Newton–Raphson on the
//!   complex tridiagonal system, segments, exact arc length), per segment; peer: the
//!   natural C2 cubic spline through the same points (tridiagonal solve) plus numeric arc
//!   length as above.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use rcagd::ph::planar::gauss7;
use rcagd::ph::{PhQuinticSpline, PlanarHermiteData, PlanarPhCurve, SplineEnds};
use std::hint::black_box;

fn hermite_data(k: usize) -> PlanarHermiteData<f64> {
    let a = k as f64 * 0.1;
    PlanarHermiteData::new(
        [0.0, 0.0],
        [1.0 + a.cos(), 0.5 + a.sin()],
        [1.0 + 0.3 * a.sin(), 0.7],
        [0.8, -0.9 + 0.2 * a.cos()],
    )
}

/// Arc length of a planar polynomial curve given by its power-form derivative
/// components, by composite 7-point Gauss–Legendre on `pieces` sub-intervals.
fn numeric_length(dx: &[f64], dy: &[f64], pieces: usize) -> f64 {
    let ev = |c: &[f64], t: f64| c.iter().rev().fold(0.0, |acc, a| acc * t + a);
    let f = |t: f64| ev(dx, t).hypot(ev(dy, t));
    (0..pieces)
        .map(|i| {
            let a = i as f64 / pieces as f64;
            let b = (i + 1) as f64 / pieces as f64;
            gauss7(&f, a, b)
        })
        .sum()
}

/// The cubic Hermite curve of the data and its numeric arc length.
fn cubic_hermite_length(d: &PlanarHermiteData<f64>) -> f64 {
    // r(t) = p0 h00 + d0 h10 + p1 h01 + d1 h11; r'(t) in power form:
    // r' = d0 + (−6p0 − 4d0 + 6p1 − 2d1) t + (6p0 + 3d0 − 6p1 + 3d1) t²
    let comp = |k: usize| {
        [
            d.d0[k],
            -6.0 * d.p0[k] - 4.0 * d.d0[k] + 6.0 * d.p1[k] - 2.0 * d.d1[k],
            6.0 * d.p0[k] + 3.0 * d.d0[k] - 6.0 * d.p1[k] + 3.0 * d.d1[k],
        ]
    };
    numeric_length(&comp(0), &comp(1), 16)
}

fn bench_hermite(c: &mut Criterion) {
    let data: Vec<PlanarHermiteData<f64>> = (0..64).map(hermite_data).collect();
    let mut g = c.benchmark_group("hermite");
    g.throughput(Throughput::Elements(data.len() as u64));
    g.bench_function("ph_quintic_preimages_and_arc_length", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for d in &data {
                for w in d.quintic_preimages().unwrap() {
                    let curve = PlanarPhCurve::new(w.to_vec(), d.p0).unwrap();
                    acc += curve.arc_length();
                }
            }
            black_box(acc)
        })
    });
    g.bench_function("ph_quintic_full_solve_with_shape_measures", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for d in &data {
                let s = d.solve().unwrap();
                acc += s.best().map(|x| x.bending_energy).unwrap_or(0.0);
            }
            black_box(acc)
        })
    });
    g.bench_function("peer_cubic_hermite_gauss_legendre_length", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for d in &data {
                acc += cubic_hermite_length(d);
            }
            black_box(acc)
        })
    });
    g.finish();
}

/// Natural C2 cubic spline (uniform parameter, one unit per span) through the points,
/// plus the numeric arc length of every span.
fn cubic_spline_length(p: &[[f64; 2]]) -> f64 {
    let n = p.len() - 1;
    // second derivatives M_i per coordinate: M_{i−1} + 4M_i + M_{i+1} =
    // 6(p_{i+1} − 2p_i + p_{i−1}), M_0 = M_n = 0 (Thomas algorithm)
    let second = |k: usize| {
        let m = n - 1;
        let mut cp = vec![0.0; m];
        let mut dp = vec![0.0; m];
        for i in 0..m {
            let rhs = 6.0 * (p[i + 2][k] - 2.0 * p[i + 1][k] + p[i][k]);
            let (prev_c, prev_d) = if i > 0 {
                (cp[i - 1], dp[i - 1])
            } else {
                (0.0, 0.0)
            };
            let den = 4.0 - prev_c;
            cp[i] = 1.0 / den;
            dp[i] = (rhs - prev_d) / den;
        }
        let mut mm = vec![0.0; n + 1];
        for i in (0..m).rev() {
            mm[i + 1] = dp[i] - cp[i] * mm[i + 2];
        }
        mm
    };
    let s = [second(0), second(1)];
    let mut total = 0.0;
    for i in 0..n {
        // span i: r'(t) = (p_{i+1} − p_i) − (2M_i + M_{i+1})/6 + M_i t + (M_{i+1} − M_i) t²/2
        let comp = |k: usize| {
            let (a, b) = (s[k][i], s[k][i + 1]);
            [
                p[i + 1][k] - p[i][k] - (2.0 * a + b) / 6.0,
                a,
                (b - a) / 2.0,
            ]
        };
        total += numeric_length(&comp(0), &comp(1), 16);
    }
    total
}

fn bench_spline(c: &mut Criterion) {
    let mut g = c.benchmark_group("spline");
    for n in [16usize, 64] {
        let pts: Vec<[f64; 2]> = (0..=n)
            .map(|i| {
                let t = i as f64;
                [t, (0.7 * t).sin() + 0.3 * (1.9 * t).cos()]
            })
            .collect();
        g.throughput(Throughput::Elements(n as u64));
        g.bench_with_input(
            BenchmarkId::new("ph_quintic_c2_natural", n),
            &pts,
            |b, pts| {
                b.iter(|| {
                    let s = PhQuinticSpline::interpolate(pts, &SplineEnds::Natural).unwrap();
                    black_box(s.arc_length())
                })
            },
        );
        let closed = &pts[..n];
        g.bench_with_input(
            BenchmarkId::new("ph_quintic_c2_closed", n),
            closed,
            |b, pts| {
                b.iter(|| {
                    let s = PhQuinticSpline::interpolate(pts, &SplineEnds::Closed);
                    black_box(s.map(|s| s.arc_length()).unwrap_or(0.0))
                })
            },
        );
        g.bench_with_input(
            BenchmarkId::new("peer_cubic_c2_natural_gauss_legendre_length", n),
            &pts,
            |b, pts| b.iter(|| black_box(cubic_spline_length(pts))),
        );
    }
    g.finish();
}

criterion_group!(benches, bench_hermite, bench_spline);
criterion_main!(benches);
