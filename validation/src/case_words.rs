//! The cases' labels in Hungarian: where a check's worst value occurred
//! (`glass inside critical +1ulp`, `pixel (42, 13) R`, `silver at 75°`),
//! as the references and the checks name their cases, and the settings of
//! a trade-off record (`integrator path, 16 spp`).
//!
//! A label is words from a small vocabulary around numbers, symbols and
//! identifiers (`cos=0.3`, `theta_i=critical-1e-6rad`, `R_p`); the words
//! are put into Hungarian one by one, the numbers and identifiers kept.
//! A label with a word outside the vocabulary has no Hungarian
//! ([`hungarian`] gives `None`), so that a page shows it as the English it
//! is rather than half translated.

/// Whole phrases, put into Hungarian before the words.
const PHRASES: &[(&str, &str)] = &[
    ("the image's mean", "a kép átlaga"),
    ("the sphere's pixels", "a gömb képpontjai"),
    ("(the course)", "(a kurzusé)"),
    ("nearest double", "legközelebbi f64"),
    ("linear ramp", "lineáris átmenet"),
    ("mirror pixels", "tükörképpont"),
    ("floor pixels", "padlóképpont"),
    ("load average", "terhelési átlag"),
];

/// What a case is measured against (`diffuse R against area`), with the
/// Hungarian that follows it (`…-hoz mérve`).
const AGAINST: &[(&str, &str)] = &[
    ("area", "a felületi fényekhez mérve"),
    ("ptracer", "a fénykövetőhöz mérve"),
    ("path_centres", "a path_centres-hez mérve"),
    ("white", "a fehérhez mérve"),
    ("orange", "a narancshoz mérve"),
];

/// The words, one by one.
const WORDS: &[(&str, &str)] = &[
    ("pixel", "képpont"),
    ("pixels", "képpont"),
    ("values", "érték"),
    ("glass", "üveg"),
    ("water", "víz"),
    ("diamond", "gyémánt"),
    ("gold", "arany"),
    ("silver", "ezüst"),
    ("copper", "réz"),
    ("aluminium", "alumínium"),
    ("inside", "belül"),
    ("outside", "kívül"),
    ("in", "befelé"),
    ("out", "kifelé"),
    ("critical", "határszög"),
    ("brewster", "Brewster-szög"),
    ("transmitted", "áteresztett"),
    ("tilted", "döntött"),
    ("sky", "ég"),
    ("objects", "tárgyak"),
    ("plane", "sík"),
    ("light", "fény"),
    ("vertex", "csúcs"),
    ("worst", "legrosszabb"),
    ("found", "(keresett)"),
    ("course", "kurzus"),
    ("diffuse", "diffúz"),
    ("surface", "felület"),
    ("spectral", "spektrális"),
    ("wavelengths", "hullámhossz"),
    ("integral", "integrál"),
    ("matrix", "mátrix"),
    ("seed", "mag"),
    ("scene", "jelenet"),
    ("exact", "pontos"),
    ("case", "eset"),
    ("law", "törvény"),
    ("pair", "pár"),
    ("floats", "lebegőpontos"),
    ("reals", "valós"),
    ("near", "közeli"),
    ("black", "fekete"),
    ("red", "piros"),
    ("yellow", "sárga"),
    ("primaries", "alapszínek"),
    ("ptracer", "fénykövető"),
    ("integrator", "integrátor"),
    ("local", "helyi"),
    ("path", "útkövető"),
    ("photon", "fotontérkép"),
    ("fresnel", "Fresnel"),
    ("schlick-rarer", "Schlick (a ritkább oldal szögével)"),
    ("whitted", "Whitted"),
    ("box", "doboz"),
    ("fixed", "rögzített"),
    ("scaled", "skálázott"),
    ("precision", "pontosság"),
];

/// Words and symbols a label keeps as they are: names, channels, units.
const KEPT: &[&str] = &[
    "R",
    "G",
    "B",
    "RGB",
    "CIE",
    "Lab",
    "n",
    "κ",
    "d",
    "m",
    "nm",
    "px",
    "spp",
    "cos",
    "eta",
    "kappa",
    "ColorChecker",
    "Sharma",
    "Schlick",
    "Mitsuba",
    "×",
    "=",
    "−",
    "-",
];

/// `label` in Hungarian, or `None` where a word of it is not in the
/// vocabulary.
pub fn hungarian(label: &str) -> Option<String> {
    let mut text = label.to_owned();
    for (en, hu) in PHRASES {
        text = text.replace(en, hu);
    }
    if let Some((left, right)) = text.split_once(" against ") {
        let (_, hu) = AGAINST.iter().find(|(en, _)| *en == right)?;
        return Some(format!("{} {hu}", words(left)?));
    }
    words(&text)
}

/// `label` in Hungarian, or as it is where a word of it is not in the
/// vocabulary (inside a sentence that is Hungarian around it).
pub fn in_hungarian(label: &str) -> String {
    hungarian(label).unwrap_or_else(|| label.to_owned())
}

/// `text` word by word; `at` becomes the comma it means (`silver at 75°`,
/// `ezüst, 75°`).
fn words(text: &str) -> Option<String> {
    let mut out: Vec<String> = Vec::new();
    for token in text.split(' ') {
        if token == "at" {
            if let Some(last) = out.last_mut() {
                last.push(',');
            }
            continue;
        }
        let core = token.trim_matches(|c: char| ",:;()".contains(c));
        let hu = match WORDS.iter().find(|(en, _)| *en == core) {
            Some((_, hu)) => *hu,
            None if kept(core) => core,
            None => return None,
        };
        out.push(token.replacen(core, hu, 1));
    }
    Some(out.join(" "))
}

/// A symbol, a number or an identifier (`cos=0.3`, `R_p`, `41deg`), or a
/// word the label keeps ([`KEPT`]); not a word to put into Hungarian.
fn kept(core: &str) -> bool {
    KEPT.contains(&core)
        || !core.chars().any(char::is_alphabetic)
        || core.contains(|c: char| c.is_ascii_digit() || "_=|+#[]\"/".contains(c))
        || (core.chars().count() == 1)
        || PHRASES.iter().any(|(_, hu)| hu.contains(core))
}

#[cfg(test)]
mod tests {
    use super::hungarian;

    #[test]
    fn the_labels_of_the_cases_read_in_hungarian() {
        let cases = [
            ("glass inside critical +1ulp", "üveg belül határszög +1ulp"),
            ("pixel (42, 13) R", "képpont (42, 13) R"),
            ("silver at 75°", "ezüst, 75°"),
            (
                "diffuse B against area",
                "diffúz B a felületi fényekhez mérve",
            ),
            ("the image's mean, G", "a kép átlaga, G"),
            ("3480 pixels", "3480 képpont"),
            ("", ""),
        ];
        for (en, hu) in cases {
            assert_eq!(hungarian(en).as_deref(), Some(hu), "{en}");
        }
    }

    #[test]
    fn a_label_with_a_word_outside_the_vocabulary_has_no_hungarian() {
        assert_eq!(hungarian("glass beyond critical"), None);
        assert_eq!(hungarian("diffuse R against something"), None);
    }
}
