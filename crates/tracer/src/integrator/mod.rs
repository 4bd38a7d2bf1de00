//! The three levels of light transport of `003` ("lokális illumináció",
//! "rekurzív sugárkövetés", "globális illumináció") and the course shader's
//! own loop, all on one scene, all shading with the `radiometry` laws.
//!
//! | integrator | at a rough surface | at a mirror or glass | cost |
//! |---|---|---|---|
//! | [`local`] | ambient + direct light, shadow rays | background seen in the mirror direction is not traced: black | 1 ray + 1 per light |
//! | [`whitted`] | ambient + direct light, shadow rays | recursion, Fresnel-weighted, to `max_depth`, cut below `throughput_cutoff` | grows with mirrors |
//! | [`path`] | direct light + one cosine-sampled bounce (no ambient: the indirect light is computed) | one branch, chosen with the Fresnel probability | `spp` paths per pixel |
//! | [`photon`] | as `path`, plus the caustic photon map's radiance (delta lights through mirrors and glass) | as `path`; photons follow one lobe each | `spp` paths per pixel + `photons × passes` photons |
//! | [`course`] | the final GLSL shader of `000`, bugs included | | |
//!
//! The physical integrators never look at a material: they ask the hit
//! what it does with light ([`scatter::Surface`]), take a rough surface's
//! direct light from [`direct`], and a smooth one's lobes from
//! [`scatter::Lobes`], where each specular decision is made once. The
//! course's loop keeps its own rules, intersection included, in [`course`].
//!
//! Radiance is in W/(sr·m²) per channel; the tracer computes in `f32`.

use glam::Vec3;

use crate::geometry::{Hit, Object, Ray};
use crate::sampler::Sample;
use crate::scene::faults::{self, Fault};
use crate::scene::{IntegratorKind, Scene, Settings};
use crate::trap::Trap;

pub mod course;
pub mod direct;
pub mod local;
pub mod path;
mod pending;
pub mod photon;
pub mod scatter;
mod shortcut;
pub mod whitted;

pub use scatter::Bounce;

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
    /// The photon map's photons, each segment (and a directional light's
    /// photon's escape test).
    pub photon: u64,
    /// The most bounces any path took after its primary hit.
    pub deepest: u32,
}

impl RayCounts {
    /// All rays.
    pub fn total(&self) -> u64 {
        self.primary + self.reflection + self.refraction + self.shadow + self.diffuse + self.photon
    }

    /// Adds another tally.
    pub fn add(&mut self, other: &RayCounts) {
        self.primary += other.primary;
        self.reflection += other.reflection;
        self.refraction += other.refraction;
        self.shadow += other.shadow;
        self.diffuse += other.diffuse;
        self.photon += other.photon;
        self.deepest = self.deepest.max(other.deepest);
    }

    /// Counts one secondary ray of kind `bounce`, the `depth`-th of its path.
    fn bounce(&mut self, bounce: Bounce, depth: u32) {
        match bounce {
            Bounce::Diffuse => self.diffuse += 1,
            Bounce::Reflection => self.reflection += 1,
            Bounce::Refraction => self.refraction += 1,
        }
        self.deepest = self.deepest.max(depth);
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
    /// The mirror tube whose held rays end a camera path (`path` and
    /// `photon`; see [`crate::trap`]): the rest of such a path adds nothing.
    pub trap: Option<Trap>,
}

impl Machinery {
    /// Everything on: the reference against which skipping is measured.
    pub fn everything(scene: &Scene, settings: &Settings) -> Self {
        Machinery {
            shadow_rays: true,
            lights: vec![true; scene.lights.len()],
            spp: settings.spp,
            trap: None,
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
    /// A law left out on purpose (`scene::faults`, tests only): read once
    /// from the thread that built the tracer.
    pub(crate) fault: Option<Fault>,
    /// The caustic photon maps (`photon` only, built by [`Tracer::with_caustics`]).
    pub caustics: Option<photon::Caustics>,
}

/// A colour from a function of its channel index.
pub(crate) fn rgb(f: impl Fn(usize) -> f32) -> Vec3 {
    Vec3::new(f(0), f(1), f(2))
}

impl<'a> Tracer<'a> {
    /// The tracer of `scene` under `settings`, running `machinery`, with
    /// the fault planted on this thread, if any (`scene::faults`).
    pub fn new(scene: &'a Scene, settings: Settings, machinery: Machinery) -> Self {
        Tracer {
            scene,
            settings,
            machinery,
            fault: faults::current(),
            caustics: None,
        }
    }

    /// This tracer with its caustic maps built, where its integrator has them.
    pub fn with_caustics(mut self) -> Self {
        if self.settings.integrator == IntegratorKind::Photon {
            self.caustics = Some(photon::Caustics::build(&self));
        }
        self
    }
}

impl Tracer<'_> {
    /// The nearest hit along `ray`, robustly: the stable sphere roots,
    /// planes and the tube seen from both sides; its shading normal bent by
    /// the object's bump map, if it has one ([`crate::bump`]).
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let mut hit = self.intersect_surface(ray)?;
        let object = hit.object as usize;
        if let Some(Some(field)) = self.scene.bumps.get(object) {
            hit.shading = crate::bump::shading_normal(&self.scene.objects[object], field, &hit);
        }
        Some(hit)
    }

    /// The nearest hit along `ray` on the smooth surfaces, its shading
    /// normal the geometric one: all that a shadow ray asks.
    pub(crate) fn intersect_surface(&self, ray: &Ray) -> Option<Hit> {
        self.nearest(ray, |object, bounded| match object {
            Object::Sphere(s) => s.intersect(bounded, 0.0, s.roots(bounded)),
            Object::Plane(p) => p.intersect(bounded, 0.0),
            Object::Tube(t) => t.intersect(bounded, 0.0),
        })
    }

    /// The nearest of the hits `hit_of` finds along `ray`, each object
    /// searched only up to the nearest hit so far.
    fn nearest(&self, ray: &Ray, hit_of: impl Fn(&Object, &Ray) -> Option<Hit>) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        for (i, object) in self.scene.objects.iter().enumerate() {
            let bounded = Ray {
                t_max: best.map_or(ray.t_max, |h| h.t),
                ..*ray
            };
            if let Some(mut h) = hit_of(object, &bounded) {
                h.object = i as u32;
                best = Some(h);
            }
        }
        best
    }

    /// The radiance arriving along a primary ray, by the chosen integrator
    /// (`photon` looks up the maps of [`Tracer::with_caustics`]; a tracer
    /// without them traces the path tracer's paths alone), its random
    /// numbers drawn from `sample` (the deterministic integrators draw none).
    pub fn radiance(&self, ray: &Ray, sample: &mut Sample, counts: &mut RayCounts) -> Vec3 {
        counts.primary += 1;
        match self.settings.integrator {
            IntegratorKind::Local => self.local(ray, counts),
            IntegratorKind::Whitted => self.whitted(ray, 0, Vec3::ONE, counts),
            IntegratorKind::Path => self.path(ray, sample, counts, None),
            IntegratorKind::Photon => self.photon(ray, sample, counts),
            IntegratorKind::Course => self.course(ray, counts),
        }
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
