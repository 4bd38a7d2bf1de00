//! Rays and the course scenes' primitives: spheres, two-sided planes and the
//! kaleidoscope's regular-polygon mirror tube; lengths in metres, at the
//! tracer's precision tier ([`radiometry::Vector3`]; `f32` unless named).
//!
//! Every hit point is re-projected onto the surface it lies on, so its
//! rounding error is a few ulps of the surface's own coordinates whatever
//! the ray's length; [`Hit::error`] bounds it, and [`crate::spawn`] moves
//! secondary rays off the surface by that bound.

mod object;
mod plane;
mod ray;
mod sphere;
mod tube;

pub use object::Object;
pub use plane::Plane;
pub use ray::{Hit, Ray};
pub use sphere::{Roots, Sphere};
pub use tube::Tube;
