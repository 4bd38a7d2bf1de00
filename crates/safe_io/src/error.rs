//! Why a file could not be written: each kind names the file or directory
//! concerned.

/// Why a file could not be written.
#[derive(Debug, thiserror::Error)]
pub enum WriteError {
    /// An I/O failure, with the file it concerns.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The destination.
        path: String,
        /// The reason.
        source: std::io::Error,
    },
    /// The destination's directory does not exist.
    #[error("cannot write {path}: the directory {dir} does not exist")]
    NoDirectory {
        /// The destination.
        path: String,
        /// Its directory.
        dir: String,
    },
    /// A directory in which no file can be created.
    #[error("cannot write into the directory {dir}: {source}")]
    Unwritable {
        /// The directory.
        dir: String,
        /// The reason.
        source: std::io::Error,
    },
    /// A destination that exists and is not a regular file (a directory,
    /// FIFO, device, socket or symbolic link), which writing would replace.
    #[error("{path} exists and is not a regular file; it is not replaced")]
    NotARegularFile {
        /// The destination.
        path: String,
    },
    /// A destination that is one of the files being read.
    #[error("{path} is {input}, which is being read; give another output")]
    IsAnInput {
        /// The destination.
        path: String,
        /// The input, as given.
        input: String,
    },
}
