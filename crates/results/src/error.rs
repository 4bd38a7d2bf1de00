//! Why a section could not be settled, and the variable that turns
//! comparison into rewriting, which the errors name.

use std::path::{Path, PathBuf};

/// The environment variable that turns comparison into rewriting.
pub const WRITE_VAR: &str = "RESULTS_WRITE";

/// Why a section could not be settled.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The committed section differs from the computed one.
    #[error("docs/results.md: section `{name}` differs from what `{command}` computes now (`- ` committed, `+ ` computed); if the change is intended, rerun with {WRITE_VAR}=1\n{diff}")]
    Differs {
        /// The section's name.
        name: String,
        /// The command that computes it.
        command: String,
        /// The line diff, committed against computed.
        diff: String,
    },
    /// The document has no such section.
    #[error(
        "docs/results.md has no section `{name}`; run `{command}` with {WRITE_VAR}=1 to add it"
    )]
    Missing {
        /// The section's name.
        name: String,
        /// The command that computes it.
        command: String,
    },
    /// A slow table whose inputs changed since its key was recorded: the
    /// table may be the same, but only running it says so.
    #[error("docs/results.md: section `{name}`'s inputs changed since it was written (docs/results.keys.json); run `{command}` (with {WRITE_VAR}=1 to record its key, and its table if that changed)")]
    KeyStale {
        /// The section's name.
        name: String,
        /// The command that computes it.
        command: String,
    },
    /// The recorded keys, or `cargo metadata`'s list of the crates, could
    /// not be read.
    #[error("{}: {message}", path.display())]
    Keys {
        /// The file or command read.
        path: PathBuf,
        /// What was wrong with it.
        message: String,
    },
    /// A benchmark was not measured in this run.
    #[error("benchmark `{0}` was not measured in this run (filtered out?); the section is left as it was")]
    NotMeasured(String),
    /// Criterion's files could not be read.
    #[error("criterion's output: {0}")]
    Criterion(String),
    /// The document could not be read or written.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// What the operating system said.
        source: std::io::Error,
    },
}

impl Error {
    pub(crate) fn io(path: &Path, source: std::io::Error) -> Self {
        Self::Io {
            path: path.to_owned(),
            source,
        }
    }
}
