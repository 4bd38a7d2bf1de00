//! One object of a scene: a sphere, a plane or a tube.

use glam::Vec3;

use super::plane::Plane;
use super::sphere::Sphere;
use super::tube::Tube;
use radiometry::{Real, Vector3};

/// One object of a scene.
#[derive(Clone, Debug, PartialEq)]
pub enum Object<V: Vector3 = Vec3> {
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
    pub fn at_tier<V: Vector3>(&self) -> Object<V> {
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

impl<V: Vector3> Object<V> {
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
