//! Scene files: the JSON schema (version 1), its parsing and its validation.
//!
//! A scene file is read in two passes. The first is serde's (`json`):
//! syntax, types and unknown fields, each error carrying the JSON path of
//! the bad value (via `serde_path_to_error`). The second is
//! [`SceneFile::validate`]: the values' domains, again naming the path. Only
//! a validated scene becomes a [`Scene`], whose numbers are the tracer's
//! `f32` and whose render settings are settled ([`Settings`]). Every refusal
//! is a [`SceneError`]: a typed [`ErrorKind`] and the field's JSON path. The
//! schema is documented in `docs/scene-schema.md`.
//!
//! | module | what |
//! |---|---|
//! | [`schema`] | the file as written |
//! | [`fields`] | the schema's fields, as the JSON paths errors name |
//! | `json` | bytes to text to the schema, errors with their JSON path |
//! | `shape` | the shapes serde would accept beyond the schema, refused |
//! | [`values`] | one value in its domain: finite, positive, a count, a direction, an image size |
//! | [`validate`] | the schema to the model, each value in its domain |
//! | [`environment`] | the environment's scale and image files, read and sized once |
//! | [`bound`] | the largest radiance the scene's numbers can give, within `f32` |
//! | [`model`] | the validated scene the integrators read |
//! | [`settings`] | render settings as given and as settled |
//! | `shipped` | the scenes that ship with the tracer, listed in `shipped.json`: [`course_scenes`], [`technique_scenes`] |
//! | [`error`] | the kinds of refusal |

pub mod bound;
pub mod environment;
pub mod error;
#[cfg(feature = "faults")]
#[doc(hidden)]
pub mod faults;
#[cfg(not(feature = "faults"))]
pub(crate) mod faults;
pub mod fields;
mod json;
pub mod model;
pub mod schema;
pub mod settings;
mod shape;
mod shipped;
pub mod validate;
pub mod values;

pub use crate::kinds::{
    FresnelModel, FresnelName, GlassShortcut, IntegratorKind, PixelFilter, Precision, RayOffset,
};
pub use crate::kinds::{MAX_DEPTH, MAX_PHOTONS, MAX_PHOTON_PASSES, MAX_SPP};
pub use crate::kinds::{MAX_IMAGE_SIDE, MAX_PIXELS, SCHEMA_VERSION};
pub use error::{ErrorKind, SceneError};
pub use model::{Light, Material, Scene};
pub use schema::SceneFile;
pub use settings::{PhotonSettings, RenderSpec, Settings};
pub use shipped::{course_scenes, technique_scenes};

/// Reads and validates a scene file; an environment's image files are
/// named relative to its directory.
pub fn load(path: &std::path::Path) -> Result<Scene, SceneError> {
    let bytes = std::fs::read(path).map_err(|source| {
        let file = path.display().to_string();
        SceneError::new(".", ErrorKind::Read { file, source })
    })?;
    parse_bytes_in(&bytes, path.parent().unwrap_or(std::path::Path::new("")))
}

/// [`parse_bytes`], an environment's image files named relative to `dir`.
pub fn parse_bytes_in(bytes: &[u8], dir: &std::path::Path) -> Result<Scene, SceneError> {
    json::scene_file(json::text(bytes)?)?.validate_in(dir)
}

/// Parses and validates a scene from the bytes of a file: UTF-8 (a bad
/// byte is refused with its line and column), one JSON object; an
/// environment's image files are named relative to the current directory.
pub fn parse_bytes(bytes: &[u8]) -> Result<Scene, SceneError> {
    parse(json::text(bytes)?)
}

/// Parses and validates a scene from JSON text.
pub fn parse(text: &str) -> Result<Scene, SceneError> {
    json::scene_file(text)?.validate()
}
