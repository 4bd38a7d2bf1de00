//! Why a sweep, a budget or one of their renders could not run: the
//! library's kinds, each naming the value that was wrong and never a
//! command-line flag (the front end that took the value adds its name).

use std::path::PathBuf;

use tracer::job::RenderError;

use super::budget::Need;
use super::jobs::JobError;
use crate::checkout::CheckoutError;
use crate::python::ToolError;
use tracer::output::OutputError;
use tracer::scene::SceneError;

/// A failure of the trade-off library.
#[derive(Debug, thiserror::Error)]
pub enum TradeoffError {
    /// The scene, or a setting a sweep gives it, that the tracer refused.
    #[error("scene {}: {error}", file.display())]
    Scene {
        /// The scene file, as given.
        file: PathBuf,
        /// The tracer's error.
        error: SceneError,
    },
    /// A render that could not run or finish.
    #[error(transparent)]
    Render(#[from] RenderError),
    /// A file (a cached truth, a record) that could not be written.
    #[error(transparent)]
    Output(OutputError),
    /// A record that could not be written as JSON; serde's message.
    #[error(transparent)]
    Encode(serde_json::Error),
    /// A sweep spread over machines: a job or result line refused, a job
    /// not in the plan, results missing or given twice.
    #[error(transparent)]
    Jobs(#[from] JobError),
    /// A sweep of a scene whose physical render is black (no light
    /// reaches the camera): there is no light transport to trade.
    #[error("scene {}: its physical render is black: no light reaches the camera, so there is no light transport to trade", file.display())]
    TruthIsBlack {
        /// The scene file, as given.
        file: PathBuf,
    },
    /// A budget that cannot be met, or not even bounded.
    #[error(transparent)]
    Budget(#[from] BudgetError),
    /// The Pareto plot cannot be drawn: no checkout to find its script in.
    #[error(transparent)]
    Checkout(CheckoutError),
    /// The Pareto plot cannot be drawn: there is no Python environment.
    #[error("no Python environment at {} (`optics validate` creates it once)", python.display())]
    NoPython {
        /// The interpreter looked for.
        python: PathBuf,
    },
    /// The Pareto plot's script failed.
    #[error(transparent)]
    Plot(ToolError),
}

/// Why the accuracy budget cannot render within its tolerance.
#[derive(Debug, thiserror::Error)]
pub enum BudgetError {
    /// No candidate is predicted to reach the tolerance.
    #[error(
        "cannot reach {metric} {tolerance}; the best is {metric} ≤ {best:.4}, with {settings}"
    )]
    Unreachable {
        /// The metric's name.
        metric: &'static str,
        /// The tolerance asked for.
        tolerance: f64,
        /// The smallest bound any candidate reaches.
        best: f64,
        /// Its settings, in words, at the most samples the budget renders
        /// it at.
        settings: String,
        /// Those samples per pixel (a power of two), `None` for a
        /// deterministic candidate.
        top_spp: Option<u32>,
        /// What it would need to reach the tolerance.
        need: Need,
    },
    /// The pilot cannot bound the light the truth carries
    /// above 0: black, or too noisy at its samples.
    #[error("a pilot of {pilot_spp} samples per pixel cannot tell the light on the surfaces from its noise")]
    PilotNoisy {
        /// The pilot's samples per pixel.
        pilot_spp: u32,
    },
    /// The scene's rough material reflects more light than
    /// it receives (the course's `π kd` above 1): its light grows with
    /// depth, no truth converges and no bound holds.
    #[error("material \"{material}\" reflects {gain:.2} times the light it receives, so no error can be bounded")]
    EnergyGain {
        /// The material's name in the scene file.
        material: String,
        /// What it reflects for what it receives (its largest channel).
        gain: f32,
    },
}
