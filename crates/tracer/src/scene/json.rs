//! Scene text to a [`SceneFile`]: serde with the JSON path of every error,
//! after rewriting the schema's `"type"` tags into serde's external tagging.

use serde_json::Value;

use super::schema::SceneFile;
use super::{ErrorKind, SceneError};

/// Parses JSON text into the schema's types; errors name the JSON path.
pub(super) fn scene_file(text: &str) -> Result<SceneFile, SceneError> {
    let de = &mut serde_json::Deserializer::from_str(text);
    let mut value: Value = serde_path_to_error::deserialize(de).map_err(|err| {
        let path = err.path().to_string();
        let inner = err.into_inner();
        let mut message = without_position(&inner);
        if message == "expected value" {
            message.push_str(" (JSON numbers are finite: NaN and Infinity are not numbers)");
        }
        let kind = ErrorKind::Syntax {
            message,
            line: inner.line(),
            column: inner.column(),
        };
        SceneError::new(path, kind)
    })?;
    retag(&mut value)?;
    serde_path_to_error::deserialize(value).map_err(|err| {
        let mut path = json_path(err.path());
        let message = without_position(err.inner());
        if message.starts_with("unknown variant") {
            // The kind was the object's "type" before retagging.
            path.push_str(".type");
        }
        SceneError::new(path, ErrorKind::Schema { message })
    })
}

fn without_position(err: &serde_json::Error) -> String {
    let text = err.to_string();
    match text.find(" at line ") {
        Some(i) => text[..i].to_owned(),
        None => text,
    }
}

/// The path of a value as the file spells it: variant names, which exist
/// only after [`retag`], are left out.
fn json_path(path: &serde_path_to_error::Path) -> String {
    use serde_path_to_error::Segment;
    let mut out = String::new();
    for segment in path.iter() {
        match segment {
            Segment::Seq { index } => out.push_str(&format!("[{index}]")),
            Segment::Map { key } => {
                if !out.is_empty() {
                    out.push('.');
                }
                out.push_str(key);
            }
            Segment::Enum { .. } | Segment::Unknown => {}
        }
    }
    if out.is_empty() {
        ".".to_owned()
    } else {
        out
    }
}

/// Rewrites each `{"type": "sphere", ...}` as `{"sphere": {...}}`, serde's
/// external tagging. Serde's internally tagged enums buffer their content
/// and lose the path of an error inside it; externally tagged ones keep it.
fn retag(scene: &mut Value) -> Result<(), SceneError> {
    let Some(top) = scene.as_object_mut() else {
        return Ok(()); // serde reports the wrong type with its path
    };
    let mut places: Vec<(String, &mut Value)> = Vec::new();
    for (key, value) in top.iter_mut() {
        match (key.as_str(), value) {
            ("camera", v) => places.push(("camera".into(), v)),
            ("materials", Value::Object(m)) => {
                for (name, v) in m.iter_mut() {
                    places.push((format!("materials.{name}"), v));
                }
            }
            ("objects" | "lights", Value::Array(items)) => {
                for (i, v) in items.iter_mut().enumerate() {
                    places.push((format!("{key}[{i}]"), v));
                }
            }
            _ => {}
        }
    }
    for (path, value) in places {
        let Value::Object(fields) = value else {
            continue; // serde reports the wrong type with its path
        };
        let kind = match fields.remove("type") {
            Some(Value::String(kind)) => kind,
            Some(other) => {
                return Err(SceneError::new(
                    format!("{path}.type"),
                    ErrorKind::TypeNotString {
                        got: other.to_string(),
                    },
                ))
            }
            None => {
                return Err(SceneError::new(
                    format!("{path}.type"),
                    ErrorKind::TypeMissing,
                ))
            }
        };
        let body = Value::Object(std::mem::take(fields));
        *value = Value::Object(serde_json::Map::from_iter([(kind, body)]));
    }
    Ok(())
}
