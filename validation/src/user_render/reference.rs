//! The reference a user's image is held against: the scene rendered by the
//! tracer at the image's size with its own physical integrator, as a mean
//! and, for a Monte Carlo render, the per-sample variance; and what the
//! camera sees at each pixel, the regions of the report.

use std::path::Path;

use tracer::job::{Overrides, RenderJob};
use tracer::scene::{ErrorKind as SceneKind, IntegratorKind, RenderSpec};

use super::error::{CompareError, Error};
use crate::compare::regions::silhouettes;
use crate::renders::{sample_statistics, tracer_render};

/// The first seed of a path-traced reference's renders: a user's renders
/// with seeds below 2³² share no random stream with it.
pub const FIRST_SEED: u64 = 1 << 32;

/// The scene's reference at one size.
pub struct Reference {
    /// The job it was rendered with.
    pub job: RenderJob,
    /// Mean radiance, flat RGB, rows top to bottom.
    pub mean: Vec<f64>,
    /// Per-sample variance and samples, for a Monte Carlo reference.
    pub noise: Option<(Vec<f64>, u32)>,
    /// Per pixel, the region: the object seen, or `objects.len()` for the
    /// background.
    pub labels: Vec<usize>,
    /// Per pixel, whether a neighbour sees another region.
    pub silhouettes: Vec<bool>,
}

/// The job for `scene` at `width × height` under `integrator`; a size the
/// scene cannot be rendered at is the image's fault.
pub fn job(
    scene: &Path,
    (width, height): (u32, u32),
    integrator: Option<IntegratorKind>,
) -> Result<RenderJob, Error> {
    let overrides = Overrides {
        render: RenderSpec {
            integrator,
            ..RenderSpec::default()
        },
        width: Some(width),
        height: Some(height),
        allow_expensive: false,
    };
    let job = RenderJob::load(scene, &overrides).map_err(|error| {
        let size = error.field().starts_with("overrides.width")
            || error.field().starts_with("overrides.height")
            || matches!(error.kind(), SceneKind::TooManyPixels { .. });
        match size {
            true => Error::Compare(CompareError::Size {
                width,
                height,
                error,
            }),
            false => Error::Scene {
                file: scene.to_owned(),
                error,
            },
        }
    })?;
    if job.settings().integrator == IntegratorKind::Course {
        return Err(CompareError::CourseReference.into());
    }
    Ok(job)
}

/// Renders the reference: one render of a deterministic integrator, or
/// `samples` renders at one sample per pixel with seeds from
/// [`FIRST_SEED`] for the sampling integrators (`path`, `photon`) where their paths vary.
pub fn render(job: RenderJob, samples: u32) -> Result<Reference, Error> {
    let settings = *job.settings();
    let scene = job.scene();
    let mut probe = settings;
    probe.spp = 2;
    let varies = settings.integrator.samples()
        && RenderJob::with_settings(scene.clone(), probe).is_ok_and(|j| j.machinery().spp > 1);
    let (mean, noise) = if varies {
        let seeds = FIRST_SEED..FIRST_SEED + u64::from(samples);
        let (mean, variance) = sample_statistics(tracer_render, scene, settings, seeds)
            .map_err(|message| CompareError::Reference { message })?;
        (mean, Some((variance, samples)))
    } else {
        let image = job.render(None, &|_| {})?.image;
        let mean = image
            .pixels
            .iter()
            .flat_map(|p| p.to_array())
            .map(f64::from)
            .collect();
        (mean, None)
    };
    let background = scene.objects.len();
    let labels: Vec<usize> = job
        .first_hits()
        .into_iter()
        .map(|hit| hit.map_or(background, |i| i as usize))
        .collect();
    let silhouettes = silhouettes(&labels, scene.width, scene.height);
    Ok(Reference {
        job,
        mean,
        noise,
        labels,
        silhouettes,
    })
}
