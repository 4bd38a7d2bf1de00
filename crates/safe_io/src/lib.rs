//! Safe file I/O for every crate of the suite, without the renderer: a
//! file (or a set of files) written whole or not at all, the destination
//! checked before the work, SIGINT and SIGTERM handled while writing, and
//! JSON read with every object's keys given once.
//!
//! ```
//! let dir = tempfile::tempdir().unwrap();
//! let (json, markdown) = (dir.path().join("sweep.json"), dir.path().join("sweep.md"));
//! // Refused before the work if the write could not succeed.
//! safe_io::check_destination(&json, &[]).unwrap();
//! // Both replaced whole, or neither: never one of two runs.
//! safe_io::write_all_atomically(&[(&json, b"{}\n"), (&markdown, b"# sweep\n")]).unwrap();
//! assert_eq!(std::fs::read(&json).unwrap(), b"{}\n");
//!
//! // A key given twice is refused, not silently overwritten.
//! let twice = serde_json::from_str::<safe_io::json::UniqueKeys>(r#"{"eta": 1.5, "eta": 2}"#);
//! assert!(twice.unwrap_err().to_string().starts_with(safe_io::json::TWICE));
//! ```
//!
//! | module | what |
//! |---|---|
//! | [`error`] | why a file could not be written |
//! | [`atomic`] | a set of files written to temporaries, then renamed into place as one |
//! | [`check`] | the destination checked before the work |
//! | [`interrupt`] | SIGINT and SIGTERM while writing: temporaries removed, a commit finished first |
//! | [`json`] | JSON read with every object's keys given once: the one reading of scene files, batch lines and plans |

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod atomic;
pub mod check;
pub mod error;
pub mod interrupt;
pub mod json;

pub use atomic::{write_all_atomically, write_atomically};
pub use check::{check_destination, writable_directory};
pub use error::WriteError;
