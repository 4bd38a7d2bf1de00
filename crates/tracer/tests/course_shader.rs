//! The course's final GLSL shader (`000`), reproduced by the `course`
//! integrator, against the laws: each test demonstrates one erratum of
//! `docs/errata.md`.

mod common;

use common::{course_scene, gold, pinhole_scene, radiance_along, tracer};
use glam::Vec3;
use serde_json::json;
use tracer::geometry::Ray;
use tracer::job::RenderJob;
use tracer::scene::{IntegratorKind, Scene, Settings};

fn radiance(scene: &Scene, integrator: IntegratorKind, ray: &Ray) -> Vec3 {
    let settings = Settings {
        integrator,
        ..scene.settings
    };
    radiance_along(scene, &settings, ray)
}

fn floor_under_point_light(height: f64) -> Scene {
    pinhole_scene(
        4,
        4,
        json!({
            "materials": { "matte": { "type": "course_rough", "ambient": [0, 0, 0], "diffuse": [0.5, 0.5, 0.5],
                                      "specular": [0, 0, 0], "shininess": 1 } },
            "objects": [ { "type": "sphere", "center": [0, -10, 0], "radius": 10, "material": "matte" } ],
            "lights": [ { "type": "point", "position": [0, height, 0], "intensity": [1, 1, 1] } ]
        }),
    )
}

/// `normalize(hit.hitPoint - light.position)` points from the light to the
/// point: the course lights the floor only where the light is *below* it,
/// and with no inverse-square falloff.
#[test]
fn course_point_light_direction_is_reversed_and_does_not_fall_off() {
    let down = Ray::new(Vec3::new(0.0, 5.0, 0.3), -Vec3::Y);
    for height in [1.0, 2.0] {
        let scene = floor_under_point_light(height);
        let course = radiance(&scene, IntegratorKind::Course, &down);
        let law = radiance(&scene, IntegratorKind::Whitted, &down);
        assert_eq!(course, Vec3::ZERO, "the course leaves the lit floor dark");
        // kd cos θ · I / r²: the law, with the inverse square, at the hit
        // point on the 10 m sphere (4.5 mm below y = 0).
        let p = glam::DVec3::new(0.0, -10.0 + (100_f64 - 0.09).sqrt(), 0.3);
        let to_light = glam::DVec3::new(0.0, height, 0.0) - p;
        let r2 = to_light.length_squared();
        let cos = (p - glam::DVec3::new(0.0, -10.0, 0.0))
            .normalize()
            .dot(to_light.normalize());
        // f32 rounding of the hit point and the products: relative 1e-5.
        let expected = 0.5 * cos / r2;
        assert!(
            (law.x as f64 - expected).abs() < 1e-5 * expected,
            "{law} vs {expected}"
        );
    }
}

/// The final shader adds `lightAmbient` at every mirror bounce, unweighted:
/// a gold sphere reflecting an empty black sky shows 0.05 per bounce.
#[test]
fn course_adds_unweighted_ambient_at_every_mirror_bounce() {
    let scene = pinhole_scene(
        4,
        4,
        json!({
            "ambient": [0.05, 0.05, 0.05],
            "materials": { "gold": gold() },
            "objects": [ { "type": "sphere", "center": [0, 0, 4], "radius": 1, "material": "gold" } ]
        }),
    );
    let head_on = Ray::new(Vec3::new(0.0, 0.0, -2.0), Vec3::Z);
    assert_eq!(
        radiance(&scene, IntegratorKind::Course, &head_on),
        Vec3::splat(0.05)
    );
    assert_eq!(
        radiance(&scene, IntegratorKind::Whitted, &head_on),
        Vec3::ZERO
    );
}

/// The kaleidoscope's mirror normals, `cross(p(i+1) − p(i), z)`, point out of
/// the tube, and `intersectPlane` only accepts `dot(normal, dir) > 0.001`:
/// every mirror hit sees the normal facing away, so `Fresnel(F0,
/// dot(−dir, n))` is called with a negative cosine, where GLSL's `pow(x, 5.0)`
/// is undefined (GLSL ES 1.00 §8.2: "Results are undefined if x < 0").
#[test]
fn course_kaleidoscope_feeds_pow_a_negative_cosine_at_every_mirror() {
    let scene = course_scene("kaleidoscope", 32, 24);
    let tracer = tracer(&scene, scene.settings);
    let tube = 3; // objects[3] in the scene file
    let mut mirror_hits = 0;
    for y in 0..scene.height {
        for x in 0..scene.width {
            let ray = scene.camera.ray(x, y);
            if let Some(hit) = tracer.intersect(&ray).filter(|h| h.object == tube) {
                mirror_hits += 1;
                assert!((-ray.direction).dot(hit.normal) < 0.0);
            }
        }
    }
    assert!(mirror_hits > 100, "{mirror_hits}");
}

/// "I removed the shadows, because in this case everything is always in
/// shadow": true, and the law says why. The tube is closed around its axis,
/// so the directional light cannot reach anything inside: with shadows, the
/// physically correct kaleidoscope is lit by the ambient term alone.
#[test]
fn directional_light_cannot_reach_inside_the_closed_kaleidoscope() {
    let mut scene = course_scene("kaleidoscope", 32, 24);
    scene.ambient = Vec3::ZERO;
    let settings = scene.settings;
    // Everything switched on, the light and its shadow rays included: the
    // scene analysis would skip the light for exactly this reason, which is
    // what is under test here, so it must not decide.
    let everything = |scene: &Scene| {
        let job = RenderJob::with_settings(scene.clone(), settings).unwrap();
        job.render_with(&job.everything(), None, &|_| {})
            .unwrap()
            .image
    };
    let image = everything(&scene);
    assert!(image.pixels.iter().all(|p| *p == Vec3::ZERO));
    // And the light is really there: without the tube's walls shadowing,
    // the spheres inside are lit.
    let mut open = scene.clone();
    open.objects
        .retain(|o| !matches!(o, tracer::geometry::Object::Tube(_)));
    let lit = everything(&open);
    assert!(
        lit.pixels.iter().any(|p| p.max_element() > 0.0),
        "the light reaches nothing even without the tube"
    );
}

/// The far wall's normal (0, 0, 1) points away from the camera; the course
/// sees it only from behind, where `dot(n, light)` is negative for a light
/// from the camera's side, and adds no ambient at rough surfaces: the wall
/// is black. Two-sided, it is shaded on the side the camera sees.
#[test]
fn course_far_wall_is_black_where_the_two_sided_plane_is_lit() {
    let scene = pinhole_scene(
        4,
        4,
        json!({
            "materials": { "green": { "type": "course_rough", "ambient": [0.8, 0.6, 0.4], "diffuse": [0.1, 0.8, 0.3],
                                      "specular": [0, 0, 0], "shininess": 1 } },
            "objects": [ { "type": "plane", "point": [0, 0, 20], "normal": [0, 0, 1], "material": "green" } ],
            "lights": [ { "type": "directional", "towards": [1, 0.5, -1], "irradiance": [1, 1, 1] } ]
        }),
    );
    let ahead = Ray::new(Vec3::new(0.0, 0.0, -2.0), Vec3::Z);
    assert_eq!(radiance(&scene, IntegratorKind::Course, &ahead), Vec3::ZERO);
    // kd cos θ with cos θ = 1 / 1.5 (the light's direction normalised).
    let law = radiance(&scene, IntegratorKind::Whitted, &ahead);
    assert!(
        (law - Vec3::new(0.1, 0.8, 0.3) / 1.5).abs().max_element() < 1e-6,
        "{law}"
    );
}
