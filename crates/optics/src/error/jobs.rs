//! The errors of a sweep spread over machines (`optics tradeoff --plan`,
//! `optics tradeoff-job`, `optics tradeoff --collect`), from the library,
//! with the flag or argument each input came from ([`flag`]).

pub use validation::tradeoff::jobs::{listed, ImageProblem, Input, JobError, LineKind, Place};

/// The flag or argument of the command line an input came from.
pub fn flag(input: Input) -> &'static str {
    match input {
        Input::Plan => "--plan",
        Input::Out => "--out",
        Input::Collect => "--collect",
        Input::Jobs => "JOBS",
        Input::Index => "INDEX",
        Input::Job => "job",
    }
}
