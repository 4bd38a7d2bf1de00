//! The cross-check harness: the radiometry crate's laws and colorimetry
//! against references nobody here wrote (Mitsuba 3, colour-science) and
//! against 50-digit values (mpmath).
//!
//! The references are JSON files in `validation/reference/`, written by the
//! scripts in `python-checks/` and committed, so every check runs with no
//! Python installed. Each check is a pure function of the laws under test
//! and a reference document, returning a [`Check`]: the worst disagreements,
//! the failures (ours beyond tolerance) and the findings (the references
//! disagreeing with each other). The laws are a parameter, so a deliberately
//! broken law can be shown to be caught.
//!
//! ```
//! use validation::laws::{self, Laws, MitsubaLaws};
//!
//! let reference = MitsubaLaws::load(&validation::reference::committed_dir()).unwrap();
//! let checks = laws::check_all(&Laws::radiometry(), &reference);
//! assert!(checks.iter().all(|c| c.passed()));
//! ```
//!
//! [`pipeline::run`] is the whole harness as one call (`optics validate`
//! fronts it): the Python environment ([`python`]), the regeneration
//! ([`regenerate`]), every kind of check ([`suite`]), the random cases
//! ([`exchange`]) and the report ([`report`]), against a checkout of the
//! suite found at run time ([`checkout`]).

#![forbid(unsafe_code)]
#![warn(missing_docs)]
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod case_words;
pub mod check;
pub mod checkout;
pub mod colorimetry;
pub mod compare;
pub mod context;
pub mod exchange;
pub mod flip;
pub mod full_light;
pub mod laws;
pub mod metals;
pub mod mpmath;
pub mod pipeline;
pub mod python;
pub mod reference;
pub mod regenerate;
pub mod renders;
pub mod report;
pub mod speed;
pub mod statistics;
pub mod suite;
pub mod techniques;
pub mod tradeoff;
pub mod user_render;

pub use check::{Check, Metric};

pub use reference::ReferenceError;
