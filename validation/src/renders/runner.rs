//! Rendering for the comparisons: the renderer under test, and the path
//! tracer's per-pixel sample statistics.

use tracer::job::RenderJob;
use tracer::render::Image;
use tracer::scene::{IntegratorKind, PixelFilter, RayOffset, RenderSpec, Scene, Settings};

use super::common::flatten;

/// Renders a scene with settings; the tracer, or a deliberately broken one.
pub type Renderer = fn(&Scene, &Settings) -> Result<Image, String>;

/// The tracer as `optics render` runs it: the scene's needs decide the
/// machinery, all cores.
pub fn tracer_render(scene: &Scene, settings: &Settings) -> Result<Image, String> {
    RenderJob::with_settings(scene.clone(), *settings)
        .map_err(|e| e.to_string())?
        .render(None, &|_| {})
        .map(|r| r.image)
        .map_err(|e| e.to_string())
}

/// The tracer's path samples: per-pixel mean and unbiased variance of one
/// sample, from `samples` renders at 1 sample per pixel with seeds
/// `0..samples`, box filtered as the reference is (each render's one sample
/// jittered over the whole pixel, independently of the others').
pub fn path_statistics(
    render: Renderer,
    scene: &Scene,
    max_depth: u32,
    samples: u32,
) -> Result<(Vec<f64>, Vec<f64>), String> {
    path_statistics_with(render, scene, max_depth, samples, PixelFilter::Box, None)
}

/// [`path_statistics`] through `pixel_filter`, with secondary rays started
/// by `ray_offset` instead of the scene's rule where one is given.
pub fn path_statistics_with(
    render: Renderer,
    scene: &Scene,
    max_depth: u32,
    samples: u32,
    pixel_filter: PixelFilter,
    ray_offset: Option<RayOffset>,
) -> Result<(Vec<f64>, Vec<f64>), String> {
    let spec = RenderSpec {
        integrator: Some(IntegratorKind::Path),
        pixel_filter: Some(pixel_filter),
        max_depth: Some(max_depth.into()),
        spp: Some(1.0),
        ray_offset,
        ..RenderSpec::default()
    };
    let settings = scene
        .settings
        .settle("comparison", &spec)
        .map_err(|e| e.to_string())?;
    sample_statistics(render, scene, settings, 0..u64::from(samples))
}

/// Per-pixel mean and unbiased variance of one sample under `settings`
/// (its pixel filter kept), from one render at 1 sample per pixel for each
/// seed of `seeds` (at least two).
pub fn sample_statistics(
    render: Renderer,
    scene: &Scene,
    mut settings: Settings,
    seeds: std::ops::Range<u64>,
) -> Result<(Vec<f64>, Vec<f64>), String> {
    settings.spp = 1;
    let n = (3 * scene.width * scene.height) as usize;
    let samples = seeds.end - seeds.start;
    // Welford's running mean and sum of squared deviations: exact zero
    // variance where every sample is the same, no cancellation elsewhere.
    let (mut mean, mut squares) = (vec![0.0; n], vec![0.0; n]);
    for (k, seed) in seeds.enumerate() {
        settings.seed = seed;
        let image = flatten(&render(scene, &settings)?);
        let count = (k + 1) as f64;
        for (i, v) in image.into_iter().enumerate() {
            let delta = v - mean[i];
            mean[i] += delta / count;
            squares[i] += delta * (v - mean[i]);
        }
    }
    let variance = squares.iter().map(|q| q / (samples as f64 - 1.0)).collect();
    Ok((mean, variance))
}
