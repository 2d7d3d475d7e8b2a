//! # rcagd
//!
//! Exact rational constructions for CAD, generic over the scalar
//! ([`rcagd_algebra::Scalar`]: exact [`rcagd_algebra::Rational`] or `f64`). Every
//! construction returns homogeneous rational Bézier curves or patches
//! ([`rcagd_geom::BezierCurve`], [`rcagd_geom::BezierPatch`]) and implements
//! [`Certified`]: its defining property decided as an exact polynomial identity.
//!
//! Modules:
//! * [`conic`]: exact rational circle arcs ([`conic::CircleArc`], [`conic::circle_arcs`])
//!   and full circles ([`conic::full_circle`]) from the stereographic parametrization;
//! * [`cylinder`]: rational biquadratic patches on a circular cylinder
//!   ([`cylinder::CylinderPatch`]);
//! * [`error`]: the typed [`ConstructionError`].
//!
//! Layer rule: depends on `rcagd-algebra` and `rcagd-geom` only.

pub mod canal;
pub mod conic;
pub mod conic_surface;
pub mod cyclide;
pub mod cyclographic;
pub mod cylinder;
pub mod envelope;
pub mod error;
pub mod laguerre;
pub mod lines;
pub mod ndim;
pub mod ph;
pub mod pn;
pub mod quadric;

mod certs;
mod pivot;

pub use conic::{circle_arcs, full_circle, CircleArc, CircleArcs, FullCircle};
pub use cylinder::{cylinder_patches, CylinderPatch};
pub use error::ConstructionError;

use rcagd_algebra::Certificate;

/// A construction that can decide its defining properties.
///
/// For exact scalars every certificate is a proof (a polynomial identity over Q
/// checked exactly); for `f64` it is a tolerance check (`Certificate::exact == false`).
pub trait Certified {
    /// The certificates of every defining property of the construction.
    fn certify(&self) -> Vec<Certificate>;

    /// `true` if every certificate holds.
    fn all_hold(&self) -> bool {
        Certificate::all_hold(&self.certify())
    }
}
