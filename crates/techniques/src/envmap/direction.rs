//! A direction of the maps: any finite, non-zero vector, normalised once,
//! where it enters.

use glam::DVec3;
use radiometry::domain::{self, DomainError};

/// A unit direction, finite and normalised once, where it entered.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Direction(DVec3);

/// Why a vector is not a direction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DirectionError {
    /// Every component is zero: the vector points nowhere.
    Zero,
    /// A component is NaN or infinite.
    NotFinite,
}

impl Direction {
    /// The direction of `v`, of any finite non-zero length (normalised by
    /// [`radiometry::domain::direction`], which scales first, so that
    /// `(1e-300, 0, 0)` and `(1e300, 1e300, 0)` have one too).
    pub fn new(v: DVec3) -> Result<Self, DirectionError> {
        match domain::direction("direction", v) {
            Ok(d) => Ok(Self(d.unit)),
            Err(DomainError::ZeroVector { .. }) => Err(DirectionError::Zero),
            Err(DomainError::NotFinite { .. } | DomainError::OutOfRange { .. }) => {
                Err(DirectionError::NotFinite)
            }
        }
    }

    /// The unit vector.
    pub fn get(self) -> DVec3 {
        self.0
    }

    /// A direction a map built on its way back: a vector whose largest
    /// component is near 1 (a point on a cube face, a reflected unit
    /// vector), so plain normalisation neither underflows nor overflows.
    pub(super) fn from_built(v: DVec3) -> Self {
        Self(v.normalize())
    }
}

impl From<radiometry::domain::Direction> for Direction {
    /// The direction the radiometry crate validated where it entered (an
    /// `optics` flag): its unit vector, not checked again.
    fn from(d: radiometry::domain::Direction) -> Self {
        Self(d.unit)
    }
}
