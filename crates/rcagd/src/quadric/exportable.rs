//! Curves and patches on a quadric made exportable: pieces with Bernstein weights of one
//! sign, each certified on the quadric.
//!
//! STEP and IGES need rational B-spline weights of one sign. A curve (patch) on a quadric
//! whose weights have mixed signs while its weight function has no zero on `[0, 1]` (e.g.
//! `k₀ = |x|² > 0` for the images on the sphere) is restricted to the `2^L` intervals
//! `[i/2^L, (i+1)/2^L]` (the `2^L × 2^L` sub-squares) for the least `L` that gives every
//! piece weights of one sign ([`rcagd_geom::weight_sign::split_curve_uniform`],
//! [`rcagd_geom::weight_sign::split_patch_uniform`]; subdivision by de Casteljau, Farin,
//! *Curves and Surfaces for CAGD*, §4.6 and §16.4, so each piece is exactly a piece of the
//! same curve). The certificates decide, exactly, that every piece lies on the quadric
//! (`Xᵀ Q X ≡ 0`) and, for curves, that consecutive pieces join (equal homogeneous end
//! points).

use super::image::{certify_curve_on_quadric, certify_patch_on_quadric};
use super::Mat4;
use rcagd_algebra::{Certificate, Scalar};
use rcagd_geom::weight_sign::{split_curve_uniform, split_patch_uniform};
use rcagd_geom::{BezierCurve, BezierPatch, GeomError};

/// The deepest bisection level for curves (patches: `min(3, this)`).
pub const MAX_SPLIT: u32 = 4;

/// The pieces of [`exportable_curve`] / [`exportable_patch`] and their certificates; one
/// piece (the input) and no certificate when no split was needed or none was found.
#[derive(Debug, Clone, PartialEq)]
pub struct Exportable<T> {
    /// The pieces, in parameter order.
    pub pieces: Vec<T>,
    /// The certificates of the split (module docs); empty without a split.
    pub certificates: Vec<Certificate>,
}

/// The curve, or its restrictions to `2^L` intervals with weights of one sign (module
/// docs), with the certificates.
///
/// # Errors
/// As [`split_curve_uniform`].
pub fn exportable_curve<F: Scalar>(
    curve: BezierCurve<F>,
    q: &Mat4<F>,
) -> Result<Exportable<BezierCurve<F>>, GeomError> {
    match split_curve_uniform(&curve, MAX_SPLIT)? {
        Some(pieces) if pieces.len() > 1 => Ok(curve_split_on_quadric(
            pieces,
            q,
            "with weights of one sign (export)",
        )),
        _ => Ok(Exportable {
            pieces: vec![curve],
            certificates: Vec::new(),
        }),
    }
}

/// As [`exportable_curve`] with the number of halvings `level` given instead of searched:
/// the `2^level` uniform pieces. For a float build, `level` is the exact build's (`log₂`
/// of its piece count; a Bernstein weight that is `0` over Q is a residue `±ε` in `f64`,
/// so the search could stop at another level), as [`exportable_patch_at`].
///
/// # Errors
/// [`GeomError::Parameter`] for `level > MAX_SPLIT`; errors of [`BezierCurve::restrict`].
pub fn exportable_curve_at<F: Scalar>(
    curve: BezierCurve<F>,
    q: &Mat4<F>,
    level: u32,
) -> Result<Exportable<BezierCurve<F>>, GeomError> {
    if level > MAX_SPLIT {
        return Err(GeomError::Parameter(format!(
            "exportable_curve_at: level {level} > {MAX_SPLIT}"
        )));
    }
    if level == 0 {
        return Ok(Exportable {
            pieces: vec![curve],
            certificates: Vec::new(),
        });
    }
    let k = 1i64 << level;
    let pieces = (0..k)
        .map(|i| curve.restrict(&F::from_ratio(i, k), &F::from_ratio(i + 1, k)))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(curve_split_on_quadric(
        pieces,
        q,
        "(the exact build's split, export)",
    ))
}

/// The pieces of a curve on the quadric `q` with the certificates that each lies on it
/// and that consecutive pieces join (exactly: equal homogeneous end points; `f64`: equal
/// to `10⁻⁹` of their size, the pieces being restricted separately).
fn curve_split_on_quadric<F: Scalar>(
    pieces: Vec<BezierCurve<F>>,
    q: &Mat4<F>,
    how: &str,
) -> Exportable<BezierCurve<F>> {
    let k = pieces.len();
    let mut certs = vec![Certificate::decide(
        format!("split into {k} pieces [i/{k}, (i+1)/{k}] {how}; every piece lies on the quadric: Xᵀ Q X ≡ 0"),
        pieces.iter().all(|p| certify_curve_on_quadric(p, q, "").holds),
        F::EXACT,
        || "a piece is off the quadric".to_string(),
    )];
    let same = |a: &[F], b: &[F]| {
        if F::EXACT {
            return a == b;
        }
        let size = a
            .iter()
            .chain(b)
            .map(|x| x.to_f64().abs())
            .fold(0.0, f64::max);
        a.iter().zip(b).all(|(x, y)| {
            (x.to_f64() - y.to_f64()).abs() <= rcagd_geom::certify::F64_RELATIVE_TOLERANCE * size
        })
    };
    let joined = pieces.windows(2).all(|w| match w {
        [a, b] => match (a.control_points().last(), b.control_points().next()) {
            (Some(x), Some(y)) => same(x, y),
            _ => true,
        },
        _ => true,
    });
    certs.push(Certificate::decide(
        if F::EXACT {
            "consecutive pieces join exactly (equal homogeneous end points)"
        } else {
            "consecutive pieces join (equal homogeneous end points to 10⁻⁹ of their size)"
        },
        joined,
        F::EXACT,
        || "two pieces do not join".to_string(),
    ));
    Exportable {
        pieces,
        certificates: certs,
    }
}

/// As [`exportable_curve`] for a patch: its restrictions to the `2^L × 2^L` sub-squares
/// (`L ≤ 3`).
///
/// # Errors
/// As [`split_patch_uniform`].
pub fn exportable_patch<F: Scalar>(
    patch: BezierPatch<F>,
    q: &Mat4<F>,
) -> Result<Exportable<BezierPatch<F>>, GeomError> {
    match split_patch_uniform(&patch, MAX_SPLIT.min(3))? {
        Some(pieces) if pieces.len() > 1 => {
            let k = (1..=8).find(|k| k * k >= pieces.len()).unwrap_or(1);
            Ok(split_on_quadric(
                pieces,
                q,
                &format!("split into {k}×{k} sub-patches with weights of one sign (export)"),
            ))
        }
        _ => Ok(Exportable {
            pieces: vec![patch],
            certificates: Vec::new(),
        }),
    }
}

/// As [`exportable_patch`] with the number of halvings `level` given instead of searched:
/// the `2^level × 2^level` uniform sub-patches. For a float build, `level` is the exact
/// build's (`log₄` of its piece count): whether a Bernstein weight is `0` or of the other
/// sign is an exact sign test, a rounding residue `±ε` in `f64`, so the search could stop
/// at another level.
///
/// # Errors
/// [`GeomError::Parameter`] for `level > 3`; errors of [`BezierPatch::restrict`].
pub fn exportable_patch_at<F: Scalar>(
    patch: BezierPatch<F>,
    q: &Mat4<F>,
    level: u32,
) -> Result<Exportable<BezierPatch<F>>, GeomError> {
    if level > 3 {
        return Err(GeomError::Parameter(format!(
            "exportable_patch_at: level {level} > 3"
        )));
    }
    if level == 0 {
        return Ok(Exportable {
            pieces: vec![patch],
            certificates: Vec::new(),
        });
    }
    let k = 1i64 << level;
    let at = |i: i64| F::from_ratio(i, k);
    let mut pieces = Vec::with_capacity((k * k) as usize);
    for i in 0..k {
        for j in 0..k {
            pieces.push(patch.restrict(&at(i), &at(i + 1), &at(j), &at(j + 1))?);
        }
    }
    Ok(split_on_quadric(
        pieces,
        q,
        &format!("split into {k}×{k} sub-patches (the exact build's split, export)"),
    ))
}

/// The sub-patches `pieces` of a patch on the quadric `q` with the certificate that each
/// lies on it (`what`: how they were split).
fn split_on_quadric<F: Scalar>(
    pieces: Vec<BezierPatch<F>>,
    q: &Mat4<F>,
    what: &str,
) -> Exportable<BezierPatch<F>> {
    let on = pieces
        .iter()
        .all(|p| certify_patch_on_quadric(p, q, "").holds);
    let cert = Certificate::decide(
        format!("{what}; every sub-patch lies on the quadric: Xᵀ Q X ≡ 0"),
        on,
        F::EXACT,
        || "a sub-patch is off the quadric".to_string(),
    );
    Exportable {
        pieces,
        certificates: vec![cert],
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    /// A curve with positive weights is returned as is, without certificates.
    #[test]
    fn positive_curve_is_kept() {
        let m: Mat4<Rational> = [
            [q(-1), q(0), q(0), q(0)],
            [q(0), q(1), q(0), q(0)],
            [q(0), q(0), q(1), q(0)],
            [q(0), q(0), q(0), q(0)],
        ];
        let c = BezierCurve::from_homogeneous(vec![
            vec![q(1), q(1), q(0), q(0)],
            vec![q(1), q(1), q(1), q(0)],
            vec![q(2), q(0), q(2), q(0)],
        ])
        .unwrap();
        let e = exportable_curve(c.clone(), &m).unwrap();
        assert_eq!(e.pieces, vec![c]);
        assert!(e.certificates.is_empty());
    }

    /// A circle arc whose middle weight is negative but whose weight function
    /// `16s² − 16s + 5` is positive on [0, 1]: split into pieces of one sign, all on the
    /// circle `x² + y² = w²`, joined.
    #[test]
    fn mixed_weights_are_split_and_certified() {
        let m: Mat4<Rational> = [
            [q(-1), q(0), q(0), q(0)],
            [q(0), q(1), q(0), q(0)],
            [q(0), q(0), q(1), q(0)],
            [q(0), q(0), q(0), q(0)],
        ];
        // (w, x, y) = ((1 + t²)… ) in Bernstein form: the circle (1 − t², 2t)/(1 + t²) on
        // t ∈ [−2, 2] reparametrized to [0, 1]: t = 4s − 2
        // w = 1 + (4s − 2)², x = 1 − (4s − 2)², y = 2(4s − 2)
        // Bernstein coefficients (degree 2): w: 5, −3, 5; x: −3, 5, −3; y: −4, 0, 4
        let c = BezierCurve::from_homogeneous(vec![
            vec![q(5), q(-3), q(-4), q(0)],
            vec![q(-3), q(5), q(0), q(0)],
            vec![q(5), q(-3), q(4), q(0)],
        ])
        .unwrap();
        let e = exportable_curve(c, &m).unwrap();
        assert!(e.pieces.len() > 1);
        assert!(
            e.certificates.iter().all(|c| c.holds && c.exact),
            "{:?}",
            e.certificates
        );
    }
}
