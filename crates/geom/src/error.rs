//! Typed errors of the geometry layer.

use rcagd_algebra::AlgebraError;
use thiserror::Error;

/// Errors raised by the geometry layer. Every variant names the violated precondition.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum GeomError {
    /// No control points, or a net with an empty row.
    #[error("empty control net: {0}")]
    Empty(String),
    /// Control points of different dimensions, or a flat array whose length does not
    /// fit the declared degree and dimension.
    #[error("dimension mismatch: {0}")]
    Dimension(String),
    /// Degrees that do not fit together (e.g. joining curves of different degree).
    #[error("degree mismatch: {0}")]
    Degree(String),
    /// A parameter outside its domain, or an empty parameter interval.
    #[error("parameter out of range: {0}")]
    Parameter(String),
    /// A weight that is zero or negative where the operation needs positive weights,
    /// or a point at infinity where a finite point is needed.
    #[error("bad weight: {0}")]
    Weight(String),
    /// A malformed knot vector.
    #[error("bad knot vector: {0}")]
    Knots(String),
    /// An algebraic failure underneath.
    #[error(transparent)]
    Algebra(#[from] AlgebraError),
}
