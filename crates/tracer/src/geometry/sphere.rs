//! The sphere: its ray roots, computed stably, and its hit re-projected
//! onto the surface.

use glam::Vec3;
use num_traits::Float;
use radiometry::{Real, Vector3};

use super::ray::{Hit, Ray};

/// A sphere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere<V: Vector3 = Vec3> {
    /// Centre, m.
    pub center: V,
    /// Radius, m, > 0.
    pub radius: V::Scalar,
    /// Material index.
    pub material: u32,
}

/// The two roots `t0 ≤ t1` of `|o + t d − c|² = r²` for a unit `d`, or `None`.
pub type Roots<T = f32> = Option<(T, T)>;

impl<V: Vector3> Sphere<V> {
    /// The roots of the ray-sphere quadratic, computed stably.
    ///
    /// With `f = o − c` and unit `d`, the textbook discriminant
    /// `b² − 4ac = 4((f·d)² − (f·f − r²))` subtracts two numbers of size
    /// `|f|²` to get one of size `r²`: for a sphere small against its
    /// distance, `f32` keeps none of its digits (nor `f64`, further out). Here the discriminant is
    /// `r² − |f − (f·d) d|²`, the squared half-chord from the distance of
    /// the centre to the line (Haines et al., "Precision Improvements for
    /// Ray/Sphere Intersection", *Ray Tracing Gems* ch. 7), and the smaller
    /// root avoids cancelling `−b ± √Δ` by taking `q = −(b + sign(b)√Δ)`,
    /// `t = c/q` and `t = q` (Press et al., *Numerical Recipes* §5.6).
    #[inline]
    pub fn roots(&self, ray: &Ray<V>) -> Roots<V::Scalar> {
        let f = ray.origin - self.center;
        let b = f.dot(ray.direction);
        let perp = f - ray.direction * b;
        let r2 = self.radius * self.radius;
        let disc = r2 - perp.dot(perp);
        let zero = V::Scalar::lit(0.0);
        if !(disc >= zero) {
            return None;
        }
        let c = f.dot(f) - r2;
        let q = -(b + disc.sqrt().copysign(b));
        let (t0, t1) = if q == zero { (zero, zero) } else { (c / q, q) };
        Some(if t0 <= t1 { (t0, t1) } else { (t1, t0) })
    }

    /// The roots as the course's shader computes them (`000`,
    /// `intersectSphere`): `(−b ± √(b² − 4ac)) / 2a`. Kept to show, in the
    /// tests and in the `course` integrator, where it fails.
    pub fn roots_naive(&self, ray: &Ray<V>) -> Roots<V::Scalar> {
        let (two, four) = (V::Scalar::lit(2.0), V::Scalar::lit(4.0));
        let dist = ray.origin - self.center;
        let a = ray.direction.dot(ray.direction);
        let b = dist.dot(ray.direction) * two;
        let c = dist.dot(dist) - self.radius * self.radius;
        let discr = b * b - four * a * c;
        if discr < V::Scalar::lit(0.0) {
            return None;
        }
        let s = discr.sqrt();
        Some(((-b - s) / two / a, (-b + s) / two / a))
    }

    /// The nearest hit in `(t_min, ray.t_max)`.
    #[inline]
    pub fn intersect(
        &self,
        ray: &Ray<V>,
        t_min: V::Scalar,
        roots: Roots<V::Scalar>,
    ) -> Option<Hit<V>> {
        let (t0, t1) = roots?;
        let t = if t0 > t_min && t0 < ray.t_max {
            t0
        } else if t1 > t_min && t1 < ray.t_max {
            t1
        } else {
            return None;
        };
        let normal = (ray.at(t) - self.center).normalize_or_zero();
        // Re-projection: c + r n is within a few ulps of |c| + r of the
        // true surface point, however far the ray travelled.
        let point = self.center + normal * self.radius;
        let error = V::Scalar::gamma(6) * (self.center.abs() + V::splat(self.radius)).max_element();
        Some(Hit {
            t,
            point,
            error,
            normal,
            shading: normal,
            two_sided: false,
            material: self.material,
            object: 0,
        })
    }
}
