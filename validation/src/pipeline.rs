//! The whole harness as one call: set up the pinned Python environment,
//! regenerate the references (or take the committed ones), run every check,
//! have Mitsuba evaluate random cases, and write `report.json`,
//! `report.html` and the figures.
//!
//! ```no_run
//! use validation::checkout::Checkout;
//! use validation::pipeline::{self, Options};
//!
//! let options = Options::quick(Checkout::at_build_time(), "example");
//! let outcome = pipeline::run(&options, |step| eprintln!("{step:?}"))?;
//! println!("{} checks passed: {}", outcome.report.checks.len(), outcome.passed());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Every file is written to a temporary name beside it and renamed into
//! place (`safe_io::write_atomically`), so an interrupted run never
//! leaves a partial report. The destinations are checked before any check
//! runs ([`check_outputs`]), the figures are written before the report, and
//! `report.json` and `report.html` are renamed into place as one pair
//! (`safe_io::write_all_atomically`): never one without the other.

use std::path::{Path, PathBuf};

use safe_io::{check_destination, writable_directory, write_all_atomically};
use tracer::output::OutputError;

use crate::regenerate::regenerate;
use crate::report::Report;
use crate::report::{to_html, to_json};
use crate::suite::schedule::Merge;
use crate::suite::{self, Context};

use files::create_dir;
use python_side::{
    copy_tradeoff_plots, draw_figures, exchange_report, figures_or_report, random_cases,
    set_up_python, write_render_figures,
};

/// What a run produced.
#[derive(Debug)]
pub struct Outcome {
    /// Every check, summarised.
    pub report: Report,
    /// The directory written.
    pub out: PathBuf,
    /// The figures, relative to `out`.
    pub figures: Vec<String>,
}

impl Outcome {
    /// Whether every check passed.
    pub fn passed(&self) -> bool {
        self.report.passed()
    }

    /// `report.json`.
    pub fn report_json(&self) -> PathBuf {
        self.out.join("report.json")
    }

    /// `report.html`.
    pub fn report_html(&self) -> PathBuf {
        self.out.join("report.html")
    }
}

/// Runs the harness as `options` say; `progress` hears of each step.
pub fn run(options: &Options, mut progress: impl FnMut(Step)) -> Result<Outcome, PipelineError> {
    let checkout = &options.checkout;
    let scripts = checkout.python_checks();
    let out = options
        .out
        .clone()
        .unwrap_or_else(|| checkout.root().join("validation/out"));
    check_outputs(&out)?;
    let python = (options.python.as_ref())
        .map(|setup| set_up_python(checkout, setup, &mut progress))
        .transpose()?;
    let (reference_dir, mut first_checks) =
        references(options, python.as_deref(), &out, &mut progress)?;
    let context = Context {
        reference_dir,
        checkout: checkout.root().to_owned(),
        quick: options.quick,
    };
    let kinds = suite::standard_kinds();
    let total = kinds.len();
    let mut report = Report::new(options.quick, &options.command);
    // The Python side runs beside the checks: Mitsuba's evaluation of the
    // random cases needs none of them, and the figures only the data of the
    // kinds that feed them, so each starts as soon as it can.
    let (random, drawn) = std::thread::scope(|scope| -> Result<_, PipelineError> {
        let random = python.as_ref().map(|python| {
            let count = RANDOM_CASES[usize::from(!options.quick)];
            progress(Step::RandomCases { cases: 3 * count });
            let (scripts, out) = (&scripts, &out);
            scope.spawn(move || random_cases(python, scripts, out, options.seed, count))
        });
        let mut drawing = None;
        suite::schedule::run_merged(&kinds, &context, &mut report, |step| {
            match step {
                Merge::Awaiting { index, names } => progress(Step::Checks {
                    index,
                    total,
                    names,
                }),
                Merge::FigureData { report } => {
                    if let Some(python) = &python {
                        progress(Step::DrawingFigures);
                        exchange_report(&out, report)?;
                        let (scripts, out) = (&scripts, &out);
                        drawing = Some(scope.spawn(move || draw_figures(python, scripts, out)));
                    }
                }
            }
            Ok::<(), PipelineError>(())
        })?;
        progress(Step::ChecksDone);
        // Neither thread panics: their errors are values.
        let random = random.map(|h| h.join().expect("the random cases' thread"));
        let drawn = drawing.map(|h| h.join().expect("the figures' thread"));
        Ok((random, drawn))
    })?;
    if let Some(random) = random {
        first_checks.push(random?);
    }
    report.checks.splice(0..0, first_checks);
    report.summarise();
    let mut figures = match drawn {
        Some(drawn) => figures_or_report(drawn, &mut report),
        None => Vec::new(),
    };
    figures.extend(write_render_figures(&out, &report)?);
    figures.extend(copy_tradeoff_plots(checkout, &out, &report)?);
    report.word_tradeoffs();
    let (json, html) = (to_json(&report), to_html(&report, &figures, options.lang));
    write_all_atomically(&[
        (&out.join("report.json"), json.as_bytes()),
        (&out.join("report.html"), html.as_bytes()),
    ])
    .map_err(OutputError::from)?;
    Ok(Outcome {
        report,
        out,
        figures,
    })
}

/// The references the checks read, and the regeneration's check: the
/// committed ones under `--quick` or without Python; else each one current
/// by its key or regenerated into `out/reference` (`crate::regenerate`).
fn references(
    options: &Options,
    python: Option<&Path>,
    out: &Path,
    progress: &mut impl FnMut(Step),
) -> Result<(PathBuf, Vec<crate::check::Check>), PipelineError> {
    let checkout = &options.checkout;
    match python {
        Some(python) if !options.quick => {
            let fresh = out.join("reference");
            create_dir(&fresh)?;
            progress(Step::Regenerating);
            let regenerated = regenerate(python, checkout, &fresh, &out.join("cache"))?;
            Ok((fresh, vec![regenerated]))
        }
        _ => Ok((checkout.reference_dir(), Vec::new())),
    }
}

/// Refuses, before any work, an output directory where the report or
/// the figures could not be written: `out` and `out/figures` are created
/// and take new files, and `report.json` and `report.html` are absent or
/// regular files.
pub fn check_outputs(out: &Path) -> Result<(), PipelineError> {
    if out.exists() && !out.is_dir() {
        return Err(PipelineError::OutNotADirectory {
            path: out.to_owned(),
        });
    }
    let figures = out.join("figures");
    create_dir(&figures)?;
    writable_directory(&figures).map_err(OutputError::from)?;
    for name in ["report.json", "report.html"] {
        check_destination(&out.join(name), &[]).map_err(OutputError::from)?;
    }
    Ok(())
}

mod error;
mod files;
mod options;
mod python_side;
mod step;

pub use error::PipelineError;
pub use options::{Options, PythonOptions, RANDOM_CASES};
pub use step::Step;

#[cfg(test)]
mod tests;
