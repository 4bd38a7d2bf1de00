//! Planar reflections and projected planar shadows: the two 4 × 4 matrices
//! of the slides, for any plane.
//!
//! Both slides' formulas were audited line by line against a derivation
//! (the matrices below are built as the slides build them and tested
//! against the direct geometric answer): the reflection matrix
//! `M = F⁻¹ S(1, −1, 1) F` with `F = R(n, (0, 1, 0)) T(−p)` is right; the
//! shadow matrix of a point light `l` onto `n · x + d = 0`, and its special
//! case for `y = 0`, are right, with the caveats the slides give (a shadow
//! also appears where none is cast), which [`Shadow`] names.

use glam::{DMat4, DQuat, DVec3, DVec4};

/// A plane `n · x + d = 0` with a unit normal `n`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    normal: DVec3,
    d: f64,
}

/// Why a plane could not be made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlaneError {
    /// The normal is zero, infinite or NaN: it has no direction.
    Normal,
    /// The point is not finite.
    Point,
}

impl Plane {
    /// The plane through `point` with normal along `normal` (normalised
    /// here, once).
    pub fn through(point: DVec3, normal: DVec3) -> Result<Self, PlaneError> {
        let normal = normal.try_normalize().ok_or(PlaneError::Normal)?;
        if !point.is_finite() {
            return Err(PlaneError::Point);
        }
        Ok(Self {
            normal,
            d: -normal.dot(point),
        })
    }

    /// The unit normal `n`.
    pub fn normal(&self) -> DVec3 {
        self.normal
    }

    /// `d` of `n · x + d = 0`.
    pub fn d(&self) -> f64 {
        self.d
    }

    /// The signed distance `n · x + d` of `x` from the plane.
    pub fn distance(&self, x: DVec3) -> f64 {
        self.normal.dot(x) + self.d
    }

    /// The plane's point nearest the origin, `−d n`.
    pub fn point(&self) -> DVec3 {
        -self.d * self.normal
    }
}

/// The slides' reflection matrix with its factors, as the slide builds it:
/// `M = F⁻¹ S(1, −1, 1) F`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reflection {
    /// `F = R(n, (0, 1, 0)) T(−p)`: takes the plane onto `y = 0`, its
    /// normal onto `+y`.
    pub to_floor: DMat4,
    /// `S(1, −1, 1)`: the mirror in `y = 0`.
    pub mirror: DMat4,
    /// `F⁻¹`: back from `y = 0` to the plane.
    pub from_floor: DMat4,
    /// `M = F⁻¹ S F`.
    pub matrix: DMat4,
}

/// The slides' reflection matrix of `plane` and its factors. Drawing a
/// scene's objects through `M` draws their mirror image in the plane; the
/// lights' positions and directions go through it too.
pub fn reflection(plane: &Plane) -> Reflection {
    // R(n, (0, 1, 0)): the shortest rotation taking n onto y (a half turn
    // when n = −y).
    let rotation = DQuat::from_rotation_arc(plane.normal, DVec3::Y);
    let to_floor = DMat4::from_quat(rotation) * DMat4::from_translation(-plane.point());
    let mirror = DMat4::from_scale(DVec3::new(1.0, -1.0, 1.0));
    let from_floor = to_floor.inverse();
    Reflection {
        to_floor,
        mirror,
        from_floor,
        matrix: from_floor * mirror * to_floor,
    }
}

/// The slides' reflection matrix of `plane`: `M = F⁻¹ S(1, −1, 1) F`, where
/// `F = R(n, (0, 1, 0)) T(−p)` moves the plane onto `y = 0` ([`reflection`]
/// hands back the factors too).
pub fn reflection_matrix(plane: &Plane) -> DMat4 {
    reflection(plane).matrix
}

/// Whether a point light at `light` lies on `plane`, `n · l + d = 0`, to
/// the rounding of computing `n · l + d` (64 ε of its terms' sizes). There
/// the shadow matrix is `−(l, 1)(n, d)ᵀ`, of rank 1: it sends every vertex
/// off the plane to the light itself and casts no shadow.
pub fn light_on_plane(light: DVec3, plane: &Plane) -> bool {
    let size = (plane.normal * light).abs().element_sum() + plane.d.abs();
    plane.distance(light).abs() <= 64.0 * f64::EPSILON * size
}

/// The slides' shadow matrix of a point light at `light` onto `plane`:
/// `M v` (homogeneous) is where the line from the light through `v` meets
/// the plane, `p = l − (d + n·l) / (n·(v − l)) (v − l)`.
pub fn shadow_matrix(light: DVec3, plane: &Plane) -> DMat4 {
    let (n, d) = (plane.normal, plane.d);
    let nl = n.dot(light);
    // Rows of the slides' matrix, written as columns of glam's.
    let row = |i: usize| {
        let l = light[i];
        let mut r = DVec4::new(-l * n.x, -l * n.y, -l * n.z, -l * d);
        r[i] += nl + d;
        r
    };
    DMat4::from_cols_array_2d(&[
        row(0).into(),
        row(1).into(),
        row(2).into(),
        [-n.x, -n.y, -n.z, nl],
    ])
    .transpose()
}

/// The slides' special case for the plane `y = 0`, written out as on the
/// slide.
pub fn shadow_matrix_y0(light: DVec3) -> DMat4 {
    let DVec3 { x, y, z } = light;
    DMat4::from_cols_array_2d(&[
        [y, -x, 0.0, 0.0],
        [0.0, 0.0, 0.0, 0.0],
        [0.0, -z, y, 0.0],
        [0.0, -1.0, 0.0, y],
    ])
    .transpose()
}

/// What projecting a vertex from a point light onto a plane gives, with the
/// slides' caveats as outcomes: the matrix projects every vertex, but only
/// one between the light and the plane casts a shadow there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shadow {
    /// The vertex lies between the light and the plane: its shadow is here.
    Cast(DVec3),
    /// The vertex lies beyond the plane, seen from the light: the matrix
    /// still puts a point on the plane, but no shadow falls there.
    BeyondPlane(DVec3),
    /// The plane lies behind the light, seen from the vertex: the matrix
    /// puts a point on the plane on the far side of the light (an
    /// "anti-shadow").
    BehindLight(DVec3),
    /// The line from the light through the vertex is parallel to the plane
    /// (or the vertex is the light): it never meets it.
    Parallel,
    /// The light lies on the plane ([`light_on_plane`]): the matrix is
    /// singular and every line from the light meets the plane at the light.
    LightOnPlane,
}

/// Where the shadow of `vertex` from a point light at `light` falls on
/// `plane`, by the shadow matrix, with the outcome decided from the ray
/// parameter `t` of `light + t (vertex − light)` at the plane: `t > 1`
/// casts, `0 < t ≤ 1` is beyond the plane, `t ≤ 0` behind the light; a
/// light on the plane is [`Shadow::LightOnPlane`] whatever the vertex.
///
/// Assumes `light` and `vertex` finite, and small enough that the matrix
/// product stays in `f64`: a NaN, or a product that overflowed, reads as
/// [`Shadow::Parallel`]. Check them where they enter, as `optics
/// shadow-matrix` does.
pub fn project_shadow(light: DVec3, plane: &Plane, vertex: DVec3) -> Shadow {
    if light_on_plane(light, plane) {
        return Shadow::LightOnPlane;
    }
    let towards = vertex - light;
    let along = plane.normal.dot(towards);
    let h = shadow_matrix(light, plane) * vertex.extend(1.0);
    if along == 0.0 || h.w == 0.0 || !h.is_finite() {
        return Shadow::Parallel;
    }
    let p = h.truncate() / h.w;
    let t = -plane.distance(light) / along;
    if t > 1.0 {
        Shadow::Cast(p)
    } else if t > 0.0 {
        Shadow::BeyondPlane(p)
    } else {
        Shadow::BehindLight(p)
    }
}

#[cfg(test)]
mod tests;
