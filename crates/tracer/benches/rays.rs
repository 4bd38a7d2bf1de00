//! Rays per second on the course scenes, one thread, 160 × 120, each
//! integrator the scene is meant for. Criterion's throughput is the number
//! of rays a render casts (counted by the tracer), so it reports rays/s.
//!
//! `cargo bench -p tracer --bench rays`

use std::path::Path;

use criterion::{criterion_group, Criterion, Throughput};
use tracer::job::RenderJob;
use tracer::scene::{self, IntegratorKind, Scene, Settings};

/// The course scene `name`, at 160 × 120.
fn load(name: &str) -> Scene {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    scene::load(&dir.join(format!("{name}.json")))
        .expect("course scene")
        .resized(160, 120)
}

/// The integrators a scene is benched with, and their samples per pixel:
/// the course shader where the scene is within it, else `path`.
fn runs(scene: &Scene) -> [(IntegratorKind, u32); 2] {
    if scene.within_course_shader() {
        [(IntegratorKind::Whitted, 1), (IntegratorKind::Course, 1)]
    } else {
        [(IntegratorKind::Whitted, 1), (IntegratorKind::Path, 4)]
    }
}

fn rays_per_second(c: &mut Criterion) {
    let mut group = c.benchmark_group("rays");
    group.sample_size(10);
    for name in scene::course_scenes() {
        let scene = load(name);
        for (integrator, spp) in runs(&scene) {
            let settings = Settings {
                integrator,
                spp,
                ..scene.settings
            };
            let job = RenderJob::with_settings(scene.clone(), settings).expect("renderable");
            let rays = job
                .render(Some(1), &|_| {})
                .expect("thread pool")
                .rays
                .total();
            group.throughput(Throughput::Elements(rays));
            group.bench_function(format!("{name}/{integrator}"), |b| {
                b.iter(|| job.render(Some(1), &|_| {}).expect("thread pool"))
            });
        }
    }
    group.finish();
}

criterion_group!(benches, rays_per_second);

fn main() {
    results::criterion::main(benches, record);
}

/// The section `tracer-rays` of `docs/results.md`: millions of rays per
/// second per scene and integrator.
fn record(run: &results::criterion::Run) -> Result<results::Section, results::Error> {
    let mut table = String::from("| scene | whitted | other |\n|---|---|---|\n");
    for name in scene::course_scenes() {
        let runs = runs(&load(name));
        let [(_, _), (other, _)] = runs;
        let ids = runs.map(|(integrator, _)| format!("rays/{name}/{integrator}"));
        let rates: Vec<f64> = run
            .estimates(&ids)?
            .iter()
            .map(|e| e.per_second().unwrap_or(f64::NAN) / 1e6)
            .collect();
        table += &format!("| `{name}` | {:.1} | {other} {:.1} |\n", rates[0], rates[1]);
    }
    Ok(results::Section::measured(
        "tracer-rays",
        "cargo bench -p tracer --bench rays",
        &format!("Millions of rays per second, one thread, 160 × 120.\n\n{table}"),
    ))
}
