//! Recursive ray tracing (Whitted; `003`, "rekurzív sugárkövetés"): direct
//! light at rough surfaces, and every lobe of a mirror or glass followed,
//! Fresnel-weighted, to `max_depth`, a branch cut once its throughput falls
//! below `throughput_cutoff`.

use super::counts::RayCounts;
use super::scatter::Surface;
use super::tracer::Tracer;
use crate::geometry::Ray;
use radiometry::{Real, Vector3};

impl<V: Vector3> Tracer<'_, V> {
    /// Radiance along `ray`, `depth` bounces after the primary hit, whose
    /// contribution to the pixel is scaled by `throughput`.
    pub(super) fn whitted(
        &self,
        ray: &Ray<V>,
        depth: u32,
        throughput: V,
        counts: &mut RayCounts,
    ) -> V {
        let Some(hit) = self.intersect(ray) else {
            return self.scene.escaped(ray.direction);
        };
        let material = &self.world.materials[hit.material as usize];
        let wo = -ray.direction;
        let n = hit.shading_normal(ray.direction);
        match material.surface(&hit) {
            Surface::Shows(radiance) => radiance,
            Surface::Rough => {
                material.ambient(self.world.ambient) + self.direct(&hit, n, wo, material, counts)
            }
            Surface::Smooth => {
                if depth >= self.settings.max_depth {
                    return V::ZERO;
                }
                let lobes = self.lobes(&hit, n, wo, material);
                let refraction = lobes.refraction.map(|(lobe, _)| lobe);
                let mut sum = V::ZERO;
                for lobe in std::iter::once(lobes.reflection).chain(refraction) {
                    let next = throughput * lobe.weight;
                    if next.max_element() >= V::Scalar::of_f32(self.settings.throughput_cutoff) {
                        counts.bounce(lobe.bounce, depth + 1);
                        sum += lobe.weight * self.whitted(&lobe.ray, depth + 1, next, counts);
                    }
                }
                sum
            }
        }
    }
}
