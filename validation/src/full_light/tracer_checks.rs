//! The checks of all the light by a renderer under test: every scene of the
//! reference, rendered by the tracer (or a deliberately broken renderer) and
//! checked with [`super::checks`].

use super::checks::{
    check_all_the_light_in, check_independent, check_missing_share, check_same_missing_light,
    has_delta_surface, TracerRender,
};
use super::estimates::{Estimate, Region};
use super::reference::{decode, DecodedLight, FullLight, FILE};
use crate::check::Check;
use crate::context::{Context, Samples};
use crate::reference::ReferenceError;
use crate::renders::{path_statistics_with, sample_statistics, tracer_render, Renderer};
use tracer::scene::{IntegratorKind, PixelFilter};

/// The checks of all the light, by a renderer under test.
pub struct FullLightChecks {
    /// The renderer.
    pub render: Renderer,
}

impl FullLightChecks {
    /// The tracer.
    pub fn tracer() -> Self {
        Self {
            render: tracer_render,
        }
    }

    /// Samples per pixel of the tracer's path renders: 16 with `--quick`,
    /// 256 otherwise.
    pub const SAMPLES: Samples = Samples {
        quick: 16,
        full: 256,
    };

    /// Renders of the `photon` check, one sample per pixel each with its
    /// own photon maps: 8 with `--quick` (each builds 80 000 photons; their
    /// regions' means are far from the heavy tails that need the path
    /// check's 16), 256 otherwise.
    pub const PHOTON_RENDERS: Samples = Samples {
        quick: 8,
        full: 256,
    };

    /// Every scene of `reference` (read from `context`'s reference directory).
    pub fn run_all(
        &self,
        reference: &FullLight,
        context: &Context,
        checks: &mut Vec<Check>,
    ) -> Result<(), ReferenceError> {
        let file = context.reference_dir.join(FILE);
        for (index, s) in reference.scenes.iter().enumerate() {
            let decoded = decode(&file, index, s)?;
            checks.extend(check_independent(&s.name, &decoded));
            checks.push(check_missing_share(&s.name, &decoded));
            let samples = context.samples(Self::SAMPLES);
            let max_depth = decoded.scene.settings.max_depth;
            // Through the pixel centres, as `path_centres` is rendered.
            let centres = path_statistics_with(
                self.render,
                &decoded.scene,
                max_depth,
                samples,
                PixelFilter::Center,
                None,
            );
            checks.push(match centres {
                Ok((mean, variance)) => check_same_missing_light(
                    &s.name,
                    &IntegratorKind::Path.to_string(),
                    &decoded,
                    TracerRender {
                        mean: &mean,
                        variance: &variance,
                        samples,
                    },
                ),
                Err(e) => render_failed(&s.name, "path.missing_share", &e),
            });
            let diffuse = Estimate::ALL
                .iter()
                .any(|&e| decoded.passes.contains_key(&(e, Region::Diffuse)));
            if has_delta_surface(&decoded.scene) && diffuse {
                let renders = context.samples(Self::PHOTON_RENDERS);
                checks.push(self.all_the_light(&s.name, &decoded, renders));
            }
        }
        Ok(())
    }

    /// The tracer's `photon` integrator, which claims all the light that
    /// reaches diffuse surfaces, against Mitsuba's two full-light estimates
    /// on the pixels that see one: `samples` renders of one sample per pixel
    /// through the pixel centres, each with [`PHOTONS_PER_PASS`] photons in
    /// each of [`PHOTON_PASSES`] passes. The pixels that see a mirror or
    /// glass are not compared: they hold the delta lights' own images
    /// (light → mirrors or glass → camera), a point of unbounded radiance
    /// that no integrator of a delta light draws and the stand-in area
    /// lights spread over a disk.
    fn all_the_light(&self, name: &str, decoded: &DecodedLight, samples: u32) -> Check {
        let mut settings = decoded.scene.settings;
        settings.integrator = IntegratorKind::Photon;
        settings.pixel_filter = PixelFilter::Center;
        settings.photon.photons = PHOTONS_PER_PASS;
        settings.photon.passes = PHOTON_PASSES;
        let integrator = IntegratorKind::Photon.to_string();
        match sample_statistics(self.render, &decoded.scene, settings, 0..u64::from(samples)) {
            Ok((mean, variance)) => check_all_the_light_in(
                name,
                &integrator,
                decoded,
                TracerRender {
                    mean: &mean,
                    variance: &variance,
                    samples,
                },
                &[Region::Diffuse],
            ),
            Err(e) => render_failed(name, "photon.all_the_light", &e),
        }
    }
}

/// Photons per pass of each `photon` render of the check: each of the
/// check's renders builds its own maps, so fewer than a picture's.
const PHOTONS_PER_PASS: u32 = 20_000;

/// Photon passes of each `photon` render of the check.
const PHOTON_PASSES: u32 = 4;

/// A check that failed because its render did.
fn render_failed(name: &str, what: &str, error: &str) -> Check {
    let mut check = Check::new(
        &format!("full_light.tracer.{name}.{what}"),
        [
            &format!("{name}: the tracer's render"),
            &format!("{name}: a sugárkövető képe"),
        ],
        ["mitsuba_full_light.json", "mitsuba_full_light.json"],
        ["the render succeeds", "a kép sikeresen elkészül"],
    );
    check.cases = 1;
    check.fail(format!("the render failed: {error}"));
    check
}
