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
mod direction;
pub mod lat_long;
pub mod sphere;
mod texel;

pub use direction::{Direction, DirectionError};
pub use texel::TexelError;

#[cfg(test)]
mod tests;
