//! Rays per second on the course scenes, one thread, 160 × 120, each
//! integrator the scene is meant for. Criterion's throughput is the number
//! of rays a render casts (counted by the tracer), so it reports rays/s.
//!
//! `cargo bench -p tracer --bench rays`

use std::path::Path;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use tracer::job::RenderJob;
use tracer::scene::{self, IntegratorKind, Settings};

const SCENES: [&str; 9] = [
    "first_red_sphere",
    "normals",
    "diffuse",
    "blinn_phong",
    "shadow",
    "gold_spheres",
    "kaleidoscope",
    "kaleidoscope_lit",
    "webgl_seven_spheres",
];

fn rays_per_second(c: &mut Criterion) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../validation/scenes");
    let mut group = c.benchmark_group("rays");
    group.sample_size(10);
    for name in SCENES {
        let scene = scene::load(&dir.join(format!("{name}.json")))
            .expect("course scene")
            .resized(160, 120);
        let mut runs = vec![(IntegratorKind::Whitted, 1), (IntegratorKind::Course, 1)];
        if name == "kaleidoscope_lit" || name == "webgl_seven_spheres" {
            runs = vec![(IntegratorKind::Whitted, 1), (IntegratorKind::Path, 4)];
        }
        for (integrator, spp) in runs {
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
criterion_main!(benches);
