//! The output model every op produces: [`rcagd_io::model`]'s [`Object`] (name, op,
//! params, exact [`Geometry`], certificates).

pub use rcagd_io::model::{Geometry, Object};
