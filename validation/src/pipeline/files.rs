//! Directories and files of a run, created and written whole.

use std::path::Path;

use safe_io::write_atomically;
use tracer::output::OutputError;

use super::error::PipelineError;

/// Creates `path` and its parents.
pub(super) fn create_dir(path: &Path) -> Result<(), PipelineError> {
    std::fs::create_dir_all(path).map_err(|source| PipelineError::CreateDir {
        path: path.to_owned(),
        source,
    })
}

/// Writes `dir/name` atomically.
pub(super) fn write(dir: &Path, name: &str, contents: &[u8]) -> Result<(), OutputError> {
    Ok(write_atomically(&dir.join(name), contents)?)
}
