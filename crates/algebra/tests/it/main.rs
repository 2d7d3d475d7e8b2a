//! The integration tests of `rcagd-algebra`, in one test binary (one link instead of one per file;
//! see docs/ARCHITECTURE.md, "Tests").

mod big_integers;
mod conic_point_props;
mod conic_point_rows;
mod factor_ext;
mod fields_linalg;
mod plane_positivity;
mod roots_resultants;
