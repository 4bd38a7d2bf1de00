//! The pipeline's own promises: files replaced whole, destinations
//! refused before any check runs, the report's pair never split.

use super::files::write;
use super::*;
use crate::checkout::Checkout;
use safe_io::WriteError;

#[test]
fn writing_replaces_the_file_whole() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "r.json", b"first").unwrap();
    write(dir.path(), "r.json", b"second").unwrap();
    assert_eq!(std::fs::read(dir.path().join("r.json")).unwrap(), b"second");
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        1,
        "no temporary file left"
    );
}

#[test]
fn an_output_path_that_is_a_file_is_refused_before_anything_runs() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("taken");
    std::fs::write(&file, "x").unwrap();
    let options = Options {
        out: Some(file.clone()),
        ..Options::quick(Checkout::at_build_time(), "test")
    };
    let mut steps = 0;
    let error = run(&options, |_| steps += 1).unwrap_err();
    assert!(
        matches!(&error, PipelineError::OutNotADirectory { path } if *path == file),
        "{error}"
    );
    assert_eq!(steps, 0);
}

/// Runs the reduced set into `out`; the error and how many steps ran.
fn refused(out: &Path) -> (PipelineError, usize) {
    let options = Options {
        out: Some(out.to_owned()),
        ..Options::quick(Checkout::at_build_time(), "test")
    };
    let mut steps = 0;
    let error = run(&options, |_| steps += 1).unwrap_err();
    (error, steps)
}

#[test]
fn a_report_html_that_cannot_be_replaced_is_refused_before_any_check() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("report.html")).unwrap();
    let (error, steps) = refused(dir.path());
    assert!(
        matches!(
            &error,
            PipelineError::Write(OutputError::Write(WriteError::NotARegularFile { .. }))
        ),
        "{error}"
    );
    assert_eq!(steps, 0, "checks ran before the refusal");
    assert!(
        !dir.path().join("report.json").exists(),
        "report.json without report.html"
    );
}

/// sysfs takes no new files, even from root: `figures` linked there is an
/// unwritable figures directory for whoever runs the test.
#[cfg(target_os = "linux")]
#[test]
fn an_unwritable_figures_directory_is_refused_before_any_check() {
    let dir = tempfile::tempdir().unwrap();
    std::os::unix::fs::symlink("/sys", dir.path().join("figures")).unwrap();
    let (error, steps) = refused(dir.path());
    assert!(
        matches!(
            &error,
            PipelineError::Write(OutputError::Write(WriteError::Unwritable { .. }))
        ),
        "{error}"
    );
    assert_eq!(steps, 0, "checks ran before the refusal");
    assert!(
        !dir.path().join("report.json").exists(),
        "report.json without report.html"
    );
}
