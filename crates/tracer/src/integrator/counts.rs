//! What a render's rays were cast for: the tally every integrator keeps,
//! and the kind of each secondary ray it counts.

/// What kind of secondary ray leaves a surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Bounce {
    /// A sampled direction off a rough surface (the path tracer's).
    Diffuse,
    /// The mirror direction.
    Reflection,
    /// Through a dielectric interface.
    Refraction,
}

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
    pub(crate) fn bounce(&mut self, bounce: Bounce, depth: u32) {
        match bounce {
            Bounce::Diffuse => self.diffuse += 1,
            Bounce::Reflection => self.reflection += 1,
            Bounce::Refraction => self.refraction += 1,
        }
        self.deepest = self.deepest.max(depth);
    }
}
