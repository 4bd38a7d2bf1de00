//! A sweep as independent render jobs, one JSON line each, for a
//! scheduler that is not ours (GNU parallel, a Slurm array, Ray): the job
//! line (`optics.tradeoff-job`), the result line a job writes
//! (`optics.tradeoff-result`), and the plan both are checked against.
//!
//! A job line says everything its job renders: the scene file and its
//! FNV-1a, the size, the sweep's flags, the point's label and settled
//! settings, and the plan's id (an FNV-1a of the scene's and of those
//! flags). The job runs by planning again from its own line and taking
//! its job from that plan, so a line edited since planning, a scene
//! changed since, or a build of optics that plans otherwise is refused by
//! name instead of rendering something else under the job's name.
//!
//! Jobs 0 and 1 are the two halves of the ground truth; jobs 2 onwards
//! the sweep's points in the sweep's order, the scene's own first.

mod english;
pub mod error;
mod line;
mod result;
#[cfg(test)]
mod tests;

pub use english::{listed, Named};
pub use error::{ImageProblem, Input, JobError, LineKind, Place, VERSION};
pub use line::read_line;
pub use result::{encode, JobResult, RESULT_FIELDS};

use serde::{Deserialize, Serialize};
use serde_json::Value;
use tracer::job::RenderJob;
use tracer::scene::Settings;

use super::{sweep, truth};

/// Jobs before the sweep's points: the truth's two halves.
pub const TRUTH_JOBS: usize = 2;

/// The most seeds of a Monte Carlo point whose images are kept for the
/// measures (the further renders are timed only).
pub const MAX_KEPT: usize = 8;

/// What a sweep is planned from: the scene and the flags that change
/// what is rendered or how often.
#[derive(Clone, Debug, PartialEq)]
pub struct PlanKey {
    /// The scene file, as given.
    pub scene: String,
    /// FNV-1a of its bytes, 16 hex digits.
    pub scene_fnv1a: String,
    /// `--lambert`.
    pub lambert: bool,
    /// The settled size, pixels.
    pub width: u32,
    /// The settled size, pixels.
    pub height: u32,
    /// `--spp`.
    pub spp: u32,
    /// `--truth-spp`.
    pub truth_spp: u32,
    /// `--repeats`.
    pub repeats: u32,
    /// `--min-seconds`.
    pub min_seconds: f64,
}

impl PlanKey {
    /// The plan's id: FNV-1a of the scene's, the flags and the tracer's
    /// version. `--min-seconds` enters to the microsecond, so that a value
    /// read back from JSON one unit in the last place off is the same plan.
    pub fn id(&self) -> String {
        let flags = format!(
            "{} {}x{} spp {} truth {} repeats {} min {:.6}",
            self.lambert,
            self.width,
            self.height,
            self.spp,
            self.truth_spp,
            self.repeats,
            self.min_seconds
        );
        format!(
            "{:016x}",
            truth::fnv1a(&[
                self.scene_fnv1a.as_bytes(),
                flags.as_bytes(),
                env!("CARGO_PKG_VERSION").as_bytes(),
            ])
        )
    }
}

/// FNV-1a of a scene file's bytes, as the lines carry it.
pub fn scene_fnv1a(bytes: &[u8]) -> String {
    format!("{:016x}", truth::fnv1a(&[bytes]))
}

/// One job: a line of the plan.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Job {
    /// `optics.tradeoff-job`.
    pub schema: String,
    /// [`VERSION`].
    pub version: u32,
    /// The plan's id ([`PlanKey::id`]).
    pub plan: String,
    /// This job, from 0.
    pub job: usize,
    /// The plan's jobs.
    pub jobs: usize,
    /// The scene file, as given to `--plan`.
    pub scene: String,
    /// FNV-1a of the scene file when planned.
    pub scene_fnv1a: String,
    /// `--lambert`.
    pub lambert: bool,
    /// Image width, pixels.
    pub width: u32,
    /// Image height, pixels.
    pub height: u32,
    /// `--spp`.
    pub spp: u32,
    /// `--truth-spp`.
    pub truth_spp: u32,
    /// `--repeats`: the fewest renders of a point.
    pub repeats: u32,
    /// `--min-seconds`: a point renders until its renders add up to this.
    pub min_seconds: f64,
    /// `truth` for the truth's halves, else the sweep's axis.
    pub axis: String,
    /// The setting in words, as the table prints it.
    pub label: String,
    /// The settings of its first render, settled (a Monte Carlo point's
    /// further renders take the next seeds).
    pub settings: Value,
}

impl Job {
    /// The plan key the line was planned from.
    pub fn key(&self) -> PlanKey {
        PlanKey {
            scene: self.scene.clone(),
            scene_fnv1a: self.scene_fnv1a.clone(),
            lambert: self.lambert,
            width: self.width,
            height: self.height,
            spp: self.spp,
            truth_spp: self.truth_spp,
            repeats: self.repeats,
            min_seconds: self.min_seconds,
        }
    }

    /// Whether it renders a half of the truth (once) rather than a point.
    pub fn is_truth(&self) -> bool {
        self.job < TRUTH_JOBS
    }
}

/// A plan: every job, with the settings each renders.
#[derive(Clone, Debug)]
pub struct Planned {
    /// The lines.
    pub jobs: Vec<Job>,
    /// Each job's settings, settled.
    pub settings: Vec<Settings>,
}

impl Planned {
    /// The jobs of `plan` (the sweep around `render`'s settings) under
    /// `key`: the truth's halves, then each point.
    pub fn new(key: &PlanKey, render: &RenderJob, plan: &sweep::Plan) -> Self {
        let half = sweep::truth_settings(render, (key.truth_spp / 2).max(1));
        let second = Settings {
            seed: half.seed.wrapping_add(1),
            ..half
        };
        let mut runs: Vec<(String, String, Settings)> = vec![
            ("truth".into(), "truth, half 1 of 2".into(), half),
            ("truth".into(), "truth, half 2 of 2".into(), second),
        ];
        for point in &plan.points {
            let axis = serde_json::to_value(point.axis)
                .ok()
                .and_then(|a| a.as_str().map(str::to_owned))
                .unwrap_or_default();
            runs.push((axis, point.label.clone(), point.settings));
        }
        let (id, count) = (key.id(), runs.len());
        let jobs = runs
            .iter()
            .enumerate()
            .map(|(job, (axis, label, settings))| Job {
                schema: LineKind::Job.schema().to_owned(),
                version: VERSION,
                plan: id.clone(),
                job,
                jobs: count,
                scene: key.scene.clone(),
                scene_fnv1a: key.scene_fnv1a.clone(),
                lambert: key.lambert,
                width: key.width,
                height: key.height,
                spp: key.spp,
                truth_spp: key.truth_spp,
                repeats: key.repeats,
                min_seconds: key.min_seconds,
                axis: axis.clone(),
                label: label.clone(),
                settings: serde_json::to_value(settings).unwrap_or_default(),
            })
            .collect();
        let settings = runs.into_iter().map(|(_, _, s)| s).collect();
        Planned { jobs, settings }
    }

    /// The job `line` names, if the plan has it and gives it every field
    /// the line gives; else the first field that differs.
    pub fn check(&self, line: &Job, at: &Place) -> Result<usize, JobError> {
        if line.job >= self.jobs.len() && !index_unchecked() {
            return Err(JobError::NoSuchJob {
                input: Input::Job,
                at: at.clone(),
                index: line.job,
                jobs: self.jobs.len(),
            });
        }
        let planned = &self.jobs[line.job];
        let (given, wanted) = (to_fields(line), to_fields(planned));
        for name in JOB_FIELDS {
            if !given
                .get(name)
                .is_some_and(|g| wanted.get(name).is_some_and(|w| same(g, w)))
            {
                return Err(JobError::NotPlanned {
                    at: at.clone(),
                    field: name,
                    job: planned.job,
                });
            }
        }
        Ok(line.job)
    }

    /// How many images job `job` keeps of `renders` renders: one for a
    /// deterministic setting (each render is the same image), the first
    /// [`MAX_KEPT`] seeds' for a Monte Carlo one.
    pub fn kept(&self, job: usize, renders: usize) -> usize {
        let keep = if self.settings[job].integrator.samples() && job >= TRUTH_JOBS {
            MAX_KEPT
        } else {
            1
        };
        renders.min(keep)
    }
}

/// The fields of a job line, by name, in the order [`Job`] declares them.
pub const JOB_FIELDS: [&str; 17] = [
    "schema",
    "version",
    "plan",
    "job",
    "jobs",
    "scene",
    "scene_fnv1a",
    "lambert",
    "width",
    "height",
    "spp",
    "truth_spp",
    "repeats",
    "min_seconds",
    "axis",
    "label",
    "settings",
];

fn to_fields(job: &Job) -> serde_json::Map<String, Value> {
    match serde_json::to_value(job) {
        Ok(Value::Object(map)) => map,
        _ => serde_json::Map::new(),
    }
}

/// Whether two JSON values are the same, numbers to 4 units in the last
/// place: serde_json reads a float back within one of what was written.
pub(crate) fn same(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => match (x.as_f64(), y.as_f64()) {
            (Some(x), Some(y)) => (x - y).abs() <= 4.0 * f64::EPSILON * x.abs().max(y.abs()),
            _ => x == y,
        },
        (Value::Array(x), Value::Array(y)) => {
            x.len() == y.len() && x.iter().zip(y).all(|(x, y)| same(x, y))
        }
        (Value::Object(x), Value::Object(y)) => {
            x.len() == y.len() && x.iter().all(|(k, v)| y.get(k).is_some_and(|w| same(v, w)))
        }
        _ => a == b,
    }
}

#[cfg(any(test, feature = "faults"))]
thread_local! {
    /// A test-only switch that reverts the check of a job line's index
    /// against its plan, for the tradeoff-jobs fuzz target to find.
    pub static INDEX_UNCHECKED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

#[cfg(any(test, feature = "faults"))]
fn index_unchecked() -> bool {
    INDEX_UNCHECKED.get()
}

#[cfg(not(any(test, feature = "faults")))]
fn index_unchecked() -> bool {
    false
}
