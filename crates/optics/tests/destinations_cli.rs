//! `optics render`'s destination checked before the render, through the
//! binary: what is not a regular file is refused and kept as it was, the
//! scene being read is never overwritten (under any of its names), and an
//! unwritable directory is reported as such instead of after the render.
//! Each refusal names `--output`, exits non-zero and writes nothing.

mod support;
use support::listing;

use std::path::Path;
use std::process::{Command, Output};

use serde_json::Value;

fn scene(name: &str) -> String {
    format!(
        "{}/../tracer/scenes/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    )
}

/// `optics --json render SCENE -o PNG` at 8×6.
fn render(scene: &Path, png: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_optics"))
        .arg("--json")
        .arg("render")
        .arg(scene)
        .arg("-o")
        .arg(png)
        .args(["--width", "8", "--height", "6"])
        .output()
        .expect("the optics binary runs")
}

/// The refusal's kind, after checking that it is a clean refusal of
/// `--output`: exit status 1, no panic, the field named.
fn refused(out: &Output) -> String {
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    let error: Value = serde_json::from_str(&String::from_utf8_lossy(&out.stdout))
        .unwrap_or_else(|e| panic!("{e}: {stderr}"));
    assert_eq!(error["error"]["field"], "--output", "{error}");
    error["error"]["kind"]
        .as_str()
        .unwrap_or_default()
        .to_owned()
}

#[cfg(unix)]
#[test]
fn an_output_on_a_fifo_is_refused_and_the_fifo_kept() {
    use std::os::unix::fs::FileTypeExt;
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("out.png");
    let made = Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    let out = render(Path::new(&scene("shadow")), &fifo);
    assert_eq!(refused(&out), "output.not_a_regular_file");
    let kept = std::fs::symlink_metadata(&fifo).unwrap().file_type();
    assert!(kept.is_fifo(), "the FIFO was replaced: {kept:?}");
    assert_eq!(listing(dir.path()), ["out.png"]);
}

/// A device node of its own (a copy of `/dev/null`, made with `mknod`), so
/// that a writer that replaced device nodes would replace only the test's.
#[cfg(unix)]
#[test]
fn an_output_on_a_device_node_is_refused() {
    use std::os::unix::fs::FileTypeExt;
    let dir = tempfile::tempdir().unwrap();
    let device = dir.path().join("null.png");
    let made = Command::new("mknod")
        .args(["-m", "666"])
        .arg(&device)
        .args(["c", "1", "3"])
        .status()
        .unwrap();
    if !made.success() {
        eprintln!("mknod is not permitted here (not root): the device case is not run");
        return;
    }
    let out = render(Path::new(&scene("shadow")), &device);
    assert_eq!(refused(&out), "output.not_a_regular_file");
    let kept = std::fs::symlink_metadata(&device).unwrap().file_type();
    assert!(kept.is_char_device(), "the device was replaced: {kept:?}");
    assert_eq!(listing(dir.path()), ["null.png"]);
}

#[test]
fn a_pfm_that_is_a_directory_is_refused_and_no_png_is_left() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("out.pfm")).unwrap();
    let out = render(Path::new(&scene("shadow")), &dir.path().join("out.png"));
    assert_eq!(refused(&out), "output.not_a_regular_file");
    assert_eq!(listing(dir.path()), ["out.pfm"]);
}

#[test]
fn an_output_that_is_the_scene_is_refused_and_the_scene_kept() {
    let dir = tempfile::tempdir().unwrap();
    let copy = dir.path().join("scene.json");
    std::fs::copy(scene("shadow"), &copy).unwrap();
    let before = std::fs::read(&copy).unwrap();
    // The PNG as the scene, by its own name and by another.
    for png in [copy.clone(), dir.path().join(".").join("scene.json")] {
        let out = render(&copy, &png);
        assert_eq!(refused(&out), "output.is_an_input", "{}", png.display());
    }
    // The PFM as the scene: `-o scene.png` beside a scene named scene.pfm.
    let pfm = dir.path().join("scene.pfm");
    std::fs::rename(&copy, &pfm).unwrap();
    let out = render(&pfm, &dir.path().join("scene.png"));
    assert_eq!(refused(&out), "output.is_an_input");
    assert_eq!(std::fs::read(&pfm).unwrap(), before);
    assert_eq!(listing(dir.path()), ["scene.pfm"]);
}

#[cfg(unix)]
#[test]
fn an_output_hard_linked_to_the_scene_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let copy = dir.path().join("scene.json");
    std::fs::copy(scene("shadow"), &copy).unwrap();
    let link = dir.path().join("out.png");
    std::fs::hard_link(&copy, &link).unwrap();
    let out = render(&copy, &link);
    assert_eq!(refused(&out), "output.is_an_input");
    assert_eq!(
        std::fs::read(&copy).unwrap(),
        std::fs::read(scene("shadow")).unwrap()
    );
}

/// sysfs takes no new files, even from root, so the directory is
/// unwritable for whoever runs the test.
#[cfg(target_os = "linux")]
#[test]
fn an_unwritable_output_directory_is_refused_before_the_render() {
    let out = render(Path::new(&scene("shadow")), Path::new("/sys/out.png"));
    assert_eq!(refused(&out), "output.unwritable");
    let message = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(message.contains("/sys"), "{message}");
}
