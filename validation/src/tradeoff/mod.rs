//! The speed/accuracy trade as `optics tradeoff` records it: the record's
//! vocabulary, shared by the command that writes it and by the report that
//! reads it ([`record`]), the fixed error measures ([`measure`]), the
//! Pareto front ([`pareto`]), the accuracy budget's prediction
//! ([`budget`]), the verdict on a
//! shortcut ([`Verdict`]) and what a scene's sweep says of each
//! ([`findings`]), and the checks `optics validate` makes of the
//! committed records (`docs/tradeoffs/*.json`, written by
//! `docs/tradeoffs/make`): [`checks`].

pub mod budget;
pub mod checks;
pub mod engine;
pub mod error;
pub mod findings;
pub mod jobs;
pub mod measure;
pub mod mitsuba;
pub mod pareto;
pub mod pilot;
pub mod prose;
pub mod record;
pub mod render;
pub mod sweep;
pub mod truth;

mod schema;
mod verdict;

pub use schema::{MEASURES, SCHEMA, SCHEMA_VERSION, SCHLICK_UNNAMED_VERSION};
pub use verdict::{Verdict, JUST_NOTICEABLE, WORTH_IT};

pub use jobs::VERSION as JOB_VERSION;
