//! What the budget says: what it chose and why, term by term, what the
//! scene's own settings would have cost, and with `--verify` the error
//! reached; as text, or as the one `--json` record.

use clap::ValueEnum;
use tracer::output::Destination;
use validation::tradeoff::budget::displayed::DRAWS;
use validation::tradeoff::budget::{self, Bound, K};
use validation::tradeoff::engine::{describe, Metric, Outcome, Predicted};
use validation::tradeoff::measure::Errors;

use crate::error;
use crate::ui::Ui;
use record::{say, Lang};
use record::{Answer, Record};

/// Shows the budget's record.
pub fn show(
    inputs: &impl serde::Serialize,
    destination: &Destination,
    outcome: &Outcome,
    ui: &Ui,
) -> error::Result<()> {
    let lang = ui.lang;
    let (png, pfm) = (destination.png(), destination.pfm());
    let mut record = Record::new("render", String::new(), "");
    record
        .inputs_from(inputs)
        .set_answer(
            Answer::List(vec![
                png.display().to_string().into(),
                pfm.display().to_string().into(),
            ]),
            None,
        )
        .details_from(outcome);
    for line in lines(outcome, lang) {
        record.step(|| line);
    }
    record.step(|| {
        say!(
            lang,
            "rendered: {} rays → {}, {}",
            "kép: {} sugár → {}, {}",
            outcome.rays,
            png.display(),
            pfm.display()
        )
    });
    if let Some(errors) = &outcome.verified {
        record.step(|| {
            verified_line(
                outcome.metric,
                (outcome.predicted.bound(), outcome.tolerance),
                errors,
                lang,
            )
        });
    }
    ui.show_steps(&record)
}

/// What `--verify` reached: the chosen measure against its prediction
/// and tolerance, then each of the other three once.
fn verified_line(
    chosen: Metric,
    (bound, tolerance): (f64, f64),
    errors: &Errors,
    lang: Lang,
) -> String {
    let reached = chosen.of(errors);
    let others: Vec<String> = Metric::value_variants()
        .iter()
        .filter(|&&metric| metric != chosen)
        .map(|&metric| measure_text(metric, errors, lang))
        .collect();
    say!(
        lang,
        "verified against the ground truth: {} {:.4} (predicted ≤ {:.4}, tolerance {}): {}; {}",
        "ellenőrizve a referencián: {} {:.4} (becslés ≤ {:.4}, tűrés {}): {}; {}",
        chosen.name(),
        reached,
        bound,
        budget::written(tolerance),
        if reached <= tolerance {
            lang.pick("within", "belül")
        } else {
            lang.pick("OVER the tolerance", "a tűrés FÖLÖTT")
        },
        others.join(", ")
    )
}

/// One measure reached, as the verify line names it.
fn measure_text(metric: Metric, errors: &Errors, lang: Lang) -> String {
    let value = metric.of(errors);
    match metric {
        Metric::RelRmse => format!("rel_rmse {value:.4}"),
        Metric::DeltaEMean => say!(lang, "ΔE2000 mean {:.3}", "ΔE2000 átlag {:.3}", value),
        Metric::DeltaEP99 => format!("ΔE2000 p99 {value:.3}"),
        Metric::FlipMean => format!("ꟻLIP {value:.4}"),
    }
}

/// The choice and its reasons, one line each.
fn lines(outcome: &Outcome, lang: Lang) -> Vec<String> {
    let p = &outcome.predicted;
    let mut lines = Vec::new();
    if outcome.lambert {
        lines.push(say!(
            lang,
            "--lambert: course_rough rendered and measured as Lambert of albedo kd",
            "--lambert: a course_rough Lambert-anyagként, kd albedóval renderelve és mérve"
        ));
    }
    lines.extend([
        say!(
            lang,
            "pilot: {} candidates, two halves of {} spp each against the truth's settings, {} rays",
            "próba: {} jelölt, két {} mintás fél mindegyik, a referencia beállításai mellett, {} sugár",
            outcome.candidates.len(),
            outcome.pilot_spp / 2,
            outcome.pilot_rays
        ),
        say!(
            lang,
            "chosen: {}, predicted {} ≤ {:.4} (tolerance {}), {:.3e} rays",
            "választás: {}, becsült {} ≤ {:.4} (tűrés {}), {:.3e} sugár",
            describe(&outcome.chosen),
            outcome.metric.name(),
            p.bound(),
            budget::written(outcome.tolerance),
            p.rays()
        ),
        prediction_line(p, lang),
    ]);
    for (name, bound) in &outcome.terms {
        lines.push(say!(
            lang,
            "  of which {} alone: bias ≤ {:.4}",
            "  ebből {} önmagában: torzítás ≤ {:.4}",
            name,
            bound
        ));
    }
    let s = &outcome.scene;
    lines.push(say!(
        lang,
        "the scene's own settings: predicted {} ≤ {:.4}, {:.3e} rays",
        "a jelenet saját beállításai: becsült {} ≤ {:.4}, {:.3e} sugár",
        outcome.metric.name(),
        s.bound(),
        s.rays()
    ));
    lines
}

/// The terms of a prediction: bias and noise added in squares, or the
/// simulated renders and their margin.
fn prediction_line(p: &Predicted, lang: Lang) -> String {
    match p {
        Predicted::RelRmse(p) => match p.spp {
            Some(spp) => say!(
                lang,
                "  = √(bias² + noise²): bias ≤ {:.4} (what the settings leave out of the truth, from the pilot), Monte Carlo noise ≤ {:.4} at {} spp",
                "  = √(torzítás² + zaj²): torzítás ≤ {:.4} (amit a beállítás kihagy a referenciából, a próbából), Monte Carlo zaj ≤ {:.4} {} mintánál",
                p.bias,
                p.noise,
                spp
            ),
            None => say!(
                lang,
                "  = bias ≤ {:.4} (what the settings leave out of the truth, from the pilot); deterministic: no noise",
                "  = torzítás ≤ {:.4} (amit a beállítás kihagy a referenciából, a próbából); determinisztikus: nincs zaj",
                p.bias
            ),
        },
        Predicted::Shown(p) => match p.spp {
            Some(spp) => say!(
                lang,
                "  = the largest of {} simulated renders (the pilot's mean, its noise at {} spp and the ground truth's), {:.4}, + {} standard deviations of them with the pilot's own noise drawn again, {:.4}",
                "  = {} szimulált kép legnagyobbika (a próba átlaga, zaja {} mintánál és a referenciáé), {:.4}, + a próba saját zaját újra sorsoló képek szórásának {}-szorosa, {:.4}",
                DRAWS,
                spp,
                p.simulated,
                K,
                p.margin
            ),
            None => say!(
                lang,
                "  = the largest of {} simulated renders (the pilot's mean; deterministic: only the ground truth's noise), {:.4}, + {} standard deviations of them with the pilot's own noise drawn again, {:.4}",
                "  = {} szimulált kép legnagyobbika (a próba átlaga; determinisztikus: csak a referencia zaja), {:.4}, + a próba saját zaját újra sorsoló képek szórásának {}-szorosa, {:.4}",
                DRAWS,
                p.simulated,
                K,
                p.margin
            ),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The verify line names each of the four measures once, in both
    /// languages, the chosen one first: its value (to the printed digits)
    /// appears exactly once.
    #[test]
    fn the_verify_line_names_each_measure_once() {
        let errors = Errors {
            rel_rmse: 0.0283,
            delta_e_mean: 1.095,
            delta_e_p99: 17.078,
            flip_mean: 0.0227,
            light: 1.0,
            light_noise: None,
            split: None,
        };
        let values = ["0.0283", "1.095", "17.078", "0.0227"];
        for &chosen in Metric::value_variants() {
            for lang in [Lang::En, Lang::Hu] {
                let line = verified_line(chosen, (0.0897, 0.1), &errors, lang);
                for value in values {
                    assert_eq!(line.matches(value).count(), 1, "{value} in {line}");
                }
                let first = line.split(": ").nth(1).unwrap_or_default();
                assert!(first.starts_with(chosen.name()), "{line}");
            }
        }
    }
}
