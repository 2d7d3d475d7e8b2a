//! The integration tests of `rcagd-cli`, in one test binary (one link instead of one per file;
//! see docs/ARCHITECTURE.md, "Tests").

mod analysis_ops;
mod budget;
mod canal_cyclographic_op;
mod cli;
mod common;
mod conic_ops;
mod cyclide_ops;
mod degenerate;
mod docs;
mod exchange_weights;
mod float;
mod float_geo;
mod float_pn;
mod fuzz;
mod fuzz_corpus;
mod library_first;
mod limits;
mod messages;
mod ndim;
mod pipes;
mod python_stubs;
mod quadric_ops;
mod queries;
mod sphere_family_ops;
mod sweep_ops;
mod unit;
