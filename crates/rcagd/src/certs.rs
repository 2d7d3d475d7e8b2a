//! Certificate helpers shared by the constructions.
//!
//! The polynomial identities (a curve or patch on a quadric, a point interpolated)
//! are decided by `rcagd_geom::certify` (exact Bernstein coefficients, never
//! sampling); this module gives them the constructions' readable property names and
//! adds the join certificates of piecewise curves (C0, G1). For `f64` the checks use
//! the relative tolerance `1e-9`.

use crate::error::{format_point, format_scalar, ConstructionError};
use rcagd_algebra::{Certificate, Scalar};
use rcagd_geom::certify;
use rcagd_geom::{BezierCurve, BezierPatch};

/// Relative tolerance of the `f64` checks (that of `rcagd_geom::certify`).
pub(crate) const TOL: f64 = certify::F64_RELATIVE_TOLERANCE;

/// `x == 0` exactly for exact scalars, `|x| ≤ TOL · max(scale, 1)` for `f64`.
pub(crate) fn is_negligible<F: Scalar>(x: &F, scale: f64) -> bool {
    if F::EXACT {
        x.is_zero()
    } else {
        let v = x.to_f64();
        v.is_finite() && v.abs() <= TOL * scale.max(1.0)
    }
}

/// Replaces the generic property text of a `rcagd_geom::certify` verdict by `property`
/// (verdict, exactness and residual are kept); an error becomes a failing certificate.
fn relabel<E: core::fmt::Display>(
    verdict: Result<Certificate, E>,
    property: &str,
    exact: bool,
) -> Certificate {
    match verdict {
        Ok(mut c) => {
            c.property = property.to_string();
            c
        }
        Err(e) => Certificate::fails(property, e.to_string(), exact),
    }
}

/// Decides `X(t)ᵀ Q X(t) ≡ 0` (exact Bernstein coefficients of degree `2n`).
///
/// # Errors
/// [`ConstructionError::Geom`] unless `Q` is `(d+1)×(d+1)`.
pub(crate) fn curve_on_quadric<F: Scalar>(
    curve: &BezierCurve<F>,
    q: &[Vec<F>],
    property: &str,
) -> Result<Certificate, ConstructionError> {
    let mut c = certify::curve_on_quadric(curve, q)?;
    c.property = property.to_string();
    Ok(c)
}

/// Decides `X(u,v)ᵀ Q X(u,v) ≡ 0` (exact Bernstein coefficients of bidegree `(2m, 2n)`).
///
/// # Errors
/// [`ConstructionError::Geom`] unless `Q` is `(d+1)×(d+1)`.
pub(crate) fn patch_on_quadric<F: Scalar>(
    patch: &BezierPatch<F>,
    q: &[Vec<F>],
    property: &str,
) -> Result<Certificate, ConstructionError> {
    let mut c = certify::patch_on_quadric(patch, q)?;
    c.property = property.to_string();
    Ok(c)
}

/// `h` (homogeneous, weight first) is the Euclidean point `p`: `w ≠ 0` and `hₖ = w·pₖ`.
/// Returns a description of the mismatch on failure.
pub(crate) fn homogeneous_is_point<F: Scalar>(h: &[F], p: &[F]) -> Result<(), String> {
    let Some((w, rest)) = h.split_first() else {
        return Err("empty point".into());
    };
    if rest.len() != p.len() {
        return Err(format!("dimension {} ≠ {}", rest.len(), p.len()));
    }
    if w.is_zero() {
        return Err("point at infinity (w = 0)".into());
    }
    let scale = w.to_f64().abs() * p.iter().map(|x| x.to_f64().abs()).fold(1.0, f64::max);
    for (xk, pk) in rest.iter().zip(p) {
        let r = xk.clone() - w.clone() * pk.clone();
        if !is_negligible(&r, scale) {
            let euclid: Vec<F> = rest.iter().map(|x| x.clone() / w.clone()).collect();
            return Err(format!(
                "P = {} ≠ {}",
                format_point(&euclid),
                format_point(p)
            ));
        }
    }
    Ok(())
}

/// `P(t) = point` exactly.
pub(crate) fn interpolates<F: Scalar>(
    curve: &BezierCurve<F>,
    t: &F,
    point: &[F],
    property: &str,
) -> Certificate {
    relabel(certify::interpolates(curve, t, point), property, F::EXACT)
}

/// `P(u, v) = point` exactly.
pub(crate) fn patch_interpolates<F: Scalar>(
    patch: &BezierPatch<F>,
    u: &F,
    v: &F,
    point: &[F],
    property: &str,
) -> Certificate {
    relabel(
        certify::patch_interpolates(patch, u, v, point),
        property,
        F::EXACT,
    )
}

/// The Euclidean point of a homogeneous point (`None` at infinity).
pub(crate) fn euclidean<F: Scalar>(h: &[F]) -> Option<Vec<F>> {
    let (w, rest) = h.split_first()?;
    let inv = w.inv()?;
    Some(rest.iter().map(|x| x.clone() * inv.clone()).collect())
}

/// The end of `a` equals the start of `b` (C0 join).
pub(crate) fn c0_join<F: Scalar>(
    a: &BezierCurve<F>,
    b: &BezierCurve<F>,
    label: &str,
) -> Certificate {
    let property = format!("C0 join {label}: end point = start point");
    let end = a.control_point(a.degree());
    let start = b.control_point(0);
    match euclidean(start) {
        Some(p) => match homogeneous_is_point(end, &p) {
            Ok(()) => Certificate::holds(property, F::EXACT),
            Err(r) => Certificate::fails(property, r, F::EXACT),
        },
        None => Certificate::fails(property, "start point at infinity", F::EXACT),
    }
}

/// The end tangent of `a` and the start tangent of `b` point the same way (G1 join):
/// with positive weights the end tangent direction is `pₙ − pₙ₋₁` and the start
/// tangent direction `q₁ − q₀` (Euclidean control points); they must be parallel
/// (all 2×2 minors vanish) with positive dot product.
pub(crate) fn g1_join<F: Scalar>(
    a: &BezierCurve<F>,
    b: &BezierCurve<F>,
    label: &str,
) -> Certificate {
    let property = format!("G1 join {label}: tangent directions parallel and equally oriented");
    let n = a.degree();
    if n == 0 || b.degree() == 0 {
        return Certificate::fails(property, "degree 0 curve has no tangent", F::EXACT);
    }
    let pts = (
        euclidean(a.control_point(n - 1)),
        euclidean(a.control_point(n)),
        euclidean(b.control_point(0)),
        euclidean(b.control_point(1)),
    );
    let (Some(a0), Some(a1), Some(b0), Some(b1)) = pts else {
        return Certificate::fails(property, "control point at infinity", F::EXACT);
    };
    let ta: Vec<F> = a1
        .iter()
        .zip(&a0)
        .map(|(x, y)| x.clone() - y.clone())
        .collect();
    let tb: Vec<F> = b1
        .iter()
        .zip(&b0)
        .map(|(x, y)| x.clone() - y.clone())
        .collect();
    let scale = ta
        .iter()
        .chain(&tb)
        .map(|x| x.to_f64().abs())
        .fold(0.0, f64::max);
    let scale2 = scale * scale;
    let mut dot = F::zero();
    for (x, y) in ta.iter().zip(&tb) {
        dot += x.clone() * y.clone();
    }
    for i in 0..ta.len() {
        for j in i + 1..ta.len() {
            let minor = ta[i].clone() * tb[j].clone() - ta[j].clone() * tb[i].clone();
            if !is_negligible(&minor, scale2) {
                return Certificate::fails(
                    property,
                    format!(
                        "tangents {} and {} are not parallel (minor {})",
                        format_point(&ta),
                        format_point(&tb),
                        format_scalar(&minor)
                    ),
                    F::EXACT,
                );
            }
        }
    }
    if dot > F::zero() {
        Certificate::holds(property, F::EXACT)
    } else {
        Certificate::fails(
            property,
            format!(
                "tangents {} and {} are not equally oriented",
                format_point(&ta),
                format_point(&tb)
            ),
            F::EXACT,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    fn unit_quarter() -> BezierCurve<Rational> {
        BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(1, 1), q(0, 1)],
            vec![q(1, 1), q(1, 1), q(1, 1)],
            vec![q(2, 1), q(0, 1), q(2, 1)],
        ])
        .expect("valid")
    }

    fn unit_circle_matrix() -> Vec<Vec<Rational>> {
        vec![
            vec![q(-1, 1), q(0, 1), q(0, 1)],
            vec![q(0, 1), q(1, 1), q(0, 1)],
            vec![q(0, 1), q(0, 1), q(1, 1)],
        ]
    }

    #[test]
    fn quarter_circle_is_on_the_unit_circle() {
        let c =
            curve_on_quadric(&unit_quarter(), &unit_circle_matrix(), "unit circle").expect("dims");
        assert!(c.holds && c.exact, "{c}");
        assert!(interpolates(&unit_quarter(), &q(1, 1), &[q(0, 1), q(1, 1)], "end").holds);
        assert!(!interpolates(&unit_quarter(), &q(1, 2), &[q(0, 1), q(1, 1)], "mid").holds);
    }

    #[test]
    fn perturbed_curve_fails_with_residual() {
        let bad = BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(1, 1), q(0, 1)],
            vec![q(1, 1), q(1, 1), q(1, 1)],
            vec![q(2, 1), q(0, 1), q(21, 10)],
        ])
        .expect("valid");
        let c = curve_on_quadric(&bad, &unit_circle_matrix(), "unit circle").expect("dims");
        assert!(!c.holds);
        assert!(c.residual.is_some());
        assert!(curve_on_quadric(&bad, &[vec![q(1, 1)]], "x").is_err());
    }

    #[test]
    fn joins() {
        let a = unit_quarter();
        let b = BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(0, 1), q(1, 1)],
            vec![q(1, 1), q(-1, 1), q(1, 1)],
            vec![q(2, 1), q(-2, 1), q(0, 1)],
        ])
        .expect("valid");
        assert!(c0_join(&a, &b, "0→1").holds);
        assert!(g1_join(&a, &b, "0→1").holds);
        assert!(!c0_join(&b, &a, "1→0").holds);
        assert!(!g1_join(&b, &a, "1→0").holds);
    }
}
