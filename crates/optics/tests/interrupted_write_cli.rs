//! SIGINT and SIGTERM during `optics render`'s write, through the binary:
//! no temporary left, and the PNG/PFM pair never mixed. The signal is sent
//! at a known point, not a guessed moment: the writer's test hook
//! (`TRACER_TEST_PAUSE`, see `safe_io::interrupt`) pauses it there and says
//! so on stderr, and the signal's handler reports the phase it arrived in,
//! which each test asserts.
#![cfg(unix)]

mod support;
use support::listing;

use std::io::{BufRead, BufReader, Read};
use std::os::unix::process::ExitStatusExt;
use std::path::Path;
use std::process::{Command, Stdio};

const SIGINT: i32 = 2;
const SIGTERM: i32 = 15;

fn scene(name: &str) -> String {
    format!(
        "{}/../tracer/scenes/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    )
}

fn render(scene_name: &str, png: &Path, width: &str) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_optics"));
    command
        .arg("render")
        .arg(scene(scene_name))
        .arg("-o")
        .arg(png)
        .args(["--width", width, "--height", "6"]);
    command
}

/// Renders without interruption; the PNG's and the PFM's bytes.
fn rendered(scene_name: &str, png: &Path, width: &str) -> (Vec<u8>, Vec<u8>) {
    let out = render(scene_name, png, width).output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    read_pair(png)
}

fn read_pair(png: &Path) -> (Vec<u8>, Vec<u8>) {
    (
        std::fs::read(png).unwrap(),
        std::fs::read(png.with_extension("pfm")).unwrap(),
    )
}

/// Runs `command` paused at `point`, sends `signal` once it says it has
/// paused there, and returns how it ended and the rest of its stderr.
fn interrupted(
    mut command: Command,
    point: &str,
    signal: i32,
) -> (std::process::ExitStatus, String) {
    let mut child = command
        .env("TRACER_TEST_PAUSE", point)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stderr = BufReader::new(child.stderr.take().unwrap());
    let announced = format!("tracer: paused {point}");
    let mut line = String::new();
    loop {
        line.clear();
        let read = stderr.read_line(&mut line).unwrap();
        assert!(read > 0, "the writer ended without pausing at {point}");
        if line.trim_end() == announced {
            break;
        }
    }
    let sent = Command::new("kill")
        .arg(format!("-{signal}"))
        .arg(child.id().to_string())
        .status()
        .unwrap();
    assert!(sent.success());
    let mut rest = String::new();
    stderr.read_to_string(&mut rest).unwrap();
    (child.wait().unwrap(), rest)
}

fn a_signal_before_the_rename_keeps_the_previous_pair(signal: i32) {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("out.png");
    let previous = rendered("shadow", &png, "8");
    let (status, stderr) = interrupted(render("diffuse", &png, "10"), "before-commit", signal);
    assert_eq!(status.signal(), Some(signal), "{status:?}: {stderr}");
    assert!(
        stderr.contains(&format!(
            "signal {signal} while staged: 2 temporaries removed"
        )),
        "the signal did not arrive with both temporaries complete: {stderr}"
    );
    assert_eq!(
        listing(dir.path()),
        ["out.pfm", "out.png"],
        "a temporary was left"
    );
    assert!(read_pair(&png) == previous, "the previous pair was changed");
}

#[test]
fn sigint_before_the_rename_keeps_the_previous_pair_and_no_temporary() {
    a_signal_before_the_rename_keeps_the_previous_pair(SIGINT);
}

#[test]
fn sigterm_before_the_rename_keeps_the_previous_pair_and_no_temporary() {
    a_signal_before_the_rename_keeps_the_previous_pair(SIGTERM);
}

#[test]
fn sigint_between_the_renames_waits_for_the_new_pair() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("out.png");
    let fresh = rendered("diffuse", &dir.path().join("fresh.png"), "10");
    rendered("shadow", &png, "8");
    let (status, stderr) = interrupted(render("diffuse", &png, "10"), "mid-commit", SIGINT);
    assert_eq!(status.signal(), Some(SIGINT), "{status:?}: {stderr}");
    assert!(
        stderr.contains("signal 2 while committing: 0 temporaries removed"),
        "the signal did not arrive between the renames: {stderr}"
    );
    assert_eq!(
        listing(dir.path()),
        ["fresh.pfm", "fresh.png", "out.pfm", "out.png"],
        "a temporary or backup was left"
    );
    assert!(read_pair(&png) == fresh, "the pair is not the new render's");
}

#[test]
fn sigint_while_the_temporaries_are_written_removes_the_written_one_and_keeps_the_pair() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("out.png");
    let previous = rendered("shadow", &png, "8");
    let (status, stderr) = interrupted(render("diffuse", &png, "10"), "mid-stage", SIGINT);
    assert_eq!(status.signal(), Some(SIGINT), "{status:?}: {stderr}");
    assert!(
        stderr.contains("signal 2 while staging: 1 temporaries removed"),
        "the signal did not arrive with one temporary written and one to go: {stderr}"
    );
    assert_eq!(
        listing(dir.path()),
        ["out.pfm", "out.png"],
        "a temporary was left"
    );
    assert!(read_pair(&png) == previous, "the previous pair was changed");
}
