//! Pipe surfaces: canal surfaces of constant radius (Gruber §2.1 "Rohrfläche"; Peternell
//! Cor. 4.3: pipes around rational spines are rational).
//!
//! For a constant radius `ṙ ≡ 0`, so `D = |ṁ|²·W⁴/d²`, and the construction of
//! [`super::envelope`] needs `|ṁ|²` as a sum of two squares:
//!
//! * around a **PH curve** (Besednjak; `|r'|² = σ²`) the split is `(σ/d, 0)` — rational over
//!   the scalar field of the curve, generic over [`Scalar`] (also `f64`), no factorization
//!   ([`pipe_around_ph`], [`pipe_around_ph_poly`]); this is the case singled out by Gruber
//!   §2.1 ("Pythagorean-Hodograph Kurven … lassen eine einfachere Konstruktion zu");
//! * around a **planar** spine (`ṁ₃ ≡ 0` in some coordinate) the split is `(ṁ₁, ṁ₂)`;
//! * around any other rational spine the exact split of [`super::sum_of_squares`] decides
//!   (over `Q`, one quadratic field, or an error) — [`pipe_surface`].

use super::envelope::{
    canal_surface, canal_surface_with_split, CanalBuild, CanalOptions, CanalSurface,
};
use super::{CanalError, CanalSpine};
use crate::ph::{PhCurve, PhPolyCurve};
use rcagd_algebra::{Poly, Rational, Scalar};
use rcagd_geom::BezierCurve;

fn check_radius<F: Scalar>(r: &F) -> Result<(), CanalError> {
    if r.is_zero() || !r.to_f64().is_finite() {
        return Err(CanalError::InvalidArgument(format!(
            "the pipe radius must be non-zero and finite, got {}",
            crate::error::format_scalar(r)
        )));
    }
    Ok(())
}

/// The pipe of radius `r` around a polynomial PH curve `r(t)` with parametric speed `σ`.
///
/// # Errors
/// [`CanalError::InvalidArgument`] for `r = 0`; as [`canal_surface_with_split`].
pub fn pipe_around_ph_parts<F: Scalar>(
    position: &[Poly<F>; 3],
    sigma: &Poly<F>,
    radius: &F,
    options: &CanalOptions,
) -> Result<CanalSurface<F>, CanalError> {
    check_radius(radius)?;
    let spine = CanalSpine::polynomial(position.clone(), Poly::constant(radius.clone()));
    let g1 = if F::EXACT {
        let h: [Poly<F>; 3] = core::array::from_fn(|i| position[i].derivative());
        let d = h.iter().fold(Poly::zero(), |acc: Poly<F>, p| acc.gcd(p));
        if d.degree().is_some_and(|k| k > 0) {
            sigma.div_exact(&d)?
        } else {
            // gcd is the monic constant 1: σ stays, up to the leading-coefficient scaling
            // of the derivative numerators (none for W = 1)
            sigma.clone()
        }
    } else {
        sigma.clone()
    };
    canal_surface_with_split(&spine, &g1, &Poly::zero(), options)
}

/// The pipe of radius `r` around a spatial PH curve in quaternion form (docs/math/ph-curves.md, "The hodograph and the speed"):
/// split `(σ, 0)`, exact over the curve's scalar field.
///
/// # Errors
/// As [`pipe_around_ph_parts`].
pub fn pipe_around_ph<F: Scalar>(
    curve: &PhCurve<F>,
    radius: &F,
    options: &CanalOptions,
) -> Result<CanalSurface<F>, CanalError> {
    pipe_around_ph_parts(&curve.position(), &curve.speed(), radius, options)
}

/// The pipe of radius `r` around a PH curve in power form.
///
/// # Errors
/// As [`pipe_around_ph_parts`].
pub fn pipe_around_ph_poly<F: Scalar>(
    curve: &PhPolyCurve<F>,
    radius: &F,
    options: &CanalOptions,
) -> Result<CanalSurface<F>, CanalError> {
    pipe_around_ph_parts(curve.position(), curve.speed(), radius, options)
}

/// The pipe of radius `r` around a planar rational spine given as a Bézier curve of
/// dimension 3 whose `axis` coordinate is constant: split `(P_a, P_b)` (no factorization).
///
/// # Errors
/// [`CanalError::InvalidArgument`] if the spine is not planar in that coordinate; as
/// [`canal_surface_with_split`].
pub fn pipe_around_planar<F: Scalar>(
    spine: &BezierCurve<F>,
    radius: &F,
    options: &CanalOptions,
) -> Result<CanalSurface<F>, CanalError> {
    check_radius(radius)?;
    let s = CanalSpine::constant_radius(spine, radius)?;
    let p = s.derivative_numerators()?;
    let Some(j) = (0..3).find(|&j| p[j].is_zero()) else {
        return Err(CanalError::InvalidArgument(
            "the spine is not planar in a coordinate plane (no ṁⱼ ≡ 0)".into(),
        ));
    };
    let others: Vec<usize> = (0..3).filter(|&i| i != j).collect();
    canal_surface_with_split(&s, &p[others[0]], &p[others[1]], options)
}

/// The pipe of radius `r` around any rational spine, exactly: over `Q` when `|ṁ|²` (cleared)
/// is a sum of two rational squares, else over the quadratic field it needs (stated), else
/// an error ([`super::sum_of_squares`]). With a domain in `options` the frame is chosen
/// so that the parametrization has no base point there ([`super::frame`]).
///
/// # Errors
/// As [`canal_surface`]; [`CanalError::InvalidArgument`] for `r = 0`.
pub fn pipe_surface(
    spine: &BezierCurve<Rational>,
    radius: &Rational,
    options: &CanalOptions,
) -> Result<CanalBuild, CanalError> {
    check_radius(radius)?;
    let s = CanalSpine::constant_radius(spine, radius)?;
    if options.domain.is_some() {
        super::frame::canal_surface_pole_free(&s, options)
    } else {
        canal_surface(&s, options)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Certified;
    use rcagd_algebra::quaternion::Quaternion;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    #[test]
    fn pipe_around_ph_cubic_exact_and_f64() {
        let a = vec![
            Quaternion::new(q(1), q(0), q(1), q(0)),
            Quaternion::new(q(0), q(1), q(0), q(1)),
        ];
        let c = PhCurve::new(a, [q(0), q(0), q(0)]).expect("ph");
        let s = pipe_around_ph(&c, &Rational::from_ratio(1, 2), &CanalOptions::default())
            .expect("pipe");
        assert!(s.all_hold(), "{:?}", s.certify());
        let opts = CanalOptions {
            axis: Some(s.axis()),
            ..CanalOptions::default()
        };
        let sf = pipe_around_ph(&c.to_f64(), &0.5, &opts).expect("f64");
        assert!(sf.all_hold());
        // f64 and exact agree (same axis, same split up to the content factor)
        let t = Rational::from_ratio(1, 3);
        let u = Rational::from_ratio(2, 5);
        let pe = s.eval(&t, &u).expect("pt");
        let pf = sf.eval(&(1.0 / 3.0), &0.4).expect("pt");
        for k in 0..3 {
            assert!((Scalar::to_f64(&pe[k]) - pf[k]).abs() < 1e-12, "{k}");
        }
    }
}
