//! The light the path tracer misses on the course scenes: on the pixels
//! where the camera sees a directly lit rough surface, the `photon`
//! integrator's mean radiance over the `path` integrator's, both at
//! 160 × 120, 256 samples per pixel box filtered, Russian roulette off, seed 0, the
//! photon map at its defaults (16 passes of 100 000 photons from a 5 cm
//! radius), at each scene's `max_depth` and that radius unless the table
//! says otherwise (a light path then has at most `max_depth + 1` surface
//! vertices, both ways: Mitsuba's `max_depth` of `max_depth + 2`, which
//! counts the segments to the camera and the light too).
//!
//! `cargo run --release -p tracer --example missing_light`
//!
//! A pixel is counted where the physical integrators' primary ray meets a
//! rough object ([`RenderJob::first_hits`]) and the `local` integrator,
//! without ambient light, gives it some radiance (a light reaches it
//! unshadowed). The radiance is the sum of the three channels. The
//! kaleidoscope is measured as it is (the course's Blinn-Phong) and with
//! its rough material replaced by Lambert of albedo `kd`, as Mitsuba's
//! light tracer measured it.
//!
//! The table is the section `missing-light` of `docs/results.md`: the
//! program fails when the committed copy differs, and rewrites it under
//! `RESULTS_WRITE=1`. It takes about 100 s in a test build, so `cargo
//! test`, which builds it as a test, computes it only when its inputs
//! changed: the tracer's source and the crates it links, the course
//! scenes, the lock file and the compiler ([`results::key`]).

use std::path::Path;

use serde_json::Value;
use tracer::job::{Overrides, RenderJob};
use tracer::render::Image;
use tracer::scene::{self, IntegratorKind, RenderSpec};

results::deterministic_example!(
    "missing-light",
    "cargo run --release -p tracer --example missing_light",
    table,
    keyed_by["crates/tracer/scenes"]
);

/// The scene file `name`, its course rough materials made Lambert of
/// albedo `kd` where `lambert`.
fn scene_file(name: &str, lambert: bool) -> Value {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/{name}.json"));
    let mut file: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    if lambert {
        for material in file["materials"].as_object_mut().unwrap().values_mut() {
            if material["type"] == "course_rough" {
                let kd = material["diffuse"].clone();
                *material = serde_json::json!({ "type": "lambert", "albedo": kd });
            }
        }
    }
    file
}

/// One row's variation of a scene's settings.
#[derive(Clone, Copy, Default)]
struct Vary {
    /// Course rough made Lambert.
    lambert: bool,
    max_depth: Option<u32>,
    photon_radius: Option<f64>,
}

fn draw(file: &Value, integrator: IntegratorKind, vary: Vary) -> (RenderJob, Image) {
    let scene = scene::parse(&file.to_string()).expect("course scene");
    let overrides = Overrides {
        render: RenderSpec {
            integrator: Some(integrator),
            spp: Some(256.0),
            throughput_cutoff: Some(0.0),
            seed: Some(0),
            max_depth: vary.max_depth.map(f64::from),
            photon_radius: vary.photon_radius,
            ..RenderSpec::default()
        },
        width: Some(160),
        height: Some(120),
        allow_expensive: true,
    };
    let job = RenderJob::new(scene, &overrides).expect("renderable");
    let image = job.render(None, &|_| {}).expect("thread pool").image;
    (job, image)
}

fn row(name: &str, vary: Vary) -> String {
    let file = scene_file(name, vary.lambert);
    let mut unlit = file.clone();
    unlit["ambient"] = serde_json::json!([0, 0, 0]);
    let (job, path) = draw(&file, IntegratorKind::Path, vary);
    let (_, photon) = draw(&file, IntegratorKind::Photon, vary);
    let (_, local) = draw(&unlit, IntegratorKind::Local, vary);
    let materials = &job.scene().materials;
    let objects = &job.scene().objects;
    let lit: Vec<usize> = job
        .first_hits()
        .iter()
        .enumerate()
        .filter(|(i, hit)| {
            hit.is_some_and(|o| materials[objects[o as usize].material() as usize].is_rough())
                && local.pixels[*i].max_element() > 0.0
        })
        .map(|(i, _)| i)
        .collect();
    let mean = |image: &Image| {
        lit.iter()
            .map(|i| image.pixels[*i].element_sum() as f64)
            .sum::<f64>()
            / lit.len().max(1) as f64
    };
    let (p, q) = (mean(&path), mean(&photon));
    let model = if vary.lambert {
        "Lambert"
    } else {
        "as written"
    };
    let (depth, radius) = (job.settings().max_depth, job.settings().photon.radius);
    format!(
        "| {name} | {model} | {depth} | {radius} | {} | {p:.4} | {q:.4} | {:.3} |\n",
        lit.len(),
        q / p
    )
}

fn table() -> String {
    let mut table = String::from(
        "| scene | rough surfaces | max_depth | photon_radius | directly lit rough pixels | path | photon | photon / path |\n\
         |---|---|---|---|---|---|---|---|\n",
    );
    let lambert = Vary {
        lambert: true,
        ..Vary::default()
    };
    let depth = |d| Vary {
        max_depth: Some(d),
        ..lambert
    };
    let radius = |r| Vary {
        photon_radius: Some(r),
        ..lambert
    };
    for (name, vary) in [
        ("kaleidoscope_lit", Vary::default()),
        ("kaleidoscope_lit", lambert),
        ("kaleidoscope_lit", depth(1)),
        ("kaleidoscope_lit", depth(2)),
        ("kaleidoscope_lit", depth(3)),
        ("kaleidoscope_lit", depth(4)),
        ("kaleidoscope_lit", radius(0.025)),
        ("kaleidoscope_lit", radius(0.1)),
        ("glass_spheres", Vary::default()),
        ("gold_spheres", Vary::default()),
        ("webgl_seven_spheres", Vary::default()),
        ("shadow", Vary::default()),
        ("diffuse", Vary::default()),
    ] {
        table.push_str(&row(name, vary));
    }
    table
}
