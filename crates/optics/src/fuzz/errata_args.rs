//! `optics errata`'s arguments: ids and classes from the table, in other
//! cases, spoiled, and hostile strings (empty, control characters, long,
//! paths, other scripts, flag-like), through the parser and the command.
//! The promises: no panic; a known id or class is answered; an unknown id
//! is refused as `errata.unknown_id` naming `ID`, an unknown class as
//! `errata.unknown_class` naming `--class`; a line the parser refuses
//! held a value that reads as a flag, and its error names an argument.

use super::{run_and_report, runner, Coverage};
use clap::Parser;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use record::Lang;
use serde_json::Value;

/// Text no id or class is: the edges of what a shell can pass.
const HOSTILE: [&str; 12] = [
    "",
    " ",
    "\u{0}",
    "003-boxed-refraction\n",
    "../../etc/passwd",
    "ǅ\u{301}",
    "٣-",
    "-",
    "--class",
    "-x",
    "physics;rm -rf /",
    "\u{202e}scisyhp",
];

/// An id: from the table, changed in case or cut, or hostile.
fn id() -> impl Strategy<Value = String> {
    let ids: Vec<String> = ::errata::all().iter().map(|e| e.id.clone()).collect();
    prop_oneof![
        3 => prop::sample::select(ids.clone()),
        1 => prop::sample::select(ids.clone()).prop_map(|id| id.to_uppercase()),
        1 => (prop::sample::select(ids), 0..20usize).prop_map(|(id, n)| id[..n.min(id.len())].to_owned()),
        2 => prop::sample::select(HOSTILE.to_vec()).prop_map(str::to_owned),
        1 => any::<String>(),
        1 => "[a-z0-9-]{0,40}",
    ]
}

/// A class: named in either language, in another case, or hostile.
fn class() -> impl Strategy<Value = String> {
    let names = vec![
        "physics",
        "picture",
        "cosmetic",
        "fizika",
        "kép",
        "kozmetikai",
        "PHYSICS",
        "Kép",
    ];
    prop_oneof![
        3 => prop::sample::select(names).prop_map(str::to_owned),
        2 => prop::sample::select(HOSTILE.to_vec()).prop_map(str::to_owned),
        1 => any::<String>(),
        1 => "[a-zé]{0,12}",
    ]
}

/// A command line: `optics [--json] [--lang hu] errata [ID] [--class C]`.
fn command_line() -> impl Strategy<Value = (Vec<String>, Option<String>, Option<String>)> {
    (
        any::<bool>(),
        any::<bool>(),
        prop::option::of(id()),
        prop::option::of(class()),
    )
        .prop_map(|(json, hu, id, class)| {
            let mut args = vec!["optics".to_owned()];
            args.extend(json.then(|| "--json".to_owned()));
            if hu {
                args.extend(["--lang".to_owned(), "hu".to_owned()]);
            }
            args.push("errata".to_owned());
            args.extend(id.clone());
            if let Some(class) = &class {
                args.extend(["--class".to_owned(), class.clone()]);
            }
            (args, id, class)
        })
}

/// The promises of one command line; `id` and `class` as given.
fn check_line(
    args: &[String],
    id: Option<&str>,
    class: Option<&str>,
    coverage: &Coverage,
) -> Result<(), TestCaseError> {
    let cli = match crate::Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(usage) => {
            let json = crate::Error::from(crate::ErrorKind::Usage(usage)).to_json(Lang::En);
            coverage.error(&json);
            let flag_like = [id, class]
                .into_iter()
                .flatten()
                .any(|v| v.starts_with('-'));
            prop_assert!(flag_like, "{args:?} refused: {json}");
            prop_assert!(json["field"].is_string(), "{json} names no argument");
            return Ok(());
        }
    };
    let crate::Command::Errata(errata_args) = &cli.command else {
        return Err(TestCaseError::fail(format!("{args:?}: not errata")));
    };
    let outcome = crate::errata::record(errata_args, Lang::Hu)
        .map(|record| serde_json::to_value(&record).expect("a record is JSON"));
    check_outcome(
        outcome.map_err(|e| e.to_json(Lang::En)),
        id,
        class,
        coverage,
    )
}

/// The promises of the command's outcome: an answer for a known id and
/// class, else the error naming the argument that was wrong.
fn check_outcome(
    outcome: Result<Value, Value>,
    id: Option<&str>,
    class: Option<&str>,
    coverage: &Coverage,
) -> Result<(), TestCaseError> {
    let known_class = class.is_none_or(|c| ::errata::parse_class(c).is_ok());
    let known_id = id.is_none_or(|i| ::errata::find(i).is_ok());
    match outcome {
        Ok(record) => {
            coverage.answer();
            prop_assert!(
                known_class && known_id,
                "{id:?} {class:?} answered: {record}"
            );
            prop_assert!(record["answer"].as_array().is_some_and(|a| !a.is_empty()));
        }
        Err(error) => {
            coverage.error(&error);
            let (kind, field) = (error["kind"].as_str(), error["field"].as_str());
            if !known_class {
                prop_assert_eq!(
                    (kind, field),
                    (Some("errata.unknown_class"), Some("--class"))
                );
            } else {
                prop_assert!(!known_id, "{id:?} {class:?} refused: {error}");
                prop_assert_eq!((kind, field), (Some("errata.unknown_id"), Some("ID")));
            }
        }
    }
    Ok(())
}

fn fuzz(cases: u32, coverage: &Coverage) -> Result<(), String> {
    runner(cases)
        .run(&command_line(), |(args, id, class)| {
            check_line(&args, id.as_deref(), class.as_deref(), coverage)
        })
        .map_err(|e| e.to_string())
}

#[test]
fn errata_args_keep_their_promises() {
    run_and_report("errata args", fuzz);
}

/// The promises catch an error that does not name its argument: an
/// unknown class reported as an unknown id, as a command that checked the
/// id first would.
#[test]
fn an_error_naming_the_wrong_argument_is_caught() {
    let wrong = serde_json::json!({"kind": "errata.unknown_id", "field": "ID", "message": ""});
    let coverage = Coverage::default();
    let outcome = check_outcome(Err(wrong), Some("nope"), Some("severe"), &coverage);
    assert!(outcome.is_err(), "the wrong argument was not caught");
}
