//! How the command line shows what it has: a record as text or one JSON
//! object, in English or Hungarian, and a failure on stderr (with `--json`
//! also as the error object on stdout). The only module that prints.

use crate::error::{self, Error, ErrorKind};
use record::{Lang, Record};
use std::io::Write;

/// How results are shown: plain text or one JSON object, in English or Hungarian.
#[derive(Debug, Clone, Copy)]
pub struct Ui {
    /// One JSON object rather than text (`--json`).
    pub json: bool,
    /// The language of the text (`--lang`).
    pub lang: Lang,
}

impl Ui {
    /// Prints a record in the chosen form.
    pub fn show(&self, record: &Record) -> error::Result<()> {
        let text = if self.json {
            let json = serde_json::to_string(record).map_err(ErrorKind::Encode)?;
            json + "\n"
        } else {
            record.to_text(self.lang)
        };
        print_out(&text)
    }

    /// Prints a record whose text form is its steps alone, one a line
    /// (`render`, `inspect`, `validate`: their steps are what they report).
    pub fn show_steps(&self, record: &Record) -> error::Result<()> {
        if self.json {
            return self.show(record);
        }
        let steps: String = record
            .steps
            .iter()
            .map(|step| format!("{step}\n"))
            .collect();
        print_out(&steps)
    }

    /// [`Ui::show_steps`], and in text the record's notes after its steps
    /// (what was skipped or reduced, what to mind), which are otherwise
    /// read only in the JSON.
    pub fn show_steps_and_notes(&self, record: &Record) -> error::Result<()> {
        self.show_steps(record)?;
        if self.json {
            return Ok(());
        }
        let notes: String = record.notes.iter().map(|n| format!("{n}\n")).collect();
        print_out(&notes)
    }

    /// The form chosen on a command line that did not parse: `--json` and
    /// `--lang hu` are looked for among the raw arguments, so that even a
    /// syntax error is reported in the form asked for.
    pub(crate) fn from_raw_args(args: impl IntoIterator<Item = std::ffi::OsString>) -> Self {
        let args: Vec<_> = args.into_iter().collect();
        let hu = args.windows(2).any(|w| w[0] == "--lang" && w[1] == "hu")
            || args.iter().any(|a| a == "--lang=hu");
        Ui {
            json: args.iter().any(|a| a == "--json"),
            lang: if hu { Lang::Hu } else { Lang::En },
        }
    }

    /// Reports a failure: the JSON error object on stdout with `--json`,
    /// and the message on stderr. Where either is closed there is no one
    /// left to tell, and the exit status says it.
    pub(crate) fn report(&self, error: &Error) {
        if self.json {
            let json = serde_json::json!({ "error": error.to_json(self.lang) });
            let _ = print_out(&format!("{json}\n"));
        }
        let text = match error.kind() {
            // The parser's own layout, with its usage line and tips.
            ErrorKind::Usage(usage) => error::usage_rendered(usage, self.lang),
            _ => format!(
                "{}: {}\n",
                self.lang.pick("error", "hiba"),
                error.message(self.lang)
            ),
        };
        print_err(&text);
    }
}

/// Writes `text` to stdout, all of it or an error; the one way the
/// commands print, so that a closed stdout is one [`ErrorKind::Write`].
pub(crate) fn print_out(text: &str) -> error::Result<()> {
    let mut out = std::io::stdout().lock();
    let written = out.write_all(text.as_bytes()).and_then(|()| out.flush());
    written.map_err(|e| ErrorKind::Write(e).into())
}

/// Writes `text` to stderr, where a failure has nowhere left to go: the
/// one way the commands write to it, so a closed stderr never panics.
pub(crate) fn print_err(text: &str) {
    let _ = std::io::stderr().lock().write_all(text.as_bytes());
}

/// Whether the output's reader has gone (`optics … | head`): not a failure
/// to report but the end of the run, as for the Unix tools.
pub(crate) fn reader_gone(error: &Error) -> bool {
    matches!(error.kind(), ErrorKind::Write(e) if e.kind() == std::io::ErrorKind::BrokenPipe)
}
