//! Typed errors of the constructions.
//!
//! Every variant names the violated precondition, and where a precondition is an
//! equation (a point on a circle) it carries the residual, formatted exactly
//! (`"p/q"`) for exact scalars and as a decimal for `f64`.

use rcagd_algebra::{AlgebraError, Scalar};
use rcagd_geom::GeomError;
use thiserror::Error;

/// Errors raised by the constructions of `rcagd`. Every variant names the violated
/// precondition.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum ConstructionError {
    /// A point that must lie on a circle does not: `residual = |p − c|² − r²`
    /// (exactly zero is required for exact scalars).
    #[error("point `{point}` = {coords} is not on the circle: |p − c|² − r² = {residual}")]
    PointNotOnCircle {
        /// Which input point (`"from"`, `"to"`, …).
        point: String,
        /// The point, formatted.
        coords: String,
        /// The residual `|p − c|² − r²`, formatted.
        residual: String,
    },
    /// Two points that must differ coincide (e.g. the end points of an arc).
    #[error("coincident points: {0}")]
    CoincidentPoints(String),
    /// A radius that must be positive is zero or negative.
    #[error("the radius must be positive, got {radius}")]
    NonPositiveRadius {
        /// The radius, formatted.
        radius: String,
    },
    /// An interval `[a, b]` that must satisfy `a < b` does not.
    #[error("empty interval: {name} needs {lower} < {upper}")]
    EmptyInterval {
        /// What the interval is (`"heights z0 < z1"`).
        name: String,
        /// The lower end, formatted.
        lower: String,
        /// The upper end, formatted.
        upper: String,
    },
    /// A single rational quadratic arc must turn by less than 180°.
    #[error("a single rational quadratic arc must span less than 180°: {0} (split it, e.g. with circle_arcs)")]
    ArcTooLarge(String),
    /// An input number is NaN or infinite (only possible for `f64`).
    #[error("input `{0}` is not a finite number")]
    NotFinite(String),
    /// Any other invalid argument; the message names the precondition.
    #[error("invalid argument: {0}")]
    InvalidArgument(String),
    /// A failure of the geometry layer.
    #[error(transparent)]
    Geom(#[from] GeomError),
    /// A failure of the algebra layer.
    #[error(transparent)]
    Algebra(#[from] AlgebraError),
}

pub use rcagd_algebra::format_scalar;
/// Formats a point `(x, y, …)` with [`format_scalar`].
pub use rcagd_algebra::format_vector as format_point;

/// Fails with [`ConstructionError::NotFinite`] if an `f64` input is NaN or infinite
/// (exact scalars are always finite).
pub(crate) fn check_finite<F: Scalar>(name: &str, xs: &[&F]) -> Result<(), ConstructionError> {
    if !F::EXACT && xs.iter().any(|x| !x.to_f64().is_finite()) {
        return Err(ConstructionError::NotFinite(name.to_string()));
    }
    Ok(())
}

/// Fails with [`ConstructionError::NonPositiveRadius`] unless `r > 0`.
pub(crate) fn check_radius<F: Scalar>(r: &F) -> Result<(), ConstructionError> {
    check_finite("radius", &[r])?;
    if *r > F::zero() {
        Ok(())
    } else {
        Err(ConstructionError::NonPositiveRadius {
            radius: format_scalar(r),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    #[test]
    fn formats_exact_and_float() {
        assert_eq!(format_scalar(&Rational::from_ratio(-3, 6)), "-1/2");
        assert_eq!(format_scalar(&0.25f64), "0.25");
        assert_eq!(
            format_point(&[Rational::from(1), Rational::from_ratio(2, 3)]),
            "(1, 2/3)"
        );
    }

    #[test]
    fn radius_checks() {
        assert!(check_radius(&Rational::from(1)).is_ok());
        assert!(matches!(
            check_radius(&Rational::from(0)),
            Err(ConstructionError::NonPositiveRadius { .. })
        ));
        assert!(matches!(
            check_radius(&f64::NAN),
            Err(ConstructionError::NotFinite(_))
        ));
        assert!(matches!(
            check_radius(&-1.0f64),
            Err(ConstructionError::NonPositiveRadius { .. })
        ));
    }
}
