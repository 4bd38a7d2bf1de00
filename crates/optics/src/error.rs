//! Why a command failed, as a typed kind.
//!
//! An error's identity is its [`ErrorKind`]; its English text is only the
//! kind's `Display`, its Hungarian text an exhaustive `match` over the kinds
//! in [`crate::lang`], and its JSON form `{"kind", "field", "message"}` takes
//! the kind's [`name`](ErrorKind::name). Adding a kind without a name, a
//! field or a translation stops the build.
//!
//! Another crate's typed errors are wrapped whole as one variant, as
//! [`ErrorKind::Domain`] wraps the radiometry crate's [`DomainError`] and
//! [`ErrorKind::Scene`] the tracer's [`SceneError`]; the translation of such
//! a variant is one exhaustive `match` over that crate's kinds, beside the
//! others in `lang`, and its name and field are given in `error::render` or
//! `error::harness`. Messages that come from outside the suite (the argument
//! parser's, serde's, the operating system's) keep their text, and the
//! kinds that carry them say which argument or field they concern.

use radiometry::domain::DomainError;
use std::fmt;
use std::path::PathBuf;
use tracer::job::RenderError;
use tracer::output::OutputError;
use tracer::scene::SceneError;

#[cfg(feature = "harness")]
pub mod compare;
mod english;
#[cfg(feature = "harness")]
pub mod harness;
#[cfg(feature = "harness")]
pub mod jobs;
pub mod render;
mod usage;

pub(crate) use usage::{usage_argument, usage_text};

/// The outcome of a step that can fail with one of the suite's own errors.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// A failure of a command: its kind, which also knows the argument or JSON
/// field it concerns.
#[derive(Debug)]
pub struct Error {
    // Boxed: the harness's kinds are large, and an error is moved often.
    kind: Box<ErrorKind>,
}

/// Every failure the suite reports.
#[derive(Debug)]
pub enum ErrorKind {
    /// A number outside the domain of a law (the radiometry crate's kinds).
    Domain(DomainError),
    /// The command line did not parse; the argument parser's message.
    Usage(clap::Error),
    /// A vector argument that is not three comma-separated parts.
    VectorParts {
        /// How many parts were given.
        count: usize,
    },
    /// A component of a vector argument that is not a number.
    VectorComponent {
        /// `x`, `y` or `z`.
        axis: &'static str,
        /// The text given for it.
        text: String,
    },
    /// An angle in degrees outside `[0, 180]`.
    AngleDegrees {
        /// The input's name as the user wrote it.
        name: String,
        /// The value given, degrees.
        value: f64,
    },
    /// Neither or both of the two ways of giving the incidence.
    CosineOrAngle {
        /// The cosine's name as the user writes it.
        cosine: String,
        /// The angle's name as the user writes it.
        angle: String,
    },
    /// Light from inside a conductor, which has no transmitted side.
    ConductorFromInside {
        /// The name of the input that gave the incidence.
        name: String,
        /// The signed cosine of incidence it gave.
        cos_i: f64,
    },
    /// A critical angle asked for light going into a denser (or equal) medium.
    NoCriticalAngle {
        /// The name of the index the light comes from.
        name: String,
        /// Its value.
        n: f64,
        /// The name of the index beyond the boundary.
        name_outside: String,
        /// Its value.
        n_outside: f64,
    },
    /// A batch line with nothing on it.
    EmptyLine,
    /// A batch line that is not JSON; serde's message.
    MalformedJson(serde_json::Error),
    /// A batch line that is JSON but not an object.
    NotAnObject,
    /// A request without a `law`.
    LawMissing,
    /// A request whose `law` is not a string.
    LawNotString,
    /// A request naming a law the batch does not evaluate.
    UnknownLaw {
        /// The law named.
        law: String,
    },
    /// A request field (or the request) that does not deserialise; serde's
    /// message.
    Request {
        /// The JSON path of the field; `None` for the request as a whole.
        path: Option<String>,
        /// serde's description.
        message: String,
    },
    /// A line of the batch input that could not be read; the operating
    /// system's message.
    ReadLine {
        /// The line number, from 1.
        line: usize,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// A batch line longer than [`crate::batch::MAX_LINE_BYTES`]: skipped
    /// to its newline unread.
    LineTooLong {
        /// The most bytes a line may hold.
        limit: usize,
    },
    /// A batch line whose bytes are not UTF-8 text.
    NotUtf8 {
        /// The 1-based column of the first byte that is not.
        column: usize,
    },
    /// A result too large for `f64` from inputs that each are finite.
    Overflow {
        /// The quantity, as the working names it (`L_ref`, `f_r`).
        quantity: &'static str,
        /// The inputs it grows with, as the user wrote them.
        inputs: Vec<String>,
    },
    /// The output could not be written; the operating system's message.
    Write(std::io::Error),
    /// A record that could not be written as JSON; serde's message.
    Encode(serde_json::Error),
    /// A scene file, or a setting given beside it, that the tracer refused:
    /// its kind and the JSON path of the bad value.
    Scene {
        /// The scene file as given.
        file: PathBuf,
        /// The tracer's error.
        error: SceneError,
    },
    /// The render's destination (`--output`) refused, or an image that
    /// could not be written there.
    Output(OutputError),
    /// The render's worker threads could not be started; rayon's message.
    Threads(rayon::ThreadPoolBuildError),
    /// A rendered pixel that is not finite in `f32`; nothing is written.
    RadianceNotFinite {
        /// Column, from 0 at the left.
        x: u32,
        /// Row, from 0 at the top.
        y: u32,
    },
    /// No usable checkout of the suite, for a command without `--checkout`
    /// (`OPTICS_CHECKOUT`, or the working directory's).
    #[cfg(feature = "harness")]
    Checkout(validation::checkout::CheckoutError),
    /// No usable checkout, for a command that takes `--checkout`.
    #[cfg(feature = "harness")]
    CheckoutWithFlag(validation::checkout::CheckoutError),
    /// The harness could not run to the end.
    #[cfg(feature = "harness")]
    Pipeline(validation::pipeline::PipelineError),
    /// The harness ran to the end and some of its checks failed.
    #[cfg(feature = "harness")]
    ChecksFailed {
        /// The checks that failed.
        failed: usize,
        /// All checks run.
        checks: usize,
    },
    /// `optics compare` could not compare, or found the image different.
    #[cfg(feature = "harness")]
    Compare(compare::CompareError),
    /// `optics tradeoff` on a scene whose physical render is black (no
    /// light reaches the camera): there is no light transport to trade.
    #[cfg(feature = "harness")]
    TruthIsBlack {
        /// The scene file, as given.
        file: PathBuf,
    },
    /// `optics render --tolerance` that no candidate is predicted to reach.
    #[cfg(feature = "harness")]
    BudgetUnreachable {
        /// The metric's name.
        metric: &'static str,
        /// The tolerance asked for.
        tolerance: f64,
        /// The smallest bound any candidate reaches.
        best: f64,
        /// Its settings, in words, at the most samples the budget renders
        /// it at.
        settings: String,
        /// Those samples per pixel (a power of two), `None` for a
        /// deterministic candidate.
        top_spp: Option<u32>,
        /// What it would need to reach the tolerance.
        need: validation::tradeoff::budget::Need,
    },
    /// `optics render --tolerance` whose pilot cannot bound the light the
    /// truth carries above 0: black, or too noisy at its samples.
    #[cfg(feature = "harness")]
    BudgetPilotNoisy {
        /// The pilot's samples per pixel.
        pilot_spp: u32,
    },
    /// `optics render --tolerance` of a scene whose rough material reflects
    /// more light than it receives (the course's `π kd` above 1), without
    /// `--lambert`: its light grows with depth, no truth converges and no
    /// bound holds.
    #[cfg(feature = "harness")]
    BudgetEnergyGain {
        /// The material's name in the scene file.
        material: String,
        /// What it reflects for what it receives (its largest channel).
        gain: f32,
    },
    /// A sweep spread over machines: a job or result line refused, a job
    /// not in the plan, results missing or given twice.
    #[cfg(feature = "harness")]
    Jobs(jobs::JobError),
}

impl Error {
    /// What failed.
    pub fn kind(&self) -> &ErrorKind {
        &self.kind
    }

    /// The argument or JSON field the failure concerns, as the user wrote
    /// it, when known.
    pub fn field(&self) -> Option<String> {
        self.kind.field()
    }
}

impl From<ErrorKind> for Error {
    fn from(kind: ErrorKind) -> Self {
        Self {
            kind: Box::new(kind),
        }
    }
}

#[cfg(feature = "harness")]
impl From<compare::CompareError> for Error {
    fn from(error: compare::CompareError) -> Self {
        ErrorKind::Compare(error).into()
    }
}

#[cfg(feature = "harness")]
impl From<validation::tradeoff::error::TradeoffError> for Error {
    fn from(error: validation::tradeoff::error::TradeoffError) -> Self {
        use validation::tradeoff::error::TradeoffError;
        match error {
            TradeoffError::Scene { file, error } => ErrorKind::Scene { file, error }.into(),
            TradeoffError::Render(error) => error.into(),
            TradeoffError::Output(error) => ErrorKind::Output(error).into(),
            TradeoffError::Encode(error) => ErrorKind::Encode(error).into(),
            TradeoffError::Jobs(error) => ErrorKind::Jobs(error).into(),
            TradeoffError::TruthIsBlack { file } => ErrorKind::TruthIsBlack { file }.into(),
            TradeoffError::BudgetUnreachable {
                metric,
                tolerance,
                best,
                settings,
                top_spp,
                need,
            } => ErrorKind::BudgetUnreachable {
                metric,
                tolerance,
                best,
                settings,
                top_spp,
                need,
            }
            .into(),
            TradeoffError::BudgetPilotNoisy { pilot_spp } => {
                ErrorKind::BudgetPilotNoisy { pilot_spp }.into()
            }
            TradeoffError::BudgetEnergyGain { material, gain } => {
                ErrorKind::BudgetEnergyGain { material, gain }.into()
            }
            TradeoffError::Checkout(error) => ErrorKind::Checkout(error).into(),
            TradeoffError::NoPython { python } => {
                let error = validation::python::ToolError::Start {
                    what: validation::python::Task::Script(
                        validation::tradeoff::engine::PLOT_SCRIPT.into(),
                    ),
                    program: python.display().to_string(),
                    source: std::io::Error::new(
                        std::io::ErrorKind::NotFound,
                        "no .venv: `optics validate` creates it once (or pass --no-plot)",
                    ),
                };
                ErrorKind::Pipeline(validation::pipeline::PipelineError::Tool(error)).into()
            }
            TradeoffError::Plot(error) => {
                ErrorKind::Pipeline(validation::pipeline::PipelineError::Tool(error)).into()
            }
        }
    }
}

#[cfg(feature = "harness")]
impl From<jobs::JobError> for Error {
    fn from(error: jobs::JobError) -> Self {
        ErrorKind::Jobs(error).into()
    }
}

impl From<DomainError> for Error {
    fn from(error: DomainError) -> Self {
        ErrorKind::Domain(error).into()
    }
}

impl From<RenderError> for Error {
    fn from(error: RenderError) -> Self {
        match error {
            RenderError::Threads(error) => ErrorKind::Threads(error).into(),
            RenderError::Output(error) => ErrorKind::Output(error).into(),
            RenderError::NotFinite { x, y } => ErrorKind::RadianceNotFinite { x, y }.into(),
        }
    }
}

impl ErrorKind {
    /// The kind's stable name, the `kind` of the JSON error object.
    pub fn name(&self) -> &'static str {
        match self {
            ErrorKind::Domain(DomainError::NotFinite { .. }) => "domain.not_finite",
            ErrorKind::Domain(DomainError::OutOfRange { .. }) => "domain.out_of_range",
            ErrorKind::Domain(DomainError::ZeroVector { .. }) => "domain.zero_vector",
            ErrorKind::Usage(_) => "usage",
            ErrorKind::VectorParts { .. } => "vector_parts",
            ErrorKind::VectorComponent { .. } => "vector_component",
            ErrorKind::AngleDegrees { .. } => "angle_degrees",
            ErrorKind::CosineOrAngle { .. } => "cosine_or_angle",
            ErrorKind::ConductorFromInside { .. } => "conductor_from_inside",
            ErrorKind::NoCriticalAngle { .. } => "no_critical_angle",
            ErrorKind::EmptyLine => "empty_line",
            ErrorKind::MalformedJson(_) => "malformed_json",
            ErrorKind::NotAnObject => "not_an_object",
            ErrorKind::LawMissing => "law_missing",
            ErrorKind::LawNotString => "law_not_a_string",
            ErrorKind::UnknownLaw { .. } => "unknown_law",
            ErrorKind::Request { .. } => "request",
            ErrorKind::ReadLine { .. } => "read_line",
            ErrorKind::NotUtf8 { .. } => "not_utf8",
            ErrorKind::LineTooLong { .. } => "line_too_long",
            ErrorKind::Overflow { .. } => "overflow",
            ErrorKind::Write(_) => "write",
            ErrorKind::Encode(_) => "encode",
            ErrorKind::Scene { error, .. } => render::scene_name(error.kind()),
            ErrorKind::Output(error) => render::output_name(error),
            ErrorKind::Threads(_) => "threads",
            ErrorKind::RadianceNotFinite { .. } => "render.not_finite",
            #[cfg(feature = "harness")]
            ErrorKind::Checkout(error) | ErrorKind::CheckoutWithFlag(error) => {
                harness::checkout_name(error)
            }
            #[cfg(feature = "harness")]
            ErrorKind::Pipeline(error) => harness::pipeline_name(error),
            #[cfg(feature = "harness")]
            ErrorKind::ChecksFailed { .. } => "harness.checks_failed",
            #[cfg(feature = "harness")]
            ErrorKind::Compare(error) => error.name(),
            #[cfg(feature = "harness")]
            ErrorKind::TruthIsBlack { .. } => "tradeoff.truth_is_black",
            #[cfg(feature = "harness")]
            ErrorKind::BudgetUnreachable { .. } => "budget.unreachable",
            #[cfg(feature = "harness")]
            ErrorKind::BudgetPilotNoisy { .. } => "budget.pilot_noisy",
            #[cfg(feature = "harness")]
            ErrorKind::BudgetEnergyGain { .. } => "budget.energy_gain",
            #[cfg(feature = "harness")]
            ErrorKind::Jobs(error) => error.name(),
        }
    }

    fn field(&self) -> Option<String> {
        match self {
            ErrorKind::Domain(error) => Some(error.name().to_owned()),
            ErrorKind::Usage(error) => usage_argument(error),
            ErrorKind::AngleDegrees { name, .. }
            | ErrorKind::ConductorFromInside { name, .. }
            | ErrorKind::NoCriticalAngle { name, .. } => Some(name.clone()),
            ErrorKind::LawMissing | ErrorKind::LawNotString | ErrorKind::UnknownLaw { .. } => {
                Some("law".to_owned())
            }
            ErrorKind::Request { path, .. } => path.clone(),
            ErrorKind::CosineOrAngle { cosine, angle } => Some(format!("{cosine}, {angle}")),
            ErrorKind::Overflow { inputs, .. } => Some(inputs.join(", ")),
            ErrorKind::VectorParts { .. }
            | ErrorKind::VectorComponent { .. }
            | ErrorKind::EmptyLine
            | ErrorKind::MalformedJson(_)
            | ErrorKind::NotAnObject
            | ErrorKind::ReadLine { .. }
            | ErrorKind::NotUtf8 { .. }
            | ErrorKind::LineTooLong { .. }
            | ErrorKind::Write(_)
            | ErrorKind::Encode(_)
            | ErrorKind::Threads(_)
            | ErrorKind::RadianceNotFinite { .. } => None,
            ErrorKind::Scene { error, .. } => Some(error.field().to_owned()),
            ErrorKind::Output(_) => Some("--output".to_owned()),
            #[cfg(feature = "harness")]
            ErrorKind::Checkout(error) => Some(harness::checkout_field(error, None).to_owned()),
            #[cfg(feature = "harness")]
            ErrorKind::CheckoutWithFlag(error) => {
                Some(harness::checkout_field(error, Some(harness::CHECKOUT_FLAG)).to_owned())
            }
            #[cfg(feature = "harness")]
            ErrorKind::Pipeline(error) => harness::pipeline_field(error),
            #[cfg(feature = "harness")]
            ErrorKind::ChecksFailed { .. } => None,
            #[cfg(feature = "harness")]
            ErrorKind::Compare(error) => compare::field(error),
            #[cfg(feature = "harness")]
            ErrorKind::TruthIsBlack { .. } => Some("SCENE".to_owned()),
            #[cfg(feature = "harness")]
            ErrorKind::BudgetUnreachable { .. } => Some("--tolerance".to_owned()),
            #[cfg(feature = "harness")]
            ErrorKind::BudgetPilotNoisy { .. } => Some("--pilot-spp".to_owned()),
            #[cfg(feature = "harness")]
            ErrorKind::BudgetEnergyGain { .. } => Some("--lambert".to_owned()),
            #[cfg(feature = "harness")]
            ErrorKind::Jobs(error) => error.field(jobs::flag),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.kind.fmt(f)
    }
}

impl std::error::Error for Error {}
