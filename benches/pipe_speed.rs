//! Wall time of the exact pipe around a PH quintic with every certificate, and of its global
//! self-intersection check alone (issue 17 / 20, docs/plans/pipes.md "Speed"). No criterion:
//! the median of repeated runs, printed as a table.
//!
//! Run: `cargo bench -p rcagd-benches --bench pipe_speed` (release profile, no extra
//! dependencies).

use rcagd::canal::{
    check_pipe_embedded, check_pipe_regularity, pipe_around_ph_exportable, pipe_around_ph_with,
    CanalSpine, Method, Orientation,
};
use rcagd::ph::PhCurve;
use rcagd::Certified;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::{Poly, Rational, Scalar};
use std::time::{Duration, Instant};

fn quintic(a: [[i64; 4]; 3]) -> PhCurve<Rational> {
    let q = |c: [i64; 4]| {
        Quaternion::new(
            Rational::from(c[0]),
            Rational::from(c[1]),
            Rational::from(c[2]),
            Rational::from(c[3]),
        )
    };
    let zero = Rational::from(0);
    PhCurve::new(a.map(q).to_vec(), [zero.clone(), zero.clone(), zero]).expect("PH quintic")
}

fn median(mut f: impl FnMut(), runs: usize) -> Duration {
    let mut v: Vec<Duration> = (0..runs)
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed()
        })
        .collect();
    v.sort();
    v[v.len() / 2]
}

fn main() {
    let cases = [
        // the gallery's pipe_ph_quintic (preimage 1, i + k, 1 + j), r = 1/10
        (
            "gallery quintic, r = 1/10",
            [[1, 0, 0, 0], [0, 1, 0, 1], [1, 0, 1, 0]],
            (1, 10),
        ),
        // issue 17's quintic, r = 1/8
        (
            "issue quintic, r = 1/8",
            [[1, 0, 0, 0], [1, 1, 0, 1], [0, 0, 1, 1]],
            (1, 8),
        ),
    ];
    let (zero, one) = (Rational::from(0), Rational::from(1));
    println!("| spine | local check r·κ < 1 | global check | pipe build + all certificates | of which certify() | build, Peternell–Pottmann only | build, Krasauskas only |");
    println!("| --- | --- | --- | --- | --- | --- | --- |");
    for (name, a, (p, d)) in cases {
        let c = quintic(a);
        let r = Rational::from_ratio(p, d);
        let s = CanalSpine::polynomial(c.position().clone(), Poly::constant(r.clone()));
        let local = median(
            || {
                let cert = check_pipe_regularity(&s, (&zero, &one)).expect("regular");
                assert!(cert.holds);
            },
            21,
        );
        let built =
            pipe_around_ph_exportable(&c, &r, (&zero, &one), Orientation::Positive).expect("pipe");
        let certify = median(
            || {
                std::hint::black_box(built.certify());
            },
            11,
        );
        let global = median(
            || {
                let cert = check_pipe_embedded(&s, (&zero, &one)).expect("embedded");
                assert!(cert.holds);
            },
            21,
        );
        let full = median(
            || {
                let e = pipe_around_ph_exportable(&c, &r, (&zero, &one), Orientation::Positive)
                    .expect("pipe");
                let certs = e.certify();
                assert!(certs.iter().all(|c| c.holds), "a certificate fails");
                std::hint::black_box(certs);
            },
            11,
        );
        let only = |m: Method| {
            median(
                || {
                    let e = pipe_around_ph_with(&c, &r, (&zero, &one), Orientation::Positive, m)
                        .expect("pipe");
                    std::hint::black_box(e);
                },
                11,
            )
        };
        let pp = only(Method::PeternellPottmann);
        let kr = only(Method::Krasauskas);
        let ms = |d: Duration| d.as_secs_f64() * 1e3;
        println!(
            "| {name} | {:.2} ms | {:.2} ms | {:.2} ms | {:.2} ms | {:.2} ms | {:.2} ms |",
            ms(local),
            ms(global),
            ms(full),
            ms(certify),
            ms(pp),
            ms(kr)
        );
    }
}
