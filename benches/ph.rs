//! Spatial PH curves (Besednjak, docs/math/ph-curves.md): Hermite solves, arc length and frames, against what a
//! kernel without PH structure does with the same curve.
//!
//! Curve: the least-energy helical PH quintic of Besednjak Example 9.1 (`p_s = 0`,
//! `d_s = (1,0,1)`, `p_f = (1,1,1)`, `d_f = (0,1,1)`), in `f64`. `N = 1000` parameters
//! `t_k = k/(N−1)`.
//!
//! Timed (same run):
//! * `hermite_solve_f64` — the whole chapter-9 solve in `f64` (elimination quartic, real
//!   roots, all interpolants, their bending energies by adaptive Gauss–Kronrod, helix
//!   axes); throughput = solves;
//! * `arc_length_ph` — `s(t_k)` from the exact arc-length polynomial (Horner), per point;
//! * `arc_length_quadrature` — the peer: `∫_0^{t_k} |r'(t)| dt` of the same curve treated
//!   as a generic polynomial curve, adaptive 7-point Gauss–Legendre (interval halving, local
//!   tolerance halved per level) to `1e-12` relative, per point;
//! * `erf_frame` — the rational Euler–Rodrigues frame `(AiA*, AjA*, AkA*)/σ` at `t_k`;
//! * `rmf_double_reflection` — the peer: the rotation-minimizing frame propagated along the
//!   `N` sample points by the double reflection method (Wang, Jüttler, Zheng, Liu 2008),
//!   from the curve points and unit tangents (as a kernel without PH frames does).
//!
//! Reported once before timing: arc length by both methods and their difference, the
//! double-reflection frame's orthonormality defect.
//!
//! Run: `cargo bench -p rcagd-benches --features bench --bench ph -- --warm-up-time 1 --measurement-time 3`

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use rcagd::ph::{HermiteData, PhCurve};
use rcagd_algebra::Poly;
use std::hint::black_box;

const N: usize = 1000;

fn data() -> HermiteData<f64> {
    HermiteData::new(
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 1.0],
        [1.0, 1.0, 1.0],
        [0.0, 1.0, 1.0],
    )
}

fn best_curve() -> PhCurve<f64> {
    let sol = data().solve_f64().expect("Ex 9.1 has solutions");
    sol.best()
        .first()
        .map(|i| i.curve.clone())
        .expect("a least-energy interpolant")
}

fn eval3(p: &[Poly<f64>; 3], t: f64) -> [f64; 3] {
    [p[0].eval(&t), p[1].eval(&t), p[2].eval(&t)]
}

fn norm(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

const GX: [f64; 7] = [
    -0.949_107_912_342_758_5,
    -0.741_531_185_599_394_4,
    -0.405_845_151_377_397_2,
    0.0,
    0.405_845_151_377_397_2,
    0.741_531_185_599_394_4,
    0.949_107_912_342_758_5,
];
const GW: [f64; 7] = [
    0.129_484_966_168_869_7,
    0.279_705_391_489_276_7,
    0.381_830_050_505_118_9,
    0.417_959_183_673_469_4,
    0.381_830_050_505_118_9,
    0.279_705_391_489_276_7,
    0.129_484_966_168_869_7,
];

fn gl7(f: &dyn Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let h = 0.5 * (b - a);
    let c = 0.5 * (a + b);
    GX.iter()
        .zip(GW)
        .map(|(x, w)| w * f(c + h * x))
        .sum::<f64>()
        * h
}

fn adaptive(f: &dyn Fn(f64) -> f64, a: f64, b: f64, whole: f64, eps: f64, depth: u32) -> f64 {
    let m = 0.5 * (a + b);
    let l = gl7(f, a, m);
    let r = gl7(f, m, b);
    if depth == 0 || (l + r - whole).abs() <= eps {
        l + r
    } else {
        adaptive(f, a, m, l, 0.5 * eps, depth - 1) + adaptive(f, m, b, r, 0.5 * eps, depth - 1)
    }
}

/// Generic arc length `∫_0^t |r'|` by adaptive Gauss–Legendre to `tol` relative.
fn arc_length_quadrature(d1: &[Poly<f64>; 3], t: f64, tol: f64) -> f64 {
    if t <= 0.0 {
        return 0.0;
    }
    let f = |x: f64| norm(eval3(d1, x));
    let whole = gl7(&f, 0.0, t);
    adaptive(&f, 0.0, t, whole, tol * whole.abs(), 30)
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn axpy(a: [f64; 3], s: f64, b: [f64; 3]) -> [f64; 3] {
    [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]]
}
fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Double reflection RMF (Wang et al. 2008) along `ts`, starting from `r0 ⊥ t(ts[0])`.
fn rmf(pos: &[Poly<f64>; 3], d1: &[Poly<f64>; 3], ts: &[f64], r0: [f64; 3]) -> Vec<[[f64; 3]; 3]> {
    let unit = |v: [f64; 3]| {
        let n = norm(v);
        [v[0] / n, v[1] / n, v[2] / n]
    };
    let mut out = Vec::with_capacity(ts.len());
    let mut x = eval3(pos, ts[0]);
    let mut t = unit(eval3(d1, ts[0]));
    let mut r = r0;
    out.push([t, r, cross(t, r)]);
    for &s in &ts[1..] {
        let x1 = eval3(pos, s);
        let t1 = unit(eval3(d1, s));
        let v1 = sub(x1, x);
        let c1 = dot(v1, v1);
        let rl = axpy(r, -2.0 / c1 * dot(v1, r), v1);
        let tl = axpy(t, -2.0 / c1 * dot(v1, t), v1);
        let v2 = sub(t1, tl);
        let c2 = dot(v2, v2);
        let r1 = if c2 > 0.0 {
            axpy(rl, -2.0 / c2 * dot(v2, rl), v2)
        } else {
            rl
        };
        out.push([t1, r1, cross(t1, r1)]);
        x = x1;
        t = t1;
        r = r1;
    }
    out
}

fn bench(c: &mut Criterion) {
    let curve = best_curve();
    let pc = curve.to_poly_curve();
    let s_poly = pc.arc_length_poly();
    let pos = pc.position().clone();
    let d1 = pc.hodograph();
    let erf = curve.euler_rodrigues_frame();
    let ts: Vec<f64> = (0..N).map(|k| k as f64 / (N - 1) as f64).collect();

    // accuracy, once
    let s_ph = s_poly.eval(&1.0);
    let s_q = arc_length_quadrature(&d1, 1.0, 1e-12);
    let e0 = erf.eval(&0.0).expect("σ(0) > 0");
    let frames = rmf(&pos, &d1, &ts, e0[1]);
    let defect = frames
        .iter()
        .map(|f| {
            (dot(f[0], f[1]).abs())
                .max((dot(f[1], f[1]) - 1.0).abs())
                .max((dot(f[2], f[2]) - 1.0).abs())
        })
        .fold(0.0, f64::max);
    eprintln!(
        "Ex 9.1 least-energy quintic: S (PH polynomial) = {s_ph:.15}, S (adaptive GL 1e-12) = {s_q:.15}, |ΔS| = {:.1e}; double-reflection RMF orthonormality defect over {N} points = {defect:.1e}",
        (s_ph - s_q).abs()
    );

    let mut g = c.benchmark_group("ph_hermite");
    g.throughput(Throughput::Elements(1));
    let d = data();
    g.bench_function("hermite_solve_f64", |b| {
        b.iter(|| black_box(&d).solve_f64().expect("solutions"))
    });
    g.finish();

    let mut g = c.benchmark_group("ph_per_point");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("arc_length_ph", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for &t in &ts {
                acc += s_poly.eval(black_box(&t));
            }
            acc
        })
    });
    g.bench_function("arc_length_quadrature", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for &t in &ts {
                acc += arc_length_quadrature(&d1, black_box(t), 1e-12);
            }
            acc
        })
    });
    g.bench_function("erf_frame", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for t in &ts {
                if let Some(f) = erf.eval(black_box(t)) {
                    acc += f[1][0];
                }
            }
            acc
        })
    });
    g.bench_function("rmf_double_reflection", |b| {
        b.iter(|| rmf(&pos, &d1, black_box(&ts), e0[1]))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
