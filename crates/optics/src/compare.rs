//! `optics compare`: a user's own render of a scene held against the
//! suite's reference render of it. The comparison is the library's
//! ([`validation::user_render`]); this module settles the flags into its
//! request, makes the one call and prints the record, adding the flags'
//! names to what the library says.

use std::path::PathBuf;
use std::process::ExitCode;

use record::{say, Record};
use serde::Serialize;
use tracer::scene::IntegratorKind;
use validation::user_render::{self, Comparison, Names, Request};

use crate::error::compare::{IMAGE, VARIANCE};
use crate::error::HarnessKind;
use crate::error::{self, ErrorKind};
use crate::ui::Ui;

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

/// Compares; the exit status says whether the image agrees (with
/// `--json` the record is the whole answer, without it a disagreement is
/// also reported as an error).
pub fn run(args: &CompareArgs, ui: &Ui) -> error::Result<ExitCode> {
    let request = Request {
        image: &args.image,
        scene: &args.scene,
        variance: args.variance.as_deref().zip(args.samples),
        diff: args.diff.as_deref(),
        integrator: args.integrator,
        reference_samples: args.reference_samples,
        names: NAMES,
    };
    let comparison = user_render::compare(&request, |job| {
        crate::render::warn_if_long(job, ui.lang);
    })
    .map_err(failure)?;
    ui.show_steps(&record(args, &comparison, ui))?;
    match (comparison.verdict(), ui.json) {
        (Ok(()), _) => Ok(ExitCode::SUCCESS),
        (Err(_), true) => Ok(ExitCode::FAILURE),
        (Err(disagrees), false) => Err(ErrorKind::Harness(HarnessKind::Compare(disagrees)).into()),
    }
}

/// The library's error as this command's: a scene refused as `optics
/// render` refuses it, a render stopped as a render's, an image's kind as
/// one of compare's.
fn failure(error: user_render::Error) -> error::Error {
    use user_render::Error as Failure;
    match error {
        Failure::Scene { file, error } => ErrorKind::Scene { file, error }.into(),
        Failure::Render(error) => error.into(),
        Failure::Compare(error) => ErrorKind::Harness(HarnessKind::Compare(error)).into(),
    }
}

/// The images as the errors name them: the argument and the flag.
const NAMES: Names = Names {
    image: IMAGE,
    variance: VARIANCE,
};

/// The library's record with the flags as given, and the advice to give
/// an image's own noise where the image was held to the reference's alone.
fn record(args: &CompareArgs, comparison: &Comparison, ui: &Ui) -> Record {
    let lang = ui.lang;
    let mut record = user_render::record(comparison, lang);
    record.inputs_from(args);
    if comparison.held_to_reference_noise_alone() {
        record.step(|| say!(
            lang,
            "the reference is Monte Carlo and the image is held to its noise alone: an image with noise of its own needs --variance and --samples",
            "a referencia Monte Carlo-becslés, a képet csak a referencia zajához méri: saját zajjal bíró képhez a --variance és a --samples kell"
        ));
    }
    record
}

/// The image as [`run`] admits it before rendering (the fuzz target's
/// entry point): decoded, every value finite, and its size one the scene
/// can be rendered at, with the job that renders the reference.
#[cfg(test)]
pub(crate) fn admit(
    path: &std::path::Path,
    bytes: &[u8],
    scene: &std::path::Path,
    integrator: Option<IntegratorKind>,
) -> error::Result<(user_render::UserImage, tracer::job::RenderJob)> {
    user_render::admit(IMAGE, path, bytes, scene, integrator).map_err(failure)
}

/// The image reader's fault switch, where the fuzz target finds it.
#[cfg(test)]
pub(crate) mod user_image {
    pub(crate) use validation::user_render::LENGTH_UNCHECKED;
}
