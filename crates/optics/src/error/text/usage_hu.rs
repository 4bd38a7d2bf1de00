//! The argument parser's errors in Hungarian, written from what the error
//! holds (its kind and `clap::error::ContextKind`s), laid out as clap lays
//! out its English: the message, its tips, the usage line, where to read
//! more.

use std::error::Error as _;
use std::fmt::Write as _;

use clap::error::{ContextKind, ContextValue, ErrorKind as Clap};

use crate::error::usage::FlagRefusal;
use crate::error::Error;

/// What was wrong, on the error's first line (and, for a choice of
/// values or subcommands, the list on the next).
pub(super) fn message(error: &clap::Error) -> String {
    let arg = string(error, ContextKind::InvalidArg);
    let value = string(error, ContextKind::InvalidValue);
    let mut text = match (error.kind(), arg, value) {
        (Clap::InvalidValue, Some(_), Some("")) => String::from("nem kapott értéket"),
        (Clap::InvalidValue, Some(_), Some(value)) => format!("érvénytelen érték: '{value}'"),
        (Clap::ValueValidation, Some(_), Some(value)) => refused(error, value),
        (Clap::UnknownArgument, Some(arg), _) => format!("váratlan argumentum: '{arg}'"),
        (Clap::InvalidSubcommand, ..) => match string(error, ContextKind::InvalidSubcommand) {
            Some(sub) => format!("ismeretlen alparancs: '{sub}'"),
            None => String::from("ismeretlen alparancs"),
        },
        (Clap::MissingRequiredArgument, ..) => missing(error),
        (Clap::ArgumentConflict, ..) => conflict(error),
        (Clap::MissingSubcommand, ..) => match string(error, ContextKind::InvalidSubcommand) {
            Some(name) => format!("'{name}' után alparancsot kell megadni"),
            None => String::from("alparancsot kell megadni"),
        },
        (Clap::TooManyValues, Some(arg), Some(value)) => {
            format!("'{arg}': váratlan érték: '{value}'; több értéket nem vár")
        }
        (Clap::TooFewValues | Clap::WrongNumberOfValues, Some(arg), _) => counts(error, arg),
        (Clap::NoEquals, Some(arg), _) => {
            format!("'{arg}' értékét egyenlőségjellel kell megadni")
        }
        (Clap::InvalidUtf8, ..) => String::from("a parancssorban érvénytelen UTF-8 áll"),
        _ => String::from("hibás parancssor"),
    };
    let list = match error.kind() {
        Clap::InvalidValue => Some(("lehetséges értékek", ContextKind::ValidValue)),
        Clap::MissingSubcommand => Some(("alparancsok", ContextKind::ValidSubcommand)),
        _ => None,
    };
    if let Some((name, kind)) = list {
        if let Some(ContextValue::Strings(values)) = error.get(kind) {
            let _ = write!(text, "\n  [{name}: {}]", values.join(", "));
        }
    }
    text
}

/// The advice clap gives after the message: a similar subcommand, flag
/// or value, or how to pass a value that looks like a flag.
pub(super) fn tips(error: &clap::Error) -> Vec<String> {
    let similar = [
        (ContextKind::SuggestedSubcommand, "alparancs", "alparancsok"),
        (ContextKind::SuggestedArg, "kapcsoló", "kapcsolók"),
        (ContextKind::SuggestedValue, "érték", "értékek"),
    ];
    let mut tips: Vec<String> = similar
        .into_iter()
        .filter_map(|(kind, one, many)| {
            let names = match error.get(kind)? {
                ContextValue::String(name) => vec![name.clone()],
                ContextValue::Strings(names) => names.clone(),
                _ => return None,
            };
            let quoted: Vec<String> = names.iter().map(|n| format!("'{n}'")).collect();
            Some(match quoted.len() {
                1 => format!("van hasonló {one}: {}", quoted[0]),
                _ => format!("vannak hasonló {many}: {}", quoted.join(", ")),
            })
        })
        .collect();
    if let Some(ContextValue::StyledStrs(suggestions)) = error.get(ContextKind::Suggested) {
        tips.extend(suggestions.iter().filter_map(|s| as_value(&s.to_string())));
    }
    tips
}

/// The usage line clap attached, under its Hungarian heading.
pub(super) fn usage_line(error: &clap::Error) -> Option<String> {
    let Some(ContextValue::StyledStr(usage)) = error.get(ContextKind::Usage) else {
        return None;
    };
    let usage = usage.to_string();
    let usage = usage.strip_prefix("Usage:").unwrap_or(&usage).trim_start();
    Some(format!("Használat: {usage}"))
}

/// Where to read more, as clap closes its errors.
pub(super) const MORE: &str = "Bővebben: '--help'.";

/// clap's advice to pass a value that looks like a flag after `--`.
fn as_value(english: &str) -> Option<String> {
    let (_, spelled) = english
        .strip_prefix("to pass '")?
        .split_once("' as a value, use '")?;
    Some(format!(
        "ha értéknek szánta, így adható meg: '{}'",
        spelled.strip_suffix('\'')?
    ))
}

fn string(error: &clap::Error, kind: ContextKind) -> Option<&str> {
    match error.get(kind)? {
        ContextValue::String(text) => Some(text),
        _ => None,
    }
}

/// A value the argument's parser refused, and why: the suite's own
/// error translated, a number's standard refusals in words, else the
/// parser's reason as it gave it.
fn refused(error: &clap::Error, value: &str) -> String {
    let Some(source) = error.source() else {
        return format!("érvénytelen érték: '{value}'");
    };
    if let Some(ours) = source.downcast_ref::<Error>() {
        return ours.kind().message(record::Lang::Hu);
    }
    let reason = if let Some(refusal) = source.downcast_ref::<FlagRefusal>() {
        refusal.hu.clone()
    } else if source.is::<std::num::ParseFloatError>() {
        String::from("nem szám")
    } else if let Some(int) = source.downcast_ref::<std::num::ParseIntError>() {
        use std::num::IntErrorKind as Int;
        String::from(match int.kind() {
            Int::Empty => "üres",
            Int::PosOverflow => "túl nagy",
            Int::NegOverflow => "túl kicsi",
            _ => "nem egész szám",
        })
    } else {
        let text = source.to_string();
        match text.split_once(" is not in ") {
            Some((_, range)) => format!("a megengedett tartományon kívül esik: {range}"),
            None => text,
        }
    };
    format!("érvénytelen érték: '{value}' ({reason})")
}

fn missing(error: &clap::Error) -> String {
    let args = match error.get(ContextKind::InvalidArg) {
        Some(ContextValue::Strings(args)) => args.clone(),
        _ => Vec::new(),
    };
    match args.as_slice() {
        [one] => format!("hiányzik a kötelező argumentum:\n  {one}"),
        _ => format!(
            "hiányoznak a kötelező argumentumok:\n  {}",
            args.join("\n  ")
        ),
    }
}

fn conflict(error: &clap::Error) -> String {
    let arg = string(error, ContextKind::InvalidArg)
        .or_else(|| string(error, ContextKind::InvalidSubcommand))
        .unwrap_or("?");
    match error.get(ContextKind::PriorArg) {
        Some(ContextValue::String(prior)) if prior == arg => {
            format!("'{arg}' csak egyszer adható meg")
        }
        Some(ContextValue::String(prior)) => {
            format!("'{arg}' nem adható meg együtt ezzel: '{prior}'")
        }
        Some(ContextValue::Strings(prior)) => {
            format!(
                "'{arg}' nem adható meg együtt ezekkel:\n  {}",
                prior.join("\n  ")
            )
        }
        _ => format!("'{arg}' nem adható meg együtt a többi megadott argumentummal"),
    }
}

fn counts(error: &clap::Error, arg: &str) -> String {
    let number = |kind| match error.get(kind) {
        Some(ContextValue::Number(n)) => *n,
        _ => 0,
    };
    let given = number(ContextKind::ActualNumValues);
    match error.kind() {
        Clap::TooFewValues => format!(
            "'{arg}' legalább {} értéket vár, de csak {given} érkezett",
            number(ContextKind::MinValues)
        ),
        _ => format!(
            "'{arg}' {} értéket vár, de {given} érkezett",
            number(ContextKind::ExpectedNumValues)
        ),
    }
}
