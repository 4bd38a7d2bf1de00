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
//! Radiance is in W/(sr·m²) per channel. The tracer computes at its
//! precision tier ([`crate::tier`], `Settings::precision`): `local`,
//! `whitted` and the steps they share in `f32` or `f64`; `path`, `photon`
//! and `course` in `f32` only.

use glam::{DVec3, Vec3};
use radiometry::Real;

use crate::geometry::{Hit, Object, Ray};
use crate::sampler::Sample;
use crate::scene::faults::{self, Fault};
use crate::scene::model::World;
use crate::scene::{IntegratorKind, Scene, Settings};
use crate::tier::Vector;
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

/// One render's tracer: the scene, the settings and the machinery, at
/// precision tier `V` (`Vec3`: `f32`; `DVec3`: `f64`).
pub struct Tracer<'a, V: Vector = Vec3> {
    /// The scene.
    pub scene: &'a Scene,
    /// The scene's objects, materials and lights at the tier, widened once.
    pub world: World<V>,
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
pub(crate) fn rgb<V: Vector>(f: impl Fn(usize) -> V::Scalar) -> V {
    V::new(f(0), f(1), f(2))
}

impl<'a, V: Vector> Tracer<'a, V> {
    /// The tracer of `scene` under `settings`, running `machinery`, with
    /// the fault planted on this thread, if any (`scene::faults`), at tier
    /// `V`. A render takes its tier from `settings.precision`
    /// ([`crate::job::RenderJob`]).
    pub fn new(scene: &'a Scene, settings: Settings, machinery: Machinery) -> Self {
        Tracer {
            scene,
            world: World::of(scene),
            settings,
            machinery,
            fault: faults::current(),
            caustics: None,
        }
    }
}

impl Tracer<'_> {
    /// This tracer with its caustic maps built, where its integrator has them.
    pub fn with_caustics(mut self) -> Self {
        if self.settings.integrator == IntegratorKind::Photon {
            self.caustics = Some(photon::Caustics::build(&self));
        }
        self
    }
}

impl<V: Vector> Tracer<'_, V> {
    /// The nearest hit along `ray`, robustly: the stable sphere roots,
    /// planes and the tube seen from both sides; its shading normal bent by
    /// the object's bump map, if it has one ([`crate::bump`]).
    pub fn intersect(&self, ray: &Ray<V>) -> Option<Hit<V>> {
        let mut hit = self.intersect_surface(ray)?;
        let object = hit.object as usize;
        if let Some(Some(field)) = self.scene.bumps.get(object) {
            hit.shading = crate::bump::shading_normal(&self.world.objects[object], field, &hit);
        }
        Some(hit)
    }

    /// The nearest hit along `ray` on the smooth surfaces, its shading
    /// normal the geometric one: all that a shadow ray asks.
    pub(crate) fn intersect_surface(&self, ray: &Ray<V>) -> Option<Hit<V>> {
        let zero = V::Scalar::lit(0.0);
        self.nearest(ray, |object, bounded| match object {
            Object::Sphere(s) => s.intersect(bounded, zero, s.roots(bounded)),
            Object::Plane(p) => p.intersect(bounded, zero),
            Object::Tube(t) => t.intersect(bounded, zero),
        })
    }

    /// The nearest of the hits `hit_of` finds along `ray`, each object
    /// searched only up to the nearest hit so far.
    fn nearest(
        &self,
        ray: &Ray<V>,
        hit_of: impl Fn(&Object<V>, &Ray<V>) -> Option<Hit<V>>,
    ) -> Option<Hit<V>> {
        let mut best: Option<Hit<V>> = None;
        for (i, object) in self.world.objects.iter().enumerate() {
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
}

impl Tracer<'_> {
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

/// The radiance along a primary ray at a tracer's tier: what
/// [`crate::render`] asks of a tracer of either tier.
pub(crate) trait Primary<V: Vector>: Sync {
    /// The tracer's scene, settings and machinery.
    fn tracer(&self) -> &Tracer<'_, V>;
    /// The radiance arriving along `ray` (see [`Tracer::radiance`]).
    fn primary(&self, ray: &Ray<V>, sample: &mut Sample, counts: &mut RayCounts) -> V;
}

impl Primary<Vec3> for Tracer<'_> {
    fn tracer(&self) -> &Tracer<'_> {
        self
    }
    fn primary(&self, ray: &Ray, sample: &mut Sample, counts: &mut RayCounts) -> Vec3 {
        self.radiance(ray, sample, counts)
    }
}

impl Primary<DVec3> for Tracer<'_, DVec3> {
    fn tracer(&self) -> &Tracer<'_, DVec3> {
        self
    }
    /// `local` and `whitted`, the integrators of the `f64` tier; a job
    /// settles no other there (`Settings::settle`).
    fn primary(&self, ray: &Ray<DVec3>, _: &mut Sample, counts: &mut RayCounts) -> DVec3 {
        counts.primary += 1;
        match self.settings.integrator {
            IntegratorKind::Local => self.local(ray, counts),
            IntegratorKind::Whitted => self.whitted(ray, 0, DVec3::ONE, counts),
            other => unreachable!("{other} is settled at f32 only"),
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
