//! What the tracer's tests share: scenes written inline or read from the
//! course's files, renders through a job, and single rays through a tracer
//! with all its machinery switched on.

// Each test file uses the helpers it needs; the rest are unused there.
#![allow(dead_code)]

use glam::Vec3;
use serde_json::{json, Value};
use tracer::geometry::Ray;
use tracer::integrator::{Machinery, RayCounts, Tracer};
use tracer::job::RenderJob;
use tracer::render::Image;
use tracer::sampler::Sampler;
use tracer::scene::{self, IntegratorKind, Scene, Settings};

/// The integrators built from the laws: all but the course's shader.
pub const LAW_INTEGRATORS: [IntegratorKind; 3] = [
    IntegratorKind::Local,
    IntegratorKind::Whitted,
    IntegratorKind::Path,
];

/// The course's gold (`000`), a conductor of index `n + iκ` per channel.
pub const GOLD_N: [f64; 3] = [0.17, 0.35, 1.5];
/// Its extinction coefficients.
pub const GOLD_KAPPA: [f64; 3] = [3.1, 2.7, 1.9];

/// The course's gold as a scene file's material.
pub fn gold() -> Value {
    json!({ "type": "conductor", "n": GOLD_N, "kappa": GOLD_KAPPA })
}

/// A scene written inline; the test's own scenes are valid.
pub fn parse(value: Value) -> Scene {
    scene::parse(&value.to_string()).expect("test scene is valid")
}

/// A scene seen through the course's pinhole camera at `width × height`;
/// `body` holds the rest (materials, objects, lights, background).
pub fn pinhole_scene(width: u32, height: u32, mut body: Value) -> Scene {
    body["version"] = json!(1);
    body["image"] = json!({ "width": width, "height": height });
    body["camera"] = json!({ "type": "course_pinhole" });
    parse(body)
}

/// The course scene `scenes/<name>.json`, resized to `width × height`.
pub fn course_scene(name: &str, width: u32, height: u32) -> Scene {
    let path = format!("{}/scenes/{name}.json", env!("CARGO_MANIFEST_DIR"));
    scene::load(std::path::Path::new(&path))
        .unwrap()
        .resized(width, height)
}

/// The render job of `scene` under `settings`.
pub fn job(scene: &Scene, settings: &Settings) -> RenderJob {
    RenderJob::with_settings(scene.clone(), *settings).expect("renderable")
}

/// The image of `scene` under `settings` on `threads` threads.
pub fn render_with(scene: &Scene, settings: &Settings, threads: Option<usize>) -> Image {
    job(scene, settings).render(threads, &|_| {}).unwrap().image
}

/// A tracer of `scene` running everything, whatever the scene needs.
pub fn tracer(scene: &Scene, settings: Settings) -> Tracer<'_> {
    Tracer::new(scene, settings, Machinery::everything(scene, &settings))
}

/// The radiance along one `ray`, from the first pixel's first sample.
pub fn radiance_along(scene: &Scene, settings: &Settings, ray: &Ray) -> Vec3 {
    let mut sample = Sampler::for_pixel(settings.seed, 0).sample(0);
    tracer(scene, *settings).radiance(ray, &mut sample, &mut RayCounts::default())
}
