//! Certified local regularity of pipe surfaces: `r·κ < 1` on the whole parameter interval,
//! decided exactly by polynomial positivity (see `docs/math/pipes.md#regularity`).
//!
//! The pipe `x = m + r q` of radius `r` around a spine `m(t)` (the envelope of the spheres of
//! radius `r` centred on the spine; D. Gruber, "Rationale Parametrisierungen von
//! Kugelhüllflächen", 2008, §2.1 "Rohrfläche") is free of local self-intersections iff
//! `r·κ(t) < 1` for the curvature `κ` of the spine and `m′(t) ≠ 0`: the normal-plane circle
//! of radius `r` then lies inside the osculating-circle region, and `x_t` never vanishes
//! (`|x_t| = |m′|(1 − r κ cos θ)`).
//!
//! For a rational spine `m = M/W` let `P = W M′ − W′ M` (so `m′ = P/W²`). Then
//! `m′ × m″ = (P × P′)/W⁴` and `κ = |m′ × m″|/|m′|³ = W²|P × P′|/|P|³`, so on an interval
//! where `W ≠ 0` and `P ≠ 0`
//!
//! ```text
//! r κ < 1   ⇔   F(t) = |P|⁶ − r² W⁴ |P × P′|² > 0,
//! ```
//!
//! a polynomial inequality. `F > 0` on `[a, b]` iff `F(a) > 0` and `F` has no real root in
//! `[a, b]` (exact root counting by Descartes' rule on Bernstein coefficients,
//! `rcagd_algebra::roots`). Where it fails, the roots of `F` bound the parameter intervals
//! with `r κ ≥ 1`, and the error names one ([`CanalError::RadiusNotBelowCurvatureRadius`]).
//! A root of `|P|²` in `[a, b]` is a zero-length tangent ([`CanalError::ZeroTangent`]).

use super::{CanalError, CanalSpine};
use crate::error::format_scalar;
use rcagd_algebra::roots::{isolate_real_roots_in, rational_roots, RootInterval};
use rcagd_algebra::{Certificate, Poly, Rational, Scalar};

type P = Poly<Rational>;

fn cross(a: &[P; 3], b: &[P; 3]) -> [P; 3] {
    [
        &(&a[1] * &b[2]) - &(&a[2] * &b[1]),
        &(&a[2] * &b[0]) - &(&a[0] * &b[2]),
        &(&a[0] * &b[1]) - &(&a[1] * &b[0]),
    ]
}

fn norm_sq(a: &[P; 3]) -> P {
    &(&(&a[0] * &a[0]) + &(&a[1] * &a[1])) + &(&a[2] * &a[2])
}

/// The polynomials of the module docs for a pipe family (`R = r W`): `(|P|², F)` and `r`.
///
/// # Errors
/// [`CanalError::InvalidArgument`] if the radius is not constant (`R W′ − R′ W ≢ 0`) or
/// zero.
pub fn pipe_regularity_polynomials(
    spine: &CanalSpine<Rational>,
) -> Result<(P, P, Rational), CanalError> {
    let w = spine.weight();
    let r_poly = spine.radius_poly();
    let wd = w.derivative();
    if !(&(r_poly * &wd) - &(&r_poly.derivative() * w)).is_zero() {
        return Err(CanalError::InvalidArgument(
            "the regularity test r·κ < 1 is for pipes (constant radius)".into(),
        ));
    }
    // r = R/W with W ≢ 0: the ratio of leading coefficients
    let r = match (r_poly.degree(), w.degree()) {
        (Some(dr), Some(dw)) if dr == dw => r_poly.leading() / w.leading(),
        _ => {
            return Err(CanalError::InvalidArgument(
                "the pipe radius must be non-zero".into(),
            ))
        }
    };
    let m = spine.center_polys();
    let p: [P; 3] = core::array::from_fn(|i| &(w * &m[i].derivative()) - &(&wd * &m[i]));
    let pd: [P; 3] = core::array::from_fn(|i| p[i].derivative());
    let pp = norm_sq(&p);
    let w2 = w * w;
    let f = &(&(&pp * &pp) * &pp)
        - &(&(&w2 * &w2) * &norm_sq(&cross(&p, &pd))).scale(&(r.clone() * r.clone()));
    Ok((pp, f, r))
}

/// A root for messages: exact when rational, else `≈ x` with its isolating interval.
fn describe(iv: &RootInterval, p: &P) -> String {
    if iv.is_exact() {
        return format_scalar(&iv.lo);
    }
    if let Some(r) = rational_roots(p).into_iter().find(|r| iv.contains(r)) {
        return format_scalar(&r);
    }
    let mut iv = iv.clone();
    let _ = iv.refine(p, &Rational::from_ratio(1, 1 << 30));
    let approx = iv.root_f64(p).unwrap_or_else(|_| iv.midpoint_f64());
    format!("{approx:.6}")
}

/// Decides `r·κ < 1` and `m′ ≠ 0` on `[a, b]` for a pipe family exactly (module docs) and
/// returns the certificate.
///
/// # Errors
/// [`CanalError::ZeroTangent`] where `m′ = 0` on `[a, b]`;
/// [`CanalError::RadiusNotBelowCurvatureRadius`] naming an interval (or point) of `[a, b]`
/// where `r κ ≥ 1`; [`CanalError::DegenerateSpine`] where `W = 0` on `[a, b]`;
/// [`CanalError::InvalidArgument`] as [`pipe_regularity_polynomials`] or for `a > b`.
pub fn check_pipe_regularity(
    spine: &CanalSpine<Rational>,
    domain: (&Rational, &Rational),
) -> Result<Certificate, CanalError> {
    let (a, b) = domain;
    if a > b {
        return Err(CanalError::InvalidArgument(format!(
            "empty parameter interval [{}, {}]",
            format_scalar(a),
            format_scalar(b)
        )));
    }
    if let Some(iv) = isolate_real_roots_in(spine.weight(), a, b)?.first() {
        return Err(CanalError::DegenerateSpine(format!(
            "the spine weight W vanishes at t = {} in [{}, {}] (a point at infinity)",
            describe(iv, spine.weight()),
            format_scalar(a),
            format_scalar(b)
        )));
    }
    let (pp, f, r) = pipe_regularity_polynomials(spine)?;
    if pp.is_zero() {
        return Err(CanalError::ZeroTangent {
            at: format!(
                "every t (the spine is a point on [{}, {}])",
                format_scalar(a),
                format_scalar(b)
            ),
        });
    }
    if let Some(iv) = isolate_real_roots_in(&pp, a, b)?.first() {
        return Err(CanalError::ZeroTangent {
            at: describe(iv, &pp),
        });
    }
    if f.is_zero() {
        // r κ ≡ 1: every point of the spine has curvature radius |r|
        return Err(CanalError::RadiusNotBelowCurvatureRadius {
            radius: format_scalar(&r),
            from: format_scalar(a),
            to: format_scalar(b),
            witness: format_scalar(a),
            curvature_radius: format!("{:.6}", Scalar::to_f64(&r).abs()),
        });
    }
    let mut roots = isolate_real_roots_in(&f, a, b)?;
    if roots.is_empty() && f.eval(a) > Rational::ZERO {
        return Ok(Certificate::holds(
            format!(
                "r·κ < 1 and m′ ≠ 0 for t ∈ [{}, {}] (r = {}): F = |P|⁶ − r²W⁴|P × P′|² > 0 there (no real root, F({}) > 0), P = W M′ − W′ M — no local self-intersection",
                format_scalar(a),
                format_scalar(b),
                format_scalar(&r),
                format_scalar(a)
            ),
            true,
        ));
    }
    // the gaps between the roots (and the ends) where F < 0, else a root where F = 0;
    // isolating intervals may share an endpoint (not a root): refine them first
    let width = Rational::from_ratio(1, 1 << 20);
    for iv in &mut roots {
        if !iv.is_exact() {
            iv.refine(&f, &width)?;
        }
    }
    let mut cuts: Vec<(Rational, Rational, String)> =
        vec![(a.clone(), a.clone(), format_scalar(a))];
    for iv in &roots {
        cuts.push((iv.lo.clone(), iv.hi.clone(), describe(iv, &f)));
    }
    cuts.push((b.clone(), b.clone(), format_scalar(b)));
    let curvature_radius = |t: &Rational| -> String {
        // 1/κ = r·(|P|⁶/(r²W⁴|P × P′|²))^{1/2}
        let fv = Scalar::to_f64(&f.eval(t));
        let ppv = Scalar::to_f64(&pp.eval(t));
        let rf = Scalar::to_f64(&r).abs();
        let num = ppv * ppv * ppv;
        let den = num - fv; // r²W⁴|P × P′|²
        if den <= 0.0 {
            "∞".into()
        } else {
            format!("{:.6}", rf * (num / den).sqrt())
        }
    };
    let err =
        |from: &str, to: &str, witness: &Rational| CanalError::RadiusNotBelowCurvatureRadius {
            radius: format_scalar(&r),
            from: from.to_string(),
            to: to.to_string(),
            witness: format_scalar(witness),
            curvature_radius: curvature_radius(witness),
        };
    for w in cuts.windows(2) {
        let (left, right) = (&w[0], &w[1]);
        if left.1 <= right.0 {
            let s = (left.1.clone() + right.0.clone()) / Rational::from(2);
            if f.eval(&s) < Rational::ZERO {
                return Err(err(&left.2, &right.2, &s));
            }
        }
    }
    // F ≥ 0 with a root: r κ = 1 at that parameter (a singular point of the pipe)
    let iv = roots
        .first()
        .cloned()
        .unwrap_or_else(|| RootInterval::exact(a.clone()));
    let t = describe(&iv, &f);
    Err(err(&t, &t, &iv.midpoint()))
}

/// A rational `s ≥ √x` (an `f64` guess made safe, checked exactly).
pub(crate) fn sqrt_upper(x: &Rational) -> Rational {
    let guess = Scalar::to_f64(x).sqrt() * (1.0 + 1e-12) + f64::MIN_POSITIVE;
    let mut s = Scalar::to_rational(&guess).unwrap_or(Rational::ONE);
    while s.clone() * s.clone() < *x {
        s = s.clone() * Rational::from(2) + Rational::ONE;
    }
    s
}

/// Certifies that no two parts of the pipe of radius `r` around the spine meet: since
/// session 10 the decisive check [`super::check_pipe_embedded`] (exact subdivision of the
/// double-critical pairs, `docs/math/pipes.md#global`); kept under its old name.
///
/// # Errors
/// As [`super::check_pipe_embedded`].
pub fn check_pipe_global(
    spine: &CanalSpine<Rational>,
    domain: (&Rational, &Rational),
) -> Result<Certificate, CanalError> {
    super::self_intersection::check_pipe_embedded(spine, domain)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    fn parabola(r: Rational) -> CanalSpine<Rational> {
        // m = (t, t², 0): κ(0) = 2, the least radius of curvature is 1/2 (at t = 0)
        CanalSpine::polynomial(
            [
                Poly::from_ints(&[0, 1]),
                Poly::from_ints(&[0, 0, 1]),
                Poly::zero(),
            ],
            Poly::constant(r),
        )
    }

    #[test]
    fn parabola_pipe_is_regular_below_the_least_curvature_radius() {
        let (a, b) = (q(-1, 1), q(1, 1));
        let c = check_pipe_regularity(&parabola(q(49, 100)), (&a, &b)).expect("regular");
        assert!(c.holds && c.exact, "{c:?}");
        // F = (1 + 4t²)³ − 4r²
        let (pp, f, r) = pipe_regularity_polynomials(&parabola(q(1, 4))).expect("polys");
        assert_eq!(r, q(1, 4));
        assert_eq!(pp, Poly::from_ints(&[1, 0, 4]));
        assert_eq!(f, &pp.pow(3) - &Poly::constant(q(1, 4)));
    }

    #[test]
    fn parabola_pipe_too_thick_names_the_interval() {
        let (a, b) = (q(-1, 1), q(1, 1));
        // r = 1: r κ ≥ 1 for |t| ≤ √((4^{1/3} − 1)/4) ≈ 0.383210
        match check_pipe_regularity(&parabola(q(1, 1)), (&a, &b)) {
            Err(CanalError::RadiusNotBelowCurvatureRadius {
                from,
                to,
                witness,
                curvature_radius,
                ..
            }) => {
                assert_eq!(from, "-0.383210");
                assert_eq!(to, "0.383210");
                assert_eq!(witness, "0");
                assert_eq!(curvature_radius, "0.500000");
            }
            other => panic!("{other:?}"),
        }
        // r = 1/2 touches: r κ = 1 exactly at t = 0
        match check_pipe_regularity(&parabola(q(1, 2)), (&a, &b)) {
            Err(CanalError::RadiusNotBelowCurvatureRadius { from, to, .. }) => {
                assert_eq!((from.as_str(), to.as_str()), ("0", "0"));
            }
            other => panic!("{other:?}"),
        }
        // away from the vertex the same radius is fine
        let c = check_pipe_regularity(&parabola(q(1, 2)), (&q(1, 10), &b)).expect("regular");
        assert!(c.holds);
    }

    #[test]
    fn cusp_is_a_zero_tangent() {
        let s = CanalSpine::polynomial(
            [
                Poly::from_ints(&[0, 0, 1]),
                Poly::from_ints(&[0, 0, 0, 1]),
                Poly::zero(),
            ],
            Poly::constant(q(1, 10)),
        );
        match check_pipe_regularity(&s, (&q(-1, 1), &q(1, 1))) {
            Err(CanalError::ZeroTangent { at }) => assert_eq!(at, "0"),
            other => panic!("{other:?}"),
        }
        // on [1/2, 1] the cusp is outside
        assert!(check_pipe_regularity(&s, (&q(1, 2), &q(1, 1))).is_ok());
    }

    #[test]
    fn rational_spine_circle_has_constant_curvature() {
        // the circle (1 − t², 2t, 0)/(1 + t²) of radius 1: r κ < 1 iff |r| < 1
        let w = Poly::from_ints(&[1, 0, 1]);
        let fam = |r: Rational| {
            CanalSpine::new(
                w.clone(),
                [
                    Poly::from_ints(&[1, 0, -1]),
                    Poly::from_ints(&[0, 2]),
                    Poly::zero(),
                ],
                w.scale(&r),
            )
            .expect("family")
        };
        let (a, b) = (q(0, 1), q(1, 1));
        assert!(check_pipe_regularity(&fam(q(99, 100)), (&a, &b)).is_ok());
        assert!(matches!(
            check_pipe_regularity(&fam(q(-1, 1)), (&a, &b)),
            Err(CanalError::RadiusNotBelowCurvatureRadius { .. })
        ));
        assert!(matches!(
            check_pipe_regularity(&fam(q(3, 2)), (&a, &b)),
            Err(CanalError::RadiusNotBelowCurvatureRadius { .. })
        ));
    }

    #[test]
    fn global_check_separates_far_parts_and_refuses_a_near_loop() {
        // the parabola is far from itself: certified for a thin pipe
        let (a, b) = (q(-1, 1), q(1, 1));
        let c = check_pipe_global(&parabola(q(1, 20)), (&a, &b)).expect("apart");
        assert!(c.holds && c.exact, "{c:?}");
        // a loop: m = (t² − 1, t³ − t, 0) crosses itself at t = ±1 (the point (0, 0))
        let s = CanalSpine::polynomial(
            [
                Poly::from_ints(&[-1, 0, 1]),
                Poly::from_ints(&[0, -1, 0, 1]),
                Poly::zero(),
            ],
            Poly::constant(q(1, 50)),
        );
        let (a, b) = (q(-3, 2), q(3, 2));
        assert!(check_pipe_regularity(&s, (&a, &b)).is_ok());
        match check_pipe_global(&s, (&a, &b)) {
            Err(CanalError::PipeSelfIntersects { distance, .. }) => {
                let d: f64 = distance.parse().expect("number");
                assert!(d < 1e-6, "{distance}");
            }
            other => panic!("{other:?}"),
        }
        // the same loop on [−1/2, 3/2] (one crossing parameter only): apart
        let c = check_pipe_global(&s, (&q(-1, 2), &b)).expect("apart");
        assert!(c.holds);
    }
}
