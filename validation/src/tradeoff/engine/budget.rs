//! The accuracy budget, run: a cheap pilot pass ([`pilot`]) measures, at
//! the render's own size, what each candidate setting leaves out of the
//! ground truth and how noisy it is; the prediction
//! ([`crate::tradeoff::budget`]) bounds each candidate's error at each
//! sample count, and the cheapest in rays within the tolerance is
//! rendered. Verified, the render is measured against the ground truth
//! the trade-off sweep uses (its cache shared).
//!
//! The relative RMSE of linear radiance is bounded from the pilot's sums
//! (its bias and noise add in squares); the displayed image's measures
//! (ΔE2000, ꟻLIP), which clamp and quantise, by simulating the final
//! render from the pilot and measuring it with the sweep's own code
//! ([`super::predictor`]).

use std::path::Path;

use serde::Serialize;
use tracer::job::RenderJob;
use tracer::output::Destination;
use tracer::scene::Settings;

use super::predictor::{self, Predicted, Predictor};
use crate::tradeoff::budget::displayed::Shown;
use crate::tradeoff::budget::{self, Bound, Choice};
use crate::tradeoff::error::{BudgetError, TradeoffError};
use crate::tradeoff::measure::{self, Mask};
use crate::tradeoff::{pilot, sweep, truth};

/// The fixed error measures a budget can name, as the sweep names them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "snake_case")]
pub enum Metric {
    /// Relative RMSE of linear radiance over the surface pixels.
    #[cfg_attr(feature = "clap", value(name = "rel_rmse"))]
    RelRmse,
    /// Mean ΔE2000 of the displayed image.
    #[cfg_attr(feature = "clap", value(name = "delta_e_mean"))]
    DeltaEMean,
    /// 99th percentile of ΔE2000 of the displayed image.
    #[cfg_attr(feature = "clap", value(name = "delta_e_p99"))]
    DeltaEP99,
    /// Mean ꟻLIP of the displayed image.
    #[cfg_attr(feature = "clap", value(name = "flip_mean"))]
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

/// A budget: a tolerance of a metric.
#[derive(Clone, Copy, Debug)]
pub struct Budget {
    /// The bound on the metric, above 0 and finite.
    pub tolerance: f64,
    /// The metric.
    pub metric: Metric,
}

/// A budgeted render as a front end asks for it.
#[derive(Clone, Copy, Debug)]
pub struct BudgetRequest<'a> {
    /// The scene file, as given (for its errors and the truth's cache).
    pub scene: &'a Path,
    /// The tolerance and its metric.
    pub budget: Budget,
    /// Samples per pixel of the pilot pass, in two halves.
    pub pilot_spp: u32,
    /// Whether course_rough is rendered and measured as Lambert.
    pub lambert: bool,
    /// Samples per pixel of the ground truth (two halves): the truth the
    /// displayed measures' simulation stands for, and the one the render
    /// is verified against.
    pub truth_spp: u32,
    /// The ground truth's cache, to measure the render against; `None`
    /// leaves it unmeasured.
    pub verify: Option<&'a Path>,
    /// Worker threads (all cores when `None`).
    pub threads: Option<usize>,
}

/// What the budget chose, and what it measured: the record's details.
#[derive(Debug, Serialize)]
pub struct Outcome {
    /// The tolerance and its metric.
    pub tolerance: f64,
    /// The metric.
    pub metric: Metric,
    /// Whether course_rough was rendered and measured as Lambert
    /// .
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

/// Renders `job` (the scene as [`super::measured_scene`] gives it) at the
/// cheapest settings predicted within `request`'s budget into
/// `destination`: what it chose, and why.
pub fn render_within(
    job: &RenderJob,
    request: &BudgetRequest<'_>,
    destination: &Destination,
) -> Result<Outcome, TradeoffError> {
    let budget = request.budget;
    if let Some((gain, material)) = job.scene().diffuse_gain() {
        return Err(BudgetError::EnergyGain {
            material: material.to_owned(),
            gain,
        }
        .into());
    }
    let mask = Mask::from_hits(&job.first_hits());
    let half = (request.pilot_spp / 2).max(1);
    let truth = pilot::truth_settings(job, half);
    let candidates = pilot::candidates(job, &truth);
    let pass = pilot::run(
        job,
        request.scene,
        (&truth, &candidates),
        (half, &mask, budget.metric.shown().is_some()),
        request.threads,
    )?;
    let predictor = predict(&pass, budget.metric, (half, &mask), request)?;
    let (choice, within) = predictor.choose(budget.tolerance);
    let choice = choice.expect("the truth's settings are always a candidate");
    let (index, predicted) = match choice {
        Choice::Chosen { index, prediction } => (index, prediction),
        Choice::Unreachable {
            index,
            prediction,
            need,
        } => {
            return Err(unreachable(
                budget,
                &candidates[index].settings,
                (prediction, need),
                half,
            )
            .into());
        }
    };
    let chosen = final_settings(&candidates[index].settings, predicted.spp(), half);
    let final_job = RenderJob::with_settings(job.scene().clone(), chosen).map_err(|error| {
        TradeoffError::Scene {
            file: request.scene.to_owned(),
            error,
        }
    })?;
    let rendered = final_job.render_to(destination, request.threads, &|_| {})?;
    let verified = match request.verify {
        Some(cache) => Some(verify(job, request, cache, &mask, &rendered.image)?),
        None => None,
    };
    Ok(Outcome {
        tolerance: budget.tolerance,
        metric: budget.metric,
        lambert: request.lambert,
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
    })
}

/// Why `budget` cannot be met: the candidate `settings` predicted
/// nearest, at the most samples the budget renders it at, and what it
/// would need.
fn unreachable(
    budget: Budget,
    settings: &Settings,
    (prediction, need): (Predicted, crate::tradeoff::budget::Need),
    half: u32,
) -> BudgetError {
    BudgetError::Unreachable {
        metric: budget.metric.name(),
        tolerance: budget.tolerance,
        best: prediction.bound(),
        settings: describe(&final_settings(settings, prediction.spp(), half)),
        top_spp: prediction.spp(),
        need,
    }
}

/// The predictor of `metric` from the pilot's pass, or why the pilot
/// cannot bound the light at all.
fn predict(
    pass: &pilot::Pass,
    metric: Metric,
    (half, mask): (u32, &Mask),
    request: &BudgetRequest<'_>,
) -> Result<Predictor, TradeoffError> {
    let [a, b] = &pass.reference;
    let energy = budget::energy([a, b], mask).ok_or(BudgetError::PilotNoisy {
        pilot_spp: 2 * half,
    })?;
    Ok(match metric.shown() {
        None => Predictor::rel_rmse(pass.pilots.clone(), energy),
        Some(shown) => Predictor::shown(
            shown,
            (&pass.reference, &pass.halves),
            &pass.pilots,
            (half, mask, request.truth_spp),
        ),
    })
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
    request: &BudgetRequest<'_>,
    cache: &Path,
    mask: &Mask,
    image: &tracer::render::Image,
) -> Result<measure::Errors, TradeoffError> {
    std::fs::create_dir_all(cache).map_err(|source| {
        TradeoffError::Output(
            safe_io::WriteError::Io {
                path: cache.display().to_string(),
                source,
            }
            .into(),
        )
    })?;
    let threads = request.threads;
    let request = truth::Request {
        scene_file: request.scene,
        spp: request.truth_spp,
        lambert: request.lambert,
        dir: cache,
        fresh: false,
    };
    let (truth, _) = truth::obtain(job, &request, mask, threads)?;
    Ok(measure::errors(std::slice::from_ref(image), &truth, mask))
}
