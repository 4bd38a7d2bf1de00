//! A second front end over the comparison of `optics compare`, in a few
//! lines and without the command line: renders `gold_spheres.json` at
//! 32 × 24 pixels through the tracer's `RenderJob`, writes it as a PFM,
//! and holds it against the suite's reference render with
//! `validation::user_render::compare`; then the same image 10 % too
//! bright, which must disagree.
//!
//! `cargo run --example compare_a_render -p validation` (a second or two);
//! `cargo test --example compare_a_render -p validation` checks both
//! verdicts.

use std::path::{Path, PathBuf};

use record::Lang;
use tracer::job::{Overrides, RenderJob};
use tracer::output::write_pfm;
use validation::user_render::{compare, record, Comparison, Names, Request};

/// The course's gold spheres, lit and seen with the Whitted integrator.
fn scene() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../crates/tracer/scenes/gold_spheres.json")
}

/// Renders the scene at 32 × 24 pixels, every radiance times `gain`, into
/// a PFM in `dir`.
fn render(dir: &Path, gain: f32) -> PathBuf {
    let overrides = Overrides {
        width: Some(32),
        height: Some(24),
        ..Overrides::default()
    };
    let job = RenderJob::load(&scene(), &overrides).expect("the scene loads at 32 × 24");
    let mut image = job.render(None, &|_| {}).expect("it renders").image;
    for pixel in &mut image.pixels {
        *pixel *= gain;
    }
    let path = dir.join(format!("gold-{gain}.pfm"));
    write_pfm(&path, &image).expect("the PFM is written");
    path
}

/// Holds the image at `path` against the scene's reference.
fn compare_image(path: &Path) -> Comparison {
    let scene = scene();
    let request = Request {
        image: path,
        scene: &scene,
        variance: None,
        diff: None,
        integrator: None,
        reference_samples: 16,
        names: Names::default(),
    };
    compare(&request, |_job| {}).expect("the image is compared")
}

fn main() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    for gain in [1.0, 1.1] {
        let comparison = compare_image(&render(dir.path(), gain));
        let verdict = match comparison.verdict() {
            Ok(()) => "agrees".to_owned(),
            Err(disagrees) => disagrees.to_string(),
        };
        println!("radiance × {gain}: {verdict}");
        for line in record(&comparison, Lang::En).steps {
            println!("  {line}");
        }
    }
}

#[test]
fn the_tracers_own_render_agrees_and_a_brighter_one_does_not() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let same = compare_image(&render(dir.path(), 1.0));
    assert!(same.verdict().is_ok(), "{:?}", same.verdict());
    // 10 % is a hundred times the tolerance's relative part (1e-3).
    let brighter = compare_image(&render(dir.path(), 1.1));
    assert!(brighter.verdict().is_err());
}
