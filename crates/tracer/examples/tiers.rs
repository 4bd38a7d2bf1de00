//! What the `f64` tier changes in the course scenes' images: each scene
//! rendered by its own settings (`whitted`) at 160 × 120 in `f32` and in
//! `f64` (`render.precision`), and the images compared pixel by pixel, by
//! the largest channel's absolute difference in W/(sr·m²): the mean over
//! the pixels, the largest, and how many pixels differ by more than 10⁻³
//! (about a quarter of an 8-bit step at radiance 1). At the course's scale,
//! metres from the origin, this is all `f32` gives up; far from the origin
//! it is more (`tests/precision.rs`).
//!
//! `cargo run --release -p tracer --example tiers`
//!
//! The table is the section `precision-tiers` of `docs/results.md`: the
//! program (and `cargo test`, which builds it as a test) fails when the
//! committed copy differs, and rewrites it under `RESULTS_WRITE=1`.

use std::path::Path;

use tracer::job::{Overrides, RenderJob};
use tracer::render::Image;
use tracer::scene::{self, Precision, RenderSpec};

results::deterministic_example!(
    "precision-tiers",
    "cargo run --release -p tracer --example tiers",
    table
);

/// The course scene `name` rendered at `precision`, 160 × 120.
fn render(name: &str, precision: Precision) -> Image {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(format!("{name}.json"));
    let overrides = Overrides {
        render: RenderSpec {
            precision: Some(precision),
            ..RenderSpec::default()
        },
        width: Some(160),
        height: Some(120),
        ..Overrides::default()
    };
    let scene = scene::load(&path).expect("a course scene");
    let job = RenderJob::new(scene, &overrides).expect("the course scenes render at either tier");
    job.render(None, &|_| {}).expect("renders").image
}

fn table() -> String {
    let mut table = String::from(
        "| scene | integrator | mean \\|f64 − f32\\| | largest | pixels > 10⁻³ |\n\
         |---|---|---|---|---|\n",
    );
    for name in scene::course_scenes() {
        let (single, double) = (render(name, Precision::F32), render(name, Precision::F64));
        let (mean, max) = double.difference(&single);
        let over = double
            .pixels
            .iter()
            .zip(&single.pixels)
            .filter(|(a, b)| (**a - **b).abs().max_element() > 1e-3)
            .count();
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/{name}.json"));
        let integrator = scene::load(&path).unwrap().settings.integrator;
        table += &format!(
            "| `{name}` | {integrator} | {mean:.2e} | {max:.2e} | {over} of {} |\n",
            single.pixels.len()
        );
    }
    table
}
