//! The law evaluators' `--json` records.

use crate::common::{assert_record_fields, json, number};

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

    for model in ["schlick-incident", "schlick-rarer"] {
        let schlick = json(&["fresnel", "--eta", "1.5", "--cos-i", "1", "--model", model]);
        assert!((number(&schlick["answer"]) - 0.04).abs() < 1e-15);
        assert_eq!(schlick["inputs"]["model"], model);
        let details = &schlick["details"];
        assert!(details["exact"].is_number() && details["error"].is_number());
        assert!(details["schlick-incident"].is_number() && details["schlick-rarer"].is_number());
    }

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

/// A BRDF whose every coefficient is 0 (their value when not given)
/// reflects nothing, and the record says so rather than answering 0
/// silently; one coefficient given is enough to lift the note.
#[test]
fn a_brdf_with_no_coefficient_given_says_it_reflects_nothing() {
    let geometry = [
        "--normal",
        "0,0,1",
        "--light-dir",
        "0,3,4",
        "--view-dir",
        "0,4,3",
        "--radiance",
        "5",
    ];
    let mut args = vec!["shade"];
    args.extend(geometry);
    let record = json(&args);
    assert_eq!(number(&record["answer"]), 0.0);
    let notes = record["notes"].to_string();
    assert!(
        notes.contains("--kd and --ks are both 0 (their value when not given)"),
        "{notes}"
    );
    let mut lambert = vec!["shade", "--model", "lambert"];
    lambert.extend(geometry);
    let notes = json(&lambert)["notes"].to_string();
    assert!(notes.contains("--kd is 0"), "{notes}");
    let mut given = vec!["shade", "--ks", "1"];
    given.extend(geometry);
    assert!(!json(&given)["notes"]
        .to_string()
        .contains("reflects nothing"));
}
