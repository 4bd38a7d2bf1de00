//! The destination check, made before the work: the directory exists and
//! takes new files, what the destination names (if anything) is a regular
//! file the write may replace, and it is none of the files being read.

use std::path::Path;

use crate::atomic::{directory, probe};
use crate::error::WriteError;

/// Refuses `path` as a destination unless a write there can succeed and
/// replaces nothing it must not: its directory exists and a file can be
/// created in it; if `path` exists it is a regular file (not a directory,
/// FIFO, device, socket or symbolic link, which a rename would replace);
/// and it is not one of `inputs` (the files the work reads), under any name.
pub fn check_destination(path: &Path, inputs: &[&Path]) -> Result<(), WriteError> {
    let dir = directory(path)?;
    if let Ok(existing) = std::fs::symlink_metadata(path) {
        if !existing.file_type().is_file() {
            return Err(WriteError::NotARegularFile {
                path: path.display().to_string(),
            });
        }
        if let Some(input) = inputs.iter().find(|input| same_file(path, input)) {
            return Err(WriteError::IsAnInput {
                path: path.display().to_string(),
                input: input.display().to_string(),
            });
        }
    }
    writable_directory(dir)
}

/// Refuses `dir` unless a file can be created in it (tried, then removed).
pub fn writable_directory(dir: &Path) -> Result<(), WriteError> {
    probe(dir).map_err(|source| WriteError::Unwritable {
        dir: dir.display().to_string(),
        source,
    })
}

/// Whether `a` and `b` name one file (hard links and symbolic links
/// included).
fn same_file(a: &Path, b: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        match (std::fs::metadata(a), std::fs::metadata(b)) {
            (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
            _ => false,
        }
    }
    #[cfg(not(unix))]
    {
        match (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
            (Ok(a), Ok(b)) => a == b,
            _ => false,
        }
    }
}
