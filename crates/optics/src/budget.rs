//! `optics render --tolerance T --metric M`: the accuracy budget's flags,
//! and its record. The budget itself is the library's
//! ([`validation::tradeoff::engine::render_within`]): a cheap pilot pass
//! measures what each candidate setting leaves out of the ground truth and
//! how noisy it is, the prediction bounds each candidate's error at each
//! sample count, and the cheapest in rays within `T` is rendered. With
//! `--verify` the render is measured against the ground truth the
//! trade-off sweep uses (its cache shared).

mod report;

use std::path::{Path, PathBuf};

use serde::Serialize;
use tracer::job::RenderJob;
use tracer::output::Destination;
use tracer::scene::MAX_SPP;
use validation::tradeoff::engine::{self, BudgetRequest};

pub use validation::tradeoff::engine::{Budget, Metric};

use crate::error::usage::{flag_number, FlagNumber};
use crate::error::{self, ErrorKind};
use crate::ui::Ui;

/// The budget's flags beside `render`'s.
#[derive(clap::Args, Debug, Serialize)]
pub struct BudgetArgs {
    /// Choose the cheapest settings whose predicted error (--metric) stays
    /// under this: a positive, finite number (a relative RMSE of 0.05 is 5 %).
    /// The budget chooses the integrator, spp, max_depth, the Fresnel law
    /// and the pixel filter: give none of them.
    #[arg(
        long,
        value_parser = tolerance_flag,
        requires = "metric",
        conflicts_with_all = ["integrator", "spp", "max_depth", "fresnel", "pixel_filter"]
    )]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// The measure the tolerance is of: the relative RMSE of linear
    /// radiance, or the mean or 99th percentile of ΔE2000 or the mean
    /// ꟻLIP of the displayed image, as `optics tradeoff` measures them.
    #[arg(long, value_enum, requires = "tolerance")]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub metric: Option<Metric>,
    /// Measure the error reached against the ground truth (rendered at
    /// --truth-spp, or read from its cache).
    #[arg(long, requires = "tolerance")]
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub verify: bool,
    /// Measure and render the scene with its course_rough materials made
    /// Lambert of albedo kd, the stand-in `optics tradeoff --lambert` uses
    /// (the course's kd is in 1/sr: its albedo π kd exceeds 1 and no
    /// truth converges); --verify then uses the matching truth.
    #[arg(long, requires = "tolerance")]
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub lambert: bool,
    /// Samples per pixel of the pilot pass, in two halves.
    #[arg(long, default_value_t = 8,
          value_parser = clap::value_parser!(u32).range(2..=1024))]
    pub pilot_spp: u32,
    /// Samples per pixel of the ground truth of --verify (two halves).
    #[arg(long, default_value_t = 1024,
          value_parser = clap::value_parser!(u32).range(2..=MAX_SPP as i64))]
    pub truth_spp: u32,
    /// Where the ground truth is cached (shared with `optics tradeoff`).
    #[arg(long, default_value = "validation/out/tradeoff/truth")]
    pub truth_cache: PathBuf,
}

/// `--tolerance`: a finite number above 0.
fn tolerance_flag(text: &str) -> FlagNumber {
    flag_number(
        text,
        |t| (t.is_finite() && t > 0.0) || tolerance_unchecked(),
        |t| {
            (
                format!("{t} is not a positive, finite tolerance"),
                format!("a(z) {t} nem pozitív, véges tűréshatár"),
            )
        },
    )
}

#[cfg(test)]
thread_local! {
    /// A test-only switch that reverts the check of `--tolerance`, for the
    /// budget-flags fuzz target to find.
    pub(crate) static TOLERANCE_UNCHECKED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

#[cfg(test)]
fn tolerance_unchecked() -> bool {
    TOLERANCE_UNCHECKED.get()
}

#[cfg(not(test))]
fn tolerance_unchecked() -> bool {
    false
}

impl BudgetArgs {
    /// The budget the flags ask for, `None` without `--tolerance`.
    pub fn settle(&self) -> Option<Budget> {
        let (tolerance, metric) = (self.tolerance?, self.metric?);
        Some(Budget { tolerance, metric })
    }
}

/// A budgeted render as `optics render` asks for it: the command's flags
/// (the record's inputs), the scene as it is to be measured, where the
/// image goes, the budget's own flags and the worker threads.
pub struct Asked<'a, I: Serialize> {
    /// The command's flags, as the record shows them.
    pub inputs: &'a I,
    /// The scene file, as given.
    pub scene: &'a Path,
    /// The scene, loaded as the budget measures it
    /// ([`engine::measured_scene`]).
    pub job: &'a RenderJob,
    /// The image's destination, as given.
    pub output: &'a Path,
    /// The budget's flags.
    pub flags: &'a BudgetArgs,
    /// Worker threads (all cores when `None`).
    pub threads: Option<usize>,
}

/// Renders the scene `asked` names at the cheapest settings within
/// `budget`, and prints the record.
pub fn run<I: Serialize>(asked: &Asked<'_, I>, budget: Budget, ui: &Ui) -> error::Result<()> {
    let flags = asked.flags;
    let destination = Destination::new(asked.output, &[asked.scene]).map_err(ErrorKind::Output)?;
    let request = BudgetRequest {
        scene: asked.scene,
        budget,
        pilot_spp: flags.pilot_spp,
        lambert: flags.lambert,
        truth_spp: flags.truth_spp,
        verify: flags.verify.then_some(flags.truth_cache.as_path()),
        threads: asked.threads,
    };
    let outcome = engine::render_within(asked.job, &request, &destination)?;
    report::show(asked.inputs, &destination, &outcome, ui)
}
