//! The primitives and cameras: hit distances, normals, inside and outside,
//! grazing rays, rays starting on the surface, and the stable sphere
//! intersection against the course's textbook quadratic.

use glam::{DVec3, Vec3};
use tracer::camera::{Camera, LookAtView, COURSE_EYE};
use tracer::geometry::{Hit, Plane, Ray, Sphere, Tube};
use tracer::scene::RayOffset;
use tracer::spawn;

/// Results of a handful of f32 operations on values of order 1: a few ulps.
const F32_TOL: f32 = 1e-6;

fn sphere(center: Vec3, radius: f32) -> Sphere {
    Sphere {
        center,
        radius,
        material: 0,
    }
}

fn hit_sphere(s: &Sphere, ray: &Ray) -> Option<Hit> {
    s.intersect(ray, 0.0, s.roots(ray))
}

#[test]
fn sphere_hit_from_outside_has_distance_and_outward_normal() {
    let s = sphere(Vec3::ZERO, 1.0);
    let hit = hit_sphere(&s, &Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z)).unwrap();
    assert!((hit.t - 4.0).abs() < F32_TOL);
    assert!((hit.point - Vec3::new(0.0, 0.0, -1.0)).length() < F32_TOL);
    assert!((hit.normal - Vec3::new(0.0, 0.0, -1.0)).length() < F32_TOL);
    assert!(hit.normal.dot(Vec3::Z) < 0.0, "arrived from outside");
}

#[test]
fn sphere_hit_from_inside_keeps_the_outward_normal() {
    let s = sphere(Vec3::ZERO, 2.0);
    let hit = hit_sphere(&s, &Ray::new(Vec3::ZERO, Vec3::X)).unwrap();
    assert!((hit.t - 2.0).abs() < F32_TOL);
    assert!((hit.normal - Vec3::X).length() < F32_TOL);
    assert!(hit.normal.dot(Vec3::X) > 0.0, "arrived from inside");
}

#[test]
fn sphere_behind_the_ray_is_missed() {
    let s = sphere(Vec3::new(0.0, 0.0, -5.0), 1.0);
    assert!(hit_sphere(&s, &Ray::new(Vec3::ZERO, Vec3::Z)).is_none());
}

#[test]
fn sphere_grazing_rays_hit_inside_the_silhouette_and_miss_outside() {
    let s = sphere(Vec3::ZERO, 1.0);
    let just_inside = Ray::new(Vec3::new(0.0, 0.999, -5.0), Vec3::Z);
    let hit = hit_sphere(&s, &just_inside).unwrap();
    // The chord's half-length is √(1 − 0.999²) = 0.0447; f32 keeps it to a
    // few ulps of the quantities it is computed from (order 1).
    let expected = 5.0 - (1.0_f64 - 0.999 * 0.999).sqrt();
    assert!((hit.t as f64 - expected).abs() < 1e-5);
    let just_outside = Ray::new(Vec3::new(0.0, 1.0001, -5.0), Vec3::Z);
    assert!(hit_sphere(&s, &just_outside).is_none());
}

#[test]
fn ray_starting_on_the_sphere_finds_only_the_far_side() {
    let s = sphere(Vec3::new(3.0, -2.0, 7.0), 1.5);
    let first = hit_sphere(&s, &Ray::new(Vec3::new(3.0, -2.0, 0.0), Vec3::Z)).unwrap();
    // Leaving outwards (reflection): nothing more to hit.
    let out = Ray::new(
        spawn::origin(&first, first.normal, RayOffset::Robust),
        -Vec3::Z,
    );
    assert!(hit_sphere(&s, &out).is_none());
    // Going in (refraction): the far side, one diameter on.
    let inward = Ray::new(
        spawn::origin(&first, -first.normal, RayOffset::Robust),
        Vec3::Z,
    );
    let far = hit_sphere(&s, &inward).unwrap();
    assert!((far.t - 3.0).abs() < 1e-5, "t = {}", far.t);
}

/// A sphere of radius 0.05 m, 4 km away, hit 0.04 m off its centre: the
/// textbook discriminant `b² − 4ac` subtracts two numbers near 6.4·10⁷
/// whose difference is 0.0036; f32 spacing there is 4, so no digit of it
/// survives. The stable form computes it from the centre's distance to the
/// line and keeps the hit distance to a few ulps of 4000.
#[test]
fn stable_sphere_intersection_holds_where_the_textbook_quadratic_fails_in_f32() {
    let (center, radius, offset) = (DVec3::new(0.0, 0.0, 4000.0), 0.05_f64, 0.04_f64);
    let origin = DVec3::new(0.0, offset, 0.0);
    // Reference in f64: t = 4000 − √(r² − offset²) = 3999.97.
    let t_ref = center.z - (radius * radius - offset * offset).sqrt();
    let s = sphere(center.as_vec3(), radius as f32);
    let ray = Ray::new(origin.as_vec3(), Vec3::Z);

    let (t_stable, _) = s.roots(&ray).expect("the stable form finds the hit");
    let stable_error = (t_stable as f64 - t_ref).abs();
    // One f32 ulp at 4000 is 2.4e-4 m: allow four.
    assert!(stable_error < 1e-3, "stable t error {stable_error} m");

    match s.roots_naive(&ray) {
        None => {} // the discriminant rounded below zero: the sphere vanishes
        Some((t_naive, _)) => {
            let naive_error = (t_naive as f64 - t_ref).abs();
            // The textbook form loses the chord (0.03 m) entirely or worse.
            assert!(
                naive_error > 0.01,
                "the textbook form was expected to fail here, error {naive_error} m"
            );
        }
    }
}

#[test]
fn plane_is_hit_from_both_sides_and_parallel_rays_miss() {
    let plane = Plane {
        point: Vec3::new(0.0, 1.0, 0.0),
        normal: Vec3::Y,
        material: 0,
    };
    let from_above = plane
        .intersect(&Ray::new(Vec3::new(0.0, 3.0, 0.0), -Vec3::Y), 0.0)
        .unwrap();
    assert!((from_above.t - 2.0).abs() < F32_TOL);
    assert_eq!(from_above.shading_normal(-Vec3::Y), Vec3::Y);
    let from_below = plane
        .intersect(&Ray::new(Vec3::new(0.5, -1.0, 0.0), Vec3::Y), 0.0)
        .unwrap();
    assert!((from_below.t - 2.0).abs() < F32_TOL);
    // Correctly initialised from behind: the shading normal faces the ray.
    assert_eq!(from_below.shading_normal(Vec3::Y), -Vec3::Y);
    assert!(plane
        .intersect(&Ray::new(Vec3::new(0.0, 3.0, 0.0), Vec3::X), 0.0)
        .is_none());
    // A ray lying in the plane: parallel, no hit.
    assert!(plane
        .intersect(&Ray::new(Vec3::new(0.0, 1.0, 0.0), Vec3::X), 0.0)
        .is_none());
}

#[test]
fn ray_leaving_a_plane_does_not_find_it_again() {
    let plane = Plane {
        point: Vec3::new(0.0, 0.0, 20.0),
        normal: Vec3::Z,
        material: 0,
    };
    let dir = Vec3::new(0.3, 0.2, 1.0).normalize();
    let hit = plane
        .intersect(&Ray::new(Vec3::new(0.1, 0.2, -2.0), dir), 0.0)
        .unwrap();
    let n = hit.shading_normal(dir);
    let back = Ray::new(
        spawn::origin(&hit, n, RayOffset::Robust),
        tracer_reflect(-dir, n),
    );
    assert!(plane.intersect(&back, 0.0).is_none());
}

fn tracer_reflect(w: Vec3, n: Vec3) -> Vec3 {
    radiometry::specular::reflect(w, n)
}

#[test]
fn tube_is_closed_around_its_axis_and_open_along_it() {
    let tube = Tube::new(Vec3::ZERO, Vec3::Z, 3, 2.5, 0);
    let inradius = 2.5 * (std::f32::consts::PI / 3.0).cos();
    for i in 0..360 {
        let a = (i as f32 + 0.5).to_radians();
        let dir = Vec3::new(a.cos(), a.sin(), 0.1).normalize();
        let hit = tube
            .intersect(&Ray::new(Vec3::new(0.0, 0.0, 1.0), dir), 0.0)
            .unwrap_or_else(|| panic!("a ray at {i}° escaped the closed tube"));
        // On a side: at the inradius from the axis along that side's normal,
        // and the normal points out of the tube.
        let radial = Vec3::new(hit.point.x, hit.point.y, 0.0);
        assert!((radial.dot(hit.normal) - inradius).abs() < 1e-5);
        assert!(hit.normal.dot(dir) > 0.0);
        assert!(radial.length() <= 2.5 + 1e-5);
    }
    assert!(tube
        .intersect(&Ray::new(Vec3::ZERO, Vec3::Z), 0.0)
        .is_none());
}

/// The tube's hit is its side planes' hits ([`Plane::intersect`]) kept
/// where they fall on their strip, the nearest of them, bit for bit: for
/// 3, 4 and 6 sides, about a tilted axis, 20 000 rays each from inside and
/// outside, in every direction (including the corners' slack).
#[test]
fn a_tube_hit_is_the_nearest_on_strip_hit_of_its_side_planes_bit_for_bit() {
    let mut rng = tracer::rng::Pcg32::new(7, 11);
    let mut unit = || rng.next_f32() * 2.0 - 1.0;
    for sides in [3, 4, 6] {
        let axis = Vec3::new(0.1, -0.2, 1.0).normalize();
        let tube = Tube::new(Vec3::new(0.3, -0.1, 0.5), axis, sides, 2.5, 0);
        let strip_hit = |ray: &Ray| {
            let mut best: Option<Hit> = None;
            for ((face, mid), tangent) in tube.faces.iter().zip(&tube.midpoints).zip(&tube.tangents)
            {
                let bounded = Ray {
                    t_max: best.map_or(ray.t_max, |h| h.t),
                    ..*ray
                };
                if let Some(hit) = face.intersect(&bounded, 0.0) {
                    let along = (hit.point - *mid).dot(*tangent).abs();
                    if along <= tube.half_side * (1.0 + 4.0 * f32::EPSILON) + hit.error {
                        best = Some(hit);
                    }
                }
            }
            best
        };
        for _ in 0..20_000 {
            let origin = Vec3::new(unit(), unit(), unit()) * 4.0;
            let direction = Vec3::new(unit(), unit(), unit()).normalize_or_zero();
            if direction == Vec3::ZERO {
                continue;
            }
            let ray = Ray::new(origin, direction);
            assert_eq!(
                tube.intersect(&ray, 0.0),
                strip_hit(&ray),
                "{sides} sides, {ray:?}"
            );
        }
    }
}

#[test]
fn tube_seen_from_outside_is_hit_on_its_outer_face_and_missed_beside_it() {
    let tube = Tube::new(Vec3::ZERO, Vec3::Z, 4, 1.0, 0);
    // A square of circumradius 1 with corners on the axes, (±1, 0) and
    // (0, ±1): at y = 0.25 the side from (−1, 0) to (0, 1) is at x = −0.75.
    let hit = tube
        .intersect(&Ray::new(Vec3::new(-5.0, 0.25, 0.0), Vec3::X), 0.0)
        .unwrap();
    assert!((hit.t - 4.25).abs() < 1e-5, "t = {}", hit.t);
    assert!(
        hit.normal.dot(Vec3::X) < 0.0,
        "the outer face, seen from outside"
    );
    assert!(tube
        .intersect(&Ray::new(Vec3::new(-5.0, 1.5, 0.0), Vec3::X), 0.0)
        .is_none());
}

#[test]
fn course_camera_centre_ray_looks_down_z_from_the_eye() {
    let camera = Camera::course_pinhole(33, 25);
    let ray = camera.ray(16, 12);
    assert_eq!(ray.origin, COURSE_EYE);
    assert!((ray.direction - Vec3::Z).length() < F32_TOL);
}

#[test]
fn course_camera_corner_rays_pass_through_the_aspect_corrected_image_plane() {
    let (w, h) = (40, 20);
    let camera = Camera::course_pinhole(w, h);
    let aspect = w as f64 / h as f64;
    for (x, y, sx, sy) in [(0, 0, -1.0, 1.0), (w - 1, h - 1, 1.0, -1.0)] {
        let ray = camera.ray(x, y);
        let ndc = (sx * (1.0 - 1.0 / w as f64), sy * (1.0 - 1.0 / h as f64));
        let expected = DVec3::new(ndc.0 * aspect, ndc.1, 2.0).normalize();
        assert!((ray.direction.as_dvec3() - expected).length() < 1e-6);
        // It meets z = 0 at (ndc.x · aspect, ndc.y): the course's image plane.
        let t = 2.0 / ray.direction.z;
        let on_plane = ray.at(t);
        assert!((on_plane.x as f64 - ndc.0 * aspect).abs() < 1e-5);
        assert!((on_plane.y as f64 - ndc.1).abs() < 1e-5);
    }
}

fn look_at(w: u32, h: u32) -> Camera {
    Camera::look_at(
        LookAtView {
            eye: DVec3::new(1.0, 2.0, 3.0),
            target: DVec3::new(1.0, 2.0, -7.0),
            up: DVec3::Y,
            fov_y: 60_f64.to_radians(),
            near: 0.5,
            far: 50.0,
        },
        w,
        h,
    )
}

#[test]
fn look_at_centre_ray_starts_on_the_near_plane_towards_the_target() {
    let ray = look_at(31, 21).ray(15, 10);
    assert!((ray.direction - -Vec3::Z).length() < 1e-6);
    // Unprojected from clip z = −1: the near plane, 0.5 m in front of the eye.
    assert!((ray.origin - Vec3::new(1.0, 2.0, 2.5)).length() < 1e-5);
}

#[test]
fn look_at_edge_rays_span_the_field_of_view() {
    let (w, h) = (31, 21);
    let camera = look_at(w, h);
    // Top row, centre column: the pixel centre is at ndc.y = 1 − 1/h, so its
    // angle from the axis is atan(tan(fov/2) (1 − 1/h)).
    let top = camera.ray(15, 0).direction.as_dvec3();
    let expected = ((30_f64.to_radians()).tan() * (1.0 - 1.0 / h as f64)).atan();
    let angle = top.dot(-DVec3::Z).acos();
    assert!((angle - expected).abs() < 1e-6, "{angle} vs {expected}");
    assert!(top.y > 0.0, "row 0 is the top of the image");
    // Right column: the horizontal field is widened by the aspect ratio.
    let right = camera.ray(w - 1, 10).direction.as_dvec3();
    let aspect = w as f64 / h as f64;
    let expected = ((30_f64.to_radians()).tan() * aspect * (1.0 - 1.0 / w as f64)).atan();
    assert!((right.dot(-DVec3::Z).acos() - expected).abs() < 1e-6);
    assert!(right.x > 0.0);
}

/// Spheres from 1 mm to 1 km in radius, centred from the origin out to
/// 10⁶ m: a ray leaving any hit point outwards, by the error-bound offset,
/// never finds its own sphere again, and one leaving inwards always finds
/// the far side. 2 000 random hits per scale. Spheres smaller than a
/// thousandth of their distance from the origin are left out: there f32
/// spaces its values by more than a hundredth of the radius, and no offset
/// can be both safe and inside the sphere.
#[test]
fn error_bound_offset_never_restarts_on_its_own_sphere_at_any_scale() {
    let mut rng = tracer::rng::Pcg32::new(1, 2);
    let mut hits = 0usize;
    for distance in [0.0_f32, 1.0, 1e2, 1e4, 1e6] {
        for radius in [1e-3_f32, 1.0, 1e3] {
            if radius < 1e-3 * distance {
                continue;
            }
            let center = Vec3::new(distance, -0.5 * distance, 0.25 * distance);
            let s = sphere(center, radius);
            for _ in 0..2000 {
                let u = Vec3::new(
                    rng.next_f32() - 0.5,
                    rng.next_f32() - 0.5,
                    rng.next_f32() - 0.5,
                );
                let Some(dir) = u.try_normalize() else {
                    continue;
                };
                // Aim at the sphere from outside, along −dir.
                let origin = center + dir * (3.0 * radius);
                let Some(hit) = hit_sphere(&s, &Ray::new(origin, -dir)) else {
                    continue;
                };
                hits += 1;
                let out = Ray::new(spawn::origin(&hit, hit.normal, RayOffset::Robust), dir);
                assert!(
                    hit_sphere(&s, &out).is_none(),
                    "restarted on the surface: centre {center}, r {radius}"
                );
                let inward = Ray::new(
                    spawn::origin(&hit, -hit.normal, RayOffset::Robust),
                    -hit.normal,
                );
                let far = hit_sphere(&s, &inward)
                    .unwrap_or_else(|| panic!("no far side: centre {center}, r {radius}"));
                // Through the centre: one diameter, to f32 rounding of the
                // coordinates (|centre| + r) times a few.
                let slack = 1e-5 * (center.abs().max_element() + radius);
                assert!(
                    (far.t - 2.0 * radius).abs() <= slack + 1e-5 * radius,
                    "{} vs {}",
                    far.t,
                    2.0 * radius
                );
            }
        }
    }
    // Every ray is aimed at its sphere from outside: nearly all must hit.
    assert!(hits > 10_000, "only {hits} hits");
}
