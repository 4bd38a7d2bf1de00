//! Rays and the course scenes' primitives: spheres, two-sided planes and the
//! kaleidoscope's regular-polygon mirror tube; lengths in metres, at the
//! tracer's precision tier ([`crate::tier`]; `f32` unless named).
//!
//! Every hit point is re-projected onto the surface it lies on, so its
//! rounding error is a few ulps of the surface's own coordinates whatever
//! the ray's length; [`Hit::error`] bounds it, and [`crate::spawn`] moves
//! secondary rays off the surface by that bound.

use glam::Vec3;
use num_traits::Float;
use radiometry::Real;

use crate::tier::{Tier, Vector};

/// A ray: `origin + t · direction` for `t` in `(0, t_max)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray<V: Vector = Vec3> {
    /// Where the ray starts, m.
    pub origin: V,
    /// Unit direction of travel.
    pub direction: V,
    /// The ray ends here (a point light's distance; infinity otherwise).
    pub t_max: V::Scalar,
}

impl<V: Vector> Ray<V> {
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
pub struct Hit<V: Vector = Vec3> {
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

impl<V: Vector> Hit<V> {
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

/// A sphere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere<V: Vector = Vec3> {
    /// Centre, m.
    pub center: V,
    /// Radius, m, > 0.
    pub radius: V::Scalar,
    /// Material index.
    pub material: u32,
}

/// The two roots `t0 ≤ t1` of `|o + t d − c|² = r²` for a unit `d`, or `None`.
pub type Roots<T = f32> = Option<(T, T)>;

impl<V: Vector> Sphere<V> {
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

/// An infinite plane, visible from both sides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane<V: Vector = Vec3> {
    /// A point on the plane, m.
    pub point: V,
    /// Unit normal, as declared.
    pub normal: V,
    /// Material index.
    pub material: u32,
}

impl<V: Vector> Plane<V> {
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
    fn parameter(&self, ray: &Ray<V>, t_min: V::Scalar, t_max: V::Scalar) -> Option<V::Scalar> {
        let denom = self.normal.dot(ray.direction);
        if denom == V::Scalar::lit(0.0) {
            return None;
        }
        let t = (self.point - ray.origin).dot(self.normal) / denom;
        (t > t_min && t < t_max).then_some(t)
    }

    /// The point at `t` re-projected onto the plane along its normal, and
    /// the bound on its error.
    fn surface_point(&self, ray: &Ray<V>, t: V::Scalar) -> (V, V::Scalar) {
        let p = ray.at(t);
        // Re-projection onto the plane along its normal.
        let point = p - self.normal * (p - self.point).dot(self.normal);
        let error = V::Scalar::gamma(8) * point.abs().max(self.point.abs()).max_element();
        (point, error)
    }
}

/// The homework's kaleidoscope (`000`): `sides` mirror strips forming a
/// regular polygon of circumradius `radius` around an axis, infinite along
/// it. Corner `i` is at angle `2π i / sides` from the first basis vector
/// perpendicular to the axis (the x axis for a tube along z, as in the course).
#[derive(Clone, Debug, PartialEq)]
pub struct Tube<V: Vector = Vec3> {
    /// The side planes; each normal points out of the tube.
    pub faces: Vec<Plane<V>>,
    /// Unit axis direction.
    pub axis: V,
    /// A point on the axis.
    pub axis_point: V,
    /// The number of sides, ≥ 3.
    pub sides: u32,
    /// The circumradius, m.
    pub radius: V::Scalar,
    /// Half the side length, m: a hit farther than this from the side's
    /// midline is off the strip.
    pub half_side: V::Scalar,
    /// Midpoints of the sides (on the axis plane through `axis_point`).
    pub midpoints: Vec<V>,
    /// Unit tangents along each side, perpendicular to the axis.
    pub tangents: Vec<V>,
}

impl<V: Vector> Tube<V> {
    /// Builds the tube. `axis` must be a unit vector and `sides ≥ 3`.
    pub fn new(axis_point: V, axis: V, sides: u32, radius: V::Scalar, material: u32) -> Self {
        let reference = if axis.x().abs() < V::Scalar::lit(0.9) {
            V::X
        } else {
            V::Y
        };
        let u = (reference - axis * reference.dot(axis)).normalize();
        let v = axis.cross(u);
        let alpha = std::f64::consts::TAU / sides as f64;
        let corner = |i: u32| {
            let a = alpha * i as f64;
            axis_point + (u * V::Scalar::lit(a.cos()) + v * V::Scalar::lit(a.sin())) * radius
        };
        let mut faces = Vec::new();
        let mut midpoints = Vec::new();
        let mut tangents = Vec::new();
        for i in 0..sides {
            let (p1, p2) = (corner(i), corner(i + 1));
            let tangent = (p2 - p1).normalize();
            // As the course builds it: cross(edge, axis) points outwards for
            // corners running anticlockwise about the axis.
            let normal = tangent.cross(axis).normalize();
            faces.push(Plane {
                point: p1,
                normal,
                material,
            });
            midpoints.push((p1 + p2) * V::Scalar::lit(0.5));
            tangents.push(tangent);
        }
        let half_side = V::Scalar::lit(radius.to_f64() * (alpha / 2.0).sin());
        Tube {
            faces,
            axis,
            axis_point,
            sides,
            radius,
            half_side,
            midpoints,
            tangents,
        }
    }

    /// The nearest hit on any strip, from either side. Each side's hit is
    /// worked out as [`Plane::intersect`] does, bit for bit, and the
    /// nearest one alone becomes a [`Hit`].
    pub fn intersect(&self, ray: &Ray<V>, t_min: V::Scalar) -> Option<Hit<V>> {
        let mut best: Option<(usize, V::Scalar, V, V::Scalar)> = None;
        for (i, ((face, mid), tangent)) in self
            .faces
            .iter()
            .zip(&self.midpoints)
            .zip(&self.tangents)
            .enumerate()
        {
            let t_max = best.map_or(ray.t_max, |(_, t, _, _)| t);
            let Some(t) = face.parameter(ray, t_min, t_max) else {
                continue;
            };
            let (point, error) = face.surface_point(ray, t);
            // On the strip: within half a side of the side's midline.
            // A hit exactly on an edge belongs to both strips; the
            // small slack keeps rays into a corner from slipping through.
            let along = (point - *mid).dot(*tangent).abs();
            let slack = V::Scalar::lit(1.0) + V::Scalar::lit(4.0) * V::Scalar::epsilon();
            if along <= self.half_side * slack + error {
                best = Some((i, t, point, error));
            }
        }
        let (i, t, point, error) = best?;
        let face = &self.faces[i];
        Some(Hit {
            t,
            point,
            error,
            normal: face.normal,
            shading: face.normal,
            two_sided: true,
            material: face.material,
            object: 0,
        })
    }
}

/// One object of a scene.
#[derive(Clone, Debug, PartialEq)]
pub enum Object<V: Vector = Vec3> {
    /// A sphere.
    Sphere(Sphere<V>),
    /// A two-sided plane.
    Plane(Plane<V>),
    /// A kaleidoscope tube.
    Tube(Tube<V>),
}

impl Object {
    /// This object at tier `V`: its numbers widened exactly, a tube built
    /// again from its corners' construction in `V`'s arithmetic.
    pub fn at_tier<V: Vector>(&self) -> Object<V> {
        let widen = V::Scalar::of_f32;
        match self {
            Object::Sphere(s) => Object::Sphere(Sphere {
                center: V::of_f32(s.center),
                radius: widen(s.radius),
                material: s.material,
            }),
            Object::Plane(p) => Object::Plane(p.at_tier()),
            Object::Tube(t) => Object::Tube(Tube::new(
                V::of_f32(t.axis_point),
                V::of_f32(t.axis),
                t.sides,
                widen(t.radius),
                t.faces[0].material,
            )),
        }
    }
}

impl Plane {
    /// This plane at tier `V`, its numbers widened exactly.
    pub fn at_tier<V: Vector>(&self) -> Plane<V> {
        Plane {
            point: V::of_f32(self.point),
            normal: V::of_f32(self.normal),
            material: self.material,
        }
    }
}

impl<V: Vector> Object<V> {
    /// The material index.
    pub fn material(&self) -> u32 {
        match self {
            Object::Sphere(s) => s.material,
            Object::Plane(p) => p.material,
            Object::Tube(t) => t.faces[0].material,
        }
    }

    /// Whether no segment between two of its points leaves it: such an
    /// object cannot cast a shadow on itself or reflect into itself.
    pub fn is_convex(&self) -> bool {
        matches!(self, Object::Sphere(_) | Object::Plane(_))
    }
}
