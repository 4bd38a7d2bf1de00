//! What the argument parser's errors say, read once: the argument they
//! name, the number refused for its decimal comma, and their message on
//! one line.

/// The argument a command-line error names (`--eta <ETA>`), if it names one.
pub(crate) fn usage_argument(error: &clap::Error) -> Option<String> {
    use clap::error::{ContextKind, ContextValue};
    match error.get(ContextKind::InvalidArg)? {
        ContextValue::String(arg) => Some(arg.clone()),
        ContextValue::Strings(args) => Some(args.join(", ")),
        _ => None,
    }
}

/// The value a number was refused for, written with a decimal point,
/// where it was refused only for its decimal comma (`1,4`, as Hungarian
/// students write it): `1.4`.
pub(crate) fn decimal_comma_fixed(error: &clap::Error) -> Option<String> {
    use clap::error::{ContextKind, ContextValue};
    use std::error::Error as _;
    // Only a value refused as a number: a vector's parts are refused by
    // the suite's own parser, whose commas are separators.
    error
        .source()?
        .downcast_ref::<std::num::ParseFloatError>()?;
    let ContextValue::String(value) = error.get(ContextKind::InvalidValue)? else {
        return None;
    };
    if value.matches(',').count() != 1 {
        return None;
    }
    let fixed = value.replace(',', ".");
    fixed.parse::<f64>().ok().map(|_| fixed)
}

/// The argument parser's message without its `error: ` and the usage and
/// help hints that follow it, on one line.
pub(crate) fn usage_message(error: &clap::Error) -> String {
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

/// A flag's value its own parser refused, said in both languages: the
/// parser runs before the language is known, so it hands both on and the
/// error's rendering picks one (English is its `Display`).
#[derive(Debug)]
pub(crate) struct FlagRefusal {
    /// Why, in English.
    pub en: String,
    /// Why, in Hungarian.
    pub hu: String,
}

impl std::fmt::Display for FlagRefusal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.en)
    }
}

impl std::error::Error for FlagRefusal {}

#[cfg(feature = "harness")]
/// What a flag's own number parser returns: a number that is not one is
/// refused as the standard parser refuses it (so a decimal comma gets its
/// hint), one outside the flag's range as a [`FlagRefusal`].
pub(crate) type FlagNumber = Result<f64, Box<dyn std::error::Error + Send + Sync>>;

#[cfg(feature = "harness")]
/// `text` as a number that `accept` takes, else refused with `why`'s
/// two sentences about it.
pub(crate) fn flag_number(
    text: &str,
    accept: impl Fn(f64) -> bool,
    why: impl Fn(f64) -> (String, String),
) -> FlagNumber {
    let value: f64 = text.parse()?;
    if accept(value) {
        return Ok(value);
    }
    let (en, hu) = why(value);
    Err(Box::new(FlagRefusal { en, hu }))
}
