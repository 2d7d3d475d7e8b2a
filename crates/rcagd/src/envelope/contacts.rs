//! The two contact points of one sphere of a sphere-family envelope, certified.
//!
//! At a parameter `(s, t)` of `Ω` the sphere `Φ(s, t) = (m; r)` touches the envelope in
//! the two points of the cyclographic construction (Gruber, *Canal surfaces and
//! sphere families*, §3.1.2; [`SphereFamilyEnvelope::cyclographic_contacts`]): `Ψ(s, t)`
//! and the point `Ψ₂(s, t)` of the other sheet ([`SphereFamilyEnvelope::other_sheet_homogeneous`]).
//! The certificates decide, exactly, that each contact point lies on its sphere
//! (`|f − m|² = r²`) and that one of them is `Ψ₂(s, t)`.

use super::sphere_family::{SphereFamilyEnvelope, SphereFamilyError};
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Rational};

/// The contacts of one sphere ([`SphereFamilyEnvelope::certified_contacts`]).
#[derive(Debug, Clone, PartialEq)]
pub struct CertifiedContacts {
    /// The sphere `(m, r)` at the parameter.
    pub sphere: ([Rational; 3], Rational),
    /// The two contact points.
    pub points: [[Rational; 3]; 2],
    /// The cyclographic certificate, `|f − m|² = r²` for each point, and "one point is
    /// `Ψ₂(s, t)`", in this order.
    pub certificates: Vec<Certificate>,
}

impl SphereFamilyEnvelope<Rational> {
    /// The two contact points of the sphere at `(s, t)` with their certificates (module
    /// docs); `psi2` is [`Self::other_sheet_homogeneous`] (computed once by the caller for
    /// many parameters).
    ///
    /// # Errors
    /// As [`Self::cyclographic_contacts`].
    pub fn certified_contacts(
        &self,
        s: &Rational,
        t: &Rational,
        psi2: &[MPoly<Rational>; 4],
    ) -> Result<CertifiedContacts, SphereFamilyError> {
        let zero = Rational::from(0);
        let ((m, r), pts) = self.cyclographic_contacts(s, t)?;
        let mut certs = vec![self.cyclographic_certificate(s, t)];
        let x = [s.clone(), t.clone()];
        let v: Vec<Rational> = psi2
            .iter()
            .map(|p| p.eval(&x).unwrap_or_else(|_| zero.clone()))
            .collect();
        for (k, pt) in pts.iter().enumerate() {
            let d = (0..3).fold(zero.clone(), |acc, i| {
                let di = &pt[i] - &m[i];
                acc + &di * &di
            }) - &r * &r;
            certs.push(Certificate::decide(
                format!(
                    "contact point {} at ({s}, {t}) lies on its sphere: |f − m|² = r²",
                    k + 1
                ),
                d == zero,
                true,
                || format!("|f − m|² − r² = {d}"),
            ));
        }
        let other_is_psi2 = v[0] != zero
            && pts
                .iter()
                .any(|pt| (0..3).all(|i| pt[i] == &v[i + 1] / &v[0]));
        certs.push(Certificate::decide(
            format!("a contact point at ({s}, {t}) is the other sheet's Ψ₂(s, t)"),
            other_is_psi2,
            true,
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
