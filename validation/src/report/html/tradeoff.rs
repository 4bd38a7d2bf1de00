//! The speed/accuracy trade of each scene, as `optics tradeoff` recorded
//! it: what its numbers say, every setting's time and errors, the scene's
//! Pareto plot, and the command and machine they came from.

use std::fmt::Write as _;

use super::figures::figure;
use super::format::{case, english, escape, inline_code, number, readable};
use crate::report::document::Report;
use crate::tradeoff::checks::REGENERATE;
use crate::tradeoff::prose::sentences;
use crate::tradeoff::record::{Point, Record};
use record::{say, Lang};

/// One folded section per scene, after the area's checks.
pub(super) fn tradeoffs(h: &mut String, report: &Report, figures: &[&String], lang: Lang) {
    if report.tradeoffs.is_empty() {
        return;
    }
    let _ = writeln!(
        h,
        "<p>{}</p>",
        say!(
            lang,
            "Each scene rendered under every setting it allows, each varied alone from the \
             scene's own, timed and measured against a converged render with all the light \
             (the checkout's <code>docs/tradeoffs.md</code> defines the measures). \
             <em>Not seen</em>: within ΔE2000 1 of the scene's own render at the 99th percentile; \
             <em>worth it</em>: not seen and at most 0.9× its time. Regenerate with \
             <code>{}</code>.",
            "Minden jelenet minden megengedett beállítással, mindegyik egyedül eltérve a \
             jelenet sajátjától, időre mérve és összevetve egy a teljes fénnyel konvergált képpel \
             (a mértékeket a <code>docs/tradeoffs.md</code> írja le). \
             <em>Nem látható</em>: a 99. percentilisben ΔE2000 1-en belül van a jelenet saját \
             képétől; <em>megéri</em>: nem látható, és legfeljebb 0.9-szer annyi ideig tart. \
             Újragenerálás: <code>{}</code>.",
            REGENERATE
        )
    );
    for (k, record) in report.tradeoffs.iter().enumerate() {
        let stem = record.stem();
        let _ = writeln!(
            h,
            "<details><summary><b>{}</b>: {}</summary>",
            escape(&stem),
            say!(
                lang,
                "{} settings, {} × {}, truth {} spp",
                "{} beállítás, {} × {}, pontos kép {} spp",
                record.points.len(),
                record.width,
                record.height,
                record.truth.spp
            )
        );
        stamp(h, record, lang);
        if let Some(words) = report.tradeoff_words.get(&stem) {
            let words = match (lang, &record.findings) {
                (Lang::Hu, Some(findings)) => inline_code(&sentences(findings, lang).join(" ")),
                _ => inline_code(words),
            };
            let _ = writeln!(
                h,
                "<p class=findings><b>{}</b> {words}</p>",
                lang.pick("What the numbers say.", "Amit a számok mondanak.")
            );
        }
        table(h, k, record, lang);
        let plot = format!("tradeoff_{stem}.png");
        if let Some(plot) = figures.iter().find(|f| f.ends_with(&plot)) {
            h.push_str("<div class=plot>");
            figure(h, plot);
            h.push_str("</div>");
        }
        h.push_str("</details>\n");
    }
}

/// Where the times were taken: the command, the machine, the day, its load.
fn stamp(h: &mut String, record: &Record, lang: Lang) {
    let load = if record.load.is_empty() {
        String::new()
    } else {
        format!(" ({})", case(lang, &record.load))
    };
    let _ = writeln!(
        h,
        "<p class=small>{}</p>",
        say!(
            lang,
            "Measured by <code>{}</code> on {}, {}{}.",
            "Mérte: <code>{}</code>, gép: {}, {}{}.",
            escape(&record.command),
            english(lang, &record.machine),
            escape(&record.date),
            load
        )
    );
}

/// Every setting of record `k`: its time (median and range of the timed
/// renders), its errors from the truth, the light it carries, its ΔE p99
/// from the scene's own render, and the verdict.
fn table(h: &mut String, k: usize, record: &Record, lang: Lang) {
    h.push_str(lang.pick(
        "<div class=scroll><table class=trade><tr><th>setting</th>\
         <th>time, ms: median (range)</th><th>× own</th><th>rel RMSE</th><th>ΔE mean</th>\
         <th>ΔE p99</th><th>ꟻLIP</th><th>light, % of truth</th><th>ΔE p99 vs own</th>\
         <th>verdict</th></tr>\n",
        "<div class=scroll><table class=trade><tr><th>beállítás</th>\
         <th>idő, ms: medián (tartomány)</th><th>× saját</th><th>rel. RMSE</th><th>ΔE átlag</th>\
         <th>ΔE p99</th><th>ꟻLIP</th><th>fény, a pontos kép %-a</th><th>ΔE p99 a sajáthoz</th>\
         <th>ítélet</th></tr>\n",
    ));
    let base = record.points.first().map_or(f64::NAN, |p| p.seconds_median);
    for (i, p) in record.points.iter().enumerate() {
        let at = |field: &str| format!("/tradeoffs/{k}/points/{i}/{field}");
        let cell = |field: &str, value: f64| number("td", &at(field), value, &readable(value));
        let light = p.errors.light.map_or_else(
            || "<td class=num>–</td>".to_owned(),
            |share| number("td", &at("errors/light"), share, &readable(100.0 * share)),
        );
        let _ = writeln!(
            h,
            "<tr><td>{}</td>{}<td class=num>{}</td>{}{}{}{}{light}{}<td>{}</td></tr>",
            case(lang, &p.label),
            time(p, &at),
            readable(p.seconds_median / base),
            cell("errors/rel_rmse", p.errors.rel_rmse),
            cell("errors/delta_e_mean", p.errors.delta_e_mean),
            cell("errors/delta_e_p99", p.errors.delta_e_p99),
            cell("errors/flip_mean", p.errors.flip_mean),
            cell("against_scene/delta_e_p99", p.against_scene.delta_e_p99),
            p.verdict
                .map_or(lang.pick("the scene's own", "a jelenet sajátja"), |v| v
                    .said(lang))
        );
    }
    h.push_str("</table></div>\n");
}

/// A setting's time cell: the median, and beneath it the fastest and the
/// slowest render where more than one was timed, in milliseconds.
fn time(p: &Point, at: &dyn Fn(&str) -> String) -> String {
    let ms =
        |field: &str, seconds: f64| number("span", &at(field), seconds, &readable(1e3 * seconds));
    let median = ms("seconds_median", p.seconds_median);
    let by_time = |a: &(usize, &f64), b: &(usize, &f64)| a.1.total_cmp(b.1);
    let fastest = p.seconds.iter().enumerate().min_by(by_time);
    let slowest = p.seconds.iter().enumerate().max_by(by_time);
    match (fastest, slowest) {
        (Some((lo, &low)), Some((hi, &high))) if p.seconds.len() > 1 => format!(
            "<td class=num>{median}<br><span class=small>({}–{})</span></td>",
            ms(&format!("seconds/{lo}"), low),
            ms(&format!("seconds/{hi}"), high)
        ),
        _ => format!("<td class=num>{median}</td>"),
    }
}
