//! The steps of a run, as progress hears of them.

use crate::python::SetUp;

/// A step of the run, for progress messages.
#[derive(Clone, Copy, Debug)]
pub enum Step<'a> {
    /// Setting the Python environment up.
    Python(SetUp<'a>),
    /// Regenerating the references with the pinned tools.
    Regenerating,
    /// Kind `index` of `total` kinds of check is awaited next (the kinds
    /// run beside one another; their results are taken in order).
    Checks {
        /// Which kind, from 0.
        index: usize,
        /// How many kinds.
        total: usize,
        /// Its name in English and in Hungarian.
        names: [&'a str; 2],
    },
    /// Every kind of check has run.
    ChecksDone,
    /// Having Mitsuba evaluate `cases` random cases.
    RandomCases {
        /// How many, all laws together.
        cases: usize,
    },
    /// Drawing the figures.
    DrawingFigures,
}
