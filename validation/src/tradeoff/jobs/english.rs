//! A sweep's job errors in English ([`Named`]), the inputs they concern
//! named as the caller names them.

use std::fmt;

use super::error::{ImageProblem, Input, JobError, VERSION};

/// A [`JobError`] in English with its inputs named by the front end.
pub struct Named<'a> {
    error: &'a JobError,
    name: fn(Input) -> &'static str,
}

impl JobError {
    /// The error in English, its inputs by `name`.
    pub fn named(&self, name: fn(Input) -> &'static str) -> Named<'_> {
        Named { error: self, name }
    }
}

/// `3 (integrator path, 16 spp), 7 (spp 4)` and `…` past those listed.
pub fn listed(jobs: &[(usize, String)], count: usize) -> String {
    let mut text = jobs
        .iter()
        .map(|(job, label)| format!("{job} ({label})"))
        .collect::<Vec<_>>()
        .join(", ");
    if count > jobs.len() {
        text += ", …";
    }
    text
}

impl fmt::Display for JobError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.named(Input::noun).fmt(f)
    }
}

impl std::error::Error for JobError {}

impl fmt::Display for Named<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.lines(f)
    }
}

impl Named<'_> {
    /// A line refused as read: unreadable, not its schema, not planned.
    fn lines(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let name = self.name;
        match self.error {
            JobError::Read {
                input,
                path,
                source,
            } => write!(
                f,
                "{} {}: cannot read it: {source}",
                name(*input),
                path.display()
            ),
            JobError::Line {
                kind,
                at,
                field: Some(field),
                message,
            } => write!(f, "{at}: not an {} line: {field}: {message}", kind.schema()),
            JobError::Line {
                kind, at, message, ..
            } => write!(f, "{at}: not an {} line: {message}", kind.schema()),
            JobError::Schema { kind, at, found } => {
                write!(f, "{at}: schema is {found:?}, expected {:?}", kind.schema())
            }
            JobError::Version { kind, at, found } => write!(
                f,
                "{at}: version {found} of {}; this optics reads version {}",
                kind.schema(),
                VERSION
            ),
            JobError::NoSuchJob {
                input,
                at,
                index,
                jobs,
            } if *jobs == 0 => write!(
                f,
                "{} {index}: the plan {} has no jobs (it is empty)",
                name(*input),
                at.path.display()
            ),
            JobError::NoSuchJob {
                input,
                at,
                index,
                jobs,
            } => write!(
                f,
                "{} {index}: the plan {} has {jobs} jobs, 0 to {}",
                name(*input),
                at.path.display(),
                jobs.saturating_sub(1)
            ),
            JobError::NotPlanned { at, field, job } => write!(
                f,
                "{at}: {field} is not what the plan gives job {job}: the line was edited, \
                 or planned by another build of optics; plan again"
            ),
            _ => self.plan(f),
        }
    }

    /// A sweep's results refused against their plan, or a file unwritten.
    fn plan(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let name = self.name;
        match self.error {
            JobError::SceneChanged { scene, at } => write!(
                f,
                "scene {}: the file changed since it was planned ({at}); plan again",
                scene.display()
            ),
            JobError::OtherPlan {
                at,
                found,
                planned_as,
                expected,
            } => write!(
                f,
                "{at}: a result of plan {found} (`{planned_as}`), this sweep is plan \
                 {expected}: give {} the scene and the flags given to {}",
                name(Input::Collect),
                name(Input::Plan)
            ),
            JobError::Duplicate { job, first, second } => {
                write!(f, "job {job} has two results: {first} and {second}")
            }
            JobError::Missing { jobs, count, of } => write!(
                f,
                "{count} of {of} jobs have no result: {}",
                listed(jobs, *count)
            ),
            JobError::Image { at, problem } => match problem {
                ImageProblem::Encoding { index } => {
                    write!(f, "{at}: images[{index}] is not base64 of a PFM image")
                }
                ImageProblem::Size {
                    index,
                    got,
                    expected,
                } => write!(
                    f,
                    "{at}: images[{index}] is {} × {} pixels, the plan {} × {}",
                    got.0, got.1, expected.0, expected.1
                ),
                ImageProblem::Count { got, expected } => write!(
                    f,
                    "{at}: images holds {got} images, the job keeps {expected} for its renders"
                ),
            },
            JobError::Times { at, field } => write!(
                f,
                "{at}: {field} must be finite numbers ≥ 0, one to 64 renders' worth"
            ),
            JobError::NoResults { path } => write!(
                f,
                "{} {}: no result files (*.json, *.jsonl) in it",
                name(Input::Collect),
                path.display()
            ),
            JobError::IndexNeeded { path, lines: 0 } => write!(
                f,
                "{}: {} holds no jobs (it is empty): nothing to run",
                name(Input::Jobs),
                path.display()
            ),
            JobError::IndexNeeded { path, lines } => write!(
                f,
                "{}: {} holds {lines} lines; give the job's index, 0 to {}",
                name(Input::Index),
                path.display(),
                lines.saturating_sub(1)
            ),
            JobError::Write { input, error } => write!(f, "{}: {error}", name(*input)),
            JobError::Read { .. }
            | JobError::Line { .. }
            | JobError::Schema { .. }
            | JobError::Version { .. }
            | JobError::NoSuchJob { .. }
            | JobError::NotPlanned { .. } => self.lines(f),
        }
    }
}
