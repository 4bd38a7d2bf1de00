//! One job of a planned sweep ([`crate::tradeoff::jobs`]), run: its result
//! line written into a directory, whole or not at all, so that a job
//! stopped half-way (Ctrl-C, a scheduler's time limit) leaves no result
//! and is run again.

use std::path::{Path, PathBuf};

use tracer::scene::Settings;

use super::measured::median;
use super::request::SweepRequest;
use super::setup::Setup;
use super::timing::{renders_wanted, MAX_RENDERS};
use crate::checkout::Lookup;
use crate::tradeoff::error::TradeoffError;
use crate::tradeoff::jobs::{self, Input, Job, JobError, JobResult, LineKind, Place, Planned};
use crate::tradeoff::render::render;

/// A job run: its line, its index, its result and where it was written.
#[derive(Debug)]
pub struct JobRun {
    /// The job's line.
    pub line: Job,
    /// Its index in the plan.
    pub index: usize,
    /// What it measured.
    pub result: JobResult,
    /// The result's file.
    pub file: PathBuf,
}

impl JobRun {
    /// The median of its render times, s.
    pub fn median_seconds(&self) -> f64 {
        median(&self.result.seconds)
    }
}

/// Runs the job `text` (the line read from `at`) and writes its result
/// into `out` as `job-NNNN.json`, with `threads` worker threads.
pub fn run_job(
    text: &str,
    at: Place,
    out: &Path,
    threads: Option<usize>,
) -> Result<JobRun, TradeoffError> {
    // A job renders and times; it reads no reference.
    let checkout = Lookup::default();
    let line: Job = jobs::read_line(text, LineKind::Job, &at)?;
    let scene = PathBuf::from(&line.scene);
    if let Ok(bytes) = std::fs::read(&scene) {
        if jobs::scene_fnv1a(&bytes) != line.scene_fnv1a {
            return Err(JobError::SceneChanged { scene, at }.into());
        }
    }
    let sweep = SweepRequest {
        scene,
        width: Some(line.width),
        height: Some(line.height),
        spp: line.spp,
        truth_spp: line.truth_spp,
        repeats: line.repeats,
        min_seconds: line.min_seconds,
        out: out.to_owned(),
        lambert: line.lambert,
        fresh: false,
        threads,
        checkout,
    };
    let setup = Setup::new(&sweep)?;
    let planned = Planned::new(&setup.key, &setup.job, &setup.plan);
    let index = planned.check(&line, &at)?;
    // Before any render is spent: a result with nowhere to go is refused now.
    std::fs::create_dir_all(out).map_err(|source| {
        let error = safe_io::WriteError::Io {
            path: out.display().to_string(),
            source,
        };
        JobError::Write {
            input: Input::Out,
            error: error.into(),
        }
    })?;
    let result = run(&setup, &planned, index, &sweep, &line)?;
    let file = out.join(format!("job-{index:04}.json"));
    let json = serde_json::to_string(&result).map_err(TradeoffError::Encode)? + "\n";
    safe_io::write_atomically(&file, json.as_bytes()).map_err(|error| JobError::Write {
        input: Input::Out,
        error: error.into(),
    })?;
    Ok(JobRun {
        line,
        index,
        result,
        file,
    })
}

/// The job's line in `text`, the plan read from `jobs`: line `index`, or
/// its only one.
pub fn job_line(
    text: &str,
    jobs: &Path,
    index: Option<usize>,
) -> Result<(String, Place), JobError> {
    let lines: Vec<&str> = text.lines().collect();
    let index = match (index, lines.len()) {
        (Some(index), _) => index,
        (None, 1) => 0,
        (None, count) => {
            return Err(JobError::IndexNeeded {
                path: jobs.to_owned(),
                lines: count,
            })
        }
    };
    let at = Place {
        path: jobs.to_owned(),
        line: index + 1,
    };
    let Some(line) = lines.get(index) else {
        return Err(JobError::NoSuchJob {
            input: Input::Index,
            at,
            index,
            jobs: lines.len(),
        });
    };
    Ok(((*line).to_owned(), at))
}

/// Renders job `index`: a truth half once; a point after one untimed
/// warm-up render, as many times as a sweep in one run renders it, each
/// with the next seed.
fn run(
    setup: &Setup,
    planned: &Planned,
    index: usize,
    args: &SweepRequest,
    line: &Job,
) -> Result<JobResult, TradeoffError> {
    let first = planned.settings[index];
    let threads = args.threads;
    let truth = line.is_truth();
    if !truth {
        render(&setup.job, &args.scene, first, threads)?;
    }
    let (mut seconds, mut rays, mut images) = (Vec::new(), 0.0, Vec::new());
    let mut wanted = if truth { 1 } else { args.repeats as usize };
    for round in 0..MAX_RENDERS {
        if seconds.len() >= wanted {
            break;
        }
        let settings = Settings {
            seed: first.seed.wrapping_add(round as u64),
            ..first
        };
        let rendered = render(&setup.job, &args.scene, settings, threads)?;
        seconds.push(rendered.elapsed.as_secs_f64());
        rays += rendered.rays.total() as f64;
        if images.len() < planned.kept(index, usize::MAX) {
            images.push(jobs::encode(&rendered.image));
        }
        if round == 0 && !truth {
            wanted = renders_wanted(seconds[0], args.repeats, args.min_seconds);
        }
    }
    Ok(JobResult {
        schema: LineKind::Result.schema().to_owned(),
        version: jobs::VERSION,
        plan: line.plan.clone(),
        planned_as: args.command_line(),
        scene_fnv1a: line.scene_fnv1a.clone(),
        job: index,
        jobs: line.jobs,
        label: line.label.clone(),
        seconds,
        rays,
        machine: results::machine(),
        date: results::today(),
        load: results::load(),
        images,
    })
}
