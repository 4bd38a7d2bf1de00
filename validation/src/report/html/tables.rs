//! The page's tables after the areas: the metal colours, their timing,
//! every check, the references read.

use std::fmt::Write as _;

use super::format::{case, english, escape, number, readable, status, swatch};
use crate::report::document::Report;
use record::{say, Lang};

/// The metal shortcuts' worst CIEDE2000, with swatches.
pub(super) fn metal_colours(h: &mut String, report: &Report, lang: Lang) {
    if !report.metal_delta_e.is_empty() {
        h.push_str(lang.pick(
            "<h2 id=metal-colours>Metal colours: CIEDE2000 of the shortcuts from the spectral colour</h2>\n\
             <p>Worst over the angles of incidence; about 1 is a just-noticeable difference.</p>\n\
             <div class=scroll><table><tr><th>metal</th><th>shortcut</th><th>worst ΔE00</th><th>at</th><th>spectral | shortcut at that angle</th></tr>\n",
            "<h2 id=metal-colours>Fémek színe: a rövidítések CIEDE2000-eltérése a spektrális színtől</h2>\n\
             <p>A legrosszabb a beesési szögek közül; nagyjából 1 az éppen észrevehető különbség.</p>\n\
             <div class=scroll><table><tr><th>fém</th><th>rövidítés</th><th>legrosszabb ΔE00</th><th>hol</th><th>spektrális | rövidítés abban a szögben</th></tr>\n",
        ));
        for (k, w) in report.metal_delta_e.iter().enumerate() {
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
            let at = |field: &str| format!("/metal_delta_e/{k}/{field}");
            let _ = writeln!(
                h,
                "<tr><td>{}</td><td>{}</td>{}{}<td>{} {}</td></tr>",
                case(lang, &w.metal),
                case(lang, &w.method),
                number(
                    "td",
                    &at("delta_e_2000"),
                    w.delta_e_2000,
                    &format!("{:.2}", w.delta_e_2000)
                ),
                number(
                    "td",
                    &at("at_angle_deg"),
                    w.at_angle_deg,
                    &format!("{}°", readable(w.at_angle_deg))
                ),
                find("spectral (exact)"),
                find(&w.method)
            );
        }
        h.push_str("</table></div>\n");
    }
}

/// The metal-colour timings.
pub(super) fn speed(h: &mut String, report: &Report, lang: Lang) {
    if !report.speed.is_empty() {
        h.push_str(lang.pick(
            "<h2 id=speed>Speed: time per metal colour</h2>\n<div class=scroll><table><tr><th>method</th><th>ns per colour</th><th>colours timed</th></tr>\n",
            "<h2 id=speed>Sebesség: egy fém színének ideje</h2>\n<div class=scroll><table><tr><th>módszer</th><th>ns színenként</th><th>mért színek</th></tr>\n",
        ));
        for (k, t) in report.speed.iter().enumerate() {
            let _ = writeln!(
                h,
                "<tr><td>{}</td>{}{}</tr>",
                case(lang, &t.method),
                number(
                    "td",
                    &format!("/speed/{k}/ns_per_colour"),
                    t.ns_per_colour,
                    &format!("{:.0}", t.ns_per_colour)
                ),
                number(
                    "td",
                    &format!("/speed/{k}/iterations"),
                    t.iterations as f64,
                    &t.iterations.to_string()
                )
            );
        }
        if let [spectral, rgb] = report.speed.as_slice() {
            let unoptimised = match (spectral.optimised, lang) {
                (true, _) => "",
                (false, Lang::En) => "; an unoptimised build: <code>cargo run --release -p optics -- validate</code> gives representative times",
                (false, Lang::Hu) => "; optimalizálatlan fordítás: jellemző időket a <code>cargo run --release -p optics -- validate</code> ad",
            };
            let _ = writeln!(
                h,
                "</table></div>\n<p>{}</p>",
                say!(
                    lang,
                    "The spectrum costs {:.1}× the three wavelengths (wall clock, this machine, one run{}).",
                    "A spektrum a három hullámhossz {:.1}-szeresébe kerül (faliórán mérve, ezen a gépen, egy futás{}).",
                    spectral.ns_per_colour / rgb.ns_per_colour,
                    unoptimised
                )
            );
        } else {
            h.push_str("</table></div>\n");
        }
    }
}

/// Every check, failed ones open, with its failures and findings.
pub(super) fn every_check(h: &mut String, report: &Report, lang: Lang) {
    let _ = writeln!(
        h,
        "<h2 id=checks>{}</h2>",
        lang.pick("Every check in detail", "Minden ellenőrzés részletesen")
    );
    for (i, check) in report.checks.iter().enumerate() {
        let cases = number(
            "span",
            &format!("/checks/{i}/cases"),
            check.cases as f64,
            &check.cases.to_string(),
        );
        let _ = writeln!(
            h,
            "<details{}><summary>{} <b>{}</b>: {}</summary>\n<p>{}</p>",
            if check.passed() { "" } else { " open" },
            status(check, lang),
            escape(&check.id),
            say!(
                lang,
                "{} ({} cases)",
                "{} ({} eset)",
                escape(check.title.pick(lang)),
                cases
            ),
            say!(
                lang,
                "Reference: {}.<br>Tolerance: {}.",
                "Referencia: {}.<br>Tűrés: {}.",
                escape(check.reference.pick(lang)),
                escape(check.tolerance.pick(lang))
            )
        );
        let failures: Vec<String> = (check.failures.iter().enumerate())
            .map(|(k, f)| match (lang, check.failure_hu(k)) {
                (Lang::Hu, Some(hu)) => escape(hu),
                _ => english(lang, f),
            })
            .collect();
        let findings: Vec<String> = (check.findings.iter())
            .map(|f| escape(f.pick(lang)))
            .collect();
        let kinds = [
            (lang.pick("Failures", "Sikertelen esetek"), failures),
            (lang.pick("Findings", "Megállapítások"), findings),
        ];
        for (kind, list) in kinds {
            if !list.is_empty() {
                let _ = writeln!(h, "<p>{kind} ({}):</p><ul>", list.len());
                for item in list {
                    let _ = writeln!(h, "<li>{item}</li>");
                }
                h.push_str("</ul>\n");
            }
        }
        h.push_str("</details>\n");
    }
}

/// The references read, and the page's end.
pub(super) fn references(h: &mut String, report: &Report, lang: Lang) {
    h.push_str(lang.pick(
        "<h2 id=references>References</h2>\n<div class=scroll><table><tr><th>file</th><th>schema</th><th>regenerate</th></tr>\n",
        "<h2 id=references>Referenciák</h2>\n<div class=scroll><table><tr><th>fájl</th><th>séma</th><th>újragenerálás</th></tr>\n",
    ));
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
