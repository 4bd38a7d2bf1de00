//! What a run is asked to do, and where.

use std::path::PathBuf;

use crate::checkout::Checkout;
use record::Lang;

/// Random cases of each law that Mitsuba evaluates: reduced set, full set.
pub const RANDOM_CASES: [usize; 2] = [300, 3000];

/// What to run, and where.
#[derive(Clone, Debug)]
pub struct Options {
    /// The suite's checkout: references, scenes, generators.
    pub checkout: Checkout,
    /// The reduced set: the committed references instead of regenerated
    /// ones, fewer samples and cases.
    pub quick: bool,
    /// Directory for the report and the figures, created if missing
    /// [default: `validation/out` in the checkout].
    pub out: Option<PathBuf>,
    /// The Python side; `None`: no Python at all (committed references, no
    /// random cases, no drawn figures).
    pub python: Option<PythonOptions>,
    /// Seed of the random cases.
    pub seed: u64,
    /// The command line recorded in the report.
    pub command: String,
    /// The language `report.html` is written in (`report.json` is the
    /// same in either).
    pub lang: Lang,
}

/// The Python environment the references come from.
#[derive(Clone, Debug)]
pub struct PythonOptions {
    /// The Python 3 interpreter that creates the environment.
    pub base: PathBuf,
    /// The environment, created if missing [default: `.venv` in the checkout].
    pub venv: Option<PathBuf>,
}

impl Options {
    /// The reduced set against `checkout`'s committed references, no Python,
    /// seed 1, the report in the checkout's `validation/out`, in English.
    pub fn quick(checkout: Checkout, command: &str) -> Self {
        Self {
            checkout,
            quick: true,
            out: None,
            python: None,
            seed: 1,
            command: command.to_owned(),
            lang: Lang::En,
        }
    }
}
