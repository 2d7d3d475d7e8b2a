//! Grid evaluation of one rational bicubic patch in E3 (non-trivial weights) on a
//! 1000 × 1000 grid (10⁶ points), in the same run:
//!
//! * `rcagd_eval_patch_grid` — [`rcagd_geom::grid::eval_patch_grid`] (row collapse);
//! * `baseline_tensor_4x4` — a hand-written fixed-degree loop: precomputed Bernstein
//!   values, the straightforward `Σᵢ Σⱼ Bᵢ(u) Bⱼ(v) Pᵢⱼ` 4 × 4 tensor sum per point;
//! * `baseline_row_collapse_4x4` — the same row-collapse scheme as rcagd, hand-written
//!   for degree 3 (the near-limit of rcagd's own algorithm);
//! * `curvo_regular_sample_points` — curvo 0.3 `NurbsSurface3D::regular_sample_points`
//!   (its batched grid evaluation with precomputed basis functions);
//! * `curvo_evaluator_point_at` — curvo's per-point `SurfaceEvaluator::point_at`;
//! * `rcagd_exact_*` — exact [`Rational`] evaluation on a 12 × 12 grid, per point.
//!
//! Every method's results are checked against `eval_patch_grid` (to 1e-9, the exact
//! points to 1e-12) before timing. Throughput is in grid points.
//!
//! Run: `cargo bench -p rcagd-benches --features bench --bench grid_eval -- --warm-up-time 1 --measurement-time 3`

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use curvo::prelude::NurbsSurface3D;
use nalgebra::Point4;
use rcagd_algebra::{Rational, Scalar};
use rcagd_geom::grid::{eval_patch_grid, linspace};
use rcagd_geom::nurbs::NurbsSurface;
use rcagd_geom::BezierPatch;
use std::hint::black_box;

const N: usize = 1000;
const EXACT_N: usize = 12;

/// The benchmark patch: a bicubic wave over the unit square with weights in
/// `{1, 5/4, 3/2, 2}`; all numbers are dyadic, so the f64 and exact patches are equal.
fn net() -> Vec<Vec<[Rational; 4]>> {
    let ws = [
        Rational::from(1),
        Rational::from_ratio(5, 4),
        Rational::from_ratio(3, 2),
        Rational::from(2),
    ];
    (0..4)
        .map(|i| {
            (0..4)
                .map(|j| {
                    let w = ws[(i + 2 * j + i * j) % 4].clone();
                    let x = Rational::from_ratio(i as i64, 3) + Rational::from_ratio(j as i64, 16);
                    let y = Rational::from_ratio(j as i64, 3) - Rational::from_ratio(i as i64, 8);
                    let z = Rational::from_ratio(((i * 3 + j * 5) % 7) as i64 - 3, 4);
                    [w.clone(), w.clone() * x, w.clone() * y, w * z]
                })
                .collect()
        })
        .collect()
}

fn exact_patch() -> BezierPatch<Rational> {
    BezierPatch::from_homogeneous(
        net()
            .into_iter()
            .map(|row| row.into_iter().map(|p| p.to_vec()).collect())
            .collect(),
    )
    .expect("valid net")
}

fn f64_patch() -> BezierPatch<f64> {
    BezierPatch::from_homogeneous(
        net()
            .into_iter()
            .map(|row| {
                row.iter()
                    .map(|p| p.iter().map(Scalar::to_f64).collect())
                    .collect()
            })
            .collect(),
    )
    .expect("valid net")
}

fn bernstein3(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    [s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t]
}

/// The near-limit baseline: fixed 4 × 4 tensor loop, Bernstein values precomputed once
/// per call for every u and every v (included in the timing, as in rcagd's call); the
/// points are written per grid row with `Vec::extend`, as rcagd writes them.
fn baseline(net: &[[[f64; 4]; 4]; 4], us: &[f64], vs: &[f64], out: &mut Vec<[f64; 3]>) {
    out.clear();
    let bu: Vec<[f64; 4]> = us.iter().map(|&u| bernstein3(u)).collect();
    let bv: Vec<[f64; 4]> = vs.iter().map(|&v| bernstein3(v)).collect();
    for a in &bu {
        out.extend(bv.iter().map(|b| {
            let mut h = [0.0f64; 4];
            for i in 0..4 {
                for j in 0..4 {
                    let bij = a[i] * b[j];
                    for c in 0..4 {
                        h[c] += bij * net[i][j][c];
                    }
                }
            }
            let r = 1.0 / h[0];
            [h[1] * r, h[2] * r, h[3] * r]
        }));
    }
}

/// A second hand-written baseline: the same row-collapse scheme as rcagd, fixed to
/// degree 3 (`Qⱼ(u) = Σᵢ Bᵢ(u) Pᵢⱼ` once per row, then `Σⱼ Bⱼ(v) Qⱼ` per point). This
/// is the near-limit for rcagd's algorithm: the ratio to it measures rcagd's overhead.
fn baseline_row_collapse(
    net: &[[[f64; 4]; 4]; 4],
    us: &[f64],
    vs: &[f64],
    out: &mut Vec<[f64; 3]>,
) {
    out.clear();
    let bv: Vec<[f64; 4]> = vs.iter().map(|&v| bernstein3(v)).collect();
    for &u in us {
        let a = bernstein3(u);
        let mut q = [[0.0f64; 4]; 4];
        for i in 0..4 {
            for j in 0..4 {
                for c in 0..4 {
                    q[j][c] += a[i] * net[i][j][c];
                }
            }
        }
        out.extend(bv.iter().map(|b| {
            let mut h = [0.0f64; 4];
            for j in 0..4 {
                for c in 0..4 {
                    h[c] += b[j] * q[j][c];
                }
            }
            let r = 1.0 / h[0];
            [h[1] * r, h[2] * r, h[3] * r]
        }));
    }
}

fn curvo_surface(p: &BezierPatch<f64>) -> NurbsSurface3D<f64> {
    // curvo stores homogeneous points weight last: (wx, wy, wz, w)
    let cps: Vec<Vec<Point4<f64>>> = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| {
                    let c = p.control_point(i, j);
                    Point4::new(c[1], c[2], c[3], c[0])
                })
                .collect()
        })
        .collect();
    let knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    NurbsSurface3D::new(3, 3, knots.clone(), knots, cps)
}

fn max_diff(a: &[[f64; 3]], b: &[[f64; 3]]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .flat_map(|(x, y)| (0..3).map(move |c| (x[c] - y[c]).abs()))
        .fold(0.0, f64::max)
}

fn bench_grid(c: &mut Criterion) {
    let patch = f64_patch();
    let us = linspace(0.0, 1.0, N - 1);
    let vs = linspace(0.0, 1.0, N - 1);
    let mut fixed = [[[0.0f64; 4]; 4]; 4];
    for (i, row) in fixed.iter_mut().enumerate() {
        for (j, p) in row.iter_mut().enumerate() {
            p.copy_from_slice(patch.control_point(i, j));
        }
    }
    let surf = curvo_surface(&patch);

    // ---- agreement checks before timing ----
    let mut ours = Vec::new();
    eval_patch_grid(&patch, &us, &vs, &mut ours).expect("E3 patch");
    let mut base = Vec::new();
    baseline(&fixed, &us, &vs, &mut base);
    let d_base = max_diff(&ours, &base);
    assert!(d_base < 1e-9, "baseline disagrees by {d_base}");
    let mut rc = Vec::new();
    baseline_row_collapse(&fixed, &us, &vs, &mut rc);
    let d_rc = max_diff(&ours, &rc);
    assert!(d_rc < 1e-9, "row-collapse baseline disagrees by {d_rc}");
    let sampled: Vec<[f64; 3]> = surf
        .regular_sample_points(N - 1, N - 1)
        .into_iter()
        .flatten()
        .map(|p| [p.x, p.y, p.z])
        .collect();
    let d_curvo = max_diff(&ours, &sampled);
    assert!(
        d_curvo < 1e-9,
        "curvo regular_sample_points disagrees by {d_curvo}"
    );
    let mut ev = surf.evaluator();
    let mut pointwise = Vec::with_capacity(N * N);
    for &u in &us {
        for &v in &vs {
            let p = ev.point_at(u, v);
            pointwise.push([p.x, p.y, p.z]);
        }
    }
    let d_curvo_pt = max_diff(&ours, &pointwise);
    assert!(
        d_curvo_pt < 1e-9,
        "curvo point_at disagrees by {d_curvo_pt}"
    );
    eprintln!(
        "agreement with eval_patch_grid over 10^6 points: baseline {d_base:.1e}, \
         row-collapse baseline {d_rc:.1e}, \
         curvo regular_sample_points {d_curvo:.1e}, curvo point_at {d_curvo_pt:.1e}"
    );

    let mut g = c.benchmark_group("grid_1000x1000_rational_bicubic");
    g.throughput(Throughput::Elements((N * N) as u64));
    g.sample_size(10);
    let mut out: Vec<[f64; 3]> = Vec::with_capacity(N * N);
    g.bench_function("rcagd_eval_patch_grid", |b| {
        b.iter(|| {
            eval_patch_grid(black_box(&patch), black_box(&us), black_box(&vs), &mut out)
                .expect("E3 patch");
            black_box(out.last().copied())
        })
    });
    let mut out2: Vec<[f64; 3]> = Vec::with_capacity(N * N);
    g.bench_function("baseline_tensor_4x4", |b| {
        b.iter(|| {
            baseline(black_box(&fixed), black_box(&us), black_box(&vs), &mut out2);
            black_box(out2.last().copied())
        })
    });
    g.bench_function("baseline_row_collapse_4x4", |b| {
        b.iter(|| {
            baseline_row_collapse(black_box(&fixed), black_box(&us), black_box(&vs), &mut out2);
            black_box(out2.last().copied())
        })
    });
    g.bench_function("curvo_regular_sample_points", |b| {
        b.iter(|| black_box(surf.regular_sample_points(black_box(N - 1), black_box(N - 1))))
    });
    let mut out3: Vec<[f64; 3]> = Vec::with_capacity(N * N);
    g.bench_function("curvo_evaluator_point_at", |b| {
        b.iter(|| {
            out3.clear();
            let mut ev = surf.evaluator();
            for &u in black_box(&us) {
                for &v in black_box(&vs) {
                    let p = ev.point_at(u, v);
                    out3.push([p.x, p.y, p.z]);
                }
            }
            black_box(out3.last().copied())
        })
    });
    g.finish();
}

fn bench_exact(c: &mut Criterion) {
    let exact = exact_patch();
    let nurbs = NurbsSurface::from_bezier(&exact).expect("valid");
    let params: Vec<Rational> = (0..EXACT_N)
        .map(|k| Rational::from_ratio(k as i64, (EXACT_N - 1) as i64))
        .collect();
    // check against the f64 grid before timing
    let pf: Vec<f64> = params.iter().map(Scalar::to_f64).collect();
    let mut fast = Vec::new();
    eval_patch_grid(&f64_patch(), &pf, &pf, &mut fast).expect("E3 patch");
    for (i, u) in params.iter().enumerate() {
        for (j, v) in params.iter().enumerate() {
            let e = exact.eval(u, v).expect("finite");
            let d = nurbs.eval(u, v).expect("finite");
            assert_eq!(e, d, "Bézier and NURBS exact evaluation disagree");
            let f = fast[i * EXACT_N + j];
            for k in 0..3 {
                let x = Scalar::to_f64(&e[k]);
                assert!((x - f[k]).abs() <= 1e-12 * x.abs().max(1.0));
            }
        }
    }
    let mut g = c.benchmark_group("exact_rational_bicubic_12x12");
    g.throughput(Throughput::Elements((EXACT_N * EXACT_N) as u64));
    g.sample_size(10);
    g.bench_function("rcagd_exact_bezier_eval", |b| {
        b.iter(|| {
            for u in &params {
                for v in &params {
                    black_box(exact.eval(black_box(u), black_box(v)).expect("finite"));
                }
            }
        })
    });
    g.bench_function("rcagd_exact_nurbs_de_boor", |b| {
        b.iter(|| {
            for u in &params {
                for v in &params {
                    black_box(nurbs.eval(black_box(u), black_box(v)).expect("finite"));
                }
            }
        })
    });
    g.finish();
}

criterion_group!(benches, bench_grid, bench_exact);
criterion_main!(benches);
