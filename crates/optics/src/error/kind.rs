//! The kinds of failure a command reports ([`ErrorKind`]): each kind's
//! stable name (the JSON error's `kind`) and the argument or field it
//! concerns; and the [`Error`] that carries one.

use std::fmt;
use std::path::PathBuf;

use ::errata::LookupError;
use radiometry::domain::DomainError;
use record::Lang;
use tracer::output::OutputError;
use tracer::scene::SceneError;

#[cfg(feature = "harness")]
use super::harness::HarnessKind;
use super::render;
use super::usage::usage_argument;

/// A failure of a command: its kind, which also knows the argument or JSON
/// field it concerns.
#[derive(Debug)]
pub struct Error {
    // Boxed: the harness's kinds are large, and an error is moved often.
    kind: Box<ErrorKind>,
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

    /// The error's message in `lang`.
    pub fn message(&self, lang: Lang) -> String {
        self.kind.message(lang)
    }

    /// The error as JSON: `{"kind": …, "field": …, "message": …}`, the
    /// message in `lang`, the field `null` when unknown.
    pub fn to_json(&self, lang: Lang) -> serde_json::Value {
        serde_json::json!({
            "kind": self.kind.name(),
            "field": self.field(),
            "message": self.message(lang),
        })
    }
}

impl From<ErrorKind> for Error {
    fn from(kind: ErrorKind) -> Self {
        Self {
            kind: Box::new(kind),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.kind.fmt(f)
    }
}

impl std::error::Error for Error {}

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
    /// Neither or both of a material's index and its name (or a name with
    /// an extinction coefficient beside it).
    IndexOrMetal {
        /// The index's name as the user writes it.
        eta: String,
        /// The extinction coefficient's name.
        kappa: String,
        /// The metal's name.
        metal: String,
    },
    /// A list that must hold a value holds none.
    EmptyList {
        /// The list's name as the user writes it.
        name: String,
    },
    /// Light from inside a conductor, which has no transmitted side.
    ConductorFromInside {
        /// The name of the input that gave the incidence.
        name: String,
        /// The signed cosine of incidence it gave.
        cos_i: f64,
        /// The angle of incidence, degrees, where the input was an angle.
        degrees: Option<f64>,
    },
    /// A Fresnel model named by the bare `schlick`, which names neither of
    /// Schlick's forms.
    SchlickFormUnnamed {
        /// The input's name as the user wrote it.
        name: String,
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
    MalformedJson {
        /// serde's message.
        error: serde_json::Error,
        /// Whether the line spells NaN or an infinity where parsing stopped.
        non_finite: bool,
    },
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
        /// The laws there are (`law_table::LAWS`).
        expected: &'static [&'static str],
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
    /// An erratum id or a class of errata that `optics errata` does not
    /// know.
    Errata(::errata::LookupError),
    /// A failure of the cross-check harness, the trade-off sweep or the
    /// budget (the `harness` feature's commands).
    #[cfg(feature = "harness")]
    Harness(HarnessKind),
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
            ErrorKind::IndexOrMetal { .. } => "index_or_metal",
            ErrorKind::EmptyList { .. } => "empty_list",
            ErrorKind::ConductorFromInside { .. } => "conductor_from_inside",
            ErrorKind::NoCriticalAngle { .. } => "no_critical_angle",
            ErrorKind::SchlickFormUnnamed { .. } => "schlick_form_unnamed",
            ErrorKind::EmptyLine => "empty_line",
            ErrorKind::MalformedJson { .. } => "malformed_json",
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
            ErrorKind::Errata(LookupError::UnknownId { .. }) => "errata.unknown_id",
            ErrorKind::Errata(LookupError::UnknownClass { .. }) => "errata.unknown_class",
            #[cfg(feature = "harness")]
            ErrorKind::Harness(kind) => kind.name(),
        }
    }

    pub(crate) fn field(&self) -> Option<String> {
        match self {
            ErrorKind::Domain(error) => Some(error.name().to_owned()),
            ErrorKind::Usage(error) => usage_argument(error),
            ErrorKind::AngleDegrees { name, .. }
            | ErrorKind::ConductorFromInside { name, .. }
            | ErrorKind::NoCriticalAngle { name, .. }
            | ErrorKind::SchlickFormUnnamed { name }
            | ErrorKind::EmptyList { name } => Some(name.clone()),
            ErrorKind::IndexOrMetal { eta, kappa, metal } => {
                Some(format!("{eta}, {kappa}, {metal}"))
            }
            ErrorKind::LawMissing | ErrorKind::LawNotString | ErrorKind::UnknownLaw { .. } => {
                Some("law".to_owned())
            }
            ErrorKind::Request { path, .. } => path.clone(),
            ErrorKind::CosineOrAngle { cosine, angle } => Some(format!("{cosine}, {angle}")),
            ErrorKind::Overflow { inputs, .. } => Some(inputs.join(", ")),
            ErrorKind::VectorParts { .. }
            | ErrorKind::VectorComponent { .. }
            | ErrorKind::EmptyLine
            | ErrorKind::MalformedJson { .. }
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
            ErrorKind::Errata(LookupError::UnknownId { .. }) => Some("ID".to_owned()),
            ErrorKind::Errata(LookupError::UnknownClass { .. }) => Some("--class".to_owned()),
            #[cfg(feature = "harness")]
            ErrorKind::Harness(kind) => kind.field(),
        }
    }
}
