//! PN surfaces: rational surfaces with a rational unit normal field, hence rational offsets
//! at every rational distance (Peternell, ch. 4 and §5.4–§5.5; corrected formulas
//! in docs/math/laguerre-pn.md).
//!
//! Every PN surface here is a [`PnSurface`]: polynomials in the parameters `(u, v)` for the
//! homogeneous point `(W, X₁, X₂, X₃)`, the unit normal `(N₁, N₂, N₃)/N₀` with
//! `N₁² + N₂² + N₃² ≡ N₀²`, the support function `h` of the oriented tangent plane
//! `h + n·x = 0`, and a cofactor `K` with `W = N₀ K`. The offset at distance `d` is
//! `x + d n = (X + d K N)/W` — the same denominator, so the same degree
//! ([`PnSurface::offset`]); its support function is `h − d` (docs/math/laguerre-pn.md#conventions).
//!
//! * [`isotropic`]: the isotropic model `I³` (Theorem 4.3): any rational surface
//!   `y(u,v) = (A/C, B/C, G/D)` of `I³` gives a PN surface by the closed formula of
//!   Theorem 4.3/4.4 (docs/math/laguerre-pn.md#closed-formula, generalized here from graphs
//!   to parametrized surfaces); graphs `y₃ = F(u, v)`, the dual form (4.1)/(4.4), the
//!   support-function form (4.2), isotropic spheres (cycles), parabolic Dupin cyclides (`F`
//!   quadratic), the paraboloid `F = pS/(S − 1)`;
//! * [`support`]: any rational field of oriented planes with a Pythagorean normal
//!   (`h`, `N`) → points `e ∩ e_u ∩ e_v` (§4.1), the anticaustic of a rational mirror for
//!   parallel light (Theorem 4.1, (3.18) corrected), the Laguerre image of a PN surface
//!   (Theorem 4.2);
//! * [`offset`]: offsets with their certificates, the offset in the isotropic model
//!   `F ↦ F − (d/2)(S + 1)`, the principal radii (distances at which an offset
//!   degenerates) and where an offset degenerates on a parameter rectangle;
//! * [`ruled`]: envelopes of rational families of cones of revolution (Theorem 4.5) —
//!   non-developable ruled surfaces (Cor. 4.2), canal surfaces (Cor. 4.3), quadrics and
//!   their offsets (Theorem 4.6, §4.7), surfaces of revolution with a PH profile — and
//!   the offsets of ruled 2-manifolds in `Rⁿ` (Theorem 5.2);
//! * [`modeling`]: the modeling scheme of §4.4: Hermite data (points with oriented
//!   planes) → gradient data in `I³` → C¹ Powell–Sabin quadratic spline → piecewise
//!   parabolic Dupin cyclides;
//! * [`focal`]: the focal surfaces of a PN surface (its curvature-sphere γ-surfaces,
//!   Peternell §3.9) and the sections `Γ(φ) ∩ π` of its γ-hypersurface (offsets for
//!   `π ∥ R³`);
//! * [`planar`]: the planar case — rational PH (PN) curves from the isotropic model of
//!   the plane, their offsets, and the agreement with [`crate::ph`].
//!
//! All constructions are generic over [`rcagd_algebra::Scalar`] and implement
//! [`crate::Certified`]: the unit normal as the identity `N·N ≡ N₀²`, the normal
//! orthogonal to both partial derivatives, the point on its tangent plane, and for offsets
//! `x_d − x ≡ d n`; exact polynomial identities over `Rational`.

pub mod developable;
pub mod focal;
pub mod hypercyclide;
pub mod isotropic;
pub mod modeling;
pub mod motion;
pub mod offset;
pub mod planar;
pub(crate) mod poly;
pub mod reducing_frame;
pub mod ruled;
pub mod support;
pub mod surface;
pub mod two_sheet;

pub use isotropic::IsotropicSurface;
pub use offset::PnOffset;
pub use poly::{Domain, RatFn};
pub use surface::PnSurface;

use crate::laguerre::LaguerreError;
use rcagd_algebra::AlgebraError;
use rcagd_geom::GeomError;
use thiserror::Error;

/// Errors of the PN constructions. Every variant names the violated precondition and,
/// where the failure has a location, the parameter point.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum PnError {
    /// An input that violates a documented precondition.
    #[error("invalid input: {0}")]
    InvalidInput(String),
    /// A normal field that must be Pythagorean is not: `N₁² + N₂² + N₃² ≢ N₀²`.
    #[error("the normal field is not a rational unit normal: {0}")]
    NotUnitNormal(String),
    /// The Gauss map is degenerate (`J ≡ 0` or `det(N_u, N_v, N) ≡ 0`): the planes form a
    /// one-parameter family (a developable surface); `e ∩ e_u ∩ e_v` is not a point.
    #[error("the tangent planes are developable (degenerate Gauss map): {0}")]
    Developable(String),
    /// A developable surface without an edge of regression `e ∩ ė ∩ ë`: a cylinder
    /// (`det(P, Ṗ, P̈) ≡ 0`, the edge is at infinity) or a cone (the edge is the vertex).
    #[error("no edge of regression: {0}")]
    NoEdgeOfRegression(String),
    /// The parametrization is singular or undefined at a parameter point of the domain.
    #[error("{what} at (u, v) = {at}")]
    Singular {
        /// What vanishes (`"W = 0: point at infinity"`, `"x_u × x_v = 0"`).
        what: String,
        /// The parameter point (exact for exact scalars).
        at: String,
    },
    /// A plane curve is singular or undefined at a parameter `t` of its interval (for an
    /// offset: the distance equals the radius of curvature there).
    #[error("{what} at t = {at}")]
    CurveSingular {
        /// What vanishes.
        what: String,
        /// The parameter (exact for exact scalars), or the interval where it lies.
        at: String,
    },
    /// The offset at distance `d` is singular at a parameter point: `d` is a principal
    /// radius of curvature there.
    #[error("the offset at distance {distance} degenerates at (u, v) = {at}: {detail}")]
    OffsetDegenerates {
        /// The distance, formatted.
        distance: String,
        /// The parameter point.
        at: String,
        /// What was found (a zero, or a sign change between two points).
        detail: String,
    },
    /// A rational point (sum of two squares, point on a conic family) needed by the
    /// construction was not found over Q (docs/math/laguerre-pn.md#conventions).
    #[error("no rational solution found: {0}")]
    NoRationalPoint(String),
    /// A cycle curve whose chords or tangents are isotropic in the cyclographic model
    /// (`|m₁ − m₂|² ≡ (r₁ − r₂)²`, or `|ṁ|² ≡ ṙ²` for a canal surface): the two cycles
    /// touch each other in oriented contact for every `t`, and they span no real cone of
    /// revolution (Peternell §3.3, (4.8): the isotropic circle `d′(t)` has radius 0).
    #[error("isotropic cycle curve: {0}")]
    IsotropicCycles(String),
    /// Data the modeling scheme of §4.4 cannot match.
    #[error("the modeling scheme cannot match the data: {0}")]
    ModelingData(String),
    /// A failure of the Laguerre-geometry layer.
    #[error(transparent)]
    Laguerre(#[from] LaguerreError),
    /// A failure of the geometry layer.
    #[error(transparent)]
    Geom(#[from] GeomError),
    /// A failure of the algebra layer.
    #[error(transparent)]
    Algebra(#[from] AlgebraError),
}
