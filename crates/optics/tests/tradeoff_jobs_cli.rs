//! A sweep spread over machines, through the binary: `--plan` writes one
//! line per job and renders nothing, each `tradeoff-job` writes its result
//! whole, `--collect` gives the errors a sweep in one run gives for the
//! same seeds, and every bad input is refused by a typed kind naming its
//! field and file, with nothing written.
#![cfg(all(unix, feature = "harness"))]

mod support;
use support::listing;

use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

use serde_json::Value;

/// The sweep's flags: tiny and quick, two renders a point, none added
/// for time, so that both ways render the same seeds.
const FLAGS: [&str; 12] = [
    "--lambert",
    "--width",
    "16",
    "--height",
    "12",
    "--truth-spp",
    "8",
    "--repeats",
    "2",
    "--min-seconds",
    "0",
    "--no-plot",
];

fn optics(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(args)
        .output()
        .expect("the optics binary runs")
}

fn job_command(jobs: &Path, index: &str, out: &Path) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_optics"));
    command
        .args(["--json", "tradeoff-job"])
        .arg(jobs)
        .arg(index)
        .arg("--out")
        .arg(out);
    command
}

fn run_job(jobs: &Path, index: usize, out: &Path) -> Output {
    job_command(jobs, &index.to_string(), out).output().unwrap()
}

/// A copy of the course's `shadow` scene in `dir`, so a test may change it.
fn scene_in(dir: &Path) -> PathBuf {
    let source = format!(
        "{}/../tracer/scenes/shadow.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let copy = dir.join("shadow.json");
    std::fs::copy(source, &copy).unwrap();
    copy
}

fn tradeoff(scene: &Path, extra: &[&str]) -> Output {
    let mut args = vec!["--json", "tradeoff", scene.to_str().unwrap()];
    args.extend_from_slice(&FLAGS);
    args.extend_from_slice(extra);
    optics(&args)
}

/// Plans the sweep of `scene` into `dir/jobs.jsonl`; its lines.
fn plan(scene: &Path, dir: &Path) -> (PathBuf, Vec<Value>) {
    let jobs = dir.join("jobs.jsonl");
    let out = tradeoff(scene, &["--plan", jobs.to_str().unwrap()]);
    assert!(out.status.success(), "{}", stderr(&out));
    let lines = std::fs::read_to_string(&jobs)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    (jobs, lines)
}

/// Plans and runs every job into `dir/results`.
fn plan_and_run(scene: &Path, dir: &Path) -> (PathBuf, PathBuf, usize) {
    let (jobs, lines) = plan(scene, dir);
    let results = dir.join("results");
    for index in 0..lines.len() {
        let out = run_job(&jobs, index, &results);
        assert!(out.status.success(), "job {index}: {}", stderr(&out));
    }
    (jobs, results, lines.len())
}

fn collect(scene: &Path, results: &Path, out: &Path) -> Output {
    let (results, out) = (results.to_str().unwrap(), out.to_str().unwrap());
    tradeoff(scene, &["--collect", results, "--out", out])
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// The JSON error of a refused command: exit status 1 (not a panic's
/// 101), kind and field as given.
fn refused(out: &Output, kind: &str, field: &str) -> String {
    assert_eq!(out.status.code(), Some(1), "{}", stderr(out));
    let error: Value = serde_json::from_slice(&out.stdout).expect("one JSON error");
    assert_eq!(error["error"]["kind"], kind, "{error}");
    assert_eq!(error["error"]["field"], field, "{error}");
    error["error"]["message"].as_str().unwrap().to_owned()
}

fn read(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn a_plan_writes_one_line_per_job_and_renders_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_in(dir.path());
    let (_, lines) = plan(&scene, dir.path());
    // The truth's two halves, then the points a sweep in one run renders.
    let single = tradeoff(&scene, &["--out", dir.path().join("one").to_str().unwrap()]);
    let record: Value = serde_json::from_slice(&single.stdout).unwrap();
    let points = record["details"]["sweep"]["points"].as_array().unwrap();
    assert_eq!(lines.len(), points.len() + 2);
    for (i, line) in lines.iter().enumerate() {
        assert_eq!(line["schema"], "optics.tradeoff-job");
        assert_eq!(line["version"], 1);
        assert_eq!(line["job"], i);
        assert_eq!(line["jobs"], lines.len());
        assert_eq!(line["plan"], lines[0]["plan"]);
    }
    assert_eq!(lines[0]["axis"], "truth");
    for (line, point) in lines[2..].iter().zip(points) {
        assert_eq!(line["label"], point["label"]);
        assert_eq!(line["settings"], point["settings"]);
    }
    // With --json, one record: the plan's file, its id and its jobs.
    let again = dir.path().join("again.jsonl");
    let out = tradeoff(&scene, &["--plan", again.to_str().unwrap()]);
    let record: Value = serde_json::from_slice(&out.stdout).expect("one JSON record");
    assert_eq!(record["law"], "tradeoff");
    assert_eq!(record["answer"][0], again.to_str().unwrap());
    assert_eq!(record["details"]["plan"], lines[0]["plan"]);
    assert_eq!(record["details"]["jobs"], lines.len());
    assert_eq!(
        std::fs::read(&again).unwrap(),
        std::fs::read(dir.path().join("jobs.jsonl")).unwrap()
    );
    std::fs::remove_file(&again).unwrap();
    // Nothing rendered: no results, no truth cached.
    let mut want = vec!["jobs.jsonl", "one", "shadow.json"];
    want.sort();
    assert_eq!(listing(dir.path()), want);
}

#[test]
fn collected_jobs_give_the_errors_of_a_sweep_in_one_run() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_in(dir.path());
    let (_, results, jobs) = plan_and_run(&scene, dir.path());
    assert_eq!(listing(&results).len(), jobs, "one result file per job");
    let out = collect(&scene, &results, &dir.path().join("collected"));
    assert!(out.status.success(), "{}", stderr(&out));
    let one = tradeoff(&scene, &["--out", dir.path().join("one").to_str().unwrap()]);
    assert!(one.status.success(), "{}", stderr(&one));
    let collected = read(&dir.path().join("collected/shadow-lambert.json"));
    let single = read(&dir.path().join("one/shadow-lambert.json"));
    assert_eq!(collected["schema"], "optics.tradeoff");
    assert_eq!(collected["version"], 2);
    // The same seeds, the same images: every measure equal to the last
    // bit, against the truth and against the scene's own render; the
    // truth's own noise too. Times differ, and with them fronts and
    // verdicts.
    assert_eq!(collected["truth"]["noise"], single["truth"]["noise"]);
    assert_eq!(collected["truth"]["key"], single["truth"]["key"]);
    let (a, b) = (
        collected["points"].as_array().unwrap(),
        single["points"].as_array().unwrap(),
    );
    assert_eq!(a.len(), b.len());
    for (p, q) in a.iter().zip(b) {
        assert_eq!(p["label"], q["label"]);
        assert_eq!(p["errors"], q["errors"], "{}", p["label"]);
        assert_eq!(p["against_scene"], q["against_scene"], "{}", p["label"]);
        assert_eq!(p["seconds"].as_array().unwrap().len(), 2);
    }
    assert_eq!(collected["collected"]["jobs"], jobs);
    assert!(
        single.get("collected").is_none(),
        "a one-run record is as before"
    );
}

#[test]
fn a_job_runs_from_stdin_and_a_closed_stdout_is_not_a_failure() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_in(dir.path());
    let (jobs, lines) = plan(&scene, dir.path());
    let results = dir.path().join("results");
    let line = serde_json::to_string(&lines[3]).unwrap() + "\n";
    let mut child = Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(["tradeoff-job", "-", "--out", results.to_str().unwrap()])
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(line.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    let result = read(&results.join("job-0003.json"));
    assert_eq!(result["schema"], "optics.tradeoff-result");
    assert_eq!(result["job"], 3);
    // Its reader gone before it prints: the result is written all the same.
    std::fs::remove_file(results.join("job-0003.json")).unwrap();
    let (read_end, write_end) = std::io::pipe().unwrap();
    drop(read_end);
    let out = job_command(&jobs, "3", &results)
        .stdout(write_end)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(results.join("job-0003.json").is_file());
}

#[test]
fn a_job_stopped_before_its_result_is_renamed_leaves_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_in(dir.path());
    let (jobs, _) = plan(&scene, dir.path());
    let results = dir.path().join("results");
    let mut child = job_command(&jobs, "2", &results)
        .env("TRACER_TEST_PAUSE", "before-commit")
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut lines = BufReader::new(child.stderr.take().unwrap()).lines();
    let paused = lines.any(|l| l.unwrap() == "tracer: paused before-commit");
    assert!(paused, "the job ended without pausing before its rename");
    let sent = Command::new("kill")
        .args(["-2", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(sent.success());
    let status = child.wait().unwrap();
    assert!(!status.success(), "{status:?}");
    assert!(listing(&results).is_empty(), "{:?}", listing(&results));
}

#[test]
fn collect_refuses_results_missing_or_given_twice_naming_the_job() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_in(dir.path());
    let (_, results, jobs) = plan_and_run(&scene, dir.path());
    let out_dir = dir.path().join("collected");
    let kept = dir.path().join("job-0004.json");
    std::fs::rename(results.join("job-0004.json"), &kept).unwrap();
    let message = refused(
        &collect(&scene, &results, &out_dir),
        "jobs.missing",
        "--collect",
    );
    assert!(
        message.starts_with(&format!("1 of {jobs} jobs have no result: 4 (")),
        "{message}"
    );
    std::fs::copy(&kept, results.join("job-0004.json")).unwrap();
    std::fs::copy(&kept, results.join("again.jsonl")).unwrap();
    let message = refused(
        &collect(&scene, &results, &out_dir),
        "jobs.duplicate",
        "job",
    );
    assert!(message.contains("job 4 has two results"), "{message}");
    assert!(message.contains("again.jsonl:1") && message.contains("job-0004.json:1"));
    assert!(
        !out_dir.join("shadow-lambert.json").exists(),
        "nothing written"
    );
}

#[test]
fn collect_refuses_another_plan_schema_or_version() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_in(dir.path());
    let (_, results, _) = plan_and_run(&scene, dir.path());
    let out_dir = dir.path().join("collected");
    // Collected with another flag than planned.
    let (r, o) = (results.to_str().unwrap(), out_dir.to_str().unwrap());
    let out = tradeoff(&scene, &["--collect", r, "--out", o, "--spp", "4"]);
    let message = refused(&out, "jobs.other_plan", "plan");
    assert!(message.contains("job-0000.json:1"), "{message}");
    assert!(
        message.contains("--spp 16 --truth-spp 8"),
        "the plan's flags: {message}"
    );
    // A result of another version, then of another schema.
    let file = results.join("job-0005.json");
    let text = std::fs::read_to_string(&file).unwrap();
    let edit = |from: &str, to: &str| std::fs::write(&file, text.replace(from, to)).unwrap();
    edit("\"version\":1", "\"version\":2");
    let message = refused(
        &collect(&scene, &results, &out_dir),
        "jobs.version",
        "version",
    );
    assert!(message.contains("job-0005.json:1: version 2"), "{message}");
    edit("optics.tradeoff-result", "optics.tradeoff-job");
    refused(
        &collect(&scene, &results, &out_dir),
        "jobs.schema",
        "schema",
    );
    edit("\"rays\":", "\"colour\":1,\"rays\":");
    let message = refused(&collect(&scene, &results, &out_dir), "jobs.line", "colour");
    assert!(message.contains("job-0005.json:1"), "{message}");
    assert!(
        !out_dir.join("shadow-lambert.json").exists(),
        "nothing written"
    );
}

#[test]
fn a_scene_changed_since_planning_is_refused_by_job_and_by_collect() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_in(dir.path());
    let (jobs, results, _) = plan_and_run(&scene, dir.path());
    let mut text = std::fs::read_to_string(&scene).unwrap();
    text.push('\n');
    std::fs::write(&scene, text).unwrap();
    let fresh = dir.path().join("fresh");
    let message = refused(
        &run_job(&jobs, 2, &fresh),
        "jobs.scene_changed",
        "scene_fnv1a",
    );
    assert!(message.contains(scene.to_str().unwrap()), "{message}");
    assert!(!fresh.exists(), "no result written");
    let out = collect(&scene, &results, &dir.path().join("collected"));
    refused(&out, "jobs.scene_changed", "scene_fnv1a");
}

#[test]
fn a_plan_replaces_neither_the_scene_nor_what_is_not_a_regular_file() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_in(dir.path());
    let before = std::fs::read(&scene).unwrap();
    let link = dir.path().join("link.jsonl");
    std::os::unix::fs::symlink(&scene, &link).unwrap();
    let directory = dir.path().join("a-directory");
    std::fs::create_dir(&directory).unwrap();
    for (plan, reason) in [
        (&scene, "which is being read"),
        (&link, "is not a regular file"),
        (&directory, "is not a regular file"),
    ] {
        let out = tradeoff(&scene, &["--plan", plan.to_str().unwrap()]);
        let message = refused(&out, "jobs.write", "--plan");
        assert!(message.contains(reason), "{message}");
    }
    assert_eq!(
        std::fs::read(&scene).unwrap(),
        before,
        "the scene is as it was"
    );
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(directory.is_dir());
}

#[test]
fn bad_job_lines_are_refused_by_field_with_nothing_written() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_in(dir.path());
    let (jobs, lines) = plan(&scene, dir.path());
    let results = dir.path().join("results");
    let out = run_job(&jobs, lines.len(), &results);
    let message = refused(&out, "jobs.no_such_job", "INDEX");
    assert!(
        message.contains(&format!("has {} jobs", lines.len())),
        "{message}"
    );
    let edited = |field: &str, value: Value| {
        let mut line = lines[2].clone();
        match value {
            Value::Null => drop(line.as_object_mut().unwrap().remove(field)),
            value => line[field] = value,
        }
        let file = dir.path().join("edited.jsonl");
        std::fs::write(&file, line.to_string() + "\n").unwrap();
        job_command(&file, "0", &results).output().unwrap()
    };
    let cases = [
        ("colour", Value::from("red"), "jobs.line", "colour"),
        ("width", Value::from("16"), "jobs.line", "width"),
        ("width", Value::Null, "jobs.line", "width"),
        ("version", Value::from(2), "jobs.version", "version"),
        (
            "schema",
            Value::from("optics.tradeoff"),
            "jobs.schema",
            "schema",
        ),
        ("job", Value::from(999), "jobs.no_such_job", "job"),
        ("label", Value::from("faster"), "jobs.not_planned", "label"),
        ("spp", Value::from(4), "jobs.not_planned", "plan"),
    ];
    for (field, value, kind, named) in cases {
        let message = refused(&edited(field, value.clone()), kind, named);
        assert!(
            message.contains("edited.jsonl"),
            "{field} {value}: {message}"
        );
    }
    // A key given twice, even with the value it has, is refused by name.
    let twice = format!("{{\"width\": {}, ", lines[2]["width"]);
    let file = dir.path().join("twice.jsonl");
    std::fs::write(&file, lines[2].to_string().replacen('{', &twice, 1) + "\n").unwrap();
    let out = job_command(&file, "0", &results).output().unwrap();
    let message = refused(&out, "jobs.line", "width");
    assert!(message.contains(safe_io::json::TWICE), "{message}");
    // A line of JSON that is not an object is refused as such, not by
    // the fields serde would count in a list.
    for not_an_object in ["[]", "[1, 2]", "3", "null", "\"job\""] {
        let file = dir.path().join("not-an-object.jsonl");
        std::fs::write(&file, format!("{not_an_object}\n")).unwrap();
        let out = job_command(&file, "0", &results).output().unwrap();
        assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
        let error: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(error["error"]["kind"], "jobs.line", "{error}");
        let message = error["error"]["message"].as_str().unwrap();
        assert!(
            message.contains("JSON object"),
            "{not_an_object}: {message}"
        );
    }
    let file = dir.path().join("broken.jsonl");
    std::fs::write(&file, "{\"schema\": \"optics.tradeoff-job\",\n").unwrap();
    let out = job_command(&file, "0", &results).output().unwrap();
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    let error: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(error["error"]["kind"], "jobs.line", "{error}");
    assert!(error["error"]["field"].is_null(), "{error}");
    let message = error["error"]["message"].as_str().unwrap();
    assert!(
        message.contains("broken.jsonl:1: not an optics.tradeoff-job line"),
        "{message}"
    );
    let out = job_command(&jobs, "", &results).output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(2),
        "an INDEX that is not a number is a usage error"
    );
    let out = Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(["--json", "tradeoff-job"])
        .arg(&jobs)
        .output()
        .unwrap();
    refused(&out, "jobs.index_needed", "INDEX");
    assert!(!results.exists(), "nothing written");
    // An --out that is a file: refused by name before the render.
    let file = dir.path().join("a-file");
    std::fs::write(&file, b"x").unwrap();
    let message = refused(&run_job(&jobs, 2, &file), "jobs.write", "--out");
    assert!(message.contains("a-file"), "{message}");
}

#[test]
fn an_empty_plan_is_refused_as_holding_no_jobs_in_both_languages() {
    let dir = tempfile::tempdir().unwrap();
    let jobs = dir.path().join("empty.jsonl");
    std::fs::write(&jobs, b"").unwrap();
    let results = dir.path().join("results");
    let without_index = Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(["--json", "tradeoff-job"])
        .arg(&jobs)
        .output()
        .unwrap();
    let needed = refused(&without_index, "jobs.index_needed", "JOBS");
    assert!(needed.contains("holds no jobs"), "{needed}");
    let no_such = refused(&run_job(&jobs, 0, &results), "jobs.no_such_job", "INDEX");
    assert!(no_such.contains("has no jobs"), "{no_such}");
    for message in [needed, no_such] {
        assert!(!message.contains("0 to 0"), "a range of no jobs: {message}");
    }
    let hungarian = Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(["--json", "--lang", "hu", "tradeoff-job"])
        .arg(&jobs)
        .output()
        .unwrap();
    let message = refused(&hungarian, "jobs.index_needed", "JOBS");
    assert!(message.contains("nem tartalmaz feladatot"), "{message}");
    assert!(!results.exists(), "nothing written");
}
