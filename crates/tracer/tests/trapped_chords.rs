//! Total internal reflection inside a sphere is forever: reflection keeps a
//! chord's distance `b` from the centre, so every hit of the chord meets the
//! surface at the same angle, `sin θ = b / r`. A chord beyond the critical
//! angle (`b / r > 1/η`) never leaves, and no light from outside reaches a
//! camera along it (`inside_water`'s dark ring at the rim of Snell's window).
//!
//! A ray offset along the normal breaks the symmetry: each reflected ray
//! starts a distance `δ` inside the surface, which shortens `b` by about
//! `δ sin θ`, so a chord near the critical angle drifts below it and
//! escapes. Mitsuba 3 offsets by `ε (1 + max |p_i|)`, ε ≈ 8.94e-5, and its
//! `path` integrator lights the ring (`renders.mitsuba.inside_water.path`'s
//! findings); the tracer's robust offset, twice the hit's rounding-error
//! bound, keeps it dark for 1024 bounces.

mod common;

use common::{parse, render_with};
use serde_json::json;
use tracer::scene::{IntegratorKind, RayOffset, Scene, Settings};

/// The sphere's index: critical at `sin θ = 1/1.5 ≈ 0.667`.
const ETA: f64 = 1.5;

/// A unit glass sphere at the origin under a white sky, the camera inside
/// at `(b, 0, 0)` looking along `+z` with a narrow view, so that every
/// pixel's chord passes about `b` from the centre.
fn inside_sphere(b: f64) -> Scene {
    parse(json!({
        "version": 1,
        "image": { "width": 4, "height": 4 },
        "camera": { "type": "look_at", "eye": [b, 0, 0], "target": [b, 0, 1], "up": [0, 1, 0],
                    "fov_y_deg": 0.05, "near": 1e-4, "far": 100 },
        "background": [1, 1, 1],
        "materials": { "glass": { "type": "dielectric", "eta": ETA } },
        "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "glass" } ]
    }))
}

fn whitted(ray_offset: RayOffset) -> Settings {
    Settings {
        integrator: IntegratorKind::Whitted,
        max_depth: 1024,
        throughput_cutoff: 0.0,
        ray_offset,
        ..Settings::default()
    }
}

/// The largest channel of any pixel.
fn brightest(scene: &Scene, settings: &Settings) -> f32 {
    render_with(scene, settings, Some(1))
        .pixels
        .iter()
        .map(|p| p.max_element())
        .fold(0.0, f32::max)
}

#[test]
fn a_chord_beyond_the_critical_angle_stays_trapped_for_a_thousand_bounces() {
    // sin θ = 0.70, 5 % past the critical 0.667: exactly dark.
    let scene = inside_sphere(0.70);
    assert_eq!(brightest(&scene, &whitted(RayOffset::Robust)), 0.0);
}

#[test]
fn a_chord_below_the_critical_angle_sees_the_sky() {
    // sin θ = 0.60: the light comes in (fault check of the scene itself: a
    // camera that sees nothing would pass the test above).
    let scene = inside_sphere(0.60);
    assert!(brightest(&scene, &whitted(RayOffset::Robust)) > 0.5);
}

#[test]
fn mitsubas_offset_lets_the_trapped_chord_escape() {
    // Shortening b by about δ sin θ = 1.8e-4 · 0.7 a bounce, the chord
    // crosses the critical angle after about 260 bounces.
    let scene = inside_sphere(0.70);
    let mitsuba = RayOffset::Scaled(1500.0 / 16_777_216.0);
    assert!(brightest(&scene, &whitted(mitsuba)) > 0.1);
}
