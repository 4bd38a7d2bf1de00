//! The results document, `docs/results.md`: every table of numbers the
//! suite's documents quote, each in a section written by the command that
//! computes it, so that no number is copied by hand.
//!
//! A section sits between two marker lines and opens with the command that
//! wrote it. There are two kinds:
//!
//! - **deterministic** (accuracy against references, precision tiers,
//!   measured image differences): the test or example that computes the
//!   table compares it with the committed section and fails with a line
//!   diff when they differ; run with `RESULTS_WRITE=1` it rewrites the
//!   section instead.
//! - **measured** (timings, ratios, throughput): written whenever the bench
//!   measures, stamped with the command, the machine and the date, and never
//!   compared.
//!
//! ```
//! let committed = "<!-- results: demo -->\nold\n<!-- /results: demo -->\n";
//! let section = results::Section::deterministic("demo", "cargo test", "| a | 1.00 |");
//! assert!(results::compare(committed, &section).is_err());
//! let rewritten = results::replace(committed, &section);
//! assert!(results::compare(&rewritten, &section).is_ok());
//! ```

pub mod criterion;
mod diff;
mod stamp;

use std::path::{Path, PathBuf};
use std::sync::Mutex;

pub use stamp::{load, machine, today};

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
    fn io(path: &Path, source: std::io::Error) -> Self {
        Self::Io {
            path: path.to_owned(),
            source,
        }
    }
}

/// One section of the document: its name, the command that computes it and
/// its text.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    name: String,
    command: String,
    text: String,
    deterministic: bool,
}

impl Section {
    /// A table that depends only on the code and the committed references:
    /// compared with the committed copy.
    pub fn deterministic(name: &str, command: &str, body: &str) -> Self {
        let lead = format!(
            "Written by `{command}`, which fails when this copy differs \
             (`{WRITE_VAR}=1` rewrites it)."
        );
        Self::new(name, command, &lead, body, true)
    }

    /// A timing: stamped with the command, this machine and today's date,
    /// never compared.
    pub fn measured(name: &str, command: &str, body: &str) -> Self {
        let load = load().map_or(String::new(), |l| format!(" ({l})"));
        let lead = format!(
            "Measured by `{command}` on {}{load}, {}; a timing of that machine, not compared.",
            machine(),
            today()
        );
        Self::new(name, command, &lead, body, false)
    }

    fn new(name: &str, command: &str, lead: &str, body: &str, deterministic: bool) -> Self {
        Self {
            name: name.to_owned(),
            command: command.to_owned(),
            text: format!("{lead}\n\n{}\n", body.trim_end()),
            deterministic,
        }
    }

    /// The section's name, as its markers carry it.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The section's text between its markers.
    pub fn text(&self) -> &str {
        &self.text
    }
}

fn begin(name: &str) -> String {
    format!("<!-- results: {name} -->\n")
}

fn end(name: &str) -> String {
    format!("<!-- /results: {name} -->\n")
}

/// The byte range of `name`'s text between its markers, if present.
fn locate(document: &str, name: &str) -> Option<std::ops::Range<usize>> {
    let start = document.find(&begin(name))? + begin(name).len();
    let len = document[start..].find(&end(name))?;
    Some(start..start + len)
}

/// `Ok` when `document` holds `section` exactly; otherwise the diff, or that
/// the section is missing.
pub fn compare(document: &str, section: &Section) -> Result<(), Error> {
    let range = locate(document, &section.name).ok_or_else(|| Error::Missing {
        name: section.name.clone(),
        command: section.command.clone(),
    })?;
    let committed = &document[range];
    if committed == section.text {
        return Ok(());
    }
    Err(Error::Differs {
        name: section.name.clone(),
        command: section.command.clone(),
        diff: diff::lines(committed, &section.text),
    })
}

/// `document` with `section`'s text put between its markers; a section not
/// yet in the document is appended at its end.
pub fn replace(document: &str, section: &Section) -> String {
    match locate(document, &section.name) {
        Some(range) => {
            let mut out = document.to_owned();
            out.replace_range(range, &section.text);
            out
        }
        None => {
            let sep = if document.is_empty() || document.ends_with("\n\n") {
                ""
            } else if document.ends_with('\n') {
                "\n"
            } else {
                "\n\n"
            };
            let (b, e) = (begin(&section.name), end(&section.name));
            format!("{document}{sep}{b}{}{e}", section.text)
        }
    }
}

/// The workspace root, where `docs/results.md` lives.
fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// `docs/results.md` of this checkout.
pub fn document_path() -> PathBuf {
    workspace_root().join("docs/results.md")
}

/// Whether `RESULTS_WRITE=1` asks for the sections to be rewritten.
pub fn write_requested() -> bool {
    std::env::var_os(WRITE_VAR).is_some_and(|v| v == "1")
}

/// Serialises rewrites of the document by the tests of one process.
static DOCUMENT: Mutex<()> = Mutex::new(());

/// Settles `section` against `docs/results.md`: a deterministic section is
/// compared (rewritten under `RESULTS_WRITE=1`), a measured one written.
pub fn settle(section: &Section) -> Result<(), Error> {
    let path = document_path();
    let _guard = DOCUMENT.lock().unwrap_or_else(|e| e.into_inner());
    let document = match std::fs::read_to_string(&path) {
        Ok(text) => text,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => String::new(),
        Err(e) => return Err(Error::io(&path, e)),
    };
    if section.deterministic && !write_requested() {
        return compare(&document, section);
    }
    let updated = replace(&document, section);
    if updated != document {
        let tmp = path.with_extension("md.tmp");
        std::fs::write(&tmp, updated).map_err(|e| Error::io(&tmp, e))?;
        std::fs::rename(&tmp, &path).map_err(|e| Error::io(&path, e))?;
    }
    Ok(())
}

/// [`settle`], panicking with its message (the diff) when it fails: for
/// tests, where a stale table is a failure like any other assertion.
#[track_caller]
pub fn assert_settled(section: &Section) {
    if let Err(e) = settle(section) {
        panic!("{e}");
    }
}

/// An example that prints a deterministic table and is also built as a test
/// (`[[example]] test = true`): `main` prints the table and settles its
/// section, and the test `committed_table_is_current` settles it under
/// `cargo test`, so CI compares it with the committed copy.
///
/// `deterministic_example!("name", "the command that runs it", table)`,
/// where `table: fn() -> String`.
#[macro_export]
macro_rules! deterministic_example {
    ($name:literal, $command:literal, $table:path) => {
        fn main() {
            let table = $table();
            println!("{table}");
            $crate::assert_settled(&$crate::Section::deterministic($name, $command, &table));
        }

        #[test]
        fn committed_table_is_current() {
            $crate::assert_settled(&$crate::Section::deterministic($name, $command, &$table()));
        }
    };
}

#[cfg(test)]
mod tests;
