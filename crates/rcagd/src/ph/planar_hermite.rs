//! Planar PH quintic C1 Hermite interpolation (Farouki–Neff 1995, "Hermite
//! interpolation by Pythagorean hodograph quintics"; Farouki 2008 §25.1; issue 5 part B).
//!
//! With `w(t) = w_0 b_0² + w_1 b_1² + w_2 b_2²` (quadratic Bernstein) and `r' = w²`, the
//! conditions `r'(0) = d_0`, `r'(1) = d_1`, `r(1) − r(0) = Δp` read `w_0² = d_0`,
//! `w_2² = d_1` and (the integral `∫₀¹ w²` of the Bernstein products, checked with sympy)
//!
//! `3w_0² + 3w_0w_1 + 2w_1² + w_0w_2 + 3w_1w_2 + 3w_2² = 15Δp`,
//!
//! whose solutions are `w_1 = −¾(w_0 + w_2) ± ¼√(120Δp − 15(d_0 + d_1) + 10w_0w_2)`.
//! With `w_0 = √d_0` (the overall sign of `w` does not change `r`), `w_2 = ±√d_1` and the
//! two signs of the outer root this gives four interpolants. All square roots are complex
//! (`√(a+ib) = x + iy`, `x = √((|z|+a)/2)`, `y = b/(2x)`); in exact arithmetic they exist
//! iff the radicands are squares of Gaussian rationals, otherwise the problem is solved in
//! `f64` ([`PlanarHermiteData::solve_auto`] picks). The "good" interpolant (Farouki–Neff)
//! is the one with the smallest absolute rotation index `(1/2π)∫|κ|ds`; ties are broken by
//! the bending energy `∫κ²ds`.

use super::planar::{complex_sqrt, scalar_cert, PlanarPhCurve, C};
use super::PhError;
use rcagd_algebra::{Certificate, Rational, Scalar};

/// Planar C1 Hermite data: `r(0) = p0`, `r'(0) = d0`, `r(1) = p1`, `r'(1) = d1`.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanarHermiteData<F> {
    /// Start point.
    pub p0: [F; 2],
    /// Start derivative.
    pub d0: [F; 2],
    /// End point.
    pub p1: [F; 2],
    /// End derivative.
    pub d1: [F; 2],
}

/// One of the four PH quintic interpolants.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanarHermiteInterpolant<F> {
    /// `+1` if `w_2 = +√d_1`, `−1` if `w_2 = −√d_1` (principal roots).
    pub end_sign: i8,
    /// Sign of the outer root in `w_1`.
    pub root_sign: i8,
    /// The PH quintic.
    pub curve: PlanarPhCurve<F>,
    /// Absolute rotation index `(1/2π)∫|κ| ds` (f64; `+∞` for an interpolant with a cusp,
    /// where `σ` vanishes on `[0, 1]` and the quadrature does not apply).
    pub absolute_rotation_index: f64,
    /// Bending energy `∫κ² ds` (f64; `+∞` for an interpolant with a cusp: it diverges).
    pub bending_energy: f64,
    /// `true` for the "good" interpolant (least rotation index, then least energy).
    pub best: bool,
}

/// All four interpolants.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanarHermiteSolution<F> {
    /// The data.
    pub data: PlanarHermiteData<F>,
    /// The four interpolants, `(end_sign, root_sign)` = `(+,+), (+,−), (−,+), (−,−)`.
    pub interpolants: Vec<PlanarHermiteInterpolant<F>>,
    /// `true` if every square root was rational (exact scalar): the control points are
    /// exact.
    pub exact: bool,
}

/// The result of [`PlanarHermiteData::solve_auto`].
pub type PlanarHermiteResult =
    super::util::ExactOrFloat<PlanarHermiteSolution<Rational>, PlanarHermiteSolution<f64>>;

/// The error of a complex square root that is not in `F`: irrational for exact `F`
/// (solve in `f64`); for `f64` (where every root exists) an overflowed radicand.
fn no_root<F: Scalar>(what: &str) -> PhError {
    if F::EXACT {
        PhError::Irrational(format!(
            "{what} is not a Gaussian rational; use the f64 path"
        ))
    } else {
        PhError::NonFinite {
            what: format!("{what} (from the Hermite data)"),
        }
    }
}

/// [`PhError::NonFinite`] when an `f64` preimage coefficient overflowed.
fn check_preimage<F: Scalar>(w: &[&C<F>; 3]) -> Result<(), PhError> {
    super::util::check_finite(
        || "the preimage (w0, w1, w2) computed from the Hermite data".into(),
        w.iter().flat_map(|c| [&c.re, &c.im]),
    )
}

fn cx<F: Scalar>(p: &[F; 2]) -> C<F> {
    C::new(p[0].clone(), p[1].clone())
}

impl<F: Scalar> PlanarHermiteData<F> {
    /// New data.
    pub fn new(p0: [F; 2], d0: [F; 2], p1: [F; 2], d1: [F; 2]) -> Self {
        PlanarHermiteData { p0, d0, p1, d1 }
    }

    fn check(&self) -> Result<(), PhError> {
        super::util::check_finite(
            || "the Hermite data (p0, d0, p1, d1)".into(),
            self.p0
                .iter()
                .chain(&self.d0)
                .chain(&self.p1)
                .chain(&self.d1),
        )?;
        super::util::check_hermite_ends(&self.p0, &self.d0, &self.p1, &self.d1)
    }

    /// The four interpolants in `F`: for exact `F` every square root must be rational
    /// (else [`PhError::Irrational`]); for `f64` always (given valid data).
    ///
    /// # Errors
    /// [`PhError::ZeroTangent`] for `d0 = 0` or `d1 = 0`, [`PhError::CoincidentEndPoints`]
    /// for `p0 = p1`, [`PhError::Irrational`] (exact `F`) for an irrational root,
    /// [`PhError::OutOfRange`] for non-finite data; [`PhError::NonFinite`] (`f64`) when
    /// the data are finite but an intermediate overflows.
    pub fn solve(&self) -> Result<PlanarHermiteSolution<F>, PhError> {
        self.check()?;
        let mut interpolants = Vec::with_capacity(4);
        for end_sign in [1i8, -1] {
            for root_sign in [1i8, -1] {
                interpolants.push(self.branch(end_sign, root_sign)?);
            }
        }
        mark_best(&mut interpolants);
        Ok(PlanarHermiteSolution {
            data: self.clone(),
            interpolants,
            exact: F::EXACT,
        })
    }

    /// One interpolant: `w_0 = √d_0`, `w_2 = end_sign·√d_1` (principal roots),
    /// `w_1 = −¾(w_0 + w_2) + root_sign·¼√(120Δp − 15(d_0 + d_1) + 10w_0w_2)`
    /// (`best` is left `false`). In exact arithmetic one branch may be rational while
    /// another is not.
    ///
    /// # Errors
    /// As [`Self::solve`].
    pub fn solve_branch(
        &self,
        end_sign: i8,
        root_sign: i8,
    ) -> Result<PlanarHermiteInterpolant<F>, PhError> {
        self.check()?;
        self.branch(end_sign, root_sign)
    }

    fn branch(&self, end_sign: i8, root_sign: i8) -> Result<PlanarHermiteInterpolant<F>, PhError> {
        let irr = no_root::<F>;
        let d0 = cx(&self.d0);
        let d1 = cx(&self.d1);
        let dp = cx(&self.p1) - cx(&self.p0);
        let w0 = complex_sqrt(&d0).ok_or_else(|| irr("√d0"))?;
        let w2p = complex_sqrt(&d1).ok_or_else(|| irr("√d1"))?;
        let f = |n: i64| F::from_i64(n);
        let w2 = if end_sign > 0 { w2p } else { -w2p };
        // c = 120Δp − 15(d0 + d1) + 10 w0 w2
        let c =
            dp.scale(&f(120)) - (d0 + d1).scale(&f(15)) + (w0.clone() * w2.clone()).scale(&f(10));
        let root = complex_sqrt(&c).ok_or_else(|| irr("√(120Δp − 15(d0 + d1) + 10 w0 w2)"))?;
        let r = if root_sign > 0 { root } else { -root };
        let w1 = (r - (w0.clone() + w2.clone()).scale(&f(3))).scale(&(F::one() / f(4)));
        check_preimage(&[&w0, &w1, &w2])?;
        let curve = PlanarPhCurve::new(vec![w0, w1, w2], self.p0.clone())?;
        // an interpolant through a cusp (σ vanishes on [0, 1]) is still an interpolant:
        // its energy diverges and its rotation index is not computed (+∞ for both), so it
        // is never the best one; before, it failed the whole solve
        let absolute_rotation_index = curve.absolute_rotation_index().unwrap_or(f64::INFINITY);
        let bending_energy = curve.bending_energy().unwrap_or(f64::INFINITY);
        Ok(PlanarHermiteInterpolant {
            end_sign: if end_sign > 0 { 1 } else { -1 },
            root_sign: if root_sign > 0 { 1 } else { -1 },
            curve,
            absolute_rotation_index,
            bending_energy,
            best: false,
        })
    }

    /// The preimages `(w_0, w_1, w_2)` of the four interpolants, in the order
    /// `(end_sign, root_sign)` = `(+,+), (+,−), (−,+), (−,−)`, without the shape measures
    /// (the fast path: four complex square roots and a few products).
    ///
    /// # Errors
    /// As [`Self::solve`].
    pub fn quintic_preimages(&self) -> Result<Vec<[C<F>; 3]>, PhError> {
        self.check()?;
        let irr = no_root::<F>;
        let d0 = cx(&self.d0);
        let d1 = cx(&self.d1);
        let dp = cx(&self.p1) - cx(&self.p0);
        let w0 = complex_sqrt(&d0).ok_or_else(|| irr("√d0"))?;
        let w2p = complex_sqrt(&d1).ok_or_else(|| irr("√d1"))?;
        let f = |n: i64| F::from_i64(n);
        let base = dp.scale(&f(120)) - (d0 + d1).scale(&f(15));
        let quarter = F::one() / f(4);
        let mut out = Vec::with_capacity(4);
        for w2 in [w2p.clone(), -w2p] {
            let c = base.clone() + (w0.clone() * w2.clone()).scale(&f(10));
            let root = complex_sqrt(&c).ok_or_else(|| irr("√(120Δp − 15(d0 + d1) + 10 w0 w2)"))?;
            let m = (w0.clone() + w2.clone()).scale(&f(3));
            for r in [root.clone(), -root] {
                let w1 = (r - m.clone()).scale(&quarter);
                check_preimage(&[&w0, &w1, &w2])?;
                out.push([w0.clone(), w1, w2.clone()]);
            }
        }
        Ok(out)
    }

    /// The four interpolants in `f64`.
    ///
    /// # Errors
    /// As [`Self::solve`] (never [`PhError::Irrational`]).
    pub fn solve_f64(&self) -> Result<PlanarHermiteSolution<f64>, PhError> {
        let m = |v: &[F; 2]| [v[0].to_f64(), v[1].to_f64()];
        PlanarHermiteData::new(m(&self.p0), m(&self.d0), m(&self.p1), m(&self.d1)).solve()
    }

    /// Exact when every square root is rational, otherwise `f64`.
    ///
    /// # Errors
    /// As [`Self::solve`] (the irrational case falls back to `f64`).
    pub fn solve_auto(&self) -> Result<PlanarHermiteResult, PhError> {
        let conv = |v: &[F; 2]| -> Result<[Rational; 2], PhError> {
            let a = v[0]
                .to_rational()
                .ok_or_else(|| PhError::OutOfRange("non-finite Hermite data".into()))?;
            let b = v[1]
                .to_rational()
                .ok_or_else(|| PhError::OutOfRange("non-finite Hermite data".into()))?;
            Ok([a, b])
        };
        let exact = PlanarHermiteData::new(
            conv(&self.p0)?,
            conv(&self.d0)?,
            conv(&self.p1)?,
            conv(&self.d1)?,
        );
        match exact.solve() {
            Ok(s) => Ok(PlanarHermiteResult::Exact(Box::new(s))),
            Err(PhError::Irrational(_)) => {
                Ok(PlanarHermiteResult::Float(Box::new(self.solve_f64()?)))
            }
            Err(e) => Err(e),
        }
    }
}

fn mark_best<F>(v: &mut [PlanarHermiteInterpolant<F>]) {
    let mut best: Option<usize> = None;
    for (i, c) in v.iter().enumerate() {
        best = match best {
            None => Some(i),
            Some(b) => {
                let (rb, eb) = (v[b].absolute_rotation_index, v[b].bending_energy);
                let (ri, ei) = (c.absolute_rotation_index, c.bending_energy);
                let tie = (ri - rb).abs() <= 1e-9 * (1.0 + rb.abs());
                if ri < rb && !tie || tie && ei < eb {
                    Some(i)
                } else {
                    Some(b)
                }
            }
        };
    }
    if let Some(b) = best {
        if let Some(c) = v.get_mut(b) {
            c.best = true;
        }
    }
}

impl<F: Scalar> PlanarHermiteSolution<F> {
    /// The "good" interpolant (least absolute rotation index, then least energy).
    pub fn best(&self) -> Option<&PlanarHermiteInterpolant<F>> {
        self.interpolants.iter().find(|c| c.best)
    }

    /// Certificates of every interpolant: its PH certificates
    /// ([`PlanarPhCurve::certify`]) and the four Hermite conditions `r(0) = p0`,
    /// `r'(0) = d0`, `r(1) = p1`, `r'(1) = d1` (exact for exact scalars).
    pub fn certify(&self) -> Vec<Certificate> {
        let mut out = Vec::new();
        for (k, c) in self.interpolants.iter().enumerate() {
            let tag = format!("interpolant {k} ({:+}, {:+})", c.end_sign, c.root_sign);
            for mut cert in c.curve.certify() {
                cert.property = format!("{tag}: {}", cert.property);
                out.push(cert);
            }
            out.extend(hermite_certs(&tag, &c.curve, &self.data));
        }
        out
    }
}

/// The four Hermite conditions of a planar curve as certificates.
pub(crate) fn hermite_certs<F: Scalar>(
    tag: &str,
    c: &PlanarPhCurve<F>,
    d: &PlanarHermiteData<F>,
) -> Vec<Certificate> {
    let r0 = c.eval(&F::zero());
    let r1 = c.eval(&F::one());
    let t0 = c.derivative_at(&F::zero());
    let t1 = c.derivative_at(&F::one());
    let mut out = Vec::new();
    for (name, got, want) in [
        ("r(0) = p0", r0, &d.p0),
        ("r'(0) = d0", t0, &d.d0),
        ("r(1) = p1", r1, &d.p1),
        ("r'(1) = d1", t1, &d.d1),
    ] {
        for (i, axis) in ["x", "y"].iter().enumerate() {
            out.push(scalar_cert(
                format!("{tag}: {name} ({axis})"),
                &got[i],
                &want[i],
            ));
        }
    }
    out
}

impl<F: Scalar> crate::Certified for PlanarHermiteSolution<F> {
    fn certify(&self) -> Vec<Certificate> {
        PlanarHermiteSolution::certify(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    #[test]
    fn exact_when_roots_are_rational() {
        // w0 = 1, w2 = ±(1 + i) (d0 = 1, d1 = 2i); c± = 120Δp − 15(d0 + d1) ± 10(1 + i)
        // must both be squares: c+ = (6+5i)² = 11 + 60i, c− = (4+5i)² = −9 + 40i, whose
        // difference is 20(1 + i); then 120Δp = 16 + 80i, Δp = (2/15, 2/3).
        let data = PlanarHermiteData::new(
            [q(0), q(0)],
            [q(1), q(0)],
            [q(2) / q(15), q(2) / q(3)],
            [q(0), q(2)],
        );
        let s = data.solve().unwrap();
        assert!(s.exact);
        assert!(Certificate::all_hold(&s.certify()));
        assert_eq!(s.interpolants.len(), 4);
        assert_eq!(s.interpolants.iter().filter(|c| c.best).count(), 1);
        // w1 = −¾(w0 + w2) + ¼(6 + 5i) for the (+, +) interpolant
        let w1 = &s.interpolants[0].curve.preimage_coefficients()[1];
        assert_eq!(*w1, C::new(q(0), q(1) / q(2)));
        assert!(data.solve_auto().unwrap().is_exact());
        // f64 agrees
        let f = data.solve_f64().unwrap();
        for (a, b) in s.interpolants.iter().zip(&f.interpolants) {
            let pa = a.curve.control_points();
            let pb = b.curve.control_points();
            for (x, y) in pa.iter().zip(&pb) {
                assert!((Scalar::to_f64(&x[0]) - y[0]).abs() < 1e-12);
                assert!((Scalar::to_f64(&x[1]) - y[1]).abs() < 1e-12);
            }
            assert_eq!(a.best, b.best);
        }
        // irrational data fall back to f64
        let irr = PlanarHermiteData::new([q(0), q(0)], [q(2), q(0)], [q(1), q(0)], [q(1), q(1)]);
        assert!(matches!(irr.solve(), Err(PhError::Irrational(_))));
        let r = irr.solve_auto().unwrap();
        assert!(!r.is_exact());
        assert!(Certificate::all_hold(&r.certify()));
    }

    #[test]
    fn errors() {
        let z = [q(0), q(0)];
        let one = [q(1), q(0)];
        assert!(matches!(
            PlanarHermiteData::new(z.clone(), z.clone(), one.clone(), one.clone()).solve(),
            Err(PhError::ZeroTangent(_))
        ));
        assert!(matches!(
            PlanarHermiteData::new(one.clone(), one.clone(), one.clone(), one.clone()).solve(),
            Err(PhError::CoincidentEndPoints(_))
        ));
    }
}
