//! # rcagd-algebra
//!
//! The exact algebra that every rcagd construction is built on: the scalar traits
//! ([`Ring`], [`Field`], [`Scalar`]) with implementations for `f64` and the exact
//! rational [`Rational`], exact parsing of user numbers, univariate polynomials
//! ([`Poly`]) and certificates ([`Certificate`]).
//!
//! Layer rule: this crate depends on nothing else in rcagd.

pub mod certificate;
pub mod error;
pub mod poly;
pub mod rational;
pub mod scalar;

pub use certificate::Certificate;
pub use error::AlgebraError;
pub use poly::Poly;
pub use rational::{parse_rational, Rational};
pub use scalar::{Field, Ring, Scalar};
