//! Numbers and text as the page shows them.

use std::fmt::Write as _;

use crate::case_words;
use crate::check::Check;
use record::Lang;

/// `text` safe inside an element or a quoted attribute.
pub(super) fn escape(text: &str) -> String {
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

/// Prose as Markdown writes it, for the page: each `` `span` `` between a
/// pair of backticks as code, the rest escaped; a backtick left unpaired
/// stays a backtick.
pub(super) fn inline_code(text: &str) -> String {
    let parts: Vec<&str> = text.split('`').collect();
    let paired = parts.len() - (parts.len() + 1) % 2;
    let mut out = String::with_capacity(text.len() + 16);
    for (k, part) in parts.iter().enumerate() {
        match (k % 2, k < paired) {
            (1, true) => {
                let _ = write!(out, "<code>{}</code>", escape(part));
            }
            (1, false) => {
                out.push('`');
                out.push_str(&escape(part));
            }
            _ => out.push_str(&escape(part)),
        }
    }
    out
}

/// A check's verdict, marked.
pub(super) fn status(check: &Check, lang: Lang) -> &'static str {
    if check.passed() {
        lang.pick("<span class=pass>pass</span>", "<span class=pass>jó</span>")
    } else {
        lang.pick(
            "<span class=fail>FAIL</span>",
            "<span class=fail>HIBA</span>",
        )
    }
}

/// A text the suite has only in English (a measured quantity's name, a
/// finding in the check's own words), escaped; on a page in another
/// language marked as English (`lang=en`), so that a screen reader reads
/// it as English and the page's test knows it for what is left.
pub(super) fn english(lang: Lang, text: &str) -> String {
    match lang {
        Lang::En => escape(text),
        Lang::Hu => format!("<span lang=en>{}</span>", escape(text)),
    }
}

/// A case's label (where a worst value occurred, a metal), escaped; on
/// the Hungarian page in Hungarian where its words are all in
/// [`case_words`]'s vocabulary, and marked as English where they are not.
pub(super) fn case(lang: Lang, label: &str) -> String {
    match (lang, case_words::hungarian(label)) {
        (Lang::Hu, Some(hu)) => escape(&hu),
        _ => english(lang, label),
    }
}

/// A patch of the encoded sRGB colour `srgb`.
pub(super) fn swatch(srgb: [f64; 3]) -> String {
    let [r, g, b] = srgb.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8);
    format!("<span class=swatch style=\"background: rgb({r}, {g}, {b})\"></span>")
}

/// A number for reading: four significant digits, no exponent between
/// 0.001 and 100 000.
pub(super) fn readable(x: f64) -> String {
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
pub(super) fn readable_at(at: &str) -> String {
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

/// A number the page shows, in a `tag` element (`td`, `span`) that carries
/// where `report.json` holds it (`pointer`, a JSON pointer) and its value
/// in full, so that a test can read every number back out of the page.
/// Each number of `report.json` is shown so once, where its table puts it.
pub(super) fn number(tag: &str, pointer: &str, value: f64, shown: &str) -> String {
    marked(tag, "data-json", pointer, value, shown)
}

/// A number quoted again (a card's headline quotes its area's worst
/// value): marked as a quotation of `pointer`, so that the test that reads
/// the page's numbers back checks it too without counting it as the
/// number's place.
pub(super) fn quote(pointer: &str, value: f64, shown: &str) -> String {
    marked("span", "data-quote", pointer, value, shown)
}

fn marked(tag: &str, attribute: &str, pointer: &str, value: f64, shown: &str) -> String {
    let class = if tag == "td" { " class=num" } else { "" };
    format!(
        "<{tag}{class} {attribute}=\"{}\" data-value=\"{value:e}\">{shown}</{tag}>",
        escape(pointer)
    )
}
