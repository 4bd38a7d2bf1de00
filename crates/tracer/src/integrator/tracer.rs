//! One render's tracer: the scene at its precision tier, the settled
//! settings, the machinery that runs, and the nearest hit along a ray,
//! which every integrator asks.

use glam::Vec3;
use radiometry::{Real, Vector3};

use super::machinery::Machinery;
use super::photon::maps::Caustics;
use crate::geometry::{Hit, Object, Ray};
use crate::scene::faults::{self, Fault};
use crate::scene::model::World;
use crate::scene::{Scene, Settings};

/// One render's tracer: the scene, the settings and the machinery, at
/// precision tier `V` (`Vec3`: `f32`; `DVec3`: `f64`).
pub struct Tracer<'a, V: Vector3 = Vec3> {
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
    pub caustics: Option<Caustics>,
}

impl<'a, V: Vector3> Tracer<'a, V> {
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

impl<V: Vector3> Tracer<'_, V> {
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
    pub(super) fn nearest(
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
