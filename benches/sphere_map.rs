//! Mapping a rational bicubic patch (bidegree (3,3)) onto the unit sphere by Jüttler's
//! δ (Jüttler (9); docs/math/quadrics.md, "The map δ onto the sphere": polar-form rule, result bidegree (6,6)) and certifying
//! `Xᵀ Q X ≡ 0`, exact (`Rational`) and `f64`; in the same run the peer comparison of the
//! two ways to get points of the sphere patch on a 32 × 32 grid:
//!
//! * `grid_mapped_patch_32` — evaluate the mapped (6,6) patch with
//!   [`rcagd_geom::grid::eval_patch_grid`] (the patch is computed once, outside the loop);
//! * `map_then_grid_32` — the same including the mapping `patch_image` (f64) per iteration;
//! * `kernel_pointwise_delta_32` — the "kernel" way: evaluate the (3,3) preimage on the
//!   grid with `eval_patch_grid`, then map every point through δ and dehomogenize.
//!
//! The three agree to 1e-12 (checked before timing). δ is quadratic and homogeneous, so
//! `δ(1, x) = δ(w, w·x)/w²` is the same projective point.
//!
//! Run: `cargo bench -p rcagd-benches --features bench --bench sphere_map -- --warm-up-time 1 --measurement-time 3`

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use rcagd::quadric::image::certify_patch_on_quadric;
use rcagd::quadric::stereographic::{delta, sphere_matrix};
use rcagd::quadric::{patch_image, Delta};
use rcagd::Certified;
use rcagd_algebra::{Rational, Scalar};
use rcagd_geom::grid::{eval_patch_grid, linspace};
use rcagd_geom::BezierPatch;
use std::hint::black_box;

const G: usize = 32;

/// A rational bicubic patch in E³ with weights in `{1, 5/4, 3/2, 2}` (dyadic data: the
/// `f64` and exact patches are equal).
fn net() -> Vec<Vec<Vec<Rational>>> {
    let ws = [
        Rational::from(1),
        Rational::from_ratio(5, 4),
        Rational::from_ratio(3, 2),
        Rational::from(2),
    ];
    (0..4i64)
        .map(|i| {
            (0..4i64)
                .map(|j| {
                    let w = ws[((i + 2 * j + i * j) % 4) as usize].clone();
                    let x = Rational::from(i) / Rational::from(3)
                        + Rational::from(j) / Rational::from(16);
                    let y = Rational::from(j) / Rational::from(3)
                        - Rational::from(i) / Rational::from(8);
                    let z = Rational::from((i * 3 + j * 5) % 7 - 3) / Rational::from(4);
                    vec![w.clone(), w.clone() * x, w.clone() * y, w * z]
                })
                .collect()
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let exact = BezierPatch::from_homogeneous(net()).expect("net");
    let float = exact.to_f64();
    let q_exact = sphere_matrix::<Rational>();
    let q_float = sphere_matrix::<f64>();

    // correctness before timing
    let img_exact = patch_image(&Delta, &exact).expect("exact image");
    assert!(img_exact.all_hold(), "exact certificates");
    assert_eq!(img_exact.image().degree(), (6, 6));
    let img_float = patch_image(&Delta, &float).expect("f64 image");
    assert!(img_float.all_hold(), "f64 certificates");
    let us = linspace(0.0, 1.0, G);
    let mut grid_a = Vec::new();
    eval_patch_grid(img_float.image(), &us, &us, &mut grid_a).expect("grid");
    let kernel = |out: &mut Vec<[f64; 3]>, pre: &mut Vec<[f64; 3]>| {
        eval_patch_grid(&float, &us, &us, pre).expect("grid");
        out.clear();
        out.extend(pre.iter().map(|&[x, y, z]| {
            let k = delta(&[1.0, x, y, z]);
            [k[1] / k[0], k[2] / k[0], k[3] / k[0]]
        }));
    };
    let (mut grid_b, mut pre) = (Vec::new(), Vec::new());
    kernel(&mut grid_b, &mut pre);
    let err = grid_a
        .iter()
        .zip(&grid_b)
        .flat_map(|(a, b)| a.iter().zip(b).map(|(x, y)| (x - y).abs()))
        .fold(0.0, f64::max);
    assert!(err < 1e-12, "grid vs pointwise δ: {err}");
    for p in &grid_a {
        let r = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
        assert!((r - 1.0).abs() < 1e-12, "off the sphere: {r}");
    }

    let mut g = c.benchmark_group("sphere_map");
    g.sample_size(10);
    g.bench_function("exact_map_delta_3x3", |b| {
        b.iter(|| patch_image(&Delta, black_box(&exact)).expect("image"))
    });
    g.bench_function("exact_certify_on_sphere_6x6", |b| {
        b.iter(|| {
            let c = certify_patch_on_quadric(black_box(img_exact.image()), &q_exact, "on K");
            assert!(c.holds);
        })
    });
    g.bench_function("exact_map_and_certify_all", |b| {
        b.iter(|| {
            let img = patch_image(&Delta, black_box(&exact)).expect("image");
            assert!(img.all_hold());
        })
    });
    g.bench_function("f64_map_delta_3x3", |b| {
        b.iter(|| patch_image(&Delta, black_box(&float)).expect("image"))
    });
    g.bench_function("f64_certify_on_sphere_6x6", |b| {
        b.iter(|| {
            let c = certify_patch_on_quadric(black_box(img_float.image()), &q_float, "on K");
            assert!(c.holds);
        })
    });
    g.throughput(Throughput::Elements((G * G) as u64));
    let mut out = Vec::new();
    g.bench_function("grid_mapped_patch_32", |b| {
        b.iter(|| eval_patch_grid(black_box(img_float.image()), &us, &us, &mut out).expect("grid"))
    });
    g.bench_function("map_then_grid_32", |b| {
        b.iter(|| {
            let img = patch_image(&Delta, black_box(&float)).expect("image");
            eval_patch_grid(img.image(), &us, &us, &mut out).expect("grid")
        })
    });
    g.bench_function("kernel_pointwise_delta_32", |b| {
        b.iter(|| kernel(black_box(&mut out), &mut pre))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
