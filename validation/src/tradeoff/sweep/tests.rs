use super::*;
use tracer::job::Overrides;

/// A course scene at 8 × 6, for the tests of what a sweep or a budget
/// plans for it.
pub(crate) fn job(name: &str) -> RenderJob {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../crates/tracer/scenes")
        .join(format!("{name}.json"));
    let overrides = Overrides {
        width: Some(8),
        height: Some(6),
        ..Overrides::default()
    };
    RenderJob::load(&path, &overrides).unwrap()
}

fn axes(plan: &Plan) -> Vec<Axis> {
    let mut axes: Vec<Axis> = plan.points.iter().map(|p| p.axis).collect();
    axes.dedup();
    axes
}

#[test]
fn a_scene_without_mirrors_or_glass_sweeps_no_fresnel_law_and_no_depth() {
    let plan = plan(&job("shadow"), 16);
    assert!(!axes(&plan).contains(&Axis::Fresnel));
    assert!(!axes(&plan).contains(&Axis::MaxDepth));
    assert!(plan.skipped.iter().any(|s| s.axis == "fresnel"));
    assert!(
        axes(&plan).contains(&Axis::RayOffset),
        "shadow rays leave surfaces"
    );
}

#[test]
fn the_kaleidoscope_sweeps_depth_fresnel_and_its_ladder() {
    let plan = plan(&job("kaleidoscope_lit"), 16);
    let axes = axes(&plan);
    for axis in [
        Axis::Scene,
        Axis::Integrator,
        Axis::MaxDepth,
        Axis::Fresnel,
        Axis::PixelFilter,
    ] {
        assert!(axes.contains(&axis), "{axis:?} missing from {axes:?}");
    }
    // Deterministic scene integrator: no spp axis, path on the ladder at 16.
    assert!(!axes.contains(&Axis::Spp));
    assert!(plan
        .points
        .iter()
        .any(|p| p.label == "integrator path, 16 spp"));
    assert_eq!(plan.points[0].axis, Axis::Scene);
}

#[test]
fn no_two_points_render_the_same_settings() {
    for scene in [
        "kaleidoscope_lit",
        "glass_spheres",
        "gold_spheres",
        "shadow",
    ] {
        let plan = plan(&job(scene), 16);
        for (i, p) in plan.points.iter().enumerate() {
            assert!(
                plan.points[..i].iter().all(|q| q.settings != p.settings),
                "{scene}: {} repeats an earlier point",
                p.label
            );
        }
    }
}

/// A whitted scene sweeps its tier: one row at f64 beside its own f32,
/// and no reason left for not sweeping it; a path scene keeps the
/// reason, and a scene at f64 keeps every rung of the ladder.
#[test]
fn the_tier_is_swept_where_the_integrator_computes_in_f64() {
    let whitted = plan(&job("gold_spheres"), 16);
    let tiers: Vec<&Point> = whitted
        .points
        .iter()
        .filter(|p| p.axis == Axis::Precision)
        .collect();
    assert_eq!(tiers.len(), 1, "{:?}", whitted.points);
    assert_eq!(tiers[0].settings.precision, Precision::F64);
    assert_eq!(tiers[0].label, "precision f64");
    assert!(whitted.skipped.iter().all(|s| s.axis != "f32 against f64"));

    let scene = job("inside_water").scene().clone();
    let settings = scene.settings.settle(
        "test",
        &RenderSpec {
            integrator: Some(IntegratorKind::Path),
            ..RenderSpec::default()
        },
    );
    let path = plan(
        &RenderJob::with_settings(scene, settings.unwrap()).unwrap(),
        16,
    );
    assert!(path.points.iter().all(|p| p.axis != Axis::Precision));
    assert!(path.skipped.iter().any(|s| s.axis == "f32 against f64"));

    let at_f64 = RenderJob::with_settings(
        job("gold_spheres").scene().clone(),
        Settings {
            precision: Precision::F64,
            ..*job("gold_spheres").settings()
        },
    )
    .unwrap();
    let ladder = plan(&at_f64, 16);
    for integrator in [IntegratorKind::Path, IntegratorKind::Course] {
        assert!(
            ladder
                .points
                .iter()
                .any(|p| p.settings.integrator == integrator
                    && p.settings.precision == Precision::F32),
            "{integrator} missing from the ladder at f64"
        );
    }
    assert_eq!(
        truth_settings(&at_f64, 64).precision,
        Precision::F32,
        "the truth is the path tracer's, in f32"
    );
}

#[test]
fn glass_has_no_course_integrator_and_its_truth_carries_the_caustics() {
    let job = job("glass_spheres");
    let plan = plan(&job, 16);
    assert!(plan
        .points
        .iter()
        .all(|p| p.settings.integrator != IntegratorKind::Course));
    let truth = truth_settings(&job, 64);
    assert_eq!(truth.integrator, IntegratorKind::Photon);
    assert_eq!(truth.pixel_filter, PixelFilter::Box);
    assert!(truth.max_depth >= 64);
}
