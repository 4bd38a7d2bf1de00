//! `report.html`: the report for people, section by section, in English
//! or Hungarian: each text of the page written in both languages at the
//! place that writes it.

mod areas;
mod course_texts;
mod figures;
mod format;
mod headline;
mod renders;
mod style;
mod tables;
mod tradeoff;

use std::fmt::Write as _;

use super::document::Report;
use crate::check::Check;
use areas::{gather, Gathered};
use course_texts::course_texts_card;
use figures::{figure, thumbnail, REGENERATE};
use format::{case, english, escape, number, readable, readable_at, status};
use record::{say, Lang};
use renders::render_gallery;
use style::STYLE;
use tables::{every_check, metal_colours, references, speed};

/// `report.html` in `lang`: the verdict and one card per area first, each
/// area's section with its figures beside its numbers, every check in
/// detail, and the references read; `figures` are file names relative to
/// the report.
pub fn to_html(report: &Report, figures: &[String], lang: Lang) -> String {
    let areas = gather(report, figures);
    let mut h = String::new();
    header(&mut h, report, lang);
    cards(&mut h, &areas, lang);
    findings(&mut h, report, lang);
    for area in &areas {
        area_section(&mut h, area, lang);
        match area.area.key {
            "renders" => render_gallery(&mut h, report, &area.figures, lang),
            "tradeoff" => tradeoff::tradeoffs(&mut h, report, &area.figures, lang),
            _ => {}
        }
    }
    metal_colours(&mut h, report, lang);
    speed(&mut h, report, lang);
    let claimed: Vec<&String> = areas
        .iter()
        .flat_map(|a| a.figures.iter().copied())
        .collect();
    let others: Vec<&String> = figures.iter().filter(|f| !claimed.contains(f)).collect();
    if !others.is_empty() {
        let _ = writeln!(
            h,
            "<h2 id=figures>{}</h2>\n<div class=figures>",
            lang.pick("Other figures", "További ábrák")
        );
        for f in others {
            figure(&mut h, f);
        }
        h.push_str("</div>\n");
    }
    every_check(&mut h, report, lang);
    references(&mut h, report, lang);
    h
}

/// The page head, the style and the verdict.
fn header(h: &mut String, report: &Report, lang: Lang) {
    let s = &report.summary;
    let title = lang.pick(
        "optics validation report",
        "Az optics ellenőrzési jelentése",
    );
    let _ = write!(
        h,
        "<!doctype html>\n<html lang={}><head><meta charset=utf-8>\
         <meta name=viewport content=\"width=device-width, initial-scale=1\">\
         <title>{title}</title>\n<style>{STYLE}</style></head><body>\n\
         <h1>{title}</h1>\n",
        lang.pick("en", "hu")
    );
    let count = |field: &str, value: usize| {
        number(
            "span",
            &format!("/summary/{field}"),
            value as f64,
            &value.to_string(),
        )
    };
    let (checks, passed, failed) = (
        count("checks", s.checks),
        count("passed", s.passed),
        count("failed", s.failed),
    );
    let (verdict, tally) = if s.failed == 0 {
        (
            say!(
                lang,
                "<p class=\"verdict pass\">All {} checks pass.</p>",
                "<p class=\"verdict pass\">{} ellenőrzés, mind sikeres.</p>",
                checks
            ),
            say!(
                lang,
                "{} passed, {} failed",
                "{} sikeres, {} sikertelen",
                passed,
                failed
            ),
        )
    } else {
        (
            say!(
                lang,
                "<p class=\"verdict fail\">{} of {} checks FAIL.</p>",
                "<p class=\"verdict fail\">{1} ellenőrzésből {0} HIBÁS.</p>",
                failed,
                checks
            ),
            say!(lang, "{} passed", "{} sikeres", passed),
        )
    };
    let set = match (report.quick, lang) {
        (true, Lang::En) => "the reduced set",
        (false, Lang::En) => "the full set",
        (true, Lang::Hu) => "a szűkített készlet",
        (false, Lang::Hu) => "a teljes készlet",
    };
    let _ = writeln!(
        h,
        "{verdict}\n<p class=small>{}</p>",
        say!(
            lang,
            "{}; {} findings about the references (below), which are not failures. Produced by \
             <code>{}</code> ({}); regenerate everything here with <code>{}</code>.",
            "{}; {} megállapítás a referenciákról (lent); ezek nem számítanak kudarcnak. \
             Készítette: <code>{}</code> ({}); mindent, ami itt van, újragenerál: <code>{}</code>.",
            tally,
            count("findings", s.findings),
            escape(&report.command),
            set,
            REGENERATE
        )
    );
}

/// One card per area: its pass count, its headline, its figure (a link to
/// the figure in full); then the course texts' card.
fn cards(h: &mut String, areas: &[Gathered], lang: Lang) {
    h.push_str("<div class=cards>\n");
    for a in areas {
        let passed = a.checks.iter().filter(|(_, c)| c.passed()).count();
        let class = if passed == a.checks.len() {
            "pass"
        } else {
            "fail"
        };
        let tally = say!(
            lang,
            "{} of {} pass",
            "{} / {} sikeres",
            passed,
            a.checks.len()
        );
        let _ = write!(
            h,
            "<div class=card><h3><a href=\"#{}\">{}</a></h3><p><span class={class}>{tally}</span>",
            a.area.key,
            lang.pick(a.area.title[0], a.area.title[1]),
        );
        if let Some(line) = headline::headline(a.area, &a.checks, lang) {
            let _ = write!(h, "<br>{line}");
        }
        h.push_str("</p>");
        if let Some(f) = a.figures.first() {
            thumbnail(h, f);
        }
        h.push_str("</div>\n");
    }
    course_texts_card(h, lang);
    h.push_str("</div>\n");
}

/// The findings about the references: one plain sentence per check that
/// has any (its [`Check::gist`], or its first finding where it has none),
/// every finding in its check's own words folded beneath.
fn findings(h: &mut String, report: &Report, lang: Lang) {
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
        "{}<ul>",
        say!(
            lang,
            "<h2 id=findings>What the references get wrong</h2>\n<p>Where a reference departs \
             from the exact law or from the other reference, reported and not counted as a \
             failure ({} findings in {} checks):</p>",
            "<h2 id=findings>Amiben a referenciák tévednek</h2>\n<p>Ahol egy referencia eltér \
             a pontos törvénytől vagy a másik referenciától: jelentjük, de nem számít \
             kudarcnak ({} megállapítás {} ellenőrzésben):</p>",
            report.summary.findings,
            with.len()
        )
    );
    for check in with {
        let gist = match &check.gist {
            Some(gist) => escape(gist.pick(lang)),
            None => escape(check.findings[0].pick(lang)),
        };
        let n = check.findings.len();
        let _ = writeln!(
            h,
            "<li>{gist} <span class=small>({})</span><details><summary>{}</summary><ul>",
            escape(&check.id),
            match lang {
                Lang::En => format!("{n} finding{} in detail", if n == 1 { "" } else { "s" }),
                Lang::Hu => format!("{n} megállapítás részletesen"),
            }
        );
        for f in &check.findings {
            let _ = writeln!(h, "<li>{}</li>", escape(f.pick(lang)));
        }
        h.push_str("</ul></details></li>\n");
    }
    h.push_str("</ul>\n");
}

/// An area: its figures beside the table of its checks' worst values.
fn area_section(h: &mut String, a: &Gathered, lang: Lang) {
    let title = lang.pick(a.area.title[0], a.area.title[1]);
    let _ = writeln!(h, "<h2 id=\"{}\">{title}</h2>", a.area.key);
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
            "<details><summary>{}</summary>",
            say!(
                lang,
                "The worst value of each of {} quantities over {} checks",
                "{} mennyiség legrosszabb értéke {} ellenőrzésben",
                rows,
                a.checks.len()
            )
        );
    }
    let _ = writeln!(
        h,
        "<div class=scroll><table><tr>{}</tr>",
        lang.pick(
            "<th>check</th><th>quantity</th><th>worst</th><th>at</th>",
            "<th>ellenőrzés</th><th>mennyiség</th><th>legrosszabb</th><th>hol</th>"
        )
    );
    for &(i, check) in &a.checks {
        for (j, m) in check.metrics.iter().enumerate() {
            let _ = writeln!(
                h,
                "<tr><td>{} {}</td><td>{}</td>{}<td>{}</td></tr>",
                status(check, lang),
                escape(short_id(&check.id)),
                match (lang, &m.name_hu) {
                    (Lang::Hu, Some(hu)) => escape(hu),
                    _ => english(lang, &m.name),
                },
                number(
                    "td",
                    &format!("/checks/{i}/metrics/{j}/worst"),
                    m.worst,
                    &readable(m.worst)
                ),
                case(lang, &readable_at(&m.at))
            );
        }
    }
    h.push_str("</table></div>\n");
    if folded {
        h.push_str("</details>\n");
    }
    h.push_str("</div></div>\n");
    more_figures(h, a, lang);
}

/// The area's figures after its first, folded (the renders' and the
/// trade-off's have sections of their own).
fn more_figures(h: &mut String, a: &Gathered, lang: Lang) {
    if a.figures.len() > 1 && !["renders", "tradeoff"].contains(&a.area.key) {
        let _ = writeln!(
            h,
            "<details><summary>{}</summary><div class=figures>",
            say!(
                lang,
                "{} more figures",
                "további {} ábra",
                a.figures.len() - 1
            )
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
        let mut check = Check::new("x.y", ["t", "t"], ["r", "r"], ["tol", "tol"]);
        check.cases = 1;
        check.fail("broken <law>".into());
        report.checks.push(check);
        report.summarise();
        let html = to_html(&report, &[], Lang::En);
        assert!(
            html.contains("<details open>")
                && html.contains("FAIL")
                && html.contains("broken &lt;law&gt;")
        );
    }
}
