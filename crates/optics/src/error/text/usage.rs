//! A command-line error in both languages: the argument parser's message
//! in English (with the decimal point's advice), and in Hungarian a
//! lead-in naming the argument, then the suite's own message translated,
//! or else the parser's as it wrote it.

use std::error::Error as _;

use record::{say, Lang};

use crate::error::usage::{decimal_comma_fixed, usage_argument, usage_message};
use crate::error::Error;

/// The advice after a number refused for its decimal comma.
pub(crate) fn decimal_comma(fixed: &str, lang: Lang) -> String {
    say!(
        lang,
        "numbers take a decimal point, not a comma: {fixed}",
        "a számokban tizedespont áll, nem vessző: {fixed}"
    )
}

/// The parser's error in `lang`.
pub(super) fn usage(error: &clap::Error, lang: Lang) -> String {
    let ours = error.source().and_then(|e| e.downcast_ref::<Error>());
    let mut message = match (lang, ours) {
        (Lang::Hu, Some(ours)) => ours.kind().message(lang),
        (Lang::En, _) | (Lang::Hu, None) => usage_message(error),
    };
    if let Some(fixed) = decimal_comma_fixed(error) {
        message += &format!(" ({})", decimal_comma(&fixed, lang));
    }
    match (lang, usage_argument(error)) {
        (Lang::En, _) => message,
        (Lang::Hu, Some(arg)) => format!("hibás parancssori argumentum ({arg}): {message}"),
        (Lang::Hu, None) => format!("hibás parancssor: {message}"),
    }
}
