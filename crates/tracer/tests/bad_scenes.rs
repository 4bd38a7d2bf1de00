//! Bad scene files: each is refused with an error that names the JSON path
//! of the bad value and says what was expected; none panics.

mod common;

use serde_json::{json, Value};
use tracer::scene::{self, ErrorKind};

fn good() -> Value {
    json!({
        "version": 1,
        "image": { "width": 32, "height": 24 },
        "camera": { "type": "course_pinhole" },
        "materials": {
            "green": { "type": "lambert", "albedo": [0.1, 0.8, 0.3] },
            "gold": common::gold()
        },
        "objects": [
            { "type": "sphere", "center": [1, 1, 4], "radius": 0.8, "material": "green" },
            { "type": "mirror_tube", "axis_point": [0, 0, 0], "axis": [0, 0, 1], "sides": 3, "radius": 2.5, "material": "gold" }
        ],
        "lights": [ { "type": "directional", "towards": [1, 0.5, -1], "irradiance": [1, 1, 1] } ],
        "render": { "spp": 4 }
    })
}

fn with(pointer: &str, value: Value) -> String {
    let mut scene = good();
    let mut at = &mut scene;
    for key in pointer.trim_start_matches('/').split('/') {
        at = match key.parse::<usize>() {
            Ok(i) if at.is_array() => &mut at[i],
            _ => &mut at[key], // inserts a new field into an object
        };
    }
    *at = value;
    scene.to_string()
}

/// The good scene seen through a look-at camera from the origin towards +z,
/// with its `field` set to `value`.
fn look_at_with(field: &str, value: Value) -> String {
    let mut camera = json!({ "type": "look_at", "eye": [0, 0, 0], "target": [0, 0, 1], "up": [0, 1, 0],
                             "fov_y_deg": 40, "near": 0.1, "far": 10 });
    camera[field] = value;
    with("/camera", camera)
}

fn error(text: &str) -> String {
    match scene::parse(text) {
        Ok(_) => panic!("accepted a bad scene: {text}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn the_good_scene_is_accepted() {
    assert!(scene::parse(&good().to_string()).is_ok());
}

/// One case per line: the bad file, and what the message must contain.
#[test]
fn bad_scenes_are_refused_with_the_path_of_the_bad_value() {
    let nan_text = good()
        .to_string()
        .replace("\"radius\":0.8", "\"radius\":NaN");
    let cases: Vec<(&str, String, &[&str])> = vec![
        (
            "syntax error",
            "{\"version\": 1, \"image\": {".to_string(),
            &["line 1"],
        ),
        (
            "trailing comma",
            good().to_string().replacen('}', ",}", 1),
            &["line 1"],
        ),
        (
            "unknown field",
            with("/camera/zoom", json!(2)),
            &["camera", "unknown field `zoom`"],
        ),
        (
            "unknown top-level field",
            with("/lightz", json!([])),
            &["unknown field `lightz`"],
        ),
        (
            "wrong type",
            with("/objects/0/radius", json!("big")),
            &["objects[0].radius", "invalid type"],
        ),
        (
            "NaN literal",
            nan_text,
            &[
                "objects[0].radius",
                "NaN and Infinity are not numbers",
                "line 1",
            ],
        ),
        (
            "overflowing number",
            good()
                .to_string()
                .replace("\"radius\":0.8", "\"radius\":1e999"),
            &["objects[0].radius"],
        ),
        (
            "centre beyond f32",
            with("/objects/0/center", json!([0, 1e39, 4])),
            &["objects[0].center[1]", "within f32 range"],
        ),
        (
            "negative radius",
            with("/objects/0/radius", json!(-0.8)),
            &["objects[0].radius", "positive", "-0.8"],
        ),
        (
            "zero radius",
            with("/objects/0/radius", json!(0)),
            &["objects[0].radius", "positive"],
        ),
        (
            "zero-length light direction",
            with("/lights/0/towards", json!([0, 0, 0])),
            &["lights[0].towards", "non-zero direction"],
        ),
        (
            "zero-length tube axis",
            with("/objects/1/axis", json!([0, 0, 0])),
            &["objects[1].axis", "non-zero direction"],
        ),
        (
            "zero-sided tube",
            with("/objects/1/sides", json!(0)),
            &["objects[1].sides", "from 3 to 64", "got 0"],
        ),
        (
            "two-sided tube",
            with("/objects/1/sides", json!(2)),
            &["objects[1].sides", "from 3"],
        ),
        (
            "fractional sides",
            with("/objects/1/sides", json!(3.5)),
            &["objects[1].sides", "whole number"],
        ),
        (
            "10^6 × 10^6 image",
            with("/image", json!({ "width": 1_000_000, "height": 1_000_000 })),
            &["image.width", "16384", "1000000"],
        ),
        (
            "too many pixels",
            with("/image", json!({ "width": 16384, "height": 16384 })),
            &["image", "67108864"],
        ),
        (
            "negative size",
            with("/image/height", json!(-24)),
            &["image.height", "-24"],
        ),
        (
            "spp = 0",
            with("/render/spp", json!(0)),
            &["render.spp", "from 1"],
        ),
        (
            "an unknown pixel filter",
            with("/render/pixel_filter", json!("gaussian")),
            &["render.pixel_filter", "gaussian", "box", "center"],
        ),
        (
            "no photons",
            with("/render/photons", json!(0)),
            &["render.photons", "from 1"],
        ),
        (
            "a fixed ray offset of 0",
            with("/render/ray_offset", json!({ "fixed": 0.0 })),
            &["render.ray_offset.fixed", "positive"],
        ),
        (
            "a negative scaled ray offset",
            with("/render/ray_offset", json!({ "scaled": -8.94e-5 })),
            &["render.ray_offset.scaled", "positive"],
        ),
        (
            "a photon radius of 0",
            with("/render/photon_radius", json!(0)),
            &["render.photon_radius", "positive"],
        ),
        (
            "more photons over the passes than the maps hold",
            with(
                "/render",
                json!({ "photons": 1_048_576, "photon_passes": 5 }),
            ),
            &["render.photon_passes", "1 to 4", "got 5"],
        ),
        (
            "unknown material",
            with("/objects/0/material", json!("blue")),
            &["objects[0].material", "\"blue\""],
        ),
        (
            "albedo above 1",
            with("/materials/green/albedo", json!([0.1, 1.5, 0.3])),
            &["materials.green.albedo[1]", "in [0, 1]"],
        ),
        (
            "negative kappa",
            with("/materials/gold/kappa", json!([3.1, -2.7, 1.9])),
            &["materials.gold.kappa[1]", "non-negative", "-2.7"],
        ),
        (
            "index beyond the f32 laws",
            with("/materials/gold/n", json!([0.17, 1e12, 1.5])),
            &[
                "materials.gold.n[1]",
                "from 1e-9 to 1e9",
                "got 1000000000000",
            ],
        ),
        (
            "wrong version",
            with("/version", json!(2)),
            &["version", "version 1"],
        ),
        (
            "glass plane",
            with(
                "/materials/gold",
                json!({ "type": "dielectric", "eta": 1.5 }),
            ),
            &["objects[1].material", "dielectric"],
        ),
        (
            "unknown object type",
            with("/objects/0/type", json!("cube")),
            &["objects[0].type", "unknown variant `cube`"],
        ),
    ];
    for (name, text, needles) in cases {
        let message = error(&text);
        for needle in needles {
            assert!(
                message.contains(needle),
                "{name}: {message:?} lacks {needle:?}"
            );
        }
    }
}

#[test]
fn a_missing_file_is_named() {
    let err = scene::load(std::path::Path::new("no/such/scene.json")).unwrap_err();
    assert!(matches!(err.kind(), ErrorKind::Read { file, .. } if file == "no/such/scene.json"));
    assert_eq!(err.field(), ".");
}

/// One case per line: the bad file, the field the error names, and its kind
/// (what a front end translates; the English text is only its display).
#[test]
fn each_refusal_carries_its_field_and_kind() {
    type Kind = fn(&ErrorKind) -> bool;
    let cases: Vec<(&str, String, &str, Kind)> = vec![
        ("syntax", "{\"version\": 1,".into(), ".", |k| {
            matches!(k, ErrorKind::Syntax { line: 1, .. })
        }),
        (
            "schema",
            with("/camera/zoom", json!(2)),
            "camera.zoom",
            |k| matches!(k, ErrorKind::Schema { .. }),
        ),
        (
            "type missing",
            with("/lights/0/type", Value::Null).replace(",\"type\":null", ""),
            "lights[0].type",
            |k| matches!(k, ErrorKind::TypeMissing),
        ),
        (
            "type not a string",
            with("/objects/0/type", json!(3)),
            "objects[0].type",
            |k| matches!(k, ErrorKind::TypeNotString { got } if got == "3"),
        ),
        ("version", with("/version", json!(2)), "version", |k| {
            matches!(k, ErrorKind::Version { got: 2 })
        }),
        (
            "count",
            with("/objects/1/sides", json!(2)),
            "objects[1].sides",
            |k| {
                matches!(
                    k,
                    ErrorKind::NotACount {
                        min: 3,
                        max: 64,
                        ..
                    }
                )
            },
        ),
        (
            "pixels",
            with("/image", json!({ "width": 16384, "height": 16384 })),
            "image",
            |k| matches!(k, ErrorKind::TooManyPixels { .. }),
        ),
        (
            "domain",
            with("/objects/0/radius", json!(-1)),
            "objects[0].radius",
            |k| matches!(k, ErrorKind::Domain(_)),
        ),
        (
            "target is eye",
            look_at_with("target", json!([0, 0, 0])),
            "camera.target",
            |k| matches!(k, ErrorKind::TargetIsEye),
        ),
        (
            "up along the view",
            look_at_with("up", json!([0, 0, 2])),
            "camera.up",
            |k| matches!(k, ErrorKind::UpAlongView),
        ),
        (
            "field of view",
            look_at_with("fov_y_deg", json!(180)),
            "camera.fov_y_deg",
            |k| matches!(k, ErrorKind::FieldOfView { degrees } if *degrees == 180.0),
        ),
        (
            "far before near",
            look_at_with("far", json!(0.05)),
            "camera.far",
            |k| matches!(k, ErrorKind::FarNotBeyondNear { .. }),
        ),
        (
            "unknown material",
            with("/objects/0/material", json!("blue")),
            "objects[0].material",
            |k| matches!(k, ErrorKind::UnknownMaterial { name, defined } if name == "blue" && defined.len() == 2),
        ),
        (
            "glass tube",
            with(
                "/materials/gold",
                json!({ "type": "dielectric", "eta": 1.5 }),
            ),
            "objects[1].material",
            |k| matches!(k, ErrorKind::DielectricWithoutInside),
        ),
        (
            "settings",
            with("/render/max_depth", json!(1e6)),
            "render.max_depth",
            |k| matches!(k, ErrorKind::NotACount { min: 0, .. }),
        ),
    ];
    for (name, text, field, kind) in cases {
        let error = scene::parse(&text).expect_err(name);
        assert_eq!(error.field(), field, "{name}: {error}");
        assert!(kind(error.kind()), "{name}: {:?}", error.kind());
    }
}

/// `scene::course_scenes` and `scene::technique_scenes` name every scene
/// file in `crates/tracer/scenes/` and nothing else, so a scene added or
/// removed there is seen by every test, bench and example that walks the
/// lists.
#[test]
fn the_course_scene_list_is_the_scene_folder() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes");
    let mut on_disk: Vec<String> = std::fs::read_dir(dir)
        .expect("the scene folder")
        .filter_map(|e| {
            let name = e.expect("a directory entry").file_name();
            name.to_str()?.strip_suffix(".json").map(str::to_owned)
        })
        .collect();
    on_disk.sort();
    let mut listed: Vec<String> = tracer::scene::course_scenes()
        .iter()
        .chain(tracer::scene::technique_scenes())
        .map(|s| String::from(*s))
        .collect();
    listed.sort();
    assert_eq!(on_disk, listed);
}

/// A point light whose irradiance cannot be bounded because the scene's
/// extent makes f32's rounding of hit points larger than its distance to a
/// surface is refused at the light, naming the object whose coordinates
/// set that extent, not at a material as a radiance beyond f32.
#[test]
fn a_light_within_rounding_of_a_far_object_is_refused_at_the_light() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/kaleidoscope_lit.json"
    ))
    .unwrap();
    let mut scene: Value = serde_json::from_str(&text).unwrap();
    let tube = scene["objects"]
        .as_array()
        .unwrap()
        .iter()
        .position(|o| o["type"] == "mirror_tube")
        .unwrap();
    scene["objects"][tube]["axis_point"] = json!([0, 0, 1e19]);
    let error = scene::parse(&scene.to_string()).expect_err("refused");
    assert_eq!(error.field(), "lights[0]", "{error}");
    match error.kind() {
        ErrorKind::LightWithinRounding {
            distance,
            rounding,
            widest,
        } => {
            assert_eq!(*widest, tube);
            assert!(distance <= rounding && *distance > 0.0, "{error}");
        }
        other => panic!("refused as {other:?}"),
    }
}
