//! The `optics` binary, run as a user runs it: the course's quiz answers
//! with their rounding, the JSON record's fields, `optics batch`
//! round-tripping every law, and bad input refused by name without a panic.
//!
//! Declared as a test of the `optics` package (its `Cargo.toml`), so that
//! cargo builds the binary first and hands its path in `CARGO_BIN_EXE_optics`.

use serde_json::Value;
use std::io::Write;
use std::process::{Command, Output, Stdio};

fn optics(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(args)
        .output()
        .expect("the optics binary runs")
}

fn stdout(output: &Output) -> String {
    String::from_utf8(output.stdout.clone()).expect("stdout is UTF-8")
}

fn stderr(output: &Output) -> String {
    String::from_utf8(output.stderr.clone()).expect("stderr is UTF-8")
}

/// Runs with `--json`, expects success, returns the one JSON object printed.
fn json(args: &[&str]) -> Value {
    let mut all = vec!["--json"];
    all.extend_from_slice(args);
    let output = optics(&all);
    assert!(
        output.status.success(),
        "optics {args:?} failed: {}",
        stderr(&output)
    );
    serde_json::from_str(stdout(&output).trim()).expect("one JSON object")
}

fn batch(input: &str) -> (Vec<Value>, Output) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_optics"))
        .arg("batch")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the optics binary runs");
    child
        .stdin
        .take()
        .expect("stdin is piped")
        .write_all(input.as_bytes())
        .expect("stdin takes the requests");
    let output = child.wait_with_output().expect("optics batch finishes");
    let lines = stdout(&output)
        .lines()
        .map(|l| serde_json::from_str(l).expect("each output line is JSON"))
        .collect();
    (lines, output)
}

fn number(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("{v} is not a number"))
}

/// Every subcommand's `--json` record carries the documented fields.
fn assert_record_fields(record: &Value) {
    for field in ["law", "inputs", "answer", "unit", "steps"] {
        assert!(record.get(field).is_some(), "no {field:?} in {record}");
    }
    assert!(record["law"].is_string());
    assert!(record["inputs"].is_object());
    assert!(record["unit"].is_string());
    let steps = record["steps"].as_array().expect("steps is a list");
    assert!(!steps.is_empty() && steps.iter().all(Value::is_string));
}

// The course's quiz (`003`, "Kvíz"): the printed answers are 2.77 %, 2.4,
// 5.74° and 2.5; question 1 marks statements 1–5 true. Tolerances: the exact
// values are 1/36, 12/5, asin(1/10) and 5/2; 1e-12 covers the rounding of a
// dozen operations on numbers of order 1.

#[test]
fn quiz_seed_answers_every_question_with_correct_rounding() {
    let quiz = json(&["quiz", "seed"]);
    assert_record_fields(&quiz);
    let questions = quiz["details"]["questions"].as_array().expect("questions");
    assert_eq!(questions.len(), 5);

    let q1 = &questions[0];
    let verdicts: Vec<bool> = q1["answer"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_bool().unwrap())
        .collect();
    assert_eq!(
        verdicts,
        [true, false, true, true, true, false, false, false, false]
    );
    assert_eq!(
        q1["details"]["agrees_with_printed"], false,
        "statement 2 is printed true"
    );
    assert!(q1["notes"][0].as_str().unwrap().contains("irradiance"));

    let q2 = &questions[1];
    assert!((number(&q2["answer"]) - 1.0 / 36.0).abs() < 1e-12);
    assert_eq!(q2["details"]["agrees_with_printed"], false);
    let note = q2["notes"][0].as_str().unwrap();
    assert!(
        note.contains("truncated") && note.contains("2.78"),
        "{note}"
    );

    let q3 = &questions[2];
    assert!((number(&q3["answer"]) - 2.4).abs() < 1e-12);
    assert_eq!(q3["unit"], "W/(sr m^2)");
    assert_eq!(q3["details"]["agrees_with_printed"], true);

    let q4 = &questions[3];
    assert!((number(&q4["answer"]) - 0.1f64.asin().to_degrees()).abs() < 1e-12);
    assert_eq!(q4["unit"], "deg");
    assert_eq!(q4["details"]["agrees_with_printed"], true);

    let q5 = &questions[4];
    assert!((number(&q5["answer"]) - 2.5).abs() < 1e-12);
    assert_eq!(q5["details"]["agrees_with_printed"], true);
}

#[test]
fn quiz_seed_text_shows_the_working_and_the_corrected_rounding() {
    let output = optics(&["quiz", "seed"]);
    assert!(output.status.success());
    let text = stdout(&output);
    for expected in [
        "Question 1",
        "2.78 %",
        "the printed answer 2.77 % is truncated instead of rounded",
        "L_ref = f_r · E = 0.6 · 4 = 2.4",
        "θc = arcsin(0.1) = 5.73917°",
        "cos δ = N · H = 0.707107",
        "L_ref = f_r · E = 0.625 · 4 = 2.5",
    ] {
        assert!(text.contains(expected), "missing {expected:?} in\n{text}");
    }
}

#[test]
fn quiz_list_names_every_solver_with_an_example() {
    let text = stdout(&optics(&["quiz"]));
    for name in ["seed", "f0", "lambert", "critical-angle", "blinn-phong"] {
        assert!(
            text.contains(&format!("optics quiz {name}")),
            "no example for {name}"
        );
    }
}

#[test]
fn quiz_solvers_match_the_seed_answers() {
    // The quiz's exercises with the flags of ROUND_TRIP below; the last
    // passes ks = 1.41421356, √2 to 9 digits, so its 2.5 holds to 1e-8.
    let expected = [
        ("f0", 1.0 / 36.0, 1e-12),
        ("lambert", 2.4, 1e-12),
        ("critical_angle", 0.1f64.asin().to_degrees(), 1e-12),
        ("blinn_phong", 2.5, 1e-8),
    ];
    for (law, value, tolerance) in expected {
        let (_, args) = ROUND_TRIP
            .iter()
            .find(|(request, _)| request.contains(&format!("\"{law}\"")))
            .expect("a request for every quiz law");
        let record = json(args);
        assert_eq!(record["law"], law);
        assert!(
            (number(&record["answer"]) - value).abs() < tolerance,
            "{law}: {record}"
        );
    }
    let lambert = json(ROUND_TRIP[5].1);
    let steps = lambert["steps"].to_string();
    assert!(
        steps.contains("light_dir has length 5: normalised to (0, 0.6, 0.8)"),
        "{steps}"
    );
}

#[test]
fn law_evaluators_print_the_documented_json_record() {
    let glass = json(&["fresnel", "--eta", "1.5", "--theta-i-deg", "60"]);
    assert_record_fields(&glass);
    assert_eq!(glass["law"], "fresnel");
    assert_eq!(glass["unit"], "1");
    // Glass at 60°: cos θt = √(2/3) by Snell, and the textbook Fresnel
    // equations are well conditioned here (1e-15: a few roundings of 0.09).
    let (ci, ct) = (0.5f64, (2.0f64 / 3.0).sqrt());
    let r_s = ((ci - 1.5 * ct) / (ci + 1.5 * ct)).powi(2);
    let r_p = ((1.5 * ci - ct) / (1.5 * ci + ct)).powi(2);
    assert!((number(&glass["answer"]) - (r_s + r_p) / 2.0).abs() < 1e-15);
    // R_s, R_p and T come along in details.
    let d = &glass["details"];
    assert!((number(&d["r_s"]) + number(&d["r_p"]) - 2.0 * number(&glass["answer"])).abs() < 1e-15);
    assert!((number(&d["transmittance"]) + number(&glass["answer"]) - 1.0).abs() < 1e-15);

    let tir = json(&["fresnel", "--eta", "1.5", "--cos-i", "-0.5"]);
    assert_eq!(number(&tir["answer"]), 1.0);
    assert_eq!(tir["details"]["total_internal_reflection"], true);

    let schlick = json(&[
        "fresnel", "--eta", "1.5", "--cos-i", "1", "--model", "schlick",
    ]);
    assert!((number(&schlick["answer"]) - 0.04).abs() < 1e-15);
    assert!(schlick["details"]["exact"].is_number() && schlick["details"]["error"].is_number());

    let gold = json(&["fresnel", "--eta", "0.17", "--kappa", "3.1", "--cos-i", "1"]);
    let f0 = (0.83f64.powi(2) + 3.1f64.powi(2)) / (1.17f64.powi(2) + 3.1f64.powi(2));
    assert!((number(&gold["answer"]) - f0).abs() < 1e-15);

    let refracted = json(&[
        "refract",
        "--wi",
        "0,0.6,0.8",
        "--normal",
        "0,0,1",
        "--eta",
        "1.5",
    ]);
    assert_record_fields(&refracted);
    let t: Vec<f64> = refracted["answer"]
        .as_array()
        .unwrap()
        .iter()
        .map(number)
        .collect();
    // sin θt = 0.6 / 1.5 = 0.4 on the far side.
    assert!((t[1] + 0.4).abs() < 1e-15 && t[2] < 0.0);
    assert_eq!(refracted["details"]["outcome"], "refracted");

    let totally = json(&[
        "refract",
        "--wi",
        "0,0.8,-0.6",
        "--normal",
        "0,0,1",
        "--eta",
        "1.5",
    ]);
    assert!(totally["answer"].is_null());
    assert_eq!(totally["details"]["outcome"], "total_internal_reflection");

    let mirrored = json(&["reflect", "--wi", "0,3,4", "--normal", "0,0,2"]);
    assert_eq!(mirrored["answer"], serde_json::json!([0.0, -0.6, 0.8]));

    let shaded = json(&[
        "shade",
        "--model",
        "lambert",
        "--normal",
        "0,0,1",
        "--light-dir",
        "0,0,1",
        "--view-dir",
        "0,1,1",
        "--radiance",
        "2",
        "--kd",
        "0.5",
    ]);
    assert!((number(&shaded["answer"]) - 1.0 / std::f64::consts::PI).abs() < 1e-15);
}

/// One request per law, with its subcommand's flags.
const ROUND_TRIP: [(&str, &[&str]); 8] = [
    (
        r#"{"law": "fresnel", "eta": 1.5, "cos_i": 0.3}"#,
        &["fresnel", "--eta", "1.5", "--cos-i", "0.3"],
    ),
    (
        r#"{"law": "refract", "wi": [0, 0.6, 0.8], "normal": [0, 0, 1], "eta": 1.5}"#,
        &[
            "refract",
            "--wi",
            "0,0.6,0.8",
            "--normal",
            "0,0,1",
            "--eta",
            "1.5",
        ],
    ),
    (
        r#"{"law": "reflect", "wi": [1, 2, 3], "normal": [0, 0, 1]}"#,
        &["reflect", "--wi", "1,2,3", "--normal", "0,0,1"],
    ),
    (
        r#"{"law": "shade", "model": "blinn-phong-reciprocal", "normal": [0, 0, 1], "light_dir": [0, 3, 4], "view_dir": [0, 4, 3], "radiance": 5, "ks": 1.5, "shine": 3}"#,
        &[
            "shade",
            "--model",
            "blinn-phong-reciprocal",
            "--normal",
            "0,0,1",
            "--light-dir",
            "0,3,4",
            "--view-dir",
            "0,4,3",
            "--radiance",
            "5",
            "--ks",
            "1.5",
            "--shine",
            "3",
        ],
    ),
    (r#"{"law": "f0", "n": 1.4}"#, &["quiz", "f0", "--n", "1.4"]),
    (
        r#"{"law": "lambert", "normal": [0, 0, 1], "light_dir": [0, 3, 4], "view_dir": [1, 2, 3], "radiance": 5, "kd": 0.6}"#,
        &[
            "quiz",
            "lambert",
            "--normal",
            "0,0,1",
            "--light-dir",
            "0,3,4",
            "--view-dir",
            "1,2,3",
            "--radiance",
            "5",
            "--kd",
            "0.6",
        ],
    ),
    (
        r#"{"law": "critical_angle", "n": 10}"#,
        &["quiz", "critical-angle", "--n", "10"],
    ),
    (
        r#"{"law": "blinn_phong", "normal": [0, 0, 1], "light_dir": [0, 3, 4], "view_dir": [0, 4, 3], "radiance": 5, "ks": 1.41421356, "shine": 3}"#,
        &[
            "quiz",
            "blinn-phong",
            "--normal",
            "0,0,1",
            "--light-dir",
            "0,3,4",
            "--view-dir",
            "0,4,3",
            "--radiance",
            "5",
            "--ks",
            "1.41421356",
            "--shine",
            "3",
        ],
    ),
];

#[test]
fn batch_results_equal_the_subcommands_json_output() {
    let input: String = ROUND_TRIP
        .iter()
        .map(|(request, _)| format!("{request}\n"))
        .collect();
    let (results, output) = batch(&input);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(results.len(), ROUND_TRIP.len());
    for ((request, args), result) in ROUND_TRIP.iter().zip(&results) {
        assert_record_fields(result);
        assert_eq!(
            *result,
            json(args),
            "batch {request} differs from optics --json {args:?}"
        );
    }
}

#[test]
fn batch_reports_a_bad_line_and_goes_on_in_order() {
    let input = [
        r#"{"law": "fresnel", "eta": 1.5, "cos_i": 1}"#,
        r#"{"law": "fresnel", "eta": "glass", "cos_i": 1}"#,
        "not json",
        "",
        r#"{"law": "teleport", "eta": 1}"#,
        r#"{"eta": 1.5}"#,
        r#"{"law": "fresnel", "eta": 1.5, "cos_i": 1, "colour": "red"}"#,
        r#"{"law": "refract", "wi": [0, 0, 0], "normal": [0, 0, 1], "eta": 1.5}"#,
        r#"{"law": "fresnel", "eta": 1.5, "cos_i": 0.5}"#,
    ]
    .join("\n");
    let (results, output) = batch(&input);
    assert_eq!(output.status.code(), Some(1), "some lines failed");
    assert!(stderr(&output).contains("7 of 9 lines gave errors"));
    assert_eq!(results.len(), 9);
    assert!((number(&results[0]["answer"]) - 0.04).abs() < 1e-15);
    let expected = [
        (2, "eta: invalid type"),
        (3, "malformed JSON"),
        (4, "empty line"),
        (5, "unknown law \"teleport\""),
        (6, "law: missing"),
        (7, "unknown field `colour`"),
        (8, "wi must be a non-zero direction"),
    ];
    for (line, message) in expected {
        let result = &results[line - 1];
        assert_eq!(result["line"], line, "{result}");
        let error = result["error"]
            .as_str()
            .unwrap_or_else(|| panic!("line {line}: {result}"));
        assert!(
            error.contains(message),
            "line {line}: {error:?} lacks {message:?}"
        );
    }
    assert_eq!(results[8]["law"], "fresnel");
    assert!(results[8]["answer"].is_number());
}

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
            &["reflect", "--wi", "0,1,1", "--normal", "0,0,1e-320"],
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

#[test]
fn json_errors_are_json_too() {
    let output = optics(&["--json", "fresnel", "--eta", "-1", "--cos-i", "0.3"]);
    assert_eq!(output.status.code(), Some(1));
    let error: Value = serde_json::from_str(stdout(&output).trim()).expect("a JSON error object");
    assert!(error["error"].as_str().unwrap().contains("--eta"));
}

#[test]
fn hungarian_output_speaks_the_course_language() {
    let text = stdout(&optics(&["--lang", "hu", "quiz", "seed"]));
    for expected in [
        "1. kérdés",
        "eredmény",
        "csonkolva, nem kerekítve",
        "teljes visszaverődés",
    ] {
        assert!(text.contains(expected), "missing {expected:?}");
    }
    // The statements of question 1 are quoted as the course prints them.
    assert!(text.contains("A törésmutató a két közegbeli fénysebességek arányával egyezik meg."));
    let refused = optics(&["--lang", "hu", "fresnel", "--eta", "-1", "--cos-i", "0.5"]);
    assert_eq!(
        stderr(&refused).trim(),
        "hiba: --eta: pozitív törésmutatónak kell lennie, kapott érték: -1"
    );
    let english = stdout(&optics(&["quiz", "seed"]));
    assert!(!english.contains("kérdés"));
}

#[test]
fn every_subcommand_has_help_with_an_example() {
    let subcommands: &[&[&str]] = &[
        &["quiz"],
        &["quiz", "seed"],
        &["quiz", "f0"],
        &["quiz", "lambert"],
        &["quiz", "critical-angle"],
        &["quiz", "blinn-phong"],
        &["fresnel"],
        &["refract"],
        &["reflect"],
        &["shade"],
        &["batch"],
        &["render"],
        &["inspect"],
        &["validate"],
    ];
    for sub in subcommands {
        let mut args = sub.to_vec();
        args.push("--help");
        let output = optics(&args);
        assert!(output.status.success(), "optics {args:?}");
        let text = stdout(&output);
        assert!(
            text.contains("Example") && text.contains("optics "),
            "no example in optics {args:?}:\n{text}"
        );
    }
}
