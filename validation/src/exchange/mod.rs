//! Cases the Rust side exports for a reference tool to evaluate, and the
//! results it hands back: the laws at random inputs against Mitsuba 3.
//!
//! The committed references cover chosen grids; this adds inputs nobody
//! chose. `optics validate` draws [`random_cases`] from a seeded generator,
//! writes them as `cases.json` (schema `law-cases/1`), runs
//! `python-checks/mitsuba_eval.py` on them, reads back `results.json`
//! (schema `law-results/1`: Mitsuba's outputs, one per case, in order) and
//! compares with [`check_random`].
//!
//! The radiometry crate's `f64` laws stand in for the exact values here:
//! their reflectances are within 8 `f64` ulps of 50-digit references, on
//! the grid and at random inputs of their own (checks `laws.mpmath.*` and
//! `laws.mpmath.random.*`), eight orders of magnitude below the `f32`
//! tolerances. This check is the one against Mitsuba; the one against an
//! independent exact value is `laws.mpmath.random.*`.
//! The tolerances and the rule separating failures from findings are those
//! of [`crate::laws`].

mod cases;
mod compare;

pub use cases::{
    random_cases, CasesFile, LawCase, LawResult, ResultsFile, CASES_SCHEMA, RESULTS_SCHEMA,
};
pub use compare::check_random;
