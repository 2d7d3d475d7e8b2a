//! The two contact points of one sphere of a sphere-family envelope, certified.
//!
//! At a parameter `(s, t)` of `Ω` the sphere `Φ(s, t) = (m; r)` touches the envelope in
//! the two points of the cyclographic construction (Gruber, *Canal surfaces and
//! sphere families*, §3.1.2; [`SphereFamilyEnvelope::cyclographic_contacts`]): `Ψ(s, t)`
//! and the point `Ψ₂(s, t)` of the other sheet ([`SphereFamilyEnvelope::other_sheet_homogeneous`]).
//! The certificates decide, exactly for exact scalars (by a tolerance scaled by the terms
//! for an inexact one), that each contact point lies on its sphere (`|f − m|² = r²`) and
//! that one of them is `Ψ₂(s, t)`.

use super::sphere_family::{SphereFamilyEnvelope, SphereFamilyError};
use crate::error::format_scalar;
use crate::lines::SqrtScalar;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Rational};

/// The contacts of one sphere ([`SphereFamilyEnvelope::certified_contacts`]).
#[derive(Debug, Clone, PartialEq)]
pub struct CertifiedContacts<F = Rational> {
    /// The sphere `(m, r)` at the parameter.
    pub sphere: ([F; 3], F),
    /// The two contact points.
    pub points: [[F; 3]; 2],
    /// The cyclographic certificate, `|f − m|² = r²` for each point, and "one point is
    /// `Ψ₂(s, t)`", in this order.
    pub certificates: Vec<Certificate>,
}

impl<F: SqrtScalar> SphereFamilyEnvelope<F> {
    /// The two contact points of the sphere at `(s, t)` with their certificates (module
    /// docs); `psi2` is [`Self::other_sheet_homogeneous`] (computed once by the caller for
    /// many parameters). Exact scalars decide the identities exactly; an inexact scalar
    /// compares `|f − m|² − r²` with `10⁻⁹` of the size of the terms that cancel,
    /// `1 + Σ(|fᵢ| + |mᵢ|)² + r²`, and `W·fᵢ − Xᵢ` (`Ψ₂ = (W, X₁, X₂, X₃)`) with `10⁻⁹` of
    /// `|W||fᵢ| + |Xᵢ|` (at least 1).
    ///
    /// # Errors
    /// As [`Self::cyclographic_contacts`].
    pub fn certified_contacts(
        &self,
        s: &F,
        t: &F,
        psi2: &[MPoly<F>; 4],
    ) -> Result<CertifiedContacts<F>, SphereFamilyError> {
        let zero = F::zero();
        let ((m, r), pts) = self.cyclographic_contacts(s, t)?;
        let mut certs = vec![self.cyclographic_certificate(s, t)];
        let x = [s.clone(), t.clone()];
        let v: Vec<F> = psi2
            .iter()
            .map(|p| p.eval(&x).unwrap_or_else(|_| zero.clone()))
            .collect();
        let (ss, ts) = (format_scalar(s), format_scalar(t));
        let mag = |a: &F| a.to_f64().abs();
        for (k, pt) in pts.iter().enumerate() {
            let d = (0..3).fold(zero.clone(), |acc, i| {
                let di = pt[i].clone() - m[i].clone();
                acc + di.clone() * di
            }) - r.clone() * r.clone();
            let ok = if F::EXACT {
                d.is_zero()
            } else {
                let scale = 1.0
                    + (0..3)
                        .map(|i| (mag(&pt[i]) + mag(&m[i])).powi(2))
                        .sum::<f64>()
                    + mag(&r) * mag(&r);
                mag(&d) <= 1e-9 * scale
            };
            certs.push(Certificate::decide(
                format!(
                    "contact point {} at ({ss}, {ts}) lies on its sphere: |f − m|² = r²",
                    k + 1
                ),
                ok,
                F::EXACT,
                || format!("|f − m|² − r² = {}", format_scalar(&d)),
            ));
        }
        let is_psi2 = |pt: &[F; 3]| {
            (0..3).all(|i| {
                let d = v[0].clone() * pt[i].clone() - v[i + 1].clone();
                if F::EXACT {
                    d.is_zero()
                } else {
                    mag(&d) <= 1e-9 * (mag(&v[0]) * mag(&pt[i]) + mag(&v[i + 1])).max(1.0)
                }
            })
        };
        let other_is_psi2 = !v[0].is_zero() && pts.iter().any(is_psi2);
        certs.push(Certificate::decide(
            format!("a contact point at ({ss}, {ts}) is the other sheet's Ψ₂(s, t)"),
            other_is_psi2,
            F::EXACT,
            || "neither contact point is Ψ₂(s, t)".into(),
        ));
        Ok(CertifiedContacts {
            sphere: (m, r),
            points: pts,
            certificates: certs,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lines::NetKind;

    fn q(a: i64, b: i64) -> Rational {
        Rational::from(a) / Rational::from(b)
    }

    /// Gruber §3.3.4 (polar axes), the gallery example `sphere_family_cyclographic_polar`.
    #[test]
    fn polar_axes_contacts_are_certified() {
        let i = |n: i64| Rational::from(n);
        let points = vec![
            vec![i(1), i(0), i(0), i(0)],
            vec![i(0), i(0), i(0), i(-1)],
            vec![i(0), i(1), i(0), i(0)],
            vec![i(0), i(0), i(1), i(0)],
        ];
        let a = vec![vec![i(0)], vec![i(0)], vec![i(1)]];
        let b = vec![vec![i(0), i(0), i(1)]];
        let env = SphereFamilyEnvelope::<Rational>::from_data(
            NetKind::Hyperbolic,
            &points,
            &a,
            None,
            Some(&b),
            [None, None],
        )
        .expect("envelope");
        let psi2 = env.other_sheet_homogeneous();
        for (s, t) in [(q(1, 2), q(1, 2)), (q(3, 4), q(1, 3))] {
            let c = env.certified_contacts(&s, &t, &psi2).expect("contacts");
            assert_eq!(c.certificates.len(), 4);
            assert!(
                c.certificates.iter().all(|x| x.holds && x.exact),
                "{:?}",
                c.certificates
            );
            let (m, r) = &c.sphere;
            for p in &c.points {
                let d = (0..3).fold(Rational::from(0), |acc, k| {
                    acc + (&p[k] - &m[k]) * (&p[k] - &m[k])
                });
                assert_eq!(d, r * r);
            }
        }
    }
}
