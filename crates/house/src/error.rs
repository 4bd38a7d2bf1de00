//! The one failure: a source file that could not be read or parsed.

use std::fmt;
use std::path::{Path, PathBuf};

/// A source file or folder that could not be read, or a file that does not
/// parse as Rust.
#[derive(Debug)]
pub struct Error {
    /// The file or folder.
    pub path: PathBuf,
    /// What went wrong.
    pub detail: String,
}

impl Error {
    pub(crate) fn new(path: &Path, detail: impl fmt::Display) -> Self {
        Error {
            path: path.to_path_buf(),
            detail: detail.to_string(),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path.display(), self.detail)
    }
}

impl std::error::Error for Error {}
