//! # rcagd-cli
//!
//! The `rcagd` command-line tool as a library: recipe reading ([`recipe`]), typed
//! parameter values ([`value`]), the op registry ([`ops`]), building ([`build`]),
//! output ([`output`]) and the certified gallery ([`gallery`]). `src/main.rs` is the
//! thin clap front end.
//!
//! Every problem with an input file is a [`source::Diagnostic`] with file, line and
//! column; nothing that depends on input panics.

/// The first error writing to standard output (a full disk, `> /dev/full`, a closed
/// pipe), kept for [`stdout_error`]: the command then exits non-zero.
static STDOUT_ERROR: std::sync::OnceLock<std::io::Error> = std::sync::OnceLock::new();

/// Writes to standard output without panicking; a failure is recorded
/// ([`stdout_error`]) and later writes are skipped.
pub fn write_stdout(s: &str) {
    use std::io::Write as _;
    if STDOUT_ERROR.get().is_some() {
        return;
    }
    let mut o = std::io::stdout().lock();
    if let Err(e) = o.write_all(s.as_bytes()).and_then(|()| o.flush()) {
        let _ = STDOUT_ERROR.set(e);
    }
}

/// The error that made a write to standard output fail, if any.
pub fn stdout_error() -> Option<&'static std::io::Error> {
    STDOUT_ERROR.get()
}

/// Writes to standard error, ignoring errors.
pub fn write_stderr(s: &str) {
    use std::io::Write as _;
    let _ = std::io::stderr().lock().write_all(s.as_bytes());
}

/// `print!` that never panics.
macro_rules! out {
    ($($t:tt)*) => { $crate::write_stdout(&format!($($t)*)) };
}
/// `println!` that never panics.
macro_rules! outln {
    ($($t:tt)*) => { $crate::write_stdout(&format!("{}\n", format_args!($($t)*))) };
}
/// `eprint!` that never panics.
macro_rules! err {
    ($($t:tt)*) => { $crate::write_stderr(&format!($($t)*)) };
}
/// `eprintln!` that never panics.
macro_rules! errln {
    ($($t:tt)*) => { $crate::write_stderr(&format!("{}\n", format_args!($($t)*))) };
}

pub mod build;
pub mod closure;
pub mod float;
pub mod float_agreement;
pub mod fuzz;
pub mod gallery;
pub mod limits;
pub mod model;
pub mod ops;
pub mod output;
pub mod recipe;
pub mod source;
pub mod value;

/// Exit code: every certificate holds.
pub const EXIT_OK: u8 = 0;
/// Exit code: a certificate fails (or a gallery object cannot be built).
pub const EXIT_FAIL: u8 = 1;
/// Exit code: a usage or input error (bad recipe, unreadable file, unwritable directory).
pub const EXIT_INPUT: u8 = 2;
