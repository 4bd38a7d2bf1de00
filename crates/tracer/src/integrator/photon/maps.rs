//! The caustic maps of one render, one per pass of progressive radius
//! reduction, and the radiance a pass's map estimates at a hit.

use glam::Vec3;

use super::grid::Grid;
use crate::geometry::Hit;
use crate::integrator::counts::RayCounts;
use crate::scene::Material;

/// Knaus and Zwicker's `α`: the fraction of the photons a pass's radius
/// keeps from the last (2/3 is their and Hachisuka and Jensen's choice).
pub const ALPHA: f64 = 2.0 / 3.0;

/// One pass's caustic map and its gather radius.
#[derive(Clone, Debug)]
pub struct Pass {
    /// The photons.
    pub map: Grid,
    /// The gather radius, m.
    pub radius: f32,
}

/// The caustic maps of one render, one per pass, and what they cost.
#[derive(Clone, Debug)]
pub struct Caustics {
    /// The passes, in order.
    pub passes: Vec<Pass>,
    /// Rays the photons cast.
    pub rays: RayCounts,
}

/// The radius of each of `passes` passes from `first`: `r²_{k+1} = r²_k (k
/// + α) / (k + 1)`, computed in `f64`.
pub fn radii(first: f32, passes: u32) -> Vec<f32> {
    let mut r2 = (first as f64).powi(2);
    (1..=passes)
        .map(|k| {
            let r = r2.sqrt() as f32;
            r2 *= (k as f64 + ALPHA) / (k as f64 + 1.0);
            r
        })
        .collect()
}

impl Pass {
    /// The caustic radiance leaving `hit` (shading normal `n`) towards
    /// `wo`, by `material`'s BRDF: the photons on the same object within
    /// the radius that met at most `bounces` mirrors or glass, `Σ f_r Φ /
    /// (π r²)`.
    pub fn radiance(
        &self,
        hit: &Hit,
        n: Vec3,
        wo: Vec3,
        material: &Material,
        bounces: u32,
    ) -> Vec3 {
        let mut flux = Vec3::ZERO;
        self.map.within(hit.point, self.radius, |p| {
            if p.object == hit.object && p.bounces <= bounces {
                flux += material.brdf(n, p.towards_source, wo) * p.flux;
            }
        });
        flux / (std::f32::consts::PI * self.radius * self.radius)
    }
}
