//! The `photon` integrator: the path tracer's camera paths ([`super::path`])
//! and, at every rough vertex they reach, the radiance of a caustic photon
//! map (Jensen, *Realistic Image Synthesis Using Photon Mapping*, 2001):
//! the delta lights' light that reached the surface through at least one
//! mirror or glass surface, `L S+ D`, which no camera path can find (it
//! would have to hit a point or a direction).
//!
//! Nothing is counted twice: a camera path adds, at a rough vertex, the
//! direct light by shadow rays (the light's last vertex before it is this
//! one: `L D`) and the map (`L S+ D`); a path's first vertex after the
//! light is either rough or smooth, so each light path is counted by one.
//!
//! A light path has as many surface vertices as the path tracer allows
//! its camera paths, `max_depth + 1`: a camera path's rough vertex after
//! `d` bounces looks up only the photons that met at most `max_depth − d`
//! mirrors or glass (a path tracer with the lights made small spheres
//! would find the same paths, up to the same length).
//!
//! The estimate at a point `x` is the photons' flux within radius `r` on
//! the same object, `Σ f_r(ωp, ωo) Φp / (π r²)`: biased by the kernel,
//! which progressive radius reduction removes (Knaus and Zwicker,
//! "Progressive Photon Mapping: A Probabilistic Approach", ACM TOG 30(3),
//! 2011): pass `k` has its own photons and `r²_{k+1} = r²_k (k + α)/(k + 1)`,
//! `α = 2/3`; each camera path looks up one pass, drawn uniformly, so a
//! pixel's mean is the mean over passes, whose bias vanishes and variance
//! falls as the passes grow.

use glam::Vec3;
use rayon::prelude::*;

use super::counts::RayCounts;
use super::scatter::Surface;
use super::tracer::Tracer;
use crate::geometry::Ray;
use crate::rng::Pcg32;
use crate::sampler::Sample;
use crate::scene::faults::Fault;
use crate::scene::IntegratorKind;

mod emit;
mod grid;
mod landed;
pub(super) mod maps;

pub use grid::Grid;
pub use landed::Photon;
pub use maps::{radii, Caustics, Pass, ALPHA};

impl Caustics {
    /// The maps of `tracer`'s settings: every pass's photons traced in
    /// parallel, each on its own stream, gathered in emission order. No
    /// pass where no light can start a caustic (no mirror or glass, or no
    /// light): the camera paths are then the path tracer's, bit for bit.
    pub fn build(tracer: &Tracer) -> Caustics {
        let settings = tracer.settings.photon;
        let emitter = emit::Emitter::new(tracer);
        let mut rays = RayCounts::default();
        let mut passes = Vec::with_capacity(settings.passes as usize);
        if emitter.is_empty() {
            return Caustics { passes, rays };
        }
        let radii = radii(settings.radius, settings.passes);
        for (pass, radius) in radii.into_iter().enumerate() {
            let traced: Vec<(Option<Photon>, RayCounts)> = (0..settings.photons)
                .into_par_iter()
                .map(|i| {
                    let mut rng = Pcg32::for_photon(tracer.settings.seed, pass as u32, i);
                    let mut counts = RayCounts::default();
                    let photon = emitter
                        .emit(&mut rng, settings.photons)
                        .and_then(|e| tracer.trace_photon(e, &mut rng, &mut counts));
                    (photon, counts)
                })
                .collect();
            let mut photons = Vec::new();
            for (photon, counts) in traced {
                rays.add(&counts);
                photons.extend(photon);
            }
            passes.push(Pass {
                map: Grid::new(photons, radius),
                radius,
            });
        }
        Caustics { passes, rays }
    }
}

impl Tracer<'_> {
    /// This tracer with its caustic maps built, where its integrator has them.
    pub fn with_caustics(mut self) -> Self {
        if self.settings.integrator == IntegratorKind::Photon {
            self.caustics = Some(Caustics::build(&self));
        }
        self
    }

    /// The `photon` integrator: a camera path that looks up one pass's
    /// caustic map, drawn uniformly, at its rough vertices.
    pub(super) fn photon(
        &self,
        primary: &Ray,
        sample: &mut Sample,
        counts: &mut RayCounts,
    ) -> Vec3 {
        let pass = self.caustics.as_ref().and_then(|c| {
            let n = c.passes.len();
            let k = if n > 1 {
                ((sample.next_1d() * n as f32) as usize).min(n - 1)
            } else {
                0
            };
            c.passes.get(k)
        });
        self.path(primary, sample, counts, pass)
    }

    /// Follows one photon through mirrors and glass, one lobe at a time
    /// (chosen with the Fresnel probability at glass, as the camera paths
    /// choose), to the first rough surface: the photon left there, if it
    /// met from 1 to `max_depth` smooth ones first; Russian roulette below
    /// `throughput_cutoff`.
    fn trace_photon(
        &self,
        emitted: emit::Emitted,
        rng: &mut Pcg32,
        counts: &mut RayCounts,
    ) -> Option<Photon> {
        if let Some(escape) = emitted.escape {
            counts.photon += 1;
            if self.intersect(&escape).is_some() {
                return None;
            }
        }
        let (mut ray, mut flux) = (emitted.ray, emitted.flux);
        let start = flux.max_element();
        let stored_before_any_mirror =
            matches!(self.fault, Some(Fault::PhotonsStoredBeforeAnyMirror));
        for bounces in 0..=self.settings.max_depth {
            counts.photon += 1;
            let hit = self.intersect(&ray)?;
            let material = &self.scene.materials[hit.material as usize];
            let wo = -ray.direction;
            let n = hit.shading_normal(ray.direction);
            match material.surface(&hit) {
                Surface::Shows(_) => return None,
                Surface::Rough => {
                    return (bounces > 0 || stored_before_any_mirror).then_some(Photon {
                        point: hit.point,
                        towards_source: wo,
                        flux,
                        object: hit.object,
                        bounces,
                    });
                }
                Surface::Smooth if bounces == self.settings.max_depth => return None,
                Surface::Smooth => {
                    let lobes = self.lobes(&hit, n, wo, material);
                    let (lobe, chance) = match lobes.refraction {
                        None => (lobes.reflection, 1.0),
                        Some((refracted, r)) if rng.next_f32() >= r => (refracted, 1.0 - r),
                        Some((_, r)) => (lobes.reflection, r),
                    };
                    if !matches!(self.fault, Some(Fault::PhotonsUnweightedAtMirrors)) {
                        flux *= lobe.power / chance;
                    }
                    ray = lobe.ray;
                }
            }
            let peak = flux.max_element();
            if !(peak > 0.0) {
                return None;
            }
            let cutoff = self.settings.throughput_cutoff * start;
            if peak < cutoff {
                let survive = peak / cutoff;
                if rng.next_f32() >= survive {
                    return None;
                }
                flux /= survive;
            }
        }
        None
    }
}
