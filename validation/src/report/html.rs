//! `report.html`: the report for people, section by section.

use std::fmt::Write as _;

use super::Report;
use crate::check::Check;

fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            _ => out.push(c),
        }
    }
    out
}

fn status(check: &Check) -> &'static str {
    if check.passed() {
        "<span class=pass>pass</span>"
    } else {
        "<span class=fail>FAIL</span>"
    }
}

fn swatch(srgb: [f64; 3]) -> String {
    let [r, g, b] = srgb.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8);
    format!("<span class=swatch style=\"background: rgb({r}, {g}, {b})\"></span>")
}

/// `report.html`: summary, headline tables, every check, the figures found
/// in `figures` (file names relative to the report).
pub fn to_html(report: &Report, figures: &[String]) -> String {
    let mut h = String::new();
    header(&mut h, report);
    worst_errors(&mut h, report);
    metal_colours(&mut h, report);
    speed(&mut h, report);
    figures_section(&mut h, figures);
    every_check(&mut h, report);
    references(&mut h, report);
    h
}

/// The page head, the style and the summary line.
fn header(h: &mut String, report: &Report) {
    let s = &report.summary;
    let _ = write!(
        h,
        "<!doctype html>\n<html lang=en><head><meta charset=utf-8><title>optics validation report</title>\n\
         <style>body{{font-family:sans-serif;max-width:70em;margin:2em auto;padding:0 1em}}\
         table{{border-collapse:collapse;margin:1em 0}}td,th{{border:1px solid #ccc;padding:.2em .5em;text-align:left}}\
         td.num{{text-align:right;font-family:monospace}}.pass{{color:#070}}.fail{{color:#b00;font-weight:bold}}\
         .swatch{{display:inline-block;width:2em;height:1em;border:1px solid #888;vertical-align:middle}}\
         details{{margin:.5em 0}}img{{max-width:100%}}code{{background:#f4f4f4}}</style></head><body>\n\
         <h1>optics validation report</h1>\n<p>Produced by <code>{}</code> ({}). \
         {} checks: <span class=pass>{} passed</span>, <span class={}>{} failed</span>; {} findings about the references.</p>\n",
        escape(&report.command),
        if report.quick { "reduced set" } else { "full set" },
        s.checks,
        s.passed,
        if s.failed > 0 { "fail" } else { "pass" },
        s.failed,
        s.findings
    );
}

/// Every metric's worst value, one row per check and quantity.
fn worst_errors(h: &mut String, report: &Report) {
    h.push_str("<h2>Worst errors per law and reference</h2>\n<table><tr><th>check</th><th>status</th><th>quantity</th><th>worst</th><th>at</th></tr>\n");
    for check in &report.checks {
        for m in &check.metrics {
            let _ = writeln!(
                h,
                "<tr><td>{}</td><td>{}</td><td>{}</td><td class=num>{:.3e}</td><td>{}</td></tr>",
                escape(&check.id),
                status(check),
                escape(&m.name),
                m.worst,
                escape(&m.at)
            );
        }
    }
    h.push_str("</table>\n");
}

/// The metal shortcuts' worst CIEDE2000, with swatches.
fn metal_colours(h: &mut String, report: &Report) {
    if !report.metal_delta_e.is_empty() {
        h.push_str("<h2>Metal colours: CIEDE2000 of the shortcuts from the spectral colour</h2>\n\
                    <p>Worst over the angles of incidence; about 1 is a just-noticeable difference.</p>\n\
                    <table><tr><th>metal</th><th>shortcut</th><th>worst ΔE00</th><th>at</th><th>spectral | shortcut at that angle</th></tr>\n");
        for w in &report.metal_delta_e {
            let find = |method: &str| {
                report
                    .metal_colours
                    .iter()
                    .find(|c| {
                        c.metal == w.metal && c.method == method && c.angle_deg == w.at_angle_deg
                    })
                    .map(|c| swatch(c.srgb))
                    .unwrap_or_default()
            };
            let _ = writeln!(
                h,
                "<tr><td>{}</td><td>{}</td><td class=num>{:.2}</td><td class=num>{}°</td><td>{} {}</td></tr>",
                escape(&w.metal),
                escape(&w.method),
                w.delta_e_2000,
                w.at_angle_deg,
                find("spectral (exact)"),
                find(&w.method)
            );
        }
        h.push_str("</table>\n");
    }
}

/// The metal-colour timings.
fn speed(h: &mut String, report: &Report) {
    if !report.speed.is_empty() {
        h.push_str("<h2>Speed: time per metal colour</h2>\n<table><tr><th>method</th><th>ns per colour</th><th>colours timed</th></tr>\n");
        for t in &report.speed {
            let _ = writeln!(
                h,
                "<tr><td>{}</td><td class=num>{:.0}</td><td class=num>{}</td></tr>",
                escape(&t.method),
                t.ns_per_colour,
                t.iterations
            );
        }
        if let [spectral, rgb] = report.speed.as_slice() {
            let _ = writeln!(
                h,
                "</table>\n<p>The spectrum costs {:.1}× the three wavelengths (wall clock, this machine, one run{}).</p>",
                spectral.ns_per_colour / rgb.ns_per_colour,
                if spectral.optimised {
                    ""
                } else {
                    "; an unoptimised build: <code>cargo run --release -p optics -- validate</code> gives representative times"
                }
            );
        } else {
            h.push_str("</table>\n");
        }
    }
}

/// The figures, by file name relative to the report.
fn figures_section(h: &mut String, figures: &[String]) {
    if !figures.is_empty() {
        h.push_str("<h2>Figures</h2>\n");
        for f in figures {
            let _ = writeln!(
                h,
                "<figure><img src=\"{0}\" alt=\"{0}\"><figcaption>{0}</figcaption></figure>",
                escape(f)
            );
        }
    }
}

/// Every check, failed ones open, with its failures and findings.
fn every_check(h: &mut String, report: &Report) {
    h.push_str("<h2>Every check</h2>\n");
    for check in &report.checks {
        let _ = writeln!(
            h,
            "<details{}><summary>{} <b>{}</b>: {} ({} cases)</summary>\n<p>Reference: {}.<br>Tolerance: {}.</p>",
            if check.passed() { "" } else { " open" },
            status(check),
            escape(&check.id),
            escape(&check.title),
            check.cases,
            escape(&check.reference),
            escape(&check.tolerance)
        );
        for (kind, list) in [("Failures", &check.failures), ("Findings", &check.findings)] {
            if !list.is_empty() {
                let _ = writeln!(h, "<p>{kind} ({}):</p><ul>", list.len());
                for item in list {
                    let _ = writeln!(h, "<li>{}</li>", escape(item));
                }
                h.push_str("</ul>\n");
            }
        }
        h.push_str("</details>\n");
    }
}

/// The references read, and the page's end.
fn references(h: &mut String, report: &Report) {
    h.push_str(
        "<h2>References</h2>\n<table><tr><th>file</th><th>schema</th><th>regenerate</th></tr>\n",
    );
    for (name, info) in &report.references {
        let _ = writeln!(
            h,
            "<tr><td>{}</td><td>{}</td><td><code>{}</code></td></tr>",
            escape(name),
            escape(&info.schema),
            escape(&info.regenerate)
        );
    }
    h.push_str("</table>\n</body></html>\n");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn html_is_escaped() {
        assert_eq!(escape("<a & \"b\">"), "&lt;a &amp; &quot;b&quot;&gt;");
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
