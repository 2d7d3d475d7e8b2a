//! Euclidean Laguerre geometry (Peternell, ch. 3; corrected formulas in
//! docs/math/laguerre-pn.md): oriented planes and cycles (oriented spheres, points as
//! cycles of radius 0), their oriented contact, the cyclographic, Blaschke, isotropic and
//! dual isotropic models with the maps between them, and Laguerre transformations —
//! offsetting among them, as the dilatation `r ↦ r + d`.
//!
//! * [`models`]: [`OrientedPlane`], [`Cycle`], [`IsotropicSphere`], the Lorentz product
//!   of the cyclographic model, and every model map with its inverse;
//! * [`transform`]: [`LaguerreMap`] — a pe similarity `x ↦ a + λ A x` of the cyclographic
//!   model `R⁴` (`AᵀEA = E`, `E = diag(1,1,1,−1)`, Peternell (3.8)/(3.9)) acting on cycles,
//!   oriented planes and points of the isotropic model; dilatations (offsets),
//!   translations, rotations, similarities and Lorentz boosts;
//! * [`query`]: questions answered exactly — a cycle or an oriented plane in every model
//!   (cyclographic, Blaschke, isotropic, dual isotropic, Möbius) and back, the
//!   isotropic-model function of an implicit quadric, the cycles of a Laguerre map.
//!
//! **Conventions (docs/math/laguerre-pn.md#conventions).** An oriented plane is `e = (e0, n)`, `|n| = 1`, with
//! point set `e0 + n·x = 0`; a cycle `(m; r)` has signed radius `r`. Oriented contact is
//! `e0 + n·m + r = 0` (3.3) with contact point `m + r n`. The offset `x ↦ x + d n` is
//! `e0 ↦ e0 − d`, i.e. `r ↦ r + d`; Peternell's printed `e0 ↦ e0 + d` ((3.15), (4.2), (5.4)) is
//! the offset by `−d` (docs/math/laguerre-pn.md#conventions).
//!
//! PN surfaces, which are the images of surfaces of the isotropic model, live in
//! [`crate::pn`]; the Laguerre image of a PN surface is
//! [`crate::pn::PnSurface::laguerre_image`].

pub mod models;
pub mod patches;
pub mod query;
pub mod transform;

pub use models::{lorentz_product, Cycle, IsotropicSphere, OrientedPlane};
pub use transform::{isotropic_dilatation, isotropic_translation, LaguerreMap};

use thiserror::Error;

/// Errors of the Laguerre-geometry module. Every variant names the violated
/// precondition; numbers are formatted exactly (`"p/q"`) for exact scalars.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum LaguerreError {
    /// A normal vector that must be a unit vector is not: `residual = |n|² − 1`.
    #[error(
        "the normal {normal} of an oriented plane must be a unit vector: |n|² − 1 = {residual}"
    )]
    NotUnitNormal {
        /// The normal, formatted.
        normal: String,
        /// `|n|² − 1`, formatted.
        residual: String,
    },
    /// An oriented plane with normal `(0, 0, 1)` has no image in the isotropic model
    /// (Peternell §3.4: it belongs to the isotropic conformal closure; rotate the frame).
    #[error("the oriented plane {0} has normal (0, 0, 1): it has no image in the isotropic model (rotate the frame)")]
    NoIsotropicImage(String),
    /// A hyperplane of the cyclographic model that must be a γ-hyperplane is not, or a
    /// point that must lie on the Blaschke cylinder does not.
    #[error("not a γ-hyperplane / Blaschke point: {0}")]
    NotLightlike(String),
    /// A matrix that must be pe-orthogonal (`AᵀEA = E`) or orthogonal is not.
    #[error("the matrix is not {kind}: residual {residual}")]
    NotOrthogonal {
        /// `"pe-orthogonal (AᵀEA = E)"` or `"orthogonal (RᵀR = I)"`.
        kind: String,
        /// The first non-zero entry of the residual, formatted.
        residual: String,
    },
    /// A cycle and a plane that must be in oriented contact are not:
    /// `residual = e0 + n·m + r`.
    #[error("the cycle and the oriented plane are not in oriented contact: e0 + n·m + r = {0}")]
    NotInContact(String),
    /// Degenerate input (zero scale factor, a point at infinity, a boost with `s² = 1`, …).
    #[error("degenerate input: {0}")]
    Degenerate(String),
    /// An `f64` input is NaN or infinite.
    #[error("input `{0}` is not a finite number")]
    NotFinite(String),
}
