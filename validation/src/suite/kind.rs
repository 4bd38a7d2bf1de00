//! What a kind of check is.

use crate::context::Context;
use crate::reference::ReferenceError;
use crate::report::Report;

/// One kind of check.
pub trait CheckKind: Sync {
    /// A stable name, used in progress messages (`laws`, `colorimetry`).
    fn name(&self) -> &'static str;
    /// Its name in Hungarian, for progress messages under `--lang hu`.
    fn name_hu(&self) -> &'static str;
    /// Runs the checks, appending them and their data to `report`.
    fn run(&self, context: &Context, report: &mut Report) -> Result<(), ReferenceError>;
    /// Whether the report's figures (`python-checks/plot_report.py`) draw
    /// data this kind writes: the figures start once every kind that does
    /// has finished.
    fn feeds_figures(&self) -> bool {
        false
    }
    /// Whether it times something with the wall clock, and so runs alone,
    /// after the other kinds have finished ([`super::schedule::run_merged`]).
    fn measures_time(&self) -> bool {
        false
    }
}
