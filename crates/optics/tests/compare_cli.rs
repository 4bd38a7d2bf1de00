//! `optics compare` through the binary: the course shader's render of a
//! course scene recognised as different from the physical one, the
//! physical render as agreeing (a Whitted scene as PNG and PFM, a
//! path-traced one as a mean with its variance), a planted error in one
//! object found and attributed to it, and bad inputs refused by kind and
//! field with no difference map written.
#![cfg(feature = "harness")]

mod support;
use support::{listing, optics};

use std::path::{Path, PathBuf};

use serde_json::Value;
use tracer::job::{Overrides, RenderJob};
use tracer::output::pfm_bytes;
use tracer::render::Image;
use tracer::scene::{IntegratorKind, RenderSpec};

/// The size the tests render at: small, so the debug build stays quick.
const SIZE: (u32, u32) = (32, 24);

fn scene(name: &str) -> String {
    format!(
        "{}/../tracer/scenes/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    )
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// `optics render` at [`SIZE`]: the PNG, and the PFM beside it.
fn render(dir: &Path, scene: &str, name: &str, extra: &[&str]) -> PathBuf {
    let png = dir.join(format!("{name}.png"));
    let (w, h) = (SIZE.0.to_string(), SIZE.1.to_string());
    let mut args = vec![
        "render",
        scene,
        "-o",
        png.to_str().unwrap(),
        "--width",
        &w,
        "--height",
        &h,
    ];
    args.extend_from_slice(extra);
    let out = optics(&args);
    assert!(out.status.success(), "{}", text(&out.stderr));
    png
}

/// `optics --json compare IMAGE --scene SCENE ARGS…`: the record, after
/// checking the exit status says the verdict.
fn compare(image: &Path, scene: &str, extra: &[&str]) -> Value {
    let mut args = vec![
        "--json",
        "compare",
        image.to_str().unwrap(),
        "--scene",
        scene,
    ];
    args.extend_from_slice(extra);
    let out = optics(&args);
    let record: Value = serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|_| panic!("{}{}", text(&out.stdout), text(&out.stderr)));
    let agrees = record["answer"] == Value::Bool(true);
    assert_eq!(out.status.success(), agrees, "{record}");
    assert!(!text(&out.stderr).contains("panicked"));
    record
}

/// The region of `record` that is object `object`.
fn region(record: &Value, object: u64) -> &Value {
    record["details"]["regions"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["object"] == object)
        .unwrap_or_else(|| panic!("no object {object} in {record}"))
}

#[test]
fn the_physical_whitted_render_agrees_and_the_course_shaders_does_not() {
    let dir = tempfile::tempdir().unwrap();
    let s = scene("gold_spheres");
    let physical = render(dir.path(), &s, "physical", &[]);
    let course = render(dir.path(), &s, "course", &["--integrator", "course"]);
    for image in [physical.clone(), physical.with_extension("pfm")] {
        let record = compare(&image, &s, &[]);
        assert_eq!(record["answer"], true, "{record}");
        assert_eq!(record["details"]["pixels_disagreeing"], 0);
        assert!(record["details"]["pixels_compared"].as_u64().unwrap() > 600);
    }
    let diff = dir.path().join("diff.png");
    for image in [course.clone(), course.with_extension("pfm")] {
        let record = compare(&image, &s, &["--diff", diff.to_str().unwrap()]);
        assert_eq!(record["answer"], false, "{record}");
        // The course's reversed Fresnel darkens both gold spheres: every
        // pixel of each disagrees, and by tens of percent.
        for object in [0, 1] {
            let r = region(&record, object);
            assert_eq!(r["disagreeing"], r["pixels"], "{r}");
            assert!(r["relative_difference"].as_f64().unwrap() < -0.2, "{r}");
        }
    }
    let map = image::open(&diff).unwrap().to_rgb8();
    assert_eq!(map.dimensions(), SIZE);
    // A gold sphere's pixel disagrees: magenta.
    assert_eq!(map.get_pixel(19, 6).0, [255, 0, 255]);
}

/// `samples` renders at one sample per pixel with seeds 0, 1, …: the mean
/// and per-sample variance as a user's renderer would give them.
fn mean_and_variance(scene: &str, samples: u32) -> (Image, Image) {
    // Settled as `optics render --integrator path` settles it: box filtered.
    let overrides = Overrides {
        render: RenderSpec {
            integrator: Some(IntegratorKind::Path),
            ..RenderSpec::default()
        },
        width: Some(SIZE.0),
        height: Some(SIZE.1),
        ..Overrides::default()
    };
    let job = RenderJob::load(Path::new(scene), &overrides).unwrap();
    let settings = *job.settings();
    let (mean, variance) = validation::renders::sample_statistics(
        validation::renders::tracer_render,
        job.scene(),
        settings,
        0..u64::from(samples),
    )
    .unwrap();
    let image = |v: &[f64]| Image {
        width: SIZE.0,
        height: SIZE.1,
        pixels: v
            .chunks(3)
            .map(|c| glam::Vec3::new(c[0] as f32, c[1] as f32, c[2] as f32))
            .collect(),
    };
    (image(&mean), image(&variance))
}

#[test]
fn a_path_traced_mean_with_its_variance_agrees_by_welchs_test() {
    let dir = tempfile::tempdir().unwrap();
    let s = scene("webgl_seven_spheres");
    let (mean, variance) = mean_and_variance(&s, 64);
    let (mean_pfm, variance_pfm) = (dir.path().join("mean.pfm"), dir.path().join("var.pfm"));
    std::fs::write(&mean_pfm, pfm_bytes(&mean)).unwrap();
    std::fs::write(&variance_pfm, pfm_bytes(&variance)).unwrap();
    let args = [
        "--integrator",
        "path",
        "--variance",
        variance_pfm.to_str().unwrap(),
        "--samples",
        "64",
    ];
    let record = compare(&mean_pfm, &s, &args);
    assert_eq!(record["answer"], true, "{record}");
    let tests = record["details"]["t_tests"]["count"].as_u64().unwrap();
    assert!(tests > 1000, "{record}");
    // The course shader's render, deterministic, against the path reference.
    let course = render(dir.path(), &s, "course", &["--integrator", "course"]);
    let record = compare(&course.with_extension("pfm"), &s, &["--integrator", "path"]);
    assert_eq!(record["answer"], false, "{record}");
    assert!(
        record["details"]["fraction_disagreeing"].as_f64().unwrap() > 0.5,
        "{record}"
    );
}

#[test]
fn one_objects_colour_changed_by_three_percent_is_found_in_that_object_alone() {
    let dir = tempfile::tempdir().unwrap();
    let s = scene("webgl_seven_spheres");
    let png = render(dir.path(), &s, "physical", &[]);
    let pfm = png.with_extension("pfm");
    let mut image = tracer::output::read_pfm(&std::fs::read(&pfm).unwrap()).unwrap();
    let overrides = Overrides {
        width: Some(SIZE.0),
        height: Some(SIZE.1),
        ..Overrides::default()
    };
    let job = RenderJob::load(Path::new(&s), &overrides).unwrap();
    // Object 1, the red sphere, 3 % brighter in its red channel.
    const PLANTED: u32 = 1;
    for (pixel, hit) in image.pixels.iter_mut().zip(job.first_hits()) {
        if hit == Some(PLANTED) {
            pixel.x *= 1.03;
        }
    }
    std::fs::write(&pfm, pfm_bytes(&image)).unwrap();
    let record = compare(&pfm, &s, &[]);
    assert_eq!(record["answer"], false, "{record}");
    for r in record["details"]["regions"].as_array().unwrap() {
        let disagreeing = r["disagreeing"].as_u64().unwrap();
        if r["object"] == u64::from(PLANTED) {
            assert_eq!(r["disagreeing"], r["pixels"], "{r}");
            assert!(disagreeing > 0);
            // 3 % of the red channel is 1 % of the three channels' sum at most.
            let relative = r["relative_difference"].as_f64().unwrap();
            assert!(relative > 0.0 && relative <= 0.03 + 1e-6, "{r}");
            assert_eq!(r["worst_at"][2], "R");
        } else {
            assert_eq!(disagreeing, 0, "{r}");
        }
    }
}

/// The JSON error object of a failed compare, after checking the exit
/// status, the Hungarian message on stderr and that no map was written.
fn refused(dir: &Path, args: &[&str]) -> Value {
    let before = listing(dir);
    let mut all = vec!["--json", "--lang", "hu", "compare"];
    all.extend_from_slice(args);
    let out = optics(&all);
    assert_ne!(out.status.code(), Some(0), "{args:?}");
    let stderr = text(&out.stderr);
    assert!(stderr.starts_with("hiba: "), "{stderr:?}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert_eq!(listing(dir), before, "a file was written");
    let record: Value = serde_json::from_slice(&out.stdout).unwrap();
    record["error"].clone()
}

#[test]
fn bad_inputs_are_refused_by_kind_and_field() {
    let dir = tempfile::tempdir().unwrap();
    let s = scene("gold_spheres");
    let png = render(dir.path(), &s, "physical", &[]);
    let pfm = png.with_extension("pfm");
    let p = |path: &Path| path.to_str().unwrap().to_owned();
    let write = |name: &str, bytes: &[u8]| {
        let path = dir.path().join(name);
        std::fs::write(&path, bytes).unwrap();
        p(&path)
    };
    let text_file = write("notes.txt", b"not an image");
    let truncated = write("truncated.pfm", &std::fs::read(&pfm).unwrap()[..100]);
    let huge = write(
        "huge.pfm",
        &pfm_bytes(&Image {
            width: 20_000,
            height: 1,
            pixels: vec![glam::Vec3::ZERO; 20_000],
        }),
    );
    let small = write(
        "small.pfm",
        &pfm_bytes(&Image {
            width: 4,
            height: 3,
            pixels: vec![glam::Vec3::ONE; 12],
        }),
    );
    let mut nan = tracer::output::read_pfm(&std::fs::read(&pfm).unwrap()).unwrap();
    nan.pixels[40].y = f32::NAN;
    let nan = write("nan.pfm", &pfm_bytes(&nan));
    let missing = p(&dir.path().join("missing.png"));
    let diff = p(&dir.path().join("diff.png"));
    let (png, pfm) = (p(&png), p(&pfm));
    let cases: Vec<(Vec<&str>, &str, &str)> = vec![
        (vec![&missing, "--scene", &s], "compare.read", "IMAGE"),
        (
            vec![&text_file, "--scene", &s],
            "compare.unknown_format",
            "IMAGE",
        ),
        (vec![&truncated, "--scene", &s], "compare.pfm", "IMAGE"),
        (vec![&nan, "--scene", &s], "compare.bad_value", "IMAGE"),
        (vec![&huge, "--scene", &s], "compare.size", "IMAGE"),
        (
            vec![&pfm, "--scene", &s, "--variance", &small, "--samples", "8"],
            "compare.size_mismatch",
            "--variance",
        ),
        (
            vec![&pfm, "--scene", &s, "--variance", &png, "--samples", "8"],
            "compare.variance_needs_pfm",
            "--variance",
        ),
        (
            vec![&png, "--scene", &s, "--variance", &pfm, "--samples", "8"],
            "compare.variance_needs_pfm",
            "IMAGE",
        ),
        (
            vec![&pfm, "--scene", &s, "--integrator", "course"],
            "compare.course_reference",
            "--integrator",
        ),
        (
            vec![&pfm, "--scene", &s, "--variance", &pfm],
            "usage",
            "--samples <SAMPLES>",
        ),
        (
            vec![&pfm, "--scene", &s, "--diff", &pfm],
            "compare.diff",
            "--diff",
        ),
    ];
    for (args, kind, field) in cases {
        let error = refused(dir.path(), &args);
        assert_eq!(error["kind"], kind, "{args:?}: {error}");
        assert_eq!(error["field"], field, "{args:?}: {error}");
    }
    // A disagreement is the answer: without --json, an error of its own
    // kind and exit status 1, the map written.
    let out = optics(&[
        "--lang", "hu", "compare", &small, "--scene", &s, "--diff", &diff,
    ]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = text(&out.stderr);
    assert!(
        stderr.starts_with("hiba: a kép ") && stderr.contains("helyen eltér"),
        "{stderr}"
    );
    assert!(Path::new(&diff).is_file());
}
