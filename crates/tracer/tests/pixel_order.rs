//! A render's pixels against the plain loop they stand for: each sample's
//! numbers drawn from its own [`Sampler`] sample, its camera ray made by
//! [`Camera::ray_at`], traced, and summed in sample order in `f64`. The
//! render makes its camera rays in blocks and its samples' numbers with
//! work shared across a pixel; none of it may change a bit.

mod common;

use glam::{DVec3, Vec3};
use tracer::filter::sample_point;
use tracer::integrator::RayCounts;
use tracer::sampler::Sampler;
use tracer::scene::{IntegratorKind, PixelFilter, Scene, Settings};

/// Pixel `(x, y)` as the plain loop computes it.
fn plain_pixel(scene: &Scene, settings: &Settings, x: u32, y: u32) -> Vec3 {
    let tracer = common::tracer(scene, *settings);
    let samples = Sampler::for_pixel(settings.seed, (y * scene.width + x) as u64);
    let mut sum = DVec3::ZERO;
    for k in 0..settings.spp {
        let mut sample = samples.sample(k);
        let within = sample_point(settings.pixel_filter, &mut sample);
        let ray = scene.camera.ray_at(x, y, within);
        let radiance = tracer.radiance(&ray, &mut sample, &mut RayCounts::default());
        sum += radiance.as_dvec3();
    }
    (sum / settings.spp as f64).as_vec3()
}

/// Every pixel of the path tracer's render (box filter) has the plain
/// loop's bits (tolerance: none, `f32` compared exactly), under the
/// course's pinhole (`shadow`, `gold_spheres`) and a look-at camera
/// (`glass_spheres`), at sample counts below, at and off a multiple of
/// any block size a render might use (1, 7, 8, 13, 32).
#[test]
fn pixels_have_the_bits_of_one_sample_traced_after_another() {
    let mut compared = 0;
    for name in ["shadow", "gold_spheres", "glass_spheres"] {
        let scene = common::course_scene(name, 12, 9);
        for spp in [1, 7, 8, 13, 32] {
            let settings = Settings {
                integrator: IntegratorKind::Path,
                pixel_filter: PixelFilter::Box,
                spp,
                max_depth: 6,
                seed: 17,
                ..Settings::default()
            };
            let image = common::render_with(&scene, &settings, Some(2));
            for y in 0..scene.height {
                for x in 0..scene.width {
                    let plain = plain_pixel(&scene, &settings, x, y);
                    assert_eq!(
                        image.get(x, y).to_array().map(f32::to_bits),
                        plain.to_array().map(f32::to_bits),
                        "{name} at {spp} spp, pixel ({x}, {y})"
                    );
                    compared += 1;
                }
            }
        }
    }
    assert_eq!(compared, 3 * 5 * 12 * 9);
}
