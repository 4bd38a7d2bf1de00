//! The law table against what it generates: the subcommands, the batch
//! reader, the fields, and the table in `docs/cli.md`.

use super::schema::{self, Kind};
use super::{command_words, Law, LAWS, QUIZ_LAWS};
use clap::CommandFactory;
use record::{Lang, Steps};

/// Each law is a subcommand of `optics` under the words the table gives,
/// with its `--help` line.
#[test]
fn every_law_is_a_subcommand_of_its_own_name() {
    let mut cli = crate::Cli::command();
    cli.build();
    for &law in LAWS {
        let mut command = &cli;
        for word in command_words(law) {
            command = command
                .find_subcommand(&word)
                .unwrap_or_else(|| panic!("{law}: no subcommand {word}"));
        }
        assert!(command.get_about().is_some(), "{law}: no --help line");
    }
    assert!(QUIZ_LAWS.iter().all(|law| LAWS.contains(law)));
}

/// Every law's fields as the table reads them: a name in a request's
/// form, a kind, a help line, and at least one required field or group.
#[test]
fn every_law_has_named_typed_and_documented_fields() {
    for &law in LAWS {
        let fields = schema::fields(law);
        assert!(!fields.is_empty(), "{law}: no fields");
        for field in &fields {
            assert!(
                field
                    .name
                    .chars()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_'),
                "{law}: {}",
                field.name
            );
            assert!(!field.help.is_empty(), "{law}.{}: no help", field.name);
        }
    }
    let kind = |law, name| {
        let fields = schema::fields(law);
        fields
            .into_iter()
            .find(|f| f.name == name)
            .map(|f| (f.kind, f.required))
    };
    assert_eq!(kind("reflect", "wi"), Some((Kind::Vector, true)));
    assert_eq!(kind("fresnel", "eta"), Some((Kind::Number, false)));
    assert_eq!(
        schema::fields("fresnel")
            .into_iter()
            .find(|f| f.name == "eta")
            .and_then(|f| f.one_of),
        Some(vec!["eta".to_owned(), "metal".to_owned()])
    );
    assert_eq!(kind("fresnel", "kappa"), Some((Kind::Number, false)));
    assert!(
        matches!(kind("envmap", "map"), Some((Kind::Choice(c), false)) if c.contains(&"lat-long".to_owned()))
    );
    assert!(schema::fields("teleport").is_empty());
}

/// The batch reads every law the table lists, from the example of its own
/// `--help`, and answers it as the command line does.
#[test]
fn batch_reads_every_law_the_table_lists() {
    for &law in LAWS {
        let (request, flags) = schema::example(law);
        let mut args = vec!["optics".to_owned(), "--json".to_owned()];
        args.extend(command_words(law));
        args.extend(flags);
        let fields = serde_json::Value::Object(request);
        let read = Law::read(law, &fields).expect("a law of the table");
        let batch = read
            .unwrap_or_else(|e| panic!("{law}: {e}"))
            .solve(crate::input::Via::Json, Lang::En, Steps::Wanted)
            .unwrap_or_else(|e| panic!("{law}: {e}"));
        assert_eq!(batch.law, law);
        let cli = <crate::Cli as clap::Parser>::try_parse_from(&args)
            .unwrap_or_else(|e| panic!("{args:?}: {e}"));
        let flags = crate::law_record(&cli.command, Lang::En)
            .expect("a law's command")
            .unwrap_or_else(|e| panic!("{args:?}: {e}"));
        // Alike but for how the notes name a field (`kd`, `--kd`).
        let (batch, flags) = (
            serde_json::to_value(&batch).unwrap(),
            serde_json::to_value(&flags).unwrap(),
        );
        for part in ["law", "inputs", "answer", "unit", "steps", "details"] {
            assert_eq!(
                batch[part], flags[part],
                "{law}: {part} of the batch and the command line"
            );
        }
    }
    assert!(Law::read("teleport", &serde_json::json!({})).is_none());
}

#[cfg(feature = "harness")]
/// The table of laws in `docs/cli.md` is the one the law table writes
/// (`RESULTS_WRITE=1` rewrites it).
#[test]
fn docs_table_of_laws_is_current() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/cli.md");
    let section = results::Section::deterministic(
        super::docs::SECTION,
        super::docs::COMMAND,
        &super::docs::table(),
    );
    if let Err(e) = results::settle_in(&path, &section) {
        panic!("{e}");
    }
}
