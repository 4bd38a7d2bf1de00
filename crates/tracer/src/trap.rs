//! Rays a mirror tube holds until their path's depth runs out, and so
//! paths that can carry no more light.
//!
//! A [`Tube`]'s sides are parallel to its axis, so their normals are
//! perpendicular to it and a mirror reflection there keeps a ray's axial
//! component: a ray inside the tube that moves along the axis away from
//! every other object of the scene keeps moving away at every bounce, and
//! since the tube is closed around its axis and infinite along it, the ray
//! meets the tube again and again and never escapes. A smooth conductor
//! adds no light of its own at a hit, so the rest of such a camera path
//! adds nothing to its sum: the path tracer ends it there
//! ([`Machinery::trap`](crate::integrator::Machinery::trap)) and the image
//! keeps every bit. In the kaleidoscope the light that the spheres and the
//! far wall scatter back towards the camera is such: without the rule it
//! reflects down the tube until `max_depth`.
//!
//! The rule holds in `f32` with margins: with the axis along a coordinate
//! axis the sides' normals have no axial component at all and a
//! reflection keeps the ray's axial component exactly
//! (`radiometry::specular::reflect`); otherwise a normal's axial component
//! is a few ulps and each reflection moves the ray's by less than 10⁻⁶, so
//! over [`MAX_DEPTH`](crate::scene::MAX_DEPTH) bounces less than
//! [`MIN_AXIAL`] lets its sign change. A ray with almost no transverse
//! component would travel so far before it meets a side that it may
//! escape; [`MIN_TRANSVERSE`] keeps such rays out.

use glam::Vec3;
use serde::Serialize;

use crate::geometry::{Object, Plane, Ray, Tube};
use crate::scene::{Material, Scene};

/// The least axial component of a held ray's unit direction (see the module).
pub const MIN_AXIAL: f32 = 1e-3;

/// The least transverse component of a held ray's unit direction: it meets
/// a side within `2 r / MIN_TRANSVERSE` of a tube of circumradius `r`.
pub const MIN_TRANSVERSE: f32 = 1e-3;

/// A scene's mirror tube, seen as a trap: its sides, and the interval of
/// the axis that every other object lies within.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Trap {
    /// The tube's index in the scene's objects.
    pub object: usize,
    /// The axial interval `[below, above]`, m from the tube's axis point,
    /// outside which no other object reaches (widened by a margin).
    pub axial_range: [f32; 2],
    #[serde(skip)]
    axis: Vec3,
    #[serde(skip)]
    axis_point: Vec3,
    #[serde(skip)]
    faces: Vec<Plane>,
}

impl Trap {
    /// The trap of `scene`: its one tube, a smooth conductor without a bump
    /// map, where every other object has a bounded extent along the axis (a
    /// sphere, or a plane perpendicular to it). `None` otherwise.
    pub fn of(scene: &Scene) -> Option<Trap> {
        let mut tubes = scene
            .objects
            .iter()
            .enumerate()
            .filter_map(|(i, o)| match o {
                Object::Tube(tube) => Some((i, tube)),
                _ => None,
            });
        let (object, tube) = tubes.next()?;
        if tubes.next().is_some() {
            return None;
        }
        let mirror = matches!(
            scene.materials[tube.faces[0].material as usize],
            Material::Conductor { .. }
        );
        let bumped = scene.bumps.get(object).is_some_and(|b| b.is_some());
        if !mirror || bumped {
            return None;
        }
        let (mut below, mut above) = (f32::INFINITY, f32::NEG_INFINITY);
        for (i, o) in scene.objects.iter().enumerate() {
            if i == object {
                continue;
            }
            let [lo, hi] = axial_extent(tube, o)?;
            below = below.min(lo);
            above = above.max(hi);
        }
        // Rounding of the extents and of the hits: far more than either.
        let margin = 1e-3 * (1.0 + below.abs().max(above.abs()).min(f32::MAX));
        Some(Trap {
            object,
            axial_range: [below - margin, above + margin],
            axis: tube.axis,
            axis_point: tube.axis_point,
            faces: tube.faces.clone(),
        })
    }

    /// Whether `ray` is held: it starts strictly inside the tube, moves
    /// along the axis away from the axial range of every other object (by
    /// at least [`MIN_AXIAL`]), starting outside it, and has a transverse
    /// component (at least [`MIN_TRANSVERSE`]). Such a ray meets only the
    /// tube again, however many times it bounces.
    #[inline]
    pub fn holds(&self, ray: &Ray) -> bool {
        let axial = ray.direction.dot(self.axis);
        let at = (ray.origin - self.axis_point).dot(self.axis);
        let [below, above] = self.axial_range;
        let away = (axial <= -MIN_AXIAL && at < below) || (axial >= MIN_AXIAL && at > above);
        if !away {
            return false;
        }
        let transverse = ray.direction - self.axis * axial;
        transverse.length_squared() >= MIN_TRANSVERSE * MIN_TRANSVERSE
            && self
                .faces
                .iter()
                .all(|f| (ray.origin - f.point).dot(f.normal) < 0.0)
    }
}

/// The interval of `tube`'s axis, m from its axis point, that `object`
/// lies within, or `None` where it is unbounded (a plane not perpendicular
/// to the axis, another tube).
fn axial_extent(tube: &Tube, object: &Object) -> Option<[f32; 2]> {
    let along = |p: Vec3| (p - tube.axis_point).dot(tube.axis);
    match object {
        Object::Sphere(s) => {
            let c = along(s.center);
            Some([c - s.radius, c + s.radius])
        }
        Object::Plane(p) if p.normal.cross(tube.axis).length_squared() == 0.0 => {
            let c = along(p.point);
            Some([c, c])
        }
        Object::Plane(_) | Object::Tube(_) => None,
    }
}
