//! `optics compare`: a user's own render of a scene held against the
//! suite's reference render of it, by the harness's own machinery
//! ([`validation::compare`]): which test fits the image, the verdict, the
//! regions that disagree and by how much, and a difference map.
//!
//! | image | test |
//! |---|---|
//! | PNG (8-bit sRGB) | its codes within those of the reference's tolerance interval, one code more either side |
//! | PFM (linear radiance) | per pixel-channel `\|Δ\| ≤ 1e-5 + 1e-3 · \|reference\|`, plus the reference's own noise |
//! | PFM with `--variance` and `--samples` | Welch's t per pixel-channel, Bonferroni-corrected, and beyond that tolerance |

mod reference;
mod report;
pub(crate) mod user_image;

use std::path::PathBuf;
use std::process::ExitCode;

use safe_io::check_destination;
use serde::Serialize;
use tracer::output::{to_srgb8, write_png};
use tracer::scene::IntegratorKind;
use validation::compare::map::difference_map;
use validation::compare::regions::{summarise, Summary};
use validation::compare::welch::{welch, Tests};
use validation::compare::{tolerance, Estimate, Tolerance, Verdicts};
use validation::renders::ALPHA;

use crate::error::compare::CompareError;
use crate::error::{self, ErrorKind};
use crate::ui::Ui;
use reference::Reference;
pub(crate) use user_image::UserImage;

#[derive(clap::Args, Debug, Serialize)]
#[command(after_help = "Examples:
  optics compare mine.png --scene crates/tracer/scenes/gold_spheres.json
  optics compare mine.pfm --scene scene.json --diff diff.png
  optics --json compare mean.pfm --scene scene.json --variance var.pfm --samples 64

Renders the scene with the tracer at IMAGE's size (its own physical
integrator, or --integrator) and compares, pixel by pixel and channel by
channel; pixels on silhouettes are not compared. Exit status 1 when the
image disagrees. See docs/cli.md for the tests and their tolerances.")]
pub struct CompareArgs {
    /// The image to check: a PNG (8-bit sRGB, as `optics render` writes it)
    /// or a PFM (linear radiance, W/(sr m²) per channel).
    pub image: PathBuf,
    /// The scene file it is a render of.
    #[arg(long)]
    pub scene: PathBuf,
    /// The per-sample variance of IMAGE's radiance, a PFM of its size;
    /// IMAGE is then the mean of --samples samples per pixel.
    #[arg(long, value_name = "VAR.pfm", requires = "samples")]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub variance: Option<PathBuf>,
    /// Samples per pixel behind IMAGE and --variance.
    #[arg(long, requires = "variance", value_parser = clap::value_parser!(u32).range(2..))]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub samples: Option<u32>,
    /// Write the difference map here, a PNG of IMAGE's size.
    #[arg(long, value_name = "DIFF.png")]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub diff: Option<PathBuf>,
    /// The reference's light transport (default: the scene's); physical only.
    #[arg(long, value_enum)]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub integrator: Option<IntegratorKind>,
    /// Renders at one sample per pixel behind a path-traced reference.
    #[arg(long, default_value_t = 256, value_parser = clap::value_parser!(u32).range(2..=65536))]
    pub reference_samples: u32,
}

/// What the comparison found.
pub(crate) struct Outcome {
    /// Per pixel-channel.
    pub verdicts: Verdicts,
    /// Per region.
    pub summary: Summary,
    /// The t-tests, where Welch's test was used.
    pub tests: Option<Tests>,
}

/// Compares; the exit status says whether the image agrees (with
/// `--json` the record is the whole answer, without it a disagreement is
/// also reported as an error).
pub fn run(args: &CompareArgs, ui: &Ui) -> error::Result<ExitCode> {
    let bytes = user_image::read_bytes("IMAGE", &args.image)?;
    let (image, job) = admit(&args.image, &bytes, &args.scene, args.integrator)?;
    let (width, height) = image.size();
    let variance = match &args.variance {
        Some(path) => Some(read_variance(path, &image)?),
        None => None,
    };
    if let Some(diff) = &args.diff {
        let mut inputs = vec![args.image.as_path(), args.scene.as_path()];
        inputs.extend(args.variance.as_deref());
        check_destination(diff, &inputs)
            .map_err(|e| ErrorKind::Compare(CompareError::Diff(e.into())))?;
    }
    crate::render::warn_if_long(&job, ui.lang);
    let reference = reference::render(job, args.reference_samples)?;
    let outcome = judge(&image, variance.as_deref(), args.samples, &reference);
    if let Some(diff) = &args.diff {
        write_png(diff, &difference_map(&outcome.verdicts, width, height))
            .map_err(|e| ErrorKind::Compare(CompareError::Diff(e)))?;
    }
    ui.show_steps(&report::record(args, &reference, &outcome, ui.lang))?;
    let summary = &outcome.summary;
    match (summary.agrees(), ui.json) {
        (true, _) => Ok(ExitCode::SUCCESS),
        (false, true) => Ok(ExitCode::FAILURE),
        (false, false) => Err(ErrorKind::Compare(CompareError::Disagrees {
            disagreeing: summary.disagreeing,
            pixels: summary.pixels,
        })
        .into()),
    }
}

/// The image as [`run`] admits it before rendering: decoded, every value
/// finite, and its size one the scene can be rendered at, with the job
/// that renders the reference.
pub(crate) fn admit(
    path: &std::path::Path,
    bytes: &[u8],
    scene: &std::path::Path,
    integrator: Option<IntegratorKind>,
) -> error::Result<(UserImage, tracer::job::RenderJob)> {
    let image = user_image::decode("IMAGE", path, bytes)?;
    if let UserImage::Linear { width, values, .. } = &image {
        user_image::check_values("IMAGE", *width, values, false)?;
    }
    let job = reference::job(scene, image.size(), integrator)?;
    Ok((image, job))
}

/// The variance image: a PFM of IMAGE's size, every value finite and ≥ 0.
fn read_variance(path: &std::path::Path, image: &UserImage) -> error::Result<Vec<f64>> {
    let fault = |e: CompareError| error::Error::from(ErrorKind::Compare(e));
    if matches!(image, UserImage::Codes { .. }) {
        return Err(fault(CompareError::VarianceNeedsPfm { field: "IMAGE" }));
    }
    match user_image::read("--variance", path).map_err(fault)? {
        UserImage::Codes { .. } => Err(fault(CompareError::VarianceNeedsPfm {
            field: "--variance",
        })),
        UserImage::Linear {
            width,
            height,
            values,
        } => {
            if (width, height) != image.size() {
                return Err(fault(CompareError::SizeMismatch {
                    got: (width, height),
                    expected: image.size(),
                }));
            }
            user_image::check_values("--variance", width, &values, true).map_err(fault)?;
            Ok(values)
        }
    }
}

/// The test that fits the image, made against the reference away from
/// its silhouettes, and its summary by region.
fn judge(
    image: &UserImage,
    variance: Option<&[f64]>,
    samples: Option<u32>,
    reference: &Reference,
) -> Outcome {
    let mask = Some(reference.silhouettes.as_slice());
    let noise = reference
        .noise
        .as_ref()
        .map(|(variance, samples)| Estimate {
            mean: &reference.mean,
            variance,
            samples: *samples,
        });
    let (verdicts, tests, in_unit) = match (image, variance) {
        (UserImage::Codes { codes, .. }, _) => {
            let v = tolerance::codes(
                codes,
                &reference.mean,
                noise.as_ref(),
                Tolerance::RENDERS,
                ALPHA,
                mask,
            );
            let codes = reference
                .mean
                .iter()
                .map(|&r| f64::from(to_srgb8(r as f32)))
                .collect();
            (v, None, codes)
        }
        (UserImage::Linear { values, .. }, None) => {
            let v = tolerance::radiance(
                values,
                &reference.mean,
                noise.as_ref(),
                Tolerance::RENDERS,
                ALPHA,
                mask,
            );
            (v, None, reference.mean.clone())
        }
        (UserImage::Linear { values, .. }, Some(variance)) => {
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
                variance,
                samples: samples.unwrap_or(2),
            };
            let (v, tests) = welch(
                &image,
                noise.as_ref().unwrap_or(&fixed),
                reference.job.scene().width,
                Tolerance::RENDERS,
                ALPHA,
                mask,
            );
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
