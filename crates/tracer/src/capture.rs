//! The slides' capture of a cube map by tracing (`001`, "Környezet
//! leképezés", step 1): what a scene sends towards a point from every
//! direction, rendered into an [`Environment::Cube`](crate::environment::Environment)'s
//! faces by the scene's own integrator.

use glam::{DVec3, Vec3};
use rayon::prelude::*;
use techniques::envmap::cube::{CubeTexel, Face};

use crate::environment::{CubeMap, Texels};
use crate::geometry::Ray;
use crate::integrator::{Machinery, RayCounts, Tracer};
use crate::sampler::Sampler;
use crate::scene::{Scene, Settings};

/// The slides' step 1 for a cube map: the radiance `scene` sends towards
/// `centre` from every direction, traced from `centre` by `settings`'
/// integrator, one ray through each texel's centre of six `side × side`
/// faces. The caller removes the object the map is for: the slides'
/// object never sees itself. Texels are traced in parallel, each with its
/// own sample (`seed`, face and texel), so the map does not depend
/// on the thread count.
pub fn capture_cube(scene: &Scene, settings: Settings, centre: Vec3, side: u32) -> CubeMap {
    let tracer = Tracer::new(scene, settings, Machinery::everything(scene, &settings));
    let n = side as usize;
    let faces = Face::ALL
        .iter()
        .enumerate()
        .map(|(f, &face)| {
            let texels = (0..n * n)
                .into_par_iter()
                .map(|k| {
                    let (i, j) = ((k % n) as f64, (k / n) as f64);
                    let (u, v) = ((i + 0.5) / n as f64, (j + 0.5) / n as f64);
                    // Texel centres lie inside the unit square.
                    let texel = CubeTexel::from_uv(face, u, v).expect("a texel centre");
                    let direction: DVec3 = texel.direction().get();
                    let ray = Ray::new(centre, direction.as_vec3());
                    let mut sample =
                        Sampler::for_pixel(settings.seed, (f * n * n + k) as u64).sample(0);
                    tracer.radiance(&ray, &mut sample, &mut RayCounts::default())
                })
                .collect();
            Texels::new(side, side, texels).expect("side × side texels")
        })
        .collect();
    CubeMap::of_side(side, faces)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::Environment;

    /// A cube map captured under the direction-colour sky looks up, in
    /// every direction, what the sky sends there: each face is where
    /// `techniques::envmap::cube` looks (a face flipped or swapped would
    /// be wrong by up to 1). Within 0.016: inside a face the bilinear
    /// filter errs by about (π/2 / 32)² / 8, 3e-4; within half a texel of
    /// a face's edge it clamps, holding the edge texel's value over half a
    /// texel (at most 1/32 rad) of a sky whose slope is at most 1/2 per
    /// radian. 5.8e-3 measured.
    #[test]
    fn a_captured_cube_map_looks_up_what_it_captured() {
        let scene = crate::scene::parse(
            r#"{ "version": 1, "image": { "width": 1, "height": 1 },
                 "camera": { "type": "course_pinhole" }, "materials": {}, "objects": [],
                 "environment": { "type": "direction_colour" } }"#,
        )
        .unwrap();
        let sky = scene.environment.as_deref().unwrap().clone();
        let map = Environment::Cube {
            map: capture_cube(&scene, scene.settings, Vec3::new(3.0, -2.0, 1.0), 32),
            scale: 1.0,
        };
        let mut worst = 0.0_f32;
        for k in 0..2000 {
            // A spiral over the sphere of directions.
            let z = 1.0 - 2.0 * (k as f32 + 0.5) / 2000.0;
            let phi = k as f32 * 2.399_963;
            let r = (1.0 - z * z).sqrt();
            let d = Vec3::new(r * phi.cos(), r * phi.sin(), z);
            worst = worst.max((map.radiance(d) - sky.radiance(d)).abs().max_element());
        }
        assert!(worst < 0.016, "{worst}");
    }
}
