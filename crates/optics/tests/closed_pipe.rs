//! A closed stdout (`optics … | head`) ends every subcommand quietly: no
//! panic, nothing on stderr, exit status 0, as the Unix tools end.
//!
//! The pipe's reading end is closed before the binary starts, so its first
//! write fails: the test cannot pass by the write landing before the close.

#![cfg(unix)]

use std::os::fd::{FromRawFd, OwnedFd};
use std::process::{Command, Output, Stdio};

/// The writing end of a pipe whose reading end is already closed.
fn pipe_without_reader() -> OwnedFd {
    let mut fds = [0; 2];
    // SAFETY: `pipe` fills both descriptors on success; each is owned once.
    unsafe {
        assert_eq!(libc::pipe(fds.as_mut_ptr()), 0, "a pipe");
        assert_eq!(libc::close(fds[0]), 0, "its reading end closed");
        OwnedFd::from_raw_fd(fds[1])
    }
}

fn into_closed_pipe(args: &[&str], stdin: &[u8]) -> Output {
    use std::io::Write;
    let mut child = Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::from(pipe_without_reader()))
        .stderr(Stdio::piped())
        .spawn()
        .expect("the optics binary runs");
    let mut input = child.stdin.take().expect("stdin is piped");
    // A command that does not read its stdin may close it first.
    let _ = input.write_all(stdin);
    drop(input);
    child.wait_with_output().expect("optics finishes")
}

fn scene(path: &str) -> String {
    format!("{}/../../{path}", env!("CARGO_MANIFEST_DIR"))
}

fn assert_ends_quietly(args: &[&str], stdin: &[u8]) {
    let output = into_closed_pipe(args, stdin);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "optics {args:?}: {stderr}");
    assert!(stderr.is_empty(), "optics {args:?} printed {stderr:?}");
}

#[test]
fn a_law_printed_into_a_closed_pipe_ends_quietly() {
    assert_ends_quietly(
        &["--json", "fresnel", "--eta", "1.5", "--cos-i", "0.5"],
        b"",
    );
    assert_ends_quietly(&["fresnel", "--eta", "1.5", "--cos-i", "0.5"], b"");
    assert_ends_quietly(&["quiz", "seed"], b"");
}

#[test]
fn an_error_printed_into_a_closed_pipe_still_reaches_stderr() {
    let output = into_closed_pipe(&["--json", "fresnel", "--eta", "-1", "--cos-i", "0.5"], b"");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("--eta must be a positive refractive index"),
        "{stderr}"
    );
}

#[test]
fn a_batch_into_a_closed_pipe_ends_quietly() {
    let lines = "{\"law\":\"f0\",\"n\":1.5}\n".repeat(100);
    assert_ends_quietly(&["batch"], lines.as_bytes());
}

#[test]
fn inspect_and_render_into_a_closed_pipe_end_quietly() {
    let shadow = scene("crates/tracer/scenes/shadow.json");
    let small = ["--width", "8", "--height", "6"];
    let inspect: Vec<&str> = ["inspect", shadow.as_str()]
        .iter()
        .chain(&small)
        .copied()
        .collect();
    assert_ends_quietly(&inspect, b"");
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("shadow.png");
    let png = png.to_str().unwrap();
    for json in [&[][..], &["--json"][..]] {
        let args: Vec<&str> = json
            .iter()
            .chain(&["render", shadow.as_str(), "-o", png])
            .chain(&small)
            .copied()
            .collect();
        assert_ends_quietly(&args, b"");
    }
}
