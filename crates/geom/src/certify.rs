//! Certificates for Bézier curves and patches: defining properties decided as
//! identities of Bernstein polynomials.
//!
//! A polynomial is zero iff all its Bernstein coefficients are zero, so a property
//! `f(X(t)) ≡ 0` is decided by computing the Bernstein coefficients of `f(X(t))`
//! exactly (products of the coordinate vectors, never sampling) and testing them.
//! Over an exact scalar (`F::EXACT`) the verdict is a proof and a failure shows the
//! first non-zero coefficient as an exact fraction. Over `f64` a coefficient counts as
//! zero when `|c| ≤ 10⁻⁹ · scale`, with a scale bounding the coefficients' size from
//! the inputs; a failure reports the largest residual.

use crate::curve::BezierCurve;
use crate::error::GeomError;
use crate::patch::BezierPatch;
use crate::polymap::Bernstein2;
use rcagd_algebra::{bernstein, Certificate, Scalar};

/// Relative tolerance of `f64` certificates.
pub const F64_RELATIVE_TOLERANCE: f64 = 1e-9;

pub use rcagd_algebra::format_scalar;
use rcagd_algebra::format_vector;

/// `[[…], […]]` as text.
fn format_matrix<F: Scalar>(m: &[Vec<F>]) -> String {
    let rows: Vec<String> = m.iter().map(|r| format_vector(r)).collect();
    format!("[{}]", rows.join(", "))
}

/// The largest absolute value, as `f64` (0 for an empty slice).
pub(crate) fn max_abs<F: Scalar>(v: &[F]) -> f64 {
    v.iter().map(|x| x.abs().to_f64()).fold(0.0, f64::max)
}

/// Decides `coeffs ≡ 0` for the polynomial with these (Bernstein or power)
/// coefficients. Exact scalars: every coefficient is exactly zero; the residual names
/// the first non-zero coefficient as an exact fraction. `f64`: `max |cₖ| ≤ 10⁻⁹`
/// (absolute; see [`polynomial_is_zero_scaled`]), the residual is the largest `|cₖ|`.
pub fn polynomial_is_zero<F: Scalar>(property: &str, coeffs: &[F]) -> Certificate {
    polynomial_is_zero_scaled(property, coeffs, 1.0)
}

/// As [`polynomial_is_zero`], with the `f64` tolerance `10⁻⁹ · scale` (`scale` bounds
/// the size the coefficients would have without cancellation).
pub fn polynomial_is_zero_scaled<F: Scalar>(
    property: &str,
    coeffs: &[F],
    scale: f64,
) -> Certificate {
    if F::EXACT {
        let first = coeffs.iter().enumerate().find(|(_, c)| !c.is_zero());
        Certificate::decide(property, first.is_none(), true, || match first {
            Some((k, c)) => {
                let nonzero = coeffs.iter().filter(|c| !c.is_zero()).count();
                format!(
                    "coefficient {k} of {} is {} ({nonzero} non-zero, largest |c| ≈ {:e})",
                    coeffs.len(),
                    format_scalar(c),
                    max_abs(coeffs)
                )
            }
            None => String::new(),
        })
    } else {
        let (k, largest) = coeffs.iter().map(|c| c.abs().to_f64()).enumerate().fold(
            (0, 0.0_f64),
            |best, (k, a)| {
                if a > best.1 || a.is_nan() {
                    (k, a)
                } else {
                    best
                }
            },
        );
        let tol = F64_RELATIVE_TOLERANCE * scale.abs();
        Certificate::decide(property, largest <= tol, false, || {
            format!(
                "largest |coefficient| {largest:e} (coefficient {k} of {}) exceeds {tol:e}",
                coeffs.len()
            )
        })
    }
}

/// Certifies that the curve lies on the quadric `Xᵀ Q X = 0` (`Q` is `(d+1)×(d+1)` in
/// homogeneous coordinates, weight first): `X(t)ᵀ Q X(t) ≡ 0` as a Bernstein
/// polynomial of degree `2n` ([`BezierCurve::quadratic_form`]).
///
/// # Errors
/// [`GeomError::Dimension`] unless `Q` is `(d+1)×(d+1)`.
pub fn curve_on_quadric<F: Scalar>(
    curve: &BezierCurve<F>,
    q: &[Vec<F>],
) -> Result<Certificate, GeomError> {
    let coeffs = curve.quadratic_form(q)?;
    let property = format!(
        "X(t)ᵀ Q X(t) ≡ 0 (curve of degree {} on the quadric Q = {})",
        curve.degree(),
        format_matrix(q)
    );
    let scale = quadric_scale(q, curve.coords());
    Ok(polynomial_is_zero_scaled(&property, &coeffs, scale))
}

/// Certifies that the patch lies on the quadric `Xᵀ Q X = 0`: the tensor Bernstein
/// polynomial `X(u,v)ᵀ Q X(u,v)` of bidegree `(2m, 2n)` vanishes.
///
/// # Errors
/// [`GeomError::Dimension`] unless `Q` is `(d+1)×(d+1)`.
pub fn patch_on_quadric<F: Scalar>(
    patch: &BezierPatch<F>,
    q: &[Vec<F>],
) -> Result<Certificate, GeomError> {
    let coeffs = patch.quadratic_form(q)?;
    let (m, n) = patch.degree();
    let property = format!(
        "X(u,v)ᵀ Q X(u,v) ≡ 0 (patch of bidegree ({m}, {n}) on the quadric Q = {})",
        format_matrix(q)
    );
    let scale = quadric_scale(q, patch.coords());
    Ok(polynomial_is_zero_scaled(&property, &coeffs, scale))
}

/// `Σ|Q_ab| · max|X|²`, a bound on the Bernstein coefficients of `XᵀQX`.
fn quadric_scale<F: Scalar>(q: &[Vec<F>], coords: &[F]) -> f64 {
    let sq: f64 = q.iter().flatten().map(|x| x.abs().to_f64()).sum();
    let x = max_abs(coords);
    sq * x * x
}

/// The cross terms `PᵢQ_k − P_kQᵢ` (`i ≠ k`) against the coordinate `k` of `Q` with
/// the largest coefficient, concatenated, with the scale `max|P| · max|Q|`; `None` if
/// `P` or `Q` vanishes identically. Over the field of rational functions, `P ∥ Q` iff
/// these vanish (as `Q_k ≢ 0`).
fn cross_terms<F: Scalar>(
    p: &[Bernstein2<F>],
    q: &[Bernstein2<F>],
) -> Result<Option<(Vec<F>, f64)>, GeomError> {
    let Some((k, qmax)) = pivot(q) else {
        return Ok(None);
    };
    let Some((_, pmax)) = pivot(p) else {
        return Ok(None);
    };
    let (Some(pk), Some(qk)) = (p.get(k), q.get(k)) else {
        return Err(GeomError::Dimension("coordinate count mismatch".into()));
    };
    let mut out = Vec::new();
    for (i, (pi, qi)) in p.iter().zip(q).enumerate() {
        if i == k {
            continue;
        }
        let a = bernstein::product_tensor_scalar(&pi.coeffs, pi.degree, &qk.coeffs, qk.degree)?;
        let b = bernstein::product_tensor_scalar(&pk.coeffs, pk.degree, &qi.coeffs, qi.degree)?;
        out.extend(a.into_iter().zip(b).map(|(x, y)| x - y));
    }
    Ok(Some((out, pmax * qmax)))
}

/// The coordinate with the largest absolute coefficient and that value, `None` if all
/// coordinates vanish.
fn pivot<F: Scalar>(cols: &[Bernstein2<F>]) -> Option<(usize, f64)> {
    let mut best: Option<(usize, F)> = None;
    for (i, c) in cols.iter().enumerate() {
        for x in &c.coeffs {
            let ax = x.abs();
            let better = match &best {
                Some((_, b)) => ax > *b,
                None => true,
            };
            if !ax.is_zero() && better {
                best = Some((i, ax));
            }
        }
    }
    best.map(|(i, b)| (i, b.to_f64()))
}

fn agree<F: Scalar>(
    property: &str,
    p: &[Bernstein2<F>],
    q: &[Bernstein2<F>],
) -> Result<Certificate, GeomError> {
    match cross_terms(p, q)? {
        Some((terms, scale)) => Ok(polynomial_is_zero_scaled(property, &terms, scale)),
        None => Ok(Certificate::fails(
            property,
            "a homogeneous coordinate vector vanishes identically",
            F::EXACT,
        )),
    }
}

/// Certifies that two curves are the same rational parametrization:
/// `P(t) ∥ Q(t)` as polynomial vectors, i.e. all cross terms `PᵢQⱼ − PⱼQᵢ ≡ 0`
/// (any degrees; equal up to degree elevation, a scalar factor of the homogeneous
/// coordinates, or a common polynomial factor).
///
/// # Errors
/// [`GeomError::Dimension`] if the dimensions differ.
pub fn curves_agree<F: Scalar>(
    a: &BezierCurve<F>,
    b: &BezierCurve<F>,
) -> Result<Certificate, GeomError> {
    if a.dim() != b.dim() {
        return Err(GeomError::Dimension(format!(
            "comparing curves in dimensions {} and {}",
            a.dim(),
            b.dim()
        )));
    }
    let property = format!(
        "P(t) ∥ Q(t): curves of degree {} and {} are the same parametrization (PᵢQⱼ − PⱼQᵢ ≡ 0)",
        a.degree(),
        b.degree()
    );
    agree(&property, &a.coordinate_columns(), &b.coordinate_columns())
}

/// Certifies that two patches are the same rational parametrization,
/// `P(u,v) ∥ Q(u,v)` as polynomial vectors.
///
/// # Errors
/// [`GeomError::Dimension`] if the dimensions differ.
pub fn patches_agree<F: Scalar>(
    a: &BezierPatch<F>,
    b: &BezierPatch<F>,
) -> Result<Certificate, GeomError> {
    if a.dim() != b.dim() {
        return Err(GeomError::Dimension(format!(
            "comparing patches in dimensions {} and {}",
            a.dim(),
            b.dim()
        )));
    }
    let property = format!(
        "P(u,v) ∥ Q(u,v): patches of bidegree {:?} and {:?} are the same parametrization",
        a.degree(),
        b.degree()
    );
    agree(&property, &a.coordinate_columns(), &b.coordinate_columns())
}

/// Certifies `x(t) = point` for an exact parameter: `Xᵢ(t) − w(t)·pointᵢ = 0` for
/// `i = 1..d` with `w(t) ≠ 0`.
///
/// # Errors
/// [`GeomError::Dimension`] if `point` has not `d` coordinates.
pub fn interpolates<F: Scalar>(
    curve: &BezierCurve<F>,
    t: &F,
    point: &[F],
) -> Result<Certificate, GeomError> {
    let property = format!(
        "P({}) = {} (curve interpolates the point)",
        format_scalar(t),
        format_vector(point)
    );
    point_residual(&property, &curve.eval_homogeneous(t), point)
}

/// Certifies `x(u, v) = point` for exact parameters.
///
/// # Errors
/// [`GeomError::Dimension`] if `point` has not `d` coordinates.
pub fn patch_interpolates<F: Scalar>(
    patch: &BezierPatch<F>,
    u: &F,
    v: &F,
    point: &[F],
) -> Result<Certificate, GeomError> {
    let property = format!(
        "P({}, {}) = {} (patch interpolates the point)",
        format_scalar(u),
        format_scalar(v),
        format_vector(point)
    );
    point_residual(&property, &patch.eval_homogeneous(u, v), point)
}

fn point_residual<F: Scalar>(
    property: &str,
    h: &[F],
    point: &[F],
) -> Result<Certificate, GeomError> {
    let Some((w, x)) = h.split_first() else {
        return Err(GeomError::Empty("no homogeneous point".into()));
    };
    if x.len() != point.len() {
        return Err(GeomError::Dimension(format!(
            "point has {} coordinates, the curve or patch has dimension {}",
            point.len(),
            x.len()
        )));
    }
    if w.is_zero() {
        return Ok(Certificate::fails(
            property,
            "the weight vanishes there (point at infinity)",
            F::EXACT,
        ));
    }
    let residual: Vec<F> = x
        .iter()
        .zip(point)
        .map(|(xi, pi)| xi.clone() - w.clone() * pi.clone())
        .collect();
    let scale = max_abs(x).max(w.abs().to_f64() * max_abs(point));
    Ok(polynomial_is_zero_scaled(property, &residual, scale))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn pt(v: &[i64]) -> Vec<Rational> {
        v.iter().map(|&x| Rational::from(x)).collect()
    }

    fn circle_q() -> Vec<Vec<Rational>> {
        vec![pt(&[-1, 0, 0]), pt(&[0, 1, 0]), pt(&[0, 0, 1])]
    }

    fn quarter_circle() -> BezierCurve<Rational> {
        BezierCurve::from_homogeneous(vec![pt(&[1, 1, 0]), pt(&[1, 1, 1]), pt(&[2, 0, 2])])
            .expect("valid")
    }

    #[test]
    fn circle_on_quadric_exact_and_f64() {
        let c = quarter_circle();
        let cert = curve_on_quadric(&c, &circle_q()).expect("3×3");
        assert!(cert.holds && cert.exact, "{cert}");
        let f = curve_on_quadric(
            &c.to_f64(),
            &[
                vec![-1.0, 0.0, 0.0],
                vec![0.0, 1.0, 0.0],
                vec![0.0, 0.0, 1.0],
            ],
        )
        .expect("3×3");
        assert!(f.holds && !f.exact);
        // Perturb the middle weight: no longer a circle.
        let bad =
            BezierCurve::from_homogeneous(vec![pt(&[1, 1, 0]), pt(&[2, 2, 2]), pt(&[2, 0, 2])])
                .expect("valid");
        let cert = curve_on_quadric(&bad, &circle_q()).expect("3×3");
        assert!(!cert.holds);
        assert!(
            cert.residual
                .as_deref()
                .is_some_and(|r| r.contains("coefficient")),
            "{cert}"
        );
        assert!(curve_on_quadric(&c, &circle_q()[..2]).is_err());
    }

    #[test]
    fn polynomial_is_zero_reports_exact_residual() {
        let c = polynomial_is_zero("p ≡ 0", &[Rational::from(0), Rational::from_ratio(3, 7)]);
        assert!(!c.holds);
        assert!(
            c.residual.as_deref().is_some_and(|r| r.contains("3/7")),
            "{c}"
        );
        assert!(polynomial_is_zero::<Rational>("p ≡ 0", &[]).holds);
        let f = polynomial_is_zero("p ≡ 0", &[1e-12, -2e-12]);
        assert!(f.holds);
        let f = polynomial_is_zero("p ≡ 0", &[1e-3]);
        assert!(!f.holds);
        assert!(!polynomial_is_zero("p ≡ 0", &[f64::NAN]).holds);
    }

    #[test]
    fn interpolation_and_agreement() {
        let c = quarter_circle();
        let third = Rational::from_ratio(1, 3);
        let p = vec![Rational::from_ratio(4, 5), Rational::from_ratio(3, 5)];
        assert!(interpolates(&c, &third, &p).expect("2D").holds);
        let wrong = vec![Rational::from_ratio(4, 5), Rational::from_ratio(2, 5)];
        assert!(!interpolates(&c, &third, &wrong).expect("2D").holds);
        assert!(interpolates(&c, &third, &p[..1]).is_err());
        assert!(curves_agree(&c, &c.elevate(3)).expect("same dim").holds);
        assert!(!curves_agree(&c, &c.reverse()).expect("same dim").holds);
        let zero = BezierCurve::from_homogeneous(vec![pt(&[0, 0, 0])]).expect("valid");
        assert!(!curves_agree(&c, &zero).expect("same dim").holds);
        let c3 = BezierCurve::from_homogeneous(vec![pt(&[1, 0, 0, 0])]).expect("valid");
        assert!(curves_agree(&c, &c3).is_err());
    }

    #[test]
    fn formats_numbers() {
        assert_eq!(format_scalar(&Rational::from_ratio(-3, 6)), "-1/2");
        assert_eq!(format_scalar(&0.5), "0.5");
    }
}
