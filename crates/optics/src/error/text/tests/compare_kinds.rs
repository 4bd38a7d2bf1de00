//! One example of every kind of `optics compare`'s errors.

use super::{named, os_error};
use crate::error::compare::{CompareError, PfmProblem};
use crate::error::ErrorKind;
use crate::error::HarnessKind;
use safe_io::WriteError;
use tracer::output::OutputError;
use tracer::scene::{ErrorKind as Scene, SceneError};

/// The place of a compare error's kind among the compare slots.
pub fn compare_slot(error: &CompareError) -> usize {
    match error {
        CompareError::Read { .. } => 0,
        CompareError::UnknownFormat { .. } => 1,
        CompareError::Png { .. } => 2,
        CompareError::PngPixels { .. } => 3,
        CompareError::Pfm { .. } => 4,
        CompareError::BadValue { .. } => 5,
        CompareError::VarianceNeedsPfm { .. } => 6,
        CompareError::Size { .. } => 7,
        CompareError::SizeMismatch { .. } => 8,
        CompareError::CourseReference => 9,
        CompareError::Reference { .. } => 10,
        CompareError::Diff(_) => 11,
        CompareError::Disagrees { .. } => 12,
    }
}

/// How many compare slots there are.
pub const SLOTS: usize = 13;

fn compare(error: CompareError, quoted: &[&str]) -> (ErrorKind, Vec<String>) {
    (
        ErrorKind::Harness(HarnessKind::Compare(error)),
        named(quoted),
    )
}

/// One example of each kind (and of each PFM problem), with the text it
/// quotes verbatim.
pub fn examples() -> Vec<(ErrorKind, Vec<String>)> {
    let os = os_error().to_string();
    let image = "/tmp/mine.pfm";
    let pfm = |problem| {
        compare(
            CompareError::Pfm {
                field: "IMAGE",
                path: image.into(),
                problem,
            },
            &["IMAGE", image],
        )
    };
    vec![
        compare(
            CompareError::Read {
                field: "--variance",
                path: image.into(),
                source: os_error(),
            },
            &["--variance", image, &os],
        ),
        compare(
            CompareError::UnknownFormat {
                field: "IMAGE",
                path: "/tmp/notes.txt".into(),
            },
            &["IMAGE", "/tmp/notes.txt"],
        ),
        compare(
            CompareError::Png {
                field: "IMAGE",
                path: "/tmp/mine.png".into(),
                message: "Format error decoding Png: CRC error".into(),
            },
            &[
                "IMAGE",
                "/tmp/mine.png",
                "Format error decoding Png: CRC error",
            ],
        ),
        compare(
            CompareError::PngPixels {
                field: "IMAGE",
                path: "/tmp/mine.png".into(),
                format: "Rgb16".into(),
            },
            &["IMAGE", "/tmp/mine.png", "Rgb16", "sRGB", "RGBA"],
        ),
        pfm(PfmProblem::Header),
        pfm(PfmProblem::Scale),
        pfm(PfmProblem::Length {
            expected: 24,
            got: 12,
        }),
        compare(
            CompareError::BadValue {
                field: "--variance",
                x: 3,
                y: 4,
                channel: 'G',
                value: -1.0,
            },
            &["--variance"],
        ),
        compare(
            CompareError::VarianceNeedsPfm {
                field: "--variance",
            },
            &["--variance"],
        ),
        compare(
            CompareError::VarianceNeedsPfm { field: "IMAGE" },
            &["IMAGE"],
        ),
        compare(
            CompareError::Size {
                width: 20_000,
                height: 1,
                error: SceneError::new(
                    "overrides.width",
                    Scene::NotACount {
                        value: 20_000.0,
                        min: 1,
                        max: 16_384,
                    },
                ),
            },
            &["IMAGE", "overrides.width"],
        ),
        compare(
            CompareError::SizeMismatch {
                got: (4, 3),
                expected: (32, 24),
            },
            &["--variance", "IMAGE"],
        ),
        compare(
            CompareError::CourseReference,
            &[
                "--integrator",
                "whitted",
                "path",
                "photon",
                "local",
                "course",
            ],
        ),
        compare(
            CompareError::Reference {
                message: "cannot start the render's threads".into(),
            },
            &["cannot start the render's threads"],
        ),
        compare(
            CompareError::Diff(OutputError::Write(WriteError::IsAnInput {
                path: image.into(),
                input: image.into(),
            })),
            &["--diff", image],
        ),
        compare(
            CompareError::Disagrees {
                disagreeing: 12,
                pixels: 653,
            },
            &[],
        ),
    ]
}
