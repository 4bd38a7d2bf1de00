//! A command-line error in both languages: the argument parser's message
//! in English (with the decimal point's advice), and in Hungarian the same
//! written from the error's context (`usage_hu`), a refused value behind
//! a lead-in naming the argument.

use record::{say, Lang};

use super::usage_hu;

use crate::error::usage::{decimal_comma_fixed, usage_argument, usage_message};

/// The advice after a number refused for its decimal comma.
pub(crate) fn decimal_comma(fixed: &str, lang: Lang) -> String {
    say!(
        lang,
        "numbers take a decimal point, not a comma: {fixed}",
        "a számokban tizedespont áll, nem vessző: {fixed}"
    )
}

/// The parser's error in `lang`, on one line (the JSON error's message).
pub(super) fn usage(error: &clap::Error, lang: Lang) -> String {
    let mut message = match lang {
        Lang::En => usage_message(error),
        Lang::Hu => hungarian(error).replace("\n  ", " "),
    };
    if let Some(fixed) = decimal_comma_fixed(error) {
        message += &format!(" ({})", decimal_comma(&fixed, lang));
    }
    message
}

/// The parser's error in Hungarian: a lead-in naming the argument whose
/// value was refused, then what was wrong (the suite's own message where
/// the value was refused by the suite's parser).
fn hungarian(error: &clap::Error) -> String {
    use clap::error::ErrorKind as Clap;
    let message = usage_hu::message(error);
    match (error.kind(), usage_argument(error)) {
        (Clap::InvalidValue | Clap::ValueValidation, Some(arg)) => {
            format!("hibás parancssori argumentum ({arg}): {message}")
        }
        _ => message,
    }
}

/// The parser's error as stderr shows it: in English clap's own
/// rendering, in Hungarian the same layout in Hungarian; both with the
/// decimal point's advice among the tips.
pub(crate) fn rendered(error: &clap::Error, lang: Lang) -> String {
    let fixed = decimal_comma_fixed(error).map(|fixed| decimal_comma(&fixed, lang));
    if lang == Lang::En {
        let rendered = error.render().to_string();
        return match (fixed, rendered.split_once('\n')) {
            (Some(fixed), Some((first, rest))) => format!("{first}\n\n  tip: {fixed}\n{rest}"),
            _ => rendered,
        };
    }
    let mut text = format!("hiba: {}", hungarian(error));
    let tips: Vec<String> = usage_hu::tips(error).into_iter().chain(fixed).collect();
    if !tips.is_empty() {
        text += "\n";
    }
    for tip in tips {
        text += &format!("\n  tipp: {tip}");
    }
    if let Some(usage) = usage_hu::usage_line(error) {
        text += &format!("\n\n{usage}");
    }
    format!("{text}\n\n{}\n", usage_hu::MORE)
}
