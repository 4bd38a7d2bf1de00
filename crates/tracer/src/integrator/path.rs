//! Path tracing (`003`, "globális illumináció"): at each rough surface the
//! lights' direct light and one cosine-sampled bounce; at a smooth one a
//! single lobe, chosen with the Fresnel probability; Russian roulette below
//! `throughput_cutoff`. With a caustic map's pass (the `photon`
//! integrator), each rough vertex adds the map's radiance to its direct light.
//!
//! Each vertex that goes on draws two slots of its [`Sample`], in the same
//! order whatever the surface, so that the samples of a pixel meet the same
//! slot at the same depth: the scattering pair (a rough surface's
//! direction, or a smooth one's lobe from its first number) and the Russian
//! roulette number.
//!
//! A conductor's weight, and the roulette after it, wait until the
//! throughput is next used (`integrator/pending.rs`), and a path ends where the
//! mirror tube holds its ray ([`crate::trap`]): neither changes a bit of
//! the estimate, only the work spent on paths that gather nothing more.

use glam::Vec3;

use super::counts::{Bounce, RayCounts};
use super::hemisphere::cosine_sample;
use super::pending::{roulette, Pending};
use super::photon::maps::Pass;
use super::scatter::{Lobe, Surface};
use super::tracer::Tracer;
use crate::geometry::{Hit, Ray};
use crate::sampler::{Sample, Slot1d};
use crate::scene::Material;
use crate::spawn;

impl Tracer<'_> {
    pub(super) fn path(
        &self,
        primary: &Ray,
        sample: &mut Sample,
        counts: &mut RayCounts,
        caustics: Option<&Pass>,
    ) -> Vec3 {
        let mut ray = *primary;
        let mut beta = Vec3::ONE;
        let mut sum = Vec3::ZERO;
        let mut depth = 0;
        // Conductor bounces are weighed where `beta` is next used.
        let mut pending = Pending::new();
        let trap = self.machinery.trap.as_ref();
        loop {
            let Some(hit) = self.intersect(&ray) else {
                let escaped = |beta: Vec3| sum + beta * self.scene.escaped(ray.direction);
                return pending.settle(self, beta).map_or(sum, escaped);
            };
            let material = &self.scene.materials[hit.material as usize];
            let wo = -ray.direction;
            let n = hit.shading_normal(ray.direction);
            let (next, bounce, conductor) = match material.surface(&hit) {
                Surface::Shows(radiance) => {
                    let shown = |beta: Vec3| sum + beta * radiance;
                    return pending.settle(self, beta).map_or(sum, shown);
                }
                Surface::Rough => {
                    let Some(settled) = pending.settle(self, beta) else {
                        return sum;
                    };
                    beta = settled;
                    sum += beta * self.direct(&hit, n, wo, material, counts);
                    if let Some(pass) = caustics {
                        sum += beta * self.caustic(pass, &hit, n, wo, material, depth);
                    }
                    if depth >= self.settings.max_depth {
                        return sum;
                    }
                    match self.diffuse_bounce(&hit, n, wo, material, sample, &mut beta) {
                        Some(ray) => (ray, Bounce::Diffuse, None),
                        None => return sum,
                    }
                }
                Surface::Smooth => {
                    if depth >= self.settings.max_depth {
                        return sum;
                    }
                    let u = sample.take_1d();
                    if let Some((ray, cos_i)) = self.conductor_mirror(&hit, n, wo, material) {
                        (ray, Bounce::Reflection, Some((cos_i, material)))
                    } else {
                        let Some(settled) = pending.settle(self, beta) else {
                            return sum;
                        };
                        beta = settled;
                        let lobe = self.one_lobe(&hit, n, wo, material, u, &mut beta);
                        (lobe.ray, lobe.bounce, None)
                    }
                }
            };
            // A ray the mirror tube holds meets nothing else again: the
            // rest of the path adds nothing to `sum` (`crate::trap`).
            if trap.is_some_and(|t| t.holds(&next)) {
                return sum;
            }
            depth += 1;
            counts.bounce(bounce, depth);
            // Taken whether or not the roulette is played, so that the next
            // vertex's slots are the same for every sample; its number is
            // worked out only where it is played.
            let number = sample.take_1d();
            let Some(played) = self.carry_on(&mut pending, conductor, number, beta) else {
                return sum;
            };
            beta = played;
            ray = next;
        }
    }

    /// The radiance of the caustic map's `pass` leaving `hit` towards `wo`
    /// at a rough vertex after `depth` bounces: its photons that met at
    /// most the bounces the camera path has left.
    fn caustic(
        &self,
        pass: &Pass,
        hit: &Hit,
        n: Vec3,
        wo: Vec3,
        material: &Material,
        depth: u32,
    ) -> Vec3 {
        let bounces = self.settings.max_depth.saturating_sub(depth);
        pass.radiance(hit, n, wo, material, bounces)
    }

    /// The throughput after a bounce, its roulette played on `number`: a
    /// conductor's bounce held in `pending` until `beta` is next used, any
    /// other played at once; `None` where the roulette ended the path.
    fn carry_on<'m>(
        &self,
        pending: &mut Pending<'m>,
        conductor: Option<(f32, &'m Material)>,
        number: Slot1d,
        beta: Vec3,
    ) -> Option<Vec3> {
        match conductor {
            Some((cos_i, material)) => pending.push(self, (cos_i, material, number), beta),
            None => roulette(beta, number, self.settings.throughput_cutoff),
        }
    }

    /// The rough surface's bounce off `hit` (shading normal `n`, towards
    /// `wo`), its weight folded into `beta`: a cosine-weighted direction
    /// drawn from `sample`'s pair, or `None` where it dips below the surface.
    fn diffuse_bounce(
        &self,
        hit: &Hit,
        n: Vec3,
        wo: Vec3,
        material: &Material,
        sample: &mut Sample,
        beta: &mut Vec3,
    ) -> Option<Ray> {
        // Cosine-weighted hemisphere sampling: pdf = cos θ / π,
        // so the weight f_r cos θ / pdf is π f_r.
        let [u1, u2] = sample.next_2d();
        let wi = cosine_sample(n, u1, u2);
        // About a bump map's bent normal the hemisphere may dip
        // below the surface: that light is lost, as a bump map
        // loses it (without one, `wi · n > 0` always). `-wo` is the
        // ray's direction, bit for bit.
        let side = hit.facing_normal(-wo);
        if !(wi.dot(side) > 0.0) {
            return None;
        }
        let f = material.brdf(n, wi, wo);
        *beta *= f * std::f32::consts::PI;
        Some(Ray::new(
            spawn::origin(hit, side, self.settings.ray_offset),
            wi,
        ))
    }

    /// One lobe of a smooth surface, its weight folded into `beta`. With a
    /// refracted lobe, the branch is chosen with probability R, so that the
    /// Fresnel weight cancels (`u`'s number, uniform in `[0, 1)`, picks it). With the
    /// mirror lobe alone (a conductor, or total internal reflection) it is
    /// certain and carries its weight itself (under total internal
    /// reflection 1 for the exact law and Schlick's rarer-medium form; the
    /// incident form and the course's formula give less), and `u`'s number
    /// is not worked out.
    fn one_lobe(
        &self,
        hit: &Hit,
        n: Vec3,
        wo: Vec3,
        material: &Material,
        u: Slot1d,
        beta: &mut Vec3,
    ) -> Lobe {
        let lobes = self.lobes(hit, n, wo, material);
        match lobes.refraction {
            None => {
                *beta *= lobes.reflection.weight;
                lobes.reflection
            }
            Some((refracted, reflectance)) if u.value() >= reflectance => {
                *beta *= refracted.weight / (1.0 - reflectance);
                refracted
            }
            Some(_) => lobes.reflection,
        }
    }
}
