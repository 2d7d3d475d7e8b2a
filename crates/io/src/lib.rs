//! # rcagd-io
//!
//! Exporters for rcagd objects:
//! * [`model`]: the exchange model, [`Object`] (name, op, params, exact [`Geometry`],
//!   certificates);
//! * [`quantity`]: named exact values an op returns besides geometry (rationals,
//!   `a + b√d`, polynomials, isolated real roots, vectors);
//! * [`json`]: JSON per the user-facing contract (exact `"p/q"` control points and floats);
//! * [`obj`]: Wavefront OBJ of triangle meshes (with normals) and polylines;
//! * [`svg`]: SVG pictures of curves and patches;
//! * [`report`]: `report.json` and a self-contained `index.html`;
//! * [`error`]: the typed [`IoError`].
//!
//! Layer rule: depends on `rcagd-algebra` and `rcagd-geom` only.

pub mod balance;
pub mod error;
pub mod gltf;
pub mod iges;
pub mod iges_read;
pub mod json;
pub mod mesh;
pub mod model;
pub mod ndim;
pub mod obj;
pub mod ply;
pub mod png;
pub mod quantity;
pub mod raster;
pub mod report;
pub mod spine;
pub mod step;
pub mod step_read;
pub mod stl;
pub mod svg;

pub use error::IoError;
pub use json::{object_to_json, objects_to_json};
pub use model::{Geometry, Object};
pub use report::{write_report, FileLink, ReportEntry};
pub use svg::{curves_svg, geometry_svg, object_svg, patches_svg, PatchStyle, SvgOptions, View};
