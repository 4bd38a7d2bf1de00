//! Every erratum of the table checked: both languages, one class, a place
//! that exists in its text, tests that exist; the page generated from it;
//! and each check shown to catch the fault it is for.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use record::Lang;

use crate::erratum::{Class, Erratum, Text};
use crate::listing::{one, ranking};
use crate::table::{all, find, parse_class, ranked, LookupError, TABLE};

/// The workspace's root.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// `shared/seeds/` beside the checkout, where the course texts are.
fn seeds() -> PathBuf {
    root().join("../shared/seeds")
}

/// How many lines each course text has.
fn line_counts() -> Vec<(Text, usize)> {
    Text::ALL
        .iter()
        .map(|&text| {
            let path = seeds().join(text.file_name());
            let body = std::fs::read_to_string(&path)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            (text, body.lines().count())
        })
        .collect()
}

/// The places that do not exist: a first line of 0, a range running
/// backwards, or a last line past the end of the text.
fn bad_places(errata: &[Erratum], counts: &[(Text, usize)]) -> Vec<String> {
    errata
        .iter()
        .filter(|e| {
            let [first, last] = e.lines;
            let length = counts.iter().find(|(t, _)| *t == e.text).map_or(0, |c| c.1);
            first == 0 || last < first || last as usize > length
        })
        .map(|e| format!("{}: lines {:?}", e.id, e.lines))
        .collect()
}

/// Every name a `fn` is declared with in the workspace's Rust sources.
fn functions_declared() -> BTreeSet<String> {
    let mut names = BTreeSet::new();
    let mut stack = vec![root().join("crates"), root().join("validation")];
    while let Some(dir) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() && path.file_name().is_some_and(|n| n != "target") {
                stack.push(path);
            } else if path.extension().is_some_and(|x| x == "rs") {
                let text = std::fs::read_to_string(&path).unwrap_or_default();
                for (i, _) in text.match_indices("fn ") {
                    let name: String = text[i + 3..]
                        .chars()
                        .take_while(|c| c.is_alphanumeric() || *c == '_')
                        .collect();
                    names.insert(name);
                }
            }
        }
    }
    names
}

/// The tests the errata name that no `fn` of the workspace declares.
fn missing_tests(errata: &[Erratum], declared: &BTreeSet<String>) -> Vec<String> {
    errata
        .iter()
        .flat_map(|e| e.tests.iter().map(move |t| (e, t)))
        .filter(|(_, t)| !declared.contains(t.as_str()))
        .map(|(e, t)| format!("{}: no fn {t}", e.id))
        .collect()
}

/// The texts of an erratum that are empty or the same in both languages.
fn unworded(erratum: &Erratum) -> Vec<&'static str> {
    let mut wrong = Vec::new();
    let mut check = |what, words: &crate::Words| {
        if words.en.trim().is_empty() || words.hu.trim().is_empty() || words.en == words.hu {
            wrong.push(what);
        }
    };
    check("title", &erratum.title);
    check("right", &erratum.right);
    if let Some(effect) = &erratum.effect {
        check("effect", effect);
    }
    wrong
}

/// A copy of the first erratum with `change` made to it.
fn planted(change: impl FnOnce(&mut Erratum)) -> Vec<Erratum> {
    let mut copy = all()[0].clone();
    change(&mut copy);
    vec![copy]
}

#[test]
fn every_erratum_has_a_stable_id_of_its_text() {
    let ids: BTreeSet<&str> = all().iter().map(|e| e.id.as_str()).collect();
    assert_eq!(ids.len(), all().len(), "two errata share an id");
    for e in all() {
        assert!(
            e.id.starts_with(&format!("{}-", e.text.prefix())),
            "{}: not of {}",
            e.id,
            e.text.prefix()
        );
        let lower = |c: char| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-';
        assert!(e.id.chars().all(lower), "{}", e.id);
        assert!(!e.written.trim().is_empty(), "{}: nothing written", e.id);
        assert!(!e.tests.is_empty(), "{}: no test", e.id);
    }
}

#[test]
fn every_erratum_is_worded_in_both_languages() {
    for e in all() {
        assert_eq!(unworded(e), Vec::<&str>::new(), "{}", e.id);
    }
    let same = planted(|e| e.right.hu = e.right.en.clone());
    assert_eq!(unworded(&same[0]), ["right"], "a copied English is caught");
    let empty = planted(|e| e.title.hu = " ".into());
    assert_eq!(
        unworded(&empty[0]),
        ["title"],
        "an empty Hungarian is caught"
    );
}

#[test]
fn every_erratum_has_exactly_one_class() {
    let rows: Vec<serde_json::Value> = serde_json::from_str(TABLE).unwrap();
    for row in &rows {
        let class = row["class"]
            .as_str()
            .unwrap_or_else(|| panic!("{row}: one class"));
        assert!(parse_class(class).is_ok(), "{class}");
    }
    // The table is the ranking: its classes in order, worst first.
    let classes: Vec<Class> = all().iter().map(|e| e.class).collect();
    assert!(classes.is_sorted(), "the table's classes are out of order");
    let two = r#"[{"id": "000-x", "class": ["physics", "picture"]}]"#;
    assert!(serde_json::from_str::<Vec<Erratum>>(two).is_err());
}

#[test]
fn every_erratum_points_at_lines_of_its_text() {
    let counts = line_counts();
    assert_eq!(bad_places(all(), &counts), Vec::<String>::new());
    let past = planted(|e| e.lines = [1, 100_000]);
    assert_eq!(
        bad_places(&past, &counts).len(),
        1,
        "a line past the end is caught"
    );
    let backwards = planted(|e| e.lines = [20, 10]);
    assert_eq!(bad_places(&backwards, &counts).len(), 1);
}

#[test]
fn every_erratum_names_tests_that_exist() {
    let declared = functions_declared();
    assert_eq!(missing_tests(all(), &declared), Vec::<String>::new());
    // Put together here, so that no `fn` of this file spells it.
    let name = ["course", "999", "no_such_law_is_shown"].join("_");
    let absent = planted(|e| e.tests.push(name.clone()));
    assert_eq!(
        missing_tests(&absent, &declared),
        [format!("{}: no fn {name}", all()[0].id)],
        "a test that does not exist is caught"
    );
}

#[test]
fn the_ranking_puts_physics_first_and_keeps_the_tables_order() {
    let ranked = ranked();
    assert_eq!(ranked.len(), all().len());
    assert_eq!(ranked[0].class, Class::Physics);
    assert_eq!(ranked.last().map(|e| e.class), Some(Class::Cosmetic));
    let physics = ranking(Some(Class::Physics), Lang::En);
    let json = serde_json::to_value(&physics).unwrap();
    let listed = json["answer"].as_array().unwrap();
    assert!(listed.iter().all(|e| e["class"] == "physics"));
    assert_eq!(listed[0]["rank"], 1);
}

#[test]
fn a_lookup_names_what_it_did_not_find() {
    assert_eq!(
        find("003-no-such").unwrap_err(),
        LookupError::UnknownId {
            id: "003-no-such".into()
        }
    );
    assert_eq!(parse_class("Fizika"), Ok(Class::Physics));
    assert_eq!(parse_class("kép"), Ok(Class::Picture));
    let error = parse_class("severe").unwrap_err();
    assert!(error.to_string().contains("\"severe\""), "{error}");
    let record = one("003-boxed-refraction", Lang::Hu).unwrap();
    let text = record.to_text(Lang::Hu);
    assert!(
        text.contains("helyesen:") && text.contains("003, 246. sor"),
        "{text}"
    );
}

#[test]
fn docs_errata_page_is_current() {
    let path = root().join("docs/errata.md");
    let section = results::Section::deterministic(
        crate::page::SECTION,
        crate::page::COMMAND,
        &crate::page::section(),
    );
    if let Err(e) = results::settle_in(&path, &section) {
        panic!("{e}");
    }
}
