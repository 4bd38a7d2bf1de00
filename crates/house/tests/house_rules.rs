//! The house rules on this workspace: each test fails naming every offender
//! against its rule (`cargo run -p house --example offenders` prints them
//! all with a count per rule), but for the offences listed in
//! `crates/house/known_offenders.txt`, the work still owed. That list only
//! shrinks: an offence not on it fails its rule's test, and a listed one
//! that is gone fails `the_list_of_known_offenders_only_shrinks` until it
//! is struck off.

use std::collections::BTreeSet;
use std::path::PathBuf;

use house::{offenders, Offender, Rule};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn found() -> Vec<Offender> {
    offenders(&root()).unwrap_or_else(|e| panic!("the workspace could not be read: {e}"))
}

/// The offences still owed, one identity a line (`#` starts a comment).
fn known() -> BTreeSet<String> {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("known_offenders.txt");
    let text = std::fs::read_to_string(&path).unwrap_or_default();
    text.lines()
        .map(str::trim)
        .filter(|line| !line.is_empty() && !line.starts_with('#'))
        .map(str::to_owned)
        .collect()
}

/// Fails listing every offender against `rule` in this workspace that is
/// not a known one.
fn keeps(rule: Rule) {
    let known = known();
    let found: Vec<String> = found()
        .into_iter()
        .filter(|o| o.rule == rule && !known.contains(&o.identity()))
        .map(|o| format!("  {o}"))
        .collect();
    assert!(
        found.is_empty(),
        "{} offender(s), {rule}:\n{}",
        found.len(),
        found.join("\n")
    );
}

#[test]
fn the_list_of_known_offenders_only_shrinks() {
    let standing: BTreeSet<String> = found().iter().map(Offender::identity).collect();
    let gone: Vec<String> = known().difference(&standing).cloned().collect();
    assert!(
        gone.is_empty(),
        "no longer offending, strike off crates/house/known_offenders.txt:\n  {}",
        gone.join("\n  ")
    );
}

#[test]
fn no_product_file_is_over_400_lines() {
    keeps(Rule::LongFile);
}

#[test]
fn no_product_function_is_over_80_lines() {
    keeps(Rule::LongFunction);
}

#[test]
fn no_files_of_a_crate_import_each_other_round_a_circle() {
    keeps(Rule::ImportCircle);
}

#[test]
fn no_file_imports_from_its_ancestor_module() {
    keeps(Rule::UpwardImport);
}

#[test]
fn no_library_error_text_names_a_flag() {
    keeps(Rule::FlagInLibraryError);
}
