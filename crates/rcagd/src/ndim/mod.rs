//! The n-dimensional constructions of Peternell, "Rational Parametrizations for Envelopes
//! of Quadric Families", chapter 5 and §3.6 (derivations and corrections in
//! docs/math/n-dimensional.md):
//!
//! * [`hypersurface`]: PN hypersurfaces of `Rⁿ` from their tangent hyperplanes (§5.2, the
//!   dual forms (5.3)/(5.4), the isotropic model), exact offsets `h ↦ h − d`, and their
//!   3-dimensional pictures (a parameter slice projected onto three coordinates);
//! * [`anticaustic`]: anticaustics of mirror hypersurfaces and `k`-dimensional mirrors for
//!   parallel light (§3.6, (3.18) corrected), and the converse of Theorem 4.1;
//! * [`hypercone`]: envelopes of rational families of sphere-hypercones (Theorem 5.1);
//! * [`ruled`]: ruled `(k+1)`-manifolds `x = l(t) + Σ uⱼ gⱼ(t)` (5.13) with the asymptotic
//!   bundle `A(t)`, the space `T(t)`, the singular space (Lemma 5.1) or central space, and
//!   their offset hypersurfaces for every `k` (Theorem 5.2, Steps 1–3), the rational unit
//!   normal from a polynomial point on the quadric family (5.25) found by the algebra
//!   layer's conic-point engine (Prop. 5.1).
//!
//! Everything is generic over [`rcagd_algebra::Scalar`] and implements
//! [`crate::Certified`] (exact polynomial identities over `Rational`).

pub mod anticaustic;
pub mod hypercone;
pub mod hypersurface;
pub(crate) mod poly;
pub mod ruled;

pub use anticaustic::{mirror_of, Anticaustic};
pub use hypercone::HyperconeEnvelope;
pub use hypersurface::{PnHypersurface, PnHypersurfaceOffset};
pub use ruled::{RuledKind, RuledManifold, RuledOffset};

use crate::pn::PnError;
use rcagd_algebra::AlgebraError;
use rcagd_geom::GeomError;
use thiserror::Error;

/// Errors of the n-dimensional constructions; every variant names the violated
/// precondition.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum NdimError {
    /// An input that violates a documented precondition.
    #[error("invalid input: {0}")]
    InvalidInput(String),
    /// A normal field that must be Pythagorean is not (`Σ Eᵢ² ≢ L²`).
    #[error("the normal field is not a rational unit normal: {0}")]
    NotUnitNormal(String),
    /// The construction degenerates (hyperplanes without an envelope point, a manifold
    /// with only singular points, a normal space that vanishes).
    #[error("degenerate input: {0}")]
    Degenerate(String),
    /// The offset is in general not rational (Theorem 5.2's excluded cases: the normal is
    /// constant along the generators and the normal space is 1-dimensional) and this one's
    /// normal has no rational length.
    #[error("the offset is not rational: {0}")]
    NotRational(String),
    /// A rational point needed by the construction (a point on a conic family over
    /// `Q(t)`) was not found over `Q`; the message names the reason.
    #[error("no rational solution found: {0}")]
    NoRationalPoint(String),
    /// A failure of the PN layer.
    #[error(transparent)]
    Pn(#[from] PnError),
    /// A failure of the geometry layer.
    #[error(transparent)]
    Geom(#[from] GeomError),
    /// A failure of the algebra layer.
    #[error(transparent)]
    Algebra(#[from] AlgebraError),
}
