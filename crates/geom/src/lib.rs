//! # rcagd-geom
//!
//! Rational Bézier curves and tensor-product patches in homogeneous form, NURBS,
//! tessellation, and certificate helpers. Depends only on `rcagd-algebra`.

pub mod curve;
pub mod error;
pub mod patch;

pub use curve::BezierCurve;
pub use error::GeomError;
pub use patch::BezierPatch;
