//! Environment mapping: a reflected direction to the texture coordinate
//! that stores the far surroundings seen along it, and back, for the
//! slides' three maps (`001`, "Környezet leképezés").
//!
//! | map | module | texel |
//! |---|---|---|
//! | latitude–longitude | [`lat_long`] | `(u, v)` from the angles `(φ, ρ)` |
//! | cube | [`cube`] | a [`cube::Face`] and `(u, v)` on it |
//! | sphere | [`sphere`] | `(u, v)` in the disc of a mirrored sphere's picture, or the rim |
//!
//! # Conventions
//!
//! - **A direction points away from the reflecting point**, into the
//!   surroundings: the reflected vector `r` of the slides, as the radiometry
//!   crate's directions point away from the surface. It is given in the
//!   map's own frame; for the sphere map that frame is the eye's, in which
//!   the viewer looks down `−z` and the direction towards the viewer is
//!   `e = (0, 0, 1)` (OpenGL's eye space, the slides' "(0, 0, 1)").
//! - **Any finite, non-zero vector is a direction.** It is normalised once,
//!   where it enters, by [`Direction::new`]; every map takes a
//!   [`Direction`] and never checks it again.
//! - **Texture coordinates `(u, v)` lie in `[0, 1]`**; each map says which
//!   edge is which and what its seams and singular points are. A texel
//!   given back (not computed here) is checked once, by its map's
//!   `from_uv`, with a [`TexelError`] naming the coordinate.
//! - Every map is a bijection away from its seams, and the way back is
//!   exact there too: a direction on a seam, at a cube edge or corner or at
//!   a pole, maps to one texel, decided as its map documents, and that
//!   texel gives the direction back. The only direction without a texel of
//!   its own is the sphere map's `(0, 0, −1)`, which is an outcome,
//!   [`sphere::SphereTexel::Rim`].
//!
//! ```
//! use glam::DVec3;
//! use techniques::envmap::{cube, Direction};
//!
//! // The slides' example: (−3.2, 5.1, −8.4) is looked up on the −Z face.
//! let r = Direction::new(DVec3::new(-3.2, 5.1, -8.4)).unwrap();
//! let texel = cube::CubeTexel::from_direction(r);
//! assert_eq!(texel.face(), cube::Face::NegativeZ);
//! assert!((texel.direction().get() - r.get()).length() < 1e-15);
//! ```

pub mod cube;
pub mod lat_long;
pub mod sphere;

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
    fn from_built(v: DVec3) -> Self {
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

/// Why a texel given back is not one of a map's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TexelError {
    /// `u` is not a finite number in `[0, 1]`; the value given.
    U(f64),
    /// `v` is not a finite number in `[0, 1]`; the value given.
    V(f64),
    /// `(u, v)` lies outside the sphere map's disc
    /// `(2u − 1)² + (2v − 1)² ≤ 1`.
    OutsideDisc {
        /// `u` given.
        u: f64,
        /// `v` given.
        v: f64,
    },
}

/// `(u, v)` checked to lie in the unit square, once, for every map.
fn unit_square(u: f64, v: f64) -> Result<(f64, f64), TexelError> {
    if !(0.0..=1.0).contains(&u) {
        return Err(TexelError::U(u));
    }
    if !(0.0..=1.0).contains(&v) {
        return Err(TexelError::V(v));
    }
    Ok((u, v))
}

#[cfg(test)]
mod tests;
