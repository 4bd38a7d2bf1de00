//! Where the results live: the workspace root of this checkout, and its
//! `docs/results.md`.

use std::path::{Path, PathBuf};

/// The workspace root, where `docs/results.md` lives.
pub(crate) fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// `docs/results.md` of this checkout.
pub fn document_path() -> PathBuf {
    workspace_root().join("docs/results.md")
}
