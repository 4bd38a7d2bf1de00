//! Scene files written to break the reader: text after the scene, shapes
//! serde would accept beyond the schema, bytes that are not UTF-8, a
//! byte-order mark, and numbers each in range whose products are not. Each
//! is refused with its kind and the field it concerns, or read as the
//! schema says, and no accepted scene renders a NaN.

mod common;

use serde_json::{json, Value};
use tracer::job::{Overrides, RenderError, RenderJob};
use tracer::scene::error::JsonType;
use tracer::scene::{self, ErrorKind, SceneError};

fn course_file(name: &str) -> Value {
    let path = format!("{}/scenes/{name}.json", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn refused(text: &str) -> SceneError {
    match scene::parse(text) {
        Ok(_) => panic!("accepted: {text}"),
        Err(error) => error,
    }
}

#[test]
fn text_after_the_scene_is_refused() {
    let good = course_file("shadow").to_string();
    for (name, text) in [
        ("garbage", format!("{good}\ngarbage")),
        ("two scenes", format!("{good}{good}")),
        ("a stray brace", format!("{good} }}")),
    ] {
        let error = refused(&text);
        assert_eq!(error.field(), ".", "{name}");
        assert!(
            matches!(error.kind(), ErrorKind::Syntax { message, .. } if message == "trailing characters"),
            "{name}: {:?}",
            error.kind()
        );
    }
    // Whitespace after the scene is not text.
    assert!(scene::parse(&format!("{good}\n\n  \t\n")).is_ok());
}

#[test]
fn an_unknown_integrator_is_named_at_its_own_field() {
    let mut file = course_file("shadow");
    file["render"] = json!({ "integrator": "pathx" });
    let error = refused(&file.to_string());
    assert_eq!(error.field(), "render.integrator", "{error}");
    assert!(matches!(error.kind(), ErrorKind::Schema { .. }));
    // An unknown object kind is still its "type".
    file["render"] = json!({});
    file["objects"][0]["type"] = json!("cube");
    assert_eq!(refused(&file.to_string()).field(), "objects[0].type");
}

/// One case per line: the shape serde would accept, where, and what the
/// schema has there.
#[test]
fn shapes_beyond_the_schema_are_refused_by_path() {
    let file = course_file("shadow");
    let set = |field: &str, value: Value| {
        let mut f = file.clone();
        f[field] = value;
        f.to_string()
    };
    let whole_as_array = Value::Array(file.as_object().unwrap().values().cloned().collect());
    let cases = [
        (
            "the scene as an array",
            whole_as_array.to_string(),
            ".",
            JsonType::Object,
        ),
        (
            "the image as an array",
            set("image", json!([8, 6])),
            "image",
            JsonType::Object,
        ),
        (
            "the render as an array",
            set("render", json!([])),
            "render",
            JsonType::Object,
        ),
        (
            "an integrator as an object",
            set("render", json!({ "integrator": { "path": null } })),
            "render.integrator",
            JsonType::String,
        ),
        (
            "a Fresnel law as an object",
            set("render", json!({ "fresnel": { "exact": null } })),
            "render.fresnel",
            JsonType::String,
        ),
        (
            "a pixel filter as an object",
            set("render", json!({ "pixel_filter": { "box": null } })),
            "render.pixel_filter",
            JsonType::String,
        ),
        (
            "the robust offset as an object",
            set("render", json!({ "ray_offset": { "robust": null } })),
            "render.ray_offset",
            JsonType::String,
        ),
    ];
    for (name, text, field, expected) in cases {
        let error = refused(&text);
        assert_eq!(error.field(), field, "{name}: {error}");
        assert!(
            matches!(error.kind(), ErrorKind::WrongShape { expected: e, .. } if *e == expected),
            "{name}: {:?}",
            error.kind()
        );
    }
    // The documented shapes are read.
    for render in [
        json!({ "integrator": "path", "fresnel": "schlick-rarer", "ray_offset": "robust" }),
        json!({ "fresnel": "schlick-incident" }),
        json!({ "integrator": "whitted", "pixel_filter": "box" }),
        json!({ "pixel_filter": "center" }),
        json!({ "ray_offset": { "fixed": 0.001 } }),
        json!({ "ray_offset": { "scaled": 8.94e-5 } }),
    ] {
        scene::parse(&set("render", render)).expect("documented shape");
    }
}

/// The bare `schlick` named one form in some places and the other
/// elsewhere: a scene that gives it is refused at `render.fresnel`, and
/// the message names both forms, so no scene silently changes meaning.
#[test]
fn a_bare_schlick_is_refused_naming_the_field_and_both_forms() {
    let mut file = course_file("shadow");
    file["render"] = json!({ "fresnel": "schlick" });
    let error = refused(&file.to_string());
    assert_eq!(error.field(), "render.fresnel", "{error}");
    assert!(
        matches!(error.kind(), ErrorKind::SchlickFormUnnamed),
        "{:?}",
        error.kind()
    );
    let message = error.to_string();
    for form in ["\"schlick-incident\"", "\"schlick-rarer\""] {
        assert!(message.contains(form), "{message}");
    }
}

#[test]
fn bytes_that_are_not_utf8_are_refused_with_their_position() {
    let text = course_file("shadow").to_string();
    let mut bytes = b"{\n  \"vers\xC3\xA9ion\": \xFF1,".to_vec();
    bytes.extend_from_slice(&text.as_bytes()[1..]);
    let error = scene::parse_bytes(&bytes).unwrap_err();
    assert_eq!(error.field(), ".");
    // Line 2: `  "vers`, é (one character of two bytes), `ion": `, the bad byte.
    assert!(
        matches!(
            error.kind(),
            ErrorKind::NotUtf8 {
                line: 2,
                column: 15
            }
        ),
        "{:?}",
        error.kind()
    );
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("latin1.json");
    std::fs::write(&path, &bytes).unwrap();
    let error = scene::load(&path).unwrap_err();
    assert!(matches!(error.kind(), ErrorKind::NotUtf8 { line: 2, .. }));
}

#[test]
fn a_byte_order_mark_is_ignored_and_the_nan_hint_is_given_only_for_nan() {
    let text = course_file("shadow").to_string();
    let bom = [b"\xEF\xBB\xBF".as_slice(), text.as_bytes()].concat();
    scene::parse_bytes(&bom).expect("a byte-order mark is ignored (RFC 8259 §8.1)");
    scene::parse(&format!("\u{feff}{text}")).expect("as text too");
    let hint = "NaN and Infinity are not numbers";
    let nan = text.replacen("0.8", "NaN", 1);
    assert!(
        refused(&nan).to_string().contains(hint),
        "{}",
        refused(&nan)
    );
    let inf = text.replacen("0.8", "-Infinity", 1);
    assert!(
        refused(&inf).to_string().contains(hint),
        "{}",
        refused(&inf)
    );
    for other in ["{,}", "\u{1}", &text.replacen("0.8", "x", 1)] {
        let message = refused(other).to_string();
        assert!(!message.contains(hint), "{other:?}: {message}");
    }
}

#[test]
fn a_read_error_gives_the_reason_once() {
    let error = scene::load(std::path::Path::new("no/such/dir/scene.json")).unwrap_err();
    let reason = std::io::Error::from(std::io::ErrorKind::NotFound).to_string();
    let message = error.to_string();
    assert!(message.starts_with("cannot be read: "), "{message}");
    // Told once, in the message; no cause chain to print it again.
    assert!(std::error::Error::source(&error).is_none());
    assert_eq!(
        message.matches("os error").count(),
        1,
        "{message} ({reason})"
    );
}

/// Products of accepted numbers beyond `f32`, refused at validation and
/// named by the material that reaches them; a point light on a surface,
/// whose irradiance there has no bound, named as the light.
#[test]
fn products_of_scene_numbers_beyond_f32_are_refused_at_the_material() {
    let mut lit = course_file("kaleidoscope_lit");
    lit["materials"]["green"]["diffuse"] = json!([3.4e38, 3.4e38, 3.4e38]);
    let mut ambient = course_file("shadow");
    ambient["ambient"] = json!([1e20, 1e20, 1e20]);
    let rough = first_rough(&ambient);
    ambient["materials"][&rough]["ambient"] = json!([1e20, 1e20, 1e20]);
    let mut near = course_file("shadow");
    // A point light within rounding of a lit sphere: E = I / r² unbounded.
    let sphere = near["objects"][0].clone();
    let (c, r) = (&sphere["center"], sphere["radius"].as_f64().unwrap());
    let on = json!([c[0], c[1].as_f64().unwrap() + r, c[2]]);
    near["lights"] = json!([{ "type": "point", "position": on, "intensity": [1, 1, 1] }]);
    for (name, file, field) in [
        (
            "kd 3.4e38 under a point light",
            lit,
            "materials.green".to_owned(),
        ),
        (
            "ambient 1e20 and ka 1e20",
            ambient,
            format!("materials.{rough}"),
        ),
    ] {
        let error = refused(&file.to_string());
        assert_eq!(error.field(), field, "{name}: {error}");
        assert!(
            matches!(error.kind(), ErrorKind::RadianceOverflow { bound } if *bound > f32::MAX as f64),
            "{name}: {:?}",
            error.kind()
        );
    }
    // The light on the sphere is the cause, not the sphere's material.
    let error = refused(&near.to_string());
    assert_eq!(error.field(), "lights[0]", "{error}");
    assert!(
        matches!(error.kind(), ErrorKind::LightWithinRounding { distance, rounding, .. } if distance <= rounding),
        "{:?}",
        error.kind()
    );
}

fn first_rough(file: &Value) -> String {
    let materials = file["materials"].as_object().unwrap();
    let (name, _) = materials
        .iter()
        .find(|(_, m)| m["type"] == "course_rough")
        .unwrap();
    name.clone()
}

/// What the bound cannot see, a path's gain (here the path tracer's
/// `π f_r` per bounce, 3·10¹², between two walls that never let a path
/// out), is refused after tracing and before anything is written.
#[test]
fn a_render_that_leaves_f32_is_refused_before_writing() {
    let wall = json!({ "type": "course_rough", "ambient": [0, 0, 0], "diffuse": [1e12, 1e12, 1e12],
                       "specular": [0, 0, 0], "shininess": 1 });
    let scene = common::parse(json!({
        "version": 1, "image": { "width": 4, "height": 3 },
        "camera": { "type": "course_pinhole" },
        "materials": { "wall": wall },
        "objects": [
            { "type": "plane", "point": [0, 0, 5], "normal": [0, 0, -1], "material": "wall" },
            { "type": "plane", "point": [0, 0, -5], "normal": [0, 0, 1], "material": "wall" }
        ],
        "lights": [ { "type": "point", "position": [0, 0, 0], "intensity": [1, 1, 1] } ],
        "render": { "integrator": "path", "max_depth": 11 }
    }));
    let job = RenderJob::new(scene, &Overrides::default()).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("out.png");
    let destination = tracer::output::Destination::new(&png, &[]).unwrap();
    match job.render_to(&destination, Some(1), &|_| {}) {
        Err(RenderError::NotFinite { x, y }) => assert!(x < 4 && y < 3),
        other => panic!("rendered: {:?}", other.map(|r| r.image.pixels)),
    }
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        0,
        "nothing written"
    );
}

/// Every course scene is within the bound and renders finite, under every
/// integrator that can render it.
#[test]
fn the_course_scenes_are_within_the_bound_and_render_finite() {
    let dir = format!("{}/scenes", env!("CARGO_MANIFEST_DIR"));
    let mut scenes = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "json") {
            continue;
        }
        let scene = scene::load(&path).unwrap().resized(8, 6);
        for integrator in common::LAW_INTEGRATORS {
            let settings = tracer::scene::Settings {
                integrator,
                ..scene.settings
            };
            let image = common::render_with(&scene, &settings, Some(1));
            assert!(image.pixels.iter().all(|p| p.is_finite()), "{path:?}");
        }
        scenes += 1;
    }
    assert!(scenes >= 9, "{scenes}");
}
