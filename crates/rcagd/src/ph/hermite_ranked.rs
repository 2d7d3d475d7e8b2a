//! The interpolants of the spatial PH quintic Hermite problem ranked by bending energy,
//! each with the control points to write and its certificates.
//!
//! [`HermiteSolution::interpolants`] are the helical quintics of Besednjak §9 (the real
//! roots of the elimination quartic, two interpolants per admissible root). Each is enclosed
//! from the exact root ([`HermiteSolution::enclose`]: control points and the bending energy
//! `E = ∫κ²σ dt`, Besednjak (9.29), in interval arithmetic). The ranking is by increasing
//! energy (the enclosure's midpoint, or the `f64` quadrature where `σ` cannot be proven
//! positive). The control points written are the exact ones (rational root and square
//! roots), else the midpoints of the enclosures, else the `f64` solution. The certificates
//! decide the Hermite end conditions `r(0) = p_s`, `r(1) = p_f`, `r'(0) = 5(p₁ − p₀) = d_s`,
//! `r'(1) = 5(p₅ − p₄) = d_f` on the written points (exactly when they are exact, else to
//! `10⁻⁹` relative), repeat the `f64` quaternion form's PH and helix certificates and the
//! enclosure's, and check that the interpolant flagged least-energy is the first.

use super::hermite::{HermiteData, HermiteSolution};
use super::hermite_enclosure::EnclosedInterpolant;
use super::PhError;
use rcagd_algebra::{Certificate, QuadExt, Rational, Scalar};

/// One interpolant of [`HermiteSolution::ranked_interpolants`].
#[derive(Debug, Clone)]
pub struct RankedInterpolant {
    /// Index into [`HermiteSolution::interpolants`].
    pub index: usize,
    /// Rank by increasing bending energy, `1` = least.
    pub rank: usize,
    /// The control points written (module docs).
    pub control_points: Vec<Vec<Rational>>,
    /// The control points are exact.
    pub exact: bool,
    /// The enclosure from the exact root, or why there is none.
    pub enclosure: Result<EnclosedInterpolant, PhError>,
    /// The bending energy used for the ranking.
    pub energy: f64,
    /// The certificates (module docs).
    pub certificates: Vec<Certificate>,
}

fn to_q(x: f64) -> Result<Rational, PhError> {
    Rational::try_from(x).map_err(|_| PhError::NonFinite {
        what: format!("the value {x} of an f64 interpolant (from the Hermite data)"),
    })
}

fn prefixed(prefix: &str, certs: Vec<Certificate>) -> impl Iterator<Item = Certificate> + '_ {
    certs.into_iter().map(move |mut c| {
        c.property = format!("{prefix}{}", c.property);
        c
    })
}

impl HermiteSolution<QuadExt> {
    /// Every interpolant, enclosed to `point_tolerance` (control points) and
    /// `energy_tolerance` (relative, energy), ranked by increasing bending energy, with its
    /// written control points and certificates (module docs); `data` is the rational
    /// Hermite data the solution was computed from.
    ///
    /// # Errors
    /// [`PhError::OutOfRange`] if an `f64` control point is not finite;
    /// [`PhError::Degenerate`] for an interpolant without control points.
    pub fn ranked_interpolants(
        &self,
        data: &HermiteData<Rational>,
        point_tolerance: &Rational,
        energy_tolerance: &Rational,
    ) -> Result<Vec<RankedInterpolant>, PhError> {
        let mut encs: Vec<Option<Result<EnclosedInterpolant, PhError>>> =
            (0..self.interpolants.len())
                .map(|i| Some(self.enclose(i, point_tolerance, energy_tolerance)))
                .collect();
        let energy = |i: usize, encs: &[Option<Result<EnclosedInterpolant, PhError>>]| match encs
            .get(i)
            .and_then(Option::as_ref)
        {
            Some(Ok(e)) => e.bending_energy.to_f64(),
            _ => self
                .interpolants
                .get(i)
                .map_or(f64::NAN, |s| s.bending_energy),
        };
        let mut order: Vec<usize> = (0..self.interpolants.len()).collect();
        order.sort_by(|a, b| energy(*a, &encs).total_cmp(&energy(*b, &encs)));
        let count = order.len();
        let energies: Vec<f64> = order.iter().map(|i| energy(*i, &encs)).collect();
        let mut out = Vec::with_capacity(count);
        for (k, idx) in order.into_iter().enumerate() {
            let e_idx = energy(idx, &encs);
            let (Some(s), Some(enc)) = (
                self.interpolants.get(idx),
                encs.get_mut(idx).and_then(Option::take),
            ) else {
                return Err(PhError::Degenerate(
                    "internal error: an interpolant index out of range".into(),
                ));
            };
            let exact = s.exact_control_points.is_some();
            let pts: Vec<Vec<Rational>> = match (&s.exact_control_points, &enc) {
                (Some(p), _) => p.iter().map(|v| v.to_vec()).collect(),
                (None, Ok(e)) => e
                    .control_points_f64()
                    .iter()
                    .map(|v| v.iter().map(|x| to_q(*x)).collect::<Result<Vec<_>, _>>())
                    .collect::<Result<Vec<_>, _>>()?,
                (None, Err(_)) => s
                    .curve
                    .control_points()
                    .iter()
                    .map(|v| v.iter().map(|x| to_q(*x)).collect::<Result<Vec<_>, _>>())
                    .collect::<Result<Vec<_>, _>>()?,
            };
            let mut certs = Vec::new();
            let last = pts.len().saturating_sub(1);
            let (Some(p0), Some(p1), Some(p4), Some(p5)) = (
                pts.first(),
                pts.get(1),
                pts.get(last.saturating_sub(1)),
                pts.get(last),
            ) else {
                return Err(PhError::Degenerate(
                    "internal error: an interpolant without control points".into(),
                ));
            };
            let five = Rational::from(5);
            let close = |a: &[Rational], b: &[Rational]| -> (bool, f64) {
                let d = a
                    .iter()
                    .zip(b)
                    .map(|(x, y)| Scalar::to_f64(&(x - y).abs()))
                    .fold(0.0, f64::max);
                let scale = 1.0
                    + b.iter()
                        .map(|x| Scalar::to_f64(&x.abs()))
                        .fold(0.0, f64::max);
                (if exact { d == 0.0 } else { d <= 1e-9 * scale }, d)
            };
            let ds: Vec<Rational> = p1.iter().zip(p0).map(|(a, b)| (a - b) * &five).collect();
            let df: Vec<Rational> = p5.iter().zip(p4).map(|(a, b)| (a - b) * &five).collect();
            for (prop, a, b) in [
                ("r(0) = p_s", p0.as_slice(), data.p_s.as_slice()),
                ("r(1) = p_f", p5.as_slice(), data.p_f.as_slice()),
                (
                    "r'(0) = 5(p_1 − p_0) = d_s",
                    ds.as_slice(),
                    data.d_s.as_slice(),
                ),
                (
                    "r'(1) = 5(p_5 − p_4) = d_f",
                    df.as_slice(),
                    data.d_f.as_slice(),
                ),
            ] {
                let (ok, d) = close(a, b);
                certs.push(Certificate::decide(prop, ok, exact, || {
                    format!("max deviation {d:e}")
                }));
            }
            certs.extend(prefixed("f64 quaternion form: ", s.curve.certify()));
            certs.extend(prefixed(
                "f64 quaternion form: ",
                s.curve.to_poly_curve().certify_helix_test(&s.helix),
            ));
            if let Ok(e) = &enc {
                certs.extend(e.certify());
            }
            let least = energies.iter().all(|x| e_idx <= *x * (1.0 + 1e-9));
            certs.push(Certificate::decide(
                format!(
                    "bending energy E = ∫κ²σ dt = {e_idx:.9} (rank {} of {count}; k0 = {:.7}, k2 = {:.7}, φ = {:.7}){}",
                    k + 1,
                    s.k0,
                    s.k2,
                    s.phi,
                    if s.least_energy { ": the least of all interpolants" } else { "" }
                ),
                e_idx.is_finite() && (least == s.least_energy),
                false,
                || format!("energies of all interpolants: {energies:?}"),
            ));
            out.push(RankedInterpolant {
                index: idx,
                rank: k + 1,
                control_points: pts,
                exact,
                enclosure: enc,
                energy: e_idx,
                certificates: certs,
            });
        }
        Ok(out)
    }
}
