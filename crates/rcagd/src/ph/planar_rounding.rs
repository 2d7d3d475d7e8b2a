//! A floating-point planar PH interpolant made exact by rounding its preimage, and the
//! check of its Hermite conditions.
//!
//! A planar PH curve is determined by its complex preimage `w(t)` and its start point
//! (Farouki, *Pythagorean-Hodograph Curves*, §11.2, `r' = w²`); rounding the `f64`
//! coefficients of `w` to the rationals they are (every finite `f64` is a rational) gives an
//! exact PH curve — PH by construction — that meets the Hermite data only to the rounding
//! error, which the certificate measures (`10⁻⁹` relative, not exact).

use super::planar::PlanarPhCurve;
use super::planar_hermite::PlanarHermiteData;
use super::PhError;
use rcagd_algebra::{Certificate, Complex, Rational, Scalar};

impl PlanarPhCurve<f64> {
    /// The exact PH curve of the rounded preimage, starting at `p0` (module docs).
    ///
    /// # Errors
    /// [`PhError::NonFinite`] for a non-finite coefficient; as [`PlanarPhCurve::new`].
    pub fn rounded(&self, p0: &[Rational; 2]) -> Result<PlanarPhCurve<Rational>, PhError> {
        let rat = |x: f64| {
            Rational::try_from(x).map_err(|_| PhError::NonFinite {
                what: format!("the f64 preimage coefficient {x}"),
            })
        };
        let w = self
            .preimage_coefficients()
            .iter()
            .map(|z| Ok(Complex::new(rat(z.re)?, rat(z.im)?)))
            .collect::<Result<Vec<_>, PhError>>()?;
        PlanarPhCurve::new(w, p0.clone())
    }
}

impl<F: Scalar> PlanarPhCurve<F> {
    /// `r(0) = p0`, `r'(0) = d0`, `r(1) = p1`, `r'(1) = d1` to `10⁻⁹` times the largest datum
    /// (a tolerance check for a rounded interpolant, `exact: false`).
    pub fn rounded_hermite_certificate(&self, d: &PlanarHermiteData<F>) -> Certificate {
        let z = F::zero();
        let o = F::one();
        let pairs = [
            (self.eval(&z), &d.p0),
            (self.derivative_at(&z), &d.d0),
            (self.eval(&o), &d.p1),
            (self.derivative_at(&o), &d.d1),
        ];
        let mut res = 0.0_f64;
        let mut scale = 1.0_f64;
        for (a, b) in &pairs {
            for k in 0..2 {
                res = res.max(Scalar::to_f64(&(a[k].clone() - b[k].clone())).abs());
                scale = scale.max(Scalar::to_f64(&b[k]).abs());
            }
        }
        let tol = 1e-9 * scale;
        Certificate::decide(
            format!("Hermite conditions r(0) = p0, r'(0) = d0, r(1) = p1, r'(1) = d1 to {tol:e} (preimage rounded from f64)"),
            res <= tol,
            false,
            || format!("{res:e}"),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_keeps_the_curve() {
        let w = vec![Complex::new(1.0, 0.5), Complex::new(0.25, -1.0)];
        let c = PlanarPhCurve::new(w, [0.0, 0.0]).unwrap();
        let e = c.rounded(&[Rational::from(0), Rational::from(0)]).unwrap();
        let (z, o) = (Rational::from(0), Rational::from(1));
        let d = PlanarHermiteData {
            p0: e.eval(&z),
            d0: e.derivative_at(&z),
            p1: e.eval(&o),
            d1: e.derivative_at(&o),
        };
        assert!(e.rounded_hermite_certificate(&d).holds);
        let p1 = c.eval(&1.0);
        let e1 = e.eval(&o);
        for k in 0..2 {
            assert!((p1[k] - Scalar::to_f64(&e1[k])).abs() <= 1e-12);
        }
    }
}
