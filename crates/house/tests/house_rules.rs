//! The house rules on this workspace: each test fails naming every offender
//! against its rule (`cargo run -p house --example offenders` prints them
//! all with a count per rule).

use std::path::PathBuf;

use house::{offenders, Rule};

/// Fails listing every offender against `rule` in this workspace.
fn keeps(rule: Rule) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let found: Vec<String> = offenders(&root)
        .unwrap_or_else(|e| panic!("the workspace could not be read: {e}"))
        .into_iter()
        .filter(|o| o.rule == rule)
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
