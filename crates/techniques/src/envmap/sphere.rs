//! The sphere map: the picture of a mirrored unit sphere seen from far
//! along `+z` (orthographically, looking down `−z`); a direction is looked
//! up where the sphere's normal reflects the view into it.
//!
//! The slides (`001`, lines 143–180), in the eye frame of the module
//! conventions: the normal `n` at which the view is reflected into `r` lies
//! half way between `r` and the direction towards the viewer
//! `e = (0, 0, 1)`,
//!
//! `m = √(r_x² + r_y² + (r_z + 1)²) = |r + e|`,
//! `n = (r_x / m, r_y / m, (r_z + 1) / m)`,
//!
//! and the texel is where that normal appears in the picture,
//! `u = (n_x + 1) / 2`, `v = (n_y + 1) / 2` (OpenGL's `SPHERE_MAP`
//! texture-coordinate generation, OpenGL 2.1 §2.11.4, whose `m` is twice
//! the slides'). Audited: the formula is right. Since `|r| = 1`,
//! `m² = 2 (1 + r_z)`, so `m = 2 n_z`.
//!
//! The way back is the law of reflection,
//! [`radiometry::specular::reflect`]: `r = 2 (n · e) n − e`, with
//! `n_z = √(1 − n_x² − n_y²)` on the visible half of the sphere.
//!
//! Every direction has a texel but one: `r = (0, 0, −1)`, straight away
//! from the viewer, where `m = 0`. It is reflected at the sphere's
//! silhouette, so the whole rim of the picture stores it: the outcome
//! [`SphereTexel::Rim`], not a NaN. Directions behind the sphere
//! (`r_z < 0`) fill the ring `1/√2 < |(2u − 1, 2v − 1)| < 1`, half of the
//! disc's area; near the rim a step of one rounding in `(u, v)` turns the
//! direction by about `ε / n_z`, which is the map's resolution there, not
//! an error of the formulas.

use glam::DVec3;
use radiometry::domain;
use radiometry::specular::reflect;

use super::direction::Direction;
use super::texel::{unit_square, TexelError};

/// The direction towards the viewer, `e = (0, 0, 1)`.
pub const TOWARDS_VIEWER: DVec3 = DVec3::Z;

/// Where a direction is stored in the sphere map.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SphereTexel {
    /// A point of the sphere's picture, with the normal that reflects the
    /// view into the direction.
    Disc(DiscTexel),
    /// `r = (0, 0, −1)`: `m = 0` and `n = (r + e) / m` has no value; the
    /// view grazes the sphere's silhouette there, and every point of the
    /// picture's rim stores this one direction.
    Rim,
}

/// A point of the sphere map's picture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiscTexel {
    u: f64,
    v: f64,
    m: f64,
    normal: DVec3,
}

impl DiscTexel {
    /// `u = (n_x + 1) / 2`.
    pub fn u(&self) -> f64 {
        self.u
    }

    /// `v = (n_y + 1) / 2`.
    pub fn v(&self) -> f64 {
        self.v
    }

    /// The slides' `m = |r + e| = 2 n_z`.
    pub fn m(&self) -> f64 {
        self.m
    }

    /// The sphere's unit normal `n = (r + e) / m` at this point.
    pub fn normal(&self) -> DVec3 {
        self.normal
    }
}

impl SphereTexel {
    /// The texel `r` is looked up at.
    pub fn from_direction(r: Direction) -> Self {
        let r = r.get();
        // r + e is zero only at r = −e; else its length m and direction n
        // come from the radiometry crate's scaled normalisation, which
        // holds for r_x = 1e-300 too, where the squares underflow.
        match domain::direction("r + e", r + TOWARDS_VIEWER) {
            // n_z = (r_z + 1) / m, taken as m / 2 (m² = 2 (1 + r_z)): the
            // same number, but it neither underflows where m is tiny nor
            // carries the rounding of r_z, relatively large in r_z + 1
            // near the rim.
            Ok(half) => {
                let m = half.given_length;
                Self::disc(DVec3::new(half.unit.x, half.unit.y, m / 2.0), m)
            }
            Err(_) => SphereTexel::Rim,
        }
    }

    /// The texel at `(u, v)`, inside the picture's disc
    /// `(2u − 1)² + (2v − 1)² ≤ 1` (up to four roundings beyond it, which
    /// a texel computed on the rim may carry); [`SphereTexel::Rim`] on
    /// the rim.
    pub fn from_uv(u: f64, v: f64) -> Result<Self, TexelError> {
        let (u, v) = unit_square(u, v)?;
        let (nx, ny) = (2.0 * u - 1.0, 2.0 * v - 1.0);
        let across = nx * nx + ny * ny;
        if across > 1.0 + 4.0 * f64::EPSILON {
            return Err(TexelError::OutsideDisc { u, v });
        }
        let nz = (1.0 - across).max(0.0).sqrt();
        if nz == 0.0 {
            return Ok(SphereTexel::Rim);
        }
        let normal = DVec3::new(nx, ny, nz);
        Ok(Self::disc(normal, 2.0 * nz))
    }

    fn disc(normal: DVec3, m: f64) -> Self {
        SphereTexel::Disc(DiscTexel {
            u: (normal.x + 1.0) / 2.0,
            v: (normal.y + 1.0) / 2.0,
            m,
            normal,
        })
    }

    /// The direction stored at this texel: the view reflected about the
    /// normal, `2 (n · e) n − e`; `(0, 0, −1)` on the rim.
    pub fn direction(&self) -> Direction {
        match self {
            SphereTexel::Disc(texel) => {
                Direction::from_built(reflect(TOWARDS_VIEWER, texel.normal))
            }
            SphereTexel::Rim => Direction::from_built(-TOWARDS_VIEWER),
        }
    }
}
