//! The infinite plane, visible from both sides.

use glam::Vec3;
use radiometry::{Real, Vector3};

use super::ray::{Hit, Ray};

/// An infinite plane, visible from both sides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane<V: Vector3 = Vec3> {
    /// A point on the plane, m.
    pub point: V,
    /// Unit normal, as declared.
    pub normal: V,
    /// Material index.
    pub material: u32,
}

impl<V: Vector3> Plane<V> {
    /// The hit in `(t_min, ray.t_max)` from either side; rays parallel to
    /// the plane (including those lying in it) miss.
    pub fn intersect(&self, ray: &Ray<V>, t_min: V::Scalar) -> Option<Hit<V>> {
        let t = self.parameter(ray, t_min, ray.t_max)?;
        let (point, error) = self.surface_point(ray, t);
        Some(Hit {
            t,
            point,
            error,
            normal: self.normal,
            shading: self.normal,
            two_sided: true,
            material: self.material,
            object: 0,
        })
    }

    /// The ray parameter of the plane in `(t_min, t_max)`, or `None`.
    pub(super) fn parameter(
        &self,
        ray: &Ray<V>,
        t_min: V::Scalar,
        t_max: V::Scalar,
    ) -> Option<V::Scalar> {
        let denom = self.normal.dot(ray.direction);
        if denom == V::Scalar::lit(0.0) {
            return None;
        }
        let t = (self.point - ray.origin).dot(self.normal) / denom;
        (t > t_min && t < t_max).then_some(t)
    }

    /// The point at `t` re-projected onto the plane along its normal, and
    /// the bound on its error.
    pub(super) fn surface_point(&self, ray: &Ray<V>, t: V::Scalar) -> (V, V::Scalar) {
        let p = ray.at(t);
        // Re-projection onto the plane along its normal.
        let point = p - self.normal * (p - self.point).dot(self.normal);
        let error = V::Scalar::gamma(8) * point.abs().max(self.point.abs()).max_element();
        (point, error)
    }
}

impl Plane {
    /// This plane at tier `V`, its numbers widened exactly.
    pub fn at_tier<V: Vector3>(&self) -> Plane<V> {
        Plane {
            point: V::of_f32(self.point),
            normal: V::of_f32(self.normal),
            material: self.material,
        }
    }
}
