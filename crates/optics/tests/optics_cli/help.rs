//! Every subcommand's `--help` shows an example, in the language asked for.

use crate::common::{optics, stdout};

#[test]
fn every_subcommand_has_help_with_an_example() {
    let others: &[&[&str]] = &[
        &["quiz"],
        &["quiz", "seed"],
        &["batch"],
        &["render"],
        &["inspect"],
        &["errata"],
        &["validate"],
    ];
    let laws = optics::law_table::LAWS
        .iter()
        .map(|&law| optics::law_table::command_words(law));
    let others = others
        .iter()
        .map(|words| words.iter().map(|w| w.to_string()).collect());
    for sub in laws.chain(others) {
        let mut args: Vec<&str> = sub.iter().map(String::as_str).collect();
        args.push("--help");
        let output = optics(&args);
        assert!(output.status.success(), "optics {args:?}");
        let text = stdout(&output);
        assert!(
            text.contains("Example") && text.contains("optics "),
            "no example in optics {args:?}:\n{text}"
        );
    }
}

/// `--lang hu` rewrites the help before parsing: the about, clap's own
/// headings and the flags' help are Hungarian, the examples verbatim.
#[test]
fn hungarian_help_is_hungarian_and_keeps_its_examples() {
    let output = optics(&["--lang", "hu", "quiz", "f0", "--help"]);
    assert!(output.status.success());
    let text = stdout(&output);
    let expected = [
        "Merőleges beesésű visszaverődés (F0) a törésmutatóból\n\nHasználat: optics quiz f0",
        "Kapcsolók:",
        "Törésmutató (a külső közeghez viszonyítva)",
        "[alapértelmezett: 0]",
        "Példa (a kvíz 2. kérdése):\n  optics quiz f0 --n 1.4",
    ];
    for part in expected {
        assert!(text.contains(part), "no {part:?} in\n{text}");
    }
    for english in ["Usage:", "Options:", "[default:", "Print help"] {
        assert!(!text.contains(english), "{english:?} in\n{text}");
    }
}
