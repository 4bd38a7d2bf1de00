//! The typed errors of `render`, `inspect` and `validate` through the
//! binary: a bad scene field, an unwritable output and a missing checkout,
//! each as the JSON error object (kind, field, message) and in Hungarian.

mod support;
use support::optics;

use std::path::Path;
#[cfg(feature = "harness")]
use std::process::Command;
use std::process::Output;

use serde_json::Value;

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// The JSON error object a failed command printed, after checking that it
/// failed with status 1 and said so on stderr in the language asked for.
fn error_object(out: &Output, lead: &str) -> Value {
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    let stderr = text(&out.stderr);
    assert!(stderr.starts_with(lead), "{stderr:?}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    let record: Value = serde_json::from_slice(&out.stdout).unwrap();
    record["error"].clone()
}

/// A one-sphere scene with `radius` and `camera`'s extra fields.
fn write_scene(dir: &Path, radius: f64, camera_extra: &str) -> String {
    let file = dir.join("scene.json");
    std::fs::write(
        &file,
        format!(
            r#"{{"version": 1, "image": {{"width": 8, "height": 6}},
                "camera": {{"type": "course_pinhole"{camera_extra}}},
                "materials": {{"red": {{"type": "lambert", "albedo": [0.8, 0.1, 0.1]}}}},
                "objects": [{{"type": "sphere", "center": [0, 0, 4], "radius": {radius},
                              "material": "red"}}]}}"#
        ),
    )
    .unwrap();
    file.to_str().unwrap().to_owned()
}

#[test]
fn a_bad_scene_field_is_named_by_its_json_path_in_both_languages() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_scene(dir.path(), -1.0, "");
    let png = dir.path().join("out.png");
    let png = png.to_str().unwrap();
    for command in [vec!["render", &scene, "-o", png], vec!["inspect", &scene]] {
        let mut args = vec!["--json", "--lang", "hu"];
        args.extend(&command);
        let error = error_object(&optics(&args), "hiba: ");
        assert_eq!(error["kind"], "scene.domain.out_of_range", "{command:?}");
        assert_eq!(error["field"], "objects[0].radius", "{command:?}");
        let message = error["message"].as_str().unwrap();
        assert!(
            message.starts_with(&format!("a(z) {scene} jelenet: objects[0].radius: pozitív")),
            "{message}"
        );
        let mut args = vec!["--json"];
        args.extend(&command);
        let error = error_object(&optics(&args), "error: ");
        let message = error["message"].as_str().unwrap();
        assert!(
            message.starts_with(&format!(
                "scene {scene}: objects[0].radius must be positive"
            )),
            "{message}"
        );
    }
    assert!(!dir.path().join("out.png").exists());
}

#[test]
fn a_field_the_schema_does_not_know_keeps_serdes_text_behind_a_hungarian_lead() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_scene(dir.path(), 1.0, r#", "zoom": 2"#);
    let out = optics(&["--json", "--lang", "hu", "inspect", &scene]);
    let error = error_object(&out, "hiba: ");
    assert_eq!(error["kind"], "scene.schema");
    assert_eq!(error["field"], "camera.zoom");
    let message = error["message"].as_str().unwrap();
    assert!(
        message
            .contains("camera.zoom: nem felel meg a jelenetleírás sémájának: unknown field `zoom`"),
        "{message}"
    );
}

#[test]
fn an_unwritable_output_is_refused_naming_the_flag() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_scene(dir.path(), 1.0, "");
    let missing = dir.path().join("missing").join("out.png");
    let missing = missing.to_str().unwrap();
    let pfm = dir.path().join("out.pfm");
    let cases = [
        (missing, "output.no_directory", "könyvtár nem létezik"),
        (
            pfm.to_str().unwrap(),
            "output.pfm_is_png",
            "a PNG nevét kell megadni",
        ),
    ];
    for (output, kind, hungarian) in cases {
        let out = optics(&["--json", "--lang", "hu", "render", &scene, "-o", output]);
        let error = error_object(&out, "hiba: --output: ");
        assert_eq!(error["kind"], kind);
        assert_eq!(error["field"], "--output");
        let message = error["message"].as_str().unwrap();
        assert!(
            message.starts_with("--output: ") && message.contains(hungarian),
            "{message}"
        );
        let out = optics(&["render", &scene, "-o", output]);
        assert!(
            text(&out.stderr).starts_with("error: --output: "),
            "{}",
            text(&out.stderr)
        );
    }
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        1,
        "only the scene"
    );
}

#[cfg(feature = "harness")]
#[test]
fn a_missing_checkout_is_named_by_what_named_it() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("no-checkout");
    let missing = missing.to_str().unwrap();
    let quick = ["validate", "--quick", "--no-python"];
    let mut args = vec!["--json", "--lang", "hu"];
    args.extend(quick);
    // An explicit directory that is not a checkout.
    let mut explicit = args.clone();
    explicit.extend(["--checkout", missing]);
    let error = error_object(&optics(&explicit), "hiba: --checkout ");
    assert_eq!(error["kind"], "checkout.not_a_checkout");
    assert_eq!(error["field"], "--checkout");
    let message = error["message"].as_str().unwrap();
    assert!(
        message.contains("nem a programcsomag munkapéldánya"),
        "{message}"
    );
    // The variable, when no flag is given.
    let out = Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(&args)
        .env("OPTICS_CHECKOUT", missing)
        .output()
        .unwrap();
    let error = error_object(&out, "hiba: OPTICS_CHECKOUT ");
    assert_eq!(error["field"], "OPTICS_CHECKOUT");
    // Neither, from outside any checkout.
    let out = Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(&args)
        .env_remove("OPTICS_CHECKOUT")
        .current_dir(dir.path())
        .output()
        .unwrap();
    let error = error_object(&out, "hiba: nem található");
    assert_eq!(error["kind"], "checkout.not_found");
    assert_eq!(error["field"], "--checkout");
    let out = Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(quick)
        .env_remove("OPTICS_CHECKOUT")
        .current_dir(dir.path())
        .output()
        .unwrap();
    let stderr = text(&out.stderr);
    assert!(
        stderr.starts_with("error: no checkout of the suite found"),
        "{stderr}"
    );
}
