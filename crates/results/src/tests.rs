//! The section comparison can fail: a changed number, a changed command
//! and a missing section are each reported, and rewriting makes the
//! comparison pass without touching the rest of the document.

use super::*;

const TABLE: &str = "| law | worst |\n|---|---|\n| dielectric R | 3.86 ulps |\n";

fn committed() -> String {
    let section = Section::deterministic("accuracy", "cargo test -p demo", TABLE);
    format!("# Results\n\nprose\n\n{}after\n", replace("", &section))
}

#[test]
fn the_same_table_compares_equal() {
    let section = Section::deterministic("accuracy", "cargo test -p demo", TABLE);
    compare(&committed(), &section).expect("unchanged");
}

#[test]
fn a_changed_number_fails_with_a_diff_naming_both_values() {
    let changed = TABLE.replace("3.86", "3.87");
    let section = Section::deterministic("accuracy", "cargo test -p demo", &changed);
    let message = compare(&committed(), &section).unwrap_err().to_string();
    assert!(
        message.contains("- | dielectric R | 3.86 ulps |"),
        "{message}"
    );
    assert!(
        message.contains("+ | dielectric R | 3.87 ulps |"),
        "{message}"
    );
    assert!(message.contains("cargo test -p demo") && message.contains(WRITE_VAR));
}

#[test]
fn a_changed_command_fails_too() {
    let section = Section::deterministic("accuracy", "cargo test -p other", TABLE);
    assert!(matches!(
        compare(&committed(), &section),
        Err(Error::Differs { .. })
    ));
}

#[test]
fn a_missing_section_is_named() {
    let section = Section::deterministic("speed-of-light", "cargo test -p demo", TABLE);
    let err = compare(&committed(), &section).unwrap_err();
    assert!(matches!(err, Error::Missing { ref name, .. } if name == "speed-of-light"));
}

#[test]
fn rewriting_replaces_only_the_section() {
    let changed = TABLE.replace("3.86", "4.00");
    let section = Section::deterministic("accuracy", "cargo test -p demo", &changed);
    let rewritten = replace(&committed(), &section);
    compare(&rewritten, &section).expect("rewritten");
    assert!(rewritten.starts_with("# Results\n\nprose\n\n<!-- results: accuracy -->\n"));
    assert!(rewritten.ends_with("<!-- /results: accuracy -->\nafter\n"));
    assert!(!rewritten.contains("3.86"));
}

#[test]
fn a_new_section_is_appended_after_a_blank_line() {
    let section = Section::deterministic("new", "cargo test -p demo", TABLE);
    let appended = replace("# Results\n", &section);
    assert!(appended.starts_with("# Results\n\n<!-- results: new -->\n"));
    compare(&appended, &section).expect("appended");
}

#[test]
fn a_measured_section_names_its_command_machine_and_date() {
    let section = Section::measured("speed", "cargo bench -p demo", "| a | 1 ns |");
    assert!(section.text().contains("cargo bench -p demo"));
    assert!(section.text().contains(&machine()));
    assert!(section.text().contains(&today()));
    assert!(!section.deterministic);
}

/// A keyed table's key follows its inputs: a changed byte of a file it
/// reads changes it, and a key recorded for other inputs is not current.
mod keyed {
    use crate::key::Inputs;

    const PROGRAM: &str = "crates/tracer/examples/missing_light.rs";

    fn inputs<'a>(data: &'a [&'a str]) -> Inputs<'a> {
        Inputs {
            package: "tracer",
            program: PROGRAM,
            data,
        }
    }

    #[test]
    fn a_changed_input_changes_the_key() {
        let dir = tempfile_dir();
        let file = dir.join("scene.json");
        std::fs::write(&file, "{\"a\": 1}").unwrap();
        let path = file.to_str().unwrap();
        let before = inputs(&[path]).key().unwrap();
        assert_eq!(
            before,
            inputs(&[path]).key().unwrap(),
            "the key is a function of the inputs"
        );
        std::fs::write(&file, "{\"a\": 2}").unwrap();
        let after = inputs(&[path]).key().unwrap();
        assert_ne!(before, after);
        let _ = std::fs::remove_dir_all(dir);
    }

    #[test]
    fn the_recorded_key_of_other_inputs_is_not_current() {
        let dir = tempfile_dir();
        let file = dir.join("extra.json");
        std::fs::write(&file, "{}").unwrap();
        let other = [file.to_str().unwrap()];
        assert!(!crate::key_is_current(
            "missing-light",
            "cargo run --release -p tracer --example missing_light",
            &inputs(&other),
        ));
        let _ = std::fs::remove_dir_all(dir);
    }

    #[test]
    fn an_input_that_is_not_there_is_an_error() {
        let missing = inputs(&["crates/tracer/no-such-directory"]).key();
        assert!(missing
            .unwrap_err()
            .to_string()
            .contains("no-such-directory"));
    }

    /// A directory of this test's own under the system's temporary one.
    fn tempfile_dir() -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!(
            "results-key-{}-{:?}",
            std::process::id(),
            std::thread::current().id()
        ));
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }
}
