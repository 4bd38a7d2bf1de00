//! What can stop a comparison, or what it found against the image: an
//! image that cannot be read or does not fit the scene, a difference map
//! that cannot be written, an image that disagrees. Each kind has a stable
//! name; the English says what is wrong with which value and names the
//! inputs by the names their caller gave them ([`super::Names`]).

use std::fmt;
use std::path::PathBuf;

use tracer::job::RenderError;
use tracer::output::OutputError;
use tracer::scene::SceneError;

/// What is wrong in a PFM file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PfmProblem {
    /// The header is not `PF` or `Pf`, a width, a height and a scale,
    /// separated by white space.
    Header,
    /// The scale is zero or not a finite number (its sign gives the byte order).
    Scale,
    /// The pixel data is not `width × height × channels` floats.
    Length {
        /// Bytes the header calls for.
        expected: u64,
        /// Bytes present.
        got: u64,
    },
}

/// Why an image could not be compared, or what the comparison found.
///
/// `field` is the name the caller gave the input concerned: the image's
/// or the variance's, as set in [`super::Names`].
#[derive(Debug)]
pub enum CompareError {
    /// An input image could not be read; the operating system's message.
    Read {
        /// The image's or the variance's name.
        field: &'static str,
        /// The file.
        path: PathBuf,
        /// The reason.
        source: std::io::Error,
    },
    /// A file that is neither a PNG nor a PFM, by its first bytes.
    UnknownFormat {
        /// The image's or the variance's name.
        field: &'static str,
        /// The file.
        path: PathBuf,
    },
    /// A PNG the decoder refused; its message.
    Png {
        /// The image's name.
        field: &'static str,
        /// The file.
        path: PathBuf,
        /// The decoder's message.
        message: String,
    },
    /// A PNG whose pixels are not 8-bit RGB or RGBA.
    PngPixels {
        /// The image's name.
        field: &'static str,
        /// The file.
        path: PathBuf,
        /// The decoder's name of its pixel format.
        format: String,
    },
    /// A malformed PFM.
    Pfm {
        /// The image's or the variance's name.
        field: &'static str,
        /// The file.
        path: PathBuf,
        /// What is wrong.
        problem: PfmProblem,
    },
    /// A value that is not finite (or, in a variance, negative).
    BadValue {
        /// The image's or the variance's name.
        field: &'static str,
        /// Column, from 0 at the left.
        x: u32,
        /// Row, from 0 at the top.
        y: u32,
        /// `R`, `G` or `B`.
        channel: char,
        /// The value.
        value: f32,
    },
    /// A variance image that is a PNG, or a variance given for a PNG.
    VarianceNeedsPfm {
        /// The variance's name (a PNG given as the variance) or the
        /// image's (a PNG given with a variance).
        field: &'static str,
    },
    /// The image's size is one the scene cannot be rendered at.
    Size {
        /// The image's width, pixels.
        width: u32,
        /// Its height.
        height: u32,
        /// The tracer's refusal.
        error: SceneError,
    },
    /// The variance image's size is not the image's.
    SizeMismatch {
        /// The variance image's width and height.
        got: (u32, u32),
        /// The image's.
        expected: (u32, u32),
    },
    /// The reference would be the course shader, which is not physical.
    CourseReference,
    /// The reference render failed; the tracer's message.
    Reference {
        /// The message.
        message: String,
    },
    /// The difference map could not be written.
    Diff(OutputError),
    /// The image disagrees with the reference.
    Disagrees {
        /// Pixels that disagree.
        disagreeing: usize,
        /// Pixels compared.
        pixels: usize,
    },
}

impl CompareError {
    /// The kind's stable name.
    pub fn name(&self) -> &'static str {
        match self {
            CompareError::Read { .. } => "compare.read",
            CompareError::UnknownFormat { .. } => "compare.unknown_format",
            CompareError::Png { .. } => "compare.png",
            CompareError::PngPixels { .. } => "compare.png_pixels",
            CompareError::Pfm { .. } => "compare.pfm",
            CompareError::BadValue { .. } => "compare.bad_value",
            CompareError::VarianceNeedsPfm { .. } => "compare.variance_needs_pfm",
            CompareError::Size { .. } => "compare.size",
            CompareError::SizeMismatch { .. } => "compare.size_mismatch",
            CompareError::CourseReference => "compare.course_reference",
            CompareError::Reference { .. } => "compare.reference",
            CompareError::Diff(_) => "compare.diff",
            CompareError::Disagrees { .. } => "compare.disagrees",
        }
    }
}

/// Why [`super::compare`] stopped: the scene, the reference's render, or
/// the image.
#[derive(Debug)]
pub enum Error {
    /// The scene file was refused for a reason other than the image's size.
    Scene {
        /// The scene file, as given.
        file: PathBuf,
        /// The tracer's refusal.
        error: SceneError,
    },
    /// The reference render stopped.
    Render(RenderError),
    /// The image could not be compared, or the difference map not written.
    Compare(CompareError),
}

impl From<CompareError> for Error {
    fn from(error: CompareError) -> Self {
        Error::Compare(error)
    }
}

impl From<RenderError> for Error {
    fn from(error: RenderError) -> Self {
        Error::Render(error)
    }
}

impl fmt::Display for PfmProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PfmProblem::Header => write!(
                f,
                "the header is not PF or Pf, a width, a height and a scale separated by white space"
            ),
            PfmProblem::Scale => write!(
                f,
                "the scale is zero or not a finite number (its sign gives the byte order)"
            ),
            PfmProblem::Length { expected, got } => write!(
                f,
                "the header calls for {expected} bytes of pixels, the file has {got}"
            ),
        }
    }
}

impl fmt::Display for CompareError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CompareError::Read { field, path, source } => {
                write!(f, "{field} {}: cannot read it: {source}", path.display())
            }
            CompareError::UnknownFormat { field, path } => write!(
                f,
                "{field} {}: neither a PNG nor a PFM (by its first bytes)",
                path.display()
            ),
            CompareError::Png { field, path, message } => {
                write!(f, "{field} {}: not a readable PNG: {message}", path.display())
            }
            CompareError::PngPixels { field, path, format } => write!(
                f,
                "{field} {}: a PNG of {format} pixels; compare reads 8-bit sRGB (RGB or RGBA)",
                path.display()
            ),
            CompareError::Pfm { field, path, problem } => {
                write!(f, "{field} {}: not a readable PFM: {problem}", path.display())
            }
            // A finite value is refused only as a negative variance.
            CompareError::BadValue { field, x, y, channel, value } => write!(
                f,
                "{field}: pixel ({x}, {y}) {channel} is {value}, not a finite number{}",
                if value.is_finite() { " ≥ 0" } else { "" }
            ),
            CompareError::VarianceNeedsPfm { field } => write!(
                f,
                "{field}: a variance goes with a PFM of the mean and is itself a PFM of linear values, not a PNG"
            ),
            CompareError::Size { width, height, error } => write!(
                f,
                "the image is {width} × {height} pixels, a size the scene cannot be rendered at: {error}"
            ),
            CompareError::SizeMismatch { got, expected } => write!(
                f,
                "the variance is {} × {} pixels, the image {} × {}: they must be the same size",
                got.0, got.1, expected.0, expected.1
            ),
            CompareError::CourseReference => write!(
                f,
                "the reference's integrator is course, which is not physical: it must be whitted, path, photon or local"
            ),
            CompareError::Reference { message } => {
                write!(f, "the reference render failed: {message}")
            }
            CompareError::Diff(error) => write!(f, "the difference map: {error}"),
            CompareError::Disagrees { disagreeing, pixels } => write!(
                f,
                "the image disagrees with the reference at {disagreeing} of {pixels} pixels"
            ),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Scene { file, error } => write!(f, "{}: {error}", file.display()),
            Error::Render(error) => write!(f, "{error}"),
            Error::Compare(error) => write!(f, "{error}"),
        }
    }
}

impl std::error::Error for PfmProblem {}
impl std::error::Error for CompareError {}
impl std::error::Error for Error {}
