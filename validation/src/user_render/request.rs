//! One comparison as one call: the image and its scene in, the reference,
//! the verdicts and the difference map out; each input checked where it
//! enters, before the reference is rendered.

use std::path::{Path, PathBuf};

use safe_io::check_destination;
use tracer::job::RenderJob;
use tracer::output::write_png;
use tracer::scene::IntegratorKind;

use super::error::{CompareError, Error};
use super::judge::{judge, Noise, Outcome};
use super::reference::{self, Reference};
use super::user_image::{self, UserImage};
use crate::compare::map::difference_map;

/// The names the caller knows the input images by (a command's arguments,
/// a form's fields), quoted in the errors about them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Names {
    /// The image's.
    pub image: &'static str,
    /// The variance's.
    pub variance: &'static str,
}

impl Default for Names {
    fn default() -> Self {
        Names {
            image: "image",
            variance: "variance",
        }
    }
}

/// A comparison, settled: what to compare with what, and how.
#[derive(Clone, Debug)]
pub struct Request<'a> {
    /// The image to check: a PNG (8-bit sRGB) or a PFM (linear radiance,
    /// W/(sr m²) per channel).
    pub image: &'a Path,
    /// The scene file it is a render of.
    pub scene: &'a Path,
    /// The per-sample variance of the image's radiance (a PFM of its
    /// size) and the samples per pixel (≥ 2) it is the mean of.
    pub variance: Option<(&'a Path, u32)>,
    /// Where to write the difference map, a PNG of the image's size.
    pub diff: Option<&'a Path>,
    /// The reference's light transport (`None`: the scene's); physical only.
    pub integrator: Option<IntegratorKind>,
    /// Renders at one sample per pixel behind a path-traced reference.
    pub reference_samples: u32,
    /// How the errors name the images.
    pub names: Names,
}

/// What one comparison found, and where its difference map went.
pub struct Comparison {
    /// The reference the image was held against.
    pub reference: Reference,
    /// The verdicts and their summary.
    pub outcome: Outcome,
    /// The difference map, written.
    pub diff: Option<PathBuf>,
}

impl Comparison {
    /// `Ok` when the image agrees, else the disagreement as an error.
    pub fn verdict(&self) -> Result<(), CompareError> {
        let summary = &self.outcome.summary;
        match summary.agrees() {
            true => Ok(()),
            false => Err(CompareError::Disagrees {
                disagreeing: summary.disagreeing,
                pixels: summary.pixels,
            }),
        }
    }

    /// Whether a Monte Carlo reference held an image with no noise of its
    /// own to the reference's noise alone (an image's own noise needs its
    /// variance and samples).
    pub fn held_to_reference_noise_alone(&self) -> bool {
        self.reference.noise.is_some() && self.outcome.tests.is_none()
    }
}

/// Compares `request.image` with the scene's reference at its size: reads
/// and checks every input, then calls `before_render` with the job about to
/// render the reference (a front end may warn that it is long), renders it,
/// judges and writes the difference map.
pub fn compare(
    request: &Request,
    before_render: impl FnOnce(&RenderJob),
) -> Result<Comparison, Error> {
    let names = request.names;
    let bytes = user_image::read_bytes(names.image, request.image)?;
    let (image, job) = admit(
        names.image,
        request.image,
        &bytes,
        request.scene,
        request.integrator,
    )?;
    let noise = match request.variance {
        Some((path, samples)) => Some((read_variance(names, path, &image)?, samples)),
        None => None,
    };
    if let Some(diff) = request.diff {
        let mut inputs = vec![request.image, request.scene];
        inputs.extend(request.variance.map(|(path, _)| path));
        check_destination(diff, &inputs).map_err(|e| CompareError::Diff(e.into()))?;
    }
    before_render(&job);
    let reference = reference::render(job, request.reference_samples)?;
    let noise = noise.as_ref().map(|(variance, samples)| Noise {
        variance,
        samples: *samples,
    });
    let outcome = judge(&image, noise, &reference);
    if let Some(diff) = request.diff {
        let (width, height) = image.size();
        write_png(diff, &difference_map(&outcome.verdicts, width, height))
            .map_err(CompareError::Diff)?;
    }
    Ok(Comparison {
        reference,
        outcome,
        diff: request.diff.map(Path::to_owned),
    })
}

/// The image as [`compare`] admits it before rendering: `bytes` (read from
/// `path`, named `name`) decoded, every value finite, and its size one the
/// scene can be rendered at, with the job that renders the reference.
pub fn admit(
    name: &'static str,
    path: &Path,
    bytes: &[u8],
    scene: &Path,
    integrator: Option<IntegratorKind>,
) -> Result<(UserImage, RenderJob), Error> {
    let image = user_image::decode(name, path, bytes)?;
    if let UserImage::Linear { width, values, .. } = &image {
        user_image::check_values(name, *width, values, false)?;
    }
    let job = reference::job(scene, image.size(), integrator)?;
    Ok((image, job))
}

/// The variance image: a PFM of the image's size, every value finite and ≥ 0.
fn read_variance(names: Names, path: &Path, image: &UserImage) -> Result<Vec<f64>, CompareError> {
    if matches!(image, UserImage::Codes { .. }) {
        return Err(CompareError::VarianceNeedsPfm { field: names.image });
    }
    match user_image::read(names.variance, path)? {
        UserImage::Codes { .. } => Err(CompareError::VarianceNeedsPfm {
            field: names.variance,
        }),
        UserImage::Linear {
            width,
            height,
            values,
        } => {
            if (width, height) != image.size() {
                return Err(CompareError::SizeMismatch {
                    got: (width, height),
                    expected: image.size(),
                });
            }
            user_image::check_values(names.variance, width, &values, true)?;
            Ok(values)
        }
    }
}
