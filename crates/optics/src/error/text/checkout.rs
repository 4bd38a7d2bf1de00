//! No usable checkout of the suite, in both languages: what named the
//! directory and what it lacks, or where none was found and the advice
//! that the reporting command accepts. The library's English is kept
//! where this command adds nothing to it.

use record::{say, Lang};
use validation::checkout::{CheckoutError, Via, ENV, MARKERS};

/// A checkout error in `lang`, for a command whose checkout flag is `flag`
/// (`None`: the command has none): the flag leads the message of a
/// directory it named, and the advice after a missing checkout names only
/// what the command accepts.
pub(super) fn checkout(error: &CheckoutError, flag: Option<&str>, lang: Lang) -> String {
    match (error, flag) {
        (
            CheckoutError::NotACheckout {
                via: Via::Explicit,
                path,
                marker,
            },
            Some(flag),
        ) => say!(
            lang,
            "{flag} {}: not a checkout of the suite (it has no {marker})",
            "{flag} {}: nem a programcsomag munkapéldánya (nincs benne {marker})",
            path.display()
        ),
        (CheckoutError::NotACheckout { via, path, marker }, _) => match lang {
            Lang::En => error.to_string(),
            Lang::Hu => format!(
                "{} {}: nem a programcsomag munkapéldánya (nincs benne {marker})",
                via_hu(*via),
                path.display()
            ),
        },
        (CheckoutError::NotFound { start }, _) => {
            let advice = match flag {
                Some(flag) => say!(
                    lang,
                    "pass {flag} DIR, set {ENV}=DIR, or run from inside a checkout",
                    "adja meg a {flag} DIR kapcsolót, állítsa be az {ENV}=DIR változót, \
                     vagy futtassa egy munkapéldányon belülről"
                ),
                None => say!(
                    lang,
                    "set {ENV}=DIR, or run from inside a checkout",
                    "állítsa be az {ENV}=DIR változót, vagy futtassa egy munkapéldányon belülről"
                ),
            };
            match lang {
                Lang::En => format!("{error}; {advice}"),
                Lang::Hu => format!(
                    "nem található a programcsomag munkapéldánya: nem neveztek meg egyet sem, az \
                     {ENV} változó üres vagy nincs beállítva, és sem {}, sem egy fölötte lévő \
                     könyvtár nem tartalmazza egyszerre ezeket: {}, {}; {advice}",
                    start.display(),
                    MARKERS[0],
                    MARKERS[1]
                ),
            }
        }
    }
}

/// What named a directory that is no checkout, in Hungarian, where no
/// flag of the command named it.
fn via_hu(via: Via) -> &'static str {
    match via {
        Via::Explicit => "a megnevezett könyvtár",
        Via::Environment => ENV,
        Via::Search => "a munkakönyvtár",
        Via::BuildTime => "e fordítás munkapéldánya",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::harness::{checkout_field, CHECKOUT_FLAG};

    fn not_found() -> CheckoutError {
        CheckoutError::NotFound {
            start: "/tmp/work".into(),
        }
    }

    #[test]
    fn a_command_without_the_flag_is_not_advised_to_pass_it() {
        let message = checkout(&not_found(), None, Lang::En);
        assert!(!message.contains("--"), "{message}");
        assert!(message.contains(&format!("set {ENV}=DIR")), "{message}");
        assert_eq!(checkout_field(&not_found(), None), ENV);
    }

    #[test]
    fn a_command_with_the_flag_is_advised_to_pass_it() {
        let message = checkout(&not_found(), Some(CHECKOUT_FLAG), Lang::En);
        for way in [
            "--checkout DIR",
            &format!("{ENV}=DIR"),
            "from inside a checkout",
        ] {
            assert!(message.contains(way), "{message}");
        }
        assert_eq!(
            checkout_field(&not_found(), Some(CHECKOUT_FLAG)),
            CHECKOUT_FLAG
        );
    }
}
