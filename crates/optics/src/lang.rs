//! The two languages of the text output: English, and Hungarian, the
//! language of the source course.

use clap::ValueEnum;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Lang {
    /// English.
    En,
    /// Magyar (Hungarian).
    Hu,
}

impl Lang {
    /// The text in this language.
    pub fn pick<'a>(self, en: &'a str, hu: &'a str) -> &'a str {
        match self {
            Lang::En => en,
            Lang::Hu => hu,
        }
    }
}

/// `say!(lang, "English {x}", "Magyar {x}")`: a formatted line in `lang`.
macro_rules! say {
    ($lang:expr, $en:literal, $hu:literal $(, $arg:expr)* $(,)?) => {
        match $lang {
            $crate::lang::Lang::En => format!($en $(, $arg)*),
            $crate::lang::Lang::Hu => format!($hu $(, $arg)*),
        }
    };
}
pub(crate) use say;
