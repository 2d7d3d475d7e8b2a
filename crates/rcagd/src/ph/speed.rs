//! Parametric speed, arc length, parameter at arc length, constant-feed sampling.
//!
//! docs/math/ph-curves.md, "Speed and arc length" (Besednjak §3.2): the arc length `s(t) = ∫₀ᵗ σ` of a PH curve is a
//! polynomial of degree `n`; with the Bernstein coefficients `σ_k` of `σ` (degree
//! `n − 1`), `s` has Bernstein coefficients `s_0 = 0`, `s_{k+1} = s_k + σ_k/n`, and the
//! total length is `S = (1/n) Σ_k σ_k`. For a regular curve `σ > 0` on `[0, 1]`, so `s` is
//! increasing and `s(t) = s*` has exactly one solution, found here by a safeguarded
//! Newton iteration on the exact polynomial (Newton steps inside a bracketing interval,
//! bisection when a step leaves it or stalls).

use super::hodograph::{PhCurve, PhPolyCurve};
use super::util::*;
use super::PhError;
use rcagd_algebra::bernstein;
use rcagd_algebra::{Certificate, Poly, Rational, Scalar};

/// A parameter `t` with `s(t) ≈ s*`, and an exact bracket: `s(lo) ≤ s* ≤ s(hi)`,
/// `lo ≤ t ≤ hi` (for exact scalars the bracket is a proof; for `f64` it is evaluated in
/// floating point).
#[derive(Debug, Clone, PartialEq)]
pub struct ArcLengthParameter<F> {
    /// The parameter (exact root if `lo == hi`).
    pub t: F,
    /// Lower end of the bracket.
    pub lo: F,
    /// Upper end of the bracket.
    pub hi: F,
    /// Number of Newton/bisection iterations used.
    pub iterations: usize,
}

impl<F: Scalar> PhPolyCurve<F> {
    /// The arc-length function `s(t) = ∫₀ᵗ σ(τ) dτ` in power form (docs/math/ph-curves.md, "Speed and arc length").
    pub fn arc_length_poly(&self) -> Poly<F> {
        integrate(&self.sigma)
    }

    /// Arc length between the parameters `a` and `b`: `s(b) − s(a)`.
    pub fn arc_length_between(&self, a: &F, b: &F) -> F {
        let s = self.arc_length_poly();
        s.eval(b) - s.eval(a)
    }

    /// Total arc length `s(1)` on `[0, 1]`.
    pub fn arc_length(&self) -> F {
        self.arc_length_poly().eval(&F::one())
    }

    /// The parameter `t ∈ [0, 1]` at arc length `s*` from `r(0)`: the root of
    /// `s(t) − s*` by a safeguarded Newton iteration, stopped when the bracket is
    /// narrower than `tol` (or an exact root is hit). For exact scalars the Newton
    /// iterates are rounded to nearby dyadic rationals (the bracket stays exact).
    ///
    /// # Errors
    /// [`PhError::OutOfRange`] if `s* ∉ [0, S]` or `tol ≤ 0`; [`PhError::Degenerate`] if `σ`
    /// vanishes identically.
    pub fn parameter_at_arc_length(
        &self,
        target: &F,
        tol: &F,
    ) -> Result<ArcLengthParameter<F>, PhError> {
        let s = self.arc_length_poly();
        let total = s.eval(&F::one());
        self.param_search(&s, &total, target, tol, None)
    }

    pub(crate) fn param_search(
        &self,
        s: &Poly<F>,
        total: &F,
        target: &F,
        tol: &F,
        guess: Option<F>,
    ) -> Result<ArcLengthParameter<F>, PhError> {
        if self.sigma.is_zero() {
            return Err(PhError::Degenerate("σ ≡ 0".into()));
        }
        if *tol <= F::zero() {
            return Err(PhError::OutOfRange(format!(
                "the tolerance must be positive, got {}",
                fmt_scalar(tol)
            )));
        }
        // f64: a target within round-off of an end is clamped to it
        let target = &if !F::EXACT
            && (target.to_f64() - total.to_f64()).abs() <= 1e-12 * total.to_f64().abs()
        {
            total.clone()
        } else if !F::EXACT && target.to_f64().abs() <= 1e-12 * total.to_f64().abs() {
            F::zero()
        } else {
            target.clone()
        };
        if *target < F::zero() || *target > *total {
            return Err(PhError::OutOfRange(format!(
                "arc length {} outside [0, {}]",
                fmt_scalar(target),
                fmt_scalar(total)
            )));
        }
        let f = |t: &F| s.eval(t) - target.clone();
        let mut lo = F::zero();
        let mut hi = F::one();
        if target.is_zero() {
            return Ok(ArcLengthParameter {
                t: lo.clone(),
                lo,
                hi: F::zero(),
                iterations: 0,
            });
        }
        if *target == *total {
            return Ok(ArcLengthParameter {
                t: hi.clone(),
                lo: F::one(),
                hi,
                iterations: 0,
            });
        }
        let two = F::from_i64(2);
        let mut t = guess
            .filter(|g| *g > F::zero() && *g < F::one())
            .unwrap_or_else(|| target.clone() / total.clone());
        let round = |x: F| -> F {
            if F::EXACT {
                match Rational::try_from(x.to_f64()) {
                    Ok(q) => F::from_rational(&q),
                    Err(_) => x,
                }
            } else {
                x
            }
        };
        for it in 1..=400 {
            let ft = f(&t);
            if ft.is_zero() {
                return Ok(ArcLengthParameter {
                    t: t.clone(),
                    lo: t.clone(),
                    hi: t,
                    iterations: it,
                });
            }
            if ft < F::zero() {
                lo = t.clone();
            } else {
                hi = t.clone();
            }
            if hi.clone() - lo.clone() <= *tol {
                return Ok(ArcLengthParameter {
                    t,
                    lo,
                    hi,
                    iterations: it,
                });
            }
            let d = self.sigma.eval(&t);
            let mut next = None;
            if d > F::zero() {
                let step = ft.clone() / d;
                let cand = round(t.clone() - step.clone());
                if cand > lo && cand < hi && cand != t {
                    // Newton converged to within tol: bracket the root from both sides.
                    if step.abs() <= tol.clone() / two.clone() {
                        let half = tol.clone() / two.clone() / two.clone();
                        let a = round(cand.clone() - half.clone());
                        let b = round(cand.clone() + half);
                        let a = if a > lo { a } else { lo.clone() };
                        let b = if b < hi { b } else { hi.clone() };
                        if f(&a) <= F::zero() && f(&b) >= F::zero() {
                            return Ok(ArcLengthParameter {
                                t: cand,
                                lo: a,
                                hi: b,
                                iterations: it,
                            });
                        }
                    }
                    next = Some(cand);
                }
            }
            t = next.unwrap_or_else(|| (lo.clone() + hi.clone()) / two.clone());
        }
        Ok(ArcLengthParameter {
            t,
            lo,
            hi,
            iterations: 400,
        })
    }

    /// Constant-feed sampling: parameters `t_0 = 0 < t_1 < … < t_N = 1` with
    /// `s(t_k) = k·S/N` (to within `tol` in `t`), each search started from the previous
    /// parameter shifted by the local feed (Besednjak §3.2, docs/math/ph-curves.md, "Speed and arc length").
    ///
    /// # Errors
    /// [`PhError::OutOfRange`] for `count = 0`; as [`Self::parameter_at_arc_length`].
    pub fn constant_feed_parameters(&self, count: usize, tol: &F) -> Result<Vec<F>, PhError> {
        if count == 0 {
            return Err(PhError::OutOfRange(
                "at least one feed step is needed".into(),
            ));
        }
        let s = self.arc_length_poly();
        let total = s.eval(&F::one());
        let step = total.clone() / F::from_i64(count as i64);
        let mut out = vec![F::zero()];
        let mut prev = F::zero();
        for k in 1..count {
            let target = step.clone() * F::from_i64(k as i64);
            let sp = self.sigma.eval(&prev);
            let guess = if sp > F::zero() {
                Some(prev.clone() + (target.clone() - s.eval(&prev)) / sp)
            } else {
                None
            };
            let p = self.param_search(&s, &total, &target, tol, guess)?;
            prev = p.t.clone();
            out.push(p.t);
        }
        out.push(F::one());
        Ok(out)
    }

    /// Certificate `s'(t) ≡ σ(t)` and `s(0) = 0` for the arc-length polynomial.
    pub fn certify_arc_length(&self) -> Vec<Certificate> {
        let s = self.arc_length_poly();
        vec![
            identity_cert("s'(t) ≡ σ(t) (arc length)", &s.derivative(), &self.sigma),
            scalar_cert("s(0) = 0", &s.eval(&F::zero()), &F::zero()),
        ]
    }
}

impl<F: Scalar> PhCurve<F> {
    /// The Bernstein coefficients (degree `n`) of the arc-length function:
    /// `s_0 = 0`, `s_{k+1} = s_k + σ_k/n` (docs/math/ph-curves.md, "Speed and arc length").
    pub fn arc_length_bernstein(&self) -> Vec<F> {
        let sig = self.speed_bernstein();
        let n = F::from_i64(sig.len() as i64);
        let mut out = vec![F::zero()];
        for s in sig {
            let last = out.last().cloned().unwrap_or_else(F::zero);
            out.push(last + s / n.clone());
        }
        out
    }

    /// Total arc length `S = (1/n) Σ_k σ_k` (docs/math/ph-curves.md, "Speed and arc length").
    pub fn arc_length(&self) -> F {
        let sig = self.speed_bernstein();
        let n = F::from_i64(sig.len() as i64);
        sig.into_iter().fold(F::zero(), |a, b| a + b) / n
    }

    /// The parameter at arc length `s*` (see [`PhPolyCurve::parameter_at_arc_length`]).
    ///
    /// # Errors
    /// As [`PhPolyCurve::parameter_at_arc_length`].
    pub fn parameter_at_arc_length(
        &self,
        target: &F,
        tol: &F,
    ) -> Result<ArcLengthParameter<F>, PhError> {
        self.to_poly_curve().parameter_at_arc_length(target, tol)
    }

    /// Certificates of the arc length: `s'(t) ≡ σ(t)` for the Bernstein form of `s`, and
    /// `s(1) = (1/n)Σσ_k` agrees with `∫₀¹ σ` in power form (docs/math/ph-curves.md).
    pub fn certify_arc_length(&self) -> Vec<Certificate> {
        let s = bernstein::from_bernstein(&self.arc_length_bernstein());
        let sigma = self.speed();
        vec![
            identity_cert(
                "s'(t) ≡ σ(t) for s with Bernstein coefficients s_{k+1} = s_k + σ_k/n (Besednjak §3.2)",
                &s.derivative(),
                &sigma,
            ),
            scalar_cert(
                "s(1) = (1/n)Σσ_k equals ∫₀¹ σ",
                &self.arc_length(),
                &integrate(&sigma).eval(&F::one()),
            ),
        ]
    }
}
