//! `optics envmap`, `reflection-matrix` and `shadow-matrix`: the slides'
//! numbers, one record shape, both languages, and bad input refused by
//! the flag's name.

use crate::common::{assert_record_fields, json, number, optics, stderr, stdout};
use serde_json::Value;

/// Two numbers the slides' arithmetic gives, to the few roundings of
/// normalising the direction first (4 ε).
fn close(got: &Value, want: f64) {
    let got = number(got);
    assert!(
        (got - want).abs() <= 4.0 * f64::EPSILON,
        "{got} against {want}"
    );
}

#[test]
fn envmap_cube_puts_the_slides_example_on_minus_z() {
    let record = json(&["envmap", "--dir", "-3.2,5.1,-8.4", "--map", "cube"]);
    assert_record_fields(&record);
    assert_eq!(record["law"], "envmap");
    let cube = &record["answer"]["cube"];
    assert_eq!(cube["face"], "-Z");
    // u = (3.2/8.4 + 1)/2, v = (−5.1/8.4 + 1)/2.
    close(&cube["u"], 29.0 / 42.0);
    close(&cube["v"], 11.0 / 56.0);
    assert!(record["answer"].get("sphere").is_none(), "{record}");
}

#[test]
fn envmap_all_answers_each_map_with_its_outcome() {
    let record = json(&["envmap", "--dir", "1,1,0"]);
    let answer = &record["answer"];
    assert_eq!(answer["cube"]["face"], "+Y", "the tie goes to y over x");
    close(&answer["lat_long"]["phi"], std::f64::consts::FRAC_PI_4);
    close(&answer["lat_long"]["v"], 0.5);
    assert_eq!(answer["sphere"]["outcome"], "disc");
    // Straight away from the viewer: the sphere map's rim, not a NaN.
    let away = json(&["envmap", "--dir", "0,0,-5", "--map", "sphere"]);
    assert_eq!(away["answer"]["sphere"]["outcome"], "rim");
    assert_eq!(away["answer"]["sphere"]["m"], 0.0);
}

#[test]
fn the_techniques_explain_in_hungarian() {
    let floor = ["--plane-point", "0,0,0", "--plane-normal", "0,1,0"];
    let mut shadow = vec!["shadow-matrix", "--light", "0,4,0", "--vertex", "1,2,0"];
    shadow.extend(floor);
    let mut mirror = vec!["reflection-matrix"];
    mirror.extend(floor);
    let cases: [(Vec<&str>, &[&str]); 3] = [
        (
            vec!["envmap", "--dir", "-3.2,5.1,-8.4"],
            &[
                "kocka",
                "): a -Z lap",
                "szélességi–hosszúsági",
                "gömbtérkép",
                "0.690476",
            ],
        ),
        (
            mirror,
            &[
                "Sík tükrözési mátrixa",
                "az y = 0 síkra tükröz: S = [(1, 0, 0, 0), (0, -1, 0, 0)",
                "ellenőrzés: det M = -1",
            ],
        ),
        (
            shadow,
            &[
                "Pontfényforrás árnyékmátrixa",
                "a sík az y = 0: a diák különleges esete",
                "a csúcs a fény és a sík között van",
            ],
        ),
    ];
    for (args, phrases) in cases {
        let mut hu = vec!["--lang", "hu"];
        hu.extend(&args);
        let output = optics(&hu);
        assert!(output.status.success(), "optics {hu:?}");
        let text = stdout(&output);
        for phrase in phrases.iter().chain(&["eredmény:"]) {
            assert!(text.contains(phrase), "no {phrase:?} in:\n{text}");
        }
    }
}

#[test]
fn reflection_matrix_mirrors_the_floor_y_1() {
    let record = json(&[
        "reflection-matrix",
        "--plane-point",
        "0,1,0",
        "--plane-normal",
        "0,2,0",
    ]);
    assert_record_fields(&record);
    assert_eq!(record["law"], "reflection_matrix");
    // y → 2 − y: the rows of the exact matrix (the half turn is exact).
    let want = [
        [1.0, 0.0, 0.0, 0.0],
        [0.0, -1.0, 0.0, 2.0],
        [0.0, 0.0, 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ];
    for (row, want) in record["answer"].as_array().unwrap().iter().zip(want) {
        for (got, want) in row.as_array().unwrap().iter().zip(want) {
            assert!((number(got) - want).abs() <= 1e-15, "{record}");
        }
    }
}

#[test]
fn shadow_matrix_names_each_outcome_of_a_vertex() {
    // Light 4 m above the floor: (vertex, outcome, point).
    let cases: [(&str, &str, Option<[f64; 3]>); 4] = [
        ("1,2,0", "cast", Some([2.0, 0.0, 0.0])),
        ("1,-2,0", "beyond_plane", Some([2.0 / 3.0, 0.0, 0.0])),
        ("1,6,0", "behind_light", Some([-2.0, 0.0, 0.0])),
        ("1,4,0", "parallel", None),
    ];
    for (vertex, outcome, point) in cases {
        let record = json(&[
            "shadow-matrix",
            "--light",
            "0,4,0",
            "--plane-point",
            "0,0,0",
            "--plane-normal",
            "0,1,0",
            "--vertex",
            vertex,
        ]);
        assert_record_fields(&record);
        assert_eq!(record["details"]["outcome"], outcome, "{record}");
        match point {
            Some(p) => {
                let got = record["details"]["point"].as_array().unwrap();
                for (got, want) in got.iter().zip(p) {
                    assert!((number(got) - want).abs() <= 1e-15, "{record}");
                }
            }
            None => assert!(record["details"].get("point").is_none(), "{record}"),
        }
    }
    // Without a vertex: the matrix alone.
    let record = json(&[
        "shadow-matrix",
        "--light",
        "0,4,0",
        "--plane-point",
        "0,0,0",
        "--plane-normal",
        "0,1,0",
    ]);
    assert!(record["details"].get("outcome").is_none(), "{record}");
    assert_eq!(
        record["answer"][3],
        serde_json::json!([0.0, -1.0, 0.0, 4.0])
    );
}

/// The rows of a record's matrix, as numbers.
fn matrix(value: &Value) -> Vec<Vec<f64>> {
    let rows = value.as_array().expect("a matrix by rows");
    rows.iter()
        .map(|row| row.as_array().unwrap().iter().map(number).collect())
        .collect()
}

#[test]
fn reflection_matrix_shows_its_factors_and_mirrors_a_light() {
    // The plane x + y = 1: M swaps x and y about it, (x, y) → (1 − y, 1 − x).
    let record = json(&[
        "reflection-matrix",
        "--plane-point",
        "0,1,0",
        "--plane-normal",
        "1,1,0",
        "--point",
        "2,3,4",
        "--direction",
        "0,-2,0",
    ]);
    assert_record_fields(&record);
    let m = matrix(&record["answer"]);
    // The exact zeros come out as zeros, not as the −3.3e-16 of the
    // products' rounding; the rest within 4 ε of the exact entries.
    assert_eq!(m[0][0], 0.0, "{record}");
    assert_eq!(m[1][1], 0.0, "{record}");
    let want = [
        [0.0, -1.0, 0.0, 1.0],
        [-1.0, 0.0, 0.0, 1.0],
        [0.0, 0.0, 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ];
    for (got, want) in m.iter().flatten().zip(want.iter().flatten()) {
        assert!((got - want).abs() <= 4.0 * f64::EPSILON, "{record}");
    }
    // M = F⁻¹ S F with the factors shown: F takes the plane's point
    // (0, 1, 0) onto y = 0 (its second row dotted with (0, 1, 0, 1)).
    let f = matrix(&record["details"]["to_floor"]);
    assert!((f[1][1] + f[1][3]).abs() <= 4.0 * f64::EPSILON, "{record}");
    let steps = record["steps"].to_string();
    for phrase in ["F = [", "S = [(1, 0, 0, 0), (0, -1, 0, 0)", "F⁻¹ = ["] {
        assert!(steps.contains(phrase), "no {phrase:?} in {steps}");
    }
    assert!(!steps.contains("e-1"), "rounding noise printed: {steps}");
    // A light at (2, 3, 4) goes to (−2, −1, 4); a light shining down, (0, −1, 0),
    // shines along (1, 0, 0) in the mirror.
    let point: Vec<f64> = record["details"]["point_image"]
        .as_array()
        .unwrap()
        .iter()
        .map(number)
        .collect();
    let direction: Vec<f64> = record["details"]["direction_image"]
        .as_array()
        .unwrap()
        .iter()
        .map(number)
        .collect();
    for (got, want) in point.iter().zip([-2.0, -1.0, 4.0]) {
        assert!((got - want).abs() <= 16.0 * f64::EPSILON, "{record}");
    }
    for (got, want) in direction.iter().zip([1.0, 0.0, 0.0]) {
        assert!((got - want).abs() <= 4.0 * f64::EPSILON, "{record}");
    }
}

#[test]
fn shadow_matrix_with_the_light_on_the_plane_is_degenerate() {
    // The light on the floor: M = −(l, 1)(n, d)ᵀ sends the vertex to the light.
    let record = json(&[
        "shadow-matrix",
        "--light",
        "1,0,2",
        "--plane-point",
        "0,0,0",
        "--plane-normal",
        "0,1,0",
        "--vertex",
        "1,2,0",
    ]);
    assert_record_fields(&record);
    assert_eq!(record["details"]["matrix"], "degenerate", "{record}");
    assert_eq!(record["details"]["outcome"], "degenerate", "{record}");
    assert!(record["details"].get("point").is_none(), "{record}");
    // Off the plane it is not.
    let above = json(&[
        "shadow-matrix",
        "--light",
        "1,1e-6,2",
        "--plane-point",
        "0,0,0",
        "--plane-normal",
        "0,1,0",
    ]);
    assert!(above["details"].get("matrix").is_none(), "{above}");
}

#[test]
fn shadow_matrix_on_y_0_is_the_slides_special_case() {
    let floor = |normal: &'static str| {
        json(&[
            "shadow-matrix",
            "--light",
            "1,4,2",
            "--plane-point",
            "3,0,-1",
            "--plane-normal",
            normal,
        ])
    };
    let record = floor("0,5,0");
    assert_eq!(
        matrix(&record["details"]["slides_y0"]),
        vec![
            vec![4.0, -1.0, 0.0, 0.0],
            vec![0.0, 0.0, 0.0, 0.0],
            vec![0.0, -2.0, 4.0, 0.0],
            vec![0.0, -1.0, 0.0, 4.0],
        ]
    );
    assert_eq!(record["details"]["slides_y0"], record["answer"], "{record}");
    // A plane other than y = 0 has no special case.
    let tilted = floor("0,1,1");
    assert!(tilted.get("details").is_none(), "{tilted}");
}

/// Bad input: a message naming the flag, a non-zero exit, no panic, and
/// with `--json` the error object's field is the flag.
#[test]
fn bad_technique_input_is_refused_by_flag_without_a_panic() {
    let floor = ["--plane-point", "0,0,0", "--plane-normal", "0,1,0"];
    let shadow = |light: &'static str, vertex: &'static str| -> Vec<&'static str> {
        let mut args = vec!["shadow-matrix", "--light", light];
        args.extend(floor);
        args.extend(["--vertex", vertex]);
        args
    };
    let cases: Vec<(Vec<&str>, &str, &str)> = vec![
        (
            vec!["envmap", "--dir", "0,0,0"],
            "--dir",
            "--dir must be a non-zero direction",
        ),
        (
            vec!["envmap", "--dir", "0,NaN,1"],
            "--dir.y",
            "--dir.y must be a finite number",
        ),
        (
            vec!["envmap", "--dir", "1,2"],
            "--dir <DIR>",
            "expected three comma-separated numbers",
        ),
        (
            vec!["envmap", "--dir", "1,2,3", "--map", "octahedral"],
            "--map <MAP>",
            "octahedral",
        ),
        (
            vec![
                "reflection-matrix",
                "--plane-point",
                "0,0,0",
                "--plane-normal",
                "0,-0,0",
            ],
            "--plane-normal",
            "--plane-normal must be a non-zero direction",
        ),
        (
            vec![
                "reflection-matrix",
                "--plane-point",
                "inf,0,0",
                "--plane-normal",
                "0,1,0",
            ],
            "--plane-point.x",
            "--plane-point.x must be a finite number",
        ),
        (
            shadow("0,NaN,0", "1,2,0"),
            "--light.y",
            "--light.y must be a finite number",
        ),
        (
            shadow("0,4,0", "1,2,NaN"),
            "--vertex.z",
            "--vertex.z must be a finite number",
        ),
        (
            shadow("1e308,4,0", "-1e308,2,0"),
            "--light, --plane-point, --vertex",
            "p overflows",
        ),
    ];
    for (args, field, message) in cases {
        let output = optics(&args);
        let err = stderr(&output);
        assert!(!output.status.success(), "optics {args:?} succeeded");
        assert!(
            err.contains(message),
            "optics {args:?}: {err:?} lacks {message:?}"
        );
        assert!(!err.contains("panicked"), "optics {args:?} panicked: {err}");
        let mut with_json = vec!["--json"];
        with_json.extend(&args);
        let output = optics(&with_json);
        let error: Value = serde_json::from_str(stdout(&output).trim()).expect("a JSON error");
        assert_eq!(error["error"]["field"], field, "optics {args:?}: {error}");
    }
}

#[test]
fn bad_technique_input_is_refused_in_hungarian() {
    let output = optics(&["--lang", "hu", "envmap", "--dir", "0,0,0"]);
    assert!(!output.status.success());
    let err = stderr(&output);
    assert!(err.contains("hiba: --dir: nem nulla hosszú"), "{err}");
}
