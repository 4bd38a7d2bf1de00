//! The shapes serde would accept beyond the schema, refused by path: serde
//! reads a struct from an array as well as from an object (a whole scene
//! as `[1, {...}, ...]`, `"image": [8, 6]`) and a unit choice from a
//! one-key object as well as from its name (`"integrator": {"path": null}`).
//! The schema (`docs/scene-schema.md`) has one shape for each: these are
//! checked here, before serde, and every other type error is serde's.

use serde_json::Value;

use super::error::JsonType;
use super::error::{ErrorKind, SceneError};

/// The scene's settings that are one of several names.
const CHOICES: [&str; 4] = ["integrator", "fresnel", "pixel_filter", "precision"];

/// Refuses a struct written other than as an object, and a choice written
/// other than as its name.
pub(super) fn check(scene: &Value) -> Result<(), SceneError> {
    object(".", scene)?;
    for field in ["image", "render"] {
        if let Some(value) = scene.get(field) {
            object(field, value)?;
        }
    }
    let Some(render) = scene.get("render") else {
        return Ok(());
    };
    for field in CHOICES {
        if let Some(value) = render.get(field) {
            expect(&format!("render.{field}"), value, JsonType::String)?;
        }
    }
    match render.get("ray_offset") {
        // `{"fixed": metres}` and `{"scaled": ε}` are the choices that carry
        // a value.
        Some(Value::Object(map)) if map.contains_key("fixed") || map.contains_key("scaled") => {
            Ok(())
        }
        Some(value) => expect("render.ray_offset", value, JsonType::String),
        None => Ok(()),
    }
}

fn object(path: &str, value: &Value) -> Result<(), SceneError> {
    expect(path, value, JsonType::Object)
}

fn expect(path: &str, value: &Value, expected: JsonType) -> Result<(), SceneError> {
    let got = JsonType::of(value);
    if got == expected {
        Ok(())
    } else {
        Err(SceneError::new(
            path,
            ErrorKind::WrongShape { expected, got },
        ))
    }
}
