//! One example of every kind of the errors of a sweep spread over
//! machines (`--plan`, `tradeoff-job`, `--collect`).

use super::{named, os_error};
use crate::error::jobs::{ImageProblem, Input, JobError, LineKind, Place};
use crate::error::ErrorKind;
use crate::error::HarnessKind;
use safe_io::WriteError;
use tracer::output::OutputError;

/// The place of a jobs error's kind among the jobs slots (each image
/// problem a slot of its own).
pub fn jobs_slot(error: &JobError) -> usize {
    match error {
        JobError::Read { .. } => 0,
        JobError::Line { .. } => 1,
        JobError::Schema { .. } => 2,
        JobError::Version { .. } => 3,
        JobError::NoSuchJob { .. } => 4,
        JobError::NotPlanned { .. } => 5,
        JobError::SceneChanged { .. } => 6,
        JobError::OtherPlan { .. } => 7,
        JobError::Duplicate { .. } => 8,
        JobError::Missing { .. } => 9,
        JobError::Image { .. } => 10,
        JobError::Times { .. } => 11,
        JobError::NoResults { .. } => 12,
        JobError::IndexNeeded { .. } => 13,
        JobError::Write { .. } => 14,
    }
}

/// How many jobs slots there are.
pub const SLOTS: usize = 15;

fn jobs(error: JobError, quoted: &[&str]) -> (ErrorKind, Vec<String>) {
    (ErrorKind::Harness(HarnessKind::Jobs(error)), named(quoted))
}

fn at(line: usize) -> Place {
    Place {
        path: "results/job-0003.json".into(),
        line,
    }
}

/// One example of each kind (and of each image problem), with the text it
/// quotes verbatim.
pub fn examples() -> Vec<(ErrorKind, Vec<String>)> {
    let os = os_error().to_string();
    let place = "results/job-0003.json:1";
    let image = |problem, quoted: &[&str]| jobs(JobError::Image { at: at(1), problem }, quoted);
    vec![
        jobs(
            JobError::Read {
                input: Input::Jobs,
                path: "jobs.jsonl".into(),
                source: os_error(),
            },
            &["JOBS", "jobs.jsonl", &os],
        ),
        jobs(
            JobError::Line {
                kind: LineKind::Job,
                at: at(2),
                field: Some("colour".into()),
                message: "unknown field `colour`".into(),
            },
            &[
                "results/job-0003.json:2",
                "unknown field `colour`",
                "colour",
                "optics.tradeoff-job",
            ],
        ),
        jobs(
            JobError::Schema {
                kind: LineKind::Result,
                at: at(1),
                found: "optics.tradeoff".into(),
            },
            &[
                place,
                "schema",
                "\"optics.tradeoff\"",
                "\"optics.tradeoff-result\"",
            ],
        ),
        jobs(
            JobError::Version {
                kind: LineKind::Job,
                at: at(1),
                found: 2,
            },
            &[place, "optics.tradeoff-job", "optics"],
        ),
        jobs(
            JobError::NoSuchJob {
                input: Input::Index,
                at: at(40),
                index: 40,
                jobs: 27,
            },
            &["INDEX", "results/job-0003.json"],
        ),
        jobs(
            JobError::NotPlanned {
                at: at(1),
                field: "settings",
                job: 3,
            },
            &[place, "settings", "optics"],
        ),
        jobs(
            JobError::SceneChanged {
                scene: "scenes/shadow.json".into(),
                at: at(1),
            },
            &["scenes/shadow.json", place],
        ),
        jobs(
            JobError::OtherPlan {
                at: at(1),
                found: "0123456789abcdef".into(),
                planned_as: "optics tradeoff shadow.json --spp 4".into(),
                expected: "fedcba9876543210".into(),
            },
            &[
                place,
                "optics tradeoff shadow.json --spp 4",
                "0123456789abcdef",
                "fedcba9876543210",
                "--collect",
                "--plan",
            ],
        ),
        jobs(
            JobError::Duplicate {
                job: 3,
                first: at(1),
                second: Place {
                    path: "more/job-0003.json".into(),
                    line: 1,
                },
            },
            &[place, "more/job-0003.json:1"],
        ),
        jobs(
            JobError::Missing {
                jobs: vec![(3, "integrator path, 16 spp".into())],
                count: 2,
                of: 27,
            },
            &["3 (integrator path, 16 spp)"],
        ),
        image(
            ImageProblem::Encoding { index: 0 },
            &[place, "images", "base64"],
        ),
        image(
            ImageProblem::Size {
                index: 1,
                got: (8, 6),
                expected: (16, 12),
            },
            &[place, "images"],
        ),
        image(
            ImageProblem::Count {
                got: 2,
                expected: 3,
            },
            &[place, "images"],
        ),
        jobs(
            JobError::Times {
                at: at(1),
                field: "seconds",
            },
            &[place, "seconds"],
        ),
        jobs(
            JobError::NoResults {
                path: "results".into(),
            },
            &["--collect", "results", "*.json, *.jsonl"],
        ),
        jobs(
            JobError::IndexNeeded {
                path: "jobs.jsonl".into(),
                lines: 27,
            },
            &["INDEX", "jobs.jsonl"],
        ),
        jobs(
            JobError::Write {
                input: Input::Plan,
                error: OutputError::Write(WriteError::Io {
                    path: "jobs.jsonl".into(),
                    source: os_error(),
                }),
            },
            &["--plan", "jobs.jsonl", &os],
        ),
    ]
}
