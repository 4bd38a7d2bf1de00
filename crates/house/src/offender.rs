//! An offender against a house rule: which rule, and the place that breaks it.

use std::fmt;
use std::path::PathBuf;

/// The most lines a product source file may have.
pub const MAX_FILE_LINES: usize = 400;
/// The most lines a product function may have, from its `fn` line to its
/// closing brace.
pub const MAX_FN_LINES: usize = 80;

/// The house rules, one per kind of offence.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Rule {
    /// A product source file over [`MAX_FILE_LINES`] lines.
    LongFile,
    /// A product function over [`MAX_FN_LINES`] lines.
    LongFunction,
    /// Files of one crate that import each other round a circle.
    ImportCircle,
    /// A file importing a name defined in one of its ancestor module files.
    UpwardImport,
    /// A library error text that names a command-line flag (`--name`).
    FlagInLibraryError,
}

impl Rule {
    /// Every rule, in the order they are reported.
    pub const ALL: [Rule; 5] = [
        Rule::LongFile,
        Rule::LongFunction,
        Rule::ImportCircle,
        Rule::UpwardImport,
        Rule::FlagInLibraryError,
    ];
}

impl fmt::Display for Rule {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Rule::LongFile => "file over 400 lines",
            Rule::LongFunction => "function over 80 lines",
            Rule::ImportCircle => "import circle",
            Rule::UpwardImport => "upward import",
            Rule::FlagInLibraryError => "flag in a library error",
        })
    }
}

/// Where an offence is, with what the rule needs to name it.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Place {
    /// A whole file and its line count.
    File {
        /// The file, relative to the workspace root.
        path: PathBuf,
        /// Its number of lines.
        lines: usize,
    },
    /// A function: its file, the line of its `fn`, its name and length.
    Function {
        /// The file, relative to the workspace root.
        path: PathBuf,
        /// The line of its `fn` keyword (1-based).
        line: usize,
        /// Its name, `Type::method` for a method.
        name: String,
        /// Its length in lines.
        lines: usize,
    },
    /// Every file of one circle, sorted.
    Circle {
        /// The files, relative to the workspace root.
        files: Vec<PathBuf>,
    },
    /// An import from a file to one of its ancestors.
    Import {
        /// The importing file, relative to the workspace root.
        from: PathBuf,
        /// The line of the import (1-based).
        line: usize,
        /// The ancestor file it imports from.
        to: PathBuf,
        /// The path as written, e.g. `super::Tracer`.
        written: String,
    },
    /// A string literal in an error text.
    Text {
        /// The file, relative to the workspace root.
        path: PathBuf,
        /// The line of the literal (1-based).
        line: usize,
        /// The error type whose text it is.
        owner: String,
        /// The flag found in it, e.g. `--allow-expensive`.
        flag: String,
    },
}

/// One offence against one rule.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Offender {
    /// The rule broken.
    pub rule: Rule,
    /// Where.
    pub place: Place,
}

impl fmt::Display for Offender {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.place {
            Place::File { path, lines } => {
                write!(
                    f,
                    "{}: {lines} lines (at most {MAX_FILE_LINES})",
                    path.display()
                )
            }
            Place::Function {
                path,
                line,
                name,
                lines,
            } => write!(
                f,
                "{}:{line}: fn {name} is {lines} lines (at most {MAX_FN_LINES})",
                path.display()
            ),
            Place::Circle { files } => {
                write!(f, "import circle of {} files:", files.len())?;
                for file in files {
                    write!(f, " {}", file.display())?;
                }
                Ok(())
            }
            Place::Import {
                from,
                line,
                to,
                written,
            } => write!(
                f,
                "{}:{line}: imports `{written}` from its ancestor {}",
                from.display(),
                to.display()
            ),
            Place::Text {
                path,
                line,
                owner,
                flag,
            } => write!(
                f,
                "{}:{line}: the text of {owner} names the flag {flag}",
                path.display()
            ),
        }
    }
}

impl Offender {
    /// The offence without the numbers that move when code around it
    /// changes (line numbers, lengths): `rule: place`, one line, stable
    /// while the offence stands. What `known_offenders.txt` lists.
    pub fn identity(&self) -> String {
        let place = match &self.place {
            Place::File { path, .. } => path.display().to_string(),
            Place::Function { path, name, .. } => format!("{}: fn {name}", path.display()),
            Place::Circle { files } => files
                .iter()
                .map(|f| f.display().to_string())
                .collect::<Vec<_>>()
                .join(" "),
            Place::Import { from, to, .. } => format!("{} -> {}", from.display(), to.display()),
            Place::Text {
                path, owner, flag, ..
            } => {
                format!("{}: {owner} names {flag}", path.display())
            }
        };
        format!("{}: {place}", self.rule)
    }
}
