//! Bad input: refused by name, typed, in the chosen language, without a panic.

use crate::common::{optics, stderr, stdout};
use serde_json::Value;

/// Bad input: a message naming the argument, a non-zero exit, no panic.
#[test]
fn bad_input_is_refused_by_name_without_a_panic() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["fresnel", "--eta", "glass", "--cos-i", "0.3"],
            "'--eta <ETA>'",
        ),
        (
            &["fresnel", "--eta", "NaN", "--cos-i", "0.3"],
            "--eta must be a finite number",
        ),
        (
            &["fresnel", "--eta", "-1.5", "--cos-i", "0.3"],
            "--eta must be a positive refractive index",
        ),
        (
            &["fresnel", "--eta", "0", "--cos-i", "0.3"],
            "--eta must be a positive refractive index",
        ),
        (
            &["fresnel", "--eta", "1.5", "--kappa", "-1", "--cos-i", "0.3"],
            "--kappa must be a non-negative",
        ),
        (
            &["fresnel", "--eta", "1e60", "--cos-i", "0.3"],
            "--eta must be a refractive index from 1e-50 to 1e50, got 1e60",
        ),
        (
            &[
                "fresnel", "--eta", "1.5", "--kappa", "1e-300", "--cos-i", "0.3",
            ],
            "--kappa must be an extinction coefficient of 0 or from 1e-50 to 1e50",
        ),
        (
            &["fresnel", "--eta", "1.5", "--cos-i", "1.0001"],
            "--cos-i must be in [-1, 1]",
        ),
        (
            &["fresnel", "--eta", "1.5", "--cos-i", "-2"],
            "--cos-i must be in [-1, 1]",
        ),
        (
            &["fresnel", "--eta", "1.5", "--theta-i-deg", "200"],
            "--theta-i-deg must be an angle in [0, 180]",
        ),
        (&["fresnel", "--eta", "1.5"], "--cos-i"),
        (
            &["fresnel", "--eta", "0.2", "--kappa", "3", "--cos-i", "-0.5"],
            "--cos-i must be ≥ 0 for a conductor",
        ),
        (
            &[
                "refract", "--wi", "0,0,0", "--normal", "0,0,1", "--eta", "1.5",
            ],
            "--wi must be a non-zero direction",
        ),
        (
            &[
                "refract", "--wi", "0,1,1", "--normal", "0,inf,1", "--eta", "1.5",
            ],
            "--normal.y must be a finite number",
        ),
        (
            &["reflect", "--wi", "0,1", "--normal", "0,0,1"],
            "'--wi <WI>'",
        ),
        (
            &["reflect", "--wi", "0,1,1", "--normal", "0,-0,0"],
            "--normal must be a non-zero direction",
        ),
        (
            &[
                "shade",
                "--normal",
                "0,0,1",
                "--light-dir",
                "0,0,1",
                "--view-dir",
                "0,0,1",
                "--radiance",
                "-5",
            ],
            "--radiance must be non-negative",
        ),
        (
            &["quiz", "f0", "--n", "-1.4"],
            "--n must be a positive refractive index",
        ),
        (
            &["quiz", "critical-angle", "--n", "0.5"],
            "no critical angle",
        ),
        (
            &[
                "quiz",
                "lambert",
                "--normal",
                "0,0,0",
                "--light-dir",
                "0,3,4",
                "--view-dir",
                "1,2,3",
                "--radiance",
                "5",
                "--kd",
                "0.6",
            ],
            "--normal must be a non-zero direction",
        ),
    ];
    for (args, message) in cases {
        let output = optics(args);
        let err = stderr(&output);
        assert!(!output.status.success(), "optics {args:?} succeeded");
        assert!(
            err.contains(message),
            "optics {args:?}: {err:?} lacks {message:?}"
        );
        assert!(!err.contains("panicked"), "optics {args:?} panicked: {err}");
    }
}

/// A refused command line, with the JSON error it must print: arguments,
/// kind, field, a phrase of the message, exit status.
type JsonErrorCase<'a> = (&'a [&'a str], &'a str, Option<&'a str>, &'a str, i32);

#[test]
fn json_errors_are_typed_objects_naming_the_field() {
    let cases: &[JsonErrorCase] = &[
        (
            &["fresnel", "--eta", "-1", "--cos-i", "0.3"],
            "domain.out_of_range",
            Some("--eta"),
            "--eta must be a positive refractive index",
            1,
        ),
        (
            &["fresnel", "--eta", "1.5", "--theta-i-deg", "200"],
            "angle_degrees",
            Some("--theta-i-deg"),
            "an angle in [0, 180] degrees",
            1,
        ),
        (
            &["quiz", "critical-angle", "--n", "0.5"],
            "no_critical_angle",
            Some("--n"),
            "no critical angle",
            1,
        ),
        (
            &[
                "fresnel", "--eta", "1.5", "--cos-i", "0.3", "--model", "schlick",
            ],
            "schlick_form_unnamed",
            Some("--model"),
            "--model: \"schlick\" names neither of Schlick's forms: give \"schlick-incident\"",
            1,
        ),
        (
            &["fresnel", "--eta", "glass", "--cos-i", "0.3"],
            "usage",
            Some("--eta <ETA>"),
            "invalid value 'glass'",
            2,
        ),
        (
            &["reflect", "--wi", "0,1", "--normal", "0,0,1"],
            "usage",
            Some("--wi <WI>"),
            "got 2 part(s)",
            2,
        ),
    ];
    for (args, kind, field, message, status) in cases {
        let mut all = vec!["--json"];
        all.extend_from_slice(args);
        let output = optics(&all);
        assert_eq!(output.status.code(), Some(*status), "optics {all:?}");
        let printed: Value = serde_json::from_str(stdout(&output).trim())
            .unwrap_or_else(|e| panic!("optics {all:?}: no JSON error object ({e})"));
        let error = &printed["error"];
        assert_eq!(error["kind"], *kind, "optics {all:?}: {printed}");
        assert_eq!(error["field"].as_str(), *field, "optics {all:?}: {printed}");
        let text = error["message"].as_str().expect("a message");
        assert!(
            text.contains(message),
            "optics {all:?}: {text:?} lacks {message:?}"
        );
    }
}

/// Through the binary, a few of every family of kinds in Hungarian: the
/// suite's own messages wholly translated, the argument parser's written
/// in Hungarian behind a lead-in naming the argument (the first line of
/// what stderr shows).
#[test]
fn hungarian_errors_leave_no_english_of_the_suites_own() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["fresnel", "--eta", "1e60", "--cos-i", "0.3"],
            "hiba: --eta: 1e-50 és 1e50 közötti törésmutatónak kell lennie, kapott érték: 1e60",
        ),
        (
            &["fresnel", "--eta", "0.2", "--kappa", "3", "--cos-i", "-0.5"],
            "hiba: --cos-i: vezetőnél (kappa > 0) ≥ 0 kell legyen: fény nem érkezhet fém belsejéből, kapott érték: -0.5",
        ),
        (
            &["quiz", "critical-angle", "--n", "0.5"],
            "hiba: --n = 0.5 nem nagyobb, mint --n-outside = 1: sűrűbb (vagy azonos) közegbe lépő fény mindig megtörik, nincs határszög",
        ),
        (
            &["fresnel", "--eta", "1.5", "--cos-i", "0.3", "--model", "schlick"],
            "hiba: --model: a \"schlick\" Schlick két alakja közül egyiket sem nevezi meg: \
             \"schlick-incident\" (a beesési szög koszinusza, ahogy a kurzus írja; nem ismeri a \
             teljes visszaverődést) vagy \"schlick-rarer\" (a ritkább közegbeli szög \
             koszinusza; a teljes visszaverődés helyes) adható meg",
        ),
        (
            &["reflect", "--wi", "0,1", "--normal", "0,0,1"],
            "hiba: hibás parancssori argumentum (--wi <WI>): három vesszővel elválasztott számot kell megadni (például 0,3,4), kapott részek száma: 2",
        ),
        (
            &["fresnel", "--eta", "glass", "--cos-i", "0.3"],
            "hiba: hibás parancssori argumentum (--eta <ETA>): érvénytelen érték: 'glass' (nem szám)",
        ),
    ];
    for (args, message) in cases {
        let mut all = vec!["--lang", "hu"];
        all.extend_from_slice(args);
        let output = optics(&all);
        assert!(!output.status.success(), "optics {all:?} succeeded");
        let text = stderr(&output);
        assert_eq!(text.lines().next(), Some(*message), "optics {all:?}");
    }
    let batch = crate::common::batch_in(&["--lang", "hu"], "not json\n");
    let error = &batch.0[0]["error"];
    assert_eq!(error["kind"], "malformed_json");
    let text = error["message"].as_str().expect("a message");
    assert!(text.starts_with("hibás JSON: "), "{text}");
}

/// Light from inside a metal is refused in the quantity the user gave:
/// an angle past 90° is named as an angle (not as the cosine it makes,
/// -0.4999999999999998 for 120°), a negative cosine as a cosine.
#[test]
fn a_conductor_lit_from_inside_is_refused_in_the_quantity_given() {
    let metal = ["fresnel", "--eta", "0.17", "--kappa", "3.1"];
    let angle = optics(&[&metal[..], &["--theta-i-deg", "120"]].concat());
    assert_eq!(angle.status.code(), Some(1));
    let text = stderr(&angle);
    assert!(
        text.contains("--theta-i-deg must be at most 90 degrees for a conductor")
            && text.contains("got 120"),
        "{text}"
    );
    assert!(!text.contains("-0.49"), "{text}");
    let cosine = optics(&[&metal[..], &["--cos-i", "-0.5"]].concat());
    let text = stderr(&cosine);
    assert!(
        text.contains("--cos-i must be ≥ 0 for a conductor") && text.contains("got -0.5"),
        "{text}"
    );
}

/// `fresnel` without an angle asks for either form of it, not for the
/// cosine alone: the usage names `--cos-i` and `--theta-i-deg` as one
/// choice, and both given are refused.
#[test]
fn fresnel_without_an_incidence_asks_for_either_form() {
    let missing = optics(&["fresnel", "--eta", "1.5"]);
    assert_eq!(missing.status.code(), Some(2));
    let text = stderr(&missing);
    assert!(
        text.contains("<--cos-i <COS_I>|--theta-i-deg <THETA_I_DEG>>"),
        "{text}"
    );
    let both = optics(&[
        "fresnel",
        "--eta",
        "1.5",
        "--cos-i",
        "1",
        "--theta-i-deg",
        "3",
    ]);
    assert_eq!(both.status.code(), Some(2));
    assert!(
        stderr(&both).contains("cannot be used with"),
        "{}",
        stderr(&both)
    );
}

/// A number written with a decimal comma (`1,4`, as Hungarian students
/// write it) is refused with the advice to write `1.4`, in the parser's
/// text, in Hungarian and in the JSON error; a value that is not a number
/// either way gets no such advice.
#[test]
fn a_decimal_comma_is_refused_with_the_number_it_meant() {
    let english = optics(&["quiz", "critical-angle", "--n", "1,4"]);
    assert_eq!(english.status.code(), Some(2));
    let text = stderr(&english);
    assert!(
        text.contains("tip: numbers take a decimal point, not a comma: 1.4"),
        "{text}"
    );
    let hungarian = stderr(&optics(&[
        "--lang",
        "hu",
        "quiz",
        "critical-angle",
        "--n",
        "1,4",
    ]));
    assert!(
        hungarian.contains("a számokban tizedespont áll, nem vessző: 1.4"),
        "{hungarian}"
    );
    let json = optics(&["--json", "fresnel", "--eta", "1,5", "--cos-i", "1"]);
    let error: Value = serde_json::from_slice(&json.stdout).unwrap();
    let message = error["error"]["message"].as_str().unwrap();
    assert!(message.contains("not a comma: 1.5"), "{message}");
    let neither = stderr(&optics(&["quiz", "critical-angle", "--n", "1,4,5"]));
    assert!(!neither.contains("decimal point"), "{neither}");
}

/// Under `--lang hu` a command line that does not parse is refused in
/// Hungarian with clap's layout kept: the tip, the usage line, where to
/// read more, exit status 2, and with `--json` the error object.
#[test]
fn a_hungarian_parser_error_keeps_its_tip_and_usage() {
    let output = optics(&["--lang", "hu", "rendr"]);
    assert_eq!(output.status.code(), Some(2));
    assert_eq!(
        stderr(&output),
        "hiba: ismeretlen alparancs: 'rendr'\n\n  tipp: van hasonló alparancs: 'render'\n\n\
         Használat: optics [KAPCSOLÓK] <ALPARANCS>\n\nBővebben: '--help'.\n"
    );
    let json = optics(&["--json", "--lang", "hu", "rendr"]);
    assert_eq!(json.status.code(), Some(2));
    let error: Value = serde_json::from_slice(&json.stdout).unwrap();
    assert_eq!(error["error"]["kind"], "usage");
    assert_eq!(error["error"]["message"], "ismeretlen alparancs: 'rendr'");
}
