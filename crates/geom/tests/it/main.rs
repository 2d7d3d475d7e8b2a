//! The integration tests of `rcagd-geom`, in one test binary (one link instead of one per file;
//! see docs/ARCHITECTURE.md, "Tests").

mod bezier_props;
mod nurbs_tess;
mod pole_free;
