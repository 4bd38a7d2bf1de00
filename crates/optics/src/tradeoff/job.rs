//! `optics tradeoff-job JOBS INDEX`: runs one job of a planned sweep
//! ([`validation::tradeoff::engine::run_job`]) and writes its result line
//! into `--out`, whole or not at all, so that a job stopped half-way
//! (Ctrl-C, a scheduler's time limit) leaves no result and is run again.

use std::io::Read as _;
use std::path::{Path, PathBuf};

use serde::Serialize;
use validation::tradeoff::engine;

use crate::error;
use crate::error::jobs::{Input, JobError};
use crate::ui::Ui;
use record::say;
use record::{Answer, Record};

/// `optics tradeoff-job`'s arguments.
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
    let text = read_plan(&args.jobs)?;
    let (line, at) = engine::job_line(&text, &args.jobs, args.index)?;
    let run = engine::run_job(&line, at, &args.out, args.threads.map(|t| t as usize))?;
    let (index, line, result) = (run.index, &run.line, &run.result);
    let mut record = Record::new("tradeoff-job", String::new(), "");
    record.inputs_from(args).set_answer(
        Answer::List(vec![run.file.display().to_string().into()]),
        None,
    );
    let median_ms = run.median_seconds() * 1e3;
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
            run.file.display()
        )
    });
    record
        .detail("job", index)
        .detail("label", &line.label)
        .detail("seconds", &result.seconds);
    ui.show_steps(&record)
}

/// The plan's text: the file `jobs`, or stdin for `-`.
fn read_plan(jobs: &Path) -> Result<String, JobError> {
    let read_error = |source| JobError::Read {
        input: Input::Jobs,
        path: jobs.to_owned(),
        source,
    };
    if jobs == Path::new("-") {
        let mut text = String::new();
        std::io::stdin()
            .lock()
            .read_to_string(&mut text)
            .map_err(read_error)?;
        Ok(text)
    } else {
        std::fs::read_to_string(jobs).map_err(read_error)
    }
}
