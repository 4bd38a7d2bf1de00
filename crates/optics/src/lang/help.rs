//! The command line's help in Hungarian: the parser's `clap::Command`, as
//! the derive attributes build it in English, rewritten before parsing
//! from the one table of Hungarian help texts ([`super::help_hu`]).
//!
//! Every text a help page shows has a slot, named by the command's path
//! (`["quiz", "f0"]`) and a key: an argument's id (`"n"`), a possible
//! value as `"arg=value"`, or the command's own `"#about"`,
//! `"#long_about"` and `"#after_help"`. An argument's or a value's slot
//! declared on a command also serves the same key in every command below
//! it: the global flags and the built-in `help` and `version` are
//! declared once, on the root.
//! `english_texts` lists every slot the English help fills, so that a
//! test can name each one the table lacks.
//!
//! clap writes a few words of its own ("Usage:", "Options:", "[default:
//! …]", "Possible values:"): under Hungarian they are replaced too, by a
//! help template and by headings and value lists written here.

use clap::builder::{Command, PossibleValue};
use clap::Arg;

use super::help_hu::{Slot, SLOTS};
use crate::law_table::LAWS;

/// The key of a command's about (its one-line description).
pub(crate) const ABOUT: &str = "#about";
/// The key of a command's long about (a doc comment of two paragraphs or more).
pub(crate) const LONG_ABOUT: &str = "#long_about";
/// The key of a command's after-help (its examples and notes).
pub(crate) const AFTER_HELP: &str = "#after_help";

/// The page's layout, clap's default with its one English heading replaced.
const TEMPLATE: &str =
    "{before-help}{about-with-newline}\nHasználat: {usage}\n\n{all-args}{after-help}";

/// One English text of the help and the slot it needs.
#[cfg(test)]
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Text {
    /// The command's path below the program: `["quiz", "f0"]`.
    pub path: Vec<String>,
    /// The slot's key on that command.
    pub key: String,
    /// What the English help shows there.
    pub english: String,
}

/// The Hungarian of a slot, and where it is declared: on the command
/// itself, else (for an argument or a value, not for the command's own
/// texts) on the nearest command above it.
pub(crate) fn slot(path: &[String], key: &str) -> Option<&'static Slot> {
    let path = described(path);
    let lowest = if key.starts_with('#') { path.len() } else { 0 };
    (lowest..=path.len()).rev().find_map(|depth| {
        SLOTS
            .iter()
            .flat_map(|family| family.iter())
            .find(|(at, k, _)| {
                *k == key
                    && at
                        .iter()
                        .copied()
                        .eq(path[..depth].iter().map(String::as_str))
            })
    })
}

/// The command a page describes: clap's `help` subcommand holds a copy of
/// the commands beside it (`help render` shows `render`'s about), and
/// itself, wherever it appears, takes the slots of `["help"]`.
fn described(path: &[String]) -> Vec<String> {
    match path.iter().position(|word| word == "help") {
        Some(at) if at + 1 < path.len() => described(&[&path[..at], &path[at + 1..]].concat()),
        Some(_) => vec![String::from("help")],
        None => path.to_vec(),
    }
}

/// A slot's Hungarian as the page shows it: `{laws}` is the law table's
/// names, as the English of `batch` lists them.
fn hungarian_text(path: &[String], key: &str) -> Option<String> {
    let (_, _, text) = slot(path, key)?;
    Some(text.replace("{laws}", &LAWS.join(", ")))
}

/// The parser's command (built: with its globals, `help` and `version`
/// in place), every help text it shows in Hungarian.
pub(crate) fn hungarian(mut command: Command) -> Command {
    command.build();
    rewrite(command, &[])
}

fn rewrite(command: Command, path: &[String]) -> Command {
    let ids: Vec<_> = command
        .get_arguments()
        .map(|a| a.get_id().clone())
        .collect();
    let subcommands: Vec<String> = command
        .get_subcommands()
        .map(|s| s.get_name().to_owned())
        .collect();
    let hu = |key: &str| hungarian_text(path, key);
    let mut command = command.subcommand_value_name("ALPARANCS");
    // clap writes "[OPTIONS]" into the usage line itself: the line is
    // taken as clap renders it, that word replaced, and handed back.
    let usage = command.render_usage().to_string();
    let usage = usage.strip_prefix("Usage: ").unwrap_or(&usage);
    let usage = usage.replace("[OPTIONS]", "[KAPCSOLÓK]");
    let mut command = command
        .override_usage(usage)
        .help_template(TEMPLATE)
        .subcommand_help_heading("Alparancsok");
    if let (Some(_), Some(about)) = (command.get_about(), hu(ABOUT)) {
        command = command.about(about);
    }
    if let (Some(_), Some(about)) = (command.get_long_about(), hu(LONG_ABOUT)) {
        command = command.long_about(about);
    }
    if let (Some(_), Some(after)) = (command.get_after_help(), hu(AFTER_HELP)) {
        command = command.after_help(after);
    }
    for id in ids {
        command = command.mut_arg(id, |arg| rewrite_arg(arg, path));
    }
    for name in subcommands {
        let below: Vec<String> = path.iter().cloned().chain([name.clone()]).collect();
        command = command.mut_subcommand(name, |sub| rewrite(sub, &below));
    }
    command
}

/// An argument's help, heading, default and possible values in Hungarian.
fn rewrite_arg(arg: Arg, path: &[String]) -> Arg {
    let id = arg.get_id().as_str().to_owned();
    let heading = if arg.is_positional() {
        "Argumentumok"
    } else {
        "Kapcsolók"
    };
    let Some(text) = hungarian_text(path, &id) else {
        return arg.help_heading(heading);
    };
    let (short, long) = match text.split_once("\n\n") {
        Some((first, _)) => (first.trim_end_matches('.'), text.as_str()),
        None => (text.as_str(), text.as_str()),
    };
    let values = possible_values(&arg, path);
    let default = default_value(&arg);
    let mut short = short.to_owned();
    let mut long = long.to_owned();
    if let Some(default) = &default {
        short += &format!(" [alapértelmezett: {default}]");
    }
    if !values.is_empty() {
        let names: Vec<&str> = values.iter().map(|(name, _)| name.as_str()).collect();
        short += &format!(" [lehetséges értékek: {}]", names.join(", "));
        long += &value_list(&values);
    }
    if let Some(default) = &default {
        long += &format!("\n\n[alapértelmezett: {default}]");
    }
    arg.help(short)
        .long_help(long)
        .hide_default_value(true)
        .hide_possible_values(true)
        .help_heading(heading)
}

/// The default a help page shows, as clap shows it (`[default: …]`).
fn default_value(arg: &Arg) -> Option<String> {
    let shown = !arg.is_hide_default_value_set()
        && arg.get_action().takes_values()
        && !arg.get_default_values().is_empty();
    shown.then(|| {
        let values: Vec<_> = arg
            .get_default_values()
            .iter()
            .map(|v| v.to_string_lossy().into_owned())
            .collect();
        values.join(", ")
    })
}

/// An argument's shown possible values, each with its Hungarian help.
fn possible_values(arg: &Arg, path: &[String]) -> Vec<(String, Option<String>)> {
    if arg.is_hide_possible_values_set() || !arg.get_action().takes_values() {
        return Vec::new();
    }
    let id = arg.get_id().as_str();
    arg.get_possible_values()
        .iter()
        .filter(|value| !value.is_hide_set())
        .map(|value| {
            let key = value_key(id, value);
            let help = value.get_help().and_then(|_| hungarian_text(path, &key));
            (value.get_name().to_owned(), help)
        })
        .collect()
}

/// The long help's list of values: a block with their help, as clap
/// writes it, where they have any; else none (the short form has them).
fn value_list(values: &[(String, Option<String>)]) -> String {
    if values.iter().all(|(_, help)| help.is_none()) {
        let names: Vec<&str> = values.iter().map(|(name, _)| name.as_str()).collect();
        return format!("\n\n[lehetséges értékek: {}]", names.join(", "));
    }
    let width = values.iter().map(|(name, _)| name.len()).max().unwrap_or(0);
    let mut list = String::from("\n\nLehetséges értékek:");
    for (name, help) in values {
        match help {
            Some(help) => {
                list += &format!(
                    "\n- {:<width$} {help}",
                    format!("{name}:"),
                    width = width + 1
                )
            }
            None => list += &format!("\n- {name}"),
        }
    }
    list
}

/// The key of a possible value's slot: `"model=schlick"`.
pub(crate) fn value_key(arg: &str, value: &PossibleValue) -> String {
    format!("{arg}={}", value.get_name())
}

/// Every English text the help shows, with its slot, from the command
/// down (built first, so that the globals and built-in flags are there).
#[cfg(test)]
pub(crate) fn english_texts(mut command: Command) -> Vec<Text> {
    command.build();
    let mut texts = Vec::new();
    walk(&command, &[], &mut texts);
    texts
}

#[cfg(test)]
fn walk(command: &Command, path: &[String], texts: &mut Vec<Text>) {
    let mut add = |key: String, english: &clap::builder::StyledStr| {
        texts.push(Text {
            path: path.to_vec(),
            key,
            english: english.to_string(),
        })
    };
    let own = [
        (ABOUT, command.get_about()),
        (LONG_ABOUT, command.get_long_about()),
        (AFTER_HELP, command.get_after_help()),
    ];
    for (key, text) in own {
        if let Some(text) = text {
            add(key.to_owned(), text);
        }
    }
    for arg in command.get_arguments().filter(|a| !a.is_hide_set()) {
        let id = arg.get_id().as_str();
        if let Some(help) = arg.get_long_help().or(arg.get_help()) {
            add(id.to_owned(), help);
        }
        for value in arg.get_possible_values() {
            if let (false, Some(help)) = (value.is_hide_set(), value.get_help()) {
                add(value_key(id, &value), help);
            }
        }
    }
    for sub in command.get_subcommands().filter(|s| !s.is_hide_set()) {
        let below: Vec<String> = path
            .iter()
            .cloned()
            .chain([sub.get_name().to_owned()])
            .collect();
        walk(sub, &below, texts);
    }
}
