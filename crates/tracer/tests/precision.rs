//! The precision tier (`tracer::tier`): what `f32` costs far from the
//! origin, where `f64` keeps the image, and the tier as a setting, settled
//! once and refused by name where the integrator does not compute in it.

mod common;

use common::{gold, parse};
use serde_json::{json, Value};
use tracer::job::{Overrides, RenderJob};
use tracer::render::Image;
use tracer::scene::{ErrorKind, IntegratorKind, Precision, RenderSpec, Settings};

/// A small lit scene, 5 cm spheres a few centimetres apart, whose every
/// coordinate is `offset` plus a multiple of 2⁻⁶ m: exact in `f32` up to
/// 2¹⁷ m, so that the scene at `offset` is exactly the scene at the origin
/// moved, in both tiers' numbers. A Lambert sphere and a gold one beside it
/// on a Lambert floor under a directional light: shading normals, a shadow,
/// a mirror's reflection and the offsets of secondary rays all show.
fn small_scene_at(offset: f64, precision: &str) -> Value {
    let at = |x: f64, y: f64, z: f64| json!([offset + x, offset + y, offset + z]);
    json!({
        "version": 1,
        "image": { "width": 48, "height": 32 },
        "camera": { "type": "look_at", "eye": at(0.078125, 0.09375, -0.5),
                    "target": at(0.078125, 0.0, 0.0), "up": [0, 1, 0],
                    "fov_y_deg": 30, "near": 0.0625, "far": 16 },
        "background": [0.1, 0.1, 0.2],
        "materials": {
            "white": { "type": "lambert", "albedo": [0.8, 0.8, 0.8] },
            "grey": { "type": "lambert", "albedo": [0.5, 0.5, 0.5] },
            "gold": gold()
        },
        "objects": [
            { "type": "sphere", "center": at(0.0, 0.0, 0.0), "radius": 0.0625, "material": "white" },
            { "type": "sphere", "center": at(0.15625, 0.0, 0.0), "radius": 0.0625, "material": "gold" },
            { "type": "plane", "point": at(0.0, -0.0625, 0.0), "normal": [0, 1, 0], "material": "grey" }
        ],
        "lights": [ { "type": "directional", "towards": [0.5, 1, -0.25], "irradiance": [3, 3, 3] } ],
        "render": { "integrator": "whitted", "precision": precision }
    })
}

fn render(scene: Value) -> Image {
    RenderJob::new(parse(scene), &Overrides::default())
        .unwrap()
        .render(Some(2), &|_| {})
        .unwrap()
        .image
}

/// Translation invariance: a scene moved 10⁵ m from the origin renders the
/// image it renders at the origin. At `f64` the moved image agrees with the
/// one at the origin to 10⁻⁶ in every pixel-channel (measured: 3·10⁻⁸, one
/// `f32` ulp of the film; `f64`'s own error at 10⁵ m is about 10⁻¹¹ m
/// against 6 cm spheres), as the `f32` image at the origin does to 10⁻⁵
/// (measured: 1.3·10⁻⁶). At `f32` one ulp at 10⁵ m is 7.8 mm, an eighth of
/// a sphere's radius, and the hit's error bound, by which secondary rays
/// leave, is 3.6 cm: normals, shadows and reflections go wrong, the mean
/// pixel-channel differs by more than 10⁻² and the worst by more than 0.3
/// (measured: 0.024 and 0.58).
#[test]
fn a_scene_moved_far_from_the_origin_keeps_its_image_in_f64_and_loses_it_in_f32() {
    let home = render(small_scene_at(0.0, "f64"));
    let (mean, max) = render(small_scene_at(1e5, "f64")).difference(&home);
    assert!(max < 1e-6, "f64 moved 1e5 m: mean {mean:e}, max {max:e}");

    // The f32 image at the origin is the f64 one there, to f32's own error.
    let home_f32 = render(small_scene_at(0.0, "f32"));
    let (mean0, max0) = home_f32.difference(&home);
    assert!(
        max0 < 1e-5,
        "f32 at the origin: mean {mean0:e}, max {max0:e}"
    );

    let (mean, max) = render(small_scene_at(1e5, "f32")).difference(&home);
    assert!(
        mean > 1e-2 && max > 0.3,
        "f32 moved 1e5 m: mean {mean:e}, max {max:e}"
    );
}

/// The tier is settled once: `f64` under `local` and `whitted`, refused
/// under the others by the field that asked for it (the scene's
/// `render.precision`, the overrides' `precision`, or an overriding
/// `integrator` that the scene's tier does not serve); an unknown tier is
/// refused by its field.
#[test]
fn the_f64_tier_is_settled_for_local_and_whitted_and_refused_by_name_elsewhere() {
    let scene = |precision: &str, integrator: &str| {
        let mut s = small_scene_at(0.0, precision);
        s["render"]["integrator"] = json!(integrator);
        s.to_string()
    };
    for integrator in ["local", "whitted"] {
        let settled = tracer::scene::parse(&scene("f64", integrator)).unwrap();
        assert_eq!(settled.settings.precision, Precision::F64, "{integrator}");
    }
    for integrator in ["path", "photon", "course"] {
        let e = tracer::scene::parse(&scene("f64", integrator)).unwrap_err();
        assert_eq!(e.field(), "render.precision", "{integrator}");
        assert!(matches!(e.kind(), ErrorKind::PrecisionNotServed { .. }));
    }
    let e = tracer::scene::parse(&scene("f16", "whitted")).unwrap_err();
    assert_eq!(e.field(), "render.precision");

    let at_f64 = tracer::scene::parse(&scene("f64", "whitted")).unwrap();
    let overrides = |integrator, precision| Overrides {
        render: RenderSpec {
            integrator,
            precision,
            ..RenderSpec::default()
        },
        ..Overrides::default()
    };
    let path = Some(IntegratorKind::Path);
    let e = RenderJob::new(at_f64.clone(), &overrides(path, None)).unwrap_err();
    assert_eq!(e.field(), "overrides.integrator");
    let e = RenderJob::new(at_f64.clone(), &overrides(path, Some(Precision::F64))).unwrap_err();
    assert_eq!(e.field(), "overrides.precision");
    let job = RenderJob::new(at_f64.clone(), &overrides(path, Some(Precision::F32))).unwrap();
    assert_eq!(job.settings().precision, Precision::F32);

    // Settings varied after settling are checked again by the job.
    let varied = Settings {
        integrator: IntegratorKind::Path,
        ..at_f64.settings
    };
    let e = RenderJob::with_settings(at_f64, varied).unwrap_err();
    assert!(matches!(e.kind(), ErrorKind::PrecisionNotServed { .. }));
}
