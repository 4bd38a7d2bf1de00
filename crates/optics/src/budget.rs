//! `optics render --tolerance T --metric M`: the accuracy budget. A cheap
//! pilot pass ([`pilot`]) measures, at the render's own size, what each
//! candidate setting leaves out of the ground truth and how noisy it is;
//! the prediction ([`validation::tradeoff::budget`]) bounds each
//! candidate's error at each sample count, and the cheapest in rays within
//! `T` is rendered. With `--verify` the render is measured against the
//! ground truth the trade-off sweep uses (its cache shared).
//!
//! The relative RMSE of linear radiance is bounded from the pilot's sums
//! (its bias and noise add in squares); the displayed image's measures
//! (ΔE2000, ꟻLIP), which clamp and quantise, by simulating the final
//! render from the pilot and measuring it with the sweep's own code
//! ([`predictor`]).

pub use validation::tradeoff::pilot;
pub mod predictor;
mod report;

use std::path::{Path, PathBuf};

use serde::Serialize;
use tracer::job::RenderJob;
use tracer::output::Destination;
use tracer::scene::{Settings, MAX_SPP};
use validation::tradeoff::budget::displayed::Shown;
use validation::tradeoff::budget::{self, Bound, Choice};
use validation::tradeoff::measure::{self, Mask};

use predictor::{Predicted, Predictor};

use crate::error::{self, ErrorKind};
use crate::render::RenderArgs;
use crate::tradeoff::{setup, sweep, truth};
use crate::ui::Ui;

/// The most samples per pixel the budget gives a candidate: 2^16.
pub const MAX_BUDGET_SPP: u32 = 1 << 16;

/// The fixed error measures a budget can name, as the sweep names them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Metric {
    /// Relative RMSE of linear radiance over the surface pixels.
    #[value(name = "rel_rmse")]
    RelRmse,
    /// Mean ΔE2000 of the displayed image.
    #[value(name = "delta_e_mean")]
    DeltaEMean,
    /// 99th percentile of ΔE2000 of the displayed image.
    #[value(name = "delta_e_p99")]
    DeltaEP99,
    /// Mean ꟻLIP of the displayed image.
    #[value(name = "flip_mean")]
    FlipMean,
}

impl Metric {
    /// Its name in the sweep's record (one of [`crate::tradeoff::MEASURES`]).
    pub fn name(self) -> &'static str {
        match self {
            Metric::RelRmse => "rel_rmse",
            Metric::DeltaEMean => "delta_e_mean",
            Metric::DeltaEP99 => "delta_e_p99",
            Metric::FlipMean => "flip_mean",
        }
    }

    /// The displayed image's measure it is, `None` for the relative RMSE.
    pub fn shown(self) -> Option<Shown> {
        match self {
            Metric::RelRmse => None,
            Metric::DeltaEMean => Some(Shown::DeltaEMean),
            Metric::DeltaEP99 => Some(Shown::DeltaEP99),
            Metric::FlipMean => Some(Shown::FlipMean),
        }
    }

    /// Its value among the sweep's measures.
    pub fn of(self, errors: &measure::Errors) -> f64 {
        self.shown()
            .map_or(errors.rel_rmse, |shown| shown.of(errors))
    }
}

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
fn tolerance_flag(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(t) if (t.is_finite() && t > 0.0) || tolerance_unchecked() => Ok(t),
        Ok(t) => Err(format!("{t} is not a positive, finite tolerance")),
        Err(e) => Err(e.to_string()),
    }
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

/// A budget settled from its flags: a tolerance of a metric.
#[derive(Clone, Copy, Debug)]
pub struct Budget {
    /// The bound on the metric, above 0 and finite.
    pub tolerance: f64,
    /// The metric.
    pub metric: Metric,
}

impl BudgetArgs {
    /// The budget the flags ask for, `None` without `--tolerance`.
    pub fn settle(&self) -> Option<Budget> {
        let (tolerance, metric) = (self.tolerance?, self.metric?);
        Some(Budget { tolerance, metric })
    }
}

/// What the budget chose, and what it measured: the record's details.
#[derive(Debug, Serialize)]
pub struct Outcome {
    /// The tolerance and its metric.
    pub tolerance: f64,
    /// The metric.
    pub metric: Metric,
    /// Whether course_rough was rendered and measured as Lambert
    /// (`--lambert`).
    pub lambert: bool,
    /// The settings rendered.
    pub chosen: Settings,
    /// What they leave out of the truth's settings.
    pub shortcut: pilot::Shortcut,
    /// Their prediction.
    pub predicted: Predicted,
    /// The terms measured alone (name, bound in the metric without the
    /// candidate's own noise).
    pub terms: Vec<(&'static str, f64)>,
    /// The scene's own settings at their own samples.
    pub scene: Predicted,
    /// Rays the rendered image cast.
    pub rays: u64,
    /// Rays the pilot pass cast.
    pub pilot_rays: u64,
    /// The pilot's samples per pixel (two halves).
    pub pilot_spp: u32,
    /// Every candidate, its settings and its cheapest prediction within
    /// the tolerance (none where it cannot reach it).
    pub candidates: Vec<(String, Option<Predicted>)>,
    /// The measures against the ground truth, with `--verify`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub verified: Option<measure::Errors>,
}

/// Renders `args`'s scene at the cheapest settings within `budget`.
pub fn run(args: &RenderArgs, budget: Budget, ui: &Ui) -> error::Result<()> {
    let flags = &args.budget;
    let job = args
        .job
        .job_of(&args.scene, |scene| setup::measured(scene, flags.lambert))?;
    if let Some((gain, material)) = job.scene().diffuse_gain() {
        return Err(ErrorKind::BudgetEnergyGain {
            material: material.to_owned(),
            gain,
        }
        .into());
    }
    let destination = Destination::new(&args.output, &[&args.scene]).map_err(ErrorKind::Output)?;
    let threads = args.threads.map(|t| t as usize);
    let mask = Mask::from_hits(&job.first_hits());
    let half = (flags.pilot_spp / 2).max(1);
    let truth = pilot::truth_settings(&job, half);
    let candidates = pilot::candidates(&job, &truth);
    let pass = pilot::run(
        &job,
        &args.scene,
        (&truth, &candidates),
        (half, &mask, budget.metric.shown().is_some()),
        threads,
    )?;
    let [a, b] = &pass.reference;
    let energy = budget::energy([a, b], &mask).ok_or(ErrorKind::BudgetPilotNoisy {
        pilot_spp: 2 * half,
    })?;
    let predictor = match budget.metric.shown() {
        None => Predictor::rel_rmse(pass.pilots.clone(), energy),
        Some(shown) => Predictor::shown(
            shown,
            (&pass.reference, &pass.halves),
            &pass.pilots,
            (half, &mask, flags.truth_spp),
        ),
    };
    let (choice, within) = predictor.choose(budget.tolerance);
    let choice = choice.expect("the truth's settings are always a candidate");
    let (index, predicted) = match choice {
        Choice::Chosen { index, prediction } => (index, prediction),
        Choice::Unreachable {
            index,
            prediction,
            need,
        } => {
            return Err(ErrorKind::BudgetUnreachable {
                metric: budget.metric.name(),
                tolerance: budget.tolerance,
                best: prediction.bound(),
                settings: describe(&final_settings(
                    &candidates[index].settings,
                    prediction.spp(),
                    half,
                )),
                top_spp: prediction.spp(),
                need,
            }
            .into());
        }
    };
    let chosen = final_settings(&candidates[index].settings, predicted.spp(), half);
    let final_job = RenderJob::with_settings(job.scene().clone(), chosen).map_err(|error| {
        ErrorKind::Scene {
            file: args.scene.clone(),
            error,
        }
    })?;
    let rendered = final_job.render_to(&destination, threads, &|_| {})?;
    let verified = if flags.verify {
        Some(verify(
            &job,
            flags,
            &args.scene,
            &mask,
            &rendered.image,
            threads,
        )?)
    } else {
        None
    };
    let outcome = Outcome {
        tolerance: budget.tolerance,
        metric: budget.metric,
        lambert: flags.lambert,
        chosen,
        shortcut: candidates[index].shortcut,
        predicted,
        terms: predictor::terms(&candidates, &predictor, index),
        scene: predictor.at(0, job.settings().spp),
        rays: rendered.rays.total(),
        pilot_rays: pass.rays,
        pilot_spp: 2 * half,
        candidates: candidates
            .iter()
            .zip(within)
            .map(|(c, best)| (describe(&c.settings), best))
            .collect(),
        verified,
    };
    report::show(args, &destination, &outcome, ui)
}

/// A candidate's settings at the samples its prediction took (the caustic
/// map's photons scaled alike), rendered with the seed after the pilot's
/// two.
fn final_settings(settings: &Settings, spp: Option<u32>, half_spp: u32) -> Settings {
    let at = match spp {
        Some(spp) => pilot::scaled_photons(settings, half_spp, spp),
        None => *settings,
    };
    Settings {
        seed: settings.seed.wrapping_add(2),
        ..at
    }
}

/// The settings in a few words, as the sweep writes them, and the
/// caustic map's photons where there is one.
pub fn describe(settings: &Settings) -> String {
    let words = sweep::describe(settings);
    if settings.integrator == tracer::scene::IntegratorKind::Photon {
        let p = &settings.photon;
        format!("{words}, {} photons × {} passes", p.photons, p.passes)
    } else {
        words
    }
}

/// The measures of `image` against the ground truth of the trade-off
/// sweep, from its cache where it holds it.
fn verify(
    job: &RenderJob,
    flags: &BudgetArgs,
    scene: &Path,
    mask: &Mask,
    image: &tracer::render::Image,
    threads: Option<usize>,
) -> error::Result<measure::Errors> {
    std::fs::create_dir_all(&flags.truth_cache).map_err(|source| {
        ErrorKind::Output(
            safe_io::WriteError::Io {
                path: flags.truth_cache.display().to_string(),
                source,
            }
            .into(),
        )
    })?;
    let request = truth::Request {
        scene_file: scene,
        spp: flags.truth_spp,
        lambert: flags.lambert,
        dir: &flags.truth_cache,
        fresh: false,
    };
    let (truth, _) = truth::obtain(job, &request, mask, threads)?;
    Ok(measure::errors(std::slice::from_ref(image), &truth, mask))
}
