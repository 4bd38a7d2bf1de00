//! `docs/results.md` of this checkout: where it is, and settling a section
//! against it.

use std::sync::Mutex;

use crate::error::{Error, WRITE_VAR};
use crate::key::{self, Inputs};
pub use crate::root::document_path;
use crate::section::{compare, replace, Section};

/// Whether `RESULTS_WRITE=1` asks for the sections to be rewritten.
pub fn write_requested() -> bool {
    std::env::var_os(WRITE_VAR).is_some_and(|v| v == "1")
}

/// Serialises rewrites of the document by the tests of one process.
static DOCUMENT: Mutex<()> = Mutex::new(());

/// Settles `section` against `docs/results.md`: a deterministic section is
/// compared (rewritten under `RESULTS_WRITE=1`), a measured one written.
pub fn settle(section: &Section) -> Result<(), Error> {
    settle_in(&document_path(), section)
}

/// [`settle`] against another document of the checkout (a table of
/// `docs/cli.md` generated from the code's own declarations).
pub fn settle_in(path: &std::path::Path, section: &Section) -> Result<(), Error> {
    let _guard = DOCUMENT.lock().unwrap_or_else(|e| e.into_inner());
    let document = match std::fs::read_to_string(path) {
        Ok(text) => text,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => String::new(),
        Err(e) => return Err(Error::io(path, e)),
    };
    if section.deterministic && !write_requested() {
        return compare(&document, section);
    }
    let updated = replace(&document, section);
    if updated != document {
        let tmp = path.with_extension("md.tmp");
        std::fs::write(&tmp, updated).map_err(|e| Error::io(&tmp, e))?;
        std::fs::rename(&tmp, path).map_err(|e| Error::io(path, e))?;
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

/// Whether the keyed section `name` is committed and its key, recorded
/// with it, is that of `inputs` now: then the committed table is what the
/// program computes, unrun. Always `false` under `RESULTS_WRITE=1`, which
/// computes and records.
#[track_caller]
pub fn key_is_current(name: &str, command: &str, inputs: &Inputs<'_>) -> bool {
    if write_requested() {
        return false;
    }
    let current = key::recorded(name).and_then(|recorded| Ok((recorded, inputs.key()?)));
    match current {
        Ok((Some(recorded), now)) if recorded == now => {
            let document = std::fs::read_to_string(document_path()).unwrap_or_default();
            crate::section::written_by(&document, name, command)
        }
        Ok(_) => false,
        Err(e) => panic!("{e}"),
    }
}

/// [`assert_settled`] for a keyed section: the table compared (or
/// written), then its key recorded under `RESULTS_WRITE=1`, or required
/// current otherwise ([`Error::KeyStale`]).
#[track_caller]
pub fn assert_settled_keyed(section: &Section, inputs: &Inputs<'_>) {
    assert_settled(section);
    let result = inputs.key().and_then(|now| {
        if write_requested() {
            return key::record(section.name(), &now);
        }
        match key::recorded(section.name())? {
            Some(recorded) if recorded == now => Ok(()),
            _ => Err(Error::KeyStale {
                name: section.name().to_owned(),
                command: section.command().to_owned(),
            }),
        }
    });
    if let Err(e) = result {
        panic!("{e}");
    }
}
