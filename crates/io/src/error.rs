//! Typed errors of the exporters.

use rcagd_geom::GeomError;
use std::path::PathBuf;
use thiserror::Error;

/// Errors raised by `rcagd-io`. Every variant names what failed.
#[derive(Debug, Error)]
pub enum IoError {
    /// A file could not be written.
    #[error("cannot write {path}: {source}")]
    Write {
        /// The file.
        path: PathBuf,
        /// The underlying error.
        #[source]
        source: std::io::Error,
    },
    /// A directory could not be created.
    #[error("cannot create directory {path}: {source}")]
    CreateDir {
        /// The directory.
        path: PathBuf,
        /// The underlying error.
        #[source]
        source: std::io::Error,
    },
    /// JSON serialization failed.
    #[error("JSON serialization failed: {0}")]
    Json(#[from] serde_json::Error),
    /// A failure of the geometry layer.
    #[error(transparent)]
    Geom(#[from] GeomError),
    /// The input cannot be exported (out-of-range index, non-finite coordinate, …);
    /// the message names the violated precondition.
    #[error("invalid input for export: {0}")]
    Invalid(String),
}
