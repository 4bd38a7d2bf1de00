//! `optics tradeoff`: the sweep's JSON is versioned, its Pareto marks are
//! the fronts of its own numbers, its errors obey the physics they measure
//! (the course shader's π, an unbiased path tracer's zero bias), the truth
//! is cached, and bad flags are refused by name with nothing written.
#![cfg(feature = "harness")]

use std::path::Path;
use std::process::{Command, Output};

use serde_json::Value;

fn optics(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the optics binary runs")
}

fn scene(name: &str) -> String {
    format!(
        "{}/../tracer/scenes/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    )
}

/// `optics --json tradeoff` on the scene `name`, small and quick, `extra`
/// given after (a flag in `extra` replaces the default of that flag).
fn sweep(name: &str, out: &Path, extra: &[&str]) -> Output {
    let path = scene(name);
    let out = out.to_str().unwrap();
    let defaults = [
        ("--width", "24"),
        ("--height", "18"),
        ("--truth-spp", "32"),
        ("--repeats", "2"),
        ("--min-seconds", "0"),
        ("--out", out),
    ];
    let mut args = vec!["--json", "tradeoff", &path, "--no-plot"];
    for (flag, value) in defaults {
        let given = extra
            .iter()
            .any(|e| *e == flag || e.starts_with(&format!("{flag}=")));
        if !given {
            args.extend([flag, value]);
        }
    }
    args.extend_from_slice(extra);
    optics(&args)
}

fn read(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The points no other beats on both median time and `measure`.
fn undominated(points: &[Value], measure: &str) -> Vec<String> {
    let at = |p: &Value| {
        (
            p["seconds_median"].as_f64().unwrap(),
            p["errors"][measure].as_f64().unwrap(),
        )
    };
    points
        .iter()
        .filter(|p| {
            let (t, e) = at(p);
            !points.iter().any(|q| {
                let (u, f) = at(q);
                u <= t && f <= e && (u < t || f < e)
            })
        })
        .map(|p| p["label"].as_str().unwrap().to_owned())
        .collect()
}

#[test]
fn the_sweep_of_a_scene_is_versioned_and_its_fronts_are_its_own_numbers() {
    let dir = tempfile::tempdir().unwrap();
    let out = sweep("shadow", dir.path(), &["--lambert"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let sweep = read(&dir.path().join("shadow-lambert.json"));
    assert_eq!(sweep["schema"], "optics.tradeoff");
    assert_eq!(sweep["version"], 2);
    assert!(dir.path().join("shadow-lambert.md").is_file());
    let points = sweep["points"].as_array().unwrap();
    assert_eq!(points[0]["axis"], "scene");
    for measure in ["rel_rmse", "delta_e_mean", "delta_e_p99", "flip_mean"] {
        let mut marked: Vec<String> = points
            .iter()
            .filter(|p| p["pareto"].as_array().unwrap().iter().any(|m| m == measure))
            .map(|p| p["label"].as_str().unwrap().to_owned())
            .collect();
        let mut want = undominated(points, measure);
        marked.sort();
        want.sort();
        assert_eq!(marked, want, "{measure}");
    }
    // No mirror or glass in `shadow`: no Fresnel axis, and it says so.
    assert!(points.iter().all(|p| p["axis"] != "fresnel"));
    assert!(sweep["skipped"]
        .as_array()
        .unwrap()
        .iter()
        .any(|s| s["axis"] == "fresnel"));
    // The stdout record carries the same sweep.
    let record: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(record["law"], "tradeoff");
    assert_eq!(record["details"]["sweep"]["points"], sweep["points"]);
    // ... and its findings, read from those points: the scene's own
    // whitted against local, and the light each integrator leaves out,
    // one minus the light its point carries (to 1e-12: a subtraction).
    let findings = &record["details"]["sweep"]["findings"];
    assert_eq!(*findings, sweep["findings"]);
    assert!(findings["local_against_whitted"].is_object(), "{findings}");
    let left_out = findings["light_left_out"]["integrators"]
        .as_array()
        .unwrap();
    assert_eq!(left_out[0]["integrator"], "whitted");
    let carried = points[0]["errors"]["light"].as_f64().unwrap();
    let left = left_out[0]["left_out"].as_f64().unwrap();
    assert!((1.0 - carried - left).abs() < 1e-12, "{carried} {left}");
    assert_eq!(
        sweep["rgb_against_spectrum"],
        serde_json::json!([]),
        "no metal"
    );
}

#[test]
fn the_measured_errors_obey_the_physics_they_measure() {
    let dir = tempfile::tempdir().unwrap();
    let out = sweep("shadow", dir.path(), &["--lambert", "--repeats", "4"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let sweep = read(&dir.path().join("shadow-lambert.json"));
    let point = |label: &str| {
        sweep["points"]
            .as_array()
            .unwrap()
            .iter()
            .find(|p| p["label"] == label)
            .unwrap_or_else(|| panic!("no point {label}"))
            .clone()
    };
    // The course shader reads Lambert's albedo as kd in 1/sr: π times too
    // bright where lit, so its relative error is above 1.
    let course = point("integrator course");
    assert!(
        course["errors"]["rel_rmse"].as_f64().unwrap() > 1.0,
        "{course}"
    );
    // The path tracer is unbiased: its squared bias is within the noise of
    // four renders, below its variance; its efficiency is 1/(variance × time).
    let path = point("integrator path, 16 spp");
    let split = &path["errors"]["split"];
    let (variance, bias) = (
        split["variance"].as_f64().unwrap(),
        split["bias_squared"].as_f64().unwrap(),
    );
    assert!(variance > 0.0 && bias < variance, "{split}");
    let efficiency = path["efficiency"].as_f64().unwrap();
    let want = 1.0 / (variance * path["seconds_median"].as_f64().unwrap());
    assert!((efficiency - want).abs() <= 1e-9 * want);
    // Deterministic settings have no split.
    assert!(point("integrator local")["errors"].get("split").is_none());
}

#[test]
fn the_truth_is_cached_and_rendered_again_on_request() {
    let dir = tempfile::tempdir().unwrap();
    let first = sweep("blinn_phong", dir.path(), &["--lambert"]);
    assert!(
        first.status.success(),
        "{}",
        String::from_utf8_lossy(&first.stderr)
    );
    let truth = |out: &Output| {
        let record: Value = serde_json::from_slice(&out.stdout).unwrap();
        record["details"]["sweep"]["truth"].clone()
    };
    assert_eq!(truth(&first)["cached"], false);
    let second = sweep("blinn_phong", dir.path(), &["--lambert"]);
    assert_eq!(truth(&second)["cached"], true);
    assert_eq!(truth(&second)["key"], truth(&first)["key"]);
    let fresh = sweep("blinn_phong", dir.path(), &["--lambert", "--fresh"]);
    assert_eq!(truth(&fresh)["cached"], false);
    // A cached image cut short is not used: the truth is rendered again,
    // and the record and the notes say why.
    let file = truth(&fresh)["file"].as_str().unwrap().to_owned();
    let bytes = std::fs::read(&file).unwrap();
    std::fs::write(&file, &bytes[..bytes.len() / 2]).unwrap();
    let cut = sweep("blinn_phong", dir.path(), &["--lambert"]);
    assert_eq!(truth(&cut)["cached"], false);
    assert_eq!(truth(&cut)["replaced"]["why"], "image", "{}", truth(&cut));
    let record: Value = serde_json::from_slice(&cut.stdout).unwrap();
    assert!(
        record["notes"]
            .to_string()
            .contains("the cached truth was not used"),
        "{record}"
    );
    assert_eq!(
        truth(&sweep("blinn_phong", dir.path(), &["--lambert"]))["cached"],
        true
    );
    // Another size is another truth.
    let other = sweep("blinn_phong", dir.path(), &["--lambert", "--width", "20"]);
    assert_eq!(truth(&other)["cached"], false);
    assert_ne!(truth(&other)["key"], truth(&first)["key"]);
}

#[test]
fn the_course_material_that_multiplies_light_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let out = sweep("shadow", dir.path(), &[]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let record: Value = serde_json::from_slice(&out.stdout).unwrap();
    let notes = record["notes"].to_string();
    assert!(
        notes.contains("the material green reflects up to 2.51 times"),
        "{notes}"
    );
}

#[test]
fn bad_flags_are_refused_by_name_and_nothing_is_written() {
    let dir = tempfile::tempdir().unwrap();
    for (flag, value) in [
        ("--repeats", "0"),
        ("--min-seconds", "NaN"),
        ("--min-seconds=-1", ""),
        ("--truth-spp", "1"),
        ("--width", "0"),
    ] {
        let args: Vec<&str> = [flag, value]
            .into_iter()
            .filter(|a| !a.is_empty())
            .collect();
        let out = sweep("shadow", dir.path(), &args);
        assert_eq!(out.status.code(), Some(2), "{flag} {value}");
        let flag = flag.split('=').next().unwrap();
        let error: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert!(
            error["error"]["field"].as_str().unwrap().contains(flag),
            "{flag}: {error}"
        );
    }
    let missing = sweep("no_such_scene", dir.path(), &[]);
    assert_eq!(missing.status.code(), Some(1));
    assert!(std::fs::read_dir(dir.path()).unwrap().next().is_none());
    // An --out that is a file: refused before any render, naming it.
    let file = dir.path().join("a-file");
    std::fs::write(&file, b"x").unwrap();
    let out = sweep("shadow", &file, &[]);
    assert_eq!(out.status.code(), Some(1));
    let error: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(
        error["error"]["message"]
            .as_str()
            .unwrap()
            .contains("a-file"),
        "{error}"
    );
}

#[test]
fn the_sweep_replaces_neither_its_scene_nor_what_is_not_a_regular_file() {
    // The record is SCENE.json in --out: the scene's own directory as
    // --out would write it over the scene.
    let dir = tempfile::tempdir().unwrap();
    let copy = dir.path().join("shadow.json");
    std::fs::copy(scene("shadow"), &copy).unwrap();
    let before = std::fs::read(&copy).unwrap();
    let elsewhere = dir.path().join("elsewhere");
    std::fs::create_dir_all(elsewhere.join("shadow.md")).unwrap();
    for (out, reason) in [
        (dir.path(), "which is being read"),
        (elsewhere.as_path(), "is not a regular file"),
    ] {
        let out = optics(&[
            "--json",
            "tradeoff",
            copy.to_str().unwrap(),
            "--no-plot",
            "--width",
            "16",
            "--height",
            "12",
            "--truth-spp",
            "16",
            "--repeats",
            "1",
            "--min-seconds",
            "0",
            "--out",
            out.to_str().unwrap(),
        ]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{stderr}");
        let error: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(error["error"]["kind"], "jobs.write", "{error}");
        assert_eq!(error["error"]["field"], "--out", "{error}");
        let message = error["error"]["message"].as_str().unwrap();
        assert!(message.contains(reason), "{message}");
    }
    assert_eq!(
        std::fs::read(&copy).unwrap(),
        before,
        "the scene is as it was"
    );
    assert!(elsewhere.join("shadow.md").is_dir());
    for out in [dir.path(), elsewhere.as_path()] {
        assert!(!out.join("truth").exists(), "refused before any render");
    }
}

#[test]
fn a_scene_without_light_has_nothing_to_trade_and_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let out = sweep("kaleidoscope", dir.path(), &["--truth-spp", "4"]);
    assert_eq!(out.status.code(), Some(1));
    let error: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(error["error"]["kind"], "tradeoff.truth_is_black");
    assert_eq!(error["error"]["field"], "SCENE");
    assert!(!dir.path().join("kaleidoscope.json").exists());
}

#[test]
fn the_text_says_what_was_not_swept_and_why_in_both_languages() {
    let dir = tempfile::tempdir().unwrap();
    let path = scene("shadow");
    let out_dir = dir.path().to_str().unwrap();
    for (lang, want) in [
        (
            "en",
            "not swept: fresnel: no mirror or glass: no Fresnel law is evaluated",
        ),
        ("hu", "nem mért: fresnel: nincs tükör vagy üveg"),
    ] {
        let out = optics(&[
            "--lang",
            lang,
            "tradeoff",
            &path,
            "--width",
            "16",
            "--height",
            "12",
            "--truth-spp",
            "4",
            "--repeats",
            "1",
            "--min-seconds",
            "0",
            "--no-plot",
            "--out",
            out_dir,
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(text.contains(want), "{lang}: {text}");
        assert!(
            text.contains("green"),
            "{lang}: the multiplying material is named: {text}"
        );
    }
}

/// A scene with a metal carries the harness's colour error of it: the
/// gold of `gold_spheres` (the course's `n, κ`, as the tracer holds them
/// in `f32`) against gold's measured spectrum, the same numbers
/// `validation::metals::three_channel_delta_e` gives (to 1e-12: JSON
/// keeps every bit); and its findings read the bounce limit into the
/// scene's own 63 and Schlick's law against the exact one.
#[test]
fn a_metal_scene_carries_its_metals_rgb_error_and_its_depth_and_schlick_findings() {
    use validation::metals::{self, MetalLaws, MetalsReference};
    let dir = tempfile::tempdir().unwrap();
    let out = sweep("gold_spheres", dir.path(), &["--lambert", "--repeats", "1"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let sweep = read(&dir.path().join("gold_spheres-lambert.json"));
    let rgb = &sweep["rgb_against_spectrum"][0];
    assert_eq!(rgb["material"], "gold");
    assert_eq!(rgb["outcome"], "measured");
    let reference = MetalsReference::load(&validation::reference::committed_dir()).unwrap();
    let gold = reference.metals.iter().find(|m| m.name == "gold").unwrap();
    let f32s = |v: [f64; 3]| v.map(|x| f64::from(x as f32));
    let want = metals::three_channel_delta_e(
        &MetalLaws::radiometry(),
        gold,
        f32s(radiometry::course::GOLD_000_N),
        f32s(radiometry::course::GOLD_000_KAPPA),
    )
    .unwrap();
    let got = rgb["delta_e"].as_array().unwrap();
    assert_eq!(got.len(), want.len());
    for (g, (_, w)) in got.iter().zip(&want) {
        assert!((g.as_f64().unwrap() - w).abs() < 1e-12, "{g} {w}");
    }
    let findings = &sweep["findings"];
    assert_eq!(findings["bounces"]["own"], 63);
    assert!(
        findings["bounces"]["steps"]
            .as_array()
            .unwrap()
            .iter()
            .any(|s| s["to"] == 63),
        "{findings}"
    );
    assert!(
        findings["schlick"]["shortcut"]["label"] == "fresnel schlick-rarer",
        "{findings}"
    );
}

/// A plot that cannot be drawn (a checkout without its Python
/// environment) leaves no record behind: the sweep writes its JSON, its
/// Markdown and its plot, or none of them. With `--no-plot` the same
/// sweep writes the other two.
#[test]
fn a_sweep_whose_plot_cannot_be_drawn_writes_nothing() {
    let checkout = tempfile::tempdir().unwrap();
    std::fs::create_dir_all(checkout.path().join("validation/reference")).unwrap();
    std::fs::create_dir_all(checkout.path().join("python-checks")).unwrap();
    std::fs::write(checkout.path().join("python-checks/requirements.txt"), "").unwrap();
    let dir = tempfile::tempdir().unwrap();
    let (path, out) = (scene("shadow"), dir.path().to_str().unwrap().to_owned());
    let args = [
        "--json",
        "tradeoff",
        &path,
        "--lambert",
        "--width",
        "8",
        "--height",
        "6",
        "--truth-spp",
        "4",
        "--repeats",
        "1",
        "--min-seconds",
        "0",
        "--out",
        &out,
    ];
    let run = |extra: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_optics"))
            .args(args)
            .args(extra)
            .env("OPTICS_CHECKOUT", checkout.path())
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .output()
            .expect("the optics binary runs")
    };
    let failed = run(&[]);
    assert_eq!(
        failed.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&failed.stderr)
    );
    let error: Value = serde_json::from_slice(&failed.stdout).unwrap();
    assert!(
        error["error"]["message"]
            .as_str()
            .unwrap()
            .contains("--no-plot"),
        "{error}"
    );
    for file in [
        "shadow-lambert.json",
        "shadow-lambert.md",
        "shadow-lambert-pareto.png",
    ] {
        assert!(!dir.path().join(file).exists(), "{file} written");
    }
    assert!(run(&["--no-plot"]).status.success());
    assert!(dir.path().join("shadow-lambert.json").exists());
    assert!(dir.path().join("shadow-lambert.md").exists());
}
