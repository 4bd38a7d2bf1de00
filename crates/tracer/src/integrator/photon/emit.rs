//! Where the caustic photons start: each used delta light chosen by its
//! power, its photons aimed only where a specular chain can begin.
//!
//! A photon whose first hit is rough starts no caustic (it is the direct
//! light, which the camera paths' shadow rays compute), so emission may
//! skip every direction that cannot meet a mirror or glass first, without
//! bias. Finite smooth objects (spheres) are aimed at: from a point light
//! the cones they subtend, from a directional light the discs of their
//! shadows; a direction inside `k` of the targets has density `k / Σ` of
//! the targets' total solid angle or area (one-sample balance over the
//! overlaps). An unbounded smooth object (a plane, the mirror tube) makes
//! a point light emit over the whole sphere; a directional light cannot
//! cover it with a finite disc, so its light by way of an unbounded mirror
//! or glass is not in the map (`docs/tracer.md`).

use glam::Vec3;

use crate::geometry::{Object, Ray};
use crate::integrator::tracer::Tracer;
use crate::rng::Pcg32;
use crate::scene::Light;

/// A finite smooth object, by its bounding sphere.
#[derive(Clone, Copy, Debug)]
struct Target {
    centre: Vec3,
    radius: f32,
}

/// How one light's photons are aimed.
#[derive(Clone, Debug)]
enum Aim {
    /// Uniformly over the sphere (a point light).
    Sphere,
    /// Into the cones of the targets (a point light), `cos` of each
    /// half-angle with its axis.
    Cones(Vec<(Vec3, f32)>),
    /// Through the shadow discs of the targets (a directional light).
    Discs(Vec<Target>),
}

/// One light's photons: where they start, and the light's power into them.
#[derive(Clone, Debug)]
struct Source {
    light: Light,
    aim: Aim,
    /// The targets' total solid angle (sr) or disc area (m²); 4π for the sphere.
    measure: f32,
}

/// A photon as it leaves its light.
#[derive(Clone, Copy, Debug)]
pub(super) struct Emitted {
    /// Its ray.
    pub ray: Ray,
    /// The flux it carries, W per channel.
    pub flux: Vec3,
    /// A directional light's photon starts at a finite distance: this ray,
    /// from its start back towards the light, must escape, or something
    /// farther shadows it and there is no photon.
    pub escape: Option<Ray>,
}

/// The photon emitter of a render.
#[derive(Clone, Debug)]
pub(super) struct Emitter {
    sources: Vec<Source>,
    /// Each source's probability, cumulated.
    cdf: Vec<f32>,
    /// Each source's probability.
    chance: Vec<f32>,
    /// The distance a directional light's photon starts from its disc, m.
    far: f32,
}

impl Emitter {
    /// The emitter of the lights `tracer` runs.
    pub(super) fn new(tracer: &Tracer) -> Emitter {
        let scene = tracer.scene;
        let smooth = |o: &Object| scene.materials[o.material() as usize].is_specular();
        let mut targets = Vec::new();
        let mut unbounded = false;
        for object in scene.objects.iter().filter(|o| smooth(o)) {
            match object {
                Object::Sphere(s) => targets.push(Target {
                    centre: s.center,
                    radius: s.radius,
                }),
                Object::Plane(_) | Object::Tube(_) => unbounded = true,
            }
        }
        // Beyond every finite object: a directional photon starts outside
        // them all, and what lies farther is found by its escape ray.
        let far = scene
            .objects
            .iter()
            .filter_map(|o| match o {
                Object::Sphere(s) => Some(s.center.length() + s.radius),
                _ => None,
            })
            .fold(1.0_f32, f32::max)
            * 4.0;
        let mut sources = Vec::new();
        for (light, _) in scene
            .lights
            .iter()
            .zip(&tracer.machinery.lights)
            .filter(|(_, on)| **on)
        {
            if let Some(source) = source(*light, &targets, unbounded) {
                sources.push(source);
            }
        }
        let weight: Vec<f32> = sources.iter().map(|s| s.power().element_sum()).collect();
        let total: f32 = weight.iter().sum();
        let chance: Vec<f32> = weight.iter().map(|w| w / total).collect();
        let cdf = chance
            .iter()
            .scan(0.0, |acc, p| {
                *acc += p;
                Some(*acc)
            })
            .collect();
        Emitter {
            sources,
            cdf,
            chance,
            far,
        }
    }

    /// Whether any light can start a caustic.
    pub(super) fn is_empty(&self) -> bool {
        self.sources.is_empty() || !(self.chance.iter().sum::<f32>() > 0.0)
    }

    /// One of `n` photons, or `None` for a degenerate draw.
    pub(super) fn emit(&self, rng: &mut Pcg32, n: u32) -> Option<Emitted> {
        let u = rng.next_f32();
        let i = self
            .cdf
            .iter()
            .position(|c| u < *c)
            .unwrap_or(self.cdf.len() - 1);
        let source = &self.sources[i];
        let (ray, overlaps) = source.start(rng, self.far)?;
        let share = source.measure / (overlaps as f32 * self.chance[i] * n as f32);
        let escape = matches!(source.light, Light::Directional { .. })
            .then(|| Ray::new(ray.origin, -ray.direction));
        Some(Emitted {
            ray,
            flux: source.strength() * share,
            escape,
        })
    }
}

/// The source of `light`, or `None` where it can start no caustic.
fn source(light: Light, targets: &[Target], unbounded: bool) -> Option<Source> {
    let (aim, measure) = match light {
        Light::Point { position, .. } => {
            let inside = targets
                .iter()
                .any(|t| (t.centre - position).length() <= t.radius);
            if unbounded || inside {
                (Aim::Sphere, 4.0 * std::f32::consts::PI)
            } else if targets.is_empty() {
                return None;
            } else {
                let cones: Vec<(Vec3, f32)> = targets
                    .iter()
                    .map(|t| {
                        let to = t.centre - position;
                        let d = to.length();
                        (to / d, (1.0 - (t.radius / d).powi(2)).max(0.0).sqrt())
                    })
                    .collect();
                let solid: f32 = cones
                    .iter()
                    .map(|(_, c)| std::f32::consts::TAU * (1.0 - c))
                    .sum();
                (Aim::Cones(cones), solid)
            }
        }
        Light::Directional { .. } if targets.is_empty() => return None,
        Light::Directional { .. } => {
            let area = targets
                .iter()
                .map(|t| std::f32::consts::PI * t.radius * t.radius)
                .sum();
            (Aim::Discs(targets.to_vec()), area)
        }
    };
    (measure > 0.0).then_some(Source {
        light,
        aim,
        measure,
    })
}

impl Source {
    /// Intensity (W/sr) or irradiance (W/m²) per channel.
    fn strength(&self) -> Vec3 {
        match self.light {
            Light::Point { intensity, .. } => intensity,
            Light::Directional { irradiance, .. } => irradiance,
        }
    }

    /// The power sent into the targets, W per channel (counting overlaps
    /// once per target: the weight that picks this light, not a flux).
    fn power(&self) -> Vec3 {
        self.strength() * self.measure
    }

    /// A photon's ray, and how many targets its direction or start meets
    /// (1 for the whole sphere); `None` for a degenerate draw.
    fn start(&self, rng: &mut Pcg32, far: f32) -> Option<(Ray, u32)> {
        let (u0, u1, u2) = (rng.next_f32(), rng.next_f32(), rng.next_f32());
        match (&self.aim, self.light) {
            (Aim::Sphere, Light::Point { position, .. }) => {
                let z = 1.0 - 2.0 * u1;
                let r = (1.0 - z * z).max(0.0).sqrt();
                let phi = std::f32::consts::TAU * u2;
                let d = Vec3::new(r * phi.cos(), r * phi.sin(), z);
                Some((Ray::new(position, d), 1))
            }
            (Aim::Cones(cones), Light::Point { position, .. }) => {
                let (axis, cos_max) = cones[pick(cones.iter().map(|c| 1.0 - c.1), u0)];
                let cos = 1.0 - u1 * (1.0 - cos_max);
                let d = around(axis, cos, u2);
                let overlaps = cones.iter().filter(|(a, c)| d.dot(*a) >= *c).count();
                (overlaps > 0).then(|| (Ray::new(position, d), overlaps as u32))
            }
            (Aim::Discs(discs), Light::Directional { towards, .. }) => {
                let t = discs[pick(discs.iter().map(|t| t.radius * t.radius), u0)];
                let (e1, e2) = towards.any_orthonormal_pair();
                let (r, phi) = (t.radius * u1.sqrt(), std::f32::consts::TAU * u2);
                let on_disc = t.centre + (e1 * phi.cos() + e2 * phi.sin()) * r;
                let overlaps = discs
                    .iter()
                    .filter(|d| {
                        (on_disc - d.centre)
                            .reject_from_normalized(towards)
                            .length()
                            <= d.radius
                    })
                    .count()
                    .max(1);
                Some((Ray::new(on_disc + towards * far, -towards), overlaps as u32))
            }
            _ => None,
        }
    }
}

/// The index drawn by `u` from weights `w` (in proportion to them).
fn pick(w: impl Iterator<Item = f32> + Clone, u: f32) -> usize {
    let total: f32 = w.clone().sum();
    let mut acc = 0.0;
    let count = w.clone().count();
    for (i, wi) in w.enumerate() {
        acc += wi / total;
        if u < acc {
            return i;
        }
    }
    count - 1
}

/// The unit direction at `cos θ` from `axis`, at azimuth `2π u`.
fn around(axis: Vec3, cos: f32, u: f32) -> Vec3 {
    let sin = (1.0 - cos * cos).max(0.0).sqrt();
    let phi = std::f32::consts::TAU * u;
    let (t, b) = axis.any_orthonormal_pair();
    (t * (sin * phi.cos()) + b * (sin * phi.sin()) + axis * cos).normalize()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrator::Machinery;
    use crate::scene::{self, Settings};

    /// The flux the emitter sends, summed over `n` photons, for `light`
    /// (JSON) and mirror spheres at `centres` of radius 1.
    fn emitted_flux(light: &str, centres: &[[f32; 3]], n: u32) -> f64 {
        let spheres: Vec<String> = centres
            .iter()
            .map(|c| {
                format!(
                    r#"{{ "type": "sphere", "center": [{}, {}, {}], "radius": 1, "material": "mirror" }}"#,
                    c[0], c[1], c[2]
                )
            })
            .collect();
        let text = format!(
            r#"{{ "version": 1, "image": {{ "width": 2, "height": 2 }},
                 "camera": {{ "type": "course_pinhole" }},
                 "materials": {{ "mirror": {{ "type": "conductor", "n": [0.2, 0.2, 0.2], "kappa": [3, 3, 3] }},
                                 "floor": {{ "type": "lambert", "albedo": [0.5, 0.5, 0.5] }} }},
                 "objects": [ {}, {{ "type": "sphere", "center": [0, -50, 0], "radius": 1, "material": "floor" }} ],
                 "lights": [ {light} ] }}"#,
            spheres.join(", ")
        );
        let scene = scene::parse(&text).unwrap();
        let settings = Settings::default();
        let tracer = Tracer::new(&scene, settings, Machinery::everything(&scene, &settings));
        let emitter = Emitter::new(&tracer);
        let mut rng = Pcg32::new(11, 13);
        (0..n)
            .filter_map(|_| emitter.emit(&mut rng, n))
            .map(|e| e.flux.x as f64)
            .sum()
    }

    /// Relative error of a sum of 200 000 photons: the draws that meet two
    /// targets carry half, so the sum varies; 1 % is over 10 of its
    /// standard deviations.
    const TOLERANCE: f64 = 0.01;

    /// A directional light sends `E A` through the shadow discs, `A` the
    /// area of their union: for two discs of radius 1 whose centres are 1
    /// apart, `2π − (2 acos ½ − √3/2)`; for two discs on one another, `π`.
    #[test]
    fn a_directional_light_sends_its_irradiance_times_the_discs_union() {
        let light = r#"{ "type": "directional", "towards": [0, 1, 0], "irradiance": [2, 2, 2] }"#;
        let lens = 2.0 * 0.5_f64.acos() - 3.0_f64.sqrt() / 2.0;
        for (centres, union) in [
            (
                vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]],
                std::f64::consts::TAU - lens,
            ),
            (vec![[0.0, 0.0, 0.0], [0.0, 3.0, 0.0]], std::f64::consts::PI),
        ] {
            let flux = emitted_flux(light, &centres, 200_000);
            let want = 2.0 * union;
            assert!((flux / want - 1.0).abs() < TOLERANCE, "{flux} vs {want}");
        }
    }

    /// A point light sends `I Ω` into the cones of the spheres, `Ω` their
    /// union's solid angle: one sphere of radius 1 at distance 4, `2π (1 −
    /// √15/4)`, alone or with a second sphere just like it (counted once).
    #[test]
    fn a_point_light_sends_its_intensity_times_the_cones_union() {
        let light = r#"{ "type": "point", "position": [0, 0, 0], "intensity": [3, 3, 3] }"#;
        let omega = std::f64::consts::TAU * (1.0 - 15.0_f64.sqrt() / 4.0);
        for centres in [
            vec![[4.0, 0.0, 0.0]],
            vec![[4.0, 0.0, 0.0], [4.0, 0.0, 0.0]],
        ] {
            let flux = emitted_flux(light, &centres, 200_000);
            let want = 3.0 * omega;
            assert!((flux / want - 1.0).abs() < TOLERANCE, "{flux} vs {want}");
        }
    }
}
