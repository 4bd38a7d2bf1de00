//! Local illumination (`003`, "lokális illumináció"): the ambient term and
//! the lights' direct light at the first surface hit; a mirror or glass is
//! not followed and shows black.

use glam::Vec3;

use super::scatter::Surface;
use super::{RayCounts, Tracer};
use crate::geometry::Ray;

impl Tracer<'_> {
    pub(super) fn local(&self, ray: &Ray, counts: &mut RayCounts) -> Vec3 {
        let Some(hit) = self.intersect(ray) else {
            return self.scene.escaped(ray.direction);
        };
        let material = &self.scene.materials[hit.material as usize];
        match material.surface(&hit) {
            Surface::Shows(radiance) => radiance,
            Surface::Smooth => Vec3::ZERO,
            Surface::Rough => {
                let n = hit.shading_normal(ray.direction);
                material.ambient(self.scene.ambient)
                    + self.direct(&hit, n, -ray.direction, material, counts)
            }
        }
    }
}
