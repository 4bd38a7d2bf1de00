//! The measured image differences of `docs/errata.md`: each course scene
//! rendered the course shader's way and physically, and single errata
//! switched on alone in an otherwise physical render.
//!
//! `cargo run --release -p tracer --example errata`
//!
//! Differences are of linear radiance, per pixel the largest channel
//! difference, then the mean and the largest over the image; and the share
//! of pixels whose 8-bit sRGB value changes by more than 2 levels in any
//! channel (visible side by side). Renders are 320 × 240.
//!
//! The table is the section `errata-images` of `docs/results.md`: the
//! program (and `cargo test`, which builds it as a test) fails when the
//! committed copy differs, and rewrites it under `RESULTS_WRITE=1`.

use std::path::Path;

use tracer::job::RenderJob;
use tracer::output;
use tracer::render::Image;
use tracer::scene::{self, FresnelModel, IntegratorKind, RayOffset, Scene, Settings};

fn draw(scene: &Scene, settings: &Settings) -> Image {
    RenderJob::with_settings(scene.clone(), *settings)
        .expect("renderable")
        .render(None, &|_| {})
        .expect("thread pool")
        .image
}

fn visible_share(a: &Image, b: &Image) -> f64 {
    let (a8, b8) = (output::srgb8(a), output::srgb8(b));
    let changed = a8
        .chunks(3)
        .zip(b8.chunks(3))
        .filter(|(p, q)| p.iter().zip(*q).any(|(x, y)| x.abs_diff(*y) > 2))
        .count();
    changed as f64 / (a8.len() / 3) as f64
}

fn row(what: &str, scene_name: &str, a: &Image, b: &Image) -> String {
    let (mean, max) = a.difference(b);
    format!(
        "| {what} | {scene_name} | {mean:.4} | {max:.4} | {:.1} % |\n",
        100.0 * visible_share(a, b)
    )
}

results::deterministic_example!(
    "errata-images",
    "cargo run --release -p tracer --example errata",
    table
);

fn table() -> String {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let load = |name: &str| {
        scene::load(&dir.join(format!("{name}.json")))
            .expect("course scene")
            .resized(320, 240)
    };
    let mut table = String::from(
        "| erratum | scene | mean diff | max diff | pixels visibly changed |\n|---|---|---|---|---|\n",
    );
    // The lit course scenes within the course's shader (an unlit one has
    // nothing the shader shades).
    for name in scene::course_scenes() {
        let scene = load(name);
        if !scene.within_course_shader() || scene.lights.is_empty() {
            continue;
        }
        let physical = Settings {
            integrator: IntegratorKind::Whitted,
            ..scene.settings
        };
        let course = Settings {
            integrator: IntegratorKind::Course,
            ..physical
        };
        table += &row(
            "whole course shader vs whitted",
            name,
            &draw(&scene, &course),
            &draw(&scene, &physical),
        );
    }
    for name in ["gold_spheres", "kaleidoscope_lit", "webgl_seven_spheres"] {
        let scene = load(name);
        let exact = scene.settings;
        let reversed = Settings {
            fresnel: FresnelModel::Course,
            ..exact
        };
        let schlick = Settings {
            fresnel: FresnelModel::SchlickRarer,
            ..exact
        };
        let fixed = Settings {
            ray_offset: RayOffset::Fixed(0.001),
            ..exact
        };
        let reference = draw(&scene, &exact);
        table += &row(
            "Fresnel cos⁵θ alone",
            name,
            &draw(&scene, &reversed),
            &reference,
        );
        table += &row(
            "schlick-rarer for exact (not an erratum)",
            name,
            &draw(&scene, &schlick),
            &reference,
        );
        table += &row(
            "fixed EPSILON 0.001 alone",
            name,
            &draw(&scene, &fixed),
            &reference,
        );
    }
    table
}
