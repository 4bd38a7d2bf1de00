//! Local illumination (`003`, "lokális illumináció"): the ambient term and
//! the lights' direct light at the first surface hit; a mirror or glass is
//! not followed and shows black.

use super::counts::RayCounts;
use super::scatter::Surface;
use super::tracer::Tracer;
use crate::geometry::Ray;
use radiometry::Vector3;

impl<V: Vector3> Tracer<'_, V> {
    pub(super) fn local(&self, ray: &Ray<V>, counts: &mut RayCounts) -> V {
        let Some(hit) = self.intersect(ray) else {
            return self.scene.escaped(ray.direction);
        };
        let material = &self.world.materials[hit.material as usize];
        match material.surface(&hit) {
            Surface::Shows(radiance) => radiance,
            Surface::Smooth => V::ZERO,
            Surface::Rough => {
                let n = hit.shading_normal(ray.direction);
                material.ambient(self.world.ambient)
                    + self.direct(&hit, n, -ray.direction, material, counts)
            }
        }
    }
}
