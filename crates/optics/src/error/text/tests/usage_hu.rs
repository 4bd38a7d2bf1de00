//! The argument parser's errors under `--lang hu`, one of each kind the
//! parser reports: the Hungarian message, clap's tip and usage line kept
//! in Hungarian, and no English word beyond the names they quote.

use clap::CommandFactory;
use record::Lang;

use crate::error::usage_rendered;
use record::english::{command_names, english_left, words};

/// The parser's error for `args` (after `optics --lang hu`), as the
/// Hungarian parser reports it, in both languages.
fn refused(args: &[&str]) -> (String, String) {
    let command = crate::lang::help::hungarian(crate::Cli::command());
    let line = ["optics", "--lang", "hu"].iter().chain(args);
    let error = match command.try_get_matches_from(line) {
        Err(error) => error,
        Ok(_) => panic!("{args:?} parses"),
    };
    assert_eq!(error.exit_code(), 2, "{args:?}");
    // The English, as `--lang en` has it, from the English command.
    let english = crate::Cli::command()
        .try_get_matches_from(["optics"].iter().chain(args))
        .expect_err("refused in English too");
    (
        usage_rendered(&english, Lang::En),
        usage_rendered(&error, Lang::Hu),
    )
}

/// A command line, the message that begins the error, and the tip and
/// the usage line it shows, if any.
type Case = (
    &'static [&'static str],
    &'static str,
    Option<&'static str>,
    Option<&'static str>,
);

/// A case per kind of error.
const CASES: &[Case] = &[
    (
        &["rendr"],
        "hiba: ismeretlen alparancs: 'rendr'\n",
        Some("  tipp: van hasonló alparancs: 'render'\n"),
        Some("Használat: optics [KAPCSOLÓK] <ALPARANCS>\n"),
    ),
    (
        &["reflect", "--wii", "0,0,1", "--normal", "0,0,1"],
        "hiba: váratlan argumentum: '--wii'\n",
        Some("  tipp: van hasonló kapcsoló: '--wi'\n"),
        Some("Használat: optics reflect [KAPCSOLÓK] --wi <WI> --normal <NORMAL>\n"),
    ),
    (
        &["quiz", "f0"],
        "hiba: hiányzik a kötelező argumentum:\n  --n <N>\n",
        None,
        Some("Használat: optics quiz f0 [KAPCSOLÓK] --n <N>\n"),
    ),
    (
        &[
            "fresnel", "--eta", "1.5", "--cos-i", "1", "--model", "schlik",
        ],
        "hiba: hibás parancssori argumentum (--model <MODEL>): érvénytelen érték: 'schlik'\n  \
         [lehetséges értékek: exact, schlick-incident, schlick-rarer, course]\n",
        Some("  tipp: van hasonló érték: 'schlick-rarer'\n"),
        None,
    ),
    (
        &[
            "fresnel",
            "--theta-i-deg",
            "60",
            "--cos-i",
            "0.5",
            "--eta",
            "1.33",
        ],
        "hiba: '--theta-i-deg <THETA_I_DEG>' nem adható meg együtt ezzel: '--cos-i <COS_I>'\n",
        None,
        Some(
            "Használat: optics fresnel [KAPCSOLÓK] <--cos-i <COS_I>|--theta-i-deg <THETA_I_DEG>> <--eta <ETA>|--metal <METAL>>\n",
        ),
    ),
    (
        &["quiz", "critical-angle", "--n", "1,4"],
        "hiba: hibás parancssori argumentum (--n <N>): érvénytelen érték: '1,4' (nem szám)\n",
        Some("  tipp: a számokban tizedespont áll, nem vessző: 1.4\n"),
        None,
    ),
    (
        &["tradeoff", "s.json", "--min-seconds=-1"],
        "hiba: hibás parancssori argumentum (--min-seconds <MIN_SECONDS>): érvénytelen érték: \
         '-1' (a(z) -1 nem 0 és 60 másodperc közé esik)",
        None,
        None,
    ),
    (
        &["tradeoff", "s.json", "--min-seconds", "0,5"],
        "hiba: hibás parancssori argumentum (--min-seconds <MIN_SECONDS>): érvénytelen érték: \
         '0,5' (nem szám)",
        Some("tipp: a számokban tizedespont áll, nem vessző: 0.5"),
        None,
    ),
    (
        &["render", "s.json", "-o", "s.png", "--spp", "0"],
        "hiba: hibás parancssori argumentum (--spp <SPP>): érvénytelen érték: '0' \
         (a megengedett tartományon kívül esik: 1..=",
        None,
        None,
    ),
];

#[test]
fn parser_errors_are_hungarian_with_their_tip_and_usage() {
    for &(args, message, tip, usage) in CASES {
        let (en, hu) = refused(args);
        assert!(hu.starts_with(message), "{args:?}:\n{hu}");
        for part in [tip, usage].into_iter().flatten() {
            assert!(hu.contains(part), "{args:?}: no {part:?} in\n{hu}");
        }
        assert!(hu.ends_with("\n\nBővebben: '--help'.\n"), "{args:?}:\n{hu}");
        let names = command_names(&crate::Cli::command());
        let left = english_left(&hu, &words(&en), &names);
        assert!(left.is_empty(), "{args:?}: English {left:?} left in\n{hu}");
    }
}

/// The English stays clap's own rendering, word for word.
#[test]
fn parser_errors_in_english_are_clap_own() {
    let error = crate::Cli::command()
        .try_get_matches_from(["optics", "rendr"])
        .unwrap_err();
    assert_eq!(usage_rendered(&error, Lang::En), error.render().to_string());
}
