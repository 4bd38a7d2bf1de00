//! The errors of a sweep spread over machines (`optics tradeoff --plan`,
//! `optics tradeoff-job`, `optics tradeoff --collect`): a job or result
//! line that cannot be read, one of another schema, plan or scene, a job
//! that is not in the plan, results missing or given twice. Each kind's
//! stable name, the argument or line field it concerns, and its English
//! text (its Hungarian is in `crate::lang::jobs`).

use std::fmt;
use std::path::PathBuf;

use tracer::output::OutputError;

/// Which of the two line schemas a line was read as.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LineKind {
    /// A job line, `optics.tradeoff-job`.
    Job,
    /// A result line, `optics.tradeoff-result`.
    Result,
}

impl LineKind {
    /// The schema name the line must carry.
    pub fn schema(self) -> &'static str {
        match self {
            LineKind::Job => "optics.tradeoff-job",
            LineKind::Result => "optics.tradeoff-result",
        }
    }
}

/// A line of a file: the file (`-` for stdin) and its 1-based number.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Place {
    /// The file as given.
    pub path: PathBuf,
    /// The line, from 1.
    pub line: usize,
}

impl fmt::Display for Place {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}", self.path.display(), self.line)
    }
}

/// What is wrong with a result's images.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageProblem {
    /// An image that is not base64 of a PFM file.
    Encoding {
        /// Its place in `images`, from 0.
        index: usize,
    },
    /// An image of another size than the plan's.
    Size {
        /// Its place in `images`, from 0.
        index: usize,
        /// Its width and height.
        got: (u32, u32),
        /// The plan's.
        expected: (u32, u32),
    },
    /// Another count of images than the job keeps for its renders.
    Count {
        /// Images given.
        got: usize,
        /// Images the job keeps.
        expected: usize,
    },
}

/// Why a job could not be planned, run or collected.
#[derive(Debug)]
pub enum JobError {
    /// A file of jobs or results that cannot be read.
    Read {
        /// `JOBS` or `--collect`.
        field: &'static str,
        /// The file or directory.
        path: PathBuf,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// A line that is not a job (or a result): not JSON, or a field
    /// missing, unknown or of the wrong type; serde's message.
    Line {
        /// What the line was read as.
        kind: LineKind,
        /// Where.
        at: Place,
        /// The field, when serde names one.
        field: Option<String>,
        /// serde's message.
        message: String,
    },
    /// A line of another schema.
    Schema {
        /// What the line was read as.
        kind: LineKind,
        /// Where.
        at: Place,
        /// The schema it names.
        found: String,
    },
    /// A line of another version of its schema.
    Version {
        /// What the line was read as.
        kind: LineKind,
        /// Where.
        at: Place,
        /// The version it names.
        found: u32,
    },
    /// `INDEX` past the plan's jobs, or a line naming a job the plan does
    /// not have.
    NoSuchJob {
        /// `INDEX` or `job`.
        field: &'static str,
        /// The file that was read.
        at: Place,
        /// The job asked for.
        index: usize,
        /// How many jobs the plan has.
        jobs: usize,
    },
    /// A job line whose field is not what the plan gives for its job:
    /// edited since planning, or planned by another build of optics.
    NotPlanned {
        /// Where.
        at: Place,
        /// The field.
        field: &'static str,
        /// The job.
        job: usize,
    },
    /// The scene file is not the one planned (its FNV-1a differs).
    SceneChanged {
        /// The scene file.
        scene: PathBuf,
        /// The job or result line that planned it.
        at: Place,
    },
    /// A result of another plan (another scene, size or flags).
    OtherPlan {
        /// Where.
        at: Place,
        /// The result's plan.
        found: String,
        /// The command that plans it, as the result says.
        planned_as: String,
        /// This sweep's plan.
        expected: String,
    },
    /// Two results of one job.
    Duplicate {
        /// The job.
        job: usize,
        /// The first result.
        first: Place,
        /// The second.
        second: Place,
    },
    /// Jobs without a result.
    Missing {
        /// The jobs, with their labels (the first few).
        jobs: Vec<(usize, String)>,
        /// How many are missing in all.
        count: usize,
        /// How many jobs the plan has.
        of: usize,
    },
    /// A result whose images do not fit its job.
    Image {
        /// Where.
        at: Place,
        /// What is wrong.
        problem: ImageProblem,
    },
    /// A result whose `seconds` or `rays` are not finite numbers ≥ 0 (1 to
    /// 64 times).
    Times {
        /// Where.
        at: Place,
        /// `seconds` or `rays`.
        field: &'static str,
    },
    /// A `--collect` directory without result files.
    NoResults {
        /// The directory.
        path: PathBuf,
    },
    /// No `INDEX` for a file of several jobs.
    IndexNeeded {
        /// The file (`-`: stdin).
        path: PathBuf,
        /// How many lines it holds.
        lines: usize,
    },
    /// The plan (`--plan`) or a result (`--out`) could not be written.
    Write {
        /// `--plan` or `--out`.
        field: &'static str,
        /// The tracer's error.
        error: OutputError,
    },
}

impl JobError {
    /// The kind's stable name.
    pub fn name(&self) -> &'static str {
        match self {
            JobError::Read { .. } => "jobs.read",
            JobError::Line { .. } => "jobs.line",
            JobError::Schema { .. } => "jobs.schema",
            JobError::Version { .. } => "jobs.version",
            JobError::NoSuchJob { .. } => "jobs.no_such_job",
            JobError::NotPlanned { .. } => "jobs.not_planned",
            JobError::SceneChanged { .. } => "jobs.scene_changed",
            JobError::OtherPlan { .. } => "jobs.other_plan",
            JobError::Duplicate { .. } => "jobs.duplicate",
            JobError::Missing { .. } => "jobs.missing",
            JobError::Image { .. } => "jobs.image",
            JobError::Times { .. } => "jobs.times",
            JobError::NoResults { .. } => "jobs.no_results",
            JobError::IndexNeeded { .. } => "jobs.index_needed",
            JobError::Write { .. } => "jobs.write",
        }
    }

    /// The argument or line field it concerns.
    pub fn field(&self) -> Option<String> {
        let field = match self {
            JobError::Read { field, .. }
            | JobError::NoSuchJob { field, .. }
            | JobError::NotPlanned { field, .. }
            | JobError::Times { field, .. }
            | JobError::Write { field, .. } => field,
            JobError::IndexNeeded { lines: 0, .. } => "JOBS",
            JobError::IndexNeeded { .. } => "INDEX",
            JobError::Line { field, .. } => return field.clone(),
            JobError::Schema { .. } => "schema",
            JobError::Version { .. } => "version",
            JobError::SceneChanged { .. } => "scene_fnv1a",
            JobError::OtherPlan { .. } => "plan",
            JobError::Duplicate { .. } => "job",
            JobError::Missing { .. } | JobError::NoResults { .. } => "--collect",
            JobError::Image { .. } => "images",
        };
        Some((*field).to_owned())
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
        match self {
            JobError::Read {
                field,
                path,
                source,
            } => write!(f, "{field} {}: cannot read it: {source}", path.display()),
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
                validation::tradeoff::JOB_VERSION
            ),
            JobError::NoSuchJob {
                field,
                at,
                index,
                jobs,
            } if *jobs == 0 => write!(
                f,
                "{field} {index}: the plan {} has no jobs (it is empty)",
                at.path.display()
            ),
            JobError::NoSuchJob {
                field,
                at,
                index,
                jobs,
            } => write!(
                f,
                "{field} {index}: the plan {} has {jobs} jobs, 0 to {}",
                at.path.display(),
                jobs.saturating_sub(1)
            ),
            JobError::NotPlanned { at, field, job } => write!(
                f,
                "{at}: {field} is not what the plan gives job {job}: the line was edited, \
                 or planned by another build of optics; plan again"
            ),
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
                 {expected}: give --collect the scene and the flags given to --plan"
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
                "--collect {}: no result files (*.json, *.jsonl) in it",
                path.display()
            ),
            JobError::IndexNeeded { path, lines: 0 } => write!(
                f,
                "JOBS: {} holds no jobs (it is empty): nothing to run",
                path.display()
            ),
            JobError::IndexNeeded { path, lines } => write!(
                f,
                "INDEX: {} holds {lines} lines; give the job's index, 0 to {}",
                path.display(),
                lines.saturating_sub(1)
            ),
            JobError::Write { field, error } => write!(f, "{field}: {error}"),
        }
    }
}
