//! Envelopes of two-parameter sphere families (docs/BENCHMARKS.md, section "Sphere-family
//! envelopes: the thirteen subcases").
//!
//! D. Gruber, "Rationale Parametrisierungen von Kugelhüllflächen" (2008), §3.3–3.5: the
//! thirteen printed subcases (net, support functions) and the genuine secant elliptic net,
//! each built exactly over `Q` (`SphereFamilyEnvelope::from_data`: the linear system (3.7),
//! the reparametrization (3.16), `Ψ(s, t)`) and certified exactly (`certify()`: consistency,
//! (3.7), tangency (3.8), fibration, `|Ψ − π(Φ)|² ≡ Φ₄²` and both tangency identities as
//! polynomial identities in `s, t`). The summary (bidegree and total degree of the
//! homogeneous `Ψ(s, t)`, positive-weight export patches on the gallery rectangle and their
//! control points) is printed once before the timings.
//!
//! Run: `cargo bench -p rcagd-benches --features bench --bench sphere_family -- --warm-up-time 1 --measurement-time 3`.

use criterion::{criterion_group, criterion_main, Criterion};
use rcagd::envelope::SphereFamilyEnvelope;
use rcagd::lines::NetKind;
use rcagd::Certified;
use rcagd_algebra::{Rational, Scalar};
use std::hint::black_box;

/// One subcase: net data as in `examples/recipes/sphere_family.toml`.
struct Case {
    section: &'static str,
    kind: NetKind,
    points: [[i64; 4]; 4],
    /// `a` as power coefficients `a[i][j]` of `uⁱvʲ`.
    a: &'static [&'static [i64]],
    /// `b` (elliptic: `None`, i.e. `ā(v)`).
    b: Option<&'static [&'static [i64]]>,
    /// The gallery rectangle `[s₀, s₁] × [t₀, t₁]` as `(num, den)` pairs.
    domain: [(i64, i64); 4],
    /// The implicit degree the thesis states ("Grad der algebraischen Fläche").
    thesis_degree: usize,
}

const U2: &[&[i64]] = &[&[0], &[0], &[1]];
const U2X2: &[&[i64]] = &[&[0], &[0], &[2]];
const V2: &[&[i64]] = &[&[0, 0, 1]];
const V2X2: &[&[i64]] = &[&[0, 0, 2]];
const TWO_UV: &[&[i64]] = &[&[0, 0], &[0, 2]];
const D1: [(i64, i64); 4] = [(1, 4), (1, 1), (1, 4), (1, 1)];

const CASES: &[Case] = &[
    Case {
        section: "3.3.1",
        kind: NetKind::Hyperbolic,
        points: [[1, 0, 0, 0], [0, 1, 0, 0], [0, 2, 0, 1], [0, 0, 1, 0]],
        a: U2,
        b: Some(V2),
        domain: D1,
        thesis_degree: 18,
    },
    Case {
        section: "3.3.2",
        kind: NetKind::Hyperbolic,
        points: [[1, 0, 0, 0], [0, 0, 0, 1], [0, 1, 0, 2], [0, 0, 1, 0]],
        a: U2,
        b: Some(V2),
        domain: D1,
        thesis_degree: 18,
    },
    Case {
        section: "3.3.3",
        kind: NetKind::Hyperbolic,
        points: [[1, 0, 0, 1], [0, 1, 0, 0], [1, 0, 0, -1], [0, 0, 1, 0]],
        a: U2X2,
        b: Some(V2X2),
        domain: D1,
        thesis_degree: 26,
    },
    Case {
        section: "3.3.4",
        kind: NetKind::Hyperbolic,
        points: [[1, 0, 0, 0], [0, 1, 0, 0], [0, 1, 0, 2], [0, 0, 1, 0]],
        a: U2X2,
        b: Some(V2X2),
        domain: D1,
        thesis_degree: 18,
    },
    Case {
        section: "3.3.4p",
        kind: NetKind::Hyperbolic,
        points: [[1, 0, 0, 0], [0, 0, 0, -1], [0, 1, 0, 0], [0, 0, 1, 0]],
        a: U2,
        b: Some(V2),
        domain: D1,
        thesis_degree: 6,
    },
    Case {
        section: "3.3.5",
        kind: NetKind::Hyperbolic,
        points: [[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
        a: U2,
        b: Some(V2),
        domain: [(1, 4), (1, 2), (1, 4), (1, 2)],
        thesis_degree: 18,
    },
    Case {
        section: "3.3.6",
        kind: NetKind::Hyperbolic,
        points: [[1, 0, 0, 0], [0, 0, 1, 0], [1, 0, 0, 1], [0, 1, 0, 0]],
        a: U2,
        b: Some(V2),
        domain: D1,
        thesis_degree: 15,
    },
    // the printed 3.4.1 (its axes are tangents of Ω, not secants)
    Case {
        section: "3.4.1",
        kind: NetKind::Elliptic,
        points: [[0, 0, 0, 1], [0, 1, 0, 0], [1, 0, 0, 0], [0, 0, 1, 0]],
        a: U2,
        b: None,
        domain: D1,
        thesis_degree: 18,
    },
    Case {
        section: "3.4.2",
        kind: NetKind::Elliptic,
        points: [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
        a: U2,
        b: None,
        domain: D1,
        thesis_degree: 12,
    },
    Case {
        section: "3.5.1",
        kind: NetKind::Parabolic,
        points: [[1, 0, 0, 0], [0, 0, 1, 0], [0, 1, 0, 0], [0, 0, 0, 1]],
        a: U2,
        b: Some(TWO_UV),
        domain: D1,
        thesis_degree: 14,
    },
    Case {
        section: "3.5.2",
        kind: NetKind::Parabolic,
        points: [[1, 0, 0, 0], [0, 0, 0, 1], [1, -1, 0, 0], [0, 0, 1, 0]],
        a: U2,
        b: Some(TWO_UV),
        domain: D1,
        thesis_degree: 14,
    },
    Case {
        section: "3.5.3a",
        kind: NetKind::Parabolic,
        points: [[1, 0, 0, 1], [0, 0, 1, 0], [0, 1, 0, 0], [0, 0, 0, 1]],
        a: U2,
        b: Some(TWO_UV),
        domain: D1,
        thesis_degree: 12,
    },
    Case {
        section: "3.5.3b",
        kind: NetKind::Parabolic,
        points: [[1, 0, 0, 1], [0, 0, 1, 0], [0, -1, 0, 1], [1, 0, 0, 0]],
        a: U2,
        b: Some(TWO_UV),
        domain: D1,
        thesis_degree: 12,
    },
    // not in the thesis: a genuine secant elliptic net (§3.4.1 proper), c(u) = (2, u, i, u i)
    Case {
        section: "3.4.1 secant",
        kind: NetKind::Elliptic,
        points: [[2, 0, 0, 0], [0, 0, 1, 0], [0, 1, 0, 0], [0, 0, 0, 1]],
        a: U2,
        b: None,
        domain: D1,
        thesis_degree: 18,
    },
];

fn grid(g: &[&[i64]]) -> Vec<Vec<Rational>> {
    g.iter()
        .map(|r| r.iter().map(|&x| Rational::from(x)).collect())
        .collect()
}

fn build(c: &Case) -> SphereFamilyEnvelope<Rational> {
    let rows: Vec<Vec<Rational>> = c
        .points
        .iter()
        .map(|p| p.iter().map(|&x| Rational::from(x)).collect())
        .collect();
    let b = c.b.map(grid);
    SphereFamilyEnvelope::from_data(c.kind, &rows, &grid(c.a), None, b.as_deref(), [None, None])
        .expect("envelope")
}

fn bench(c: &mut Criterion) {
    println!("| § | bidegree of Ψ | total degree | export patches | control points | certificates | thesis degree |");
    for case in CASES {
        let env = build(case);
        let certs = env.certify();
        let q = |(n, d): (i64, i64)| Rational::from_ratio(n, d);
        let [s0, s1, t0, t1] = case.domain.map(q);
        let (patches, weights) = env.export_patches((s0, s1), (t0, t1)).expect("patches");
        let cps: usize = patches
            .iter()
            .map(|p| (p.degree().0 + 1) * (p.degree().1 + 1))
            .sum();
        let hold = certs.iter().all(|c| c.holds) && weights.holds;
        println!(
            "| {} | {:?} | {} | {} | {cps} | {} (all hold: {hold}) | {} |",
            case.section,
            env.bidegree(),
            env.total_degree(),
            patches.len(),
            certs.len(),
            case.thesis_degree,
        );
    }
    let mut g = c.benchmark_group("sphere_family");
    g.sample_size(10);
    for case in CASES {
        g.bench_function(format!("{} build", case.section), |b| {
            b.iter(|| black_box(build(case)))
        });
        g.bench_function(format!("{} build+certify", case.section), |b| {
            b.iter(|| {
                let env = build(case);
                black_box(env.certify())
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
