//! The renders against Mitsuba, scene by scene: each scene's reference
//! decoded, rendered by the renderer under test with the reference's
//! settings, compared, and checked to be the scene file on disk.

use std::path::Path;

use tracer::render::Image;
use tracer::scene::{IntegratorKind, PixelFilter, RayOffset};

use super::common::{Compared, MITSUBA_RAY_EPSILON};
use super::figure::RenderFigure;
use super::path::compare_path;
use super::reference::{decode, MitsubaRenders, SceneRenders, FILE};
use super::runner::{path_statistics, path_statistics_with, tracer_render, Renderer};
use super::whitted::compare_whitted;
use crate::check::Check;
use crate::context::{Context, Samples};
use crate::reference::ReferenceError;

/// The renders against Mitsuba, by a renderer under test.
pub struct RenderChecks {
    /// The renderer.
    pub render: Renderer,
}

impl RenderChecks {
    /// The tracer.
    pub fn tracer() -> Self {
        Self {
            render: tracer_render,
        }
    }

    /// Samples per pixel of the tracer's path renders at the reference's
    /// 320 × 240: 8 with `--quick` (about 4.5 s of the run, most of it the
    /// lit kaleidoscope's mirror chains), 128 otherwise.
    pub const SAMPLES: Samples = Samples {
        quick: 8,
        full: 128,
    };

    /// Every scene of `reference` (read from `context`'s reference
    /// directory), appended to `checks` and `figures`.
    pub fn run_all(
        &self,
        reference: &MitsubaRenders,
        context: &Context,
        checks: &mut Vec<Check>,
        figures: &mut Vec<RenderFigure>,
    ) -> Result<(), ReferenceError> {
        let file = context.reference_dir.join(FILE);
        for (index, s) in reference.scenes.iter().enumerate() {
            let decoded = decode(&file, index, s)?;
            let stale = stale_scene(&context.checkout, s, &reference.regenerate);
            let mut settings = decoded.scene.settings;
            settings.integrator = IntegratorKind::Whitted;
            settings.max_depth = s.whitted.max_depth;
            settings.throughput_cutoff = s.whitted.throughput_cutoff as f32;
            let whitted = match (self.render)(&decoded.scene, &settings) {
                Ok(ours) => compare_whitted(&s.name, &decoded, &ours),
                Err(e) => failed_render(&s.name, "whitted", e),
            };
            let path = s.path.as_ref().and_then(|p| {
                let samples = context.samples(Self::SAMPLES);
                let Some(images) = &decoded.path else {
                    return None;
                };
                // Under Mitsuba's rule every bounce can free light its
                // offsets move (inside a dielectric sphere), so the escapes
                // are counted as Mitsuba's `path` counts them: after
                // `mitsuba_max_depth - 1` scatterings, one more than the
                // suite's `max_depth` allows.
                let under_mitsuba_offsets = || {
                    path_statistics_with(
                        self.render,
                        &images.scene,
                        p.mitsuba_max_depth - 1,
                        samples,
                        PixelFilter::Box,
                        Some(RayOffset::Scaled(MITSUBA_RAY_EPSILON)),
                    )
                };
                match path_statistics(self.render, &images.scene, p.max_depth, samples) {
                    Ok((mean, variance)) => compare_path(
                        &s.name,
                        &decoded,
                        p.samples,
                        (&mean, &variance),
                        samples,
                        &under_mitsuba_offsets,
                    ),
                    Err(e) => Some(failed_render(&s.name, "path", e)),
                }
            });
            for mut compared in std::iter::once(whitted).chain(path) {
                if let Some(stale) = &stale {
                    compared.check.fail(stale.clone());
                }
                checks.push(compared.check);
                figures.push(compared.figure);
            }
        }
        Ok(())
    }
}

/// Why the scene file in the checkout is not the one Mitsuba rendered, if it
/// is not; a scene file that cannot be read is not compared.
fn stale_scene(checkout: &Path, s: &SceneRenders, regenerate: &str) -> Option<String> {
    let text = std::fs::read_to_string(checkout.join(&s.scene_file)).ok()?;
    (text != s.scene_text).then(|| {
        format!(
            "{} differs from the scene Mitsuba rendered: regenerate with `{regenerate}`",
            s.scene_file
        )
    })
}

fn failed_render(name: &str, integrator: &str, error: String) -> Compared {
    let mut check = Check::new(
        &format!("renders.mitsuba.{name}.{integrator}"),
        [
            &format!("{name}: the tracer's {integrator} render"),
            &format!("{name}: a sugárkövető {integrator} képe"),
        ],
        [
            "Mitsuba 3 (mitsuba_renders.json)",
            "Mitsuba 3 (mitsuba_renders.json)",
        ],
        ["the render succeeds", "a kép sikeresen elkészül"],
    );
    check.cases = 1;
    check.fail(format!("the render failed: {error}"));
    Compared {
        check,
        figure: RenderFigure {
            file: format!("render_{name}_{integrator}.png"),
            image: Image {
                width: 1,
                height: 1,
                pixels: vec![glam::Vec3::ZERO],
            },
            panels: 1,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::committed_dir;

    #[test]
    fn a_scene_file_edited_since_the_reference_is_named() {
        let reference = MitsubaRenders::load(&committed_dir()).unwrap();
        let s = &reference.scenes[0];
        let checkout = tempfile::tempdir().unwrap();
        let on_disk = checkout.path().join(&s.scene_file);
        // No file: nothing to compare.
        assert_eq!(stale_scene(checkout.path(), s, "regen"), None);
        std::fs::create_dir_all(on_disk.parent().unwrap()).unwrap();
        std::fs::write(&on_disk, &s.scene_text).unwrap();
        assert_eq!(stale_scene(checkout.path(), s, "regen"), None);
        std::fs::write(&on_disk, format!("{} ", s.scene_text)).unwrap();
        let stale = stale_scene(checkout.path(), s, "regen").unwrap();
        assert!(
            stale.starts_with(&s.scene_file) && stale.ends_with("`regen`"),
            "{stale}"
        );
    }
}
