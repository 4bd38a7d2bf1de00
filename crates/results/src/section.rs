//! One section of the document, between its two marker lines: built,
//! compared with the committed copy, or put in its place.

use crate::diff;
use crate::error::{Error, WRITE_VAR};
use crate::stamp::{load, machine, today};

/// One section of the document: its name, the command that computes it and
/// its text.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    name: String,
    command: String,
    text: String,
    pub(crate) deterministic: bool,
}

impl Section {
    /// A table that depends only on the code and the committed references:
    /// compared with the committed copy.
    pub fn deterministic(name: &str, command: &str, body: &str) -> Self {
        let lead = format!(
            "{}, which fails when this copy differs \
             (`{WRITE_VAR}=1` rewrites it).",
            written_by_lead(command)
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

    /// The command that computes it.
    pub fn command(&self) -> &str {
        &self.command
    }

    /// The section's text between its markers.
    pub fn text(&self) -> &str {
        &self.text
    }
}

/// How a deterministic section's text opens: the command that wrote it.
fn written_by_lead(command: &str) -> String {
    format!("Written by `{command}`")
}

/// Whether `document` holds a deterministic section `name` written by
/// `command`.
pub(crate) fn written_by(document: &str, name: &str, command: &str) -> bool {
    locate(document, name)
        .is_some_and(|range| document[range].starts_with(&written_by_lead(command)))
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
