//! A sweep as people read it on the terminal: its plan, or its table,
//! what its numbers say, the files written and what to mind; the files
//! themselves are the library's ([`engine::write_sweep`]).

use std::path::Path;

use validation::checkout::Lookup;
use validation::tradeoff::checks::UNCONVERGED;
use validation::tradeoff::engine::{self, PlanWritten, Setup, Sweep};
use validation::tradeoff::jobs::TRUTH_JOBS;
use validation::tradeoff::prose;

use super::args::TradeoffArgs;
use crate::error;
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
            "{}: {}×{}, {} felületi képpont; referencia {} minta ({}), relatív zajszint {:.1e}",
            sweep.scene,
            sweep.width,
            sweep.height,
            sweep.surface_pixels,
            sweep.truth.spp,
            match (sweep.truth.cached, lang) {
                (true, Lang::En) => "cached",
                (false, Lang::En) => "rendered",
                (true, Lang::Hu) => "gyorsítótárból",
                (false, Lang::Hu) => "most renderelve",
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
            lang.pick("variance", "szórásnégyzet"),
            lang.pick("bias²", "torzítás²"),
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
            engine::front_marks(p),
        ));
    }
    lines.extend(engine::mitsuba_table(
        &sweep.mitsuba,
        sweep.mitsuba_missing.as_ref(),
        lang,
    ));
    lines
}

/// Writes the sweep's JSON, Markdown and plot, and prints its record.
/// The plot is drawn with the checkout `checkout` finds, unless
/// `--no-plot`.
pub fn write_and_show(
    sweep: &Sweep,
    args: &TradeoffArgs,
    checkout: &Lookup,
    ui: &Ui,
) -> error::Result<()> {
    let lang = ui.lang;
    let files = &sweep.files;
    let written = engine::write_sweep(sweep, (!args.no_plot).then_some(checkout))?;
    let plotted = written.get(2);
    let mut record = Record::new("tradeoff", String::new(), "");
    let answer = written
        .iter()
        .map(|f| f.display().to_string().into())
        .collect();
    record
        .inputs_from(args)
        .set_answer(Answer::List(answer), None);
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
    if let Some(stale) = &sweep.truth.replaced {
        record.note(say!(
            lang,
            "the cached truth was not used: {}; it was rendered again",
            "a gyorsítótárban talált referencia nem használható: {}; újra renderelve",
            lang.pick(&stale.to_string(), &stale.hu())
        ));
    }
    for skipped in &sweep.skipped {
        record.note(say!(
            lang,
            "not swept: {}: {}",
            "nem mért: {}: {}",
            lang.pick(skipped.axis, skipped.axis_hu),
            lang.pick(skipped.why, skipped.why_hu)
        ));
    }
    record.detail("sweep", sweep);
    // The notes (what was not swept, a truth not to be trusted) are read
    // after the table in text too, not only in the JSON.
    ui.show_steps_and_notes(&record)
}

/// Prints what `--plan` wrote: how many jobs, how to run them and how to
/// collect their results.
pub fn show_plan(
    setup: &Setup,
    args: &TradeoffArgs,
    (path, written): (&Path, PlanWritten),
    ui: &Ui,
) -> error::Result<()> {
    let lang = ui.lang;
    let count = written.jobs;
    let mut record = Record::new("tradeoff", String::new(), "");
    record
        .inputs_from(args)
        .set_answer(Answer::List(vec![path.display().to_string().into()]), None);
    record.step(|| {
        say!(
            lang,
            "planned {} jobs of {} ({}×{}, plan {}): jobs 0 and 1 the truth's two halves, 2 to {} the {} settings; written: {}",
            "{} feladat tervezve: {} ({}×{}, terv: {}): a 0. és 1. a referencia két fele, a 2–{}. a {} beállítás; kiírva: {}",
            count,
            setup.key.scene,
            setup.key.width,
            setup.key.height,
            setup.key.id(),
            count - 1,
            count - TRUTH_JOBS,
            path.display()
        )
    });
    record.step(|| {
        say!(
            lang,
            "run each, anywhere the scene file is: optics tradeoff-job {} INDEX --out RESULTS (INDEX 0 to {})",
            "mindegyik futtatása bárhol, ahol a jelenetfájl elérhető: optics tradeoff-job {} INDEX --out RESULTS (INDEX: 0–{})",
            path.display(),
            count - 1
        )
    });
    record.step(|| {
        say!(
            lang,
            "then merge them here: {} --collect RESULTS",
            "majd az összesítés itt: {} --collect RESULTS",
            args.request().command_line()
        )
    });
    record.detail("plan", setup.key.id()).detail("jobs", count);
    ui.show_steps(&record)
}
