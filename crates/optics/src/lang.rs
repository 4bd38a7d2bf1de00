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

/// An error message in `lang`: the domain errors of the laws (a wrong
/// number, named by its argument) are translated; others stay in English.
pub fn error_message(error: &anyhow::Error, lang: Lang) -> String {
    use radiometry::domain::DomainError;
    match (lang, error.downcast_ref::<DomainError>()) {
        (Lang::Hu, Some(DomainError::NotFinite { name, value })) => {
            format!("{name}: véges számnak kell lennie, kapott érték: {value}")
        }
        (
            Lang::Hu,
            Some(DomainError::OutOfRange {
                name,
                value,
                expected,
            }),
        ) => {
            let expected = match *expected {
                "in [-1, 1]" => "a [-1, 1] tartományba kell esnie",
                "in [0, 1]" => "a [0, 1] tartományba kell esnie",
                "a positive refractive index" => "pozitív törésmutatónak kell lennie",
                "a refractive index from 1e-50 to 1e50" => {
                    "1e-50 és 1e50 közötti törésmutatónak kell lennie"
                }
                "an extinction coefficient of 0 or from 1e-50 to 1e50" => {
                    "0 vagy 1e-50 és 1e50 közötti kioltási tényezőnek kell lennie"
                }
                "a refractive index from 1e-9 to 1e9 (the range of the f32 laws)" => {
                    "1e-9 és 1e9 közötti törésmutatónak kell lennie (az f32 törvények tartománya)"
                }
                "an extinction coefficient of 0 or from 1e-9 to 1e9 (the range of the f32 laws)" => {
                    "0 vagy 1e-9 és 1e9 közötti kioltási tényezőnek kell lennie (az f32 törvények tartománya)"
                }
                "a non-negative extinction coefficient" => {
                    "nemnegatív kioltási tényezőnek kell lennie"
                }
                "non-negative" => "nemnegatívnak kell lennie",
                other => other,
            };
            let value = radiometry::domain::shown(*value);
            format!("{name}: {expected}, kapott érték: {value}")
        }
        (Lang::Hu, Some(DomainError::ZeroVector { name, x, y, z })) => {
            format!("{name}: nem nulla hosszú iránynak kell lennie, kapott: ({x}, {y}, {z})")
        }
        _ => format!("{error:#}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use radiometry::domain;

    #[test]
    fn domain_errors_are_translated_and_keep_the_argument_name() {
        let error = anyhow::Error::from(domain::refractive_index("--eta", -1.0).unwrap_err());
        assert_eq!(
            error_message(&error, Lang::En),
            "--eta must be a positive refractive index, got -1"
        );
        assert_eq!(
            error_message(&error, Lang::Hu),
            "--eta: pozitív törésmutatónak kell lennie, kapott érték: -1"
        );
    }
}
