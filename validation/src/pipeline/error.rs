//! Why a run of the harness could not reach its end.

use std::path::PathBuf;

use tracer::output::OutputError;

use crate::python::ToolError;
use crate::reference::ReferenceError;
use crate::regenerate::RegenerateError;

/// Why the harness could not run to the end (failed checks are not errors:
/// they are in the report).
#[derive(Debug, thiserror::Error)]
pub enum PipelineError {
    /// The output directory names something else.
    #[error("the output directory {} exists and is not a directory", .path.display())]
    OutNotADirectory {
        /// It.
        path: PathBuf,
    },
    /// A directory could not be created.
    #[error("cannot create the directory {}: {source}", .path.display())]
    CreateDir {
        /// The directory.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The checkout has no pinned requirements for the Python side.
    #[error("{} not found: the Python side runs from a checkout of the suite", .path.display())]
    NoRequirements {
        /// The file looked for.
        path: PathBuf,
    },
    /// A report, figure or exchange file could not be written.
    #[error(transparent)]
    Write(#[from] OutputError),
    /// A reference, or Mitsuba's results, could not be used.
    #[error(transparent)]
    Reference(#[from] ReferenceError),
    /// A Python tool could not run or failed.
    #[error(transparent)]
    Tool(#[from] ToolError),
    /// The regeneration could not be judged.
    #[error(transparent)]
    Regenerate(#[from] RegenerateError),
}
