//! Every error kind walked in both languages. That each kind has both
//! texts the compiler sees (`super`); these check what it cannot: each
//! text is there and differs from the other, and the Hungarian has no
//! English left but the names, numbers and other programs' messages it
//! quotes.

#[cfg(feature = "harness")]
use crate::error::HarnessKind;
use crate::error::{Error, ErrorKind};
use clap::Parser;
use radiometry::domain::{self, DomainError, Expected};
use record::english::{english_left, words};
use record::Lang;
use std::collections::BTreeSet;
#[cfg(feature = "harness")]
use validation::tradeoff::error::BudgetError;

#[cfg(feature = "harness")]
mod compare_kinds;
#[cfg(feature = "harness")]
mod harness_kinds;
#[cfg(feature = "harness")]
mod jobs_kinds;
mod render_kinds;
mod usage_hu;

/// The operating system's message that examples quote.
fn os_error() -> std::io::Error {
    std::io::Error::other("no space left on device")
}

/// The names a message is expected to quote verbatim.
fn named(names: &[&str]) -> Vec<String> {
    names.iter().map(|&name| name.to_owned()).collect()
}

/// One example of every kind, each with the text it quotes verbatim in
/// both languages: the names the user wrote, and messages from outside the
/// suite (serde's, the operating system's).
fn every_kind() -> Vec<(Error, Vec<String>)> {
    let usage = |args: &[&str]| match crate::Cli::try_parse_from(args) {
        Err(error) => error,
        Ok(_) => panic!("{args:?} parses"),
    };
    let foreign = ["optics", "fresnel", "--eta", "glass", "--cos-i", "1"];
    let foreign_usage = usage(&foreign);
    let our_usage = usage(&["optics", "reflect", "--wi", "0,1", "--normal", "0,0,1"]);
    let json_error = || serde_json::from_str::<serde_json::Value>("{").unwrap_err();
    let named = |name: &str| vec![name.to_owned()];
    let named_all = |names: &[&str]| names.iter().map(|&n| n.to_owned()).collect::<Vec<_>>();
    let laws = crate::law_table::LAWS.join(", ");
    let mut kinds: Vec<(ErrorKind, Vec<String>)> = vec![
        (
            DomainError::NotFinite {
                name: "--eta".into(),
                value: f64::NAN,
            }
            .into(),
            named("--eta"),
        ),
        (
            DomainError::ZeroVector {
                name: "--light-dir".into(),
                x: 0.0,
                y: 0.0,
                z: 0.0,
            }
            .into(),
            named("--light-dir"),
        ),
        (
            ErrorKind::Usage(foreign_usage),
            vec!["--eta <ETA>".into(), "glass".into()],
        ),
        (ErrorKind::Usage(our_usage), named("--wi <WI>")),
        (ErrorKind::VectorParts { count: 2 }, vec![]),
        (
            ErrorKind::VectorComponent {
                axis: "y",
                text: "x".into(),
            },
            vec![],
        ),
        (
            ErrorKind::AngleDegrees {
                name: "--theta-i-deg".into(),
                value: 200.0,
            },
            named("--theta-i-deg"),
        ),
        (
            ErrorKind::CosineOrAngle {
                cosine: "cos_i".into(),
                angle: "theta_i_deg".into(),
            },
            vec!["cos_i".into(), "theta_i_deg".into()],
        ),
        (
            ErrorKind::IndexOrMetal {
                eta: "--eta".into(),
                kappa: "--kappa".into(),
                metal: "--metal".into(),
            },
            vec!["--eta".into(), "--kappa".into(), "--metal".into()],
        ),
        (
            ErrorKind::EmptyList {
                name: "cos_i".into(),
            },
            named("cos_i"),
        ),
        (
            ErrorKind::ConductorFromInside {
                name: "--cos-i".into(),
                cos_i: -0.5,
                degrees: None,
            },
            named("--cos-i"),
        ),
        (
            ErrorKind::ConductorFromInside {
                name: "--theta-i-deg".into(),
                cos_i: -0.5,
                degrees: Some(120.0),
            },
            named("--theta-i-deg"),
        ),
        (
            ErrorKind::NoCriticalAngle {
                name: "--n".into(),
                n: 0.5,
                name_outside: "--n-outside".into(),
                n_outside: 1.0,
            },
            vec!["--n-outside".into(), "--n".into()],
        ),
        (
            ErrorKind::SchlickFormUnnamed {
                name: "--model".into(),
            },
            vec![
                "--model".into(),
                "schlick-incident".into(),
                "schlick-rarer".into(),
                "schlick".into(),
            ],
        ),
        (ErrorKind::EmptyLine, vec![]),
        (
            ErrorKind::MalformedJson {
                error: json_error(),
                non_finite: false,
            },
            vec![json_error().to_string()],
        ),
        (ErrorKind::NotAnObject, vec![]),
        (ErrorKind::LawMissing, vec![]),
        (ErrorKind::LawNotString, vec![]),
        (
            ErrorKind::UnknownLaw {
                law: "teleport".into(),
                expected: crate::law_table::LAWS,
            },
            vec![laws, "teleport".into()],
        ),
        (
            ErrorKind::Request {
                path: Some("eta".into()),
                message: "invalid type".into(),
            },
            vec!["invalid type".into(), "eta".into()],
        ),
        (
            ErrorKind::Request {
                path: None,
                message: "missing field `eta`".into(),
            },
            vec!["missing field `eta`".into()],
        ),
        (
            ErrorKind::ReadLine {
                line: 3,
                source: os_error(),
            },
            vec![os_error().to_string()],
        ),
        (ErrorKind::Write(os_error()), vec![os_error().to_string()]),
        (ErrorKind::NotUtf8 { column: 7 }, vec![]),
        (ErrorKind::LineTooLong { limit: 1024 }, vec![]),
        (
            ErrorKind::Overflow {
                quantity: "L_ref",
                inputs: vec!["--radiance".into(), "--kd".into()],
            },
            vec!["L_ref".into(), "--radiance, --kd".into()],
        ),
        (
            ErrorKind::Encode(json_error()),
            vec![json_error().to_string()],
        ),
        (
            ErrorKind::Errata(::errata::LookupError::UnknownId {
                id: "003-teleport".into(),
            }),
            vec![
                "ID".into(),
                "\"003-teleport\"".into(),
                "optics errata".into(),
            ],
        ),
        (
            ErrorKind::Errata(::errata::LookupError::UnknownClass {
                class: "severe".into(),
            }),
            named_all(&["--class", "\"severe\"", "physics", "picture", "cosmetic"]),
        ),
    ];
    kinds.extend(render_kinds::examples());
    #[cfg(feature = "harness")]
    kinds.extend(harness_kinds::examples());
    #[cfg(feature = "harness")]
    kinds.extend(compare_kinds::examples());
    #[cfg(feature = "harness")]
    kinds.extend(jobs_kinds::examples());
    for expected in Expected::ALL {
        let error = DomainError::OutOfRange {
            name: "--eta".into(),
            value: -1.0,
            expected,
        };
        kinds.push((error.into(), named("--eta")));
    }
    kinds
        .into_iter()
        .map(|(kind, quoted)| (kind.into(), quoted))
        .collect()
}

impl From<DomainError> for ErrorKind {
    fn from(error: DomainError) -> Self {
        ErrorKind::Domain(error)
    }
}

/// The place of a kind in [`SLOTS`]: an exhaustive match, so a new kind
/// stops the build here until it is given a slot, and the walk then fails
/// until [`every_kind`] has an example of it.
fn slot(kind: &ErrorKind) -> usize {
    match kind {
        ErrorKind::Domain(DomainError::NotFinite { .. }) => 0,
        ErrorKind::Domain(DomainError::OutOfRange { .. }) => 1,
        ErrorKind::Domain(DomainError::ZeroVector { .. }) => 2,
        ErrorKind::Usage(_) => 3,
        ErrorKind::VectorParts { .. } => 4,
        ErrorKind::VectorComponent { .. } => 5,
        ErrorKind::AngleDegrees { .. } => 6,
        ErrorKind::CosineOrAngle { .. } => 7,
        ErrorKind::ConductorFromInside { .. } => 8,
        ErrorKind::NoCriticalAngle { .. } => 9,
        ErrorKind::EmptyLine => 10,
        ErrorKind::MalformedJson { .. } => 11,
        ErrorKind::NotAnObject => 12,
        ErrorKind::LawMissing => 13,
        ErrorKind::LawNotString => 14,
        ErrorKind::UnknownLaw { .. } => 15,
        ErrorKind::Request { .. } => 16,
        ErrorKind::ReadLine { .. } => 17,
        ErrorKind::Write(_) => 18,
        ErrorKind::Encode(_) => 19,
        ErrorKind::NotUtf8 { .. } => 20,
        ErrorKind::Overflow { .. } => 21,
        ErrorKind::LineTooLong { .. } => 22,
        ErrorKind::SchlickFormUnnamed { .. } => 23,
        ErrorKind::Errata(::errata::LookupError::UnknownId { .. }) => 24,
        ErrorKind::Errata(::errata::LookupError::UnknownClass { .. }) => 25,
        ErrorKind::IndexOrMetal { .. } => 26,
        ErrorKind::EmptyList { .. } => 27,
        ErrorKind::Scene { error, .. } => CALCULATOR + render_kinds::scene_slot(error.kind()),
        ErrorKind::Output(error) => CALCULATOR + render_kinds::output_slot(error),
        ErrorKind::Threads(_) => CALCULATOR + render_kinds::THREADS,
        ErrorKind::RadianceNotFinite { .. } => CALCULATOR + render_kinds::NOT_FINITE,
        #[cfg(feature = "harness")]
        ErrorKind::Harness(HarnessKind::Checkout(error))
        | ErrorKind::Harness(HarnessKind::CheckoutWithFlag(error)) => {
            CALCULATOR + render_kinds::SLOTS + harness_kinds::checkout_slot(error)
        }
        #[cfg(feature = "harness")]
        ErrorKind::Harness(HarnessKind::Pipeline(error)) => {
            CALCULATOR + render_kinds::SLOTS + harness_kinds::pipeline_slot(error)
        }
        #[cfg(feature = "harness")]
        ErrorKind::Harness(HarnessKind::ChecksFailed { .. }) => {
            CALCULATOR + render_kinds::SLOTS + harness_kinds::CHECKS_FAILED
        }
        #[cfg(feature = "harness")]
        ErrorKind::Harness(HarnessKind::Plot(_)) => {
            CALCULATOR + render_kinds::SLOTS + harness_kinds::PLOT
        }
        #[cfg(feature = "harness")]
        ErrorKind::Harness(HarnessKind::NoPlotPython { .. }) => {
            CALCULATOR + render_kinds::SLOTS + harness_kinds::NO_PLOT_PYTHON
        }
        #[cfg(feature = "harness")]
        ErrorKind::Harness(HarnessKind::TruthIsBlack { .. }) => {
            CALCULATOR + render_kinds::SLOTS + harness_kinds::TRUTH_IS_BLACK
        }
        #[cfg(feature = "harness")]
        ErrorKind::Harness(HarnessKind::Budget(BudgetError::Unreachable { .. })) => {
            CALCULATOR + render_kinds::SLOTS + harness_kinds::BUDGET_UNREACHABLE
        }
        #[cfg(feature = "harness")]
        ErrorKind::Harness(HarnessKind::Budget(BudgetError::PilotNoisy { .. })) => {
            CALCULATOR + render_kinds::SLOTS + harness_kinds::BUDGET_PILOT_NOISY
        }
        #[cfg(feature = "harness")]
        ErrorKind::Harness(HarnessKind::Budget(BudgetError::EnergyGain { .. })) => {
            CALCULATOR + render_kinds::SLOTS + harness_kinds::BUDGET_ENERGY_GAIN
        }
        #[cfg(feature = "harness")]
        ErrorKind::Harness(HarnessKind::Compare(error)) => {
            CALCULATOR
                + render_kinds::SLOTS
                + harness_kinds::SLOTS
                + compare_kinds::compare_slot(error)
        }
        #[cfg(feature = "harness")]
        ErrorKind::Harness(HarnessKind::Jobs(error)) => {
            CALCULATOR
                + render_kinds::SLOTS
                + harness_kinds::SLOTS
                + compare_kinds::SLOTS
                + jobs_kinds::jobs_slot(error)
        }
    }
}

/// The calculator's own kinds' slots.
const CALCULATOR: usize = 28;

#[cfg(feature = "harness")]
const SLOTS: usize = CALCULATOR
    + render_kinds::SLOTS
    + harness_kinds::SLOTS
    + compare_kinds::SLOTS
    + jobs_kinds::SLOTS;
#[cfg(not(feature = "harness"))]
const SLOTS: usize = CALCULATOR + render_kinds::SLOTS;

#[test]
fn every_kind_has_an_example_and_a_name_of_its_own() {
    let mut seen = [false; SLOTS];
    let mut names = BTreeSet::new();
    for (error, _) in every_kind() {
        seen[slot(error.kind())] = true;
        names.insert(error.kind().name());
    }
    let missing: Vec<usize> = (0..SLOTS).filter(|&i| !seen[i]).collect();
    assert!(
        missing.is_empty(),
        "no example of the kinds in slots {missing:?}"
    );
    assert_eq!(names.len(), SLOTS, "two kinds share a name: {names:?}");
}

#[test]
fn every_kind_is_worded_in_both_languages() {
    for (error, _) in every_kind() {
        let (en, hu) = (error.message(Lang::En), error.message(Lang::Hu));
        let name = error.kind().name();
        assert!(!en.trim().is_empty(), "{name}: no English");
        assert!(!hu.trim().is_empty(), "{name}: no Hungarian");
        assert_ne!(en, hu, "{name}: the Hungarian is the English");
    }
}

#[test]
fn hungarian_messages_have_no_english_left() {
    for (error, quoted) in every_kind() {
        let (mut en, mut hu) = (error.message(Lang::En), error.message(Lang::Hu));
        for text in &quoted {
            assert!(hu.contains(text.as_str()), "{hu:?} does not quote {text:?}");
            en = en.replace(text.as_str(), " ");
            hu = hu.replace(text.as_str(), " ");
        }
        let left = english_left(&hu, &words(&en), &BTreeSet::new());
        assert!(
            left.is_empty(),
            "{:?}: English {left:?} left in {hu:?}",
            error.kind().name()
        );
    }
}

#[test]
fn the_json_error_names_its_kind_and_field() {
    let error = Error::from(domain::refractive_index("--eta", -1.0).unwrap_err());
    assert_eq!(
        error.to_json(Lang::Hu),
        serde_json::json!({
            "kind": "domain.out_of_range",
            "field": "--eta",
            "message": "--eta: pozitív törésmutatónak kell lennie, kapott érték: -1",
        })
    );
    assert_eq!(
        error.message(Lang::En),
        "--eta must be a positive refractive index, got -1"
    );
    let line = Error::from(ErrorKind::EmptyLine).to_json(Lang::En);
    assert_eq!(line["field"], serde_json::Value::Null);
}

#[test]
fn a_render_error_becomes_the_kind_of_what_failed() {
    let output = tracer::output::OutputError::PfmIsPng {
        path: "a.pfm".into(),
    };
    let error = Error::from(tracer::job::RenderError::Output(output));
    assert_eq!(error.kind().name(), "output.pfm_is_png");
    assert_eq!(error.field().as_deref(), Some("--output"));
    let threads = render_kinds::thread_pool_error();
    let error = Error::from(tracer::job::RenderError::Threads(threads));
    assert_eq!(error.kind().name(), "threads");
}
