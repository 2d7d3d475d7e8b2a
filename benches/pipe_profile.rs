//! A loop of the exact pipe build with every certificate (the gallery quintic, or issue 17's
//! with `issue` as the first argument), for `perf record` (docs/plans/pipes.md, "Speed").
//!
//! Run: `cargo bench -p rcagd-benches --bench pipe_profile --no-run`, then
//! `perf record --call-graph dwarf target/release/deps/pipe_profile-… [issue] [runs]`.
//! Prints the summary of the choice, the CPU time and the wall time of every run (the CPU
//! time from `/proc/self/task/*/schedstat`, ns; read by `benches/occ/pipe_ratio.py`), and
//! their median / mean.

use rcagd::canal::{pipe_around_ph_exportable, Orientation};
use rcagd::ph::PhCurve;
use rcagd::Certified;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::{Rational, Scalar};
use std::time::Instant;

/// The CPU time (user + system) of this process so far in ms, from `/proc/self/stat` (in
/// clock ticks of 10 ms: meaningful summed over many runs), or `None` without that file.
fn cpu_ms() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/self/stat").ok()?;
    // the fields after the command name (which is in parentheses)
    let rest = s.get(s.rfind(')')? + 2..)?;
    let f: Vec<&str> = rest.split_whitespace().collect();
    let utime: f64 = f.get(11)?.parse().ok()?;
    let stime: f64 = f.get(12)?.parse().ok()?;
    Some((utime + stime) * 10.0)
}

/// The CPU time of this process so far in ns: the sum over its threads of the first field
/// of `/proc/self/task/*/schedstat` (the scheduler's run time, ns resolution), or `None`
/// without those files.
fn cpu_ns() -> Option<u64> {
    let mut total = 0u64;
    for t in std::fs::read_dir("/proc/self/task").ok()? {
        let s = std::fs::read_to_string(t.ok()?.path().join("schedstat")).ok()?;
        total += s.split_whitespace().next()?.parse::<u64>().ok()?;
    }
    Some(total)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let issue = args.get(1).is_some_and(|a| a == "issue");
    let runs: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(50);
    let (a, r) = if issue {
        ([[1, 0, 0, 0], [1, 1, 0, 1], [0, 0, 1, 1]], (1, 8))
    } else {
        ([[1, 0, 0, 0], [0, 1, 0, 1], [1, 0, 1, 0]], (1, 10))
    };
    let q = |c: [i64; 4]| {
        Quaternion::new(
            Rational::from(c[0]),
            Rational::from(c[1]),
            Rational::from(c[2]),
            Rational::from(c[3]),
        )
    };
    let zero = Rational::from(0);
    let c = PhCurve::new(
        a.map(q).to_vec(),
        [zero.clone(), zero.clone(), zero.clone()],
    )
    .expect("PH quintic");
    let r = Rational::from_ratio(r.0, r.1);
    let one = Rational::from(1);
    let mut times = Vec::new();
    let mut cpu_runs = Vec::new();
    let cpu0 = cpu_ms();
    let mut summary = String::new();
    for _ in 0..runs {
        let t = Instant::now();
        let c0 = cpu_ns();
        let e =
            pipe_around_ph_exportable(&c, &r, (&zero, &one), Orientation::Positive).expect("pipe");
        let certs = e.certify();
        assert!(certs.iter().all(|c| c.holds), "a certificate fails");
        times.push(t.elapsed().as_secs_f64() * 1e3);
        if let (Some(a), Some(b)) = (c0, cpu_ns()) {
            cpu_runs.push(b.saturating_sub(a) as f64 / 1e6);
        }
        summary = e.summary();
    }
    // every run, in order (for benches/occ/pipe_ratio.py: medians and spreads across runs)
    let list = |v: &[f64]| {
        v.iter()
            .map(|x| format!("{x:.4}"))
            .collect::<Vec<_>>()
            .join(" ")
    };
    println!("per-run CPU ms: {}", list(&cpu_runs));
    println!("per-run wall ms: {}", list(&times));
    times.sort_by(f64::total_cmp);
    let cpu = match (cpu0, cpu_ms()) {
        (Some(a), Some(b)) => (b - a) / runs as f64,
        _ => f64::NAN,
    };
    println!("{summary}");
    println!(
        "wall: median {:.2} ms, min {:.2} ms; CPU: mean {cpu:.2} ms; over {runs} runs",
        times[times.len() / 2],
        times[0],
    );
}
