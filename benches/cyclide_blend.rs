//! Cyclide blends between two cylinders: rcagd's exact blend (the timing half of the
//! comparison with OpenCascade in `benches/occ/cyclide_blend.py`).
//!
//! Two cases, the blends of examples/recipes/cyclide.toml:
//!
//! * `elbow`: cylinders of radius 1 with axes x and y, blended by the quarter of the torus
//!   with major radius 2 (contact spheres `(2, 0, 0; 1)` and `(0, 2, 0; 1)`);
//! * `parallel`: parallel cylinders (axes along z) of radii 1 and 2 through `(0, 0)` and
//!   `(4, 1)`, blended by half of a ring cyclide (contact spheres `(0, 0, 0; 1)`,
//!   `(4, 1, 0; 2)`).
//!
//! Timed: `exact_build` (`blend_cones` over Q and its rational Bézier patches),
//! `exact_certify` (every certificate of the blend, exact polynomial identities),
//! `f64_build` (the same construction in `f64`). Before timing, the patch count, bidegree
//! and control-point count are printed.
//!
//! Run: `cargo bench -p rcagd-benches --features bench --bench cyclide_blend -- --warm-up-time 1 --measurement-time 3`
//! (or `bash benches/occ/cyclide_blend.sh` for both halves of the comparison in one run).

use criterion::{criterion_group, criterion_main, Criterion};
use rcagd::cyclide::blend_cones;
use rcagd_algebra::{Rational, Scalar};
use std::hint::black_box;

type Q = Rational;

/// `(name, P₁, d₁, P₂, d₂)` of a case, as integers.
type Case = (&'static str, [i64; 4], [i64; 4], [i64; 4], [i64; 4]);

const CASES: [Case; 2] = [
    (
        "elbow",
        [2, 0, 0, 1],
        [1, 0, 0, 0],
        [0, 2, 0, 1],
        [0, 1, 0, 0],
    ),
    (
        "parallel",
        [0, 0, 0, 1],
        [0, 0, 1, 0],
        [4, 1, 0, 2],
        [0, 0, 1, 0],
    ),
];

fn conv<F: Scalar>(v: [i64; 4]) -> [F; 4] {
    v.map(F::from_i64)
}

fn report() {
    for (name, p1, d1, p2, d2) in CASES {
        let blend = blend_cones::<Q>(conv(p1), conv(d1), conv(p2), conv(d2)).expect("blend");
        let patches = blend.patches().expect("patches");
        let points: usize = patches
            .iter()
            .map(|p| {
                let (m, n) = p.degree();
                (m + 1) * (n + 1)
            })
            .sum();
        let certs = blend.certify();
        let holds = certs.iter().all(|c| c.holds);
        println!(
            "cyclide_blend/{name}: {} patches of bidegree ({}, {}), {points} control points, {} certificates, all hold: {holds}",
            patches.len(),
            patches[0].degree().0,
            patches[0].degree().1,
            certs.len()
        );
    }
}

fn bench(c: &mut Criterion) {
    report();
    for (name, p1, d1, p2, d2) in CASES {
        let mut g = c.benchmark_group(format!("cyclide_blend/{name}"));
        g.bench_function("exact_build", |b| {
            b.iter(|| {
                let blend =
                    blend_cones::<Q>(conv(p1), conv(d1), conv(p2), conv(d2)).expect("blend");
                black_box(blend.patches().expect("patches"))
            })
        });
        let blend = blend_cones::<Q>(conv(p1), conv(d1), conv(p2), conv(d2)).expect("blend");
        g.bench_function("exact_certify", |b| {
            b.iter(|| black_box(black_box(&blend).certify()))
        });
        g.bench_function("f64_build", |b| {
            b.iter(|| {
                let blend =
                    blend_cones::<f64>(conv(p1), conv(d1), conv(p2), conv(d2)).expect("blend");
                black_box(blend.patches().expect("patches"))
            })
        });
        g.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
