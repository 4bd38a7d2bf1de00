//! The cube map: the face a direction's major axis points at, and the
//! texture coordinates `(u, v)` in `[0, 1]` on that face.
//!
//! The slides (`001`, lines 61–66): the component of largest magnitude
//! selects the face ("(−3.2, 5.1, −8.4) selects −Z"); the other two,
//! divided by its magnitude and mapped to `[0, 1]`, are the coordinates on
//! the face. The slides do not say which of the two is `u` nor their
//! signs; this module takes OpenGL's, the convention of the `samplerCUBE`
//! lookups the slides' Cg code makes: the OpenGL 4.6 core specification,
//! §8.13.1 "Cube Map Texture Selection", Table 8.19,
//!
//! | major axis | face | `s_c` | `t_c` | `m_a` |
//! |---|---|---|---|---|
//! | `+r_x` | `+X` | `−r_z` | `−r_y` | `r_x` |
//! | `−r_x` | `−X` | `r_z` | `−r_y` | `r_x` |
//! | `+r_y` | `+Y` | `r_x` | `r_z` | `r_y` |
//! | `−r_y` | `−Y` | `r_x` | `−r_z` | `r_y` |
//! | `+r_z` | `+Z` | `r_x` | `−r_y` | `r_z` |
//! | `−r_z` | `−Z` | `−r_x` | `−r_y` | `r_z` |
//!
//! with `u = (s_c / |m_a| + 1) / 2`, `v = (t_c / |m_a| + 1) / 2` (the
//! specification's `s`, `t`). [`Face::frame`] is this table, the one place
//! it is written; both ways round read it.
//!
//! Ties, decided once: the table does not say which face a direction on a
//! cube edge or corner (two or three components of equal magnitude)
//! belongs to. Here `z` wins over `y` and `y` over `x`. Either face would
//! give the direction back, since the edge lies on both (at `u` or `v` 0
//! or 1); the decision only makes the answer one.

use glam::DVec3;

use super::direction::Direction;
use super::texel::{unit_square, TexelError};

/// A face of the cube, named by the axis direction it is centred on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Face {
    /// `+X` (OpenGL's `TEXTURE_CUBE_MAP_POSITIVE_X`).
    PositiveX,
    /// `−X`.
    NegativeX,
    /// `+Y`.
    PositiveY,
    /// `−Y`.
    NegativeY,
    /// `+Z`.
    PositiveZ,
    /// `−Z`.
    NegativeZ,
}

/// One row of Table 8.19: the major axis and its sign, and which signed
/// components are `s_c` and `t_c`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// The major axis, 0 for `x`, 1 for `y`, 2 for `z`.
    pub axis: usize,
    /// The sign of the major component on this face, ±1.
    pub sign: f64,
    /// `s_c = s_sign · r[s_axis]`.
    pub s_axis: usize,
    /// The sign of `s_c`, ±1.
    pub s_sign: f64,
    /// `t_c = t_sign · r[t_axis]`.
    pub t_axis: usize,
    /// The sign of `t_c`, ±1.
    pub t_sign: f64,
}

impl Face {
    /// The six faces in OpenGL's order (`+X, −X, +Y, −Y, +Z, −Z`).
    pub const ALL: [Face; 6] = [
        Face::PositiveX,
        Face::NegativeX,
        Face::PositiveY,
        Face::NegativeY,
        Face::PositiveZ,
        Face::NegativeZ,
    ];

    /// The face's row of Table 8.19.
    pub fn frame(self) -> Frame {
        let row = |axis, sign, (s_axis, s_sign), (t_axis, t_sign)| Frame {
            axis,
            sign,
            s_axis,
            s_sign,
            t_axis,
            t_sign,
        };
        let (x, y, z) = (0, 1, 2);
        match self {
            Face::PositiveX => row(x, 1.0, (z, -1.0), (y, -1.0)),
            Face::NegativeX => row(x, -1.0, (z, 1.0), (y, -1.0)),
            Face::PositiveY => row(y, 1.0, (x, 1.0), (z, 1.0)),
            Face::NegativeY => row(y, -1.0, (x, 1.0), (z, -1.0)),
            Face::PositiveZ => row(z, 1.0, (x, 1.0), (y, -1.0)),
            Face::NegativeZ => row(z, -1.0, (x, -1.0), (y, -1.0)),
        }
    }

    /// The face `r` is looked up on: the axis of its largest component
    /// (ties: `z` over `y` over `x`), on the side of that component's
    /// sign.
    pub fn of(r: Direction) -> Self {
        let r = r.get();
        let a = r.abs();
        if a.z >= a.x && a.z >= a.y {
            if r.z >= 0.0 {
                Face::PositiveZ
            } else {
                Face::NegativeZ
            }
        } else if a.y >= a.x {
            if r.y >= 0.0 {
                Face::PositiveY
            } else {
                Face::NegativeY
            }
        } else if r.x >= 0.0 {
            Face::PositiveX
        } else {
            Face::NegativeX
        }
    }

    /// `+X`, …, `−Z`, as the slides and the specification write them.
    pub fn name(self) -> &'static str {
        match self {
            Face::PositiveX => "+X",
            Face::NegativeX => "-X",
            Face::PositiveY => "+Y",
            Face::NegativeY => "-Y",
            Face::PositiveZ => "+Z",
            Face::NegativeZ => "-Z",
        }
    }
}

/// A texel of the cube map: a face and `(u, v)` on it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CubeTexel {
    face: Face,
    u: f64,
    v: f64,
}

impl CubeTexel {
    /// The face and texel `r` is looked up at.
    pub fn from_direction(r: Direction) -> Self {
        let face = Face::of(r);
        let f = face.frame();
        let r = r.get();
        // |m_a| is the largest magnitude, so each ratio lies in [−1, 1].
        let major = r[f.axis].abs();
        let s = f.s_sign * r[f.s_axis] / major;
        let t = f.t_sign * r[f.t_axis] / major;
        Self {
            face,
            u: (s + 1.0) / 2.0,
            v: (t + 1.0) / 2.0,
        }
    }

    /// The texel at `(u, v)`, each in `[0, 1]`, on `face`.
    pub fn from_uv(face: Face, u: f64, v: f64) -> Result<Self, TexelError> {
        let (u, v) = unit_square(u, v)?;
        Ok(Self { face, u, v })
    }

    /// The face.
    pub fn face(&self) -> Face {
        self.face
    }

    /// `u = (s_c / |m_a| + 1) / 2`.
    pub fn u(&self) -> f64 {
        self.u
    }

    /// `v = (t_c / |m_a| + 1) / 2`.
    pub fn v(&self) -> f64 {
        self.v
    }

    /// The direction stored at this texel: the point `(s_c, t_c)` of the
    /// face at distance 1 along its axis, read back through the table and
    /// normalised; the inverse of [`CubeTexel::from_direction`].
    pub fn direction(&self) -> Direction {
        let f = self.face.frame();
        let mut r = DVec3::ZERO;
        r[f.axis] = f.sign;
        // s_sign² = 1: the sign that made s_c from the component unmakes it.
        r[f.s_axis] = f.s_sign * (2.0 * self.u - 1.0);
        r[f.t_axis] = f.t_sign * (2.0 * self.v - 1.0);
        Direction::from_built(r)
    }
}
