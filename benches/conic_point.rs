//! The conic-point engine (`rcagd_algebra::conic_point`, Peternell Thm 1.1) against the size
//! of its input (docs/BENCHMARKS.md, section "The conic-point engine"). No peer: no other
//! library decides `X²L + Y²M + Z²N = 0` over `Q[t]` (the sum-of-squares searches it
//! replaced were incomplete), so the result is a table of times, not a ratio.
//!
//! Families of degree `d ∈ {2, 4, 8, 12, 16, 20}` with coefficients of `b ∈ {8, 32, 64}`
//! bits from a fixed pseudo-random generator:
//! * **solvable**: `L`, `M` random of degree `d`, `X`, `Y` random linear, `Z = 1`,
//!   `N = −(X²L + Y²M)` (degree `d + 2`): a point exists and must be found;
//! * **random**: `L`, `M`, `N` random of degree `d` (mixed signs): a point or a proof.
//!
//! A summary (decision, time of one run, degree of the point) is printed first; criterion
//! then times a few cases.
//!
//! Run: `cargo bench -p rcagd-benches --features bench --bench conic_point -- --warm-up-time 1 --measurement-time 3`.

use criterion::{criterion_group, criterion_main, Criterion};
use rcagd_algebra::conic_point::{certify_conic_point, conic_point, ConicPoint};
use rcagd_algebra::{Poly, Rational};
use std::hint::black_box;
use std::time::Instant;

/// xorshift64*: reproducible pseudo-random numbers.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    /// A non-zero integer of at most `bits` bits with a random sign.
    fn int(&mut self, bits: u32) -> Rational {
        let m = if bits >= 64 {
            u64::MAX
        } else {
            (1u64 << bits) - 1
        };
        let v = (self.next() & m).max(1);
        let r = Rational::from(v);
        if self.next() & 1 == 1 {
            -r
        } else {
            r
        }
    }
    fn poly(&mut self, d: usize, bits: u32) -> Poly<Rational> {
        Poly::new((0..=d).map(|_| self.int(bits)).collect())
    }
}

fn solvable(rng: &mut Rng, d: usize, bits: u32) -> [Poly<Rational>; 3] {
    let l = rng.poly(d, bits);
    let m = rng.poly(d, bits);
    let x = rng.poly(1, bits);
    let y = rng.poly(1, bits);
    let n = -&(&(&(&x * &x) * &l) + &(&(&y * &y) * &m));
    [l, m, n]
}

fn random(rng: &mut Rng, d: usize, bits: u32) -> [Poly<Rational>; 3] {
    [rng.poly(d, bits), rng.poly(d, bits), rng.poly(d, bits)]
}

fn describe(c: &[Poly<Rational>; 3]) -> (String, f64) {
    let t0 = Instant::now();
    let out = conic_point(&c[0], &c[1], &c[2]);
    let dt = t0.elapsed().as_secs_f64();
    let what = match &out {
        Ok(ConicPoint::Rational(p)) => {
            let deg = p.iter().filter_map(|x| x.degree()).max().unwrap_or(0);
            let ok = certify_conic_point(c, p).holds;
            format!("point of degree {deg} (certified: {ok})")
        }
        Ok(ConicPoint::QuadraticField { radicand, .. }) => format!("point over Q(√{radicand})"),
        Ok(ConicPoint::NoPoint { .. }) => "no point (proof)".into(),
        Err(e) => format!("undecided: {e}"),
    };
    (what, dt)
}

fn bench(c: &mut Criterion) {
    let degrees = [2usize, 4, 8, 12, 16, 20];
    let bits = [8u32, 32, 64];
    println!("kind | degree | bits | result | time (s)");
    for &b in &bits {
        for &d in &degrees {
            let mut rng = Rng(0x9E37_79B9_7F4A_7C15 ^ (d as u64 * 1_000 + u64::from(b)));
            let s = solvable(&mut rng, d, b);
            let (w, t) = describe(&s);
            println!("solvable | {d} | {b} | {w} | {t:.4}");
            let r = random(&mut rng, d, b);
            let (w, t) = describe(&r);
            println!("random | {d} | {b} | {w} | {t:.4}");
        }
    }
    let mut g = c.benchmark_group("conic_point");
    g.sample_size(10);
    for (d, b) in [(2usize, 8u32), (8, 32), (12, 8)] {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15 ^ (d as u64 * 1_000 + u64::from(b)));
        let s = solvable(&mut rng, d, b);
        g.bench_function(format!("solvable_d{d}_b{b}"), |bch| {
            bch.iter(|| conic_point(black_box(&s[0]), &s[1], &s[2]))
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
