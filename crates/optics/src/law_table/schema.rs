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
    /// Numbers, as many as given: `[c, …]` in a request, `c,…` on the
    /// command line.
    List,
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
    /// The fields of the group, one of which every request must give,
    /// that this one belongs to (Fresnel's `cos_i` and `theta_i_deg`).
    pub one_of: Option<Vec<String>>,
    /// The fields it cannot be given with: the others of a group at most
    /// one of which is given (Fresnel's `metal` and `kappa`).
    pub excludes: Vec<String>,
    /// What it holds.
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
    let members = |required: bool| -> Vec<Vec<String>> {
        command
            .get_groups()
            // The group clap derives for the arguments' struct holds all
            // of them, any number at once: it excludes nothing.
            .filter(|group| {
                group.is_required_set() == required && !clap::ArgGroup::clone(group).is_multiple()
            })
            .map(|group| group.get_args().map(|id| id.as_str().to_owned()).collect())
            .collect()
    };
    let (groups, at_most_one) = (members(true), members(false));
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
            // A hidden value is read to be refused (the bare `schlick`),
            // not offered.
            let choices: Vec<String> = arg
                .get_possible_values()
                .iter()
                .filter(|v| !v.is_hide_set())
                .map(|v| v.get_name().to_owned())
                .collect();
            let kind = if !choices.is_empty() {
                Kind::Choice(choices)
            } else if arg.get_value_delimiter().is_some() {
                Kind::List
            } else if parses("1.5") {
                Kind::Number
            } else {
                debug_assert!(parses("0,0,1"), "--{:?} takes a vector", arg.get_long());
                Kind::Vector
            };
            let name = arg.get_id().as_str().to_owned();
            let one_of = groups
                .iter()
                .find(|members| members.contains(&name))
                .cloned();
            let excludes = at_most_one
                .iter()
                .filter(|members| members.contains(&name))
                .flatten()
                .filter(|member| **member != name)
                .cloned()
                .collect();
            Field {
                name,
                required: arg.is_required_set(),
                one_of,
                excludes,
                kind,
                help: arg.get_help().map(ToString::to_string).unwrap_or_default(),
            }
        })
        .collect()
}

/// The first example of the law's `--help` (`optics reflect --wi 0,0.6,0.8
/// --normal 0,0,1`), as a batch line's fields and as the flags after the
/// law's command words. Panics where the help gives none, or gives a flag
/// that is not a field of the law.
#[cfg(test)]
pub fn example(law: &str) -> (serde_json::Map<String, serde_json::Value>, Vec<String>) {
    let command = command(law).unwrap_or_else(|| panic!("{law} is not a law"));
    let words = format!("optics {} ", command_words(law).join(" "));
    let line = crate::help_example::first_example(&command, &words)
        .unwrap_or_else(|| panic!("`{words}--help` shows no example"));
    let flags: Vec<String> = line[words.len()..]
        .split_whitespace()
        .map(str::to_owned)
        .collect();
    let fields = fields(law);
    let mut request = serde_json::Map::new();
    for pair in flags.chunks(2) {
        let name = pair[0].trim_start_matches("--").replace('-', "_");
        let field = fields
            .iter()
            .find(|f| f.name == name)
            .unwrap_or_else(|| panic!("{words}: {} is not a field", pair[0]));
        let text = pair.get(1).map_or("", String::as_str);
        let value = match field.kind {
            Kind::Vector | Kind::List => serde_json::json!(text
                .split(',')
                .map(|c| c.parse::<f64>().expect("a component"))
                .collect::<Vec<_>>()),
            Kind::Number => serde_json::json!(text.parse::<f64>().expect("a number")),
            Kind::Choice(_) => serde_json::json!(text),
        };
        request.insert(name, value);
    }
    (request, flags)
}
