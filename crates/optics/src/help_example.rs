//! A command's first example, as its `--help` shows it: the line of its
//! after-help that starts with the command's words, without the remark in
//! parentheses that may follow.

/// The first line of `command`'s after-help that starts with `words`
/// (`optics quiz f0`), its remark (after two spaces and a parenthesis)
/// left off; `None` where the help shows no such line.
pub(crate) fn first_example(command: &clap::Command, words: &str) -> Option<String> {
    let help = command.get_after_help()?.to_string();
    let line = help
        .lines()
        .map(str::trim)
        .find(|line| line.starts_with(words))?;
    Some(
        line.split("  (")
            .next()
            .unwrap_or(line)
            .trim_end()
            .to_owned(),
    )
}
