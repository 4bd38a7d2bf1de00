//! The cost of a render, known before it starts: the estimate of the rays
//! cast bounds the rays a render casts, a render past `needs::MAX_RAYS` is
//! refused unless the caller allows it, and progress is reported from the
//! start.

mod common;

use std::sync::Mutex;

use serde_json::json;
use tracer::job::{Overrides, RenderJob};
use tracer::needs::{MAX_RAYS, WARN_RAYS};
use tracer::scene::{ErrorKind, IntegratorKind, RenderSpec, Scene, Settings};

/// A glass sphere in front of the camera and a lit floor: every branch of
/// the tracers (mirror, glass, shadow, diffuse bounce).
fn glass_scene(cutoff: f64, depth: u32) -> Scene {
    common::pinhole_scene(
        8,
        6,
        json!({
            "materials": {
                "glass": { "type": "dielectric", "eta": 1.5 },
                "floor": { "type": "lambert", "albedo": [0.5, 0.5, 0.5] },
                "gold": common::gold()
            },
            "objects": [
                { "type": "sphere", "center": [0, 0, 1], "radius": 1.2, "material": "glass" },
                { "type": "sphere", "center": [1.5, 0.5, 3], "radius": 0.5, "material": "gold" },
                { "type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0], "material": "floor" }
            ],
            "lights": [ { "type": "point", "position": [0, 3, 0], "intensity": [5, 5, 5] } ],
            "render": { "integrator": "whitted", "throughput_cutoff": cutoff, "max_depth": depth }
        }),
    )
}

/// The case: Whitted through glass with no cutoff doubles its rays
/// per bounce; at depth 230 it is refused before any ray is cast, and
/// allowed when asked.
#[test]
fn an_exponential_render_is_refused_before_it_starts_unless_allowed() {
    let scene = glass_scene(0.0, 230);
    let error = RenderJob::new(scene.clone(), &Overrides::default()).unwrap_err();
    assert_eq!(error.field(), ".");
    assert!(
        matches!(error.kind(), ErrorKind::TooExpensive { rays } if *rays > MAX_RAYS),
        "{:?}",
        error.kind()
    );
    let allowed = Overrides {
        allow_expensive: true,
        ..Overrides::default()
    };
    let job = RenderJob::new(scene, &allowed).expect("allowed");
    assert!(job.rays() > MAX_RAYS);
    // A cutoff bounds the branches: the same depth is cheap.
    let job = RenderJob::new(glass_scene(1e-3, 230), &Overrides::default()).unwrap();
    assert!(job.rays() < WARN_RAYS, "{}", job.rays());
}

/// The estimate is an upper bound: for every course scene and the glass
/// scene, under every integrator (the photon pass's rays included), no
/// render casts more rays than it said.
#[test]
fn the_estimate_bounds_the_rays_cast() {
    let mut scenes: Vec<Scene> = tracer::scene::course_scenes()
        .iter()
        .map(|name| common::course_scene(name, 16, 12))
        .collect();
    scenes.extend([
        glass_scene(0.0, 8),
        glass_scene(1e-3, 11),
        glass_scene(0.1, 40),
    ]);
    let mut cases = 0;
    for scene in &scenes {
        for integrator in [
            IntegratorKind::Local,
            IntegratorKind::Whitted,
            IntegratorKind::Path,
            IntegratorKind::Photon,
            IntegratorKind::Course,
        ] {
            let render = RenderSpec {
                integrator: Some(integrator),
                spp: Some(4.0),
                photons: Some(2000.0),
                photon_passes: Some(3.0),
                ..RenderSpec::default()
            };
            let overrides = Overrides {
                render,
                ..Overrides::default()
            };
            let Ok(job) = RenderJob::new(scene.clone(), &overrides) else {
                continue; // glass under the course's shader
            };
            let cast = job.render(Some(1), &|_| {}).unwrap().rays.total() as f64;
            assert!(
                cast <= job.rays(),
                "{integrator}: cast {cast} > estimated {}",
                job.rays()
            );
            cases += 1;
        }
    }
    assert!(cases >= 45, "{cases}");
}

/// The progress callback hears 0 before any row is traced, so a front end
/// shows its bar at once, however long the first row takes.
#[test]
fn progress_is_reported_from_the_start() {
    let scene = common::course_scene("shadow", 4, 3);
    let job = common::job(&scene, &Settings::default());
    let calls = Mutex::new(Vec::new());
    job.render(Some(1), &|rows| calls.lock().unwrap().push(rows))
        .unwrap();
    let calls = calls.into_inner().unwrap();
    assert_eq!(calls.first(), Some(&0), "{calls:?}");
    let mut rest = calls[1..].to_vec();
    rest.sort();
    assert_eq!(rest, vec![1, 2, 3]);
}

/// A refusal names the values at fault and what would be accepted, never a
/// command line's flag: the front end that took the value adds its flag.
#[test]
fn the_refusals_name_no_flag() {
    for kind in [
        ErrorKind::TooExpensive { rays: 1e13 },
        ErrorKind::CourseHasNoRefraction,
    ] {
        let text = tracer::scene::SceneError::new(".", kind).to_string();
        assert!(!text.contains("--"), "{text}");
    }
}
