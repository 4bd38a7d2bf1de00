//! Every subcommand's `--help` shows an example.

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
