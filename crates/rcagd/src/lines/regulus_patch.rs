//! A patch of the quadric carrying a regulus: the lines of the regulus through a segment of
//! its first line.
//!
//! The regulus of three skew lines `a, b, c` consists of their common transversals
//! (Gruber, *Canal surfaces and sphere families*, §1.1; Pottmann–Wallner, *Computational
//! Line Geometry*, §1.3): the transversal through a point `P` of `a` is the line from `P`
//! to `Q = c ∩ (P ∨ b)` (the plane through `P` and `b`, met with `c`). For `P(s)` linear in
//! `s` on the segment `P₀P₁` of `a`, `Q(s)` is linear in `s` as well (join and meet are
//! bilinear), so the ruled patch with corners `P₀, Q₀, P₁, Q₁` is the bilinear patch
//! `(1 − λ)P(s) + λQ(s)` of the carrier quadric. `Q₀, Q₁` are scaled to positive weights;
//! weights of different signs mean a transversal of the segment meets `c` at infinity.

use super::plucker::Line;
use super::regulus::Regulus;
use super::LineError;
use rcagd_algebra::{format_vector, Certificate, Scalar};
use rcagd_geom::certify::patch_on_quadric;
use rcagd_geom::{BezierPatch, GeomError};
use thiserror::Error;

/// Errors of [`Regulus::segment_patch`].
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum RegulusPatchError {
    /// The join or meet is undefined (a point on `b`, a plane containing `c`).
    #[error(transparent)]
    Line(#[from] LineError),
    /// A transversal of the segment meets the third line at infinity.
    #[error("the transversals through the segment of the first line meet the third line at infinity (choose another segment on the first line)")]
    AtInfinity,
    /// The patch could not be formed.
    #[error(transparent)]
    Geom(#[from] GeomError),
}

impl<F: Scalar> Regulus<F> {
    /// The bilinear patch of the transversals through the segment `p0 p1` (homogeneous
    /// points, weight first, on the first line) between the first and the third line
    /// (module docs).
    ///
    /// # Errors
    /// [`RegulusPatchError`] as named there.
    pub fn segment_patch(
        &self,
        p0: &[F; 4],
        p1: &[F; 4],
    ) -> Result<BezierPatch<F>, RegulusPatchError> {
        let [_, b, c]: &[Line<F>; 3] = self.lines();
        let mut q = Vec::with_capacity(2);
        for p in [p0, p1] {
            let u = b.join_point(p)?;
            q.push(c.meet_plane(&u)?);
        }
        let (w0, w1) = (q[0][0].clone(), q[1][0].clone());
        if w0.is_zero() || w1.is_zero() || (w0 > F::zero()) != (w1 > F::zero()) {
            return Err(RegulusPatchError::AtInfinity);
        }
        if w0 < F::zero() {
            for x in &mut q {
                for v in x.iter_mut() {
                    *v = -v.clone();
                }
            }
        }
        let net = vec![
            vec![p0.to_vec(), q[0].to_vec()],
            vec![p1.to_vec(), q[1].to_vec()],
        ];
        Ok(BezierPatch::from_homogeneous(net)?)
    }

    /// Certificates of a [`Self::segment_patch`]: it lies on the carrier quadric
    /// ([`Self::quadric`], `Xᵀ Q X ≡ 0` exactly) and every weight is positive.
    pub fn segment_patch_certificates(&self, patch: &BezierPatch<F>) -> Vec<Certificate> {
        let mut certs = Vec::with_capacity(2);
        match self.quadric() {
            Ok(qm) => {
                let rows: Vec<Vec<F>> = qm.iter().map(|r| r.to_vec()).collect();
                match patch_on_quadric(patch, &rows) {
                    Ok(c) => certs.push(c),
                    Err(e) => certs.push(Certificate::fails(
                        "patch on the carrier quadric",
                        e.to_string(),
                        F::EXACT,
                    )),
                }
            }
            Err(e) => certs.push(Certificate::fails(
                "carrier quadric",
                e.to_string(),
                F::EXACT,
            )),
        }
        let weights = patch.weights();
        certs.push(Certificate::decide(
            "every weight > 0 (no pole on the patch)",
            weights.iter().all(|w| *w > F::zero()),
            F::EXACT,
            || format_vector(&weights),
        ));
        certs
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    /// The hyperbolic paraboloid z = xy: lines y = 0 (z = 0), y = 1 (z = x), y = 2 (z = 2x).
    #[test]
    fn paraboloid_patch_lies_on_the_quadric() {
        let l =
            |y: i64| Line::from_affine_points(&[q(0), q(y), q(0)], &[q(1), q(y), q(y)]).unwrap();
        let reg = Regulus::from_lines(&l(0), &l(1), &l(2)).unwrap();
        let p0 = [q(1), q(0), q(0), q(0)];
        let p1 = [q(1), q(1), q(0), q(0)];
        let patch = reg.segment_patch(&p0, &p1).unwrap();
        let certs = reg.segment_patch_certificates(&patch);
        assert_eq!(certs.len(), 2);
        assert!(certs.iter().all(|c| c.holds && c.exact), "{certs:?}");
    }
}
