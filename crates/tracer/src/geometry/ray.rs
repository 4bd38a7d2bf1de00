//! A ray and where it meets a surface: the hit point, its error bound and
//! the normals on the side the ray came from.

use glam::Vec3;
use num_traits::Float;
use radiometry::{Real, Vector3};

/// A ray: `origin + t · direction` for `t` in `(0, t_max)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray<V: Vector3 = Vec3> {
    /// Where the ray starts, m.
    pub origin: V,
    /// Unit direction of travel.
    pub direction: V,
    /// The ray ends here (a point light's distance; infinity otherwise).
    pub t_max: V::Scalar,
}

impl<V: Vector3> Ray<V> {
    /// An unbounded ray.
    pub fn new(origin: V, direction: V) -> Self {
        Ray {
            origin,
            direction,
            t_max: V::Scalar::infinity(),
        }
    }

    /// The point at parameter `t`.
    pub fn at(&self, t: V::Scalar) -> V {
        self.origin + self.direction * t
    }
}

/// Where a ray meets a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit<V: Vector3 = Vec3> {
    /// Ray parameter of the hit, m (the direction is a unit vector).
    pub t: V::Scalar,
    /// The hit point, re-projected onto the surface.
    pub point: V,
    /// Bound on the absolute rounding error of each component of `point`, m.
    pub error: V::Scalar,
    /// Unit normal. For a sphere it points outside (so `dot(normal,
    /// direction) > 0` means the ray arrived from inside); for the two-sided
    /// plane and tube it is the normal as declared, whichever side was hit.
    /// The geometric normal: offsets, sides and visibility follow it.
    pub normal: V,
    /// The unit normal shading uses, on the same side as `normal`: `normal`
    /// bent by the object's bump map ([`crate::bump`]), or `normal` itself.
    pub shading: V,
    /// Whether the surface has no inside (plane, tube): shading uses the
    /// side of the normal the ray came from.
    pub two_sided: bool,
    /// Index of the material.
    pub material: u32,
    /// Index of the object.
    pub object: u32,
}

impl<V: Vector3> Hit<V> {
    /// Whether a ray along `ray_direction` met a two-sided surface from
    /// behind its declared normal: decided by the geometric normal, once
    /// for both of the normals below.
    fn met_from_behind(&self, ray_direction: V) -> bool {
        self.two_sided && self.normal.dot(ray_direction) > V::Scalar::lit(0.0)
    }

    /// The geometric normal on the side the ray came from, for two-sided
    /// surfaces; the outward normal for closed ones. Secondary rays start
    /// off the surface along it, and a light below it is below the horizon.
    pub fn facing_normal(&self, ray_direction: V) -> V {
        if self.met_from_behind(ray_direction) {
            -self.normal
        } else {
            self.normal
        }
    }

    /// The shading normal on the side [`Hit::facing_normal`] chose: what
    /// the BRDF and the cosines of the lights see. Without a bump map it
    /// is the facing normal itself.
    pub fn shading_normal(&self, ray_direction: V) -> V {
        if self.met_from_behind(ray_direction) {
            -self.shading
        } else {
            self.shading
        }
    }
}
