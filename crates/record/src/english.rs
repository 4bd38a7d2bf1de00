//! English left in a Hungarian text, found by its words: a word of four
//! letters or more that is also a word of the English it translates, or
//! a common English word, and is not a name. What the text quotes or
//! writes as code (`--spp`, `path`, `'glass'`, `docs/cli.md`, `sRGB`,
//! `<SCENE>`) is not read as words at all. Shared by the checks of every
//! Hungarian text the suite writes: the errors', the help's, the report's.

use std::collections::BTreeSet;

/// Names the Hungarian keeps as they are: people, programs, formats,
/// and the suite's own words for things (`kappa`).
pub const NAMES: &[&str] = &[
    "json",
    "kappa",
    "fresnel",
    "schlick",
    "mitsuba",
    "lambert",
    "phong",
    "blinn",
    "whitted",
    "monte",
    "carlo",
    "python",
    "matplotlib",
    "snellius",
    "descartes",
    "pareto",
    "optics",
    "printf",
    "parallel",
    "albedó",
    "magyar",
    "erratum",
    "brewster",
    "sellmeier",
    "schott",
    "fraunhofer",
    "welch",
    "sharma",
    "dalal",
    "flip",
    "mpmath",
    "ulps",
    "herbie",
    "bonferroni",
    "delta",
];

/// Common English words a translation might leave behind that the
/// English it translates need not hold.
pub const COMMON: &[&str] = &[
    "about",
    "after",
    "also",
    "argument",
    "arguments",
    "before",
    "both",
    "command",
    "commands",
    "default",
    "each",
    "error",
    "every",
    "exists",
    "file",
    "found",
    "from",
    "given",
    "help",
    "information",
    "into",
    "invalid",
    "more",
    "must",
    "none",
    "only",
    "option",
    "options",
    "other",
    "possible",
    "print",
    "provided",
    "required",
    "same",
    "similar",
    "some",
    "subcommand",
    "subcommands",
    "than",
    "that",
    "their",
    "them",
    "then",
    "there",
    "these",
    "this",
    "tip",
    "unexpected",
    "unknown",
    "usage",
    "used",
    "value",
    "values",
    "were",
    "what",
    "when",
    "where",
    "which",
    "while",
    "with",
    "without",
    "your",
];

/// The words of four letters or more, lower-cased.
pub fn words(text: &str) -> BTreeSet<String> {
    text.split(|c: char| !c.is_alphabetic())
        .filter(|word| word.chars().count() >= 4)
        .map(str::to_lowercase)
        .collect()
}

/// The text without what it writes as code or quotes: spans in
/// backticks or quotes, and tokens that are paths, flags, placeholders,
/// acronyms or identifiers.
pub fn prose(text: &str) -> String {
    let mut kept = String::new();
    let mut quote: Option<char> = None;
    let mut previous = ' ';
    for c in text.chars() {
        match quote {
            Some(open) if c == open => quote = None,
            Some(_) => {}
            None if c == '`' || c == '"' || (c == '\'' && !previous.is_alphabetic()) => {
                quote = Some(c)
            }
            None => kept.push(c),
        }
        previous = c;
    }
    kept.split_whitespace()
        .map(|token| token.trim_matches(|c: char| ",.;:()[]!?".contains(c)))
        .filter(|token| !is_code(token))
        .collect::<Vec<_>>()
        .join(" ")
}

/// A flag, a path, a placeholder, an identifier or an acronym (`sRGB`,
/// `ꟻLIP`, `PNG`): any capital after the first letter.
fn is_code(token: &str) -> bool {
    token.starts_with('-')
        || token.contains(|c: char| "/_.=$*~<>{}^|\\@#&+".contains(c) || c.is_ascii_digit())
        || token.chars().skip(1).any(char::is_uppercase)
}

/// The English words left in `hungarian`: its words that are in
/// `english` (the vocabulary of what it translates) or [`COMMON`], and
/// neither in [`NAMES`] nor, as a whole token, in `names` (`reflect`,
/// `shadow-matrix`, `lat-long`), with or without the case ending
/// Hungarian joins to a name by a hyphen (`colour-science-hez`).
pub fn english_left(
    hungarian: &str,
    english: &BTreeSet<String>,
    names: &BTreeSet<String>,
) -> Vec<String> {
    let prose = prose(hungarian);
    let left: BTreeSet<String> = prose
        .split_whitespace()
        .filter(|token| {
            // A name keeps its own hyphens and underscores, not the
            // sentence's commas and brackets.
            let bare = token.trim_matches(|c: char| !c.is_alphanumeric() && c != '-' && c != '_');
            let stem = bare.rsplit_once('-').map_or(bare, |(stem, _)| stem);
            ![token, bare, stem]
                .iter()
                .any(|t| names.contains(&t.to_lowercase()))
        })
        .flat_map(words)
        .filter(|word| english.contains(word) || COMMON.contains(&word.as_str()))
        .filter(|word| !NAMES.contains(&word.as_str()))
        .collect();
    left.into_iter().collect()
}

/// What a command line names rather than says: its commands, flags,
/// values and placeholders, lower-cased.
#[cfg(feature = "clap")]
pub fn command_names(command: &clap::Command) -> BTreeSet<String> {
    let mut found = BTreeSet::from([command.get_name().to_lowercase()]);
    for arg in command.get_arguments() {
        found.extend(arg.get_long().map(str::to_owned));
        let placeholders = arg.get_value_names().into_iter().flatten();
        found.extend(placeholders.map(|n| n.to_lowercase()));
        found.extend(
            arg.get_possible_values()
                .iter()
                .map(|v| v.get_name().to_owned()),
        );
    }
    for sub in command.get_subcommands() {
        found.extend(command_names(sub));
    }
    found
}
