//! The integration tests of `rcagd-io`, in one test binary (one link instead of one per file;
//! see docs/ARCHITECTURE.md, "Tests").

mod exchange;
mod export;
mod mesh;
mod samples;
