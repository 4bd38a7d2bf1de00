//! The three levels of light transport of `003` ("lokális illumináció",
//! "rekurzív sugárkövetés", "globális illumináció") and the course shader's
//! own loop, all on one scene, all shading with the `radiometry` laws.
//!
//! | integrator | at a rough surface | at a mirror or glass | cost |
//! |---|---|---|---|
//! | `local` | ambient + direct light, shadow rays | background seen in the mirror direction is not traced: black | 1 ray + 1 per light |
//! | `whitted` | ambient + direct light, shadow rays | recursion, Fresnel-weighted, to `max_depth`, cut below `throughput_cutoff` | grows with mirrors |
//! | `path` | direct light + one cosine-sampled bounce (no ambient: the indirect light is computed) | one branch, chosen with the Fresnel probability | `spp` paths per pixel |
//! | `course` | the final GLSL shader of `000`, bugs included | | |
//!
//! Radiance is in W/(sr·m²) per channel; the tracer computes in `f32`.

use glam::Vec3;
use radiometry::brdf::{BlinnPhong, Brdf, Lambert};
use radiometry::{course, fresnel, radiance, specular};

use crate::geometry::{Hit, Object, Ray};
use crate::rng::Pcg32;
use crate::scene::{FresnelModel, IntegratorKind, Light, Material, RayOffset, Scene};
use crate::spawn;

/// Counts of rays cast, by purpose.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct RayCounts {
    /// From the camera.
    pub primary: u64,
    /// Mirror reflections (conductors and dielectrics).
    pub reflection: u64,
    /// Refractions into or out of dielectrics.
    pub refraction: u64,
    /// Towards lights.
    pub shadow: u64,
    /// The path tracer's diffuse bounces.
    pub diffuse: u64,
    /// The most bounces any path took after its primary hit.
    pub deepest: u32,
}

impl RayCounts {
    /// All rays.
    pub fn total(&self) -> u64 {
        self.primary + self.reflection + self.refraction + self.shadow + self.diffuse
    }

    /// Adds another tally.
    pub fn add(&mut self, other: &RayCounts) {
        self.primary += other.primary;
        self.reflection += other.reflection;
        self.refraction += other.refraction;
        self.shadow += other.shadow;
        self.diffuse += other.diffuse;
        self.deepest = self.deepest.max(other.deepest);
    }

    fn bounced(&mut self, depth: u32) {
        self.deepest = self.deepest.max(depth);
    }
}

/// Settled render settings.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Settings {
    /// The light transport.
    pub integrator: IntegratorKind,
    /// Samples per pixel; only the path tracer is random, the others use 1.
    pub spp: u32,
    /// Bounces allowed after the primary hit (the course's `maxBounces`
    /// counts the primary hit too: its 12 is `max_depth` 11).
    pub max_depth: u32,
    /// Fresnel law of smooth materials.
    pub fresnel: FresnelModel,
    /// A branch whose throughput (largest channel) falls below this is cut
    /// (`whitted`) or continued with Russian roulette (`path`). 0 never cuts.
    pub throughput_cutoff: f32,
    /// Seed of the path tracer.
    pub seed: u64,
    /// How secondary rays leave a surface.
    pub ray_offset: RayOffset,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            integrator: IntegratorKind::Whitted,
            spp: 1,
            max_depth: 11,
            fresnel: FresnelModel::Exact,
            throughput_cutoff: 1e-3,
            seed: 0,
            ray_offset: RayOffset::Robust,
        }
    }
}

impl Settings {
    /// The scene's own settings over the defaults.
    pub fn from_scene(scene: &Scene) -> Self {
        let d = Settings::default();
        let r = &scene.render;
        Settings {
            integrator: r.integrator.unwrap_or(d.integrator),
            spp: r.spp.map_or(d.spp, |x| x as u32),
            max_depth: r.max_depth.map_or(d.max_depth, |x| x as u32),
            fresnel: r.fresnel.unwrap_or(d.fresnel),
            throughput_cutoff: r
                .throughput_cutoff
                .map_or(d.throughput_cutoff, |x| x as f32),
            seed: r.seed.unwrap_or(d.seed),
            ray_offset: r.ray_offset.unwrap_or(d.ray_offset),
        }
    }
}

/// What a render actually runs: the scene's needs (see [`crate::needs`])
/// decide which parts are switched on. Switching a part on that the scene
/// does not need never changes the image, only its cost.
#[derive(Clone, Debug, PartialEq)]
pub struct Machinery {
    /// Cast shadow rays (off when no object can block a light).
    pub shadow_rays: bool,
    /// Which lights are evaluated (off: a light that delivers nothing).
    pub lights: Vec<bool>,
    /// Samples per pixel actually taken (1 when every path is deterministic).
    pub spp: u32,
}

impl Machinery {
    /// Everything on: the reference against which skipping is measured.
    pub fn everything(scene: &Scene, settings: &Settings) -> Self {
        Machinery {
            shadow_rays: true,
            lights: vec![true; scene.lights.len()],
            spp: settings.spp,
        }
    }
}

/// One render's tracer: the scene, the settings and the machinery.
pub struct Tracer<'a> {
    /// The scene.
    pub scene: &'a Scene,
    /// Settled settings.
    pub settings: Settings,
    /// What runs.
    pub machinery: Machinery,
}

fn rgb(f: impl Fn(usize) -> f32) -> Vec3 {
    Vec3::new(f(0), f(1), f(2))
}

impl Tracer<'_> {
    /// The nearest hit along `ray`, robustly.
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        self.intersect_with(ray, false)
    }

    /// The nearest hit along `ray`; `course` intersects as the course's
    /// shader does (textbook sphere quadratic, planes seen only from behind).
    fn intersect_with(&self, ray: &Ray, course: bool) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        for (i, object) in self.scene.objects.iter().enumerate() {
            let bounded = Ray {
                t_max: best.map_or(ray.t_max, |h| h.t),
                ..*ray
            };
            let hit = match object {
                Object::Sphere(s) => {
                    let roots = if course {
                        s.roots_naive(&bounded)
                    } else {
                        s.roots(&bounded)
                    };
                    s.intersect(&bounded, 0.0, roots)
                }
                Object::Plane(p) => p.intersect(&bounded, 0.0),
                Object::Tube(t) => t.intersect(&bounded, 0.0),
            };
            // The course's `intersectPlane` accepts only `dot(normal, dir) >
            // 0.001`: planes are one-sided, seen from behind their normal.
            let hit =
                hit.filter(|h| !(course && h.two_sided && h.normal.dot(ray.direction) <= 0.001));
            if let Some(mut h) = hit {
                h.object = i as u32;
                best = Some(h);
            }
        }
        best
    }

    fn occluded(&self, ray: &Ray, counts: &mut RayCounts) -> bool {
        counts.shadow += 1;
        self.intersect(ray).is_some()
    }

    /// Reflected radiance from the delta lights at a rough surface:
    /// `Σ f_r(wi, wo) E(wi)`, with shadow rays stopped at point lights.
    fn direct(
        &self,
        hit: &Hit,
        n: Vec3,
        wo: Vec3,
        material: &Material,
        counts: &mut RayCounts,
    ) -> Vec3 {
        let mut sum = Vec3::ZERO;
        for (light, _) in self
            .scene
            .lights
            .iter()
            .zip(&self.machinery.lights)
            .filter(|(_, on)| **on)
        {
            // The direction to the light, the irradiance it delivers, and
            // where a shadow ray must stop (a point light's position).
            let (wi, irradiance, stop_at) = match *light {
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
                    let Some(sample) = radiance::point_irradiance(1.0, position, hit.point, n)
                    else {
                        continue;
                    };
                    (
                        sample.to_light,
                        rgb(|c| {
                            radiance::point_irradiance(intensity[c], position, hit.point, n)
                                .map_or(0.0, |s| s.irradiance)
                        }),
                        Some(position),
                    )
                }
            };
            if irradiance.max_element() <= 0.0 {
                continue;
            }
            let f = self.brdf(material, n, wi, wo);
            if f.max_element() <= 0.0 {
                continue;
            }
            if self.machinery.shadow_rays {
                let origin = spawn::origin(hit, n, self.settings.ray_offset);
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

    /// The BRDF of a rough material per channel, 1/sr.
    fn brdf(&self, material: &Material, n: Vec3, wi: Vec3, wo: Vec3) -> Vec3 {
        match *material {
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
            _ => Vec3::ZERO,
        }
    }

    /// The course's ambient term: `ka · L_ambient` for the course's model;
    /// for a Lambert surface under a uniform ambient radiance, the reflected
    /// radiance is `albedo · L_ambient` (its directional albedo, see
    /// `radiometry::brdf::Lambert`).
    fn ambient(&self, material: &Material) -> Vec3 {
        match *material {
            Material::CourseRough { ambient, .. } => ambient * self.scene.ambient,
            Material::Lambert { albedo } => albedo * self.scene.ambient,
            _ => Vec3::ZERO,
        }
    }

    /// Conductor reflectance per channel at `cos_i`, by the chosen law.
    fn conductor_fresnel(&self, cos_i: f32, n: [f32; 3], kappa: [f32; 3]) -> Vec3 {
        Vec3::from_array(match self.settings.fresnel {
            FresnelModel::Exact => fresnel::conductor_rgb(cos_i, n, kappa),
            FresnelModel::Schlick => fresnel::schlick_rgb(cos_i, fresnel::f0_rgb(n, kappa)),
            FresnelModel::Course => {
                let f0 = fresnel::f0_rgb(n, kappa);
                core::array::from_fn(|c| course::fresnel_000_glsl(f0[c], cos_i))
            }
        })
    }

    /// Dielectric reflectance and transmittance at signed `cos_i`.
    fn dielectric_fresnel(&self, cos_i: f32, eta: f32) -> (f32, f32) {
        match self.settings.fresnel {
            FresnelModel::Exact => {
                let f = fresnel::dielectric_polarized(cos_i, eta);
                (f.reflectance(), f.transmittance())
            }
            FresnelModel::Schlick => {
                let r = fresnel::schlick_dielectric(cos_i, eta);
                (r, 1.0 - r)
            }
            // The course has no glass; its formula with the incident cosine.
            FresnelModel::Course => {
                let r = course::fresnel_000_glsl(fresnel::f0(eta, 0.0), cos_i.abs());
                (r, 1.0 - r)
            }
        }
    }

    fn unlit(material: &Material, hit: &Hit) -> Option<Vec3> {
        match *material {
            Material::Flat { radiance } => Some(radiance),
            Material::NormalColour => Some(hit.normal * 0.5 + 0.5),
            _ => None,
        }
    }

    /// The radiance arriving along a primary ray, by the chosen integrator.
    pub fn radiance(&self, ray: &Ray, rng: &mut Pcg32, counts: &mut RayCounts) -> Vec3 {
        counts.primary += 1;
        match self.settings.integrator {
            IntegratorKind::Local => self.local(ray, counts),
            IntegratorKind::Whitted => self.whitted(ray, 0, Vec3::ONE, counts),
            IntegratorKind::Path => self.path(ray, rng, counts),
            IntegratorKind::Course => self.course(ray, counts),
        }
    }

    fn local(&self, ray: &Ray, counts: &mut RayCounts) -> Vec3 {
        let Some(hit) = self.intersect(ray) else {
            return self.scene.background;
        };
        let material = &self.scene.materials[hit.material as usize];
        if let Some(l) = Self::unlit(material, &hit) {
            return l;
        }
        if !material.is_rough() {
            return Vec3::ZERO;
        }
        let n = hit.shading_normal(ray.direction);
        self.ambient(material) + self.direct(&hit, n, -ray.direction, material, counts)
    }

    fn whitted(&self, ray: &Ray, depth: u32, throughput: Vec3, counts: &mut RayCounts) -> Vec3 {
        let Some(hit) = self.intersect(ray) else {
            return self.scene.background;
        };
        let material = &self.scene.materials[hit.material as usize];
        if let Some(l) = Self::unlit(material, &hit) {
            return l;
        }
        let wo = -ray.direction;
        let n = hit.shading_normal(ray.direction);
        match *material {
            Material::CourseRough { .. } | Material::Lambert { .. } => {
                self.ambient(material) + self.direct(&hit, n, wo, material, counts)
            }
            Material::Conductor { n: eta, kappa } => {
                let facing = if n.dot(wo) < 0.0 { -n } else { n };
                let f = self.conductor_fresnel(facing.dot(wo), eta, kappa);
                let next = throughput * f;
                if depth >= self.settings.max_depth
                    || next.max_element() < self.settings.throughput_cutoff
                {
                    return Vec3::ZERO;
                }
                counts.reflection += 1;
                counts.bounced(depth + 1);
                let r = Ray::new(
                    spawn::origin(&hit, facing, self.settings.ray_offset),
                    specular::reflect(wo, facing),
                );
                f * self.whitted(&r, depth + 1, next, counts)
            }
            Material::Dielectric { eta } => {
                if depth >= self.settings.max_depth {
                    return Vec3::ZERO;
                }
                let cos_o = n.dot(wo);
                let outward = if cos_o >= 0.0 { n } else { -n };
                let (reflectance, transmittance) = self.dielectric_fresnel(cos_o, eta);
                let mut sum = Vec3::ZERO;
                if throughput.max_element() * reflectance >= self.settings.throughput_cutoff {
                    counts.reflection += 1;
                    counts.bounced(depth + 1);
                    let r = Ray::new(
                        spawn::origin(&hit, outward, self.settings.ray_offset),
                        specular::reflect(wo, n),
                    );
                    sum +=
                        reflectance * self.whitted(&r, depth + 1, throughput * reflectance, counts);
                }
                if let Some(t) = specular::refract(wo, n, eta) {
                    let weight = radiance::across_interface(transmittance, t.eta_path);
                    if throughput.max_element() * weight >= self.settings.throughput_cutoff {
                        counts.refraction += 1;
                        counts.bounced(depth + 1);
                        let r = Ray::new(
                            spawn::origin(&hit, -outward, self.settings.ray_offset),
                            t.direction,
                        );
                        sum += weight * self.whitted(&r, depth + 1, throughput * weight, counts);
                    }
                }
                sum
            }
            Material::Flat { .. } | Material::NormalColour => unreachable!("handled as unlit"),
        }
    }

    fn path(&self, primary: &Ray, rng: &mut Pcg32, counts: &mut RayCounts) -> Vec3 {
        let mut ray = *primary;
        let mut beta = Vec3::ONE;
        let mut sum = Vec3::ZERO;
        let mut depth = 0;
        loop {
            let Some(hit) = self.intersect(&ray) else {
                return sum + beta * self.scene.background;
            };
            let material = &self.scene.materials[hit.material as usize];
            if let Some(l) = Self::unlit(material, &hit) {
                return sum + beta * l;
            }
            let wo = -ray.direction;
            let n = hit.shading_normal(ray.direction);
            let (next, kind) = match *material {
                Material::CourseRough { .. } | Material::Lambert { .. } => {
                    sum += beta * self.direct(&hit, n, wo, material, counts);
                    if depth >= self.settings.max_depth {
                        return sum;
                    }
                    // Cosine-weighted hemisphere sampling: pdf = cos θ / π,
                    // so the weight f_r cos θ / pdf is π f_r.
                    let wi = cosine_sample(n, rng.next_f32(), rng.next_f32());
                    let f = self.brdf(material, n, wi, wo);
                    beta *= f * std::f32::consts::PI;
                    (
                        Ray::new(spawn::origin(&hit, n, self.settings.ray_offset), wi),
                        0,
                    )
                }
                Material::Conductor { n: eta, kappa } => {
                    if depth >= self.settings.max_depth {
                        return sum;
                    }
                    let facing = if n.dot(wo) < 0.0 { -n } else { n };
                    beta *= self.conductor_fresnel(facing.dot(wo), eta, kappa);
                    let dir = specular::reflect(wo, facing);
                    (
                        Ray::new(spawn::origin(&hit, facing, self.settings.ray_offset), dir),
                        1,
                    )
                }
                Material::Dielectric { eta } => {
                    if depth >= self.settings.max_depth {
                        return sum;
                    }
                    let cos_o = n.dot(wo);
                    let outward = if cos_o >= 0.0 { n } else { -n };
                    let (reflectance, transmittance) = self.dielectric_fresnel(cos_o, eta);
                    let refraction = specular::refract(wo, n, eta);
                    // Choose a branch with probability R: the Fresnel
                    // weight cancels. Under total internal reflection the
                    // mirror branch is certain and carries the law's R
                    // itself (1 for the exact law and Schlick; the course's
                    // formula gives less).
                    if refraction.is_none() {
                        beta *= reflectance;
                    }
                    match refraction {
                        Some(t) if rng.next_f32() >= reflectance => {
                            beta *= radiance::across_interface(transmittance, t.eta_path)
                                / (1.0 - reflectance);
                            (
                                Ray::new(
                                    spawn::origin(&hit, -outward, self.settings.ray_offset),
                                    t.direction,
                                ),
                                2,
                            )
                        }
                        _ => {
                            let dir = specular::reflect(wo, n);
                            (
                                Ray::new(
                                    spawn::origin(&hit, outward, self.settings.ray_offset),
                                    dir,
                                ),
                                1,
                            )
                        }
                    }
                }
                Material::Flat { .. } | Material::NormalColour => unreachable!("handled as unlit"),
            };
            match kind {
                0 => counts.diffuse += 1,
                1 => counts.reflection += 1,
                _ => counts.refraction += 1,
            }
            depth += 1;
            counts.bounced(depth);
            let peak = beta.max_element();
            if peak <= 0.0 {
                return sum;
            }
            if peak < self.settings.throughput_cutoff {
                // Russian roulette: survive with probability peak / cutoff and
                // carry 1 / probability, so the estimate stays unbiased.
                let survive = peak / self.settings.throughput_cutoff;
                if rng.next_f32() >= survive {
                    return sum;
                }
                beta /= survive;
            }
            ray = next;
        }
    }

    /// The loop of the course's final shader (`000`, the kaleidoscope's
    /// `rayTrace`), line by line: `maxBounces = max_depth + 1` iterations;
    /// at a mirror `weight *= Fresnel(F0, dot(−dir, n))` with the course's
    /// reversed Fresnel ([`course::fresnel_000_glsl`]) and `radiance +=
    /// lightAmbient`, unweighted; at a rough surface `radiance += weight ·
    /// energy · (kd cos θ + ks cos^s δ)` without shadows (the shader comments
    /// them out) and stop; secondary rays start `EPSILON = 0.001` along the
    /// unflipped normal. A point light's direction is taken from the light
    /// to the point, as the shader writes it, with no falloff.
    fn course(&self, primary: &Ray, counts: &mut RayCounts) -> Vec3 {
        const EPSILON: f32 = 0.001;
        let mut ray = *primary;
        let mut weight = Vec3::ONE;
        let mut sum = Vec3::ZERO;
        for bounce in 0..=self.settings.max_depth {
            let Some(hit) = self.intersect_with(&ray, true) else {
                break;
            };
            let material = &self.scene.materials[hit.material as usize];
            if let Some(l) = Self::unlit(material, &hit) {
                return sum + l;
            }
            let n = hit.normal;
            match *material {
                Material::Conductor { n: eta, kappa } => {
                    let f0 = fresnel::f0_rgb(eta, kappa);
                    let cos = (-ray.direction).dot(n);
                    weight *= rgb(|c| course::fresnel_000_glsl(f0[c], cos));
                    counts.reflection += 1;
                    counts.bounced(bounce + 1);
                    ray = Ray::new(
                        hit.point + n * EPSILON,
                        specular::reflect(-ray.direction, n),
                    );
                    sum += self.scene.ambient;
                }
                Material::CourseRough { .. } | Material::Lambert { .. } => {
                    let material = match *material {
                        // The course has no normalised Lambert: its `kd` is the albedo.
                        Material::Lambert { albedo } => Material::CourseRough {
                            ambient: albedo,
                            diffuse: albedo,
                            specular: Vec3::ZERO,
                            shininess: 0.0,
                        },
                        m => m,
                    };
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
                            // weight · energy · (kd cos θ + ks cos^s δ) is the
                            // course's Blinn-Phong BRDF times E⊥ cos θ.
                            let f = self.brdf(&material, n, to_light, -ray.direction);
                            sum += weight
                                * rgb(|c| {
                                    radiance::reflected_radiance(
                                        f[c],
                                        radiance::directional_irradiance(energy[c], n, to_light),
                                    )
                                });
                        }
                    }
                    break;
                }
                // The course's shader has no glass; the check in
                // `needs::check_integrator` refuses such scenes first.
                Material::Dielectric { .. } => break,
                Material::Flat { .. } | Material::NormalColour => unreachable!("handled as unlit"),
            }
        }
        sum
    }
}

/// A direction on the hemisphere around `n` with density `cos θ / π`
/// (Malley's method: a uniform point on the unit disc lifted to the
/// hemisphere; Pharr, Jakob and Humphreys, *pbrt* 4th ed., §A.5.3), from two
/// uniform numbers in `[0, 1)`.
pub fn cosine_sample(n: Vec3, u1: f32, u2: f32) -> Vec3 {
    let r = u1.sqrt();
    let phi = std::f32::consts::TAU * u2;
    let (x, y) = (r * phi.cos(), r * phi.sin());
    let z = (1.0 - u1).max(0.0).sqrt();
    let (t, b) = n.any_orthonormal_pair();
    (t * x + b * y + n * z).normalize()
}
