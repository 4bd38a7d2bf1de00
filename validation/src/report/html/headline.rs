//! A card's headline: its area's sentence ([`super::areas`]) with the
//! worst value it speaks of filled in, quoted from where the page shows it.

use record::Lang;

use super::areas::Area;
use super::format::{escape, quote, readable};
use crate::check::{Check, Metric};

/// The area's headline sentence in `lang`, filled with the worst value of
/// its quantity over its checks; without a quantity, its worst Fresnel
/// error in ulps where it measures them (the laws held to a bound in ulps
/// alone; an angle's bound grows with its condition number). Where the
/// value is missing, its number of findings.
pub(super) fn headline(area: &Area, checks: &[(usize, &Check)], lang: Lang) -> Option<String> {
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
    let sentence = area.headline.as_ref()?;
    let found = match sentence.quantity {
        Some(name) => metrics().filter(|(_, _, m)| m.name == name).max_by(worst),
        None => metrics()
            .filter(|(_, c, m)| c.id.contains("fresnel") || m.name.starts_with("fresnel"))
            .filter(|(_, _, m)| m.name.contains("ulps") && m.worst.is_finite())
            .max_by(worst),
    };
    if let Some((at, _, m)) = found {
        let value = quote(&at, m.worst, &readable(m.worst));
        let [en, hu] = sentence.says;
        return Some(escape(lang.pick(en, hu)).replacen("{}", &value, 1));
    }
    let findings: usize = checks.iter().map(|(_, c)| c.findings.len()).sum();
    (findings > 0).then(|| match lang {
        Lang::En if findings == 1 => "1 finding about the reference".to_owned(),
        Lang::En => format!("{findings} findings about the reference"),
        Lang::Hu => format!("{findings} megállapítás a referenciáról"),
    })
}
