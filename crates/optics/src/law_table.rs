//! The laws, declared once (module `table`): each one's name, its arguments and where it
//! sits on the command line. Everything else about a law is generated
//! from this table or read from its arguments' declaration:
//!
//! - the subcommands (`optics fresnel`, `optics quiz f0`, …) and their
//!   `--help`, from the arguments' `clap` attributes;
//! - `optics batch`'s requests: the law's name, read straight into its
//!   arguments by their `serde` attributes ([`Law::read`]), and the names a
//!   request may give ([`LAWS`]);
//! - the JSON record's `law` (each law's `LAW` constant);
//! - the fields of each request, for the fuzz targets and the docs
//!   ([`schema`]), and the table of laws in `docs/cli.md` ([`docs`]).
//!
//! A law's own file holds its arguments and its `solve`: the inputs checked,
//! the radiometry crate called, the working narrated in both languages.
//! Adding a law is that file and one line in `table.rs`'s `laws!`.

pub mod docs;
pub mod schema;
mod table;

pub use table::{command_words, Law, LawCommand, QuizLaw, LAWS, QUIZ_LAWS};

#[cfg(test)]
mod tests;
