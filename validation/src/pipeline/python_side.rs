//! The Python side of a run: the pinned environment, Mitsuba's evaluation
//! of random cases, the report's figures, and the figures copied beside it.

use std::path::{Path, PathBuf};
use std::process::Command;

use crate::check::Check;
use crate::checkout::Checkout;
use crate::exchange;
use crate::laws::{Laws, Laws64};
use crate::python::{self, run_tool, Task, ToolError};
use crate::report::Report;

use super::error::PipelineError;
use super::files::{create_dir, write};
use super::options::PythonOptions;
use super::step::Step;

/// The environment's interpreter, the environment set up first if needed.
pub(super) fn set_up_python(
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
pub(super) fn random_cases(
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
pub(super) fn figures_or_report(
    drawn: Result<Vec<String>, ToolError>,
    report: &mut Report,
) -> Vec<String> {
    match drawn {
        Ok(figures) => figures,
        Err(error) => {
            let mut check = Check::new(
                "report.figures",
                [
                    "The report's figures, drawn by python-checks/plot_report.py",
                    "A jelentés ábrái, a python-checks/plot_report.py rajzolja",
                ],
                ["matplotlib", "matplotlib"],
                ["the script succeeds", "a szkript sikeresen lefut"],
            );
            check.cases = 1;
            check.fail(error.to_string());
            report.checks.push(check);
            report.summarise();
            Vec::new()
        }
    }
}

/// Writes the report so far to `out/exchange/report.json`, for the figure
/// script.
pub(super) fn exchange_report(out: &Path, report: &Report) -> Result<(), PipelineError> {
    let exchange = out.join("exchange");
    create_dir(&exchange)?;
    write(
        &exchange,
        "report.json",
        crate::report::to_json(report).as_bytes(),
    )?;
    Ok(())
}

/// Runs the figure script on `out/exchange/report.json`; the figure file
/// names, relative to `out`.
pub(super) fn draw_figures(
    python: &Path,
    scripts: &Path,
    out: &Path,
) -> Result<Vec<String>, ToolError> {
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
pub(super) fn write_render_figures(
    out: &Path,
    report: &Report,
) -> Result<Vec<String>, PipelineError> {
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
pub(super) fn copy_tradeoff_plots(
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
