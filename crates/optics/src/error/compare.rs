//! The errors of `optics compare` as its user reads them: the library's
//! kinds ([`validation::user_render::CompareError`]) with the argument
//! each concerns and the flags' names in the English (the Hungarian is in
//! `crate::lang::compare`).

use std::fmt;

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

/// The English, naming the flag each error came from; the library's own
/// where it already names the input by the name this command gave it.
pub fn english(error: &CompareError, f: &mut fmt::Formatter<'_>) -> fmt::Result {
    match error {
        CompareError::BadValue { field, x, y, channel, value } => write!(
            f,
            "{field}: pixel ({x}, {y}) {channel} is {value}, not a finite number{}",
            if *field == VARIANCE { " ≥ 0" } else { "" }
        ),
        CompareError::VarianceNeedsPfm { field: VARIANCE } => write!(
            f,
            "{VARIANCE}: give the variance as a PFM of linear values, not a PNG"
        ),
        CompareError::VarianceNeedsPfm { field } => write!(
            f,
            "{field}: a PNG holds 8-bit codes, not radiance; a variance goes with a PFM of the mean"
        ),
        CompareError::Size { width, height, error } => write!(
            f,
            "{IMAGE} is {width} × {height} pixels, a size the scene cannot be rendered at: {error}"
        ),
        CompareError::SizeMismatch { got, expected } => write!(
            f,
            "{VARIANCE} is {} × {} pixels, {IMAGE} {} × {}: they must be the same size",
            got.0, got.1, expected.0, expected.1
        ),
        CompareError::CourseReference => write!(
            f,
            "--integrator: the reference is physical; give whitted, path, photon or local, not course"
        ),
        CompareError::Diff(error) => write!(f, "--diff: {error}"),
        CompareError::Read { .. }
        | CompareError::UnknownFormat { .. }
        | CompareError::Png { .. }
        | CompareError::PngPixels { .. }
        | CompareError::Pfm { .. }
        | CompareError::Reference { .. }
        | CompareError::Disagrees { .. } => write!(f, "{error}"),
    }
}
