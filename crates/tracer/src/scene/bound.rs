//! The largest radiance a scene's numbers can give, bounded in `f64` at
//! validation, so that a scene whose products leave `f32` is refused by
//! name instead of rendering infinity and NaN.
//!
//! Each number of a scene is within `f32` alone, but the shading multiplies
//! them: the ambient term is `ka · L_ambient`, a rough surface under a
//! light sends at most `(kd + ks) · E⊥` (Blinn-Phong: `f_r E⊥ cos θ =
//! kd E⊥ cos θ + ks E⊥ cos^s δ`; Lambert: `albedo / π · E⊥ cos θ`, and the
//! course shader reads `albedo` as `kd`), and a point light gives `E⊥ =
//! I / r²` at distance `r`, which is at least the light's distance to the
//! nearest surface. The bound on a rough surface is the ambient term plus
//! that direct term summed over the lights; a scene whose bound is beyond
//! `f32::MAX` is refused ([`ErrorKind::RadianceOverflow`]) at the material
//! that reaches it.
//!
//! What the bound does not cover, the gain of a path (a glass sphere's
//! `η²`, a path tracer's `π f_r / cos`-weighted bounces), depends on the
//! paths taken: a render that still leaves `f32` is refused after tracing
//! and before writing ([`RenderError::NotFinite`](crate::job::RenderError::NotFinite)).

use glam::{DVec3, Vec3};

use super::error::{ErrorKind, SceneError};
use super::model::{Light, Material, Scene};
use crate::geometry::Object;

/// Refuses a scene whose rough surfaces can send radiance beyond `f32`.
pub(super) fn check(scene: &Scene) -> Result<(), SceneError> {
    if super::faults::undone(super::faults::Fault::RadianceUnbounded) {
        return Ok(());
    }
    let irradiance = lights_irradiance(scene);
    for (name, material) in scene.material_names.iter().zip(&scene.materials) {
        let bound = material_bound(material, scene.ambient, irradiance);
        if bound > f32::MAX as f64 || bound.is_nan() {
            // Unbounded because a point light is within rounding of a
            // surface: that light is the cause, not the material.
            if let Some(error) = light_within_rounding(scene) {
                return Err(error);
            }
            return Err(SceneError::new(
                format!("materials.{name}"),
                ErrorKind::RadianceOverflow { bound },
            ));
        }
    }
    Ok(())
}

/// The first point light within the rounding of a surface's hit points,
/// as the error naming it, the surface and the rounding.
fn light_within_rounding(scene: &Scene) -> Option<SceneError> {
    scene.lights.iter().enumerate().find_map(|(i, light)| {
        let Light::Point { position, .. } = *light else {
            return None;
        };
        let near = clearance(&scene.objects, position.as_dvec3());
        (near.distance <= near.rounding).then(|| {
            let kind = ErrorKind::LightWithinRounding {
                distance: near.distance,
                rounding: near.rounding,
                widest: near.widest,
            };
            SceneError::new(format!("lights[{i}]"), kind)
        })
    })
}

/// How far a point is from the scene's surfaces, and how far hit points
/// are rounded.
struct Clearance {
    /// To the nearest surface, m.
    distance: f64,
    /// Of a hit point in `f32`: a few ulps of the scene's extent, m.
    rounding: f64,
    /// The object whose coordinates set that extent.
    widest: usize,
}

fn clearance(objects: &[Object], p: DVec3) -> Clearance {
    let plane = |point: Vec3, normal: Vec3| (p - point.as_dvec3()).dot(normal.as_dvec3()).abs();
    let mut nearest = f64::INFINITY;
    let (mut scale, mut widest) = (p.abs().max_element(), 0);
    for (i, object) in objects.iter().enumerate() {
        let (d, size) = match object {
            Object::Sphere(s) => {
                let c = s.center.as_dvec3();
                let size = c.abs().max_element() + s.radius as f64;
                (((p - c).length() - s.radius as f64).abs(), size)
            }
            Object::Plane(q) => (plane(q.point, q.normal), q.point.abs().max_element() as f64),
            Object::Tube(t) => t
                .faces
                .iter()
                .fold((f64::INFINITY, 0.0_f64), |(d, size), f| {
                    let size = size.max(f.point.abs().max_element() as f64);
                    (d.min(plane(f.point, f.normal)), size)
                }),
        };
        nearest = nearest.min(d);
        if size > scale {
            (scale, widest) = (size, i);
        }
    }
    Clearance {
        distance: nearest,
        rounding: 8.0 * f32::EPSILON as f64 * scale,
        widest,
    }
}

/// The largest radiance a material sends, per the module's bound, in the
/// channel where it is largest (`inf` where a point light sits on a
/// surface it lights).
pub fn material_bound(material: &Material, ambient: Vec3, irradiance: DVec3) -> f64 {
    let (ka, kd_ks) = match *material {
        Material::CourseRough {
            ambient: ka,
            diffuse,
            specular,
            ..
        } => (ka.as_dvec3(), diffuse.as_dvec3() + specular.as_dvec3()),
        Material::Lambert { albedo } => (albedo.as_dvec3(), albedo.as_dvec3()),
        _ => return 0.0,
    };
    let sum = ka * ambient.as_dvec3() + times(kd_ks, irradiance);
    sum.max_element()
}

/// `a · b` per channel, where a zero factor gives zero even against an
/// unbounded one (no light, or no coefficient, sends nothing).
fn times(a: DVec3, b: DVec3) -> DVec3 {
    let f = |a: f64, b: f64| if a == 0.0 || b == 0.0 { 0.0 } else { a * b };
    DVec3::new(f(a.x, b.x), f(a.y, b.y), f(a.z, b.z))
}

/// The most irradiance the lights together deliver on any surface, W/m²
/// per channel.
pub fn lights_irradiance(scene: &Scene) -> DVec3 {
    scene
        .lights
        .iter()
        .map(|light| match *light {
            Light::Directional { irradiance, .. } => irradiance.as_dvec3(),
            Light::Point {
                position,
                intensity,
            } => {
                let r = nearest_surface(&scene.objects, position.as_dvec3());
                let r2 = r * r;
                let i = intensity.as_dvec3();
                DVec3::new(i.x / r2, i.y / r2, i.z / r2).max(DVec3::ZERO)
            }
        })
        .fold(DVec3::ZERO, |sum, e| sum + e)
}

/// A lower bound on the distance from `p` to every surface, m, less the
/// rounding of a hit point in `f32` (a light within rounding of a surface
/// is on it: distance 0).
fn nearest_surface(objects: &[Object], p: DVec3) -> f64 {
    let near = clearance(objects, p);
    (near.distance - near.rounding).max(0.0)
}
