//! The whole harness as one call: set up the pinned Python environment,
//! regenerate the references (or take the committed ones), run every check,
//! have Mitsuba evaluate random cases, and write `report.json`,
//! `report.html` and the figures.
//!
//! ```no_run
//! use validation::checkout::Checkout;
//! use validation::pipeline::{self, Options};
//!
//! let options = Options::quick(Checkout::find(None)?, "example");
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
use std::process::Command;

use safe_io::{check_destination, writable_directory, write_all_atomically, write_atomically};
use tracer::output::OutputError;

use crate::check::Check;
use crate::checkout::Checkout;
use crate::exchange;
use crate::laws::{Laws, Laws64};
use crate::python::{self, run_tool, SetUp, Task, ToolError};
use crate::reference::ReferenceError;
use crate::regenerate::{regenerate, RegenerateError};
use crate::report::Report;
use crate::report::{to_html, to_json};
use crate::suite::{self, Context};

/// Random cases of each law that Mitsuba evaluates: reduced set, full set.
pub const RANDOM_CASES: [usize; 2] = [300, 3000];

/// What to run, and where.
#[derive(Clone, Debug)]
pub struct Options {
    /// The suite's checkout: references, scenes, generators.
    pub checkout: Checkout,
    /// The reduced set: the committed references instead of regenerated
    /// ones, fewer samples and cases.
    pub quick: bool,
    /// Directory for the report and the figures, created if missing
    /// [default: `validation/out` in the checkout].
    pub out: Option<PathBuf>,
    /// The Python side; `None`: no Python at all (committed references, no
    /// random cases, no drawn figures).
    pub python: Option<PythonOptions>,
    /// Seed of the random cases.
    pub seed: u64,
    /// The command line recorded in the report.
    pub command: String,
}

/// The Python environment the references come from.
#[derive(Clone, Debug)]
pub struct PythonOptions {
    /// The Python 3 interpreter that creates the environment.
    pub base: PathBuf,
    /// The environment, created if missing [default: `.venv` in the checkout].
    pub venv: Option<PathBuf>,
}

impl Options {
    /// The reduced set against `checkout`'s committed references, no Python,
    /// seed 1, the report in the checkout's `validation/out`.
    pub fn quick(checkout: Checkout, command: &str) -> Self {
        Self {
            checkout,
            quick: true,
            out: None,
            python: None,
            seed: 1,
            command: command.to_owned(),
        }
    }
}

/// A step of the run, for progress messages.
#[derive(Clone, Copy, Debug)]
pub enum Step<'a> {
    /// Setting the Python environment up.
    Python(SetUp<'a>),
    /// Regenerating the references with the pinned tools.
    Regenerating,
    /// About to run kind `index` of `total` kinds of check.
    Checks {
        /// Which kind, from 0.
        index: usize,
        /// How many kinds.
        total: usize,
        /// Its name.
        name: &'a str,
    },
    /// Every kind of check has run.
    ChecksDone,
    /// Having Mitsuba evaluate `cases` random cases.
    RandomCases {
        /// How many, all laws together.
        cases: usize,
    },
    /// Drawing the figures.
    DrawingFigures,
}

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

/// Why the harness could not run to the end (failed checks are not errors:
/// they are in the report).
#[derive(Debug, thiserror::Error)]
pub enum PipelineError {
    /// The output directory names something else.
    #[error("the output directory {} exists and is not a directory", .path.display())]
    OutNotADirectory {
        /// It.
        path: PathBuf,
    },
    /// A directory could not be created.
    #[error("cannot create the directory {}: {source}", .path.display())]
    CreateDir {
        /// The directory.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The checkout has no pinned requirements for the Python side.
    #[error("{} not found: the Python side runs from a checkout of the suite", .path.display())]
    NoRequirements {
        /// The file looked for.
        path: PathBuf,
    },
    /// A report, figure or exchange file could not be written.
    #[error(transparent)]
    Write(#[from] OutputError),
    /// A reference, or Mitsuba's results, could not be used.
    #[error(transparent)]
    Reference(#[from] ReferenceError),
    /// A Python tool could not run or failed.
    #[error(transparent)]
    Tool(#[from] ToolError),
    /// The regeneration could not be judged.
    #[error(transparent)]
    Regenerate(#[from] RegenerateError),
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
    let python = match &options.python {
        Some(setup) => Some(set_up_python(checkout, setup, &mut progress)?),
        None => None,
    };
    let mut first_checks = Vec::new();
    let reference_dir = match (&python, options.quick) {
        (Some(python), false) => {
            let fresh = out.join("reference");
            create_dir(&fresh)?;
            progress(Step::Regenerating);
            first_checks.push(regenerate(python, checkout, &fresh, &out.join("cache"))?);
            fresh
        }
        _ => checkout.reference_dir(),
    };
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
    let figures_after = kinds.iter().rposition(|k| k.feeds_figures());
    let (random, drawn) = std::thread::scope(|scope| -> Result<_, PipelineError> {
        let random = python.as_ref().map(|python| {
            let count = RANDOM_CASES[usize::from(!options.quick)];
            progress(Step::RandomCases { cases: 3 * count });
            let (scripts, out) = (&scripts, &out);
            scope.spawn(move || random_cases(python, scripts, out, options.seed, count))
        });
        let mut drawing = None;
        for (index, kind) in kinds.iter().enumerate() {
            progress(Step::Checks {
                index,
                total,
                name: kind.name(),
            });
            kind.run(&context, &mut report)?;
            if let (Some(python), Some(true)) = (&python, figures_after.map(|i| i == index)) {
                progress(Step::DrawingFigures);
                let exchange = out.join("exchange");
                create_dir(&exchange)?;
                write(&exchange, "report.json", to_json(&report).as_bytes())?;
                let (scripts, out) = (&scripts, &out);
                drawing = Some(scope.spawn(move || draw_figures(python, scripts, out)));
            }
        }
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
    let (json, html) = (to_json(&report), to_html(&report, &figures));
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

fn create_dir(path: &Path) -> Result<(), PipelineError> {
    std::fs::create_dir_all(path).map_err(|source| PipelineError::CreateDir {
        path: path.to_owned(),
        source,
    })
}

/// Writes `dir/name` atomically.
fn write(dir: &Path, name: &str, contents: &[u8]) -> Result<(), OutputError> {
    Ok(write_atomically(&dir.join(name), contents)?)
}

/// The environment's interpreter, the environment set up first if needed.
fn set_up_python(
    checkout: &Checkout,
    setup: &PythonOptions,
    progress: &mut impl FnMut(Step),
) -> Result<PathBuf, PipelineError> {
    let requirements = checkout.python_checks().join("requirements.txt");
    if !requirements.is_file() {
        return Err(PipelineError::NoRequirements { path: requirements });
    }
    let venv = setup
        .venv
        .clone()
        .unwrap_or_else(|| checkout.root().join(".venv"));
    let interpreter = python::ensure_environment(&setup.base, &venv, &requirements, |step| {
        progress(Step::Python(step))
    })?;
    Ok(interpreter)
}

/// Exports `count` random cases of each law, has Mitsuba evaluate them, and
/// compares (`crate::exchange`).
fn random_cases(
    python: &Path,
    scripts: &Path,
    out: &Path,
    seed: u64,
    count: usize,
) -> Result<Check, PipelineError> {
    let dir = out.join("exchange");
    create_dir(&dir)?;
    let cases = exchange::random_cases(seed, count);
    let text = serde_json::to_string(&cases).expect("the cases always serialise");
    write(&dir, "cases.json", text.as_bytes())?;
    let mut command = Command::new(python);
    command
        .arg(scripts.join("mitsuba_eval.py"))
        .arg(dir.join("cases.json"))
        .arg(dir.join("results.json"));
    run_tool(
        command,
        Task::Script("python-checks/mitsuba_eval.py".into()),
    )?;
    let results: exchange::ResultsFile =
        crate::reference::load(&dir, "results.json", exchange::RESULTS_SCHEMA)?;
    Ok(exchange::check_random(
        &Laws::radiometry(),
        &Laws64::radiometry(),
        &cases,
        &results,
    ))
}

/// The figure script's figures, drawn from the report as it stands
/// (written for the script to `out/exchange/report.json`); when it fails,
/// a failed check in the report instead of figures.
fn figures_or_report(drawn: Result<Vec<String>, ToolError>, report: &mut Report) -> Vec<String> {
    match drawn {
        Ok(figures) => figures,
        Err(error) => {
            let mut check = Check::new(
                "report.figures",
                "The report's figures, drawn by python-checks/plot_report.py",
                "matplotlib",
                "the script succeeds",
            );
            check.cases = 1;
            check.fail(error.to_string());
            report.checks.push(check);
            report.summarise();
            Vec::new()
        }
    }
}

/// Runs the figure script on `out/exchange/report.json`; the figure file
/// names, relative to `out`.
fn draw_figures(python: &Path, scripts: &Path, out: &Path) -> Result<Vec<String>, ToolError> {
    let mut command = Command::new(python);
    command
        .arg(scripts.join("plot_report.py"))
        .arg(out.join("exchange/report.json"))
        .arg(out.join("figures"));
    let listed = run_tool(command, Task::Script("python-checks/plot_report.py".into()))?;
    Ok(listed
        .lines()
        .map(|name| format!("figures/{}", name.trim()))
        .collect())
}

/// Writes the render triptychs (ours | Mitsuba | difference) as PNG under
/// `out/figures/`; their names, relative to `out`.
fn write_render_figures(out: &Path, report: &Report) -> Result<Vec<String>, PipelineError> {
    let dir = out.join("figures");
    create_dir(&dir)?;
    let mut names = Vec::new();
    for figure in &report.render_figures {
        tracer::output::write_png(&dir.join(&figure.file), &figure.image)?;
        names.push(format!("figures/{}", figure.file));
    }
    Ok(names)
}

/// Copies each trade-off record's Pareto plot (drawn by the command that
/// wrote the record) beside the report as `figures/tradeoff_STEM.png`, so
/// that the report stands alone; their names, relative to `out`. A record
/// without its plot is shown without it.
fn copy_tradeoff_plots(
    checkout: &Checkout,
    out: &Path,
    report: &Report,
) -> Result<Vec<String>, PipelineError> {
    let dir = out.join("figures");
    let mut names = Vec::new();
    for record in &report.tradeoffs {
        let stem = record.stem();
        let plot = checkout
            .root()
            .join(crate::tradeoff::checks::DIR)
            .join(format!("{stem}-pareto.png"));
        let Ok(bytes) = std::fs::read(&plot) else {
            continue;
        };
        let name = format!("tradeoff_{stem}.png");
        write(&dir, &name, &bytes)?;
        names.push(format!("figures/{name}"));
    }
    Ok(names)
}

#[cfg(test)]
mod tests;
