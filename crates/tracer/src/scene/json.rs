//! Scene text to a [`SceneFile`]: bytes to UTF-8 text, text to one JSON
//! value, no key given twice in an object, and nothing after it, its
//! shapes checked ([`super::shape`]), then serde with the JSON path of
//! every error, after rewriting the schema's `"type"` tags into serde's
//! external tagging.

use serde_json::error::Category;
use serde_json::Value;

use safe_io::json::{without_position, UniqueKeys};

use super::error::{ErrorKind, SceneError};
use super::faults::{self, Fault};
use super::schema::SceneFile;
use super::{fields, shape};

/// Bytes to text: UTF-8, or the position of the first byte that is not.
pub(super) fn text(bytes: &[u8]) -> Result<&str, SceneError> {
    std::str::from_utf8(bytes).map_err(|err| {
        let good = &bytes[..err.valid_up_to()];
        let line = good.iter().filter(|&&b| b == b'\n').count() + 1;
        let start = good.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
        // The bytes before the bad one are valid, so this cannot fail.
        let column = std::str::from_utf8(&good[start..]).map_or(1, |s| s.chars().count() + 1);
        SceneError::new(".", ErrorKind::NotUtf8 { line, column })
    })
}

/// Parses JSON text into the schema's types; errors name the JSON path. One
/// leading byte-order mark is ignored (RFC 8259 §8.1 lets a parser ignore
/// it; editors on some systems write one).
pub(super) fn scene_file(text: &str) -> Result<SceneFile, SceneError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let de = &mut serde_json::Deserializer::from_str(text);
    let UniqueKeys(mut value) = serde_path_to_error::deserialize(&mut *de).map_err(|err| {
        let path = json_path(err.path());
        match err.inner().classify() {
            // A key given twice: the text is JSON, the scene is not.
            Category::Data => {
                let message = without_position(err.inner());
                SceneError::new(path, ErrorKind::Schema { message })
            }
            _ => syntax(text, path, err.into_inner()),
        }
    })?;
    // One scene per file: text after it is an error, not ignored.
    if !faults::undone(Fault::TrailingTextIgnored) {
        de.end().map_err(|err| syntax(text, ".".to_owned(), err))?;
    }
    if !faults::undone(Fault::ShapesUnchecked) {
        shape::check(&value)?;
    }
    let tagged = retag(&mut value)?;
    serde_path_to_error::deserialize(value).map_err(|err| {
        let mut path = json_path(err.path());
        let message = without_position(err.inner());
        if message.starts_with("unknown variant") && tagged.contains(&path) {
            // The kind was the object's "type" before retagging.
            path.push_str(".type");
        }
        SceneError::new(path, ErrorKind::Schema { message })
    })
}

/// A syntax error at `path` (its part that is a field of the schema: the
/// text may break off in a key it does not have), with its position, and
/// the hint about NaN and Infinity only where the text there spells one.
fn syntax(text: &str, path: String, err: serde_json::Error) -> SceneError {
    let path = fields::known_prefix(&path).to_owned();
    let mut message = without_position(&err);
    if safe_io::json::spells_non_finite(text, &err) {
        message.push_str(&format!(" ({})", safe_io::json::NON_FINITE_HINT));
    }
    let kind = ErrorKind::Syntax {
        message,
        line: err.line(),
        column: err.column(),
    };
    SceneError::new(path, kind)
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
/// external tagging, and likewise an object's `"bump"`. Serde's internally
/// tagged enums buffer their content and lose the path of an error inside
/// it; externally tagged ones keep it. Returns the paths retagged, where an
/// unknown kind is the `"type"`'s.
fn retag(scene: &mut Value) -> Result<Vec<String>, SceneError> {
    let Some(top) = scene.as_object_mut() else {
        return Ok(Vec::new()); // serde reports the wrong type with its path
    };
    let mut places: Vec<(String, &mut Value)> = Vec::new();
    for (key, value) in top.iter_mut() {
        match (key.as_str(), value) {
            ("camera", v) => places.push(("camera".into(), v)),
            ("environment", v) => places.push(("environment".into(), v)),
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
    let mut tagged = Vec::new();
    for (path, value) in places {
        let Some(body) = retag_one(&path, value)? else {
            continue; // serde reports the wrong type with its path
        };
        tagged.push(path.clone());
        if path.starts_with("objects") {
            if let Some(bump) = body.get_mut("bump") {
                let bump_path = format!("{path}.bump");
                if retag_one(&bump_path, bump)?.is_some() {
                    tagged.push(bump_path);
                }
            }
        }
    }
    Ok(tagged)
}

/// Rewrites one `{"type": kind, ...}` at `path` as `{kind: {...}}` and
/// hands back the body; `None` for a value that is not an object.
fn retag_one<'v>(
    path: &str,
    value: &'v mut Value,
) -> Result<Option<&'v mut serde_json::Map<String, Value>>, SceneError> {
    let Value::Object(fields) = value else {
        return Ok(None);
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
    Ok(value
        .as_object_mut()
        .and_then(|m| m.values_mut().next())
        .and_then(Value::as_object_mut))
}
