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
        /// What was expected.
        expected: Expected,
    },
    /// A direction with no direction: every component zero.
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

impl DomainError {
    /// The input's name as the user wrote it (a flag, a JSON path).
    pub fn name(&self) -> &str {
        match self {
            DomainError::NotFinite { name, .. }
            | DomainError::OutOfRange { name, .. }
            | DomainError::ZeroVector { name, .. } => name,
        }
    }
}

/// What an input outside its range should have been: the identity of the
/// expectation, whose English phrase is its `Display` ("in [-1, 1]").
/// Translations match on it, so a new expectation without one stops the
/// build.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Expected {
    /// A cosine, in `[-1, 1]`.
    Cosine,
    /// A fraction, in `[0, 1]`.
    Fraction,
    /// Zero or more.
    NonNegative,
    /// An angle of incidence, in `[0, π/2]` rad.
    IncidenceAngle,
    /// A refractive index greater than zero.
    PositiveIndex,
    /// An extinction coefficient of zero or more.
    NonNegativeExtinction,
    /// A refractive index within [`INDEX_RANGE`].
    IndexInRange,
    /// An extinction coefficient of zero or within [`INDEX_RANGE`].
    ExtinctionInRange,
    /// A refractive index within [`INDEX_RANGE_F32`].
    IndexInRangeF32,
    /// An extinction coefficient of zero or within [`INDEX_RANGE_F32`].
    ExtinctionInRangeF32,
    /// A number that stays finite in `f32` (|x| < 3.4e38).
    WithinF32,
    /// A positive number that stays positive and finite in `f32`.
    PositiveF32,
}

impl Expected {
    /// Every expectation, in declaration order.
    pub const ALL: [Expected; 12] = [
        Expected::Cosine,
        Expected::Fraction,
        Expected::NonNegative,
        Expected::IncidenceAngle,
        Expected::PositiveIndex,
        Expected::NonNegativeExtinction,
        Expected::IndexInRange,
        Expected::ExtinctionInRange,
        Expected::IndexInRangeF32,
        Expected::ExtinctionInRangeF32,
        Expected::WithinF32,
        Expected::PositiveF32,
    ];

    /// The position in [`Expected::ALL`]; an exhaustive match, so that a new
    /// expectation must be given a place in the list.
    pub const fn ordinal(self) -> usize {
        match self {
            Expected::Cosine => 0,
            Expected::Fraction => 1,
            Expected::NonNegative => 2,
            Expected::IncidenceAngle => 3,
            Expected::PositiveIndex => 4,
            Expected::NonNegativeExtinction => 5,
            Expected::IndexInRange => 6,
            Expected::ExtinctionInRange => 7,
            Expected::IndexInRangeF32 => 8,
            Expected::ExtinctionInRangeF32 => 9,
            Expected::WithinF32 => 10,
            Expected::PositiveF32 => 11,
        }
    }

    /// The index range the expectation names, if it names one.
    pub fn index_range(self) -> Option<&'static IndexRange> {
        match self {
            Expected::IndexInRange | Expected::ExtinctionInRange => Some(&INDEX_RANGE),
            Expected::IndexInRangeF32 | Expected::ExtinctionInRangeF32 => Some(&INDEX_RANGE_F32),
            Expected::Cosine
            | Expected::Fraction
            | Expected::NonNegative
            | Expected::IncidenceAngle
            | Expected::PositiveIndex
            | Expected::NonNegativeExtinction
            | Expected::WithinF32
            | Expected::PositiveF32 => None,
        }
    }
}

impl core::fmt::Display for Expected {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let ends = self.index_range().map(IndexRange::ends_text);
        let (low, high) = ends.unwrap_or_default();
        match self {
            Expected::Cosine => write!(f, "in [-1, 1]"),
            Expected::Fraction => write!(f, "in [0, 1]"),
            Expected::NonNegative => write!(f, "non-negative"),
            Expected::IncidenceAngle => write!(f, "an angle in [0, π/2] rad"),
            Expected::PositiveIndex => write!(f, "a positive refractive index"),
            Expected::NonNegativeExtinction => write!(f, "a non-negative extinction coefficient"),
            Expected::IndexInRange => write!(f, "a refractive index from {low} to {high}"),
            Expected::ExtinctionInRange => {
                write!(f, "an extinction coefficient of 0 or from {low} to {high}")
            }
            Expected::IndexInRangeF32 => write!(
                f,
                "a refractive index from {low} to {high} (the range of the f32 laws)"
            ),
            Expected::ExtinctionInRangeF32 => write!(
                f,
                "an extinction coefficient of 0 or from {low} to {high} (the range of the f32 laws)"
            ),
            Expected::WithinF32 => write!(f, "within f32 range (|x| < 3.4e38)"),
            Expected::PositiveF32 => write!(f, "positive (and representable in f32)"),
        }
    }
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

fn in_range(name: &str, value: f64, ok: bool, expected: Expected) -> Result<f64, DomainError> {
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
    in_range(name, value, (-1.0..=1.0).contains(&value), Expected::Cosine)
}

/// The indices and extinction coefficients the laws are valid on in one
/// precision tier (crate conventions): they form fourth powers of them, which
/// must stay finite and normal. No material comes near either end.
#[derive(Clone, Debug, PartialEq)]
pub struct IndexRange {
    /// The valid indices, and positive extinction coefficients.
    pub range: core::ops::RangeInclusive<f64>,
    index: Expected,
    extinction: Expected,
}

/// The `f64` tier's: from 1e-50 to 1e50.
pub const INDEX_RANGE: IndexRange = IndexRange {
    range: 1e-50..=1e50,
    index: Expected::IndexInRange,
    extinction: Expected::ExtinctionInRange,
};

/// The `f32` tier's: from 1e-9 to 1e9.
pub const INDEX_RANGE_F32: IndexRange = IndexRange {
    range: 1e-9..=1e9,
    index: Expected::IndexInRangeF32,
    extinction: Expected::ExtinctionInRangeF32,
};

impl IndexRange {
    /// The two ends as messages write them: `1e-50`, `1e50`.
    pub fn ends_text(&self) -> (String, String) {
        (
            format!("{:e}", self.range.start()),
            format!("{:e}", self.range.end()),
        )
    }

    /// A real refractive index or relative index `eta`: positive, and in
    /// the range.
    pub fn refractive_index(&self, name: &str, value: f64) -> Result<f64, DomainError> {
        in_range(name, value, value > 0.0, Expected::PositiveIndex)?;
        in_range(name, value, self.range.contains(&value), self.index)
    }

    /// An extinction coefficient `kappa`: zero, or in the range.
    pub fn extinction(&self, name: &str, value: f64) -> Result<f64, DomainError> {
        in_range(name, value, value >= 0.0, Expected::NonNegativeExtinction)?;
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
    in_range(
        name,
        value,
        (0.0..=1.0).contains(&value),
        Expected::Fraction,
    )
}

/// A non-negative quantity (radiance, a BRDF coefficient, an exponent).
pub fn non_negative(name: &str, value: f64) -> Result<f64, DomainError> {
    in_range(name, value, value >= 0.0, Expected::NonNegative)
}

/// An angle of incidence in radians, in `[0, π/2]`.
pub fn incidence_angle(name: &str, value: f64) -> Result<f64, DomainError> {
    in_range(
        name,
        value,
        (0.0..=core::f64::consts::FRAC_PI_2).contains(&value),
        Expected::IncidenceAngle,
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

/// A direction: finite components, not all zero; normalised.
///
/// Every such vector has a direction, however short or long: the vector is
/// first scaled by a power of two that brings its largest component near 1
/// (as `hypot` scales), so that the squared length neither underflows
/// (`(0, 3e-162, 4e-162)`) nor overflows (`(0, 3e200, 4e200)`). A power of
/// two scales exactly, so a vector whose squares were representable gives
/// the same unit vector, bit for bit, as dividing it by its length.
pub fn direction(name: &str, v: DVec3) -> Result<Direction, DomainError> {
    for (axis, c) in ["x", "y", "z"].into_iter().zip(v.to_array()) {
        finite(&format!("{name}.{axis}"), c)?;
    }
    let largest = v.abs().max_element();
    if largest == 0.0 {
        return Err(DomainError::ZeroVector {
            name: name.to_owned(),
            x: v.x,
            y: v.y,
            z: v.z,
        });
    }
    // 2^-k with k the exponent of the largest component, applied in two
    // halves: 2^-k alone is not representable for a subnormal component.
    let k = largest.log2().floor() as i32;
    let (down, down_rest) = (2f64.powi(-k / 2), 2f64.powi(-k + k / 2));
    let scaled = v * down * down_rest;
    let length = crate::Vector3::length(scaled);
    let [x, y, z] = scaled.to_array();
    Ok(Direction {
        unit: DVec3::new(x / length, y / length, z / length),
        given_length: length / down / down_rest,
    })
}

#[cfg(test)]
mod tests;
