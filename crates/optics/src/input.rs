//! Inputs shared by the command line and `optics batch`: vectors written
//! `x,y,z` on the command line or `[x, y, z]` in JSON, and the names errors
//! use for each input, in the form the user wrote it.

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
    type Err = String;

    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let parts: Vec<&str> = text.split(',').map(str::trim).collect();
        let [x, y, z] = parts[..] else {
            return Err(format!(
                "expected three comma-separated numbers such as 0,3,4, got {} part(s)",
                parts.len()
            ));
        };
        let parse = |axis: &str, part: &str| {
            part.parse::<f64>()
                .map_err(|_| format!("the {axis} component {part:?} is not a number"))
        };
        Ok(Self([parse("x", x)?, parse("y", y)?, parse("z", z)?]))
    }
}

impl Vec3Arg {
    pub fn dvec3(self) -> DVec3 {
        DVec3::from_array(self.0)
    }
}

/// Where the inputs came from, which decides how an error names them:
/// `--cos-i` on the command line, `cos_i` in a batch request.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Via {
    Flags,
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

    pub fn finite(self, field: &str, x: f64) -> Result<f64, DomainError> {
        domain::finite(&self.name(field), x)
    }

    pub fn cosine(self, field: &str, x: f64) -> Result<f64, DomainError> {
        domain::cosine(&self.name(field), x)
    }

    pub fn index(self, field: &str, x: f64) -> Result<f64, DomainError> {
        domain::refractive_index(&self.name(field), x)
    }

    pub fn extinction(self, field: &str, x: f64) -> Result<f64, DomainError> {
        domain::extinction(&self.name(field), x)
    }

    pub fn non_negative(self, field: &str, x: f64) -> Result<f64, DomainError> {
        domain::non_negative(&self.name(field), x)
    }

    pub fn direction(self, field: &str, v: Vec3Arg) -> Result<Direction, DomainError> {
        domain::direction(&self.name(field), v.dvec3())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vectors_parse_from_comma_separated_text() {
        assert_eq!("0,3,4".parse(), Ok(Vec3Arg([0.0, 3.0, 4.0])));
        assert_eq!(" 1, -2.5 ,1e3".parse(), Ok(Vec3Arg([1.0, -2.5, 1000.0])));
        assert!("0,3".parse::<Vec3Arg>().unwrap_err().contains("2 part(s)"));
        assert!("0,x,4"
            .parse::<Vec3Arg>()
            .unwrap_err()
            .contains("y component"));
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
    }
}
