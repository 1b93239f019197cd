//! What can go wrong making the report: each variant carries what the user needs (the study,
//! the template, the path) and its sentence is the one the tool prints.

use crate::figures::error::FigureError;
use std::path::PathBuf;

/// A report that could not be made.
#[derive(Debug, thiserror::Error)]
pub enum ReportError {
    /// A figure could not be drawn.
    #[error(transparent)]
    Figure(#[from] FigureError),
    /// The checks could not run.
    #[error(transparent)]
    Checks(#[from] checks::check::CheckError),
    /// The corrected forms could not be applied or checked.
    #[error(transparent)]
    Corrections(#[from] checks::corrections::CorrectionError),
    /// A built-in scene could not be loaded.
    #[error(transparent)]
    Scene(#[from] physics::scene::SceneError),
    /// A study could not be computed.
    #[error(transparent)]
    Studies(#[from] studies::StudyError),
    /// A study of the pipeline failed.
    #[error("the {study} study failed: {reason}")]
    Study {
        /// The study's name.
        study: String,
        /// Why.
        reason: String,
    },
    /// A template is broken or cannot be rendered (the template's name in the sentence).
    #[error("{0}")]
    Template(String),
    /// A file or directory could not be created or written.
    #[error("cannot {action} {}: {reason}", path.display())]
    Io {
        /// "create" or "write".
        action: &'static str,
        /// The path.
        path: PathBuf,
        /// The system's reason.
        reason: std::io::Error,
    },
    /// report.json or its schema could not be made or does not validate.
    #[error("{0}")]
    Json(String),
    /// A lower layer's sentence (scene loading, the checks, the experiment, a figure list).
    #[error("{0}")]
    Input(String),
}

impl From<String> for ReportError {
    fn from(s: String) -> Self {
        ReportError::Input(s)
    }
}

impl From<&str> for ReportError {
    fn from(s: &str) -> Self {
        ReportError::Input(s.to_string())
    }
}

/// The binary prints the sentence.
impl From<ReportError> for String {
    fn from(e: ReportError) -> Self {
        e.to_string()
    }
}

impl ReportError {
    /// An I/O failure on `path`.
    pub fn io(action: &'static str, path: &std::path::Path, reason: std::io::Error) -> Self {
        ReportError::Io {
            action,
            path: path.to_path_buf(),
            reason,
        }
    }
}
