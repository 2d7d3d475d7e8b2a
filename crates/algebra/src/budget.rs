//! A work budget for long exact computations: cooperative cancellation.
//!
//! Exact arithmetic has no a-priori bound on its running time that is both cheap to
//! state and tight: a resultant, a subresultant PRS or a tensor Bernstein conversion of
//! inputs of valid size can still take many seconds when the coefficients grow. A
//! *budget* is a deadline installed on the current thread for the duration of one
//! computation ([`with_limit`], or the scoped [`Guard`] of [`install`]); the hot loops
//! of the exact algebra (polynomial products, divisions, gcds and PRS, resultants,
//! multivariate products, factorization, Bernstein conversions, root isolation) call
//! [`checkpoint`], which ends the computation promptly once the deadline has passed.
//!
//! How the computation ends: the checkpoint unwinds the stack with a private payload
//! ([`WorkLimitExceeded`]) through [`std::panic::resume_unwind`], which does not run the
//! panic hook (nothing is printed); [`with_limit`] catches exactly that payload and
//! returns it as an error value (any other panic continues to unwind). Code between the
//! checkpoint and the boundary is left by unwinding, so it must not hold invariants
//! across a checkpoint that a drop cannot restore (the algebra holds none: its values
//! are immutable or local).
//!
//! Without a budget installed, [`checkpoint`] reads one thread-local cell and returns.
//! With one, it counts, and every [`STRIDE`]-th checkpoint (and the first one after a
//! budget is installed) reads the monotonic clock (`Instant::now`, a vDSO call of a few
//! tens of nanoseconds on Linux): floating-point polynomial products, whose rows cost
//! about as much as a clock read, stay fast under a budget. Checkpoints are placed
//! where the work between two of them is far larger than a counter step (a row of a
//! product, a step of a division or a PRS).
//!
//! Budgets nest: an inner budget never extends an outer one (the earlier deadline
//! wins), and the outer budget is restored when the inner scope ends. A budget is
//! per thread: work that a computation hands to other threads (rayon) runs without it
//! unless the code installs it there ([`inherit`] for the closure of a parallel `map`,
//! or [`current`] and [`within`]).

use std::cell::Cell;
use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};
use std::time::{Duration, Instant};

/// A deadline and the limit it was made from (for the message).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Budget {
    /// When the work must end.
    pub deadline: Instant,
    /// The time allowed (the deadline minus the moment the budget was made).
    pub limit: Duration,
}

impl Budget {
    /// A budget of `limit` from now (a limit so large that the deadline cannot be
    /// represented is no deadline in practice: about 30 years from now).
    pub fn from_now(limit: Duration) -> Self {
        let now = Instant::now();
        let deadline = now
            .checked_add(limit)
            .or_else(|| now.checked_add(Duration::from_secs(1 << 30)))
            .unwrap_or(now);
        Budget { deadline, limit }
    }

    /// The earlier of two budgets.
    fn min(self, other: Budget) -> Budget {
        if other.deadline < self.deadline {
            other
        } else {
            self
        }
    }
}

/// The error (and the unwinding payload) of a computation that ran out of its budget.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("work limit exceeded: the computation took more than {} s", secs(self.limit))]
pub struct WorkLimitExceeded {
    /// The time that was allowed.
    pub limit: Duration,
}

/// A duration in seconds for messages: whole seconds when it is whole, else to 0.001 s.
pub fn secs(d: Duration) -> String {
    if d.subsec_nanos() == 0 {
        d.as_secs().to_string()
    } else {
        format!("{:.3}", d.as_secs_f64())
    }
}

/// The clock is read at every `STRIDE`-th checkpoint under a budget.
pub const STRIDE: u32 = 32;

thread_local! {
    static CURRENT: Cell<Option<Budget>> = const { Cell::new(None) };
    /// Checkpoints left before the next clock read.
    static COUNTDOWN: Cell<u32> = const { Cell::new(0) };
}

/// The budget installed on this thread, if any.
pub fn current() -> Option<Budget> {
    CURRENT.with(Cell::get)
}

/// Restores the previous budget of its thread when dropped (also while unwinding).
#[must_use = "the budget is removed when the guard is dropped"]
#[derive(Debug)]
pub struct Guard {
    previous: Option<Budget>,
}

impl Drop for Guard {
    fn drop(&mut self) {
        CURRENT.with(|c| c.set(self.previous));
    }
}

/// Installs `budget` on this thread until the returned guard is dropped; an outer
/// budget with an earlier deadline stays in force.
pub fn install_budget(budget: Budget) -> Guard {
    let previous = current();
    let b = previous.map_or(budget, |p| p.min(budget));
    CURRENT.with(|c| c.set(Some(b)));
    // the first checkpoint under the new budget reads the clock
    COUNTDOWN.with(|c| c.set(0));
    Guard { previous }
}

/// Installs a budget of `limit` from now on this thread until the guard is dropped.
pub fn install(limit: Duration) -> Guard {
    install_budget(Budget::from_now(limit))
}

/// Runs `f` under `budget` when there is one (nested in any budget of this thread, the
/// earlier deadline wins), else as it is: how a task on another thread takes over the
/// budget of the code that spawned it (`let b = budget::current();` there,
/// `budget::within(b, || …)` in the task).
pub fn within<T>(budget: Option<Budget>, f: impl FnOnce() -> T) -> T {
    let _guard = budget.map(install_budget);
    f()
}

/// Wraps the closure of a parallel iterator's `map` (or any task run on other threads)
/// so that every call runs under the budget of the thread that made the wrapper (the
/// caller of the parallel iteration): `.par_iter().map(budget::inherit(|x| …))`.
/// An exhausted budget unwinds out of the task, and rayon carries that unwinding (its
/// payload unchanged) to the caller, where [`catch`] or [`with_limit`] turn it into
/// [`WorkLimitExceeded`].
pub fn inherit<A, T, F>(f: F) -> impl Fn(A) -> T + Send + Sync
where
    F: Fn(A) -> T + Send + Sync,
{
    let budget = current();
    move |a| within(budget, || f(a))
}

/// Ends the computation (by unwinding with a [`WorkLimitExceeded`] payload, caught by
/// [`with_limit`] or [`catch`]) when this thread's budget is exhausted (the clock is
/// read at the first checkpoint under a budget and then at every [`STRIDE`]-th);
/// returns at once when no budget is installed.
#[inline]
pub fn checkpoint() {
    if let Some(b) = current() {
        let left = COUNTDOWN.with(Cell::get);
        if left == 0 {
            COUNTDOWN.with(|c| c.set(STRIDE - 1));
            exhausted(b);
        } else {
            COUNTDOWN.with(|c| c.set(left - 1));
        }
    }
}

#[cold]
#[inline(never)]
fn exhausted(b: Budget) {
    if Instant::now() >= b.deadline {
        resume_unwind(Box::new(WorkLimitExceeded { limit: b.limit }));
    }
}

/// Whether this thread's budget is exhausted (for code that returns a `Result` and
/// prefers to propagate the error itself).
///
/// # Errors
/// [`WorkLimitExceeded`] when the deadline has passed.
pub fn check() -> Result<(), WorkLimitExceeded> {
    match current() {
        Some(b) if Instant::now() >= b.deadline => Err(WorkLimitExceeded { limit: b.limit }),
        _ => Ok(()),
    }
}

/// Runs `f` and turns an unwinding [`WorkLimitExceeded`] payload into an error; any
/// other panic continues to unwind. Installs no budget (see [`with_limit`]).
///
/// # Errors
/// [`WorkLimitExceeded`] when a checkpoint inside `f` found the budget exhausted.
pub fn catch<T>(f: impl FnOnce() -> T) -> Result<T, WorkLimitExceeded> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(v) => Ok(v),
        Err(payload) => match payload.downcast::<WorkLimitExceeded>() {
            Ok(e) => Err(*e),
            Err(other) => resume_unwind(other),
        },
    }
}

/// Whether a caught panic payload is a budget's [`WorkLimitExceeded`] (for code that
/// catches panics itself).
pub fn as_work_limit(payload: &(dyn std::any::Any + Send)) -> Option<WorkLimitExceeded> {
    payload.downcast_ref::<WorkLimitExceeded>().copied()
}

/// Runs `f` with a work budget of `limit` (nested in any budget already installed):
/// the library's entry point for bounded exact work.
///
/// ```
/// use rcagd_algebra::{budget, Poly, Rational};
/// use std::time::Duration;
/// let p = Poly::new(vec![Rational::from(1), Rational::from(1)]);
/// let q = budget::with_limit(Duration::from_secs(60), || p.pow(8)).unwrap();
/// assert_eq!(q.degree(), Some(8));
/// ```
///
/// # Errors
/// [`WorkLimitExceeded`] when `f` was still working at the deadline (it ended at its
/// next checkpoint).
pub fn with_limit<T>(limit: Duration, f: impl FnOnce() -> T) -> Result<T, WorkLimitExceeded> {
    let _guard = install(limit);
    catch(f)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_budget_means_no_change() {
        assert_eq!(current(), None);
        checkpoint();
        assert_eq!(check(), Ok(()));
        assert_eq!(catch(|| 7), Ok(7));
    }

    #[test]
    fn a_spent_budget_ends_at_the_next_checkpoint_and_is_removed_after() {
        let r = with_limit(Duration::ZERO, || {
            checkpoint();
            1
        });
        assert_eq!(
            r,
            Err(WorkLimitExceeded {
                limit: Duration::ZERO
            })
        );
        assert_eq!(current(), None);
        assert_eq!(
            r.unwrap_err().to_string(),
            "work limit exceeded: the computation took more than 0 s"
        );
    }

    #[test]
    fn budgets_nest_and_the_earlier_deadline_wins() {
        let r = with_limit(Duration::ZERO, || {
            with_limit(Duration::from_secs(3600), || {
                checkpoint();
            })
        });
        // the inner scope reports the outer (earlier) budget's limit
        assert_eq!(
            r,
            Ok(Err(WorkLimitExceeded {
                limit: Duration::ZERO
            }))
        );
        let outer = with_limit(Duration::from_secs(3600), || {
            let inner = with_limit(Duration::ZERO, checkpoint);
            assert!(inner.is_err());
            // the outer budget is back in force
            checkpoint();
            current().map(|b| b.limit)
        });
        assert_eq!(outer, Ok(Some(Duration::from_secs(3600))));
    }

    /// `Σ (k+1)/(k+2) xᵏ` of degree `n`.
    fn p(n: i64) -> crate::Poly<crate::Rational> {
        use crate::Rational;
        crate::Poly::new(
            (0..=n)
                .map(|k| Rational::from(k + 1) / Rational::from(k + 2))
                .collect(),
        )
    }

    #[test]
    fn a_long_exact_computation_ends_promptly_under_a_tiny_budget() {
        // powers of a degree-60 polynomial: hours of work without a budget
        let p = p(60);
        let start = Instant::now();
        let r = with_limit(Duration::from_millis(50), || {
            let mut q = p.clone();
            for _ in 0..10_000 {
                q = &q * &p;
            }
            q
        });
        let took = start.elapsed();
        assert_eq!(
            r.map(|q| q.degree()),
            Err(WorkLimitExceeded {
                limit: Duration::from_millis(50)
            })
        );
        assert!(took < Duration::from_secs(5), "took {took:?}");
        assert_eq!(current(), None);
    }

    #[test]
    fn a_budget_that_is_not_exhausted_changes_no_result() {
        let work = || {
            let p = p(12);
            let q = &(&p * &p) * &p;
            (
                crate::resultant::resultant(&p, &p.derivative()),
                q.gcd(&q.derivative()),
                crate::roots::isolate_real_roots(&q.derivative()).map(|r| r.len()),
            )
        };
        let plain = work();
        assert_eq!(with_limit(Duration::from_secs(3600), work), Ok(plain));
    }

    /// The cost of a checkpoint (measured, not asserted: `cargo test --profile test -p
    /// rcagd-algebra --lib budget::tests::checkpoint_cost -- --ignored --nocapture`).
    #[test]
    #[ignore = "a measurement"]
    fn checkpoint_cost() {
        let n = 100_000_000u32;
        let t = Instant::now();
        for _ in 0..n {
            checkpoint();
        }
        let none = t.elapsed().as_secs_f64() / f64::from(n) * 1e9;
        let m = 10_000_000u32;
        let with = with_limit(Duration::from_secs(3600), || {
            let t = Instant::now();
            for _ in 0..m {
                checkpoint();
            }
            t.elapsed().as_secs_f64() / f64::from(m) * 1e9
        })
        .unwrap();
        // an exact workload (products, gcds, resultants, root isolation) without and with
        // a budget installed
        let work = || {
            let p = p(30);
            let q = &(&p * &p) * &p;
            let g = q.gcd(&q.derivative());
            let r = crate::resultant::resultant(&p, &p.derivative());
            let roots = crate::roots::isolate_real_roots(&q.derivative()).map(|r| r.len());
            (g.degree(), r, roots)
        };
        let time = |f: &dyn Fn()| {
            let mut best = f64::INFINITY;
            for _ in 0..7 {
                let t = Instant::now();
                f();
                best = best.min(t.elapsed().as_secs_f64());
            }
            best
        };
        let plain = time(&|| {
            let _ = std::hint::black_box(work());
        });
        let budgeted = time(&|| {
            let _ = std::hint::black_box(with_limit(Duration::from_secs(3600), work).unwrap());
        });
        // a floating-point workload: many small products (a row costs about a clock read)
        let fwork = || {
            let a = crate::Poly::new(vec![0.5f64, -1.25, 2.0, 0.75, -0.5, 1.5]);
            let mut acc = 0.0;
            for k in 0..200_000 {
                let b = crate::Poly::new(vec![1.0, f64::from(k % 7), -0.25]);
                acc += (&a * &b).eval(&0.5);
            }
            acc
        };
        let fplain = time(&|| {
            let _ = std::hint::black_box(fwork());
        });
        let fbudgeted = time(&|| {
            let _ = std::hint::black_box(with_limit(Duration::from_secs(3600), fwork).unwrap());
        });
        eprintln!(
            "checkpoint: {none:.2} ns without a budget, {with:.1} ns with one; exact workload \
             {:.1} ms without, {:.1} ms with a budget ({:+.1} %); f64 products {:.1} ms \
             without, {:.1} ms with a budget ({:+.1} %)",
            plain * 1e3,
            budgeted * 1e3,
            (budgeted / plain - 1.0) * 100.0,
            fplain * 1e3,
            fbudgeted * 1e3,
            (fbudgeted / fplain - 1.0) * 100.0
        );
    }

    #[test]
    fn within_and_inherit_carry_a_budget_to_other_threads() {
        assert_eq!(within(None, current), None);
        let r = with_limit(Duration::ZERO, || {
            let task = inherit(|x: u32| {
                checkpoint();
                x
            });
            // the task runs on another thread, as a rayon worker would run it
            std::thread::scope(|s| s.spawn(|| catch(|| task(1))).join().unwrap())
        });
        assert_eq!(
            r,
            Ok(Err(WorkLimitExceeded {
                limit: Duration::ZERO
            }))
        );
        // without a budget at the wrapper's creation the task runs unbudgeted
        let task = inherit(|x: u32| {
            checkpoint();
            x + 1
        });
        assert_eq!(
            std::thread::scope(|s| s.spawn(|| catch(|| task(1))).join().unwrap()),
            Ok(2)
        );
    }

    #[test]
    fn other_panics_pass_through() {
        let r = std::panic::catch_unwind(|| with_limit(Duration::from_secs(5), || panic!("x")));
        assert!(r.is_err());
        assert_eq!(current(), None);
    }
}
