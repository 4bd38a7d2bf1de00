//! The loop of the course's final shader (`000`, the kaleidoscope's
//! `rayTrace`), line by line, with the shader's own rules: its intersection
//! (the textbook sphere quadratic, planes seen only from behind), its
//! reversed Fresnel, its unweighted ambient, its missing shadows and its
//! fixed `EPSILON`. None of these rules reaches the physical integrators.

use glam::Vec3;
use radiometry::{course, fresnel, radiance, specular};

use super::counts::{Bounce, RayCounts};
use super::direct::rgb;
use super::tracer::Tracer;
use crate::geometry::{Hit, Object, Ray};
use crate::scene::{Light, Material};

/// How far the course moves a secondary ray's origin along the normal, m.
const EPSILON: f32 = 0.001;

impl Tracer<'_> {
    /// The nearest hit along `ray` as the course's shader finds it: the
    /// textbook sphere quadratic, and planes one-sided, since its
    /// `intersectPlane` accepts only `dot(normal, dir) > 0.001`.
    pub fn course_intersect(&self, ray: &Ray) -> Option<Hit> {
        self.nearest(ray, |object, bounded| {
            let hit = match object {
                Object::Sphere(s) => s.intersect(bounded, 0.0, s.roots_naive(bounded)),
                Object::Plane(p) => p.intersect(bounded, 0.0),
                Object::Tube(t) => t.intersect(bounded, 0.0),
            };
            hit.filter(|h| !(h.two_sided && h.normal.dot(ray.direction) <= 0.001))
        })
    }

    /// `maxBounces = max_depth + 1` iterations; at a mirror `weight *=
    /// Fresnel(F0, dot(−dir, n))` with the course's reversed Fresnel
    /// ([`course::fresnel_000_glsl`]) and `radiance += lightAmbient`,
    /// unweighted; at a rough surface `radiance += weight · energy · (kd cos
    /// θ + ks cos^s δ)` without shadows (the shader comments them out) and
    /// stop; secondary rays start `EPSILON = 0.001` along the unflipped
    /// normal.
    pub(super) fn course(&self, primary: &Ray, counts: &mut RayCounts) -> Vec3 {
        let mut ray = *primary;
        let mut weight = Vec3::ONE;
        let mut sum = Vec3::ZERO;
        for bounce in 0..=self.settings.max_depth {
            let Some(hit) = self.course_intersect(&ray) else {
                break;
            };
            let n = hit.normal;
            match self.scene.materials[hit.material as usize] {
                Material::Flat { radiance } => return sum + radiance,
                Material::NormalColour => return sum + (n * 0.5 + 0.5),
                Material::Conductor { n: eta, kappa, .. } => {
                    let f0 = fresnel::f0_rgb(eta, kappa);
                    let cos = (-ray.direction).dot(n);
                    weight *= rgb::<Vec3>(|c| course::fresnel_000_glsl(f0[c], cos));
                    counts.bounce(Bounce::Reflection, bounce + 1);
                    ray = Ray::new(
                        hit.point + n * EPSILON,
                        specular::reflect(-ray.direction, n),
                    );
                    sum += self.scene.ambient;
                }
                Material::CourseRough { .. } => {
                    let material = self.scene.materials[hit.material as usize];
                    self.course_lights(&hit, &material, -ray.direction, weight, &mut sum);
                    break;
                }
                // The course has no normalised Lambert: its `kd` is the albedo.
                Material::Lambert { albedo } => {
                    let material = Material::CourseRough {
                        ambient: albedo,
                        diffuse: albedo,
                        specular: Vec3::ZERO,
                        shininess: 0.0,
                    };
                    self.course_lights(&hit, &material, -ray.direction, weight, &mut sum);
                    break;
                }
                // The course's shader has no glass; the job refuses such
                // scenes first (`ErrorKind::CourseHasNoRefraction`).
                Material::Dielectric { .. } => break,
            }
        }
        sum
    }

    /// The shader's light loop at a rough surface, unshadowed, each light's
    /// term times `weight` added to `sum` in turn. A point light's direction
    /// is taken from the light to the point, as the shader writes it, with
    /// no falloff.
    fn course_lights(
        &self,
        hit: &Hit,
        material: &Material,
        wo: Vec3,
        weight: Vec3,
        sum: &mut Vec3,
    ) {
        let n = hit.normal;
        for light in &self.scene.lights {
            let (to_light, energy) = match *light {
                Light::Directional {
                    towards,
                    irradiance,
                } => (towards, irradiance),
                // `normalize(hit.hitPoint - light.position)`: points away from the light.
                Light::Point {
                    position,
                    intensity,
                } => ((hit.point - position).normalize_or_zero(), intensity),
            };
            let cos_theta = n.dot(to_light);
            if cos_theta > 0.0 {
                // weight · energy · (kd cos θ + ks cos^s δ) is the course's
                // Blinn-Phong BRDF times E⊥ cos θ.
                let f = material.brdf(n, to_light, wo);
                *sum += weight
                    * rgb::<Vec3>(|c| {
                        radiance::reflected_radiance(
                            f[c],
                            radiance::directional_irradiance(energy[c], n, to_light),
                        )
                    });
            }
        }
    }
}
