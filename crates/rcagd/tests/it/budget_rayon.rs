//! Work an op spreads over rayon inherits the caller's work budget (issue 19, item 1):
//! `rcagd_algebra::budget::inherit` installs the caller's deadline in every task, and an
//! exhausted budget unwinds out of the task and out of the parallel iteration to the
//! caller's `with_limit`.

use rayon::prelude::*;
use rcagd::canal::{pipe_along_chain, Orientation};
use rcagd_algebra::budget::{self, WorkLimitExceeded};
use rcagd_algebra::{Rational, Scalar};
use rcagd_geom::BezierCurve;
use std::time::{Duration, Instant};

#[test]
fn a_rayon_job_under_a_spent_budget_ends_promptly() {
    // every task would loop for ever without the budget: it ends only because the
    // caller's (spent) budget is installed in it
    let start = Instant::now();
    let r = budget::with_limit(Duration::from_millis(20), || {
        (0..8)
            .into_par_iter()
            .map(budget::inherit(|k: u64| {
                let mut x = k;
                loop {
                    budget::checkpoint();
                    x = x.wrapping_mul(6364136223846793005).wrapping_add(1);
                    std::hint::black_box(x);
                }
            }))
            .collect::<Vec<u64>>()
    });
    assert_eq!(
        r,
        Err(WorkLimitExceeded {
            limit: Duration::from_millis(20)
        })
    );
    assert!(
        start.elapsed() < Duration::from_secs(10),
        "{:?}",
        start.elapsed()
    );
    assert_eq!(budget::current(), None);
}

fn q(n: i64) -> Rational {
    Rational::from(n)
}

#[test]
fn the_pieces_of_a_pipe_along_a_chain_are_built_under_the_callers_budget() {
    // three planar cubic spine pieces: the pipes around them are built in parallel
    let piece = |x: i64| {
        BezierCurve::from_points(&[
            vec![q(x), q(0), q(0)],
            vec![q(x + 1), q(1), q(0)],
            vec![q(x + 2), q(-1), q(0)],
            vec![q(x + 3), q(0), q(0)],
        ])
        .expect("curve")
    };
    let spine = vec![piece(0), piece(3), piece(6)];
    let radius = Rational::from_ratio(1, 50);
    let built = budget::with_limit(Duration::from_secs(3600), || {
        pipe_along_chain(&spine, &radius, Orientation::Positive).map(|c| c.patches().len())
    });
    assert!(matches!(built, Ok(Ok(n)) if n > 0), "{built:?}");
    let start = Instant::now();
    let spent = budget::with_limit(Duration::ZERO, || {
        pipe_along_chain(&spine, &radius, Orientation::Positive).map(|c| c.patches().len())
    });
    assert_eq!(
        spent,
        Err(WorkLimitExceeded {
            limit: Duration::ZERO
        })
    );
    assert!(
        start.elapsed() < Duration::from_secs(10),
        "{:?}",
        start.elapsed()
    );
}
