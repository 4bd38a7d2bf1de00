//! Validation of user input into the domain of the laws.
//!
//! The laws themselves never panic and give NaN outside their domain (see
//! the crate conventions). Code that takes numbers from a person or a file
//! checks them here first, so that a bad value is reported by the name of
//! the input that carried it, with what was expected.
//!
//! ```
//! use radiometry::domain;
//! assert_eq!(domain::refractive_index("--eta", 1.5), Ok(1.5));
//! let err = domain::refractive_index("--eta", -1.0).unwrap_err();
//! assert_eq!(err.to_string(), "--eta must be a positive refractive index, got -1");
//! ```

use glam::DVec3;

/// An input outside the domain of a law, named by the input that carried it.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum DomainError {
    /// NaN or infinite.
    #[error("{name} must be a finite number, got {value}")]
    NotFinite {
        /// The input's name as the user wrote it (a flag, a JSON path).
        name: String,
        /// The value given.
        value: f64,
    },
    /// Finite, but outside the allowed range.
    #[error("{name} must be {expected}, got {}", shown(*.value))]
    OutOfRange {
        /// The input's name as the user wrote it.
        name: String,
        /// The value given.
        value: f64,
        /// What was expected, as a phrase ("in [-1, 1]").
        expected: &'static str,
    },
    /// A direction with no direction: zero length (or too small to
    /// normalise).
    #[error("{name} must be a non-zero direction, got ({x}, {y}, {z})")]
    ZeroVector {
        /// The input's name as the user wrote it.
        name: String,
        /// The components given.
        x: f64,
        /// The components given.
        y: f64,
        /// The components given.
        z: f64,
    },
}

/// A number as an error message shows it: as Rust prints it, but in
/// scientific notation where that would run to more than a few digits
/// (`1e60`, not sixty-one of them).
pub fn shown(value: f64) -> String {
    let magnitude = value.abs();
    if magnitude != 0.0 && !(1e-5..1e16).contains(&magnitude) {
        format!("{value:e}")
    } else {
        format!("{value}")
    }
}

/// A finite number.
pub fn finite(name: &str, value: f64) -> Result<f64, DomainError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(DomainError::NotFinite {
            name: name.to_owned(),
            value,
        })
    }
}

fn in_range(name: &str, value: f64, ok: bool, expected: &'static str) -> Result<f64, DomainError> {
    finite(name, value)?;
    if ok {
        Ok(value)
    } else {
        Err(DomainError::OutOfRange {
            name: name.to_owned(),
            value,
            expected,
        })
    }
}

/// A cosine, in `[-1, 1]`.
pub fn cosine(name: &str, value: f64) -> Result<f64, DomainError> {
    in_range(name, value, (-1.0..=1.0).contains(&value), "in [-1, 1]")
}

/// The indices and extinction coefficients the laws are valid on in one
/// precision tier (crate conventions): they form fourth powers of them, which
/// must stay finite and normal. No material comes near either end.
#[derive(Clone, Debug, PartialEq)]
pub struct IndexRange {
    /// The valid indices, and positive extinction coefficients.
    pub range: core::ops::RangeInclusive<f64>,
    index: &'static str,
    extinction: &'static str,
}

/// The `f64` tier's: from 1e-50 to 1e50.
pub const INDEX_RANGE: IndexRange = IndexRange {
    range: 1e-50..=1e50,
    index: "a refractive index from 1e-50 to 1e50",
    extinction: "an extinction coefficient of 0 or from 1e-50 to 1e50",
};

/// The `f32` tier's: from 1e-9 to 1e9.
pub const INDEX_RANGE_F32: IndexRange = IndexRange {
    range: 1e-9..=1e9,
    index: "a refractive index from 1e-9 to 1e9 (the range of the f32 laws)",
    extinction: "an extinction coefficient of 0 or from 1e-9 to 1e9 (the range of the f32 laws)",
};

impl IndexRange {
    /// A real refractive index or relative index `eta`: positive, and in
    /// the range.
    pub fn refractive_index(&self, name: &str, value: f64) -> Result<f64, DomainError> {
        in_range(name, value, value > 0.0, "a positive refractive index")?;
        in_range(name, value, self.range.contains(&value), self.index)
    }

    /// An extinction coefficient `kappa`: zero, or in the range.
    pub fn extinction(&self, name: &str, value: f64) -> Result<f64, DomainError> {
        in_range(
            name,
            value,
            value >= 0.0,
            "a non-negative extinction coefficient",
        )?;
        let ok = value == 0.0 || self.range.contains(&value);
        in_range(name, value, ok, self.extinction)
    }
}

/// A real refractive index or relative index `eta` for the `f64` laws:
/// positive, and within [`INDEX_RANGE`].
pub fn refractive_index(name: &str, value: f64) -> Result<f64, DomainError> {
    INDEX_RANGE.refractive_index(name, value)
}

/// An extinction coefficient `kappa` for the `f64` laws: zero, or within
/// [`INDEX_RANGE`].
pub fn extinction(name: &str, value: f64) -> Result<f64, DomainError> {
    INDEX_RANGE.extinction(name, value)
}

/// A fraction (reflectance, albedo), in `[0, 1]`.
pub fn fraction(name: &str, value: f64) -> Result<f64, DomainError> {
    in_range(name, value, (0.0..=1.0).contains(&value), "in [0, 1]")
}

/// A non-negative quantity (radiance, a BRDF coefficient, an exponent).
pub fn non_negative(name: &str, value: f64) -> Result<f64, DomainError> {
    in_range(name, value, value >= 0.0, "non-negative")
}

/// An angle of incidence in radians, in `[0, π/2]`.
pub fn incidence_angle(name: &str, value: f64) -> Result<f64, DomainError> {
    in_range(
        name,
        value,
        (0.0..=core::f64::consts::FRAC_PI_2).contains(&value),
        "an angle in [0, π/2] rad",
    )
}

/// A direction given by a vector of any non-zero length.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Direction {
    /// The unit vector.
    pub unit: DVec3,
    /// The length of the vector as given; 1 if it was already unit length.
    pub given_length: f64,
}

impl Direction {
    /// Whether the given vector had to be normalised (its length differed
    /// from 1 by more than rounding).
    pub fn was_normalized(&self) -> bool {
        (self.given_length - 1.0).abs() > 4.0 * f64::EPSILON
    }
}

/// A direction: finite components, non-zero length; normalised.
pub fn direction(name: &str, v: DVec3) -> Result<Direction, DomainError> {
    for (axis, c) in ["x", "y", "z"].into_iter().zip(v.to_array()) {
        finite(&format!("{name}.{axis}"), c)?;
    }
    let zero = || DomainError::ZeroVector {
        name: name.to_owned(),
        x: v.x,
        y: v.y,
        z: v.z,
    };
    let unit = crate::Vector3::try_normalize(v).ok_or_else(zero)?;
    Ok(Direction {
        unit,
        given_length: v.length(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_name_the_input_and_the_expectation() {
        let cases: [(Result<f64, DomainError>, &str); 8] = [
            (cosine("cos_i", 1.5), "cos_i must be in [-1, 1], got 1.5"),
            (
                cosine("cos_i", f64::NAN),
                "cos_i must be a finite number, got NaN",
            ),
            (
                extinction("--kappa", -0.1),
                "--kappa must be a non-negative extinction coefficient, got -0.1",
            ),
            (
                refractive_index("eta", 0.0),
                "eta must be a positive refractive index, got 0",
            ),
            (fraction("kd", 1.2), "kd must be in [0, 1], got 1.2"),
            (
                refractive_index("--eta", 1e60),
                "--eta must be a refractive index from 1e-50 to 1e50, got 1e60",
            ),
            (
                extinction("--kappa", 1e-60),
                "--kappa must be an extinction coefficient of 0 or from 1e-50 to 1e50, got 1e-60",
            ),
            (
                finite("radiance", f64::INFINITY),
                "radiance must be a finite number, got inf",
            ),
        ];
        for (result, message) in cases {
            assert_eq!(result.unwrap_err().to_string(), message);
        }
    }

    #[test]
    fn directions_are_normalized_and_zero_vectors_rejected() {
        let d = direction("--light-dir", DVec3::new(0.0, 3.0, 4.0)).unwrap();
        assert_eq!(d.unit, DVec3::new(0.0, 0.6, 0.8));
        assert!(d.was_normalized() && d.given_length == 5.0);
        assert!(!direction("n", DVec3::Z).unwrap().was_normalized());
        assert_eq!(
            direction("--normal", DVec3::ZERO).unwrap_err().to_string(),
            "--normal must be a non-zero direction, got (0, 0, 0)"
        );
        assert_eq!(
            direction("n", DVec3::new(0.0, f64::NAN, 1.0))
                .unwrap_err()
                .to_string(),
            "n.y must be a finite number, got NaN"
        );
        assert!(direction("tiny", DVec3::splat(1e-320)).is_err());
    }
}
