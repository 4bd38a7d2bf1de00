//! The share of the light the path tracer misses on any scene, measured by
//! the tracer alone: where no reference of Mitsuba's holds the scene (a
//! user's own), `passes` independent renders of `path` and of `photon`
//! (whose caustic map carries the chains delta light → mirrors or glass →
//! rough surface that no camera path finds), each region's mean per pass,
//! and `1 − path / photon` with its standard error from the spread of the
//! passes ([`share`], the delta method).
//!
//! What that error leaves out: the photon map's own kernel bias, which
//! blurs a caustic over the gather radius. It shifts light within a region
//! more than it adds or removes it, so a region's share is less affected
//! than a pixel's; the harness measures it on the course scenes against
//! Mitsuba's light tracer (`full_light.tracer.*.photon.all_the_light`).

use tracer::job::{RenderError, RenderJob};
use tracer::render::Image;
use tracer::scene::{IntegratorKind, PixelFilter, Precision, RenderSpec};

use super::statistics::{share, RegionMean, Share};

/// The passes a measurement takes of each integrator: the fewest whose
/// Student t (3 degrees of freedom) still gives a usable standard error.
pub const PASSES: u32 = 4;

/// What the path tracer misses of the light on one scene, per region.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MissingShare {
    /// Where the camera sees any surface.
    pub surface: Share,
    /// Where it sees a rough (diffuse) one; `None` where it sees none.
    pub diffuse: Option<Share>,
    /// Independent renders of each integrator.
    pub passes: u32,
    /// Seconds all the renders took.
    pub seconds: f64,
}

/// Measures on `job`'s scene, at its settings (size, spp, depth, photon
/// map), `passes` renders of `path` and of `photon` on `threads` threads,
/// the seeds of each pass their own. `None` where the camera sees no
/// surface, or the photon renders carry no light there.
pub fn missing_share(
    job: &RenderJob,
    passes: u32,
    threads: Option<usize>,
) -> Result<Option<MissingShare>, RenderError> {
    let scene = job.scene();
    let hits = job.first_hits();
    let surface: Vec<bool> = hits.iter().map(Option::is_some).collect();
    let diffuse: Vec<bool> = hits
        .iter()
        .map(|hit| {
            hit.is_some_and(|o| {
                scene.materials[scene.objects[o as usize].material() as usize].is_rough()
            })
        })
        .collect();
    if !surface.contains(&true) {
        return Ok(None);
    }
    let mut seconds = 0.0;
    let mut means = |integrator: IntegratorKind, first_seed: u64| {
        let mut per_pass = Vec::with_capacity(passes as usize);
        for pass in 0..u64::from(passes) {
            let spec = RenderSpec {
                integrator: Some(integrator),
                precision: Some(Precision::F32),
                pixel_filter: Some(PixelFilter::Box),
                seed: Some(first_seed + pass),
                ..RenderSpec::default()
            };
            let settings = job
                .settings()
                .settle("inspect.measure", &spec)
                .expect("an integrator, the f32 tier, the box filter and a seed are each within their domain");
            let varied = RenderJob::with_settings(scene.clone(), settings)
                .expect("path and photon render every scene at the f32 tier");
            let rendered = varied.render(threads, &|_| {})?;
            seconds += rendered.elapsed.as_secs_f64();
            per_pass.push([
                region_mean(&rendered.image, &surface),
                region_mean(&rendered.image, &diffuse),
            ]);
        }
        Ok::<_, RenderError>(per_pass)
    };
    let base = job.settings().seed;
    let path = means(IntegratorKind::Path, base)?;
    let photon = means(IntegratorKind::Photon, base + u64::from(passes))?;
    let region = |r: usize| {
        let per_pass = |passes: &[[Option<f64>; 2]]| -> Option<RegionMean> {
            let values: Option<Vec<f64>> = passes.iter().map(|p| p[r]).collect();
            Some(RegionMean::from_passes(values?))
        };
        let (found, full) = (per_pass(&path)?, per_pass(&photon)?);
        (full.0.mean > 0.0).then(|| share(found, full))
    };
    let Some(surface) = region(0) else {
        return Ok(None);
    };
    Ok(Some(MissingShare {
        surface,
        diffuse: region(1),
        passes,
        seconds,
    }))
}

/// The mean radiance over `mask`'s pixels, summed over the channels;
/// `None` for an empty mask.
fn region_mean(image: &Image, mask: &[bool]) -> Option<f64> {
    let (sum, count) = image
        .pixels
        .iter()
        .zip(mask)
        .filter(|(_, &inside)| inside)
        .fold((0.0, 0usize), |(sum, count), (p, _)| {
            (sum + f64::from(p.x + p.y + p.z), count + 1)
        });
    (count > 0).then(|| sum / count as f64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use tracer::job::Overrides;

    /// A course scene at 48 × 36, 16 samples per pixel, path.
    fn job(name: &str) -> RenderJob {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../crates/tracer/scenes")
            .join(format!("{name}.json"));
        let overrides = Overrides {
            width: Some(48),
            height: Some(36),
            render: RenderSpec {
                integrator: Some(IntegratorKind::Path),
                spp: Some(16.0),
                ..RenderSpec::default()
            },
            ..Overrides::default()
        };
        RenderJob::load(&path, &overrides).unwrap()
    }

    /// Where no delta light reaches a rough surface through mirrors or
    /// glass, photon renders what path does: the share is zero within 4
    /// standard errors.
    #[test]
    fn a_scene_without_mirrors_or_glass_misses_no_light() {
        let m = missing_share(&job("diffuse"), PASSES, Some(2))
            .unwrap()
            .unwrap();
        assert!(m.surface.standard_error > 0.0, "{m:?}");
        assert!(
            m.surface.share.abs() <= 4.0 * m.surface.standard_error,
            "{m:?}"
        );
    }

    /// The sun reflected by the gold spheres onto the green floor is light
    /// no camera path finds: path misses a share of the diffuse region's
    /// light more than 5 standard errors above zero, and at most all of it.
    #[test]
    fn path_misses_the_gold_spheres_caustic() {
        let m = missing_share(&job("gold_spheres"), PASSES, Some(2))
            .unwrap()
            .unwrap();
        let diffuse = m.diffuse.expect("the camera sees the floor");
        assert!(diffuse.share > 5.0 * diffuse.standard_error, "{m:?}");
        assert!(diffuse.share < 1.0, "{m:?}");
        assert_eq!(m.passes, PASSES);
    }
}
