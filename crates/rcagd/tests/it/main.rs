//! The integration tests of `rcagd`, in one test binary (one link instead of one per file;
//! see docs/ARCHITECTURE.md, "Tests").

mod canal_cyclographic;
mod canal_props;
mod cyclide;
mod laguerre_props;
mod laguerre_query;
mod line_generation;
mod lines_props;
mod ndim;
mod ph_planar;
mod ph_preimage;
mod ph_props;
mod pn_laguerre;
mod pn_props;
mod primitives;
mod quadric_props;
mod quadric_query;
mod seed000_examples;
mod seed001_examples;
mod seed003_examples;
mod seed003_sphere_families;
mod seed004_conic_examples;
mod seed004_laguerre_examples;
mod seed004_pn_examples;
