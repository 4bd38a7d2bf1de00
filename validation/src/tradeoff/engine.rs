//! The trade-off sweep and the accuracy budget, run: what `optics
//! tradeoff`, `optics tradeoff-job` and `optics render --tolerance` do,
//! for any front end.
//!
//! A sweep is asked for by a [`SweepRequest`] and settled once
//! ([`Setup::new`]): the scene at its size, the surface pixels, the
//! points of [`super::sweep::plan`]. It renders here ([`render_here`],
//! progress through a callback) or as independent jobs that a scheduler
//! spreads over machines ([`plan_jobs`] writes them, [`run_job`] runs one,
//! [`collect`] merges their results); both end in the same measures
//! ([`measure_points`]) and the same files ([`write_sweep`]).
//!
//! The budget ([`render_within`]) renders a scene at the cheapest
//! settings predicted within a tolerance of a measure ([`Metric`]).

mod budget;
mod distribute;
mod measured;
mod metals;
mod predictor;
mod renders;
mod request;
mod second;
mod setup;
mod timing;
mod worker;
mod written;

pub use budget::{describe, render_within, Budget, BudgetRequest, Metric, Outcome};
pub use distribute::{accept, collect, plan_jobs, PlanWritten};
pub use measured::{measure_points, median, Grazing, Measured, Sweep};
pub use predictor::{terms, Predicted, Predictor, MAX_BUDGET_SPP};
pub use renders::{Collected, Provenance, Renders, Timed};
pub use request::SweepRequest;
pub use second::{markdown as mitsuba_markdown, table as mitsuba_table};
pub use setup::{measured_scene, Files, Setup};
pub use timing::{render_here, renders_wanted, Progress, MAX_RENDERS};
pub use worker::{job_line, run_job, JobRun};
pub use written::{front_marks, markdown, plot, verdicts, write_sweep, PLOT_SCRIPT};
