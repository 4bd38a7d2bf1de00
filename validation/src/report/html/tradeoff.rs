//! The speed/accuracy trade of each scene, as `optics tradeoff` recorded
//! it: every setting's time and errors beside the scene's Pareto plot.

use std::fmt::Write as _;

use super::figure;
use super::format::{escape, number, readable};
use crate::report::Report;
use crate::tradeoff::checks::REGENERATE;

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
        let plot = figures
            .iter()
            .find(|f| f.ends_with(&format!("tradeoff_{stem}.png")));
        let _ = writeln!(
            h,
            "<details><summary><b>{}</b>: {} settings, {} × {}, truth {} spp; {}, {} ({})</summary>\n\
             <p class=small><code>{}</code></p><div class=side>",
            escape(&stem),
            record.points.len(),
            record.width,
            record.height,
            record.truth.spp,
            escape(&record.machine),
            escape(&record.date),
            escape(&record.load),
            escape(&record.command)
        );
        if let Some(plot) = plot {
            h.push_str("<div>");
            figure(h, plot);
            h.push_str("</div>");
        }
        h.push_str(
            "<div><div class=scroll><table><tr><th>setting</th><th>ms</th><th>× own</th>\
             <th>rel RMSE</th><th>ΔE p99</th><th>ꟻLIP</th><th>ΔE p99 vs own</th><th>verdict</th></tr>\n",
        );
        let base = record.points.first().map_or(f64::NAN, |p| p.seconds_median);
        for (i, p) in record.points.iter().enumerate() {
            let at = |field: &str| format!("/tradeoffs/{k}/points/{i}/{field}");
            let cell = |field: &str, value: f64| number("td", &at(field), value, &readable(value));
            let _ = writeln!(
                h,
                "<tr><td>{}</td>{}<td class=num>{}</td>{}{}{}{}<td>{}</td></tr>",
                escape(&p.label),
                number(
                    "td",
                    &at("seconds_median"),
                    p.seconds_median,
                    &readable(1e3 * p.seconds_median)
                ),
                readable(p.seconds_median / base),
                cell("errors/rel_rmse", p.errors.rel_rmse),
                cell("errors/delta_e_p99", p.errors.delta_e_p99),
                cell("errors/flip_mean", p.errors.flip_mean),
                cell("against_scene/delta_e_p99", p.against_scene.delta_e_p99),
                p.verdict.map_or("the scene's own", |v| v.plain())
            );
        }
        h.push_str("</table></div></div></div></details>\n");
    }
}
