//! A sweep written: its record (`STEM.json`), its section of
//! `docs/tradeoffs.md` (`STEM.md`) with its verdicts, and its Pareto plot
//! drawn by `python-checks/plot_tradeoff.py`.

use std::path::{Path, PathBuf};
use std::process::Command;

use record::Lang;

use super::measured::{Measured, Sweep};
use super::second;
use crate::checkout::Lookup;
use crate::python::{run_tool, Task};
use crate::tradeoff::checks::UNCONVERGED;
use crate::tradeoff::error::TradeoffError;
use crate::tradeoff::verdict::Verdict;
use crate::tradeoff::{prose, sweep};

/// Writes the sweep's JSON and Markdown and, given the checkout's
/// `lookup`, its Pareto plot (drawn by that checkout's script and Python
/// environment): all of them or none. The plot is drawn first, from the JSON in a
/// directory of its own, so that a plot that cannot be drawn leaves no
/// record behind. Returns the files written.
pub fn write_sweep(sweep: &Sweep, plot: Option<&Lookup>) -> Result<Vec<PathBuf>, TradeoffError> {
    let files = &sweep.files;
    let json = serde_json::to_string_pretty(sweep).map_err(TradeoffError::Encode)? + "\n";
    let markdown = markdown(sweep, &sweep.stem);
    let png = match plot {
        Some(lookup) => Some(plot_bytes(&json, lookup)?),
        None => None,
    };
    let mut written = vec![
        (files.json.as_path(), json.as_bytes()),
        (files.markdown.as_path(), markdown.as_bytes()),
    ];
    if let Some(png) = &png {
        written.push((files.plot.as_path(), png.as_slice()));
    }
    safe_io::write_all_atomically(&written).map_err(|error| TradeoffError::Output(error.into()))?;
    Ok(written.iter().map(|(path, _)| path.to_path_buf()).collect())
}

/// The Pareto plot of the record `json`, drawn in a temporary directory.
fn plot_bytes(json: &str, lookup: &Lookup) -> Result<Vec<u8>, TradeoffError> {
    let io = |path: &Path, source| {
        TradeoffError::Output(
            safe_io::WriteError::Io {
                path: path.display().to_string(),
                source,
            }
            .into(),
        )
    };
    let dir = tempfile::tempdir().map_err(|e| io(&std::env::temp_dir(), e))?;
    let (record, png) = (dir.path().join("sweep.json"), dir.path().join("sweep.png"));
    std::fs::write(&record, json).map_err(|e| io(&record, e))?;
    plot(&record, &png, lookup)?;
    std::fs::read(&png).map_err(|e| io(&png, e))
}

/// `R` `A` `P` `F`: on the front of relative RMSE, mean ΔE, 99th-percentile
/// ΔE, ꟻLIP.
pub fn front_marks(p: &Measured) -> String {
    [
        ("rel_rmse", 'R'),
        ("delta_e_mean", 'A'),
        ("delta_e_p99", 'P'),
        ("flip_mean", 'F'),
    ]
    .iter()
    .map(|&(name, mark)| if p.pareto.contains(&name) { mark } else { '·' })
    .collect()
}

/// The scene's section of `docs/tradeoffs.md`.
pub fn markdown(sweep: &Sweep, stem: &str) -> String {
    let mut out = format!("## `{stem}`\n\n");
    out += &format!(
        "`{}` — {}, {}{}.\n\n",
        sweep.command,
        sweep.machine,
        sweep.date,
        sweep
            .load
            .as_ref()
            .map_or_else(String::new, |l| format!(", {l}"))
    );
    out += &format!(
        "{}×{} pixels, {} of them surface pixels. Ground truth: {} spp of `{}` \
         (box filter, max_depth {}), relative noise floor {:.1e}.\n\n",
        sweep.width,
        sweep.height,
        sweep.surface_pixels,
        sweep.truth.spp,
        sweep.truth.settings["integrator"].as_str().unwrap_or("?"),
        sweep.truth.settings["max_depth"],
        sweep.truth.noise_relative,
    );
    if sweep.truth.noise_relative > UNCONVERGED {
        out += &format!(
            "**The truth is not converged here**: its own noise is {:.2} of its energy \
             (fireflies), so every setting's error below is read through that noise.\n\n",
            sweep.truth.noise_relative
        );
    }
    out += "| setting | time (ms), median (range) | rays | rel. RMSE | ΔE mean | ΔE p99 | ꟻLIP | variance | bias² | efficiency | ΔE p99 vs own | front |\n";
    out += "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:-:|\n";
    for p in &sweep.points {
        out += &markdown_row(p);
    }
    if let Some(findings) = &sweep.findings {
        out += "\n**What the numbers say.** ";
        out += &prose::sentences(findings, Lang::En).join(" ");
        out += "\n";
    }
    out += "\nAgainst the scene's own settings (time ratio; ΔE2000 p99 against their render):\n\n";
    for line in verdicts(sweep) {
        out += &format!("- {line}\n");
    }
    out += &second::markdown(&sweep.mitsuba);
    if !sweep.skipped.is_empty() {
        out += "\nNot swept here: ";
        out += &sweep
            .skipped
            .iter()
            .map(|s| format!("{} ({})", s.axis, s.why))
            .collect::<Vec<_>>()
            .join("; ");
        out += ".\n";
    }
    out += &format!("\n![{stem}: time against each error](tradeoffs/{stem}-pareto.png)\n\n");
    out
}

/// A point's row of the Markdown table.
fn markdown_row(p: &Measured) -> String {
    let split = p.errors.split;
    let spread = if p.seconds.len() > 1 {
        let (lo, hi) = p
            .seconds
            .iter()
            .fold((f64::INFINITY, 0.0_f64), |(lo, hi), &s| {
                (lo.min(s), hi.max(s))
            });
        format!(" ({:.3}–{:.3})", lo * 1e3, hi * 1e3)
    } else {
        String::new()
    };
    format!(
        "| {} | {:.3}{} | {:.3e} | {:.4} | {:.2} | {:.2} | {:.3} | {} | {} | {} | {:.2} | {} |\n",
        p.point.label,
        p.seconds_median * 1e3,
        spread,
        p.rays,
        p.errors.rel_rmse,
        p.errors.delta_e_mean,
        p.errors.delta_e_p99,
        p.errors.flip_mean,
        split.map_or_else(|| "–".to_owned(), |s| format!("{:.2e}", s.variance)),
        split.map_or_else(|| "–".to_owned(), |s| format!("{:.2e}", s.bias_squared)),
        p.efficiency
            .map_or_else(|| "–".to_owned(), |e| format!("{e:.3e}")),
        p.against_scene.delta_e_p99,
        front_marks(p),
    )
}

/// One line per axis: each setting's time against the scene's own and its
/// ΔE p99 against the scene's own render, with its verdict; first the light
/// the scene's settings leave out.
pub fn verdicts(sweep: &Sweep) -> Vec<String> {
    let Some(base) = sweep.points.first() else {
        return Vec::new();
    };
    let mut lines = vec![format!(
        "The scene's own settings ({}) are {:.3} relative RMSE from the truth, ΔE2000 {:.2} on average and {:.2} at the 99th percentile.",
        base.point.label.trim_start_matches("scene: "),
        base.errors.rel_rmse,
        base.errors.delta_e_mean,
        base.errors.delta_e_p99
    )];
    let mut axes: Vec<sweep::Axis> = Vec::new();
    for p in &sweep.points[1..] {
        if !axes.contains(&p.point.axis) {
            axes.push(p.point.axis);
        }
    }
    for axis in axes {
        let points: Vec<&Measured> = sweep.points[1..]
            .iter()
            .filter(|p| p.point.axis == axis)
            .collect();
        let entries: Vec<String> = points
            .iter()
            .map(|p| {
                format!(
                    "`{}` {:.2}× the time, ΔE p99 {:.2}: {}",
                    p.point.label,
                    p.seconds_median / base.seconds_median.max(f64::MIN_POSITIVE),
                    p.against_scene.delta_e_p99,
                    p.verdict.map_or("", Verdict::words)
                )
            })
            .collect();
        lines.push(format!("{}.", entries.join("; ")));
    }
    lines
}

/// Draws `json`'s Pareto plot into `png` with the checkout's
/// `python-checks/plot_tradeoff.py` and its `.venv`, of the checkout
/// `lookup` finds.
pub fn plot(json: &Path, png: &Path, lookup: &Lookup) -> Result<PathBuf, TradeoffError> {
    let checkout = lookup.find().map_err(TradeoffError::Checkout)?;
    let python = checkout.root().join(".venv/bin/python");
    if !python.is_file() {
        return Err(TradeoffError::NoPython { python });
    }
    let mut command = Command::new(python);
    command
        .arg(checkout.python_checks().join("plot_tradeoff.py"))
        .arg(json)
        .arg(png);
    run_tool(command, Task::Script(PLOT_SCRIPT.into())).map_err(TradeoffError::Plot)?;
    Ok(png.to_owned())
}

/// The script that draws the plot, in the checkout.
pub const PLOT_SCRIPT: &str = "python-checks/plot_tradeoff.py";
