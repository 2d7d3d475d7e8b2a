//! Line geometry of projective 3-space in Plücker coordinates (Gruber §1.1;
//! docs/math/lines-and-canal.md, "Plücker coordinates" and "Complexes, congruences, reguli").
//!
//! Conventions (used throughout rcagd):
//!
//! * a **point** is a homogeneous vector `p = (p₀, p₁, p₂, p₃)`, weight first; its affine
//!   position is `(p₁, p₂, p₃)/p₀`;
//! * a **plane** is a coordinate vector `u = (u₀, u₁, u₂, u₃)` of the plane
//!   `u₀x₀ + u₁x₁ + u₂x₂ + u₃x₃ = 0`, i.e. `u₀ + u₁x + u₂y + u₃z = 0` in affine coordinates;
//! * a **line** `l = p ∧ q = (l₁, l₂, l₃; l₄, l₅, l₆) = (l₀₁, l₀₂, l₀₃; l₂₃, l₃₁, l₁₂)` with
//!   `l_ik = p_i q_k − p_k q_i` (Gruber (1.1)); for affine points `(l₁, l₂, l₃)` is the
//!   direction `q − p` and `(l₄, l₅, l₆) = p × (q − p)` the moment vector;
//! * the **Klein quadric** (Plücker identity, Gruber (1.3)/(1.6)) is
//!   `l₁l₄ + l₂l₅ + l₃l₆ = 0`, and its polar (symmetric bilinear) form is the
//!   *reciprocal product* `Ω(g, h) = ⟨ḡ, h⟩ + ⟨g, h̄⟩ = g₁h₄ + g₂h₅ + g₃h₆ + g₄h₁ + g₅h₂ + g₆h₃`
//!   (Gruber (1.10)): two lines meet (or are parallel) iff `Ω(g, h) = 0`, and a line lies
//!   in the linear complex `C` iff `Ω(c, x) = 0` (Gruber (1.11)).
//!
//! Map of the module:
//!
//! * [`plucker`]: [`Line`] (from two points, two planes, point and direction, coordinates),
//!   the incidence matrix (1.7), points and planes of a line (the `sᵢ` of docs/math/lines-and-canal.md, "Plücker coordinates"), meeting,
//!   intersection point and joining plane, the polarity `E` of docs/math/lines-and-canal.md, "Complexes, congruences, reguli" (1.19);
//! * [`complex`]: [`LinearComplex`]: regular and singular complexes, the null polarity,
//!   axis and parameter;
//! * [`congruence`]: [`LinearCongruence`] = the intersection of two linear complexes (a line
//!   net, Gruber §1.1.6), classified as hyperbolic, elliptic, parabolic or degenerate with
//!   its focal lines, and the fibration `point ↦ the net line through it`;
//! * [`regulus`]: [`Regulus`] through three pairwise skew lines (both rulings as rational
//!   families with the carrier quadric) and [`common_transversals`] of four lines;
//! * [`net`]: [`LineNet`], regular line nets given by their axes (hyperbolic, elliptic,
//!   parabolic) with their fibration, the input of the sphere-family envelopes.
//!
//! Every construction is generic over [`Scalar`]; where a square root is needed (focal
//! lines of a hyperbolic or elliptic congruence, common transversals) the result lives in
//! [`SqrtScalar::Ext`]: the quadratic extension [`QuadExt`] for exact rationals, `f64` for
//! `f64`.

pub mod complex;
pub mod congruence;
pub mod drawing;
pub mod generation;
pub mod net;
pub mod order_bound;
pub mod order_one;
pub mod parametrized;
pub mod plucker;
pub mod regulus;
pub mod regulus_patch;

pub use complex::LinearComplex;
pub use congruence::{net_line, CongruenceKind, FocalLines, LinearCongruence};
pub use drawing::{
    congruence_strips, point_family_patches, CongruenceDrawing, CongruenceSpec, DrawError,
};
pub use generation::{regulus_meeting, GeneratedNet, Generation, GenerationError, LineFamily};
pub use net::{AxisPosition, ComplexPointRow, LineNet, NetError, NetKind, PointRow};
pub use order_one::{
    focal_coefficients, focal_points, order_and_class_decided, CubicChordCongruence,
    OneNCongruence, OrderClass, OrderOneError,
};
pub use parametrized::ParametrizedCongruence;
pub use plucker::{reciprocal_product, Line, LineOrigin};
pub use regulus::{
    common_transversals, common_transversals_along, common_transversals_recorded,
    CommonTransversals, Regulus, TransversalCount, TransversalRoute,
};

use crate::error::format_scalar;
use rcagd_algebra::quadratic::sqrt_in_extension;
use rcagd_algebra::{QuadExt, Rational, Scalar};
use thiserror::Error;

/// Errors of the line-geometry module. Every variant names the violated precondition.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum LineError {
    /// Two points that must span a line coincide (projectively): `p ∧ q = 0`.
    #[error("coincident points: {0} and {1} span no line (p ∧ q = 0)")]
    CoincidentPoints(String, String),
    /// Two planes that must meet in a line coincide: `u ∧ v = 0`.
    #[error("coincident planes: {0} and {1} meet in no line (u ∧ v = 0)")]
    CoincidentPlanes(String, String),
    /// A coordinate vector that must be non-zero is zero (a point, plane, direction or line).
    #[error("zero vector: {0}")]
    ZeroVector(String),
    /// Six numbers that must be Plücker coordinates violate the Klein quadric.
    #[error("not a line: l₁l₄ + l₂l₅ + l₃l₆ = {residual} ≠ 0 (Klein quadric, Gruber (1.3))")]
    NotOnKleinQuadric {
        /// The value of `l₁l₄ + l₂l₅ + l₃l₆`.
        residual: String,
    },
    /// Two lines that must meet are skew.
    #[error("the lines are skew: reciprocal product Ω(g, h) = {0} ≠ 0 (Gruber (1.10))")]
    Skew(String),
    /// Two lines that must be skew meet (or are parallel).
    #[error("lines {0} and {1} meet (Ω = 0) but must be skew")]
    NotSkew(String, String),
    /// Two lines that must differ are the same line.
    #[error("the lines coincide: {0}")]
    SameLine(String),
    /// A point lies on a line (or axis) where it must not.
    #[error("the point {0} lies on the line {1}")]
    PointOnLine(String, String),
    /// A line lies in a plane where it must not.
    #[error("the line {0} lies in the plane {1}")]
    LineInPlane(String, String),
    /// Two linear complexes that must span a pencil are proportional.
    #[error("dependent linear complexes: {0}")]
    DependentComplexes(String),
    /// A point where the fibration of a congruence is undefined (a point of a focal line,
    /// the vertex of a singular net).
    #[error("singular point of the congruence: {0}")]
    SingularPoint(String),
    /// The operation needs a regular (resp. singular) linear complex.
    #[error("{0}")]
    ComplexKind(String),
    /// An algebra failure underneath.
    #[error(transparent)]
    Algebra(#[from] rcagd_algebra::AlgebraError),
}

/// A scalar whose square roots live in a known extension: exact rationals use the real
/// quadratic field [`QuadExt`] (`√q ∈ Q(√s)`, `s` the square-free part of `q`), `f64` and
/// [`rcagd_algebra::DoubleDouble`] use themselves. Focal lines of hyperbolic congruences
/// and common transversals of four lines are defined over `Ext`.
pub trait SqrtScalar: Scalar {
    /// The scalar type of the square roots.
    type Ext: Scalar;
    /// The embedding `F → Ext`.
    fn embed(&self) -> Self::Ext;
    /// `√self` for `self ≥ 0`, `None` for negative values.
    fn sqrt_ext(&self) -> Option<Self::Ext>;
}

impl SqrtScalar for f64 {
    type Ext = f64;
    fn embed(&self) -> f64 {
        *self
    }
    fn sqrt_ext(&self) -> Option<f64> {
        (*self >= 0.0).then(|| self.sqrt())
    }
}

impl SqrtScalar for rcagd_algebra::DoubleDouble {
    type Ext = rcagd_algebra::DoubleDouble;
    fn embed(&self) -> Self {
        *self
    }
    fn sqrt_ext(&self) -> Option<Self> {
        self.sqrt()
    }
}

impl SqrtScalar for Rational {
    type Ext = QuadExt;
    fn embed(&self) -> QuadExt {
        QuadExt::rational(self.clone())
    }
    fn sqrt_ext(&self) -> Option<QuadExt> {
        sqrt_in_extension(self).ok()
    }
}

/// Formats a homogeneous vector for messages.
pub(crate) fn fmt_vec<F: Scalar>(v: &[F]) -> String {
    let parts: Vec<String> = v.iter().map(format_scalar).collect();
    format!("({})", parts.join(", "))
}

/// `Σ aᵢbᵢ`.
pub(crate) fn dot<F: rcagd_algebra::Ring>(a: &[F], b: &[F]) -> F {
    a.iter()
        .zip(b)
        .fold(F::zero(), |acc, (x, y)| acc + x.clone() * y.clone())
}

/// `true` if every entry is zero (exactly for exact scalars; `f64` compares with zero too:
/// callers that need tolerances use [`is_small`]).
pub(crate) fn all_zero<F: Scalar>(v: &[F]) -> bool {
    v.iter().all(|x| x.is_zero())
}

/// Zero test with the relative tolerance of the `f64` certificates (exact for exact scalars).
pub(crate) fn is_small<F: Scalar>(x: &F, scale: f64) -> bool {
    if F::EXACT {
        x.is_zero()
    } else {
        let v = x.to_f64();
        v.is_finite() && v.abs() <= rcagd_geom::certify::F64_RELATIVE_TOLERANCE * scale.max(1.0)
    }
}

/// The largest `|vᵢ|` as `f64` (a scale for tolerance tests).
pub(crate) fn scale_of<F: Scalar>(v: &[F]) -> f64 {
    v.iter().map(|x| x.to_f64().abs()).fold(0.0, f64::max)
}

/// `true` if the two vectors are proportional (all 2×2 minors vanish). Zero vectors are
/// proportional to everything.
pub(crate) fn proportional<F: Scalar>(a: &[F], b: &[F]) -> bool {
    let s = scale_of(a) * scale_of(b);
    for i in 0..a.len() {
        for j in i + 1..a.len() {
            let m = a[i].clone() * b[j].clone() - a[j].clone() * b[i].clone();
            if !is_small(&m, s) {
                return false;
            }
        }
    }
    true
}
