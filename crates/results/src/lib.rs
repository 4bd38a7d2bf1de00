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

#![warn(missing_docs)]

#[cfg(feature = "criterion")]
pub mod criterion;
mod diff;
mod document;
mod error;
pub mod key;
mod root;
mod section;
mod stamp;

pub use document::{
    assert_settled, assert_settled_keyed, document_path, key_is_current, settle, settle_in,
    write_requested,
};
pub use error::{Error, WRITE_VAR};
pub use section::{compare, replace, Section};
pub use stamp::{load, machine, today};
/// An example that prints a deterministic table and is also built as a test
/// (`[[example]] test = true`): `main` prints the table and settles its
/// section, and the test `committed_table_is_current` settles it under
/// `cargo test`, so CI compares it with the committed copy.
///
/// `deterministic_example!("name", "the command that runs it", table)`,
/// where `table: fn() -> String`.
///
/// A table slow to compute names the files it reads after `keyed_by`
/// (`deterministic_example!("name", "command", table, keyed_by ["dir"])`):
/// its test then computes it only when the key of its inputs ([`key`])
/// differs from the one recorded with it, and fails if the key is stale
/// even where the table came out the same, so that the next run is quick
/// again once the key is recorded (`RESULTS_WRITE=1`).
#[macro_export]
macro_rules! deterministic_example {
    ($name:literal, $command:literal, $table:path, keyed_by [$($data:literal),* $(,)?]) => {
        /// The inputs the table is keyed by.
        const KEYED_BY: $crate::key::Inputs<'static> = $crate::key::Inputs {
            package: env!("CARGO_PKG_NAME"),
            program: file!(),
            data: &[$($data),*],
        };

        fn main() {
            let table = $table();
            println!("{table}");
            $crate::assert_settled_keyed(
                &$crate::Section::deterministic($name, $command, &table),
                &KEYED_BY,
            );
        }

        #[test]
        fn committed_table_is_current() {
            if $crate::key_is_current($name, $command, &KEYED_BY) {
                return;
            }
            $crate::assert_settled_keyed(
                &$crate::Section::deterministic($name, $command, &$table()),
                &KEYED_BY,
            );
        }
    };
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
