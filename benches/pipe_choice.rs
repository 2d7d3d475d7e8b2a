//! The choices of the exact pipe's candidate search, printed (one line per spine: the summary
//! and a hash of the whole result), to compare two versions of the search
//! (docs/plans/pipes.md, "Speed"): the seed quintics with and without their split, random PH
//! quintics and pipes around random planar cubics (a fixed pseudo-random sequence).
//!
//! Run: `cargo bench -p rcagd-benches --bench pipe_choice` (release). Each line: the hash of
//! the whole result, `chosen` and the hash of the chosen pipe alone (its pieces and
//! certificates, without the counts of candidates), the summary.

use rcagd::canal::pipe_around_ph_exportable;
use rcagd::canal::{canal_surface_exportable, CanalOptions, CanalSpine, Orientation};
use rcagd::ph::PhCurve;
use rcagd::Certified;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::{Poly, Rational, Scalar};
use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};

fn q(n: i64) -> Rational {
    Rational::from(n)
}

fn quintic(a: &[[i64; 4]]) -> Option<PhCurve<Rational>> {
    let quats = a
        .iter()
        .map(|c| Quaternion::new(q(c[0]), q(c[1]), q(c[2]), q(c[3])))
        .collect();
    PhCurve::new(quats, [q(0), q(0), q(0)]).ok()
}

fn report<E: std::fmt::Debug>(name: &str, r: Result<rcagd::canal::ExportableCanal, E>) {
    match r {
        Ok(e) => {
            let mut h = DefaultHasher::new();
            format!("{e:?}").hash(&mut h);
            format!("{:?}", e.certify()).hash(&mut h);
            // the chosen pipe alone (pieces: interval, frame, surface, patches; and the
            // certificates), without the counts of candidates tried and exporting, which
            // pruning the search changes
            let mut c = DefaultHasher::new();
            format!("{:?}", e.pieces()).hash(&mut c);
            format!("{:?}", e.certify()).hash(&mut c);
            println!(
                "{name}: {:016x} chosen {:016x} {}",
                h.finish(),
                c.finish(),
                e.summary()
            );
        }
        Err(e) => println!("{name}: error {e:?}"),
    }
}

fn main() {
    let (zero, one) = (q(0), q(1));
    let seeds = [
        ([[1, 0, 0, 0], [0, 1, 0, 1], [1, 0, 1, 0]], (1, 10)),
        ([[1, 0, 0, 0], [1, 1, 0, 1], [0, 0, 1, 1]], (1, 8)),
    ];
    for (k, (a, r)) in seeds.iter().enumerate() {
        let c = quintic(a).expect("PH");
        let r = Rational::from_ratio(r.0, r.1);
        report(
            &format!("seed {k} ph"),
            pipe_around_ph_exportable(&c, &r, (&zero, &one), Orientation::Positive),
        );
        let s = CanalSpine::polynomial(c.position().clone(), Poly::constant(r));
        let options = CanalOptions {
            domain: Some((q(0), q(1))),
            ..CanalOptions::default()
        };
        report(
            &format!("seed {k} general"),
            canal_surface_exportable(&s, None, &options),
        );
    }
    let mut state: u64 = 0x2545_f491_4f6c_dd1d;
    let mut next = |lo: i64, hi: i64| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        lo + (state % (hi - lo) as u64) as i64
    };
    let cases: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(24);
    for k in 0..cases {
        let a: Vec<[i64; 4]> = (0..3)
            .map(|_| [next(-3, 4), next(-3, 4), next(-3, 4), next(-3, 4)])
            .collect();
        let r = Rational::from_ratio(next(1, 20), 40);
        if let Some(c) = quintic(&a) {
            report(
                &format!("random {k} ph {a:?}"),
                pipe_around_ph_exportable(&c, &r, (&zero, &one), Orientation::Positive),
            );
        }
        let cubic: Vec<i64> = (0..12).map(|_| next(-4, 5)).collect();
        let planar = next(0, 2) == 0;
        let m: [Poly<Rational>; 3] = core::array::from_fn(|i| match i {
            2 if planar => Poly::zero(),
            2 => Poly::from_ints(&cubic[..4]),
            _ => Poly::from_ints(&cubic[4 * i..4 * i + 4]),
        });
        let s = CanalSpine::polynomial(m, Poly::constant(r));
        let options = CanalOptions {
            domain: Some((q(0), q(1))),
            ..CanalOptions::default()
        };
        report(
            &format!("random {k} cubic {cubic:?} {planar}"),
            canal_surface_exportable(&s, None, &options),
        );
    }
}
