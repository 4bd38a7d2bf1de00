//! The errors of `optics compare` as its user reads them: the library's
//! kinds ([`validation::user_render::CompareError`]) with the argument
//! each concerns.

pub use validation::user_render::{CompareError, PfmProblem};

/// The image's name: the positional argument.
pub const IMAGE: &str = "IMAGE";

/// The variance's name: its flag.
pub const VARIANCE: &str = "--variance";

/// The argument an error concerns.
pub fn field(error: &CompareError) -> Option<String> {
    let field = match error {
        CompareError::Read { field, .. }
        | CompareError::UnknownFormat { field, .. }
        | CompareError::Png { field, .. }
        | CompareError::PngPixels { field, .. }
        | CompareError::Pfm { field, .. }
        | CompareError::BadValue { field, .. }
        | CompareError::VarianceNeedsPfm { field } => field,
        CompareError::Size { .. } => IMAGE,
        CompareError::SizeMismatch { .. } => VARIANCE,
        CompareError::CourseReference => "--integrator",
        CompareError::Diff(_) => "--diff",
        CompareError::Reference { .. } | CompareError::Disagrees { .. } => return None,
    };
    Some(field.to_owned())
}
