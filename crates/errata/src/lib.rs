//! The errata of the course texts, as data: every place where the notes
//! (`shared/seeds/`, by prefix: `000` GLSL tutorial, `001` slides, `002`
//! WebGL tracer, `003` textbook chapter) disagree with the laws, read from
//! one table, `errata.json` beside this crate, and nowhere else.
//!
//! Each [`Erratum`] has a stable id, its place in the text (the text's
//! prefix and lines), what is written there, what is right in English and
//! Hungarian (ready to paste back into the notes), a [`Class`], its
//! measured effect where one exists, and the tests that demonstrate it.
//! The table's order within a class is the ranking, worst first:
//! [`ranked`] puts the classes in order, physics first.
//!
//! From the table come `docs/errata.md` ([`page`]), `optics errata`
//! ([`listing`]) and the validation report's card ([`counts`], [`worst`]).
//!
//! ```
//! use errata::{counts, find, ranked, Class};
//!
//! let worst = ranked()[0];
//! assert_eq!(worst.class, Class::Physics);
//! let total: usize = counts().iter().map(|(_, n)| n).sum();
//! assert_eq!(total, ranked().len());
//! let fresnel = find("000-fresnel-backwards").unwrap();
//! assert!(fresnel.written.contains("pow(cosTheta, 5.0)"));
//! assert_eq!(record::Lang::Hu.pick(&fresnel.title.en, &fresnel.title.hu), fresnel.title.hu);
//! ```

#![warn(missing_docs)]

mod erratum;
pub mod listing;
pub mod page;
mod table;

pub use erratum::{Class, Erratum, Text, Words};
pub use table::{all, counts, find, parse_class, ranked, worst, LookupError};

#[cfg(test)]
mod tests;
