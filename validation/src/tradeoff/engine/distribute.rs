//! A sweep spread over machines by a scheduler that is not ours:
//! [`plan_jobs`] writes its jobs ([`crate::tradeoff::jobs`]),
//! [`super::run_job`] runs one, and [`collect`] merges their results into
//! the record a sweep in one run writes, measured by the same fixed
//! measures against the truth the two halves' jobs rendered.
//!
//! Collecting refuses, naming the file, the line and the job: results
//! missing or given twice, of another schema or version, of another plan
//! (another scene, size or flags) or of a scene file changed since.

use std::path::{Path, PathBuf};

use super::renders::{Collected, Provenance, Renders, Timed};
use super::request::SweepRequest;
use super::setup::Setup;
use crate::tradeoff::error::TradeoffError;
use crate::tradeoff::jobs::{
    self, Input, JobError, JobResult, LineKind, Place, Planned, TRUTH_JOBS,
};
use crate::tradeoff::truth;

/// A sweep's plan, written: how many jobs it holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlanWritten {
    /// The jobs, one line each: the truth's two halves, then each point.
    pub jobs: usize,
}

/// Writes the sweep's jobs to `path`, one line each, whole or not at all.
pub fn plan_jobs(
    setup: &Setup,
    args: &SweepRequest,
    path: &Path,
) -> Result<PlanWritten, TradeoffError> {
    let refused = |error: safe_io::WriteError| {
        TradeoffError::Jobs(JobError::Write {
            input: Input::Plan,
            error: error.into(),
        })
    };
    // The rename would replace a FIFO, device node, directory or link, or
    // the scene itself, with the plan.
    safe_io::check_destination(path, &[&args.scene]).map_err(refused)?;
    let planned = Planned::new(&setup.key, &setup.job, &setup.plan);
    let mut text = String::new();
    for job in &planned.jobs {
        text += &serde_json::to_string(job).map_err(TradeoffError::Encode)?;
        text += "\n";
    }
    safe_io::write_atomically(path, text.as_bytes()).map_err(refused)?;
    Ok(PlanWritten {
        jobs: planned.jobs.len(),
    })
}

/// Every job's result in `results` (files, or directories of them),
/// checked against this sweep's plan, merged; the truth's halves cached as
/// a sweep in one run caches them.
pub fn collect(
    setup: &Setup,
    request: &truth::Request<'_>,
    results: &[PathBuf],
) -> Result<Renders, TradeoffError> {
    let planned = Planned::new(&setup.key, &setup.job, &setup.plan);
    let mut slots: Vec<Option<(Place, JobResult)>> = vec![None; planned.jobs.len()];
    for file in result_files(results)? {
        let text = std::fs::read_to_string(&file).map_err(|source| JobError::Read {
            input: Input::Collect,
            path: file.clone(),
            source,
        })?;
        for (i, line) in text.lines().enumerate() {
            if line.trim().is_empty() {
                continue;
            }
            let at = Place {
                path: file.clone(),
                line: i + 1,
            };
            let result: JobResult = jobs::read_line(line, LineKind::Result, &at)?;
            let job = accept(&planned, setup, &result, &at)?;
            if let Some((first, _)) = &slots[job] {
                return Err(JobError::Duplicate {
                    job,
                    first: first.clone(),
                    second: at,
                }
                .into());
            }
            slots[job] = Some((at, result));
        }
    }
    let missing: Vec<(usize, String)> = slots
        .iter()
        .enumerate()
        .filter(|(_, slot)| slot.is_none())
        .map(|(job, _)| (job, planned.jobs[job].label.clone()))
        .collect();
    if !missing.is_empty() {
        return Err(JobError::Missing {
            count: missing.len(),
            jobs: missing.into_iter().take(5).collect(),
            of: planned.jobs.len(),
        }
        .into());
    }
    let size = (setup.key.width, setup.key.height);
    let mut timed = Vec::with_capacity(slots.len());
    let mut ran = Vec::with_capacity(slots.len());
    for (job, slot) in slots.into_iter().enumerate() {
        let (at, result) = slot.expect("every job has a result: checked above");
        let kept = planned.kept(job, result.seconds.len());
        timed.push(Timed {
            images: result.images(&at, kept, size)?,
            seconds: result.seconds.clone(),
            rays: result.rays,
        });
        ran.push(result);
    }
    let points = timed.split_off(TRUTH_JOBS);
    let [a, b] = <[Timed; TRUTH_JOBS]>::try_from(timed)
        .unwrap_or_else(|_| unreachable!("the plan opens with the truth's two halves"));
    let seconds = a.seconds[0] + b.seconds[0];
    let cache = truth::Cache::new(&setup.job, request)?;
    let (truth, record) = cache.store(
        a.images.into_iter().next().expect("one image: checked"),
        b.images.into_iter().next().expect("one image: checked"),
        seconds,
        &setup.mask,
    )?;
    Ok((truth, record, points, provenance(&ran, setup.key.id())))
}

/// The job `result` is of, if it is one of this sweep's plan.
pub fn accept(
    planned: &Planned,
    setup: &Setup,
    result: &JobResult,
    at: &Place,
) -> Result<usize, JobError> {
    if result.scene_fnv1a != setup.key.scene_fnv1a {
        return Err(JobError::SceneChanged {
            scene: setup.key.scene.clone().into(),
            at: at.clone(),
        });
    }
    let expected = setup.key.id();
    if result.plan != expected {
        return Err(JobError::OtherPlan {
            at: at.clone(),
            found: result.plan.clone(),
            planned_as: result.planned_as.clone(),
            expected,
        });
    }
    let Some(job) = planned.jobs.get(result.job) else {
        return Err(JobError::NoSuchJob {
            input: Input::Job,
            at: at.clone(),
            index: result.job,
            jobs: planned.jobs.len(),
        });
    };
    let differs = [
        ("jobs", result.jobs != job.jobs),
        ("label", result.label != job.label),
    ];
    if let Some((field, _)) = differs.iter().find(|(_, differs)| *differs) {
        return Err(JobError::NotPlanned {
            at: at.clone(),
            field,
            job: result.job,
        });
    }
    Ok(result.job)
}

/// The result files `paths` name: each file itself, each directory's
/// `*.json` and `*.jsonl` in name order.
fn result_files(paths: &[PathBuf]) -> Result<Vec<PathBuf>, JobError> {
    let mut files = Vec::new();
    for path in paths {
        if !path.is_dir() {
            files.push(path.clone());
            continue;
        }
        let read_error = |source| JobError::Read {
            input: Input::Collect,
            path: path.clone(),
            source,
        };
        let mut found: Vec<PathBuf> = std::fs::read_dir(path)
            .map_err(read_error)?
            .filter_map(|entry| entry.ok().map(|e| e.path()))
            .filter(|p| p.is_file() && p.extension().is_some_and(|e| e == "json" || e == "jsonl"))
            .collect();
        if found.is_empty() {
            return Err(JobError::NoResults { path: path.clone() });
        }
        found.sort();
        files.extend(found);
    }
    Ok(files)
}

/// Where the jobs ran: their machines, days and loads, summed up.
fn provenance(results: &[JobResult], plan: String) -> Provenance {
    let mut machines: Vec<String> = Vec::new();
    for r in results {
        if !machines.contains(&r.machine) {
            machines.push(r.machine.clone());
        }
    }
    let mut dates: Vec<&str> = results.iter().map(|r| r.date.as_str()).collect();
    dates.sort_unstable();
    dates.dedup();
    let date = match dates.as_slice() {
        [] => String::new(),
        [one] => (*one).to_owned(),
        [first, .., last] => format!("{first} to {last}"),
    };
    let loads: Vec<f64> = results
        .iter()
        .filter_map(|r| r.load.as_deref()?.rsplit(' ').next()?.parse().ok())
        .collect();
    let load = (!loads.is_empty()).then(|| {
        let (lo, hi) = loads
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &l| {
                (lo.min(l), hi.max(l))
            });
        format!("load average {lo} to {hi} as the jobs ended")
    });
    let machine = match machines.as_slice() {
        [one] => one.clone(),
        many => format!("{} machines: {}", many.len(), many.join("; ")),
    };
    Provenance {
        machine,
        date,
        load,
        collected: Some(Collected {
            plan,
            jobs: results.len(),
            machines,
        }),
    }
}
