//! The mirror tube's trap (`tracer::trap`): which rays it holds, which
//! scenes have one, and that ending the held paths changes no pixel.

mod common;

use common::{course_scene, gold, job, pinhole_scene};
use glam::Vec3;
use serde_json::json;
use tracer::geometry::Ray;
use tracer::integrator::Machinery;
use tracer::scene::{IntegratorKind, Settings};
use tracer::trap::Trap;

/// The lit kaleidoscope's trap: the tube around the z axis, the spheres
/// between z = 9.2 and 11.3 m and the far wall at z = 20 m.
fn kaleidoscope_trap() -> Trap {
    Trap::of(&course_scene("kaleidoscope_lit", 32, 24)).expect("a gold tube among bounded objects")
}

#[test]
fn a_ray_moving_away_from_everything_inside_the_tube_is_held() {
    let trap = kaleidoscope_trap();
    let [below, above] = trap.axial_range;
    // The objects' extent, widened by a margin of at most 10⁻³ (1 + 20 m).
    assert!((9.2 - 0.03..9.2).contains(&below), "{below}");
    assert!((20.0..20.0 + 0.03).contains(&above), "{above}");
    let held = |origin: Vec3, direction: Vec3| trap.holds(&Ray::new(origin, direction.normalize()));
    // Back towards the camera, before the spheres: held.
    assert!(held(Vec3::new(0.5, 0.2, 8.0), Vec3::new(0.6, 0.1, -0.8)));
    assert!(held(Vec3::ZERO, Vec3::new(-1.0, 0.3, -1e-2)));
    // Towards the spheres, among them, or along the axis (it escapes
    // without meeting a side): not held.
    assert!(!held(Vec3::new(0.5, 0.2, 8.0), Vec3::new(0.6, 0.1, 0.8)));
    assert!(!held(Vec3::new(0.0, 0.0, 10.0), Vec3::new(0.6, 0.1, -0.8)));
    assert!(!held(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0)));
    // Axial component under the least the rule trusts: not held.
    assert!(!held(Vec3::ZERO, Vec3::new(1.0, 0.0, -1e-4)));
    // Outside the tube (the far wall reaches past it): not held.
    assert!(!held(Vec3::new(5.0, 0.0, 8.0), Vec3::new(0.6, 0.1, -0.8)));
}

#[test]
fn only_a_smooth_unbumped_mirror_tube_among_bounded_objects_traps() {
    let tube = |material: &str| {
        json!({ "type": "mirror_tube", "axis_point": [0, 0, 0], "axis": [0, 0, 1],
                "sides": 3, "radius": 2.5, "material": material })
    };
    let sphere =
        json!({ "type": "sphere", "center": [0, 0, 10], "radius": 0.8, "material": "matte" });
    let scene = |objects: Vec<serde_json::Value>| {
        pinhole_scene(
            8,
            6,
            json!({
                "materials": { "gold": gold(), "matte": { "type": "lambert", "albedo": [0.5, 0.5, 0.5] } },
                "objects": objects,
                "lights": [ { "type": "point", "position": [0, 0, 6], "intensity": [30, 30, 30] } ]
            }),
        )
    };
    let plane = |normal: [f64; 3]| json!({ "type": "plane", "point": [0, 0, 20], "normal": normal, "material": "matte" });
    assert!(Trap::of(&scene(vec![
        tube("gold"),
        sphere.clone(),
        plane([0.0, 0.0, 1.0])
    ]))
    .is_some());
    // A rough tube lights its hits; a tilted wall spans the whole axis; a
    // second tube, or none, is no trap of one tube.
    assert!(Trap::of(&scene(vec![tube("matte"), sphere.clone()])).is_none());
    assert!(Trap::of(&scene(vec![
        tube("gold"),
        sphere.clone(),
        plane([0.0, 0.6, 0.8])
    ]))
    .is_none());
    assert!(Trap::of(&scene(vec![tube("gold"), tube("gold"), sphere.clone()])).is_none());
    assert!(Trap::of(&scene(vec![sphere])).is_none());
}

/// Ending the held paths keeps every bit of the image (their rest adds
/// nothing) and casts fewer rays; the course's lit kaleidoscope, path
/// traced at 64 × 48, 4 samples, two seeds.
#[test]
fn ending_held_paths_leaves_the_kaleidoscope_unchanged_bit_for_bit() {
    let scene = course_scene("kaleidoscope_lit", 64, 48);
    for seed in [0, 1] {
        let settings = Settings {
            integrator: IntegratorKind::Path,
            spp: 4,
            max_depth: 16,
            seed,
            ..scene.settings
        };
        let job = job(&scene, &settings);
        let lean = job.machinery();
        assert!(lean.trap.is_some());
        let untrapped = Machinery {
            trap: None,
            ..lean.clone()
        };
        let a = job.render(None, &|_| {}).unwrap();
        let b = job.render_with(&untrapped, None, &|_| {}).unwrap();
        assert!(
            a.image == b.image,
            "seed {seed}: ending held paths changed the image"
        );
        assert!(
            a.rays.reflection < b.rays.reflection,
            "seed {seed}: {} against {} reflections",
            a.rays.reflection,
            b.rays.reflection
        );
    }
}
