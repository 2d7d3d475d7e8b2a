//! Dupin cyclides as cyclographic images of pe conics (M. Peternell, "Rational
//! Parametrizations for Envelopes of Quadric Families", §3.8.1: Lemma 3.4, Prop. 3.1,
//! Prop. 3.2; our derivations in docs/math/cyclides.md).
//!
//! Map of the module:
//!
//! * [`conic`]: the pe circle `C₀ + ρ(cos θ U + sin θ V)` and the pe parabola
//!   `C₀ + tU + (t²/2)N` ([`PeConic`]), validated with named errors, and the conjugate
//!   conic of the second family of enveloped spheres;
//! * [`surface`]: [`DupinCyclide`], the rational biquadratic parametrization by the contact
//!   points of the two families with its rational unit normal, the type
//!   ([`CyclideKind`]), offsets, patches covering the whole real cyclide, certificates;
//! * [`implicit`]: the quartic (cubic) implicit equation;
//! * [`pencil`]: the dual quadrics `C`, `Ω`, `D` (and `P`) of the pencil `λC + μΩ`
//!   (Prop. 3.1, 3.2) with the certificates that `D` is singular and the cyclide's tangent
//!   planes are common tangent hyperplanes of the pencil;
//! * [`spheres`]: the cyclide enveloping the spheres tangent to three given spheres.

pub mod blend;
pub mod conic;
pub mod implicit;
pub mod pe;
pub mod pencil;
pub mod route;
pub mod spheres;
pub mod surface;

pub use blend::{blend_cones, fitting_contact_sphere, CyclideBlend};
pub use conic::{CycleCurve, PeConic};
pub use pencil::{DualPencil, PencilMember};
pub use route::Route;
pub use spheres::{from_three_spheres, from_three_spheres_along, three_spheres_route};
pub use surface::{CyclideKind, DupinCyclide};

use thiserror::Error;

/// Errors of the cyclide constructions; every variant names the violated precondition.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum CyclideError {
    /// The pe circle has radius 0 (or the parabola degenerates to a line).
    #[error("pe circle of radius 0: {0}")]
    ZeroRadius(String),
    /// The given pair is not pe-orthonormal (or the parabola data not in a γ-plane).
    #[error("not pe-orthonormal: {0}")]
    NotOrthonormal(String),
    /// The conic has isotropic (or timelike) tangents: no real envelope there.
    #[error("spine with isotropic tangents: {0}")]
    IsotropicTangents(String),
    /// The data describe no surface (all cycles are points, …).
    #[error("degenerate cyclide: {0}")]
    Degenerate(String),
    /// Three spheres in a position without a cyclide of tangent spheres.
    #[error("three spheres in degenerate position: {0}")]
    DegenerateSpheres(String),
    /// The axes of the two cones of a blend are skew (their lines in `R^{3,1}` are not
    /// coplanar): no cyclide blend exists.
    #[error("skew axes: {0}")]
    SkewAxes(String),
    /// The data of a cyclide blend admit no pe circle (unequal tangent lengths, a
    /// non-Euclidean plane, coinciding lines).
    #[error("no cyclide blend: {0}")]
    NoBlend(String),
    /// A square root the construction needs is not in the scalar field.
    #[error("not rational over the input field: {0}")]
    NotRational(String),
    /// Any other invalid argument.
    #[error("invalid argument: {0}")]
    InvalidArgument(String),
}
