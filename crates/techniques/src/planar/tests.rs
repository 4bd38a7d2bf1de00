//! The identities of the planar matrices, each a property over random
//! planes and points in a box of ±10 m (unit normals from random vectors).
//! Tolerance: 1e-9 m (or 1e-9 relative for the determinant), far above the
//! rounding of a few 4 × 4 products of numbers of order 10 (about 1e-13)
//! and far below any geometric error a wrong matrix makes.

use glam::{DMat4, DVec3};
use proptest::prelude::*;

use super::*;

const TOLERANCE: f64 = 1e-9;

fn vector() -> impl Strategy<Value = DVec3> {
    (-10.0..10.0f64, -10.0..10.0f64, -10.0..10.0f64).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn plane() -> impl Strategy<Value = Plane> {
    (vector(), vector())
        .prop_filter("a normal with a direction", |(_, n)| n.length() > 1e-3)
        .prop_map(|(p, n)| Plane::through(p, n).unwrap())
}

fn transform_point(m: &DMat4, v: DVec3) -> DVec3 {
    let h = *m * v.extend(1.0);
    h.truncate() / h.w
}

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).abs().max_element() <= TOLERANCE * (1.0 + b.abs().max_element())
}

proptest! {
    #[test]
    fn the_reflection_matrix_is_an_involution(plane in plane()) {
        let m = reflection_matrix(&plane);
        let twice = m * m;
        prop_assert!(twice.abs_diff_eq(DMat4::IDENTITY, TOLERANCE), "{twice:?}");
    }

    #[test]
    fn the_reflection_matrix_has_determinant_minus_one(plane in plane()) {
        let det = reflection_matrix(&plane).determinant();
        prop_assert!((det + 1.0).abs() <= TOLERANCE, "{det}");
    }

    #[test]
    fn the_reflection_matrix_fixes_the_planes_points(plane in plane(), v in vector()) {
        // v moved onto the plane along its normal.
        let on = v - plane.distance(v) * plane.normal();
        let image = transform_point(&reflection_matrix(&plane), on);
        prop_assert!(close(image, on), "{on} went to {image}");
    }

    #[test]
    fn the_reflection_matrix_reflects_points_across_the_plane(plane in plane(), v in vector()) {
        // The mirror image: as far behind the plane as v is in front.
        let mirrored = v - 2.0 * plane.distance(v) * plane.normal();
        let image = transform_point(&reflection_matrix(&plane), v);
        prop_assert!(close(image, mirrored), "{v}: {image} against {mirrored}");
    }

    #[test]
    fn the_reflection_matrix_mirrors_light_directions(plane in plane(), w in vector()) {
        // A direction (w = 0) reflects by the law of reflection, untranslated.
        let n = plane.normal();
        let mirrored = w - 2.0 * n.dot(w) * n;
        let image = (reflection_matrix(&plane) * w.extend(0.0)).truncate();
        prop_assert!(close(image, mirrored), "{w}: {image} against {mirrored}");
    }

    #[test]
    fn a_projected_shadow_lies_on_the_plane_and_on_the_line_from_the_light(
        plane in plane(), light in vector(), v in vector(),
    ) {
        let towards = v - light;
        prop_assume!(plane.normal().dot(towards).abs() > 1e-3 * towards.length());
        let p = match project_shadow(light, &plane, v) {
            Shadow::Cast(p) | Shadow::BeyondPlane(p) | Shadow::BehindLight(p) => p,
            Shadow::Parallel | Shadow::LightOnPlane => return Err(TestCaseError::fail(format!("{:?}", project_shadow(light, &plane, v)))),
        };
        let scale = 1.0 + p.abs().max_element() + light.abs().max_element();
        prop_assert!(plane.distance(p).abs() <= TOLERANCE * scale, "{p} off the plane");
        // p − l parallel to v − l.
        let off_line = (p - light).cross(towards).length() / towards.length();
        prop_assert!(off_line <= TOLERANCE * scale, "{p} {off_line} off the line");
    }

    #[test]
    fn the_y0_shadow_matrix_is_the_general_one_for_n_y_and_d_0(light in vector()) {
        let y0 = Plane::through(DVec3::ZERO, DVec3::Y).unwrap();
        let general = shadow_matrix(light, &y0);
        prop_assert!(general.abs_diff_eq(shadow_matrix_y0(light), 0.0), "{general:?}");
    }

    #[test]
    fn a_cast_shadow_is_where_the_tracers_ray_from_the_light_meets_the_plane(
        plane in plane(), light in vector(), v in vector(),
    ) {
        // The tracer's own plane intersection, in f32: agreement within
        // its rounding, 1e-4 m relative to the scene's size.
        let shadow = project_shadow(light, &plane, v);
        let towards = (v - light).as_vec3().normalize();
        let ray = tracer::geometry::Ray::new(light.as_vec3(), towards);
        let traced = tracer::geometry::Plane {
            point: plane.point().as_vec3(),
            normal: plane.normal().as_vec3(),
            material: 0,
        };
        let hit = traced.intersect(&ray, 0.0);
        match shadow {
            Shadow::Cast(p) | Shadow::BeyondPlane(p) => {
                // Glancing lines meet the plane far away, where f32 cannot
                // follow; and a vertex within 1e-3 m of the plane is left to
                // the exact test above.
                prop_assume!(p.length() < 1e2 && plane.distance(v).abs() > 1e-3);
                let hit = hit.ok_or_else(|| TestCaseError::fail("the traced ray missed"))?;
                let at = hit.point.as_dvec3();
                prop_assert!((at - p).length() <= 1e-4 * (1.0 + p.length()), "{at} against {p}");
                // Cast exactly when v comes before the plane along the ray.
                let v_at = (v - light).length();
                prop_assert_eq!(matches!(shadow, Shadow::Cast(_)), f64::from(hit.t) > v_at);
            }
            Shadow::BehindLight(p) => {
                prop_assume!(p.length() < 1e2 && plane.distance(light).abs() > 1e-3);
                prop_assert!(hit.is_none(), "a ray forward met the plane");
            }
            Shadow::Parallel | Shadow::LightOnPlane => {}
        }
    }
}

#[test]
fn the_slides_caveats_are_outcomes() {
    // Light 4 m above the floor y = 0.
    let floor = Plane::through(DVec3::ZERO, DVec3::Y).unwrap();
    let light = DVec3::new(0.0, 4.0, 0.0);
    // A vertex 2 m up, 1 m aside: its shadow 2 m aside on the floor.
    assert_eq!(
        project_shadow(light, &floor, DVec3::new(1.0, 2.0, 0.0)),
        Shadow::Cast(DVec3::new(2.0, 0.0, 0.0))
    );
    // Below the floor: projected onto it, but no shadow falls there.
    assert!(matches!(
        project_shadow(light, &floor, DVec3::new(1.0, -2.0, 0.0)),
        Shadow::BeyondPlane(_)
    ));
    // Above the light: the anti-shadow on the far side.
    assert!(matches!(
        project_shadow(light, &floor, DVec3::new(1.0, 6.0, 0.0)),
        Shadow::BehindLight(p) if p.x < 0.0
    ));
    // Level with the light: never meets the floor.
    assert_eq!(
        project_shadow(light, &floor, DVec3::new(1.0, 4.0, 0.0)),
        Shadow::Parallel
    );
}

#[test]
fn a_plane_needs_a_normal_with_a_direction() {
    assert_eq!(
        Plane::through(DVec3::ZERO, DVec3::ZERO),
        Err(PlaneError::Normal)
    );
    assert_eq!(
        Plane::through(DVec3::ZERO, DVec3::new(f64::NAN, 1.0, 0.0)),
        Err(PlaneError::Normal)
    );
    assert_eq!(
        Plane::through(DVec3::splat(f64::INFINITY), DVec3::Y),
        Err(PlaneError::Point)
    );
}

#[test]
fn the_half_turn_handles_a_normal_opposite_to_y() {
    // n = −y: the rotation onto +y is a half turn; the matrix still mirrors.
    let plane = Plane::through(DVec3::new(0.0, 1.0, 0.0), -DVec3::Y).unwrap();
    let image = transform_point(&reflection_matrix(&plane), DVec3::new(3.0, 4.0, 5.0));
    assert!(close(image, DVec3::new(3.0, -2.0, 5.0)), "{image}");
}

/// `(b − a) × (c − a) · (eye − a)`: positive where `eye` sees the triangle
/// `a b c` counter-clockwise (OpenGL's default front face).
fn winding(a: DVec3, b: DVec3, c: DVec3, eye: DVec3) -> f64 {
    (b - a).cross(c - a).dot(eye - a)
}

proptest! {
    #[test]
    fn the_reflection_matrix_mirrors_light_positions(
        plane in plane(), light in vector(), v in vector(),
    ) {
        // A point light drawn through M (the slides' `setLightSourcePositions`
        // after `glScalef`) lights the mirrored vertex from the mirrored
        // side: the same distance, the direction the law of reflection
        // gives, so the cosine with the mirrored normal is unchanged.
        let m = reflection_matrix(&plane);
        let (light_image, v_image) = (transform_point(&m, light), transform_point(&m, v));
        let n = plane.normal();
        let to_light = light - v;
        let mirrored = to_light - 2.0 * n.dot(to_light) * n;
        prop_assert!(close(light_image - v_image, mirrored), "{light_image} {v_image} against {mirrored}");
    }

    #[test]
    fn the_reflection_matrix_swaps_the_planes_sides(plane in plane(), v in vector()) {
        // What lies below the floor comes out above it, as far: the reason
        // the mirrored drawing needs a clip plane.
        let image = transform_point(&reflection_matrix(&plane), v);
        let scale = 1.0 + v.abs().max_element() + plane.d().abs();
        prop_assert!(
            (plane.distance(image) + plane.distance(v)).abs() <= TOLERANCE * scale,
            "{v} at {} went to {image} at {}", plane.distance(v), plane.distance(image)
        );
    }

    #[test]
    fn the_reflection_matrix_reverses_the_winding_of_every_triangle(
        plane in plane(), a in vector(), b in vector(), c in vector(), eye in vector(),
    ) {
        // det M = −1: a triangle counter-clockwise from the eye is clockwise
        // in the mirror seen from the mirrored eye; with back faces culled,
        // the mirrored object's front faces are the ones dropped.
        let before = winding(a, b, c, eye);
        prop_assume!(before.abs() > 1e-3);
        let m = reflection_matrix(&plane);
        let [a2, b2, c2, eye2] = [a, b, c, eye].map(|p| transform_point(&m, p));
        let after = winding(a2, b2, c2, eye2);
        prop_assert!((after + before).abs() <= TOLERANCE * 1e3 * (1.0 + before.abs()), "{before} became {after}");
    }
}

/// Erratum (`001`, lines 576–586 and 647): the matrices are typeset row by
/// row for column vectors, `M (x, y, z, 1)`, and `glMultMatrixf` reads its
/// 16 floats column by column (OpenGL 2.1 §2.11.2). A `shadowMat` filled
/// as the slide reads is applied as `Mᵀ`, which puts no vertex on the
/// ground; filled column by column (transposed), it does.
#[test]
fn course_001_gl_mult_matrix_needs_the_shadow_matrix_stored_column_major() {
    let light = DVec3::new(1.0, 4.0, 2.0);
    let vertex = DVec3::new(0.5, 1.0, 0.3);
    let floor = Plane::through(DVec3::ZERO, DVec3::Y).unwrap();
    for m in [shadow_matrix_y0(light), shadow_matrix(light, &floor)] {
        // What `glMultMatrixf` applies, given the 16 floats in each order.
        let typed_row_by_row = DMat4::from_cols_array(&m.transpose().to_cols_array());
        let stored_column_major = DMat4::from_cols_array(&m.to_cols_array());
        let right = transform_point(&stored_column_major, vertex);
        let wrong = transform_point(&typed_row_by_row, vertex);
        // 1e-9 m: the tolerance of the properties above.
        assert!(floor.distance(right).abs() <= TOLERANCE, "{right}");
        assert!(floor.distance(wrong).abs() > 0.1, "{wrong} is on the floor");
    }
}

/// Erratum (`001`, line 343 against lines 363–366): `glScalef(1, −1, 1)`
/// is the reflection matrix of the floor `y = 0`, and it turns every
/// triangle's winding (the property above), so with back faces culled the
/// listing culls the mirrored object's front faces; the slides' own cure,
/// culling front faces (`glFrontFace(GL_CW)` or `glCullFace(GL_FRONT)`)
/// while it draws, is not in the listing.
#[test]
fn course_001_gl_scale_mirror_turns_front_faces_into_back_faces() {
    let floor = Plane::through(DVec3::ZERO, DVec3::Y).unwrap();
    let gl_scale = DMat4::from_scale(DVec3::new(1.0, -1.0, 1.0));
    assert!(reflection_matrix(&floor).abs_diff_eq(gl_scale, TOLERANCE));
    // A triangle of the object, counter-clockwise (front) as the eye sees it.
    let eye = DVec3::new(0.0, 3.0, 5.0);
    let [a, b, c] = [
        DVec3::new(-1.0, 1.0, 0.0),
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::new(0.0, 2.0, 0.0),
    ];
    assert!(winding(a, b, c, eye) > 0.0);
    // Its mirror image seen from the mirrored eye: clockwise, culled as a
    // back face.
    let [a2, b2, c2, eye2] = [a, b, c, eye].map(|p| transform_point(&gl_scale, p));
    assert!(winding(a2, b2, c2, eye2) < 0.0);
}

#[test]
fn a_light_on_the_plane_makes_the_shadow_matrix_send_every_vertex_to_the_light() {
    // The light on the plane x + 2y + 3z = 14 (1 + 4 + 9 = 14): computed
    // with the unit normal, n · l + d is 4.4e-16, not 0, the rounding of
    // d = −n · p and n · l.
    let plane = Plane::through(DVec3::new(1.0, 2.0, 3.0), DVec3::new(1.0, 2.0, 3.0)).unwrap();
    let light = DVec3::new(14.0, 0.0, 0.0);
    assert_ne!(plane.distance(light), 0.0);
    assert!(light_on_plane(light, &plane));
    let m = shadow_matrix(light, &plane);
    for v in [DVec3::new(1.0, 0.0, 0.0), DVec3::new(-2.0, 5.0, 1.0)] {
        assert_eq!(project_shadow(light, &plane, v), Shadow::LightOnPlane);
        // Rank 1: M v is a multiple of (l, 1), the light itself.
        assert!(close(transform_point(&m, v), light), "{v}");
    }
    // A micrometre above the plane the matrix projects again.
    let above = light + 1e-6 * plane.normal();
    assert!(!light_on_plane(above, &plane));
    assert!(matches!(
        project_shadow(above, &plane, DVec3::new(1.0, 0.0, 0.0)),
        Shadow::Cast(_) | Shadow::BeyondPlane(_) | Shadow::BehindLight(_)
    ));
}

#[test]
fn the_reflection_factors_are_the_slides_f_s_and_f_inverse() {
    // The floor y = 1: F moves it down by 1, S mirrors, F⁻¹ moves it back.
    let floor = Plane::through(DVec3::new(0.0, 1.0, 0.0), DVec3::Y).unwrap();
    let r = reflection(&floor);
    let down = DMat4::from_translation(DVec3::new(0.0, -1.0, 0.0));
    assert!(r.to_floor.abs_diff_eq(down, TOLERANCE), "{:?}", r.to_floor);
    assert!((r.from_floor * r.to_floor).abs_diff_eq(DMat4::IDENTITY, TOLERANCE));
    assert!(r
        .matrix
        .abs_diff_eq(r.from_floor * r.mirror * r.to_floor, 0.0));
    assert_eq!(r.mirror.determinant(), -1.0);
}

/// One pixel of a depth-buffered framebuffer, drawn as OpenGL draws: with
/// `GL_DEPTH_TEST` on a fragment is kept only if nearer than what is
/// there (and writes its depth); with it off every fragment is kept and
/// no depth is written (OpenGL 2.1 §4.1.6).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Pixel {
    colour: &'static str,
    depth: f64,
}

impl Pixel {
    fn draw(&mut self, colour: &'static str, depth: f64, depth_test: bool) {
        if !depth_test {
            self.colour = colour;
        } else if depth < self.depth {
            *self = Pixel { colour, depth };
        }
    }
}

/// `001` lines 609–680: the listing draws the ground, the lit jet (line
/// 627), then the shadow with `glDisable(GL_DEPTH_TEST)` (lines 642–654).
/// At a pixel where the jet (5 m away) stands in front of the shadow on
/// the ground (10 m away), the shadow drawn last without the depth test
/// covers the jet; in the order of lines 601–603 (ground, shadow without
/// the depth test, then everything else with it) the jet stays in front.
/// Exact: a comparison of depths.
#[test]
fn course_001_shadow_drawn_last_without_depth_test_covers_the_jet() {
    let cleared = Pixel {
        colour: "clear",
        depth: f64::INFINITY,
    };
    let mut listing = cleared;
    listing.draw("ground", 10.0, true);
    listing.draw("jet", 5.0, true);
    listing.draw("shadow", 10.0, false);
    assert_eq!(listing.colour, "shadow", "the listing's order");
    let mut slides = cleared;
    slides.draw("ground", 10.0, true);
    slides.draw("shadow", 10.0, false);
    slides.draw("jet", 5.0, true);
    assert_eq!(slides.colour, "jet", "the order of lines 601–603");
}
