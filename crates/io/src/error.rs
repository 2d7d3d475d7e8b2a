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
    /// A spine file (STEP, IGES or JSON) holds no curve.
    #[error("the spine file {0} has no curves (a pipe needs at least one rational B-spline or Bézier curve)")]
    NoSpineCurves(String),
    /// A file being read is malformed or outside the subset the readers accept. The
    /// message names the format, the line (1-based, where known) and the entity
    /// (`#7` in STEP, `type 126 at DE 5` in IGES), e.g.
    /// `STEP line 12, entity #7: expected a list of weights`.
    #[error("{format}{}{}: {message}", line_part(.line), entity_part(.entity))]
    Read {
        /// `"STEP"`, `"IGES"` or `"sidecar"`.
        format: &'static str,
        /// The 1-based line of the file, where known.
        line: Option<usize>,
        /// The entity (`#7`, `type 126 at DE 5`), where known.
        entity: Option<String>,
        /// What is wrong.
        message: String,
    },
}

fn line_part(line: &Option<usize>) -> String {
    line.map_or_else(String::new, |l| format!(" line {l}"))
}

fn entity_part(entity: &Option<String>) -> String {
    entity
        .as_ref()
        .map_or_else(String::new, |e| format!(", entity {e}"))
}

impl IoError {
    /// A [`IoError::Read`] error.
    pub fn read(
        format: &'static str,
        line: Option<usize>,
        entity: Option<String>,
        message: impl std::fmt::Display,
    ) -> Self {
        IoError::Read {
            format,
            line,
            entity,
            message: message.to_string(),
        }
    }

    /// The line of a [`IoError::Read`] error.
    pub fn line(&self) -> Option<usize> {
        match self {
            IoError::Read { line, .. } => *line,
            _ => None,
        }
    }

    /// The entity of a [`IoError::Read`] error.
    pub fn entity(&self) -> Option<&str> {
        match self {
            IoError::Read { entity, .. } => entity.as_deref(),
            _ => None,
        }
    }
}
