//! The test that fits the image, made against the reference away from its
//! silhouettes, and its summary by region.
//!
//! | image | test |
//! |---|---|
//! | PNG (8-bit sRGB) | its codes within those of the reference's tolerance interval, one code more either side |
//! | PFM (linear radiance) | per pixel-channel `\|Δ\| ≤ 1e-5 + 1e-3 · \|reference\|`, plus the reference's own noise |
//! | PFM with its variance and samples | Welch's t per pixel-channel, Bonferroni-corrected, and beyond that tolerance |

use tracer::output::to_srgb8;

use super::reference::Reference;
use super::user_image::UserImage;
use crate::compare::regions::{summarise, Summary};
use crate::compare::welch::{welch, Tests};
use crate::compare::{tolerance, Estimate, Tolerance, Verdicts};
use crate::renders::ALPHA;

/// What the comparison found.
pub struct Outcome {
    /// Per pixel-channel.
    pub verdicts: Verdicts,
    /// Per region.
    pub summary: Summary,
    /// The t-tests, where Welch's test was used.
    pub tests: Option<Tests>,
}

/// The per-sample variance of a linear image's radiance and the samples
/// per pixel behind it: the image is then their mean.
#[derive(Clone, Copy, Debug)]
pub struct Noise<'a> {
    /// Flat RGB, rows top to bottom, as the image.
    pub variance: &'a [f64],
    /// Samples per pixel, ≥ 2.
    pub samples: u32,
}

/// Holds `image` (with its noise, for a linear image) against `reference`.
pub fn judge(image: &UserImage, noise: Option<Noise>, reference: &Reference) -> Outcome {
    let mask = mask_of(reference);
    let reference_noise = reference
        .noise
        .as_ref()
        .map(|(variance, samples)| Estimate {
            mean: &reference.mean,
            variance,
            samples: *samples,
        });
    let (verdicts, tests, in_unit) = match (image, noise) {
        (UserImage::Codes { codes, .. }, _) => {
            let v = tolerance::codes(
                codes,
                &reference.mean,
                reference_noise.as_ref(),
                Tolerance::RENDERS,
                ALPHA,
                mask,
            );
            (v, None, reference_codes(&reference.mean))
        }
        (UserImage::Linear { values, .. }, None) => {
            let v = tolerance::radiance(
                values,
                &reference.mean,
                reference_noise.as_ref(),
                Tolerance::RENDERS,
                ALPHA,
                mask,
            );
            (v, None, reference.mean.clone())
        }
        (UserImage::Linear { values, .. }, Some(noise)) => {
            let (v, tests) = welch_test(values, noise, reference_noise.as_ref(), reference);
            (v, Some(tests), reference.mean.clone())
        }
    };
    let regions = reference.job.scene().objects.len() + 1;
    let width = reference.job.scene().width;
    let summary = summarise(&verdicts, &reference.labels, regions, width, &in_unit);
    Outcome {
        verdicts,
        summary,
        tests,
    }
}

/// The reference's 8-bit sRGB codes, the unit a PNG's differences are in.
fn reference_codes(mean: &[f64]) -> Vec<f64> {
    mean.iter()
        .map(|&r| f64::from(to_srgb8(r as f32)))
        .collect()
}

/// Welch's test of a mean image with its noise against the reference's
/// (or, for a deterministic reference, against its values alone).
fn welch_test(
    values: &[f64],
    noise: Noise,
    reference_noise: Option<&Estimate>,
    reference: &Reference,
) -> (Verdicts, Tests) {
    let zeros = vec![0.0; reference.mean.len()];
    // A deterministic reference: no variance, and two samples so
    // that Welch's degrees of freedom come from the image alone.
    let fixed = Estimate {
        mean: &reference.mean,
        variance: &zeros,
        samples: 2,
    };
    let image = Estimate {
        mean: values,
        variance: noise.variance,
        samples: noise.samples,
    };
    welch(
        &image,
        reference_noise.unwrap_or(&fixed),
        reference.job.scene().width,
        Tolerance::RENDERS,
        ALPHA,
        mask_of(reference),
    )
}

/// The pixels not compared: those on the reference's silhouettes.
fn mask_of(reference: &Reference) -> Option<&[bool]> {
    Some(reference.silhouettes.as_slice())
}
