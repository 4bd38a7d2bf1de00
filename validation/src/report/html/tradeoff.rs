//! The speed/accuracy trade of each scene, as `optics tradeoff` recorded
//! it: what its numbers say, every setting's time and errors, the scene's
//! Pareto plot, and the command and machine they came from.

use std::fmt::Write as _;

use super::figures::figure;
use super::format::{escape, inline_code, number, readable};
use crate::report::document::Report;
use crate::tradeoff::checks::REGENERATE;
use crate::tradeoff::record::{Point, Record};

/// One folded section per scene, after the area's checks.
pub(super) fn tradeoffs(h: &mut String, report: &Report, figures: &[&String]) {
    if report.tradeoffs.is_empty() {
        return;
    }
    let _ = writeln!(
        h,
        "<p>Each scene rendered under every setting it allows, each varied alone from the \
         scene's own, timed and measured against a converged render with all the light \
         (the checkout's <code>docs/tradeoffs.md</code> defines the measures). \
         <em>Not seen</em>: within ΔE2000 1 of the scene's own render at the 99th percentile; \
         <em>worth it</em>: not seen and at most 0.9× its time. Regenerate with \
         <code>{REGENERATE}</code>.</p>"
    );
    for (k, record) in report.tradeoffs.iter().enumerate() {
        let stem = record.stem();
        let _ = writeln!(
            h,
            "<details><summary><b>{}</b>: {} settings, {} × {}, truth {} spp</summary>",
            escape(&stem),
            record.points.len(),
            record.width,
            record.height,
            record.truth.spp,
        );
        stamp(h, record);
        if let Some(words) = report.tradeoff_words.get(&stem) {
            let _ = writeln!(
                h,
                "<p class=findings><b>What the numbers say.</b> {}</p>",
                inline_code(words)
            );
        }
        table(h, k, record);
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
fn stamp(h: &mut String, record: &Record) {
    let load = if record.load.is_empty() {
        String::new()
    } else {
        format!(" ({})", escape(&record.load))
    };
    let _ = writeln!(
        h,
        "<p class=small>Measured by <code>{}</code> on {}, {}{load}.</p>",
        escape(&record.command),
        escape(&record.machine),
        escape(&record.date),
    );
}

/// Every setting of record `k`: its time (median and range of the timed
/// renders), its errors from the truth, the light it carries, its ΔE p99
/// from the scene's own render, and the verdict.
fn table(h: &mut String, k: usize, record: &Record) {
    h.push_str(
        "<div class=scroll><table class=trade><tr><th>setting</th>\
         <th>time, ms: median (range)</th><th>× own</th><th>rel RMSE</th><th>ΔE mean</th>\
         <th>ΔE p99</th><th>ꟻLIP</th><th>light, % of truth</th><th>ΔE p99 vs own</th>\
         <th>verdict</th></tr>\n",
    );
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
            escape(&p.label),
            time(p, &at),
            readable(p.seconds_median / base),
            cell("errors/rel_rmse", p.errors.rel_rmse),
            cell("errors/delta_e_mean", p.errors.delta_e_mean),
            cell("errors/delta_e_p99", p.errors.delta_e_p99),
            cell("errors/flip_mean", p.errors.flip_mean),
            cell("against_scene/delta_e_p99", p.against_scene.delta_e_p99),
            p.verdict.map_or("the scene's own", |v| v.plain())
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
