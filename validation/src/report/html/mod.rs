//! `report.html`: the report for people, section by section.

mod areas;
mod course_texts;
mod figures;
mod format;
mod renders;
mod tables;
mod tradeoff;

use std::fmt::Write as _;

use super::document::Report;
use crate::check::{Check, Metric};
use areas::{gather, Gathered};
use course_texts::course_texts_card;
use figures::{figure, REGENERATE};
use format::{escape, number, quote, readable, readable_at, status};
use renders::render_gallery;
use tables::{every_check, metal_colours, references, speed};

/// `report.html`: the verdict and one card per area first, each area's
/// section with its figures beside its numbers, every check in detail, and
/// the references read; `figures` are file names relative to the report.
pub fn to_html(report: &Report, figures: &[String]) -> String {
    let areas = gather(report, figures);
    let mut h = String::new();
    header(&mut h, report);
    cards(&mut h, &areas);
    findings(&mut h, report);
    for area in &areas {
        area_section(&mut h, area);
        match area.area.key {
            "renders" => render_gallery(&mut h, report, &area.figures),
            "tradeoff" => tradeoff::tradeoffs(&mut h, report, &area.figures),
            _ => {}
        }
    }
    metal_colours(&mut h, report);
    speed(&mut h, report);
    let claimed: Vec<&String> = areas
        .iter()
        .flat_map(|a| a.figures.iter().copied())
        .collect();
    let others: Vec<&String> = figures.iter().filter(|f| !claimed.contains(f)).collect();
    if !others.is_empty() {
        h.push_str("<h2 id=figures>Other figures</h2>\n<div class=figures>\n");
        for f in others {
            figure(&mut h, f);
        }
        h.push_str("</div>\n");
    }
    every_check(&mut h, report);
    references(&mut h, report);
    h
}

/// The page head, the style and the verdict.
fn header(h: &mut String, report: &Report) {
    let s = &report.summary;
    let _ = write!(
        h,
        "<!doctype html>\n<html lang=en><head><meta charset=utf-8>\
         <meta name=viewport content=\"width=device-width, initial-scale=1\">\
         <title>optics validation report</title>\n<style>{STYLE}</style></head><body>\n\
         <h1>optics validation report</h1>\n"
    );
    let count = |field: &str, value: usize| {
        number(
            "span",
            &format!("/summary/{field}"),
            value as f64,
            &value.to_string(),
        )
    };
    let verdict = if s.failed == 0 {
        format!(
            "<p class=\"verdict pass\">All {} checks pass.</p>",
            count("checks", s.checks)
        )
    } else {
        format!(
            "<p class=\"verdict fail\">{} of {} checks FAIL.</p>",
            count("failed", s.failed),
            count("checks", s.checks)
        )
    };
    let tally = if s.failed == 0 {
        format!(
            "{} passed, {} failed",
            count("passed", s.passed),
            count("failed", s.failed)
        )
    } else {
        format!("{} passed", count("passed", s.passed))
    };
    let _ = writeln!(
        h,
        "{verdict}\n<p class=small>{tally}; {} findings about the references (below), which are not \
         failures. Produced by <code>{}</code> ({}); regenerate everything here with <code>{REGENERATE}</code>.</p>",
        count("findings", s.findings),
        escape(&report.command),
        if report.quick { "the reduced set" } else { "the full set" },
    );
}

const STYLE: &str = "body{font-family:sans-serif;max-width:72em;margin:1em auto;padding:0 1em;line-height:1.4;overflow-wrap:anywhere}\
h2{margin-top:2em;border-bottom:1px solid #ddd}\
.verdict{font-size:1.3em;font-weight:bold;margin-bottom:.2em}.small{font-size:.9em;color:#444}\
.cards{display:grid;grid-template-columns:repeat(auto-fill,minmax(12.5em,1fr));gap:.6em}\
.card{border:1px solid #ccc;border-radius:.4em;padding:.6em;min-width:0}\
.card h3{margin:0 0 .3em;font-size:1em}.card a{color:inherit}.card img{width:100%;height:6em;object-fit:contain}\
.scroll{overflow-x:auto;max-width:100%}\
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:.2em .5em;text-align:left;vertical-align:top}\
td{overflow-wrap:anywhere}td.num{text-align:right;font-family:monospace;white-space:nowrap}\
.pass{color:#070}.fail{color:#b00;font-weight:bold}\
.swatch{display:inline-block;width:2em;height:1em;border:1px solid #888;vertical-align:middle}\
details{margin:.5em 0}summary{cursor:pointer}\
.side{display:flex;flex-wrap:wrap;gap:1em;align-items:flex-start}.side>*{min-width:0;flex:1 1 24em}\
.figures{display:flex;flex-wrap:wrap;gap:1em}figure{margin:0;max-width:100%;min-width:0}\
img{max-width:100%}img.pixels{image-rendering:pixelated}\
figcaption{font-size:.85em;color:#444;overflow-wrap:anywhere}\
.render{width:16em;max-width:100%}.flip img{display:block;width:100%;height:100%;object-fit:cover;object-position:0 0}\
.flip:hover img,.flip:focus img{object-position:var(--second) 0}.flip:focus{outline:2px solid #36c}\
.trade td,.trade th{overflow-wrap:normal}.trade td:first-child{min-width:9em}.trade td:last-child{white-space:nowrap}.plot{max-width:48em}\
.ramp{display:inline-block;width:8em;height:1em;border:1px solid #888;vertical-align:middle}code{background:#f4f4f4;overflow-wrap:anywhere}";

/// One card per area: its pass count, its headline, its figure; then the
/// course texts' card.
fn cards(h: &mut String, areas: &[Gathered]) {
    h.push_str("<div class=cards>\n");
    for a in areas {
        let passed = a.checks.iter().filter(|(_, c)| c.passed()).count();
        let class = if passed == a.checks.len() {
            "pass"
        } else {
            "fail"
        };
        let _ = write!(
            h,
            "<div class=card><h3><a href=\"#{}\">{}</a></h3><p><span class={class}>{passed} of {} pass</span>",
            a.area.key,
            a.area.title,
            a.checks.len()
        );
        if let Some(line) = headline(a.area.headline, &a.checks) {
            let _ = write!(h, "<br>{line}");
        }
        h.push_str("</p>");
        if let Some(f) = a.figures.first() {
            let _ = write!(h, "<img src=\"{0}\" alt=\"{0}\">", escape(f));
        }
        h.push_str("</div>\n");
    }
    course_texts_card(h);
    h.push_str("</div>\n");
}

/// The worst value of the area's `quantity` over its checks; without one,
/// its worst Fresnel error in ulps where it measures them (the laws held to
/// a bound in ulps alone; an angle's bound grows with its condition
/// number); failing both, its number of findings.
fn headline(quantity: Option<&str>, checks: &[(usize, &Check)]) -> Option<String> {
    let metrics = || {
        checks.iter().flat_map(|&(i, c)| {
            c.metrics
                .iter()
                .enumerate()
                .map(move |(j, m)| (format!("/checks/{i}/metrics/{j}/worst"), c, m))
        })
    };
    let worst = |a: &(String, &Check, &Metric), b: &(String, &Check, &Metric)| {
        a.2.worst.total_cmp(&b.2.worst)
    };
    let named =
        quantity.and_then(|name| metrics().filter(|(_, _, m)| m.name == name).max_by(worst));
    if let Some((at, _, m)) = named {
        let value = quote(&at, m.worst, &readable(m.worst));
        return Some(format!("largest {value}: {}", escape(&m.name)));
    }
    let ulps = metrics()
        .filter(|(_, c, m)| c.id.contains("fresnel") || m.name.starts_with("fresnel"))
        .filter(|(_, _, m)| m.name.contains("ulps") && m.worst.is_finite())
        .max_by(worst);
    if let Some((at, _, m)) = ulps {
        let value = quote(&at, m.worst, &readable(m.worst));
        return Some(format!(
            "worst {value} ulps ({})",
            escape(m.name.trim_end_matches(" (ulps)"))
        ));
    }
    let findings: usize = checks.iter().map(|(_, c)| c.findings.len()).sum();
    let plural = if findings == 1 { "" } else { "s" };
    (findings > 0).then(|| format!("{findings} finding{plural} about the reference"))
}

/// The findings about the references: one plain sentence per check that
/// has any (its [`Check::gist`], or its first finding where it has none),
/// every finding in its check's own words folded beneath.
fn findings(h: &mut String, report: &Report) {
    let with: Vec<&Check> = report
        .checks
        .iter()
        .filter(|c| !c.findings.is_empty())
        .collect();
    if with.is_empty() {
        return;
    }
    let _ = writeln!(
        h,
        "<h2 id=findings>What the references get wrong</h2>\n<p>Where a reference departs \
         from the exact law or from the other reference, reported and not counted as a \
         failure ({} findings in {} checks):</p><ul>",
        report.summary.findings,
        with.len()
    );
    for check in with {
        let gist = check.gist.as_deref().unwrap_or(&check.findings[0]);
        let _ = writeln!(
            h,
            "<li>{} <span class=small>({})</span><details><summary>{} finding{} in detail</summary><ul>",
            escape(gist),
            escape(&check.id),
            check.findings.len(),
            if check.findings.len() == 1 { "" } else { "s" }
        );
        for f in &check.findings {
            let _ = writeln!(h, "<li>{}</li>", escape(f));
        }
        h.push_str("</ul></details></li>\n");
    }
    h.push_str("</ul>\n");
}

/// An area: its figures beside the table of its checks' worst values.
fn area_section(h: &mut String, a: &Gathered) {
    let _ = writeln!(h, "<h2 id=\"{}\">{}</h2>", a.area.key, a.area.title);
    let rows: usize = a.checks.iter().map(|(_, c)| c.metrics.len().max(1)).sum();
    h.push_str("<div class=side>\n");
    if let Some(f) = a.figures.first() {
        h.push_str("<div>");
        figure(h, f);
        h.push_str("</div>\n");
    }
    h.push_str("<div>");
    let folded = rows > 12;
    if folded {
        let _ = writeln!(
            h,
            "<details><summary>The worst value of each of {} quantities over {} checks</summary>",
            rows,
            a.checks.len()
        );
    }
    h.push_str("<div class=scroll><table><tr><th>check</th><th>quantity</th><th>worst</th><th>at</th></tr>\n");
    for &(i, check) in &a.checks {
        for (j, m) in check.metrics.iter().enumerate() {
            let _ = writeln!(
                h,
                "<tr><td>{} {}</td><td>{}</td>{}<td>{}</td></tr>",
                status(check),
                escape(short_id(&check.id)),
                escape(&m.name),
                number(
                    "td",
                    &format!("/checks/{i}/metrics/{j}/worst"),
                    m.worst,
                    &readable(m.worst)
                ),
                escape(&readable_at(&m.at))
            );
        }
    }
    h.push_str("</table></div>\n");
    if folded {
        h.push_str("</details>\n");
    }
    h.push_str("</div></div>\n");
    if a.figures.len() > 1 && !["renders", "tradeoff"].contains(&a.area.key) {
        let _ = writeln!(
            h,
            "<details><summary>{} more figures</summary><div class=figures>",
            a.figures.len() - 1
        );
        for f in &a.figures[1..] {
            figure(h, f);
        }
        h.push_str("</div></details>\n");
    }
}

/// A check's id without the area's part: `renders.mitsuba.shadow.path` as
/// `mitsuba.shadow.path`.
fn short_id(id: &str) -> &str {
    id.split_once('.').map_or(id, |(_, rest)| rest)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn html_is_escaped() {
        assert_eq!(escape("<a & \"b\">"), "&lt;a &amp; &quot;b&quot;&gt;");
    }

    #[test]
    fn prose_shows_its_code_spans_as_code_and_escapes_the_rest() {
        for (markdown, html) in [
            ("`max_depth 4` (0.77×)", "<code>max_depth 4</code> (0.77×)"),
            ("a < b, `x & y`", "a &lt; b, <code>x &amp; y</code>"),
            ("`a` and `b`", "<code>a</code> and <code>b</code>"),
            ("one ` left", "one ` left"),
            ("`a` and ` left", "<code>a</code> and ` left"),
            ("", ""),
        ] {
            assert_eq!(format::inline_code(markdown), html, "{markdown}");
        }
    }

    #[test]
    fn a_failed_check_is_shown_open_and_marked() {
        let mut report = Report::new(true, "optics validate --quick");
        let mut check = Check::new("x.y", "t", "r", "tol");
        check.cases = 1;
        check.fail("broken <law>".into());
        report.checks.push(check);
        report.summarise();
        let html = to_html(&report, &[]);
        assert!(
            html.contains("<details open>")
                && html.contains("FAIL")
                && html.contains("broken &lt;law&gt;")
        );
    }
}
