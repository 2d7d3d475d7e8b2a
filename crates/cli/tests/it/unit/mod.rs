//! Unit tests of the library's modules, through its public API (one test binary for the
//! crate: docs/ARCHITECTURE.md, "Tests").

mod build;
mod closure;
mod fuzz_float_check;
mod fuzz_gen;
mod gallery;
mod limits;
mod ops_canal;
mod ops_pn;
mod ops_poly_io;
mod recipe;
mod recipe_json;
mod recipe_toml;
mod source;
mod value;
