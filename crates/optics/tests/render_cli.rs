//! `optics render` and `optics inspect` through the binary: outputs, the
//! JSON record, thread-count independence, and bad scene files refused with
//! the JSON path, a non-zero exit, no panic and no file written.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use serde_json::Value;

fn optics(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(args)
        .output()
        .expect("the optics binary runs")
}

fn scene(name: &str) -> String {
    format!(
        "{}/../tracer/scenes/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    )
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

fn render_small(scene_path: &str, png: &Path, extra: &[&str]) -> Output {
    let png = png.to_str().unwrap();
    let mut args = vec![
        "render", scene_path, "-o", png, "--width", "32", "--height", "24",
    ];
    args.extend_from_slice(extra);
    optics(&args)
}

#[test]
fn render_writes_a_png_and_a_pfm_and_prints_a_summary() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("gold.png");
    let out = render_small(&scene("gold_spheres"), &png, &[]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    let pfm = std::fs::read(png.with_extension("pfm")).unwrap();
    assert!(pfm.starts_with(b"PF\n32 24\n-1.0\n"));
    assert_eq!(pfm.len(), "PF\n32 24\n-1.0\n".len() + 32 * 24 * 12);
    let summary = text(&out.stdout);
    assert!(
        summary.contains("32×24 whitted") && summary.contains("rays/s"),
        "{summary}"
    );
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(&png).unwrap().permissions().mode() & 0o777;
        assert_eq!(
            mode, 0o644,
            "an ordinary file, not the temporary file's 0600"
        );
    }
    // Only the two images are left in the directory: no temporary files.
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
}

/// Samples a deterministic integrator cannot use are said to be dropped
/// in the text too, not only in `--json`'s notes: `--spp 4` under
/// `whitted` renders one sample per pixel, and says so.
#[test]
fn samples_a_deterministic_render_drops_are_said_in_the_text() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("shadow.png");
    let out = render_small(&scene("shadow"), &png, &["--spp", "4"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let said = text(&out.stdout);
    assert!(
        said.contains("4 samples per pixel reduced to 1: the whitted integrator is deterministic"),
        "{said}"
    );
    let out = render_small(&scene("shadow"), &png, &["--spp", "1"]);
    assert!(!text(&out.stdout).contains("reduced to 1"));
}

#[test]
fn render_json_record_has_the_documented_fields() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("k.png");
    let png_arg = png.to_str().unwrap();
    let out = optics(&[
        "--json",
        "render",
        &scene("kaleidoscope_lit"),
        "-o",
        png_arg,
        "--width",
        "32",
        "--height",
        "24",
        "--integrator",
        "path",
        "--spp",
        "2",
        "--seed",
        "5",
        "--max-depth",
        "4",
        "--fresnel",
        "schlick-rarer",
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let record: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(record["law"], "render");
    // The flags as given, and the settings as settled.
    assert_eq!(record["inputs"]["integrator"], "path");
    assert_eq!(record["inputs"]["spp"], 2);
    assert_eq!(record["inputs"]["output"], png_arg);
    assert_eq!(record["details"]["settings"]["integrator"], "path");
    assert_eq!(record["details"]["settings"]["fresnel"], "schlick-rarer");
    assert_eq!(record["details"]["settings"]["spp"], 2);
    // No filter given: the path integrator's default, settled and shown.
    assert_eq!(record["details"]["settings"]["pixel_filter"], "box");
    assert!(record["inputs"].get("pixel_filter").is_none());
    assert_eq!(record["unit"], "");
    assert!(record["details"]["rays_total"].as_u64().unwrap() >= 32 * 24 * 2);
    assert!(record["details"]["rays_per_second"].as_f64().unwrap() > 0.0);
    assert_eq!(record["details"]["png"], png_arg);
    let pfm = png.with_extension("pfm");
    assert_eq!(
        record["answer"],
        serde_json::json!([png_arg, pfm.to_str().unwrap()])
    );
    let steps = record["steps"].as_array().unwrap();
    assert_eq!(steps.len(), 1, "the summary line: {steps:?}");
    assert!(
        steps[0].as_str().unwrap().contains("32×24 path"),
        "{steps:?}"
    );
}

/// `--pixel-filter` over the integrator's default: a Whitted render box
/// filtered takes all its samples; the path tracer through the centres.
#[test]
fn the_pixel_filter_flag_is_settled_over_the_integrators_default() {
    let dir = tempfile::tempdir().unwrap();
    for (integrator, filter, spp_taken) in [
        ("whitted", "box", 4),
        ("path", "center", 4),
        ("whitted", "center", 1),
    ] {
        let png = dir.path().join(format!("{integrator}-{filter}.png"));
        let out = optics(&[
            "--json",
            "render",
            &scene("gold_spheres"),
            "-o",
            png.to_str().unwrap(),
            "--width",
            "16",
            "--height",
            "12",
            "--integrator",
            integrator,
            "--pixel-filter",
            filter,
            "--spp",
            "4",
        ]);
        assert!(out.status.success(), "{}", text(&out.stderr));
        let record: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(record["inputs"]["pixel_filter"], filter);
        assert_eq!(record["details"]["settings"]["pixel_filter"], filter);
        assert_eq!(
            record["details"]["samples_per_pixel_taken"], spp_taken,
            "{integrator} {filter}"
        );
    }
    let out = optics(&[
        "render",
        &scene("gold_spheres"),
        "-o",
        "x.png",
        "--pixel-filter",
        "gaussian",
    ]);
    assert!(!out.status.success());
    assert!(
        text(&out.stderr).contains("--pixel-filter"),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn render_is_identical_for_one_and_two_threads() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a.png"), dir.path().join("b.png"));
    let flags = |t: &'static str| ["--integrator", "path", "--spp", "3", "--threads", t];
    assert!(render_small(&scene("webgl_seven_spheres"), &a, &flags("1"))
        .status
        .success());
    assert!(render_small(&scene("webgl_seven_spheres"), &b, &flags("2"))
        .status
        .success());
    assert_eq!(
        std::fs::read(a.with_extension("pfm")).unwrap(),
        std::fs::read(b.with_extension("pfm")).unwrap()
    );
}

#[test]
fn course_integrator_refuses_glass_with_the_material_path() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("glass.json");
    std::fs::write(
        &file,
        r#"{"version": 1, "image": {"width": 8, "height": 8}, "camera": {"type": "course_pinhole"},
            "materials": {"glass": {"type": "dielectric", "eta": 1.5}},
            "objects": [{"type": "sphere", "center": [0, 0, 4], "radius": 1, "material": "glass"}]}"#,
    )
    .unwrap();
    let png = dir.path().join("out.png");
    let out = render_small(file.to_str().unwrap(), &png, &["--integrator", "course"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stderr).contains("materials.glass"),
        "{}",
        text(&out.stderr)
    );
    assert!(!png.exists());
}

fn bad_scene(name: &str, edit: impl Fn(&mut Value)) -> (String, PathBuf) {
    let mut value: Value =
        serde_json::from_str(&std::fs::read_to_string(scene("kaleidoscope")).unwrap()).unwrap();
    edit(&mut value);
    (name.to_owned(), PathBuf::from(value.to_string()))
}

/// One case per line: the bad scene and the path its error must name.
#[test]
fn bad_scene_files_exit_non_zero_naming_the_json_path_without_panic_or_output() {
    let dir = tempfile::tempdir().unwrap();
    let cases: Vec<((String, PathBuf), &str)> = vec![
        (
            ("syntax".into(), PathBuf::from("{\"version\": 1,")),
            "line 1",
        ),
        (
            bad_scene("unknown field", |v| v["camera"]["zoom"] = 2.into()),
            "camera.zoom: unknown field `zoom`",
        ),
        (
            bad_scene("negative radius", |v| {
                v["objects"][0]["radius"] = (-0.8).into()
            }),
            "objects[0].radius",
        ),
        (
            bad_scene("zero direction", |v| {
                v["lights"][0]["towards"] = serde_json::json!([0, 0, 0])
            }),
            "lights[0].towards",
        ),
        (
            bad_scene("zero-sided tube", |v| v["objects"][3]["sides"] = 0.into()),
            "objects[3].sides",
        ),
        (
            bad_scene("huge image", |v| {
                v["image"] = serde_json::json!({"width": 1_000_000, "height": 1_000_000})
            }),
            "image.width",
        ),
        (
            bad_scene("spp 0", |v| v["render"]["spp"] = 0.into()),
            "render.spp",
        ),
        (
            bad_scene("bare schlick", |v| {
                v["render"]["fresnel"] = "schlick".into()
            }),
            "render.fresnel: \"schlick\" names neither of Schlick's forms",
        ),
        (
            (
                "NaN".into(),
                PathBuf::from(
                    std::fs::read_to_string(scene("kaleidoscope"))
                        .unwrap()
                        .replacen("0.8", "NaN", 1),
                ),
            ),
            "line",
        ),
    ];
    for ((name, contents), needle) in cases {
        let file = dir.path().join(format!("{}.json", name.replace(' ', "_")));
        std::fs::write(&file, contents.to_str().unwrap()).unwrap();
        let png = dir.path().join(format!("{}.png", name.replace(' ', "_")));
        let out = optics(&[
            "render",
            file.to_str().unwrap(),
            "-o",
            png.to_str().unwrap(),
        ]);
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{name}: {stderr}");
        assert!(
            stderr.contains(needle),
            "{name}: {stderr:?} lacks {needle:?}"
        );
        assert!(!stderr.contains("panicked"), "{name}: {stderr}");
        assert!(
            !png.exists() && !png.with_extension("pfm").exists(),
            "{name} wrote an image"
        );
        // The same through inspect.
        let out = optics(&["--json", "inspect", file.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(1), "{name}");
        let record: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert!(
            record["error"]["message"]
                .as_str()
                .unwrap()
                .contains(needle),
            "{name}"
        );
    }
}

/// `--fresnel schlick` names no form: refused at `overrides.fresnel` with
/// both forms named, in the JSON error and in Hungarian, and nothing is
/// written.
#[test]
fn a_bare_schlick_fresnel_flag_is_refused_naming_both_forms() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("x.png");
    let scene = scene("gold_spheres");
    let args = [
        "render",
        &scene,
        "-o",
        png.to_str().unwrap(),
        "--fresnel",
        "schlick",
    ];
    let out = optics(&[&["--json"], &args[..]].concat());
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    let record: Value = serde_json::from_slice(&out.stdout).unwrap();
    let error = &record["error"];
    assert_eq!(error["kind"], "scene.schlick_form_unnamed", "{record}");
    assert_eq!(error["field"], "overrides.fresnel", "{record}");
    let message = error["message"].as_str().unwrap();
    assert!(
        message.contains("\"schlick-incident\"") && message.contains("\"schlick-rarer\""),
        "{message}"
    );
    let hu = optics(&[&["--lang", "hu"], &args[..]].concat());
    let hu = text(&hu.stderr);
    assert!(
        hu.contains("overrides.fresnel: a \"schlick\" Schlick két alakja"),
        "{hu}"
    );
    assert!(!png.exists());
}

#[test]
fn zero_samples_and_absurd_sizes_on_the_command_line_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("x.png");
    for (flag, value) in [
        ("--spp", "0"),
        ("--width", "1000000"),
        ("--threads", "0"),
        ("--max-depth", "-1"),
        ("--photons", "0"),
        ("--photon-passes", "0"),
    ] {
        let arg = format!("{flag}={value}");
        let out = optics(&[
            "render",
            &scene("normals"),
            "-o",
            png.to_str().unwrap(),
            &arg,
        ]);
        assert_eq!(out.status.code(), Some(2), "{flag} {value}");
        assert!(text(&out.stderr).contains(flag), "{}", text(&out.stderr));
    }
    assert!(!png.exists());
}

/// The photon integrator from the command line: its settings in the
/// record as settled, the photon pass's rays among the rays; a bad radius,
/// or photons over the passes beyond what the maps hold, refused naming
/// the flag's field, with no file written.
#[test]
fn photon_settings_are_taken_from_the_command_line_and_refused_by_name() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("glass.png");
    let photon = [
        "--integrator",
        "photon",
        "--spp",
        "2",
        "--photons",
        "3000",
        "--photon-passes",
        "2",
        "--photon-radius",
        "0.1",
    ];
    let mut args = vec!["--json", "render", "-o", png.to_str().unwrap()];
    let glass = scene("glass_spheres");
    args.extend([glass.as_str(), "--width", "16", "--height", "12"]);
    args.extend(photon);
    let out = optics(&args);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let record: Value = serde_json::from_slice(&out.stdout).unwrap();
    let settings = &record["details"]["settings"];
    assert_eq!(settings["integrator"], "photon");
    assert_eq!(settings["photon"]["photons"], 3000);
    assert_eq!(settings["photon"]["passes"], 2);
    assert_eq!(settings["photon"]["radius"], 0.1);
    assert!(record["details"]["rays"]["photon"].as_u64().unwrap() > 0);
    assert!(png.exists());
    for (extra, field) in [
        ("--photon-radius=-1", "overrides.photon_radius"),
        ("--photon-radius=NaN", "overrides.photon_radius"),
        ("--photons=4194304", "overrides.photons"),
    ] {
        let bad = dir.path().join("bad.png");
        let out = render_small(&glass, &bad, &["--integrator", "photon", extra]);
        assert!(!out.status.success(), "{extra:?}");
        assert!(
            text(&out.stderr).contains(field),
            "{extra:?}: {}",
            text(&out.stderr)
        );
        assert!(
            !text(&out.stderr).contains("panicked"),
            "{}",
            text(&out.stderr)
        );
        assert!(!bad.exists(), "{extra:?}");
    }
}

#[test]
fn inspect_reports_needs_and_measures_the_skipped_shadow_rays() {
    let out = optics(&[
        "--json",
        "inspect",
        &scene("blinn_phong"),
        "--width",
        "32",
        "--height",
        "24",
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let record: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(record["law"], "inspect");
    let needs = &record["answer"];
    assert_eq!(needs["shadows"], false);
    assert_eq!(needs["reflection_depth"], "none");
    let skipped = record["details"]["skipped"].as_array().unwrap();
    let shadow = skipped.iter().find(|s| s["part"] == "shadow_rays").unwrap();
    // One shadow ray per lit pixel of the sphere would have been cast.
    assert!(shadow["extra_rays"].as_i64().unwrap() > 0);
    assert_eq!(shadow["image_identical"], true);

    let out = optics(&[
        "inspect",
        &scene("kaleidoscope"),
        "--width",
        "32",
        "--height",
        "24",
    ]);
    let report = text(&out.stdout);
    assert!(
        report.contains("reflection depth reachable: up to 11"),
        "{report}"
    );
    assert!(report.contains("shadows possible: no"), "{report}");
    assert!(
        report.contains("light 0 (directional) skipped: the closed mirror tube around the camera"),
        "{report}"
    );
    // Each light says whether it is used, in words: "lights used: 0
    // directional" read as no light at all.
    assert!(
        report.contains(
            "lights: light 0 (directional) not used: the closed mirror tube around the camera"
        ),
        "{report}"
    );
    // The part switched back on is named in words, not by its record key.
    assert!(
        report.contains("the unused lights: would cost") && report.contains("image identical: yes"),
        "{report}"
    );
    assert!(!report.contains("unused_lights"), "{report}");
    let lit = text(
        &optics(&[
            "inspect",
            &scene("shadow"),
            "--width",
            "16",
            "--height",
            "12",
        ])
        .stdout,
    );
    assert!(lit.contains("lights: light 0 (directional) used"), "{lit}");
}

/// `inspect` takes the settings `render` takes, and settles them the same
/// way: its record shows them.
#[test]
fn inspect_takes_every_setting_render_takes() {
    let out = optics(&[
        "--json",
        "inspect",
        &scene("webgl_seven_spheres"),
        "--width",
        "16",
        "--height",
        "12",
        "--integrator",
        "path",
        "--spp",
        "2",
        "--max-depth",
        "3",
        "--fresnel",
        "schlick-incident",
        "--seed",
        "9",
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let record: Value = serde_json::from_slice(&out.stdout).unwrap();
    let settings = &record["details"]["settings"];
    assert_eq!(settings["integrator"], "path");
    assert_eq!(settings["spp"], 2);
    assert_eq!(settings["max_depth"], 3);
    assert_eq!(settings["fresnel"], "schlick-incident");
    assert_eq!(settings["seed"], 9);
    assert_eq!(record["answer"]["reflection_depth"]["up_to_max_depth"], 3);
    assert_eq!(record["inputs"]["max_depth"], 3);
    assert_eq!(record["inputs"]["seed"], 9);
}
