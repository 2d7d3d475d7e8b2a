//! A non-negative polynomial as a sum of two squares, `D = g₁² + g₂²`, for the canal-surface
//! constructions (D. Gruber, "Rationale Parametrisierungen von Kugelhüllflächen", 2008, §2.1
//! before (2.14); M. Peternell, "Rational Parametrizations for Envelopes of Quadric
//! Families", (4.9)).
//!
//! The exact decomposition is the algebra layer's engine
//! ([`rcagd_algebra::sum_of_squares`]: complete over `Q`, or over one named real quadratic
//! field); this module only adds the canal-specific diagnosis (the parameter interval where
//! `D < 0`) and the explicit `f64` split [`sum_of_two_squares_f64`], computed from the
//! complex roots. Never silently in `f64`.

use super::{negative_interval, CanalError};
use rcagd_algebra::complex::{re_im_polys, Complex};
use rcagd_algebra::roots::square_free_decomposition;
pub use rcagd_algebra::sum_of_squares::{GaussianSplit, SumOfSquares, SumOfSquaresError};
use rcagd_algebra::{Poly, Rational, Scalar};

impl From<SumOfSquaresError> for CanalError {
    fn from(e: SumOfSquaresError) -> Self {
        match e {
            SumOfSquaresError::Zero => CanalError::DegenerateSpine("D ≡ 0".into()),
            SumOfSquaresError::NeedsLargerExtension(m) => CanalError::NeedsLargerExtension(m),
            SumOfSquaresError::Factorization(m) => CanalError::Factorization(m),
            SumOfSquaresError::Algebra(a) => CanalError::Algebra(a),
            other => CanalError::InvalidArgument(other.to_string()),
        }
    }
}

/// The factorization of `D` over `Q(i)` ([`GaussianSplit::new`]) after the canal check that
/// `D ≥ 0` on `R` ([`CanalError::NoRealEnvelope`] names the interval where it fails).
///
/// # Errors
/// [`CanalError::NoRealEnvelope`], [`CanalError::DegenerateSpine`] for `D ≡ 0`,
/// [`CanalError::Factorization`].
pub fn gaussian_split(d: &Poly<Rational>) -> Result<GaussianSplit, CanalError> {
    if let Some(neg) = negative_interval(d, None)? {
        return Err(neg);
    }
    Ok(GaussianSplit::new(d)?)
}

/// `D = g₁² + g₂²`: over `Q` if possible, else over one quadratic field (the algebra
/// layer's engine, [`rcagd_algebra::sum_of_squares::sum_of_two_squares`]).
///
/// # Errors
/// As [`gaussian_split`]; [`CanalError::NeedsLargerExtension`] when one quadratic field does
/// not suffice.
pub fn sum_of_two_squares(d: &Poly<Rational>) -> Result<SumOfSquares, CanalError> {
    Ok(gaussian_split(d)?.decompose(0)?)
}

/// `D = g₁² + g₂²` in `f64`. The `f64` coefficients are exact binary rationals, so the
/// square-free decomposition `D = c·A²·S` is computed exactly (multiple roots are the
/// ill-conditioned part of root finding); the simple, non-real roots of `S` are found by
/// Durand–Kerner and the split is `g₁ + ig₂ = √c·A·∏_{Im z > 0}(t − z)`. Approximate; the
/// caller states it.
///
/// # Errors
/// [`CanalError::DegenerateSpine`] for the zero polynomial, [`CanalError::NoRealEnvelope`]
/// if `D` is negative somewhere, [`CanalError::InvalidArgument`] for non-finite
/// coefficients or roots that do not separate.
pub fn sum_of_two_squares_f64(d: &Poly<f64>) -> Result<(Poly<f64>, Poly<f64>), CanalError> {
    let dq: Poly<Rational> = Poly::new(
        d.coeffs()
            .iter()
            .map(|x| {
                Scalar::to_rational(x).ok_or_else(|| {
                    CanalError::InvalidArgument("D has a non-finite coefficient".into())
                })
            })
            .collect::<Result<Vec<_>, _>>()?,
    );
    sum_of_two_squares_approx(&dq)
}

/// `D = g₁² + g₂²` in `f64` for an exact `D`: exact square-free decomposition, numerical
/// roots of the square-free odd part only (see [`sum_of_two_squares_f64`]).
///
/// # Errors
/// As [`sum_of_two_squares_f64`].
pub fn sum_of_two_squares_approx(
    dq: &Poly<Rational>,
) -> Result<(Poly<f64>, Poly<f64>), CanalError> {
    if dq.is_zero() {
        return Err(CanalError::DegenerateSpine("D ≡ 0".into()));
    }
    if let Some(neg) = negative_interval(dq, None)? {
        return Err(neg);
    }
    let lc = Scalar::to_f64(&dq.leading());
    let mut a = Poly::constant(Rational::ONE);
    let mut s = Poly::constant(Rational::ONE);
    for (f, k) in square_free_decomposition(dq) {
        a = &a * &f.pow((k / 2) as u32);
        if k % 2 == 1 {
            s = &s * &f;
        }
    }
    let sf = s.map(Scalar::to_f64);
    let roots = durand_kerner(&sf)?;
    let scale = roots.iter().map(|z| z.norm_sq().sqrt()).fold(1.0, f64::max);
    let upper: Vec<Complex<f64>> = roots
        .iter()
        .filter(|z| z.im > 1e-12 * scale)
        .cloned()
        .collect();
    let n = s.degree().unwrap_or(0);
    if 2 * upper.len() != n {
        return Err(CanalError::InvalidArgument(
            "the roots of the square-free part of D do not separate into conjugate pairs in f64"
                .into(),
        ));
    }
    let h = upper
        .iter()
        .fold(Poly::constant(Complex::new(lc.sqrt(), 0.0)), |acc, z| {
            &acc * &Poly::new(vec![-z.clone(), Complex::new(1.0, 0.0)])
        });
    let af = a.map(|x| Complex::new(Scalar::to_f64(x), 0.0));
    Ok(re_im_polys(&(&h * &af)))
}

/// The complex roots of the square-free `p` (`rcagd_algebra::roots::complex_roots_f64`).
fn durand_kerner(p: &Poly<f64>) -> Result<Vec<Complex<f64>>, CanalError> {
    rcagd_algebra::roots::complex_roots_f64(p)
        .ok_or_else(|| CanalError::InvalidArgument("the root finder did not converge".into()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(c: &[i64]) -> Poly<Rational> {
        Poly::from_ints(c)
    }

    #[test]
    fn canal_diagnosis() {
        // negative somewhere: the canal error names the interval
        assert!(matches!(
            sum_of_two_squares(&p(&[-1, 0, 1])),
            Err(CanalError::NoRealEnvelope { .. })
        ));
        // t² + 9 over Q
        let d = p(&[9, 0, 1]);
        let s = sum_of_two_squares(&d).expect("sos");
        assert!(matches!(s, SumOfSquares::Rational { .. }) && s.verifies(&d));
        assert!(matches!(
            sum_of_two_squares(&p(&[2, 0, 0, 0, 1])),
            Err(CanalError::NeedsLargerExtension(_))
        ));
    }

    #[test]
    fn f64_path() {
        let d = Poly::new(vec![2.0, 0.0, 3.0, 0.0, 1.0]); // (t²+1)(t²+2)
        let (g1, g2) = sum_of_two_squares_f64(&d).expect("f64");
        let s = &(&g1 * &g1) + &(&g2 * &g2);
        for (a, b) in s.coeffs().iter().zip(d.coeffs()) {
            assert!((a - b).abs() < 1e-9, "{a} vs {b}");
        }
    }
}
