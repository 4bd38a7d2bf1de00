//! Environment mapping against ray tracing: how wrong the slides' two
//! assumptions are (`001`: the reflected objects are far away, and a
//! surface never reflects itself) when they do not hold.
//!
//! The map is made as the slides make it (step 1): the surroundings are
//! rendered from the mirror's centre, with the mirror removed, by the
//! tracer, into a cube map ([`tracer::capture::capture_cube`]), from
//! geometry at a finite distance. The mirror is then rendered twice by the
//! same Whitted tracer: (a) alone under that map, so that each reflected
//! ray looks its direction up (steps 2–5), and (b) among the surroundings
//! themselves, each reflected ray traced. The errors of (a) against (b)
//! are the tradeoff sweep's fixed measures ([`crate::tradeoff::measure`]:
//! relative RMSE of radiance, ΔE2000 of the displayed image, ꟻLIP) over
//! the pixels where the camera sees a mirror.
//!
//! Two surroundings, each at distance `d` from the mirror's centre (in
//! mirror radii) and scaled with `d`, so that the map captured from the
//! centre is the same at every distance and only the traced mirror
//! changes ([`Surroundings`]):
//!
//! - **objects**: nine emitting (`flat`) spheres of distinct colours, each
//!   of radius `0.3 d`, none within 70° of the camera's side of the axis
//!   (so none hides the mirror from the camera at `d ≥ 2`). Their edges
//!   are sharp: the map's error lives in bands along them.
//! - **sky**: one `normal_colour` sphere of radius `d` around the mirror,
//!   seen from inside: the direction-colour sky `(u + 1)/2` brought to a
//!   finite distance, smooth everywhere. The camera must be inside it
//!   (`d > 4`).

use std::f64::consts::PI;
use std::sync::Arc;

use glam::Vec3;
use serde::Serialize;
use serde_json::{json, Value};
use tracer::capture::capture_cube;
use tracer::environment::Environment;
use tracer::geometry::Ray;
use tracer::integrator::{Machinery, Tracer};
use tracer::job::RenderJob;
use tracer::render::Image;
use tracer::scene::{self, Scene};

use crate::tradeoff::measure::{errors, Errors, Mask, Truth};

/// The sizes of one comparison: the image's height (pixels; the two
/// spheres' image is twice as wide) and the captured cube map's side.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Resolution {
    /// Image height, pixels.
    pub image: u32,
    /// Cube face side, texels.
    pub cube: u32,
}

/// One comparison: the traced and the environment-mapped render, the
/// mirror pixels, and the errors over them.
#[derive(Clone, Debug)]
pub struct Comparison {
    /// (b), every reflected ray traced.
    pub traced: Image,
    /// (a), every reflected ray looked up in its mirror's captured map.
    pub mapped: Image,
    /// The pixels where the camera sees a mirror.
    pub mask: Mask,
    /// (a) against (b) over the mask.
    pub errors: Errors,
    /// Where mirrors see each other: (a) against (b) over the mirror
    /// pixels whose reflected ray meets another mirror, and over the rest,
    /// with their pixel counts; `None` for a lone mirror.
    pub split: Option<MirrorSplit>,
}

/// The errors of two mirrors, where each shows the other and elsewhere.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct MirrorSplit {
    /// Over the pixels whose reflected ray meets the other mirror.
    pub seeing_a_mirror: Errors,
    /// Their count.
    pub seeing_a_mirror_pixels: usize,
    /// Over the other mirror pixels.
    pub elsewhere: Errors,
    /// Their count.
    pub elsewhere_pixels: usize,
}

/// The mirror: a smooth conductor reflecting about 0.9 in each channel at
/// normal incidence (`n = 0.2`, `κ = 4`), the same in both renders.
fn mirror() -> Value {
    json!({ "type": "conductor", "n": [0.2, 0.2, 0.2], "kappa": [4, 4, 4] })
}

/// What surrounds the mirrors.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Surroundings {
    /// Nine coloured spheres of radius `0.3 d` at distance `d`.
    Objects,
    /// A `normal_colour` sphere of radius `d` around the origin.
    Sky,
}

/// The objects' directions from the mirror's centre, as the polar angle
/// from `+z` and the azimuth from `+x`, degrees, and their colours.
const OBJECTS: [(f64, f64, [f64; 3]); 9] = [
    (0.0, 0.0, [0.9, 0.9, 0.9]),
    (60.0, 0.0, [0.9, 0.1, 0.1]),
    (60.0, 90.0, [0.1, 0.8, 0.1]),
    (60.0, 180.0, [0.1, 0.2, 0.9]),
    (60.0, 270.0, [0.9, 0.8, 0.1]),
    (110.0, 45.0, [0.8, 0.1, 0.8]),
    (110.0, 135.0, [0.1, 0.8, 0.8]),
    (110.0, 225.0, [0.9, 0.5, 0.1]),
    (110.0, 315.0, [0.4, 0.1, 0.7]),
];

/// The surroundings at distance `d` around the origin, as scene objects
/// and their materials (`c0`, `c1`, …; `sky`).
fn surroundings(kind: Surroundings, d: f64) -> (Vec<Value>, serde_json::Map<String, Value>) {
    let mut objects = Vec::new();
    let mut materials = serde_json::Map::new();
    if kind == Surroundings::Sky {
        materials.insert("sky".into(), json!({ "type": "normal_colour" }));
        objects
            .push(json!({ "type": "sphere", "center": [0, 0, 0], "radius": d, "material": "sky" }));
        return (objects, materials);
    }
    for (k, (theta, phi, colour)) in OBJECTS.iter().enumerate() {
        let (t, p) = (theta * PI / 180.0, phi * PI / 180.0);
        let c = [d * t.sin() * p.cos(), d * t.sin() * p.sin(), d * t.cos()];
        let name = format!("c{k}");
        materials.insert(name.clone(), json!({ "type": "flat", "radiance": colour }));
        objects.push(json!({ "type": "sphere", "center": c, "radius": 0.3 * d, "material": name }));
    }
    (objects, materials)
}

/// The scene of `mirrors` (unit spheres at these centres, listed first)
/// among the surroundings at `d`, seen from `(0, 0, −eye)` with a
/// vertical field of view `fov_y_deg`, at `width × height`.
fn scene_of(
    mirrors: &[[f64; 3]],
    (kind, d): (Surroundings, f64),
    view: (f64, f64),
    size: (u32, u32),
) -> Scene {
    let (mut objects, mut materials) = surroundings(kind, d);
    materials.insert("mirror".into(), mirror());
    let spheres = mirrors
        .iter()
        .map(|c| json!({ "type": "sphere", "center": c, "radius": 1, "material": "mirror" }));
    objects.splice(0..0, spheres);
    let file = json!({
        "version": 1,
        "image": { "width": size.0, "height": size.1 },
        "camera": { "type": "look_at", "eye": [0, 0, -view.0], "target": [0, 0, 0], "up": [0, 1, 0],
                    "fov_y_deg": view.1, "near": 0.01, "far": 1000 },
        "materials": materials,
        "objects": objects,
        "render": { "integrator": "whitted", "max_depth": 11 }
    });
    scene::parse(&file.to_string()).expect("the comparison's scene is valid")
}

fn render(scene: Scene) -> (Image, Vec<Option<u32>>) {
    let settings = scene.settings;
    let job = RenderJob::with_settings(scene, settings).expect("renderable");
    let hits = job.first_hits();
    (job.render(None, &|_| {}).expect("rendered").image, hits)
}

/// Compares the traced `scene` whose first `mirrors` objects are mirrors
/// with each mirror rendered under its own map captured from its centre.
fn compare(scene: &Scene, centres: &[[f64; 3]], cube: u32) -> Comparison {
    let (traced, hits) = render(scene.clone());
    let mut mapped = traced.clone();
    for (k, centre) in centres.iter().enumerate() {
        let centre = Vec3::from_array(centre.map(|c| c as f32));
        // Step 1: the surroundings from the mirror's centre, itself removed.
        let mut around = scene.clone();
        around.objects.remove(k);
        let map = capture_cube(&around, scene.settings, centre, cube);
        // Steps 2–5: the mirror alone, its reflected rays looking the map up.
        let mut alone = scene.clone();
        alone.objects = vec![scene.objects[k].clone()];
        alone.environment = Some(Arc::new(Environment::Cube { map, scale: 1.0 }));
        let (image, _) = render(alone);
        for (i, hit) in hits.iter().enumerate() {
            if *hit == Some(k as u32) {
                mapped.pixels[i] = image.pixels[i];
            }
        }
    }
    let mirrors = centres.len() as u32;
    let on_mirror: Vec<Option<u32>> = hits.iter().map(|h| h.filter(|&i| i < mirrors)).collect();
    let mask = Mask::from_hits(&on_mirror);
    let measure = |mask: &Mask| {
        errors(
            std::slice::from_ref(&mapped),
            &Truth::new(traced.clone(), 0.0, mask),
            mask,
        )
    };
    let errors = measure(&mask);
    let split = (centres.len() > 1).then(|| {
        let sees = sees_a_mirror(scene, mirrors, &on_mirror);
        let (one, other): (Vec<_>, Vec<_>) = on_mirror
            .iter()
            .zip(&sees)
            .map(|(hit, &sees)| (hit.filter(|_| sees), hit.filter(|_| !sees)))
            .unzip();
        let (seeing, elsewhere) = (Mask::from_hits(&one), Mask::from_hits(&other));
        MirrorSplit {
            seeing_a_mirror: measure(&seeing),
            seeing_a_mirror_pixels: seeing.count(),
            elsewhere: measure(&elsewhere),
            elsewhere_pixels: elsewhere.count(),
        }
    });
    Comparison {
        traced,
        mapped,
        mask,
        errors,
        split,
    }
}

/// Whether each pixel's primary ray, reflected at the mirror it meets
/// (`on_mirror`), meets one of the first `mirrors` objects next.
fn sees_a_mirror(scene: &Scene, mirrors: u32, on_mirror: &[Option<u32>]) -> Vec<bool> {
    let tracer = Tracer::new(
        scene,
        scene.settings,
        Machinery::everything(scene, &scene.settings),
    );
    let width = scene.width as usize;
    on_mirror
        .iter()
        .enumerate()
        .map(|(i, hit)| {
            hit.is_some() && {
                let ray = scene.camera.ray((i % width) as u32, (i / width) as u32);
                tracer.intersect(&ray).is_some_and(|h| {
                    let r = radiometry::specular::reflect(-ray.direction, h.normal);
                    // A classification, not a render: any offset off the surface will do.
                    let next = Ray::new(h.point + h.normal * 1e-3, r);
                    tracer.intersect(&next).is_some_and(|n| n.object < mirrors)
                })
            }
        })
        .collect()
}

/// One mirror sphere of radius 1 at the origin among the surroundings at
/// distance `d` (mirror radii), seen from 4 radii away so that it fills
/// most of a square image.
pub fn one_sphere(kind: Surroundings, d: f64, resolution: Resolution) -> Comparison {
    let size = (resolution.image, resolution.image);
    let scene = scene_of(&[[0.0; 3]], (kind, d), (4.0, 32.0), size);
    compare(&scene, &[[0.0; 3]], resolution.cube)
}

/// The centres of the two mirrors side by side: 0.1 radius apart.
pub const TWO_SPHERES: [[f64; 3]; 2] = [[-1.05, 0.0, 0.0], [1.05, 0.0, 0.0]];

/// Two mirror spheres side by side, 0.1 radius apart, among the
/// surroundings at distance `d`, in an image twice as wide as high; each
/// mirror looked up in its own map, which holds the other mirror as it
/// was traced without the first: the map cannot show a mirror in
/// another that shows the first.
pub fn two_spheres(kind: Surroundings, d: f64, resolution: Resolution) -> Comparison {
    let size = (2 * resolution.image, resolution.image);
    let scene = scene_of(&TWO_SPHERES, (kind, d), (7.0, 20.0), size);
    compare(&scene, &TWO_SPHERES, resolution.cube)
}

/// One row of the distance sweep.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Row {
    /// Distance of the surroundings from the mirror's centre, mirror radii.
    pub distance: f64,
    /// The measures over the mirror's pixels.
    pub errors: Errors,
}

/// The least-squares slope of `ln y` against `ln x`: the exponent `p` of
/// the power law `y ∝ x^p` that fits best in relative terms.
pub fn log_log_slope(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let logs: Vec<(f64, f64)> = points.iter().map(|&(x, y)| (x.ln(), y.ln())).collect();
    let mx = logs.iter().map(|p| p.0).sum::<f64>() / n;
    let my = logs.iter().map(|p| p.1).sum::<f64>() / n;
    let sxy: f64 = logs.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = logs.iter().map(|p| (p.0 - mx).powi(2)).sum();
    sxy / sxx
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fitted_exponent_of_a_power_law_is_its_power() {
        let points: Vec<(f64, f64)> = [1.0, 2.0, 5.0, 30.0].map(|x| (x, 3.0 / x)).to_vec();
        assert!((log_log_slope(&points) + 1.0).abs() < 1e-12);
    }
}
