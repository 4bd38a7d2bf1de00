//! The Hungarian help checked against the parser it rewrites: every text
//! the English help shows has its slot, every slot is read, a shared slot
//! stands for one English text, and no page under `--lang hu` has English
//! left but names, flags and the examples' command lines.

use std::collections::{BTreeMap, BTreeSet};

use clap::{Command, CommandFactory};

use super::help::{self, english_texts, Text};
use super::help_hu::SLOTS;
use record::english::{command_names, english_left, prose, words};

fn english() -> Vec<Text> {
    english_texts(crate::Cli::command())
}

fn place(path: &[String], key: &str) -> String {
    format!("({path:?}, {key:?})")
}

#[test]
fn every_help_text_has_a_hungarian_slot() {
    let missing: Vec<String> = english()
        .iter()
        .filter(|text| help::slot(&text.path, &text.key).is_none())
        .map(|text| format!("{}: {:?}", place(&text.path, &text.key), text.english))
        .collect();
    assert!(
        missing.is_empty(),
        "{} help texts have no Hungarian in lang/help_hu.rs:\n{}",
        missing.len(),
        missing.join("\n")
    );
}

#[test]
fn a_shared_slot_translates_one_english_text() {
    let mut by_slot: BTreeMap<String, BTreeMap<String, Vec<String>>> = BTreeMap::new();
    for text in english() {
        if let Some((at, key, _)) = help::slot(&text.path, &text.key) {
            let declared = format!("({at:?}, {key:?})");
            let readers = by_slot.entry(declared).or_default();
            let read_by = readers.entry(text.english.clone()).or_default();
            read_by.push(place(&text.path, &text.key));
        }
    }
    let ambiguous: Vec<String> = by_slot
        .iter()
        .filter(|(_, readers)| readers.len() > 1)
        .map(|(declared, readers)| format!("{declared} serves {readers:#?}"))
        .collect();
    assert!(ambiguous.is_empty(), "{}", ambiguous.join("\n"));
}

#[test]
fn every_hungarian_slot_is_read() {
    let texts = english();
    let read: BTreeSet<(Vec<String>, String)> = texts
        .iter()
        .filter_map(|text| help::slot(&text.path, &text.key))
        .map(|(at, key, _)| (at.iter().map(|w| w.to_string()).collect(), key.to_string()))
        .collect();
    let unread: Vec<String> = SLOTS
        .iter()
        .flat_map(|family| family.iter())
        .map(|(at, key, _)| (at.iter().map(|w| w.to_string()).collect(), key.to_string()))
        .filter(|slot| !read.contains(slot))
        .map(|(at, key)| place(&at, &key))
        .collect();
    assert!(
        unread.is_empty(),
        "slots no help text reads (a flag renamed or gone?):\n{}",
        unread.join("\n")
    );
}

/// Every command's path below the program, the program first.
fn paths(command: &Command, path: Vec<String>, all: &mut Vec<Vec<String>>) {
    all.push(path.clone());
    for sub in command.get_subcommands() {
        let mut below = path.clone();
        below.push(sub.get_name().to_owned());
        paths(sub, below, all);
    }
}

fn find<'a>(command: &'a mut Command, path: &[String]) -> &'a mut Command {
    path.iter().fold(command, |command, name| {
        command.find_subcommand_mut(name).expect("a subcommand")
    })
}

#[test]
fn hungarian_help_pages_have_no_english_left() {
    let mut english_command = crate::Cli::command();
    english_command.build();
    let mut hungarian = help::hungarian(crate::Cli::command());
    let vocabulary: BTreeSet<String> = english()
        .iter()
        .flat_map(|text| words(&prose(&text.english)))
        .collect();
    let mut named = command_names(&english_command);
    // The values `optics errata --class` takes, in either language.
    named.extend(
        ::errata::Class::ALL
            .into_iter()
            .flat_map(|class| [class.name(), class.word(record::Lang::Hu)].map(str::to_owned)),
    );
    let mut all = Vec::new();
    paths(&english_command, Vec::new(), &mut all);
    let mut left = Vec::new();
    for path in all {
        let en = find(&mut english_command, &path);
        let en_lines: BTreeSet<String> = [en.render_long_help(), en.render_help()]
            .iter()
            .flat_map(|page| {
                page.to_string()
                    .lines()
                    .map(str::trim)
                    .map(str::to_owned)
                    .collect::<Vec<_>>()
            })
            .collect();
        let hu = find(&mut hungarian, &path);
        for page in [hu.render_long_help(), hu.render_help()] {
            // A line the English shows too is an example's command line.
            for line in page.to_string().lines().map(str::trim) {
                if en_lines.contains(line) {
                    continue;
                }
                let mut english = english_left(line, &vocabulary, &named);
                // clap's own placeholders, which the reader of prose skips.
                for word in ["[OPTIONS]", "<COMMAND>", "[COMMAND]"] {
                    if line.contains(word) {
                        english.push(word.to_owned());
                    }
                }
                if !english.is_empty() {
                    left.push(format!(
                        "optics {}: {english:?} in {line:?}",
                        path.join(" ")
                    ));
                }
            }
        }
    }
    left.dedup();
    assert!(left.is_empty(), "English left:\n{}", left.join("\n"));
}

/// The check above can fail: an English text kept under Hungarian is found.
#[test]
fn english_left_in_a_page_is_found() {
    let vocabulary = words("Samples per pixel");
    let found = english_left("Samples képpontonként", &vocabulary, &BTreeSet::new());
    assert_eq!(found, ["samples"]);
    let kept = english_left("a `path` esetén --spp <SPP>", &vocabulary, &BTreeSet::new());
    assert!(kept.is_empty(), "{kept:?}");
}
