//! rcagd's benchmarks live beside this file, one criterion bench per file; see
//! docs/BENCHMARKS.md for what each measures, the peers, and the commands. They build only
//! with `--features bench` (criterion and curvo stay out of `cargo test --workspace`).
