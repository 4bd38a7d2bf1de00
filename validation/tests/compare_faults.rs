//! The image-against-reference core (`validation::compare`) on the
//! tracer's own renders with planted faults: each test must flag the fault,
//! where it was planted and nowhere else, and pass the unbroken image.

use std::path::Path;

use tracer::job::{Overrides, RenderJob};
use tracer::output::to_srgb8;
use tracer::scene::IntegratorKind;
use validation::compare::regions::{silhouettes, summarise, Summary};
use validation::compare::{tolerance, welch, Estimate, Tolerance, Verdicts};
use validation::renders::{sample_statistics, tracer_render, ALPHA};

/// A course scene at 32 × 24 pixels.
fn job(name: &str) -> RenderJob {
    let path = format!(
        "{}/../crates/tracer/scenes/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let overrides = Overrides {
        width: Some(32),
        height: Some(24),
        ..Overrides::default()
    };
    RenderJob::load(Path::new(&path), &overrides).unwrap()
}

/// The object seen at each pixel, the background last.
fn labels(job: &RenderJob) -> (Vec<usize>, usize) {
    let background = job.scene().objects.len();
    let labels = job
        .first_hits()
        .into_iter()
        .map(|h| h.map_or(background, |i| i as usize))
        .collect();
    (labels, background + 1)
}

fn flat(job: &RenderJob) -> Vec<f64> {
    let image = job.render(Some(1), &|_| {}).unwrap().image;
    image
        .pixels
        .iter()
        .flat_map(|p| p.to_array())
        .map(f64::from)
        .collect()
}

/// `image` with every channel of `object`'s pixels scaled by `factor`.
fn planted(image: &[f64], labels: &[usize], object: usize, factor: f64) -> Vec<f64> {
    let mut image = image.to_vec();
    for (p, &label) in labels.iter().enumerate() {
        if label == object {
            for v in &mut image[3 * p..3 * p + 3] {
                *v *= factor;
            }
        }
    }
    image
}

/// Asserts that only `object`'s region disagrees, every compared pixel of it.
#[track_caller]
fn caught_in(summary: &Summary, object: usize) {
    assert!(!summary.agrees());
    for r in &summary.regions {
        match r.region == object {
            true => assert_eq!(r.disagreeing, r.pixels, "{r:?}"),
            false => assert_eq!(r.disagreeing, 0, "{r:?}"),
        }
    }
}

fn summary(verdicts: &Verdicts, labels: &[usize], count: usize, reference: &[f64]) -> Summary {
    summarise(verdicts, labels, count, 32, reference)
}

#[test]
fn a_one_percent_shift_of_one_object_is_found_in_radiance_there_alone() {
    // 1 % is ten times the renders' relative tolerance (1e-3).
    let job = job("webgl_seven_spheres");
    let (labels, count) = labels(&job);
    let mask = silhouettes(&labels, 32, 24);
    let reference = flat(&job);
    let check = |image: &[f64]| {
        let v = tolerance::radiance(
            image,
            &reference,
            None,
            Tolerance::RENDERS,
            ALPHA,
            Some(&mask),
        );
        summary(&v, &labels, count, &reference)
    };
    assert!(check(&reference).agrees());
    for object in [1, 4] {
        caught_in(&check(&planted(&reference, &labels, object, 1.01)), object);
    }
}

#[test]
fn a_ten_percent_shift_of_one_object_is_found_in_8_bit_codes_there_alone() {
    // 10 % moves every code above 40 by two or more (one code is 1.7 % of
    // the radiance at code 128, 4.4 % at code 40: IEC 61966-2-1's slope),
    // beyond the one code allowed for rounding; the red sphere's channels
    // that are dark stay within it, so the test is of the codes it moves.
    let job = job("webgl_seven_spheres");
    let (labels, count) = labels(&job);
    let mask = silhouettes(&labels, 32, 24);
    let reference = flat(&job);
    let codes = |image: &[f64]| {
        image
            .iter()
            .map(|&v| to_srgb8(v as f32))
            .collect::<Vec<u8>>()
    };
    let check = |image: &[f64]| {
        let v = tolerance::codes(
            &codes(image),
            &reference,
            None,
            Tolerance::RENDERS,
            ALPHA,
            Some(&mask),
        );
        let in_codes: Vec<f64> = codes(&reference).into_iter().map(f64::from).collect();
        summary(&v, &labels, count, &in_codes)
    };
    assert!(check(&reference).agrees());
    // The ground plane (object 0), lit and mid-grey.
    caught_in(&check(&planted(&reference, &labels, 0, 1.10)), 0);
}

#[test]
fn welchs_test_passes_independent_path_renders_and_finds_one_object_ten_percent_brighter() {
    let job = job("webgl_seven_spheres");
    let mut settings = *job.settings();
    settings.integrator = IntegratorKind::Path;
    let scene = job.scene();
    let run = |settings, seeds| sample_statistics(tracer_render, scene, settings, seeds).unwrap();
    let (mean, variance) = run(settings, 1000..1064);
    let reference = Estimate {
        mean: &mean,
        variance: &variance,
        samples: 64,
    };
    let (labels, _) = labels(&job);
    let mask = silhouettes(&labels, 32, 24);
    let judge = |mean: &[f64], variance: &[f64]| {
        let image = Estimate {
            mean,
            variance,
            samples: 64,
        };
        welch::welch(
            &image,
            &reference,
            32,
            Tolerance::RENDERS,
            ALPHA,
            Some(&mask),
        )
        .0
    };
    let (m, v) = run(settings, 0..64);
    assert_eq!(judge(&m, &v).disagreeing_count(), 0);
    // The ground plane (object 0) 10 % brighter: found there, not elsewhere.
    let verdicts = judge(&planted(&m, &labels, 0, 1.10), &v);
    let (_, count) = self::labels(&job);
    let found = summary(&verdicts, &labels, count, &mean);
    assert!(
        found.regions[0].disagreeing > found.regions[0].pixels / 2,
        "{found:?}"
    );
    assert_eq!(found.disagreeing, found.regions[0].disagreeing, "{found:?}");
}
