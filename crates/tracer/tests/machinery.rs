//! What a scene needs and what the renderer runs: every course scene loads
//! and renders, skipping unused machinery leaves the image unchanged, the
//! shadow rule for convex objects, and the reachable bounce depth as a bound
//! the renders respect.

mod common;

use common::{job, render_with};
use tracer::job::RenderJob;
use tracer::needs;
use tracer::scene::{self, IntegratorKind, Scene, Settings};

fn course_scenes() -> Vec<(String, Scene)> {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes");
    let mut scenes: Vec<(String, Scene)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .map(|p| {
            (
                p.display().to_string(),
                scene::load(&p).unwrap().resized(32, 24),
            )
        })
        .collect();
    scenes.sort_by(|a, b| a.0.cmp(&b.0));
    scenes
}

#[test]
fn every_course_scene_loads_and_renders() {
    let scenes = course_scenes();
    assert!(scenes.len() >= 9);
    for (name, scene) in scenes {
        let s = scene.settings;
        let image = render_with(&scene, &s, None);
        assert!(image.pixels.iter().all(|p| p.is_finite()), "{name}");
        assert!(
            image.pixels.iter().any(|p| p.max_element() > 0.0),
            "{name} is black"
        );
    }
}

#[test]
fn skipping_unused_machinery_leaves_the_image_unchanged() {
    for (name, scene) in course_scenes() {
        for integrator in common::LAW_INTEGRATORS {
            let s = Settings {
                spp: 2,
                ..Settings {
                    integrator,
                    ..scene.settings
                }
            };
            let job = job(&scene, &s);
            let (lean, full) = (job.machinery(), job.everything());
            let a = job.render(None, &|_| {}).unwrap();
            let b = job.render_with(&full, None, &|_| {}).unwrap();
            let needs = job.needs();
            let tube_keeps_light_out = needs
                .lights
                .iter()
                .any(|l| l.reason == Some(tracer::needs::Unused::OutsideClosedTube));
            if tube_keeps_light_out {
                // Skipping a light the closed tube keeps out also removes
                // its rounding leaks: a shadow ray that starts within
                // rounding of where a sphere or the far wall meets a mirror
                // can slip out. Only darker pixels, and rare (1 of 76 800 at
                // 320 × 240 with 16 paths per pixel).
                let changed = a
                    .image
                    .pixels
                    .iter()
                    .zip(&b.image.pixels)
                    .filter(|(p, q)| p != q)
                    .count();
                assert!(
                    changed * 1000 <= a.image.pixels.len(),
                    "{name} {integrator}: {changed} pixels"
                );
                assert!(a
                    .image
                    .pixels
                    .iter()
                    .zip(&b.image.pixels)
                    .all(|(p, q)| p.cmple(*q).all()));
            } else if lean.spp == full.spp {
                assert!(
                    a.image == b.image,
                    "{name} {integrator}: skipping changed the image"
                );
            } else {
                // Fewer samples of a deterministic path: the same value,
                // up to the f64 mean's last rounding to f32.
                let (_, max) = a.image.difference(&b.image);
                assert!(max <= 1e-6, "{name} {integrator}: {max}");
            }
            assert!(a.rays.total() <= b.rays.total());
        }
    }
}

#[test]
fn a_single_convex_sphere_needs_no_shadow_rays_and_two_spheres_do() {
    let scenes = course_scenes();
    let find = |suffix: &str| &scenes.iter().find(|(n, _)| n.ends_with(suffix)).unwrap().1;
    let s = Settings::default();
    assert!(!needs::analyse(find("/blinn_phong.json"), &s).shadows);
    assert!(needs::analyse(find("/shadow.json"), &s).shadows);
    let kaleidoscope = needs::analyse(find("/kaleidoscope.json"), &s);
    assert_eq!(
        kaleidoscope.reflection_depth,
        needs::ReflectionDepth::UpToMaxDepth(s.max_depth)
    );
    assert!(kaleidoscope.conductors && !kaleidoscope.refraction);
    // The course's light is outside the closed tube around the camera: it
    // cannot light anything, and no shadow ray is needed to find that out.
    assert!(!kaleidoscope.lights[0].used && !kaleidoscope.shadows);
    let lit = needs::analyse(find("/kaleidoscope_lit.json"), &s);
    assert!(
        lit.lights[0].used && lit.shadows,
        "a point light inside the tube"
    );
}

/// The depth `needs` allows is a bound the renders respect, and a tight one
/// where mirrors face each other.
#[test]
fn measured_bounce_depth_stays_within_the_reachable_depth() {
    for (name, scene) in course_scenes() {
        for integrator in [
            IntegratorKind::Whitted,
            IntegratorKind::Path,
            IntegratorKind::Course,
        ] {
            let s = Settings {
                integrator,
                max_depth: 4,
                ..scene.settings
            };
            let job = match RenderJob::with_settings(scene.clone(), s) {
                Ok(job) => job,
                // The course's shader has no glass: such scenes are refused.
                Err(e) => {
                    assert!(
                        integrator == IntegratorKind::Course
                            && matches!(e.kind(), scene::ErrorKind::CourseHasNoRefraction),
                        "{name} {integrator}: {e}"
                    );
                    continue;
                }
            };
            let deepest = job.render(None, &|_| {}).unwrap().rays.deepest;
            let bound = match job.needs().reflection_depth {
                needs::ReflectionDepth::None => 0,
                needs::ReflectionDepth::One => 1,
                needs::ReflectionDepth::UpToMaxDepth(d) => d,
            };
            let diffuse_bounces = integrator == IntegratorKind::Path && job.needs().rough_surfaces;
            if !diffuse_bounces {
                assert!(deepest <= bound, "{name} {integrator}: {deepest} > {bound}");
            }
            if name.ends_with("/kaleidoscope_lit.json") && integrator == IntegratorKind::Whitted {
                assert_eq!(
                    deepest, 4,
                    "mirrors facing each other use every bounce allowed"
                );
            }
        }
    }
}
