//! # rcagd-geom
//!
//! Rational Bézier curves and tensor-product patches in homogeneous form, NURBS,
//! tessellation, and certificate helpers. Depends only on `rcagd-algebra`.

pub mod certify;
pub mod curve;
pub mod error;
pub mod grid;
pub mod nurbs;
pub mod patch;
pub mod polymap;
pub mod tessellate;
pub mod weight_sign;

pub use curve::BezierCurve;
pub use error::GeomError;
pub use patch::BezierPatch;
