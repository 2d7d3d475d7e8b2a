//! # rcagd-algebra
//!
//! The exact algebra that every rcagd construction is built on: the scalar traits
//! ([`Ring`], [`Field`], [`Scalar`]) with implementations for `f64` and the exact
//! rational [`Rational`], exact parsing of user numbers, quadratic extensions,
//! complex numbers and quaternions, univariate polynomials in power and Bernstein
//! form, multivariate polynomials, resultants, real-root isolation, exact linear
//! algebra, and certificates ([`Certificate`]).
//!
//! Layer rule: this crate depends on nothing else in rcagd.

pub mod bernstein;
pub mod budget;
pub mod certificate;
pub mod complex;
pub mod conic_point;
pub mod double_double;
pub mod error;
pub mod factor;
pub mod factor_ext;
pub mod integer;
pub mod integer_squares;
pub mod interval;
pub mod linalg;
pub mod mpoly;
pub mod plane_positivity;
pub mod poly;
pub mod quadratic;
pub mod quaternion;
pub mod rational;
pub mod resultant;
pub mod roots;
pub mod scalar;
pub mod sum_of_squares;

pub use certificate::Certificate;
pub use complex::Complex;
pub use double_double::DoubleDouble;
pub use error::AlgebraError;
pub use linalg::{Matrix, Solution};
pub use poly::Poly;
pub use quadratic::QuadExt;
pub use quaternion::Quaternion;
pub use rational::{parse_rational, Rational};
pub use scalar::{format_poly, format_scalar, format_vector, sqrt_in_field, Field, Ring, Scalar};
