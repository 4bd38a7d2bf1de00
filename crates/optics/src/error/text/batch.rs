//! A line of the JSON batch interface refused, in both languages side by
//! side: empty, not JSON, not a request, too long, not UTF-8, unreadable.

use record::{say, Lang};

/// A batch line with nothing on it.
pub(super) fn empty_line(lang: Lang) -> String {
    say!(
        lang,
        "empty line: every line holds one request",
        "üres sor: minden sor egy kérést tartalmaz"
    )
}

/// A line that is not JSON, with why where it spells NaN or an infinity.
pub(super) fn malformed_json(error: &serde_json::Error, non_finite: bool, lang: Lang) -> String {
    let why = match (non_finite, lang) {
        (false, _) => String::new(),
        (true, Lang::En) => format!(" ({})", safe_io::json::NON_FINITE_HINT),
        (true, Lang::Hu) => " (a JSON számai végesek: a NaN és az Infinity nem szám)".to_owned(),
    };
    say!(
        lang,
        "malformed JSON: {error}{why}",
        "hibás JSON: {error}{why}"
    )
}

/// A batch line that is JSON but not an object.
pub(super) fn not_an_object(lang: Lang) -> String {
    say!(
        lang,
        "a request must be a JSON object",
        "a kérésnek JSON-objektumnak kell lennie"
    )
}

/// A request without a `law`.
pub(super) fn law_missing(lang: Lang) -> String {
    say!(
        lang,
        "law: missing; every request names its law",
        "law: hiányzik; minden kérés megnevezi a törvényét"
    )
}

/// A request whose `law` is not a string.
pub(super) fn law_not_string(lang: Lang) -> String {
    say!(lang, "law: must be a string", "law: szövegnek kell lennie")
}

/// A request naming a law the batch does not evaluate.
pub(super) fn unknown_law(law: &str, expected: &[&str], lang: Lang) -> String {
    say!(
        lang,
        "law: unknown law {law:?}, expected one of {}",
        "law: ismeretlen törvény: {law:?}, a lehetségesek: {}",
        expected.join(", ")
    )
}

/// A request field at `path` (`None`: the request as a whole) that does
/// not deserialise, with serde's `message`.
pub(super) fn request(path: Option<&str>, message: &str, lang: Lang) -> String {
    match path {
        Some(path) => say!(
            lang,
            "{path}: {message}",
            "{path}: a kérés mezője nem olvasható: {message}"
        ),
        None => say!(lang, "{message}", "a kérés nem olvasható: {message}"),
    }
}

/// A line of the batch input that could not be read.
pub(super) fn read_line(line: usize, source: &std::io::Error, lang: Lang) -> String {
    say!(
        lang,
        "reading line {line}: {source}",
        "a(z) {line}. sor nem olvasható: {source}"
    )
}

/// A line longer than `limit` bytes, skipped unread.
pub(super) fn line_too_long(limit: usize, lang: Lang) -> String {
    say!(
        lang,
        "the line is longer than {limit} bytes (a request is an object of a few \
         numbers): skipped to its end unread",
        "a sor hosszabb {limit} bájtnál (egy kérés néhány számból álló objektum): \
         olvasás nélkül a végéig átugorva"
    )
}

/// A line whose byte at `column` (from 1) is not UTF-8.
pub(super) fn not_utf8(column: usize, lang: Lang) -> String {
    say!(
        lang,
        "the line is not UTF-8 text: the byte at column {column} is not",
        "a sor nem UTF-8 szöveg: a(z) {column}. oszlopban lévő bájt hibás"
    )
}
