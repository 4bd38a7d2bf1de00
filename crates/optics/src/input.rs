//! Inputs shared by the command line and `optics batch`: vectors written
//! `x,y,z` on the command line or `[x, y, z]` in JSON, and the names errors
//! use for each input, in the form the user wrote it.

use crate::error::{Error, ErrorKind};
use glam::DVec3;
use radiometry::domain::{self, Direction, DomainError};
use serde::Deserialize;
use std::str::FromStr;

/// A 3-vector as given: `0,3,4` on the command line, `[0, 3, 4]` in JSON.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
#[serde(from = "[f64; 3]")]
pub struct Vec3Arg(pub [f64; 3]);

impl From<[f64; 3]> for Vec3Arg {
    fn from(v: [f64; 3]) -> Self {
        Self(v)
    }
}

impl FromStr for Vec3Arg {
    type Err = Error;

    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let parts: Vec<&str> = text.split(',').map(str::trim).collect();
        let [x, y, z] = parts[..] else {
            return Err(ErrorKind::VectorParts { count: parts.len() }.into());
        };
        let parse = |axis: &'static str, part: &str| {
            part.parse::<f64>().map_err(|_| {
                Error::from(ErrorKind::VectorComponent {
                    axis,
                    text: part.to_owned(),
                })
            })
        };
        Ok(Self([parse("x", x)?, parse("y", y)?, parse("z", z)?]))
    }
}

impl Vec3Arg {
    /// The vector as `glam`'s.
    pub fn dvec3(self) -> DVec3 {
        DVec3::from_array(self.0)
    }
}

/// Where the inputs came from, which decides how an error names them:
/// `--cos-i` on the command line, `cos_i` in a batch request.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Via {
    /// Flags of the command line: `--cos-i`.
    Flags,
    /// Fields of a batch request: `cos_i`.
    Json,
}

impl Via {
    /// The user's name for the input whose JSON field is `field`.
    pub fn name(self, field: &str) -> String {
        match self {
            Via::Flags => format!("--{}", field.replace('_', "-")),
            Via::Json => field.to_owned(),
        }
    }

    /// `check` of the input whose JSON field is `field`, given the
    /// user's name for it (in JSON the field itself, so a batch line's
    /// checks copy no name unless one fails).
    fn check<T>(
        self,
        field: &str,
        check: impl FnOnce(&str) -> Result<T, DomainError>,
    ) -> Result<T, DomainError> {
        match self {
            Via::Flags => check(&self.name(field)),
            Via::Json => check(field),
        }
    }

    /// `x` if finite, else the error naming `field` as the user wrote it.
    pub fn finite(self, field: &str, x: f64) -> Result<f64, DomainError> {
        self.check(field, |name| domain::finite(name, x))
    }

    /// `x` if a cosine, in `[-1, 1]`.
    pub fn cosine(self, field: &str, x: f64) -> Result<f64, DomainError> {
        self.check(field, |name| domain::cosine(name, x))
    }

    /// `x` if a refractive index: finite and positive.
    pub fn index(self, field: &str, x: f64) -> Result<f64, DomainError> {
        self.check(field, |name| domain::refractive_index(name, x))
    }

    /// `x` if an extinction coefficient: finite and not negative.
    pub fn extinction(self, field: &str, x: f64) -> Result<f64, DomainError> {
        self.check(field, |name| domain::extinction(name, x))
    }

    /// `x` if finite and not negative.
    pub fn non_negative(self, field: &str, x: f64) -> Result<f64, DomainError> {
        self.check(field, |name| domain::non_negative(name, x))
    }

    /// `v` as a direction: finite and not zero, with its unit vector.
    pub fn direction(self, field: &str, v: Vec3Arg) -> Result<Direction, DomainError> {
        self.check(field, |name| domain::direction(name, v.dvec3()))
    }

    /// A position: every component finite, each named as a direction's
    /// are (`--light.y`).
    pub fn point(self, field: &str, v: Vec3Arg) -> Result<DVec3, DomainError> {
        self.check(field, |name| {
            for (axis, c) in ["x", "y", "z"].into_iter().zip(v.0) {
                domain::finite(&format!("{name}.{axis}"), c)?;
            }
            Ok(v.dvec3())
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vectors_parse_from_comma_separated_text() {
        let parse = |text: &str| text.parse::<Vec3Arg>();
        assert_eq!(parse("0,3,4").ok(), Some(Vec3Arg([0.0, 3.0, 4.0])));
        assert_eq!(
            parse(" 1, -2.5 ,1e3").ok(),
            Some(Vec3Arg([1.0, -2.5, 1000.0]))
        );
        let parts = parse("0,3").unwrap_err();
        assert!(matches!(parts.kind(), ErrorKind::VectorParts { count: 2 }));
        assert!(parts.to_string().contains("2 part(s)"));
        let component = parse("0,x,4").unwrap_err();
        assert!(matches!(
            component.kind(),
            ErrorKind::VectorComponent { axis: "y", .. }
        ));
        assert!(component.to_string().contains("y component"));
    }

    #[test]
    fn errors_name_the_input_as_written() {
        assert_eq!(Via::Flags.name("cos_i"), "--cos-i");
        assert_eq!(Via::Json.name("cos_i"), "cos_i");
        let err = Via::Flags
            .direction("normal", Vec3Arg([0.0; 3]))
            .unwrap_err();
        assert_eq!(
            err.to_string(),
            "--normal must be a non-zero direction, got (0, 0, 0)"
        );
        let err = Via::Flags
            .point("plane_point", Vec3Arg([0.0, f64::NAN, 1.0]))
            .unwrap_err();
        assert_eq!(
            err.to_string(),
            "--plane-point.y must be a finite number, got NaN"
        );
    }
}
