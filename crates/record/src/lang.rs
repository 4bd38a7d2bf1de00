//! The two languages the suite speaks: English, and Hungarian, the language
//! of the source course.

/// A language of the text output.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
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

/// `say!(lang, "English {x}", "Magyar {x}")`: a formatted line in `lang`,
/// both languages written side by side at the place that says it.
#[macro_export]
macro_rules! say {
    ($lang:expr, $en:literal, $hu:literal $(, $arg:expr)* $(,)?) => {
        match $lang {
            $crate::Lang::En => format!($en $(, $arg)*),
            $crate::Lang::Hu => format!($hu $(, $arg)*),
        }
    };
}

#[cfg(test)]
mod tests {
    use super::Lang;

    #[test]
    fn each_language_picks_its_own_text() {
        assert_eq!(Lang::En.pick("light", "fény"), "light");
        assert_eq!(Lang::Hu.pick("light", "fény"), "fény");
        let n = 3;
        assert_eq!(crate::say!(Lang::Hu, "{} rays", "{} sugár", n), "3 sugár");
        assert_eq!(crate::say!(Lang::En, "{} rays", "{} sugár", n), "3 rays");
    }
}
