//! A law's request fields, read from its arguments' declaration: the flag
//! `--light-dir` is the field `light_dir`, required where the flag is, a
//! number, a vector or a choice as the flag's parser takes it.

use super::table::{command_words, LawCommand, QuizLaw};
use clap::{Command, Subcommand};

/// What a field holds.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A number, `1.5`.
    Number,
    /// A vector, `[x, y, z]` in a request and `x,y,z` on the command line.
    Vector,
    /// One of the names a choice takes (`exact`, `lat-long`, …).
    Choice(Vec<String>),
}

/// One field of a law's request.
#[derive(Clone, Debug)]
pub struct Field {
    /// The field's name in a request; the flag is `--` and `-` for `_`.
    pub name: String,
    /// Whether every request must give it (a field of a group one of
    /// which is required, as Fresnel's incidence, is not).
    pub required: bool,
    pub kind: Kind,
    /// The flag's help line, in English.
    pub help: String,
}

/// The command line of every law: `optics` with the laws' subcommands,
/// and `quiz` with the exercises'.
pub fn commands() -> Command {
    let quiz = QuizLaw::augment_subcommands(Command::new("quiz"));
    LawCommand::augment_subcommands(Command::new("optics")).subcommand(quiz)
}

/// The subcommand of the law named `law` in a request; `None` for a name
/// that is not a law's.
pub fn command(law: &str) -> Option<Command> {
    let mut command = commands();
    for word in command_words(law) {
        command = command.find_subcommand(&word)?.clone();
    }
    Some(command)
}

/// The fields of the law named `law`, in the order its `--help` lists
/// them; empty for a name that is not a law's.
pub fn fields(law: &str) -> Vec<Field> {
    let Some(command) = command(law) else {
        return Vec::new();
    };
    command
        .get_arguments()
        .filter(|arg| arg.get_long().is_some())
        .map(|arg| {
            // The flag's own parser, alone on a command line of its own.
            let parses = |text: &str| {
                let flag = format!("--{}", arg.get_long().unwrap_or_default());
                Command::new("probe")
                    .no_binary_name(true)
                    .arg(arg.clone())
                    .try_get_matches_from([flag.as_str(), text])
                    .is_ok()
            };
            let choices: Vec<String> = arg
                .get_possible_values()
                .iter()
                .map(|v| v.get_name().to_owned())
                .collect();
            let kind = if !choices.is_empty() {
                Kind::Choice(choices)
            } else if parses("1.5") {
                Kind::Number
            } else {
                debug_assert!(parses("0,0,1"), "--{:?} takes a vector", arg.get_long());
                Kind::Vector
            };
            Field {
                name: arg.get_id().as_str().to_owned(),
                required: arg.is_required_set(),
                kind,
                help: arg.get_help().map(ToString::to_string).unwrap_or_default(),
            }
        })
        .collect()
}
