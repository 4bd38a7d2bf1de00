//! `optics tradeoff-job JOBS INDEX`: runs one job of a planned sweep
//! ([`super::jobs`]) and writes its result line into `--out`, whole or
//! not at all, so that a job stopped half-way (Ctrl-C, a scheduler's time
//! limit) leaves no result and is run again.

use std::io::Read as _;
use std::path::{Path, PathBuf};

use serde::Serialize;
use tracer::scene::Settings;

use super::jobs::{self, Job, JobResult, Planned};
use super::{median, render, renders_wanted, Setup, TradeoffArgs, MAX_RENDERS};
use crate::error::jobs::{Input, JobError, LineKind, Place};
use crate::error::{self, ErrorKind};
use crate::ui::Ui;
use record::say;
use record::{Answer, Record};

#[derive(clap::Args, Debug, Serialize)]
#[command(after_help = "Examples:
  optics tradeoff crates/tracer/scenes/shadow.json --lambert --plan jobs.jsonl
  optics tradeoff-job jobs.jsonl 3 --out results
  parallel optics tradeoff-job jobs.jsonl {} --out results ::: $(seq 0 26)
  sed -n 4p jobs.jsonl | optics tradeoff-job - --out results

Writes RESULTS/job-NNNN.json (schema optics.tradeoff-result), one line;
`optics tradeoff SCENE [the plan's flags] --collect RESULTS` merges them.
See docs/cli.md, \"Spread a sweep over machines\".")]
pub struct TradeoffJobArgs {
    /// The plan (`optics tradeoff --plan`), JSON Lines; `-` reads stdin.
    #[arg(value_name = "JOBS")]
    pub jobs: PathBuf,
    /// The job to run: its line in JOBS, from 0 (needed when JOBS holds
    /// more than one line).
    #[arg(value_name = "INDEX")]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub index: Option<usize>,
    /// Directory for the result (created if missing).
    #[arg(long, short, default_value = "validation/out/tradeoff/results")]
    pub out: PathBuf,
    /// Worker threads (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub threads: Option<u32>,
}

/// Runs the job `args` names and writes its result.
pub fn run_job(args: &TradeoffJobArgs, ui: &Ui) -> error::Result<()> {
    let lang = ui.lang;
    let (text, at) = job_line(&args.jobs, args.index)?;
    let line: Job = jobs::read_line(&text, LineKind::Job, &at)?;
    let scene = PathBuf::from(&line.scene);
    if let Ok(bytes) = std::fs::read(&scene) {
        if jobs::scene_fnv1a(&bytes) != line.scene_fnv1a {
            return Err(JobError::SceneChanged { scene, at }.into());
        }
    }
    let sweep = TradeoffArgs {
        scene,
        width: Some(line.width),
        height: Some(line.height),
        spp: line.spp,
        truth_spp: line.truth_spp,
        repeats: line.repeats,
        min_seconds: line.min_seconds,
        out: args.out.clone(),
        lambert: line.lambert,
        fresh: false,
        no_plot: true,
        threads: args.threads,
        plan: None,
        collect: Vec::new(),
    };
    let setup = Setup::new(&sweep)?;
    let planned = Planned::new(&setup.key, &setup.job, &setup.plan);
    let index = planned.check(&line, &at)?;
    // Before any render is spent: a result with nowhere to go is refused now.
    std::fs::create_dir_all(&args.out).map_err(|source| {
        let error = safe_io::WriteError::Io {
            path: args.out.display().to_string(),
            source,
        };
        JobError::Write {
            input: Input::Out,
            error: error.into(),
        }
    })?;
    let result = run(&setup, &planned, index, &sweep, &line)?;

    let file = args.out.join(format!("job-{index:04}.json"));
    let json = serde_json::to_string(&result).map_err(ErrorKind::Encode)? + "\n";
    safe_io::write_atomically(&file, json.as_bytes()).map_err(|error| JobError::Write {
        input: Input::Out,
        error: error.into(),
    })?;

    let mut record = Record::new("tradeoff-job", String::new(), "");
    record
        .inputs_from(args)
        .set_answer(Answer::List(vec![file.display().to_string().into()]), None);
    let median_ms = median(&result.seconds) * 1e3;
    let renders = result.seconds.len();
    record.step(|| {
        say!(
            lang,
            "job {} of {}: {}: {} render(s), median {:.3} ms, {:.3e} rays each; written: {}",
            "{}. feladat ({} közül): {}: {} renderelés, medián {:.3} ms, egyenként {:.3e} sugár; kiírva: {}",
            index,
            line.jobs,
            line.label,
            renders,
            median_ms,
            result.rays / renders as f64,
            file.display()
        )
    });
    record
        .detail("job", index)
        .detail("label", &line.label)
        .detail("seconds", &result.seconds);
    ui.show_steps(&record)
}

/// The job's line: line `index` of `jobs` (stdin for `-`), or its only one.
fn job_line(jobs: &Path, index: Option<usize>) -> Result<(String, Place), JobError> {
    let read_error = |source| JobError::Read {
        input: Input::Jobs,
        path: jobs.to_owned(),
        source,
    };
    let text = if jobs == Path::new("-") {
        let mut text = String::new();
        std::io::stdin()
            .lock()
            .read_to_string(&mut text)
            .map_err(read_error)?;
        text
    } else {
        std::fs::read_to_string(jobs).map_err(read_error)?
    };
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
    args: &TradeoffArgs,
    line: &Job,
) -> error::Result<JobResult> {
    let first = planned.settings[index];
    let threads = args.threads.map(|t| t as usize);
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
        planned_as: super::command_line(args),
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
