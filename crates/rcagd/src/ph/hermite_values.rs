//! The values of the planar PH quintic Hermite problem (Farouki–Neff 1995, "Hermite
//! interpolation by Pythagorean hodograph quintics"; Farouki 2008 §25.1): for each of the
//! four interpolants the elimination polynomial of the middle preimage coefficient,
//!
//! `2w₁² + 3(w₀ + w₂)w₁ + (3w₀² + w₀w₂ + 3w₂² − 15Δp) = 0`,
//!
//! (the end condition `∫₀¹ w² = Δp` with `w₀² = d₀`, `w₂² = d₁`), its discriminant
//! `120Δp − 15(d₀ + d₁) + 10w₀w₂` (the radicand of [`super::planar_hermite`]), the
//! solution `w = (w₀, w₁, w₂)`, arc length, absolute rotation index and bending energy.

use super::planar::C;
use super::planar_hermite::PlanarHermiteSolution;
use rcagd_algebra::{Certificate, Scalar};

/// One interpolant of the planar Hermite problem with its algebraic data.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanarHermiteBranch<F> {
    /// `(sign of w₂ = ±√d₁, sign of the outer root)`.
    pub signs: (i8, i8),
    /// `(w₀, w₁, w₂)`.
    pub w: [C<F>; 3],
    /// The coefficients `[c₀, c₁, c₂]` of `c₂w₁² + c₁w₁ + c₀ = 0`: `c₂ = 2`,
    /// `c₁ = 3(w₀ + w₂)`, `c₀ = 3w₀² + w₀w₂ + 3w₂² − 15Δp`.
    pub quadratic: [C<F>; 3],
    /// `c₁² − 4c₂c₀ = 120Δp − 15(d₀ + d₁) + 10w₀w₂`.
    pub discriminant: C<F>,
    /// Arc length `∫₀¹ |w|²`.
    pub arc_length: F,
    /// Absolute rotation index `(1/2π)∫|κ| ds` (a quadrature).
    pub absolute_rotation_index: f64,
    /// Bending energy `∫κ² ds` (a quadrature).
    pub bending_energy: f64,
    /// The "good" interpolant.
    pub best: bool,
}

/// The branches of a solved planar Hermite problem.
pub fn planar_hermite_branches<F: Scalar>(
    s: &PlanarHermiteSolution<F>,
) -> Vec<PlanarHermiteBranch<F>> {
    let d = &s.data;
    let dp = C::new(
        d.p1[0].clone() - d.p0[0].clone(),
        d.p1[1].clone() - d.p0[1].clone(),
    );
    let k = |n: i64| C::from_real(F::from_i64(n));
    s.interpolants
        .iter()
        .map(|c| {
            let w = c.curve.preimage_coefficients();
            let w: [C<F>; 3] = [w[0].clone(), w[1].clone(), w[2].clone()];
            let [w0, _, w2] = w.clone();
            let quadratic = [
                k(3) * w0.clone() * w0.clone()
                    + w0.clone() * w2.clone()
                    + k(3) * w2.clone() * w2.clone()
                    - k(15) * dp.clone(),
                k(3) * (w0.clone() + w2.clone()),
                k(2),
            ];
            let d0 = C::new(d.d0[0].clone(), d.d0[1].clone());
            let d1 = C::new(d.d1[0].clone(), d.d1[1].clone());
            let discriminant = k(120) * dp.clone() - k(15) * (d0 + d1) + k(10) * w0 * w2;
            PlanarHermiteBranch {
                signs: (c.end_sign, c.root_sign),
                w,
                quadratic,
                discriminant,
                arc_length: c.curve.arc_length(),
                absolute_rotation_index: c.absolute_rotation_index,
                bending_energy: c.bending_energy,
                best: c.best,
            }
        })
        .collect()
}

impl<F: Scalar> PlanarHermiteBranch<F> {
    /// `w₁` solves its quadratic, whose discriminant is `120Δp − 15(d₀ + d₁) + 10w₀w₂`
    /// (exact for exact scalars).
    pub fn certify(&self) -> Vec<Certificate> {
        let [c0, c1, c2] = self.quadratic.clone();
        let w1 = self.w[1].clone();
        let r = c2.clone() * w1.clone() * w1.clone() + c1.clone() * w1 + c0.clone();
        let scale = [&c0, &c1, &c2]
            .iter()
            .map(|c| c.re.to_f64().abs() + c.im.to_f64().abs())
            .fold(1.0, f64::max);
        let zero = |z: &C<F>, s: f64| {
            crate::certs::is_negligible(&z.re, s) && crate::certs::is_negligible(&z.im, s)
        };
        let disc =
            c1.clone() * c1 - C::from_real(F::from_i64(4)) * c2 * c0 - self.discriminant.clone();
        vec![
            Certificate::decide(
                format!(
                    "interpolant {:?}: 2w₁² + 3(w₀ + w₂)w₁ + 3w₀² + w₀w₂ + 3w₂² − 15Δp = 0",
                    self.signs
                ),
                zero(&r, scale * scale),
                F::EXACT,
                || {
                    format!(
                        "residual {} + {}i",
                        crate::error::format_scalar(&r.re),
                        crate::error::format_scalar(&r.im)
                    )
                },
            ),
            Certificate::decide(
                format!(
                    "interpolant {:?}: its discriminant is 120Δp − 15(d₀ + d₁) + 10w₀w₂",
                    self.signs
                ),
                zero(&disc, scale * scale),
                F::EXACT,
                || "the discriminant differs".into(),
            ),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ph::PlanarHermiteData;
    use rcagd_algebra::Rational;

    fn q(n: i64, d: i64) -> Rational {
        Rational::from_ratio(n, d)
    }

    /// Farouki–Neff data with rational roots: for w₂ = 1 + i the discriminant is
    /// 11 + 60i = (6 + 5i)² (hand computation), and every branch is certified; the `f64`
    /// solution gives the same discriminants.
    #[test]
    fn branches_of_an_exact_problem() {
        let data = PlanarHermiteData::new(
            [q(0, 1), q(0, 1)],
            [q(1, 1), q(0, 1)],
            [q(2, 15), q(2, 3)],
            [q(0, 1), q(2, 1)],
        );
        let s = data.solve().expect("exact");
        let b = planar_hermite_branches(&s);
        assert_eq!(b.len(), 4);
        assert_eq!(b[0].discriminant, C::new(q(11, 1), q(60, 1)));
        for x in &b {
            for c in x.certify() {
                assert!(c.holds && c.exact, "{c}");
            }
        }
        let f = PlanarHermiteData::new([0.0, 0.0], [1.0, 0.0], [2.0 / 15.0, 2.0 / 3.0], [0.0, 2.0])
            .solve()
            .expect("f64");
        let bf = planar_hermite_branches(&f);
        for (x, y) in b.iter().zip(&bf) {
            for c in y.certify() {
                assert!(c.holds, "{c}");
            }
            assert!((Scalar::to_f64(&x.discriminant.re) - y.discriminant.re).abs() < 1e-9);
            assert!((Scalar::to_f64(&x.discriminant.im) - y.discriminant.im).abs() < 1e-9);
        }
    }
}
