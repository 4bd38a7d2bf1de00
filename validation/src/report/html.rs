//! `report.html`: the report for people, section by section.

use std::fmt::Write as _;

use radiometry::colour::srgb_encode;

use super::Report;
use crate::check::Check;
use crate::compare::map::{heat_colour, LEGEND};
use crate::renders::TRIPTYCH_GAP;

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

/// The areas of the report, in the order of its first screen: a title, the
/// check ids it gathers (by prefix; the first area that claims a check
/// keeps it), and the figures that say it best (file-name prefixes).
const AREAS: [Area; 7] = [
    Area {
        key: "mpmath",
        title: "Laws against 50-digit mpmath",
        checks: &["laws.mpmath."],
        figures: &["fresnel_errors"],
        headline: None,
    },
    Area {
        key: "mitsuba-laws",
        title: "Laws against Mitsuba 3",
        checks: &["laws.mitsuba."],
        figures: &["fresnel_curves"],
        headline: None,
    },
    Area {
        key: "metals",
        title: "Metals: spectra and colour",
        checks: &["colour.colour-science.metals"],
        figures: &["metal_swatches", "metal_delta_e", "metal_spectra"],
        headline: Some("reflectance: max |ours − exact|"),
    },
    Area {
        key: "colour",
        title: "Colour against colour-science",
        checks: &["colour."],
        figures: &[],
        headline: Some("CIELAB: max |ours − colour-science|"),
    },
    Area {
        key: "renders",
        title: "Renders against Mitsuba 3",
        checks: &["renders."],
        figures: &["render_kaleidoscope_lit_path", "render_"],
        headline: Some("|ours − Mitsuba| / tolerance"),
    },
    Area {
        key: "images",
        title: "ꟻLIP against NVIDIA's evaluator",
        checks: &["images."],
        figures: &[],
        headline: Some("mean: |ours − NVIDIA|"),
    },
    Area {
        key: "full-light",
        title: "All the light",
        checks: &["full_light."],
        figures: &[],
        headline: None,
    },
];

/// One area of the report.
struct Area {
    key: &'static str,
    title: &'static str,
    checks: &'static [&'static str],
    figures: &'static [&'static str],
    /// The quantity whose worst value heads the card; `None`: the worst
    /// Fresnel error in ulps.
    headline: Option<&'static str>,
}

/// The command that writes the report and every figure in it.
const REGENERATE: &str = "cargo run --release -p optics -- validate";

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
        if area.area.key == "renders" {
            render_gallery(&mut h, report, &area.figures);
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

/// An area with the checks and figures it claimed.
struct Gathered<'a> {
    area: &'static Area,
    checks: Vec<&'a Check>,
    figures: Vec<&'a String>,
}

fn gather<'a>(report: &'a Report, figures: &'a [String]) -> Vec<Gathered<'a>> {
    let mut areas: Vec<Gathered> = AREAS
        .iter()
        .map(|area| Gathered {
            area,
            checks: Vec::new(),
            figures: Vec::new(),
        })
        .collect();
    let mut other = Vec::new();
    for check in &report.checks {
        match areas
            .iter_mut()
            .find(|a| a.area.checks.iter().any(|p| check.id.starts_with(p)))
        {
            Some(area) => area.checks.push(check),
            None => other.push(check),
        }
    }
    for area in &mut areas {
        for prefix in area.area.figures {
            let file = |f: &&String| f.rsplit('/').next().unwrap_or(f).starts_with(prefix);
            for f in figures.iter().filter(file) {
                if !area.figures.contains(&f) {
                    area.figures.push(f);
                }
            }
        }
    }
    areas.retain(|a| !a.checks.is_empty());
    if !other.is_empty() {
        static OTHER: Area = Area {
            key: "other",
            title: "Other checks",
            checks: &[],
            figures: &[],
            headline: None,
        };
        areas.push(Gathered {
            area: &OTHER,
            checks: other,
            figures: Vec::new(),
        });
    }
    areas
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
    let verdict = if s.failed == 0 {
        format!("<p class=\"verdict pass\">All {} checks pass.", s.checks)
    } else {
        format!(
            "<p class=\"verdict fail\">{} of {} checks FAIL.",
            s.failed, s.checks
        )
    };
    let _ = writeln!(
        h,
        "{verdict} {} findings about the references (below), which are not failures.</p>\n\
         <p class=small>Produced by <code>{}</code> ({}); regenerate everything here with <code>{REGENERATE}</code>.</p>",
        s.findings,
        escape(&report.command),
        if report.quick { "the reduced set" } else { "the full set" },
    );
}

const STYLE: &str = "body{font-family:sans-serif;max-width:72em;margin:1em auto;padding:0 1em;line-height:1.4;overflow-wrap:anywhere}\
h2{margin-top:2em;border-bottom:1px solid #ddd}\
.verdict{font-size:1.3em;font-weight:bold}.small{font-size:.9em;color:#444}\
.cards{display:grid;grid-template-columns:repeat(auto-fill,minmax(15em,1fr));gap:.8em}\
.card{border:1px solid #ccc;border-radius:.4em;padding:.6em;min-width:0}\
.card h3{margin:0 0 .3em;font-size:1em}.card a{color:inherit}.card img{width:100%;height:7em;object-fit:contain}\
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
.flip:hover img,.flip:focus img{object-position:50% 0}.flip:focus{outline:2px solid #36c}\
.ramp{display:inline-block;width:8em;height:1em;border:1px solid #888;vertical-align:middle}code{background:#f4f4f4;overflow-wrap:anywhere}";

/// One card per area: its pass count, its headline, its figure.
fn cards(h: &mut String, areas: &[Gathered]) {
    h.push_str("<div class=cards>\n");
    for a in areas {
        let passed = a.checks.iter().filter(|c| c.passed()).count();
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
    h.push_str("</div>\n");
}

/// The worst value of the area's `quantity` over its checks; without one,
/// its worst Fresnel error in ulps where it measures them (the laws held to
/// a bound in ulps alone; an angle's bound grows with its condition
/// number); failing both, its number of findings.
fn headline(quantity: Option<&str>, checks: &[&Check]) -> Option<String> {
    let named = quantity.and_then(|name| {
        checks
            .iter()
            .flat_map(|c| c.metrics.iter())
            .filter(|m| m.name == name)
            .max_by(|a, b| a.worst.total_cmp(&b.worst))
    });
    if let Some(m) = named {
        return Some(format!("worst {}: {}", readable(m.worst), escape(&m.name)));
    }
    let worst = checks
        .iter()
        .flat_map(|c| c.metrics.iter().map(move |m| (c, m)))
        .filter(|(c, m)| c.id.contains("fresnel") || m.name.starts_with("fresnel"))
        .map(|(_, m)| m)
        .filter(|m| m.name.contains("ulps") && m.worst.is_finite())
        .max_by(|a, b| a.worst.total_cmp(&b.worst));
    if let Some(m) = worst {
        return Some(format!(
            "worst {} ulps ({})",
            readable(m.worst),
            escape(m.name.trim_end_matches(" (ulps)"))
        ));
    }
    let findings: usize = checks.iter().map(|c| c.findings.len()).sum();
    let plural = if findings == 1 { "" } else { "s" };
    (findings > 0).then(|| format!("{findings} finding{plural} about the reference"))
}

/// The findings about the references, in the words of their checks.
fn findings(h: &mut String, report: &Report) {
    let all: Vec<(&str, &String)> = report
        .checks
        .iter()
        .flat_map(|c| c.findings.iter().map(move |f| (c.id.as_str(), f)))
        .collect();
    if all.is_empty() {
        return;
    }
    let _ = writeln!(
        h,
        "<h2 id=findings>What the references get wrong</h2>\n<p>Where a reference departs \
         from the exact law, reported and not counted as a failure ({}):</p><ul>",
        all.len()
    );
    let item = |h: &mut String, (id, f): &(&str, &String)| {
        let _ = writeln!(
            h,
            "<li>{} <span class=small>({})</span></li>",
            escape(f),
            escape(id)
        );
    };
    for f in all.iter().take(4) {
        item(h, f);
    }
    h.push_str("</ul>\n");
    if all.len() > 4 {
        let _ = writeln!(h, "<details><summary>{} more</summary><ul>", all.len() - 4);
        for f in &all[4..] {
            item(h, f);
        }
        h.push_str("</ul></details>\n");
    }
}

/// An area: its figures beside the table of its checks' worst values.
fn area_section(h: &mut String, a: &Gathered) {
    let _ = writeln!(h, "<h2 id=\"{}\">{}</h2>", a.area.key, a.area.title);
    let rows: usize = a.checks.iter().map(|c| c.metrics.len().max(1)).sum();
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
    for check in &a.checks {
        for m in &check.metrics {
            let _ = writeln!(
                h,
                "<tr><td>{} {}</td><td>{}</td><td class=num data-check=\"{}\" data-metric=\"{}\" data-value=\"{:e}\">{}</td><td>{}</td></tr>",
                status(check),
                escape(short_id(&check.id)),
                escape(&m.name),
                escape(&check.id),
                escape(&m.name),
                m.worst,
                readable(m.worst),
                escape(&readable_at(&m.at))
            );
        }
    }
    h.push_str("</table></div>\n");
    if folded {
        h.push_str("</details>\n");
    }
    h.push_str("</div></div>\n");
    if a.figures.len() > 1 && a.area.key != "renders" {
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

/// Each render compared: ours, flipping to Mitsuba's under the pointer or
/// the keyboard's focus (the triptych's first two panels, so the two are
/// pixel for pixel the same size), and the whole triptych with the
/// difference map, its scale beside it.
fn render_gallery(h: &mut String, report: &Report, figures: &[&String]) {
    if figures.is_empty() {
        return;
    }
    let _ = writeln!(
        h,
        "<h3 id=render-figures>Each render: ours, flipping to Mitsuba's</h3>\n\
         <p>Point at (or tab to) an image to see Mitsuba's render in its place; beside it \
         ours | Mitsuba | the difference, enlarged without smoothing. {}</p>\n<div class=figures>",
        heat_legend()
    );
    for file in figures {
        let name = file.rsplit('/').next().unwrap_or(file);
        let Some(f) = report.render_figures.iter().find(|f| f.file == name) else {
            figure(h, file);
            continue;
        };
        // Three panels and two gaps across, one panel high.
        let panel = (f.image.width - 2 * TRIPTYCH_GAP) / 3;
        let _ = writeln!(
            h,
            "<figure class=render><div class=flip tabindex=0 style=\"aspect-ratio:{panel}/{height}\">\
             <img class=pixels src=\"{src}\" alt=\"ours, or Mitsuba's under the pointer: {name}\"></div>\
             <figcaption>{label}: ours (pointed at: Mitsuba)</figcaption></figure>",
            height = f.image.height,
            src = escape(file),
            name = escape(name),
            label = escape(name.trim_start_matches("render_").trim_end_matches(".png")),
        );
        figure(h, file);
    }
    h.push_str("</div>\n");
}

/// The difference map's colour scale, drawn from the map's own colours.
fn heat_legend() -> String {
    let css = |c: glam::Vec3| {
        let [r, g, b] = [c.x, c.y, c.z].map(|v| (srgb_encode(f64::from(v)) * 255.0).round() as u8);
        format!("rgb({r},{g},{b})")
    };
    let stops: Vec<String> = (0..=8)
        .map(|k| {
            let t = f64::from(k) / 8.0;
            format!("{} {}%", css(heat_colour(&[t])), k * 100 / 8)
        })
        .collect();
    format!(
        "<span class=legend><span class=ramp style=\"background:linear-gradient(to right,{})\"></span> \
         0 to 1 <span class=swatch style=\"background:{}\"></span> beyond 1 \
         <span class=swatch style=\"background:{}\"></span> masked</span> (the difference map: {})",
        stops.join(","),
        css(heat_colour(&[2.0])),
        css(heat_colour(&[f64::NAN])),
        escape(LEGEND)
    )
}

/// A check's id without the area's part: `renders.mitsuba.shadow.path` as
/// `mitsuba.shadow.path`.
fn short_id(id: &str) -> &str {
    id.split_once('.').map_or(id, |(_, rest)| rest)
}

/// A figure, named by its file and the command that regenerates it.
fn figure(h: &mut String, file: &str) {
    let pixels = if file.contains("render_") {
        " class=pixels"
    } else {
        ""
    };
    let _ = writeln!(
        h,
        "<figure><img{pixels} src=\"{0}\" alt=\"{0}\"><figcaption>{0}: <code>{REGENERATE}</code></figcaption></figure>",
        escape(file)
    );
}

/// A number for reading: four significant digits, no exponent between
/// 0.001 and 100 000.
fn readable(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let magnitude = x.abs().log10().floor() as i32;
    if (-3..5).contains(&magnitude) {
        let decimals = (3 - magnitude).max(0) as usize;
        let text = format!("{x:.decimals$}");
        if text.contains('.') {
            return text.trim_end_matches('0').trim_end_matches('.').to_owned();
        }
        return text;
    }
    let text = format!("{x:.3e}");
    match text.split_once('e') {
        Some((mantissa, exponent)) if mantissa.contains('.') => {
            let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
            format!("{mantissa}e{exponent}")
        }
        _ => text,
    }
}

/// Where a worst value occurred, for reading: a case given as a JSON
/// request (`case 7: {"law": ...}`) as its fields, `name = value`.
fn readable_at(at: &str) -> String {
    let (label, body) = match at.find('{') {
        Some(i) => (at[..i].trim_end(), &at[i..]),
        None => return at.to_owned(),
    };
    let Ok(serde_json::Value::Object(fields)) = serde_json::from_str::<serde_json::Value>(body)
    else {
        return at.to_owned();
    };
    let fields: Vec<String> = fields
        .iter()
        .map(|(k, v)| match v {
            serde_json::Value::Number(n) => match n.as_f64() {
                Some(x) if !n.is_i64() && !n.is_u64() => format!("{k} = {}", readable(x)),
                _ => format!("{k} = {n}"),
            },
            serde_json::Value::String(s) => format!("{k} = {s}"),
            other => format!("{k} = {other}"),
        })
        .collect();
    let label = label.trim_end_matches(':');
    if label.is_empty() {
        fields.join(", ")
    } else {
        format!("{label}: {}", fields.join(", "))
    }
}

/// The metal shortcuts' worst CIEDE2000, with swatches.
fn metal_colours(h: &mut String, report: &Report) {
    if !report.metal_delta_e.is_empty() {
        h.push_str("<h2 id=metal-colours>Metal colours: CIEDE2000 of the shortcuts from the spectral colour</h2>\n\
                    <p>Worst over the angles of incidence; about 1 is a just-noticeable difference.</p>\n\
                    <div class=scroll><table><tr><th>metal</th><th>shortcut</th><th>worst ΔE00</th><th>at</th><th>spectral | shortcut at that angle</th></tr>\n");
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
        h.push_str("</table></div>\n");
    }
}

/// The metal-colour timings.
fn speed(h: &mut String, report: &Report) {
    if !report.speed.is_empty() {
        h.push_str("<h2 id=speed>Speed: time per metal colour</h2>\n<div class=scroll><table><tr><th>method</th><th>ns per colour</th><th>colours timed</th></tr>\n");
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
                "</table></div>\n<p>The spectrum costs {:.1}× the three wavelengths (wall clock, this machine, one run{}).</p>",
                spectral.ns_per_colour / rgb.ns_per_colour,
                if spectral.optimised {
                    ""
                } else {
                    "; an unoptimised build: <code>cargo run --release -p optics -- validate</code> gives representative times"
                }
            );
        } else {
            h.push_str("</table></div>\n");
        }
    }
}

/// Every check, failed ones open, with its failures and findings.
fn every_check(h: &mut String, report: &Report) {
    h.push_str("<h2 id=checks>Every check in detail</h2>\n");
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
        "<h2 id=references>References</h2>\n<div class=scroll><table><tr><th>file</th><th>schema</th><th>regenerate</th></tr>\n",
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
    h.push_str("</table></div>\n</body></html>\n");
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
