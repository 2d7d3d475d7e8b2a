//! General spatial PH quintic C1 Hermite interpolation (Farouki–al-Kandari–Sakkalis
//! 2002, "Hermite interpolation by rotation-invariant spatial Pythagorean-hodograph
//! curves"; Farouki 2008 §25.2; issue 5 part B).
//!
//! With the quaternion preimage `A(t) = A_0 b_0² + A_1 b_1² + A_2 b_2²` and
//! `r' = A i A*` ([`PhCurve`]), the data `r(0) = p_0`, `r'(0) = d_0`, `r(1) = p_1`,
//! `r'(1) = d_1` require `A_0 i A_0* = d_0`, `A_2 i A_2* = d_1` and (the quaternion form of
//! the planar equation, completed to a square; checked with sympy on the planar case)
//!
//! `(4A_1 + 3(A_0 + A_2)) i (4A_1 + 3(A_0 + A_2))* = 120Δp − 15(d_0 + d_1) + 5X`,
//! `X = A_0 i A_2* + A_2 i A_0*`.
//!
//! Every equation `Q i Q* = c` has the one-parameter family of solutions
//! `Q = Q̂(c) e^{iφ}` ([`solve_qiq`]); as `A ↦ A e^{iθ}` does not change `r'`, the
//! interpolants form a two-parameter family: `A_0 = Q̂(d_0)e^{iφ_0}`,
//! `A_2 = Q̂(d_1)e^{iφ_2}`, `A_1 = (Q̂(c) − 3(A_0 + A_2))/4` (the middle angle fixed to
//! `φ_1 = 0`). The free angles are given as unit complex numbers `(cos φ, sin φ)` so that
//! rational rotations (e.g. `φ = −π/2 ↦ (0, −1)`, or any `((1−τ²)/(1+τ²), 2τ/(1+τ²))`)
//! keep exact data exact; the construction is exact whenever the three square roots of
//! [`solve_qiq`] are rational, otherwise it runs in `f64` and certifies the interpolation
//! to a tolerance, reporting the residual. The default ([`SpatialHermiteData::default_f64`])
//! starts from the least bending energy interpolant among `φ_0, φ_2 ∈ {−π/2, 0, π/2, π}`
//! (which includes the customary `φ_0 = φ_2 = −π/2`) and refines both angles by a cyclic
//! golden-section search (a local minimum of the bending energy).

use super::hodograph::{solve_qiq, PhCurve};
use super::planar::{gauss7, scalar_cert};
use super::util::aib;
use super::PhError;
use rcagd_algebra::{Certificate, Poly, Quaternion, Rational, Scalar};

/// Spatial C1 Hermite data.
#[derive(Debug, Clone, PartialEq)]
pub struct SpatialHermiteData<F> {
    /// `r(0)`.
    pub p0: [F; 3],
    /// `r'(0)`.
    pub d0: [F; 3],
    /// `r(1)`.
    pub p1: [F; 3],
    /// `r'(1)`.
    pub d1: [F; 3],
}

/// One spatial PH quintic Hermite interpolant.
#[derive(Debug, Clone, PartialEq)]
pub struct SpatialHermiteQuintic<F> {
    /// The data.
    pub data: SpatialHermiteData<F>,
    /// `(cos φ_0, sin φ_0)`.
    pub rotation0: (F, F),
    /// `(cos φ_2, sin φ_2)`.
    pub rotation2: (F, F),
    /// The quintic (quaternion form, start point `p_0`).
    pub curve: PhCurve<F>,
    /// Bending energy `∫κ² ds` (`f64` quadrature).
    pub bending_energy: f64,
}

/// The result of [`SpatialHermiteData::solve_auto`].
pub type SpatialHermiteResult =
    super::util::ExactOrFloat<SpatialHermiteQuintic<Rational>, SpatialHermiteQuintic<f64>>;

/// The minimizer of `f` on `[lo, hi]` by `n` golden-section steps and its value (the better
/// of the final bracket's interior points; `f` may be `+∞` where undefined).
pub(crate) fn golden_min(f: impl Fn(f64) -> f64, lo: f64, hi: f64, n: usize) -> (f64, f64) {
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (lo, hi);
    let mut c = b - g * (b - a);
    let mut d = a + g * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..n {
        if fc <= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = f(d);
        }
    }
    if fc <= fd {
        (c, fc)
    } else {
        (d, fd)
    }
}

/// `(cos φ, sin φ) = ((1 − τ²)/(1 + τ²), 2τ/(1 + τ²))` for `τ = tan(φ/2)` (exact for
/// rational `τ`; `τ = −1` gives `φ = −π/2`).
pub fn rotation_from_half_tangent<F: Scalar>(tau: &F) -> (F, F) {
    let t2 = tau.clone() * tau.clone();
    let den = F::one() + t2.clone();
    (
        (F::one() - t2) / den.clone(),
        tau.clone() * F::from_i64(2) / den,
    )
}

/// `c = 120(p_1 − p_0) − 15(d_0 + d_1) + 5(A_0 i A_2* + A_2 i A_0*)`, the right-hand side of
/// the quintic's middle equation `B i B* = c`, `B = 4A_1 + 3(A_0 + A_2)` (module doc).
pub(crate) fn middle_rhs<F: Scalar>(
    (p0, d0): (&[F; 3], &[F; 3]),
    (p1, d1): (&[F; 3], &[F; 3]),
    a0: &Quaternion<F>,
    a2: &Quaternion<F>,
) -> [F; 3] {
    let x = aib(a0, a2) + aib(a2, a0);
    let f = |n: i64| F::from_i64(n);
    let xv = [x.x, x.y, x.z];
    core::array::from_fn(|k| {
        (p1[k].clone() - p0[k].clone()) * f(120) - (d0[k].clone() + d1[k].clone()) * f(15)
            + xv[k].clone() * f(5)
    })
}

/// The middle coefficient `A_1 = (Q̂(c)e^{iφ_1} − 3(A_0 + A_2))/4` of the quintic
/// interpolant with end coefficients `A_0`, `A_2`, where
/// `c = 120(p_1 − p_0) − 15(d_0 + d_1) + 5(A_0 i A_2* + A_2 i A_0*)` (module doc);
/// `rotation1 = None` is `φ_1 = 0`.
///
/// # Errors
/// [`PhError::Degenerate`] if `c = 0` (for `f64`: negligible against the tangents), as
/// [`solve_qiq`] otherwise.
pub(crate) fn middle_coefficient<F: Scalar>(
    (p0, d0): (&[F; 3], &[F; 3]),
    (p1, d1): (&[F; 3], &[F; 3]),
    a0: &Quaternion<F>,
    a2: &Quaternion<F>,
    rotation1: Option<(F, F)>,
) -> Result<Quaternion<F>, PhError> {
    let f = |n: i64| F::from_i64(n);
    let c = middle_rhs((p0, d0), (p1, d1), a0, a2);
    let cnorm = c.iter().map(|v| v.to_f64().abs()).fold(0.0, f64::max);
    let scale = d0
        .iter()
        .chain(d1)
        .map(|v| v.to_f64().abs())
        .fold(0.0, f64::max);
    if c.iter().all(|v| v.is_zero()) || (!F::EXACT && cnorm <= 1e-14 * scale) {
        return Err(PhError::Degenerate(
            "120Δp − 15(d0 + d1) + 5X = 0 for these angles: choose other φ0, φ2".into(),
        ));
    }
    let b = solve_qiq(&c, rotation1)?;
    Ok((b - (a0.clone() + a2.clone()).scale(&f(3))).scale(&(F::one() / f(4))))
}

impl<F: Scalar> SpatialHermiteData<F> {
    /// New data.
    pub fn new(p0: [F; 3], d0: [F; 3], p1: [F; 3], d1: [F; 3]) -> Self {
        SpatialHermiteData { p0, d0, p1, d1 }
    }

    fn check(&self) -> Result<(), PhError> {
        super::util::check_hermite_ends(&self.p0, &self.d0, &self.p1, &self.d1)
    }

    /// [`PhError::NonFinite`] when the data (converted to `f64`) are not finite.
    fn check_finite(&self) -> Result<(), PhError> {
        super::util::check_finite(
            || "the Hermite data (p0, d0, p1, d1) in f64".into(),
            self.p0
                .iter()
                .chain(&self.d0)
                .chain(&self.p1)
                .chain(&self.d1),
        )
    }

    /// The interpolant with free angles `φ_0`, `φ_2` given as `(cos φ, sin φ)`.
    ///
    /// # Errors
    /// [`PhError::ZeroTangent`], [`PhError::CoincidentEndPoints`], [`PhError::OutOfRange`]
    /// (non-finite data, or `cos² + sin² ≠ 1`); [`PhError::Irrational`] (exact `F`) when a
    /// square root is irrational; [`PhError::Degenerate`] if
    /// `120Δp − 15(d_0 + d_1) + 5X = 0` (then `A_1` is not determined by this branch).
    pub fn interpolant(
        &self,
        rotation0: (F, F),
        rotation2: (F, F),
    ) -> Result<SpatialHermiteQuintic<F>, PhError> {
        let mut s = self.build(rotation0, rotation2)?;
        s.bending_energy = s.curve.to_poly_curve().bending_energy()?;
        Ok(s)
    }

    /// The interpolant with a quick energy estimate (composite Gauss–Legendre, 16 × 7
    /// nodes) in place of the adaptive one.
    fn build(
        &self,
        rotation0: (F, F),
        rotation2: (F, F),
    ) -> Result<SpatialHermiteQuintic<F>, PhError> {
        self.check()?;
        let a0 = solve_qiq(&self.d0, Some(rotation0.clone()))?;
        let a2 = solve_qiq(&self.d1, Some(rotation2.clone()))?;
        let a1 = middle_coefficient((&self.p0, &self.d0), (&self.p1, &self.d1), &a0, &a2, None)?;
        let curve = PhCurve::new(vec![a0, a1, a2], self.p0.clone())?;
        let bending_energy = quick_energy(&curve);
        Ok(SpatialHermiteQuintic {
            data: self.clone(),
            rotation0,
            rotation2,
            curve,
            bending_energy,
        })
    }

    fn to_f64(&self) -> SpatialHermiteData<f64> {
        let m = |v: &[F; 3]| [v[0].to_f64(), v[1].to_f64(), v[2].to_f64()];
        SpatialHermiteData::new(m(&self.p0), m(&self.d0), m(&self.p1), m(&self.d1))
    }

    /// The `f64` interpolant for angles `φ_0`, `φ_2` (radians).
    ///
    /// # Errors
    /// As [`Self::interpolant`].
    pub fn interpolant_f64(
        &self,
        phi0: f64,
        phi2: f64,
    ) -> Result<SpatialHermiteQuintic<f64>, PhError> {
        let d = self.to_f64();
        d.check_finite()?;
        d.interpolant((phi0.cos(), phi0.sin()), (phi2.cos(), phi2.sin()))
    }

    /// The least bending energy `f64` interpolant: the best of `φ_0, φ_2 ∈ {−π/2, 0, π/2, π}`,
    /// refined by a cyclic golden-section search in `φ_0` and `φ_2` (brackets of half a turn
    /// around the current angles, shrinking each round) from there. Candidates are compared
    /// by a 16 × 7-node Gauss–Legendre estimate; the chosen one's energy is then computed
    /// adaptively. The refinement reaches a local minimum near the best grid point (the
    /// energy as a function of the two angles need not be unimodal).
    ///
    /// # Errors
    /// As [`Self::interpolant`] (if every candidate fails, the first error).
    pub fn default_f64(&self) -> Result<SpatialHermiteQuintic<f64>, PhError> {
        use core::f64::consts::FRAC_PI_2;
        let d = self.to_f64();
        d.check_finite()?;
        let eval = |a: f64, b: f64| d.build((a.cos(), a.sin()), (b.cos(), b.sin()));
        let angles = [-FRAC_PI_2, 0.0, FRAC_PI_2, 2.0 * FRAC_PI_2];
        let mut best: Option<(f64, f64, SpatialHermiteQuintic<f64>)> = None;
        let mut first_err = None;
        for &a in &angles {
            for &b in &angles {
                match eval(a, b) {
                    Ok(s) => {
                        if best
                            .as_ref()
                            .is_none_or(|x| s.bending_energy < x.2.bending_energy * (1.0 - 1e-12))
                        {
                            best = Some((a, b, s));
                        }
                    }
                    Err(e) => {
                        first_err.get_or_insert(e);
                    }
                }
            }
        }
        let Some((mut a, mut b, mut sol)) = best else {
            return Err(
                first_err.unwrap_or_else(|| PhError::NoRealSolution("no candidate angles".into()))
            );
        };
        // cyclic golden-section refinement; failures count as +∞
        let energy = |a: f64, b: f64| eval(a, b).map_or(f64::INFINITY, |s| s.bending_energy);
        let mut half = FRAC_PI_2;
        let mut e = sol.bending_energy;
        for _ in 0..4 {
            let (na, ea) = golden_min(|x| energy(x, b), a - half, a + half, 12);
            if ea < e {
                (a, e) = (na, ea);
            }
            let (nb, eb) = golden_min(|x| energy(a, x), b - half, b + half, 12);
            if eb < e {
                (b, e) = (nb, eb);
            }
            half *= 0.5;
        }
        if let Ok(s) = eval(a, b) {
            if s.bending_energy < sol.bending_energy {
                sol = s;
            }
        }
        sol.bending_energy = sol.curve.to_poly_curve().bending_energy()?;
        Ok(sol)
    }

    /// Exact (over `Rational`) for the rotations given as rational half-angle tangents
    /// `τ_0`, `τ_2` when every square root is rational, otherwise `f64` for the same angles.
    ///
    /// # Errors
    /// As [`Self::interpolant`], except that irrational roots fall back to `f64`.
    pub fn solve_auto(&self, tau0: &F, tau2: &F) -> Result<SpatialHermiteResult, PhError> {
        let bad = || PhError::OutOfRange("non-finite Hermite data".into());
        let r3 = |v: &[F; 3]| -> Result<[Rational; 3], PhError> {
            Ok([
                v[0].to_rational().ok_or_else(bad)?,
                v[1].to_rational().ok_or_else(bad)?,
                v[2].to_rational().ok_or_else(bad)?,
            ])
        };
        let exact =
            SpatialHermiteData::new(r3(&self.p0)?, r3(&self.d0)?, r3(&self.p1)?, r3(&self.d1)?);
        let t0 = tau0.to_rational().ok_or_else(bad)?;
        let t2 = tau2.to_rational().ok_or_else(bad)?;
        let rot0 = rotation_from_half_tangent(&t0);
        let rot2 = rotation_from_half_tangent(&t2);
        match exact.interpolant(rot0.clone(), rot2.clone()) {
            Ok(s) => Ok(SpatialHermiteResult::Exact(Box::new(s))),
            Err(PhError::Irrational(_)) => {
                let m = |r: &(Rational, Rational)| (Scalar::to_f64(&r.0), Scalar::to_f64(&r.1));
                Ok(SpatialHermiteResult::Float(Box::new(
                    self.to_f64().interpolant(m(&rot0), m(&rot2))?,
                )))
            }
            Err(e) => Err(e),
        }
    }
}

/// `∫₀¹ |r'×r''|²/σ⁵ dt` (the bending energy) by composite 7-point Gauss–Legendre on 16
/// pieces, in `f64` (`∞` if `σ` vanishes at a node).
fn quick_energy<F: Scalar>(c: &PhCurve<F>) -> f64 {
    let h: Vec<Poly<f64>> = c
        .hodograph()
        .iter()
        .map(|p| p.map(|x| x.to_f64()))
        .collect();
    let h2: Vec<Poly<f64>> = h.iter().map(|p| p.derivative()).collect();
    let s = c.speed().map(|x| x.to_f64());
    let f = |t: f64| {
        let a: Vec<f64> = h.iter().map(|p| p.eval(&t)).collect();
        let b: Vec<f64> = h2.iter().map(|p| p.eval(&t)).collect();
        let cx = a[1] * b[2] - a[2] * b[1];
        let cy = a[2] * b[0] - a[0] * b[2];
        let cz = a[0] * b[1] - a[1] * b[0];
        let sg = s.eval(&t);
        (cx * cx + cy * cy + cz * cz) / (sg * sg * sg * sg * sg)
    };
    (0..16)
        .map(|i| gauss7(&f, i as f64 / 16.0, (i + 1) as f64 / 16.0))
        .sum::<f64>()
}

impl<F: Scalar> SpatialHermiteQuintic<F> {
    /// The largest interpolation residual `max(|r(0) − p_0|, |r'(0) − d_0|, |r(1) − p_1|,
    /// |r'(1) − d_1|)` (computed in `F`, reported in `f64`).
    pub fn residual(&self) -> f64 {
        let pts = self.curve.control_points();
        let h = self.curve.hodograph_bernstein();
        let (Some(first), Some(last), Some(h0), Some(h4)) =
            (pts.first(), pts.last(), h.first(), h.last())
        else {
            return f64::INFINITY;
        };
        let d = &self.data;
        [(first, &d.p0), (h0, &d.d0), (last, &d.p1), (h4, &d.d1)]
            .iter()
            .map(|(a, b)| {
                (0..3)
                    .map(|k| (a[k].clone() - b[k].clone()).to_f64().powi(2))
                    .sum::<f64>()
                    .sqrt()
            })
            .fold(0.0, f64::max)
    }

    /// Certificates: the PH certificates of the quintic ([`PhCurve::certify`]) and the
    /// Hermite conditions `r(0) = p_0`, `r'(0) = d_0`, `r(1) = p_1`, `r'(1) = d_1` per
    /// coordinate (exact for exact scalars; for `f64` to a relative tolerance, with the
    /// residual reported on failure).
    pub fn certify(&self) -> Vec<Certificate> {
        let mut out = self.curve.certify();
        let pts = self.curve.control_points();
        let h = self.curve.hodograph_bernstein();
        let d = &self.data;
        if let (Some(first), Some(last), Some(h0), Some(h4)) =
            (pts.first(), pts.last(), h.first(), h.last())
        {
            for (name, got, want) in [
                ("r(0) = p0", first, &d.p0),
                ("r'(0) = d0", h0, &d.d0),
                ("r(1) = p1", last, &d.p1),
                ("r'(1) = d1", h4, &d.d1),
            ] {
                for (k, axis) in ["x", "y", "z"].iter().enumerate() {
                    out.push(scalar_cert(format!("{name} ({axis})"), &got[k], &want[k]));
                }
            }
        }
        out
    }
}

impl<F: Scalar> crate::Certified for SpatialHermiteQuintic<F> {
    fn certify(&self) -> Vec<Certificate> {
        SpatialHermiteQuintic::certify(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    #[test]
    fn exact_from_a_rational_quintic() {
        // data read off a PH quintic with rational preimage A_0 = i, A_1 = 2 + j + k,
        // A_2 = i + j + k (A_2 i A_2* = (−1, 2, 2)); B = 4A_1 + 3(A_0 + A_2) has
        // B_w² + B_x² = 8² + 6² = 10², so every square root is rational at φ0 = φ2 = 0
        let a0 = Quaternion::new(q(0), q(1), q(0), q(0));
        let a1 = Quaternion::new(q(2), q(0), q(1), q(1));
        let a2 = Quaternion::new(q(0), q(1), q(1), q(1));
        let c = PhCurve::new(vec![a0, a1, a2], [q(0), q(0), q(0)]).unwrap();
        let pts = c.control_points();
        let h = c.hodograph_bernstein();
        let data =
            SpatialHermiteData::new(pts[0].clone(), h[0].clone(), pts[5].clone(), h[4].clone());
        let f = data.default_f64().unwrap();
        assert!(Certificate::all_hold(&f.certify()));
        assert!(f.residual() < 1e-12);
        // exact at φ0 = φ2 = 0 when the three square roots are rational, else f64
        let r = data.solve_auto(&q(0), &q(0)).unwrap();
        assert!(Certificate::all_hold(&r.certify()));
        assert!(r.is_exact());
        if let SpatialHermiteResult::Exact(s) = &r {
            assert_eq!(s.residual(), 0.0);
            assert!(s.certify().iter().all(|c| c.exact));
            // f64 at the same angles agrees with the exact interpolant
            let f = data.interpolant_f64(0.0, 0.0).unwrap();
            for (a, b) in s
                .curve
                .control_points()
                .iter()
                .zip(f.curve.control_points())
            {
                for k in 0..3 {
                    assert!((Scalar::to_f64(&a[k]) - b[k]).abs() < 1e-12);
                }
            }
            assert!((s.bending_energy - f.bending_energy).abs() < 1e-9 * s.bending_energy);
        }
        // irrational: φ0 = π/2 (τ = 1) moves X, and the f64 fallback still certifies
        let r = data.solve_auto(&q(1), &q(0)).unwrap();
        assert!(Certificate::all_hold(&r.certify()));
        assert!(matches!(
            SpatialHermiteData::new(
                [q(0), q(0), q(0)],
                [q(0), q(0), q(0)],
                [q(1), q(1), q(1)],
                [q(1), q(1), q(1)]
            )
            .interpolant((q(1), q(0)), (q(1), q(0))),
            Err(PhError::ZeroTangent(_))
        ));
    }
}
