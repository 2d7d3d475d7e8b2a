//! Krasauskas' reduced pencil vs Peternell–Pottmann for rational canal surfaces
//! (docs/BENCHMARKS.md, section "Canal surfaces: Krasauskas' reduced pencil").
//!
//! The ring torus (`R = 2`, `ρ = 1/2`) and the ring Dupin cyclide of the gallery
//! (`dupin_canal` with `ρ = 4`, `r₀ = 3/2`, `s = 1/7`) as envelopes of rational circle
//! families on `t ∈ [0, 1]`: the exact build with each method (`rcagd::canal::Method`),
//! its bidegree and control-point count (domain patches), and the time of build and
//! certification. The summary is printed once before the timings.
//!
//! Run: `cargo bench -p rcagd-benches --features bench --bench canal_degree -- --warm-up-time 1 --measurement-time 3`.

use criterion::{criterion_group, criterion_main, Criterion};
use rcagd::canal::{canal_surface, CanalBuild, CanalOptions, CanalSpine, Method};
use rcagd::Certified;
use rcagd_algebra::{Poly, Rational, Scalar};
use std::hint::black_box;

fn torus() -> CanalSpine<Rational> {
    let w = Poly::from_ints(&[1, 0, 1]);
    let m = [
        Poly::from_ints(&[2, 0, -2]),
        Poly::from_ints(&[0, 4]),
        Poly::zero(),
    ];
    let r = w.scale(&Rational::from_ratio(1, 2));
    CanalSpine::new(w, m, r).expect("torus family")
}

fn dupin() -> CanalSpine<Rational> {
    // a = 25/24, b = 7/24 (s = 1/7), ρ = 4, r₀ = 3/2
    let w = Poly::from_ints(&[1, 0, 1]);
    let rho = Rational::from(4);
    let (a, b) = (Rational::from_ratio(25, 24), Rational::from_ratio(7, 24));
    let cos = Poly::from_ints(&[1, 0, -1]);
    let sin = Poly::from_ints(&[0, 2]);
    let m = [cos.scale(&rho), sin.scale(&(rho.clone() * a)), Poly::zero()];
    let r = &w.scale(&Rational::from_ratio(3, 2)) + &sin.scale(&(rho * b));
    CanalSpine::new(w, m, r).expect("Dupin family")
}

fn options(method: Method) -> CanalOptions {
    CanalOptions {
        method,
        domain: Some((Rational::from(0), Rational::from(1))),
        ..CanalOptions::default()
    }
}

fn build(spine: &CanalSpine<Rational>, method: Method) -> CanalBuild {
    canal_surface(spine, &options(method)).expect("canal surface")
}

fn bench(c: &mut Criterion) {
    let cases = [("torus", torus()), ("dupin", dupin())];
    for (name, spine) in &cases {
        for method in [Method::PeternellPottmann, Method::Krasauskas] {
            let b = build(spine, method);
            let s = b.as_rational().expect("rational");
            let patches = s.domain_patches().expect("patches");
            let cps: usize = patches
                .iter()
                .map(|p| (p.degree().0 + 1) * (p.degree().1 + 1))
                .sum();
            let positive = patches
                .iter()
                .all(|p| p.weights().iter().all(|w| *w > Rational::ZERO));
            println!(
                "{name} {method:?}: bidegree {:?}, {} domain patches, {cps} control points, positive weights: {positive}, certificates hold: {}",
                b.degree(),
                patches.len(),
                b.all_hold()
            );
        }
    }
    let mut g = c.benchmark_group("canal_degree");
    g.sample_size(10);
    for (name, spine) in &cases {
        for (label, method) in [
            ("pp", Method::PeternellPottmann),
            ("krasauskas", Method::Krasauskas),
            ("lowest", Method::Lowest),
        ] {
            g.bench_function(format!("{name}_{label}_build"), |bch| {
                bch.iter(|| build(black_box(spine), method))
            });
        }
        for (label, method) in [
            ("pp", Method::PeternellPottmann),
            ("krasauskas", Method::Krasauskas),
        ] {
            let b = build(spine, method);
            g.bench_function(format!("{name}_{label}_certify"), |bch| {
                bch.iter(|| black_box(&b).certify())
            });
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
