//! Running the binary, and what every test reads from it.

use serde_json::Value;
use std::io::Write;
use std::process::{Command, Output, Stdio};

pub fn optics(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(args)
        .output()
        .expect("the optics binary runs")
}

pub fn stdout(output: &Output) -> String {
    String::from_utf8(output.stdout.clone()).expect("stdout is UTF-8")
}

pub fn stderr(output: &Output) -> String {
    String::from_utf8(output.stderr.clone()).expect("stderr is UTF-8")
}

/// Runs with `--json`, expects success, returns the one JSON object printed.
pub fn json(args: &[&str]) -> Value {
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

pub fn batch(input: &str) -> (Vec<Value>, Output) {
    batch_in(&[], input)
}

/// `optics <global> batch` with `input` on stdin: the output lines as JSON.
pub fn batch_in(global: &[&str], input: &str) -> (Vec<Value>, Output) {
    batch_bytes(global, &[], input.as_bytes())
}

/// `optics <global> batch <args>` with the bytes `input` on stdin: the
/// output lines as JSON.
pub fn batch_bytes(global: &[&str], args: &[&str], input: &[u8]) -> (Vec<Value>, Output) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(global)
        .arg("batch")
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the optics binary runs");
    child
        .stdin
        .take()
        .expect("stdin is piped")
        .write_all(input)
        .expect("stdin takes the requests");
    let output = child.wait_with_output().expect("optics batch finishes");
    let lines = stdout(&output)
        .lines()
        .map(|l| serde_json::from_str(l).expect("each output line is JSON"))
        .collect();
    (lines, output)
}

pub fn number(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("{v} is not a number"))
}

/// Every subcommand's `--json` record carries the documented fields.
pub fn assert_record_fields(record: &Value) {
    for field in ["law", "inputs", "answer", "unit", "steps"] {
        assert!(record.get(field).is_some(), "no {field:?} in {record}");
    }
    assert!(record["law"].is_string());
    assert!(record["inputs"].is_object());
    assert!(record["unit"].is_string());
    let steps = record["steps"].as_array().expect("steps is a list");
    assert!(!steps.is_empty() && steps.iter().all(Value::is_string));
}

/// One request per law, with its subcommand's flags.
pub const ROUND_TRIP: [(&str, &[&str]); 8] = [
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
