//! The cyclographic parametrization `Γ(s, t)` of Gruber §2.3 as a rational alternative when
//! the constructions in the spine parameter need a quadratic field
//! (docs/math/lines-and-canal.md, "Canal surfaces": cyclographic construction for quadratic
//! families; docs/math/sphere-families.md, "Canal surfaces by the cyclographic
//! parametrization").
//!
//! Peternell–Pottmann and Krasauskas parametrize the canal surface by the spine parameter
//! `p` and an angle; they are rational over `Q` only if `D = |ṁ|² − ṙ²` is a sum of two
//! squares over `Q(p)` — a rational point on every characteristic circle, rational in `p`.
//! The cyclographic map does not need one: for a family `k(p) = (m, r)(p)` of degree ≤ 2
//! the contact condition `⟨w(s, t), k̇(p)⟩ = 0` (`w` the isotropic direction on Ω) is linear
//! in `p`, so `p = N(s, t)/Dn(s, t)` is rational (Gruber (2.21)) and
//! `Γ(s, t) = π(k(p)) − r(p)·(w₁, w₂, w₃)/w₄` covers the whole envelope over `Q`
//! ([`QuadraticCanal`]). Its parameter rectangles are regions of Ω(s, t), not spine
//! intervals: a curve `p = const` is a conic of the `(s, t)` plane without a rational
//! parametrization in `p` exactly when `D` does not split — which is why the spine-parameter
//! constructions fail there.
//!
//! [`canal_surface_rational`] tries the spine-parameter constructions
//! ([`canal_surface_pole_free`]) first and falls back to `Γ` when they need `Q(√d)`.

use super::envelope::{CanalBuild, CanalOptions, CanalSurface, QuadraticCanal};
use super::frame::{canal_surface_pole_free, EXPORT_SPLITS};
use super::{CanalError, CanalSpine};
use crate::error::format_scalar;
use crate::Certified;
use rcagd_algebra::{Certificate, Rational};
use rcagd_geom::weight_sign::{split_patches_adaptive, SignRule};
use rcagd_geom::BezierPatch;

/// A canal surface over `Q`: in the spine parameter, or by the cyclographic
/// parametrization when the former needs a quadratic field.
#[derive(Debug, Clone)]
pub enum RationalCanal {
    /// Peternell–Pottmann or Krasauskas, over `Q` ([`canal_surface_pole_free`]).
    Spine(Box<CanalSurface<Rational>>),
    /// `Γ(s, t)` on a rectangle of Ω(s, t) (module docs).
    Cyclographic(Box<CyclographicCanal>),
}

/// The cyclographic parametrization of a quadratic family on a rectangle of Ω(s, t).
#[derive(Debug, Clone)]
pub struct CyclographicCanal {
    surface: QuadraticCanal<Rational>,
    radicand: Rational,
    patches: Vec<BezierPatch<Rational>>,
}

impl CyclographicCanal {
    /// `Γ(s, t)` and its reparametrization.
    pub fn surface(&self) -> &QuadraticCanal<Rational> {
        &self.surface
    }

    /// The radicand `d` of the field `Q(√d)` the spine-parameter constructions need.
    pub fn radicand(&self) -> &Rational {
        &self.radicand
    }

    /// The Bézier pieces of `Γ` on the rectangle, every Bernstein weight positive.
    pub fn patches(&self) -> &[BezierPatch<Rational>] {
        &self.patches
    }
}

impl Certified for CyclographicCanal {
    /// The identities of [`QuadraticCanal`] (`Γ` lies on the sphere `k(p(s, t))` and on its
    /// characteristic plane; `w ⊥ k̇`), and the positive weights of the pieces.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.surface.certify();
        let n = self.patches.len();
        let ok = self
            .patches
            .iter()
            .all(|p| p.weights().iter().all(|w| *w > Rational::from(0)));
        out.push(Certificate::decide(
            format!(
                "every Bernstein weight of the {n} pieces of Γ is > 0 (no pole on the rectangle)"
            ),
            ok,
            true,
            || "a piece has a weight ≤ 0".to_string(),
        ));
        out
    }
}

/// The canal surface of `spine` over `Q`: [`canal_surface_pole_free`] when it is rational;
/// when it needs `Q(√d)` and the family is polynomial of degree ≤ 2, the cyclographic
/// parametrization `Γ(s, t)` on `cyclographic_domain = [s₀, s₁, t₀, t₁]` (module docs).
///
/// # Errors
/// The errors of [`canal_surface_pole_free`]; [`CanalError::IrrationalSplit`] when the
/// spine-parameter constructions need `Q(√d)` and `Γ` does not apply (degree > 2 or a
/// non-constant weight); [`CanalError::CyclographicDomainNeeded`] when `Γ` applies but no
/// rectangle is given; [`CanalError::InvalidArgument`] for an empty rectangle or one where
/// `Γ` has a pole.
pub fn canal_surface_rational(
    spine: &CanalSpine<Rational>,
    options: &CanalOptions,
    cyclographic_domain: Option<&[Rational; 4]>,
) -> Result<RationalCanal, CanalError> {
    let radicand = match canal_surface_pole_free(spine, options)? {
        CanalBuild::Rational(s) => return Ok(RationalCanal::Spine(Box::new(s))),
        CanalBuild::Extension { radicand, .. } => radicand,
    };
    let Ok(surface) = QuadraticCanal::from_spine(spine) else {
        return Err(CanalError::IrrationalSplit {
            radicand: format_scalar(&radicand),
        });
    };
    let Some([s0, s1, t0, t1]) = cyclographic_domain else {
        return Err(CanalError::CyclographicDomainNeeded {
            radicand: format_scalar(&radicand),
        });
    };
    if s0 >= s1 || t0 >= t1 {
        return Err(CanalError::InvalidArgument(format!(
            "empty rectangle [{}, {}] × [{}, {}] of Ω(s, t)",
            format_scalar(s0),
            format_scalar(s1),
            format_scalar(t0),
            format_scalar(t1)
        )));
    }
    let patch = surface.patch((s0, s1), (t0, t1))?;
    let split = split_patches_adaptive(vec![patch], SignRule::Positive, EXPORT_SPLITS)
        .map_err(|e| CanalError::InvalidArgument(e.to_string()))?;
    if split.failed > 0 {
        return Err(CanalError::InvalidArgument(format!(
            "Γ(s, t) has a pole on the rectangle [{}, {}] × [{}, {}]: its weight Dn(s, t)²·(1 + s² + t²) vanishes where the spine parameter p = N/Dn is infinite — choose a rectangle off the curve Dn = 0",
            format_scalar(s0),
            format_scalar(s1),
            format_scalar(t0),
            format_scalar(t1)
        )));
    }
    Ok(RationalCanal::Cyclographic(Box::new(CyclographicCanal {
        surface,
        radicand,
        patches: split.pieces,
    })))
}
