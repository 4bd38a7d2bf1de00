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

/// The committed reference directory, `validation/reference/`.
pub fn committed_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("reference")
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

/// How closely a regenerated reference must reproduce the committed one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Reproduction {
    /// Byte for byte: the generator does all its arithmetic itself (mpmath,
    /// Mitsuba) or copies published data.
    Exact,
    /// The same JSON document, every number within
    /// [`BLAS_TOLERANCE`]` · max(1, |value|)`: the generator's numbers go
    /// through numpy's BLAS, whose kernel (chosen per CPU) rounds the last
    /// bits differently. See `python-checks/reproduce.py` for the measured
    /// spread; this is the same rule.
    UpToBlasRounding,
}

/// The tolerance of [`Reproduction::UpToBlasRounding`], twenty times the
/// largest difference measured between two OpenBLAS kernels (5.7e-14, in
/// CIELAB a*).
pub const BLAS_TOLERANCE: f64 = 1e-12;

/// Where `fresh` departs from `committed` (at most `limit` places, each
/// named by its JSON path), empty when it reproduces it as `how` requires.
/// Key order is not compared here (the JSON reader sorts keys); the Python
/// check of the same files compares it.
pub fn departures(committed: &[u8], fresh: &[u8], how: Reproduction, limit: usize) -> Vec<String> {
    if committed == fresh {
        return Vec::new();
    }
    if how == Reproduction::Exact {
        return vec!["the bytes differ".to_owned()];
    }
    let parse = |bytes: &[u8]| serde_json::from_slice::<serde_json::Value>(bytes);
    let (a, b) = match (parse(committed), parse(fresh)) {
        (Ok(a), Ok(b)) => (a, b),
        (Err(e), _) => return vec![format!("the committed file is not JSON: {e}")],
        (_, Err(e)) => return vec![format!("the regenerated file is not JSON: {e}")],
    };
    let mut found = Vec::new();
    walk(&a, &b, &mut String::new(), &mut found);
    found.truncate(limit);
    found
}

fn walk(a: &serde_json::Value, b: &serde_json::Value, path: &mut String, found: &mut Vec<String>) {
    use serde_json::Value;
    let here = |path: &str| {
        if path.is_empty() {
            ".".to_owned()
        } else {
            path.to_owned()
        }
    };
    match (a, b) {
        (Value::Number(x), Value::Number(y)) if x.is_f64() || y.is_f64() => {
            let (x, y) = (
                x.as_f64().unwrap_or(f64::NAN),
                y.as_f64().unwrap_or(f64::NAN),
            );
            let scale = 1f64.max(x.abs()).max(y.abs());
            if !((x - y).abs() <= BLAS_TOLERANCE * scale) {
                found.push(format!(
                    "{}: committed {x:?}, regenerated {y:?}",
                    here(path)
                ));
            }
        }
        (Value::Object(x), Value::Object(y)) => {
            if !x.keys().eq(y.keys()) {
                let keys =
                    |m: &serde_json::Map<String, Value>| m.keys().cloned().collect::<Vec<_>>();
                found.push(format!(
                    "{}: keys {:?} against {:?}",
                    here(path),
                    keys(x),
                    keys(y)
                ));
                return;
            }
            for (key, value) in x {
                let len = path.len();
                path.push('.');
                path.push_str(key);
                walk(value, &y[key], path, found);
                path.truncate(len);
            }
        }
        (Value::Array(x), Value::Array(y)) => {
            if x.len() != y.len() {
                found.push(format!(
                    "{}: {} elements against {}",
                    here(path),
                    x.len(),
                    y.len()
                ));
                return;
            }
            for (i, (u, v)) in x.iter().zip(y).enumerate() {
                let len = path.len();
                path.push_str(&format!("[{i}]"));
                walk(u, v, path, found);
                path.truncate(len);
            }
        }
        _ if a == b => {}
        _ => found.push(format!("{}: committed {a}, regenerated {b}", here(path))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduction_tolerates_blas_rounding_and_nothing_else() {
        let committed =
            br#"{"schema": "x/1", "n": 3, "values": [0.1, -16.29901162733291, 1e-300]}"#;
        let blas = br#"{"schema": "x/1", "n": 3, "values": [0.10000000000000003, -16.299011627332966, 1e-300]}"#;
        let up_to = Reproduction::UpToBlasRounding;
        assert!(departures(committed, blas, up_to, 5).is_empty());
        assert_eq!(
            departures(committed, blas, Reproduction::Exact, 5),
            ["the bytes differ"]
        );
        let changed: [&[u8]; 5] = [
            br#"{"schema": "x/1", "n": 3, "values": [0.100000001, -16.29901162733291, 1e-300]}"#,
            br#"{"schema": "x/1", "n": 3, "values": [0.1, -16.29901162733291]}"#,
            br#"{"schema": "x/1", "n": 4, "values": [0.1, -16.29901162733291, 1e-300]}"#,
            br#"{"schema": "x/2", "n": 3, "values": [0.1, -16.29901162733291, 1e-300]}"#,
            br#"{"schema": "x/1", "n": 3, "values": [0.1, -16.29901162733291, "1e-300"]}"#,
        ];
        for fresh in changed {
            let found = departures(committed, fresh, up_to, 5);
            assert_eq!(
                found.len(),
                1,
                "{}: {found:?}",
                String::from_utf8_lossy(fresh)
            );
        }
        let found = departures(committed, changed[0], up_to, 5);
        assert!(
            found[0].starts_with(".values[0]: committed 0.1"),
            "{found:?}"
        );
        assert!(!departures(committed, b"{", up_to, 5).is_empty());
    }

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
