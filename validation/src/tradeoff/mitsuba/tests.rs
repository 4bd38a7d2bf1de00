use std::path::PathBuf;

use glam::{DVec3, Vec3};
use tracer::integrator::{Machinery, RayCounts, Tracer};
use tracer::render::Image;
use tracer::sampler::Sampler;
use tracer::scene::{IntegratorKind, Scene, Settings};

use super::*;

fn reference_file() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("reference/mitsuba_full_light.json")
}

fn full_light() -> FullLight {
    FullLight::load(reference_file().parent().unwrap()).unwrap()
}

fn course_scene(name: &str) -> Scene {
    let file = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../crates/tracer/scenes")
        .join(format!("{name}.json"));
    tracer::scene::load(&file).unwrap()
}

/// `scene` at `width × height` rendered by `whitted` (deterministic) with
/// the box filter's integral taken by the midpoint rule on an `n × n` grid
/// of points in each pixel.
fn box_render(scene: &Scene, width: u32, height: u32, n: u32) -> Image {
    let scene = scene.resized(width, height);
    let settings = Settings {
        integrator: IntegratorKind::Whitted,
        ..scene.settings
    };
    let tracer = Tracer::new(&scene, settings, Machinery::everything(&scene, &settings));
    let mut counts = RayCounts::default();
    let pixels = (0..height)
        .flat_map(|y| (0..width).map(move |x| (x, y)))
        .map(|(x, y)| {
            let grid = (0..n).flat_map(|j| (0..n).map(move |i| (i, j)));
            grid.map(|(i, j)| {
                let within = (
                    (f64::from(i) + 0.5) / f64::from(n),
                    (f64::from(j) + 0.5) / f64::from(n),
                );
                let ray = scene.camera.ray_at(x, y, within);
                let mut sample = Sampler::for_pixel(0, 0).sample(0);
                tracer.radiance(&ray, &mut sample, &mut counts).as_dvec3()
            })
            .sum::<DVec3>()
                / f64::from(n * n)
        })
        .map(|p| p.as_vec3())
        .collect();
    Image {
        width,
        height,
        pixels,
    }
}

/// The 2 × 2 block mean of a box render is the box render at half the
/// size: on `gold_spheres` (gold mirrors, a rough sphere, the background)
/// at 32 × 24 with a 4 × 4 grid per pixel against 16 × 12 with an 8 × 8
/// grid, the same points of the image plane. Within 1e-4 of each pixel's
/// largest channel plus 1e-6 absolute: the points agree to f32 rounding of
/// the rays (the camera computes in f64 and rounds once), and a ray moved
/// by 1 ulp changes a smooth shading by far less; a silhouette crossed by
/// such a ray would fail it, and none is at these points.
#[test]
fn a_block_mean_of_a_box_render_is_the_box_render_at_the_smaller_size() {
    let scene = course_scene("gold_spheres");
    let fine = box_render(&scene, 32, 24, 4);
    let coarse = box_render(&scene, 16, 12, 8);
    let halved = box_downsample(&fine, 2);
    assert_eq!(halved.len(), coarse.pixels.len());
    for (k, (a, b)) in halved.iter().zip(&coarse.pixels).enumerate() {
        let b = b.as_dvec3();
        let tolerance = 1e-4 * b.max_element() + 1e-6;
        assert!(
            (*a - b).abs().max_element() <= tolerance,
            "pixel {k}: block mean {a} against {b}"
        );
    }
}

/// The block mean of a synthetic image with known blocks: 2 × 2 blocks of
/// 1, 2, 3, 4 (mean 2.5) and of 0, 0, 0, 8 (mean 2), exact in binary.
#[test]
fn a_block_mean_is_the_mean_of_its_block() {
    let v = |x: f32| Vec3::splat(x);
    let image = Image {
        width: 4,
        height: 2,
        pixels: vec![
            v(1.0),
            v(2.0),
            v(0.0),
            v(0.0),
            v(3.0),
            v(4.0),
            v(0.0),
            v(8.0),
        ],
    };
    assert_eq!(
        box_downsample(&image, 2),
        vec![DVec3::splat(2.5), DVec3::splat(2.0)]
    );
}

/// Σx / ΣM against passes of channel sums 1, 2, 3, 4: M = 2.5, the
/// passes' sample variance 5/3, so se(M) = √(5/12); an image whose region
/// mean is 5 carries twice the light, ± 2 · √(5/12) / 2.5. Exact to 1e-15.
#[test]
fn the_light_share_and_its_standard_error_from_the_passes() {
    let (light, se) = light_share(5.0, &[1.0, 2.0, 3.0, 4.0]);
    assert!((light - 2.0).abs() < 1e-15, "{light}");
    let expected = 2.0 * (5.0_f64 / 12.0).sqrt() / 2.5;
    assert!((se - expected).abs() < 1e-15, "{se} against {expected}");
}

/// Only the region counts: outside it the image and the reference hold
/// 100 and 0. Inside, x = 1.1 M everywhere gives a relative RMSE of 0.1
/// and a region light of 3 · 1.1 (1e-12: sums of a few terms).
#[test]
fn the_relative_rmse_and_the_light_are_over_the_region_alone() {
    let mask = [true, false, true];
    let reference = vec![DVec3::ONE, DVec3::ZERO, DVec3::splat(2.0)];
    let image = vec![DVec3::splat(1.1), DVec3::splat(100.0), DVec3::splat(2.2)];
    let rmse = relative_rmse(std::slice::from_ref(&image), &reference, &mask);
    assert!((rmse - 0.1).abs() < 1e-12, "{rmse}");
    let light = region_light(&image, &mask);
    assert!((light - 1.5 * 3.0 * 1.1).abs() < 1e-12, "{light}");
}

fn point(label: &str, truth: f64, mitsuba: f64) -> Against {
    Against {
        label: label.to_owned(),
        light: 1.0,
        light_se: 0.0,
        rel_rmse: mitsuba,
        rel_rmse_truth: truth,
    }
}

/// Three settings ordered a < b < c by the sweep's truth; Mitsuba's swaps
/// b and c: two pairs concordant, one discordant. A tie is neither.
#[test]
fn the_ranking_counts_the_pairs_ordered_alike_and_the_other_way() {
    let points = [
        point("a", 0.1, 0.2),
        point("b", 0.2, 0.4),
        point("c", 0.3, 0.3),
    ];
    let ranking = Ranking::of(&points);
    assert_eq!(ranking.concordant, 2);
    assert_eq!(ranking.discordant, vec![["b".to_owned(), "c".to_owned()]]);
    assert!(!ranking.agrees());
    let tied = Ranking::of(&[point("a", 0.1, 0.2), point("b", 0.1, 0.3)]);
    assert_eq!((tied.concordant, tied.discordant.len()), (0, 0));
}

fn why(scene: &Scene, name: &str) -> Result<u32, NoReference> {
    reference_for(scene, name, &full_light(), &reference_file()).map(|r| r.factor)
}

/// Each reason a sweep has no reference, and one that has.
#[test]
fn a_sweep_without_a_reference_says_why() {
    let at = |scene: &Scene, w, h| scene.resized(w, h);
    let shadow = course_scene("shadow").course_rough_as_lambert();
    assert_eq!(why(&at(&shadow, 160, 120), "shadow"), Ok(2));
    assert_eq!(why(&at(&shadow, 80, 60), "shadow"), Ok(1));
    assert!(matches!(
        why(&at(&shadow, 100, 75), "shadow"),
        Err(NoReference::SizeDoesNotMap {
            width: 100,
            height: 75,
            reference: (80, 60)
        })
    ));
    assert!(matches!(
        why(&at(&shadow, 160, 60), "shadow"),
        Err(NoReference::SizeDoesNotMap { .. })
    ));
    let kaleidoscope = course_scene("kaleidoscope");
    assert!(matches!(
        why(&at(&kaleidoscope, 160, 120), "kaleidoscope"),
        Err(NoReference::Excluded { .. })
    ));
    assert!(matches!(
        why(&at(&shadow, 160, 120), "bump_sphere"),
        Err(NoReference::NotMeasured { .. })
    ));
    let course = course_scene("shadow");
    assert_eq!(
        why(&at(&course, 160, 120), "shadow"),
        Err(NoReference::NotLambert)
    );
    let gold = course_scene("gold_spheres").course_rough_as_lambert();
    let differs = why(&at(&gold, 160, 120), "gold_spheres").unwrap_err();
    assert!(
        matches!(
            &differs,
            NoReference::SceneDiffers { part: "background", backgrounds: Some((ours, theirs)) }
                if *ours == [0.25, 0.3, 0.4] && *theirs == [0.0; 3]
        ),
        "{differs}"
    );
    let measured = &full_light().scenes;
    let water = measured.iter().find(|s| s.name == "inside_water").unwrap();
    let water = tracer::scene::parse(&water.scene_text).unwrap();
    assert_eq!(
        why(&at(&water, 160, 120), "inside_water"),
        Err(NoReference::NoRegion)
    );
}

fn measured(points: Vec<Against>) -> MitsubaTruth {
    MitsubaTruth::Measured(AgainstMitsuba {
        scene: "shadow".to_owned(),
        estimate: "ptracer".to_owned(),
        region: "diffuse".to_owned(),
        width: 80,
        height: 60,
        factor: 2,
        pixels: 260,
        passes: 16,
        spp: 64,
        max_depth: 16,
        floor: point("truth", 0.0, 0.01),
        ranking: Ranking::of(&points),
        points,
    })
}

/// `optics validate` holds the field to its numbers: a record as written
/// passes; one whose ranking was edited, whose settings are not the
/// record's, whose share is negative or whose reason is empty fails.
#[test]
fn the_record_is_held_to_its_own_numbers() {
    let points = vec![point("a", 0.1, 0.2), point("b", 0.2, 0.3)];
    let labels = ["a", "b"];
    assert!(hold(None, &labels).is_empty());
    assert!(hold(Some(&measured(points.clone())), &labels).is_empty());
    let mut edited = measured(points.clone());
    if let MitsubaTruth::Measured(m) = &mut edited {
        m.ranking.concordant = 0;
    }
    assert_eq!(hold(Some(&edited), &labels).len(), 1);
    assert_eq!(hold(Some(&measured(points.clone())), &["a", "c"]).len(), 1);
    let mut negative = points;
    negative[1].light = -1.0;
    assert_eq!(hold(Some(&measured(negative)), &labels).len(), 1);
    assert_eq!(
        hold(Some(&MitsubaTruth::NoReference(" ".into())), &labels).len(),
        1
    );
    assert!(hold(Some(&MitsubaTruth::NoReference("why".into())), &labels).is_empty());
}

/// The findings' reading: a truth whose share is 1.0014 ± 0.0014 is
/// within two standard errors of Mitsuba's light, one of 1.0167 ± 0.0017
/// is not; the scene's own settings are the first point; a discordant
/// pair is counted; nothing is said where nothing was measured.
#[test]
fn the_findings_say_whether_the_truths_agree_within_the_noise() {
    let with_floor = |light: f64, se: f64| {
        let mut m = measured(vec![point("own", 0.3, 0.2), point("b", 0.2, 0.3)]);
        if let MitsubaTruth::Measured(m) = &mut m {
            m.floor.light = light;
            m.floor.light_se = se;
            m.points[0].light = 1.34;
        }
        m
    };
    let near = SecondTruth::of(Some(&with_floor(1.0014, 0.0014))).unwrap();
    assert!(near.within_noise);
    assert_eq!((near.own[0], near.pairs, near.discordant), (1.34, 1, 1));
    let far = SecondTruth::of(Some(&with_floor(1.0167, 0.0017))).unwrap();
    assert!(!far.within_noise);
    let below = SecondTruth::of(Some(&with_floor(0.9833, 0.0017))).unwrap();
    assert!(!below.within_noise);
    assert_eq!(
        SecondTruth::of(Some(&MitsubaTruth::NoReference("why".into()))),
        None
    );
    assert_eq!(SecondTruth::of(None), None);
}
