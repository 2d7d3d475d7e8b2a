//! Exact PN offsets against the approximated offsets a CAD kernel makes.
//!
//! Two PN surfaces of Peternell (docs/math/laguerre-pn.md) on a parameter rectangle, offset at a rational distance:
//!
//! * the PN surface of the cubic graph `F = u³/3 − uv + v²/2 + 5` of the isotropic model
//!   (Theorem 4.3) on `[−1/2, 1/2]²`, `d = 1/4` (the gallery surface `pn_cubic_graph`;
//!   with constant term 1 instead of 5 it has parabolic, i.e. singular, points there);
//! * the ellipsoid of revolution `(a, b, c) = (4, 4, 1)` of §4.7 (Theorem 4.5 in the
//!   umbilic frame) on `[1/4, 3/4] × [−1/2, 1/2]`, `d = 1/2`;
//! * the hyperbolic paraboloid `z = xy` as a PN ruled surface (Cor. 4.2) on
//!   `[1/4, 5/4] × [1/2, 2]`, `d = 1/2`.
//!
//! Both the surface and its offset are checked regular on the rectangle (exact Bernstein
//! signs of `det(x_u, x_v, n)`) before anything is measured.
//!
//! The exact offset `x + d n = (X + dKN)/W` is a rational Bézier patch with deviation 0
//! (certified: `x_d − x ≡ d n`). The approximated offset is what a kernel without PN
//! knowledge does: sample the offset (here from the exact formula in `f64`) on an `n × n`
//! grid, interpolate by a bicubic B-spline (uniform clamped knots, interpolation at the
//! Greville abscissae), and refine `n` until the maximum deviation from the true offset on
//! a 4× finer validation grid is below `1e-6`. Reported once before timing: bidegree and
//! control-point count of both, and the deviation.
//!
//! Timed (same run): `exact_offset_q` (offset + Bézier patch over Q), `exact_offset_f64`
//! (the same in `f64`), `approx_offset_1e-6` (the sampling-and-fitting loop, `f64`).
//!
//! Run: `cargo bench -p rcagd-benches --features bench --bench pn_offset -- --warm-up-time 1 --measurement-time 3`

use criterion::{criterion_group, criterion_main, Criterion};
use rcagd::pn::ruled::{EllipsoidPn, RuledPn};
use rcagd::pn::{Domain, IsotropicSurface, PnSurface, RatFn};
use rcagd::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Rational, Scalar};
use std::hint::black_box;

type Q = Rational;

fn q(p: i64, d: i64) -> Q {
    Q::from_ratio(p, d)
}

struct Case {
    name: &'static str,
    surface: PnSurface<Q>,
    domain: Domain<Q>,
    d: Q,
}

fn cases() -> Vec<Case> {
    let f = MPoly::from_terms(
        2,
        vec![
            (vec![3, 0], q(1, 3)),
            (vec![1, 1], q(-1, 1)),
            (vec![0, 2], q(1, 2)),
            (vec![0, 0], q(5, 1)),
        ],
    )
    .expect("2 vars");
    let graph = IsotropicSurface::graph_poly(f).to_pn_surface().expect("pn");
    let ell = EllipsoidPn::new(q(4, 1), q(4, 1), q(1, 1)).expect("rational");
    let t = MPoly::var(2, 0);
    let c = |k: i64| RatFn::poly(MPoly::constant(2, q(k, 1)));
    let hp = RuledPn::new(
        [RatFn::poly(t.clone()), c(0), c(0)],
        [c(0), c(1), RatFn::poly(t)],
        None,
    )
    .expect("non-developable");
    vec![
        Case {
            name: "cubic graph (Thm 4.3)",
            surface: graph,
            domain: Domain::new(q(-1, 2), q(1, 2), q(-1, 2), q(1, 2)).expect("rect"),
            d: q(1, 4),
        },
        Case {
            name: "ellipsoid of revolution (§4.7)",
            surface: ell.surface().clone(),
            domain: Domain::new(q(1, 4), q(3, 4), q(-1, 2), q(1, 2)).expect("rect"),
            d: q(1, 2),
        },
        Case {
            name: "hyperbolic paraboloid (Cor. 4.2)",
            surface: hp.surface().clone(),
            domain: Domain::new(q(1, 4), q(5, 4), q(1, 2), q(2, 1)).expect("rect"),
            d: q(1, 2),
        },
    ]
}

// ---------------------------------------------------------------------------------
// A bicubic B-spline interpolant, as a CAD kernel would fit an offset
// ---------------------------------------------------------------------------------

/// Clamped uniform cubic knot vector for `n ≥ 4` control points on `[0, 1]`.
fn knots(n: usize) -> Vec<f64> {
    let inner = n - 3;
    let mut k = vec![0.0; 4];
    for i in 1..inner {
        k.push(i as f64 / inner as f64);
    }
    k.extend([1.0; 4]);
    k
}

/// The four non-zero cubic B-spline values at `t` and the first index.
fn basis(k: &[f64], n: usize, t: f64) -> (usize, [f64; 4]) {
    let mut span = 3;
    while span < n - 1 && t >= k[span + 1] {
        span += 1;
    }
    let mut nb = [0.0; 4];
    nb[0] = 1.0;
    let (mut left, mut right) = ([0.0; 4], [0.0; 4]);
    for j in 1..4 {
        left[j] = t - k[span + 1 - j];
        right[j] = k[span + j] - t;
        let mut saved = 0.0;
        for r in 0..j {
            let tmp = nb[r] / (right[r + 1] + left[j - r]);
            nb[r] = saved + right[r + 1] * tmp;
            saved = left[j - r] * tmp;
        }
        nb[j] = saved;
    }
    (span - 3, nb)
}

fn greville(k: &[f64], n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| (k[i + 1] + k[i + 2] + k[i + 3]) / 3.0)
        .collect()
}

/// Solves `A X = B` (dense, partial pivoting) for `m` right-hand sides.
fn solve(mut a: Vec<Vec<f64>>, mut b: Vec<Vec<f64>>) -> Vec<Vec<f64>> {
    let n = a.len();
    for c in 0..n {
        let p = (c..n)
            .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
            .unwrap_or(c);
        a.swap(c, p);
        b.swap(c, p);
        for r in c + 1..n {
            let f = a[r][c] / a[c][c];
            if f == 0.0 {
                continue;
            }
            let pivot_row = a[c].clone();
            for (x, y) in a[r][c..n].iter_mut().zip(&pivot_row[c..n]) {
                *x -= f * y;
            }
            let (bc, br) = (b[c].clone(), &mut b[r]);
            for (x, y) in br.iter_mut().zip(bc) {
                *x -= f * y;
            }
        }
    }
    for c in (0..n).rev() {
        for r in 0..c {
            let f = a[r][c] / a[c][c];
            let bc = b[c].clone();
            for (x, y) in b[r].iter_mut().zip(bc) {
                *x -= f * y;
            }
        }
        let d = a[c][c];
        for x in b[c].iter_mut() {
            *x /= d;
        }
    }
    b
}

struct Bspline {
    n: usize,
    k: Vec<f64>,
    ctrl: Vec<[f64; 3]>, // n × n, row-major in s
}

impl Bspline {
    fn eval(&self, s: f64, t: f64) -> [f64; 3] {
        let (i0, bs) = basis(&self.k, self.n, s);
        let (j0, bt) = basis(&self.k, self.n, t);
        let mut p = [0.0; 3];
        for (a, ba) in bs.iter().enumerate() {
            for (b, bb) in bt.iter().enumerate() {
                let c = self.ctrl[(i0 + a) * self.n + j0 + b];
                for d in 0..3 {
                    p[d] += ba * bb * c[d];
                }
            }
        }
        p
    }
}

/// Bicubic interpolation of `f` at the Greville grid (tensor product of 1-D solves).
fn fit(f: &dyn Fn(f64, f64) -> [f64; 3], n: usize) -> Bspline {
    let k = knots(n);
    let g = greville(&k, n);
    let mat: Vec<Vec<f64>> = g
        .iter()
        .map(|&t| {
            let (i0, b) = basis(&k, n, t);
            let mut row = vec![0.0; n];
            for (a, v) in b.iter().enumerate() {
                row[i0 + a] = *v;
            }
            row
        })
        .collect();
    // samples P[i][j] → solve along t for every row i, then along s for every column
    let samples: Vec<Vec<f64>> = g
        .iter()
        .map(|&s| g.iter().flat_map(|&t| f(s, t)).collect())
        .collect();
    // along t: for row i, the system mat · C_i = P_i (3 coords per point)
    let rows: Vec<Vec<f64>> = samples
        .iter()
        .map(|row| {
            let rhs: Vec<Vec<f64>> = row.chunks(3).map(|c| c.to_vec()).collect();
            solve(mat.clone(), rhs).concat()
        })
        .collect();
    // along s: one system with n·3 right-hand sides per column index
    let rhs: Vec<Vec<f64>> = rows.clone();
    let sol = solve(mat, rhs);
    let ctrl = sol
        .iter()
        .flat_map(|r| r.chunks(3).map(|c| [c[0], c[1], c[2]]).collect::<Vec<_>>())
        .collect();
    Bspline { n, k, ctrl }
}

fn max_error(a: &Bspline, f: &dyn Fn(f64, f64) -> [f64; 3], m: usize) -> f64 {
    let mut e: f64 = 0.0;
    for i in 0..=m {
        for j in 0..=m {
            let (s, t) = (i as f64 / m as f64, j as f64 / m as f64);
            let (p, x) = (a.eval(s, t), f(s, t));
            let d = ((p[0] - x[0]).powi(2) + (p[1] - x[1]).powi(2) + (p[2] - x[2]).powi(2)).sqrt();
            e = e.max(d);
        }
    }
    e
}

/// Refines the grid until the deviation is below `tol`; returns the spline and its error.
fn approximate(f: &dyn Fn(f64, f64) -> [f64; 3], tol: f64) -> (Bspline, f64) {
    let mut n = 4;
    loop {
        let s = fit(f, n);
        let e = max_error(&s, f, 4 * n);
        if e < tol || n >= 160 {
            return (s, e);
        }
        n = (n as f64 * 1.4).ceil() as usize;
    }
}

fn offset_f64<'a>(
    s: &'a PnSurface<f64>,
    dom: &'a Domain<f64>,
) -> impl Fn(f64, f64) -> [f64; 3] + 'a {
    move |a, b| {
        let [u, v] = dom.point(&a, &b);
        s.eval(&u, &v).expect("defined")
    }
}

fn report() {
    eprintln!("\n| surface | offset | exact: bidegree, control points, deviation | approx. at 1e-6: bicubic control points, max deviation |");
    eprintln!("|---|---|---|---|");
    for c in cases() {
        let off = c.surface.offset(c.d.clone());
        assert!(off.all_hold(), "exact offset certified");
        c.surface.check_regular(&c.domain).expect("regular surface");
        off.check_regular(&c.domain).expect("regular offset");
        let patch = off.patch(&c.domain).expect("patch");
        let (m, n) = patch.degree();
        let sf = off.surface().map_scalar(Scalar::to_f64);
        let dom = Domain::new(
            Scalar::to_f64(&c.domain.u.0),
            Scalar::to_f64(&c.domain.u.1),
            Scalar::to_f64(&c.domain.v.0),
            Scalar::to_f64(&c.domain.v.1),
        )
        .expect("rect");
        let f = offset_f64(&sf, &dom);
        let (spl, err) = approximate(&f, 1e-6);
        eprintln!(
            "| {} | d = {} | ({m}, {n}), {} control points, 0 (certified x_d − x ≡ d n) | {} control points ({}×{}), {:.2e} |",
            c.name,
            c.d,
            (m + 1) * (n + 1),
            spl.n * spl.n,
            spl.n,
            spl.n,
            err
        );
    }
    eprintln!();
}

fn bench(c: &mut Criterion) {
    report();
    for case in cases() {
        let mut g = c.benchmark_group(case.name);
        g.bench_function("exact_offset_q", |b| {
            b.iter(|| {
                let off = case.surface.offset(black_box(case.d.clone()));
                black_box(off.patch(&case.domain).expect("patch"))
            })
        });
        let sf = case.surface.map_scalar(Scalar::to_f64);
        let df = Scalar::to_f64(&case.d);
        let dom = Domain::new(
            Scalar::to_f64(&case.domain.u.0),
            Scalar::to_f64(&case.domain.u.1),
            Scalar::to_f64(&case.domain.v.0),
            Scalar::to_f64(&case.domain.v.1),
        )
        .expect("rect");
        g.bench_function("exact_offset_f64", |b| {
            b.iter(|| {
                let off = sf.offset(black_box(df));
                black_box(off.patch(&dom).expect("patch"))
            })
        });
        let off = sf.offset(df);
        let target = off.surface().clone();
        let f = offset_f64(&target, &dom);
        g.sample_size(10);
        g.bench_function("approx_offset_1e-6", |b| {
            b.iter(|| black_box(approximate(&f, 1e-6).1))
        });
        g.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
