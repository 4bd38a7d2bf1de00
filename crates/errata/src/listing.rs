//! What `optics errata` prints: the errata ranked (of one class, or all),
//! or one in full, as the record every command prints.

use record::{say, Answer, Lang, Record};

use crate::erratum::{Class, Erratum};
use crate::table::{counts, find, ranked, LookupError};

/// The record's `law`.
pub const LAW: &str = "errata";

/// The errata ranked, physics first, of `class` only when given: one line
/// of working per erratum (its rank, class, place and id) with its title
/// beneath, and each erratum whole, both languages, in the answer.
pub fn ranking(class: Option<Class>, lang: Lang) -> Record {
    let chosen: Vec<(usize, &Erratum)> = ranked()
        .into_iter()
        .enumerate()
        .map(|(i, e)| (i + 1, e))
        .filter(|(_, e)| class.is_none_or(|c| e.class == c))
        .collect();
    let mut record = Record::new(LAW, heading(class, chosen.len(), lang), "");
    if let Some(class) = class {
        record.input("class", class.name());
    }
    // The widest place of either language's form, so the ids line up.
    let width = lang
        .pick("000:1249–1251", "000, 1249–1251. sor")
        .chars()
        .count();
    for &(rank, erratum) in &chosen {
        record.step(|| {
            format!(
                "{rank:>2}. {:<10} {:<width$} {}",
                erratum.class.word(lang),
                erratum.place(lang),
                erratum.id
            )
        });
        record.step(|| format!("    {}", erratum.title.pick(lang)));
    }
    let list = chosen.iter().map(|&(rank, e)| as_json(rank, e)).collect();
    let summary = tally(lang);
    record.set_answer(Answer::List(list), Some(summary));
    record.details_from(count_fields());
    record
}

/// The erratum `id` in full: where, what is written, what is right in
/// `lang`, its effect and its tests.
pub fn one(id: &str, lang: Lang) -> Result<Record, LookupError> {
    let erratum = find(id)?;
    let rank = ranked()
        .iter()
        .position(|e| e.id == erratum.id)
        .map_or(0, |i| i + 1);
    let title = format!("{} — {}", erratum.id, erratum.title.pick(lang));
    let mut record = Record::new(LAW, title, "");
    record.input("id", &erratum.id);
    let place = erratum.place(lang);
    record.step(|| say!(lang, "place: {place}", "hely: {place}"));
    let written = &erratum.written;
    record.step(|| say!(lang, "written: {written}", "írva: {written}"));
    let right = erratum.right.pick(lang);
    record.step(|| say!(lang, "right: {right}", "helyesen: {right}"));
    if let Some(effect) = &erratum.effect {
        let effect = effect.pick(lang);
        record.step(|| say!(lang, "effect: {effect}", "hatás: {effect}"));
    }
    let tests = erratum.tests.join(", ");
    record.step(|| say!(lang, "tests: {tests}", "tesztek: {tests}"));
    let (class, total) = (erratum.class.word(lang), ranked().len());
    let standing = say!(
        lang,
        "{class}, rank {rank} of {total}",
        "{class}, a rangsorban {rank}. a(z) {total} közül"
    );
    record.set_answer(Answer::List(vec![as_json(rank, erratum)]), Some(standing));
    Ok(record)
}

/// The listing's heading: how many, of which class.
fn heading(class: Option<Class>, shown: usize, lang: Lang) -> String {
    match class {
        None => say!(
            lang,
            "The errata of the course texts, ranked, physics first: {shown}",
            "A kurzus szövegeinek hibái rangsorban, a fizikaiakkal kezdve: {shown}"
        ),
        Some(class) => {
            let (name, meaning) = (class.word(lang), class.meaning(lang));
            say!(
                lang,
                "The errata of class {name} ({meaning}), ranked: {shown}",
                "A(z) {name} osztály hibái ({meaning}), rangsorban: {shown}"
            )
        }
    }
}

/// The counts in words: `58 errata: 21 physics, 29 picture, 8 cosmetic`.
pub fn tally(lang: Lang) -> String {
    let counts = counts();
    let total: usize = counts.iter().map(|(_, n)| n).sum();
    let parts: Vec<String> = counts
        .iter()
        .map(|(class, n)| format!("{n} {}", class.word(lang)))
        .collect();
    let parts = parts.join(", ");
    say!(lang, "{total} errata: {parts}", "{total} hiba: {parts}")
}

/// The counts as the record's details: `{"physics": 21, …}`.
fn count_fields() -> serde_json::Map<String, serde_json::Value> {
    counts()
        .iter()
        .map(|(class, n)| (class.name().to_owned(), (*n).into()))
        .collect()
}

/// An erratum as the JSON answer gives it: its rank and every field.
fn as_json(rank: usize, erratum: &Erratum) -> serde_json::Value {
    let mut value = serde_json::to_value(erratum).unwrap_or_default();
    if let Some(object) = value.as_object_mut() {
        object.insert("rank".to_owned(), rank.into());
    }
    value
}
