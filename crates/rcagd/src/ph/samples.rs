//! Sampled PH-curve data for display and machining: curvature combs and constant-feed
//! marks with their accuracy certificate.
//!
//! * **Comb.** The tooth at `t` joins `r(t)` to `r(t) + λ·κn(t)`, `κn = (σr'' − σ'r')/σ³`
//!   the curvature vector ([`PhPolyCurve::curvature_vector`]; docs/math/ph-curves.md,
//!   "Curvature and torsion"; Farin, *Curves and Surfaces for CAGD*, §23.3 on curvature
//!   plots): exact at rational `t`, skipped where `σ(t) = 0`.
//! * **Feed.** The parameters `t_k` with `s(t_k) = k·S/N` (`s` the arc-length polynomial,
//!   `S = s(1)`) to the parameter tolerance `τ` ([`PhPolyCurve::constant_feed_parameters`];
//!   Farouki, *Pythagorean-Hodograph Curves*, §17.2, real-time interpolators). Since
//!   `|s(t) − s(t*)| ≤ max σ · |t − t*|` and `max σ` on `[0, 1]` is at most the largest
//!   Bernstein coefficient of `σ`, the certificate decides `|s(t_k) − k·S/N| ≤ max σ · τ`
//!   for every mark, exactly.

use super::hodograph::{PhCurve, PhPolyCurve};
use super::util::{add3, peval, scale3};
use super::PhError;
use rcagd_algebra::{format_scalar, Certificate, Scalar};

impl<F: Scalar> PhPolyCurve<F> {
    /// The comb teeth `(r(t), r(t) + λ·κn(t))` at the parameters `ts` (module docs),
    /// skipping the zeros of `σ`.
    pub fn curvature_comb(&self, ts: &[F], lambda: &F) -> Vec<([F; 3], [F; 3])> {
        let (num, den) = self.curvature_vector();
        let mut out = Vec::with_capacity(ts.len());
        for t in ts {
            let d = den.eval(t);
            if d.is_zero() {
                continue;
            }
            let p = self.eval(t);
            let tip = add3(&p, &scale3(&peval(&num, t), &(lambda.clone() / d)));
            out.push((p, tip));
        }
        out
    }
}

/// Constant-feed marks of a PH curve ([`PhCurve::constant_feed_marks`]).
#[derive(Debug, Clone, PartialEq)]
pub struct FeedMarks<F> {
    /// The parameters `t_k`, `k = 0 … N`.
    pub parameters: Vec<F>,
    /// The arc length `S`.
    pub total: F,
    /// `max_k |s(t_k) − k·S/N|`.
    pub worst: F,
    /// `max σ · τ` (largest Bernstein coefficient of `σ` times the tolerance).
    pub bound: F,
    /// `N`.
    pub count: usize,
}

impl<F: Scalar> PhCurve<F> {
    /// The `count + 1` constant-feed parameters to the tolerance `tol` and their worst arc
    /// length error (module docs).
    ///
    /// # Errors
    /// As [`PhPolyCurve::constant_feed_parameters`].
    pub fn constant_feed_marks(&self, count: usize, tol: &F) -> Result<FeedMarks<F>, PhError> {
        let pc = self.to_poly_curve();
        let parameters = pc.constant_feed_parameters(count, tol)?;
        let s = pc.arc_length_poly();
        let total = pc.arc_length();
        let smax = self
            .speed_bernstein()
            .into_iter()
            .fold(F::zero(), |a, b| if b > a { b } else { a });
        let bound = smax * tol.clone();
        let n = F::from_i64(i64::try_from(count).unwrap_or(i64::MAX));
        let mut worst = F::zero();
        for (k, t) in parameters.iter().enumerate() {
            let target = total.clone() * F::from_i64(k as i64) / n.clone();
            let err = (s.eval(t) - target).abs();
            if err > worst {
                worst = err;
            }
        }
        Ok(FeedMarks {
            parameters,
            total,
            worst,
            bound,
            count,
        })
    }
}

impl<F: Scalar> FeedMarks<F> {
    /// `|s(t_k) − k·S/N| ≤ max σ · τ` for every mark; `tol_text` names `τ` (e.g. `2⁻⁴⁰`).
    pub fn certificate(&self, tol_text: &str) -> Certificate {
        Certificate::decide(
            format!(
                "|s(t_k) − k·S/{}| ≤ max σ · {tol_text} for every mark (constant feed, S = {})",
                self.count,
                format_scalar(&self.total)
            ),
            self.worst <= self.bound,
            F::EXACT,
            || format!("worst |s(t_k) − k·S/N| = {}", format_scalar(&self.worst)),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::{Quaternion, Rational};

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    fn cubic() -> PhCurve<Rational> {
        let a0 = Quaternion {
            w: q(1),
            x: q(0),
            y: q(0),
            z: q(0),
        };
        let a1 = Quaternion {
            w: q(0),
            x: q(1),
            y: q(0),
            z: q(1),
        };
        PhCurve::new(vec![a0, a1], [q(0), q(0), q(0)]).unwrap()
    }

    #[test]
    fn comb_teeth_point_along_the_curvature_vector() {
        let pc = cubic().to_poly_curve();
        let ts: Vec<Rational> = (0..5).map(|k| q(k) / q(4)).collect();
        let teeth = pc.curvature_comb(&ts, &q(1));
        assert_eq!(teeth.len(), 5);
        let (num, den) = pc.curvature_vector();
        for ((p, tip), t) in teeth.iter().zip(&ts) {
            let d = den.eval(t);
            for i in 0..3 {
                assert_eq!(&tip[i] - &p[i], num[i].eval(t) / d.clone());
            }
        }
    }

    #[test]
    fn feed_marks_are_within_the_bound() {
        let c = cubic();
        let tol = q(1) / q(1 << 20);
        let m = c.constant_feed_marks(8, &tol).unwrap();
        assert_eq!(m.parameters.len(), 9);
        assert!(m.worst <= m.bound);
        assert!(m.certificate("2⁻²⁰").holds);
    }
}
