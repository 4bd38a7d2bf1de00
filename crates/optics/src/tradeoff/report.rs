//! A sweep as people read it: the terminal's table, the Markdown section
//! of `docs/tradeoffs.md` with its verdicts, and the Pareto plot drawn by
//! `python-checks/plot_tradeoff.py`.

use std::path::{Path, PathBuf};
use std::process::Command;

use validation::checkout::Checkout;
use validation::pipeline::PipelineError;
use validation::python::{run_tool, Task, ToolError};

use super::{prose, Measured, Sweep, TradeoffArgs, Verdict, UNCONVERGED};
use crate::error::{self, ErrorKind};
use crate::ui::Ui;
use record::{say, Lang};
use record::{Answer, Record};

/// The table, one line a point, a header first.
pub fn table(sweep: &Sweep, lang: Lang) -> Vec<String> {
    let width = sweep
        .points
        .iter()
        .map(|p| p.point.label.chars().count())
        .max()
        .unwrap_or(7)
        .max(7);
    let mut lines = vec![
        say!(
            lang,
            "{}: {}×{}, {} surface pixels; truth {} spp ({}), relative noise floor {:.1e}",
            "{}: {}×{}, {} felületi pixel; referencia {} minta ({}), relatív zajszint {:.1e}",
            sweep.scene,
            sweep.width,
            sweep.height,
            sweep.surface_pixels,
            sweep.truth.spp,
            if sweep.truth.cached {
                "cached"
            } else {
                "rendered"
            },
            sweep.truth.noise_relative
        ),
        format!(
            "{:<width$}  {:>9}  {:>10}  {:>8}  {:>6}  {:>6}  {:>6}  {:>9}  {:>9}  {:>9}  {:>7}  front",
            lang.pick("setting", "beállítás"),
            lang.pick("time ms", "idő ms"),
            lang.pick("rays", "sugár"),
            "rel RMSE",
            "ΔE avg",
            "ΔE p99",
            "ꟻLIP",
            "variance",
            "bias²",
            lang.pick("effic.", "hatékony."),
            lang.pick("vs own", "saját"),
        ),
    ];
    for p in &sweep.points {
        let split = p.errors.split;
        lines.push(format!(
            "{:<width$}  {:>9}  {:>10}  {:>8}  {:>6.2}  {:>6.2}  {:>6.3}  {:>9}  {:>9}  {:>9}  {:>7.2}  {}",
            p.point.label,
            format!("{:.3}", p.seconds_median * 1e3),
            format!("{:.3e}", p.rays),
            format!("{:.4}", p.errors.rel_rmse),
            p.errors.delta_e_mean,
            p.errors.delta_e_p99,
            p.errors.flip_mean,
            split.map_or_else(|| "-".to_owned(), |s| format!("{:.2e}", s.variance)),
            split.map_or_else(|| "-".to_owned(), |s| format!("{:.2e}", s.bias_squared)),
            p.efficiency
                .map_or_else(|| "-".to_owned(), |e| format!("{e:.3e}")),
            p.against_scene.delta_e_p99,
            front_marks(p),
        ));
    }
    lines.extend(super::mitsuba::table(
        &sweep.mitsuba,
        sweep.mitsuba_missing.as_ref(),
        lang,
    ));
    lines
}

/// `R` `A` `P` `F`: on the front of relative RMSE, mean ΔE, 99th-percentile
/// ΔE, ꟻLIP.
fn front_marks(p: &Measured) -> String {
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
    if sweep.truth.noise_relative > super::UNCONVERGED {
        out += &format!(
            "**The truth is not converged here**: its own noise is {:.2} of its energy \
             (fireflies), so every setting's error below is read through that noise.\n\n",
            sweep.truth.noise_relative
        );
    }
    out += "| setting | time (ms), median (range) | rays | rel. RMSE | ΔE mean | ΔE p99 | ꟻLIP | variance | bias² | efficiency | ΔE p99 vs own | front |\n";
    out += "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:-:|\n";
    for p in &sweep.points {
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
        out += &format!(
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
        );
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
    out += &super::mitsuba::markdown(&sweep.mitsuba);
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
    let mut axes: Vec<super::sweep::Axis> = Vec::new();
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

/// Writes the sweep's JSON, Markdown and plot, and prints its record.
pub fn write_and_show(sweep: &Sweep, args: &TradeoffArgs, ui: &Ui) -> error::Result<()> {
    let lang = ui.lang;
    let files = &sweep.files;
    let json = serde_json::to_string_pretty(sweep).map_err(ErrorKind::Encode)? + "\n";
    let markdown = markdown(sweep, &sweep.stem);
    safe_io::write_all_atomically(&[
        (files.json.as_path(), json.as_bytes()),
        (files.markdown.as_path(), markdown.as_bytes()),
    ])
    .map_err(|error| ErrorKind::Output(error.into()))?;
    let plotted = if args.no_plot {
        None
    } else {
        Some(plot(&files.json, &files.plot)?)
    };

    let mut record = Record::new("tradeoff", String::new(), "");
    let mut written = vec![
        files.json.display().to_string().into(),
        files.markdown.display().to_string().into(),
    ];
    if plotted.is_some() {
        written.push(files.plot.display().to_string().into());
    }
    record
        .inputs_from(args)
        .set_answer(Answer::List(written), None);
    for line in table(sweep, lang) {
        record.step(|| line);
    }
    for sentence in sweep
        .findings
        .iter()
        .flat_map(|f| prose::sentences(f, lang))
    {
        record.step(|| sentence);
    }
    record.step(|| {
        say!(
            lang,
            "written: {}, {}{}",
            "kiírva: {}, {}{}",
            files.json.display(),
            files.markdown.display(),
            plotted.map_or_else(String::new, |p| format!(", {}", p.display()))
        )
    });
    if let Some((gain, name)) = &sweep.gain {
        record.note(say!(
            lang,
            "the material {} reflects up to {:.2} times the light it receives (π kd; the course's kd is in 1/sr): where such surfaces see each other, light multiplies and no truth converges; --lambert measures the scene with the suite's physical stand-in",
            "a(z) {} anyag a kapott fény legfeljebb {:.2}-szeresét veri vissza (π kd; a kurzus kd-je 1/sr-ben értendő): ahol ilyen felületek látják egymást, a fény sokszorozódik, és nincs konvergens referencia; a --lambert a csomag fizikai helyettesítőjével mér",
            name,
            gain
        ));
    }
    if sweep.truth.noise_relative > UNCONVERGED {
        record.note(say!(
            lang,
            "the truth is not converged: its own noise is {:.2} of its energy (above {}), so the relative RMSE and the ΔE of every setting are read through that noise; raise --truth-spp",
            "a referencia nem konvergált: saját zaja energiájának {:.2} része ({} felett), így minden beállítás relatív RMSE-je és ΔE-je e zajon át látszik; növelje a --truth-spp értékét",
            sweep.truth.noise_relative,
            UNCONVERGED
        ));
    }
    for skipped in &sweep.skipped {
        record.note(say!(
            lang,
            "not swept: {}: {}",
            "nem mért: {}: {}",
            skipped.axis,
            lang.pick(skipped.why, skipped.why_hu)
        ));
    }
    record.detail("sweep", sweep);
    ui.show_steps(&record)?;
    // The notes (what was not swept, a truth not to be trusted) are read
    // after the table in text too, not only in the JSON.
    if !ui.json {
        let notes: String = record.notes.iter().map(|n| format!("{n}\n")).collect();
        crate::ui::print_out(&notes)?;
    }
    Ok(())
}

/// Draws `json`'s Pareto plot into `png` with the checkout's
/// `python-checks/plot_tradeoff.py` and its `.venv`.
pub fn plot(json: &Path, png: &Path) -> error::Result<PathBuf> {
    let checkout = Checkout::find(None).map_err(ErrorKind::Checkout)?;
    let python = checkout.root().join(".venv/bin/python");
    let script = "python-checks/plot_tradeoff.py";
    if !python.is_file() {
        let error = ToolError::Start {
            what: Task::Script(script.into()),
            program: python.display().to_string(),
            source: std::io::Error::new(
                std::io::ErrorKind::NotFound,
                "no .venv: `optics validate` creates it once (or pass --no-plot)",
            ),
        };
        return Err(ErrorKind::Pipeline(PipelineError::Tool(error)).into());
    }
    let mut command = Command::new(python);
    command
        .arg(checkout.python_checks().join("plot_tradeoff.py"))
        .arg(json)
        .arg(png);
    run_tool(command, Task::Script(script.into()))
        .map_err(|e| ErrorKind::Pipeline(PipelineError::Tool(e)))?;
    Ok(png.to_owned())
}
