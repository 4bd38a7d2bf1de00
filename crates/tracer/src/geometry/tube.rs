//! The homework's kaleidoscope: a regular polygon of mirror strips around
//! an axis.

use glam::Vec3;
use num_traits::Float;
use radiometry::{Real, Vector3};

use super::plane::Plane;
use super::ray::{Hit, Ray};

/// The homework's kaleidoscope (`000`): `sides` mirror strips forming a
/// regular polygon of circumradius `radius` around an axis, infinite along
/// it. Corner `i` is at angle `2π i / sides` from the first basis vector
/// perpendicular to the axis (the x axis for a tube along z, as in the course).
#[derive(Clone, Debug, PartialEq)]
pub struct Tube<V: Vector3 = Vec3> {
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

impl<V: Vector3> Tube<V> {
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
        let wide_radius: f64 = radius.into();
        let half_side = V::Scalar::lit(wide_radius * (alpha / 2.0).sin());
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
