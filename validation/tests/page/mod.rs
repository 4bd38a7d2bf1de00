//! `report.html` read as a person reads it.

use std::collections::BTreeSet;

use record::english::{english_left, prose, words as english_words};

/// The page's text as a reader sees it: its tags taken out.
pub fn words(html: &str) -> String {
    let mut text = String::with_capacity(html.len());
    let mut in_tag = false;
    for c in html.chars() {
        match c {
            '<' => in_tag = true,
            '>' => in_tag = false,
            _ if !in_tag => text.push(c),
            _ => {}
        }
    }
    text
}

/// The page's prose, a line per line of the page: its text without its
/// tags, its style and what it writes as code, its entities read; with
/// `marked_english` false, without what it marks as written in English
/// (an element inside the page with `lang=en`).
pub fn prose_of(html: &str, marked_english: bool) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    // The element being skipped, and how deep inside its kind.
    let mut skipping: Option<(String, usize)> = None;
    let mut rest = html;
    while let Some(open) = rest.find('<') {
        let text = &rest[..open];
        if skipping.is_none() {
            for (k, part) in text.split('\n').enumerate() {
                if k > 0 {
                    lines.push(std::mem::take(&mut line));
                }
                line.push_str(&unescape(part));
            }
        }
        let close = rest[open..].find('>').map_or(rest.len(), |c| open + c + 1);
        let tag = &rest[open + 1..close.saturating_sub(1).max(open + 1)];
        let name: String = tag
            .trim_start_matches('/')
            .chars()
            .take_while(|c| c.is_alphanumeric())
            .collect();
        match &mut skipping {
            Some((kind, depth)) if *kind == name => {
                if tag.starts_with('/') {
                    *depth -= 1;
                    if *depth == 0 {
                        skipping = None;
                    }
                } else {
                    *depth += 1;
                }
            }
            Some(_) => {}
            None if !tag.starts_with('/')
                && (["style", "code"].contains(&name.as_str())
                    || (!marked_english && name != "html" && tag.contains("lang=en"))) =>
            {
                skipping = Some((name, 1));
            }
            None => line.push(' '),
        }
        rest = &rest[close..];
    }
    lines.push(line);
    lines.retain(|l| !l.trim().is_empty());
    lines
}

fn unescape(text: &str) -> String {
    text.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&amp;", "&")
}

/// The English left in the Hungarian page `hu`: each of its lines with a
/// word of the English page `en` (or a common English word) that is not
/// a name, nor one of `names` (the scenes' and checks' own names).
pub fn english_left_in(hu: &str, en: &str, names: &BTreeSet<String>) -> Vec<String> {
    let vocabulary: BTreeSet<String> = prose_of(en, true)
        .iter()
        .flat_map(|line| english_words(&prose(line)))
        .collect();
    prose_of(hu, false)
        .iter()
        .filter_map(|line| {
            let left = english_left(line, &vocabulary, names);
            (!left.is_empty()).then(|| format!("{left:?} in {:?}", line.trim()))
        })
        .collect()
}

/// The page's numbers as a test reads them: each number's source
/// (`data-json` or `data-quote`) with its value (`data-value`), sorted (a
/// sentence may put its numbers in another order in another language).
pub fn number_marks(html: &str) -> Vec<String> {
    let attributes: Vec<String> = html
        .split(" data-")
        .skip(1)
        .filter(|part| {
            ["json=", "quote=", "value="]
                .iter()
                .any(|k| part.starts_with(k))
        })
        .map(|part| part.split('"').take(2).collect::<Vec<_>>().join(""))
        .collect();
    let mut marks: Vec<String> = attributes.chunks(2).map(|pair| pair.join(" ")).collect();
    marks.sort();
    marks
}
