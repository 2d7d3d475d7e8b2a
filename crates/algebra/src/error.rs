//! Typed errors of the algebra layer.

use thiserror::Error;

/// Errors raised by the algebra layer. Every variant names the violated precondition.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum AlgebraError {
    /// A string could not be read as an exact number.
    #[error("not a number: {input:?} ({reason})")]
    ParseNumber { input: String, reason: String },
    /// Division by an exact zero (a zero polynomial, a zero denominator, a singular pivot).
    #[error("division by zero: {0}")]
    DivisionByZero(String),
    /// Two operands do not fit together (dimensions, degrees, extensions).
    #[error("mismatch: {0}")]
    Mismatch(String),
    /// The operation needs an argument that is not there (empty input, degree too low).
    #[error("invalid argument: {0}")]
    InvalidArgument(String),
    /// The requested value is not in the field (e.g. a square root of a non-square).
    #[error("not representable: {0}")]
    NotRepresentable(String),
}
