//! Loading the reference files of `validation/reference/`: each is one JSON
//! document with a `schema` field naming its format and version; a file of an
//! unknown schema is refused rather than half-read.

use std::path::{Path, PathBuf};

use serde::de::DeserializeOwned;
use serde::Deserialize;

/// Why a reference file could not be used.
#[derive(Debug, thiserror::Error)]
pub enum ReferenceError {
    /// The file could not be read.
    #[error("cannot read reference {path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The file is not the JSON its schema describes.
    #[error("reference {path} is malformed at `{field}`: {message}")]
    Malformed {
        /// The file.
        path: PathBuf,
        /// The path of the offending field, e.g. `dielectric[3].mitsuba.f`.
        field: String,
        /// What was wrong.
        message: String,
    },
    /// The file declares a different format or version.
    #[error("reference {path} has schema `{found}`, expected `{expected}`")]
    Schema {
        /// The file.
        path: PathBuf,
        /// The declared schema.
        found: String,
        /// The schema this harness reads.
        expected: &'static str,
    },
}

/// The committed reference directory of the checkout this crate was built
/// from, for tests and examples (the harness's command reads the checkout's
/// it finds at run time: [`crate::checkout::Checkout::reference_dir`]).
pub fn committed_dir() -> PathBuf {
    crate::checkout::Checkout::at_build_time().reference_dir()
}

#[derive(Deserialize)]
struct SchemaOnly {
    schema: String,
}

/// Reads `dir/name`, checks that its `schema` is `expected`, and parses it,
/// naming the offending field on failure.
pub fn load<T: DeserializeOwned>(
    dir: &Path,
    name: &str,
    expected: &'static str,
) -> Result<T, ReferenceError> {
    let path = dir.join(name);
    let text = std::fs::read_to_string(&path).map_err(|source| ReferenceError::Io {
        path: path.clone(),
        source,
    })?;
    parse(&path, &text, expected)
}

/// Parses reference text (see [`load`]); `path` is only used in errors.
pub fn parse<T: DeserializeOwned>(
    path: &Path,
    text: &str,
    expected: &'static str,
) -> Result<T, ReferenceError> {
    let malformed = |e: serde_path_to_error::Error<serde_json::Error>| ReferenceError::Malformed {
        path: path.to_owned(),
        field: e.path().to_string(),
        message: e.inner().to_string(),
    };
    let head: SchemaOnly =
        serde_path_to_error::deserialize(&mut serde_json::Deserializer::from_str(text))
            .map_err(malformed)?;
    if head.schema != expected {
        return Err(ReferenceError::Schema {
            path: path.to_owned(),
            found: head.schema,
            expected,
        });
    }
    serde_path_to_error::deserialize(&mut serde_json::Deserializer::from_str(text))
        .map_err(malformed)
}

/// Parses any reference document, whatever its schema (for reading the
/// self-description fields every reference carries).
pub fn parse_any<T: DeserializeOwned>(path: &Path, text: &str) -> Result<T, ReferenceError> {
    serde_path_to_error::deserialize(&mut serde_json::Deserializer::from_str(text)).map_err(|e| {
        ReferenceError::Malformed {
            path: path.to_owned(),
            field: e.path().to_string(),
            message: e.inner().to_string(),
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Deserialize, Debug)]
    #[allow(dead_code)]
    struct Doc {
        schema: String,
        cases: Vec<Case>,
    }
    #[derive(Deserialize, Debug)]
    #[allow(dead_code)]
    struct Case {
        cos_i: f64,
    }

    #[test]
    fn a_malformed_field_is_named() {
        let text = r#"{"schema": "x/1", "cases": [{"cos_i": 1.0}, {"cos_i": "half"}]}"#;
        let err = parse::<Doc>(Path::new("r.json"), text, "x/1").unwrap_err();
        let message = err.to_string();
        assert!(message.contains("cases[1].cos_i"), "{message}");
    }

    #[test]
    fn another_schema_is_refused() {
        let err = parse::<Doc>(
            Path::new("r.json"),
            r#"{"schema": "x/2", "cases": []}"#,
            "x/1",
        )
        .unwrap_err();
        assert!(matches!(err, ReferenceError::Schema { .. }), "{err}");
    }
}
