//! `optics tradeoff`: what each shortcut a scene allows costs in accuracy
//! and buys in time, measured on whole renders against a converged ground
//! truth with all the light, by fixed error measures
//! ([`validation::tradeoff::measure`]). The sweep itself is the library's
//! ([`validation::tradeoff::engine`]); this module parses its flags,
//! shows its progress and prints its record.
//!
//! A sweep renders here, in one run, or as independent jobs that a
//! scheduler spreads over machines: `--plan` writes them, `optics
//! tradeoff-job` runs one, `--collect` merges their results;
//! both end in the same measures and the same record.

mod args;
mod job;
mod report;

#[cfg(test)]
pub(crate) use args::SECONDS_UNCHECKED;
pub use args::{Mode, TradeoffArgs};
pub use job::{run_job, TradeoffJobArgs};

use validation::tradeoff::engine::{self, Progress, Setup};

use crate::error;
use crate::ui::Ui;

/// Runs the sweep `args` asks for, in the mode it asks for, and prints
/// its record.
pub fn run(args: &TradeoffArgs, ui: &Ui) -> error::Result<()> {
    let request = args.request();
    let setup = Setup::new(&request)?;
    let mode = args.mode();
    if let Mode::Plan(jobs) = mode {
        let written = engine::plan_jobs(&setup, &request, jobs)?;
        return report::show_plan(&setup, args, (jobs, written), ui);
    }
    setup.files.prepare(&args.scene)?;
    let truth_dir = setup.files.truth_dir();
    let truth = setup.truth_request(&request, &truth_dir);
    let renders = match mode {
        Mode::Collect(results) => engine::collect(&setup, &truth, results)?,
        _ => {
            let bar = progress_bar(setup.plan.points.len() as u64 + 1);
            engine::render_here(&setup, &request, &truth, &|step| bar.tell(step))?
        }
    };
    let sweep = engine::measure_points(setup, &request, renders)?;
    report::write_and_show(&sweep, args, &request.checkout, ui)
}

/// The sweep's progress bar on a terminal, nothing elsewhere.
struct Bar(Option<indicatif::ProgressBar>);

/// A progress bar of `steps` steps: the truth, then each setting.
fn progress_bar(steps: u64) -> Bar {
    Bar(crate::render::progress_bar(steps).inspect(|bar| {
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "{bar:40} {pos}/{len} settings, {eta} left: {msg}",
            )
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
    }))
}

impl Bar {
    /// Shows `step`.
    fn tell(&self, step: Progress<'_>) {
        let Some(bar) = &self.0 else {
            return;
        };
        match step {
            Progress::Truth => bar.set_message("ground truth"),
            Progress::Point(label) => {
                bar.inc(1);
                bar.set_message(label.to_owned());
            }
            Progress::Done => bar.finish_and_clear(),
        }
    }
}
