//! A job or result line read strictly: JSON of the line's fields (none
//! unknown, none given twice, none missing), then its schema and version.

use safe_io::json::UniqueKeys;
use serde_json::error::Category;
use serde_json::Value;

use super::error::{JobError, LineKind, Place, VERSION};

/// A line read as `kind`: JSON of the line's fields (none unknown, none
/// given twice, none missing), then its schema and version; each refusal
/// names the line and the field.
pub fn read_line<T: serde::de::DeserializeOwned>(
    text: &str,
    kind: LineKind,
    at: &Place,
) -> Result<T, JobError> {
    let line_error = |field: Option<String>, message: String| JobError::Line {
        kind,
        at: at.clone(),
        field,
        message,
    };
    let json = &mut serde_json::Deserializer::from_str(text);
    let UniqueKeys(value) = serde_path_to_error::deserialize(&mut *json).map_err(|e| {
        // A key given twice is named; a syntax error has no field.
        let field = (e.inner().classify() == Category::Data).then(|| e.path().to_string());
        line_error(field, e.into_inner().to_string())
    })?;
    json.end().map_err(|e| line_error(None, e.to_string()))?;
    if !value.is_object() {
        return Err(line_error(
            None,
            format!("a line is a JSON object of the job's fields, not {value}"),
        ));
    }
    // The schema and version first: a line of another version is refused
    // as that, not by the first field the versions disagree on.
    if let Some(found) = value.get("schema") {
        if found.as_str() != Some(kind.schema()) {
            let found = found
                .as_str()
                .map_or_else(|| found.to_string(), str::to_owned);
            return Err(JobError::Schema {
                kind,
                at: at.clone(),
                found,
            });
        }
    }
    if let Some(found) = value.get("version").and_then(Value::as_u64) {
        if found != u64::from(VERSION) {
            return Err(JobError::Version {
                kind,
                at: at.clone(),
                found: u32::try_from(found).unwrap_or(u32::MAX),
            });
        }
    }
    let mut track = serde_path_to_error::Track::new();
    let fields = serde_path_to_error::Deserializer::new(value, &mut track);
    T::deserialize(fields).map_err(|e| {
        let path = track.path().to_string();
        let field = (path != ".").then_some(path).or_else(|| unknown_field(&e));
        line_error(field, e.to_string())
    })
}

/// The field serde names in an unknown-field or missing-field message.
fn unknown_field(error: &serde_json::Error) -> Option<String> {
    let text = error.to_string();
    let start = text.find('`')? + 1;
    let end = start + text[start..].find('`')?;
    Some(text[start..end].to_owned())
}
