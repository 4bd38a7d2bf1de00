//! Bump maps in the tracer (`techniques::bump`, `tracer::bump`): a flat
//! field renders bit for bit as no field; the bumps change the shading on
//! the bumped object and nowhere else, and leave the silhouette, the
//! shadows and the terminator of the smooth surface (the technique's known
//! limits); a constant slope shows the analytic tilted normal; bad values
//! are refused by field.

mod common;

use common::{parse, render_with};
use glam::Vec3;
use serde_json::{json, Value};
use tracer::job::RenderJob;
use tracer::render::Image;
use tracer::scene::{self, ErrorKind, IntegratorKind, Scene, Settings};

/// A rough sphere (bump `sphere_bump`) over a rough floor (bump
/// `floor_bump`), lit by a point light up and to the left and a grazing
/// directional light from the right, seen from above and in front; a grey
/// ambient light. `Value::Null` leaves the object without a bump field.
fn scene(sphere_bump: Value, floor_bump: Value) -> Scene {
    let mut sphere =
        json!({ "type": "sphere", "center": [0, 1, 0], "radius": 1, "material": "clay" });
    let mut floor =
        json!({ "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor" });
    if !sphere_bump.is_null() {
        sphere["bump"] = sphere_bump;
    }
    if !floor_bump.is_null() {
        floor["bump"] = floor_bump;
    }
    parse(json!({
        "version": 1,
        "image": { "width": 48, "height": 36 },
        "camera": { "type": "look_at", "eye": [0, 2.5, -5], "target": [0, 0.8, 0], "up": [0, 1, 0],
                    "fov_y_deg": 40, "near": 0.1, "far": 100 },
        "background": [0.2, 0.3, 0.4],
        "ambient": [0.05, 0.05, 0.05],
        "materials": {
            "clay": { "type": "course_rough", "ambient": [1, 1, 1], "diffuse": [0.25, 0.2, 0.15],
                      "specular": [0.3, 0.3, 0.3], "shininess": 40 },
            "floor": { "type": "lambert", "albedo": [0.6, 0.6, 0.6] }
        },
        "objects": [sphere, floor],
        "lights": [
            { "type": "point", "position": [-3, 5, -2], "intensity": [20, 20, 20] },
            { "type": "directional", "towards": [1, 0.3, 0], "irradiance": [0.5, 0.5, 0.5] }
        ]
    }))
}

fn sine() -> Value {
    json!({ "type": "sine", "amplitude": 0.01, "period": 0.0625 })
}

fn settings(integrator: IntegratorKind) -> Settings {
    Settings {
        integrator,
        spp: 4,
        ..Settings::default()
    }
}

fn first_hits(scene: &Scene) -> Vec<Option<u32>> {
    RenderJob::with_settings(scene.clone(), settings(IntegratorKind::Whitted))
        .unwrap()
        .first_hits()
}

fn bits(image: &Image) -> Vec<[u32; 3]> {
    image
        .pixels
        .iter()
        .map(|p| p.to_array().map(f32::to_bits))
        .collect()
}

/// `"bump": {"type": "flat"}`, a slope of zero and a sine of amplitude
/// zero change no bit of any law integrator's image: the bent normal of
/// a flat field is the geometric normal itself (`techniques::bump`), and
/// nothing else in the tracer looks at the bump.
#[test]
fn a_flat_bump_field_renders_bit_identical_to_no_bump() {
    let plain = scene(Value::Null, Value::Null);
    let flats = [
        json!({ "type": "flat" }),
        json!({ "type": "slope", "du": 0, "dv": 0 }),
        json!({ "type": "sine", "amplitude": 0, "period": 0.25 }),
    ];
    for integrator in common::LAW_INTEGRATORS {
        let expected = bits(&render_with(&plain, &settings(integrator), Some(2)));
        for flat in &flats {
            let bumped = scene(flat.clone(), flat.clone());
            let image = render_with(&bumped, &settings(integrator), Some(2));
            assert!(bits(&image) == expected, "{integrator}: {flat}");
        }
    }
}

/// Which pixels see which object is the same with and without bumps, to
/// the pixel: the bumps bend the shading normal and never the surface (the
/// slides' "the effect vanishes at the silhouettes").
#[test]
fn the_silhouette_is_unchanged_by_bumps() {
    let plain = first_hits(&scene(Value::Null, Value::Null));
    let bumped = first_hits(&scene(sine(), sine()));
    assert_eq!(plain, bumped);
    let sphere = plain.iter().filter(|h| **h == Some(0)).count();
    assert!(sphere > 200, "the sphere covers {sphere} pixels");
}

/// Bumps on the sphere alone change the shading on the sphere, at most of
/// its pixels, and nowhere else: the floor, its shadow of the sphere and
/// the background are bit for bit the smooth scene's (the bumps cast no
/// shadow of their own, and the sphere's shadow is the smooth sphere's).
#[test]
fn shading_changes_where_the_bump_is_and_shadows_do_not() {
    let plain_scene = scene(Value::Null, Value::Null);
    let hits = first_hits(&plain_scene);
    for integrator in [IntegratorKind::Local, IntegratorKind::Whitted] {
        let plain = render_with(&plain_scene, &settings(integrator), Some(2));
        let bumped = render_with(&scene(sine(), Value::Null), &settings(integrator), Some(2));
        let (mut on_sphere, mut changed) = (0, 0);
        for (i, hit) in hits.iter().enumerate() {
            let same = plain.pixels[i].to_array().map(f32::to_bits)
                == bumped.pixels[i].to_array().map(f32::to_bits);
            if *hit == Some(0) {
                on_sphere += 1;
                changed += usize::from(!same);
            } else {
                assert!(same, "{integrator}: pixel {i} off the sphere changed");
            }
        }
        // The lit side changes almost everywhere; the far side, lit by the
        // ambient term alone, not at all (`beyond_the_terminator_...`).
        assert!(
            changed * 3 > on_sphere,
            "{integrator}: {changed} of {on_sphere}"
        );
    }
}

/// Where the smooth sphere faces away from every light, the bumped one
/// is just as dark: a light below the geometric horizon stays dark even
/// where a bent normal leans towards it (the bumps cannot light their own
/// far side, nor cast a shadow on the near side). Under `local`, the
/// renderer switches shadow rays off for a lone convex object, so only the
/// horizon test keeps those pixels dark. The pixels checked are those
/// the smooth render shows at the ambient term `ka · L_a` alone.
#[test]
fn beyond_the_terminator_bumps_stay_dark() {
    // The sphere alone under the point light from up, left and in front.
    let lone = |bump: Value| {
        let mut s = scene(bump, Value::Null);
        s.objects.truncate(1);
        s.bumps.truncate(1);
        s.lights.truncate(1);
        s
    };
    let bumpy = json!({ "type": "sine", "amplitude": 0.05, "period": 0.0625 });
    let (plain_scene, bumped_scene) = (lone(Value::Null), lone(bumpy));
    let job = RenderJob::with_settings(bumped_scene.clone(), settings(IntegratorKind::Local));
    assert!(!job.unwrap().machinery().shadow_rays, "shadow rays are on");
    let hits = first_hits(&plain_scene);
    let plain = render_with(&plain_scene, &settings(IntegratorKind::Local), Some(1));
    let bumped = render_with(&bumped_scene, &settings(IntegratorKind::Local), Some(1));
    let ambient = Vec3::splat(0.05);
    let mut dark = 0;
    for (i, hit) in hits.iter().enumerate() {
        if *hit == Some(0) && plain.pixels[i] == ambient {
            dark += 1;
            assert_eq!(bumped.pixels[i], ambient, "pixel {i}");
        }
    }
    assert!(dark > 50, "{dark} pixels beyond the terminator");
}

/// A floor tilted by `h = 0.5 u` shows, in the normal colours, the normal
/// of the tilted plane: `normalize(n − 0.5 P_u)` with `P_u` the floor's
/// first tangent (`techniques::bump::on_plane`), at every pixel, to the
/// `f32` rounding of the colour (1e-6).
#[test]
fn a_constant_slope_shows_the_analytic_tilted_normal() {
    let scene = parse(json!({
        "version": 1,
        "image": { "width": 8, "height": 6 },
        "camera": { "type": "look_at", "eye": [0, 3, -3], "target": [0, 0, 0], "up": [0, 1, 0],
                    "fov_y_deg": 30, "near": 0.1, "far": 100 },
        "materials": { "normals": { "type": "normal_colour" } },
        "objects": [ { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "normals",
                       "bump": { "type": "slope", "du": 0.5, "dv": 0 } } ]
    }));
    let p_u = glam::DVec3::Y.any_orthonormal_vector();
    let tilted = (glam::DVec3::Y - p_u * 0.5).normalize().as_vec3();
    let image = render_with(&scene, &settings(IntegratorKind::Whitted), Some(1));
    for p in &image.pixels {
        let shown = (*p - 0.5) * 2.0;
        assert!(
            (shown - tilted).abs().max_element() < 1e-6,
            "{shown} against {tilted}"
        );
    }
}

/// Each bad bump is refused with the field that is wrong, table-driven.
#[test]
fn bad_bumps_are_refused_by_field() {
    let cases: [(Value, &str, &str); 9] = [
        (
            json!({ "type": "sine", "amplitude": 0.1, "period": 0.001 }),
            "objects[0].bump.period",
            "Bump",
        ),
        (
            json!({ "type": "sine", "amplitude": 0.1, "period": -1 }),
            "objects[0].bump.period",
            "Bump",
        ),
        (
            json!({ "type": "sine", "amplitude": 1e300, "period": 1 }),
            "objects[0].bump.amplitude",
            "Bump",
        ),
        (
            json!({ "type": "slope", "du": 2e6, "dv": 0 }),
            "objects[0].bump.du",
            "Bump",
        ),
        (
            json!({ "type": "slope", "du": 0, "dv": -1e7 }),
            "objects[0].bump.dv",
            "Bump",
        ),
        (json!({ "type": "bumpy" }), "objects[0].bump.type", "Schema"),
        (
            json!({ "amplitude": 1 }),
            "objects[0].bump.type",
            "TypeMissing",
        ),
        (
            json!({ "type": 3 }),
            "objects[0].bump.type",
            "TypeNotString",
        ),
        (
            json!({ "type": "sine", "amplitude": 0.1 }),
            "objects[0].bump",
            "Schema",
        ),
    ];
    let file = |bump: &Value, material: &str| {
        json!({
            "version": 1, "image": { "width": 4, "height": 3 },
            "camera": { "type": "course_pinhole" },
            "materials": { "clay": { "type": "lambert", "albedo": [0.5, 0.5, 0.5] },
                           "gold": common::gold() },
            "objects": [ { "type": "sphere", "center": [0, 0, 4], "radius": 1, "material": material,
                           "bump": bump } ]
        })
        .to_string()
    };
    for (bump, field, kind) in cases {
        let error = scene::parse(&file(&bump, "clay")).unwrap_err();
        assert_eq!(error.field(), field, "{bump}: {error}");
        assert!(
            format!("{:?}", error.kind()).starts_with(kind),
            "{bump}: {error:?}"
        );
    }
    // On a mirror the bump is refused: its lobes follow the geometric normal.
    let error = scene::parse(&file(&sine(), "gold")).unwrap_err();
    assert_eq!(error.field(), "objects[0].bump");
    assert!(matches!(error.kind(), ErrorKind::BumpOnSmoothSurface));
    // The tube has no bump maps.
    let tube = r#"{ "version": 1, "image": { "width": 4, "height": 3 },
        "camera": { "type": "course_pinhole" },
        "materials": { "clay": { "type": "lambert", "albedo": [0.5, 0.5, 0.5] } },
        "objects": [ { "type": "mirror_tube", "axis_point": [0, 0, 0], "axis": [0, 0, 1],
                       "sides": 3, "radius": 1, "material": "clay", "bump": { "type": "flat" } } ] }"#;
    let error = scene::parse(tube).unwrap_err();
    assert!(
        matches!(error.kind(), ErrorKind::Schema { .. }),
        "{error:?}"
    );
}

/// The shipped picture's scene reads, and its two spheres differ only in
/// the bump.
#[test]
fn the_bump_sphere_scene_reads() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/bump_sphere.json");
    let scene = scene::load(std::path::Path::new(path)).unwrap();
    assert_eq!(scene.objects.len(), 3);
    assert!(scene.bumps[0].is_none() && scene.bumps[1].is_some());
}

/// The side a ray meets a two-sided plane from is decided by the
/// geometric normal, once, for both normals: a floor tilted by a steep
/// bump (`h = 5 u`, the bent normal 78.7° off the vertical) met from below
/// by a ray that climbs less steeply than the tilt still sees the floor's
/// underside, with the bent normal turned to that side, although the ray
/// runs against the bent normal itself.
#[test]
fn the_side_of_a_bumped_plane_is_the_geometric_normals() {
    let scene = parse(json!({
        "version": 1, "image": { "width": 4, "height": 3 },
        "camera": { "type": "course_pinhole" },
        "materials": { "clay": { "type": "lambert", "albedo": [0.5, 0.5, 0.5] } },
        "objects": [ { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "clay",
                       "bump": { "type": "slope", "du": 5, "dv": 0 } } ]
    }));
    let p_u = glam::DVec3::Y.any_orthonormal_vector().as_vec3();
    let bent = (Vec3::Y - p_u * 5.0).normalize();
    // Up through the floor, against the bent normal.
    let direction = (Vec3::Y * 0.1 + p_u).normalize();
    assert!(direction.dot(Vec3::Y) > 0.0 && direction.dot(bent) < 0.0);
    let ray = tracer::geometry::Ray::new(-direction * 2.0, direction);
    let hit = common::tracer(&scene, settings(IntegratorKind::Whitted))
        .intersect(&ray)
        .expect("the floor");
    assert!((hit.shading - bent).length() < 1e-6, "{}", hit.shading);
    assert_eq!(hit.facing_normal(direction), -Vec3::Y);
    assert_eq!(hit.shading_normal(direction), -hit.shading);
}
