//! The errors of a sweep spread over machines: a job or result line that
//! cannot be read, one of another schema, plan or scene, a job that is not
//! in the plan, results missing or given twice. Each kind's stable name
//! and its English text, with the inputs it concerns named by the caller
//! ([`Named`](super::english::Named)): a front end gives the names its user typed (a flag, an
//! argument), the library's own `Display` plain nouns ([`Input::noun`]).

use std::fmt;
use std::path::PathBuf;

use tracer::output::OutputError;

/// The version of the two line schemas of a sweep spread over machines,
/// its jobs (`optics.tradeoff-job`) and their results
/// (`optics.tradeoff-result`): raised when a field changes meaning or goes.
pub const VERSION: u32 = 1;

/// Which input of a sweep spread over machines a failure concerns; the
/// front end that took it knows its name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Input {
    /// The file the plan's job lines are written to.
    Plan,
    /// The file a job's result line is written to.
    Out,
    /// The directory the results are collected from.
    Collect,
    /// The file of job lines a job is run from.
    Jobs,
    /// The index of the job to run in that file.
    Index,
    /// The `job` field of a job line.
    Job,
}

impl Input {
    /// The input in plain words, as the library names it.
    pub fn noun(self) -> &'static str {
        match self {
            Input::Plan => "the plan file",
            Input::Out => "the result file",
            Input::Collect => "the results directory",
            Input::Jobs => "the jobs file",
            Input::Index => "the job index",
            Input::Job => "the job",
        }
    }
}

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
        /// The jobs file or the results directory.
        input: Input,
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
    /// A job index past the plan's jobs, or a line naming a job the plan
    /// does not have.
    NoSuchJob {
        /// The job index or a job line's `job`.
        input: Input,
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
    /// A results directory without result files.
    NoResults {
        /// The directory.
        path: PathBuf,
    },
    /// No job index for a file of several jobs (or a file of none).
    IndexNeeded {
        /// The file (`-`: stdin).
        path: PathBuf,
        /// How many lines it holds.
        lines: usize,
    },
    /// The plan or a result could not be written.
    Write {
        /// The plan file or the result file.
        input: Input,
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

    /// The input or line field it concerns, the inputs by `name`.
    pub fn field(&self, name: fn(Input) -> &'static str) -> Option<String> {
        let field = match self {
            JobError::Read { input, .. }
            | JobError::NoSuchJob { input, .. }
            | JobError::Write { input, .. } => name(*input),
            JobError::NotPlanned { field, .. } | JobError::Times { field, .. } => field,
            JobError::IndexNeeded { lines: 0, .. } => name(Input::Jobs),
            JobError::IndexNeeded { .. } => name(Input::Index),
            JobError::Line { field, .. } => return field.clone(),
            JobError::Schema { .. } => "schema",
            JobError::Version { .. } => "version",
            JobError::SceneChanged { .. } => "scene_fnv1a",
            JobError::OtherPlan { .. } => "plan",
            JobError::Duplicate { .. } => "job",
            JobError::Missing { .. } | JobError::NoResults { .. } => name(Input::Collect),
            JobError::Image { .. } => "images",
        };
        Some(field.to_owned())
    }
}
