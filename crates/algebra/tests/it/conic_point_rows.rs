//! The rows of the conic-point benchmark (docs/BENCHMARKS.md, "The conic-point engine
//! against input size") without a release build of the criterion bench: the same families
//! as `benches/conic_point.rs` (same generator and seeds), one run each, printed as table
//! rows. Ignored by default (minutes):
//! `cargo test -p rcagd-algebra --test it conic_point_rows -- --ignored --nocapture`
//! (`CONIC_ROWS=8:32,16:64` restricts to the given `degree:bits` cases).

use rcagd_algebra::conic_point::{certify_conic_point, conic_point, ConicPoint};
use rcagd_algebra::{Poly, Rational};
use std::time::Instant;

/// xorshift64* as in `benches/conic_point.rs`.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
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

fn describe(c: &[Poly<Rational>; 3]) -> String {
    let t0 = Instant::now();
    let out = conic_point(&c[0], &c[1], &c[2]);
    let dt = t0.elapsed().as_secs_f64();
    let what = match &out {
        Ok(ConicPoint::Rational(p)) => {
            let deg = p.iter().filter_map(|x| x.degree()).max().unwrap_or(0);
            assert!(certify_conic_point(c, p).holds, "uncertified point");
            format!("point, degree {deg}")
        }
        Ok(ConicPoint::QuadraticField { radicand, .. }) => format!("point over Q(√{radicand})"),
        Ok(ConicPoint::NoPoint { .. }) => "no point (proof)".into(),
        Err(e) => format!("undecided: {e}"),
    };
    format!("{what} | {dt:.4} s")
}

#[test]
#[ignore = "minutes: the benchmark rows"]
fn conic_point_rows() {
    let only: Option<Vec<(usize, u32)>> = std::env::var("CONIC_ROWS").ok().map(|s| {
        s.split(',')
            .filter_map(|c| {
                let (d, b) = c.split_once(':')?;
                Some((d.parse().ok()?, b.parse().ok()?))
            })
            .collect()
    });
    println!("| degree d | bits b | solvable: result | time | random: result | time |");
    for b in [8u32, 32, 64] {
        for d in [2usize, 4, 8, 12, 16, 20] {
            if only.as_ref().is_some_and(|o| !o.contains(&(d, b))) {
                continue;
            }
            let mut rng = Rng(0x9E37_79B9_7F4A_7C15 ^ (d as u64 * 1_000 + u64::from(b)));
            let l = rng.poly(d, b);
            let m = rng.poly(d, b);
            let x = rng.poly(1, b);
            let y = rng.poly(1, b);
            let n = -&(&(&(&x * &x) * &l) + &(&(&y * &y) * &m));
            let s = describe(&[l, m, n]);
            let r = describe(&[rng.poly(d, b), rng.poly(d, b), rng.poly(d, b)]);
            println!("| {d} | {b} | {s} | {r} |");
        }
    }
}
