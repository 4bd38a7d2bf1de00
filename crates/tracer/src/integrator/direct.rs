//! Light at a rough surface: the delta lights' reflected radiance with its
//! shadow rays, the course's ambient term, and the BRDFs behind both.

use radiometry::brdf::{BlinnPhong, Brdf, Lambert};
use radiometry::{radiance, Real, Vector3};

use super::counts::RayCounts;
use super::tracer::Tracer;
use crate::geometry::{Hit, Ray};
use crate::scene::{Light, Material};
use crate::spawn;

impl<V: Vector3> Material<V> {
    /// The BRDF of a rough material per channel, 1/sr (zero for the others,
    /// which scatter only into discrete directions or not at all).
    pub fn brdf(&self, n: V, wi: V, wo: V) -> V {
        match *self {
            Material::CourseRough {
                diffuse,
                specular,
                shininess,
                ..
            } => rgb(|c| {
                BlinnPhong {
                    kd: diffuse[c],
                    ks: specular[c],
                    shine: shininess,
                }
                .eval(n, wi, wo)
            }),
            Material::Lambert { albedo } => rgb(|c| Lambert { albedo: albedo[c] }.eval(n, wi, wo)),
            _ => V::ZERO,
        }
    }

    /// The course's ambient term under ambient radiance `l_ambient`:
    /// `ka · L_ambient` for the course's model; for a Lambert surface under a
    /// uniform ambient radiance, the reflected radiance is `albedo ·
    /// L_ambient` (its directional albedo, see `radiometry::brdf::Lambert`).
    pub fn ambient(&self, l_ambient: V) -> V {
        match *self {
            Material::CourseRough { ambient, .. } => ambient * l_ambient,
            Material::Lambert { albedo } => albedo * l_ambient,
            _ => V::ZERO,
        }
    }
}

impl<V: Vector3> Tracer<'_, V> {
    fn occluded(&self, ray: &Ray<V>, counts: &mut RayCounts) -> bool {
        counts.shadow += 1;
        self.intersect_surface(ray).is_some()
    }

    /// Reflected radiance from the delta lights at a rough surface:
    /// `Σ f_r(wi, wo) E(wi)`, with shadow rays stopped at point lights.
    /// `n` is the shading normal, which the BRDF and the light's cosine
    /// see; a light below the geometric horizon is dark whatever `n` says
    /// (a bump map's bent normal may lean towards it), and shadow rays start
    /// off the geometric surface.
    pub(crate) fn direct(
        &self,
        hit: &Hit<V>,
        n: V,
        wo: V,
        material: &Material<V>,
        counts: &mut RayCounts,
    ) -> V {
        let zero = V::Scalar::lit(0.0);
        let side = hit.facing_normal(-wo);
        let mut sum = V::ZERO;
        for (light, _) in self
            .world
            .lights
            .iter()
            .zip(&self.machinery.lights)
            .filter(|(_, on)| **on)
        {
            let Some((wi, irradiance, stop_at)) = arrival(light, hit, n) else {
                continue;
            };
            if !(wi.dot(side) > zero) {
                continue;
            }
            if irradiance.max_element() <= zero {
                continue;
            }
            let f = material.brdf(n, wi, wo);
            if f.max_element() <= zero {
                continue;
            }
            if self.machinery.shadow_rays {
                let origin = spawn::origin(hit, side, self.settings.ray_offset);
                let mut shadow = Ray::new(origin, wi);
                if let Some(position) = stop_at {
                    // Aimed at the light from the moved origin, and stopped there.
                    let to_light = position - origin;
                    shadow.t_max = to_light.length();
                    shadow.direction = to_light / shadow.t_max;
                }
                if self.occluded(&shadow, counts) {
                    continue;
                }
            }
            sum += rgb(|c| radiance::reflected_radiance(f[c], irradiance[c]));
        }
        sum
    }
}

/// The direction to `light` from `hit` (normal `n`), the irradiance it
/// delivers there, and where a shadow ray must stop (a point light's
/// position); `None` where a point light sits on the point.
#[allow(clippy::type_complexity)]
fn arrival<V: Vector3>(light: &Light<V>, hit: &Hit<V>, n: V) -> Option<(V, V, Option<V>)> {
    Some(match *light {
        Light::Directional {
            towards,
            irradiance,
        } => (
            towards,
            rgb(|c| radiance::directional_irradiance(irradiance[c], n, towards)),
            None,
        ),
        Light::Point {
            position,
            intensity,
        } => {
            let sample = radiance::point_irradiance(V::Scalar::lit(1.0), position, hit.point, n)?;
            (
                sample.to_light,
                rgb(|c| {
                    radiance::point_irradiance(intensity[c], position, hit.point, n)
                        .map_or(V::Scalar::lit(0.0), |s| s.irradiance)
                }),
                Some(position),
            )
        }
    })
}

/// A colour from a function of its channel index.
pub(crate) fn rgb<V: Vector3>(f: impl Fn(usize) -> V::Scalar) -> V {
    V::new(f(0), f(1), f(2))
}
