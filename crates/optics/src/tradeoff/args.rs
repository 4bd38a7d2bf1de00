//! `optics tradeoff`'s flags, and the sweep and mode they ask for.

use std::path::{Path, PathBuf};

use crate::error::usage::{flag_number, FlagNumber};
use crate::image_size::ImageSize;
use serde::Serialize;
use tracer::scene::MAX_SPP;
use validation::tradeoff::engine::SweepRequest;

/// `optics tradeoff`'s flags.
#[derive(clap::Args, Debug, Serialize)]
#[command(after_help = "Examples:
  optics tradeoff crates/tracer/scenes/kaleidoscope_lit.json --width 160 --height 120
  optics --json tradeoff crates/tracer/scenes/gold_spheres.json --repeats 5 --out /tmp/gold
  optics tradeoff crates/tracer/scenes/shadow.json --lambert --plan jobs.jsonl
  optics tradeoff crates/tracer/scenes/shadow.json --lambert --collect results

Writes SCENE.json (schema optics.tradeoff), SCENE.md (the table) and
SCENE-pareto.png (time against each error, log-log) into --out, and caches
the ground truth under --out/truth. See docs/tradeoffs.md for the measures.
--plan writes the sweep's render jobs instead (run each with `optics
tradeoff-job`), and --collect merges their results: docs/cli.md, \"Spread a
sweep over machines\".")]
pub struct TradeoffArgs {
    /// The scene file (JSON, see docs/scene-schema.md).
    pub scene: PathBuf,
    /// The image's size, where it overrides the scene's.
    #[command(flatten)]
    #[serde(flatten)]
    pub size: ImageSize,
    /// Samples per pixel of the Monte Carlo integrators on the ladder when
    /// the scene's own integrator is deterministic.
    #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u32).range(1..=MAX_SPP as i64))]
    pub spp: u32,
    /// Samples per pixel of the ground truth (two halves of half as many).
    #[arg(long, default_value_t = 1024, value_parser = clap::value_parser!(u32).range(2..=MAX_SPP as i64))]
    pub truth_spp: u32,
    /// Renders per setting: the time is their median; Monte Carlo settings
    /// take a new seed each, and two or more split variance from bias.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..=100))]
    pub repeats: u32,
    /// Render each setting until its renders add up to this many seconds
    /// (at most 64 renders), for a steadier median.
    #[arg(long, default_value_t = 0.5, value_parser = seconds_flag)]
    pub min_seconds: f64,
    /// Directory for the results and the truth's cache (created if missing).
    #[arg(long, short, default_value = "validation/out/tradeoff")]
    pub out: PathBuf,
    /// Measure the scene with its course_rough materials made Lambert of
    /// albedo kd, the suite's energy-conserving stand-in (the course's kd is
    /// in 1/sr: its diffuse albedo is π kd, up to 2.5 in the course scenes,
    /// and light multiplies between surfaces that see each other).
    #[arg(long)]
    pub lambert: bool,
    /// Render the ground truth again even when a cached one matches.
    #[arg(long)]
    pub fresh: bool,
    /// Do not draw the Pareto plot (it needs .venv's matplotlib).
    #[arg(long)]
    pub no_plot: bool,
    /// Worker threads (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub threads: Option<u32>,
    /// Render nothing: write the sweep as independent jobs, one JSON line
    /// each, to this file, for `optics tradeoff-job` to run anywhere.
    #[arg(long, value_name = "JOBS.jsonl", conflicts_with = "collect")]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plan: Option<PathBuf>,
    /// Render nothing: merge the results of the plan's jobs (directories
    /// of result files, or the files) into the sweep's record; give the
    /// scene and the flags given to --plan.
    #[arg(long, value_name = "RESULTS", num_args = 1..)]
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub collect: Vec<PathBuf>,
}

/// What `optics tradeoff` does, settled from its flags once.
#[derive(Debug, PartialEq)]
pub enum Mode<'a> {
    /// Render and measure the sweep here.
    Sweep,
    /// Write its jobs to this file (`--plan`).
    Plan(&'a Path),
    /// Measure the results of its jobs (`--collect`).
    Collect(&'a [PathBuf]),
}

impl TradeoffArgs {
    /// The sweep the flags ask for.
    pub fn request(&self) -> SweepRequest {
        SweepRequest {
            scene: self.scene.clone(),
            width: self.size.width,
            height: self.size.height,
            spp: self.spp,
            truth_spp: self.truth_spp,
            repeats: self.repeats,
            min_seconds: self.min_seconds,
            out: self.out.clone(),
            lambert: self.lambert,
            fresh: self.fresh,
            threads: self.threads.map(|t| t as usize),
            checkout: crate::checkout::lookup(None),
        }
    }

    /// The mode the flags ask for (clap refuses `--plan` with `--collect`).
    pub fn mode(&self) -> Mode<'_> {
        match (&self.plan, self.collect.as_slice()) {
            (Some(jobs), _) => Mode::Plan(jobs),
            (None, []) => Mode::Sweep,
            (None, results) => Mode::Collect(results),
        }
    }
}

/// `--min-seconds`: a finite number of seconds, 0 to 60.
fn seconds_flag(text: &str) -> FlagNumber {
    flag_number(
        text,
        |s| (0.0..=60.0).contains(&s) || seconds_unchecked(),
        |s| {
            (
                format!("{s} is not between 0 and 60 seconds"),
                format!("a(z) {s} nem 0 és 60 másodperc közé esik"),
            )
        },
    )
}

#[cfg(test)]
thread_local! {
    /// A test-only switch that reverts the range check of `--min-seconds`,
    /// for the tradeoff-flags fuzz target to find.
    pub(crate) static SECONDS_UNCHECKED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

#[cfg(test)]
fn seconds_unchecked() -> bool {
    SECONDS_UNCHECKED.get()
}

#[cfg(not(test))]
fn seconds_unchecked() -> bool {
    false
}
