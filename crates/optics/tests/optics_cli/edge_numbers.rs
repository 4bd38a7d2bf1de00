//! Numbers at the edges of what a user may type: negative exponents read
//! as values, vectors too short or too long to square, and products that
//! overflow; each an answer physics allows, or an error naming the input.

use crate::common::{batch, json, number, optics, stderr, stdout};
use serde_json::Value;

fn error_of(args: &[&str]) -> Value {
    let mut all = vec!["--json"];
    all.extend_from_slice(args);
    let output = optics(&all);
    assert_eq!(
        output.status.code(),
        Some(1),
        "optics {args:?}: {}",
        stderr(&output)
    );
    let printed: Value = serde_json::from_str(stdout(&output).trim()).expect("one JSON object");
    printed["error"].clone()
}

#[test]
fn a_negative_number_with_a_negative_exponent_is_a_value_not_a_flag() {
    let grazing = json(&["fresnel", "--eta", "1.5", "--cos-i", "-1e-5"]);
    assert_eq!(
        number(&grazing["answer"]),
        1.0,
        "from inside, beyond the critical angle"
    );
    let angle = json(&["fresnel", "--eta", "1.5", "--theta-i-deg", "1e-5"]);
    assert!(number(&angle["answer"]) > 0.03);
    let cases: [(&[&str], &str); 3] = [
        (&["quiz", "f0", "--n", "-1E-5"], "--n"),
        (
            &[
                "shade",
                "--normal",
                "0,0,1",
                "--light-dir",
                "0,3,4",
                "--view-dir",
                "0,4,3",
                "--radiance",
                "-2.5e-3",
            ],
            "--radiance",
        ),
        (
            &[
                "quiz",
                "critical-angle",
                "--n",
                "2",
                "--n-outside",
                "-1e-300",
            ],
            "--n-outside",
        ),
    ];
    for (args, field) in cases {
        let error = error_of(args);
        assert_eq!(error["kind"], "domain.out_of_range", "{args:?}: {error}");
        assert_eq!(error["field"], field, "{args:?}: {error}");
    }
}

/// Within 4 ulp of 1: a unit vector's components each rounded once, the
/// length's squares and root rounded again.
fn assert_unit(answer: &Value, what: &str) {
    let v: Vec<f64> = answer
        .as_array()
        .expect("a vector")
        .iter()
        .map(number)
        .collect();
    let length = v.iter().map(|c| c * c).sum::<f64>().sqrt();
    assert!(
        (length - 1.0).abs() <= 4.0 * f64::EPSILON,
        "{what}: |{v:?}| = {length}"
    );
}

#[test]
fn tiny_and_huge_vectors_give_unit_directions() {
    for wi in [
        "0,3e-162,4e-162",
        "0,3e200,4e200",
        "0,-5e-324,5e-324",
        "1e308,1e308,1e308",
    ] {
        let reflected = json(&["reflect", "--wi", wi, "--normal", "0,0,1"]);
        assert_unit(&reflected["answer"], &format!("reflect {wi}"));
        let refracted = json(&[
            "refract",
            "--wi",
            wi,
            "--normal",
            "0,0,1e-300",
            "--eta",
            "1.5",
        ]);
        assert_unit(&refracted["answer"], &format!("refract {wi}"));
    }
}

#[test]
fn an_overflowing_product_is_an_error_not_a_null_answer() {
    let shade = [
        "shade",
        "--normal",
        "0,0,1",
        "--light-dir",
        "0,3,4",
        "--view-dir",
        "0,4,3",
        "--radiance",
        "1e308",
        "--kd",
        "1e308",
    ];
    let error = error_of(&shade);
    assert_eq!(error["kind"], "overflow", "{error}");
    assert_eq!(error["field"], "--radiance, --kd, --ks", "{error}");
    assert!(error["message"]
        .as_str()
        .unwrap()
        .starts_with("L_ref overflows"));
    let request = r#"{"law": "lambert", "normal": [0, 0, 1], "light_dir": [0, 3, 4], "view_dir": [1, 2, 3], "radiance": 5, "kd": 1.7e308}"#;
    let (results, _) = batch(&format!("{request}\n"));
    let error = &results[0]["error"];
    assert_eq!(error["kind"], "overflow", "{}", results[0]);
    assert_eq!(error["field"], "radiance, kd", "{}", results[0]);
}

/// Grazing incidence given as 90° is exactly grazing: R = 1 and T = 0 to
/// the bit, for glass and for gold, not the 1 − 3.6e-16 that the rounding
/// of 90° in radians (a cosine of 6.1e-17) gave.
#[test]
fn fresnel_at_ninety_degrees_is_exactly_grazing() {
    for kappa in ["0", "3.1"] {
        let record = json(&[
            "fresnel",
            "--eta",
            "1.5",
            "--kappa",
            kappa,
            "--theta-i-deg",
            "90",
        ]);
        assert_eq!(record["answer"].as_f64(), Some(1.0), "{record}");
        let steps = record["steps"].to_string();
        assert!(steps.contains("|cos θi| = 0,"), "{steps}");
        if kappa == "0" {
            assert_eq!(
                record["details"]["transmittance"].as_f64(),
                Some(0.0),
                "{record}"
            );
        }
    }
}
