//! Why a command failed, as a typed kind.
//!
//! An error's identity is its [`ErrorKind`]; its message in each language
//! is one exhaustive `match` over the kinds whose arms give the English and
//! the Hungarian side by side (`text`), the English being also the kind's
//! `Display`; and its JSON form `{"kind", "field", "message"}` takes the
//! kind's [`name`](ErrorKind::name). Adding a kind without a name, a field
//! or its Hungarian stops the build.
//!
//! Another crate's typed errors are wrapped whole as one variant, as
//! [`ErrorKind::Domain`] wraps the radiometry crate's [`DomainError`] and
//! [`ErrorKind::Scene`] the tracer's [`tracer::scene::SceneError`]: their
//! English is that crate's `Display`, their Hungarian one exhaustive
//! `match` over that crate's kinds in `text`, and their name and field are
//! given in `error::render` or `error::harness`. Messages that come from
//! outside the suite (the argument parser's, serde's, the operating
//! system's) keep their text, and the kinds that carry them say which
//! argument or field they concern.

use radiometry::domain::DomainError;
use tracer::job::RenderError;

#[cfg(feature = "harness")]
pub mod compare;
#[cfg(feature = "harness")]
pub mod harness;
#[cfg(feature = "harness")]
pub mod jobs;
mod kind;
pub mod render;
mod text;
pub(crate) mod usage;

#[cfg(feature = "harness")]
pub use harness::HarnessKind;
pub use kind::{Error, ErrorKind};
pub(crate) use text::usage_rendered;

/// The outcome of a step that can fail with one of the suite's own errors.
pub type Result<T, E = Error> = std::result::Result<T, E>;

#[cfg(feature = "harness")]
impl From<compare::CompareError> for Error {
    fn from(error: compare::CompareError) -> Self {
        ErrorKind::Harness(HarnessKind::Compare(error)).into()
    }
}

#[cfg(feature = "harness")]
impl From<HarnessKind> for Error {
    fn from(kind: HarnessKind) -> Self {
        ErrorKind::Harness(kind).into()
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
            TradeoffError::Jobs(error) => ErrorKind::Harness(HarnessKind::Jobs(error)).into(),
            TradeoffError::TruthIsBlack { file } => {
                ErrorKind::Harness(HarnessKind::TruthIsBlack { file }).into()
            }
            TradeoffError::Budget(error) => ErrorKind::Harness(HarnessKind::Budget(error)).into(),
            TradeoffError::Checkout(error) => {
                ErrorKind::Harness(HarnessKind::Checkout(error)).into()
            }
            TradeoffError::NoPython { python } => {
                ErrorKind::Harness(HarnessKind::NoPlotPython { python }).into()
            }
            TradeoffError::Plot(error) => ErrorKind::Harness(HarnessKind::Plot(error)).into(),
        }
    }
}

#[cfg(feature = "harness")]
impl From<jobs::JobError> for Error {
    fn from(error: jobs::JobError) -> Self {
        ErrorKind::Harness(HarnessKind::Jobs(error)).into()
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
