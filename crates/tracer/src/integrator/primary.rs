//! The radiance along a primary ray: each integrator chosen by the
//! settings, at either precision tier.

use glam::{DVec3, Vec3};

use super::counts::RayCounts;
use super::tracer::Tracer;
use crate::geometry::Ray;
use crate::sampler::Sample;
use crate::scene::IntegratorKind;
use radiometry::Vector3;

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
pub(crate) trait Primary<V: Vector3>: Sync {
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
