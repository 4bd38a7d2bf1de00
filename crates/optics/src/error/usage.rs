//! What the argument parser's errors say, read once: the argument they
//! name and their message on one line.

/// The argument a command-line error names (`--eta <ETA>`), if it names one.
pub(crate) fn usage_argument(error: &clap::Error) -> Option<String> {
    use clap::error::{ContextKind, ContextValue};
    match error.get(ContextKind::InvalidArg)? {
        ContextValue::String(arg) => Some(arg.clone()),
        ContextValue::Strings(args) => Some(args.join(", ")),
        _ => None,
    }
}

/// The argument parser's message without its `error: ` and the usage and
/// help hints that follow it, on one line.
pub(crate) fn usage_text(error: &clap::Error) -> String {
    let text = error.to_string();
    let message: Vec<&str> = text
        .lines()
        .take_while(|line| !line.trim().is_empty())
        .map(str::trim)
        .collect();
    let message = message.join(" ");
    message
        .strip_prefix("error: ")
        .unwrap_or(&message)
        .to_owned()
}
