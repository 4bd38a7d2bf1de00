//! Why a scene file or its settings were refused: a typed [`ErrorKind`]
//! and the JSON path of the field it concerns. The English text is only the
//! [`Display`](std::fmt::Display) of the kind, so that a front end can
//! translate every kind with an exhaustive `match`.

use std::fmt;

use radiometry::domain::DomainError;

mod english;
mod image;
mod json_type;
mod kind;

pub use image::{ImageProblem, SizeRule};
pub use json_type::JsonType;
pub use kind::ErrorKind;

/// A refused scene or setting: what is wrong, and where.
#[derive(Debug)]
pub struct SceneError {
    field: String,
    kind: ErrorKind,
}

impl SceneError {
    /// An error of `kind` at the JSON path `field`.
    pub fn new(field: impl Into<String>, kind: ErrorKind) -> Self {
        SceneError {
            field: field.into(),
            kind,
        }
    }

    /// The JSON path of the bad value: `.` for the whole file (a file that
    /// cannot be read, text that is not one JSON value, JSON that breaks
    /// off before a value could be named); settings given beside the file
    /// are under `overrides`. A field the schema does not have (an unknown
    /// field, or a syntax error in its value) is named as the file spells it.
    pub fn field(&self) -> &str {
        &self.field
    }

    /// What is wrong.
    pub fn kind(&self) -> &ErrorKind {
        &self.kind
    }
}

impl From<DomainError> for SceneError {
    fn from(error: DomainError) -> Self {
        let field = match &error {
            DomainError::NotFinite { name, .. }
            | DomainError::OutOfRange { name, .. }
            | DomainError::ZeroVector { name, .. } => name.clone(),
        };
        SceneError::new(field, ErrorKind::Domain(error))
    }
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.kind {
            // These name their subject themselves.
            ErrorKind::Read { .. } | ErrorKind::Domain(_) => write!(f, "{}", self.kind),
            // The whole file is the file the caller names.
            kind if self.field == "." => write!(f, "{kind}"),
            kind => write!(f, "{}: {kind}", self.field),
        }
    }
}

// No `source`: the operating system's reason is part of the message, and
// a reporter that also printed the chain would print it twice.
impl std::error::Error for SceneError {}
