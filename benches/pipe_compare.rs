//! Exact pipe around a PH quintic vs a swept-circle approximation (docs/BENCHMARKS.md,
//! section "Exact pipe vs swept-circle approximation").
//!
//! * **Exact:** `rcagd::canal::pipe_around_ph_pole_free` — the rational pipe of radius `r`
//!   around a spatial PH quintic (split `D = σ²`, Gruber 2008 §2.1) on `t ∈ [0, 1]`, in a frame
//!   (rational reflection) without base points there; exact (`Rational`) and the same
//!   construction in `f64`; construction and certification (the canal identities as
//!   polynomial identities).
//! * **Approximation, as a CAD kernel makes it:** sample the spine at `N` parameters, carry a
//!   rotation-minimizing frame along it (double reflection, Wang–Jüttler–Zheng–Liu 2008),
//!   place `M` points of the circle of radius `r` in each normal plane, and skin them by
//!   bicubic B-spline interpolation (clamped, averaged knots; the circle direction closed by
//!   repeating the first point). `N` and `M` are doubled until the largest radial error
//!   `| dist(x, spine) − r |` on a validation grid 4× finer (nearest spine point by Newton)
//!   is ≤ 1e-6.
//!
//! Run: `cargo bench -p rcagd-benches --features bench --bench pipe_compare -- --warm-up-time 1 --measurement-time 3`.
//! The summary (degrees, control-point counts, errors) is printed once before the timings.

use criterion::{criterion_group, criterion_main, Criterion};
use rcagd::canal::frame::householder;
use rcagd::canal::pipe::pipe_around_ph_parts;
use rcagd::canal::{
    pipe_around_ph_pole_free, pole_free_direction, AxisChoice, CanalOptions, CanalSpine,
    CanalSurface, Orientation,
};
use rcagd::ph::PhCurve;
use rcagd::Certified;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::{Poly, Rational, Scalar};
use std::hint::black_box;
use std::time::Instant;

const RADIUS: (i64, i64) = (1, 10);
const TOLERANCE: f64 = 1e-6;

/// The PH quintic of the gallery recipe `pipe_ph_quintic`.
fn quintic() -> PhCurve<Rational> {
    let q = |a: i64, b: i64, c: i64, d: i64| {
        Quaternion::new(
            Rational::from(a),
            Rational::from(b),
            Rational::from(c),
            Rational::from(d),
        )
    };
    let coeffs = vec![q(1, 0, 0, 0), q(0, 1, 0, 1), q(1, 0, 1, 0)];
    let zero = Rational::from(0);
    PhCurve::new(coeffs, [zero.clone(), zero.clone(), zero]).expect("PH quintic")
}

/// The exact pipe on `t ∈ [0, 1]` in a frame without base points (`rcagd::canal::frame`).
fn exact_pipe(c: &PhCurve<Rational>) -> CanalSurface<Rational> {
    let r = Rational::from_ratio(RADIUS.0, RADIUS.1);
    let (a, b) = (Rational::from(0), Rational::from(1));
    pipe_around_ph_pole_free(c, &r, (&a, &b), Orientation::Positive).expect("exact pipe")
}

/// The frame of the exact build (the Householder reflection of the chosen direction).
fn frame(c: &PhCurve<Rational>) -> [[f64; 3]; 3] {
    let r = Rational::from_ratio(RADIUS.0, RADIUS.1);
    let spine = CanalSpine::polynomial(c.position(), Poly::constant(r));
    let (a, b) = (Rational::from(0), Rational::from(1));
    let e = pole_free_direction(&spine, &a, &b)
        .expect("direction search")
        .expect("a pole-free direction");
    householder(&e).map(|row| row.map(|x| Scalar::to_f64(&x)))
}

/// The same construction in `f64`: the spine in the frame `h`, the PH split `(σ, 0)`, axis
/// `x₃`, mapped back by `h`.
fn f64_pipe(c: &PhCurve<f64>, h: &[[f64; 3]; 3]) -> CanalSurface<f64> {
    let r = RADIUS.0 as f64 / RADIUS.1 as f64;
    let pos = c.position();
    let ph: [Poly<f64>; 3] = core::array::from_fn(|i| {
        (0..3).fold(Poly::zero(), |acc, j| &acc + &pos[j].scale(&h[i][j]))
    });
    let opts = CanalOptions {
        axis: Some(AxisChoice {
            axis: 2,
            positive: true,
        }),
        ..CanalOptions::default()
    };
    let s = pipe_around_ph_parts(&ph, &c.speed(), &r, &opts).expect("f64 pipe");
    let spine = CanalSpine::polynomial(pos, Poly::constant(r));
    s.transformed(h, &spine).expect("frame back")
}

/// Splits the patches at 1/2 (circle direction first) until every Bernstein weight is
/// positive (what a kernel needs to accept them), as the `pipe_ph` recipe op does.
fn positive_patches(
    patches: Vec<rcagd_geom::BezierPatch<Rational>>,
) -> Vec<rcagd_geom::BezierPatch<Rational>> {
    let half = Rational::from_ratio(1, 2);
    let mut out = Vec::new();
    let mut todo: Vec<(rcagd_geom::BezierPatch<Rational>, usize)> =
        patches.into_iter().map(|p| (p, 0)).collect();
    while let Some((p, dv)) = todo.pop() {
        if p.weights().iter().all(|w| *w > Rational::from(0)) {
            out.push(p);
        } else if dv < 4 {
            let (a, b) = p.subdivide_v(&half).expect("split");
            todo.push((a, dv + 1));
            todo.push((b, dv + 1));
        } else {
            let (a, b) = p.subdivide_u(&half).expect("split");
            todo.push((a, dv));
            todo.push((b, dv));
        }
    }
    out
}

// ----------------------------------------------------------------------------------------
// the swept-circle approximation
// ----------------------------------------------------------------------------------------

struct Spine {
    p: [Poly<f64>; 3],
    d1: [Poly<f64>; 3],
    d2: [Poly<f64>; 3],
}

impl Spine {
    fn new(c: &PhCurve<Rational>) -> Self {
        let p = c.position().map(|x| x.map(Scalar::to_f64));
        let d1 = p.clone().map(|x| x.derivative());
        let d2 = d1.clone().map(|x| x.derivative());
        Spine { p, d1, d2 }
    }
    fn at(&self, t: f64) -> [f64; 3] {
        core::array::from_fn(|k| self.p[k].eval(&t))
    }
    fn tangent(&self, t: f64) -> [f64; 3] {
        core::array::from_fn(|k| self.d1[k].eval(&t))
    }
    /// Distance from `x` to the spine, by Newton on `(m(t) − x)·m'(t) = 0` from `t0`
    /// (clamped to [0, 1]; the validation points are interior, near `t0`).
    fn distance(&self, x: &[f64; 3], t0: f64) -> f64 {
        let mut t = t0;
        for _ in 0..30 {
            let m = self.at(t);
            let d1 = self.tangent(t);
            let d2: [f64; 3] = core::array::from_fn(|k| self.d2[k].eval(&t));
            let diff = sub(&m, x);
            let f = dot(&diff, &d1);
            let fp = dot(&d1, &d1) + dot(&diff, &d2);
            let step = f / fp;
            t = (t - step).clamp(0.0, 1.0);
            if step.abs() < 1e-15 {
                break;
            }
        }
        norm(&sub(&self.at(t), x))
    }
}

fn sub(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    core::array::from_fn(|k| a[k] - b[k])
}
fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn norm(a: &[f64; 3]) -> f64 {
    dot(a, a).sqrt()
}
fn scale(a: &[f64; 3], s: f64) -> [f64; 3] {
    a.map(|x| x * s)
}
fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Rotation-minimizing frames `(t, r, s)` at the parameters (double reflection method).
fn rmf(spine: &Spine, ts: &[f64]) -> Vec<[[f64; 3]; 3]> {
    let t0 = spine.tangent(ts[0]);
    let t0 = scale(&t0, 1.0 / norm(&t0));
    let helper = if t0[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let r0 = cross(&t0, &helper);
    let r0 = scale(&r0, 1.0 / norm(&r0));
    let mut out = vec![[t0, r0, cross(&t0, &r0)]];
    for w in ts.windows(2) {
        let [ti, ri, _] = out[out.len() - 1];
        let v1 = sub(&spine.at(w[1]), &spine.at(w[0]));
        let c1 = dot(&v1, &v1);
        let rl = sub(&ri, &scale(&v1, 2.0 * dot(&v1, &ri) / c1));
        let tl = sub(&ti, &scale(&v1, 2.0 * dot(&v1, &ti) / c1));
        let tn = spine.tangent(w[1]);
        let tn = scale(&tn, 1.0 / norm(&tn));
        let v2 = sub(&tn, &tl);
        let c2 = dot(&v2, &v2);
        let rn = if c2 > 0.0 {
            sub(&rl, &scale(&v2, 2.0 * dot(&v2, &rl) / c2))
        } else {
            rl
        };
        let rn = scale(&rn, 1.0 / norm(&rn));
        out.push([tn, rn, cross(&tn, &rn)]);
    }
    out
}

/// The clamped cubic knot vector of interpolation at `params` (averaging, de Boor).
fn knots(params: &[f64]) -> Vec<f64> {
    let n = params.len();
    let mut k = vec![params[0]; 4];
    for j in 1..n - 3 {
        k.push((params[j] + params[j + 1] + params[j + 2]) / 3.0);
    }
    k.extend(std::iter::repeat_n(params[n - 1], 4));
    k
}

/// The span and the four non-zero cubic B-spline basis values at `u`.
fn basis(k: &[f64], u: f64) -> (usize, [f64; 4]) {
    let n = k.len() - 4; // number of basis functions
    let mut span = 3;
    while span < n - 1 && u >= k[span + 1] {
        span += 1;
    }
    let mut nb = [1.0, 0.0, 0.0, 0.0];
    let mut left = [0.0; 4];
    let mut right = [0.0; 4];
    for j in 1..4 {
        left[j] = u - k[span + 1 - j];
        right[j] = k[span + j] - u;
        let mut saved = 0.0;
        for r in 0..j {
            let temp = nb[r] / (right[r + 1] + left[j - r]);
            nb[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        nb[j] = saved;
    }
    (span, nb)
}

/// Solves `A X = B` (dense, partial pivoting) for several right-hand sides.
#[allow(clippy::needless_range_loop)] // row operations between two rows of `a` by index
fn solve(mut a: Vec<Vec<f64>>, mut b: Vec<Vec<f64>>) -> Vec<Vec<f64>> {
    let n = a.len();
    for c in 0..n {
        let piv = (c..n)
            .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
            .unwrap_or(c);
        a.swap(c, piv);
        b.swap(c, piv);
        for r in c + 1..n {
            let f = a[r][c] / a[c][c];
            if f != 0.0 {
                for k in c..n {
                    a[r][k] -= f * a[c][k];
                }
                for k in 0..b[r].len() {
                    b[r][k] -= f * b[c][k];
                }
            }
        }
    }
    for c in (0..n).rev() {
        for k in 0..b[c].len() {
            let mut s = b[c][k];
            for j in c + 1..n {
                s -= a[c][j] * b[j][k];
            }
            b[c][k] = s / a[c][c];
        }
    }
    b
}

/// Interpolating cubic B-spline control points of `data` (rows = points) at `params`.
fn interpolate(params: &[f64], k: &[f64], data: Vec<Vec<f64>>) -> Vec<Vec<f64>> {
    let n = params.len();
    let mut a = vec![vec![0.0; n]; n];
    for (i, &u) in params.iter().enumerate() {
        let (span, nb) = basis(k, u);
        for (r, v) in nb.iter().enumerate() {
            a[i][span - 3 + r] = *v;
        }
    }
    solve(a, data)
}

/// The skinned bicubic B-spline surface.
struct Skin {
    ks: Vec<f64>,
    kv: Vec<f64>,
    /// `ctrl[i][j]` = control point `(i, j)`.
    ctrl: Vec<Vec<[f64; 3]>>,
}

impl Skin {
    fn control_points(&self) -> usize {
        self.ctrl.len() * self.ctrl.first().map_or(0, Vec::len)
    }
    fn eval(&self, s: f64, v: f64) -> [f64; 3] {
        let (si, ns) = basis(&self.ks, s);
        let (vi, nv) = basis(&self.kv, v);
        let mut p = [0.0; 3];
        for (a, ba) in ns.iter().enumerate() {
            for (b, bb) in nv.iter().enumerate() {
                let c = &self.ctrl[si - 3 + a][vi - 3 + b];
                for k in 0..3 {
                    p[k] += ba * bb * c[k];
                }
            }
        }
        p
    }
}

/// Sweeps `m` circle points along `n` spine stations and skins them.
fn swept_circle(spine: &Spine, r: f64, n: usize, m: usize) -> Skin {
    let ts: Vec<f64> = (0..n).map(|i| i as f64 / (n - 1) as f64).collect();
    let frames = rmf(spine, &ts);
    let vs: Vec<f64> = (0..=m).map(|j| j as f64 / m as f64).collect();
    // data[i][j]: circle point j at station i
    let data: Vec<Vec<[f64; 3]>> = ts
        .iter()
        .zip(&frames)
        .map(|(&t, f)| {
            let c = spine.at(t);
            vs.iter()
                .map(|&v| {
                    let (sn, cs) = (2.0 * std::f64::consts::PI * v).sin_cos();
                    core::array::from_fn(|k| c[k] + r * (cs * f[1][k] + sn * f[2][k]))
                })
                .collect()
        })
        .collect();
    let ks = knots(&ts);
    let kv = knots(&vs);
    // along v for every station
    let rows: Vec<Vec<[f64; 3]>> = data
        .iter()
        .map(|row| {
            let sol = interpolate(&vs, &kv, row.iter().map(|p| p.to_vec()).collect());
            sol.iter().map(|p| [p[0], p[1], p[2]]).collect()
        })
        .collect();
    // along s for every v-control index
    let mut ctrl = vec![vec![[0.0; 3]; m + 1]; n];
    for j in 0..=m {
        let col: Vec<Vec<f64>> = rows.iter().map(|r| r[j].to_vec()).collect();
        let sol = interpolate(&ts, &ks, col);
        for (i, p) in sol.iter().enumerate() {
            ctrl[i][j] = [p[0], p[1], p[2]];
        }
    }
    Skin { ks, kv, ctrl }
}

/// The largest radial error on a validation grid `4n × 4m` (cell midpoints and nodes).
fn radial_error(spine: &Spine, skin: &Skin, r: f64, n: usize, m: usize) -> f64 {
    let (gs, gv) = (4 * n, 4 * m);
    let mut worst = 0.0f64;
    for i in 0..=gs {
        let s = i as f64 / gs as f64;
        for j in 0..gv {
            let v = (j as f64 + 0.5) / gv as f64;
            let x = skin.eval(s, v);
            let e = (spine.distance(&x, s) - r).abs();
            worst = worst.max(e);
        }
    }
    worst
}

/// Refines until the radial error is ≤ [`TOLERANCE`]: `(n, m, skin, error)`.
fn refine(spine: &Spine, r: f64) -> (usize, usize, Skin, f64) {
    let (mut n, mut m) = (8usize, 8usize);
    loop {
        let skin = swept_circle(spine, r, n, m);
        let e = radial_error(spine, &skin, r, n, m);
        if e <= TOLERANCE || n >= 1024 {
            return (n, m, skin, e);
        }
        // refine the direction that dominates: compare the error of each direction alone
        let e_n = radial_error(spine, &swept_circle(spine, r, 2 * n, m), r, 2 * n, m);
        let e_m = radial_error(spine, &swept_circle(spine, r, n, 2 * m), r, n, 2 * m);
        if e_n <= e_m {
            n *= 2;
        } else {
            m *= 2;
        }
    }
}

fn bench(c: &mut Criterion) {
    let curve = quintic();
    let cf = curve.to_f64();
    let r = RADIUS.0 as f64 / RADIUS.1 as f64;

    // ---- summary (printed once) ----
    let t = Instant::now();
    let exact = exact_pipe(&curve);
    let t_build = t.elapsed();
    let t = Instant::now();
    let certs = exact.certify();
    let t_cert = t.elapsed();
    assert!(certs.iter().all(|c| c.holds), "{certs:?}");
    let (dt, du) = exact.degree();
    let patches = exact
        .full_patches((&Rational::from(0), &Rational::from(1)))
        .expect("patches");
    let count = |ps: &[rcagd_geom::BezierPatch<Rational>]| -> usize {
        ps.iter()
            .map(|p| {
                let (a, b) = p.degree();
                (a + 1) * (b + 1)
            })
            .sum()
    };
    let cp = count(&patches);
    let positive = positive_patches(patches.to_vec());
    let cp_pos = count(&positive);
    let h = frame(&curve);
    let spine = Spine::new(&curve);
    let t = Instant::now();
    let (n, m, skin, err) = refine(&spine, r);
    let t_refine = t.elapsed();
    // the radial error of the exact pipe evaluated in f64, and of the f64 construction
    // (rounding only; the exact one is 0 by its certificates)
    let fpipe = f64_pipe(&cf, &h);
    let exact_f = exact.map_scalar(Scalar::to_f64);
    let mut exact_err = 0.0f64;
    let mut f64_err = 0.0f64;
    for i in 0..=64 {
        for j in -32..=32 {
            let (tt, uu) = (f64::from(i) / 64.0, f64::from(j) / 4.0);
            if let Ok(x) = exact_f.eval(&tt, &uu) {
                exact_err = exact_err.max((spine.distance(&x, tt) - r).abs());
            }
            if let Ok(x) = fpipe.eval(&tt, &uu) {
                f64_err = f64_err.max((spine.distance(&x, tt) - r).abs());
            }
        }
    }
    assert!(fpipe.certify().iter().all(|c| c.holds));
    println!(
        "pipe_compare: exact pipe bidegree ({dt}, {du}): 2 patches, {cp} control points ({} patches, {cp_pos} control points split to positive weights); certified in {t_cert:?}, built in {t_build:?}; radial error evaluated in f64: exact {exact_err:.2e}, f64 construction {f64_err:.2e}",
        positive.len()
    );
    println!(
        "pipe_compare: swept circle {n} stations × {} circle points = {} control points, radial error {err:.2e} (refinement {t_refine:?})",
        m + 1,
        skin.control_points()
    );

    // ---- timings ----
    let mut g = c.benchmark_group("pipe_compare");
    g.bench_function("exact_build", |b| b.iter(|| exact_pipe(black_box(&curve))));
    g.bench_function("exact_certify", |b| b.iter(|| black_box(&exact).certify()));
    g.bench_function("f64_build", |b| b.iter(|| f64_pipe(black_box(&cf), &h)));
    g.bench_function("f64_certify", |b| b.iter(|| black_box(&fpipe).certify()));
    g.bench_function("swept_final_fit", |b| {
        b.iter(|| swept_circle(black_box(&spine), r, n, m))
    });
    g.bench_function("swept_final_validate", |b| {
        b.iter(|| radial_error(black_box(&spine), &skin, r, n, m))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
