//! `optics validate`'s output directory checked before any check runs,
//! through the binary: a report that could not be written whole is refused
//! at once, naming `--out`, and no `report.json` is left without its
//! `report.html`.
#![cfg(feature = "harness")]

use std::path::Path;
use std::process::{Command, Output};

use serde_json::Value;

/// `optics --json validate --quick --no-python --out OUT` on this checkout.
fn validate(out: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(["--json", "validate", "--quick", "--no-python", "--checkout"])
        .arg(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
        .arg("--out")
        .arg(out)
        .output()
        .expect("the optics binary runs")
}

/// The refusal, after checking that it is one of `--out` with exit status
/// 1, no panic and no report written.
fn refused(out: &Path) -> Value {
    let run = validate(out);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(
        !out.join("report.json").exists(),
        "report.json without report.html"
    );
    let error: Value = serde_json::from_slice(&run.stdout)
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&run.stdout)));
    assert_eq!(error["error"]["field"], "--out", "{error}");
    assert_eq!(error["error"]["kind"], "harness.write", "{error}");
    error
}

#[test]
fn validate_refuses_a_report_html_it_cannot_replace_before_any_check() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("report.html")).unwrap();
    let error = refused(dir.path());
    let message = error["error"]["message"].as_str().unwrap_or_default();
    assert!(message.contains("report.html"), "{message}");
}

/// sysfs takes no new files, even from root.
#[cfg(target_os = "linux")]
#[test]
fn validate_refuses_an_unwritable_figures_directory_before_any_check() {
    let dir = tempfile::tempdir().unwrap();
    std::os::unix::fs::symlink("/sys", dir.path().join("figures")).unwrap();
    let error = refused(dir.path());
    let message = error["error"]["message"].as_str().unwrap_or_default();
    assert!(message.contains("figures"), "{message}");
}
